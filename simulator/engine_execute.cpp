#include "engine.h"
#include "engine_arith.h"
#include "engine_timers.h"

#include "model/image/bcd.h"
#include "model/listing/structure.h"
#include "model/target/address.h"
#include "model/target/word_text.h"
#include "simulator/tr.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstring>

// The interpreter of the compiled program: one pass over the flat step array per scan. It
// lives apart from the engine's control and access so the hot loop reads as one piece.

namespace rung::simulator {

namespace {

// The compiler holds a program to these (model/listing/structure.h).
static_assert(Engine::kBlockStack == model::kMaxOpenBlocks);
static_assert(Engine::kPushStack == model::kMaxStackDepthOfAnyTarget);

// A rising (or falling) edge of `now` against the value the slot kept from the last scan.
inline bool edge(std::uint8_t &prev, bool now, bool falling) {
    const bool v = falling ? (prev && !now) : (now && !prev);
    prev = now;
    return v;
}

// BCD digits -> number; -1 when a nibble is above 9 (or the value is negative).
std::int32_t fromBcd(std::int32_t raw) {
    return static_cast<std::int32_t>(model::fromBcd(raw).value_or(-1));
}

} // namespace

std::int32_t Engine::readBcdSet(const Step &s, std::size_t step) {
    const std::int32_t raw =
        s.x.index >= 0 ? m_words[static_cast<std::size_t>(s.x.index)] : s.x.constant;
    const std::int32_t decoded = fromBcd(raw);
    if (decoded < 0) {
        setFlag(m_program->flags.error, true); // W353 TIM / CNT: "ER: SV is not in BCD"
        runtimeError(step,
                     EngineTr::tr("set value %1 is not a BCD number; the instruction is "
                                  "skipped")
                         .arg(QString::number(static_cast<std::uint32_t>(raw) & 0xFFFFu, 16)));
        return -1;
    }
    // The set value in use, as the PLC holds it: BCD digits on the CPM1 (W353: timer and
    // counter SVs and PVs are BCD), so the watch list shows the word a Host Link read gives.
    if (s.y.index >= 0)
        m_words[static_cast<std::size_t>(s.y.index)] = wrapToWidth(raw, 16);
    return std::max<std::int32_t>(0, decoded);
}

// Word logic and the BCD conversions act on the word's bits, so they read it unsigned at the
// destination's width (a CPM1 channel 9999h is held as a negative 16-bit number).
void Engine::wordLogic(const Step &s, std::size_t step) {
    const std::uint32_t mask = s.width >= 32 ? 0xFFFFFFFFu : 0xFFFFu;
    auto read = [&](const WordOperand &o) {
        return static_cast<std::uint32_t>(o.index >= 0 ? m_words[static_cast<std::size_t>(o.index)]
                                                       : o.constant) &
               mask;
    };
    const std::uint32_t a = read(s.x);
    std::int64_t r = 0;
    switch (static_cast<WordOp>(s.op)) {
    case WordOp::And:
        r = a & read(s.y);
        break;
    case WordOp::Or:
        r = a | read(s.y);
        break;
    case WordOp::Xor:
        r = a ^ read(s.y);
        break;
    case WordOp::Not:
        r = ~a & mask;
        break;
    case WordOp::ToBcd: {
        // The value is the signed number the word holds; BCD has 4 digits a 16-bit word.
        const std::int64_t v =
            s.x.index >= 0 ? m_words[static_cast<std::size_t>(s.x.index)] : s.x.constant;
        const std::int64_t max = s.width >= 32 ? 99999999 : 9999;
        if (v < 0 || v > max) {
            setFlag(m_program->flags.error, true); // W353 BCD(24): "ER: S is greater than 270F"
            // In the family's own words: a CPM1 user reads the word as #9999, not -26215.
            const model::Target &t = layout().target();
            runtimeError(
                step, EngineTr::tr("%1 does not fit in BCD (0..%2); the destination is "
                                   "unchanged")
                          .arg(s.width >= 32 ? QString::number(v) : model::formatWord(t, v),
                               s.width >= 32 ? QString::number(max) : model::formatWord(t, max)));
            return;
        }
        r = toBcd(v);
        break;
    }
    case WordOp::FromBcd: {
        const std::int32_t v = fromBcd(static_cast<std::int32_t>(a & 0x7FFFFFFFu));
        if (v < 0 || (a & 0x80000000u)) {
            setFlag(m_program->flags.error, true); // W353 BIN(23): "ER: S is not BCD"
            runtimeError(step,
                         EngineTr::tr("%1 is not a BCD number; the destination is unchanged")
                             .arg(model::formatConstant(
                                 layout().target(), model::Constant{static_cast<qint64>(a),
                                                                    model::Constant::Style::Hex})));
            return;
        }
        r = v;
        break;
    }
    }
    storeWord(static_cast<std::size_t>(s.dest), r, s.width);
    if (m_program->flags.any())
        resultFlags(r); // W353: "EQ: ON when the result is 0"
}

// Kept out of the scan loop: the message's temporaries would otherwise weigh on it.
std::int64_t Engine::outOfDecimalRange(std::size_t step, std::int64_t value) {
    const std::int64_t wrapped = ((value % 10000) + 10000) % 10000;
    runtimeError(
        step, EngineTr::tr("result %1 is outside 0..9999; %2 is written").arg(value).arg(wrapped));
    return wrapped;
}

// STEP(08) B: 254.07 is ON in the cycle a step starts (W353).
[[gnu::always_inline]] inline void Engine::markStepStart(const Step &s, bool active,
                                                         std::int32_t *R) {
    const BitRef &stepStart = m_program->flags.stepStart;
    const bool started =
        edge(m_edges[static_cast<std::size_t>(s.slot)], s.bit.valid() && active, false);
    if (s.bit.valid() && stepStart.valid())
        put(R, stepStart, started);
}

// Kept out of the scan loop, as outOfDecimalRange.
void Engine::subroutinesTooDeep(std::size_t step) {
    runtimeError(step, EngineTr::tr("subroutines nest deeper than %1 levels; the call "
                                    "is skipped")
                           .arg(kSubroutineDepth));
}

template <bool Record, bool Resumable, bool Special>
std::size_t Engine::execute(std::size_t from, std::size_t to) {
    const Program &p = *m_program;
    const Step *steps = p.steps.data();
    const std::size_t n = p.steps.size();
    std::int32_t *R = m_words.data();
    std::int32_t *W = p.deferredBitWrites ? m_write.data() : R;
    const Pass pass{p, R, W, m_stats.periodMs};
    auto rd = [R](const BitRef &b) { return readBit(R, b); };
    auto rdw = [R](const WordOperand &o) { return readWord(R, o); };

    bool blocks[kBlockStack];
    bool pushed[kPushStack];
    int bsp = 0;
    int psp = 0;
    bool acc = false;
    bool interlock = true;
    bool stepActive = true;
    bool gate = true;
    const bool flags = p.flags.any(); // the W353 flags: MOV(21) sets EQ
    int depth = 0;                    // SBS(91) nesting
    // Written before read (entries below depth only): no clearing at every scan, which
    // cost a loop of its own.
    std::size_t returns[kSubroutineDepth];
    bool held[kSubroutineDepth];
    // A stopped scan's registers come in and go back; the whole scan keeps them local, so
    // the plain scan's loop is the one it always was.
    if constexpr (Resumable) {
        const Registers &r = m_regs;
        depth = r.depth;
        std::copy_n(r.returns, depth, returns);
        std::copy_n(r.held, depth, held);
        bsp = r.bsp;
        psp = r.psp;
        acc = r.acc;
        interlock = r.interlock;
        stepActive = r.stepActive;
        gate = r.gate;
        std::copy_n(r.blocks, bsp, blocks);
        std::copy_n(r.pushed, psp, pushed);
    }
    auto leave = [&](std::size_t next) {
        if constexpr (Resumable) {
            Registers &r = m_regs;
            r.next = next;
            r.bsp = bsp;
            r.psp = psp;
            r.acc = acc;
            r.interlock = interlock;
            r.stepActive = stepActive;
            r.gate = gate;
            std::copy_n(blocks, bsp, r.blocks);
            std::copy_n(pushed, psp, r.pushed);
            r.depth = depth;
            std::copy_n(returns, depth, r.returns);
            std::copy_n(held, depth, r.held);
        }
        return next;
    };
    // A box's inputs before its last one wait on the block stack (the last is acc): they come
    // off in reverse order.
    auto pop = [&] { return bsp > 0 ? blocks[--bsp] : false; };
    // A contact's value: the bit (NOT: inverted), its edge, a comparison.
    auto contact = [&](const Step &s) { return rd(s.bit) != ((s.flags & kNegated) != 0); };
    auto contactEdge = [&](const Step &s) {
        return edge(m_edges[static_cast<std::size_t>(s.slot)], rd(s.bit),
                    (s.flags & kFalling) != 0);
    };
    auto holds = [&](const Step &s) {
        return model::compareHolds(model::CompareOp(s.op), rdw(s.x), rdw(s.y)) !=
               ((s.flags & kNegated) != 0);
    };
    // LD, LDP / LDF, LD= ...: a new block starts from v.
    auto load = [&](const Step &s, bool v) {
        if (s.flags & kRungStart) {
            bsp = 0;
            psp = 0;
        } else if (bsp < kBlockStack) {
            blocks[bsp++] = acc;
        }
        // Bitwise, not &&/||: a contact's value follows the inputs, so a branch on it
        // is mispredicted about half the time (that cost the scan 1.4x, issue 10).
        acc = v & gate;
    };

    Step resolved;
    std::size_t i = from;
    for (; i < to; ++i) {
        const Step *step = &steps[i];
        // One test per step for the rare ones, so that the plain scan pays little for them:
        // an operand resolved at run time, or "@MOV(21)", which runs on the rising edge of
        // its condition while the rung's condition goes on to the instructions after it.
        const bool special = Special && (step->flags & (kResolve | kDifferentiated)) != 0;
        bool level = false;
        if (special) [[unlikely]] {
            if (step->flags & kResolve) {
                if (!resolveStep(*step, i, resolved)) {
                    if constexpr (Record)
                        m_flow[i] = acc;
                    continue;
                }
                step = &resolved;
            }
            level = acc;
            if (step->flags & kDifferentiated)
                acc = edge(m_edges[static_cast<std::size_t>(step->slot)], acc, false);
        }
        const Step &s = *step;
        switch (s.code) {
        case Code::Load:
            load(s, contact(s));
            break;
        case Code::LoadEdge:
            load(s, contactEdge(s));
            break;
        case Code::LoadCompare:
            load(s, holds(s));
            break;
        case Code::And:
            acc = acc & contact(s);
            break;
        case Code::Or:
            acc = acc | (contact(s) & gate);
            break;
        case Code::AndEdge:
            acc = acc & contactEdge(s);
            break;
        case Code::OrEdge:
            acc = acc | (contactEdge(s) & gate);
            break;
        case Code::AndCompare:
            acc = acc & holds(s);
            break;
        case Code::OrCompare:
            acc = acc | (holds(s) & gate);
            break;
        case Code::AndBlock:
            if (bsp > 0)
                acc = blocks[--bsp] & acc;
            break;
        case Code::OrBlock:
            if (bsp > 0)
                acc = blocks[--bsp] | acc;
            break;
        case Code::Push:
            if (psp < kPushStack)
                pushed[psp++] = acc;
            break;
        case Code::ReadStack:
            if (psp > 0)
                acc = pushed[psp - 1];
            break;
        case Code::Pop:
            if (psp > 0)
                acc = pushed[--psp];
            break;
        case Code::Invert:
            acc = !acc;
            break;
        case Code::EdgeFlow:
            acc = edge(m_edges[static_cast<std::size_t>(s.slot)], acc, (s.flags & kFalling) != 0);
            break;
        case Code::Out:
            put(W, s.bit, acc != ((s.flags & kNegated) != 0));
            break;
        case Code::Set:
            if (acc)
                put(W, s.bit, true);
            break;
        case Code::SetStep:
            if (acc) {
                put(W, s.bit, true);
                put(W, p.bitLists[static_cast<std::size_t>(s.slot)], false);
            }
            break;
        case Code::Reset:
            if (acc)
                resetTargets(s, W);
            break;
        case Code::Pulse:
            put(W, s.bit,
                edge(m_edges[static_cast<std::size_t>(s.slot)], acc, (s.flags & kFalling) != 0));
            break;
        case Code::Toggle:
            if (edge(m_edges[static_cast<std::size_t>(s.slot)], acc, false))
                put(W, s.bit, !rd(s.bit));
            break;
        case Code::Keep: {
            const bool set = pop();
            if (acc)
                put(W, s.bit, false);
            else if (set)
                put(W, s.bit, true);
            break;
        }
        case Code::Timer:
            timer(s, i, acc, pass); // engine_timers.h, as the other boxes
            break;
        case Code::Counter: {
            // Vigor (kOneInput): one input, cleared by RST alone; else the count input waits on
            // the block stack and the condition resets.
            const bool oneInput = (s.flags & kOneInput) != 0;
            counter(s, i, oneInput ? acc : pop(), !oneInput && acc, pass);
            break;
        }
        case Code::UpDownCounter: {
            const bool down = pop();
            const bool up = pop();
            upDownCounter(s, i, up, down, acc, pass);
            break;
        }
        case Code::PlTimer:
            plTimer(s, i, acc, pass);
            break;
        case Code::PlCounter: {
            const bool down = pop();
            const bool up = pop();
            plCounter(s, i, up, down, acc, pass);
            break;
        }
        case Code::Transfer:
            if (acc != ((s.flags & kNegated) != 0))
                transfer(s, i, pass); // engine_arith.h, as the other word instructions
            break;
        case Code::Move:
            if (acc) {
                store(s.dest, rdw(s.x), s.width);
                if (flags) [[unlikely]]
                    resultFlags(rdw(s.x));
            }
            break;
        case Code::Arithmetic:
            if (acc)
                arithmetic(s, i); // engine_cpm1.cpp
            break;
        case Code::ShiftRegister: {
            const bool pulse = pop();
            const bool data = pop();
            shiftRegister(s, data, pulse, acc);
            break;
        }
        // SBS, RET and SBN move the loop's index and the return stack: written here, as JMP
        // and END below.
        case Code::SubroutineCall:
            // SBS(91): run the subroutine from its SBN(92), come back after the SBS.
            if (acc && s.count >= 0) {
                if (depth == kSubroutineDepth) {
                    subroutinesTooDeep(i);
                    break;
                }
                returns[depth] = i;
                held[depth++] = level;
                if constexpr (Record)
                    m_flow[i] = acc;
                i = static_cast<std::size_t>(s.count);
                acc = true;
                continue;
            }
            break;
        case Code::SubroutineReturn:
            if constexpr (Record)
                m_flow[i] = acc;
            if (depth == 0) { // reached without a call: the main program is over
                i = n;
                continue;
            }
            i = returns[--depth];
            acc = held[depth];
            continue;
        case Code::SubroutineStart:
            // The first SBN(92) ends the main program: on to END.
            if constexpr (Record)
                m_flow[i] = acc;
            i = static_cast<std::size_t>(s.slot) - 1;
            continue;
        case Code::StepDefine:
            // STEP(08) B: what follows runs as in an interlock whose condition is B, up to the
            // next STEP(08); STEP(08) alone ends the steps.
            stepActive = !s.bit.valid() || rd(s.bit);
            gate = interlock && stepActive;
            acc = gate;
            markStepStart(s, stepActive, R);
            break;
        case Code::StepNext:
            // SNXT(09) B: the step it stands in ends (its bit OFF, so from the next cycle on
            // its outputs are OFF and its timers reset) and the step of B starts.
            if (acc) {
                if (s.slot >= 0)
                    put(W, p.bitLists[static_cast<std::size_t>(s.slot)], false);
                put(W, s.bit, true);
            }
            break;
        case Code::Compare:
            if (acc)
                compare(s, pass);
            break;
        case Code::Add:
            if (acc)
                store(s.dest, std::int64_t{rdw(s.x)} + rdw(s.y), s.width);
            break;
        case Code::Sub:
            if (acc)
                store(s.dest, std::int64_t{rdw(s.x)} - rdw(s.y), s.width);
            break;
        case Code::Mul:
            if (acc)
                multiply(s, pass);
            break;
        case Code::Div:
            if (acc)
                divide(s, i, pass);
            break;
        case Code::Inc:
        case Code::Dec:
            if (acc)
                store(s.dest, std::int64_t{R[s.dest]} + (s.code == Code::Inc ? 1 : -1), s.width);
            break;
        case Code::WordLogic:
            if (acc)
                wordLogic(s, i);
            break;
        case Code::Math:
            if (acc)
                math(s, i, pass);
            break;
        case Code::BlockMove:
            if (acc)
                blockMove(s, pass);
            break;
        case Code::DoubleMove:
            if (acc)
                doubleMove(s, pass);
            break;
        case Code::CheckCode:
            if (acc)
                checkCode(s, i); // engine_words.cpp
            break;
        case Code::Swap:
            if (acc)
                swapBytes(s); // engine_text.cpp
            break;
        case Code::ToAscii:
            if (acc)
                toAscii(s, i);
            break;
        case Code::FromAscii:
            if (acc)
                fromAscii(s, i);
            break;
        case Code::ShiftDigits:
            if (acc)
                shiftDigits(s, i);
            break;
        case Code::DoubleDivide:
            if (acc)
                doubleDivide(s, i);
            break;
        case Code::Communicate:
            communicate(s, i, acc); // engine_comm.cpp: every scan, ON or OFF
            break;
        case Code::MoveConstants:
            if (acc)
                for (int k = 0; k < s.count; ++k)
                    store(s.dest + k, p.constants[static_cast<std::size_t>(s.slot + k)], s.width);
            break;
        case Code::IndirectMove:
            if (acc)
                indirectMove(s, i, pass);
            break;
        case Code::Interlock:
            interlock = acc;
            gate = interlock && stepActive;
            break;
        case Code::InterlockClear:
            interlock = true;
            gate = stepActive;
            break;
        case Code::Jump:
            if (!acc && s.slot > static_cast<int>(i))
                i = static_cast<std::size_t>(s.slot); // the JPE/JME itself does nothing
            break;
        case Code::JumpEnd:
        case Code::Nop:
            break;
        case Code::StepLadder:
            stepActive = rd(s.bit);
            gate = interlock && stepActive;
            acc = gate;
            break;
        case Code::Return:
            stepActive = true;
            gate = interlock;
            acc = gate;
            break;
        case Code::End:
            if constexpr (Record)
                m_flow[i] = acc;
            return leave(n);
        }
        if (special) [[unlikely]] {
            if (step == &resolved)
                writeBack(steps[i], resolved, W);
            if (s.flags & kDifferentiated)
                acc = level;
        }
        if constexpr (Record)
            m_flow[i] = acc;
    }
    return leave(i);
}

template std::size_t Engine::execute<false, false>(std::size_t, std::size_t);
template std::size_t Engine::execute<true, false>(std::size_t, std::size_t);
template std::size_t Engine::execute<false, false, false>(std::size_t, std::size_t);
template std::size_t Engine::execute<true, false, false>(std::size_t, std::size_t);
template std::size_t Engine::execute<false, true>(std::size_t, std::size_t);
template std::size_t Engine::execute<true, true>(std::size_t, std::size_t);

} // namespace rung::simulator
