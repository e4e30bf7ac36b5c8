#include "network/network_history.h"

#include "network/network.h"
#include "network/station.h"
#include "simulator/engine.h"
#include "simulator/scan_writes.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <span>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rung::network {

namespace {

// Whether N words differ, in one pass the compiler vectorizes (inlined into the clones below,
// it takes their instructions).
template <std::size_t N>
[[gnu::always_inline]] inline bool wordsDiffer(const std::int32_t *a, const std::int32_t *b) {
    std::uint32_t d = 0;
    for (std::size_t k = 0; k < N; ++k)
        d |= static_cast<std::uint32_t>(a[k] ^ b[k]);
    return d != 0;
}

constexpr std::uint32_t kRun = 0x80000000u; // a word change's index: a run follows

// The most appendChangedWords writes for an image of n words: a pair a word, or a run of one
// (three words) for the last word of a group of 8 and a pair for each other; and 8 more, as a
// run's values are copied 8 words at a time (encodeGroup).
constexpr std::size_t encodedBound(std::size_t n) {
    return 2 * n + n / 8 + 16;
}

// Where appendChangedWords writes: the end of what it wrote, and the run open there.
struct Encoder {
    std::uint32_t *out = nullptr;
    std::uint32_t *run = nullptr; // the count of the run open at the end of out (or none)
    std::size_t runEnd = 0;       // the word after it
};

// A group of `length` (at most 8) words from g of which some differ: which ones as a mask,
// their changes written (runs found in the mask), `old` updated. L: the length when it is
// known (8: the compare and the copies unroll), else 0. Out of line: inlined into
// appendChangedWords, the compiler shared its loads with the compare of the groups that do not
// differ, which left the vector registers (5 times the instructions).
template <std::size_t L>
[[gnu::noinline]] void encodeGroup(Encoder &e, std::int32_t *old, const std::int32_t *now,
                                   std::size_t g, std::size_t length) {
    if constexpr (L != 0)
        length = L;
    std::uint32_t changed = 0;
#if defined(__SSE2__)
    if constexpr (L == 8) {
        // Which of the 8 differ: two compares and their sign masks (the loop below, which the
        // compiler left scalar, was a third of this function's instructions).
        const auto load = [](const std::int32_t *p) {
            return _mm_loadu_si128(reinterpret_cast<const __m128i *>(p));
        };
        const __m128i lo = _mm_cmpeq_epi32(load(old + g), load(now + g));
        const __m128i hi = _mm_cmpeq_epi32(load(old + g + 4), load(now + g + 4));
        const int same =
            _mm_movemask_ps(_mm_castsi128_ps(lo)) | (_mm_movemask_ps(_mm_castsi128_ps(hi)) << 4);
        changed = ~static_cast<std::uint32_t>(same) & 0xffu;
    } else
#endif
    {
        for (std::size_t k = 0; k < length; ++k)
            changed |= static_cast<std::uint32_t>(old[g + k] != now[g + k]) << k;
    }
    // The group's words and 8 zeros after them: a run's values are copied 8 words at a time
    // from here (the words after the run are written over next, or left beyond the end). A
    // copy of `count` words called the library's memcpy: a third of the recording's
    // instructions in BM_NetworkHistoryRatio/1.
    std::int32_t group[16] = {};
    if constexpr (L != 0)
        std::memcpy(group, now + g, L * sizeof(std::int32_t));
    while (changed != 0) {
        const int from = std::countr_zero(changed);
        const int ones = std::countr_one(changed >> from);
        changed &= ~(((1u << ones) - 1u) << from);
        const std::size_t first = g + static_cast<std::size_t>(from);
        const auto count = static_cast<std::size_t>(ones);
        if (e.run && e.runEnd == first) {
            *e.run += static_cast<std::uint32_t>(count);
        } else if (count == 1 && (first % 8) != 7) {
            e.out[0] = static_cast<std::uint32_t>(first);
            e.out[1] = static_cast<std::uint32_t>(now[first]);
            e.out += 2;
            e.run = nullptr;
            continue;
        } else {
            e.out[0] = static_cast<std::uint32_t>(first) | kRun;
            e.out[1] = static_cast<std::uint32_t>(count);
            e.run = e.out + 1;
            e.out += 2;
        }
        if constexpr (L != 0)
            std::memcpy(e.out, group + from, L * sizeof(std::uint32_t));
        else
            std::memcpy(e.out, now + first, count * sizeof(std::uint32_t));
        e.out += count;
        e.runEnd = first + count;
    }
    std::memcpy(old + g, now + g, length * sizeof(std::int32_t));
}

// Writes at `out` the words of `now` in the ranges (cut at n) that differ from `old`, encoded
// as Instant::changes keeps them, copies them into `old`, and returns the end of what it wrote
// (`out` has room for encodedBound(n)). A changed word is (index, value); neighbours that
// changed, two or more, or a changed word that ends a group of 8 (the next group may go on
// with it), are a run (first | kRun, count, values), which goes on across groups and ranges as
// long as the words that changed follow each other: a busy program's registers side by side
// cost a word each.
// A block of 64 words is compared in one pass of XOR and OR, which the compiler turns into
// wide vector instructions (AVX2 where the processor has it: the function is compiled twice,
// chosen when the program loads); a block that differs, and a range shorter than a block
// (what a program writes), is looked at 8 words at a time the same way (encodeGroup for a
// group that differs: a group that changed whole is 8 values copied onto the run). Comparing
// every station's image was most of the recording's cost (BM_NetworkHistoryRatio,
// docs/performance.md); writing each word of a changed group as a pair without a branch, and
// finding the runs in the pairs afterwards, was most of what was left with busy programs.
// Not under a sanitizer: the clones' resolver runs while the dynamic linker relocates the
// program, before the sanitizer's runtime is up, and ThreadSanitizer's instrumentation of it
// crashed there (CI, test_network under TSan).
#if defined(__has_feature)
#if __has_feature(thread_sanitizer) || __has_feature(address_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
#define RUNG_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
#define RUNG_SANITIZED 1
#endif
#if defined(__x86_64__) && (defined(__clang__) || defined(__GNUC__)) && !defined(RUNG_SANITIZED)
[[gnu::target_clones("avx2", "default")]]
#endif
std::uint32_t *
appendChangedWords(std::int32_t *old, const std::int32_t *now,
                   const std::pair<std::size_t, std::size_t> *ranges, std::size_t count,
                   std::size_t n, std::uint32_t *out) {
    constexpr std::size_t kBlock = 64;
    constexpr std::size_t kGroup = 8;
    Encoder e{out};
    for (std::size_t r = 0; r < count; ++r) {
        const std::size_t to = std::min(ranges[r].second, n);
        std::size_t b = ranges[r].first;
        for (; b + kBlock <= to; b += kBlock) {
            if (!wordsDiffer<kBlock>(old + b, now + b)) [[likely]]
                continue;
            for (std::size_t g = b; g < b + kBlock; g += kGroup)
                if (wordsDiffer<kGroup>(old + g, now + g))
                    encodeGroup<kGroup>(e, old, now, g, kGroup);
        }
        for (; b + kGroup <= to; b += kGroup)
            if (wordsDiffer<kGroup>(old + b, now + b))
                encodeGroup<kGroup>(e, old, now, b, kGroup);
        if (b < to && std::memcmp(old + b, now + b, (to - b) * sizeof(std::int32_t)) != 0)
            encodeGroup<0>(e, old, now, b, to - b); // the image's last words
    }
    return e.out;
}

// The ranges widened to whole groups of 8 words (appendChangedWords compares a group in one
// pass), within the image's n words, and joined where they then touch.
void alignRanges(simulator::WordRanges &ranges, std::size_t n) {
    simulator::WordRanges out;
    for (auto [b, e] : ranges) {
        b &= ~std::size_t(7);
        e = std::min(n, (e + 7) & ~std::size_t(7));
        if (!out.empty() && b <= out.back().second)
            out.back().second = std::max(out.back().second, e);
        else if (b < e)
            out.emplace_back(b, e);
    }
    ranges = std::move(out);
}

// The words before a station's word changes in Instant::changes: its scans, its virtual ms and
// its ports' last communication, two words each.
constexpr std::size_t kStationHead = 6;

// Calls f(index, value) for each word change of one station's part from c[p] (its length
// first), and leaves p after it.
template <typename C, typename F> void forEachWordChange(const C &c, std::size_t &p, F f) {
    const std::size_t end = p + 1 + c[p];
    ++p;
    while (p < end) {
        if (c[p] & kRun) {
            const std::size_t first = c[p] & ~kRun;
            const std::size_t count = c[p + 1];
            for (std::size_t k = 0; k < count; ++k)
                f(first + k, static_cast<std::int32_t>(c[p + 2 + k]));
            p += 2 + count;
        } else {
            f(std::size_t(c[p]), static_cast<std::int32_t>(c[p + 1]));
            p += 2;
        }
    }
}

// p from one station's part of Instant::changes to the next one's.
template <typename C> void skipStation(const C &c, std::size_t &p) {
    p += kStationHead;
    p += 1 + std::size_t(c[p]);
    p += 1 + std::size_t(c[p]);
}

} // namespace

