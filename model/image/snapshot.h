#pragma once

// What a monitor shows: the memory image, forced bits, scan statistics and the power flow
// of the last scan. A plain value: the simulator fills it, and so will the online monitor,
// from the same MemoryLayout.

#include "model/image/memory_layout.h"

#include <QtGlobal>

#include <memory>
#include <optional>
#include <vector>

namespace rung::model {

struct ScanStatistics {
    quint64 scans = 0;        // completed scans since start
    qint64 timeMs = 0;        // virtual time at the end of the last scan
    qint64 periodMs = 10;     // virtual scan period
    qint64 execNsCurrent = 0; // wall-clock time the last scan took to evaluate
    qint64 execNsMin = 0;
    qint64 execNsMax = 0;
};

// A scan stopped between two instructions (a breakpoint, or stepping one instruction at a
// time): what the interpreter holds before `instruction` runs.
struct ScanPause {
    int instruction = -1;          // the next instruction to run (index in the list)
    bool result = false;           // the logic result (accumulator) so far
    std::vector<bool> blockStack;  // ANB/ORB, AND LD/OR LD operands, bottom first
    std::vector<bool> memoryStack; // MPS/MRD/MPP, bottom first
    bool interlock = true;         // false inside an open IL/MC whose condition is OFF
    bool stepActive = true;        // false inside an STL block whose step is OFF
    int breakpoint = -1;           // the breakpoint's instruction that stopped it; -1 a step
    friend bool operator==(const ScanPause &, const ScanPause &) = default;
};

struct Snapshot {
    std::shared_ptr<const MemoryLayout> layout;
    std::vector<std::int32_t> words;       // MemoryLayout order
    std::vector<std::uint32_t> forceMask;  // per word: forced bits
    std::vector<std::uint32_t> forceValue; // per word: their forced values
    ScanStatistics statistics;
    // Logic result after each instruction of the last scan (index = instruction index);
    // empty when power-flow recording is off.
    std::vector<bool> powerFlow;
    // An online source lost its link to the PLC: the words are the last values read, kept so
    // the user still sees them, and no longer the PLC's. A simulation is never stale.
    bool stale = false;
    // Set while the scan is stopped inside (the words then hold what the scan wrote so far).
    std::optional<ScanPause> pause;
    // A timer's or counter's coil: its input (a counter's count input) as the box last ran,
    // per element state slot (MemoryLayout::elementState). The Vigor Computer Link reads it
    // at 0780h..07BFh (Vigor M/VB/VH communication manual, B-5-3). Empty where the origin
    // does not know it (an online PLC).
    std::vector<bool> coils;
    // Online: the words the PLC has answered for at least once (MemoryLayout order); the
    // others hold 0 because nobody asked, not because the PLC said so (a Vigor timer's set
    // value lives in the program, and no protocol area holds it). Null: every word is the
    // memory's own (a simulation).
    std::shared_ptr<const std::vector<bool>> wordsRead;
    // A network station: the virtual time (us, the clock of statistics.timeMs) at which a port
    // of the PLC last received a byte or its last byte sent leaves; -1: never, or nothing is
    // known of its ports (a PLC simulated alone has none, an online PLC is not asked).
    qint64 communicatedUs = -1;

    bool bit(const Address &address) const {
        const BitRef r = layout ? layout->bit(address) : BitRef{};
        return r.valid() && (static_cast<std::uint32_t>(word(r.word)) & r.mask) != 0;
    }
    // Word value; a timer/counter gives its current value.
    std::int32_t value(const Address &address) const {
        return layout ? layout->value(words, address) : 0;
    }
    std::int32_t setValue(const Address &address) const {
        return layout ? word(layout->setValueWord(address)) : 0;
    }
    // The set value in force is known: the memory holds it, or the PLC answered for it.
    bool setValueKnown(const Address &address) const {
        return layout && known(layout->setValueWord(address));
    }
    bool valueKnown(const Address &address) const {
        if (!layout)
            return false;
        const int word = address.bit < 0 ? layout->word(address) : -1;
        return known(word >= 0 ? word : layout->bit(address).word);
    }
    std::optional<bool> coil(const Address &address) const {
        const int slot = layout ? layout->elementState(address) : -1;
        if (slot < 0 || static_cast<std::size_t>(slot) >= coils.size())
            return std::nullopt;
        return coils[static_cast<std::size_t>(slot)];
    }
    bool forced(const Address &address) const {
        const BitRef r = layout ? layout->bit(address) : BitRef{};
        return r.valid() && static_cast<std::size_t>(r.word) < forceMask.size() &&
               (forceMask[static_cast<std::size_t>(r.word)] & r.mask) != 0;
    }

private:
    bool known(int index) const {
        if (index < 0 || static_cast<std::size_t>(index) >= words.size())
            return false;
        return !wordsRead || (static_cast<std::size_t>(index) < wordsRead->size() &&
                              (*wordsRead)[static_cast<std::size_t>(index)]);
    }
    std::int32_t word(int index) const {
        return index >= 0 && static_cast<std::size_t>(index) < words.size()
                   ? words[static_cast<std::size_t>(index)]
                   : 0;
    }
};

} // namespace rung::model
