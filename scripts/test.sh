#!/usr/bin/env bash
# The whole test suite: install what is missing, build, run ctest.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$HS_BUILD"
ctest --output-on-failure -j "$(nproc)" "$@"