struct NetworkHistory::Key {
    explicit Key(HistoryArena *arena)
        : held(HistoryAllocator<std::uint64_t>(arena))
        , words(HistoryAllocator<std::int32_t>(arena)) {}
    // The image's words, kept for the blocks of 64 that hold any word not 0 (a program uses a
    // few hundred of a VB's ten thousand; a key of every word was half of what a history
    // wrote, all of it fresh memory): held has a bit a block (bit b of held[i]: block 64 i +
    // b), words the blocks held, in order (the image's last block as long as it is).
    std::size_t size = 0; // words in the image
    std::vector<std::uint64_t, HistoryAllocator<std::uint64_t>> held;
    std::vector<std::int32_t, HistoryAllocator<std::int32_t>> words;
    static constexpr std::size_t kBlock = 64;

    // The key of the image `image`.
    void take(std::span<const std::int32_t> image) {
        size = image.size();
        const std::size_t blocks = (size + kBlock - 1) / kBlock;
        held.assign((blocks + 63) / 64, 0);
        std::size_t kept = 0;
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t first = b * kBlock;
            const std::size_t n = std::min(kBlock, size - first);
            bool any = false;
            if (n == kBlock) {
                any = wordsDiffer<kBlock>(image.data() + first, kZeros.data());
            } else {
                for (std::size_t i = 0; i < n; ++i)
                    any = any || image[first + i] != 0;
            }
            if (any) {
                held[b / 64] |= std::uint64_t(1) << (b % 64);
                kept += n;
            }
        }
        words.reserve(kept);
        forEachBlock([&](std::size_t first, std::size_t n, std::size_t) {
            words.insert(words.end(), image.begin() + std::ptrdiff_t(first),
                         image.begin() + std::ptrdiff_t(first + n));
        });
    }
    // Calls f(first word, its count, where it is in words) for each block held, rising.
    template <typename F> void forEachBlock(F f) const {
        std::size_t at = 0;
        for (std::size_t i = 0; i < held.size(); ++i)
            for (std::uint64_t bits = held[i]; bits != 0; bits &= bits - 1) {
                const std::size_t first =
                    (i * 64 + static_cast<std::size_t>(std::countr_zero(bits))) * kBlock;
                const std::size_t n = std::min(kBlock, size - first);
                f(first, n, at);
                at += n;
            }
    }
    // The image as the key keeps it.
    template <typename V> void copyTo(V &out) const {
        out.assign(size, 0);
        forEachBlock([&](std::size_t first, std::size_t n, std::size_t at) {
            std::copy_n(words.begin() + std::ptrdiff_t(at), n, out.begin() + std::ptrdiff_t(first));
        });
    }
    // One word of it (index < size).
    std::int32_t word(std::size_t index) const {
        const std::size_t b = index / kBlock;
        const std::uint64_t bit = std::uint64_t(1) << (b % 64);
        if ((held[b / 64] & bit) == 0)
            return 0;
        std::size_t rank = static_cast<std::size_t>(std::popcount(held[b / 64] & (bit - 1)));
        for (std::size_t i = 0; i < b / 64; ++i)
            rank += static_cast<std::size_t>(std::popcount(held[i]));
        return words[rank * kBlock + index % kBlock];
    }
    static constexpr std::array<std::int32_t, kBlock> kZeros{};
    // The forced bits, a mask and a value a word, kept for the words that have any: (index,
    // mask, value) each (a key of the whole image would be three times its words).
    std::vector<std::uint32_t> forces;
    std::size_t forceWords = 0;     // the size of the snapshot's forceMask and forceValue
    std::vector<std::uint8_t> flow; // empty: power flow not recorded then
    std::size_t bytes() const {
        return sizeof(Key) + held.size() * 8 + words.size() * 4 + forces.size() * 4 + flow.size();
    }
};

