// Vigor word operands (issue 14): digit-designated bit devices (K1M20, K4Y0, K2X10; TO K1 K1
// K1M20 K1 in the Vigor M/VB/VH communication manual) and the index registers - V0..V7, Z0..Z7
// in that manual's operand tables, E0..E7 / F0..F7 in PLC concepts (WPLSoft family) 1.4
// (D0E0 = D0Z0, K10F0 = K10V0) - parsed, printed, refused where a slot takes no word, checked
// like any device, and carried through the ladder both ways.

#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <tuple>

using namespace rung::model;

namespace {

using rung::testing::vigor;

ParseResult parseVigor(const char *text) {
    return parseInstructionList(vigor(), QString::fromLatin1(text));
}

std::string errors(const ParseResult &r) {
    QString out;
    for (const ParseError &e : r.errors)
        out += QStringLiteral("%1:%2 %3\n").arg(e.line).arg(e.column).arg(e.message);
    return out.toStdString();
}

Operand operand(const char *text) {
    auto o = parseOperand(vigor(), QString::fromLatin1(text));
    EXPECT_TRUE(std::holds_alternative<Operand>(o))
        << text << ": " << std::get<AddressError>(o).message.toStdString();
    return std::holds_alternative<Operand>(o) ? std::get<Operand>(o) : Operand{};
}

QString operandError(const char *text) {
    auto o = parseOperand(vigor(), QString::fromLatin1(text));
    return std::holds_alternative<AddressError>(o) ? std::get<AddressError>(o).message : QString();
}

std::vector<Diagnostic> check(const char *text) {
    const ParseResult r = parseVigor(text);
    EXPECT_TRUE(r.ok()) << errors(r);
    return checkList(r.list);
}

bool has(const std::vector<Diagnostic> &found, const char *code, const char *words) {
    for (const Diagnostic &d : found)
        if (d.code == QLatin1String(code) && d.message.contains(QLatin1String(words)))
            return true;
    return false;
}

} // namespace

TEST(VigorOperands, DigitGroupsNameTheirFirstBitAndCount) {
    const Operand y = operand("K4Y0");
    EXPECT_EQ(y.kind, Operand::Kind::Device);
    EXPECT_EQ(y.digits, 4);
    EXPECT_EQ(formatAddress(vigor(), y.address), QStringLiteral("Y0"));
    // Octal areas: K2X10 starts at X10 (element 8).
    const Operand x = operand("k2x10");
    EXPECT_EQ(x.digits, 2);
    EXPECT_EQ(x.address.index, 8);
    EXPECT_EQ(formatOperand(vigor(), x), QStringLiteral("K2X10"));
    EXPECT_EQ(formatOperand(vigor(), operand("K1M20")), QStringLiteral("K1M20"));
    // A K constant stays a constant; a hexadecimal constant keeps its E and F digits.
    EXPECT_EQ(operand("K10").kind, Operand::Kind::Constant);
    const Operand hex = operand("H1E0");
    EXPECT_EQ(hex.kind, Operand::Kind::Constant);
    EXPECT_EQ(hex.constant.value, 0x1E0);
    EXPECT_FALSE(hex.index.valid());
}

TEST(VigorOperands, IndexRegistersModifyWordsGroupsAndKConstants) {
    const Operand d = operand("D0E0");
    EXPECT_EQ(d.kind, Operand::Kind::Device);
    EXPECT_EQ(formatAddress(vigor(), d.address), QStringLiteral("D0"));
    // The E of PLC concepts (WPLSoft family) is the Vigor's Z (the low word), F its V: printed
    // as the Vigor names them.
    EXPECT_EQ(formatAddress(vigor(), d.index), QStringLiteral("Z0"));
    EXPECT_EQ(operand("D0Z0"), d);
    const Operand k = operand("K10F0");
    EXPECT_EQ(k.kind, Operand::Kind::Constant);
    EXPECT_EQ(k.constant.value, 10);
    EXPECT_EQ(formatAddress(vigor(), k.index), QStringLiteral("V0"));
    EXPECT_EQ(formatOperand(vigor(), k), QStringLiteral("K10V0"));
    const Operand g = operand("K4M0E1");
    EXPECT_EQ(g.digits, 4);
    EXPECT_EQ(formatOperand(vigor(), g), QStringLiteral("K4M0Z1"));
    EXPECT_EQ(formatOperand(vigor(), operand("t5f7")), QStringLiteral("T5V7"));
    EXPECT_EQ(formatOperand(vigor(), operand("C3v2")), QStringLiteral("C3V2"));
    // Index registers are plain words too (PLC concepts (WPLSoft family) 1.4: "can be used as
    // general purpose register").
    EXPECT_EQ(formatOperand(vigor(), operand("E7")), QStringLiteral("Z7"));
    EXPECT_EQ(formatOperand(vigor(), operand("V7")), QStringLiteral("V7"));
}

