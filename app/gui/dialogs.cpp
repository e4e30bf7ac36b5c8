#include "dialogs.h"

#include <QBoxLayout>
#include <QDialog>
#include <QFontMetrics>
#include <QGridLayout>
#include <QInputDialog>
#include <QPlainTextEdit>

namespace rung::app {

int titleBarWidth(const QWidget *dialog) {
    QFont bold = dialog->font();
    bold.setBold(true);
    const QFontMetrics metrics(bold);
    return metrics.horizontalAdvance(dialog->windowTitle()) + 10 * metrics.height();
}

void fitTitle(QDialog *dialog) {
    const int width = titleBarWidth(dialog);
    dialog->setMinimumWidth(std::max(dialog->minimumWidth(), width));
    // A dialog whose layout sets its size (a message box when shown, an input dialog's
    // minimum-and-maximum constraint) takes a strut across its layout instead.
    QLayout *layout = dialog->layout();
    if (!layout)
        return;
    const QMargins margins = layout->contentsMargins();
    auto *strut = new QSpacerItem(width - margins.left() - margins.right(), 0, QSizePolicy::Fixed,
                                  QSizePolicy::Minimum);
    if (auto *grid = qobject_cast<QGridLayout *>(layout))
        grid->addItem(strut, grid->rowCount(), 0, 1, grid->columnCount());
    else if (auto *box = qobject_cast<QBoxLayout *>(layout))
        box->addItem(strut);
    else
        delete strut; // a form layout leaves the minimum width alone
}

namespace {

// Shows an input dialog set up by the caller with its title whole; whether it was accepted, also
// in *ok when given.
bool execFitted(QInputDialog &dialog, bool *ok) {
    dialog.minimumSizeHint(); // an input dialog builds its layout only when asked for a size
    fitTitle(&dialog);
    const bool accepted = dialog.exec() == QDialog::Accepted;
    if (ok)
        *ok = accepted;
    return accepted;
}

} // namespace

QString askText(QWidget *parent, const QString &title, const QString &label, const QString &text,
                bool *ok) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setTextValue(text);
    dialog.setInputMode(QInputDialog::TextInput);
    return execFitted(dialog, ok) ? dialog.textValue() : QString();
}

QString askMultiLineText(QWidget *parent, const QString &title, const QString &label,
                         const QString &text, bool *ok) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setOption(QInputDialog::UsePlainTextEditForTextInput);
    dialog.setTextValue(text);
    dialog.minimumSizeHint(); // its layout, as above: the text edit exists from here
    // A rung comment reads as written: room for about 75 characters a line and a few lines,
    // long lines wrapped rather than scrolled out of sight.
    if (auto *edit = dialog.findChild<QPlainTextEdit *>()) {
        const QFontMetrics metrics(edit->font());
        edit->setMinimumSize(metrics.averageCharWidth() * 76, metrics.lineSpacing() * 8);
        edit->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    }
    return execFitted(dialog, ok) ? dialog.textValue() : QString();
}

int askInt(QWidget *parent, const QString &title, const QString &label, int value, int min, int max,
           bool *ok) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setInputMode(QInputDialog::IntInput);
    dialog.setIntRange(min, max);
    dialog.setIntValue(value);
    return execFitted(dialog, ok) ? dialog.intValue() : value;
}

double askDouble(QWidget *parent, const QString &title, const QString &label, double value,
                 double min, double max, int decimals, bool *ok) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setInputMode(QInputDialog::DoubleInput);
    dialog.setDoubleDecimals(decimals);
    dialog.setDoubleRange(min, max);
    dialog.setDoubleValue(value);
    return execFitted(dialog, ok) ? dialog.doubleValue() : value;
}

QMessageBox::StandardButton messageBox(QMessageBox::Icon icon, QWidget *parent,
                                       const QString &title, const QString &text,
                                       QMessageBox::StandardButtons buttons) {
    if (buttons == QMessageBox::NoButton)
        buttons =
            icon == QMessageBox::Question ? QMessageBox::Yes | QMessageBox::No : QMessageBox::Ok;
    QMessageBox box(icon, title, text, buttons, parent);
    fitTitle(&box);
    return static_cast<QMessageBox::StandardButton>(box.exec());
}

} // namespace rung::app
