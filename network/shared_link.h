#pragma once

// CPU Link and Parallel Link (Vigor M/VB/VH communication manual, B-3-4, B-3-5): PLCs share data
// areas over a "dedicated communication protocol" whose frames the manual does not publish. The
// network exchanges the areas at the level the manual does publish (which devices, how often, what
// the status devices show) and puts no frame on a wire; such a port is never bridged to a real one.

#include "network/network.h"

namespace rung::network {

// One group per wire whose ports run CPU Link, one per pair running Parallel Link; false with
// what is wrong (two masters, station numbers twice, a second link on one wire).
bool makeSharedLinks(Network *network, std::vector<std::unique_ptr<Actor>> *groups, QString *error);

} // namespace rung::network
