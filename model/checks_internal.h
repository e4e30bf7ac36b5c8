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
    // The message for the ladder, where listing lines mean nothing: %1 is the rung (1-based)
    // of the first related instruction. Empty: the message serves both.
    QString ladderMessage;
};

// forms == false: no fuzzy-form findings (the ladder's own listing), and none of their work.
std::vector<Finding> checkListFindings(const InstructionList &list, const CheckOptions &options,
                                       bool forms = true);

} // namespace rung::model::detail