TEST(VigorOperands, WhatIsNoOperandSaysWhy) {
    EXPECT_TRUE(operandError("K5M0").contains(QLatin1String("K1..K4"))) << "16-bit words";
    EXPECT_TRUE(operandError("K0M0").contains(QLatin1String("K1..K4")));
    EXPECT_TRUE(operandError("K4D0").contains(QLatin1String("bit device")));
    // The 16 bits of K4Y770 run past Y777, the last output.
    const QString past = operandError("K4Y770");
    EXPECT_TRUE(past.contains(QLatin1String("Y770..Y1007"))) << past.toStdString();
    EXPECT_TRUE(past.contains(QLatin1String("Y1000"))) << past.toStdString();
    // K4M5112 would need M5120.., which does not exist before M9000.
    EXPECT_FALSE(operandError("K4M5112").isEmpty());
    EXPECT_TRUE(operandError("K2M5104").isEmpty()); // M5104..M5111
    EXPECT_TRUE(operandError("D0E8").contains(QLatin1String("Z0..Z7")));
    EXPECT_TRUE(operandError("D0Z8").contains(QLatin1String("Z0..Z7")));
    EXPECT_TRUE(operandError("E0E1").contains(QLatin1String("cannot be indexed")));
    EXPECT_TRUE(operandError("V0Z1").contains(QLatin1String("cannot be indexed")));
    EXPECT_TRUE(operandError("M0E0").contains(QLatin1String("not the bit M0")));
    EXPECT_TRUE(operandError("D0X1").contains(QLatin1String("unexpected")));
    // Crossing from M499 into the latched area is one run of bits: M496..M511 exist.
    EXPECT_TRUE(operandError("K4M496").isEmpty());
}

TEST(VigorOperands, ListingsRoundTripWithDigitsAndIndexes) {
    const char *text = "LD= K4M0 K10V0\n"
                       "MOV K4X0 D0Z0\n"
                       "LD X1\n"
                       "AND<> D5V7 K2Y10\n"
                       "CMP K1M20 K5 M10\n"
                       "LD X2\n"
                       "ADD K4M0Z1 D1 K2Y0\n"
                       "LD X3\n"
                       "TMR T0 D10Z2\n"
                       "LD X0\n"
                       "INC K1Y0\n"
                       "END\n";
    const ParseResult r = parseVigor(text);
    ASSERT_TRUE(r.ok()) << errors(r);
    const QString printed = printInstructionList(r.list);
    EXPECT_EQ(printed, QString::fromLatin1(text));
    // The spellings of PLC concepts (WPLSoft family) read as the same program.
    const ParseResult wplsoft =
        parseVigor("LD= K4M0 K10F0\nMOV K4X0 D0E0\nLD X1\nAND<> D5F7 K2Y10\nCMP K1M20 K5 M10\n"
                   "LD X2\nADD K4M0E1 D1 K2Y0\nLD X3\nTMR T0 D10E2\nLD X0\nINC K1Y0\nEND\n");
    ASSERT_TRUE(wplsoft.ok()) << errors(wplsoft);
    EXPECT_EQ(printInstructionList(wplsoft.list), printed);
    for (const Diagnostic &d : checkList(r.list))
        EXPECT_NE(d.severity, Severity::Error) << d.message.toStdString();
}

