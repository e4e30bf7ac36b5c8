#include "convert_test_util.h"
#include "random_program.h"

#include "logic_oracle.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/ladder/network.h"
#include "tests/model/listing_test_util.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>

#include <algorithm>
#include <cctype>
#include <random>
#include <set>

using namespace rung::model;
using namespace rung::model::test;

TEST(Conversion, ExecutionOrderExampleIsAlreadyCanonical) {
    const QString text = QString::fromLatin1(rung::testing::kExecutionOrderExample);
    LadderProgram ladder;
    EXPECT_EQ(roundTrip(parse(Family::Vigor, text), &ladder), text);
    ASSERT_EQ(ladder.rungs.size(), 1u);
    const Rung &r = ladder.rungs[0];
    // (X0 | M0) & X1 over X3 & M1, then the block (Y1 & X4 | T0 & M3): two parallel blocks.
    EXPECT_EQ(r.columns, 4);
    ASSERT_TRUE(r.outputs[0].has_value());
    EXPECT_EQ(printInstruction(Target::get(Family::Vigor), *r.outputs[0]),
              QStringLiteral("OUT Y1"));
    ASSERT_TRUE(r.outputs[1].has_value());
    EXPECT_EQ(printInstruction(Target::get(Family::Vigor), *r.outputs[1]),
              QStringLiteral("TMR T0 K10"));
}

TEST(Conversion, StackedAnbBecomesAnbAfterEachBlock) {
    // PLC concepts (WPLSoft family) 1.7 example 1: "OK" form in, "better" form out.
    const QString ok =
        lines({"LD X0", "OR X1", "LD X2", "OR X3", "LD X4", "OR X5", "ANB", "ANB", "OUT Y0"});
    const QString better =
        lines({"LD X0", "OR X1", "LD X2", "OR X3", "ANB", "LD X4", "OR X5", "ANB", "OUT Y0"});
    EXPECT_EQ(canonical(Family::Vigor, ok), better);
    EXPECT_EQ(canonical(Family::Vigor, better), better);
}

TEST(Conversion, StackedOrbBecomesAnOrChain) {
    // PLC concepts (WPLSoft family) 1.7 example 2: "bad" form in, "good" form out.
    const QString bad = lines({"LD X0", "LD X1", "LD X2", "LD X3", "ORB", "ORB", "ORB", "OUT Y0"});
    const QString good = lines({"LD X0", "OR X1", "OR X2", "OR X3", "OUT Y0"});
    EXPECT_EQ(canonical(Family::Vigor, bad), good);
    EXPECT_EQ(canonical(Family::Vigor, good), good);
}

TEST(Conversion, VigorBranchesUseMpsMrdMpp) {
    const QString text = lines(
        {"LD X0", "MPS", "AND X1", "OUT Y0", "MRD", "AND X2", "OUT Y1", "MPP", "AND X3", "OUT Y2"});
    EXPECT_EQ(canonical(Family::Vigor, text), text);
}

TEST(Conversion, OutputsAtTheBranchPointNeedNoStack) {
    const QString text = lines({"LD X0", "OUT Y0", "OUT Y1", "AND X1", "OUT Y2"});
    EXPECT_EQ(canonical(Family::Vigor, text), text);
    // The same written with MPS/MPP loses the needless stack instructions.
    const QString withStack =
        lines({"LD X0", "MPS", "OUT Y0", "MRD", "OUT Y1", "MPP", "AND X1", "OUT Y2"});
    EXPECT_EQ(canonical(Family::Vigor, withStack), text);
}

