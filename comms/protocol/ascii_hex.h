#pragma once

// The ASCII fields of the Vigor link and Host Link frames, in one place for both codecs:
// upper-case hex digits (both PLCs send upper case only) and fixed-width decimal numbers;
// and a code as the manuals print it ("0F"), for the messages of all three protocols.

#include <QByteArray>
#include <QString>

#include <optional>

namespace rung::comms::detail {

// `digits` upper-case hex digits of value, high digit first.
void appendHex(QByteArray &out, int value, int digits);
// `digits` decimal digits of value, zero-padded.
void appendDecimal(QByteArray &out, int value, int digits);
std::optional<int> hexDigit(char c);
// The value of `digits` characters at `at`; nullopt when one is missing or not a digit.
std::optional<int> hexValue(QByteArrayView text, qsizetype at, int digits);
std::optional<int> decimalValue(QByteArrayView text, qsizetype at, int digits);
// Two upper-case hex digits: "0F".
QString hex2(int value);

} // namespace rung::comms::detail
