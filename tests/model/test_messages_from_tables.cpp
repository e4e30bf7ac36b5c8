// A family is a table, its messages too: what a message says of a family (its name, how it
// writes constants, which values an operand takes, which device to show as an example) is
// read from the target's fields, so a fifth PLC, here a copy of a table with other fields,
// gets its own facts in the same texts, without a new text.

#include "model/checks/operand_rules.h"
#include "model/target/address.h"
#include "model/target/target.h"
#include "model/target/target_lists.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

QString constantError(const Target &t, const char *text) {
    const auto r = parseConstant(t, QString::fromLatin1(text));
    if (!std::holds_alternative<AddressError>(r)) {
        ADD_FAILURE() << text << " parsed";
        return {};
    }
    return std::get<AddressError>(r).message;
}

} // namespace

TEST(MessagesFromTables, AConstantOfAnotherStyleIsRefusedInTheTargetsOwnWords) {
    EXPECT_EQ(constantError(Target::get(Family::Vpc), "#12"),
              QStringLiteral("#12: VPC has no # constants; write a constant as a plain number "
                             "(e.g. 150)"));
    EXPECT_EQ(constantError(Target::get(Family::Vigor), "#12"),
              QStringLiteral("#12: Vigor has no # constants; write a constant as K (decimal) "
                             "or H (hexadecimal)"));
    // A fifth family: the name and the notation of its table, nothing written for it.
    Target fifth = Target::get(Family::Vpc);
    fifth.displayName = QStringLiteral("Newco 9");
    fifth.constants = ConstantNotation{};
    fifth.constants.prefixed = true;
    EXPECT_EQ(constantError(fifth, "#12"),
              QStringLiteral("#12: Newco 9 has no # constants; write a constant as K (decimal) "
                             "or H (hexadecimal)"));
    EXPECT_EQ(constantError(fifth, "12"),
              QStringLiteral("12: write a constant as K (decimal) or H (hexadecimal)"));
    fifth.constants = ConstantNotation{};
    fifth.constants.bcd = true;
    EXPECT_EQ(constantError(fifth, "12"),
              QStringLiteral("12: write a constant with # (e.g. #0150)"));
}

// The PL110 time base: "10, 100 or 1000" comes from the operand's allowedValues; another
// table's values give another message.
TEST(MessagesFromTables, AnOperandsAllowedValuesComeFromItsSpec) {
    const Target &pl110 = Target::get(Family::Pl110);
    const InstructionSpec *ton = pl110.findInstruction(QStringLiteral("TON"));
    ASSERT_NE(ton, nullptr);
    ASSERT_GE(ton->operands.size(), 3u);
    Instruction ins;
    ins.spec = ton;
    ins.operands.resize(3);
    ins.operands[2].kind = Operand::Kind::Constant;
    ins.operands[2].constant = Constant{50, Constant::Style::Plain};
    auto breaches = operandBreaches(pl110, ins);
    ASSERT_EQ(breaches.size(), 1u);
    EXPECT_EQ(breaches[0].message,
              QStringLiteral("the time base (ms) of TON must be 10, 100 or 1000, not 50"));
    InstructionSpec other = *ton;
    other.operands[2].allowedValues = {1, 50};
    ins.spec = &other;
    ins.operands[2].constant = Constant{10, Constant::Style::Plain};
    breaches = operandBreaches(pl110, ins);
    ASSERT_EQ(breaches.size(), 1u);
    EXPECT_EQ(breaches[0].message,
              QStringLiteral("the time base (ms) of TON must be 1 or 50, not 10"));
}

TEST(MessagesFromTables, ExampleDevicesAreEachFamilysOwn) {
    EXPECT_EQ(exampleDevice(Target::get(Family::Vigor)), QStringLiteral("X0"));
    EXPECT_EQ(exampleDevice(Target::get(Family::Vigor), true), QStringLiteral("Y0"));
    EXPECT_EQ(exampleDevice(Target::get(Family::Vpc)), QStringLiteral("i00"));
    EXPECT_EQ(exampleDevice(Target::get(Family::Cpm1)), QStringLiteral("000.00"));
    EXPECT_EQ(exampleDevice(Target::get(Family::Pl110)), QStringLiteral("I1"));
    EXPECT_EQ(exampleDevice(Target::get(Family::Pl110), true), QStringLiteral("Q1"));
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (bool output : {false, true}) {
            const QString device = exampleDevice(t, output);
            ASSERT_FALSE(device.isEmpty()) << t.id.toStdString();
            EXPECT_TRUE(std::holds_alternative<Address>(parseAddress(t, device)))
                << device.toStdString();
        }
    }
}

TEST(MessagesFromTables, ExampleWordsAreEachFamilysDataMemory) {
    EXPECT_EQ(exampleWord(Target::get(Family::Vigor), 10), QStringLiteral("D10"));
    EXPECT_EQ(exampleWordRange(Target::get(Family::Vigor), 4), QStringLiteral("D0..D3"));
    EXPECT_EQ(exampleWord(Target::get(Family::Cpm1), 10), QStringLiteral("DM 0010"));
    EXPECT_EQ(exampleWord(Target::get(Family::Pl110), 10), QStringLiteral("V10"));
    EXPECT_EQ(exampleWordRange(Target::get(Family::Pl110), 4), QStringLiteral("V0..V3"));
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        const QString word = exampleWord(t, 10);
        ASSERT_FALSE(word.isEmpty()) << t.id.toStdString();
        const auto parsed = parseAddress(t, word);
        ASSERT_TRUE(std::holds_alternative<Address>(parsed)) << word.toStdString();
        const Address a = std::get<Address>(parsed);
        EXPECT_TRUE(a.bit < 0 && t.area(a.area).kind != AreaKind::Bit) << word.toStdString();
    }
}

TEST(MessagesFromTables, TheFamiliesAreListedFromTheRegistry) {
    const QStringList ids = targetIds();
    ASSERT_EQ(ids.size(), static_cast<qsizetype>(Target::families().size()));
    EXPECT_EQ(ids, (QStringList{"vpc", "vigor", "cpm1", "pl110"}));
    EXPECT_EQ(targetDisplayNames().size(), ids.size());
    EXPECT_EQ(targetDisplayNames().at(1), Target::get(Family::Vigor).displayName);
}
