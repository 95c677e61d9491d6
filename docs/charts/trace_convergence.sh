#!/usr/bin/env bash
# Error against time for the reference path tracer (bounce-trace) on the Cornell box.
#
# Usage (from the repo root):
#   docs/charts/trace_convergence.sh [BUILD_DIR] [OUT_DIR]
#     BUILD_DIR  holds bin/bounce-trace and bin/bounce-compare (default build/release)
#     OUT_DIR    receives the reference EXR, the images, trace_convergence.csv and .svg
#                (default out/charts)
#   Environment: REPEATS (default 3) timed runs per point; the fastest wall time is kept
#   (the images are bit-identical across runs, only the time varies with machine load).
#
# 1. Reference: 4096 spp, seed 1, 128x128 (reused if OUT_DIR already has it).
# 2. For spp = 1..256 (powers of two) and backend in {embree, bvh}: render with seed 2, time
#    the whole process (wall seconds: scene load, BVH build, tracing, EXR write), compare to the
#    reference with bounce-compare --json, keep RMSE and relMSE over all channels.
# 3. Write OUT_DIR/trace_convergence.csv and plot OUT_DIR/trace_convergence.svg
#    (docs/charts/plot_convergence.py, Python standard library only).
#
# The error is measured against a 4096-spp estimate, not the exact image: with independent
# seeds E[measured MSE] = MSE(image) + MSE(reference), so the reference's own noise
# (1/16 of the 256-spp image's variance at 1/N convergence) floors the curve.
set -euo pipefail

build=${1:-build/release}
out=${2:-out/charts}
repeats=${REPEATS:-3}
scene=content/cornell_box/cornell_box.gltf
size=(--width 128 --height 128)
python=/usr/bin/python3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

trace=$build/bin/bounce-trace
compare=$build/bin/bounce-compare
for tool in "$trace" "$compare"; do
  [[ -x $tool ]] || { echo "trace_convergence: $tool: not found or not executable (build it first)" >&2; exit 1; }
done
[[ -f $scene ]] || { echo "trace_convergence: $scene: not found (run from the repo root)" >&2; exit 1; }
[[ -x $python ]] || { echo "trace_convergence: $python: not found" >&2; exit 1; }
mkdir -p "$out"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", b - a }'; }

ref=$out/cornell_ref_4096spp.exr
if [[ -f $ref ]]; then
  echo "reference: reusing $ref" >&2
else
  echo "reference: rendering $ref (4096 spp; a few minutes on 2 cores)" >&2
  t0=$(now)
  "$trace" "$scene" "${size[@]}" --spp 4096 --seed 1 --quiet --out "$ref"
  echo "reference: $(elapsed "$t0" "$(now)") s wall" >&2
fi

csv=$out/trace_convergence.csv
rows=$(mktemp "$out/.trace_convergence.csv.XXXXXX")
trap 'rm -f "$rows"' EXIT
echo "spp,backend,seconds,trace_seconds,rmse,relmse" >"$rows"

for spp in 1 2 4 8 16 32 64 128 256; do
  for backend in embree bvh; do
    img=$out/cornell_${backend}_${spp}spp.exr
    best=""
    trace_s=""
    for ((r = 0; r < repeats; r++)); do
      t0=$(now)
      summary=$("$trace" "$scene" "${size[@]}" --spp "$spp" --seed 2 --backend "$backend" \
        --quiet --out "$img" 2>&1)
      s=$(elapsed "$t0" "$(now)")
      if [[ -z $best ]] || awk -v a="$s" -v b="$best" 'BEGIN { exit !(a < b) }'; then
        best=$s
        # Summary line: "... Msamples in 0.08 s (..." -> the tracing time alone.
        trace_s=$(sed -n 's/.* in \([0-9.]*\) s (.*/\1/p' <<<"$summary")
      fi
    done
    metrics=$("$compare" "$img" "$ref" --json |
      "$python" -c 'import json, sys; a = json.load(sys.stdin)["all"]; print("%.6g,%.6g" % (a["rmse"], a["relMse"]))')
    echo "$spp,$backend,$best,$trace_s,$metrics" >>"$rows"
    echo "$spp spp $backend: $best s wall (trace $trace_s s), rmse,relmse = $metrics" >&2
  done
done

chmod 644 "$rows"
mv "$rows" "$csv"
trap - EXIT
"$python" "$here/plot_convergence.py" "$csv" "$out/trace_convergence.svg"
echo "wrote $csv and $out/trace_convergence.svg" >&2
