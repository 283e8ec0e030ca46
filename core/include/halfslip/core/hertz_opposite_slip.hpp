// halfslip core: slip and zone energy of the Hertz opposite-sign regime by
// fixed Gauss-Legendre rules in a variable that makes the integrand analytic
// in a strip of known width (issue 16).
//
// In a slip zone at distance u from the stick edge (stick width e, canonical
// units) the density is b(u) = -2 R(u) (1 + 2 G(u)/pi), R = sqrt(u (u + e)),
// with G the elliptic integral of the other zone (opposite_G_state). With
//   u = e sinh^2(tau/2):   R = du/dtau = (e/2) sinh(tau),  u + e = e cosh^2(tau/2)
// the slip is h(dl) = int_0^T R(u)^2 g(u) dtau, g = -2 (1 + 2G/pi),
// T = 2 asinh(sqrt(dl/e)). The square-root end at u = 0 is gone (R^2 is
// entire in tau), and G(u), whose only singularities lie at u <= -e (the
// characteristic p_x <= 0; the log branch point at u = -e that makes b
// vary on the scale of e when the stick zone is tiny), is analytic in the
// strip |Im tau| < pi: u = -e is tau = i pi. A Gauss-Legendre rule of n nodes
// on a panel of length L inside that strip converges like rho^(-2n),
// rho = a + sqrt(1 + a^2), a = 2 pi / L; for L <= 2 (rho >= 6.4) 12 nodes
// leave < 1e-17 relative (the integrand grows like e^(2 tau), which costs at
// most a factor e^4.2 on the ellipse beyond the panel's right end). A stick
// zone far narrower than the slip zone only makes T long (T ~ ln(4 dl/e)),
// and the integrand's growth e^(2 tau) makes [0, T - 24] worth < 1e-20 of the
// total: at most 12 panels of length <= 2 and one for the rest.
// The zone energy int_0^L Pi(L - u) b(u) du (Pi = pressure_tail) has the
// pressure's c^(3/2) at the contact edge u = L: on the last panel
// tau = T - L_p s^2 makes it s^4 times a function analytic near [0, 1].
// tests/test_hertz.cpp checks both against the tanh-sinh path in long double
// and tests/test_reference.cpp against the MPFR reference backend.
#pragma once
#include <algorithm>
#include <cmath>

#include "gauss.hpp"
#include "hertz_opposite.hpp"

