#!/usr/bin/env bash
# The mesh bake's targets in one command (issue 39; docs/bakers.md): a generated 2M-triangle
# binary PLY baked by `parallax-cli bake height|normal|ao --mesh`, whole process timed with
# /usr/bin/time -v (elapsed, CPU and peak resident memory), Assimp's read time as the CLI reports it,
# against the bound 3 x the mesh's vertex and index data + the output maps (as float in memory).
#
#   benchmarks/mesh-bake-report.sh --build DIR [--triangles N] [--repeats N] [--out DIR]
set -euo pipefail

build=""
triangles=2000000
repeats=2
out="mesh-bake-report"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --triangles) triangles=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[[ -n "$build" ]] || { echo "--build DIR is required" >&2; exit 2; }
cli="$build/app/cli/parallax-cli"
make="$build/benchmarks/parallax-bench-make-mesh-tile"
mkdir -p "$out"
mesh="$out/tile.ply"
"$make" "$mesh" "$triangles" >/dev/null
read -r vertices faces < <(awk '/^element vertex/{v=$3} /^element face/{f=$3} /^end_header/{print v, f; exit}' "$mesh")
# Vertex data: position and normal, 24 bytes; index data 12 bytes a triangle.
meshBytes=$((vertices * 24 + faces * 12))

report="$out/mesh-bake-report.md"
{
  echo "# Mesh bake, $(date -u +%F)"
  echo
  echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores," \
       "$(awk '/MemTotal/{printf "%.0f GB", $2/1048576}' /proc/meminfo); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "Mesh: $faces triangles, $vertices vertices, $(stat -c %s "$mesh") bytes; vertex + index data $((meshBytes / 1048576)) MiB"
  echo
  echo "| bake | size | run | whole process s | CPU s (user + sys) | Assimp read s | peak RSS MiB | bound MiB |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$report"

run() { # kind size mapsBytes args...
  local kind=$1 size=$2 maps=$3
  shift 3
  for r in $(seq 1 "$repeats"); do
    local log="$out/$kind-$r.log"
    /usr/bin/time -v "$cli" bake "$kind" --mesh "$mesh" --size "$size" "$@" \
      --out "$out/$kind.png" >"$log" 2>&1
    local wall rss read cpu
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/{n=split($2,t,":"); s=0; for(i=1;i<=n;i++) s=s*60+t[i]; print s}' "$log")
    cpu=$(awk -F': ' '/User time|System time/{s+=$2} END{printf "%.2f", s}' "$log")
    rss=$(awk -F': ' '/Maximum resident set size/{printf "%.0f", $2/1024}' "$log")
    read=$(sed -n 's/.*read in \([0-9.]*\) s.*/\1/p' "$log")
    local bound=$(((3 * meshBytes + maps) / 1048576))
    echo "| $kind $* | $size² | $r | $wall | $cpu | $read | $rss | $bound |" >>"$report"
  done
}
# The maps as the baker holds them: float heights (and their hit counts), float RGB normals.
run height 2048 $((2048 * 2048 * 6)) --samples 2
run normal 2048 $((2048 * 2048 * 18)) --samples 2
run ao 1024 $((1024 * 1024 * 10)) --rays 64
cat "$report"
