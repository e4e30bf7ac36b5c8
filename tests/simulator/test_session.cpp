// The simulator as a MonitorSource: an engine on its worker thread, driven from the test's
// thread (the owner) while another thread reads snapshots. Waits are QSignalSpy::wait or
// loops that process events until a condition holds, with generous time limits; no sleep
// is an assertion.

#include "session_fixture.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>
#include <vector>

using namespace rung;
using namespace rung::simulator;
using RunState = model::MonitorSource::RunState;
using test::eventually;
using test::kPatienceMs;
using test::SessionFixture;

TEST(SimulatorSession, StartsStoppedWithAPowerOnSnapshot) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    EXPECT_EQ(f.session->runState(), RunState::Stopped);
    ASSERT_TRUE(eventually([&] { return f.latest() != nullptr; }));
    EXPECT_EQ(f.latest()->statistics.scans, 0u);
    EXPECT_FALSE(f.latest()->bit(f.at("Y0")));
}

TEST(SimulatorSession, ForcedInputDrivesTheOutputAfterAScan) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    // Commands are answered before the next scan, even though the worker finishes them.
    const auto id = f.session->force(f.at("X0"), true);
    EXPECT_TRUE(f.finish(id).first);
    f.session->singleScan();
    ASSERT_TRUE(eventually([&] {
        auto s = f.latest();
        return s && s->statistics.scans == 1;
    }));
    EXPECT_TRUE(f.latest()->bit(f.at("Y0")));
    EXPECT_TRUE(f.latest()->forced(f.at("X0")));
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));

    EXPECT_TRUE(f.finish(f.session->release(f.at("X0"))).first);
    f.session->singleScan();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 2; }));
    EXPECT_FALSE(f.latest()->bit(f.at("Y0")));
    EXPECT_FALSE(f.latest()->forced(f.at("X0")));
}

TEST(SimulatorSession, WrittenWordIsInTheNextSnapshot) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    EXPECT_TRUE(f.finish(f.session->writeWord(f.at("D5"), 1234)).first);
    ASSERT_TRUE(eventually([&] { return f.latest()->value(f.at("D5")) == 1234; }));
    EXPECT_TRUE(f.finish(f.session->writeSetValue(f.at("T3"), 50)).first);
    ASSERT_TRUE(eventually([&] { return f.latest()->setValue(f.at("T3")) == 50; }));
}

TEST(SimulatorSession, CommandOnAWrongDeviceFailsWithItsName) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    const auto [ok, error] = f.finish(f.session->force(f.at("D0"), true)); // a word, not a bit
    EXPECT_FALSE(ok);
    EXPECT_TRUE(error.contains(QLatin1String("D0"))) << error.toStdString();
    const auto [ok2, error2] = f.finish(f.session->writeSetValue(f.at("D0"), 1));
    EXPECT_FALSE(ok2);
    EXPECT_TRUE(error2.contains(QLatin1String("D0"))) << error2.toStdString();
}

TEST(SimulatorSession, PowerCycleKeepsRetentiveAreasOnly) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    f.session->writeWord(f.at("D0"), 11);   // data registers
    f.session->writeWord(f.at("D200"), 22); // latched data registers (Vigor table: retentive)
    EXPECT_TRUE(f.finish(f.session->powerCycle()).first);
    // The worker publishes before it reports a completion: no waiting for the snapshot.
    const auto after = f.session->snapshot();
    ASSERT_NE(after, nullptr);
    EXPECT_EQ(after->value(f.at("D200")), 22);
    EXPECT_EQ(after->value(f.at("D0")), 0);
}

