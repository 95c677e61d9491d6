"""Lightmap error against bake time (docs/charts/bake_error.png) from bench_bake's sweep CSV.

    build/release/bin/bench_bake --sweep docs/charts/bake_error.csv
    /usr/bin/python3 docs/charts/plot_bake_error.py docs/charts/bake_error.csv docs/charts/bake_error.png

x: CPU seconds of the bake (atlas excluded; 2 threads), y: mean absolute relative error of the
texels' irradiance against independent path-traced irradiance (300 texels, 8192 samples each;
the reference's own standard error is drawn as the dotted floor). One line per texel budget and
denoiser setting; points are target errors 0.4 … 0.03.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
styles = {("0",): "-o", ("1",): "--s"}
floor = []
for budget in sorted({r["texel_budget"] for r in rows}, key=int, reverse=True):
    for denoise in ("0", "1"):
        sel = [r for r in rows if r["texel_budget"] == budget and r["denoise"] == denoise]
        if not sel:
            continue
        size = float(sel[0]["texel_size_m"]) * 100
        xs = [float(r["cpu_s"]) for r in sel]
        ys = [100 * float(r["mean_abs_rel_error"]) for r in sel]
        ax.plot(xs, ys, styles[(denoise,)],
                label=f"texel {size:.1f} cm, denoiser {'on' if denoise == '1' else 'off'}")
        for r, x, y in zip(sel, xs, ys):
            ax.annotate(r["target_error"].rstrip("0"), (x, y), fontsize=6,
                        textcoords="offset points", xytext=(3, 3))
        floor.append(100 * 0.8 * float(sel[0]["reference_error"]))
ax.axhline(5, color="grey", lw=0.8)
ax.text(0.2, 5.2, "goal 5%", fontsize=7, color="grey")
ax.axhline(max(floor), color="grey", ls=":", lw=0.8)
ax.text(0.2, max(floor) * 1.05, "reference noise (mean |rel|)", fontsize=7, color="grey")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("bake CPU time, s (Cornell box; labels: --target-error)")
ax.set_ylabel("mean |relative error| of texel irradiance, %")
ax.set_title("Lightmap error against bake time")
ax.legend(fontsize=7)
ax.grid(True, which="both", lw=0.3)
fig.tight_layout()
fig.savefig(sys.argv[2])
