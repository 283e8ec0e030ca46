#!/bin/sh
# The installed prefix works from anywhere, with no environment variable:
#   relocated_prefix.sh PREFIX BINDIR LIBDIR WORKDIR
# copies PREFIX to WORKDIR/moved and runs the installed halfslip command there
# under `env -i` (no LD_LIBRARY_PATH, no PATH); its run path must be relative
# ($ORIGIN) and must find the moved libhalfslip, not the original one.
set -eu
unset LD_LIBRARY_PATH 2>/dev/null || true
prefix=$1 bindir=$2 libdir=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cp -a "$prefix" "$work/moved"
exe="$work/moved/$bindir/halfslip"
if command -v readelf >/dev/null 2>&1; then
  rp=$(readelf -d "$exe" | grep -E 'R(UN)?PATH' || true)
  case "$rp" in *'$ORIGIN'*) ;; *) echo "installed halfslip has no relative run path: '$rp'"; exit 1 ;; esac
fi
found=$(ldd "$exe" | sed -n 's/^[[:space:]]*libhalfslip\.so[^ ]* => \([^ ]*\) .*/\1/p')
case "$(realpath "$found")" in
  "$(realpath "$work/moved")"/*) ;;
  *) echo "the moved halfslip loads '$found', not the moved library"; exit 1 ;;
esac
v=$(env -i "$exe" --version) || { echo "installed halfslip does not run: exit $?"; exit 1; }
echo "$v"
env -i "$exe" solve --json >/dev/null
for lib in "$work/moved/$libdir"/libhalfslip*.so.*[0-9]; do
  [ -L "$lib" ] && continue
  ldd "$lib" | grep -q "not found" && { echo "$lib has unresolved libraries"; ldd "$lib"; exit 1; }
done
echo "relocated prefix: ok"
