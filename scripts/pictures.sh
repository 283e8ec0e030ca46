#!/usr/bin/env bash
# The README pictures (docs/figures/hertz_scene.png, flat_scene.png, regime_map.png),
# drawn by the Python plotting module halfslip.plot from the library just built.
# Needs a Python with matplotlib: Debian's /usr/bin/python3 with python3-matplotlib
# (HS_PYTHON overrides the interpreter).
set -euo pipefail
export HS_EXTRA_PACKAGES="python3-matplotlib"
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
py="${HS_PYTHON:-/usr/bin/python3}"
"$py" -c "import matplotlib" 2>/dev/null || { echo "pictures.sh: $py has no matplotlib (apt install python3-matplotlib)" >&2; exit 1; }
HALFSLIP_LIBRARY="$HS_BUILD/libhalfslip.so" PYTHONPATH="$HS_ROOT/bindings/python" PYTHONDONTWRITEBYTECODE=1 \
  "$py" "$HS_ROOT/scripts/pictures.py" "$HS_ROOT/docs/figures"
