#!/usr/bin/env bash
# benchmarks/gpu-report.sh end to end on this machine's GL (llvmpipe on CI), quick sizes, and its
# refusals: each run's exit status and message are checked, and a refused run leaves the folder
# it was pointed at byte-identical and nothing beside it.
#   gpu-report-test.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -uo pipefail
src=$1
build=$2
work=$3
script="$src/benchmarks/gpu-report.sh"
rm -rf "$work"
mkdir -p "$work"
failures=0
check() { # check DESCRIPTION CONDITION...
    local what=$1
    shift
    if "$@"; then
        echo "ok: $what"
    else
        echo "FAILED: $what"
        failures=$((failures + 1))
    fi
}

# 1. The report, end to end.
"$script" --build "$build" --out "$work/report" --quick >"$work/run.log" 2>&1
status=$?
check "the report runs (exit 0)" test "$status" -eq 0
[ "$status" -eq 0 ] || cat "$work/run.log"
r="$work/report"
check "frame-times.csv has its header" grep -q '^technique,size,production_ms,verify_ms,production_vs_none,production_vs_verify,renderer$' "$r/frame-times.csv"
# Every technique in both flavours: 11 rows of positive times at the one quick size.
rows=$(awk -F, 'NR > 1 && $3 > 0 && $4 > 0 { n++ } END { print n + 0 }' "$r/frame-times.csv")
check "frame-times.csv times 11 techniques in both flavours ($rows rows)" test "$rows" -eq 11
check "bench.csv has the GPU kernels' error columns" grep -q ',gpu_kernels,gpu_mean_error,gpu_p99_error,gpu_max_error,gpu_mean_fetches$' "$r/bench.csv"
check "bench.csv rows carry production GPU errors" grep -q ',production,[0-9.e+-]*,[0-9.e+-]*,[0-9.e+-]*,[0-9.e+-]*$' "$r/bench.csv"
check "bench.csv has no missing GPU timing" bash -c "! grep -q 'no GPU' '$r/bench.csv'"
check "work-precision.svg is an SVG" grep -q '<svg' "$r/work-precision.svg"
check "the report names the GL renderer" grep -q '^GL: OpenGL [0-9]' "$r/gpu-report.txt"
check "render --time compares the flavours" grep -q '^production / verify frame time: [0-9.]*$' "$r/render-time.txt"
check "nothing left beside the report" test "$(ls -A "$work" | tr '\n' ' ')" = "report run.log "

# 2. A folder that is not an earlier report is refused and left as it was.
mkdir -p "$work/precious"
echo "keep me" >"$work/precious/notes.txt"
before=$(cd "$work/precious" && sha256sum notes.txt)
"$script" --build "$build" --out "$work/precious" --quick >"$work/refused.log" 2>&1
status=$?
check "a foreign folder is refused (exit 1)" test "$status" -eq 1
check "the refusal names the folder" grep -q "error: $work/precious: exists and is not an earlier GPU report" "$work/refused.log"
check "the foreign folder is unchanged" test "$(cd "$work/precious" && sha256sum notes.txt)" = "$before"
check "the foreign folder gained nothing" test "$(ls -A "$work/precious")" = "notes.txt"

# 3. A build folder without the programs.
"$script" --build "$work/no-build" --out "$work/r2" --quick >"$work/nobuild.log" 2>&1
status=$?
check "a missing build folder is refused (exit 1)" test "$status" -eq 1
check "the refusal names it" grep -q "error: $work/no-build: no such build folder" "$work/nobuild.log"
check "no report and no temporary folder left" test "$(ls -A "$work" | grep -c -e '^r2$' -e '^\.gpu-report')" -eq 0

# 4. Running again replaces the earlier report.
"$script" --build "$build" --out "$work/report" --quick >"$work/again.log" 2>&1
check "an earlier report is replaced (exit 0)" test $? -eq 0

echo "$failures failed"
[ "$failures" -eq 0 ]
