// bench::MedianLimit (median_limit.h) judged through the benchmark library itself: scripted
// figures for each repetition, the library's own rising iteration counts in the first, and the
// report checked afterwards. Exit 0 when every check holds; each failed check is printed.
// What broke before it: an error in the first repetition of five crashed the library while it
// computed the aggregates, and the report was lost (the process ends in SIGSEGV here then).

#include "tests/benchmarks/median_limit.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using rung::bench::MedianLimit;

// The figure of a call: script[k] for the k-th call with the same iteration count as the call
// before (the library's estimation calls of the first repetition each get script[0], which
// the judge must not count; the five repetitions get script[0..4]).
double scripted(benchmark::State &state, const std::vector<double> &script, long long &count,
                std::size_t &k) {
    if (state.iterations() != count) {
        count = state.iterations();
        k = 0;
    }
    return script[std::min(k++, script.size() - 1)];
}

void spin(benchmark::State &state) {
    int x = 0;
    for (auto _ : state)
        benchmark::DoNotOptimize(++x);
}

// Over the limit in the first repetition only (the one that crashed the library), 1.2x the
// median of five: over 1.15x, so the last repetition errors with every figure.
void BM_MedianOver(benchmark::State &state) {
    static long long count = -1;
    static std::size_t k = 0;
    spin(state);
    static MedianLimit limit("BM_MedianOver", 5);
    limit.judge(state, "ratio", scripted(state, {2.0, 1.0, 1.1, 1.2, 1.3}, count, k), 1.15,
                "the figure");
}

// The first repetition over the limit, the median (1.1x) under it: no error.
void BM_MedianUnder(benchmark::State &state) {
    static long long count = -1;
    static std::size_t k = 0;
    spin(state);
    static MedianLimit limit("BM_MedianUnder", 5);
    limit.judge(state, "ratio", scripted(state, {2.0, 1.0, 1.1, 1.0, 1.2}, count, k), 1.15,
                "the figure");
}

// An error that is not about time in the first repetition: kept, reported by the last.
void BM_ErrorKept(benchmark::State &state) {
    static long long count = -1;
    static std::size_t k = 0;
    spin(state);
    const double v = scripted(state, {1.0, 1.0, 1.0, 1.0, 1.0}, count, k);
    static MedianLimit limit("BM_ErrorKept", 5);
    limit.judge(state, "ratio", v, 1.15, "the figure", k == 1 ? "the image differs" : "");
}

class Collect : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run> &runs) override {
        all.insert(all.end(), runs.begin(), runs.end());
        ConsoleReporter::ReportRuns(runs);
    }
    std::vector<Run> all;
};

} // namespace

BENCHMARK(BM_MedianOver)->Repetitions(5);
BENCHMARK(BM_MedianUnder)->Repetitions(5);
BENCHMARK(BM_ErrorKept)->Repetitions(5);

int main(int argc, char **argv) {
    benchmark::Initialize(&argc, argv);
    Collect report;
    benchmark::RunSpecifiedBenchmarks(&report);
    int failed = 0;
    auto check = [&](bool ok, const std::string &what) {
        std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
        failed += ok ? 0 : 1;
    };
    auto runs = [&](const std::string &name) {
        std::vector<benchmark::BenchmarkReporter::Run> out;
        for (const auto &r : report.all)
            if (r.run_name.function_name == name)
                out.push_back(r);
        return out;
    };
    auto errors = [](const std::vector<benchmark::BenchmarkReporter::Run> &rs) {
        std::vector<std::string> out;
        for (const auto &r : rs)
            if (r.error_occurred)
                out.push_back(r.error_message);
        return out;
    };
    auto hasMedian = [](const std::vector<benchmark::BenchmarkReporter::Run> &rs) {
        for (const auto &r : rs)
            if (r.run_type == benchmark::BenchmarkReporter::Run::RT_Aggregate &&
                r.aggregate_name == "median")
                return true;
        return false;
    };

    const auto over = runs("BM_MedianOver");
    check(over.size() >= 5 && !over[0].error_occurred && over[4].error_occurred,
          "BM_MedianOver: the first repetition passes, the last errors");
    check(errors(over) == std::vector<std::string>{"the figure costs more than its limit 1.150x: "
                                                   "median 1.200x of 2.000x 1.000x 1.100x "
                                                   "1.200x 1.300x"},
          "BM_MedianOver: one error, the median of the five repetitions and each figure (" +
              (errors(over).empty() ? std::string("none") : errors(over).front()) + ")");
    check(hasMedian(over), "BM_MedianOver: the aggregates are reported");

    const auto under = runs("BM_MedianUnder");
    check(under.size() >= 5 && errors(under).empty(), "BM_MedianUnder: no error");
    check(hasMedian(under), "BM_MedianUnder: the aggregates are reported");

    const auto kept = runs("BM_ErrorKept");
    check(errors(kept) == std::vector<std::string>{"the image differs"} && kept.size() >= 5 &&
              kept[4].error_occurred,
          "BM_ErrorKept: the first repetition's error, reported by the last");
    return failed == 0 ? 0 : 1;
}
