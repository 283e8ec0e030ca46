// halfslip core: fast Cauchy sums on the real line (issue 13 item 4: the zone
// energies and slips of a sampled pressure at linear cost in the sample count).
//
//   f_c(y_j) = sum_i q_{c,i} / (x_i - y_j),  c = 0 .. nq - 1 (several charge sets),
//
// for sorted sources x_i and sorted targets y_j, over every pair (j, i) except
// those of neighbouring leaves, which go to the caller (near(ja, jb, ia, ib):
// targets [ja, jb) against sources [ia, ib)), who sums them directly, e.g. with
// a principal-value subtraction.
//
// The fast multipole method of Greengard and Rokhlin in one dimension, with
// scaled Taylor expansions. Both point sets get a binary tree over index ranges
// (leaves of at most `leaf` points); a node covers [min, max] of its points,
// centre c, radius r. A source node's multipole moments a_k = sum_i q_i
// ((x_i - c)/r)^k, k < p, give the field far away,
//   sum_i q_i/(x_i - y) = -sum_k a_k r^k/(y - c)^(k+1);
// a dual traversal pairs target node A (centre z, radius s) and source node B
// once their intervals are at least 3 max(r, s) apart, and turns B's moments
// into A's local expansion sum_l b_l ((y - z)/s)^l,
//   b_l = -(1/D) v^l sum_k binom(k + l, l) a_k u^k,  D = z - c, u = r/D, v = -s/D
// (M2L: one division, p^2 products). Then |u|, |v| <= 1/5 and truncating both
// series after p = 24 terms errs by ~2 (2/5)^p... in practice each is bounded by
// (1/5)^p/(1 - 1/5) = 8e-17 relative to sum |q|/distance. Moments and local
// expansions move between parent and child by the binomial theorem (M2M, L2L),
// and the leaves evaluate their expansion at their targets (Horner).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <boost/math/tools/precision.hpp>

#include "numerics.hpp"

