#pragma once

// What the timing chart draws, copied out of a MonitorSource's history (the recorder's lock
// is held only for the copy): per channel the value at the window's start and every change
// in it, the trigger's marks, and the newest scan. Also the chart's CSV: one row where any
// channel changes. Below the widgets, so the command line and the tests reach it without a
// display.

#include "model/image/history.h"
#include "model/image/value_format.h"

#include <QString>
#include <QStringList>

#include <vector>

class QTextStream;

namespace rung::model {

class MonitorSource;

struct TimingChannel {
    Address address;
    QString device; // as the target writes it
    QString symbol;
    bool bit = true;
    int bits = 16; // a word's width
    ValueFormat format = ValueFormat::Decimal;
};

struct TimingWindow {
    qint64 fromMs = 0;
    qint64 toMs = 0;
    // Per channel: the value at fromMs when known, then each change up to toMs.
    std::vector<std::vector<HistoryRecorder::Change>> changes;
    // Per channel: from which virtual time its values are known (-1: not yet).
    std::vector<qint64> knownFromMs;
    std::vector<HistoryRecorder::Mark> marks;
};

// The channels' changes between fromMs and toMs, read under the source's history lock.
TimingWindow readWindow(const MonitorSource &source, const std::vector<TimingChannel> &channels,
                        qint64 fromMs, qint64 toMs);

// The whole kept history of the channels as the simulation's CSV (model/image/scan_csv.h): a
// row for each scan after which any channel changed, with every channel's value after that
// scan (bits 0/1, words as signed numbers; empty before a channel's first recorded value).
// Returns the number of rows written.
int writeCsv(const MonitorSource &source, const std::vector<TimingChannel> &channels,
             QTextStream &out);

// The moments in a channel's changes where the trigger became true (marks for a trigger armed
// after the fact, found in what is already recorded).
std::vector<HistoryRecorder::Mark>
triggerMoments(const std::vector<HistoryRecorder::Change> &changes, const Trigger &trigger);

} // namespace rung::model
