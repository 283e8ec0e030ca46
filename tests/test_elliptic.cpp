// Bulirsch's cel against Boost.Math's Carlson R_F, R_D, R_J (duplication
// theorem), in double and long double. The identities used by the Hertz side
// conditions (core/elliptic.hpp):
//   R_F(0,P,Q) = cel(kc,1,1,1)/sqrt(Q), R_D(0,Q,P) = 3 cel(kc,1,1,0)/(P sqrt Q),
//   R_J(0,P,Q,r) = 3 cel(kc,r/Q,0,1)/(Q sqrt Q),  kc^2 = P/Q.
#include <doctest/doctest.h>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

#include "halfslip/core/elliptic.hpp"
#include "testing.hpp"

using hs::core::cel;
using hs_test::rel_eps;

TEST_CASE_TEMPLATE("cel reproduces Carlson R_F, R_D, R_J", T, double, long double) {
  hs_test::rng r(42);
  double worst_f = 0, worst_d = 0, worst_j = 0;
  for (int i = 0; i < 2000; ++i) {
    // P/Q spans k -> 1 (P/Q tiny) to k -> 0 (P/Q -> 1), r/Q spans (1e-12, 1e3)
    const T Q = T(r.log_uniform(1e-3, 1e3));
    const T P = Q * T(r.log_uniform(1e-30, 1.0));
    const T rr = Q * T(r.log_uniform(1e-12, 1e3));
    const T kc = std::sqrt(P / Q), sQ = std::sqrt(Q);
    const T rf = boost::math::ellint_rf(T(0), P, Q);
    const T rd = boost::math::ellint_rd(T(0), Q, P);
    const T rj = boost::math::ellint_rj(T(0), P, Q, rr);
    worst_f = std::max(worst_f, rel_eps(cel(kc, T(1), T(1), T(1)) / sQ, rf));
    worst_d = std::max(worst_d, rel_eps(3 * cel(kc, T(1), T(1), T(0)) / (P * sQ), rd));
    worst_j = std::max(worst_j, rel_eps(3 * cel(kc, rr / Q, T(0), T(1)) / (Q * sQ), rj));
  }
  MESSAGE("max rel. error in eps: R_F " << worst_f << ", R_D " << worst_d << ", R_J " << worst_j);
  // Both sides are few-ulp algorithms (Boost documents < 10 eps for these
  // Carlson forms; cel's AGM loses a few ulps per rounding in ~6 steps):
  // 64 eps bounds the sum of both errors with margin.
  CHECK(worst_f < 64);
  CHECK(worst_d < 64);
  CHECK(worst_j < 64);
}

TEST_CASE("cel rejects kc <= 0 and p <= 0 with an exception, not a crash") {
  CHECK_THROWS_AS(cel(0.0, 1.0, 1.0, 1.0), hs::core::error);
  CHECK_THROWS_AS(cel(0.5, -1.0, 1.0, 1.0), hs::core::error);
}

// Issue 16: the three cel of the opposite-sign side conditions in one pass
// are the three calls, bit for bit (the same operations on each stream), in
// both branches of the small-modulus switch.
TEST_CASE_TEMPLATE("cel3 is bitwise cel(kc,1,1,1), cel(kc,1,1,0), cel(kc,p,0,1)", T, double, long double) {
  hs_test::rng r(7);
  for (int i = 0; i < 500; ++i) {
    const T kc = T(r.log_uniform(1e-12, 1.0));
    const T p = T(r.log_uniform(1.0, 1e3));
    const auto c = hs::core::cel3(kc, p);
    CHECK(c.c111 == cel(kc, T(1), T(1), T(1)));
    CHECK(c.c110 == cel(kc, T(1), T(1), T(0)));
    CHECK(c.cp == cel(kc, p, T(0), T(1)));
    const T lkc = std::log(kc);
    const auto cl = hs::core::cel3_log(kc, lkc, p);
    CHECK(cl.c111 == hs::core::cel_log(kc, lkc, T(1), T(1), T(1)));
    CHECK(cl.c110 == hs::core::cel_log(kc, lkc, T(1), T(1), T(0)));
    CHECK(cl.cp == hs::core::cel_log(kc, lkc, p, T(0), T(1)));
  }
}
