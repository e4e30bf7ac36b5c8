#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "random_program.h"

#include <gtest/gtest.h>

#include <map>

#include <algorithm>

using namespace rung::model;

namespace {

struct Case {
    const char *code;
    Family family;
    const char *model; // nullptr: the default model
    const char *triggers;
    const char *clean;
};

QString text(const char *semicolonSeparated) {
    return QString::fromLatin1(semicolonSeparated).replace(QLatin1Char(';'), QLatin1Char('\n'));
}

std::vector<Diagnostic> check(Family family, const char *model, const QString &listing) {
    const Target &t = Target::get(family);
    const ModelVariant *variant = model ? t.model(QString::fromLatin1(model)) : nullptr;
    ParseResult parsed = parseInstructionList(t, listing);
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? ""
                                                       : parsed.errors[0].message.toStdString());
    CheckOptions o;
    o.model = variant;
    return checkList(parsed.list, o);
}

const Diagnostic *find(const std::vector<Diagnostic> &ds, const char *code) {
    for (const Diagnostic &d : ds)
        if (d.code == QLatin1String(code))
            return &d;
    return nullptr;
}

QString all(const std::vector<Diagnostic> &ds) {
    QString s;
    for (const Diagnostic &d : ds)
        s += QStringLiteral("%1 %2:%3 %4\n")
                 .arg(d.code)
                 .arg(d.location.line)
                 .arg(d.location.column)
                 .arg(d.message);
    return s;
}

QString repeat(const char *lines, int times) {
    QString s;
    for (int i = 0; i < times; ++i)
        s += text(lines) + QLatin1Char('\n');
    return s;
}

