// halfslip core: Hertz contact, slip zones of opposite sign.
//
// Canonical frame (q = Q/fP >= 0, s = sigma/(f p0) >= 0, a = 1): the right
// zone (beta1, 1) slips negative (traction -fp), the left zone (-1, -beta2)
// positive. The side conditions (A.10) with q_c = +-fp - q_st become
//   F1 = pi (beta1 - beta2)/2 + 2 A0 - pi s/4                         = 0
//   F2 = pi (3(beta1^2+beta2^2)/8 - beta1 beta2/4 - 1/2) + 2 A1
//        + pi q/2 - pi s (beta1 - beta2)/8                             = 0
// with A_m = int_{beta1}^{1} t^m sqrt(1-t^2)/sqrt((t-beta1)(t+beta2)) dt
// (the sum form of the two zones = the elementary difference form of
// Appendix B + twice the right-zone integral). A_m and their derivatives are
// complete elliptic integrals (docs/errata.md gives the derivation and the
// corrected printed eqs (23)/(24); tests/test_hertz.cpp proves them against
// direct quadrature).
//
// State: the three lengths d1 = 1 - beta1, d2 = 1 - beta2, e = beta1 + beta2
// (d1 + d2 + e = 2) are carried separately so that each keeps full relative
// accuracy when it is small (d1 near the regime boundary, d1 and d2 for tiny
// loads, e near gross sliding).
#pragma once
#include <algorithm>
#include <cmath>

#include "elliptic.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> struct opposite_state {
  T d1, d2, e;
};

// Carlson-basis quantities of the side conditions at a state.
template <class T> struct opposite_basis {
  T op1, op2, Q, sQ, kc, RF, eRDb, RDb, RJc;
  explicit opposite_basis(const opposite_state<T> &st) {
    using std::sqrt;
    op2 = st.d1 + st.e;  // 1 + beta2
    op1 = st.d2 + st.e;  // 1 + beta1
    Q = op1 * op2;
    sQ = sqrt(Q);
    const T P = 2 * st.e;
    kc = sqrt(P / Q);
    RF = cel(kc, T(1), T(1), T(1)) / sQ;
    const T C = cel(kc, T(1), T(1), T(0));
    eRDb = 3 * C / (2 * sQ);  // e * R_D(0,Q,P), finite as e -> 0
    RDb = eRDb / st.e;
    RJc = 3 * cel(kc, 2 / op1, T(0), T(1)) / (Q * sQ);  // R_J(0,P,Q,2(1+beta2))
  }
};

template <class T> struct opposite_eval {
  T F1, F2, J00, J01, J10, J11;  // residuals and d(F)/d(beta1, beta2)
};

template <class T> opposite_eval<T> opposite_residual(const T &q, const T &s, const opposite_state<T> &st) {
  const T pi_ = pi<T>();
  const T d1 = st.d1, d2 = st.d2;
  const T b1 = 1 - d1, b2 = 1 - d2, bdiff = d2 - d1;  // beta1 - beta2
  const opposite_basis<T> B(st);
  const T A0 = 2 * d1 * (B.RF + bdiff * B.op2 * B.RJc / 3 - d2 * B.eRDb / 3);
  const T poly = -4 * (d1 + d2) + 3 * d1 * d1 - 2 * d1 * d2 + 3 * d2 * d2;  // 3b1^2-2b1b2+3b2^2-4
  const T A1 = d1 * ((4 - 3 * d1 + d2) * B.RF / 2 + B.op2 * poly * B.RJc / 6 - d2 * bdiff * B.eRDb / 2);
  const T a01 = -2 * B.RF + 2 * d1 * (B.op2 * B.RJc - d2 * B.RDb) / 3;
  const T a02 = -2 * d1 * (B.op2 * B.RJc + d2 * B.RDb) / 3;
  const T a11 = (1 - 3 * b1) * B.RF + d1 * ((3 * b1 - b2) * B.op2 * B.RJc - (3 * b1 + b2) * d2 * B.RDb) / 3;
  const T a12 = -d1 * B.RF + d1 * (-(b1 - 3 * b2) * B.op2 * B.RJc + (b1 + 3 * b2) * d2 * B.RDb) / 3;
  opposite_eval<T> r;
  r.F1 = pi_ * bdiff / 2 + 2 * A0 - pi_ * s / 4;
  // D1 = pi(3(b1^2+b2^2)/8 - b1 b2/4 - 1/2) written in d's (no cancellation)
  const T D1 = pi_ * (-(d1 + d2) / 2 + 3 * (d1 * d1 + d2 * d2) / 8 - d1 * d2 / 4);
  r.F2 = D1 + 2 * A1 + pi_ * q / 2 - pi_ * s * bdiff / 8;
  r.J00 = pi_ / 2 + 2 * a01;
  r.J01 = -pi_ / 2 + 2 * a02;
  r.J10 = pi_ * (3 * b1 - b2) / 4 + 2 * a11 - pi_ * s / 8;
  r.J11 = pi_ * (3 * b2 - b1) / 4 + 2 * a12 + pi_ * s / 8;
  return r;
}

