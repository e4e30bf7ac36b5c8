#pragma once

// A limit stated on the median of a benchmark's repetitions (docs/performance.md: "the ratios:
// 5 repetitions, median"), judged once, on the last repetition, with every repetition's figure
// in the error. Judging each repetition on its own (SkipWithError in every one over the limit)
// lost the whole report: Debian's libbenchmark 1.7.1 reads the statistics settings of the
// first repetition's run when it computes the aggregates, which an errored run does not have,
// and crashed (SIGSEGV) whenever the first repetition errored and two others did not
// (benchmark::ComputeStats). Only the last repetition errors here, so the aggregates come
// from the runs before it and the report is printed whole.
//
// Which call of the benchmark's function is its last repetition: the library runs the first
// repetition with rising iteration counts until one is long enough (each count larger than
// the one before), then every other repetition with that count; so the calls that end with
// `repetitions` runs of the same count end the benchmark. Register such a benchmark without
// DisplayAggregatesOnly: that hides the runs, and with them the last repetition's error.

#include "smoke.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rung::bench {

class MedianLimit {
public:
    // key: the benchmark and its arguments; repetitions: as registered (Repetitions).
    MedianLimit(std::string key, int repetitions)
        : m_key(std::move(key))
        , m_repetitions(std::max(1, repetitions)) {}

    // One run of the benchmark (this call of its function): its figure, and what went wrong
    // in it that is not about time (empty: nothing), kept for the last repetition (the first
    // such error of any call since the benchmark's last repetition before). Sets the
    // counter `counter`. On the last repetition: the first error any repetition saw, else,
    // in a measuring run (judgesTime), whether the median is over `limit`; `what` names what
    // costs more than its limit.
    void judge(benchmark::State &state, const char *counter, double value, double limit,
               const std::string &what, const std::string &error = {}) {
        state.counters[counter] = value;
        Runs &runs = table()[m_key];
        const auto iterations = static_cast<long long>(state.iterations());
        if (runs.iterations != iterations) {
            runs.values.clear(); // a count the next repetitions may repeat
            runs.iterations = iterations;
        }
        runs.values.push_back(value);
        if (runs.error.empty())
            runs.error = error;
        if (int(runs.values.size()) < m_repetitions)
            return;
        const std::vector<double> values = std::move(runs.values);
        const std::string first = std::move(runs.error);
        table().erase(m_key); // a later run of the same benchmark starts again
        if (!first.empty()) {
            state.SkipWithError(first.c_str());
            return;
        }
        const double middle = median(values);
        if (!judgesTime() || middle <= limit)
            return;
        std::string why = what + " costs more than its limit " + number(limit) + ": median " +
                          number(middle) + " of";
        for (double v : values)
            why += " " + number(v);
        state.SkipWithError(why.c_str());
    }

    static double median(std::vector<double> v) {
        if (v.empty())
            return 0;
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    }

private:
    struct Runs {
        long long iterations = -1;
        std::vector<double> values; // of the calls with this count, in order
        std::string error;
    };
    static std::map<std::string, Runs> &table() {
        static std::map<std::string, Runs> runs;
        return runs;
    }
    static std::string number(double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3fx", v);
        return text;
    }
    std::string m_key;
    int m_repetitions;
};

} // namespace rung::bench