const Case kCases[] = {
    // Fuzzy syntax (PLC concepts (WPLSoft family) 1.7 and 1.8).
    {"FZ001", Family::Vigor, nullptr, "LD X0;OR X1;LD X2;OR X3;LD X4;OR X5;ANB;ANB;OUT Y0;END",
     "LD X0;OR X1;LD X2;OR X3;ANB;LD X4;OR X5;ANB;OUT Y0;END"},
    {"FZ002", Family::Vigor, nullptr, "LD X0;LD X1;LD X2;LD X3;ORB;ORB;ORB;OUT Y0;END",
     "LD X0;OR X1;OR X2;OR X3;OUT Y0;END"},
    {"FZ003", Family::Vigor, nullptr,
     "LD X0;LD X1;LD X2;LD X3;LD X4;LD X5;LD X6;LD X7;LD X10;LD "
     "X11;ANB;ANB;ANB;ANB;ANB;ANB;ANB;ANB;ANB;OUT Y0;END",
     "LD X0;LD X1;LD X2;LD X3;LD X4;LD X5;LD X6;LD X7;LD X10;ANB;ANB;ANB;ANB;ANB;ANB;ANB;ANB;OUT "
     "Y0;END"},
    // FZ004-FZ006 only where the text is not the canonical one (the canonical listing of a
    // ladder never gets a fuzzy-form warning); the clean program is the fix applied.
    {"FZ004", Family::Vigor, nullptr, "LD X0;LD X1;LD X2;ORB;ANB;OUT Y0;END",
     "LD X0;LD X1;OR X2;ANB;OUT Y0;END"},
    {"FZ005", Family::Vigor, nullptr, "LD X0;LD X1;AND X2;LD X3;ORB;ORB;OUT Y0;END",
     "LD X1;AND X2;LD X3;ORB;OR X0;OUT Y0;END"},
    {"FZ006", Family::Vigor, nullptr, "LD X0;MPS;LD X1;LD X2;ORB;ANB;OUT Y0;MPP;OUT Y1;END",
     "LD X0;OUT Y1;LD X1;LD X2;ORB;ANB;OUT Y0;END"},
    // Branch stack.
    {"ST001", Family::Vigor, nullptr,
     "LD X0;MPS;AND X1;MPS;AND X2;MPS;AND X3;MPS;AND X4;MPS;AND X5;MPS;AND X6;MPS;AND X7;MPS;AND "
     "X10;MPS;AND "
     "X11;OUT Y0;MPP;OUT Y1;MPP;OUT Y2;MPP;OUT Y3;MPP;OUT Y4;MPP;OUT Y5;MPP;OUT Y6;MPP;OUT "
     "Y7;MPP;OUT Y10;END",
     "LD X0;MPS;AND X1;MPS;AND X2;MPS;AND X3;MPS;AND X4;MPS;AND X5;MPS;AND X6;MPS;AND X7;MPS;AND "
     "X10;OUT Y0;MPP;OUT Y1;MPP;OUT Y2;MPP;OUT Y3;MPP;OUT Y4;MPP;OUT Y5;MPP;OUT Y6;MPP;OUT Y7;END"},
    {"ST002", Family::Vigor, nullptr, "LD X0;MPP;OUT Y0;END",
     "LD X0;MPS;AND X1;OUT Y0;MPP;AND X2;OUT Y1;END"},
    {"ST003", Family::Vigor, nullptr, "LD X0;MPS;AND X1;OUT Y0;LD X2;OUT Y1;END",
     "LD X0;MPS;AND X1;OUT Y0;MPP;AND X3;OUT Y2;LD X2;OUT Y1;END"},
    // END and nesting (VPC "END' missing!", "IL (JMP) missing", "IL-JMP interlace").
    {"EN001", Family::Vpc, nullptr, "LD i00;OUT o00", "LD i00;OUT o00;END"},
    {"EN002", Family::Vigor, nullptr, "LD X0;OUT Y0;END;LD X1;OUT Y1",
     "LD X0;OUT Y0;LD X1;OUT Y1;END"},
    {"NE001", Family::Vpc, nullptr, "LD i00;IL;LD i01;IL;LD i02;OUT o00;ILC;END",
     "LD i00;IL;LD i02;OUT o00;ILC;END"},
    {"NE002", Family::Vpc, nullptr, "LD i00;OUT o00;ILC;END", "LD i00;IL;LD i01;OUT o00;ILC;END"},
    {"NE003", Family::Vpc, nullptr, "LD i00;JMP;LD i01;JMP;LD i02;OUT o00;JPE;JPE;END",
     "LD i00;JMP;LD i02;OUT o00;JPE;END"},
    {"NE004", Family::Vpc, nullptr, "LD i00;OUT o00;JPE;END", "LD i00;JMP;LD i01;OUT o00;JPE;END"},
    {"NE005", Family::Vpc, nullptr, "LD i00;IL;LD i01;JMP;LD i02;OUT o00;ILC;JPE;END",
     "LD i00;IL;LD i01;JMP;LD i02;OUT o00;JPE;ILC;END"},
    {"NE006", Family::Cpm1, nullptr, "LD 000.00;JMP(04) 50;LD 000.01;OUT 010.00;JME(05) 50;END(01)",
     "LD 000.00;JMP(04) 49;LD 000.01;OUT 010.00;JME(05) 49;END(01)"},
    {"NE007", Family::Cpm1, nullptr,
     "LD 000.00;JMP(04) 01;LD 000.01;OUT 010.00;JME(05) 01;LD 000.02;OUT 010.01;JME(05) 01;END(01)",
     "LD 000.00;JMP(04) 01;LD 000.02;JMP(04) 01;LD 000.01;OUT 010.00;JME(05) 01;END(01)"},
    {"SL001", Family::Vigor, nullptr, "LD M9002;SET S0;STL S0;LD X0;OUT Y0;END",
     "LD M9002;SET S0;STL S0;LD X0;OUT Y0;RET;END"},
    // CPM1 subroutines and steps (Omron W353 "Subroutines", "Step Instructions").
    {"SB001", Family::Cpm1, nullptr, "LD 000.00;SBS(91) 01;END(01)",
     "LD 000.00;SBS(91) 01;SBN(92) 01;RET(93);END(01)"},
    {"SB002", Family::Cpm1, nullptr,
     "LD 000.00;SBS(91) 01;SBN(92) 01;RET(93);SBN(92) 01;RET(93);END(01)",
     "LD 000.00;SBS(91) 01;SBN(92) 01;RET(93);SBN(92) 02;RET(93);END(01)"},
    {"SB003", Family::Cpm1, nullptr, "LD 000.00;SBS(91) 01;SBN(92) 01;LD 000.01;OUT 010.00;END(01)",
     "LD 000.00;SBS(91) 01;SBN(92) 01;LD 000.01;OUT 010.00;RET(93);END(01)"},
    {"SB004", Family::Cpm1, nullptr,
     "LD 000.00;SBS(91) 01;SBN(92) 01;RET(93);LD 000.01;OUT 010.00;END(01)",
     "LD 000.00;SBS(91) 01;LD 000.01;OUT 010.00;SBN(92) 01;RET(93);END(01)"},
    {"SP001", Family::Cpm1, nullptr,
     "LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.01;OUT 010.00;END(01)",
     "LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.01;OUT 010.00;STEP(08);END(01)"},
    {"SP002", Family::Cpm1, nullptr, "LD 000.01;OUT 010.00;STEP(08);END(01)",
     "LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.01;OUT 010.00;STEP(08);END(01)"},
    {"SP003", Family::Cpm1, nullptr,
     "LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.01;JMP(04) 01;LD 000.02;OUT "
     "010.00;JME(05) 01;STEP(08);END(01)",
     "LD 000.01;JMP(04) 01;LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.02;OUT "
     "010.00;STEP(08);JME(05) 01;END(01)"},
    {"OP005", Family::Cpm1, nullptr, "LD 000.00;ADD(30) DM 0000 #00FF DM 0001;END(01)",
     "LD 000.00;ADD(30) DM 0000 #0099 DM 0001;END(01)"},
    // Operands per target and model.
    {"OP001", Family::Vpc, "VPC2416", "LD i00;OUT o20;END", "LD i00;OUT o15;END"},
    {"OP002", Family::Vigor, nullptr, "LD X0;OUT X1;END", "LD X0;OUT Y1;END"},
    {"OP003", Family::Vpc, nullptr, "LD i00;TIM05;LD i01;LD i02;CNT05;END",
     "LD i00;TIM05;LD i01;LD i02;CNT06;END"},
    {"OP004", Family::Vigor, nullptr, "LD X0;TMR T0 K40000;END", "LD X0;TMR T0 K100;END"},
    {"DC001", Family::Vpc, nullptr, "LD i00;OUT o00;LD i01;OUT o00;END",
     "LD i00;OUT o00;LD i01;OUT o01;END"},
    {"DC002", Family::Vigor, nullptr, "LD M9000;LINK D1000 D100;LD X0;LINK D1200 D200;END",
     "LD M9000;LINK D1000 D100;LD X0;MBUS D1200 D200;END"},
    {"OC001", Family::Vigor, nullptr, "OUT Y0;END", "LD M9000;OUT Y0;END"},
    {"BL001", Family::Vigor, nullptr, "LD X0;LD X1;OUT Y0;END", "LD X0;AND X1;OUT Y0;END"},
};

} // namespace

