#!/usr/bin/env bash
# Reliability stage of the test suite (issue 7), run by scripts/test.sh:
#   1. ThreadSanitizer on the thread-safety suite (tests/test_threads.cpp)
#   2. valgrind memcheck on the C ABI test program
#   3. one clang build with AddressSanitizer + UndefinedBehaviorSanitizer (every check) and
#      libFuzzer's coverage instrumentation of the library itself, which serves
#      a. the C test program (test_capi, against the static library) and every fuzz corpus input
#         run once, and
#      b. a bounded libFuzzer run of every target in tests/fuzz/: the double and the reference
#         C ABI, sampled and callback pressures, load histories, the dimensional entry points,
#         the asymptotic model, the reference field evaluations, and the CLI's pressure-file
#         parser and argument parsing (issue 13; the long run is scripts/fuzz_long.sh)
#   HALFSLIP_RELIABILITY=full adds (first) the whole ctest suite built with gcc's ASan + UBSan:
#   about 16 min on the project's 2-core machine, which CI's budget (the whole test command well
#   under 20 min) cannot carry; run it before a release and after changes to memory handling.
# Sanitizer and fuzz builds use a short precision ladder (HALFSLIP_REF_TIERS)
# to keep build time down. HS_FUZZ_SECONDS sets the time per fuzz target (default 6 s: a
# smoke run, the seeds and crash inputs first).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh" >/dev/null
hs_packages=(clang libclang-rt-14-dev valgrind)
hs_install_missing
cd "$HS_ROOT"
SECONDS=0
short_tiers="50;80;120"
jobs="$(nproc)"
# -O1 -g1 (line tables, enough for the sanitizers' stack traces): one tier of the reference backend
# compiles in 29 s with ASan against 68 s at -O2 -g (gcc 12, 2026-12-07).
opt="-O1 -g1 -DNDEBUG"
common=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$opt" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$opt"
        "-DCMAKE_Fortran_FLAGS_RELWITHDEBINFO=$opt" -DHALFSLIP_BUILD_BENCH=OFF "-DHALFSLIP_REF_TIERS=$short_tiers")
sanitizer_env=(ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1)
stage_time() { echo "   ($1: $SECONDS s since the reliability stage began)"; }

if [ "${HALFSLIP_RELIABILITY:-}" = full ]; then
  # gcc's UBSan checks "alignment" and "null" on every pointer use of the inlined MPFR and Eigen
  # templates: with them a tier compiles in 112 s, without them in 33 s. A null dereference is
  # still caught (by ASan, as a SEGV), and the clang build (stage 3) keeps every UBSan check.
  echo "== reliability (full): gcc ASan + UBSan, whole test suite (cases marked HS_LONG skipped: tests/testing.hpp)"
  cmake -S . -B build-asan "${common[@]}" -DHALFSLIP_SANITIZE_EXCLUDE=alignment,null \
    -DHALFSLIP_SANITIZE=address,undefined >/dev/null
  cmake --build build-asan -j "$jobs" >/dev/null
  (cd build-asan && env "${sanitizer_env[@]}" ctest --output-on-failure -j "$jobs" -E exported_symbols)
  stage_time "whole suite under ASan + UBSan"
fi

echo "== reliability 1/3: ThreadSanitizer, the thread-safety suite"
cmake -S . -B build-tsan "${common[@]}" -DHALFSLIP_SANITIZE=thread -DHALFSLIP_BUILD_CLI=OFF >/dev/null
cmake --build build-tsan -j "$jobs" --target test_threads >/dev/null
TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/test_threads
stage_time "stage 1"

echo "== reliability 2/3: valgrind memcheck, C ABI test"
valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite \
  "$HS_BUILD/tests/test_capi"
stage_time "stage 2"

fuzz_targets=(solve ref samples pressure_file history callback dimensional asymptotic ref_fields cli_args)
echo "== reliability 3/3: clang ASan + UBSan: the C test program, the fuzz corpora, then libFuzzer ${HS_FUZZ_SECONDS:-6} s per target"
# (the Fortran module is left out: gfortran takes neither clang's sanitizer runtime nor
# -fsanitize=fuzzer-no-link; the release ctest and valgrind cover it)
cmake -S . -B build-fuzz "${common[@]}" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DHALFSLIP_FUZZ=ON \
  -DHALFSLIP_BUILD_TESTS=ON -DHALFSLIP_BUILD_CLI=OFF -DHALFSLIP_BUILD_FORTRAN=OFF \
  -DHALFSLIP_SANITIZE=address,undefined >/dev/null
cmake --build build-fuzz -j "$jobs" --target "${fuzz_targets[@]/#/fuzz_}" test_capi >/dev/null
stage_time "clang sanitizer build"
(cd build-fuzz && env "${sanitizer_env[@]}" ctest --output-on-failure -R '^capi$')
# every corpus input once (slow-* included), by the fuzz targets themselves (a file argument runs
# that input once), two targets at a time
printf '%s\n' "${fuzz_targets[@]}" | xargs -P "$jobs" -I{} sh -c \
  'build-fuzz/tests/fuzz/fuzz_{} -timeout=300 tests/fuzz/corpus/{}/* >build-fuzz/replay_{}.log 2>&1 ||
   { tail -40 build-fuzz/replay_{}.log; echo "fuzz_{}: a corpus input fails under the sanitizers"; exit 255; }'
stage_time "C ABI suites and corpora"
mkdir -p tests/fuzz/crashes
for t in "${fuzz_targets[@]}"; do
  work="$(mktemp -d)"
  # slow-* inputs (valid, but seconds under the sanitizers) are replayed by ctest only
  find tests/fuzz/corpus/$t -maxdepth 1 -type f ! -name 'slow-*' -exec cp {} "$work/" \;
  # crash inputs are written to tests/fuzz/crashes/: copy them into corpus/$t to keep them as regression tests
  log="$(mktemp)"
  # a fixed seed keeps CI reproducible (HS_FUZZ_SEED=0 lets libFuzzer pick one, for longer local hunts)
  if ! build-fuzz/tests/fuzz/fuzz_$t "$work" -seed="${HS_FUZZ_SEED:-1}" -max_total_time="${HS_FUZZ_SECONDS:-6}" -max_len=256 -timeout=20 \
      -rss_limit_mb=4096 -artifact_prefix=tests/fuzz/crashes/$t- -print_final_stats=1 >"$log" 2>&1; then
    tail -40 "$log"
    echo "fuzz_$t found a failing input in tests/fuzz/crashes/ (add it to tests/fuzz/corpus/$t/)"
    exit 1
  fi
  grep -E "stat::number_of_executed_units|stat::new_units_added" "$log" | sed "s/^/fuzz_$t: /"
  rm -rf "$work" "$log"
done
echo "reliability: all stages passed in $SECONDS s"
