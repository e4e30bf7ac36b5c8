// Scan-cycle semantics on a synthetic target (sim_test_target.h), independent of the real
// device tables and the IL parser.

#include "sim_test_target.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

using Sim = test::TableSim;

TEST(EngineLatch, StopFirstLatchHoldsAfterStartReleaseAndStopWins) {
    Sim s("LD X0\nOR Y0\nANI X1\nOUT Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    s.in("X0", true);
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", false);
    s.scan(3);
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", true);
    s.in("X1", true);
    s.scan();
    EXPECT_FALSE(s.bit("Y0")); // stop wins while both are pressed
}

TEST(EngineLatch, LaterInstructionWinsBetweenSetAndReset) {
    Sim stopFirst("LD X0\nSET Y0\nLD X1\nRST Y0\nEND");
    stopFirst.in("X0", true);
    stopFirst.in("X1", true);
    stopFirst.scan();
    EXPECT_FALSE(stopFirst.bit("Y0"));
    Sim startFirst("LD X1\nRST Y0\nLD X0\nSET Y0\nEND");
    startFirst.in("X0", true);
    startFirst.in("X1", true);
    startFirst.scan();
    EXPECT_TRUE(startFirst.bit("Y0"));
}

TEST(EngineLatch, KeepResetInputWins) {
    Sim s("LD X0\nLD X1\nKEEP M0\nEND");
    s.in("X0", true);
    s.scan();
    EXPECT_TRUE(s.bit("M0"));
    s.in("X0", false);
    s.scan();
    EXPECT_TRUE(s.bit("M0"));
    s.in("X0", true);
    s.in("X1", true);
    s.scan();
    EXPECT_FALSE(s.bit("M0"));
}

TEST(EngineLogic, OscillatorTogglesEveryScan) {
    Sim s("LDI Y1\nOUT Y1\nEND");
    for (int k = 0; k < 6; ++k) {
        s.scan();
        EXPECT_EQ(s.bit("Y1"), k % 2 == 0) << "scan " << k;
    }
}

TEST(EngineLogic, BlocksCombineAsSeriesAndParallel) {
    // (X0 | X1) & (X2 | X3) -> Y0 ; (X0 & X1) | (X2 & X3) -> Y1
    Sim s("LD X0\nOR X1\nLD X2\nOR X3\nANB\nOUT Y0\n"
          "LD X0\nAND X1\nLD X2\nAND X3\nORB\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok());
    for (int v = 0; v < 16; ++v) {
        const bool x[4] = {(v & 1) != 0, (v & 2) != 0, (v & 4) != 0, (v & 8) != 0};
        s.in("X0", x[0]);
        s.in("X1", x[1]);
        s.in("X2", x[2]);
        s.in("X3", x[3]);
        s.scan();
        EXPECT_EQ(s.bit("Y0"), (x[0] || x[1]) && (x[2] || x[3])) << v;
        EXPECT_EQ(s.bit("Y1"), (x[0] && x[1]) || (x[2] && x[3])) << v;
    }
}

TEST(EngineLogic, StackBranchesShareTheBranchPoint) {
    Sim s("LD X0\nMPS\nAND X1\nOUT Y0\nMRD\nAND X2\nOUT Y1\nMPP\nINV\nOUT Y2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.in("X2", true);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_FALSE(s.bit("Y2"));
    s.in("X0", false);
    s.scan();
    EXPECT_FALSE(s.bit("Y1"));
    EXPECT_TRUE(s.bit("Y2"));
}

TEST(EngineLogic, OutNotDrivesTheInvertedResult) {
    Sim s("LD X0\nOUTN Y0\nEND");
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", true);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
}

TEST(EngineEdges, EdgeContactsAndPulsesLastOneScan) {
    Sim s("LDP X0\nOUT Y0\nLDF X0\nOUT Y1\nLD X0\nPLS M0\nLD X0\nPLF M1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    s.in("X0", true);
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("M0"));
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("M0"));
    s.in("X0", false);
    s.scan();
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_TRUE(s.bit("M1"));
    s.scan();
    EXPECT_FALSE(s.bit("Y1"));
    EXPECT_FALSE(s.bit("M1"));
}

TEST(EngineTimer, TimerTurnsOnAfterItsSetTimeAndResetsWhenTheInputDrops) {
    Sim s("LD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND"); // 10 x 100 ms
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.scan(100); // input seen ON at t = 0 .. 990 ms
    EXPECT_FALSE(s.bit("T0"));
    EXPECT_EQ(s.value("T0"), 9);
    s.scan(); // t = 1000 ms
    EXPECT_TRUE(s.bit("T0"));
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_EQ(s.value("T0"), 10);
    s.scan(50);
    EXPECT_EQ(s.value("T0"), 10); // stops at the set value
    s.in("X0", false);
    s.scan();
    EXPECT_FALSE(s.bit("T0"));
    EXPECT_EQ(s.value("T0"), 0);
}

TEST(EngineTimer, TimerFollowsThePeriod) {
    Sim s("LD X0\nTMR T1 K5\nEND");
    s.engine->setPeriodMs(100);
    s.in("X0", true);
    s.scan(5);
    EXPECT_FALSE(s.bit("T1"));
    s.scan();
    EXPECT_TRUE(s.bit("T1"));
    EXPECT_EQ(s.engine->statistics().timeMs, 600);
}

TEST(EngineCounter, CounterCountsRisingEdgesUntilResetByRst) {
    Sim s("LD X0\nCNT C0 K3\nLD X1\nRST C0\nLD C0\nOUT Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    for (int k = 0; k < 3; ++k) {
        EXPECT_FALSE(s.bit("Y0"));
        s.in("X0", true);
        s.scan(2); // held: counts once
        s.in("X0", false);
        s.scan();
        EXPECT_EQ(s.value("C0"), k + 1);
    }
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("C0"), 3); // stops at the set value
    s.in("X1", true);
    s.scan();
    EXPECT_FALSE(s.bit("C0"));
    EXPECT_EQ(s.value("C0"), 0);
}

TEST(EngineCounter, TwoInputCounterResetInputIsTheLastBlock) {
    Sim s("LD X0\nLD X1\nCNT2 C1 K2\nEND");
    ASSERT_TRUE(s.result.ok());
    for (int k = 0; k < 2; ++k) {
        s.in("X0", true);
        s.scan();
        s.in("X0", false);
        s.scan();
    }
    EXPECT_TRUE(s.bit("C1"));
    s.in("X1", true);
    s.scan();
    EXPECT_FALSE(s.bit("C1"));
    EXPECT_EQ(s.value("C1"), 0);
}

TEST(EngineCounter, ReversibleCounterWrapsAtBothLimits) {
    Sim s("LD X0\nLD X1\nLD X2\nCNTR C2 K2\nEND");
    ASSERT_TRUE(s.result.ok());
    auto pulse = [&](const char *input) {
        s.in(input, true);
        s.scan();
        s.in(input, false);
        s.scan();
    };
    pulse("X0");
    pulse("X0");
    EXPECT_EQ(s.value("C2"), 2);
    EXPECT_FALSE(s.bit("C2"));
    pulse("X0"); // 2 -> 0 wraps
    EXPECT_EQ(s.value("C2"), 0);
    EXPECT_TRUE(s.bit("C2"));
    pulse("X1"); // 0 -> 2 wraps downwards
    EXPECT_EQ(s.value("C2"), 2);
    EXPECT_TRUE(s.bit("C2"));
    pulse("X1");
    EXPECT_EQ(s.value("C2"), 1);
    EXPECT_FALSE(s.bit("C2"));
}

TEST(EngineControl, InterlockOffDropsOutputsResetsTimersKeepsSetBits) {
    Sim s("LD X0\nIL\nLD X1\nOUT Y0\nLD X1\nTMR T0 K1\nLD X1\nSET M0\nILC\nLD X1\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.in("X1", true);
    s.scan(11); // T0 K1: 100 ms
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("T0"));
    EXPECT_TRUE(s.bit("M0"));
    s.in("X0", false);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("T0"));
    EXPECT_TRUE(s.bit("M0"));
    EXPECT_TRUE(s.bit("Y1")); // after ILC the interlock no longer applies
}

