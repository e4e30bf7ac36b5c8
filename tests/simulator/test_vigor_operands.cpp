// Digit-designated operands and index registers on the real VigorBits table (issue 14; V/Z as
// the operand tables of the Vigor M/VB/VH communication manual name them, E/F as PLC concepts
// (WPLSoft family) 1.4 does): what MOV, CMP, ADD and the other word instructions read and
// write, the octal X/Y numbering inside a group, and the operation error of an index that
// lands outside its areas.

#include "real_target_sim.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

struct VigorBits : test::RealTargetSim {
    explicit VigorBits(const char *text)
        : RealTargetSim(model::Family::Vigor, text) {}
    std::string bitsOf(std::initializer_list<const char *> names) const {
        std::string s;
        for (const char *n : names)
            s += bit(n) ? '1' : '0';
        return s;
    }
};

} // namespace

TEST(VigorDigitGroups, MovToK4Y0WritesSixteenOutputsCountingInOctal) {
    VigorBits s("LD M9000\nMOV H1234 K4Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    ASSERT_TRUE(s.result.diagnostics.empty());
    s.engine->scan();
    // 1234h = bits 2, 4, 5, 9, 12: Y2, Y4, Y5, Y11, Y14 (the 10th and 13th outputs).
    EXPECT_EQ(s.bitsOf({"Y0", "Y1", "Y2", "Y3", "Y4", "Y5", "Y6", "Y7"}), "00101100");
    EXPECT_EQ(s.bitsOf({"Y10", "Y11", "Y12", "Y13", "Y14", "Y15", "Y16", "Y17"}), "01001000");
    EXPECT_FALSE(s.bit("Y20"));
}

// A digit group is written through the engine's scratch word behind the image: what the
// engine hands its readers (the history recorder, the benchmarks' compiled-code check) is the
// layout's words alone, the same as a snapshot holds.
TEST(VigorDigitGroups, TheEnginesImageIsTheLayoutsWordsAsASnapshotHoldsThem) {
    VigorBits s("LD M9000\nMOV H1234 K4Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    const auto words = s.engine->words();
    EXPECT_EQ(words.size(), static_cast<std::size_t>(s.result.program->layout->wordCount()));
    EXPECT_EQ(std::vector<std::int32_t>(words.begin(), words.end()), s.engine->snapshot().words);
}

TEST(VigorDigitGroups, K2X4ReadsX4ToX7ThenX10ToX13) {
    VigorBits s("LD M9000\nMOV K2X4 D0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X4", true);
    s.in("X13", true);
    s.in("X14", true); // the 9th bit: not in K2
    s.in("X3", true);  // before the group
    s.engine->scan();
    EXPECT_EQ(s.value("D0"), 0x81);
}

TEST(VigorDigitGroups, AShortGroupWritesItsBitsOnlyAndReadsUnsigned) {
    VigorBits s("LD M9000\nMOV K31 K1M20\nLD M9000\nMOV K1M20 D1\nLD M9000\nMOV K-1 K4M100\n"
                "LD M9000\nMOV K4M100 D2\nLD M9000\nMOV K2M100 D3\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setBit(s.at("M24"), true);
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"M19", "M20", "M21", "M22", "M23", "M24"}), "011111"); // 31 & 0Fh
    EXPECT_EQ(s.value("D1"), 15);
    EXPECT_EQ(s.value("D2"), -1); // K4: the 16 bits, a signed word
    EXPECT_EQ(s.value("D3"), 255);
}

TEST(VigorDigitGroups, CmpAddIncAndCompareContactsWorkOnGroups) {
    VigorBits s("LD M9000\nCMP K1X0 K5 M10\n"
                "LD X10\nADD K2M0 K3 K2M0\n"
                "LD X11\nINC K1Y0\n"
                "LD>= K2M0 K6\nOUT Y10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.in("X2", true); // K1X0 = 5
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"M10", "M11", "M12"}), "010");
    s.in("X10", true);
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"M0", "M1", "M2"}), "110"); // 3
    EXPECT_FALSE(s.bit("Y10"));
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"M0", "M1", "M2"}), "011"); // 6
    EXPECT_TRUE(s.bit("Y10"));
    s.in("X11", true);
    for (int k = 0; k < 16; ++k)
        s.engine->scan();
    // 16 increments of a 4-bit group wrap to where it started.
    EXPECT_EQ(s.bitsOf({"Y0", "Y1", "Y2", "Y3"}), "0000");
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"Y0", "Y1", "Y2", "Y3", "Y4"}), "10000");
}

