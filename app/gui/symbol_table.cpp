#include "symbol_table.h"

#include "editor/document.h"
#include "model/project/symbols_csv.h"

#include "model/project/file_read.h"

#include <QDir>
#include <QEvent>
#include <QHeaderView>
#include <QSaveFile>
#include <QStyle>

namespace rung::app {

namespace {
// A symbol table opened, imported: read no further than this.
constexpr qint64 kMaxCsvBytes = 64 * 1024 * 1024;
} // namespace

SymbolTable::SymbolTable(editor::Document *document, QWidget *parent)
    : QTableWidget(0, 3, parent)
    , m_document(document) {
    setObjectName(QStringLiteral("symbolsTable"));
    horizontalHeader()->setStretchLastSection(true);
    setHeaders();
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    connect(this, &QTableWidget::cellChanged, this, [this](int row, int) {
        if (!m_updating)
            edited(row);
    });
}

void SymbolTable::setHeaders() {
    const QStringList titles{tr("Device"), tr("Name"), tr("Comment")};
    setHorizontalHeaderLabels(titles);
    // The device and name columns as wide as their titles ("Operandus" was cut at 70 px),
    // never narrower than a device and a short name; the comment takes the rest.
    const QFontMetrics metrics(horizontalHeader()->font());
    const int padding = 2 * horizontalHeader()->style()->pixelMetric(QStyle::PM_HeaderMargin) + 12;
    setColumnWidth(0, std::max(70, metrics.horizontalAdvance(titles[0]) + padding));
    setColumnWidth(1, std::max(90, metrics.horizontalAdvance(titles[1]) + padding));
}

void SymbolTable::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        setHeaders();
    QTableWidget::changeEvent(event);
}

void SymbolTable::setPending(const std::vector<model::PendingSymbol> &rows) {
    m_pending = rows;
}

void SymbolTable::edited(int row) {
    // Edited in place: the complete rows make the new symbol list (one undo step when it
    // changed), the others wait in the table; a row cleared of everything goes.
    std::vector<model::Symbol> symbols;
    const std::vector<model::PendingSymbol> before = std::move(m_pending);
    m_pending.clear();
    auto text = [this](int r, int c) { return item(r, c) ? item(r, c)->text() : QString(); };
    for (int r = 0; r < rowCount(); ++r) {
        const model::PendingSymbol typed{text(r, 0).trimmed(), text(r, 1), text(r, 2)};
        if (typed.device.isEmpty() && typed.name.isEmpty() && typed.comment.isEmpty())
            continue;
        const auto parsed =
            typed.device.isEmpty()
                ? std::variant<model::Address, model::AddressError>(model::AddressError{})
                : model::parseAddress(m_document->target(), typed.device,
                                      m_document->modelVariant());
        if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
            if (r == row && !typed.device.isEmpty())
                emit message(e->message);
            m_pending.push_back(typed);
            continue;
        }
        symbols.push_back({std::get<model::Address>(parsed), typed.name, typed.comment});
    }
    m_document->setSymbols(symbols); // refreshes the table when it changed anything
    refresh();
    if (m_pending != before)
        emit pendingChanged();
}

void SymbolTable::refresh() {
    m_updating = true;
    const auto &symbols = m_document->project().symbols;
    const int count = static_cast<int>(symbols.size());
    const int pending = static_cast<int>(m_pending.size());
    setRowCount(count + pending + 1); // a free row for a new symbol
    for (int r = 0; r < count; ++r) {
        const model::Symbol &s = symbols[static_cast<std::size_t>(r)];
        setItem(r, 0, new QTableWidgetItem(model::formatAddress(m_document->target(), s.address)));
        setItem(r, 1, new QTableWidgetItem(s.name));
        setItem(r, 2, new QTableWidgetItem(s.comment));
    }
    for (int i = 0; i < pending; ++i) {
        const model::PendingSymbol &p = m_pending[static_cast<std::size_t>(i)];
        auto *device = new QTableWidgetItem(p.device);
        if (!p.device.isEmpty()) {
            const auto parsed =
                model::parseAddress(m_document->target(), p.device, m_document->modelVariant());
            if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
                device->setForeground(QColor(0xb0, 0x00, 0x20));
                device->setBackground(QColor(0xfd, 0xe7, 0xea));
                device->setToolTip(e->message);
            }
        }
        setItem(count + i, 0, device);
        setItem(count + i, 1, new QTableWidgetItem(p.name));
        setItem(count + i, 2, new QTableWidgetItem(p.comment));
    }
    for (int c = 0; c < 3; ++c)
        setItem(count + pending, c, new QTableWidgetItem);
    m_updating = false;
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
