#include "random_program.h"

#include "model/convert.h"
#include "model/ladder_text.h"
#include "model/logic.h"
#include "model/network.h"

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

namespace {

InstructionList parse(Family family, const QString &text) {
    ParseResult r = parseInstructionList(Target::get(family), text);
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? std::string()
                                             : QStringLiteral("%1:%2: %3")
                                                   .arg(r.errors[0].line)
                                                   .arg(r.errors[0].column)
                                                   .arg(r.errors[0].message)
                                                   .toStdString())
                        << "\n"
                        << text.toStdString();
    return r.list;
}

QString problemsOf(const std::vector<Diagnostic> &ds) {
    QString s;
    for (const Diagnostic &d : ds)
        s += QStringLiteral("%1 line %2 rung %3: %4\n")
                 .arg(d.code)
                 .arg(d.location.line)
                 .arg(d.location.rung)
                 .arg(d.message);
    return s;
}

// IL -> ladder -> IL, printed.
QString roundTrip(const InstructionList &list, LadderProgram *ladder = nullptr) {
    ToLadderResult lad = listToLadder(list);
    EXPECT_TRUE(lad.ok()) << problemsOf(lad.problems).toStdString();
    ToListingResult back = ladderToList(lad.ladder);
    EXPECT_TRUE(back.ok()) << problemsOf(back.problems).toStdString();
    if (ladder)
        *ladder = lad.ladder;
    return printInstructionList(back.list);
}

QString canonical(Family family, const QString &text) {
    return roundTrip(parse(family, text));
}

QString lines(std::initializer_list<const char *> ls) {
    QString s;
    for (const char *l : ls)
        s += QString::fromLatin1(l) + QLatin1Char('\n');
    return s;
}

// ladder-rules.md, "Execution order example (seed 004, 1.5.1)", verbatim.
const char *kExecutionOrder =
    "LD X0\nOR M0\nAND X1\nLD X3\nAND M1\nORB\nLD Y1\nAND X4\nLD T0\nAND M3\n"
    "ORB\nANB\nOUT Y1\nTMR T0 K10\n";

} // namespace

TEST(Conversion, ExecutionOrderExampleIsAlreadyCanonical) {
    const QString text = QString::fromLatin1(kExecutionOrder);
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
    // seed 004 1.7 example 1: "OK" form in, "better" form out.
    const QString ok =
        lines({"LD X0", "OR X1", "LD X2", "OR X3", "LD X4", "OR X5", "ANB", "ANB", "OUT Y0"});
    const QString better =
        lines({"LD X0", "OR X1", "LD X2", "OR X3", "ANB", "LD X4", "OR X5", "ANB", "OUT Y0"});
    EXPECT_EQ(canonical(Family::Vigor, ok), better);
    EXPECT_EQ(canonical(Family::Vigor, better), better);
}

