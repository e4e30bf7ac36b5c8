// Breakpoints, stepping and triggers inside one station of a simulated network
// (network_session.h, network_session_debug.cpp): the station holds mid-scan, every other
// station waits at its scan boundary and the clock stands; stepping moves the held station
// alone; run goes on with the whole network. The network room's part (Network::runUntil
// stopping at a held scan and going on as if nothing had stopped) is tested without threads.

#include "network/network_session.h"

#include "network_fixture.h"

#include "../eventually.h"

#include "model/target/target.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

namespace rung::network::test {
namespace {

using waits::eventually;
using RunState = model::MonitorSource::RunState;

// Three Vigor stations on no wire, scanning every 10, 7 and 10 ms: each counts its scans in
// D0 and D1, the two INCs apart so that a scan held between them shows D0 = D1 + 1.
// Instructions: 0 LD M9000, 1 INC D0, 2 INC D1, 3 END.
const char *const kCounter = "; target: vigor\nLD M9000\nINC D0\nINC D1\nEND\n";
const QByteArray kThreeStations = R"({"period": 10, "stations": [
    {"name": "a", "program": "counter", "model": "VB"},
    {"name": "b", "program": "counter", "model": "VB", "period": 7},
    {"name": "c", "program": "counter", "model": "VB"}]})";

struct DebugFixture {
    std::unique_ptr<NetworkSession> session;
    QString error;

    DebugFixture() {
        NetworkDescription d;
        EXPECT_TRUE(parseNetwork(kThreeStations, QStringLiteral("/tmp/debug.rungnet"), &d, &error))
            << error.toStdString();
        session = NetworkSession::start(
            d, listingLoader({{QStringLiteral("counter"), QString::fromLatin1(kCounter)}}), &error);
        EXPECT_TRUE(session) << error.toStdString();
    }
    StationSource *station(const char *name) const {
        return session->station(QString::fromLatin1(name));
    }
    qint64 value(const char *name, const char *device) const {
        StationSource *s = station(name);
        const auto snapshot = s->snapshot();
        const auto a = model::parseAddress(s->target(), QString::fromLatin1(device));
        return snapshot && std::holds_alternative<model::Address>(a)
                   ? snapshot->value(std::get<model::Address>(a))
                   : -1;
    }
    std::optional<model::ScanPause> pause(const char *name) const {
        const auto snapshot = station(name)->snapshot();
        return snapshot ? snapshot->pause : std::nullopt;
    }
    // At its scan boundary: no scan held, both counters equal.
    bool atBoundary(const char *name) const {
        return !pause(name) && value(name, "D0") == value(name, "D1");
    }
    bool paused() const {
        return eventually([&] { return session->runState() == RunState::Paused; });
    }
    void breakAt(const char *name, int instruction) const {
        simulator::Breakpoint b;
        b.instruction = instruction;
        session->setBreakpoints(QString::fromLatin1(name), {b});
    }
};

TEST(NetworkSession, ABreakpointInOneStationStopsTheWholeNetworkAtTheOthersScanBoundary) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    QSignalSpy hits(f.session.get(), &NetworkSession::breakpointHit);
    f.breakAt("b", 2);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(f.paused());
    ASSERT_EQ(hits.count(), 1);
    EXPECT_EQ(hits[0][0].toString(), QStringLiteral("b"));
    EXPECT_EQ(hits[0][1].toInt(), 2);
    EXPECT_EQ(f.session->heldStation(), QStringLiteral("b"));
    // b holds between its INCs, at its first scan's instant (7 ms)...
    ASSERT_TRUE(f.pause("b"));
    EXPECT_EQ(f.pause("b")->instruction, 2);
    EXPECT_EQ(f.pause("b")->breakpoint, 2);
    EXPECT_EQ(f.value("b", "D0"), 1);
    EXPECT_EQ(f.value("b", "D1"), 0);
    EXPECT_EQ(f.session->nowUs(), 7000);
    // ...and the others wait at their scan boundary: none has scanned yet at 7 ms.
    EXPECT_TRUE(f.atBoundary("a"));
    EXPECT_TRUE(f.atBoundary("c"));
    EXPECT_EQ(f.value("a", "D0"), 0);
    EXPECT_EQ(f.value("c", "D0"), 0);
    EXPECT_EQ(f.station("b")->runState(), RunState::Paused);

    // Run goes on with the whole network: the next stop is b's next scan, 7 ms later, with a
    // and c having scanned once each (at 10 ms) meanwhile.
    f.session->run();
    ASSERT_TRUE(eventually([&] { return hits.count() == 2; }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.session->nowUs(), 14000);
    EXPECT_EQ(f.value("b", "D0"), 2);
    EXPECT_EQ(f.value("b", "D1"), 1);
    EXPECT_TRUE(f.atBoundary("a"));
    EXPECT_TRUE(f.atBoundary("c"));
    EXPECT_EQ(f.value("a", "D0"), 1);
    EXPECT_EQ(f.value("c", "D0"), 1);
}

