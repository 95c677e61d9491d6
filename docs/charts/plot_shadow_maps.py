#!/usr/bin/python3
"""Spot and point shadow maps: visibility error against frame time. One line per light kind and
filter, each point a shadow-map resolution (texels per side of the map or cube face). The error
is the fraction of pixels whose shadow-mapped visibility disagrees with ray-traced visibility
(one-pixel band along true shadow edges excluded); the frame time is wall ms per 1280x720 frame.

Usage: /usr/bin/python3 docs/charts/plot_shadow_maps.py CSV PNG
CSV: tests/bench/bench_shadows.cpp's, e.g.
  build/release/bin/bench_shadows --out docs/charts/shadow_maps.csv --frames 6
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_shadow_maps: {sys.argv[1]}: no rows")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), dpi=110, sharey=True)
    for ax, light in zip(axes, ("spot", "point")):
        series = {}
        for r in rows:
            if r["light"] != light:
                continue
            if r.get("is_default") == "1":
                continue  # the default set-up, repeated in the sweep
            key = (r["filter"], float(r["filter_radius_texels"]))
            series.setdefault(key, []).append(
                (int(r["resolution"]), float(r["ms_per_frame"]), 100 * float(r["disagree_fraction"])))
        for (filt, radius), pts in sorted(series.items()):
            pts.sort()
            label = "hardware 2x2" if filt == "hardware" else f"Poisson r={radius:g} texels"
            ax.plot([p[1] for p in pts], [max(p[2], 1e-3) for p in pts], marker="o", label=label)
            for res, ms, err in pts:
                ax.annotate(str(res), (ms, max(err, 1e-3)), textcoords="offset points",
                            xytext=(3, 3), fontsize=7)
        unshadowed = [float(r["ms_per_frame_unshadowed"]) for r in rows if r["light"] == light]
        if unshadowed:
            ax.axvline(unshadowed[0], color="grey", linestyle=":", label="no shadows (time)")
        ax.axhline(0.5, color="red", linestyle="--", linewidth=0.8, label="goal 0.5%")
        ax.set_yscale("log")
        ax.set_title(f"{light} light")
        ax.set_xlabel("ms per frame (1280x720, llvmpipe, 2 cores, loaded machine)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("pixels disagreeing with ray-traced visibility (%)\n(0 drawn at 0.001)")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
