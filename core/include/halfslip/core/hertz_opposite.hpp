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
#include <limits>
#include <type_traits>

#include "elliptic.hpp"
#include "newton.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

// le = ln e is authoritative only when e is below the normal range of T (a
// stick zone narrower than ~1e-308 a in double, reached for sigma/(f p0) of
// a few hundred and more); otherwise it may be left 0 and ln e is taken
// from e. The solver keeps both.
template <class T> struct opposite_state {
  T d1, d2, e;
  T le{0};
};

// ln e of a state (see opposite_state)
template <class T> T log_width(const opposite_state<T> &st) {
  using std::log;
  return st.e >= boost::math::tools::min_value<T>() ? T(log(st.e)) : st.le;
}

// Carlson-basis quantities of the side conditions at a state. lkc = ln kc is
// computed only where cel_log reads it (kc <= cel_switch<T>(), a stick zone
// narrower than ~eps^1.2); elsewhere it is NaN.
template <class T> struct opposite_basis {
  T op1, op2, Q, sQ, kc, lkc, RF, eRDb, RJc;
  explicit opposite_basis(const opposite_state<T> &st) {
    using std::exp;
    using std::log;
    using std::sqrt;
    op2 = st.d1 + st.e;  // 1 + beta2
    op1 = st.d2 + st.e;  // 1 + beta1
    Q = op1 * op2;
    sQ = sqrt(Q);
    if (st.e >= boost::math::tools::min_value<T>()) {
      const T P = 2 * st.e;
      kc = sqrt(P / Q);
      lkc = kc > cel_switch<T>() ? std::numeric_limits<T>::quiet_NaN() : T(log(kc));
    } else {
      // stick zone below the range of T: the modulus from ln e (it may
      // underflow too; cel_log then uses its logarithm)
      lkc = (log(T(2)) + st.le - log(Q)) / 2;
      kc = exp(lkc);
    }
    // the three share the modulus: one pass (elliptic.hpp, cel3)
    const cel_triple<T> c = cel3_log(kc, lkc, T(2 / op1));
    RF = c.c111 / sQ;
    eRDb = 3 * c.c110 / (2 * sQ);       // e * R_D(0,Q,P), finite as e -> 0
    RJc = 3 * c.cp / (Q * sQ);          // R_J(0,P,Q,2(1+beta2))
  }
};

// 3 b1^2 - 2 b1 b2 + 3 b2^2 - 4 written in d1 = 1 - b1, d2 = 1 - b2
template <class T> T moments_poly(const T &d1, const T &d2) {
  return -4 * (d1 + d2) + 3 * d1 * d1 - 2 * d1 * d2 + 3 * d2 * d2;
}

// The single-zone moments A0, A1 from the Carlson basis B of the state (d1, d2, e)
// (docs/errata.md: the corrected eqs (23)/(24)).
template <class T, class Basis> void opposite_moments_of(const Basis &B, const T &d1, const T &d2, T &A0, T &A1) {
  const T bdiff = d2 - d1;
  A0 = 2 * d1 * (B.RF + bdiff * B.op2 * B.RJc / 3 - d2 * B.eRDb / 3);
  A1 = d1 * ((4 - 3 * d1 + d2) * B.RF / 2 + B.op2 * moments_poly(d1, d2) * B.RJc / 6 - d2 * bdiff * B.eRDb / 2);
}

// Residuals and their derivatives in the coordinates c = (beta1 - beta2)/2
// (centre of the stick zone) and ln e (e = beta1 + beta2). Written so that
// every entry stays finite as e -> 0: R_D(0,Q,P) ~ 1/sqrt(e) enters only as
// e*R_D, and the derivative in e only as e*dF/de (= dF/d ln e).
template <class T> struct opposite_eval {
  T F1, F2;
  T F1c, F2c;  // dF/dc at fixed e
  T F1l, F2l;  // dF/d(ln e) at fixed c
  T mag;       // sum of the magnitudes of the terms of F1 and F2 (their rounding scale)
};

// The side conditions F1, F2 at a state from its basis B (Carlson
// quantities: op2, RF, eRDb, RJc)
template <class T, class Basis>
void opposite_conditions(const T &q, const T &s, const opposite_state<T> &st, const Basis &B, T &F1, T &F2, T &D1) {
  const T pi_ = pi<T>();
  const T d1 = st.d1, d2 = st.d2;
  const T bdiff = d2 - d1;  // beta1 - beta2
  T A0, A1;
  opposite_moments_of(B, d1, d2, A0, A1);
  F1 = pi_ * bdiff / 2 + 2 * A0 - pi_ * s / 4;
  // D1 = pi(3(b1^2+b2^2)/8 - b1 b2/4 - 1/2) written in d's (no cancellation)
  D1 = pi_ * (-(d1 + d2) / 2 + 3 * (d1 * d1 + d2 * d2) / 8 - d1 * d2 / 4);
  F2 = D1 + 2 * A1 + pi_ * q / 2 - pi_ * s * bdiff / 8;
}

