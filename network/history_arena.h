#pragma once

// Memory for the network's history (network_history.h): its instants (the deque's blocks),
// their changes and its keys' words, taken from chunks of 2 MB in the order they are
// recorded, in huge pages where the kernel gives them (madvise). A recording writes fresh
// memory all the time, and each 4 KB page of it first touched was a page fault: with busy
// programs most of the time BM_NetworkHistoryRatio/1 took beyond its instructions, and the
// deque's blocks from the heap 20 faults a block of 1,000 slices in /0 (docs/performance.md).
// A chunk goes when everything in it is freed (the oldest instants go first, so chunks empty
// in order); a few empty ones are kept for the next.
//
// One thread at a time: the one that records (allocations and the instants it drops).

#include <cstddef>
#include <vector>

namespace rung::network {

class HistoryArena {
public:
    static constexpr std::size_t kChunk = std::size_t(2) << 20;

    HistoryArena() = default;
    HistoryArena(const HistoryArena &) = delete;
    HistoryArena &operator=(const HistoryArena &) = delete;
    ~HistoryArena();

    void *allocate(std::size_t bytes);
    void deallocate(void *p, std::size_t bytes);
    // Chunks taken from the system and not given back (in use, current, kept for the next).
    std::size_t chunksHeld() const { return m_held; }

private:
    struct Header {
        std::size_t live = 0; // allocations not freed yet
    };
    static constexpr std::size_t kHeader = 64;
    static constexpr std::size_t kLarge = kChunk / 4; // more: from the heap
    static constexpr std::size_t kSpare = 4;
    char *newChunk();
    void release(char *chunk); // kept for the next, or freed
    void freeChunk(char *chunk);
    char *m_current = nullptr;
    std::size_t m_used = 0;
    std::vector<char *> m_spare;
    std::size_t m_held = 0;
};

// A std::vector's allocator from a HistoryArena.
template <typename T> struct HistoryAllocator {
    using value_type = T;
    HistoryArena *arena = nullptr;
    explicit HistoryAllocator(HistoryArena *a)
        : arena(a) {}
    template <typename U>
    HistoryAllocator(const HistoryAllocator<U> &other)
        : arena(other.arena) {}
    T *allocate(std::size_t n) { return static_cast<T *>(arena->allocate(n * sizeof(T))); }
    void deallocate(T *p, std::size_t n) { arena->deallocate(p, n * sizeof(T)); }
    template <typename U> bool operator==(const HistoryAllocator<U> &other) const {
        return arena == other.arena;
    }
};

} // namespace rung::network
