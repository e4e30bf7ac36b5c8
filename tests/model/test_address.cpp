#include "model/target/address.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <limits>

// Readable failure output: gtest would print a QString as an array of UTF-16 units.
static void PrintTo(const QString &s, std::ostream *os) {
    *os << '"' << s.toStdString() << '"';
}

using namespace rung::model;

namespace {

using rung::testing::cpm1;
using rung::testing::pl110;
using rung::testing::vigor;
using rung::testing::vpc;

int areaIndex(const Target &t, const char *key) {
    for (int i = 0; i < static_cast<int>(t.areas.size()); ++i)
        if (t.area(i).key == QLatin1String(key))
            return i;
    ADD_FAILURE() << "no area " << key;
    return -1;
}

// The parsed address, or a failure naming the error.
Address parsed(const Target &t, const QString &text, const ModelVariant *model = nullptr) {
    const auto r = parseAddress(t, text, model);
    if (const auto *e = std::get_if<AddressError>(&r)) {
        ADD_FAILURE() << text.toStdString() << ": " << e->message.toStdString();
        return {};
    }
    return std::get<Address>(r);
}

// The error message, or a failure when the text parses.
AddressError failure(const Target &t, const QString &text, const ModelVariant *model = nullptr) {
    const auto r = parseAddress(t, text, model);
    if (const auto *a = std::get_if<Address>(&r)) {
        ADD_FAILURE() << text.toStdString() << " parsed as area " << a->area << " index "
                      << a->index;
        return {};
    }
    return std::get<AddressError>(r);
}

struct Device {
    Family family;
    const char *text;
    const char *area;
    int index;
    int bit;
};

// First and last element of every area, spelled as the manuals (docs/targets.md) write them.
const Device kDevices[] = {
    {Family::Vpc, "i00", "i", 0, -1},
    {Family::Vpc, "i39", "i", 39, -1},
    {Family::Vpc, "o00", "o", 0, -1},
    {Family::Vpc, "o29", "o", 29, -1},
    {Family::Vpc, "t00", "t", 0, -1},
    {Family::Vpc, "t31", "t", 31, -1},
    {Family::Vpc, "c00", "c", 0, -1},
    {Family::Vpc, "c31", "c", 31, -1},
    {Family::Vpc, "r00", "r", 0, -1},
    {Family::Vpc, "r71", "r", 71, -1},
    {Family::Vpc, "r72", "rl", 72, -1},
    {Family::Vpc, "r87", "rl", 87, -1},
    {Family::Vpc, "r88", "rsw", 88, -1},
    {Family::Vpc, "r89", "rsw", 89, -1},
    {Family::Vpc, "r90", "rs", 90, -1},
    {Family::Vpc, "r95", "rs", 95, -1},
    {Family::Vpc, "a00", "a", 0, -1},
    {Family::Vpc, "a07", "a", 7, -1},
    {Family::Vpc, "d00", "d", 0, -1},
    {Family::Vpc, "d03", "d", 3, -1},
    {Family::Vpc, "p00", "p", 0, -1},
    {Family::Vpc, "p75", "p", 75, -1},
    {Family::Vpc, "p76", "p76", 76, -1},
    {Family::Vpc, "p77", "p77", 77, -1},
    {Family::Vigor, "X0", "X", 0, -1},
    {Family::Vigor, "X777", "X", 0777, -1},
    {Family::Vigor, "Y0", "Y", 0, -1},
    {Family::Vigor, "Y777", "Y", 0777, -1},
    {Family::Vigor, "M0", "M", 0, -1},
    {Family::Vigor, "M499", "M", 499, -1},
    {Family::Vigor, "M500", "ML", 500, -1},
    {Family::Vigor, "M5119", "ML", 5119, -1},
    {Family::Vigor, "M9000", "SM", 9000, -1},
    {Family::Vigor, "M9255", "SM", 9255, -1},
    {Family::Vigor, "S0", "S", 0, -1},
    {Family::Vigor, "S999", "SL", 999, -1},
    {Family::Vigor, "T0", "T", 0, -1},
    {Family::Vigor, "T199", "T", 199, -1},
    {Family::Vigor, "T200", "T10", 200, -1},
    {Family::Vigor, "T249", "T1R", 249, -1},
    {Family::Vigor, "T255", "TR", 255, -1},
    {Family::Vigor, "Z7", "Z", 7, -1},
    {Family::Vigor, "V0", "V", 0, -1},
    {Family::Vigor, "C0", "C", 0, -1},
    {Family::Vigor, "C199", "CL", 199, -1},
    {Family::Vigor, "C200", "C32", 200, -1},
    {Family::Vigor, "C255", "C32", 255, -1},
    {Family::Vigor, "D0", "D", 0, -1},
    {Family::Vigor, "D8191", "DL", 8191, -1},
    {Family::Vigor, "D9000", "SD", 9000, -1},
    {Family::Vigor, "D9255", "SD", 9255, -1},
    {Family::Cpm1, "000.00", "IN", 0, 0},
    {Family::Cpm1, "009.15", "IN", 9, 15},
    {Family::Cpm1, "010.00", "OUT", 10, 0},
    {Family::Cpm1, "019.15", "OUT", 19, 15},
    {Family::Cpm1, "200.00", "WR", 200, 0},
    {Family::Cpm1, "231.15", "WR", 231, 15},
    {Family::Cpm1, "253.13", "SR", 253, 13},
    {Family::Cpm1, "255.15", "SR", 255, 15},
    {Family::Cpm1, "250", "SR", 250, -1},
    {Family::Cpm1, "HR00.00", "HR", 0, 0},
    {Family::Cpm1, "HR19.15", "HR", 19, 15},
    {Family::Cpm1, "TIM 000", "TIM", 0, -1},
    {Family::Cpm1, "TIM 127", "TIM", 127, -1},
    {Family::Cpm1, "CNT 000", "CNT", 0, -1},
    {Family::Cpm1, "CNT 127", "CNT", 127, -1},
    {Family::Cpm1, "DM 0000", "DM", 0, -1},
    {Family::Cpm1, "DM 1023", "DM", 1023, -1},
    {Family::Cpm1, "DM 6144", "DMR", 6144, -1},
    {Family::Cpm1, "DM 6667", "DMR", 6667, -1},
    {Family::Pl110, "I1", "I", 1, -1},
    {Family::Pl110, "I256", "I", 256, -1},
    {Family::Pl110, "Q1", "Q", 1, -1},
    {Family::Pl110, "Q256", "Q", 256, -1},
    {Family::Pl110, "B1", "B", 1, -1},
    {Family::Pl110, "B32", "B", 32, -1},
    {Family::Pl110, "M1", "M", 1, -1},
    {Family::Pl110, "M128", "M", 128, -1},
    {Family::Pl110, "T1", "T", 1, -1},
    {Family::Pl110, "T48", "T", 48, -1},
    {Family::Pl110, "T64", "T49", 64, -1},
    {Family::Pl110, "C1", "C", 1, -1},
    {Family::Pl110, "C16", "C", 16, -1},
    {Family::Pl110, "V0", "V", 0, -1},
    {Family::Pl110, "V349", "V", 349, -1},
    {Family::Pl110, "V3.5", "V", 3, 5},
    {Family::Pl110, "SM0.0", "SM", 0, 0},
    {Family::Pl110, "SM0.13", "SM", 0, 13},
    {Family::Pl110, "SM99", "SM", 99, -1},
    {Family::Pl110, "AI1", "AI", 1, -1},
    {Family::Pl110, "AI4", "AI", 4, -1},
    {Family::Pl110, "AQ1", "AQ", 1, -1},
    {Family::Pl110, "PT48", "PT", 48, -1},
    {Family::Pl110, "PT64", "PT49", 64, -1},
    {Family::Pl110, "VD348", "VD", 348, -1},
    {Family::Pl110, "SMD20", "SMD", 20, -1},
    {Family::Pl110, "TR4", "TR", 4, -1},
    {Family::Pl110, "PV16", "PV", 16, -1},
    {Family::Pl110, "EEP999", "EEP", 999, -1},
    {Family::Pl110, "MMC12999", "MMC", 12999, -1},
    {Family::Pl110, "DISP167", "DISP", 167, -1},
};

} // namespace