class EveryCode : public ::testing::TestWithParam<Case> {};

TEST_P(EveryCode, TriggersOnItsProgramAndNotOnTheCleanOne) {
    const Case &c = GetParam();
    const auto bad = check(c.family, c.model, text(c.triggers));
    const Diagnostic *d = find(bad, c.code);
    ASSERT_NE(d, nullptr) << all(bad).toStdString();
    EXPECT_FALSE(d->message.isEmpty());
    EXPECT_GT(d->location.line, 0) << "a listing finding has a line";
    const auto good = check(c.family, c.model, text(c.clean));
    EXPECT_EQ(find(good, c.code), nullptr) << all(good).toStdString();
}

INSTANTIATE_TEST_SUITE_P(Checks, EveryCode, ::testing::ValuesIn(kCases),
                         [](const auto &info) { return std::string(info.param.code); });

TEST(Checks, DuplicateCoilIsAWarningOnVigorAndAnErrorOnVpcAndCpm1) {
    const auto vigor = check(Family::Vigor, nullptr, text("LD X0;OUT Y0;LD X1;OUT Y0;END"));
    ASSERT_NE(find(vigor, "DC001"), nullptr);
    EXPECT_EQ(find(vigor, "DC001")->severity, Severity::Warning);
    const auto cpm1 =
        check(Family::Cpm1, nullptr, text("LD 000.00;OUT 010.00;LD 000.01;OUT 010.00;END(01)"));
    ASSERT_NE(find(cpm1, "DC001"), nullptr);
    EXPECT_EQ(find(cpm1, "DC001")->severity, Severity::Error);
    // Both places: the finding is on the second coil and names the first.
    EXPECT_EQ(find(cpm1, "DC001")->location.line, 4);
    ASSERT_EQ(find(cpm1, "DC001")->related.size(), 1u);
    EXPECT_EQ(find(cpm1, "DC001")->related[0].line, 2);
    EXPECT_TRUE(find(cpm1, "DC001")->message.contains(QStringLiteral("line 2")))
        << find(cpm1, "DC001")->message.toStdString();
}

TEST(Checks, OnTheLadderADuplicateCoilNamesTheRungOfTheFirst) {
    const Target &t = Target::get(Family::Vigor);
    const ParseResult parsed =
        parseInstructionList(t, text("LD X0;OUT Y1;LD X1;OUT Y0;LD X2;OUT Y0;END"));
    ASSERT_TRUE(parsed.ok());
    const ToLadderResult ladder = listToLadder(parsed.list);
    ASSERT_TRUE(ladder.ok());
    const auto ds = checkLadder(ladder.ladder);
    const Diagnostic *d = find(ds, "DC001");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.rung, 2);
    ASSERT_EQ(d->related.size(), 1u);
    EXPECT_EQ(d->related[0].rung, 1);
    EXPECT_TRUE(d->message.contains(QStringLiteral("rung 2"))) << d->message.toStdString();
    EXPECT_FALSE(d->message.contains(QStringLiteral("line"))) << d->message.toStdString();
}

TEST(Checks, ProgramTooLongForTheModel) {
    const QString longProgram = repeat("LD i00;OUT r00", 1025) + QStringLiteral("END\n");
    EXPECT_NE(find(check(Family::Vpc, nullptr, longProgram), "LN001"), nullptr);
    EXPECT_EQ(
        find(check(Family::Vpc, nullptr, repeat("LD i00;OUT r00", 1000) + QStringLiteral("END\n")),
             "LN001"),
        nullptr);
}

TEST(Checks, FuzzyFormsOfferTheCanonicalRewrite) {
    const auto ds =
        check(Family::Vigor, nullptr, text("LD X0;LD X1;LD X2;LD X3;ORB;ORB;ORB;OUT Y0;END"));
    const Diagnostic *d = find(ds, "FZ002");
    ASSERT_NE(d, nullptr);
    ASSERT_TRUE(d->fix.has_value());
    EXPECT_EQ(d->fix->firstLine, 1);
    EXPECT_EQ(d->fix->lastLine, 8);
    EXPECT_EQ(d->fix->listing, text("LD X0;OR X1;OR X2;OR X3;OUT Y0") + QLatin1Char('\n'));
}

TEST(Checks, OperandRangeNamesTheModel) {
    const auto ds = check(Family::Vpc, "VPC2416", text("LD i00;OUT o20;END"));
    ASSERT_NE(find(ds, "OP001"), nullptr);
    EXPECT_EQ(find(ds, "OP001")->message,
              QStringLiteral("o20 is beyond VPC2416's outputs o00..o15"));
}

// ---- ladder checks --------------------------------------------------------------------------