TEST(EngineControl, SkippedJumpRegionKeepsItsState) {
    Sim s("LD X0\nJMP K1\nLD X1\nOUT Y0\nLD X1\nTMR T0 K2\nJME K1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X1", true);
    s.scan(2); // jump taken (X0 OFF): nothing inside runs
    EXPECT_FALSE(s.bit("Y0"));
    s.in("X0", true);
    s.scan(2);
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_EQ(s.value("T0"), 0); // 10 ms since the timer started: still below one unit
    s.in("X0", false);
    s.in("X1", false);
    s.scan(30);
    EXPECT_TRUE(s.bit("Y0")); // frozen while skipped
    s.in("X0", true);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
}

TEST(EngineControl, StepLadderTransfersWithSetAndRunsOnlyTheActiveStep) {
    Sim s("LD SM9002\nSET S0\nSTL S0\nOUT Y0\nLD X0\nSET S1\nSTL S1\nOUT Y1\nLD X1\nSET S0\n"
          "RET\nEND");
    ASSERT_TRUE(s.result.ok());
    s.scan();
    EXPECT_TRUE(s.bit("S0"));
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", true);
    s.scan();
    EXPECT_TRUE(s.bit("S1"));
    EXPECT_FALSE(s.bit("S0"));
    s.in("X0", false);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("Y1"));
    s.in("X1", true);
    s.scan();
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("Y1"));
}

