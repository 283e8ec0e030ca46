// Issue 16 (Google Benchmark): the Hertz opposite-sign solve (stored start and
// hand-off, core/hertz_opposite.hpp) against the starts it replaces
// (solve_opposite_legacy) and against one std::comp_ellint_1 call, the
// baseline of the targets; the slip at a point and the zone energies,
// fixed Gauss rules in tau (the library) against the adaptive tanh-sinh path
// they replace (hertz_solution::hhat_tanh_sinh / energy_hat_tanh_sinh, kept
// callable), and for the slip the same rules without the per-solution table
// (hhat_untabulated) and the table's one-time set-up; and hs_solve_batch
// against one hs_solve + summary per scene, on the same scenes in the same run.
//   build/bench/bench_opposite --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//       --benchmark_out=bench/results/opposite.csv --benchmark_out_format=csv
#include <benchmark/benchmark.h>
#include <halfslip/halfslip.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "halfslip/core/hertz.hpp"

namespace core = hs::core;

namespace {

// the scene of bench_capi's hertz_opposite row, and a large-sigma one (stick
// width ~ 1e-41: the tau interval is long)
core::hertz_solution<double> solution(double q, double s) {
  core::hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  return core::solve_hertz(sc);
}

// one complete elliptic integral of the first kind (C++17 special math), the
// issue's unit; the modulus varies over the loop as in a solve
void bm_comp_ellint_1(benchmark::State &state) {
  double k = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(std::comp_ellint_1(k));
    k = k < 0.9 ? k + 0.0137 : 0.1;
  }
}

// the canonical solve: q, s as hertz_solution's canonical frame
void bm_solve(benchmark::State &state, double q, double s, bool legacy) {
  for (auto _ : state) {
    const auto r = legacy ? core::solve_opposite_legacy<double>(q, s, 100) : core::solve_opposite<double>(q, s, 100);
    benchmark::DoNotOptimize(r.delta1);
  }
}

// path 0: adaptive tanh-sinh (before issue 16); 1: the library (the fixed
// rules, reading the per-solution table where the zone has one; the table is
// built by the first call, before the timed loop); 2: the same fixed rules
// without the table (the library before session 13)
void bm_slip(benchmark::State &state, double q, double s, int path) {
  const auto sol = solution(q, s);
  const double dl = 0.5 * sol.delta1;  // middle of zone 1, as bench_capi
  benchmark::DoNotOptimize(sol.hhat(1, dl));
  for (auto _ : state) {
    const double h = path == 0 ? sol.hhat_tanh_sinh(1, dl) : path == 1 ? sol.hhat(1, dl) : sol.hhat_untabulated(1, dl);
    benchmark::DoNotOptimize(h);
  }
}

// the one-time set-up of a zone's slip table (what the first slip of a
// solution adds), to set beside the solve
void bm_slip_table(benchmark::State &state, double q, double s) {
  const auto sol = solution(q, s);
  const auto st = sol.zone_state(1);
  for (auto _ : state) {
    const core::opposite_zone_integrals<double> z(st, true);
    benchmark::DoNotOptimize(z.tabulated());
  }
}

void bm_energy(benchmark::State &state, double q, double s, bool old) {
  const auto sol = solution(q, s);
  for (auto _ : state) {
    const double e = old ? sol.energy_hat_tanh_sinh(1) + sol.energy_hat_tanh_sinh(-1)
                         : sol.energy_hat(1) + sol.energy_hat(-1);
    benchmark::DoNotOptimize(e);
  }
}

// 10^6 mixed-regime scenes (same sign, opposite sign, both signs of Q and sigma)
std::vector<hs_scene> batch_scenes(size_t n) {
  std::vector<hs_scene> v(n);
  for (size_t i = 0; i < n; ++i) {
    hs_scene_default(&v[i]);
    v[i].Q_over_fP = -0.95 + 1.9 * double((i * 7919) % 1000) / 999.0;
    v[i].sigma_over_fp0 = -5 + 10 * double((i * 104729) % 1001) / 1000.0;
  }
  return v;
}

