#!/usr/bin/env bash
# Issue 28, measurement 3: the serial part of a bake, stage by stage. Bakes SCENE with
# `--threads 1` and `--threads T`, prints each stage's seconds (bake.json measured.seconds), the
# speed-up and the stage's serial share by Amdahl's law, s = (T·t_T / t_1 − 1) / (T − 1) (0: all
# of it parallel, 1: none), and checks that every file of the two bake folders is the same bytes
# (bake.json apart from its `measured` block).
#
# Usage (from the repo root):
#   tests/bench/bake_thread_scaling.sh SCENE T [BUILD_DIR] [OUT_DIR]
#     SCENE      e.g. content/conference/conference_panels.json
#     T          threads of the second bake (2 on a 2-core machine, 16 on a 16-core one)
#     BUILD_DIR  holds bin/bounce-bake (default build/release)
#     OUT_DIR    receives the two bake folders and their logs (default out/bench)
# Run it on an otherwise idle machine: a process sharing the cores with others gets a share of
# them whatever its thread count, and the shares then measure the others' load, not the bake.
set -euo pipefail

scene=$1
threads=$2
build=${3:-build/release}
out=${4:-out/bench}
mkdir -p "$out"
name=$(basename "$scene" | sed 's/\.[a-z]*$//')
for t in 1 "$threads"; do
  rm -rf "$out/${name}_t$t.bake"
  "$build/bin/bounce-bake" "$scene" --threads "$t" -o "$out/${name}_t$t.bake" --quiet \
    2> "$out/${name}_t$t.log"
done
/usr/bin/python3 - "$out/${name}_t1.bake" "$out/${name}_t$threads.bake" "$threads" <<'PY'
import filecmp, json, os, sys
one, many, t = sys.argv[1], sys.argv[2], int(sys.argv[3])
a, b = (json.load(open(os.path.join(d, "bake.json"))) for d in (one, many))
s1, sT = a["measured"]["seconds"], b["measured"]["seconds"]
print(f"{'stage':12} {'1 thread':>10} {f'{t} threads':>11} {'speed-up':>9} {'serial share':>13}")
for stage in list(s1):
    x, y = s1[stage], sT.get(stage, 0.0)
    share = (t * y / x - 1) / (t - 1) if x > 0 and t > 1 else float("nan")
    speed = x / y if y > 0 else float("nan")
    print(f"{stage:12} {x:9.3f}s {y:10.3f}s {speed:9.2f} {share:13.3f}")
for d in (a, b):
    d.pop("measured")
files = sorted(f for f in os.listdir(one) if f != "bake.json")
same = [f for f in files if filecmp.cmp(os.path.join(one, f), os.path.join(many, f), shallow=False)]
print("bake.json (measured apart):", "same" if a == b else "DIFFERENT")
print("same bytes:", ", ".join(same) or "none")
if len(same) != len(files) or a != b:
    print("DIFFERENT:", ", ".join(sorted(set(files) - set(same))))
    sys.exit(1)
PY