TEST(SimulatorSession, StopReturnsToPowerOnAndStepsCountScans) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    QSignalSpy states(f.session.get(), &model::MonitorSource::runStateChanged);
    f.session->writeWord(f.at("D200"), 7);
    f.session->runScans(5);
    EXPECT_EQ(f.session->runState(), RunState::Stepping);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 5; }));
    EXPECT_EQ(f.latest()->value(f.at("D200")), 7);
    f.session->stop();
    EXPECT_EQ(f.session->runState(), RunState::Stopped);
    // Power-on of a fresh PLC: every area at zero, the retentive ones too.
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 0; }));
    EXPECT_EQ(f.latest()->value(f.at("D200")), 0);
    ASSERT_GE(states.count(), 3);
    EXPECT_EQ(states.at(0).at(0).value<RunState>(), RunState::Stepping);
    EXPECT_EQ(states.at(1).at(0).value<RunState>(), RunState::Paused);
    EXPECT_EQ(states.at(2).at(0).value<RunState>(), RunState::Stopped);
}

TEST(SimulatorSession, RunningAtFullSpeedTellsReadersAtMostThirtyTimesASecond) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    ASSERT_TRUE(eventually([&] { return f.latest() != nullptr; }));
    QSignalSpy changes(f.session.get(), &model::MonitorSource::snapshotChanged);
    f.session->setSpeed(0); // as fast as the engine goes: many thousand scans a second
    f.session->run();
    QElapsedTimer window;
    window.start();
    while (window.elapsed() < 1000)
        changes.wait(50);
    const qint64 elapsed = window.elapsed();
    f.session->pause();
    const quint64 scans = f.latest()->statistics.scans;
    // One notification per kMinSnapshotIntervalMs at most, plus the one that may be due at
    // the start of the window.
    EXPECT_LE(changes.count(), elapsed / model::MonitorSource::kMinSnapshotIntervalMs + 1);
    EXPECT_GE(changes.count(), 3); // and it does keep telling
    EXPECT_GT(scans, static_cast<quint64>(changes.count()));
}

TEST(SimulatorSession, RealTimeSpeedPacesVirtualTime) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    f.session->setPeriodMs(10);
    f.session->setSpeed(1.0);
    // The clock starts before run(): the worker anchors its pacing after run(), so a test
    // thread descheduled between the two cannot shorten what it measures.
    QElapsedTimer t;
    t.start();
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.timeMs >= 300; }));
    const qint64 wall = t.elapsed();
    f.session->pause();
    // 300 ms of virtual time cannot come sooner than 290 ms of wall time at x1 (the first
    // scan is due at once). A loaded machine only makes it later, so no upper bound: the
    // speed factor's other side is below, x10 against x1.
    EXPECT_GE(wall, 290);

    // x10 from here: 300 ms more virtual time in no less than 29 ms of wall time, and sooner
    // than at x1 unless this thread is starved for a quarter of a second.
    // A command's completion comes after a snapshot of the paused engine: the exact start.
    EXPECT_TRUE(f.finish(f.session->writeWord(f.at("D1"), 0)).first);
    const qint64 from = f.session->snapshot()->statistics.timeMs;
    QElapsedTimer t10;
    t10.start();
    f.session->setSpeed(10.0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.timeMs >= from + 300; }));
    const qint64 wall10 = t10.elapsed();
    f.session->pause();
    EXPECT_GE(wall10, 29);
    EXPECT_LT(wall10, wall);
}

TEST(SimulatorSession, RunAfterStopPacesFromTheFreshEngineClock) {
    // Stop then run with the worker held: it sees both at once. Pacing from the old engine's
    // clock would owe it the 200 ms already run and catch up in a burst.
    SessionFixture f("LD X0\nOUT Y0\nEND");
    f.session->setPeriodMs(10);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.timeMs >= 200; }));
    QElapsedTimer t;
    model::MonitorSource::CommandId marker = 0;
    f.whileWorkerHeld([&] {
        f.session->stop();
        t.start();
        f.session->run();
        marker = f.session->writeWord(f.at("D0"), 1); // finished once the reset is published
    });
    EXPECT_TRUE(f.finish(marker).first);
    EXPECT_LT(f.session->snapshot()->statistics.timeMs, 150);
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.timeMs >= 150; }));
    EXPECT_GE(t.elapsed(), 140);
    f.session->pause();
}

