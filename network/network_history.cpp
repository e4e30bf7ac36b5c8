#include "network/network_history.h"

#include "network/network.h"
#include "network/station.h"
#include "simulator/engine.h"

#include <algorithm>

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

// Appends (index, value) for every word of `now` that differs from `old`, and copies it into
// `old`. A block of 64 words is compared in one pass of XOR and OR, which the compiler turns
// into wide vector instructions (AVX2 where the processor has it: the function is compiled
// twice, chosen when the program loads); a block that differs is looked at 8 words at a time
// the same way, and those 8 written out without a branch a word. Comparing every station's
// image is most of the recording's cost (BM_NetworkHistoryRatio, docs/performance.md): this
// is about 3 instructions a 32 bytes; a memcmp a block and the loop around it were about 8.
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
void appendChangedWords(std::int32_t *old, const std::int32_t *now, std::size_t n,
                        std::vector<std::uint32_t> &changes) {
    constexpr std::size_t kBlock = 64;
    constexpr std::size_t kGroup = 8;
    // Every word of [from, to) written as a pair, the cursor moved on only where it changed.
    auto walk = [&](std::size_t from, std::size_t to) {
        const std::size_t at = changes.size();
        changes.resize(at + 2 * (to - from));
        std::uint32_t *out = changes.data() + at;
        for (std::size_t k = from; k < to; ++k) {
            out[0] = static_cast<std::uint32_t>(k);
            out[1] = static_cast<std::uint32_t>(now[k]);
            out += old[k] != now[k] ? 2 : 0;
            old[k] = now[k];
        }
        changes.resize(static_cast<std::size_t>(out - changes.data()));
    };
    std::size_t b = 0;
    for (; b + kBlock <= n; b += kBlock) {
        if (!wordsDiffer<kBlock>(old + b, now + b)) [[likely]]
            continue;
        for (std::size_t g = b; g < b + kBlock; g += kGroup)
            if (wordsDiffer<kGroup>(old + g, now + g))
                walk(g, g + kGroup);
    }
    walk(b, n);
}

constexpr std::uint32_t kRun = 0x80000000u; // a word change's index: a run follows

// (index, value) pairs, indices rising, as Instant::changes keeps them: three or more
// neighbours as one run.
void encodeWordChanges(const std::vector<std::uint32_t> &pairs,
                       std::vector<std::uint32_t> &changes) {
    const std::size_t n = pairs.size();
    const std::size_t at = changes.size();
    changes.resize(at + n); // a run never takes more than its pairs
    const std::uint32_t *in = pairs.data();
    std::uint32_t *out = changes.data() + at;
    for (std::size_t i = 0; i < n;) {
        std::size_t e = i + 2; // the run [i, e) of neighbours
        while (e < n && in[e] == in[e - 2] + 1)
            e += 2;
        if (e - i < 6) {
            for (std::size_t k = i; k < e; ++k)
                *out++ = in[k];
        } else {
            *out++ = in[i] | kRun;
            *out++ = static_cast<std::uint32_t>((e - i) / 2);
            for (std::size_t k = i + 1; k < e; k += 2)
                *out++ = in[k];
        }
        i = e;
    }
    changes.resize(static_cast<std::size_t>(out - changes.data()));
}

// Calls f(index, value) for each word change of one station's part from c[p] (its length
// first), and leaves p after it.
template <typename F>
void forEachWordChange(const std::vector<std::uint32_t> &c, std::size_t &p, F f) {
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
void skipStation(const std::vector<std::uint32_t> &c, std::size_t &p) {
    p += 4;
    p += 1 + std::size_t(c[p]);
    p += 1 + std::size_t(c[p]);
}

} // namespace

struct NetworkHistory::Key {
    std::vector<std::int32_t> words;
    // The forced bits, a mask and a value a word, kept for the words that have any: (index,
    // mask, value) each (a key of the whole image would be three times its words).
    std::vector<std::uint32_t> forces;
    std::size_t forceWords = 0;     // the size of the snapshot's forceMask and forceValue
    std::vector<std::uint8_t> flow; // empty: power flow not recorded then
    std::size_t bytes() const {
        return sizeof(Key) + words.size() * 4 + forces.size() * 4 + flow.size();
    }
};