TEST(Conversion, VpcRepeatsTheConditionForEachBranch) {
    // VPC has no branch stack: the ladder's branch becomes one rung per path.
    const Target &vpc = Target::get(Family::Vpc);
    ParseResult vigorLike = parseInstructionList(
        vpc, lines({"LD i00", "AND i01", "OUT o00", "LD i00", "AND i02", "OUT o01"}));
    ASSERT_TRUE(vigorLike.ok());
    LadderProgram ladder;
    ladder.target = &vpc;
    // Draw the branch by hand: i00 then (i01 -> o00 | i02 -> o01).
    Rung r(2, 2);
    const auto dev = [&](const char *name) {
        Operand o;
        o.address = std::get<Address>(parseAddress(vpc, QString::fromLatin1(name)));
        return o;
    };
    r.cell(0, 0).kind = CellKind::Contact;
    r.cell(0, 0).contact.operands = {dev("i00")};
    r.cell(0, 1).kind = CellKind::Contact;
    r.cell(0, 1).contact.operands = {dev("i01")};
    r.cell(1, 1).kind = CellKind::Contact;
    r.cell(1, 1).contact.operands = {dev("i02")};
    r.setLink(0, 1, true);
    Instruction o0 = vigorLike.list.instructions[2];
    Instruction o1 = vigorLike.list.instructions[5];
    r.outputs[0] = o0;
    r.outputs[1] = o1;
    ladder.rungs.push_back(r);
    ToListingResult list = ladderToList(ladder);
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(printInstructionList(list.list), printInstructionList(vigorLike.list));
}

TEST(Conversion, CpmKeepTakesTwoBlocks) {
    const QString text =
        lines({"LD 000.00", "OR 010.00", "LD 000.01", "KEEP(11) 010.00", "END(01)"});
    LadderProgram ladder;
    EXPECT_EQ(roundTrip(parse(Family::Cpm1, text), &ladder), text);
    ASSERT_EQ(ladder.rungs.size(), 2u);
    EXPECT_EQ(ladder.rungs[0].boxInputRows(0), (std::vector<int>{0, 2}));
}

TEST(Conversion, FunctionCodeSpellingsMeanTheSameInstruction) {
    EXPECT_EQ(canonical(Family::Cpm1, lines({"LD 000.00", "LD 000.01", "KEEP 010.00", "END"})),
              lines({"LD 000.00", "LD 000.01", "KEEP(11) 010.00", "END(01)"}));
}

TEST(Conversion, RungCommentsTravelBothWays) {
    const QString text =
        lines({"; start the pump", "LD X0", "OUT Y0", "; stop it", "LD X1", "OUT Y1"});
    LadderProgram ladder;
    EXPECT_EQ(roundTrip(parse(Family::Vigor, text), &ladder), text);
    ASSERT_EQ(ladder.rungs.size(), 2u);
    EXPECT_EQ(ladder.rungs[1].comment, QStringLiteral("stop it"));
}

TEST(Conversion, BrokenListingReportsTheLine) {
    const InstructionList list =
        parse(Family::Vigor, lines({"LD X0", "ANB", "OUT Y0", "LD X1", "OUT Y1"}));
    ToLadderResult r = listToLadder(list);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.problems[0].location.line, 2);
    // The good rung after it is still drawn.
    ASSERT_EQ(r.ladder.rungs.size(), 1u);
    EXPECT_EQ(r.rungLine[0], 4);
}

TEST(Conversion, OpenBlockAtTheEndIsReported) {
    ToLadderResult r =
        listToLadder(parse(Family::Vigor, lines({"LD X0", "OUT Y0", "LD X1", "LD X2"})));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.problems.back().code, QStringLiteral("CV007"));
}