TEST(VigorOperands, OnlyWordSlotsTakeThem) {
    ParseResult r = parseVigor("LD K1X0\nOUT Y0\nEND");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].column, 4);
    EXPECT_TRUE(r.errors[0].message.contains(QLatin1String("is a word (4 bits)")));
    r = parseVigor("LD X0\nOUT M0E0\nEND");
    ASSERT_EQ(r.errors.size(), 1u);
    r = parseVigor("LD X0\nOUT K1Y0\nEND");
    ASSERT_EQ(r.errors.size(), 1u);
    r = parseVigor("LD X0\nTMR T0E0 K10\nEND");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(r.errors[0].message.contains(QLatin1String("index register")));
    r = parseVigor("LD X0\nMOV D0 K10F0\nEND");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(r.errors[0].message.contains(QLatin1String("constant")));
    r = parseVigor("LD X0\nBMOV D0 D10 K2F0\nEND"); // n is a plain constant
    EXPECT_FALSE(r.ok());
    // K2F0 is the constant 2 indexed by F0 (V0), never a digit group of the word F0.
    const Operand k = operand("K2F0");
    EXPECT_EQ(k.kind, Operand::Kind::Constant);
    EXPECT_EQ(k.digits, 0);
}

TEST(VigorOperands, ChecksReadTheGroupAsTheDevicesItWrites) {
    // X is read-only: K4X0 as a destination is OP002, at its column.
    std::vector<Diagnostic> found = check("LD X0\nMOV K5 K4X0\nEND");
    ASSERT_TRUE(has(found, "OP002", "K4X0 cannot be written")) << found.size();
    // K4M9000 writes M9000 (ON while the PLC runs) among its bits; K1M9004 does not.
    found = check("LD X0\nMOV K5 K1M9000\nEND");
    EXPECT_TRUE(has(found, "OP002", "the PLC drives it"));
    EXPECT_FALSE(parseVigor("LD X0\nMOV K5 K2M8996\nEND").ok()); // M8996.. does not exist
    found = check("LD X0\nMOV K5 K1M9004\nEND");
    EXPECT_FALSE(has(found, "OP002", ""));
    // A block move counts words: BMOV takes no digit group (OP005, as the simulator says).
    found = check("LD X0\nBMOV K4M0 D0 K2\nEND");
    EXPECT_TRUE(has(found, "OP005", "BMOV moves whole words: K4M0"));
    found = check("LD X0\nBMOV D0E0 D10F1 K2\nEND");
    EXPECT_FALSE(has(found, "OP005", ""));
}

// The example programs of the Vigor M/VB/VH communication manual (VB-1COM): digit groups in TO
// / FROM, accepted, never an error; simulated (docs/network.md), so no SIM100 either.
TEST(VigorOperands, VbOneComProgramsWithDigitGroupsPassTheChecks) {
    const std::vector<Diagnostic> found = check("LD M9000\n"
                                                "TO K1 K1 K1M20 K1\n"
                                                "LD M9000\n"
                                                "FROM K1 K28 K2M30 K1\n"
                                                "END\n");
    int notSimulated = 0;
    for (const Diagnostic &d : found) {
        EXPECT_NE(d.severity, Severity::Error) << d.message.toStdString();
        notSimulated += d.code == QLatin1String("SIM100");
    }
    EXPECT_EQ(notSimulated, 0);
}