// The worker's copy of every station as the last instant left it.
struct NetworkHistory::Worker {
    struct Station {
        std::vector<std::int32_t> words;
        std::vector<std::uint32_t> forceMask;
        std::vector<std::uint32_t> forceValue;
        bool forced = false; // any bit of forceMask set (a key looks for them only then)
        std::vector<std::uint8_t> flow;
        bool flowRecorded = false;
        // The words a scan of its program can write (simulator/scan_writes.h); none: any.
        const simulator::Program *program = nullptr;
        std::optional<simulator::WordRanges> scanWrites;
    };
    std::vector<Station> stations;
    std::size_t sinceKey = 0;           // instants since the last key
    std::size_t changeBytes = 0;        // bytes of changes since the last key
    std::size_t keyBytes = 0;           // what a key of every station costs
    std::vector<std::uint32_t> changes; // reused between instants
    // One station's word changes, encoded (appendChangedWords): room for encodedBound words.
    std::unique_ptr<std::uint32_t[]> encoded;
    simulator::WordRanges written; // one station's ranges marked written, reused
    std::size_t encodedSize = 0;
};

std::size_t NetworkHistory::Instant::bytes() const {
    std::size_t n = sizeof(Instant) + statistics.capacity() * sizeof(model::ScanStatistics) +
                    communicated.capacity() * sizeof(qint64) +
                    changes.capacity() * sizeof(std::uint32_t) +
                    keys.capacity() * sizeof(std::shared_ptr<const Key>);
    for (const auto &k : keys)
        n += k ? k->bytes() : 0;
    return n;
}

