#!/bin/sh
# Build and run consumers with pkg-config against an installed prefix:
#   pkgconfig_consumer.sh PKGCONFIGDIR LIBDIR WORKDIR SRCDIR CC [FC]
# C against the shared library, C against the static library (exactly what
# `pkg-config --static` says), and Fortran (halfslip-fortran.pc) when FC is given.
# The programs run with no LD_LIBRARY_PATH: the .pc files give a run path.
# EXTRA_LDFLAGS (environment) is added to every link (sanitizer builds).
set -eu
pcdir=$1 libdir=$2 work=$3 src=$4 cc=$5 fc=${6:-}
export PKG_CONFIG_PATH="$pcdir"
unset PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR LD_LIBRARY_PATH 2>/dev/null || true
ldflags=${EXTRA_LDFLAGS:-}
rm -rf "$work" && mkdir -p "$work" && cd "$work"

echo "pkg-config --cflags --libs halfslip: $(pkg-config --cflags --libs halfslip)"
pkg-config --exists --print-errors "halfslip >= 0.1"
# shellcheck disable=SC2046
$cc -std=c99 -pedantic -Wall -Wextra -Werror "$src/consumer.c" $(pkg-config --cflags --libs halfslip) -lm $ldflags \
  -o c_shared
# the run path, not some other copy on the loader's path, finds the installed library
found=$(ldd ./c_shared | sed -n 's/^[[:space:]]*libhalfslip\.so[^ ]* => \([^ ]*\) .*/\1/p')
if [ -z "$found" ] || [ "$(realpath "$found")" != "$(realpath "$libdir"/libhalfslip.so.*[0-9] | head -1)" ]; then
  echo "c_shared does not find $libdir/libhalfslip.so through its run path"; ldd ./c_shared; exit 1
fi
./c_shared

static_libs=$(pkg-config --static --libs halfslip)
echo "pkg-config --static --libs halfslip: $static_libs"
for l in -l:libhalfslip.a -lmpfr -lgmp -lstdc++; do
  case " $static_libs " in *" $l "*) ;; *) echo "Libs.private lacks $l"; exit 1 ;; esac
done
# shellcheck disable=SC2046
$cc -std=c99 -pedantic -Wall -Wextra -Werror "$src/consumer.c" $(pkg-config --static --cflags halfslip) \
  $static_libs $ldflags -o c_static
if ldd ./c_static 2>/dev/null | grep -q libhalfslip; then
  echo "c_static still needs libhalfslip.so"; exit 1
fi
./c_static

if [ -n "$fc" ]; then
  echo "pkg-config --cflags --libs halfslip-fortran: $(pkg-config --cflags --libs halfslip-fortran)"
  # shellcheck disable=SC2046
  $fc "$src/consumer.f90" $(pkg-config --cflags --libs halfslip-fortran) $ldflags -o f_shared
  ./f_shared
fi
echo "pkg-config consumers: ok"
