#include "engine.h"

#include "model/target/address.h"
#include "simulator/tr.h"

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <map>
#include <utility>

// Breakpoints, stepping inside a scan and the online edit. A scan that may stop runs in
// segments between breakpoints (Engine::execute<..., true>): no test per instruction, so a
// scan with breakpoints set costs about what a plain one does, and a scan without any takes
// the plain path untouched.

namespace rung::simulator {

namespace {

using Clock = std::chrono::steady_clock;

qint64 nanosSince(Clock::time_point start) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
}

} // namespace

bool Engine::setBreakpoints(const std::vector<Breakpoint> &breakpoints, QString *error) {
    if (m_pendingProgram) { // the edit's program takes them when it takes over
        const int next = static_cast<int>(m_pendingProgram->steps.size());
        for (const Breakpoint &b : breakpoints)
            if (b.instruction < 0 || b.instruction >= next) {
                if (error)
                    *error = EngineTr::tr("the program has no instruction %1 to stop at")
                                 .arg(b.instruction);
                return false;
            }
        m_pendingBreakpoints = breakpoints;
        return true;
    }
    const int n = static_cast<int>(m_program->steps.size());
    std::vector<ArmedBreakpoint> armed;
    for (const Breakpoint &b : breakpoints) {
        if (b.instruction < 0 || b.instruction >= n) {
            if (error)
                *error =
                    EngineTr::tr("the program has no instruction %1 to stop at").arg(b.instruction);
            return false;
        }
        ArmedBreakpoint a{b, {}, -1, false};
        if (b.when == Breakpoint::When::Compare) {
            a.word = layout().word(b.device);
            if (a.word < 0) {
                if (error)
                    *error = EngineTr::tr("%1 is no word to compare")
                                 .arg(b.device.valid()
                                          ? model::formatAddress(layout().target(), b.device)
                                          : EngineTr::tr("(no device)"));
                return false;
            }
        } else if (b.when != Breakpoint::When::Always) {
            a.bit = layout().bit(b.device);
            if (!a.bit.valid()) {
                if (error)
                    *error = EngineTr::tr("%1 is no bit to watch")
                                 .arg(b.device.valid()
                                          ? model::formatAddress(layout().target(), b.device)
                                          : EngineTr::tr("(no device)"));
                return false;
            }
            a.previous =
                (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(a.bit.word)]) &
                 a.bit.mask) != 0;
        }
        armed.push_back(a);
    }
    std::stable_sort(armed.begin(), armed.end(),
                     [](const ArmedBreakpoint &x, const ArmedBreakpoint &y) {
                         return x.spec.instruction < y.spec.instruction;
                     });
    m_breakpointList = breakpoints;
    m_armed = std::move(armed);
    m_nextBreak.clear();
    if (m_armed.empty())
        return true;
    m_nextBreak.assign(static_cast<std::size_t>(n) + 1, n);
    std::vector<bool> at(static_cast<std::size_t>(n), false);
    for (const ArmedBreakpoint &a : m_armed)
        at[static_cast<std::size_t>(a.spec.instruction)] = true;
    for (int i = n - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        m_nextBreak[k] = at[k] ? i : m_nextBreak[k + 1];
    }
    return true;
}

std::size_t Engine::runSegment(std::size_t from, std::size_t to) {
    return m_record ? execute<true, true>(from, to) : execute<false, true>(from, to);
}

void Engine::startInsideScan() {
    beginScan();
    m_inside = true;
    m_regs = Registers{};
    m_insideNs = 0;
    m_stoppedBy = -1;
}

void Engine::completeInsideScan() {
    endScan();
    m_inside = false;
    m_stoppedBy = -1;
    recordExecTime(m_insideNs);
    if (m_pendingProgram)
        replaceProgram(std::exchange(m_pendingProgram, nullptr),
                       std::exchange(m_pendingBreakpoints, {}));
}

