// halfslip core: the Cauchy integrals of a contact state's pressure and shear
// traction from values cached once per state (issue 15, docs/fields.md).
//
// F0[g](zeta) = int g(s)/(s - zeta) ds and F1[g](zeta) = int g(s)/(s - zeta)^2 ds
// over |s| < a. The contact is cut at the breakpoints (edges, stick
// boundaries, kinks of p); every piece is halved, and on each half
// s = end + h t^2 (t in [0, 1]) removes the square roots at its end. Each half
// is covered by base panels in t graded geometrically towards t = 0,
// [0, 2^-L], [2^-L, 2^(1-L)], ..., [1/2, 1], with L set by the nearest
// singularity beyond the end (a neighbouring breakpoint at distance delta lies
// at t = i sqrt(delta/|h|)) or by a log-singular kink (L >= 6). p and q are
// evaluated once, at the 20 Gauss-Legendre nodes of every base panel.
//
// At a point zeta the kernel has poles at t = +-tau, tau = sqrt((zeta - end)/h).
// A panel whose poles lie at least its length away is summed with its cached
// nodes (Bernstein ellipse parameter > 4: error < 1e-20 relative). A nearer
// panel is bisected towards the poles and the subpanels' nodes take p and q from
// the base panel's degree-19 interpolant (barycentric form). On the real axis
// (the surface) the principal value uses instead the subtraction
//   int g/(t - c) dt = sum_k W_k (g_k - g(c))/(t_k - c) + g(c) log((tb - c)/(ta - c)),
// exact for the interpolant, with the divided differences in a form stable
// when c is near a node.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "numerics.hpp"

