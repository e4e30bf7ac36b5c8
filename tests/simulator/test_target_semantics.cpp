// The simulator takes a target's execution facts from its table (model::Semantics, Limits,
// InstructionSpec), not from the family: the same synthetic target (sim_test_target.h) behaves
// as its table fields say. The families' own values are checked in tests/model/test_targets.cpp.

#include "sim_test_target.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

using test::TableSim;

TEST(TableSemantics, ParallelOutputShowsTheWordOnTheBitsTheTableNames) {
    TableSim s(test::makeTestTarget(model::Family::Vigor));
    s.target->semantics.parallelOut = {QStringLiteral("D5"), QStringLiteral("Y2"), 4};
    ASSERT_TRUE(s.compile("LD SM9000\nMOV K21 D5\nEND"));
    s.engine->runScans(1);
    // 21 = 1 0101b; four bits from Y2: the value modulo 16 = 0101b.
    EXPECT_TRUE(s.bit("Y2"));
    EXPECT_FALSE(s.bit("Y3"));
    EXPECT_TRUE(s.bit("Y4"));
    EXPECT_FALSE(s.bit("Y5"));
    EXPECT_FALSE(s.bit("Y6")); // bit 4 of 21 lies beyond the port's width
    EXPECT_FALSE(s.bit("Y1")); // below the first bit
}

TEST(TableSemantics, ParallelInputReadsTheBitsIntoTheWord) {
    TableSim s(test::makeTestTarget(model::Family::Vigor));
    s.target->semantics.parallelIn = {QStringLiteral("D7"), QStringLiteral("X4"), 3};
    ASSERT_TRUE(s.compile("LD SM9000\nMOV D7 D8\nEND"));
    for (const char *x : {"X4", "X6", "X7"}) // X7 lies beyond the three bits
        s.engine->setBit(s.at(x), true);
    s.engine->runScans(1);
    EXPECT_EQ(s.value("D7"), 0b101);
    EXPECT_EQ(s.value("D8"), 0b101);
}

TEST(TableSemantics, NoPortWithoutATableEntry) {
    TableSim s(test::makeTestTarget(model::Family::Vigor));
    ASSERT_TRUE(s.compile("LD SM9000\nMOV K5 D5\nEND"));
    s.engine->runScans(1);
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("Y2"));
}

TEST(TableSemantics, DeferredBitWritesFollowTheField) {
    auto t = test::makeTestTarget(model::Family::Vigor);
    t->semantics.deferredBitWrites = true;
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD SM9000\nOUT M0\nLD M0\nOUT Y0\nEND"));
    s.engine->runScans(1);
    EXPECT_TRUE(s.bit("M0"));
    EXPECT_FALSE(s.bit("Y0")); // the contact saw the image of the scan before
    s.engine->runScans(1);
    EXPECT_TRUE(s.bit("Y0"));
}

TEST(TableSemantics, DownTimersBelowTheTableLimitCountDown) {
    auto t = test::makeTestTarget(model::Family::Vigor);
    t->semantics.downTimersBelow = 2;
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD X0\nTMR T1 K10\nLD X0\nTMR T2 K10\nEND"));
    s.engine->setBit(s.at("X0"), true);
    s.engine->runScans(4); // three 10 ms periods after the first scan (100 ms base: 0 units)
    const int startDown = s.value("T1");
    EXPECT_EQ(startDown, 10);    // counts down from the set value
    EXPECT_EQ(s.value("T2"), 0); // counts up from zero
}

TEST(TableSemantics, AnInstructionsOwnTimeBaseWinsOverTheTargets) {
    auto t = test::makeTestTarget(model::Family::Vigor);
    auto fast = test::spec("TMRF", model::Op::Timer);
    fast.timerBaseMs = 10;
    t->instructions.push_back(fast);
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD X0\nTMRF T0 K5\nLD X0\nTMR T1 K5\nEND"));
    s.engine->setBit(s.at("X0"), true);
    s.engine->runScans(6);     // 50 ms of timing at a 10 ms period
    EXPECT_TRUE(s.bit("T0"));  // 5 x 10 ms
    EXPECT_FALSE(s.bit("T1")); // 5 x 100 ms
}

TEST(TableSemantics, TimerCurrentValueStopsAtTheTablesLimit) {
    auto t = test::makeTestTarget(model::Family::Vigor);
    t->limits.timerMax = 3;
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD X0\nTMR T0 K50\nEND"));
    s.engine->setBit(s.at("X0"), true);
    s.engine->runScans(100); // 990 ms: 9 units of 100 ms
    EXPECT_EQ(s.value("T0"), 3);
}

TEST(TableSemantics, SaturatingCountersStopAtTheTablesLimits) {
    // PL110 semantics (MUP: up/down counters saturate) with narrower limits in the table.
    auto t = test::makeTestTarget(model::Family::Pl110);
    t->limits.counterMin = -2;
    t->limits.counterMax = 3;
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD X0\nLD X1\nLD X2\nCNTR C0 K10\nEND"));
    auto pulses = [&](const char *input, int n) {
        for (int k = 0; k < n; ++k) {
            s.in(input, true);
            s.scan();
            s.in(input, false);
            s.scan();
        }
    };
    pulses("X0", 5); // up
    EXPECT_EQ(s.value("C0"), 3);
    pulses("X1", 9); // down
    EXPECT_EQ(s.value("C0"), -2);
}

TEST(TableSemantics, ScanTimeWordsStopAtTheTablesLimit) {
    auto t = test::makeTestTarget(model::Family::Vigor);
    t->systemDevices.push_back(
        {QStringLiteral("D99"), model::SystemRole::ScanTimeCurrent, nullptr, 100});
    t->limits.scanTimeMax = 250;
    TableSim s(std::move(t));
    ASSERT_TRUE(s.compile("LD X0\nOUT Y0\nEND"));
    s.engine->setPeriodMs(20); // 200 units of 0.1 ms
    s.scan();
    EXPECT_EQ(s.value("D99"), 200);
    s.engine->setPeriodMs(30); // 300: over the limit
    s.scan();
    EXPECT_EQ(s.value("D99"), 250);
}
