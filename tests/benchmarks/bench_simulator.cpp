// Scan speed of the simulator (issue 3): a 2048-step mixed program, the same with power-flow
// recording, and the STL traffic light over 24 h of virtual time at 10 ms scans.
// Runs on the synthetic Vigor-like target of the engine tests so it does not depend on the
// device tables; the instruction mix is what a real program holds.

#include "tests/benchmarks/compiled_scan.h"
#include "tests/benchmarks/hand_written/mixed_scan.h"
#include "tests/benchmarks/mixed_program.h"
#include "tests/benchmarks/smoke.h"
#include "tests/model/random_program.cpp"
#include "tests/simulator/sim_test_target.h"

#include "model/image/history.h"
#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"
#include "simulator/scan_history.h"

#include "model/target/address.h"
#include "simulator/session.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace rung;
using namespace rung::simulator;
using rung::bench::mixedProgram;

namespace {

// Traffic light (PLC concepts (WPLSoft family) 1.9 example 16): red 35 s, yellow 5 s, green
// 25 s, green blinking 5 s; the same program as tests/data/sim/vigor_traffic_light.il.
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

// One scan of the 10,000-rung program of bench_core (the property tests' random Vigor program:
// series / parallel blocks, several outputs a rung, MPS branches, KEEP boxes) on the real
// Vigor table; its inputs X0..X7 change every 8 scans.
void BM_Scan10000Rungs(benchmark::State &state) {
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    testing::RandomProgramOptions o;
    o.rungs = bench::sized(10000, 200);
    const model::ParseResult parsed =
        model::parseInstructionList(vigor, testing::randomProgram(vigor, 42, o));
    const CompileResult compiled = parsed.ok() ? compileProgram(parsed.list) : CompileResult{};
    if (!compiled.ok()) {
        state.SkipWithError("the 10,000-rung program did not compile");
        return;
    }
    Engine engine(compiled.program);
    std::vector<model::Address> inputs;
    for (int k = 0; k < 8; ++k)
        inputs.push_back(
            std::get<model::Address>(model::parseAddress(vigor, QStringLiteral("X%1").arg(k))));
    quint64 k = 0;
    for (auto _ : state) {
        const quint64 pattern = ++k / 8;
        for (std::size_t i = 0; i < inputs.size(); ++i)
            engine.setBit(inputs[i], ((pattern * 0x9E3779B97F4A7C15ull) >> (40 + i)) & 1u);
        engine.scan();
    }
    state.counters["steps"] = static_cast<double>(compiled.program->steps.size());
}

// A small PL110 program with no communication instruction (the timers of PL110 manual 4.2.4):
// what a scan's END costs beside the program when the PL110's ports are not used (issue 35:
// serviceComms ran every scan of every PL110 program).
void BM_ScanPl110NoPorts(benchmark::State &state) {
    const model::Target &pl110 = model::Target::get(model::Family::Pl110);
    const model::ParseResult parsed = model::parseInstructionList(
        pl110, QStringLiteral("LD I1\nTON T1 3 100\nLD I1\nTOFF T2 3 100\nLD I1\n"
                              "TONR T3 6 100\nLD T1\nOUT Q1\nEND\n"));
    const CompileResult compiled = parsed.ok() ? compileProgram(parsed.list) : CompileResult{};
    if (!compiled.ok() || !compiled.program->comms.empty()) {
        state.SkipWithError("the PL110 program did not compile");
        return;
    }
    Engine engine(compiled.program);
    const model::Address input = parsed.list.instructions[0].operands[0].address;
    int k = 0;
    for (auto _ : state) {
        engine.setBit(input, (++k & 8) != 0);
        engine.scan();
    }
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

// Two ways of scanning alternated in blocks of 1000 scans, so machine noise hits both alike:
// each block function runs its block and returns nothing; sets <a>_ns_per_scan,
// <b>_ns_per_scan and ratio = b / a.
template <typename A, typename B>
void alternate(benchmark::State &state, const char *nameA, A blockA, const char *nameB, B blockB) {
    using Clock = std::chrono::steady_clock;
    constexpr int kBlock = 1000;
    double aNs = 0;
    double bNs = 0;
    for (auto _ : state) {
        auto start = Clock::now();
        blockA(kBlock);
        aNs += std::chrono::duration<double, std::nano>(Clock::now() - start).count();
        start = Clock::now();
        blockB(kBlock);
        bNs += std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    }
    const double scans = static_cast<double>(state.iterations()) * kBlock;
    state.counters[std::string(nameA) + "_ns_per_scan"] = aNs / scans;
    state.counters[std::string(nameB) + "_ns_per_scan"] = bNs / scans;
    state.counters["ratio"] = aNs > 0 ? bNs / aNs : 0;
}

// The interpreter against compiled C++ of the same 2048 steps (issue 11: "the limit for an
// interpreter is compiled code"): the generated code (generator/gen_compiled_scan.cpp) is
// first checked to leave the engine's image scan after scan; ratio = engine / compiled.
void BM_CompiledRatio(benchmark::State &state) {
    Fixture f(mixedProgram());
    if (!f.result.ok() || bench::kCompiledSteps != 2048 ||
        bench::kCompiledWords != f.result.program->layout->wordCount()) {
        state.SkipWithError("the generated program is not the benchmark's");
        return;
    }
    const model::Address input = f.list.instructions[0].operands[0].address;
    const model::BitRef inputBit = f.result.program->layout->bit(input);
    std::vector<std::int32_t> words(static_cast<std::size_t>(bench::kCompiledWords), 0);
    std::vector<std::int32_t> stimulus(words.size(), 0);
    bench::CompiledState compiledState;
    int k = 0;
    auto stimulate = [&](int n) {
        const bool on = (n & 8) != 0;
        auto &w =
            reinterpret_cast<std::uint32_t &>(stimulus[static_cast<std::size_t>(inputBit.word)]);
        w = on ? (w | inputBit.mask) : (w & ~inputBit.mask);
        f.engine.setBit(input, on);
    };
    for (; k < 2000; ++k) { // the same logic: the same image after every scan
        stimulate(k);
        f.engine.scan();
        bench::compiledScan(words.data(), stimulus.data(), compiledState, 10);
        const auto engineWords = f.engine.words();
        if (words.size() != engineWords.size() ||
            !std::equal(words.begin(), words.end(), engineWords.begin())) {
            std::string why;
            if (words.size() != engineWords.size()) {
                why = QStringLiteral("the compiled program holds %1 words, the engine %2")
                          .arg(words.size())
                          .arg(engineWords.size())
                          .toStdString();
            } else {
                const auto diff = std::mismatch(words.begin(), words.end(), engineWords.begin());
                why = QStringLiteral("the compiled program and the engine differ after scan %1: "
                                     "word %2 is %3 compiled, %4 in the engine")
                          .arg(k)
                          .arg(diff.first - words.begin())
                          .arg(*diff.first)
                          .arg(*diff.second)
                          .toStdString();
            }
            state.SkipWithError(why.c_str());
            return;
        }
    }
    int a = k;
    int b = k;
    alternate(
        state, "compiled",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++a) {
                const bool on = (a & 8) != 0;
                auto &w = reinterpret_cast<std::uint32_t &>(
                    stimulus[static_cast<std::size_t>(inputBit.word)]);
                w = on ? (w | inputBit.mask) : (w & ~inputBit.mask);
                bench::compiledScan(words.data(), stimulus.data(), compiledState, 10);
            }
        },
        "engine",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++b) {
                f.engine.setBit(input, (b & 8) != 0);
                f.engine.scan();
            }
        });
    benchmark::DoNotOptimize(words.data());
}

