// halfslip core: partial slip under constant normal load for a general
// contact pressure (issue #4): Hertz, flat punch with rounded corners, power
// law, sampled or callback pressure (pressure.hpp).
//
// Canonical frame (as hertz.hpp): a = 1, p_hat = p/p0 (p0 = 2P/(pi a)),
// f = E* = 1, q = Q/fP >= 0, s = sigma/(f p0) >= 0 after the symmetries
// (Q, sigma) -> (-Q, -sigma) (all slips flip) and sigma -> -sigma (mirror
// x -> -x; for an asymmetric pressure the mirrored pressure is used).
// Zone R = (b1, 1) slips with sign sR, zone L = (-1, -b2) with sL = +1;
// sR = +1 (same sign) or -1 (opposite sign). Side conditions (docs/conventions.md):
//   F1 = sL I1L - sR I1R - pi s/4                          = 0
//   F2 = sL I2L - sR I2R - pi s (b1 - b2)/8 + pi q/2       = 0
// with I_jZ = int_Z p_hat(t) t^(j-1) / sqrt(|t-b1||t+b2|) dt. The solver uses
// F2 - c F1 in place of F2, c = (b1 - b2)/2 the stick-zone centre: the
// moment about the centre, sL K_L - sR K_R + pi q/2 with K_Z = int_Z p_hat
// (t - c)/sqrt(|t-b1||t+b2|) dt. The pi s terms cancel exactly and t - c
// = +-(distance to the stick edge + e/2) has no cancellation, so the second
// condition keeps full accuracy as s grows (as s -> infinity it becomes the
// balance q pi/2 = int_{-1}^{x0} p_hat - int_{x0}^{1} p_hat; issue 13).
//
// Unknowns. One Newton iteration covers both regimes: x1 = +d1 (same sign) or
// -d1 (opposite sign), d1 = 1 - b1 the length of zone R, and x2 = ln e, e = b1 + b2
// the stick-zone length (tiny for large s). Since I_jR = O(d1) as d1 -> 0, the
// residual sR(x1) I_jR(|x1|) is C^1 across x1 = 0 (the regime boundary) and
// the iteration crosses it freely; the regime is the sign of x1 at the
// solution. This is the rule "solve same-sign first; if it has no solution
// with b1 < a, the scene is opposite-sign": a same-sign solution is exactly
// a root with x1 > 0.
//
// Zone integrals: t = b1 + d1 sin^2(theta) (zone R), t = -b2 - d2 sin^2(theta)
// (zone L) turn both end behaviours (sqrt at the contact edge, 1/sqrt at the
// stick edge) into the smooth weight 2 d cos^2(theta). The remaining factor
// 1/sqrt(e + d sin^2 theta) is nearly singular at theta = 0 when e << d:
// panels are graded geometrically towards 0 from theta ~ sqrt(e/d). Pressure
// kinks are panel ends; at graded kinks (log-singular p') the panel is mapped
// polynomially, theta = end + L u^m (m from the precision). Gauss-Legendre
// of order N per panel, nodes computed in T. N doubles until the residual
// evaluated with 2N agrees with zero to the tolerance; the order used is
// reported.
//
// Zone energies and slips (general_solution::energy_hat, hhat) reuse these
// panels with fixed Gauss-Legendre rules: h' at the nodes of order M from
// Cauchy sums over the nodes of order M + 1 (interlacing on shared panels),
// the pressure tail cumulated on the same nodes (Legendre integration
// matrix); M doubles until two orders agree to max(rtol, eps^(3/4)).
// Beyond long double, graded kinks get geometric layers of panels and the
// own zone's graded panels a high-order inner rule (see make_panels and
// graded_inner_order). The
// nested adaptive evaluations remain as energy_hat_adaptive / hhat_adaptive
// (reference only: ~1000x slower).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "hertz.hpp"
#include "newton.hpp"
#include "numerics.hpp"
#include "pressure.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> struct general_options {
  int max_iterations = 100;  // Newton iterations per solve (continuation: per step)
  T rtol = T(0);             // 0: full precision of T
  int max_order = 1024;      // largest Gauss-Legendre order per panel (solver, energies and slips)
};

