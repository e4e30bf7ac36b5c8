#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
export RUNG_BUILD_DIR=build-asan
export RUNG_CMAKE_ARGS="-DRUNG_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug -DRUNG_BUILD_BENCHMARKS=OFF"
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
exec bash scripts/test.sh
