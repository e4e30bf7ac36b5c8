#include "engine.h"

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <utility>

namespace rung::simulator {

namespace {

qint64 clockPeriodMs(model::SystemRole role) {
    switch (role) {
    case model::SystemRole::Clock10ms:
        return 10;
    case model::SystemRole::Clock100ms:
        return 100;
    case model::SystemRole::Clock1s:
        return 1000;
    case model::SystemRole::Clock1min:
        return 60000;
    default:
        return 0;
    }
}

} // namespace

Engine::Engine(std::shared_ptr<const Program> program)
    : m_program(std::move(program)) {
    m_scratch = static_cast<std::size_t>(m_program->layout->wordCount());
    const std::size_t words = m_scratch + kScratchWords;
    m_words.assign(words, 0);
    if (m_program->deferredBitWrites) // the VPC's bit image written during the scan
        m_write.assign(words, 0);
    m_stimulus.assign(words, 0);
    m_forceMask.assign(words, 0);
    m_forceValue.assign(words, 0);
    m_states.assign(static_cast<std::size_t>(m_program->layout->elementStateCount()), {});
    m_edges.assign(static_cast<std::size_t>(m_program->edgeSlots), 0);
    m_flow.assign(m_program->steps.size(), 0);
    m_reported.assign(m_program->steps.size(), 0);
    m_comm.tasks.assign(m_program->comms.size(), {});
    loadPresets();
}

void Engine::loadPresets() {
    for (const auto &[word, value] : m_program->presetLoads)
        m_words[static_cast<std::size_t>(word)] = value;
}

void Engine::reset() {
    const qint64 period = m_stats.periodMs;
    const bool record = m_record;
    const std::vector<Breakpoint> breakpoints =
        m_pendingProgram ? m_pendingBreakpoints : m_breakpointList;
    std::shared_ptr<const Program> program = m_pendingProgram ? m_pendingProgram : m_program;
    model::PlcPorts *ports = m_ports;
    *this = Engine(std::move(program));
    m_stats.periodMs = period;
    m_record = record;
    attachPorts(ports);
    setBreakpoints(breakpoints);
}

void Engine::setPeriodMs(qint64 periodMs) {
    m_stats.periodMs = std::max<qint64>(1, periodMs);
}

void Engine::scan() {
    if (m_inside) {
        const auto start = std::chrono::steady_clock::now();
        runSegment(m_regs.next, m_program->steps.size());
        m_insideNs += std::chrono::duration_cast<std::chrono::nanoseconds>(
                          std::chrono::steady_clock::now() - start)
                          .count();
        completeInsideScan();
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = m_program->steps.size();
    beginScan();
    // The plain program's loop has no test for the rare steps at all (a test per step cost
    // ~10% of a scan, docs/performance.md); the fast loop runs it when the compiler made one.
    if (m_program->fast.size() == n + 1) {
        // One loop for each: a freed register (bits written to the image itself) is worth
        // a few instructions a step.
        const bool forced = !m_forcedWords.empty();
        const bool deferred = m_program->deferredBitWrites;
        using Run = std::size_t (Engine::*)();
        static constexpr Run runs[2][2][2][2] = {{{{&Engine::runFast<false, false, false, false>,
                                                    &Engine::runFast<false, false, false, true>},
                                                   {&Engine::runFast<false, false, true, false>,
                                                    &Engine::runFast<false, false, true, true>}},
                                                  {{&Engine::runFast<false, true, false, false>,
                                                    &Engine::runFast<false, true, false, true>},
                                                   {&Engine::runFast<false, true, true, false>,
                                                    &Engine::runFast<false, true, true, true>}}},
                                                 {{{&Engine::runFast<true, false, false, false>,
                                                    &Engine::runFast<true, false, false, true>},
                                                   {&Engine::runFast<true, false, true, false>,
                                                    &Engine::runFast<true, false, true, true>}},
                                                  {{&Engine::runFast<true, true, false, false>,
                                                    &Engine::runFast<true, true, false, true>},
                                                   {&Engine::runFast<true, true, true, false>,
                                                    &Engine::runFast<true, true, true, true>}}}};
        (this->*runs[m_record][forced][deferred][m_program->guarded])();
    } else {
        const bool special = m_program->specialSteps;
        if (m_record)
            special ? execute<true, false>(0, n) : execute<true, false, false>(0, n);
        else
            special ? execute<false, false>(0, n) : execute<false, false, false>(0, n);
    }
    endScan();
    recordExecTime(std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::steady_clock::now() - start)
                       .count());
}

void Engine::recordExecTime(qint64 ns) {
    m_stats.execNsCurrent = ns;
    m_stats.execNsMin = m_stats.scans == 1 ? ns : std::min(m_stats.execNsMin, ns);
    m_stats.execNsMax = std::max(m_stats.execNsMax, ns);
}

void Engine::runScans(quint64 count) {
    for (quint64 k = 0; k < count; ++k)
        scan();
}

bool Engine::runUntil(const std::function<bool(const Engine &)> &condition, quint64 maxScans) {
    for (quint64 k = 0; k < maxScans; ++k) {
        scan();
        if (condition(*this))
            return true;
    }
    return false;
}

void Engine::runFor(qint64 durationMs) {
    if (durationMs <= 0)
        return;
    const qint64 scans = std::max<qint64>(1, durationMs / m_stats.periodMs);
    runScans(static_cast<quint64>(scans));
}

void Engine::beginScan() {
    const Program &p = *m_program;
    std::int32_t *R = m_words.data();
    for (const auto &[begin, end] : p.inputWordRanges)
        std::copy(m_stimulus.begin() + begin, m_stimulus.begin() + end, m_words.begin() + begin);
    // TEST mode (PL110 manual 2.1.2): "la lettura degli ingressi digitali viene disabilitata. Lo
    // stato degli ingressi viene prelevato dalle word SM37".
    if (p.inputTest.valid() && p.inputTestWord >= 0 &&
        (static_cast<std::uint32_t>(R[p.inputTest.word]) & p.inputTest.mask)) {
        const auto image = static_cast<std::uint32_t>(R[p.inputTestWord]);
        for (std::size_t k = 0; k < p.inputTestBits.size(); ++k) {
            auto &w = reinterpret_cast<std::uint32_t &>(R[p.inputTestBits[k].word]);
            w = (image >> k) & 1u ? (w | p.inputTestBits[k].mask) : (w & ~p.inputTestBits[k].mask);
        }
    }
    const qint64 t = m_stats.timeMs;
    // A virtual scan lasts exactly one period; the scan-time words show it in the unit the
    // target table gives (0.1 ms on Vigor and PL110), min / max since power-on.
    const qint64 period = m_stats.periodMs;
    m_scanMinMs = m_scansSincePowerOn == 0 ? period : std::min(m_scanMinMs, period);
    m_scanMaxMs = m_scansSincePowerOn == 0 ? period : std::max(m_scanMaxMs, period);
    auto scanTime = [&p](qint64 ms, int unitUs) {
        return static_cast<std::int32_t>(std::min<qint64>(ms * 1000 / unitUs, p.scanTimeMax));
    };
    for (const SystemBinding &b : p.system) {
        if (b.word >= 0) {
            R[b.word] = scanTime(b.role == model::SystemRole::ScanTimeMin   ? m_scanMinMs
                                 : b.role == model::SystemRole::ScanTimeMax ? m_scanMaxMs
                                                                            : period,
                                 b.unitUs);
            continue;
        }
        bool on = false;
        switch (b.role) {
        case model::SystemRole::AlwaysOn:
        case model::SystemRole::Run:
            on = true;
            break;
        case model::SystemRole::FirstScan:
            on = m_scansSincePowerOn == 0;
            break;
        case model::SystemRole::ScanToggle:
            on = (m_scansSincePowerOn & 1u) != 0;
            break;
        default:
            if (const qint64 clock = clockPeriodMs(b.role); clock > 0)
                on = (t % clock) < clock / 2;
            break;
        }
        writeBit(R[b.bit.word], b.bit.mask, on);
    }
    if (p.parallelInWord >= 0) {
        std::int32_t v = 0;
        for (std::size_t k = 0; k < p.parallelInBits.size(); ++k)
            if (static_cast<std::uint32_t>(R[p.parallelInBits[k].word]) & p.parallelInBits[k].mask)
                v |= 1 << k;
        R[p.parallelInWord] = v;
    }
    applyForces(R);
    if (p.deferredBitWrites)
        for (const auto &[begin, end] : p.bitWordRanges)
            std::copy(m_words.begin() + begin, m_words.begin() + end, m_write.begin() + begin);
}

void Engine::endScan() {
    const Program &p = *m_program;
    // W353 appendix B: "The ER, CY, GT, LT and EQ Flags are turned OFF when END(01) is
    // executed".
    if (p.flags.any())
        clearArithmeticFlags();
    std::int32_t *W = p.deferredBitWrites ? m_write.data() : m_words.data();
    if (p.writesParallelOut) {
        // Only the port's bits exist (Semantics::parallelOut.bits): the value shows modulo 2^bits.
        const auto v =
            static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(p.parallelOutWord)]);
        for (std::size_t k = 0; k < p.parallelOutBits.size(); ++k)
            put(W, p.parallelOutBits[k], (v >> k) & 1u);
    }
    // PL110 (PL110 manual 4.2.5): "PV viene confrontato con il valore corrente al termine di
    // ogni ciclo": the count bit follows the C word as the scan left it. MDOWN is ON at 0,
    // OFF while its RESET is ON (the box keeps RESET in bit 2 of its state).
    for (const std::int32_t k : p.endOfScanCounters) {
        const Step &s = p.steps[static_cast<std::size_t>(k)];
        if (!p.gates.empty() && s.slot >= 0) { // a counter off by SM0.13 keeps its bit
            const ElementGate &g = p.gates[static_cast<std::size_t>(s.slot)];
            if (g.bit.valid() &&
                ((static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(g.bit.word)]) &
                  g.bit.mask) != 0) != g.whenOn)
                continue;
        }
        const std::int32_t current = m_words[static_cast<std::size_t>(s.dest)];
        const std::int32_t set = m_words[static_cast<std::size_t>(s.y.index)];
        const bool resetOn = (m_states[static_cast<std::size_t>(s.slot)].previous & 4) != 0;
        put(W, s.bit, (s.flags & kDown) ? !resetOn && current == 0 : current >= set);
    }
    if (p.deferredBitWrites)
        for (const auto &[begin, end] : p.bitWordRanges)
            std::copy(m_write.begin() + begin, m_write.begin() + end, m_words.begin() + begin);
    if (!p.comms.empty() || (!p.ports.empty() && portsBusy()))
        serviceComms(); // engine_comm.cpp, engine_ports.cpp
    if (p.terminal.pageShown >= 0)
        serviceTerminal(); // engine_panel.cpp
    ++m_stats.scans;
    ++m_scansSincePowerOn;
    m_stats.timeMs += m_stats.periodMs;
}

