#include "model/image/timing_data.h"

#include "model/image/monitor_source.h"
#include "model/image/scan_csv.h"

#include <QTextStream>

#include <algorithm>
#include <limits>
#include <map>

namespace rung::model {

using Change = HistoryRecorder::Change;

TimingWindow readWindow(const MonitorSource &source, const std::vector<TimingChannel> &channels,
                        qint64 fromMs, qint64 toMs) {
    TimingWindow w;
    w.fromMs = fromMs;
    w.toMs = toMs;
    w.changes.resize(channels.size());
    w.knownFromMs.assign(channels.size(), -1);
    source.readHistory([&](const HistoryRecorder &h) {
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

int writeCsv(const MonitorSource &source, const std::vector<TimingChannel> &channels,
             QTextStream &out) {
    constexpr qint64 lowest = std::numeric_limits<qint64>::min() / 2;
    constexpr qint64 highest = std::numeric_limits<qint64>::max() / 2;
    std::vector<std::vector<Change>> all(channels.size());
    source.readHistory([&](const HistoryRecorder &h) {
        for (std::size_t k = 0; k < channels.size(); ++k)
            all[k] = h.changes(channels[k].address, lowest, highest);
    });
    QStringList devices;
    for (const TimingChannel &c : channels)
        devices << c.device;
    ScanCsvWriter csv(out, devices);
    // Every scan at which something changed, in order; then each channel's value after it.
    std::map<quint64, qint64> moments; // scan -> time
    for (const auto &changes : all)
        for (const Change &c : changes)
            moments.emplace(c.scan, c.timeMs);
    std::vector<std::size_t> next(channels.size(), 0);
    QStringList value(devices.size());
    for (const auto &[scan, time] : moments) {
        for (std::size_t k = 0; k < channels.size(); ++k)
            while (next[k] < all[k].size() && all[k][next[k]].scan <= scan)
                value[qsizetype(k)] = QString::number(all[k][next[k]++].value);
        csv.row(scan, time, value);
    }
    return csv.rows();
}

std::vector<HistoryRecorder::Mark> triggerMoments(const std::vector<Change> &changes,
                                                  const Trigger &trigger) {
    std::vector<HistoryRecorder::Mark> out;
    for (std::size_t k = 1; k < changes.size(); ++k)
        if (trigger.fires(changes[k - 1].value, changes[k].value))
            out.push_back({changes[k].scan, changes[k].timeMs});
    return out;
}

} // namespace rung::model
