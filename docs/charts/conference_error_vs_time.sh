#!/usr/bin/env bash
# Error of the renderer's indirect frame (with a fresh lightmap bake) against bake time, on the
# Conference Room lit by its eight ceiling panels and two spots (content/conference/
# conference_panels.json, ../shared/scenes): a sweep of the per-texel target error at two texel
# sizes (bounce-bake's default for a room, 5 cm, and 10 cm), denoised as by default (issue 15,
# measurement 6).
#
# Usage (from the repo root):
#   docs/charts/conference_error_vs_time.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bench_indirect_accuracy (default build/release)
#     OUT_DIR    receives the reference EXRs, conference_error_vs_time.csv and .png
#                (default out/charts)
#
# Each point: bench_indirect_accuracy (tests/bench) bakes in-process through bakeScene with
# bounce-bake's settings (at most 4096 samples per texel, 4096 VPLs: the chairs and the other
# instances the atlas leaves to the VPLs read their light), draws --mode indirect at 384x216,
# box-filters it to 96x54 and compares with bounce-trace --indirect-only (8192 spp, traced once
# and cached) over the static, non-emissive, edge-free pixels: mean |dY|/Y. The reference's own
# noise can add up to ref_noise_allowance (about 2.8%) to that mean; the chart draws it as a band.
set -euo pipefail

build=${1:-build/release}
out=${2:-out/charts}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bench="$build/bin/bench_indirect_accuracy"
scene="$here/../../content/conference/conference_panels.json"
mkdir -p "$out"
csv="$out/conference_error_vs_time.csv"
common=("$scene" --size 96 --height 54 --box 4 --ref-spp 8192 --vpls 4096
        --ref "$out/conference_ref96.exr")

source "$here/room_error_sweep.sh"
room_error_sweep "$bench" "$csv" "$out/conference_error_vs_time.png" \
  "Conference Room (8 panels), 96×54 from 384×216, labels: per-texel target error" "${common[@]}"
