// halfslip core: the state of a history taken by static solves (static_history.hpp): the
// stick traction on theta panels, and the start state of a phase whose slip and energy follow
// from its start and end states (folds, patches; docs/history.md). Canonical frame as
// core/history.hpp: a = p0 = f = E* = 1, q = Q/fP, s = sigma/(f p0).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "gauss.hpp"
#include "numerics.hpp"
#include "pressure.hpp"

namespace hs { namespace core {

namespace shdetail {

// Gauss-Legendre rule in theta on (0, pi) with barycentric weights for interpolation.
template <class T> struct trule {
  std::vector<T> t, w, bw, sh, ch;  // nodes on (-1, 1), weights, barycentric weights, sin, cos(theta/2)
  std::vector<T> wp1, wp2;          // w_j P_{n-1}(t_j) (2n - 1)/2 and w_j P_{n-2}(t_j) (2n - 3)/2

  explicit trule(int n) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const auto r = gauss_legendre<T>(n);
    t = r->x;
    w = r->w;
    const T pi_ = pi<T>();
    for (int j = 0; j < n; ++j) {
      bw.push_back(T((j % 2) ? -1 : 1) * sqrt((1 - t[j]) * (1 + t[j]) * w[j]));
      const T th = pi_ * (1 + t[j]) / 2;
      sh.push_back(sin(th / 2));
      ch.push_back(cos(th / 2));
      // (the coefficients of P_{n-1}, P_{n-2} of the values at the nodes: resolved())
      T p0 = 1, p1 = t[j];
      for (int k = 2; k < n; ++k) {
        const T p2 = (T(2 * k - 1) * t[j] * p1 - T(k - 1) * p0) / T(k);
        p0 = p1;
        p1 = p2;
      }
      wp1.push_back(w[j] * p1 * T(2 * (n - 1) + 1) / 2);
      wp2.push_back(w[j] * p0 * T(2 * (n - 2) + 1) / 2);
    }
  }
  int n() const { return int(t.size()); }
  // interpolate values v at theta-parameter t0 in [-1, 1]
  // node j on the panel [l, r] (x = l + (r - l) sin^2(theta_j/2), from the nearer end) and its
  // distances dl, dr to the panel's ends
  T node(const T &l, const T &r, int j, T &dl, T &dr) const {
    dl = (r - l) * sh[j] * sh[j];
    dr = (r - l) * ch[j] * ch[j];
    return dl <= dr ? l + dl : r - dr;
  }
  T node(const T &l, const T &r, int j) const {
    T dl, dr;
    return node(l, r, j, dl, dr);
  }
  T interp(const std::vector<T> &v, const T &t0) const {
    T num = 0, den = 0;
    for (size_t j = 0; j < t.size(); ++j) {
      const T d = t0 - t[j];
      if (d == 0) return v[j];
      const T c = bw[j] / d;
      num += c * v[j];
      den += c;
    }
    return num / den;
  }
};

// the grading level K of a piece of length L whose end lies D from a near singularity (0: not
// graded): theta intervals down to pi 2^-K, the scale 2 sqrt(D/L) of the singularity in theta
template <class T> int grade_level(const T &D, const T &L) {
  using std::max;
  using std::sqrt;
  if (!(D < L)) return 0;
  const T a0 = max(T(2) * sqrt(max(D, T(0)) / L), T(64) * eps<T>());
  int K = 1;
  while (K < 63 && pi<T>() * T(std::ldexp(1.0, -K)) > a0) ++K;
  return K;
}

// the theta-parameter in [-1, 1] of x in [l, r]
template <class T> T tpar(const T &l, const T &r, const T &x) {
  using std::atan2;
  using std::sqrt;
  const T a = x - l, b = r - x;
  const T th = 2 * atan2(sqrt(a > 0 ? a : T(0)), sqrt(b > 0 ? b : T(0)));
  return 2 * th / pi<T>() - 1;
}

}  // namespace shdetail

// one panel of the state's stick traction
template <class T> struct sh_panel {
  T l, r;
  bool analytic = false;  // q = c p(x) exactly (a zone that stuck whole)
  T c{0};
  std::vector<T> v;     // values at the rule's nodes (analytic == false)
  bool cusp_l = false;  // l is a memory point (a square-root cusp of q)
};

namespace shdetail {
// The traction of a state at x: s_i p in a slip zone, else its stick panels (sorted,
// contiguous over the stick zone; an analytic panel is a multiple of p). pf() gives p(x), called
// only where it is needed (one pressure evaluation a band node, where the caller has it).
template <class T, class PF>
T state_traction(const std::vector<sh_panel<T>> &panels, const trule<T> &rule, const T &b1, const T &b2, int s1,
                 int s2, const T &x, const PF &pf) {
  if (x > b1) return T(s1) * pf();
  if (x < -b2) return T(s2) * pf();
  size_t lo = 0, hi = panels.size();
  while (hi - lo > 1) {
    const size_t m = (lo + hi) / 2;
    if (panels[m].l <= x) lo = m;
    else hi = m;
  }
  const auto &P = panels[lo];
  if (P.analytic) return P.c * pf();
  return rule.interp(P.v, tpar(P.l, P.r, x));
}

// The nodes and weights of the rule on the pieces [cuts_k, cuts_k+1]: 32-point Gauss-Legendre in
// theta on each, x = l + L sin^2(theta/2), which takes square-root behaviour at the cuts;
// g(eta, w, end, dist) for each node in turn, with the node's exact distance dist to the nearer
// end of its piece. (A node next to a root of the integrand's square root at a piece's end, in a
// piece of a few 1e-12, rounds onto it: eta - root is then 0 and the integrand infinite; the
// distance is not.)
template <class T, class G> void pv_nodes_d(const std::vector<T> &cuts, G &&g) {
  using std::cos;
  using std::sin;
  const T pi_ = pi<T>();
  const auto gr = gauss_legendre<T>(32);
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const T l = cuts[k], L = cuts[k + 1] - l;
    if (!(L > 0)) continue;
    for (size_t j = 0; j < gr->x.size(); ++j) {
      const T th = pi_ * (1 + gr->x[j]) / 2, sh = sin(th / 2), ch = cos(th / 2);
      const T xl = L * sh * sh, xr = L * ch * ch;
      const T w = pi_ / 2 * gr->w[j] * L * sh * ch;
      if (xl <= xr) g(l + xl, w, l, xl);
      else g(cuts[k + 1] - xr, w, cuts[k + 1], xr);
    }
  }
}
// the same, g(eta, w)
template <class T, class G> void pv_nodes(const std::vector<T> &cuts, G &&g) {
  pv_nodes_d(cuts, [&](const T &eta, const T &w, const T &, const T &) { g(eta, w); });
}

// PV int over the pieces [cuts_k, cuts_k+1] of f(eta) / (eta - x), x inside [cuts.front(),
// cuts.back()] (one of the cuts) or outside it: pv_nodes_d's rule, f(eta, end, dist) given each
// node's exact distance to its piece's end (f(x, NaN, 0) at x itself: no end known); the singular
// part f(x) ln((hi - x)/(x - lo)) in closed form
template <class T, class F> T pv_pieces(const std::vector<T> &cuts, const F &f, const T &x, bool inside) {
  using std::log;
  T fx = 0, s = 0;
  if (inside) {
    fx = f(x, std::numeric_limits<T>::quiet_NaN(), T(0));
    s = fx * log((cuts.back() - x) / (x - cuts.front()));
  }
  pv_nodes_d(cuts, [&](const T &eta, const T &w, const T &end, const T &dist) {
    // (a node on x itself, in a piece of a few ulps next to it: its term is w f'(x), w ~ L)
    if (inside && eta == x) return;
    s += w * (f(eta, end, dist) - fx) / (eta - x);
  });
  return s;
}

}  // namespace shdetail

