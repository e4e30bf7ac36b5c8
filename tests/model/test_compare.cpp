#include "model/compare/compare.h"
#include "model/compare/project_text.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/structure.h"

#include "tests/model/random_program.h"
#include "tests/targets.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::vigor;

namespace {

// A project from a listing, as `diff` reads one: its ladder, with the comments written after
// an instruction counted as its rung's.
Project listed(const Target &t, const QString &text) {
    const ParseResult parsed = parseInstructionList(t, text);
    EXPECT_TRUE(parsed.ok()) << text.toStdString();
    ToLadderResult ladder = listToLadder(parsed.list);
    EXPECT_TRUE(ladder.ok()) << text.toStdString();
    Project p;
    p.target = &t;
    p.model = t.defaultModel().name;
    p.program = ladder.ladder;
    addInstructionComments(parsed.list, &p.program);
    return p;
}

Address at(const Target &t, const char *device) {
    return std::get<Address>(parseAddress(t, QString::fromLatin1(device)));
}

// Rung k of a program of n distinct rungs: LD Xk, AND Mk, OUT Yk (Vigor numbers in octal).
QString rungText(int k) {
    return QStringLiteral("LD X%1\nAND M%2\nOUT Y%1\n").arg(k, 0, 8).arg(k);
}

QString program(const std::vector<QString> &rungs) {
    QString text;
    for (const QString &r : rungs)
        text += r;
    return text + QStringLiteral("END\n");
}

std::vector<QString> distinctRungs(int n) {
    std::vector<QString> rungs;
    for (int k = 0; k < n; ++k)
        rungs.push_back(rungText(k));
    return rungs;
}

std::vector<RungStatus> statuses(const Comparison &c) {
    std::vector<RungStatus> out;
    for (const RungDifference &r : c.rungs)
        out.push_back(r.status);
    return out;
}

} // namespace

TEST(Compare, AProgramEqualsItself) {
    const Project p = listed(vigor(), program(distinctRungs(5)));
    const Comparison c = compareProjects(p, p);
    EXPECT_TRUE(c.equal());
    EXPECT_EQ(c.count(RungStatus::Same), 6); // five rungs and END
    EXPECT_EQ(comparisonText(c, QStringLiteral("a"), QStringLiteral("b")),
              QStringLiteral("--- A: a\n+++ B: b\nThe programs are the same (rungs: 6).\n"));
}

// The fuzzy spellings of one logic (PLC concepts (WPLSoft family) 1.7: a contact loaded alone
// and joined by ANB), other whitespace and another comment layout are not differences.
TEST(Compare, FuzzySpellingsWhitespaceAndCommentPlacementAreNoDifference) {
    const Project a = listed(vigor(), QStringLiteral("; start the pump\nLD X0\nLD X1\nANB\nOUT "
                                                     "Y0\nEND\n"));
    const Project b = listed(vigor(), QStringLiteral("LD   X0   ; start   the pump\n\n  AND X1\n"
                                                     "OUT Y0\nEND\n"));
    const Comparison c = compareProjects(a, b);
    EXPECT_TRUE(c.equal()) << comparisonText(c, {}, {}).toStdString();
}

