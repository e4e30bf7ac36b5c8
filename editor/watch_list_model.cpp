#include "watch_list_model.h"

#include "device_mime.h"
#include "document.h"

#include "model/image/power_flow.h"

#include <algorithm>

namespace rung::editor {

WatchListModel::WatchListModel(Document *document, QObject *parent)
    : QAbstractItemModel(parent)
    , m_document(document) {
    connect(document, &Document::programChanged, this, &WatchListModel::follow);
    follow();
}

// Rows: a list's index carries 0, a device row's the number of its list plus one.
QModelIndex WatchListModel::index(int row, int column, const QModelIndex &parent) const {
    if (!hasIndex(row, column, parent))
        return {};
    return parent.isValid() ? createIndex(row, column, static_cast<quintptr>(parent.row()) + 1)
                            : createIndex(row, column, quintptr{0});
}

QModelIndex WatchListModel::parent(const QModelIndex &child) const {
    if (!child.isValid() || child.internalId() == 0)
        return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, quintptr{0});
}

int WatchListModel::rowCount(const QModelIndex &parent) const {
    if (!parent.isValid())
        return static_cast<int>(m_lists.size());
    if (parent.internalId() != 0 || parent.column() != 0)
        return 0;
    return static_cast<int>(m_lists[static_cast<std::size_t>(parent.row())].rows.size());
}

int WatchListModel::columnCount(const QModelIndex &) const {
    return Columns;
}

bool WatchListModel::isDevice(const QModelIndex &index) const {
    return rowAt(index) != nullptr;
}

int WatchListModel::listOf(const QModelIndex &index) const {
    if (!index.isValid() || index.model() != this)
        return -1;
    return index.internalId() == 0 ? index.row() : static_cast<int>(index.internalId() - 1);
}

const WatchListModel::Row *WatchListModel::rowAt(const QModelIndex &index) const {
    if (!index.isValid() || index.model() != this || index.internalId() == 0)
        return nullptr;
    const auto list = static_cast<std::size_t>(index.internalId() - 1);
    if (list >= m_lists.size() || index.row() >= static_cast<int>(m_lists[list].rows.size()))
        return nullptr;
    return &m_lists[list].rows[static_cast<std::size_t>(index.row())];
}

QString WatchListModel::device(const QModelIndex &index) const {
    const Row *row = rowAt(index);
    return row ? row->device : QString();
}

std::optional<model::Address> WatchListModel::address(const QModelIndex &index) const {
    const Row *row = rowAt(index);
    return row ? row->address : std::nullopt;
}

bool WatchListModel::isBit(const model::Address &address) const {
    return address.bit >= 0 ||
           (address.valid() && m_target->area(address.area).kind == model::AreaKind::Bit);
}

bool WatchListModel::isBit(const QModelIndex &index) const {
    const auto a = address(index);
    return a && isBit(*a);
}

bool WatchListModel::isElement(const model::Address &address) const {
    if (address.bit >= 0 || !address.valid())
        return false;
    const model::AreaKind kind = m_target->area(address.area).kind;
    return kind == model::AreaKind::Timer || kind == model::AreaKind::Counter;
}

bool WatchListModel::isElement(const QModelIndex &index) const {
    const auto a = address(index);
    return a && isElement(*a);
}

int WatchListModel::bitsOf(const model::Address &address) const {
    return m_target->area(address.area).wordBits;
}

model::ValueFormat WatchListModel::format(const QModelIndex &index) const {
    const Row *row = rowAt(index);
    return row ? row->format : model::ValueFormat::Decimal;
}

std::shared_ptr<const model::Snapshot> WatchListModel::snapshot() const {
    std::shared_ptr<const model::Snapshot> s = m_source ? m_source->snapshot() : nullptr;
    return s && s->layout && &s->layout->target() == m_target ? s : nullptr;
}

QString WatchListModel::valueText(const Row &row, const model::Snapshot &snapshot) const {
    const model::Address &a = *row.address;
    const int bits = bitsOf(a);
    const model::ValueFormat f = row.format;
    QString text;
    if (isBit(a))
        text = snapshot.bit(a) ? tr("ON") : tr("OFF");
    else if (isElement(a)) {
        // Current value against the preset (a constant one as the program has it; "?" online
        // where no protocol area holds it), and the done bit.
        const std::optional<qint64> preset =
            model::ProgramFlow::presetWordOf(*m_target, row.box, a, snapshot);
        text = tr("%1 of %2, %3")
                   .arg(model::formatValue(snapshot.value(a), bits, f),
                        preset ? model::formatValue(static_cast<std::int32_t>(*preset), bits, f)
                               : QStringLiteral("?"),
                        snapshot.bit(a) ? tr("ON") : tr("OFF"));
    } else
        text = model::formatValue(snapshot.value(a), bits, f);
    return snapshot.forced(a) ? tr("%1 (forced)").arg(text) : text;
}

