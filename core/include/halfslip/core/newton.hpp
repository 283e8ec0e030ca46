// halfslip core: the 2x2 linear solve and the damped Newton kernel for two
// unknowns shared by the Hertz opposite-sign solver (hertz_opposite.hpp) and
// the general-pressure solver (general_solver.hpp); the 2x2 solve also serves
// the refinement and predictor steps and the load-history steps (history.hpp).
#pragma once
#include <cmath>

#include <boost/math/tools/precision.hpp>

namespace hs { namespace core {

// x = A^-1 b for A = [a11 a12; a21 a22] by Cramer's rule. det is returned for
// the caller's own singularity test (x is then inf or NaN, as IEEE division
// gives it). A Newton correction is -x for b = F: negating the quotient is
// exact, so this is bitwise the -(...)/det the solvers wrote before.
template <class T> struct solve2x2_result { T det, x1, x2; };

// with the determinant already known (the same matrix applied to several b)
template <class T> solve2x2_result<T> solve2x2(const T &a11, const T &a12, const T &a21, const T &a22, const T &det,
                                               const T &b1, const T &b2) {
  return {det, (b1 * a22 - b2 * a12) / det, (a11 * b2 - a21 * b1) / det};
}

template <class T>
solve2x2_result<T> solve2x2(const T &a11, const T &a12, const T &a21, const T &a22, const T &b1, const T &b2) {
  return solve2x2(a11, a12, a21, a22, T(a11 * a22 - a12 * a21), b1, b2);
}

// Jacobian of two residuals in the step coordinates (x, y); y is a
// logarithm (ln e, the stick-zone length), x the other unknown.
template <class T> struct jacobian2 { T a11, a12, a21, a22; };

// Step sizes of an accepted Newton step: `conv` for the problem's own
// convergence test, `noise` for the stalled-step test of the kernel.
template <class T> struct newton_steps { T conv, noise; };

struct newton_outcome {
  bool converged;
  int iterations;  // iterations begun (max_iterations when the loop ran out)
};

// Damped Newton for two unknowns with the globalisation both side-condition
// solvers share:
//  - the affine-invariant monitor of Deuflhard (Newton Methods for Nonlinear
//    Problems, Springer 2004, sec. 3.3, the natural level function): a trial
//    is accepted when |J^-1 F(trial)|_1, with this iteration's Jacobian J,
//    falls below (1 - lam/4) of the full correction |J^-1 F|_1 (near Q -> fP
//    the two side conditions are nearly parallel and |F| alone would accept
//    steps that ruin the weakly determined direction), or when the residual
//    is at its rounding floor and did not grow;
//  - a trust region of 4 in y = ln e (the problem caps x);
//  - up to 40 halvings of the step;
//  - the noise floor: if no halving is accepted, or the Jacobian is singular,
//    the current state is the solution when its residual is at the floor; once at the floor, a step
//    that stopped shrinking quadratically (at least 1/4 of the previous one)
//    ends the iteration (a weakly determined length is then known to the
//    accuracy the residual allows).
// The problem P supplies (all inlined: no allocation, no virtual call):
//   using real, state, eval (eval has F1, F2);
//   jacobian2<real> jacobian(const state &, const eval &)
//   bool shortcut(state &, dx, dy, prev_noise_step)  accept a tiny full step unevaluated
//   void cap_x(dx, dy)                                the problem's cap on x
//   bool trial(const state &, lam, dx, dy, state &)   the damped state, false if rejected
//   eval residual(const state &)
//   real floor(const eval &)                          rounding floor of |F1| + |F2|
//   newton_steps<real> steps(const state &, lam, dx, dy)   of the last trial
//   bool converged(lam, conv_step, norm, floor)
// st holds the start on entry and the last iterate on exit; r is the residual
// at the start.
template <class P> newton_outcome damped_newton(P &p, typename P::state &st, typename P::eval r, int max_iterations) {
  using T = typename P::real;
  using std::abs;
  auto norm_of = [](const typename P::eval &f) { return T(abs(f.F1) + abs(f.F2)); };
  T norm = norm_of(r);
  T floor = p.floor(r);
  T prev_step = -1;
  for (int it = 1; it <= max_iterations; ++it) {
    const jacobian2<T> J = p.jacobian(st, r);
    const auto x = solve2x2(J.a11, J.a12, J.a21, J.a22, r.F1, r.F2);
    // a singular Jacobian: no step; the state is the solution if its residual
    // is at the rounding floor (as when no damped step decreases it, below;
    // seen with a stick zone below the range of T, where the columns in c and
    // ln e are parallel to rounding), else a failure
    if (!(x.det != 0) || !(abs(x.det) < boost::math::tools::max_value<T>())) return {norm <= floor, it};
    T dx = -x.x1, dy = -x.x2;
    auto level = [&](const typename P::eval &f) {
      const auto z = solve2x2(J.a11, J.a12, J.a21, J.a22, x.det, f.F1, f.F2);
      return T(abs(z.x1) + abs(z.x2));
    };
    const T level0 = abs(dx) + abs(dy);
    if (p.shortcut(st, dx, dy, prev_step)) return {true, it};
    const T cap = 4;
    if (abs(dy) > cap) {
      dx *= cap / abs(dy);
      dy = dy > 0 ? cap : -cap;
    }
    p.cap_x(dx, dy);
    T lam = 1;
    typename P::state nst{};
    typename P::eval nr{};
    T nnorm = 0;
    bool decreased = false;
    for (int k = 0; k < 40; ++k, lam /= 2) {
      if (!p.trial(st, lam, dx, dy, nst)) continue;
      nr = p.residual(nst);
      nnorm = norm_of(nr);
      if (!(nnorm == nnorm)) continue;
      if (level(nr) <= (1 - lam / 4) * level0 || (nnorm <= p.floor(nr) && nnorm <= norm)) {
        decreased = true;
        break;
      }
    }
    // no step reduces the residual: at the rounding floor, or stuck
    if (!decreased) return {norm <= floor, it};
    const newton_steps<T> steps = p.steps(st, lam, dx, dy);
    st = nst;
    r = nr;
    norm = nnorm;
    floor = p.floor(r);
    if (p.converged(lam, steps.conv, norm, floor)) return {true, it};
    if (norm <= floor && prev_step >= 0 && steps.noise >= prev_step / 4) return {true, it};
    prev_step = steps.noise;
  }
  return {false, max_iterations};
}

}}  // namespace hs::core