// Their derivatives (opposite_eval's F1c, F2c, F1l, F2l) from the basis B
template <class T, class Basis> void opposite_derivatives(const T &s, const opposite_state<T> &st, const Basis &B,
                                                          T &F1c, T &F2c, T &F1l, T &F2l) {
  const T pi_ = pi<T>();
  const T d1 = st.d1, d2 = st.d2, e = st.e;
  const T b1 = 1 - d1, bdiff = d2 - d1;
  // (x/3 as x * (1/3): the derivatives only steer Newton)
  const T third = T(1) / 3;
  const T oRJ = B.op2 * B.RJc;
  F1c = pi_ - 4 * B.RF + 8 * d1 * oRJ * third;
  F2c = pi_ * bdiff - pi_ * s / 4 + 2 * (2 - 4 * b1) * B.RF + 8 * d1 * third * (bdiff * oRJ - d2 * B.eRDb);
  F1l = -2 * e * B.RF - 4 * d1 * d2 * B.eRDb * third;
  F2l = pi_ * e * e / 4 + 2 * e * (-b1 * B.RF + d1 * e * oRJ * third) - 2 * d1 * bdiff * d2 * B.eRDb * third;
}

// Basis is the provider of the Carlson quantities (default: cel-based
// opposite_basis; bench/ swaps in Boost's and GSL's R_F/R_D/R_J).
template <class T, class Basis = opposite_basis<T>>
opposite_eval<T> opposite_residual(const T &q, const T &s, const opposite_state<T> &st) {
  const T pi_ = pi<T>();
  const T d1 = st.d1, d2 = st.d2;
  const T bdiff = d2 - d1;  // beta1 - beta2
  const Basis B(st);
  opposite_eval<T> r;
  T D1;
  opposite_conditions(q, s, st, B, r.F1, r.F2, D1);
  {
    using std::abs;
    const T poly = moments_poly(d1, d2);
    // the terms of A0, A1 grow like ln(1/e) d1 / (d1 + e)^(3/2) as e -> 0 near
    // Q -> fP, far beyond pi s: the rounding of F is judged on them
    // (a rounding scale: x/3 as x * (1/3))
    const T third = T(1) / 3;
    const T t0 = abs(B.RF) + (abs(bdiff * B.op2 * B.RJc) + abs(d2 * B.eRDb)) * third;
    const T t1 = abs((4 - 3 * d1 + d2) * B.RF) / 2 + abs(B.op2 * poly * B.RJc) * third / 2 + abs(d2 * bdiff * B.eRDb) / 2;
    r.mag = pi_ * (abs(bdiff) + s / 2 + q / 2) + abs(D1) + 4 * d1 * t0 + 2 * d1 * t1;
  }
  opposite_derivatives(s, st, B, r.F1c, r.F2c, r.F1l, r.F2l);
  return r;
}

// The single-zone moments A0, A1 (exposed for tests: the residual's own formulas).
template <class T> void opposite_moments(const opposite_state<T> &st, T &A0, T &A1) {
  opposite_moments_of(opposite_basis<T>(st), st.d1, st.d2, A0, A1);
}

// G(x) = int_{beta1}^{1} sqrt(1-t^2)/(sqrt((t-beta1)(t+beta2)) (t-x)) dt for a
// point x = -beta2 - dl of the left zone (0 <= dl <= d2), given the state of
// the configuration (beta1, beta2) as (d1, d2, e).
template <class T> T opposite_G_state(const opposite_state<T> &st, const T &dl) {
  const opposite_basis<T> B(st);
  const T opx = st.d2 - dl;                      // 1 + x
  const T omx = st.d1 + st.e + dl;               // 1 - x
  const T px = 2 * (st.e + dl) / (B.op1 * omx);  // q_x / Q, no cancellation
  const T RJq = 3 * cel_log(B.kc, B.lkc, px, T(0), T(1)) / (B.Q * B.sQ);
  return 4 * st.d1 * B.op2 / 3 * (B.RJc + opx / omx * RJq);
}