TEST(SimulatorSession, AfterAStallPacingGoesOnFromNowWithoutABurst) {
    // The worker is held for a second at x1: it does not then run a second's worth of scans
    // at once. Wall time after the stall bounds virtual time (plus the catch-up allowance,
    // a period and the age of the snapshot read before); a loaded machine only loosens it.
    SessionFixture f("LD X0\nOUT Y0\nEND");
    f.session->setPeriodMs(10);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans >= 3; }));
    f.session->readHistory([](const model::HistoryRecorder &) {
        // The stall is the stimulus, not a wait for something: its length is the test's.
        std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    });
    QElapsedTimer t;
    t.start();
    const qint64 from = f.latest()->statistics.timeMs;
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.timeMs >= from + 400; }));
    const qint64 wall = t.elapsed();
    f.session->pause();
    // A burst would bring the 400 ms at once (measured: about 55 ms, the snapshot rate).
    EXPECT_GE(wall, 400 - 50 - 10 - model::MonitorSource::kMinSnapshotIntervalMs - 10);
}

TEST(SimulatorSession, StopReleasesAForceSubmittedBeforeIt) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    ASSERT_TRUE(f.session->watchHistory(f.at("Y0")));
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans >= 3; }));
    // Both completions may arrive in one delivery: collect them all.
    std::vector<model::MonitorSource::CommandId> finished;
    QObject context;
    QObject::connect(f.session.get(), &model::MonitorSource::commandFinished, &context,
                     [&](model::MonitorSource::CommandId id, bool ok, const QString &) {
                         if (ok)
                             finished.push_back(id);
                     });
    model::MonitorSource::CommandId before = 0, after = 0;
    f.whileWorkerHeld([&] {
        before = f.session->force(f.at("X0"), true);
        f.session->stop();
        after = f.session->force(f.at("X1"), true);
    });
    ASSERT_TRUE(eventually([&] { return finished.size() >= 2; }));
    EXPECT_EQ(finished, (std::vector<model::MonitorSource::CommandId>{before, after}));
    const auto s = f.session->snapshot();
    EXPECT_EQ(s->statistics.scans, 0u);
    EXPECT_FALSE(s->forced(f.at("X0")));
    EXPECT_TRUE(s->forced(f.at("X1")));
    f.session->singleScan();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 1; }));
    EXPECT_FALSE(f.latest()->bit(f.at("Y0")));
}

TEST(SimulatorSession, StopClearsTheHistory) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    ASSERT_TRUE(f.session->watchHistory(f.at("Y0")));
    f.session->runScans(3);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 3; }));
    f.session->readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_EQ(h.knownFrom(f.at("Y0")), std::optional<quint64>(1));
    });
    f.session->stop();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 0; }));
    f.session->readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_FALSE(h.knownFrom(f.at("Y0")).has_value());
        EXPECT_EQ(h.deviceCount(), 1); // still watched
    });
    f.session->runScans(2);
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 2; }));
    f.session->readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_EQ(h.knownFrom(f.at("Y0")), std::optional<quint64>(1));
    });
}