TEST(Address, ManualDevicesParseToTheirAreaAndPrintBackVerbatim) {
    for (const Device &d : kDevices) {
        SCOPED_TRACE(d.text);
        const Target &t = Target::get(d.family);
        const Address a = parsed(t, QString::fromLatin1(d.text));
        EXPECT_EQ(a.area, areaIndex(t, d.area));
        EXPECT_EQ(a.index, d.index);
        EXPECT_EQ(a.bit, d.bit);
        EXPECT_EQ(formatAddress(t, a), QString::fromLatin1(d.text));
    }
}

TEST(Address, EveryAreaRoundTripsItsFirstAndLastElement) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (int i = 0; i < static_cast<int>(t.areas.size()); ++i) {
            const Area &area = t.area(i);
            for (int index : {area.first, area.last}) {
                const Address a{i, index, -1};
                const QString text = formatAddress(t, a);
                SCOPED_TRACE(text.toStdString());
                EXPECT_EQ(parsed(t, text), a);
            }
        }
    }
}

TEST(Address, OneBeyondEveryPrefixsRangeIsAnError) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (int i = 0; i < static_cast<int>(t.areas.size()); ++i) {
            const Area &area = t.area(i);
            // The span of all areas written with this prefix (M0..M5119 and M9000.. are two
            // spans on Vigor; the step past each span's end must fail).
            int hi = area.last;
            for (const Area &other : t.areas)
                if (other.prefix == area.prefix && other.first == hi + 1)
                    hi = other.last;
            if (area.prefix.isEmpty())
                continue; // CPM1 channels: 020 is a valid word of no area; tested below
            Address past{i, hi + 1, -1};
            const QString text = formatAddress(t, past);
            SCOPED_TRACE(text.toStdString());
            bool inAnother = false;
            for (const Area &other : t.areas)
                inAnother = inAnother || (other.prefix == area.prefix && other.first <= hi + 1 &&
                                          hi + 1 <= other.last);
            if (!inAnother) {
                EXPECT_FALSE(failure(t, text).message.isEmpty());
            }
        }
    }
}

