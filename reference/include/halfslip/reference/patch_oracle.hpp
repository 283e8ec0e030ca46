// halfslip -- reference oracle for an advancing segment whose final stick set is TWO
// intervals: S = (-b2, pl) U (pr, b1), with an interior slip patch (pl, pr) of direction dp between
// them and the edge zones (b1, 1), (-1, -b2) as in the one-interval static solve (docs/history.md,
// "Advancing segments in one static solve"). Derivation and checks: docs/history.md, "Interior slip
// zones: the two-interval static solve (an oracle)"; tests/test_patch_oracle.cpp. Written for the
// tests (session 15): it shares no code with core/ (its own Gauss rule and quadrature).
//
// Units: a = p0 = f = E* = 1; q = Q/fP, s = sigma/(f p0); int q dx = q pi/2.
//
// Premise (the static argument): every point of the final stick set S was stuck throughout the
// segment, so its slip is unchanged, including the constant: the slip gradient change vanishes on
// S AND the slip change across the patch integrates to zero. Every point of the complement
// G = (b1, 1) U (pl, pr) U (-1, -b2) slips at the end with its zone's direction:
//     dq = g = d p - q_S on G  (d = d1, dp, d2),
//     (2/pi) PV int_{-1}^{1} dq(xi)/(x - xi) dxi = ds/2  on S,   int dq = dQ pi/2.
// With R(z) = (z - b1)(z + b2)(z - pl)(z - pr) and Y(z) = sqrt(R(z)) ~ z^2 (cuts on S), Y is real
// on G: Y = +sqrt|R| on band 1 and band 2, -sqrt|R| on the patch; on S its upper value is
// Y+ = +i sqrt|R| on (pr, b1) and -i sqrt|R| on (-b2, pl). The bounded solution exists iff
//     r0 = (1/pi) int_G g / Y                                = 0
//     r1 = ds/4 + (1/pi) int_G g t / Y                       = 0
//     r2 = (1/pi) int_G g t^2 / Y + ds e1/8 - dQ/2           = 0   (e1 = b1 - b2 + pl + pr)
// and then, on S,  dq(x) = +-(sqrt|R(x)|/pi) int_G g(t) / (Y(t) (t - x)) dt  (+ on (pr, b1),
// - on (-b2, pl)). The patch condition (zero net slip change across the patch):
//     r3 = J = dh(pr) - dh(pl) = -(2/pi) int_G (g/Y)(t) K(t) dt = 0,
//     K(t) = PV int_patch Y(x)/(t - x) dx.
// The slip change at x (any x, relative to the stick set) comes from the log kernel:
//     dh(x) - dh(x0) = (2/pi) int dq(t) ln|(x - t)/(x0 - t)| dt - ds (x - x0)/2.
//
// With pl == pr the class is the one-interval solve (residual1, dq_stick with ends {b1, b2, 0, 0}).
// A zero-width patch solves the four conditions to O(width^2) wherever the one-interval traction
// touches dp p (the degenerate branch): solve() throws when the patch collapses below 1e-6.
// Energies: if every point of a final zone slipped one way only, its dissipation over the segment
// is int_zone d p dh dx from the end state (energy(); the caller checks one-way slip, e.g. by the
// same solve at intermediate load fractions). The caller gives the directions and a start guess.
//
// Everything is Gauss-Legendre on theta panels, x = l + (r - l) sin^2(theta/2) (which takes the
// square-root end behaviour of 1/Y, p and the cusps of q_S), graded geometrically towards both
// piece ends; pieces are cut at the roots of R, at the start state's cusps and at +-1.
// Double precision; slow and simple on purpose. One object must not be used by two threads at once
// (it caches the nodes of the last ends); separate objects are independent.
#pragma once
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace hs { namespace reference {

namespace podetail {
constexpr double pi = 3.141592653589793238462643383279502884;

// Gauss-Legendre nodes/weights on (-1, 1) by Newton on P_n (own code, no library share)
inline void gauss_legendre(int n, std::vector<double> &x, std::vector<double> &w) {
  x.assign(n, 0);
  w.assign(n, 0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1;
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    x[i] = -z;
    x[n - 1 - i] = z;
    w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// a node of a piece [l, r]: x, its distances to both piece ends (exact), and the weight (dx)
struct node {
  double x, dl, dr, w, l, r;  // (l, r: the piece)
};
// x - t for a node t, exact where x is an end of the node's piece
inline double diff(double x, const node &n) {
  if (x == n.l) return -n.dl;
  if (x == n.r) return n.dr;
  return x - n.x;
}

// sin^2 map on [l, r] with theta panels graded towards 0 and pi (levels K), each with the
// Gauss-Legendre rule (gx, gw)
inline void piece_nodes(double l, double r, const std::vector<double> &gx, const std::vector<double> &gw, int K,
                        std::vector<node> &out) {
  const double L = r - l;
  if (!(L > 0)) return;
  std::vector<double> br{0};
  for (int k = K; k >= 1; --k) br.push_back(pi / 2 * std::ldexp(1.0, -k));
  br.push_back(pi / 2);
  for (int k = 1; k <= K; ++k) br.push_back(pi - pi / 2 * std::ldexp(1.0, -k));
  br.push_back(pi);
  for (size_t j = 0; j + 1 < br.size(); ++j) {
    const double a = br[j], b = br[j + 1];
    for (size_t i = 0; i < gx.size(); ++i) {
      const double th = 0.5 * (a + b) + 0.5 * (b - a) * gx[i];
      const double s = std::sin(th / 2), c = std::cos(th / 2);
      node nd;
      nd.dl = L * s * s;
      nd.dr = L * c * c;
      nd.x = th < pi / 2 ? l + nd.dl : r - nd.dr;
      nd.w = 0.5 * (b - a) * gw[i] * L * s * c;
      nd.l = l;
      nd.r = r;
      out.push_back(nd);
    }
  }
}
}  // namespace podetail

struct patch_oracle_options {
  int order = 20;   // Gauss order per theta panel
  int levels = 12;  // geometric grading levels towards each piece end
  int korder = 96;  // Gauss-Chebyshev (2nd kind) order of the patch kernel K
};

class patch_oracle {
 public:
  struct ends {
    double b1, b2, pl, pr;  // stick set (-b2, pl) U (pr, b1); pl == pr: no patch (one interval)
  };
  using options = patch_oracle_options;

  // qS: start traction on [-1, 1]; p: pressure; cusps: points where qS (or p) is not smooth
  // (the start state's memory points and ends); dQ, ds: the segment's load change; d1, d2, dp:
  // the directions of zone 1, zone 2 and the patch at the end.
  patch_oracle(std::function<double(double)> qS, std::function<double(double)> p, std::vector<double> cusps,
               double dQ, double ds, double d1, double d2, double dp, options o = options())
      : qS_(std::move(qS)), p_(std::move(p)), cusps_(std::move(cusps)), dQ_(dQ), ds_(ds), d1_(d1), d2_(d2), dp_(dp), o_(o) {
    if (o_.order < 2 || o_.levels < 0 || o_.korder < 2) throw std::invalid_argument("patch_oracle: an order out of range");
    std::sort(cusps_.begin(), cusps_.end());
    podetail::gauss_legendre(o_.order, gx_, gw_);
  }

  double g(int zone, double x) const {  // zone 1, 2, or 3 (patch)
    const double d = zone == 1 ? d1_ : (zone == 2 ? d2_ : dp_);
    return d * p_(x) - qS_(x);
  }

  // ---- geometry of R ----------------------------------------------------------------------
  static bool has_patch(const ends &e) { return e.pr > e.pl; }
  // sqrt|R(x)| with exact distances dl/dr to the ends of the piece [l, r] that holds x
  double sqrtR(const ends &e, const podetail::node &nd, double l, double r) const {
    auto dist = [&](double root) {
      if (root == l) return nd.dl;
      if (root == r) return nd.dr;
      return std::fabs(nd.x - root);
    };
    double v = dist(e.b1) * dist(-e.b2);
    if (has_patch(e)) v *= dist(e.pl) * dist(e.pr);
    return std::sqrt(v);
  }

  // the complement G as pieces (zone, l, r), cut at the cusps
  struct piece {
    int zone;
    double l, r;
  };
  std::vector<piece> pieces(const ends &e) const {
    std::vector<piece> out;
    auto add = [&](int z, double l, double r) {
      if (!(r > l)) return;
      double a = l;
      for (double c : cusps_)
        if (c > l && c < r) {
          out.push_back({z, a, c});
          a = c;
        }
      out.push_back({z, a, r});
    };
    add(1, e.b1, 1.0);
    if (has_patch(e)) add(3, e.pl, e.pr);
    add(2, -1.0, -e.b2);
    return out;
  }
  // Y on G: + on bands for two intervals; one interval: + on band 1, - on band 2; - on the patch
  int ysign(const ends &e, int zone) const {
    if (zone == 3) return -1;
    if (zone == 2 && !has_patch(e)) return -1;
    return 1;
  }

  // nodes of G with g/Y * weight precomputed
  struct gnode {
    double x, gy;  // x, g(x) w / Y(x)
    int zone;
  };
  const std::vector<gnode> &gnodes(const ends &e) const {
    if (cache_valid_ && e.b1 == ce_.b1 && e.b2 == ce_.b2 && e.pl == ce_.pl && e.pr == ce_.pr) return gn_;
    gn_.clear();
    std::vector<podetail::node> nds;
    for (const auto &pc : pieces(e)) {
      nds.clear();
      podetail::piece_nodes(pc.l, pc.r, gx_, gw_, o_.levels, nds);
      for (const auto &nd : nds) {
        const double Y = ysign(e, pc.zone) * sqrtR(e, nd, pc.l, pc.r);
        gn_.push_back({nd.x, g(pc.zone, nd.x) * nd.w / Y, pc.zone});
      }
    }
    ce_ = e;
    cache_valid_ = true;
    return gn_;
  }

  // K(t) = PV int_patch Y(x)/(t - x) dx, Y = -sqrt((x-pl)(pr-x)) m(x), m = sqrt((b1-x)(x+b2))
  double K(const ends &e, double t) const {
    const int n = o_.korder;
    const double mid = 0.5 * (e.pl + e.pr), hw = 0.5 * (e.pr - e.pl);
    auto m = [&](double x) { return std::sqrt((e.b1 - x) * (x + e.b2)); };
    const bool inside = t > e.pl && t < e.pr;
    const double mt = inside ? m(t) : 0;
    double s = 0;
    for (int k = 1; k <= n; ++k) {  // Gauss-Chebyshev 2nd kind: int sqrt(1-u^2) f(u) du
      const double ph = k * podetail::pi / (n + 1);
      const double u = std::cos(ph), wk = podetail::pi / (n + 1) * std::sin(ph) * std::sin(ph);
      const double x = mid + hw * u;
      const double f = inside ? (m(x) - mt) / (t - x) : m(x) / (t - x);
      s += wk * hw * hw * f;  // sqrt((x-pl)(pr-x)) dx = hw^2 sqrt(1-u^2) du
    }
    if (inside) s += mt * podetail::pi * (t - mid);
    return -s;
  }

  // ---- the four conditions --------------------------------------------------------------------
  // two intervals: (r0, r1, r2, r3) as in the header comment
  std::array<double, 4> residual(const ends &e) const {
    const auto &G = gnodes(e);
    double m0 = 0, m1 = 0, m2 = 0, J = 0;
    for (const auto &n : G) {
      m0 += n.gy;
      m1 += n.gy * n.x;
      m2 += n.gy * n.x * n.x;
    }
    if (has_patch(e))
      for (const auto &n : G) J += n.gy * K(e, n.x);
    const double e1 = e.b1 - e.b2 + e.pl + e.pr;
    return {{m0 / podetail::pi, ds_ / 4 + m1 / podetail::pi, m2 / podetail::pi + ds_ * e1 / 8 - dQ_ / 2,
             -2 / podetail::pi * J}};
  }
  // one interval (pl, pr ignored), the library's two conditions
  std::array<double, 2> residual1(double b1, double b2) const {
    ends e{b1, b2, 0, 0};
    const auto &G = gnodes(e);
    const double c = (b1 - b2) / 2;
    double I = 0, Jc = 0;
    for (const auto &n : G) {
      I += n.gy;
      Jc += n.gy * (n.x - c);
    }
    return {{ds_ / 4 + I / podetail::pi, Jc - dQ_ * podetail::pi / 2}};
  }

  // Newton on (b1, b2, pl, pr) with a central-difference Jacobian; throws if it does not settle
  ends solve(ends e, int max_it = 60, double tol = 1e-13) const {
    const double h = 1e-6;
    double last = -1;
    for (int it = 0; it < max_it; ++it) {
      auto r = residual(e);
      Eigen::Vector4d F(r[0], r[1], r[2], r[3]);
      Eigen::Matrix4d Jm;
      for (int j = 0; j < 4; ++j) {
        ends ep = e, em = e;
        at(ep, j) += h;
        at(em, j) -= h;
        const auto rp = residual(ep), rm = residual(em);
        for (int i = 0; i < 4; ++i) Jm(i, j) = (rp[i] - rm[i]) / (2 * h);
      }
      Eigen::Vector4d dx = Jm.fullPivLu().solve(F);
      if (!dx.allFinite()) throw std::runtime_error("patch_oracle: singular Newton step");
      double lam = 1;
      for (int k = 0; k < 30; ++k) {
        ends t = e;
        for (int j = 0; j < 4; ++j) at(t, j) -= lam * dx[j];
        if (t.b1 < 1 && t.b2 < 1 && t.pr > t.pl && t.b1 > t.pr && -t.b2 < t.pl) {
          const auto rt = residual(t);
          const double nt = std::hypot(std::hypot(rt[0], rt[1]), std::hypot(rt[2], rt[3]));
          if (nt < F.norm() || lam < 1e-3) {
            e = t;
            break;
          }
        }
        lam /= 2;
      }
      const double stp = dx.cwiseAbs().maxCoeff();
      if (stp < tol || (stp < 1e-10 && last >= 0 && stp > last / 2)) {
        // a patch of (nearly) zero width solves the four conditions to O(width^2) for any point at
        // which the one-interval traction touches g_p: the degenerate branch, not a two-interval state
        if (e.pr - e.pl < 1e-6) throw std::runtime_error("patch_oracle: the patch collapsed (degenerate branch)");
        return e;
      }
      last = stp;
    }
    throw std::runtime_error("patch_oracle: Newton did not settle");
  }
  // Newton on a subset of the unknowns (mask), the others held (used by the checks)
  ends solve_masked(ends e, std::array<bool, 4> freev, std::array<int, 4> eqs, int max_it = 60) const {
    std::vector<int> fv;
    for (int j = 0; j < 4; ++j)
      if (freev[j]) fv.push_back(j);
    const int n = int(fv.size());
    const double h = 1e-6;
    for (int it = 0; it < max_it; ++it) {
      auto r = residual(e);
      Eigen::VectorXd F(n);
      for (int i = 0; i < n; ++i) F[i] = r[eqs[i]];
      Eigen::MatrixXd Jm(n, n);
      for (int j = 0; j < n; ++j) {
        ends ep = e, em = e;
        at(ep, fv[j]) += h;
        at(em, fv[j]) -= h;
        const auto rp = residual(ep), rm = residual(em);
        for (int i = 0; i < n; ++i) Jm(i, j) = (rp[eqs[i]] - rm[eqs[i]]) / (2 * h);
      }
      Eigen::VectorXd dx = Jm.fullPivLu().solve(F);
      for (int j = 0; j < n; ++j) at(e, fv[j]) -= dx[j];
      if (dx.cwiseAbs().maxCoeff() < 1e-14) return e;
    }
    return e;
  }

  // ---- the state after the segment ----------------------------------------------------------
  // dq at x in S (a point of the stick set)
  double dq_stick(const ends &e, double x) const {
    const auto &G = gnodes(e);
    double s = 0;
    for (const auto &n : G) s += n.gy / (n.x - x);
    double R = (e.b1 - x) * (x + e.b2);
    int sg = 1;
    if (has_patch(e)) {
      R *= (x - e.pl) * (x - e.pr);
      if (x < e.pl) sg = -1;
    }
    return sg * std::sqrt(std::fabs(R)) / podetail::pi * s;
  }
  int where(const ends &e, double x) const {  // 1, 2, 3 (patch) or 0 (stick)
    if (x >= e.b1) return 1;
    if (x <= -e.b2) return 2;
    if (has_patch(e) && x >= e.pl && x <= e.pr) return 3;
    return 0;
  }
  double traction(const ends &e, double x) const {
    const int z = where(e, x);
    if (z == 0) return qS_(x) + dq_stick(e, x);
    return (z == 1 ? d1_ : (z == 2 ? d2_ : dp_)) * p_(x);
  }
  double dq(const ends &e, double x) const { return traction(e, x) - qS_(x); }

  // nodes of the whole contact (-1, 1) cut at the roots, the cusps and extra points, with dq
  std::vector<podetail::node> all_nodes(const ends &e, std::vector<double> extra, std::vector<double> *dqv) const {
    std::vector<double> c{-1.0, -e.b2, e.b1, 1.0};
    if (has_patch(e)) {
      c.push_back(e.pl);
      c.push_back(e.pr);
    }
    for (double x : cusps_)
      if (x > -1 && x < 1) c.push_back(x);
    for (double x : extra) c.push_back(x);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    std::vector<podetail::node> out;
    for (size_t k = 0; k + 1 < c.size(); ++k) podetail::piece_nodes(c[k], c[k + 1], gx_, gw_, o_.levels, out);
    if (dqv) {
      dqv->clear();
      for (const auto &n : out) dqv->push_back(dq(e, n.x));
    }
    return out;
  }
  // int dq over (-1, 1)
  double force(const ends &e) const {
    std::vector<double> v;
    const auto nd = all_nodes(e, {}, &v);
    double s = 0;
    for (size_t k = 0; k < nd.size(); ++k) s += nd[k].w * v[k];
    return s;
  }
  // slip change at each of xs relative to x0 (log kernel; pieces cut at xs and x0)
  std::vector<double> slip_change(const ends &e, const std::vector<double> &xs, double x0) const {
    std::vector<double> ex(xs);
    ex.push_back(x0);
    std::vector<double> v;
    const auto nd = all_nodes(e, ex, &v);
    std::vector<double> out;
    for (double x : xs) {
      double s = 0;
      for (size_t k = 0; k < nd.size(); ++k) s += nd[k].w * v[k] * std::log(std::fabs(podetail::diff(x, nd[k]) / podetail::diff(x0, nd[k])));
      out.push_back(2 / podetail::pi * s - ds_ * (x - x0) / 2);
    }
    return out;
  }
  // (2/pi) PV int dq(xi)/(x - xi) dxi at x (pieces cut at x; PV by the symmetric cut:
  // int over the two pieces next to x of (dq(xi) - dq(x))/(x - xi) plus dq(x) log-term)
  double slip_gradient_term(const ends &e, double x) const {
    std::vector<double> v;
    const auto nd = all_nodes(e, {x}, &v);
    const double dx0 = dq(e, x);
    double s = 0;
    for (size_t k = 0; k < nd.size(); ++k) s += nd[k].w * (v[k] - dx0) / podetail::diff(x, nd[k]);
    s += dx0 * std::log((x + 1) / (1 - x));  // PV int_{-1}^{1} dxi/(x - xi)
    return 2 / podetail::pi * s;
  }
  // energy dissipated over the segment in the zone z (1, 2, 3) if every point of it slipped in one
  // direction only: int_zone d p dh dx, dh relative to the stick set (reference point x0 in S)
  double energy(const ends &e, int z, double x0, int npts = 0) const {
    double l, r, d;
    if (z == 1) { l = e.b1; r = 1; d = d1_; }
    else if (z == 2) { l = -1; r = -e.b2; d = d2_; }
    else { l = e.pl; r = e.pr; d = dp_; }
    std::vector<podetail::node> nd;
    std::vector<double> c{l};
    for (double x : cusps_)
      if (x > l && x < r) c.push_back(x);
    c.push_back(r);
    std::vector<double> ex, ew;
    podetail::gauss_legendre(npts ? npts : 8, ex, ew);
    for (size_t k = 0; k + 1 < c.size(); ++k) podetail::piece_nodes(c[k], c[k + 1], ex, ew, 3, nd);
    std::vector<double> xs;
    for (auto &n : nd) xs.push_back(n.x);
    const auto h = slip_change(e, xs, x0);
    double E = 0;
    for (size_t k = 0; k < nd.size(); ++k) E += nd[k].w * d * p_(nd[k].x) * h[k];
    return E;
  }

  static double &at(ends &e, int j) { return j == 0 ? e.b1 : (j == 1 ? e.b2 : (j == 2 ? e.pl : e.pr)); }

 private:
  std::function<double(double)> qS_, p_;
  std::vector<double> cusps_;
  double dQ_, ds_;
  double d1_, d2_, dp_;  // directions (the checks use a non-unit dp as a scale of g on the patch)
  options o_;
  std::vector<double> gx_, gw_;  // the Gauss-Legendre rule of order o_.order
  mutable std::vector<gnode> gn_;
  mutable ends ce_{};
  mutable bool cache_valid_ = false;
};

}}  // namespace hs::reference