bool Engine::breakpointHolds(std::size_t instruction) {
    bool stop = false;
    auto it =
        std::lower_bound(m_armed.begin(), m_armed.end(), static_cast<int>(instruction),
                         [](const ArmedBreakpoint &a, int i) { return a.spec.instruction < i; });
    // Every breakpoint on the instruction is evaluated (each keeps its own previous value).
    for (; it != m_armed.end() && it->spec.instruction == static_cast<int>(instruction); ++it) {
        using When = Breakpoint::When;
        ArmedBreakpoint &a = *it;
        bool now = false;
        if (a.bit.valid())
            now = (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(a.bit.word)]) &
                   a.bit.mask) != 0;
        switch (a.spec.when) {
        case When::Always:
            stop = true;
            break;
        case When::Rises:
            stop = stop || (now && !a.previous);
            break;
        case When::Falls:
            stop = stop || (!now && a.previous);
            break;
        case When::IsOn:
            stop = stop || now;
            break;
        case When::IsOff:
            stop = stop || !now;
            break;
        case When::Compare:
            stop = stop || model::compareHolds(a.spec.op, m_words[static_cast<std::size_t>(a.word)],
                                               a.spec.value);
            break;
        }
        a.previous = now;
    }
    return stop;
}

ScanStop Engine::scanToBreakpoint() {
    const std::size_t n = m_program->steps.size();
    if (m_armed.empty()) {
        scan();
        return ScanStop::Completed;
    }
    std::size_t i = 0;
    bool resuming = m_inside;
    if (m_inside)
        i = m_regs.next;
    else
        startInsideScan();
    const auto start = Clock::now();
    for (;;) {
        if (i >= n) {
            m_insideNs += nanosSince(start);
            completeInsideScan();
            return ScanStop::Completed;
        }
        if (!resuming && m_nextBreak[i] == static_cast<int>(i) && breakpointHolds(i)) {
            m_regs.next = i;
            m_stoppedBy = static_cast<int>(i);
            m_insideNs += nanosSince(start);
            return ScanStop::Breakpoint;
        }
        resuming = false;
        i = runSegment(i, static_cast<std::size_t>(m_nextBreak[i + 1]));
    }
}

ScanStop Engine::stepInstruction() {
    if (!m_inside) {
        startInsideScan();
        return ScanStop::Stepped;
    }
    const auto start = Clock::now();
    const std::size_t next = runSegment(m_regs.next, m_regs.next + 1);
    m_insideNs += nanosSince(start);
    m_stoppedBy = -1;
    if (next >= m_program->steps.size()) {
        completeInsideScan();
        return ScanStop::Completed;
    }
    return ScanStop::Stepped;
}

bool Engine::advanceTo(int instruction) {
    if (!m_inside)
        startInsideScan();
    const auto target = static_cast<std::size_t>(std::max(0, instruction));
    const std::size_t n = m_program->steps.size();
    const auto start = Clock::now();
    // A jump may pass the instruction; the loop then runs on to END.
    while (m_regs.next < target && m_regs.next < n)
        runSegment(m_regs.next, target);
    m_insideNs += nanosSince(start);
    if (m_regs.next >= n) {
        completeInsideScan();
        return false;
    }
    return m_regs.next == target;
}

std::optional<ScanPause> Engine::pausePosition() const {
    if (!m_inside)
        return std::nullopt;
    ScanPause p;
    p.instruction = static_cast<int>(m_regs.next);
    p.result = m_regs.acc;
    p.blockStack.assign(m_regs.blocks, m_regs.blocks + m_regs.bsp);
    p.memoryStack.assign(m_regs.pushed, m_regs.pushed + m_regs.psp);
    p.interlock = m_regs.interlock;
    p.stepActive = m_regs.stepActive;
    p.breakpoint = m_stoppedBy;
    return p;
}

