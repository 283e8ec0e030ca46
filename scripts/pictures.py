#!/usr/bin/env python3
"""The README pictures (issue 15), drawn by halfslip.plot from the library:

  docs/figures/hertz_scene.png   Hertz, Q/fP = 0.5, sigma/fp0 = 0.5, f = 0.6
  docs/figures/flat_scene.png    flat punch with rounded corners b_f/a = 0.5, Q/fP = 0.4, sigma/fp0 = 1.5, f = 0.6
  docs/figures/regime_map.png    the paper's Figure 3 (contours of b1/a, same/opposite-sign boundary)

usage: pictures.py OUT_DIR  (run by scripts/pictures.sh with a Python that has matplotlib)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "halfslip"  # reproducible output

import halfslip  # noqa: E402
import halfslip.plot as hp  # noqa: E402


def main(out):
    os.makedirs(out, exist_ok=True)
    with halfslip.solve(Q_over_fP=0.5, sigma_over_fp0=0.5, f=0.6) as sol:
        fig = hp.overview(sol, title="Hertz: Q/fP = 0.5, σ/fp0 = 0.5, f = 0.6 (%s slip zones)" % sol.regime_name)
        hp.save(fig, os.path.join(out, "hertz_scene.png"), dpi=80)
    with halfslip.Scene(Q_over_fP=0.4, sigma_over_fp0=1.5, f=0.6).solve(flat_over_a=0.5) as sol:
        fig = hp.overview(sol, title="flat punch, rounded corners b_f/a = 0.5: Q/fP = 0.4, σ/fp0 = 1.5, f = 0.6 "
                                     "(%s slip zones)" % sol.regime_name)
        hp.save(fig, os.path.join(out, "flat_scene.png"), dpi=80)
    ax = hp.regime_map()
    hp.save(ax, os.path.join(out, "regime_map.png"), dpi=80)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "docs/figures")
