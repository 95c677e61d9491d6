#!/usr/bin/python3
"""Plot error against time: log-log relMSE vs wall seconds, one line per backend, as SVG.

Usage: plot_convergence.py CSV SVG
CSV columns: spp, backend, seconds, trace_seconds, rmse, relmse (trace_convergence.sh).

Python standard library only; the SVG is written by hand. Also prints, per backend, the
least-squares slope of log relMSE against log seconds and against log spp (an unbiased Monte
Carlo estimator gives -1: variance ~ 1/N and N ~ t once start-up is negligible), and the time
ratio of each backend to the first one at equal spp.
"""

import csv
import math
import os
import sys
import tempfile

WIDTH, HEIGHT = 720, 520
LEFT, RIGHT, TOP, BOTTOM = 90, 30, 50, 70  # plot margins, px
COLOURS = ["#1f6fb4", "#d9541e", "#2a9d3a", "#8c4fb0"]


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_convergence: {path}: no data rows")
    series = {}
    for r in rows:
        series.setdefault(r["backend"], []).append(
            (int(r["spp"]), float(r["seconds"]), float(r["relmse"]))
        )
    for pts in series.values():
        pts.sort()
    return series


def slope(xs, ys):
    """Least-squares slope of log10(y) against log10(x)."""
    lx = [math.log10(x) for x in xs]
    ly = [math.log10(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx


def minus(x):
    """x with two decimals and a typographic minus sign."""
    return f"{x:.2f}".replace("-", "−")


def decades(lo, hi):
    return math.floor(math.log10(lo)), math.ceil(math.log10(hi))


def power_label(k):
    """10^k as SVG text with a raised exponent."""
    return f'10<tspan dy="-7" font-size="10">{k}</tspan>'


def svg(series, title):
    xs = [s for pts in series.values() for _, s, _ in pts]
    ys = [e for pts in series.values() for _, _, e in pts]
    x0, x1 = decades(min(xs), max(xs))
    y0, y1 = decades(min(ys), max(ys))
    pw, ph = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM

    def px(x):
        return LEFT + (math.log10(x) - x0) / (x1 - x0) * pw

    def py(y):
        return TOP + (y1 - math.log10(y)) / (y1 - y0) * ph

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
        f'viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif" font-size="13">',
        f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
        f'<text x="{WIDTH / 2}" y="28" text-anchor="middle" font-size="15">{title}</text>',
    ]
    # Grid and log ticks: a labelled line per decade, minor ticks at 2..9 x 10^k.
    for k in range(x0, x1 + 1):
        for m in range(1, 10) if k < x1 else [1]:
            x = px(m * 10.0**k)
            major = m == 1
            out.append(
                f'<line x1="{x:.1f}" y1="{TOP}" x2="{x:.1f}" y2="{TOP + ph}" '
                f'stroke="{"#ccc" if major else "#eee"}"/>'
            )
            out.append(
                f'<line x1="{x:.1f}" y1="{TOP + ph}" x2="{x:.1f}" '
                f'y2="{TOP + ph + (7 if major else 4)}" stroke="black"/>'
            )
            if major:
                out.append(
                    f'<text x="{x:.1f}" y="{TOP + ph + 24}" text-anchor="middle">'
                    f"{power_label(k)}</text>"
                )
    for k in range(y0, y1 + 1):
        for m in range(1, 10) if k < y1 else [1]:
            y = py(m * 10.0**k)
            major = m == 1
            out.append(
                f'<line x1="{LEFT}" y1="{y:.1f}" x2="{LEFT + pw}" y2="{y:.1f}" '
                f'stroke="{"#ccc" if major else "#eee"}"/>'
            )
            out.append(
                f'<line x1="{LEFT - (7 if major else 4)}" y1="{y:.1f}" x2="{LEFT}" '
                f'y2="{y:.1f}" stroke="black"/>'
            )
            if major:
                out.append(
                    f'<text x="{LEFT - 10}" y="{y + 5:.1f}" text-anchor="end">'
                    f"{power_label(k)}</text>"
                )
    out.append(
        f'<rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}" fill="none" stroke="black"/>'
    )
    out.append(
        f'<text x="{LEFT + pw / 2}" y="{HEIGHT - 20}" text-anchor="middle">'
        "wall time per image, end to end (s)</text>"
    )
    out.append(
        f'<text transform="translate(24 {TOP + ph / 2}) rotate(-90)" text-anchor="middle">'
        "relMSE against the 4096-spp reference (dimensionless)</text>"
    )

    # Dashed 1/t line through the geometric centre of the first backend's points.
    first = next(iter(series.values()))
    cx = sum(math.log10(s) for _, s, _ in first) / len(first)
    cy = sum(math.log10(e) for _, _, e in first) / len(first)
    lo = max(10.0**x0, 10.0 ** (cx + cy - y1))
    hi = min(10.0**x1, 10.0 ** (cx + cy - y0))
    out.append(
        f'<line x1="{px(lo):.1f}" y1="{py(10 ** (cx + cy) / lo):.1f}" x2="{px(hi):.1f}" '
        f'y2="{py(10 ** (cx + cy) / hi):.1f}" stroke="#555" stroke-width="1.5" '
        'stroke-dasharray="7 5"/>'
    )

    legend = []
    for i, (name, pts) in enumerate(series.items()):
        colour = COLOURS[i % len(COLOURS)]
        path = " ".join(f"{px(s):.1f},{py(e):.1f}" for _, s, e in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for spp, s, e in pts:
            out.append(f'<circle cx="{px(s):.1f}" cy="{py(e):.1f}" r="3.5" fill="{colour}"/>')
            if i == 0:
                out.append(
                    f'<text x="{px(s) - 5:.1f}" y="{py(e) + 14:.1f}" text-anchor="end" '
                    f'font-size="10" fill="#444">{spp}</text>'
                )
        secs, errs = [s for _, s, _ in pts], [e for _, _, e in pts]
        text = f"{name}: fitted slope {minus(slope(secs, errs))}"
        if len(pts) >= 5:  # without 1-4 spp, where start-up time is a large share
            text += f", {minus(slope(secs[3:], errs[3:]))} from {pts[3][0]} spp"
        legend.append((colour, text, ""))
    legend.append(("#555", "1/t (slope −1)", "7 5"))

    lx, ly = LEFT + pw - 335, TOP + 12
    out.append(
        f'<rect x="{lx - 10}" y="{ly - 8}" width="335" height="{22 * len(legend) + 28}" '
        'fill="white" stroke="#999"/>'
    )
    for j, (colour, text, dash) in enumerate(legend):
        y = ly + 8 + 22 * j
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(
            f'<line x1="{lx}" y1="{y}" x2="{lx + 30}" y2="{y}" stroke="{colour}" '
            f'stroke-width="2"{dash_attr}/>'
        )
        out.append(f'<text x="{lx + 38}" y="{y + 4}">{text}</text>')
    out.append(
        f'<text x="{lx}" y="{ly + 8 + 22 * len(legend)}" font-size="11" fill="#444">'
        "point labels: samples per pixel</text>"
    )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_convergence.py CSV SVG")
    csv_path, svg_path = sys.argv[1], sys.argv[2]
    series = read_rows(csv_path)
    text = svg(series, "bounce-trace, Cornell box 128×128: error against time")

    # Atomic write: a reader never sees a half-written chart.
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(svg_path)), suffix=".svg")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.chmod(tmp, 0o644)  # mkstemp creates 0600
    os.replace(tmp, svg_path)

    base_name, base = next(iter(series.items()))
    base_time = {spp: s for spp, s, _ in base}
    for name, pts in series.items():
        spp, secs, err = zip(*pts)
        print(
            f"{name}: slope log relMSE / log seconds = {slope(secs, err):.3f}, "
            f"/ log spp = {slope(spp, err):.3f}"
            + (f", over spp >= 8: {slope(secs[3:], err[3:]):.3f} / {slope(spp[3:], err[3:]):.3f}"
               if len(pts) >= 5 else "")
        )
        if name != base_name:
            ratios = [s / base_time[n] for n, s, _ in pts if n in base_time]
            print(
                f"  time {name}/{base_name} at equal spp: "
                + " ".join(f"{r:.2f}" for r in ratios)
            )


if __name__ == "__main__":
    main()
