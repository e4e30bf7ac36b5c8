#pragma once

// The memory image of a target as flat arrays, laid out from the target's area table.
// Bit areas are packed 16 bits to a word; word, channel, timer and counter areas take one
// word per element. The layout is a pure function of the Target, so the simulator and the
// online monitor build the same one and snapshots can be read without the engine.

#include "model/target/target.h"

#include <cstdint>
#include <vector>

namespace rung::model {

// A bit as a word index plus a mask (a bit device, a channel bit, a timer's done bit).
struct BitRef {
    std::int32_t word = -1;
    std::uint32_t mask = 0;
    bool valid() const { return word >= 0; }
};

struct AreaLayout {
    AreaKind kind = AreaKind::Bit;
    int first = 0;
    int count = 0;      // elements
    int bitBase = -1;   // packed bits: bit areas, the done bits of timers/counters
    int wordBase = -1;  // values: word/channel areas, timer/counter current values
    int setBase = -1;   // timer/counter set values
    int stateBase = -1; // timer/counter element state (engine side), one per element
    int wordBits = 16;
    bool retentive = false;
    bool presetsAddressable = false; // timers/counters: an area of the program holds the set values
    // Area::doubleWordsOf (PL110 VD, SMD): element n is the words wordBase + n - first (high)
    // and the one after it (low) of another area; it has no words of its own.
    bool doubleWords = false;
};

class MemoryLayout {
public:
    explicit MemoryLayout(const Target &target);

    const Target &target() const { return *m_target; }
    int wordCount() const { return m_words; }
    int elementStateCount() const { return m_states; }
    const AreaLayout &area(int index) const { return m_areas[static_cast<std::size_t>(index)]; }
    int areaCount() const { return static_cast<int>(m_areas.size()); }

    // -1 / invalid when the address does not name such a thing in this layout.
    BitRef bit(const Address &address) const;
    int word(const Address &address) const;         // value (timer/counter: current value)
    int setValueWord(const Address &address) const; // timer/counter set value
    int elementState(const Address &address) const; // timer/counter state slot
    // Whether the program reads and writes this timer's/counter's set value as a word
    // (Area::presetsOf): its constant preset is then loaded there, not read from the step.
    bool presetAddressable(const Address &address) const;
    int wordBits(const Address &address) const;
    // The value of a word device in `words` (an image in this layout's order): a double word
    // (doubleWords) joins its two words, high first; -1 words read 0.
    std::int32_t value(const std::vector<std::int32_t> &words, const Address &address) const;

private:
    bool inRange(const Address &address) const;

    const Target *m_target;
    std::vector<AreaLayout> m_areas;
    int m_words = 0;
    int m_states = 0;
};

// Sign-extends / wraps a value to the width of its area (16 or 32 bits, two's complement).
inline std::int32_t wrapToWidth(std::int64_t value, int bits) {
    if (bits >= 32)
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(value));
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(value));
}

} // namespace rung::model
