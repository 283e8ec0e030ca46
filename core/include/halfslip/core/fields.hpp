// halfslip core: the stresses the contact puts into each body (issue 15).
//
// A contact state is the pressure p(x) and the shear traction q(x) on |x| < a
// (q acts on body 1, positive in +x; docs/conventions.md), the points where
// they are not smooth, and the bulk stress each body carries. Any state can be
// plugged in (monotonic solutions: make_state(); load histories later).
//
// Body 1 occupies y > 0, body 2 y < 0 (the interface is y = 0). In each body,
// with z = |y| the depth, the Flamant solution for a half-plane loaded by a
// pressure p and a tangential traction t (t = q on body 1, t = -q on body 2)
// is written with the Cauchy integrals (zeta = x + i z)
//   F0[g](zeta) = int g(s)/(s - zeta) ds,   F1[g](zeta) = int g(s)/(s - zeta)^2 ds:
//   sigma_x = -(Im F0[p] + z Re F1[p])/pi + (2 Re F0[t] - z Im F1[t])/pi
//   sigma_z = -(Im F0[p] - z Re F1[p])/pi + z Im F1[t]/pi
//   tau_xz  =  z Im F1[p]/pi - (Im F0[t] + z Re F1[t])/pi
// (Johnson, Contact Mechanics, eq 2.23, rewritten). Global components:
// sigma_xx = sigma_x + bulk, sigma_yy = sigma_z, sigma_xy = tau_xz in body 1
// and -tau_xz in body 2 (so that sigma_yy = -p and sigma_xy = -q on both
// sides of the interface). docs/fields.md has the derivation and the tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "field_panels.hpp"
#include "general.hpp"
#include "hertz.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

// Adds the Cauchy integrals of amp * sqrt(c^2 - (s - e)^2) on [e - c, e + c]
// (closed form: pi amp c (X - nu), pi amp (nu/X - 1), nu = (zeta - e)/c,
// X = sqrt(nu - 1) sqrt(nu + 1) ~ nu at infinity; Im zeta >= 0).
template <class T>
void add_semi_ellipse(const T &amp, const T &c, const T &e, const std::complex<T> &zeta, cauchy_pair<T> &out) {
  if (!(c > 0) || amp == 0) return;
  if (zeta.imag() == 0) {  // the real axis outside the support: all real (the surface off the contact)
    using std::abs;
    using std::sqrt;
    const T nu = (zeta.real() - e) / c;
    if (abs(nu) > 1) {
      const T X = nu > 0 ? T(sqrt((nu - 1) * (nu + 1))) : T(-sqrt((nu - 1) * (nu + 1)));
      out.F0 += std::complex<T>(pi<T>() * amp * c * (X - nu), T(0));
      out.F1 += std::complex<T>(pi<T>() * amp * (nu / X - 1), T(0));
      return;
    }
  }
  const std::complex<T> nu = (zeta - e) / c;
  const std::complex<T> X = std::sqrt(nu - T(1)) * std::sqrt(nu + T(1));
  out.F0 += pi<T>() * amp * c * (X - nu);
  out.F1 += pi<T>() * amp * (nu / X - T(1));
}

