#!/usr/bin/env bash
# Installs what is missing, builds everything (warnings are errors) and runs every test.
#   bash scripts/test.sh              what CI runs (.ci/run), in stages:
#                                     1. an AddressSanitizer + UndefinedBehaviorSanitizer build
#                                        of everything, benchmarks included, in build-asan;
#                                     2. every test in it;
#                                     3. every benchmark once, on its small workload;
#                                     4. the two programs built alone (build-package), the
#                                        .deb made from them and what it installs checked;
#                                     5. a ThreadSanitizer build of the rooms with threads and
#                                        their suites, in build-tsan;
#                                     6. those suites under ThreadSanitizer.
#                                     The seconds of each stage are printed at the end.
#   bash scripts/test.sh --optimised  the same tests from an optimised build (RelWithDebInfo)
#                                     in build-test, and every benchmark briefly: quicker to
#                                     run while working; the figures in docs/performance.md
#                                     come from such a build
# Any failure, sanitizer report or broken benchmark fails the script.
#
# Why it is shaped so (a fresh clone on a two-core machine; the README has the figures):
# the sanitizer builds use clang, which compiles this code about 40% faster than GCC at -O0,
# with precompiled headers (cmake/RungPrecompiled.cmake); the optimised build and the
# programs users build stay GCC's. Every build of CI's run is a unity build (CMAKE_UNITY_BUILD: a
# room's files compiled together, the Qt headers read once a batch; the package's programs
# built in 93 s instead of 150 s), so no two files of a room may define a helper of the same
# name, even in an anonymous namespace; a developer's own build compiles each file alone. The model and its tests, the longest suite, are compiled at
# -O1 (RUNG_OPTIMISE_MODEL_TESTS). ctest runs each test binary in a few shards instead of a
# process a test: under AddressSanitizer a process start with Qt costs more than most tests.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=sanitize
case "${1:-}" in
--optimised) mode=optimised ;;
--sanitize | "") ;;
*)
    echo "usage: bash scripts/test.sh [--optimised]" >&2
    exit 2
    ;;
esac

start=$(date +%s)
stage_names=()
stage_seconds=()
summary() {
    local status=$?
    ((${#stage_names[@]})) || return 0
    echo
    echo "Stage times (seconds):"
    local i
    for i in "${!stage_names[@]}"; do
        printf '  %-44s %5d\n' "${stage_names[$i]}" "${stage_seconds[$i]}"
    done
    printf '  %-44s %5d\n' "total" "$(($(date +%s) - start))"
    ((status == 0)) || echo "FAILED in stage: ${current_stage:-?}"
}
trap summary EXIT
# stage NAME COMMAND...: runs the command and keeps its seconds for the summary.
stage() {
    current_stage=$1
    shift
    local t
    t=$(date +%s)
    echo "== $current_stage"
    "$@"
    stage_names+=("$current_stage")
    stage_seconds+=($(($(date +%s) - t)))
}

stage "install what is missing" bash scripts/install-deps.sh
jobs=$(nproc)
export QT_QPA_PLATFORM=offscreen

configure_and_build() { # DIR CMAKE_ARGS... [-- TARGETS...]
    local dir=$1
    shift
    local args=() targets=()
    while (($#)) && [ "$1" != -- ]; do
        args+=("$1")
        shift
    done
    (($#)) && shift && targets=("$@")
    cmake -S . -B "$dir" -G Ninja -DRUNG_WERROR=ON -DCMAKE_UNITY_BUILD=ON "${args[@]}" \
        ${RUNG_CMAKE_ARGS:-} >/dev/null
    if ((${#targets[@]})); then
        cmake --build "$dir" -j "$jobs" --target "${targets[@]}"
    else
        cmake --build "$dir" -j "$jobs"
    fi
}

if [ "$mode" = optimised ]; then
    dir="${RUNG_BUILD_DIR:-build-test}"
    # Each file alone, as a developer builds (the unity build is CI's, below).
    stage "build (optimised)" configure_and_build "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_UNITY_BUILD=OFF
    stage "tests (optimised)" ctest --test-dir "$dir" --output-on-failure -j "$jobs" --timeout 600
    stage "benchmarks (short runs)" bash scripts/run-benchmarks.sh "$dir"
    stage "package checks" bash scripts/check-package.sh "$dir"
    echo "All tests passed in $(($(date +%s) - start)) s"
    exit 0
fi

# Line tables (-g1) are all a sanitizer report needs, and compile faster than full -g.
sanitizer_build=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug
    -DCMAKE_CXX_FLAGS_DEBUG=-g1)
dir="${RUNG_BUILD_DIR:-build-asan}"
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
stage "build (AddressSanitizer + UBSan)" configure_and_build "$dir" "${sanitizer_build[@]}" \
    -DRUNG_SANITIZE=ON -DRUNG_TEST_SHARDS=4 -DRUNG_OPTIMISE_MODEL_TESTS=ON
stage "tests (AddressSanitizer + UBSan)" \
    ctest --test-dir "$dir" --output-on-failure -j "$jobs" --timeout 900
stage "benchmarks, once each (smoke)" bash scripts/run-benchmarks.sh "$dir" --smoke

# The package (issue 33's checks in CI): the two programs built alone, the .deb made from them
# and what it installs checked (scripts/check-package.sh: lintian, desktop-file-validate,
# appstreamcli, the MIME types, an install moved elsewhere running an example, the man pages
# and the completion). Built by clang without optimisation: every check reads the files, their
# metadata and what the programs say and do, none of which the optimisation changes, and it
# costs a third less than -O1. The package users get comes from a Release build (README,
# Install).
stage "build (the programs, for the package)" configure_and_build build-package \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-DNDEBUG" \
    -DRUNG_BUILD_TESTS=OFF -DRUNG_BUILD_BENCHMARKS=OFF
stage "package checks" bash scripts/check-package.sh build-package

# ThreadSanitizer: only the rooms with threads and their suites, no GUI, no benchmarks. Qt
# itself is not instrumented: its cross-thread event posting is not seen as synchronisation,
# hence the suppressions of reports inside libQt6Core alone.
stage "build (ThreadSanitizer)" configure_and_build build-tsan "${sanitizer_build[@]}" \
    -DRUNG_TSAN=ON -DRUNG_BUILD_GUI=OFF -DRUNG_BUILD_BENCHMARKS=OFF -- test_simulator test_comms \
    test_network
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/tsan.supp"
tsan_suites() {
    # The simulator's session, inbox and history; all of comms (the online session, the slave
    # server, the relay, the drivers against real Modbus peers). Side by side: one core each.
    build-tsan/tests/test_simulator --gtest_brief=1 &
    local simulator=$!
    local comms_status=0 simulator_status=0
    build-tsan/tests/test_comms --gtest_brief=1 || comms_status=$?
    wait "$simulator" || simulator_status=$?
    # The network's session: a network on its worker thread, its stations read by the owner;
    # its bridges (lines opened and read on the worker, cancelled from the owner).
    local network_status=0
    build-tsan/tests/test_network --gtest_brief=1 \
        --gtest_filter='NetworkSession.*:SessionBridges.*:NetworkHold.*' ||
        network_status=$?
    ((comms_status == 0 && simulator_status == 0 && network_status == 0)) ||
        { echo "ThreadSanitizer: test_comms exit $comms_status, test_simulator exit $simulator_status, test_network exit $network_status"; return 1; }
}
stage "tests (ThreadSanitizer)" tsan_suites
# The summary closes the output.
echo "All tests passed in $(($(date +%s) - start)) s"
