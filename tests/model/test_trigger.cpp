// Trigger conditions as the timing chart and breakpoints type them: "Y0 rises", "D10 > 100".

#include "model/image/trigger.h"
#include "model/target/address.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

using rung::testing::vigor;

Trigger parsed(const Target &t, const char *text) {
    const auto r = parseTrigger(t, QString::fromUtf8(text));
    EXPECT_TRUE(std::holds_alternative<Trigger>(r))
        << text << ": "
        << (std::holds_alternative<QString>(r) ? std::get<QString>(r).toStdString() : "");
    return std::holds_alternative<Trigger>(r) ? std::get<Trigger>(r) : Trigger{};
}

QString error(const Target &t, const char *text) {
    const auto r = parseTrigger(t, QString::fromUtf8(text));
    EXPECT_TRUE(std::holds_alternative<QString>(r)) << text;
    return std::holds_alternative<QString>(r) ? std::get<QString>(r) : QString();
}

} // namespace

TEST(Trigger, ReadsEdgesAndComparisons) {
    const Target &t = vigor();
    const Trigger rises = parsed(t, "Y0 rises");
    EXPECT_EQ(rises.kind, Trigger::Kind::Rises);
    EXPECT_EQ(formatAddress(t, rises.device), QStringLiteral("Y0"));
    EXPECT_EQ(parsed(t, "X17 falls").kind, Trigger::Kind::Falls);
    EXPECT_EQ(parsed(t, "X17 ↓").kind, Trigger::Kind::Falls);
    EXPECT_EQ(parsed(t, " y0   RISES ").kind, Trigger::Kind::Rises);
    const Trigger above = parsed(t, "D10 > 100");
    EXPECT_EQ(above.kind, Trigger::Kind::Compare);
    EXPECT_EQ(above.op, CompareOp::Gt);
    EXPECT_EQ(above.value, 100);
    EXPECT_EQ(parsed(t, "D10>=-5").op, CompareOp::Ge);
    EXPECT_EQ(parsed(t, "D10>=-5").value, -5);
    EXPECT_EQ(parsed(t, "D10 <> 0x1F").value, 31);
    EXPECT_EQ(parsed(t, "T0 = 10").op, CompareOp::Eq);
    EXPECT_EQ(formatTrigger(t, parsed(t, "D10 <= 7")), QStringLiteral("D10 <= 7"));
    EXPECT_EQ(formatTrigger(t, rises), QStringLiteral("Y0 rises"));
}

TEST(Trigger, SaysWhatIsWrong) {
    const Target &t = vigor();
    EXPECT_TRUE(error(t, "").contains(QStringLiteral("rises")));
    EXPECT_TRUE(error(t, "D10 rises").contains(QStringLiteral("word")));
    EXPECT_TRUE(error(t, "X8 rises").contains(QStringLiteral("octal")));
    EXPECT_TRUE(error(t, "D10 > ten").contains(QStringLiteral("ten")));
    EXPECT_TRUE(error(t, "Y0 jumps").contains(QStringLiteral("Y0 jumps")));
}

TEST(Trigger, FiresOnlyWhenTheConditionBecomesTrue) {
    Trigger rises{{0, 0, -1}, Trigger::Kind::Rises};
    EXPECT_TRUE(rises.fires(0, 1));
    EXPECT_FALSE(rises.fires(1, 1));
    EXPECT_FALSE(rises.fires(1, 0));
    Trigger falls{{0, 0, -1}, Trigger::Kind::Falls};
    EXPECT_TRUE(falls.fires(1, 0));
    EXPECT_FALSE(falls.fires(0, 0));
    Trigger above{{0, 0, -1}, Trigger::Kind::Compare, CompareOp::Gt, 100};
    EXPECT_TRUE(above.fires(100, 101));
    EXPECT_FALSE(above.fires(101, 150));
    EXPECT_FALSE(above.fires(150, 100));
}