namespace gdetail {

template <class T> struct panel {
  T lo, hi;
  int grade;  // 0: none, -1: graded towards lo, +1: towards hi
};

// Exponent of the polynomial grading at log-singular kinks: on the graded
// panel (t - k) ln|t - k| becomes u^(2m-1) ln u, whose Gauss-Legendre error
// falls like N^(-4m); m is chosen so that N ~ 16 reaches eps.
template <class T> int grading_power() {
  const int d10 = std::numeric_limits<T>::digits10;
  return std::max(4, (d10 * 10 + 47) / 48);
}

// Geometric layers around graded kinks for the fixed-rule energies and slips
// (see make_panels); none up to long double, where the map alone suffices
// (m = 4) and the double-precision cost and results stay as they were.
template <class T> int kink_layers() {
  return std::numeric_limits<T>::digits10 > 20 ? 6 : 0;
}

// Panels on [0, pi/2] in theta for a zone of length d next to a stick zone
// of length e; kinks: theta values with their grading flag.
// layers > 0 (fixed-rule energies beyond double): the graded panels at a
// graded kink are confined to length h 2^-layers (h: the smaller reach, i.e.
// distance to the zone end or half way to another kink), and ungraded panels
// doubling in length away from the kink fill each reach. Without them the
// map theta = k + L u^m (m = 11 at 50 digits) squeezes the analyticity
// region of the smooth factors by ~m, and the long panel beyond the kink
// sees the kink at 1/6 of its length: both gave ~1e-30 at order 64.
template <class T>
std::vector<panel<T>> make_panels(const T &d, const T &e, std::vector<std::pair<T, bool>> kinks, int layers = 0) {
  using std::asin; using std::sqrt; using std::min; using std::ldexp;
  const T half_pi = pi<T>() / 2;
  std::vector<std::pair<T, bool>> pts = kinks;
  pts.push_back({T(0), false});
  pts.push_back({half_pi, false});
  if (layers > 0) {
    for (const auto &k : kinks) {
      if (!k.second) continue;
      // reach on each side: to the zone end or half way to another kink
      T lo = k.first, hi = half_pi - k.first;
      for (const auto &o : kinks) {
        if (o.first < k.first) lo = min(lo, (k.first - o.first) / 2);
        if (o.first > k.first) hi = min(hi, (o.first - k.first) / 2);
      }
      const T h = min(lo, hi);
      if (!(h > 0)) continue;
      for (T st = ldexp(h, -layers); st < lo; st *= 2) pts.push_back({k.first - st, false});
      for (T st = ldexp(h, -layers); st < hi; st *= 2) pts.push_back({k.first + st, false});
    }
  }
  // geometric grading towards theta = 0 (singularity at theta ~ i sqrt(e/d))
  const T epsr = sqrt(e / d);
  if (epsr < half_pi / 2) {
    T g = epsr < 1 ? asin(epsr) : epsr;
    // a panel [g, 2g] is 1.5 of its half-lengths... from the singularity: ratio 2
    // (no floor above the scale itself: a floor at eps^2 left one panel
    // [0, eps^2] across the near-singularity once e < eps^4 d, sigma/(f p0)
    // of a few hundred; issue 13)
    using std::sqrt;
    const T tiny = sqrt(boost::math::tools::min_value<T>());
    if (g < tiny) g = tiny;
    for (; g < half_pi / 2; g *= 2) pts.push_back({g, false});
  }
  std::sort(pts.begin(), pts.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  // merge equal points (a graded flag wins)
  std::vector<std::pair<T, bool>> u;
  for (const auto &p : pts) {
    if (!u.empty() && !(p.first > u.back().first)) {
      u.back().second = u.back().second || p.second;
      continue;
    }
    u.push_back(p);
  }
  std::vector<panel<T>> out;
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    const T lo = u[i].first, hi = u[i + 1].first;
    const bool gl = u[i].second, gh = u[i + 1].second;
    if (gl && gh) {
      const T mid = (lo + hi) / 2;
      out.push_back({lo, mid, -1});
      out.push_back({mid, hi, +1});
    } else {
      out.push_back({lo, hi, gl ? -1 : (gh ? 1 : 0)});
    }
  }
  return out;
}

// Calls f(theta, weight) for every node of the composite rule of order n.
template <class T, class F> void for_nodes(const std::vector<panel<T>> &panels, int n, const F &f) {
  using std::pow;
  const auto rule = gauss_legendre<T>(n);
  const int m = grading_power<T>();
  for (const auto &pn : panels) {
    const T L = pn.hi - pn.lo;
    for (int i = 0; i < n; ++i) {
      const T t = rule->x[i], w = rule->w[i];
      if (pn.grade == 0) {
        f(pn.lo + L * (1 + t) / 2, L * w / 2);
      } else {
        const T u = pn.grade < 0 ? (1 + t) / 2 : (1 - t) / 2;
        T um1 = 1;
        for (int k = 0; k < m - 1; ++k) um1 *= u;
        const T off = L * um1 * u;
        const T wt = L * T(m) * um1 * w / 2;
        f(pn.grade < 0 ? pn.lo + off : pn.hi - off, wt);
      }
    }
  }
}

// Calls f(theta, pi/2 - theta, weight, jacobian) for every node of the
// composite rule of order n (weight = jacobian * Gauss-Legendre weight);
// pi/2 - theta is formed without cancellation near pi/2.
template <class T, class F> void for_nodes_c(const std::vector<panel<T>> &panels, int n, const F &f) {
  const auto rule = gauss_legendre<T>(n);
  const int m = grading_power<T>();
  const T half_pi = pi<T>() / 2;
  for (const auto &pn : panels) {
    const T L = pn.hi - pn.lo, top = half_pi - pn.hi;
    for (int i = 0; i < n; ++i) {
      const T t = rule->x[i], w = rule->w[i];
      if (pn.grade == 0) {
        f(pn.lo + L * (1 + t) / 2, top + L * (1 - t) / 2, L * w / 2, L / 2);
      } else {
        const T u = pn.grade < 0 ? (1 + t) / 2 : (1 - t) / 2;
        T um1 = 1, geo = 1;  // u^(m-1), 1 + u + ... + u^(m-1)
        for (int k = 0; k < m - 1; ++k) { um1 *= u; geo += um1; }
        const T off = L * um1 * u;
        const T jac = L * T(m) * um1 / 2;
        if (pn.grade < 0) f(pn.lo + off, top + L * (1 - t) / 2 * geo, jac * w, jac);
        else f(pn.hi - off, top + off, jac * w, jac);
      }
    }
  }
}

// The nodes of one slip zone in theta (t = stick edge +- d sin^2 theta) with
// what the zone energy and slip need there.
template <class T> struct zone_nodes {
  int n = 0;                     // nodes per panel
  T d{0};
  std::vector<panel<T>> panels;
  std::vector<T> s2, c2, w, jac;  // sin^2, cos^2 (each accurate), weight, d theta/d x
  std::vector<T> H;               // Cauchy density per d theta: 2 d c2 sqrt(far) phi / sqrt(e + d s2)
  std::vector<T> p;               // p_hat
  std::vector<char> graded;       // node on a graded panel
};

// cut: an extra (ungraded) panel end in (0, pi/2), if any; graded_only: keep
// only the graded panels (the high-order inner rule of hgrad_nodes).
template <class T>
zone_nodes<T> make_zone_nodes(const pressure_model<T> &pm, int side, const T &d, const T &e, int n,
                              const T *cut = nullptr, bool graded_only = false) {
  using std::asin; using std::sin; using std::sqrt;
  zone_nodes<T> z;
  z.n = n;
  z.d = d;
  if (!(d > 0)) return z;
  std::vector<std::pair<T, bool>> kinks;
  for (const auto &bp : pm.breakpoints()) {
    const T dist = side > 0 ? bp.x - 1 + d : d - 1 - bp.x;
    if (dist > 0 && dist < d) kinks.push_back({asin(sqrt(dist / d)), bp.graded});
  }
  if (cut && *cut > 0 && *cut < pi<T>() / 2) kinks.push_back({*cut, false});
  z.panels = make_panels<T>(d, e, kinks, kink_layers<T>());
  if (graded_only) {
    std::vector<panel<T>> g;
    for (const auto &pn : z.panels)
      if (pn.grade != 0) g.push_back(pn);
    z.panels.swap(g);
  }
  const std::size_t N = z.panels.size() * std::size_t(n);
  z.s2.reserve(N); z.c2.reserve(N); z.w.reserve(N); z.jac.reserve(N); z.H.reserve(N); z.p.reserve(N);
  for_nodes_c<T>(z.panels, n, [&](const T &th, const T &thc, const T &w, const T &jac) {
    const T sn = sin(th), cs = sin(thc);
    const T s2 = sn * sn, c2 = cs * cs;
    const T dc = d * c2, ds = d * s2;
    const T t = side > 0 ? (s2 < T(0.5) ? 1 - d + ds : 1 - dc) : (s2 < T(0.5) ? d - 1 - ds : dc - 1);
    const T dm = side > 0 ? 2 - dc : dc, dp = side > 0 ? dc : 2 - dc;
    const T far = side > 0 ? dm : dp;
    const T ph = pm.phi(t, dm, dp);
    z.s2.push_back(s2);
    z.c2.push_back(c2);
    z.w.push_back(w);
    z.jac.push_back(jac);
    z.H.push_back(2 * d * c2 * sqrt(far) * ph / sqrt(e + ds));
    z.p.push_back(sqrt(dm * dp) * ph);
  });
  for (const auto &pn : z.panels) z.graded.insert(z.graded.end(), std::size_t(n), char(pn.grade != 0));
  return z;
}

}  // namespace gdetail