// Stick point of full sliding with opposite-sign zones, the limit of the
// stick zone as s -> infinity: (2/pi)(c sqrt(1-c^2) + asin c) = q. With
// c = cos(psi/2) this is psi - sin(psi) = pi (1 - q), psi in (0, pi], solved by
// Newton (convex, from the cubic small-psi start); returns c and
// w = sqrt(1 - c^2) = sin(psi/2), both without cancellation as q -> 1.
// Running out of max_iterations throws no_convergence.
template <class T> void sliding_stick_point(const T &q, T &c, T &w, int max_iterations = 100) {
  using std::abs;
  using std::cbrt;
  using std::cos;
  using std::min;
  using std::sin;
  const T target = pi<T>() * (1 - q);
  T psi = min(cbrt(6 * target), pi<T>());
  int i = 0;
  for (; i < max_iterations; ++i) {
    const T h = y_minus_sin(psi) - target;
    const T sh = sin(psi / 2);
    const T dpsi = h / (2 * sh * sh);
    psi = min(psi - dpsi, pi<T>());
    if (abs(dpsi) <= 2 * eps<T>() * psi) break;
  }
  check_iterations(i, max_iterations, "sliding stick point: Newton iteration did not converge");
  c = cos(psi / 2);
  w = sin(psi / 2);
}

template <class T> struct opposite_result {
  T beta1, beta2, delta1, delta2;
  T width;  // beta1 + beta2, kept separately: full relative accuracy when tiny
  int iterations;
  T log_width;  // ln(width), finite when width underflows
};

template <class T> T residual_norm(const opposite_eval<T> &r) {
  using std::abs;
  return abs(r.F1) + abs(r.F2);
}

