#!/usr/bin/env python3
"""Line chart (SVG, standard library only) of CSV columns against the first.

usage: plot_lines.py data.csv out.svg "title" "x label" "y label" [col ...]
"""
import csv
import sys

W, H, L, R, T, B = 760, 440, 110, 220, 40, 60
COLORS = ["#1f77b4", "#1f77b4", "#d62728", "#d62728", "#2ca02c", "#9467bd"]


def main(path, out, title, xl, yl, cols):
    rows = list(csv.DictReader(open(path)))
    xk = list(rows[0].keys())[0]
    cols = cols or [k for k in rows[0].keys() if k != xk]
    xs = [float(r[xk]) for r in rows]
    ys = {c: [float(r[c]) for r in rows] for c in cols}
    x0, x1 = min(xs), max(xs)
    y0 = min(min(v) for v in ys.values())
    y1 = max(max(v) for v in ys.values())
    pad = 0.05 * (y1 - y0 or 1)
    y0, y1 = y0 - pad, y1 + pad

    def X(x):
        return L + (x - x0) / (x1 - x0) * (W - L - R)

    def Y(y):
        return H - B - (y - y0) / (y1 - y0) * (H - T - B)

    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>', f'<text x="{L}" y="24" font-size="15">{title}</text>',
         f'<rect x="{L}" y="{T}" width="{W-L-R}" height="{H-T-B}" fill="none" stroke="black"/>']
    for i in range(6):
        xv = x0 + (x1 - x0) * i / 5
        yv = y0 + (y1 - y0) * i / 5
        s.append(f'<line x1="{X(xv):.1f}" y1="{T}" x2="{X(xv):.1f}" y2="{H-B}" stroke="#ddd"/>')
        s.append(f'<text x="{X(xv)-14:.1f}" y="{H-B+18}">{xv:.3g}</text>')
        s.append(f'<line x1="{L}" y1="{Y(yv):.1f}" x2="{W-R}" y2="{Y(yv):.1f}" stroke="#ddd"/>')
        s.append(f'<text x="{L-62}" y="{Y(yv)+4:.1f}">{yv:.3g}</text>')
    if y0 < 0 < y1:
        s.append(f'<line x1="{L}" y1="{Y(0):.1f}" x2="{W-R}" y2="{Y(0):.1f}" stroke="black" stroke-width="0.6"/>')
    s.append(f'<text x="{L + (W-L-R)/2 - 40}" y="{H-15}">{xl}</text>')
    s.append(f'<text transform="translate(22,{T + (H-T-B)/2 + 70}) rotate(-90)">{yl}</text>')
    for i, c in enumerate(cols):
        pts = " ".join(f"{X(x):.1f},{Y(y):.1f}" for x, y in zip(xs, ys[c]))
        dash = ' stroke-dasharray="6,4"' if "asymptotic" in c else ""
        col = "#1f77b4" if "shear" in c else "#d62728" if "bulk" in c else COLORS[i % len(COLORS)]
        s.append(f'<polyline points="{pts}" fill="none" stroke="{col}" stroke-width="2"{dash}/>')
        ly = T + 20 + 22 * i
        s.append(f'<line x1="{W-R+10}" y1="{ly}" x2="{W-R+40}" y2="{ly}" stroke="{col}" stroke-width="2"{dash}/>')
        s.append(f'<text x="{W-R+46}" y="{ly+4}">{c}</text>')
    s.append("</svg>")
    open(out, "w").write("\n".join(s) + "\n")
    print(f"chart written to {out}")


if __name__ == "__main__":
    a = sys.argv
    main(a[1], a[2], a[3], a[4], a[5], a[6:])
