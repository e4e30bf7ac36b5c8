// System devices and power-cycle retention of each family, on the real target tables (the
// engine tests run on a synthetic target; these pin what the manuals name).

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

using Family = test::RealTargetSim;

} // namespace

TEST(SystemDevices, VpcRunIsOnR92TogglesAndR95IsTheSecondClock) {
    Family f(model::Family::Vpc, "LD r88\nOUT o00\nLD r92\nOUT o01\nLD r95\nOUT o02\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("r92", 6), "010101"); // OFF in the first scan after power-on
    EXPECT_TRUE(f.bit("o00"));
    // 1 s clock at 10 ms scans: ON for the first 50 scans of every 100.
    Family g(model::Family::Vpc, "LD r95\nOUT o02\nEND");
    ASSERT_TRUE(g.result.ok());
    g.engine->runScans(50);
    EXPECT_TRUE(g.bit("r95"));
    g.engine->runScans(1);
    EXPECT_FALSE(g.bit("r95"));
    g.engine->runScans(49);
    EXPECT_FALSE(g.bit("r95"));
    g.engine->runScans(1);
    EXPECT_TRUE(g.bit("r95"));
}

TEST(SystemDevices, VigorM9000IsAlwaysOnAndM9002PulsesOnTheFirstScan) {
    Family f(model::Family::Vigor, "LD M9002\nOUT Y0\nLD M9000\nOUT Y1\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("Y0", 4), "1000");
    EXPECT_TRUE(f.bit("Y1"));
}

// The scan-time words count 0.1 ms on Vigor (D9010-D9012) and PL110 (SM6-SM8, PL110 manual
// 2.1.2, "risoluzione 100 uS"); a virtual scan lasts one period. The devices come from the table.
void expectScanTimeWordsInTenthsOfAMillisecond(model::Family family, const char *program) {
    Family f(family, program);
    ASSERT_TRUE(f.result.ok());
    auto word = [&](model::SystemRole role) {
        for (const model::SystemDevice &d : f.target.systemDevices)
            if (d.role == role)
                return f.value(d.device.toLatin1().constData());
        ADD_FAILURE() << "no device for the role";
        return -1;
    };
    using R = model::SystemRole;
    f.engine->setPeriodMs(20);
    f.engine->scan();
    EXPECT_EQ(word(R::ScanTimeCurrent), 200);
    EXPECT_EQ(word(R::ScanTimeMin), 200);
    EXPECT_EQ(word(R::ScanTimeMax), 200);
    f.engine->setPeriodMs(5);
    f.engine->scan();
    f.engine->setPeriodMs(30);
    f.engine->scan();
    f.engine->setPeriodMs(10);
    f.engine->scan();
    EXPECT_EQ(word(R::ScanTimeCurrent), 100);
    EXPECT_EQ(word(R::ScanTimeMin), 50);
    EXPECT_EQ(word(R::ScanTimeMax), 300);
    f.engine->powerCycle(); // min / max start again
    f.engine->scan();
    EXPECT_EQ(word(R::ScanTimeMin), 100);
    EXPECT_EQ(word(R::ScanTimeMax), 100);
}

TEST(SystemDevices, VigorScanTimeCurrentMinMaxInTenthsOfAMillisecond) {
    expectScanTimeWordsInTenthsOfAMillisecond(model::Family::Vigor, "LD M9000\nOUT Y0\nEND");
}

TEST(SystemDevices, Pl110ScanTimeCurrentMinMaxInTenthsOfAMillisecond) {
    expectScanTimeWordsInTenthsOfAMillisecond(model::Family::Pl110, "LD SM0.0\nOUT Q1\nEND");
}

TEST(SystemDevices, ScanTimeWordsStopAt32767) {
    Family f(model::Family::Vigor, "LD M9000\nOUT Y0\nEND");
    ASSERT_TRUE(f.result.ok());
    f.engine->setPeriodMs(5000);
    f.engine->scan();
    EXPECT_EQ(f.value("D9010"), 32767);
}

// r93 "0.01 s ON-OFF cycle" and r94 "0.1 s" (VPC user's manual, III): ON for the first half of
// each cycle of virtual time at the start of the scan. At the default 10 ms period r93 is
// sampled at the same phase every scan and so reads ON in every scan (docs/simulator.md).
TEST(SystemDevices, VpcR93AndR94AreTheHundredthAndTenthOfASecondClocks) {
    Family f(model::Family::Vpc, "LD r93\nOUT o00\nLD r94\nOUT o01\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("r94", 12), "111110000011");
    EXPECT_TRUE(f.bit("o01")); // VPC: the coil shows r94 of the scan
    EXPECT_EQ(f.bits("r93", 6), "111111");
    Family g(model::Family::Vpc, "LD r93\nOUT o00\nLD r94\nOUT o01\nEND");
    ASSERT_TRUE(g.result.ok());
    g.engine->setPeriodMs(1);
    EXPECT_EQ(g.bits("r93", 12), "111110000011");
    EXPECT_EQ(g.bits("r94", 40), std::string(38, '1') + "00"); // 12 ms .. 51 ms
}

TEST(SystemDevices, Cpm1AlwaysOnFirstScanAndSecondClock) {
    Family f(model::Family::Cpm1, "LD 253.13\nOUT 010.00\nLD 253.15\nOUT 010.01\nLD 255.02\n"
                                  "OUT 010.02\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("010.01", 3), "100");
    EXPECT_TRUE(f.bit("010.00"));
    EXPECT_TRUE(f.bit("010.02")); // 1 s clock: ON in the first half second
    f.engine->runScans(50);
    EXPECT_FALSE(f.bit("010.02"));
}

TEST(SystemDevices, Pl110RunFirstScanToggleAndClocks) {
    Family f(model::Family::Pl110, "LD SM0.0\nOUT Q1\nLD SM0.1\nOUT Q2\nLD SM0.4\nOUT Q3\n"
                                   "LD SM0.3\nOUT Q4\nLD SM0.2\nOUT Q5\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("Q2", 3), "100");
    EXPECT_TRUE(f.bit("Q1"));
    EXPECT_EQ(f.bits("Q3", 4), "1010"); // scans 4..7: the toggle alternates every scan
    EXPECT_TRUE(f.bit("Q4"));
    EXPECT_TRUE(f.bit("Q5"));
    f.engine->runScans(50);
    EXPECT_FALSE(f.bit("Q4")); // 1 s clock, 0.5 s ON
    EXPECT_TRUE(f.bit("Q5"));  // 60 s clock, 30 s ON
    f.engine->runFor(30000);
    EXPECT_FALSE(f.bit("Q5"));
}

TEST(PowerCycle, VpcKeepsTimersCountersRegistersAndR72ToR87) {
    Family f(model::Family::Vpc,
             "LD i00\nOUT r71\nLD i00\nOUT r72\nLD i00\nOUT p05,p06\nLD i00\nTIM16\nEND");
    ASSERT_TRUE(f.result.ok()) << f.result.diagnostics.front().message.toStdString();
    f.engine->writeWord(f.at("p06"), 1234);
    f.engine->writeSetValue(f.at("t16"), 1000);
    f.in("i00", true);
    f.engine->runScans(20);
    ASSERT_TRUE(f.bit("r71"));
    ASSERT_TRUE(f.bit("r72"));
    const std::int32_t timer = f.value("t16");
    ASSERT_GT(timer, 0);
    f.in("i00", false);
    f.engine->powerCycle();
    EXPECT_FALSE(f.bit("r71"));
    EXPECT_TRUE(f.bit("r72"));
    EXPECT_EQ(f.value("p05"), 1234);
    EXPECT_EQ(f.value("t16"), timer);
    EXPECT_EQ(f.engine->setValue(f.at("t16")), 1000);
}

TEST(PowerCycle, Cpm1KeepsHoldingRelaysAndResetsTimers) {
    Family f(model::Family::Cpm1,
             "LD 000.00\nOUT HR00.00\nLD 000.00\nOUT 200.00\nLD 000.00\nTIM 000 #0100\nEND");
    ASSERT_TRUE(f.result.ok());
    f.in("000.00", true);
    f.engine->runScans(20);
    ASSERT_TRUE(f.bit("HR00.00"));
    ASSERT_TRUE(f.bit("200.00"));
    ASSERT_NE(f.value("TIM 000"), 0);
    f.in("000.00", false);
    f.engine->powerCycle();
    EXPECT_TRUE(f.bit("HR00.00"));
    EXPECT_FALSE(f.bit("200.00"));
    EXPECT_EQ(f.value("TIM 000"), 0);
}

TEST(PowerCycle, VigorLatchedRangesSurviveAndTheOthersClear) {
    // M500+, S500+, C100+ (and the 32-bit C200+), D200+ are latched in the Vigor table.
    Family f(model::Family::Vigor,
             "LD X0\nOUT M0\nLD X0\nOUT M499\nLD X0\nOUT M500\nLD X0\nSET S0\nLD X0\n"
             "SET S500\nLD X0\nCNT C0 K5\nLD X0\nCNT C100 K5\nLD X0\nCNT C200 K5\nLD X0\n"
             "MOV K7 D199\nLD X0\nMOV K8 D200\nEND");
    ASSERT_TRUE(f.parsed.ok());
    ASSERT_TRUE(f.result.ok());
    f.run("X0", "101", "X0"); // two rising edges: the counters hold 2
    for (const char *d : {"M0", "M499", "M500", "S0", "S500"})
        ASSERT_TRUE(f.bit(d)) << d;
    f.in("X0", false);
    f.engine->powerCycle();
    for (const char *d : {"M0", "M499", "S0"})
        EXPECT_FALSE(f.bit(d)) << d;
    EXPECT_TRUE(f.bit("M500"));
    EXPECT_TRUE(f.bit("S500"));
    EXPECT_EQ(f.value("C0"), 0);
    EXPECT_EQ(f.value("C100"), 2);
    EXPECT_EQ(f.value("C200"), 2);
    EXPECT_EQ(f.value("D199"), 0);
    EXPECT_EQ(f.value("D200"), 8);
}

TEST(PowerCycle, Cpm1CountersKeepTheirValue) {
    Family f(model::Family::Cpm1, "LD 000.00\nLD 000.01\nCNT 001 #0010\nEND");
    ASSERT_TRUE(f.result.ok());
    f.engine->scan(); // CNT counts down from the set value
    f.pulses("000.00", 3);
    ASSERT_EQ(f.value("CNT 001"), 7);
    f.engine->powerCycle();
    EXPECT_EQ(f.value("CNT 001"), 7);
    f.engine->scan(); // the count goes on from there
    f.in("000.00", true);
    f.engine->scan();
    EXPECT_EQ(f.value("CNT 001"), 6);
}

TEST(PowerCycle, VpcCountersKeepTheirCount) {
    Family f(model::Family::Vpc, "LD i00\nLD i01\nCNT16\nEND");
    ASSERT_TRUE(f.result.ok());
    f.engine->writeSetValue(f.at("c16"), 10);
    f.pulses("i00", 4);
    ASSERT_EQ(f.value("c16"), 4);
    f.engine->powerCycle();
    EXPECT_EQ(f.value("c16"), 4);
    EXPECT_EQ(f.engine->setValue(f.at("c16")), 10);
}

TEST(PowerCycle, FirstScanPulseComesAgain) {
    Family f(model::Family::Vigor, "LD M9002\nOUT Y0\nEND");
    ASSERT_TRUE(f.result.ok());
    EXPECT_EQ(f.bits("Y0", 2), "10");
    f.engine->powerCycle();
    EXPECT_EQ(f.bits("Y0", 2), "10");
}

TEST(ParallelIo, VpcP77ReadsI00ToI11AsANumberWithI11TheMostSignificantBit) {
    Family f(model::Family::Vpc, "LD r88\nOUT p00,p77\nEND");
    ASSERT_TRUE(f.result.ok());
    for (const char *in : {"i00", "i03", "i11", "i12"})
        f.in(in, true);
    f.engine->scan();
    EXPECT_EQ(f.value("p77"), 1 + 8 + 2048); // i12 is not part of it
    EXPECT_EQ(f.value("p00"), 2057);
}
