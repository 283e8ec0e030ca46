// halfslip core, general pressures (general.hpp): quadrature panels in theta
// for one slip zone (t = stick edge +- d sin^2 theta), graded at pressure
// kinks and towards the near-singular stick edge; the theta -> (t, 1 + t,
// 1 - t) node map; the kink -> theta map; the node sets of the fixed-rule
// energies and slips.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <boost/math/tools/precision.hpp>

#include "gauss.hpp"
#include "numerics.hpp"
#include "pressure.hpp"

namespace hs { namespace core { namespace gdetail {

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
template <class T> int kink_layers() { return std::numeric_limits<T>::digits10 > 20 ? 6 : 0; }

template <class T> std::vector<panel<T>> panels_between(std::vector<std::pair<T, bool>> pts);

// Geometric layers at the graded kinks (theta, graded) of a range [a, b]: the ungraded panel ends
// k -+ h 2^-layers 2^j (h: the smaller reach, i.e. distance to the range's end or half way to
// another kink) appended to pts, so that the polynomially graded panels at k are h 2^-layers long
// and ungraded panels doubling in length away from k fill each reach (none for layers <= 0).
template <class T> void add_kink_layers(const std::vector<std::pair<T, bool>> &kinks, const T &a, const T &b,
                                        int layers, std::vector<std::pair<T, bool>> &pts) {
  using std::ldexp;
  using std::min;
  if (layers <= 0) return;
  for (const auto &k : kinks) {
    if (!k.second) continue;
    // reach on each side: to the range's end or half way to another kink
    T lo = k.first - a, hi = b - k.first;
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

// Panels on [0, pi/2] in theta for a zone of length d next to a stick zone
// of length e; kinks: theta values with their grading flag.
// layers > 0 (fixed-rule energies beyond double): add_kink_layers. Without them the
// map theta = k + L u^m (m = 11 at 50 digits) squeezes the analyticity
// region of the smooth factors by ~m, and the long panel beyond the kink
// sees the kink at 1/6 of its length: both gave ~1e-30 at order 64.
template <class T>
std::vector<panel<T>> make_panels(const T &d, const T &e, std::vector<std::pair<T, bool>> kinks, int layers = 0) {
  using std::asin;
  using std::sqrt;
  const T half_pi = pi<T>() / 2;
  std::vector<std::pair<T, bool>> pts;
  pts.reserve(kinks.size() + 16);
  pts.assign(kinks.begin(), kinks.end());
  pts.push_back({T(0), false});
  pts.push_back({half_pi, false});
  add_kink_layers(kinks, T(0), half_pi, layers, pts);
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
  return panels_between(std::move(pts));
}

// The panels between consecutive points (theta, graded) of pts (any order; equal points merged,
// a graded flag wins): a panel is graded towards each graded end, and one with both ends graded
// is split at its middle into two, each graded towards its own.
template <class T> std::vector<panel<T>> panels_between(std::vector<std::pair<T, bool>> pts) {
  std::sort(pts.begin(), pts.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  // merge equal points (a graded flag wins)
  std::vector<std::pair<T, bool>> u;
  u.reserve(pts.size());
  for (const auto &p : pts) {
    if (!u.empty() && !(p.first > u.back().first)) {
      u.back().second = u.back().second || p.second;
      continue;
    }
    u.push_back(p);
  }
  std::vector<panel<T>> out;
  out.reserve(2 * u.size());
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

// Distance of the pressure breakpoint x from the stick edge of zone `side`
// of length d (+1: zone R = (b1, 1), x - b1 = x - 1 + d; -1: zone L = (-1, -b2),
// -b2 - x = d - 1 - x); the breakpoint lies inside the zone when it is in (0, d).
template <class T> T kink_distance(int side, const T &d, const T &x) {
  return side > 0 ? T(x - 1 + d) : T(d - 1 - x);
}

// The scale towards which the panels of zone `side` are graded at its stick edge:
// the stick width e (the near singularity at theta ~ i sqrt(e/d)), or, where
// nearer, the distance to a pressure breakpoint just beyond the stick edge, in
// the stick zone: a singularity of the integrands at theta ~ i sqrt(dist/d).
// Issue 13: the power law at n = 1.01 (the cusp |x|^0.01 at x = 0, 1.9e-5 a
// beyond the stick edge of zone 2, stick width 0.124 a) at Q/fP = 0.9977,
// sigma/fp0 = 3 had zone energies off by 5e-6 (estimate 2e-13) from the
// panels graded only to sqrt(e/d).
template <class T> T grading_scale(const pressure_model<T> &pm, int side, const T &d, const T &e) {
  using std::min;
  T g = e;
  for (const auto &bp : pm.breakpoints()) {
    const T dist = -kink_distance(side, d, bp.x);  // > 0: beyond the stick edge
    if (dist > 0 && dist < g) g = dist;
  }
  return g;
}

// The breakpoints inside zone `side` as theta = asin(sqrt(dist/d)), with their
// grading flag (the kink -> theta map of every panel set of a zone).
template <class T> std::vector<std::pair<T, bool>> zone_kinks(const pressure_model<T> &pm, int side, const T &d) {
  using std::asin;
  using std::sqrt;
  std::vector<std::pair<T, bool>> kinks;
  for (const auto &bp : pm.breakpoints()) {
    const T dist = kink_distance(side, d, bp.x);
    if (dist > 0 && dist < d) kinks.push_back({asin(sqrt(dist / d)), bp.graded});
  }
  return kinks;
}

// The node map: the point t = stick edge +- d sin^2 theta of zone `side` of
// length d, from s2 = sin^2 theta and c2 = cos^2 theta (each accurate), with
// its distances dm = 1 + t, dp = 1 - t to the contact edges, all without
// cancellation (t from the nearer zone end).
template <class T> struct zone_point {
  T t, dm, dp;
  const T &far(int side) const { return side > 0 ? dm : dp; }  // distance to the far contact edge
};

template <class T> zone_point<T> zone_point_at(int side, const T &d, const T &s2, const T &c2) {
  const T dc = d * c2, ds = d * s2;
  if (side > 0) return {s2 < T(0.5) ? T(1 - d + ds) : T(1 - dc), T(2 - dc), dc};
  return {s2 < T(0.5) ? T(d - 1 - ds) : T(dc - 1), dc, T(2 - dc)};
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
  // no panels, no rule (the graded-only inner rule of order 6M + 1 of a zone
  // without graded panels: at 120 digits its rules were most of the energies' time)
  if (panels.empty()) return;
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
        for (int k = 0; k < m - 1; ++k) {
          um1 *= u;
          geo += um1;
        }
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
  int n = 0;  // nodes per panel
  T d{0};
  std::vector<panel<T>> panels;
  std::vector<T> s2, c2, w, jac;  // sin^2, cos^2 (each accurate), weight, d theta/d x
  std::vector<T> H;               // Cauchy density per d theta: 2 d c2 sqrt(far) phi / sqrt(e + d s2)
  std::vector<T> p;               // p_hat
  std::vector<char> graded;       // node on a graded panel
};

// cut: an extra (ungraded) panel end in (0, pi/2), if any; graded_only: keep
// only the graded panels (the high-order inner rule of hgrad_nodes); layers:
// geometric layers at graded kinks (make_panels); grade_all: every kink graded
// (the expansions of general_expansion.hpp: at a plain kink, e.g. a knot of a
// piecewise cubic, the Cauchy integrals have a (x - k)^2 ln|x - k| term, which
// the interpolant resolves only algebraically unless the panels are graded).
template <class T> zone_nodes<T> make_zone_nodes(const pressure_model<T> &pm, int side, const T &d, const T &e, int n,
                                                 const T *cut = nullptr, bool graded_only = false,
                                                 int layers = kink_layers<T>(), bool grade_all = false) {
  using std::asin;
  using std::sin;
  using std::sqrt;
  zone_nodes<T> z;
  z.n = n;
  z.d = d;
  if (!(d > 0)) return z;
  std::vector<std::pair<T, bool>> kinks = zone_kinks(pm, side, d);
  if (grade_all)
    for (auto &k : kinks) k.second = true;
  if (cut && *cut > 0 && *cut < pi<T>() / 2) kinks.push_back({*cut, false});
  z.panels = make_panels<T>(d, grading_scale(pm, side, d, e), kinks, layers);
  if (graded_only) {
    std::vector<panel<T>> g;
    for (const auto &pn : z.panels)
      if (pn.grade != 0) g.push_back(pn);
    z.panels.swap(g);
  }
  const std::size_t N = z.panels.size() * std::size_t(n);
  z.s2.reserve(N);
  z.c2.reserve(N);
  z.w.reserve(N);
  z.jac.reserve(N);
  z.H.reserve(N);
  z.p.reserve(N);
  for_nodes_c<T>(z.panels, n, [&](const T &th, const T &thc, const T &w, const T &jac) {
    const T sn = sin(th), cs = sin(thc);
    const T s2 = sn * sn, c2 = cs * cs;
    const T ds = d * s2;
    const zone_point<T> x = zone_point_at(side, d, s2, c2);
    const T ph = pm.phi(x.t, x.dm, x.dp);
    z.s2.push_back(s2);
    z.c2.push_back(c2);
    z.w.push_back(w);
    z.jac.push_back(jac);
    z.H.push_back(2 * d * c2 * sqrt(x.far(side)) * ph / sqrt(e + ds));
    z.p.push_back(sqrt(x.dm * x.dp) * ph);
  });
  for (const auto &pn : z.panels) z.graded.insert(z.graded.end(), std::size_t(n), char(pn.grade != 0));
  return z;
}

// Drops the leading panels of z that end at or below theta_c, with their nodes
// (the outer rule of the energies and slips, issue 13): at large sigma the
// panels graded towards the stick edge reach down to theta ~ sqrt(e/d), 480 of
// them at e = 1e-291, while those below theta_c = eps theta_top carry a part
// of the zone integral of order (u_c/d) = eps^2 relative (u = d sin^2 theta is the
// distance from the stick edge, and the integrands are bounded there). The
// inner rules keep every panel: the Cauchy integrals need them (each carries
// ~ln 2 of the density's log). Nothing is dropped unless e/d < ~eps^2.
template <class T> void drop_outer_panels_below(zone_nodes<T> &z, const T &theta_c) {
  std::size_t k = 0;
  while (k < z.panels.size() && !(z.panels[k].hi > theta_c)) ++k;
  if (k == 0) return;
  const auto cut = std::ptrdiff_t(k * std::size_t(z.n));
  z.panels.erase(z.panels.begin(), z.panels.begin() + std::ptrdiff_t(k));
  for (auto *v : {&z.s2, &z.c2, &z.w, &z.jac, &z.H, &z.p}) v->erase(v->begin(), v->begin() + cut);
  z.graded.erase(z.graded.begin(), z.graded.begin() + cut);
}

}}}  // namespace hs::core::gdetail
