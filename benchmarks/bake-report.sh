#!/usr/bin/env bash
# The cone bakers' cost growth in one command: `parallax-cli bake cone|relaxed-cone` on generated
# maps at each size, whole process (file read and write included), timed with /usr/bin/time, this
# build's CLI against a baseline commit's built in a scratch folder (today's baker: fc05edd) in the
# same run, runs interleaved and repeated; with --gpu also `bake --gpu` (the same kernels on the
# GPU). Writes bake-times.csv (every run), bake-report.md (medians, ratios, the machine, its load,
# the GL renderer) and the maps' mean cone ratios into one folder.
#
#   benchmarks/bake-report.sh [--build DIR] [--baseline REF|none] [--baseline-cli FILE]
#                             [--sizes 512,1024,2048] [--maps bricks,noise]
#                             [--kinds cone,relaxed-cone] [--repeats N] [--gpu] [--gpu-only]
#                             [--baseline-max-size N] [--recommend] [--out DIR]
#
# --build DIR           an existing build folder (else build-bake-report/ is configured and built,
#                       RelWithDebInfo, as the project's figures are measured)
# --baseline REF        the commit to compare with (default fc05edd, before issue 32); none: skip
# --baseline-cli FILE   an already built baseline parallax-cli instead of building REF
# --baseline-max-size N the largest size the baseline bakes (default 4096: its relaxed bake of an
#                       8192² map ran for more than 24 minutes)
# --gpu                 also bake with --gpu (a GPU's EGL device where there is one, see
#                       PX_EGL_PLATFORM; llvmpipe otherwise)
# --gpu-only            only `bake --gpu` (the GPU growth table: docs/bench/)
# --recommend           also a cold `recommend --height MAP --cache NEW_DIR` per map and size
#                       (baker "recommend", "recommend-baseline"; it bakes both cone maps)
# --out DIR             where the report goes (default bake-report/); an existing folder is
#                       replaced only if it holds an earlier report
#
# A one-call GPU run for a machine with a GPU (the real-GPU targets: relaxed 8192² in 5 s):
#   benchmarks/bake-report.sh --gpu-only --sizes 512,1024,2048,4096,8192 --repeats 3 \
#       --out docs/bench/gpu-bake-$(date +%F)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=""
baseline="fc05edd"
baselineCli=""
sizes="512,1024,2048"
maps="bricks,noise"
kinds="cone,relaxed-cone"
repeats=2
gpu=0
cpu=1
baselineMax=4096
recommend=0
out="bake-report"
while [ $# -gt 0 ]; do
    case "$1" in
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --baseline) baseline=${2:?--baseline needs a commit or none}; shift 2 ;;
    --baseline-cli) baselineCli=${2:?--baseline-cli needs a file}; shift 2 ;;
    --baseline-max-size) baselineMax=${2:?--baseline-max-size needs a size}; shift 2 ;;
    --sizes) sizes=${2:?--sizes needs a list}; shift 2 ;;
    --maps) maps=${2:?--maps needs a list}; shift 2 ;;
    --kinds) kinds=${2:?--kinds needs a list}; shift 2 ;;
    --repeats) repeats=${2:?--repeats needs a count}; shift 2 ;;
    --gpu) gpu=1; shift ;;
    --gpu-only) gpu=1; cpu=0; baseline=none; shift ;;
    --recommend) recommend=1; shift ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    -h | --help) sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "error: unknown option $1 (see --help)" >&2; exit 2 ;;
    esac
done

fail() {
    echo "error: $*" >&2
    exit 1
}
[ -x /usr/bin/time ] || fail "/usr/bin/time is missing (Debian package time)"

if [ -z "$build" ]; then
    build="$root/build-bake-report"
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null ||
        fail "$build: configuring failed"
    cmake --build "$build" --target parallax-cli || fail "$build: the build failed"
fi
cli="$build/app/cli/parallax-cli"
[ -x "$cli" ] || fail "$cli: not built (cmake --build $build --target parallax-cli)"

if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ] && [ ! -f "$out/bake-report.md" ]; then
    fail "$out: exists and is not an earlier bake report (no bake-report.md): not replaced"
fi
parent=$(dirname "$out")
[ -d "$parent" ] || fail "$parent: no such folder"
work=$(mktemp -d "$parent/.bake-report.XXXXXX")
trap 'rm -rf "$work"' EXIT

