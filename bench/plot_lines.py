#!/usr/bin/env python3
"""Line chart of CSV columns against the first, drawn by halfslip.plot
(matplotlib). Columns named *shear* are blue, *bulk* red, *asymptotic* dashed.
The output format follows the file name (.svg, .png).

usage: plot_lines.py data.csv out.svg "title" "x label" "y label" [col ...]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "halfslip"
import halfslip.plot as hp  # noqa: E402


def main(path, outs, title, xl, yl, cols):
    rows = list(csv.DictReader(open(path)))
    xk = list(rows[0].keys())[0]
    cols = cols or [k for k in rows[0].keys() if k != xk]
    xs = [float(r[xk]) for r in rows]
    series = []
    for i, c in enumerate(cols):
        color = "C0" if "shear" in c else "C3" if "bulk" in c else "C%d" % (i % 10)
        series.append({"x": xs, "y": [float(r[c]) for r in rows], "label": c, "color": color,
                       "ls": "--" if "asymptotic" in c else "-"})
    for out in outs.split(","):
        ax = hp.chart(series, title=title, xlabel=xl, ylabel=yl)
        ax.axhline(0, color="k", lw=0.6)
        hp.save(ax, out)
        print(f"chart written to {out}")


if __name__ == "__main__":
    a = sys.argv
    main(a[1], a[2], a[3], a[4], a[5], a[6:])
