#!/usr/bin/env bash
# The paper's Figures 5 and 6 (asymptotic edge model vs full solution) as CSV
# and charts (SVG, plus PNG when rsvg-convert can be installed) in docs/figures/.
set -euo pipefail
export HS_BENCH=ON
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh" >/dev/null
hs_packages=(librsvg2-bin)
hs_install_missing || true
out="$HS_ROOT/docs/figures"
mkdir -p "$out"
"$HS_BUILD/bench/figures_asymptotic" "$out"
python3 "$HS_ROOT/bench/plot_lines.py" "$out/fig5.csv" "$out/fig5.svg" "Fig. 5: work done against friction, b/a = 0.9" "z/d (from the contact edge)" "W / (f^2 p0^2 a / E*)"
python3 "$HS_ROOT/bench/plot_lines.py" "$out/fig6.csv" "$out/fig6.svg" "Fig. 6: fractional error of the asymptotic energy" "b/a" "(asymptotic - full) / full"
if command -v rsvg-convert >/dev/null 2>&1; then
  for f in fig5 fig6; do rsvg-convert "$out/$f.svg" -o "$out/$f.png"; done
  echo "PNG charts written"
fi
