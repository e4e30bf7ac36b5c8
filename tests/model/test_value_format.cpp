// The watch table's formats and ranges: exact texts for each format, values typed back, and
// device ranges in each target's numbering.

#include "model/image/value_format.h"
#include "model/target/address.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

std::int64_t read(const char *text, int bits, ValueFormat f) {
    const auto r = parseValue(QString::fromLatin1(text), bits, f);
    EXPECT_TRUE(std::holds_alternative<std::int64_t>(r))
        << text << ": "
        << (std::holds_alternative<QString>(r) ? std::get<QString>(r).toStdString() : "");
    return std::holds_alternative<std::int64_t>(r) ? std::get<std::int64_t>(r) : -999999;
}

QString refused(const char *text, int bits, ValueFormat f) {
    const auto r = parseValue(QString::fromLatin1(text), bits, f);
    EXPECT_TRUE(std::holds_alternative<QString>(r)) << text;
    return std::holds_alternative<QString>(r) ? std::get<QString>(r) : QString();
}

QStringList names(const Target &t, const char *range, const ModelVariant *model = nullptr) {
    const auto r = parseAddressRange(t, QString::fromLatin1(range), model);
    EXPECT_TRUE((std::holds_alternative<std::vector<Address>>(r)))
        << range << ": "
        << (std::holds_alternative<AddressError>(r)
                ? std::get<AddressError>(r).message.toStdString()
                : "");
    QStringList out;
    if (const auto *list = std::get_if<std::vector<Address>>(&r))
        for (const Address &a : *list)
            out << formatAddress(t, a);
    return out;
}

} // namespace

TEST(ValueFormat, ShowsAWordInEachFormat) {
    EXPECT_EQ(formatValue(-5, 16, ValueFormat::Decimal), QStringLiteral("65531"));
    EXPECT_EQ(formatValue(-5, 16, ValueFormat::Signed), QStringLiteral("-5"));
    EXPECT_EQ(formatValue(-5, 16, ValueFormat::Hex), QStringLiteral("0xFFFB"));
    EXPECT_EQ(formatValue(-5, 16, ValueFormat::Binary), QStringLiteral("1111 1111 1111 1011"));
    EXPECT_EQ(formatValue(0x1234, 16, ValueFormat::Bcd), QStringLiteral("1234"));
    EXPECT_EQ(formatValue(0x0150, 16, ValueFormat::Bcd), QStringLiteral("150"));
    EXPECT_EQ(formatValue(0x12A4, 16, ValueFormat::Bcd), QStringLiteral("0x12A4 (not BCD)"));
    EXPECT_EQ(formatValue(255, 16, ValueFormat::Hex), QStringLiteral("0x00FF"));
    EXPECT_EQ(formatValue(100, 16, ValueFormat::Decimal), QStringLiteral("100"));
    EXPECT_EQ(formatValue(100, 16, ValueFormat::Signed), QStringLiteral("100"));
    // 32-bit words (Vigor C200..C255) keep all their digits.
    EXPECT_EQ(formatValue(-1, 32, ValueFormat::Decimal), QStringLiteral("4294967295"));
    EXPECT_EQ(formatValue(-1, 32, ValueFormat::Signed), QStringLiteral("-1"));
    EXPECT_EQ(formatValue(70000, 32, ValueFormat::Hex), QStringLiteral("0x00011170"));
    EXPECT_EQ(formatValue(5, 32, ValueFormat::Binary),
              QStringLiteral("0000 0000 0000 0000 0000 0000 0000 0101"));
    EXPECT_EQ(formatValue(0x12345678, 32, ValueFormat::Bcd), QStringLiteral("12345678"));
}

TEST(ValueFormat, ReadsAValueTypedInItsFormat) {
    EXPECT_EQ(read("-5", 16, ValueFormat::Signed), -5);
    EXPECT_EQ(read("65531", 16, ValueFormat::Decimal), 65531);
    EXPECT_EQ(read("0x10", 16, ValueFormat::Decimal), 16);
    EXPECT_EQ(read("FFFB", 16, ValueFormat::Hex), 0xFFFB);
    EXPECT_EQ(read("0x1f", 16, ValueFormat::Hex), 31);
    EXPECT_EQ(read("H1F", 16, ValueFormat::Hex), 31);
    EXPECT_EQ(read("16#1F", 16, ValueFormat::Hex), 31);
    EXPECT_EQ(read("1111 1111 1111 1011", 16, ValueFormat::Binary), 0xFFFB);
    EXPECT_EQ(read("1_0000", 16, ValueFormat::Binary), 16);
    EXPECT_EQ(read("1234", 16, ValueFormat::Bcd), 0x1234);
    EXPECT_EQ(read("150", 16, ValueFormat::Bcd), 0x150);
    EXPECT_EQ(read("12345678", 32, ValueFormat::Bcd), 0x12345678);
    // A value shown is read back as the same value (values whose nibbles are BCD digits).
    for (const ValueFormat f : kValueFormats)
        for (const std::int32_t v : {0, 1, 9, 0x150, 0x1234, 0x9999})
            EXPECT_EQ(read(formatValue(v, 16, f).toLatin1().constData(), 16, f) & 0xFFFF, v)
                << valueFormatKey(f).toStdString() << " " << v;
}

