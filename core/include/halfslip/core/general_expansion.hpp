// halfslip core, general pressures (general.hpp): B_x on each slip zone as a
// short Legendre expansion per quadrature panel, with the end behaviour
// factored out, so that B_x and the slip at a point and the zone energies are
// sums (issue 16).
//
// On zone z (canonical frame, u = d sin^2 theta the distance from the stick
// edge) B_x = +-R(u) K(theta), R(u) = sqrt(u (e + u)) the square-root end
// behaviour at the stick edge (and the whole of it: at the contact edge the
// Cauchy integrals of the sqrt-vanishing density have no sqrt term), and
// K = -(2/pi) (dirR C_R - dirL C_L) smooth in theta on each panel of the
// solver's panel set of the zone (graded geometrically towards theta = 0 from
// the near singularity at theta ~ i sqrt(e/d); pressure kinks are panel ends,
// on either side of which the Cauchy integrals are analytic: a (x - k) ln|x - k|
// term of the pressure gives the Cauchy integral only a one-sided
// pi (x - k) term; graded panels are mapped polynomially as for the zone
// integrals). Per panel, in the panel's rule variable r in [-1, 1]:
//   K(r)        = sum_{k < M} c_k P_k(r)  from K at the M Gauss-Legendre nodes
//                 (the fixed-rule h' of general_solution::hgrad_nodes, inner
//                 rule M + 1 interlacing);
//   h(r) - h_lo = sum_{k <= M} a_k P_k(r)  the antiderivative of dh/dr =
//                 R K du/dtheta dtheta/dr (Legendre integration, exact for the
//                 interpolant);
// and the zone energy int p h du by the same nodes (as energy_hat_order).
// Accuracy control: M starts at twice the solver's order (interpolation needs
// about twice the order of integration for the same error) and doubles until
// the last two coefficients of K on every panel are below tol max|K| (tol:
// 32 eps, or rtol/64 where larger); where that needs more than max_order the
// expansion is not made and the fixed-rule and adaptive paths answer.
// Evaluation: K at a point by the Legendre recurrence (O(M)); h by the
// antiderivative's series, except in the lower half of the panel at the stick
// edge (h ~ u^(3/2) there: the series' absolute error eps sum|a_k| would be
// large relative to h), where h = int_0^theta by Gauss-Legendre of order M/2
// on [0, theta] of the interpolant (O(M^2)).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "gauss.hpp"
#include "general_panels.hpp"
#include "numerics.hpp"

