#!/usr/bin/env bash
# A GPU report in one command: frame times of every technique in both kernel flavours
# (render-bench) and the work-precision bench with GPU timings and the GPU kernels' own errors
# (parallax-cli bench --gpu) on the built-in samples, as CSVs and the SVG plot in one folder,
# with the GL renderer, driver and EGL platform named.
#
#   benchmarks/gpu-report.sh [--build DIR] [--out DIR] [--quick]
#
# --build DIR  an existing build folder (else build-gpu-report/ is configured and built, Release)
# --out DIR    where the report goes (default gpu-report/); an existing folder is replaced only
#              if it holds an earlier report
# --quick      small sizes (a few seconds on llvmpipe: the ctest)
#
# Headless: the GL context comes from EGL, a GPU's EGL device where there is one (PX_EGL_PLATFORM=
# device insists on it, e.g. on a headless NVIDIA machine), else Mesa's surfaceless platform.
# GPU times are GL timer queries on real GPUs, a steady clock around glFinish on llvmpipe.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=""
out="gpu-report"
quick=0
while [ $# -gt 0 ]; do
    case "$1" in
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    --quick) quick=1; shift ;;
    -h | --help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "error: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done

fail() {
    echo "error: $*" >&2
    exit 1
}

if [ -z "$build" ]; then
    build="$root/build-gpu-report"
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null ||
        fail "$build: configuring failed"
    cmake --build "$build" --target parallax-cli render-bench || fail "$build: the build failed"
fi
[ -d "$build" ] || fail "$build: no such build folder"
cli="$build/app/cli/parallax-cli"
bench="$build/tests/render/render-bench"
[ -x "$cli" ] || fail "$cli: not built (cmake --build $build --target parallax-cli)"
[ -x "$bench" ] || fail "$bench: not built (Google Benchmark missing?)"

# The report is made beside its destination and renamed into place: a failure leaves any earlier
# report as it was.
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ] && [ ! -f "$out/gpu-report.txt" ]; then
    fail "$out: exists and is not an earlier GPU report (no gpu-report.txt): not replaced"
fi
parent=$(dirname "$out")
[ -d "$parent" ] || fail "$parent: no such folder"
work=$(mktemp -d "$parent/.gpu-report.XXXXXX")
trap 'rm -rf "$work"' EXIT

if [ "$quick" = 1 ]; then
    sizes="64x64"
    frame_args=(--min-time=0.02 --map-size=64)
    sample_size=32
    bench_args=(--rays 8 --scales 0.05 --defaults-only --gpu-rays 32 --gpu-frames 1)
else
    sizes="512x512,1920x1080"
    frame_args=()
    sample_size=256
    bench_args=(--rays 128 --scales 0.05,0.1 --gpu-rays 1440 --gpu-frames 3)
fi

echo "GL context and kernels' frame time (parallax-cli render --time)..."
"$cli" sample bricks --size 512 --out "$work/bricks.png" >/dev/null
"$cli" render --height "$work/bricks.png" --technique pom --size "${sizes%%,*}" --time 5 \
    --out "$work/frame.png" >"$work/render-time.txt" || fail "parallax-cli render failed"
rm -f "$work/bricks.png" "$work/frame.png"
gl=$(grep '^GL: ' "$work/render-time.txt") || fail "parallax-cli render named no GL context"

echo "Frame times, both kernel flavours (render-bench --sizes=$sizes)..."
"$bench" --sizes="$sizes" "${frame_args[@]}" --csv="$work/frame-times.csv" >"$work/render-bench.txt" ||
    fail "render-bench failed (see $work/render-bench.txt)"

echo "Error against cost with GPU timings (parallax-cli bench --gpu)..."
"$cli" bench --sample bricks,stones,rivets,noise --sample-size "$sample_size" "${bench_args[@]}" \
    --gpu --quiet --out "$work/bench.csv" --plot "$work/work-precision.svg" ||
    fail "parallax-cli bench failed"
# A bench without a GL context writes empty GPU columns and says why: that is no GPU report.
if why=$(grep -m1 -o 'no GPU \(timing\|hits\)[^"]*' "$work/bench.csv"); then
    fail "parallax-cli bench measured nothing on the GPU: $why"
fi

{
    echo "Parallax Studio GPU report"
    echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
    echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
    echo "CPU: $(grep -m1 '^model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ //')"
    echo "$gl"
    echo "PX_EGL_PLATFORM: ${PX_EGL_PLATFORM:-(not set: device if there is one, else surfaceless)}"
    echo "mode: $([ "$quick" = 1 ] && echo quick || echo full); frame sizes $sizes; samples ${sample_size}²"
    echo
    echo "frame-times.csv     render-bench: median ms per technique and kernel flavour, ratios"
    echo "bench.csv           parallax-cli bench --gpu: errors (CPU and GPU kernels), fetches, times"
    echo "work-precision.svg  the bench's work-precision plot"
    echo "render-time.txt     parallax-cli render --time: pom in both flavours"
    echo "render-bench.txt    render-bench's own output"
} >"$work/gpu-report.txt"

chmod 755 "$work"
rm -rf "$out"
mv "$work" "$out"
trap - EXIT
echo "wrote $out: $(cd "$out" && ls | tr '\n' ' ')"
