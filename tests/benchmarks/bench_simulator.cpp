// Scan speed of the simulator (issue 3): a 2048-step mixed program, the same with power-flow
// recording, and the STL traffic light over 24 h of virtual time at 10 ms scans.
// Runs on the synthetic Vigor-like target of the engine tests so it does not depend on the
// device tables; the instruction mix is what a real program holds.

#include "tests/simulator/sim_test_target.h"

#include "model/image/history.h"
#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <QFile>

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

using namespace rung;
using namespace rung::simulator;

namespace {

// 128 rungs of 16 steps: contacts, a block, a stack branch, a timer, a counter, moves and
// arithmetic.
QString mixedProgram() {
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

// Traffic light (seed 004, 1.9 example 16): red 35 s, yellow 5 s, green 25 s, green blinking
// 5 s; the same program as tests/data/sim/vigor_traffic_light.il.
const char *kTrafficLight = "LD SM9002\nSET S0\n"
                            "STL S0\nOUT Y0\nTMR T0 K350\nLD T0\nSET S1\n"
                            "STL S1\nOUT Y1\nTMR T1 K50\nLD T1\nSET S2\n"
                            "STL S2\nOUT M2\nTMR T2 K250\nLD T2\nSET S3\n"
                            "STL S3\nTMR T3 K50\nLDI T5\nTMR T4 K5\nLD T4\nTMR T5 K5\nLDI T4\n"
                            "OUT M3\nLD T3\nSET S0\nRET\nLD M2\nOR M3\nOUT Y2\nEND";

struct Fixture {
    explicit Fixture(const QString &program)
        : target(test::makeTestTarget())
        , list(test::assemble(*target, program))
        , result(compileProgram(list))
        , engine(result.program) {}
    std::unique_ptr<model::Target> target;
    model::InstructionList list;
    CompileResult result;
    Engine engine;
};

void scanMixed(benchmark::State &state, bool record) {
    Fixture f(mixedProgram());
    if (f.list.instructions.size() != 2048 || !f.result.ok()) {
        state.SkipWithError("program did not compile to 2048 steps");
        return;
    }
    f.engine.setPowerFlowRecording(record);
    // Inputs that change so edges, timers and counters do work.
    int k = 0;
    for (auto _ : state) {
        f.engine.setBit(f.list.instructions[0].operands[0].address, (++k & 8) != 0);
        f.engine.scan();
    }
    state.counters["steps"] = 2048;
    state.counters["ns_per_step"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * 2048,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Scan2048Steps(benchmark::State &state) {
    scanMixed(state, false);
}
void BM_Scan2048StepsWithPowerFlow(benchmark::State &state) {
    scanMixed(state, true);
}

// A feature's cost as one figure: blocks of scans alternate on two engines of the same
// program, plain and with the feature (afterScan: the feature's own work after each of its
// scans), so machine noise hits both alike. Sets <name>_ns_per_scan, plain_ns_per_scan and
// their ratio.
template <typename AfterScan>
void sideBySide(benchmark::State &state, Fixture &plain, Fixture &with, const char *name,
                AfterScan afterScan) {
    using Clock = std::chrono::steady_clock;
    const model::Address input = plain.list.instructions[0].operands[0].address;
    constexpr int kBlock = 1000;
    double plainNs = 0;
    double withNs = 0;
    auto block = [&](Fixture &f, bool feature) {
        const auto start = Clock::now();
        for (int k = 0; k < kBlock; ++k) {
            f.engine.setBit(input, (k & 8) != 0);
            f.engine.scan();
            if (feature)
                afterScan(f);
        }
        return std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    };
    for (auto _ : state) {
        plainNs += block(plain, false);
        withNs += block(with, true);
    }
    const double scans = static_cast<double>(state.iterations()) * kBlock;
    state.counters["plain_ns_per_scan"] = plainNs / scans;
    state.counters[std::string(name) + "_ns_per_scan"] = withNs / scans;
    state.counters["ratio"] = plainNs > 0 ? withNs / plainNs : 0;
}

// The cost of power-flow recording.
void BM_PowerFlowRatio(benchmark::State &state) {
    Fixture plain(mixedProgram());
    Fixture recording(mixedProgram());
    if (!plain.result.ok() || !recording.result.ok()) {
        state.SkipWithError("program did not compile");
        return;
    }
    recording.engine.setPowerFlowRecording(true);
    sideBySide(state, plain, recording, "flow", [](Fixture &) {});
}

// The cost of the history recorder with 1,000 watched devices (issue 11: <= 10% of the plain
// scan): bits, words, timer and counter values of the mixed program, recorded after every
// scan.
void BM_HistoryRatio(benchmark::State &state) {
    Fixture plain(mixedProgram());
    Fixture recording(mixedProgram());
    if (!plain.result.ok() || !recording.result.ok()) {
        state.SkipWithError("program did not compile");
        return;
    }
    model::HistoryRecorder history(recording.result.program->layout);
    const model::Target &t = *recording.target;
    for (std::size_t area = 0; area < t.areas.size() && history.deviceCount() < 1000; ++area)
        for (int i = t.areas[area].first; i <= t.areas[area].last && history.deviceCount() < 1000;
             ++i)
            history.watch({static_cast<int>(area), i, -1});
    if (history.deviceCount() != 1000) {
        state.SkipWithError("the target has fewer than 1000 devices");
        return;
    }
    sideBySide(state, plain, recording, "history", [&](Fixture &f) {
        history.record(f.engine.statistics().scans, f.engine.statistics().timeMs,
                       f.engine.words().data());
    });
    state.counters["history_MB"] = static_cast<double>(history.memoryBytes()) / 1e6;
}

// The cost of operands resolved at run time (Vigor digit groups and index registers,
// docs/simulator.md): 1,024 moves on the real Vigor table, plain words (MOV D10 D1010) against
// the same moves from a digit group into an indexed word (MOV K4M16 D1010Z0), blocks of scans
// alternated as sideBySide does. Both programs scan the same number of steps; the plain
// program also pays the one flag test every step now has.
void BM_ResolvedOperandsRatio(benchmark::State &state) {
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    QString plainText;
    QString resolvedText;
    for (int k = 0; k < 1024; ++k) {
        plainText += QStringLiteral("LD M9000\nMOV D%1 D%2\n").arg(k % 200).arg(1000 + k);
        resolvedText +=
            QStringLiteral("LD M9000\nMOV K4M%1 D%2Z0\n").arg(16 * (k % 250)).arg(1000 + k);
    }
    auto compile = [&](const QString &text) {
        const model::ParseResult parsed = model::parseInstructionList(vigor, text);
        return parsed.ok() ? compileProgram(parsed.list) : CompileResult{};
    };
    const CompileResult plainProgram = compile(plainText);
    const CompileResult resolvedProgram = compile(resolvedText);
    if (!plainProgram.ok() || !resolvedProgram.ok()) {
        state.SkipWithError("the programs did not compile");
        return;
    }
    Engine plain(plainProgram.program);
    Engine resolved(resolvedProgram.program);
    using Clock = std::chrono::steady_clock;
    constexpr int kBlock = 200;
    double plainNs = 0;
    double resolvedNs = 0;
    auto block = [&](Engine &e) {
        const auto start = Clock::now();
        for (int k = 0; k < kBlock; ++k)
            e.scan();
        return std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    };
    for (auto _ : state) {
        plainNs += block(plain);
        resolvedNs += block(resolved);
    }
    const double scans = static_cast<double>(state.iterations()) * kBlock;
    state.counters["plain_ns_per_scan"] = plainNs / scans;
    state.counters["resolved_ns_per_scan"] = resolvedNs / scans;
    state.counters["ratio"] = plainNs > 0 ? resolvedNs / plainNs : 0;
}

void BM_TrafficLight24Hours(benchmark::State &state) {
    for (auto _ : state) {
        Fixture f(QString::fromLatin1(kTrafficLight));
        f.engine.setPeriodMs(10);
        f.engine.runFor(24LL * 3600 * 1000);
        benchmark::DoNotOptimize(f.engine.statistics().scans);
    }
}

// The same 24 h on the real Vigor table and listing, as a user's simulation runs it.
void BM_TrafficLight24HoursVigorListing(benchmark::State &state) {
    QFile file(QStringLiteral(RUNG_TEST_DATA_DIR "/sim/vigor_traffic_light.il"));
    if (!file.open(QIODevice::ReadOnly)) {
        state.SkipWithError("vigor_traffic_light.il not found");
        return;
    }
    const model::ParseResult parsed = model::parseInstructionList(
        model::Target::get(model::Family::Vigor), QString::fromUtf8(file.readAll()));
    const CompileResult compiled = parsed.ok() ? compileProgram(parsed.list) : CompileResult{};
    if (!compiled.ok()) {
        state.SkipWithError("the traffic light did not compile");
        return;
    }
    for (auto _ : state) {
        Engine engine(compiled.program);
        engine.setPeriodMs(10);
        engine.runFor(24LL * 3600 * 1000);
        benchmark::DoNotOptimize(engine.statistics().scans);
    }
}

} // namespace

// Repetitions give medians (the figures docs/simulator.md quotes).
BENCHMARK(BM_Scan2048Steps)->Repetitions(5)->DisplayAggregatesOnly(true);
BENCHMARK(BM_Scan2048StepsWithPowerFlow)->Repetitions(5)->DisplayAggregatesOnly(true);
BENCHMARK(BM_PowerFlowRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_HistoryRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_ResolvedOperandsRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_TrafficLight24Hours)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
BENCHMARK(BM_TrafficLight24HoursVigorListing)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);

BENCHMARK_MAIN();
