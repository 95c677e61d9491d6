"""The lightmap's error against its irradiance time, whole paths beside the cache gather
(docs/charts/cache_gather.png, docs/baker.md "Gather with a cache"), from the CSVs of
docs/charts/cache_gather_sweep.sh (one per scene):

    /usr/bin/python3 docs/charts/plot_cache_gather.py OUT.png TITLE_1 CSV_1 [TITLE_2 CSV_2 ...]

x: seconds of the irradiance stage (the cache pass included; 2 threads, shared machine), y: the
light-weighted relative L1 error of the lightmap against a converged bake of the same texels
(lightmap_flux_error). One panel per scene; points are target errors, labelled.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
pairs = list(zip(sys.argv[2::2], sys.argv[3::2]))
fig, axes = plt.subplots(1, len(pairs), figsize=(6 * len(pairs), 4.2), dpi=120, squeeze=False)
for ax, (title, path) in zip(axes[0], pairs):
    rows = list(csv.DictReader(open(path)))
    for gather, style in (("paths", "-o"), ("cache", "--s")):
        for spp in sorted({r["cache_spp"] for r in rows if r["gather"] == gather}, key=int):
            sel = [r for r in rows if r["gather"] == gather and r["cache_spp"] == spp]
            sel.sort(key=lambda r: float(r["irradiance_s"]))
            xs = [float(r["irradiance_s"]) for r in sel]
            ys = [100 * float(r["rel_l1"]) for r in sel]
            label = "whole paths" if gather == "paths" else f"cache ({spp} spp)"
            ax.plot(xs, ys, style, label=label)
            for r, x, y in zip(sel, xs, ys):
                ax.annotate(r["target"], (x, y), textcoords="offset points", xytext=(4, 4),
                            fontsize=7)
    ax.set_xscale("log")
    ax.set_xlabel("irradiance stage, s (2 threads)")
    ax.set_ylabel("light-weighted |error| vs converged bake, %")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.tight_layout()
fig.savefig(out)
