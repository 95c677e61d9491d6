#!/usr/bin/env bash
# Error of the renderer's indirect frame (with a fresh lightmap bake) against bake time, on our
# own interior (content/sunlit_room, camera "room"): a sweep of the per-texel target error at
# two texel sizes (bounce-bake's default for a room, 5 cm, and 10 cm), denoised as by default.
#
# Usage (from the repo root):
#   docs/charts/sunlit_room_error_vs_time.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bench_indirect_accuracy (default build/release)
#     OUT_DIR    receives the reference EXRs, sunlit_room_error_vs_time.csv and .png
#                (default out/charts)
#
# Each point: bench_indirect_accuracy (tests/bench) bakes in-process through bakeScene with
# bounce-bake's settings (at most 4096 samples per texel, 4096 VPLs: the instances the atlas
# leaves to the VPLs, the door frame, read their light), draws --mode indirect at 360x240,
# box-filters it to 90x60 (the tracer averages each pixel's area) and compares with
# bounce-trace --indirect-only (8192 spp, traced once and cached) over the static,
# non-emissive, edge-free pixels: mean |dY|/Y. The reference's own noise can add up to
# ref_noise_allowance (about 2.7%) to that mean; the chart draws it as a band.
set -euo pipefail

build=${1:-build/release}
out=${2:-out/charts}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bench="$build/bin/bench_indirect_accuracy"
scene="$here/../../content/sunlit_room/sunlit_room.gltf"
mkdir -p "$out"
csv="$out/sunlit_room_error_vs_time.csv"
common=("$scene" --camera room --size 90 --height 60 --box 4 --ref-spp 8192 --vpls 4096
        --ref "$out/sunlit_room_ref90.exr")

source "$here/room_error_sweep.sh"
room_error_sweep "$bench" "$csv" "$out/sunlit_room_error_vs_time.png" \
  "Sunlit room (our interior), 90×60 from 360×240, labels: per-texel target error" "${common[@]}"
