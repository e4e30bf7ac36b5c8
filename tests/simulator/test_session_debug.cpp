// The session's breakpoints, stepping, online edit and history (issue 11), on its worker
// thread: a running session stops at a breakpoint (Paused, the stopped scan in the
// snapshot); steps and finishes the scan; an edit while running keeps a counter's value; a
// HistorySource shows an earlier scan exactly as the live session published it, and refuses
// commands. Part of test_simulator, so the ThreadSanitizer stage runs it.

#include "session_fixture.h"

#include "simulator/history_source.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

#include <map>

using namespace rung;
using namespace rung::simulator;
using RunState = model::MonitorSource::RunState;
using test::eventually;
using test::SessionFixture;

namespace {

// 0 LD X0, 1 OR X1, 2 LD X2, 3 AND X3, 4 ORB, 5 MPS, 6 AND X4, 7 OUT Y0, 8 MPP, 9 OUT Y1,
// 10 END
constexpr const char *kBlocks =
    "LD X0\nOR X1\nLD X2\nAND X3\nORB\nMPS\nAND X4\nOUT Y0\nMPP\nOUT Y1\nEND";

Breakpoint at(int instruction) {
    Breakpoint b;
    b.instruction = instruction;
    return b;
}

std::optional<model::ScanPause> pauseOf(const SessionFixture &f) {
    const auto s = f.session->snapshot();
    return s ? s->pause : std::nullopt;
}

} // namespace

TEST(SessionBreakpoints, RunningStopsAtTheBreakpointThenStepsAndFinishesTheScan) {
    SessionFixture f(kBlocks);
    f.session->writeBit(f.at("X0"), true);
    f.session->writeBit(f.at("X2"), true);
    f.session->setBreakpoints({at(4)});
    QSignalSpy hit(f.session.get(), &SimulatorSession::breakpointHit);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return hit.count() == 1; }));
    EXPECT_EQ(hit.at(0).at(0).toInt(), 4);
    EXPECT_EQ(f.session->runState(), RunState::Paused);
    auto p = pauseOf(f);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->instruction, 4);
    EXPECT_EQ(p->breakpoint, 4);
    EXPECT_FALSE(p->result);                           // X2 AND X3
    EXPECT_EQ(p->blockStack, std::vector<bool>{true}); // X0 OR X1
    const quint64 scans = f.latest()->statistics.scans;

    f.session->stepInstruction(); // ORB
    ASSERT_TRUE(eventually([&] {
        const auto q = pauseOf(f);
        return q && q->instruction == 5 && f.session->runState() == RunState::Paused;
    }));
    p = pauseOf(f);
    EXPECT_TRUE(p->result);
    EXPECT_TRUE(p->blockStack.empty());
    EXPECT_EQ(p->breakpoint, -1);
    f.session->stepInstruction(); // MPS
    ASSERT_TRUE(eventually([&] {
        const auto q = pauseOf(f);
        return q && q->instruction == 6;
    }));
    EXPECT_EQ(pauseOf(f)->memoryStack, std::vector<bool>{true});

    f.session->finishScan();
    ASSERT_TRUE(eventually([&] {
        const auto s = f.session->snapshot();
        return !s->pause && s->statistics.scans == scans + 1 &&
               f.session->runState() == RunState::Paused;
    }));
    EXPECT_TRUE(f.latest()->bit(f.at("Y1")));
    EXPECT_EQ(hit.count(), 1);
}

TEST(SessionBreakpoints, AConditionalBreakpointStopsWhenTheWordPassesTheValue) {
    SessionFixture f("LD M9000\nINC D10\nLD X0\nOUT Y0\nEND");
    Breakpoint b = at(2);
    b.when = Breakpoint::When::Compare;
    b.device = f.at("D10");
    b.op = model::CompareOp::Gt;
    b.value = 100;
    f.session->setBreakpoints({b});
    QSignalSpy hit(f.session.get(), &SimulatorSession::breakpointHit);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return hit.count() == 1; }));
    const auto s = f.session->snapshot();
    EXPECT_EQ(s->value(f.at("D10")), 101);
    EXPECT_EQ(s->statistics.scans, 100u);
    // Run goes on from the stopped instruction; D10 > 100 holds again in the next scan.
    f.session->run();
    ASSERT_TRUE(eventually([&] { return hit.count() == 2; }));
    EXPECT_EQ(f.latest()->statistics.scans, 101u);
    // Without breakpoints it runs on.
    f.session->setBreakpoints({});
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans > 300; }));
    f.session->pause();
}

TEST(SessionBreakpoints, ABreakpointBeyondTheProgramIsSaidAndChangesNothing) {
    SessionFixture f(kBlocks);
    f.session->setBreakpoints({at(99)});
    ASSERT_TRUE(eventually([&] { return !f.session->errorText().isEmpty(); }));
    EXPECT_TRUE(f.session->errorText().contains(QStringLiteral("99")));
}

