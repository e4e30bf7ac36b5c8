#pragma once

// When a MonitorSource tells its readers that a new snapshot is there: on a fixed beat of
// kPerSecond a second, and sooner for a snapshot that answers the user (an input toggled, a
// value written), so what they did shows without waiting for the beat.
//
// A beat, not "at least 1000/30 ms after the last one": that rule drifts below 30 a second by
// the event loop's delay on every notification, and the overlay's 30 Hz is then out of reach.
// After a pause (nothing new for more than a beat) the beat starts again from the next
// snapshot, so readers never get a burst of catch-up notifications. Times in microseconds
// of any steady clock. Pure, single-threaded: MonitorSource calls it on its owner thread.

#include <QtGlobal>

#include <algorithm>
#include <limits>

namespace rung::model {

class NotifyBeat {
public:
    static constexpr int kPerSecond = 30;
    static constexpr qint64 kBeatUs = 1'000'000 / kPerSecond;
    // An answer to the user comes at once, but not closer than this to the notification
    // before it: a slider dragged across its range is still a bounded rate.
    static constexpr qint64 kAnswerGapUs = 8'000;

    // The time the next notification is due, for what is waiting (nothing waiting: never).
    qint64 dueUs(bool waiting, bool answer) const {
        if (!waiting)
            return kNever;
        if (!m_started)
            return 0;
        const qint64 beat = m_nextUs;
        return answer ? std::min(beat, m_lastUs + kAnswerGapUs) : beat;
    }
    // A notification went out at nowUs.
    void notified(qint64 nowUs) {
        // On the beat (or late by less than a beat): the next one keeps the grid. Early (an
        // answer), or late by more than a beat (nothing new came): a new grid from now.
        const bool onGrid = m_started && nowUs >= m_nextUs && nowUs - m_nextUs < kBeatUs;
        m_nextUs = onGrid ? m_nextUs + kBeatUs : nowUs + kBeatUs;
        m_lastUs = nowUs;
        m_started = true;
    }

    static constexpr qint64 kNever = std::numeric_limits<qint64>::max();

private:
    bool m_started = false;
    qint64 m_nextUs = 0;
    qint64 m_lastUs = 0;
};

} // namespace rung::model
