#!/bin/bash
# Frame time of two bounce-render builds side by side (alternating, twice), on the Conference Room
# with 8 ceiling panels and on panels_over_rails' 64 small panels (the area-light cube budget
# matters) and on many_lights' 64 point lights (it does not):
#   docs/charts/area_shadow_budget_frames.sh BEFORE/bin/bounce-render AFTER/bin/bounce-render
# Each run prints the first frame (with the shader JIT), the mean of the 2 later frames and, from
# a build that has it, the area-light cube budget line. Run from the repository root.
set -euo pipefail
before=$1
after=$2
for scene in content/conference/conference_panels.json content/panels_over_rails/panels_over_rails.gltf \
  content/many_lights/many_lights.gltf; do
  [[ -f $scene ]] || continue
  for round in 1 2; do
    for which in before after; do
      bin=$before
      [[ $which == after ]] && bin=$after
      echo "== $(basename "$scene") $which round $round $(date +%T) load $(cut -d' ' -f1 /proc/loadavg)"
      "$bin" "$scene" --width 640 --height 360 --frames 3 --no-bake --context osmesa \
        --out "/tmp/area_shadow_budget_$which.png" 2>&1 |
        grep -E "first frame|more frames|area-light|area lights beyond" || true
    done
  done
done
