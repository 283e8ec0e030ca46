// halfslip -- independent load-history oracle for one segment after a Hertz ramp: the state
// reached by a straight segment (Q0, s0) -> (Q1, s1) along which both stick-zone ends only advance
// is found by one static solve, with no time stepping (docs/history.md, "Advancing segments in one
// solve"). It shares no code with the library's march (core/history.hpp): it is written from the
// stick-zone integral equation and uses Boost's tanh-sinh quadrature and a 2x2 Newton iteration.
//
// Units (docs/conventions.md): a = p0 = f = E* = 1, Hertz pressure p = sqrt(1 - x^2), loads
// q = Q/(fP) and s = sigma/(f p0); the stick zone is (-b2, b1), c = (b1 - b2)/2.
//
// Start state: the monotonic same-sign Hertz state at (q0, s0) (both zones slipping in the
// direction of q0, e0 = sqrt(1 - |q0|), c0 = s0/4): q_S = sgn p on the slip zones and
// q_S = sgn (p - sqrt(e0^2 - (x - c0)^2)) on the stick zone. (The ramp to it must not recede:
// |s0| <= 2|q0| or e0 > 2|q0/s0|.)
//
// The segment: every point of the final stick zone stays stuck throughout, so its slip gradient
// is unchanged and the traction change dq = q_new - q_S satisfies on it
//     (2/pi) PV int_{-1}^{1} dq(xi)/(x - xi) dxi = ds/2,          int dq = dQ pi/2,
// while on band i (between the new end and the edge) dq = g_i = d_i p - q_S, d_i the new
// direction of zone i (g_i vanishes where zone i keeps slipping in the same direction). The
// bounded solution on the stick zone exists iff (two conditions for b1, b2; W = sqrt|(x-b1)(x+b2)|)
//     ds/4 + (1/pi) [ int_band1 g1/W - int_band2 g2/W ] = 0,
//     int_band1 g1 (x - c)/W - int_band2 g2 (x - c)/W = dQ pi/2,
// and then dq(x) = (w(x)/pi) [ int_band1 g1/(W (xi - x)) - int_band2 g2/(W (xi - x)) ] on the
// stick zone, w = sqrt((b1 - x)(x + b2)). For (q0, s0) = 0 this is the monotonic solution
// (the test checks it against e = sqrt(1 - q), c = s/4). The caller states the new directions;
// the result is only the true state if the ends advance monotonically along the segment, which
// the caller ensures by the choice of the segment (e.g. both r_i reverse at its start and keep
// their sign), and if the final stick traction stays within the friction limit (checked by
// traction_margin).
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