TEST(Address, Pl110BitsStartAtOne) {
    EXPECT_EQ(failure(pl110(), QStringLiteral("I0")).message,
              QStringLiteral("I0 is beyond PL110's digital inputs I1..I256"));
    EXPECT_FALSE(failure(pl110(), QStringLiteral("Q0")).message.isEmpty());
    EXPECT_FALSE(failure(pl110(), QStringLiteral("Q257")).message.isEmpty());
    EXPECT_FALSE(failure(pl110(), QStringLiteral("T65")).message.isEmpty());
    EXPECT_FALSE(failure(pl110(), QStringLiteral("C17")).message.isEmpty());
    EXPECT_FALSE(failure(pl110(), QStringLiteral("V350")).message.isEmpty());
    // I20 is bit 3 of word 2 (PL110 manual 2.1.3): element 20 counted from I1.
    EXPECT_EQ(parsed(pl110(), QStringLiteral("I20")).index, 20);
}

TEST(Address, Pl110WordPrefixesOfTheManualAreAliases) {
    // The PL110 manual writes VW30 and SMW4 for word access; they print as V30 and SM4.
    const Address vw = parsed(pl110(), QStringLiteral("VW30"));
    EXPECT_EQ(vw, parsed(pl110(), QStringLiteral("V30")));
    EXPECT_EQ(formatAddress(pl110(), vw), QStringLiteral("V30"));
    EXPECT_EQ(parsed(pl110(), QStringLiteral("SMW4")), parsed(pl110(), QStringLiteral("SM4")));
    EXPECT_EQ(failure(pl110(), QStringLiteral("VW350")).message,
              QStringLiteral("VW350 is beyond PL110's variables V0..V349"));
}

TEST(Address, Pl110BitAreasHaveNoBitSuffix) {
    EXPECT_EQ(failure(pl110(), QStringLiteral("Q1.2")).message,
              QStringLiteral("Q1.2: Q has no bit numbers"));
}