namespace hs { namespace core {

template <class T> struct cauchy_pair { std::complex<T> F0{0, 0}, F1{0, 0}; };

// Panel ends in t in [0, 1] graded geometrically towards t0, the real part of a
// pole at distance delta from the real axis (delta < 1/2 only): t0 and t0 -+ d
// for d = max(delta, 64 eps), 2d, 4d, ... < 1. Shared by the quadrature from
// scratch (fields.hpp) and its high-precision form (field_hp.hpp).
template <class T> void grade_towards(std::vector<T> &cuts, const T &t0, const T &delta) {
  if (!(delta < T(0.5))) return;
  const T dmin = std::max(delta, T(64) * eps<T>());
  cuts.push_back(t0);
  for (T d = dmin; d < 1; d *= 2) {
    if (t0 - d > 0) cuts.push_back(t0 - d);
    if (t0 + d < 1) cuts.push_back(t0 + d);
  }
}

template <class T> class traction_panels {
 public:
  static constexpr int n = 20;
  struct panel {
    T end, h;                    // s = end + h t^2 on this half-piece
    T m;                         // the piece's midpoint (t = 1), the same number for both halves
    T ba, bb;                    // t-range of the base panel (children keep it)
    T ta, tb;                    // t-range of the panel
    int half;                    // index of the half-piece
    std::array<T, n> s, wp, wq;  // nodes, weight * p, weight * q (weights of ds)
    std::array<T, n> p, q;       // values at the nodes (for interpolation)
  };
  struct half_piece {
    T end, h, lo, hi;          // s-range [lo, hi]
    T m;                       // the piece's midpoint
    std::size_t first, count;  // its panels
  };

  // dens(s, p, q) gives the densities; pts: sorted breakpoints, pts[0] = -a,
  // pts.back() = a; kinks: the breakpoints where p is log-singular (graded more).
  template <class D> traction_panels(const D &dens, const std::vector<T> &pts, const std::vector<T> &kinks) {
    using gl = boost::math::quadrature::gauss<T, n>;
    using std::abs;
    using std::sqrt;
    // full node set on [-1, 1], ascending, and barycentric weights (-1)^k sqrt((1 - x^2) w)
    const auto &xs = gl::abscissa();
    const auto &ws = gl::weights();
    for (int k = 0; k < n / 2; ++k) {
      xr_[n / 2 - 1 - k] = -xs[k];
      wr_[n / 2 - 1 - k] = ws[k];
      xr_[n / 2 + k] = xs[k];
      wr_[n / 2 + k] = ws[k];
    }
    for (int k = 0; k < n; ++k) lam_[k] = (k % 2 ? -1 : 1) * sqrt((1 - xr_[k] * xr_[k]) * wr_[k]);
    // values at the nodes of the left/right half of a panel from its own nodes:
    // child = M parent, M[i][k] = l_k((x_i -+ 1)/2) (Lagrange basis, barycentric)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i) {
        const T u = (xr_[i] + (side == 0 ? T(-1) : T(1))) / 2;
        T den = 0;
        for (int k = 0; k < n; ++k) den += lam_[k] / (u - xr_[k]);
        for (int k = 0; k < n; ++k) half_[side][i * n + k] = lam_[k] / (u - xr_[k]) / den;
      }
    a_ = pts.back();
    auto is_kink = [&](const T &e) { return std::find(kinks.begin(), kinks.end(), e) != kinks.end(); };
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const T lo = pts[i], hi = pts[i + 1];
      if (!(hi > lo)) continue;
      const T m = (lo + hi) / 2;
      for (int side = 0; side < 2; ++side) {
        const T end = side == 0 ? lo : hi;
        const T h = side == 0 ? m - lo : m - hi;
        // the nearest singularity beyond the end: the neighbouring breakpoint
        int L = 1;
        T delta = -1;
        if (side == 0 && i > 0) delta = lo - pts[i - 1];
        if (side == 1 && i + 2 < pts.size()) delta = pts[i + 2] - hi;
        if (delta > 0) {
          const T r = sqrt(delta / abs(h));  // the singularity's distance in t
          while (L < 60 && std::ldexp(T(1), -L) > r / 2) ++L;
        }
        if (is_kink(end)) L = std::max(L, 12);
        half_piece hp{end, h, side == 0 ? lo : m, side == 0 ? m : hi, m, panels_.size(), 0};
        T t1 = 1;
        for (int l = 0; l <= L; ++l) {
          const T t0 = l == L ? T(0) : std::ldexp(T(1), -(l + 1));
          panels_.push_back(make_panel(dens, end, h, m, t0, t1, int(halves_.size())));
          t1 = t0;
        }
        hp.count = panels_.size() - hp.first;
        halves_.push_back(hp);
      }
    }
    for (const panel &pn : panels_)
      for (int k = 0; k < n; ++k) {
        S_.push_back(pn.s[k]);
        WP_.push_back(pn.wp[k]);
        WQ_.push_back(pn.wq[k]);
      }
  }

  T a() const { return a_; }
  std::size_t size() const { return panels_.size() * n; }

  // F0 and F1 of p and q at zeta (Im zeta >= 0; on the real axis only off the contact).
  void cauchy(const std::complex<T> &zeta, cauchy_pair<T> &P, cauchy_pair<T> &Q) const {
    P = {};
    Q = {};
    for (const half_piece &hp : halves_) {
      const std::complex<T> tau = std::sqrt((zeta - hp.end) / hp.h);
      if (far(tau, T(0), T(0.5)) && far(tau, T(0.5), T(1))) {  // far from every panel (lengths <= 1/2)
        const std::size_t o = hp.first * n;
        sum_nodes(&S_[o], &WP_[o], &WQ_[o], hp.count * n, zeta, P, Q);
        continue;
      }
      for (std::size_t i = hp.first; i < hp.first + hp.count; ++i) {
        const panel &pn = panels_[i];
        if (far(tau, pn.ta, pn.tb)) sum_nodes(&S_[i * n], &WP_[i * n], &WQ_[i * n], n, zeta, P, Q);
        else refine(pn, tau, zeta, 0, P, Q);
      }
    }
  }

