#!/usr/bin/env bash
# Error of the renderer's indirect frame (with a fresh lightmap bake) against bake time, on the
# Cornell box: a sweep of the per-texel target error, with and without the denoiser, at two
# texel sizes (bounce-bake's default budget of 16384 texels, 1.1 cm, and 4096 texels, 2.2 cm).
#
# Usage (from the repo root):
#   docs/charts/lightmap_error_vs_time.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bench_indirect_accuracy (default build/release)
#     OUT_DIR    receives the reference EXRs, lightmap_error_vs_time.csv and .png
#                (default out/charts)
#
# Each point: bench_indirect_accuracy (tests/bench) bakes in-process with bounce-bake's settings
# (at most 4096 samples per texel), draws --mode indirect at 64x64 and compares with
# bounce-trace --indirect-only (16384 spp, traced once and cached) over the static,
# non-emissive, edge-free pixels: mean |dY|/Y. The reference's own noise can add up to
# ref_noise_allowance (about 1.2%) to that mean; the chart draws it as a band.
set -euo pipefail

build=${1:-build/release}
out=${2:-out/charts}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bench="$build/bin/bench_indirect_accuracy"
mkdir -p "$out"
csv="$out/lightmap_error_vs_time.csv"
common=(--size 64 --ref-spp 16384 --ref "$out/lightmap_ref64.exr")

"$bench" "${common[@]}" --texel-budget 16384 --target-error 0.1 --header > "$csv"
for budget in 16384 4096; do
  for denoise in on off; do
    for target in 0.2 0.1 0.05; do
      [ "$budget" = 16384 ] && [ "$denoise" = on ] && [ "$target" = 0.1 ] && continue
      "$bench" "${common[@]}" --texel-budget "$budget" --denoise "$denoise" \
        --target-error "$target" >> "$csv"
    done
  done
done
/usr/bin/python3 "$here/plot_lightmap_error.py" "$csv" "$out/lightmap_error_vs_time.png"
