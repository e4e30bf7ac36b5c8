#pragma once

// The timer and counter boxes of every family, as execute() runs them: the set value read
// (readSet), the element's state in m_states, the done bit and the current value written.
// Included by engine_execute.cpp and engine_fast.cpp alone: the bodies are inlined into the
// scans' loops (engine.h, Engine::Pass). Not part of the simulator's interface: include engine.h
// instead.

#include "engine.h"

#include <algorithm>

namespace rung::simulator {

// RST: the listed bits OFF, words 0, timer and counter elements cleared.
[[gnu::always_inline]] inline void Engine::resetTargets(const Step &s, std::int32_t *W) {
    const Program &p = *m_program;
    for (int k = 0; k < s.count; ++k) {
        const ResetTarget &t = p.resets[static_cast<std::size_t>(s.slot + k)];
        if (t.bit.valid())
            put(W, t.bit, false);
        if (t.word >= 0)
            store(t.word, 0, 32);
        if (t.state >= 0) { // the input edge memory stays: no count on release
            ElementState &st = m_states[static_cast<std::size_t>(t.state)];
            st.accumulated = 0;
            st.running = 0;
        }
    }
}

[[gnu::always_inline]] inline bool Engine::gateOpen(const Pass &pass, std::int32_t slot) const {
    const Program &p = pass.program;
    if (p.gates.empty() || slot < 0)
        return true;
    const ElementGate &g = p.gates[static_cast<std::size_t>(slot)];
    return !g.bit.valid() || readBit(pass.R, g.bit) == g.whenOn;
}

[[gnu::always_inline]] inline void Engine::timer(const Step &s, std::size_t step, bool on,
                                                 const Pass &pass) {
    ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
    if (!gateOpen(pass, s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
        return;
    const std::int32_t set = readSet(s, step);
    if (set < 0)
        return;
    std::int64_t units = 0;
    const bool keeps = s.op == kTimerAccumulates; // only RST clears it
    if (!on) {
        if (!keeps)
            st.accumulated = 0;
        st.running = 0;
    } else {
        if (st.running)
            st.accumulated =
                std::min<std::int64_t>(st.accumulated + pass.period, std::int64_t{set} * s.count);
        st.running = 1;
    }
    if (on || keeps)
        units = st.accumulated / s.count;
    put(pass.W, s.bit, (on || keeps) && units >= set);
    const std::int64_t present =
        (s.flags & kDown) ? set - units : std::min<std::int64_t>(units, pass.program.timerMax);
    // CPM1 (W353): the present value is BCD too: CMP(20) TIM 000 #0100 compares
    // digits, and a Host Link RC reads the same word.
    pass.R[s.dest] =
        (s.flags & kBcd) ? wrapToWidth(toBcd(present), 16) : static_cast<std::int32_t>(present);
}

[[gnu::always_inline]] inline void Engine::counter(const Step &s, std::size_t step, bool input,
                                                   bool reset, const Pass &pass) {
    ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
    if (!gateOpen(pass, s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
        return;
    const std::int32_t set = readSet(s, step);
    if (set < 0)
        return;
    if (reset) {
        st.accumulated = 0;
    } else if (input && !st.previous && st.accumulated < set) {
        ++st.accumulated;
    }
    st.previous = input;
    put(pass.W, s.bit, !reset && st.accumulated >= set);
    const std::int64_t present = (s.flags & kDown) ? set - st.accumulated : st.accumulated;
    pass.R[s.dest] = wrapToWidth((s.flags & kBcd) ? toBcd(present) : present, s.width);
}

[[gnu::always_inline]] inline void Engine::upDownCounter(const Step &s, std::size_t step, bool up,
                                                         bool down, bool reset, const Pass &pass) {
    ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
    if (!gateOpen(pass, s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
        return;
    const std::int32_t set = readSet(s, step);
    if (set < 0)
        return;
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
    put(pass.W, s.bit, st.running != 0);
    pass.R[s.dest] = (s.flags & kBcd) ? wrapToWidth(toBcd(st.accumulated), 16)
                                      : static_cast<std::int32_t>(st.accumulated);
}

[[gnu::always_inline]] inline void Engine::plTimer(const Step &s, std::size_t step, bool on,
                                                   const Pass &pass) {
    // PL110 (PL110 manual 4.2.4): the current value counts time-base units in the T word
    // and saturates at Limits::timerMax; st.accumulated holds the ms not yet a whole unit.
    ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
    if (!gateOpen(pass, s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
        return;
    const std::int32_t set = readSet(s, step);
    if (set < 0)
        return;
    std::int32_t &current = pass.R[s.dest];
    auto advance = [&] {
        st.accumulated += pass.period;
        const std::int64_t units = std::int64_t{current} + st.accumulated / s.count;
        st.accumulated %= s.count;
        current = static_cast<std::int32_t>(std::min(units, pass.program.timerMax));
    };
    bool out = false;
    switch (static_cast<PlTimerMode>(s.op)) {
    case PlTimerMode::OnDelay:
        if (on) {
            if (st.running)
                advance();
        } else {
            current = 0;
            st.accumulated = 0;
        }
        st.running = on;
        out = on && current >= set;
        break;
    case PlTimerMode::Accumulating:
        // Every scan that saw the coil ON was ON until this one (4.2.4: "accumulare
        // il tempo per piu periodi di attivazione"): a one-scan pulse adds a period,
        // a coil on SM0.4 half the elapsed time. Held ON, it counts as TON does.
        if (st.running)
            advance();
        st.running = on;
        out = current >= set;
        break;
    case PlTimerMode::OffDelay:
        // running: 0 idle, 1 input ON, 2 timing after an ON -> OFF transition
        if (on) {
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
    put(pass.W, s.bit, out);
}

[[gnu::always_inline]] inline void Engine::plCounter(const Step &s, std::size_t step, bool up,
                                                     bool down, bool reset, const Pass &pass) {
    // PL110 MUP / MDOWN (PL110 manual 4.2.5): counts rising edges of UP and DOWN in the
    // C word, which saturates at Limits::counterMin..counterMax (-32768..32767; MDOWN
    // stops at 0); RESET clears MUP
    // and loads PV into MDOWN. MUP is ON at >= PV, MDOWN at 0.
    const Program &p = pass.program;
    ElementState &st = m_states[static_cast<std::size_t>(s.slot)];
    if (!gateOpen(pass, s.slot)) // Area::enabledBy (PL110 SM0.13): the box does nothing
        return;
    const std::int32_t set = readSet(s, step);
    if (set < 0)
        return;
    const bool upEdge = up && !(st.previous & 1);
    const bool downEdge = down && !(st.previous & 2);
    st.previous = static_cast<std::uint8_t>((up ? 1 : 0) | (down ? 2 : 0));
    std::int32_t &current = pass.R[s.dest];
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
}

} // namespace rung::simulator
