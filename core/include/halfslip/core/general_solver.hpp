// halfslip core, general pressures (general.hpp): the solver: Newton at a
// fixed order (the damped_newton kernel of newton.hpp), the starts (Hertz,
// shear-only, large sigma), continuation in sigma, and the order control.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <boost/math/tools/precision.hpp>

#include "general_post.hpp"
#include "general_residual.hpp"
#include "hertz.hpp"
#include "newton.hpp"
#include "numerics.hpp"
#include "pressure.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> struct general_options {
  int max_iterations = 100;  // Newton iterations per solve (continuation: per step)
  T rtol = T(0);             // 0: full precision of T
  int max_order = 1024;      // largest Gauss-Legendre order per panel (solver, energies and slips)
  // A start from a solve at a lower precision (issue 16: the reference backend
  // starts its work tier from the double solution and its check tier from the
  // work tier's): the canonical state x1 = +-d1 (+ same sign, - opposite sign),
  // ln e, and the order at which Newton begins (at least the one the tolerance
  // gives; 0: that one). Only a start: the order control and the tolerances are
  // unchanged, and if Newton fails from it the usual starts follow.
  bool has_start = false;
  T start_x1 = T(0), start_ln_e = T(0);
  int start_order = 0;
  // With a start: its first Newton step may be taken unevaluated when K s^2 is far
  // below the step tolerance (solve_general; issue 16). false: the old path, which
  // evaluates the residual after every step (tests compare the two).
  bool start_shortcut = true;
};

namespace gdetail {

template <class T> T residual_norm(const general_eval<T> &r) {
  using std::abs;
  return abs(r.F1) + abs(r.F2);
}

// The unified side conditions at fixed order n as a problem of damped_newton
// (newton.hpp), in (x1, ln e).
template <class T> struct general_problem {
  using real = T;
  using state = general_state<T>;
  using eval = general_eval<T>;
  const pressure_model<T> &pm;
  const T &q, &s;
  int n;
  const T &tol_step;
  T noise_floor;

  bool quadratic;  // the Jacobian is exact (pressure_model::exact_dphi): Newton converges quadratically

  general_problem(const pressure_model<T> &pm_, const T &q_, const T &s_, int n_, const T &tol_step_)
      : pm(pm_), q(q_), s(s_), n(n_), tol_step(tol_step_) {
    noise_floor = 64 * eps<T>() * pi<T>() * (1 + s);
    quadratic = pm.exact_dphi();
  }
  eval residual(const state &st) const { return general_residual(pm, q, s, st, n, true); }
  // the rounding floor of |F1| + |F2|: the quadrature's own (64 eps pi (1 + s))
  // or, where larger, 4 grains of the state (general_eval::grain)
  T floor(const eval &r) const {
    using std::max;
    return max(noise_floor, T(4 * r.grain));
  }
  jacobian2<T> jacobian(const state &, const eval &r) const { return {r.J11, r.J12, r.J21, r.J22}; }
  // Quadratic convergence (issue 16): full steps s_k, s_{k+1} <= s_k/4 give
  // K = s_{k+1}/s_k^2 (s_{k+2} ~ K s_{k+1}^2 in the quadratic regime of Newton with
  // the exact Jacobian); kest is the latest such estimate (-1: none), last_full the
  // last full step (-1: none, or the last step was damped). A Newton at the doubled
  // order starts with the estimate of the run at the order before (the same side
  // conditions, to the quadrature's difference): its first step, from the order-n
  // solution, is that difference, and where K s^2 is far below the step tolerance
  // it is taken without evaluating the residual there (that evaluation would only
  // confirm it; the order control's next residual, at the doubled order, is taken
  // at the new state anyway).
  T kest = -1, last_full = -1;
  // a full step below the step tolerance after a converging one: take it
  // without evaluating the residual there (it would only confirm the step).
  // Likewise a step s whose successor K s^2 is below an eighth of the step
  // tolerance, with K the largest of kest, 1 and 1/(the shorter zone): after a
  // converging step with an estimate of K, or (the first step, no estimate) a
  // step already below the step tolerance (the evaluation there judged only
  // the decrease of the Newton correction, which a step that small passes).
  // (K = max(1, kest) alone, without the zone, sent three scenes of the grid of
  // docs/benchmarks.md from order 16 to 32: kest from two steps can be low.)
  // Only with an exact Jacobian: with the default difference quotient of phi'
  // (power law n = 1.5, q = 0.1, sigma/fp0 = 10) the steps fell 1e-6, 2e-9,
  // 1.5e-12 (linear) where K s^2 predicted 4e-18 after 2e-9
  bool shortcut(state &st, const T &dx, const T &dy, const T &prev_step) const {
    using std::abs;
    using std::exp;
    using std::max;
    using std::min;
    const T step = max(abs(dx), abs(dy));
    bool take = prev_step >= 0 && step <= tol_step && step <= prev_step;
    if (!take && quadratic &&
        ((kest > 0 && (last_full < 0 || step <= last_full / 4)) || (prev_step < 0 && step <= tol_step))) {
      const T d1 = st.d1(), d2 = st.d2();
      const T dmin = d2 > 0 ? min(d1, d2) : d1;
      T K = max(T(1), kest);
      if (dmin > 0) K = max(K, T(1 / dmin));
      take = K * step * step <= tol_step / 8;
    }
    if (!take) return false;
    state nst;
    if (!trial(st, T(1), dx, dy, nst)) return false;
    st = nst;
    return true;
  }
  // x1 = +-d1 moves by at most the contact half-width
  void cap_x(T &dx, T &dy) const {
    using std::abs;
    if (abs(dx) > 1) {
      dy /= abs(dx);
      dx = dx > 0 ? T(1) : T(-1);
    }
  }
  bool trial(const state &st, const T &lam, const T &dx, const T &dy, state &nst) const {
    nst = st.step(lam * dx, lam * dy);
    const T nd2 = nst.d2();
    // (the width may leave the range of T: ln e carries it, issue 13)
    return nst.ln_e == nst.ln_e && nst.ln_e < 1 && nd2 > st.d2() / 4 && nst.d1() < 2;
  }
  newton_steps<T> steps(const state &, const T &lam, const T &dx, const T &dy) {
    using std::abs;
    using std::max;
    const T step = max(abs(lam * dx), abs(lam * dy));
    if (lam == 1) {
      if (last_full > 0 && step <= last_full / 4) kest = step / last_full / last_full;
      last_full = step;
    } else {
      kest = last_full = -1;
    }
    return {step, step};
  }
  bool converged(const T &lam, const T &step, const T &, const T &) const { return lam == 1 && step <= tol_step; }
};

// Newton from a start at fixed order n; true on convergence. iterations is
// increased by the iterations begun. kest (if given): the estimate of K of
// general_problem from the run at the order before (-1: none), and on return
// this run's.
template <class T> bool newton(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int n,
                               const T &tol_step, int max_it, int &iterations, const general_eval<T> *r0 = nullptr,
                               T *kest = nullptr) {
  general_problem<T> p(pm, q, s, n, tol_step);
  if (kest) p.kest = *kest;
  const newton_outcome o = damped_newton(p, st, r0 ? *r0 : p.residual(st), max_it);
  if (kest) *kest = o.converged ? p.kest : T(-1);
  iterations += o.iterations;
  // a state without a finite ln e (a width that underflowed with no logarithm
  // carried) is not a solution, even where the kernel's singular-Jacobian rule
  // (newton.hpp) accepts it: the residual no longer depends on the width there
  // (flat punch, sigma/fp0 = 2000: d1 was 0.762 for 0.643)
  using std::isfinite;
  return o.converged && bool(isfinite(st.lw()));
}

// Newton that raises the order where it stalls on the quadrature's own error
// (issue 13, near sliding). Newton works at a fixed order n, whose residual is
// a smooth function of the state only where the rule resolves the integrands;
// near sliding (1 - |Q/fP| ~ 1e-10) the order the tolerance gives (16 in double)
// does not: the residual at order 16 jumps by 2.4e-8 in F2 where a graded
// panel is added (power law n = 6.79, sigma/fp0 = 1), or is off by 3.9e-7
// throughout (n = 9.875, sigma/fp0 = -2.2: at order 16 F2 has no root, and
// Newton ran ln e to -infinity), while F2 itself is ~1e-11 there (the moment
// condition is nearly flat near sliding). Newton then stalls above the noise
// floor. Where it stalls and the residual at 2n differs from the one at n by
// more than that floor at the stalled state, the order is doubled (n is
// updated) and Newton goes on from there, while 4n stays within max_order
// (the order control validates at 2n). False when it stalls at a resolved
// order, or at the order limit.
template <class T>
bool newton_raising_order(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int &n,
                          int max_order, const T &tol_step, int max_it, int &iterations, int max_raise) {
  using std::abs;
  using std::isfinite;
  general_state<T> start = st;
  if (newton(pm, q, s, st, n, tol_step, max_it, iterations)) return true;
  // at most max_raise doublings: in a region far from the root the orders may
  // disagree at every order, and Newton at order 1024 cost 6 s there (flat punch
  // b_f/a = 0.95, 1 - Q/fP = 1e-6, sigma/fp0 = 10, from the Hertz start; the
  // continuation in sigma solves it in 0.15 s)
  for (int raised = 0; raised < max_raise && 4 * n <= max_order; ++raised) {
    const general_problem<T> p(pm, q, s, 2 * n, tol_step);
    // whether the residual at order n differs from the one at 2n at a state by
    // more than the floor (r2: the residual at 2n there)
    auto unresolved = [&](const general_state<T> &x, const general_eval<T> &r2) {
      const general_eval<T> rn = general_residual(pm, q, s, x, n, false);
      const T change = abs(rn.F1 - r2.F1) + abs(rn.F2 - r2.F2);
      return change > p.floor(r2);
    };
    auto usable = [](const general_state<T> &x) { return x.d2() > 0 && x.d1() < 2 && bool(isfinite(x.lw())); };
    // at the stalled state, at the full Newton step from it (the order-n
    // residual may jump between the two: flat punch b_f/a = 0.8, 1 - Q/fP =
    // 4.5e-11, sigma/fp0 = 0.018, by 8e-11 in F2 across a step of 0.02 in ln e),
    // or at the start (Newton at order n may have left it for a region where
    // the orders agree: the same punch at 1 - Q/fP = 1e-10, sigma/fp0 = 1, from
    // the near-sliding start at order 32); Newton at 2n goes on from the stalled
    // state, or from the start where only the start is unresolved
    bool raise = false;
    general_state<T> from = st;
    if (usable(st)) {
      const general_eval<T> r2 = general_residual(pm, q, s, st, 2 * n, true);
      raise = unresolved(st, r2);
      if (!raise) {
        const auto x = solve2x2(r2.J11, r2.J12, r2.J21, r2.J22, r2.F1, r2.F2);
        if (x.det != 0) {
          const general_state<T> full = st.step(-x.x1, -x.x2);
          if (usable(full)) raise = unresolved(full, general_residual(pm, q, s, full, 2 * n, false));
        }
      }
    }
    if (!raise && usable(start) && unresolved(start, general_residual(pm, q, s, start, 2 * n, false))) {
      raise = true;
      from = start;
    }
    if (!raise) return false;  // resolved (or NaN): a genuine stall
    n *= 2;
    st = from;
    start = from;
    if (newton(pm, q, s, st, n, tol_step, max_it, iterations)) return true;
  }
  return false;
}

// Bracketed Illinois iteration for a root of f on [lo, hi] (f(lo), f(hi) of
// opposite signs) until done(lo, hi) or f vanishes; false if the iteration
// limit is reached first or f is NaN.
template <class T, class F, class Done>
bool illinois_until(F f, T lo, T hi, T flo, T fhi, Done done, T &root) {
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    T m = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(m > lo && m < hi)) m = (lo + hi) / 2;
    const T fm = f(m);
    if (!(fm == fm)) return false;
    if ((fm < 0) == (flo < 0)) {
      lo = m;
      flo = fm;
      if (side == -1) fhi /= 2;
      side = -1;
    } else {
      hi = m;
      fhi = fm;
      if (side == +1) flo /= 2;
      side = +1;
    }
    if (done(lo, hi) || fm == 0) {
      root = fm == 0 ? m : (lo + hi) / 2;
      return true;
    }
  }
  return false;
}
// ... to an absolute bracket width tol
template <class T, class F> bool illinois(F f, T lo, T hi, T flo, T fhi, const T &tol, T &root) {
  return illinois_until(f, lo, hi, flo, fhi, [&](const T &l, const T &h) { return h - l <= tol; }, root);
}

