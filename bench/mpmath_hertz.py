#!/usr/bin/env python3
"""The alternative a user would write in Python: solve the same Hertz side
conditions with mpmath at a given number of digits, (a) with the closed forms
through mpmath's Carlson functions and mp.findroot, (b) with mp.quad of the
raw integrals (30 and 50 digits only: slow). Appends rows to the reference
benchmark CSV: kind,method,regime,digits,median_ms. Benchmark only; the test
suite never uses mpmath.

usage: mpmath_hertz.py results.csv
"""
import sys
import time

try:
    import mpmath as mp
except ImportError:  # the benchmark is optional where mpmath is absent
    print("mpmath not available: skipping the mpmath comparison")
    sys.exit(0)


def closed_residual(q, s, b1, b2):
    e = b1 + b2
    om1, om2, op1, op2 = 1 - b1, 1 - b2, 1 + b1, 1 + b2
    P, Q = 2 * e, op1 * op2
    RF = mp.elliprf(0, P, Q)
    RD = mp.elliprd(0, Q, P)
    RJ = mp.elliprj(0, P, Q, 2 * op2)
    A0 = 2 * om1 * (RF + (b1 - b2) * op2 * RJ / 3 - om2 * e * RD / 3)
    A1 = om1 * ((3 * b1 - b2 + 2) * RF / 2 + op2 * (3 * b1**2 - 2 * b1 * b2 + 3 * b2**2 - 4) * RJ / 6
                - om2 * (b1 - b2) * e * RD / 2)
    F1 = mp.pi * (b1 - b2) / 2 + 2 * A0 - mp.pi * s / 4
    F2 = mp.pi * (mp.mpf(3) / 8 * (b1**2 + b2**2) - b1 * b2 / 4 - mp.mpf(1) / 2) + 2 * A1 + mp.pi * q / 2 \
        - mp.pi * s * (b1 - b2) / 8
    return F1, F2


def quad_residual(q, s, b1, b2):
    def side(j):
        right = mp.quad(lambda t: t**(j - 1) * mp.sqrt(1 - t * t) / mp.sqrt((t - b1) * (t + b2)), [b1, 1])
        left = mp.quad(lambda t: t**(j - 1) * mp.sqrt(1 - t * t) / mp.sqrt((t - b1) * (t + b2)), [-1, -b2])
        return left + right
    return (side(1) - mp.pi * s / 4,
            side(2) + mp.pi * q / 2 - mp.pi * s * (b1 - b2) / 8)


def solve(residual, q, s, start):
    return mp.findroot(lambda b1, b2: residual(q, s, b1, b2), start)


def median_ms(f, reps):
    t = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        t.append((time.perf_counter() - t0) * 1e3)
    t.sort()
    return t[len(t) // 2]


def main(csv):
    rows = []
    q, s = mp.mpf("0.3"), mp.mpf(2)
    for digits in (30, 50, 100, 300):
        mp.mp.dps = digits + 10
        start = (mp.mpf("0.75"), mp.mpf("0.37"))  # near the solution: a generous start
        t = median_ms(lambda: solve(closed_residual, q, s, start), 5)
        rows.append(("solve", "mpmath-closed-forms+findroot", "opposite-sign", digits, t))
        print(f"mpmath closed forms + findroot, {digits} digits: {t:.2f} ms")
        if digits <= 50:
            t = median_ms(lambda: solve(quad_residual, q, s, start), 1)
            rows.append(("solve", "mpmath-quad+findroot", "opposite-sign", digits, t))
            print(f"mpmath quad + findroot, {digits} digits: {t:.1f} ms")
    with open(csv, "a") as f:
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main(sys.argv[1])
