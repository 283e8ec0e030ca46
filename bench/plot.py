#!/usr/bin/env python3
"""Speed-accuracy chart from bench_hertz's CSV: error against the reference vs
median time per solve, log-log, one marker per (method, regime). Drawn by
halfslip.plot (matplotlib; scripts/bench.sh runs it with Debian's python3).

usage: plot.py results.csv out.svg
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "halfslip"
import halfslip.plot as hp  # noqa: E402


def main(path, out):
    rows = [r for r in csv.DictReader(open(path)) if r["kind"] == "solve"]
    floor = 1e-17  # errors reported as 0 are drawn at this floor
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    series = []
    for i, m in enumerate(methods):
        for reg, style, mk in (("same-sign", "marker", "o"), ("opposite-sign", "hollow", "s")):
            pts = [(float(r["median_ns"]), max(float(r["max_abs_err_b"] or 0), floor)) for r in rows
                   if r["method"] == m and r["regime"] == reg]
            if pts:
                series.append({"x": [p[0] for p in pts], "y": [p[1] for p in pts], "style": style, "marker": mk,
                               "color": "C%d" % (i % 10), "label": "%s, %s" % (m, reg)})
    ax = hp.chart(series, title="Hertz solve: error vs time", xlabel="median time per solve [ns]",
                  ylabel="max |b - b_ref| / a (0 drawn at 1e-17)", logx=True, logy=True, legend="upper right",
                  size=(10, 5))
    ax.set_ylim(floor / 3, 1e-13)
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="x-small")
    hp.save(ax, out)
    print(f"chart written to {out}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
