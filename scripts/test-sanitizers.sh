#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer and runs every test; then builds
# the simulator tests with ThreadSanitizer and runs them (the session, the command inbox and
# the history recorder run on several threads). Any report fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
(
    export RUNG_BUILD_DIR=build-asan
    # Line tables (-g1) are all a sanitizer report needs, and compile faster than full -g.
    export RUNG_CMAKE_ARGS="-DRUNG_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DRUNG_BUILD_BENCHMARKS=OFF"
    export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    bash scripts/test.sh
)

# ThreadSanitizer: only what has threads (test_simulator; the online session's tests of
# test_comms), no GUI, no benchmarks, so the stage stays small. Qt itself is not instrumented: its cross-thread event posting is not
# seen as synchronisation, hence the suppressions of reports inside libQt6Core alone.
start=$(date +%s)
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DRUNG_WERROR=ON -DRUNG_TSAN=ON \
    -DRUNG_BUILD_GUI=OFF -DRUNG_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-tsan -j "$(nproc)" --target test_simulator test_comms
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp" \
    build-tsan/tests/test_simulator --gtest_brief=1
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp" \
    build-tsan/tests/test_comms --gtest_brief=1 --gtest_filter='OnlineSession*:*RealPeerSession*'
echo "ThreadSanitizer stage: $(($(date +%s) - start)) s"
