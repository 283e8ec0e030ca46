// halfslip reference: slow, obviously-correct oracles for the tests.
//
// Each oracle integrates the raw integrals of the paper by tanh-sinh quadrature
// (Boost.Math) in the working type T, independently of every closed form in
// core/. Lengths are in units of a (a = 1); p = p0 sqrt(1 - x^2) with p0 = 1,
// f = 1, E* = 1 unless said otherwise. Convention (docs/conventions.md):
//   q_st(x) = (Q/pi - sigma x / 4) / sqrt(1 - x^2),  Q/(f p0) = (pi/2) q.
#pragma once
#include <array>
#include <cmath>
#include <functional>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/precision.hpp>

namespace hs { namespace reference {

// Termination tolerance eps^(2/3): tanh-sinh converges quadratically, so the
// last level's error is far below the level-to-level difference it stops on.
template <class T> T tol_for() {
  using std::cbrt;
  const T c = cbrt(boost::math::tools::epsilon<T>());
  return c * c;
}

// integral over [lo, hi] of g(x, dist_lo, dist_hi) with accurate distances
// to both ends (tanh-sinh, complement-aware).
template <class T, class G> T integrate_ends(const G &g, const T &lo, const T &hi) {
  const T e = boost::math::tools::epsilon<T>();
  boost::math::quadrature::tanh_sinh<T> ts(20, e * e * e * e);  // see core integrate_ts
  const T L = hi - lo;
  // xc is the exact distance to the nearer end; the distance to the far end
  // is taken from the interval length, not from the rounded abscissa, so that
  // both stay accurate on intervals much shorter than |lo|.
  return ts.integrate(
      [&](const T &x, const T &xc) {
        const T dlo = xc < 0 ? -xc : L - xc;
        const T dhi = xc > 0 ? xc : L + xc;
        return g(x, dlo, dhi);
      },
      lo, hi, tol_for<T>());
}

// Side conditions (A.10) with q_c = s_zone f p - q_st, j = 1, 2:
//   r_j = int_left q_c s^{j-1}/sqrt((s-b1)(s+b2)) - int_right (same).
// Returned scaled by 1/p0 (dimensionless). sR, sL are the slip-traction signs
// (+1 or -1) in the right zone (b1, 1) and the left zone (-1, -b2).
template <class T> std::array<T, 2> side_residuals(const T &q, const T &s, const T &b1, const T &b2, int sR, int sL) {
  using std::sqrt;
  const T pi = boost::math::constants::pi<T>();
  const T Qn = pi * q / 2;  // Q / (f p0 a)
  std::array<T, 2> r{};
  for (int j = 1; j <= 2; ++j) {
    // right zone: t = b1 + u, u in (0, 1 - b1)
    const T right = integrate_ends<T>(
        [&](const T &t, const T &u, const T &v) {  // u = t - b1, v = 1 - t
          const T root1 = sqrt(v * (1 + t));       // sqrt(1 - t^2)
          const T qc = sR * root1 - (Qn / pi - s * t / 4) / root1;
          const T R = sqrt(u * (t + b2));
          return qc * (j == 1 ? T(1) : t) / R;
        },
        b1, T(1));
    const T left = integrate_ends<T>(
        [&](const T &t, const T &u, const T &v) {  // u = t + 1, v = -b2 - t
          const T root1 = sqrt(u * (1 - t));
          const T qc = sL * root1 - (Qn / pi - s * t / 4) / root1;
          const T R = sqrt((b1 - t) * v);
          return qc * (j == 1 ? T(1) : t) / R;
        },
        T(-1), -b2);
    r[j - 1] = left - right;
  }
  return r;
}

// Principal value of int_lo^hi g(t)/(t - x) dt for lo < x < hi, where g may
// have integrable end singularities: subtract g(x) and add g(x) log((hi-x)/(x-lo)).
template <class T, class G> T cauchy_pv(const G &g, const T &lo, const T &hi, const T &x) {
  using std::log;
  const T gx = g(x, x - lo, hi - x);
  // g takes the distances to the ends of the *whole* interval [lo, hi]
  const T left = integrate_ends<T>(
      [&](const T &t, const T &dlo, const T &dx) {
        // dx = x - t; the difference quotient is bounded, its weight at dx -> 0 vanishes
        return dx > 0 ? (g(t, dlo, hi - t) - gx) / -dx : T(0);
      },
      lo, x);
  const T right = integrate_ends<T>(
      [&](const T &t, const T &dx, const T &dhi) { return dx > 0 ? (g(t, t - lo, dhi) - gx) / dx : T(0); }, x, hi);
  return left + right + gx * log((hi - x) / (x - lo));
}

// Dislocation density from eqs (4)/(5) (= (A.8)/(A.9)) with the raw q_c,
// including q_st (whose contribution must vanish), in units of f p0 / E*
// (f = p0 = E* = 1): B(x) for x in either slip zone.
template <class T> T Bx_eq4(const T &q, const T &s, const T &b1, const T &b2, int sR, int sL, const T &x) {
  using std::sqrt;
  const T pi = boost::math::constants::pi<T>();
  const T Qn = pi * q / 2;
  // weight 1/sqrt((t-b1)(t+b2)) times q_c; the (t - x) factor is applied by the caller
  auto gR = [&](const T &t, const T &u, const T &v) {
    const T root1 = sqrt(v * (1 + t));
    const T qcv = sR * root1 - (Qn / pi - s * t / 4) / root1;
    return qcv / sqrt(u * (t + b2));
  };
  auto gL = [&](const T &t, const T &u, const T &v) {
    const T root1 = sqrt(u * (1 - t));
    const T qcv = sL * root1 - (Qn / pi - s * t / 4) / root1;
    return qcv / sqrt((b1 - t) * v);
  };
  const T Rx = sqrt((x - b1) * (x + b2));
  if (x > b1) {
    const T IR = cauchy_pv<T>(gR, b1, T(1), x);
    const T IL = integrate_ends<T>([&](const T &t, const T &u, const T &v) { return gL(t, u, v) / (t - x); }, T(-1),
                                   -b2);
    return -2 / pi * Rx * (IR - IL);
  }
  const T IR = integrate_ends<T>([&](const T &t, const T &u, const T &v) { return gR(t, u, v) / (t - x); }, b1, T(1));
  const T IL = cauchy_pv<T>(gL, T(-1), -b2, x);
  return 2 / pi * Rx * (IR - IL);
}

// Single-zone integrals of the Hertz side conditions, parametrised by the
// zone length d1 = 1 - b1 and e = b1 + b2 (both kept exact: t = b1 + u,
// 1 - t = d1 - u, t + b2 = u + e):
//   A_m = int_{b1}^{1} t^m sqrt(1-t^2) / sqrt((t-b1)(t+b2)) dt, m = 0, 1.
template <class T> T A_moment(int m, const T &d1, const T &e) {
  using std::sqrt;
  return integrate_ends<T>(
      [&](const T &u, const T &du, const T &dv) {  // du = u, dv = d1 - u
        const T t = 1 - d1 + u;
        return (m == 0 ? T(1) : t) * sqrt(dv * (2 - d1 + u)) / sqrt(du * (du + e));
      },
      T(0), d1);
}

// G = int_{b1}^{1} sqrt(1-t^2) / (sqrt((t-b1)(t+b2)) (t - x)) dt at the
// left-zone point x = -b2 - dl: t - x = u + e + dl.
template <class T> T G_integral(const T &d1, const T &e, const T &dl) {
  using std::sqrt;
  return integrate_ends<T>(
      [&](const T &u, const T &du, const T &dv) {
        return sqrt(dv * (2 - d1 + u)) / (sqrt(du * (du + e)) * (du + e + dl));
      },
      T(0), d1);
}

// J_j[g] = int_left g s^{j-1}/R - int_right g s^{j-1}/R for g given as a
// function of (t, 1 - t, 1 + t): the difference identities of Appendix B.
template <class T, class G> T J_difference(int j, const T &b1, const T &b2, const G &g) {
  using std::sqrt;
  const T right = integrate_ends<T>(
      [&](const T &t, const T &u, const T &v) { return g(t, v, 1 + t) * (j == 1 ? T(1) : t) / sqrt(u * (t + b2)); },
      b1, T(1));
  const T left = integrate_ends<T>(
      [&](const T &t, const T &u, const T &v) { return g(t, 1 - t, u) * (j == 1 ? T(1) : t) / sqrt((b1 - t) * v); },
      T(-1), -b2);
  return left - right;
}

// Plain quadrature of a function over [lo, hi] with end distances (for slip
// and energy oracles).
template <class T, class G> T integrate(const G &g, const T &lo, const T &hi) { return integrate_ends<T>(g, lo, hi); }

}}  // namespace hs::reference
