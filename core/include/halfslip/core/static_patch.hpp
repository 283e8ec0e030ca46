// halfslip core: the static solve of an advancing segment whose final stick set is TWO intervals,
// S = (-b2, pl) U (pr, b1), with an interior slip patch (pl, pr) of direction dp between them and
// the edge zones (b1, 1), (-1, -b2) (issue 14; derivation in docs/history.md, "Interior slip zones:
// the two-interval static solve"). The state before the segment is an sh_start (static_state.hpp).
//
// Canonical frame as core/history.hpp: a = p0 = f = E* = 1, q = Q/fP, s = sigma/(f p0),
// int q dx = q pi/2.
//
// Premise (the static argument of the one-interval solve): every point of S was stuck throughout
// the segment, so its slip is unchanged, including the constant; every point of G = (b1, 1) U
// (pl, pr) U (-1, -b2) slipped, one way only, and ends at the limit of its zone's direction:
//     dq = g = d p - q_S on G,
//     (2/pi) PV int dq(xi)/(x - xi) dxi = ds/2 on S,   int dq = dq_load pi/2,   dh(pr) = dh(pl).
// With R(z) = (z - b1)(z + b2)(z - pl)(z - pr) and Y = sqrt(R) ~ z^2 at infinity (cuts on S),
// Y = +sqrt|R| on both bands and -sqrt|R| on the patch; the bounded solution exists iff
//     r0 = (1/pi) int_G g/Y = 0,
//     r1 = ds/4 + (1/pi) int_G g t/Y = 0,
//     r2 = (1/pi) int_G g t^2/Y + ds e1/8 - dq_load/2 = 0,      e1 = b1 - b2 + pl + pr,
//     r3 = -(2/pi) int_G (g/Y)(t) K(t) dt = 0,   K(t) = PV int_patch Y(x)/(t - x) dx,
// and then dq(x) = +-(sqrt|R(x)|/pi) int_G g(t)/(Y(t)(t - x)) dt on S (+ on (pr, b1), - on
// (-b2, pl)). On G the slip gradient change is, as for one interval with Y for X,
//     dh'(x) = -(2/pi) Y(x) PV int_G g(t)/(Y(t)(t - x)) dt
// (Plemelj on two intervals: Omega = Phi - i ds/8 has Omega/Y = the Cauchy integral of g/Y over G,
// no polynomial, since Y ~ z^2 and Omega -> -i ds/8). Checked against the reference oracle
// (reference/patch_oracle.hpp, which shares no code) and the BEM in tests/test_static_patch.cpp.
//
// A zero-width patch solves the four conditions to O(width^2) wherever the one-interval traction
// touches dp p (a spurious root): solve() refuses a patch narrower than 1e-6 of the stick zone.
// The energies are those of one-way slip, d int_zone p dh from the end state alone; the caller
// checks the premise (one_way here; the ends nested along the segment, static_history).
//
// Quadrature: Gauss-Legendre on theta panels, x = l + (r - l) sin^2(theta/2) (square-root
// behaviour at every piece end: 1/Y at a root, p at +-1, q_S at a memory point), the pieces of G
// cut at the start state's cusps, graded geometrically towards an end that lies near a root of R
// outside the piece or near the point x of a kernel 1/(t - x). Node sets are kept by grading
// (one object per ends: not for use by two threads at once; copies are independent).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include <Eigen/Dense>
#include <boost/math/special_functions/fpclassify.hpp>

#include "gauss.hpp"
#include "numerics.hpp"
#include "static_state.hpp"
#include "status.hpp"

