#!/bin/sh
# The lightmap's error against its bake time, whole paths beside the cache gather
# (docs/baker.md "Gather with a cache"): each bake's lightmap.exr against a converged bake of the
# same texels (lightmap_flux_error: the light-weighted relative L1 error, RMSE and bias), and its
# irradiance seconds (the cache pass included) from bake.json. One CSV row per bake; the bakes
# are kept in DIR/<gather>_<target>_<cacheSpp>.bake.
#
#   docs/charts/cache_gather_sweep.sh SCENE REF.bake DIR OUT.csv [bounce-bake options...]
#   (REF.bake: bounce-bake SCENE -o REF.bake --target-error 0 --spp N [the same options])
#   TARGETS="0.3 0.2 0.1 0.05" CACHE_SPPS="32" by default.
set -eu
scene=$1 ref=$2 dir=$3 csv=$4
shift 4
bin=${BIN:-build/release/bin}
mkdir -p "$dir"
echo "scene,gather,target,cache_spp,irradiance_s,total_s,spp_mean,rays,samples,rel_l1,rel_rmse,bias" >"$csv"
for target in ${TARGETS:-0.3 0.2 0.1 0.05}; do
  for run in paths ${CACHE_SPPS:-32}; do
    gather=cache cache=$run
    [ "$run" = paths ] && gather=paths cache=0
    out="$dir/${gather}_${target}_${cache}.bake"
    "$bin/bounce-bake" "$scene" -o "$out" --quiet --target-error "$target" --gather "$gather" \
      --cache-spp "$((cache > 0 ? cache : 1))" "$@"
    error=$("$bin/lightmap_flux_error" "$out/lightmap.exr" "$ref/lightmap.exr")
    /usr/bin/python3 - "$out/bake.json" "$scene" "$gather" "$target" "$cache" "$error" \
      >>"$csv" <<'PY'
import json, sys
bake = json.load(open(sys.argv[1]))
s = bake["measured"]["seconds"]
l1, rmse, bias, _ = sys.argv[6].split()
print(",".join(str(v) for v in [sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5],
      s["irradiance"], s["total"], bake["samples"]["perTexelMean"], bake["rays"]["traced"],
      bake["samples"]["total"], l1, rmse, bias]))
PY
    tail -1 "$csv"
  done
done