// The single-zone moments A0, A1 (exposed for tests).
template <class T> void opposite_moments(const opposite_state<T> &st, T &A0, T &A1) {
  const T d1 = st.d1, d2 = st.d2, bdiff = d2 - d1;
  const opposite_basis<T> B(st);
  A0 = 2 * d1 * (B.RF + bdiff * B.op2 * B.RJc / 3 - d2 * B.eRDb / 3);
  const T poly = -4 * (d1 + d2) + 3 * d1 * d1 - 2 * d1 * d2 + 3 * d2 * d2;
  A1 = d1 * ((4 - 3 * d1 + d2) * B.RF / 2 + B.op2 * poly * B.RJc / 6 - d2 * bdiff * B.eRDb / 2);
}

// G(x) = int_{beta1}^{1} sqrt(1-t^2)/(sqrt((t-beta1)(t+beta2)) (t-x)) dt for a
// point x = -beta2 - dl of the left zone (0 <= dl <= d2), given the state of
// the configuration (beta1, beta2) as (d1, d2, e).
template <class T> T opposite_G_state(const opposite_state<T> &st, const T &dl) {
  const opposite_basis<T> B(st);
  const T opx = st.d2 - dl;             // 1 + x
  const T omx = st.d1 + st.e + dl;      // 1 - x
  const T px = 2 * (st.e + dl) / (B.op1 * omx);  // q_x / Q, no cancellation
  const T RJq = 3 * cel(B.kc, px, T(0), T(1)) / (B.Q * B.sQ);
  return 4 * st.d1 * B.op2 / 3 * (B.RJc + opx / omx * RJq);
}

// Convenience used by hertz_solution::bhat: configuration given by beta's and d's.
template <class T> T opposite_G(const T &b1, const T &b2, const T &d1, const T &d2, const T &dl) {
  opposite_state<T> st{d1, d2, b1 + b2};
  return opposite_G_state(st, dl);
}

// Stick point c of full sliding with opposite-sign zones: the limit of the
// stick zone as s -> infinity, (2/pi)(c sqrt(1-c^2) + asin c) = q.
template <class T> T sliding_stick_point(const T &q) {
  using std::abs; using std::asin; using std::sqrt;
  T lo = -1, hi = 1, c = q * pi<T>() / 4;
  for (int i = 0; i < 200; ++i) {
    const T w = sqrt((1 - c) * (1 + c));
    const T g = 2 / pi<T>() * (c * w + asin(c)) - q;
    if (g > 0) hi = c; else lo = c;
    const T dg = 4 / pi<T>() * w;
    T cn = c - g / dg;
    if (!(cn > lo && cn < hi)) cn = (lo + hi) / 2;
    if (abs(cn - c) <= 4 * eps<T>()) { c = cn; break; }
    c = cn;
  }
  return c;
}

template <class T> struct opposite_result {
  T beta1, beta2, delta1, delta2;
  int iterations;
};

template <class T> T residual_norm(const opposite_eval<T> &r) {
  using std::abs;
  return abs(r.F1) + abs(r.F2);
}

