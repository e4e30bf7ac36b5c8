#pragma once

// The words of a station's image written between its scans: by a link's exchange (CPU Link,
// Parallel Link, shared_link.cpp) or a slave's side answering a master's write (EngineImage),
// bridged or not. The network's history (network_history.h) compares these and the words the
// station's program can write (simulator/scan_writes.h) after a slice, not the whole image:
// every writer of a station's image other than its scan and the session's commands (after
// which the history compares everything) marks here what it wrote.
//
// Kept as a bit a block of 64 words (a mark is a few instructions: a link marks the same
// areas at every exchange, whether a history records or not), which the history compares
// whole. One thread: the network's.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rung::network {

class ImageWrites {
public:
    static constexpr std::size_t kBlockWords = 64;

    // [first, first + count) were written.
    void mark(std::size_t first, std::size_t count) { addBlocks(m_blocks, first, count); }
    // The blocks of a bitmap addBlocks made were written (a link's share: its runs and bits
    // worked out once).
    void mark(const std::vector<std::uint64_t> &blocks) {
        if (blocks.size() > m_blocks.size())
            m_blocks.resize(blocks.size(), 0);
        for (std::size_t i = 0; i < blocks.size(); ++i)
            m_blocks[i] |= blocks[i];
    }
    // The blocks of [first, first + count) set in `blocks` (a bit a block, as kept here).
    static void addBlocks(std::vector<std::uint64_t> &blocks, std::size_t first,
                          std::size_t count) {
        if (count == 0)
            return;
        const std::size_t from = first / kBlockWords;
        const std::size_t to = (first + count - 1) / kBlockWords;
        if (to / 64 >= blocks.size())
            blocks.resize(to / 64 + 1, 0);
        for (std::size_t b = from; b <= to; ++b)
            blocks[b / 64] |= std::uint64_t(1) << (b % 64);
    }
    // Any word may have been written; `forces`: forced bits too (a slave's force or release).
    void markAll(bool forces) {
        m_all = true;
        m_forces = m_forces || forces;
    }

    bool all() const { return m_all; }
    bool forces() const { return m_forces; }
    // Calls f(first, end) for each run of blocks marked, in words, rising.
    template <typename F> void forEachRange(F f) const {
        for (std::size_t i = 0; i < m_blocks.size(); ++i) {
            std::uint64_t bits = m_blocks[i];
            while (bits != 0) {
                const int from = std::countr_zero(bits);
                const int ones = std::countr_one(bits >> from);
                const std::size_t block = i * 64 + static_cast<std::size_t>(from);
                f(block * kBlockWords, (block + static_cast<std::size_t>(ones)) * kBlockWords);
                bits = ones + from >= 64 ? 0 : bits & (~std::uint64_t(0) << (from + ones));
            }
        }
    }
    // The history took them.
    void clear() {
        for (std::uint64_t &b : m_blocks)
            b = 0;
        m_all = false;
        m_forces = false;
    }

private:
    std::vector<std::uint64_t> m_blocks; // bit b of word i: block 64 i + b
    bool m_all = false;
    bool m_forces = false;
};

} // namespace rung::network