// Sums of the single-zone integrals (I2: the moment about the stick-zone
// centre, int p_hat (t - c)/R(t) dt) and their derivatives in the zone length
// d at fixed stick-zone length e (a translation of the stick zone) and in e
// at fixed d. Derivatives in b1 and b2 separately are each O(1/e) and cancel
// in the translation: formed that way, the Jacobian lost every digit once
// e < ~1e-16 (large sigma; issue 13). The d-derivative below is O(ln(1/e));
// the e-derivative is kept as e dI/de (the 1/e^(3/2) of each node times e
// overflowed for e < 1e-205).
template <class T> struct zone_sums {
  T I1{0}, I2{0}, I1d{0}, I2d{0}, I1le{0}, I2le{0};
};

// Single-zone integrals I_j = int_zone p_hat t^(j-1)/R(t) dt, j = 1, 2, and
// (if jac) their derivatives in b1 and b2, by the composite rule of order n.
// side = +1: zone (b1, 1) of length d = d1; side = -1: zone (-1, -b2), d = d2.
// e = b1 + b2 > 0.
template <class T>
zone_sums<T> zone_integrals(const pressure_model<T> &pm, int side, const T &d, const T &e, int n, bool jac) {
  using std::asin; using std::cos; using std::sin; using std::sqrt;
  zone_sums<T> r;
  if (!(d > 0)) return r;
  // kinks inside the zone, as theta
  std::vector<std::pair<T, bool>> kinks;
  for (const auto &bp : pm.breakpoints()) {
    // distance from the stick edge of the zone: zone R: t - b1 = t - 1 + d; zone L: -b2 - t = 1 - d - t
    const T dist = side > 0 ? bp.x - 1 + d : d - 1 - bp.x;
    if (dist > 0 && dist < d) kinks.push_back({asin(sqrt(dist / d)), bp.graded});
  }
  const auto panels = gdetail::make_panels<T>(d, e, kinks);
  gdetail::for_nodes<T>(panels, n, [&](const T &th, const T &w) {
    const T sn = sin(th), cs = cos(th);
    const T s2 = sn * sn, c2 = cs * cs;
    const T dc = d * c2;           // distance to the contact edge
    const T ds = d * s2;           // distance to the stick edge
    const T g = e + ds;            // |t - (other stick edge)|: t + b2 (R) or b1 - t (L)
    const T t = side > 0 ? (s2 < T(0.5) ? 1 - d + ds : 1 - dc) : (s2 < T(0.5) ? d - 1 - ds : dc - 1);
    const T dm = side > 0 ? 2 - dc : dc;  // 1 + t
    const T dp = side > 0 ? dc : 2 - dc;  // 1 - t
    T dph = 0;
    const T ph = jac ? pm.phi_dphi(t, dm, dp, dph) : pm.phi(t, dm, dp);
    const T far = side > 0 ? dm : dp;     // distance to the far contact edge
    const T sf = sqrt(far);
    const T psi = sf * ph;                 // p_hat / sqrt(distance to the near edge)
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
  });
  return r;
}

// Residuals and Jacobian in (x1, ln e) of the unified system.
template <class T> struct general_eval {
  T F1, F2;
  T J11, J12, J21, J22;  // dF/dx1, dF/dln e
};

template <class T> struct general_state {
  T x1;  // +d1 (same sign), -d1 (opposite sign)
  T e;   // b1 + b2
  T d1() const { using std::abs; return abs(x1); }
  T d2() const { return 2 - d1() - e; }
  int sR() const { return x1 < 0 ? -1 : 1; }
};

template <class T>
general_eval<T> general_residual(const pressure_model<T> &pm, const T &q, const T &s, const general_state<T> &st,
                                 int n, bool jac) {
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
  return r;
}

// ---------------------------------------------------------------------------
template <class T>
class general_solution : public canonical_solution<general_solution<T>, T, general_scene<T>> {
 public:
  using base = canonical_solution<general_solution<T>, T, general_scene<T>>;
  using base::reg; using base::beta1; using base::beta2; using base::delta1; using base::delta2;
  using base::width; using base::rtol; using base::scene; using base::mirror; using base::negate;
  using base::dirR; using base::dirL; using base::iterations; using base::sign; using base::locate;
  int continuation_steps = 0;
  int order = 0;            // Gauss-Legendre order per panel of the accepted residual
  int max_order = 1024;     // largest order of the energies and slips (general_options::max_order)
  std::shared_ptr<const pressure_model<T>> owned;  // mirrored view, if any
  const pressure_model<T> *pm = nullptr;            // canonical pressure (must outlive)

  T quad_tol() const {
    using std::cbrt;
    const T c = cbrt(eps<T>());
    return c * c;  // tanh-sinh converges quadratically: far below this in practice
  }

