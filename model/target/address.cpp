#include "model/target/address.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QVarLengthArray>

#include <algorithm>
#include <limits>
#include <vector>

namespace rung::model {

namespace {

// The length of the longest spelling of each area's prefix that starts s and is followed
// by a digit, or -1; and the longest of all. This runs for every operand the parser reads, so
// it compares against the table's prepared spellings (Target::prefixSpellings) once.
struct PrefixMatches {
    QVarLengthArray<qsizetype, 64> length;
    qsizetype best = -1;
};

PrefixMatches matchPrefixes(const Target &target, const QString &s) {
    PrefixMatches m;
    m.length.resize(static_cast<qsizetype>(target.areas.size()));
    std::fill(m.length.begin(), m.length.end(), qsizetype(-1));
    std::vector<Target::PrefixSpelling> own;
    const std::vector<Target::PrefixSpelling> *spellings = &target.prefixSpellings();
    if (spellings->empty()) {
        own = target.makePrefixSpellings();
        spellings = &own;
    }
    for (const Target::PrefixSpelling &p : *spellings) {
        const qsizetype n = p.text.size();
        if (s.size() <= n || !s[n].isDigit())
            continue;
        qsizetype same = 0; // prefixes are a few letters: no call into QString for them
        while (same < n && s[same] == p.text[same])
            ++same;
        if (same < n)
            continue;
        qsizetype &length = m.length[p.area];
        length = std::max(length, n);
        m.best = std::max(m.best, n);
    }
    return m;
}

int radixOf(Numbering n) {
    return n == Numbering::Octal ? 8 : 10;
}

QString formatNumber(const Area &area, int value) {
    QString digits = QString::number(value, radixOf(area.numbering));
    if (digits.size() < area.digits)
        digits.prepend(QString(area.digits - digits.size(), QLatin1Char('0')));
    return digits;
}

QString areaName(const Area &area) {
    return area.description ? QCoreApplication::translate("rung::model::Target", area.description)
                            : area.key;
}

struct Candidate {
    int area = -1;
    qsizetype prefixLength = 0; // in squeezed characters
};

// Reads digits in the given radix; stops at the first non-digit. Returns -1 digits read on
// overflow so a 100-digit number is an error, not a wrap-around.
struct Number {
    qint64 value = 0;
    qsizetype length = 0;
    bool overflow = false;
    qsizetype badDigit = -1; // position of a decimal digit not valid in the radix
};

Number readNumber(QStringView text, qsizetype from, int radix) {
    Number n;
    for (qsizetype i = from; i < text.size(); ++i) {
        const QChar c = text[i];
        if (!c.isDigit() || c.unicode() > '9')
            break;
        const int d = c.unicode() - '0';
        if (d >= radix && n.badDigit < 0)
            n.badDigit = i;
        if (n.value > (std::numeric_limits<int>::max() - d) / 10)
            n.overflow = true;
        else
            n.value = n.value * radix + d;
        ++n.length;
    }
    return n;
}

// Map a position in the squeezed text back to the original text (for the column).
int originalColumn(QStringView text, qsizetype squeezedPos) {
    qsizetype seen = 0;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i].isSpace())
            continue;
        if (seen == squeezedPos)
            return static_cast<int>(i);
        ++seen;
    }
    return static_cast<int>(text.size());
}

} // namespace

QString squeezeAddress(QStringView text) {
    QString out;
    out.reserve(text.size());
    for (QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x80) { // ASCII, nearly every operand: no table lookup
            if (u != ' ' && (u < '\t' || u > '\r'))
                out.append(QChar(u >= 'a' && u <= 'z' ? u - ('a' - 'A') : u));
        } else if (!c.isSpace()) {
            out.append(c.toUpper());
        }
    }
    return out;
}

