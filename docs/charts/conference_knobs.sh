#!/bin/bash
# The renderer's knobs on the Conference Room (issue 27): each setting's frame time against its
# full frame's error with one bake, one view and one path-traced reference.
#   docs/charts/conference_knobs.sh BUILD BAKE REF OUT
# BUILD holds bin/bounce-render and bin/bounce-compare; BAKE a bounce-bake folder of
# content/conference/conference_panels.json; REF `bounce-trace … --width 96 --height 54` of the
# full frame (camera 'corner'); OUT gets one EXR per setting and knobs.csv (then
# plot_conference_knobs.py draws the chart). Frames at 384x216 (--box 4 against the 96x54
# reference), --frames 4: the mean of the 3 frames after the first (render + readback) and the
# lit pass's GPU time. Run from the repository root.
set -euo pipefail
build=$1 bake=$2 ref=$3 out=$4
scene=content/conference/conference_panels.json
mkdir -p "$out"
csv=$out/knobs.csv
echo "knob,setting,frame_ms,lit_pass_ms,mare,relmse,load" > "$csv"
run() {  # knob setting args...
  local knob=$1 setting=$2
  shift 2
  local exr="$out/${knob}_${setting}.exr"
  local log
  log=$("$build/bin/bounce-render" "$scene" --bake "$bake" --width 384 --height 216 --frames 4 \
    --out "$exr" "$@" 2>&1)
  local ms lit
  ms=$(sed -n 's/.*more frames: \([0-9.]*\) ms per frame.*/\1/p' <<< "$log")
  lit=$(awk '/lit forward pass/ {print $6}' <<< "$log")
  local metrics
  metrics=$("$build/bin/bounce-compare" "$exr" "$ref" --box 4 --json |
    /usr/bin/python3 -c "import json,sys; a=json.load(sys.stdin)['all']; print(f\"{a['meanAbsRelError']:.5f},{a['relMse']:.6f}\")")
  echo "$knob,$setting,$ms,$lit,$metrics,$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$csv"
}
# llvmpipe allows 1 to 4 samples (2 is rounded up to 4: the same image).
for m in 1 4; do run msaa "$m" --msaa "$m"; done
for r in 128 256 512 1024 2048; do run shadow_resolution "$r" --shadow-resolution "$r"; done
run shadow_filter hardware --shadow-filter hardware
run shadow_filter poisson_r3 --shadow-filter-radius 3
run shadows none --no-shadows
run light_culling off --no-light-culling
run probes vpls --no-probes
run area_lights live --live-static-lights
run mode lightmap_only --mode lightmap
