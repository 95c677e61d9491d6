"""The Conference Room's indirect light at 480 × 270: the path tracer beside the two 10 cm bakes
of docs/charts/cache_gather_sweep.sh at target 0.1 (whole paths, cache gather), and a crop of the
whiteboard, its frame, the wall-floor corner and the chairs (docs/charts/cache_gather_look.jpg):

    S=content/conference/conference_panels.json
    build/release/bin/bounce-trace $S --indirect-only --spp 256 --width 480 --height 270 \\
        --out T.exr --png T.png
    build/release/bin/bounce-render $S --bake DIR/paths_0.1_0.bake --mode indirect \\
        --width 480 --height 270 --out P.png
    build/release/bin/bounce-render $S --bake DIR/cache_0.1_32.bake --mode indirect \\
        --width 480 --height 270 --out C.png
    /usr/bin/python3 docs/charts/plot_cache_gather_look.py T.png P.png C.png OUT.jpg
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

titles = ["path tracer, 256 spp", "bake, whole paths (10 cm, 0.1)", "bake, cache gather (10 cm, 0.1)"]
fig, axes = plt.subplots(2, 3, figsize=(16, 7), dpi=80)
for column, (path, title) in enumerate(zip(sys.argv[1:4], titles)):
    image = mpimg.imread(path)
    axes[0][column].imshow(image)
    axes[0][column].set_title(title)
    axes[1][column].imshow(image[60:170, 130:300], interpolation="nearest")
    for row in (0, 1):
        axes[row][column].axis("off")
fig.tight_layout()
fig.savefig(sys.argv[4], pil_kwargs={"quality": 85})