  // C_Z(xi) = int_Z p_hat(t) / (R(t) (t - xi)) dt (principal value when xi in Z)
  // for the canonical point xi at distance dl from the stick edge of zone pz.
  T cauchy(int zside, int pz, const T &dl) const {
    using std::asin; using std::cos; using std::sin; using std::sqrt;
    const T d = zside > 0 ? delta1 : delta2;
    if (!(d > 0)) return T(0);
    const T e = width;
    auto H = [&](const T &th, const T &thc) {  // thc: pi/2 - th
      const T sn = sin(th), cs = sin(thc);
      const T s2 = sn * sn, c2 = cs * cs;
      const T dc = d * c2, ds = d * s2;
      const T t = zside > 0 ? (s2 < T(0.5) ? 1 - d + ds : 1 - dc) : (s2 < T(0.5) ? d - 1 - ds : dc - 1);
      const T dm = zside > 0 ? 2 - dc : dc, dp = zside > 0 ? dc : 2 - dc;
      const T far = zside > 0 ? dm : dp;
      return 2 * d * c2 * sqrt(far) * pm->phi(t, dm, dp) / sqrt(e + ds);
    };
    const T half_pi = pi<T>() / 2;
    std::vector<T> cuts;
    for (const auto &bp : pm->breakpoints()) {
      const T dist = zside > 0 ? bp.x - 1 + d : d - 1 - bp.x;
      if (dist > 0 && dist < d) cuts.push_back(asin(sqrt(dist / d)));
    }
    const T tol = quad_tol();
    if (pz != zside) {
      // no singularity: |t - xi| = e + dl + d sin^2
      auto f = [&](const T &th, const T &thc) {
        const T sn = sin(th);
        const T den = e + dl + d * sn * sn;
        return H(th, thc) / den;
      };
      const T sum = integrate_pieces<T>(f, T(0), half_pi, cuts, tol);
      // zone R: t - xi > 0 (xi in zone L); zone L: t - xi < 0 (xi in zone R)
      return zside > 0 ? sum : -sum;
    }
    // principal value: t - xi = +-d (sin^2 th - sin^2 thx); PV int_0^{pi/2} dth/(sin^2 th - c) = 0
    if (!(dl > 0)) return T(0);
    const T ratio = dl / d;
    const T thx = ratio >= 1 ? half_pi : asin(sqrt(ratio));
    const T thxc = ratio >= 1 ? T(0) : half_pi - thx;
    const T Hx = H(thx, thxc);
    cuts.push_back(T(0));
    cuts.push_back(half_pi);
    cuts.push_back(thx);
    std::sort(cuts.begin(), cuts.end());
    T sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const T lo = cuts[i], hi = cuts[i + 1];
      if (!(hi > lo)) continue;
      sum += integrate_ts<T>([&](const T &th, const T &xc) {
        // exact distance to thx when thx is an end of this piece
        T delta;
        if (xc < 0 && lo == thx) delta = -xc;
        else if (xc > 0 && hi == thx) delta = -xc;
        else delta = th - thx;
        const T thc = (xc > 0 && hi == half_pi) ? xc : half_pi - th;
        const T den = sin(delta) * sin(2 * thx + delta);
        if (den == 0) return T(0);
        return (H(th, thc) - Hx) / den;
      }, lo, hi, tol);
    }
    return zside > 0 ? sum / d : -sum / d;
  }

  // canonical dimensionless B_x (units f p0 / E*) at distance dl from the
  // stick edge of zone z (+1: R, -1: L)
  T bhat(int z, const T &dl) const {
    using std::sqrt;
    if (!(dl > 0)) return T(0);
    const T Rx = sqrt(dl * (width + dl));
    const T br = dirR * cauchy(+1, z, dl) - dirL * cauchy(-1, z, dl);
    return (z > 0 ? -2 : 2) * Rx * br / pi<T>();
  }
  // d h / d(dl) in zone z (h = 0 at the stick edge)
  T hgrad(int z, const T &dl) const { return z > 0 ? bhat(z, dl) : -bhat(z, dl); }
  T zone_length(int z) const { return z > 0 ? delta1 : delta2; }

  std::vector<T> kink_distances(int z) const {
    std::vector<T> v;
    const T d = zone_length(z);
    for (const auto &bp : pm->breakpoints()) {
      const T dist = z > 0 ? bp.x - 1 + d : d - 1 - bp.x;
      if (dist > 0 && dist < d) v.push_back(dist);
    }
    return v;
  }

  // canonical slip (units f p0 a / E*), reference evaluation by nested
  // adaptive tanh-sinh
  T hhat_adaptive(int z, const T &dl) const {
    if (!(dl > 0)) return T(0);
    std::vector<T> cuts;
    for (const T &k : kink_distances(z))
      if (k < dl) cuts.push_back(k / dl);
    return dl * integrate_split<T>([&](const T &w) { return hgrad(z, w * dl); }, cuts, quad_tol());
  }

  // ---- fixed-rule zone energy and slip ----
  // Zone z is covered by the solver's panels in theta (u = d sin^2 theta the
  // distance from the stick edge) with Gauss-Legendre of order M per panel
  // (the outer rule). h'(u) = -(2/pi) R(u) (dirR C_R - dirL C_L) is needed at
  // the outer nodes only; the Cauchy integrals C_Z use the same panels of
  // zone Z with order M + 1 (the inner rule). On the own zone, the nodes of
  // orders M and M + 1 on the same panel interlace, so the subtracted
  // principal-value quotient (H(theta) - H(theta_x))/(sin^2 theta -
  // sin^2 theta_x) never sees a near-zero denominator; the pressure is
  // evaluated once per node. Cost: O(M^2 panels^2) arithmetic.

  // Order of the inner rule on the graded panels of the own zone (0: none,
  // the inner rule M + 1 there too). For an outer node theta_j = k - delta
  // near a graded kink k, the quotient (H(theta) - H_j)/(sin^2 theta -
  // sin^2 theta_j) on the graded panel across k continues the other side's
  // log term: poles at u = (delta/L)^(1/m) exp(+-i pi/m) (u the graded
  // variable there), which the rule of order M + 1 resolves only
  // algebraically (measured at 50 digits, M = 64, no layers: 7e-26 for the
  // graded outer nodes; 2e-48 still from the layer next to them; the own
  // graded panel 6e-35). 6M + 1 (also interlacing) reaches the precision.
  // Not needed in double (m = 4: the errors stay below 1e-16).
  static int graded_inner_order(int M) {
    return std::numeric_limits<T>::digits10 > 20 ? 6 * M + 1 : 0;
  }

  // h' at the first `count` outer nodes O of zone z (inner rules IR, IL;
  // G: the high-order rule on the graded panels of zone z, or null).
  std::vector<T> hgrad_nodes(int z, const gdetail::zone_nodes<T> &O, const gdetail::zone_nodes<T> &IR,
                             const gdetail::zone_nodes<T> &IL, std::size_t count,
                             const gdetail::zone_nodes<T> *G = nullptr) const {
    using std::sqrt;
    const T e = width;
    std::vector<T> g(count, T(0));
    for (std::size_t j = 0; j < count; ++j) {
      const T sj = O.s2[j], cj = O.c2[j];
      const T u = O.d * sj;
      T br = 0;
      for (int Z : {+1, -1}) {
        const int dir = Z > 0 ? dirR : dirL;
        const auto &I = Z > 0 ? IR : IL;
        if (dir == 0 || !(I.d > 0)) continue;
        const std::size_t n = I.s2.size();
        T sum = 0;
        if (Z == z) {
          // t - xi = Z d (sin^2 theta - sin^2 theta_j); PV int_0^{pi/2} dtheta/(sin^2 theta - c) = 0
          const T Hj = O.H[j];
          const bool hi = G && !G->s2.empty();
          for (std::size_t i = 0; i < n; ++i) {
            if (hi && I.graded[i]) continue;
            const T den = (I.s2[i] + sj < 1) ? I.s2[i] - sj : cj - I.c2[i];
            // den = 0 only where both nodes have merged into a graded panel
            // end in rounding (high orders): weights there are negligible
            if (den != 0) sum += I.w[i] * (I.H[i] - Hj) / den;
          }
          if (hi) {
            for (std::size_t i = 0; i < G->s2.size(); ++i) {
              const T den = (G->s2[i] + sj < 1) ? G->s2[i] - sj : cj - G->c2[i];
              if (den != 0) sum += G->w[i] * (G->H[i] - Hj) / den;
            }
          }
          sum /= I.d;
        } else {
          // |t - xi| = e + u + d_Z sin^2 theta
          const T base = e + u;
          for (std::size_t i = 0; i < n; ++i) sum += I.w[i] * I.H[i] / (base + I.d * I.s2[i]);
        }
        // C_Z = Z sum; br = dirR C_R - dirL C_L
        br += T(dir) * sum;
      }
      g[j] = -2 * sqrt(u * (e + u)) * br / pi<T>();
    }
    return g;
  }

  // zone energy with the outer order M (see above), by parts:
  // int_0^d tail(d - u) h'(u) du with the tail cumulated on the outer nodes
  T energy_hat_order(int z, int M) const {
    using std::abs; using std::sqrt;
    const T d = zone_length(z);
    if (!(d > 0)) return T(0);
    const auto O = gdetail::make_zone_nodes<T>(*pm, z, d, width, M);
    const auto IR = gdetail::make_zone_nodes<T>(*pm, +1, delta1, width, M + 1);
    const auto IL = gdetail::make_zone_nodes<T>(*pm, -1, delta2, width, M + 1);
    const int Kg = graded_inner_order(M);
    gdetail::zone_nodes<T> G;
    if (Kg > 0) G = gdetail::make_zone_nodes<T>(*pm, z, d, width, Kg, nullptr, true);
    const std::vector<T> g = hgrad_nodes(z, O, IR, IL, O.s2.size(), Kg > 0 ? &G : nullptr);
    const auto cum = gauss_legendre_cumulative<T>(M);
    std::vector<T> f(M);
    T after = 0, E = 0;
    for (std::size_t P = O.panels.size(); P-- > 0;) {
      const std::size_t b = P * M;
      T tot = 0;
      for (int k = 0; k < M; ++k) {
        // p_hat du/dtheta, du/dtheta = 2 d sin cos
        f[k] = O.p[b + k] * 2 * d * sqrt(O.s2[b + k] * O.c2[b + k]);
        tot += O.w[b + k] * f[k];
      }
      for (int i = 0; i < M; ++i) {
        T tail = 0;
        for (int k = 0; k < M; ++k) tail += cum->S[std::size_t(i) * M + k] * O.jac[b + k] * f[k];
        tail += after;
        E += O.w[b + i] * 2 * d * sqrt(O.s2[b + i] * O.c2[b + i]) * tail * g[b + i];
      }
      after += tot;
    }
    return abs(E);
  }

  // slip at distance dl from the stick edge with the outer order M: the
  // panels of zone z (outer and inner rules alike, so that their nodes still
  // interlace) get an extra end at theta_x = asin(sqrt(dl/d)); h is the sum
  // over the panels below it (relative accuracy also for dl << d).
  T hhat_order(int z, const T &dl, int M) const {
    using std::asin; using std::sqrt;
    const T d = zone_length(z);
    if (!(dl > 0) || !(d > 0)) return T(0);
    const T half_pi = pi<T>() / 2;
    const T thx = dl >= d ? half_pi : (2 * dl <= d ? T(asin(sqrt(dl / d))) : half_pi - asin(sqrt((d - dl) / d)));
    const auto O = gdetail::make_zone_nodes<T>(*pm, z, d, width, M, &thx);
    std::size_t np = 0;
    while (np < O.panels.size() && !(O.panels[np].hi > thx)) ++np;
    const auto IR = gdetail::make_zone_nodes<T>(*pm, +1, delta1, width, M + 1, z > 0 ? &thx : nullptr);
    const auto IL = gdetail::make_zone_nodes<T>(*pm, -1, delta2, width, M + 1, z < 0 ? &thx : nullptr);
    const int Kg = graded_inner_order(M);
    gdetail::zone_nodes<T> G;
    if (Kg > 0) G = gdetail::make_zone_nodes<T>(*pm, z, d, width, Kg, &thx, true);
    const std::vector<T> g = hgrad_nodes(z, O, IR, IL, np * M, Kg > 0 ? &G : nullptr);
    T h = 0;
    for (std::size_t j = 0; j < np * std::size_t(M); ++j) h += O.w[j] * 2 * d * sqrt(O.s2[j] * O.c2[j]) * g[j];
    return h;
  }

  // canonical zone energy int p_hat |h| (units f^2 p0^2 a^2 / E*), by parts:
  // dir * int_0^d tail(d - u) h'(u) du. Reference evaluation by nested
  // adaptive tanh-sinh (slow: pressure tails and Cauchy integrals per node).
  T energy_hat_adaptive(int z) const {
    using std::abs;
    const T d = zone_length(z);
    if (!(d > 0)) return T(0);
    std::vector<T> cuts;
    for (const T &k : kink_distances(z)) cuts.push_back(k);
    // c: distance to the contact edge
    const T sum = integrate_pieces<T>([&](const T &u, const T &c) { return pm->tail(z, c) * hgrad(z, u); }, T(0), d,
                                      cuts, quad_tol());
    return abs(sum);
  }

  // Outer order control: from the smallest power of two >= 2/3 of the
  // digits of T (as the solver starts; 1/2 beyond double), the order doubles until two
  // successive results agree to energy_tol(); the
  // result of the higher order is returned (its error is far below the
  // difference: geometric convergence on the smooth panels, N^(-4m) on the
  // graded ones).
  T energy_tol() const {
    using std::max; using std::sqrt;
    const T e34 = sqrt(eps<T>() * sqrt(eps<T>()));
    return max(rtol, e34);
  }
  template <class F> T by_order(const F &f) const {
    using std::abs; using std::max;
    const T tol = energy_tol();
    int M = 4;
    {
      using std::log10;
      const T digits = -log10(eps<T>());
      // with the kink layers (beyond double) every panel converges
      // geometrically; order 32 is already within ~1e-39 at 50 digits
      const T start = gdetail::kink_layers<T>() > 0 ? digits / 2 : digits * 2 / 3;
      while (T(M) < start) M *= 2;
    }
    T v = f(M);
    for (; 2 * M <= max_order; M *= 2) {
      const T v2 = f(2 * M);
      if (!(abs(v2 - v) > tol * abs(v2))) return v2;
      v = v2;
    }
    // the orders allowed ran out before two agreed: report it (no silent value)
    throw error(status::no_convergence, "zone energy or slip: no two orders agreed up to the order limit (max_order)");
  }
  T energy_hat(int z) const {
    if (!(zone_length(z) > 0)) return T(0);
    return by_order([&](int M) { return energy_hat_order(z, M); });
  }
  T hhat(int z, const T &dl) const {
    if (!(dl > 0) || !(zone_length(z) > 0)) return T(0);
    return by_order([&](int M) { return hhat_order(z, dl, M); });
  }

  // Shear traction q(x) on body 1 (traction.hpp), split at the pressure's kinks.
  std::vector<T> user_kinks() const {
    std::vector<T> k;
    for (const auto &bp : pm->breakpoints()) k.push_back(scene.a * (mirror ? -bp.x : bp.x));
    return k;
  }
  T traction(const T &x) const { return this->traction_generic(x, user_kinks()); }

  T pressure(const T &x) const {
    const T xi = (mirror ? -x : x) / scene.a;
    if (!(xi > -1 && xi < 1)) return T(0);
    return scene.p0 * pm->p(xi);
  }
};

