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
template <class T> T cel_log(const T &kc, const T &lkc, const T &p, const T &a, const T &b) {
  using std::log;
  using std::min;
  using std::pow;
  using std::sqrt;
  if (!(p > 0)) throw error(status::internal, "cel: needs p > 0");
  const T ks = pow(boost::math::tools::epsilon<T>(), T(0.6)) * min(T(1), sqrt(p));
  if (kc > ks) return cel(kc, p, a, b);
  return cel(ks, p, a, b) + b / p * (log(ks) - lkc);
}

}}  // namespace hs::core
