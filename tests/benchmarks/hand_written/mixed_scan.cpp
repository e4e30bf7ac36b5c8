// The benchmarks' 2048-step program written by hand (mixed_scan.h). Each rung of
// mixed_program.h, r = 0..127, a = r % 32, b = 7r % 32:
//   LD X[a] / AND M[r+100] / OR Y[b] / LD X[a+5] / ORI M[r+200] / ANB / MPS / AND X[a+9] /
//   OUT M[r] / MPP / TMR T[r%32] K50 / LD M[r+1] / CNT C[r%32] K10 / LD SM9000 /
//   MOV D[r%90] D[r+3] / ADD D[r+3] K3 D[r+6]

#include "tests/benchmarks/hand_written/mixed_scan.h"

#include <algorithm>

namespace rung::bench {

void handWrittenScan(HandWrittenPlc &plc, const bool *inputs, std::int32_t periodMs) {
    std::copy(inputs, inputs + 32, plc.X);
    plc.SM[0] = true;                     // always ON
    plc.SM[2] = plc.scans == 0;           // first scan
    plc.SM[10] = (plc.scans & 1u) != 0;   // scan toggle
    plc.SM[13] = plc.timeMs % 1000 < 500; // 1 s clock
    for (int r = 0; r < 128; ++r) {
        const int a = r % 32;
        const int b = (r * 7) % 32;
        const bool on =
            ((plc.X[a] && plc.M[r + 100]) || plc.Y[b]) && (plc.X[(a + 5) % 32] || !plc.M[r + 200]);
        plc.M[r] = on && plc.X[(a + 9) % 32];

        const int t = r % 32; // TMR T K50, 100 ms units
        plc.TS[t] = 50;
        if (!on) {
            plc.Tms[t] = 0;
            plc.Trunning[t] = false;
        } else {
            if (plc.Trunning[t])
                plc.Tms[t] = std::min(plc.Tms[t] + periodMs, 50 * 100);
            plc.Trunning[t] = true;
        }
        const int units = plc.Tms[t] / 100;
        plc.T[t] = on && units >= 50;
        plc.TV[t] = static_cast<std::int16_t>(units);

        const bool count = plc.M[(r + 1) % 128]; // CNT C K10
        plc.CS[t] = 10;
        if (count && !plc.Cprevious[t] && plc.CV[t] < 10)
            ++plc.CV[t];
        plc.Cprevious[t] = count;
        plc.C[t] = plc.CV[t] >= 10;

        if (plc.SM[0]) {
            plc.D[(r + 3) % 90] = plc.D[r % 90];
            plc.D[(r + 6) % 90] = static_cast<std::int16_t>(plc.D[(r + 3) % 90] + 3);
        }
    }
    ++plc.scans;
    plc.timeMs += periodMs;
}

} // namespace rung::bench
