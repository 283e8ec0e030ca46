// halfslip core: contact pressure models for the general (non-Hertz) path.
//
// Every model is dimensionless: lengths in units of the contact half-width a
// (contact |x| < 1), pressure in units of p0 = 2P/(pi a), so that
//     p_hat(x) = p(a x)/p0,   integral_{-1}^{1} p_hat = pi/2.
// A model supplies the edge-regular factor
//     phi(x) = p_hat(x) / sqrt(1 - x^2),
// which is bounded, positive and smooth near both edges for a pressure that
// vanishes like sqrt(distance) at the edges (the declared edge behaviour of
// every model). phi is evaluated from x and the exact distances to the edges
// dm = 1 + x, dp = 1 - x, so that callers that know these distances better
// than x (quadrature nodes close to an edge) lose nothing.
//
// Models: Hertz, flat punch with rounded corners (Ciavarella, Hills & Monno
// 1998), symmetric power-law profile g = A|x|^n, sampled pressure and a
// user callback. Generic in the real type T (double, long double, Boost
// multiprecision): every precision-dependent choice derives from eps<T>().
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/special_functions/cos_pi.hpp>
#include <boost/math/special_functions/zeta.hpp>

#include "gauss.hpp"
#include "knots.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

// Gauss-Legendre rules (gl_rule, gauss_legendre): gauss.hpp.

// A point of (-1, 1) where phi is not smooth. graded: phi' is log-singular
// there (or phi has a |x - x_k|^alpha term); quadrature panels ending there
// are graded polynomially towards it. Otherwise a plain split (e.g. a knot of
// a piecewise cubic).
template <class T> struct breakpoint {
  T x;
  bool graded;
};

// ---------------------------------------------------------------------------
template <class T> class pressure_model {
 public:
  virtual ~pressure_model() = default;
  // phi = p_hat / sqrt(1 - x^2); dm = 1 + x, dp = 1 - x.
  virtual T phi(const T &x, const T &dm, const T &dp) const = 0;
  // d phi / dx. Default: central difference with step cbrt(eps) times the
  // distance to the nearer edge (phi is smooth up to the edges), accurate to
  // eps^(2/3): used only in Newton Jacobians, never in a residual.
  virtual T dphi(const T &x, const T &dm, const T &dp) const {
    using std::cbrt;
    using std::min;
    const T h = cbrt(eps<T>()) * min(min(dm, dp), T(1)) / 2;
    return (phi(x + h, dm + h, dp - h) - phi(x - h, dm - h, dp + h)) / (2 * h);
  }
  // phi and (in d) phi' together; models that share work between the two
  // (the flat punch: the same logarithms) override this.
  virtual T phi_dphi(const T &x, const T &dm, const T &dp, T &d) const {
    d = dphi(x, dm, dp);
    return phi(x, dm, dp);
  }
  virtual std::vector<breakpoint<T>> breakpoints() const { return {}; }
  // phi_dphi's derivative is phi's own to rounding (closed forms, not the
  // default difference above, whose error near a cusp of phi left the general
  // solver's Newton converging only linearly: power law n = 1.5, issue 16). The
  // solver then trusts quadratic convergence to skip evaluations that would
  // only confirm a step (general_solver.hpp, general_problem::shortcut).
  virtual bool exact_dphi() const { return false; }
  // Stick half-width c (units of a) of the symmetric shear-only problem
  // (sigma = 0) at q = Q/fP in [0, 1), if known in closed form or cheaply
  // (a start for the solver); false otherwise.
  virtual bool shear_only_half_width(const T &, T &) const { return false; }
  // Relative accuracy of phi in units of eps (the solver's convergence tests
  // and residual tolerance scale with it): a few eps for the closed forms; the
  // power law sums ~n/2 terms (or raises |x| to n - 1) and is good to ~n eps.
  virtual T accuracy_eps() const { return T(4); }
  // p(-x) = p(x): the mirror x -> -x is then a symmetry of the problem.
  virtual bool symmetric() const { return false; }
  // phi at the edge x = side (+1 or -1): the edge coefficient of the
  // pressure, p_hat ~ sqrt(2 z) phi(side) at distance z from the edge (so the
  // asymptotic model's K_N = p0 sqrt(2/a) edge_phi). Default: phi is smooth
  // up to the edges (its expansion in the distance z is a power series), so
  // Richardson extrapolation from z = h, 2h, 4h (error O(h^3)) with h chosen
  // to balance that against rounding amplified by ~10.
  virtual T edge_phi(int side) const {
    using std::cbrt;
    using std::min;
    const T h = min(T(1) / 64, T(cbrt(eps<T>())) / 4);
    auto at = [&](const T &z) {
      const T x = side > 0 ? 1 - z : z - 1;
      return side > 0 ? phi(x, 2 - z, z) : phi(x, z, 2 - z);
    };
    const T f1 = at(h), f2 = at(2 * h), f4 = at(4 * h);
    // quadratic through (h, f1), (2h, f2), (4h, f4) at z = 0: 8/3 f1 - 2 f2 + 1/3 f4
    return (8 * f1 - 6 * f2 + f4) / 3;
  }
  // Integral of p_hat from the edge on `side` (+1: x = 1, -1: x = -1) over a
  // length c in [0, 2]. Default: quadrature (t = edge -+ c w^2 removes the sqrt).
  virtual T tail(int side, const T &c) const;

  // Product quadrature over the knots of a model with very many of them (the
  // sampled pressure, knots.hpp): the zone integrals and tails use it instead
  // of a panel end at every knot. Empty for the other models.
  virtual knot_view<T> knots() const { return {}; }

  T p(const T &x, const T &dm, const T &dp) const {
    using std::sqrt;
    if (!(dm > 0) || !(dp > 0)) return T(0);
    return sqrt(dm * dp) * phi(x, dm, dp);
  }
  T p(const T &x) const { return p(x, 1 + x, 1 - x); }
};

// Integral of f(w) over [0, 1] by tanh-sinh split at given points (in w).
template <class T, class F> T integrate_split(const F &f, std::vector<T> cuts, const T &tol) {
  return integrate_pieces<T>([&](const T &w, const T &) { return f(w); }, T(0), T(1), std::move(cuts), tol);
}

template <class T> T pressure_model<T>::tail(int side, const T &c) const {
  using std::sqrt;
  if (!(c > 0)) return T(0);
  // t = edge - side * c w^2: distance to this edge c w^2, to the other 2 - c w^2
  std::vector<T> cuts;
  for (const auto &b : breakpoints()) {
    const T dist = side > 0 ? 1 - b.x : 1 + b.x;
    if (dist > 0 && dist < c) cuts.push_back(sqrt(dist / c));
  }
  const T sc = sqrt(c);
  auto f = [&](const T &w) {
    const T near = c * w * w, far = 2 - near;
    const T x = side > 0 ? 1 - near : near - 1;
    const T ph = side > 0 ? phi(x, far, near) : phi(x, near, far);
    return 2 * c * sc * w * w * sqrt(far) * ph;
  };
  return integrate_split<T>(f, cuts, boost::math::tools::root_epsilon<T>());
}

// ---------------------------------------------------------------------------
// a. Hertz: p = p0 sqrt(1 - x^2).
template <class T> class hertz_pressure final : public pressure_model<T> {
 public:
  T phi(const T &, const T &, const T &) const override { return T(1); }
  T dphi(const T &, const T &, const T &) const override { return T(0); }
  T phi_dphi(const T &, const T &, const T &, T &d) const override {
    d = 0;
    return T(1);
  }
  bool exact_dphi() const override { return true; }
  bool symmetric() const override { return true; }
  T edge_phi(int) const override { return T(1); }
  bool shear_only_half_width(const T &q, T &c) const override {
    using std::sqrt;
    c = sqrt(1 - q);
    return true;
  }
  T tail(int, const T &c) const override { return pressure_tail(c); }
  // Contact half-width from the load per unit length P of a cylinder of
  // radius R (plane strain, E* the contact modulus): a = sqrt(4 P R / (pi E*)).
  static T half_width_from_load(const T &P, const T &R, const T &Estar) {
    using std::sqrt;
    return sqrt(4 * P * R / (pi<T>() * Estar));
  }
};

// The pressure unit of every model, p0 = 2P/(pi a) (the Hertz peak pressure).
template <class T> T pressure_unit(const T &P, const T &a) { return 2 * P / (pi<T>() * a); }

