#!/usr/bin/env bash
# Installs what is missing, builds everything (warnings are errors) and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build_dir="${RUNG_BUILD_DIR:-build-test}"
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRUNG_WERROR=ON \
    ${RUNG_CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
export QT_QPA_PLATFORM=offscreen
# A short run of every benchmark proves they still build and run; the figures are for reading.
for b in "$build_dir"/tests/benchmarks/bench_*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
    log="$build_dir/$(basename "$b").log"
    "$b" --benchmark_min_time=0.01 >"$log" 2>&1 || { cat "$log"; echo "FAILED: $b"; exit 1; }
done
# The tests run last, so their summary closes the output.
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" --timeout 600
