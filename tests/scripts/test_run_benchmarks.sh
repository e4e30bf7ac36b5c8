#!/usr/bin/env bash
# scripts/run-benchmarks.sh fails, naming the program and the benchmark, when a benchmark
# reports an error, crashes or exits non-zero, and passes when every one measures. Fake
# benchmark programs stand in for the real ones: what is tested is the script's judgement.
set -uo pipefail
script="$(cd "$(dirname "$0")/../.." && pwd)/scripts/run-benchmarks.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
check() { # WHAT CONDITION...
    local what=$1
    shift
    if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fails=$((fails + 1)); fi
}
fake() { # NAME BODY: an executable bench_NAME under $work/tests/benchmarks
    mkdir -p "$work/tests/benchmarks"
    printf '#!/usr/bin/env bash\n%s\n' "$2" >"$work/tests/benchmarks/bench_$1"
    chmod +x "$work/tests/benchmarks/bench_$1"
}
good='echo "BM_Fine/1   12.5 ms   12.4 ms   1"'

fake fine "$good"
out=$(bash "$script" "$work" --smoke 2>&1)
check "every benchmark measured: exit 0" test $? -eq 0
check "the program is named with its results" grep -q "bench_fine: 1 results" <<<"$out"

fake broken 'echo "BM_Ratio/iterations:1   ERROR OCCURRED: '"'"'the compiled program and the engine differ'"'"'"'
out=$(bash "$script" "$work" --smoke 2>&1)
check "an ERROR OCCURRED fails the run" test $? -ne 0
check "... naming the benchmark and its error" \
    grep -q "BM_Ratio/iterations:1: ERROR OCCURRED: 'the compiled program and the engine differ'" <<<"$out"
check "... and the program" grep -q "Benchmarks failed: bench_broken" <<<"$out"
rm "$work/tests/benchmarks/bench_broken"

fake crash "$good"'
kill -SEGV $$'
out=$(bash "$script" "$work" 2>&1)
check "a crash after results fails the run" test $? -ne 0
check "... naming the program" grep -q "Benchmarks failed: bench_crash" <<<"$out"
rm "$work/tests/benchmarks/bench_crash"

fake exits "$good"'
exit 3'
out=$(bash "$script" "$work" 2>&1)
check "a non-zero exit fails the run" test $? -ne 0
check "... saying the exit status" grep -q "bench_exits (exit 3)" <<<"$out"
rm -r "$work/tests/benchmarks"

out=$(bash "$script" "$work" 2>&1)
check "no benchmark program at all fails the run" test $? -ne 0

((fails == 0))