TEST(Address, Pl110DisplayExistsOnlyOnTheModelWithTheTerminal) {
    const ModelVariant *one = pl110().model(QStringLiteral("PL110-1A"));
    const ModelVariant *two = pl110().model(QStringLiteral("PL110-2A"));
    ASSERT_TRUE(one && two);
    EXPECT_EQ(failure(pl110(), QStringLiteral("DISP0"), one).message,
              QStringLiteral("DISP0: PL110-1A has no display characters"));
    EXPECT_EQ(parsed(pl110(), QStringLiteral("DISP0"), two).index, 0);
}

TEST(Address, VigorInputsAndOutputsAreOctal) {
    const AddressError e = failure(vigor(), QStringLiteral("X8"));
    EXPECT_EQ(e.message, QStringLiteral("X8: X is numbered in octal"));
    EXPECT_EQ(e.column, 1);
    EXPECT_EQ(failure(vigor(), QStringLiteral("Y19")).message,
              QStringLiteral("Y19: Y is numbered in octal"));
    EXPECT_EQ(parsed(vigor(), QStringLiteral("X7")).index, 7);
    EXPECT_EQ(parsed(vigor(), QStringLiteral("X10")).index, 8); // X10 follows X7
    EXPECT_EQ(parsed(vigor(), QStringLiteral("Y17")).index, 15);
    EXPECT_EQ(formatAddress(vigor(), Address{areaIndex(vigor(), "X"), 8, -1}),
              QStringLiteral("X10"));
    EXPECT_FALSE(failure(vigor(), QStringLiteral("X1000")).message.isEmpty());
    // M is decimal: M8 and M19 exist.
    EXPECT_EQ(parsed(vigor(), QStringLiteral("M19")).index, 19);
}

TEST(Address, VigorThirtyTwoBitCountersAreTheirOwnArea) {
    EXPECT_EQ(vigor().area(parsed(vigor(), QStringLiteral("C199")).area).wordBits, 16);
    EXPECT_EQ(vigor().area(parsed(vigor(), QStringLiteral("C200")).area).wordBits, 32);
}

TEST(Address, VpcModelNarrowsOutputsWithTheModelsRangeInTheMessage) {
    const ModelVariant *m = vpc().model(QStringLiteral("VPC2416"));
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(failure(vpc(), QStringLiteral("o31"), m).message,
              QStringLiteral("o31 is beyond VPC2416's outputs o00..o15"));
    EXPECT_EQ(failure(vpc(), QStringLiteral("o16"), m).message,
              QStringLiteral("o16 is beyond VPC2416's outputs o00..o15"));
    EXPECT_EQ(parsed(vpc(), QStringLiteral("o15"), m).index, 15);
    EXPECT_EQ(failure(vpc(), QStringLiteral("i24"), m).message,
              QStringLiteral("i24 is beyond VPC2416's inputs i00..i23"));
    EXPECT_EQ(parsed(vpc(), QStringLiteral("i23"), m).index, 23);
    // Without a model the family's full range applies.
    EXPECT_EQ(parsed(vpc(), QStringLiteral("o29")).index, 29);
    EXPECT_EQ(failure(vpc(), QStringLiteral("o30")).message,
              QStringLiteral("o30 is beyond VPC's outputs o00..o29"));
}

TEST(Address, OutOfRangeNamesEverySpanOfThePrefix) {
    // r00..r71, r72..r87, r88..r89 and r90..r95 are one span to the user.
    EXPECT_EQ(failure(vpc(), QStringLiteral("r96")).message,
              QStringLiteral("r96 is beyond VPC's auxiliary relays r00..r95"));
    EXPECT_EQ(failure(vpc(), QStringLiteral("r96"), vpc().model(QStringLiteral("VPC106"))).message,
              QStringLiteral("r96 is beyond VPC106's auxiliary relays r00..r95"));
    EXPECT_EQ(failure(vigor(), QStringLiteral("M9300")).message,
              QStringLiteral("M9300 is beyond Vigor's M0..M5119, M9000..M9255"));
    EXPECT_EQ(failure(vigor(), QStringLiteral("M6000")).message,
              QStringLiteral("M6000 is beyond Vigor's M0..M5119, M9000..M9255"));
    EXPECT_EQ(failure(cpm1(), QStringLiteral("020.00")).message,
              QStringLiteral("020.00 is beyond CPM1's 000..019, 200..255"));
}

