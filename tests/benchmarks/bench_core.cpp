// The core's speed (issue 2, section 9): 10,000 rungs of mixed logic through IL -> ladder ->
// IL (target <= 1 s) and through every check (target <= 0.5 s), on this 2-core machine class.
// The program comes from the property tests' random generator: series/parallel blocks in
// fuzzy orders, several outputs per rung, MPS branches, KEEP boxes.

#include "tests/benchmarks/smoke.h"
#include "tests/model/random_program.cpp"

#include "model/checks/checks.h"
#include "model/convert/convert.h"

#include <benchmark/benchmark.h>

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
        ParseResult parsed = parseInstructionList(t, rung::testing::randomProgram(t, 42, o));
        it = cache.emplace(family, parsed.list).first;
    }
    return it->second;
}

void listToLadderToList(benchmark::State &state, Family family) {
    const InstructionList &list = program(family);
    for (auto _ : state) {
        ToLadderResult ladder = listToLadder(list);
        ToListingResult back = ladderToList(ladder.ladder);
        benchmark::DoNotOptimize(back.list.instructions.data());
    }
    state.counters["rungs"] = kRungs;
    state.counters["instructions"] = static_cast<double>(list.instructions.size());
}

void allChecksOnTheListing(benchmark::State &state, Family family) {
    const InstructionList &list = program(family);
    std::size_t findings = 0;
    for (auto _ : state) {
        auto ds = checkList(list);
        findings = ds.size();
        benchmark::DoNotOptimize(ds.data());
    }
    state.counters["findings"] = static_cast<double>(findings);
}

void allChecksOnTheLadder(benchmark::State &state, Family family) {
    const LadderProgram ladder = listToLadder(program(family)).ladder;
    for (auto _ : state) {
        auto ds = checkLadder(ladder);
        benchmark::DoNotOptimize(ds.data());
    }
}

void parseListing(benchmark::State &state) {
    const Target &t = Target::get(Family::Vigor);
    rung::testing::RandomProgramOptions o;
    o.rungs = kRungs;
    const QString text = rung::testing::randomProgram(t, 42, o);
    for (auto _ : state) {
        ParseResult r = parseInstructionList(t, text);
        benchmark::DoNotOptimize(r.list.instructions.data());
    }
}

} // namespace

BENCHMARK_CAPTURE(listToLadderToList, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(listToLadderToList, vpc, Family::Vpc)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(listToLadderToList, cpm1, Family::Cpm1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(allChecksOnTheListing, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(allChecksOnTheLadder, vigor, Family::Vigor)->Unit(benchmark::kMillisecond);
BENCHMARK(parseListing)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
