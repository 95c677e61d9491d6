#!/usr/bin/env bash
# Direct light in a real room, error against frame time (docs/shadows.md, "Baked visibility"):
# the Conference Room under eight ceiling panels written as one mesh
# (content/conference/conference_panels.json) rendered --mode direct at 1280x720 with shadow maps
# only (no bake) and with the static area lights' baked visibility at two texel sizes (the
# default, 5 cm since the texel-density rule, and 10 cm), each
# box-filtered 4x4 and compared with bounce-trace --direct-only (320x180, 2048 spp).
#
# Usage (from the repo root): docs/charts/direct_error_vs_time.sh [BUILD_DIR] [OUT_DIR]
# Needs ../shared/scenes/conference. About 40 min on 2 cores (three bakes, two references, renders).
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
# Baked direct: the panels' direct light in the lightmap (conference_panels_baked.json), the spots
# live. Its direct light cannot be drawn apart from the lightmap's indirect light, so it is
# measured on the full frame against bounce-trace's full image (same size and samples), beside
# the default bake's baked visibility measured the same way.
full_ref=$out/conference_panels_full_2048spp.exr
[[ -f $full_ref ]] || "$bin/bounce-trace" "$scene" --spp 2048 --width 320 --height 180 \
  --out "$full_ref" --quiet
full_frame() {  # bake scene -> "frame_ms error" of --mode full against the full trace
  local ms
  ms=$("$bin/bounce-render" "$2" --bake "$1" --mode full --width 1280 --height 720 --frames 3 \
    --out "$out/frame.exr" 2>&1 | sed -n 's/.*more frames: \([0-9.]*\) ms per frame.*/\1/p')
  echo "$ms $("$bin/bounce-compare" "$out/frame.exr" "$full_ref" --box 4 --json |
    /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin)["all"]["meanAbsRelError"])')"
}
baked=$out/conference_panels_baked_direct.bake
[[ -d $baked ]] || "$bin/bounce-bake" content/conference/conference_panels_baked.json -o "$baked" --quiet
for pair in "baked visibility (full frame):$out/conference_panels_default.bake:$scene" \
            "baked direct (full frame):$baked:content/conference/conference_panels_baked.json"; do
  IFS=: read -r method bake file <<< "$pair"
  read -r t bs vs < <(/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1]));
s = d["measured"]["seconds"]; print(d["atlas"]["texelSize"], s["total"], s["visibility"])' "$bake/bake.json")
  read -r ms err < <(full_frame "$bake" "$file")
  echo "$method,$t,$bs,$vs,$ms,$err" >> "$csv"
done
/usr/bin/python3 "$here/plot_direct_error_vs_time.py" "$csv" "$out/direct_error_vs_time.png"
echo "wrote $csv and $out/direct_error_vs_time.png" >&2