namespace gdetail {

template <class T> T residual_norm(const general_eval<T> &r) {
  using std::abs;
  return abs(r.F1) + abs(r.F2);
}

// Newton from a start at fixed order n; true on convergence.
template <class T>
bool newton(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int n, const T &tol_step,
            int max_it, int &iterations, const general_eval<T> *r0 = nullptr) {
  using std::abs; using std::exp; using std::max;
  const T tiny = boost::math::tools::min_value<T>() / eps<T>();
  const T noise_floor = 64 * eps<T>() * pi<T>() * (1 + s);
  general_eval<T> r = r0 ? *r0 : general_residual(pm, q, s, st, n, true);
  T norm = residual_norm(r);
  T prev_step = -1;
  for (int it = 1; it <= max_it; ++it) {
    ++iterations;
    const T det = r.J11 * r.J22 - r.J12 * r.J21;
    if (!(det != 0) || !(abs(det) < boost::math::tools::max_value<T>())) return false;
    T dx = -(r.F1 * r.J22 - r.F2 * r.J12) / det;
    T dy = -(r.J11 * r.F2 - r.J21 * r.F1) / det;
    const T a11 = r.J11, a12 = r.J12, a21 = r.J21, a22 = r.J22;
    auto level = [&](const general_eval<T> &f) {
      return abs((f.F1 * a22 - f.F2 * a12) / det) + abs((a11 * f.F2 - a21 * f.F1) / det);
    };
    const T level0 = abs(dx) + abs(dy);
    // a full step below the step tolerance after a converging one: take it
    // without evaluating the residual there (it would only confirm the step)
    if (prev_step >= 0 && max(abs(dx), abs(dy)) <= tol_step && max(abs(dx), abs(dy)) <= prev_step) {
      st.x1 += dx;
      st.e *= exp(dy);
      return true;
    }
    const T cap = 4;
    if (abs(dy) > cap) { dx *= cap / abs(dy); dy = dy > 0 ? cap : -cap; }
    if (abs(dx) > 1) { dy /= abs(dx); dx = dx > 0 ? T(1) : T(-1); }
    T lam = 1;
    general_state<T> nst;
    general_eval<T> nr;
    T nnorm = 0;
    bool ok = false;
    for (int k = 0; k < 40; ++k, lam /= 2) {
      nst.x1 = st.x1 + lam * dx;
      nst.e = st.e * exp(lam * dy);
      const T nd2 = nst.d2();
      if (!(nst.e > tiny) || !(nd2 > st.d2() / 4) || !(nst.d1() < 2)) continue;
      nr = general_residual(pm, q, s, nst, n, true);
      nnorm = residual_norm(nr);
      if (!(nnorm == nnorm)) continue;
      if (level(nr) <= (1 - lam / 4) * level0 || (nnorm <= noise_floor && nnorm <= norm)) {
        ok = true;
        break;
      }
    }
    if (!ok) return norm <= noise_floor;
    const T step = max(abs(lam * dx), abs(lam * dy));
    st = nst;
    r = nr;
    norm = nnorm;
    if (lam == 1 && step <= tol_step) return true;
    if (norm <= noise_floor && prev_step >= 0 && step >= prev_step / 4) return true;
    prev_step = step;
  }
  return false;
}

// Start at s = 0: the restriction of F2 to b1 = b2 = 1 - d (e = 2 - 2d),
// F2(d) = I2L - I2R + pi q/2, falls monotonically from pi q/2 (d = 0) to
// pi (q - 1)/2 (d -> 1); bracketed Illinois iteration in d to sqrt(eps).
// (For a symmetric pressure this is eq (15) and b1 = b2 exactly; for an
// asymmetric one it is a start for the 2D Newton.)
template <class T>
general_state<T> shear_only_start(const pressure_model<T> &pm, const T &q, int n) {
  using std::abs; using std::sqrt;
  auto F = [&](const T &d) {
    return general_residual(pm, q, T(0), general_state<T>{d, 2 * (1 - d)}, n, false).F2;
  };
  T lo = 0, hi = 1, flo = pi<T>() * q / 2, fhi = pi<T>() * (q - 1) / 2;
  int side = 0;
  const T tol = sqrt(eps<T>());
  for (int it = 0; it < 200 && hi - lo > tol; ++it) {
    T d = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(d > lo && d < hi)) d = (lo + hi) / 2;
    const T fd = F(d);
    if (fd > 0) {
      lo = d; flo = fd;
      if (side == +1) fhi /= 2;
      side = +1;
    } else {
      hi = d; fhi = fd;
      if (side == -1) flo /= 2;
      side = -1;
    }
  }
  const T d = (lo + hi) / 2;
  return {d, 2 * (1 - d)};
}