// ---------------------------------------------------------------------------
// b. Flat punch of half-width b_f with corners rounded to radius R
// (Ciavarella, Hills & Monno 1998). With x = a sin(phi), b_f = a sin(phi0):
//   P = a^2 (pi - 2 phi0 - sin 2phi0) / (2 A R),
//   p = a/(pi A R) [(pi - 2phi0) cos phi + sin phi ln|sin(phi+phi0)/sin(phi-phi0)|
//                   + sin phi0 ln|tan((phi+phi0)/2) tan((phi-phi0)/2)|],
// so p_hat = [...] / g(beta), g(beta) = pi - 2 phi0 - sin 2 phi0 = 2 ep - sin 2 ep
// with ep = acos(beta), beta = b_f/a. (Normalisation and the sqrt edge
// behaviour verified with mpmath at 30 digits.) p' is log-singular at
// x = +-beta: graded breakpoints.
//
// Evaluation (issue 13). The bracket above is a sum of terms of size ~1 whose
// result is ~g c: as b_f -> a it cancelled ~4/g of its digits (3.5e4 eps at
// b_f/a = 0.999, 1.6e6 eps at 0.9999, measured against 50 digits), and the
// solver lost the stick zone at large sigma. It is evaluated instead from the
// inversion integral of the profile, written in the angle tau = acos(t) of the
// rounded part (mpmath: equal to the bracket to 1e-36):
//   phi(x) = [T(|x|) + T(-|x|)] / g,
//   T(X) = int_0^ep (cos tau - cos ep)/(cos tau - X) dtau   (principal value for X > cos ep).
// The integrand is positive for X < cos ep (the flat, and the X = -|x| term).
// With tau* = acos X, a = (tau* + ep)/2, b = (tau* - ep)/2 and r = tau*/ep:
//   r >= 2: Gauss-Legendre in tau (the integrand is even in tau, poles at
//     +-tau*: the rule of order N on [-ep, ep] errs by ~rho^(-2N), rho = r + sqrt(r^2 - 1);
//     the order is the smallest of a ladder with rho^(-2N) <= eps/64), every
//     term positive;
//   1 < r < 2 (the flat next to the kink): T = ep - (2 sin a sin b / sin tau*) ln(sin a / sin b),
//     which cancels at most a factor ~6 (r = 2);
//   r < 1 (the rounded corner, principal value):
//     T = ep + 2 cos(ep/2) sin(a) L(u) / cos(tau*/2),  u = 2 cos(ep/2) sin(tau*/2) / sin(-b),
//     L(u) = ln(1 + u)/u: both terms positive;
//   r = 1 (the kink): T = ep.
// X = +-|x| enters only through cos tau - X = D - (1 - cos tau), D = 1 - |x| (X = |x|)
// or 1 + |x| (X = -|x|), formed from the exact distance to the nearer edge.
// phi' (Newton Jacobians only, accurate to ~eps^(3/4)): dT/dX by the same rule
// (int (cos tau - cos ep)/(cos tau - X)^2) for r >= 2; for 1 < r < 2
//   dT/dX = [ln(sin a/sin b)(1 - cos ep cos tau*) - sin ep sin tau*] / sin^3 tau*;
// in the corner -(dT/dtau*)/sin tau* from the product above, and below
// tau* = ep eps^(1/4) the even series T = T0 + T2 tau*^2 + T4 tau*^4 (sympy):
//   T2 = sin(ep)/6 - cot(ep/2)/3,
//   T4 = 7 sin(ep)/360 - cot(ep/2)/18 - cos(ep/2) cos(ep) / (60 sin^3(ep/2)).
template <class T> class flat_rounded_pressure final : public pressure_model<T> {
 public:
  // beta = b_f / a in [0, 1)
  explicit flat_rounded_pressure(const T &beta) : beta_(beta) {
    using std::acosh;
    using std::asin;
    using std::cos;
    using std::log;
    using std::pow;
    using std::sin;
    using std::sqrt;
    if (!(beta >= 0) || !(beta < 1)) throw error(status::bad_geometry, "flat punch: need 0 <= b_f/a < 1");
    g_ = load_factor(beta);
    if (beta == 0) return;
    // ep = acos(beta); sin and cos of ep/2 from 1 -+ beta (1 - beta exact for
    // beta >= 1/2): no loss as beta -> 1, and at the kink dist = 1 - beta
    // sin(b) = sin(tau*/2) cos(ep/2) - cos(tau*/2) sin(ep/2) is exactly 0
    omb_ = 1 - beta;
    se2_ = sqrt(omb_ / 2);
    ce2_ = sqrt((1 + beta) / 2);
    ep_ = 2 * asin(se2_);
    sep_ = 2 * se2_ * ce2_;
    cep_ = beta;
    {
      // the corner's even series in tau* (sympy; c = cos(ep/2), s = sin(ep/2), every term < 0):
      //   T2 = -c^3/(3 s),  T4 = -c^5/(60 s^3) - c^3/(18 s),
      //   T6 = -c^7/(560 s^5) - c^5/(180 s^3) - 17 c^3/(2160 s),
      //   T8 = -c^9/(4032 s^7) - c^7/(1120 s^5) - c^5/(800 s^3) - 31 c^3/(30240 s);
      // in x = (tau*/ep)^2 the terms fall by ~x each (measured): the derivative
      // from them errs by ~x^4 relative, the product rule above by ~eps/sqrt(x):
      // balanced at x = eps^(2/9) (tau* = ep/55 in double; both sides within ~60 eps)
      const T c = ce2_, s = se2_, c2 = c * c, s2 = s * s;
      const T k = c2 / s2;
      t2_ = -c2 * c / (3 * s);
      t4_ = t2_ * (k / 20 + T(1) / 6);
      t6_ = -c2 * c / s * (k * k / 560 + k / 180 + T(17) / 2160);
      t8_ = -c2 * c / s * (k * k * k / 4032 + k * k / 1120 + k / 800 + T(31) / 30240);
      tau_series_ = ep_ * pow(eps<T>(), T(1) / 9);
    }
    // the Gauss ladder: order N serves r >= rmin(N) (ladder_plan); per node
    // 1 - cos tau = 2 sin^2(tau/2) and cos tau - cos ep = 2 (sin(ep/2) - sin(tau/2))
    // (sin(ep/2) + sin(tau/2)), one sine a node (the product
    // 2 sin((ep + tau)/2) sin((ep - tau)/2) took three: with the rungs' bisection
    // for rmin, now done once per type, the constructor was a third of a solve
    // through the C ABI, ~7 us; issue 16). The difference sin(ep/2) - sin(tau/2)
    // is as accurate, relative, as ep - tau from the rounded tau = ep x_k.
    const rung_plans plans = ladder_plan();
    {
      std::size_t total = 0;
      for (const auto &pl : plans.v) total += std::size_t(pl.N / 2);
      nodes_.reserve(2 * total);
    }
    ladder_.reserve(plans.v.size());
    for (const auto &pl : plans.v) {
      rung r;
      r.rmin = pl.rmin;
      r.first = nodes_.size();
      const auto rule = gauss_legendre<T>(pl.N);
      for (int k = 0; k < pl.N; ++k) {
        if (!(rule->x[k] > 0)) continue;
        const T tau = ep_ * rule->x[k];
        const T sh = sin(tau / 2);
        nodes_.push_back(2 * sh * sh);                                        // 1 - cos tau
        nodes_.push_back(ep_ * rule->w[k] * (2 * (se2_ - sh) * (se2_ + sh)));  // w (cos tau - cos ep)
      }
      r.count = (nodes_.size() - r.first) / 2;
      r.dmin = vers_of(r.rmin * ep_);
      ladder_.push_back(r);
    }
    dclosed_ = vers_of(closed_form_limit() * ep_);
    dseries_ = vers_of(tau_series_);
  }
  // The orders of the Gauss ladder and from which r each serves: N serves
  // r >= rmin(N), the smallest r >= 2 with (2r)^(-2N)-like truncation below
  // eps/64 relative: rho(r)^(-2N) 16 r^2 <= eps/64 (the factor r^2: the
  // integrand's pole part is ~r^2 times the integral, which is small because
  // cos tau - cos ep vanishes at the end). Independent of beta: computed once
  // per type for the built-in floating types (an immutable function-local
  // static), per call for the others (whose eps may be set at run time).
  struct rung_plan {
    int N;
    T rmin;
  };
  struct rung_plans {
    std::vector<rung_plan> v;
  };
  static rung_plans make_ladder_plan() {
    using std::acosh;
    using std::log;
    rung_plans out;
    const T L = log(1024 / eps<T>());
    auto need = [&](const T &r) { return (L + 2 * log(r)) / (2 * acosh(r)); };
    for (int N : {4, 6, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 256}) {
      rung_plan r{N, T(2)};
      if (need(T(2)) > N) {
        T lo = 2, hi = 2;
        while (need(hi) > N) hi *= 2;
        for (int it = 0; it < 200 && hi - lo > hi / 64; ++it) {
          const T m = (lo + hi) / 2;
          (need(m) > N ? lo : hi) = m;
        }
        r.rmin = hi;
      }
      out.v.push_back(r);
      if (!(r.rmin > 2)) break;
    }
    if (out.v.back().rmin > 2)
      throw error(status::bad_option, "flat punch: precision beyond the Gauss ladder of the pressure");
    return out;
  }
  static rung_plans ladder_plan() {
    if constexpr (std::is_floating_point<T>::value) {
      static const rung_plans plans = make_ladder_plan();
      return plans;
    } else {
      return make_ladder_plan();
    }
  }
  // g(beta) = pi - 2 asin(beta) - sin(2 asin beta) = 2ep - sin(2ep), ep = acos(beta)
  static T load_factor(const T &beta) {
    using std::acos;
    return y_minus_sin(2 * acos(beta));
  }
  // d g / d beta = -4 sqrt(1 - beta^2)
  static T load_factor_derivative(const T &beta) {
    using std::sqrt;
    return -4 * sqrt((1 - beta) * (1 + beta));
  }
  // Contact half-width a from the load: a^2 g(b_f/a) = 2 A R P (A: plane-strain
  // compliance, R: corner radius). Returns a > b_f (Newton in a, bracketed).
  static T half_width_from_load(const T &P, const T &A, const T &R, const T &bf) {
    if (!(P > 0) || !(A > 0) || !(R > 0) || !(bf >= 0))
      throw error(status::bad_geometry, "flat punch: need P, A, R > 0 and b_f >= 0");
    if (bf == 0) {  // Hertz: a^2 pi = 2 A R P
      using std::sqrt;
      return sqrt(2 * A * R * P / pi<T>());
    }
    // with a = bf / beta: bf^2 g(beta)/beta^2 = 2ARP, decreasing in beta
    const T target = 2 * A * R * P / (bf * bf);
    const T beta = solve_ratio(target);
    return bf / beta;
  }
  // Half-width c/a of the same punch under the load (1 - q) P, for
  // beta = b_f/a: c^2 g(beta/c) = (1 - q) g(beta), c in (beta, 1]. This is
  // the Ciavarella-Jager stick half-width under shear q = Q/fP.
  static T reduced_load_half_width(const T &beta, const T &q) {
    if (beta == 0) {
      using std::sqrt;
      return sqrt(1 - q);
    }
    const T target = (1 - q) * load_factor(beta) / (beta * beta);
    return beta / solve_ratio(target);
  }

  T phi(const T &x, const T &dm, const T &dp) const override { return eval(x, dm, dp, nullptr); }
  T dphi(const T &x, const T &dm, const T &dp) const override {
    T d;
    eval(x, dm, dp, &d);
    return d;
  }
  T phi_dphi(const T &x, const T &dm, const T &dp, T &d) const override { return eval(x, dm, dp, &d); }
  // (phi' to ~eps^(3/4) relative, see above: a Newton step's linear error is that
  // times the step, far below any step the solver skips)
  bool exact_dphi() const override { return true; }
  std::vector<breakpoint<T>> breakpoints() const override {
    if (beta_ == 0) return {};
    return {{-beta_, true}, {beta_, true}};
  }
  bool symmetric() const override { return true; }
  // Ciavarella-Jager: the contact half-width of the same punch under (1 - q) P
  bool shear_only_half_width(const T &q, T &c) const override {
    if (!(q >= 0) || !(q < 1)) return false;
    c = reduced_load_half_width(beta_, q);
    return true;
  }
  // the edge coefficient phi(+-1) = (ep + sin ep + T(-1)) / g, exactly (the
  // default extrapolation errs by ~(h/(1 - beta))^3: 3e-9 at beta = 0.999)
  T edge_phi(int) const override {
    if (beta_ == 0) return T(1);
    return eval(T(1), T(2), T(0), nullptr);
  }
  T beta() const { return beta_; }
  // The switches of the evaluation (tests/test_switches.cpp), each a threshold
  // in D = 1 - X (X = |x| or -|x|, see above): the closed forms below
  // closed_form_distance() (tau* = 2 ep), the Gauss ladder above, with the
  // order of rung j from ladder_distances()[j] up (the rungs by increasing
  // order); below series_distance() the corner's derivative takes its series.
  static T closed_form_limit() { return T(2); }
  T closed_form_distance() const { return dclosed_; }
  std::vector<T> ladder_distances() const {
    std::vector<T> v;
    for (const auto &r : ladder_) v.push_back(r.dmin);
    return v;
  }
  std::vector<int> ladder_orders() const {
    std::vector<int> v;
    for (const auto &r : ladder_) v.push_back(int(2 * r.count));
    return v;
  }
  T series_distance() const { return dseries_; }

 private:
  struct rung {
    T rmin, dmin;  // r = tau*/ep from which the rung serves, and 1 - cos(rmin ep) (> 2: never)
    // its nodes in nodes_ from 2 first on: (1 - cos tau, w (cos tau - cos ep)) for each
    std::size_t first = 0, count = 0;
  };
  // T(X) and (if d) dT/dX, from D = 1 - X = 1 - cos tau* and Dc = 1 + X (each
  // formed by the caller from the exact edge distance). 1 - cos tau* grows with
  // tau* on [0, pi], so every switch in r = tau*/ep is a threshold in D.
  // (sh_, ch_: sqrt(D/2) and sqrt(Dc/2), which the closed forms use; eval forms
  // them once for both terms, whose D and Dc are swapped)
  T term(const T &D, const T &sh_, const T &ch_, T *d) const {
    using std::abs;
    using std::asin;
    using std::log;
    using std::log1p;
    using std::sqrt;
    if (D >= dclosed_) {
      std::size_t j = 0;
      while (j + 1 < ladder_.size() && ladder_[j].dmin > D) ++j;
      const rung &R = ladder_[j];
      const T *nd = nodes_.data() + R.first;
      T s = 0, sd = 0;
      if constexpr (!inplace_loops<T>::value) {
        for (std::size_t k = 0; k < R.count; ++k, nd += 2) {
          const T inv = 1 / (D - nd[0]);
          const T f = nd[1] * inv;
          s += f;
          sd += f * inv;
        }
      } else {
        // the same operations in place (no temporary a term; issue 16: this sum is
        // most of a flat-punch solve in the reference backend), and sd only if asked
        T dt, inv, f;
        for (std::size_t k = 0; k < R.count; ++k, nd += 2) {
          dt = D;
          dt -= nd[0];
          inv = 1;
          inv /= dt;
          f = nd[1];
          f *= inv;
          s += f;
          if (d) {
            f *= inv;
            sd += f;
          }
        }
      }
      if (d) *d = sd;
      return s;
    }
    // sin and cos of tau*/2 from D = 1 - cos tau* and Dc = 1 + cos tau*; then
    // sin a, sin b, cos a, cos b by the addition theorems (no trigonometric call)
    // (at the kink D = 1 - beta exactly: sin b = 0, T = ep)
    const T &sh = sh_, &ch = ch_;
    // sin b = (sin^2(tau*/2) - sin^2(ep/2))/sin a = (D - (1 - beta))/(2 sin a): the
    // difference D - (1 - beta) of two numbers known exactly near the kink (Sterbenz)
    const T sa = sh * ce2_ + ch * se2_, sb = (D - omb_) / (2 * sa);
    const T st = 2 * sh * ch;         // sin tau*
    const T omcc = omb_ + beta_ * D;  // 1 - cos ep cos tau*, without cancellation
    if (sb > 0) {
      const T lam = log1p(2 * ch * se2_ / sb);  // ln(sin a / sin b)
      if (d) *d = (lam * omcc - sep_ * st) / (st * st * st);
      return ep_ - sa * sb / (sh * ch) * lam;
    }
    if (sb == 0) {
      // the kink: T = ep; dT/dX is log-singular there, its finite part is returned
      if (d) *d = (log(sa) * omcc - sep_ * st) / (st * st * st);
      return ep_;
    }
    const T nb = -sb;  // sin(-b) > 0
    const T u = 2 * ce2_ * sh / nb;
    T L, Lp;  // ln(1 + u)/u and its derivative
    if (u < T(0.125)) {
      // L = sum_k (-u)^k/(k+1), L' = sum_{k>=1} k (-1)^k u^(k-1)/(k+1): alternating, |u| < 1/8
      L = 1;
      Lp = 0;
      T pk = 1;  // (-1)^(k-1) u^(k-1)
      int k = 1;
      for (; k < 1000; ++k) {
        const T tl = -pk * u / T(k + 1), tp = -pk * T(k) / T(k + 1);
        L += tl;
        Lp += tp;
        if (!(abs(tp) > eps<T>() * abs(Lp) / 8)) break;
        pk *= -u;
      }
      check_iterations(k, 1000, "flat punch: the series of ln(1+u)/u did not converge");
    } else {
      L = log1p(u) / u;
      Lp = (1 / (1 + u) - L) / u;
    }
    const T val = ep_ + 2 * ce2_ * sa * L / ch;
    if (d) {
      if (D < dseries_) {
        // even series in tau*: dT/dX = -(dT/dtau*)/sin tau*
        //   = -(2 T2 + 4 T4 tau*^2 + 6 T6 tau*^4 + 8 T8 tau*^6) tau*/sin tau*
        const T ts = 2 * asin(sh), t2 = ts * ts;
        *d = -(2 * t2_ + t2 * (4 * t4_ + t2 * (6 * t6_ + t2 * 8 * t8_))) * (st > 0 ? T(ts / st) : T(1));
      } else {
        // dT/dtau* = 2 cos(ep/2) [cos(a)/2 L/ch + sin(a) L' u' / ch + sin(a) L sh/(2 ch^2)],
        // u' = du/dtau* = 2 cos(ep/2) [ch/(2 nb) + sh cos(-b)/(2 nb^2)]
        const T ca = ch * ce2_ - sh * se2_, cb = ch * ce2_ + sh * se2_;
        const T up = ce2_ * (ch / nb + sh * cb / (nb * nb));
        const T dts = 2 * ce2_ * (ca * L / (2 * ch) + sa * Lp * up / ch + sa * L * sh / (2 * ch * ch));
        *d = -dts / st;
      }
    }
    return val;
  }
  // phi and (if d) phi' = d phi / dx.
  T eval(const T &x, const T &dm, const T &dp, T *d) const {
    using std::min;
    if (beta_ == 0) {
      if (d) *d = 0;
      return T(1);
    }
    const T dist = min(dm, dp);  // 1 - |x|
    T dpl = 0, dmi = 0;
    // X = |x|: 1 - X = dist; X = -|x|: 1 - X = 2 - dist
    const T dist2 = 2 - dist;
    T a = 0, b = 0;  // sqrt(dist/2), sqrt((2 - dist)/2): only the closed forms need them
    if (dist < dclosed_ || dist2 < dclosed_) {
      using std::sqrt;
      a = sqrt(dist / 2);
      b = sqrt(dist2 / 2);
    }
    const T tp = term(dist, a, b, d ? &dpl : nullptr);
    const T tm = term(dist2, b, a, d ? &dmi : nullptr);
    if (d) {
      // d/d|x| [T(|x|) + T(-|x|)] = T'(|x|) - T'(-|x|)
      const T dd = (dpl - dmi) / g_;
      *d = x < 0 ? -dd : dd;
    }
    return (tp + tm) / g_;
  }
  // beta in (0, 1) with g(beta)/beta^2 = target (decreasing in beta from +inf to 0).
  // Newton on g/b^2 - target, bracketed, its sign and step taken from F = g - target b^2,
  // without b^3 or g/b^2: at target ~ 1e235 (fuzz_dimensional, CI 2026-11-27: P = 7.6e260,
  // R = 2.1e32, b_f = 8.5e32, E* = 6.5e-8) the bisection reached b ~ 2e-103 where
  // 2 g/b^3 overflowed to inf, the step h/dh was 0 and the loop took b, 1e14 times
  // too large, as converged. The start sqrt(pi/target) is beta to O(beta) for large
  // targets (g(b) = pi - 4b + O(b^3)); from 1/2 the search halves b a step at a time,
  // ~390 steps down to the 1e-117 of this input.
  static T solve_ratio(const T &target) {
    using std::abs;
    using std::sqrt;
    if (!(target > 0)) throw error(status::bad_geometry, "flat punch: load must be positive");
    T lo = 0, hi = 1, b = T(0.5);
    if (target > 4 * pi<T>()) b = sqrt(pi<T>() / target);
    int it = 0;
    for (; it < 400; ++it) {
      const T g = load_factor(b);
      const T F = g - (target * b) * b;
      if (F > 0) lo = b;
      else hi = b;
      // Newton's step on h = g/b^2 - target, h/h' = F b / (g' b - 2 g), without b^3
      T nb = b - F * b / (load_factor_derivative(b) * b - 2 * g);
      // (a Newton step below half an ulp of b leaves nb = b, the bracket end just
      // set: that is convergence, not a reason to bisect; bisecting there took
      // ~30 more iterations back to the same b: 37 and 56 in all at b_f/a = 0.5,
      // q = 0.3 and 0.6, now 6 and 7)
      if (!(nb >= lo && nb <= hi)) nb = (lo + hi) / 2;
      const T step = abs(nb - b);
      b = nb;
      if (step <= 2 * eps<T>() * b || hi - lo <= 2 * eps<T>() * b) break;
    }
    check_iterations(it, 400, "flat punch: the half-width from the load did not converge");
    return b;
  }
  T beta_, g_;
  T ep_{0}, ce2_{0}, se2_{0}, sep_{0}, cep_{0};      // acos(beta); cos, sin of ep/2; sin, cos of ep
  T omb_{0};                                         // 1 - beta
  T tau_series_{0}, t2_{0}, t4_{0}, t6_{0}, t8_{0};  // corner derivative: switch and series coefficients
  T dclosed_{0}, dseries_{0};                        // the switches tau* = 2 ep and tau* = tau_series_ in D
  // 1 - cos(tau) for tau in [0, pi]; 3 (above every D) beyond pi
  static T vers_of(const T &tau) {
    using std::sin;
    if (!(tau <= pi<T>())) return T(3);
    const T s = sin(tau / 2);
    return 2 * s * s;
  }
  std::vector<rung> ladder_;
  std::vector<T> nodes_;  // the rungs' nodes (rung)
};

