#pragma once

// Test oracle: the combinational meaning of a listing and of a ladder, used to prove that
// conversion keeps meaning: every output is a boolean function of the contacts' devices. Edges,
// timers and counters are read as plain bits; the simulator is the full oracle.

#include "model/ladder/ladder.h"
#include "model/listing/il.h"

#include <functional>
#include <map>

namespace rung::model {

using BitReader = std::function<bool(const Address &)>;
// Device -> value written by output instructions, in program order (later writes win).
using OutputImage = std::map<Address, bool>;

// Evaluate one pass of the listing; instructions other than contacts, blocks, stack and
// bit outputs (OUT, SET, RST, timers' and counters' enable inputs) are skipped. IL..ILC and
// STL..RET AND every load with their condition; the target's always-ON relay reads ON.
// The ladder's outputs act in row order, each contact read just before the first output it
// feeds, so both mean the same when a rung reads what it writes (docs/conversion.md).
OutputImage evaluateList(const InstructionList &list, const BitReader &read);
OutputImage evaluateLadder(const LadderProgram &ladder, const BitReader &read);

} // namespace rung::model
