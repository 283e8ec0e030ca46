#!/usr/bin/env bash
# Long libFuzzer run of every target in tests/fuzz/ (issue 13; not run by CI, whose
# short smoke run is stage 4 of scripts/reliability.sh). Rounds of HS_FUZZ_ROUND_SECONDS
# per target, one target at a time, niced, until the executions of all targets add up to
# HS_FUZZ_TOTAL (default 10^7) or HS_FUZZ_MAX_SECONDS have passed (default 8 h); the
# working corpora live in build-fuzz/long-corpus/<target> (seeded from tests/fuzz/corpus,
# kept between rounds and runs). Prints the executions per target and in total.
# A failing input stops that target for the run and is written to tests/fuzz/crashes/
# (a timeout: an input slower than HS_FUZZ_TIMEOUT seconds under the sanitizers);
# copy it into tests/fuzz/corpus/<target>/ once the defect is fixed.
#   bash scripts/fuzz_long.sh                      # 10^7 executions
#   HS_FUZZ_TOTAL=1000000 HS_FUZZ_ROUND_SECONDS=60 bash scripts/fuzz_long.sh
#   HS_FUZZ_TARGETS="solve callback" bash scripts/fuzz_long.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
total_goal="${HS_FUZZ_TOTAL:-10000000}"
round="${HS_FUZZ_ROUND_SECONDS:-300}"
max_seconds="${HS_FUZZ_MAX_SECONDS:-28800}"
timeout_s="${HS_FUZZ_TIMEOUT:-120}"
read -r -a targets <<< "${HS_FUZZ_TARGETS:-solve ref samples pressure_file history callback dimensional asymptotic ref_fields cli_args}"

command -v clang++ >/dev/null || { echo "fuzz_long: needs clang (bash scripts/reliability.sh installs it)" >&2; exit 1; }
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHALFSLIP_BUILD_BENCH=OFF "-DHALFSLIP_REF_TIERS=50;80;120" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DHALFSLIP_FUZZ=ON -DHALFSLIP_BUILD_TESTS=OFF \
  -DHALFSLIP_BUILD_CLI=OFF -DHALFSLIP_SANITIZE=address,undefined >/dev/null
nice cmake --build build-fuzz -j "${HS_JOBS:-2}" --target "${targets[@]/#/fuzz_}" >/dev/null

mkdir -p tests/fuzz/crashes build-fuzz/long-corpus
declare -A execs failed
for t in "${targets[@]}"; do
  execs[$t]=0
  failed[$t]=""
  mkdir -p "build-fuzz/long-corpus/$t"
  cp -n tests/fuzz/corpus/$t/* "build-fuzz/long-corpus/$t/"
done

start=$(date +%s)
sum=0
n_round=0
while [ "$sum" -lt "$total_goal" ] && [ $(($(date +%s) - start)) -lt "$max_seconds" ]; do
  n_round=$((n_round + 1))
  active=0
  for t in "${targets[@]}"; do
    [ -n "${failed[$t]}" ] && continue
    active=1
    log="build-fuzz/long-corpus/$t.log"
    if ! nice -n 19 "build-fuzz/tests/fuzz/fuzz_$t" "build-fuzz/long-corpus/$t" -seed=0 -max_total_time="$round" \
        -max_len=512 -timeout="$timeout_s" -rss_limit_mb=4096 \
        -artifact_prefix="tests/fuzz/crashes/$t-" -print_final_stats=1 >"$log" 2>&1; then
      failed[$t]="$(grep -o "Test unit written to [^ ]*" "$log" | tail -1 | sed 's/Test unit written to //')"
      [ -n "${failed[$t]}" ] || failed[$t]="(see $log)"
      echo "fuzz_$t: failing input ${failed[$t]}"
      grep -E "broken:|ERROR: libFuzzer|SUMMARY" "$log" | head -3 | sed "s/^/  /"
    fi
    n=$(grep -E "stat::number_of_executed_units" "$log" | awk '{print $2}' | tail -1)
    execs[$t]=$((execs[$t] + ${n:-0}))
    sum=$((sum + ${n:-0}))
    echo "round $n_round fuzz_$t: +${n:-0} executions (total $sum)"
    [ "$sum" -ge "$total_goal" ] && break
  done
  [ "$active" -eq 1 ] || break
done

echo "== fuzz_long: executions per target ($(($(date +%s) - start)) s, $n_round rounds of ${round} s per target)"
for t in "${targets[@]}"; do
  printf "  fuzz_%-14s %12d%s\n" "$t" "${execs[$t]}" "${failed[$t]:+  FAILED: ${failed[$t]}}"
done
printf "  %-19s %12d\n" "total" "$sum"
for t in "${targets[@]}"; do [ -z "${failed[$t]}" ] || exit 1; done
