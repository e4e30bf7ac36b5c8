#pragma once

// A scenario recorded from a simulation (docs/scenario-tests.md "Recording"): what the user
// did to the inputs (written, toggled, forced, released) with its virtual time, as set, force
// and release statements, and after each the outputs seen, as expectations; replayed against a
// changed program it says what the change changed.

#include "scan_history.h"
#include "scenario.h"

#include "model/image/history.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace rung::simulator {

struct RecordedScenario {
    QString text;
    QStringList notes; // translated: what the scenario holds otherwise than the run (a stopped
                       // scan's command taken at the next scan, a period changed)
};

// `programLine`: the file the scenario names (as the `program` statement writes it);
// `outputs`: the devices whose values become the expectations. nullopt with *error
// (translated) when the history does not hold the simulation from its start or holds no scan.
std::optional<RecordedScenario>
recordScenario(const ScanHistory &history, const model::Target &target, const QString &programLine,
               const std::vector<model::Address> &outputs, QString *error);

// A scenario from what a PLC was seen doing online: the history of its inputs and outputs,
// refresh by refresh, between fromMs and toMs of the session's time. Each change of an input
// becomes a set statement at its time from fromMs, rounded up to `periodMs`, the period the
// scenario runs at; before each next one, and at the end, the outputs seen are expectations.
// nullopt with *error (translated) when the history holds no input or output in that time.
std::optional<RecordedScenario>
recordObservedScenario(const model::HistoryRecorder &history, const model::Target &target,
                       const QString &programLine, const std::vector<model::Address> &inputs,
                       const std::vector<model::Address> &outputs, qint64 fromMs, qint64 toMs,
                       qint64 periodMs, QString *error);

} // namespace rung::simulator
