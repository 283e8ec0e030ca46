// halfslip -- independent load-history oracle: a collocation boundary-element method that marches a
// (Q, sigma) path in small load increments at constant normal load P.
//
// It shares no code with the library's solvers: it is written directly from the elasticity of two
// elastically similar half-planes (Dundurs beta = 0) and Coulomb friction, and only uses Eigen for
// the dense linear algebra. Tests use it to check the library's load-history solver.
//
// Units (docs/conventions.md): a = 1, p0 = 1, f = 1, E* = 1. Q is Q/(fP) (P = pi/2, so the shear force
// is Q*pi/2), sigma is sigma/(f p0). Energies are in f^2 p0^2 a^2 / E*.
//
// What it computes
// ----------------
// The relative tangential displacement of the surfaces (the slip) at x in (-1, 1) is
//     h(x, t) = (2/pi) int_{-1}^{1} q(xi, t) ln|x - xi| dxi  -  sigma(t) x / 2  +  C(t),
// where q is the shear traction and C(t) an unknown rigid-body relative shift. Its derivative is the
// dislocation density B = dh/dx = (2/pi) PV int q/(x - xi) dxi - sigma/2 (the fully stuck traction
// q_st = (Q/2 - sigma x/4)/sqrt(1 - x^2) gives B = 0 on |x| < 1). The normal load is applied first and
// held; the history starts stuck with q = 0, h = 0 at Q = sigma = 0.
//
// Discretization: N elements on the cosine mesh x_k = -cos(pi k/N), k = 0..N; q is constant on each
// element; h is collocated at the element midpoints with the exact integral of the log kernel over each
// element. The pressure enters as its element average pbar_j (4-point Gauss in theta, x = -cos theta).
// Equilibrium sum_j q_j w_j = Q pi/2 (w_j the element lengths) fixes C.
//
// Time: each path segment is cut into n = max(1, ceil(steps_per_unit * max(|dQ|, |dsigma|/4)))
// equal load increments. At each increment, every element is either
//   stick: h_new = h_old at its midpoint (no slip increment), and |q| <= pbar must hold, or
//   slip : q = s pbar with s = +1 or -1, and s (h_new - h_old) >= 0 must hold.
// The active set is found by a primal-dual active-set iteration started from the previous increment's
// set (every violator switched at once; after 30 iterations only the worst one, to break cycles). Each
// iteration solves the (N+1)x(N+1) linear system by a cached LU factorization of a reference active set
// plus a Woodbury correction for the rows that differ from it (refactored when more than 48 differ).
// If the iteration does not settle within options::max_iterations, run() throws std::runtime_error.
//
// Zones, read from the element states after the last increment of each segment: zone 1 is the run of
// slipping elements, all with the sign of the last one, that touches x = +1 (b1 = 1, dir1 = 0 if the
// last element sticks); zone 2 likewise from x = -1. The zone end is the mesh node between the last
// stick and the first slip element, moved to where the stick-side defect (1 - s q/pbar)^2, extrapolated
// linearly from the two stick elements next to it, vanishes, clamped to the neighbouring element
// midpoints (options::refine_ends = false gives the mesh node). The dissipated energy of an increment
// is sum over slipping elements of |q_j| |h_new - h_old| w_j (backward Euler in time); it is given to
// zone 1 if the element midpoint lies right of the stick-zone centre (b1 - b2)/2 at the end of that
// increment, else to zone 2.
//
// Accuracy (measured by tests/test_bem_history.cpp, Hertz; N = nodes = steps_per_unit):
//   zone ends: max |b - exact| over monotonic, same-sign and unloading cases 3.2e-3 (N = 100),
//     9.5e-4 (200), 5.6e-4 (400), i.e. within 0.5 element width (pi/N) sqrt(1 - b^2) at N = 400
//     (observed 0.01 to 0.11 widths); with refine_ends = false about one element width.
//   monotonic energy per zone: relative error 5.6e-4 (100), 1.4e-4 (200), 3.5e-5 (400): second order.
//   slip profile h: max error 2e-4 of max h at N = 300; equilibrium to rounding (3e-16).
// Defaults (400, 400) cost about 0.2 to 0.5 s per path of unit length on one core.
// Double precision throughout; no globals; run() is reentrant and thread-safe. Cost: O(N^2) per
// increment, plus an O(N^3) factorization after every ~48 boundary changes.