NetworkHistory::NetworkHistory()
    : NetworkHistory(Limits{}) {}

NetworkHistory::NetworkHistory(Limits limits)
    : m_limits(limits)
    , m_worker(std::make_unique<Worker>()) {
    m_limits.keyEvery = std::max<std::size_t>(1, m_limits.keyEvery);
}

NetworkHistory::~NetworkHistory() = default;

void NetworkHistory::start(const Network &network) {
    std::vector<std::shared_ptr<const model::MemoryLayout>> layouts;
    for (const auto &s : network.stations())
        layouts.push_back(s->engine().program().layout);
    {
        std::lock_guard lock(m_mutex);
        m_instants.clear();
        m_bytes = 0;
        m_keys = 0;
        m_layouts = std::move(layouts);
        ++m_generation;
    }
    *m_worker = Worker{};
    m_worker->stations.resize(network.stations().size());
    for (const auto &s : network.stations())
        s->written().clear();               // what was written before is in the first instant
    m_worker->sinceKey = m_limits.keyEvery; // the first instant is a key
    record(network, true);
}

void NetworkHistory::record(const Network &network, bool commands) {
    Worker &w = *m_worker;
    const auto &stations = network.stations();
    if (stations.size() != w.stations.size())
        return; // not the network start() was given
    Instant instant(m_arena.get());
    instant.us = network.nowUs();
    bool key = w.sinceKey >= m_limits.keyEvery || w.changeBytes >= w.keyBytes;
    std::vector<std::uint32_t> &changes = w.changes;
    changes.clear();
    for (std::size_t i = 0; i < stations.size(); ++i) {
        const simulator::Engine &engine = stations[i]->engine();
        Worker::Station &prev = w.stations[i];
        const model::ScanStatistics &statistics = engine.statistics();
        const auto scans = static_cast<quint64>(statistics.scans);
        const auto ms = static_cast<quint64>(statistics.timeMs);
        changes.push_back(static_cast<std::uint32_t>(scans));
        changes.push_back(static_cast<std::uint32_t>(scans >> 32));
        changes.push_back(static_cast<std::uint32_t>(ms));
        changes.push_back(static_cast<std::uint32_t>(ms >> 32));
        Station &station = *stations[i];
        const auto communicated = static_cast<quint64>(station.communicatedUs());
        changes.push_back(static_cast<std::uint32_t>(communicated));
        changes.push_back(static_cast<std::uint32_t>(communicated >> 32));
        ImageWrites &written = station.written();
        // Forced bits change only by a command, between two slices, or a slave's force.
        if (commands || written.forces()) {
            const model::Snapshot s = engine.snapshot();
            if (s.forceMask != prev.forceMask || s.forceValue != prev.forceValue) {
                prev.forceMask = s.forceMask;
                prev.forceValue = s.forceValue;
                prev.forced = std::any_of(s.forceMask.begin(), s.forceMask.end(),
                                          [](std::uint32_t m) { return m != 0; });
                key = true;
            }
        }
        // The words that changed (appendChangedWords): those a scan of the program can write
        // and those written between scans (Station::written), or every word after commands,
        // after a write the station could not say where, and when the program changed (an
        // online edit taking over at a scan's END: the scan ran the program before).
        const simulator::Program *program = &engine.program();
        bool all = commands || written.all() || program != prev.program;
        if (program != prev.program || commands) {
            prev.program = program;
            prev.scanWrites = simulator::scanWrites(*program);
            if (prev.scanWrites)
                alignRanges(*prev.scanWrites, engine.words().size());
        }
        all = all || !prev.scanWrites;
        const std::span<const std::int32_t> words = engine.words();
        if (prev.words.size() != words.size()) {
            prev.words.assign(words.begin(), words.end());
            key = true;
        }
        if (w.encodedSize < encodedBound(words.size())) {
            w.encodedSize = encodedBound(words.size());
            w.encoded = std::make_unique_for_overwrite<std::uint32_t[]>(w.encodedSize);
        }
        std::uint32_t *const encoded = w.encoded.get();
        std::uint32_t *out = encoded;
        if (all) {
            const std::pair<std::size_t, std::size_t> whole{0, words.size()};
            out = appendChangedWords(prev.words.data(), words.data(), &whole, 1, words.size(), out);
        } else {
            out = appendChangedWords(prev.words.data(), words.data(), prev.scanWrites->data(),
                                     prev.scanWrites->size(), words.size(), out);
            // A word both name is written once: the second compare finds it equal.
            w.written.clear();
            written.forEachRange(
                [&](std::size_t b, std::size_t e) { w.written.emplace_back(b, e); });
            out = appendChangedWords(prev.words.data(), words.data(), w.written.data(),
                                     w.written.size(), words.size(), out);
        }
        written.clear();
        changes.push_back(static_cast<std::uint32_t>(out - encoded));
        changes.insert(changes.end(), encoded, out);
        // The power flow of the station whose ladder is on screen (the others record none).
        const bool flowRecorded = engine.powerFlowRecording();
        const std::vector<std::uint8_t> &flow = engine.powerFlow();
        const std::size_t flowAt = changes.size();
        changes.push_back(0);
        if (flowRecorded != prev.flowRecorded ||
            (flowRecorded && flow.size() != prev.flow.size())) {
            prev.flowRecorded = flowRecorded;
            if (flowRecorded)
                prev.flow = flow;
            else
                prev.flow.clear();
            key = true;
        } else if (flowRecorded) {
            for (std::size_t k = 0; k < flow.size(); ++k)
                if ((flow[k] != 0) != (prev.flow[k] != 0)) {
                    prev.flow[k] = flow[k];
                    changes.push_back(static_cast<std::uint32_t>(k));
                }
        }
        changes[flowAt] = static_cast<std::uint32_t>(changes.size() - flowAt - 1);
    }
    if (key) {
        // The next key when the changes since this one cost as much as a key of every word
        // (a rebuild then applies at most about an image's bytes of changes to the key).
        std::size_t keyBytes = 0;
        instant.keys.reserve(stations.size());
        for (const auto &station : stations) {
            instant.statistics.push_back(station->engine().statistics());
            instant.communicated.push_back(station->communicatedUs());
        }
        for (const Worker::Station &s : w.stations) {
            auto k = std::make_shared<Key>(m_arena.get());
            k->take(s.words);
            k->forceWords = s.forceMask.size();
            const std::uint32_t *mask = s.forceMask.data();
            // Read only when some bit is forced: the mask is a word an image word, and
            // reading it whole made a key twice the memory traffic of its copy.
            for (std::size_t b = 0; s.forced && b < s.forceMask.size(); b += 64) {
                const std::size_t e = std::min(s.forceMask.size(), b + 64);
                std::uint32_t any = 0; // a block without forced bits at vector speed
                for (std::size_t i = b; i < e; ++i)
                    any |= mask[i];
                if (any == 0)
                    continue;
                for (std::size_t i = b; i < e; ++i)
                    if (mask[i] != 0)
                        k->forces.insert(k->forces.end(),
                                         {static_cast<std::uint32_t>(i), mask[i], s.forceValue[i]});
            }
            k->flow = s.flow;
            keyBytes +=
                s.words.size() * sizeof(std::int32_t) + k->forces.size() * 4 + k->flow.size();
            instant.keys.push_back(std::move(k));
        }
        w.keyBytes = keyBytes;
        w.sinceKey = 0;
        w.changeBytes = 0;
    } else {
        instant.changes.assign(changes.begin(), changes.end());
        w.changeBytes += instant.changes.size() * sizeof(std::uint32_t);
        ++w.sinceKey;
    }
    append(std::move(instant));
}

