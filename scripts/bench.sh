#!/usr/bin/env bash
# Benchmarks (not part of the test suite): build, run, write CSV data to
# bench/results/ and the chart to docs/.
#   bench/results/hertz.csv      double fast path vs Boost/GSL Carlson and naive quadrature
#   bench/results/reference.csv  MPFR reference at 30/50/100/300 digits vs mpmath
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
mkdir -p "$HS_ROOT/bench/results"
"$HS_BUILD/bench/bench_hertz" "$HS_ROOT/bench/results/hertz.csv"
python3 "$HS_ROOT/bench/plot.py" "$HS_ROOT/bench/results/hertz.csv" "$HS_ROOT/docs/bench_hertz.svg"
"$HS_BUILD/bench/bench_reference" "$HS_ROOT/bench/results/reference.csv"
python3 "$HS_ROOT/bench/mpmath_hertz.py" "$HS_ROOT/bench/results/reference.csv"
