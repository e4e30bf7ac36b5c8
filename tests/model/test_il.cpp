// The listing parser and printer on every target's listing: the manuals' listings verbatim,
// parse -> print -> parse identity, aliases, step numbers, and every error with its place.

#include "model/listing/il.h"
#include "tests/model/listing_test_util.h"

#include <QDir>
#include <QFile>
#include <QStringList>

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::describeErrors;
using rung::testing::kExecutionOrderExample;
using rung::testing::parseListing;

namespace {

// parse -> print -> parse gives the same instructions and comments, and printing is a
// fixpoint (the canonical form prints to itself).
void expectRoundTrip(Family family, const QString &text, const PrintOptions &options = {}) {
    const ParseResult first = parseListing(family, text);
    ASSERT_TRUE(first.ok()) << describeErrors(first) << text.toStdString();
    const QString printed = printInstructionList(first.list, options);
    const ParseResult second = parseListing(family, printed);
    ASSERT_TRUE(second.ok()) << describeErrors(second) << printed.toStdString();
    ASSERT_EQ(first.list.instructions.size(), second.list.instructions.size())
        << printed.toStdString();
    for (std::size_t i = 0; i < first.list.instructions.size(); ++i)
        EXPECT_TRUE(first.list.instructions[i].sameAs(second.list.instructions[i]))
            << "instruction " << i << " of\n"
            << printed.toStdString();
    EXPECT_EQ(first.list.comments, second.list.comments);
    EXPECT_EQ(printInstructionList(second.list, options), printed);
}

QStringList printedLines(Family family, const QString &text) {
    const ParseResult r = parseListing(family, text);
    EXPECT_TRUE(r.ok()) << describeErrors(r);
    return printInstructionList(r.list, {.stepNumbers = false, .comments = false})
        .split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

// ---- VPC (VPC user's manual) ---------------------------------------------------------------

// The listings of the VPC user's manual, VII, verbatim.
const char *const kVpcSeedListings[] = {
    "LD p01>p02\nAND NOT r02\nLD r03\nAND t04\nOR LD\nOUT p15+p17\n",
    "LD p01>p02\nAND NOT r02\nOUT t00+p00\n",
    "LD i03\nAND r04\nOUT t01-c05\n",
    "LD r88\nOUT p00+p01\n",
    "LD r95\nIL\nOUT NOT r04\nLD r04\nOUT p02+p01\nILC\n",
};

TEST(IlVpc, SeedListingsParseWithoutErrorsAndRoundTrip) {
    for (const char *listing : kVpcSeedListings)
        expectRoundTrip(Family::Vpc, QString::fromLatin1(listing));
}

TEST(IlVpc, ConsoleLineWithStepNumberParses) {
    // VPC user's manual, V.a "RUN & MONITOR mode": "0002 LD  p01<p00".
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("0002 LD  p01<p00"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 1u);
    const Instruction &ins = r.list.instructions[0];
    EXPECT_EQ(ins.op(), Op::Load);
    EXPECT_EQ(ins.spec->compare, CompareOp::Lt);
    ASSERT_EQ(ins.operands.size(), 2u);
    EXPECT_EQ(formatAddress(Target::get(Family::Vpc), ins.operands[0].address), "p01");
    EXPECT_EQ(formatAddress(Target::get(Family::Vpc), ins.operands[1].address), "p00");
    EXPECT_EQ(ins.column, 6);
}

TEST(IlVpc, SeedTransfersReadAsTransferWithDestinationFirst) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("OUT p21,p12\nOUT p15+p17\n"
                                                                   "OUT p15-p17\nOUT* p21,p12"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 4u);
    const TransferOp expected[] = {TransferOp::Assign, TransferOp::Add, TransferOp::Subtract,
                                   TransferOp::Assign};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(r.list.instructions[i].op(), Op::Transfer);
        EXPECT_EQ(r.list.instructions[i].spec->transfer, expected[i]);
    }
    EXPECT_FALSE(r.list.instructions[0].spec->negated);
    EXPECT_TRUE(r.list.instructions[3].spec->negated);
    EXPECT_EQ(formatAddress(Target::get(Family::Vpc), r.list.instructions[0].operands[0].address),
              "p21");
}

