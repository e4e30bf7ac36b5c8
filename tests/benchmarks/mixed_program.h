#pragma once

// The benchmarks' 2048-step program: 128 rungs of 16 steps with contacts, a block, a stack
// branch, a timer, a counter, moves and arithmetic, on the synthetic Vigor-like target of the
// engine tests (tests/simulator/sim_test_target.h). bench_simulator scans it; the generator
// (generator/gen_compiled_scan.cpp) writes the same logic as C++ for the compiled-code
// comparison.

#include <QString>

namespace rung::bench {

inline QString mixedProgram() {
    QString p;
    for (int r = 0; r < 128; ++r) {
        const int a = r % 32;
        const int b = (r * 7) % 32;
        p += QStringLiteral("LD X%1\nAND M%2\nOR Y%3\nLD X%4\nORI M%5\nANB\nMPS\nAND X%6\n"
                            "OUT M%7\nMPP\nTMR T%8 K50\nLD M%9\nCNT C%8 K10\nLD SM9000\n"
                            "MOV D%10 D%11\nADD D%11 K3 D%12\n")
                 .arg(a)
                 .arg(r + 100)
                 .arg(b)
                 .arg((a + 5) % 32)
                 .arg(r + 200)
                 .arg((a + 9) % 32)
                 .arg(r)
                 .arg(r % 32)
                 .arg((r + 1) % 128)
                 .arg(r % 90)
                 .arg((r + 3) % 90)
                 .arg((r + 6) % 90);
    }
    return p;
}

} // namespace rung::bench
