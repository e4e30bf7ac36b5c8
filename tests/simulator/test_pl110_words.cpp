// PL110 double words, trimmers and SM0.13 on the real table (PL110 manual 2.1.1, 2.1.2, 4.2.4,
// 4.2.20; issue 14), and the Vigor timers of 1 ms and 10 ms and the accumulating ones; the
// golden traces pl110_double_words, pl110_sm0_13, pl110_trimmer_preset and
// vigor_timer_resolutions show the manuals' examples.

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

using test::Pl110;

using test::Vigor;

} // namespace

TEST(Pl110DoubleWords, AWriteSplitsHighWordFirstAndAReadJoinsThem) {
    Pl110 s("LD SM0.0\nMOV 100000 VD10\nLD SM0.0\nMOV VD10 VD20\nLD SM0.0\nMOV VD20 V30\nEND");
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics.front().message.toStdString();
    s.engine->scan();
    // 100000 = 0001 86A0h: V10 = 1 (high), V11 = 86A0h (low, a signed 16-bit word).
    EXPECT_EQ(s.value("V10"), 1);
    EXPECT_EQ(s.value("V11"), static_cast<std::int16_t>(0x86A0));
    EXPECT_EQ(s.value("VD10"), 100000);
    EXPECT_EQ(s.value("VD20"), 100000);
    EXPECT_EQ(s.value("V30"), static_cast<std::int16_t>(0x86A0)); // a word keeps the low bits
    // VD11 overlaps: V11 (high) and V12 (low).
    EXPECT_EQ(s.value("VD11"), static_cast<std::int32_t>(0x86A00000u));
}

TEST(Pl110DoubleWords, FmComputesOnThirtyTwoBits) {
    Pl110 s("LD SM0.0\nFM VD0 + 1 VD0\nLD SM0.0\nFM VD0 * 2 VD4\nLD= VD4 131072\nOUT Q1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("VD0"), 65535);
    s.engine->scan();
    EXPECT_EQ(s.value("VD0"), 65536);
    EXPECT_EQ(s.value("V0"), 1);
    EXPECT_EQ(s.value("V1"), 0);
    EXPECT_EQ(s.value("VD4"), 131072);
    EXPECT_TRUE(s.bit("Q1"));
}

TEST(Pl110DoubleWords, SmdReadsTheEncoderCountHighWordFirst) {
    Pl110 s("LD SM0.0\nMOV SMD22 VD0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("SM22"), -1); // FFFFh
    s.engine->writeWord(s.at("SM23"), -2); // FFFEh
    s.engine->scan();
    EXPECT_EQ(s.value("VD0"), -2);
    EXPECT_EQ(s.value("SMD22"), -2);
}

TEST(Pl110DoubleWords, VdIsRetainedWithV) {
    Pl110 s("LD SM0.1\nMOV 70000 VD0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    s.engine->writeWord(s.at("VD0"), 123456);
    s.engine->powerCycle();
    EXPECT_EQ(s.value("VD0"), 123456);
}

TEST(Pl110Trimmers, ATrimmerIsStimulusTheProgramReads) {
    Pl110 s("LD SM0.0\nMOV TR2 V0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("TR2"), 150);
    s.engine->scan();
    EXPECT_EQ(s.value("V0"), 150);
}

TEST(Pl110Sm013, CountersStopAndTimersFrom49RunWhileItIsOn) {
    Pl110 s("LD I1\nTON T49 2 10\nLD I1\nTON T1 2 10\nLD I2\nLD I3\nLD I4\nMUP C1 1\n"
            "LD I5\nOUT SM0.13\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("I1", true);
    s.engine->runScans(4);
    EXPECT_EQ(s.value("T49"), 0); // disabled: SM0.13 is OFF
    EXPECT_EQ(s.value("T1"), 3);
    s.in("I2", true);
    s.engine->scan();
    EXPECT_EQ(s.value("C1"), 1);
    EXPECT_TRUE(s.bit("C1"));
    s.in("I2", false);
    s.in("I5", true);
    s.engine->scan(); // SM0.13 ON from here on (the coil is after the boxes)
    s.in("I2", true);
    s.engine->runScans(3);
    EXPECT_EQ(s.value("C1"), 1); // no count while the counters are off
    EXPECT_TRUE(s.bit("C1"));    // and the bit keeps its state
    EXPECT_EQ(s.value("T49"), 2);
    EXPECT_TRUE(s.bit("T49"));
}

TEST(VigorTimers, TheAccumulatingTimersAreRetainedOverAPowerCycle) {
    Vigor s("LD X0\nTMR T250 K50\nLD X0\nTMR T0 K50\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(100);
    s.in("X0", true);
    s.engine->runScans(4);
    EXPECT_EQ(s.value("T250"), 3);
    EXPECT_EQ(s.value("T0"), 3);
    s.engine->powerCycle();
    EXPECT_EQ(s.value("T250"), 3);
    EXPECT_EQ(s.value("T0"), 0);
    s.in("X0", false);
    s.engine->scan();
    EXPECT_EQ(s.value("T250"), 3); // kept while its coil is OFF
}

TEST(VigorTimers, TenMillisecondTimersCountHundredthsAtEveryScanPeriod) {
    Vigor s("LD X0\nTMR T245 K100\nLD X0\nTMR T249 K1000\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(5);
    s.in("X0", true);
    s.engine->runScans(201); // 1 s after the first scan that saw X0
    EXPECT_EQ(s.value("T245"), 100);
    EXPECT_TRUE(s.bit("T245"));
    EXPECT_EQ(s.value("T249"), 1000);
    EXPECT_TRUE(s.bit("T249"));
}

// docs/targets.md "Scan time": the D1010..D1012 of PLC concepts (WPLSoft family) 1.1 (Delta's)
// are data on the Vigor - the LINK / MBUS tables of the Vigor M/VB/VH communication manual use
// D1000.. as data - and the scan time is D9010..D9012.
TEST(VigorScanTime, D9010HoldsTheScanTimeAndD1010IsAPlainRegister) {
    Vigor s("LD M9000\nMOV K1234 D1010\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(10);
    s.engine->runScans(2);
    EXPECT_EQ(s.value("D9010"), 100); // 10 ms in 0.1 ms
    EXPECT_EQ(s.value("D1010"), 1234);
    EXPECT_EQ(s.value("D1011"), 0);
}
