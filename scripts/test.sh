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
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" --timeout 600
# A short run of every benchmark proves they still build and run; the figures are for reading.
for b in "$build_dir"/tests/benchmarks/bench_*; do
    [ -f "$b" ] && [ -x "$b" ] || continue
    "$b" --benchmark_min_time=0.01 >/dev/null
done
