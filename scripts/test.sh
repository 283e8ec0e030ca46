#!/usr/bin/env bash
# The whole test suite: install what is missing, build, run ctest, then the
# reliability stage (sanitizers, valgrind, bounded fuzzing; scripts/reliability.sh).
# HALFSLIP_QUICK=1 skips the reliability stage (for quick local runs; CI runs it).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
(cd "$HS_BUILD" && ctest --output-on-failure -j "$(nproc)" "$@")
if [ "${HALFSLIP_QUICK:-0}" != "1" ]; then
  bash "$HS_ROOT/scripts/reliability.sh"
fi
