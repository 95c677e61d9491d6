#!/usr/bin/python3
"""The VPL term's error against its frame time, with and without culling and VPL shadow maps,
and the lightmap's point (docs/vpl_measurements.md, "Error against frame time").

    nice build/release/bin/bench_vpl_error --ref-spp 4096 --ref out/vpl_error_ref128.exr \
        --out docs/charts/vpl_error_vs_time.csv
    /usr/bin/python3 docs/charts/plot_vpl_error_vs_time.py docs/charts/vpl_error_vs_time.csv \
        docs/charts/vpl_error_vs_time.png

CSV: bench_vpl_error's columns. Log-log: x the process CPU time per frame (the steadier figure
on a shared machine; the wall time is in the CSV); y, left: the mean |ΔY|/Y against the path
tracer with the reference's noise allowance as a grey band; right: the relative MSE with the
reference's expected share (mean σ²/Y²) subtracted. One line per {culling, visibility} through
the VPL counts (labelled); the lightmap a star.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {
    (0, 0): "every VPL, no visibility",
    (0, 1): "every VPL, VPL shadow maps",
    (1, 0): "lightcut culling, no visibility",
    (1, 1): "lightcut culling, VPL shadow maps",
}
STYLES = {(0, 0): ("C0", "--", "o"), (0, 1): ("C0", "-", "s"),
          (1, 0): ("C1", "--", "o"), (1, 1): ("C1", "-", "s")}


def metric_mean_abs(r):
    return 100 * float(r["mean_abs_rel_error"])


def metric_mse(r):
    # The renderer's own part: the reference's expected share mean(σ²/Y²) removed.
    return max(float(r["rel_mse"]) - float(r["ref_rel_var"]), 1e-6)


def panel(ax, rows, metric, ylabel):
    for key, label in LABELS.items():
        points = [r for r in rows if r["method"] == "vpl"
                  and (int(r["culling"]), int(r["shadows"])) == key]
        if not points:
            continue
        points.sort(key=lambda r: int(r["vpls"]))
        colour, line, marker = STYLES[key]
        x = [float(p["cpu_ms"]) for p in points]
        y = [metric(p) for p in points]
        ax.plot(x, y, line, marker=marker, color=colour, label=label)
        for p, xi, yi in zip(points, x, y):
            # Culled labels below the point: at ≤ 255 VPLs culling falls back to every VPL.
            ax.annotate(p["vpls"], (xi, yi), textcoords="offset points",
                        xytext=(4, -10 if key[0] else 3),
                        fontsize=7, color=colour)
    for r in rows:
        if r["method"] == "lightmap":
            ax.plot(float(r["cpu_ms"]), metric(r), "*", color="C2", markersize=16,
                    label="lightmap (bounce-bake defaults)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("frame time, ms process CPU per frame\n(128², llvmpipe, 2 shared cores)")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_vpl_error_vs_time: {csv_path}: no data rows")
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2))
    panel(left, rows, metric_mean_abs, "mean |ΔY|/Y against the path tracer, %")
    noise = 100 * max(float(r["ref_noise_allowance"]) for r in rows)
    left.axhspan(1e-3, noise, color="0.85", zorder=0,
                 label=f"reference noise allowance ({noise:.1f}%)")
    left.set_ylim(bottom=0.8 * noise)
    ticks = [2, 3, 5, 10, 20, 30, 50]
    left.set_yticks(ticks)
    left.set_yticklabels([str(t) for t in ticks])
    left.legend(fontsize=8)
    panel(right, rows, metric_mse, "relative MSE, mean((ΔY/Y)²) − reference variance")
    fig.suptitle("Cornell box, indirect light: VPL count (labels) against the lightmap")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