// The opposite-sign side conditions as a problem of damped_newton
// (newton.hpp), in log coordinates for the lengths that may be tiny: (c, ln e)
// while the right slip zone is longer than the stick zone, (ln d1, ln e) once
// d1 < e (near the regime boundary), so that every iterate keeps d1, e > 0
// and the Jacobian stays well conditioned as d1 -> 0 or e -> 0.
template <class T, class Basis> struct opposite_problem {
  using real = T;
  using state = opposite_state<T>;
  using eval = opposite_eval<T>;
  const T &q, &s;
  T floor0;
  bool near_boundary = false;
  T dd1 = 0, dd2 = 0, rel_de = 0;  // length changes of the last trial
  bool handoff = false;            // a refinement in a wider type follows (shortcut)
  T last_conv = -1;                // relative size of the last accepted step
  bool last_full = false;          // ... and whether it was a full step
  bool at_floor = false;           // the residual of the current state is at its rounding floor

  opposite_problem(const T &q_, const T &s_) : q(q_), s(s_) {
    // Residuals are sums of terms of size <= pi (1 + s): rounding leaves them
    // at a few eps times that; a result is accepted only at that level.
    floor0 = 64 * eps<T>() * pi<T>() * (1 + s);
  }
  eval residual(const state &st) const { return opposite_residual<T, Basis>(q, s, st); }
  // rounding of the residual: of its terms (mag) and of the state itself (the
  // lengths are known to an ulp of 2, and F moves by F_c per unit length;
  // F_c ~ 1/(d1 + e) grows large as Q -> fP at large sigma)
  T floor(const eval &f) const {
    using std::abs;
    using std::max;
    return max(floor0, 64 * eps<T>() * f.mag + 8 * eps<T>() * (abs(f.F1c) + abs(f.F2c)));
  }
  jacobian2<T> jacobian(const state &st, const eval &r) {
    near_boundary = st.d1 < st.e;
    at_floor = residual_norm(r) <= floor(r);
    // x = c: columns (Fc, Fl). x = ln d1 at fixed e: dc = -d1 dx, and at fixed
    // d1 a change of ln e moves c by -e/2 d(ln e).
    if (!near_boundary) return {r.F1c, r.F1l, r.F2c, r.F2l};
    return {-st.d1 * r.F1c, r.F1l - st.e / 2 * r.F1c, -st.d1 * r.F2c, r.F2l - st.e / 2 * r.F2c};
  }
  // Hand-off to the refinement in a wider type (refine_opposite, which is
  // itself a Newton step): once the full step is so small that the state it
  // leads to is within ~1e-10 of the root (the quadratic convergence
  // measured on the last two steps), or the residual is already at its
  // rounding floor (near the regime boundary, where d1 is a small
  // difference, the steps stop shrinking there), it is taken unevaluated and
  // the iteration ends; the wider step then removes what is left (its own
  // error ~ K (1e-10)^2). Only where such a refinement follows (handoff).
  bool shortcut(state &st, const T &dx, const T &dy, const T &) {
    using std::abs;
    using std::max;
    if (!handoff) return false;
    // relative change of each length the full step would make
    T rd1, rd2;
    const T rde = abs(dy);
    if (!near_boundary) {
      rd1 = abs(dx + st.e * dy / 2) / st.d1;
      rd2 = abs(dx - st.e * dy / 2) / st.d2;
    } else {
      rd1 = abs(dx);
      rd2 = abs(st.d1 * dx + st.e * dy) / st.d2;
    }
    const T rel = max(max(rd1, rd2), rde);
    bool take;
    if (at_floor) {
      // the residual is rounding: the step is of the size of that noise (the
      // lengths are as good as T can make them), and small enough that the
      // wider step takes it from here: 1e-8 relative, or where d1 is a
      // tiny difference near the regime boundary (its relative step is
      // noise of order eps s/d1) 1e-6 relative with lengths moved by < 1e-12
      const T ad1 = near_boundary ? T(abs(st.d1 * dx)) : T(abs(dx + st.e * dy / 2));
      take = rel <= T(1e-8) || (rel <= T(1e-6) && ad1 <= T(1e-12) && rde <= T(1e-12));
    } else if (last_conv > 0 && last_full) {
      const T K = rel / (last_conv * last_conv);  // contraction constant of the last step
      take = rel <= T(1e-4) && rel <= last_conv / 8 && K * rel * rel <= T(1e-10);
    } else {
      take = rel <= T(1e-9);
    }
    if (!take) return false;
    state nst;
    if (!trial(st, T(1), dx, dy, nst)) return false;
    st = nst;
    return true;
  }
  // trust region in ln d1 as in ln e
  void cap_x(T &dx, T &dy) const {
    using std::abs;
    const T cap = 4;
    if (near_boundary && abs(dx) > cap) {
      dy *= cap / abs(dx);
      dx = dx > 0 ? cap : -cap;
    }
  }
  bool trial(const state &st, const T &lam, const T &dx, const T &dy, state &nst) {
    using boost::math::expm1;
    using boost::math::isfinite;
    using std::exp;
    using std::expm1;
    using std::log;
    rel_de = expm1(lam * dy);
    const T de = st.e * rel_de;
    if (!near_boundary) {
      const T dc = lam * dx;
      dd1 = -dc - de / 2;
      dd2 = dc - de / 2;
    } else {
      dd1 = st.d1 * expm1(lam * dx);
      dd2 = -dd1 - de;
    }
    // fraction to the boundary for the linearly updated lengths
    if (st.d1 + dd1 <= st.d1 / 4 || st.d2 + dd2 <= st.d2 / 4) return false;
    // e from ln e: it may be below the range of T (then only le carries it)
    const T nle = st.le + lam * dy;
    // (with a hand-off, the iterates need not be consistent to the last ulp:
    // e + de, without a second exponential, where e is in T's range)
    const T ne = handoff && st.e >= boost::math::tools::min_value<T>() ? T(st.e + de) : T(exp(nle));
    nst = {st.d1 + dd1, st.d2 + dd2, ne, nle};
    // keep d1 + d2 + e = 2 exactly in the largest of the three
    if (nst.d1 >= nst.d2 && nst.d1 >= nst.e) nst.d1 = 2 - nst.d2 - nst.e;
    else if (nst.d2 >= nst.e) nst.d2 = 2 - nst.d1 - nst.e;
    else {
      const T e0 = nst.e;
      nst.e = 2 - nst.d1 - nst.d2;
      // the recomputed e differs from e0 by roundings only (dd1 + dd2 + de
      // = 0): ln e to first order in the difference, without a logarithm
      const T rel = (nst.e - e0) / e0;
      using std::abs;
      nst.le = handoff && abs(rel) <= T(1e-8) ? T(nle + rel) : T(log(nst.e));
    }
    return isfinite(nst.le) && nst.e >= 0;
  }
  // relative change of each length (all three must settle); the stalled-step
  // test on the absolute change of d1, d2
  newton_steps<T> steps(const state &st, const T &lam, const T &, const T &) {
    using std::abs;
    using std::max;
    const newton_steps<T> r{max(max(abs(dd1) / st.d1, abs(dd2) / st.d2), T(abs(rel_de))), max(abs(dd1), abs(dd2))};
    last_conv = r.conv;
    last_full = lam == 1;
    return r;
  }
  bool converged(const T &, const T &step, const T &norm, const T &floor) const {
    return step <= 4 * eps<T>() && norm <= floor;
  }
};

