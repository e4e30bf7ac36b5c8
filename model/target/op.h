#pragma once

// What an instruction does, independent of its spelling, and the facts about an Op that every
// room asks (the converter, the checks, the compiler, the ladder view): written once here.

#include <cstdint>

namespace rung::model {

// What an instruction does, independent of its spelling.
enum class Op : std::uint8_t {
    Load,      // start a block with a contact
    And,       // contact in series
    Or,        // contact in parallel
    AndBlock,  // ANB / AND LD
    OrBlock,   // ORB / OR LD
    Push,      // MPS
    ReadStack, // MRD
    Pop,       // MPP
    Invert,    // INV (Vigor), NOT (PL110)
    Out,       // coil; Instruction::negated for OUT NOT
    Set,
    Reset,
    PulseRise,      // PLS / DIFU
    PulseFall,      // PLF / DIFD
    Keep,           // two inputs (set, reset), reset wins: VPC LR, CPM1 KEEP
    Timer,          // one input
    Counter,        // Vigor: one input (reset by RST); VPC/CPM1: two inputs (count, reset)
    UpDownCounter,  // three inputs (up, down, reset): CPM1 CNTR, PL110 MUP/MDOWN
    Transfer,       // VPC OUT d,s / OUT d+s / OUT d-s (and OUT* forms)
    Apply,          // application instruction box (MOV, ADD, CMP, FM, ...)
    Interlock,      // IL
    InterlockClear, // ILC
    Jump,           // JMP
    JumpEnd,        // JPE / JME
    StepLadder,     // STL
    Return,         // RET
    End,
    Nop,
    // Omron CPM1 (W353): SBN(92) N starts subroutine N, RET(93) ends it (both stand alone,
    // after the main program); STEP(08) B starts the step of control bit B, STEP(08) alone
    // ends the step area. SBS(91) and SNXT(09) are application boxes (Op::Apply).
    SubroutineStart,
    SubroutineReturn,
    StepDefine,
};

// A contact: opens a block (LD) or extends the open one (AND, OR).
constexpr bool isContact(Op op) {
    return op == Op::Load || op == Op::And || op == Op::Or;
}

// Works on the power flow between the rail and the outputs: contacts, INV / NOT (and PL110's
// P / N), the block joins ANB / ORB and the branch stack MPS / MRD / MPP. Everything else is
// an output: it takes the accumulator (or stands alone) and ends what the rung has so far.
constexpr bool isLogic(Op op) {
    switch (op) {
    case Op::Load:
    case Op::And:
    case Op::Or:
    case Op::AndBlock:
    case Op::OrBlock:
    case Op::Push:
    case Op::ReadStack:
    case Op::Pop:
    case Op::Invert:
        return true;
    default:
        return false;
    }
}

constexpr bool isOutput(Op op) {
    return !isLogic(op);
}

// Takes no condition: stands alone in its rung, drawn with no contacts from the left rail
// (END, ILC, JPE / JME, RET, STL, NOP; CPM1 SBN(92), RET(93), STEP(08)).
constexpr bool isUnconditional(Op op) {
    switch (op) {
    case Op::End:
    case Op::InterlockClear:
    case Op::JumpEnd:
    case Op::Return:
    case Op::StepLadder:
    case Op::Nop:
    case Op::SubroutineStart:
    case Op::SubroutineReturn:
    case Op::StepDefine:
        return true;
    default:
        return false;
    }
}

// Joins the last two open blocks (ANB / ORB, AND LD / OR LD).
constexpr bool joinsBlocks(Op op) {
    return op == Op::AndBlock || op == Op::OrBlock;
}

// The branch stack: MPS / MRD / MPP.
constexpr bool isStackOp(Op op) {
    return op == Op::Push || op == Op::ReadStack || op == Op::Pop;
}

// Drives the bit of its first operand from the rung's condition, so driving it twice is a
// duplicate coil (DC001): OUT, KEEP, PLS / PLF, a timer or a counter. SET / RST and moves may
// be written many times.
constexpr bool drivesCoil(Op op) {
    switch (op) {
    case Op::Out:
    case Op::Keep:
    case Op::PulseRise:
    case Op::PulseFall:
    case Op::Timer:
    case Op::Counter:
    case Op::UpDownCounter:
        return true;
    default:
        return false;
    }
}

} // namespace rung::model
