#include "engine.h"
#include "engine_arith.h"
#include "engine_timers.h"

// The plain scan's loop (Engine::runFast): the steps a whole scan runs most, over
// Program::fast, with the interpreter's registers in the CPU's. It is small on purpose: the
// full interpreter (engine_execute.cpp) holds every code and its state lived on the stack;
// here a step the loop does not run itself (FastOp::Slow) goes to the full interpreter for
// that one step, with the registers handed over in m_regs, and the loop goes on where it
// left. The results are the full interpreter's, bit for bit (the engine tests run both).

namespace rung::simulator {

namespace {

inline bool edgeOf(std::uint8_t &prev, bool now, bool falling) {
    const bool v = falling ? (prev && !now) : (now && !prev);
    prev = now;
    return v;
}

} // namespace

// Labels as values (GCC and Clang): the threaded dispatch below.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wgnu-label-as-value"
#pragma clang diagnostic ignored "-Wpedantic"
#else
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#endif

template <bool Record, bool Forced, bool Deferred, bool Guarded> std::size_t Engine::runFast() {
    const Program &p = *m_program;
    const FastStep *fast = p.fast.data();
    const Step *steps = p.steps.data();
    const std::size_t n = p.steps.size();
    std::int32_t *R = m_words.data();
    std::int32_t *W = Deferred ? m_write.data() : R;
    const std::uint32_t *forced = m_forceMask.data();
    std::uint8_t *edges = m_edges.data();
    const Pass pass{p, R, W, m_stats.periodMs};
    // A local pointer: m_flow's data read again after every byte stored cost an instruction.
    std::uint8_t *const flow = Record ? m_flow.data() : nullptr;
    const bool flags = p.flags.any();
    // The stacks live where the full interpreter finds them when a step goes to it.
    bool *blocks = m_regs.blocks;
    bool *pushed = m_regs.pushed;
    int bsp = 0;
    int psp = 0;
    bool acc = false;
    bool gate = true;
    // A program without STL, STEP(08), MC / IL: no step ever turns the gate OFF, so the loop
    // made for it (Guarded false) does not read it at every contact.
#define RUNG_GATE (Guarded ? gate : true)
    bool interlock = true;
    bool stepActive = true;
    m_regs.depth = 0;

    auto bitOf = [R](const FastStep &f) {
        return (static_cast<std::uint32_t>(R[f.word]) & f.mask) != 0;
    };
    // A contact's value, negated or not (FastStep::flip).
    auto contact = [R](const FastStep &f) {
        return ((static_cast<std::uint32_t>(R[f.word]) ^ f.flip) & f.mask) != 0;
    };
    auto write = [&](const FastStep &f, bool on) {
        if constexpr (Forced)
            if (forced[f.word] & f.mask)
                return;
        writeBit(W[f.word], f.mask, f.flip, on); // a coil's flip: ~mask
    };
    // put() and storeWord() without the look at the forces when nothing is forced.
    auto putBit = [&](const BitRef &b, bool on) {
        if constexpr (Forced)
            if (forced[b.word] & b.mask)
                return;
        writeBit(W[b.word], b.mask, on);
    };
    // A timer's or counter's done bit (FastElement::bitKeep).
    auto putKept = [&](const FastElement &e, bool on) {
        if constexpr (Forced)
            if (forced[e.bitWord] & e.bitMask)
                return;
        writeBit(W[e.bitWord], e.bitMask, e.bitKeep, on);
    };
    auto storeAt = [&](std::int32_t index, std::int64_t value, int width) {
        if constexpr (Forced)
            storeWord(static_cast<std::size_t>(index), value, width);
        else
            R[index] = wrapToWidth(value, width);
    };
    ElementState *states = m_states.data();
    auto stateOf = [states](const FastElement &e) -> ElementState & {
        return *reinterpret_cast<ElementState *>(reinterpret_cast<char *>(states) + e.state);
    };
    const std::int64_t period = m_stats.periodMs;
    const std::int64_t timerMax = p.timerMax;
    // Timers and counters whose set value is BCD or that an area gates take the full body
    // (FastOp::TimerFull, engine_timers.h); the rest run the lean one below, the same rules.
    auto setOf = [R](const Step &s) {
        const std::int32_t set =
            std::max<std::int32_t>(0, s.x.index >= 0 ? R[s.x.index] : s.x.constant);
        if (s.y.index >= 0)
            R[s.y.index] = set;
        return set;
    };
    // The time base is 1, 10, 100 or 1000 ms in every table: a division by a constant is a
    // multiplication, a division by a variable tens of cycles.
    auto units = [](std::int64_t ms, std::int32_t base) -> std::int64_t {
        switch (base) {
        case 1:
            return ms;
        case 10:
            return ms / 10;
        case 100:
            return ms / 100;
        case 1000:
            return ms / 1000;
        default:
            return ms / base;
        }
    };
    auto load = [&](bool v, bool start) {
        if (start) {
            bsp = 0;
            psp = 0;
        } else if (!Guarded || bsp < kBlockStack) { // Program::guarded: bounded
            blocks[bsp++] = acc;
        }
        acc = v & RUNG_GATE;
    };
    // The Step of an op that reads it (FastStep::word holds its byte offset).
    auto stepOf = [steps](const FastStep &f) -> const Step & {
        return *reinterpret_cast<const Step *>(reinterpret_cast<const char *>(steps) + f.word);
    };
    auto edgeAt = [&](const FastStep &f) {
        const Step &s = stepOf(f);
        return edgeOf(edges[static_cast<std::size_t>(s.slot)], readBit(R, s.bit),
                      (s.flags & kFalling) != 0);
    };

    // Direct-threaded: each op ends by jumping to the next op's code through the table, so
    // the processor predicts each op's successor on its own (a switch at the loop's head cost
    // 12 instructions a step, callgrind). Program::fast ends with a Stop sentinel, so the
    // loop tests no bound. The order is FastOp's.
    static constexpr const void *table[] = {&&opSlow,
                                            &&opLoadStart,
                                            &&opLoadStartNot,
                                            &&opLoad,
                                            &&opLoadNot,
                                            &&opAnd,
                                            &&opAndNot,
                                            &&opOr,
                                            &&opOrNot,
                                            &&opLoadEdge,
                                            &&opAndEdge,
                                            &&opOrEdge,
                                            &&opAndBlock,
                                            &&opOrBlock,
                                            &&opPush,
                                            &&opReadStack,
                                            &&opPop,
                                            &&opInvert,
                                            &&opOut,
                                            &&opOutNot,
                                            &&opSet,
                                            &&opReset,
                                            &&opTimer,
                                            &&opCounter,
                                            &&opMove,
                                            &&opAdd,
                                            &&opSub,
                                            &&opInc,
                                            &&opDec,
                                            &&opNop,
                                            &&opEnd,
                                            &&opSeriesStart2,
                                            &&opSeriesAnd2,
                                            &&opParallelAnd,
                                            &&opSeriesOr,
                                            &&opBranchOut,
                                            &&opBranchOutNot,
                                            &&opTimerFull,
                                            &&opCounterFull,
                                            &&opMoveWord16,
                                            &&opMoveConst16,
                                            &&opAddWordConst16,
                                            &&opAddWordWord16,
                                            &&opSubWordConst16,
                                            &&opSubWordWord16,
                                            &&opStepLadder,
                                            &&opReturn,
                                            &&opInterlock,
                                            &&opInterlockClear,
                                            &&opSetStep,
                                            &&opJump,
                                            &&opTimerK,
                                            &&opCounterK,
                                            &&opLoadStartTimerK,
                                            &&opLoadStartCounterK,
                                            &&opLoadStartMoveWord16,
                                            &&opLoadStartMoveConst16,
                                            &&opLoadStartOut,
                                            &&opSeriesStartOr,
                                            &&opSeriesStart2P,
                                            &&opSeriesAnd2P,
                                            &&opParallelAndP,
                                            &&opSeriesOrP,
                                            &&opBranchOutP,
                                            &&opBranchOutNotP,
                                            &&opSeriesStartOrP,
                                            &&opStop};
    static_assert(std::size(table) == static_cast<std::size_t>(FastOp::Stop) + 1);
    const FastStep *f = fast;
    auto at = [&] { return static_cast<std::size_t>(f - fast); };
#define RUNG_NEXT()                                                                                \
    do {                                                                                           \
        if constexpr (Record)                                                                      \
            flow[at()] = acc;                                                                      \
        ++f;                                                                                       \
        goto *table[static_cast<std::size_t>(f->op)];                                              \
    } while (false)

    goto *table[static_cast<std::size_t>(f->op)];
opLoadStart:
    load(bitOf(*f), true);
    RUNG_NEXT();
opLoadStartNot:
    load(!bitOf(*f), true);
    RUNG_NEXT();
opLoad:
    load(bitOf(*f), false);
    RUNG_NEXT();
opLoadNot:
    load(!bitOf(*f), false);
    RUNG_NEXT();
opAnd:
    acc = acc & bitOf(*f);
    RUNG_NEXT();
opAndNot:
    acc = acc & !bitOf(*f);
    RUNG_NEXT();
opOr:
    acc = acc | (bitOf(*f) & RUNG_GATE);
    RUNG_NEXT();
opOrNot:
    acc = acc | (!bitOf(*f) & RUNG_GATE);
    RUNG_NEXT();
opLoadEdge:
    load(edgeAt(*f), (stepOf(*f).flags & kRungStart) != 0);
    RUNG_NEXT();
opAndEdge:
    acc = acc & edgeAt(*f);
    RUNG_NEXT();
opOrEdge:
    acc = acc | (edgeAt(*f) & RUNG_GATE);
    RUNG_NEXT();
opAndBlock:
    if (bsp > 0)
        acc = blocks[--bsp] & acc;
    RUNG_NEXT();
opOrBlock:
    if (bsp > 0)
        acc = blocks[--bsp] | acc;
    RUNG_NEXT();
opPush:
    if (!Guarded || psp < kPushStack)
        pushed[psp++] = acc;
    RUNG_NEXT();
opReadStack:
    if (psp > 0)
        acc = pushed[psp - 1];
    RUNG_NEXT();
opPop:
    if (psp > 0)
        acc = pushed[--psp];
    RUNG_NEXT();
opInvert:
    acc = !acc;
    RUNG_NEXT();
opOut:
    write(*f, acc);
    RUNG_NEXT();
opOutNot:
    write(*f, !acc);
    RUNG_NEXT();
opSet:
    if (acc)
        write(*f, true);
    RUNG_NEXT();
opReset:
    if (acc)
        resetTargets(stepOf(*f), W);
    RUNG_NEXT();
opTimer : {
    // Engine::timer (engine_timers.h) for a set value in binary on an ungated element.
    const Step &s = stepOf(*f);
    ElementState &st = states[s.slot];
    const std::int32_t set = setOf(s);
    const bool keeps = s.op == kTimerAccumulates;
    if (!acc) {
        if (!keeps)
            st.accumulated = 0;
        st.running = 0;
    } else {
        if (st.running)
            st.accumulated =
                std::min<std::int64_t>(st.accumulated + period, std::int64_t{set} * s.count);
        st.running = 1;
    }
    const std::int64_t u = acc || keeps ? units(st.accumulated, s.count) : 0;
    putBit(s.bit, (acc || keeps) && u >= set);
    R[s.dest] = static_cast<std::int32_t>((s.flags & kDown) ? set - u : std::min(u, timerMax));
    RUNG_NEXT();
}
opCounter : {
    const Step &s = stepOf(*f);
    const bool oneInput = (s.flags & kOneInput) != 0;
    bool input = acc;
    if (!oneInput)
        input = bsp > 0 ? blocks[--bsp] : false;
    const bool reset = !oneInput && acc;
    // Engine::counter (engine_timers.h) for a set value in binary on an ungated element.
    ElementState &st = states[s.slot];
    const std::int32_t set = setOf(s);
    if (reset)
        st.accumulated = 0;
    else if (input && !st.previous && st.accumulated < set)
        ++st.accumulated;
    st.previous = input;
    putBit(s.bit, !reset && st.accumulated >= set);
    R[s.dest] = wrapToWidth((s.flags & kDown) ? set - st.accumulated : st.accumulated, s.width);
    RUNG_NEXT();
}
opMove:
    if (acc) {
        const Step &s = stepOf(*f);
        const std::int32_t v = readWord(R, s.x);
        storeAt(s.dest, v, s.width);
        if (flags) [[unlikely]]
            resultFlags(v);
    }
    RUNG_NEXT();
opAdd:
    if (acc) {
        const Step &s = stepOf(*f);
        storeAt(s.dest, std::int64_t{readWord(R, s.x)} + readWord(R, s.y), s.width);
    }
    RUNG_NEXT();
opSub:
    if (acc) {
        const Step &s = stepOf(*f);
        storeAt(s.dest, std::int64_t{readWord(R, s.x)} - readWord(R, s.y), s.width);
    }
    RUNG_NEXT();
opInc:
    if (acc) {
        const Step &s = stepOf(*f);
        storeAt(s.dest, std::int64_t{R[s.dest]} + 1, s.width);
    }
    RUNG_NEXT();
opDec:
    if (acc) {
        const Step &s = stepOf(*f);
        storeAt(s.dest, std::int64_t{R[s.dest]} - 1, s.width);
    }
    RUNG_NEXT();
opNop:
    RUNG_NEXT();
opSlow : {
    // One step in the full interpreter: the registers go over in m_regs and come back with
    // the step that runs next (a jump, a call or END may move it); it records the power flow.
    Registers &r = m_regs;
    r.acc = acc;
    r.gate = gate;
    r.interlock = interlock;
    r.stepActive = stepActive;
    r.bsp = bsp;
    r.psp = psp;
    const std::size_t next = execute<Record, true>(at(), at() + 1);
    acc = r.acc;
    gate = r.gate;
    interlock = r.interlock;
    stepActive = r.stepActive;
    bsp = r.bsp;
    psp = r.psp;
    if (next >= n)
        return next;
    f = fast + next;
    goto *table[static_cast<std::size_t>(f->op)];
}
// The runs of contacts as one op, each in two forms: C = contact, any contact negated or not,
// and C = bitOf for the P ops, whose contacts are none negated (compile_fast.cpp): the negation
// costs a load and an XOR a contact.
#define RUNG_SERIES_START2(C)                                                                      \
    do {                                                                                           \
        const bool a = C(f[0]) & RUNG_GATE;                                                        \
        bsp = 0;                                                                                   \
        psp = 0;                                                                                   \
        if constexpr (Record)                                                                      \
            flow[at()] = a;                                                                        \
        acc = a & C(f[1]);                                                                         \
        ++f;                                                                                       \
        RUNG_NEXT();                                                                               \
    } while (false)
#define RUNG_SERIES_START_OR(C)                                                                    \
    do {                                                                                           \
        const bool a = C(f[0]) & RUNG_GATE;                                                        \
        const bool series = a & C(f[1]);                                                           \
        bsp = 0;                                                                                   \
        psp = 0;                                                                                   \
        if constexpr (Record) {                                                                    \
            flow[at()] = a;                                                                        \
            flow[at() + 1] = series;                                                               \
        }                                                                                          \
        acc = series | (C(f[2]) & RUNG_GATE);                                                      \
        f += 2;                                                                                    \
        RUNG_NEXT();                                                                               \
    } while (false)
#define RUNG_SERIES_AND2(C)                                                                        \
    do {                                                                                           \
        acc = acc & C(f[0]);                                                                       \
        if constexpr (Record)                                                                      \
            flow[at()] = acc;                                                                      \
        acc = acc & C(f[1]);                                                                       \
        ++f;                                                                                       \
        RUNG_NEXT();                                                                               \
    } while (false)
// The block stack's bound, as LD and ANB / ORB keep it (the compiler never comes near it): at
// the bound the run goes step by step from its LD.
#define RUNG_BLOCK_BOUND()                                                                         \
    do {                                                                                           \
        if (Guarded && bsp >= kBlockStack) [[unlikely]] {                                          \
            if (f->flip)                                                                           \
                goto opLoadNot;                                                                    \
            goto opLoad;                                                                           \
        }                                                                                          \
    } while (false)
#define RUNG_PARALLEL_AND(C)                                                                       \
    do {                                                                                           \
        RUNG_BLOCK_BOUND();                                                                        \
        const bool a = C(f[0]) & RUNG_GATE;                                                        \
        const bool branch = a | (C(f[1]) & RUNG_GATE);                                             \
        if constexpr (Record) {                                                                    \
            flow[at()] = a;                                                                        \
            flow[at() + 1] = branch;                                                               \
        }                                                                                          \
        acc = acc & branch;                                                                        \
        f += 2;                                                                                    \
        RUNG_NEXT();                                                                               \
    } while (false)
#define RUNG_SERIES_OR(C)                                                                          \
    do {                                                                                           \
        RUNG_BLOCK_BOUND();                                                                        \
        const bool a = C(f[0]) & RUNG_GATE;                                                        \
        const bool series = a & C(f[1]);                                                           \
        if constexpr (Record) {                                                                    \
            flow[at()] = a;                                                                        \
            flow[at() + 1] = series;                                                               \
        }                                                                                          \
        acc = acc | series;                                                                        \
        f += 2;                                                                                    \
        RUNG_NEXT();                                                                               \
    } while (false)
// The coil's value; MPP gives acc back as it was.
#define RUNG_BRANCH_OUT(C, negated)                                                                \
    do {                                                                                           \
        if (Guarded && psp >= kPushStack) [[unlikely]]                                             \
            goto opPush;                                                                           \
        const bool on = acc & C(f[1]);                                                             \
        if constexpr (Record) {                                                                    \
            flow[at()] = acc;                                                                      \
            flow[at() + 1] = on;                                                                   \
            flow[at() + 2] = on;                                                                   \
        }                                                                                          \
        write(f[2], on != (negated));                                                              \
        f += 3;                                                                                    \
        RUNG_NEXT();                                                                               \
    } while (false)
opSeriesStart2:
    RUNG_SERIES_START2(contact);
opSeriesStart2P:
    RUNG_SERIES_START2(bitOf);
opSeriesStartOr:
    RUNG_SERIES_START_OR(contact);
opSeriesStartOrP:
    RUNG_SERIES_START_OR(bitOf);
opSeriesAnd2:
    RUNG_SERIES_AND2(contact);
opSeriesAnd2P:
    RUNG_SERIES_AND2(bitOf);
opParallelAnd:
    RUNG_PARALLEL_AND(contact);
opParallelAndP:
    RUNG_PARALLEL_AND(bitOf);
opSeriesOr:
    RUNG_SERIES_OR(contact);
opSeriesOrP:
    RUNG_SERIES_OR(bitOf);
opBranchOut:
    RUNG_BRANCH_OUT(contact, false);
opBranchOutP:
    RUNG_BRANCH_OUT(bitOf, false);
opBranchOutNot:
    RUNG_BRANCH_OUT(contact, true);
opBranchOutNotP:
    RUNG_BRANCH_OUT(bitOf, true);
#undef RUNG_SERIES_START2
#undef RUNG_SERIES_START_OR
#undef RUNG_SERIES_AND2
#undef RUNG_PARALLEL_AND
#undef RUNG_SERIES_OR
#undef RUNG_BLOCK_BOUND
#undef RUNG_BRANCH_OUT
opTimerFull:
    timer(stepOf(*f), at(), acc, pass);
    RUNG_NEXT();
opCounterFull : {
    const Step &s = stepOf(*f);
    const bool oneInput = (s.flags & kOneInput) != 0;
    bool input = acc;
    if (!oneInput)
        input = bsp > 0 ? blocks[--bsp] : false;
    counter(s, at(), input, !oneInput && acc, pass);
    RUNG_NEXT();
}
opMoveWord16:
    if (acc)
        storeAt(f->word, R[f->mask], 16);
    RUNG_NEXT();
opMoveConst16:
    if (acc)
        storeAt(f->word, static_cast<std::int32_t>(f->mask), 16);
    RUNG_NEXT();
opAddWordConst16:
    if (acc)
        storeAt(f->word, std::int64_t{R[f->mask]} + static_cast<std::int32_t>(f->flip), 16);
    RUNG_NEXT();
opAddWordWord16:
    if (acc)
        storeAt(f->word, std::int64_t{R[f->mask]} + R[f->flip], 16);
    RUNG_NEXT();
opSubWordConst16:
    if (acc)
        storeAt(f->word, std::int64_t{R[f->mask]} - static_cast<std::int32_t>(f->flip), 16);
    RUNG_NEXT();
opSubWordWord16:
    if (acc)
        storeAt(f->word, std::int64_t{R[f->mask]} - R[f->flip], 16);
    RUNG_NEXT();
opStepLadder:
    // STL: what follows runs while the step's bit is ON, up to the next STL or RET.
    stepActive = bitOf(*f);
    gate = interlock && stepActive;
    acc = gate;
    RUNG_NEXT();
opReturn:
    stepActive = true;
    gate = interlock;
    acc = gate;
    RUNG_NEXT();
opInterlock:
    interlock = acc;
    gate = interlock && stepActive;
    RUNG_NEXT();
opInterlockClear:
    interlock = true;
    gate = stepActive;
    RUNG_NEXT();
opSetStep:
    if (acc) { // SET of a step relay inside an STL block: the current step is reset
        const Step &s = stepOf(*f);
        putBit(s.bit, true);
        putBit(p.bitLists[static_cast<std::size_t>(s.slot)], false);
    }
    RUNG_NEXT();
opJump:
    // JMP / CJ forward while its condition is OFF: on at its JME, whose power flow it
    // records, as the full interpreter does.
    if (!acc && f->word > static_cast<std::int32_t>(at()))
        f = fast + f->word;
    RUNG_NEXT();
opTimerK : {
    // opTimer's rules with what the K set value decides worked out by the compiler: the done
    // bit is on once the time reached set x base; units by a multiply-shift (FastElement).
    // A timer whose input is OFF, most of a program's timers most of the time, only clears.
    const FastElement &e = *f->element();
    ElementState &st = stateOf(e);
    R[e.setWord] = e.set;
    if (!acc) {
        st.running = 0;
        st.accumulated = 0;
        putKept(e, false);
        R[e.dest] = 0;
        RUNG_NEXT();
    }
    const std::int64_t ms =
        st.running ? std::min<std::int64_t>(st.accumulated + period, e.limitMs) : st.accumulated;
    st.running = 1;
    st.accumulated = ms;
    putKept(e, ms >= e.limitMs);
    std::int64_t units = static_cast<std::int64_t>(
        (static_cast<std::uint64_t>(std::min(ms, e.limitMs)) * e.magic) >> kFastDivShift);
    if (ms > e.limitMs) [[unlikely]] // kept from before an online edit lowered the set value
        units = std::min<std::int64_t>(ms / e.base, timerMax);
    R[e.dest] = static_cast<std::int32_t>(units);
    RUNG_NEXT();
}
opCounterK : {
    const FastElement &e = *f->element();
    ElementState &st = stateOf(e);
    R[e.setWord] = e.set;
    if (acc && !st.previous && st.accumulated < e.set)
        ++st.accumulated;
    st.previous = acc;
    putKept(e, st.accumulated >= e.set);
    R[e.dest] = static_cast<std::int16_t>(static_cast<std::uint16_t>(st.accumulated));
    RUNG_NEXT();
}
// The rung's first contact, then straight into the next step's code (no dispatch): it
// is the step the compiler saw there (compile_fast.cpp, fuse).
#define RUNG_LOAD_START_THEN(next)                                                                 \
    do {                                                                                           \
        bsp = 0;                                                                                   \
        psp = 0;                                                                                   \
        acc = contact(*f) & RUNG_GATE;                                                             \
        if constexpr (Record)                                                                      \
            flow[at()] = acc;                                                                      \
        ++f;                                                                                       \
        goto next;                                                                                 \
    } while (false)
opLoadStartTimerK:
    RUNG_LOAD_START_THEN(opTimerK);
opLoadStartCounterK:
    RUNG_LOAD_START_THEN(opCounterK);
opLoadStartMoveWord16:
    RUNG_LOAD_START_THEN(opMoveWord16);
opLoadStartMoveConst16:
    RUNG_LOAD_START_THEN(opMoveConst16);
opLoadStartOut:
    RUNG_LOAD_START_THEN(opOut);
#undef RUNG_LOAD_START_THEN
opEnd:
    if constexpr (Record)
        flow[at()] = acc;
    return n;
opStop:
    return n;
#undef RUNG_NEXT
#undef RUNG_GATE
}

#if defined(__clang__)
#pragma clang diagnostic pop
#else
#pragma GCC diagnostic pop
#endif

template std::size_t Engine::runFast<false, false, false, false>();
template std::size_t Engine::runFast<false, false, false, true>();
template std::size_t Engine::runFast<false, false, true, false>();
template std::size_t Engine::runFast<false, false, true, true>();
template std::size_t Engine::runFast<false, true, false, false>();
template std::size_t Engine::runFast<false, true, false, true>();
template std::size_t Engine::runFast<false, true, true, false>();
template std::size_t Engine::runFast<false, true, true, true>();
template std::size_t Engine::runFast<true, false, false, false>();
template std::size_t Engine::runFast<true, false, false, true>();
template std::size_t Engine::runFast<true, false, true, false>();
template std::size_t Engine::runFast<true, false, true, true>();
template std::size_t Engine::runFast<true, true, false, false>();
template std::size_t Engine::runFast<true, true, false, true>();
template std::size_t Engine::runFast<true, true, true, false>();
template std::size_t Engine::runFast<true, true, true, true>();

} // namespace rung::simulator
