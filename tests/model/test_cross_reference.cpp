// The cross reference without a display: each device's uses by rung and step, as a contact, a
// coil or in a box, filtered by a device or a prefix, and stopped at a limit that says whether
// anything was left out.

#include "model/listing/cross_reference.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

struct Listed {
    InstructionList list;
    std::vector<int> rungFirst;
};

// Each string is a rung.
Listed rungs(const QStringList &texts) {
    Listed out;
    const Target &vigor = Target::get(Family::Vigor);
    const ParseResult parsed = parseInstructionList(vigor, texts.join(QString()));
    EXPECT_TRUE(parsed.ok());
    out.list = parsed.list;
    int first = 0;
    for (const QString &rung : texts) {
        out.rungFirst.push_back(first);
        first += static_cast<int>(rung.count(QLatin1Char('\n')));
    }
    out.rungFirst.push_back(first);
    return out;
}

CrossReference uses(const Listed &program, const QString &filter, int maxUses = 100) {
    return crossReference(Target::get(Family::Vigor), nullptr, program.list.instructions,
                          program.rungFirst, filter, maxUses);
}

QStringList devicesOf(const CrossReference &xref) {
    QStringList out;
    for (const CrossReference::Device &d : xref.devices)
        out << formatAddress(Target::get(Family::Vigor), d.address);
    return out;
}

const Listed &example() {
    static const Listed program =
        rungs({QStringLiteral("LD X0\nOUT Y0\n"), QStringLiteral("LDI Y0\nAND X1\nSET M0\n"),
               QStringLiteral("LD M0\nMOV D0 D0\nRST M0\n"), QStringLiteral("END\n")});
    return program;
}

} // namespace

TEST(CrossReference, EachUseHasItsRungStepAndKindOnce) {
    const CrossReference all = uses(example(), QString());
    EXPECT_FALSE(all.exact);
    EXPECT_FALSE(all.capped);
    EXPECT_EQ(devicesOf(all), (QStringList{QStringLiteral("X0"), QStringLiteral("X1"),
                                          QStringLiteral("Y0"), QStringLiteral("M0"),
                                          QStringLiteral("D0")}));
    const CrossReference::Device &m0 = all.devices[3];
    ASSERT_EQ(m0.uses.size(), 3u);
    EXPECT_EQ(m0.uses[0].rung, 1);
    EXPECT_EQ(m0.uses[0].step, 4);
    EXPECT_EQ(m0.uses[0].use, DeviceUse::Coil); // SET
    EXPECT_EQ(m0.uses[0].instruction, QStringLiteral("SET M0"));
    EXPECT_EQ(m0.uses[1].use, DeviceUse::Contact);
    EXPECT_EQ(m0.uses[1].rung, 2);
    EXPECT_EQ(m0.uses[2].use, DeviceUse::Coil); // RST
    // MOV D0 D0 names D0 twice: one use, in a box.
    const CrossReference::Device &d0 = all.devices[4];
    ASSERT_EQ(d0.uses.size(), 1u);
    EXPECT_EQ(d0.uses[0].use, DeviceUse::Box);
    EXPECT_EQ(d0.uses[0].instruction, QStringLiteral("MOV D0 D0"));
    EXPECT_EQ(all.devices[2].uses[1].use, DeviceUse::Contact); // LDI Y0
    EXPECT_EQ(all.uses, 8);
}

TEST(CrossReference, AFilterIsADeviceElseAPrefixInAnyCase) {
    const CrossReference x0 = uses(example(), QStringLiteral(" x0 "));
    EXPECT_TRUE(x0.exact);
    EXPECT_EQ(devicesOf(x0), QStringList{QStringLiteral("X0")});
    const CrossReference inputs = uses(example(), QStringLiteral("x"));
    EXPECT_FALSE(inputs.exact);
    EXPECT_EQ(devicesOf(inputs), (QStringList{QStringLiteral("X0"), QStringLiteral("X1")}));
    EXPECT_TRUE(uses(example(), QStringLiteral("X7")).devices.empty()); // a device unused
    EXPECT_TRUE(uses(example(), QStringLiteral("Q")).devices.empty());
}

TEST(CrossReference, TheLimitSaysWhetherAnyUseWasLeftOut) {
    const CrossReference exactly = uses(example(), QString(), 8);
    EXPECT_FALSE(exactly.capped);
    EXPECT_EQ(exactly.uses, 8);
    const CrossReference short1 = uses(example(), QString(), 7);
    EXPECT_TRUE(short1.capped);
    EXPECT_EQ(short1.uses, 7);
    EXPECT_EQ(devicesOf(short1).size(), 5); // RST M0 was the one left out
    const CrossReference first = uses(example(), QString(), 1);
    EXPECT_TRUE(first.capped);
    EXPECT_EQ(devicesOf(first), QStringList{QStringLiteral("X0")}); // no device without uses
    EXPECT_TRUE(uses(example(), QString(), 0).devices.empty());
}
