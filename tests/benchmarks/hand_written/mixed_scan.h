#pragma once

// The benchmarks' 2048-step program (mixed_program.h) written by hand in C++, as a programmer
// would write the same logic without a PLC: plain arrays of bool and 16/32-bit integers, one
// function a scan, the 128 rungs as one loop. The goal of issue 35 ("The scan engine within 3x
// of compiled code") is measured against it (BM_HandWrittenRatio); bench_simulator checks
// first that it leaves the engine's image scan after scan.

#include <cstdint>

namespace rung::bench {

struct HandWrittenPlc {
    bool X[32] = {};
    bool Y[32] = {};
    bool M[500] = {};
    bool SM[16] = {}; // SM9000..SM9015
    // T0..T31: done bit, current value, set value in use; the ms the input has been ON.
    bool T[32] = {};
    std::int16_t TV[32] = {};
    std::int16_t TS[32] = {};
    std::int32_t Tms[32] = {};
    bool Trunning[32] = {};
    // C0..C31 (one input, Vigor CNT).
    bool C[32] = {};
    std::int16_t CV[32] = {};
    std::int16_t CS[32] = {};
    bool Cprevious[32] = {};
    std::int16_t D[100] = {};
    std::uint32_t scans = 0;
    std::int32_t timeMs = 0;
};

// One scan: the inputs X0..X31 from `inputs`, the system bits, the 128 rungs, the clock.
void handWrittenScan(HandWrittenPlc &plc, const bool *inputs, std::int32_t periodMs);

} // namespace rung::bench