void Engine::applyForces(std::int32_t *words) const {
    for (int w : m_forcedWords) {
        const auto i = static_cast<std::size_t>(w);
        auto &v = reinterpret_cast<std::uint32_t &>(words[w]);
        v = (v & ~m_forceMask[i]) | (m_forceValue[i] & m_forceMask[i]);
    }
}

void Engine::rebuildForcedWords() {
    m_forcedWords.clear();
    for (std::size_t i = 0; i < m_forceMask.size(); ++i)
        if (m_forceMask[i])
            m_forcedWords.push_back(static_cast<int>(i));
}

void Engine::runtimeError(std::size_t step, const QString &message) {
    if (m_reported[step])
        return;
    m_reported[step] = 1;
    m_errors.push_back({static_cast<int>(step), m_program->lines[step], message});
}

bool Engine::isStimulus(const model::Address &address) const {
    const model::Area &a = layout().target().area(address.area);
    return a.physical && !a.writable;
}

bool Engine::bit(const model::Address &address) const {
    const BitRef r = layout().bit(address);
    return r.valid() &&
           (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(r.word)]) & r.mask);
}

std::int32_t Engine::value(const model::Address &address) const {
    return layout().value(m_words, address);
}

std::int32_t Engine::setValue(const model::Address &address) const {
    const int w = layout().setValueWord(address);
    return w >= 0 ? m_words[static_cast<std::size_t>(w)] : 0;
}

