#include "model/image/value_format.h"
#include "model/image/bcd.h"
#include "model/tr.h"

#include <QCoreApplication>

namespace rung::model {

namespace {

std::uint32_t widthMask(int bits) {
    return bits >= 32 ? 0xFFFFFFFFu : (1u << bits) - 1u;
}

} // namespace

QString valueFormatKey(ValueFormat format) {
    switch (format) {
    case ValueFormat::Decimal:
        return QStringLiteral("dec");
    case ValueFormat::Signed:
        return QStringLiteral("signed");
    case ValueFormat::Hex:
        return QStringLiteral("hex");
    case ValueFormat::Binary:
        return QStringLiteral("bin");
    case ValueFormat::Bcd:
        return QStringLiteral("bcd");
    }
    return {};
}

std::optional<ValueFormat> valueFormatFromKey(const QString &key) {
    for (const ValueFormat f : kValueFormats)
        if (valueFormatKey(f) == key)
            return f;
    return std::nullopt;
}

QString valueFormatName(ValueFormat format) {
    switch (format) {
    case ValueFormat::Decimal:
        return ValueFormatTr::tr("Decimal");
    case ValueFormat::Signed:
        return ValueFormatTr::tr("Signed");
    case ValueFormat::Hex:
        return ValueFormatTr::tr("Hexadecimal");
    case ValueFormat::Binary:
        return ValueFormatTr::tr("Binary");
    case ValueFormat::Bcd:
        return ValueFormatTr::tr("BCD");
    }
    return {};
}

QString formatValue(std::int32_t value, int bits, ValueFormat format) {
    bits = bits >= 32 ? 32 : 16;
    const std::uint32_t u = static_cast<std::uint32_t>(value) & widthMask(bits);
    const QString hex =
        QLatin1String("0x") + QStringLiteral("%1").arg(u, bits / 4, 16, QLatin1Char('0')).toUpper();
    switch (format) {
    case ValueFormat::Decimal:
        return QString::number(u);
    case ValueFormat::Signed:
        return QString::number(bits >= 32 ? static_cast<std::int32_t>(u)
                                          : static_cast<std::int16_t>(u));
    case ValueFormat::Hex:
        return hex;
    case ValueFormat::Binary: {
        QString out;
        for (int b = bits - 1; b >= 0; --b) {
            out += (u >> b) & 1u ? QLatin1Char('1') : QLatin1Char('0');
            if (b > 0 && b % 4 == 0)
                out += QLatin1Char(' ');
        }
        return out;
    }
    case ValueFormat::Bcd: {
        const std::optional<std::int64_t> decimal = fromBcd(u);
        return decimal ? QString::number(*decimal) : ValueFormatTr::tr("%1 (not BCD)").arg(hex);
    }
    }
    return {};
}

std::variant<std::int64_t, QString> parseValue(const QString &text, int bits, ValueFormat format) {
    bits = bits >= 32 ? 32 : 16;
    QString t = text.trimmed();
    if (t.isEmpty())
        return ValueFormatTr::tr("Type a value");
    const qint64 lowest = -(qint64{1} << (bits - 1));
    const qint64 highest = (qint64{1} << bits) - 1;
    const auto inRange = [&](qint64 v) -> std::variant<std::int64_t, QString> {
        if (v < lowest || v > highest)
            return ValueFormatTr::tr("%1 does not fit a %2-bit word (%3..%4)")
                .arg(t)
                .arg(bits)
                .arg(lowest)
                .arg(highest);
        return std::int64_t{v};
    };
    bool ok = false;
    switch (format) {
    case ValueFormat::Decimal:
    case ValueFormat::Signed: {
        const bool hex = t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive);
        const qint64 v = hex ? t.mid(2).toLongLong(&ok, 16) : t.toLongLong(&ok, 10);
        if (!ok)
            return ValueFormatTr::tr("\"%1\" is not a whole number (0x before a hexadecimal one)")
                .arg(t);
        return inRange(v);
    }
    case ValueFormat::Hex: {
        QString digits = t;
        for (const char *prefix : {"0x", "16#", "H"})
            if (digits.startsWith(QLatin1String(prefix), Qt::CaseInsensitive)) {
                digits = digits.mid(static_cast<qsizetype>(qstrlen(prefix)));
                break;
            }
        const qint64 v = digits.size() <= bits / 4 ? digits.toLongLong(&ok, 16) : -1;
        if (!ok || digits.startsWith(QLatin1Char('-')) || digits.startsWith(QLatin1Char('+')))
            return ValueFormatTr::tr("\"%1\" is not a hexadecimal value of at most %2 digits")
                .arg(t)
                .arg(bits / 4);
        return inRange(v);
    }
    case ValueFormat::Binary: {
        QString digits = t;
        digits.remove(QLatin1Char(' ')).remove(QLatin1Char('_'));
        const qint64 v = digits.size() <= bits ? digits.toLongLong(&ok, 2) : -1;
        if (!ok || digits.startsWith(QLatin1Char('-')) || digits.startsWith(QLatin1Char('+')))
            return ValueFormatTr::tr("\"%1\" is not a binary value of at most %2 digits")
                .arg(t)
                .arg(bits);
        return inRange(v);
    }
    case ValueFormat::Bcd: {
        qint64 v = 0;
        ok = !t.isEmpty() && t.size() <= bits / 4;
        for (const QChar c : t) {
            if (!ok || c < QLatin1Char('0') || c > QLatin1Char('9')) {
                ok = false;
                break;
            }
            v = v * 16 + (c.unicode() - '0');
        }
        if (!ok)
            return ValueFormatTr::tr("\"%1\" is not a BCD value: at most %2 decimal digits")
                .arg(t)
                .arg(bits / 4);
        return inRange(v);
    }
    }
    return ValueFormatTr::tr("Type a value");
}

} // namespace rung::model