// Start at s = 0: the restriction of F2 to b1 = b2 = 1 - d (e = 2 - 2d),
// F2(d) = I2L - I2R + pi q/2, falls monotonically from pi q/2 (d = 0) to
// pi (q - 1)/2 (d -> 1); bracketed Illinois iteration in d to sqrt(eps) d.
// (For a symmetric pressure this is eq (15) and b1 = b2 exactly; for an
// asymmetric one it is a start for the 2D Newton.) The iteration limit is
// not an error: the result is only a start, which Newton validates (and
// reports no_convergence if it cannot finish from it).
template <class T> general_state<T> shear_only_start(const pressure_model<T> &pm, const T &q, int n) {
  using std::abs;
  using std::sqrt;
  auto F = [&](const T &d) { return general_residual(pm, q, T(0), general_state<T>{d, 2 * (1 - d)}, n, false).F2; };
  const T tol = sqrt(eps<T>());
  T d = T(1) / 2;  // (the limit reached, or F not finite: a start all the same)
  // relative to the bracket's upper end: slip zones far narrower than sqrt(eps) a (issue 13:
  // the flat punch at b_f/a = 1 - 1e-8, Q/fP = 0.9 has d = 7.8e-9 at s = 0; an absolute
  // sqrt(eps) left the start at d ~ 1e-8 off, Newton failed from it, and every
  // 0 < sigma/fp0 < 3 there ended in NO_CONVERGENCE)
  illinois_until(F, T(0), T(1), pi<T>() * q / 2, pi<T>() * (q - 1) / 2,
                 [&](const T &lo, const T &hi) { return hi - lo <= tol * hi; }, d);
  return {d, 2 * (1 - d)};
}