TEST(SessionBreakpoints, StepAtAScanBoundaryStartsAScanAndRunScansStopsAtABreakpoint) {
    SessionFixture f(kBlocks);
    f.session->stepInstruction();
    ASSERT_TRUE(eventually([&] {
        const auto p = pauseOf(f);
        return p && p->instruction == 0 && f.session->runState() == RunState::Paused;
    }));
    f.session->finishScan();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans == 1; }));
    f.session->setBreakpoints({at(9)});
    QSignalSpy hit(f.session.get(), &SimulatorSession::breakpointHit);
    f.session->runScans(5);
    ASSERT_TRUE(eventually([&] { return hit.count() == 1; }));
    EXPECT_EQ(f.latest()->statistics.scans, 1u);
    EXPECT_EQ(f.session->runState(), RunState::Paused);
}

TEST(SessionOnlineEdit, AnEditWhileRunningKeepsTheCounterValue) {
    SessionFixture f("LD X0\nCNT C0 K100\nEND");
    f.session->setSpeed(0);
    for (int k = 0; k < 6; ++k) {
        f.session->writeBit(f.at("X0"), true);
        f.session->singleScan();
        ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
        f.session->writeBit(f.at("X0"), false);
        f.session->singleScan();
        ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    }
    ASSERT_TRUE(eventually([&] { return f.latest()->value(f.at("C0")) == 6; }));
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans > 50; }));
    const model::ParseResult parsed = model::parseInstructionList(
        f.sim.target, QStringLiteral("LD X0\nCNT C0 K100\nLD C0\nOUT Y0\nLD M9000\nOUT Y1\nEND"));
    ASSERT_TRUE(parsed.ok());
    const CompileResult edited = compileProgram(parsed.list);
    ASSERT_TRUE(edited.ok());
    EXPECT_TRUE(f.finish(f.session->replaceProgram(edited.program)).first);
    ASSERT_TRUE(eventually([&] { return f.latest()->bit(f.at("Y1")); }));
    EXPECT_EQ(f.latest()->value(f.at("C0")), 6);
    EXPECT_EQ(f.session->runState(), RunState::Running);
    f.session->writeBit(f.at("X0"), true);
    ASSERT_TRUE(eventually([&] { return f.latest()->value(f.at("C0")) == 7; }));
    f.session->pause();
}

TEST(SessionHistory, AHistorySourceShowsAnEarlierScanAsItWasLive) {
    SessionFixture f("LD X0\nCNT C0 K100\nLD M9000\nADD D0 K7 D0\nLD X1\nOUT Y0\nEND");
    f.session->setSpeed(0);
    std::map<quint64, std::shared_ptr<const model::Snapshot>> live;
    for (int k = 0; k < 8; ++k) {
        f.session->writeBit(f.at("X0"), k % 2 == 0);
        f.session->writeBit(f.at("X1"), k % 3 == 0);
        f.session->runScans(3);
        ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
        const auto s = f.session->snapshot();
        live[s->statistics.scans] = s;
    }
    ASSERT_EQ(live.size(), 8u);
    HistorySource history(f.session->scanHistory());
    QSignalSpy shown(&history, &HistorySource::shown);
    for (const auto &[scan, snapshot] : live) {
        history.showScan(scan);
        ASSERT_TRUE(eventually([&, scan = scan] { return history.shownScan() == scan; }));
        const auto rebuilt = history.snapshot();
        ASSERT_TRUE(rebuilt);
        EXPECT_EQ(rebuilt->words, snapshot->words) << "scan " << scan;
        EXPECT_EQ(rebuilt->statistics.timeMs, snapshot->statistics.timeMs);
    }
    ASSERT_TRUE(eventually([&] { return shown.count() == 8; }));
    EXPECT_EQ(shown.last().at(0).toULongLong(), 24u);
    // By virtual time: 95 ms is after scan 9 (10 ms scans).
    history.showTime(95);
    ASSERT_TRUE(eventually([&] { return history.shownScan() == 9u; }));
    EXPECT_EQ(history.snapshot()->words, live.at(9)->words);
    EXPECT_EQ(HistorySource::label(9, 90), QStringLiteral("History: scan 9 (0:00:00.09)"));
    // Read-only.
    bool done = false;
    QString error;
    QObject::connect(&history, &model::MonitorSource::commandFinished, &history,
                     [&](model::MonitorSource::CommandId, bool ok, const QString &e) {
                         EXPECT_FALSE(ok);
                         error = e;
                         done = true;
                     });
    history.writeBit(f.at("X0"), true);
    ASSERT_TRUE(eventually([&] { return done; }));
    EXPECT_TRUE(error.startsWith(QStringLiteral("history is read-only"))) << error.toStdString();
}

TEST(SessionHistory, HistoryIsRebuiltWhileTheSessionRunsOn) {
    SessionFixture f("LD M9000\nINC D0\nEND");
    // x100: 2,000 scans in 0.2 s, while the hour the history keeps lasts 36 s.
    f.session->setSpeed(100);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.latest()->statistics.scans > 2000; }));
    HistorySource history(f.session->scanHistory());
    // Scan N leaves D0 = N: any scan asked for while scans go on is rebuilt exactly.
    for (const quint64 scan : {quint64{1}, quint64{1000}, quint64{1999}, quint64{7}}) {
        history.showScan(scan);
        ASSERT_TRUE(eventually([&] { return history.shownScan() == scan; }));
        EXPECT_EQ(history.snapshot()->value(f.at("D0")), static_cast<int>(scan));
    }
    f.session->stop();
    ASSERT_TRUE(eventually([&] { return f.session->scanHistory()->window().lastScan == 0; }));
}
