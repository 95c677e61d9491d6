#!/usr/bin/python3
"""The irradiance probes' error against their largest spacing: relative RMS of the baked light
read from the probes at points of the probe-lit surfaces against the same light traced there
(the reference's own noise taken out), and the probe stage's time.

Usage: /usr/bin/python3 docs/charts/plot_probe_spacing.py CSV PNG
CSV: bench_probe_spacing's output (spacing_m, probes, sampled, seconds, rel_rms, rel_rms_noise,
mean_rel, median_rel, bias_rel).
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
        rows = sorted(csv.DictReader(f), key=lambda r: float(r["spacing_m"]))
    if not rows:
        sys.exit(f"plot_probe_spacing: {sys.argv[1]}: no rows")
    h = [100 * float(r["spacing_m"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7.5, 4.6), dpi=110)
    ax.plot(h, [100 * float(r["rel_rms"]) for r in rows], marker="o",
            label="relative RMS error (reference noise removed)")
    ax.plot(h, [100 * float(r["median_rel"]) for r in rows], marker="D",
            label="median |a − b| / (b + 0.01 b̄)")
    ax.plot(h, [100 * float(r["bias_rel"]) for r in rows], marker="s", linestyle="--",
            label="bias, Σ(a − b) / Σ b")
    ax.axvline(25, color="grey", linestyle=":", label="default largest spacing, 25 cm")
    ax.set_xlabel("largest probe spacing h, cm")
    ax.set_ylabel("error of the probes' E at the surfaces, %")
    ax.grid(True, alpha=0.3)
    right = ax.twinx()
    right.plot(h, [float(r["seconds"]) for r in rows], color="tab:red", marker="^",
               label="probe stage, s")
    right.set_ylabel("probe stage seconds (2 cores, shared)", color="tab:red")
    lines = ax.get_legend_handles_labels()
    more = right.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], fontsize=8, loc="upper center")
    ax.set_title("Conference Room: probe-lit surfaces' baked light against probe spacing")
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