namespace {

// A bridge: X2 joins the two branches between contacts, so X3 -> X2 -> X1 would carry current
// right to left through X2's branch point (PLC concepts (WPLSoft family) 1.8). No listing can
// express it.
const char *kBridge = "LADDER vigor WIDTH 8\n"
                      "RUNG 1 ROWS 3 COLUMNS 3\n"
                      "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                      "|        |                 |\n"
                      "|        +-[ X2 ]-+        +\n"
                      "|                 |        |\n"
                      "|-[ X3 ]----------+-[ X4 ]-+\n";

const char *kCorrected = "LADDER vigor WIDTH 8\n"
                         "RUNG 1 ROWS 3 COLUMNS 3\n"
                         "|-[ X0 ]-+-[ X1 ]----------+(OUT Y0)\n"
                         "|        |                 |\n"
                         "|        +-[ X2 ]---[ X4 ]-+\n"
                         "|                          |\n"
                         "|-[ X3 ]---[ X4 ]----------+\n"
                         "\n";

LadderProgram ladderOf(const char *source) {
    LadderTextResult r = parseLadderText(Target::get(Family::Vigor), QString::fromLatin1(source));
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].message.toStdString());
    return r.ladder;
}

} // namespace

TEST(LadderChecks, ReverseCurrentMarksTheCellsAndOffersTheStandardCorrection) {
    const LadderProgram ladder = ladderOf(kBridge);
    const auto ds = checkLadder(ladder);
    const Diagnostic *d = find(ds, "RC001");
    ASSERT_NE(d, nullptr) << all(ds).toStdString();
    EXPECT_EQ(d->location.rung, 0);
    EXPECT_EQ(d->related.size(), 5u); // X0, X1, X2, X3, X4
    ASSERT_TRUE(d->fix.has_value());
    LadderProgram fixed;
    fixed.target = ladder.target;
    fixed.rungs = d->fix->rungs;
    EXPECT_EQ(printLadderText(fixed), QString::fromLatin1(kCorrected));
    EXPECT_EQ(find(checkLadder(fixed), "RC001"), nullptr);
    // The listing cannot express the bridge: conversion refuses it with the same finding.
    EXPECT_FALSE(ladderToList(ladder).ok());
    EXPECT_TRUE(ladderToList(fixed).ok());
}

TEST(LadderChecks, OpenBranchAndUnconnectedContact) {
    const LadderProgram open = ladderOf("LADDER vigor WIDTH 8\n"
                                        "RUNG 1 ROWS 2 COLUMNS 2\n"
                                        "|-[ X0 ]---[ X1 ]-+(OUT Y0)\n"
                                        "|\n"
                                        "|         -[ X2 ]-+(OUT Y1)\n");
    const auto ds = checkLadder(open);
    ASSERT_NE(find(ds, "LD001"), nullptr) << all(ds).toStdString();
    EXPECT_EQ(find(ds, "LD001")->location.row, 1);
    ASSERT_NE(find(ds, "LD002"), nullptr);
    EXPECT_EQ(find(ds, "LD002")->location.row, 1);
    EXPECT_EQ(find(ds, "LD002")->location.cell, 1);
    // The list has no line for it: the message names it and its place.
    EXPECT_EQ(find(ds, "LD002")->message,
              QStringLiteral("X2 (row 2, column 2) is not on any path from the left rail to an "
                             "output: the list leaves it out"));
    const auto clean = checkLadder(ladderOf("LADDER vigor WIDTH 8\n"
                                            "RUNG 1 ROWS 1 COLUMNS 2\n"
                                            "|-[ X0 ]---[ X1 ]-+(OUT Y0)\n"));
    EXPECT_EQ(find(clean, "LD001"), nullptr);
    EXPECT_EQ(find(clean, "LD002"), nullptr);
}

// END missing: the fix appends it, as a rung in the ladder and as a line in the list (the last
// line kept as typed).
TEST(LadderChecks, MissingEndOffersToAppendIt) {
    const LadderProgram ladder = ladderOf("LADDER vigor WIDTH 8\n"
                                          "RUNG 1 ROWS 1 COLUMNS 1\n"
                                          "|-[ X0 ]-+(OUT Y0)\n");
    const auto ds = checkLadder(ladder);
    const Diagnostic *d = find(ds, "EN001");
    ASSERT_NE(d, nullptr) << all(ds).toStdString();
    ASSERT_TRUE(d->fix.has_value());
    EXPECT_EQ(d->fix->label, QStringLiteral("Append END"));
    EXPECT_EQ(d->fix->firstRung, 1);
    EXPECT_EQ(d->fix->lastRung, 0); // nothing replaced
    LadderProgram fixed = ladder;
    fixed.rungs.insert(fixed.rungs.end(), d->fix->rungs.begin(), d->fix->rungs.end());
    EXPECT_EQ(find(checkLadder(fixed), "EN001"), nullptr);
    EXPECT_EQ(printInstructionList(ladderToList(fixed).list),
              QStringLiteral("LD X0\nOUT Y0\nEND\n"));

    const QString typed = QStringLiteral("LD  X0\nOUT Y0 ; lamp\n; the end\n");
    const ParseResult parsed = parseInstructionList(Target::get(Family::Vigor), typed);
    CheckOptions o;
    o.source = &typed;
    const auto listed = checkList(parsed.list, o);
    const Diagnostic *l = find(listed, "EN001");
    ASSERT_NE(l, nullptr);
    ASSERT_TRUE(l->fix.has_value());
    EXPECT_EQ(l->fix->firstLine, 2);
    EXPECT_EQ(l->fix->lastLine, 2);
    EXPECT_EQ(l->fix->listing, QStringLiteral("OUT Y0 ; lamp\nEND\n"));
    // On CPM1 END has its function code.
    const QString cpm1 = QStringLiteral("LD 000.00\nOUT 010.00");
    const ParseResult p1 = parseInstructionList(Target::get(Family::Cpm1), cpm1);
    o.source = &cpm1;
    const auto c = checkList(p1.list, o);
    ASSERT_NE(find(c, "EN001"), nullptr);
    ASSERT_TRUE(find(c, "EN001")->fix.has_value());
    EXPECT_EQ(find(c, "EN001")->fix->listing, QStringLiteral("OUT 010.00\nEND(01)\n"));
}