  // Re F0[q](x + i0) for real x (the principal value on the contact), x not a breakpoint.
  T re_f0_q(const T &x) const {
    using std::abs;
    using std::sqrt;
    T sum = 0;
    for (const half_piece &hp : halves_) {
      const T tau2 = (x - hp.end) / hp.h;
      const bool real_pole = tau2 >= 0;
      const std::complex<T> tau = real_pole ? std::complex<T>(sqrt(tau2), 0) : std::complex<T>(0, sqrt(-tau2));
      // 1 - tau to full relative accuracy (1 - tau^2 = (m - x)/h): the two
      // halves of a piece then see a pole near their common end t = 1 alike
      const T om = real_pole ? (hp.m - x) / hp.h / (1 + tau.real()) : T(0);
      const T sg = hp.h > 0 ? T(1) : T(-1);
      const T r = real_pole ? T(0.25) : T(0.5);
      if (far(tau, T(0), T(0.5), r) && far(tau, T(0.5), T(1), r)) {
        sum += real_sum(&S_[hp.first * n], &WQ_[hp.first * n], hp.count * n, x);
        continue;
      }
      for (std::size_t i = hp.first; i < hp.first + hp.count; ++i) {
        const panel &pn = panels_[i];
        if (far(tau, pn.ta, pn.tb, r)) {
          sum += real_sum(&S_[i * n], &WQ_[i * n], n, x);
          continue;
        }
        sum += pv_refine(pn, tau, om, sg, x, 0);
      }
    }
    return sum;
  }

  // Re F0[q](x) at a breakpoint x (a half-piece end, or +-a): the principal
  // value by subtraction of qx = q(x),
  //   int (q(s) - qx)/(s - x) ds + qx log((a - x)/(a + x)).
  // On the half-pieces that end at x, s - x = h t^2 exactly and
  // (q - qx)/(s - x) ds = 2 (q - qx)/t dt is smooth in t (q - qx ~ t there);
  // every other half-piece is at least half its piece's length from x, or
  // graded towards its end so that x lies beyond its smallest panels: the
  // cached nodes do. qx is not used at |x| = a (p and q vanish there).
  T re_f0_q_break(const T &x, const T &qx) const {
    using std::abs;
    using std::log;
    const bool edge = abs(x) >= a_;
    const T qs = edge ? T(0) : qx;
    T sum = 0;
    for (const half_piece &hp : halves_) {
      const bool adjacent = hp.end == x;
      for (std::size_t i = hp.first; i < hp.first + hp.count; ++i) {
        const panel &pn = panels_[i];
        const T mid = (pn.ta + pn.tb) / 2, hl = (pn.tb - pn.ta) / 2;
        for (int k = 0; k < n; ++k) {
          const T t = mid + hl * xr_[k];
          const T w = wr_[k] * hl * 2 * abs(pn.h) * t;
          const T d = adjacent ? pn.h * t * t : pn.s[k] - x;
          sum += w * (pn.q[k] - qs) / d;
        }
      }
    }
    if (qs != 0) sum += qs * log((a_ - x) / (a_ + x));
    return sum;
  }

 private:
  template <class D>
  panel make_panel(const D &dens, const T &end, const T &h, const T &m, const T &t0, const T &t1, int half) {
    using std::abs;
    panel pn;
    pn.end = end;
    pn.h = h;
    pn.m = m;
    pn.ta = t0;
    pn.tb = t1;
    pn.ba = t0;
    pn.bb = t1;
    pn.half = half;
    const T mid = (t0 + t1) / 2, hl = (t1 - t0) / 2;
    for (int k = 0; k < n; ++k) {
      const T t = mid + hl * xr_[k];
      pn.s[k] = end + h * t * t;
      const T w = wr_[k] * hl * 2 * abs(h) * t;
      dens(pn.s[k], pn.p[k], pn.q[k]);
      pn.wp[k] = w * pn.p[k];
      pn.wq[k] = w * pn.q[k];
    }
    return pn;
  }

