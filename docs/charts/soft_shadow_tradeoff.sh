#!/usr/bin/env bash
# Shadow quality against frame time (docs/shadows.md): the Cornell box's direct light rendered
# with each shadow-map resolution (512…4096 texels per cube face) and filter (hard, soft), timed
# offscreen, and compared with a path-traced direct-only reference.
#
# Usage (from the repo root): docs/charts/soft_shadow_tradeoff.sh [BUILD_DIR] [OUT_DIR] [SIZE] [SPP]
#   BUILD_DIR holds bin/bounce-trace and bin/bench_soft_shadows (default build/release)
#   OUT_DIR   receives the reference EXRs, soft_shadow_tradeoff.csv and .png (default out/charts)
#   SIZE      image side in pixels (default 512); SPP reference samples per pixel (default 512)
# The reference is reused when OUT_DIR already has it (512², 512 spp: ~5 min on 2 cores).
set -euo pipefail
build=${1:-build/release}
out=${2:-out/charts}
size=${3:-512}
spp=${4:-512}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=content/cornell_box/cornell_box.gltf
for tool in "$build/bin/bounce-trace" "$build/bin/bench_soft_shadows"; do
  [[ -x $tool ]] || { echo "soft_shadow_tradeoff: $tool: not built" >&2; exit 1; }
done
mkdir -p "$out"
ref=$out/cornell_direct_${size}_${spp}spp.exr
se=$out/cornell_direct_${size}_${spp}spp_stderr.exr
if [[ ! -f $ref || ! -f $se ]]; then
  "$build/bin/bounce-trace" "$scene" --direct-only --width "$size" --height "$size" --spp "$spp" \
    --out "$ref" --std-error "$se" --quiet
fi
"$build/bin/bench_soft_shadows" "$ref" "$se" --size "$size" --frames 5 --out "$out/soft_shadow_tradeoff.csv"
/usr/bin/python3 "$here/plot_soft_shadows.py" "$out/soft_shadow_tradeoff.csv" "$out/soft_shadow_tradeoff.png"
echo "wrote $out/soft_shadow_tradeoff.csv and $out/soft_shadow_tradeoff.png" >&2
