#!/usr/bin/env python3
"""Stability charts of the other geometries (issue 13), from bench_stability's CSV, drawn
with halfslip.plot (matplotlib; scripts/bench.sh runs it with Debian's python3):

  stability_flat.svg     flat punch with rounded corners: sigma/fp0 to 1e4, b_f/a -> 0, b_f/a -> 1
                         at sigma/fp0 = 1 and at 1000
  stability_power.svg    power law: sigma/fp0 to 1e4 (n = 4), the exponent to 999.9 at sigma/fp0 = 1
                         and at 1000
  stability_samples.svg  sampled pressures: the sample count to 10^6 on four scenes

One curve per method (relative error of d1, d2 against the trusted value); a failure
(status) is an x at the top of its panel, a timeout or a point skipped after two
timeouts a hollow square there; the dashed line of a method's colour is AUTO's own
error estimate (auto 0). Also writes stability_geometries_summary.md next to the CSV.

usage: plot_stability.py stability_geometries.csv out_dir
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "halfslip"
import halfslip.plot as hp  # noqa: E402

FLOOR, TOP = 1e-19, 10.0
METHODS = ["default", "quadrature 1e-8", "asymptotic", "auto 0", "auto 1e-10", "reference"]
COLORS = {m: "C%d" % i for i, m in enumerate(METHODS)}
ZERO_AT = 1e-14  # where b_f/a = 0 is drawn on the log axis

CHARTS = {
    "flat": ("stability_flat.svg", "Flat punch with rounded corners, Q/fP = 0.3", [
        ("sigma", "b_f/a = 0.5: sigma/fp0 -> 1e4", "sigma/fp0"),
        ("bf_to_0", "b_f/a -> 0, sigma/fp0 = 1", "b_f/a"),
        ("bf_to_1", "b_f/a -> 1, sigma/fp0 = 1", "1 - b_f/a"),
        ("bf_to_1_sigma1000", "b_f/a -> 1, sigma/fp0 = 1000 (truth: sliding point)", "1 - b_f/a"),
    ]),
    "power": ("stability_power.svg", "Power law g = A|x|^n, Q/fP = 0.3", [
        ("sigma", "n = 4: sigma/fp0 -> 1e4", "sigma/fp0"),
        ("exponent", "exponent n, sigma/fp0 = 1", "n"),
        ("exponent_sigma1000", "exponent n, sigma/fp0 = 1000 (truth: sliding point)", "n"),
    ]),
    "samples": ("stability_samples.svg", "Sampled pressures: n + 1 uniform samples", [
        ("hertz_q0.3_s1", "Hertz samples, Q/fP = 0.3, sigma/fp0 = 1", "n"),
        ("hertz_q0.3_s100", "Hertz samples, Q/fP = 0.3, sigma/fp0 = 100 (tiny stick)", "n"),
        ("hertz_near_sliding", "Hertz samples, 1 - Q/fP = 1e-6, sigma = 0", "n"),
        ("flat0.5_q0.3_s1", "flat punch b_f/a = 0.5 samples, Q/fP = 0.3, sigma/fp0 = 1\n"
         "(error includes the sampling error)", "n"),
    ]),
}


def fnum(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return math.nan


def claim_broken(r):
    """The result's claim (estimate for resolved zones, zone_resolution for unresolved ones)
    exceeded beyond twice the truth's own uncertainty (as bench_stability counts it)."""
    if r["status"] != "ok" or r["truth"] in ("none", "samples-flat") or not r["error"]:
        return False
    est, res, tu = fnum(r["estimate"]), fnum(r["resolution"]), abs(fnum(r["truth_unc"]) or 0)
    if math.isnan(tu):
        tu = 0.0
    for d, t in ((fnum(r["d1"]), fnum(r["truth_d1"])), (fnum(r["d2"]), fnum(r["truth_d2"]))):
        ae = abs(d - t)
        if d > res:
            if t > 0 and ae / t > est and ae / t > 2 * tu:
                return True
        elif ae > res and ae > 2 * tu * t:
            return True
    return False


def xval(sweep, r):
    v = fnum(r["param"])
    return ZERO_AT if (sweep == "bf_to_0" and v == 0) else v


