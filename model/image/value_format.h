#pragma once

// How a monitor shows a word: decimal (unsigned), signed, hexadecimal, binary or BCD, as the
// watch table lets the user choose per row and the timing chart draws its bus values. A
// value typed in the same format is read back by parseValue. The file keys are stable
// (docs/project-format.md, watchLists[].formats).

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <variant>

namespace rung::model {

enum class ValueFormat : std::uint8_t { Decimal, Signed, Hex, Binary, Bcd };

constexpr ValueFormat kValueFormats[] = {ValueFormat::Decimal, ValueFormat::Signed,
                                         ValueFormat::Hex, ValueFormat::Binary, ValueFormat::Bcd};

// "dec", "signed", "hex", "bin", "bcd"
QString valueFormatKey(ValueFormat format);
std::optional<ValueFormat> valueFormatFromKey(const QString &key);
// The translated name for menus: "Decimal", "Signed", "Hexadecimal", "Binary", "BCD".
QString valueFormatName(ValueFormat format);

// The value of a word of `bits` bits (16 or 32) in the format:
// Decimal 65535, Signed -1, Hex 0xFFFF (all the word's digits), Binary 1111 1111 1111 1111
// (nibbles apart), BCD 1234 (the digits the nibbles spell; a nibble above 9: "0x12A4 (not
// BCD)", translated).
QString formatValue(std::int32_t value, int bits, ValueFormat format);

// A value typed for a word of `bits` bits, read in the format: Decimal and Signed take a
// whole number (or 0x... hexadecimal), Hex takes hexadecimal digits (0x, H or 16# before them
// allowed), Binary 0s and 1s (spaces and _ between them allowed), BCD up to bits/4 decimal
// digits (stored as their nibbles: 1234 -> 0x1234). The error is translated and says why.
std::variant<std::int64_t, QString> parseValue(const QString &text, int bits, ValueFormat format);

} // namespace rung::model
