#pragma once

// Two-way conversion between the ladder grid and the instruction list.
// Ladder -> IL writes the canonical form (docs/conversion.md); IL -> ladder accepts every
// valid ("fuzzy") form and lays it out on the grid.

#include "model/checks/diagnostic.h"
#include "model/ladder/ladder.h"
#include "model/listing/il.h"

#include <vector>

namespace rung::model {

// Where an instruction written from a ladder came from, so the power flow of each instruction
// can be drawn on its cell (docs/conversion.md "Origin map").
struct CellOrigin {
    int rung = -1;
    // A contact (INV included): its cell. An output: its row and the output column
    // (Rung::columns). ANB, ORB, MPS, MRD, MPP, IL, ILC and the always-ON load an interlock
    // writes: the rung only (row and column -1).
    int row = -1;
    int column = -1;
    friend bool operator==(const CellOrigin &, const CellOrigin &) = default;
};

struct ToListingResult {
    InstructionList list;
    std::vector<CellOrigin> origin; // parallel to list.instructions
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
// What listToLadder reports, without drawing the ladder: the checks need only this, and a
// drawing of a 10,000-rung list is most of their memory.
std::vector<Diagnostic> listToLadderProblems(const InstructionList &list);

} // namespace rung::model
