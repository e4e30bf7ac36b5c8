#pragma once

#include "program.h"

#include "model/checks/checks.h"
#include "model/listing/il.h"

namespace rung::simulator {

// Compiles a parsed instruction list for scanning. Errors (an instruction the simulator
// cannot run, a stack that underflows, an operand of the wrong kind) leave the result
// without a program; boxes the simulator does not model give a "not simulated" warning and
// run as NOP. Every diagnostic carries the instruction's line and column.
CompileResult compileProgram(const model::InstructionList &list);

// What starting a simulation does: the checks the PLC would make (model::checkList) and then
// compileProgram. A program with a check error does not start: the result has no program and
// its diagnostics say why (the check errors first; warnings of the checks are left to the
// editor's problems list, so a running simulation is not buried in style advice).
CompileResult prepareProgram(const model::InstructionList &list,
                             const model::CheckOptions &options = {});

} // namespace rung::simulator