TEST(VigorOperands, TheLadderCarriesThemBothWays) {
    const ParseResult r = parseVigor("LD= K4M0 K10F0\nAND X1\nMOV K2X4 D0E0\nEND\n");
    ASSERT_TRUE(r.ok()) << errors(r);
    const ToLadderResult ladder = listToLadder(r.list);
    ASSERT_TRUE(ladder.ok());
    const QString text = printLadderText(ladder.ladder);
    EXPECT_TRUE(text.contains(QLatin1String("K4M0=K10V0"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QLatin1String("MOV K2X4 D0Z0"))) << text.toStdString();
    const LadderTextResult back = parseLadderText(vigor(), text);
    ASSERT_TRUE(back.ok()) << back.errors.front().message.toStdString();
    const ToListingResult list = ladderToList(back.ladder);
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(printInstructionList(list.list), printInstructionList(r.list));
}

TEST(VigorOperands, AContactInTheLadderTakesNoWord) {
    QString error;
    EXPECT_FALSE(contactFromText(vigor(), QStringLiteral("K1X0"), &error));
    EXPECT_TRUE(error.contains(QLatin1String("contact takes a bit device"))) << error.toStdString();
    EXPECT_TRUE(contactFromText(vigor(), QStringLiteral("K1X0>=K2F1"), &error));
}

// The statements of the example programs of the Vigor M/VB/VH communication manual, verbatim:
// each is accepted, warned as not simulated, and takes the FX family's 16-bit size (one step
// and two per operand; neither manual gives step counts, docs/targets.md).
TEST(VigorOperands, CommunicationStatementsParseWithTheirSteps) {
    // statement, steps, simulated (no SIM100; the communication instructions run in a network,
    // docs/network.md; REF alone is not simulated)
    const std::tuple<const char *, int, bool> statements[] = {
        {"VRRD K1 D0", 5, true},
        {"LINK D1000 D100", 5, true},
        {"MBUS D1000 D100", 5, true},
        {"RS D0 D200 D100 D201", 9, true},
        {"HEX D59 D106 K2", 7, true},
        {"ASCI D111 D12 K4", 7, true},
        {"CCD D2 D102 K15", 7, true},
        {"CCD D52 D104 K11", 7, true},
        {"SMOV D55 K2 K2 D110 K4", 11, true},
        {"TO K1 K1000 D0 K19", 9, true},
        {"FROM K1 K2000 D50 K11", 9, true},
        {"REF X0 K8", 5, false},
        {"SWAP D0", 3, true},
        {"TO K1 K1 K1M20 K1", 9, true},
        {"FROM K1 K28 K2M30 K1", 9, true},
        // B-3-9 and B-4-5: two ASCII characters a call; B-4-5's communication format.
        {"DMOV H00310035 D4", 9, true},
        {"DMOV H00310030 D2", 9, true},
        {"DMOV H00320030 D10", 9, true},
        {"DMOV H00310036 D4", 9, true},
        {"TOP K1 K0 H7096 K1", 9, true}};
    for (const auto &[statement, steps, simulated] : statements) {
        SCOPED_TRACE(statement);
        const ParseResult r = parseInstructionList(
            vigor(), QStringLiteral("LD M9000\n%1\nEND").arg(QLatin1String(statement)));
        ASSERT_TRUE(r.ok()) << errors(r);
        EXPECT_EQ(instructionSteps(vigor(), r.list.instructions[1]), steps);
        const std::vector<Diagnostic> found = checkList(r.list);
        if (simulated) {
            EXPECT_TRUE(found.empty())
                << (found.empty() ? "" : found.front().message.toStdString());
            continue;
        }
        ASSERT_EQ(found.size(), 1u);
        EXPECT_EQ(found[0].code, QStringLiteral("SIM100"));
        EXPECT_EQ(found[0].location.line, 2);
    }
}

// The FNC numbers the Vigor M/VB/VH communication manual and the FX family give them: MOV 12
// (DMOV its 32-bit form), TO 79 (TOP its pulse form), CCD 84; "DMOV(12)" names the same
// instruction.
TEST(VigorOperands, FunctionNumbersOfTheSeedInstructions) {
    ASSERT_NE(vigor().findInstruction(QStringLiteral("DMOV")), nullptr);
    EXPECT_EQ(vigor().findInstruction(QStringLiteral("DMOV"))->functionCode, 12);
    EXPECT_TRUE(vigor().findInstruction(QStringLiteral("DMOV"))->doubleWord);
    ASSERT_NE(vigor().findInstruction(QStringLiteral("TOP")), nullptr);
    EXPECT_EQ(vigor().findInstruction(QStringLiteral("TOP"))->functionCode, 79);
    EXPECT_EQ(vigor().findInstruction(QStringLiteral("CCD"))->functionCode, 84);
    EXPECT_EQ(vigor().findInstruction(QStringLiteral("DMOV(12)")),
              vigor().findInstruction(QStringLiteral("DMOV")));
}