namespace hs { namespace core {

template <class T> class cauchy_fmm {
 public:
  static constexpr int p = 24;

  // x: nx sorted sources; y: ny sorted targets (both must outlive the object)
  cauchy_fmm(const T *x, std::size_t nx, const T *y, std::size_t ny, std::size_t leaf = 32)
      : x_(x), y_(y), leaf_(leaf < 1 ? 1 : leaf) {
    binom_.assign(std::size_t(2 * p) * 2 * p, T(0));
    for (int n = 0; n < 2 * p; ++n) {
      binom_[std::size_t(n) * 2 * p] = 1;
      for (int k = 1; k <= n; ++k)
        binom_[std::size_t(n) * 2 * p + k] =
            binom_[std::size_t(n - 1) * 2 * p + k - 1] + (k < n ? binom_[std::size_t(n - 1) * 2 * p + k] : T(0));
    }
    if (nx > 0) build(sn_, x_, 0, nx);
    if (ny > 0) build(tn_, y_, 0, ny);
  }

  // out[c][j] += the far field of charge set c at target j
  template <class Near> void apply(int nq, const T *const *q, T *const *out, const Near &near) const {
    if (sn_.empty() || tn_.empty()) return;
    const std::size_t S = sn_.size(), Tn = tn_.size();
    std::vector<T> A(S * nq * p, T(0)), B(Tn * nq * p, T(0));
    // upward: children have larger indices than their parent
    T pw[p];
    for (std::size_t b = S; b-- > 0;) {
      const node &nd = sn_[b];
      T *ab = &A[b * nq * p];
      if (nd.left < 0) {
        for (std::size_t i = nd.lo; i < nd.hi; ++i) {
          const T xi = (x_[i] - nd.c) / nd.r;
          T t = 1;
          for (int k = 0; k < p; ++k) {
            pw[k] = t;
            t *= xi;
          }
          for (int c = 0; c < nq; ++c) {
            const T qi = q[c][i];
            for (int k = 0; k < p; ++k) ab[c * p + k] += qi * pw[k];
          }
        }
        continue;
      }
      // M2M: ((x - c)/r)^k = sum_j binom(k, j) ((x - c')/r')^j (r'/r)^j ((c' - c)/r)^(k - j)
      for (int ch : {nd.left, nd.right}) {
        const node &cn = sn_[ch];
        const T rho = cn.r / nd.r, del = (cn.c - nd.c) / nd.r;
        T rp[p], dp[p];
        rp[0] = dp[0] = 1;
        for (int k = 1; k < p; ++k) {
          rp[k] = rp[k - 1] * rho;
          dp[k] = dp[k - 1] * del;
        }
        for (int c = 0; c < nq; ++c) {
          const T *ac = &A[(std::size_t(ch) * nq + c) * p];
          for (int k = 0; k < p; ++k) {
            T s = 0;
            for (int j = 0; j <= k; ++j) s += binom(k, j) * ac[j] * rp[j] * dp[k - j];
            ab[c * p + k] += s;
          }
        }
      }
    }
    traverse(0, 0, nq, A, B, near);
    // downward: local expansions to the children (L2L) and to the targets (L2P)
    for (std::size_t a = 0; a < Tn; ++a) {
      const node &nd = tn_[a];
      const T *ba = &B[a * nq * p];
      if (nd.left >= 0) {
        // ((y - z)/s)^l = (w s'/s + del)^l, w = (y - z')/s', del = (z' - z)/s
        for (int ch : {nd.left, nd.right}) {
          const node &cn = tn_[ch];
          const T rho = cn.r / nd.r, del = (cn.c - nd.c) / nd.r;
          T rp[p], dp[p];
          rp[0] = dp[0] = 1;
          for (int k = 1; k < p; ++k) {
            rp[k] = rp[k - 1] * rho;
            dp[k] = dp[k - 1] * del;
          }
          for (int c = 0; c < nq; ++c) {
            T *bc = &B[(std::size_t(ch) * nq + c) * p];
            for (int j = 0; j < p; ++j) {
              T s = 0;
              for (int l = j; l < p; ++l) s += binom(l, j) * ba[c * p + l] * dp[l - j];
              bc[j] += s * rp[j];
            }
          }
        }
        continue;
      }
      for (std::size_t j = nd.lo; j < nd.hi; ++j) {
        const T w = (y_[j] - nd.c) / nd.r;
        for (int c = 0; c < nq; ++c) {
          const T *bc = ba + c * p;
          T s = bc[p - 1];
          for (int l = p - 2; l >= 0; --l) s = s * w + bc[l];
          out[c][j] += s;
        }
      }
    }
  }

 private:
  struct node {
    std::size_t lo, hi;
    T c, r;
    int left, right;
  };

  const T &binom(int n, int k) const { return binom_[std::size_t(n) * 2 * p + k]; }

  void build(std::vector<node> &tree, const T *pts, std::size_t lo, std::size_t hi) {
    const std::size_t id = tree.size();
    const T lo_v = pts[lo], hi_v = pts[hi - 1];
    const T c = (lo_v + hi_v) / 2;
    T r = (hi_v - lo_v) / 2;
    if (!(r > 0)) r = boost::math::tools::min_value<T>() / eps<T>();  // one position: any radius
    tree.push_back({lo, hi, c, r, -1, -1});
    if (hi - lo <= leaf_) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    const int l = int(tree.size());
    build(tree, pts, lo, mid);
    const int rr = int(tree.size());
    build(tree, pts, mid, hi);
    tree[id].left = l;
    tree[id].right = rr;
  }

  static bool separated(const node &a, const node &b) {
    const T gap = b.c - b.r > a.c + a.r ? T((b.c - b.r) - (a.c + a.r))
                                        : (a.c - a.r > b.c + b.r ? T((a.c - a.r) - (b.c + b.r)) : T(0));
    return gap >= 3 * (a.r > b.r ? a.r : b.r);
  }

  template <class Near>
  void traverse(int ia, int ib, int nq, const std::vector<T> &A, std::vector<T> &B, const Near &near) const {
    const node &a = tn_[ia], &b = sn_[ib];
    if (separated(a, b)) {
      // M2L
      const T D = a.c - b.c, u = b.r / D, v = -a.r / D;
      T up[p], vp[p];
      up[0] = vp[0] = 1;
      for (int k = 1; k < p; ++k) {
        up[k] = up[k - 1] * u;
        vp[k] = vp[k - 1] * v;
      }
      for (int c = 0; c < nq; ++c) {
        const T *ac = &A[(std::size_t(ib) * nq + c) * p];
        T au[p];
        for (int k = 0; k < p; ++k) au[k] = ac[k] * up[k];
        T *bc = &B[(std::size_t(ia) * nq + c) * p];
        for (int l = 0; l < p; ++l) {
          T s = 0;
          for (int k = 0; k < p; ++k) s += binom(k + l, l) * au[k];
          bc[l] -= s * vp[l] / D;
        }
      }
      return;
    }
    const bool la = a.left < 0, lb = b.left < 0;
    if (la && lb) {
      near(a.lo, a.hi, b.lo, b.hi);
      return;
    }
    if (!la && (lb || a.r >= b.r)) {
      traverse(a.left, ib, nq, A, B, near);
      traverse(a.right, ib, nq, A, B, near);
    } else {
      traverse(ia, b.left, nq, A, B, near);
      traverse(ia, b.right, nq, A, B, near);
    }
  }

  const T *x_, *y_;
  std::size_t leaf_;
  std::vector<node> sn_, tn_;
  std::vector<T> binom_;
};

// The same sums for targets that come one at a time (an adaptive subdivision that decides
// where to evaluate from the values it has: core/static_history.hpp's new traction on a
// sampled pressure), by a treecode (Barnes and Hut; Greengard and Rokhlin's multipole
// expansion without the local one):
//
//   f(y) = sum_i q_i / (x_i - y).
//
// The sources (copied, sorted) get a binary tree over index ranges (leaves of at most `leaf`
// points); node (centre c, radius r) holds the moments a_k = sum_i q_i ((x_i - c)/r)^k,
// k < m, each from its points (no translation: |(x_i - c)/r| <= 1, no growth). A node with
// |y - c| > 4r contributes -(1/D) sum_k a_k (r/D)^k, D = y - c (Horner), whose truncation
// errs by at most sum|q_i|/|D| 4^-m/(1 - 1/4) <= (5/3) 4^-m sum|q_i|/|x_i - y| (|x_i - y| <=
// 5|D|/4); m is one more than the least with (5/3) 4^-m <= eps/4. Other nodes open, down to leaves summed
// directly. Cost per target: about 2 m log2(n/leaf) + 2 leaf operations, not n.
template <class T> class cauchy_treecode {
 public:
  explicit cauchy_treecode(std::vector<std::pair<T, T>> src, std::size_t leaf = 32) : leaf_(leaf < 1 ? 1 : leaf) {
    std::sort(src.begin(), src.end(), [](const std::pair<T, T> &a, const std::pair<T, T> &b) { return a.first < b.first; });
    x_.reserve(src.size());
    q_.reserve(src.size());
    for (auto &s : src) {
      x_.push_back(std::move(s.first));
      q_.push_back(std::move(s.second));
    }
    m_ = 1;
    const T target = eps<T>() / 4 * 3 / 5;
    for (T t = 1; t > target && m_ < 4096; t /= 4) ++m_;
    if (!x_.empty()) build(0, x_.size());
  }
  std::size_t size() const { return x_.size(); }
  int terms() const { return m_; }

  T operator()(const T &y) const {
    using std::abs;
    T s = 0;
    if (nodes_.empty()) return s;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const node &nd = nodes_[std::size_t(stack[--top])];
      const T D = y - nd.c;
      if (abs(D) > 4 * nd.r) {
        const T t = nd.r / D;
        const T *a = &mom_[nd.mom];
        T acc = a[m_ - 1];
        for (int k = m_ - 1; k-- > 0;) acc = acc * t + a[k];
        s -= acc / D;
      } else if (nd.left < 0) {
        for (std::size_t i = nd.lo; i < nd.hi; ++i) s += q_[i] / (x_[i] - y);
      } else {
        stack[top++] = nd.right;
        stack[top++] = nd.left;
      }
    }
    return s;
  }

