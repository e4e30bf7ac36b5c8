#pragma once

// A network as the subject of a scenario test (docs/scenario-tests.md, "A network"):
// `program plant.rungnet` in a .rungtest, devices written STATION/DEVICE ("st1/D0"), one
// step of the scenario's period moving the whole network on its one virtual clock.

#include "network/network.h"

#include "simulator/scenario.h"

namespace rung::network {

// Reads and builds the network file; null with what, where and why, a line each.
std::unique_ptr<simulator::ScenarioSubject>
networkScenarioSubject(const QString &path, const ProgramLoader &loader, QStringList *errors);

} // namespace rung::network
