#!/usr/bin/python3
"""Plot bake time and peak memory against the static triangle count (bake_time_vs_triangles.sh).

Usage: plot_bake_time_vs_triangles.py CSV PNG
CSV: the script's columns. Content scenes as labelled points (with their texel size and atlas
use), the synthetic series (one room, its quads cut N x N) as a line.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_bake_time_vs_triangles: {csv_path}: no data rows")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, column, label in ((axes[0], "bake_s", "bake time, s (2 cores)"),
                              (axes[1], "peak_mb", "peak resident memory, MB")):
        synthetic = [r for r in rows if r["series"] == "synthetic"]
        synthetic.sort(key=lambda r: int(r["triangles"]))
        ax.plot([int(r["triangles"]) for r in synthetic], [float(r[column]) for r in synthetic],
                "-o", color="C0", label="sunlit room cut N×N, 10 cm texels")
        for r in rows:
            x, y = int(r["triangles"]), float(r[column])
            if r["series"] == "content":
                ax.plot([x], [y], "s", color="C1")
                text = (f"{r['scene']}\n{100 * float(r['texel_size_m']):.1f} cm, "
                        f"use {float(r['utilisation']):.2f}")
            else:
                text = r["scene"].replace("sunlit_", "")
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(5, 4), fontsize=7)
        ax.plot([], [], "s", color="C1", label="content scenes, bounce-bake defaults")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("static triangles")
        ax.set_ylabel(label)
        ax.legend(fontsize=8, loc="lower right")
    fig.suptitle("Bake against triangle count (labels: texel size, atlas use)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
