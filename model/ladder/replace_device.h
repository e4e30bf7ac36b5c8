#pragma once

// Edit > Replace Device, as an edit of the program: no window needed to do or test it.

#include "model/ladder/ladder.h"

#include <QString>

#include <vector>

namespace rung::model {

// Every operand naming `from`, in contacts and outputs, names `to` instead. Returns how many
// operands changed; constants and text operands stay. When `to` cannot stand in one of the
// places `from` holds (a word where a contact needs a bit, a marker where a timer is
// expected), nothing changes, the result is -1 and `problem` says where and why (translated).
int replaceDevice(std::vector<Rung> &rungs, const Target &target, const Address &from,
                  const Address &to, QString *problem = nullptr);

} // namespace rung::model