std::variant<Address, AddressError> parseAddress(const Target &target, QStringView text,
                                                 const ModelVariant *model) {
    const QStringView trimmed = text.trimmed();
    const int lead = static_cast<int>(text.indexOf(trimmed.isEmpty() ? text : trimmed));
    const QString s = squeezeAddress(trimmed);
    const QStringView shown = trimmed; // for the messages: no copy on the way that has none
    auto error = [&](const QString &message, qsizetype squeezedPos) {
        return AddressError{message, lead + originalColumn(trimmed, squeezedPos)};
    };
    if (s.isEmpty())
        return AddressError{AddressTr::tr("A device is missing"), 0};

    // The longest prefix followed by a digit wins: "HR00" is HR, not an unprefixed channel.
    const PrefixMatches prefixes = matchPrefixes(target, s);
    const qsizetype bestLength = prefixes.best;
    if (bestLength < 0) {
        // Name the prefix the user wrote, if any, for a clearer message.
        qsizetype letters = 0;
        while (letters < s.size() && !s[letters].isDigit())
            ++letters;
        if (letters == s.size()) {
            for (const Area &a : target.areas)
                if (squeezeAddress(a.prefix) == s)
                    return error(
                        AddressTr::tr("%1: a number is expected after %2").arg(shown, a.prefix),
                        s.size());
        }
        return error(AddressTr::tr("%1 is not a device of %2").arg(shown, target.displayName), 0);
    }

    // Areas sharing the prefix differ by numbering only in theory; read with the first one's
    // rules, then pick the area whose range holds the number.
    int firstArea = -1;
    for (int i = 0; i < static_cast<int>(target.areas.size()); ++i)
        if (prefixes.length[i] == bestLength) {
            firstArea = i;
            break;
        }
    const Area &rules = target.area(firstArea);
    const Number number = readNumber(s, bestLength, radixOf(rules.numbering));
    if (number.overflow)
        return error(AddressTr::tr("%1: the number is too large").arg(shown), bestLength);
    if (number.badDigit >= 0)
        return error(AddressTr::tr("%1: %2 is numbered in octal").arg(shown, rules.prefix),
                     number.badDigit);

    int bit = -1;
    qsizetype pos = bestLength + number.length;
    if (pos < s.size() && s[pos] == QLatin1Char('.')) {
        const Number b = readNumber(s, pos + 1, 10);
        if (b.length == 0)
            return error(AddressTr::tr("%1: a bit number is expected after the point").arg(shown),
                         pos + 1);
        if (b.overflow || b.value > 15)
            return error(AddressTr::tr("%1: bit %2 is beyond 00..15").arg(shown).arg(b.value),
                         pos + 1);
        bit = static_cast<int>(b.value);
        pos += 1 + b.length;
    }
    if (pos < s.size())
        return error(AddressTr::tr("%1: unexpected '%2' after the device").arg(shown, s.mid(pos)),
                     pos);

    qint64 value = number.value;
    // The Omron CPM1 guide writes a CPM1 bit as channel digits + two bit digits without the point:
    // 25313 is 253.13, HR0005 is HR00.05.
    if (bit < 0 && rules.numbering == Numbering::ChannelBit && rules.digits > 0 &&
        number.length == rules.digits + 2) {
        const int b = static_cast<int>(value % 100);
        if (b > 15)
            return error(AddressTr::tr("%1: bit %2 is beyond 00..15").arg(shown).arg(b),
                         bestLength + number.length - 2);
        bit = b;
        value /= 100;
    }
    const int index = static_cast<int>(value);
    const QString who = model ? model->name : target.displayName;
    int matched = -1;
    int anyArea = -1;
    for (int i = 0; i < static_cast<int>(target.areas.size()); ++i) {
        const Area &a = target.area(i);
        if (prefixes.length[i] != bestLength)
            continue;
        if (anyArea < 0)
            anyArea = i;
        if (index < a.first || index > a.last)
            continue;
        const bool bitForm = bit >= 0;
        const bool wantsBit = a.numbering == Numbering::ChannelBit;
        if (bitForm && !wantsBit)
            continue;
        matched = i;
        break;
    }
    if (matched < 0) {
        // Out of every area's range: name the spans the prefix covers (on the model, if one
        // is given), merged where areas follow each other: "r96 is beyond VPC's auxiliary
        // relays r00..r95", "M9300 is beyond Vigor's M0..M5119, M9000..M9255".
        bool bitAllowed = false;
        std::vector<std::pair<int, int>> spans;
        for (int i = 0; i < static_cast<int>(target.areas.size()); ++i) {
            const Area &a = target.area(i);
            if (prefixes.length[i] != bestLength)
                continue;
            bitAllowed = bitAllowed || a.numbering == Numbering::ChannelBit;
            if (const auto r = target.range(i, model))
                spans.push_back(*r);
        }
        if (bit >= 0 && !bitAllowed)
            return error(AddressTr::tr("%1: %2 has no bit numbers").arg(shown, rules.prefix),
                         bestLength);
        const Area &a = target.area(anyArea);
        if (spans.empty())
            return error(AddressTr::tr("%1: %2 has no %3").arg(shown, who, areaName(a)), 0);
        std::sort(spans.begin(), spans.end());
        std::vector<std::pair<int, int>> merged{spans.front()};
        for (const auto &span : spans) {
            if (span.first <= merged.back().second + 1)
                merged.back().second = std::max(merged.back().second, span.second);
            else
                merged.push_back(span);
        }
        QStringList ranges;
        for (const auto &[lo, hi] : merged)
            ranges << a.prefix + formatNumber(a, lo) + QStringLiteral("..") + a.prefix +
                          formatNumber(a, hi);
        // One span reads best with the area's name; several spans cross areas of different
        // kinds (CPM1 input and work channels), so only the ranges are named.
        if (merged.size() == 1)
            return error(
                AddressTr::tr("%1 is beyond %2's %3 %4").arg(shown, who, areaName(a), ranges[0]),
                bestLength);
        return error(AddressTr::tr("%1 is beyond %2's %3")
                         .arg(shown, who, ranges.join(QStringLiteral(", "))),
                     bestLength);
    }

    const Area &a = target.area(matched);
    if (model) {
        const auto r = target.range(matched, model);
        if (!r)
            return error(AddressTr::tr("%1: %2 has no %3").arg(shown, who, areaName(a)), 0);
        if (index < r->first || index > r->second) {
            // The model narrows the area: name the model's range, as the user sees it.
            return error(AddressTr::tr("%1 is beyond %2's %3 %4")
                             .arg(shown, who, areaName(a),
                                  a.prefix + formatNumber(a, r->first) + QStringLiteral("..") +
                                      a.prefix + formatNumber(a, r->second)),
                         bestLength);
        }
    }
    return Address{matched, index, bit};
}

