// PL110 boxes on the real target table and listing (PL110 manual 4.2.4 - 4.2.9): what the golden
// traces in tests/data/sim/pl110_*.il do not pin.

#include "model/checks/checks.h"
#include "model/image/panel_view.h"
#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

using test::Pl110;

} // namespace

// Contacts and coils of the PL110 manual, 4.2.1 - 4.2.18, on the real PL110 table.
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

// PL110 manual 4.2.4: TONR "consente di accumulare il tempo per piu periodi di attivazione della
// bobina" - every ON period counts whole, also one of a single scan.
TEST(Pl110Timer, TonrAccumulatesOneScanActivations) {
    Pl110 s("LD I1\nTONR T1 100 10\nLD I1\nTON T2 100 10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(10);
    s.pulses("I1", 7); // seven ON periods of one 10 ms scan each
    EXPECT_EQ(s.value("T1"), 7);
    EXPECT_EQ(s.value("T2"), 0); // TON restarts with every activation
}

TEST(Pl110Timer, TonrCountsTheWholeOfEveryOnPeriod) {
    Pl110 s("LD I1\nTONR T1 100 10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(10);
    for (int period = 0; period < 3; ++period) { // three periods of 4 ON scans, 2 OFF
        s.in("I1", true);
        s.engine->runScans(4);
        s.in("I1", false);
        s.engine->runScans(2);
    }
    EXPECT_EQ(s.value("T1"), 12); // 3 x 40 ms in 10 ms units: no first scan lost
}

// PL110 manual 2.1.9 / 2.1.11: PT and PV are where the presets are kept.
TEST(Pl110Presets, PtAndPvReadThePresetsInForce) {
    Pl110 s("LD SM0.0\nMOV PT3 V0\nLD SM0.0\nMOV PV2 V1\nLD I1\nTON T3 25 100\n"
            "LD I1\nLD I2\nLD I3\nMUP C2 7\nLD I1\nTON T4 V10 100\nLD SM0.0\nMOV PT4 V2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("V10"), 12);
    s.engine->scan();
    // Read before the boxes run in this scan: the constant presets are there from the start.
    EXPECT_EQ(s.value("V0"), 25);
    EXPECT_EQ(s.value("V1"), 7);
    EXPECT_EQ(s.value("PT3"), 25);
    EXPECT_EQ(s.value("PV2"), 7);
    EXPECT_EQ(s.value("V2"), 12); // an indirect preset: the value it read
    EXPECT_EQ(s.value("PT1"), 0); // no timer T1: nothing is preset
}

TEST(Pl110Presets, WritingPvChangesTheCounterPreset) {
    Pl110 s("LD I4\nMOV 2 PV1\nLD I1\nLD I2\nLD I3\nMUP C1 5\nEND");
    ASSERT_TRUE(s.result.ok());
    s.pulses("I1", 2);
    EXPECT_EQ(s.value("C1"), 2);
    EXPECT_FALSE(s.bit("C1")); // 2 < 5
    s.in("I4", true);
    s.engine->scan();
    EXPECT_TRUE(s.bit("C1")); // 2 >= the new preset 2
    EXPECT_EQ(s.value("PV1"), 2);
    // A power cycle loads the program's preset again.
    s.in("I4", false);
    s.engine->powerCycle();
    s.engine->scan();
    EXPECT_EQ(s.value("PV1"), 5);
}

// `check` and the simulator read one set of operand rules (model::operandBreaches): what the
// simulator refuses, check reports as OP005 on the same line with the same words.
TEST(Pl110Operands, CheckAndSimulatorRefuseTheSameOperands) {
    struct Case {
        const char *program;
        int line;
        const char *says;
    };
    const Case cases[] = {
        // 4.2.4: time bases of 10 ms, 100 ms and 1 s only
        {"LD I1\nTON T1 5 100\nLD I2\nTOFF T2 5 50\nEND", 4, "10, 100 or 1000, not 50"},
        {"LD I1\nTONR T1 5 1\nEND", 2, "10, 100 or 1000, not 1"},
        // 4.2.14: SBIT / RBIT name bit 0..15
        {"LD I1\nSBIT V3 16\nEND", 2, "from 0 to 15, not 16"},
        {"LD I1\nRBIT V3 -1\nEND", 2, "from 0 to 15, not -1"},
        // ... of a word: Q5 starts no word of Q's 16 bits, so Q5 3 names no bit
        {"LD I1\nSBIT Q5 3\nEND", 2, "Q5 starts no word of 16 bits (Q1 and Q17 do)"},
        // 4.2.12: QI on the terminals Q1..Q8 only
        {"LD I1\nOUTQI Q9\nEND", 2, "OUTQI takes only Q1..Q8, not Q9"},
        {"LD I1\nOUTQI M1\nEND", 2, "OUTQI takes only Q1..Q8, not M1"},
        // 4.2.11: II reads the terminals I1..I8 only
        {"LDII I9\nOUT Q1\nEND", 1, "LDII takes only I1..I8, not I9"},
        // 4.2.3: the bistable relay changes only on its own coil
        {"LD I1\nOUT B1\nEND", 2, "OUT cannot write B1"},
        {"LD I1\nSBIT B2\nEND", 2, "SBIT cannot write B2"},
        {"LD I1\nMOV 1 B1\nEND", 2, "are written only by OUTB"},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.program);
        Pl110 s(c.program);
        ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
        ASSERT_FALSE(s.result.ok());
        ASSERT_EQ(s.result.diagnostics.size(), 1u) << "one message, not the compiler's too";
        const model::Diagnostic &sim = s.result.diagnostics.front();
        EXPECT_EQ(sim.location.line, c.line);
        EXPECT_TRUE(sim.message.contains(QLatin1String(c.says))) << sim.message.toStdString();

        std::vector<model::Diagnostic> op005;
        for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
            if (d.code == QLatin1String("OP005"))
                op005.push_back(d);
        ASSERT_EQ(op005.size(), 1u);
        EXPECT_EQ(op005.front().severity, model::Severity::Error);
        EXPECT_EQ(op005.front().location.line, c.line);
        EXPECT_EQ(op005.front().message, sim.message);
    }
    // What the manual allows passes both.
    for (const char *good : {"LD I1\nTON T1 5 10\nLD I1\nTOFF T2 5 1000\nEND",
                             "LD I1\nSBIT V3 15\nLD I1\nRBIT V3 0\nEND", "LD I1\nOUTQI Q8\nEND",
                             "LDII I8\nOUT Q1\nEND", "LD I1\nOUTB B32\nLD B32\nOUT Q1\nEND"}) {
        SCOPED_TRACE(good);
        Pl110 s(good);
        ASSERT_TRUE(s.parsed.ok());
        EXPECT_TRUE(s.result.ok());
        for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
            EXPECT_NE(d.code, QLatin1String("OP005")) << d.message.toStdString();
    }
}

// 4.2.14 sets or resets "un bit di un'area di memoria", bit 0 the least significant: a bit
// area is a memory of words of 16 bits from I1, Q1, M1, ... (as word operands read it), so
// SBIT Q1 3 is Q1..Q16's bit 3, Q4; without a bit number SBIT Q1 is Q1 itself.
TEST(Pl110Operands, SbitOnABitAreaCountsFromTheWordsFirstBit) {
    Pl110 s("LD I1\nSBIT Q1 3\nLD I1\nSBIT Q17 15\nLD I1\nSBIT M2\n"
            "LD I2\nRBIT Q1 3\nLD I2\nRBIT Q17 15\nLD I2\nRBIT M2\nEND");
    ASSERT_TRUE(s.result.ok());
    for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
        EXPECT_NE(d.severity, model::Severity::Error) << d.message.toStdString();
    s.in("I1", true);
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q4"));
    EXPECT_TRUE(s.bit("Q32"));
    EXPECT_TRUE(s.bit("M2"));
    EXPECT_FALSE(s.bit("Q1"));
    EXPECT_FALSE(s.bit("Q17"));
    EXPECT_EQ(s.value("Q1"), 1 << 3) << "Q1..Q16 read as a word";
    s.in("I1", false);
    s.in("I2", true);
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q4"));
    EXPECT_FALSE(s.bit("Q32"));
    EXPECT_FALSE(s.bit("M2"));
}

// PL110 manual 2.1.2 lists the special markers up to SM185; 5.4's user-page program enables
// pages 17 and 18 with SMW103.0 and SMW103.1 in its initialisation code.
TEST(Pl110SpecialMarkers, TheWholeDocumentedRangeIsAddressable) {
    Pl110 s("LD SM0.1\nSBIT SMW103 0\nLD SM0.1\nSBIT SMW103 1\nLD SM0.0\nMOV SMW105 SM185\n"
            "LD SM0.0\nMOV 7 SMW104\nEND");
    ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("SM105"), 17);
    s.engine->scan();
    EXPECT_EQ(s.value("SM103"), 3); // pages 17 and 18 enabled
    EXPECT_EQ(s.value("SM104"), 7);
    EXPECT_EQ(s.value("SM185"), 17);
    const model::ParseResult beyond =
        model::parseInstructionList(s.target, QStringLiteral("LD SM0.0\nMOV 1 SM186\nEND"));
    EXPECT_FALSE(beyond.ok());
}

// PLProg's [Init] section (5.4) and the timed interrupts (SM16/SM17) are not part of a
// listing: a clear error says so and what to write instead, not "unknown instruction".
TEST(Pl110Sections, InitSectionIsAClearNotSupportedError) {
    const model::Target &t = model::Target::get(model::Family::Pl110);
    const model::ParseResult r = model::parseInstructionList(
        t, QStringLiteral("[Init]\nLD SM0.0\nSBIT SMW103 0\n[Main]\nLD I1\nOUT Q1\nEND\n"));
    ASSERT_EQ(r.errors.size(), 2u);
    EXPECT_EQ(r.errors[0].line, 1);
    EXPECT_EQ(r.errors[1].line, 4);
    EXPECT_TRUE(r.errors[0].message.contains(QStringLiteral("'[Init]' are not supported")))
        << r.errors[0].message.toStdString();
    EXPECT_TRUE(r.errors[0].message.contains(QStringLiteral("LD SM0.1")));
}

// PL110 manual 4.2.5: PV "viene confrontato con il valore corrente al termine di ogni ciclo del
// programma": a contact after the box sees the bit of the previous cycle, and a write to C
// later in the cycle decides the bit.
TEST(Pl110Counter, TheCountBitIsComparedAtTheEndOfTheCycle) {
    Pl110 s("LD I1\nLD I2\nLD I3\nMUP C1 2\nLD C1\nOUT Q1\nLD I4\nMOV 0 C1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.pulses("I1", 1);
    s.in("I1", true);
    s.engine->scan(); // the second count: C1 = 2 >= PV at the end of this cycle
    EXPECT_EQ(s.value("C1"), 2);
    EXPECT_TRUE(s.bit("C1"));
    EXPECT_FALSE(s.bit("Q1")); // LD C1 ran before the compare
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1"));
    s.in("I4", true); // MOV 0 C1 after the box: the compare sees 0
    s.engine->scan();
    EXPECT_EQ(s.value("C1"), 0);
    EXPECT_FALSE(s.bit("C1"));
    EXPECT_TRUE(s.bit("Q1")); // still the previous cycle's bit
}

TEST(Pl110Counter, MdownIsOffWhileResetIsOnAndOnAtZero) {
    Pl110 s("LD I1\nLD I2\nLD I3\nMDOWN C1 2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I3", true);
    s.engine->scan();
    EXPECT_EQ(s.value("C1"), 2);
    EXPECT_FALSE(s.bit("C1"));
    s.in("I3", false);
    s.pulses("I2", 2);
    EXPECT_EQ(s.value("C1"), 0);
    EXPECT_TRUE(s.bit("C1"));
    s.in("I3", true);
    s.engine->scan();
    EXPECT_FALSE(s.bit("C1"));
}

// PL110 manual 2.1.2: SM0.5 TEST "la lettura degli ingressi digitali viene disabilitata. Lo stato
// degli ingressi viene prelevato dalle word SM37" (SM37.0 -> I1, SM37.7 -> I8).
TEST(Pl110TestMode, InputsComeFromSm37WhileSm05IsOn) {
    Pl110 s("LD I1\nOUT Q1\nLD I8\nOUT Q8\nLD I9\nOUT Q9\nLD M1\nOUT SM0.5\nEND");
    ASSERT_TRUE(s.result.ok());
    for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
        EXPECT_NE(d.severity, model::Severity::Error) << d.message.toStdString(); // R/W bits
    s.in("I1", true);
    s.in("I9", true);
    s.engine->writeWord(s.at("SM37"), 0x80); // I8 only
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1")); // SM0.5 still OFF: the terminals
    EXPECT_FALSE(s.bit("Q8"));
    s.in("M1", true);
    s.engine->scan(); // SM0.5 is set at the end of this scan
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q1")); // I1 is ON at the terminal, OFF in SM37
    EXPECT_TRUE(s.bit("Q8"));
    EXPECT_TRUE(s.bit("Q9")); // beyond I8 the terminals still count
    s.in("M1", false);
    s.engine->scan();
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q1"));
    EXPECT_FALSE(s.bit("Q8"));
}

// The positioning example of the PL110 manual, 4.2.20, compares with a signed constant,
// "IF VD8 == #-1" (on a single word here; the manual's own double word VD8 is golden trace
// pl110_double_words).
TEST(Pl110Contacts, IfComparesWithASignedHashConstant) {
    Pl110 s("LD= V8 #-1\nOUT Q4\nLD= V8 1\nOUT Q3\nEND");
    ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("V8"), -1);
    s.engine->scan();
    EXPECT_TRUE(s.bit("Q4"));
    EXPECT_FALSE(s.bit("Q3"));
    s.engine->writeWord(s.at("V8"), 1);
    s.engine->scan();
    EXPECT_FALSE(s.bit("Q4"));
    EXPECT_TRUE(s.bit("Q3"));
}

// Issue 14: what `check` warns as not simulated (SIM101, PL110 manual 2.1.2) the simulator says
// again when it starts, with the same words.
TEST(Pl110Unmodelled, TheSimulatorWarnsAsCheckDoes) {
    Pl110 s("LD SM0.0\nMOV 50 SM4\nLD SM0.0\nMOV SM71 V0\nLD SM110.3\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    std::vector<model::Diagnostic> fromCheck;
    for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
        if (d.code == QLatin1String("SIM101"))
            fromCheck.push_back(d);
    ASSERT_EQ(fromCheck.size(), 2u); // SM4 and SM71; the SET key SM110.3 is simulated
    ASSERT_EQ(s.result.diagnostics.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(s.result.diagnostics[k].code, QLatin1String("SIM101"));
        EXPECT_EQ(s.result.diagnostics[k].location.line, fromCheck[k].location.line);
        EXPECT_EQ(s.result.diagnostics[k].message, fromCheck[k].message);
    }
}

// Issue 30, PL110 manual 2.1.2: the terminal's words at power-on are the table's defaults
// ("SM102 ... default 31=tutte abilit.", "SM104 Numero pagina di avvio (default 1)", SM129
// "Cifre totali campo parametro 1 (default 1)", SM132 row 2, SM133 column 15), and the page
// shown (SM105) is the start page from the end of the first scan.
TEST(Pl110Terminal, PowerOnDefaultsAndTheStartPage) {
    Pl110 s("LD I1\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_EQ(s.value("SM101"), 2);
    EXPECT_EQ(s.value("SM102"), 31);
    EXPECT_EQ(s.value("SM104"), 1);
    EXPECT_EQ(s.value("SM129"), 1);
    EXPECT_EQ(s.value("SM132"), 2);
    EXPECT_EQ(s.value("SM149"), 4);
    EXPECT_EQ(s.value("SM183"), 8);
    EXPECT_EQ(s.value("SM184"), 15);
    EXPECT_EQ(s.value("SM105"), 0);
    s.engine->scan();
    EXPECT_EQ(s.value("SM105"), 1);
}

// 5.4: the initialisation enables user pages 17 and 18 ("settando a 1 i bit SMW103.0 e
// SMW103.1 si abilitano le prime 2 pagine utente"); a start page set there (SM104: "impostare
// questa word SM nel codice di inizializzazione") is the first page shown.
TEST(Pl110Terminal, TheStartPageTheInitialisationSets) {
    Pl110 s("LD SM0.1\nSBIT SMW103 0\nLD SM0.1\nSBIT SMW103 1\nLD SM0.1\nMOV 18 SM104\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_EQ(s.value("SM105"), 18);
}

// SM106: "Se la pagina esiste ed è abilitata, verrà visualizzata, mentre se il valore scritto non
// è congruente, la visualizzazione rimarrà alla pagina attuale. Una volta richiamata la pagina
// richiesta, la word verrà automaticamente forzata al valore 0".
TEST(Pl110Terminal, APageRequestIsShownAndResetAnUnknownOneIsKept) {
    Pl110 s("LD SM0.1\nSBIT SMW103 0\nLD I1\nMOV 17 SM106\nLD I2\nMOV 20 SM106\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_EQ(s.value("SM105"), 1);
    s.in("I1", true);
    s.engine->scan();
    EXPECT_EQ(s.value("SM105"), 17);
    EXPECT_EQ(s.value("SM106"), 0);
    s.in("I1", false);
    s.in("I2", true); // page 20 is not enabled
    s.engine->scan();
    EXPECT_EQ(s.value("SM105"), 17);
    EXPECT_EQ(s.value("SM106"), 20);
}

// SM107 / SM108 (2.1.2): "se tramite il terminale si modifica la variabile VW30, si avrà, per il
// solo ciclo di scansione successivo alla modifica, SM107 = 1 e SM108 = 30. Nel ciclo successivo
// le due aree verranno automaticamente poste a 0." The keys store between scans (the front
// panel writes the variable and the note); the program reads the note in the scan after.
TEST(Pl110Terminal, TheNoteOfTheLastVariableStoredLastsOneScan) {
    Pl110 s("LD SM0.0\nMOV SM107 V0\nLD SM0.0\nMOV SM108 V2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    s.engine->writeWord(s.at("VW30"), 7);
    s.engine->writeWord(s.at("SM107"), 1);
    s.engine->writeWord(s.at("SM108"), 30);
    s.engine->scan();
    EXPECT_EQ(s.value("V0"), 1); // the program saw the note
    EXPECT_EQ(s.value("V2"), 30);
    EXPECT_EQ(s.value("SM107"), 0); // and it is gone after that scan
    EXPECT_EQ(s.value("SM108"), 0);
    s.engine->scan();
    EXPECT_EQ(s.value("V0"), 0);
    EXPECT_EQ(s.value("V2"), 0);
    EXPECT_EQ(s.value("VW30"), 7); // the variable itself stays
}

// 5.2: "Il tasto swap permette di scorrere in modo circolare tutte le pagine rese disponibili
// dal programma ladder": one page a press (SM110.0 from 0 to 1), the system pages SM102 enables
// then the user pages SM103 enables, back to the first.
TEST(Pl110Terminal, SwapStepsThroughTheEnabledPagesInACircle) {
    Pl110 s("LD SM0.1\nMOV 5 SM102\nLD SM0.1\nMOV 2 SM103\nEND"); // pages 1, 3 and 18
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    ASSERT_EQ(s.value("SM105"), 1);
    std::vector<int> shown;
    for (int press = 0; press < 3; ++press) {
        s.engine->writeWord(s.at("SM110"), 1);
        s.engine->scan();
        s.engine->scan(); // held: one step only
        shown.push_back(s.value("SM105"));
        s.engine->writeWord(s.at("SM110"), 0);
        s.engine->scan();
    }
    EXPECT_EQ(shown, (std::vector<int>{3, 18, 1}));
}

// The END's port work is skipped while no port is used (issue 35, Engine::portsBusy), and
// comes back when the program switches a port to free-port without any instruction or
// network: SM79 then counts the receive buffer, and a write to it empties the buffer (PL110
// manual 2.1.2: "qualsiasi scrittura ... equivale allo svuotamento del buffer").
TEST(Pl110Ports, FreePortSwitchedOnByTheProgramAloneKeepsTheReceiveCount) {
    Pl110 s("LD I2\nMOV 256 SM78\nLD I1\nMOV 5 SM79\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    s.engine->scan();
    EXPECT_EQ(s.value("SM79"), 5); // no port in use: SM79 is the program's word
    s.in("I2", true);
    s.engine->scan();
    EXPECT_EQ(s.value("SM78"), 256);
    EXPECT_EQ(s.value("SM79"), 0); // free-port: the write emptied the buffer
    s.in("I2", false);
    s.engine->scan();
    EXPECT_EQ(s.value("SM79"), 0);
}

// PL110 manual 2.1.16: "Per scrivere "TESTO DISPLAY" nella riga 3 del display per esempio, nel
// programma ladder sara sufficiente inserire la seguente bobina: MOVTXT (DISP42, 1 Char per
// word) "TESTO DISPLAY"": one character a word from DISP42 while the coil's condition is ON.
TEST(Pl110Movtxt, StoresTheManualsDisplayRowOneCharacterAWord) {
    Pl110 s("LD I1\nMOVTXT DISP42 1 \"TESTO DISPLAY\"\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_EQ(s.value("DISP42"), 0) << "nothing stored while the condition is OFF";
    s.engine->setBit(s.at("I1"), true);
    s.engine->scan();
    const QString expected = QStringLiteral("TESTO DISPLAY");
    for (int k = 0; k < expected.size(); ++k) {
        const QByteArray name = QStringLiteral("DISP%1").arg(42 + k).toLatin1();
        EXPECT_EQ(s.value(name.constData()), expected[k].unicode()) << name.constData();
    }
    EXPECT_EQ(s.value("DISP55"), 0) << "the word after the text is untouched";
}

// 4.2.10: DUE_CARATTERI_PER_WORD, "iniziando dalla parte alta della word": "ABC" is 4142h,
// then 43h in the high byte of the next word.
TEST(Pl110Movtxt, TwoCharactersAWordStartAtTheHighByte) {
    Pl110 s("LD SM0.0\nMOVTXT V10 2 \"ABC\"\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_EQ(s.value("V10"), 0x4142);
    EXPECT_EQ(s.value("V11"), 0x4300);
    EXPECT_EQ(s.value("V12"), 0);
}

// PL110 manual 5.4's page 18: "SetPAR1 [Modifiable, Par = VW0, Min = #0, Max = #1400]",
// "FormatPAR1 [16 bit signed, Tot7, Dec1, Spaces]", "PosPAR1 [Row4, Column10, Free]" (4.2.26
// ..4.2.28): field 1's words of 2.1.2 from SM118 (state, the variable's area in SM107's list
// and number high / low, the limits' likewise, type, digits, decimals, fill, row, column,
// access), written while the coils' condition is ON; the terminal then shows VW0 = 250 as
// "25.0" in row 4 from column 10.
TEST(Pl110Terminal, SetParFormatParAndPosParWriteTheFieldsWords) {
    Pl110 s("LD I1\nSetPAR 1 2 VW0 0 1400\nLD I1\nFormatPAR 1 0 7 1 0\nLD I1\nPosPAR 1 4 10 "
            "0\nLD I1\nSetPAR 2 1 AI1 V10 #99\nLD I1\nPosPAR 2 6 10 0\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_TRUE(s.result.diagnostics.empty()) << s.result.diagnostics.front().message.toStdString();
    s.engine->scan();
    EXPECT_EQ(s.value("SM118"), 0) << "nothing written while the condition is OFF";
    s.engine->setBit(s.at("I1"), true);
    s.engine->scan();
    std::vector<int> field1;
    for (int k = 118; k < 135; ++k)
        field1.push_back(s.value(QStringLiteral("SM%1").arg(k).toLatin1().constData()));
    EXPECT_EQ(field1, (std::vector<int>{2, 1, 0, 0, 0, 0, 0, 0, 0, 1400, 0, 7, 1, 0, 4, 10, 0}));
    // Field 2 (from SM135): AI1 is area 3 number 1, the minimum V10 (area 1, 10).
    std::vector<int> field2;
    for (int k = 135; k < 145; ++k)
        field2.push_back(s.value(QStringLiteral("SM%1").arg(k).toLatin1().constData()));
    EXPECT_EQ(field2, (std::vector<int>{1, 3, 0, 1, 1, 0, 10, 0, 0, 99}));

    // Field 2 in row 6 (at power-on the fields stand in rows 2, 4, 6, 8 at column 15).
    s.engine->writeWord(s.at("VW0"), 250);
    s.engine->writeWord(s.at("SM105"), 18);
    const model::Snapshot shot = s.engine->snapshot();
    model::PanelInput in;
    in.snapshot = &shot;
    in.runState = model::MonitorSource::RunState::Running;
    const model::PanelView view =
        model::panelView(s.target, s.target.model(QStringLiteral("PL110-2A")), in);
    ASSERT_GE(view.lines.size(), 4);
    EXPECT_EQ(view.lines[3], QStringLiteral("             25.0    "))
        << view.lines.join(u'|').toStdString();
}

// A field the display does not have, and a variable that is not in SM107's list, do not
// compile; the table's ranges are `check`'s.
TEST(Pl110Terminal, SetParRefusesWhatTheFieldCannotHold) {
    const auto firstMessage = [](const Pl110 &s) {
        return s.result.diagnostics.empty() ? std::string()
                                            : s.result.diagnostics.front().message.toStdString();
    };
    Pl110 bit("LD I1\nSetPAR 1 2 Q1 0 10\nEND");
    EXPECT_FALSE(bit.result.ok());
    EXPECT_NE(firstMessage(bit).find("not Q1"), std::string::npos) << firstMessage(bit);
    Pl110 row("LD I1\nPosPAR 1 9 10 0\nEND");
    EXPECT_FALSE(row.result.ok());
    EXPECT_NE(firstMessage(row).find("row of PosPAR must be from 1 to 8, not 9"), std::string::npos)
        << firstMessage(row);
}
