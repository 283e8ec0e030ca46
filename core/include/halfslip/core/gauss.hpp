// halfslip core: Gauss-Legendre rules in the working precision T, the
// Legendre three-term recurrence they are built from, the cumulative
// (Legendre integration) matrix of a rule, and the one cache that holds both
// per (order, precision) behind a mutex (the only global mutable state of the
// core).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> struct gl_rule {
  std::vector<T> x, w;  // nodes and weights on [-1, 1], x increasing
};
template <class T> std::shared_ptr<const gl_rule<T>> gauss_legendre(int n);

// sin and cos of the nodes of the rule of order n on the interval [0, pi/2],
// theta_k = 0 + (pi/2)(1 + x_k)/2 formed as the composite rules of
// general_panels.hpp form it for the panel [0, pi/2] (so the same values): the
// one panel of a slip zone without kinks or grading, whose nodes do not move
// with the zone (issue 16: the sine and cosine were ~12% of a general solve).
template <class T> struct gl_quarter {
  std::vector<T> sn, cs;
};

// Gauss-Legendre rule of order n with its Legendre table P_j(x_k), j <= n, and
// the cumulative matrix S_ik = int_{x_i}^{1} l_k(x) dx of the Lagrange basis
// (exact for polynomials of degree < n).
template <class T> struct gl_cumulative {
  std::shared_ptr<const gl_rule<T>> rule;
  std::vector<T> P;  // P[k * (n + 1) + j] = P_j(x_k)
  std::vector<T> S;  // S[i * n + k]
  int n = 0;
};

// Bonnet's recurrence: P_j(x) from P_{j-1} = p1 and P_{j-2} = p0 (j >= 2).
template <class T> T legendre_next(int j, const T &x, const T &p1, const T &p0) {
  return (T(2 * j - 1) * x * p1 - T(j - 1) * p0) / T(j);
}

// P_n(x) (returned in pn) and P_{n-1}(x) (in pn1), n >= 1.
template <class T> void legendre_pair(int n, const T &x, T &pn, T &pn1) {
  T p0 = 1, p1 = x;
  for (int j = 2; j <= n; ++j) {
    const T p2 = legendre_next(j, x, p1, p0);
    p0 = p1;
    p1 = p2;
  }
  pn = p1;
  pn1 = p0;
}

