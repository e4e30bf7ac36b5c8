#include "symbol_table_model.h"

#include "document.h"

#include <algorithm>

namespace rung::editor {

SymbolTableModel::SymbolTableModel(Document *document, QObject *parent)
    : QAbstractTableModel(parent)
    , m_document(document)
    , m_rows(rows()) {
    // Every change of the symbols (an edit here, an import, undo, redo, another project)
    // comes as programChanged.
    connect(document, &Document::programChanged, this, &SymbolTableModel::sync);
}

void SymbolTableModel::setPending(const std::vector<model::PendingSymbol> &rows) {
    m_pending = rows;
    sync();
}

void SymbolTableModel::refresh() {
    sync();
}

void SymbolTableModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    sync(); // the reasons, in the new language
}

QString SymbolTableModel::whyPending(const model::PendingSymbol &row) const {
    if (row.device.isEmpty())
        return tr("No device yet: the row becomes a symbol when it names one");
    const auto parsed =
        model::parseAddress(m_document->target(), row.device, m_document->modelVariant());
    if (const auto *e = std::get_if<model::AddressError>(&parsed))
        return e->message;
    // Read from a file: a device of this PLC, taken into the symbols at the next edit.
    return tr("No symbol yet: edit the row to make it one");
}

std::vector<SymbolTableModel::Row> SymbolTableModel::rows() const {
    std::vector<Row> out;
    const auto &symbols = m_document->project().symbols;
    out.reserve(symbols.size() + m_pending.size() + 1);
    for (const model::Symbol &s : symbols)
        out.push_back({{model::formatAddress(m_document->target(), s.address), s.name, s.comment},
                       false,
                       {}});
    for (const model::PendingSymbol &p : m_pending)
        out.push_back({{p.device, p.name, p.comment}, true, whyPending(p)});
    out.push_back({}); // a free row for a new symbol
    return out;
}

void SymbolTableModel::changed(int first, int last, const std::vector<Row> &now) {
    // Rows first..last take their new content: the span that differs.
    while (first <= last &&
           m_rows[static_cast<std::size_t>(first)] == now[static_cast<std::size_t>(first)])
        ++first;
    while (last >= first &&
           m_rows[static_cast<std::size_t>(last)] == now[static_cast<std::size_t>(last)])
        --last;
    if (first > last)
        return;
    std::copy(now.begin() + first, now.begin() + last + 1, m_rows.begin() + first);
    emit dataChanged(index(first, 0), index(last, ColumnCount - 1));
}

void SymbolTableModel::sync() {
    const std::vector<Row> now = rows();
    const int before = static_cast<int>(m_rows.size());
    const int after = static_cast<int>(now.size());
    // The rows both have change in place; then the rows past them come or go at the end.
    changed(0, std::min(before, after) - 1, now);
    if (after > before) {
        beginInsertRows({}, before, after - 1);
        m_rows.insert(m_rows.end(), now.begin() + before, now.end());
        endInsertRows();
    } else if (after < before) {
        beginRemoveRows({}, after, before - 1);
        m_rows.resize(static_cast<std::size_t>(after));
        endRemoveRows();
    }
}

int SymbolTableModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int SymbolTableModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SymbolTableModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() ||
        !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Row &row = m_rows[static_cast<std::size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return row.cells[index.column()];
    case Qt::ToolTipRole:
        if (row.pending && index.column() == DeviceColumn)
            return row.why;
        break;
    case PendingRole:
        return row.pending;
    }
    return {};
}

bool SymbolTableModel::setData(const QModelIndex &index, const QVariant &value, int role) {
    if (role != Qt::EditRole || !index.isValid() ||
        !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return false;
    // The rows as shown with this cell as typed: the complete ones make the new symbol list
    // (one undo step when it changed), the others wait; a row cleared of everything goes.
    std::vector<Row> typed = m_rows;
    typed[static_cast<std::size_t>(index.row())].cells[index.column()] = value.toString();
    std::vector<model::Symbol> symbols;
    std::vector<model::PendingSymbol> pending;
    for (std::size_t r = 0; r < typed.size(); ++r) {
        const model::PendingSymbol row{typed[r].cells[DeviceColumn].trimmed(),
                                       typed[r].cells[NameColumn], typed[r].cells[CommentColumn]};
        if (row.device.isEmpty() && row.name.isEmpty() && row.comment.isEmpty())
            continue;
        if (!row.device.isEmpty()) {
            const auto parsed =
                model::parseAddress(m_document->target(), row.device, m_document->modelVariant());
            if (const auto *a = std::get_if<model::Address>(&parsed)) {
                symbols.push_back({*a, row.name, row.comment});
                continue;
            }
            if (static_cast<int>(r) == index.row())
                emit message(std::get<model::AddressError>(parsed).message);
        }
        pending.push_back(row);
    }
    const bool pendingChanged = pending != m_pending;
    m_pending = std::move(pending);
    m_document->setSymbols(symbols); // programChanged when it changed them: sync
    sync();
    if (pendingChanged)
        emit this->pendingChanged();
    return true;
}

Qt::ItemFlags SymbolTableModel::flags(const QModelIndex &index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable;
}

QVariant SymbolTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case DeviceColumn:
        return tr("Device");
    case NameColumn:
        return tr("Name");
    case CommentColumn:
        return tr("Comment");
    }
    return {};
}

} // namespace rung::editor