// Sliding stick point (issue 13): as s grows the stick zone shrinks onto the
// point x0 where the limiting friction forces of the two slip zones balance
// Q, q pi/2 = int_{-1}^{x0} p_hat - int_{x0}^{1} p_hat, i.e. the tail of p_hat
// beyond x0 is pi (1 - q)/4. Returns d_inf = 1 - x0 (Illinois on the tail,
// which grows monotonically with its length; false if the iteration limit is
// reached).
template <class T> bool sliding_point(const pressure_model<T> &pm, const T &q, T &d_inf) {
  const T target = pi<T>() * (1 - q) / 4;
  return illinois_until([&](const T &d) { return pm.tail(+1, d) - target; }, T(0), T(2), -target,
                        pi<T>() / 2 - target, [](const T &lo, const T &hi) { return hi - lo <= 4 * eps<T>() * hi; },
                        d_inf);
}

// Start for large s (issue 13): the stick zone centred on the sliding stick
// point x0, its width e from F1 = 0 at that centre. F1 is nearly linear in
// ln e once e << 1 (the zone integrals grow like ln(1/e)): secant steps in
// ln e from two small widths. Newton in (x1, ln e) then follows x0 and the
// width on a log scale. False if no such start exists (the stick zone would
// be below the range of T: then ln e carries it, general_state). The secant
// limit is not an error: the result is only a start, validated by Newton.
template <class T>
bool large_sigma_start(const pressure_model<T> &pm, const T &q, const T &s, int n, general_state<T> &out) {
  using std::abs;
  using std::exp;
  using std::log;
  using std::max;
  using std::min;
  T d_inf;
  if (!sliding_point(pm, q, d_inf) || !(d_inf > 0 && d_inf < 2)) return false;
  // F1 = G - pi s/4 with G the zone integrals (F1 at s = 0): the secant on G
  // against pi s/4, so that a large s does not swamp the differences of G
  // (at sigma/fp0 = 1e20 one ulp of pi s/4 is 16384)
  auto G = [&](const T &le) {
    const T e = exp(le);
    return general_residual(pm, q, T(0), general_state<T>::from_log(-(d_inf - e / 2), le), n, false).F1;
  };
  const T target = pi<T>() * s / 4;
  const T cap = log(min(min(T(1), T(d_inf / 2)), T((2 - d_inf) / 2)));
  T l0 = min(T(-8), cap), l1 = l0 - 8;
  T g0 = G(l0), g1 = G(l1);
  for (int it = 0; it < 30; ++it) {
    if (!(g1 != g0) || !(g0 == g0) || !(g1 == g1)) return false;
    // (the slope first: no overflow at huge s; a step beyond the range of T is
    // cut to half of it, sigma/fp0 ~ 1e308)
    T l2 = l1 - (g1 - target) / ((g1 - g0) / (l1 - l0));
    if (!(l2 >= -boost::math::tools::max_value<T>())) l2 = -boost::math::tools::max_value<T>() / 2;
    l2 = min(l2, cap);
    if (!(abs(l2) <= boost::math::tools::max_value<T>())) return false;
    const T g2 = G(l2);
    l0 = l1;
    g0 = g1;
    l1 = l2;
    g1 = g2;
    if (abs(l1 - l0) <= T(1e-3) * (1 + abs(l1))) break;
  }
  const T e = exp(l1);
  out = general_state<T>::from_log(-(d_inf - e / 2), l1);
  return out.d2() > 0;
}

// Start near sliding, same sign (issue 13). As q -> 1 at sigma != 0 the stick
// zone shrinks onto a point x0, and the two conditions separate: F1 tends to a
// finite limit in x0 alone (the 1/sqrt singularities of the two zones' I1 at the
// stick zone cancel for zones slipping the same way: x0 is where the profile's
// slope matches sigma, at the rounded corner for a flat punch), while F2, the
// moment about the centre, tends to pi (q - 1)/2 whatever x0 is and fixes the
// width through its O(e^2) part. The Hertz start puts the stick zone where
// Hertz's would be (for a flat punch b_f/a = 0.8 at 1 - Q/fP = 1e-10, sigma/fp0
// = 1: in the flat part, where the conditions do not depend on it, |J| ~ 1e-9),
// and the continuation in sigma from the shear-only zone (e = 1.6 a for that
// punch) must follow the zone's collapse onto x0 within sigma/fp0 ~ 1e-3. Here:
// x1 from F1 at a small width e0 (a scan of 32 points for a sign change, then
// Illinois), then ln e from F2 at that x1 (Illinois in ln e). Only a start,
// validated by Newton; false where no sign change is found.
template <class T>
bool near_sliding_start(const pressure_model<T> &pm, const T &q, const T &s, int n, general_state<T> &out) {
  using std::log;
  using std::sqrt;
  if (!(q > T(0.99)) || !(q < 1)) return false;
  T e0 = 2 * sqrt(1 - q);
  if (e0 > T(1e-3)) e0 = T(1e-3);
  auto F1 = [&](const T &x1) { return general_residual(pm, q, s, general_state<T>{x1, e0}, n, false).F1; };
  // the scan: 32 points evenly, and towards either end geometrically down to
  // e0 (a stick point next to an edge: flat punch b_f/a = 0.5, sigma/fp0 = 5,
  // 1 - |Q/fP| = 1e-11, d1 ~ 0.01 a)
  const int m = 32;
  const T top = 2 - e0;
  std::vector<T> pts;
  for (T x = top / m; x > 2 * e0; x /= 4) pts.insert(pts.begin(), x / 2);
  const std::size_t ng = pts.size();  // (at most ~30: top/m down to e0 >= 2e-8 by 4s)
  for (int i = 1; i < m; ++i) pts.push_back(top * i / m);
  for (std::size_t i = ng; i-- > 0;) pts.push_back(top - pts[i]);
  T x1 = -1;
  T pa = pts[0], fa = F1(pa);
  for (std::size_t i = 1; i < pts.size() && x1 < 0; ++i) {
    const T pb = pts[i], fb = F1(pb);
    if (fa == fa && fb == fb && (fa < 0) != (fb < 0)) {
      T r;
      if (!illinois(F1, pa, pb, fa, fb, T(64 * eps<T>()), r)) return false;
      x1 = r;
    }
    pa = pb;
    fa = fb;
  }
  if (!(x1 > 0)) return false;
  // ln e from F2 at x1: F2 -> pi (q - 1)/2 < 0 as e -> 0; up from ln e0 until it turns
  auto F2 = [&](const T &le) { return general_residual(pm, q, s, general_state<T>::from_log(x1, le), n, false).F2; };
  T la = log(e0), f2a = F2(la);
  T lb = la, f2b = f2a;
  const T lmax = log(T(2 - x1));
  if (f2a < 0) {
    while (f2b < 0 && lb < lmax) {
      la = lb;
      f2a = f2b;
      lb = lb + 1 < lmax ? lb + 1 : lmax;
      f2b = F2(lb);
    }
  } else {
    const T lmin = log(T(tiny_width<T>()));
    while (f2a >= 0 && la > lmin) {
      lb = la;
      f2b = f2a;
      la -= 1;
      f2a = F2(la);
    }
  }
  if (!(f2a < 0) || !(f2b >= 0)) return false;
  T le;
  if (!illinois(F2, la, lb, f2a, f2b, T(1e-6), le)) return false;
  out = general_state<T>::from_log(x1, le);
  return out.d2() > 0 && out.d1() < 2;
}

