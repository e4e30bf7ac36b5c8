#include "convert_test_util.h"
#include "model/checks/checks.h"
#include "model/listing/structure.h"
#include "random_program.h"

#include <gtest/gtest.h>

// The one listing structure (model/listing/structure.h): rungs, block pairs, stack limits,
// and that the converter and the checks read a listing with it.

using namespace rung::model;
using rung::model::test::parse;

namespace {

QString text(const char *semicolonSeparated) {
    return QString::fromLatin1(semicolonSeparated).replace(QLatin1Char(';'), QLatin1Char('\n'));
}

std::vector<RungSpan> spans(Family family, const char *listing) {
    return rungSpans(parse(family, text(listing)).instructions);
}

std::vector<Diagnostic> check(Family family, const char *listing) {
    return checkList(parse(family, text(listing)));
}

bool has(const std::vector<Diagnostic> &ds, const char *code) {
    return std::any_of(ds.begin(), ds.end(),
                       [&](const Diagnostic &d) { return d.code == QLatin1String(code); });
}

} // namespace

TEST(RungSpans, ALoadAfterAnOutputStartsARung) {
    // 0 LD 1 OUT 2 LD 3 AND 4 OUT 5 END
    EXPECT_EQ(spans(Family::Vigor, "LD X0;OUT Y0;LD X1;AND X2;OUT Y1;END"),
              (std::vector<RungSpan>{{0, 2}, {2, 5}, {5, 6}}));
}

TEST(RungSpans, AnOutputAfterAnOutputContinuesTheRung) {
    EXPECT_EQ(spans(Family::Vigor, "LD X0;OUT Y0;AND X1;OUT Y1;END"),
              (std::vector<RungSpan>{{0, 4}, {4, 5}}));
}

TEST(RungSpans, APendingMpsKeepsTheBranchInItsRung) {
    // MPP LD X2 ANB continues the branch: one rung until END.
    EXPECT_EQ(spans(Family::Vigor, "LD X0;MPS;AND X1;OUT Y0;MPP;LD X2;ANB;OUT Y1;LD X3;OUT Y2"),
              (std::vector<RungSpan>{{0, 8}, {8, 10}}));
}

TEST(RungSpans, ABlockJoinedToTheAccumulatorContinuesTheRung) {
    EXPECT_EQ(spans(Family::Vigor, "LD X0;OUT Y0;LD X1;OR X2;ANB;OUT Y1;LD X3;OUT Y2"),
              (std::vector<RungSpan>{{0, 6}, {6, 8}}));
}

TEST(RungSpans, InstructionsWithoutAConditionStandAlone) {
    EXPECT_EQ(spans(Family::Vpc, "LD i00;IL;LD i01;OUT o00;ILC;LD i02;JMP;JPE;END"),
              (std::vector<RungSpan>{{0, 2}, {2, 4}, {4, 5}, {5, 7}, {7, 8}, {8, 9}}));
}

TEST(RungSpans, SpanOfFindsTheRungOfAnInstruction) {
    const std::vector<RungSpan> s = spans(Family::Vigor, "LD X0;OUT Y0;LD X1;AND X2;OUT Y1;END");
    EXPECT_EQ(spanOf(s, 0), (RungSpan{0, 2}));
    EXPECT_EQ(spanOf(s, 3), (RungSpan{2, 5}));
    EXPECT_EQ(spanOf(s, 5), (RungSpan{5, 6}));
    EXPECT_EQ(spanOf(s, 9), (RungSpan{9, 10})); // beyond the listing: a span of its own
}

// The converter draws one rung per span, starting on the span's first line: over random
// programs of every target. Not only the count (the converter cuts the list with these very
// spans): each span converted on its own gives one rung, the same rung the whole list gives.
TEST(RungSpans, TheConverterDrawsOneRungPerSpan) {
    for (Family f : {Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110}) {
        const Target &t = Target::get(f);
        for (std::uint64_t seed = 1; seed <= 200; ++seed) {
            const InstructionList list = parse(f, rung::testing::randomProgram(t, seed));
            const std::vector<RungSpan> s = rungSpans(list.instructions);
            const ToLadderResult lad = listToLadder(list);
            ASSERT_TRUE(lad.ok()) << seed;
            ASSERT_EQ(lad.rungLine.size(), s.size()) << t.id.toStdString() << " seed " << seed;
            ASSERT_EQ(lad.ladder.rungs.size(), s.size()) << t.id.toStdString() << " seed " << seed;
            for (std::size_t k = 0; k < s.size(); ++k) {
                EXPECT_EQ(lad.rungLine[k],
                          list.instructions[static_cast<std::size_t>(s[k].first)].line);
                InstructionList alone;
                alone.target = list.target;
                alone.instructions.assign(list.instructions.begin() + s[k].first,
                                          list.instructions.begin() + s[k].last);
                const ToLadderResult one = listToLadder(alone);
                ASSERT_TRUE(one.ok()) << t.id.toStdString() << " seed " << seed << " span " << k;
                ASSERT_EQ(one.ladder.rungs.size(), 1u)
                    << t.id.toStdString() << " seed " << seed << " span " << k;
                EXPECT_TRUE(one.ladder.rungs.front() == lad.ladder.rungs[k])
                    << t.id.toStdString() << " seed " << seed << " span " << k;
            }
        }
    }
}