QVariant WatchListModel::data(const QModelIndex &index, int role) const {
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const Row *row = rowAt(index);
    if (!row) { // a list
        if (index.column() != DeviceColumn)
            return {};
        const QString &name = m_lists[static_cast<std::size_t>(index.row())].name;
        if (role == Qt::DisplayRole || role == Qt::EditRole)
            return name;
        if (role == Qt::AccessibleTextRole)
            return tr("Watch list %1").arg(name);
        return {};
    }
    const bool text = role == Qt::DisplayRole || role == Qt::EditRole;
    switch (index.column()) {
    case DeviceColumn:
        return text ? QVariant(row->device) : QVariant();
    case SymbolColumn:
        if (text)
            return row->symbol;
        return role == Qt::ToolTipRole && !row->comment.isEmpty() ? QVariant(row->comment)
                                                                  : QVariant();
    case FormatColumn:
        return text ? QVariant(row->address && !isBit(*row->address)
                                   ? model::valueFormatName(row->format)
                                   : QString())
                    : QVariant();
    default:
        break;
    }
    // The value and force columns: what the latest snapshot holds.
    if (!row->address)
        return index.column() == ValueColumn && role == Qt::DisplayRole ? tr("not a device")
                                                                        : QVariant();
    const std::shared_ptr<const model::Snapshot> s = snapshot();
    const model::Address &a = *row->address;
    const bool forced = s && s->forced(a);
    if (role == ForcedRole)
        return forced;
    if (index.column() == ValueColumn) {
        if (role == Qt::DisplayRole)
            return s ? valueText(*row, *s) : QString();
        // The editor opens on the value alone, in the row's format, not on "12 (forced)".
        if (role == Qt::EditRole)
            return !s         ? QString()
                   : isBit(a) ? (s->bit(a) ? tr("ON") : tr("OFF"))
                              : model::formatValue(s->value(a), bitsOf(a), row->format);
        return {};
    }
    if (!s)
        return role == Qt::DisplayRole ? QVariant(QString()) : QVariant();
    const bool bit = isBit(a);
    const QString state = s->bit(a) ? tr("ON") : tr("OFF");
    if (role == Qt::DisplayRole)
        return forced && bit ? state : QString();
    if (role == Qt::AccessibleTextRole)
        return !forced ? tr("Not forced") : bit ? tr("Forced %1").arg(state) : tr("Forced");
    return {};
}

Qt::ItemFlags WatchListModel::flags(const QModelIndex &index) const {
    if (!index.isValid())
        return Qt::ItemIsDropEnabled;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsDropEnabled;
    const Row *row = rowAt(index);
    if (!row)
        return f;
    f |= Qt::ItemIsDragEnabled | Qt::ItemNeverHasChildren;
    // What can be written: a bit or a word, not a timer's or counter's current value.
    if (index.column() == ValueColumn && m_source && row->address && !isElement(index))
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant WatchListModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case DeviceColumn:
            return tr("Device");
        case SymbolColumn:
            return tr("Symbol");
        case ValueColumn:
            return tr("Value");
        case FormatColumn:
            return tr("Format");
        case ForceColumn:
            return tr("Forced");
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case ValueColumn:
            return tr("Double-click or F2: write a value; a bit flips");
        case FormatColumn:
            return tr("Double-click: show the word in decimal, signed, "
                      "hexadecimal, binary or BCD");
        case ForceColumn:
            return tr("Double-click: force a bit ON or OFF, or release it");
        }
    }
    return {};
}

void WatchListModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, Columns - 1);
    if (m_lists.empty())
        return;
    emit dataChanged(index(0, 0), index(rowCount() - 1, Columns - 1));
    for (int i = 0; i < rowCount(); ++i)
        if (const int n = rowCount(index(i, 0)); n > 0)
            emit dataChanged(index(0, 0, index(i, 0)), index(n - 1, Columns - 1, index(i, 0)));
}

void WatchListModel::setMonitorSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    m_told.clear();
    if (source) {
        connect(source, &model::MonitorSource::snapshotChanged, this,
                &WatchListModel::valuesChanged);
        connect(source, &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                    if (!ok)
                        emit message(error);
                });
        tellWatched(true);
    }
    valuesChanged(); // the values, and whether the value column takes one
}

void WatchListModel::valuesChanged() {
    // Only the cells that show the snapshot: a list of 500 devices at 30 snapshots a second
    // repaints what is in view, nothing is rebuilt.
    static const QList<int> roles{Qt::DisplayRole, Qt::EditRole, Qt::AccessibleTextRole,
                                  ForcedRole};
    for (int i = 0; i < rowCount(); ++i) {
        const QModelIndex list = index(i, 0);
        if (const int n = rowCount(list); n > 0) {
            emit dataChanged(index(0, ValueColumn, list), index(n - 1, ValueColumn, list), roles);
            emit dataChanged(index(0, ForceColumn, list), index(n - 1, ForceColumn, list), roles);
        }
    }
}

