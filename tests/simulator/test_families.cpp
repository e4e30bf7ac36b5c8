// System devices and power-cycle retention of each family, on the real target tables (the
// engine tests run on a synthetic target; these pin what the manuals name).

#include "model/address.h"
#include "model/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

struct Family {
    Family(model::Family family, const char *text)
        : target(model::Target::get(family))
        , parsed(model::parseInstructionList(target, QString::fromLatin1(text))) {
        if (parsed.ok())
            result = compileProgram(parsed.list);
        if (result.ok())
            engine = std::make_unique<Engine>(result.program);
    }
    model::Address at(const char *name) const {
        const auto parsedAddress = model::parseAddress(target, QString::fromLatin1(name));
        EXPECT_TRUE(std::holds_alternative<model::Address>(parsedAddress)) << name;
        return std::get<model::Address>(parsedAddress);
    }
    bool bit(const char *name) const { return engine->bit(at(name)); }
    std::int32_t value(const char *name) const { return engine->value(at(name)); }
    // The value of a bit device after each of n scans, as a 0/1 string.
    std::string bits(const char *name, int n) {
        std::string s;
        for (int i = 0; i < n; ++i) {
            engine->scan();
            s += bit(name) ? '1' : '0';
        }
        return s;
    }

    const model::Target &target;
    model::ParseResult parsed;
    CompileResult result;
    std::unique_ptr<Engine> engine;
};

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
    f.engine->setPeriodMs(20);
    f.engine->scan();
    EXPECT_EQ(f.value("D9010"), 20); // scan time, current
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
    f.engine->setBit(f.at("i00"), true);
    f.engine->runScans(20);
    ASSERT_TRUE(f.bit("r71"));
    ASSERT_TRUE(f.bit("r72"));
    const std::int32_t timer = f.value("t16");
    ASSERT_GT(timer, 0);
    f.engine->setBit(f.at("i00"), false);
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
    f.engine->setBit(f.at("000.00"), true);
    f.engine->runScans(20);
    ASSERT_TRUE(f.bit("HR00.00"));
    ASSERT_TRUE(f.bit("200.00"));
    ASSERT_NE(f.value("TIM 000"), 0);
    f.engine->setBit(f.at("000.00"), false);
    f.engine->powerCycle();
    EXPECT_TRUE(f.bit("HR00.00"));
    EXPECT_FALSE(f.bit("200.00"));
    EXPECT_EQ(f.value("TIM 000"), 0);
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
        f.engine->setBit(f.at(in), true);
    f.engine->scan();
    EXPECT_EQ(f.value("p77"), 1 + 8 + 2048); // i12 is not part of it
    EXPECT_EQ(f.value("p00"), 2057);
}
