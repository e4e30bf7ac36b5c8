#pragma once

// The recent past of a simulation, able to show any scan of it again. The engine is
// deterministic on virtual time, so the record is only what came from outside, scan by scan:
// the commands applied (inputs written, forces, power cycles, online edits; at a scan
// boundary or at the instruction where a stopped scan took them) and period changes, plus
// checkpoints: copies of the whole engine, taken each time the scans since the last one
// have cost Limits::checkpointEvalNs (10 ms) of evaluation. Rebuilding scan N copies the checkpoint
// at or before N and runs the record on from there: at most that much evaluation, whatever N.
//
// The window is bounded: the oldest checkpoint goes once the next one is at least
// Limits::windowMs (an hour) of virtual time old (so at least the last hour is kept, and at most
// one checkpoint interval more), and checkpoints are thinned evenly when they pass
// Limits::maxCheckpointBytes (64 MB; a rebuild then re-runs more scans, never shows anything else).
//
// Threads: the session's worker records (start, record, afterScan); any thread reads
// (window, scanAt, rebuild) under the history's lock, which the worker takes only to add a
// checkpoint or an event. rebuild() runs outside the lock on copies.

#include "command_inbox.h"
#include "engine.h"

#include <QtGlobal>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <variant>
#include <vector>

namespace rung::simulator {

class ScanHistory {
public:
    struct Limits {
        qint64 windowMs = 3600 * 1000;              // virtual time kept
        qint64 checkpointEvalNs = 10 * 1000 * 1000; // evaluation between checkpoints
        std::size_t maxCheckpointBytes = 64u << 20; // then thinned
        std::size_t maxEvents = 1000000;            // then the oldest checkpoint goes
    };

    struct SetPeriod {
        qint64 periodMs = 10;
    };
    using Action = std::variant<EngineCommand, SetPeriod>;

    struct Window {
        quint64 firstScan = 0; // the oldest scan that can be shown
        quint64 lastScan = 0;  // the newest (the scans completed)
        qint64 firstMs = 0;    // their virtual times (at the end of the scan)
        qint64 lastMs = 0;
        std::size_t checkpoints = 0;
        std::size_t bytes = 0; // checkpoints and record
        bool empty() const { return lastScan < firstScan; }
    };

    ScanHistory();
    explicit ScanHistory(Limits limits);

    // Worker: forgets the past and starts from the engine as it is (at a scan boundary).
    void start(const Engine &engine);
    // Worker: an action about to be applied to the engine (at its present position).
    void record(const Engine &engine, Action action);
    // Worker: after every completed scan; evalNs = what it cost.
    void afterScan(const Engine &engine, qint64 evalNs);

    // Any thread.
    Window window() const;
    // The last scan whose end is at or before timeMs (clamped to the window); empty when
    // nothing is recorded.
    std::optional<quint64> scanAt(qint64 timeMs) const;
    // The image after `scan` (its statistics: scans and virtual time; power flow recorded),
    // empty when the scan is outside the window.
    std::optional<model::Snapshot> rebuild(quint64 scan) const;
    // What came from outside in the window, oldest first: the completed scans when it was
    // applied, where inside a stopped scan (-1: at a boundary), and what (a scenario is
    // recorded from it: scenario_record.h).
    struct Recorded {
        quint64 scan = 0;
        int position = -1;
        Action action;
    };
    std::vector<Recorded> recorded() const;
    // The scan period the window starts with.
    qint64 firstPeriodMs() const;

private:
    struct Checkpoint {
        quint64 scan = 0;
        qint64 timeMs = 0;
        qint64 periodMs = 10;
        std::shared_ptr<const Engine> engine;
        std::size_t bytes = 0;
    };
    struct Event {
        quint64 scan = 0;  // completed scans when it was applied
        int position = -1; // the stopped scan's next instruction; -1 at a boundary
        Action action;
    };

    void checkpoint(const Engine &engine); // under m_mutex
    void trim();                           // under m_mutex

    Limits m_limits;
    mutable std::mutex m_mutex;
    std::deque<Checkpoint> m_checkpoints;
    std::deque<Event> m_events;
    std::size_t m_checkpointBytes = 0;
    std::atomic<quint64> m_lastScan{0};
    std::atomic<qint64> m_lastMs{0};
    // Worker only.
    qint64 m_sinceCheckpointNs = 0;
    std::size_t m_eventsSinceCheckpoint = 0;
};

} // namespace rung::simulator
