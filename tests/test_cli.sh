#!/bin/sh
# The halfslip command: default scene, JSON keys, bad input -> non-zero exit and one line.
set -u
cli="$1"
pass=0; fail=0
ok() { pass=$((pass+1)); }
ko() { fail=$((fail+1)); echo "FAILED: $1"; }

out=$("$cli" solve) && echo "$out" | grep -q "regime: same-sign" && ok || ko "default solve"
echo "$out" | grep -q "b1/a" && ok || ko "report has b1/a"

js=$("$cli" solve --Q-over-fP 0.3 --sigma-over-fp0 2 --json) && ok || ko "json solve"
for k in regime b1 b2 d1 d2 a; do
  echo "$js" | grep -q "\"$k\": " && ok || ko "json key $k"
done
echo "$js" | grep -q '"regime": "opposite-sign"' && ok || ko "json regime"
# 17 significant digits
echo "$js" | grep -Eq '"b1": -?[0-9]\.[0-9]{16}' && ok || ko "17 digits"
if command -v python3 >/dev/null 2>&1; then
  echo "$js" | python3 -c 'import json,sys; json.load(sys.stdin)' && ok || ko "valid JSON"
fi

"$cli" solve --P 1000 --R 0.05 --E-star 1.15e11 --f 0.6 --Q 300 --sigma 2e6 --json >/dev/null && ok || ko "dimensional"
# dimensional power law: n = 2 with A = 1/(2R) is the Hertz scene above
h=$("$cli" solve --P 1000 --R 0.05 --E-star 1.15e11 --f 0.6 --Q 300 --sigma 2e6 | grep "b1/a")
p=$("$cli" solve --geometry power-law --exponent 2 --P 1000 --A 10 --E-star 1.15e11 --f 0.6 --Q 300 --sigma 2e6 | grep "b1/a")
# (to 1e-13: the quadrature's estimate is 6e-14; the last of 15 printed digits may differ)
[ -n "$h" ] && python3 -c "
import re, sys
h = [float(v) for v in re.findall(r'= ([0-9.e+-]+)', sys.argv[1])]
p = [float(v) for v in re.findall(r'= ([0-9.e+-]+)', sys.argv[2])]
assert len(h) == 2 and len(p) == 2 and all(abs(a - b) <= 1e-13 for a, b in zip(h, p)), (h, p)
" "$h" "$p" && ok || ko "dimensional power law n = 2 is Hertz"
"$cli" solve --geometry power-law --exponent 3 --P 1000 --R 0.05 --E-star 1e11 --f 0.6 --Q 300 --sigma 0 >/dev/null 2>&1 && ko "--R accepted for a power law" || ok

for bad in "--Q-over-fP 1.0" "--Q-over-fP nan" "--f -1" "--Q-over-fP abc" "--geometry cube" "--bogus 1" "--a 0"; do
  err=$("$cli" solve $bad 2>&1 >/dev/null); rc=$?
  if [ $rc -ne 0 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ]; then ok; else ko "bad input '$bad' (rc=$rc): $err"; fi
done
err=$("$cli" solve --Q-over-fP 1.5 2>&1 >/dev/null); echo "$err" | grep -q "Q-over-fP" && ok || ko "message names the bad value"

# issue 13: a zone below the model's resolution: regime "boundary", direction 0, zone_resolution in the JSON
js=$("$cli" solve --Q-over-fP -0.45989658854377635 --sigma-over-fp0 -1.0603308717987363 --json) && echo "$js" | grep -q '"regime": "boundary"' && ok || ko "boundary regime"
echo "$js" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["slip_dir1"] == 0 and 0 < d["zone_resolution"] < 1e-14 and d["d1"] <= d["zone_resolution"]' && ok || ko "boundary: direction 0, zone_resolution"
out=$("$cli" solve --Q-over-fP -0.45989658854377635 --sigma-over-fp0 -1.0603308717987363) && echo "$out" | grep -q "at or below the model's zone resolution" && ok || ko "boundary note in the report"
# issue 13: the flat punch at b_f/a = 0.999 and large sigma, the power law at n = 999
"$cli" solve --geometry flat-rounded --flat-over-a 0.999 --Q-over-fP 0.3 --sigma-over-fp0 100 --json >/dev/null && ok || ko "flat punch 0.999 at sigma/fp0 = 100"
"$cli" solve --geometry power-law --exponent 999 --Q-over-fP 0.3 --sigma-over-fp0 100 --no-energy --json >/dev/null && ok || ko "power law n = 999 at sigma/fp0 = 100"