// Newton's method from a start; true on convergence (out, iterations set).
// handoff: a refinement in a wider type follows (opposite_problem::shortcut);
// le_set: start.le is ln start.e (else it is computed here).
template <class T, class Basis = opposite_basis<T>>
bool opposite_newton(const T &q, const T &s, const opposite_state<T> &start, int max_iterations,
                     opposite_state<T> &out, int &iterations, bool handoff = false, bool le_set = false) {
  using boost::math::isfinite;
  opposite_state<T> st = start;
  if (!le_set) st.le = log_width(st);
  if (!(st.e >= 0) || !isfinite(st.le) || !(st.d1 > 0) || !(st.d2 > 0)) return false;
  opposite_problem<T, Basis> p(q, s);
  p.handoff = handoff;
  const newton_outcome o = damped_newton(p, st, p.residual(st), max_iterations);
  if (!o.converged) return false;
  out = st;
  iterations = o.iterations;
  return true;
}

// Wider type for one step of iterative refinement of a converged solution
// (double -> long double); other types refine in themselves (no-op).
template <class T> struct refine_type { using type = T; };
template <> struct refine_type<double> { using type = long double; };

// One Newton step with the residual and Jacobian evaluated in the wider type
// R: removes the rounding error the residual's O(pi s) terms leave in the
// lengths, so that d1, d2 come out to a few ulps relative, not absolute.
template <class T, class R> opposite_state<T> refine_opposite(const T &q, const T &s, const opposite_state<T> &st) {
  using std::abs;
  using std::exp;
  using std::expm1;
  using std::log;
  // a wider type may hold a stick zone that underflows in T (long double: e
  // down to ~1e-4900)
  // (st.le as Newton carries it: ln st.e)
  const R le = R(st.le != 0 ? st.le : log_width(st));
  const R ew = st.e >= boost::math::tools::min_value<T>() ? R(st.e) : R(exp(le));
  // the largest of the three lengths carries the rounding of d1 + d2 + e = 2
  // in T; in R it is recomputed from the other two, else the residual is
  // evaluated off the constraint and (near Q -> fP, where the side
  // conditions are nearly parallel) the step amplifies that by 1e3 or more
  opposite_state<R> w{R(st.d1), R(st.d2), ew, le};
  bool e_exact = true;  // w.e = exp(le) (le is ln e as carried)
  if (w.d1 >= w.d2 && w.d1 >= w.e) w.d1 = 2 - w.d2 - w.e;
  else if (w.d2 >= w.e) w.d2 = 2 - w.d1 - w.e;
  else {
    w.e = 2 - w.d1 - w.d2;
    e_exact = false;
  }
  // the side conditions in R; their derivatives (a correction of a few ulps
  // needs them only roughly) in T, from the same Carlson quantities
  const opposite_basis<R> BR(w);
  R F1, F2, D1;
  opposite_conditions(R(q), R(s), w, BR, F1, F2, D1);
  struct {
    T op2, RF, eRDb, RJc;
  } BT{T(BR.op2), T(BR.RF), T(BR.eRDb), T(BR.RJc)};
  T F1c, F2c, F1l, F2l;
  opposite_derivatives(s, opposite_state<T>{T(w.d1), T(w.d2), T(w.e), T(w.le)}, BT, F1c, F2c, F1l, F2l);
  // coordinates (c, ln e): dc changes d1 by -dc, d2 by +dc; ln e as in Newton
  const auto x = solve2x2(R(F1c), R(F1l), R(F2c), R(F2l), F1, F2);
  if (!(x.det != 0)) return st;
  const R dc = -x.x1, dl = -x.x2;
  // expm1 of a small correction by its series (|dl| <= 1e-6 leaves dl^4/24 < 5e-20 dl)
  const R de = w.e * (abs(dl) <= R(1e-6) ? R(dl * (1 + dl / 2 * (1 + dl / 3))) : R(expm1(dl)));
  opposite_state<R> n{w.d1 - dc - de / 2, w.d2 + dc - de / 2, w.e + de, le + dl};
  if (!(n.d1 > 0 && n.d2 > 0 && n.e >= 0)) return st;
  // a refinement step is a small correction; anything else means the wider
  // evaluation disagrees, and the converged state is kept
  // (ln e is weakly determined when the stick zone is tiny, and of size
  // ~ sigma/(f p0): its correction is judged relative to it)
  if (abs(dc) > R(1e-6) || abs(dl) > R(1e-6) * (1 + abs(le))) return st;
  // ln of the new e: le + dl, where le is ln w.e (to the rounding of le in T:
  // within an ulp of T's ln e) unless w.e was recomputed above
  const T ne = T(n.e);
  if (e_exact || !(n.e >= boost::math::tools::min_value<R>())) return {T(n.d1), T(n.d2), ne, T(n.le)};
  // w.e was recomputed from the other two: it differs from ew (= exp(le))
  // by roundings of T, and ln w.e = le + (w.e - ew)/ew to first order
  const R rel = (w.e - ew) / ew;
  if (abs(rel) <= R(1e-8)) return {T(n.d1), T(n.d2), ne, T(n.le + rel)};
  return {T(n.d1), T(n.d2), ne, T(log(n.e))};
}