// The checks read a listing's problems without drawing it (listToLadderProblems): the same
// problems, in the same order, as the drawing finds, over random programs of every target
// with lines left out (most then have problems) and the manual's broken forms.
TEST(Conversion, ProblemsWithoutTheDrawingAreTheDrawingsProblems) {
    const auto same = [](const InstructionList &list) {
        const std::vector<Diagnostic> drawn = listToLadder(list).problems;
        const std::vector<Diagnostic> read = listToLadderProblems(list);
        EXPECT_EQ(read.size(), drawn.size());
        for (std::size_t k = 0; k < std::min(read.size(), drawn.size()); ++k) {
            EXPECT_EQ(read[k].code, drawn[k].code) << k;
            EXPECT_EQ(read[k].location.line, drawn[k].location.line) << k;
            EXPECT_EQ(read[k].location.column, drawn[k].location.column) << k;
            EXPECT_EQ(read[k].message, drawn[k].message) << k;
        }
        return drawn.size();
    };
    EXPECT_EQ(same(parse(Family::Vigor, lines({"LD X0", "ANB", "OUT Y0", "LD X1", "OUT Y1"}))), 1u);
    EXPECT_EQ(same(parse(Family::Vigor, lines({"LD X0", "OUT Y0", "LD X1", "LD X2"}))), 1u);
    std::size_t withProblems = 0;
    for (Family f : {Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110}) {
        const Target &t = Target::get(f);
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            rung::testing::RandomProgramOptions o;
            o.extended = seed % 2 == 0;
            QStringList text = rung::testing::randomProgram(t, seed, o).split(QLatin1Char('\n'));
            EXPECT_EQ(same(parse(f, text.join(QLatin1Char('\n')))), 0u) << seed;
            std::mt19937_64 random(seed);
            for (int cut = 0; cut < 3 && text.size() > 2; ++cut) {
                text.removeAt(
                    static_cast<qsizetype>(random() % static_cast<std::uint64_t>(text.size() - 1)));
                withProblems += same(parse(f, text.join(QLatin1Char('\n')))) > 0 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(withProblems, 100u); // of 360 cut listings: the broken paths are compared too
}

// The examples of PLC concepts (WPLSoft family) (the execution-order program of 1.5.1, the
// fuzzy pairs of 1.7 and 1.8) and its design examples of 1.9 (their listings are drawings in
// the manual; written here from the text).
TEST(SeedExamples, RoundTripIsAFixpointAndKeepsMeaning) {
    const Target &t = Target::get(Family::Vigor);
    const std::vector<const char *> programs = {
        rung::testing::kExecutionOrderExample,
        // 1.7 example 1, OK and better; example 2, bad and good.
        "LD X0\nOR X1\nLD X2\nOR X3\nLD X4\nOR X5\nANB\nANB\nOUT Y0\n",
        "LD X0\nOR X1\nLD X2\nOR X3\nANB\nLD X4\nOR X5\nANB\nOUT Y0\n",
        "LD X0\nLD X1\nLD X2\nLD X3\nORB\nORB\nORB\nOUT Y0\n",
        "LD X0\nOR X1\nOR X2\nOR X3\nOUT Y0\n",
        // 1.9: stop-first, start-first, SET/RST both orders, interlock, sequential control,
        // oscillator, timer oscillator, flasher, delay-off, counting range extension.
        "LD X1\nOR Y1\nANI X2\nOUT Y1\n",
        "LD X1\nLD Y1\nANI X2\nORB\nOUT Y1\n",
        "LD X1\nSET Y1\nLD X2\nRST Y1\n",
        "LD X2\nRST Y1\nLD X1\nSET Y1\n",
        "LD X1\nANI Y2\nOUT Y1\nLD X2\nANI Y1\nOUT Y2\n",
        "LD X1\nOR Y1\nANI Y2\nOUT Y1\nLD X2\nOR Y2\nAND Y1\nOUT Y2\n",
        "LDI Y1\nOUT Y1\n",
        "LD X0\nANI Y1\nTMR T0 K10\nLD T0\nOUT Y1\n",
        "LD X0\nANI T2\nTMR T1 K10\nLD T1\nTMR T2 K20\nLD X0\nANI T1\nOUT Y1\n",
        "LDI X0\nTMR T10 K1000\nLD X0\nOR Y1\nANI T10\nOUT Y1\n",
        "LD X13\nCNT C5 K100\nLD C5\nCNT C6 K50\nLD X12\nRST C5\nRST C6\n",
    };
    std::uint64_t seed = 1;
    for (const char *p : programs)
        checkProgram(t, QString::fromLatin1(p), seed++);
}

// PLC concepts (WPLSoft family) 1.8: each correction draws a different ladder with the same
// meaning.
TEST(SeedExamples, CorrectedFormsComputeTheSameOutputs) {
    const Target &t = Target::get(Family::Vigor);
    const std::vector<std::pair<const char *, const char *>> pairs = {
        // ex. 1: the block after a contact moves to the front, dropping an ANB.
        {"LD X0\nLD X1\nOR X2\nANB\nOUT Y0\n", "LD X1\nOR X2\nAND X0\nOUT Y0\n"},
        // ex. 2: the block goes first and the single device joins it with OR, dropping an ORB.
        {"LD X2\nLD X0\nAND X1\nORB\nOUT Y0\n", "LD X0\nAND X1\nOR X2\nOUT Y0\n"},
        // ex. 4: the output without extra contacts goes on top, dropping MPS/MPP.
        {"LD X0\nMPS\nAND X1\nOUT Y1\nMPP\nOUT Y0\n", "LD X0\nOUT Y0\nAND X1\nOUT Y1\n"},
    };
    for (const auto &[worse, better] : pairs) {
        const InstructionList a = parse(Family::Vigor, QString::fromLatin1(worse));
        const InstructionList b = parse(Family::Vigor, QString::fromLatin1(better));
        const std::set<Address> devices = devicesRead(a);
        const std::vector<Address> order(devices.begin(), devices.end());
        for (std::uint64_t bits = 0; bits < (1u << order.size()); ++bits) {
            const BitReader read = [&](const Address &x) {
                const auto i = std::lower_bound(order.begin(), order.end(), x) - order.begin();
                return ((bits >> i) & 1u) != 0;
            };
            EXPECT_EQ(evaluateList(a, read), evaluateList(b, read)) << worse;
        }
        checkProgram(t, QString::fromLatin1(worse), 1);
        checkProgram(t, QString::fromLatin1(better), 2);
    }
}

class RandomPrograms : public ::testing::TestWithParam<Family> {};

TEST_P(RandomPrograms, RoundTripIsAFixpointAndKeepsMeaning) {
    const Target &target = Target::get(GetParam());
    // >= 2000 programs per target (issue 2, section 9), four rungs each, kept fast.
    for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
        rung::testing::RandomProgramOptions o;
        o.rungs = 4;
        checkProgram(target, rung::testing::randomProgram(target, seed, o), seed);
        if (::testing::Test::HasFatalFailure())
            return;
    }
}

TEST_P(RandomPrograms, WithTimersEdgesComparesAndMovesTheRoundTripIsAFixpoint) {
    const Target &target = Target::get(GetParam());
    for (std::uint64_t seed = 1; seed <= 500; ++seed) {
        rung::testing::RandomProgramOptions o;
        o.rungs = 5;
        o.extended = true;
        checkProgram(target, rung::testing::randomProgram(target, seed, o), seed);
        if (::testing::Test::HasFatalFailure())
            return;
    }
}

INSTANTIATE_TEST_SUITE_P(AllTargets, RandomPrograms,
                         ::testing::Values(Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110),
                         [](const auto &info) { return Target::get(info.param).id.toStdString(); });

// ---- Every listing in the test data, for its target ----------------------------------------

namespace {

std::vector<std::string> dataListings() {
    std::vector<std::string> names;
    for (const char *sub : {"il", "sim"}) {
        QDir dir(QStringLiteral(RUNG_TEST_DATA_DIR "/") + QLatin1String(sub));
        for (const QString &name : dir.entryList({QStringLiteral("*.il")}, QDir::Files))
            names.push_back((QLatin1String(sub) + QLatin1Char('/') + name).toStdString());
    }
    return names;
}

class DataListings : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(DataListings, RoundTripIsAFixpointAndKeepsMeaning) {
    QFile file(QStringLiteral(RUNG_TEST_DATA_DIR "/") + QString::fromStdString(GetParam()));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(file.readAll());
    // The first line names the target ("; target: vigor"); otherwise the file name does.
    QString id = declaredTarget(text);
    if (id.isEmpty())
        id = QFileInfo(file.fileName()).fileName().section(QLatin1Char('_'), 0, 0);
    const Target *target = Target::byId(id);
    ASSERT_NE(target, nullptr);
    checkProgram(*target, text, 1);
}

INSTANTIATE_TEST_SUITE_P(TestData, DataListings, ::testing::ValuesIn(dataListings()),
                         [](const auto &info) {
                             std::string s = info.param;
                             for (char &c : s)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return s;
                         });

TEST(DataListingsFound, AtLeastTheSeedsAndTheSimulatorExamples) {
    EXPECT_GE(dataListings().size(), 25u);
}

// ---- Branches on targets without a branch stack ----------------------------------------------
