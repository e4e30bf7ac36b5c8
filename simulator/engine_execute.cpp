#include "engine.h"

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

template <bool Record, bool Resumable, bool Special>
std::size_t Engine::execute(std::size_t from, std::size_t to) {
    const Program &p = *m_program;
    const Step *steps = p.steps.data();
    const std::size_t n = p.steps.size();
    std::int32_t *R = m_words.data();
    std::int32_t *W = p.deferredBitWrites ? m_write.data() : R;
    const std::int64_t period = m_stats.periodMs;
    const std::int64_t timerMax = p.timerMax; // Limits::timerMax
    auto rd = [R](const BitRef &b) {
        return (static_cast<std::uint32_t>(R[b.word]) & b.mask) != 0;
    };
    auto rdw = [R](const WordOperand &o) { return o.index >= 0 ? R[o.index] : o.constant; };
    auto gateOpen = [&](std::int32_t slot) {
        if (p.gates.empty() || slot < 0)
            return true;
        const ElementGate &g = p.gates[static_cast<std::size_t>(slot)];
        return !g.bit.valid() || rd(g.bit) == g.whenOn;
    };
    auto wrw = [&](std::int32_t index, std::int64_t v, int width) {
        storeWord(static_cast<std::size_t>(index), v, width);
    };

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
        case Code::LoadEdge:
        case Code::LoadCompare: {
            bool v;
            if (s.code == Code::Load) {
                v = rd(s.bit) != ((s.flags & kNegated) != 0);
            } else if (s.code == Code::LoadEdge) {
                v = edge(m_edges[static_cast<std::size_t>(s.slot)], rd(s.bit),
                         (s.flags & kFalling) != 0);
            } else {
                v = model::compareHolds(model::CompareOp(s.op), rdw(s.x), rdw(s.y)) !=
                    ((s.flags & kNegated) != 0);
            }
            if (s.flags & kRungStart) {
                bsp = 0;
                psp = 0;
            } else if (bsp < kBlockStack) {
                blocks[bsp++] = acc;
            }
            // Bitwise, not &&/||: a contact's value follows the inputs, so a branch on it
            // is mispredicted about half the time (that cost the scan 1.4x, issue 10).
            acc = v & gate;
            break;
        }
        case Code::And:
            acc = acc & (rd(s.bit) != ((s.flags & kNegated) != 0));
            break;
        case Code::Or:
            acc = acc | ((rd(s.bit) != ((s.flags & kNegated) != 0)) & gate);
            break;
        case Code::AndEdge:
        case Code::OrEdge: {
            const bool v = edge(m_edges[static_cast<std::size_t>(s.slot)], rd(s.bit),
                                (s.flags & kFalling) != 0);
            acc = s.code == Code::AndEdge ? acc & v : acc | (v & gate);
            break;
        }
        case Code::AndCompare:
        case Code::OrCompare: {
            const bool v = model::compareHolds(model::CompareOp(s.op), rdw(s.x), rdw(s.y)) !=
                           ((s.flags & kNegated) != 0);
            acc = s.code == Code::AndCompare ? acc & v : acc | (v & gate);
            break;
        }
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
            if (acc) {
                for (int k = 0; k < s.count; ++k) {
                    const ResetTarget &t = p.resets[static_cast<std::size_t>(s.slot + k)];
                    if (t.bit.valid())
                        put(W, t.bit, false);
                    if (t.word >= 0)
                        wrw(t.word, 0, 32);
                    if (t.state >= 0) { // the input edge memory stays: no count on release
                        ElementState &st = m_states[static_cast<std::size_t>(t.state)];
                        st.accumulated = 0;
                        st.running = 0;
                    }
                }
            }
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
            const bool set = bsp > 0 ? blocks[--bsp] : false;
            if (acc)
                put(W, s.bit, false);
            else if (set)
                put(W, s.bit, true);
            break;
        }
        case Code::Timer: {
            ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
            if (!gateOpen(s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
                break;
            const std::int32_t set = readSet(s, i);
            if (set < 0)
                break;
            std::int64_t units = 0;
            const bool keeps = s.op == kTimerAccumulates; // only RST clears it
            if (!acc) {
                if (!keeps)
                    st.accumulated = 0;
                st.running = 0;
            } else {
                if (st.running)
                    st.accumulated = std::min<std::int64_t>(st.accumulated + period,
                                                            std::int64_t{set} * s.count);
                st.running = 1;
            }
            if (acc || keeps)
                units = st.accumulated / s.count;
            put(W, s.bit, (acc || keeps) && units >= set);
            const std::int64_t present =
                (s.flags & kDown) ? set - units : std::min<std::int64_t>(units, timerMax);
            // CPM1 (W353): the present value is BCD too: CMP(20) TIM 000 #0100 compares
            // digits, and a Host Link RC reads the same word.
            R[s.dest] = (s.flags & kBcd) ? wrapToWidth(toBcd(present), 16)
                                         : static_cast<std::int32_t>(present);
            break;
        }
        case Code::Counter: {
            ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
            bool input = acc;
            bool reset = false;
            if (!(s.flags & kOneInput)) {
                input = bsp > 0 ? blocks[--bsp] : false;
                reset = acc;
            }
            if (!gateOpen(s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
                break;
            const std::int32_t set = readSet(s, i);
            if (set < 0)
                break;
            if (reset) {
                st.accumulated = 0;
            } else if (input && !st.previous && st.accumulated < set) {
                ++st.accumulated;
            }
            st.previous = input;
            put(W, s.bit, !reset && st.accumulated >= set);
            const std::int64_t present = (s.flags & kDown) ? set - st.accumulated : st.accumulated;
            R[s.dest] = wrapToWidth((s.flags & kBcd) ? toBcd(present) : present, s.width);
            break;
        }
        case Code::UpDownCounter: {
            ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
            const bool reset = acc;
            const bool down = bsp > 0 ? blocks[--bsp] : false;
            const bool up = bsp > 0 ? blocks[--bsp] : false;
            if (!gateOpen(s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
                break;
            const std::int32_t set = readSet(s, i);
            if (set < 0)
                break;
            const bool upEdge = up && !(st.previous & 1);
            const bool downEdge = down && !(st.previous & 2);
            st.previous = static_cast<std::uint8_t>((up ? 1 : 0) | (down ? 2 : 0));
            if (reset) {
                st.accumulated = 0;
                st.running = 0; // completion flag
            } else if ((upEdge || downEdge) && !(up && down)) {
                // Omron CPM1 guide: the value does not change while both inputs are at 1
                if (upEdge) {
                    st.running = st.accumulated >= set;
                    st.accumulated = st.running ? 0 : st.accumulated + 1;
                } else {
                    st.running = st.accumulated <= 0;
                    st.accumulated = st.running ? set : st.accumulated - 1;
                }
            }
            put(W, s.bit, st.running != 0);
            R[s.dest] = (s.flags & kBcd) ? wrapToWidth(toBcd(st.accumulated), 16)
                                         : static_cast<std::int32_t>(st.accumulated);
            break;
        }
        case Code::PlTimer: {
            // PL110 (PL110 manual 4.2.4): the current value counts time-base units in the T word
            // and saturates at Limits::timerMax; st.accumulated holds the ms not yet a whole unit.
            ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
            if (!gateOpen(s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
                break;
            const std::int32_t set = readSet(s, i);
            if (set < 0)
                break;
            std::int32_t &current = R[s.dest];
            auto advance = [&] {
                st.accumulated += period;
                const std::int64_t units = std::int64_t{current} + st.accumulated / s.count;
                st.accumulated %= s.count;
                current = static_cast<std::int32_t>(std::min(units, timerMax));
            };
            bool out = false;
            switch (static_cast<PlTimerMode>(s.op)) {
            case PlTimerMode::OnDelay:
                if (acc) {
                    if (st.running)
                        advance();
                } else {
                    current = 0;
                    st.accumulated = 0;
                }
                st.running = acc;
                out = acc && current >= set;
                break;
            case PlTimerMode::Accumulating:
                // Every scan that saw the coil ON was ON until this one (4.2.4: "accumulare
                // il tempo per piu periodi di attivazione"): a one-scan pulse adds a period,
                // a coil on SM0.4 half the elapsed time. Held ON, it counts as TON does.
                if (st.running)
                    advance();
                st.running = acc;
                out = current >= set;
                break;
            case PlTimerMode::OffDelay:
                // running: 0 idle, 1 input ON, 2 timing after an ON -> OFF transition
                if (acc) {
                    current = 0;
                    st.accumulated = 0;
                    st.running = 1;
                } else if (st.running == 1) {
                    st.running = 2;
                } else if (st.running == 2) {
                    advance();
                    if (current >= set) {
                        current = std::min(current, set);
                        st.running = 0;
                    }
                }
                out = st.running != 0;
                break;
            }
            put(W, s.bit, out);
            break;
        }
        case Code::PlCounter: {
            // PL110 MUP / MDOWN (PL110 manual 4.2.5): counts rising edges of UP and DOWN in the
            // C word, which saturates at Limits::counterMin..counterMax (-32768..32767; MDOWN
            // stops at 0); RESET clears MUP
            // and loads PV into MDOWN. MUP is ON at >= PV, MDOWN at 0.
            ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
            const bool reset = acc;
            const bool down = bsp > 0 ? blocks[--bsp] : false;
            const bool up = bsp > 0 ? blocks[--bsp] : false;
            if (!gateOpen(s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
                break;
            const std::int32_t set = readSet(s, i);
            if (set < 0)
                break;
            const bool upEdge = up && !(st.previous & 1);
            const bool downEdge = down && !(st.previous & 2);
            st.previous = static_cast<std::uint8_t>((up ? 1 : 0) | (down ? 2 : 0));
            std::int32_t &current = R[s.dest];
            const bool countsDown = (s.flags & kDown) != 0;
            if (reset) {
                current = countsDown ? set : 0;
            } else {
                if (upEdge && current < p.counterMax)
                    ++current;
                if (downEdge && current > (countsDown ? std::max(0, p.counterMin) : p.counterMin))
                    --current;
            }
            // The count bit is compared at the end of the cycle (4.2.5), by endScan.
            st.previous = static_cast<std::uint8_t>(st.previous | (reset ? 4 : 0));
            break;
        }
        case Code::Transfer:
            if (acc != ((s.flags & kNegated) != 0)) {
                const std::int64_t v = rdw(s.x);
                const std::int64_t d = R[s.dest];
                const auto kind = static_cast<TransferKind>(s.op);
                std::int64_t r = kind == TransferKind::Assign ? v
                                 : kind == TransferKind::Add  ? d + v
                                                              : d - v;
                if ((s.flags & kDecimal4) && (r < 0 || r > 9999)) [[unlikely]]
                    r = outOfDecimalRange(i, r);
                wrw(s.dest, r, s.width);
            }
            break;
        case Code::Move:
            if (acc) {
                wrw(s.dest, rdw(s.x), s.width);
                if (flags) [[unlikely]]
                    resultFlags(rdw(s.x));
            }
            break;
        case Code::Arithmetic:
            if (acc)
                arithmetic(s, i); // engine_cpm1.cpp
            break;
        case Code::ShiftRegister: {
            const bool pulse = bsp > 0 ? blocks[--bsp] : false;
            const bool data = bsp > 0 ? blocks[--bsp] : false;
            shiftRegister(s, data, pulse, acc);
            break;
        }
        case Code::SubroutineCall:
            // SBS(91): run the subroutine from its SBN(92), come back after the SBS.
            if (acc && s.count >= 0) {
                if (depth == kSubroutineDepth) {
                    runtimeError(i, EngineTr::tr("subroutines nest deeper than %1 levels; the call "
                                                 "is skipped")
                                        .arg(kSubroutineDepth));
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
        case Code::StepDefine: {
            // STEP(08) B: what follows runs as in an interlock whose condition is B, up to the
            // next STEP(08); STEP(08) alone ends the steps. 254.07 is ON in the cycle a step
            // starts (W353).
            stepActive = !s.bit.valid() || rd(s.bit);
            gate = interlock && stepActive;
            acc = gate;
            const bool started =
                edge(m_edges[static_cast<std::size_t>(s.slot)], s.bit.valid() && stepActive, false);
            if (s.bit.valid() && p.flags.stepStart.valid())
                put(R, p.flags.stepStart, started);
            break;
        }
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
            if (acc) {
                const std::int32_t a = rdw(s.x);
                const std::int32_t b = rdw(s.y);
                const BitRef *bits = &p.bitLists[static_cast<std::size_t>(s.slot)];
                put(W, bits[0], a > b);
                put(W, bits[1], a == b);
                put(W, bits[2], a < b);
            }
            break;
        case Code::Add:
            if (acc)
                wrw(s.dest, std::int64_t{rdw(s.x)} + rdw(s.y), s.width);
            break;
        case Code::Sub:
            if (acc)
                wrw(s.dest, std::int64_t{rdw(s.x)} - rdw(s.y), s.width);
            break;
        case Code::Mul:
            if (acc) {
                const std::int64_t product = std::int64_t{rdw(s.x)} * rdw(s.y);
                if (s.slot >= 0 && s.width < 32) {
                    wrw(s.dest, product & 0xFFFF, 16);
                    wrw(s.slot, product >> 16, 16);
                } else {
                    wrw(s.dest, product, 32);
                    if (s.slot >= 0)
                        wrw(s.slot, product >> 32, 32);
                }
            }
            break;
        case Code::Div:
            if (acc) {
                const std::int64_t a = rdw(s.x);
                const std::int64_t b = rdw(s.y);
                if (b == 0) {
                    runtimeError(i, EngineTr::tr("division by zero; the destination is unchanged"));
                    break;
                }
                wrw(s.dest, a / b, s.width);
                if (s.slot >= 0)
                    wrw(s.slot, a % b, s.width);
            }
            break;
        case Code::Inc:
        case Code::Dec:
            if (acc)
                wrw(s.dest, std::int64_t{R[s.dest]} + (s.code == Code::Inc ? 1 : -1), s.width);
            break;
        case Code::WordLogic:
            if (acc)
                wordLogic(s, i);
            break;
        case Code::Math:
            if (acc) {
                const std::int64_t a = rdw(s.x);
                const std::int64_t b = rdw(s.y);
                std::int64_t r = 0;
                switch (static_cast<MathOp>(s.op)) {
                case MathOp::Add:
                    r = a + b;
                    break;
                case MathOp::Sub:
                    r = a - b;
                    break;
                case MathOp::Mul:
                    r = a * b;
                    break;
                case MathOp::Div:
                    r = b == 0 ? 0 : a / b;
                    break;
                case MathOp::Or:
                    r = a | b;
                    break;
                case MathOp::And:
                    r = a & b;
                    break;
                case MathOp::Xor:
                    r = a ^ b;
                    break;
                case MathOp::Shl:
                    r = b < 0 || b > 31
                            ? 0
                            : static_cast<std::int64_t>(static_cast<std::uint64_t>(a) << b);
                    break;
                case MathOp::Shr:
                    r = b < 0 || b > 31
                            ? 0
                            : static_cast<std::int64_t>(static_cast<std::uint32_t>(a) >> b);
                    break;
                }
                if (static_cast<MathOp>(s.op) == MathOp::Div && b == 0)
                    runtimeError(i, EngineTr::tr("division by zero; the destination is unchanged"));
                else
                    wrw(s.dest, r, s.width);
            }
            break;
        case Code::BlockMove:
            if (acc) {
                // memmove order: an overlapping block copies as if through a buffer
                if (s.x.index >= 0 && s.x.index < s.dest) {
                    for (int k = s.count - 1; k >= 0; --k)
                        wrw(s.dest + k, R[s.x.index + k], s.width);
                } else {
                    for (int k = 0; k < s.count; ++k)
                        wrw(s.dest + k, s.x.index >= 0 ? R[s.x.index + k] : s.x.constant, s.width);
                }
            }
            break;
        case Code::DoubleMove:
            if (acc) {
                // FX order: the low word first (DMOV H00310035 D4: D4 = 0035h, D5 = 0031h).
                const std::int32_t v = s.y.index >= 0
                                           ? static_cast<std::int32_t>(
                                                 (static_cast<std::uint32_t>(R[s.y.index]) << 16) |
                                                 (static_cast<std::uint32_t>(rdw(s.x)) & 0xFFFFu))
                                           : rdw(s.x);
                if (s.slot >= 0) {
                    wrw(s.dest, v, 16);
                    wrw(s.slot, v >> 16, 16);
                } else {
                    wrw(s.dest, v, s.width);
                }
            }
            break;
        case Code::CheckCode:
            if (acc)
                checkCode(s, i); // engine_words.cpp
            break;
        case Code::IndirectMove:
            if (acc) {
                const std::int32_t index = rdw(s.y);
                if (index < 0 || index >= s.count) {
                    runtimeError(
                        i, EngineTr::tr("MOVIND index %1 is outside 0..%2; nothing is written")
                               .arg(index)
                               .arg(s.count - 1));
                    break;
                }
                wrw(s.dest + index, rdw(s.x), s.width);
            }
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
