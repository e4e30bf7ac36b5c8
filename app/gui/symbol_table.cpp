#include "symbol_table.h"

#include "editor/document.h"
#include "editor/symbol_table_model.h"
#include "model/project/symbols_csv.h"

#include "model/project/file_read.h"

#include <QDir>
#include <QEvent>
#include <QHeaderView>
#include <QIdentityProxyModel>
#include <QSaveFile>
#include <QStyle>

namespace rung::app {

namespace {
// A symbol table opened, imported: read no further than this.
constexpr qint64 kMaxCsvBytes = 64 * 1024 * 1024;

// A row that is no symbol yet, as the table shows it: its device's cell in the colours of an
// error (editor::SymbolTableModel::PendingRole; the tooltip says why).
class MarkedRows : public QIdentityProxyModel {
public:
    using QIdentityProxyModel::QIdentityProxyModel;

    QVariant data(const QModelIndex &index, int role) const override {
        if ((role == Qt::ForegroundRole || role == Qt::BackgroundRole) &&
            index.column() == editor::SymbolTableModel::DeviceColumn &&
            index.data(editor::SymbolTableModel::PendingRole).toBool())
            return role == Qt::ForegroundRole ? QColor(0xb0, 0x00, 0x20) : QColor(0xfd, 0xe7, 0xea);
        return QIdentityProxyModel::data(index, role);
    }
};

} // namespace

SymbolTable::SymbolTable(editor::Document *document, QWidget *parent)
    : QTableView(parent)
    , m_document(document)
    , m_model(new editor::SymbolTableModel(document, this)) {
    setObjectName(QStringLiteral("symbolsTable"));
    auto *shown = new MarkedRows(this);
    shown->setSourceModel(m_model);
    setModel(shown);
    horizontalHeader()->setStretchLastSection(true);
    setHeaders();
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    connect(m_model, &editor::SymbolTableModel::message, this, &SymbolTable::message);
    connect(m_model, &editor::SymbolTableModel::pendingChanged, this, &SymbolTable::pendingChanged);
}

void SymbolTable::setHeaders() {
    // The device and name columns as wide as their titles ("Operandus" was cut at 70 px),
    // never narrower than a device and a short name; the comment takes the rest.
    const QFontMetrics metrics(horizontalHeader()->font());
    const int padding = 2 * horizontalHeader()->style()->pixelMetric(QStyle::PM_HeaderMargin) + 12;
    auto title = [this](int column) {
        return m_model->headerData(column, Qt::Horizontal).toString();
    };
    setColumnWidth(editor::SymbolTableModel::DeviceColumn,
                   std::max(70, metrics.horizontalAdvance(title(0)) + padding));
    setColumnWidth(editor::SymbolTableModel::NameColumn,
                   std::max(90, metrics.horizontalAdvance(title(1)) + padding));
}

void SymbolTable::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        m_model->retranslate();
        setHeaders();
    }
    QTableView::changeEvent(event);
}

const std::vector<model::PendingSymbol> &SymbolTable::pending() const {
    return m_model->pending();
}

void SymbolTable::setPending(const std::vector<model::PendingSymbol> &rows) {
    m_model->setPending(rows);
}

void SymbolTable::refresh() {
    m_model->refresh();
}

bool SymbolTable::exportCsv(const QString &path, QString *error) const {
    QSaveFile file(path);
    const QByteArray bytes =
        model::symbolsToCsv(m_document->target(), m_document->project().symbols).toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error)
            *error = tr("%1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return false;
    }
    return true;
}

bool SymbolTable::importCsv(const QString &path, QString *error) {
    QByteArray bytes;
    QString ioError;
    if (const model::ReadStatus status = model::readAtMost(path, kMaxCsvBytes, &bytes, &ioError);
        status != model::ReadStatus::Ok) {
        *error = model::readFailure(status, path, kMaxCsvBytes, ioError);
        return false;
    }
    const model::SymbolsCsv csv = model::symbolsFromCsv(
        m_document->target(), m_document->modelVariant(), QString::fromUtf8(bytes));
    if (!csv.ok()) {
        *error = tr("%1, line %2: %3").arg(path).arg(csv.errorLine).arg(csv.error);
        return false;
    }
    m_document->setSymbols(csv.symbols);
    return true;
}

} // namespace rung::app
