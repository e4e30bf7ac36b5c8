#include "scan_history.h"

#include <algorithm>
#include <limits>

namespace rung::simulator {

namespace {

// A burst of commands (a script writing inputs every scan) makes replays long: a checkpoint
// after this many keeps them short.
constexpr std::size_t kEventsPerCheckpoint = 10000;

} // namespace

ScanHistory::ScanHistory()
    : ScanHistory(Limits{}) {}

ScanHistory::ScanHistory(Limits limits)
    : m_limits(limits) {}

void ScanHistory::start(const Engine &engine) {
    std::lock_guard lock(m_mutex);
    m_checkpoints.clear();
    m_events.clear();
    m_checkpointBytes = 0;
    m_sinceCheckpointNs = 0;
    checkpoint(engine);
}

void ScanHistory::record(const Engine &engine, Action action) {
    std::lock_guard lock(m_mutex);
    m_events.push_back({engine.statistics().scans, engine.stoppedAt(), std::move(action)});
    ++m_eventsSinceCheckpoint;
}

void ScanHistory::afterScan(const Engine &engine, qint64 evalNs) {
    m_lastScan.store(engine.statistics().scans, std::memory_order_relaxed);
    m_lastMs.store(engine.statistics().timeMs, std::memory_order_relaxed);
    m_sinceCheckpointNs += std::max<qint64>(evalNs, 1);
    if (m_sinceCheckpointNs < m_limits.checkpointEvalNs &&
        m_eventsSinceCheckpoint < kEventsPerCheckpoint)
        return; // the usual scan: no lock, no copy
    std::lock_guard lock(m_mutex);
    checkpoint(engine);
    trim();
}

void ScanHistory::checkpoint(const Engine &engine) {
    Checkpoint c;
    c.scan = engine.statistics().scans;
    c.timeMs = engine.statistics().timeMs;
    c.periodMs = engine.periodMs();
    auto copy = std::make_shared<Engine>(engine);
    copy->setBreakpoints({});
    c.bytes = copy->memoryBytes();
    c.engine = std::move(copy);
    m_checkpointBytes += c.bytes;
    m_checkpoints.push_back(std::move(c));
    m_sinceCheckpointNs = 0;
    m_eventsSinceCheckpoint = 0;
    m_lastScan.store(engine.statistics().scans, std::memory_order_relaxed);
    m_lastMs.store(engine.statistics().timeMs, std::memory_order_relaxed);
}

void ScanHistory::trim() {
    const qint64 now = m_lastMs.load(std::memory_order_relaxed);
    auto dropFront = [this] {
        m_checkpointBytes -= m_checkpoints.front().bytes;
        m_checkpoints.pop_front();
    };
    // The window: the oldest checkpoint goes once the next one already covers it.
    while (m_checkpoints.size() >= 2 && m_checkpoints[1].timeMs <= now - m_limits.windowMs)
        dropFront();
    // Memory: thin the checkpoints evenly (drop the one whose neighbours are closest).
    while (m_checkpointBytes > m_limits.maxCheckpointBytes && m_checkpoints.size() > 2) {
        std::size_t best = 1;
        quint64 bestGap = std::numeric_limits<quint64>::max();
        for (std::size_t k = 1; k + 1 < m_checkpoints.size(); ++k) {
            const quint64 gap = m_checkpoints[k + 1].scan - m_checkpoints[k - 1].scan;
            if (gap < bestGap) {
                bestGap = gap;
                best = k;
            }
        }
        m_checkpointBytes -= m_checkpoints[best].bytes;
        m_checkpoints.erase(m_checkpoints.begin() + static_cast<std::ptrdiff_t>(best));
    }
    while (m_events.size() > m_limits.maxEvents && m_checkpoints.size() >= 2) {
        dropFront();
        while (!m_events.empty() && m_events.front().scan < m_checkpoints.front().scan)
            m_events.pop_front();
    }
    while (!m_events.empty() && m_events.front().scan < m_checkpoints.front().scan)
        m_events.pop_front();
}

ScanHistory::Window ScanHistory::window() const {
    std::lock_guard lock(m_mutex);
    Window w;
    if (m_checkpoints.empty()) {
        w.firstScan = 1;
        return w;
    }
    w.firstScan = m_checkpoints.front().scan;
    w.firstMs = m_checkpoints.front().timeMs;
    w.lastScan = std::max(m_lastScan.load(std::memory_order_relaxed), w.firstScan);
    w.lastMs = std::max(m_lastMs.load(std::memory_order_relaxed), w.firstMs);
    w.checkpoints = m_checkpoints.size();
    w.bytes = m_checkpointBytes + m_events.size() * sizeof(Event);
    return w;
}

std::vector<ScanHistory::Recorded> ScanHistory::recorded() const {
    std::lock_guard lock(m_mutex);
    std::vector<Recorded> out;
    out.reserve(m_events.size());
    for (const Event &e : m_events)
        out.push_back({e.scan, e.position, e.action});
    return out;
}

qint64 ScanHistory::firstPeriodMs() const {
    std::lock_guard lock(m_mutex);
    return m_checkpoints.empty() ? 10 : m_checkpoints.front().periodMs;
}

std::optional<quint64> ScanHistory::scanAt(qint64 timeMs) const {
    std::lock_guard lock(m_mutex);
    if (m_checkpoints.empty())
        return std::nullopt;
    const quint64 last =
        std::max(m_lastScan.load(std::memory_order_relaxed), m_checkpoints.front().scan);
    auto c = std::upper_bound(m_checkpoints.begin(), m_checkpoints.end(), timeMs,
                              [](qint64 t, const Checkpoint &k) { return t < k.timeMs; });
    if (c == m_checkpoints.begin())
        return m_checkpoints.front().scan;
    --c;
    quint64 scan = c->scan;
    qint64 time = c->timeMs;
    qint64 period = c->periodMs;
    auto e = std::lower_bound(m_events.begin(), m_events.end(), scan,
                              [](const Event &ev, quint64 s) { return ev.scan < s; });
    for (; e != m_events.end(); ++e) {
        const auto *set = std::get_if<SetPeriod>(&e->action);
        if (!set)
            continue;
        const qint64 at = time + static_cast<qint64>(e->scan - scan) * period;
        if (at > timeMs)
            break;
        scan = e->scan;
        time = at;
        period = std::max<qint64>(1, set->periodMs);
    }
    const quint64 result = scan + static_cast<quint64>((timeMs - time) / period);
    return std::min(result, last);
}

std::optional<model::Snapshot> ScanHistory::rebuild(quint64 scan) const {
    std::shared_ptr<const Engine> from;
    std::vector<Event> events;
    {
        std::lock_guard lock(m_mutex);
        if (m_checkpoints.empty() || scan < m_checkpoints.front().scan ||
            scan > std::max(m_lastScan.load(std::memory_order_relaxed), m_checkpoints.front().scan))
            return std::nullopt;
        auto c = std::upper_bound(m_checkpoints.begin(), m_checkpoints.end(), scan,
                                  [](quint64 s, const Checkpoint &k) { return s < k.scan; });
        --c; // the first checkpoint is at or before `scan`
        // At least one scan is run again, so its power flow is there to show.
        if (c->scan == scan && c != m_checkpoints.begin())
            --c;
        from = c->engine;
        auto e = std::lower_bound(m_events.begin(), m_events.end(), c->scan,
                                  [](const Event &ev, quint64 s) { return ev.scan < s; });
        for (; e != m_events.end() && e->scan < scan; ++e)
            events.push_back(*e);
    }
    Engine engine(*from);
    engine.setPowerFlowRecording(true);
    std::size_t k = 0;
    while (engine.statistics().scans < scan) {
        const quint64 now = engine.statistics().scans;
        for (; k < events.size() && events[k].scan <= now; ++k) {
            const Event &e = events[k];
            if (e.scan < now)
                continue;
            if (e.position >= 0 && engine.stoppedAt() != e.position)
                engine.advanceTo(e.position);
            if (const auto *set = std::get_if<SetPeriod>(&e.action))
                engine.setPeriodMs(set->periodMs);
            else
                applyCommand(engine, std::get<EngineCommand>(e.action), nullptr);
        }
        engine.scan();
    }
    model::Snapshot s = engine.snapshot();
    s.statistics.execNsCurrent = s.statistics.execNsMin = s.statistics.execNsMax = 0;
    return s;
}

} // namespace rung::simulator