// The worker's copy of every station as the last instant left it.
struct NetworkHistory::Worker {
    struct Station {
        std::vector<std::int32_t> words;
        std::vector<std::uint32_t> forceMask;
        std::vector<std::uint32_t> forceValue;
        std::vector<std::uint8_t> flow;
        bool flowRecorded = false;
    };
    std::vector<Station> stations;
    std::size_t sinceKey = 0;           // instants since the last key
    std::size_t changeBytes = 0;        // bytes of changes since the last key
    std::size_t keyBytes = 0;           // what a key of every station costs
    std::vector<std::uint32_t> changes; // reused between instants
    std::vector<std::uint32_t> pairs;   // one station's (index, value), reused
};

std::size_t NetworkHistory::Instant::bytes() const {
    std::size_t n = sizeof(Instant) + statistics.capacity() * sizeof(model::ScanStatistics) +
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
    m_worker->sinceKey = m_limits.keyEvery; // the first instant is a key
    record(network, true);
}

void NetworkHistory::record(const Network &network, bool commands) {
    Worker &w = *m_worker;
    const auto &stations = network.stations();
    if (stations.size() != w.stations.size())
        return; // not the network start() was given
    Instant instant;
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
        // Forced bits change only by a command, between two slices.
        if (commands) {
            const model::Snapshot s = engine.snapshot();
            if (s.forceMask != prev.forceMask || s.forceValue != prev.forceValue) {
                prev.forceMask = s.forceMask;
                prev.forceValue = s.forceValue;
                key = true;
            }
        }
        // The words that changed (appendChangedWords).
        const std::span<const std::int32_t> words = engine.words();
        if (prev.words.size() != words.size()) {
            prev.words.assign(words.begin(), words.end());
            key = true;
        }
        w.pairs.clear();
        appendChangedWords(prev.words.data(), words.data(), words.size(), w.pairs);
        const std::size_t countAt = changes.size();
        changes.push_back(0);
        encodeWordChanges(w.pairs, changes);
        changes[countAt] = static_cast<std::uint32_t>(changes.size() - countAt - 1);
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
        std::size_t keyBytes = 0;
        instant.keys.reserve(stations.size());
        for (const auto &station : stations)
            instant.statistics.push_back(station->engine().statistics());
        for (const Worker::Station &s : w.stations) {
            auto k = std::make_shared<Key>();
            k->words = s.words;
            k->forceWords = s.forceMask.size();
            const std::uint32_t *mask = s.forceMask.data();
            for (std::size_t b = 0; b < s.forceMask.size(); b += 64) {
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
            keyBytes += k->bytes();
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
    s.words = key.words;
    s.forceMask.assign(key.forceWords, 0);
    s.forceValue.assign(key.forceWords, 0);
    for (std::size_t f = 0; f < key.forces.size(); f += 3) {
        s.forceMask[key.forces[f]] = key.forces[f + 1];
        s.forceValue[key.forces[f]] = key.forces[f + 2];
    }
    s.statistics = m_instants[k].statistics[station];
    std::vector<std::uint8_t> flow = key.flow;
    for (std::size_t j = k + 1; j <= instant; ++j) {
        const std::vector<std::uint32_t> &c = m_instants[j].changes;
        std::size_t p = 0;
        for (std::size_t t = 0; t < station; ++t)
            skipStation(c, p);
        if (j == instant) {
            s.statistics.scans = c[p] | quint64(c[p + 1]) << 32;
            s.statistics.timeMs = static_cast<qint64>(c[p + 2] | quint64(c[p + 3]) << 32);
        }
        p += 4;
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
    if (word >= m_instants[k].keys[station]->words.size())
        return out;
    WordValue now;
    for (std::size_t j = k; j < m_instants.size(); ++j) {
        const Instant &instant = m_instants[j];
        now.us = instant.us;
        if (!instant.keys.empty()) {
            now.value = instant.keys[station]->words[word];
            now.scans = instant.statistics[station].scans;
            now.timeMs = instant.statistics[station].timeMs;
        } else {
            const std::vector<std::uint32_t> &c = instant.changes;
            std::size_t p = 0;
            for (std::size_t t = 0; t < station; ++t)
                skipStation(c, p);
            now.scans = c[p] | quint64(c[p + 1]) << 32;
            now.timeMs = static_cast<qint64>(c[p + 2] | quint64(c[p + 3]) << 32);
            p += 4;
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
