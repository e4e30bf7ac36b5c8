#include "model/target/target.h"

#include "model/target/address.h"
#include "model/target/target_data.h"

#include <array>

namespace rung::model {

namespace {

constexpr std::array kFamilies{Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110};
// The family a new, empty document and the new-project dialog start with.
constexpr Family kDefaultFamily = Family::Vigor;

struct Registry {
    Target vpc = detail::makeVpcTarget();
    Target vigor = detail::makeVigorTarget();
    Target cpm1 = detail::makeCpm1Target();
    Target pl110 = detail::makePl110Target();
    Registry() {
        for (Target *t : {&vpc, &vigor, &cpm1, &pl110})
            t->buildIndex();
    }
};

const Registry &registry() {
    static const Registry instance; // built once, thread-safe, never changes afterwards
    return instance;
}

// "KEEP(11)" -> "KEEP", 11; "LD" -> "LD", -1
QString stripFunctionCode(const QString &mnemonic, int *code) {
    *code = -1;
    const qsizetype open = mnemonic.indexOf(QLatin1Char('('));
    if (open > 0 && mnemonic.endsWith(QLatin1Char(')'))) {
        bool ok = false;
        const int value = mnemonic.mid(open + 1, mnemonic.size() - open - 2).toInt(&ok);
        if (ok) {
            *code = value;
            return mnemonic.left(open).trimmed();
        }
    }
    return mnemonic;
}

QString normalizeSpaces(const QString &text) {
    // What the parser asks nearly always, an upper-case mnemonic with single spaces ("LD",
    // "AND LD"), is its own normal form: no copy.
    bool normal = !text.isEmpty();
    for (qsizetype i = 0; normal && i < text.size(); ++i) {
        const char16_t u = text[i].unicode();
        const bool space = u == ' ';
        normal = u < 0x80 && !(u >= 'a' && u <= 'z') && !(u >= '\t' && u <= '\r') &&
                 !(space && (i == 0 || i + 1 == text.size() || text[i - 1] == QLatin1Char(' ')));
    }
    return normal ? text : text.simplified().toUpper();
}

struct CompareSymbol {
    const char *text;
    CompareOp op;
};
// Every way a listing writes an operator, the longest first; the first of each operator is
// how it is printed.
constexpr CompareSymbol kCompareSymbols[] = {
    {"<>", CompareOp::Ne}, {"<=", CompareOp::Le}, {">=", CompareOp::Ge}, {"=<", CompareOp::Le},
    {"=>", CompareOp::Ge}, {"<", CompareOp::Lt},  {">", CompareOp::Gt},  {"=", CompareOp::Eq}};

} // namespace

const char *compareSymbol(CompareOp op) {
    for (const CompareSymbol &s : kCompareSymbols)
        if (s.op == op)
            return s.text;
    return "";
}

std::optional<CompareAt> findCompare(QStringView text) {
    for (const CompareSymbol &s : kCompareSymbols) {
        const qsizetype at = text.indexOf(QLatin1String(s.text));
        if (at > 0)
            return CompareAt{s.op, at, qsizetype(qstrlen(s.text))};
    }
    return std::nullopt;
}

const Target &Target::get(Family family) {
    const Registry &r = registry();
    switch (family) {
    case Family::Vpc:
        return r.vpc;
    case Family::Vigor:
        return r.vigor;
    case Family::Cpm1:
        return r.cpm1;
    case Family::Pl110:
        return r.pl110;
    }
    return r.vpc;
}

const Target &Target::defaultTarget() {
    return get(kDefaultFamily);
}

const Target *Target::byId(const QString &id) {
    for (Family f : kFamilies) {
        const Target &t = get(f);
        if (t.id.compare(id, Qt::CaseInsensitive) == 0)
            return &t;
    }
    return nullptr;
}

std::span<const Family> Target::families() {
    return kFamilies;
}

const ModelVariant *Target::model(const QString &name) const {
    for (const ModelVariant &m : models)
        if (m.name.compare(name, Qt::CaseInsensitive) == 0)
            return &m;
    return nullptr;
}

const ModelVariant &Target::defaultModel() const {
    // The largest model is the default: a program written for it fits every smaller check
    // the user opts into by choosing a model.
    return models.back();
}

std::vector<Target::PrefixSpelling> Target::makePrefixSpellings() const {
    std::vector<PrefixSpelling> out;
    for (int i = 0; i < static_cast<int>(areas.size()); ++i) {
        const Area &a = area(i);
        QStringList spellings{a.prefix};
        spellings << a.prefixAliases;
        for (const QString &spelling : spellings)
            out.push_back({squeezeAddress(spelling), i});
    }
    return out;
}

void Target::buildIndex() {
    m_prefixes = makePrefixSpellings();
    m_spellings.clear();
    for (int i = 0; i < static_cast<int>(instructions.size()); ++i) {
        const InstructionSpec &spec = instructions[static_cast<std::size_t>(i)];
        m_spellings.insert(normalizeSpaces(spec.mnemonic), i);
        for (const QString &alias : spec.aliases)
            m_spellings.insert(normalizeSpaces(alias), i);
    }
}

const InstructionSpec *Target::findInstruction(const QString &mnemonic) const {
    int code = -1;
    const QString wanted = normalizeSpaces(stripFunctionCode(mnemonic.trimmed(), &code));
    if (!m_spellings.isEmpty()) {
        // The first entry of the table that matches, as the linear search below finds it.
        int best = -1;
        for (auto it = m_spellings.constFind(wanted);
             it != m_spellings.cend() && it.key() == wanted; ++it) {
            const InstructionSpec &spec = instructions[static_cast<std::size_t>(it.value())];
            if (code >= 0 && spec.functionCode != code)
                continue;
            if (best < 0 || it.value() < best)
                best = it.value();
        }
        return best >= 0 ? &instructions[static_cast<std::size_t>(best)] : nullptr;
    }
    for (const InstructionSpec &spec : instructions) {
        bool match = normalizeSpaces(spec.mnemonic) == wanted;
        for (const QString &alias : spec.aliases)
            match = match || normalizeSpaces(alias) == wanted;
        if (!match)
            continue;
        if (code >= 0 && spec.functionCode != code)
            continue; // "KEEP(12)" is not KEEP
        return &spec;
    }
    return nullptr;
}

const InstructionSpec *Target::findInstruction(Op op, ContactMode mode, CompareOp compare,
                                               bool negated) const {
    for (const InstructionSpec &spec : instructions)
        if (spec.op == op && spec.mode == mode && spec.compare == compare &&
            spec.negated == negated)
            return &spec;
    return nullptr;
}

int Target::indexOf(const InstructionSpec *spec) const {
    if (!spec || instructions.empty() || spec < &instructions.front() ||
        spec > &instructions.back())
        return -1;
    return static_cast<int>(spec - &instructions.front());
}

std::optional<std::pair<int, int>> Target::range(int areaIndex, const ModelVariant *variant) const {
    const Area &a = area(areaIndex);
    std::pair<int, int> r{a.first, a.last};
    if (variant) {
        for (const ModelVariant::Override &o : variant->overrides) {
            if (o.area != a.key)
                continue;
            if (o.last < o.first)
                return std::nullopt;
            r = {std::max(a.first, o.first), std::min(a.last, o.last)};
            if (r.second < r.first)
                return std::nullopt;
        }
    }
    return r;
}

const SystemDevice *Target::systemDevice(SystemRole role) const {
    for (const SystemDevice &d : systemDevices)
        if (d.role == role)
            return &d;
    return nullptr;
}

const PortSpec *Target::port(QStringView name) const {
    for (const PortSpec &p : ports)
        if (name.compare(p.name, Qt::CaseInsensitive) == 0)
            return &p;
    return nullptr;
}

bool drivenByPlc(const SystemDevice &device) {
    switch (device.role) {
    case SystemRole::Other:
    case SystemRole::Error:
    case SystemRole::Connected:
        return false;
    default:
        return !device.programWrites;
    }
}

} // namespace rung::model
