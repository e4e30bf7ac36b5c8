#include "model/checks/checks_internal.h"

#include <QCoreApplication>

#include <map>

// END and the nesting of IL/ILC, JMP/JPE (JME) and STL/RET (docs/diagnostics.md EN*, NE*, SL*).

namespace rung::model::detail {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Checks)
};

} // namespace

Finding &addFinding(std::vector<Finding> &found, const InstructionList &list, const char *code,
                    Severity severity, int index, const QString &message) {
    Finding f;
    f.diagnostic.code = QString::fromLatin1(code);
    f.diagnostic.severity = severity;
    f.diagnostic.message = message;
    f.instruction = index;
    if (index >= 0 && index < static_cast<int>(list.instructions.size())) {
        const Instruction &ins = list.instructions[static_cast<std::size_t>(index)];
        f.diagnostic.location.line = ins.line;
        f.diagnostic.location.column = ins.column;
    }
    found.push_back(std::move(f));
    return found.back();
}

void endAndNesting(const InstructionList &list, std::vector<Finding> &found) {
    const Target &t = *list.target;
    const int count = static_cast<int>(list.instructions.size());
    const auto at = [&](int i) -> const Instruction & {
        return list.instructions[static_cast<std::size_t>(i)];
    };
    const auto name = [&](int i) { return at(i).spec ? at(i).spec->mnemonic : QString(); };
    const auto location = [&](int i) {
        Location l;
        l.line = at(i).line;
        l.column = at(i).column;
        return l;
    };
    const auto add = [&](const char *code, Severity severity, int index,
                         const QString &message) -> Finding & {
        return addFinding(found, list, code, severity, index, message);
    };
    const bool needsEnd = t.findInstruction(Op::End) != nullptr;
    int end = -1;
    for (int i = 0; i < count; ++i)
        if (at(i).op() == Op::End) {
            end = i;
            break;
        }
    if (needsEnd && end < 0) {
        Finding &f = add("EN001", Severity::Error, count - 1, Tr::tr("END is missing"));
        if (count == 0)
            f.diagnostic.location.line = 1;
    }
    if (end >= 0 && end + 1 < count)
        add("EN002", Severity::Warning, end + 1,
            Tr::tr("Instructions after END are never executed"));

    int il = -1;
    int jmp = -1;
    int stl = -1;
    std::map<qint64, int> jmpLabels;
    std::map<qint64, int> jmeLabels;
    const bool labels = t.limits.jumpLabels > 0;
    for (int i = 0; i < (end >= 0 ? end : count); ++i) {
        const Op op = at(i).op();
        switch (op) {
        case Op::Interlock:
            if (il >= 0)
                add("NE001", Severity::Error, i, Tr::tr("IL inside IL: close the first with ILC"));
            il = i;
            break;
        case Op::InterlockClear:
            if (il < 0)
                add("NE002", Severity::Error, i, Tr::tr("ILC without IL (\"IL (JMP) missing\")"));
            else if (jmp > il)
                add("NE005", Severity::Error, i,
                    Tr::tr("IL-JMP interlace: the jump opened inside the interlock is still "
                           "open"));
            il = -1;
            break;
        case Op::Jump:
            if (labels) {
                const qint64 n = at(i).operands.empty() ? -1 : at(i).operands[0].constant.value;
                if (n >= t.limits.jumpLabels)
                    add("NE006", Severity::Error, i,
                        Tr::tr("Jump number %1 is beyond 00..%2")
                            .arg(n)
                            .arg(t.limits.jumpLabels - 1));
                jmpLabels.emplace(n, i);
                break;
            }
            if (jmp >= 0)
                add("NE003", Severity::Error, i, Tr::tr("JMP inside JMP: close the first jump"));
            jmp = i;
            break;
        case Op::JumpEnd:
            if (labels) {
                const qint64 n = at(i).operands.empty() ? -1 : at(i).operands[0].constant.value;
                if (jmeLabels.count(n)) {
                    Finding &f =
                        add("NE007", Severity::Error, i,
                            Tr::tr("A second %1 %2: several JMP may share a number, only one "
                                   "JME")
                                .arg(name(i))
                                .arg(n));
                    f.diagnostic.related.push_back(location(jmeLabels[n]));
                }
                if (!jmpLabels.count(n))
                    add("NE004", Severity::Error, i,
                        Tr::tr("%1 %2 without a JMP before it").arg(name(i)).arg(n));
                jmeLabels.emplace(n, i);
                break;
            }
            if (jmp < 0)
                add("NE004", Severity::Error, i,
                    Tr::tr("%1 without JMP (\"IL (JMP) missing\")").arg(name(i)));
            else if (il > jmp)
                add("NE005", Severity::Error, i,
                    Tr::tr("IL-JMP interlace: the interlock opened inside the jump is still "
                           "open"));
            jmp = -1;
            break;
        case Op::StepLadder:
            stl = i;
            break;
        case Op::Return:
            stl = -1;
            break;
        default:
            break;
        }
    }
    if (il >= 0)
        add("NE002", Severity::Error, il, Tr::tr("IL without ILC"));
    if (jmp >= 0)
        add("NE004", Severity::Error, jmp,
            Tr::tr("JMP without its end (%1)")
                .arg(t.findInstruction(Op::JumpEnd) ? t.findInstruction(Op::JumpEnd)->mnemonic
                                                    : QString()));
    for (const auto &[n, i] : jmpLabels)
        if (!jmeLabels.count(n))
            add("NE004", Severity::Error, i, Tr::tr("JMP %1 has no JME %1").arg(n));
    if (stl >= 0)
        add("SL001", Severity::Error, stl, Tr::tr("The step ladder is not closed with RET"));
}

} // namespace rung::model::detail