// The start of an advancing phase, kept where the ends jump at a fold: the slip of a static
// state (ends b1, b2, directions d1, d2, at the same load) relative to this start, outside its
// stick zone (docs/history.md, "Folds"). With g = d p - q_S on the bands and X = +W on band 1,
// -W on band 2 (W = sqrt|(x - b1)(x + b2)|), the slip gradient there is
//   dh'(x) = -(2/pi) X(x) PV int_bands g(eta) / (X(eta) (eta - x)) d eta
// (the outer values of the stick zone's finite Hilbert inversion; checked against the Hertz
// closed forms), and dh(x) is its integral from the stick end.
template <class T> struct sh_start {
  std::shared_ptr<const pressure_model<T>> pm;
  std::shared_ptr<const shdetail::trule<T>> rule;
  std::vector<sh_panel<T>> panels;
  std::vector<T> cusps;  // memory points, ends and pressure breakpoints in (-1, 1)
  T b1{1}, b2{1};
  int s1 = 0, s2 = 0;

  T traction(const T &x) const {
    return shdetail::state_traction(panels, *rule, b1, b2, s1, s2, x, [&] { return pm->p(x); });
  }
  // the cuts of (lo, hi): its ends and the cusps inside, plus x if it lies inside, with cuts
  // graded away from x at multiples of its distance to the nearer end (where the integrand
  // varies on that scale: next to the stick end, f ~ 1/sqrt)
  std::vector<T> cuts(const T &lo, const T &hi, const T *x) const {
    using std::min;
    std::vector<T> c{lo};
    for (const T &m : cusps)
      if (m > lo && m < hi) c.push_back(m);
    if (x && *x > lo && *x < hi) {
      c.push_back(*x);
      const T D = min(*x - lo, hi - *x);
      for (T d = 2 * D; d < hi - lo; d *= 2) {
        if (*x + d < hi) c.push_back(*x + d);
        if (*x - d > lo) c.push_back(*x - d);
      }
    }
    c.push_back(hi);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    // cuts within rounding of each other are one (the piece between them is merged into its
    // neighbour, not dropped): a piece of an ulp or two has its nodes on its ends, where the
    // PV's (f(eta) - f(x)) / (eta - x) is 0/0 and 1/X at the stick end infinite. A slip
    // evaluated at a sample of a sampled pressure after a fold was NaN: the knot 0.90999999999999992
    // and x = 0.91 (tests/test_static_history.cpp, "slip at a sample after a fold"). The PV point x
    // and the ends are kept.
    const T tol = 64 * eps<T>();
    std::vector<T> m{c.front()};
    for (size_t k = 1; k < c.size(); ++k) {
      const bool keep = k + 1 == c.size() || (x && c[k] == *x);
      if (c[k] - m.back() > tol) m.push_back(c[k]);
      else if (keep && m.size() > 1 && !(x && m.back() == *x)) m.back() = c[k];
      else if (keep && k + 1 == c.size()) m.push_back(c[k]);  // (lo and hi, or x and hi, that close)
    }
    return m;
  }
  // dh'(x) of the state (b1, b2, d1, d2), x outside its stick zone
  // Work shared by the dh' evaluations of one end state (e1, e2, d1, d2): the integrand at the
  // nodes of a band that x lies outside (they do not depend on x), and dh' at the theta nodes of
  // each band (one_way and energy integrate it on the same nodes). One per end state: a phase's
  // one_way checks and energies cost a fifth to a quarter less (bench/static_walks.cpp, walks 1-20).
  struct dhp_memo {
    bool have[2] = {false, false};
    std::vector<std::array<T, 3>> fixed[2];  // (eta, w, f(eta))
    std::vector<T> nodes[2];                 // dh' at theta_int's nodes over cuts(lo, hi)
    // the pieces of x's own band between two fixed cuts (its ends and cusps, no cut of x's grading
    // between), the same for every x: (eta, w, f(eta)) at their nodes, by (l, r) (a map: a sampled
    // pressure cuts the band into a piece per sample)
    std::map<std::pair<T, T>, std::vector<std::array<T, 3>>> own[2];
  };
  T dhp(const T &x, const T &e1, const T &e2, int d1, int d2, dhp_memo *mm = nullptr) const {
    using std::sqrt;
    // At a stick end itself the slip gradient is 0: it vanishes there like the square root of the
    // distance (the traction is bounded), while X below is 0 and the band sum has a node on x,
    // 0 * inf. A theta node of a piece 1.1e-12 a wide next to the end rounds onto it: periodic
    // (Q_m, Q_a, sigma_m, sigma_a, phase) = (0, 0.1, 0, 0.3, 45 deg), vertex 128, where zone 1's end
    // returns to its memory point, and the fold's energy was NaN.
    if (x == e1 || x == -e2) return T(0);
    T K = 0;
    for (int i = 1; i <= 2; ++i) {
      const int d = i == 1 ? d1 : d2;
      if (d == 0) continue;
      const T lo = i == 1 ? e1 : T(-1), hi = i == 1 ? T(1) : -e2;
      if (!(hi > lo)) continue;
      const bool in = x > lo && x < hi;
      // (at a node, with its exact distance dist to the piece's end `end`: the band's root, the stick
      // end, may be that end; periodic (0.1, 0, 0, 0.3, 45), chord 106: a fold's end 1.3e-10 from a
      // memory point, a node on the root, and zone 2's energy infinite)
      auto fd = [&](const T &eta, const T &end, const T &dist) {
        const T r1 = i == 1 ? (end == e1 ? dist : eta - e1) : e1 - eta;
        const T r2 = i == 1 ? eta + e2 : (end == -e2 ? dist : -e2 - eta);
        const T X = i == 1 ? sqrt(r1 * r2) : -sqrt(r1 * r2);
        // (one pressure evaluation a node: the traction in a slip zone is a multiple of it)
        const T pe = pm->p(eta);
        return (T(d) * pe - shdetail::state_traction(panels, *rule, b1, b2, s1, s2, eta, [&] { return pe; })) / X;
      };
      auto f = [&](const T &eta) { return fd(eta, std::numeric_limits<T>::quiet_NaN(), T(0)); };
      if (!in && mm) {  // (the nodes outside the band, their f kept)
        auto &F = mm->fixed[i - 1];
        if (!mm->have[i - 1]) {
          shdetail::pv_nodes_d(cuts(lo, hi, nullptr), [&](const T &eta, const T &w, const T &end, const T &dist) {
            F.push_back({{eta, w, fd(eta, end, dist)}});
          });
          mm->have[i - 1] = true;
        }
        T s = 0;
        for (const auto &n : F) s += n[1] * n[2] / (n[0] - x);
        K += s;
        continue;
      }
      if (in && mm) {
        // the PV term by term, with f kept on the pieces between fixed cuts (the same sums to the
        // last bit; 5-6% of the walks' time, bench/static_walks.cpp, walks 1-20)
        using std::log;
        const auto c = cuts(lo, hi, &x);
        auto fixed = [&](const T &v) {
          return v == lo || v == hi || std::find(cusps.begin(), cusps.end(), v) != cusps.end();
        };
        const T fx = f(x);
        T s = fx * log((c.back() - x) / (x - c.front()));
        for (size_t k = 0; k + 1 < c.size(); ++k) {
          const std::vector<T> piece{c[k], c[k + 1]};
          if (!fixed(c[k]) || !fixed(c[k + 1])) {
            shdetail::pv_nodes_d(piece, [&](const T &eta, const T &w, const T &end, const T &dist) {
              if (eta == x) return;
              s += w * (fd(eta, end, dist) - fx) / (eta - x);
            });
            continue;
          }
          auto &v = mm->own[i - 1][std::make_pair(c[k], c[k + 1])];
          if (v.empty())
            shdetail::pv_nodes_d(piece, [&](const T &eta, const T &w, const T &end, const T &dist) {
              v.push_back({{eta, w, fd(eta, end, dist)}});
            });
          for (const auto &n : v) {
            if (n[0] == x) continue;
            s += n[1] * (n[2] - fx) / (n[0] - x);
          }
        }
        K += s;
        continue;
      }
      K += shdetail::pv_pieces(cuts(lo, hi, in ? &x : nullptr), fd, x, in);
    }
    const T X = x > e1 ? sqrt((x - e1) * (x + e2)) : -sqrt((e1 - x) * (-e2 - x));
    return -2 / pi<T>() * X * K;
  }
  // the integral of f over the pieces between the cuts c, by 24-point Gauss-Legendre in theta
  // on each (x = l + L sin^2(theta/2): square-root behaviour at every cut)
  template <class F> static T theta_int(const std::vector<T> &c, const F &f) {
    using std::cos;
    using std::sin;
    const auto gr = gauss_legendre<T>(24);
    const T pi_ = pi<T>();
    T s = 0;
    for (size_t k = 0; k + 1 < c.size(); ++k) {
      const T l = c[k], L = c[k + 1] - l;
      for (size_t j = 0; j < gr->x.size(); ++j) {
        const T th = pi_ * (1 + gr->x[j]) / 2, sh = sin(th / 2), ch = cos(th / 2);
        s += pi_ / 2 * gr->w[j] * L * sh * ch * f(l + L * sh * sh);
      }
    }
    return s;
  }
  // the cuts c with each piece between them split into sub equal parts
  static std::vector<T> subdivided(const std::vector<T> &c, int sub) {
    std::vector<T> f{c.front()};
    for (size_t k = 0; k + 1 < c.size(); ++k)
      for (int m = 1; m <= sub; ++m) f.push_back(m == sub ? c[k + 1] : c[k] + (c[k + 1] - c[k]) * T(m) / T(sub));
    return f;
  }
  // int_a^b p, cut at the pressure's breakpoints
  T p_integral(const T &a, const T &b) const {
    std::vector<T> pcs{a};
    for (const auto &bp : pm->breakpoints())
      if (bp.x > a && bp.x < b) pcs.push_back(bp.x);
    pcs.push_back(b);
    std::sort(pcs.begin(), pcs.end());
    return theta_int(pcs, [&](const T &x) { return pm->p(x); });
  }
  // dh(x): the integral of dh' from the stick end of x's zone (0 on the stick zone)
  T dh(const T &x, const T &e1, const T &e2, int d1, int d2) const {
    if (x <= e1 && x >= -e2) return T(0);
    const T lo = x > e1 ? e1 : x, hi = x > e1 ? x : -e2;
    const T s = theta_int(cuts(lo, hi, nullptr), [&](const T &xi) { return dhp(xi, e1, e2, d1, d2); });
    return x > e1 ? s : -s;
  }
  // d_i dh >= 0 at the cuts of band i, to rounding: every band point slipped in its zone's
  // direction, the premise of taking a phase's slip and energy from its start and end states
  // (a necessary condition, checked where the cuts are: the band's ends and the cusps inside)
  // (sub > 1: each piece between cuts split into sub equal parts, the check at their ends too)
  bool one_way(int i, const T &e1, const T &e2, int d1, int d2, int sub = 1, dhp_memo *mm = nullptr) const {
    using std::abs;
    const int d = i == 1 ? d1 : d2;
    if (d == 0) return true;
    const T lo = i == 1 ? e1 : T(-1), hi = i == 1 ? T(1) : -e2;
    if (!(hi > lo)) return true;
    auto c = cuts(lo, hi, nullptr);
    if (sub > 1) c = subdivided(c, sub);
    const size_t n = c.size() - 1;
    std::vector<T> h(n);  // dh at the outer end of each piece, counted from the stick end
    T run = 0, big = 0;
    const size_t nq = gauss_legendre<T>(24)->x.size();
    std::vector<T> *keep = mm && sub == 1 ? &mm->nodes[i - 1] : nullptr;
    if (keep) keep->assign(n * nq, T(0));
    for (size_t k = 0; k < n; ++k) {
      const size_t j = i == 1 ? k : n - 1 - k;  // band 2 runs from -e2 leftwards
      size_t q = j * nq;
      const T part = theta_int({c[j], c[j + 1]}, [&](const T &xi) {
        const T v = dhp(xi, e1, e2, d1, d2, mm);
        if (keep) (*keep)[q++] = v;
        return v;
      });
      run += i == 1 ? part : -part;
      h[k] = run;
      big = std::max(big, abs(run));
    }
    for (const T &v : h)
      if (T(d) * v < -(T(1e-9) * big + T(1e-15))) return false;
    return true;
  }
  // the energy dissipated in zone i by the slip dh of the state: d_i int_band p dh dx =
  // d_i int_band Pbar dh' (Pbar: the pressure's integral from the point to the edge)
  T energy(int i, const T &e1, const T &e2, int d1, int d2, dhp_memo *mm = nullptr) const {
    const int d = i == 1 ? d1 : d2;
    if (d == 0) return T(0);
    const T lo = i == 1 ? e1 : T(-1), hi = i == 1 ? T(1) : -e2;
    if (!(hi > lo)) return T(0);
    // (int from xi to the edge of p)
    auto pbar = [&](const T &xi) { return i == 1 ? p_integral(xi, T(1)) : p_integral(T(-1), xi); };
    // (cusps holds the pressure's breakpoints)
    const auto c = cuts(lo, hi, nullptr);
    const std::vector<T> *kept = mm && mm->nodes[i - 1].size() == (c.size() - 1) * gauss_legendre<T>(24)->x.size()
                                     ? &mm->nodes[i - 1] : nullptr;
    size_t q = 0;
    const T s = theta_int(c, [&](const T &xi) { return pbar(xi) * (kept ? (*kept)[q++] : dhp(xi, e1, e2, d1, d2, mm)); });
    // zone 2: dh' integrates to dh from the end leftwards with dh = -int, so p dh = Pbar (-dh')
    return T(d) * (i == 1 ? s : -s);
  }
};

}}  // namespace hs::core
