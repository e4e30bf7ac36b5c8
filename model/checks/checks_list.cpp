#include "model/checks/checks.h"
#include "model/checks/checks_list_detail.h"
#include "model/convert/convert.h"
#include "model/tr.h"

#include <algorithm>

// The listing checks (docs/diagnostics.md). Each finding remembers the instruction it is
// about, so the ladder checks can show it on the rung that instruction came from. The checks
// run here in their order; each is in the file named after it (checks_list_detail.h).

namespace rung::model::detail {

std::vector<Finding> ListChecker::run() {
    spans();
    if (m_parsedLinesOnly) {
        operands();
        duplicates();
        return std::move(m_found);
    }
    blocksAndStack();
    if (m_formOnly) {
        std::erase_if(m_found, [](const Finding &f) {
            return !f.diagnostic.code.startsWith(QLatin1String("FZ"));
        });
        return std::move(m_found);
    }
    endAndNesting(m_list, m_found);
    offerEnd();
    operands();
    switchedElements(m_list, m_found);
    duplicates();
    length();
    // Read only here: a form-only check (betterForm) needs no reading of the whole list.
    structure(listToLadderProblems(m_list));
    return std::move(m_found);
}

// EN001 (END is missing): END on a line of its own after the last instruction's line, that
// line kept as typed.
void ListChecker::offerEnd() {
    const InstructionSpec *end = m_t.findInstruction(Op::End);
    if (!end || !m_source || size() == 0)
        return;
    for (Finding &f : m_found) {
        const int line = f.diagnostic.location.line;
        if (f.diagnostic.code != QLatin1String("EN001") || line <= 0)
            continue;
        if (m_sourceLines.isEmpty())
            m_sourceLines = m_source->split(QLatin1Char('\n'));
        QString last = m_sourceLines.value(line - 1);
        if (last.endsWith(QLatin1Char('\r')))
            last.chop(1);
        Fix fix;
        fix.label = ChecksTr::tr("Append %1").arg(end->mnemonic);
        fix.firstLine = fix.lastLine = line;
        fix.listing = last + QLatin1Char('\n') + end->mnemonic + QLatin1Char('\n');
        f.diagnostic.fix = std::move(fix);
    }
}

std::vector<Finding> checkListFindings(const InstructionList &list, const CheckOptions &options,
                                       bool forms) {
    if (!list.target)
        return {};
    ListChecker checker(list, options);
    checker.setForms(forms);
    return checker.run();
}

} // namespace rung::model::detail

namespace rung::model {

std::vector<Diagnostic> checkList(const InstructionList &list, const CheckOptions &options) {
    std::vector<Diagnostic> out;
    for (detail::Finding &f : detail::checkListFindings(list, options))
        out.push_back(std::move(f.diagnostic));
    sortDiagnostics(out);
    return out;
}

} // namespace rung::model