# model selection by --rtol: tiny slip zones + loose rtol -> asymptotic; the estimate meets rtol
js=$("$cli" solve --Q-over-fP 1e-5 --sigma-over-fp0 0 --rtol 1e-3 --json) && echo "$js" | grep -q '"model": "asymptotic"' && ok || ko "--rtol picks the asymptotic model"
echo "$js" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert 0 < d["error_estimate"] <= 1e-3' && ok || ko "estimate <= rtol"
js=$("$cli" solve --Q-over-fP 0.5 --rtol 1e-12 --json) && echo "$js" | grep -q '"model": "closed-form"' && ok || ko "--rtol 1e-12 -> closed form"
js=$("$cli" solve --geometry power-law --exponent 3 --Q-over-fP 0.5 --rtol 1e-9 --json) && echo "$js" | grep -q '"model": "quadrature"' && ok || ko "--rtol 1e-9 power law -> quadrature"
out=$("$cli" solve --rtol 1e-30) && echo "$out" | grep -q "\[30 digits certified\]" && ok || ko "--rtol 1e-30 -> reference"
"$cli" solve --model closed-form --geometry flat-rounded >/dev/null 2>&1 && ko "closed form for a flat punch accepted" || ok
"$cli" solve --model bogus >/dev/null 2>&1 && ko "--model bogus accepted" || ok
# issue 13: the message names the value given (bindings/cli/args.cpp)
"$cli" solve --model bogus 2>&1 | grep -q "bad value for --model: 'bogus' (known: default, auto" && ok || ko "--model bogus: message names the value"
"$cli" solve --rtol 0.7 >/dev/null 2>&1 && ko "--rtol 0.7 accepted" || ok

# reference backend: --digits, certified digits, JSON strings
out=$("$cli" solve --digits 35 --Q-over-fP 0.3 --sigma-over-fp0 2) && echo "$out" | grep -q "7.4905836296899063300263576571618318e-01   \[35 digits certified\]" && ok || ko "solve --digits"
js=$("$cli" solve --digits 25 --json) && echo "$js" | python3 -c 'import json,sys; json.load(sys.stdin)' && echo "$js" | grep -q '"b1": "8.321067811865475244008444e-01", "b1_digits": 25' && ok || ko "solve --digits --json"
"$cli" solve --digits 0 >/dev/null 2>&1 && ko "--digits 0 accepted" || ok
# table: sharded outputs concatenate to the unsharded one
full=$("$cli" table --Q-over-fP 0.1:0.3:3 --sigma-over-fp0 0,1.5 --digits 20 --no-energy --threads 2) && ok || ko "table"
[ "$(printf '%s\n' "$full" | wc -l)" -eq 8 ] && ok || ko "table rows (provenance, header, 6 rows)"
printf '%s\n' "$full" | head -1 | grep -qx "# halfslip [0-9.]*, 20 significant digits (reference backend), command: halfslip table --Q-over-fP 0.1:0.3:3 --sigma-over-fp0 0,1.5 --digits 20 --no-energy" && ok || ko "table provenance line"
cat_shards=$( for k in 1 2 3; do "$cli" table --Q-over-fP 0.1:0.3:3 --sigma-over-fp0 0,1.5 --digits 20 --no-energy --threads 1 --shard $k/3; done )
[ "$full" = "$cat_shards" ] && ok || ko "shards concatenate to the full table"
jl=$("$cli" table --Q-over-fP 0.2,0.999 --sigma-over-fp0 0.5 --digits 20 --format jsonl --no-energy) && ok || ko "table jsonl"
if command -v python3 >/dev/null 2>&1; then
  echo "$jl" | python3 -c 'import json,sys; [json.loads(l) for l in sys.stdin]' && ok || ko "jsonl parses"
fi
"$cli" table --Q-over-fP 0.1 --sigma-over-fp0 0 --shard 4/3 >/dev/null 2>&1 && ko "bad shard accepted" || ok

# other geometries
out=$("$cli" solve --geometry flat-rounded --flat-over-a 0.5 --Q-over-fP 0.4 --sigma-over-fp0 2) && echo "$out" | grep -q "regime: opposite-sign" && echo "$out" | grep -q "Gauss-Legendre order" && ok || ko "flat-rounded"
js=$("$cli" solve --geometry power-law --exponent 2 --json) && echo "$js" | grep -q '"b1": 0.83210678118654' && ok || ko "power law n=2 is Hertz"
"$cli" solve --geometry flat-rounded --P 1000 --R 0.01 --E-star 1.15e11 --f 0.6 --Q 300 --sigma 2e6 --flat-width 0.0005 --json >/dev/null && ok || ko "dimensional flat-rounded"
tmp=$(mktemp); python3 -c "
import math
for i in range(61):
    x=-math.cos(math.pi*i/60); print(x, math.sqrt(max(0.0,1-x*x)))" > "$tmp"
js=$("$cli" solve --geometry samples --pressure-file "$tmp" --json) && echo "$js" | grep -q '"b1": 0.83210678' && ok || ko "samples of Hertz"
rm -f "$tmp"
# pressure files: whitespace or commas, a header line, '#' comments, CRLF; same result as plain columns
tmp=$(mktemp); dir=$(mktemp -d)
python3 -c "
import math, sys
rows = [(-math.cos(math.pi*i/60), math.sqrt(max(0.0, 1 - math.cos(math.pi*i/60)**2))) for i in range(61)]
def w(name, head, fmt, eol):
    with open(sys.argv[1] + '/' + name, 'w', newline='') as fh:
        fh.write(head + ''.join(fmt % r + eol for r in rows))