def draw(rows, chart, out):
    import matplotlib.pyplot as plt
    fname, title, panels = CHARTS[chart]
    ncol = 2
    nrow = (len(panels) + 1) // 2
    fig, axs = plt.subplots(nrow, ncol, figsize=(12, 4.3 * nrow), layout="constrained", squeeze=False)
    for pi, (sweep, ptitle, xl) in enumerate(panels):
        ax = axs[pi // ncol][pi % ncol]
        rs = [r for r in rows if r["chart"] == chart and r["sweep"] == sweep]
        series, fails, hangs, notruth = [], [], [], []
        for m in METHODS:
            pts = sorted((xval(sweep, r), r) for r in rs if r["method"] == m)
            if not pts:
                continue
            ok = [(x, max(fnum(r["error"]), FLOOR)) for x, r in pts if r["status"] == "ok" and r["error"]]
            if ok:
                series.append({"x": [p[0] for p in ok], "y": [p[1] for p in ok], "color": COLORS[m], "marker": ".",
                               "label": m if pi == 0 else None})
            fails += [(x, COLORS[m]) for x, r in pts if r["status"] not in ("ok", "timeout", "skipped")]
            hangs += [(x, COLORS[m]) for x, r in pts if r["status"] in ("timeout", "skipped")]
            notruth += [x for x, r in pts if r["status"] == "ok" and r["truth"] == "none"]
            if m == "auto 0":
                est = [(x, max(fnum(r["estimate"]), FLOOR)) for x, r in pts
                       if r["status"] == "ok" and not math.isnan(fnum(r["estimate"]))]
                if est:
                    series.append({"x": [p[0] for p in est], "y": [p[1] for p in est], "color": COLORS[m],
                                   "ls": "--", "label": "auto 0: its estimate" if pi == 0 else None})
        # the truth's own uncertainty where it is above the floor
        tu = sorted({(xval(sweep, r), abs(fnum(r["truth_unc"]))) for r in rs
                     if r["method"] == "default" and not math.isnan(fnum(r["truth_unc"]))})
        if tu and max(t for _, t in tu) > FLOOR:
            series.append({"x": [p[0] for p in tu], "y": [max(p[1], FLOOR) for p in tu], "color": "0.6",
                           "ls": ":", "label": "truth's uncertainty" if pi == 0 else None})
        hp.chart(series, ax=ax, title=ptitle, xlabel=xl, ylabel="rel. error of d1, d2", logx=True, logy=True,
                 legend=None)
        for x, c in fails:
            ax.plot([x], [TOP], "x", color=c, ms=8)
        for x, c in hangs:
            ax.plot([x], [TOP * 2.5], "s", color=c, mfc="none", ms=6)
        for x in sorted(set(notruth)):  # answered, but no trusted value to judge it by
            ax.plot([x], [FLOOR * 30], "o", color="0.5", mfc="none", ms=7)
            ax.annotate("no truth", (x, FLOOR * 30), textcoords="offset points", xytext=(5, -3), fontsize=7,
                        color="0.4")
        ax.set_ylim(FLOOR / 3, TOP * 8)
        if sweep == "bf_to_0":
            ax.annotate("b_f/a = 0", (ZERO_AT, FLOOR), textcoords="offset points", xytext=(2, 6), fontsize=8)
        # where the truth changes from the reference to the sliding point
        lim = [xval(sweep, r) for r in rs if r["truth"] == "limit" and r["method"] == "default"]
        ref = [xval(sweep, r) for r in rs if r["truth"] == "reference" and r["method"] == "default"]
        if lim and ref:
            ax.axvline(min(lim), color="0.7", lw=0.8)
            ax.annotate("truth: reference | sliding point", (min(lim), FLOOR * 3), fontsize=7, ha="center",
                        color="0.4")
    for k in range(len(panels), nrow * ncol):
        axs[k // ncol][k % ncol].set_visible(False)
    axs[0][0].legend(loc="best", fontsize="x-small", ncol=2)
    fig.suptitle(title)
    fig.text(0.01, 0.002, f"Errors below {FLOOR:g} are drawn at {FLOOR:g}. x at the top: the solve returned an "
             "error status; hollow square above it: timeout (or skipped after two); grey circle: answered, no trusted "
             "value (the reference exceeded its budget).\nTruth: MPFR reference at 20 "
             "digits, the sliding stick point, or the Hertz solution (docs/benchmarks.md, \"Stability of the "
             "other geometries\").", fontsize=7)
    hp.save(fig, os.path.join(out, fname))
    print(f"chart written to {os.path.join(out, fname)}")


def summary(rows, path):
    with open(path, "w") as md:
        md.write("| chart | sweep | method | points | ok | error status | timeout / skipped | largest error "
                 "(ok) | failed at (status, timeout) | claim exceeded | ok without truth |\n|---|---|---|---|---|---|---|---|---|---|---|\n")
        for chart, (_, _, panels) in CHARTS.items():
            for sweep, _, _ in panels:
                for m in METHODS:
                    rs = [r for r in rows if r["chart"] == chart and r["sweep"] == sweep and r["method"] == m]
                    if not rs:
                        continue
                    ok = [r for r in rs if r["status"] == "ok"]
                    errs = [fnum(r["error"]) for r in ok if r["error"]]
                    bad = [r for r in rs if r["status"] not in ("ok", "timeout", "skipped")]
                    hang = [r for r in rs if r["status"] in ("timeout", "skipped")]
                    first = sorted(fnum(r["param"]) for r in bad + hang)
                    broken = [r for r in rs if claim_broken(r)]
                    md.write(f"| {chart} | {sweep} | {m} | {len(rs)} | {len(ok)} | {len(bad)} | {len(hang)} | "
                             f"{max(errs):.2g} | " if errs else
                             f"| {chart} | {sweep} | {m} | {len(rs)} | {len(ok)} | {len(bad)} | {len(hang)} | - | ")
                    md.write((", ".join(f"{v:.3g}" for v in first) + " | ") if first else "- | ")
                    md.write(", ".join(f"{r['param']} ({fnum(r['error']):.2g} > {r['estimate']})" for r in broken)
                             or "0")
                    md.write(" | " + (", ".join(f"{fnum(r['param']):.3g}" for r in ok if r["truth"] == "none") or "-")
                             + " |\n")
        checks = [r for r in rows if r["sweep"] == "truth-check"]
        if checks:
            md.write("\nSliding point against the reference where both exist (relative difference of d1, d2; "
                     "the stick width bounds it):\n\n")
            for r in checks:
                md.write(f"- {r['chart']}, sigma/fp0 = {fnum(r['param']):.4g}: {r['error']}\n")
    print(f"summary written to {path}")


def main(csv_path, out_dir):
    rows = list(csv.DictReader(open(csv_path)))
    os.makedirs(out_dir, exist_ok=True)
    for chart in CHARTS:
        draw(rows, chart, out_dir)
    summary(rows, os.path.join(os.path.dirname(csv_path), "stability_geometries_summary.md"))


if __name__ == "__main__":
    main(*sys.argv[1:3])