  // both poles +-tau at least r panel lengths from [ta, tb]. The Bernstein
  // ellipse parameter of the panel through a pole is then >= 2.41 for r = 1/2
  // (the worst case is above the middle): the 20-point rule's error is below
  // n 2.41^-40 = 1e-14 relative for the double pole of F1. Real poles (the
  // principal value on the surface) use r = 1/4: parameter >= 2.6, 2.6^-40 = 2e-17.
  static bool far(const std::complex<T> &tau, const T &ta, const T &tb, const T &r = T(0.5)) {
    const T len = r * (tb - ta);
    auto dist2 = [&](const T &re, const T &im) {
      const T dx = re < ta ? ta - re : (re > tb ? re - tb : T(0));
      return dx * dx + im * im;
    };
    return dist2(tau.real(), tau.imag()) >= len * len && dist2(-tau.real(), tau.imag()) >= len * len;
  }

  // sum_k w_k/(s_k - x) with independent partial sums (m a multiple of 4)
  static T real_sum(const T *s, const T *w, std::size_t m, const T &x) {
    T a0 = 0, a1 = 0, a2 = 0, a3 = 0;
    for (std::size_t k = 0; k < m; k += 4) {
      a0 += w[k] / (s[k] - x);
      a1 += w[k + 1] / (s[k + 1] - x);
      a2 += w[k + 2] / (s[k + 2] - x);
      a3 += w[k + 3] / (s[k + 3] - x);
    }
    return (a0 + a1) + (a2 + a3);
  }

  static void sum_nodes(const T *s, const T *wp, const T *wq, std::size_t m, const std::complex<T> &zeta,
                        cauchy_pair<T> &P, cauchy_pair<T> &Q) {
    T p0r = 0, p0i = 0, p1r = 0, p1i = 0, q0r = 0, q0i = 0, q1r = 0, q1i = 0;
    const T zr = zeta.real(), zi = zeta.imag();
    for (std::size_t k = 0; k < m; ++k) {
      // r = 1/(s - zeta) = (dr + i zi)/(dr^2 + zi^2)
      const T dr = s[k] - zr;
      const T den = 1 / (dr * dr + zi * zi);
      const T rr = dr * den, ri = zi * den;
      const T r2r = rr * rr - ri * ri, r2i = 2 * rr * ri;
      p0r += wp[k] * rr;
      p0i += wp[k] * ri;
      p1r += wp[k] * r2r;
      p1i += wp[k] * r2i;
      q0r += wq[k] * rr;
      q0i += wq[k] * ri;
      q1r += wq[k] * r2r;
      q1i += wq[k] * r2i;
    }
    P.F0 += std::complex<T>(p0r, p0i);
    P.F1 += std::complex<T>(p1r, p1i);
    Q.F0 += std::complex<T>(q0r, q0i);
    Q.F1 += std::complex<T>(q1r, q1i);
  }

  // half `side` (0 left, 1 right) of a panel, with values from its interpolant
  panel child(const panel &pn, int side, bool with_p = true) const {
    using std::abs;
    panel c;
    c.end = pn.end;
    c.h = pn.h;
    c.m = pn.m;
    c.ba = pn.ba;
    c.bb = pn.bb;
    c.half = pn.half;
    const T um = (pn.ta + pn.tb) / 2;
    c.ta = side == 0 ? pn.ta : um;
    c.tb = side == 0 ? um : pn.tb;
    const T mid = (c.ta + c.tb) / 2, hl = (c.tb - c.ta) / 2;
    const T *M = half_[side].data();
    for (int i = 0; i < n; ++i) {
      T pv = 0, qv = 0;
      if (with_p)
        for (int k = 0; k < n; ++k) {
          pv += M[i * n + k] * pn.p[k];
          qv += M[i * n + k] * pn.q[k];
        }
      else
        for (int k = 0; k < n; ++k) qv += M[i * n + k] * pn.q[k];
      const T t = mid + hl * xr_[i];
      c.s[i] = pn.end + pn.h * t * t;
      const T w = wr_[i] * hl * 2 * abs(pn.h) * t;
      c.p[i] = pv;
      c.q[i] = qv;
      c.wp[i] = w * pv;
      c.wq[i] = w * qv;
    }
    return c;
  }

