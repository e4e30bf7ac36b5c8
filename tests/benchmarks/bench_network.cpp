// Issue 29's speed: eight Vigor stations in CPU Link (mode 1, the manual's network scan time
// for 8 stations: 31 ms), each running a program of about 1,000 steps every 10 ms of virtual
// time, as fast as the machine runs them. BM_NetworkCpuLink8 reports how many times faster
// than real time the network runs (realtime_x); BM_NetworkCostRatio times the network's turn
// beside the same eight engines scanning alone in the same run, alternating, and reports
// their ratio (the network's cost: the CPU Link exchange, the clock, the ports), limit 1.10.

#include "median_limit.h"
#include "network_program.h"
#include "smoke.h"

#include "network/network.h"
#include "network/network_history.h"
#include "network/station.h"

#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

namespace {

using namespace rung;

using bench::thousandSteps;

// The ratio benchmarks' repetitions: their limits are on the median (bench::MedianLimit).
const int kRatioRepetitions = bench::times(5);

// The CPU time of this thread so far, in seconds: what a block took of the processor, without
// the time the thread waited for it while other processes ran (on a shared machine the wall
// time of a block of 1,000 slices, 5-15 ms, is often that of a scheduler's slice more).
double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

network::ProgramLoader loader(bool busy = false) {
    return [busy](const network::StationDescription &s, network::LoadedStation *loaded,
                  QString *error) {
        const model::Target *target = model::Target::byId(QStringLiteral("vigor"));
        const model::ModelVariant *variant = target->model(QStringLiteral("VB"));
        const model::ParseResult parsed = model::parseInstructionList(
            *target, thousandSteps(s.name.mid(1).toInt(), busy), variant);
        model::CheckOptions checks;
        checks.model = variant;
        const simulator::CompileResult compiled =
            parsed.ok() ? simulator::prepareProgram(parsed.list, checks)
                        : simulator::CompileResult{};
        if (!compiled.ok()) {
            *error = QStringLiteral("the benchmark's program does not compile");
            return false;
        }
        loaded->program = compiled.program;
        loaded->target = target;
        loaded->model = variant;
        return true;
    };
}

std::unique_ptr<network::Network> eightInCpuLink(QString *error, bool busy = false) {
    QString stations;
    QStringList ends;
    for (int k = 0; k < 8; ++k) {
        stations += QStringLiteral(R"(%1{"name": "s%2", "program": "p.il", "model": "VB",
            "ports": {"CP2": {"application": "cpu-link", "station": %2%3}}})")
                        .arg(k ? QStringLiteral(",") : QString())
                        .arg(k)
                        .arg(k ? QString() : QStringLiteral(R"(, "slaves": 7, "range": 1)"));
        ends << QStringLiteral("\"s%1/CP2\"").arg(k);
    }
    network::NetworkDescription d;
    if (!network::parseNetwork(QStringLiteral(R"({"stations": [%1], "wires": [[%2]]})")
                                   .arg(stations, ends.join(QLatin1Char(',')))
                                   .toUtf8(),
                               QStringLiteral("bench.rungnet"), &d, error))
        return nullptr;
    return network::Network::build(d, loader(busy), error);
}

void BM_NetworkCpuLink8(benchmark::State &state) {
    QString error;
    auto net = eightInCpuLink(&error);
    if (!net) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    qint64 virtualUs = 0;
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) {
        virtualUs += 10'000;
        net->runUntil(virtualUs);
    }
    const double real =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (virtualUs >= 31'000 &&
        net->station(QStringLiteral("s1"))
                ->engine()
                .value(std::get<model::Address>(model::parseAddress(
                    net->stations().front()->target(), QStringLiteral("D9201")))) != 31) {
        state.SkipWithError("the CPU Link did not run at its 31 ms network scan time");
        return;
    }
    // Virtual time over the real time it took (issue 29: at least 1,000 times real time).
    const double factor = double(virtualUs) / 1e6 / std::max(1e-12, real);
    state.counters["realtime_x"] = factor;
    if (bench::judgesTime() && state.iterations() > 1000 && factor < 1000)
        state.SkipWithError("the network runs less than 1,000 times faster than real time");
}

void BM_NetworkCostRatio(benchmark::State &state) {
    QString error;
    auto net = eightInCpuLink(&error);
    if (!net) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    // The same eight programs on engines of their own, no network.
    std::vector<std::unique_ptr<simulator::Engine>> plain;
    for (const auto &s : net->stations()) {
        network::StationDescription d;
        d.name = s->name();
        network::LoadedStation loaded;
        if (!loader()(d, &loaded, &error)) {
            state.SkipWithError(error.toStdString().c_str());
            return;
        }
        plain.push_back(std::make_unique<simulator::Engine>(loaded.program));
        plain.back()->setPeriodMs(10);
    }
    using Clock = std::chrono::steady_clock;
    const int block = bench::sized(1000, 2);
    // Warm both up (the first exchange resolves the status devices; the caches fill).
    qint64 virtualUs = 100'000;
    net->runUntil(virtualUs);
    for (int k = 0; k < 10; ++k)
        for (auto &e : plain)
            e->scan();
    Clock::duration inNetwork{}, alone{};
    for (auto _ : state) {
        const auto a = Clock::now();
        for (int k = 0; k < block; ++k) {
            virtualUs += 10'000;
            net->runUntil(virtualUs);
        }
        const auto b = Clock::now();
        for (int k = 0; k < block; ++k)
            for (auto &e : plain)
                e->scan();
        const auto c = Clock::now();
        inNetwork += b - a;
        alone += c - b;
    }
    const double ratio = std::chrono::duration<double>(inNetwork).count() /
                         std::max(1e-12, std::chrono::duration<double>(alone).count());
    static bench::MedianLimit limit("BM_NetworkCostRatio", kRatioRepetitions);
    limit.judge(state, "ratio", ratio, 1.10, "the network's turn beside the plain scans");
}