// ---------------------------------------------------------------------------
// c. Symmetric power-law profile g(x) = A |x|^n, n > 1, bounded at both ends.
// The half-plane inversion gives (derivation: docs; verified with mpmath)
//   p_hat(x) = (n/2) sqrt(1-x^2) F(x),  F(x) = int_0^1 (x^2 + (1-x^2) v^2)^((n-2)/2) dv
//            = 2F1(1, 1 - n/2; 3/2; 1 - x^2),
// normalised so that int p_hat = pi/2 (P = (n/2) ... is not needed: the
// dimensionless pressure depends on n only; P is proportional to a^n).
// F is evaluated by (every form free of cancellation for large n, issue 13)
//   z = 1 - x^2 <= 1/2: Euler's transformation (1-z)^((n-1)/2) 2F1(1/2, (n+1)/2; 3/2; z),
//     a series of positive terms (the series of 2F1 in z alternates);
//   n even, z > 1/2: the binomial sum sum_j C(k,j) z^j (1-z)^(k-j)/(2j+1), k = n/2 - 1;
//   x^2 < 1/2, m = (n-1)/2 not within 1/8 of an integer: the connection
//     formula  F = 2F1(1, 1/2-m; 1-m; x^2)/(2m)
//                 + |x|^(2m) (sqrt(pi)/2) Gamma(-m)/Gamma(1/2-m) / sqrt(1-x^2);
//   n odd: the recurrence I_p = (1 + 2 p x^2 I_{p-1})/(2p+1) from
//     I_{-1/2} = asinh(sqrt(1-x^2)/|x|)/sqrt(1-x^2);
//   otherwise (m = k + delta near an integer k): the same recurrence, which holds
//     for every real p (integration by parts of the definition), k steps from
//     F at the exponent 1 + 2 delta, that by the connection formula regrouped
//     around delta = 0 (F_near_int; issue 13: was a tanh-sinh integral per value).
// x = 0 is a graded breakpoint unless n is an even integer (F is then a polynomial).
template <class T> class power_law_pressure final : public pressure_model<T> {
 public:
  explicit power_law_pressure(const T &n) : n_(n) {
    using std::abs;
    using std::floor;
    if (!(n > 1) || !(n < 1000)) throw error(status::bad_geometry, "power law: need 1 < n < 1000");
    m_ = (n - 1) / 2;
    const T hn = n / 2;
    even_ = floor(hn) == hn;
    const T mr = floor(m_ + T(0.5));
    odd_ = (mr == m_);
    // Near an integer k = round(m) the connection formula's two parts, each ~ y^k/delta
    // (delta = m - k), cancel, and its series S must be summed past its pole term j = k
    // (~ y^k/delta times the one before it), which the stopping test on small terms
    // skips for small y and large k: F was off by 1e4 eps at n = 61 + 2^-19, x = 1/2
    // (issue 13; the old band |delta| < n 2^-m sent such n to the connection formula).
    // For |delta| < 1/8, every k, F is a series and k steps of a recurrence
    // (F_near_int); before, for 1 <= k it was a tanh-sinh integral per value: n = 6.79
    // near sliding took 6-13 s a solve, and NO_CONVERGENCE after 30-64 s at
    // 1 - Q/fP = 4.5e-11 (and with that band for every m, n = 307.2 took 17 s); for
    // k = 0 n = 1.05 took 4.5-8.9 s, n = 1.02 at Q/fP = 0.9977, sigma/fp0 = 3 ran 38 s
    // and failed (issue 13). delta = m - k is exact (Sterbenz).
    near_int_ = !odd_ && abs(m_ - mr) < T(0.125);
    if (near_int_) {
      k_ = int(mr);
      delta_ = m_ - mr;
      lnc_ = log_connection_near_zero(delta_);
    }
    if (!even_ && !odd_ && !near_int_)
      // (sqrt(pi)/2) Gamma(-m)/Gamma(1/2 - m) by reflection,
      // = -(sqrt(pi)/2) cot(pi m) Gamma(m + 1/2)/Gamma(m + 1): the two Gammas
      // of negative argument underflow to 0/0 from m ~ 170 (n = 999.1 gave NaN)
      conn_ = -boost::math::constants::root_pi<T>() / 2 * boost::math::cos_pi(m_) / boost::math::sin_pi(m_) *
              boost::math::tgamma_delta_ratio(T(m_ + T(0.5)), T(0.5));
    if constexpr (std::numeric_limits<T>::digits10 > std::numeric_limits<long double>::digits10) make_tables();
  }
  // Contact half-width from the load per unit length P of the profile
  // g = coef |x|^n (E*: contact modulus; coef > 0 (bad_size) and 1 < n < 1000
  // (bad_geometry) are checked here, P and E* by the caller):
  //   a^n = 2 P Gamma(n/2+1) / (E* n coef sqrt(pi) Gamma((n+1)/2)),
  // directly (a few rounding errors, divided by n in a), or in logarithms
  // where a^n under- or overflows.
  static T half_width_from_load(const T &P, const T &Estar, const T &coef, const T &n) {
    using std::exp;
    using std::isnormal;
    using std::lgamma;
    using std::log;
    using std::pow;
    using std::sqrt;
    if (!(coef > 0)) throw error(status::bad_size, "power law: profile coefficient must be > 0");
    if (!(n > 1) || !(n < 1000)) throw error(status::bad_geometry, "power law: need 1 < n < 1000");
    const T ratio = exp(lgamma(n / 2 + 1) - lgamma((n + 1) / 2));
    // the direct formula where its intermediates are normal numbers; else in logarithms
    // (issue 13, fuzz_dimensional: E* = 1.8e-19 with A = 4e-300 made the denominator
    // subnormal and a wrong by 3e-9 although a^n was a normal number)
    const T en = Estar * n, enc = en * coef, den = enc * sqrt(pi<T>());
    const T an = 2 * P / den * ratio;
    if (isnormal(an) && isnormal(P) && isnormal(Estar) && isnormal(en) && isnormal(enc) && isnormal(den) &&
        isnormal(T(2 * P)))
      return pow(an, 1 / n);
    return exp((log(P) + log(T(2)) + lgamma(n / 2 + 1) - lgamma((n + 1) / 2) - log(Estar) - log(n) - log(coef) -
                T(0.5) * log(pi<T>())) /
               n);
  }
  T phi(const T &x, const T &dm, const T &dp) const override {
    using std::min;
    const T dist = min(dm, dp);
    const T z = dist * (2 - dist);  // 1 - x^2
    return n_ / 2 * F(x, z);
  }
  // phi and phi' together beyond long double (the reference backend's tiers):
  // phi' from F alone. With I_p = int_0^1 (y + z v^2)^p dv (F = I_p, p = n/2 - 1,
  // y = x^2, z = 1 - y), d/dy under the integral and y + z v^2 = y (1 - v^2) + v^2
  // give dI_p/dy = p (I_(p-1) - I_p)/z, and the recurrence I_p = (1 + 2p y I_(p-1))/(2p + 1)
  // (F_near_int) removes I_(p-1):
  //   dF/dx = 2x dF/dy = ((1 + (n - 2) z) F - 1)/(x z).
  // (n = 4: F = 1/3 + 2x^2/3, ((1 + 2z)(1 - 2z/3) - 1)/(xz) = 4x/3.) The numerator
  // cancels to O(z) near the edges and to O(F - F(0)) near x = 0: the relative error
  // is ~ eps/z + eps/|x|^2 n, below the central difference's eps^(2/3) wherever
  // z and x^2 exceed n eps^(1/3); elsewhere (and at x = 0, a breakpoint that is no
  // node) the central difference of the base class as before. One F per node in
  // place of three (the central difference): the Jacobians of the power law's
  // solve at MPFR were two thirds of its time (issue 16). Used only in Newton
  // Jacobians, never in a residual. Double and long double keep the central
  // difference, except for n < 3 at every x != 0 with z above the limit (issue 13,
  // near sliding, round two): there p has a cusp ~|x|^(n-1) at x = 0 whose phi' the
  // central difference (step ~3e-6 in double) misses at the graded panel's nodes
  // near 0 (n = 1.5, x = 1e-6: off by 80 %, x = 1e-9: by 100 %), while the closed
  // form's numerator is ~|x|^(n-1) there (relative error ~eps/|x|^(n-1)). Near
  // sliding the Jacobian's moment row is ~1e-9 and took that error whole (J21
  // -1.7e-5 for -3e-9 at n = 1.5, 1 - Q/fP = 1e-10, sigma/fp0 = 1): Newton stalled.
  T phi_dphi(const T &x, const T &dm, const T &dp, T &d) const override {
    using std::abs;
    using std::cbrt;
    using std::min;
    {
      constexpr bool mp = std::numeric_limits<T>::digits10 > std::numeric_limits<long double>::digits10;
      const T dist = min(dm, dp);
      const T z = dist * (2 - dist);  // 1 - x^2
      const T lim = (n_ > 1 ? n_ : T(1)) * cbrt(eps<T>());
      // (for 2 < n < 3 the closed form's relative error eps/|x|^(n-1) exceeds the central
      // difference's (which straddles the cusp, ~|x|^(n-2) absolute) where |x|^(n-1) < 64 eps:
      // n = 2.5 at |x| < 6e-10; review of session 13)
      using std::pow;
      if (z > lim && x != 0 && (mp ? x * x > lim : (n_ < 3 && pow(abs(x), n_ - 1) > 64 * eps<T>()))) {
        const T f = F(x, z);
        d = n_ / 2 * (((1 + (n_ - 2) * z) * f - 1) / (x * z));
        return n_ / 2 * f;
      }
    }
    d = this->dphi(x, dm, dp);
    return phi(x, dm, dp);
  }
  // x = 0 (graded unless n is even); for large n also plain splits at the
  // distances 2^k/n from each edge (k >= 0, up to 1/4): phi rises from ~1/2 in
  // the middle to n/2 at the edges across an edge layer of width ~1/n (a pole of
  // phi at distance ~ -1/n), which one panel reaching to the edge resolved only at
  // orders of several hundred (issue 13: n = 999 at sigma/fp0 = 100 ran 18 s and
  // failed; the quadrature of F2 at orders 32 and 64 differed by 3e-4)
  std::vector<breakpoint<T>> breakpoints() const override {
    std::vector<breakpoint<T>> b;
    if (n_ >= edge_split_min()) {
      for (T dist = 1 / n_; dist <= T(0.25); dist *= 2) {
        b.push_back({dist - 1, false});
        b.push_back({1 - dist, false});
      }
    }
    if (!even_) b.push_back({T(0), true});
    std::sort(b.begin(), b.end(), [](const breakpoint<T> &u, const breakpoint<T> &v) { return u.x < v.x; });
    return b;
  }
  // the exponent from which the edge layer gets its splits
  static T edge_split_min() { return T(16); }
  bool symmetric() const override { return true; }
  T accuracy_eps() const override { return n_ > 4 ? n_ : T(4); }
  T edge_phi(int) const override { return n_ / 2; }  // F(+-1) = 2F1(..; 0) = 1
  // Ciavarella-Jager: the stick zone under shear alone is the contact under
  // P(1 - q), and P ~ a^n, so c = (1 - q)^(1/n) (log1p: no cancellation for
  // small q). The solver's start: at large n the Hertz start (d = q/2 instead
  // of ~ -ln(1-q)/n) left Newton without a path (issue 13: n = 500, sigma = 0).
  bool shear_only_half_width(const T &q, T &c) const override {
    using std::exp;
    using std::log1p;
    if (!(q >= 0) || !(q < 1)) return false;
    c = exp(log1p(-q) / n_);
    return true;
  }

  T F(const T &x, const T &z) const {
    using std::abs;
    using std::asinh;
    using std::pow;
    using std::sqrt;
    const T y = x * x;
    const T e = eps<T>();
    if (!(z == z)) return z;  // NaN: the tests below would never hold
    if (z <= T(0.5)) {
      // Euler's transformation, F = (1 - z)^((n-1)/2) 2F1(1/2, (n+1)/2; 3/2; z)
      // (DLMF 15.8.1): every term positive. The series in z itself,
      // sum_j (1 - n/2)_j/(3/2)_j z^j, alternates with terms up to ~e^(n z/2)
      // and lost everything to cancellation for large n (issue 13: F off by
      // 1e-9 relative at n = 50, by 1e13 at n = 200). Terms grow up to
      // j ~ (n+1) z/(2(1-z)) <= (n+1)/2, then fall at least like z^j.
      T term = 1, sum = 1, zj = 1;
      const T b = (n_ + 1) / 2;
      const int nt = int(euler_.size());
      int j = 0;
      for (; j < 100000; ++j) {
        if (j < nt) {
          zj *= z;
          term = euler_[j] * zj;
        } else {
          term *= (T(0.5) + j) * (b + j) / ((T(1.5) + j) * (j + 1)) * z;
        }
        sum += term;
        if (term <= e * sum / 4 && T(j) > b * z) break;
      }
      check_iterations(j, 100000, "power law: the series of F did not converge");
      using std::pow;
      return pow(abs(x), n_ - 1) * sum;
    }
    if (even_) {
      // n = 2k + 2 even, y = x^2 < 1/2: binomial expansion of the definition,
      // F = int_0^1 (y + z v^2)^k dv = sum_j C(k, j) z^j y^(k-j)/(2j + 1),
      // every term positive (the terminating series in z alternates: see above).
      // From j = k down: w_k = z^k, w_(j-1) = w_j j/(k - j + 1) y/z.
      const int k = int(n_ / 2) - 1;
      T w = pow(z, T(k)), sum = w / (2 * k + 1);
      for (int jj = k; jj > 0; --jj) {
        w *= T(jj) / T(k - jj + 1) * y / z;
        sum += w / (2 * jj - 1);
        if (w <= e * sum / 4 && T(jj) < T(k) * z) break;
      }
      return sum;
    }
    if (odd_) {
      const T ax = abs(x), be = sqrt(z);
      if (ax == 0) return 1 / (n_ - 1);
      T I = asinh(be / ax) / be;
      for (T p = T(0.5); p <= (n_ - 2) / 2 + T(0.25); p += 1) I = (1 + 2 * p * y * I) / (2 * p + 1);
      return I;
    }
    if (near_int_) return F_near_int(x, y, z);
    // 2F1(1, 1/2 - m; 1 - m; y), y < 1/2
    if (!(y == y)) return y;  // NaN: the test below would never hold
    T term = 1, sum = 1, yj = 1;
    const T b = T(0.5) - m_, c = 1 - m_;
    const int nt = int(conn_series_.size());
    int j = 0;
    for (; j < 100000; ++j) {
      if (j < nt) {
        yj *= y;
        term = conn_series_[j] * yj;
      } else {
        term *= (b + j) / (c + j) * y;
      }
      sum += term;
      // term = the coefficient j + 1 times y^(j+1). Before the largest ratio (j + 1 < m)
      // the terms still to come fall by ratios y (1 + 1/(2(m - i - 1))) <= 0.72
      // (m - i - 1 >= 9/8), then jump once by at most (1 + 4) y <= 2.5 (m - i - 1 =
      // frac(m) in [1/8, 7/8] here), then fall by ratios < y: their sum is at most
      // ~8 times this term (y < 1/2); the factor 16 keeps the truncation below eps/4.
      if (abs(term) * (T(j + 1) < m_ ? 16 : 1) <= e * abs(sum) / 4) break;
    }
    check_iterations(j, 100000, "power law: the hypergeometric series of F did not converge");
    return sum / (2 * m_) + pow(abs(x), 2 * m_) * conn_ / sqrt(z);
  }

 private:
  // F for m = k + delta, k = round(m) >= 0, 0 < |delta| < 1/8, y = x^2 < 1/2, z = 1 - y.
  // With I_p = int_0^1 (y + z v^2)^p dv, F = I_(m - 1/2), integration by parts of
  // d/dv [v (y + z v^2)^p] gives for every real p (y > 0)
  //   I_p = (1 + 2 p y I_(p-1)) / (2p + 1),
  // the recurrence of the odd-n branch: k steps, p = delta + 1/2, ..., m - 1/2, from
  // F_delta = I_(delta - 1/2), F at the exponent 1 + 2 delta. Each step adds two
  // positive terms, and the share 2 p y I_(p-1)/(2p + 1 + ...) of the old value is
  // below ~1/2 for y < 1/2: the relative error stays a few eps (it does not grow with k).
  // F_delta by the connection formula regrouped around delta = 0 (F_delta, below).
  // At x = 0, F = int_0^1 v^(n-2) dv = 1/(n-1) directly (F_delta is infinite there
  // for delta < 0). Checked against 50-digit quadrature of the definition in
  // tests/test_switches.cpp; derivation in docs/models.md ("Power law near odd n").
  T F_near_int(const T &x, const T &y, const T &z) const {
    if (!(y == y)) return y;  // NaN: the series' stopping test would never hold
    if (x == 0) return 1 / (n_ - 1);
    T I = F_delta(x, y, z);
    for (int i = 1; i <= k_; ++i) {
      const T p = delta_ + T(i) - T(0.5);
      I = (1 + 2 * p * y * I) / (2 * p + 1);
    }
    return I;
  }
  // F at the exponent 1 + 2 delta, 0 < |delta| < 1/8, x != 0, y = x^2 < 1/2, z = 1 - y.
  // The connection formula (d = delta)
  //   F = S(y)/(2d) + |x|^(2d) conn/sqrt(z),  S = 2F1(1, 1/2 - d; 1 - d; y),
  //   conn = -c(d)/(2d),  c(d) = pi d cot(pi d) Gamma(1/2 + d)/(Gamma(1/2) Gamma(1 + d))
  //                            = sqrt(pi) Gamma(1 - d)/Gamma(1/2 - d) -> 1,
  // has two parts ~ 1/(2d sqrt z) that cancel to F = O(1) (the n = 1 limit is
  // asinh(sqrt(z)/|x|)/sqrt(z)). Regrouped around the d = 0 terms (S(y; 0) = 1/sqrt(z)):
  //   F = A + B,  A = (S(y) - 1/sqrt(z))/(2d) = (1/2) sum_(j>=1) r_j e_j y^j,
  //   B = -expm1(2d ln|x| + ln c(d)) / (2d sqrt(z)),
  // with r_j = (1/2)_j/j! and e_j = (S's j-th coefficient / r_j - 1)/d by the exact
  // recurrence e_j = e_(j-1) g_j + h_j, g_j = j (j - 1/2 - d)/((j - 1/2)(j - d)),
  // h_j = -1/((2j - 1)(j - d)): every term of A negative (either sign of d) and formed
  // without cancellation. B > 0: for d > 0 expm1's argument is negative (|x| < 1,
  // ln c ~ -2 ln2 d), for d < 0 positive; either way expm1 is accurate to a few eps
  // relative (an argument of size t carries ~t eps, t <= |2d ln|x|| + 1, large only
  // where |x| is so small that y F_delta is negligible next to 1 in F_near_int).
  // A + B cancels mildly (|A/2| < B, F ~ 1.2 at y = 1/2 against B ~ 1.5).
  T F_delta(const T &x, const T &y, const T &z) const {
    using std::abs;
    using std::expm1;
    using std::log;
    using std::sqrt;
    const T e = eps<T>();
    const T &d = delta_;
    T ej = 0, rj = 1, yj = 1, A = 0;
    int j = 1;
    for (; j < 100000; ++j) {
      const T jj = T(j);
      ej = ej * (jj * (jj - T(0.5) - d) / ((jj - T(0.5)) * (jj - d))) - 1 / ((2 * jj - 1) * (jj - d));
      rj *= (jj - T(0.5)) / jj;
      yj *= y;
      const T term = rj * ej * yj;
      A += term;
      if (abs(term) <= e * abs(A) / 4) break;
    }
    check_iterations(j, 100000, "power law: the series of F near an odd n did not converge");
    const T B = -expm1(2 * d * log(abs(x)) + lnc_) / (2 * d * sqrt(z));
    return A / 2 + B;
  }
  // ln c(m) for 0 < |m| < 1/8, to a few eps relative (c - 1 = O(m) must not be
  // formed as a difference): ln(pi m cot(pi m)) = ln cos u - ln(sin u / u), u = pi m,
  // by log1p of -2 sin^2(u/2) and of the sine series; and
  // ln Gamma(1/2 + m) - ln Gamma(1/2) - ln Gamma(1 + m)
  //   = -2 ln2 m + sum_(k>=2) (-1)^k (2^k - 2) zeta(k) m^k / k
  // (the Taylor series of ln Gamma at 1 and 1/2: psi(1/2) - psi(1) = -2 ln 2,
  // psi^(k-1)(1/2) = (-1)^k (k-1)! (2^k - 1) zeta(k)); terms fall like (2m)^k <= 4^-k.
  static T log_connection_near_zero(const T &m) {
    using std::abs;
    using std::log;
    using std::log1p;
    using std::sin;
    const T e = eps<T>();
    const T u = pi<T>() * m, u2 = u * u;
    T sr = 0, term = 1;  // sin(u)/u - 1
    int k = 1;
    for (; k < 1000; ++k) {
      term *= -u2 / T((2 * k) * (2 * k + 1));
      sr += term;
      if (abs(term) <= e * abs(sr) / 4) break;
    }
    check_iterations(k, 1000, "power law: the sine series near n = 1 did not converge");
    const T s2 = sin(u / 2);
    T L = log1p(-2 * s2 * s2) - log1p(sr);
    T G = -2 * boost::math::constants::ln_two<T>() * m, mk = m, p2 = 2;
    for (k = 2; k < 1000; ++k) {
      mk *= m;
      p2 *= 2;
      const T t = (k % 2 ? -1 : 1) * (p2 - 2) * boost::math::zeta(T(k)) * mk / T(k);
      G += t;
      if (abs(t) <= e * abs(G) / 4) break;
    }
    check_iterations(k, 1000, "power law: the log-gamma series near n = 1 did not converge");
    return L + G;
  }

  // Beyond long double (the reference backend's tiers; issue 16): the coefficients
  // of F's two long series, independent of x, once per model, so that a term costs
  // two products instead of a quotient and three products (the series were most of
  // the power law's solve at MPFR). euler_[j]: the coefficient of z^(j+1) in
  // 2F1(1/2, (n+1)/2; 3/2; z); conn_series_[j]: that of y^(j+1) in
  // 2F1(1, 1/2 - m; 1 - m; y). Each table holds the terms F's stopping test needs at
  // the branch's largest argument, 1/2 (its own test, there); F continues by the
  // recurrence past a table's end (smaller arguments need fewer terms, and the
  // rounding is that of the recurrence: ~j eps relative at term j either way).
  // Double and long double build no table (F bitwise unchanged).
  void make_tables() {
    using std::abs;
    const T e = eps<T>(), h = T(0.5);
    {
      const T b = (n_ + 1) / 2;
      T c = 1, hj = 1, sum = 1;
      for (int j = 0; j < 100000; ++j) {
        c *= (T(0.5) + j) * (b + j) / ((T(1.5) + j) * (j + 1));
        euler_.push_back(c);
        hj *= h;
        sum += c * hj;
        if (c * hj <= e * sum / 4 && T(j) > b * h) break;
      }
    }
    if (!even_ && !odd_ && !near_int_) {
      const T b = T(0.5) - m_, cc = 1 - m_;
      T c = 1, hj = 1, sum = 1;
      for (int j = 0; j < 100000; ++j) {
        c *= (b + j) / (cc + j);
        conn_series_.push_back(c);
        hj *= h;
        sum += c * hj;
        if (abs(c * hj) * (T(j + 1) < m_ ? 16 : 1) <= e * abs(sum) / 4) break;
      }
    }
  }
  std::vector<T> euler_, conn_series_;
  T n_, m_, conn_{0}, lnc_{0}, delta_{0};
  int k_ = 0;  // round(m) where near_int_
  bool even_ = false, odd_ = false, near_int_ = false;
};

