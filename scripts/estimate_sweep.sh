#!/bin/bash
# Issue 13 estimate sweep (docs/validation.md, "Estimate sweep"): every double result of
# HS_MODEL_DEFAULT and HS_MODEL_AUTO (rtol 0, 1e-10; AUTO at 1e-15 and the a-posteriori estimate, issue 16)
# against the MPFR reference, per geometry.
#   bash scripts/estimate_sweep.sh [N_PER_GEOMETRY=10000] [SECONDS_PER_GEOMETRY=unlimited]
# One core, niced. Writes bench/results/estimate_sweep.csv and bench/results/estimate_sweep_summary.md.
# Needs a build with -DHALFSLIP_BUILD_BENCH=ON (target estimate_sweep) in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
N=${1:-10000}
LIMIT=${2:-1e30}
cmake --build build -j1 --target estimate_sweep >/dev/null
mkdir -p bench/results
for g in hertz flat power; do
  nice -n 10 build/bench/estimate_sweep --geometry $g --n "$N" --time-limit "$LIMIT" \
    --csv bench/results/estimate_sweep_$g.csv --summary bench/results/estimate_sweep_$g.md || true
done
cat bench/results/estimate_sweep_{hertz,flat,power}.md > bench/results/estimate_sweep_summary.md
