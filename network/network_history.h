#pragma once

// The recent past of a whole network, able to show every station at any instant of it
// (docs/network.md, "History across the network").
//
// Why a record and not a replay: one PLC's past is rebuilt by running its engine again from a
// checkpoint (simulator/scan_history.h), but a station alone cannot be run again: what its
// ports received came from the other stations, and a copy of the whole network would have to
// copy every port's protocol state, every slave's half-read frame and the frames in flight on
// the wires. What the views show of a station is its image, its forced bits, its statistics,
// the power flow of its last scan and when its ports last carried a byte (the front panel's
// COMM lamp), so that is what is kept: after each slice of virtual time, every station's words
// that changed since the slice before (a few dozen in a scan of a typical program), and now
// and then a copy of every station (a key: the blocks of its image that are not all 0) from
// which the changes run on. Showing an instant copies the key at or before it and applies the
// changes up to it: what is shown is what the station held then, word for word, by
// construction.
//
// The window is bounded by memory: once the record passes Limits::maxBytes, the oldest key
// and the changes that run from it go. A key is taken every Limits::keyEvery instants, when
// the changes since the last one have cost as much as a copy of every word, and whenever a
// station's forced bits or its power-flow recording changed, so a rebuild applies at most
// keyEvery changes.
//
// Cost: finding the changed words compares, of each station, only the words a scan of its
// program can write (simulator/scan_writes.h: its destinations, the system devices, the
// inputs; a few hundred of a Vigor VB's ten thousand) and the words written between its
// scans, which their writers mark (Station::written: a link's exchange, a slave's write);
// after commands (a write, a force, a power cycle, an online edit), after a write a writer
// could not place, when a station's program changed, and for a program whose scan may write
// anywhere (an index register, a communication instruction), the whole image (a vectorized
// pass a block of 64 words). BM_NetworkHistoryRatio, docs/performance.md.
//
// Threads: the session's worker records (start, record); any thread reads (window, at,
// stationAt) under the history's lock, which the worker takes only to append an instant.
// The comparison with the slice before runs outside the lock, on the worker's own copy.

#include "network/history_arena.h"

#include "model/image/snapshot.h"

#include <QtGlobal>

#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace rung::network {

class Network;

class NetworkHistory {
public:
    struct Limits {
        std::size_t maxBytes = 128u << 20; // then the oldest key and its changes go
        std::size_t keyEvery = 1000;       // instants between two keys at most
    };
    struct Window {
        qint64 firstUs = 0; // the oldest instant that can be shown
        qint64 lastUs = 0;  // the newest
        std::size_t instants = 0;
        std::size_t keys = 0;
        std::size_t bytes = 0;
        bool empty() const { return instants == 0; }
    };

    NetworkHistory();
    explicit NetworkHistory(Limits limits);
    ~NetworkHistory();

    // Worker: forgets the past; the network as it is now is the first instant.
    void start(const Network &network);
    // Worker: the network after a slice of virtual time, or after commands were applied
    // between two (commands: forced bits may have changed; every word is compared). A write
    // into a station's image between slices that is neither a scan's nor marked in
    // Station::written (a link's exchange, a slave's write) is a command: record it with
    // commands = true. A second instant at the same virtual time is shown in place of the
    // first.
    void record(const Network &network, bool commands);

    // Any thread.
    Window window() const;
    std::size_t stationCount() const;
    // Every station (the network's order) as it was at virtual time `us`: the last instant
    // recorded at or before it; empty before the window (or when nothing is recorded).
    std::optional<std::vector<model::Snapshot>> at(qint64 us) const;
    // One station only (cheaper).
    std::optional<model::Snapshot> stationAt(std::size_t station, qint64 us) const;
    // The virtual time of the instant `at(us)` shows; empty before the window.
    std::optional<qint64> instantAt(qint64 us) const;

    // One image word of one station through the instants after virtual time `afterUs`,
    // oldest first: its value at the first of them, then each instant at which it changed
    // (a chart row added after the fact reads its past here). *newest: the newest instant
    // read (left as it is when there is none); a later call goes on after its `us`.
    struct WordValue {
        qint64 us = 0;     // the instant
        quint64 scans = 0; // the station's statistics then
        qint64 timeMs = 0;
        std::int32_t value = 0;
        friend bool operator==(const WordValue &, const WordValue &) = default;
    };
    std::vector<WordValue> wordValues(std::size_t station, std::size_t word, qint64 afterUs,
                                      WordValue *newest = nullptr) const;
    // Counts start(): what was read of an older run (before Stop) is not this one's.
    std::uint64_t generation() const;

private:
    struct Key; // a copy of one station (its image's blocks that are not all 0)
    struct Instant {
        qint64 us = 0;
        // Per station, when this instant is a key; else empty.
        std::vector<model::ScanStatistics> statistics;
        std::vector<qint64> communicated; // Station::communicatedUs (the COMM lamp)
        std::vector<std::shared_ptr<const Key>> keys;
        // Per station, when not a key: [scans (2 words, low first), virtual ms (2 words),
        // Station::communicatedUs (2 words: what the front panel's COMM lamp showed then),
        // length L of the word changes, L words of changes, flow changes m, index x m] (a flow
        // change toggles that instruction's result). A word change is (index, value), or, for
        // neighbours that changed, (first | kRun, count, values): a busy program's registers
        // side by side cost a word each (network_history.cpp, appendChangedWords, says when a
        // run is written). The other statistics (period, evaluation times) are the key's.
        std::vector<std::uint32_t, HistoryAllocator<std::uint32_t>> changes;
        explicit Instant(HistoryArena *arena)
            : changes(HistoryAllocator<std::uint32_t>(arena)) {}
        std::size_t bytes() const;
    };
    struct Worker; // what the worker compares against

    // Under m_mutex: the index of the last instant at or before us, or -1.
    std::ptrdiff_t find(qint64 us) const;
    model::Snapshot rebuild(std::size_t station, std::size_t instant) const;
    void append(Instant instant); // takes m_mutex

    Limits m_limits;
    std::unique_ptr<Worker> m_worker;
    mutable std::mutex m_mutex;
    // The instants themselves (the deque's blocks), their changes and the keys' words
    // (history_arena.h); before m_instants, so that it goes after them.
    std::unique_ptr<HistoryArena> m_arena = std::make_unique<HistoryArena>();
    // The front one is a key. Its blocks from the arena: from the heap, each 512 bytes of
    // them (5 instants) was fresh memory while the history grew, and a 4 KB page first
    // touched a page fault, about 20 a block of 1,000 slices in BM_NetworkHistoryRatio/0.
    std::deque<Instant, HistoryAllocator<Instant>> m_instants{
        HistoryAllocator<Instant>(m_arena.get())};
    std::vector<std::shared_ptr<const model::MemoryLayout>> m_layouts;
    std::size_t m_bytes = 0;
    std::size_t m_keys = 0;
    std::uint64_t m_generation = 0;
};

} // namespace rung::network
