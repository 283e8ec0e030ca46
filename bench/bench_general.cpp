// Issue 16 (Google Benchmark): the general path (non-Hertz pressures by
// quadrature), flat punch with rounded corners b_f/a = 0.5 at rtol 1e-12, on
// the four flat-punch scenes of bench_methods (two same sign, two opposite
// sign):
//   solve/<scene>         hs_solve_geometry (HS_MODEL_QUADRATURE, rtol 1e-12)
//   setup/<scene>         the one-time expansion of B_x per zone
//                         (general_solution::make_expansion, core)
//   Bx/<scene>, slip/<scene>, energies/<scene>
//                         hs_eval_Bx and hs_eval_slip at one point, and
//                         hs_solution_energy, through the C ABI after the
//                         set-up (the points cycle over 12 points of both
//                         zones, next to the stick edges, mid-zone and next to
//                         the contact edges)
//   Bx_before/<scene>, slip_before/<scene>, energies_before/<scene>
//                         the paths they replace on the same solution, in the
//                         same run: the adaptive Cauchy integrals at the point
//                         (bhat_direct), the fixed rules with doubled orders
//                         (hhat_fixed, energy_hat_fixed), core, canonical frame
//   first_energies/<scene> hs_solve_geometry + hs_solution_energy (set-up
//                         included), against solve/<scene>
//   build/bench/bench_general --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//       --benchmark_out=bench/results/general.csv --benchmark_out_format=csv
#include <benchmark/benchmark.h>
#include <halfslip/halfslip.h>

#include <cmath>
#include <string>
#include <vector>

#include "halfslip/core/general.hpp"

namespace core = hs::core;

namespace {

struct scene {
  const char *name;
  double q, s;
};
const scene scenes[] = {{"same_q0.3_s0", 0.3, 0.0},
                        {"same_q0.6_s0.3", 0.6, 0.3},
                        {"opposite_q0.2_s2", 0.2, 2.0},
                        {"opposite_q0.5_s3", 0.5, 3.0}};
const double flat_over_a = 0.5, rtol = 1e-12;

hs_scene capi_scene(const scene &c) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = c.q;
  sc.sigma_over_fp0 = c.s;
  return sc;
}
hs_geometry flat() {
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_FLAT_ROUNDED;
  g.flat_over_a = flat_over_a;
  return g;
}
hs_options options() {
  hs_options o;
  hs_options_default(&o);
  o.model = HS_MODEL_QUADRATURE;
  o.rtol = rtol;
  return o;
}
hs_solution *capi_solve(const scene &c) {
  const hs_scene sc = capi_scene(c);
  const hs_geometry g = flat();
  const hs_options o = options();
  hs_solution *s = nullptr;
  if (hs_solve_geometry(&sc, &g, &o, &s) != HS_OK) return nullptr;
  return s;
}
// 12 points: in each zone at 1e-6, 0.02, 0.3, 0.5, 0.9 and 1 - 1e-6 of its length from the stick edge
std::vector<double> points(const hs_solution *s) {
  hs_summary su;
  su.struct_size = sizeof su;
  hs_solution_summary(s, &su);
  std::vector<double> x;
  for (double f : {1e-6, 0.02, 0.3, 0.5, 0.9, 1 - 1e-6}) {
    x.push_back(su.b1 + f * su.d1);
    x.push_back(-su.b2 - f * su.d2);
  }
  return x;
}

void bm_solve(benchmark::State &state, scene c) {
  for (auto _ : state) {
    hs_solution *s = capi_solve(c);
    if (!s) state.SkipWithError("solve failed");
    hs_solution_free(s);
  }
}

void bm_first_energies(benchmark::State &state, scene c) {
  double e[2];
  for (auto _ : state) {
    hs_solution *s = capi_solve(c);
    if (!s || hs_solution_energy(s, e) != HS_OK) state.SkipWithError("solve or energy failed");
    benchmark::DoNotOptimize(e[0]);
    hs_solution_free(s);
  }
}

template <class F> void bm_points(benchmark::State &state, scene c, F eval) {
  hs_solution *s = capi_solve(c);
  if (!s) {
    state.SkipWithError("solve failed");
    return;
  }
  const std::vector<double> x = points(s);
  double v;
  eval(s, 1, &x[0], &v);  // the set-up, once
  std::size_t i = 0;
  for (auto _ : state) {
    if (eval(s, 1, &x[i], &v) != HS_OK) state.SkipWithError("eval failed");
    benchmark::DoNotOptimize(v);
    i = i + 1 < x.size() ? i + 1 : 0;
  }
  hs_solution_free(s);
}

void bm_energies(benchmark::State &state, scene c) {
  hs_solution *s = capi_solve(c);
  double e[2];
  if (!s || hs_solution_energy(s, e) != HS_OK) {
    state.SkipWithError("solve failed");
    return;
  }
  for (auto _ : state) {
    if (hs_solution_energy(s, e) != HS_OK) state.SkipWithError("energy failed");
    benchmark::DoNotOptimize(e[0]);
  }
  hs_solution_free(s);
}

// the core solution of the same scene (canonical frame: these scenes have q, s >= 0)
core::general_solution<double> core_solve(const core::pressure_model<double> &pm, const scene &c) {
  core::general_scene<double> sc;
  sc.q = c.q;
  sc.s = c.s;
  core::general_options<double> o;
  o.rtol = rtol;
  return core::solve_general(pm, sc, o);
}
// (zone, distance from the stick edge) of the 12 points
std::vector<std::pair<int, double>> core_points(const core::general_solution<double> &g) {
  std::vector<std::pair<int, double>> v;
  for (double f : {1e-6, 0.02, 0.3, 0.5, 0.9, 1 - 1e-6})
    for (int z : {+1, -1}) v.push_back({z, f * g.zone_length(z)});
  return v;
}

void bm_setup(benchmark::State &state, scene c) {
  const core::flat_rounded_pressure<double> pm(flat_over_a);
  const auto g = core_solve(pm, c);
  for (auto _ : state) {
    const auto x = g.make_expansion();
    if (!x) state.SkipWithError("no expansion");
    benchmark::DoNotOptimize(x.get());
  }
}

void bm_before(benchmark::State &state, scene c, int what) {
  const core::flat_rounded_pressure<double> pm(flat_over_a);
  const auto g = core_solve(pm, c);
  const auto p = core_points(g);
  std::size_t i = 0;
  for (auto _ : state) {
    double v;
    if (what == 0) v = g.bhat_direct(p[i].first, p[i].second);
    else if (what == 1) v = g.hhat_fixed(p[i].first, p[i].second);
    else v = g.energy_hat_fixed(1) + g.energy_hat_fixed(-1);
    benchmark::DoNotOptimize(v);
    i = i + 1 < p.size() ? i + 1 : 0;
  }
}

}  // namespace

int main(int argc, char **argv) {
  for (const scene &c : scenes) {
    const std::string n = c.name;
    benchmark::RegisterBenchmark(("solve/" + n).c_str(), bm_solve, c)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("setup/" + n).c_str(), bm_setup, c)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("first_energies/" + n).c_str(), bm_first_energies, c)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Bx/" + n).c_str(), bm_points<decltype(&hs_eval_Bx)>, c, &hs_eval_Bx)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("slip/" + n).c_str(), bm_points<decltype(&hs_eval_slip)>, c, &hs_eval_slip)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("energies/" + n).c_str(), bm_energies, c)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Bx_before/" + n).c_str(), bm_before, c, 0)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("slip_before/" + n).c_str(), bm_before, c, 1)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("energies_before/" + n).c_str(), bm_before, c, 2)->Unit(benchmark::kMicrosecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
