// halfslip core: small numerical building blocks, generic in the real type T.
// Every truncation rule derives from std::numeric_limits<T>::epsilon() (or the
// run-time precision of a multiprecision T), never from a double constant.
#pragma once
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <vector>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include "status.hpp"

namespace hs { namespace core {

template <class T> inline T pi() { return boost::math::constants::pi<T>(); }
template <class T> inline T eps() { return boost::math::tools::epsilon<T>(); }

// s = sin x, c = cos x. A type may specialise sin_cos_of (the reference backend's MPFR
// tiers: mpfr_sin_cos, one argument reduction for both, each correctly rounded as
// mpfr_sin and mpfr_cos are, so the same values; issue 16).
template <class T> struct sin_cos_of {
  static void apply(const T &x, T &s, T &c) {
    using std::cos;
    using std::sin;
    s = sin(x);
    c = cos(x);
  }
};
template <class T> inline void sin_cos(const T &x, T &s, T &c) { sin_cos_of<T>::apply(x, s, c); }

// Whether the hottest loops of the reference backend (the flat punch's Gauss-ladder sum,
// the energies' Cauchy sums) run in place, without a temporary a term: beyond the
// built-in floating types (MPFR), where each temporary costs an initialisation. The
// same operations in the same order, so the same values: tests/test_reference_inplace.cpp
// turns it off for one MPFR type and compares (issue 16). The built-in types keep the
// plain loops (their expressions might otherwise contract differently).
template <class T> struct inplace_loops : std::integral_constant<bool, !std::is_floating_point<T>::value> {};

// (product of num) / den * v, in that order, without an intermediate overflow or
// underflow: the mantissas are multiplied (each in [1/2, 1), so their running
// product stays within [2^-16, 2)) and the exponents added, with one ldexp at the
// end. Scaling by powers of two is exact, so where the plain product has no
// intermediate outside the normal range the result is bitwise the plain one; it
// overflows or underflows only where the value itself does. Used for the
// dimensional scalings (issue 13: the zone energy (f^2 p0^2 a^2 / E*) times the
// dimensionless energy overflowed in p0^2 for p0 ~ 1e200, E* ~ 1e200, although the
// energy was ~1e200). A zero factor among finite ones gives 0; an infinite or NaN
// factor (or a zero den) gives the plain product.
// At most 14 factors in num.
template <class T> T scaled_product(std::initializer_list<T> num, const T &den, const T &v) {
  using std::frexp;
  using std::isfinite;
  using std::ldexp;
  bool finite = isfinite(den) && den != 0 && isfinite(v), zero = v == 0;
  for (const T &x : num) {
    finite = finite && isfinite(x);
    zero = zero || x == 0;
  }
  // a zero factor among finite ones: 0 (the plain product gave NaN = inf * 0 where the
  // other factors overflowed, fuzz_dimensional: an energy that underflowed to 0 times
  // f^2 p0^2 a^2/E* with p0 ~ 1e132, f ~ 1e22)
  if (finite && zero) return T(0);
  if (!finite) {
    T m = 1;
    for (const T &x : num) m *= x;
    return m / den * v;
  }
  int e = 0, k = 0;
  T m = 1;
  for (const T &x : num) {
    m *= frexp(x, &k);
    e += k;
  }
  m /= frexp(den, &k);
  e -= k;
  m *= frexp(v, &k);
  e += k;
  return ldexp(m, e);
}

namespace detail {
// The odd Taylor tail y^3/3! + sg y^5/5! + sg^2 y^7/7! + ... for 0 <= y <= 1:
// y - sin(y) (sg = -1) and sinh(y) - y (sg = +1). Running out of max_terms
// throws no_convergence; a NaN y is returned as it is, as before.
template <class T> T odd_tail_series(const T &y, int sg, int max_terms = 200) {
  using std::abs;
  if (!(y == y)) return y;  // NaN: propagate (the loop's test would never hold)
  const T y2 = y * y;
  const T r = sg < 0 ? T(-y2) : y2;  // ratio of successive terms, times (2k)(2k+1)
  T term = y * y2 / 6, sum = term;
  int k = 2;
  for (; k < max_terms; ++k) {
    term *= r / T((2 * k) * (2 * k + 1));
    sum += term;
    // sinh y - y: every term is positive, and the test without abs is ~7% faster in double
    if (sg > 0 ? term <= eps<T>() * sum : abs(term) <= eps<T>() * abs(sum)) break;
  }
  check_iterations(k, max_terms, "odd Taylor series (y - sin y, sinh y - y) did not converge");
  return sum;
}
}  // namespace detail

// y - sin(y) for y >= 0, without cancellation for small y.
template <class T> T y_minus_sin(const T &y) {
  using std::sin;
  if (y > T(1)) return y - sin(y);
  return detail::odd_tail_series(y, -1);  // y^3/3! - y^5/5! + ...
}

// sinh(y) - y for y >= 0, without cancellation for small y.
template <class T> T sinh_minus_y(const T &y) {
  using std::sinh;
  if (y > T(1)) return sinh(y) - y;
  return detail::odd_tail_series(y, +1);
}

// Integral of sqrt(u^2 - w^2) du from u = w to u = w + delta (w > 0, delta >= 0),
// accurate to a few ulps for all delta/w (no 1 - cosh cancellation).
template <class T> T sqrt_quadratic_integral(const T &delta, const T &w) {
  using std::asinh;
  using std::log;
  using std::sqrt;
  if (!(delta > 0)) return T(0);
  const T S = sqrt(delta * (2 * w + delta));  // sqrt(U^2 - w^2), U = w + delta
  if (!(w > 0)) return (w + delta) * S / 2;   // w = 0: integral of u du
  if (S <= w) {
    // u = w cosh(t): w^2/4 (sinh 2Theta - 2Theta), Theta = asinh(S/w) <= asinh(1)
    const T theta = asinh(S / w);
    return w * w / 4 * sinh_minus_y(2 * theta);
  }
  const T U = w + delta;
  // Theta = acosh(U/w) = log((U + S)/w); no cancellation here as w^2 Theta < U S / 1.6
  return (U * S - w * w * log((U + S) / w)) / 2;
}

// Pi_hat(1 - xi) = integral_xi^1 sqrt(1 - t^2) dt as a function of the distance
// c = 1 - xi in [0, 2]; accurate for small c.
template <class T> T pressure_tail(const T &c) {
  using std::asin;
  using std::sqrt;
  if (!(c > 0)) return T(0);
  const T theta = 2 * asin(sqrt(c / 2));  // acos(1 - c)
  return y_minus_sin(2 * theta) / 4;
}

// Tanh-sinh quadrature on [lo, hi] of f(x, xc) where xc is the signed distance
// to the nearest end (xc < 0: x = lo - xc; xc > 0: x = hi - xc), as in Boost.Math.
// rtol is the termination tolerance; the convergence is quadratic so the
// error is typically far below it.
// The tanh-sinh integrator of integrate_ts. Abscissae closer than eps^4 to an
// end are dropped: with integrable singularities no stronger than 1/sqrt, what
// they carry is below eps^2. (The default, 4 min_value, overflows the node
// tables for MPFR types.)
template <class T> boost::math::quadrature::tanh_sinh<T> make_tanh_sinh() {
  const T e2 = eps<T>() * eps<T>();
  return boost::math::quadrature::tanh_sinh<T>(15, e2 * e2);
}

// ts: an integrator from make_tanh_sinh to reuse (its node tables, computed
// lazily, cost far more than one integral at multiprecision: 20 ms against
// 2 ms at 80 digits); nullptr: a new one (as before). Non-const: Boost 1.74's
// integrate() is not a const member; its lazy table growth is mutex-guarded.
template <class T, class F>
T integrate_ts(const F &f, const T &lo, const T &hi, const T &rtol, T *err = nullptr, T *L1 = nullptr,
               boost::math::quadrature::tanh_sinh<T> *ts = nullptr) {
  if (!(hi > lo)) return T(0);
  if (ts) return ts->integrate(f, lo, hi, rtol, err, L1);
  return make_tanh_sinh<T>().integrate(f, lo, hi, rtol, err, L1);
}

// Integral over [lo, hi] of f(x, c), with c = hi - x exact near hi, by
// tanh-sinh on the pieces between the given interior points (kinks).
template <class T, class F>
T integrate_pieces(const F &f, const T &lo, const T &hi, std::vector<T> cuts, const T &tol) {
  cuts.push_back(lo);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  T sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const T a = cuts[i], b = cuts[i + 1];
    if (!(b > a)) continue;
    sum += integrate_ts<T>(
        [&](const T &x, const T &xc) {
          const T c = (xc > 0 && b == hi) ? xc : hi - x;
          return f(x, c);
        },
        a, b, tol);
  }
  return sum;
}

}}  // namespace hs::core