TEST(SimulatorSession, ReadersOnAnotherThreadShareConsistentSnapshotsWhileCommandsArrive) {
    // Y0 follows X0 and D0 counts scans; the reader checks each snapshot is whole (scans and
    // virtual time agree) and that time never runs backwards.
    SessionFixture f("LD M9000\nADD D0 K1 D0\nLD X0\nOUT Y0\nEND");
    ASSERT_TRUE(f.sim.result.ok());
    f.session->setSpeed(0);
    f.session->run();
    std::atomic<bool> done{false};
    std::atomic<int> reads{0};
    std::atomic<bool> consistent{true};
    const model::Address d0 = f.at("D0");
    std::thread reader([&] {
        quint64 last = 0;
        while (!done.load()) {
            if (auto s = f.session->snapshot()) {
                const auto &st = s->statistics;
                // D0 counts scans (16 bits, wrapping): a torn copy would disagree.
                if (st.scans < last || st.timeMs != static_cast<qint64>(st.scans) * st.periodMs ||
                    s->value(d0) != model::wrapToWidth(static_cast<qint64>(st.scans), 16))
                    consistent = false;
                last = st.scans;
                ++reads;
            }
            std::this_thread::yield();
        }
    });
    for (int k = 0; k < 50; ++k) {
        f.session->writeBit(f.at("X0"), k % 2 == 0);
        f.session->force(f.at("M0"), k % 3 == 0);
        QCoreApplication::processEvents();
    }
    const auto last = f.session->writeBit(f.at("X0"), true);
    EXPECT_TRUE(f.finish(last).first);
    EXPECT_TRUE(eventually([&] { return f.latest()->bit(f.at("Y0")) && reads.load() > 100; }));
    f.session->pause();
    done = true;
    reader.join();
    EXPECT_TRUE(consistent.load());
    EXPECT_GT(f.latest()->statistics.scans, 0u);
}

TEST(SimulatorSession, HistoryRecordsWatchedDevicesPerScan) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    // Through the interface, as the timing chart reads any origin.
    model::MonitorSource &source = *f.session;
    ASSERT_TRUE(source.watchHistory(f.at("Y0")));
    EXPECT_FALSE(source.watchHistory(model::Address{}));
    f.session->setPeriodMs(10);
    f.session->runScans(3); // Y0 off after scans 1..3
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    f.session->writeBit(f.at("X0"), true);
    f.session->runScans(2); // on after scans 4, 5
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 5; }));
    source.readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_EQ(h.valueAtScan(f.at("Y0"), 3), 0);
        EXPECT_EQ(h.valueAtScan(f.at("Y0"), 4), 1);
        EXPECT_EQ(h.valueAtTime(f.at("Y0"), 35), 0);
        EXPECT_EQ(h.valueAtTime(f.at("Y0"), 40), 1);
        const auto changes = h.changes(f.at("Y0"), 0, 100);
        ASSERT_EQ(changes.size(), 2u);
        EXPECT_EQ(changes[1], (model::HistoryRecorder::Change{4, 40, 1}));
    });
}

TEST(SimulatorSession, APausedSessionPublishesItsLastScan) {
    // At full speed most scans are not published (one snapshot every 34 ms); when the worker
    // goes idle it publishes the last one, so a paused view is not one interval behind. The
    // worker is woken by pause() and has a second to get there; a command's completion then
    // comes with a snapshot of the same, unchanged engine.
    SessionFixture f("LD M9000\nADD D0 K1 D0\nEND");
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans > 1000; }));
    f.session->pause();
    QElapsedTimer idle;
    idle.start();
    while (idle.elapsed() < 1000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    const auto paused = f.session->snapshot();
    EXPECT_TRUE(f.finish(f.session->writeWord(f.at("D1"), 0)).first);
    EXPECT_EQ(paused->statistics.scans, f.session->snapshot()->statistics.scans);
    EXPECT_EQ(paused->value(f.at("D0")), f.session->snapshot()->value(f.at("D0")));
}

