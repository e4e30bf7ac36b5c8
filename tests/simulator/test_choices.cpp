// Choices where a manual is ambiguous, on the real target tables (docs/simulator.md,
// "Choices where the manuals are silent or ambiguous").

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

using RealSim = test::RealTargetSim;

} // namespace

// Omron CPM1 guide, CNTR(12): "Nem változik a számláló tartalma, ha mindkét bemeneten 1 szint
// van" (the value does not change while both inputs are at 1): an edge on one input while the
// other is held ON does not count, nor do edges arriving together.
TEST(Cpm1ReversibleCounter, DoesNotCountWhileBothInputsAreOn) {
    RealSim s(model::Family::Cpm1, "LD 000.00\nLD 000.01\nLD 000.02\nCNTR(12) 003 #0005\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_TRUE(s.result.ok());
    s.in("000.00", true);
    s.engine->scan();
    ASSERT_EQ(s.value("CNT 003"), 1);
    s.in("000.01", true); // down edge while up is ON
    s.engine->scan();
    EXPECT_EQ(s.value("CNT 003"), 1);
    s.in("000.00", false);
    s.engine->scan(); // down still ON, up released: no edge, no count
    EXPECT_EQ(s.value("CNT 003"), 1);
    s.in("000.00", true); // up edge while down is ON
    s.engine->scan();
    EXPECT_EQ(s.value("CNT 003"), 1);
    s.in("000.00", false);
    s.in("000.01", false);
    s.engine->scan();
    s.in("000.00", true); // both rise together
    s.in("000.01", true);
    s.engine->scan();
    EXPECT_EQ(s.value("CNT 003"), 1);
    s.in("000.00", false);
    s.in("000.01", false);
    s.engine->scan();
    s.in("000.01", true); // a lone down edge still counts
    s.engine->scan();
    EXPECT_EQ(s.value("CNT 003"), 0);
}

// VPC user's manual, III: p00..p75 hold 0000..9999, counters 0000..9999, timers 00.00..99.99
// s. A transfer whose result leaves 0..9999 writes it modulo 10000 (as the four-digit register
// would show it) and is a runtime diagnostic naming the step, reported once per step.
TEST(VpcDecimalRange, TransferPast9999WrapsAndIsReportedWithItsLine) {
    RealSim s(model::Family::Vpc, "LD r88\nOUT p00+p01\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("p00"), 9998);
    s.engine->writeWord(s.at("p01"), 1);
    s.engine->scan();
    EXPECT_EQ(s.value("p00"), 9999);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
    s.engine->scan();
    EXPECT_EQ(s.value("p00"), 0);
    s.engine->scan();
    EXPECT_EQ(s.value("p00"), 1);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors().front().line, 2);
    EXPECT_TRUE(s.engine->runtimeErrors().front().message.contains(QStringLiteral("10000")));
    EXPECT_TRUE(s.engine->runtimeErrors().front().message.contains(QStringLiteral("0..9999")));
}

TEST(VpcDecimalRange, SubtractionBelowZeroWrapsFrom9999) {
    RealSim s(model::Family::Vpc, "LD r88\nOUT t01-p01\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeSetValue(s.at("t01"), 3);
    s.engine->writeWord(s.at("p01"), 5);
    s.engine->scan();
    EXPECT_EQ(s.engine->setValue(s.at("t01")), 9998);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_TRUE(s.engine->runtimeErrors().front().message.contains(QStringLiteral("-2")));
}