// Cauchy integrals of two densities (p and q) at zeta by Gauss-Legendre on
// graded panels. pts: sorted points -a = pts[0] < ... < pts.back() = a where
// the densities may behave like sqrt(distance). Each piece is halved; on each
// half s = end +- h t^2 removes the square root at its end, and the panels in
// t are graded geometrically towards the pole's image, so that every panel is
// at least its own length from the pole (20-point rule: error < 1e-16).
template <class T, class G> void cauchy_numeric(const G &dens, const std::vector<T> &pts, const std::complex<T> &zeta,
                                                cauchy_pair<T> &P, cauchy_pair<T> &Q,
                                                const std::vector<T> &kinks = {}) {
  using std::abs;
  using gl = boost::math::quadrature::gauss<T, 20>;
  const auto &xs = gl::abscissa();
  const auto &ws = gl::weights();
  auto panel = [&](const T &lo_end, const T &h, const T &t0, const T &t1) {
    // s = lo_end + h t^2 (h may be negative)
    const T mid = (t0 + t1) / 2, half = (t1 - t0) / 2;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      for (int sg = -1; sg <= 1; sg += 2) {
        if (xs[k] == 0 && sg > 0) continue;  // a central node once
        const T t = mid + sg * half * xs[k];
        const T s = lo_end + h * t * t;
        const T w = ws[k] * half * 2 * abs(h) * t;
        T pv, qv;
        dens(s, pv, qv);
        const std::complex<T> r = T(1) / (s - zeta);
        P.F0 += w * pv * r;
        P.F1 += w * pv * r * r;
        Q.F0 += w * qv * r;
        Q.F1 += w * qv * r * r;
      }
    }
  };
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const T lo = pts[i], hi = pts[i + 1];
    if (!(hi > lo)) continue;
    const T m = (lo + hi) / 2;
    for (int side = 0; side < 2; ++side) {
      const T end = side == 0 ? lo : hi;
      const T h = side == 0 ? m - lo : m - hi;  // s = end + h t^2
      const std::complex<T> tau = std::sqrt((zeta - end) / h);
      const T t0 = std::min(std::max(tau.real(), T(0)), T(1));
      const T delta = abs(tau - t0);
      std::vector<T> cuts{T(0), T(1)};
      // a log-singular kink of p at this end: panels graded towards it (t^2 log t)
      if (std::find(kinks.begin(), kinks.end(), end) != kinks.end())
        for (int k = 1; k <= 12; ++k) {
          using std::ldexp;  // ADL for multiprecision T
          cuts.push_back(ldexp(T(1), -k));
        }
      grade_towards(cuts, t0, delta);
      std::sort(cuts.begin(), cuts.end());
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
        if (cuts[k + 1] > cuts[k]) panel(end, h, cuts[k], cuts[k + 1]);
    }
  }
}