// One logic drawn two ways: a wire through an extra column, rows in another width.
TEST(Compare, TheDrawingIsNoDifferenceTheLogicIs) {
    // Cells of 8 characters and a node character each: X0, a wire, X1.
    const LadderTextResult wide =
        parseLadderText(vigor(), QStringLiteral("LADDER vigor WIDTH 8\n"
                                                "RUNG 1 ROWS 1 COLUMNS 3\n"
                                                "|-[ X0 ]------------[ X1 ]--(OUT Y0)\n"
                                                "RUNG 2 ROWS 1 COLUMNS 0\n"
                                                "|-(END)\n"));
    ASSERT_TRUE(wide.ok()) << wide.errors.front().message.toStdString();
    Project a;
    a.target = &vigor();
    a.model = vigor().defaultModel().name;
    a.program = wide.ladder;
    const Project b = listed(vigor(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    EXPECT_TRUE(compareProjects(a, b).equal());
    const Project other = listed(vigor(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
    EXPECT_FALSE(compareProjects(a, other).equal());
}

// The issue's case: a rung moved by ten places and changed in one contact is "moved and
// changed", with the contact named, not a deletion and an insertion.
TEST(Compare, ARungMovedTenPlacesAndChangedInOneContactIsMovedAndChanged) {
    std::vector<QString> rungs = distinctRungs(15);
    const Project a = listed(vigor(), program(rungs));
    QString moved = rungs[2];
    moved.replace(QStringLiteral("AND M2"), QStringLiteral("ANI M2"));
    rungs.erase(rungs.begin() + 2);
    rungs.insert(rungs.begin() + 12, moved);
    const Project b = listed(vigor(), program(rungs));
    const Comparison c = compareProjects(a, b);
    EXPECT_EQ(c.count(RungStatus::Inserted), 0);
    EXPECT_EQ(c.count(RungStatus::Deleted), 0);
    EXPECT_EQ(c.count(RungStatus::MovedChanged), 1);
    EXPECT_EQ(c.count(RungStatus::Same), 15);
    const auto r = std::find_if(c.rungs.begin(), c.rungs.end(), [](const RungDifference &d) {
        return d.status == RungStatus::MovedChanged;
    });
    ASSERT_NE(r, c.rungs.end());
    EXPECT_EQ(r->a, 2);
    EXPECT_EQ(r->b, 12);
    ASSERT_EQ(r->elements.size(), 1u);
    EXPECT_EQ(r->elements[0].element, ElementChange::Element::Contact);
    EXPECT_EQ(r->elements[0].kind, ElementChange::Kind::Changed);
    EXPECT_EQ(r->elements[0].before, QStringLiteral("AND M2"));
    EXPECT_EQ(r->elements[0].after, QStringLiteral("ANI M2"));
    // Where the contact is drawn on both sides, for the side-by-side view.
    EXPECT_EQ(r->elements[0].cellA.row, 0);
    EXPECT_EQ(r->elements[0].cellA.column, 1);
    EXPECT_EQ(r->elements[0].cellB.column, 1);
    const QString text = comparisonText(c, QStringLiteral("a.il"), QStringLiteral("b.il"));
    EXPECT_TRUE(text.contains(QStringLiteral("rung 3 -> 13: moved and changed\n"
                                             "    * contact changed: AND M2 -> ANI M2\n")))
        << text.toStdString();
}

TEST(Compare, AMovedRungAloneIsMoved) {
    std::vector<QString> rungs = distinctRungs(8);
    const Project a = listed(vigor(), program(rungs));
    std::rotate(rungs.begin() + 1, rungs.begin() + 2, rungs.begin() + 7); // rung 1 to 6
    const Comparison c = compareProjects(a, listed(vigor(), program(rungs)));
    EXPECT_EQ(c.count(RungStatus::Moved), 1);
    EXPECT_EQ(c.count(RungStatus::Same), 8);
    EXPECT_FALSE(c.equal());
}

TEST(Compare, InsertedAndDeletedRungsStandWhereTheyAre) {
    std::vector<QString> rungs = distinctRungs(6);
    const Project a = listed(vigor(), program(rungs));
    rungs.erase(rungs.begin() + 1);
    rungs.insert(rungs.begin() + 3, QStringLiteral("LD X20\nSET M100\n"));
    const Comparison c = compareProjects(a, listed(vigor(), program(rungs)));
    EXPECT_EQ(statuses(c),
              (std::vector<RungStatus>{RungStatus::Same, RungStatus::Deleted, RungStatus::Same,
                                       RungStatus::Same, RungStatus::Inserted, RungStatus::Same,
                                       RungStatus::Same, RungStatus::Same}));
    EXPECT_EQ(c.rungs[1].a, 1);
    EXPECT_EQ(
        c.rungs[1].instructions,
        (QStringList{QStringLiteral("LD X1"), QStringLiteral("AND M1"), QStringLiteral("OUT Y1")}));
    EXPECT_EQ(c.rungs[4].b, 3);
    const QString text = comparisonText(c, QStringLiteral("a"), QStringLiteral("b"));
    EXPECT_TRUE(text.contains(QStringLiteral("- rung 2 of A: deleted\n    - LD X1\n")))
        << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("+ rung 4 of B: inserted\n    + LD X20\n    + SET "
                                             "M100\n")))
        << text.toStdString();
}

// Which operand of a box changed, and an element added or removed, by name.
TEST(Compare, ChangedOperandsAndAddedContactsAreNamed) {
    const Project a = listed(vigor(), QStringLiteral("LD X0\nAND X1\nTMR T0 K10\nLD T0\nOUT "
                                                     "Y0\nEND\n"));
    const Project b = listed(vigor(), QStringLiteral("LD X0\nAND X1\nAND X2\nTMR T0 K20\nLD "
                                                     "T0\nOUT Y0\nEND\n"));
    const Comparison c = compareProjects(a, b);
    ASSERT_EQ(c.count(RungStatus::Changed), 1);
    const RungDifference &r = c.rungs[0];
    ASSERT_EQ(r.elements.size(), 2u);
    EXPECT_EQ(r.elements[0].kind, ElementChange::Kind::Added);
    EXPECT_EQ(r.elements[0].after, QStringLiteral("AND X2"));
    EXPECT_EQ(r.elements[1].kind, ElementChange::Kind::Changed);
    EXPECT_EQ(r.elements[1].element, ElementChange::Element::Output);
    ASSERT_EQ(r.elements[1].operands.size(), 1u);
    EXPECT_EQ(r.elements[1].operands[0].index, 1);
    EXPECT_EQ(r.elements[1].operands[0].before, QStringLiteral("K10"));
    EXPECT_EQ(r.elements[1].operands[0].after, QStringLiteral("K20"));
    const QString text = comparisonText(c, QStringLiteral("a"), QStringLiteral("b"));
    EXPECT_TRUE(text.contains(QStringLiteral(
        "rung 1: changed\n    + contact added: AND X2\n    * output changed: TMR T0 K10 -> "
        "TMR T0 K20 (operand 2: K10 -> K20)\n")))
        << text.toStdString();
}

TEST(Compare, ARungCommentThatChangedIsAChange) {
    const Project a = listed(vigor(), QStringLiteral("; pump\nLD X0\nOUT Y0\nEND\n"));
    const Project b = listed(vigor(), QStringLiteral("; the pump\nLD X0\nOUT Y0\nEND\n"));
    const Comparison c = compareProjects(a, b);
    ASSERT_EQ(c.count(RungStatus::Changed), 1);
    EXPECT_TRUE(c.rungs[0].commentChanged);
    EXPECT_TRUE(c.rungs[0].elements.empty());
    EXPECT_TRUE(comparisonText(c, {}, {}).contains(
        QStringLiteral("    * comment changed: \"pump\" -> \"the pump\"\n")));
}

TEST(Compare, SymbolsSetValuesWatchListsAndModel) {
    const Target &t = vigor();
    Project a = listed(t, program(distinctRungs(2)));
    Project b = a;
    a.symbols = {{at(t, "X0"), QStringLiteral("Start"), QStringLiteral("green button")},
                 {at(t, "X1"), QStringLiteral("Stop"), {}}};
    b.symbols = {{at(t, "X0"), QStringLiteral("Start"), QStringLiteral("green  button ")},
                 {at(t, "X2"), QStringLiteral("Spare"), QStringLiteral("unused")},
                 {at(t, "X1"), QStringLiteral("Halt"), {}}};
    a.setValues = {{at(t, "T0"), 10}, {at(t, "T1"), 5}};
    b.setValues = {{at(t, "T0"), 20}, {at(t, "T2"), 7}};
    a.watchLists = {{QStringLiteral("Main"),
                     {QStringLiteral("X0"), QStringLiteral("D0"), QStringLiteral("D1")},
                     {{QStringLiteral("D0"), ValueFormat::Hex}}},
                    {QStringLiteral("Old"), {QStringLiteral("Y0")}, {}}};
    b.watchLists = {{QStringLiteral("Main"),
                     {QStringLiteral("X0"), QStringLiteral("D0"), QStringLiteral("D2")},
                     {{QStringLiteral("D0"), ValueFormat::Bcd}}}};
    b.model = QStringLiteral("VH");
    a.model = QStringLiteral("VB");
    const Comparison c = compareProjects(a, b);
    EXPECT_FALSE(c.equal());
    EXPECT_EQ(c.count(RungStatus::Same), 3);
    const QString text = comparisonText(c, QStringLiteral("a"), QStringLiteral("b"));
    EXPECT_EQ(text, QStringLiteral("--- A: a\n+++ B: b\n"
                                   "* model changed: VB -> VH\n"
                                   "* symbol X1 changed: name \"Stop\" -> \"Halt\"\n"
                                   "+ symbol X2 added: name \"Spare\"\n"
                                   "+ symbol X2 added: comment \"unused\"\n"
                                   "* set value T0 changed: value \"10\" -> \"20\"\n"
                                   "- set value T1 removed: value \"5\"\n"
                                   "+ set value T2 added: value \"7\"\n"
                                   "- watch list \"Main\": D1 removed\n"
                                   "+ watch list \"Main\": D2 added\n"
                                   "* watch list \"Main\": D0 shown as hex -> bcd\n"
                                   "- watch list \"Old\" removed: Y0\n"
                                   "Rungs: 3 in A, 3 in B; 3 the same, 0 moved, 0 changed, 0 "
                                   "moved and changed, 0 inserted, 0 deleted.\n"));
    const QJsonObject json = QJsonDocument::fromJson(comparisonJson(c, {}, {})).object();
    EXPECT_FALSE(json.value(QStringLiteral("equal")).toBool());
    const QJsonArray symbols = json.value(QStringLiteral("symbols")).toArray();
    ASSERT_EQ(symbols.size(), 3);
    EXPECT_EQ(symbols[0].toObject().value(QStringLiteral("device")).toString(),
              QStringLiteral("X1"));
    EXPECT_EQ(symbols[0].toObject().value(QStringLiteral("after")).toString(),
              QStringLiteral("Halt"));
    EXPECT_EQ(json.value(QStringLiteral("watchLists")).toArray().size(), 4);
}

TEST(Compare, JsonHasEveryRungWithItsStatus) {
    std::vector<QString> rungs = distinctRungs(3);
    const Project a = listed(vigor(), program(rungs));
    rungs[1].replace(QStringLiteral("OUT Y1"), QStringLiteral("SET Y1"));
    const Comparison c = compareProjects(a, listed(vigor(), program(rungs)));
    const QJsonObject json =
        QJsonDocument::fromJson(comparisonJson(c, QStringLiteral("a.il"), QStringLiteral("b.il")))
            .object();
    EXPECT_EQ(json.value(QStringLiteral("target")).toString(), QStringLiteral("vigor"));
    const QJsonArray list = json.value(QStringLiteral("rungs")).toArray();
    ASSERT_EQ(list.size(), 4);
    const QJsonObject changed = list[1].toObject();
    EXPECT_EQ(changed.value(QStringLiteral("status")).toString(), QStringLiteral("changed"));
    EXPECT_EQ(changed.value(QStringLiteral("a")).toInt(), 2);
    EXPECT_EQ(changed.value(QStringLiteral("b")).toInt(), 2);
    const QJsonObject element = changed.value(QStringLiteral("elements")).toArray()[0].toObject();
    EXPECT_EQ(element.value(QStringLiteral("element")).toString(), QStringLiteral("output"));
    EXPECT_EQ(element.value(QStringLiteral("before")).toString(), QStringLiteral("OUT Y1"));
    EXPECT_EQ(element.value(QStringLiteral("after")).toString(), QStringLiteral("SET Y1"));
    EXPECT_EQ(list[0].toObject().value(QStringLiteral("status")).toString(),
              QStringLiteral("same"));
    EXPECT_EQ(
        json.value(QStringLiteral("summary")).toObject().value(QStringLiteral("changed")).toInt(),
        1);
}

// Over random programs of every family: the fuzzy listing and its canonical rewrite are the
// same program; the rungs shuffled are only moved, never inserted or deleted.
TEST(Compare, RandomProgramsEqualTheirCanonicalFormAndShufflesAreMoves) {
    for (const Family family : Target::families()) {
        const Target &t = Target::get(family);
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            rung::testing::RandomProgramOptions options;
            options.rungs = 10;
            const QString text = rung::testing::randomProgram(t, seed, options);
            const ParseResult parsed = parseInstructionList(t, text);
            ASSERT_TRUE(parsed.ok()) << text.toStdString();
            const ToLadderResult ladder = listToLadder(parsed.list);
            if (!ladder.ok())
                continue;
            Project a;
            a.target = &t;
            a.model = t.defaultModel().name;
            a.program = ladder.ladder;
            Project canonical = a;
            canonical.program = listToLadder(ladderToList(a.program).list).ladder;
            const Comparison same = compareProjects(a, canonical);
            EXPECT_TRUE(same.equal()) << t.id.toStdString() << " seed " << seed << "\n"
                                      << comparisonText(same, {}, {}).toStdString();
            Project shuffled = a;
            std::reverse(shuffled.program.rungs.begin(), shuffled.program.rungs.end());
            const Comparison moved = compareProjects(a, shuffled);
            EXPECT_EQ(moved.count(RungStatus::Inserted), 0) << t.id.toStdString() << seed;
            EXPECT_EQ(moved.count(RungStatus::Deleted), 0) << t.id.toStdString() << seed;
            EXPECT_EQ(moved.count(RungStatus::Changed) + moved.count(RungStatus::MovedChanged), 0);
        }
    }
}

// A long program with a few edits: only those are reported (the matching goes by anchors,
// not by a table of every pair).
TEST(Compare, ALongProgramReportsOnlyItsEdits) {
    std::vector<QString> rungs;
    for (int k = 0; k < 2500; ++k)
        rungs.push_back(QStringLiteral("LD M%1\nOUT M%2\n").arg(k).arg(k + 2500));
    const Project a = listed(vigor(), program(rungs));
    rungs[100] = QStringLiteral("LDI M100\nOUT M2600\n");
    rungs.erase(rungs.begin() + 2000);
    rungs.insert(rungs.begin() + 10, QStringLiteral("LD X0\nOUT Y0\n"));
    const Comparison c = compareProjects(a, listed(vigor(), program(rungs)));
    EXPECT_EQ(c.count(RungStatus::Changed), 1);
    EXPECT_EQ(c.count(RungStatus::Deleted), 1);
    EXPECT_EQ(c.count(RungStatus::Inserted), 1);
    EXPECT_EQ(c.count(RungStatus::Same), 2499); // 2,500 rungs and END, less the three edits
}

TEST(Compare, ARungNoListingHoldsIsComparedByItsDrawing) {
    // A reverse-current bridge (docs/ladder-text.md): no listing, still compared.
    const QString bridge = QStringLiteral("LADDER vigor WIDTH 8\n"
                                          "RUNG 1 ROWS 3 COLUMNS 3\n"
                                          "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                                          "|        |                 |\n"
                                          "|        +-[ X2 ]-+        +\n"
                                          "|                 |        |\n"
                                          "|-[ X3 ]----------+-[ X4 ]-+\n");
    QString other = bridge;
    other.replace(QStringLiteral("X4"), QStringLiteral("X5"));
    Project a;
    a.target = &vigor();
    a.model = vigor().defaultModel().name;
    a.program = parseLadderText(vigor(), bridge).ladder;
    Project b = a;
    EXPECT_TRUE(compareProjects(a, b).equal());
    b.program = parseLadderText(vigor(), other).ladder;
    const Comparison c = compareProjects(a, b);
    EXPECT_EQ(c.count(RungStatus::Changed), 1);
    EXPECT_TRUE(projectText(b).contains(QStringLiteral("X5")));
}

TEST(ProjectText, ShowsTheListingAndEverythingAroundItWithoutRungNumbers) {
    const Target &t = vigor();
    Project p = listed(t, QStringLiteral("; start\nLD X0\nOUT Y0\nEND\n"));
    p.symbols = {{at(t, "X0"), QStringLiteral("Start"), QStringLiteral("green")}};
    p.setValues = {{at(t, "T0"), 10}};
    p.watchLists = {{QStringLiteral("Main"),
                     {QStringLiteral("D0")},
                     {{QStringLiteral("D0"), ValueFormat::Hex}}}};
    EXPECT_EQ(projectText(p), QStringLiteral("; target: vigor\n; model: %1\n\n; start\nLD X0\n"
                                             "OUT Y0\n\nEND\n\n; symbols:\n;   X0 = Start  -- "
                                             "green\n\n; set values:\n;   T0 = 10\n\n; watch "
                                             "list \"Main\":\n;   D0 (hex)\n")
                                  .arg(t.defaultModel().name));
}

// The lists side by side: a heading per rung, the instructions aligned within it.
TEST(Compare, TheListingsStandSideBySideAligned) {
    std::vector<QString> rungs = distinctRungs(2);
    const Project a = listed(vigor(), program(rungs));
    rungs[1] = QStringLiteral("LD X1\nAND X2\nANI M1\nOUT Y1\n");
    const Project b = listed(vigor(), program(rungs));
    const Comparison c = compareProjects(a, b);
    const std::vector<ListingRow> rows = comparisonListing(c, a.program, b.program);
    using K = ListingRow::Kind;
    std::vector<std::tuple<K, QString, QString>> got;
    for (const ListingRow &r : rows)
        got.emplace_back(r.kind, r.a, r.b);
    const std::vector<std::tuple<K, QString, QString>> expected{
        {K::Rung, {}, {}},
        {K::Same, QStringLiteral("LD X0"), QStringLiteral("LD X0")},
        {K::Same, QStringLiteral("AND M0"), QStringLiteral("AND M0")},
        {K::Same, QStringLiteral("OUT Y0"), QStringLiteral("OUT Y0")},
        {K::Rung, {}, {}},
        {K::Same, QStringLiteral("LD X1"), QStringLiteral("LD X1")},
        {K::Changed, QStringLiteral("AND M1"), QStringLiteral("AND X2")},
        {K::Added, {}, QStringLiteral("ANI M1")},
        {K::Same, QStringLiteral("OUT Y1"), QStringLiteral("OUT Y1")},
        {K::Rung, {}, {}},
        {K::Same, QStringLiteral("END"), QStringLiteral("END")}};
    EXPECT_EQ(got, expected);
    EXPECT_EQ(rows[6].difference, 1);
}