void NetworkHistory::append(Instant instant) {
    const std::size_t bytes = instant.bytes();
    const bool key = !instant.keys.empty();
    std::lock_guard lock(m_mutex);
    m_instants.push_back(std::move(instant));
    m_bytes += bytes;
    m_keys += key ? 1 : 0;
    // Over the budget: the oldest key goes with the changes that run from it, while another
    // key stays.
    while (m_bytes > m_limits.maxBytes && m_keys > 1) {
        do {
            m_bytes -= m_instants.front().bytes();
            m_keys -= m_instants.front().keys.empty() ? 0 : 1;
            m_instants.pop_front();
        } while (!m_instants.empty() && m_instants.front().keys.empty());
    }
}

NetworkHistory::Window NetworkHistory::window() const {
    std::lock_guard lock(m_mutex);
    Window w;
    if (m_instants.empty())
        return w;
    w.firstUs = m_instants.front().us;
    w.lastUs = m_instants.back().us;
    w.instants = m_instants.size();
    w.keys = m_keys;
    w.bytes = m_bytes;
    return w;
}

std::size_t NetworkHistory::stationCount() const {
    std::lock_guard lock(m_mutex);
    return m_layouts.size();
}

std::ptrdiff_t NetworkHistory::find(qint64 us) const {
    const auto after = std::upper_bound(m_instants.begin(), m_instants.end(), us,
                                        [](qint64 t, const Instant &i) { return t < i.us; });
    return (after - m_instants.begin()) - 1;
}

