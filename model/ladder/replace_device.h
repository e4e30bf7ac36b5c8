#pragma once

// Edit > Replace Device, as an edit of the program: no window needed to do or test it.

#include "model/ladder/ladder.h"

#include <vector>

namespace rung::model {

// Every operand naming `from`, in contacts and outputs, names `to` instead. Returns how many
// operands changed; constants and text operands stay.
int replaceDevice(std::vector<Rung> &rungs, const Address &from, const Address &to);

} // namespace rung::model
