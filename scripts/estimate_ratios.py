#!/usr/bin/env python3
"""Issue 16: estimate / true error per scene category from an estimate_sweep CSV.

    python3 scripts/estimate_ratios.py bench/results/estimate_sweep16_hertz.csv default0 apost

For each configuration: per category (bench/estimate_sweep.cpp) the ratio
estimate / max(err, 2^-53) (a double result cannot be judged below half an ulp),
its median, 90th percentile and maximum, and the scenes whose error exceeds the
estimate (without the truth's own bound); then how many scenes AUTO at rtol
1e-15 kept in double among those whose `apost` error is <= 1e-15.
"""
import collections
import csv
import math
import sys

U = 2.0 ** -53


def main(path, configs):
    rows = list(csv.DictReader(open(path)))
    for cfg in configs:
        by = collections.defaultdict(list)
        for r in rows:
            try:
                est, err = float(r[cfg + "_est"]), float(r[cfg + "_err"])
            except (KeyError, ValueError):
                continue
            if math.isnan(err) or math.isnan(est):
                continue
            by[r["category"]].append((est / max(err, U), est, err))
        print(cfg)
        every = []
        for c in sorted(by):
            v = sorted(x[0] for x in by[c])
            every += v
            print("  category %s: %d scenes, ratio median %.3g p90 %.3g max %.3g, error > estimate: %d" % (
                c, len(v), v[len(v) // 2], v[int(0.9 * len(v))], v[-1], sum(1 for x in by[c] if x[2] > x[1])))
        every.sort()
        if every:
            print("  all: %d scenes, median %.3g p90 %.3g max %.3g, above 30x: %d" % (
                len(every), every[len(every) // 2], every[int(0.9 * len(every))], every[-1],
                sum(1 for x in every if x > 30)))
    if rows and "auto1e-15_model" in rows[0]:
        met = [r for r in rows if r.get("apost_err") not in (None, "", "nan") and float(r["apost_err"]) <= 1e-15]
        kept = sum(1 for r in met if r["auto1e-15_model"] in ("3", "4"))
        print("apost error <= 1e-15: %d scenes; AUTO at 1e-15 kept %d in double" % (len(met), kept))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:] or ["default0", "apost"])
