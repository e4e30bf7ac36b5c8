#pragma once

// A scenario recorded from a simulation (docs/scenario-tests.md "Recording"): what the user
// did to the inputs (written, toggled, forced, released) with its virtual time, as set, force
// and release statements, and after each the outputs seen, as expectations; replayed against a
// changed program it says what the change changed.

#include "scan_history.h"
#include "scenario.h"

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

} // namespace rung::simulator
