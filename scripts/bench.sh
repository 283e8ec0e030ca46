#!/usr/bin/env bash
# Benchmarks (not part of the test suite): build, run, write CSV and SVG charts
# to bench/results/ (data) and docs/ (charts).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
mkdir -p "$HS_ROOT/bench/results"
"$HS_BUILD/bench/bench_hertz" "$HS_ROOT/bench/results/hertz.csv"
python3 "$HS_ROOT/bench/plot.py" "$HS_ROOT/bench/results/hertz.csv" "$HS_ROOT/docs/bench_hertz.svg"
