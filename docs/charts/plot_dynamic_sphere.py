#!/usr/bin/python3
"""Contact sheet of the dynamic sphere at three positions in the Cornell box, modes
full, indirect and vpl, from PNGs rendered by bounce-render (docs/vpl.md, "Dynamic objects"):

    S=content/cornell_box_dynamic/cornell_box_dynamic.gltf
    bounce-bake $S -o dyn.bake
    i=0; for P in "0.42 0.30 0.12" "0.14 0.30 0.30" "0.278 0.35 0.12"; do i=$((i+1))
      for M in full indirect vpl; do
        bounce-render $S --bake dyn.bake --move sphere $P --mode $M --width 256 --height 256 \\
            --out DIR/p${i}_$M.png
      done; done
    /usr/bin/python3 docs/charts/plot_dynamic_sphere.py DIR docs/vpl/dynamic_sphere.png
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

src, out = sys.argv[1], sys.argv[2]
positions = ["sphere at (0.42, 0.30, 0.12) m\n3.3 cm from the red wall",
             "(0.14, 0.30, 0.30) m\n4 cm from the green wall", "(0.278, 0.35, 0.12) m\nmid-box"]
modes = [("full", "full: direct + lightmap;\nsphere: direct + VPLs"),
         ("indirect", "indirect: lightmap;\nsphere: rho/pi E_vpl"),
         ("vpl", "vpl: every surface\nrho/pi E_vpl")]
fig, axes = plt.subplots(3, 3, figsize=(9, 9.6))
for r, label in enumerate(positions):
    for c, (mode, title) in enumerate(modes):
        ax = axes[r][c]
        ax.imshow(mpimg.imread(f"{src}/p{r + 1}_{mode}.png"))
        ax.set_xticks([]), ax.set_yticks([])
        if r == 0:
            ax.set_title(title, fontsize=9)
        if c == 0:
            ax.set_ylabel(label, fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=100)
