// halfslip core: product quadrature for a C^1 piecewise cubic with many knots
// (the sampled pressure's phi; issue 13 item 4: linear cost in the sample count).
//
// phi is given on S segments [X_s, X_{s+1}], X_0 = -1 < X_1 < ... < X_S = 1
// (units of a), by its values F_s and slopes D_s at the segment ends (cubic
// Hermite form; the sampled pressure's two linear end segments are cubics
// too). Every integral the solver and the evaluations need is
//   int_A^B phi(t) K(t) dt
// with K smooth except at a few known points (stick and contact edges, an
// evaluation point). Two structures make them cost O(m log S) instead of O(S):
//
// 1. A balanced binary tree over the segments. Every node of at least
//    `stored` segments keeps a product rule: the m Chebyshev points tau_j of
//    the node and weights omega_j = int_node phi l_j (l_j the Lagrange basis
//    at the tau_j), so that sum_j omega_j K(tau_j) integrates phi exactly
//    against the degree-(m - 1) interpolant of K. A node whose distance from
//    every singular point of K is at least eta = 2 times its length
//    ("admissible") has K analytic in the Bernstein ellipse rho = 5 + sqrt(24)
//    = 9.9 around it: interpolation error below ~rho^-m = 1.2e-16 (m = 16)
//    relative to the node's part of the integral. Smaller admissible nodes
//    are integrated segment by segment, Gauss-Legendre of order g = 10 (error
//    ~rho^-17). cover() visits the O(log S) admissible nodes and hands the
//    pieces of the segments next to a singular point to the caller, which
//    integrates them with a map that removes the singularity.
//    Weights: a node whose children are not stored takes Chebyshev moments
//    nu_k = int phi T_k(xi) from its segments by Gauss-Legendre of order g
//    (exact: cubic times degree 15); a node with stored children takes them
//    from the children's rules (exact: those integrate phi times any
//    polynomial of degree m - 1, T_k(xi_parent) included); then
//    omega_j = (2/m) sum'_k T_k(x_j) nu_k (discrete orthogonality of the
//    Chebyshev points of the first kind). Cost O(S g m) once.
// 2. Cumulative integrals of p_hat = sqrt(1 - t^2) phi from both ends, per
//    segment by Gauss-Legendre of order g in theta, t = -+cos(theta) (which
//    removes the square root at the nearer edge), summed with compensation:
//    a tail from an edge costs one partial segment.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "gauss.hpp"
#include "numerics.hpp"

