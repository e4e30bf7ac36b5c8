#include "network/station_past_source.h"

#include "network/network_session.h"

namespace rung::network {

StationPastSource::StationPastSource(std::shared_ptr<const NetworkHistory> history,
                                     std::size_t index, StationSource *live, QObject *parent)
    : MonitorSource(parent)
    , m_history(std::move(history))
    , m_index(index)
    , m_live(live) {
    // Paused: the views draw the values as a stopped simulation's, not as a PLC gone offline.
    setRunState(RunState::Paused);
}

StationPastSource::~StationPastSource() = default;

bool StationPastSource::show(qint64 us) {
    std::optional<model::Snapshot> s = m_history->stationAt(m_index, us);
    if (!s)
        return false;
    publishSnapshot(std::make_shared<const model::Snapshot>(std::move(*s)), true);
    return true;
}

bool StationPastSource::watchHistory(const model::Address &address) {
    return m_live && m_live->watchHistory(address);
}

void StationPastSource::readHistory(
    const std::function<void(const model::HistoryRecorder &)> &read) const {
    if (m_live)
        m_live->readHistory(read);
}

QString StationPastSource::forceRefusal() const {
    return tr("history is read-only: return to live to write, force or release");
}

void StationPastSource::startCommand(CommandId id, const model::DeviceCommand &) {
    finishCommand(id, false, forceRefusal());
}

} // namespace rung::network
