#pragma once

// What `check` and the simulator's compiler must say alike. The operand rules of the
// instruction tables beyond the area and kind of an operand
// (OperandSpec::lowest/highest/allowedValues/area, Area::onlyWrittenBy): the one place both
// `check` (OP005) and the simulator's compiler read them, so that they refuse the same
// operands with the same words.

#include "model/listing/il.h"

#include <vector>

namespace rung::model {

struct OperandBreach {
    int operand = 0; // index in Instruction::operands
    QString message; // translated, names the instruction, the operand and the rule
};

std::vector<OperandBreach> operandBreaches(const Target &target, const Instruction &ins);

// Whether a control word's digits say something the instruction can do (W353 MOVB(82) Bi,
// MOVD(83) Di); `check` asks it of a constant, the simulator of a channel's value.
bool controlWordFits(ControlWord control, qint64 word);

// "PID is not simulated: it does nothing in the simulator" (ApplyFunction::NotSimulated): the
// warning SIM100 that `check` gives and the simulator gives again when a simulation starts.
QString notSimulatedMessage(const InstructionSpec &spec);

// The words a text (Operand::Kind::String) is stored as (OperandSpec::storedFrom, PL110 MOVTXT,
// PL110 manual 4.2.10): each character's Latin-1 code a word, or two characters a word, "iniziando
// dalla parte alta della word" (an odd last character leaves the low byte 0). A character
// beyond Latin-1 is stored as 0; operandBreaches refuses it.
std::vector<std::int32_t> textWords(const QString &text, int charactersPerWord);

// The characters of operand k, a text stored in the front panel's display (its character
// area, FrontPanel::display.shownCodes), that the display does not draw, with why; empty when
// it draws them all or the text goes elsewhere. `check` warns it (OP007).
QString undisplayedCharacters(const Target &target, const Instruction &ins, std::size_t k);

} // namespace rung::model
