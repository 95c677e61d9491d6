#!/usr/bin/env bash
# Direct light in a real room, error against frame time (docs/shadows.md, "Baked visibility"):
# the Conference Room under eight ceiling panels written as one mesh
# (content/conference/conference_panels.json) rendered --mode direct at 1280x720 with shadow maps
# only (no bake) and with the static area lights' baked visibility at two texel sizes (the
# default, 5 cm since the texel-density rule, and 10 cm), each
# box-filtered 4x4 and compared with bounce-trace --direct-only (320x180, 2048 spp).
#
# Usage (from the repo root): docs/charts/direct_error_vs_time.sh [BUILD_DIR] [OUT_DIR]
# Needs ../shared/scenes/conference. About 25 min on 2 cores (two bakes, the reference, renders).
set -euo pipefail
build=${1:-build/release}
out=${2:-out/charts}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=content/conference/conference_panels.json
bin=$build/bin
mkdir -p "$out"
ref=$out/conference_panels_direct_2048spp.exr
[[ -f $ref ]] || "$bin/bounce-trace" "$scene" --direct-only --spp 2048 --width 320 --height 180 \
  --out "$ref" --quiet
csv=$out/direct_error_vs_time.csv
echo "method,texel_m,bake_s,visibility_s,frame_ms,mean_abs_rel_error" > "$csv"
frame_ms() {  # mean of the frames after the first (which includes the shader JIT)
  "$bin/bounce-render" "$scene" "$@" --mode direct --width 1280 --height 720 --frames 3 \
    --out "$out/frame.exr" 2>&1 | sed -n 's/.*more frames: \([0-9.]*\) ms per frame.*/\1/p'
}
error() {
  "$bin/bounce-compare" "$out/frame.exr" "$ref" --box 4 --json |
    /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin)["all"]["meanAbsRelError"])'
}
ms=$(frame_ms); echo "shadow maps,,,,$ms,$(error)" >> "$csv"
for texel in default 0.1; do
  bake=$out/conference_panels_$texel.bake
  args=(); [[ $texel == default ]] || args=(--texel-size "$texel")
  [[ -d $bake ]] || "$bin/bounce-bake" "$scene" -o "$bake" "${args[@]}" --quiet
  read -r t bs vs < <(/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1]));
s = d["measured"]["seconds"]; print(d["atlas"]["texelSize"], s["total"], s["visibility"])' "$bake/bake.json")
  ms=$(frame_ms --bake "$bake"); echo "baked visibility,$t,$bs,$vs,$ms,$(error)" >> "$csv"
done
/usr/bin/python3 "$here/plot_direct_error_vs_time.py" "$csv" "$out/direct_error_vs_time.png"
echo "wrote $csv and $out/direct_error_vs_time.png" >&2
