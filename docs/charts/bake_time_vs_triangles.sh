#!/usr/bin/env bash
# Bake time, memory and atlas use against the static triangle count: the content scenes with
# bounce-bake's defaults (Cornell box, our interior content/sunlit_room, the Conference Room with
# its eight panels from ../shared/scenes), and a synthetic series: the sunlit room with every
# quad cut into N x N (make_sunlit_room.py --subdivide N: the same surfaces, light and texels,
# N^2 times the triangles) at 10 cm texels.
#
# Usage (from the repo root):
#   docs/charts/bake_time_vs_triangles.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bounce-bake and bin/bounce-atlas (default build/release)
#     OUT_DIR    receives the scenes' bake folders, bake_time_vs_triangles.csv and .png
#                (default out/charts)
set -euo pipefail

build=${1:-build/release}
out=${2:-out/charts}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root="$here/../.."
mkdir -p "$out/bake_time_vs_triangles"
work="$out/bake_time_vs_triangles"
csv="$out/bake_time_vs_triangles.csv"

echo "scene,series,triangles,texel_size_m,texels,atlas_w,atlas_h,utilisation,charts,bake_s,irradiance_s,vpls_s,peak_mb,estimated_peak_mb,est_error_mean" > "$csv"
row() {  # label series scene [bounce-bake options...]
  local label=$1 series=$2 scene=$3
  shift 3
  "$build/bin/bounce-atlas" "$scene" --json "$@" > "$work/$label.atlas.json"
  "$build/bin/bounce-bake" "$scene" -o "$work/$label.bake" "$@" >&2
  /usr/bin/python3 - "$label" "$series" "$work/$label.atlas.json" "$work/$label.bake/bake.json" >> "$csv" <<'PY'
import json, sys
label, series, atlas_file, bake_file = sys.argv[1:]
atlas = json.load(open(atlas_file))
bake = json.load(open(bake_file))
a, m = bake["atlas"], bake["measured"]
print(",".join(str(x) for x in [
    label, series, atlas["staticTriangles"], round(a["texelSize"], 5), a["coveredTexels"],
    a["width"], a["height"], round(a["utilisation"], 3), a["charts"],
    round(m["seconds"]["total"], 2), round(m["seconds"]["irradiance"], 2),
    round(m["seconds"]["vpls"], 2), round(m["peakBytes"] / 1e6, 1),
    round(m["estimatedPeakBytes"] / 1e6, 1), round(bake["estimatedError"]["mean"], 4)]))
PY
  tail -1 "$csv" >&2
}

row cornell_box content "$root/content/cornell_box/cornell_box.gltf"
row sunlit_room content "$root/content/sunlit_room/sunlit_room.gltf"
row conference content "$root/content/conference/conference_panels.json"
for n in 1 2 4 8 16; do
  /usr/bin/python3 "$root/content/sunlit_room/make_sunlit_room.py" "$work/sunlit_x$n.gltf" \
    --subdivide "$n"
  row "sunlit_x$((n * n))" synthetic "$work/sunlit_x$n.gltf" --texel-size 0.1
done
/usr/bin/python3 "$here/plot_bake_time_vs_triangles.py" "$csv" "$out/bake_time_vs_triangles.png"