TEST(EngineApply, ArithmeticAndMovesRunWhileTheConditionHolds) {
    Sim s("LD X0\nMOV K7 D0\nADD D0 K5 D1\nSUB D0 K10 D2\nMUL D0 K1000 D4\nDIV K23 D0 D6\n"
          "INC D8\nDEC D9\nCMP D0 K7 M10\nEND");
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics.size();
    s.scan();
    EXPECT_EQ(s.value("D0"), 0);
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("D0"), 7);
    EXPECT_EQ(s.value("D1"), 12);
    EXPECT_EQ(s.value("D2"), -3);
    EXPECT_EQ(s.value("D4"), 7000);
    EXPECT_EQ(s.value("D5"), 0);
    EXPECT_EQ(s.value("D6"), 3);
    EXPECT_EQ(s.value("D7"), 2);
    EXPECT_FALSE(s.bit("M10"));
    EXPECT_TRUE(s.bit("M11"));
    EXPECT_FALSE(s.bit("M12"));
    s.scan(2);
    EXPECT_EQ(s.value("D8"), 3);
    EXPECT_EQ(s.value("D9"), -3);
}

TEST(EngineApply, SixteenBitResultsWrapAndProductsSpillIntoTheNextWord) {
    Sim s("LD SM9000\nMOV K30000 D0\nADD D0 D0 D1\nMUL D0 D0 D2\nEND");
    s.scan();
    EXPECT_EQ(s.value("D1"), 60000 - 65536);
    const std::int64_t product = 30000LL * 30000LL;
    EXPECT_EQ(s.value("D2"), static_cast<std::int16_t>(product & 0xFFFF));
    EXPECT_EQ(s.value("D3"), static_cast<std::int16_t>(product >> 16));
}

TEST(EngineApply, DivisionByZeroLeavesTheDestinationAndReportsTheStepOnce) {
    Sim s("LD SM9000\nMOV K9 D1\nDIV K5 D0 D1\nEND");
    s.scan(3);
    EXPECT_EQ(s.value("D1"), 9);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].instruction, 2);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 3);
}

TEST(EngineApply, ZoneResetClearsBitsWordsAndCounters) {
    Sim s("LD SM9000\nMOV K4 D3\nSET M3\nLD X0\nZRST D2 D5\nZRST M2 M4\nEND");
    s.scan();
    EXPECT_EQ(s.value("D3"), 4);
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("D3"), 0);
    EXPECT_FALSE(s.bit("M3"));
}