// History across the network (network/network_history.h): the same eight stations run in two
// networks side by side, one plain, one recording every station after every 10 ms slice;
// alternating blocks of 1,000 slices; ratio = recording / plain. Argument 1: the busy
// programs (59 registers of each station change every scan, the worst the recording sees).
void BM_NetworkHistoryRatio(benchmark::State &state) {
    const bool busy = state.range(0) != 0;
    QString error;
    auto plain = eightInCpuLink(&error, busy);
    auto recorded = eightInCpuLink(&error, busy);
    if (!plain || !recorded) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    network::NetworkHistory history;
    history.start(*recorded);
    using Clock = std::chrono::steady_clock;
    const int block = bench::sized(1000, 2);
    qint64 virtualUs = 100'000;
    plain->runUntil(virtualUs);
    recorded->runUntil(virtualUs);
    history.record(*recorded, false);
    Clock::duration withHistory{}, without{};
    double cpuWith = 0, cpuWithout = 0;
    for (auto _ : state) {
        qint64 us = virtualUs;
        const double ca = threadCpuSeconds();
        const auto a = Clock::now();
        for (int k = 0; k < block; ++k) {
            us += 10'000;
            plain->runUntil(us);
        }
        const auto b = Clock::now();
        const double cb = threadCpuSeconds();
        us = virtualUs;
        for (int k = 0; k < block; ++k) {
            us += 10'000;
            recorded->runUntil(us);
            history.record(*recorded, false);
        }
        const auto c = Clock::now();
        const double cc = threadCpuSeconds();
        cpuWithout += cb - ca;
        cpuWith += cc - cb;
        virtualUs = us;
        without += b - a;
        withHistory += c - b;
    }
    const double ratio = std::chrono::duration<double>(withHistory).count() /
                         std::max(1e-12, std::chrono::duration<double>(without).count());
    // The same of the thread's CPU time (reported; the limit is on the wall time's ratio).
    state.counters["cpu_ratio"] = cpuWith / std::max(1e-12, cpuWithout);
    // Recorded exactly: the newest instant is the network as it is.
    const auto now = history.stationAt(3, recorded->nowUs());
    const bool exact = now && now->words == std::vector<std::int32_t>(
                                                recorded->stations()[3]->engine().words().begin(),
                                                recorded->stations()[3]->engine().words().end());
    static bench::MedianLimit limits[2] = {{"BM_NetworkHistoryRatio/0", kRatioRepetitions},
                                           {"BM_NetworkHistoryRatio/1", kRatioRepetitions}};
    limits[busy].judge(state, "ratio", ratio, busy ? 1.5 : 1.25, "recording the history",
                       exact ? "" : "the history does not show the network as it is");
}

// A minute of virtual time of the eight stations recorded (6,000 slices of 10 ms): the memory
// it takes (MB_minute), how many minutes the default budget (128 MB) therefore keeps, and how
// long showing an instant takes (every station rebuilt; the timed part), the instant farthest
// from its key (the worst) and random ones. Argument 1: the busy programs.
void BM_NetworkHistoryMinute(benchmark::State &state) {
    const bool busy = state.range(0) != 0;
    QString error;
    auto net = eightInCpuLink(&error, busy);
    if (!net) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    network::NetworkHistory history;
    history.start(*net);
    const int slices = bench::sized(6000, 50);
    for (int k = 1; k <= slices; ++k) {
        net->runUntil(qint64(k) * 10'000);
        history.record(*net, false);
    }
    const network::NetworkHistory::Window w = history.window();
    const double mb = double(w.bytes) / (1024.0 * 1024.0) * 6000.0 / slices;
    std::uint64_t seed = 12345;
    std::size_t shown = 0;
    for (auto _ : state) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        const qint64 us = qint64(seed >> 33) % (w.lastUs + 1);
        const auto all = history.at(us);
        shown += all ? all->size() : 0;
        benchmark::DoNotOptimize(all);
    }
    if (shown != state.iterations() * net->stations().size()) {
        state.SkipWithError("an instant of the window was not shown");
        return;
    }
    state.counters["MB_minute"] = mb;
    state.counters["minutes_kept"] = 128.0 / std::max(1e-9, mb);
    state.counters["keys"] = double(w.keys);
    if (bench::judgesTime() && mb > (busy ? 64.0 : 16.0))
        state.SkipWithError("a minute of history takes more memory than its limit");
}

} // namespace

BENCHMARK(BM_NetworkCpuLink8)->Unit(benchmark::kMicrosecond);
// Every repetition's row is shown (DisplayAggregatesOnly would hide the last one's error).
BENCHMARK(BM_NetworkCostRatio)->Unit(benchmark::kMillisecond)->Repetitions(kRatioRepetitions);
BENCHMARK(BM_NetworkHistoryRatio)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(kRatioRepetitions);
BENCHMARK(BM_NetworkHistoryMinute)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
