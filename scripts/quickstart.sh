#!/usr/bin/env bash
# The main job: install what is missing, build, and solve the default scene.
# Extra arguments go to `halfslip solve` (e.g. --Q-over-fP 0.3 --sigma-over-fp0 2 --json).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh" >&2
exec "$HS_BUILD/halfslip" solve "$@"
