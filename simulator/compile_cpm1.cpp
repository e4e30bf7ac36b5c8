#include "compiler_detail.h"

// The Omron CPM1's application instructions (W353) to steps: the word and BCD arithmetic
// with the flags ER / CY / GR / EQ / LE, the shift registers, the subroutines and the steps.
// The engine runs them in engine_cpm1.cpp.

namespace rung::simulator::detail {

void Compiler::bindFlag(model::SystemRole role, BitRef bit) {
    ArithmeticFlags &f = m_program->flags;
    switch (role) {
    case model::SystemRole::InstructionError:
        f.error = bit;
        break;
    case model::SystemRole::Carry:
        f.carry = bit;
        break;
    case model::SystemRole::Greater:
        f.greater = bit;
        break;
    case model::SystemRole::Equal:
        f.equal = bit;
        break;
    case model::SystemRole::Less:
        f.less = bit;
        break;
    case model::SystemRole::StepStart:
        f.stepStart = bit;
        break;
    default:
        break;
    }
}

void Compiler::compileArithmetic(const model::Instruction &ins, Step &s) {
    using model::ApplyFunction;
    const ApplyFunction f = ins.spec->function;
    s.code = Code::Arithmetic;
    // The words St..E of a range whose operand rules (same area, E not before St) `check` and
    // reportBreaches have seen.
    const auto range = [&](std::size_t first, std::size_t last) {
        s.dest = destOf(ins, first, false, &s.width);
        const std::int32_t end = destOf(ins, last, false, &s.width);
        s.count = s.dest >= 0 && end >= s.dest ? end - s.dest + 1 : 0;
    };
    switch (f) {
    case ApplyFunction::CompareToFlags:
        s.op = static_cast<std::uint8_t>(ArithOp::Compare);
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        break;
    case ApplyFunction::ShiftRegister:
        // LD data / LD shift pulse / LD reset / SFT(10) St E: three inputs.
        s.code = Code::ShiftRegister;
        range(0, 1);
        edgeStep(s, Code::ShiftRegister, false);
        popBlocks(ins, 2);
        break;
    case ApplyFunction::WordShift:
        s.op = static_cast<std::uint8_t>(ArithOp::WordShift);
        range(0, 1);
        break;
    case ApplyFunction::MoveNot:
        s.op = static_cast<std::uint8_t>(ArithOp::MoveNot);
        s.x = sourceOf(ins, 0);
        s.dest = destOf(ins, 1, false, &s.width);
        break;
    case ApplyFunction::MoveBit:
    case ApplyFunction::MoveDigit:
        s.op = static_cast<std::uint8_t>(f == ApplyFunction::MoveBit ? ArithOp::MoveBit
                                                                     : ArithOp::MoveDigit);
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        s.dest = destOf(ins, 2, false, &s.width);
        break;
    case ApplyFunction::BcdIncrement:
    case ApplyFunction::BcdDecrement:
        s.op = static_cast<std::uint8_t>(f == ApplyFunction::BcdIncrement ? ArithOp::BcdIncrement
                                                                          : ArithOp::BcdDecrement);
        s.dest = destOf(ins, 0, false, &s.width);
        s.x.index = s.dest;
        break;
    case ApplyFunction::BcdAdd:
    case ApplyFunction::BcdSubtract:
    case ApplyFunction::BcdMultiply:
    case ApplyFunction::BcdDivide:
    case ApplyFunction::BinaryAdd:
    case ApplyFunction::BinarySubtract:
        s.op = static_cast<std::uint8_t>(f == ApplyFunction::BcdAdd        ? ArithOp::BcdAdd
                                         : f == ApplyFunction::BcdSubtract ? ArithOp::BcdSubtract
                                         : f == ApplyFunction::BcdMultiply ? ArithOp::BcdMultiply
                                         : f == ApplyFunction::BcdDivide   ? ArithOp::BcdDivide
                                         : f == ApplyFunction::BinaryAdd   ? ArithOp::BinaryAdd
                                                                         : ArithOp::BinarySubtract);
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        s.dest = destOf(ins, 2, false, &s.width);
        if (f == ApplyFunction::BcdMultiply || f == ApplyFunction::BcdDivide)
            s.count = nextWord(ins, 2);
        break;
    case ApplyFunction::SetCarry:
    case ApplyFunction::ClearCarry:
        s.op = static_cast<std::uint8_t>(f == ApplyFunction::SetCarry ? ArithOp::SetCarry
                                                                      : ArithOp::ClearCarry);
        break;
    case ApplyFunction::FailureAlarm: {
        // FAL(06) N: N into the byte the target names for it (W353: SR 253.00..253.07).
        s.op = static_cast<std::uint8_t>(ArithOp::FailureAlarm);
        s.x = sourceOf(ins, 0);
        s.dest = -1;
        if (const model::SystemDevice *d = m_target.systemDevice(model::SystemRole::AlarmNumber)) {
            const auto parsed = model::parseAddress(m_target, d->device);
            if (const auto *a = std::get_if<model::Address>(&parsed))
                s.dest = m_layout->word(*a);
        }
        break;
    }
    case ApplyFunction::SubroutineCall:
        s.code = Code::SubroutineCall; // its SBN(92): resolveSubroutines
        s.count = -1;
        break;
    case ApplyFunction::StepNext: {
        s.code = Code::StepNext;
        s.bit = bitOf(ins, 0);
        s.slot = -1;
        if (m_stepBit.valid()) {
            s.slot = static_cast<int>(m_program->bitLists.size());
            m_program->bitLists.push_back(m_stepBit);
        }
        break;
    }
    default:
        break;
    }
}

void Compiler::compileControl(const model::Instruction &ins, Step &s) {
    switch (ins.op()) {
    case Op::SubroutineStart:
        s.code = Code::SubroutineStart; // to END: resolveSubroutines
        s.slot = static_cast<int>(m_list.instructions.size());
        break;
    case Op::SubroutineReturn:
        s.code = Code::SubroutineReturn;
        break;
    case Op::StepDefine:
        // STEP(08) B opens the step of B, STEP(08) alone ends the step area.
        s.code = Code::StepDefine;
        m_stepBit = ins.operands.empty() ? BitRef{} : bitOf(ins, 0);
        s.bit = m_stepBit;
        edgeStep(s, Code::StepDefine, false);
        break;
    default:
        break;
    }
}

// SBS(91) N runs the SBN(92) N that model::pairBlocks paired with it; the first SBN ends the
// main program, which goes on to END (W353: subroutines after the main program, before END).
void Compiler::resolveSubroutines(const model::BlockPairs &pairs) {
    for (std::size_t k = 0; k < m_list.instructions.size(); ++k) {
        Step &s = m_program->steps[k];
        if (s.code == Code::SubroutineCall)
            s.count = pairs.partner[k];
        else if (s.code == Code::SubroutineStart && pairs.end >= 0)
            s.slot = pairs.end;
    }
}

} // namespace rung::simulator::detail