bool Engine::setBit(const model::Address &address, bool on) {
    const BitRef r = layout().bit(address);
    if (!r.valid())
        return false;
    auto &s = reinterpret_cast<std::uint32_t &>(m_stimulus[static_cast<std::size_t>(r.word)]);
    if (isStimulus(address))
        s = on ? (s | r.mask) : (s & ~r.mask);
    put(m_words.data(), r, on);
    return true;
}

bool Engine::writeWord(const model::Address &address, qint64 value) {
    const int w = layout().word(address);
    if (w < 0)
        return false;
    const auto i = static_cast<std::size_t>(w);
    const std::int32_t v = wrapToWidth(value, layout().wordBits(address));
    if (layout().area(address.area).doubleWords) { // PL110 VD: high word, then low word
        storeWord(i, static_cast<std::uint32_t>(v) >> 16, 16);
        storeWord(i + 1, v, 16);
        return true;
    }
    if (isStimulus(address))
        m_stimulus[i] = v;
    storeWord(i, v, layout().wordBits(address));
    return true;
}

bool Engine::writeSetValue(const model::Address &address, qint64 value) {
    const int w = layout().setValueWord(address);
    if (w < 0)
        return false;
    m_words[static_cast<std::size_t>(w)] = wrapToWidth(value, layout().wordBits(address));
    return true;
}

