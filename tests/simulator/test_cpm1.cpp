// The CPM1's application instructions in the simulator (issue 14), as Omron's CPM1
// programming manual W353 describes them: BCD and binary arithmetic with the flags ER 255.03,
// CY 255.04, GR 255.05, EQ 255.06, LE 255.07 (appendix B "Error and Arithmetic Flag
// Operation"), moves, shifts, the "@" forms, subroutines and steps. The golden traces
// cpm1_add_carry, cpm1_sft, cpm1_step_snxt and cpm1_subroutine run the manual's examples.

#include "real_target_sim.h"

#include "model/checks/checks.h"
#include "simulator/trace.h"

#include <QTextStream>

#include <gtest/gtest.h>

#include <algorithm>

using namespace rung;
using namespace rung::simulator;

namespace {

QString lines(const char *semicolonSeparated) {
    return QString::fromLatin1(semicolonSeparated).replace(QLatin1Char(';'), QLatin1Char('\n'));
}

struct Cpm1Sim : test::RealTargetSim {
    explicit Cpm1Sim(const char *text)
        : RealTargetSim(model::Family::Cpm1, lines(text).toLatin1().constData()) {}
    void word(const char *name, std::int32_t value) { engine->writeWord(at(name), value); }
    std::uint32_t hex(const char *name) const {
        return static_cast<std::uint32_t>(value(name)) & 0xFFFFu;
    }
    std::string errors() const {
        std::string s;
        for (const RuntimeError &e : engine->runtimeErrors())
            s += std::to_string(e.line) + ": " + e.message.toStdString() + "\n";
        return s;
    }
};

// The flags go OFF at END, so a program copies them where they can be seen (W353: "their
// status cannot be monitored with a Programming Device").
const char *kCopyFlags = "AND 255.03;OUT 200.03;LD 253.13;AND 255.04;OUT 200.04;LD 253.13;"
                         "AND 255.05;OUT 200.05;LD 253.13;AND 255.06;OUT 200.06;LD 253.13;"
                         "AND 255.07;OUT 200.07;END(01)";

std::string program(const char *body) {
    return std::string(body) + ";LD 253.13;" + kCopyFlags;
}

} // namespace

// W353 ADD(30): "adds the contents of Au, Ad, and CY, and places the result in R. CY will be
// set if the result is greater than 9999"; SUB(31): "If the result is negative, CY is set and
// the 10's complement of the actual result is placed in R".
TEST(Cpm1Arithmetic, BcdAddAndSubtractCarryAndComplement) {
    Cpm1Sim add(program("LD 253.13;CLC(41);ADD(30) DM 0000 DM 0001 DM 0002").c_str());
    ASSERT_TRUE(add.result.ok());
    add.word("DM 0000", 0x9000);
    add.word("DM 0001", 0x1234);
    add.engine->scan();
    EXPECT_EQ(add.hex("DM 0002"), 0x0234u);
    EXPECT_TRUE(add.bit("200.04")); // CY
    EXPECT_FALSE(add.bit("200.06"));
    EXPECT_FALSE(add.bit("255.04")) << "the flags are OFF after END";

    Cpm1Sim sub(program("LD 253.13;CLC(41);SUB(31) DM 0000 DM 0001 DM 0002").c_str());
    ASSERT_TRUE(sub.result.ok());
    sub.word("DM 0000", 0x0100);
    sub.word("DM 0001", 0x0250);
    sub.engine->scan();
    EXPECT_EQ(sub.hex("DM 0002"), 0x9850u); // 100 - 250 = -150: 10000 - 150
    EXPECT_TRUE(sub.bit("200.04"));
    sub.word("DM 0001", 0x0100);
    sub.engine->scan();
    EXPECT_EQ(sub.hex("DM 0002"), 0u);
    EXPECT_FALSE(sub.bit("200.04"));
    EXPECT_TRUE(sub.bit("200.06")); // EQ: the result is 0
}

// The carry goes into the next addition unless CLC(41) clears it; STC(40) sets it.
TEST(Cpm1Arithmetic, CarryIsAddedUntilCleared) {
    Cpm1Sim s("LD 253.13;STC(40);ADD(30) #0001 #0002 DM 0000;ADB(50) #0001 #0002 DM 0001;"
              "CLC(41);ADD(30) #0001 #0002 DM 0002;END(01)");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0004u); // 1 + 2 + CY
    EXPECT_EQ(s.hex("DM 0001"), 0x0003u); // the first ADD cleared CY (no carry)
    EXPECT_EQ(s.hex("DM 0002"), 0x0003u);
}

