#!/usr/bin/python3
"""Shadow quality against frame time: the Cornell box's direct light (area light) against the
path tracer, mean absolute relative error vs ms per frame, one line per filter, each point a
shadow-map resolution (texels per side of each cube face).

Usage: /usr/bin/python3 docs/charts/plot_soft_shadows.py CSV PNG
CSV: tests/bench/bench_soft_shadows.cpp's (resolution, filter, ms_per_frame, mare, penumbra_share,
umbra_share); docs/charts/soft_shadow_tradeoff.sh makes both.
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
        sys.exit(f"plot_shadows: {sys.argv[1]}: no rows")
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    labels = {"hard": "hard (one comparison from the light's centre)",
              "soft": "soft (PCSS, 32 light points)"}
    for name, marker in (("hard", "s"), ("soft", "o")):
        pts = sorted((float(r["ms_per_frame"]), 100 * float(r["mare"]), int(r["resolution"]))
                     for r in rows if r["filter"] == name)
        pts.sort(key=lambda p: p[2])
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=labels[name])
        for ms, err, res in pts:
            ax.annotate(str(res), (ms, err), textcoords="offset points", xytext=(4, 4), fontsize=8)
    none = [r for r in rows if r["filter"] == "none"]
    if none:
        ax.axhline(3.0, color="grey", linestyle=":", linewidth=1)
        ax.text(ax.get_xlim()[0], 3.05, " goal 3%", color="grey", fontsize=8, va="bottom")
        ax.set_title("Cornell box, direct light vs path tracer (no shadows: %.1f%% at %.0f ms)"
                     % (100 * float(none[0]["mare"]), float(none[0]["ms_per_frame"])), fontsize=10)
    ax.set_xlabel("frame time, ms (offscreen, llvmpipe, 2 cores; median)")
    ax.set_ylabel("mean |f − r| / (r + 0.01), % of non-emitter pixels")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
