#include "comms/driver/traffic.h"

namespace rung::comms {

TrafficTap::TrafficTap()
    : m_startWall(QDateTime::currentDateTime()) {
    m_clock.start();
}

void TrafficTap::setEnabled(bool on) {
    std::lock_guard lock(m_mutex);
    m_enabled = on;
}

bool TrafficTap::enabled() const {
    std::lock_guard lock(m_mutex);
    return m_enabled;
}

void TrafficTap::append(TrafficRecord::Direction direction, QByteArrayView bytes) {
    if (bytes.isEmpty())
        return;
    std::lock_guard lock(m_mutex);
    if (!m_enabled)
        return;
    m_ring.push_back({m_next++, m_clock.nsecsElapsed() / 1000, direction, bytes.toByteArray()});
    while (m_ring.size() > kCapacity)
        m_ring.pop_front();
}

std::vector<TrafficRecord> TrafficTap::records(quint64 from, quint64 *next) const {
    std::lock_guard lock(m_mutex);
    std::vector<TrafficRecord> out;
    for (const TrafficRecord &r : m_ring)
        if (r.sequence >= from)
            out.push_back(r);
    if (next)
        *next = m_next;
    return out;
}

void TrafficTap::clear() {
    std::lock_guard lock(m_mutex);
    m_ring.clear();
}

} // namespace rung::comms