# The baseline's CLI, built from the commit in a scratch folder (ccache makes a rebuild quick).
base=""
if [ "$baseline" != none ]; then
    if [ -n "$baselineCli" ]; then
        base=$baselineCli
    else
        echo "Building the baseline $baseline's parallax-cli..."
        src="$work/baseline-src"
        mkdir -p "$src"
        git -C "$root" archive "$baseline" | tar -x -C "$src" || fail "$baseline: not a commit"
        launcher=()
        command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
        cmake -S "$src" -B "$src/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
            -DPX_BUILD_STUDIO=OFF -DPX_BUILD_TESTS=OFF -DPX_CONFORMANCE=OFF "${launcher[@]}" \
            >/dev/null || fail "$baseline: configuring failed"
        cmake --build "$src/build" --target parallax-cli >/dev/null || fail "$baseline: build failed"
        base="$src/build/app/cli/parallax-cli"
    fi
    [ -x "$base" ] || fail "$base: no baseline CLI"
fi

csv="$work/bake-times.csv"
echo "map,size,kind,baker,run,wall_s,user_s,sys_s,max_rss_mib,mean_cone_ratio,gpu_ms" >"$csv"
load() { cut -d' ' -f1-3 /proc/loadavg; }
loadStart=$(load)
gl=""

# One timed bake: appends a CSV row.
bake() { # map size kind baker binary [--gpu]
    local map=$1 size=$2 kind=$3 baker=$4 bin=$5 run=$6
    shift 6
    local res="$work/out.exr" t="$work/time.txt" gpuMs=""
    rm -f "$res"
    /usr/bin/time -f "%e %U %S %M" -o "$t" "$bin" bake "$kind" "$@" \
        --height "$work/$map-$size.exr" --bits 32 --out "$res" 2>"$work/stderr.txt" ||
        fail "$baker: bake $kind of $map $size failed: $(tail -n 3 "$work/stderr.txt")"
    if [ "$baker" = gpu ]; then
        grep -q "baked on the GPU" "$work/stderr.txt" ||
            fail "bake --gpu did not bake on the GPU: $(tail -n 3 "$work/stderr.txt")"
        gl=$(sed -n 's/^baked on the GPU (\(.*\)) in [0-9]* ms$/\1/p' "$work/stderr.txt" | head -n 1)
        # The GPU's own part (upload, dispatches, read-back), as bake --gpu reports it.
        gpuMs=$(sed -n 's/^baked on the GPU (.*) in \([0-9]*\) ms$/\1/p' "$work/stderr.txt" | head -n 1)
    fi
    read -r wall user sys rss <"$t"
    # The mean cone ratio c = G^2 of the written map (oiiotool's --stats where it is installed).
    local mean=""
    if command -v oiiotool >/dev/null; then
        mean=$(oiiotool "$res" --ch G --dup --mul --printstats 2>/dev/null |
            sed -n 's/.*Stats Avg: *\([0-9.e+-]*\).*/\1/p' | head -n 1 || true)
    fi
    echo "$map,$size,$kind,$baker,$run,$wall,$user,$sys,$((rss / 1024)),$mean,$gpuMs" >>"$csv"
    printf '  %-8s %-12s %-6s %5s²  %7.2f s wall  %7.2f s CPU  %6d MiB\n' "$baker" "$kind" "$map" \
        "$size" "$wall" "$(awk "BEGIN {print $user + $sys}")" "$((rss / 1024))"
}

# A cold recommend (a new cone cache): appends a CSV row (kind "recommend").
coldRecommend() { # map size baker binary run
    local map=$1 size=$2 baker=$3 bin=$4 run=$5 t="$work/time.txt"
    rm -rf "$work/cache"
    /usr/bin/time -f "%e %U %S %M" -o "$t" "$bin" recommend --height "$work/$map-$size.exr" \
        --cache "$work/cache" --out "$work/recommend-$baker.txt" 2>"$work/stderr.txt" ||
        fail "$baker: recommend on $map $size failed: $(tail -n 3 "$work/stderr.txt")"
    read -r wall user sys rss <"$t"
    echo "$map,$size,recommend,$baker,$run,$wall,$user,$sys,$((rss / 1024)),," >>"$csv"
    printf '  %-8s %-12s %-6s %5s²  %7.2f s wall  %7.2f s CPU  %6d MiB\n' "$baker" recommend \
        "$map" "$size" "$wall" "$(awk "BEGIN {print $user + $sys}")" "$((rss / 1024))"
}