// The near-sliding start at an order that resolves it (issue 13, round two). The
// start's ln e comes from F2, whose O(e^2) signal (~1e-11) is below the error of
// the order the tolerance gives (16 in double): at order 16 the start's ln e was
// off by 1.2 (flat punch b_f/a = 0.5, 1 - Q/fP = 1e-11, sigma/fp0 = 3: -13.65 for
// -12.44), Newton from it left for ln e ~ -17.6 at every order up to 128, and
// the continuation failed after it. Here the start is made at n and 2n, doubling
// n (up to 4 times, 4n within max_order) until the two agree (x1 to 1e-6, ln e
// to 0.05); n is then the lower of the two orders and out the start at 2n. False
// where they never agree (the caller then tries the start at the entry order, as
// before: two agreeing starts need not lead Newton to the root, flat punch
// b_f/a = 0.8, 1 - Q/fP = 1e-13, sigma/fp0 = 1). entry (entry_ok): the start at the
// entry order, made first, for that fallback.
template <class T>
bool near_sliding_start_resolved(const pressure_model<T> &pm, const T &q, const T &s, int &n, int max_order,
                                 general_state<T> &out, general_state<T> &entry, bool &entry_ok) {
  using std::abs;
  general_state<T> a;
  bool has_a = near_sliding_start(pm, q, s, n, a);
  entry = a;
  entry_ok = has_a;
  int m = n;
  for (int k = 0; k < 4 && 4 * m <= max_order; ++k) {
    general_state<T> b;
    const bool has_b = near_sliding_start(pm, q, s, 2 * m, b);
    if (has_a && has_b && abs(a.x1 - b.x1) <= T(1e-6) && abs(a.lw() - b.lw()) <= T(0.05)) {
      out = b;
      n = m;
      return true;
    }
    a = b;
    has_a = has_b;
    m *= 2;
  }
  return false;
}

// A root of f near x0 (f's sign change within x0 -+ h, h doubled up to 8 times),
// to tol; false if none is bracketed or the iteration limit is reached.
template <class T, class F> bool local_root(F f, const T &x0, T h, const T &lo_lim, const T &hi_lim, const T &tol,
                                            T &root) {
  T a = x0 - h > lo_lim ? T(x0 - h) : lo_lim, b = x0 + h < hi_lim ? T(x0 + h) : hi_lim;
  T fa = f(a), fb = f(b);
  for (int k = 0; k < 8 && fa == fa && fb == fb && (fa < 0) == (fb < 0); ++k) {
    h *= 2;
    a = x0 - h > lo_lim ? T(x0 - h) : lo_lim;
    b = x0 + h < hi_lim ? T(x0 + h) : hi_lim;
    fa = f(a);
    fb = f(b);
  }
  if (!(fa == fa && fb == fb) || (fa < 0) == (fb < 0)) return false;
  return illinois(f, a, b, fa, fb, tol, root);
}

// Near sliding, same sign (issue 13): the moment condition F2 is pi (q - 1)/2 plus
// O(e^2) terms, ~1e-13 at 1 - Q/fP = 1e-13, against the rounding of its O(1) terms
// (~4 eps pi) and Newton's acceptance floor (64 eps pi (1 + s) for |F1| + |F2|), so
// Newton may stop with ln e off by 0.3 (flat punch b_f/a = 0.5, 1 - Q/fP = 1e-13,
// sigma/fp0 = -3: d2 off by 1.3e-7 a against an estimate of 1.2e-7 relative). The
// two conditions nearly separate there (F1 fixes x1, F2 fixes ln e; J21 ~ e^2), so
// the state is polished by bracketed root finding in each in turn at order n (three
// passes): a sign change is located to the rounding of F itself, whatever the
// floor. Kept only if every step brackets a root.
template <class T>
bool polish_near_sliding(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int n) {
  using std::exp;
  using std::log;
  general_state<T> w = st;
  if (!(w.x1 > 0) || !(w.e > 0)) return false;
  for (int pass = 0; pass < 3; ++pass) {
    const T x1 = w.x1;
    auto F2 = [&](const T &le) { return general_residual(pm, q, s, general_state<T>::from_log(x1, le), n, false).F2; };
    T le;
    if (!local_root(F2, w.lw(), T(0.125), T(w.lw() - 16), T(log(T(2 - x1))), T(1e-12), le)) return false;
    const T e = exp(le);
    auto F1 = [&](const T &x) { return general_residual(pm, q, s, general_state<T>::from_log(x, le), n, false).F1; };
    T nx;
    const T h = 4 * e + 64 * eps<T>() * x1;
    if (!local_root(F1, x1, h, T(x1 / 2), T(2 - e), T(4 * eps<T>() * x1), nx)) return false;
    w = general_state<T>::from_log(nx, le);
  }
  if (!(w.d2() > 0) || !(w.x1 > 0)) return false;
  st = w;
  return true;
}

// Where the polish runs: within 1e-8 of sliding, same sign, and only in double and
// long double, whose Newton floor can hide F2 there. Beyond (the reference's MPFR
// tiers) Newton's floor is far below F2, and the polish's ln e tolerance (1e-12)
// would cap the digits that the tiers certify.
template <class T> bool polish_applies(const T &q, const general_state<T> &st) {
  return std::numeric_limits<T>::digits <= 64 && q > 1 - T(1e-8) && st.x1 > 0;
}

