// Speed and accuracy of the stresses through the C ABI (issue 15), Google Benchmark.
//
// Targets (after the solve): surface sigma_xx at 1,000 points <= 50 us (Hertz), <= 2 ms (flat
// punch); subsurface stress on a 200 x 100 grid <= 20 ms (Hertz), <= 200 ms (flat punch), each to
// 1e-10 of the peak. Scenes: Hertz Q/fP = 0.5, sigma/fp0 = 0.5 (same sign, closed forms) and 2.0
// (opposite sign, cached panels); flat punch b_f/a = 0.5, Q/fP = 0.4, sigma/fp0 = 0.5 and 2.0.
// Points: 1,000 surface points evenly over |x| <= 1.5a; the grid |x| <= 2a (200) by
// 0 < y <= 2a (100, evenly, y = 0.02a .. 2a) in body 1.
//
// usage: bench_fields ACCURACY.csv [--benchmark_out=FILE --benchmark_out_format=csv ...]
//   ACCURACY.csv: per scene, the largest difference over the grid and the surface points
//   against quadrature from scratch (core stress_at without the cached panels: q from
//   traction.hpp at every node, panels graded around each point; for Hertz same sign the
//   closed forms in long double) on every 10th grid column, divided by the peak |stress| on
//   the grid; and the cost of the first call (panels built).
// Also the states of two load histories (hs_history_state, issue 15): Hertz unloading
// 0 -> 0.6 -> 0.2, and 3 cycles of Q and sigma 90 degrees out of phase; their accuracy
// is checked in tests/test_history_fields.cpp (Ciavarella-Jager superposition, quadrature
// from scratch split at every step end).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <halfslip/halfslip.h>

#include "halfslip/core/fields.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"

namespace {

struct scene_def {
  const char *name;
  bool flat;
  double q, s;
};
const scene_def kScenes[] = {{"hertz_same", false, 0.5, 0.5},
                             {"hertz_opposite", false, 0.5, 2.0},
                             {"flat_same", true, 0.4, 0.5},
                             {"flat_opposite", true, 0.4, 2.0}};

hs_solution *solve(const scene_def &d) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = d.q;
  sc.sigma_over_fp0 = d.s;
  hs_solution *sol = nullptr;
  int st;
  if (d.flat) {
    hs_geometry g;
    hs_geometry_default(&g);
    g.kind = HS_GEOMETRY_FLAT_ROUNDED;
    g.flat_over_a = 0.5;
    st = hs_solve_geometry(&sc, &g, nullptr, &sol);
  } else {
    st = hs_solve(&sc, nullptr, &sol);
  }
  if (st != HS_OK) {
    std::fprintf(stderr, "bench_fields: solve %s: %s\n", d.name, hs_strerror(st));
    std::exit(1);
  }
  return sol;
}

struct points {
  std::vector<double> sx, gx, gy;
  points() {
    for (int i = 0; i < 1000; ++i) sx.push_back(-1.5 + 3.0 * (i + 0.5) / 1000);
    for (int j = 0; j < 100; ++j)
      for (int i = 0; i < 200; ++i) {
        gx.push_back(-2.0 + 4.0 * (i + 0.5) / 200);
        gy.push_back(2.0 * (j + 1) / 100);
      }
  }
};
const points &pts() {
  static const points p;
  return p;
}