w('spaces.txt', '', '%r %r', '\\n')
w('header.csv', 'x [m], p [Pa]\\n', '%r, %r', '\\n')
w('tabs.txt', '# exported\\r\\nx\\tp\\r\\n', '  %r\\t%r   # comment', '\\r\\n')
w('plain.csv', 'x,p\\n', '%r,%r', '\\n')" "$dir"
for f in spaces.txt header.csv tabs.txt plain.csv; do
  js=$("$cli" solve --geometry samples --pressure-file "$dir/$f" --json) && echo "$js" | grep -q '"b1": 0.83210678' && ok || ko "pressure file format $f"
done
rm -rf "$dir"
# rejections name the file, the line and the rule
rej() {  # rej CONTENT 'expected text'
  printf '%b' "$1" > "$tmp"
  err=$("$cli" solve --geometry samples --pressure-file "$tmp" 2>&1 >/dev/null); rc=$?
  if [ $rc -ne 0 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && printf '%s' "$err" | grep -qF -- "$2"; then ok
  else ko "pressure file '$1': expected '$2', got (rc=$rc) $err"; fi
}
six="-0.9 0.43\n-0.5 0.86\n0 1\n0.5 0.86\n0.9 0.43\n"
rej "" "line 1: the file is empty"
rej "# nothing\n\nx p\n" "line 3: end of file, no samples"
rej "x p\n-0.5 0.8\n0 1\n0.5 0.8\n" "line 4: end of file after 3 samples; need at least 6"
rej "x p\n-0.5 -0.8\n$six" "line 2: negative pressure p = -0.8"
rej "$six-0.2 0.9\n" "line 6: x = -0.2 does not increase (previous sample, line 5"
rej "$six""0.9 0.5\n" "line 6: x = 0.9 does not increase"
rej "-1.5 0\n$six" "line 1: x = -1.5 is outside the contact [-a, a] = [-1, 1]"
rej "$six""0.95 nan\n" "line 6: p is NaN"
rej "nan 1\n$six" "line 1: x is NaN"
rej "-0.95 inf\n$six" "line 1: p is not finite"
rej "-0.95 0.2 7\n$six" "line 1: 3 columns, expected 2"
rej "-0.95,0.2,\n$six" "line 1: 3 columns, expected 2"
rej "-0.95\n$six" "line 1: 1 column, expected 2"
rej "x p\n-0.95 0.2\nfoo 0.3\n$six" "line 3: x 'foo' is not a number"
rej "-0.95 0.2kPa\n$six" "line 1: p '0.2kPa' is not a number"
rej "-1 0.5\n$six" "line 1: p = 0.5 at the contact edge x = -1"
rej "-0.95 0\n$six" "line 1: p = 0 inside the contact"
# the library's own rules name the sample too (issue 13 item 5: was "unknown geometry or invalid
# geometry parameter"): a pressure vanishing linearly at the edges, a pressure not vanishing
rej "# triangle\n-1 0\n-0.9 0.1\n-0.5 0.5\n0 1\n0.5 0.5\n0.9 0.1\n1 0\n" "line 3: x = -0.9, p = 0.1: the two samples nearest the edge x = -a do not vanish like sqrt(distance)"
rej "-0.9 0.44\n-0.5 0.87\n0 1\n0.5 0.87\n0.9 0.44\n0.99 0.44\n" "line 6: x = 0.99, p = 0.44: the two samples nearest the edge x = +a do not vanish like sqrt(distance)"
# lines longer than 511 bytes (and than the 4096-byte read chunk) keep the line count (issue 13 item 5)
long=$(printf '%0600d' 0)
rej "# $long\n$six-0.2 0.9\n" "line 7: x = -0.2 does not increase (previous sample, line 6"
rej "-0.95 0.31$(printf '%5000s' '')\n$six""0.95 abc\n" "line 7: p 'abc' is not a number"
rej "x p # $(printf '%0700d' 0)\n-0.95 0.31 # $(printf '%09000d' 0)\n$six-0.2 0.9\n" "line 8: x = -0.2 does not increase (previous sample, line 7"
"$cli" solve --help | grep -q "first line may be a header" && ok || ko "--help documents the pressure file"
rm -f "$tmp"
for bad in "--geometry flat-rounded --flat-over-a 1" "--geometry power-law --exponent 0.5" "--geometry samples" "--geometry samples --pressure-file /nonexistent" "--exponent 3" "--geometry samples --digits 20" "--geometry flat-rounded --digits 171" "--geometry power-law --exponent 1 --digits 20" "--geometry flat-rounded --digits 20 --P 1000 --R 0.01 --E-star 1 --f 0.5 --Q 1 --sigma 0" "--exponent 3 --digits 20"; do
  err=$("$cli" solve $bad 2>&1 >/dev/null); rc=$?
  if [ $rc -ne 0 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ]; then ok; else ko "bad geometry input '$bad' (rc=$rc): $err"; fi
done

# reference backend, non-Hertz geometries: certified digits (value checked against the double solve
# 0.89398873667117629), Hertz reproduced by n = 2, table grid over b_f/a with shards
out=$("$cli" solve --digits 30 --geometry flat-rounded --flat-over-a 0.3 --Q-over-fP 0.3 --sigma-over-fp0 0.1) && echo "$out" | grep -q "b1       = 8.93988736671176220572189691154e-01   \[30 digits certified\]" && echo "$out" | grep -q "flat-rounded contact" && ok || ko "solve --digits --geometry flat-rounded"
js=$("$cli" solve --digits 25 --geometry power-law --exponent 2 --json) && echo "$js" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["geometry"] == "power-law" and d["inputs"]["exponent"] == "2" and d["b1_digits"] == 25, d' && echo "$js" | grep -q '"b1": "8.321067811865475244008444e-01"' && ok || ko "solve --digits --geometry power-law n = 2 is Hertz"
full=$("$cli" table --geometry flat-rounded --flat-over-a 0.2:0.3:3 --Q-over-fP 0.3,0.6 --sigma-over-fp0 0,1.5 --digits 20 --no-energy --threads 2) && ok || ko "table flat-rounded"
[ "$(printf '%s\n' "$full" | wc -l)" -eq 14 ] && ok || ko "table flat-rounded rows"
printf '%s\n' "$full" | sed -n 2p | grep -q "^flat_over_a,Q_over_fP,sigma_over_fp0,regime,status,b1,b1_digits" && ok || ko "table flat-rounded header"
printf '%s\n' "$full" | awk -F, 'NR > 2 && ($5 != 0 || $7 != 20 || $13 != 20) { bad = 1 } END { exit bad }' && ok || ko "table flat-rounded: status 0 and 20 certified digits"
printf '%s\n' "$full" | grep -q "^0.8,0.6,1.5,opposite-sign,0," && ok || ko "table flat-rounded: grid over b_f/a"
cat_shards=$( for k in 1 2 3; do "$cli" table --geometry flat-rounded --flat-over-a 0.2:0.3:3 --Q-over-fP 0.3,0.6 --sigma-over-fp0 0,1.5 --digits 20 --no-energy --threads 1 --shard $k/3; done )
[ "$full" = "$cat_shards" ] && ok || ko "flat-rounded shards concatenate to the full table"
jl=$("$cli" table --geometry power-law --exponent 1.5,3 --Q-over-fP 0.4 --sigma-over-fp0 0.5 --digits 15 --format jsonl --no-energy) && echo "$jl" | python3 -c 'import json,sys; r=[json.loads(l) for l in sys.stdin]; assert r[0]["provenance"]["digits"] == 15; r = r[1:]; assert [x["exponent"] for x in r] == ["1.5", "3"] and all(x["b1_digits"] == 15 for x in r), r' && ok || ko "table power-law jsonl"
"$cli" table --geometry power-law --exponent 2,0.5 --Q-over-fP 0.4 --sigma-over-fp0 0.5 >/dev/null 2>&1 && ko "table: bad exponent accepted" || ok
"$cli" table --geometry flat-rounded --Q-over-fP 0.4 --sigma-over-fp0 0.5 --digits 171 >/dev/null 2>&1 && ko "table: digits above the non-Hertz cap accepted" || ok

# asymptotic edge model
js=$("$cli" asymptotic-error --loading shear --b-over-a 0.9 --json) && echo "$js" | python3 -c 'import json,sys; e=json.load(sys.stdin)["fractional_error"]; assert -0.11 < e < -0.08, e' && ok || ko "asymptotic-error shear"
js=$("$cli" asymptotic-error --loading bulk --b-over-a 0.9 --json) && echo "$js" | python3 -c 'import json,sys; e=json.load(sys.stdin)["fractional_error"]; assert 0.06 < e < 0.1, e' && ok || ko "asymptotic-error bulk"
"$cli" asymptotic-error --loading twist --b-over-a 0.9 >/dev/null 2>&1 && ko "bad loading accepted" || ok
"$cli" asymptotic-error --loading shear --b-over-a 1 >/dev/null 2>&1 && ko "b/a = 1 accepted" || ok

# bitwise reproducible run to run (separate processes)
r1=$("$cli" solve --Q-over-fP 0.7 --sigma-over-fp0 3 --points 4 --json); r2=$("$cli" solve --Q-over-fP 0.7 --sigma-over-fp0 3 --points 4 --json)
[ "$r1" = "$r2" ] && ok || ko "run-to-run reproducibility"

# --opt=value, "did you mean", --no-energy, units, progress
a=$("$cli" solve --Q-over-fP=0.3 --sigma-over-fp0=2 --json); b=$("$cli" solve --Q-over-fP 0.3 --sigma-over-fp0 2 --json)
[ -n "$a" ] && [ "$a" = "$b" ] && ok || ko "--opt=value equals --opt value"
err=$("$cli" solve --q-over-fp 0.3 2>&1 >/dev/null); echo "$err" | grep -q "did you mean --Q-over-fP?" && ok || ko "did you mean (case): $err"
err=$("$cli" solve --sigma-over-fpo 1 2>&1 >/dev/null); echo "$err" | grep -q "did you mean --sigma-over-fp0?" && ok || ko "did you mean (typo): $err"
err=$("$cli" table --no-enrgy 2>&1 >/dev/null); echo "$err" | grep -q "did you mean --no-energy?" && ok || ko "did you mean (table): $err"
err=$("$cli" solve --frobnicate 1 2>&1 >/dev/null); echo "$err" | grep -q "did you mean" && ko "suggestion for a far-off flag: $err" || ok
"$cli" solve --json=1 >/dev/null 2>&1 && ko "--json=1 accepted" || ok
js=$("$cli" solve --no-energy --json) && echo "$js" | python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["energy1"] is None and d["energy2"] is None and d["b1"] > 0' && ok || ko "solve --no-energy --json"
out=$("$cli" solve --no-energy) && echo "$out" | grep -q "not computed (--no-energy)" && ok || ko "solve --no-energy report"
out=$("$cli" solve --digits 20 --no-energy) && ! echo "$out" | grep -q energy1 && echo "$out" | grep -q "d2       = " && ok || ko "solve --digits --no-energy"
out=$("$cli" solve --P 1000 --R 0.05 --E-star 1.15e11 --f 0.6 --Q 300 --sigma 2e6) && echo "$out" | grep -q "P = 1000 \[force per unit length\]" && echo "$out" | grep -q "b1 = .* \[length\]" && ok || ko "units in the report"
"$cli" --help | grep -q "forces per unit length" && ok || ko "--help: P and Q per unit length"
err=$("$cli" table --Q-over-fP 0.1 --sigma-over-fp0 0 --digits 15 --no-energy --progress 2>&1 >/dev/null); echo "$err" | grep -q "1/1 rows" && ok || ko "table --progress: $err"
err=$("$cli" table --Q-over-fP 0.1 --sigma-over-fp0 0 --digits 15 --no-energy 2>&1 >/dev/null </dev/null); [ -z "$err" ] && ok || ko "no progress when stderr is not a terminal: $err"

# issue 15: surface stresses in the JSON, --pad-bulk, --fields
# Hertz, same sign, sigma = 0: the peak is 2 f p0 sqrt(Q/fP) at the trailing edge x = -a (docs/fields.md)
js=$("$cli" solve --Q-over-fP 0.36 --sigma-over-fp0 0 --json) && echo "$js" | python3 -c '
import json, sys
d = json.load(sys.stdin)["surface_stress"]
b1, b2 = d["body1"], d["body2"]
assert abs(b1["max"] - 1.2) < 1e-13 and b1["x_max"] == -1.0, b1
# body 2 mirrors body 1 (sigma_xx = -p + H in body 2, -p - H in body 1): its peak is at x = +a
assert abs(b2["max"] - 1.2) < 1e-13 and b2["x_max"] == 1.0 and b1["bulk"] == 0 and b2["bulk"] == 0, b2
assert b1["min"] < -1 and b2["min"] < -1, d' && ok || ko "surface_stress JSON (Hertz peak 2 sqrt(Q/fP))"
# the pad carries 0.25, the specimen sigma + 0.25 = 0.75
js=$("$cli" solve --Q-over-fP 0.36 --sigma-over-fp0 0.5 --pad-bulk 0.25 --json) && echo "$js" | python3 -c '
import json, sys
d = json.load(sys.stdin)["surface_stress"]
assert d["body1"]["bulk"] == 0.75 and d["body2"]["bulk"] == 0.25, d
assert d["body1"]["max"] > 0.75' && ok || ko "--pad-bulk splits sigma"
out=$("$cli" solve --Q-over-fP 0.36 --sigma-over-fp0 0) && echo "$out" | grep -qi "surface" && ok || ko "report shows the surface stress peaks"
dir=$(mktemp -d)
# stuck: McEwen on the axis, sigma_xx = -((1 + 2z^2)/sqrt(1 + z^2) - 2z), sigma_yy = -1/sqrt(1 + z^2)
"$cli" solve --Q-over-fP 0 --sigma-over-fp0 0 --fields "$dir/f.csv" --nu 0.25 >/dev/null && python3 -c '
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2 * 81 * 41, len(rows)
assert list(rows[0].keys()) == "body x y sxx syy sxy max_principal max_shear von_mises".split(), rows[0].keys()
n = 0
for r in rows:
    x, y = float(r["x"]), float(r["y"])
    sxx, syy, sxy = float(r["sxx"]), float(r["syy"]), float(r["sxy"])
    assert (y >= 0) == (r["body"] == "1") or y == 0, r
    if x == 0 and y != 0:
        z = abs(y)
        assert abs(sxx + (1 + 2 * z * z) / math.sqrt(1 + z * z) - 2 * z) < 1e-13, r
        assert abs(syy + 1 / math.sqrt(1 + z * z)) < 1e-13 and abs(sxy) < 1e-13, r
        n += 1
    szz = 0.25 * (sxx + syy)
    vm = math.sqrt(((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) / 2 + 3 * sxy * sxy)
    assert abs(float(r["von_mises"]) - vm) < 1e-13 * (1 + vm), r
    assert abs(float(r["max_shear"]) - math.hypot((sxx - syy) / 2, sxy)) < 1e-13, r
assert n == 80, n' "$dir/f.csv" && ok || ko "--fields CSV (McEwen on the axis, scalars)"
# --fields-at: a point list (header, comments, commas or spaces); y < 0 is the pad
printf 'x y\n0 0.5   # below the centre\n0,-0.5\n0.25 1e-6\n' > "$dir/pts.txt"
"$cli" solve --Q-over-fP 0 --sigma-over-fp0 0 --fields "$dir/p.csv" --fields-at "$dir/pts.txt" >/dev/null && python3 -c '
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [(r["body"], float(r["x"]), float(r["y"])) for r in rows] == [("1", 0, 0.5), ("2", 0, -0.5), ("1", 0.25, 1e-6)], rows
for r in rows[:2]:
    assert abs(float(r["syy"]) + 1 / math.sqrt(1.25)) < 1e-13 and abs(float(r["sxx"]) + 1.5 / math.sqrt(1.25) - 1) < 1e-13, r
assert abs(float(rows[2]["syy"]) + math.sqrt(1 - 0.0625)) < 1e-5, rows[2]' "$dir/p.csv" && ok || ko "--fields-at point list"
printf '0 0.5\n0.1 abc\n' > "$dir/bad.txt"
err=$("$cli" solve --fields "$dir/q.csv" --fields-at "$dir/bad.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "line 2: y 'abc' is not a number" && ok || ko "--fields-at bad line: $err"
err=$("$cli" solve --fields-at "$dir/pts.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "--fields-at needs --fields" && ok || ko "--fields-at without --fields: $err"
# --digits N --fields-at PTS: certified stresses from the reference backend (hs_ref_eval_stress).
# Hertz same sign at 30 digits against the double path's closed forms (--fields CSV, 17 digits):
# the double path is good to ~1e-12 of the peak f p0 = 1 at y = 1e-6 a and ~1e-13 elsewhere
# (docs/fields.md), the bound used here; the reference claims all 30 digits at each point
printf 'x y body\n0.3 0.5\n-0.6, -0.2\n1.3 0\n0.3 0 2\n0.95 1e-6\n-0.2 -0.7\n' > "$dir/rp.txt"
"$cli" solve --Q-over-fP 0.6 --sigma-over-fp0 0.3 --fields "$dir/rd.csv" --fields-at "$dir/rp.txt" >/dev/null &&
"$cli" solve --digits 30 --Q-over-fP 0.6 --sigma-over-fp0 0.3 --no-energy --fields-at "$dir/rp.txt" --json > "$dir/r.json" && python3 -c '
import csv, json, sys
d = json.load(open(sys.argv[2]))
assert d["regime"] == "same-sign" and d["pad_bulk"] == "0", d
rows = list(csv.DictReader(open(sys.argv[1])))
f = d["fields"]
assert [(p["x"], p["y"], p["body"]) for p in f] == [("0.3", "0.5", 1), ("-0.6", "-0.2", 2), ("1.3", "0", 1), ("0.3", "0", 2), ("0.95", "1e-6", 1), ("-0.2", "-0.7", 2)], f
for p, r in zip(f, rows):
    assert int(r["body"]) == p["body"], (p, r)
    for c in ("sxx", "syy", "sxy"):
        assert p[c + "_digits"] == 30 and len(p[c].split("e")[0].replace("-", "").replace(".", "")) == 30, p
        tol = 1e-12 if abs(float(p["y"])) < 1e-4 else 1e-13
        assert abs(float(p[c]) - float(r[c])) <= tol, (c, p, r)' "$dir/rd.csv" "$dir/r.json" && ok || ko "solve --digits --fields-at: Hertz same sign at 30 digits against the double path"
out=$("$cli" solve --digits 30 --Q-over-fP 0.6 --sigma-over-fp0 0.3 --no-energy --fields-at "$dir/rp.txt") && echo "$out" | grep -q "x = 0.3, y = 0, body 2" && [ "$(echo "$out" | grep -c "\[30 digits certified\]")" -eq $((6 + 18)) ] && ok || ko "solve --digits --fields-at: the report"
# --pad-bulk is the exact decimal: 0.1 shifts sxx of both bodies by 0.1 to 30 digits (the double
# nearest 0.1 would be off by 5.6e-18), and nothing else
"$cli" solve --digits 30 --Q-over-fP 0.6 --sigma-over-fp0 0.3 --no-energy --fields-at "$dir/rp.txt" --pad-bulk 0.1 --json > "$dir/rb.json" && python3 -c '
import json, sys
from decimal import Decimal
a, b = (json.load(open(f))["fields"] for f in sys.argv[1:3])
for p, q in zip(a, b):
    # each value is rounded to 30 digits (values below 1.3: 1e-30 each)
    assert abs(Decimal(q["sxx"]) - Decimal(p["sxx"]) - Decimal("0.1")) <= Decimal("4e-30"), (p, q)
    assert q["syy"] == p["syy"] and q["sxy"] == p["sxy"], (p, q)
assert json.load(open(sys.argv[2]))["pad_bulk"] == "0.1"' "$dir/r.json" "$dir/rb.json" && ok || ko "solve --digits --pad-bulk exact decimal"
# bad input: a bad point line, y on the wrong side of the body named, a bad body, --pad-bulk, and the
# options the reference path does not take
printf '0.3 0.5\n0.1 abc\n' > "$dir/rbad.txt"
err=$("$cli" solve --digits 20 --fields-at "$dir/rbad.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "rbad.txt: line 2: y 'abc' is not a number" && ok || ko "--digits --fields-at bad line: $err"
printf '0.3 0.5\n# the pad\n0.3 0.5 2\n' > "$dir/rside.txt"
err=$("$cli" solve --digits 20 --fields-at "$dir/rside.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "line 3: y = 0.5 is not in body 2 (the pad, y <= 0)" && ok || ko "--digits --fields-at y on the wrong side: $err"
err=$("$cli" solve --fields "$dir/q.csv" --fields-at "$dir/rside.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "line 3: y = 0.5 is not in body 2 (the pad, y <= 0)" && ok || ko "--fields-at y on the wrong side (double): $err"
printf '0.3 0.5 3\n' > "$dir/rbody.txt"
err=$("$cli" solve --digits 20 --fields-at "$dir/rbody.txt" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "line 1: body '3' is not 1 (specimen) or 2 (pad)" && ok || ko "--fields-at bad body: $err"
err=$("$cli" solve --digits 20 --fields-at "$dir/rp.txt" --pad-bulk 0.1x 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "bad value for --pad-bulk: '0.1x'" && ok || ko "--digits --pad-bulk bad: $err"
for bad in "--fields $dir/x.csv" "--pad-bulk 1" "--nu 0.3 --fields-at $dir/rp.txt" "--points 5"; do
  err=$("$cli" solve --digits 20 $bad 2>&1 >/dev/null); rc=$?
  opt=$(echo "$bad" | cut -d' ' -f1)
  if [ $rc -ne 0 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q -- "$opt"; then ok; else ko "--digits $bad (rc=$rc): $err"; fi
done
# the flat punch grid (6,642 points) is quick now (it took 1.7 s before the cached panels)
"$cli" solve --geometry flat-rounded --Q-over-fP 0.4 --sigma-over-fp0 2 --fields "$dir/g.csv" >/dev/null && [ "$(wc -l < "$dir/g.csv")" -eq 6643 ] && ok || ko "--fields flat punch"
err=$("$cli" solve --fields /nonexistent/dir/f.csv 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "/nonexistent/dir/f.csv" && ok || ko "--fields unwritable: $err"
err=$("$cli" solve --fields "$dir/h.csv" --nu 0.7 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "--nu 0.7" && ok || ko "--nu 0.7 rejected, named: $err"

# issue 15: stresses of a history state. Unloading 0.6 -> 0.2 (Hertz, sigma = 0): by Ciavarella-Jager the
# state is S(0.6) - 2 S(0.2) + 2 S(0) of monotonic solutions (closed forms); the march is good to ~1e-8
"$cli" history --path "0.6,0;0.2,0" --fields "$dir/hs.csv" --fields-at "$dir/pts.txt" >/dev/null &&
for qq in 0.6 0.2 0; do "$cli" solve --Q-over-fP $qq --sigma-over-fp0 0 --fields "$dir/m$qq.csv" --fields-at "$dir/pts.txt" >/dev/null; done &&
python3 -c '
import csv, sys
r = [list(csv.DictReader(open(f))) for f in sys.argv[1:]]
assert len(r[0]) == len(r[1]) > 0
for s, a, b, c in zip(*r):
    for k in ("sxx", "syy", "sxy"):
        ref = float(a[k]) - 2 * float(b[k]) + 2 * float(c[k])
        assert abs(float(s[k]) - ref) < 1e-6, (s, k, ref)' "$dir/hs.csv" "$dir/m0.6.csv" "$dir/m0.2.csv" "$dir/m0.csv" && ok || ko "history --fields (Ciavarella-Jager)"
"$cli" history --path "0.6,0;0.2,0" --fields "$dir/h1.csv" --fields-vertex 1 >/dev/null &&
  "$cli" solve --Q-over-fP 0.6 --sigma-over-fp0 0 --fields "$dir/m1.csv" >/dev/null && python3 -c '
import csv, sys
a, b = [list(csv.DictReader(open(f))) for f in sys.argv[1:]]
assert len(a) == len(b) == 6642
assert max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b) for k in ("sxx", "syy", "sxy")) < 1e-6' "$dir/h1.csv" "$dir/m1.csv" && ok || ko "history --fields-vertex 1 = the monotonic solution"
js=$("$cli" history --path "0.6,0;0.2,0" --surface-stress --json) && echo "$js" | python3 -c '
import json, sys, math
v = json.load(sys.stdin)["vertices"]
assert abs(v[0]["surface_stress"]["body1"]["max"] - 2 * math.sqrt(0.6)) < 1e-6, v[0]
assert "surface_stress" in v[1]' && ok || ko "history --surface-stress (peak 2 f p0 sqrt(Q/fP) at the first vertex)"
"$cli" history --path "0.6,0" --json | grep -q surface_stress && ko "surface_stress without --surface-stress" || ok
# issue 14: a path along one ray is solved by superposition (exact), one off it by the march
js=$("$cli" history --path "0.6,0;0.2,0" --json) && echo "$js" | python3 -c '
import json, math, sys
d = json.load(sys.stdin)
assert d["method"] == "superposition", d["method"]
v = d["vertices"]
assert abs(v[1]["b1"] - math.sqrt(1 - 0.4 / 2)) <= 4 * 2.0 ** -52, v[1]["b1"]
assert v[1]["steps"] == 0 and v[1]["slip_dir1"] == -1' && ok || ko "history along one ray: superposition"
"$cli" history --path "0.6,0;0.2,0.3" --json | grep -q '"method": "static"' && ok || ko "history off the ray, advancing: static solves"
"$cli" history --path "0.5,0;0.1,-1" --json | grep -q '"method": "static"' && ok || ko "history with a receding end: static solves"
"$cli" history --path "0,1.5;0.15,1.5;0.25,1.2" --json | python3 -c '
import json, sys
d = json.load(sys.stdin)
v = d["vertices"][2]
assert d["method"] == "static" and v["patch_dir"] == 1 and abs(v["patch_l"] + 0.7393878) < 1e-6, d
assert abs(v["patch_r"] + 0.5778934) < 1e-6 and v["energy_patch"] > 0.9 * (v["energy2"] + v["energy_patch"]), v
assert d["vertices"][1]["patch_dir"] == 0 and d["vertices"][1]["patch_l"] is None, d' && ok || ko "history with an interior slip zone: static solves, the patch reported"
"$cli" history --path "0,1.5;0.15,1.5;0.25,1.2" | grep -q "interior slip zone: (-0.73938779, -0.57789343) a, direction +1" && ok || ko "history table: the interior slip zone"
# random walk 48 (reference/random_walk.hpp): the static solves refuse vertex 11 (a fold), the march
# meets an interior slip zone there and merges it on request
"$cli" history --interior-patches merge --path "-0.022054871333472635,0;0.036078176878091284,0;0.17507763547550786,0;0.16894801212188992,0.07411374159489148;0.15453673879434301,0.11950642516403584;0.26712308630484416,0.18952721538580361;0.21590923984054916,0.26918192221866188;0.21546317188940226,0.37639511094461003;0.34453733462337949,0.42186435559245761;0.34904128632381598,0.40758301733070301;0.39875311869061375,0.30637183947290847" --json | grep -q '"method": "march"' && ok || ko "history the static solves refuse (a fold; an interior slip zone merged): march"
js=$("$cli" history --digits 30 --path "0.6,0;0.2,0" --json) && echo "$js" | python3 -c '
import json, sys
from decimal import Decimal, getcontext
getcontext().prec = 40
d = json.load(sys.stdin)
v = d["vertices"][1]
c = (1 - Decimal("0.4") / 2).sqrt()
assert abs(Decimal(v["b1"]) - c) < Decimal("1e-29") and v["b1_digits"] == 30, v
assert v["energy1_digits"] >= 28 and v["slip_dir1"] == -1, v' && ok || ko "history --digits (certified, along one ray)"
err=$("$cli" history --digits 30 --path "0.6,0;0.2,0.3" 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q "vertex 2" && echo "$err" | grep -q "one ray" && ok || ko "history --digits off the ray: $err"
err=$("$cli" history --digits 30 --cycle 0,0.3,0,0,0 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "--cycle" && ok || ko "history --digits --cycle: $err"
err=$("$cli" history --path "0.6,0" --fields "$dir/x.csv" --fields-vertex 2 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "--fields-vertex" && ok || ko "history --fields-vertex out of range: $err"
err=$("$cli" history --path "0.6,0" --fields-vertex 1 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "needs --fields" && ok || ko "history --fields-vertex without --fields: $err"
err=$("$cli" solve --pad-bulk nan 2>&1 >/dev/null); rc=$?
[ $rc -ne 0 ] && echo "$err" | grep -q -- "--pad-bulk" && ok || ko "--pad-bulk nan rejected, named: $err"
rm -rf "$dir"

echo "cli: $pass passed, $fail failed"
[ $fail -eq 0 ]