// The curve (issue 13: the power law n -> 1 under larger sigma). F2, the moment about
// the centre, has no s, and F1 = F1|_(s=0) - pi s/4: the solutions for every s of the
// scene's q lie on the curve F2(x1, ln e) = 0, along which F1 fixes s. Where the stick
// zone's left end -b2 crosses a cusp of the pressure (the power law's x = 0,
// p ~ p(0) - c |x|^(n-1)), b2(s) has a kink (n = 1.05, Q/fP = 0.99: b2 stays within 3e-6
// of 0 from sigma/fp0 = 2.8 to 2.81 and then moves 0.9 a by 3.9, the regime turning to
// opposite sign at 3.10 where d1 = 0): Newton from the Hertz start and the continuation
// in s both stop at the cusp. Along the curve nothing is singular. At fixed x1, F2
// rises with e (steeply where -b2 crosses the cusp; measured for n = 1.05 on
// 0.01 <= |x1| <= 0.9), so its root e(x1) is bracketed on (e_lo, 2 - |x1|); x1 is then
// the root of G(x1) = F1(x1, e(x1)) at the scene's s. Both by Illinois iterations
// (ln e and x1 to 8 eps, relative). e_lo = e^(3 ln eps + 1), just above the point-stick
// switch of general_residual (widths below eps^3, where F2 no longer depends on e).
template <class T> struct curve {
  const pressure_model<T> &pm;
  const T &q, &s;
  int n;
  T le_lo;
  curve(const pressure_model<T> &pm_, const T &q_, const T &s_, int n_) : pm(pm_), q(q_), s(s_), n(n_) {
    using std::log;
    le_lo = 3 * log(eps<T>()) + 1;
  }
  T F2(const T &x1, const T &le) const {
    return general_residual(pm, q, s, general_state<T>::from_log(x1, le), n, false).F2;
  }
  T le_hi(const T &x1) const {
    using std::abs;
    using std::log;
    return log(T(2 - abs(x1))) + log1p(-T(1) / T(1 << 20));  // d2 > 0
  }
  // the lower end of the bracket at x1: the first of ln e = -8, -40, le_lo where F2 is
  // negative (a residual grades its panels to the width: one at e^-40 costs ~20 times one
  // at the roots of the band, e ~ 0.01 to 0.5)
  T lower(const T &x1, T &f) const {
    for (const T &l : {T(-8), T(-40)}) {
      if (!(l > le_lo)) break;
      f = F2(x1, l);
      if (f < 0) return l;
    }
    f = F2(x1, le_lo);
    return le_lo;
  }
  // the curve has a point at x1 (F2 changes sign on [le_lo, le_hi])
  bool has_point(const T &x1) const {
    using std::abs;
    if (!(abs(x1) < 2)) return false;
    T f;
    lower(x1, f);
    return f < 0 && F2(x1, le_hi(x1)) > 0;
  }
  // the curve's end between x1 = in (on the curve) and off (off it), by bisection on
  // has_point to 1e-14 (at most 60 halvings): it stands in for the point beyond the end
  T end(T in, T off) const {
    using std::abs;
    for (int k = 0; k < 60 && abs(off - in) > T(1e-14); ++k) {
      const T mid = (in + off) / 2;
      (has_point(mid) ? in : off) = mid;
    }
    return in;
  }
  // ln e of the curve at x1, to rtol (relative, at least 8 eps); near: a guess, bracketed outwards from
  // it first (the local search of curve_local), else the whole range
  bool point(const T &x1, const T &rtol, T &le, const T *near = nullptr) const {
    using std::abs;
    using std::max;
    using std::min;
    if (!(abs(x1) < 2)) return false;
    const T hi_lim = le_hi(x1);
    auto f = [&](const T &l) { return F2(x1, l); };
    auto done = [&](const T &l, const T &h) { return h - l <= rtol * max(T(1), T(abs(l))); };
    if (near && *near > le_lo && *near < hi_lim) {
      T h = T(1e-6) * max(T(1), T(abs(*near)));
      for (int k = 0; k < 40; ++k, h *= 4) {
        const T a = max(le_lo, T(*near - h)), b = min(hi_lim, T(*near + h));
        const T fa = f(a), fb = f(b);
        if (!(fa == fa) || !(fb == fb)) break;
        if (fa < 0 && fb > 0) return illinois_until(f, a, b, fa, fb, done, le);
        if (a == le_lo && b == hi_lim) return false;
      }
    }
    T flo;
    const T lo = lower(x1, flo), fhi = f(hi_lim);
    if (!(flo < 0) || !(fhi > 0)) return false;
    return illinois_until(f, lo, hi_lim, flo, fhi, done, le);
  }
  // G(x1) = F1 on the curve at the scene's s (NaN where the curve has no point at x1)
  T G(const T &x1, const T &rtol, T *le_out = nullptr, const T *near = nullptr) const {
    T le;
    if (!point(x1, rtol, le, near)) return std::numeric_limits<T>::quiet_NaN();
    if (le_out) *le_out = le;
    return general_residual(pm, q, s, general_state<T>::from_log(x1, le), n, false).F1;
  }
  // the root of G on [xa, xb] (G of opposite signs there), to 8 eps, as a state
  bool root(T xa, T xb, T ga, T gb, general_state<T> &out, const T *near = nullptr) const {
    using std::abs;
    using std::max;
    const T fine = 8 * eps<T>();
    T le = near ? *near : T(0);
    auto g = [&](const T &x) {
      T l;
      const T v = G(x, fine, &l, near ? &le : nullptr);
      if (v == v) le = l;
      return v;
    };
    auto done = [&](const T &l, const T &h) { return h - l <= fine * max(abs(l), abs(h)); };
    T x1;
    if (!illinois_until(g, xa, xb, ga, gb, done, x1) || !point(x1, fine, le, near ? &le : nullptr)) return false;
    out = general_state<T>::from_log(x1, le);
    return out.d2() > 0 && out.d1() < 2;
  }
};

// The curve start: x1 bracketed on a grid over both regimes, |x1| = 1.99 2^-k,
// k = 0 ... 19 (down to 4e-6) on each side of x1 = 0 (the regime boundary, d1 = 0, where
// the opposite-sign zone 1 stays narrow: n = 1.05, Q/fP = 0.9977, sigma/fp0 = 3.2 has
// d1 = 0.0049), the curve's points on the grid to 1e-3 in ln e (a sign of G is all the
// grid needs), the root then to 8 eps. Where the curve ends between two grid
// points (e(x1) -> e_lo at larger sigma: n = 1.01, Q/fP = 0.99, sigma/fp0 = 5 has its
// root within 0.03 of the end) the end, by bisection to 1e-14 on has_point, stands in
// for the point beyond it. False where no x1 of the grid brackets a root. Cost (double):
// ~600 to 1,500 residuals, most of them away from the root, where they cost more (panels
// graded to smaller widths): 0.1 to 0.4 s at orders 64 and 128 (n = 1.05 and 1.01); the
// last start tried, and only in double and long double (one residual of the reference's
// MPFR tiers costs ~7 ms at order 64: the reference uses curve_local instead).
template <class T>
bool curve_start(const pressure_model<T> &pm, const T &q, const T &s, int n, general_state<T> &out) {
  using std::pow;
  const curve<T> c(pm, q, s, n);
  const T coarse = T(1e-3);
  const int m = 20;
  auto grid = [&](int i) {  // i = 0 ... 2m, ascending
    const T r = T(0.5);
    if (i == m) return T(0);
    return i < m ? T(-T(1.99) * pow(r, T(i))) : T(T(1.99) * pow(r, T(2 * m - i)));
  };
  T xa = 0, ga = std::numeric_limits<T>::quiet_NaN();
  for (int i = 0; i <= 2 * m; ++i) {
    T xb = grid(i), gb = c.G(xb, coarse);
    if (i > 0 && (ga == ga) != (gb == gb)) {
      // one side on the curve, the other off it: test the curve's end
      const T xe = ga == ga ? c.end(xa, xb) : c.end(xb, xa), ge = c.G(xe, coarse);
      if (ga == ga && ge == ge && (ga < 0) != (ge < 0)) {
        xb = xe;
        gb = ge;
      } else if (gb == gb && ge == ge && (gb < 0) != (ge < 0)) {
        xa = xe;
        ga = ge;
      }
    }
    if (ga == ga && gb == gb && (ga < 0) != (gb < 0)) return c.root(xa, xb, ga, gb, out);
    xa = xb;
    ga = gb;
  }
  return false;
}

