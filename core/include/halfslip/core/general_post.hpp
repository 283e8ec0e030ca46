// halfslip core, general pressures (general.hpp): the solution and its
// post-processing: Cauchy integrals, slips and zone energies (fixed-rule and
// adaptive reference evaluations), traction and pressure.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>
#include <vector>

#include "frame.hpp"
#include "gauss.hpp"
#include "general_expansion.hpp"
#include "general_knots.hpp"
#include "general_panels.hpp"
#include "general_residual.hpp"
#include "hertz.hpp"
#include "numerics.hpp"
#include "pressure.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> class general_solution : public canonical_solution<general_solution<T>, T, general_scene<T>> {
 public:
  using base = canonical_solution<general_solution<T>, T, general_scene<T>>;
  using base::beta1;
  using base::beta2;
  using base::delta1;
  using base::delta2;
  using base::dirL;
  using base::dirR;
  using base::iterations;
  using base::locate;
  using base::mirror;
  using base::negate;
  using base::reg;
  using base::rtol;
  using base::scene;
  using base::sign;
  using base::width;
  int continuation_steps = 0;
  int order = 0;  // Gauss-Legendre order per panel of the accepted residual
  // the zone lengths' sensitivity to the residuals' tolerance, units of a (general_solver.hpp)
  T conditioning = 0;
  // ln(width) (issue 13): below tiny_width() the width may underflow to 0, and
  // every zone quantity is continued linearly in ln(width) from the widths
  // tiny_width() and tiny_width_b() (general_residual.hpp)
  T log_width = 0;
  bool at_given_width = false;  // the two evaluations of continued(): no continuation
  bool point_stick() const { return !at_given_width && reg != regime::stuck && width < tiny_width<T>(); }
  // f(solution) continued to log_width from the two widths of the point-stick limit
  template <class F> T continued(const F &f) const {
    using std::log;
    general_solution a = *this, b = *this;
    a.width = tiny_width<T>();
    b.width = tiny_width_b<T>();
    a.at_given_width = b.at_given_width = true;
    a.expansion_ = b.expansion_ = nullptr;  // the expansion is the given width's
    const T la = log(a.width), lb = log(b.width);
    const T fa = f(a), fb = f(b);
    return fa + (log_width - la) / (la - lb) * (fa - fb);
  }
  int max_order = 1024;  // largest order of the energies and slips (general_options::max_order)
  // The relative error of the zone energies that the caller's error estimate already
  // carries from the state (select.hpp, quadrature_estimate; 0: none): the orders of
  // the fixed rules need agree only to a 32nd of it (energy_hat_fixed). Issue 13: a flat
  // punch at 1 - b_f/a = 2e-6, Q/fP = 1 - 4e-6, whose state is good to ~1e-7, has zone
  // energies whose orders 64 to 1024 scatter by 3e-11 of the value (the rounding of the
  // Cauchy sums next to the sharp corner): "no two orders agreed", and no answer.
  T state_rtol = 0;
  std::shared_ptr<const pressure_model<T>> owned;  // mirrored view, if any
  const pressure_model<T> *pm = nullptr;           // canonical pressure (must outlive)

  T quad_tol() const {
    using std::cbrt;
    const T c = cbrt(eps<T>());
    return c * c;  // tanh-sinh converges quadratically: far below this in practice
  }

  // C_Z(xi) on the knot path (a model with a knot quadrature, knots.hpp): the
  // tree's product rules where the kernel p_hat/(R (t - xi)) is smooth, i.e. on
  // nodes at least twice their length from the stick edges, +-1 and xi; the
  // segments next to them in theta as cauchy() below (tanh-sinh per piece; on
  // the own zone the principal value by subtraction of H(theta_x), with the
  // closed form (1/sin 2theta_x) log|sin(theta - theta_x)/sin(theta + theta_x)|
  // of PV int dtheta/(sin^2 theta - sin^2 theta_x) per piece). pz = 0: xi in
  // the stick zone at distances dl from beta1 and dl2 from -beta2 (the shear
  // traction there).
  T cauchy_knots(const knot_view<T> &kv, int zside, int pz, const T &dl, const T &dl2 = T(0)) const {
    using std::abs;
    using std::asin;
    using std::log;
    using std::sin;
    using std::sqrt;
    const T d = zside > 0 ? delta1 : delta2;
    if (!(d > 0)) return T(0);
    const T e = width, half_pi = pi<T>() / 2;
    const int Z = zside;
    const T zlo = Z > 0 ? T(1 - d) : T(-1), zhi = Z > 0 ? T(1) : T(d - 1);
    auto dist = [&](const T &t) -> T {  // from Z's stick edge, without cancellation
      if (Z > 0) return d >= T(0.5) ? T(t - zlo) : T((t - 1) + d);
      return d >= T(0.5) ? T(zhi - t) : T(d - (1 + t));
    };
    // |t - xi| as A + off (xi outside Z), or A - dl (own zone, signed)
    const bool own = pz == Z;
    const T off = pz == -Z ? T(e + dl) : (pz == 0 ? (Z > 0 ? dl : dl2) : T(0));
    const T sgn = Z > 0 ? T(1) : T(-1);  // sign of t - xi off the own zone
    // xi's position (for the admissibility test only)
    const T xi = pz > 0 ? T(beta1 + dl) : (pz < 0 ? T(-beta2 - dl) : T(beta1 - dl));
    const T own_edge = Z > 0 ? zlo : zhi, other_edge = Z > 0 ? T(zlo - e) : T(zhi + e);
    const T sing[5] = {own_edge, other_edge, T(-1), T(1), xi};
    auto adm = [&](const T &a, const T &b) {
      const T lim = knot_quadrature<T>::eta() * (b - a);
      for (const T &sg : sing) {
        const T dd = sg < a ? T(a - sg) : (sg > b ? T(sg - b) : T(0));
        if (!(dd >= lim)) return false;
      }
      return true;
    };
    T sum = 0;
    auto emit = [&](const T &t, const T &w) {
      const T A = dist(t);
      const T diff = own ? T(sgn * (A - dl)) : T(sgn * (A + off));
      sum += w * sqrt((1 + t) * (1 - t) / (A * (A + e))) / diff;
    };
    std::vector<std::pair<T, T>> pieces;
    kv.cover(zlo, zhi, adm, emit, [&](const T &a, const T &b) { pieces.push_back({a, b}); });
    auto theta = [&](const T &t) -> T {
      if (t == own_edge) return T(0);
      if (t == (Z > 0 ? zhi : zlo)) return half_pi;
      const T s2 = dist(t) / d;
      if (!(s2 > 0)) return T(0);
      if (!(s2 < 1)) return half_pi;
      return asin(sqrt(s2));
    };
    auto H = [&](const T &th, const T &thc) {
      const T sn = sin(th), cs = sin(thc);
      const T s2 = sn * sn, c2 = cs * cs;
      const gdetail::zone_point<T> x = gdetail::zone_point_at(Z, d, s2, c2);
      return 2 * d * c2 * sqrt(x.far(Z)) * pm->phi(x.t, x.dm, x.dp) / sqrt(e + d * s2);
    };
    // Gauss-Legendre of order 20 on panels graded geometrically towards theta = 0,
    // from the near singularities at i sqrt(e/d) (H) and i sqrt(off/d) (the
    // kernel off the own zone), and split at theta_x: every panel is at least
    // its own length from a singularity (error < 1e-16, as the field panels)
    const auto rule = gauss_legendre<T>(20);
    std::vector<T> grade;
    for (const T &sc : {e, off}) {
      if (!(sc > 0)) continue;
      const T r = sqrt(sc / d);
      if (!(r < half_pi / 2)) continue;
      T gp = r < 1 ? asin(r) : r;
      const T tiny = sqrt(boost::math::tools::min_value<T>());
      if (gp < tiny) gp = tiny;
      for (; gp < half_pi / 2; gp *= 2) grade.push_back(gp);
    }
    // the target's theta on the own zone, H there
    T thx = 0, thxc = half_pi, Hx = 0;
    if (own) {
      const T ratio = dl / d;
      thx = ratio >= 1 ? half_pi : asin(sqrt(ratio));
      thxc = ratio >= 1 ? T(0) : half_pi - thx;
      Hx = H(thx, thxc);
      grade.push_back(thx);
      // The quotient (H - Hx)/(sin^2 theta - sin^2 theta_x) on a piece next to
      // the target's: H there is the neighbouring segment's cubic, whose value at
      // theta_x differs from Hx by ~J delta^2 (J: the jump of phi'' at the knot
      // between them, delta: the target's distance from it), a pole at theta_x
      // that a fixed rule resolves only on panels graded towards the knot (for
      // rough samples J delta^2 is not small: 7e-11 in B_x at 1e-3 noise). Cuts
      // at theta_x +- delta 2^j, delta the distance to the nearest knot.
      T delta = half_pi;
      for (const auto &pc : pieces) {
        const T a = theta(Z > 0 ? pc.first : pc.second), b = theta(Z > 0 ? pc.second : pc.first);
        if (a <= thx && thx <= b) delta = std::min(delta, std::min(T(thx - a), T(b - thx)));
      }
      if (delta > 0)
        for (T g = delta; g < half_pi; g *= 2) {
          if (thx - g > 0) grade.push_back(thx - g);
          if (thx + g < half_pi) grade.push_back(thx + g);
        }
    }
    std::sort(grade.begin(), grade.end());
    T lsum = 0;
    for (const auto &pc : pieces) {
      const T ta = Z > 0 ? pc.first : pc.second, tb = Z > 0 ? pc.second : pc.first;
      const T lo = theta(ta), hi = theta(tb);
      if (!(hi > lo)) continue;
      std::vector<T> cuts{lo};
      for (const T &gp : grade)
        if (gp > lo && gp < hi) cuts.push_back(gp);
      cuts.push_back(hi);
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const T a = cuts[i], b = cuts[i + 1], L = b - a, top = half_pi - b;
        for (int k = 0; k < 20; ++k) {
          const T th = a + L * (1 + rule->x[k]) / 2, thc = top + L * (1 - rule->x[k]) / 2;
          const T w = L * rule->w[k] / 2;
          if (!own) {
            const T sn = sin(th);
            lsum += w * H(th, thc) / (off + d * sn * sn);
            continue;
          }
          // the distance to theta_x exactly when theta_x is a panel end
          const T delta = b == thx ? T(-(L * (1 - rule->x[k]) / 2)) : (a == thx ? T(L * (1 + rule->x[k]) / 2) : T(th - thx));
          const T den = sin(delta) * sin(2 * thx + delta);
          if (den != 0) lsum += w * (H(th, thc) - Hx) / den;
        }
      }
      if (!own) continue;
      // Hx PV int_lo^hi dtheta/(sin^2 theta - s2x), the log terms at theta_x cancel between pieces
      const T s2t = sin(2 * thx);
      if (s2t != 0) {
        auto F = [&](const T &th) {
          if (th == thx) return T(0);
          return log(abs(sin(th - thx) / sin(th + thx))) / s2t;
        };
        lsum += Hx * (F(hi) - F(lo));
      }
    }
    return sum + (own ? T(sgn * lsum / d) : T(sgn * lsum));
  }

  // C_Z(xi) = int_Z p_hat(t) / (R(t) (t - xi)) dt (principal value when xi in Z)
  // for the canonical point xi at distance dl from the stick edge of zone pz.
  T cauchy(int zside, int pz, const T &dl) const {
    using std::asin;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T d = zside > 0 ? delta1 : delta2;
    if (!(d > 0)) return T(0);
    if (const knot_view<T> kv = pm->knots()) return cauchy_knots(kv, zside, pz, dl);
    const T e = width;
    auto H = [&](const T &th, const T &thc) {  // thc: pi/2 - th
      const T sn = sin(th), cs = sin(thc);
      const T s2 = sn * sn, c2 = cs * cs;
      const T ds = d * s2;
      const gdetail::zone_point<T> x = gdetail::zone_point_at(zside, d, s2, c2);
      return 2 * d * c2 * sqrt(x.far(zside)) * pm->phi(x.t, x.dm, x.dp) / sqrt(e + ds);
    };
    const T half_pi = pi<T>() / 2;
    std::vector<T> cuts;
    for (const auto &k : gdetail::zone_kinks(*pm, zside, d)) cuts.push_back(k.first);
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
      sum += integrate_ts<T>(
          [&](const T &th, const T &xc) {
            // exact distance to thx when thx is an end of this piece
            T delta;
            if (xc < 0 && lo == thx) delta = -xc;
            else if (xc > 0 && hi == thx) delta = -xc;
            else delta = th - thx;
            const T thc = (xc > 0 && hi == half_pi) ? xc : half_pi - th;
            const T den = sin(delta) * sin(2 * thx + delta);
            if (den == 0) return T(0);
            return (H(th, thc) - Hx) / den;
          },
          lo, hi, tol);
    }
    return zside > 0 ? sum / d : -sum / d;
  }

  // canonical dimensionless B_x (units f p0 / E*) at distance dl from the
  // stick edge of zone z (+1: R, -1: L): from the zone's expansion
  // (general_expansion.hpp) when there is one, else by bhat_direct
  T bhat(int z, const T &dl) const {
    if (!(dl > 0) || !(zone_length(z) > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.bhat(z, dl); });
    if (const auto *x = expansion()) {
      using std::sqrt;
      const T R = sqrt(dl * (width + dl));
      const T k = x->at(z).K(theta_of(z, dl));
      return z > 0 ? T(R * k) : T(-(R * k));
    }
    return bhat_direct(z, dl);
  }
  // B_x by the Cauchy integrals at the point (adaptive tanh-sinh per zone, the
  // path before issue 16: 20-70 us)
  T bhat_direct(int z, const T &dl) const {
    using std::sqrt;
    if (!(dl > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.bhat_direct(z, dl); });
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
      const T dist = gdetail::kink_distance(z, d, bp.x);
      if (dist > 0 && dist < d) v.push_back(dist);
    }
    return v;
  }

  // canonical slip (units f p0 a / E*), reference evaluation by nested
  // adaptive tanh-sinh
  T hhat_adaptive(int z, const T &dl) const {
    if (!(dl > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.hhat_adaptive(z, dl); });
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
  static int graded_inner_order(int M) { return std::numeric_limits<T>::digits10 > 20 ? 6 * M + 1 : 0; }

  // h' at the first `count` outer nodes O of zone z (inner rules IR, IL;
  // G: the high-order rule on the graded panels of zone z, or null).
  std::vector<T> hgrad_nodes(int z, const gdetail::zone_nodes<T> &O, const gdetail::zone_nodes<T> &IR,
                             const gdetail::zone_nodes<T> &IL, std::size_t count,
                             const gdetail::zone_nodes<T> *G = nullptr) const {
    if constexpr (inplace_loops<T>::value) {
      return hgrad_nodes_inplace(z, O, IR, IL, count, G);
    } else {
      // high orders (issue 13, bounded time: a callback pressure with kinks, whose energies
      // converge only algebraically, reached order 1024 and 10 s of CPU, 95 % of it here):
      // the fast multipole sum of the knot path, O(nodes) for the O(nodes^2) below. Its
      // truncation is ~1e-16 of sum |q|/distance (fmm1d.hpp); below the threshold (orders
      // up to ~128 on a dozen panels per zone) the direct sums stay, bitwise as before.
      // (double only: the expansion order of fmm1d.hpp truncates at ~8e-17, which in long
      // double, the truth of the estimate sweeps, cost 400 to 1000 eps_LD in h'; a review's find)
      if (std::numeric_limits<T>::digits <= 53 && !(G && !G->s2.empty()) &&
          double(count) * double(IR.s2.size() + IL.s2.size()) > fmm_pairs())
        return gdetail::knot_hgrad(z, O, IR, IL, count, dirR, dirL, width);
      return hgrad_nodes_direct(z, O, IR, IL, count, G);
    }
  }
  // pairs (outer node, inner node) above which hgrad_nodes sums by the fast multipole method
  static double fmm_pairs() { return 4e6; }
  // hgrad_nodes by direct O(count (IR + IL)) sums (the definition; tests compare the two)
  std::vector<T> hgrad_nodes_direct(int z, const gdetail::zone_nodes<T> &O, const gdetail::zone_nodes<T> &IR,
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

  // hgrad_nodes beyond double (the reference backend; issue 16: these O(M^2 panels^2)
  // sums were ~30 % of the flat punch's energies at 50 digits): the same operations in
  // the same order, rounded alike, in place (no temporary a term), with the products
  // w_i H_i and d_Z sin^2 theta_i of the other zone formed once per call instead of
  // once per outer node (the same roundings: each was formed first in each term).
  std::vector<T> hgrad_nodes_inplace(int z, const gdetail::zone_nodes<T> &O, const gdetail::zone_nodes<T> &IR,
                                     const gdetail::zone_nodes<T> &IL, std::size_t count,
                                     const gdetail::zone_nodes<T> *G) const {
    using std::sqrt;
    const T e = width;
    std::vector<T> g(count, T(0));
    // per other zone: w_i H_i and d sin^2 theta_i
    std::vector<T> wH[2], ds[2];
    for (int Z : {+1, -1}) {
      const auto &I = Z > 0 ? IR : IL;
      if (Z == z || !(I.d > 0)) continue;
      const std::size_t n = I.s2.size(), k = Z > 0 ? 0 : 1;
      wH[k].resize(n);
      ds[k].resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        wH[k][i] = I.w[i];
        wH[k][i] *= I.H[i];
        ds[k][i] = I.d;
        ds[k][i] *= I.s2[i];
      }
    }
    T sum, t, den, base, br;
    for (std::size_t j = 0; j < count; ++j) {
      const T &sj = O.s2[j], &cj = O.c2[j];
      const T u = O.d * sj;
      br = 0;
      for (int Z : {+1, -1}) {
        const int dir = Z > 0 ? dirR : dirL;
        const auto &I = Z > 0 ? IR : IL;
        if (dir == 0 || !(I.d > 0)) continue;
        const std::size_t n = I.s2.size();
        sum = 0;
        if (Z == z) {
          const T &Hj = O.H[j];
          const bool hi = G && !G->s2.empty();
          auto add = [&](const gdetail::zone_nodes<T> &N, std::size_t i) {
            den = N.s2[i];
            den += sj;
            if (den < 1) {
              den = N.s2[i];
              den -= sj;
            } else {
              den = cj;
              den -= N.c2[i];
            }
            if (den != 0) {
              t = N.H[i];
              t -= Hj;
              t *= N.w[i];
              t /= den;
              sum += t;
            }
          };
          for (std::size_t i = 0; i < n; ++i) {
            if (hi && I.graded[i]) continue;
            add(I, i);
          }
          if (hi)
            for (std::size_t i = 0; i < G->s2.size(); ++i) add(*G, i);
          sum /= I.d;
        } else {
          const std::size_t k = Z > 0 ? 0 : 1;
          base = e;
          base += u;
          for (std::size_t i = 0; i < n; ++i) {
            den = base;
            den += ds[k][i];
            t = wH[k][i];
            t /= den;
            sum += t;
          }
        }
        if (dir > 0) br += sum;
        else br -= sum;
      }
      g[j] = -2 * sqrt(u * (e + u)) * br / pi<T>();
    }
    return g;
  }

  // The knot path (general_knots.hpp): a model with a knot quadrature, in a
  // precision where the own zone's graded panels need no inner rule of their own.
  knot_view<T> knot_path(int M) const {
    if (graded_inner_order(M) > 0) return {};
    return pm->knots();
  }

  // zone energy and slip at outer order M on the knot path
  T energy_hat_knots(const knot_view<T> &kv, int z, int M) const {
    using std::abs;
    using std::sqrt;
    const T d = zone_length(z);
    const auto PR = gdetail::knot_panels<T>(kv, +1, delta1, width, M);
    const auto PL = gdetail::knot_panels<T>(kv, -1, delta2, width, M);
    const auto O = gdetail::make_knot_nodes<T>(kv, z, d, width, z > 0 ? PR : PL, false);
    const auto IR = gdetail::make_knot_nodes<T>(kv, +1, delta1, width, PR, true);
    const auto IL = gdetail::make_knot_nodes<T>(kv, -1, delta2, width, PL, true);
    const std::vector<T> g = gdetail::knot_hgrad(z, O, IR, IL, O.s2.size(), dirR, dirL, width);
    std::vector<std::shared_ptr<const gl_cumulative<T>>> cums;
    std::vector<T> f;
    T after = 0, E = 0;
    for (std::size_t P = O.panels.size(); P-- > 0;) {
      const int k = O.panels[P].order;
      if (cums.size() <= std::size_t(k)) cums.resize(k + 1);
      if (!cums[k]) cums[k] = gauss_legendre_cumulative<T>(k);
      const auto &cum = *cums[k];
      const std::size_t b = O.first[P];
      f.assign(k, T(0));
      T tot = 0;
      for (int i = 0; i < k; ++i) {
        f[i] = O.p[b + i] * 2 * d * sqrt(O.s2[b + i] * O.c2[b + i]);
        tot += O.w[b + i] * f[i];
      }
      for (int i = 0; i < k; ++i) {
        T tail = 0;
        for (int j = 0; j < k; ++j) tail += cum.S[std::size_t(i) * k + j] * O.jac[b + j] * f[j];
        tail += after;
        E += O.w[b + i] * 2 * d * sqrt(O.s2[b + i] * O.c2[b + i]) * tail * g[b + i];
      }
      after += tot;
    }
    return abs(E);
  }
  T hhat_knots(const knot_view<T> &kv, int z, const T &thx, int M) const {
    using std::sqrt;
    const T d = zone_length(z);
    const auto PR = gdetail::knot_panels<T>(kv, +1, delta1, width, M, z > 0 ? &thx : nullptr);
    const auto PL = gdetail::knot_panels<T>(kv, -1, delta2, width, M, z < 0 ? &thx : nullptr);
    const auto O = gdetail::make_knot_nodes<T>(kv, z, d, width, z > 0 ? PR : PL, false);
    std::size_t np = 0;
    while (np < O.panels.size() && !(O.panels[np].hi > thx)) ++np;
    const auto IR = gdetail::make_knot_nodes<T>(kv, +1, delta1, width, PR, true);
    const auto IL = gdetail::make_knot_nodes<T>(kv, -1, delta2, width, PL, true);
    const std::size_t count = O.first[np];
    const std::vector<T> g = gdetail::knot_hgrad(z, O, IR, IL, count, dirR, dirL, width);
    T h = 0;
    for (std::size_t j = 0; j < count; ++j) h += O.w[j] * 2 * d * sqrt(O.s2[j] * O.c2[j]) * g[j];
    return h;
  }

  // zone energy with the outer order M (see above), by parts:
  // int_0^d tail(d - u) h'(u) du with the tail cumulated on the outer nodes
  T energy_hat_order(int z, int M) const {
    using std::abs;
    using std::sqrt;
    const T d = zone_length(z);
    if (!(d > 0)) return T(0);
    if (const knot_view<T> kv = knot_path(M)) return energy_hat_knots(kv, z, M);
    auto O = gdetail::make_zone_nodes<T>(*pm, z, d, width, M);
    gdetail::drop_outer_panels_below(O, T(eps<T>() * pi<T>() / 2));
    const auto IR = gdetail::make_zone_nodes<T>(*pm, +1, delta1, width, M + 1);
    const auto IL = gdetail::make_zone_nodes<T>(*pm, -1, delta2, width, M + 1);
    const int Kg = graded_inner_order(M);
    gdetail::zone_nodes<T> G;
    if (Kg > 0) G = gdetail::make_zone_nodes<T>(*pm, z, d, width, Kg, nullptr, true);
    const std::vector<T> g = hgrad_nodes(z, O, IR, IL, O.s2.size(), Kg > 0 ? &G : nullptr);
    std::vector<T> f(M);
    T after = 0, E = 0;
    if (std::numeric_limits<T>::digits10 > std::numeric_limits<long double>::digits10) {
      // beyond long double (the reference): the tail by cumulate_tail, 2 M^2 per
      // panel from the Legendre table (O(M^2) to make), where the matrix S of
      // the branch below costs O(M^3) to make (issue 16: 2 s of 14 at 120 digits)
      const auto tab = gauss_legendre_table<T>(M);
      std::vector<T> gw(M), tail(M), coef;
      for (std::size_t P = O.panels.size(); P-- > 0;) {
        const std::size_t b = P * M;
        T tot = 0;
        for (int k = 0; k < M; ++k) {
          f[k] = O.p[b + k] * 2 * d * sqrt(O.s2[b + k] * O.c2[b + k]);
          gw[k] = O.w[b + k] * f[k];
          tot += gw[k];
        }
        cumulate_tail(*tab, gw.data(), tail.data(), coef);
        for (int i = 0; i < M; ++i)
          E += O.w[b + i] * 2 * d * sqrt(O.s2[b + i] * O.c2[b + i]) * (tail[i] + after) * g[b + i];
        after += tot;
      }
      return abs(E);
    }
    const auto cum = gauss_legendre_cumulative<T>(M);
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
    using std::asin;
    using std::sqrt;
    const T d = zone_length(z);
    if (!(dl > 0) || !(d > 0)) return T(0);
    const T half_pi = pi<T>() / 2;
    const T thx = dl >= d ? half_pi : (2 * dl <= d ? T(asin(sqrt(dl / d))) : half_pi - asin(sqrt((d - dl) / d)));
    if (const knot_view<T> kv = knot_path(M)) return hhat_knots(kv, z, thx, M);
    auto O = gdetail::make_zone_nodes<T>(*pm, z, d, width, M, &thx);
    gdetail::drop_outer_panels_below(O, T(eps<T>() * thx));
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
    if (point_stick()) return continued([&](const general_solution &g) { return g.energy_hat_adaptive(z); });
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
    using std::max;
    using std::sqrt;
    const T e34 = sqrt(eps<T>() * sqrt(eps<T>()));
    return max(rtol, e34);
  }
  template <class F> T by_order(const F &f, const T &tol) const {
    using std::abs;
    using std::max;
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
    throw error(status::no_convergence,
                "zone energy or slip: no two orders agreed up to the order limit (max_order)");
  }
  // zone energy and slip: from the zone's expansion when there is one, else
  // by the fixed rules (energy_hat_fixed, hhat_fixed)
  T energy_hat(int z) const {
    using std::abs;
    if (!(zone_length(z) > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.energy_hat(z); });
    if (const auto *x = expansion()) return abs(x->at(z).energy);
    return energy_hat_fixed(z);
  }
  T hhat(int z, const T &dl) const {
    if (!(dl > 0) || !(zone_length(z) > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.hhat(z, dl); });
    if (const auto *x = expansion()) {
      const T d = zone_length(z);
      if (!(dl < d)) return x->at(z).h0.back();
      return x->at(z).h(theta_of(z, dl));
    }
    return hhat_fixed(z, dl);
  }
  // the fixed-rule paths (before issue 16: the orders doubled until two agree)
  T energy_hat_fixed(int z) const {
    if (!(zone_length(z) > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.energy_hat_fixed(z); });
    // (the state's own error, state_rtol, sets the floor: the estimate carries it; the slips
    // have no estimate of their own and keep energy_tol)
    using std::max;
    return by_order([&](int M) { return energy_hat_order(z, M); }, max(energy_tol(), T(state_rtol / 32)));
  }
  T hhat_fixed(int z, const T &dl) const {
    if (!(dl > 0) || !(zone_length(z) > 0)) return T(0);
    if (point_stick()) return continued([&](const general_solution &g) { return g.hhat_fixed(z, dl); });
    return by_order([&](int M) { return hhat_order(z, dl, M); }, energy_tol());
  }
  // theta = asin(sqrt(dl/d)) of the point at distance dl from the stick edge
  // of zone z (from the nearer end, without cancellation)
  T theta_of(int z, const T &dl) const {
    using std::asin;
    using std::sqrt;
    const T d = zone_length(z), half_pi = pi<T>() / 2;
    return dl >= d ? half_pi : (2 * dl <= d ? T(asin(sqrt(dl / d))) : half_pi - asin(sqrt((d - dl) / d)));
  }

  // ---- the expansion (general_expansion.hpp; issue 16) ----
  // Made on the first point, slip or energy evaluation that needs it, once
  // (thread-safe); shared by the copies of the solution. Null where it does
  // not apply (beyond long double, the knot path, the point-stick limit, stuck)
  // or where its accuracy control did not pass within max_order: the paths
  // above answer then. It is of the state (zones, width) at its first use: code
  // that changes the state of a solution afterwards gives it a fresh cache
  // (expansion_ = std::make_shared<expansion_cache>(), as continued() drops it).
  struct expansion_cache {
    std::once_flag once;
    std::shared_ptr<const gdetail::general_expansion<T>> value;
  };
  std::shared_ptr<expansion_cache> expansion_;  // set by solve_general
  static constexpr double expansion_max_pairs = 4e6;
  const gdetail::general_expansion<T> *expansion() const {
    if (!expansion_) return nullptr;
    expansion_cache &c = *expansion_;
    std::call_once(c.once, [&] {
      try {
        c.value = make_expansion();
      } catch (const error &) {
        c.value = nullptr;  // the other paths answer (and report)
      }
    });
    return c.value.get();
  }
  // M from M0, raised per zone (to the order the coefficients' decay asks
  // for, at most doubled) until the last two Legendre coefficients of K on
  // every panel are below tol max|K| there (general_expansion.hpp); null if
  // not within max_order.
  std::shared_ptr<const gdetail::general_expansion<T>> make_expansion(int M0 = 0) const {
    using std::max;
    // from the smallest power of two >= twice the digits of T (32 in double:
    // order 16 never passed on the benchmark scenes). Not from the solver's
    // order: the rounding of K next to the stick edge grows like M^2 (see
    // zone_expansion::K_error), so M stays as low as the accuracy control allows.
    if (M0 <= 0)
      for (M0 = 16; M0 < 2 * std::numeric_limits<T>::digits10;) M0 *= 2;
    if (graded_inner_order(M0) > 0 || pm->knots() || point_stick() || reg == regime::stuck) return nullptr;
    auto x = std::make_shared<gdetail::general_expansion<T>>();
    const T tol = max(T(32 * eps<T>()), T(rtol / 64));
    int Mi = 0;
    gdetail::zone_nodes<T> IR, IL;
    for (int z : {+1, -1}) {
      const T d = zone_length(z);
      if (!(d > 0)) continue;
      bool ok = false;
      for (int M = M0; M <= max_order;) {
        if (Mi != M) {
          IR = gdetail::make_zone_nodes<T>(*pm, +1, delta1, width, M + 1, nullptr, false, 0, true);
          IL = gdetail::make_zone_nodes<T>(*pm, -1, delta2, width, M + 1, nullptr, false, 0, true);
          Mi = M;
        }
        const auto O = gdetail::make_zone_nodes<T>(*pm, z, d, width, M, nullptr, false, 0, true);
        // the set-up is quadratic in the nodes: beyond 4M node pairs (~5 ms;
        // many panels: a stick zone far below a, a power law of large n, many
        // samples) the paths above answer, each at its own cost, as before
        if (double(O.s2.size()) * double(IR.s2.size() + IL.s2.size()) > expansion_max_pairs) return nullptr;
        std::vector<T> K, err;
        gdetail::expansion_k_nodes<T>(z, O, IR, IL, dirR, dirL, width, K, err);
        auto &zx = x->zone[z > 0 ? 0 : 1];
        gdetail::fill_zone_expansion<T>(zx, O, K, err, width, tol);
        if (zx.tail <= tol) {
          ok = true;
          break;
        }
        // the order the coefficients' decay asks for (at least M + 8, at most 2M)
        M = std::max(M + 8, std::min(2 * M, zx.next_order));
      }
      if (!ok) return nullptr;
    }
    return x;
  }

  // Shear traction q(x) on body 1 (traction.hpp), split at the pressure's kinks.
  std::vector<T> user_kinks() const {
    std::vector<T> k;
    for (const auto &bp : pm->breakpoints()) k.push_back(scene.a * (mirror ? -bp.x : bp.x));
    return k;
  }
  T traction(const T &x) const {
    if (pm->knots()) return traction_knots(x);
    return this->traction_generic(x, user_kinks());
  }
  // The shear traction on the knot path: f dir p on the slip zones; on the
  // stick zone q = f p0 R(xi)/pi (dirR C_R(xi) - dirL C_L(xi)) (traction.hpp), in
  // the canonical frame (q_user(x) = sign q_canonical(xi), xi = +-x/a).
  T traction_knots(const T &x) const {
    using std::sqrt;
    const knot_view<T> kv = pm->knots();
    const T xi = (mirror ? -x : x) / scene.a;
    if (!(xi > -1 && xi < 1)) return T(0);
    const T fp0 = scene.f * scene.p0;
    if (delta1 > 0 && xi >= beta1) return T(this->sign() * dirR) * fp0 * pm->p(xi);
    if (delta2 > 0 && xi <= -beta2) return T(this->sign() * dirL) * fp0 * pm->p(xi);
    if (!(delta1 > 0) && !(delta2 > 0)) return T(0);
    // distances from the stick edges, the stick-zone half of R
    const T ep1 = beta1 - xi, ep2 = xi + beta2;
    const T br = (delta1 > 0 ? T(dirR) * cauchy_knots(kv, +1, 0, ep1, ep2) : T(0)) -
                 (delta2 > 0 ? T(dirL) * cauchy_knots(kv, -1, 0, ep1, ep2) : T(0));
    return T(this->sign()) * fp0 * sqrt(ep1 * ep2) / pi<T>() * br;
  }

  T pressure(const T &x) const {
    const T xi = (mirror ? -x : x) / scene.a;
    if (!(xi > -1 && xi < 1)) return T(0);
    return scene.p0 * pm->p(xi);
  }
  // at distance c from the user-frame edge `side` (the edge's distance exact: traction.hpp)
  T pressure_near_edge(const T &x, int side, const T &c) const {
    const T xi = (mirror ? -x : x) / scene.a, dist = c / scene.a;
    if (!(dist > 0) || !(dist < 2)) return T(0);
    return ((side > 0) != mirror) ? scene.p0 * pm->p(xi, 2 - dist, dist) : scene.p0 * pm->p(xi, dist, 2 - dist);
  }
};

}}  // namespace hs::core
