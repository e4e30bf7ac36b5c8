#pragma once

// The traffic of a network as `simulate --traffic FILE` writes it (docs/network.md): one line
// per transmission, its virtual time, wire, sender, bytes as hex and as text, and a note when
// a fault or a collision changed it.

#include "network/network.h"

namespace rung::network {

// "   12.345678 w1 master/CP2 02 30 35 ... |.05...|  note"
QString formatTraffic(const TrafficRecord &record);
// The first line of a traffic file.
QString trafficHeader(const QString &networkFile);

} // namespace rung::network
