#include "comms/protocol/ascii_hex.h"

namespace rung::comms::detail {

void appendHex(QByteArray &out, int value, int digits) {
    static const char table[] = "0123456789ABCDEF";
    for (int i = digits - 1; i >= 0; --i)
        out += table[(value >> (4 * i)) & 0xF];
}

void appendDecimal(QByteArray &out, int value, int digits) {
    out += QByteArray::number(value).rightJustified(digits, '0', true);
}

std::optional<int> hexDigit(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return std::nullopt;
}

std::optional<int> hexValue(QByteArrayView text, qsizetype at, int digits) {
    if (at < 0 || at + digits > text.size())
        return std::nullopt;
    int value = 0;
    for (int i = 0; i < digits; ++i) {
        const auto d = hexDigit(text[at + i]);
        if (!d)
            return std::nullopt;
        value = value << 4 | *d;
    }
    return value;
}

std::optional<int> decimalValue(QByteArrayView text, qsizetype at, int digits) {
    if (at < 0 || at + digits > text.size())
        return std::nullopt;
    int value = 0;
    for (int i = 0; i < digits; ++i) {
        const char c = text[at + i];
        if (c < '0' || c > '9')
            return std::nullopt;
        value = value * 10 + (c - '0');
    }
    return value;
}

QString hex2(int value) {
    return QString::number(value, 16).toUpper().rightJustified(2, QLatin1Char('0'));
}

} // namespace rung::comms::detail
