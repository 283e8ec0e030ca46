#!/usr/bin/env python3
"""Charts of bench_methods (issue #5), standard library only (SVG by hand;
matplotlib is not installed on the project machine).

  speed_accuracy.svg  error vs median time per solve, log-log, one marker per
                      method and geometry: time = median over the scenes of the
                      per-scene medians, error = largest over the scenes.
                      mpmath (from reference.csv, if present) is drawn hollow at
                      its nominal error 10^-digits (not measured).
  stability.svg       one panel per failure region: error vs the approach
                      parameter, one curve per double method.

usage: plot_methods.py methods.csv stability.csv reference.csv out_dir
"""
import csv
import math
import os
import statistics
import sys

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#e377c2",
          "#7f7f7f", "#bcbd22", "#393b79", "#637939", "#843c39", "#7b4173", "#3182bd", "#31a354"]


class Axes:
    """log-log axes in a box (x0, y0, w, h) of an SVG list."""

    def __init__(self, s, box, xr, yr, title, xlabel, ylabel):
        self.s, (self.x0, self.y0, self.w, self.h) = s, box
        self.lx = (math.log10(xr[0]), math.log10(xr[1]))
        self.ly = (math.log10(yr[0]), math.log10(yr[1]))
        x0, y0, w, h = box
        s.append(f'<text x="{x0 + 4}" y="{y0 - 8}" font-size="13">{title}</text>')
        step_x = max(1, round((self.lx[1] - self.lx[0]) / 8))
        step_y = max(1, round((self.ly[1] - self.ly[0]) / 8))
        for k in range(math.ceil(self.lx[0]), math.floor(self.lx[1]) + 1):
            if k % step_x:
                continue
            x = self.X(10.0 ** k)
            s.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y0 + h}" stroke="#ddd"/>')
            s.append(f'<text x="{x - 12:.1f}" y="{y0 + h + 15}" font-size="10">1e{k}</text>')
        for k in range(math.ceil(self.ly[0]), math.floor(self.ly[1]) + 1):
            if k % step_y:
                continue
            y = self.Y(10.0 ** k)
            s.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x0 + w}" y2="{y:.1f}" stroke="#ddd"/>')
            s.append(f'<text x="{x0 - 36}" y="{y + 4:.1f}" font-size="10">1e{k}</text>')
        s.append(f'<rect x="{x0}" y="{y0}" width="{w}" height="{h}" fill="none" stroke="black"/>')
        s.append(f'<text x="{x0 + w / 2 - 4 * len(xlabel) / 1.6:.0f}" y="{y0 + h + 32}" font-size="11">{xlabel}</text>')
        s.append(f'<text transform="translate({x0 - 44},{y0 + h / 2 + 3 * len(ylabel)}) rotate(-90)" '
                 f'font-size="11">{ylabel}</text>')

    def X(self, v):
        return self.x0 + (math.log10(v) - self.lx[0]) / (self.lx[1] - self.lx[0]) * self.w

    def Y(self, v):
        v = min(max(v, 10 ** self.ly[0]), 10 ** self.ly[1])
        return self.y0 + self.h - (math.log10(v) - self.ly[0]) / (self.ly[1] - self.ly[0]) * self.h


def marker(s, shape, x, y, c, hollow=False):
    fill = "none" if hollow else c
    if shape == "circle":
        s.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="5" fill="{fill}" stroke="{c}" stroke-width="1.5"/>')
    elif shape == "square":
        s.append(f'<rect x="{x - 5:.1f}" y="{y - 5:.1f}" width="10" height="10" fill="{fill}" stroke="{c}" '
                 f'stroke-width="1.5"/>')
    else:  # diamond
        s.append(f'<path d="M{x:.1f},{y - 6:.1f} L{x + 6:.1f},{y:.1f} L{x:.1f},{y + 6:.1f} L{x - 6:.1f},{y:.1f} Z" '
                 f'fill="{fill}" stroke="{c}" stroke-width="1.5"/>')