std::optional<qint64> NetworkHistory::instantAt(qint64 us) const {
    std::lock_guard lock(m_mutex);
    const std::ptrdiff_t i = find(us);
    if (i < 0)
        return std::nullopt;
    return m_instants[static_cast<std::size_t>(i)].us;
}

model::Snapshot NetworkHistory::rebuild(std::size_t station, std::size_t instant) const {
    std::size_t k = instant;
    while (m_instants[k].keys.empty())
        --k; // the front is always a key
    const Key &key = *m_instants[k].keys[station];
    model::Snapshot s;
    s.layout = m_layouts[station];
    key.copyTo(s.words);
    s.forceMask.assign(key.forceWords, 0);
    s.forceValue.assign(key.forceWords, 0);
    for (std::size_t f = 0; f < key.forces.size(); f += 3) {
        s.forceMask[key.forces[f]] = key.forces[f + 1];
        s.forceValue[key.forces[f]] = key.forces[f + 2];
    }
    s.statistics = m_instants[k].statistics[station];
    s.communicatedUs = m_instants[k].communicated[station];
    std::vector<std::uint8_t> flow = key.flow;
    for (std::size_t j = k + 1; j <= instant; ++j) {
        const auto &c = m_instants[j].changes;
        std::size_t p = 0;
        for (std::size_t t = 0; t < station; ++t)
            skipStation(c, p);
        if (j == instant) {
            s.statistics.scans = c[p] | quint64(c[p + 1]) << 32;
            s.statistics.timeMs = static_cast<qint64>(c[p + 2] | quint64(c[p + 3]) << 32);
            s.communicatedUs = static_cast<qint64>(c[p + 4] | quint64(c[p + 5]) << 32);
        }
        p += kStationHead;
        forEachWordChange(c, p,
                          [&](std::size_t index, std::int32_t value) { s.words[index] = value; });
        const std::size_t toggles = c[p++];
        for (std::size_t n = 0; n < toggles; ++n, ++p)
            flow[c[p]] = flow[c[p]] ? 0 : 1;
    }
    s.powerFlow.assign(flow.begin(), flow.end());
    return s;
}

