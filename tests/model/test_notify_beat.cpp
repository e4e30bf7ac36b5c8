// The beat on which a MonitorSource tells its readers (model/image/notify_beat.h), driven by
// a clock of our own: what the overlay's 30 repaints a second and its input-to-screen time
// rest on, checked without waiting on a real clock.

#include "model/image/notify_beat.h"

#include <gtest/gtest.h>

#include <vector>

namespace rung::model {
namespace {

constexpr qint64 kBeat = NotifyBeat::kBeatUs;

// Snapshots come every `everyUs` for `forUs`; the owner reacts `lateUs` after each time a
// notification was due (its event loop's delay). The clock ticks by stepUs. Returns the
// notification times.
std::vector<qint64> run(qint64 everyUs, qint64 forUs, qint64 lateUs,
                        const std::vector<qint64> &answersAt = {}, qint64 stepUs = 1) {
    NotifyBeat beat;
    std::vector<qint64> told;
    bool waiting = false, answer = false;
    std::size_t nextAnswer = 0;
    for (qint64 now = 0; now <= forUs; now += stepUs) {
        if (now % everyUs == 0)
            waiting = true;
        if (nextAnswer < answersAt.size() && answersAt[nextAnswer] == now) {
            waiting = answer = true;
            ++nextAnswer;
        }
        const qint64 due = beat.dueUs(waiting, answer);
        if (due != NotifyBeat::kNever && now >= due + lateUs) {
            beat.notified(now);
            told.push_back(now);
            waiting = answer = false;
        }
    }
    return told;
}

TEST(NotifyBeat, ASteadyStreamIsToldThirtyTimesASecondEvenWhenTheOwnerIsLateEachTime) {
    // A "34 ms after the last" rule told 29 a second at best, fewer with each delay.
    for (const qint64 late : {0, 300, 2000, 9000}) {
        const std::vector<qint64> told = run(1000, 10'000'000, late, {}, 100);
        EXPECT_GE(told.size(), 300u) << "late " << late;
        EXPECT_LE(told.size(), 301u) << "late " << late;
    }
}

TEST(NotifyBeat, NothingNewIsNeverToldAndAPauseBringsNoBurst) {
    NotifyBeat beat;
    EXPECT_EQ(beat.dueUs(false, false), NotifyBeat::kNever);
    EXPECT_EQ(beat.dueUs(true, false), 0); // the first snapshot at once
    beat.notified(0);
    EXPECT_EQ(beat.dueUs(true, false), kBeat);
    // Idle for a second: the next snapshot is told at once, the one after a beat later, not
    // thirty catching up.
    beat.notified(1'000'000);
    EXPECT_EQ(beat.dueUs(true, false), 1'000'000 + kBeat);
    // Snapshots every 100 ms (slower than the beat): each told when it comes.
    const std::vector<qint64> slow = run(100'000, 1'000'000, 0);
    EXPECT_EQ(slow.size(), 11u);
    for (std::size_t i = 0; i < slow.size(); ++i)
        EXPECT_EQ(slow[i], static_cast<qint64>(i) * 100'000);
}

TEST(NotifyBeat, AnAnswerToTheUserIsToldAtOnceButNotCloserThanTheGap) {
    NotifyBeat beat;
    beat.notified(0);
    // Between two beats: an answer is due at once...
    EXPECT_EQ(beat.dueUs(true, true), NotifyBeat::kAnswerGapUs);
    EXPECT_LT(beat.dueUs(true, true), beat.dueUs(true, false));
    // ...and 20 ms into the beat, as soon as it comes.
    const std::vector<qint64> told = run(1000, 100'000, 0, {20'000});
    ASSERT_GE(told.size(), 3u);
    EXPECT_EQ(told[0], 0);
    EXPECT_EQ(told[1], 20'000);         // the answer, not at 33,333
    EXPECT_EQ(told[2], 20'000 + kBeat); // a new beat from it
    // Answers every millisecond (a slider dragged): no closer than the gap.
    std::vector<qint64> answers;
    for (qint64 t = 0; t < 100'000; t += 1000)
        answers.push_back(t);
    const std::vector<qint64> dragged = run(1000, 100'000, 0, answers);
    for (std::size_t i = 1; i < dragged.size(); ++i)
        EXPECT_GE(dragged[i] - dragged[i - 1], NotifyBeat::kAnswerGapUs);
    EXPECT_GE(dragged.size(), 100'000u / NotifyBeat::kAnswerGapUs);
}

} // namespace
} // namespace rung::model
