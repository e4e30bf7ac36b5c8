#pragma once

// What a monitor shows: the memory image, forced bits, scan statistics and the power flow
// of the last scan. A plain value: the simulator fills it, and so will the online monitor,
// from the same MemoryLayout.

#include "model/image/memory_layout.h"

#include <QtGlobal>

#include <memory>
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

    bool bit(const Address &address) const {
        const BitRef r = layout ? layout->bit(address) : BitRef{};
        return r.valid() && (static_cast<std::uint32_t>(word(r.word)) & r.mask) != 0;
    }
    // Word value; a timer/counter gives its current value.
    std::int32_t value(const Address &address) const {
        return layout ? word(layout->word(address)) : 0;
    }
    std::int32_t setValue(const Address &address) const {
        return layout ? word(layout->setValueWord(address)) : 0;
    }
    bool forced(const Address &address) const {
        const BitRef r = layout ? layout->bit(address) : BitRef{};
        return r.valid() && static_cast<std::size_t>(r.word) < forceMask.size() &&
               (forceMask[static_cast<std::size_t>(r.word)] & r.mask) != 0;
    }

private:
    std::int32_t word(int index) const {
        return index >= 0 && static_cast<std::size_t>(index) < words.size()
                   ? words[static_cast<std::size_t>(index)]
                   : 0;
    }
};

} // namespace rung::model
