#pragma once

// Per-family execution semantics the target tables do not carry (docs/simulator.md).
// Device names here are parsed with the target's own address rules.

#include "model/target/target.h"

namespace rung::simulator {

struct FamilySemantics {
    bool deferredBitWrites = false; // contacts read the bit image of the previous scan (VPC)
    bool bcdSetValues = false;      // timer/counter set values are BCD (CPM1)
    int downTimersBelow = 0;        // timers with a lower element number count down
    int downCountersBelow = 0;
    double timerBaseMs = 0;     // 0 = Target::defaultTimerBaseMs
    double fastTimerBaseMs = 0; // CPM1 TIMH (function code 15)
    int fastTimerFunctionCode = -1;
    const char *parallelOut = nullptr; // VPC p76 -> o00..o11
    const char *parallelOutFirstBit = nullptr;
    const char *parallelIn = nullptr; // VPC i00..i11 -> p77
    const char *parallelInFirstBit = nullptr;
    int parallelBits = 0;
};

inline FamilySemantics familySemantics(model::Family family) {
    FamilySemantics s;
    switch (family) {
    case model::Family::Vpc:
        s.deferredBitWrites = true;
        s.downTimersBelow = 16;
        s.downCountersBelow = 16;
        s.timerBaseMs = 10;
        s.parallelOut = "p76";
        s.parallelOutFirstBit = "o00";
        s.parallelIn = "p77";
        s.parallelInFirstBit = "i00";
        s.parallelBits = 12;
        break;
    case model::Family::Vigor:
        break;
    case model::Family::Cpm1:
        s.bcdSetValues = true;
        s.downTimersBelow = 1 << 30;
        s.downCountersBelow = 1 << 30;
        s.timerBaseMs = 100;
        s.fastTimerBaseMs = 10;
        s.fastTimerFunctionCode = 15;
        break;
    case model::Family::Pl110:
        s.timerBaseMs = 100;
        break;
    }
    return s;
}

} // namespace rung::simulator
