// Branch points: how each target holds one (VPC IL/ILC, CPM1 IL(02)/ILC(03), Vigor
// MPS/MRD/MPP), and random branching ladders whose contacts read the rung's own coils.

#include "convert_test_util.h"
#include "random_program.h"

#include "model/ladder/network.h"

#include <gtest/gtest.h>

using namespace rung::model;
using namespace rung::model::test;

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
    // Every contact here reads a coil of the rung, so refusals are frequent where the listing
    // cannot hold a branch point: none with MPS, a minority with IL/ILC, and even on the PL110
    // (neither) a good share converts (409 of 500 refused when this was written).
    if (target.limits.allowsStack) {
        EXPECT_EQ(refused, 0);
    } else {
        EXPECT_LT(refused, target.findInstruction(Op::Interlock) ? 250 : 450);
    }
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
