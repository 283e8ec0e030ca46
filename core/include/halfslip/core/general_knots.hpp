// halfslip core, general pressures (general.hpp): the zone energies and slips
// of a model with very many knots (the sampled pressure from knot_tree_min
// samples on, knots.hpp) at a cost linear in the knot count (issue 13 item 4).
//
// The discretisation is that of general_post.hpp (the fixed-rule energies and
// slips): panels in theta with an end at every knot of the zone and the
// grading points towards theta = 0; outer rule of order M_p and inner rule of
// order M_p + 1 on every panel (interlacing on the own zone, so that the
// principal-value quotient never sees a near-zero denominator); h' at the
// outer nodes from Cauchy sums over the inner nodes of both zones; the tail
// cumulated on the outer nodes. Two changes make it linear:
//  - the order of a panel falls with its distance from the two points where
//    the integrands are not analytic (theta = 0, with the near singularity at
//    i asinh(sqrt(e/d)), and theta = pi/2, where the tail goes like
//    cos^3): a panel of length L at distance D has rho = z + sqrt(z^2 - 1),
//    z = 1 + 2 D/L, and takes M_p = ceil(M ln(rho_0)/ln(rho)) >= 2, rho_0 =
//    3 + sqrt(8) (D = L, the geometric grading), so that its Gauss error
//    ~rho^-2M_p stays below the reference panels' at M. A knot segment far
//    inside the zone (n = 10^6: L/D ~ 1e-6) takes 2 or 3 points. M doubles
//    every order, so the energies' order control (by_order) still compares
//    two refined results everywhere.
//  - the double sum over outer and inner nodes becomes a fast multipole sum
//    (fmm1d.hpp) in the signed distance y from the target zone's stick edge
//    (own zone y = d s^2, other zone y = -(e + d' s'^2)): the own-zone sum
//    sum_i w_i (H_i - H_j)/(y_i - y_j) as sum w H/(y_i - y_j) - H_j sum
//    w/(y_i - y_j) far apart, and with the subtraction, in the accurate
//    denominator of general_post.hpp, between neighbouring leaves.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <boost/math/tools/precision.hpp>

#include "fmm1d.hpp"
#include "gauss.hpp"
#include "general_panels.hpp"
#include "knots.hpp"
#include "numerics.hpp"
#include "pressure.hpp"

