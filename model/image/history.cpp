#include "model/image/history.h"

#include <algorithm>
#include <cstring>

namespace rung::model {

HistoryRecorder::HistoryRecorder(std::shared_ptr<const MemoryLayout> layout,
                                 std::size_t changesPerDevice)
    : m_layout(std::move(layout))
    , m_capacity(std::max<std::size_t>(2, changesPerDevice)) {}

HistoryRecorder::Device HistoryRecorder::deviceOf(const Address &address) const {
    Device d{address, -1, 0};
    // A double word (PL110 VD) is two words: the recorder follows one word per device.
    if (address.area >= 0 && address.area < m_layout->areaCount() &&
        m_layout->area(address.area).doubleWords)
        return d;
    // A bit of a word (D0.3) or a bit device (X0, a timer's done bit) records 0/1; a word,
    // a channel or a timer/counter (its current value) records the value.
    if (address.bit >= 0 || m_layout->word(address) < 0 ||
        m_layout->target().area(address.area).kind == AreaKind::Bit) {
        const BitRef r = m_layout->bit(address);
        if (r.valid()) {
            d.word = r.word;
            d.mask = r.mask;
        }
    } else {
        d.word = m_layout->word(address);
    }
    return d;
}

int HistoryRecorder::wordOf(const Address &address) const {
    return deviceOf(address).word;
}

std::int32_t HistoryRecorder::valueIn(const Address &address, std::int32_t word) const {
    return read(deviceOf(address), word);
}

bool HistoryRecorder::watch(const Address &address) {
    if (find(address) >= 0)
        return true;
    const Device d = deviceOf(address);
    if (d.word < 0)
        return false;
    m_index.emplace(address, static_cast<int>(m_devices.size()));
    m_devices.push_back(d);
    m_last.push_back(0);
    m_rings.emplace_back();
    m_fresh.push_back(static_cast<int>(m_devices.size()) - 1);
    rebuildWords();
    return true;
}

void HistoryRecorder::rebuildWords() {
    std::vector<std::pair<int, int>> byWord; // (word, device)
    byWord.reserve(m_devices.size());
    for (std::size_t i = 0; i < m_devices.size(); ++i)
        byWord.emplace_back(m_devices[i].word, static_cast<int>(i));
    std::sort(byWord.begin(), byWord.end());
    std::vector<int> oldIndex = std::move(m_wordIndex);
    std::vector<std::int32_t> oldValue = std::move(m_wordValue);
    m_wordIndex.clear();
    m_wordValue.clear();
    m_wordFirst.clear();
    m_wordDevices.clear();
    for (const auto &[word, device] : byWord) {
        if (m_wordIndex.empty() || m_wordIndex.back() != word) {
            m_wordIndex.push_back(word);
            const auto old = std::lower_bound(oldIndex.begin(), oldIndex.end(), word);
            m_wordValue.push_back(old != oldIndex.end() && *old == word
                                      ? oldValue[static_cast<std::size_t>(old - oldIndex.begin())]
                                      : 0);
            m_wordFirst.push_back(static_cast<int>(m_wordDevices.size()));
        }
        m_wordDevices.push_back(device);
    }
    m_wordFirst.push_back(static_cast<int>(m_wordDevices.size()));
    m_wordRuns.clear();
    for (std::size_t j = 0; j < m_wordIndex.size(); ++j) {
        if (!m_wordRuns.empty()) {
            WordRun &last = m_wordRuns.back();
            if (last.word + last.count == m_wordIndex[j]) {
                ++last.count;
                continue;
            }
        }
        m_wordRuns.push_back({m_wordIndex[j], static_cast<int>(j), 1});
    }
}

void HistoryRecorder::clear() {
    m_recorded = false;
    m_marks.clear();
    m_marksHead = 0;
    m_triggerBefore = 0; // power-on: every device is 0
    m_rings.assign(m_devices.size(), Ring{});
    m_fresh.clear();
    for (std::size_t i = 0; i < m_devices.size(); ++i)
        m_fresh.push_back(static_cast<int>(i));
}

bool HistoryRecorder::setTrigger(std::optional<Trigger> trigger) {
    if (trigger && !watch(trigger->device))
        return false;
    m_trigger = std::move(trigger);
    m_triggerDevice = m_trigger ? find(m_trigger->device) : -1;
    m_triggerBefore.reset();
    if (m_triggerDevice >= 0) {
        const Ring &r = m_rings[static_cast<std::size_t>(m_triggerDevice)];
        if (!r.changes.empty())
            m_triggerBefore = m_last[static_cast<std::size_t>(m_triggerDevice)];
        else if (!m_recorded)
            m_triggerBefore = 0; // nothing scanned since power-on
    }
    return true;
}

std::vector<HistoryRecorder::Mark> HistoryRecorder::marks() const {
    std::vector<Mark> out;
    out.reserve(m_marks.size());
    for (std::size_t k = 0; k < m_marks.size(); ++k)
        out.push_back(m_marks[(m_marksHead + k) % m_marks.size()]);
    return out;
}

bool HistoryRecorder::record(quint64 scan, qint64 timeMs, const std::int32_t *words) {
    auto push = [&](std::size_t i, std::int32_t v) {
        m_last[i] = v;
        Ring &r = m_rings[i];
        if (r.changes.size() < m_capacity) {
            if (r.changes.size() == r.changes.capacity()) // grow, but never past the bound
                r.changes.reserve(
                    std::min(m_capacity, std::max<std::size_t>(8, 2 * r.changes.size())));
            r.changes.push_back({scan, timeMs, v});
        } else {
            r.changes[r.head] = {scan, timeMs, v};
            r.head = (r.head + 1) % m_capacity;
        }
    };
    auto value = [&](const Device &d) { return read(d, words[d.word]); };
    for (int i : m_fresh)
        push(static_cast<std::size_t>(i), value(m_devices[static_cast<std::size_t>(i)]));
    m_fresh.clear();
    for (const WordRun &run : m_wordRuns) {
        const std::int32_t *now = words + run.word;
        std::int32_t *before = m_wordValue.data() + run.first;
        if (std::memcmp(now, before, static_cast<std::size_t>(run.count) * sizeof(std::int32_t)) ==
            0) [[likely]]
            continue;
        for (int r = 0; r < run.count; ++r) {
            const std::int32_t w = now[r];
            if (w == before[r])
                continue;
            before[r] = w;
            const auto j = static_cast<std::size_t>(run.first + r);
            for (int k = m_wordFirst[j]; k < m_wordFirst[j + 1]; ++k) {
                const auto i = static_cast<std::size_t>(m_wordDevices[static_cast<std::size_t>(k)]);
                const std::int32_t v = value(m_devices[i]);
                if (v != m_last[i])
                    push(i, v);
            }
        }
    }
    m_recorded = true;
    if (m_triggerDevice < 0) [[likely]]
        return false;
    const std::int32_t now = m_last[static_cast<std::size_t>(m_triggerDevice)];
    const std::int32_t before = m_triggerBefore.value_or(now);
    m_triggerBefore = now;
    if (!m_trigger->fires(before, now))
        return false;
    if (m_marks.size() < kMaxMarks) {
        m_marks.push_back({scan, timeMs});
    } else {
        m_marks[m_marksHead] = {scan, timeMs};
        m_marksHead = (m_marksHead + 1) % kMaxMarks;
    }
    return true;
}

int HistoryRecorder::find(const Address &address) const {
    const auto it = m_index.find(address);
    return it == m_index.end() ? -1 : it->second;
}

template <typename Key>
std::optional<std::int32_t> HistoryRecorder::valueAt(int device, Key key) const {
    if (device < 0)
        return std::nullopt;
    const Ring &r = m_rings[static_cast<std::size_t>(device)];
    const std::size_t n = r.changes.size();
    if (n == 0 || key(r.at(0)) > 0)
        return std::nullopt; // before the oldest change kept
    // The last change at or before the moment (key <= 0), by bisection over the ring.
    std::size_t lo = 0, hi = n; // answer in [lo, hi)
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        if (key(r.at(mid)) <= 0)
            lo = mid;
        else
            hi = mid;
    }
    return r.at(lo).value;
}

