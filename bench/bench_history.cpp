// Load histories (issue #14): speed and accuracy of the march, next to the
// independent collocation BEM a user could write instead. Writes
// bench/results/history.csv (one row per method and setting) and prints a
// markdown summary (bench/results/history_summary.md via scripts/bench.sh).
//   bench_history OUT.csv [--static-only]   (--static-only: section 5, the static solves, alone)
// Errors are against the same path marched at step 1/256 (zone ends in units
// of a, energies relative to the largest segment energy); times are medians of
// 3 runs on this machine.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <memory>
#include <random>
#include <vector>

#include <halfslip/halfslip.h>

#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/random_walk.hpp"
#include "halfslip/reference/reversal_oracle.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/static_history.hpp"
#include "halfslip/core/status.hpp"

using namespace hs::core;
using path_t = std::vector<std::pair<double, double>>;

namespace {

double median_time(const std::function<void()> &f, int reps = 3) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

struct result {
  std::vector<double> b1, b2, e1, e2;
};

// (core history_vertex or the C ABI's hs_history_vertex: the same field names)
template <class V> result of(const std::vector<V> &vs) {
  result r;
  for (const auto &v : vs) {
    r.b1.push_back(v.b1);
    r.b2.push_back(v.b2);
    r.e1.push_back(v.energy1);
    r.e2.push_back(v.energy2);
  }
  return r;
}

void errors(const result &a, const result &ref, double &eb, double &ee) {
  double emax = 0;
  for (size_t i = 0; i < ref.e1.size(); ++i) emax = std::max(emax, std::max(ref.e1[i], ref.e2[i]));
  eb = ee = 0;
  for (size_t i = 0; i < ref.b1.size() && i < a.b1.size(); ++i) {
    eb = std::max(eb, std::max(std::fabs(a.b1[i] - ref.b1[i]), std::fabs(a.b2[i] - ref.b2[i])));
    ee = std::max(ee, std::max(std::fabs(a.e1[i] - ref.e1[i]), std::fabs(a.e2[i] - ref.e2[i])) / emax);
  }
}

// the 162 periodic loadings of the robustness rows: (Q_a, Q_m, sigma_m, sigma_a, phase in degrees)
std::vector<std::array<double, 5>> periodic_cases() {
  std::vector<std::array<double, 5>> r;
  for (double qa : {0.1, 0.3, 0.6})
    for (double qm : {0.0, 0.15})
      for (double sm : {0.0, 0.5, 1.5})
        for (double sa : {0.0, 0.3, 1.0})
          for (double ph : {0.0, 45.0, 90.0, 180.0})
            if (!(sa == 0 && ph != 0)) r.push_back({{qa, qm, sm, sa, ph}});
  return r;
}

// a random non-proportional path of n vertices: |Q/fP| <= 0.5, sigma/fp0 in [0, 1.2], steps <= 0.15
path_t random_path(int n, unsigned seed) { return hs::reference::random_walk(n, seed); }


// The static solves at an accuracy asked (static_history_accuracy::for_rtol, what hs_history
// passes from hs_history_options.rtol): time (wall median of 3, and the process CPU time of
// one run, which a loaded machine inflates less) and the true error against the full-accuracy
// static solve of the same path: ends in a, segment energies relative to the path's largest,
// the traction at 39 points in f p0, the slip at 39 points relative to its largest; for the
// steady path also against the steady cycle's monotonic solution (closed forms, solve_general).
void static_rtol_rows(FILE *csv) {
  struct out {
    std::vector<double> b, E, q, h;
  };
  auto run = [](const std::shared_ptr<const pressure_model<double>> &pm, const static_history_accuracy<double> &acc,
                const path_t &p, static_history<double> *keep) {
    out o;
    static_history<double> h(pm, acc);
    for (const auto &v : p) {
      h.add_vertex(v.first, v.second);
      o.b.push_back(h.b1());
      o.b.push_back(h.b2());
      o.E.push_back(h.last_segment().E1);
      o.E.push_back(h.last_segment().E2);
    }
    if (keep) *keep = h;
    return o;
  };
  auto fields = [](const static_history<double> &h, out &o) {
    for (int k = -19; k <= 19; ++k) {
      o.q.push_back(h.traction(0.05 * k + 0.001));
      o.h.push_back(h.slip(0.05 * k + 0.001));
    }
  };
  path_t steady{{0.0, 0.6}};
  for (int k = 0; k < 99; ++k) steady.emplace_back(k % 2 ? 0.3 : -0.3, 0.6);
  const path_t cross{{0, 0.6}, {0.4, 0.6}, {-0.3, 0.6}, {0.35, 0.6}};
  for (int g = 0; g < 2; ++g) {
    std::shared_ptr<const pressure_model<double>> pm =
        g == 0 ? std::shared_ptr<const pressure_model<double>>(std::make_shared<hertz_pressure<double>>())
               : std::shared_ptr<const pressure_model<double>>(std::make_shared<flat_rounded_pressure<double>>(0.5));
    const char *gname = g == 0 ? "hertz" : "flat0.5";
    general_scene<double> sc;
    sc.q = 0.3;
    sc.s = 0;
    const auto m = solve_general<double>(*pm, sc);
    for (int pi = 0; pi < 2; ++pi) {
      const path_t &p = pi == 0 ? steady : cross;
      const char *pname = pi == 0 ? "steady100" : "sigma_then_Q_4";
      static_history<double> hf(pm);
      const out full0 = run(pm, static_history_accuracy<double>{}, p, &hf);
      out full = full0;
      fields(hf, full);
      double Emax = 0, hmax = 0;
      for (double e : full.E) Emax = std::max(Emax, e);
      for (double v : full.h) hmax = std::max(hmax, std::fabs(v));
      for (double rtol : {0.0, 1e-6, 1e-8, 1e-10, 1e-12}) {
        const auto acc = static_history_accuracy<double>::for_rtol(rtol);
        static_history<double> h(pm);
        out o;
        const double t = median_time([&] { o = run(pm, acc, p, &h); });
        const std::clock_t c0 = std::clock();
        run(pm, acc, p, nullptr);
        const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
        fields(h, o);
        double eb = 0, eE = 0, eq = 0, eh = 0;
        for (size_t k = 0; k < o.b.size(); ++k) eb = std::max(eb, std::fabs(o.b[k] - full.b[k]));
        for (size_t k = 0; k < o.E.size(); ++k) eE = std::max(eE, std::fabs(o.E[k] - full.E[k]) / Emax);
        for (size_t k = 0; k < o.q.size(); ++k) eq = std::max(eq, std::fabs(o.q[k] - full.q[k]));
        for (size_t k = 0; k < o.h.size(); ++k) eh = std::max(eh, std::fabs(o.h[k] - full.h[k]) / hmax);
        const double err = std::max({eb, eE, eq, eh});
        // the steady cycle's monotonic solution (the steady path only)
        double emono = 0;
        if (pi == 0)
          emono = std::max(std::fabs(h.b1() - m.b1()), std::fabs(h.last_segment().E1 - 2 * m.energy(1)) / m.energy(1));
        char setting[32];
        if (rtol > 0) std::snprintf(setting, sizeof setting, "rtol %g", rtol);
        else std::snprintf(setting, sizeof setting, "full");
        std::fprintf(csv, "%s_%s,static solves,%s,0,%.6g,%.3g,%.3g,%.3g,%zu\n", gname, pname, setting, t, eb, eE, err,
                     p.size());
        std::printf("| %s, %s | static solves, %s | %.3g ms (CPU %.3g ms) | %.1e against the full-accuracy solve "
                    "(ends %.1e a, energies %.1e, traction %.1e, slip %.1e)%s |\n",
                    g == 0 ? "Hertz" : "flat punch b_f/a = 0.5",
                    pi == 0 ? "sigma/fp0 = 0.6, then 99 half cycles Q/fP = -+0.3" : "sigma then Q cycles, 4 vertices",
                    setting, t * 1e3, cpu * 1e3, err, eb, eE, eq, eh,
                    pi == 0 ? (std::string("; ") + [&] {
                      char b[64];
                      std::snprintf(b, sizeof b, "%.1e against the monotonic solution", emono);
                      return std::string(b);
                    }()).c_str()
                            : "");
      }
    }
  }
}

}  // namespace

