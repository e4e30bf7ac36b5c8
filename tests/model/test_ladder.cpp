// The ladder grid (model/ladder/ladder.h), its plain-text drawing (docs/ladder-text.md) and the
// reverse-current analysis (model/ladder/reverse_current.h).

#include "random_program.h"
#include "tests/targets.h"

#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/ladder/replace_device.h"
#include "model/ladder/reverse_current.h"

#include <gtest/gtest.h>

#include <QFile>

using namespace rung::model;

namespace {

using rung::testing::vigor;

Contact contactOf(const char *device) {
    Contact c;
    Operand o;
    o.address = std::get<Address>(parseAddress(vigor(), QString::fromLatin1(device)));
    c.operands = {o};
    return c;
}

void put(Rung &r, int row, int column, const char *device) {
    r.cell(row, column).kind = CellKind::Contact;
    r.cell(row, column).contact = contactOf(device);
}

Instruction outputOf(const char *text) {
    ParseResult p = parseInstructionList(vigor(), QString::fromLatin1(text));
    EXPECT_TRUE(p.ok() && p.list.instructions.size() == 1) << text;
    return p.list.instructions.at(0);
}

QString cellDevice(const Rung &r, int row, int column) {
    const Cell &c = r.cell(row, column);
    if (c.kind != CellKind::Contact || c.contact.operands.empty())
        return {};
    return formatAddress(vigor(), c.contact.operands.front().address);
}

// X0 - X1 -> OUT Y0 over X2 joined at node 1, X2 -> OUT Y1.
Rung twoRowRung() {
    Rung r(2, 2);
    put(r, 0, 0, "X0");
    put(r, 0, 1, "X1");
    put(r, 1, 1, "X2");
    r.setLink(0, 1, true);
    r.outputs[0] = outputOf("OUT Y0");
    r.outputs[1] = outputOf("OUT Y1");
    return r;
}

LadderProgram ladderOf(const QString &text, Family family = Family::Vigor) {
    LadderTextResult r = parseLadderText(Target::get(family), text);
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? std::string()
                                             : QStringLiteral("%1:%2: %3")
                                                   .arg(r.errors[0].line)
                                                   .arg(r.errors[0].column)
                                                   .arg(r.errors[0].message)
                                                   .toStdString());
    return r.ladder;
}

QString readData(const char *name) {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/ladder/%1").arg(QString::fromLatin1(name)));
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << name;
    return QString::fromUtf8(f.readAll());
}

} // namespace

// ---- grid operations ------------------------------------------------------------------------

TEST(LadderGrid, NewRungIsEmptyWithOneOutputSlotPerRow) {
    Rung r(3, 4);
    EXPECT_EQ(r.cells.size(), 12u);
    EXPECT_EQ(r.links.size(), 15u);
    EXPECT_EQ(r.outputs.size(), 3u);
    for (const Cell &c : r.cells)
        EXPECT_EQ(c.kind, CellKind::Empty);
    EXPECT_FALSE(r.link(2, 4));
}

TEST(LadderGrid, ResizeKeepsWhatFits) {
    Rung r = twoRowRung();
    r.resize(1, 3);
    EXPECT_EQ(r.rows, 1);
    EXPECT_EQ(r.columns, 3);
    EXPECT_EQ(cellDevice(r, 0, 0), QStringLiteral("X0"));
    EXPECT_EQ(cellDevice(r, 0, 1), QStringLiteral("X1"));
    EXPECT_EQ(r.cell(0, 2).kind, CellKind::Empty);
    EXPECT_EQ(r.outputs.size(), 1u);
    ASSERT_TRUE(r.outputs[0].has_value());
    r.resize(0, -5); // clamped: never fewer than one row, never negative columns
    EXPECT_EQ(r.rows, 1);
    EXPECT_EQ(r.columns, 0);
    EXPECT_TRUE(r.cells.empty());
    EXPECT_EQ(r.links.size(), 1u);
}

// Widening a rung wires on the rows that reached its right end: their coils keep their
// condition; a row that stopped short stays open; a new row is empty.
TEST(LadderGrid, WideningKeepsTheWiresToTheCoils) {
    Rung r = twoRowRung();
    r.cell(1, 1) = Cell{}; // row 1 now stops short of the end
    r.widenKeepingWires(3, 4);
    EXPECT_EQ(r.columns, 4);
    EXPECT_EQ(r.cell(0, 2).kind, CellKind::Wire);
    EXPECT_EQ(r.cell(0, 3).kind, CellKind::Wire);
    EXPECT_EQ(r.cell(1, 2).kind, CellKind::Empty);
    EXPECT_EQ(r.cell(2, 3).kind, CellKind::Empty);
    EXPECT_EQ(cellDevice(r, 0, 1), QStringLiteral("X1"));
}