TEST(EngineApply, CompareContactsReadWords) {
    Sim s("LD= D0 K3\nOUT Y0\nLD> D0 K3\nOUT Y1\nEND");
    s.engine->writeWord(s.at("D0"), 3);
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("Y1"));
    s.engine->writeWord(s.at("D0"), 4);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("Y1"));
}

TEST(EngineForce, ForcedInputIgnoresItsStimulusUntilReleased) {
    Sim s("LD X0\nOUT Y0\nEND");
    s.engine->force(s.at("X0"), true);
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    s.in("X0", false);
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
    s.engine->release(s.at("X0"));
    s.scan();
    EXPECT_FALSE(s.bit("Y0")); // back to the stimulus
}

TEST(EngineForce, ForcedOutputIgnoresProgramWrites) {
    Sim s("LD X0\nOUT Y0\nLD Y0\nOUT Y1\nEND");
    s.engine->force(s.at("Y0"), false);
    s.in("X0", true);
    s.scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_FALSE(s.bit("Y1"));
    s.engine->releaseAll();
    s.scan();
    EXPECT_TRUE(s.bit("Y0"));
}

TEST(EngineSystem, FirstScanAlwaysOnToggleAndClock) {
    Sim s("LD SM9002\nOUT M0\nLD SM9000\nOUT M1\nLD SM9010\nOUT M2\nLD SM9013\nOUT M3\nEND");
    s.scan();
    EXPECT_TRUE(s.bit("M0"));
    EXPECT_TRUE(s.bit("M1"));
    EXPECT_FALSE(s.bit("M2"));
    EXPECT_TRUE(s.bit("M3")); // 1 s clock: ON for the first half second
    s.scan();
    EXPECT_FALSE(s.bit("M0"));
    EXPECT_TRUE(s.bit("M2"));
    s.scan(48); // t = 490 ms
    EXPECT_TRUE(s.bit("M3"));
    s.scan(); // t = 500 ms
    EXPECT_FALSE(s.bit("M3"));
}

TEST(EnginePower, PowerCycleKeepsRetentiveAreasOnly) {
    Sim s("LD X0\nSET M1\nLD X0\nSET L500\nLD X0\nMOV K5 D0\nLD X0\nMOV K6 R100\nLD X0\n"
          "CNT C0 K9\nLD SM9002\nOUT M2\nEND");
    s.in("X0", true);
    s.scan(2);
    s.engine->powerCycle();
    EXPECT_FALSE(s.bit("M1"));
    EXPECT_EQ(s.value("D0"), 0);
    EXPECT_TRUE(s.bit("L500"));
    EXPECT_EQ(s.value("R100"), 6);
    EXPECT_EQ(s.value("C0"), 1);
    s.in("X0", false);
    s.scan();
    EXPECT_TRUE(s.bit("M2")); // first-scan pulse again
}

TEST(EngineDeferred, VpcContactsSeeBitWritesOnlyAfterEnd) {
    // Written and read in one scan: on VPC the contact sees the previous scan's image.
    Sim vpc("LD X0\nOUT M0\nLD M0\nOUT Y0\nEND", model::Family::Vpc);
    vpc.in("X0", true);
    vpc.scan();
    EXPECT_TRUE(vpc.bit("M0"));
    EXPECT_FALSE(vpc.bit("Y0"));
    vpc.scan();
    EXPECT_TRUE(vpc.bit("Y0"));
    Sim vigor("LD X0\nOUT M0\nLD M0\nOUT Y0\nEND", model::Family::Vigor);
    vigor.in("X0", true);
    vigor.scan();
    EXPECT_TRUE(vigor.bit("Y0"));
}