void bm_batch(benchmark::State &state, int threads) {
  const size_t n = size_t(state.range(0));
  const auto sc = batch_scenes(n);
  std::vector<hs_batch_result> out(n);
  for (auto _ : state) {
    if (hs_solve_batch(n, sc.data(), nullptr, 0, threads, out.data(), sizeof(hs_batch_result)) != HS_OK)
      state.SkipWithError("batch failed");
    benchmark::DoNotOptimize(out.data());
  }
}

// the alternative: one hs_solve + hs_solution_summary per scene, one thread
void bm_loop(benchmark::State &state) {
  const size_t n = size_t(state.range(0));
  const auto sc = batch_scenes(n);
  std::vector<hs_summary> out(n);
  for (auto _ : state) {
    for (size_t i = 0; i < n; ++i) {
      hs_solution *s = nullptr;
      if (hs_solve(&sc[i], nullptr, &s) == HS_OK) {
        out[i].struct_size = sizeof(hs_summary);
        hs_solution_summary(s, &out[i]);
      }
      hs_solution_free(s);
    }
    benchmark::DoNotOptimize(out.data());
  }
}

}  // namespace

int main(int argc, char **argv) {
  struct sc {
    const char *name;
    double q, s;
  };
  benchmark::RegisterBenchmark("baseline/std::comp_ellint_1", bm_comp_ellint_1);
  // the opposite-sign solve: the scenes below, one 1e-9 past the regime
  // boundary (d1 ~ 1e-10 a) and one near sliding
  const double sb95 = 4 * 0.95 / (1 + std::sqrt(0.05));
  for (const sc c : {sc{"q0.3_s2", 0.3, 2.0}, sc{"q0.3_s60", 0.3, 60.0}, sc{"q0.95_s5", 0.95, 5.0},
                     sc{"q0.95_boundary+1e-9", 0.95, sb95 + 1e-9}})
    for (bool legacy : {false, true})
      benchmark::RegisterBenchmark(
          (std::string("solve_opposite/") + (legacy ? "legacy-start/" : "stored-start/") + c.name).c_str(),
          [c, legacy](benchmark::State &st) { bm_solve(st, c.q, c.s, legacy); });
  for (const sc c : {sc{"q0.3_s2", 0.3, 2.0}, sc{"q0.3_s60", 0.3, 60.0}}) {
    for (bool old : {true, false}) {
      const std::string tag = std::string(old ? "tanh-sinh/" : "gauss-tau/") + c.name;
      benchmark::RegisterBenchmark(("slip_point/" + tag).c_str(),
                                   [c, old](benchmark::State &st) { bm_slip(st, c.q, c.s, old ? 0 : 1); });
      benchmark::RegisterBenchmark(("energies/" + tag).c_str(),
                                   [c, old](benchmark::State &st) { bm_energy(st, c.q, c.s, old); });
    }
    benchmark::RegisterBenchmark((std::string("slip_point/gauss-tau-untabulated/") + c.name).c_str(),
                                 [c](benchmark::State &st) { bm_slip(st, c.q, c.s, 2); });
    benchmark::RegisterBenchmark((std::string("slip_table_setup/") + c.name).c_str(),
                                 [c](benchmark::State &st) { bm_slip_table(st, c.q, c.s); });
  }
  for (int t : {1, 2})
    benchmark::RegisterBenchmark(("batch/threads:" + std::to_string(t)).c_str(),
                                 [t](benchmark::State &st) { bm_batch(st, t); })
        ->Arg(1000000)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
  benchmark::RegisterBenchmark("loop_hs_solve/threads:1", bm_loop)
      ->Arg(1000000)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(3);
  {
    // the regime mix of the batch scenes (Google Benchmark's CSV takes no per-row counters here)
    const auto v = batch_scenes(1000000);
    std::vector<hs_batch_result> out(v.size());
    hs_solve_batch(v.size(), v.data(), nullptr, 0, 0, out.data(), sizeof(hs_batch_result));
    size_t opp = 0, same = 0;
    for (const auto &r : out) {
      opp += r.status == HS_OK && r.regime == HS_REGIME_OPPOSITE_SIGN;
      same += r.status == HS_OK && r.regime == HS_REGIME_SAME_SIGN;
    }
    std::printf("batch scenes: 1000000, opposite sign %zu, same sign %zu\n", opp, same);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
