// Scan speed of the simulator (issue 3): a 2048-step mixed program, the same with power-flow
// recording, and the STL traffic light over 24 h of virtual time at 10 ms scans.
// Runs on the synthetic Vigor-like target of the engine tests so it does not depend on the
// device tables; the instruction mix is what a real program holds.

#include "tests/simulator/sim_test_target.h"

#include "model/image/history.h"
#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"
#include "simulator/session.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>

#include <benchmark/benchmark.h>

#include <chrono>
#include <limits>
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
    // The timing chart's trigger is armed too: evaluated after every recorded scan.
    model::Trigger trigger;
    trigger.device = recording.list.instructions[0].operands[0].address;
    trigger.action = model::Trigger::Action::Mark;
    history.setTrigger(trigger);
    sideBySide(state, plain, recording, "history", [&](Fixture &f) {
        history.record(f.engine.statistics().scans, f.engine.statistics().timeMs,
                       f.engine.words().data());
    });
    state.counters["history_MB"] = static_cast<double>(history.memoryBytes()) / 1e6;
}

// The same cost as a user meets it: two SimulatorSessions of the mixed program run as fast as
// possible on their worker threads, in turns of 150 ms, one plain and one with 1,000 devices
// recorded, a trigger armed and a reader copying the chart's window out of the history 30
// times a second (the timing chart's refresh) while it runs. Scans per second of each; the
// ratio is plain / recording (issue 11: <= 1.10).
void BM_SessionHistoryRatio(benchmark::State &state) {
    static int argc = 1;
    static char name[] = "bench_simulator";
    static char *argv[] = {name, nullptr};
    static QCoreApplication *app =
        QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv);
    Q_UNUSED(app);
    Fixture plainF(mixedProgram());
    Fixture withF(mixedProgram());
    if (!plainF.result.ok() || !withF.result.ok()) {
        state.SkipWithError("program did not compile");
        return;
    }
    SimulatorSession plain(plainF.result.program);
    SimulatorSession with(withF.result.program);
    model::MonitorSource &source = with;
    const model::Target &t = *withF.target;
    std::vector<model::Address> watched;
    for (std::size_t area = 0; area < t.areas.size() && watched.size() < 1000; ++area)
        for (int i = t.areas[area].first; i <= t.areas[area].last && watched.size() < 1000; ++i)
            if (source.watchHistory({static_cast<int>(area), i, -1}))
                watched.push_back({static_cast<int>(area), i, -1});
    model::Trigger trigger;
    trigger.device = withF.list.instructions[0].operands[0].address;
    trigger.action = model::Trigger::Action::Mark;
    source.setTrigger(trigger);
    const std::vector<model::Address> chart(watched.begin(), watched.begin() + 64);
    const auto turn = [&](SimulatorSession &s, bool read) {
        const quint64 before = s.snapshot() ? s.snapshot()->statistics.scans : 0;
        QElapsedTimer wall;
        wall.start();
        s.setSpeed(0);
        s.run();
        qint64 nextRead = 0;
        std::size_t copied = 0;
        while (wall.elapsed() < 150) {
            if (read && wall.elapsed() >= nextRead) {
                nextRead += 33;
                s.readHistory([&](const model::HistoryRecorder &h) {
                    for (const model::Address &a : chart)
                        copied += h.changes(a, 0, std::numeric_limits<qint64>::max() / 2).size();
                });
            }
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        }
        s.pause();
        const qint64 ms = wall.elapsed();
        // The paused worker publishes its last scan.
        QElapsedTimer settle;
        settle.start();
        while (settle.elapsed() < 50)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        benchmark::DoNotOptimize(copied);
        return std::pair{static_cast<double>(s.snapshot()->statistics.scans - before),
                         static_cast<double>(ms)};
    };
    double plainScans = 0, plainMs = 0, withScans = 0, withMs = 0;
    for (auto _ : state) {
        const auto [ps, pm] = turn(plain, false);
        const auto [ws, wm] = turn(with, true);
        plainScans += ps;
        plainMs += pm;
        withScans += ws;
        withMs += wm;
    }
    const double plainRate = plainScans / plainMs * 1000;
    const double withRate = withScans / withMs * 1000;
    state.counters["plain_scans_per_s"] = plainRate;
    state.counters["history_scans_per_s"] = withRate;
    state.counters["ratio"] = withRate > 0 ? plainRate / withRate : 0;
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
BENCHMARK(BM_SessionHistoryRatio)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(4)
    ->Repetitions(3)
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_TrafficLight24Hours)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
BENCHMARK(BM_TrafficLight24HoursVigorListing)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);

BENCHMARK_MAIN();
