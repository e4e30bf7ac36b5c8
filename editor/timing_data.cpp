#include "timing_data.h"

#include "model/image/monitor_source.h"

#include <QTextStream>

#include <algorithm>
#include <limits>
#include <map>

namespace rung::editor {

using Change = model::HistoryRecorder::Change;

TimingWindow readWindow(const model::MonitorSource &source,
                        const std::vector<TimingChannel> &channels, qint64 fromMs, qint64 toMs) {
    TimingWindow w;
    w.fromMs = fromMs;
    w.toMs = toMs;
    w.changes.resize(channels.size());
    w.knownFromMs.assign(channels.size(), -1);
    source.readHistory([&](const model::HistoryRecorder &h) {
        for (std::size_t k = 0; k < channels.size(); ++k) {
            w.changes[k] = h.changes(channels[k].address, fromMs, toMs);
            if (const auto first = h.oldest(channels[k].address))
                w.knownFromMs[k] = first->timeMs;
        }
        for (const auto &m : h.marks())
            if (m.timeMs >= fromMs && m.timeMs <= toMs)
                w.marks.push_back(m);
    });
    return w;
}

int writeCsv(const model::MonitorSource &source, const std::vector<TimingChannel> &channels,
             QTextStream &out) {
    constexpr qint64 lowest = std::numeric_limits<qint64>::min() / 2;
    constexpr qint64 highest = std::numeric_limits<qint64>::max() / 2;
    std::vector<std::vector<Change>> all(channels.size());
    source.readHistory([&](const model::HistoryRecorder &h) {
        for (std::size_t k = 0; k < channels.size(); ++k)
            all[k] = h.changes(channels[k].address, lowest, highest);
    });
    QStringList header{QStringLiteral("scan"), QStringLiteral("time_ms")};
    for (const TimingChannel &c : channels)
        header << c.device;
    out << header.join(QLatin1Char(',')) << '\n';
    // Every scan at which something changed, in order; then each channel's value after it.
    std::map<quint64, qint64> moments; // scan -> time
    for (const auto &changes : all)
        for (const Change &c : changes)
            moments.emplace(c.scan, c.timeMs);
    std::vector<std::size_t> next(channels.size(), 0);
    std::vector<QString> value(channels.size());
    int rows = 0;
    for (const auto &[scan, time] : moments) {
        for (std::size_t k = 0; k < channels.size(); ++k)
            while (next[k] < all[k].size() && all[k][next[k]].scan <= scan)
                value[k] = QString::number(all[k][next[k]++].value);
        out << scan << ',' << time;
        for (const QString &v : value)
            out << ',' << v;
        out << '\n';
        ++rows;
    }
    return rows;
}

std::vector<model::HistoryRecorder::Mark> triggerMoments(const std::vector<Change> &changes,
                                                         const model::Trigger &trigger) {
    std::vector<model::HistoryRecorder::Mark> out;
    for (std::size_t k = 1; k < changes.size(); ++k)
        if (trigger.fires(changes[k - 1].value, changes[k].value))
            out.push_back({changes[k].scan, changes[k].timeMs});
    return out;
}

} // namespace rung::editor
