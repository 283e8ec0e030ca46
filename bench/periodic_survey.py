#!/usr/bin/env python3
"""Periodic loadings through `halfslip history` (issue 14): what completes, what stops and why, the
cost, and (with --bem) the energy per cycle of each completed run against the independent BEM
(bench/periodic_bem.cpp at N = 400 and 800). The loadings are bench_history's 162 periodic cases
(bench/bench_history.cpp, periodic_cases(): Q_a, Q_m, sigma_m, sigma_a, phase), 3 cycles, default rtol.

    cmake -S . -B build -DHALFSLIP_BUILD_BENCH=ON && cmake --build build --target halfslip_cli periodic_bem -j2
    python3 bench/periodic_survey.py build OUT_PREFIX [--geometry hertz|flat-rounded] [--patches error|merge]
                                     [--cases 0,5,9] [--bem]

Writes OUT_PREFIX.csv (one row per loading) and OUT_PREFIX.md (the summary). Not part of the tests:
the 162 Hertz loadings take about 90 s of CPU; --bem adds 5 to 15 s per completed run. E1, E2 are the
zones' energies per cycle with each interior slip zone's (the static solves' patches, Ep) counted on its
side of the stick zone's centre, as the BEM counts it.
"""
import csv
import json
import os
import re
import subprocess
import sys
import time


def periodic_cases():
    r = []
    for qa in (0.1, 0.3, 0.6):
        for qm in (0.0, 0.15):
            for sm in (0.0, 0.5, 1.5):
                for sa in (0.0, 0.3, 1.0):
                    for ph in (0.0, 45.0, 90.0, 180.0):
                        if not (sa == 0 and ph != 0):
                            r.append((qa, qm, sm, sa, ph))
    return r


def kind(msg):
    """The reason a run stopped, from the library's own message (hs_history_last_error); where the
    march failed after the static solves had stopped (further on, as a rule), the static solves'
    reason, which the message gives after "the static solves had stopped"."""
    cut = msg.find("the static solves had stopped")
    if cut >= 0:
        msg = msg[cut:]
    if "fold" in msg:
        return "a fold the static solves cannot follow"
    if "interior slip zone" in msg:
        return "interior slip zone"
    if "slip back" in msg:
        return "edge zone slips back"
    if "whole stick zone" in msg:
        return "whole stick zone at the limit"
    if cut >= 0:  # (the static solves' own words, after the vertex)
        return "other: " + re.sub(r"\s+", " ", msg.split(": ", 1)[-1])[:90]
    return "other: " + re.sub(r"\s+", " ", msg)[-80:]


def cpu_run(cmd):
    t0 = os.times()
    p = subprocess.run(cmd, capture_output=True, text=True)
    t1 = os.times()
    return p, (t1.children_user - t0.children_user)