TEST(Cpm1Arithmetic, BcdMultiplyAndDivideUseTwoWords) {
    Cpm1Sim s(program("LD 253.13;MUL(32) DM 0000 DM 0001 DM 0010;DIV(33) DM 0000 DM 0001 "
                      "DM 0020")
                  .c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x9999);
    s.word("DM 0001", 0x0012);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0010"), 0x9988u); // 9999 x 12 = 119988
    EXPECT_EQ(s.hex("DM 0011"), 0x0011u);
    EXPECT_EQ(s.hex("DM 0020"), 0x0833u); // 9999 / 12 = 833 remainder 3
    EXPECT_EQ(s.hex("DM 0021"), 0x0003u);
    EXPECT_TRUE(s.engine->runtimeErrors().empty()) << s.errors();
}

// W353 appendix B: "instructions with a vertical arrow under the ER column are not executed
// if ER is ON"; an operand that is not BCD turns ER ON.
TEST(Cpm1Arithmetic, AnOperandThatIsNotBcdSetsErAndWritesNothing) {
    Cpm1Sim s(program("LD 253.13;ADD(30) DM 0000 #0001 DM 0001").c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x12A4);
    s.word("DM 0001", 0x5555);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0001"), 0x5555u);
    EXPECT_TRUE(s.bit("200.03")); // ER
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 2);
    EXPECT_TRUE(s.engine->runtimeErrors()[0].message.contains(QStringLiteral("#12A4")))
        << s.errors();
    EXPECT_TRUE(s.engine->runtimeErrors()[0].message.contains(QStringLiteral("255.03")))
        << s.errors();
    // Correct again: it runs and ER goes OFF.
    s.word("DM 0000", 0x1234);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0001"), 0x1235u);
    EXPECT_FALSE(s.bit("200.03"));
}

TEST(Cpm1Arithmetic, DivisionByZeroSetsEr) {
    Cpm1Sim s(program("LD 253.13;DIV(33) #0010 DM 0000 DM 0001").c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0001", 0x7777);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0001"), 0x7777u);
    EXPECT_TRUE(s.bit("200.03"));
}

// W353 ADB(50): "CY will be set if the result is greater than FFFF"; SBB(51): "If the result
// is negative, CY is set and the 2's complement of the actual result is placed in R".
TEST(Cpm1Arithmetic, BinaryAddAndSubtract) {
    Cpm1Sim s(program("LD 253.13;CLC(41);ADB(50) DM 0000 DM 0001 DM 0002;AND 255.04;OUT 201.00;"
                      "LD 253.13;CLC(41);SBB(51) DM 0001 DM 0000 DM 0003")
                  .c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0xF000);
    s.word("DM 0001", 0x2000);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0002"), 0x1000u);
    EXPECT_TRUE(s.bit("201.00"));         // the carry of ADB
    EXPECT_EQ(s.hex("DM 0003"), 0x3000u); // 2000h - F000h = -D000h: 2's complement 3000h
    EXPECT_TRUE(s.bit("200.04"));
}

// W353 INC(38) / DEC(39): BCD, without a carry: 9999 + 1 = 0000 (EQ), 0000 - 1 = 9999.
TEST(Cpm1Arithmetic, IncrementAndDecrementWrapInBcd) {
    Cpm1Sim s(program("LD 253.13;INC(38) DM 0000;LD 253.13;DEC(39) DM 0001").c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x0998);
    s.word("DM 0001", 0x0001);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0999u);
    EXPECT_EQ(s.hex("DM 0001"), 0x0000u);
    EXPECT_TRUE(s.bit("200.06")); // DEC's result 0: EQ
    s.word("DM 0000", 0x9999);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0000u);
    EXPECT_EQ(s.hex("DM 0001"), 0x9999u);
    EXPECT_FALSE(s.bit("200.04")); // no carry
}