TEST(VigorDigitGroups, MulIntoAGroupKeepsTheLowBits) {
    VigorBits s("LD M9000\nMUL K300 K300 K4M0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->scan();
    // 90000 = 15F90h: K4 keeps 5F90h, and no word follows a group.
    int v = 0;
    for (int k = 0; k < 16; ++k)
        v |= s.bit(QStringLiteral("M%1").arg(k).toLatin1().constData()) << k;
    EXPECT_EQ(v, 0x5F90);
    EXPECT_FALSE(s.bit("M16"));
}

TEST(VigorIndexRegisters, TheRegisterMovesTheOperandEachScan) {
    VigorBits s("LD M9000\nMOV K7 D0E0\nLD M9000\nMOV K10F0 D100\nLD M9000\nMOV D20Z0 D101\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("E0"), 5);
    s.engine->writeWord(s.at("F0"), 3);
    s.engine->writeWord(s.at("D25"), 42);
    s.engine->scan();
    EXPECT_EQ(s.value("D5"), 7);
    EXPECT_EQ(s.value("D0"), 0);
    EXPECT_EQ(s.value("D100"), 13);
    EXPECT_EQ(s.value("D101"), 42);
    // D190 + 20 is D210, in the latched area after D199; a negative index goes back.
    s.engine->writeWord(s.at("E0"), 205);
    s.engine->writeWord(s.at("F0"), -4);
    s.engine->scan();
    EXPECT_EQ(s.value("D205"), 7);
    EXPECT_EQ(s.value("D100"), 6);
    EXPECT_TRUE(s.engine->runtimeErrors().empty());
}

TEST(VigorIndexRegisters, ProgramsSetTheirOwnIndex) {
    // A table walk: E0 counts 0..3, each scan D10E0 takes the scan's number.
    VigorBits s("LD M9000\nMOV Z0 D10Z0\nLD M9000\nINC Z0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->runScans(4);
    EXPECT_EQ(s.value("D10"), 0);
    EXPECT_EQ(s.value("D11"), 1);
    EXPECT_EQ(s.value("D13"), 3);
    EXPECT_EQ(s.value("Z0"), 4);
    EXPECT_EQ(s.value("E0"), 4); // the name PLC concepts (WPLSoft family) gives Z0
}

TEST(VigorIndexRegisters, IndexedGroupsAndTimerSetValues) {
    VigorBits s("LD M9000\nMOV K15 K1M0E1\nLD X0\nTMR T0 D0F1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->setPeriodMs(100);
    s.engine->writeWord(s.at("E1"), 4);
    s.engine->writeWord(s.at("F1"), 2);
    s.engine->writeWord(s.at("D2"), 3); // T0 runs 0.3 s
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"M3", "M4", "M5", "M6", "M7", "M8"}), "011110");
    s.in("X0", true);
    EXPECT_EQ(s.bits("T0", 5), "00011");
}

TEST(VigorIndexRegisters, MulAndDivWriteTheWordAfterTheIndexedOne) {
    VigorBits s("LD M9000\nMUL K300 K300 D10E0\nLD M9000\nDIV K7 K2 D20E0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("E0"), 2);
    s.engine->scan();
    EXPECT_EQ(s.value("D12") & 0xFFFF, 0x5F90);
    EXPECT_EQ(s.value("D13"), 1);
    EXPECT_EQ(s.value("D22"), 3);
    EXPECT_EQ(s.value("D23"), 1);
}

// The WPLSoft family: an index that takes a device outside its range is an operation error;
// the instruction is not executed and the scan goes on.
TEST(VigorIndexRegisters, AnIndexOutOfRangeIsAnOperationErrorAndWritesNothing) {
    VigorBits s("LD M9000\nMOV K7 D8190E0\nLD= D0E1 K0\nOUT Y0\nLDI Y1\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("E0"), 5); // D8195: between D8191 and D9000
    s.engine->writeWord(s.at("E1"), -1);
    s.engine->scan();
    EXPECT_EQ(s.value("D8191"), 0);
    EXPECT_EQ(s.value("D9000"), 0);
    EXPECT_FALSE(s.bit("Y0")); // the compare contact is open
    EXPECT_TRUE(s.bit("Y1"));  // the scan went on
    ASSERT_EQ(s.engine->runtimeErrors().size(), 2u);
    const RuntimeError &e = s.engine->runtimeErrors()[0];
    EXPECT_EQ(e.line, 2);
    EXPECT_TRUE(e.message.contains(QLatin1String("D8190Z0 with Z0 = 5 reaches D8195")))
        << e.message.toStdString();
    EXPECT_TRUE(s.engine->runtimeErrors()[1].message.contains(QLatin1String("Z1 = -1 reaches D-1")))
        << s.engine->runtimeErrors()[1].message.toStdString();
    // Back in range, the instruction runs again.
    s.engine->writeWord(s.at("E0"), 1);
    s.engine->scan();
    EXPECT_EQ(s.value("D8191"), 7);
}

TEST(VigorIndexRegisters, ABlockMoveMustLandInsideItsArea) {
    VigorBits s("LD M9000\nBMOV D0 D8180E0 K10\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("D0"), 9);
    s.engine->scan();
    EXPECT_EQ(s.value("D8180"), 9);
    s.engine->writeWord(s.at("E0"), 5); // D8185..D8194 runs past D8191
    s.engine->scan();
    EXPECT_EQ(s.value("D8185"), 0);
    EXPECT_EQ(s.engine->runtimeErrors().size(), 1u);
}

TEST(VigorIndexRegisters, ForcedBitsOfAGroupKeepTheirValue) {
    VigorBits s("LD M9000\nMOV K0 K1Y0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->force(s.at("Y1"), true);
    s.engine->scan();
    EXPECT_EQ(s.bitsOf({"Y0", "Y1", "Y2"}), "010");
}

// On the octal areas an index counts elements: K1X0Z0 with Z0 = 8 starts at X10 (the FX
// family's X0Z with Z = 8).
TEST(VigorIndexRegisters, AnIndexCountsElementsOnOctalAreas) {
    VigorBits s("LD M9000\nMOV K1X0Z0 D0\nLD M9000\nMOV K15 K1Y0Z0\nEND");
    ASSERT_TRUE(s.result.ok());
    s.engine->writeWord(s.at("Z0"), 8);
    s.in("X10", true);
    s.in("X12", true);
    s.engine->scan();
    EXPECT_EQ(s.value("D0"), 5);
    EXPECT_EQ(s.bitsOf({"Y7", "Y10", "Y11", "Y12", "Y13", "Y14"}), "011110");
}
