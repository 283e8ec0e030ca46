// Hertz benchmark: median time per solve in each regime and per point
// evaluation, for halfslip's closed forms and for the alternatives a user
// would otherwise pick, on the same scenes, with their errors.
//
//   halfslip/cel      closed forms + Bulirsch cel (the library)
//   boost-carlson     same closed forms and Newton, Boost.Math ellint_rf/rd/rj
//   gsl-carlson       same closed forms and Newton, GSL gsl_sf_ellint_RF/RD/RJ
//   naive-qaws        Newton (finite-difference Jacobian) on the raw side
//                     conditions (11)/(12), integrals by GSL QAWS (tol 1e-12)
//   naive-tanh-sinh   the same with Boost.Math tanh-sinh quadrature
//
// Error: max |b - b_ref|/a over the scenes, b_ref from the long double
// instantiation of the closed forms (checked against direct quadrature by the
// test suite). Output: a table on stdout, CSV to argv[1] (default
// bench/results/hertz.csv).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "baselines.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"

namespace core = hs::core;

namespace {

using namespace baselines;  // the closed forms with Boost/GSL Carlson, Newton with QAWS/tanh-sinh

template <class F> double median_ns(F &&f, int reps, int inner) {
  for (int i = 0; i < inner; ++i) f(i);  // warm-up: caches, branch predictors, clock ramp-up
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < inner; ++i) f(i);
    const auto t1 = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / inner);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

