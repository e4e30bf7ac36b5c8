#include "model/checks/checks_internal.h"
#include "model/listing/structure.h"
#include "model/tr.h"

#include <QCoreApplication>

// END and the nesting of IL/ILC, JMP/JPE (JME) and STL/RET (docs/diagnostics.md EN*, NE*, SL*).

namespace rung::model::detail {

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
        Finding &f = add("EN001", Severity::Error, count - 1, ChecksTr::tr("END is missing"));
        if (count == 0)
            f.diagnostic.location.line = 1;
    }
    if (end >= 0 && end + 1 < count)
        add("EN002", Severity::Warning, end + 1,
            ChecksTr::tr("Instructions after END are never executed"));

    // IL / ILC, JMP / JPE (JME), STL / RET: the one pairing the compiler uses too.
    for (const BlockProblem &p : pairBlocks(list).problems) {
        Finding &f =
            add(p.code, p.warning ? Severity::Warning : Severity::Error, p.instruction, p.message);
        if (p.related >= 0)
            f.diagnostic.related.push_back(location(p.related));
    }
}

} // namespace rung::model::detail
