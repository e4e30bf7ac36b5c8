#include "comms/driver/planner.h"

#include "model/target/target.h"

#include <algorithm>
#include <limits>
#include <map>

namespace rung::comms {

namespace {

int areaIndex(const model::Target &target, const char *key) {
    const QString k = QString::fromLatin1(key);
    for (std::size_t i = 0; i < target.areas.size(); ++i)
        if (target.areas[i].key == k)
            return int(i);
    return -1;
}

// The segment that holds the span: -1 when none does (a need outside the map: its own frame).
int segmentOf(const UnitSpan &span, const std::vector<UnitSpan> &segments) {
    const auto it = std::upper_bound(
        segments.begin(), segments.end(), span, [](const UnitSpan &a, const UnitSpan &b) {
            return a.space != b.space ? a.space < b.space : a.start < b.start;
        });
    if (it == segments.begin())
        return -1;
    const auto &s = *(it - 1);
    return s.space == span.space && span.start >= s.start && span.end() <= s.end()
               ? int(it - 1 - segments.begin())
               : -1;
}

} // namespace

std::vector<UnitSpan> mappedSegments(const model::Target &target, const model::ProtocolMap &map) {
    std::vector<UnitSpan> runs;
    for (const model::ProtocolRange &r : map.ranges) {
        const int ai = areaIndex(target, r.area);
        if (ai < 0)
            continue;
        const model::Area &area = target.area(ai);
        const int first = std::max(area.first, r.origin);
        const int last = r.last < 0 ? area.last : std::min(r.last, area.last);
        if (last < first)
            continue;
        const int width = model::unitBits(r.space);
        UnitSpan s{r.space, 0, 0};
        if (r.part == model::DevicePart::Value) {
            const int units = std::max(1, area.wordBits / width);
            s.start = r.start + (first - r.origin) * units;
            s.count = (last - first + 1) * units;
        } else {
            const int per = area.holdsWords() ? area.wordBits : 1;
            const int from = (first - r.origin) * per;
            const int to = (last - r.origin + 1) * per; // one past the last bit
            s.start = r.start + from / width;
            s.count = r.start + (to + width - 1) / width - s.start;
        }
        runs.push_back(s);
    }
    std::sort(runs.begin(), runs.end(), [](const UnitSpan &a, const UnitSpan &b) {
        return a.space != b.space ? a.space < b.space : a.start < b.start;
    });
    std::vector<UnitSpan> joined;
    for (const UnitSpan &s : runs) {
        if (!joined.empty() && joined.back().space == s.space && s.start <= joined.back().end())
            joined.back().count = std::max(joined.back().end(), s.end()) - joined.back().start;
        else
            joined.push_back(s);
    }
    return joined;
}

std::vector<PlannedRead> planReads(std::vector<UnitSpan> needs, const ReadCosts &costs,
                                   const std::vector<UnitSpan> &segments) {
    std::sort(needs.begin(), needs.end(), [](const UnitSpan &a, const UnitSpan &b) {
        return a.space != b.space ? a.space < b.space : a.start < b.start;
    });
    // Overlapping needs become one item (a frame never splits a value); touching ones stay
    // apart, so that a frame limit may fall between them.
    std::vector<UnitSpan> items;
    for (const UnitSpan &n : needs) {
        if (n.count <= 0)
            continue;
        if (!items.empty() && items.back().space == n.space && n.start < items.back().end())
            items.back().count = std::max(items.back().end(), n.end()) - items.back().start;
        else
            items.push_back(n);
    }
    std::vector<PlannedRead> plan;
    std::size_t begin = 0;
    while (begin < items.size()) {
        std::size_t end = begin;
        while (end < items.size() && items[end].space == items[begin].space)
            ++end;
        const model::ProtocolSpace space = items[begin].space;
        const int limit = std::max(1, costs.maxUnits(space));
        const std::size_t n = end - begin;
        std::vector<int> segment(n);
        for (std::size_t k = 0; k < n; ++k)
            segment[k] = segmentOf(items[begin + k], segments);
        // best[j]: bytes (then frames) to read items 0..j-1; from[j]: the first item of the
        // last frame in that best plan.
        constexpr long long inf = std::numeric_limits<long long>::max();
        std::vector<std::pair<long long, int>> best(n + 1, {inf, 0});
        std::vector<std::size_t> from(n + 1, 0);
        best[0] = {0, 0};
        for (std::size_t j = 1; j <= n; ++j) {
            const UnitSpan &last = items[begin + j - 1];
            for (std::size_t i = j; i >= 1; --i) {
                const UnitSpan &first = items[begin + i - 1];
                const int units = last.end() - first.start;
                if (i < j &&
                    (units > limit || segment[i - 1] < 0 || segment[i - 1] != segment[j - 1]))
                    break;
                const std::pair<long long, int> cost{
                    best[i - 1].first + costs.frameBytes(space, units), best[i - 1].second + 1};
                if (cost < best[j]) {
                    best[j] = cost;
                    from[j] = i;
                }
            }
        }
        std::vector<PlannedRead> frames;
        for (std::size_t j = n; j > 0; j = from[j] - 1) {
            const UnitSpan &first = items[begin + from[j] - 1];
            const UnitSpan &last = items[begin + j - 1];
            const UnitSpan span{space, first.start, last.end() - first.start};
            frames.push_back({span, costs.frameBytes(space, span.count)});
        }
        plan.insert(plan.end(), frames.rbegin(), frames.rend());
        begin = end;
    }
    return plan;
}

int totalBytes(const std::vector<PlannedRead> &plan) {
    int bytes = 0;
    for (const PlannedRead &r : plan)
        bytes += r.bytes;
    return bytes;
}

} // namespace rung::comms
