"""Frame time of the VPL term against the VPL count, with and without the per-cell lightcuts
(docs/vpl_measurements.md, "Frame time against the VPL count").

    build/release/bin/bench_vpl --benchmark_format=csv > docs/charts/vpl_frame_time.csv
    /usr/bin/python3 docs/charts/plot_vpl_frame_time.py docs/charts/vpl_frame_time.csv \
        docs/charts/vpl_frame_time.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, out):
    series = {0: [], 1: []}
    with open(path) as f:
        for row in csv.DictReader(f):
            # name: vplFrame/cap:N/culling:C/iterations:3/real_time
            parts = dict(p.split(":") for p in row["name"].split("/")[1:3])
            series[int(parts["culling"])].append(
                (float(row["vpls"]), float(row["real_time"])))
    fig, ax = plt.subplots(figsize=(6, 4))
    for culling, label in ((0, "every VPL at every pixel"), (1, "per-cell lightcut, κ = 4")):
        points = sorted(series[culling])
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=label)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("VPLs")
    ax.set_ylabel("frame time, ms (160×120, llvmpipe, 2 shared cores)")
    ax.set_title("Cornell box, --mode vpl")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
