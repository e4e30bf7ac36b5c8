#pragma once

// Binary-coded decimal: a decimal digit a nibble. The CPM1 keeps its timer and counter set
// and present values this way and has BCD arithmetic (W353), Host Link carries timer and
// counter present values so, Vigor converts with BCD / BIN, and the watch table shows a word
// as BCD. One rule for all of them.

#include <cstdint>
#include <optional>

namespace rung::model {

// The word whose nibbles are the decimal digits of value >= 0 (1234 -> 0x1234); the caller
// checks that the digits fit its word.
constexpr std::int64_t toBcd(std::int64_t value) {
    std::int64_t word = 0;
    for (int shift = 0; value > 0 && shift < 64; value /= 10, shift += 4)
        word |= (value % 10) << shift;
    return word;
}

// The number a word's nibbles spell (0x1234 -> 1234); nullopt when a nibble is above 9 or
// the word is negative.
constexpr std::optional<std::int64_t> fromBcd(std::int64_t word) {
    if (word < 0)
        return std::nullopt;
    std::int64_t number = 0;
    for (std::int64_t unit = 1; word > 0; word >>= 4, unit *= 10) {
        if ((word & 0xF) > 9)
            return std::nullopt;
        number += (word & 0xF) * unit;
    }
    return number;
}

} // namespace rung::model
