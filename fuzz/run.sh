#!/usr/bin/env bash
# Fuzzes the material reader and the image import path for a fixed time each:
#   ./fuzz/run.sh [SECONDS]      (default 60 per target)
# Builds with clang, libFuzzer, AddressSanitizer and UBSan in its own folder (build-fuzz), starts
# from the seed corpus and the regression inputs, and leaves any crashing input in
# build-fuzz/fuzz-crashes/TARGET/. A crash found becomes a regression test: copy the input into
# fuzz/regressions/TARGET/ (every build replays that folder in ctest), then fix the code.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=${PX_FUZZ_BUILD_DIR:-build-fuzz}

missing=()
for p in clang libclang-rt-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPX_FUZZ=ON -DPX_BUILD_TESTS=OFF -DPX_BUILD_STUDIO=OFF -DPX_SANITIZE=OFF
cmake --build "$build" --target px-fuzz-material px-fuzz-image

export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0"
status=0
for target in material image; do
  corpus="$build/fuzz-corpus/$target"
  crashes="$build/fuzz-crashes/$target"
  mkdir -p "$corpus" "$crashes"
  cp -n fuzz/corpus/$target/* fuzz/regressions/$target/* "$corpus"/
  echo "== fuzzing $target for ${seconds} s (corpus $corpus)"
  if ! "$build/fuzz/px-fuzz-$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$crashes/" "$corpus"; then
    echo "== $target: a crash; the input is in $crashes"
    status=1
  fi
done
exit $status
