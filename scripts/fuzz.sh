#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for SECONDS:
#   bash scripts/fuzz.sh [SECONDS] [fuzz_il_parser|fuzz_project_loader|fuzz_vigor_reply|
#                                   fuzz_modbus_reply|fuzz_hostlink_reply|fuzz_vigor_slave|
#                                   fuzz_modbus_rtu_slave|fuzz_modbus_tcp_slave|
#                                   fuzz_hostlink_slave]
# Corpora start from the project's own listings, ladders and projects; findings land in
# build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-300}"
only="${2:-}"
bash scripts/install-deps.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DRUNG_BUILD_FUZZERS=ON -DRUNG_BUILD_GUI=OFF -DRUNG_BUILD_BENCHMARKS=OFF >/dev/null
# The reply decoders of the masters, and the slaves whole (the virtual PLC's request side).
comms_fuzzers=(fuzz_vigor_reply fuzz_modbus_reply fuzz_hostlink_reply fuzz_vigor_slave
    fuzz_modbus_rtu_slave fuzz_modbus_tcp_slave fuzz_hostlink_slave)
targets=(fuzz_il_parser fuzz_project_loader "${comms_fuzzers[@]}")
[ -n "$only" ] && targets=("$only")
cmake --build build-fuzz --target "${targets[@]}"
mkdir -p build-fuzz/corpus/il build-fuzz/corpus/project build-fuzz/findings
# The IL fuzzer reads the first byte as the target (Family: 0 VPC, 1 Vigor, 2 CPM1, 3 PL110);
# each listing is seeded with its own family, named by the file's prefix.
for f in tests/data/sim/*.il; do
    case "$(basename "$f")" in
    vpc_*) byte='\000' ;;
    cpm1_*) byte='\002' ;;
    pl110_*) byte='\003' ;;
    *) byte='\001' ;;
    esac
    { printf "$byte"; cat "$f"; } > "build-fuzz/corpus/il/$(basename "$f")"
done
cp resources/examples/*/*.rung build-fuzz/corpus/project/
# The comms fuzzers start from the manuals' example frames (Vigor M/VB/VH communication manual,
# B-5-3; Omron CPM1/SRM1 programming manual W353, Host Link) and the Modbus specification's
# examples, behind the bytes that pick the request and the chunk size
# (tests/fuzz/make_corpus.py).
for name in "${comms_fuzzers[@]}"; do
    mkdir -p "build-fuzz/corpus/$name"
    cp tests/fuzz/corpus/"$name"/* "build-fuzz/corpus/$name/"
done
export ASAN_OPTIONS=detect_leaks=0
export UBSAN_OPTIONS=print_stacktrace=1
for name in fuzz_il_parser fuzz_project_loader "${comms_fuzzers[@]}"; do
    [ -n "$only" ] && [ "$only" != "$name" ] && continue
    corpus=build-fuzz/corpus/il
    [ "$name" = fuzz_project_loader ] && corpus=build-fuzz/corpus/project
    [ -d "build-fuzz/corpus/$name" ] && corpus="build-fuzz/corpus/$name"
    echo "== $name for ${seconds}s"
    log="build-fuzz/$name.log"
    status=0
    "build-fuzz/tests/fuzz/$name" -max_total_time="$seconds" -max_len=65536 -timeout=10 \
        -artifact_prefix=build-fuzz/findings/ "$corpus" >"$log" 2>&1 || status=$?
    # The closing figures: runs, coverage (cov), features (ft), corpus, speed.
    grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1 || true
    grep -E '^Done [0-9]+ runs' "$log" | tail -n 1 || true
    if [ "$status" -ne 0 ]; then
        grep -E 'ERROR|SUMMARY|runtime error|Test unit written' "$log" | head -n 20
        echo "$name found a problem: see $log and build-fuzz/findings/"
        failed=1
    fi
done
exit "${failed:-0}"
