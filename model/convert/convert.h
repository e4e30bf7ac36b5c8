#pragma once

// Two-way conversion between the ladder grid and the instruction list.
// Ladder -> IL writes the canonical form (docs/conversion.md); IL -> ladder accepts every
// valid ("fuzzy") form and lays it out on the grid.

#include "model/checks/diagnostic.h"
#include "model/ladder/ladder.h"
#include "model/listing/il.h"

#include <vector>

namespace rung::model {

struct ToListingResult {
    InstructionList list;
    // rungFirst[r] = index of the first instruction of rung r; rungFirst.back() = size.
    std::vector<int> rungFirst;
    // Rungs that cannot be expressed (reverse current, open branches, a box without inputs):
    // reported here with their cells; such rungs emit nothing.
    std::vector<Diagnostic> problems;
    bool ok() const;
};

struct ToLadderResult {
    LadderProgram ladder;
    // firstLine of each rung's instructions in the source (1-based), for cursor sync.
    std::vector<int> rungLine;
    std::vector<Diagnostic> problems; // stack underflow, a block left open, ...
    bool ok() const;
};

ToListingResult ladderToList(const LadderProgram &ladder);
ToLadderResult listToLadder(const InstructionList &list);

} // namespace rung::model