TEST(LadderChecks, OutputWiredStraightToTheRail) {
    const auto ds = checkLadder(ladderOf("LADDER vigor WIDTH 8\n"
                                         "RUNG 1 ROWS 1 COLUMNS 1\n"
                                         "|---------(OUT Y0)\n"));
    ASSERT_NE(find(ds, "OC001"), nullptr) << all(ds).toStdString();
}

TEST(LadderChecks, ListingFindingsLandOnTheirRung) {
    const Target &t = Target::get(Family::Vigor);
    ToLadderResult lad =
        listToLadder(parseInstructionList(t, text("LD X0;OUT Y0;LD X1;OUT X2;END")).list);
    ASSERT_TRUE(lad.ok());
    const auto ds = checkLadder(lad.ladder);
    ASSERT_NE(find(ds, "OP002"), nullptr) << all(ds).toStdString();
    EXPECT_EQ(find(ds, "OP002")->location.rung, 1);
}

TEST(Checks, FormOnlyGivesTheFuzzyFormsAloneWithTheirFixes) {
    const Target &t = Target::get(Family::Vigor);
    // Stacked ANB (FZ001), a coil driven twice (DC001) and no END (EN001).
    const ParseResult parsed = parseInstructionList(
        t, text("LD X0;OR X1;LD X2;OR X3;LD X4;OR X5;ANB;ANB;OUT Y0;LD X6;OUT Y0"));
    ASSERT_TRUE(parsed.ok());
    const auto all = checkList(parsed.list);
    ASSERT_NE(find(all, "FZ001"), nullptr);
    ASSERT_NE(find(all, "DC001"), nullptr);
    ASSERT_NE(find(all, "EN001"), nullptr);
    CheckOptions form;
    form.formOnly = true;
    const auto fuzzy = checkList(parsed.list, form);
    ASSERT_FALSE(fuzzy.empty());
    for (const Diagnostic &d : fuzzy)
        EXPECT_TRUE(d.code.startsWith(QLatin1String("FZ"))) << d.code.toStdString();
    const Diagnostic *stacked = find(fuzzy, "FZ001");
    ASSERT_NE(stacked, nullptr);
    ASSERT_TRUE(stacked->fix.has_value());
    EXPECT_EQ(stacked->fix->listing,
              QStringLiteral("LD X0\nOR X1\nLD X2\nOR X3\nANB\nLD X4\nOR X5\nANB\nOUT Y0\n"));
}

// ---- fuzzy forms: only where the text is not canonical, and every fix does something ---------

namespace {

ParseResult parsed(Family family, const QString &listing) {
    ParseResult p = parseInstructionList(Target::get(family), listing);
    EXPECT_TRUE(p.ok()) << listing.toStdString();
    return p;
}

// The listing with lines [fix.firstLine, fix.lastLine] replaced by the fix.
QString applied(const QString &listing, const Fix &fix) {
    QStringList lines = listing.split(QLatin1Char('\n'));
    QStringList out = lines.mid(0, fix.firstLine - 1);
    QString replacement = fix.listing;
    if (replacement.endsWith(QLatin1Char('\n')))
        replacement.chop(1);
    out += replacement.split(QLatin1Char('\n'));
    out += lines.mid(fix.lastLine);
    return out.join(QLatin1Char('\n'));
}

int count(const std::vector<Diagnostic> &ds, const QString &code) {
    return static_cast<int>(
        std::count_if(ds.begin(), ds.end(), [&](const Diagnostic &d) { return d.code == code; }));
}

} // namespace

TEST(FuzzyForms, TheCanonicalListingOfRandomProgramsHasNoFuzzyForm) {
    for (const Family family : {Family::Vigor, Family::Vpc, Family::Cpm1, Family::Pl110})
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            const QString program = rung::testing::randomProgram(Target::get(family), seed);
            const ToLadderResult drawn = listToLadder(parsed(family, program).list);
            ASSERT_TRUE(drawn.ok()) << program.toStdString();
            const ToListingResult back = ladderToList(drawn.ladder);
            ASSERT_TRUE(back.ok());
            const QString canonical = printInstructionList(back.list);
            for (const Diagnostic &d : checkList(parsed(family, canonical).list))
                EXPECT_FALSE(d.code.startsWith(QLatin1String("FZ")))
                    << d.code.toStdString() << " at line " << d.location.line << " of\n"
                    << canonical.toStdString();
        }
}

