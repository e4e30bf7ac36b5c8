// History rewind (issue 11): a past scan rebuilt from the recorded stimulus and the nearest
// checkpoint equals the image the live engine had after that scan: with commands at scan
// boundaries and inside stopped scans, period changes, power cycles and online edits; with a
// checkpoint after every scan, none but the first, and thinned ones; the window is bounded.

#include "sim_test_target.h"

#include "simulator/scan_history.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

using namespace rung;
using namespace rung::simulator;

using Sim = test::TableSim;

namespace {

// Counts rising edges of X0 in C0, a timer on X1, a word that adds every scan, a latch.
constexpr const char *kProgram = "LD X0\nCNT C0 K1000\nLD X1\nTMR T0 K20\nLD SM9000\n"
                                 "ADD D0 K3 D0\nLD X2\nOR Y0\nANI X3\nOUT Y0\nLDP X4\nINC D1\nEND";

struct Live {
    explicit Live(ScanHistory::Limits limits)
        : sim(kProgram)
        , history(limits) {
        history.start(*sim.engine);
    }
    void command(const model::DeviceCommand &c) {
        const EngineCommand e{0, c};
        history.record(*sim.engine, e);
        applyCommand(*sim.engine, e, nullptr);
    }
    void setBit(const char *device, bool on) {
        command({model::DeviceCommand::Kind::WriteBit, sim.at(device), on ? 1 : 0});
    }
    void scan() {
        sim.engine->scan();
        history.afterScan(*sim.engine, sim.engine->statistics().execNsCurrent);
        seen[sim.engine->statistics().scans] = sim.engine->snapshot();
    }
    // A run with every kind of stimulus the session records.
    void drive(int scans, std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        for (int k = 0; k < scans; ++k) {
            const auto r = rng() % 40;
            if (r < 8)
                setBit(r < 4 ? "X0" : "X1", (r & 1) != 0);
            else if (r < 10)
                setBit(r == 8 ? "X2" : "X3", (rng() & 1) != 0);
            else if (r == 10)
                command({model::DeviceCommand::Kind::Force, sim.at("X4"), 1});
            else if (r == 11)
                command({model::DeviceCommand::Kind::Release, sim.at("X4"), 0});
            else if (r == 12)
                command({model::DeviceCommand::Kind::WriteWord, sim.at("D0"),
                         static_cast<qint64>(rng() % 100)});
            else if (r == 13) {
                const EngineCommand e{0, PowerCycle{}};
                history.record(*sim.engine, e);
                applyCommand(*sim.engine, e, nullptr);
            } else if (r == 14) {
                const qint64 period = 1 + static_cast<qint64>(rng() % 20);
                history.record(*sim.engine, ScanHistory::SetPeriod{period});
                sim.engine->setPeriodMs(period);
            } else if (r == 15) {
                // Stopped inside a scan, an input written there, then on to its end.
                sim.engine->setBreakpoints({{static_cast<int>(rng() % 12)}});
                if (sim.engine->scanToBreakpoint() == ScanStop::Breakpoint) {
                    setBit("X0", true);
                    command({model::DeviceCommand::Kind::WriteWord, sim.at("D1"), 40});
                    sim.engine->stepInstruction();
                    setBit("X2", (rng() & 1) != 0);
                }
                sim.engine->setBreakpoints({});
                // The rest of the scan; the history hears of it as of any scan.
                sim.engine->scan();
                history.afterScan(*sim.engine, sim.engine->statistics().execNsCurrent);
                seen[sim.engine->statistics().scans] = sim.engine->snapshot();
                continue;
            }
            scan();
        }
    }
    Sim sim;
    ScanHistory history;
    std::map<quint64, model::Snapshot> seen; // the live snapshot after each scan
};

void expectSame(const model::Snapshot &rebuilt, const model::Snapshot &live, quint64 scan) {
    ASSERT_EQ(rebuilt.statistics.scans, live.statistics.scans) << "scan " << scan;
    EXPECT_EQ(rebuilt.statistics.timeMs, live.statistics.timeMs) << "scan " << scan;
    EXPECT_EQ(rebuilt.words, live.words) << "scan " << scan;
    EXPECT_EQ(rebuilt.forceMask, live.forceMask) << "scan " << scan;
    EXPECT_EQ(rebuilt.forceValue, live.forceValue) << "scan " << scan;
}

} // namespace

TEST(ScanHistory, EveryScanRebuiltFromCheckpointsEqualsTheLiveOne) {
    for (const qint64 every : {qint64{1}, qint64{20000}, qint64{1} << 50}) {
        ScanHistory::Limits limits;
        limits.checkpointEvalNs = every; // every scan / some / only the first
        Live live(limits);
        live.drive(600, 7);
        const auto w = live.history.window();
        EXPECT_EQ(w.firstScan, 0u);
        EXPECT_EQ(w.lastScan, live.sim.engine->statistics().scans);
        for (const auto &[scan, snapshot] : live.seen) {
            const auto rebuilt = live.history.rebuild(scan);
            ASSERT_TRUE(rebuilt.has_value()) << scan;
            expectSame(*rebuilt, snapshot, scan);
            if (::testing::Test::HasFailure())
                return;
        }
        EXPECT_FALSE(live.history.rebuild(w.lastScan + 1).has_value());
    }
}

