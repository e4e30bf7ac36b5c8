// Where and how `check` words an operand finding: a constant or a word that breaks a table rule
// is pointed at by its own column (PL110 SBIT V3 16: the 16), and a write to a read-only area
// reads as a sentence in every family.

#include "model/checks/checks.h"
#include "model/listing/il.h"

#include <gtest/gtest.h>

#include <optional>

using namespace rung::model;

namespace {

std::vector<Diagnostic> checked(Family family, const QString &text) {
    const ParseResult parsed = parseInstructionList(Target::get(family), text);
    EXPECT_TRUE(parsed.ok()) << parsed.errors.front().message.toStdString();
    CheckOptions options;
    options.source = &text;
    return checkList(parsed.list, options);
}

// A copy: the findings are a temporary of the caller's expression.
std::optional<Diagnostic> first(const std::vector<Diagnostic> &found, const char *code) {
    for (const Diagnostic &d : found)
        if (d.code == QLatin1String(code))
            return d;
    return std::nullopt;
}

} // namespace

TEST(CheckOperandPlaces, AConstantThatBreaksARuleIsPointedAtByItsColumn) {
    struct Case {
        Family family;
        const char *text;
        int line;
        int column;
    };
    const Case cases[] = {
        {Family::Pl110, "LD I1\nSBIT V3 16\nEND", 2, 9},
        {Family::Pl110, "LD I1\n  RBIT V0 -1 ; bit\nEND", 2, 11},
        {Family::Pl110, "LD SM0.0\nBLKMOV V0 V10 0\nEND", 2, 15},
        // The same written twice: the operand that breaks the rule, not the first alike.
        {Family::Pl110, "LD SM0.0\nBLKMOV 0 V10 0\nEND", 2, 14},
        {Family::Pl110, "LD SM0.0\nFM V0 % 2 V1\nEND", 2, 7},
        {Family::Vigor, "LD M9000\nBMOV D0 D10 K0\nEND", 2, 13},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.text);
        const std::optional<Diagnostic> d =
            first(checked(c.family, QString::fromLatin1(c.text)), "OP005");
        ASSERT_TRUE(d.has_value());
        EXPECT_EQ(d->location.line, c.line);
        EXPECT_EQ(d->location.column, c.column);
    }
}

TEST(CheckOperandPlaces, AWriteToAReadOnlyAreaReadsAsASentence) {
    // CPM1 DM 6144.. is "read-only data memory": the message once said "read-only data memory
    // are read-only".
    const std::optional<Diagnostic> d = first(
        checked(Family::Cpm1, QStringLiteral("LD 253.13\nMOV(21) #0001 DM 6144\nEND")), "OP002");
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->message,
              QStringLiteral("DM 6144 cannot be written: the program only reads it (read-only "
                             "data memory)"));
    const std::optional<Diagnostic> x =
        first(checked(Family::Vigor, QStringLiteral("LD M9000\nOUT X0\nEND")), "OP002");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(x->message,
              QStringLiteral("X0 cannot be written: the program only reads it (inputs)"));
}

// docs/cli.md: the program is checked whole. A rung whose blocks do not add up is BL001, and
// so is every later rung with the same mistake, not only the first.
TEST(CheckWholeProgram, EveryRungWithABlockErrorIsReported) {
    struct Case {
        Family family;
        const char *text;
        std::vector<int> lines;
    };
    const Case cases[] = {
        {Family::Vigor,
         "LD X0\nANB\nOUT Y0\nLD X1\nANB\nOUT Y1\nLD X2\nLD X3\nORB\nORB\nOUT Y2\nEND",
         {2, 5, 10}},
        {Family::Cpm1,
         "LD 000.00\nAND LD\nOUT 010.00\nLD 000.01\nAND LD\nOUT 010.01\nEND(01)",
         {2, 5}},
        {Family::Pl110, "LD I1\nANB\nOUT Q1\nLD I2\nORB\nOUT Q2\nEND", {2, 5}},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.text);
        std::vector<int> lines;
        for (const Diagnostic &d : checked(c.family, QString::fromLatin1(c.text)))
            if (d.code == QLatin1String("BL001"))
                lines.push_back(d.location.line);
        EXPECT_EQ(lines, c.lines);
    }
    // A correct rung after a broken one gives nothing.
    std::vector<int> lines;
    for (const Diagnostic &d : checked(Family::Vigor, QStringLiteral("LD X0\nANB\nOUT Y0\nLD X1\n"
                                                                     "LD X2\nORB\nOUT Y1\nEND")))
        if (d.severity == Severity::Error)
            lines.push_back(d.location.line);
    EXPECT_EQ(lines, std::vector<int>{2});
}
