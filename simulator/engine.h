#pragma once

// The scan engine: runs a compiled Program on deterministic virtual time. Every scan reads
// the input image (stimulus + forcing), evaluates the steps top to bottom, then makes the
// outputs visible at END; the virtual clock advances by exactly one period per scan.
// Not thread-safe: one thread drives an Engine (SimulatorSession: its worker; other threads
// post to a CommandInbox and read the snapshots the worker publishes).

#include "program.h"

#include "model/image/snapshot.h"

#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace rung::simulator {

using model::ScanStatistics;
using model::Snapshot;

struct RuntimeError {
    int instruction = 0; // index in the instruction list
    int line = 0;        // source line (0 when generated)
    QString message;     // translated
};

class Engine {
public:
    explicit Engine(std::shared_ptr<const Program> program);

    const Program &program() const { return *m_program; }
    const MemoryLayout &layout() const { return *m_program->layout; }

    void setPeriodMs(qint64 periodMs); // >= 1
    qint64 periodMs() const { return m_stats.periodMs; }

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

    Snapshot snapshot() const;
    // The memory image in MemoryLayout order (the history recorder reads it after a scan).
    const std::vector<std::int32_t> &words() const { return m_words; }

private:
    void loadPresets(); // Program::presetLoads, at start and at each power cycle
    struct ElementState {
        std::int64_t accumulated = 0; // timers: ms with the input ON; counters: count
        std::uint8_t previous = 0;    // counters: input state at the last execution
        std::uint8_t running = 0;     // timers: input was ON at the last execution
    };

    void beginScan();
    template <bool Record> void execute();
    // engine_operands.cpp: a step with kResolve runs as a copy whose OperandRefs are words of
    // the image or constants; false when an indexed operand lands outside its areas (the
    // PLC's operation error: the instruction does nothing).
    bool resolveStep(const Step &s, std::size_t step, Step &resolved);
    void writeBack(const Step &s, const Step &resolved, std::int32_t *bits);
    std::int64_t resolveElement(const OperandRef &ref, std::size_t step, int extent, bool *ok);
    std::int32_t readBits(const OperandRef &ref, std::int64_t element) const;
    QString refText(const OperandRef &ref) const;
    void endScan();
    void applyForces(std::int32_t *words) const;
    void rebuildForcedWords();
    void runtimeError(std::size_t step, const QString &message);
    void put(std::int32_t *words, const BitRef &bit, bool on) const {
        if (m_forceMask[static_cast<std::size_t>(bit.word)] & bit.mask)
            return;
        auto &w = reinterpret_cast<std::uint32_t &>(words[bit.word]);
        w = on ? (w | bit.mask) : (w & ~bit.mask);
    }
    // Every word write of the engine: wrapped to the word's width, forced bits kept.
    void storeWord(std::size_t i, std::int64_t value, int width) {
        const auto v = static_cast<std::uint32_t>(model::wrapToWidth(value, width));
        m_words[i] =
            static_cast<std::int32_t>((v & ~m_forceMask[i]) | (m_forceValue[i] & m_forceMask[i]));
    }
    bool isStimulus(const model::Address &address) const;
    std::int32_t readSet(const Step &s, std::size_t step);
    void wordLogic(const Step &s, std::size_t step); // Code::WordLogic, its input ON
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
};

// W353 "Subroutines": SBS(91) nests up to 16 levels.
inline constexpr int kSubroutineDepth = 16;

} // namespace rung::simulator
