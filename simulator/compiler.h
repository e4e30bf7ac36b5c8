#pragma once

#include "program.h"

#include "model/il.h"

namespace rung::simulator {

// Compiles a parsed instruction list for scanning. Errors (an instruction the simulator
// cannot run, a stack that underflows, an operand of the wrong kind) leave the result
// without a program; boxes the simulator does not model give a "not simulated" warning and
// run as NOP. Every diagnostic carries the instruction's line and column.
CompileResult compileProgram(const model::InstructionList &list);

} // namespace rung::simulator