QString formatAddress(const Target &target, const Address &address) {
    if (address.area < 0 || address.area >= static_cast<int>(target.areas.size()))
        return QStringLiteral("?");
    const Area &a = target.area(address.area);
    QString out = a.prefix + formatNumber(a, address.index);
    // CPM1 pads the bit like its channel (010.00); PL110 writes SM0.1 as the manual does.
    if (address.bit >= 0)
        out += QLatin1Char('.') +
               QStringLiteral("%1").arg(address.bit, a.digits > 0 ? 2 : 1, 10, QLatin1Char('0'));
    return out;
}

std::variant<Constant, AddressError> parseConstant(const Target &target, QStringView text) {
    const QStringView t = text.trimmed();
    const int lead = static_cast<int>(text.indexOf(t.isEmpty() ? text : t));
    if (t.isEmpty())
        return AddressError{AddressTr::tr("A constant is missing"), 0};
    Constant c;
    qsizetype pos = 0;
    int radix = 10;
    const QChar first = t[0].toUpper();
    if (first == QLatin1Char('K')) {
        c.style = Constant::Style::Decimal;
        pos = 1;
    } else if (first == QLatin1Char('H')) {
        c.style = Constant::Style::Hex;
        radix = 16;
        pos = 1;
    } else if (first == QLatin1Char('#')) {
        c.style = Constant::Style::Bcd;
        pos = 1;
    } else {
        c.style = Constant::Style::Plain;
    }
    // Each target writes constants its own way (ConstantNotation); a foreign style is a clear
    // error that names the target's own.
    const ConstantNotation &rules = target.constants;
    if ((c.style == Constant::Style::Decimal || c.style == Constant::Style::Hex) && !rules.prefixed)
        return AddressError{AddressTr::tr("%1: %2 writes constants without K or H")
                                .arg(t.toString(), target.displayName),
                            lead};
    // How this target writes a constant, for the messages that refuse another way.
    const auto ownWay = [&rules] {
        if (rules.prefixed)
            return AddressTr::tr("write a constant as K (decimal) or H (hexadecimal)");
        if (rules.bcd)
            return AddressTr::tr("write a constant with # (e.g. #0150)");
        return AddressTr::tr("write a constant as a plain number (e.g. 150)");
    };
    if (c.style == Constant::Style::Bcd && rules.hashPlain) {
        c.style = Constant::Style::Plain;
    } else if (c.style == Constant::Style::Bcd && !rules.bcd)
        return AddressError{AddressTr::tr("%1: %2 has no # constants; %3")
                                .arg(t.toString(), target.displayName, ownWay()),
                            lead};
    if (c.style == Constant::Style::Plain && !rules.plain)
        return AddressError{AddressTr::tr("%1: %2").arg(t.toString(), ownWay()), lead};
    bool negative = false;
    if (pos < t.size() && (t[pos] == QLatin1Char('-') || t[pos] == QLatin1Char('+')) &&
        c.style != Constant::Style::Bcd && c.style != Constant::Style::Hex) {
        negative = t[pos] == QLatin1Char('-');
        ++pos;
    }
    if (pos >= t.size())
        return AddressError{AddressTr::tr("%1: digits are expected").arg(t.toString()),
                            lead + static_cast<int>(pos)};
    qint64 value = 0;
    bool hexDigitInBcd = false;
    for (qsizetype i = pos; i < t.size(); ++i) {
        const QChar ch = t[i].toUpper();
        int d = -1;
        if (ch.isDigit() && ch.unicode() <= '9')
            d = ch.unicode() - '0';
        else if ((radix == 16 || c.style == Constant::Style::Bcd) && ch >= QLatin1Char('A') &&
                 ch <= QLatin1Char('F'))
            d = ch.unicode() - 'A' + 10;
        if (d < 0)
            return AddressError{
                AddressTr::tr("%1: '%2' is not a digit").arg(t.toString(), QString(t[i])),
                lead + static_cast<int>(i)};
        if (c.style == Constant::Style::Bcd && d > 9)
            hexDigitInBcd = true;
        const int base = (c.style == Constant::Style::Bcd && hexDigitInBcd) ? 16 : radix;
        value = value * base + d;
        if (value > 0xFFFFFFFFLL)
            return AddressError{AddressTr::tr("%1: the constant is too large").arg(t.toString()),
                                lead};
    }
    if (hexDigitInBcd) {
        // "#00FF" is a hexadecimal word, not BCD: re-read all digits in base 16.
        value = t.mid(pos).toString().toLongLong(nullptr, 16);
        c.style = Constant::Style::Hex;
    }
    c.value = negative ? -value : value;
    return c;
}