// The goal of issue 35: the engine against the same logic written by hand in C++
// (hand_written/mixed_scan.cpp: arrays of bool and 16-bit integers, one function a scan),
// checked first to leave the engine's image scan after scan, then blocks alternated; ratio =
// engine / hand-written (the goal: 3x at most).
void BM_HandWrittenRatio(benchmark::State &state) {
    Fixture f(mixedProgram());
    if (!f.result.ok() || f.list.instructions.size() != 2048) {
        state.SkipWithError("program did not compile to 2048 steps");
        return;
    }
    const MemoryLayout &layout = *f.result.program->layout;
    const model::Target &t = *f.target;
    auto address = [&](const QString &name) {
        const auto parsed = model::parseAddress(t, name);
        return std::get<model::Address>(parsed);
    };
    // Where each of the hand-written program's variables sits in the engine's image.
    bench::HandWrittenPlc plc;
    std::vector<std::pair<BitRef, const bool *>> bits;
    std::vector<std::pair<int, const std::int16_t *>> words;
    auto bitsOf = [&](const char *prefix, int first, int count, const bool *values) {
        for (int k = 0; k < count; ++k)
            bits.emplace_back(
                layout.bit(
                    address(QStringLiteral("%1%2").arg(QLatin1String(prefix)).arg(first + k))),
                values + k);
    };
    bitsOf("X", 0, 32, plc.X);
    bitsOf("Y", 0, 32, plc.Y);
    bitsOf("M", 0, 500, plc.M);
    bitsOf("SM", 9000, 16, plc.SM);
    bitsOf("T", 0, 32, plc.T);
    bitsOf("C", 0, 32, plc.C);
    for (int k = 0; k < 32; ++k) {
        const model::Address timer = address(QStringLiteral("T%1").arg(k));
        const model::Address counter = address(QStringLiteral("C%1").arg(k));
        words.emplace_back(layout.word(timer), plc.TV + k);
        words.emplace_back(layout.setValueWord(timer), plc.TS + k);
        words.emplace_back(layout.word(counter), plc.CV + k);
        words.emplace_back(layout.setValueWord(counter), plc.CS + k);
    }
    for (int k = 0; k < 100; ++k)
        words.emplace_back(layout.word(address(QStringLiteral("D%1").arg(k))), plc.D + k);
    std::vector<std::int32_t> image(static_cast<std::size_t>(layout.wordCount()), 0);
    auto imageOf = [&] {
        std::fill(image.begin(), image.end(), 0);
        for (const auto &[b, v] : bits)
            if (*v)
                image[static_cast<std::size_t>(b.word)] |= static_cast<std::int32_t>(b.mask);
        for (const auto &[w, v] : words)
            image[static_cast<std::size_t>(w)] = *v;
    };
    const model::Address input = f.list.instructions[0].operands[0].address; // X0
    bool inputs[32] = {};
    int k = 0;
    for (; k < 2000; ++k) { // the same logic: the same image after every scan
        inputs[0] = (k & 8) != 0;
        f.engine.setBit(input, inputs[0]);
        f.engine.scan();
        bench::handWrittenScan(plc, inputs, 10);
        imageOf();
        const auto engineWords = f.engine.words();
        if (!std::equal(image.begin(), image.end(), engineWords.begin(), engineWords.end())) {
            const auto diff = std::mismatch(image.begin(), image.end(), engineWords.begin());
            const std::string why =
                QStringLiteral("the hand-written program and the engine differ after scan %1: "
                               "word %2 is %3 hand-written, %4 in the engine")
                    .arg(k)
                    .arg(diff.first - image.begin())
                    .arg(*diff.first)
                    .arg(*diff.second)
                    .toStdString();
            state.SkipWithError(why.c_str());
            return;
        }
    }
    int a = k;
    int b = k;
    alternate(
        state, "hand_written",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++a) {
                inputs[0] = (a & 8) != 0;
                bench::handWrittenScan(plc, inputs, 10);
            }
        },
        "engine",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++b) {
                f.engine.setBit(input, (b & 8) != 0);
                f.engine.scan();
            }
        });
    benchmark::DoNotOptimize(plc.D);
}

