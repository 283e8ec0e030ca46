// halfslip core: the 2x2 linear solve and the damped Newton kernel shared by
// the Hertz opposite-sign solver (hertz_opposite.hpp), the general-pressure
// solver (general_solver.hpp) and the load-history steps (history.hpp).
#pragma once
#include <cmath>

#include <boost/math/tools/precision.hpp>

namespace hs { namespace core {

// x = A^-1 b for A = [a11 a12; a21 a22] by Cramer's rule. det is returned for
// the caller's own singularity test (x is then inf or NaN, as IEEE division
// gives it). A Newton correction is -x for b = F: negating the quotient is
// exact, so this is bitwise the -(...)/det the solvers wrote before.
template <class T> struct solve2x2_result {
  T det, x1, x2;
};

template <class T>
solve2x2_result<T> solve2x2(const T &a11, const T &a12, const T &a21, const T &a22, const T &b1, const T &b2) {
  const T det = a11 * a22 - a12 * a21;
  return {det, (b1 * a22 - b2 * a12) / det, (a11 * b2 - a21 * b1) / det};
}

}}  // namespace hs::core