namespace hs { namespace core {

// the stick set (-b2, pl) U (pr, b1) of a state with an interior slip patch (pl, pr)
template <class T> struct sh_patch_ends {
  T b1{1}, b2{1}, pl{0}, pr{0};
  T &at(int j) { return j == 0 ? b1 : (j == 1 ? b2 : (j == 2 ? pl : pr)); }
  const T &at(int j) const { return j == 0 ? b1 : (j == 1 ? b2 : (j == 2 ? pl : pr)); }
};

template <class T> class sh_patch {
 public:
  using ends = sh_patch_ends<T>;
  // st: the state before the segment; dq, ds: the segment's load increments; d1, d2, dp: the
  // directions of zone 1, zone 2 and the patch (+-1); order: Gauss order per theta panel
  sh_patch(std::shared_ptr<const sh_start<T>> st, const T &dq, const T &ds, int d1, int d2, int dp, int order = 24)
      : st_(std::move(st)), dq_(dq), ds_(ds), d_{{d1, d2, dp}}, rule_(gauss_legendre<T>(order)) {
    if (!st_) throw error(status::null_pointer, "sh_patch: no start state");
  }
  const sh_start<T> &start() const { return *st_; }
  int dir(int zone) const { return d_[zone - 1]; }  // zone 1, 2, 3 (the patch)
  const ends &solved() const { return e_; }

  // the four conditions at the ends e
  std::array<T, 4> residual(const ends &e) const {
    const T pi_ = pi<T>();
    set_ends(e);
    T m0 = 0, m1 = 0, m2 = 0;
    for (int k = 0; k < int(pcs_.size()); ++k)
      for_nodes(k, base_[k][0], base_[k][1], [&](const gnode &n) {
        m0 += n.gy;
        m1 += n.gy * n.x;
        m2 += n.gy * n.x * n.x;
      });
    const T e1 = e.b1 - e.b2 + e.pl + e.pr;
    // (r3 over the patch's width squared: r3 = O(width^2) on the spurious branch, which is then no
    // root; Newton from a patch inside the true one fell onto it, Hertz reproducer)
    const T w = e.pr - e.pl;
    return {{m0 / pi_, ds_ / 4 + m1 / pi_, m2 / pi_ + ds_ * e1 / 8 - dq_ / 2, -2 / pi_ * jump() / (w * w)}};
  }

  // Newton from e on the four conditions (central differences, a line search keeping the ends in
  // order); true with e_ = e the root, false if it does not settle, leaves the order of the ends,
  // or collapses the patch below 1e-6 of the stick zone (the spurious root)
  // (J0: a Jacobian to start from, e.g. that of the same solve at a nearby load: kept while the
  // residual falls fourfold a step, else made again by differences)
  bool solve(ends e, int max_it = 60, const Eigen::Matrix<T, 4, 4> *J0 = nullptr) {
    if (frozen_) throw error(status::internal, "sh_patch: solved already");
    using boost::math::isfinite;
    using std::abs;
    using std::cbrt;
    using std::sqrt;
    const T h = cbrt(eps<T>());
    T last = -1, first = -1;
    auto norm = [](const std::array<T, 4> &r) {
      T s = 0;
      for (const T &v : r) s += v * v;
      return sqrt(s);
    };
    Eigen::Matrix<T, 4, 4> J;
    bool refresh = J0 == nullptr;
    if (J0) J = *J0;
    if (!ordered(e)) return false;
    std::array<T, 4> r = residual(e);
    for (int it = 0; it < max_it; ++it) {
      const T n0 = norm(r);
      if (!isfinite(n0)) return false;
      if (first < 0) first = n0;
      const bool fresh = refresh;
      if (fresh) {
        for (int j = 0; j < 4; ++j) {
          // (the residuals have a kink where an end crosses a memory point of the start state: the
          // difference stays on the end's side of it, within a quarter of its distance; a patch end
          // 1.3e-5 from one converged linearly with h = eps^(1/3), Hertz walk 41, vertex 9)
          const T x = j == 1 ? -e.b2 : e.at(j);
          T hj = h;
          for (const T &c : st_->cusps)
            if (c != x) hj = std::min(hj, abs(x - c) / 4);
          hj = std::max(hj, T(1e-2) * sqrt(eps<T>()));
          ends ep = e, em = e;
          ep.at(j) += hj;
          em.at(j) -= hj;
          const auto rp = residual(ep), rm = residual(em);
          for (int i = 0; i < 4; ++i) J(i, j) = (rp[i] - rm[i]) / (2 * hj);
        }
      }
      Eigen::Matrix<T, 4, 1> F;
      for (int i = 0; i < 4; ++i) F(i) = r[i];
      const Eigen::Matrix<T, 4, 1> dx = J.fullPivLu().solve(F);
      bool fin = true;
      for (int j = 0; j < 4; ++j) fin = fin && isfinite(dx(j));
      if (!fin) {
        if (fresh) return false;
        refresh = true;
        continue;
      }
      T lam = 1, nt = 0;
      bool moved = false;
      for (int k = 0; k < 40; ++k, lam /= 2) {
        ends t = e;
        for (int j = 0; j < 4; ++j) t.at(j) -= lam * dx(j);
        if (!ordered(t)) continue;
        const auto rt = residual(t);
        nt = norm(rt);
        if (nt < n0 || (fresh && lam < T(1) / 1024)) {
          e = t;
          r = rt;
          moved = true;
          break;
        }
        if (!fresh && lam < T(1) / 16) break;  // (an old Jacobian: make a new one first)
      }
      if (!moved) {
        if (fresh) return false;
        refresh = true;
        continue;
      }
      T stp = 0;
      for (int j = 0; j < 4; ++j) stp = std::max(stp, abs(lam * dx(j)));
      // converged: a step at rounding, or (with a new Jacobian) steps that stopped halving below the
      // quadrature's floor
      if (stp < T(512) * eps<T>() || (fresh && stp < T(1e-2) * sqrt(eps<T>()) && last >= 0 && stp > last / 2)) {
        if (!(e.pr - e.pl >= T(1e-6) * (e.b1 + e.b2))) return false;  // the spurious zero-width root
        // (small steps are not a root: slow linear convergence with the line search's last resort
        // stopped at residuals of 1e-5 on a 2.6e-4-wide patch, a review's random walk)
        if (!(norm(r) <= T(1e6) * eps<T>() * std::max(T(1), first))) return false;
        e_ = e;
        J_ = J;
        set_ends(e_);
        frozen_ = true;
        // (the node sets of the solved ends are in cache_; the pieces' geometry of the search is
        // not needed after it: kept, it was ~6 times cache_'s memory per patch, a review's find)
        geo_.clear();
        return true;
      }
      refresh = !(nt <= n0 / 4);
      last = stp;
    }
    return false;
  }
  // the last Jacobian of a solve that succeeded (to start a solve at a nearby load)
  const Eigen::Matrix<T, 4, 4> &jacobian() const { return J_; }

  // ---- the state at the solved ends -------------------------------------------------------------
  // (the queries below need solve() to have succeeded)
  // which set x lies in: 1, 2 (edge zones), 3 (the patch), 0 (stick)
  int where(const T &x) const {
    if (x > e_.b1) return 1;
    if (x < -e_.b2) return 2;
    if (x > e_.pl && x < e_.pr) return 3;
    return 0;
  }
  // the traction of the state after the segment
  T traction(const T &x) const {
    const int z = where(x);
    if (z != 0) return T(d_[z - 1]) * st_->pm->p(x);
    return st_->traction(x) + dq_stick(x);
  }
  // dq(x) on the stick set
  T dq_stick(const T &x) const {
    using std::abs;
    using std::sqrt;
    set_ends(e_);
    T s = 0;
    for (int k = 0; k < int(pcs_.size()); ++k) {
      const auto &P = pcs_[k];
      int kl = base_[k][0], kr = base_[k][1];
      if (x < P.l) kl = std::max(kl, shdetail::grade_level(P.l - x, P.r - P.l));
      if (x > P.r) kr = std::max(kr, shdetail::grade_level(x - P.r, P.r - P.l));
      for_nodes(k, kl, kr, [&](const gnode &n) { s += n.gy / (n.x - x); });
    }
    const T R = (e_.b1 - x) * (x + e_.b2) * (x - e_.pl) * (x - e_.pr);
    return T(x < e_.pl ? -1 : 1) * sqrt(abs(R)) / pi<T>() * s;
  }
  // dh'(x), x in G
  T dhp(const T &x) const {
    using std::abs;
    using std::sqrt;
    set_ends(e_);
    const int z = where(x);
    if (z == 0) return T(0);
    T K = 0;
    for (int k = 0; k < int(pcs_.size()); ++k) {
      const auto &P = pcs_[k];
      if (x > P.l && x < P.r) {
        K += pv_own(P, x);
        continue;
      }
      int kl = base_[k][0], kr = base_[k][1];
      if (x <= P.l) kl = std::max(kl, shdetail::grade_level(P.l - x, P.r - P.l));
      if (x >= P.r) kr = std::max(kr, shdetail::grade_level(x - P.r, P.r - P.l));
      for_nodes(k, kl, kr, [&](const gnode &n) {
        const T d = n.x - x;
        if (d != 0) K += n.gy / d;
      });
    }
    return -2 / pi<T>() * y_at(z, x) * K;
  }
  // the slip change at x over the segment (0 on the stick set)
  T dh(const T &x) const {
    const int z = where(x);
    if (z == 0) return T(0);
    const T lo = z == 1 ? e_.b1 : (z == 2 ? x : e_.pl), hi = z == 2 ? -e_.b2 : x;
    const T s = sh_start<T>::theta_int(st_->cuts(lo, hi, nullptr), [&](const T &t) { return dhp(t); });
    return z == 2 ? -s : s;
  }
  // every point of zone z slipped in its direction (d dh >= 0, to rounding) at the cuts of the
  // zone and sub equal parts of each piece between them
  bool one_way(int z, int sub = 2) const {
    using std::abs;
    const T lo = z == 1 ? e_.b1 : (z == 2 ? T(-1) : e_.pl), hi = z == 1 ? T(1) : (z == 2 ? -e_.b2 : e_.pr);
    const auto f = sh_start<T>::subdivided(st_->cuts(lo, hi, nullptr), sub);
    const size_t n = f.size() - 1;
    std::vector<T> h;
    T run = 0, big = 0;
    for (size_t k = 0; k < n; ++k) {  // from the stick end outwards (zone 2: leftwards)
      const size_t j = z == 2 ? n - 1 - k : k;
      const T part = sh_start<T>::theta_int({f[j], f[j + 1]}, [&](const T &t) { return dhp(t); });
      run += z == 2 ? -part : part;
      h.push_back(run);
      big = std::max(big, abs(run));
    }
    const T d = T(d_[z - 1]);
    // (the patch: dh returns to 0 at pr, the last value is that residual, not a slip)
    for (size_t k = 0; k < h.size(); ++k) {
      if (z == 3 && k + 1 == h.size()) continue;
      if (!(d * h[k] >= -(T(1e-9) * big + T(1e-15)))) return false;  // (NaN: not one way)
    }
    return true;
  }
  // the energy dissipated in zone z over the segment, one-way slip: d int_zone p dh dx =
  // d int_zone Pbar dh' (Pbar: p integrated from the point to the zone's outer end; zone 2: from
  // the edge to the point, with the sign of dh = -int)
  T energy(int z) const {
    const T lo = z == 1 ? e_.b1 : (z == 2 ? T(-1) : e_.pl), hi = z == 1 ? T(1) : (z == 2 ? -e_.b2 : e_.pr);
    if (!(hi > lo)) return T(0);
    auto pbar = [&](const T &xi) { return z == 2 ? st_->p_integral(T(-1), xi) : st_->p_integral(xi, hi); };
    const T s = sh_start<T>::theta_int(st_->cuts(lo, hi, nullptr), [&](const T &xi) { return pbar(xi) * dhp(xi); });
    return T(d_[z - 1]) * (z == 2 ? -s : s);
  }

 private:
  struct piece {
    int zone;
    T l, r;
  };
  struct gnode {
    T x, gy;  // x, g(x) w / Y(x)
  };
  struct geo_node {
    T x, dl, dr, gw;  // x, its distances to the piece's ends, g(x) w
  };
  bool ordered(const ends &e) const {
    return e.b1 <= 1 && e.b2 <= 1 && e.pr > e.pl && e.b1 > e.pr && -e.b2 < e.pl;
  }
  T g(int zone, const T &x) const {
    const T px = st_->pm->p(x);
    const auto &ST = *st_;
    return T(d_[zone - 1]) * px -
           shdetail::state_traction(ST.panels, *ST.rule, ST.b1, ST.b2, ST.s1, ST.s2, x, [&] { return px; });
  }
  // Y at x of zone z (1, 2: +sqrt|R|, 3: -sqrt|R|)
  T y_at(int z, const T &x) const {
    using std::abs;
    using std::sqrt;
    const T R = (x - ce_.b1) * (x + ce_.b2) * (x - ce_.pl) * (x - ce_.pr);
    return T(z == 3 ? -1 : 1) * sqrt(abs(R));
  }
  T g_over_y(int z, const T &x) const { return g(z, x) / y_at(z, x); }
  // PV int over piece P of (g/Y)(t) / (t - x), x inside it, on the cuts of P about x, with Y from
  // each node's exact distance to P's own ends (as make_nodes): a node next to a root of R at P's
  // end, in a piece of a few 1e-12 about an x that close to it, rounds onto the root, and Y from
  // x - root was 0 (an infinite energy for a patch end 4.5e-7 from a memory point,
  // bench/periodic_survey.py case 30)
  T pv_own(const piece &P, const T &x) const {
    using std::abs;
    using std::sqrt;
    const T roots[4] = {ce_.b1, -ce_.b2, ce_.pl, ce_.pr};
    const T sg = T(P.zone == 3 ? -1 : 1);
    auto f = [&](const T &eta, const T &end, const T &dist) {
      T R = 1;
      for (const T &rt : roots) R *= rt == end ? dist : abs(eta - rt);
      return g(P.zone, eta) / (sg * sqrt(R));
    };
    return shdetail::pv_pieces(st_->cuts(P.l, P.r, &x), f, x, true);
  }

  // the pieces of G at the ends e, and each piece end's grading for a root of R close outside it
  void set_ends(const ends &e) const {
    if (have_ && e.b1 == ce_.b1 && e.b2 == ce_.b2 && e.pl == ce_.pl && e.pr == ce_.pr) return;
    if (frozen_) throw error(status::internal, "sh_patch: the ends of a solved patch are fixed");
    ce_ = e;
    have_ = true;
    cache_.clear();
    ++gen_;
    for (auto it = geo_.begin(); it != geo_.end();) it = it->second.first + 3 < gen_ ? geo_.erase(it) : std::next(it);
    pcs_.clear();
    base_.clear();
    auto add = [&](int z, const T &l, const T &r) {
      if (!(r > l)) return;
      const auto c = st_->cuts(l, r, nullptr);  // (cusps within rounding of each other are one)
      for (size_t k = 0; k + 1 < c.size(); ++k) pcs_.push_back({z, c[k], c[k + 1]});
    };
    add(1, e.b1, T(1));
    add(3, e.pl, e.pr);
    add(2, T(-1), -e.b2);
    const T roots[4] = {e.b1, -e.b2, e.pl, e.pr};
    for (const auto &P : pcs_) {
      T Dl = 4, Dr = 4;
      for (const T &rt : roots) {
        if (rt < P.l) Dl = std::min(Dl, P.l - rt);
        if (rt > P.r) Dr = std::min(Dr, rt - P.r);
      }
      base_.push_back({{shdetail::grade_level(Dl, P.r - P.l), shdetail::grade_level(Dr, P.r - P.l)}});
    }
    // the patch kernel's Chebyshev points (second kind) and m(x) = sqrt((b1 - x)(x + b2)) there
    using std::cos;
    using std::sin;
    using std::sqrt;
    const int nk = 64;
    ku_.assign(nk, T(0));
    kw_.assign(nk, T(0));
    km_.assign(nk, T(0));
    const T mid = (e.pl + e.pr) / 2, hw = (e.pr - e.pl) / 2, pi_ = pi<T>();
    for (int k = 1; k <= nk; ++k) {
      const T ph = T(k) * pi_ / T(nk + 1);
      ku_[k - 1] = mid + hw * cos(ph);
      kw_[k - 1] = pi_ / T(nk + 1) * sin(ph) * sin(ph);
      km_[k - 1] = sqrt((e.b1 - ku_[k - 1]) * (ku_[k - 1] + e.b2));
    }
  }
  // the nodes of piece k graded kl, kr levels towards its left and right ends: kept while the
  // ends are sought; once solved, only the sets made by then are kept (read-only: the queries of
  // a solved object may run in several threads) and others are made for the call
  template <class F> void for_nodes(int k, int kl, int kr, F &&f) const {
    const auto key = std::make_tuple(k, kl, kr);
    const auto it = cache_.find(key);
    if (it != cache_.end()) {
      for (const auto &n : it->second) f(n);
      return;
    }
    if (!frozen_) {
      auto &v = cache_[key];
      make_nodes(k, kl, kr, v);
      for (const auto &n : v) f(n);
      return;
    }
    std::vector<gnode> v;
    make_nodes(k, kl, kr, v);
    for (const auto &n : v) f(n);
  }
  void make_nodes(int k, int kl, int kr, std::vector<gnode> &v) const {
    using std::abs;
    using std::sqrt;
    v.clear();
    const auto &P = pcs_[k];
    const T roots[4] = {ce_.b1, -ce_.b2, ce_.pl, ce_.pr};
    std::vector<geo_node> local;
    const auto &G = geometry(P, kl, kr, local);
    v.reserve(G.size());
    for (const auto &n : G) {
      // sqrt|R| with the exact distances to the piece's own ends
      T R = 1;
      for (const T &rt : roots) R *= rt == P.l ? n.dl : (rt == P.r ? n.dr : abs(n.x - rt));
      const T Y = T(P.zone == 3 ? -1 : 1) * sqrt(R);
      v.push_back({n.x, n.gw / Y});
    }
  }
  // the nodes of piece P graded kl, kr levels towards its ends, with g w (w: the weight of the
  // theta map) and their distances to the piece's ends. They depend on the piece alone, not on the
  // other ends, so they are kept across the residuals of a solve (a Jacobian's differences move one
  // end, and most pieces stay; g was most of a patch segment's time); entries unused for three sets
  // of ends are dropped (set_ends). A solved object only reads them (a set not kept is made in local).
  const std::vector<geo_node> &geometry(const piece &P, int kl, int kr, std::vector<geo_node> &local) const {
    using std::cos;
    using std::sin;
    const auto key = std::make_tuple(P.zone, P.l, P.r, kl, kr);
    const auto it = geo_.find(key);
    if (it != geo_.end()) {
      if (!frozen_) it->second.first = gen_;
      return it->second.second;
    }
    std::vector<geo_node> *out = &local;
    if (!frozen_) {
      auto &e = geo_[key];
      e.first = gen_;
      out = &e.second;
    }
    auto &v = *out;
    v.clear();
    const T l = P.l, r = P.r, L = r - l, pi_ = pi<T>();
    std::vector<T> br{0};
    for (int m = kl; m >= 1; --m) br.push_back(pi_ / 2 * T(std::ldexp(1.0, -m)));
    br.push_back(pi_ / 2);
    for (int m = 1; m <= kr; ++m) br.push_back(pi_ - pi_ / 2 * T(std::ldexp(1.0, -m)));
    br.push_back(pi_);
    const auto &gr = *rule_;
    for (size_t j = 0; j + 1 < br.size(); ++j) {
      const T hw = (br[j + 1] - br[j]) / 2, mid = (br[j + 1] + br[j]) / 2;
      for (size_t i = 0; i < gr.x.size(); ++i) {
        const T th = mid + hw * gr.x[i], s = sin(th / 2), c = cos(th / 2);
        const T dl = L * s * s, dr = L * c * c;
        const T x = dl <= dr ? l + dl : r - dr;
        v.push_back({x, dl, dr, g(P.zone, x) * hw * gr.w[i] * L * s * c});
      }
    }
    return v;
  }
  // int_G (g/Y)(t) K(t) dt, K(t) = PV int_patch Y(x)/(t - x) dx (Gauss-Chebyshev of the second
  // kind on the patch, Y = -sqrt((x - pl)(pr - x)) m(x); the PV's singular part in closed form)
  T jump() const {
    const T mid = (ce_.pl + ce_.pr) / 2, hw = (ce_.pr - ce_.pl) / 2, pi_ = pi<T>();
    T J = 0;
    for (int k = 0; k < int(pcs_.size()); ++k) {
      const bool patch = pcs_[k].zone == 3;
      for_nodes(k, base_[k][0], base_[k][1], [&](const gnode &n) {
        T s = 0;
        if (patch) {
          using std::sqrt;
          const T mt = sqrt((ce_.b1 - n.x) * (n.x + ce_.b2));
          for (size_t j = 0; j < ku_.size(); ++j) s += kw_[j] * (km_[j] - mt) / (n.x - ku_[j]);
          s = hw * hw * s + mt * pi_ * (n.x - mid);
        } else {
          for (size_t j = 0; j < ku_.size(); ++j) s += kw_[j] * km_[j] / (n.x - ku_[j]);
          s *= hw * hw;
        }
        J += n.gy * (-s);
      });
    }
    return J;
  }

  std::shared_ptr<const sh_start<T>> st_;
  T dq_, ds_;
  std::array<int, 3> d_;
  std::shared_ptr<const gl_rule<T>> rule_;
  ends e_{};
  Eigen::Matrix<T, 4, 4> J_ = Eigen::Matrix<T, 4, 4>::Zero();
  mutable ends ce_{};
  mutable bool have_ = false;
  bool frozen_ = false;  // solved: the ends fixed, the node sets read-only
  mutable std::vector<piece> pcs_;
  mutable std::vector<std::array<int, 2>> base_;
  mutable std::map<std::tuple<int, int, int>, std::vector<gnode>> cache_;
  mutable std::vector<T> ku_, kw_, km_;
  // the node sets of the pieces (geometry()) and the set of ends each was last used for
  mutable std::map<std::tuple<int, T, T, int, int>, std::pair<long, std::vector<geo_node>>> geo_;
  mutable long gen_ = 0;
};

}}  // namespace hs::core
