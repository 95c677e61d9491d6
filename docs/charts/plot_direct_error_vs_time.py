#!/usr/bin/python3
"""Direct light in the Conference Room (8 ceiling panels in one mesh, 2 spots): mean absolute
relative error of bounce-render --mode direct (1280x720 box-filtered to 320x180) against
bounce-trace --direct-only, against the frame time, one point per method (shadow maps only;
baked visibility at a texel size, labelled with its bake time); and, as triangles, the full
frame against bounce-trace's full image for the default bake's baked visibility and for the
panels' direct light baked into the lightmap (baked direct), which cannot be drawn apart.

Usage: /usr/bin/python3 docs/charts/plot_direct_error_vs_time.py CSV PNG
CSV: docs/charts/direct_error_vs_time.sh's (method,texel_m,bake_s,visibility_s,frame_ms,
mean_abs_rel_error).
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
        sys.exit(f"plot_direct_error_vs_time: {sys.argv[1]}: no rows")
    fig, ax = plt.subplots(figsize=(7, 4.6), dpi=110)
    for r in rows:
        x = float(r["frame_ms"]) / 1000.0
        y = 100.0 * float(r["mean_abs_rel_error"])
        baked = r["method"] != "shadow maps"
        full = "full frame" in r["method"]
        label = r["method"]
        if baked:
            label += f", {100 * float(r['texel_m']):.1f} cm texels (bake {float(r['bake_s']):.0f} s"
            label += f", visibility {float(r['visibility_s']):.1f} s)" if not full else ")"
        else:
            label += " (area cubes by contribution, PCSS)"
        marker = "^" if full else ("o" if baked else "s")
        ax.scatter([x], [y], s=60, marker=marker, label=label)
    ax.axhline(5.0, color="grey", linestyle="--", linewidth=1)
    ax.text(ax.get_xlim()[0], 5.3, " issue target 5%", color="grey", fontsize=8)
    ax.set_xlabel("frame time, s (1280x720, llvmpipe, 2 shared cores)")
    ax.set_ylabel("mean abs. relative error vs path tracer, %")
    ax.set_ylim(0, None)
    ax.set_title("Conference Room direct light: error against frame time")
    ax.legend(fontsize=7, loc="center right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
