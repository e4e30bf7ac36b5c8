// Issue 29's speed: eight Vigor stations in CPU Link (mode 1, the manual's network scan time
// for 8 stations: 31 ms), each running a program of about 1,000 steps every 10 ms of virtual
// time, as fast as the machine runs them. BM_NetworkCpuLink8 reports how many times faster
// than real time the network runs (realtime_x); BM_NetworkCostRatio times the network's turn
// beside the same eight engines scanning alone in the same run, alternating, and reports
// their ratio (the network's cost: the CPU Link exchange, the clock, the ports), limit 1.10.

#include "smoke.h"

#include "network/network.h"
#include "network/station.h"

#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <benchmark/benchmark.h>

#include <chrono>

namespace {

using namespace rung;

// About 1,000 steps: 59 rungs of 17 (contacts, a coil, a move and an addition), then END.
QString thousandSteps(int station) {
    QString p = QStringLiteral("; target: vigor\n");
    for (int r = 0; r < 59; ++r)
        p += QStringLiteral("LD X%1\nAND M%2\nOR M%3\nOUT Y%4\nLD M9000\nMOV D%5 D%6\n"
                            "ADD D%6 K1 D%7\n")
                 .arg(QString::number(r % 8, 8))
                 .arg(r + 100)
                 .arg(r + 200)
                 .arg(QString::number(r % 16, 8))
                 .arg(station * 10 + r % 4)
                 .arg(100 + r)
                 .arg(300 + r);
    return p + QStringLiteral("END\n");
}

network::ProgramLoader loader() {
    return
        [](const network::StationDescription &s, network::LoadedStation *loaded, QString *error) {
            const model::Target *target = model::Target::byId(QStringLiteral("vigor"));
            const model::ModelVariant *variant = target->model(QStringLiteral("VB"));
            const model::ParseResult parsed =
                model::parseInstructionList(*target, thousandSteps(s.name.mid(1).toInt()), variant);
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

std::unique_ptr<network::Network> eightInCpuLink(QString *error) {
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
    return network::Network::build(d, loader(), error);
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
    state.counters["ratio"] = ratio;
    if (bench::judgesTime() && ratio > 1.10)
        state.SkipWithError("the network costs more than 1.10x the plain scans");
}

} // namespace

BENCHMARK(BM_NetworkCpuLink8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NetworkCostRatio)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(rung::bench::times(5))
    ->DisplayAggregatesOnly(true);
BENCHMARK_MAIN();