std::optional<std::vector<model::Snapshot>> NetworkHistory::at(qint64 us) const {
    std::lock_guard lock(m_mutex);
    const std::ptrdiff_t i = find(us);
    if (i < 0)
        return std::nullopt;
    std::vector<model::Snapshot> out;
    for (std::size_t s = 0; s < m_layouts.size(); ++s)
        out.push_back(rebuild(s, static_cast<std::size_t>(i)));
    return out;
}

std::optional<model::Snapshot> NetworkHistory::stationAt(std::size_t station, qint64 us) const {
    std::lock_guard lock(m_mutex);
    const std::ptrdiff_t i = find(us);
    if (i < 0 || station >= m_layouts.size())
        return std::nullopt;
    return rebuild(station, static_cast<std::size_t>(i));
}

std::uint64_t NetworkHistory::generation() const {
    std::lock_guard lock(m_mutex);
    return m_generation;
}

std::vector<NetworkHistory::WordValue> NetworkHistory::wordValues(std::size_t station,
                                                                  std::size_t word, qint64 afterUs,
                                                                  WordValue *newest) const {
    std::vector<WordValue> out;
    std::lock_guard lock(m_mutex);
    if (station >= m_layouts.size())
        return out;
    const std::size_t first = static_cast<std::size_t>(find(afterUs) + 1);
    if (first >= m_instants.size())
        return out;
    // From the key at or before the first instant wanted (the front is always a key).
    std::size_t k = first;
    while (m_instants[k].keys.empty())
        --k;
    if (word >= m_instants[k].keys[station]->size)
        return out;
    WordValue now;
    for (std::size_t j = k; j < m_instants.size(); ++j) {
        const Instant &instant = m_instants[j];
        now.us = instant.us;
        if (!instant.keys.empty()) {
            now.value = instant.keys[station]->word(word);
            now.scans = instant.statistics[station].scans;
            now.timeMs = instant.statistics[station].timeMs;
        } else {
            const auto &c = instant.changes;
            std::size_t p = 0;
            for (std::size_t t = 0; t < station; ++t)
                skipStation(c, p);
            now.scans = c[p] | quint64(c[p + 1]) << 32;
            now.timeMs = static_cast<qint64>(c[p + 2] | quint64(c[p + 3]) << 32);
            p += kStationHead;
            forEachWordChange(c, p, [&](std::size_t index, std::int32_t value) {
                if (index == word)
                    now.value = value;
            });
        }
        if (j >= first && (out.empty() || out.back().value != now.value))
            out.push_back(now);
    }
    if (newest)
        *newest = now;
    return out;
}

} // namespace rung::network
