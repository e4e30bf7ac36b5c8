// Listing parser errors (each with its line and column) and robustness against bad input.

#include "model/listing/il.h"
#include "tests/model/listing_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace rung::model;
using rung::testing::describeErrors;
using rung::testing::parseListing;

namespace {

// ---- Errors -------------------------------------------------------------------------------

TEST(IlErrors, UnknownMnemonicSuggestsTheClosest) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\n  ANDD X1\nOUT Y0"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 3);
    EXPECT_TRUE(r.errors[0].message.contains(QStringLiteral("ANDD")));
    EXPECT_TRUE(r.errors[0].message.contains(QStringLiteral("AND"))) << describeErrors(r);
    EXPECT_EQ(r.list.instructions.size(), 2u);
}

TEST(IlErrors, UnknownMnemonicFarFromAllGivesNoSuggestion) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("QWERTYUIOP i00"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_FALSE(r.errors[0].message.contains(QStringLiteral("did you mean")));
}

TEST(IlErrors, MissingOperand) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\nTMR T0"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 5);
    const ParseResult none = parseListing(Family::Vigor, QStringLiteral("LD"));
    ASSERT_EQ(none.errors.size(), 1u);
    EXPECT_EQ(none.errors[0].column, 4); // just after the mnemonic
}

TEST(IlErrors, ExtraOperandIsReportedAtTheExtraOperand) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0 X1\nANB   X2"));
    ASSERT_EQ(r.errors.size(), 2u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 1);
    EXPECT_EQ(r.errors[0].column, 7);
    EXPECT_EQ(r.errors[1].line, 2);
    EXPECT_EQ(r.errors[1].column, 7);
}

TEST(IlErrors, ConstantWhereADeviceIsNeeded) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\nOUT K10\nMOV K1 K2"));
    ASSERT_EQ(r.errors.size(), 2u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 5);
    EXPECT_EQ(r.errors[1].line, 3);
    EXPECT_EQ(r.errors[1].column, 8);
    const ParseResult cpm = parseListing(Family::Cpm1, QStringLiteral("LD #0001"));
    ASSERT_EQ(cpm.errors.size(), 1u) << describeErrors(cpm);
    EXPECT_EQ(cpm.errors[0].column, 4);
    // The message says what is wrong, not that K10 is no device of Vigor.
    for (const ParseError &e : {r.errors[0], r.errors[1], cpm.errors[0]})
        EXPECT_TRUE(e.message.contains(QStringLiteral("is a constant; a device is expected")))
            << e.message.toStdString();
    // Where a constant belongs it is one: a set value, a source.
    EXPECT_TRUE(parseListing(Family::Vigor, QStringLiteral("LD X0\nTMR T0 K10\nMOV K5 D0")).ok());
}

TEST(IlErrors, TimerWhereACounterIsNeeded) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\nCNT T0 K3"));
    ASSERT_EQ(r.errors.size(), 1u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].column, 5);
}