// Sliding stick point (issue 13): as s grows the stick zone shrinks onto the
// point x0 where the limiting friction forces of the two slip zones balance
// Q, q pi/2 = int_{-1}^{x0} p_hat - int_{x0}^{1} p_hat, i.e. the tail of p_hat
// beyond x0 is pi (1 - q)/4. Returns d_inf = 1 - x0 (Illinois on the tail,
// which grows monotonically with its length; false if the iteration limit is
// reached).
template <class T> bool sliding_point(const pressure_model<T> &pm, const T &q, T &d_inf) {
  using std::abs;
  const T target = pi<T>() * (1 - q) / 4;
  T lo = 0, hi = 2, flo = -target, fhi = pi<T>() / 2 - target;
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    T d = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(d > lo && d < hi)) d = (lo + hi) / 2;
    const T fd = pm.tail(+1, d) - target;
    if (fd < 0) { lo = d; flo = fd; if (side == -1) fhi /= 2; side = -1; }
    else { hi = d; fhi = fd; if (side == +1) flo /= 2; side = +1; }
    if (hi - lo <= 4 * eps<T>() * hi || fd == 0) { d_inf = fd == 0 ? d : (lo + hi) / 2; return true; }
  }
  return false;
}

// Start for large s (issue 13): the stick zone centred on the sliding stick
// point x0, its width e from F1 = 0 at that centre. F1 is nearly linear in
// ln e once e << 1 (the zone integrals grow like ln(1/e)): secant steps in
// ln e from two small widths. Newton in (x1, ln e) then follows x0 and the
// width on a log scale. False if no such start exists (the stick zone would
// be below the range of T: tiny_le is ln of the smallest width allowed).
// below_range is set when the width would be below exp(tiny_le).
template <class T>
bool large_sigma_start(const pressure_model<T> &pm, const T &q, const T &s, int n, const T &tiny_le,
                       general_state<T> &out, bool &below_range) {
  using std::abs; using std::exp; using std::log; using std::max; using std::min;
  T d_inf;
  if (!sliding_point(pm, q, d_inf) || !(d_inf > 0 && d_inf < 2)) return false;
  auto F1 = [&](const T &le) {
    const T e = exp(le);
    return general_residual(pm, q, s, general_state<T>{-(d_inf - e / 2), e}, n, false).F1;
  };
  const T cap = log(min(min(T(1), T(d_inf / 2)), T((2 - d_inf) / 2)));
  T l0 = min(T(-8), cap), l1 = l0 - 8;
  T f0 = F1(l0), f1 = F1(l1);
  for (int it = 0; it < 30; ++it) {
    if (!(f1 != f0) || !(f0 == f0) || !(f1 == f1)) return false;
    T l2 = l1 - f1 * (l1 - l0) / (f1 - f0);
    l2 = min(l2, cap);
    if (!(l2 > tiny_le)) { below_range = l2 <= tiny_le; return false; }
    const T f2 = F1(l2);
    l0 = l1; f0 = f1; l1 = l2; f1 = f2;
    if (abs(l1 - l0) <= T(1e-3) * (1 + abs(l1))) break;
  }
  const T e = exp(l1);
  out = {-(d_inf - e / 2), e};
  return out.d2() > 0;
}

