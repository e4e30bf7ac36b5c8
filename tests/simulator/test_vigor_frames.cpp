// VigorFrames instructions that the communication programs of the Vigor M/VB/VH communication
// manual use to build and check a frame (issue 14): CCD, the check code (B-3-9 "Accumulate then
// take the last two digits (HEX)", B-4-5), and DMOV, the 32-bit move that writes two
// characters a call.

#include "model/checks/checks.h"
#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

struct VigorFrames : test::RealTargetSim {
    explicit VigorFrames(const char *text)
        : RealTargetSim(model::Family::Vigor, text) {}
    void words(const char *first, std::initializer_list<int> values) {
        model::Address a = at(first);
        for (int v : values) {
            engine->writeWord(a, v);
            ++a.index;
        }
    }
};

std::vector<QString> codes(const std::vector<model::Diagnostic> &found) {
    std::vector<QString> out;
    for (const model::Diagnostic &d : found)
        out.push_back(d.code);
    return out;
}

} // namespace

// Vigor M/VB/VH communication manual, B-3-9:
// "30H+31H+35H+31H+31H+43H+30H+30H+30H+32H+03H=200H", one character a word with M9161 ON ("Assign
// 8-bits processing mode"), summed by CCD D2 D102 K11 as the master's program does. D+1 holds the
// parity, bit k ON when an odd number of the bytes have bit k ON (the FX / Delta rule): the XOR of
// the bytes, 76h.
TEST(VigorCheckCode, TheSeedFrameSumsTo200hInEightBitMode) {
    VigorFrames s("LD M9000\nOUT M9161\nLD M9000\nCCD D2 D102 K11\nEND");
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics.front().message.toStdString();
    EXPECT_TRUE(s.result.diagnostics.empty()); // simulated: no SIM100
    EXPECT_TRUE(codes(model::checkList(s.parsed.list, {})).empty());
    s.words("D2", {0x30, 0x31, 0x35, 0x31, 0x31, 0x43, 0x30, 0x30, 0x30, 0x32, 0x03});
    s.engine->scan();
    EXPECT_EQ(s.value("D102"), 0x200);
    EXPECT_EQ(s.value("D103"), 0x76);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
}

// M9161 OFF: each word gives its low byte, then its high byte; n counts bytes (CCD D0 D100
// K6 reads D0..D2). The bytes 100, 111, 120, 202, 123, 211 sum to 867, parity 11h.
TEST(VigorCheckCode, SixteenBitModeTakesTheLowByteThenTheHighByte) {
    VigorFrames s("LD X0\nCCD D0 D100 K6\nLD X0\nCCD D0 D110 K5\nEND");
    ASSERT_TRUE(s.result.ok());
    s.words("D0", {111 << 8 | 100, 202 << 8 | 120, 211 << 8 | 123});
    s.engine->scan();
    EXPECT_EQ(s.value("D100"), 0); // input OFF: nothing written
    s.in("X0", true);
    s.engine->scan();
    EXPECT_EQ(s.value("D100"), 867);
    EXPECT_EQ(s.value("D101"), 0x11);
    EXPECT_EQ(s.value("D110"), 867 - 211); // an odd count stops at a low byte
    EXPECT_EQ(s.value("D111"), 0x11 ^ 211);
}

