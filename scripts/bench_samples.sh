#!/usr/bin/env bash
# Sampled pressure against the sample count (issue 13 item 4): wall time and peak
# memory (/usr/bin/time -v, one process per n) for n = 10^3 .. 10^6 of
#   - build/bench/bench_samples (C ABI: setup and solve, zone energies, the two
#     surface-stress extremes; Hertz samples against the closed forms, and smooth
#     and noisy samples), into bench/results/samples.csv, and
#   - `halfslip solve --geometry samples --pressure-file F --json` on a file of
#     n + 1 Hertz samples (parsing, checks, solve, energies, surface stresses),
#     into bench/results/samples_cli.csv, and
#   - `halfslip history --geometry samples --pressure-file F --path "0.3,0.5;0.1,0.2"`
#     (a ray vertex, then one off it: the static solves) for n = 125 .. 2000
#     (HS_SAMPLES_HISTORY_N), into bench/results/samples_history.csv: its cost grows
#     like n^2 (README, Known limits).
# HS_SAMPLES_SECTIONS (default "bench cli history") picks the sections to run.
# Run by scripts/bench.sh after its build; alone it builds first (HS_BENCH=ON).
# Quote the numbers with the machine load they were measured under (uptime is
# recorded in the CSV comments).
set -euo pipefail
if [ -z "${HS_BUILD:-}" ] || [ ! -x "${HS_BUILD}/bench/bench_samples" ]; then
  export HS_BENCH=ON
  export HS_EXTRA_PACKAGES="${HS_EXTRA_PACKAGES:-} time"
  source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
fi
HS_ROOT="${HS_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
HS_BUILD="${HS_BUILD:-$HS_ROOT/build}"
out="$HS_ROOT/bench/results"
mkdir -p "$out"
ns="${HS_SAMPLES_N:-1000 10000 100000 1000000}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

rss() { sed -n 's/^\s*Maximum resident set size (kbytes): //p' "$1"; }
sections="${HS_SAMPLES_SECTIONS:-bench cli history}"
want() { case " $sections " in *" $1 "*) return 0 ;; esac; return 1; }
hertz_file() {  # n + 1 Hertz samples, equally spaced, into $2
  python3 - "$1" "$2" <<'EOF'
import math, sys
n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for i in range(n + 1):
        x = 1.0 if i == n else -1.0 + 2.0 * i / n
        p = 0.0 if i in (0, n) else math.sqrt((1 - x) * (1 + x))
        f.write("%r %r\n" % (x, p))
EOF
}

want bench && {
  echo "# bench_samples, Q/fP = 0.3, sigma/fp0 = 1; $(date -u +%F) on $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "kind,n,solve_s,energy_s,surface_s,total_s,d1,d2,energy1,energy2,max_rel_diff_vs_hertz,max_rss_kb"
  for kind in hertz smooth noisy; do
    for n in $ns; do
      line=$(/usr/bin/time -v -o "$tmp/time" "$HS_BUILD/bench/bench_samples" --kind "$kind" --no-header "$n")
      echo "$line,$(rss "$tmp/time")"
    done
  done
} | tee "$out/samples.csv"

want cli && {
  echo "# halfslip solve --geometry samples --pressure-file F --Q-over-fP 0.3 --sigma-over-fp0 1 --json, Hertz samples; $(date -u +%F), load: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "n,file_bytes,wall_s,max_rss_kb,d1,energy2"
  for n in $ns; do
    hertz_file "$n" "$tmp/p.txt"
    /usr/bin/time -v -o "$tmp/time" "$HS_BUILD/halfslip" solve --geometry samples --pressure-file "$tmp/p.txt" \
      --Q-over-fP 0.3 --sigma-over-fp0 1 --json > "$tmp/out.json"
    wall=$(sed -n 's/^\s*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$tmp/time" | awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }')
    vals=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print("%r,%r" % (d["d1"], d["energy2"]))' "$tmp/out.json")
    echo "$n,$(stat -c %s "$tmp/p.txt"),$wall,$(rss "$tmp/time"),$vals"
  done
} | tee "$out/samples_cli.csv"

want history && {
  echo "# halfslip history --geometry samples --pressure-file F --path \"0.3,0.5;0.1,0.2\" --json, Hertz samples; $(date -u +%F), load: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "n,user_s,wall_s,max_rss_kb,method,b1_last"
  for n in ${HS_SAMPLES_HISTORY_N:-125 250 500 1000 2000}; do
    hertz_file "$n" "$tmp/p.txt"
    /usr/bin/time -v -o "$tmp/time" "$HS_BUILD/halfslip" history --geometry samples --pressure-file "$tmp/p.txt" \
      --path "0.3,0.5;0.1,0.2" --json > "$tmp/out.json"
    user=$(sed -n 's/^\s*User time (seconds): //p' "$tmp/time")
    wall=$(sed -n 's/^\s*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$tmp/time" | awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }')
    vals=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print("%s,%r" % (d["method"], d["vertices"][-1]["b1"]))' "$tmp/out.json")
    echo "$n,$user,$wall,$(rss "$tmp/time"),$vals"
  done
} | tee "$out/samples_history.csv"