// Breakpoints set (ten, on instructions spread over the program, with conditions that never
// hold) against none: scanToBreakpoint runs the scan in segments between them, so the scan
// should cost about the same (ratio = with breakpoints / plain).
void BM_BreakpointRatio(benchmark::State &state) {
    Fixture plain(mixedProgram());
    Fixture armed(mixedProgram());
    std::vector<Breakpoint> breakpoints;
    for (int k = 0; k < 10; ++k) {
        Breakpoint b;
        b.instruction = 100 + k * 190;
        b.when = Breakpoint::When::Compare;
        b.device = armed.list.instructions[14].operands[0].address; // a D word
        b.op = model::CompareOp::Eq;
        b.value = 99999; // never
        breakpoints.push_back(b);
    }
    if (!plain.result.ok() || !armed.engine.setBreakpoints(breakpoints)) {
        state.SkipWithError("breakpoints not set");
        return;
    }
    const model::Address input = plain.list.instructions[0].operands[0].address;
    int a = 0;
    int b = 0;
    alternate(
        state, "plain",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++a) {
                plain.engine.setBit(input, (a & 8) != 0);
                plain.engine.scan();
            }
        },
        "breakpoints",
        [&](int n) {
            for (int i = 0; i < n; ++i, ++b) {
                armed.engine.setBit(input, (b & 8) != 0);
                if (armed.engine.scanToBreakpoint() != ScanStop::Completed)
                    state.SkipWithError("a breakpoint that never holds stopped the scan");
            }
        });
}

// What the session's history adds to every scan (ScanHistory::afterScan: a sum and a compare,
// and a checkpoint each 10 ms of evaluation): ratio = recording / plain.
void BM_ScanHistoryRatio(benchmark::State &state) {
    Fixture plain(mixedProgram());
    Fixture recording(mixedProgram());
    ScanHistory history;
    history.start(recording.engine);
    sideBySide(state, plain, recording, "scan_history", [&](Fixture &f) {
        history.afterScan(f.engine, f.engine.statistics().execNsCurrent);
    });
    state.counters["history_MB"] = static_cast<double>(history.window().bytes) / 1e6;
}