TEST(Conversion, StackedOrbBecomesAnOrChain) {
    // seed 004 1.7 example 2: "bad" form in, "good" form out.
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

// ---- properties over random programs --------------------------------------------------------

namespace {

std::set<Address> devicesRead(const InstructionList &list) {
    std::set<Address> out;
    for (const Instruction &i : list.instructions)
        for (const Operand &o : i.operands)
            if (o.kind == Operand::Kind::Device)
                out.insert(o.address);
    return out;
}

void checkProgram(const Target &target, const QString &text, std::uint64_t seed) {
    SCOPED_TRACE(
        QStringLiteral("target %1 seed %2\n%3").arg(target.id).arg(seed).arg(text).toStdString());
    ParseResult parsed = parseInstructionList(target, text);
    ASSERT_TRUE(parsed.ok()) << parsed.errors[0].line << ": "
                             << parsed.errors[0].message.toStdString();
    ToLadderResult lad1 = listToLadder(parsed.list);
    ASSERT_TRUE(lad1.ok()) << problemsOf(lad1.problems).toStdString();
    ToListingResult il1 = ladderToList(lad1.ladder);
    ASSERT_TRUE(il1.ok()) << problemsOf(il1.problems).toStdString();
    ToLadderResult lad2 = listToLadder(il1.list);
    ASSERT_TRUE(lad2.ok()) << problemsOf(lad2.problems).toStdString();
    ToListingResult il2 = ladderToList(lad2.ladder);
    // Fixpoint after the first pass.
    ASSERT_EQ(printInstructionList(il2.list), printInstructionList(il1.list));
    ASSERT_EQ(lad2.ladder.rungs.size(), lad1.ladder.rungs.size());
    for (std::size_t r = 0; r < lad1.ladder.rungs.size(); ++r)
        ASSERT_TRUE(lad1.ladder.rungs[r] == lad2.ladder.rungs[r])
            << "rung " << r << "\n"
            << printLadderText(lad1.ladder).toStdString()
            << printLadderText(lad2.ladder).toStdString()
            << printInstructionList(il1.list).toStdString();
    // Same meaning: the listing, its ladder and the canonical listing agree on every output.
    const std::set<Address> devices = devicesRead(parsed.list);
    const std::vector<Address> order(devices.begin(), devices.end());
    const int n = static_cast<int>(order.size());
    // Exhaustive for small programs; above that random cases, enough over 2000 programs a
    // target while keeping the Debug run short.
    const bool exhaustive = n <= 5;
    const int cases = exhaustive ? 1 << n : 24;
    std::mt19937_64 rng(seed);
    for (int k = 0; k < cases; ++k) {
        const std::uint64_t bits = exhaustive ? static_cast<std::uint64_t>(k) : rng();
        const BitReader read = [&](const Address &a) {
            const auto it = std::lower_bound(order.begin(), order.end(), a);
            const auto i = static_cast<std::size_t>(it - order.begin());
            return ((bits >> (i % 64)) & 1u) != 0;
        };
        const OutputImage a = evaluateList(parsed.list, read);
        const OutputImage b = evaluateLadder(lad1.ladder, read);
        const OutputImage c = evaluateList(il1.list, read);
        ASSERT_EQ(a, b) << "case " << k << "\n" << printLadderText(lad1.ladder).toStdString();
        ASSERT_EQ(a, c) << "case " << k;
    }
}

} // namespace

// The seed examples of ladder-rules.md (the execution-order program, the fuzzy pairs of seed
// 004 1.7 and 1.8) and the design examples of seed 004 1.9 (their listings are drawings in
// the manual; written here from the text).
TEST(SeedExamples, RoundTripIsAFixpointAndKeepsMeaning) {
    const Target &t = Target::get(Family::Vigor);
    const std::vector<const char *> programs = {
        kExecutionOrder,
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

// Seed 004 1.8: each correction draws a different ladder with the same meaning.
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

namespace {

// The auditor's rung: i00 and r05 in series, then (i01 -> OUT r05) over (i02 -> OUT o01).
const char *kVpcBranchLadder = "LADDER vpc WIDTH 12\n"
                               "RUNG 1 ROWS 2 COLUMNS 3\n"
                               "|-[ i00    ]---[ r05    ]-+-[ i01    ]--(OUT r05)\n"
                               "|                         |\n"
                               "|                         +-[ i02    ]--(OUT o01)\n";

LadderProgram ladderFromText(Family family, const QString &text) {
    LadderTextResult r = parseLadderText(Target::get(family), text);
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? std::string() : r.errors[0].message.toStdString());
    return r.ladder;
}

Address addr(Family family, const char *name) {
    return std::get<Address>(parseAddress(Target::get(family), QString::fromLatin1(name)));
}

} // namespace

TEST(Conversion, VpcHoldsABranchPointWithAnInterlockWhenABranchChangesIt) {
    const LadderProgram ladder = ladderFromText(Family::Vpc, QString::fromLatin1(kVpcBranchLadder));
    const ToListingResult list = ladderToList(ladder);
    ASSERT_TRUE(list.ok()) << problemsOf(list.problems).toStdString();
    EXPECT_EQ(printInstructionList(list.list),
              lines({"LD i00", "AND r05", "IL", "LD i01", "OUT r05", "LD i02", "OUT o01", "ILC"}));
    // i00 = r05 = i02 = 1, i01 = 0: the branch point is ON, so o01 is ON and r05 goes OFF.
    const std::set<Address> on = {addr(Family::Vpc, "i00"), addr(Family::Vpc, "r05"),
                                  addr(Family::Vpc, "i02")};
    const BitReader read = [&](const Address &a) { return on.count(a) > 0; };
    const OutputImage expected = {{addr(Family::Vpc, "r05"), false},
                                  {addr(Family::Vpc, "o01"), true}};
    EXPECT_EQ(evaluateLadder(ladder, read), expected);
    EXPECT_EQ(evaluateList(list.list, read), expected);
    checkProgram(Target::get(Family::Vpc), printInstructionList(list.list), 3);
}

TEST(Conversion, CpmHoldsABranchPointWithAnInterlockWhenABranchChangesIt) {
    QString text = QString::fromLatin1(kVpcBranchLadder);
    text.replace(QStringLiteral("LADDER vpc"), QStringLiteral("LADDER cpm1"))
        .replace(QStringLiteral("i00   "), QStringLiteral("000.00"))
        .replace(QStringLiteral("i01   "), QStringLiteral("000.01"))
        .replace(QStringLiteral("i02   "), QStringLiteral("000.02"))
        .replace(QStringLiteral("r05   "), QStringLiteral("200.05"))
        .replace(QStringLiteral("(OUT r05)"), QStringLiteral("(OUT 200.05)"))
        .replace(QStringLiteral("(OUT o01)"), QStringLiteral("(OUT 010.01)"));
    const LadderProgram ladder = ladderFromText(Family::Cpm1, text);
    const ToListingResult list = ladderToList(ladder);
    ASSERT_TRUE(list.ok()) << problemsOf(list.problems).toStdString();
    EXPECT_EQ(printInstructionList(list.list),
              lines({"LD 000.00", "AND 200.05", "IL(02)", "LD 000.01", "OUT 200.05", "LD 000.02",
                     "OUT 010.01", "ILC(03)"}));
    checkProgram(Target::get(Family::Cpm1), printInstructionList(list.list), 4);
}

TEST(Conversion, AnOutputAfterABranchInsideTheInterlockLoadsAlwaysOn) {
    // i00 & r05, then (i01 -> OUT r05), then OUT o02 straight on the branch point.
    const QString text = QStringLiteral("LADDER vpc WIDTH 12\n"
                                        "RUNG 1 ROWS 2 COLUMNS 3\n"
                                        "|-[ i00    ]---[ r05    ]-+-[ i01    ]--(OUT r05)\n"
                                        "|                         |\n"
                                        "|                         +-------------(OUT o02)\n");
    const ToListingResult list = ladderToList(ladderFromText(Family::Vpc, text));
    ASSERT_TRUE(list.ok()) << problemsOf(list.problems).toStdString();
    EXPECT_EQ(printInstructionList(list.list),
              lines({"LD i00", "AND r05", "IL", "LD i01", "OUT r05", "LD r88", "OUT o02", "ILC"}));
    checkProgram(Target::get(Family::Vpc), printInstructionList(list.list), 5);
}

TEST(Conversion, NoInterlockInsideTheProgramsOwnInterlock) {
    const Target &vpc = Target::get(Family::Vpc);
    LadderProgram ladder = ladderFromText(Family::Vpc, QString::fromLatin1(kVpcBranchLadder));
    const ToLadderResult il = listToLadder(parse(Family::Vpc, lines({"LD i10", "IL"})));
    const ToLadderResult ilc = listToLadder(parse(Family::Vpc, lines({"ILC"})));
    ASSERT_TRUE(il.ok() && ilc.ok());
    ladder.rungs.insert(ladder.rungs.begin(), il.ladder.rungs[0]);
    ladder.rungs.push_back(ilc.ladder.rungs[0]);
    const ToListingResult list = ladderToList(ladder);
    ASSERT_EQ(list.problems.size(), 1u) << printInstructionList(list.list).toStdString();
    EXPECT_EQ(list.problems[0].code, QStringLiteral("CV010"));
    EXPECT_EQ(list.problems[0].location.rung, 1);
    // Without the write-back the repeated condition is exact and allowed there.
    LadderProgram safe = ladder;
    Rung &r = safe.rungs[1];
    r.outputs[0]->operands[0].address = addr(Family::Vpc, "r06");
    const ToListingResult ok = ladderToList(safe);
    ASSERT_TRUE(ok.ok()) << problemsOf(ok.problems).toStdString();
    EXPECT_EQ(printInstructionList(ok.list),
              lines({"LD i10", "IL", "LD i00", "AND r05", "AND i01", "OUT r06", "LD i00", "AND r05",
                     "AND i02", "OUT o01", "ILC"}));
    (void)vpc;
}

// Random branching rungs drawn on the grid, for every target: the listing must mean what the
// ladder means even when a branch writes what the shared condition or a later branch reads.
namespace {

class BranchGenerator {
public:
    BranchGenerator(const Target &t, std::uint64_t seed)
        : m_t(t)
        , m_rng(seed) {
        const QString text = rung::testing::randomProgram(t, seed, {});
        const InstructionList list = parseInstructionList(t, text).list;
        for (const Instruction &i : list.instructions)
            for (const Operand &o : i.operands)
                if (o.kind == Operand::Kind::Device && i.spec->op == Op::Out && !i.spec->negated &&
                    std::find(m_coils.begin(), m_coils.end(), o.address) == m_coils.end())
                    m_coils.push_back(o.address);
        m_out = list;
    }

    bool usable() const { return m_coils.size() >= 4; }

    detail::RungLogic rung() {
        m_used = 0;
        detail::RungLogic logic;
        detail::Branch child = branch(2);
        detail::Branch::Item item;
        item.isOutput = false;
        item.child.push_back(child);
        logic.root.items.push_back(item);
        return logic;
    }

private:
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }

    detail::Expr leaf() {
        Contact c;
        Operand o;
        o.address = m_coils[static_cast<std::size_t>(pick(static_cast<int>(m_coils.size())))];
        c.operands = {o};
        c.mode = pick(4) == 0 ? ContactMode::Negated : ContactMode::Normal;
        return detail::Expr::leafOf(c);
    }

    detail::Expr cond(int n) {
        detail::Expr e = leaf();
        for (int i = 1; i < n; ++i)
            e = pick(3) == 0 ? detail::parallel(e, leaf()) : detail::series(e, leaf());
        return e;
    }

    detail::Branch branch(int depth) {
        detail::Branch b;
        b.cond = cond(1 + pick(2));
        const int items = 2 + pick(2);
        for (int i = 0; i < items; ++i) {
            detail::Branch::Item item;
            if (depth > 0 && pick(2) == 0) {
                item.isOutput = false;
                item.child.push_back(branch(depth - 1));
            } else {
                item.isOutput = true;
                item.output = outInstruction();
            }
            b.items.push_back(item);
        }
        return b;
    }

    Instruction outInstruction() {
        Instruction ins;
        ins.spec = m_t.findInstruction(Op::Out);
        Operand o;
        o.address = m_coils[m_used++ % m_coils.size()];
        ins.operands = {o};
        return ins;
    }

    const Target &m_t;
    std::mt19937_64 m_rng;
    std::vector<Address> m_coils;
    std::size_t m_used = 0;
    InstructionList m_out;
};

class BranchingLadders : public ::testing::TestWithParam<Family> {};

} // namespace

TEST_P(BranchingLadders, ListingMeansWhatTheLadderMeans) {
    const Target &target = Target::get(GetParam());
    int interlocked = 0;
    int refused = 0;
    for (std::uint64_t seed = 1; seed <= 500; ++seed) {
        BranchGenerator gen(target, seed);
        if (!gen.usable())
            continue;
        LadderProgram ladder;
        ladder.target = &target;
        for (int r = 0; r < 2; ++r)
            ladder.rungs.push_back(detail::layoutRung(gen.rung()));
        const ToListingResult list = ladderToList(ladder);
        if (!list.ok()) {
            // Only where no listing of the target can hold the branch point: refused, never
            // changed.
            ASSERT_FALSE(target.limits.allowsStack) << problemsOf(list.problems).toStdString();
            for (const Diagnostic &d : list.problems)
                ASSERT_EQ(d.code, QStringLiteral("CV010"));
            ++refused;
            continue;
        }
        const QString printed = printInstructionList(list.list);
        interlocked += printed.contains(QLatin1String("IL")) ? 1 : 0;
        SCOPED_TRACE(printLadderText(ladder).toStdString() + printed.toStdString());
        std::set<Address> devices = devicesRead(list.list);
        const std::vector<Address> order(devices.begin(), devices.end());
        std::mt19937_64 rng(seed);
        for (int k = 0; k < 32; ++k) {
            const std::uint64_t bits = rng();
            const BitReader read = [&](const Address &a) {
                const auto i = std::lower_bound(order.begin(), order.end(), a) - order.begin();
                return ((bits >> (i % 64)) & 1u) != 0;
            };
            const OutputImage fromLadder = evaluateLadder(ladder, read);
            const OutputImage fromList = evaluateList(list.list, read);
            if (fromLadder != fromList) {
                QString inputs;
                for (const Address &a : order)
                    inputs += formatAddress(target, a) + (read(a) ? "=1 " : "=0 ");
                QString diff;
                for (const auto &[a, v] : fromLadder)
                    diff += formatAddress(target, a) +
                            QStringLiteral(": ladder %1 list %2\n")
                                .arg(v)
                                .arg(fromList.count(a) ? fromList.at(a) : -1);
                FAIL() << inputs.toStdString() << "\n" << diff.toStdString();
            }
        }
        checkProgram(target, printed, seed);
        if (::testing::Test::HasFatalFailure())
            return;
    }
    if (!target.limits.allowsStack && target.findInstruction(Op::Interlock)) {
        EXPECT_GT(interlocked, 50); // the interesting case does occur
    }
    // Every contact here reads a coil of the rung, so refusals are frequent; they stay a
    // minority where IL/ILC exist.
    EXPECT_LT(refused, target.findInstruction(Op::Interlock) ? 250 : 500);
}

INSTANTIATE_TEST_SUITE_P(AllTargets, BranchingLadders,
                         ::testing::Values(Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110),
                         [](const auto &info) { return Target::get(info.param).id.toStdString(); });

TEST(Conversion, ABlockJoinedToTheAccumulatorAfterAnOutputStaysInItsRung) {
    // After OUT Y0 the accumulator still holds X0: the block (X1 | X2) is AND LD'ed to it.
    const QString text = lines({"LD X0", "OUT Y0", "LD X1", "OR X2", "ANB", "OUT Y1"});
    LadderProgram ladder;
    EXPECT_EQ(roundTrip(parse(Family::Vigor, text), &ladder), text);
    EXPECT_EQ(ladder.rungs.size(), 1u);
    checkProgram(Target::get(Family::Vigor), text, 6);
    // A load that nothing joins to the accumulator still starts the next rung.
    const QString two = lines({"LD X0", "OUT Y0", "LD X1", "OR X2", "OUT Y1"});
    EXPECT_EQ(roundTrip(parse(Family::Vigor, two), &ladder), two);
    EXPECT_EQ(ladder.rungs.size(), 2u);
}

TEST(Conversion, ABlockOredWithABranchPointsConditionIsRefusedNotRedrawn) {
    // Y1 = X0 & X2 | X3 & X4: the X3 & X4 path starts at the rail, beside the branch point.
    const ToLadderResult bad =
        listToLadder(parse(Family::Vigor, lines({"LD X0", "MPS", "AND X1", "OUT Y0", "MPP",
                                                 "AND X2", "LD X3", "AND X4", "ORB", "OUT Y1"})));
    ASSERT_EQ(bad.problems.size(), 1u);
    EXPECT_EQ(bad.problems[0].code, QStringLiteral("CV009"));
    EXPECT_EQ(bad.problems[0].location.line, 9);
    const ToLadderResult orAfterOutput =
        listToLadder(parse(Family::Vigor, lines({"LD X0", "OUT Y0", "AND X1", "OR X2", "OUT Y1"})));
    ASSERT_EQ(orAfterOutput.problems.size(), 1u);
    EXPECT_EQ(orAfterOutput.problems[0].code, QStringLiteral("CV009"));
    // The same blocks AND LD'ed to the branch point draw as usual.
    const ToLadderResult good =
        listToLadder(parse(Family::Vigor, lines({"LD X0", "MPS", "AND X1", "OUT Y0", "MPP", "LD X3",
                                                 "OR X4", "ANB", "OUT Y1"})));
    EXPECT_TRUE(good.ok()) << problemsOf(good.problems).toStdString();
}

TEST(Conversion, VigorBranchReadingTheCoilOfTheBranchAboveKeepsItsOrder) {
    // M0 is written by the first branch and read by the second: the ladder means the
    // listing's order (row order), never the value from before the rung.
    const QString text = lines({"LD X0", "MPS", "AND X1", "OUT M0", "MPP", "AND M0", "OUT Y0"});
    checkProgram(Target::get(Family::Vigor), text, 7);
    const Target &t = Target::get(Family::Vigor);
    const InstructionList list = parse(Family::Vigor, text);
    const ToLadderResult lad = listToLadder(list);
    ASSERT_TRUE(lad.ok());
    // X0 = X1 = 1, M0 = 0 before the scan: M0 goes ON, so Y0 follows it in the same pass.
    const std::set<Address> on = {addr(Family::Vigor, "X0"), addr(Family::Vigor, "X1")};
    const BitReader read = [&](const Address &a) { return on.count(a) > 0; };
    EXPECT_TRUE(evaluateLadder(lad.ladder, read).at(addr(Family::Vigor, "Y0")));
    EXPECT_TRUE(evaluateList(list, read).at(addr(Family::Vigor, "Y0")));
    (void)t;
}
