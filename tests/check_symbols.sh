#!/bin/sh
# Fails if the shared library exports any dynamic symbol not named hs_*.
set -eu
lib="$1"
syms=$(nm -D --defined-only "$lib" | awk '{print $NF}' | sed 's/@.*//' | grep -v '^HALFSLIP_' || true)
[ -n "$syms" ] || { echo "no exported symbols found in $lib"; exit 1; }
bad=$(printf '%s\n' "$syms" | grep -v '^hs_' || true)
if [ -n "$bad" ]; then
  echo "non-hs_ symbols exported:"; printf '%s\n' "$bad"; exit 1
fi
n=$(printf '%s\n' "$syms" | wc -l)
echo "exported symbols: $n, all hs_*"
for s in hs_solve hs_strerror hs_version hs_eval_Bx hs_eval_slip hs_eval_work hs_solution_energy; do
  printf '%s\n' "$syms" | grep -qx "$s" || { echo "missing $s"; exit 1; }
done