TEST(Address, EveryVpcModelAcceptsItsLastInputAndOutputAndRejectsTheNext) {
    struct Io {
        const char *name;
        int in, out, ain, aout;
    };
    // The models' I/O counts: VPC user's manual, II (docs/targets.md).
    const Io models[] = {
        {"VPC106", 10, 6, 0, 0},      {"VPC108A4", 10, 8, 4, 0}, {"VPC1410", 14, 10, 0, 0},
        {"VPC1812", 18, 12, 0, 0},    {"VPC2416", 24, 16, 0, 0}, {"VPC3224L", 32, 24, 0, 0},
        {"VPC3224A63", 32, 24, 6, 3}, {"VPC4030", 40, 30, 0, 0}, {"VPC4030A84", 40, 30, 8, 4}};
    auto name = [](char prefix, int n) {
        return QStringLiteral("%1%2")
            .arg(QChar::fromLatin1(prefix))
            .arg(n, 2, 10, QLatin1Char('0'));
    };
    for (const Io &io : models) {
        SCOPED_TRACE(io.name);
        const ModelVariant *m = vpc().model(QString::fromLatin1(io.name));
        ASSERT_NE(m, nullptr);
        for (auto [prefix, count] :
             {std::pair{'i', io.in}, {'o', io.out}, {'a', io.ain}, std::pair{'d', io.aout}}) {
            if (count > 0) {
                EXPECT_EQ(parsed(vpc(), name(prefix, 0), m).index, 0);
                EXPECT_EQ(parsed(vpc(), name(prefix, count - 1), m).index, count - 1);
            } else {
                EXPECT_FALSE(failure(vpc(), name(prefix, 0), m).message.isEmpty());
            }
            if (count < 40) {
                EXPECT_FALSE(failure(vpc(), name(prefix, count), m).message.isEmpty());
            }
        }
    }
}

TEST(Address, VpcWithoutAnalogChannelsSaysSo) {
    const ModelVariant *m = vpc().model(QStringLiteral("VPC2416"));
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(failure(vpc(), QStringLiteral("a00"), m).message,
              QStringLiteral("a00: VPC2416 has no analog inputs"));
}

TEST(Address, Cpm1ChannelBitAndFiveDigitForms) {
    const Address a = parsed(cpm1(), QStringLiteral("25313"));
    EXPECT_EQ(a, parsed(cpm1(), QStringLiteral("253.13")));
    EXPECT_EQ(formatAddress(cpm1(), a), QStringLiteral("253.13"));
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("01000")), parsed(cpm1(), QStringLiteral("010.00")));
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("00000")), parsed(cpm1(), QStringLiteral("000.00")));
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("23115")), parsed(cpm1(), QStringLiteral("231.15")));
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("HR1915")), parsed(cpm1(), QStringLiteral("HR19.15")));
    EXPECT_EQ(formatAddress(cpm1(), parsed(cpm1(), QStringLiteral("HR0005"))),
              QStringLiteral("HR00.05"));
    // A channel as a word: three digits, no bit.
    const Address word = parsed(cpm1(), QStringLiteral("010"));
    EXPECT_EQ(word.bit, -1);
    EXPECT_EQ(word.index, 10);
    EXPECT_EQ(formatAddress(cpm1(), word), QStringLiteral("010"));
}

TEST(Address, Cpm1BitBeyondFifteenIsNamed) {
    const AddressError e = failure(cpm1(), QStringLiteral("010.16"));
    EXPECT_EQ(e.message, QStringLiteral("010.16: bit 16 is beyond 00..15"));
    EXPECT_EQ(e.column, 4);
    EXPECT_EQ(failure(cpm1(), QStringLiteral("01016")).message,
              QStringLiteral("01016: bit 16 is beyond 00..15"));
    EXPECT_EQ(failure(cpm1(), QStringLiteral("HR05.99")).message,
              QStringLiteral("HR05.99: bit 99 is beyond 00..15"));
    EXPECT_EQ(failure(cpm1(), QStringLiteral("010.")).message,
              QStringLiteral("010.: a bit number is expected after the point"));
}

