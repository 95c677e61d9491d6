#!/bin/sh
# The lightmap's error against its bake time, whole paths beside the cache gather
# (docs/baker.md "Gather with a cache"): each bake's lightmap.exr against a converged bake of the
# same texels (bounce-compare's mean |relative error| and bias over the whole atlas), and its
# irradiance seconds (the cache pass included) from bake.json. One CSV row per bake.
#
#   docs/charts/cache_gather_sweep.sh SCENE REF.bake OUT.csv [bounce-bake options...]
#   (REF.bake: bounce-bake SCENE -o REF.bake --target-error 0 --spp N [the same options])
set -eu
scene=$1 ref=$2 csv=$3
shift 3
bin=${BIN:-build/release/bin}
dir=$(mktemp -d)
echo "scene,gather,target,cache_spp,irradiance_s,total_s,spp_mean,rays,samples,mean_abs_rel_error,bias" >"$csv"
for target in ${TARGETS:-0.3 0.2 0.1 0.05}; do
  for gather in paths cache; do
    for cache in ${CACHE_SPPS:-64}; do
      [ "$gather" = paths ] && [ "$cache" != "$(echo ${CACHE_SPPS:-64} | cut -d' ' -f1)" ] && continue
      "$bin/bounce-bake" "$scene" -o "$dir/b.bake" --quiet --target-error "$target" \
        --gather "$gather" --cache-spp "$cache" "$@"
      "$bin/bounce-compare" "$dir/b.bake/lightmap.exr" "$ref/lightmap.exr" --json >"$dir/c.json"
      /usr/bin/python3 - "$dir/b.bake/bake.json" "$dir/c.json" "$scene" "$gather" "$target" \
        "$cache" >>"$csv" <<'PY'
import json, sys
bake, cmp = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
s = bake["measured"]["seconds"]
print(",".join(str(v) for v in [sys.argv[3], sys.argv[4], sys.argv[5], sys.argv[6],
      s["irradiance"], s["total"], bake["samples"]["perTexelMean"], bake["rays"]["traced"],
      bake["samples"]["total"], cmp["all"]["meanAbsRelError"], cmp["all"]["bias"]]))
PY
      tail -1 "$csv"
    done
  done
done
rm -rf "$dir"
