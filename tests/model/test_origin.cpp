#include "convert_test_util.h"
#include "random_program.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <gtest/gtest.h>

// The origin map of ladder -> IL (ToListingResult::origin): every instruction names the cell
// it was written from, which the simulation overlay reads to draw each instruction's power
// flow on its cell.

using namespace rung::model;
using rung::model::test::parse;
using rung::model::test::problemsOf;

namespace {

// Every contact maps to a cell holding that contact (same instruction, same devices), every
// output to its row's output, everything else to its rung; every output of a rung is written
// exactly once. onCells counts the instructions checked against a cell.
void expectOriginsHold(const LadderProgram &ladder, const ToListingResult &listed,
                       const std::string &what, int *onCells = nullptr) {
    const auto &ins = listed.list.instructions;
    ASSERT_EQ(listed.origin.size(), ins.size()) << what;
    const Target &t = *ladder.target;
    const Address alwaysOn = systemAddress(t, SystemRole::AlwaysOn);
    int cells = 0;
    for (std::size_t r = 0; r + 1 < listed.rungFirst.size(); ++r) {
        const Rung &rung = ladder.rungs[r];
        std::vector<int> outputsWritten(static_cast<std::size_t>(rung.rows), 0);
        for (int i = listed.rungFirst[r]; i < listed.rungFirst[r + 1]; ++i) {
            const Instruction &instruction = ins[static_cast<std::size_t>(i)];
            const CellOrigin &o = listed.origin[static_cast<std::size_t>(i)];
            const std::string where = what + " rung " + std::to_string(r) + " instruction " +
                                      std::to_string(i) + " " +
                                      printInstruction(t, instruction).toStdString();
            EXPECT_EQ(o.rung, static_cast<int>(r)) << where;
            const Op op = instruction.op();
            if (isContact(op) || op == Op::Invert) {
                if (o.row < 0) {
                    // Only the always-ON load an interlock writes comes from no cell.
                    ASSERT_EQ(instruction.operands.size(), 1u) << where;
                    EXPECT_EQ(instruction.operands[0].address, alwaysOn) << where;
                    EXPECT_EQ(op, Op::Load) << where;
                    continue;
                }
                ASSERT_LT(o.row, rung.rows) << where;
                ASSERT_GE(o.column, 0) << where;
                ASSERT_LT(o.column, rung.columns) << where;
                const Cell &cell = rung.cell(o.row, o.column);
                ASSERT_EQ(cell.kind, CellKind::Contact) << where;
                EXPECT_EQ(cell.contact.invert, op == Op::Invert) << where;
                if (op != Op::Invert) {
                    EXPECT_EQ(cell.contact.operands, instruction.operands) << where;
                    EXPECT_EQ(cell.contact.mode, instruction.spec->mode) << where;
                    EXPECT_EQ(cell.contact.compare, instruction.spec->compare) << where;
                }
                ++cells;
            } else if (joinsBlocks(op) || isStackOp(op)) {
                EXPECT_EQ(o.row, -1) << where;
                EXPECT_EQ(o.column, -1) << where;
            } else if (o.row < 0) {
                // A generated interlock holding a branch point.
                EXPECT_TRUE(op == Op::Interlock || op == Op::InterlockClear) << where;
            } else {
                ASSERT_LT(o.row, rung.rows) << where;
                EXPECT_EQ(o.column, rung.columns) << where;
                const auto &out = rung.outputs[static_cast<std::size_t>(o.row)];
                ASSERT_TRUE(out.has_value()) << where;
                EXPECT_TRUE(out->sameAs(instruction)) << where;
                ++outputsWritten[static_cast<std::size_t>(o.row)];
                ++cells;
            }
        }
        for (int row = 0; row < rung.rows; ++row) {
            if (rung.outputs[static_cast<std::size_t>(row)]) {
                EXPECT_EQ(outputsWritten[static_cast<std::size_t>(row)], 1)
                    << what << " rung " << r << " row " << row;
            }
        }
    }
    if (onCells)
        *onCells = cells;
}

void checkListing(const Target &t, const QString &text, const std::string &what) {
    const ToLadderResult lad = listToLadder(parse(t.family, text));
    ASSERT_TRUE(lad.ok()) << what << problemsOf(lad.problems).toStdString();
    const ToListingResult listed = ladderToList(lad.ladder);
    ASSERT_TRUE(listed.ok()) << what << problemsOf(listed.problems).toStdString();
    int onCells = 0;
    expectOriginsHold(lad.ladder, listed, what, &onCells);
    EXPECT_GT(onCells, 0) << what;
}

} // namespace

