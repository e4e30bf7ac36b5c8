#include "program.h"

// The scan loop's form of a program (Program::ops): each step that needs no flag at run time
// becomes a specialised code with its operands in 16 bytes. A step with an operand resolved
// at run time or the differentiated form (kResolve, kDifferentiated) keeps its code: the loop
// runs it from its Step as before.

namespace rung::simulator {

std::vector<Op> lowerSteps(const Program &program) {
    std::vector<Op> ops;
    ops.reserve(program.steps.size());
    for (const Step &s : program.steps) {
        Op o;
        o.code = s.code;
        const bool negated = (s.flags & kNegated) != 0;
        const std::uint16_t rest = s.flags & ~(kNegated | kRungStart);
        auto bit = [&](Code plain, Code inverted) {
            o.code = negated ? inverted : plain;
            o.word = s.bit.word;
            o.mask = s.bit.mask;
        };
        switch (s.code) {
        case Code::Load:
            if (rest == 0 && s.bit.valid()) {
                if (s.flags & kRungStart)
                    bit(Code::LoadStartBit, Code::LoadStartNot);
                else
                    bit(Code::LoadBit, Code::LoadNot);
            }
            break;
        case Code::And:
            if (rest == 0 && !(s.flags & kRungStart) && s.bit.valid())
                bit(Code::AndBit, Code::AndNot);
            break;
        case Code::Or:
            if (rest == 0 && !(s.flags & kRungStart) && s.bit.valid())
                bit(Code::OrBit, Code::OrNot);
            break;
        case Code::Out:
            if (rest == 0 && !(s.flags & kRungStart) && s.bit.valid())
                bit(Code::OutBit, Code::OutNot);
            break;
        case Code::Move:
            // The W353 flags (MOV(21) sets EQ) stay with the Step's form.
            if (s.flags == 0 && !program.flags.any() && s.dest >= 0) {
                o.width = s.width;
                o.dest = s.dest;
                if (s.x.index >= 0) {
                    o.code = Code::MoveWord;
                    o.word = s.x.index;
                } else {
                    o.code = Code::MoveConstant;
                    o.mask = static_cast<std::uint32_t>(s.x.constant);
                }
            }
            break;
        case Code::Timer:
            if (s.flags == 0 && s.op != kTimerAccumulates && program.gates.empty() && s.count > 0)
                o.code = Code::TimerPlain;
            break;
        case Code::Counter:
            if (s.flags == kOneInput && program.gates.empty())
                o.code = Code::CounterPlain;
            break;
        default:
            break;
        }
        ops.push_back(o);
    }
    return ops;
}

std::shared_ptr<const Program> withOps(std::shared_ptr<const Program> program) {
    if (program->ops.size() == program->steps.size())
        return program;
    auto lowered = std::make_shared<Program>(*program);
    lowered->ops = lowerSteps(*lowered);
    return lowered;
}

} // namespace rung::simulator
