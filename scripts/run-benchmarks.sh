#!/usr/bin/env bash
# Runs every benchmark program of a build and fails loudly on any that breaks.
#   bash scripts/run-benchmarks.sh BUILD_DIR           each benchmark briefly (an optimised
#                                                      build: the figures are worth reading)
#   bash scripts/run-benchmarks.sh BUILD_DIR --smoke   each benchmark once, on its small
#                                                      workload (RUNG_BENCH_SMOKE=1,
#                                                      tests/benchmarks/smoke.h): what CI runs
#                                                      in the sanitizer build
# A benchmark that reports an error (SkipWithError: "ERROR OCCURRED"), crashes or exits
# non-zero fails the script, named with its program; each program's output is kept in
# BUILD_DIR/bench_NAME.log.
set -uo pipefail
build_dir="${1:?usage: bash scripts/run-benchmarks.sh BUILD_DIR [--smoke]}"
case "${2:-}" in
--smoke)
    export RUNG_BENCH_SMOKE=1
    # One iteration of whatever has no fixed count: the first run already passes the minimum.
    args=(--benchmark_min_time=0.000001)
    ;;
"") args=(--benchmark_min_time=0.01) ;;
*) echo "usage: bash scripts/run-benchmarks.sh BUILD_DIR [--smoke]" >&2; exit 2 ;;
esac
export QT_QPA_PLATFORM="${QT_QPA_PLATFORM:-offscreen}"
failed=()
ran=0
for b in "$build_dir"/tests/benchmarks/bench_*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
    name=$(basename "$b")
    log="$build_dir/$name.log"
    start=$(date +%s)
    "$b" "${args[@]}" >"$log" 2>&1
    status=$?
    ran=$((ran + 1))
    errors=$(grep -E "ERROR OCCURRED" "$log")
    if ((status != 0)) || [ -n "$errors" ] || ! grep -qE "^BM_|^[a-zA-Z]+(/|_| )" "$log"; then
        echo "----- $name (exit $status): $log"
        tail -n 40 "$log"
        if [ -n "$errors" ]; then
            echo "FAILED benchmarks of $name:"
            # The console line starts with the benchmark's name.
            echo "$errors" | awk '{print "  " $1 ": " substr($0, index($0, "ERROR OCCURRED"))}'
        fi
        failed+=("$name")
    else
        echo "$name: $(grep -cE "^[A-Za-z_]+[A-Za-z0-9_/:.<>-]* +[0-9.]+ [mun]?s " "$log") results, $(($(date +%s) - start)) s"
    fi
done
if ((ran == 0)); then
    echo "No benchmark program in $build_dir/tests/benchmarks" >&2
    exit 1
fi
if ((${#failed[@]})); then
    echo "Benchmarks failed: ${failed[*]}" >&2
    exit 1
fi