TEST(LadderGrid, InsertRowShiftsRowsBelowAndKeepsLinksThrough) {
    Rung r = twoRowRung();
    r.insertRow(1);
    ASSERT_EQ(r.rows, 3);
    EXPECT_EQ(cellDevice(r, 0, 0), QStringLiteral("X0"));
    EXPECT_EQ(r.cell(1, 1).kind, CellKind::Empty);
    EXPECT_EQ(cellDevice(r, 2, 1), QStringLiteral("X2"));
    EXPECT_FALSE(r.outputs[1].has_value());
    ASSERT_TRUE(r.outputs[2].has_value());
    EXPECT_TRUE(r.outputs[2]->sameAs(outputOf("OUT Y1")));
    // The link from row 0 to the old row 1 now runs through the new row.
    EXPECT_TRUE(r.link(0, 1));
    EXPECT_TRUE(r.link(1, 1));
    EXPECT_FALSE(r.link(2, 1));
}

TEST(LadderGrid, RemoveRowUndoesInsertRow) {
    const Rung before = twoRowRung();
    Rung r = before;
    r.insertRow(1);
    r.removeRow(1);
    EXPECT_TRUE(r == before);
    // The last row cannot go, nor can a row outside the grid.
    Rung one(1, 2);
    one.removeRow(0);
    one.removeRow(5);
    EXPECT_EQ(one.rows, 1);
}

TEST(LadderGrid, InsertColumnInsideAWiredRowContinuesTheWire) {
    Rung r = twoRowRung();
    r.insertColumn(1);
    ASSERT_EQ(r.columns, 3);
    EXPECT_EQ(cellDevice(r, 0, 0), QStringLiteral("X0"));
    EXPECT_EQ(r.cell(0, 1).kind, CellKind::Wire); // between X0 and X1
    EXPECT_EQ(cellDevice(r, 0, 2), QStringLiteral("X1"));
    EXPECT_EQ(r.cell(1, 1).kind, CellKind::Empty); // row 1 starts at the link
    EXPECT_EQ(cellDevice(r, 1, 2), QStringLiteral("X2"));
    EXPECT_TRUE(r.link(0, 1)); // the branch point stays in front of the new column
    EXPECT_FALSE(r.link(0, 2));
}

TEST(LadderGrid, RemoveColumnMergesTheNodesAndUndoesInsertColumn) {
    const Rung before = twoRowRung();
    Rung r = before;
    r.insertColumn(1);
    r.removeColumn(1);
    EXPECT_TRUE(r == before);
    r.removeColumn(0);
    ASSERT_EQ(r.columns, 1);
    EXPECT_EQ(cellDevice(r, 0, 0), QStringLiteral("X1"));
    EXPECT_TRUE(r.link(0, 0)); // the link at node 1 lands on the new node 0
    r.removeColumn(7);         // outside the grid: nothing happens
    EXPECT_EQ(r.columns, 1);
}

TEST(LadderGrid, TwoInputBoxCoversTheRowsOfItsInputs) {
    const Target &cpm = Target::get(Family::Cpm1);
    ParseResult p = parseInstructionList(cpm, QStringLiteral("LD 000.00\nLD 000.01\nKEEP(11) "
                                                             "010.00\n"));
    ASSERT_TRUE(p.ok());
    ToLadderResult lad = listToLadder(p.list);
    ASSERT_TRUE(lad.ok());
    ASSERT_EQ(lad.ladder.rungs.size(), 1u);
    const Rung &r = lad.ladder.rungs[0];
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.boxInputRows(0), (std::vector<int>{0, 1}));
    EXPECT_FALSE(r.coveredByBox(0));
    EXPECT_TRUE(r.coveredByBox(1));
    // A coil feeds from its own row only.
    const Rung coil = twoRowRung();
    EXPECT_EQ(coil.boxInputRows(1), (std::vector<int>{1}));
    EXPECT_FALSE(coil.coveredByBox(1));
}

TEST(LadderGrid, EqualityIgnoresWhereTheOutputCameFromInTheSource) {
    Rung a = twoRowRung();
    Rung b = twoRowRung();
    b.outputs[0]->line = 42;
    b.outputs[0]->step = 7;
    EXPECT_TRUE(a == b);
    b.outputs[0] = outputOf("OUT Y2");
    EXPECT_FALSE(a == b);
    b = a;
    b.setLink(0, 2, true);
    EXPECT_FALSE(a == b);
    b = a;
    b.comment = QStringLiteral("x");
    EXPECT_FALSE(a == b);
}

