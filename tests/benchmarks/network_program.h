#pragma once

// The network benchmarks' station program (bench_network.cpp), also read by the tests of what
// the network's history compares (tests/simulator/test_scan_writes.cpp).

#include <QString>

namespace rung::bench {

// About 1,000 steps: 59 rungs of 17 (contacts, a coil, a move and an addition), then END.
// busy: each addition counts its own register up, so 59 registers change every scan.
inline QString thousandSteps(int station, bool busy = false) {
    QString p = QStringLiteral("; target: vigor\n");
    for (int r = 0; r < 59; ++r)
        p += QStringLiteral("LD X%1\nAND M%2\nOR M%3\nOUT Y%4\nLD M9000\nMOV D%5 D%6\n"
                            "ADD D%8 K1 D%7\n")
                 .arg(QString::number(r % 8, 8))
                 .arg(r + 100)
                 .arg(r + 200)
                 .arg(QString::number(r % 16, 8))
                 .arg(station * 10 + r % 4)
                 .arg(100 + r)
                 .arg(300 + r)
                 .arg(busy ? 300 + r : 100 + r);
    return p + QStringLiteral("END\n");
}

} // namespace rung::bench