TEST(Address, Cpm1ModelsNarrowTheIoChannels) {
    const ModelVariant *m = cpm1().model(QStringLiteral("CPM1-20CDR"));
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("000.11"), m).index, 0);
    EXPECT_EQ(failure(cpm1(), QStringLiteral("001.00"), m).message,
              QStringLiteral("001.00 is beyond CPM1-20CDR's input channels 000..000"));
    const ModelVariant *big = cpm1().model(QStringLiteral("CPM1-30CDR"));
    ASSERT_NE(big, nullptr);
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("011.00"), big).index, 11);
}

TEST(Address, Cpm1TimerNumberIsWrittenWithOrWithoutTheSpace) {
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("TIM000")), parsed(cpm1(), QStringLiteral("TIM 000")));
    EXPECT_EQ(parsed(cpm1(), QStringLiteral("tim 5")), parsed(cpm1(), QStringLiteral("TIM 005")));
    EXPECT_FALSE(failure(cpm1(), QStringLiteral("TIM 128")).message.isEmpty());
}

TEST(Address, UnknownPrefixNamesTheTarget) {
    EXPECT_EQ(failure(vigor(), QStringLiteral("W5")).message,
              QStringLiteral("W5 is not a device of Vigor"));
    EXPECT_EQ(failure(vpc(), QStringLiteral("X10")).message,
              QStringLiteral("X10 is not a device of VPC"));
    EXPECT_EQ(failure(pl110(), QStringLiteral("QI1")).message,
              QStringLiteral("QI1 is not a device of PL110"));
}

TEST(Address, PrefixWithoutNumberSaysANumberIsExpected) {
    EXPECT_EQ(failure(vigor(), QStringLiteral("D")).message,
              QStringLiteral("D: a number is expected after D"));
}

TEST(Address, TrailingTextIsReportedAtItsColumn) {
    const AddressError e = failure(vigor(), QStringLiteral("M10x"));
    EXPECT_EQ(e.message, QStringLiteral("M10x: unexpected 'X' after the device"));
    EXPECT_EQ(e.column, 3);
}

TEST(Address, LeadingSpacesShiftTheColumn) {
    const AddressError e = failure(vigor(), QStringLiteral("  X9"));
    EXPECT_EQ(e.column, 3);
}

TEST(Address, EmptyTextIsAnError) {
    EXPECT_EQ(failure(vpc(), QString()).message, QStringLiteral("A device is missing"));
    EXPECT_EQ(failure(vpc(), QStringLiteral("   ")).message, QStringLiteral("A device is missing"));
}

TEST(Address, HugeNumbersAreErrorsNotWrapArounds) {
    EXPECT_EQ(failure(vigor(), QStringLiteral("D99999999999999999999")).message,
              QStringLiteral("D99999999999999999999: the number is too large"));
    EXPECT_FALSE(failure(cpm1(), QStringLiteral("010.99999999999999999")).message.isEmpty());
}

TEST(Address, PrefixesAreCaseInsensitive) {
    EXPECT_EQ(parsed(vpc(), QStringLiteral("I05")), parsed(vpc(), QStringLiteral("i05")));
    EXPECT_EQ(parsed(vigor(), QStringLiteral("x10")), parsed(vigor(), QStringLiteral("X10")));
    EXPECT_EQ(parsed(pl110(), QStringLiteral("sm0.1")), parsed(pl110(), QStringLiteral("SM0.1")));
}

TEST(Address, LongestPrefixWins) {
    EXPECT_EQ(pl110().area(parsed(pl110(), QStringLiteral("MMC5")).area).key,
              QStringLiteral("MMC"));
    EXPECT_EQ(pl110().area(parsed(pl110(), QStringLiteral("M5")).area).key, QStringLiteral("M"));
    EXPECT_EQ(cpm1().area(parsed(cpm1(), QStringLiteral("HR05")).area).key, QStringLiteral("HR"));
}