  // a panel near the poles: bisected until they are far
  void refine(const panel &pn, const std::complex<T> &tau, const std::complex<T> &zeta, int depth, cauchy_pair<T> &P,
              cauchy_pair<T> &Q) const {
    if (depth < 60 && !far(tau, pn.ta, pn.tb)) {
      refine(child(pn, 0), tau, zeta, depth + 1, P, Q);
      refine(child(pn, 1), tau, zeta, depth + 1, P, Q);
      return;
    }
    // s - zeta = (s(tA) - zeta) + h (t - tA)(t + tA) from the nearer end tA of
    // the base panel (s(1) is the piece's midpoint m, s(0) the breakpoint),
    // with t - tA = (mid - tA) + hl x_k exact: the distance to a pole near that
    // end keeps its relative accuracy at any depth, and the two panels that
    // meet there see the pole at the same place (otherwise their logarithmic
    // end terms, which cancel, would differ by eps/distance)
    const T mid = (pn.ta + pn.tb) / 2, hl = (pn.tb - pn.ta) / 2;
    const T tA = mid - pn.ba < pn.bb - mid ? pn.ba : pn.bb;
    const std::complex<T> A = (tA == 1 ? pn.m : pn.end + pn.h * tA * tA) - zeta;
    const T dm = mid - tA, dp = mid + tA;
    T p0r = 0, p0i = 0, p1r = 0, p1i = 0, q0r = 0, q0i = 0, q1r = 0, q1i = 0;
    for (int k = 0; k < n; ++k) {
      const std::complex<T> d = A + pn.h * ((dm + hl * xr_[k]) * (dp + hl * xr_[k]));
      const T den = 1 / (d.real() * d.real() + d.imag() * d.imag());
      const T rr = d.real() * den, ri = -d.imag() * den;  // 1/d
      const T r2r = rr * rr - ri * ri, r2i = 2 * rr * ri;
      p0r += pn.wp[k] * rr;
      p0i += pn.wp[k] * ri;
      p1r += pn.wp[k] * r2r;
      p1i += pn.wp[k] * r2i;
      q0r += pn.wq[k] * rr;
      q0i += pn.wq[k] * ri;
      q1r += pn.wq[k] * r2r;
      q1i += pn.wq[k] * r2i;
    }
    P.F0 += std::complex<T>(p0r, p0i);
    P.F1 += std::complex<T>(p1r, p1i);
    Q.F0 += std::complex<T>(q0r, q0i);
    Q.F1 += std::complex<T>(q1r, q1i);
  }

  // The contribution of the (sub)panel sub of base panel pn to Re F0[q](x),
  // x real. A real pole tau inside sub with -tau far: subtraction; poles far:
  // the nodes; otherwise bisection (values from pn's interpolant).
  T pv_refine(const panel &sub, const std::complex<T> &tau, const T &om, const T &sg, const T &x, int depth) const {
    using std::abs;
    const T len = sub.tb - sub.ta;
    // a real pole inside sub or just outside it (within len/1000: the
    // interpolant's extrapolation there is as good as inside) is subtracted,
    // so that the panels on both sides of a pole near their common end treat
    // its logarithm alike
    const T tol = len / 1000;
    const bool inside = tau.imag() == 0 && tau.real() > 0 && tau.real() >= sub.ta - tol && tau.real() <= sub.tb + tol;
    const bool minus_far = tau.real() + sub.ta >= len / 4;  // -tau lies left of sub, a quarter length away
    if (inside && minus_far) {
      // int q [1/(t - tau) + 1/(t + tau)] dt, times sgn(h)
      const T hl = len / 2, mid = (sub.ta + sub.tb) / 2;
      T direct = 0;
      for (int k = 0; k < n; ++k) direct += wr_[k] * hl * sub.q[k] / (mid + hl * xr_[k] + tau.real());
      return sg * (subtract(sub, tau.real(), om) + direct);
    }
    if (depth >= 60 || (!inside && far(tau, sub.ta, sub.tb, tau.imag() == 0 ? T(0.25) : T(0.5)))) {
      // sum w q/(s - x) with s - x from the nearer end of the base panel (see refine)
      const T mid = (sub.ta + sub.tb) / 2, hl = len / 2;
      const T tA = mid - sub.ba < sub.bb - mid ? sub.ba : sub.bb;
      const T A = (tA == 1 ? sub.m : sub.end + sub.h * tA * tA) - x;
      const T dm = mid - tA, dp = mid + tA;
      T acc = 0;
      for (int k = 0; k < n; ++k) acc += sub.wq[k] / (A + sub.h * ((dm + hl * xr_[k]) * (dp + hl * xr_[k])));
      return acc;
    }
    return pv_refine(child(sub, 0, false), tau, om, sg, x, depth + 1) +
           pv_refine(child(sub, 1, false), tau, om, sg, x, depth + 1);
  }