// The curve near a state `at` (the order control's state at the order below, or the
// reference's double start): x1 bracketed outwards from at.x1 (steps from 1e-9 (|x1| +
// 1e-3), times 4, up to 30 times, within |x1| < 1.99), the curve's point at each x1
// bracketed outwards from the last ln e. Where Newton cannot finish from `at` because
// the Jacobian is far from the residual's (the power law n = 1.05: p' ~ |x|^(n-2) at
// the cusp inside zone 2 leaves J22 off by a factor of 2.3 at order 128, Q/fP = 0.9977,
// sigma/fp0 = 3.2; Newton from the order-64 root stalls 2e-12 from the order-128 root):
// brackets need no Jacobian. A few hundred residuals; false if no root is bracketed.
template <class T>
bool curve_local(const pressure_model<T> &pm, const T &q, const T &s, int n, const general_state<T> &at,
                 general_state<T> &out) {
  using std::abs;
  using std::max;
  using std::min;
  const curve<T> c(pm, q, s, n);
  const T x0 = at.x1, lim = T(1.99);
  T le = at.lw();
  if (!(abs(x0) < lim) || !(le == le)) return false;
  // the last point on the curve met on each side (x0 itself on both, if on the curve): a
  // sign change of G between it and the next one brackets a root (at order 64 the state
  // from order 32 can lie off the curve: n = 1.05, Q/fP = 0.9977, sigma/fp0 = 10, where
  // ln e moves from -50 to -13 within 1e-6 of x1)
  T l0 = le;
  const T g0 = c.G(x0, T(1e-10), &l0, &le);
  T xs[2] = {x0, x0}, gs[2] = {g0, g0}, ls[2] = {l0, l0};
  T h = T(1e-9) * (abs(x0) + T(1e-3));
  for (int k = 0; k < 30; ++k, h *= 4) {
    for (int i = 0; i < 2; ++i) {
      const int side = i ? 1 : -1;
      const T x = side > 0 ? min(lim, T(x0 + h)) : max(-lim, T(x0 - h));
      if (x == xs[i]) continue;
      T l = gs[i] == gs[i] ? ls[i] : le;
      const T g = c.G(x, T(1e-10), &l, &l);
      if (!(g == g)) {
        if (!(gs[i] == gs[i])) xs[i] = x;  // (still off the curve: the last x off it)
        continue;
      }
      if (!(gs[i] == gs[i])) {
        // onto the curve from off it: its end between xs[i] and x stands in for the
        // point before x (as in curve_start)
        const T in = c.end(x, xs[i]);
        T le_end = c.le_lo;
        const T ge = c.G(in, T(1e-10), &le_end);
        if (ge == ge && (ge < 0) != (g < 0)) {
          const T xa = side > 0 ? in : x, xb = side > 0 ? x : in;
          const T ga = side > 0 ? ge : g, gb = side > 0 ? g : ge;
          T near = l;
          return c.root(xa, xb, ga, gb, out, &near);
        }
      } else if ((g < 0) != (gs[i] < 0)) {
        const T xa = side > 0 ? xs[i] : x, xb = side > 0 ? x : xs[i];
        const T ga = side > 0 ? gs[i] : g, gb = side > 0 ? g : gs[i];
        T near = side > 0 ? ls[i] : l;
        return c.root(xa, xb, ga, gb, out, &near);
      }
      xs[i] = x;
      gs[i] = g;
      ls[i] = l;
    }
  }
  return false;
}

// Continuation in s from s = 0 with the tangent predictor dx/ds = -J^-1 dF/ds.
template <class T> bool continuation(const pressure_model<T> &pm, const T &q, const T &s, general_state<T> &st, int n,
                                     const T &tol_step, int max_it, int &iterations, int &steps) {
  using std::abs;
  using std::exp;
  using std::ldexp;
  T sc = 0;
  // (s may be denormal: s/4 and s 2^-40 then underflow to 0; every step
  // must make progress, else a zero step loops for ever: fuzzer input
  // tests/fuzz/corpus/solve/timeout-denormal-sigma)
  T h = s / 4;
  if (!(h > 0)) h = s;
  const T hmin = s * ldexp(T(1), -40);
  // bounded time (issue 13): the step may stall far above hmin (each step converging in
  // more than 4 iterations, so that h never grows) and the steps then number up to
  // s/hmin = 2^40; fuzzer input tests/fuzz/corpus/callback/crash-continuation-stall (a
  // callback pressure with kinks, Q/fP = -0.996, sigma/fp0 = -46.7) ran for more than
  // 10 minutes. A continuation that converges takes a few dozen steps.
  const int max_steps = 2048;
  int tried = 0;
  while (sc < s) {
    if (!(h > 0) || h < hmin || ++tried > max_steps) return false;
    const T sn = (s - sc <= h || !(sc + h > sc)) ? s : sc + h;
    const T ds = sn - sc;
    // tangent predictor
    general_state<T> pred = st;
    const general_eval<T> r = general_residual(pm, q, sc, st, n, true);
    const T pi_ = pi<T>();
    const T Fs1 = -pi_ / 4, Fs2 = 0;  // F2 (the moment about the centre) has no s
    const auto x = solve2x2(r.J11, r.J12, r.J21, r.J22, Fs1, Fs2);
    if (x.det != 0) {
      const T dx = -x.x1, dy = -x.x2;
      const general_state<T> p2 = st.step(ds * dx, ds * dy);
      if (p2.ln_e == p2.ln_e && p2.d2() > 0 && p2.d1() < 2) pred = p2;
    }
    int its = 0;
    general_state<T> trial = pred;
    ++steps;
    if (newton(pm, q, sn, trial, n, tol_step, max_it, its)) {
      iterations += its;
      st = trial;
      sc = sn;
      if (its <= 4) h *= 2;
    } else {
      iterations += its;
      h /= 4;
    }
  }
  return true;
}

}  // namespace gdetail

