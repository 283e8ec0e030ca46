#!/usr/bin/env bash
# The paper's Figures 5 and 6 (asymptotic edge model vs full solution) as CSV
# and charts (SVG and PNG, drawn by halfslip.plot with matplotlib) in docs/figures/.
# Needs a Python with matplotlib: Debian's /usr/bin/python3 (HS_PYTHON overrides it).
set -euo pipefail
export HS_BENCH=ON
export HS_EXTRA_PACKAGES="python3-matplotlib"
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh" >/dev/null
out="$HS_ROOT/docs/figures"
mkdir -p "$out"
"$HS_BUILD/bench/figures_asymptotic" "$out"
py="${HS_PYTHON:-/usr/bin/python3}"
plot() { HALFSLIP_LIBRARY="$HS_BUILD/libhalfslip.so" PYTHONPATH="$HS_ROOT/bindings/python" PYTHONDONTWRITEBYTECODE=1 "$py" "$@"; }
plot "$HS_ROOT/bench/plot_lines.py" "$out/fig5.csv" "$out/fig5.svg,$out/fig5.png" "Fig. 5: work done against friction, b/a = 0.9" "z/d (from the contact edge)" "W / (f^2 p0^2 a / E*)"
plot "$HS_ROOT/bench/plot_lines.py" "$out/fig6.csv" "$out/fig6.svg,$out/fig6.png" "Fig. 6: fractional error of the asymptotic energy" "b/a" "(asymptotic - full) / full"
