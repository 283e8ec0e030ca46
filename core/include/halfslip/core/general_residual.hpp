// halfslip core, general pressures (general.hpp): the zone integrals of the
// side conditions and their derivatives, and the residual of the unified
// system in (x1, ln e).
#pragma once
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <boost/math/tools/precision.hpp>

#include "general_panels.hpp"
#include "numerics.hpp"
#include "pressure.hpp"

namespace hs { namespace core {

// Sums of the single-zone integrals (I2: the moment about the stick-zone
// centre, int p_hat (t - c)/R(t) dt) and their derivatives in the zone length
// d at fixed stick-zone length e (a translation of the stick zone) and in e
// at fixed d. Derivatives in b1 and b2 separately are each O(1/e) and cancel
// in the translation: formed that way, the Jacobian lost every digit once
// e < ~1e-16 (large sigma; issue 13). The d-derivative below is O(ln(1/e));
// the e-derivative is kept as e dI/de (the 1/e^(3/2) of each node times e
// overflowed for e < 1e-205).
template <class T> struct zone_sums { T I1{0}, I2{0}, I1d{0}, I2d{0}, I1le{0}, I2le{0}; };

namespace gdetail {
// The contribution of the node theta (weight w) of zone `side` (length d,
// stick-zone length e) to the single-zone integrals and (if jac) their
// derivatives: t = stick edge +- d sin^2(theta).
// (sn, cs: sin and cos of theta)
template <class T> void zone_node_sc(const pressure_model<T> &pm, int side, const T &d, const T &e, const T &sn,
                                     const T &cs, const T &w, bool jac, zone_sums<T> &r) {
  using std::sqrt;
  const T s2 = sn * sn, c2 = cs * cs;
  const T ds = d * s2;  // distance to the stick edge
  const T g = e + ds;   // |t - (other stick edge)|: t + b2 (R) or b1 - t (L)
  const gdetail::zone_point<T> x = gdetail::zone_point_at(side, d, s2, c2);
  T dph = 0;
  const T ph = jac ? pm.phi_dphi(x.t, x.dm, x.dp, dph) : pm.phi(x.t, x.dm, x.dp);
  const T sf = sqrt(x.far(side));  // sqrt of the distance to the far contact edge
  const T psi = sf * ph;           // p_hat / sqrt(distance to the near edge)
  const T rg = 1 / sqrt(g);
  const T base = 2 * d * c2 * psi * rg;  // integrand of I_1 (per dtheta)
  // t - c: +(ds + e/2) in zone R, -(ds + e/2) in zone L
  const T u = side > 0 ? ds + e / 2 : -(ds + e / 2);
  r.I1 += w * base;
  r.I2 += w * base * u;
  if (!jac) return;
  // psi' = d psi / dt
  const T dpsi = side > 0 ? ph / (2 * sf) + sf * dph : -ph / (2 * sf) + sf * dph;
  // at fixed theta: t = 1 - d cos^2 (R) or -1 + d cos^2 (L), g = e + d sin^2
  const T dtdd = side > 0 ? -c2 : c2;
  // d base/d e = -base/(2g); d base/d d = 2 c2 psi/sqrt(g) + 2 d c2 psi' t_d/sqrt(g)
  // - base sin^2/(2g), whose last term is at most base/(2d): no 1/e
  const T bd = 2 * c2 * psi * rg + 2 * d * c2 * dpsi * dtdd * rg - base * s2 / (2 * g);
  const T ble = -base * (e / (2 * g));  // e d base/d e, at most base/2
  // u_d = +-sin^2, e u_e = +-e/2
  const T sgn = side > 0 ? T(1) : T(-1);
  r.I1d += w * bd;
  r.I2d += w * (bd * u + sgn * base * s2);
  r.I1le += w * ble;
  r.I2le += w * (ble * u + sgn * base * e / 2);
}
template <class T> void zone_node(const pressure_model<T> &pm, int side, const T &d, const T &e, const T &th,
                                  const T &w, bool jac, zone_sums<T> &r) {
  T sn, cs;
  sin_cos(th, sn, cs);
  zone_node_sc(pm, side, d, e, sn, cs, w, jac, r);
}

// The zone integrals of a model with a knot quadrature (the sampled pressure
// from knot_tree_min samples on, knots.hpp; issue 13 item 4), at a cost
// independent of the sample count. In t, the zone's integrands are
// phi(t) K(t) with K = sqrt(1 - t^2)/sqrt(A G) (times the moment arm
// u = +-(A + e/2) for I_2), A = |t - own stick edge|, G = A + e: smooth but
// at the stick edges and +-1, so the tree nodes at least twice their length
// away from those points take their product rules. The segments (pieces)
// closer to them are integrated in theta as zone_integrals does (theta removes
// the square roots at the zone's ends; panels graded towards the near
// singularity at theta ~ i sqrt(e/d)), order n. Derivatives at fixed e in d
// (a translation: A and G grow by 1) and e d/de (G grows by e), in t at fixed
// t on the tree's part and in theta at fixed theta on the pieces, whose ends at
// knots then move: the boundary terms -+ phi K dt/dd|theta close the sum.
template <class T> zone_sums<T> zone_integrals_knots(const pressure_model<T> &pm, const knot_view<T> &kv, int side,
                                                     const T &d, const T &e, int n, bool jac) {
  using std::asin;
  using std::min;
  using std::sqrt;
  zone_sums<T> r;
  const T half_pi = pi<T>() / 2;
  // the zone [lo, hi] and the distance of t from its stick edge, without
  // cancellation (the stick edge 1 - d, d - 1 is exact for d >= 1/2; else
  // t -+ 1 is)
  const T zlo = side > 0 ? T(1 - d) : T(-1), zhi = side > 0 ? T(1) : T(d - 1);
  auto dist = [&](const T &t) -> T {
    if (side > 0) return d >= T(0.5) ? T(t - zlo) : T((t - 1) + d);
    return d >= T(0.5) ? T(zhi - t) : T(d - (1 + t));
  };
  const T own = side > 0 ? zlo : zhi, other = side > 0 ? T(zlo - e) : T(zhi + e);
  const T sing[4] = {own, other, T(-1), T(1)};
  auto adm = [&](const T &a, const T &b) {
    const T lim = knot_quadrature<T>::eta() * (b - a);
    for (const T &sg : sing) {
      const T dd = sg < a ? T(a - sg) : (sg > b ? T(sg - b) : T(0));
      if (!(dd >= lim)) return false;
    }
    return true;
  };
  const T sgn = side > 0 ? T(1) : T(-1);
  auto emit = [&](const T &t, const T &w) {
    const T A = dist(t), G = A + e;
    const T W = sqrt((1 + t) * (1 - t) / (A * G));
    const T u = sgn * (A + e / 2);
    r.I1 += w * W;
    r.I2 += w * W * u;
    if (!jac) return;
    const T Wd = -W * (1 / A + 1 / G) / 2, Wle = -W * (e / G) / 2;
    r.I1d += w * Wd;
    r.I2d += w * (Wd * u + sgn * W);
    r.I1le += w * Wle;
    r.I2le += w * (Wle * u + sgn * W * e / 2);
  };
  std::vector<std::pair<T, T>> pieces;
  kv.cover(zlo, zhi, adm, emit, [&](const T &a, const T &b) { pieces.push_back({a, b}); });
  if (pieces.empty()) return r;
  // theta of a piece end: 0 at the stick edge, pi/2 at the contact edge
  auto theta = [&](const T &t) -> T {
    if (t == own) return T(0);
    if (t == (side > 0 ? zhi : zlo)) return half_pi;
    const T s2 = dist(t) / d;
    if (!(s2 > 0)) return T(0);
    if (!(s2 < 1)) return half_pi;
    return asin(sqrt(s2));
  };
  // the grading points of make_panels towards theta = 0
  std::vector<T> grade;
  {
    const T epsr = sqrt(e / d);
    if (epsr < half_pi / 2) {
      T gp = epsr < 1 ? asin(epsr) : epsr;
      const T tiny = sqrt(boost::math::tools::min_value<T>());
      if (gp < tiny) gp = tiny;
      for (; gp < half_pi / 2; gp *= 2) grade.push_back(gp);
    }
  }
  const auto rule = gauss_legendre<T>(n);
  // H theta'(d) at a knot t (the boundary terms): with H dtheta = phi K |dt|
  // and t fixed, theta'(d) |dt/dtheta| = cos^2(theta) in both zones, so
  // H theta' = phi K cos^2(theta), cos^2 = (distance to the contact edge)/d
  auto moving = [&](const T &t, T &b1v, T &b2v) {
    const T A = dist(t), G = A + e;
    const T W = sqrt((1 + t) * (1 - t) / (A * G)) * pm.phi(t, T(1 + t), T(1 - t));
    const T c2 = (side > 0 ? T(1 - t) : T(1 + t)) / d;
    b1v = W * c2;
    b2v = W * sgn * (A + e / 2) * c2;
  };
  for (const auto &pc : pieces) {
    // theta-order ends: zone R runs with t, zone L against it
    const T ta = side > 0 ? pc.first : pc.second, tb = side > 0 ? pc.second : pc.first;
    const T tha = theta(ta), thb = theta(tb);
    if (!(thb > tha)) continue;
    std::vector<T> cuts{tha};
    for (const T &gp : grade)
      if (gp > tha && gp < thb) cuts.push_back(gp);
    cuts.push_back(thb);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const T L = cuts[i + 1] - cuts[i];
      for (int k = 0; k < n; ++k)
        zone_node(pm, side, d, e, T(cuts[i] + L * (1 + rule->x[k]) / 2), T(L * rule->w[k] / 2), jac, r);
    }
    if (!jac) continue;
    // ends at knots move with d at fixed theta: d/dd int_tha^thb H = int dH/dd
    // + [H theta']_thb - [H theta']_tha
    T v1, v2;
    if (tha > 0) {
      moving(ta, v1, v2);
      r.I1d -= v1;
      r.I2d -= v2;
    }
    if (thb < half_pi) {
      moving(tb, v1, v2);
      r.I1d += v1;
      r.I2d += v2;
    }
  }
  return r;
}
}  // namespace gdetail

// Single-zone integrals I_j = int_zone p_hat t^(j-1)/R(t) dt, j = 1, 2, and
// (if jac) their derivatives in b1 and b2, by the composite rule of order n.
// side = +1: zone (b1, 1) of length d = d1; side = -1: zone (-1, -b2), d = d2.
// e = b1 + b2 > 0.
template <class T>
zone_sums<T> zone_integrals(const pressure_model<T> &pm, int side, const T &d, const T &e, int n, bool jac) {
  zone_sums<T> r;
  if (!(d > 0)) return r;
  if (const knot_view<T> kv = pm.knots()) return gdetail::zone_integrals_knots(pm, kv, side, d, e, n, jac);
  const auto panels = gdetail::make_panels<T>(d, gdetail::grading_scale(pm, side, d, e), gdetail::zone_kinks(pm, side, d));
  if (panels.size() == 1 && panels[0].grade == 0 && panels[0].lo == 0 && panels[0].hi == pi<T>() / 2) {
    // the whole quarter [0, pi/2] (no kink, no grading): the nodes' sines and
    // cosines from the cached table, the values for_nodes would give
    const auto rule = gauss_legendre<T>(n);
    const auto qt = gauss_legendre_quarter<T>(n);
    const T L = panels[0].hi - panels[0].lo;
    for (int i = 0; i < n; ++i) gdetail::zone_node_sc(pm, side, d, e, qt->sn[i], qt->cs[i], T(L * rule->w[i] / 2), jac, r);
    return r;
  }
  gdetail::for_nodes<T>(panels, n,
                        [&](const T &th, const T &w) { gdetail::zone_node(pm, side, d, e, th, w, jac, r); });
  return r;
}

// Residuals and Jacobian in (x1, ln e) of the unified system.
template <class T> struct general_eval {
  T F1, F2;
  T J11, J12, J21, J22;  // dF/dx1, dF/dln e
  // (with the Jacobian) the grain of |F1| + |F2| in the state: the change of
  // the residual across one rounding of x1 (eps |x1|), of ln e (eps) and of the
  // far zone d2 = 2 - d1 - e at fixed d1 and e, which is formed to ~2 eps
  // absolute (issue 13:
  // flat punch b_f/a = 0.999, Q/fP = 0.3, sigma = 0, zones of 2e-4 a, where
  // |J| ~ 2e3 and no representable state had |F| below the fixed floor)
  T grain{0};
};

template <class T> struct general_state {
  T x1;  // +d1 (same sign), -d1 (opposite sign)
  T e;   // b1 + b2 (underflows to 0 at large sigma: then ln_e carries it)
  // ln e, when set (NaN: not set, ln e = log(e)). Set by every step, so that the
  // width can follow a large sigma below the range of T (issue 13)
  T ln_e = std::numeric_limits<T>::quiet_NaN();
  T d1() const {
    using std::abs;
    return abs(x1);
  }
  T d2() const { return 2 - d1() - e; }
  int sR() const { return x1 < 0 ? -1 : 1; }
  T lw() const {
    using std::log;
    return ln_e == ln_e ? ln_e : T(log(e));
  }
  static general_state from_log(const T &x1, const T &le) {
    using std::exp;
    return {x1, T(exp(le)), le};
  }
  // the step (dx, dy) in (x1, ln e)
  general_state step(const T &dx, const T &dy) const { return from_log(x1 + dx, lw() + dy); }
};

// Widths below tiny_width() = eps^3 (units of a) are the point-stick limit:
// every zone integral of the side conditions (and every slip and energy) is
// A + B ln e + O(e ln(1/e)/l), l the distance to the nearest pressure kink or
// scale (the density's 1/sqrt(e + d sin^2) near the stick edge contributes
// B ln(1/e) and the rest converges), so they are evaluated at the two widths
// eps^3 and eps^4 and continued linearly in ln e. Exact to ~eps^3 ln(1/eps)/l,
// far below eps; the width itself may be below the range of T (sigma/fp0 of
// order 1e3 and beyond; issue 13: the quadrature returned OVERFLOW there).
template <class T> T tiny_width() {
  const T e = eps<T>();
  return e * e * e;
}
template <class T> T tiny_width_b() { return tiny_width<T>() * eps<T>(); }

// The residual at the stick width st.e itself.
template <class T> general_eval<T> general_residual_at(const pressure_model<T> &pm, const T &q, const T &s,
                                                       const general_state<T> &st, int n, bool jac) {
  const T pi_ = pi<T>();
  const T d1 = st.d1(), d2 = st.d2(), e = st.e;
  const int sR = st.sR();
  const zone_sums<T> R = zone_integrals(pm, +1, d1, e, n, jac);
  const zone_sums<T> L = zone_integrals(pm, -1, d2, e, n, jac);
  general_eval<T> r;
  r.F1 = L.I1 - sR * R.I1 - pi_ * s / 4;
  r.F2 = L.I2 - sR * R.I2 + pi_ * q / 2;  // F2 - c F1 (see the top of this file)
  if (!jac) return r;
  // d1 = |x1|, d2 = 2 - d1 - e: at fixed e, d d1/d x1 = sg, d d2/d x1 = -sg;
  // at fixed x1, d d2/d e = -1 (and b1 - b2 = d2 - d1)
  const T sg = T(sR);
  r.J11 = -sg * L.I1d - R.I1d;
  r.J21 = -sg * L.I2d - R.I2d;
  r.J12 = L.I1le - sR * R.I1le - e * L.I1d;
  r.J22 = L.I2le - sR * R.I2le - e * L.I2d;
  {
    using std::abs;
    const T ep = eps<T>();
    r.grain = ep * ((abs(r.J11) + abs(r.J21)) * d1 + abs(r.J12) + abs(r.J22) + 2 * (abs(L.I1d) + abs(L.I2d)));
  }
  return r;
}

template <class T> general_eval<T> general_residual(const pressure_model<T> &pm, const T &q, const T &s,
                                                    const general_state<T> &st, int n, bool jac) {
  if (st.e < tiny_width<T>()) {
    // the point-stick limit: linear in ln e from the widths eps^3 and eps^4 (above)
    using std::abs;
    using std::log;
    using std::max;
    const T la = log(tiny_width<T>()), lb = log(tiny_width_b<T>());
    // (at s = 0: the zone integrals alone are continued; - pi s/4 is added
    // after, else it swamps them at large s: at sigma/fp0 = 1e16 it left one ulp,
    // ~1, of a difference ~50, and ln e 2% off)
    const general_eval<T> ra = general_residual_at(pm, q, T(0), general_state<T>{st.x1, tiny_width<T>()}, n, jac);
    const general_eval<T> rb = general_residual_at(pm, q, T(0), general_state<T>{st.x1, tiny_width_b<T>()}, n, jac);
    const T t = (st.lw() - la) / (la - lb);
    general_eval<T> r;
    r.F1 = ra.F1 + t * (ra.F1 - rb.F1) - pi<T>() * s / 4;
    // F2, the moment about the stick centre, has no ln e term (its weight t - c
    // vanishes at the stick zone): F2 = F2(eps^3) + O(eps^3), and continuing it
    // would only multiply its rounding by t (~1e10 at sigma/fp0 = 1e12)
    r.F2 = ra.F2;
    if (!jac) return r;
    r.J11 = ra.J11 + t * (ra.J11 - rb.J11);
    r.J21 = ra.J21;
    r.J12 = (ra.F1 - rb.F1) / (la - lb);
    r.J22 = (ra.F2 - rb.F2) / (la - lb);
    r.grain = max(ra.grain, rb.grain) * (1 + abs(t));
    return r;
  }
  return general_residual_at(pm, q, s, st, n, jac);
}

}}  // namespace hs::core