#ifndef HALFSLIP_REFERENCE_BEM_HISTORY_HPP
#define HALFSLIP_REFERENCE_BEM_HISTORY_HPP

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hs { namespace reference { namespace bem {

// The state at the end of one path segment (one entry of the input path).
struct vertex_state {
  double Q = 0, sigma = 0;          // the vertex (normalized loads)
  double b1 = 1, b2 = 1;            // stick zone (-b2, b1) at the vertex
  int dir1 = 0, dir2 = 0;           // slip direction of zones 1, 2 at the vertex; 0 = that edge sticks
  double energy1 = 0, energy2 = 0;  // energy dissipated in zones 1, 2 over the segment ending here
  int steps = 0;                    // load increments used on the segment
  int max_iterations = 0;           // largest active-set iteration count of an increment on the segment
};

struct options {
  int nodes = 400;           // number of elements N
  int steps_per_unit = 400;  // increments per unit of max(|dQ|, |dsigma|/4) along a segment
  int max_iterations = 200;  // active-set iterations per increment before run() throws
  bool refine_ends = true;   // sub-element zone ends (see marcher::zones); false: mesh nodes
};

namespace detail {

constexpr double pi = 3.141592653589793238462643383279502884;

// int ln|u| du antiderivative
inline double F(double u) { return u == 0.0 ? 0.0 : u * std::log(std::fabs(u)) - u; }

class marcher {
 public:
  marcher(const std::function<double(double)> &p, int n)
      : n_(n),
        xe_(n + 1),
        xm_(n),
        w_(n),
        pbar_(n),
        G_(n, n),
        q_(Eigen::VectorXd::Zero(n)),
        h_(Eigen::VectorXd::Zero(n)),
        stick_(n, 1),
        s_(n, 0) {
    if (n < 4) throw std::invalid_argument("bem: need at least 4 elements");
    for (int k = 0; k <= n; ++k) xe_[k] = -std::cos(pi * k / n);
    xe_[0] = -1.0;
    xe_[n] = 1.0;
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    for (int j = 0; j < n; ++j) {
      xm_[j] = 0.5 * (xe_[j] + xe_[j + 1]);
      w_[j] = xe_[j + 1] - xe_[j];
      const double t0 = pi * j / n, t1 = pi * (j + 1) / n;
      double s = 0;
      for (int g = 0; g < 4; ++g) {
        const double th = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * gx[g];
        s += gw[g] * p(-std::cos(th)) * std::sin(th);
      }
      pbar_[j] = std::max(0.0, 0.5 * (t1 - t0) * s / w_[j]);
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) G_(i, j) = (2.0 / pi) * (F(xm_[i] - xe_[j]) - F(xm_[i] - xe_[j + 1]));
    refactor();
  }

  // March from the current loads to (Q1, s1) in nsteps increments; adds the energies.
  void segment(double Q1, double sig1, int nsteps, int maxit, double &e1, double &e2, int &itmax) {
    const double Q0 = Q_, sg0 = sig_;
    for (int k = 1; k <= nsteps; ++k) {
      const double t = double(k) / nsteps;
      const int it = increment(Q0 + t * (Q1 - Q0), sg0 + t * (sig1 - sg0), maxit, e1, e2);
      itmax = std::max(itmax, it);
    }
  }

  // Zone ends. The mesh node between the last stick element k and the first slip element is moved
  // to where the stick-side defect (1 - s q/pbar)^2, extrapolated linearly from elements k-1 and k,
  // vanishes (near an advancing stick-slip boundary 1 - s q/p grows like the square root of the
  // distance), clamped to the midpoints of elements k and k+1. interp = false gives the mesh node.
  void zones(double &b1, double &b2, int &d1, int &d2, bool interp = true) const {
    const int sr = stick_[n_ - 1] ? 0 : s_[n_ - 1];
    const int sl = stick_[0] ? 0 : s_[0];
    d1 = sr;
    d2 = sl;
    b1 = b2 = 1.0;
    if (sr != 0) {
      int k = n_ - 1;
      while (k >= 0 && !stick_[k] && s_[k] == sr) --k;
      b1 = xe_[k + 1];
      if (interp && k >= 1) b1 = end(k, k - 1, sr, b1);
    }
    if (sl != 0) {
      int m = 0;
      while (m < n_ && !stick_[m] && s_[m] == sl) ++m;
      b2 = -xe_[m];
      if (interp && m + 1 < n_) b2 = -end(m, m + 1, sl, -b2);
    }
  }

  // stick elements k (next to the slip zone) and k2 (the one behind it); slip zone of sign s
  double end(int k, int k2, int s, double node) const {
    if (!stick_[k] || !stick_[k2] || !(pbar_[k] > 0) || !(pbar_[k2] > 0)) return node;
    const double d1 = 1 - s * q_[k] / pbar_[k], d2 = 1 - s * q_[k2] / pbar_[k2];
    if (!(d1 >= 0) || !(d2 > d1)) return node;
    const double a = d1 * d1, b = d2 * d2;
    const double x = xm_[k] + (xm_[k] - xm_[k2]) * a / (b - a);
    const int kn = k + (k > k2 ? 1 : -1);  // the first slip element
    const double lo = std::min(xm_[k], xm_[kn]), hi = std::max(xm_[k], xm_[kn]);
    return std::min(std::max(x, lo), hi);
  }

  const std::vector<double> &x() const { return xm_; }
  const Eigen::VectorXd &q() const { return q_; }
  const Eigen::VectorXd &h() const { return h_; }

 private:
  // full system matrix row i (i < n) for the given state: stick -> [G_i, 1], slip -> e_i
  void refactor() {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n_ + 1, n_ + 1);
    for (int i = 0; i < n_; ++i) {
      if (stick_[i]) {
        A.row(i).head(n_) = G_.row(i);
        A(i, n_) = 1.0;
      } else {
        A(i, i) = 1.0;
      }
    }
    A.row(n_).head(n_) = Eigen::Map<const Eigen::RowVectorXd>(w_.data(), n_);
    lu_.compute(A);
    ref_stick_ = stick_;
    zcache_.assign(n_, Eigen::VectorXd());
  }

  const Eigen::VectorXd &zcol(int i) {
    if (zcache_[i].size() == 0) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n_ + 1);
      e[i] = 1.0;
      zcache_[i] = lu_.solve(e);
    }
    return zcache_[i];
  }

  // v_d^T x for a changed row i: (new row - reference row) . x
  double vdot(int i, const Eigen::VectorXd &x) const {
    const double gx = G_.row(i).dot(x.head(n_)) + x[n_] - x[i];  // [G_i,1].x - e_i.x
    return stick_[i] ? gx : -gx;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd &b) {
    std::vector<int> D;
    for (int i = 0; i < n_; ++i)
      if (stick_[i] != ref_stick_[i]) D.push_back(i);
    if (D.size() > 48) {
      refactor();
      D.clear();
    }
    Eigen::VectorXd y = lu_.solve(b);
    if (D.empty()) return y;
    const int k = int(D.size());
    Eigen::MatrixXd Z(n_ + 1, k), cap(k, k);
    for (int d = 0; d < k; ++d) Z.col(d) = zcol(D[d]);
    Eigen::VectorXd vy(k);
    for (int a = 0; a < k; ++a) {
      for (int c = 0; c < k; ++c) cap(a, c) = (a == c ? 1.0 : 0.0) + vdot(D[a], Z.col(c));
      vy[a] = vdot(D[a], y);
    }
    return y - Z * cap.partialPivLu().solve(vy);
  }

  int increment(double Q, double sig, int maxit, double &e1, double &e2) {
    const Eigen::VectorXd hold = h_;
    Eigen::VectorXd b(n_ + 1), qn(n_), hn(n_);
    double hscale = 0;
    for (int it = 1; it <= maxit; ++it) {
      int nstick = 0;
      for (int i = 0; i < n_; ++i) nstick += stick_[i];
      if (nstick == 0) {  // keep one stick element (an all-slip set has no rigid-shift equation)
        int best = 0;
        for (int i = 1; i < n_; ++i)
          if (pbar_[i] > pbar_[best]) best = i;
        stick_[best] = 1;
      }
      for (int i = 0; i < n_; ++i) b[i] = stick_[i] ? hold[i] + 0.5 * sig * xm_[i] : s_[i] * pbar_[i];
      b[n_] = Q * pi / 2;
      const Eigen::VectorXd xs = solve(b);
      qn = xs.head(n_);
      for (int i = 0; i < n_; ++i)
        if (!stick_[i]) qn[i] = s_[i] * pbar_[i];  // exact values on the slip set
      hn = G_ * qn;
      for (int i = 0; i < n_; ++i) hn[i] += xs[n_] - 0.5 * sig * xm_[i];
      hscale = std::max(hscale, (hn - hold).cwiseAbs().maxCoeff());
      const double tol_h = 1e-12 * std::max(hscale, 1e-8), tol_q = 1e-12;
      // violations
      int worst = -1;
      double wv = 0;
      std::vector<int> viol;
      for (int i = 0; i < n_; ++i) {
        double v = 0;
        if (stick_[i]) {
          v = std::fabs(qn[i]) - pbar_[i] * (1 + tol_q) - 1e-15;
        } else {
          v = -(s_[i] * (hn[i] - hold[i])) - tol_h;
          v = v > 0 ? v / std::max(hscale, 1e-300) : v;  // compare on a common scale
        }
        if (v > 0) {
          viol.push_back(i);
          if (v > wv) wv = v, worst = i;
        }
      }
      if (viol.empty()) {
        for (int i = 0; i < n_; ++i)
          if (stick_[i]) hn[i] = hold[i];  // exact: no slip increment
        // energies, attributed with the zones at the end of the increment
        q_ = qn;
        h_ = hn;
        Q_ = Q;
        sig_ = sig;
        double b1, b2;
        int d1, d2;
        zones(b1, b2, d1, d2, false);
        const double centre = 0.5 * (b1 - b2);
        for (int i = 0; i < n_; ++i) {
          if (stick_[i]) continue;
          const double dw = std::fabs(qn[i]) * std::fabs(hn[i] - hold[i]) * w_[i];
          (xm_[i] > centre ? e1 : e2) += dw;
        }
        return it;
      }
      if (it > 30) viol.assign(1, worst);
      for (int i : viol) {
        if (stick_[i]) {
          stick_[i] = 0;
          s_[i] = qn[i] > 0 ? 1 : -1;
        } else {
          stick_[i] = 1;
        }
      }
    }
    throw std::runtime_error("bem: active-set iteration did not settle at Q = " + std::to_string(Q) +
                             ", sigma = " + std::to_string(sig));
  }

  int n_;
  std::vector<double> xe_, xm_, w_, pbar_;
  Eigen::MatrixXd G_;
  Eigen::VectorXd q_, h_;
  std::vector<char> stick_, ref_stick_;
  std::vector<int> s_;
  double Q_ = 0, sig_ = 0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  std::vector<Eigen::VectorXd> zcache_;
};

}  // namespace detail