// A table the registry has not indexed (a fifth family being written, a test's own) parses
// as the indexed one does: parseAddress prepares the prefix spellings itself then.
TEST(Address, ATableNotYetIndexedParsesAsTheIndexedOne) {
    Target fresh;
    fresh.displayName = cpm1().displayName;
    fresh.areas = cpm1().areas;
    fresh.constants = cpm1().constants;
    ASSERT_TRUE(fresh.prefixSpellings().empty());
    for (const char *text : {"HR05", "TIM 000", "tim000", "010.00", "00105", "LR 15.15"})
        EXPECT_EQ(parsed(fresh, QLatin1String(text)), parsed(cpm1(), QLatin1String(text))) << text;
    EXPECT_EQ(failure(fresh, QStringLiteral("HR")).message,
              failure(cpm1(), QStringLiteral("HR")).message);
    fresh.buildIndex();
    EXPECT_EQ(fresh.prefixSpellings().size(), cpm1().prefixSpellings().size());
}

// A copy of a table given an area of its own is indexed again (Target::buildIndex), and the
// new prefix is read with and without spaces, in either case, by its alias too.
TEST(Address, ACopiedTableWithANewAreaReadsItsPrefixOnceIndexedAgain) {
    Target fifth = vigor();
    Area words;
    words.key = QStringLiteral("W");
    words.prefix = QStringLiteral("WR");
    words.prefixAliases = {QStringLiteral("W R")};
    words.kind = AreaKind::Word;
    words.last = 99;
    fifth.areas.push_back(words);
    fifth.buildIndex();
    const int w = static_cast<int>(fifth.areas.size()) - 1;
    for (const char *text : {"WR12", "wr 12", "W R12", "w r 12"})
        EXPECT_EQ(parsed(fifth, QLatin1String(text)), (Address{w, 12, -1})) << text;
    EXPECT_EQ(parsed(fifth, QStringLiteral("D12")), parsed(vigor(), QStringLiteral("D12")));
}

TEST(Address, InvalidAddressPrintsAsQuestionMark) {
    EXPECT_EQ(formatAddress(vpc(), Address{}), QStringLiteral("?"));
    EXPECT_EQ(formatAddress(vpc(), Address{1000, 0, -1}), QStringLiteral("?"));
}

// Constants ---------------------------------------------------------------------------------

Constant constant(const Target &t, const char *text) {
    const auto r = parseConstant(t, QString::fromLatin1(text));
    if (const auto *e = std::get_if<AddressError>(&r)) {
        ADD_FAILURE() << text << ": " << e->message.toStdString();
        return {};
    }
    return std::get<Constant>(r);
}

QString constantError(const Target &t, const char *text) {
    const auto r = parseConstant(t, QString::fromLatin1(text));
    if (std::holds_alternative<Constant>(r)) {
        ADD_FAILURE() << text << " parsed";
        return {};
    }
    return std::get<AddressError>(r).message;
}

TEST(Constant, VigorWritesKDecimalAndHHex) {
    EXPECT_EQ(constant(vigor(), "K10"), (Constant{10, Constant::Style::Decimal}));
    EXPECT_EQ(constant(vigor(), "K1000"), (Constant{1000, Constant::Style::Decimal}));
    EXPECT_EQ(constant(vigor(), "H1F"), (Constant{31, Constant::Style::Hex}));
    EXPECT_EQ(constant(vigor(), "K-5"), (Constant{-5, Constant::Style::Decimal}));
    EXPECT_EQ(formatConstant(vigor(), Constant{31, Constant::Style::Hex}), QStringLiteral("H1F"));
    EXPECT_EQ(formatConstant(vigor(), Constant{10, Constant::Style::Decimal}),
              QStringLiteral("K10"));
    EXPECT_EQ(constantError(vigor(), "10"),
              QStringLiteral("10: write a constant as K (decimal) or H (hexadecimal)"));
    EXPECT_EQ(constantError(vigor(), "K1X"), QStringLiteral("K1X: 'X' is not a digit"));
}

