// The terminal strips of the models (ModelVariant::terminals) name devices the model has, in
// the counts the manuals give.

#include "model/target/address.h"
#include "model/target/target.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

int areaIndex(const Target &t, const QString &key) {
    for (int k = 0; k < static_cast<int>(t.areas.size()); ++k)
        if (t.area(k).key == key)
            return k;
    return -1;
}

// inputs, outputs (bit terminals), analog inputs, analog outputs (word terminals).
std::array<int, 4> counts(const Target &t, const ModelVariant &m) {
    std::array<int, 4> c{};
    for (const TerminalBlock &b : m.terminals) {
        const Area &a = t.area(areaIndex(t, b.area));
        c[(b.words() ? 2 : 0) + (a.writable ? 1 : 0)] += b.count;
    }
    return c;
}

} // namespace

TEST(Terminals, EveryBlockNamesDevicesTheModelHas) {
    for (const Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (const ModelVariant &m : t.models) {
            EXPECT_FALSE(m.terminals.empty()) << m.name.toStdString();
            for (const TerminalBlock &b : m.terminals) {
                const int area = areaIndex(t, b.area);
                ASSERT_GE(area, 0) << m.name.toStdString() << " " << b.area.toStdString();
                const bool channelBits = t.area(area).kind == AreaKind::Channel && !b.words();
                for (int k = 0; k < b.count; ++k) {
                    const Address a =
                        channelBits ? Address{area, b.first, k} : Address{area, b.first + k, -1};
                    const QString text = formatAddress(t, a);
                    EXPECT_TRUE(std::holds_alternative<Address>(parseAddress(t, text, &m)))
                        << m.name.toStdString() << ": " << text.toStdString();
                }
            }
        }
    }
}

TEST(Terminals, CountsAreThoseOfTheManuals) {
    const Target &vpc = Target::get(Family::Vpc);
    // VPC user's manual, II: VPC3224A63 32 in / 24 out / 6 analog in / 3 analog out.
    EXPECT_EQ(counts(vpc, *vpc.model(QStringLiteral("VPC3224A63"))),
              (std::array<int, 4>{32, 24, 6, 3}));
    EXPECT_EQ(counts(vpc, *vpc.model(QStringLiteral("VPC106"))), (std::array<int, 4>{10, 6, 0, 0}));
    const Target &cpm1 = Target::get(Family::Cpm1);
    // Omron CPM1 guide: 12 inputs / 8 outputs; two analog setting pots (channels 250, 251, BCD
    // 0..200).
    EXPECT_EQ(counts(cpm1, *cpm1.model(QStringLiteral("CPM1-20CDR"))),
              (std::array<int, 4>{12, 8, 2, 0}));
    EXPECT_EQ(counts(cpm1, *cpm1.model(QStringLiteral("CPM1-30CDR"))),
              (std::array<int, 4>{18, 12, 2, 0}));
    const ModelVariant &cpm20 = *cpm1.model(QStringLiteral("CPM1-20CDR"));
    ASSERT_EQ(cpm20.terminals.size(), 3u);
    EXPECT_EQ(cpm20.terminals[0].count, 12);
    EXPECT_EQ(cpm20.terminals[1].count, 8);
    EXPECT_TRUE(cpm20.terminals[2].bcd);
    EXPECT_EQ(cpm20.terminals[2].highest, 200);
    const Target &pl110 = Target::get(Family::Pl110);
    // PL110 manual 1.1: 8 digital inputs, 8 relay outputs, 4 analog inputs (10 bit), 1 analog out.
    EXPECT_EQ(counts(pl110, *pl110.model(QStringLiteral("PL110-2A"))),
              (std::array<int, 4>{8, 8, 4, 1}));
    const Target &vigor = Target::get(Family::Vigor);
    EXPECT_EQ(counts(vigor, *vigor.model(QStringLiteral("VB"))),
              (std::array<int, 4>{16, 16, 0, 0}));
}