TEST(FuzzyForms, EveryFixChangesTheTextAndClearsItsCode) {
    std::map<QString, int> fixes; // by code
    for (const Family family : {Family::Vigor, Family::Vpc, Family::Cpm1, Family::Pl110})
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            const QString program = rung::testing::randomProgram(Target::get(family), seed);
            const auto found = checkList(parsed(family, program).list);
            for (const Diagnostic &d : found) {
                if (!d.code.startsWith(QLatin1String("FZ")) || !d.fix)
                    continue;
                ++fixes[d.code];
                const QString before =
                    program.split(QLatin1Char('\n'))
                        .mid(d.fix->firstLine - 1, d.fix->lastLine - d.fix->firstLine + 1)
                        .join(QLatin1Char('\n'));
                const QString after = applied(program, *d.fix);
                EXPECT_NE(printInstructionList(parsed(family, after).list),
                          printInstructionList(parsed(family, program).list))
                    << d.code.toStdString() << ": the fix changes nothing in\n"
                    << before.toStdString();
                // The fixed rung has that form once less (a rung may have it twice).
                const auto inRung = [&](const std::vector<Diagnostic> &ds, int lines) {
                    return std::count_if(ds.begin(), ds.end(), [&](const Diagnostic &e) {
                        return e.code == d.code && e.location.line >= d.fix->firstLine &&
                               e.location.line < d.fix->firstLine + lines;
                    });
                };
                const auto again = checkList(parsed(family, after).list);
                EXPECT_LT(inRung(again, static_cast<int>(d.fix->listing.count(QLatin1Char('\n')))),
                          inRung(found, d.fix->lastLine - d.fix->firstLine + 1))
                    << d.code.toStdString() << " stays after its fix of\n"
                    << before.toStdString() << "\ninto\n"
                    << d.fix->listing.toStdString();
            }
        }
    // Every kind of fix is tried: the canonical rewrite (FZ001, FZ002) and the moves.
    for (const char *code : {"FZ001", "FZ002", "FZ004", "FZ005", "FZ006"})
        EXPECT_GT(fixes[QString::fromLatin1(code)], 0) << code << " never offered a fix";
}

TEST(FuzzyForms, TheReorderingFixesAreTheManualsForms) {
    const struct {
        const char *code;
        const char *program;
        const char *fixed;
    } cases[] = {
        // FZ004 keeps the single contact in front (AFixKeepsTheOrderOfContactsInSeries).
        {"FZ004", "LD X0;LD X1;LD X2;ORB;ANB;OUT Y0;END", "LD X0;LD X1;OR X2;ANB;OUT Y0"},
        {"FZ005", "LD X0;LD X1;AND X2;LD X3;ORB;ORB;OUT Y0;END",
         "LD X1;AND X2;LD X3;ORB;OR X0;OUT Y0"},
        {"FZ006", "LD X0;MPS;LD X1;LD X2;ORB;ANB;OUT Y0;MPP;OUT Y1;END",
         "LD X0;OUT Y1;LD X1;LD X2;ORB;ANB;OUT Y0"},
        {"FZ006", "LD X0;MPS;LD X1;LD X2;ORB;ANB;OUT Y0;MRD;OUT Y1;MPP;AND X3;OUT Y2;END",
         "LD X0;OUT Y1;MPS;LD X1;LD X2;ORB;ANB;OUT Y0;MPP;AND X3;OUT Y2"},
    };
    for (const auto &c : cases) {
        const auto ds = check(Family::Vigor, nullptr, text(c.program));
        const Diagnostic *d = find(ds, c.code);
        ASSERT_NE(d, nullptr) << c.program << "\n" << all(ds).toStdString();
        ASSERT_TRUE(d->fix.has_value()) << c.program;
        EXPECT_EQ(d->fix->listing, text(c.fixed) + QLatin1Char('\n')) << c.program;
    }
}

