#!/usr/bin/env python3
"""Random probe of `halfslip solve` on the general path, as a new user would try it (issue 13).

    python3 bench/probe_general.py BUILD_DIR GEOMETRY [SEED [COUNT]]

GEOMETRY: flat-rounded or power-law. Each scene draws Q/fP uniformly in (-1, 1) or, half the time,
within 1e-8..1 of sliding; sigma/fp0 log-uniformly within 1e-3..1e4 in magnitude, either sign;
b_f/a log-uniformly within 1e-12..1 of 1 or within 1e-3..1, or the exponent n = 1 + 10^U(-3, 3).
The whole report is asked for (energies, the ramp note, the surface stresses), as the CLI gives it.
Prints every scene that fails or takes longer than 2 s (the documented budget of a double solve
with its energies is 3 s on the project's 2-core machine: docs/models.md, "Time budget").
Only the standard library (no numpy).
"""
import random
import subprocess
import sys
import time


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    build, geo = sys.argv[1], sys.argv[2]
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    count = int(sys.argv[4]) if len(sys.argv) > 4 else 150
    rng = random.Random(seed)
    flagged = []
    t0 = time.time()
    for _ in range(count):
        if rng.random() < 0.5:
            q = rng.choice([1, -1]) * (1 - 10 ** rng.uniform(-8, 0))
        else:
            q = rng.uniform(-1, 1)
        s = rng.choice([1, -1]) * 10 ** rng.uniform(-3, 4)
        args = [build + "/halfslip", "solve", "--geometry", geo, "--Q-over-fP", repr(q),
                "--sigma-over-fp0", repr(s), "--json"]
        if geo == "flat-rounded":
            b = 1 - 10 ** rng.uniform(-12, 0) if rng.random() < 0.5 else 10 ** rng.uniform(-3, 0)
            args += ["--flat-over-a", repr(b)]
        elif geo == "power-law":
            args += ["--exponent", repr(1 + 10 ** rng.uniform(-3, 3))]
        else:
            sys.exit("GEOMETRY: flat-rounded or power-law")
        t = time.time()
        r = subprocess.run(args, capture_output=True, text=True, timeout=600)
        dt = time.time() - t
        if r.returncode != 0:
            flagged.append((" ".join(args[2:]), r.stderr.strip()[:200], round(dt, 2)))
        elif dt > 2:
            flagged.append((" ".join(args[2:]), "slow", round(dt, 2)))
    print(f"{geo}, seed {seed}: {sum(1 for f in flagged if f[1] != 'slow')} of {count} failed, "
          f"{sum(1 for f in flagged if f[1] == 'slow')} took over 2 s; {time.time() - t0:.1f} s in all")
    for f in flagged:
        print(f)


if __name__ == "__main__":
    main()
