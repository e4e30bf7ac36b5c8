#include "model/listing/il.h"
#include "model/tr.h"

#include <QCoreApplication>

// Operands with modifiers, as the WPLSoft family writes them (PLC concepts (WPLSoft family)
// 1.4): a digit count before a bit device (K4Y0: the word of Y0..Y17) and an index register
// after a word device or a decimal constant (D0E0, K10F0, K4M0E1). Every room reads and writes
// them through the functions here: the listing parser and printer, the ladder text, the
// project files.

namespace rung::model {

namespace {

// Where the parts of an operand are: [baseStart, baseEnd) the device or constant, the digit
// count before it, the index register after it (indexStart < 0: none).
struct Parts {
    bool digitGroup = false;
    int digits = 0;
    qsizetype baseStart = 0;
    qsizetype baseEnd = 0;
    qsizetype indexStart = -1;
    bool modified() const { return digitGroup || indexStart >= 0; }
};

bool isAsciiDigit(QChar c) {
    return c.unicode() >= '0' && c.unicode() <= '9';
}

bool hasIndexRegisters(const Target &target) {
    return std::any_of(target.areas.begin(), target.areas.end(),
                       [](const Area &a) { return a.indexRegister; });
}

// Whether s is an index register alone: one of its spellings and digits ("Z0", "F7").
bool isIndexRegister(const Target &target, QStringView s) {
    qsizetype letters = 0;
    while (letters < s.size() && s[letters].isLetter())
        ++letters;
    if (letters == 0 || letters == s.size())
        return false;
    for (qsizetype i = letters; i < s.size(); ++i)
        if (!isAsciiDigit(s[i]))
            return false;
    const QStringView name = s.left(letters);
    for (const Area &a : target.areas) {
        if (!a.indexRegister)
            continue;
        if (name.compare(a.prefix, Qt::CaseInsensitive) == 0)
            return true;
        for (const QString &alias : a.prefixAliases)
            if (name.compare(alias, Qt::CaseInsensitive) == 0)
                return true;
    }
    return false;
}

Parts split(const Target &target, QStringView s) {
    Parts p;
    p.baseEnd = s.size();
    // Kn + a letter: "K4Y0" is a digit group; "K10" stays a constant, and so does "K10V0" (the
    // constant 10 indexed by V0).
    if (target.constants.digitGroups > 0 && s.size() >= 3 && s[0].toUpper() == QLatin1Char('K') &&
        isAsciiDigit(s[1])) {
        qsizetype j = 1;
        int n = 0;
        while (j < s.size() && isAsciiDigit(s[j]) && n < 1000)
            n = n * 10 + (s[j++].unicode() - '0');
        if (j < s.size() && s[j].isLetter() && !isIndexRegister(target, s.mid(j))) {
            p.digitGroup = true;
            p.digits = n;
            p.baseStart = j;
        }
    }
    if (!hasIndexRegisters(target))
        return p;
    // A hexadecimal constant holds E and F as digits: H1E0 is 1E0h, never indexed.
    if (p.baseStart < s.size() && s[p.baseStart].toUpper() == QLatin1Char('H'))
        return p;
    qsizetype i = s.size();
    while (i > p.baseStart && isAsciiDigit(s[i - 1]))
        --i;
    if (i == s.size())
        return p;
    qsizetype k = i;
    while (k > p.baseStart && s[k - 1].isLetter())
        --k;
    if (k == i || k <= p.baseStart || !isAsciiDigit(s[k - 1]))
        return p;
    const QStringView letters = s.mid(k, i - k);
    for (const Area &a : target.areas) {
        if (!a.indexRegister)
            continue;
        QStringList spellings = a.prefixAliases;
        spellings << a.prefix;
        for (const QString &spelling : spellings)
            if (letters.compare(spelling, Qt::CaseInsensitive) == 0) {
                p.indexStart = k;
                p.baseEnd = k;
                return p;
            }
    }
    return p;
}

AddressError shifted(AddressError e, qsizetype by) {
    e.column += static_cast<int>(by);
    return e;
}

QString indexRegisterNames(const Target &target) {
    QStringList names;
    for (const Area &a : target.areas) {
        if (!a.indexRegister)
            continue;
        QStringList spellings{a.prefix};
        spellings << a.prefixAliases;
        for (const QString &p : spellings)
            names << p + QString::number(a.first) + QStringLiteral("..") + p +
                         QString::number(a.last);
    }
    return names.join(QStringLiteral(", "));
}

} // namespace

bool hasOperandModifiers(const Target &target, QStringView text) {
    return split(target, text.trimmed()).modified();
}

std::variant<Operand, AddressError> parseOperand(const Target &target, QStringView text,
                                                 const ModelVariant *model) {
    const QStringView s = text.trimmed();
    const qsizetype lead = s.isEmpty() ? 0 : text.indexOf(s);
    const QString shown = s.toString();
    const Parts p = split(target, s);
    Operand o;
    if (!p.modified()) {
        auto a = parseAddress(target, s, model);
        if (const Address *address = std::get_if<Address>(&a)) {
            o.kind = Operand::Kind::Device;
            o.address = *address;
            return o;
        }
        auto c = parseConstant(target, s);
        if (const Constant *constant = std::get_if<Constant>(&c)) {
            o.kind = Operand::Kind::Constant;
            o.constant = *constant;
            return o;
        }
        return shifted(std::get<AddressError>(a), lead);
    }
    const QStringView base = s.mid(p.baseStart, p.baseEnd - p.baseStart);
    if (p.digitGroup) {
        const int most = target.constants.digitGroups;
        if (p.digits < 1 || p.digits > most)
            return AddressError{
                InstructionListTr::tr("%1: K%2 is no digit count here; K1..K%3 (groups of 4 "
                                      "bits) fit a word")
                    .arg(shown)
                    .arg(p.digits)
                    .arg(most),
                static_cast<int>(lead)};
        auto a = parseAddress(target, base, model);
        if (const AddressError *e = std::get_if<AddressError>(&a))
            return shifted(*e, lead + p.baseStart);
        const Address first = std::get<Address>(a);
        const Area &area = target.area(first.area);
        if (area.kind != AreaKind::Bit)
            return AddressError{
                InstructionListTr::tr("%1: K%2 takes a bit device (the first of its bits), not "
                                      "%3")
                    .arg(shown)
                    .arg(p.digits)
                    .arg(base.toString()),
                static_cast<int>(lead + p.baseStart)};
        const int bits = p.digits * 4;
        for (int k = 1; k < bits; ++k)
            if (!offsetAddress(target, first, k, model).valid()) {
                const QString last =
                    formatAddress(target, Address{first.area, first.index + bits - 1, -1});
                const QString missing =
                    formatAddress(target, Address{first.area, first.index + k, -1});
                return AddressError{
                    InstructionListTr::tr("%1 takes the %2 bits %3..%4, but %5 does not exist")
                        .arg(shown)
                        .arg(bits)
                        .arg(formatAddress(target, first), last, missing),
                    static_cast<int>(lead + p.baseStart)};
            }
        o.kind = Operand::Kind::Device;
        o.address = first;
        o.digits = p.digits;
    } else {
        auto a = parseAddress(target, base, model);
        if (const Address *address = std::get_if<Address>(&a)) {
            const Area &area = target.area(address->area);
            if (area.indexRegister)
                return AddressError{
                    InstructionListTr::tr("%1: an index register cannot be indexed").arg(shown),
                    static_cast<int>(lead)};
            if (area.kind == AreaKind::Bit || address->bit >= 0)
                return AddressError{
                    InstructionListTr::tr(
                        "%1: index registers modify words (D0E0, K4M0E0) and K constants, "
                        "not the bit %2")
                        .arg(shown, base.toString()),
                    static_cast<int>(lead)};
            o.kind = Operand::Kind::Device;
            o.address = *address;
        } else {
            auto c = parseConstant(target, base);
            const Constant *constant = std::get_if<Constant>(&c);
            if (!constant)
                return shifted(std::get<AddressError>(a), lead + p.baseStart);
            if (constant->style != Constant::Style::Decimal)
                return AddressError{
                    InstructionListTr::tr("%1: index registers modify K constants, not %2")
                        .arg(shown, base.toString()),
                    static_cast<int>(lead)};
            o.kind = Operand::Kind::Constant;
            o.constant = *constant;
        }
    }
    if (p.indexStart >= 0) {
        const QStringView indexText = s.mid(p.indexStart);
        auto a = parseAddress(target, indexText, model);
        if (const AddressError *e = std::get_if<AddressError>(&a))
            return shifted(*e, lead + p.indexStart);
        const Address index = std::get<Address>(a);
        if (!target.area(index.area).indexRegister)
            return AddressError{InstructionListTr::tr("%1: %2 is not an index register (%3)")
                                    .arg(shown, indexText.toString(), indexRegisterNames(target)),
                                static_cast<int>(lead + p.indexStart)};
        o.index = index;
    }
    return o;
}

} // namespace rung::model