// March the path (0, 0) -> path[0] -> path[1] -> ... (pairs (Q, sigma), normalized, |Q| < 1) with the
// pressure p(x) on |x| < 1 (normalized by p0; p >= 0). Returns one vertex_state per path entry (the
// zones at that vertex and the energies dissipated on the segment ending there). Optionally returns the
// final element-midpoint abscissae x, shear traction q and accumulated slip h.
inline std::vector<vertex_state> run(const std::function<double(double)> &p,
                                     const std::vector<std::pair<double, double>> &path, const options &o = options(),
                                     std::vector<double> *q_out = nullptr, std::vector<double> *h_out = nullptr,
                                     std::vector<double> *x_out = nullptr) {
  detail::marcher m(p, o.nodes);
  std::vector<vertex_state> out;
  double Q0 = 0, s0 = 0;
  for (const auto &v : path) {
    if (!(std::fabs(v.first) < 1)) throw std::invalid_argument("bem: |Q| must be < 1");
    vertex_state r;
    r.Q = v.first;
    r.sigma = v.second;
    const double len = std::max(std::fabs(v.first - Q0), std::fabs(v.second - s0) / 4);
    r.steps = std::max(1, int(std::ceil(o.steps_per_unit * len - 1e-9)));
    m.segment(v.first, v.second, r.steps, o.max_iterations, r.energy1, r.energy2, r.max_iterations);
    m.zones(r.b1, r.b2, r.dir1, r.dir2, o.refine_ends);
    out.push_back(r);
    Q0 = v.first;
    s0 = v.second;
  }
  if (x_out) *x_out = m.x();
  if (q_out) q_out->assign(m.q().data(), m.q().data() + m.q().size());
  if (h_out) h_out->assign(m.h().data(), m.h().data() + m.h().size());
  return out;
}

}}}  // namespace hs::reference::bem

#endif