EditApplied Engine::replaceProgram(std::shared_ptr<const Program> program,
                                   const std::vector<Breakpoint> &breakpoints) {
    const MemoryLayout &now = layout();
    const MemoryLayout &next = *program->layout;
    if (&now.target() != &next.target() || now.wordCount() != next.wordCount() ||
        now.elementStateCount() != next.elementStateCount())
        return EditApplied::LayoutDiffers;
    if (m_inside) {
        m_pendingProgram = std::move(program);
        m_pendingBreakpoints = breakpoints;
        return EditApplied::AtScanEnd;
    }
    const Program &old = *m_program;
    // Edge memories follow their instruction: the k-th edge step of the same kind on the same
    // bit (or, for P/N and pulses, the k-th of its kind) keeps the k-th one's memory.
    using Key = std::tuple<Code, std::uint8_t, std::int32_t, std::uint32_t>;
    auto key = [](const Step &s) {
        return Key{s.code, static_cast<std::uint8_t>(s.flags & kFalling), s.bit.word, s.bit.mask};
    };
    auto hasEdge = [](const Step &s) {
        switch (s.code) {
        case Code::LoadEdge:
        case Code::AndEdge:
        case Code::OrEdge:
        case Code::EdgeFlow:
        case Code::Pulse:
        case Code::Toggle:
            return s.slot >= 0;
        default:
            return false;
        }
    };
    std::map<Key, std::vector<std::uint8_t>> kept;
    for (const Step &s : old.steps)
        if (hasEdge(s))
            kept[key(s)].push_back(m_edges[static_cast<std::size_t>(s.slot)]);
    std::vector<std::uint8_t> edges(static_cast<std::size_t>(program->edgeSlots), 0);
    std::map<Key, std::size_t> taken;
    for (const Step &s : program->steps) {
        if (!hasEdge(s))
            continue;
        const Key k = key(s);
        const std::size_t nth = taken[k]++;
        const auto found = kept.find(k);
        std::uint8_t value = 0;
        if (found != kept.end() && nth < found->second.size())
            value = found->second[nth];
        else if (s.bit.valid() &&
                 (s.code == Code::LoadEdge || s.code == Code::AndEdge || s.code == Code::OrEdge))
            value = (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(s.bit.word)]) &
                     s.bit.mask) != 0;
        edges[static_cast<std::size_t>(s.slot)] = value;
    }
    // Constant presets (PL110 PT/PV) the edit changed or added take their new value.
    std::map<std::int32_t, std::int32_t> oldPresets(old.presetLoads.begin(), old.presetLoads.end());
    for (const auto &[word, value] : program->presetLoads) {
        const auto found = oldPresets.find(word);
        if (found == oldPresets.end() || found->second != value)
            m_words[static_cast<std::size_t>(word)] = value;
    }
    m_program = std::move(program);
    m_edges = std::move(edges);
    m_flow.assign(m_program->steps.size(), 0);
    m_reported.assign(m_program->steps.size(), 0);
    // The communication instructions are the new program's: each starts afresh on its port (a
    // module keeps its buffer memory, as the hardware would).
    m_comm.tasks.assign(m_program->comms.size(), {});
    m_comm.serial = -1;
    attachPorts(m_ports);
    // Breakpoints name instructions: the old program's go, the new program's come.
    m_breakpointList.clear();
    m_armed.clear();
    m_nextBreak.clear();
    setBreakpoints(breakpoints);
    return EditApplied::Now;
}

std::size_t Engine::memoryBytes() const {
    auto bytes = [](const auto &v) { return v.capacity() * sizeof(v[0]); };
    return sizeof(*this) + bytes(m_words) + bytes(m_write) + bytes(m_stimulus) +
           bytes(m_forceMask) + bytes(m_forceValue) + bytes(m_forcedWords) + bytes(m_states) +
           bytes(m_edges) + bytes(m_flow) + bytes(m_reported) + bytes(m_errors) + bytes(m_armed) +
           bytes(m_nextBreak) + bytes(m_breakpointList);
}

} // namespace rung::simulator
