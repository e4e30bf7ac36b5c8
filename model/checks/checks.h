#pragma once

// The checks the vendor tools make, on the listing and on the ladder. Every code is listed
// in docs/diagnostics.md and has a test that triggers it and one that does not.

#include "model/checks/diagnostic.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder.h"
#include "model/listing/il.h"

#include <vector>

namespace rung::model {

struct CheckOptions {
    const ModelVariant *model = nullptr; // nullptr: the family's default model
    // Only the fuzzy-syntax findings (FZ*) on the form of the text: for an editor that keeps
    // the user's listing as typed and has the program's other findings from the ladder.
    bool formOnly = false;
    // Some lines of the text did not parse and are not in the list: only what each instruction
    // shows by itself or beside the others that did (operands, double coils). The rungs,
    // blocks, stack, END and length would be judged on a list with holes, and wait until
    // every line parses.
    bool parsedLinesOnly = false;
    // The text the listing was parsed from, if at hand: operand findings then point at the
    // operand's column instead of the instruction's.
    const QString *source = nullptr;
};

// Checks on a parsed listing (fuzzy forms, END, nesting, stack, operands, duplicates, length).
std::vector<Diagnostic> checkList(const InstructionList &list, const CheckOptions &options = {});

// Checks on the ladder (reverse current, open branches, unconnected elements, outputs with no
// condition) plus every listing check mapped back to rung locations.
std::vector<Diagnostic> checkLadder(const LadderProgram &ladder, const CheckOptions &options = {});
// The same with the listing of the ladder already made (ladderToList(ladder)), as the editor
// has it: the conversion is the larger part of the work.
std::vector<Diagnostic> checkLadder(const LadderProgram &ladder, const ToListingResult &listing,
                                    const CheckOptions &options = {});

} // namespace rung::model
