// The compare operators: one table of how listings write them (model/target/target.cpp) and
// one evaluation, read by the parser, the ladder text, the targets' tables, the trigger, the
// simulator and the monitor's power flow.

#include "model/image/trigger.h"
#include "model/ladder/ladder_text.h"
#include "model/target/target.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

TEST(CompareOperators, EachSymbolReadsBackAsItsOperator) {
    for (const CompareOp op : kCompareOps) {
        const QString symbol = QString::fromLatin1(compareSymbol(op));
        const std::optional<CompareAt> found =
            findCompare(QStringLiteral("D0") + symbol + QStringLiteral("D1"));
        ASSERT_TRUE(found.has_value()) << symbol.toStdString();
        EXPECT_EQ(found->op, op) << symbol.toStdString();
        EXPECT_EQ(found->at, 2);
        EXPECT_EQ(found->length, symbol.size());
    }
    EXPECT_STREQ(compareSymbol(CompareOp::None), "");
}

TEST(CompareOperators, TheLongestSymbolWinsAndTheReversedOnesRead) {
    EXPECT_EQ(findCompare(u"D0<=K5")->op, CompareOp::Le);
    EXPECT_EQ(findCompare(u"D0>=K5")->op, CompareOp::Ge);
    EXPECT_EQ(findCompare(u"D0<>K5")->op, CompareOp::Ne);
    // VPC listings write "=<" and "=>" too.
    EXPECT_EQ(findCompare(u"p01=<p00")->op, CompareOp::Le);
    EXPECT_EQ(findCompare(u"p01=>p00")->length, 2);
    EXPECT_EQ(findCompare(u"p01=>p00")->op, CompareOp::Ge);
    // No left operand, no operator.
    EXPECT_FALSE(findCompare(u"<D0").has_value());
    EXPECT_FALSE(findCompare(u"X0").has_value());
}

TEST(CompareOperators, HoldAsArithmeticSays) {
    struct Case {
        CompareOp op;
        bool less, equal, greater; // 1 op 2, 2 op 2, 3 op 2
    };
    const Case cases[] = {{CompareOp::Eq, false, true, false},   {CompareOp::Ne, true, false, true},
                          {CompareOp::Lt, true, false, false},   {CompareOp::Le, true, true, false},
                          {CompareOp::Gt, false, false, true},   {CompareOp::Ge, false, true, true},
                          {CompareOp::None, false, false, false}};
    for (const Case &c : cases) {
        EXPECT_EQ(compareHolds(c.op, 1, 2), c.less) << compareSymbol(c.op);
        EXPECT_EQ(compareHolds(c.op, 2, 2), c.equal) << compareSymbol(c.op);
        EXPECT_EQ(compareHolds(c.op, 3, 2), c.greater) << compareSymbol(c.op);
    }
    EXPECT_TRUE(compareHolds(CompareOp::Lt, -32768, 32767));
}

TEST(CompareOperators, TheLadderTextAndTheTriggerReadTheListingsSpellings) {
    // One table: what a listing reads, a drawn compare contact and a trigger read too.
    const Target &t = rung::testing::vigor();
    QString error;
    const std::optional<Contact> c = contactFromText(t, QStringLiteral("D0=<K10"), &error);
    ASSERT_TRUE(c.has_value()) << error.toStdString();
    EXPECT_EQ(c->compare, CompareOp::Le);
    EXPECT_EQ(contactToText(t, *c), QStringLiteral("D0<=K10"));
    const auto trigger = parseTrigger(t, QStringLiteral("D10 => 100"));
    ASSERT_TRUE(std::holds_alternative<Trigger>(trigger));
    EXPECT_EQ(std::get<Trigger>(trigger).op, CompareOp::Ge);
    EXPECT_EQ(formatTrigger(t, std::get<Trigger>(trigger)), QStringLiteral("D10 >= 100"));
}
