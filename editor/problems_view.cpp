#include "problems_view.h"

#include <QAbstractTableModel>
#include <QContextMenuEvent>
#include <QCoreApplication>
#include <QEvent>
#include <QHeaderView>
#include <QIcon>
#include <QMenu>
#include <QPainter>
#include <QStyle>

#include <algorithm>

namespace rung::editor {

// The findings as rows: severity, code, place, message. Texts are made when a row is drawn.
class ProblemsModel : public QAbstractTableModel {
    Q_DECLARE_TR_FUNCTIONS(rung::editor::ProblemsView)

public:
    ProblemsModel(QObject *parent, QIcon error, QIcon warning)
        : QAbstractTableModel(parent)
        , m_error(std::move(error))
        , m_warning(std::move(warning)) {}

    void setDiagnostics(std::vector<model::Diagnostic> diagnostics) {
        beginResetModel();
        m_diagnostics = std::move(diagnostics);
        endResetModel();
    }
    // The headers and rows in the language now installed.
    void retranslate() {
        emit headerDataChanged(Qt::Horizontal, 0, kColumns - 1);
        if (!m_diagnostics.empty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, kColumns - 1));
    }
    const std::vector<model::Diagnostic> &diagnostics() const { return m_diagnostics; }

    int rowCount(const QModelIndex &parent = {}) const override {
        return parent.isValid() ? 0 : static_cast<int>(m_diagnostics.size());
    }
    int columnCount(const QModelIndex &parent = {}) const override {
        return parent.isValid() ? 0 : kColumns;
    }

    QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
        if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
            return {};
        switch (section) {
        case 0:
            return tr("Severity");
        case 1:
            return tr("Code");
        case 2:
            return tr("Place");
        case 3:
            return tr("Message");
        }
        return {};
    }

    QVariant data(const QModelIndex &index, int role) const override {
        if (!index.isValid() || index.row() >= rowCount())
            return {};
        const model::Diagnostic &d = m_diagnostics[static_cast<std::size_t>(index.row())];
        const bool error = d.severity == model::Severity::Error;
        if (role == Qt::DecorationRole && index.column() == 0)
            return error ? m_error : m_warning;
        if (role == Qt::ToolTipRole && index.column() == 3)
            return d.message;
        if (role != Qt::DisplayRole)
            return {};
        switch (index.column()) {
        case 0:
            return error                                    ? tr("Error")
                   : d.severity == model::Severity::Warning ? tr("Warning")
                                                            : tr("Note");
        case 1:
            return d.code;
        case 2:
            return place(d);
        case 3:
            return d.fix ? tr("%1 (fix available)").arg(d.message) : d.message;
        }
        return {};
    }

    static QString place(const model::Diagnostic &d) {
        if (d.location.onListing())
            return tr("line %1").arg(d.location.line);
        if (d.location.onLadder())
            return d.location.row >= 0
                       ? tr("rung %1, row %2").arg(d.location.rung + 1).arg(d.location.row + 1)
                       : tr("rung %1").arg(d.location.rung + 1);
        return {};
    }

private:
    static constexpr int kColumns = 4;
    std::vector<model::Diagnostic> m_diagnostics;
    QIcon m_error;
    QIcon m_warning;
};

ProblemsView::ProblemsView(QWidget *parent)
    : QTreeView(parent)
    , m_model(new ProblemsModel(this, style()->standardIcon(QStyle::SP_MessageBoxCritical),
                                style()->standardIcon(QStyle::SP_MessageBoxWarning))) {
    setModel(m_model);
    retranslate();
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    header()->setStretchLastSection(true);
    connect(this, &QTreeView::activated, this, [this](const QModelIndex &index) {
        // A copy: whoever shows the place may refresh the findings this one is among.
        if (const model::Diagnostic *d = diagnosticAt(index.row()))
            emit locate(model::Diagnostic(*d));
    });
}

void ProblemsView::retranslate() {
    m_model->retranslate();
    setAccessibleName(tr("Problems"));
}

void ProblemsView::changeEvent(QEvent *event) {
    // The rows come again from whoever found them (in the new language); the headers and
    // the severities are ours.
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTreeView::changeEvent(event);
}

void ProblemsView::setDiagnostics(const std::vector<model::Diagnostic> &diagnostics) {
    std::vector<model::Diagnostic> sorted = diagnostics;
    model::sortDiagnostics(sorted);
    m_model->setDiagnostics(std::move(sorted));
    // Columns fit their contents (the rows in view and about a thousand more: Qt's measure),
    // but never narrower than a "Warning" with its icon, a code and a "rung 10, row 2": an
    // empty or short list does not squeeze its headers.
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

int ProblemsView::rowCount() const {
    return m_model->rowCount();
}

int ProblemsView::count(model::Severity severity) const {
    const auto &all = m_model->diagnostics();
    return static_cast<int>(std::count_if(
        all.begin(), all.end(), [severity](const auto &d) { return d.severity == severity; }));
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
    QTreeView::paintEvent(event);
    if (rowCount() > 0)
        return;
    // An empty list says so, instead of looking like it has not run.
    QPainter p(viewport());
    p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    p.drawText(viewport()->rect(), Qt::AlignCenter, tr("No problems found"));
}

const model::Diagnostic *ProblemsView::diagnosticAt(int row) const {
    const auto &all = m_model->diagnostics();
    if (row < 0 || row >= static_cast<int>(all.size()))
        return nullptr;
    return &all[static_cast<std::size_t>(row)];
}

void ProblemsView::contextMenuEvent(QContextMenuEvent *event) {
    const model::Diagnostic *d = diagnosticAt(indexAt(event->pos()).row());
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
