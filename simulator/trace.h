#pragma once

// Traces: run a program for N scans with stimuli applied after given numbers of scans and
// print the chosen devices as CSV after every END. The `simulate` command and the golden-trace
// tests share this, so both read the same options.

#include "engine.h"

#include <QStringList>
#include <QTextStream>

namespace rung::simulator {

struct TraceStimulus {
    model::Address address;
    qint64 value = 0;
    quint64 scan = 0; // applied once this many scans have run (0: before the first)
};

struct TraceColumn {
    enum class Kind : std::uint8_t { Bit, Word, SetValue, Hex };
    QString name; // as given
    model::Address address;
    Kind kind = Kind::Bit;
};

struct TraceRequest {
    quint64 scans = 0;
    qint64 periodMs = 10;
    std::vector<TraceStimulus> stimuli;
    std::vector<TraceColumn> columns;
};

// A trace prints a row per scan: at most this many (27 h 46 min at 10 ms).
constexpr qint64 kMaxTraceScans = 10000000;

// Reads --scans N (1..kMaxTraceScans), --period MS, --set DEV=VALUE@SCAN (repeatable) and
// --trace DEV[,DEV...]. A trace column "cv:T0" / "sv:T0" is a timer/counter's current / set
// value; "hex:DM 0100" a word as four hexadecimal digits (a CPM1 BCD word reads as its
// digits); a bare timer or counter is its done bit; a word device its value. A --set value
// "#6103" is a word in hexadecimal digits; "@SCAN" applies it once SCAN scans have run (0:
// before the first). Unknown options are errors, and so is a --set @N or later with
// --scans N (no scan runs after it).
bool parseTraceOptions(const model::Target &target, const QStringList &args, TraceRequest *request,
                       QString *error);

// The pieces both traces use (a program's, and a network's where each column names a
// station): a column as --trace writes it ("cv:T0", "hex:DM 0100", "D0"), a --set value
// ("-5", "#6103"), a stimulus applied to an engine, a column's value as the CSV prints it.
bool parseTraceColumn(const model::Target &target, const QString &text, TraceColumn *column,
                      QString *error);
bool parseTraceDevice(const model::Target &target, const QString &text, model::Address *address,
                      QString *error);
bool parseTraceValue(const QString &text, qint64 *value);
void applyStimulus(Engine &engine, const TraceStimulus &stimulus);
QString traceValue(const Engine &engine, const TraceColumn &column);

// Runs the request on a fresh engine, writing the CSV (model/image/scan_csv.h: scans from 1,
// the time at a scan's end) with a row per scan. Stimuli on a timer/counter set its set
// value; on a word device its value; otherwise the bit.
void runTrace(const std::shared_ptr<const Program> &program, const TraceRequest &request,
              QTextStream &out, std::vector<RuntimeError> *runtimeErrors = nullptr);

} // namespace rung::simulator
