#pragma once

// Random valid programs for the property tests: rungs of series/parallel networks written in
// any of the valid ("fuzzy") orders, several outputs per rung, MPS branches where the target
// has a branch stack, IL/ILC branch forms where it has none, two-input boxes where it has one.
// A rung may read the devices its own outputs write.

#include "model/target/target.h"

#include <QString>

#include <cstdint>

namespace rung::testing {

struct RandomProgramOptions {
    int rungs = 8;
    int maxDepth = 3;
    bool fuzzy = true;    // also emit stacked ANB/ORB and LD/ORB chains
    bool branches = true; // MPS/MRD/MPP (or output continuations) and parallel outputs
    bool boxes = true;    // LR / KEEP / two-input counters where the target has them
    bool end = true;
    // Also edge contacts, compare contacts, timers (with their contacts) and a move box, as
    // far as the target has them; for the simulator, whose equivalence covers them.
    bool extended = false;
};

QString randomProgram(const model::Target &target, std::uint64_t seed,
                      const RandomProgramOptions &options = {});

} // namespace rung::testing
