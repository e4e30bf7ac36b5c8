#include "model/checks/checks_list_detail.h"
#include "model/tr.h"

// The program's length against the model's steps (LN001; docs/diagnostics.md).

namespace rung::model::detail {

void ListChecker::length() {
    int steps = 0;
    for (const Instruction &ins : m_list.instructions)
        steps += instructionSteps(m_t, ins);
    const int limit = m_model->programSteps > 0 ? m_model->programSteps : m_t.limits.programSteps;
    if (limit > 0 && steps > limit)
        add("LN001", Severity::Error, size() - 1,
            ChecksTr::tr("The program needs %1 steps; %2 holds %3")
                .arg(steps)
                .arg(m_model->name)
                .arg(limit));
}

} // namespace rung::model::detail