TEST(SimulatorSession, AStoppingTriggerPausesAtTheScanWhereItBecameTrue) {
    // As fast as possible: thousands of scans between two snapshots, yet the trigger is
    // evaluated on every recorded scan, so the session stops at exactly scan 501 (D0 counts
    // one a scan from the first: D0 > 500 first holds after scan 501). D0 stops at 1000: a
    // count that wrapped at 32767 would make the condition false and true again, a second
    // firing whenever the run below outpaced the test by 65536 scans (the machine's speed).
    SessionFixture f("LD M9000\nCMP D0 K999 M0\nLDI M0\nADD D0 K1 D0\nEND");
    model::MonitorSource &source = *f.session;
    model::Trigger trigger;
    trigger.device = f.at("D0");
    trigger.kind = model::Trigger::Kind::Compare;
    trigger.op = model::CompareOp::Gt;
    trigger.value = 500;
    ASSERT_TRUE(source.setTrigger(trigger));
    QSignalSpy fired(&source, &model::MonitorSource::triggered);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    EXPECT_EQ(fired.at(0).at(0).toULongLong(), 501u);
    EXPECT_EQ(fired.at(0).at(1).toLongLong(), 5010);
    EXPECT_EQ(source.runState(), RunState::Paused);
    // The snapshot the reader finds when told is that scan's.
    EXPECT_EQ(source.snapshot()->statistics.scans, 501u);
    EXPECT_EQ(source.snapshot()->value(f.at("D0")), 501);
    source.readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_EQ(h.marks(), (std::vector<model::HistoryRecorder::Mark>{{501, 5010}}));
    });
    // Run goes on from there; the condition stays true, so it does not fire again.
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans > 1000; }));
    EXPECT_EQ(f.latest()->value(f.at("D0")), 1000);
    f.session->pause();
    EXPECT_EQ(fired.count(), 1);
}

// A trigger armed on a running PLC whose history watched nothing so far (no scan recorded):
// a condition that already holds is not "becoming true" at the next scan; the next rise is.
TEST(SimulatorSession, ATriggerArmedAfterUnrecordedScansFiresOnTheNextRiseOnly) {
    SessionFixture f("LD X0\nOUT Y0\nEND");
    model::MonitorSource &source = *f.session;
    EXPECT_TRUE(f.finish(source.writeBit(f.at("X0"), true)).first);
    for (int k = 0; k < 3; ++k) {
        const quint64 before = f.latest()->statistics.scans;
        f.session->singleScan();
        ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == before + 1; }));
    }
    auto trigger =
        std::get<model::Trigger>(model::parseTrigger(f.sim.target, QStringLiteral("Y0 rises")));
    trigger.action = model::Trigger::Action::Mark;
    ASSERT_TRUE(source.setTrigger(trigger)); // Y0 is ON already
    QSignalSpy fired(&source, &model::MonitorSource::triggered);
    for (const bool on : {true, false, true}) {
        EXPECT_TRUE(f.finish(source.writeBit(f.at("X0"), on)).first);
        const quint64 before = f.latest()->statistics.scans;
        f.session->singleScan();
        ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == before + 1; }));
    }
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    EXPECT_EQ(fired.at(0).at(0).toULongLong(), 6u) << "the rise at scan 6, not scan 4";
    EXPECT_TRUE(source.setTrigger(std::nullopt));
}

TEST(SimulatorSession, AMarkingTriggerNotesEveryRiseAndKeepsRunning) {
    // Y0 follows X0; X0 pulsed twice by single scans: two marks, never paused by them.
    SessionFixture f("LD X0\nOUT Y0\nEND");
    model::MonitorSource &source = *f.session;
    auto parsed = model::parseTrigger(f.sim.target, QStringLiteral("Y0 rises"));
    ASSERT_TRUE(std::holds_alternative<model::Trigger>(parsed));
    auto trigger = std::get<model::Trigger>(parsed);
    trigger.action = model::Trigger::Action::Mark;
    ASSERT_TRUE(source.setTrigger(trigger));
    QSignalSpy fired(&source, &model::MonitorSource::triggered);
    for (const bool on : {false, true, false, false, true, true}) {
        EXPECT_TRUE(f.finish(source.writeBit(f.at("X0"), on)).first);
        const quint64 before = f.latest()->statistics.scans;
        f.session->singleScan();
        ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == before + 1; }));
    }
    ASSERT_TRUE(eventually([&] { return fired.count() == 2; }));
    EXPECT_EQ(fired.at(0).at(0).toULongLong(), 2u);
    EXPECT_EQ(fired.at(1).at(0).toULongLong(), 5u);
    source.readHistory([&](const model::HistoryRecorder &h) {
        EXPECT_EQ(h.marks(), (std::vector<model::HistoryRecorder::Mark>{{2, 20}, {5, 50}}));
    });
    EXPECT_TRUE(source.setTrigger(std::nullopt));
}