// ---------------------------------------------------------------------------
// Checks shared by the user-supplied pressures.
namespace detail {
// local exponent of p at an edge from two distances d1 < d2: p ~ d^alpha.
// The declared edge behaviour is alpha = 1/2; accepted in [1/4, 3/4].
// not_sqrt: the message for an exponent outside that range.
template <class T>
void check_edge_exponent(const T &p1, const T &d1, const T &p2, const T &d2,
                         const char *not_sqrt = "pressure must vanish like sqrt(distance) at both contact edges") {
  using std::log;
  if (!(p1 > 0) || !(p2 > 0)) throw error(status::bad_geometry, "pressure must be positive inside the contact");
  const T alpha = log(p2 / p1) / log(d2 / d1);
  if (!(alpha >= T(0.25) && alpha <= T(0.75))) throw error(status::bad_geometry, not_sqrt);
}
}  // namespace detail

// ---------------------------------------------------------------------------
// d1. Sampled pressure (x_i, p_i), dimensional, on a contact of half-width a.
// phi_i = p_i / sqrt(a^2 - x_i^2) is interpolated by a monotone piecewise
// cubic (Fritsch-Carlson / PCHIP slopes) and extrapolated linearly to the
// edges with the end slope; the pressure is sqrt(a^2 - x^2) phi(x). Samples
// at x = +-a must have p = 0 and are not interpolated. Rejected (bad_geometry):
// fewer than 4 interior samples, x not strictly increasing or outside [-a, a],
// a negative p, a zero p inside, and an edge behaviour other than sqrt
// (local exponent from the two outermost interior samples at each edge).
template <class T> class sampled_pressure final : public pressure_model<T> {
 public:
  // where (if not null) receives, when a rule is broken, the index of the
  // sample the rule is about (xs.size(): the samples as a whole), so that a
  // caller can name it (the C ABI's hs_check_samples, the CLI's file line).
  // tree_min: the interior-sample count from which the knot quadrature is
  // used (tests compare both sides of the switch on the same samples).
  sampled_pressure(const std::vector<T> &xs, const std::vector<T> &ps, const T &a, std::size_t *where = nullptr,
                   std::size_t tree_min = knot_tree_min)
      : a_(a) {
    using std::abs;
    using std::sqrt;
    std::size_t at = xs.size();
    auto fail = [&](std::size_t i, status s, const char *msg) {
      if (where) *where = i;
      throw error(s, msg);
    };
    if (!(a > 0)) fail(at, status::bad_size, "sampled pressure: a must be > 0");
    if (xs.size() != ps.size()) fail(at, status::bad_geometry, "sampled pressure: size mismatch");
    T pmax = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (!(ps[i] >= 0)) fail(i, status::bad_geometry, "pressure must not be negative");
      if (i > 0 && !(xs[i] > xs[i - 1])) fail(i, status::bad_geometry, "sample abscissae must increase");
      if (!(xs[i] >= -a && xs[i] <= a)) fail(i, status::bad_geometry, "sample outside the contact");
      pmax = std::max(pmax, ps[i]);
    }
    // the interior samples (|x| < a); the edge rules need the two outermost at each edge
    x_.reserve(xs.size());
    f_.reserve(xs.size());
    std::vector<std::size_t> index;  // input index of the interior samples
    index.reserve(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const T dm = a + xs[i], dp = a - xs[i];
      if (dm == 0 || dp == 0) {
        if (ps[i] > 64 * eps<T>() * pmax) fail(i, status::bad_geometry, "pressure must vanish at the contact edges");
        continue;
      }
      if (!(ps[i] > 0)) fail(i, status::bad_geometry, "pressure must be positive inside the contact");
      x_.push_back(xs[i] / a);
      f_.push_back(ps[i] / sqrt(dm * dp));
      index.push_back(i);
    }
    const std::size_t n = x_.size();
    if (n < 4) fail(at, status::bad_geometry, "sampled pressure: need at least 4 interior samples");
    // distances (units of a) of interior sample k from the edges, and its p
    auto dm_of = [&](std::size_t k) { return T((a + xs[index[k]]) / a); };
    auto dp_of = [&](std::size_t k) { return T((a - xs[index[k]]) / a); };
    auto p_of = [&](std::size_t k) { return ps[index[k]]; };
    try {
      at = index[0];
      detail::check_edge_exponent(p_of(0), dm_of(0), p_of(1), dm_of(1),
                                  "the two samples nearest the edge x = -a do not vanish like sqrt(distance) "
                                  "(local exponent of p outside [1/4, 3/4])");
      at = index[n - 1];
      detail::check_edge_exponent(p_of(n - 1), dp_of(n - 1), p_of(n - 2), dp_of(n - 2),
                                  "the two samples nearest the edge x = +a do not vanish like sqrt(distance) "
                                  "(local exponent of p outside [1/4, 3/4])");
    } catch (const error &e) {
      fail(at, e.code(), e.what());
    }
    // PCHIP slopes
    std::vector<T> h(n - 1), del(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      h[i] = x_[i + 1] - x_[i];
      del[i] = (f_[i + 1] - f_[i]) / h[i];
    }
    d_.assign(n, T(0));
    for (std::size_t i = 1; i + 1 < n; ++i) {
      if (del[i - 1] * del[i] > 0) {
        const T w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
        d_[i] = (w1 + w2) / (w1 / del[i - 1] + w2 / del[i]);
      }
    }
    auto endslope = [](const T &h0, const T &h1, const T &d0, const T &d1) {
      T d = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
      if (d * d0 <= 0) d = 0;
      else if (d0 * d1 <= 0 && abs(d) > abs(3 * d0)) d = 3 * d0;
      return d;
    };
    d_[0] = endslope(h[0], h[1], del[0], del[1]);
    d_[n - 1] = endslope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
    // edge values of phi by linear extrapolation must stay positive
    const T dm0 = dm_of(0), dpn = dp_of(n - 1);
    if (!(f_[0] - d_[0] * dm0 > 0))
      fail(index[0], status::bad_geometry,
           "the samples nearest the edge x = -a extrapolate to a negative p/sqrt(a^2 - x^2) at the edge "
           "(p must vanish like sqrt(distance) there)");
    if (!(f_[n - 1] + d_[n - 1] * dpn > 0))
      fail(index[n - 1], status::bad_geometry,
           "the samples nearest the edge x = +a extrapolate to a negative p/sqrt(a^2 - x^2) at the edge "
           "(p must vanish like sqrt(distance) there)");
    // a panel end at every knot (phi is only C^1 there), built once: the
    // quadratures ask for the list per Cauchy integral (issue 13 item 4)
    // (on the knot path built on demand instead: only the slow reference
    // evaluations and the load histories ask for them there)
    if (n < tree_min) {
      bps_.reserve(n);
      for (const T &x : x_) bps_.push_back({x, false});
    }
    // from knot_tree_min knots on, the product quadrature over the knots
    // (knots.hpp): linear cost in n; below, the quadrature with a panel end at
    // every knot, as before (results unchanged)
    if (n >= tree_min) {
      std::vector<T> X, F, D;
      X.reserve(n + 2);
      F.reserve(n + 2);
      D.reserve(n + 2);
      X.push_back(T(-1));
      F.push_back(f_[0] - d_[0] * dm0);
      D.push_back(d_[0]);
      for (std::size_t i = 0; i < n; ++i) {
        X.push_back(x_[i]);
        F.push_back(f_[i]);
        D.push_back(d_[i]);
      }
      X.push_back(T(1));
      F.push_back(f_[n - 1] + d_[n - 1] * dpn);
      D.push_back(d_[n - 1]);
      kq_ = std::make_shared<knot_quadrature<T>>(std::move(X), std::move(F), std::move(D));
    }
    // normalisation: P = a^2 int_{-1}^{1} sqrt(1-xi^2) phi(xi) dxi (phi dimensional)
    scale_ = 1;
    const T I = kq_ ? kq_->total() : this->tail(+1, T(2));  // int p with scale 1 (phi in p/sqrt units / a)
    P_ = a * a * I;
    p0_ = 2 * P_ / (pi<T>() * a);
    scale_ = a / p0_;
    if (kq_) kq_->set_scale(scale_);
  }
  // the interior-sample count from which the knot quadrature is used
  // (test_switches.cpp); double only: its rules (16 points, eta = 2) and the
  // energies' fast sums (24 terms) are accurate to ~1e-16, not to the rounding
  // of a longer type, which keeps the panel path
  static constexpr std::size_t knot_tree_min = std::numeric_limits<T>::digits <= 53 ? 256 : std::size_t(-1);
  T phi(const T &x, const T &, const T &) const override { return scale_ * interp(x, false); }
  T dphi(const T &x, const T &, const T &) const override { return scale_ * interp(x, true); }
  std::vector<breakpoint<T>> breakpoints() const override {
    if (!kq_) return bps_;
    std::vector<breakpoint<T>> v;
    v.reserve(x_.size());
    for (const T &x : x_) v.push_back({x, false});
    return v;
  }
  knot_view<T> knots() const override { return {kq_.get(), false}; }
  T tail(int side, const T &c) const override { return kq_ ? kq_->tail(side, c) : pressure_model<T>::tail(side, c); }
  std::size_t knot_count() const { return x_.size(); }
  T load() const { return P_; }  // P
  T p0() const { return p0_; }   // 2P/(pi a)
  T half_width() const { return a_; }

 private:
  T interp(const T &x, bool deriv) const {
    const std::size_t n = x_.size();
    if (x <= x_[0]) return deriv ? d_[0] : f_[0] + d_[0] * (x - x_[0]);
    if (x >= x_[n - 1]) return deriv ? d_[n - 1] : f_[n - 1] + d_[n - 1] * (x - x_[n - 1]);
    const std::size_t i = std::upper_bound(x_.begin(), x_.end(), x) - x_.begin() - 1;
    const T h = x_[i + 1] - x_[i], t = (x - x_[i]) / h;
    const T t2 = t * t, t3 = t2 * t;
    if (!deriv)
      return (2 * t3 - 3 * t2 + 1) * f_[i] + (t3 - 2 * t2 + t) * h * d_[i] + (-2 * t3 + 3 * t2) * f_[i + 1] +
             (t3 - t2) * h * d_[i + 1];
    return ((6 * t2 - 6 * t) * f_[i] + (-6 * t2 + 6 * t) * f_[i + 1]) / h + (3 * t2 - 4 * t + 1) * d_[i] +
           (3 * t2 - 2 * t) * d_[i + 1];
  }
  T a_;
  std::vector<T> x_, f_, d_;
  std::vector<breakpoint<T>> bps_;
  std::shared_ptr<knot_quadrature<T>> kq_;
  T scale_{1}, P_{0}, p0_{1};
};

