#!/usr/bin/env python3
"""Charts of bench_methods (issue #5), drawn by halfslip.plot (matplotlib;
scripts/bench.sh runs it with Debian's python3):

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
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "halfslip"
import halfslip.plot as hp  # noqa: E402

# 20 distinct colours (tab20: the dark shades first, then the light ones)
COLORS = [matplotlib.colormaps["tab20"](i) for i in list(range(0, 20, 2)) + list(range(1, 20, 2))]


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
    labels = []
    for p in pts:
        if p[0] not in labels:
            labels.append(p[0])
    series = []
    for li, m in enumerate(labels):
        for g, mk in (("hertz", "o"), ("flat-rounded", "D")):
            sel = [p for p in pts if p[0] == m and (p[1] == g or (g == "flat-rounded" and p[1] != "hertz"))]
            if sel:
                series.append({"x": [p[2] for p in sel], "y": [max(p[3], FLOOR) for p in sel], "marker": mk,
                               "style": "hollow" if sel[0][5] else "marker", "color": COLORS[li % len(COLORS)],
                               "label": m if g == "hertz" or not any(p[0] == m and p[1] == "hertz" for p in pts)
                               else None})
    ax = hp.chart(series, title="Speed vs accuracy: Hertz (circles), flat punch b_f/a = 0.5 (diamonds)",
                  xlabel="median time per solve [ns]", ylabel=f"largest rel. error of d1, d2 (clipped at {FLOOR:g})",
                  logx=True, logy=True, legend="center left", size=(11, 6.2))
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize="x-small")
    for (m, g, t, e, fails, hollow, note) in pts:
        c = COLORS[labels.index(m) % len(COLORS)]
        y = max(e, FLOOR)
        if e < FLOOR:
            ax.annotate("↓", (t, y), textcoords="offset points", xytext=(-3, -14), color=c, fontsize=9)
        if note:
            ax.annotate(note, (t, y), textcoords="offset points", xytext=(-8, 7), color=c, fontsize=8)
        if fails:
            ax.annotate(f"{fails} fail", (t, y), textcoords="offset points", xytext=(6, 4), color=c, fontsize=8)
    ax.set_ylim(FLOOR / 10, TOP * 10)
    ax.text(0.0, -0.13, "↓: error below the axis floor; hollow: mpmath, nominal error", transform=ax.transAxes,
            fontsize=8)
    hp.save(ax, out)
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
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(2, 2, figsize=(12, 8.6), layout="constrained")
    for pi, (sweep, title, xl) in enumerate(PANELS):
        ax = axs[pi // 2][pi % 2]
        rs = [r for r in rows if r["sweep"] == sweep]
        series = []
        fails = []
        for mi, m in enumerate(methods):
            c = "C%d" % (mi % 10)
            for side in ((-1, 1) if sweep == "regime_boundary" else (0,)):
                pts = []
                for r in rs:
                    if r["method"] != m or r["error"] == "no-truth":
                        continue
                    v = float(r["param"])
                    if side and (v > 0) != (side > 0):
                        continue
                    e = TOP if r["error"] == "fail" else max(float(r["error"]), FLOOR)
                    pts.append((abs(v), e, r["error"] == "fail"))
                pts.sort()
                if pts:
                    series.append({"x": [p[0] for p in pts], "y": [p[1] for p in pts], "color": c, "marker": ".",
                                   "ls": "--" if side < 0 else "-", "label": m if pi == 0 and side >= 0 else None})
                    fails += [(p[0], p[1], c) for p in pts if p[2]]
        if not series:
            ax.set_visible(False)
            continue
        hp.chart(series, ax=ax, title=title, xlabel=xl, ylabel="rel. error of d1, d2", logx=True, logy=True,
                 legend="upper left" if pi == 0 else None)
        for x, y, c in fails:
            ax.plot([x], [y], "x", color=c, ms=7)
        ax.set_ylim(FLOOR / 3, TOP * 3)
    fig.text(0.01, 0.003, f"Truth: MPFR reference at 40 digits. Errors below {FLOOR:g} are drawn at {FLOOR:g}; "
             "x at the top: the solve failed; no point: the 40-digit reference failed too.", fontsize=8)
    hp.save(fig, out)
    print(f"chart written to {out}")


def main(methods_csv, stab_csv, reference_csv, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    speed_accuracy(methods_csv, reference_csv, os.path.join(out_dir, "speed_accuracy.svg"))
    stability(stab_csv, os.path.join(out_dir, "stability.svg"))


if __name__ == "__main__":
    main(*sys.argv[1:5])