TEST(EngineDeferred, VpcOnceASecondExampleAddsOncePerSecond) {
    // VPC user's manual, VII: LD r95 IL OUT NOT r04 LD r04 OUT p02+p01 ILC (docs/simulator.md)
    Sim s("LD SM9013\nIL\nOUTN M4\nLD M4\nXFER D2 D1\nILC\nEND", model::Family::Vpc);
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D1"), 3);
    s.scan(100); // 0 .. 990 ms
    EXPECT_EQ(s.value("D2"), 0);
    s.scan(); // 1000 ms: the clock rises
    EXPECT_EQ(s.value("D2"), 3);
    s.scan(899);
    EXPECT_EQ(s.value("D2"), 27); // 1000, 2000, ... 9000 ms
}

TEST(EngineCompile, StackUnderflowIsAnErrorWithItsLine) {
    Sim s("LD X0\nANB\nOUT Y0\nEND");
    EXPECT_FALSE(s.result.ok());
    ASSERT_FALSE(s.result.diagnostics.empty());
    EXPECT_EQ(s.result.diagnostics[0].location.line, 2);
    EXPECT_EQ(s.result.diagnostics[0].severity, model::Severity::Error);
}

TEST(EngineCompile, PopWithoutPushIsAnError) {
    Sim s("LD X0\nMPP\nOUT Y0\nEND");
    EXPECT_FALSE(s.result.ok());
    EXPECT_EQ(s.result.diagnostics.at(0).location.line, 2);
}

TEST(EngineCompile, JumpWithoutEndIsAnError) {
    Sim s("LD X0\nJMP K3\nEND");
    EXPECT_FALSE(s.result.ok());
}

TEST(EngineCompile, UnmodelledBoxIsReportedAsNotSimulatedAndTheProgramStarts) {
    Sim s("LD X0\nPID D0 D1 D2\nLD X0\nOUT Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_EQ(s.result.diagnostics.size(), 1u);
    EXPECT_EQ(s.result.diagnostics[0].severity, model::Severity::Warning);
    EXPECT_EQ(s.result.diagnostics[0].code, QStringLiteral("SIM100"));
    EXPECT_EQ(s.result.diagnostics[0].location.line, 2);
}

TEST(EngineMonitor, PowerFlowRecordsTheResultAfterEveryInstruction) {
    Sim s("LD X0\nAND X1\nOUT Y0\nLDI X0\nOUT Y1\nEND");
    s.engine->setPowerFlowRecording(true);
    s.in("X0", true);
    s.scan();
    const Snapshot snap = s.engine->snapshot();
    const std::vector<bool> expected{true, false, false, false, false, false};
    EXPECT_EQ(snap.powerFlow, expected);
    EXPECT_TRUE(snap.bit(s.at("X0")));
    EXPECT_FALSE(snap.bit(s.at("Y0")));
    EXPECT_EQ(snap.statistics.scans, 1u);
}

TEST(EngineTimer, Cpm1SetValueFromAWordIsBcdAndABadDigitIsARuntimeError) {
    Sim s("LD X0\nTMR T0 D0\nEND", model::Family::Cpm1);
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D0"), 0x0015); // BCD 15 = 1.5 s; CPM1 timers count down
    s.engine->setPeriodMs(100);
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("T0"), 0x15); // the present value is BCD as well (W353)
    s.scan(5);
    EXPECT_EQ(s.value("T0"), 0x10);
    s.scan(10);
    EXPECT_TRUE(s.bit("T0"));
    EXPECT_EQ(s.value("T0"), 0);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
    s.engine->writeWord(s.at("D0"), 0x001A);
    s.scan(3);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 2);
}

TEST(EngineRun, RunUntilStopsAtTheConditionAndRunForCountsWholePeriods) {
    Sim s("LD SM9000\nINC D0\nEND");
    const model::Address d0 = s.at("D0");
    EXPECT_TRUE(s.engine->runUntil([&](const Engine &e) { return e.value(d0) == 25; }, 100));
    EXPECT_EQ(s.engine->statistics().scans, 25u);
    EXPECT_FALSE(s.engine->runUntil([&](const Engine &e) { return e.value(d0) == 0; }, 10));
    EXPECT_EQ(s.engine->statistics().scans, 35u);
    s.engine->setPeriodMs(20);
    s.engine->runFor(1000);
    EXPECT_EQ(s.engine->statistics().scans, 85u);
    EXPECT_EQ(s.engine->statistics().timeMs, 35 * 10 + 1000);
}

