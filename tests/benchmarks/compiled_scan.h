#pragma once

// The benchmarks' 2048-step program as compiled C++ (generated at build time by
// generator/gen_compiled_scan.cpp into compiled_scan_2048.cpp): one scan of the same logic
// the engine interprets, on the same memory image (MemoryLayout order).

#include <algorithm>
#include <cstdint>

namespace rung::bench {

// Timer and counter elements the generated code keeps state for (the synthetic target has
// 64); the generator refuses a program with more.
constexpr int kCompiledStateSlots = 256;

struct CompiledState {
    std::int64_t accumulated[kCompiledStateSlots] = {};
    std::uint8_t previous[kCompiledStateSlots] = {};
    std::uint8_t running[kCompiledStateSlots] = {};
    std::uint64_t scans = 0;
    std::int64_t timeMs = 0;
};

extern const int kCompiledSteps;
extern const int kCompiledWords;

// One scan: inputs from `stimulus`, the system bits, the program, the clock.
void compiledScan(std::int32_t *R, const std::int32_t *stimulus, CompiledState &st,
                  std::int64_t period);

} // namespace rung::bench
