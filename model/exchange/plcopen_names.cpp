#include "model/exchange/plcopen.h"

#include "model/target/address.h"

#include <QRegularExpression>

// Devices as IEC 61131-3 names and located addresses (docs/plcopen.md). The areas come from
// the target's table: the first physical input and output areas, its analog words, its data
// memory; no family is named here.

namespace rung::model {

namespace {

bool bitLike(const Area &a) {
    return a.kind == AreaKind::Bit || a.kind == AreaKind::Channel;
}

// The first physical area of bits (or channels of bits) that is an input (not writable) or an
// output; of words with `words`.
int physicalArea(const Target &t, bool output, bool words) {
    for (std::size_t i = 0; i < t.areas.size(); ++i) {
        const Area &a = t.areas[i];
        if (!a.physical || a.writable != output)
            continue;
        if (words ? a.kind == AreaKind::Word : bitLike(a))
            return static_cast<int>(i);
    }
    return -1;
}

bool inRange(const Target &t, const Address &a, const ModelVariant *model) {
    const auto range = t.range(a.area, model);
    return range && a.index >= range->first && a.index <= range->second;
}

} // namespace

// The plain data memory (model::exampleWord's rule): a word area the program writes freely;
// a channel area with a prefix where the target has no such word area (CPM1 DM).
int dataMemoryArea(const Target &t) {
    const auto plain = [](const Area &a) {
        return a.writable && !a.system && !a.physical && !a.indexRegister && !a.presetsOf;
    };
    for (const AreaKind kind : {AreaKind::Word, AreaKind::Channel})
        for (std::size_t i = 0; i < t.areas.size(); ++i) {
            const Area &a = t.areas[i];
            if (a.kind == kind && plain(a) && (kind != AreaKind::Channel || !a.prefix.isEmpty()))
                return static_cast<int>(i);
        }
    return -1;
}

QString iecName(const Target &target, const Address &address) {
    QString text = formatAddress(target, address);
    QString out;
    for (const QChar c : text) {
        if (c.isSpace())
            continue;
        out += (c.isLetterOrNumber() && c.unicode() < 128) ? c : QLatin1Char('_');
    }
    if (!out.isEmpty() && out.front().isDigit())
        out.prepend(target.area(address.area).key);
    return out;
}

std::optional<Address> deviceOfIecName(const Target &target, const QString &name,
                                       const ModelVariant *model) {
    if (name.isEmpty())
        return std::nullopt;
    QStringList candidates{name, QString(name).replace(QLatin1Char('_'), QLatin1Char('.'))};
    // An area's key before a name that starts with a digit (IN000_01 is 000.01).
    for (const Area &a : target.areas)
        if (!a.key.isEmpty() && name.startsWith(a.key) && name.size() > a.key.size() &&
            name[a.key.size()].isDigit())
            candidates
                << QString(name.mid(a.key.size())).replace(QLatin1Char('_'), QLatin1Char('.'));
    for (const QString &c : candidates) {
        const auto parsed = parseAddress(target, c, model);
        if (const Address *a = std::get_if<Address>(&parsed))
            // Only a name the device itself would get: "X0" and "DM0010", not "x0_" or "DM10".
            if (iecName(target, *a).compare(name, Qt::CaseInsensitive) == 0)
                return *a;
    }
    return std::nullopt;
}

std::optional<Address> deviceOfLocation(const Target &target, const QString &location,
                                        const ModelVariant *model) {
    static const QRegularExpression re(QStringLiteral("^%([IQM])([XWBDL]?)(\\d+)(?:\\.(\\d+))?$"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(location.trimmed());
    if (!m.hasMatch())
        return std::nullopt;
    const QChar where = m.captured(1).toUpper().front();
    const QString size = m.captured(2).toUpper();
    const int number = m.captured(3).toInt();
    const bool hasBit = !m.captured(4).isEmpty();
    const int bit = m.captured(4).toInt();
    Address a;
    if ((size == QLatin1String("X") || size.isEmpty()) && hasBit && where != QLatin1Char('M')) {
        if (bit > 7)
            return std::nullopt;
        a.area = physicalArea(target, where == QLatin1Char('Q'), false);
        if (a.area < 0)
            return std::nullopt;
        const Area &area = target.area(a.area);
        const int n = number * 8 + bit;
        if (area.kind == AreaKind::Channel) {
            a.index = area.first + n / 16;
            a.bit = n % 16;
        } else {
            a.index = area.first;
            a = offsetAddress(target, a, n, model);
        }
    } else if (size == QLatin1String("W") && !hasBit) {
        a.area = where == QLatin1Char('M') ? dataMemoryArea(target)
                                           : physicalArea(target, where == QLatin1Char('Q'), true);
        if (a.area < 0)
            return std::nullopt;
        // The run goes on into the next area of the prefix (Vigor D199, D200 the latched D).
        a.index = target.area(a.area).first;
        a = offsetAddress(target, a, number, model);
    } else {
        return std::nullopt;
    }
    if (!a.valid() || !inRange(target, a, model))
        return std::nullopt;
    return a;
}

QString locationOfDevice(const Target &target, const Address &a) {
    if (!a.valid())
        return {};
    const Area &area = target.area(a.area);
    // In the located area, or an area of its prefix and kind after it (D200 after D0..D199).
    const auto within = [&](int base) {
        if (base < 0)
            return false;
        const Area &b = target.area(base);
        return a.area == base ||
               (b.prefix == area.prefix && b.kind == area.kind && b.physical == area.physical &&
                b.writable == area.writable && a.index >= b.first);
    };
    for (const bool output : {false, true}) {
        const int bits = physicalArea(target, output, false);
        if (within(bits)) {
            const QChar where = output ? QLatin1Char('Q') : QLatin1Char('I');
            const int first = target.area(bits).first;
            int n = -1;
            if (area.kind == AreaKind::Channel && a.bit >= 0)
                n = (a.index - first) * 16 + a.bit;
            else if (area.kind == AreaKind::Bit)
                n = a.index - first;
            if (n < 0)
                return {};
            return QStringLiteral("%%1X%2.%3").arg(where).arg(n / 8).arg(n % 8);
        }
        const int words = physicalArea(target, output, true);
        if (within(words) && a.bit < 0)
            return QStringLiteral("%%1W%2")
                .arg(output ? QLatin1Char('Q') : QLatin1Char('I'))
                .arg(a.index - target.area(words).first);
    }
    const int data = dataMemoryArea(target);
    if (within(data) && a.bit < 0)
        return QStringLiteral("%MW%1").arg(a.index - target.area(data).first);
    return {};
}

} // namespace rung::model
