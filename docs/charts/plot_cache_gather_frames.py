"""The Conference Room's indirect frame: the path tracer, the paths-gathered bake and the
cache-gathered bake side by side (docs/charts/cache_gather_frames.png, docs/baker.md "Gather with
a cache"), from bench_indirect_accuracy's --out-dir PNGs:

    for g in paths cache; do build/release/bin/bench_indirect_accuracy \\
        content/conference/conference_panels.json --size 96 --height 54 --box 4 --ref-spp 8192 \\
        --ref REF.exr --vpls 4096 --gather $g --out-dir DIR_$g; done
    for g in paths cache; do build/release/bin/bounce-compare DIR_$g/indirect.exr REF.exr \
        --mask DIR_$g/mask.png --error-image DIR_$g/err.png --error-scale 0.2; done
    /usr/bin/python3 docs/charts/plot_cache_gather_frames.py DIR_paths DIR_cache OUT.png

Top row: the three frames; bottom row: each bake's |error| against the tracer (blue 0, red ≥ 20%,
black: pixels the bench leaves out: edges, emitters, dynamic objects).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

paths, cache, out = sys.argv[1:4]
images = [(f"{paths}/reference.png", "path tracer, 8192 spp"),
          (f"{paths}/indirect.png", "bake, whole paths"),
          (f"{cache}/indirect.png", "bake, cache gather")]
errors = [(None, ""), (f"{paths}/err.png", "|error|, whole paths"),
          (f"{cache}/err.png", "|error|, cache gather")]
fig, axes = plt.subplots(2, 3, figsize=(15, 6.4), dpi=110)
for ax, (path, title) in zip(list(axes[0]) + list(axes[1]), images + errors):
    ax.axis("off")
    if path is None:
        continue
    ax.imshow(mpimg.imread(path), interpolation="nearest")
    ax.set_title(title)
fig.tight_layout()
fig.savefig(out)
