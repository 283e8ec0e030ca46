// The baselines a user would otherwise pick, shared by bench_hertz.cpp and
// bench_methods.cpp: the Hertz closed forms with Boost / GSL Carlson functions, and
// Newton on the raw side conditions (11)/(12) with GSL QAWS or Boost tanh-sinh
// quadrature. a = p0 = f = 1; results are b1, b2. Used by bench_methods.cpp.
#pragma once
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_ellint.h>

#include <algorithm>
#include <array>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>
#include <functional>

#include "halfslip/core/hertz.hpp"

namespace baselines {
namespace core = hs::core;

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
struct brf {
  double operator()(double x, double y, double z) const { return boost::math::ellint_rf(x, y, z); }
};
struct brd {
  double operator()(double x, double y, double z) const { return boost::math::ellint_rd(x, y, z); }
};
struct brj {
  double operator()(double x, double y, double z, double p) const { return boost::math::ellint_rj(x, y, z, p); }
};
struct grf {
  double operator()(double x, double y, double z) const { return gsl_sf_ellint_RF(x, y, z, GSL_PREC_DOUBLE); }
};
struct grd {
  double operator()(double x, double y, double z) const { return gsl_sf_ellint_RD(x, y, z, GSL_PREC_DOUBLE); }
};
struct grj {
  double operator()(double x, double y, double z, double p) const {
    return gsl_sf_ellint_RJ(x, y, z, p, GSL_PREC_DOUBLE);
  }
};
using boost_basis = carlson_basis_impl<brf, brd, brj>;
using gsl_basis = carlson_basis_impl<grf, grd, grj>;

struct result {
  double b1, b2;
  bool ok;
};

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
inline std::array<double, 2> naive_residual(naive_quadrature &Qd, double q, double s, double b1, double b2, int sR,
                                            int sL) {
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

inline result solve_naive(naive_quadrature &Qd, double q, double s) {
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

}  // namespace baselines