namespace hs { namespace core {

template <class T> class knot_quadrature {
 public:
  static constexpr int m = 16;               // points of a node's product rule
  static constexpr int g = 10;               // Gauss-Legendre order per segment
  static constexpr std::size_t stored = 32;  // a node keeps a rule from this many segments
  static T eta() { return T(2); }            // admissible: distance >= eta * length

  // X: S + 1 segment ends; F, D: phi and phi' there. scale multiplies phi.
  knot_quadrature(std::vector<T> X, std::vector<T> F, std::vector<T> D)
      : X_(std::move(X)), F_(std::move(F)), D_(std::move(D)) {
    using std::cos;
    S_ = X_.size() - 1;
    rule_ = gauss_legendre<T>(g);
    rule4_ = gauss_legendre<T>(4);
    rule6_ = gauss_legendre<T>(6);
    for (int j = 0; j < m; ++j) cheb_[j] = cos(pi<T>() * (T(j) + T(0.5)) / m);
    // T_k(x_j) for the conversion moments -> weights
    for (int j = 0; j < m; ++j) {
      T t0 = 1, t1 = cheb_[j];
      tab_[j * m + 0] = t0;
      if (m > 1) tab_[j * m + 1] = t1;
      for (int k = 2; k < m; ++k) {
        const T t2 = 2 * cheb_[j] * t1 - t0;
        tab_[j * m + k] = t2;
        t0 = t1;
        t1 = t2;
      }
    }
    root_ = build(0, S_);
    cumulate();
  }

  void set_scale(const T &s) { scale_ = s; }
  const T &scale() const { return scale_; }
  std::size_t segments() const { return S_; }
  const T &end(std::size_t s) const { return X_[s]; }
  // the segment holding t (the left one at a knot), t in [-1, 1]
  std::size_t segment(const T &t) const {
    std::size_t s = std::size_t(std::upper_bound(X_.begin(), X_.end(), t) - X_.begin());
    if (s == 0) return 0;
    return std::min(s - 1, S_ - 1);
  }
  // phi (unscaled) on segment s at t, and (if d) its derivative
  T phi(std::size_t s, const T &t, T *d = nullptr) const {
    const T h = X_[s + 1] - X_[s];
    return hermite(s, (t - X_[s]) / h, d);
  }

  // |phi'' jump| (unscaled) at the knot X_s between segments s - 1 and s (0 < s < S)
  T jump2(std::size_t s) const {
    using std::abs;
    const T hl = X_[s] - X_[s - 1], hr = X_[s + 1] - X_[s];
    // Hermite second derivatives at the right end of s - 1 and the left end of s
    const T left = (6 * (F_[s - 1] - F_[s]) / hl + 2 * D_[s - 1] + 4 * D_[s]) / hl;
    const T right = (6 * (F_[s + 1] - F_[s]) / hr - 4 * D_[s] - 2 * D_[s + 1]) / hr;
    return abs(right - left);
  }

  // int p_hat over the length c from the edge on `side` (+1: x = 1, -1: x = -1),
  // scaled: the nearer edge's cumulative sum plus one partial segment, whose
  // angle comes from c itself (relative accuracy for small c)
  T tail(int side, const T &c) const {
    if (!(c > 0)) return T(0);
    if (!(c < 2)) return total();
    const T t = side > 0 ? T(1 - c) : T(c - 1);
    const std::size_t s = segment(t);
    if (side > 0) return scale_ * (CR_[s + 1] + piece_from(+1, s, T(1 - X_[s + 1]), c));
    return scale_ * (CL_[s] + piece_from(-1, s, T(1 + X_[s]), c));
  }
  T total() const { return scale_ * CL_[S_]; }

  // Integral of phi K over [A, B] (-1 <= A < B <= 1): emit(t, w) for the
  // nodes of the admissible tree nodes (w: weight times phi, scaled), and
  // leaf(lo, hi) for every piece of a segment that is not admissible
  // (adm(a, b): K smooth enough on [a, b], see the top of this file).
  template <class Adm, class Emit, class Leaf>
  void cover(const T &A, const T &B, const Adm &adm, const Emit &emit, const Leaf &leaf) const {
    if (!(B > A)) return;
    visit(0, S_, root_, A, B, adm, emit, leaf);
  }

 private:
  struct node {
    std::size_t lo, hi;
    int left, right;  // stored children (-1: not stored)
    std::size_t off;  // weights omega_[off .. off + m)
  };

  T hermite(std::size_t s, const T &u, T *d) const {
    const T h = X_[s + 1] - X_[s];
    const T u2 = u * u, u3 = u2 * u;
    const T f0 = F_[s], f1 = F_[s + 1], d0 = D_[s] * h, d1 = D_[s + 1] * h;
    if (d) *d = ((6 * u2 - 6 * u) * (f0 - f1)) / h + (3 * u2 - 4 * u + 1) * D_[s] + (3 * u2 - 2 * u) * D_[s + 1];
    return (2 * u3 - 3 * u2 + 1) * f0 + (u3 - 2 * u2 + u) * d0 + (-2 * u3 + 3 * u2) * f1 + (u3 - u2) * d1;
  }

  static std::size_t split(std::size_t lo, std::size_t hi) { return lo + (hi - lo) / 2; }

  // moments nu_k += w T_k(xi) for xi in [-1, 1]
  static void add_moments(T *nu, const T &xi, const T &w) {
    T t0 = 1, t1 = xi;
    nu[0] += w;
    nu[1] += w * xi;
    for (int k = 2; k < m; ++k) {
      const T t2 = 2 * xi * t1 - t0;
      nu[k] += w * t2;
      t0 = t1;
      t1 = t2;
    }
  }

  int build(std::size_t lo, std::size_t hi) {
    if (hi - lo < stored) return -1;
    const std::size_t mid = split(lo, hi);
    const int l = build(lo, mid), r = build(mid, hi);
    node nd{lo, hi, l, r, omega_.size()};
    const T c = (X_[lo] + X_[hi]) / 2, rad = (X_[hi] - X_[lo]) / 2;
    T nu[m] = {};
    auto from_child = [&](int ci, std::size_t clo, std::size_t chi) {
      if (ci >= 0) {
        const node &ch = nodes_[ci];
        const T cc = (X_[ch.lo] + X_[ch.hi]) / 2, cr = (X_[ch.hi] - X_[ch.lo]) / 2;
        for (int j = 0; j < m; ++j) add_moments(nu, (cc + cr * cheb_[j] - c) / rad, omega_[ch.off + j]);
        return;
      }
      // the segments' Gauss points, their T_k by the recurrence for all points
      // at once (vectorisable across the points)
      T xi[g], wv[g], t0[g], t1[g];
      for (std::size_t s = clo; s < chi; ++s) {
        const T h = X_[s + 1] - X_[s];
        for (int q = 0; q < g; ++q) {
          const T u = (1 + rule_->x[q]) / 2;
          xi[q] = (X_[s] + h * u - c) / rad;
          wv[q] = h * rule_->w[q] / 2 * hermite(s, u, nullptr);
          t0[q] = 1;
          t1[q] = xi[q];
        }
        T s0 = 0, s1 = 0;
        for (int q = 0; q < g; ++q) {
          s0 += wv[q];
          s1 += wv[q] * xi[q];
        }
        nu[0] += s0;
        nu[1] += s1;
        for (int k = 2; k < m; ++k) {
          T sk = 0;
          for (int q = 0; q < g; ++q) {
            const T t2 = 2 * xi[q] * t1[q] - t0[q];
            t0[q] = t1[q];
            t1[q] = t2;
            sk += wv[q] * t2;
          }
          nu[k] += sk;
        }
      }
    };
    from_child(l, lo, mid);
    from_child(r, mid, hi);
    nu[0] /= 2;
    for (int j = 0; j < m; ++j) {
      T sum = 0;
      for (int k = 0; k < m; ++k) sum += tab_[j * m + k] * nu[k];
      omega_.push_back(2 * sum / m);
    }
    nodes_.push_back(nd);
    return int(nodes_.size() - 1);
  }

  template <class Adm, class Emit, class Leaf> void visit(std::size_t lo, std::size_t hi, int id, const T &A,
                                                          const T &B, const Adm &adm, const Emit &emit,
                                                          const Leaf &leaf) const {
    using std::max;
    using std::min;
    const T a = X_[lo], b = X_[hi];
    if (!(b > A) || !(a < B)) return;
    if (a >= A && b <= B && adm(a, b)) {
      if (id >= 0) {
        const node &nd = nodes_[id];
        const T c = (a + b) / 2, r = (b - a) / 2;
        for (int j = 0; j < m; ++j) emit(T(c + r * cheb_[j]), T(scale_ * omega_[nd.off + j]));
        return;
      }
      for (std::size_t s = lo; s < hi; ++s) {
        const T h = X_[s + 1] - X_[s];
        for (int q = 0; q < g; ++q) {
          const T u = (1 + rule_->x[q]) / 2;
          emit(T(X_[s] + h * u), T(scale_ * h * rule_->w[q] / 2 * hermite(s, u, nullptr)));
        }
      }
      return;
    }
    if (hi - lo == 1) {
      leaf(T(max(a, A)), T(min(b, B)));
      return;
    }
    const std::size_t mid = split(lo, hi);
    const int l = id >= 0 ? nodes_[id].left : -1, r = id >= 0 ? nodes_[id].right : -1;
    visit(lo, mid, l, A, B, adm, emit, leaf);
    visit(mid, hi, r, A, B, adm, emit, leaf);
  }

  // int p_hat (unscaled) over the part of segment s at distances dlo < dhi
  // from the edge `edge` (+1: x = 1, -1: x = -1), by Gauss-Legendre of order g
  // in the angle from that edge, 2 asin(sqrt(dist/2)): t = -+cos(angle),
  // sqrt(1 - t^2) dt = sin^2(angle) d(angle), smooth up to the edge
  T piece_from(int edge, std::size_t s, const T &dlo, const T &dhi) const {
    using std::asin;
    using std::sin;
    using std::sqrt;
    if (!(dhi > dlo)) return T(0);
    auto ang = [](const T &dist) { return 2 * asin(sqrt(dist / 2)); };
    const T lo_a = ang(dlo), L = ang(dhi) - lo_a, h = X_[s + 1] - X_[s];
    T sum = 0;
    for (int q = 0; q < g; ++q) {
      const T th = lo_a + L * (1 + rule_->x[q]) / 2;
      const T sn = sin(th), half = sin(th / 2);
      const T dist = 2 * half * half;  // 1 - cos(angle)
      const T t = edge > 0 ? T(1 - dist) : T(dist - 1);
      sum += rule_->w[q] * sn * sn * hermite(s, (t - X_[s]) / h, nullptr);
    }
    return sum * L / 2;
  }
  // the whole segment s: by Gauss-Legendre in t when it lies at least
  // eta = 2 of its lengths from both edges (p_hat analytic around it: error
  // ~(4 R)^-(2 q - 3), R = distance/length, at order q), else in the angle
  // from the nearer edge (split at 0)
  T piece(std::size_t s) const {
    using std::sqrt;
    const T &lo = X_[s], &hi = X_[s + 1];
    const T L = hi - lo, D = std::min(T(1 + lo), T(1 - hi));
    if (D >= eta() * L) {
      // order: 4 from R = 1000 (error ~4000^-5 = 1e-18), 6 from R = 30, else g
      const T R = D / L;
      const auto &rl = R >= T(1000) ? rule4_ : (R >= T(30) ? rule6_ : rule_);
      const int nq = int(rl->x.size());
      T sum = 0;
      for (int q = 0; q < nq; ++q) {
        const T u = (1 + rl->x[q]) / 2, t = lo + L * u;
        sum += rl->w[q] * sqrt((1 + t) * (1 - t)) * hermite(s, u, nullptr);
      }
      return sum * L / 2;
    }
    if (hi <= 0) return piece_from(-1, s, T(1 + lo), T(1 + hi));
    if (lo >= 0) return piece_from(+1, s, T(1 - hi), T(1 - lo));
    return piece_from(-1, s, T(1 + lo), T(1)) + piece_from(+1, s, T(1 - hi), T(1));
  }

  // compensated cumulative sums from both edges
  void cumulate() {
    std::vector<T> seg(S_);
    for (std::size_t s = 0; s < S_; ++s) seg[s] = piece(s);
    CL_.assign(S_ + 1, T(0));
    CR_.assign(S_ + 1, T(0));
    T sum = 0, c = 0;
    for (std::size_t s = 0; s < S_; ++s) {
      const T y = seg[s] - c, t = sum + y;
      c = (t - sum) - y;
      sum = t;
      CL_[s + 1] = sum;
    }
    sum = 0;
    c = 0;
    for (std::size_t s = S_; s-- > 0;) {
      const T y = seg[s] - c, t = sum + y;
      c = (t - sum) - y;
      sum = t;
      CR_[s] = sum;
    }
  }

  std::vector<T> X_, F_, D_;
  std::size_t S_ = 0;
  std::shared_ptr<const gl_rule<T>> rule_, rule4_, rule6_;
  T cheb_[m];
  T tab_[m * m];
  std::vector<node> nodes_;
  std::vector<T> omega_;
  int root_ = -1;
  std::vector<T> CL_, CR_;
  T scale_{1};
};

// A model's knot quadrature as seen through its mirror images (t -> -t).
template <class T> struct knot_view {
  const knot_quadrature<T> *q = nullptr;
  bool mirror = false;
  explicit operator bool() const { return q != nullptr; }
  std::size_t segments() const { return q->segments(); }
  // end s of the segments in the view's coordinates (s = 0: -1, s = S: 1)
  T end(std::size_t s) const { return mirror ? T(-q->end(q->segments() - s)) : q->end(s); }
  // the segment holding t
  std::size_t segment(const T &t) const {
    if (!mirror) return q->segment(t);
    const std::size_t S = q->segments();
    return S - 1 - q->segment(T(-t));
  }
  // |phi'' jump| (scaled) at the view's knot between segments s - 1 and s (0 < s < S)
  T jump2(std::size_t s) const { return q->scale() * q->jump2(mirror ? q->segments() - s : s); }
  // phi (scaled) on segment s of the view at t
  T phi(std::size_t s, const T &t) const {
    if (!mirror) return q->scale() * q->phi(s, t);
    return q->scale() * q->phi(q->segments() - 1 - s, T(-t));
  }
  template <class Adm, class Emit, class Leaf>
  void cover(const T &A, const T &B, const Adm &adm, const Emit &emit, const Leaf &leaf) const {
    if (!mirror) {
      q->cover(A, B, adm, emit, leaf);
      return;
    }
    q->cover(
        T(-B), T(-A), [&](const T &a, const T &b) { return adm(T(-b), T(-a)); },
        [&](const T &t, const T &w) { emit(T(-t), w); }, [&](const T &lo, const T &hi) { leaf(T(-hi), T(-lo)); });
  }
};

}}  // namespace hs::core