 private:
  struct node {
    std::size_t lo, hi, mom;
    T c, r;
    int left, right;
  };
  // (depth: halving index ranges from at most 2^62 points is below 64 levels, so the
  // evaluation's stack of 128 holds every pending right child)
  int build(std::size_t lo, std::size_t hi) {
    const int id = int(nodes_.size());
    const T c = (x_[lo] + x_[hi - 1]) / 2, r = (x_[hi - 1] - x_[lo]) / 2;
    nodes_.push_back({lo, hi, mom_.size(), c, r, -1, -1});
    mom_.resize(mom_.size() + std::size_t(m_), T(0));
    T *a = &mom_[nodes_[std::size_t(id)].mom];
    for (std::size_t i = lo; i < hi; ++i) {
      const T u = r > 0 ? T((x_[i] - c) / r) : T(0);
      T t = q_[i];
      for (int k = 0; k < m_; ++k) {
        a[k] += t;
        t *= u;
      }
    }
    if (hi - lo <= leaf_) return id;
    const std::size_t mid = lo + (hi - lo) / 2;
    const int l = build(lo, mid);
    const int rr = build(mid, hi);
    nodes_[std::size_t(id)].left = l;
    nodes_[std::size_t(id)].right = rr;
    return id;
  }
  std::size_t leaf_;
  int m_ = 1;
  std::vector<T> x_, q_, mom_;
  std::vector<node> nodes_;
};

}}  // namespace hs::core
