#pragma once

// A listing finding with the instructions it is about, so the ladder checks can place it on
// the rung those instructions came from. Internal to model/.

#include "checks.h"

#include <vector>

namespace rung::model::detail {

struct Finding {
    Diagnostic diagnostic;
    int instruction = -1;     // index in the listing
    std::vector<int> related; // indexes of the related instructions
};

std::vector<Finding> checkListFindings(const InstructionList &list, const CheckOptions &options);

} // namespace rung::model::detail