namespace gauss_detail {

// The one rule cache: (order, digits of T) -> the rule and, once asked for,
// its cumulative matrix. Entries are immutable and shared; a rule built twice
// by racing threads is kept once (the first inserted).
template <class T> struct rule_cache {
  struct entry {
    std::shared_ptr<const gl_rule<T>> rule;
    std::shared_ptr<const gl_cumulative<T>> cum;
    std::shared_ptr<const gl_cumulative<T>> tab;  // the Legendre table alone (S empty)
    std::shared_ptr<const gl_quarter<T>> quarter;  // sines and cosines on [0, pi/2]
  };
  std::mutex mtx;
  std::map<std::pair<int, int>, entry> map;
  static rule_cache &get() {
    static rule_cache c;
    return c;
  }
};

template <class T> std::shared_ptr<const gl_rule<T>> make_rule_wide(int n, int max_newton);

// Nodes by Newton's method on P_n from Tricomi's asymptotic start, iterated
// until the correction is below a few eps (quadratic convergence: one more
// step then changes nothing). Running out of max_newton throws no_convergence.
// Beyond long double (the reference backend's MPFR tiers), make_rule_wide.
// the k-th node pair (x, -x) of an n-point rule, its weight from P_n'(x) = dp
template <class T, class R> void store_node(R &r, int n, int k, const T &x, const T &dp) {
  const T w = 2 / ((1 - x * x) * dp * dp);
  r.x[n - k] = x;
  r.w[n - k] = w;
  r.x[k - 1] = -x;
  r.w[k - 1] = w;
}

template <class T> std::shared_ptr<const gl_rule<T>> make_rule(int n, int max_newton = 100) {
  using std::abs;
  using std::cos;
  if constexpr (std::numeric_limits<T>::digits10 > std::numeric_limits<long double>::digits10)
    return make_rule_wide<T>(n, max_newton);
  auto r = std::make_shared<gl_rule<T>>();
  r->x.resize(n);
  r->w.resize(n);
  const T pi_ = pi<T>();
  for (int k = 1; k <= (n + 1) / 2; ++k) {
    // Tricomi: x_k ~ (1 - (n-1)/(8n^3)) cos(pi (4k-1)/(4n+2)) (k-th largest root)
    const T nn = T(n);
    T x = (1 - (nn - 1) / (8 * nn * nn * nn)) * cos(pi_ * T(4 * k - 1) / T(4 * n + 2));
    T dp = 1, p1 = 0, p0 = 0;
    int it = 0;
    for (; it < max_newton; ++it) {
      legendre_pair(n, x, p1, p0);
      // p1 = P_n(x), p0 = P_{n-1}(x)
      dp = T(n) * (x * p1 - p0) / (x * x - 1);
      const T dx = p1 / dp;
      x -= dx;
      if (abs(dx) <= 2 * eps<T>()) {
        if (it > 0 && abs(dx) <= eps<T>() / 2) break;
      }
      if (abs(dx) <= eps<T>() / 4) break;
    }
    check_iterations(it, max_newton, "Gauss-Legendre nodes: Newton iteration on P_n did not converge");
    // final derivative at the converged node
    legendre_pair(n, x, p1, p0);
    dp = T(n) * (x * p1 - p0) / (x * x - 1);
    store_node(*r, n, k, x, dp);
  }
  if (n % 2 == 1) r->x[n / 2] = 0;
  return r;
}

// The rule of order n beyond long double (issue 16: at 80 and 120 digits the
// rules were most of a reference solve). Each node starts from the long double
// rule's (cached, shared by every precision; correct to ~1e-19), and Newton on
// P_n runs in T with the recurrence's coefficients (2j - 1)/j, (j - 1)/j formed
// once per rule and in-place arithmetic (no division, no temporary per step):
// 2 or 3 steps, each doubling the digits. Newton's error after a step dx is
// about |P''/(2 P')| dx^2 = |x|/(1 - x^2) dx^2 (Legendre's equation at a root),
// so the iteration stops once twice that is below eps/16: the node is then
// converged without the confirming step of make_rule (whose next correction
// would be below eps). The weight is 2/((1 - x^2) P_n'(x)^2) at the final node,
// as in make_rule. Running out of max_newton throws no_convergence.
template <class T> std::shared_ptr<const gl_rule<T>> make_rule_wide(int n, int max_newton) {
  using std::abs;
  using std::swap;
  auto r = std::make_shared<gl_rule<T>>();
  r->x.resize(n);
  r->w.resize(n);
  if (n < 1) return r;
  // long double start: the cached long double rule of the same order
  const auto start = gauss_legendre<long double>(n);
  std::vector<T> a(std::size_t(n) + 1), c(std::size_t(n) + 1);
  for (int j = 2; j <= n; ++j) {
    a[j] = T(2 * j - 1);
    a[j] /= j;
    c[j] = T(j - 1);
    c[j] /= j;
  }
  T p0, p1, p2, t, x, dp, dx, omx2;
  const T tol = eps<T>() / 16;
  // P_n(x) in p1, P_{n-1}(x) in p0
  auto eval = [&](const T &xv) {
    p0 = 1;
    p1 = xv;
    for (int j = 2; j <= n; ++j) {
      p2 = xv;
      p2 *= p1;
      p2 *= a[j];
      t = p0;
      t *= c[j];
      p2 -= t;
      swap(p0, p1);
      swap(p1, p2);
    }
  };
  for (int k = 1; k <= (n + 1) / 2; ++k) {
    x = T(start->x[n - k]);  // k-th largest root
    int it = 0;
    for (; it < max_newton; ++it) {
      eval(x);
      omx2 = 1 - x * x;
      dp = T(n) * (p0 - x * p1) / omx2;
      dx = p1 / dp;
      x -= dx;
      if (!(abs(dx) > eps<T>() / 4)) break;
      // predicted error of the new x: |x|/(1 - x^2) dx^2
      if (!(2 * abs(x) * dx * dx > tol * omx2)) break;
    }
    check_iterations(it, max_newton, "Gauss-Legendre nodes: Newton iteration on P_n did not converge");
    eval(x);
    dp = T(n) * (x * p1 - p0) / (x * x - 1);
    store_node(*r, n, k, x, dp);
  }
  if (n % 2 == 1) r->x[n / 2] = 0;
  return r;
}

// The rule with its Legendre table P_j(x_k) (S left empty): O(n^2).
template <class T> std::shared_ptr<gl_cumulative<T>> make_table(std::shared_ptr<const gl_rule<T>> rule) {
  auto c = std::make_shared<gl_cumulative<T>>();
  const int n = int(rule->x.size());
  c->n = n;
  c->rule = std::move(rule);
  const auto &x = c->rule->x;
  c->P.assign(std::size_t(n) * (n + 1), T(0));
  for (int k = 0; k < n; ++k) {
    T *p = &c->P[std::size_t(k) * (n + 1)];
    p[0] = 1;
    p[1] = x[k];
    for (int j = 2; j <= n; ++j) p[j] = legendre_next(j, x[k], p[j - 1], p[j - 2]);
  }
  return c;
}

template <class T> std::shared_ptr<const gl_cumulative<T>> make_cumulative(std::shared_ptr<const gl_rule<T>> rule) {
  const std::shared_ptr<gl_cumulative<T>> c = make_table<T>(std::move(rule));
  const int n = c->n;
  const auto &x = c->rule->x;
  // int_{x_i}^{1} P_0 = 1 - x_i; int_{x_i}^{1} P_j = (P_{j-1}(x_i) - P_{j+1}(x_i))/(2j + 1)
  c->S.assign(std::size_t(n) * n, T(0));
  // O(n^3): at n = 1024, the energies' largest order, 3.1 s before on this machine (loaded),
  // 1.7 s now (issue 13 "bounded time"; a kinked callback pressure needs that order). B rows
  // i at a time: their sums run side by side (independent chains) over each row P_k, and the
  // differences (P_{j-1}(x_i) - P_{j+1}(x_i))/2 are formed once per i. Each sum runs in the
  // same order as before and the halving is exact, so S is bitwise unchanged.
  constexpr int B = 8;
  std::vector<T> D(std::size_t(B) * n);
  for (int i0 = 0; i0 < n; i0 += B) {
    const int nb = std::min(B, n - i0);
    for (int b = 0; b < nb; ++b) {
      const T *pi_ = &c->P[std::size_t(i0 + b) * (n + 1)];
      for (int j = 1; j < n; ++j) D[std::size_t(j) * B + b] = (pi_[j - 1] - pi_[j + 1]) / 2;
    }
    for (int k = 0; k < n; ++k) {
      const T *pk = &c->P[std::size_t(k) * (n + 1)];
      // B independent sums side by side (each in its own order, j ascending)
      T s[B];
      for (int b = 0; b < B; ++b) s[b] = b < nb ? T((1 - x[i0 + b]) / 2) : T(0);
      if (nb == B) {
        for (int j = 1; j < n; ++j) {
          const T p = pk[j];
          for (int b = 0; b < B; ++b) s[b] += p * D[std::size_t(j) * B + b];
        }
      } else {
        for (int j = 1; j < n; ++j)
          for (int b = 0; b < nb; ++b) s[b] += pk[j] * D[std::size_t(j) * B + b];
      }
      for (int b = 0; b < nb; ++b) c->S[std::size_t(i0 + b) * n + k] = c->rule->w[k] * s[b];
    }
  }
  return c;
}

}  // namespace gauss_detail

