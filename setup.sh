#!/usr/bin/env bash
# Parallax Studio set-up on Debian 12: installs what is missing, builds, then either opens the
# editor on the built-in sample (`./setup.sh editor`) or runs every test (`./setup.sh test`).
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-editor}
build=${PX_BUILD_DIR:-build}
packages=(
  build-essential cmake ninja-build pkg-config git
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-svg-dev qt6-qpa-plugins
  libglm-dev libopenimageio-dev openimageio-tools
  nlohmann-json3-dev libcli11-dev libtbb-dev libbenchmark-dev
  libplplot-dev libpng-dev libassimp-dev libkissfft-dev libembree-dev
  desktop-file-utils appstream
  xvfb xauth fonts-dejavu-core
  libgl1-mesa-dri libegl1 libegl-dev libgles-dev mesa-utils glslang-tools
  clang-format clang-tidy
  time
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm is needed as a command, not as Debian's package: a machine with NodeSource's nodejs already has
# it, and Debian's npm conflicts with that nodejs.
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
# The Khronos glTF validator the export tests run (from the npm registry).
if ! NODE_PATH="$(npm root -g 2>/dev/null)" node -e "require('gltf-validator')" 2>/dev/null; then
  echo "Installing: gltf-validator (npm)"
  $([ "$(id -u)" -eq 0 ] || echo sudo) npm install -g --no-fund --no-audit gltf-validator
fi

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo ${PX_CMAKE_ARGS:-}
cmake --build "$build" --parallel

case "$mode" in
  editor)
    if [ -x "$build/app/studio/parallax-studio" ]; then
      exec "$build/app/studio/parallax-studio" "${@:2}"
    fi
    # Built without the editor (-DPX_BUILD_STUDIO=OFF): trace the built-in sample instead.
    "$build/app/cli/parallax-cli" sample bricks --size 256 --out "$build/bricks.png"
    "$build/app/cli/parallax-cli" trace --height "$build/bricks.png" --scale 0.05 --polar 60 \
      --azimuth 35 --rays 64 --technique pyramid --out "$build/bricks-trace.csv"
    echo "Traced the built-in bricks sample: $build/bricks-trace.csv"
    ;;
  test)
    export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
    chmod 700 "$XDG_RUNTIME_DIR"
    cd "$build"
    # One Xvfb around all of ctest: the GL and GUI tests need a display, the rest ignore it.
    xvfb-run -a -s "-screen 0 1920x1080x24 -nolisten tcp" \
      ctest --output-on-failure --parallel "$(nproc)" "${@:2}"
    ;;
  *)
    echo "usage: $0 [editor|test] [arguments for the editor or ctest]" >&2
    exit 2
    ;;
esac