volatile double g_sink;

}  // namespace

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  const std::string csv = argc > 1 ? argv[1] : "bench/results/hertz.csv";
  struct scene {
    double q, s;
  };
  // same-sign and opposite-sign scenes over the regimes
  std::vector<scene> same, opp;
  for (double q : {0.05, 0.2, 0.4, 0.6, 0.8, 0.95})
    for (double f : {-0.9, -0.5, 0.0, 0.5, 0.9}) same.push_back({q, f * 4 * q / (1 + std::sqrt(1 - q))});
  for (double q : {0.0, 0.1, 0.3, 0.5, 0.7, 0.9})
    for (double ds : {0.05, 0.3, 1.0, 2.5, 5.0}) opp.push_back({q, 4 * q / (1 + std::sqrt(1 - q)) + ds});

  auto ref = [](const scene &c) {
    core::hertz_scene<long double> sc;
    sc.q = c.q;
    sc.s = c.s;
    const auto sol = core::solve_hertz(sc);
    return std::pair<double, double>(double(sol.b1()), double(sol.b2()));
  };
  struct method {
    std::string name;
    std::function<result(double, double)> solve;
    int inner;
  };
  qaws Qw;
  tanh_sinh_q Tq;
  std::vector<method> methods = {
      {"halfslip/cel", [](double q, double s) { return solve_closed<core::opposite_basis<double>>(q, s); }, 2000},
      {"boost-carlson", [](double q, double s) { return solve_closed<boost_basis>(q, s); }, 200},
      {"gsl-carlson", [](double q, double s) { return solve_closed<gsl_basis>(q, s); }, 200},
      {"naive-qaws", [&](double q, double s) { return solve_naive(Qw, q, s); }, 1},
      {"naive-tanh-sinh", [&](double q, double s) { return solve_naive(Tq, q, s); }, 1},
  };

  std::ofstream out(csv);
  out << "kind,method,regime,median_ns,max_abs_err_b,failures\n";
  std::printf("%-18s %-14s %14s %14s %9s\n", "method", "regime", "median/solve", "max|b-bref|/a", "failures");
  for (auto &M : methods) {
    for (int reg = 0; reg < 2; ++reg) {
      const auto &sc = reg == 0 ? same : opp;
      double err = 0;
      int fails = 0;
      for (const auto &c : sc) {
        const auto r = M.solve(c.q, c.s);
        const auto b = ref(c);
        if (!r.ok || !std::isfinite(r.b1)) {
          ++fails;
          continue;
        }
        err = std::max(err, std::max(std::abs(r.b1 - b.first), std::abs(r.b2 - b.second)));
      }
      const int inner = M.inner;
      const double ns = median_ns(
          [&](int i) {
            const auto &c = sc[size_t(i) % sc.size()];
            g_sink = M.solve(c.q, c.s).b1;
          },
          M.inner >= 100 ? 15 : 3, std::max<int>(inner, int(sc.size())));
      const char *rn = reg == 0 ? "same-sign" : "opposite-sign";
      std::printf("%-18s %-14s %11.3g ns %14.3g %9d\n", M.name.c_str(), rn, ns, err, fails);
      out << "solve," << M.name << "," << rn << "," << ns << "," << err << "," << fails << "\n";
    }
  }

  // point evaluations of B_x, slip and energy with halfslip
  for (int reg = 0; reg < 2; ++reg) {
    const auto &sc = reg == 0 ? same : opp;
    std::vector<core::hertz_solution<double>> sols;
    for (const auto &c : sc) {
      core::hertz_scene<double> s;
      s.q = c.q;
      s.s = c.s;
      sols.push_back(core::solve_hertz(s));
    }
    const char *rn = reg == 0 ? "same-sign" : "opposite-sign";
    const double nsB = median_ns(
        [&](int i) {
          const auto &s = sols[size_t(i) % sols.size()];
          g_sink = s.Bx(0.5 * (s.b1() + 1));
        },
        15, 20000);
    const double nsH = median_ns(
        [&](int i) {
          const auto &s = sols[size_t(i) % sols.size()];
          g_sink = s.slip(0.5 * (s.b1() + 1));
        },
        7, reg == 0 ? 20000 : 200);
    const double nsE = median_ns(
        [&](int i) {
          const auto &s = sols[size_t(i) % sols.size()];
          g_sink = s.energy(1) + s.energy(2);
        },
        5, 60);
    std::printf("%-18s %-14s B_x %.3g ns, slip %.3g ns, both energies %.3g ns\n", "halfslip/eval", rn, nsB, nsH, nsE);
    out << "eval_Bx,halfslip," << rn << "," << nsB << ",,0\n";
    out << "eval_slip,halfslip," << rn << "," << nsH << ",,0\n";
    out << "energy,halfslip," << rn << "," << nsE << ",,0\n";
  }
  // General-pressure path (issue 4): Hertz through the general solver (error
  // against the closed forms' reference) and the flat punch with rounded
  // corners, b_f/a = 0.5, at several tolerances.
  {
    const core::hertz_pressure<double> hz;
    const core::flat_rounded_pressure<double> flat(0.5);
    for (double rtol : {1e-6, 1e-9, 1e-12, 0.0}) {
      core::general_options<double> o;
      o.rtol = rtol;
      for (int reg = 0; reg < 2; ++reg) {
        const auto &sc = reg == 0 ? same : opp;
        const char *rn = reg == 0 ? "same-sign" : "opposite-sign";
        double err = 0;
        int order = 0;
        for (const auto &c : sc) {
          core::general_scene<double> g;
          g.q = c.q;
          g.s = c.s;
          const auto sol = core::solve_general(hz, g, o);
          const auto b = ref(c);
          err = std::max(err, std::max(std::abs(sol.b1() - b.first), std::abs(sol.b2() - b.second)));
          order = std::max(order, sol.order);
        }
        const double nsH = median_ns(
            [&](int i) {
              const auto &c = sc[size_t(i) % sc.size()];
              core::general_scene<double> g;
              g.q = c.q;
              g.s = c.s;
              g_sink = core::solve_general(hz, g, o).b1();
            },
            5, int(sc.size()));
        const double nsF = median_ns(
            [&](int i) {
              const auto &c = sc[size_t(i) % sc.size()];
              core::general_scene<double> g;
              g.q = std::min(c.q, 0.9);
              g.s = c.s;
              g_sink = core::solve_general(flat, g, o).b1();
            },
            5, int(sc.size()));
        const std::string name = "general-path rtol=" + (rtol > 0 ? std::to_string(int(std::round(-std::log10(rtol))))
                                                                  : std::string("full"));
        std::printf("%-18s %-14s %11.3g ns %14.3g %9d   (Hertz via general path; order %d)\n", name.c_str(), rn, nsH,
                    err, 0, order);
        std::printf("%-18s %-14s %11.3g ns %14s %9d   (flat punch b_f/a = 0.5)\n", name.c_str(), rn, nsF, "-", 0);
        out << "solve," << name << "," << rn << "," << nsH << "," << err << ",0\n";
        out << "flat_solve," << name << "," << rn << "," << nsF << ",,0\n";
      }
    }
  }
  std::printf("CSV written to %s\n", csv.c_str());
  return 0;
}
