#pragma once

// What a connection panel shows about a link (issue 13): counters, round-trip times and a
// tap of the bytes both ways, time-stamped. The driver's worker thread writes; any thread
// reads. The tap keeps the last kCapacity records in a ring: a UI that subscribes pulls what
// is new since the sequence number it saw last (records(from)), so a slow reader loses the
// oldest records, never the driver's time.

#include <QByteArray>
#include <QDateTime>
#include <QElapsedTimer>

#include <cstdint>
#include <deque>
#include <mutex>
#include <vector>

namespace rung::comms {

struct LinkStatistics {
    quint64 requests = 0;   // frames sent (every attempt, retries included)
    quint64 replies = 0;    // valid replies received
    quint64 retries = 0;    // requests sent again after noise, a broken reply or silence
    quint64 timeouts = 0;   // attempts that ended in silence or a reply that stopped
    quint64 errors = 0;     // exchanges that failed after their retries (or were refused)
    quint64 refusals = 0;   // the PLC answered with an error / exception / end code
    quint64 reconnects = 0; // the link came back after it was lost
    quint64 bytesSent = 0;
    quint64 bytesReceived = 0;
    quint64 refreshes = 0;      // complete polls of the watched devices
    double lastRoundTripMs = 0; // request sent -> reply complete, the last good exchange
    double minRoundTripMs = 0;
    double maxRoundTripMs = 0;
    double meanRoundTripMs = 0; // over every good exchange
    double lastRefreshMs = 0;   // the last complete poll of the watched devices
    int framesPerRefresh = 0;   // of the current plan
    int bytesPerRefresh = 0;    // of the current plan, request and reply
};

struct TrafficRecord {
    enum class Direction : std::uint8_t { Sent, Received };
    quint64 sequence = 0;
    qint64 timeUs = 0; // since TrafficTap::start() (a monotonic clock)
    Direction direction = Direction::Sent;
    QByteArray bytes;
};

class TrafficTap {
public:
    static constexpr std::size_t kCapacity = 4096;

    TrafficTap();
    // Wall-clock time of timeUs 0, to print a record's time of day.
    QDateTime start() const { return m_startWall; }
    void setEnabled(bool on);
    bool enabled() const;
    void append(TrafficRecord::Direction direction, QByteArrayView bytes);
    // The records with sequence >= from, oldest first; *next is the sequence to ask for next
    // time. Records older than the ring are gone: the first returned says where it resumes.
    std::vector<TrafficRecord> records(quint64 from, quint64 *next = nullptr) const;
    void clear();

private:
    mutable std::mutex m_mutex;
    QDateTime m_startWall;
    QElapsedTimer m_clock;
    bool m_enabled = true;
    quint64 m_next = 0;
    std::deque<TrafficRecord> m_ring;
};

} // namespace rung::comms
