#!/usr/bin/env bash
# Installs any missing Debian packages halfslip needs, then configures and
# builds it in ./build (Release). Sourced by the other scripts; safe to rerun.
set -euo pipefail
HS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HS_BUILD="${HS_BUILD:-$HS_ROOT/build}"

hs_packages=(cmake make g++ gfortran pkg-config python3 libboost-dev libmpfr-dev libgmp-dev libeigen3-dev libgsl-dev doctest-dev)
# scripts that need more (bench.sh, pictures.sh, figures.sh) name it in HS_EXTRA_PACKAGES
read -r -a hs_extra <<< "${HS_EXTRA_PACKAGES:-}"
hs_packages+=("${hs_extra[@]}")

hs_install_missing() {
  local missing=()
  for p in "${hs_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "halfslip: installing missing Debian packages: ${missing[*]}" >&2
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "halfslip: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

hs_build() {
  # the benchmarks are built only by the commands that run them (HS_BENCH=ON:
  # scripts/bench.sh, scripts/figures.sh), to keep the test command's build short
  cmake -S "$HS_ROOT" -B "$HS_BUILD" -DCMAKE_BUILD_TYPE=Release "-DHALFSLIP_BUILD_BENCH=${HS_BENCH:-OFF}" >/dev/null
  cmake --build "$HS_BUILD" -j "$(nproc)"
}

hs_install_missing
# HS_SKIP_BUILD=1: packages only (scripts/bench_compare.sh builds its own trees)
[ "${HS_SKIP_BUILD:-0}" = 1 ] || hs_build