// ---- the plain-text drawing -----------------------------------------------------------------

TEST(LadderText, BridgeDrawingReadsAndPrintsBackExactly) {
    const QString text = readData("bridge.ladder");
    const LadderProgram ladder = ladderOf(text);
    ASSERT_EQ(ladder.rungs.size(), 1u);
    const Rung &r = ladder.rungs[0];
    EXPECT_EQ(r.rows, 3);
    EXPECT_EQ(r.columns, 3);
    EXPECT_EQ(cellDevice(r, 1, 1), QStringLiteral("X2"));
    EXPECT_TRUE(r.link(0, 1));
    EXPECT_TRUE(r.link(1, 2));
    EXPECT_TRUE(r.link(0, 3));
    EXPECT_EQ(printLadderText(ladder), text);
}

TEST(LadderText, ContactMarksAndComparesReadBack) {
    const Target &t = vigor();
    for (const char *text : {"X0", "/X0", "^X0", "_X0", "D0>=K10"}) {
        QString error;
        const std::optional<Contact> c = contactFromText(t, QString::fromLatin1(text), &error);
        ASSERT_TRUE(c.has_value()) << text << ": " << error.toStdString();
        EXPECT_EQ(contactToText(t, *c), QString::fromLatin1(text));
    }
    QString error;
    EXPECT_FALSE(contactFromText(t, QStringLiteral("Q99"), &error).has_value());
    EXPECT_FALSE(error.isEmpty());
}

TEST(LadderText, BadDrawingSaysWhereAndWhy) {
    LadderTextResult r = parseLadderText(vigor(), QStringLiteral("LADDER vigor WIDTH 8\n"
                                                                 "RUNG 1 ROWS 1 COLUMNS 1\n"
                                                                 "|-[ Q9 ]-+(OUT Y0)\n"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].line, 3);
    EXPECT_GT(r.errors[0].column, 0);
    EXPECT_FALSE(r.errors[0].message.isEmpty());
    // Truncated and garbage input give errors, never a crash.
    for (const char *bad : {"LADDER", "LADDER vigor WIDTH 8\nRUNG 1 ROWS 3 COLUMNS 2\n|-[ X0",
                            "RUNG 1 ROWS 99999999999 COLUMNS 2\n", "\x01\x02", "LADDER nope"})
        EXPECT_FALSE(parseLadderText(vigor(), QString::fromLatin1(bad)).ok()) << bad;
}

class LadderTextRoundTrip : public ::testing::TestWithParam<Family> {};

TEST_P(LadderTextRoundTrip, PrintThenParseGivesTheSameLadder) {
    const Target &target = Target::get(GetParam());
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        rung::testing::RandomProgramOptions o;
        o.rungs = 4;
        ParseResult p = parseInstructionList(target, rung::testing::randomProgram(target, seed, o));
        ASSERT_TRUE(p.ok()) << seed;
        ToLadderResult lad = listToLadder(p.list);
        ASSERT_TRUE(lad.ok()) << seed;
        const QString text = printLadderText(lad.ladder);
        LadderTextResult back = parseLadderText(target, text);
        ASSERT_TRUE(back.ok()) << seed << "\n"
                               << text.toStdString() << back.errors[0].line << ": "
                               << back.errors[0].message.toStdString();
        ASSERT_EQ(back.ladder.rungs.size(), lad.ladder.rungs.size()) << seed;
        for (std::size_t i = 0; i < back.ladder.rungs.size(); ++i)
            ASSERT_TRUE(back.ladder.rungs[i] == lad.ladder.rungs[i])
                << "seed " << seed << " rung " << i << "\n"
                << text.toStdString();
        ASSERT_EQ(printLadderText(back.ladder), text) << seed;
    }
}

