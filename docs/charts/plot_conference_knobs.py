#!/usr/bin/python3
"""The renderer's knobs on the Conference Room: full-frame error against the path tracer
(mean |a - b| / (|b| + 0.01), 96x54) against the frame time (llvmpipe, 384x216), one marker
style per knob, each point labelled with its setting; the lightmap-only frame's time as a
vertical line (its error is not a full frame's).

Usage: /usr/bin/python3 docs/charts/plot_conference_knobs.py CSV PNG
CSV: docs/charts/conference_knobs.sh's knobs.csv (knob, setting, frame_ms, lit_pass_ms, mare,
relmse, load).
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"msaa": "o", "shadow_resolution": "s", "shadow_filter": "^", "shadows": "v",
           "light_culling": "D", "probes": "P", "area_lights": "X"}
LABELS = {"msaa": "samples per pixel (--msaa)", "shadow_resolution": "spot map texels",
          "shadow_filter": "shadow filter", "shadows": "no shadows",
          "light_culling": "no light culling", "probes": "VPLs for the probe-lit",
          "area_lights": "static lights per pixel (--live-static-lights)"}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_conference_knobs: {sys.argv[1]}: no rows")
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    for knob, marker in MARKERS.items():
        pts = [(float(r["frame_ms"]), 100 * float(r["mare"]), r["setting"]) for r in rows
               if r["knob"] == knob]
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, linestyle="-"
                if len(pts) > 1 else "none", label=LABELS[knob])
        for ms, err, setting in pts:
            ax.annotate(setting, (ms, err), textcoords="offset points", xytext=(4, 3), fontsize=7)
    for r in rows:
        if r["knob"] == "mode" and r["setting"] == "lightmap_only":
            ax.axvline(float(r["frame_ms"]), color="grey", linestyle=":",
                       label="lightmap-only frame (msaa 4)")
    ax.axhline(5.0, color="red", linewidth=0.8, linestyle="--", label="5 % (issue 27)")
    ax.set_xlabel("frame time, ms (llvmpipe, 384x216, render + readback; a proxy)")
    ax.set_ylabel("full frame vs bounce-trace, mean relative error, %")
    ax.set_title("Conference Room: the renderer's knobs (default bake, camera 'corner')")
    ax.set_xscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