std::optional<std::int32_t> HistoryRecorder::valueAtScan(const Address &address,
                                                         quint64 scan) const {
    return valueAt(find(address), [scan](const Change &c) {
        return c.scan < scan ? -1 : c.scan > scan ? 1 : 0;
    });
}

std::optional<std::int32_t> HistoryRecorder::valueAtTime(const Address &address,
                                                         qint64 timeMs) const {
    return valueAt(find(address), [timeMs](const Change &c) {
        return c.timeMs < timeMs ? -1 : c.timeMs > timeMs ? 1 : 0;
    });
}

std::optional<quint64> HistoryRecorder::knownFrom(const Address &address) const {
    const int device = find(address);
    if (device < 0 || m_rings[static_cast<std::size_t>(device)].changes.empty())
        return std::nullopt;
    return m_rings[static_cast<std::size_t>(device)].at(0).scan;
}

std::optional<HistoryRecorder::Change> HistoryRecorder::oldest(const Address &address) const {
    const int device = find(address);
    if (device < 0 || m_rings[static_cast<std::size_t>(device)].changes.empty())
        return std::nullopt;
    return m_rings[static_cast<std::size_t>(device)].at(0);
}

std::vector<HistoryRecorder::Change> HistoryRecorder::changes(const Address &address, qint64 fromMs,
                                                              qint64 toMs) const {
    std::vector<Change> out;
    const int device = find(address);
    if (device < 0 || toMs < fromMs)
        return out;
    const Ring &r = m_rings[static_cast<std::size_t>(device)];
    for (std::size_t k = 0; k < r.changes.size(); ++k) {
        const Change &c = r.at(k);
        if (c.timeMs > toMs)
            break;
        if (c.timeMs <= fromMs) {
            // Only the last change at or before fromMs: the value the window starts with.
            if (out.empty())
                out.push_back(c);
            else
                out.back() = c;
        } else {
            out.push_back(c);
        }
    }
    return out;
}

std::size_t HistoryRecorder::memoryBytes() const {
    std::size_t bytes = 0;
    for (const Ring &r : m_rings)
        bytes += r.changes.capacity() * sizeof(Change);
    return bytes;
}

} // namespace rung::model