namespace hs { namespace core { namespace gdetail {

template <class T> struct zone_expansion {
  int M = 0;  // coefficients of K per panel (Gauss-Legendre order of the nodes)
  T d{0}, e{0};
  std::vector<panel<T>> panels;
  std::vector<T> kc;  // K: M Legendre coefficients per panel
  std::vector<T> ac;  // h - h_lo: M + 1 Legendre coefficients per panel
  std::vector<T> h0;  // h at each panel's lower end (panels.size() + 1 entries)
  // per panel, the coefficients of K and of h - h_lo that count: the trailing
  // ones whose magnitudes add up to at most 2^-60 max|K| on the panel (of h: 2^-60 h at
  // the panel's lower end, or at its middle on the first panel) are left out
  std::vector<int> kn, an;
  T energy{0};        // int_0^d p_hat h du (signed)
  T tail{0};  // largest last-two-coefficients of K over max(max|K|, floor/tol): <= tol passes (accuracy control)
  T tol{0};                     // the tolerance of the accuracy control
  int next_order = 0;           // where the control failed: the order to try next
  std::vector<T> noise, kscale;  // per panel: the largest rounding bound of K at its nodes
                                 // (expansion_k_nodes), and max |K| at them

  // The error estimate of K at theta: the node values' rounding carried by
  // the interpolant (8 times the panel's largest bound, for the interpolant's
  // Lebesgue constant) plus the truncation (the last two coefficients below
  // tol max|K| on the panel, the series converging geometrically: 4 tol max|K|). Next to the stick edge the first
  // term dominates: the principal-value quotients over the nodes nearest
  // theta = 0 lose eps |H| / theta_1 (theta_1 ~ L/M^2: ~1e-12 relative at
  // M = 32; the adaptive path bhat_direct loses as much there).
  T K_error(const T &th) const {
    const std::size_t P = find(th);
    return 8 * noise[P] + 4 * tol * kscale[P];
  }

  std::vector<T> ra, rb;  // the recurrence's (2j - 1)/j and (j - 1)/j, j <= M

  // sum_{k < n} c_k P_k(r) by the forward Legendre recurrence (stable on [-1, 1])
  T legendre_sum(const T *c, int n, const T &r) const {
    T p0 = 1, p1 = r;
    T s = c[0];
    if (n > 1) s += c[1] * r;
    for (int j = 2; j < n; ++j) {
      const T p2 = ra[j] * r * p1 - rb[j] * p0;
      s += c[j] * p2;
      p0 = p1;
      p1 = p2;
    }
    return s;
  }
  // the panel containing theta (the last one whose lo <= theta)
  std::size_t find(const T &th) const {
    std::size_t lo = 0, hi = panels.size();
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (panels[mid].lo <= th) lo = mid;
      else hi = mid;
    }
    return lo;
  }
  // the rule variable r of theta on panel pn (inverse of for_nodes_c's map)
  static T rule_var(const panel<T> &pn, const T &th) {
    using std::pow;
    const T L = pn.hi - pn.lo;
    if (pn.grade == 0) return std::min(T(1), std::max(T(-1), T(2 * (th - pn.lo) / L - 1)));
    const T m = T(grading_power<T>());
    if (pn.grade < 0) {
      const T v = std::max(T(0), T((th - pn.lo) / L));
      return std::min(T(1), T(2 * pow(v, 1 / m) - 1));
    }
    const T v = std::max(T(0), T((pn.hi - th) / L));
    return std::max(T(-1), T(1 - 2 * pow(v, 1 / m)));
  }
  T K(const T &th) const {
    const std::size_t P = find(th);
    return legendre_sum(&kc[P * std::size_t(M)], kn[P], rule_var(panels[P], th));
  }
  // h at theta (u = d sin^2 theta, uc = d - u the distance to the contact edge)
  T h(const T &th) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const std::size_t P = find(th);
    const panel<T> &pn = panels[P];
    if (P == 0 && th < pn.lo + (pn.hi - pn.lo) / 2) {
      // int_0^th R K 2 d sin cos dtheta by Gauss-Legendre of order n = M/2 (the
      // integrand is the interpolant's on a half panel or less: M/2 nodes
      // resolve it as M do the panel); the n Legendre series summed together
      // (independent recurrences, k outermost)
      const int nk = kn[0];
      const auto rule = gauss_legendre<T>(std::min(std::max(8, M / 2), std::max(8, (nk + 1) / 2 + 4)));
      const std::size_t n = rule->x.size();
      T buf[5 * 64];
      std::vector<T> big;
      T *r = buf, *p0 = buf + 64, *p1 = buf + 128, *k = buf + 192, *wt = buf + 256;
      if (n > 64) {
        big.resize(5 * n);
        r = big.data();
        p0 = r + n;
        p1 = p0 + n;
        k = p1 + n;
        wt = k + n;
      }
      for (std::size_t i = 0; i < n; ++i) {
        const T t = th * (1 + rule->x[i]) / 2;
        const T sn = sin(t), cs = cos(t);
        const T u = d * sn * sn;
        wt[i] = rule->w[i] * sqrt(u * (e + u)) * 2 * d * sn * cs;
        r[i] = rule_var(pn, t);
        p0[i] = 1;
        p1[i] = r[i];
        k[i] = kc[0] + (nk > 1 ? kc[1] * r[i] : T(0));
      }
      for (int j = 2; j < nk; ++j) {
        const T a = ra[j], b = rb[j], c = kc[j];
        for (std::size_t i = 0; i < n; ++i) {
          const T p2 = a * r[i] * p1[i] - b * p0[i];
          k[i] += c * p2;
          p0[i] = p1[i];
          p1[i] = p2;
        }
      }
      T s = 0;
      for (std::size_t i = 0; i < n; ++i) s += wt[i] * k[i];
      return s * th / 2;
    }
    return h0[P] + legendre_sum(&ac[P * std::size_t(M + 1)], an[P], rule_var(pn, th));
  }
};

template <class T> struct general_expansion {
  zone_expansion<T> zone[2];  // [0]: zone R (+1), [1]: zone L (-1)
  const zone_expansion<T> &at(int z) const { return zone[z > 0 ? 0 : 1]; }
};

// K = -(2/pi) (dirR C_R - dirL C_L) at the outer nodes O of zone z (order M)
// from the inner nodes IR, IL (order M + 1 on the same panels: on the own zone
// the two interlace), as general_solution::hgrad_nodes without R, with err:
// the rounding bound 4 eps/pi times the sum of the terms' magnitudes. Four
// partial sums (independent divisions in flight: ~3x faster than one).
template <class T>
void expansion_k_nodes(int z, const zone_nodes<T> &O, const zone_nodes<T> &IR, const zone_nodes<T> &IL, int dirR,
                       int dirL, const T &e, std::vector<T> &K, std::vector<T> &err) {
  using std::abs;
  const std::size_t count = O.s2.size();
  K.assign(count, T(0));
  err.assign(count, T(0));
  for (std::size_t j = 0; j < count; ++j) {
    const T sj = O.s2[j], cj = O.c2[j];
    const T u = O.d * sj;
    T br = 0, ab = 0;
    for (int Z : {+1, -1}) {
      const int dir = Z > 0 ? dirR : dirL;
      const zone_nodes<T> &I = Z > 0 ? IR : IL;
      if (dir == 0 || !(I.d > 0)) continue;
      const std::size_t n = I.s2.size();
      const T *w = I.w.data(), *H = I.H.data(), *s2 = I.s2.data(), *c2 = I.c2.data();
      T s[4] = {0, 0, 0, 0}, a[4] = {0, 0, 0, 0};
      if (Z == z) {
        // t - xi = Z d (sin^2 theta - sin^2 theta_j), from the nearer end
        const T Hj = O.H[j], aHj = abs(Hj);
        auto term = [&](std::size_t i, int k) {
          const T den = (s2[i] + sj < 1) ? T(s2[i] - sj) : T(cj - c2[i]);
          const T r = den != 0 ? T(1 / den) : T(0);
          s[k] += w[i] * (H[i] - Hj) * r;
          a[k] += abs(w[i] * r) * (abs(H[i]) + aHj);
        };
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4)
          for (int k = 0; k < 4; ++k) term(i + k, k);
        for (; i < n; ++i) term(i, 0);
        const T sum = ((s[0] + s[1]) + (s[2] + s[3])) / I.d;
        br += T(dir) * sum;
        ab += ((a[0] + a[1]) + (a[2] + a[3])) / I.d;
      } else {
        const T base = e + u, dZ = I.d;
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4)
          for (int k = 0; k < 4; ++k) s[k] += w[i + k] * H[i + k] / (base + dZ * s2[i + k]);
        for (; i < n; ++i) s[0] += w[i] * H[i] / (base + dZ * s2[i]);
        const T sum = (s[0] + s[1]) + (s[2] + s[3]);
        br += T(dir) * sum;
        ab += abs(sum);
      }
    }
    K[j] = -2 * br / pi<T>();
    err[j] = 4 * eps<T>() * ab / pi<T>();
  }
}