QString formatConstant(const Target &target, const Constant &constant) {
    switch (constant.style) {
    case Constant::Style::Decimal:
        return QStringLiteral("K%1").arg(constant.value);
    case Constant::Style::Hex:
        // Without an H prefix a hexadecimal word is a #-constant with a letter digit (CPM1).
        if (target.constants.bcd && !target.constants.prefixed)
            return QStringLiteral("#%1").arg(constant.value, 4, 16, QLatin1Char('0')).toUpper();
        return QStringLiteral("H%1").arg(constant.value, 0, 16).toUpper();
    case Constant::Style::Bcd:
        return QStringLiteral("#%1").arg(constant.value, 4, 10, QLatin1Char('0'));
    case Constant::Style::Plain:
        break;
    }
    // A plain value in the target's own notation: plain where it has one, else K, else #.
    if (target.constants.plain)
        return QString::number(constant.value);
    if (target.constants.prefixed)
        return QStringLiteral("K%1").arg(constant.value);
    if (target.constants.bcd)
        return QStringLiteral("#%1").arg(constant.value, 4, 10, QLatin1Char('0'));
    return QString::number(constant.value);
}

Address offsetAddress(const Target &target, const Address &address, qint64 offset,
                      const ModelVariant *model) {
    if (!address.valid() || address.area >= static_cast<int>(target.areas.size()))
        return {};
    const Area &base = target.area(address.area);
    const qint64 element = qint64{address.index} + offset;
    for (int i = 0; i < static_cast<int>(target.areas.size()); ++i) {
        const Area &a = target.area(i);
        if (a.prefix != base.prefix || a.kind != base.kind)
            continue;
        const auto range = target.range(i, model);
        if (range && element >= range->first && element <= range->second)
            return Address{i, static_cast<int>(element), address.bit};
    }
    return {};
}

