// PL110 boxes on the real target table and listing (seed 003 4.2.4 - 4.2.9): what the golden
// traces in tests/data/sim/pl110_*.il do not pin.

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

struct Pl110 : test::RealTargetSim {
    explicit Pl110(const char *text)
        : RealTargetSim(model::Family::Pl110, text) {}
};

} // namespace

// Contacts and coils of seed 003 4.2.1 - 4.2.18 on the real PL110 table.
TEST(Pl110Contacts, PIsOnForOneScanWhenThePowerFlowRises) {
    Pl110 s("LD I1\nP\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty());
    EXPECT_EQ(s.run("I1", "0111001100", "Q1"), "0100001000");
}

TEST(Pl110Contacts, NIsOnForOneScanWhenThePowerFlowFalls) {
    Pl110 s("LD I1\nN\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_EQ(s.run("I1", "0111001100", "Q1"), "0000100010");
}

TEST(Pl110Contacts, PActsOnThePowerFlowAtItsPlaceNotOnADevice) {
    // I1 stays ON; the flow reaching P rises when I2 turns ON.
    Pl110 s("LD I1\nAND I2\nP\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    EXPECT_EQ(s.run("I2", "011011", "Q1"), "010010");
}

TEST(Pl110Contacts, NotInvertsThePowerFlow) {
    Pl110 s("LD I1\nAND I2\nNOT\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    EXPECT_EQ(s.run("I2", "0110", "Q1"), "1001");
}

TEST(Pl110Contacts, ImmediateInputContactReadsTheInput) {
    Pl110 s("LDII I1\nOUT Q1\nLDNII I1\nOUT Q2\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_EQ(s.run("I1", "0110", "Q1"), "0110");
    EXPECT_FALSE(s.bit("Q1"));
    EXPECT_TRUE(s.bit("Q2"));
}

TEST(Pl110Contacts, BistableContactFollowsTheBBit) {
    Pl110 s("LD B3\nOUT Q1\nLDN B3\nOUT Q2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q1"));
    EXPECT_TRUE(s.bit("Q2"));
    s.in("B3", true);
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1"));
    EXPECT_FALSE(s.bit("Q2"));
}

TEST(Pl110Contacts, IfComparesTwoValues) {
    Pl110 s("LD>= V1 V2\nOUT Q1\nLDIF<> V1 5\nOUT Q2\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("V1"), 5);
    s.engine->writeWord(s.at("V2"), 7);
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q1"));
    EXPECT_FALSE(s.bit("Q2"));
    s.engine->writeWord(s.at("V2"), -3);
    s.engine->writeWord(s.at("V1"), 6);
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1"));
    EXPECT_TRUE(s.bit("Q2"));
}

TEST(Pl110Contacts, BitContactReadsOneBitOfAWord) {
    Pl110 s("LD V3.5\nOUT Q1\nLDN V3.0\nOUT Q2\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("V3"), 1 << 5 | 1);
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1"));
    EXPECT_FALSE(s.bit("Q2"));
    s.engine->writeWord(s.at("V3"), 1 << 4);
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q1"));
    EXPECT_TRUE(s.bit("Q2"));
}

TEST(Pl110Coils, ImmediateOutputIsSeenByTheRestOfTheScan) {
    Pl110 s("LD I1\nOUTQI Q2\nLD Q2\nOUT M1\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_EQ(s.run("I1", "0110", "Q2"), "0110");
    s.in("I1", true);
    s.engine->scan();
    EXPECT_TRUE(s.bit("M1")); // OUTQI is simulated as a coil the rest of the scan reads
}

TEST(Pl110Coils, BistableCoilFlipsOnEachActivation) {
    Pl110 s("LD I1\nOUTB B1\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty()); // simulated, not a SIM100 warning
    EXPECT_EQ(s.run("I1", "0111010110", "B1"), "0111100111");
}

TEST(Pl110Coils, BistableCoilStartsFromTheBitAsWritten) {
    Pl110 s("LD I1\nOUTB B2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("B2", true);
    EXPECT_EQ(s.run("I1", "0100", "B2"), "1000");
}

TEST(Pl110Timer, TimeBaseOperandSetsTheUnitOfTheCurrentValue) {
    Pl110 s("LD I1\nTON T1 5 1000\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(100);
    s.in("I1", true);
    s.engine->runScans(50); // the first scan starts the timer, 49 more are 4.9 s
    EXPECT_EQ(s.value("T1"), 4);
    EXPECT_FALSE(s.bit("T1"));
    s.engine->scan();
    EXPECT_EQ(s.value("T1"), 5);
    EXPECT_TRUE(s.bit("T1"));
}

TEST(Pl110Timer, OnlyTheThreeTimeBasesOfTheManualAreAccepted) {
    Pl110 s("LD I1\nTON T1 5 100\nLD I2\nTOFF T2 5 50\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_FALSE(s.result.ok());
    ASSERT_FALSE(s.result.diagnostics.empty());
    EXPECT_EQ(s.result.diagnostics.front().location.line, 4);
    EXPECT_TRUE(s.result.diagnostics.front().message.contains(QStringLiteral("10, 100 or 1000")));
}

TEST(Pl110Timer, CurrentValueStopsAt32767) {
    Pl110 s("LD I1\nTON T1 100 10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    s.engine->runScans(40000);
    EXPECT_EQ(s.value("T1"), 32767);
    EXPECT_TRUE(s.bit("T1"));
}

TEST(Pl110Counter, UpCountStaysAtTheMaximum) {
    Pl110 s("LD I1\nLD I2\nLD I3\nMUP C1 10\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty()); // MUP is simulated, not a SIM100 warning
    s.engine->writeWord(s.at("C1"), 32767);
    s.in("I1", true);
    s.engine->scan();
    EXPECT_EQ(s.value("C1"), 32767);
    EXPECT_TRUE(s.bit("C1"));
}

TEST(Pl110Counter, DownCountOfMupStaysAtTheMinimum) {
    Pl110 s("LD I1\nLD I2\nLD I3\nMUP C1 10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("C1"), -32768);
    s.in("I2", true);
    s.engine->scan();
    EXPECT_EQ(s.value("C1"), -32768);
}

TEST(Pl110IndirectMove, IndexOutsideTheAreaIsARuntimeErrorWithItsLine) {
    // V340..V349 are the last ten words of V: index 10 is one past the end.
    Pl110 s("LD SM0.0\nMOVIND 5 V340 V0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("V0"), 9);
    s.engine->scan();
    EXPECT_EQ(s.value("V349"), 5);
    s.engine->writeWord(s.at("V0"), 10);
    s.engine->scan();
    s.engine->writeWord(s.at("V0"), -1);
    s.engine->scan();
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u); // reported once per step
    EXPECT_EQ(s.engine->runtimeErrors().front().line, 2);
    EXPECT_TRUE(s.engine->runtimeErrors().front().message.contains(QStringLiteral("0..9")));
    EXPECT_EQ(s.value("V339"), 0); // nothing written outside the vector
}

TEST(Pl110Boxes, UnmodelledBoxesAreReportedWhenTheSimulationStarts) {
    Pl110 s("LD I1\nPID 1 2 3\nLD I1\nOUT Q1\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_TRUE(s.result.ok());
    ASSERT_EQ(s.result.diagnostics.size(), 1u);
    EXPECT_EQ(s.result.diagnostics[0].code, QStringLiteral("SIM100"));
    EXPECT_EQ(s.result.diagnostics[0].location.line, 2);
}

TEST(Pl110Power, VariablesSurviveAPowerCycleMarkersAndTimersClear) {
    Pl110 s("LD I1\nOUT M1\nLD I1\nTONR T1 100 10\nLD I1\nMOV 42 V5\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    s.engine->runScans(10);
    ASSERT_TRUE(s.bit("M1"));
    ASSERT_EQ(s.value("T1"), 9);
    s.in("I1", false);
    s.engine->powerCycle();
    EXPECT_EQ(s.value("V5"), 42);
    EXPECT_FALSE(s.bit("M1"));
    EXPECT_EQ(s.value("T1"), 0);
}

TEST(SimulationStart, ProgramWithACheckErrorDoesNotStart) {
    const model::Target &t = model::Target::get(model::Family::Cpm1);
    const model::ParseResult bad =
        model::parseInstructionList(t, QStringLiteral("LD 000.00\nOUT 010.00\nLD 000.01\n"
                                                      "OUT 010.00\nEND\n"));
    ASSERT_TRUE(bad.ok());
    const CompileResult refused = prepareProgram(bad.list);
    EXPECT_FALSE(refused.ok());
    ASSERT_FALSE(refused.diagnostics.empty());
    EXPECT_EQ(refused.diagnostics.front().severity, model::Severity::Error);
    EXPECT_EQ(refused.diagnostics.front().location.line, 4);

    const model::ParseResult good =
        model::parseInstructionList(t, QStringLiteral("LD 000.00\nOR 000.01\nOUT 010.00\nEND\n"));
    ASSERT_TRUE(good.ok());
    EXPECT_TRUE(prepareProgram(good.list).ok());
}
