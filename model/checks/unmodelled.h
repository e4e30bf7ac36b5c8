#pragma once

// Devices the simulator keeps as plain memory while the PLC does more with them
// (Target::unmodelled: PL110 display pages, keys and page request, PL110 manual 2.1.2). `check`
// warns SIM101 at each use and the simulator's compiler again when a simulation starts, with
// the same words, so nobody trusts a trace of what is not modelled.

#include "model/listing/il.h"

#include <vector>

namespace rung::model {

struct UnmodelledUse {
    int operand = 0; // index in Instruction::operands
    QString message; // translated: "SM106 is not simulated: ..."
};

std::vector<UnmodelledUse> unmodelledUses(const Target &target, const Instruction &ins);

} // namespace rung::model