TEST(ScanHistory, TheRebuiltScanCarriesItsPowerFlow) {
    Live live({});
    live.setBit("X2", true);
    live.scan();
    live.scan();
    const auto rebuilt = live.history.rebuild(1);
    ASSERT_TRUE(rebuilt);
    ASSERT_EQ(rebuilt->powerFlow.size(), live.sim.result.program->steps.size());
    EXPECT_TRUE(rebuilt->powerFlow[9]); // OUT Y0 energised
    EXPECT_FALSE(rebuilt->pause.has_value());
}

TEST(ScanHistory, AnOnlineEditIsReplayedAtItsScan) {
    Live live({});
    for (int k = 0; k < 5; ++k) {
        live.setBit("X0", true);
        live.scan();
        live.setBit("X0", false);
        live.scan();
    }
    const auto edited = compileProgram(
        test::assemble(*live.sim.target,
                       QStringLiteral("LD X0\nCNT C0 K1000\nLD C0\nOUT Y5\nLD X1\nOUT Y6\nEND")));
    ASSERT_TRUE(edited.ok());
    const EngineCommand edit{0, ReplaceProgram{edited.program, {}}};
    live.history.record(*live.sim.engine, edit);
    applyCommand(*live.sim.engine, edit, nullptr);
    live.setBit("X1", true);
    live.scan();
    live.scan();
    ASSERT_EQ(live.sim.value("C0"), 5);
    for (const auto &[scan, snapshot] : live.seen) {
        const auto rebuilt = live.history.rebuild(scan);
        ASSERT_TRUE(rebuilt);
        expectSame(*rebuilt, snapshot, scan);
    }
}

TEST(ScanHistory, TheWindowKeepsTheLastHourOfVirtualTimeAndNoMore) {
    ScanHistory::Limits limits;
    limits.windowMs = 1000;      // 100 scans of 10 ms
    limits.checkpointEvalNs = 1; // a checkpoint every scan
    Live live(limits);
    live.drive(500, 3);
    const auto w = live.history.window();
    EXPECT_LE(w.lastMs - w.firstMs, 1000 + 20 * 10); // one checkpoint interval more at most
    EXPECT_GE(w.lastMs - w.firstMs, 1000 - 20);
    EXPECT_FALSE(live.history.rebuild(w.firstScan - 1).has_value());
    for (quint64 scan = w.firstScan; scan <= w.lastScan; ++scan) {
        const auto rebuilt = live.history.rebuild(scan);
        ASSERT_TRUE(rebuilt);
        expectSame(*rebuilt, live.seen.at(scan), scan);
    }
}

TEST(ScanHistory, ThinnedCheckpointsStayWithinTheirBytesAndStillRebuildExactly) {
    ScanHistory::Limits limits;
    limits.checkpointEvalNs = 1;
    Live probe(limits);
    const std::size_t one = probe.history.window().bytes;
    limits.maxCheckpointBytes = one * 8;
    Live live(limits);
    live.drive(400, 11);
    const auto w = live.history.window();
    EXPECT_LE(w.checkpoints, 8u);
    EXPECT_EQ(w.firstScan, 0u);
    for (const auto &[scan, snapshot] : live.seen) {
        const auto rebuilt = live.history.rebuild(scan);
        ASSERT_TRUE(rebuilt);
        expectSame(*rebuilt, snapshot, scan);
    }
}

TEST(ScanHistory, TimeMapsToTheScanThroughPeriodChanges) {
    Live live({});
    for (int k = 0; k < 10; ++k) // 10 scans of 10 ms: 0..100 ms
        live.scan();
    live.history.record(*live.sim.engine, ScanHistory::SetPeriod{5});
    live.sim.engine->setPeriodMs(5);
    for (int k = 0; k < 10; ++k) // 10 scans of 5 ms: 100..150 ms
        live.scan();
    EXPECT_EQ(live.history.scanAt(0), 0u);
    EXPECT_EQ(live.history.scanAt(49), 4u);
    EXPECT_EQ(live.history.scanAt(100), 10u);
    EXPECT_EQ(live.history.scanAt(112), 12u);
    EXPECT_EQ(live.history.scanAt(150), 20u);
    EXPECT_EQ(live.history.scanAt(99999), 20u); // clamped to the newest
    EXPECT_EQ(live.seen.at(12).statistics.timeMs, 110);
}

TEST(ScanHistory, StartForgetsThePast) {
    Live live({});
    live.drive(50, 5);
    live.sim.engine->reset();
    live.history.start(*live.sim.engine);
    const auto w = live.history.window();
    EXPECT_EQ(w.firstScan, 0u);
    EXPECT_EQ(w.lastScan, 0u);
    EXPECT_FALSE(live.history.rebuild(10).has_value());
}
