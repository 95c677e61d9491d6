#!/usr/bin/env bash
# How one bake scales over processes (docs/bake_scaling.md): the same bake as one process, over
# mpirun -np 2 with one thread per rank (the machine's 2 cores shared out), and oversubscribed
# (-np 2 and -np 4, each rank with every core), timed side by side on this machine; every run's
# lightmap is checked to be the one-process bake's bytes. Speed-up is against the one process on
# the same cores; efficiency is the speed-up per core used, relative to the one process (every
# run here uses all the machine's cores, so the two are equal: what is lost is the stages every
# rank repeats and the hand-over of tiles).
#
# Usage (from the repo root): docs/charts/bake_scaling.sh [BUILD_DIR] [OUT_DIR] [SCENE] [BAKE FLAGS...]
# Default scene: the Conference Room (needs ../shared/scenes/conference) at 10 cm texels and at
# most 256 samples per texel, 16-texel tiles: about 10 min on 2 cores.
set -euo pipefail
build=${1:-build/release}
out=${2:-out/charts}
scene=${3:-content/conference/conference_panels.json}
shift $(( $# < 3 ? $# : 3 ))
flags=("$@")
[[ ${#flags[@]} -gt 0 ]] || flags=(--texel-size 0.1 --spp 256 --tile-size 16 --vpls 4096)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bake="$build/bin/bounce-bake"
cores=$(nproc)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
csv=$out/bake_scaling.csv
echo "run,ranks,threads_per_rank,cores,seconds,speedup,efficiency,tiles_by_rank,same_bytes" > "$csv"
one=""
run() {  # name ranks threads command...
  local name=$1 ranks=$2 threads=$3; shift 3
  local dir=$out/scaling_$name.bake start end seconds
  rm -rf "$dir" "$dir.journal"
  start=$(date +%s.%N)
  "$@" "$scene" -o "$dir" "${flags[@]}" --threads "$threads" --quiet 2> "$out/scaling_$name.log"
  end=$(date +%s.%N)
  seconds=$(echo "$end - $start" | bc -l)
  local shares same=yes
  shares=$(sed -n 's/.*tiles computed by rank 0, 1, ...: //p' "$out/scaling_$name.log" | tr -d ' ' | tr ',' ' ')
  [[ -z $one ]] && one=$seconds
  if [[ $name != one ]]; then cmp -s "$dir/lightmap.exr" "$out/scaling_one.bake/lightmap.exr" || same=no; fi
  local speedup efficiency used
  speedup=$(echo "$one / $seconds" | bc -l)
  used=$(( ranks * threads < cores ? ranks * threads : cores ))
  efficiency=$(echo "$speedup * $cores / $used" | bc -l)
  printf '%s,%d,%d,%d,%.2f,%.3f,%.3f,%s,%s\n' "$name" "$ranks" "$threads" "$used" "$seconds" \
    "$speedup" "$efficiency" "${shares:-all}" "$same" >> "$csv"
  echo "$name: $seconds s" >&2
}
run one 1 "$cores" "$bake"
run np2_core_each 2 1 mpirun --bind-to none -np 2 "$bake" --mpi
run np2_oversubscribed 2 "$cores" mpirun --bind-to none --oversubscribe -np 2 "$bake" --mpi
run np4_oversubscribed 4 1 mpirun --bind-to none --oversubscribe -np 4 "$bake" --mpi
/usr/bin/python3 "$here/plot_bake_scaling.py" "$csv" "$out/bake_scaling.png"
echo "wrote $csv and $out/bake_scaling.png" >&2
