// Conversion speed (issue 2, section 9): 10,000 rungs of mixed logic IL -> ladder -> IL,
// target <= 1 s on the 2-core machine, per target and per direction, plus the plain-text
// ladder. The program comes from the property tests' random generator (series/parallel
// blocks in fuzzy orders, several outputs per rung, MPS branches, two-input boxes).

#include "tests/benchmarks/smoke.h"
#include "tests/model/random_program.cpp"

#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"

#include <benchmark/benchmark.h>

#include <map>

using namespace rung::model;

namespace {

const int kRungs = rung::bench::sized(10000, 200);

const InstructionList &program(Family family) {
    static std::map<Family, InstructionList> cache;
    auto it = cache.find(family);
    if (it == cache.end()) {
        rung::testing::RandomProgramOptions o;
        o.rungs = kRungs;
        const Target &t = Target::get(family);
        it = cache
                 .emplace(family,
                          parseInstructionList(t, rung::testing::randomProgram(t, 7, o)).list)
                 .first;
    }
    return it->second;
}

void roundTrip(benchmark::State &state, Family family) {
    const InstructionList &list = program(family);
    for (auto _ : state) {
        ToLadderResult ladder = listToLadder(list);
        ToListingResult back = ladderToList(ladder.ladder);
        benchmark::DoNotOptimize(back.list.instructions.data());
    }
    state.counters["rungs"] = kRungs;
    state.counters["instructions"] = static_cast<double>(list.instructions.size());
}

void listToLadderOnly(benchmark::State &state, Family family) {
    const InstructionList &list = program(family);
    for (auto _ : state) {
        ToLadderResult ladder = listToLadder(list);
        benchmark::DoNotOptimize(ladder.ladder.rungs.data());
    }
}

void ladderToListOnly(benchmark::State &state, Family family) {
    const LadderProgram ladder = listToLadder(program(family)).ladder;
    for (auto _ : state) {
        ToListingResult back = ladderToList(ladder);
        benchmark::DoNotOptimize(back.list.instructions.data());
    }
}

void ladderTextRoundTrip(benchmark::State &state, Family family) {
    const LadderProgram ladder = listToLadder(program(family)).ladder;
    const Target &t = Target::get(family);
    for (auto _ : state) {
        LadderTextResult back = parseLadderText(t, printLadderText(ladder));
        benchmark::DoNotOptimize(back.ladder.rungs.data());
    }
}

} // namespace

BENCHMARK_CAPTURE(roundTrip, vpc, Family::Vpc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(roundTrip, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(roundTrip, cpm1, Family::Cpm1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(roundTrip, pl110, Family::Pl110)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(listToLadderOnly, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ladderToListOnly, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ladderTextRoundTrip, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
