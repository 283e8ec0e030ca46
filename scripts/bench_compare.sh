#!/usr/bin/env bash
# Same table, same run: the per-call cost of the C ABI (bench/bench_capi.cpp, Google
# Benchmark) for a base revision and for the working tree, built alike and run
# alternately on this machine, so that load affects both the same way.
#
#   bash scripts/bench_compare.sh [BASE_REV]     (default: HEAD)
#
# Writes bench/results/compare.csv (benchmark, base and new median ns, new/base) and
# prints the same as a Markdown table. Both libraries are built Release with the
# precision ladder HALFSLIP_REF_TIERS (default "50;80": the 50-digit reference row
# certifies with the 80-digit tier in both) and nothing else (no tests, no benchmarks).
set -euo pipefail
base_rev="${1:-HEAD}"
HS_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tiers="${HALFSLIP_REF_TIERS:-50;80}"
rounds="${HS_COMPARE_ROUNDS:-2}"
work="${HS_COMPARE_DIR:-$HS_ROOT/build-compare}"
export HS_EXTRA_PACKAGES="libbenchmark-dev"
# installs missing Debian packages only (the build below is our own)
HS_BUILD="$work/new" HS_SKIP_BUILD=1 source "$HS_ROOT/scripts/setup.sh"

sha=$(git -C "$HS_ROOT" rev-parse --verify "$base_rev^{commit}")
mkdir -p "$work/base-src"
if [ "$(cat "$work/base-src/.rev" 2>/dev/null)" != "$sha" ]; then
  rm -rf "$work/base-src" "$work/base" && mkdir -p "$work/base-src"
  git -C "$HS_ROOT" archive "$sha" | tar -x -C "$work/base-src"
  echo "$sha" > "$work/base-src/.rev"
fi

build_lib() {  # source dir, build dir
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DHALFSLIP_BUILD_TESTS=OFF -DHALFSLIP_BUILD_BENCH=OFF \
    -DHALFSLIP_BUILD_FORTRAN=OFF "-DHALFSLIP_REF_TIERS=$tiers" >/dev/null
  cmake --build "$2" -j "$(nproc)" --target halfslip
  g++ -O2 -std=c++17 -I"$1/capi/include" "$HS_ROOT/bench/bench_capi.cpp" -o "$2/bench_capi" \
    -L"$2" -lhalfslip -lbenchmark -lpthread -Wl,-rpath,"$2"
}
build_lib "$work/base-src" "$work/base"
build_lib "$HS_ROOT" "$work/new"

flags=(--benchmark_repetitions=3 --benchmark_min_time=0.2 --benchmark_format=json)
for r in $(seq 1 "$rounds"); do
  for which in base new; do
    echo "round $r: $which" >&2
    "$work/$which/bench_capi" "${flags[@]}" > "$work/$which.$r.json"
  done
done

python3 - "$work" "$rounds" "$HS_ROOT/bench/results/compare.csv" "$sha" <<'PY'
import json, statistics, sys
work, rounds, out, sha = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def medians(which):
    t = {}
    for r in range(1, rounds + 1):
        for b in json.load(open(f"{work}/{which}.{r}.json"))["benchmarks"]:
            if b.get("run_type") != "iteration" or b.get("error_occurred"):
                continue
            scale = {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
            t.setdefault(b["run_name"], []).append(b["real_time"] * scale)
    return {k: statistics.median(v) for k, v in t.items()}
base, new = medians("base"), medians("new")
names = [n for n in new if n in base] + [n for n in new if n not in base]
fmt = lambda ns: f"{ns/1e6:.3f} ms" if ns >= 1e6 else f"{ns/1e3:.3f} us" if ns >= 1e3 else f"{ns:.1f} ns"
with open(out, "w") as f:
    f.write("benchmark,base_ns,new_ns,new_over_base\n")
    print(f"base {sha[:10]} against the working tree, median of {rounds} rounds x 3 repetitions each\n")
    print("| benchmark | base | new | new/base |\n|---|---|---|---|")
    for n in names:
        b, w = base.get(n), new[n]
        ratio = f"{w/b:.2f}" if b else "n/a"
        f.write(f"{n},{b if b else ''},{w},{ratio}\n")
        print(f"| {n} | {fmt(b) if b else 'n/a'} | {fmt(w)} | {ratio} |")
PY
