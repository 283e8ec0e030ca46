// Per-call cost of the public C ABI (Google Benchmark), one scene per regime and
// geometry: solve, zone energies, B_x and slip at points, the closed-form steady
// cycle, and the MPFR reference backend at 30 digits (the short ladder of
// bench_compare.sh serves up to ~40).
//
// It uses only functions that have been in the C ABI since 0.4, so the same source
// builds against an older library: scripts/bench_compare.sh builds it against a
// base revision and against the working tree and runs the two alternately in one
// session (issue 12's "no slowdown, same table, same run"). Each benchmark checks
// the regime of its scene once, so a changed scene cannot pass for a fast one.
#include <benchmark/benchmark.h>
#include <halfslip/halfslip.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

struct scene_spec {
  const char *name;
  int geometry;  // HS_GEOMETRY_*
  double param;  // flat_over_a or exponent
  double q, s;
  int regime;  // expected HS_REGIME_*
  double rtol;
};

// Same-sign and opposite-sign scenes of each geometry (regimes checked at run time).
const scene_spec k_scenes[] = {
    {"hertz_same", HS_GEOMETRY_HERTZ, 0, 0.3, 0.2, HS_REGIME_SAME_SIGN, 0},
    {"hertz_opposite", HS_GEOMETRY_HERTZ, 0, 0.3, 2.0, HS_REGIME_OPPOSITE_SIGN, 0},
    {"flat_same", HS_GEOMETRY_FLAT_ROUNDED, 0.5, 0.3, 0.0, HS_REGIME_SAME_SIGN, 1e-12},
    {"flat_opposite", HS_GEOMETRY_FLAT_ROUNDED, 0.5, 0.5, 3.0, HS_REGIME_OPPOSITE_SIGN, 1e-12},
    {"power4_same", HS_GEOMETRY_POWER_LAW, 4.0, 0.3, 0.2, HS_REGIME_SAME_SIGN, 1e-12},
};

int solve(const scene_spec &sp, hs_solution **out) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = sp.q;
  sc.sigma_over_fp0 = sp.s;
  hs_options o;
  hs_options_default(&o);
  o.rtol = sp.rtol;
  if (sp.geometry == HS_GEOMETRY_HERTZ) return hs_solve(&sc, &o, out);
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = sp.geometry;
  if (sp.geometry == HS_GEOMETRY_FLAT_ROUNDED) g.flat_over_a = sp.param;
  if (sp.geometry == HS_GEOMETRY_POWER_LAW) g.exponent = sp.param;
  return hs_solve_geometry(&sc, &g, &o, out);
}

// Solves once and checks the regime; nullptr (and the benchmark skipped) on failure.
hs_solution *checked_solution(benchmark::State &state, const scene_spec &sp) {
  hs_solution *sol = nullptr;
  const int st = solve(sp, &sol);
  if (st != HS_OK) {
    state.SkipWithError(hs_strerror(st));
    return nullptr;
  }
  hs_summary su;
  su.struct_size = sizeof su;
  hs_solution_summary(sol, &su);
  if (su.regime != sp.regime) {
    state.SkipWithError("the scene is not in its expected regime");
    hs_solution_free(sol);
    return nullptr;
  }
  return sol;
}

void bm_solve(benchmark::State &state, const scene_spec &sp) {
  hs_solution *sol = checked_solution(state, sp);
  if (!sol) return;
  hs_solution_free(sol);
  for (auto _ : state) {
    hs_solution *s = nullptr;
    if (solve(sp, &s) != HS_OK) state.SkipWithError("solve failed");
    benchmark::DoNotOptimize(s);
    hs_solution_free(s);
  }
}

void bm_energy(benchmark::State &state, const scene_spec &sp) {
  hs_solution *sol = checked_solution(state, sp);
  if (!sol) return;
  double e[2];
  for (auto _ : state) {
    if (hs_solution_energy(sol, e) != HS_OK) state.SkipWithError("energy failed");
    benchmark::DoNotOptimize(e);
  }
  hs_solution_free(sol);
}

// One point in each slip zone (the middle of the zone), per call of n = 2.
void bm_points(benchmark::State &state, const scene_spec &sp, int what) {
  hs_solution *sol = checked_solution(state, sp);
  if (!sol) return;
  hs_summary su;
  su.struct_size = sizeof su;
  hs_solution_summary(sol, &su);
  const double x[2] = {su.b1 + su.d1 / 2, -su.b2 - su.d2 / 2};
  double out[2];
  for (auto _ : state) {
    const int st = what == 0 ? hs_eval_Bx(sol, 2, x, out) : hs_eval_slip(sol, 2, x, out);
    if (st != HS_OK) state.SkipWithError("evaluation failed");
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(2 * state.iterations());
  hs_solution_free(sol);
}

void bm_reference(benchmark::State &state, const char *q, const char *s, int digits) {
  hs_ref_scene sc;
  hs_ref_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  for (auto _ : state) {
    hs_ref_solution *r = nullptr;
    const int st = hs_ref_solve(&sc, digits, &r);
    if (st != HS_OK) state.SkipWithError(hs_strerror(st));
    benchmark::DoNotOptimize(r);
    hs_ref_solution_free(r);
  }
}

}  // namespace

int main(int argc, char **argv) {
  for (const auto &sp : k_scenes) {
    benchmark::RegisterBenchmark((std::string("solve/") + sp.name).c_str(),
                                 [&sp](benchmark::State &st) { bm_solve(st, sp); });
    benchmark::RegisterBenchmark((std::string("energy/") + sp.name).c_str(),
                                 [&sp](benchmark::State &st) { bm_energy(st, sp); });
    benchmark::RegisterBenchmark((std::string("Bx_point/") + sp.name).c_str(),
                                 [&sp](benchmark::State &st) { bm_points(st, sp, 0); });
    benchmark::RegisterBenchmark((std::string("slip_point/") + sp.name).c_str(),
                                 [&sp](benchmark::State &st) { bm_points(st, sp, 1); });
  }
  benchmark::RegisterBenchmark("reference30/hertz_opposite", [](benchmark::State &st) {
    bm_reference(st, "0.3", "2", 30);
  })->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