namespace hs { namespace reference {

template <class T> class reversal_oracle {
 public:
  reversal_oracle(const T &q0, const T &s0, const T &q1, const T &s1, int d1, int d2)
      : q0_(q0), s0_(s0), dq_(q1 - q0), ds_(s1 - s0), d1_(d1), d2_(d2) {
    using std::abs;
    using std::sqrt;
    if (!(abs(q0) < 1) || !(abs(q1) < 1)) throw std::invalid_argument("reversal_oracle: |q| >= 1");
    sg_ = q0 > 0 ? 1 : (q0 < 0 ? -1 : 0);
    if (sg_ == 0 && s0 != 0)  // a sigma-only ramp has zones slipping in opposite directions
      throw std::invalid_argument("reversal_oracle: the start must be a same-sign Hertz state (q0 != 0 or s0 = 0)");
    e0_ = sqrt(1 - abs(q0));
    // q < 0: the state is minus that at (-q0, -s0), whose centre is -s0/4
    c0_ = T(sg_) * s0 / 4;
    B1o_ = c0_ + e0_;
    B2o_ = e0_ - c0_;
    if (sg_ != 0 && !(B1o_ <= 1 && B2o_ <= 1)) throw std::invalid_argument("reversal_oracle: start not same-sign");
  }

  T p(const T &x) const {
    using std::sqrt;
    return sqrt((1 - x) * (1 + x));
  }
  // traction of the start state
  T qS(const T &x) const {
    using std::sqrt;
    if (sg_ == 0) return T(0);
    if (x >= B1o_ || x <= -B2o_) return T(sg_) * p(x);
    const T v = x - c0_;
    return T(sg_) * (p(x) - sqrt((e0_ - v) * (e0_ + v)));
  }
  T g(int i, const T &x) const { return T(i == 1 ? d1_ : d2_) * p(x) - qS(x); }

  // int over band i of g_i(x) k(x) / W(x), split at the start state's ends (cusps of q_S)
  template <class K> T band(int i, const T &b1, const T &b2, const K &k) const {
    using std::abs;
    using std::sqrt;
    std::vector<T> pts;
    if (i == 1) {
      pts = {b1};
      if (sg_ != 0 && B1o_ > b1 && B1o_ < 1) pts.push_back(B1o_);
      pts.push_back(T(1));
    } else {
      pts = {T(-1)};
      if (sg_ != 0 && -B2o_ > -1 && -B2o_ < -b2) pts.push_back(-B2o_);
      pts.push_back(-b2);
    }
    T sum = 0;
    for (size_t j = 0; j + 1 < pts.size(); ++j) {
      const T lo = pts[j], hi = pts[j + 1];
      if (!(hi > lo)) continue;
      // Boost passes xc = lo - x (< 0) near lo and hi - x (> 0) near hi: the distances
      // to the ends exact, so W is accurate at the band's inner end
      auto f = [&](const T &x, const T &xc) {
        const T dlo = xc < 0 ? -xc : x - lo, dhi = xc > 0 ? xc : hi - x;
        T W;
        if (i == 1) W = sqrt((j == 0 ? dlo : x - b1) * (x + b2));
        else W = sqrt((j + 2 == pts.size() ? dhi : -b2 - x) * (b1 - x));
        return g(i, x) * k(x) / W;
      };
      sum += ts_.integrate(f, lo, hi, tol());
    }
    return sum;
  }

  // the two conditions at (b1, b2)
  std::array<T, 2> residual(const T &b1, const T &b2) const {
    const T pi = boost::math::constants::pi<T>();
    const T c = (b1 - b2) / 2;
    const T I1 = band(1, b1, b2, [](const T &) { return T(1); });
    const T I2 = band(2, b1, b2, [](const T &) { return T(1); });
    const T J1 = band(1, b1, b2, [&](const T &x) { return x - c; });
    const T J2 = band(2, b1, b2, [&](const T &x) { return x - c; });
    return {{ds_ / 4 + (I1 - I2) / pi, J1 - J2 - dq_ * pi / 2}};
  }

  // Newton from (b1, b2) with a centred-difference Jacobian; stops at the quadrature's noise
  // floor (a step that no longer halves, below 1e3 eps); throws if it does not settle
  std::array<T, 2> solve(T b1, T b2, int max_it = 60) const {
    using std::abs;
    using std::cbrt;
    using std::max;
    const T eps = std::numeric_limits<T>::epsilon();
    const T h = cbrt(eps);
    T last = -1;
    for (int it = 0; it < max_it; ++it) {
      const auto r = residual(b1, b2);
      const auto r1p = residual(b1 + h, b2), r1m = residual(b1 - h, b2);
      const auto r2p = residual(b1, b2 + h), r2m = residual(b1, b2 - h);
      const T j11 = (r1p[0] - r1m[0]) / (2 * h), j21 = (r1p[1] - r1m[1]) / (2 * h);
      const T j12 = (r2p[0] - r2m[0]) / (2 * h), j22 = (r2p[1] - r2m[1]) / (2 * h);
      const T det = j11 * j22 - j12 * j21;
      const T x1 = (r[0] * j22 - r[1] * j12) / det, x2 = (j11 * r[1] - j21 * r[0]) / det;
      using boost::math::isfinite;
      if (!isfinite(x1) || !isfinite(x2))  // e.g. a segment that only continues the ramp: g = 0
        throw std::runtime_error("reversal_oracle: singular Newton step");
      // keep the ends inside the contact and the stick zone non-empty
      T lam = 1;
      while (lam > T(1e-6) && !(b1 - lam * x1 < 1 && b2 - lam * x2 < 1 && b1 - lam * x1 + b2 - lam * x2 > 0))
        lam /= 2;
      b1 -= lam * x1;
      b2 -= lam * x2;
      const T stp = max(abs(x1), abs(x2));
      if (stp <= 8 * eps || (stp <= 1000 * eps && last >= 0 && stp > last / 2)) return {{b1, b2}};
      last = stp;
    }
    throw std::runtime_error("reversal_oracle: Newton did not settle");
  }

  // traction after the segment at a point x of the stick zone (-b2, b1)
  T traction(const T &x, const T &b1, const T &b2) const {
    using std::sqrt;
    const T pi = boost::math::constants::pi<T>();
    const T w = sqrt((b1 - x) * (x + b2));
    const T K1 = band(1, b1, b2, [&](const T &xi) { return 1 / (xi - x); });
    const T K2 = band(2, b1, b2, [&](const T &xi) { return 1 / (xi - x); });
    return qS(x) + w / pi * (K1 - K2);
  }
  // largest d_i q/p - 1 over M points of the stick zone next to end i (<= 0: within the limit)
  T traction_margin(int i, const T &b1, const T &b2, int M = 16) const {
    T worst = -1;
    const T L = b1 + b2;
    for (int k = 1; k < M; ++k) {
      const T x = i == 1 ? b1 - L * T(k) / T(M) : -b2 + L * T(k) / T(M);
      const T v = T(i == 1 ? d1_ : d2_) * traction(x, b1, b2) / p(x) - 1;
      if (v > worst) worst = v;
    }
    return worst;
  }

 private:
  static T tol() {  // tanh-sinh's termination: sqrt(eps) gives about eps (doubly exponential)
    using std::sqrt;
    return sqrt(std::numeric_limits<T>::epsilon());
  }
  T q0_, s0_, dq_, ds_;
  int d1_, d2_, sg_ = 0;
  T e0_{1}, c0_{0}, B1o_{1}, B2o_{1};
  mutable boost::math::quadrature::tanh_sinh<T> ts_;  // (a test oracle: not for concurrent use)
};

}}  // namespace hs::reference
