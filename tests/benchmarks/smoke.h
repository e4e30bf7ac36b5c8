#pragma once

// A benchmark's size, full or in a smoke run. CI runs every benchmark once in the sanitizer
// build (scripts/run-benchmarks.sh --smoke sets RUNG_BENCH_SMOKE=1) to prove that it still
// builds, runs and measures what it says, not to time it: there every workload shrinks to
// its small size, every repetition count and fixed iteration count to one. The figures in
// docs/performance.md come from full runs of an optimised build.

#include <cstdlib>
#include <cstring>

namespace rung::bench {

inline bool smoke() {
    static const bool on = [] {
        const char *v = std::getenv("RUNG_BENCH_SMOKE");
        return v && *v && std::strcmp(v, "0") != 0;
    }();
    return on;
}

// `full` in a measuring run, `small` in a smoke run.
inline int sized(int full, int small) {
    return smoke() ? small : full;
}

// Repetitions and fixed iteration counts: one each in a smoke run.
inline int times(int full) {
    return sized(full, 1);
}

// A limit on time (a rate, a latency) is judged in a measuring run only: a smoke run, under
// the sanitizers on a shared two-core machine, proves that the benchmark runs and that what
// it computes is right, not how fast (there the online refresh fell under its 0.9 of the
// wire's rate while a build ran beside it). Limits on exact counts are judged in both.
inline bool judgesTime() {
    return !smoke();
}

// How long a benchmark waits for something to happen before it calls it an error: the
// sanitizers make everything several times slower.
inline int patienceMs(int full) {
    return smoke() ? full * 5 : full;
}

} // namespace rung::bench