TEST(Constant, Cpm1WritesBcdWithHash) {
    EXPECT_EQ(constant(cpm1(), "#1553"), (Constant{1553, Constant::Style::Bcd}));
    EXPECT_EQ(formatConstant(cpm1(), Constant{150, Constant::Style::Bcd}), QStringLiteral("#0150"));
    // Hex digits make it a hexadecimal word.
    EXPECT_EQ(constant(cpm1(), "#00FF"), (Constant{255, Constant::Style::Hex}));
    EXPECT_EQ(formatConstant(cpm1(), Constant{255, Constant::Style::Hex}), QStringLiteral("#00FF"));
    EXPECT_EQ(constantError(cpm1(), "1553"),
              QStringLiteral("1553: write a constant with # (e.g. #0150)"));
    EXPECT_EQ(constantError(cpm1(), "K10"),
              QStringLiteral("K10: CPM1 writes constants without K or H"));
}

TEST(Constant, VpcAndPl110WritePlainNumbers) {
    EXPECT_EQ(constant(vpc(), "1234"), (Constant{1234, Constant::Style::Plain}));
    EXPECT_EQ(formatConstant(vpc(), Constant{1234, Constant::Style::Plain}),
              QStringLiteral("1234"));
    EXPECT_EQ(constantError(vpc(), "#12"),
              QStringLiteral("#12: VPC has no # constants; write a constant as a plain number "
                             "(e.g. 150)"));
    EXPECT_EQ(constant(pl110(), "-32768"), (Constant{-32768, Constant::Style::Plain}));
    // PLProg writes MOV(Tx = #0): on PL110 '#' marks a plain number.
    EXPECT_EQ(constant(pl110(), "#0"), (Constant{0, Constant::Style::Plain}));
}

TEST(Constant, EmptyAndOversizedConstantsAreErrors) {
    EXPECT_EQ(constantError(vigor(), ""), QStringLiteral("A constant is missing"));
    EXPECT_EQ(constantError(vigor(), "K"), QStringLiteral("K: digits are expected"));
    EXPECT_EQ(constantError(vigor(), "K99999999999999999999"),
              QStringLiteral("K99999999999999999999: the constant is too large"));
}

// Robustness -------------------------------------------------------------------------------

TEST(Address, GarbageGivesAnErrorInsideTheTextOrAnAddressInsideItsArea) {
    // Deterministic mix of prefixes, digits, points, spaces and junk.
    const QString alphabet =
        QStringLiteral("XYMSTCDKHirtocpadIQBVSMAIWP0123456789.. #-+*\t\u00e9\u0663");
    std::uint32_t seed = 12345;
    auto next = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return seed >> 8;
    };
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (int n = 0; n < 3000; ++n) {
            QString text;
            const int length = static_cast<int>(next() % 12);
            for (int k = 0; k < length; ++k)
                text += alphabet[static_cast<qsizetype>(next() % alphabet.size())];
            SCOPED_TRACE(text.toStdString());
            const auto r = parseAddress(t, text, &t.models.front());
            if (const auto *a = std::get_if<Address>(&r)) {
                ASSERT_GE(a->area, 0);
                ASSERT_LT(a->area, static_cast<int>(t.areas.size()));
                EXPECT_GE(a->index, t.area(a->area).first);
                EXPECT_LE(a->index, t.area(a->area).last);
                EXPECT_LE(a->bit, 15);
                // What parses prints back to something that parses to the same address.
                EXPECT_EQ(std::get<Address>(parseAddress(t, formatAddress(t, *a))), *a);
            } else {
                const AddressError &e = std::get<AddressError>(r);
                EXPECT_FALSE(e.message.isEmpty());
                EXPECT_GE(e.column, 0);
                EXPECT_LE(e.column, text.size());
            }
            const auto c = parseConstant(t, text);
            if (const auto *e = std::get_if<AddressError>(&c)) {
                EXPECT_FALSE(e->message.isEmpty());
                EXPECT_GE(e->column, 0);
                EXPECT_LE(e->column, text.size());
            }
        }
    }
}