TEST(IlVpc, StarIsShortForNotAndPrintsCanonically) {
    EXPECT_EQ(printedLines(Family::Vpc, QStringLiteral("LD* p01<p00\nAND* i01\nOUT* o02\n"
                                                       "OUT* p21,p12")),
              (QStringList{"LD NOT p01<p00", "AND NOT i01", "OUT NOT o02", "OUT NOT p21,p12"}));
    const ParseResult a = parseListing(Family::Vpc, QStringLiteral("LD* p01<p00"));
    const ParseResult b = parseListing(Family::Vpc, QStringLiteral("ld not p01<p00"));
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_TRUE(a.list.instructions[0].sameAs(b.list.instructions[0]));
}

TEST(IlVpc, FusedTimerAndCounterNumbers) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("LD i00\nTIM00\nLD i01\nLD i02\n"
                                                                   "CNT05\nLD i03\nTIM31"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 7u);
    EXPECT_EQ(r.list.instructions[1].op(), Op::Timer);
    EXPECT_EQ(r.list.instructions[4].op(), Op::Counter);
    const Target &vpc = Target::get(Family::Vpc);
    EXPECT_EQ(formatAddress(vpc, r.list.instructions[1].operands.at(0).address), "t00");
    EXPECT_EQ(formatAddress(vpc, r.list.instructions[4].operands.at(0).address), "c05");
    EXPECT_EQ(printInstruction(vpc, r.list.instructions[4]), "CNT05");
    EXPECT_EQ(printInstruction(vpc, r.list.instructions[6]), "TIM31");
}

TEST(IlVpc, EveryInstructionOfTheFamilyRoundTrips) {
    expectRoundTrip(Family::Vpc, QStringLiteral("LD i00\nLD NOT i01\nAND r02\nAND NOT r03\n"
                                                "OR o04\nOR NOT t05\nAND LD\nOR LD\n"
                                                "LD p01=p02\nAND p01>a00\nOR NOT p03<p04\n"
                                                "OUT o00\nOUT NOT r05\nLR r10\nTIM06\nCNT07\n"
                                                "IL\nILC\nJMP\nJPE\nOUT d00,p00\n"
                                                "OUT t00,a00\nEND\n"));
}

TEST(IlVpc, StepNumbersPrintedAsTheConsoleShowsThemAndReadBack) {
    const ParseResult r = parseListing(Family::Vpc, QString::fromLatin1(kVpcSeedListings[0]));
    ASSERT_TRUE(r.ok());
    const QString printed = printInstructionList(r.list, {.stepNumbers = true});
    EXPECT_TRUE(printed.startsWith(QStringLiteral("0000 LD p01>p02\n0001 AND NOT r02\n")))
        << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("0005 OUT p15+p17\n"))) << printed.toStdString();
    expectRoundTrip(Family::Vpc, printed, {.stepNumbers = true});
}

TEST(IlVpc, CompareTheTableDoesNotHaveIsAnErrorAtTheSymbol) {
    // VPC compares with = < > only (VPC user's manual).
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("LD p01<=p00"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].line, 1);
    EXPECT_EQ(r.errors[0].column, 7);
}

TEST(IlVpc, TransferWithoutSourceIsAnError) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("LD i00\nOUT p21,"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 9);
}

// ---- CPM1 (Omron CPM1 guide) ----------------------------------------------------------------

const char *const kCpm1SeedListings[] = {
    "LD 000.00\nOUT 010.00\n",
    "LD 000.00\nAND 000.01\nOUT 010.00\n",
    "LD 000.00\nOR 000.01\nAND 000.02\nOUT 010.00\n",
    "LD 000.00\nOR 000.01\nAND NOT 000.02\nOUT NOT 010.00\n",
    "LD      000.00\nOR      000.01\nLD      000.02\nOR NOT  000.03\nAND LD\nOUT     010.00\n",
    "LD      000.00\nOR      000.01\nLD      000.02\nAND NOT 000.03\nOR LD\nOUT     010.00\n",
};

