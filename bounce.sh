#!/usr/bin/env bash
# The two entry points of the README, idempotent on a fresh Debian 12 machine (as root):
#   ./bounce.sh demo   install what is missing, build what the demo shows (Release: the renderer,
#                      the viewer, the Cornell box's bake), render the box with its baked global
#                      illumination
#   ./bounce.sh test   install what is missing, then three CTest runs (docs/README: Tests):
#                      the whole suite in Release; the whole suite again built with ASan + UBSan
#                      (preset debug); each libFuzzer target for 8 s (preset fuzz, clang)
set -euo pipefail
cd "$(dirname "$0")"

# Debian 12 packages bounce builds with (see docs/dependencies.md); the demo needs only these.
packages=(
  cmake ninja-build make g++ lld pkg-config python3-glad
  libosmesa6-dev libegl1-mesa-dev libgles-dev libglfw3-dev libglm-dev
  libopenmesh-dev libeigen3-dev libstb-dev libembree-dev libtbb-dev
  libtinygltf-dev libtinyobjloader-dev libtinyexr-dev
  libcli11-dev nlohmann-json3-dev libimgui-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
)
# What only the test command adds: the viewer's tests run under Xvfb, the fuzz targets need clang.
test_packages=(xvfb xauth clang libclang-rt-14-dev)

install_missing() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    echo "bounce: installing ${missing[*]}" >&2
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -q
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends \
      -o DPkg::Lock::Timeout=600 "${missing[@]}"
  fi
}

case "${1:-}" in
  demo)
    install_missing "${packages[@]}"
    cmake --preset release
    # Only what the demo shows: the renderer, the viewer and the Cornell box's bake (CMakePresets.json).
    cmake --build --preset demo
    mkdir -p out
    scene=content/cornell_box/cornell_box.gltf
    bake=build/release/content/cornell_box/cornell_box.bake
    build/release/bin/bounce-render "$scene" --bake "$bake" \
      --out out/cornell_box.png --out out/cornell_box.exr
    for mode in direct indirect; do
      build/release/bin/bounce-render "$scene" --bake "$bake" --mode "$mode" \
        --out "out/cornell_box_$mode.png"
    done
    echo "bounce: wrote out/cornell_box.png and .exr (direct + baked indirect light)," \
      "out/cornell_box_direct.png and out/cornell_box_indirect.png"
    if [ -n "${DISPLAY:-}" ] && [ -z "${CI:-}" ]; then
      build/release/bin/bounce-view "$scene" --bake "$bake"
    fi
    ;;
  test)
    install_missing "${packages[@]}" "${test_packages[@]}"
    # Each step says how long it took (the CI budget: docs/README, "Tests and benchmarks").
    step() {
      local start=$SECONDS
      "$@"
      echo "bounce: $* took $((SECONDS - start)) s" >&2
    }
    step cmake --preset release
    step cmake --build --preset release
    step ctest --preset release
    # The same suite under AddressSanitizer + UBSan (any report fails its test).
    step cmake --preset debug
    step cmake --build --preset debug
    step ctest --preset debug
    # A short bounded run of each fuzz target, seeded from tests/corpus (docs/fuzzing.md).
    step cmake --preset fuzz
    step cmake --build --preset fuzz
    step ctest --preset fuzz
    ;;
  *)
    echo "usage: $0 demo|test" >&2
    exit 2
    ;;
esac