// Continuation in s from s = 0 with the tangent predictor dx/ds = -J^-1 dF/ds.
template <class T>
bool continuation(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int n,
                  const T &tol_step, int max_it, int &iterations, int &steps) {
  using std::abs; using std::exp; using std::ldexp;
  T sc = 0;
  // (s may be denormal: s/4 and s 2^-40 then underflow to 0; every step
  // must make progress, else a zero step loops for ever: fuzzer input
  // tests/fuzz/corpus/solve/timeout-denormal-sigma)
  T h = s / 4;
  if (!(h > 0)) h = s;
  const T hmin = s * ldexp(T(1), -40);
  const T tiny = boost::math::tools::min_value<T>() / eps<T>();
  while (sc < s) {
    if (!(h > 0) || h < hmin) return false;
    const T sn = (s - sc <= h || !(sc + h > sc)) ? s : sc + h;
    const T ds = sn - sc;
    // tangent predictor
    general_state<T> pred = st;
    const general_eval<T> r = general_residual(pm, q, sc, st, n, true);
    const T pi_ = pi<T>();
    const T Fs1 = -pi_ / 4, Fs2 = 0;  // F2 (the moment about the centre) has no s
    const auto x = solve2x2(r.J11, r.J12, r.J21, r.J22, Fs1, Fs2);
    if (x.det != 0) {
      const T dx = -x.x1, dy = -x.x2;
      general_state<T> p2{st.x1 + ds * dx, st.e * exp(ds * dy)};
      if (p2.e > tiny && p2.d2() > 0 && p2.d1() < 2) pred = p2;
    }
    int its = 0;
    general_state<T> trial = pred;
    ++steps;
    if (newton(pm, q, sn, trial, n, tol_step, max_it, its)) {
      iterations += its;
      st = trial;
      sc = sn;
      if (its <= 4) h *= 2;
    } else {
      iterations += its;
      h /= 4;
    }
  }
  return true;
}

}  // namespace gdetail

