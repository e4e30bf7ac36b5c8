#pragma once

// The window's small dialogs, each wide enough for its title in a window manager's title bar
// and for its text: an input dialog only as wide as its field cut "Find Device" to
// "Find...Device" (and "Trova operando" to "Trova ... rando") under openbox.

#include <QMessageBox>
#include <QString>

class QDialog;
class QWidget;

namespace rung::app {

// The width a title bar needs for the dialog's title: the text in a bold title-bar font and
// about ten text heights for the window manager's icon and buttons (openbox takes about
// 115 px, and its title font may be larger than ours).
int titleBarWidth(const QWidget *dialog);
// Makes the dialog at least that wide (a message box too: its layout gets a strut).
void fitTitle(QDialog *dialog);

// QInputDialog::getText / getMultiLineText with the title fitted; a comment is edited in a
// field wide enough for a line of about 75 characters.
QString askText(QWidget *parent, const QString &title, const QString &label, const QString &text,
                bool *ok);
QString askMultiLineText(QWidget *parent, const QString &title, const QString &label,
                         const QString &text, bool *ok);

// QInputDialog::getInt / getDouble with the title fitted: the field alone made "Run Scans"
// read "Ciklus…tatása" and "Esegui… nsioni" in a title bar.
int askInt(QWidget *parent, const QString &title, const QString &label, int value, int min, int max,
           bool *ok);
double askDouble(QWidget *parent, const QString &title, const QString &label, double value,
                 double min, double max, int decimals, bool *ok);

// QMessageBox's static functions with the title fitted.
// No buttons given: Yes and No for a question, else OK.
QMessageBox::StandardButton
messageBox(QMessageBox::Icon icon, QWidget *parent, const QString &title, const QString &text,
           QMessageBox::StandardButtons buttons = QMessageBox::NoButton);

} // namespace rung::app