// `X3 X4` written with a block (LD X3 / LD X4 / ANB) is fixed as LD X3 / AND X4: a fix keeps
// the order of the contacts it does not need to move (it used to give LD X4 / AND X3).
TEST(FuzzyForms, AFixKeepsTheOrderOfContactsInSeries) {
    const struct {
        const char *program;
        const char *fixed;
    } cases[] = {
        {"LD X3;LD X4;ANB;OUT Y0;END", "LD X3;AND X4;OUT Y0"},
        {"LD X3;LDI X4;AND X5;ANB;OUT Y0;END", "LD X3;ANI X4;AND X5;OUT Y0"},
        {"LD X0;OUT Y1;LD X3;LD X4;ANB;OUT Y0;END", "LD X3;AND X4;OUT Y0"},
    };
    for (const auto &c : cases) {
        const auto ds = check(Family::Vigor, nullptr, text(c.program));
        const Diagnostic *d = find(ds, "FZ004");
        ASSERT_NE(d, nullptr) << c.program << "\n" << all(ds).toStdString();
        ASSERT_TRUE(d->fix.has_value()) << c.program;
        EXPECT_EQ(d->fix->listing, text(c.fixed) + QLatin1Char('\n')) << c.program;
        EXPECT_EQ(d->fix->label, QStringLiteral("Join the contacts in series and drop the ANB"));
        EXPECT_TRUE(d->message.contains(QStringLiteral("AND"))) << d->message.toStdString();
    }
    // A block with a branch after a single contact: X0 stays in front (it used to move behind
    // the branch, LD X1 / LD X2 / ORB / AND X0), the branch is written as an OR, and the rung
    // so fixed has no fuzzy form left.
    const auto ds = check(Family::Vigor, nullptr, text("LD X0;LD X1;LD X2;ORB;ANB;OUT Y0;END"));
    const Diagnostic *d = find(ds, "FZ004");
    ASSERT_NE(d, nullptr) << all(ds).toStdString();
    ASSERT_TRUE(d->fix.has_value());
    EXPECT_EQ(d->fix->listing, text("LD X0;LD X1;OR X2;ANB;OUT Y0") + QLatin1Char('\n'));
    EXPECT_FALSE(d->message.contains(QStringLiteral("front and drop"))) << d->message.toStdString();
    const auto fixed = check(Family::Vigor, nullptr, d->fix->listing + QStringLiteral("END\n"));
    for (const Diagnostic &left : fixed)
        EXPECT_NE(left.severity, Severity::Error) << all(fixed).toStdString();
    for (const Diagnostic &left : fixed)
        EXPECT_FALSE(left.code.startsWith(QLatin1String("FZ"))) << all(fixed).toStdString();
    // The same with more contacts on the branch: their order stays too.
    const auto longer =
        check(Family::Vigor, nullptr, text("LD X0;LD X1;AND X3;LD X2;ORB;ANB;OUT Y0;END"));
    if (const Diagnostic *l = find(longer, "FZ004"); l && l->fix) {
        EXPECT_TRUE(l->fix->listing.startsWith(QStringLiteral("LD X0\n")))
            << l->fix->listing.toStdString();
    }
}

TEST(FuzzyForms, CanonicalFormsOfTheManualGetNoWarning) {
    // The converter's own output of the manual's execution-order example and of the forms the
    // fuzzy-form warnings used to fire on although there is nothing else to write.
    for (const char *program :
         {"LD X0;OR M0;AND X1;LD X3;AND M1;ORB;LD Y1;AND X4;LD T0;AND M3;ORB;ANB;OUT Y1;TMR T0 "
          "K10;END",
          "LD X0;LD X1;OR X2;ANB;OUT Y0;END", "LD X0;LD X1;AND X2;ORB;OUT Y0;END",
          "LD X0;MPS;AND X1;OUT Y0;MPP;OUT Y1;END"}) {
        const auto ds = check(Family::Vigor, nullptr, text(program));
        EXPECT_EQ(count(ds, QStringLiteral("FZ002")) + count(ds, QStringLiteral("FZ004")) +
                      count(ds, QStringLiteral("FZ005")) + count(ds, QStringLiteral("FZ006")),
                  0)
            << program << "\n"
            << all(ds).toStdString();
    }
}

TEST(FuzzyForms, ALadderHasNoFuzzyFormWarnings) {
    const Target &t = Target::get(Family::Vigor);
    const ToLadderResult lad = listToLadder(
        parsed(Family::Vigor, text("LD X0;LD X1;LD X2;LD X3;ORB;ORB;ORB;OUT Y0;END")).list);
    ASSERT_TRUE(lad.ok());
    ASSERT_EQ(lad.ladder.target, &t);
    for (const Diagnostic &d : checkLadder(lad.ladder))
        EXPECT_FALSE(d.code.startsWith(QLatin1String("FZ"))) << d.code.toStdString();
}

// ---- operands the instruction cannot write --------------------------------------------------

TEST(Checks, TheDevicesThePlcDrivesCannotBeWritten) {
    const struct {
        Family family;
        const char *program;
        const char *device;
    } driven[] = {
        {Family::Vigor, "LD X0;OUT M9000;END", "M9000"},
        {Family::Vigor, "LD X0;OUT M9002;END", "M9002"},
        {Family::Vigor, "LD X0;SET M9013;END", "M9013"},
        {Family::Vigor, "LD X0;MOV K5 D9010;END", "D9010"},
        {Family::Cpm1, "LD 000.00;OUT 253.13;END(01)", "253.13"},
        {Family::Pl110, "LD I1;OUT SM0.1;END", "SM0.1"}, // in a writable area: the table says
    };
    for (const auto &c : driven) {
        const auto ds = check(c.family, nullptr, text(c.program));
        const Diagnostic *d = find(ds, "OP002");
        ASSERT_NE(d, nullptr) << c.program << "\n" << all(ds).toStdString();
        EXPECT_TRUE(d->message.startsWith(QString::fromLatin1(c.device))) << c.program;
        EXPECT_EQ(d->location.line, 2);
    }
    // Read, or written where the program may (the programs of the Vigor M/VB/VH communication
    // manual drive M9100 to start dialing).
    for (const char *program :
         {"LD M9000;OUT Y0;END", "LD X0;OUT M9100;END", "LD M9013;MOV D9010 D0;END"})
        EXPECT_EQ(find(check(Family::Vigor, nullptr, text(program)), "OP002"), nullptr) << program;
    // VPC: the program may drop r88 (RUN) to stop and raise r89 (ERR), as docs/targets.md says.
    for (const char *program : {"LD i00;OUT r88;END", "LD i00;OUT r89;END"})
        EXPECT_EQ(find(check(Family::Vpc, nullptr, text(program)), "OP002"), nullptr) << program;
}