TEST(EngineMonitor, SnapshotShowsForcedBitsAndTimerValues) {
    Sim s("LD X0\nTMR T3 K20\nEND");
    s.engine->force(s.at("X0"), true);
    s.scan(11);
    const Snapshot snap = s.engine->snapshot();
    EXPECT_TRUE(snap.forced(s.at("X0")));
    EXPECT_FALSE(snap.forced(s.at("X1")));
    EXPECT_EQ(snap.value(s.at("T3")), 1);
    EXPECT_TRUE(snap.powerFlow.empty()); // recording is off
    EXPECT_EQ(snap.statistics.timeMs, 110);
}

TEST(EngineApply, TransferAddsEveryScanWhileTheConditionHolds) {
    Sim s("LD X0\nXFER D0 D1\nEND", model::Family::Vpc);
    s.engine->writeWord(s.at("D1"), 4);
    s.scan(2);
    EXPECT_EQ(s.value("D0"), 0);
    s.in("X0", true);
    s.scan(3);
    EXPECT_EQ(s.value("D0"), 12);
}

TEST(EngineMonitor, SnapshotShowsTheSetValueInUseForInstructionConstants) {
    Sim s("LD X0\nTMR T2 K35\nLD X0\nCNT C4 K7\nEND");
    s.scan();
    const Snapshot snap = s.engine->snapshot();
    EXPECT_EQ(snap.setValue(s.at("T2")), 35);
    EXPECT_EQ(snap.setValue(s.at("C4")), 7);
}

TEST(EngineApply, FormulaAppliesEachOperator) {
    Sim s("LD SM9000\nFM K12 + K5 D0\nFM K12 - K5 D1\nFM K12 * K5 D2\nFM K12 / K5 D3\n"
          "FM K12 | K5 D4\nFM K12 & K5 D5\nFM K12 ^ K5 D6\nFM K12 << K2 D7\nFM K12 >> K2 D8\n"
          "FM K1 << K40 D9\nEND");
    ASSERT_TRUE(s.result.ok());
    s.scan();
    const int expected[] = {17, 7, 60, 2, 13, 4, 9, 48, 3, 0};
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(s.engine->value({s.at("D0").area, k, -1}), expected[k]) << k;
}

TEST(EngineApply, FormulaWithAnUnknownOperatorDoesNotCompile) {
    Sim s("LD SM9000\nFM K1 % K2 D0\nEND");
    EXPECT_FALSE(s.result.ok());
}

TEST(EngineApply, SetAndResetBitOfAWord) {
    Sim s("LD X0\nSBIT D0 K3\nLD X1\nRBIT D0 K3\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("D0"), 8);
    s.in("X1", true);
    s.scan();
    EXPECT_EQ(s.value("D0"), 0);
}

TEST(EngineApply, BlockMoveCopiesOrFillsAndChecksTheAreaEnd) {
    Sim s("LD SM9000\nMOV K1 D10\nMOV K2 D11\nMOV K3 D12\nBLKMOV D10 D11 K3\nBLKMOV K9 D20 K2\n"
          "END");
    ASSERT_TRUE(s.result.ok());
    s.scan();
    // overlapping copy behaves as through a buffer: D11..D13 = 1, 2, 3
    EXPECT_EQ(s.value("D11"), 1);
    EXPECT_EQ(s.value("D12"), 2);
    EXPECT_EQ(s.value("D13"), 3);
    EXPECT_EQ(s.value("D20"), 9);
    EXPECT_EQ(s.value("D21"), 9);
    Sim past("LD SM9000\nBLKMOV K0 D98 K5\nEND");
    EXPECT_FALSE(past.result.ok());
}