def main():
    a = sys.argv[1:]
    if len(a) < 2:
        sys.exit(__doc__)
    build, out = a[0], a[1]
    geom = a[a.index("--geometry") + 1] if "--geometry" in a else "hertz"
    patches = a[a.index("--patches") + 1] if "--patches" in a else "error"
    cases = periodic_cases()
    idx = [int(x) for x in a[a.index("--cases") + 1].split(",")] if "--cases" in a else range(len(cases))
    bem = "--bem" in a
    cli = os.path.join(build, "halfslip")
    bem_exe = os.path.join(build, "bench", "periodic_bem")
    rows = []
    for i in idx:
        qa, qm, sm, sa, ph = cases[i]
        cyc = "%g,%g,%g,%g,%g" % (qm, qa, sm, sa, ph)
        p, cpu = cpu_run([cli, "history", "--cycle", cyc, "--cycles", "3", "--json", "--geometry", geom,
                          "--interior-patches", patches])
        row = dict(case=i, qa=qa, qm=qm, sm=sm, sa=sa, phase=ph, geometry=geom, patches=patches, cpu_s=round(cpu, 3))
        if p.returncode == 0:
            d = json.loads(p.stdout)
            vs = d["vertices"]
            # (interior slip zones taken by the static solves: their energy, energy_per_cycle_patch, is
            # counted with the zone on whose side of the stick zone's centre each lies, as the BEM
            # counts it)
            E1, E2, Ep = d["energy_per_cycle1"], d["energy_per_cycle2"], d.get("energy_per_cycle_patch", 0.0)
            last = max(v["cycle"] for v in vs)
            for v in vs:
                if v["cycle"] == last and v.get("energy_patch"):
                    right = v["patch_dir"] and v["patch_l"] + v["patch_r"] > v["b1"] - v["b2"]
                    if right:
                        E1 += v["energy_patch"]
                    else:
                        E2 += v["energy_patch"]
            row.update(outcome="complete", method=d.get("method"), E1=E1, E2=E2, Ep=Ep,
                       estimate=max(v.get("error_estimate") or 0 for v in vs),
                       merges=vs[-1].get("interior_merges", 0))
            if bem:
                for N in (400, 800):
                    b = subprocess.run([bem_exe, "%g" % qm, "%g" % qa, "%g" % sm, "%g" % sa, "%g" % ph, "3", str(N),
                                        "flat" if geom != "hertz" else "hertz"], capture_output=True, text=True)
                    m = re.search(r"cycle 3: E1 (\S+) E2 (\S+)", b.stdout)
                    if m:
                        row["bem%d_E1" % N], row["bem%d_E2" % N] = float(m.group(1)), float(m.group(2))
                if "bem800_E1" in row and "bem400_E1" in row:
                    s = max(abs(row["bem800_E1"]), abs(row["bem800_E2"]))
                    row["err_vs_bem800"] = max(abs(row["E1"] - row["bem800_E1"]), abs(row["E2"] - row["bem800_E2"])) / s
                    row["bem_spread"] = max(abs(row["bem400_E1"] - row["bem800_E1"]),
                                            abs(row["bem400_E2"] - row["bem800_E2"])) / s
        else:
            row.update(outcome="stopped", reason=kind(p.stderr))
        rows.append(row)
        print(i, row.get("outcome"), row.get("reason", row.get("method", "")), row["cpu_s"], flush=True)
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    done = [r for r in rows if r["outcome"] == "complete"]
    stopped = [r for r in rows if r["outcome"] == "stopped"]
    reasons = {}
    for r in stopped:
        reasons[r["reason"]] = reasons.get(r["reason"], 0) + 1
    methods = {}
    for r in done:
        methods[r["method"]] = methods.get(r["method"], 0) + 1

    def q(v, f):
        v = sorted(v)
        return v[min(len(v) - 1, int(f * len(v)))] if v else float("nan")

    lines = ["# Periodic loadings, %s, --interior-patches %s (%s)" % (geom, patches, time.strftime("%Y-%m-%d")), "",
             "`python3 bench/periodic_survey.py %s`" % " ".join(a), "",
             "- %d loadings: %d complete (%s), %d stopped" % (
                 len(rows), len(done), ", ".join("%d %s" % (n, m) for m, n in sorted(methods.items())), len(stopped))]
    for k, n in sorted(reasons.items(), key=lambda t: -t[1]):
        lines.append("  - %d: %s" % (n, k))
    withp = [r for r in done if r.get("Ep")]
    if withp:
        lines.append("- %d complete with an interior slip zone taken by the static solves (cases %s)" % (
            len(withp), ", ".join(str(r["case"]) for r in withp)))
    lines.append("- CPU s: complete median %.2f, 90th percentile %.2f, max %.2f; stopped median %.2f, max %.2f" % (
        q([r["cpu_s"] for r in done], .5), q([r["cpu_s"] for r in done], .9), max([r["cpu_s"] for r in done] or [0]),
        q([r["cpu_s"] for r in stopped], .5), max([r["cpu_s"] for r in stopped] or [0])))
    cmp = [r for r in done if "err_vs_bem800" in r]
    if cmp:
        e = [r["err_vs_bem800"] for r in cmp]
        sp = [r["bem_spread"] for r in cmp]
        lines.append("- against the BEM (energy per cycle, last cycle, over max(E1, E2)), %d runs: |run - BEM800| median "
                     "%.2g, 90th percentile %.2g, worst %.2g; |BEM400 - BEM800| median %.2g, worst %.2g" % (
                         len(cmp), q(e, .5), q(e, .9), max(e), q(sp, .5), max(sp)))
        for r in cmp:
            if r["err_vs_bem800"] > 3 * max(r["bem_spread"], 1e-5):
                lines.append("  - case %d (Q_a %g, Q_m %g, sigma_m %g, sigma_a %g, %g deg): %.2g of the largest energy, "
                             "BEM spread %.2g, estimate %.2g, merges %s" % (
                                 r["case"], r["qa"], r["qm"], r["sm"], r["sa"], r["phase"], r["err_vs_bem800"],
                                 r["bem_spread"], r["estimate"], r["merges"]))
    open(out + ".md", "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