namespace hs { namespace core { namespace gdetail {

template <class T> struct kpanel {
  T lo, hi;         // theta range
  std::size_t seg;  // knot segment of the view it lies on
  int order;        // outer order (the inner rule has order + 1)
};

// Panels of zone `side` (length d next to a stick zone of length e) in theta:
// an end at every knot, the grading points of make_panels towards theta = 0
// and the optional cut; in increasing theta, O(knots in the zone).
template <class T>
std::vector<kpanel<T>> knot_panels(const knot_view<T> &kv, int side, const T &d, const T &e, int M,
                                   const T *cut = nullptr) {
  using std::asin;
  using std::asinh;
  using std::ceil;
  using std::log;
  using std::sqrt;
  std::vector<kpanel<T>> out;
  if (!(d > 0)) return out;
  const T half_pi = pi<T>() / 2;
  // distance of t from the zone's stick edge without cancellation (as zone_integrals_knots)
  const T zlo = side > 0 ? T(1 - d) : T(-1), zhi = side > 0 ? T(1) : T(d - 1);
  auto theta = [&](const T &t) -> T {
    T dist;
    if (side > 0) dist = d >= T(0.5) ? T(t - zlo) : T((t - 1) + d);
    else dist = d >= T(0.5) ? T(zhi - t) : T(d - (1 + t));
    const T s2 = dist / d;
    if (!(s2 > 0)) return T(0);
    if (!(s2 < 1)) return half_pi;
    return asin(sqrt(s2));
  };
  std::vector<T> extra;  // grading points and the cut, ascending
  {
    const T epsr = sqrt(e / d);
    if (epsr < half_pi / 2) {
      T gp = epsr < 1 ? asin(epsr) : epsr;
      const T tiny = sqrt(boost::math::tools::min_value<T>());
      if (gp < tiny) gp = tiny;
      for (; gp < half_pi / 2; gp *= 2) extra.push_back(gp);
    }
    if (cut && *cut > 0 && *cut < half_pi) {
      extra.push_back(*cut);
      std::sort(extra.begin(), extra.end());
    }
  }
  // the near singularity's distance from the real axis, and the order rule:
  // the smallest k >= 2 with rho^-2k below both the reference panels' error at
  // M, rho_0^-2M, and eps/1000 (each panel's relative error; they add up to
  // that of the energy at most)
  const T sing = asinh(sqrt(e / d));
  const T lr0 = log(3 + sqrt(T(8)));
  const T lfloor = -log(eps<T>()) + log(T(1000));  // ln(1000/eps)
  const T ltarget = std::min(T(2 * M * lr0), lfloor);
  // A knot where phi'' jumps by J puts a pole of residue ~J delta^2/2 into the
  // principal-value quotient on the neighbouring panel (delta: the target's
  // distance from the knot, ~L/k^2 for the outer nodes next to it), which a
  // rule of order k integrates to ~J delta^2 ~ J L^2/k^4 relative to phi at
  // those nodes; their weights, ~L/k^2, make it ~J L^2/k^6 of the panel's part
  // of the energy (the outer rule's error from the (t - knot)^2 log|t - knot|
  // the knot puts into h' is smaller). A panel whose knots would make that
  // exceed 1e-13 at order k (data rough on the panel's scale) takes the order
  // that brings it there, at most M (and from M on, the energies' order control
  // checks it).
  auto order_of = [&](const T &lo, const T &hi, const T &r) {
    const T L = hi - lo;
    const T D = std::min(T(sqrt(lo * lo + sing * sing)), T(half_pi - hi));
    const T z = 1 + 2 * D / L;
    if (!(z > 3)) return M;
    const T rho = z + sqrt((z - 1) * (z + 1));
    const int k = std::max(2, int(ceil(ltarget / (2 * log(rho)))));
    if (r > T(1e-13) * k * k * k * k * k * k) {
      using std::pow;
      // (compared as T: for rough enough data the order exceeds every int, issue 13
      // fuzzing, tests/fuzz/corpus/samples/crash-rough-order-overflow)
      const T kr = ceil(pow(r / T(1e-13), T(1) / 6));
      if (!(kr < T(M))) return M;
      return std::min(M, std::max(k, int(kr)));
    }
    return std::min(M, k);
  };
  std::size_t ei = 0;
  const std::size_t S = kv.segments();
  // J L^2/|phi| of segment seg: the larger jump at its two knots, its length
  auto roughness = [&](std::size_t seg) {
    using std::abs;
    const T a = kv.end(seg), b = kv.end(seg + 1), L = b - a;
    const T J = std::max(seg > 0 ? kv.jump2(seg) : T(0), seg + 1 < S ? kv.jump2(seg + 1) : T(0));
    if (!(J > 0)) return T(0);
    const T ph = abs(kv.phi(seg, T((a + b) / 2)));
    return J * L * L / ph;
  };
  auto push = [&](const T &lo, const T &hi, std::size_t seg) {
    if (!(hi > lo)) return;
    const T r = roughness(seg);
    T a = lo;
    while (ei < extra.size() && !(extra[ei] > a)) ++ei;
    while (ei < extra.size() && extra[ei] < hi) {
      out.push_back({a, extra[ei], seg, order_of(a, extra[ei], r)});
      a = extra[ei++];
    }
    out.push_back({a, hi, seg, order_of(a, hi, r)});
  };
  if (side > 0) {
    std::size_t s = kv.segment(zlo);
    T prev = T(0);
    for (; s < S; ++s) {
      const T e1 = kv.end(s + 1);
      const T th = e1 >= zhi ? half_pi : theta(e1);
      push(prev, th, s);
      prev = th;
      if (e1 >= zhi) break;
    }
  } else {
    std::size_t s = kv.segment(zhi);
    T prev = T(0);
    for (;;) {
      const T e0 = kv.end(s);
      const T th = e0 <= zlo ? half_pi : theta(e0);
      push(prev, th, s);
      prev = th;
      if (e0 <= zlo || s == 0) break;
      --s;
    }
  }
  return out;
}

// The nodes of one zone on knot panels: outer (order k) or inner (k + 1) rule.
template <class T> struct knot_nodes {
  T d{0};
  std::vector<kpanel<T>> panels;
  std::vector<std::size_t> first;  // first node of each panel (panels.size() + 1 entries)
  std::vector<T> s2, c2, w, H, p, jac;
};

// panels: knot_panels(kv, side, d, e, M, cut) (shared by a zone's outer and inner rules)
template <class T>
knot_nodes<T> make_knot_nodes(const knot_view<T> &kv, int side, const T &d, const T &e,
                              const std::vector<kpanel<T>> &panels, bool inner) {
  using std::sin;
  using std::sqrt;
  knot_nodes<T> z;
  z.d = d;
  if (!(d > 0)) return z;
  z.panels = panels;
  std::size_t N = 0;
  z.first.reserve(z.panels.size() + 1);
  for (const auto &pn : z.panels) {
    z.first.push_back(N);
    N += std::size_t(pn.order + (inner ? 1 : 0));
  }
  z.first.push_back(N);
  z.s2.reserve(N);
  z.c2.reserve(N);
  z.w.reserve(N);
  z.H.reserve(N);
  if (!inner) {
    z.p.reserve(N);
    z.jac.reserve(N);
  }
  const T half_pi = pi<T>() / 2;
  int last = -1;
  std::shared_ptr<const gl_rule<T>> rule;
  for (const auto &pn : z.panels) {
    const int k = pn.order + (inner ? 1 : 0);
    if (k != last) {
      rule = gauss_legendre<T>(k);
      last = k;
    }
    const T L = pn.hi - pn.lo, top = half_pi - pn.hi;
    for (int i = 0; i < k; ++i) {
      const T th = pn.lo + L * (1 + rule->x[i]) / 2, thc = top + L * (1 - rule->x[i]) / 2;
      const T sn = sin(th), cs = sin(thc);
      const T s2 = sn * sn, c2 = cs * cs;
      const zone_point<T> x = zone_point_at(side, d, s2, c2);
      const T ph = kv.phi(pn.seg, x.t);
      z.s2.push_back(s2);
      z.c2.push_back(c2);
      z.w.push_back(L * rule->w[i] / 2);
      z.H.push_back(2 * d * c2 * sqrt(x.far(side)) * ph / sqrt(e + d * s2));
      if (!inner) {
        z.p.push_back(sqrt(x.dm * x.dp) * ph);
        z.jac.push_back(L / 2);
      }
    }
  }
  return z;
}

// h' at the first `count` outer nodes O of zone z (the inner rules IR, IL of
// both zones; slip directions dirR, dirL; stick-zone length e), as
// general_solution::hgrad_nodes, by the fast multipole sum. Nodes: knot_nodes, or
// the panel path's zone_nodes at high orders (general_solution::hgrad_nodes): each
// zone's nodes ascending in sin^2 theta.
template <class T, class Nodes>
std::vector<T> knot_hgrad(int z, const Nodes &O, const Nodes &IR, const Nodes &IL, std::size_t count, int dirR,
                          int dirL, const T &e) {
  using std::sqrt;
  std::vector<T> g(count, T(0));
  if (count == 0) return g;
  const Nodes &own = z > 0 ? IR : IL, &oth = z > 0 ? IL : IR;
  const int dz = z > 0 ? dirR : dirL, doth = z > 0 ? dirL : dirR;
  const bool use_own = dz != 0 && own.d > 0, use_oth = doth != 0 && oth.d > 0;
  // sources in y (signed distance from zone z's stick edge), ascending: the other
  // zone from its contact edge towards the stick zone, then the own zone
  const std::size_t no = use_oth ? oth.s2.size() : 0, nw = use_own ? own.s2.size() : 0;
  std::vector<T> y(no + nw), q0(no + nw), q1(no + nw);
  for (std::size_t k = 0; k < no; ++k) {
    const std::size_t i = no - 1 - k;
    y[k] = -(e + oth.d * oth.s2[i]);
    q0[k] = -T(doth) * oth.w[i] * oth.H[i];
    q1[k] = 0;
  }
  for (std::size_t i = 0; i < nw; ++i) {
    y[no + i] = own.d * own.s2[i];
    q0[no + i] = T(dz) * own.w[i] * own.H[i];
    q1[no + i] = T(dz) * own.w[i];
  }
  std::vector<T> qo(no);  // w H of the other zone's sources, in source order
  for (std::size_t k = 0; k < no; ++k) qo[k] = oth.w[no - 1 - k] * oth.H[no - 1 - k];
  std::vector<T> yt(count), f0(count, T(0)), f1(count, T(0));
  for (std::size_t j = 0; j < count; ++j) yt[j] = O.d * O.s2[j];
  std::vector<T> br(count, T(0));
  if (no + nw > 0) {
    cauchy_fmm<T> fmm(y.data(), y.size(), yt.data(), count, 48);
    const T *q[2] = {q0.data(), q1.data()};
    T *out[2] = {f0.data(), f1.data()};
    fmm.apply(2, q, out, [&](std::size_t ja, std::size_t jb, std::size_t ia, std::size_t ib) {
      // the other zone's sources [ia, min(ib, no)), the own zone's [max(ia, no), ib)
      const std::size_t kb = std::min(ib, no), ka = std::max(ia, no);
      for (std::size_t j = ja; j < jb; ++j) {
        const T sj = O.s2[j], cj = O.c2[j], Hj = O.H[j], u = O.d * sj;
        T so = 0, sw = 0;
        for (std::size_t k = ia; k < kb; ++k) so += qo[k] / (e + u + oth.d * oth.s2[no - 1 - k]);
        // s^2_i - s^2_j from the sines near theta = 0, from the cosines near pi/2
        // (each accurate where it is small); den = 0 only for nodes merged in
        // rounding, whose weights are negligible
        if (ib > ka) {
          const T *sv = sj < T(0.5) ? &own.s2[0] : &own.c2[0];
          const T ref = sj < T(0.5) ? sj : cj, sg = sj < T(0.5) ? T(1) : T(-1);
          for (std::size_t i = ka - no; i < ib - no; ++i) {
            const T den = sg * (sv[i] - ref);
            sw += den != 0 ? own.w[i] * (own.H[i] - Hj) / den : T(0);
          }
        }
        br[j] += T(doth) * so + T(dz) * sw / own.d;
      }
    });
  }
  for (std::size_t j = 0; j < count; ++j) {
    const T u = O.d * O.s2[j];
    g[j] = -2 * sqrt(u * (e + u)) * (br[j] + f0[j] - O.H[j] * f1[j]) / pi<T>();
  }
  return g;
}

}}}  // namespace hs::core::gdetail
