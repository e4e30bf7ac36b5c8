#!/usr/bin/env bash
# Installs what is missing, builds everything (warnings are errors) and runs every test.
#   bash scripts/test.sh              AddressSanitizer + UndefinedBehaviorSanitizer build in
#                                     build-asan running every test and benchmark, then the
#                                     threaded tests under ThreadSanitizer in build-tsan
#                                     (what CI runs: .ci/run)
#   bash scripts/test.sh --optimised  the same tests and benchmarks from an optimised build
#                                     (RelWithDebInfo) in build-test, no sanitizers: quicker
#                                     to run while working, and the build the figures in
#                                     docs/performance.md come from
# Any failure or sanitizer report fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=1
case "${1:-}" in
--optimised) sanitize=0 ;;
--sanitize | "") ;;
*) echo "usage: bash scripts/test.sh [--optimised]" >&2; exit 2 ;;
esac
bash scripts/install-deps.sh
start=$(date +%s)

if ((sanitize)); then
    build_dir="${RUNG_BUILD_DIR:-build-asan}"
    # Line tables (-g1) are all a sanitizer report needs, and compile faster than full -g.
    config=(-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DRUNG_SANITIZE=ON)
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
    build_dir="${RUNG_BUILD_DIR:-build-test}"
    config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
fi
cmake -S . -B "$build_dir" -G Ninja -DRUNG_WERROR=ON "${config[@]}" ${RUNG_CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
echo "Build: $(($(date +%s) - start)) s"
export QT_QPA_PLATFORM=offscreen
# Every benchmark builds with the rest. The optimised build runs each briefly, so they keep
# running; the figures are for reading (docs/performance.md). Under the sanitizers their
# whole-program workloads (10,000 rungs, 24 simulated hours) take minutes, so there they only
# start and list themselves.
if ((sanitize)); then
    bench_args=(--benchmark_list_tests=true)
else
    bench_args=(--benchmark_min_time=0.01)
fi
for b in "$build_dir"/tests/benchmarks/bench_*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
    log="$build_dir/$(basename "$b").log"
    "$b" "${bench_args[@]}" >"$log" 2>&1 || { cat "$log"; echo "FAILED: $b"; exit 1; }
done
echo "Build and benchmark runs: $(($(date +%s) - start)) s"
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" --timeout 600
echo "Build, benchmarks and tests: $(($(date +%s) - start)) s"

if ((sanitize)); then
    # ThreadSanitizer: only the binaries with threads, no GUI, no benchmarks, so the stage
    # stays small. Qt itself is not instrumented: its cross-thread event posting is not seen
    # as synchronisation, hence the suppressions of reports inside libQt6Core alone.
    tsan_start=$(date +%s)
    cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 \
        -DRUNG_WERROR=ON -DRUNG_TSAN=ON -DRUNG_BUILD_GUI=OFF -DRUNG_BUILD_BENCHMARKS=OFF >/dev/null
    cmake --build build-tsan -j "$(nproc)" --target test_simulator test_comms
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
    # The simulator's session, inbox and history; all of comms (the online session, the slave
    # server, the relay, the drivers against real Modbus peers): ~15 s under TSan.
    build-tsan/tests/test_simulator --gtest_brief=1
    build-tsan/tests/test_comms --gtest_brief=1
    echo "ThreadSanitizer stage: $(($(date +%s) - tsan_start)) s"
fi
# The summary closes the output.
echo "All tests passed in $(($(date +%s) - start)) s"