// Solve the opposite-sign side conditions for canonical q >= 0, s > 4(1 - sqrt(1-q)).
template <class T> opposite_result<T> solve_opposite(const T &q, const T &s, int max_iterations) {
  using std::abs; using std::exp; using std::max; using std::min; using std::sqrt;
  const T pi_ = pi<T>();
  const T m = q / (1 + sqrt(1 - q));  // same-sign d1 + s/4
  // Start 1: continue the same-sign lengths across the boundary.
  opposite_state<T> best{};
  T best_norm = -1;
  opposite_eval<T> best_eval{};
  auto consider = [&](opposite_state<T> st) {
    if (!(st.d1 > 0 && st.d2 > 0 && st.e > 0)) return;
    const auto r = opposite_residual(q, s, st);
    const T n = residual_norm(r);
    if (best_norm < 0 || n < best_norm) {
      best = st;
      best_norm = n;
      best_eval = r;
    }
  };
  {
    T d1 = max(s / 4 - m, s * eps<T>());
    T d2 = m + s / 4;
    const T sum = d1 + d2;
    if (sum < T(1.9)) consider({d1, d2, 2 - sum});
  }
  // Start 2: large-s asymptote, stick zone of width e ~ exp(-(pi s/8 - pi c/2)/w) around c.
  {
    const T c = sliding_stick_point(q);
    const T w = sqrt((1 - c) * (1 + c));
    T e = 4 * w * exp(-(pi_ * s / 8 - pi_ * c / 2) / w);
    e = min(e, T(1.8) * (1 - c));
    if (e > 0) consider({1 - c - e / 2, 1 + c - e / 2, e});
  }
  if (best_norm < 0) throw error(status::no_convergence, "opposite-sign regime: no valid starting point");

  opposite_state<T> st = best;
  opposite_eval<T> r = best_eval;
  T norm = best_norm;
  const T tol = 4 * eps<T>();
  const T noise = sqrt(eps<T>());
  T prev_step = -1;
  for (int it = 1; it <= max_iterations; ++it) {
    const T det = r.J00 * r.J11 - r.J01 * r.J10;
    if (!(det != 0)) throw error(status::no_convergence, "opposite-sign regime: singular Jacobian");
    const T db1 = (r.F1 * r.J11 - r.F2 * r.J01) / det;  // beta1 decreases by db1
    const T db2 = (r.J00 * r.F2 - r.J10 * r.F1) / det;
    const T dd1 = db1, dd2 = db2, de = -(db1 + db2);
    // Fraction to the boundary: no length may shrink below a quarter of itself.
    T lam = 1;
    if (dd1 < 0) lam = min(lam, T(0.75) * st.d1 / -dd1);
    if (dd2 < 0) lam = min(lam, T(0.75) * st.d2 / -dd2);
    if (de < 0) lam = min(lam, T(0.75) * st.e / -de);
    opposite_state<T> nst;
    opposite_eval<T> nr;
    T nnorm;
    for (int k = 0;; ++k) {
      nst = {st.d1 + lam * dd1, st.d2 + lam * dd2, st.e + lam * de};
      // keep d1 + d2 + e = 2 exactly in the largest of the three
      if (nst.d1 >= nst.d2 && nst.d1 >= nst.e) nst.d1 = 2 - nst.d2 - nst.e;
      else if (nst.d2 >= nst.e) nst.d2 = 2 - nst.d1 - nst.e;
      else nst.e = 2 - nst.d1 - nst.d2;
      nr = opposite_residual(q, s, nst);
      nnorm = residual_norm(nr);
      if (nnorm <= norm || k >= 6 || lam * max(abs(dd1), abs(dd2)) < noise) break;
      lam /= 2;
    }
    // Step size, relative to each length (all three must settle).
    const T step = max(max(abs(lam * dd1) / st.d1, abs(lam * dd2) / st.d2), abs(lam * de) / st.e);
    const T abs_step = lam * max(abs(dd1), abs(dd2));
    st = nst;
    r = nr;
    norm = nnorm;
    if (step <= tol || abs_step <= tol * eps<T>()) return {1 - st.d1, 1 - st.d2, st.d1, st.d2, it};
    // Rounding-noise regime: the step stopped shrinking quadratically.
    if (abs_step < noise && prev_step >= 0 && abs_step >= prev_step / 2 && lam == 1)
      return {1 - st.d1, 1 - st.d2, st.d1, st.d2, it};
    prev_step = abs_step;
  }
  throw error(status::no_convergence, "opposite-sign regime: Newton iteration did not converge");
}

}}  // namespace hs::core
