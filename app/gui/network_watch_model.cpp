#include "app/gui/network_watch_model.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"
#include "network/network_session.h"

namespace rung::app {

QString exampleStationDevice(const network::NetworkSession *session) {
    if (!session || session->stations().empty())
        return QStringLiteral("STATION/DEVICE");
    const network::StationSource *s = session->stations().front();
    return s->stationName() + QLatin1Char('/') + model::exampleDevice(s->target());
}

NetworkWatchModel::NetworkWatchModel(QObject *parent)
    : QAbstractTableModel(parent) {
    m_beat.setSingleShot(true);
    m_beat.setInterval(model::MonitorSource::kMinSnapshotIntervalMs);
    connect(&m_beat, &QTimer::timeout, this, &NetworkWatchModel::refreshValues);
}

void NetworkWatchModel::setSession(network::NetworkSession *session) {
    if (m_session == session)
        return;
    beginResetModel();
    if (m_session)
        for (network::StationSource *s : m_session->stations())
            disconnect(s, nullptr, this, nullptr);
    m_session = session;
    m_rows.clear();
    for (const auto &shown : m_shown)
        if (shown.second)
            disconnect(shown.second, nullptr, this, nullptr);
    m_shown.clear();
    if (session)
        for (network::StationSource *s : session->stations())
            connect(s, &model::MonitorSource::snapshotChanged, this, [this] {
                if (!m_beat.isActive())
                    m_beat.start();
            });
    endResetModel();
}

bool NetworkWatchModel::addDevice(const QString &text, QString *error) {
    const QString trimmed = text.trimmed();
    const qsizetype slash = trimmed.indexOf(QLatin1Char('/'));
    if (!m_session) {
        *error = tr("No network is open");
        return false;
    }
    QStringList names;
    for (network::StationSource *s : m_session->stations())
        names << s->stationName();
    if (slash <= 0) {
        //: %1 what was typed, %2 the stations, e.g. "master, s5, s2"
        *error =
            tr("%1: write STATION/DEVICE, e.g. %2 (stations: %3)")
                .arg(trimmed, exampleStationDevice(m_session), names.join(QStringLiteral(", ")));
        return false;
    }
    network::StationSource *station = m_session->station(trimmed.left(slash).trimmed());
    if (!station) {
        *error = tr("%1: no station \"%2\" (stations: %3)")
                     .arg(trimmed, trimmed.left(slash).trimmed(), names.join(QStringLiteral(", ")));
        return false;
    }
    const auto parsed =
        model::parseAddress(station->target(), trimmed.mid(slash + 1).trimmed(), station->model());
    if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
        *error = QStringLiteral("%1: %2").arg(trimmed, e->message);
        return false;
    }
    const model::Address address = std::get<model::Address>(parsed);
    for (const Row &r : m_rows)
        if (r.station == station && r.address == address)
            return true;
    Row row;
    row.station = station;
    row.address = address;
    row.device = model::formatAddress(station->target(), address);
    row.bit = address.bit >= 0 ||
              station->target().areas[std::size_t(address.area)].kind == model::AreaKind::Bit;
    const int at = static_cast<int>(m_rows.size());
    beginInsertRows({}, at, at);
    m_rows.push_back(row);
    endInsertRows();
    return true;
}

void NetworkWatchModel::removeRow(int row) {
    if (row < 0 || row >= rowCount())
        return;
    beginRemoveRows({}, row, row);
    m_rows.erase(m_rows.begin() + row);
    endRemoveRows();
}

QStringList NetworkWatchModel::devices() const {
    QStringList out;
    for (const Row &r : m_rows)
        out << (r.station ? r.station->stationName() : QString()) + QLatin1Char('/') + r.device;
    return out;
}

int NetworkWatchModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int NetworkWatchModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant NetworkWatchModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Row &r = m_rows[std::size_t(index.row())];
    if (role == Qt::TextAlignmentRole && index.column() == Value)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::EditRole)
        return {};
    switch (index.column()) {
    case Device:
        return (r.station ? r.station->stationName() : QString()) + QLatin1Char('/') + r.device;
    case Station:
        return r.station && r.station->model() ? r.station->model()->name : QString();
    case Value: {
        const model::MonitorSource *from = source(r);
        const auto snapshot = from ? from->snapshot() : nullptr;
        if (!snapshot)
            return role == Qt::EditRole ? QVariant(0) : QVariant(QStringLiteral("-"));
        if (r.bit) {
            const bool on = snapshot->bit(r.address);
            return role == Qt::EditRole ? QVariant(on ? 1 : 0)
                                        : QVariant(on ? tr("ON") : tr("OFF"));
        }
        return QVariant::fromValue<qint64>(snapshot->value(r.address));
    }
    default:
        return {};
    }
}

QVariant NetworkWatchModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Device:
        return tr("Station/Device");
    case Value:
        return tr("Value");
    case Station:
        //: the PLC model of the row's station ("VB", "PL110-2A")
        return tr("Model");
    default:
        return {};
    }
}

Qt::ItemFlags NetworkWatchModel::flags(const QModelIndex &index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Value)
        f |= Qt::ItemIsEditable;
    return f;
}

bool NetworkWatchModel::setData(const QModelIndex &index, const QVariant &value, int role) {
    if (role != Qt::EditRole || !index.isValid() || index.column() != Value ||
        index.row() >= rowCount())
        return false;
    const Row &r = m_rows[std::size_t(index.row())];
    if (!r.station)
        return false;
    const QString text = value.toString().trimmed();
    if (r.bit) {
        const bool on = text == QLatin1String("1") ||
                        text.compare(tr("ON"), Qt::CaseInsensitive) == 0 ||
                        text.compare(QLatin1String("on"), Qt::CaseInsensitive) == 0;
        source(r)->writeBit(r.address, on);
        return true;
    }
    bool ok = false;
    const qint64 number = text.toLongLong(&ok);
    if (!ok)
        return false;
    source(r)->writeWord(r.address, number);
    return true;
}

void NetworkWatchModel::setShownSource(network::StationSource *station,
                                       model::MonitorSource *shown) {
    for (auto it = m_shown.begin(); it != m_shown.end();)
        if (!it->first || it->first == station) {
            if (it->second && it->second != shown)
                disconnect(it->second, nullptr, this, nullptr);
            it = m_shown.erase(it);
        } else {
            ++it;
        }
    if (shown && shown != station) {
        m_shown.emplace_back(station, shown);
        connect(shown, &model::MonitorSource::snapshotChanged, this, [this] {
            if (!m_beat.isActive())
                m_beat.start();
        });
    }
    refreshValues();
}

model::MonitorSource *NetworkWatchModel::source(const Row &row) const {
    for (const auto &[station, shown] : m_shown)
        if (station == row.station && shown)
            return shown;
    return row.station;
}

void NetworkWatchModel::refreshValues() {
    if (!m_rows.empty())
        emit dataChanged(index(0, Value), index(rowCount() - 1, Value), {Qt::DisplayRole});
}

} // namespace rung::app
