"""Frame time against the point-light count, light culling on and off (docs/charts/light_culling.png),
from bench_light_culling's CSV.

    build/release/bin/bench_light_culling --width 1280 --height 720 --frames 1 \
        --counts 8,64,256,1024 --out docs/charts/light_culling.csv
    /usr/bin/python3 docs/charts/plot_light_culling.py docs/charts/light_culling.csv docs/charts/light_culling.png

x: point lights in the field (log), y: wall time of one 1280x720 frame (render + glFinish, log;
llvmpipe, 2 vCPUs shared with another engineer's builds). many_lights (64 lights in a 12 m room,
every light within every cluster's reach) is drawn as two lone markers.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
field = [r for r in rows if r["scene"] == "field"]
room = [r for r in rows if r["scene"] == "many_lights"]
fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
xs = [int(r["lights"]) for r in field]
ax.plot(xs, [float(r["ms_off"]) for r in field], "-o", color="tab:red", label="culling off (every light)")
ax.plot(xs, [float(r["ms_on"]) for r in field], "-s", color="tab:blue", label="culling on (cluster lists)")
for r in field:
    ax.annotate("%.0f/cluster" % float(r["lights_per_cluster"]), (int(r["lights"]), float(r["ms_on"])),
                textcoords="offset points", xytext=(4, -12), fontsize=8, color="tab:blue")
for r in room:
    ax.plot([int(r["lights"])], [float(r["ms_off"])], "x", color="tab:red", markersize=9,
            label="many_lights, off")
    ax.plot([int(r["lights"])], [float(r["ms_on"])], "+", color="tab:blue", markersize=11,
            label="many_lights, on")
ax.set_xscale("log", base=2)
ax.set_yscale("log")
ax.set_xlabel("point lights (field: 5 m apart, 0.05-0.5 W/sr, floor 5(sqrt(N)+1) m wide)")
ax.set_ylabel("ms per 1280x720 frame (llvmpipe, 2 shared vCPUs)")
ax.set_title("Light culling: frame time against light count (E_floor at EV 0)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2])
