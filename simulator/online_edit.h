#pragma once

// What an online edit would do to a running simulation (docs/simulator.md "Online edit"):
// the IDE asks before an edit that cannot keep the image (another memory layout: another
// PLC) or that changes which timers and counters the program uses (their values would be
// left to elements no longer counted, and new ones start from what the image holds).

#include "program.h"

#include <vector>

namespace rung::simulator {

struct EditImpact {
    bool layoutDiffers = false;
    std::vector<model::Address> elementsGone; // timers/counters the old program used only
    std::vector<model::Address> elementsNew;  // those only the new one uses
    bool keepsImage() const { return !layoutDiffers; }
    bool changesElements() const { return !elementsGone.empty() || !elementsNew.empty(); }
};

EditImpact assessEdit(const Program &running, const Program &edited);

// The timers and counters a program runs (its timer and counter boxes), in address order.
std::vector<model::Address> timersAndCounters(const Program &program);

} // namespace rung::simulator