// The result from a converged state: one refinement step in the wider type
// where there is one (refine_opposite), then the betas.
template <class T> opposite_result<T> finish_opposite(const T &q, const T &s, opposite_state<T> x, int iterations) {
  using W = typename refine_type<T>::type;
  if (!std::is_same<W, T>::value) x = refine_opposite<T, W>(q, s, x);
  const T beta1 = 1 - x.d1;
  T beta2 = 1 - x.d2;
  // A stick zone narrower than the rounding of beta1, beta2 (large sigma)
  // must not come out with -b2 > b1: clamp it to zero width in the betas
  // (its true width stays in x.e).
  if (beta1 + beta2 < 0) beta2 = -beta1;
  return {beta1, beta2, x.d1, x.d2, x.e, iterations, log_width(x)};
}

// Solve the opposite-sign side conditions for canonical q >= 0, s > 4(1 - sqrt(1-q))
// without the stored start (solve_opposite): Newton from the better of two starts: the same-sign lengths continued
// across the boundary, and the large-sigma asymptote (stick zone of width
// e ~ 4w exp(-(pi s/8 - pi c/2)/w) about the sliding stick point c). Should
// both fail (seen only for Q/fP > 1 - 1e-5 just past the regime boundary),
// continuation in sigma from the boundary, where the solution is known.
template <class T, class Basis = opposite_basis<T>>
opposite_result<T> solve_opposite_legacy(const T &q, const T &s, int max_iterations, int spent = 0) {
  using boost::math::isfinite;
  using std::exp;
  using std::ldexp;
  using std::log;
  using std::max;
  using std::min;
  using std::sqrt;
  const T pi_ = pi<T>();
  const T m = q / (1 + sqrt(1 - q));  // same-sign d1 + s/4
  opposite_state<T> best{};
  T best_norm = -1;
  auto consider = [&](opposite_state<T> st) {
    if (!(st.d1 > 0 && st.d2 > 0 && st.e >= 0 && isfinite(log_width(st)))) return;
    const T n = residual_norm(opposite_residual<T, Basis>(q, s, st));
    if (best_norm < 0 || n < best_norm) {
      best = st;
      best_norm = n;
    }
  };
  const T d1_lin = max(s / 4 - m, s * eps<T>());
  consider({d1_lin, m + s / 4, 2 - d1_lin - (m + s / 4)});  // rejected unless e > 0
  // The asymptote is needed when the first start is invalid or its stick
  // zone is already narrow.
  if (best_norm < 0 || best.e < T(0.5)) {
    T c_inf, w;
    sliding_stick_point(q, c_inf, w);
    // in logarithms: e itself underflows for s of a few hundred
    T le = log(4 * w) - (pi_ * s / 8 - pi_ * c_inf / 2) / w;
    le = min(le, T(log(T(1.8) * (1 - c_inf))));
    const T e = exp(le);
    consider({1 - c_inf - e / 2, 1 + c_inf - e / 2, e, le});
  }
  if (best_norm < 0)
    throw error(
        status::overflow,
        "opposite-sign regime: the logarithm of the stick-zone width is not representable (sigma/(f p0) too large)");
  opposite_state<T> st;
  int its = 0;
  using W = typename refine_type<T>::type;
  auto finish = [&](const opposite_state<T> &x, int n) { return finish_opposite(q, s, x, n); };
  const bool handoff = !std::is_same<W, T>::value;
  if (opposite_newton<T, Basis>(q, s, best, max_iterations, st, its, handoff)) return finish(st, spent + its);
  // Continuation: s_k = s_b + (s - s_b) 2^(k-K); d1 grows linearly from 0.
  const T sb = 4 * m, span = s - sb;
  const int K = 40;
  opposite_state<T> cur{span * ldexp(T(1), -K) / 4, 2 * m, 0};
  cur.e = 2 - cur.d1 - cur.d2;
  int total = spent + its;
  for (int k = K; k >= 0; --k) {
    const T sk = k == 0 ? s : sb + span * ldexp(T(1), -k);
    opposite_state<T> next;
    int n = 0;
    if (!opposite_newton<T, Basis>(q, sk, cur, max_iterations, next, n))
      throw error(status::no_convergence, "opposite-sign regime: Newton iteration did not converge");
    total += n;
    cur = next;
    if (k > 0) {  // predictor: d1 ~ linear in s - s_b near the boundary
      const T grow = cur.d1;
      cur.d1 += grow;
      if (cur.e > 2 * grow) cur.e -= grow;
      else cur.d2 -= grow;
    }
  }
  return finish(cur, total);
}