  // PV int_{ta}^{tb} q(t)/(t - c) dt for the panel's interpolant q, c real in
  // [ta, tb], by subtraction of q(c).
  T subtract(const panel &pn, const T &c, const T &om) const {
    using std::abs;
    using std::log;
    const T mid = (pn.ta + pn.tb) / 2, hl = (pn.tb - pn.ta) / 2;
    const T u = (c - mid) / hl;  // in the reference interval
    // g(u) by the barycentric formula; node hit: exact value
    std::array<T, n> r;
    int hit = -1;
    for (int k = 0; k < n; ++k) {
      const T d = u - xr_[k];
      if (d == 0) {
        hit = k;
        r[k] = 0;
      } else r[k] = lam_[k] / d;
    }
    T gc;
    if (hit >= 0) gc = pn.q[hit];
    else {
      T num = 0, den = 0;
      for (int k = 0; k < n; ++k) {
        num += r[k] * pn.q[k];
        den += r[k];
      }
      gc = num / den;
    }
    // sum_j W_j (g_j - g(c))/(t_j - c) = sum_j wr_j (g(u) - g_j)/(u - x_j) (the factors hl cancel),
    // the divided differences in the form sum_{k != j} r_k (g_k - g_j) / (lam_j + sum_{k != j} r_k (u - x_j))
    T acc = 0;
    for (int j = 0; j < n; ++j) {
      const T uj = u - xr_[j];
      if (hit >= 0 && hit != j) {  // r_hit is infinite: the ratio tends to (g_hit - g_j)/(u - x_j)
        acc += wr_[j] * (gc - pn.q[j]) / uj;
        continue;
      }
      T num = 0, den = lam_[j];
      for (int k = 0; k < n; ++k) {
        if (k == j || k == hit) continue;
        num += r[k] * (pn.q[k] - pn.q[j]);
        den += r[k] * uj;
      }
      acc += wr_[j] * num / den;
    }
    // principal value of the log. c at a panel end: the log of the distance is
    // replaced by that of the distance in s, |s - x| ~ |2 h c| |t - c|, for a
    // unit |s - x|; the panels on the two sides of x then cancel what is dropped.
    // (tb - c)/hl: at tb = 1 from om = 1 - c, accurate
    auto lg_dist = [&](const T &d) { return d != 0 ? T(log(abs(d))) : T(-log(abs(2 * pn.h * c * hl))); };
    const T A = pn.tb == 1 ? om / hl : (pn.tb - c) / hl;
    return acc + gc * (lg_dist(A) - lg_dist((pn.ta - c) / hl));
  }

  std::vector<panel> panels_;
  std::vector<half_piece> halves_;
  std::vector<T> S_, WP_, WQ_;  // the nodes of all panels in order (contiguous per half-piece)
  std::array<T, n> xr_, wr_, lam_;
  std::array<std::array<T, n * n>, 2> half_;  // bisection matrices
  T a_{1};
};

}}  // namespace hs::core