// The zone's expansion from K at the outer nodes O (order M; K = h'/R) and
// the rule's Legendre table.
template <class T>
void fill_zone_expansion(zone_expansion<T> &x, const zone_nodes<T> &O, const std::vector<T> &K,
                         const std::vector<T> &err, const T &e, const T &tol) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const int M = O.n;
  const auto cum = gauss_legendre_cumulative<T>(M);
  const auto &rule = *cum->rule;
  const std::size_t np = O.panels.size();
  x.M = M;
  x.next_order = 0;
  x.ra.assign(std::size_t(M + 1), T(0));
  x.rb.assign(std::size_t(M + 1), T(0));
  for (int j = 1; j <= M; ++j) {
    x.ra[j] = T(2 * j - 1) / T(j);
    x.rb[j] = T(j - 1) / T(j);
  }
  x.d = O.d;
  x.e = e;
  x.panels = O.panels;
  x.kc.assign(np * std::size_t(M), T(0));
  x.ac.assign(np * std::size_t(M + 1), T(0));
  x.h0.assign(np + 1, T(0));
  x.noise.assign(np, T(0));
  x.kscale.assign(np, T(0));
  x.tol = tol;
  T tail = 0, E = 0;
  std::vector<T> q(M), c(M);
  for (std::size_t P = 0; P < np; ++P) {
    const std::size_t b = P * std::size_t(M);
    T *kc = &x.kc[b];
    T *ac = &x.ac[P * std::size_t(M + 1)];
    // dh/dr at the nodes: R K du/dtheta dtheta/dr
    for (int i = 0; i < M; ++i) {
      const T u = O.d * O.s2[b + i];
      q[i] = sqrt(u * (e + u)) * K[b + i] * 2 * O.d * sqrt(O.s2[b + i] * O.c2[b + i]) * O.jac[b + i];
    }
    // Legendre coefficients (k innermost: independent sums, same order of terms per k)
    std::fill(c.begin(), c.end(), T(0));
    for (int i = 0; i < M; ++i) {
      const T wk = rule.w[i] * K[b + i], wq = rule.w[i] * q[i];
      const T *Pi = &cum->P[std::size_t(i) * (M + 1)];
      for (int k = 0; k < M; ++k) {
        kc[k] += wk * Pi[k];
        c[k] += wq * Pi[k];
      }
    }
    for (int k = 0; k < M; ++k) {
      kc[k] *= T(2 * k + 1) / 2;
      c[k] *= T(2 * k + 1) / 2;
    }
    // the last coefficients are judged against the larger of tol max|K| and
    // the rounding of K at the panel's nodes (err: hgrad_nodes' bound, eps
    // times the sum of the terms' magnitudes; the own zone's principal-value
    // quotients over near nodes dominate it: next to the stick edge ~ eps |K|/theta,
    // and next to a graded kink, where the nodes crowd)
    T floor = 0, kmax = 0;
    for (int i = 0; i < M; ++i) {
      floor = max(floor, err[b + i]);
      kmax = max(kmax, T(abs(K[b + i])));
    }
    x.noise[P] = floor;
    x.kscale[P] = kmax;
    if (kmax > 0) {
      const T scale = max(kmax, T(floor / tol));
      const T t = max(abs(kc[M - 1]), abs(kc[M - 2])) / scale;
      tail = max(tail, t);
      // the order this panel needs if its coefficients fall geometrically at
      // the rate they fell from M/2 to M (a guess for the next try: the
      // control above still decides)
      if (t > tol) {
        using std::ceil;
        using std::log;
        const T mid = max(abs(kc[M / 2]), abs(kc[M / 2 - 1])) / scale;
        int need = 2 * M;
        if (mid > 4 * t && t > 0) {
          const T extra = T(M) / 2 * log(t / tol) / log(mid / t);
          if (extra < T(M)) need = M + int(ceil(T(1.25) * extra));
        }
        x.next_order = std::max(x.next_order, std::min(2 * M, ((need + 7) / 8) * 8));
      }
    }
    // antiderivative from r = -1: c_0 (P_0 + P_1), c_k (P_{k+1} - P_{k-1})/(2k + 1)
    ac[0] += c[0];
    ac[1] += c[0];
    for (int k = 1; k < M; ++k) {
      ac[k + 1] += c[k] / T(2 * k + 1);
      ac[k - 1] -= c[k] / T(2 * k + 1);
    }
    T whole = 0;  // at r = 1 every P_j is 1
    for (int j = 0; j <= M; ++j) whole += ac[j];
    x.h0[P + 1] = x.h0[P] + whole;
    // energy: p_hat h du at the nodes (weights O.w = w jac)
    for (int i = 0; i < M; ++i) {
      const T *Pi = &cum->P[std::size_t(i) * (M + 1)];
      T hs[4] = {0, 0, 0, 0};
      int j = 0;
      for (; j + 4 <= M + 1; j += 4)
        for (int k = 0; k < 4; ++k) hs[k] += ac[j + k] * Pi[j + k];
      for (; j <= M; ++j) hs[0] += ac[j] * Pi[j];
      const T hi = x.h0[P] + ((hs[0] + hs[1]) + (hs[2] + hs[3]));
      E += O.w[b + i] * O.p[b + i] * 2 * O.d * sqrt(O.s2[b + i] * O.c2[b + i]) * hi;
    }
  }
  x.energy = E;
  x.tail = tail;
  // the counting lengths (see kn, an)
  using std::ldexp;
  x.kn.assign(np, M);
  x.an.assign(np, M + 1);
  for (std::size_t P = 0; P < np; ++P) {
    const T lk = ldexp(x.kscale[P], -60);
    T dropped = 0;
    int n = M;
    while (n > 2 && (dropped += abs(x.kc[P * std::size_t(M) + n - 1])) <= lk) --n;
    x.kn[P] = n;
    const T lh = ldexp(P == 0 ? T(abs(x.h0[1]) / 8) : T(abs(x.h0[P])), -60);
    dropped = 0;
    n = M + 1;
    while (n > 2 && (dropped += abs(x.ac[P * std::size_t(M + 1) + n - 1])) <= lh) --n;
    x.an[P] = n;
  }
}

}}}  // namespace hs::core::gdetail