// A project holds each contact as its text (contactToText): read alone (contactFromText, as
// loadProject does), it is the contact the drawing had, for every kind of contact of a target.
TEST_P(LadderTextRoundTrip, EveryContactReadsBackAlone) {
    const Target &target = Target::get(GetParam());
    int contacts = 0;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        rung::testing::RandomProgramOptions o;
        o.rungs = 6;
        o.extended = true;
        ParseResult p = parseInstructionList(target, rung::testing::randomProgram(target, seed, o));
        ASSERT_TRUE(p.ok()) << seed;
        const ToLadderResult lad = listToLadder(p.list);
        for (const Rung &rung : lad.ladder.rungs)
            for (int r = 0; r < rung.rows; ++r)
                for (int c = 0; c < rung.columns; ++c) {
                    if (rung.cell(r, c).kind != CellKind::Contact)
                        continue;
                    const Contact &drawn = rung.cell(r, c).contact;
                    const QString text = contactToText(target, drawn);
                    QString error;
                    const std::optional<Contact> read = contactFromText(target, text, &error);
                    ASSERT_TRUE(read.has_value())
                        << text.toStdString() << ": " << error.toStdString();
                    EXPECT_TRUE(*read == drawn) << text.toStdString();
                    ++contacts;
                }
    }
    EXPECT_GT(contacts, 500);
    // What is not a contact says why.
    for (const char *bad : {"", "/", "~X", "?X0", "X0]-[X1"}) {
        QString error;
        EXPECT_FALSE(contactFromText(target, QString::fromLatin1(bad), &error).has_value()) << bad;
        EXPECT_FALSE(error.isEmpty()) << bad;
    }
}

INSTANTIATE_TEST_SUITE_P(AllTargets, LadderTextRoundTrip,
                         ::testing::Values(Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110),
                         [](const auto &info) { return Target::get(info.param).id.toStdString(); });

// ---- reverse current ------------------------------------------------------------------------

TEST(ReverseCurrent, BridgeIsFoundWithItsCellsAndCorrected) {
    const LadderProgram ladder = ladderOf(readData("bridge.ladder"));
    const std::vector<ReverseCurrentFinding> found = findReverseCurrent(ladder.rungs[0]);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].row, 0);
    const std::vector<std::pair<int, int>> cells = {{0, 0}, {0, 2}, {1, 1}, {2, 0}, {2, 2}};
    EXPECT_EQ(found[0].cells, cells);
    LadderProgram corrected;
    corrected.target = ladder.target;
    corrected.rungs = {found[0].corrected};
    EXPECT_EQ(printLadderText(corrected), readData("bridge_corrected.ladder"));
    EXPECT_TRUE(findReverseCurrent(found[0].corrected).empty());
}

TEST(ReverseCurrent, SeriesParallelRungsHaveNoFinding) {
    EXPECT_TRUE(findReverseCurrent(twoRowRung()).empty());
    const Target &t = vigor();
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        ParseResult p = parseInstructionList(t, rung::testing::randomProgram(t, seed));
        ToLadderResult lad = listToLadder(p.list);
        for (const Rung &r : lad.ladder.rungs)
            ASSERT_TRUE(findReverseCurrent(r).empty()) << seed;
    }
}

TEST(ReverseCurrent, ConversionRefusesTheBridgeWithAProblemNotGarbage) {
    const LadderProgram ladder = ladderOf(readData("bridge.ladder"));
    const ToListingResult r = ladderToList(ladder);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.problems[0].location.rung, 0);
    EXPECT_TRUE(r.list.instructions.empty());
    ASSERT_EQ(r.rungFirst.size(), 2u);
    EXPECT_EQ(r.rungFirst[0], r.rungFirst[1]); // the rung emits nothing
}

// ---- rows wider than the target's row ------------------------------------------------------

TEST(LadderGrid, RowsWiderThanTheTargetAreStoredWhole) {
    const Target &t = vigor();
    ASSERT_EQ(t.limits.contactsPerRow, 11);
    QString text = QStringLiteral("LD X0\n");
    for (int i = 1; i < 16; ++i)
        text += QStringLiteral("AND X%1\n").arg(i, 0, 8);
    text += QStringLiteral("OUT Y0\n");
    ParseResult p = parseInstructionList(t, text);
    ASSERT_TRUE(p.ok());
    ToLadderResult lad = listToLadder(p.list);
    ASSERT_TRUE(lad.ok());
    ASSERT_EQ(lad.ladder.rungs.size(), 1u);
    EXPECT_EQ(lad.ladder.rungs[0].rows, 1);
    EXPECT_EQ(lad.ladder.rungs[0].columns, 16);
    EXPECT_EQ(printInstructionList(ladderToList(lad.ladder).list), text);
    LadderTextResult back = parseLadderText(t, printLadderText(lad.ladder));
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(back.ladder.rungs[0] == lad.ladder.rungs[0]);
}

TEST(LadderText, LinkDrawnOnTheRailReadsBack) {
    LadderProgram ladder;
    ladder.target = &vigor();
    Rung r = twoRowRung();
    r.setLink(0, 0, true);
    ladder.rungs = {r};
    const QString text = printLadderText(ladder);
    EXPECT_TRUE(text.contains(QStringLiteral("\n+"))) << text.toStdString();
    LadderTextResult back = parseLadderText(vigor(), text);
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(back.ladder.rungs[0] == r);
    EXPECT_TRUE(back.ladder.rungs[0].link(0, 0));
}