// W353 CMP(20): GR, EQ and LE from two unsigned words; the flags are read right after it.
TEST(Cpm1Compare, SetsGreaterEqualLess) {
    Cpm1Sim s(program("LD 253.13;CMP(20) DM 0000 #0100").c_str());
    ASSERT_TRUE(s.result.ok());
    const auto flags = [&] {
        std::string f;
        for (const char *b : {"200.05", "200.06", "200.07"})
            f += s.bit(b) ? '1' : '0';
        return f;
    };
    s.word("DM 0000", 0x0200);
    s.engine->scan();
    EXPECT_EQ(flags(), "100");
    s.word("DM 0000", 0x0100);
    s.engine->scan();
    EXPECT_EQ(flags(), "010");
    s.word("DM 0000", 0x0050);
    s.engine->scan();
    EXPECT_EQ(flags(), "001");
    s.word("DM 0000", 0x8000); // unsigned: 8000h is above 0100h
    s.engine->scan();
    EXPECT_EQ(flags(), "100");
}

// W353 MOV(21) / MVN(22): "EQ: ON when all zeros are transferred".
TEST(Cpm1Moves, MoveAndMoveNotSetEq) {
    Cpm1Sim s(program("LD 253.13;MOV(21) DM 0000 DM 0001;MVN(22) DM 0000 DM 0002").c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x00F0);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0001"), 0x00F0u);
    EXPECT_EQ(s.hex("DM 0002"), 0xFF0Fu);
    EXPECT_FALSE(s.bit("200.06"));
    s.word("DM 0000", 0xFFFF); // MOV moves FFFF, MVN writes 0000: EQ from the last one
    s.engine->scan();
    EXPECT_TRUE(s.bit("200.06"));
}

// W353 MOVB(82) S Bi D: Bi's rightmost two digits name S's bit, the leftmost two D's bit.
// MOVD(83) S Di D: Di's digit 0 the first source digit, digit 1 the number of digits - 1,
// digit 2 the first destination digit; digits wrap from the leftmost to the rightmost.
TEST(Cpm1Moves, BitAndDigitMoves) {
    Cpm1Sim s(program("LD 253.13;MOVB(82) DM 0000 #1203 DM 0001;MOVD(83) DM 0000 #0210 DM 0002;"
                      "MOVD(83) DM 0000 #0033 DM 0003")
                  .c_str());
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x1238); // bit 03 is ON
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0001"), 0x1000u); // bit 12 := bit 03
    EXPECT_EQ(s.hex("DM 0002"), 0x3800u); // digits 0, 1 (8, 3) into digits 2, 3
    EXPECT_EQ(s.hex("DM 0003"), 0x2381u); // 4 digits from digit 3 on, wrapping
    EXPECT_TRUE(s.engine->runtimeErrors().empty()) << s.errors();
    // A bit designator read from a channel is checked when it runs: ER, nothing written.
    Cpm1Sim c(program("LD 253.13;MOVB(82) DM 0000 DM 0005 DM 0001").c_str());
    ASSERT_TRUE(c.result.ok());
    c.word("DM 0000", 0xFFFF);
    c.word("DM 0005", 0x0016);
    c.engine->scan();
    EXPECT_EQ(c.hex("DM 0001"), 0u);
    EXPECT_TRUE(c.bit("200.03"));
}

// W353 WSFT(16) St E: "shifts data between St and E in word units. Zeros are written into St
// and the content of E is lost."
TEST(Cpm1Shift, WordShiftMovesWordsUp) {
    Cpm1Sim s("LD 000.00;@WSFT(16) DM 0000 DM 0002;END(01)");
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x1111);
    s.word("DM 0001", 0x2222);
    s.word("DM 0002", 0x3333);
    s.in("000.00", true);
    s.engine->scan();
    s.engine->scan(); // differentiated: once
    EXPECT_EQ(s.hex("DM 0000"), 0u);
    EXPECT_EQ(s.hex("DM 0001"), 0x1111u);
    EXPECT_EQ(s.hex("DM 0002"), 0x2222u);
}

// SFT(10) over two words: bit 15 of St goes into bit 00 of the next word.
TEST(Cpm1Shift, ShiftRegisterCarriesAcrossWords) {
    Cpm1Sim s("LD 000.00;LD 000.01;LD 000.02;SFT(10) HR00 HR01;END(01)");
    ASSERT_TRUE(s.result.ok());
    s.word("HR00", static_cast<std::int16_t>(0x8001));
    s.pulses("000.01", 1);
    EXPECT_EQ(s.hex("HR00"), 0x0002u);
    EXPECT_EQ(s.hex("HR01"), 0x0001u);
    s.in("000.00", true); // data ON; the pulse held ON shifts once
    s.in("000.01", true);
    s.engine->scan();
    s.engine->scan();
    EXPECT_EQ(s.hex("HR00"), 0x0005u);
    s.in("000.02", true); // reset
    s.engine->scan();
    EXPECT_EQ(s.hex("HR00"), 0u);
    EXPECT_EQ(s.hex("HR01"), 0u);
}