def speed_accuracy(methods_csv, reference_csv, out):
    rows = list(csv.DictReader(open(methods_csv)))
    FLOOR, TOP = 1e-40, 10.0
    pts = []  # (label, geometry, time_ns, error, failures, hollow)
    keys = []
    for r in rows:
        k = (r["method"], r["geometry"])
        if k not in keys:
            keys.append(k)
    for m, g in keys:
        rs = [r for r in rows if (r["method"], r["geometry"]) == (m, g)]
        t = statistics.median(float(r["median_ns"]) for r in rs)
        errs = [float(r["error"]) for r in rs if r["error"] != "fail"]
        fails = len(rs) - len(errs)
        pts.append((m, g, t, max(errs) if errs else TOP, fails, False, ""))
    # the same summary as a Markdown table (docs/benchmarks.md quotes it)
    with open(os.path.join(os.path.dirname(methods_csv), "methods_summary.md"), "w") as md:
        md.write("| method | geometry | median time / solve | max error (d1, d2) | failures |\n|---|---|---|---|---|\n")
        for m, g, t, e, fails, _, _ in pts:
            tt = f"{t:.3g} ns" if t < 1e3 else (f"{t / 1e3:.3g} µs" if t < 1e6 else f"{t / 1e6:.3g} ms")
            md.write(f"| {m} | {g} | {tt} | {e:.2g} | {fails or ''} |\n")
    if reference_csv and os.path.exists(reference_csv):
        for r in csv.DictReader(open(reference_csv)):
            if r["method"].startswith("mpmath"):
                d = int(r["digits"])
                pts.append((f'{r["method"]} (nominal)', "hertz", float(r["median_ms"]) * 1e6,
                            10.0 ** -d, 0, True, f"{d}d"))
    W, H = 1000, 620
    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>']
    tmin = 10 ** math.floor(math.log10(min(p[2] for p in pts)))
    tmax = 10 ** math.ceil(math.log10(max(p[2] for p in pts)))
    ax = Axes(s, (70, 40, 560, 500), (tmin, tmax), (FLOOR, TOP),
              "Speed vs accuracy: Hertz (circles), flat punch b_f/a = 0.5 (diamonds)",
              "median time per solve [ns]", f"largest rel. error of d1, d2 (clipped at {FLOOR:g})")
    labels = []
    for p in pts:
        if p[0] not in labels:
            labels.append(p[0])
    for (m, g, t, e, fails, hollow, note) in pts:
        c = COLORS[labels.index(m) % len(COLORS)]
        x, y = ax.X(t), ax.Y(max(e, FLOOR))
        marker(s, "circle" if g == "hertz" else "diamond", x, y, c, hollow)
        if e < FLOOR:
            s.append(f'<text x="{x - 4:.1f}" y="{y + 16:.1f}" fill="{c}" font-size="11">&#8595;</text>')
        if note:
            s.append(f'<text x="{x - 8:.1f}" y="{y - 9:.1f}" fill="{c}" font-size="10">{note}</text>')
        if fails:
            s.append(f'<text x="{x + 7:.1f}" y="{y - 6:.1f}" fill="{c}" font-size="10">{fails} fail</text>')
    for i, m in enumerate(labels):
        c = COLORS[i % len(COLORS)]
        ly = 50 + 19 * i
        hollow = "nominal" in m
        marker(s, "circle", 660, ly, c, hollow)
        s.append(f'<text x="672" y="{ly + 4}" font-size="11">{m}</text>')
    s.append(f'<text x="660" y="{50 + 19 * len(labels) + 14}" font-size="10">&#8595;: error below the axis floor; '
             f'hollow: mpmath, nominal error</text>')
    s.append("</svg>")
    open(out, "w").write("\n".join(s) + "\n")
    print(f"chart written to {out}")


PANELS = [
    ("small_zone", "d/a -> 0 (sigma = 0)", "Q/fP"),
    ("near_sliding", "Q/fP -> 1 (sigma = 0)", "1 - Q/fP"),
    ("regime_boundary", "regime boundary, Q/fP = 0.5 (solid: opp. side, dashed: same)",
     "|sigma/sigma_b - 1|"),
    ("tiny_stick", "k -> 1: tiny stick zone, Q/fP = 0.3", "sigma/fp0"),
]


def stability(stab_csv, out):
    rows = list(csv.DictReader(open(stab_csv)))
    FLOOR, TOP = 1e-18, 10.0
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    W, H = 1060, 760
    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>']
    for pi, (sweep, title, xl) in enumerate(PANELS):
        rs = [r for r in rows if r["sweep"] == sweep]
        if not rs:
            continue
        xs = [abs(float(r["param"])) for r in rs]
        xr = (10 ** math.floor(math.log10(min(xs))), 10 ** math.ceil(math.log10(max(xs))))
        box = (70 + 420 * (pi % 2), 50 + 350 * (pi // 2), 360, 260)
        ax = Axes(s, box, xr, (FLOOR, TOP), title, xl, "rel. error of d1, d2")
        for mi, m in enumerate(methods):
            c = COLORS[mi % len(COLORS)]
            for side in ((-1, 1) if sweep == "regime_boundary" else (0,)):
                pts = []
                for r in rs:
                    if r["method"] != m or r["error"] == "no-truth":
                        continue
                    v = float(r["param"])
                    if side and (v > 0) != (side > 0):
                        continue
                    e = TOP if r["error"] == "fail" else max(float(r["error"]), FLOOR)
                    pts.append((ax.X(abs(v)), ax.Y(e), r["error"] == "fail"))
                pts.sort()
                if pts:
                    dash = ' stroke-dasharray="5,3"' if side < 0 else ""
                    path = " ".join(f"{x:.1f},{y:.1f}" for x, y, _ in pts)
                    s.append(f'<polyline points="{path}" fill="none" stroke="{c}" stroke-width="1.6"{dash}/>')
                    for x, y, failed in pts:
                        if failed:
                            s.append(f'<text x="{x - 4:.1f}" y="{y + 4:.1f}" fill="{c}" font-size="11">x</text>')
                        else:
                            s.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="2.5" fill="{c}"/>')
    for mi, m in enumerate(methods):
        c = COLORS[mi % len(COLORS)]
        x = 70 + 230 * mi
        s.append(f'<line x1="{x}" y1="20" x2="{x + 24}" y2="20" stroke="{c}" stroke-width="2"/>'
                 f'<text x="{x + 30}" y="24">{m}</text>')
    s.append(f'<text x="70" y="{H - 8}" font-size="10">Truth: MPFR reference at 40 digits. '
             f'Errors below {FLOOR:g} are drawn at {FLOOR:g}; x at the top: the solve failed; '
             f'no point: the 40-digit reference failed too.</text>')
    s.append("</svg>")
    open(out, "w").write("\n".join(s) + "\n")
    print(f"chart written to {out}")


def main(methods_csv, stab_csv, reference_csv, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    speed_accuracy(methods_csv, reference_csv, os.path.join(out_dir, "speed_accuracy.svg"))
    stability(stab_csv, os.path.join(out_dir, "stability.svg"))


if __name__ == "__main__":
    main(*sys.argv[1:5])
