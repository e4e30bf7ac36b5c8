#pragma once

// What `rungstudio-cli check NET.rungnet` finds in a network beyond each station's program
// (docs/network.md, "Checking a network"): two masters on one wire, two ports answering one
// station number, a LINK or MBUS table naming a station that no port on its wire answers,
// a master instruction on a port that is on no wire; the PL110's COM / EXP queries naming a
// slave nothing answers, NAIS MATSUSHITA-MASTER ports, SEND outside free-port. The tables are
// read as the stations' first scan leaves them (a table is built by the program, one MOV a
// register).

#include "network/network.h"

#include <vector>

namespace rung::network {

struct NetworkFinding {
    bool error = true; // false: a warning
    QString where;     // "wire w1", "master: line 18"
    QString message;   // translated
};

// Runs the stations' first scans to read the tables: give it a network built for the
// check, not one that is simulating.
std::vector<NetworkFinding> checkNetwork(Network &network);

} // namespace rung::network
