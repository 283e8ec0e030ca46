// halfslip core: complete elliptic integrals for the Hertz side conditions.
//
// Bulirsch's general complete elliptic integral (R. Bulirsch, Numer. Math. 13
// (1969) 305-315):
//   cel(kc, p, a, b) = int_0^{pi/2} (a cos^2 t + b sin^2 t)
//                      / ((cos^2 t + p sin^2 t) sqrt(cos^2 t + kc^2 sin^2 t)) dt
// for kc > 0, p > 0. One AGM-like loop, quadratically convergent, generic in
// T; it gives the *differences* (E - k'^2 K)/k^2 = cel(kc,1,1,0) and
// (Pi(n) - K)/n = cel(kc,1-n,0,1) directly, with no cancellation as k -> 0 or
// n -> 0, and is an order of magnitude faster in double than R_J from the
// duplication theorem (bench/bench_hertz.cpp measures both).
// The Carlson forms the side conditions use follow from (Q > 0, kc^2 = P/Q):
//   R_F(0,P,Q)   = cel(kc,1,1,1) / sqrt(Q)
//   R_D(0,Q,P)   = 3 cel(kc,1,1,0) / (P sqrt(Q))
//   R_J(0,P,Q,r) = 3 cel(kc, r/Q, 0, 1) / (Q sqrt(Q))
// (checked against Boost.Math's ellint_rf/rd/rj in tests/test_elliptic.cpp).
#pragma once
#include <cmath>
#include <type_traits>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/precision.hpp>

#include "status.hpp"

namespace hs { namespace core {

// max_iterations: the loop's limit (the default is never reached for valid
// input: each step squares the relative gap); running out throws no_convergence.
template <class T> T cel(T kc, T p, T a, T b, int max_iterations = 200) {
  using std::abs;
  using std::sqrt;
  if (!(kc > 0) || !(p > 0)) throw error(status::internal, "cel: needs kc > 0 and p > 0");
  // The loop stops once kc and g agree to sqrt(eps): the last step is quadratic.
  const T ca = sqrt(boost::math::tools::epsilon<T>());
  T e = kc, em = T(1);
  p = sqrt(p);
  b /= p;
  int i = 0;
  for (; i < max_iterations; ++i) {
    const T f = a;
    a += b / p;
    T g = e / p;
    b += f * g;
    b += b;
    p += g;
    g = em;
    em += kc;
    if (abs(g - kc) <= g * ca) break;
    kc = sqrt(e);
    kc += kc;
    e = kc * em;
  }
  check_iterations(i, max_iterations, "cel: the AGM iteration did not converge");
  return boost::math::constants::half_pi<T>() * (b + a * em) / (em * (em + p));
}

// cel for a modulus kc that may be below the range of T, given lkc = ln kc
// (kc = exp(lkc), possibly 0). As kc -> 0 the integrand near t = pi/2 is
// (b/p) / sqrt(cos^2 t + kc^2), so cel(kc) = (b/p) ln(1/kc) + C(p, a, b) +
// O((kc^2/p) ln kc): below the switch ks = eps^0.6 min(1, sqrt(p)) the
// remainder is under eps and the value is cel(ks) + (b/p)(ln ks - ln kc)
// (tests/test_elliptic.cpp compares it with cel where both are defined).
// A stick zone narrower than the range of T (large sigma) has such a modulus.
// eps^0.6, cel_log's switch for p >= 1 (computed once for the built-in
// floating types: powl is dear; other types compute it each time, their
// precision may be set at run time)
template <class T> T cel_switch() {
  using std::pow;
  if constexpr (std::is_floating_point<T>::value) {
    static const T ks = pow(boost::math::tools::epsilon<T>(), T(0.6));
    return ks;
  } else {
    return pow(boost::math::tools::epsilon<T>(), T(0.6));
  }
}

template <class T> T cel_log(const T &kc, const T &lkc, const T &p, const T &a, const T &b) {
  using std::log;
  using std::min;
  using std::sqrt;
  if (!(p > 0)) throw error(status::internal, "cel: needs p > 0");
  const T ks = cel_switch<T>() * min(T(1), sqrt(p));
  if (kc > ks) return cel(kc, p, a, b);
  return cel(ks, p, a, b) + b / p * (log(ks) - lkc);
}

// The three cel of the opposite-sign side conditions, which share the modulus:
//   c111 = cel(kc, 1, 1, 1), c110 = cel(kc, 1, 1, 0), cp = cel(kc, p, 0, 1),
// in one pass of the loop of cel: the AGM of kc (kc, e, em) is common to all
// three and p's sequence to the first two, so each is computed by exactly the
// operations of its own call (bitwise the three calls) at about half their
// cost (one square root and five divisions per step instead of three and
// six). Running out of max_iterations throws no_convergence.
template <class T> struct cel_triple { T c111, c110, cp; };

template <class T> cel_triple<T> cel3(T kc, T p3, int max_iterations = 200) {
  using std::abs;
  using std::sqrt;
  if (!(kc > 0) || !(p3 > 0)) throw error(status::internal, "cel: needs kc > 0 and p > 0");
  const T ca = sqrt(boost::math::tools::epsilon<T>());
  T e = kc, em = T(1);
  // streams 1, 2: p = 1 (sqrt(1) = 1, b /= 1 exact); stream 3: a = 0, b = 1
  T p = T(1), a1 = T(1), b1 = T(1), a2 = T(1), b2 = T(0);
  p3 = sqrt(p3);
  T a3 = T(0), b3 = T(1) / p3;
  int i = 0;
  for (; i < max_iterations; ++i) {
    const T f1 = a1, f2 = a2, f3 = a3;
    a1 += b1 / p;
    a2 += b2 / p;
    a3 += b3 / p3;
    const T g = e / p, g3 = e / p3;
    b1 += f1 * g;
    b1 += b1;
    b2 += f2 * g;
    b2 += b2;
    b3 += f3 * g3;
    b3 += b3;
    p += g;
    p3 += g3;
    const T gm = em;
    em += kc;
    if (abs(gm - kc) <= gm * ca) break;
    kc = sqrt(e);
    kc += kc;
    e = kc * em;
  }
  check_iterations(i, max_iterations, "cel: the AGM iteration did not converge");
  const T h = boost::math::constants::half_pi<T>();
  return {h * (b1 + a1 * em) / (em * (em + p)), h * (b2 + a2 * em) / (em * (em + p)),
          h * (b3 + a3 * em) / (em * (em + p3))};
}

// cel3 for a modulus that may be below the range of T (as cel_log)
template <class T> cel_triple<T> cel3_log(const T &kc, const T &lkc, const T &p3) {
  using std::log;
  using std::min;
  using std::sqrt;
  if (!(p3 > 0)) throw error(status::internal, "cel: needs p > 0");
  const T ks = cel_switch<T>();
  if (kc > ks) {
    // the third's switch is ks min(1, sqrt(p3)) <= ks: the same unless p3 < 1
    if (p3 >= 1 || kc > ks * sqrt(p3)) return cel3(kc, p3);
    cel_triple<T> r = cel3(kc, T(1));
    r.cp = cel_log(kc, lkc, p3, T(0), T(1));
    return r;
  }
  const T lks = log(ks);
  cel_triple<T> r;
  if (p3 >= 1) {
    r = cel3(ks, p3);
    r.cp += 1 / p3 * (lks - lkc);
  } else {
    r = cel3(ks, T(1));
    r.cp = cel_log(kc, lkc, p3, T(0), T(1));
  }
  r.c111 += (lks - lkc);
  return r;
}

}}  // namespace hs::core