// W353: "Differentiated instructions are executed only once when their execution condition
// changes ... from OFF to ON".
TEST(Cpm1Differentiated, RunsOnceOnTheRisingEdgeAndLeavesTheRungCondition) {
    Cpm1Sim s("LD 000.00;@INC(38) DM 0000;INC(38) DM 0001;OUT 010.00;END(01)");
    ASSERT_TRUE(s.result.ok());
    s.in("000.00", true);
    for (int k = 0; k < 3; ++k)
        s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0001u);
    EXPECT_EQ(s.hex("DM 0001"), 0x0003u); // the level condition goes on after @INC
    EXPECT_TRUE(s.bit("010.00"));
    s.in("000.00", false);
    s.engine->scan();
    s.in("000.00", true);
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0002u);
}

// W353 TIM: "ER: SV is not in BCD" - the timer's set value read from a channel.
TEST(Cpm1Flags, TimerWithANonBcdSetValueSetsEr) {
    Cpm1Sim s("LD 253.13;TIM 000 DM 0000;LD 253.13;AND 255.03;OUT 200.03;END(01)");
    ASSERT_TRUE(s.result.ok());
    s.word("DM 0000", 0x00AB);
    s.engine->scan();
    EXPECT_TRUE(s.bit("200.03"));
}

// W353 "Subroutines": SBS(91) nests up to 16 levels; a subroutine that calls itself goes
// deeper and is stopped with a runtime error instead of hanging.
TEST(Cpm1Subroutines, NestingDeeperThanSixteenIsARuntimeError) {
    Cpm1Sim s("LD 253.13;SBS(91) 00;SBN(92) 00;LD 253.13;INC(38) DM 0000;LD 253.13;SBS(91) 00;"
              "RET(93);END(01)");
    ASSERT_TRUE(s.result.ok()) << (s.result.diagnostics.empty()
                                       ? ""
                                       : s.result.diagnostics[0].message.toStdString());
    s.engine->scan();
    EXPECT_EQ(s.hex("DM 0000"), 0x0016u); // 16 levels ran
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 7);
}

// A step's outputs go OFF and its timers reset once the step is over (W353); its KEEP keeps.
TEST(Cpm1Steps, AnEndedStepResetsOutputsAndTimersKeepsKeep) {
    Cpm1Sim s("LD 000.00;SNXT(09) LR10.00;STEP(08) LR10.00;LD 253.13;TIM 001 #0002;LD 253.13;"
              "OUT 010.00;LD 253.13;LD 000.03;KEEP(11) 200.01;LD 000.01;SNXT(09) LR10.01;"
              "STEP(08);END(01)");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(100);
    s.pulses("000.00", 1);
    for (int k = 0; k < 3; ++k)
        s.engine->scan();
    EXPECT_TRUE(s.bit("010.00"));
    EXPECT_TRUE(s.bit("200.01"));
    EXPECT_TRUE(s.bit("TIM 001")); // 0.2 s in the step
    EXPECT_EQ(s.value("TIM 001"), 0);
    s.pulses("000.01", 1);
    EXPECT_FALSE(s.bit("LR10.00"));
    EXPECT_FALSE(s.bit("010.00"));
    EXPECT_FALSE(s.bit("TIM 001"));
    EXPECT_EQ(s.value("TIM 001"), 2); // reset to its set value (a down timer)
    EXPECT_TRUE(s.bit("200.01"));
}

