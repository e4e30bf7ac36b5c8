#pragma once

// The scan engine: runs a compiled Program on deterministic virtual time. Every scan reads
// the input image (stimulus + forcing), evaluates the steps top to bottom, then makes the
// outputs visible at END; the virtual clock advances by exactly one period per scan.
// Not thread-safe: one thread drives an Engine (SimulatorSession: its worker; other threads
// post to a CommandInbox and read the snapshots the worker publishes).

#include "comm_state.h"
#include "program.h"

#include "model/comm/link_table.h"
#include "model/comm/plc_port.h"

#include "model/image/snapshot.h"
#include "model/listing/structure.h"

#include <QString>

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace rung::simulator {

using model::ScanStatistics;
using model::Snapshot;

using model::ScanPause;

// Stops the engine before an instruction, optionally only when a condition holds then
// ("when Y0 rises", "when D10 > 100"). A rise or fall is against the value the device had the
// last time the engine reached that instruction (at first: when the breakpoint was set).
struct Breakpoint {
    enum class When : std::uint8_t { Always, Rises, Falls, IsOn, IsOff, Compare };
    int instruction = 0;
    When when = When::Always;
    model::Address device;                      // the condition's bit or word
    model::CompareOp op = model::CompareOp::Gt; // Compare
    qint64 value = 0;                           // Compare: the constant
    friend bool operator==(const Breakpoint &, const Breakpoint &) = default;
};

// How a scan that may stop inside ended.
enum class ScanStop : std::uint8_t {
    Completed,  // the scan reached its END (the engine is at a scan boundary)
    Breakpoint, // stopped before a breakpoint's instruction
    Stepped,    // stopped after one instruction (stepInstruction)
};

// What an online edit did (replaceProgram).
enum class EditApplied : std::uint8_t {
    Now,          // at a scan boundary: the next scan runs the new program
    AtScanEnd,    // the engine is inside a scan: the new program takes over at its END
    LayoutDiffers // the new program has another memory layout: nothing changed
};

struct RuntimeError {
    int instruction = 0; // index in the instruction list
    int line = 0;        // source line (0 when generated)
    QString message;     // translated
};

// W353 "Subroutines": SBS(91) nests up to 16 levels.
inline constexpr int kSubroutineDepth = 16;

class Engine {
public:
    // The interpreter's stacks (engine_execute.cpp checks them against the listing's limits).
    static constexpr int kBlockStack = model::kMaxOpenBlocks;
    static constexpr int kPushStack = model::kMaxStackDepthOfAnyTarget;

    explicit Engine(std::shared_ptr<const Program> program);

    const Program &program() const { return *m_program; }
    const MemoryLayout &layout() const { return *m_program->layout; }

    void setPeriodMs(qint64 periodMs); // >= 1
    qint64 periodMs() const { return m_stats.periodMs; }

    // One whole scan (inside a stopped scan: the rest of it), breakpoints ignored.
    void scan();
    void runScans(quint64 count);
    // Scans until the condition holds after a scan; false when maxScans ran out first.
    bool runUntil(const std::function<bool(const Engine &)> &condition, quint64 maxScans);
    void runFor(qint64 durationMs); // as many whole periods as fit (at least one if > 0)
    // Power off and on: non-retentive areas clear, retentive ones (Area::retentive) survive.
    void powerCycle();
    // A fresh PLC's power-on state (every area clear, forces released, statistics and errors
    // gone); the scan period and power-flow recording stay.
    void reset();

    // Breakpoints and stepping inside a scan (docs/simulator.md "Breakpoints"). The plain
    // scan() never looks at breakpoints: a scan without any costs what it did.
    // False with a translated reason (nothing changed) when an instruction or device is not
    // in the program's image.
    bool setBreakpoints(const std::vector<Breakpoint> &breakpoints, QString *error = nullptr);
    const std::vector<Breakpoint> &breakpoints() const { return m_breakpointList; }
    // Runs a scan (or the rest of the stopped one) until a breakpoint holds or the scan ends.
    // Resuming never stops again before the instruction it stopped at.
    ScanStop scanToBreakpoint();
    // One instruction. At a scan boundary it starts a scan (inputs read) and stops before
    // the first instruction; Completed when the instruction ended the scan.
    ScanStop stepInstruction();
    // Inside a scan: runs until the next instruction to run is `instruction` (or the scan
    // ends: false). Replays a stop of the past (history).
    bool advanceTo(int instruction);
    bool insideScan() const { return m_inside; }
    // The next instruction of a stopped scan; -1 at a scan boundary.
    int stoppedAt() const { return m_inside ? static_cast<int>(m_regs.next) : -1; }
    std::optional<ScanPause> pausePosition() const;

    // Online edit: runs `program` from the next scan boundary on with the memory image as it
    // is (values, timers, counters, forces). Edge memories follow their instruction (the
    // k-th rising contact of X1 keeps the k-th one's memory); a new edge instruction starts
    // from its device's present value, so it does not fire on the edit. Constant presets that
    // changed are loaded. The breakpoints become `breakpoints` (instructions of the new
    // program) when it takes over; until then setBreakpoints() sets those of the new program.
    EditApplied replaceProgram(std::shared_ptr<const Program> program,
                               const std::vector<Breakpoint> &breakpoints = {});

    // Bytes this engine's state holds (a history checkpoint is a copy of it).
    std::size_t memoryBytes() const;
    // Devices. Bits of physical input areas are stimulus: the input image takes them at the
    // start of each scan. Every other write changes the memory image at once.
    bool bit(const model::Address &address) const;
    std::int32_t value(const model::Address &address) const;    // timer/counter: current
    std::int32_t setValue(const model::Address &address) const; // timer/counter set value
    bool setBit(const model::Address &address, bool on);
    bool writeWord(const model::Address &address, qint64 value);
    bool writeSetValue(const model::Address &address, qint64 value);
    // A forced bit keeps its value against stimulus and program writes until released.
    bool force(const model::Address &address, bool on);
    bool release(const model::Address &address);
    void releaseAll();

    void setPowerFlowRecording(bool on) { m_record = on; }
    bool powerFlowRecording() const { return m_record; }
    const std::vector<std::uint8_t> &powerFlow() const { return m_flow; }

    const ScanStatistics &statistics() const { return m_stats; }
    const std::vector<RuntimeError> &runtimeErrors() const { return m_errors; }

    // The station's ports in a network (docs/network.md): the communication instructions
    // drive them. Without (nullptr, the default) a port is connected to nothing: what is sent
    // leaves at once and nothing comes back. The ports must outlive the engine's use of them.
    void attachPorts(model::PlcPorts *ports);

    Snapshot snapshot() const;
    // The memory image in MemoryLayout order (the history recorder reads it after a scan): the
    // layout's words only, as in a snapshot; the scratch words behind them are the engine's.
    std::span<const std::int32_t> words() const { return {m_words.data(), m_scratch}; }
    // A network's exchange without instructions (CPU Link, Parallel Link, docs/network.md)
    // writes the image between scans by word index and bit, forced bits kept.
    void storeImageWord(std::size_t index, std::int32_t value, int width) {
        storeWord(index, value, width);
    }
    void storeImageBit(const BitRef &bit, bool on) { put(m_words.data(), bit, on); }
    // The same for a run of `count` words of one width from `from`'s image (an engine of the
    // same layout) and for the bits of `mask` in one word: a CPU Link exchange copies a few
    // hundred words eight times a slice, word by word the most of the network's own cost.
    void copyImageWords(const Engine &from, std::size_t first, std::size_t count, int width);
    void copyImageBits(const Engine &from, std::size_t word, std::uint32_t mask);

private:
    void loadPresets(); // Program::presetLoads, at start and at each power cycle
    // The PL110-2A's terminal between two scans (Program::terminal, engine_panel.cpp).
    void serviceTerminal();
    bool m_swapHeld = false; // the SWAP key's bit at the last serviceTerminal
    struct ElementState {
        std::int64_t accumulated = 0; // timers: ms with the input ON; counters: count
        std::uint8_t previous = 0;    // counters: input state at the last execution
        std::uint8_t running = 0;     // timers: input was ON at the last execution
    };
    static_assert(sizeof(ElementState) == kElementStateBytes); // FastElement::state

    // The interpreter's registers, kept while a scan is stopped inside.
    struct Registers {
        std::size_t next = 0;
        bool acc = false;
        bool interlock = true;
        bool stepActive = true;
        bool gate = true;
        int bsp = 0;
        int psp = 0;
        bool blocks[kBlockStack] = {};
        bool pushed[kPushStack] = {};
        int depth = 0; // SBS(91) calls not yet returned from
        std::size_t returns[kSubroutineDepth] = {};
        bool held[kSubroutineDepth] = {};
    };
    struct ArmedBreakpoint {
        Breakpoint spec;
        BitRef bit;
        int word = -1;
        bool previous = false;
    };

    void beginScan();
    // Steps [from, to) (jumps may leave it early or late); returns the next step to run,
    // >= steps.size() once END ran. Resumable: the registers come from and go back to
    // m_regs; else they start empty (a whole scan) and stay in the function.
    // Special: the program may have kResolve / kDifferentiated steps (Program::specialSteps).
    template <bool Record, bool Resumable, bool Special = true>
    std::size_t execute(std::size_t from, std::size_t to);
    std::size_t runSegment(std::size_t from, std::size_t to);
    // A whole scan's steps from the first (engine_fast.cpp): Program::fast's loop, the full
    // interpreter for a Slow step. Forced: some bit is forced (without, no write looks).
    // Guarded: some step may turn the gate OFF, or the stacks' bounds may be reached
    // (Program::guarded; without, no gate is read and no stack bound tested).
    template <bool Record, bool Forced, bool Deferred, bool Guarded> std::size_t runFast();
    void startInsideScan();
    void completeInsideScan();
    bool breakpointHolds(std::size_t instruction);
    // engine_operands.cpp: a step with kResolve runs as a copy whose OperandRefs are words of
    // the image or constants; false when an indexed operand lands outside its areas (the
    // PLC's operation error: the instruction does nothing).
    bool resolveStep(const Step &s, std::size_t step, Step &resolved);
    void writeBack(const Step &s, const Step &resolved, std::int32_t *bits);
    std::int64_t resolveElement(const OperandRef &ref, std::size_t step, int extent, bool *ok);
    std::int32_t readBits(const OperandRef &ref, std::int64_t element) const;
    QString refText(const OperandRef &ref) const;
    void endScan();
    void recordExecTime(qint64 ns);
    void applyForces(std::int32_t *words) const;
    void rebuildForcedWords();
    void runtimeError(std::size_t step, const QString &message);
    // One bit of a word set to `on` without a branch: a coil's value follows the inputs, and
    // GCC made `on ? | : &` a jump that the scan mispredicted (cachegrind, issue 10).
    static void writeBit(std::int32_t &word, std::uint32_t mask, bool on) {
        writeBit(word, mask, ~mask, on);
    }
    // The same with the mask's complement worked out by the compiler (FastStep::flip of a
    // coil, FastElement::bitKeep): two instructions fewer a coil.
    static void writeBit(std::int32_t &word, std::uint32_t mask, std::uint32_t keep, bool on) {
        auto &w = reinterpret_cast<std::uint32_t &>(word);
        w = (w & keep) | (mask & (0u - static_cast<std::uint32_t>(on)));
    }
    void put(std::int32_t *words, const BitRef &bit, bool on) const {
        if (m_forceMask[static_cast<std::size_t>(bit.word)] & bit.mask)
            return;
        writeBit(words[bit.word], bit.mask, on);
    }
    // Every word write of the engine: wrapped to the word's width, forced bits kept.
    void storeWord(std::size_t i, std::int64_t value, int width) {
        const auto v = static_cast<std::uint32_t>(model::wrapToWidth(value, width));
        m_words[i] =
            static_cast<std::int32_t>((v & ~m_forceMask[i]) | (m_forceValue[i] & m_forceMask[i]));
    }
    bool isStimulus(const model::Address &address) const;
    // A timer's or counter's set value (negative: none, the box is skipped), also stored where
    // the program reads the set value in use. Inline: every timer and counter of a scan asks
    // it; BCD digits (CPM1) are decoded out of line.
    std::int32_t readSet(const Step &s, std::size_t step) {
        if (s.flags & kBcd) [[unlikely]]
            return readBcdSet(s, step);
        const std::int32_t set = std::max<std::int32_t>(
            0, s.x.index >= 0 ? m_words[static_cast<std::size_t>(s.x.index)] : s.x.constant);
        if (s.y.index >= 0)
            m_words[static_cast<std::size_t>(s.y.index)] = set;
        return set;
    }
    std::int32_t readBcdSet(const Step &s, std::size_t step);

    // What execute() holds for a whole pass over the steps, for the instruction bodies its
    // switch calls: the program, the image read (R), the image bits go to (W: R, or the VPC's
    // write image) and the scan period. The bodies are defined inline where only execute()
    // sees them (engine_execute.cpp, engine_timers.h, engine_arith.h) and always inlined into
    // its loop: the scan compiles to one piece of code, as when they were written in the
    // switch (callgrind, issue 34).
    struct Pass {
        const Program &program;
        std::int32_t *R;
        std::int32_t *W;
        std::int64_t period;
    };
    static bool readBit(const std::int32_t *words, const BitRef &bit) {
        return (static_cast<std::uint32_t>(words[bit.word]) & bit.mask) != 0;
    }
    static std::int32_t readWord(const std::int32_t *words, const WordOperand &o) {
        return o.index >= 0 ? words[o.index] : o.constant;
    }
    // storeWord() for a step's word index.
    void store(std::int32_t index, std::int64_t value, int width) {
        storeWord(static_cast<std::size_t>(index), value, width);
    }
    // Bit instructions and control (engine_execute.cpp).
    void resetTargets(const Step &s, std::int32_t *W);
    void markStepStart(const Step &s, bool active, std::int32_t *R);
    [[gnu::noinline, gnu::cold]] void subroutinesTooDeep(std::size_t step);
    // Timers and counters (engine_timers.h); gateOpen: Area::enabledBy (PL110 SM0.13).
    bool gateOpen(const Pass &pass, std::int32_t slot) const;
    void timer(const Step &s, std::size_t step, bool on, const Pass &pass);
    void counter(const Step &s, std::size_t step, bool input, bool reset, const Pass &pass);
    void upDownCounter(const Step &s, std::size_t step, bool up, bool down, bool reset,
                       const Pass &pass);
    void plTimer(const Step &s, std::size_t step, bool on, const Pass &pass);
    void plCounter(const Step &s, std::size_t step, bool up, bool down, bool reset,
                   const Pass &pass);
    // Word instructions with their input ON (engine_arith.h).
    void transfer(const Step &s, std::size_t step, const Pass &pass);
    void compare(const Step &s, const Pass &pass);
    void multiply(const Step &s, const Pass &pass);
    void divide(const Step &s, std::size_t step, const Pass &pass);
    void math(const Step &s, std::size_t step, const Pass &pass);
    void blockMove(const Step &s, const Pass &pass);
    void doubleMove(const Step &s, const Pass &pass);
    void indirectMove(const Step &s, std::size_t step, const Pass &pass);
    void wordLogic(const Step &s, std::size_t step); // Code::WordLogic, its input ON
    // engine_words.cpp: Vigor CCD with its input ON; whether it takes a byte a word now.
    void checkCode(const Step &s, std::size_t step);
    bool checkCodeBytes(const Step &s) const {
        return s.bit.valid() &&
               (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(s.bit.word)]) &
                s.bit.mask) != 0;
    }
    // Omron CPM1 (engine_cpm1.cpp): Code::Arithmetic with its input ON, SFT(10), the flags.
    void arithmetic(const Step &s, std::size_t step);
    void shiftRegister(const Step &s, bool data, bool pulse, bool reset);
    void setFlag(const BitRef &flag, bool on) {
        if (flag.valid())
            put(m_words.data(), flag, on);
    }
    // After an instruction that ran (ER OFF) with this result: EQ, if the target has it.
    void resultFlags(std::int64_t result) {
        setFlag(m_program->flags.error, false);
        setFlag(m_program->flags.equal, (result & 0xFFFF) == 0);
    }
    // An operand that is not what the instruction reads: ER ON and nothing written (W353).
    void operandError(std::size_t step, const QString &message);
    void clearArithmeticFlags();
    // engine_text.cpp: SWAP, ASCI, HEX, SMOV, DDIV with their input ON.
    void swapBytes(const Step &s);
    void toAscii(const Step &s, std::size_t step);
    void fromAscii(const Step &s, std::size_t step);
    void shiftDigits(const Step &s, std::size_t step);
    void doubleDivide(const Step &s, std::size_t step);
    // engine_comm.cpp: a communication instruction in the scan (every scan, ON or OFF), and
    // the communication work after the user program (Vigor M/VB/VH communication manual, B-3-4:
    // "after the PLC completes the user program").
    void communicate(const Step &s, std::size_t step, bool on);
    void serviceComms();
    // engine_ports.cpp: whether the END has port work to do (a port attached, free-port on or
    // being switched, a transmission or a query under way); a PL110 program that uses no port
    // pays one test a port for its ports.
    bool portsBusy() const;
    qint64 commNowUs() const;
    model::PlcPort *commPort(std::size_t task) const {
        return task < m_commPorts.size() ? m_commPorts[task] : nullptr;
    }
    void serviceMaster(std::size_t task);
    bool planSet(std::size_t task);
    void endSet(std::size_t task, model::LinkStatus status);
    void sendFrame(std::size_t task);
    void applyReply(const MasterFrame &frame, const std::vector<std::uint16_t> &values);
    void serviceSerial();
    void moduleWrite(const CommStep &c, const Step &s, std::size_t step, int bfm, int words);
    void moduleRead(const CommStep &c, const Step &s, std::size_t step, int bfm, int words);
    void serviceModule(int module);
    ModuleState &module(int number);
    qint64 timeoutUs() const;
    // engine_ports.cpp: the PL110's ports (Program::ports): free-port and SEND (PL110 manual
    // 4.2.19), the COM / EXP master (4.2.21).
    void freePortSend(const CommStep &c, std::size_t step);
    void servicePorts();
    void applyFreePort(std::size_t port);
    void serviceQueries(std::size_t port);
    void superviseSlave(std::size_t port);
    void sendQuery(std::size_t port, std::size_t task);
    void endQuery(std::size_t port, model::MasterStatus outcome);
    std::int32_t portWord(std::int32_t index, std::int32_t otherwise = 0) const {
        return index >= 0 ? m_words[static_cast<std::size_t>(index)] : otherwise;
    }
    bool readBit(const BitRef &b) const {
        return b.valid() && (static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(b.word)]) &
                             b.mask) != 0;
    }
    [[gnu::noinline, gnu::cold]] std::int64_t outOfDecimalRange(std::size_t step,
                                                                std::int64_t value);

    std::shared_ptr<const Program> m_program;
    // The layout's words, then kScratchWords: a bit group or double word written by a step
    // is computed there and spread afterwards (writeBack).
    static constexpr std::size_t kScratchWords = 1;
    std::size_t m_scratch = 0;      // index of the scratch word
    std::int64_t m_destElement = 0; // the element a resolved bit-group destination starts at
    std::vector<std::int32_t> m_words;
    std::vector<std::int32_t> m_write; // VPC: the bit image written during the scan
    std::vector<std::int32_t> m_stimulus;
    std::vector<std::uint32_t> m_forceMask;
    std::vector<std::uint32_t> m_forceValue;
    std::vector<int> m_forcedWords;
    std::vector<ElementState> m_states;
    std::vector<std::uint8_t> m_edges;
    std::vector<std::uint8_t> m_flow;
    std::vector<std::uint8_t> m_reported;
    std::vector<RuntimeError> m_errors;
    ScanStatistics m_stats;
    quint64 m_scansSincePowerOn = 0;
    qint64 m_scanMinMs = 0; // scan-time words: the shortest and longest period since power-on
    qint64 m_scanMaxMs = 0;
    bool m_record = false;
    // Stopped inside a scan (breakpoints, stepping).
    bool m_inside = false;
    Registers m_regs;
    qint64 m_insideNs = 0; // evaluation time of the stopped scan so far
    int m_stoppedBy = -1;  // the breakpoint's instruction that stopped it, -1 a step
    std::vector<Breakpoint> m_breakpointList;
    std::vector<ArmedBreakpoint> m_armed; // sorted by instruction
    std::vector<int> m_nextBreak;         // per step (and one past): first armed index at or after
    // Communication (engine_comm.cpp): the state, and each instruction's port (null: none).
    CommState m_comm;
    model::PlcPorts *m_ports = nullptr;
    std::vector<model::PlcPort *> m_commPorts;
    std::vector<model::PlcPort *> m_portLinks;       // Program::ports' ports (null: none)
    bool m_portAttached = false;                     // some m_portLinks is not null
    std::shared_ptr<const Program> m_pendingProgram; // an edit waiting for the scan's END
    std::vector<Breakpoint> m_pendingBreakpoints;    // and its breakpoints
};

} // namespace rung::simulator