TEST(Checks, ACoilDrivesRelaysNotTimersCountersOrRegisters) {
    for (const char *program :
         {"LD X0;OUT T0;END", "LD X0;SET C0;END", "LD X0;OUT D0;END", "LD X0;PLS T1;END"}) {
        const auto ds = check(Family::Vigor, nullptr, text(program));
        ASSERT_NE(find(ds, "OP002"), nullptr) << program << "\n" << all(ds).toStdString();
    }
    EXPECT_NE(find(check(Family::Cpm1, nullptr, text("LD 000.00;OUT TIM 001;END(01)")), "OP002"),
              nullptr);
    // Resets clear timers, counters and registers.
    for (const char *program : {"LD X0;RST T0;END", "LD X0;RST C0;END", "LD X0;RST D0;END",
                                "LD X0;ZRST T0 T5;END", "LD X0;OUT S1;END"})
        EXPECT_EQ(find(check(Family::Vigor, nullptr, text(program)), "OP002"), nullptr) << program;
}

TEST(Checks, AnOperandFindingPointsAtTheOperandWhenTheSourceIsAtHand) {
    const Target &t = Target::get(Family::Vpc);
    const QString source = QStringLiteral("LD i00\n  OUT   a01 ; no\nEND\n");
    const ParseResult p = parseInstructionList(t, source);
    ASSERT_TRUE(p.ok());
    CheckOptions o;
    o.source = &source;
    const std::vector<Diagnostic> found = checkList(p.list, o);
    const Diagnostic *d = find(found, "OP002");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->location.line, 2);
    EXPECT_EQ(d->location.column, 9);
    // Without the text, the instruction's column.
    const auto plain = checkList(p.list);
    ASSERT_NE(find(plain, "OP002"), nullptr);
    EXPECT_EQ(find(plain, "OP002")->location.column, 3);
}

TEST(Checks, ProblemsThatKeepALadderFromItsListingAreLD003) {
    // A box with several inputs must stand alone in its rung.
    const Target &t = Target::get(Family::Vpc);
    const ToLadderResult box =
        listToLadder(parseInstructionList(t, text("LD i00;LD i01;LR r00;END")).list);
    ASSERT_TRUE(box.ok()) << (box.problems.empty() ? "" : box.problems[0].message.toStdString());
    LadderProgram bad = box.ladder;
    const ToLadderResult coil = listToLadder(parseInstructionList(t, text("LD i02;OUT o00")).list);
    ASSERT_TRUE(coil.ok());
    // Give the box's rung one more row driving a coil.
    Rung &r = bad.rungs[0];
    const Rung &extra = coil.ladder.rungs[0];
    ASSERT_EQ(extra.rows, 1);
    const int row = r.rows;
    r.resize(r.rows + 1, std::max(r.columns, extra.columns));
    r.cell(row, 0) = extra.cell(0, 0);
    r.outputs[static_cast<std::size_t>(row)] = extra.outputs[0];
    const auto ds = checkLadder(bad);
    const Diagnostic *d = find(ds, "LD003");
    ASSERT_NE(d, nullptr) << all(ds).toStdString();
    EXPECT_EQ(d->location.rung, 0);
    for (const Diagnostic &e : ds)
        EXPECT_FALSE(e.code.startsWith(QLatin1String("CV"))) << e.code.toStdString();
    EXPECT_EQ(find(checkLadder(box.ladder), "LD003"), nullptr);
}

// A listing with a line that does not parse (LD X8: X is octal) is still checked where the
// other lines show something by themselves: an output to an input, a coil driven twice. What
// depends on the whole list (OUT Y0 left without its condition, the blocks, END) waits.
TEST(Checks, LinesThatDoNotParseLeaveTheOthersChecked) {
    const Target &t = Target::get(Family::Vigor);
    const QString listing = QStringLiteral("LD X8\nOUT Y0\nLD X1\nOUT X2\nLD X3\nOUT Y0\nEND\n");
    const ParseResult parsed = parseInstructionList(t, listing);
    ASSERT_EQ(parsed.errors.size(), 1u);
    EXPECT_EQ(parsed.errors[0].line, 1);
    CheckOptions partial;
    partial.source = &listing;
    partial.parsedLinesOnly = true;
    const std::vector<Diagnostic> found = checkList(parsed.list, partial);
    ASSERT_EQ(found.size(), 2u) << all(found).toStdString();
    EXPECT_EQ(found[0].code, QStringLiteral("OP002"));
    EXPECT_EQ(found[0].location.line, 4);
    EXPECT_EQ(found[0].location.column, 5); // at X2
    EXPECT_EQ(found[1].code, QStringLiteral("DC001"));
    EXPECT_EQ(found[1].location.line, 6);
    // Checked whole, the list with its hole has an output with no condition on line 2: a
    // finding of the hole, not of what the user typed.
    CheckOptions whole;
    whole.source = &listing;
    EXPECT_NE(find(checkList(parsed.list, whole), "OC001"), nullptr);
    EXPECT_EQ(find(found, "OC001"), nullptr);
}