QStringList WatchListModel::mimeTypes() const {
    return {deviceMimeType(), QStringLiteral("text/plain")};
}

QMimeData *WatchListModel::mimeData(const QModelIndexList &indexes) const {
    // In the table's order, whatever order the selection was made in.
    std::vector<std::pair<std::pair<int, int>, QString>> rows;
    for (const QModelIndex &index : indexes)
        if (const Row *row = rowAt(index))
            rows.push_back({{listOf(index), index.row()}, row->device});
    std::sort(rows.begin(), rows.end());
    QStringList devices;
    for (const auto &row : rows)
        if (!devices.contains(row.second))
            devices << row.second;
    return devices.isEmpty() ? nullptr : deviceMimeData(devices);
}

bool WatchListModel::canDropMimeData(const QMimeData *data, Qt::DropAction action, int, int,
                                     const QModelIndex &) const {
    return data && action == Qt::CopyAction && !devicesFromMime(data).isEmpty();
}

bool WatchListModel::dropMimeData(const QMimeData *data, Qt::DropAction action, int row, int column,
                                  const QModelIndex &parent) {
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    return addDevices(devicesFromMime(data), std::max(0, listOf(parent)));
}

bool WatchListModel::refuseElement(const Row &row) {
    if (!isElement(*row.address))
        return false;
    // The scan engine computes a timer's or counter's current value from the element's own
    // state every scan, so a written value would be gone at the next scan: say so instead.
    emit message(tr("%1 is a timer or counter: its current value follows the program and "
                    "cannot be written here")
                     .arg(row.device));
    return true;
}

bool WatchListModel::checkWritable(const QModelIndex &index) {
    const Row *row = rowAt(index);
    return m_source && row && row->address && !refuseElement(*row);
}

bool WatchListModel::flipBit(const QModelIndex &index) {
    if (!checkWritable(index) || !isBit(index))
        return false;
    const std::shared_ptr<const model::Snapshot> s = snapshot();
    m_source->writeBit(*address(index), !(s && s->bit(*address(index))));
    return true;
}

bool WatchListModel::setData(const QModelIndex &index, const QVariant &value, int role) {
    if (role != Qt::EditRole || index.column() != ValueColumn || !isDevice(index))
        return false;
    if (!writeValue(index, value.toString()))
        return false;
    // The row shows what the source holds (the value written once a snapshot has it): a write
    // can be refused (a past scan is read-only) or wait for the user's yes (the first write
    // to a PLC), and a value nobody wrote must not stand in the table meanwhile.
    emit dataChanged(index, index);
    return true;
}

bool WatchListModel::writeValue(const QModelIndex &index, const QString &text) {
    const Row *row = rowAt(index);
    if (!m_source || !row || !row->address || refuseElement(*row))
        return false;
    const model::Address a = *row->address;
    const QString device = row->device;
    const QString typed = text.trimmed();
    if (isBit(a)) {
        const bool on = typed == QLatin1String("1") ||
                        typed.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0 ||
                        typed.compare(tr("ON"), Qt::CaseInsensitive) == 0;
        const bool off = typed == QLatin1String("0") ||
                         typed.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0 ||
                         typed.compare(tr("OFF"), Qt::CaseInsensitive) == 0;
        if (!on && !off) {
            emit message(
                tr("\"%1\" is no value for %2: type ON or OFF (1 or 0)").arg(typed, device));
            return false;
        }
        m_source->writeBit(a, on);
        return true;
    }
    const int bits = bitsOf(a);
    const model::ValueFormat f = row->format;
    const auto value = model::parseValue(typed, bits, f);
    if (const auto *v = std::get_if<std::int64_t>(&value)) {
        m_source->writeWord(a, *v);
        return true;
    }
    QString hint;
    switch (f) {
    case model::ValueFormat::Decimal:
    case model::ValueFormat::Signed:
        hint = tr("type a whole number (0x before a hexadecimal one)");
        break;
    case model::ValueFormat::Hex:
        hint = tr("type up to %1 hexadecimal digits").arg(bits / 4);
        break;
    case model::ValueFormat::Binary:
        hint = tr("type up to %1 binary digits (0 and 1)").arg(bits);
        break;
    case model::ValueFormat::Bcd:
        hint = tr("type up to %1 decimal digits (BCD)").arg(bits / 4);
        break;
    }
    bool number = false;
    typed.toLongLong(&number);
    if (number && (f == model::ValueFormat::Decimal || f == model::ValueFormat::Signed))
        hint = tr("a %1-bit word holds %2..%3")
                   .arg(bits)
                   .arg(-(qint64{1} << (bits - 1)))
                   .arg((qint64{1} << bits) - 1);
    emit message(tr("\"%1\" is no value for %2: %3").arg(typed, device, hint));
    return false;
}

} // namespace rung::editor