// ---------------------------------------------------------------------------
// d2. User callback p(x), dimensional, on |x| < a (std::function, or a
// function pointer with user data). Optional breakpoints (dimensional) where
// p is not smooth. Validated at 2048 interior points and at every evaluation
// (positive; a negative region narrower than ~1.5e-3 a that no evaluation
// meets cannot be seen) and at the edges (sqrt behaviour: local exponent from
// distances a 2^-10 and a 2^-12).
template <class T> class callback_pressure final : public pressure_model<T> {
 public:
  using fn_type = std::function<T(const T &)>;
  callback_pressure(fn_type fn, const T &a, std::vector<T> kinks = {}) : fn_(std::move(fn)), a_(a) { init(kinks); }
  callback_pressure(T (*fn)(const T &, void *), void *user, const T &a, std::vector<T> kinks = {})
      : fn_([fn, user](const T &x) { return fn(x, user); }), a_(a) {
    init(kinks);
  }
  T phi(const T &x, const T &dm, const T &dp) const override {
    using std::sqrt;
    const T r = dm * dp;
    if (!(r > 0)) return T(0);  // exactly at an edge (zero weight in every integral)
    // every value the solver asks for is checked, not only the 64 points of
    // init: a region where p < 0 narrower than their spacing (~0.05 a) was
    // solved as if it were a pressure (issue 13); the normalisation's adaptive
    // quadrature resolves such a dip, so it meets it there
    const T v = fn_(a_ * x);
    if (!(v >= 0))
      throw error(status::bad_geometry, "pressure callback returned a negative pressure inside the contact");
    return scale_ * v / sqrt(r);
  }
  std::vector<breakpoint<T>> breakpoints() const override { return bps_; }
  T load() const { return P_; }
  T p0() const { return p0_; }

 private:
  void init(const std::vector<T> &kinks) {
    using std::cos;
    using std::ldexp;
    if (!fn_) throw error(status::null_pointer, "pressure callback is null");
    if (!(a_ > 0)) throw error(status::bad_size, "callback pressure: a must be > 0");
    for (const T &k : kinks) {
      if (!(k > -a_ && k < a_)) throw error(status::bad_geometry, "breakpoint outside the contact");
      bps_.push_back({k / a_, true});
    }
    // positivity at 2048 Chebyshev points (spacing <= pi a/2048 ~ 1.5e-3 a; 64
    // before, which missed a dip to p < 0 of width 1.7e-3 a, issue 13), and at
    // every later evaluation (phi)
    for (int i = 0; i < scan_points; ++i) {
      const T x = a_ * cos(pi<T>() * (T(i) + T(0.5)) / scan_points);
      const T v = fn_(x);
      if (!(v > 0)) throw error(status::bad_geometry, "pressure must be positive inside the contact");
    }
    const T d1 = ldexp(a_, -12), d2 = ldexp(a_, -10);
    detail::check_edge_exponent(fn_(-a_ + d1), d1, fn_(-a_ + d2), d2);
    detail::check_edge_exponent(fn_(a_ - d1), d1, fn_(a_ - d2), d2);
    scale_ = 1;
    P_ = a_ * this->tail(+1, T(2));  // int p dx = a int p(a xi) dxi; here phi = p/sqrt(1-xi^2)
    p0_ = 2 * P_ / (pi<T>() * a_);
    scale_ = 1 / p0_;
  }
  static constexpr int scan_points = 2048;
  fn_type fn_;
  T a_;
  std::vector<breakpoint<T>> bps_;
  T scale_{1}, P_{0}, p0_{1};
};

