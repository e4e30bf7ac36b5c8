#include "model/checks/operand_rules.h"

#include "model/target/address.h"

#include <QCoreApplication>

#include <algorithm>

namespace rung::model {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Checks)
};

QString slotName(const OperandSpec &spec, std::size_t k) {
    if (spec.name)
        return QCoreApplication::translate("rung::model::Target", spec.name);
    return Tr::tr("operand %1").arg(k + 1);
}

const InstructionSpec *writerOf(const Target &target, ApplyFunction function) {
    for (const InstructionSpec &s : target.instructions)
        if (s.function == function)
            return &s;
    return nullptr;
}

int areaByKey(const Target &target, const char *key) {
    for (std::size_t i = 0; i < target.areas.size(); ++i)
        if (target.areas[i].key == QLatin1String(key))
            return static_cast<int>(i);
    return -1;
}

bool isDestination(OperandKind kind) {
    return kind == OperandKind::BitDest || kind == OperandKind::WordDest;
}

} // namespace

std::vector<OperandBreach> operandBreaches(const Target &target, const Instruction &ins) {
    std::vector<OperandBreach> found;
    if (!ins.spec)
        return found;
    const InstructionSpec &spec = *ins.spec;
    for (std::size_t k = 0; k < ins.operands.size() && k < spec.operands.size(); ++k) {
        const Operand &o = ins.operands[k];
        const OperandSpec &rule = spec.operands[k];
        const int at = static_cast<int>(k);
        if (o.kind == Operand::Kind::Constant) {
            const qint64 v = o.constant.value;
            if (!rule.allowedValues.empty() &&
                std::find(rule.allowedValues.begin(), rule.allowedValues.end(), v) ==
                    rule.allowedValues.end()) {
                QStringList values;
                for (int a : rule.allowedValues)
                    values << QString::number(a);
                const QString last = values.takeLast();
                const QString choices =
                    values.isEmpty()
                        ? last
                        : Tr::tr("%1 or %2").arg(values.join(QStringLiteral(", ")), last);
                found.push_back({at, Tr::tr("the %1 of %2 must be %3, not %4")
                                         .arg(slotName(rule, k), spec.mnemonic, choices)
                                         .arg(v)});
            } else if ((rule.lowest != INT_MIN || rule.highest != INT_MAX) &&
                       (v < rule.lowest || v > rule.highest)) {
                found.push_back({at, Tr::tr("the %1 of %2 must be from %3 to %4, not %5")
                                         .arg(slotName(rule, k), spec.mnemonic)
                                         .arg(rule.lowest)
                                         .arg(rule.highest)
                                         .arg(v)});
            }
            continue;
        }
        if (o.kind != Operand::Kind::Device || !o.address.valid() ||
            o.address.area >= static_cast<int>(target.areas.size()))
            continue;
        const Area &area = target.area(o.address.area);
        if (rule.wholeWords && (o.digits > 0 || area.doubleWordsOf)) {
            // A block counts words: K4M0 or VD0 would make its length mean something else.
            found.push_back(
                {at, Tr::tr("%1 moves whole words: %2 cannot be its %3")
                         .arg(spec.mnemonic, formatOperand(target, o), slotName(rule, k))});
            continue;
        }
        if (!rule.sourceAreas.empty() &&
            std::none_of(rule.sourceAreas.begin(), rule.sourceAreas.end(),
                         [&](const char *key) { return area.key == QLatin1String(key); })) {
            QStringList prefixes;
            for (const char *key : rule.sourceAreas)
                if (const int a = areaByKey(target, key); a >= 0)
                    prefixes << target.area(a).prefix;
            found.push_back(
                {at, Tr::tr("%1 takes its %2 from a constant or from %3, not %4")
                         .arg(spec.mnemonic, slotName(rule, k), prefixes.join(QStringLiteral(", ")),
                              formatOperand(target, o))});
            continue;
        }
        const bool wrongArea = rule.area && area.key != QLatin1String(rule.area);
        if (wrongArea || o.address.index < rule.lowest || o.address.index > rule.highest) {
            // "OUTQI writes only Q1..Q8, not Q9": the range as the listing writes it.
            const int ruleArea = rule.area ? areaByKey(target, rule.area) : o.address.area;
            if (ruleArea >= 0) {
                const Area &a = target.area(ruleArea);
                const QString first =
                    formatAddress(target, Address{ruleArea, std::max(a.first, rule.lowest), -1});
                const QString last =
                    formatAddress(target, Address{ruleArea, std::min(a.last, rule.highest), -1});
                found.push_back(
                    {at, Tr::tr("%1 takes only %2..%3, not %4")
                             .arg(spec.mnemonic, first, last, formatAddress(target, o.address))});
            }
            continue;
        }
        // seed 003 4.2.3: a bistable relay changes only on its own coil.
        if (isDestination(rule.kind) && area.onlyWrittenBy != ApplyFunction::None &&
            spec.function != area.onlyWrittenBy) {
            const InstructionSpec *writer = writerOf(target, area.onlyWrittenBy);
            found.push_back(
                {at, Tr::tr("%1 cannot write %2: %3 are written only by %4")
                         .arg(spec.mnemonic, formatAddress(target, o.address),
                              QCoreApplication::translate("rung::model::Target", area.description),
                              writer ? writer->mnemonic : QString())});
        }
    }
    return found;
}

QString notSimulatedMessage(const InstructionSpec &spec) {
    return Tr::tr("%1 is not simulated: it does nothing in the simulator").arg(spec.mnemonic);
}

} // namespace rung::model