// surface sigma_xx at the 1,000 points, and the 200 x 100 grid, of a solution (freed here)
void surface_loop(benchmark::State &state, hs_solution *sol) {
  std::vector<double> out(pts().sx.size());
  hs_eval_surface_stress(sol, 1, 0.0, 1, pts().sx.data(), out.data());  // first call builds the cache
  for (auto _ : state) {
    hs_eval_surface_stress(sol, 1, 0.0, out.size(), pts().sx.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  hs_solution_free(sol);
}

void grid_loop(benchmark::State &state, hs_solution *sol) {
  std::vector<double> out(3 * pts().gx.size());
  hs_eval_stress(sol, 1, 0.0, 1, pts().gx.data(), pts().gy.data(), out.data());
  for (auto _ : state) {
    hs_eval_stress(sol, 1, 0.0, pts().gx.size(), pts().gx.data(), pts().gy.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  hs_solution_free(sol);
}

void BM_surface(benchmark::State &state, scene_def d) { surface_loop(state, solve(d)); }
void BM_grid(benchmark::State &state, scene_def d) { grid_loop(state, solve(d)); }

// the first field call on a fresh solution: the cached panels are built (solve not timed)
void BM_first_call(benchmark::State &state, scene_def d) {
  double x = 0.3, y = 0.2, out[3];
  for (auto _ : state) {
    state.PauseTiming();
    hs_solution *sol = solve(d);
    state.ResumeTiming();
    hs_eval_stress(sol, 1, 0.0, 1, &x, &y, out);
    state.PauseTiming();
    hs_solution_free(sol);
    state.ResumeTiming();
  }
}

// quadrature from scratch through the core (no cached panels)
hs::core::contact_state<double> slow_state(const scene_def &d, std::unique_ptr<hs::core::hertz_solution<double>> &h,
                                           std::unique_ptr<hs::core::general_solution<double>> &g,
                                           std::unique_ptr<hs::core::flat_rounded_pressure<double>> &pm) {
  using namespace hs::core;
  if (d.flat) {
    pm = std::make_unique<flat_rounded_pressure<double>>(0.5);
    general_scene<double> sc;
    sc.q = d.q;
    sc.s = d.s;
    g = std::make_unique<general_solution<double>>(solve_general<double>(*pm, sc));
    return general_state_of(*g);
  }
  hertz_scene<double> sc;
  sc.q = d.q;
  sc.s = d.s;
  h = std::make_unique<hertz_solution<double>>(solve_hertz(sc));
  // same sign: the closed forms (McEwen); opposite sign: the slow quadrature
  return h->reg == regime::opposite_sign ? make_state<double>(*h) : hertz_state(*h);
}

void accuracy(const char *path) {
  FILE *f = std::fopen(path, "w");
  if (!f) {
    std::fprintf(stderr, "bench_fields: cannot write %s\n", path);
    std::exit(1);
  }
  std::fprintf(f,
               "scene,grid_points_checked,peak_grid,max_err_grid_rel,surface_points,peak_surface,"
               "max_err_surface_rel,first_call_ms\n");
  for (const scene_def &d : kScenes) {
    std::unique_ptr<hs::core::hertz_solution<double>> h;
    std::unique_ptr<hs::core::general_solution<double>> g;
    std::unique_ptr<hs::core::flat_rounded_pressure<double>> pm;
    const auto ref = slow_state(d, h, g, pm);
    hs_solution *sol = solve(d);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> out(3 * pts().gx.size());
    hs_eval_stress(sol, 1, 0.0, 1, pts().gx.data(), pts().gy.data(), out.data());
    const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    hs_eval_stress(sol, 1, 0.0, pts().gx.size(), pts().gx.data(), pts().gy.data(), out.data());
    double peak = 0, err = 0;
    int n = 0;
    // Hertz same sign: the closed forms in long double (the double path is the same closed forms)
    const bool ld = !d.flat && h->reg != hs::core::regime::opposite_sign;
    hs::core::hertz_scene<long double> lsc;
    lsc.q = d.q;
    lsc.s = d.s;
    const auto lsol = hs::core::solve_hertz(lsc);
    const auto lst = hs::core::hertz_state(lsol);
    auto reference = [&](double x, double y) {
      if (!ld) return hs::core::stress_at(ref, 1, x, y);
      const auto t = hs::core::stress_at<long double>(lst, 1, x, y);
      hs::core::stress_tensor<double> r;
      r.xx = double(t.xx);
      r.yy = double(t.yy);
      r.xy = double(t.xy);
      return r;
    };
    for (std::size_t k = 0; k < pts().gx.size(); ++k) {
      for (int c = 0; c < 3; ++c) peak = std::max(peak, std::fabs(out[3 * k + c]));
      if (k % 10) continue;  // every 10th column against the slow reference
      const auto s = reference(pts().gx[k], pts().gy[k]);
      err = std::max(
          {err, std::fabs(s.xx - out[3 * k]), std::fabs(s.yy - out[3 * k + 1]), std::fabs(s.xy - out[3 * k + 2])});
      ++n;
    }
    std::vector<double> sv(pts().sx.size());
    hs_eval_surface_stress(sol, 1, 0.0, sv.size(), pts().sx.data(), sv.data());
    double speak = 0, serr = 0;
    for (std::size_t k = 0; k < sv.size(); ++k) {
      speak = std::max(speak, std::fabs(sv[k]));
      const double r = ld ? double(hs::core::surface_sxx<long double>(lst, 1, pts().sx[k]))
                          : hs::core::surface_sxx(ref, 1, pts().sx[k]);
      serr = std::max(serr, std::fabs(sv[k] - r));
    }
    std::fprintf(f, "%s,%d,%.6g,%.3g,%zu,%.6g,%.3g,%.3f\n", d.name, n, peak, err / peak, sv.size(), speak,
                 serr / speak, 1e3 * first);
    hs_solution_free(sol);
  }
  std::fclose(f);
}

// ---- states of load histories (hs_history_state): the same evaluators ----------------
// unloading: Hertz, sigma = 0, Q/fP 0 -> 0.6 -> 0.2; out_of_phase: Hertz, Q/fP = 0.3 sin wt,
// sigma/fp0 = 1.0 sin(wt + 90 deg), 3 cycles. The state after the last vertex.
struct history_def {
  const char *name;
  bool cycles;
};
const history_def kHistories[] = {{"history_unloading", false}, {"history_out_of_phase", true}};

hs_solution *history_state(const history_def &d) {
  hs_scene sc;
  hs_scene_default(&sc);
  hs_history *h = nullptr;
  int st = hs_history_new(&sc, nullptr, nullptr, &h);
  if (st == HS_OK) {
    if (d.cycles) {
      st = hs_history_add_cycles(h, 0.0, 0.3, 0.0, 1.0, 90.0, 3);
    } else {
      const double q[2] = {0.6, 0.2}, s[2] = {0.0, 0.0};
      st = hs_history_add_vertices(h, 2, q, s);
    }
  }
  size_t n = 0;
  if (st == HS_OK) st = hs_history_vertex_count(h, &n);
  hs_solution *sol = nullptr;
  if (st == HS_OK) st = hs_history_state(h, n - 1, &sol);
  hs_history_free(h);
  if (st != HS_OK) {
    std::fprintf(stderr, "bench_fields: history %s: %s\n", d.name, hs_strerror(st));
    std::exit(1);
  }
  return sol;
}

void BM_history_surface(benchmark::State &state, history_def d) { surface_loop(state, history_state(d)); }
void BM_history_grid(benchmark::State &state, history_def d) { grid_loop(state, history_state(d)); }

// the state's handle and its first field call (panel cache over the state's steps); the march not timed
void BM_history_first_call(benchmark::State &state, history_def d) {
  hs_scene sc;
  hs_scene_default(&sc);
  hs_history *h = nullptr;
  hs_history_new(&sc, nullptr, nullptr, &h);
  if (d.cycles) {
    hs_history_add_cycles(h, 0.0, 0.3, 0.0, 1.0, 90.0, 3);
  } else {
    const double q[2] = {0.6, 0.2}, s[2] = {0.0, 0.0};
    hs_history_add_vertices(h, 2, q, s);
  }
  size_t n = 0;
  hs_history_vertex_count(h, &n);
  double x = 0.3, y = 0.2, out[3];
  for (auto _ : state) {
    hs_solution *sol = nullptr;
    hs_history_state(h, n - 1, &sol);
    hs_eval_stress(sol, 1, 0.0, 1, &x, &y, out);
    hs_solution_free(sol);
  }
  hs_history_free(h);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2 || argv[1][0] == '-') {
    std::fprintf(stderr, "usage: bench_fields ACCURACY.csv [benchmark options]\n");
    return 2;
  }
  accuracy(argv[1]);
  for (const scene_def &d : kScenes) {
    benchmark::RegisterBenchmark((std::string("surface_1000/") + d.name).c_str(), BM_surface, d)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("grid_200x100/") + d.name).c_str(), BM_grid, d)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("first_call/") + d.name).c_str(), BM_first_call, d)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(5);
  }
  for (const history_def &d : kHistories) {
    benchmark::RegisterBenchmark((std::string("surface_1000/") + d.name).c_str(), BM_history_surface, d)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("grid_200x100/") + d.name).c_str(), BM_history_grid, d)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("first_call/") + d.name).c_str(), BM_history_first_call, d)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(5);
  }
  int bargc = argc - 1;
  benchmark::Initialize(&bargc, argv + 1);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
