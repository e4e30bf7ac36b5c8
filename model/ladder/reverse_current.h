#pragma once

// Reverse current: a rung whose network feeding an output can only be read by letting power
// cross an element right to left (a bridge). The checks report it with the cells involved and
// offer the standard correction: every left-to-right path kept, the shared contacts duplicated
// into the branches (PLC concepts (WPLSoft family) 1.8).

#include "model/ladder/ladder.h"

#include <utility>
#include <vector>

namespace rung::model {

struct ReverseCurrentFinding {
    int row = 0;                            // the output (or box input) row affected
    std::vector<std::pair<int, int>> cells; // (row, column) of the elements involved
    Rung corrected;                         // the rung rewritten series-parallel
};

std::vector<ReverseCurrentFinding> findReverseCurrent(const Rung &rung);

} // namespace rung::model
