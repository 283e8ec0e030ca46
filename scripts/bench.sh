#!/usr/bin/env bash
# Benchmarks (not part of the test suite): build, run, write CSV data to
# bench/results/ and the chart to docs/.
#   bench/results/hertz.csv      double fast path vs Boost/GSL Carlson and naive quadrature
#   bench/results/reference.csv  MPFR reference at 30/50/100/300 digits vs mpmath
#   bench/results/asymptotic_sweep.csv  asymptotic model vs full solution (estimate check)
#   bench/results/methods.csv, stability.csv  every model: speed, accuracy, stability (issue 5);
#     charts docs/figures/speed_accuracy.svg, docs/figures/stability.svg (docs/benchmarks.md)
#   bench/results/stability_geometries.csv, stability_geometries_summary.md  stability of every method on
#     the flat punch, the power law and sampled pressures, to each method's failure (issue 13; ~10-15 min);
#     charts docs/figures/stability_flat.svg, stability_power.svg, stability_samples.svg
#   bench/results/fields.csv, fields_accuracy.csv  stresses (issue 15; Google Benchmark)
#   bench/results/samples.csv, samples_cli.csv  sampled pressure: time, peak memory and accuracy against
#                                the sample count, C ABI and CLI (issue 13; scripts/bench_samples.sh)
#   bench/results/opposite.csv   opposite-sign slip/energies old vs new, hs_solve_batch vs a loop (issue 16)
#   bench/results/general.csv    general path (flat punch): solve, expansion set-up, B_x, slip and energies
#                                through the C ABI against the paths they replace (issue 16)
# The charts are drawn by halfslip.plot (matplotlib): Debian's /usr/bin/python3 with
# python3-matplotlib (HS_PYTHON overrides it).
set -euo pipefail
export HS_BENCH=ON
export HS_EXTRA_PACKAGES="libbenchmark-dev python3-matplotlib time"
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
mkdir -p "$HS_ROOT/bench/results"
"$HS_BUILD/bench/bench_hertz" "$HS_ROOT/bench/results/hertz.csv"
py="${HS_PYTHON:-/usr/bin/python3}"
plot() { HALFSLIP_LIBRARY="$HS_BUILD/libhalfslip.so" PYTHONPATH="$HS_ROOT/bindings/python" PYTHONDONTWRITEBYTECODE=1 "$py" "$@"; }
plot "$HS_ROOT/bench/plot.py" "$HS_ROOT/bench/results/hertz.csv" "$HS_ROOT/docs/bench_hertz.svg"
"$HS_BUILD/bench/bench_reference" "$HS_ROOT/bench/results/reference.csv"
python3 "$HS_ROOT/bench/mpmath_hertz.py" "$HS_ROOT/bench/results/reference.csv"
"$HS_BUILD/bench/bench_methods" "$HS_ROOT/bench/results/methods.csv" "$HS_ROOT/bench/results/stability.csv"
plot "$HS_ROOT/bench/plot_methods.py" "$HS_ROOT/bench/results/methods.csv" "$HS_ROOT/bench/results/stability.csv" \
  "$HS_ROOT/bench/results/reference.csv" "$HS_ROOT/docs/figures"
# issue 13: stability of the other geometries, every method to its failure, per-call time budgets
# (a hang is a "timeout" row); truths: MPFR reference, the sliding stick point, Hertz (docs/benchmarks.md)
"$HS_BUILD/bench/bench_stability" "$HS_ROOT/bench/results/stability_geometries.csv" \
  | tee "$HS_ROOT/bench/results/stability_geometries.log"
plot "$HS_ROOT/bench/plot_stability.py" "$HS_ROOT/bench/results/stability_geometries.csv" "$HS_ROOT/docs/figures"
# the sweep behind the asymptotic model's error estimate (core/select.hpp, docs/models.md)
"$HS_BUILD/bench/asymptotic_sweep" "$HS_ROOT/bench/results/asymptotic_sweep.csv" 200
# load histories: the march against the independent BEM, cycles, random paths (docs/history.md)
"$HS_BUILD/bench/bench_history" "$HS_ROOT/bench/results/history.csv" | tee "$HS_ROOT/bench/results/history_summary.md"
# point evaluations and energies on the general path
"$HS_BUILD/bench/bench_points" | tee "$HS_ROOT/bench/results/points.txt"
# sampled pressure against the sample count, 10^3 to 10^6: time and peak memory, C ABI and CLI (issue 13 item 4)
HS_BUILD="$HS_BUILD" HS_ROOT="$HS_ROOT" bash "$HS_ROOT/scripts/bench_samples.sh"
# stresses (issue 15): surface and subsurface speed (Google Benchmark), accuracy vs quadrature from scratch
if [ -x "$HS_BUILD/bench/bench_fields" ]; then
  "$HS_BUILD/bench/bench_fields" "$HS_ROOT/bench/results/fields_accuracy.csv" --benchmark_repetitions=5 \
    --benchmark_report_aggregates_only=true --benchmark_out="$HS_ROOT/bench/results/fields.csv" \
    --benchmark_out_format=csv
fi
# issue 16: opposite-sign slip and energies (fixed Gauss rules vs the old tanh-sinh path) and
# hs_solve_batch against one hs_solve per scene, same run (Google Benchmark)
if [ -x "$HS_BUILD/bench/bench_opposite" ]; then
  "$HS_BUILD/bench/bench_opposite" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$HS_ROOT/bench/results/opposite.csv" --benchmark_out_format=csv \
    | tee "$HS_ROOT/bench/results/opposite.txt"
fi
# issue 16: AUTO at rtol 1e-15 (a-posteriori estimate) against the reference route it replaces, same run
if [ -x "$HS_BUILD/bench/bench_auto" ]; then
  "$HS_BUILD/bench/bench_auto" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$HS_ROOT/bench/results/auto.csv" --benchmark_out_format=csv \
    | tee "$HS_ROOT/bench/results/auto.txt"
fi
# issue 16: the general path (flat punch b_f/a = 0.5, rtol 1e-12): solve, the expansion's set-up,
# B_x / slip at a point and energies through the C ABI, next to the paths they replace (same run)
if [ -x "$HS_BUILD/bench/bench_general" ]; then
  "$HS_BUILD/bench/bench_general" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$HS_ROOT/bench/results/general.csv" --benchmark_out_format=csv \
    | tee "$HS_ROOT/bench/results/general.txt"
fi