TEST(IlErrors, AddressOutOfRangeCarriesTheAddressColumn) {
    const ParseResult r = parseListing(Family::Vpc, QStringLiteral("LD i00\nOUT o99\nLD p01<p99"));
    ASSERT_EQ(r.errors.size(), 2u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_GE(r.errors[0].column, 5);
    EXPECT_LE(r.errors[0].column, 7);
    EXPECT_EQ(r.errors[1].line, 3);
    EXPECT_GE(r.errors[1].column, 8); // inside the right-hand operand
    EXPECT_LE(r.errors[1].column, 10);
}

TEST(IlErrors, ConstantOutOfRange) {
    const ParseResult r =
        parseListing(Family::Vigor, QStringLiteral("LD X0\nTMR T0 K99999999999\n"
                                                   "MOV K40000 D0\nMOV H10000 D0\n"
                                                   "MOV K-32768 D0\nMOV HFFFF D0"));
    ASSERT_EQ(r.errors.size(), 3u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_GE(r.errors[0].column, 8);
    EXPECT_EQ(r.errors[1].line, 3);
    EXPECT_EQ(r.errors[1].column, 5);
    EXPECT_TRUE(r.errors[1].message.contains(QStringLiteral("K32767"))) << describeErrors(r);
    EXPECT_EQ(r.errors[2].line, 4);
    // 32-bit counters take 32-bit set values; 16-bit words do not.
    EXPECT_TRUE(parseListing(Family::Vigor, QStringLiteral("LD X0\nCNT C200 K100000")).ok());
    const ParseResult cpm =
        parseListing(Family::Cpm1, QStringLiteral("LD 253.13\nMOV(21) #12345 DM0000"));
    ASSERT_EQ(cpm.errors.size(), 1u) << describeErrors(cpm);
    EXPECT_EQ(cpm.errors[0].column, 9);
    const ParseResult vpc = parseListing(Family::Vpc, QStringLiteral("LD p00<10000"));
    ASSERT_EQ(vpc.errors.size(), 1u) << describeErrors(vpc);
    EXPECT_EQ(vpc.errors[0].column, 8);
}

TEST(IlErrors, SetValueRangeIsLeftToTheChecksButCpm1NeedsBcd) {
    // OP004 (checks) reports set values out of range; the parser keeps the instruction.
    EXPECT_TRUE(parseListing(Family::Vigor, QStringLiteral("LD X0\nTMR T0 K40000")).ok());
    EXPECT_TRUE(parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nJMP(04) 50")).ok()); // NE006
    const ParseResult hex = parseListing(Family::Cpm1, QStringLiteral("LD 000.00\nTIM 000 #01A0"));
    ASSERT_EQ(hex.errors.size(), 1u);
    EXPECT_EQ(hex.errors[0].column, 9);
}

TEST(IlErrors, EveryBadLineIsReportedAndGoodLinesAreKept) {
    const ParseResult r = parseListing(Family::Vigor, QStringLiteral("LD X0\nFOO\nAND X9\nOUT Y0\n"
                                                                     "TMR\nEND"));
    ASSERT_EQ(r.errors.size(), 3u) << describeErrors(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[1].line, 3);
    EXPECT_EQ(r.errors[2].line, 5);
    EXPECT_EQ(r.list.instructions.size(), 3u);
}

TEST(IlErrors, MessagesAreNotEmptyAndPositionsAreOneBased) {
    const ParseResult r =
        parseListing(Family::Cpm1, QStringLiteral("XX\nLD\nLD 999.99\nMOV(21) #99999 DM0000"));
    ASSERT_EQ(r.errors.size(), 4u) << describeErrors(r);
    for (const ParseError &e : r.errors) {
        EXPECT_GE(e.line, 1);
        EXPECT_GE(e.column, 1);
        EXPECT_FALSE(e.message.isEmpty());
    }
}

// ---- Robustness ----------------------------------------------------------------------------

TEST(IlRobustness, ErrorsAreCappedWithAFinalTooManyErrors) {
    QString text;
    for (int i = 0; i < 5000; ++i)
        text += QStringLiteral("FOO\n");
    const ParseResult r = parseListing(Family::Vigor, text);
    ASSERT_EQ(r.errors.size(), 1001u);
    EXPECT_EQ(r.errors.back().line, 1001);
    EXPECT_TRUE(r.errors.back().message.contains(QStringLiteral("Too many errors")));
}

TEST(IlRobustness, RandomBytesNeverCrash) {
    std::mt19937 rng(12345);
    for (int round = 0; round < 200; ++round) {
        QByteArray bytes;
        const int size = static_cast<int>(rng() % 400);
        for (int i = 0; i < size; ++i)
            bytes.append(static_cast<char>(rng() % 256));
        for (Family f : Target::families()) {
            const ParseResult r = parseListing(f, QString::fromLatin1(bytes));
            for (const ParseError &e : r.errors) {
                EXPECT_GE(e.line, 1);
                EXPECT_GE(e.column, 1);
            }
            // Whatever parsed prints and parses again.
            const ParseResult again = parseListing(f, printInstructionList(r.list));
            EXPECT_TRUE(again.ok()) << describeErrors(again);
        }
    }
}

TEST(IlRobustness, VeryLongLinesAndTokens) {
    const QString longToken = QString(200000, QLatin1Char('X'));
    const ParseResult a = parseListing(Family::Vigor, QStringLiteral("LD ") + longToken);
    ASSERT_EQ(a.errors.size(), 1u);
    EXPECT_LT(a.errors[0].message.size(), 300);
    QString manyOperands = QStringLiteral("LD");
    for (int i = 0; i < 100000; ++i)
        manyOperands += QStringLiteral(" X0");
    const ParseResult b = parseListing(Family::Vigor, manyOperands);
    ASSERT_EQ(b.errors.size(), 1u);
    EXPECT_EQ(b.errors[0].column, 7);
    QString commas = QStringLiteral("MOV ");
    for (int i = 0; i < 100000; ++i)
        commas += QStringLiteral("K1,");
    EXPECT_FALSE(parseListing(Family::Vigor, commas).ok());
    EXPECT_FALSE(
        parseListing(Family::Vigor, QString(300000, QLatin1Char(';')) + QStringLiteral("\nLD"))
            .ok());
}

} // namespace
