// Word logic and BCD conversion on the real Vigor and CPM1 tables (issue 14): Vigor WAND /
// WOR / WXOR / CML / BCD / BIN (the programs of the Vigor M/VB/VH communication manual use WAND
// D104 HFF D104) and CPM1 ANDW(34) / ORW(35) / XORW(36) / COM(29) / BCD(24) / BIN(23) (Omron
// W353).

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

using test::Vigor;

using test::Cpm1;

} // namespace

// Vigor M/VB/VH communication manual (the MODBUS examples): "WAND D104 HFF D104" keeps the low
// byte of D104.
TEST(VigorWordLogic, WandKeepsTheBitsOfTheMask) {
    Vigor s("LD M9000\nWAND D104 HFF D104\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty()); // simulated: no SIM100
    s.engine->writeWord(s.at("D104"), 0x1234);
    s.engine->scan();
    EXPECT_EQ(s.value("D104"), 0x34);
}

TEST(VigorWordLogic, OrXorAndComplementRunOnlyWhileTheirInputIsOn) {
    Vigor s("LD X0\nWOR D0 D1 D10\nLD X0\nWXOR D0 D1 D11\nLD X0\nCML D0 D12\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D0"), 0x0F0F);
    s.engine->writeWord(s.at("D1"), 0x00FF);
    s.engine->scan();
    EXPECT_EQ(s.value("D10"), 0); // X0 OFF: nothing written
    s.in("X0", true);
    s.engine->scan();
    EXPECT_EQ(s.value("D10"), 0x0FFF);
    EXPECT_EQ(s.value("D11"), 0x0FF0);
    EXPECT_EQ(s.value("D12"), static_cast<std::int16_t>(0xF0F0)); // a 16-bit word, signed
}

TEST(VigorWordLogic, BcdAndBinConvertBothWays) {
    Vigor s("LD M9000\nBCD D0 D1\nLD M9000\nBIN D1 D2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D0"), 1234);
    s.engine->scan();
    EXPECT_EQ(s.value("D1"), 0x1234);
    EXPECT_EQ(s.value("D2"), 1234);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
}

TEST(VigorWordLogic, AValueBeyondFourBcdDigitsIsARuntimeErrorAndWritesNothing) {
    Vigor s("LD M9000\nBCD D0 D1\nLD M9000\nBIN D3 D4\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D0"), 10000);
    s.engine->writeWord(s.at("D1"), 7);
    s.engine->writeWord(s.at("D3"), 0x12A4); // A is no BCD digit
    s.engine->writeWord(s.at("D4"), 9);
    s.engine->scan();
    EXPECT_EQ(s.value("D1"), 7);
    EXPECT_EQ(s.value("D4"), 9);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 2u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 2);
    EXPECT_EQ(s.engine->runtimeErrors()[1].line, 4);
}