std::optional<Address> runBreaks(const Target &target, const Address &first, qint64 count,
                                 bool wordBlock) {
    if (!first.valid() || first.area >= static_cast<int>(target.areas.size()) || count < 1)
        return std::nullopt;
    int at = first.area;
    const qint64 last = qint64{first.index} + count - 1;
    if (first.index < target.area(at).first)
        return first;
    while (last > target.area(at).last) {
        const Area &here = target.area(at);
        const bool next =
            at + 1 < static_cast<int>(target.areas.size()) &&
            (!wordBlock || (here.kind != AreaKind::Timer && here.kind != AreaKind::Counter)) &&
            target.area(at + 1).prefix == here.prefix && target.area(at + 1).kind == here.kind &&
            target.area(at + 1).first == here.last + 1;
        if (!next)
            return Address{at, here.last + 1, first.bit};
        ++at;
    }
    return std::nullopt;
}

std::variant<std::vector<Address>, AddressError>
parseAddressRange(const Target &target, QStringView text, const ModelVariant *model) {
    const qsizetype dots = text.indexOf(QLatin1String(".."));
    if (dots < 0) {
        auto one = parseAddress(target, text, model);
        if (auto *e = std::get_if<AddressError>(&one))
            return *e;
        return std::vector<Address>{std::get<Address>(one)};
    }
    auto first = parseAddress(target, text.left(dots), model);
    if (auto *e = std::get_if<AddressError>(&first))
        return *e;
    auto last = parseAddress(target, text.mid(dots + 2), model);
    if (auto *e = std::get_if<AddressError>(&last)) {
        e->column += static_cast<int>(dots + 2);
        return *e;
    }
    const Address a = std::get<Address>(first);
    const Address b = std::get<Address>(last);
    const Area &areaA = target.area(a.area);
    const Area &areaB = target.area(b.area);
    const QString shown = text.trimmed().toString();
    if (areaA.prefix != areaB.prefix || areaA.kind != areaB.kind || (a.bit >= 0) != (b.bit >= 0))
        return AddressError{
            AddressTr::tr("%1: both ends of a range must be devices of one kind (D0..D15)")
                .arg(shown),
            0};
    // Bits of channels count on across channels: 000.15 is followed by 001.00.
    const bool bits = a.bit >= 0;
    const qint64 from = bits ? qint64{a.index} * 16 + a.bit : a.index;
    const qint64 to = bits ? qint64{b.index} * 16 + b.bit : b.index;
    if (to < from)
        return AddressError{AddressTr::tr("%1: the range runs backwards").arg(shown), 0};
    if (to - from + 1 > kMaxRange)
        return AddressError{AddressTr::tr("%1: %2 devices; a range holds at most %3")
                                .arg(shown)
                                .arg(to - from + 1)
                                .arg(kMaxRange),
                            0};
    std::vector<Address> out;
    out.reserve(static_cast<std::size_t>(to - from + 1));
    for (qint64 n = from; n <= to; ++n) {
        const int index = static_cast<int>(bits ? n / 16 : n);
        // The area of this number among those written with the same prefix (M / ML).
        int area = -1;
        for (int k = 0; k < static_cast<int>(target.areas.size()) && area < 0; ++k) {
            const Area &c = target.area(k);
            if (c.prefix == areaA.prefix && c.kind == areaA.kind &&
                c.numbering == areaA.numbering) {
                const auto range = target.range(k, model);
                if (range && index >= range->first && index <= range->second)
                    area = k;
            }
        }
        if (area < 0)
            return AddressError{
                AddressTr::tr("%1: the PLC has no %2 inside this range")
                    .arg(shown, formatAddress(target, {a.area, index, bits ? int(n % 16) : -1})),
                0};
        out.push_back({area, index, bits ? static_cast<int>(n % 16) : -1});
    }
    return out;
}

Address systemAddress(const Target &target, SystemRole role) {
    const SystemDevice *d = target.systemDevice(role);
    if (!d)
        return {};
    const auto parsed = parseAddress(target, d->device);
    const Address *a = std::get_if<Address>(&parsed);
    return a ? *a : Address{};
}

} // namespace rung::model