TEST(IlCpm1, SeedListingsParseWithoutErrorsAndRoundTrip) {
    for (const char *listing : kCpm1SeedListings)
        expectRoundTrip(Family::Cpm1, QString::fromLatin1(listing));
}

TEST(IlCpm1, SeedJumpListingReportsOnlyTheLmeTypoWithJmeSuggested) {
    // The Omron CPM1 guide prints "LME 0" for "JME 0"; the listing is otherwise valid.
    const ParseResult r =
        parseListing(Family::Cpm1, QStringLiteral("LD      000.02\nAND     000.03\n"
                                                  "JMP     0\nLD      000.04\n"
                                                  "OUT     010.00\nLD      000.05\n"
                                                  "OUT     010.01\nLME     0\n"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 8);
    EXPECT_EQ(r.errors[0].column, 1);
    EXPECT_TRUE(r.errors[0].message.contains(QStringLiteral("JME"))) << describeErrors(r);
    EXPECT_EQ(r.list.instructions.size(), 7u);
    expectRoundTrip(Family::Cpm1,
                    QStringLiteral("LD 000.02\nAND 000.03\nJMP 0\nLD 000.04\nOUT 010.00\n"
                                   "LD 000.05\nOUT 010.01\nJME 0\n"));
}

TEST(IlCpm1, FunctionCodeIsOptionalAndMustMatch) {
    const ParseResult a =
        parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nLD 000.01\nKEEP(11) 200.00\n"
                                                  "END(01)"));
    const ParseResult b =
        parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nLD 000.01\nkeep 200.00\n"
                                                  "end"));
    ASSERT_TRUE(a.ok()) << describeErrors(a);
    ASSERT_TRUE(b.ok()) << describeErrors(b);
    ASSERT_EQ(a.list.instructions.size(), b.list.instructions.size());
    for (std::size_t i = 0; i < a.list.instructions.size(); ++i)
        EXPECT_TRUE(a.list.instructions[i].sameAs(b.list.instructions[i]));
    EXPECT_EQ(a.list.instructions[2].op(), Op::Keep);
    EXPECT_EQ(a.list.instructions[3].op(), Op::End);

    const ParseResult wrong =
        parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nKEEP(12) 200.00"));
    ASSERT_EQ(wrong.errors.size(), 1u);
    EXPECT_EQ(wrong.errors[0].line, 2);
    EXPECT_EQ(wrong.errors[0].column, 1);
}

TEST(IlCpm1, TimersCountersAndTheirContacts) {
    const ParseResult r =
        parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nTIM 000 #0150\n"
                                                  "LD TIM 000\nOUT 010.00\n"
                                                  "LD 000.01\nLD 000.02\nCNT 001 #0005\n"
                                                  "LD 000.03\nTIMH(15) 002 HR01\n"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 9u);
    const Instruction &tim = r.list.instructions[1];
    EXPECT_EQ(tim.op(), Op::Timer);
    ASSERT_EQ(tim.operands.size(), 2u);
    EXPECT_EQ(tim.operands[1].kind, Operand::Kind::Constant);
    EXPECT_EQ(tim.operands[1].constant.value, 150);
    const Instruction &contact = r.list.instructions[2];
    ASSERT_EQ(contact.operands.size(), 1u);
    EXPECT_EQ(contact.operands[0].address, tim.operands[0].address);
    EXPECT_EQ(r.list.instructions[6].op(), Op::Counter);
    EXPECT_EQ(r.list.instructions[8].operands.at(1).kind, Operand::Kind::Device);
}

