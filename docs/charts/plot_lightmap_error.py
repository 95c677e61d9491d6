#!/usr/bin/python3
"""Plot the rendered indirect frame's error against bake time (lightmap_error_vs_time.sh).

Usage: plot_lightmap_error.py CSV PNG [TITLE]
CSV: bench_indirect_accuracy's columns. One line per (texel size, denoiser), one point per
target error, labelled; the 5% goal as a line; the reference's noise allowance as a band.
TITLE defaults to the Cornell box sweep's.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path, title="Cornell box, 64², labels: per-texel target error"):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_lightmap_error: {csv_path}: no data rows")
    series = {}
    for r in rows:
        key = (float(r["texel_size_m"]), r["denoise"])
        series.setdefault(key, []).append(r)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    styles = {"on": "-", "off": "--"}
    colours = {}
    for (texel, denoise), points in sorted(series.items()):
        points.sort(key=lambda r: float(r["bake_s"]))
        colour = colours.setdefault(texel, f"C{len(colours)}")
        x = [float(p["bake_s"]) for p in points]
        y = [100 * float(p["mean_abs_rel_error"]) for p in points]
        ax.plot(x, y, styles[denoise], marker="o", color=colour,
                label=f"{100 * texel:.1f} cm texels, denoiser {denoise}")
        for p, xi, yi in zip(points, x, y):
            ax.annotate(f"{float(p['target_error']):g}", (xi, yi), textcoords="offset points",
                        xytext=(4, 4), fontsize=7, color=colour)
    noise = 100 * max(float(r["ref_noise_allowance"]) for r in rows)
    ax.axhline(5.0, color="k", linewidth=0.8)
    ax.text(0.01, 5.0, "goal 5%", va="bottom", fontsize=8, transform=ax.get_yaxis_transform())
    ax.axhspan(0, noise, color="0.85", zorder=0,
               label=f"reference noise allowance ({noise:.1f}%)")
    ax.set_xscale("log")
    ax.set_xlabel("bake time, s (atlas + bake, 2 cores, shared machine)")
    ax.set_ylabel("indirect frame: mean |ΔY|/Y vs path tracer, %")
    ax.set_title(title)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