bool Engine::force(const model::Address &address, bool on) {
    const BitRef r = layout().bit(address);
    if (!r.valid())
        return false;
    const auto i = static_cast<std::size_t>(r.word);
    m_forceMask[i] |= r.mask;
    m_forceValue[i] = on ? (m_forceValue[i] | r.mask) : (m_forceValue[i] & ~r.mask);
    rebuildForcedWords();
    applyForces(m_words.data());
    return true;
}

bool Engine::release(const model::Address &address) {
    const BitRef r = layout().bit(address);
    if (!r.valid())
        return false;
    const auto i = static_cast<std::size_t>(r.word);
    m_forceMask[i] &= ~r.mask;
    m_forceValue[i] &= ~r.mask;
    rebuildForcedWords();
    return true;
}

void Engine::releaseAll() {
    std::fill(m_forceMask.begin(), m_forceMask.end(), 0u);
    std::fill(m_forceValue.begin(), m_forceValue.end(), 0u);
    m_forcedWords.clear();
}

void Engine::powerCycle() {
    const MemoryLayout &l = layout();
    auto clear = [&](int base, int words) {
        if (base >= 0)
            std::fill_n(m_words.begin() + base, words, 0);
    };
    for (int k = 0; k < l.areaCount(); ++k) {
        const AreaLayout &a = l.area(k);
        if (a.retentive)
            continue;
        clear(a.bitBase, (a.count + 15) / 16);
        clear(a.wordBase, a.count);
        clear(a.setBase, a.count);
        if (a.stateBase >= 0)
            std::fill_n(m_states.begin() + a.stateBase, a.count, ElementState{});
    }
    // A scan stopped inside is cut off by the power going (an edit waiting for its END
    // takes over now).
    if (m_inside) {
        m_inside = false;
        m_stoppedBy = -1;
        if (m_pendingProgram)
            replaceProgram(std::exchange(m_pendingProgram, nullptr),
                           std::exchange(m_pendingBreakpoints, {}));
    }
    std::fill(m_edges.begin(), m_edges.end(), 0);
    std::fill(m_flow.begin(), m_flow.end(), 0);
    // The communication starts afresh (a module's buffer memory too); the ports stay.
    m_comm = CommState{};
    m_comm.tasks.assign(m_program->comms.size(), {});
    loadPresets();
    applyForces(m_words.data());
    m_scansSincePowerOn = 0;
}

Snapshot Engine::snapshot() const {
    Snapshot s;
    s.layout = m_program->layout;
    s.words.assign(m_words.begin(), m_words.begin() + static_cast<std::ptrdiff_t>(m_scratch));
    s.forceMask.assign(m_forceMask.begin(),
                       m_forceMask.begin() + static_cast<std::ptrdiff_t>(m_scratch));
    s.forceValue.assign(m_forceValue.begin(),
                        m_forceValue.begin() + static_cast<std::ptrdiff_t>(m_scratch));
    s.statistics = m_stats;
    if (m_record)
        s.powerFlow.assign(m_flow.begin(), m_flow.end());
    s.pause = pausePosition();
    // The coils, from the element states: a timer's input as its box last ran (running), a
    // counter's count input (previous, bit 0; the UP input of an up/down counter).
    const MemoryLayout &l = layout();
    s.coils.assign(m_states.size(), false);
    for (int k = 0; k < l.areaCount(); ++k) {
        const AreaLayout &a = l.area(k);
        if (a.stateBase < 0)
            continue;
        for (int e = 0; e < a.count; ++e) {
            const auto slot = static_cast<std::size_t>(a.stateBase + e);
            const ElementState &st = m_states[slot];
            s.coils[slot] =
                a.kind == model::AreaKind::Timer ? st.running != 0 : (st.previous & 1) != 0;
        }
    }
    return s;
}

void Engine::copyImageWords(const Engine &from, std::size_t first, std::size_t count, int width) {
    const std::int32_t *src = from.m_words.data() + first;
    if (!m_forcedWords.empty()) {
        for (std::size_t k = 0; k < count; ++k)
            storeWord(first + k, src[k], width);
        return;
    }
    std::int32_t *dst = m_words.data() + first;
    for (std::size_t k = 0; k < count; ++k)
        dst[k] = model::wrapToWidth(src[k], width);
}

void Engine::copyImageBits(const Engine &from, std::size_t word, std::uint32_t mask) {
    mask &= ~m_forceMask[word];
    auto &w = reinterpret_cast<std::uint32_t &>(m_words[word]);
    w = (w & ~mask) | (static_cast<std::uint32_t>(from.m_words[word]) & mask);
}

} // namespace rung::simulator