// W353 FAL(06) N: a non-fatal error, its number N (01..99) in SR 253.00..253.07 as BCD, and
// the CPU goes on (Omron CPM1 guide 2.1, ERROR/ALARM: "Villog - Nem lényegi hiba, a CPU tovább
// dolgozik"); FAL 00 clears it. 253.13 (always ON) and the other flags of 253 keep theirs.
TEST(Cpm1Fal, ANonFatalErrorPutsItsNumberInto253AndTheProgramGoesOn) {
    Cpm1Sim s("LD 000.00;FAL(06) 12;LD 000.01;FAL(06) 00;LD 253.13;OUT 010.00;END(01)");
    ASSERT_TRUE(s.result.ok()) << s.errors();
    s.engine->scan();
    EXPECT_EQ(s.hex("253") & 0xFFu, 0u) << "no error yet";
    s.in("000.00", true);
    s.engine->scan();
    EXPECT_EQ(s.hex("253") & 0xFFu, 0x12u) << "FAL 12 as BCD digits";
    EXPECT_TRUE(s.bit("253.13")) << "the high byte's flags are not touched";
    EXPECT_TRUE(s.bit("010.00")) << "the program goes on after the FAL";
    EXPECT_TRUE(s.engine->runtimeErrors().empty()) << "a non-fatal error stops nothing";
    s.in("000.00", false);
    s.engine->scan();
    EXPECT_EQ(s.hex("253") & 0xFFu, 0x12u) << "the number stays after the condition goes OFF";
    s.in("000.01", true);
    s.engine->scan();
    EXPECT_EQ(s.hex("253") & 0xFFu, 0u) << "FAL 00 clears it";
    EXPECT_TRUE(s.bit("253.13"));
}

// `check` and the simulator refuse the same operands with the same words (issue 14).
TEST(Cpm1Operands, TheSimulatorRefusesWhatCheckReports) {
    for (const char *listing :
         {"LD 000.00;ADD(30) DM 0000 #12A4 DM 0001;END(01)",
          "LD 000.00;MOVB(82) 200 #0016 201;END(01)", "LD 000.00;MOVD(83) 200 #0400 201;END(01)",
          "LD 000.00;LD 000.01;LD 000.02;SFT(10) 201 200;END(01)",
          "LD 000.00;LD 000.01;LD 000.02;SFT(10) DM 0000 DM 0001;END(01)",
          "LD 000.00;MUL(32) #0002 #0003 DM 1023;END(01)", "LD 000.00;SBS(91) 50;END(01)",
          "LD 000.00;SBS(91) 03;END(01)", "SBN(92) 01;LD 253.13;OUT 010.00;END(01)",
          "LD 000.00;FAL(06) 100;END(01)"}) {
        Cpm1Sim s(listing);
        ASSERT_TRUE(s.parsed.ok()) << listing;
        EXPECT_FALSE(s.result.ok()) << listing;
        const auto checked = model::checkList(s.parsed.list);
        for (const model::Diagnostic &d : s.result.diagnostics) {
            const bool same = std::any_of(checked.begin(), checked.end(), [&](const auto &c) {
                return c.severity == model::Severity::Error && c.message == d.message &&
                       c.location.line == d.location.line;
            });
            EXPECT_TRUE(same) << listing << ": " << d.message.toStdString();
        }
    }
}

// A trace speaks the CPM1's words: --set "DM 0000=#0012@0" writes the word 0012h and a column
// hex:DM 0001 prints a word as its four digits.
TEST(Cpm1Trace, WordsAreSetAndPrintedAsTheirDigits) {
    Cpm1Sim s("LD 253.13;ADD(30) DM 0000 #0001 DM 0001;END(01)");
    ASSERT_TRUE(s.result.ok());
    TraceRequest request;
    QString error;
    ASSERT_TRUE(
        parseTraceOptions(s.target,
                          {QStringLiteral("--scans"), QStringLiteral("2"), QStringLiteral("--set"),
                           QStringLiteral("DM 0000=#0099@1"), QStringLiteral("--trace"),
                           QStringLiteral("DM 0000,hex:DM 0001")},
                          &request, &error))
        << error.toStdString();
    QString out;
    QTextStream stream(&out);
    runTrace(s.result.program, request, stream);
    stream.flush();
    EXPECT_EQ(out,
              QStringLiteral("scan,time_ms,DM 0000,hex:DM 0001\n1,10,0,#0001\n2,20,153,#0100\n"));
    EXPECT_FALSE(parseTraceOptions(s.target,
                                   {QStringLiteral("--scans"), QStringLiteral("1"),
                                    QStringLiteral("--set"), QStringLiteral("DM 0000=#12G4@1"),
                                    QStringLiteral("--trace"), QStringLiteral("DM 0000")},
                                   &request, &error));
}
