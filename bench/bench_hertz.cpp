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

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"

namespace core = hs::core;

namespace {

// ---- Carlson providers for the same closed forms -------------------------
template <class RFn, class RDn, class RJn> struct carlson_basis_impl {
  double op1, op2, Q, sQ, kc, RF, eRDb, RDb, RJc;
  explicit carlson_basis_impl(const core::opposite_state<double> &st) {
    op2 = st.d1 + st.e;
    op1 = st.d2 + st.e;
    Q = op1 * op2;
    sQ = std::sqrt(Q);
    const double P = 2 * st.e;
    kc = std::sqrt(P / Q);
    RF = RFn()(0.0, P, Q);
    RDb = RDn()(0.0, Q, P);
    eRDb = st.e * RDb;
    RJc = RJn()(0.0, P, Q, 2 * op2);
  }
};
struct brf { double operator()(double x, double y, double z) const { return boost::math::ellint_rf(x, y, z); } };
struct brd { double operator()(double x, double y, double z) const { return boost::math::ellint_rd(x, y, z); } };
struct brj { double operator()(double x, double y, double z, double p) const { return boost::math::ellint_rj(x, y, z, p); } };
struct grf { double operator()(double x, double y, double z) const { return gsl_sf_ellint_RF(x, y, z, GSL_PREC_DOUBLE); } };
struct grd { double operator()(double x, double y, double z) const { return gsl_sf_ellint_RD(x, y, z, GSL_PREC_DOUBLE); } };
struct grj { double operator()(double x, double y, double z, double p) const { return gsl_sf_ellint_RJ(x, y, z, p, GSL_PREC_DOUBLE); } };
using boost_basis = carlson_basis_impl<brf, brd, brj>;
using gsl_basis = carlson_basis_impl<grf, grd, grj>;

struct result { double b1, b2; bool ok; };

template <class Basis> result solve_closed(double q, double s) {
  core::hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  if (s / 4 <= q / (1 + std::sqrt(1 - q))) {
    const auto sol = core::solve_hertz(sc);
    return {sol.b1(), sol.b2(), true};
  }
  try {
    const auto r = core::solve_opposite<double, Basis>(q, s, 100);
    return {r.beta1, r.beta2, true};
  } catch (...) {
    return {NAN, NAN, false};
  }
}

// ---- the naive alternative: quadrature of the raw side conditions ----------
struct naive_quadrature {
  virtual ~naive_quadrature() = default;
  // int_lo^hi g(t) (t - lo)^al (hi - t)^be dt
  virtual double integrate(const std::function<double(double)> &g, double lo, double hi, double al, double be) = 0;
};

struct qaws : naive_quadrature {
  gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
  ~qaws() override { gsl_integration_workspace_free(w); }
  double integrate(const std::function<double(double)> &g, double lo, double hi, double al, double be) override {
    gsl_integration_qaws_table *t = gsl_integration_qaws_table_alloc(al, be, 0, 0);
    gsl_function F;
    F.function = [](double x, void *p) { return (*static_cast<const std::function<double(double)> *>(p))(x); };
    F.params = const_cast<std::function<double(double)> *>(&g);
    double r = 0, err = 0;
    gsl_integration_qaws(&F, lo, hi, t, 0, 1e-12, 200, w, &r, &err);
    gsl_integration_qaws_table_free(t);
    return r;
  }
};

struct tanh_sinh_q : naive_quadrature {
  boost::math::quadrature::tanh_sinh<double> ts;
  double integrate(const std::function<double(double)> &g, double lo, double hi, double al, double be) override {
    const double L = hi - lo;
    return ts.integrate(
        [&](double x, double xc) {
          const double dlo = xc < 0 ? -xc : L - xc, dhi = xc > 0 ? xc : L + xc;
          return g(x) * std::pow(dlo, al) * std::pow(dhi, be);
        },
        lo, hi, 1e-10);
  }
};

// r_j = sL int_L p t^{j-1}/R - sR int_R p t^{j-1}/R - rhs_j  (a = p0 = f = 1)
std::array<double, 2> naive_residual(naive_quadrature &Qd, double q, double s, double b1, double b2, int sR, int sL) {
  std::array<double, 2> r{};
  for (int j = 1; j <= 2; ++j) {
    const double IR = Qd.integrate(
        [&](double t) { return std::sqrt(1 + t) / std::sqrt(t + b2) * (j == 1 ? 1.0 : t); }, b1, 1.0, -0.5, 0.5);
    const double IL = Qd.integrate(
        [&](double t) { return std::sqrt(1 - t) / std::sqrt(b1 - t) * (j == 1 ? 1.0 : t); }, -1.0, -b2, 0.5, -0.5);
    const double rhs = j == 1 ? M_PI * s / 4 : -M_PI * q / 2 + M_PI * s * (b1 - b2) / 8;
    r[j - 1] = sL * IL - sR * IR - rhs;
  }
  return r;
}

result solve_naive(naive_quadrature &Qd, double q, double s) {
  const double m = q / (1 + std::sqrt(1 - q));
  const bool same = s / 4 <= m;
  const int sR = same ? 1 : -1, sL = 1;
  // start: the same-sign formula, clipped into the contact
  double b1 = std::min(std::sqrt(1 - q) + s / 4, 0.999), b2 = std::max(std::sqrt(1 - q) - s / 4, -0.999);
  if (b1 + b2 < 0.05) b2 = 0.05 - b1;
  for (int it = 0; it < 60; ++it) {
    const auto F = naive_residual(Qd, q, s, b1, b2, sR, sL);
    const double h = 1e-7;
    const auto F1 = naive_residual(Qd, q, s, b1 - h, b2, sR, sL);
    const auto F2 = naive_residual(Qd, q, s, b1, b2 - h, sR, sL);
    const double J00 = (F[0] - F1[0]) / h, J10 = (F[1] - F1[1]) / h, J01 = (F[0] - F2[0]) / h,
                 J11 = (F[1] - F2[1]) / h;
    const double det = J00 * J11 - J01 * J10;
    double d1 = (F[0] * J11 - F[1] * J01) / det, d2 = (J00 * F[1] - J10 * F[0]) / det;
    double lam = 1;
    while ((b1 - lam * d1 >= 1 || b2 - lam * d2 >= 1 || b1 - lam * d1 + b2 - lam * d2 <= 0) && lam > 1e-6) lam /= 2;
    b1 -= lam * d1;
    b2 -= lam * d2;
    if (std::abs(lam * d1) + std::abs(lam * d2) < 1e-13) return {b1, b2, true};
  }
  return {b1, b2, false};
}

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
  struct scene { double q, s; };
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
  struct method { std::string name; std::function<result(double, double)> solve; int inner; };
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
        if (!r.ok || !std::isfinite(r.b1)) { ++fails; continue; }
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
        const std::string name = "general-path rtol=" + (rtol > 0 ? std::to_string(int(std::round(-std::log10(rtol)))) : std::string("full"));
        std::printf("%-18s %-14s %11.3g ns %14.3g %9d   (Hertz via general path; order %d)\n", name.c_str(), rn, nsH, err, 0, order);
        std::printf("%-18s %-14s %11.3g ns %14s %9d   (flat punch b_f/a = 0.5)\n", name.c_str(), rn, nsF, "-", 0);
        out << "solve," << name << "," << rn << "," << nsH << "," << err << ",0\n";
        out << "flat_solve," << name << "," << rn << "," << nsF << ",,0\n";
      }
    }
  }
  std::printf("CSV written to %s\n", csv.c_str());
  return 0;
}