// Solve a general scene for the pressure pm (dimensionless model; scene
// gives a, p0, f, E* for the dimensional outputs). pm must outlive the
// solution. Throws hs::core::error on bad input or failure.
template <class T> general_solution<T> solve_general(const pressure_model<T> &pm, const general_scene<T> &sc,
                                                     const general_options<T> &opt = {}) {
  using std::abs;
  using std::max;
  using std::sqrt;
  validate(sc);
  if (opt.max_iterations < 1 || opt.max_order < 2 || !(opt.rtol >= 0))
    throw error(status::bad_option, "bad solver options");
  general_solution<T> sol;
  sol.scene = sc;
  sol.rtol = opt.rtol;
  sol.max_order = opt.max_order;
  // the expansion of B_x, made on first use (general_expansion.hpp)
  sol.expansion_ = std::make_shared<typename general_solution<T>::expansion_cache>();
  T q, s;
  sol.to_canonical(q, s);
  if (sol.mirror && !pm.symmetric()) {
    auto mp = std::make_shared<mirrored_pressure<T>>(pm);
    sol.owned = mp;
    sol.pm = mp.get();
  } else {
    sol.pm = &pm;
  }
  const pressure_model<T> &P = *sol.pm;
  if (q == 0 && s == 0) {
    sol.reg = regime::stuck;
    return sol;
  }

  // the pressure's own accuracy sets the floor (power law: ~n eps, issue 13)
  const T acc = max(T(4), P.accuracy_eps());
  const T tolq = max(opt.rtol, 16 * acc * eps<T>());
  const T tol_step = max(opt.rtol, acc * eps<T>());
  const T qtol = tolq * pi<T>() * (1 + s);
  // initial order from the tolerance: the smallest power of two >= 2/3 of
  // the digits asked for (the residual is then validated at twice the order)
  int n = 4;
  {
    using std::log10;
    const T digits = -log10(tolq);
    while (T(n) < digits * 2 / 3) n *= 2;
  }  // start: the Hertz solution of the same (q, s)
  general_state<T> st;
  {
    hertz_scene<T> hs;
    hs.q = q;
    hs.s = s;
    hertz_solution<T> h;
    try {
      h = solve_hertz(hs);
    } catch (const error &) {
      // the closed forms' own limits (sigma/fp0 above ~1e10, or next to sliding):
      // start at a narrow stick zone at the sliding point instead (large_sigma_start)
      h.reg = regime::opposite_sign;
      h.delta1 = T(0.5);
      h.delta2 = T(1.5) - eps<T>();
      h.width = eps<T>();
    }
    // Both slip zones below the resolution of the state (x1, ln e), in which the
    // far zone is d2 = 2 - |x1| - e and so known only to ~eps: Newton cannot
    // represent them, and a continuation in sigma found a spurious root instead
    // (issue 13: flat punch, Q = 0, sigma/fp0 = 1e-30 gave d2/a = 1.38). The
    // zones of any pressure are within a small factor of Hertz's at the same
    // (q, s) (0.59 for b_f/a = 0.5), so the Hertz zones decide. The asymptotic
    // edge model (core/asymptotic.hpp) is accurate there.
    if (max(h.delta1, h.delta2) < 256 * eps<T>())
      throw error(status::not_applicable,
                  "general solver: both slip zones narrower than 256 eps a (loads too small for the quadrature "
                  "model; the asymptotic edge model solves them)");
    st.x1 = h.reg == regime::opposite_sign ? -h.delta1 : h.delta1;
    st.e = h.width;
    // for a model with a known shear-only stick half-width c, scale the Hertz
    // stick zone about its centre by c / sqrt(1 - q) (exact at sigma = 0)
    T c;
    if (P.shear_only_half_width(q, c) && c > 0 && c <= 1) {
      using std::sqrt;
      const T cH = sqrt(1 - q);
      const T m = (h.delta2 - h.delta1) / 2, w = h.width / 2 * (c / cH);
      const T nb1 = m + w, nb2 = w - m;
      if (nb1 < 1 && nb2 < 1 && w > 0) {
        st.x1 = h.reg == regime::opposite_sign ? -(1 - nb1) : 1 - nb1;
        st.e = 2 * w;
      }
    }
  }
  int its = 0;
  general_state<T> trial = st;
  bool ok = false;
  if (opt.has_start) {
    // the given start at the given order (a state of the same canonical frame)
    const int n0 = n;
    while (2 * n <= opt.start_order && 4 * n <= opt.max_order) n *= 2;
    trial = general_state<T>::from_log(opt.start_x1, opt.start_ln_e);
    // K = 1 (general_problem::kest) from the start: a first step whose successor
    // K s^2 (K at least 1/(the shorter zone)) is below an eighth of the step
    // tolerance is taken unevaluated (issue 16: the reference's check tier, started
    // from the work tier's root, took a confirming residual at order n that only
    // confirmed it). The order control's residual at 2n below is evaluated at the
    // new state and accepts it only within qtol, so a wrong shortcut costs time, not
    // accuracy. A start from the double solution (step ~1e-13) never qualifies.
    T kstart = 1;
    if (trial.d2() > 0 && trial.d1() < 2 && trial.lw() == trial.lw())
      ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its,
                           static_cast<const general_eval<T> *>(nullptr), opt.start_shortcut ? &kstart : nullptr);
    if (!ok && trial.d2() > 0 && trial.d1() < 2) {
      // (the reference's tiers from the double answer in the band of the curve start: Newton
      // stalled there, n = 1.05, Q/fP = 0.9977, sigma/fp0 = 3.2 at 50 digits)
      general_state<T> c;
      const general_state<T> given = general_state<T>::from_log(opt.start_x1, opt.start_ln_e);
      if (gdetail::curve_local(P, q, s, n, given, c)) {
        trial = c;
        ok = true;
        int k = 0;
        gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, k);
        its += k;
        if (!(trial.d2() > 0 && trial.d1() < 2)) trial = c;
      }
    }
    if (!ok) {
      n = n0;
      trial = st;
    }
  }
  T kest = -1;  // general_problem::kest, carried from one order to the next
  if (!ok)
    ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its,
                         static_cast<const general_eval<T> *>(nullptr), &kest);
  if (!ok) kest = -1;
  if (!ok && st.x1 < 0 && st.e < T(0.1)) {
    // large sigma: start from the sliding stick point (issue 13)
    if (gdetail::large_sigma_start(P, q, s, n, trial))
      ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its);
  }
  if (!ok && q > T(0.99)) {
    // near sliding (issue 13): Newton at a raised order where the order-n residual
    // is not resolved (newton_raising_order), from the start where the stick zone
    // collapses onto the point at which the profile's slope matches sigma
    // (near_sliding_start; neither start above need be near it), then from the
    // Hertz start again
    const int n0 = n;
    // (up to 16 -> 256 in double from the near-sliding start: flat punch b_f/a = 0.5,
    // 1 - Q/fP = 4.5e-11, sigma/fp0 = 5 needs 256; up to 64 from the Hertz start)
    general_state<T> entry;
    bool entry_ok = false;
    if (s > 0 && gdetail::near_sliding_start_resolved(P, q, s, n, opt.max_order, trial, entry, entry_ok))
      ok = gdetail::newton_raising_order(P, q, s, trial, n, opt.max_order, tol_step, opt.max_iterations, its, 4);
    if (!ok && s > 0) {
      // the start at the entry order (made first by near_sliding_start_resolved)
      n = n0;
      trial = entry;
      if (entry_ok)
        ok = gdetail::newton_raising_order(P, q, s, trial, n, opt.max_order, tol_step, opt.max_iterations, its, 4);
    }
    if (!ok && st.x1 < 0 && s > 0) {
      // opposite sign next to sliding (issue 13, round two): no near-sliding start
      // (it follows a same-sign zone), and the large-sigma start above was tried at
      // order n only, which does not resolve F1 there (power law n = 9.875,
      // 1 - Q/fP = 1e-10, sigma/fp0 = 10: F1 at orders 16 and 32 differs by 1.2e-7
      // at the start); Newton at a raised order from it
      n = n0;
      if (gdetail::large_sigma_start(P, q, s, n, trial))
        ok = gdetail::newton_raising_order(P, q, s, trial, n, opt.max_order, tol_step, opt.max_iterations, its, 4);
    }
    if (!ok) {
      n = n0;
      trial = st;
      ok = gdetail::newton_raising_order(P, q, s, trial, n, opt.max_order, tol_step, opt.max_iterations, its, 2);
    }
    if (!ok) n = n0;
  }
  if (!ok) {
    // fallback: continuation in s from the shear-only solution
    general_state<T> s0 = gdetail::shear_only_start(P, q, n);
    if (!gdetail::newton(P, q, T(0), s0, n, tol_step, opt.max_iterations, its))
      throw error(status::no_convergence, "general solver: no convergence at sigma = 0");
    trial = s0;
    if (s > 0 && !gdetail::continuation(P, q, s, trial, n, tol_step, opt.max_iterations, its, sol.continuation_steps)) {
      // a kink of the solution in s (a zone end crossing a cusp of the pressure): the curve start
      const int n0 = n;
      int m = max(n, 64);
      ok = false;
      if (std::numeric_limits<T>::digits <= 64)
        for (; !ok && 2 * m <= opt.max_order && m <= 128; m *= 2) {
          if (!gdetail::curve_start(P, q, s, m, trial)) continue;
          n = m;
          ok = gdetail::newton(P, q, s, trial, n, tol_step, opt.max_iterations, its);
        }
      if (!ok) {
        n = n0;
        throw error(status::no_convergence, "general solver: continuation in sigma failed");
      }
    }
  }
  st = trial;
  // order control: accept n when the residual with 2n is within qtol; finish
  // with one Newton step on the 2n residual.
  T prev_move = -1, prev_rn = -1;  // the zones' move to the root at 2n and the residual, the order before
  for (;;) {
    const general_eval<T> r2 = general_residual(P, q, s, st, 2 * n, true);
    const T rn = gdetail::residual_norm(r2);
    bool accept = rn <= qtol;
    T move = 0;
    // the Newton correction to the root at 2n (the move below and the final step)
    const auto x = solve2x2(r2.J11, r2.J12, r2.J21, r2.J22, r2.F1, r2.F2);
    // Above qtol, at a floor: the residual's grain in the state, or a residual that no longer
    // shrinks with the order (the rounding of the sums: flat punch b_f/a = 0.012, Q/fP = -0.28,
    // sigma/fp0 = -404, a point stick continued in ln e, whose F1 sat at 2.6e-11 and 3.6e-11 at
    // orders 512 and 1024 against a qtol of 1.8e-11, while x1 moved by 2e-14: the order limit,
    // and NO_CONVERGENCE). Where the Jacobian is nearly singular the grain's floor also hides an
    // order that has not converged (issue 13: flat punch, 1 - b_f/a = 6.2e-7, 1 - Q/fP = 4.5e-6,
    // sigma/fp0 = -22.3, the stick zone 8e-7 a wide next to the corner: order 16 passed with a
    // residual of 9.5e-8 under a grain of 1.2e-7, yet the root at order 32 moved d1 by 8e-5 of
    // itself, and the answer was off by 1.1e-7 against an estimate of 1.8e-8). So at a floor the
    // zones' move to the root at 2n must be within the resolution the estimate assumes
    // (16 tol_step a), or, at the grain, have stopped shrinking (the rounding's own floor: it is
    // then part of the conditioning below, enlarged where it shrank by less than half: a
    // ratio rho to the move before leaves the root ~rho/(1 - rho) moves from the limit). At the
    // order limit a state at a floor is taken with its move in the conditioning.
    if (!accept) {
      const bool at_grain = rn <= 4 * r2.grain, stalled = prev_rn >= 0 && rn > prev_rn / 4;
      if (at_grain || stalled) {
        using std::expm1;
        move = abs(x.x1) + st.e * abs(T(expm1(x.x2)));
        const bool shrinking = !(prev_move >= 0 && move > prev_move / 4);
        const bool at_limit = 4 * n > opt.max_order;
        accept = x.det != 0 && (move <= 16 * tol_step || (at_grain && !shrinking) ||
                                 (at_limit && move < std::numeric_limits<T>::infinity()));
        if (accept && prev_move > 0 && move < prev_move) {
          const T rho = move / prev_move;
          if (rho > T(0.5)) move *= rho / (1 - rho);
        }
        prev_move = move;
      } else {
        prev_move = -1;
      }
    }
    prev_rn = rn;
    if (accept) {
      // the zones' conditioning (issue 13): residuals known to n1 (F1, with its
      // pi s/4 term) and n2 (F2, the moment: no s), each the step tolerance
      // (acc eps) in units of its terms, move x1 and ln e by J^-1 of them; d1 = |x1|
      // and d2 = 2 - d1 - e then by dx1 + e dln e. Large when the sliding stick
      // point nears an edge (Q -> fP at large sigma: the moment fixes x1 alone,
      // through J21 ~ p_hat(x0) -> 0; Hertz, 1 - Q/fP = 1e-12, sigma/fp0 = 100:
      // d1 = 8.9e-9 a off by 2e-4 against an estimate of 1.2e-6)
      if (x.det != 0) {
        const T n1 = tol_step * pi<T>() * (1 + s), n2 = tol_step * pi<T>();
        const T ad = abs(x.det);
        sol.conditioning =
            (abs(r2.J22) * n1 + abs(r2.J12) * n2) / ad + st.e * (abs(r2.J21) * n1 + abs(r2.J11) * n2) / ad;
      }
      if (move > sol.conditioning) sol.conditioning = move;
      if (x.det != 0) {
        using std::exp;
        const T dx = -x.x1, dy = -x.x2;
        const general_state<T> ns = st.step(dx, dy);
        // keep the regime of the accepted state unless the state sits on the boundary
        if (ns.d2() > 0 && ns.ln_e == ns.ln_e && (ns.x1 == 0 || (ns.x1 > 0) == (st.x1 > 0) || abs(st.x1) <= qtol))
          st = ns;
      }
      // near sliding: the width to the rounding of F2 (polish_near_sliding); the
      // conditioning above holds for the polished state
      if (gdetail::polish_applies(q, st)) gdetail::polish_near_sliding(P, q, s, st, max(4 * n, 128));
      n *= 2;
      break;
    }
    n *= 2;
    if (2 * n > opt.max_order) throw error(status::no_convergence, "general solver: quadrature order limit reached");
    // Newton at the doubled order from the residual just evaluated there
    const general_state<T> before = st;
    if (!gdetail::newton(P, q, s, st, n, tol_step, opt.max_iterations, its, &r2, &kest)) {
      // near sliding, where the floor hides F2 (polish_near_sliding; flat punch
      // b_f/a = 0.95, 1 - Q/fP = 1e-13, sigma/fp0 = 1): the bracketed polish, then
      // the order control goes on
      st = before;
      // (the floors' bookkeeping restarts: the state below is not the root at the order before)
      prev_rn = prev_move = -1;
      if (gdetail::polish_applies(q, st) && gdetail::polish_near_sliding(P, q, s, st, max(2 * n, 128))) continue;
      // the Jacobian can be far from the residual's (curve_local): the curve near the state
      // at the order below, by brackets, which stand where Newton cannot improve on them
      general_state<T> c;
      if (!gdetail::curve_local(P, q, s, n, before, c))
        throw error(status::no_convergence, "general solver: Newton iteration did not converge");
      st = c;
      if (!gdetail::newton(P, q, s, st, n, tol_step, opt.max_iterations, its)) st = c;
    }
  }
  sol.iterations = its;
  sol.order = n;
  sol.delta1 = st.d1();
  sol.width = st.e;
  sol.log_width = st.lw();
  sol.delta2 = st.d2();
  sol.beta1 = 1 - sol.delta1;
  sol.beta2 = 1 - sol.delta2;
  if (st.x1 < 0) {
    sol.reg = regime::opposite_sign;
    sol.dirR = -1;
  } else {
    sol.reg = regime::same_sign;
    sol.dirR = 1;
  }
  sol.dirL = 1;
  sol.settle_empty_zones();
  return sol;
}

}}  // namespace hs::core