// Fixed by the one definition: the checks used to end the rung at the load after OUT Y0 and
// reported ST003 for a rung the converter draws (the load is joined to the branch by ANB).
TEST(RungSpans, TheChecksNoLongerEndARungWhoseBlockJoinsTheBranch) {
    const char *listing = "LD X0;MPS;AND X1;OUT Y0;LD X2;AND X3;ANB;OUT Y1;MPP;OUT Y2;END";
    EXPECT_TRUE(listToLadder(parse(Family::Vigor, text(listing))).ok());
    const auto found = check(Family::Vigor, listing);
    EXPECT_FALSE(has(found, "ST003")) << rung::model::test::problemsOf(found).toStdString();
    // An MPS really left open is still reported.
    EXPECT_TRUE(has(check(Family::Vigor, "LD X0;MPS;AND X1;OUT Y0;LD X2;OUT Y1;END"), "ST003"));
}

TEST(BlockPairs, PairsInterlocksAndNestedJumps) {
    // 0 LD 1 IL 2 LD 3 OUT 4 ILC 5 LD 6 JMP 7 LD 8 OUT 9 JPE 10 END
    const BlockPairs p = pairBlocks(
        parse(Family::Vpc, text("LD i00;IL;LD i01;OUT o00;ILC;LD i02;JMP;LD i03;OUT o01;JPE;END")));
    EXPECT_TRUE(p.problems.empty());
    EXPECT_EQ(p.partner[1], 4);
    EXPECT_EQ(p.partner[4], 1);
    EXPECT_EQ(p.partner[6], 9);
    EXPECT_EQ(p.partner[9], 6);
    EXPECT_EQ(p.partner[0], -1);
    EXPECT_EQ(p.end, 10);
}

TEST(BlockPairs, NumberedJumpsShareTheirEnd) {
    // CPM1: JMP 01 twice, one JME 01.
    const BlockPairs p = pairBlocks(
        parse(Family::Cpm1, text("LD 000.00;JMP(04) 01;LD 000.01;JMP(04) 01;LD 000.02;OUT 010.00;"
                                 "JME(05) 01;END(01)")));
    EXPECT_TRUE(p.problems.empty());
    EXPECT_EQ(p.partner[1], 6);
    EXPECT_EQ(p.partner[3], 6);
    EXPECT_EQ(p.partner[6], 1);
}

// Fixed by the one rule: a numbered JMP after its JME has no end to jump to. The simulator
// refused it; the checks let it pass.
TEST(BlockPairs, ANumberedJumpAfterItsEndIsReported) {
    const char *listing = "LD 000.00;JMP(04) 01;LD 000.01;OUT 010.00;JME(05) 01;"
                          "LD 000.02;JMP(04) 01;LD 000.03;OUT 010.01;END(01)";
    const BlockPairs p = pairBlocks(parse(Family::Cpm1, text(listing)));
    ASSERT_EQ(p.problems.size(), 1u);
    EXPECT_STREQ(p.problems[0].code, "NE004");
    EXPECT_EQ(p.problems[0].instruction, 6);
    EXPECT_EQ(p.problems[0].related, 4);
    EXPECT_TRUE(p.problems[0].aboutJump);
    const auto found = check(Family::Cpm1, listing);
    ASSERT_TRUE(has(found, "NE004"));
}

TEST(BlockPairs, NothingAfterEndIsPaired) {
    const BlockPairs p = pairBlocks(parse(Family::Vpc, text("LD i00;OUT o00;END;ILC")));
    EXPECT_TRUE(p.problems.empty());
    EXPECT_EQ(p.partner[3], -1);
}

TEST(StackLimits, EveryTargetsMpsLevelsFitTheSimulatorsStack) {
    for (Family f : {Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110}) {
        const Target &t = Target::get(f);
        EXPECT_GE(t.limits.stackDepth, 1) << t.id.toStdString();
        EXPECT_LE(t.limits.stackDepth, kMaxStackDepthOfAnyTarget) << t.id.toStdString();
    }
}