// A stored start for the double solve (issue 16): the solution on a 33 x 33
// grid over
//   x = (1 - r)/(1 - r_max), r = (1 - q)^(1/3)   (q in [0, q_max], q_max = 0.999),
//   y = D/(K w + D (1 - K/D_max)), D = s - s_b(q)  (y = 1 at D = D_max w),
// with K = 8, D_max = 80 and w = sin(psi/2) of the sliding stick point (the
// scale on which the stick zone closes: e ~ exp(-pi D/(8 w)) for large D), of
// three smooth quantities (Y = D/(1 + D))
//   A = ln(d1 / Y)                     (d1 ~ D near the boundary, saturates),
//   B = ((d2 - d1)/(2 m) - 1)/Y        (the stick centre c, = m at the boundary),
//   C = (L - L_b)/Y, L = ln e + (pi s/8 - pi c_inf/2)/w and L_b its value
//       at the boundary (e = 2 sqrt(1 - q), s = 4 m); L tends to a
//       constant as D -> infinity,
// of which B and C carry their error times Y: near the boundary, where d1
// is small and a start error in c or ln e would move it by that error
// squared over d1, c and e start exact to first order in D.
// interpolated by 4 x 4-point Lagrange (bicubic) in (x, y). Beyond D_max w the
// saturated row is used, with the true s in C. The table is built on first
// use by the solver itself from the starts of solve_opposite_legacy (1089
// solves, about 1 ms), so that it is the library's own solution; it is
// immutable afterwards. Its accuracy only decides how many Newton steps
// follow (tests/test_hertz.cpp measures it), never the result.
struct opposite_start_table {
  static constexpr int nx = 33, ny = 33;
  static constexpr double r_max = 0.1;  // (1 - q_max)^(1/3)
  static constexpr double q_max = 0.999;
  static constexpr double K = 8, D_max = 80;
  double A[nx][ny], B[nx][ny], C[nx][ny];
  double W[nx];  // w at the x nodes
  bool ok = true;        // every node solved (else the table is not used)

  static double q_of_x(double x) {
    const double r = 1 - x * (1 - r_max);
    return 1 - r * r * r;
  }
  static double D_of_y(double w, double y) { return K * w * y / (1 - y * (1 - K / D_max)); }

  opposite_start_table() {
    const double pi_ = pi<double>();
    for (int i = 0; i < nx; ++i) {
      // the column q = 0 is the limit q -> 0 of B (taken at q = 1e-8)
      const double q = i == 0 ? 1e-8 : q_of_x(double(i) / (nx - 1));
      double c, w;
      sliding_stick_point(q, c, w);
      W[i] = w;
      const double m = q / (1 + std::sqrt(1 - q));
      for (int j = 0; j < ny; ++j) {
        // the row y = 0 is the limit D -> 0 (taken at D = 1e-7 w)
        const double D = j == 0 ? 1e-7 * w : D_of_y(w, double(j) / (ny - 1));
        const double s = 4 * m + D;
        const double Da = s - 4 * m, Y = Da / (1 + Da);
        const double Lb = std::log(2 * std::sqrt(1 - q)) + (pi_ * m / 2 - pi_ * c / 2) / w;
        try {
          const auto r = solve_opposite_legacy<double>(q, s, 100);
          A[i][j] = std::log(r.delta1 / Y);
          B[i][j] = ((r.delta2 - r.delta1) / (2 * m) - 1) / Y;
          C[i][j] = (r.log_width + (pi_ * s / 8 - pi_ * c / 2) / w - Lb) / Y;
        } catch (const error &) {
          ok = false;
        }
      }
    }
  }

  static const opposite_start_table &get() {
    static const opposite_start_table t;
    return t;
  }

  // 4-point Lagrange weights at position f (grid units) in a grid of n nodes;
  // returns the stencil's first node
  static int weights(double f, int n, double w[4]) {
    int i0 = int(f) - 1;
    if (i0 < 0) i0 = 0;
    if (i0 > n - 4) i0 = n - 4;
    const double t0 = f - i0, t1 = t0 - 1, t2 = t0 - 2, t3 = t0 - 3;
    const double sixth = 1.0 / 6;
    w[0] = -t1 * t2 * t3 * sixth;
    w[1] = t0 * t2 * t3 * 0.5;
    w[2] = -t0 * t1 * t3 * 0.5;
    w[3] = t0 * t1 * t2 * sixth;
    return i0;
  }

