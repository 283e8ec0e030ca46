#!/bin/bash
# Cold-process CPU times of the reference backend on the four scenes of
# docs/reference.md's cost table (issue 16): `halfslip table ... --threads 1`
# with and without --no-energy, at 50 and 100 digits. One CSV row per run:
#   tag,scene,digits,what,user_s,wall_s
# (what: b = b1, b2, d1, d2; b+E = also both zone energies). The machine is
# shared: user_s (CPU time) is the figure to compare.
# Usage: bash bench/reference_cli_times.sh BUILD_DIR TAG [DIGITS...] >> bench/results/reference_cli.csv
set -euo pipefail
BUILD=$1
TAG=$2
shift 2
DIGITS=("$@")
[ ${#DIGITS[@]} -eq 0 ] && DIGITS=(50 100)
names=(flat0.5-same flat0.5-opposite power3-same power1.5-opposite)
scenes=("flat-rounded --flat-over-a 0.5 --Q-over-fP 0.5 --sigma-over-fp0 0.5"
        "flat-rounded --flat-over-a 0.5 --Q-over-fP 0.3 --sigma-over-fp0 2"
        "power-law --exponent 3 --Q-over-fP 0.5 --sigma-over-fp0 0.5"
        "power-law --exponent 1.5 --Q-over-fP 0.3 --sigma-over-fp0 2")
tmp=$(mktemp)
for d in "${DIGITS[@]}"; do
  for what in b b+E; do
    for i in 0 1 2 3; do
      extra=""
      [ "$what" = b ] && extra="--no-energy"
      # shellcheck disable=SC2086
      /usr/bin/time -f "%U,%e" -o "$tmp" env LD_LIBRARY_PATH="$BUILD" "$BUILD/halfslip" table --geometry ${scenes[$i]} \
        --digits "$d" --threads 1 $extra > /dev/null
      echo "$TAG,${names[$i]},$d,$what,$(cat "$tmp")"
    done
  done
done
rm -f "$tmp"