IFS=, read -r -a sizeList <<<"$sizes"
IFS=, read -r -a mapList <<<"$maps"
IFS=, read -r -a kindList <<<"$kinds"
for size in "${sizeList[@]}"; do
    for map in "${mapList[@]}"; do
        "$cli" sample "$map" --size "$size" --bits 32 --out "$work/$map-$size.exr" >/dev/null ||
            fail "parallax-cli sample $map failed"
        for kind in "${kindList[@]}"; do
            for run in $(seq 1 "$repeats"); do
                [ "$cpu" = 1 ] && bake "$map" "$size" "$kind" new "$cli" "$run"
                [ -n "$base" ] && [ "$size" -le "$baselineMax" ] &&
                    bake "$map" "$size" "$kind" baseline "$base" "$run"
                [ "$gpu" = 1 ] && bake "$map" "$size" "$kind" gpu "$cli" "$run" --gpu
            done
        done
        if [ "$recommend" = 1 ]; then
            for run in $(seq 1 "$repeats"); do
                coldRecommend "$map" "$size" new "$cli" "$run"
                [ -n "$base" ] && [ "$size" -le "$baselineMax" ] &&
                    coldRecommend "$map" "$size" baseline "$base" "$run"
            done
            cmp -s "$work/recommend-new.txt" "$work/recommend-baseline.txt" ||
                echo "  note: recommend's answers differ on $map $size (new against baseline)"
        fi
        rm -f "$work/$map-$size.exr"
    done
done

# The summary: medians per map, size, kind and baker, and new against baseline.
{
    echo "# Cone bake times"
    echo
    echo "\`benchmarks/bake-report.sh\` at $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')" \
        "against ${baseline} ($(date -u +%F)); whole process, \`parallax-cli bake KIND --bits 32\`" \
        "on \`parallax-cli sample MAP --size N --bits 32\`; $repeats runs each, interleaved."
    echo
    echo "- machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')," \
        "$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
    echo "- load average (1, 5, 15 min): $loadStart at the start, $(load) at the end"
    [ -n "$gl" ] && echo "- GPU: $gl"
    echo
    echo "| map | size | kind | baker | wall (median) | CPU (median) | peak RSS | mean cone ratio | GPU part (median) | new vs baseline (wall, CPU) |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
    tail -n +2 "$csv" | sort -t, -k1,1 -k2,2n -k3,3 -k4,4 | awk -F, '
        function median(list, n,   a, i, j, t) {
            n = split(list, a, " ")
            for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
            return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
        }
        { key = $1 "," $2 "," $3 "," $4; wall[key] = wall[key] " " $6; cpu[key] = cpu[key] " " ($7 + $8)
          rss[key] = $9 > rss[key] ? $9 : rss[key]; mean[key] = $10; if ($11 != "") gms[key] = gms[key] " " $11; if (!(key in seen)) { order[++n] = key; seen[key] = 1 } }
        END {
            for (i = 1; i <= n; i++) { k = order[i]; w[k] = median(wall[k]); c[k] = median(cpu[k]) }
            for (i = 1; i <= n; i++) {
                k = order[i]; split(k, f, ","); ratio = ""
                b = f[1] "," f[2] "," f[3] ",baseline"
                if (f[4] != "baseline" && (b in w) && w[k] > 0 && c[k] > 0)
                    ratio = sprintf("%.2fx, %.2fx", w[b] / w[k], c[b] / c[k])
                g = (k in gms) ? sprintf("%.0f ms", median(gms[k])) : ""
                printf "| %s | %s² | %s | %s | %.2f s | %.2f s | %d MiB | %s | %s | %s |\n", f[1], f[2], f[3], f[4], w[k], c[k], rss[k], mean[k], g, ratio
            }
        }'
} >"$work/bake-report.md"
cat "$work/bake-report.md"

mkdir -p "$out"
rm -f "$out/bake-times.csv" "$out/bake-report.md"
mv "$csv" "$work/bake-report.md" "$out/"
echo "wrote $out/bake-report.md and $out/bake-times.csv"