// Issue 14: special-module and refresh instructions are accepted, warned at check time and
// when simulating, and do nothing in the simulator - never silently.
// FROM / TO / TOP reach a VB-1COM's buffer memory (docs/network.md): simulated, so no SIM100;
// REF is not simulated, and the check and the simulator warn of it on the same line. Without
// a network no module is connected: FROM and TO are the operation error that says so.
TEST(VigorWordLogic, ModuleInstructionsRunAndRefIsWarnedNotSimulated) {
    Vigor s("LD M9000\nFROM K1 K1 D0 K2\nLD M9000\nTO K1 K1 D0 K2\nLD M9000\nTOP K1 K0 H7096 K1\n"
            "LD M9000\nREF X0 K8\nEND");
    ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(s.result.ok());
    std::vector<int> simulatorLines;
    for (const model::Diagnostic &d : s.result.diagnostics)
        if (d.code == QLatin1String("SIM100"))
            simulatorLines.push_back(d.location.line);
    std::vector<int> checkLines;
    for (const model::Diagnostic &d : model::checkList(s.parsed.list, {}))
        if (d.code == QLatin1String("SIM100")) {
            EXPECT_EQ(d.severity, model::Severity::Warning);
            checkLines.push_back(d.location.line);
        }
    EXPECT_EQ(simulatorLines, (std::vector<int>{8}));
    EXPECT_EQ(checkLines, simulatorLines);
    s.engine->scan();
    const auto &errors = s.engine->runtimeErrors();
    ASSERT_GE(errors.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_TRUE(errors[k].message.contains(QStringLiteral("MODULE1")))
            << errors[k].message.toStdString();
}

// W353 ANDW(34) / ORW(35) / XORW(36): R = I1 op I2 on the 16 bits; COM(29) inverts in place.
TEST(Cpm1WordLogic, LogicInstructionsWithTheirFunctionCodes) {
    Cpm1 s("LD 253.13\nANDW(34) DM 0000 #00FF DM 0010\nLD 253.13\nORW(35) DM 0000 #00FF DM 0011\n"
           "LD 253.13\nXORW(36) DM 0000 #00FF DM 0012\nLD 253.13\nCOM(29) DM 0013\nEND(01)");
    ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty());
    s.engine->writeWord(s.at("DM 0000"), 0x1234);
    s.engine->writeWord(s.at("DM 0013"), 0x00FF);
    s.engine->scan();
    EXPECT_EQ(s.value("DM 0010"), 0x0034);
    EXPECT_EQ(s.value("DM 0011"), 0x12FF);
    EXPECT_EQ(s.value("DM 0012"), 0x12CB);
    EXPECT_EQ(s.value("DM 0013"), static_cast<std::int16_t>(0xFF00));
    s.engine->scan(); // COM again: back
    EXPECT_EQ(s.value("DM 0013"), 0x00FF);
}

// W353 BCD(24) / BIN(23): BCD 9999h (held as a negative 16-bit number) converts to 9999.
TEST(Cpm1WordLogic, BinAndBcdConvertTheWholeFourDigits) {
    Cpm1 s("LD 253.13\nBIN(23) DM 0000 DM 0001\nLD 253.13\nBCD(24) DM 0001 DM 0002\nEND(01)");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("DM 0000"), static_cast<std::int16_t>(0x9999));
    s.engine->scan();
    EXPECT_EQ(s.value("DM 0001"), 9999);
    EXPECT_EQ(s.value("DM 0002"), static_cast<std::int16_t>(0x9999));
    // The bare names are accepted, as for every CPM1 instruction with a function code.
    Cpm1 bare("LD 253.13\nBIN DM 0000 DM 0001\nEND(01)");
    EXPECT_TRUE(bare.result.ok());
}

// Issue 14: a CPM1 user reads a word as its four hexadecimal digits (#9999, W353 "ER: S is
// greater than 270F"), not as the signed number the simulator holds (-26215); the Vigor's
// words stay decimal, its BCD digits H-prefixed.
TEST(Cpm1WordLogic, BcdErrorsShowTheWordAsTheFamilyWritesIt) {
    Cpm1 s("LD 253.13\nBCD(24) DM 0000 DM 0001\nLD 253.13\nBIN(23) DM 0002 DM 0003\nEND(01)");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("DM 0000"), static_cast<std::int16_t>(0x9999));
    s.engine->writeWord(s.at("DM 0002"), 0x12A4);
    s.engine->scan();
    ASSERT_EQ(s.engine->runtimeErrors().size(), 2u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].message,
              QLatin1String("#9999 does not fit in BCD (0..#270F); the destination is unchanged"));
    EXPECT_EQ(s.engine->runtimeErrors()[1].message,
              QLatin1String("#12A4 is not a BCD number; the destination is unchanged"));

    Vigor v("LD M9000\nBCD D0 D1\nLD M9000\nBIN D2 D3\nEND");
    ASSERT_TRUE(v.result.ok());
    v.engine->writeWord(v.at("D0"), -5);
    v.engine->writeWord(v.at("D2"), 0x12A4);
    v.engine->scan();
    ASSERT_EQ(v.engine->runtimeErrors().size(), 2u);
    EXPECT_EQ(v.engine->runtimeErrors()[0].message,
              QLatin1String("-5 does not fit in BCD (0..9999); the destination is unchanged"));
    EXPECT_EQ(v.engine->runtimeErrors()[1].message,
              QLatin1String("H12A4 is not a BCD number; the destination is unchanged"));
}