TEST(IlCpm1, EveryInstructionOfTheFamilyRoundTrips) {
    expectRoundTrip(Family::Cpm1,
                    QStringLiteral("LD 000.00\nOUT 010.00\nLD NOT 000.01\nOUT NOT 010.01\n"
                                   "LD 253.13\nSET 200.00\nLD 000.02\nRESET 200.00\n"
                                   "LD 000.03\nDIFU(13) 200.01\nLD 000.03\nDIFD(14) 200.02\n"
                                   "LD 000.04\nLD 000.05\nKEEP(11) HR00.01\n"
                                   "LD 000.06\nTIM 003 #1553\nLD 000.07\nTIMH(15) 004 #0150\n"
                                   "LD 000.08\nLD 000.09\nCNT 005 #0010\n"
                                   "LD 000.10\nLD 000.11\nLD 000.12\nCNTR(12) 006 #0020\n"
                                   "LD TIM 003\nAND CNT 005\nOUT 010.02\n"
                                   "LD 253.13\nJMP(04) 01\nJME(05) 01\nNOP(00)\n"
                                   "LD 253.13\nMOV(21) #0012 DM0000\nEND(01)\n"));
}

TEST(IlCpm1, ConstantWithANonDigitIsAnErrorAtTheCharacter) {
    const ParseResult r = parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nTIM 000 #01X0"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 12);
}

// ---- Vigor (Vigor M/VB/VH communication manual, PLC concepts (WPLSoft family)) ----------------

TEST(IlVigor, ExecutionOrderProgramParsesAndRoundTrips) {
    const ParseResult r = parseListing(Family::Vigor, QString::fromLatin1(kExecutionOrderExample));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 14u);
    EXPECT_EQ(r.list.instructions[5].op(), Op::OrBlock);
    EXPECT_EQ(r.list.instructions[11].op(), Op::AndBlock);
    const Instruction &tmr = r.list.instructions[13];
    EXPECT_EQ(tmr.op(), Op::Timer);
    EXPECT_EQ(tmr.operands.at(1).constant.value, 10);
    expectRoundTrip(Family::Vigor, QString::fromLatin1(kExecutionOrderExample));
}