namespace gauss_detail {
// The cache slot `slot` of order n: looked up, else made (outside the lock)
// and inserted unless another thread was first.
template <class T, class V, class Make>
std::shared_ptr<const V> cached(std::shared_ptr<const V> rule_cache<T>::entry::*slot, int n, const Make &make) {
  auto &c = rule_cache<T>::get();
  const std::pair<int, int> key{n, std::numeric_limits<T>::digits};
  {
    std::lock_guard<std::mutex> lock(c.mtx);
    auto it = c.map.find(key);
    if (it != c.map.end() && it->second.*slot) return it->second.*slot;
  }
  std::shared_ptr<const V> v = make();
  std::lock_guard<std::mutex> lock(c.mtx);
  auto &e = c.map[key];
  if (!(e.*slot)) e.*slot = v;
  return e.*slot;
}
}  // namespace gauss_detail

// Gauss-Legendre rule of order n, cached per (order, precision); the
// returned rule is immutable and shared.
template <class T> std::shared_ptr<const gl_rule<T>> gauss_legendre(int n) {
  return gauss_detail::cached<T, gl_rule<T>>(&gauss_detail::rule_cache<T>::entry::rule, n,
                                             [n] { return gauss_detail::make_rule<T>(n); });
}

// The sines and cosines of gl_quarter (same cache).
template <class T> std::shared_ptr<const gl_quarter<T>> gauss_legendre_quarter(int n) {
  return gauss_detail::cached<T, gl_quarter<T>>(&gauss_detail::rule_cache<T>::entry::quarter, n, [n] {
    using std::cos;
    using std::sin;
    const auto rule = gauss_legendre<T>(n);
    auto q = std::make_shared<gl_quarter<T>>();
    const T lo = 0, hi = pi<T>() / 2;
    const T L = hi - lo;
    q->sn.reserve(std::size_t(n));
    q->cs.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i) {
      const T th = lo + L * (1 + rule->x[i]) / 2;
      q->sn.push_back(sin(th));
      q->cs.push_back(cos(th));
    }
    return std::shared_ptr<const gl_quarter<T>>(q);
  });
}

