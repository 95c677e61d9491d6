"""Bars of docs/charts/bake_scaling.sh's runs: seconds and speed-up against one process."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
names = [f"{r['run']}\n{r['ranks']} rank(s) x {r['threads_per_rank']} thr" for r in rows]
seconds = [float(r["seconds"]) for r in rows]
speedup = [float(r["speedup"]) for r in rows]
fig, ax = plt.subplots(figsize=(8, 4))
bars = ax.bar(names, seconds, color=["#555" if r["same_bytes"] == "yes" else "#c33" for r in rows])
for bar, s in zip(bars, speedup):
    ax.text(bar.get_x() + bar.get_width() / 2, bar.get_height(), f"x{s:.2f}", ha="center",
            va="bottom")
ax.set_ylabel("bake wall time (s)")
ax.set_title("One bake over MPI ranks on this 2-core machine (same bytes in every run)")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
