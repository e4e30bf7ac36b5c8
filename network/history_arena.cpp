#include "network/history_arena.h"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rung::network {

HistoryArena::~HistoryArena() {
    if (m_current)
        freeChunk(m_current);
    for (char *c : m_spare)
        freeChunk(c);
}

char *HistoryArena::newChunk() {
    char *chunk = nullptr;
    if (!m_spare.empty()) {
        chunk = m_spare.back();
        m_spare.pop_back();
    } else {
        chunk = static_cast<char *>(::operator new(kChunk, std::align_val_t(kChunk)));
        ++m_held;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        ::madvise(chunk, kChunk, MADV_HUGEPAGE); // a hint: without, 4 KB pages as before
#endif
    }
    new (chunk) Header{};
    return chunk;
}

void HistoryArena::freeChunk(char *chunk) {
    ::operator delete(chunk, std::align_val_t(kChunk));
    --m_held;
}

void HistoryArena::release(char *chunk) {
    if (m_spare.size() < kSpare)
        m_spare.push_back(chunk);
    else
        freeChunk(chunk);
}

void *HistoryArena::allocate(std::size_t bytes) {
    bytes = (bytes + 15) & ~std::size_t(15);
    if (bytes > kLarge)
        return ::operator new(bytes);
    if (!m_current || m_used + bytes > kChunk) {
        char *old = m_current;
        m_current = newChunk();
        m_used = kHeader;
        if (old && reinterpret_cast<Header *>(old)->live == 0)
            release(old);
    }
    void *p = m_current + m_used;
    m_used += bytes;
    ++reinterpret_cast<Header *>(m_current)->live;
    return p;
}

void HistoryArena::deallocate(void *p, std::size_t bytes) {
    bytes = (bytes + 15) & ~std::size_t(15);
    if (bytes > kLarge) {
        ::operator delete(p);
        return;
    }
    char *chunk = reinterpret_cast<char *>(reinterpret_cast<std::uintptr_t>(p) &
                                           ~static_cast<std::uintptr_t>(kChunk - 1));
    auto *h = reinterpret_cast<Header *>(chunk);
    if (--h->live == 0 && chunk != m_current)
        release(chunk);
}

} // namespace rung::network
