// The history recorder on a real scan: change-compressed per device, bounded, and read back
// by scan, by time and as the changes in a window.

#include "real_target_sim.h"

#include "model/image/history.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;
using Change = model::HistoryRecorder::Change;

namespace {

struct HistorySim : test::RealTargetSim {
    explicit HistorySim(
        std::size_t changesPerDevice = model::HistoryRecorder::kDefaultChangesPerDevice)
        : RealTargetSim(model::Family::Vigor, "LD X0\nOUT Y0\nLD M9000\nINC D0\nEND")
        , history(result.program->layout, changesPerDevice) {}
    void scan(int n = 1) {
        for (int k = 0; k < n; ++k) {
            engine->scan();
            history.record(engine->statistics().scans, engine->statistics().timeMs,
                           engine->words().data());
        }
    }
    model::HistoryRecorder history;
};

} // namespace

TEST(HistoryRecorder, KeepsOnlyChangesAndAnswersAnyScanInBetween) {
    HistorySim s;
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.history.watch(s.at("Y0")));
    s.scan(10); // Y0 off
    s.in("X0", true);
    s.scan(5); // on after scan 11
    s.in("X0", false);
    s.scan(5); // off after scan 16
    const auto changes = s.history.changes(s.at("Y0"), 0, 1000);
    const std::vector<Change> expected{{1, 10, 0}, {11, 110, 1}, {16, 160, 0}};
    EXPECT_EQ(changes, expected);
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 10), 0);
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 13), 1);
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 20), 0);
    EXPECT_EQ(s.history.valueAtTime(s.at("Y0"), 159), 1);
    EXPECT_EQ(s.history.valueAtTime(s.at("Y0"), 160), 0);
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 0), std::nullopt); // before the recording
    EXPECT_EQ(s.history.knownFrom(s.at("Y0")), 1u);
}

TEST(HistoryRecorder, WindowStartsWithTheValueItOpensWith) {
    HistorySim s;
    s.history.watch(s.at("Y0"));
    s.scan(3);
    s.in("X0", true);
    s.scan(3); // on after scan 4 (40 ms)
    const std::vector<Change> expected{{4, 40, 1}};
    EXPECT_EQ(s.history.changes(s.at("Y0"), 50, 60), expected);
    EXPECT_TRUE(s.history.changes(s.at("Y0"), 60, 50).empty());
    EXPECT_TRUE(s.history.changes(s.at("Y1"), 0, 60).empty()); // not watched
}

TEST(HistoryRecorder, WordsRecordTheirValue) {
    HistorySim s;
    ASSERT_TRUE(s.history.watch(s.at("D0")));
    ASSERT_TRUE(s.history.watch(s.at("D0"))); // once
    EXPECT_EQ(s.history.deviceCount(), 1);
    s.scan(5);
    EXPECT_EQ(s.history.valueAtScan(s.at("D0"), 3), 3);
    EXPECT_EQ(s.history.changes(s.at("D0"), 0, 50).size(), 5u);
}

TEST(HistoryRecorder, MemoryIsBoundedAndTheWindowSaysWhereItStarts) {
    HistorySim s(16);
    s.history.watch(s.at("D0")); // changes every scan
    s.history.watch(s.at("Y0")); // never changes
    s.scan(100);
    EXPECT_EQ(s.history.knownFrom(s.at("D0")), 85u); // the last 16 changes: scans 85..100
    EXPECT_EQ(s.history.valueAtScan(s.at("D0"), 84), std::nullopt);
    EXPECT_EQ(s.history.valueAtScan(s.at("D0"), 90), 90);
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 2), 0); // one change kept since scan 1
    EXPECT_EQ(s.history.knownFrom(s.at("Y0")), 1u);
    EXPECT_LE(s.history.memoryBytes(), 2 * 16 * sizeof(Change));
}

TEST(HistoryRecorder, DeviceWatchedLaterStartsAtItsFirstRecord) {
    HistorySim s;
    s.history.watch(s.at("Y0"));
    s.scan(5);
    EXPECT_TRUE(s.history.watch(s.at("D0")));
    s.scan(1);
    EXPECT_EQ(s.history.knownFrom(s.at("D0")), 6u);
    EXPECT_EQ(s.history.valueAtScan(s.at("D0"), 6), 6);
    EXPECT_FALSE(s.history.watch(model::Address{}));
    s.history.clear();
    EXPECT_EQ(s.history.knownFrom(s.at("Y0")), std::nullopt);
    s.scan(1);
    EXPECT_EQ(s.history.knownFrom(s.at("Y0")), 7u);
}

TEST(HistoryTrigger, FiresInTheScanWhereTheConditionBecomesTrue) {
    HistorySim s; // Y0 follows X0; D0 counts one a scan
    model::Trigger rises{s.at("Y0"), model::Trigger::Kind::Rises};
    ASSERT_TRUE(s.history.setTrigger(rises));
    std::vector<quint64> fired;
    const auto scanAndNote = [&](int n) {
        for (int k = 0; k < n; ++k) {
            s.engine->scan();
            if (s.history.record(s.engine->statistics().scans, s.engine->statistics().timeMs,
                                 s.engine->words().data()))
                fired.push_back(s.engine->statistics().scans);
        }
    };
    scanAndNote(3);
    s.in("X0", true);
    scanAndNote(3); // rises after scan 4
    s.in("X0", false);
    scanAndNote(2);
    s.in("X0", true);
    scanAndNote(1); // again after scan 9
    EXPECT_EQ(fired, (std::vector<quint64>{4, 9}));
    EXPECT_EQ(s.history.marks(), (std::vector<model::HistoryRecorder::Mark>{{4, 40}, {9, 90}}));
    // The trigger's device is recorded like any watched one.
    EXPECT_EQ(s.history.valueAtScan(s.at("Y0"), 4), 1);
}

TEST(HistoryTrigger, ArmedWhileTheConditionHoldsItWaitsForTheNextChangeIntoIt) {
    HistorySim s;
    s.history.watch(s.at("D0"));
    s.scan(20); // D0 = 20
    model::Trigger above{s.at("D0"), model::Trigger::Kind::Compare, model::CompareOp::Gt, 10};
    ASSERT_TRUE(s.history.setTrigger(above));
    s.scan(5);
    EXPECT_TRUE(s.history.marks().empty());
    // A falling condition: D0 = 5 while still counting: "D0 = 30" fires once, at scan 30.
    model::Trigger equal{s.at("D0"), model::Trigger::Kind::Compare, model::CompareOp::Eq, 30};
    ASSERT_TRUE(s.history.setTrigger(equal));
    s.scan(10);
    EXPECT_EQ(s.history.marks(), (std::vector<model::HistoryRecorder::Mark>{{30, 300}}));
}

TEST(HistoryTrigger, AfterAResetAConditionThatHoldsAtTheFirstScanFires) {
    // Power-on: every device 0. "Y0 falls" does not fire at the first scan (Y0 was never
    // ON); "D0 >= 1" does (D0 was 0 before the first scan).
    HistorySim s;
    s.history.clear();
    ASSERT_TRUE(s.history.setTrigger(model::Trigger{s.at("Y0"), model::Trigger::Kind::Falls}));
    s.scan(1);
    EXPECT_TRUE(s.history.marks().empty());
    s.history.clear();
    ASSERT_TRUE(s.history.setTrigger(
        model::Trigger{s.at("D0"), model::Trigger::Kind::Compare, model::CompareOp::Ge, 1}));
    s.scan(1);
    EXPECT_EQ(s.history.marks().size(), 1u);
    EXPECT_FALSE(s.history.setTrigger(model::Trigger{model::Address{}}));
}