TEST(NetworkSession, SteppingMovesTheHeldStationAloneAndTheClockStands) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    f.breakAt("b", 2);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.pause("b").has_value(); }));
    ASSERT_TRUE(f.paused());
    const qint64 at = f.session->nowUs();

    // One instruction: INC D1 runs, b stops before END.
    f.session->stepInstruction(QStringLiteral("b"));
    EXPECT_EQ(f.session->runState(), RunState::Stepping);
    ASSERT_TRUE(eventually([&] { return f.pause("b") && f.pause("b")->instruction == 3; }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.pause("b")->breakpoint, -1); // a step stopped it, not a breakpoint
    EXPECT_EQ(f.value("b", "D1"), 1);
    EXPECT_EQ(f.session->nowUs(), at);
    EXPECT_TRUE(f.atBoundary("a"));
    EXPECT_TRUE(f.atBoundary("c"));

    // The END: b's scan completes, the network still stands at that instant.
    f.session->stepInstruction(QStringLiteral("b"));
    ASSERT_TRUE(eventually([&] { return !f.pause("b").has_value(); }));
    ASSERT_TRUE(f.paused());
    EXPECT_TRUE(f.session->heldStation().isEmpty());
    EXPECT_TRUE(f.atBoundary("b"));
    EXPECT_EQ(f.session->nowUs(), at);

    // At a boundary, stepping into c runs the network up to c's next scan (10 ms), which
    // holds before its first instruction; b scanned at 7 ms before it, a at 10 ms.
    f.session->stepInstruction(QStringLiteral("c"));
    ASSERT_TRUE(eventually([&] { return f.pause("c").has_value(); }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.pause("c")->instruction, 0);
    EXPECT_EQ(f.session->heldStation(), QStringLiteral("c"));
    EXPECT_EQ(f.session->nowUs(), 10000);
    EXPECT_EQ(f.value("a", "D0"), 1);
    EXPECT_TRUE(f.atBoundary("a"));
    EXPECT_TRUE(f.atBoundary("b"));

    // Finish Scan: the rest of c's scan, breakpoints ignored; nothing else moves.
    f.session->finishScan();
    ASSERT_TRUE(eventually([&] { return !f.pause("c").has_value(); }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.value("c", "D0"), 1);
    EXPECT_EQ(f.value("c", "D1"), 1);
    EXPECT_EQ(f.session->nowUs(), 10000);
}

TEST(NetworkSession, ASingleScanContinuesAHeldScanThenTheNetworkAndStopForgetsTheHold) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    f.breakAt("b", 2);
    f.session->setSpeed(0);
    f.session->stepInstruction(QStringLiteral("b")); // b holds before instruction 0 at 7 ms
    ASSERT_TRUE(eventually([&] { return f.pause("b").has_value(); }));
    ASSERT_TRUE(f.paused());
    // A single scan resumes b: its breakpoint at instruction 2 holds in this very scan.
    QSignalSpy hits(f.session.get(), &NetworkSession::breakpointHit);
    f.session->singleScan();
    ASSERT_TRUE(eventually([&] { return hits.count() == 1; }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.pause("b")->instruction, 2);
    EXPECT_EQ(f.session->nowUs(), 7000);
    // Without breakpoints the next single scan ends b's scan and runs one period more.
    f.session->setBreakpoints(QStringLiteral("b"), {});
    f.session->singleScan();
    ASSERT_TRUE(eventually(
        [&] { return f.session->runState() == RunState::Paused && !f.pause("b").has_value(); }));
    EXPECT_EQ(f.session->nowUs(), 17000);
    EXPECT_TRUE(f.atBoundary("b"));
    EXPECT_EQ(f.value("b", "D0"), 2); // 7 and 14 ms
    EXPECT_EQ(f.value("a", "D0"), 1); // 10 ms

    // Stop builds the network again: nothing holds, the breakpoints kept stop it again.
    f.breakAt("a", 1);
    f.session->stop();
    ASSERT_TRUE(eventually([&] { return f.session->nowUs() == 0 && !f.pause("b"); }));
    f.session->run();
    ASSERT_TRUE(eventually([&] { return f.pause("a").has_value(); }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(f.session->nowUs(), 10000);
    EXPECT_EQ(f.pause("a")->instruction, 1);
}

TEST(NetworkSession, ABreakpointTheProgramCannotTakeIsSaid) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    f.breakAt("c", 99);
    ASSERT_TRUE(eventually([&] { return !f.session->errorText().isEmpty(); }));
    EXPECT_TRUE(f.session->errorText().startsWith(QStringLiteral("c: ")))
        << f.session->errorText().toStdString();
}

TEST(NetworkSession, AStationsStoppingTriggerPausesTheNetworkAfterThatScan) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    StationSource *b = f.station("b");
    model::Trigger t;
    t.device = std::get<model::Address>(model::parseAddress(b->target(), QStringLiteral("D0")));
    t.kind = model::Trigger::Kind::Compare;
    t.op = model::CompareOp::Ge;
    t.value = 5;
    t.action = model::Trigger::Action::Stop;
    ASSERT_TRUE(b->setTrigger(t));
    QSignalSpy fired(b, &model::MonitorSource::triggered);
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    ASSERT_TRUE(f.paused());
    // b's fifth scan, at 35 ms: the network stops right after it, a and c at their boundary.
    EXPECT_EQ(fired[0][0].toULongLong(), 5u);
    EXPECT_EQ(fired[0][1].toLongLong(), 35);
    EXPECT_EQ(f.session->nowUs(), 35000);
    EXPECT_EQ(f.value("b", "D0"), 5);
    EXPECT_TRUE(f.atBoundary("a"));
    EXPECT_TRUE(f.atBoundary("c"));
    EXPECT_EQ(f.value("a", "D0"), 3);
    EXPECT_TRUE(f.session->heldStation().isEmpty());
    b->readHistory([](const model::HistoryRecorder &h) {
        ASSERT_EQ(h.marks().size(), 1u);
        EXPECT_EQ(h.marks().back().scan, 5u);
    });
}

TEST(NetworkSession, AMarkingTriggerReportsAndTheNetworkRunsOn) {
    DebugFixture f;
    ASSERT_TRUE(f.session);
    StationSource *a = f.station("a");
    model::Trigger t;
    t.device = std::get<model::Address>(model::parseAddress(a->target(), QStringLiteral("D0")));
    t.kind = model::Trigger::Kind::Compare;
    t.op = model::CompareOp::Eq;
    t.value = 3;
    t.action = model::Trigger::Action::Mark;
    ASSERT_TRUE(a->setTrigger(t));
    QSignalSpy fired(a, &model::MonitorSource::triggered);
    f.session->runFor(100);
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    ASSERT_TRUE(f.paused());
    EXPECT_EQ(fired[0][0].toULongLong(), 3u);
    EXPECT_EQ(fired[0][1].toLongLong(), 30);
    EXPECT_EQ(f.session->nowUs(), 100000); // it ran the whole 100 ms
}

// The network room alone: a run held at a breakpoint and resumed again and again puts the
// same frames on the wire at the same times, and leaves the same values, as a run without.
TEST(NetworkHold, AScanHeldAndResumedChangesNothingInTheNetwork) {
    const QString file =
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/easy-link/easy-link.rungnet");
    NetRun plain = runNetwork({}, {}, {}, file);
    NetRun held = runNetwork({}, {}, {}, file);
    ASSERT_TRUE(plain.net && held.net) << plain.error.toStdString();
    simulator::Breakpoint atLink;
    atLink.instruction = 17; // LINK D1000 D100
    ASSERT_TRUE(held.net->station(QStringLiteral("master"))->engine().setBreakpoints({atLink}));
    plain.net->runUntil(300000);
    int holds = 0;
    while (!held.net->runUntil(300000)) {
        Station *s = held.net->holdingStation();
        ASSERT_TRUE(s);
        EXPECT_EQ(s->name(), QStringLiteral("master"));
        EXPECT_EQ(s->engine().stoppedAt(), 17);
        ++holds;
        // Nothing runs while it holds.
        const qint64 at = held.net->nowUs();
        EXPECT_FALSE(held.net->runUntil(300000));
        EXPECT_EQ(held.net->nowUs(), at);
        s->continueScan();
    }
    EXPECT_EQ(holds, 30); // every scan of the master, 10 ms each
    EXPECT_EQ(held.traffic, plain.traffic);
    EXPECT_FALSE(plain.traffic.isEmpty());
    for (const char *device : {"D0", "D1", "D100", "D9201"})
        EXPECT_EQ(value(*held.net, QStringLiteral("master"), QString::fromLatin1(device)),
                  value(*plain.net, QStringLiteral("master"), QString::fromLatin1(device)))
            << device;
}

} // namespace
} // namespace rung::network::test
