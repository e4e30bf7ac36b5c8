#pragma once

// The request planner: which reads fetch a set of scattered units with the fewest bytes on
// the wire. A gap between two needed runs is worth reading through when its units cost less
// than the overhead of another frame; a frame ends where the protocol's limit (128 link
// bytes, 125 or 30 registers, 2000 bits) or the protocol's map does (a read never crosses
// addresses that hold nothing, which a PLC refuses). The choice is exact, not greedy: a
// dynamic program over the needed runs of each space, with the protocol's own cost of a
// frame of n units (ProtocolDriver::readFrameBytes: request and reply, every Host Link part
// and delimiter), so no other set of frames reads the same units in fewer bytes.

#include "model/target/protocol_map.h"

#include <functional>
#include <vector>

namespace rung::model {
class Target;
}

namespace rung::comms {

// Units that must travel in one frame: a device's value (a Vigor C200 value is 4 link bytes,
// 2 registers), or one unit.
struct UnitSpan {
    model::ProtocolSpace space = model::ProtocolSpace::Coils;
    int start = 0;
    int count = 1;
    int end() const { return start + count; } // one past the last
    friend bool operator==(const UnitSpan &, const UnitSpan &) = default;
};

struct PlannedRead {
    UnitSpan span;
    int bytes = 0; // request and reply on the wire
    friend bool operator==(const PlannedRead &, const PlannedRead &) = default;
};

struct ReadCosts {
    std::function<int(model::ProtocolSpace)> maxUnits;
    std::function<int(model::ProtocolSpace, int units)> frameBytes;
};

// The runs of units the map gives a place to, per space, touching runs joined: a read may
// span them. Sorted by space, then start.
std::vector<UnitSpan> mappedSegments(const model::Target &target, const model::ProtocolMap &map);

// The reads that cover every needed span, fewest bytes first, then fewest frames. Needs may
// repeat and overlap. Sorted by space, then start.
std::vector<PlannedRead> planReads(std::vector<UnitSpan> needs, const ReadCosts &costs,
                                   const std::vector<UnitSpan> &segments);

int totalBytes(const std::vector<PlannedRead> &plan);

} // namespace rung::comms