namespace hs { namespace core {

// The integrals of one slip zone. st is the state as opposite_G_state takes
// it: the other zone first (st.d1 is the length of the zone whose traction
// drives G, st.d2 the length of this zone).
template <class T> class opposite_zone_integrals {
 public:
  explicit opposite_zone_integrals(const opposite_state<T> &st) : st_(st) {
    using std::log;
    using std::sqrt;
    le_ = log_width(st);
    op2_ = st.d1 + st.e;
    op1_ = st.d2 + st.e;
    Q_ = op1_ * op2_;
    const T sQ = sqrt(Q_);
    if (st.e >= boost::math::tools::min_value<T>()) {
      kc_ = sqrt(2 * st.e / Q_);
      lkc_ = log(kc_);
    } else {
      lkc_ = (log(T(2)) + le_ - log(Q_)) / 2;
      using std::exp;
      kc_ = exp(lkc_);
    }
    rj_scale_ = 3 / (Q_ * sQ);
    RJc_ = rj_scale_ * cel_log(kc_, lkc_, 2 / op1_, T(0), T(1));
    coef_ = 4 * st.d1 * op2_ / 3;
    using std::pow;
    static const T ks = pow(boost::math::tools::epsilon<T>(), T(0.6));  // cel_log's switch
    ks_ = ks;
  }

  // slip int_0^dl b(u) du (dl >= 0)
  T slip(const T &dl) const {
    if (!(dl > 0)) return T(0);
    const T tmax = tau_of(dl);
    const T em1T = expm1_neg(tmax);
    return integrate(tmax, [&](const T &sig) { return F(dl, tmax, em1T, sig); });
  }

  // int_0^L Pi(L - u) b(u) du, L the length of this zone
  T energy(const T &L) const {
    using std::expm1;
    if (!(L > 0)) return T(0);
    const T tmax = tau_of(L);
    const T em1T = expm1_neg(tmax);
    return integrate(
        tmax,
        [&](const T &sig) {
          // c = L - u = e sinh(sig/2) sinh(T - sig/2), no cancellation
          const T c = L * expm1(-sig) * expm1(sig - 2 * tmax) / (em1T * em1T);
          return pressure_tail(c) * F(L, tmax, em1T, sig);
        },
        true);
  }

  // b(u) (as opposite_G_state and hertz_solution::bhat), u > 0
  T bhat(const T &u) const { return point(u, u + st_.e); }

 private:
  opposite_state<T> st_;
  T le_, op1_, op2_, Q_, kc_, lkc_, rj_scale_, RJc_, coef_, ks_;

  static T expm1_neg(const T &x) {
    using std::expm1;
    return expm1(-x);
  }
  // tau at distance dl: sinh^2(tau/2) = dl/e
  T tau_of(const T &dl) const {
    using std::asinh;
    using std::log;
    using std::sqrt;
    if (st_.e >= boost::math::tools::min_value<T>() && dl / st_.e < T(1e150)) return 2 * asinh(sqrt(dl / st_.e));
    // 2 asinh(z) = 2 ln(2z) + O(1/z^2), z^2 = dl/e > 1e150
    return log(4 * dl) - le_;
  }
  // b at u with v = u + e (both to full relative accuracy)
  T point(const T &u, const T &v) const {
    using std::sqrt;
    const T omx = st_.d1 + v;  // 1 - x
    const T opx = st_.d2 - u;  // 1 + x
    const T px = 2 * v / (op1_ * omx);
    const T RJq = rj_scale_ * cel_fast(px);
    const T G = coef_ * (RJc_ + opx / omx * RJq);
    return -2 * sqrt(u * v) * (1 + 2 * G / pi<T>());
  }
  // cel(kc, p, 0, 1) through cel_log's switch, its threshold precomputed
  T cel_fast(const T &p) const {
    using std::min;
    using std::sqrt;
    if (kc_ > ks_ && (p >= 1 || kc_ > ks_ * sqrt(p))) return cel(kc_, p, T(0), T(1));
    return cel_log(kc_, lkc_, p, T(0), T(1));
  }
  // The integrand R^2 g = R b at tau = T - sig, T = tau(dl): u and v = u + e
  // relative to dl (sinh^2(T/2) = dl/e), so that neither the rounding of T
  // (absolute eps T when the stick zone is tiny) nor an underflowing e
  // enters them:
  //   u = dl e^(-sig) (expm1(-tau)/expm1(-T))^2, v = dl e^(-sig) ((2 + expm1(-tau))/expm1(-T))^2
  T F(const T &dl, const T &tmax, const T &em1T, const T &sig) const {
    using std::exp;
    using std::expm1;
    using std::sqrt;
    const T tau = tmax - sig;
    const T em = expm1(-tau);
    const T base = dl * exp(-sig) / (em1T * em1T);
    const T u = base * em * em, v = base * (2 + em) * (2 + em);
    // far below the point (sig beyond ~700) u and v underflow: what is left
    // there is below e^(-40) of the total (see integrate)
    if (!(v > 0)) return T(0);
    return sqrt(u * v) * point(u, v);
  }
  // int_0^tmax f(sig) dsig (sig = T - tau: the distance from the point in
  // tau) on fixed panels from sig = 0. The integrand decays like e^(-sig)
  // away from the point (u = dl e^(-sig) for large T), so the panels may
  // lengthen as the part they carry shrinks; each keeps rho^(-2n) e^(-sig_a)
  // below 1e-17 for the strip |Im| < pi. What lies beyond sig = 40 carries
  // less than e^(-40) = 4e-18 of the total: one panel up to 80, and beyond
  // 80 nothing (measured: F(40)/F(0) = 4e-18 at sigma/(f p0) = 12, Q/fP = 1 - 1e-6). last_edge: the first
  // panel carries the contact edge (edge_panel).
  template <class Fn> T integrate(const T &tmax, const Fn &f, bool last_edge = false) const {
    struct piece {
      double end;
      int n;
    };
    static constexpr piece pieces[] = {{2, 12}, {4, 12}, {6, 12}, {10, 16}, {16, 16}, {24, 16}, {32, 16}, {40, 16}};
    T sum = 0, a = 0;
    for (const piece &p : pieces) {
      const T b = tmax < T(p.end) ? tmax : T(p.end);
      if (last_edge && a == 0) sum += edge_panel(a, b, f);
      else sum += panel(a, b, b - a <= T(0.25) ? 6 : b - a <= T(0.75) ? 8 : b - a <= T(1.25) ? 10 : p.n, f);
      a = b;
      if (!(a < tmax)) return sum;
    }
    // [40, 80] once, roughly (its share is < e^(-40)); beyond 80 (< e^(-80))
    // nothing, where u, v would underflow
    return sum + panel(a, tmax < T(80) ? tmax : T(80), 12, f);
  }
  template <class Fn> static T panel(const T &a, const T &b, int n, const Fn &f) {
    const auto &r = rule(n);
    const T h = (b - a) / 2, m = (a + b) / 2;
    T s = 0;
    for (int i = 0; i < n; ++i) s += r.w[i] * f(m + h * r.x[i]);
    return s * h;
  }
  // int_0^b f(sig) dsig with the contact edge at sig = 0, where c = L - u
  // = L (1 - e^-sig)(1 - e^(sig - 2T))/(1 - e^-T)^2 vanishes and Pi(c) ~ c^(3/2):
  // sig = b (1 - cos phi), phi in [0, pi/2], makes sig^(3/2) ~ sin^3 phi; when
  // b = T it also makes the mirror branch point sig = 2T (c = 0 again) regular
  // (sig (2T - sig) = T^2 sin^2 phi), which the map sig = b s^2 would put
  // at s = sqrt(2), 0.41 beyond the rule's end (measured: 4e-14 with 12 nodes).
  template <class Fn> static T edge_panel(const T &a, const T &b, const Fn &f) {
    using std::cos;
    using std::sin;
    const T L = b - a;
    const auto &r = rule(16);
    const T h = pi<T>() / 4;
    T s = 0;
    for (int i = 0; i < 16; ++i) {
      const T phi = h * (1 + r.x[i]);
      const T sh = sin(phi / 2);
      s += r.w[i] * sin(phi) * f(a + 2 * L * sh * sh);
    }
    return s * L * h;
  }
  static const gl_rule<T> &rule(int n) {
    // immutable after their thread-safe initialisation (the rule cache's shared rules)
    static const auto r6 = gauss_legendre<T>(6), r8 = gauss_legendre<T>(8), r10 = gauss_legendre<T>(10),
                      r12 = gauss_legendre<T>(12), r16 = gauss_legendre<T>(16);
    switch (n) {
      case 6: return *r6;
      case 8: return *r8;
      case 10: return *r10;
      case 12: return *r12;
      default: return *r16;
    }
  }
};

}}  // namespace hs::core