TEST(ValueFormat, RefusesWhatIsNoValueAndSaysWhy) {
    EXPECT_TRUE(refused("", 16, ValueFormat::Decimal).contains(QStringLiteral("Type")));
    EXPECT_TRUE(refused("twelve", 16, ValueFormat::Decimal).contains(QStringLiteral("twelve")));
    EXPECT_TRUE(
        refused("70000", 16, ValueFormat::Decimal).contains(QStringLiteral("-32768..65535")));
    EXPECT_TRUE(refused("12345", 16, ValueFormat::Hex).contains(QStringLiteral("4 digits")));
    EXPECT_TRUE(refused("102", 16, ValueFormat::Binary).contains(QStringLiteral("binary")));
    EXPECT_TRUE(refused("12A4", 16, ValueFormat::Bcd).contains(QStringLiteral("BCD")));
    EXPECT_TRUE(refused("12345", 16, ValueFormat::Bcd).contains(QStringLiteral("4 decimal")));
}

TEST(ValueFormat, FileKeysAreStable) {
    QStringList keys;
    for (const ValueFormat f : kValueFormats) {
        keys << valueFormatKey(f);
        EXPECT_EQ(valueFormatFromKey(valueFormatKey(f)), f);
    }
    EXPECT_EQ(keys, (QStringList{"dec", "signed", "hex", "bin", "bcd"}));
    EXPECT_EQ(valueFormatFromKey(QStringLiteral("roman")), std::nullopt);
}

TEST(AddressRange, ListsEveryDeviceInTheTargetsNumbering) {
    const Target &vigor = Target::get(Family::Vigor);
    EXPECT_EQ(names(vigor, "D0..D3"), (QStringList{"D0", "D1", "D2", "D3"}));
    // X is octal: X0..X17 is sixteen inputs, X7 followed by X10.
    const QStringList x = names(vigor, "X0..X17");
    ASSERT_EQ(x.size(), 16);
    EXPECT_EQ(x[7], QStringLiteral("X7"));
    EXPECT_EQ(x[8], QStringLiteral("X10"));
    EXPECT_EQ(x.back(), QStringLiteral("X17"));
    // One prefix over two areas of the table (M0..M499, latched M500..).
    EXPECT_EQ(names(vigor, "M498..M501"), (QStringList{"M498", "M499", "M500", "M501"}));
    EXPECT_EQ(names(vigor, " Y5 "), QStringList{"Y5"});
    const Target &cpm1 = Target::get(Family::Cpm1);
    EXPECT_EQ(names(cpm1, "000.14..001.01"), (QStringList{"000.14", "000.15", "001.00", "001.01"}));
    const Target &vpc = Target::get(Family::Vpc);
    EXPECT_EQ(names(vpc, "i08..i11"), (QStringList{"i08", "i09", "i10", "i11"}));
}

TEST(AddressRange, RefusesRangesThatAreNoneAndSaysWhy) {
    const Target &vigor = Target::get(Family::Vigor);
    const auto error = [&](const char *text) {
        const auto r = parseAddressRange(vigor, QString::fromLatin1(text));
        EXPECT_TRUE(std::holds_alternative<AddressError>(r)) << text;
        return std::holds_alternative<AddressError>(r) ? std::get<AddressError>(r).message
                                                       : QString();
    };
    EXPECT_TRUE(error("D5..D2").contains(QStringLiteral("backwards")));
    EXPECT_TRUE(error("D0..X7").contains(QStringLiteral("one kind")));
    EXPECT_TRUE(error("D0..D5000").contains(QStringLiteral("at most 1024")));
    EXPECT_TRUE(error("X0..X18").contains(QStringLiteral("octal")));
    // A model's I/O: the VPC2416 has 24 inputs.
    const Target &vpc = Target::get(Family::Vpc);
    const auto r =
        parseAddressRange(vpc, QStringLiteral("i20..i30"), vpc.model(QStringLiteral("VPC2416")));
    ASSERT_TRUE(std::holds_alternative<AddressError>(r));
}