// Jumping the history to any scan of the last hour of the traffic light at 10 ms scans (issue
// 11: <= 100 ms): an hour of the real Vigor listing recorded as a session records it (a lamp
// forced once a minute, checkpoints each 10 ms of evaluation), then rebuilds of scans spread
// over the hour. Reports the mean and the slowest jump and the history's memory.
void BM_HistoryJumpTrafficLightHour(benchmark::State &state) {
    QFile file(QStringLiteral(RUNG_TEST_DATA_DIR "/sim/vigor_traffic_light.il"));
    if (!file.open(QIODevice::ReadOnly)) {
        state.SkipWithError("vigor_traffic_light.il not found");
        return;
    }
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    const model::ParseResult parsed =
        model::parseInstructionList(vigor, QString::fromUtf8(file.readAll()));
    const CompileResult compiled = parsed.ok() ? compileProgram(parsed.list) : CompileResult{};
    if (!compiled.ok()) {
        state.SkipWithError("the traffic light did not compile");
        return;
    }
    Engine engine(compiled.program);
    engine.setPeriodMs(10);
    ScanHistory history;
    history.start(engine);
    const auto x0 = std::get<model::Address>(model::parseAddress(vigor, QStringLiteral("X0")));
    const quint64 kHour = static_cast<quint64>(bench::sized(360000, 6000)); // scans of 10 ms
    for (quint64 k = 0; k < kHour; ++k) {
        if (k % 6000 == 0) { // a stimulus once a minute, as a user's click
            const EngineCommand c{0, model::DeviceCommand{model::DeviceCommand::Kind::WriteBit, x0,
                                                          static_cast<qint64>((k / 6000) & 1)}};
            history.record(engine, c);
            applyCommand(engine, c, nullptr);
        }
        engine.scan();
        history.afterScan(engine, engine.statistics().execNsCurrent);
    }
    const ScanHistory::Window window = history.window();
    if (window.firstScan != 0 || window.lastScan != kHour) {
        state.SkipWithError("the hour is not all in the window");
        return;
    }
    std::mt19937_64 rng(42);
    double slowest = 0;
    double total = 0;
    int jumps = 0;
    for (auto _ : state) {
        const quint64 scan = rng() % (kHour + 1);
        const auto start = std::chrono::steady_clock::now();
        const auto snapshot = history.rebuild(scan);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        benchmark::DoNotOptimize(snapshot);
        if (!snapshot || snapshot->statistics.scans != scan) {
            state.SkipWithError("a scan was not rebuilt");
            return;
        }
        slowest = std::max(slowest, ms);
        total += ms;
        ++jumps;
    }
    state.counters["jump_mean_ms"] = jumps ? total / jumps : 0;
    state.counters["jump_max_ms"] = slowest;
    state.counters["checkpoints"] = static_cast<double>(window.checkpoints);
    state.counters["history_MB"] = static_cast<double>(window.bytes) / 1e6;
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

// 24 h of virtual time (ten minutes in a smoke run).
const qint64 kDayMs = bench::sized(24 * 3600, 600) * 1000LL;

void BM_TrafficLight24Hours(benchmark::State &state) {
    for (auto _ : state) {
        Fixture f(QString::fromLatin1(kTrafficLight));
        f.engine.setPeriodMs(10);
        f.engine.runFor(kDayMs);
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
        engine.runFor(kDayMs);
        benchmark::DoNotOptimize(engine.statistics().scans);
    }
}

} // namespace

// Repetitions give medians (the figures docs/simulator.md quotes).
BENCHMARK(BM_Scan2048Steps)->Repetitions(bench::times(5))->DisplayAggregatesOnly(true);
BENCHMARK(BM_Scan10000Rungs)->Repetitions(bench::times(3))->DisplayAggregatesOnly(true);
BENCHMARK(BM_ScanPl110NoPorts)->Repetitions(bench::times(3))->DisplayAggregatesOnly(true);
BENCHMARK(BM_Scan2048StepsWithPowerFlow)->Repetitions(bench::times(5))->DisplayAggregatesOnly(true);
BENCHMARK(BM_PowerFlowRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_HistoryRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_ResolvedOperandsRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_CompiledRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_HandWrittenRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_BreakpointRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_ScanHistoryRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_HistoryJumpTrafficLightHour)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(bench::times(200));
BENCHMARK(BM_SessionHistoryRatio)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(bench::times(4))
    ->Repetitions(bench::times(3))
    ->DisplayAggregatesOnly(true);
BENCHMARK(BM_TrafficLight24Hours)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(bench::times(1))
    ->Repetitions(bench::times(3));
BENCHMARK(BM_TrafficLight24HoursVigorListing)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(bench::times(1))
    ->Repetitions(bench::times(3));

BENCHMARK_MAIN();
