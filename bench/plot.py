#!/usr/bin/env python3
"""Speed-accuracy chart from bench_hertz's CSV: error against the reference vs
median time per solve, log-log, one marker per (method, regime). Standard
library only (writes SVG directly).

usage: plot.py results.csv out.svg
"""
import csv
import math
import sys

W, H = 760, 480
L, R, T, B = 80, 230, 40, 60  # margins
COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf"]


def main(path, out):
    rows = [r for r in csv.DictReader(open(path)) if r["kind"] == "solve"]
    floor = 1e-17  # errors reported as 0 are drawn at this floor
    pts = []
    for r in rows:
        t = float(r["median_ns"])
        e = max(float(r["max_abs_err_b"] or 0), floor)
        pts.append((r["method"], r["regime"], t, e))
    methods = sorted({p[0] for p in pts}, key=lambda m: [p[0] for p in pts].index(m))
    tmin = 10 ** math.floor(math.log10(min(p[2] for p in pts)))
    tmax = 10 ** math.ceil(math.log10(max(p[2] for p in pts)))
    emin, emax = 1e-17, 1e-13

    def X(t):
        return L + (math.log10(t) - math.log10(tmin)) / (math.log10(tmax) - math.log10(tmin)) * (W - L - R)

    def Y(e):
        return H - B - (math.log10(e) - math.log10(emin)) / (math.log10(emax) - math.log10(emin)) * (H - T - B)

    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{W/2 - 60}" y="22" font-size="15">Hertz solve: error vs time</text>']
    # axes and grid
    d = tmin
    while d <= tmax * 1.001:
        x = X(d)
        s.append(f'<line x1="{x:.1f}" y1="{T}" x2="{x:.1f}" y2="{H-B}" stroke="#ddd"/>')
        s.append(f'<text x="{x-14:.1f}" y="{H-B+18}">1e{int(round(math.log10(d)))}</text>')
        d *= 10
    e = emin
    while e <= emax * 1.001:
        y = Y(e)
        s.append(f'<line x1="{L}" y1="{y:.1f}" x2="{W-R}" y2="{y:.1f}" stroke="#ddd"/>')
        s.append(f'<text x="{L-45}" y="{y+4:.1f}">1e{int(round(math.log10(e)))}</text>')
        e *= 10
    s.append(f'<rect x="{L}" y="{T}" width="{W-L-R}" height="{H-T-B}" fill="none" stroke="black"/>')
    s.append(f'<text x="{L + (W-L-R)/2 - 90}" y="{H-15}">median time per solve [ns]</text>')
    s.append(f'<text transform="translate(20,{T + (H-T-B)/2 + 80}) rotate(-90)">max |b - b_ref| / a (0 drawn at 1e-17)</text>')
    for i, m in enumerate(methods):
        c = COLORS[i % len(COLORS)]
        for (mm, reg, t, err) in pts:
            if mm != m:
                continue
            x, y = X(t), Y(err)
            if reg == "same-sign":
                s.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="6" fill="{c}"/>')
            else:
                s.append(f'<rect x="{x-6:.1f}" y="{y-6:.1f}" width="12" height="12" fill="none" stroke="{c}" stroke-width="2"/>')
        ly = T + 20 + 22 * i
        s.append(f'<circle cx="{W-R+20}" cy="{ly}" r="6" fill="{c}"/><text x="{W-R+32}" y="{ly+4}">{m}</text>')
    ly = T + 20 + 22 * len(methods) + 10
    s.append(f'<circle cx="{W-R+20}" cy="{ly}" r="6" fill="gray"/><text x="{W-R+32}" y="{ly+4}">same-sign</text>')
    s.append(f'<rect x="{W-R+14}" y="{ly+16}" width="12" height="12" fill="none" stroke="gray" stroke-width="2"/>'
             f'<text x="{W-R+32}" y="{ly+26}">opposite-sign</text>')
    s.append("</svg>")
    open(out, "w").write("\n".join(s) + "\n")
    print(f"chart written to {out}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