TEST(OriginMap, AHandWrittenRungNamesItsCells) {
    // X0 ( X1 | X2 ) -> Y0, then X3 -> Y1 below the branch point X0.
    const ToLadderResult lad = listToLadder(
        parse(Family::Vigor, QStringLiteral("LD X0\nMPS\nLD X1\nOR X2\nANB\nOUT Y0\nMPP\nAND X3\n"
                                            "OUT Y1\nEND")));
    ASSERT_TRUE(lad.ok());
    const ToListingResult listed = ladderToList(lad.ladder);
    ASSERT_TRUE(listed.ok());
    ASSERT_EQ(printInstructionList(listed.list),
              QStringLiteral("LD X0\nMPS\nLD X1\nOR X2\nANB\nOUT Y0\nMPP\nAND X3\nOUT Y1\nEND\n"));
    const int columns = lad.ladder.rungs[0].columns;
    const std::vector<CellOrigin> expected = {
        {0, 0, 0},       {0, -1, -1}, {0, 0, 1}, {0, 1, 1},       {0, -1, -1},
        {0, 0, columns}, {0, -1, -1}, {0, 2, 1}, {0, 2, columns}, {1, 0, 0},
    };
    ASSERT_EQ(listed.origin.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(listed.origin[i].rung, expected[i].rung) << i;
        EXPECT_EQ(listed.origin[i].row, expected[i].row) << i;
        EXPECT_EQ(listed.origin[i].column, expected[i].column) << i;
    }
}

TEST(OriginMap, RandomProgramsOfEveryTarget) {
    for (Family f : {Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110}) {
        const Target &t = Target::get(f);
        for (std::uint64_t seed = 1; seed <= 300; ++seed) {
            rung::testing::RandomProgramOptions options;
            options.extended = seed % 2 == 0;
            checkListing(t, rung::testing::randomProgram(t, seed, options),
                         t.id.toStdString() + " seed " + std::to_string(seed));
        }
    }
}

TEST(OriginMap, TheTestDataListings) {
    int files = 0;
    for (const char *sub : {"il", "sim"}) {
        QDir dir(QStringLiteral(RUNG_TEST_DATA_DIR "/") + QLatin1String(sub));
        for (const QString &name : dir.entryList({QStringLiteral("*.il")}, QDir::Files)) {
            QFile file(dir.filePath(name));
            ASSERT_TRUE(file.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(file.readAll());
            QString id = declaredTarget(text);
            if (id.isEmpty())
                id = name.section(QLatin1Char('_'), 0, 0);
            const Target *t = Target::byId(id);
            ASSERT_NE(t, nullptr) << name.toStdString();
            checkListing(*t, text, name.toStdString());
            ++files;
        }
    }
    EXPECT_GE(files, 25);
}

// An interlock the converter writes to hold a branch point belongs to the rung, and the
// always-ON load inside it to no cell (the audited rung of test_convert_branches.cpp).
TEST(OriginMap, AGeneratedInterlockBelongsToItsRung) {
    const LadderTextResult lad =
        parseLadderText(Target::get(Family::Vpc),
                        QStringLiteral("LADDER vpc WIDTH 12\n"
                                       "RUNG 1 ROWS 3 COLUMNS 3\n"
                                       "|-[ i00    ]---[ r05    ]-+-[ i01    ]--(OUT r05)\n"
                                       "|                         |\n"
                                       "|                         +-[ i02    ]--(OUT o01)\n"
                                       "|                         |\n"
                                       "|                         +-------------(OUT o02)\n"));
    ASSERT_TRUE(lad.ok()) << lad.errors[0].message.toStdString();
    const ToListingResult listed = ladderToList(lad.ladder);
    ASSERT_TRUE(listed.ok()) << problemsOf(listed.problems).toStdString();
    ASSERT_EQ(printInstructionList(listed.list),
              QStringLiteral("LD i00\nAND r05\nIL\nLD i01\nOUT r05\nLD i02\nOUT o01\nLD r88\n"
                             "OUT o02\nILC\n"));
    EXPECT_EQ(listed.origin[2], (CellOrigin{0, -1, -1})); // IL
    EXPECT_EQ(listed.origin[7], (CellOrigin{0, -1, -1})); // LD r88
    EXPECT_EQ(listed.origin[8], (CellOrigin{0, 2, 3}));   // OUT o02: row 2, the output column
    EXPECT_EQ(listed.origin[9], (CellOrigin{0, -1, -1})); // ILC
    expectOriginsHold(lad.ladder, listed, "vpc interlock");
}