TEST(IlVigor, SeedTabulatedListingWithStepNumbersParses) {
    // PLC concepts (WPLSoft family) 1.5.1, as printed (tabs, step numbers on some lines only).
    const ParseResult r = parseListing(
        Family::Vigor,
        QStringLiteral("1\tLD\tX0\t\n2\tOR\tM0\t\n3\tAND\tX1\t\n4\tLD\tX3\t\n\tAND\tM1\t\n"
                       "\tORB\t\t\n5\tLD\tY1\t\n\tAND\tX4\t\n6\tLD\tT0\t\n\tAND\tM3\t\n"
                       "\tORB\t\t\n7\tANB\t\t\n8\tOUT\tY1\t\n\tTMR\tT0 K10\t\n"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    const ParseResult clean =
        parseListing(Family::Vigor, QString::fromLatin1(kExecutionOrderExample));
    ASSERT_EQ(r.list.instructions.size(), clean.list.instructions.size());
    for (std::size_t i = 0; i < clean.list.instructions.size(); ++i)
        EXPECT_TRUE(r.list.instructions[i].sameAs(clean.list.instructions[i]));
}

TEST(IlVigor, FuzzySyntaxPairsParse) {
    // PLC concepts (WPLSoft family) 1.7: Better vs OK, Good vs Bad.
    for (const char *listing :
         {"LD X0\nOR X1\nLD X2\nOR X3\nANB\nLD X4\nOR X5\nANB\n",
          "LD X0\nOR X1\nLD X2\nOR X3\nLD X4\nOR X5\nANB\nANB\n", "LD X0\nOR X1\nOR X2\nOR X3\n",
          "LD X0\nLD X1\nLD X2\nLD X3\nORB\nORB\nORB\n"})
        expectRoundTrip(Family::Vigor, QString::fromLatin1(listing));
}

TEST(IlVigor, EveryInstructionOfTheFamilyRoundTrips) {
    expectRoundTrip(
        Family::Vigor,
        QStringLiteral("LD X0\nLDI X1\nANI X2\nORI X3\nLDP X4\nANDP X5\nORF X6\nANB\nLDF X7\n"
                       "ANDF X10\nORP M0\nORB\nMPS\nAND X11\nOUT Y0\nMRD\nINV\nOUT Y1\nMPP\n"
                       "SET M1\nLD M9000\nRST M1\nPLS M2\nPLF M3\nTMR T0 K10\nCNT C0 K3\n"
                       "CNT C200 K100000\nMOV K10 D0\nMOV H1F D1\nCMP D0 K5 M10\n"
                       "ZRST M0 M5\nADD D0 D1 D2\nSUB D0 K1 D3\nMUL D0 D1 D4\nDIV D4 K2 D6\n"
                       "INC D7\nDEC D8\nRST C0\nSTL S20\nOUT Y2\nRET\nEND\n"));
}

TEST(IlVigor, ConstantsDecimalAndHexadecimal) {
    const ParseResult r =
        parseListing(Family::Vigor, QStringLiteral("LD M9000\nMOV K10 D0\nMOV H1F D1"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    EXPECT_EQ(r.list.instructions[1].operands.at(0).constant.value, 10);
    EXPECT_EQ(r.list.instructions[2].operands.at(0).constant.value, 31);
    const Target &vigor = Target::get(Family::Vigor);
    EXPECT_EQ(printInstruction(vigor, r.list.instructions[2]), "MOV H1F D1");
}

TEST(IlVigor, OperandsMayBeSeparatedByCommas) {
    const ParseResult a = parseListing(Family::Vigor, QStringLiteral("MOV K10,D0"));
    const ParseResult b = parseListing(Family::Vigor, QStringLiteral("MOV K10 D0"));
    ASSERT_TRUE(a.ok()) << describeErrors(a);
    EXPECT_TRUE(a.list.instructions.at(0).sameAs(b.list.instructions.at(0)));
}

TEST(IlVigor, StepSizesFollowTheTable) {
    const Target &vigor = Target::get(Family::Vigor);
    const ParseResult r =
        parseListing(Family::Vigor, QStringLiteral("LD X0\nTMR T0 K10\nCNT C0 K3\n"
                                                   "CNT C200 K10\nMOV K10 D0\nEND"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    const auto &ins = r.list.instructions;
    EXPECT_EQ(instructionSteps(vigor, ins[0]), 1);
    EXPECT_EQ(instructionSteps(vigor, ins[1]), 3);
    EXPECT_EQ(instructionSteps(vigor, ins[2]), 3);
    EXPECT_EQ(instructionSteps(vigor, ins[3]), 5); // 32-bit counter
    EXPECT_EQ(instructionSteps(vigor, ins[4]), ins[4].spec->steps);
    EXPECT_GT(ins[4].spec->steps, 1);
    // The parser numbers steps the same way.
    int step = 0;
    for (const Instruction &i : ins) {
        EXPECT_EQ(i.step, step);
        step += instructionSteps(vigor, i);
    }
    const QString printed = printInstructionList(r.list, {.stepNumbers = true});
    EXPECT_TRUE(printed.contains(QStringLiteral("0001 TMR T0 K10\n0004 CNT C0 K3\n0007 CNT C200")))
        << printed.toStdString();
}

TEST(IlVpc, EveryInstructionIsOneLine) {
    const Target &vpc = Target::get(Family::Vpc);
    const ParseResult r =
        parseListing(Family::Vpc, QStringLiteral("LD i00\nTIM00\nOUT p00+p01\nEND"));
    ASSERT_TRUE(r.ok());
    for (const Instruction &i : r.list.instructions)
        EXPECT_EQ(instructionSteps(vpc, i), 1);
    EXPECT_EQ(r.list.instructions[3].step, 3);
}

TEST(IlVigor, OctalInputOutOfRangeIsReportedAtItsColumn) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\nAND  X8\nOUT Y0"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_GE(r.errors[0].column, 6);
    EXPECT_LE(r.errors[0].column, 7);
    EXPECT_EQ(r.list.instructions.size(), 2u); // the parse went on
}

// ---- PL110 (the product's listing, docs/targets.md) ----------------------------------------

TEST(IlPl110, ListingOfEveryElementKindRoundTrips) {
    expectRoundTrip(Family::Pl110, QStringLiteral("LD I1\nANDN T1\nTON T1 300\nOUT Q1\n"
                                                  "LDN I2\nOR M1\nAND V3.5\nOUTB B1\n"
                                                  "LD= V1 V2\nP\nSBIT V3 5\n"
                                                  "LD I3\nLD I4\nLD I5\nMUP C1 10\n"
                                                  "LD SM0.0\nFM V1 + V2 V3\nMOV V4 V5\nEND\n"));
}

TEST(IlPl110, WordSpellingsOfTheManualAreAccepted) {
    const ParseResult a = parseListing(Family::Pl110, QStringLiteral("LD SM0.0\nMOV VW30 V31"));
    const ParseResult b = parseListing(Family::Pl110, QStringLiteral("LD SM0.0\nMOV V30 V31"));
    ASSERT_TRUE(a.ok()) << describeErrors(a);
    ASSERT_TRUE(b.ok()) << describeErrors(b);
    EXPECT_TRUE(a.list.instructions[1].sameAs(b.list.instructions[1]));
}

// ---- Listing text: comments, blanks, case, tabs -------------------------------------------

TEST(IlText, CommentsBlankLinesCaseAndTabs) {
    const ParseResult r = parseListing(
        Family::Vigor, QStringLiteral("; start / stop latch\n\n  ld\tX0   // start\n"
                                      "\tOr Y0\r\nani X1\n;  coil\nOUT\tY0\n\n; the end\n"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 4u);
    EXPECT_EQ(r.list.instructions[0].line, 3);
    EXPECT_EQ(r.list.instructions[0].column, 3);
    EXPECT_EQ(r.list.instructions[1].line, 4);
    EXPECT_EQ(r.list.instructions[1].column, 2);
    ASSERT_EQ(r.list.comments.size(), 3u);
    EXPECT_EQ(r.list.comments[0], std::make_pair(0, QStringLiteral("start / stop latch")));
    EXPECT_EQ(r.list.comments[1], std::make_pair(3, QStringLiteral("coil")));
    EXPECT_EQ(r.list.comments[2], std::make_pair(4, QStringLiteral("the end")));
    EXPECT_EQ(r.list.instructions[0].comment, "start");
}

TEST(IlText, PrintKeepsLineAndTrailingComments) {
    const QString text = QStringLiteral("; latch\nLD X0 ; start button\nOR Y0\nANI X1\n"
                                        "OUT Y0\n; end of program\n");
    const ParseResult r = parseListing(Family::Vigor, text);
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    EXPECT_EQ(printInstructionList(r.list), text);
    expectRoundTrip(Family::Vigor, text);
    EXPECT_EQ(printInstructionList(r.list, {.comments = false}),
              QStringLiteral("LD X0\nOR Y0\nANI X1\nOUT Y0\n"));
}

TEST(IlText, StepNumberWithColonIsAccepted) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("0000: LD i00\n0001: OUT o00"));
    ASSERT_TRUE(r.ok()) << describeErrors(r);
    ASSERT_EQ(r.list.instructions.size(), 2u);
    EXPECT_EQ(r.list.instructions[1].column, 7);
}

TEST(IlText, EmptyAndCommentOnlyInputs) {
    EXPECT_TRUE(parseListing(Family::Vigor, QString()).list.instructions.empty());
    EXPECT_TRUE(parseListing(Family::Vigor, QString()).ok());
    const ParseResult r = parseListing(Family::Cpm1, QStringLiteral("\n\n; only a note\n\t\n"));
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r.list.instructions.empty());
    EXPECT_EQ(printInstructionList(r.list), QStringLiteral("; only a note\n"));
}

// ---- Every listing in the test data --------------------------------------------------------

TEST(IlData, EveryListingInTheTestDataRoundTrips) {
    int checked = 0;
    for (const char *sub : {"il", "sim"}) {
        QDir dir(QStringLiteral(RUNG_TEST_DATA_DIR "/") + QLatin1String(sub));
        for (const QString &name : dir.entryList({QStringLiteral("*.il")}, QDir::Files)) {
            QFile file(dir.filePath(name));
            ASSERT_TRUE(file.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(file.readAll());
            const Target *target = Target::byId(name.section(QLatin1Char('_'), 0, 0));
            ASSERT_NE(target, nullptr) << name.toStdString();
            SCOPED_TRACE(name.toStdString());
            expectRoundTrip(target->family, text);
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
}

} // namespace

namespace {

TEST(IlCpm1, PrintsTheCanonicalSpellingWithFunctionCodes) {
    EXPECT_EQ(printedLines(Family::Cpm1, QStringLiteral("ld 000.00\nld not 000.01\nkeep hr00.01\n"
                                                        "ld tim 000\njmp 0\njme 0\nend")),
              (QStringList{"LD 000.00", "LD NOT 000.01", "KEEP(11) HR00.01", "LD TIM 000",
                           "JMP(04) 00", "JME(05) 00", "END(01)"}));
}

TEST(IlVigor, PrintsTheCanonicalSpelling) {
    EXPECT_EQ(printedLines(Family::Vigor, QStringLiteral("ld x10\ntmr t0 k10\nmov h1f,d0")),
              (QStringList{"LD X10", "TMR T0 K10", "MOV H1F D0"}));
}

} // namespace

// Which PLC a listing is for when it does not say: the one that reads it, the caller's
// choice first; what nobody reads stays with the caller's choice.
TEST(ListingTarget, TheDeclarationElseTheSyntaxElseTheFallback) {
    EXPECT_EQ(listingTarget(QStringLiteral("; target: pl110\nLD X0\n"), QStringLiteral("vigor")),
              QStringLiteral("pl110"));
    EXPECT_EQ(
        listingTarget(QStringLiteral("LD 000.00\nOUT 010.00\nEND(01)\n"), QStringLiteral("vigor")),
        QStringLiteral("cpm1"));
    EXPECT_EQ(listingTarget(QStringLiteral("0000 LD i00\n0001 OUT o01\n0002 END\n"),
                            QStringLiteral("vigor")),
              QStringLiteral("vpc"));
    EXPECT_EQ(
        listingTarget(QStringLiteral("LDI X1\nOUT Y0\nTMR T0 K10\nEND\n"), QStringLiteral("cpm1")),
        QStringLiteral("vigor"));
    EXPECT_EQ(listingTarget(QStringLiteral("LD X0\nOUT Y0\nEND\n"), QStringLiteral("vigor")),
              QStringLiteral("vigor"));
    EXPECT_EQ(listingTarget(QStringLiteral("FROB 12\n"), QStringLiteral("vpc")),
              QStringLiteral("vpc"));
}

// The first line's target declaration is the file's header, read by declaredTarget(): opened
// in the IDE it must not turn into the comment of the program's first rung. A comment that
// follows it, or the same words further down, stay comments.
TEST(ListingTarget, TheDeclarationIsNoCommentOfTheProgram) {
    const Target &vigor = Target::get(Family::Vigor);
    const ParseResult parsed = parseInstructionList(
        vigor, QStringLiteral("; target: vigor\n; Start\nLD X0\nOUT Y0\n; target: none\nEND\n"));
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed.list.comments.size(), 2u);
    EXPECT_EQ(parsed.list.comments[0], std::make_pair(0, QStringLiteral("Start")));
    EXPECT_EQ(parsed.list.comments[1], std::make_pair(2, QStringLiteral("target: none")));
    EXPECT_TRUE(parseInstructionList(vigor, QStringLiteral("// target: vigor\nLD X0\nEND\n"))
                    .list.comments.empty());
}