// ---------------------------------------------------------------------------
// The mirror image p(-x) of a model (for an asymmetric pressure with
// sigma < 0, handled as sigma > 0 on the mirrored contact).
template <class T> class mirrored_pressure final : public pressure_model<T> {
 public:
  explicit mirrored_pressure(const pressure_model<T> &base) : b_(base) {}
  T phi(const T &x, const T &dm, const T &dp) const override { return b_.phi(-x, dp, dm); }
  T dphi(const T &x, const T &dm, const T &dp) const override { return -b_.dphi(-x, dp, dm); }
  T phi_dphi(const T &x, const T &dm, const T &dp, T &d) const override {
    const T v = b_.phi_dphi(-x, dp, dm, d);
    d = -d;
    return v;
  }
  std::vector<breakpoint<T>> breakpoints() const override {
    auto v = b_.breakpoints();
    for (auto &b : v) b.x = -b.x;
    std::reverse(v.begin(), v.end());
    return v;
  }
  bool symmetric() const override { return b_.symmetric(); }
  T edge_phi(int side) const override { return b_.edge_phi(-side); }
  bool shear_only_half_width(const T &q, T &c) const override { return b_.shear_only_half_width(q, c); }
  T accuracy_eps() const override { return b_.accuracy_eps(); }
  bool exact_dphi() const override { return b_.exact_dphi(); }
  T tail(int side, const T &c) const override { return b_.tail(-side, c); }
  knot_view<T> knots() const override {
    knot_view<T> v = b_.knots();
    v.mirror = !v.mirror;
    return v;
  }

 private:
  const pressure_model<T> &b_;
};

// The flat-rounded punch (flat = true, par = b_f/a) or the power law (par = n)
// at type T: the two parametrised non-Hertz pressures, for sweeps and tests
// that solve one scene at two precisions.
template <class T> std::unique_ptr<pressure_model<T>> parametrised_pressure(bool flat, const T &par) {
  if (flat) return std::unique_ptr<pressure_model<T>>(new flat_rounded_pressure<T>(par));
  return std::unique_ptr<pressure_model<T>>(new power_law_pressure<T>(par));
}

}}  // namespace hs::core