// The rule of order n with its cumulative matrix (same cache).
template <class T> std::shared_ptr<const gl_cumulative<T>> gauss_legendre_cumulative(int n) {
  return gauss_detail::cached<T, gl_cumulative<T>>(&gauss_detail::rule_cache<T>::entry::cum, n, [n] {
    return gauss_detail::make_cumulative<T>(gauss_legendre<T>(n));
  });
}

// The rule of order n with its Legendre table P_j(x_k) only (same cache; for
// the two-stage cumulative integral of cumulate_tail, O(n^2) where the matrix
// S costs O(n^3)).
template <class T> std::shared_ptr<const gl_cumulative<T>> gauss_legendre_table(int n) {
  return gauss_detail::cached<T, gl_cumulative<T>>(&gauss_detail::rule_cache<T>::entry::tab, n, [n] {
    return std::shared_ptr<const gl_cumulative<T>>(gauss_detail::make_table<T>(gauss_legendre<T>(n)));
  });
}

// tail_i = int_{x_i}^{1} of the degree < n interpolant of f/w (i.e. sum_k S_ik f_k / w_k for
// the cumulative matrix S of the rule), given g_k = w_k times the interpolated values at
// the nodes: the Legendre coefficients c_j = sum_k P_j(x_k) g_k (times (2j + 1)/2, which
// cancels against int_{x_i}^1 P_j = (P_{j-1}(x_i) - P_{j+1}(x_i))/(2j + 1)), then
// tail_i = c_0 (1 - x_i)/2 + sum_{j>=1} c_j (P_{j-1}(x_i) - P_{j+1}(x_i))/2: 2 n^2
// operations, the same sums as S regrouped (issue 16).
template <class T> void cumulate_tail(const gl_cumulative<T> &tab, const T *g, T *tail, std::vector<T> &coef) {
  const int n = tab.n;
  const std::size_t ld = std::size_t(n) + 1;
  coef.assign(std::size_t(n), T(0));
  for (int k = 0; k < n; ++k) {
    const T *pk = &tab.P[std::size_t(k) * ld];
    for (int j = 0; j < n; ++j) coef[j] += pk[j] * g[k];
  }
  const auto &x = tab.rule->x;
  T dj;
  for (int i = 0; i < n; ++i) {
    const T *pi_ = &tab.P[std::size_t(i) * ld];
    T s = coef[0] * (1 - x[i]);
    for (int j = 1; j < n; ++j) {
      dj = pi_[j - 1];
      dj -= pi_[j + 1];
      dj *= coef[j];
      s += dj;
    }
    tail[i] = s / 2;
  }
}

}}  // namespace hs::core
