#!/usr/bin/env bash
# Issue 15, measurement 1: the real scenes baked with bounce-bake's defaults (no options) must take
# at most 3 minutes of wall time and 2 GB of peak memory on a 2-core machine. For each scene: the
# wall time and peak resident set of the whole bounce-bake process (/usr/bin/time), the bake's
# own stage times, texels, samples and estimated error (bake.json), and PASS or FAIL against the
# limits. The progress line (with its ETA) is drawn to stderr with --progress; its last state is
# kept in the log.
#
# Usage (from the repo root):
#   tests/bench/default_bake_budget.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bounce-bake (default build/release)
#     OUT_DIR    receives the bake folders, their logs and default_bake_budget.csv (default out/bench)
# Scenes: the Conference Room with its eight panels and Šibenik (../shared/scenes, referenced by
# the content/ wrappers), and our interior content/sunlit_room. Run it on an otherwise idle
# machine: the limits are wall time.
set -euo pipefail

build=${1:-build/release}
out=${2:-out/bench}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root="$here/../.."
mkdir -p "$out"
csv="$out/default_bake_budget.csv"
limit_s=180
limit_mb=2048

echo "scene,cores,wall_s,peak_mb,texel_size_m,texels,spp_mean,est_error_mean,atlas_s,irradiance_s,visibility_s,verdict" > "$csv"
for scene in content/conference/conference_panels.json content/sibenik/sibenik.json \
             content/sunlit_room/sunlit_room.gltf; do
  name=$(basename "$scene" | sed 's/\.[a-z]*$//')
  rm -rf "$out/$name.bake"
  /usr/bin/time -f "%e %M" -o "$out/$name.time" \
    "$build/bin/bounce-bake" "$root/$scene" -o "$out/$name.bake" --progress 2> "$out/$name.log"
  read -r wall kb < "$out/$name.time"
  /usr/bin/python3 - "$name" "$wall" "$kb" "$out/$name.bake/bake.json" "$limit_s" "$limit_mb" \
    "$(nproc)" >> "$csv" <<'PY'
import json, sys
name, wall, kb, bake_file, limit_s, limit_mb, cores = sys.argv[1:]
bake = json.load(open(bake_file))
a, m, s = bake["atlas"], bake["measured"]["seconds"], bake["samples"]
wall, mb = float(wall), int(kb) / 1024
ok = wall <= float(limit_s) and mb <= float(limit_mb)
print(",".join(str(x) for x in [
    name, cores, round(wall, 1), round(mb), round(a["texelSize"], 4), a["coveredTexels"],
    round(s["perTexelMean"]), round(bake["estimatedError"]["mean"], 4), round(m["atlas"], 1),
    round(m["irradiance"], 1), round(m["visibility"], 1), "PASS" if ok else "FAIL"]))
PY
  tail -n 1 "$csv"
done
column -s, -t "$csv"