TEST(LadderGrid, ReplaceDeviceRenamesEveryUseInContactsAndOutputsOnly) {
    Rung b(1, 1);
    put(b, 0, 0, "X2");
    b.outputs[0] = outputOf("OUT Y0");
    std::vector<Rung> rungs = {twoRowRung(), b}; // X0 X1 -> Y0 over X2 -> Y1; X2 -> Y0
    const Address x0 = std::get<Address>(parseAddress(vigor(), QStringLiteral("X0")));
    const Address x7 = std::get<Address>(parseAddress(vigor(), QStringLiteral("X7")));
    const Address y0 = std::get<Address>(parseAddress(vigor(), QStringLiteral("Y0")));
    const Address m5 = std::get<Address>(parseAddress(vigor(), QStringLiteral("M5")));
    EXPECT_EQ(replaceDevice(rungs, vigor(), x0, x7), 1);
    EXPECT_EQ(cellDevice(rungs[0], 0, 0), QStringLiteral("X7"));
    EXPECT_EQ(cellDevice(rungs[0], 0, 1), QStringLiteral("X1")); // the others untouched
    EXPECT_EQ(cellDevice(rungs[1], 0, 0), QStringLiteral("X2"));
    EXPECT_EQ(replaceDevice(rungs, vigor(), y0, m5), 2); // an output in each rung
    EXPECT_EQ(rungs[0].outputs[0]->operands.front().address, m5);
    EXPECT_EQ(rungs[1].outputs[0]->operands.front().address, m5);
    EXPECT_EQ(formatAddress(vigor(), rungs[0].outputs[1]->operands.front().address),
              QStringLiteral("Y1"));
    EXPECT_EQ(replaceDevice(rungs, vigor(), y0, m5), 0); // nothing left to change
}

// Replace Device refuses what the list would refuse (a marker where TMR needs a timer, a word
// where a contact needs a bit) and then changes nothing, so the program never turns into one
// that cannot be listed.
TEST(LadderGrid, ReplaceDeviceRefusesADeviceThatCannotStandInAPlace) {
    Rung r(1, 1);
    put(r, 0, 0, "X0");
    r.outputs[0] = outputOf("TMR T0 K10");
    Rung c(1, 1);
    put(c, 0, 0, "T0");
    c.outputs[0] = outputOf("OUT Y0");
    const std::vector<Rung> before = {r, c};
    std::vector<Rung> rungs = before;
    const auto address = [](const char *text) {
        return std::get<Address>(parseAddress(vigor(), QString::fromLatin1(text)));
    };
    QString problem;
    EXPECT_EQ(replaceDevice(rungs, vigor(), address("T0"), address("M5"), &problem), -1);
    EXPECT_TRUE(problem.contains(QStringLiteral("M5"))) << problem.toStdString();
    EXPECT_TRUE(problem.contains(QStringLiteral("rung 1"))) << problem.toStdString();
    EXPECT_TRUE(problem.contains(QStringLiteral("a timer"))) << problem.toStdString();
    EXPECT_TRUE(rungs[0] == before[0] && rungs[1] == before[1]); // nothing changed
    problem.clear();
    EXPECT_EQ(replaceDevice(rungs, vigor(), address("X0"), address("D0"), &problem), -1);
    EXPECT_TRUE(problem.contains(QStringLiteral("a bit device"))) << problem.toStdString();
    EXPECT_TRUE(rungs[0] == before[0] && rungs[1] == before[1]);
    // A timer for a timer is fine, in the box and in the contact that reads it.
    EXPECT_EQ(replaceDevice(rungs, vigor(), address("T0"), address("T7"), &problem), 2);
}

TEST(LadderGrid, ReplaceDeviceKeepsConstants) {
    Rung r(1, 1);
    put(r, 0, 0, "X0");
    r.outputs[0] = outputOf("TMR T0 K10");
    std::vector<Rung> rungs = {r};
    const Address t0 = std::get<Address>(parseAddress(vigor(), QStringLiteral("T0")));
    const Address t1 = std::get<Address>(parseAddress(vigor(), QStringLiteral("T1")));
    EXPECT_EQ(replaceDevice(rungs, vigor(), t0, t1), 1);
    ASSERT_EQ(rungs[0].outputs[0]->operands.size(), 2u);
    EXPECT_EQ(formatOperand(vigor(), rungs[0].outputs[0]->operands[0]), QStringLiteral("T1"));
    EXPECT_EQ(formatOperand(vigor(), rungs[0].outputs[0]->operands[1]), QStringLiteral("K10"));
}