template <class T> struct stress_tensor {
  T xx{0}, yy{0}, xy{0};
  // in-plane principal stresses and maximum shear
  T radius() const {
    using std::hypot;
    return hypot((xx - yy) / 2, xy);
  }
  T max_principal() const { return (xx + yy) / 2 + radius(); }
  T min_principal() const { return (xx + yy) / 2 - radius(); }
  T max_shear() const { return radius(); }
  // von Mises in plane strain: sigma_zz = nu (xx + yy)
  T von_mises(const T &nu) const {
    using std::sqrt;
    const T zz = nu * (xx + yy);
    return sqrt(((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) / 2 + 3 * xy * xy);
  }
};

template <class T> struct contact_state {
  T a{1};
  T bulk1{0}, bulk2{0};  // sigma_xx each body carries far away (sigma = bulk1 - bulk2)
  std::function<T(const T &)> p, q;
  std::vector<T> breaks;  // interior points of (-a, a) where p or q is not smooth
  // optional closed forms: adds the Cauchy integrals of p and q at zeta and
  // returns true; false: not available (quadrature)
  std::function<bool(const std::complex<T> &, cauchy_pair<T> &, cauchy_pair<T> &)> closed;
  // optional: (2/pi) PV int q(t)/(x - t) dt for |x| <= a (for a solution:
  // E* B_x + sigma/2, exact); needed for the surface stress on the contact
  std::function<T(const T &)> hilbert_q;
  // hilbert_q is cheap everywhere (closed forms); otherwise it is used only on
  // the stick zone (stick_lo, stick_hi), where it is sigma/2, and at breakpoints
  bool hilbert_fast = false;
  // no cached panels (needs_panels false): the state's Cauchy integrals come
  // from `numeric` at O(log n) (a sampled pressure's knot path)
  bool no_panels = false;
  T stick_lo{0}, stick_hi{0};
  std::vector<T> kinks;  // breakpoints where p is log-singular (graded panels)
  // q is analytic inside the stick zone (stick_lo, stick_hi) (monotonic
  // solutions): make_panels may take it from a Chebyshev series there. Not so
  // for a load-history state, whose stick zone holds memory points.
  bool q_analytic_on_stick = true;
  // optional: p and q cached on graded panels (make_panels), shared between
  // states of the same solution; used instead of quadrature from scratch
  std::shared_ptr<const traction_panels<T>> panels;
  // optional: the Cauchy integrals by another quadrature (the reference
  // backend's, field_hp.hpp), used instead of cauchy_numeric when set
  std::function<void(const std::complex<T> &, cauchy_pair<T> &, cauchy_pair<T> &)> numeric;

  std::vector<T> points() const {
    std::vector<T> v{-a, a};
    for (const T &b : breaks)
      if (b > -a && b < a) v.push_back(b);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }
  void cauchy(const std::complex<T> &zeta, cauchy_pair<T> &P, cauchy_pair<T> &Q) const {
    P = {};
    Q = {};
    if (closed && closed(zeta, P, Q)) return;
    P = {};
    Q = {};
    if (panels) {
      panels->cauchy(zeta, P, Q);
      return;
    }
    if (numeric) {
      numeric(zeta, P, Q);
      return;
    }
    cauchy_numeric<T>(
        [&](const T &s, T &pv, T &qv) {
          pv = p(s);
          qv = q(s);
        },
        points(), zeta, P, Q, kinks);
  }
};

// Stress at (x, y) with y = +depth in body 1 (body = 1) or y = -depth in body 2.
template <class T> T surface_sxx(const contact_state<T> &st, int body, const T &x);

template <class T> stress_tensor<T> stress_at(const contact_state<T> &st, int body, const T &x, const T &depth) {
  if (body != 1 && body != 2) throw error(status::bad_option, "body must be 1 or 2");
  if (!(depth >= 0)) throw error(status::bad_option, "depth must be >= 0");
  const T z = depth;
  if (z == 0) {  // on the surface: the tractions themselves (continuous across y = 0)
    using std::abs;
    stress_tensor<T> s;
    s.xx = surface_sxx(st, body, x);
    if (abs(x) < st.a) {
      s.yy = -st.p(x);
      s.xy = -st.q(x);
    }
    return s;
  }
  cauchy_pair<T> P, Q;
  st.cauchy(std::complex<T>(x, z), P, Q);
  const T ip = T(1) / pi<T>();
  const T sx_p = -(P.F0.imag() + z * P.F1.real()) * ip;
  const T sz_p = -(P.F0.imag() - z * P.F1.real()) * ip;
  const T t_p = z * P.F1.imag() * ip;
  const T sx_q = (2 * Q.F0.real() - z * Q.F1.imag()) * ip;
  const T sz_q = z * Q.F1.imag() * ip;
  const T t_q = -(Q.F0.imag() + z * Q.F1.real()) * ip;
  stress_tensor<T> s;
  if (body == 1) {
    s.xx = sx_p + sx_q + st.bulk1;
    s.yy = sz_p + sz_q;
    s.xy = t_p + t_q;
  } else {  // traction -q, and sigma_xy = -tau_xz
    s.xx = sx_p - sx_q + st.bulk2;
    s.yy = sz_p - sz_q;
    s.xy = -(t_p - t_q);
  }
  return s;
}

// Surface direct stress sigma_xx(x, 0) of a body:
//   -p(x) -+ (2/pi) PV int q(t)/(x - t) dt + bulk   (- for body 1, + for body 2).
template <class T> T surface_sxx(const contact_state<T> &st, int body, const T &x) {
  using std::abs;
  if (body != 1 && body != 2) throw error(status::bad_option, "body must be 1 or 2");
  const T sg = body == 1 ? T(-1) : T(1);
  const T bulk = body == 1 ? st.bulk1 : st.bulk2;
  T H;
  const bool on = abs(x) <= st.a;
  if (st.panels && !(on && st.hilbert_q && st.hilbert_fast)) {
    const bool breakpoint = abs(x) == st.a || std::find(st.breaks.begin(), st.breaks.end(), x) != st.breaks.end();
    const bool stick = x > st.stick_lo && x < st.stick_hi;
    if (!(on && st.hilbert_q && (breakpoint || stick))) {
      // (2/pi) PV int q/(x - t); at a breakpoint by subtraction of q(x)
      H = -2 * (breakpoint && on ? st.panels->re_f0_q_break(x, st.q(x)) : st.panels->re_f0_q(x)) / pi<T>();
      return (on ? -st.p(x) : T(0)) + sg * H + bulk;
    }
  }
  if (on) {
    if (st.hilbert_q) return -st.p(x) + sg * st.hilbert_q(x) + bulk;
    cauchy_pair<T> P, Q;  // closed forms: the boundary values from z = +0
    if (st.closed && st.closed(std::complex<T>(x, T(0)), P, Q))
      return -st.p(x) - sg * 2 * Q.F0.real() / pi<T>() + bulk;
    throw error(status::not_applicable, "surface stress on the contact needs the state's Hilbert transform");
  }
  cauchy_pair<T> P, Q;
  st.cauchy(std::complex<T>(x, T(0)), P, Q);
  H = -2 * Q.F0.real() / pi<T>();  // (2/pi) int q/(x - t)
  return sg * H + bulk;
}

// Extremes of sigma_xx(x, 0) over |x| <= L.
template <class T> struct surface_extremes { T max, x_max, min, x_min, bulk; };

template <class T> surface_extremes<T> surface_summary(const contact_state<T> &st, int body, const T &L,
                                                       const std::vector<T> &special, int samples = 400) {
  using std::abs;
  std::vector<T> xs;
  for (int i = 0; i <= samples; ++i) xs.push_back(-L + 2 * L * T(i) / T(samples));
  // denser near the contact (where the peaks are)
  for (int i = 0; i <= samples; ++i) xs.push_back(-st.a * T(1.02) + 2 * st.a * T(1.02) * T(i) / T(samples));
  for (const T &s : special)
    if (abs(s) <= L) xs.push_back(s);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<T> v(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) v[i] = surface_sxx(st, body, xs[i]);
  auto refine = [&](int sgn) -> std::pair<T, T> {
    std::size_t k = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
      if (sgn * v[i] > sgn * v[k]) k = i;
    T best = v[k], xb = xs[k];
    if (k == 0 || k + 1 == xs.size()) return {best, xb};
    // golden section on (xs[k-1], xs[k+1]) (a cusp at a special point is kept)
    T lo = xs[k - 1], hi = xs[k + 1];
    const T g = (std::sqrt(T(5)) - 1) / 2;
    T c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    T fc = sgn * surface_sxx(st, body, c), fd = sgn * surface_sxx(st, body, d);
    for (int it = 0; it < 60 && hi - lo > 16 * eps<T>() * (abs(lo) + abs(hi) + st.a); ++it) {
      if (fc > fd) {
        hi = d;
        d = c;
        fd = fc;
        c = hi - g * (hi - lo);
        fc = sgn * surface_sxx(st, body, c);
      } else {
        lo = c;
        c = d;
        fc = fd;
        d = lo + g * (hi - lo);
        fd = sgn * surface_sxx(st, body, d);
      }
    }
    if (fc > sgn * best) {
      best = sgn * fc;
      xb = c;
    }
    if (fd > sgn * best) {
      best = sgn * fd;
      xb = d;
    }
    return {best, xb};
  };
  const auto mx = refine(+1), mn = refine(-1);
  return {mx.first, mx.second, mn.first, mn.second, body == 1 ? st.bulk1 : st.bulk2};
}

// The state of a monotonic solution (hertz_solution, general_solution,
// edge_solution, or any type with scene, pressure, traction, Bx, b1, b2).
// bulk2: the bulk stress body 2 carries; body 1 carries sigma + bulk2
// (default: the pad carries none, the specimen all of sigma).
template <class T, class S> contact_state<T> make_state(const S &sol, const T &bulk2 = T(0)) {
  contact_state<T> st;
  const T a = sol.scene.a;
  const T sigma = sol.scene.s * sol.scene.f * sol.scene.p0;
  st.a = a;
  st.bulk2 = bulk2;
  st.bulk1 = sigma + bulk2;
  st.p = [&sol](const T &x) { return sol.pressure(x); };
  // q is memoised: the far-field and surface rules reuse the same nodes
  auto memo = std::make_shared<std::map<T, T>>();
  st.q = [&sol, memo](const T &x) {
    auto it = memo->find(x);
    if (it != memo->end()) return it->second;
    const T v = sol.traction(x);
    if (memo->size() < 200000) memo->emplace(x, v);
    return v;
  };
  st.breaks = {-sol.b2(), sol.b1()};
  st.stick_lo = -sol.b2();
  st.stick_hi = sol.b1();
  const T E = sol.scene.Estar;
  st.hilbert_q = [&sol, E, sigma](const T &x) { return E * sol.Bx(x) + sigma / 2; };
  return st;
}

// Hertz: p = (p0/a) sqrt(a^2 - x^2) always, and q in closed form in the
// stuck and same-sign regimes, q = sgn(Q) f [p - (p0/a) sqrt(c^2 - (x - e)^2)],
// c = (b1 + b2)/2, e = (b1 - b2)/2 (McEwen's fields of semi-ellipses).
template <class T> contact_state<T> hertz_state(const hertz_solution<T> &sol, const T &bulk2 = T(0)) {
  contact_state<T> st = make_state<T>(sol, bulk2);
  const T a = sol.scene.a, p0 = sol.scene.p0, f = sol.scene.f;
  const bool q_closed = sol.reg != regime::opposite_sign;
  const T c = (sol.b1() + sol.b2()) / 2, e = (sol.b1() - sol.b2()) / 2;
  const T sf = sol.reg == regime::stuck ? T(0) : sol.sign() * f;
  st.hilbert_fast = true;  // B_x in closed form
  st.closed = [=](const std::complex<T> &zeta, cauchy_pair<T> &P, cauchy_pair<T> &Q) {
    if (!q_closed) return false;
    add_semi_ellipse<T>(p0 / a, a, T(0), zeta, P);
    add_semi_ellipse<T>(sf * p0 / a, a, T(0), zeta, Q);
    add_semi_ellipse<T>(-sf * p0 / a, c, e, zeta, Q);
    return true;
  };
  return st;
}

template <class T> class stick_series;

// The Cauchy integrals F0, F1 of p and q at zeta (user frame) of a general
// solution on the knot path (a sampled pressure with many samples, knots.hpp;
// issue 13 item 4): p over the contact and q = dir f p over the slip zones by
// the knot tree's product rules where 1/(s - zeta) is smooth (nodes at least
// twice their length from zeta and the edges), the segments next to those
// points by cauchy_numeric (square-root maps, panels graded towards zeta); q
// on the stick zone from its Chebyshev series (ser, or q itself) by
// cauchy_numeric. In the canonical variable t = m s/a (m = -1 when mirrored):
// 1/(s - zeta) = m/(a (t - tau)), tau = m zeta/a.
template <class T>
void knot_cauchy(const general_solution<T> &sol, const stick_series<T> *ser, const std::complex<T> &zeta,
                 cauchy_pair<T> &P, cauchy_pair<T> &Q) {
  using C = std::complex<T>;
  using std::abs;
  using std::sqrt;
  const knot_view<T> kv = sol.pm->knots();
  const T a = sol.scene.a, p0 = sol.scene.p0, f = sol.scene.f;
  const T m = sol.mirror ? T(-1) : T(1);
  const C tau = m * zeta / a;
  auto adm = [&](const T &lo, const T &hi) {
    const T lim = knot_quadrature<T>::eta() * (hi - lo);
    const T re = tau.real(), im = abs(tau.imag());
    const T dx = re < lo ? T(lo - re) : (re > hi ? T(re - hi) : T(0));
    if (!(sqrt(dx * dx + im * im) >= lim)) return false;
    return lo + 1 >= lim && 1 - hi >= lim;
  };
  // one part: scale * p over [A, B] (canonical) into the pair out
  auto part = [&](const T &A, const T &B, const T &scale, cauchy_pair<T> &out) {
    kv.cover(
        A, B, adm,
        [&](const T &t, const T &w) {
          const T v = scale * p0 * w * sqrt((1 + t) * (1 - t));
          const C r = T(1) / (C(t) - tau);
          out.F0 += v * m * r;
          out.F1 += v * r * r / a;
        },
        [&](const T &lo, const T &hi) {
          // the piece in the user frame, by quadrature from scratch
          const T s0 = a * m * lo, s1 = a * m * hi;
          const std::vector<T> pts{std::min(s0, s1), std::max(s0, s1)};
          cauchy_pair<T> dummy;
          cauchy_numeric<T>(
              [&](const T &s, T &pv, T &qv) {
                pv = scale * sol.pressure(s);
                qv = 0;
              },
              pts, zeta, out, dummy);
        });
  };
  part(T(-1), T(1), T(1), P);
  const T sg = T(sol.sign());
  if (sol.delta1 > 0 && sol.dirR != 0) part(T(1 - sol.delta1), T(1), sg * T(sol.dirR) * f, Q);
  if (sol.delta2 > 0 && sol.dirL != 0) part(T(-1), T(sol.delta2 - 1), sg * T(sol.dirL) * f, Q);
  // the stick zone (user frame)
  const T lo = -sol.b2(), hi = sol.b1();
  if (hi > lo) {
    cauchy_pair<T> dummy;
    cauchy_numeric<T>(
        [&](const T &s, T &pv, T &qv) {
          pv = 0;
          qv = ser && ser->inside(s) ? (*ser)(s) : sol.traction(s);
        },
        std::vector<T>{lo, hi}, zeta, dummy, Q);
  }
}

// General pressures: the pressure's kinks are quadrature split points too. On
// the knot path (knots.hpp) they are not: the Cauchy integrals come from
// knot_cauchy and the surface Hilbert transform from B_x (both O(log n)), and
// the state has no cached panels (no_panels).
template <class T> contact_state<T> general_state_of(const general_solution<T> &sol, const T &bulk2 = T(0)) {
  contact_state<T> st = make_state<T>(sol, bulk2);
  if (sol.pm->knots()) {
    st.hilbert_fast = true;
    st.no_panels = true;
    std::shared_ptr<stick_series<T>> ser;
    if (st.stick_hi > st.stick_lo) {
      // a higher degree than make_panels allows (q costs O(log n) here, and
      // without the series every Cauchy integral needs ~10^3 values of q), and
      // a tail of 256 eps: q comes from tanh-sinh terminated at eps^(2/3), and
      // its coefficients level off at ~4e-14 for rough samples (1e-6 noise)
      ser = std::make_shared<stick_series<T>>([&sol](const T &x) { return sol.traction(x); }, st.stick_lo,
                                              st.stick_hi, 2048, 256);
      if (!ser->ok()) ser.reset();
    }
    st.numeric = [&sol, ser](const std::complex<T> &z, cauchy_pair<T> &P, cauchy_pair<T> &Q) {
      knot_cauchy<T>(sol, ser.get(), z, P, Q);
    };
    return st;
  }
  for (const T &k : sol.user_kinks()) {
    st.breaks.push_back(k);
    st.kinks.push_back(k);
  }
  return st;
}

// q on the stick zone (lo, hi) as a Chebyshev series in theta, x = m + w cos(theta),
// m = (lo + hi)/2, w = (hi - lo)/2. q is analytic inside the stick zone (also
// across the pressure's kinks: it is the Hilbert solution driven by the slip
// zones) and behaves like sqrt(distance) at both ends, which theta makes
// analytic: near theta = 0, sqrt(hi - x) = sqrt(2w) sin(theta/2). The degree
// doubles from 32 until the last quarter of the coefficients falls below 64 eps
// of the largest (q itself, a tanh-sinh integral, is good to about 4 eps: the
// coefficients level off there, measured 2e-15 from degree 64 for the flat
// punch); when that needs more than max_degree (small slip zones put a
// singularity near the real theta axis), ok() is false and q is used directly.
template <class T> class stick_series {
 public:
  // tail_eps: the last quarter of the coefficients must fall below tail_eps eps of the largest
  template <class Q>
  stick_series(const Q &q, const T &lo, const T &hi, int max_degree = 256, int tail_eps = 64) : lo_(lo), hi_(hi) {
    using std::abs;
    using std::cos;
    m_ = (lo + hi) / 2;
    w_ = (hi - lo) / 2;
    std::vector<T> g;
    for (int N = 32; N <= max_degree; N *= 2) {
      // values at the Chebyshev-Lobatto points u_j = cos(j pi/N), theta = (u + 1) pi/2
      // (the points of N/2 are the even ones: reused)
      std::vector<T> gn(N + 1);
      for (int j = 0; j <= N; ++j) gn[j] = (j % 2 == 0 && !g.empty()) ? g[j / 2] : q(x_of(cos(pi<T>() * j / N)));
      g.swap(gn);
      c_.assign(N + 1, T(0));
      // cos(pi m/N) for m < 2N, the same numbers as computed in the sum (a
      // multiprecision cos costs microseconds: N^2 of them would dominate)
      std::vector<T> cs(2 * N);
      for (int m = 0; m < 2 * N; ++m) cs[m] = cos(pi<T>() * T(m) / N);
      for (int k = 0; k <= N; ++k) {
        T sum = 0;
        for (int j = 0; j <= N; ++j) sum += (j == 0 || j == N ? T(0.5) : T(1)) * g[j] * cs[j * k % (2 * N)];
        c_[k] = sum * 2 / N * (k == 0 || k == N ? T(0.5) : T(1));
      }
      T big = 0, tail = 0;
      for (int k = 0; k <= N; ++k) big = std::max(big, T(abs(c_[k])));
      for (int k = 3 * N / 4; k <= N; ++k) tail = std::max(tail, T(abs(c_[k])));
      tail_ = tail / big;
      if (tail <= tail_eps * eps<T>() * big) {
        ok_ = true;
        return;
      }
    }
    c_.clear();
  }
  bool ok() const { return ok_; }
  T tail() const { return tail_; }
  bool inside(const T &x) const { return x > lo_ && x < hi_; }
  T operator()(const T &x) const {
    using std::asin;
    using std::sqrt;
    // theta from the distance to the nearer end (accurate near both ends)
    const T th = x >= m_ ? 2 * asin(sqrt((hi_ - x) / (2 * w_))) : pi<T>() - 2 * asin(sqrt((x - lo_) / (2 * w_)));
    const T u = 2 * th / pi<T>() - 1;
    T b1 = 0, b2 = 0;  // Clenshaw
    for (std::size_t k = c_.size(); k-- > 1;) {
      const T b0 = 2 * u * b1 - b2 + c_[k];
      b2 = b1;
      b1 = b0;
    }
    return u * b1 - b2 + c_[0];
  }

 private:
  T x_of(const T &u) const {
    using std::cos;
    using std::sin;
    const T th = (u + 1) * pi<T>() / 2;
    // ends from the distances (hi - x = 2w sin^2(theta/2)), exact at theta = 0, pi
    if (th <= pi<T>() / 2) {
      const T sh = sin(th / 2);
      return hi_ - 2 * w_ * sh * sh;
    }
    const T ch = cos(th / 2);
    return lo_ + 2 * w_ * ch * ch;
  }
  T lo_, hi_, m_{0}, w_{0};
  std::vector<T> c_;
  bool ok_ = false;
  T tail_{1};
};

// The panels of a state (p and q at ~10^3 cached nodes). On the stick zone q
// comes from a stick_series (some 30 to 130 evaluations of q) when it
// converges, elsewhere from the state. Not needed where the state has closed forms.
template <class T> std::shared_ptr<const traction_panels<T>> make_panels(const contact_state<T> &st) {
  std::unique_ptr<stick_series<T>> ser;
  if (st.q_analytic_on_stick && st.stick_hi > st.stick_lo) {
    ser = std::make_unique<stick_series<T>>(st.q, st.stick_lo, st.stick_hi);
    if (!ser->ok()) ser.reset();
  }
  return std::make_shared<const traction_panels<T>>(
      [&](const T &s, T &pv, T &qv) {
        pv = st.p(s);
        qv = ser && ser->inside(s) ? (*ser)(s) : st.q(s);
      },
      st.points(), st.kinks);
}
// Whether the state's Cauchy integrals need quadrature (no closed forms).
template <class T> bool needs_panels(const contact_state<T> &st) {
  if (st.no_panels) return false;
  cauchy_pair<T> P, Q;
  return !(st.closed && st.closed(std::complex<T>(0, 1), P, Q));
}

}}  // namespace hs::core
