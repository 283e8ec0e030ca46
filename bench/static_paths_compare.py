#!/usr/bin/env python3
"""Compare two OUT files of bench/static_periodic_paths.cpp (ends and segment energies in hex, one
line per vertex: case vertex b1 b2 E1 E2 Ep). For every case with at least 3 vertices in both, the
largest energy difference over its common vertices relative to the case's largest segment energy (in
OUT_B), the vertex where it occurs, and the largest difference of the ends (in a). Prints the N cases
that differ most (default 10):

    python3 bench/static_paths_compare.py rtol8.txt full.txt 12
"""
import sys


def load(path):
    d = {}
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 7:
                d[(int(p[0]), int(p[1]))] = [float.fromhex(x) for x in p[2:]]
    return d


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    a, b = load(sys.argv[1]), load(sys.argv[2])
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 10
    rows = []
    for c in sorted({k[0] for k in a} & {k[0] for k in b}):
        ks = [k for k in a if k[0] == c and k in b]
        if len(ks) < 3:
            continue
        big = max(max(abs(x) for x in b[k][2:]) for k in ks) or 1.0
        worst, at, ends = 0.0, None, 0.0
        for k in ks:
            de = max(abs(a[k][i] - b[k][i]) for i in (2, 3, 4)) / big
            if de > worst:
                worst, at = de, k[1]
            ends = max(ends, max(abs(a[k][i] - b[k][i]) for i in (0, 1)))
        rows.append((worst, c, at, ends, len(ks)))
    rows.sort(reverse=True)
    for worst, c, at, ends, m in rows[:n]:
        print("case %d: energies %.2e of the largest (vertex %s), ends %.2e a, %d vertices" % (c, worst, at, ends, m))


if __name__ == "__main__":
    main()
