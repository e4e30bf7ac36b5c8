#include "problems_view.h"

#include <QContextMenuEvent>
#include <QEvent>
#include <QHeaderView>
#include <QMenu>
#include <QPainter>
#include <QStyle>

#include <algorithm>

namespace rung::editor {

ProblemsView::ProblemsView(QWidget *parent)
    : QTreeWidget(parent) {
    setColumnCount(4);
    retranslate();
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    header()->setStretchLastSection(true);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        if (const model::Diagnostic *d = diagnosticAt(indexOfTopLevelItem(item)))
            emit locate(*d);
    });
}

void ProblemsView::retranslate() {
    setHeaderLabels({tr("Severity"), tr("Code"), tr("Place"), tr("Message")});
    setAccessibleName(tr("Problems"));
}

void ProblemsView::changeEvent(QEvent *event) {
    // The rows come again from whoever found them (in the new language); the headers are ours.
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTreeWidget::changeEvent(event);
}

void ProblemsView::setDiagnostics(const std::vector<model::Diagnostic> &diagnostics) {
    m_diagnostics = diagnostics;
    model::sortDiagnostics(m_diagnostics);
    clear();
    for (const model::Diagnostic &d : m_diagnostics) {
        auto *item = new QTreeWidgetItem(this);
        const bool error = d.severity == model::Severity::Error;
        item->setIcon(0, style()->standardIcon(error ? QStyle::SP_MessageBoxCritical
                                                     : QStyle::SP_MessageBoxWarning));
        item->setText(0, error                                    ? tr("Error")
                         : d.severity == model::Severity::Warning ? tr("Warning")
                                                                  : tr("Note"));
        item->setText(1, d.code);
        QString place;
        if (d.location.onListing())
            place = tr("line %1").arg(d.location.line);
        else if (d.location.onLadder())
            place = d.location.row >= 0
                        ? tr("rung %1, row %2").arg(d.location.rung + 1).arg(d.location.row + 1)
                        : tr("rung %1").arg(d.location.rung + 1);
        item->setText(2, place);
        item->setText(3, d.fix ? tr("%1 (fix available)").arg(d.message) : d.message);
        item->setToolTip(3, d.message);
    }
    // Columns fit their contents, but never narrower than a "Warning" with its icon, a code
    // and a "rung 10, row 2": an empty or short list does not squeeze its headers.
    const QFontMetrics fm(font());
    const int minimum[3] = {fm.horizontalAdvance(tr("Warning")) + 44,
                            fm.horizontalAdvance(QStringLiteral("SYN001")) + 24,
                            fm.horizontalAdvance(tr("rung %1, row %2").arg(10).arg(2)) + 24};
    for (int c = 0; c < 3; ++c) {
        resizeColumnToContents(c);
        setColumnWidth(c, std::max(columnWidth(c), minimum[c]));
    }
    viewport()->update();
}

int ProblemsView::count(model::Severity severity) const {
    return static_cast<int>(
        std::count_if(m_diagnostics.begin(), m_diagnostics.end(),
                      [severity](const model::Diagnostic &d) { return d.severity == severity; }));
}

QString ProblemsView::summary() const {
    const int errors = count(model::Severity::Error);
    const int warnings = count(model::Severity::Warning);
    QStringList parts;
    if (errors > 0)
        parts << (errors == 1 ? tr("1 error") : tr("%1 errors").arg(errors));
    if (warnings > 0)
        parts << (warnings == 1 ? tr("1 warning") : tr("%1 warnings").arg(warnings));
    return parts.isEmpty() ? tr("Problems") : tr("Problems (%1)").arg(parts.join(tr(", ")));
}

void ProblemsView::paintEvent(QPaintEvent *event) {
    QTreeWidget::paintEvent(event);
    if (topLevelItemCount() > 0)
        return;
    // An empty list says so, instead of looking like it has not run.
    QPainter p(viewport());
    p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    p.drawText(viewport()->rect(), Qt::AlignCenter, tr("No problems found"));
}

const model::Diagnostic *ProblemsView::diagnosticAt(int row) const {
    if (row < 0 || row >= static_cast<int>(m_diagnostics.size()))
        return nullptr;
    return &m_diagnostics[static_cast<std::size_t>(row)];
}

void ProblemsView::contextMenuEvent(QContextMenuEvent *event) {
    const model::Diagnostic *d = diagnosticAt(indexOfTopLevelItem(itemAt(event->pos())));
    if (!d)
        return;
    QMenu menu(this);
    const model::Diagnostic copy = *d;
    menu.addAction(tr("Show"), this, [this, copy] { emit locate(copy); });
    if (d->fix)
        menu.addAction(d->fix->label, this, [this, copy] { emit applyFix(copy); });
    menu.exec(event->globalPos());
}

} // namespace rung::editor
