#!/bin/bash
# The Conference Room's full frame and lightmap-only frame from two builds side by side
# (alternating, twice), each with its own bake (the same settings; the after bake's probes.bin
# holds the probe-lit instances' visibility per corner), then the cost view's shadow-map taps:
#   docs/charts/probe_lit_shadows_frames.sh BEFORE/bounce-render BEFORE.bake AFTER/bounce-render AFTER.bake OUT
# Frames at 384x216, --frames 4: the first frame (shader JIT), then the mean of 3 later ones and
# each pass's GPU time. OUT gets the cost EXRs (B = taps) and the charts-mode PNGs (magenta: the
# probe-lit instances). Run from the repository root.
set -euo pipefail
before=$1 beforeBake=$2 after=$3 afterBake=$4 out=$5
scene=content/conference/conference_panels.json
mkdir -p "$out"
for round in 1 2; do
  for which in before after; do
    bin=$before bake=$beforeBake
    [[ $which == after ]] && bin=$after bake=$afterBake
    for mode in full lightmap; do
      echo "== $mode $which round $round $(date +%T) load $(cut -d' ' -f1 /proc/loadavg)"
      "$bin" "$scene" --bake "$bake" --mode "$mode" --width 384 --height 216 --frames 4 \
        --out "$out/${mode}_$which.exr" 2>&1 |
        grep -E "more frames|area-light shadow cubes|shadow: |lit forward pass" || true
    done
  done
done
for which in before after; do
  bin=$before bake=$beforeBake
  [[ $which == after ]] && bin=$after bake=$afterBake
  "$bin" "$scene" --bake "$bake" --mode cost --width 320 --height 180 --msaa 1 \
    --out "$out/cost_$which.exr" --out "$out/cost_taps_$which.png" --cost-count taps 2>&1 |
    grep -iE "taps|cost" || true
  "$bin" "$scene" --bake "$bake" --mode charts --width 320 --height 180 --msaa 1 \
    --out "$out/charts_$which.png" > /dev/null 2>&1
done