  // the start at (q, s); false outside the table (q > q_max) or where it
  // would not be a valid state
  bool start(double q, double s, opposite_state<double> &st) const {
    if (!ok || !(q >= 0 && q <= q_max)) return false;
    const double pi_ = pi<double>();
    const double r = std::cbrt(1 - q);
    double wx[4];
    const int i0 = weights((1 - r) / (1 - r_max) * (nx - 1), nx, wx);
    double w = 0;
    for (int a = 0; a < 4; ++a) w += wx[a] * W[i0 + a];
    const double m = q / (1 + std::sqrt(1 - q));
    const double D = s - 4 * m;
    if (!(D > 0) || !(w > 0)) return false;
    double y = D / (K * w + D * (1 - K / D_max));
    double yy = D / (1 + D);
    const bool sat = y > 1;
    double c_exact = 0;
    if (sat) {
      // beyond D_max the stick zone (e < 1e-13 e_b) sits at the sliding stick
      // point to within e, and ln e ~ -pi D/(8 w): c_inf and w to the last
      // ulp, not interpolated (the side conditions' sensitivity to c grows
      // like ln(1/e))
      y = 1;
      yy = D_max * w / (1 + D_max * w);
      sliding_stick_point(q, c_exact, w);
    }
    double wy[4];
    const int j0 = weights(y * (ny - 1), ny, wy);
    double Av = 0, Bv = 0, Cv = 0;
    for (int a = 0; a < 4; ++a) {
      double ra = 0, rb = 0, rc = 0;
      for (int b = 0; b < 4; ++b) {
        ra += wy[b] * A[i0 + a][j0 + b];
        rb += wy[b] * B[i0 + a][j0 + b];
        rc += wy[b] * C[i0 + a][j0 + b];
      }
      Av += wx[a] * ra;
      Bv += wx[a] * rb;
      Cv += wx[a] * rc;
    }
    st.d1 = std::exp(Av) * yy;
    st.d2 = st.d1 + 2 * m * (1 + yy * Bv);
    // ln e = L_b + Y C - (pi s/8 - pi c_inf/2)/w = ln e_b + Y C - pi D/(8 w),
    // e_b = 2 sqrt(1 - q): one exponential, and the logarithm of the final e
    const double t = yy * Cv - pi_ * D / (8 * w);
    const bool tiny = t < -700;  // e below the range of double: ln e carries it
    if (tiny) {
      st.le = std::log(2 * std::sqrt(1 - q)) + t;
      st.e = std::exp(st.le);
    } else {
      st.e = 2 * std::sqrt(1 - q) * std::exp(t);
    }
    if (sat) {
      st.d1 = 1 - c_exact - st.e / 2;
      st.d2 = 1 + c_exact - st.e / 2;
      if (!tiny) st.le = std::log(st.e);
      return st.d1 > 0 && st.d2 > 0 && std::isfinite(st.le);
    }
    // d1 + d2 + e = 2 in the largest
    if (st.e >= st.d1 && st.e >= st.d2) {
      st.e = 2 - st.d1 - st.d2;
      if (!(st.e > 0)) return false;
      st.le = std::log(st.e);
    } else {
      if (st.d2 >= st.d1) st.d2 = 2 - st.d1 - st.e;
      else st.d1 = 2 - st.d2 - st.e;
      if (!tiny) st.le = std::log(st.e);
    }
    return st.d1 > 0 && st.d2 > 0 && std::isfinite(st.le);
  }
};

// Solve the opposite-sign side conditions for canonical q >= 0, s > 4(1 - sqrt(1-q)).
// In double, Newton from the stored start (opposite_start_table; up to 16
// iterations, then the path below); otherwise, and for Q/fP > 0.999, the
// starts and the continuation of solve_opposite_legacy.
template <class T, class Basis = opposite_basis<T>>
opposite_result<T> solve_opposite(const T &q, const T &s, int max_iterations) {
  int spent = 0;
  if constexpr (std::is_same<T, double>::value) {
    opposite_state<double> st0, st;
    if (opposite_start_table::get().start(q, s, st0)) {
      const int cap = max_iterations < 16 ? max_iterations : 16;
      int its = 0;
      if (opposite_newton<T, Basis>(q, s, st0, cap, st, its, true, true)) return finish_opposite(q, s, st, its);
      spent = cap;
    }
  }
  return solve_opposite_legacy<T, Basis>(q, s, max_iterations, spent);
}

}}  // namespace hs::core