int main(int argc, char **argv) {
  // bench_history OUT.csv: every row; bench_history --static-rtol OUT.csv: only the static
  // solves' speed-accuracy rows (a minute, where the whole run takes many); bench_history OUT.csv
  // --static-only: only section 5, the static solves' robustness and cost rows (a minute);
  // bench_history OUT.csv --walks-only: only section 3, the march on the random walks (~15 min)
  const bool static_only = argc > 1 && std::string(argv[1]) == "--static-rtol";
  const char *out = argc > 1 + int(static_only) ? argv[1 + int(static_only)] : "history.csv";
  const bool section5_only = !static_only && argc > 2 && std::strcmp(argv[2], "--static-only") == 0;
  const bool walks_only = !static_only && argc > 2 && std::strcmp(argv[2], "--walks-only") == 0;
  FILE *csv = std::fopen(out, "w");
  if (!csv) return 1;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  if (static_only) {
    std::fprintf(csv, "case,method,setting,steps,seconds,err_b,err_E,error,vertices\n");
    static_rtol_rows(csv);
    std::fclose(csv);
    return 0;
  }
  std::fprintf(csv, "case,method,setting,steps,seconds,err_b,err_E,error_estimate,interior_merges\n");
  auto hertz = std::make_shared<hertz_pressure<double>>();
  auto flat = std::make_shared<flat_rounded_pressure<double>>(0.5);

  if (!section5_only) {
  if (!walks_only) {
  // 1. steady proportional Hertz cycle (+-(0.5, 0.4)): energy per cycle vs 4 x monotonic
  {
    hertz_scene<double> sc;
    sc.q = 0.5;
    sc.s = 0.4;
    const auto m = solve_hertz<double>(sc);
    const double E4 = 4 * m.energy(1);
    double t_mono = median_time(
        [&] {
          volatile double e = 4 * solve_hertz<double>(sc).energy(1);
          (void)e;
        },
        101);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    std::fprintf(csv, "steady_cycle,closed form 4 E_mono,,0,%.6g,0,0,0,0\n", t_mono);
    std::printf(
        "| steady in-phase Hertz cycle +-(0.5, 0.4), energy per cycle | closed form 4 E_mono | %.3g us | exact |\n",
        t_mono * 1e6);
    for (double rtol : {1e-6, 1e-8}) {
      double err = 0, est = 0;
      size_t steps = 0;
      const double t = median_time([&] {
        history_options<double> o;
        o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
        o.max_step = 1.0 / 32;
        refined_history<double> h(hertz, o, rtol);
        const auto r = h.add_cycles(0, 0.5, 0, 0.4, 0, 2, ramp_order::sigma_first, 64, 1e-6);
        err = std::fabs(r.energy1 - E4) / E4;
        est = h.error_estimate();
        steps = h.fine().step_count();
      });
      std::fprintf(csv, "steady_cycle,march rtol %g,,%zu,%.6g,0,%.3g,%.3g,0\n", rtol, steps, t, err, est);
      std::printf("| | march, rtol %g (2 cycles) | %.3g ms | %.1e (estimate %.1e) |\n", rtol, t * 1e3, err, est);
    }
  }

  // 1a. paths along one ray (issue 14): the superposition of monotonic solutions
  // through the C ABI (hs_history_*), exact, against the march of the same path
  // (rtol 1e-8). Random turning points t in [-0.6, 0.6] on the ray (Q/fP, sigma/fp0)
  // = t (1, 0.5) (Hertz, same sign) and t (1, 1) (flat-rounded punch b_f/a = 0.5).
  for (int geo = 0; geo < 2; ++geo) {
    const double us = geo == 0 ? 0.5 : 1.0;
    for (int n : {20, 100}) {
      std::mt19937 g(7 + n);
      std::uniform_real_distribution<double> u(-0.6, 0.6);
      std::vector<double> qs, ss;
      for (int i = 0; i < n; ++i) {
        const double t = u(g);
        qs.push_back(t);
        ss.push_back(us * t);
      }
      hs_scene sc;
      hs_scene_default(&sc);
      sc.a = sc.p0 = sc.f = sc.E_star = 1;
      hs_geometry gm;
      hs_geometry_default(&gm);
      gm.kind = HS_GEOMETRY_FLAT_ROUNDED;
      gm.flat_over_a = 0.5;
      std::vector<hs_history_vertex> sup(n);
      int st = 0;
      const double t_sup = median_time([&] {
        hs_history *h = nullptr;
        st = hs_history_new(&sc, geo == 0 ? nullptr : &gm, nullptr, &h);
        if (st == 0) st = hs_history_add_vertices(h, n, qs.data(), ss.data());
        for (int i = 0; st == 0 && i < n; ++i) {
          sup[i].struct_size = sizeof sup[i];
          st = hs_history_vertex_get(h, i, &sup[i]);
        }
        hs_history_free(h);
      });
      const char *name = geo == 0 ? "hertz" : "flat";
      if (st != 0) {
        std::fprintf(csv, "%s_ray%d,superposition,,0,%.6g,nan,nan,0,0\n", name, n, t_sup);
        std::printf("| %s ray, %d vertices | superposition | failed (status %d) | |\n", name, n, st);
        continue;
      }
      double est = 0;
      for (const auto &v : sup) est = std::max(est, v.error_estimate);
      std::fprintf(csv, "%s_ray%d,superposition (C ABI),,0,%.6g,0,0,%.3g,0\n", name, n, t_sup, est);
      std::printf("| %s ray, %d vertices | superposition (C ABI) | %.3g ms | exact (estimate %.1e) |\n", name, n,
                  t_sup * 1e3, est);
      if (n > 20) continue;  // the march of 100 vertices takes minutes
      std::shared_ptr<const pressure_model<double>> pm;
      if (geo == 0) pm = hertz;
      else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
      result rm;
      size_t steps = 0;
      double mest = 0;
      const double t_m = median_time(
          [&] {
            history_options<double> o;
            o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
            o.max_step = 1.0 / 32;
            refined_history<double> h(pm, o, 1e-8);
            for (int i = 0; i < n; ++i) h.add_vertex(qs[i], ss[i]);
            rm = of(h.fine().vertices());
            steps = h.fine().step_count();
            mest = h.error_estimate();
          },
          1);
      double eb = 0, ee = 0;
      errors(rm, of(sup), eb, ee);
      std::fprintf(csv, "%s_ray%d,march rtol 1e-8,,%zu,%.6g,%.3g,%.3g,%.3g,0\n", name, n, steps, t_m, eb, ee, mest);
      std::printf("| | march, rtol 1e-8 | %.3g s | zones %.1e a, energies %.1e (estimate %.1e) |\n", t_m, eb, ee,
                  mest);
    }
  }

  // 1b. speed-accuracy of the march against the static-solve oracle (reference/reversal_oracle.hpp):
  // seven segments after a Hertz ramp along which both ends only advance (tests/test_history.cpp),
  // largest end error over the seven against the step, and the total time
  {
    struct seg {
      double q0, s0, q1, s1;
      int d1, d2;
    };
    const seg segs[] = {{0.14915544246907966, 0.12976720841044964, 0.037592776800771471, 0.27947936305003174, -1, -1},
                        {0.5, 0.4, 0.2, 0.6, -1, -1},
                        {0.3, 0.0, 0.25, 0.8, -1, 1},
                        {0.4, 0.5, -0.1, 0.3, -1, -1},
                        {0.6, 0.2, 0.3, -0.3, -1, -1},
                        {0.2, 0.3, 0.1, 0.9, -1, 1},
                        {0.45, 0.0, 0.0, 0.0, -1, -1}};
    std::vector<std::array<double, 2>> truth;
    const double t_or = median_time([&] {
      truth.clear();
      for (const auto &c : segs) {
        hs::reference::reversal_oracle<double> o(c.q0, c.s0, c.q1, c.s1, c.d1, c.d2);
        truth.push_back(o.solve(0.9, 0.9));
      }
    });
    std::fprintf(csv, "oracle_segments,static-solve oracle,,0,%.6g,0,0,0,0\n", t_or);
    std::printf("| 7 segments after a ramp, ends only advancing | static-solve oracle (tanh-sinh, Newton) | %.3g ms | truth |\n",
                t_or * 1e3);
    auto run = [&](const std::function<void(const seg &, double &, double &, size_t &)> &march, const char *name,
                   const char *setting) {
      double err = 0, est = 0;
      size_t steps = 0;
      const double t = median_time([&] {
        err = est = 0;
        steps = 0;
        for (size_t i = 0; i < truth.size(); ++i) {
          double b1 = 0, b2 = 0;
          size_t n = 0;
          double e = 0;
          march(segs[i], b1, b2, n);
          (void)e;
          err = std::max(err, std::max(std::fabs(b1 - truth[i][0]), std::fabs(b2 - truth[i][1])));
          steps += n;
        }
      });
      std::fprintf(csv, "oracle_segments,%s,%s,%zu,%.6g,%.3g,0,0,0\n", name, setting, steps, t, err);
      std::printf("| | %s %s | %.3g ms | %.1e a |\n", name, setting, t * 1e3, err);
    };
    for (int k = 5; k <= 10; ++k) {
      char setting[32];
      std::snprintf(setting, sizeof setting, "step 1/%d", 1 << k);
      run(
          [&](const seg &c, double &b1, double &b2, size_t &n) {
            history_options<double> o;
            o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
            o.max_step = std::ldexp(1.0, -k);
            history<double> h(hertz, o);
            h.add_vertex(c.q0, c.s0);
            h.add_vertex(c.q1, c.s1);
            b1 = h.vertices().back().b1;
            b2 = h.vertices().back().b2;
            n = h.step_count();
          },
          "march", setting);
    }
    // the library's static solves from the state it reached (core/static_history.hpp): the
    // ramp and the segment, with energies and slip where no end crosses a memory point
    run(
        [&](const seg &c, double &b1, double &b2, size_t &n) {
          static_history<double> h(hertz);
          h.add_vertex(c.q0, c.s0);
          h.add_vertex(c.q1, c.s1);
          b1 = h.b1();
          b2 = h.b2();
          n = 0;
        },
        "static_history", "(2 segments each)");
    for (double rtol : {1e-6, 1e-8, 1e-10}) {
      char setting[32];
      std::snprintf(setting, sizeof setting, "rtol %g", rtol);
      run(
          [&](const seg &c, double &b1, double &b2, size_t &n) {
            history_options<double> o;
            o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
            o.max_step = 1.0 / 32;
            refined_history<double> h(hertz, o, rtol);
            h.add_vertex(c.q0, c.s0);
            h.add_vertex(c.q1, c.s1);
            b1 = h.vertices().back().b1;
            b2 = h.vertices().back().b2;
            n = h.fine().step_count();
          },
          "refined march", setting);
    }
  }

  // 2. speed-accuracy of the march and of the BEM on one non-proportional path
  // Q = 0.4 sin(th), sigma = 0.8 + 0.6 cos(th): two cycles of 16 chords after sigma alone (the test's path)
  path_t walk{{0.0, 1.4}};
  for (int c = 0; c < 2; ++c)
    for (int k = 1; k <= 16; ++k) {
      const double th = 2 * M_PI * k / 16;
      walk.emplace_back(0.4 * std::sin(th), 0.8 + 0.6 * std::cos(th));
    }
  for (int g = 0; g < 2; ++g) {
    const auto pm = g == 0 ? std::shared_ptr<const pressure_model<double>>(hertz)
                           : std::shared_ptr<const pressure_model<double>>(flat);
    const char *name = g == 0 ? "hertz_out_of_phase" : "flat0.5_out_of_phase";
    // reference: the finest march that converges on this path
    result ref;
    int kref = 8;
    for (; kref >= 6; --kref) {
      try {
        history_options<double> fo;
        fo.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
        fo.max_step = std::ldexp(1.0, -kref);
        history<double> fine(pm, fo);
        for (const auto &p : walk) fine.add_vertex(p.first, p.second);
        ref = of(fine.vertices());
        break;
      } catch (const error &) {}
    }
    std::printf("reference for %s: march at step 2^-%d\n", name, kref);
    for (int k = 4; k <= 7; ++k) {
      history_options<double> o;
      o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
      o.max_step = std::ldexp(1.0, -k);
      result r;
      size_t steps = 0, merges = 0;
      bool failed = false;
      const double t = median_time([&] {
        try {
          history<double> h(pm, o);
          for (const auto &p : walk) h.add_vertex(p.first, p.second);
          r = of(h.vertices());
          steps = h.step_count();
          merges = h.interior_merges();
        } catch (const error &) {
          failed = true;
        }
      });
      if (failed) {
        std::fprintf(csv, "%s,march,step 2^-%d,0,%.6g,nan,nan,0,0\n", name, k, t);
        continue;
      }
      double eb, ee;
      errors(r, ref, eb, ee);
      std::fprintf(csv, "%s,march,step 2^-%d,%zu,%.6g,%.3g,%.3g,0,%zu\n", name, k, steps, t, eb, ee, merges);
    }
    for (int nodes : {100, 200}) {
      hs::reference::bem::options bo;
      bo.nodes = nodes;
      bo.steps_per_unit = nodes;
      std::vector<hs::reference::bem::vertex_state> vs;
      const double t = median_time(
          [&] { vs = hs::reference::bem::run([&](double x) { return pm->p(x); }, walk, bo); }, 1);
      result r;
      for (const auto &v : vs) {
        r.b1.push_back(v.b1);
        r.b2.push_back(v.b2);
        r.e1.push_back(v.energy1);
        r.e2.push_back(v.energy2);
      }
      double eb, ee;
      errors(r, ref, eb, ee);
      std::fprintf(csv, "%s,collocation BEM,%d nodes,%d,%.6g,%.3g,%.3g,0,0\n", name, nodes, nodes, t, eb, ee);
    }
  }

  }  // !walks_only
  // 3. robustness and cost on random 100-vertex non-proportional paths (|Q/fP| <= 0.5,
  // sigma/fp0 in [0, 1.2], moves up to 0.15), Hertz and the flat punch, march at rtol 1e-8
  for (int g = 0; g < 2; ++g) {
    const auto pm = g == 0 ? std::shared_ptr<const pressure_model<double>>(hertz)
                           : std::shared_ptr<const pressure_model<double>>(flat);
    int ok = 0;
    double tsum = 0;
    std::vector<double> ests;
    for (unsigned seed = 1; seed <= 8; ++seed) {
      const path_t walk100 = random_path(100, seed);
      size_t steps = 0, done = 0;
      double est = 0, step = 0;
      const auto t0 = std::chrono::steady_clock::now();
      history_options<double> o;
      o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
      o.max_step = 1.0 / 32;
      try {
        refined_history<double> h(pm, o, 1e-8);
        for (const auto &p : walk100) {
          h.add_vertex(p.first, p.second);
          ++done;
        }
        steps = h.fine().step_count();
        est = h.error_estimate();
        step = h.step();
      } catch (const error &) {}
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      tsum += t;
      if (done == walk100.size()) {
        ++ok;
        ests.push_back(est);
      }
      std::fprintf(csv, "%s_random100_seed%u,march rtol 1e-8,step %g,%zu,%.6g,0,0,%.3g,%zu\n",
                   g == 0 ? "hertz" : "flat0.5", seed, step, steps, t, est, done);
    }
    std::sort(ests.begin(), ests.end());
    // the summed error estimate at the last vertex (the path's honest figure, docs/history.md)
    std::printf("| 8 random 100-vertex paths, %s | march rtol 1e-8 | %d of 8 complete; %.3g s in all; "
                "summed estimate median %.2g, largest %.2g |\n",
                g == 0 ? "Hertz" : "flat punch b_f/a = 0.5", ok, tsum, ests.empty() ? 0.0 : ests[ests.size() / 2],
                ests.empty() ? 0.0 : ests.back());
  }
  // 4. robustness on periodic loading: 162 cycles (Q_a 0.1-0.6, Q_m 0-0.15, sigma_m 0-1.5,
  // sigma_a 0-1, phase 0-180 degrees; 3 cycles of 16 chords after sigma first), Hertz, the march at
  // max_step 1/32 without refinement
  if (!walks_only) {
    int ok = 0, n = 0, ok_low = 0, n_low = 0;
    double tsum = 0;
    for (const auto &pc : periodic_cases()) {
              const double qa = pc[0], qm = pc[1], sm = pc[2], sa = pc[3], ph = pc[4];
              ++n;
              const bool low = sm + sa <= 1.0;
              if (low) ++n_low;
              history_options<double> o;
              o.merge_interior_patches = true;  // the approximation, counted (docs/history.md)
              o.max_step = 1.0 / 32;
              history<double> h(hertz, o);
              const auto t0 = std::chrono::steady_clock::now();
              bool done = false;
              try {
                add_cycles<double>(h, qm, qa, sm, sa, ph, 3, ramp_order::sigma_first, 16, 1e-6);
                done = true;
              } catch (const error &) {}
              const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
              tsum += t;
              if (done) {
                ++ok;
                if (low) ++ok_low;
              }
              std::fprintf(csv, "hertz_cycle_qa%g_qm%g_sm%g_sa%g_ph%g,march step 1/32,,%zu,%.6g,0,0,0,%d\n", qa, qm,
                           sm, sa, ph, h.step_count(), t, int(done));
            }
    std::printf(
        "| %d periodic loadings, Hertz (3 cycles) | march, step 1/32 | %d of %d complete (%d of %d with "
        "sigma_m + sigma_a <= 1); %.3g s in all |\n",
        n, ok, n, ok_low, n_low, tsum);
  }
  }  // !section5_only
  // 5. the static solves (core/static_history.hpp): exact where every segment advances.
  // (a) sigma then 100 half cycles of Q at constant sigma (every segment advances; the issue's
  // "non-proportional path of 100 vertices"), Hertz and flat punch, against the steady
  // cycle's closed form / general solution; (b) how far they take the random walks and
  // the periodic loadings above (the rest is marched by hs_history).
  if (!walks_only) {
    for (int g = 0; g < 2; ++g) {
      std::shared_ptr<const pressure_model<double>> pm =
          g == 0 ? hertz : std::shared_ptr<const pressure_model<double>>(std::make_shared<flat_rounded_pressure<double>>(0.5));
      general_scene<double> sc;
      sc.q = 0.3;
      sc.s = 0;
      const auto m = solve_general<double>(*pm, sc);
      double err = 0;
      const double t = median_time([&] {
        static_history<double> h(pm);
        h.add_vertex(0, 0.6);
        for (int k = 0; k < 99; ++k) h.add_vertex(k % 2 ? 0.3 : -0.3, 0.6);
        err = std::max(std::fabs(h.b1() - m.b1()), std::fabs(h.last_segment().E1 - 2 * m.energy(1)) / m.energy(1));
      });
      std::fprintf(csv, "%s_steady100,static solves,,0,%.6g,%.3g,0,0,100\n", g == 0 ? "hertz" : "flat0.5", t, err);
      std::printf("| sigma/fp0 = 0.6, then 99 half cycles Q/fP = -+0.3, %s | static solves | %.3g ms | "
                  "%.1e (ends, a; last energy, relative) against the steady cycle's monotonic solution |\n",
                  g == 0 ? "Hertz" : "flat punch b_f/a = 0.5", t * 1e3, err);
    }
    // the same at an accuracy asked (hs_history_options.rtol)
    static_rtol_rows(csv);
    for (int g = 0; g < 2; ++g) {
      std::shared_ptr<const pressure_model<double>> pm =
          g == 0 ? hertz : std::shared_ptr<const pressure_model<double>>(std::make_shared<flat_rounded_pressure<double>>(0.5));
      int ok = 0;
      size_t verts = 0;
      double tsum = 0;
      for (unsigned seed = 1; seed <= 8; ++seed) {
        const path_t walk100 = random_path(100, seed);
        static_history<double> h(pm);
        size_t done = 0;
        const auto t0 = std::chrono::steady_clock::now();
        try {
          for (const auto &p : walk100) {
            h.add_vertex(p.first, p.second);
            ++done;
          }
        } catch (const error &) {}
        tsum += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        verts += done;
        if (done == walk100.size()) ++ok;
        std::fprintf(csv, "%s_random100_seed%u,static solves,,0,0,0,0,0,%zu\n", g == 0 ? "hertz" : "flat0.5", seed,
                     done);
      }
      std::printf("| 8 random 100-vertex paths, %s | static solves | %d of 8 complete; %zu of 800 vertices before "
                  "the first segment they cannot take; %.3g s in all |\n",
                  g == 0 ? "Hertz" : "flat punch b_f/a = 0.5", ok, verts, tsum);
    }
    int ok = 0, n = 0;
    double tsum = 0;
    for (const auto &pc : periodic_cases()) {
              const double qa = pc[0], qm = pc[1], sm = pc[2], sa = pc[3], ph = pc[4];
              ++n;
              // the vertices of add_cycles with 16 chords, sigma first
              path_t p;
              const double d2r = M_PI / 180, s0 = sm + sa * std::sin(ph * d2r);
              p.emplace_back(0.0, s0);
              p.emplace_back(qm, s0);
              for (int c = 0; c < 3; ++c)
                for (int k = 1; k <= 16; ++k) {
                  const double th = 2 * M_PI * k / 16;
                  p.emplace_back(qm + qa * std::sin(th), sm + sa * std::sin(th + ph * d2r));
                }
              static_history<double> h(hertz);
              bool done = true;
              const auto t0 = std::chrono::steady_clock::now();
              try {
                for (const auto &v : p) h.add_vertex(v.first, v.second);
              } catch (const error &) {
                done = false;
              }
              tsum += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
              if (done) ++ok;
            }
    std::printf("| %d periodic loadings, Hertz (3 cycles of 16 chords) | static solves | %d of %d complete; %.3g s "
                "in all |\n",
                n, ok, n, tsum);
  }
  std::fclose(csv);
  return 0;
}
