#pragma once

// The builders of the four families' tables (target_vpc.cpp, target_vigor.cpp,
// target_cpm1.cpp, target_pl110.cpp) and the small helpers they share. Only target.cpp
// calls the builders.

#include "model/target/target.h"

#include <algorithm>

namespace rung::model::detail {

Target makeVpcTarget();
Target makeVigorTarget();
Target makeCpm1Target();
Target makePl110Target();

// The CPM1's application instructions (target_cpm1_instructions.cpp).
void addCpm1ApplicationInstructions(Target &t);

// The PL110's serial ports, their byte buffers and SEND / COM / EXP (target_pl110_comm.cpp).
std::vector<PortSpec> pl110Ports();
void addPl110SerialBuffers(Target &t);
void addPl110Communication(Target &t);
// The PL110's front panel: its lamps, the PL110-2A's terminal (target_pl110_panel.cpp).
void addPl110Panel(Target &t);

// Appends an area and returns it for the fields that differ from the defaults.
inline Area &addArea(Target &t, const char *key, const char *prefix, AreaKind kind, int first,
                     int last, const char *description) {
    Area a;
    a.key = QString::fromLatin1(key);
    a.prefix = QString::fromLatin1(prefix);
    a.kind = kind;
    a.first = first;
    a.last = last;
    a.description = description;
    t.areas.push_back(a);
    return t.areas.back();
}

// Appends an instruction and returns it for the fields that differ from the defaults.
inline InstructionSpec &addSpec(Target &t, const char *mnemonic, Op op,
                                std::vector<OperandSpec> operands, const char *summary,
                                const char *operandHelp = nullptr) {
    InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.operands = std::move(operands);
    s.summary = summary;
    s.operandHelp = operandHelp;
    t.instructions.push_back(std::move(s));
    return t.instructions.back();
}

// Bit terminals first..first+count-1 of an area, in blocks of `per` (a terminal strip's
// groups: 8 on the Vigor's octal X/Y, 8 on the VPC and PL110).
inline void addTerminals(ModelVariant &m, const char *area, int first, int count, int per = 8) {
    for (int k = 0; k < count; k += per)
        m.terminals.push_back(
            {QString::fromLatin1(area), first + k, std::min(per, count - k), 0, 0, false, nullptr});
}

// Word terminals (analog values) lowest..highest, one block.
inline void addWordTerminals(ModelVariant &m, const char *area, int first, int count, int lowest,
                             int highest, bool bcd = false, const char *label = nullptr) {
    if (count > 0)
        m.terminals.push_back(
            {QString::fromLatin1(area), first, count, lowest, highest, bcd, label});
}

} // namespace rung::model::detail
