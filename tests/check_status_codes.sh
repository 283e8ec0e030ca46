#!/bin/sh
# Fails if the status codes drift apart (issue 12 item 8c): the HS_OK/HS_ERR_*
# definitions of capi/include/halfslip/halfslip.h (name and value), the table of
# docs/api.md (name and value, in the same order), and the cases of hs_strerror
# in capi/src (every code has its own message).
# usage: check_status_codes.sh <source dir>
set -eu
src="${1:-.}"
hdr="$src/capi/include/halfslip/halfslip.h"
doc="$src/docs/api.md"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# "NAME VALUE" per line, in order of appearance
sed -n 's/^#define[[:space:]]\{1,\}\(HS_OK\|HS_ERR_[A-Z_]*\)[[:space:]]\{1,\}\([0-9]\{1,\}\).*/\1 \2/p' "$hdr" > "$tmp/header"
sed -n 's/^| `\(HS_OK\|HS_ERR_[A-Z_]*\)` | \([0-9]\{1,\}\) |.*/\1 \2/p' "$doc" > "$tmp/doc"
# the switch of hs_strerror: "case HS_...: return" in the C shim (wherever it lives)
# (white space, line breaks included, folded first: the layout is clang-format's)
cat "$src"/capi/src/*.cpp | tr -s ' \n' '  ' | grep -o 'case \(HS_OK\|HS_ERR_[A-Z_]*\): *return "' \
  | sed 's/case \([A-Z_]*\):.*/\1/' | sort > "$tmp/strerror"

n=$(wc -l < "$tmp/header")
[ "$n" -ge 2 ] || { echo "no status codes found in $hdr"; exit 1; }
status=0
if ! diff -u "$tmp/header" "$tmp/doc" > "$tmp/d1"; then
  echo "docs/api.md status table differs from halfslip.h (- header, + api.md):"; cat "$tmp/d1"; status=1
fi
cut -d' ' -f1 "$tmp/header" | sort > "$tmp/names"
if ! diff -u "$tmp/names" "$tmp/strerror" > "$tmp/d2"; then
  echo "hs_strerror cases differ from halfslip.h (- header, + hs_strerror):"; cat "$tmp/d2"; status=1
fi
# values distinct
if [ "$(cut -d' ' -f2 "$tmp/header" | sort | uniq -d)" != "" ]; then
  echo "duplicate status values in halfslip.h"; status=1
fi
[ $status -eq 0 ] && echo "status codes: $n, halfslip.h = docs/api.md = hs_strerror"
exit $status