// In 8-bit mode the high byte of each word is left out.
TEST(VigorCheckCode, EightBitModeIgnoresTheHighBytes) {
    VigorFrames s("LD M9000\nOUT M9161\nLD M9000\nCCD D0 D100 K2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.words("D0", {0x7F31, 0x1232});
    s.engine->scan();
    EXPECT_EQ(s.value("D100"), 0x63);
    EXPECT_EQ(s.value("D101"), 0x03);
}

// A block that runs past the end of its area is the PLC's operation error: nothing written,
// reported once with the line. The same block fits in 16-bit mode (two bytes a word).
TEST(VigorCheckCode, ABlockPastTheEndOfItsAreaIsNotExecuted) {
    VigorFrames s("LD X0\nOUT M9161\nLD M9000\nCCD D8190 D0 K4\nEND");
    ASSERT_TRUE(s.result.ok());
    s.words("D8190", {0x0101, 0x0202});
    s.engine->writeWord(s.at("D0"), 7);
    s.engine->scan(); // 16-bit: D8190, D8191
    EXPECT_EQ(s.value("D0"), 6);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
    s.in("X0", true);
    s.engine->scan(); // 8-bit: D8190..D8193, which do not exist
    EXPECT_EQ(s.value("D0"), 6);
    ASSERT_EQ(s.engine->runtimeErrors().size(), 1u);
    EXPECT_EQ(s.engine->runtimeErrors()[0].line, 4);
}

// An index register moves the block; it is measured where it lands.
TEST(VigorCheckCode, AnIndexedSourceIsReadWhereTheIndexPutsIt) {
    VigorFrames s("LD M9000\nOUT M9161\nLD M9000\nCCD D0Z0 D100 K2\nEND");
    ASSERT_TRUE(s.result.ok());
    s.words("D10", {0x41, 0x42});
    s.engine->writeWord(s.at("Z0"), 10);
    s.engine->scan();
    EXPECT_EQ(s.value("D100"), 0x83);
    s.engine->writeWord(s.at("Z0"), 8191); // D8191 exists, D8192 not: not executed
    s.engine->writeWord(s.at("D100"), 1);
    s.engine->scan();
    EXPECT_EQ(s.value("D100"), 1);
    EXPECT_EQ(s.engine->runtimeErrors().size(), 1u);
}

// n is 1..256 bytes (FX, Delta): check and the simulator refuse 0 alike, with one message.
TEST(VigorCheckCode, CountOutsideOneTo256IsRefusedByCheckAndSimulator) {
    VigorFrames s("LD M9000\nCCD D0 D100 K0\nEND");
    ASSERT_TRUE(s.parsed.ok());
    ASSERT_FALSE(s.result.ok());
    const auto found = model::checkList(s.parsed.list, {});
    ASSERT_EQ(codes(found), (std::vector<QString>{QStringLiteral("OP005")}));
    EXPECT_EQ(s.result.diagnostics.front().message, found.front().message);
}

// Vigor M/VB/VH communication manual, B-4-5: "DMOV H00310035 D4" puts "5" (35h) into D4 and
// "1" (31h) into D5: the low word first, as the FX family's 32-bit instructions store a pair.
TEST(VigorDoubleMove, TheLowWordGoesFirst) {
    VigorFrames s("LD M9000\nDMOV H00310035 D4\nLD M9000\nDMOV D4 D10\nLD M9000\nDMOV K-2 D20\n"
                  "LD M9000\nDMOV K100000 D30\nEND");
    ASSERT_TRUE(s.parsed.ok()) << s.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics.front().message.toStdString();
    EXPECT_TRUE(s.result.diagnostics.empty());
    EXPECT_TRUE(codes(model::checkList(s.parsed.list, {})).empty());
    s.engine->scan();
    EXPECT_EQ(s.value("D4"), 0x35);
    EXPECT_EQ(s.value("D5"), 0x31);
    EXPECT_EQ(s.value("D10"), 0x35);
    EXPECT_EQ(s.value("D11"), 0x31);
    EXPECT_EQ(s.value("D20"), -2);
    EXPECT_EQ(s.value("D21"), -1);
    EXPECT_EQ(s.value("D30"), static_cast<std::int16_t>(100000 & 0xFFFF)); // 86A0h, signed
    EXPECT_EQ(s.value("D31"), 1);
}

// A 32-bit counter is one 32-bit value on either side; a register pair meets it half way.
TEST(VigorDoubleMove, ThirtyTwoBitCountersAndIndexedPairs) {
    VigorFrames s(
        "LD M9000\nDMOV D0 C200\nLD M9000\nDMOV C200 D10\nLD M9000\nDMOV D0Z0 D20Z0\nEND");
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics.front().message.toStdString();
    s.words("D0", {0x2345, 0x0001, 0x1111, 0x2222});
    s.engine->writeWord(s.at("Z0"), 2);
    s.engine->scan();
    EXPECT_EQ(s.value("C200"), 0x12345);
    EXPECT_EQ(s.value("D10"), 0x2345);
    EXPECT_EQ(s.value("D11"), 1);
    EXPECT_EQ(s.value("D22"), 0x1111); // D2, D3 into D22, D23
    EXPECT_EQ(s.value("D23"), 0x2222);
}

// The pair must be whole: D8191 has no D8192 (check OP005 and the simulator alike).
TEST(VigorDoubleMove, ADestinationPairPastItsAreaIsRefused) {
    VigorFrames s("LD M9000\nDMOV K1 D8191\nEND");
    ASSERT_TRUE(s.parsed.ok());
    EXPECT_FALSE(s.result.ok());
    EXPECT_EQ(codes(model::checkList(s.parsed.list, {})),
              (std::vector<QString>{QStringLiteral("OP005")}));
}

// A digit group is 16 bits, not a pair: DMOV refuses it (OP005), as BMOV does.
TEST(VigorDoubleMove, ADigitGroupIsNoPair) {
    VigorFrames s("LD M9000\nDMOV K4M0 D0\nEND");
    ASSERT_TRUE(s.parsed.ok());
    EXPECT_FALSE(s.result.ok());
    EXPECT_EQ(codes(model::checkList(s.parsed.list, {})),
              (std::vector<QString>{QStringLiteral("OP005")}));
}