// Solve a general scene for the pressure pm (dimensionless model; scene
// gives a, p0, f, E* for the dimensional outputs). pm must outlive the
// solution. Throws hs::core::error on bad input or failure.
template <class T>
general_solution<T> solve_general(const pressure_model<T> &pm, const general_scene<T> &sc,
                                  const general_options<T> &opt = {}) {
  using std::abs; using std::max; using std::sqrt;
  validate(sc);
  if (opt.max_iterations < 1 || opt.max_order < 2 || !(opt.rtol >= 0))
    throw error(status::bad_option, "bad solver options");
  general_solution<T> sol;
  sol.scene = sc;
  sol.rtol = opt.rtol;
  sol.max_order = opt.max_order;
  T q = sc.q, s = sc.s;
  if (q < 0) { sol.negate = true; q = -q; s = -s; }
  if (s < 0) { sol.mirror = true; s = -s; }
  if (sol.mirror && !pm.symmetric()) {
    auto mp = std::make_shared<mirrored_pressure<T>>(pm);
    sol.owned = mp;
    sol.pm = mp.get();
  } else {
    sol.pm = &pm;
  }
  const pressure_model<T> &P = *sol.pm;
  if (q == 0 && s == 0) { sol.reg = regime::stuck; return sol; }

  const T tolq = max(opt.rtol, 64 * eps<T>());
  const T tol_step = max(opt.rtol, 4 * eps<T>());
  const T qtol = tolq * pi<T>() * (1 + s);
  // initial order from the tolerance: the smallest power of two >= 2/3 of
  // the digits asked for (the residual is then validated at twice the order)
  int n = 4;
  {
    using std::log10;
    const T digits = -log10(tolq);
    while (T(n) < digits * 2 / 3) n *= 2;
  }  // start: the Hertz solution of the same (q, s)
  general_state<T> st;
  {
    hertz_scene<T> hs;
    hs.q = q; hs.s = s;
    const auto h = solve_hertz(hs);
    st.x1 = h.reg == regime::opposite_sign ? -h.delta1 : h.delta1;
    st.e = h.width;
    // for a model with a known shear-only stick half-width c, scale the Hertz
    // stick zone about its centre by c / sqrt(1 - q) (exact at sigma = 0)
    T c;
    if (P.shear_only_half_width(q, c) && c > 0 && c <= 1) {
      using std::sqrt;
      const T cH = sqrt(1 - q);
      const T m = (h.delta2 - h.delta1) / 2, w = h.width / 2 * (c / cH);
      const T nb1 = m + w, nb2 = w - m;
      if (nb1 < 1 && nb2 < 1 && w > 0) {
        st.x1 = h.reg == regime::opposite_sign ? -(1 - nb1) : 1 - nb1;
        st.e = 2 * w;
      }
    }
  }
  int its = 0;
  general_state<T> trial = st;
  bool ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its);
  if (!ok && st.x1 < 0 && st.e < T(0.1)) {
    // large sigma: start from the sliding stick point (issue 13)
    using std::log;
    const T tiny_le = log(boost::math::tools::min_value<T>() / eps<T>());
    bool below = false;
    if (gdetail::large_sigma_start(P, q, s, n, tiny_le, trial, below))
      ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its);
    else if (below) {
      // the quadrature needs the width itself: a clear error, not seconds of
      // continuation that cannot succeed (docs/models.md, domain)
      throw error(status::overflow,
                  "general solver: sigma/(f p0) too large: the stick zone would be narrower than the range of the "
                  "floating-point type (1e-292 a in double)");
    }
  }
  if (!ok) {
    // fallback: continuation in s from the shear-only solution
    general_state<T> s0 = gdetail::shear_only_start(P, q, n);
    if (!gdetail::newton(P, q, T(0), s0, n, tol_step, opt.max_iterations, its))
      throw error(status::no_convergence, "general solver: no convergence at sigma = 0");
    trial = s0;
    if (s > 0 && !gdetail::continuation(P, q, s, trial, n, tol_step, opt.max_iterations, its,
                                        sol.continuation_steps))
      throw error(status::no_convergence, "general solver: continuation in sigma failed");
  }
  st = trial;
  // order control: accept n when the residual with 2n is within qtol; finish
  // with one Newton step on the 2n residual.
  for (;;) {
    const general_eval<T> r2 = general_residual(P, q, s, st, 2 * n, true);
    if (gdetail::residual_norm(r2) <= qtol) {
      const auto x = solve2x2(r2.J11, r2.J12, r2.J21, r2.J22, r2.F1, r2.F2);
      if (x.det != 0) {
        using std::exp;
        const T dx = -x.x1, dy = -x.x2;
        general_state<T> ns{st.x1 + dx, st.e * exp(dy)};
        // keep the regime of the accepted state unless the state sits on the boundary
        if (ns.d2() > 0 && ns.e > 0 && (ns.x1 == 0 || (ns.x1 > 0) == (st.x1 > 0) || abs(st.x1) <= qtol))
          st = ns;
      }
      n *= 2;
      break;
    }
    n *= 2;
    if (2 * n > opt.max_order)
      throw error(status::no_convergence, "general solver: quadrature order limit reached");
    // Newton at the doubled order from the residual just evaluated there
    if (!gdetail::newton(P, q, s, st, n, tol_step, opt.max_iterations, its, &r2))
      throw error(status::no_convergence, "general solver: Newton iteration did not converge");
  }
  sol.iterations = its;
  sol.order = n;
  sol.delta1 = st.d1();
  sol.width = st.e;
  sol.delta2 = st.d2();
  sol.beta1 = 1 - sol.delta1;
  sol.beta2 = 1 - sol.delta2;
  if (st.x1 < 0) {
    sol.reg = regime::opposite_sign;
    sol.dirR = -1;
  } else {
    sol.reg = regime::same_sign;
    sol.dirR = sol.delta1 > 0 ? 1 : 0;
  }
  sol.dirL = 1;
  return sol;
}

}}  // namespace hs::core
