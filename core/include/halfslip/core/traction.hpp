// halfslip core: the shear traction q(x) of a monotonic partial-slip solution,
// for any pressure, from the pressure and the stick zone alone.
//
// Conventions (docs/conventions.md): q is the shear traction that body 2
// exerts on body 1, positive in +x; Q is its resultant. On the slip zones
// q = dir_i f p(x). On the stick zone (-b2, b1) the relative surface strain
// vanishes, E* B_x = (2/pi) PV int q(xi)/(x - xi) dxi - sigma/2 = 0, a finite
// Hilbert problem for q on the stick zone whose solution bounded at both
// stick boundaries is (docs/fields.md derives it)
//
//   q(x) = R(x)/pi * int_slip q_sl(xi) sgn(xi) / ((xi - x) Rext(xi)) dxi,
//   R(x) = sqrt((b1 - x)(x + b2)),  Rext(xi) = sqrt(|xi - b1| |xi + b2|),
//
// sgn = +1 on zone 1 (xi > b1), -1 on zone 2. Q and sigma enter only through
// b1, b2 (the side conditions make the bounded solution exist and carry Q).
// With xi = b1 + d1 u^2 (zone 1) and xi = -b2 - d2 u^2 (zone 2) both zone
// integrals read int_0^1 2 sqrt(d) g(u) / (eps + d u^2) du, g = q_sl/sqrt(w + d u^2),
// eps = distance of x to that zone's stick boundary, w = b1 + b2; the nearly
// singular part g(0)/(eps + d u^2) is integrated exactly (atan), the rest by
// tanh-sinh.
#pragma once
#include <cmath>
#include <type_traits>
#include <vector>

#include "numerics.hpp"

namespace hs { namespace core {

// The pressure at x, at distance c from the contact edge on `side` (+1: x = a,
// -1: x = -a): p(x, side, c) where P takes the distance (it then need not form
// a -+ x, which near the edge has lost the digits of a zone narrower than
// ~1e-8 a: issue 13, a flat punch with 1 - b_f/a = 4.5e-12 and slip zones of
// 2e-13 a, whose pressure came out as a staircase and whose traction took the
// tanh-sinh to its last level, 27 s for the CLI's surface stresses), else p(x).
template <class T, class P> T pressure_at(const P &p, const T &x, int side, const T &c) {
  if constexpr (std::is_invocable_v<const P &, const T &, int, const T &>) return p(x, side, c);
  else return p(x);
}

// P: callable p(x) in the user frame, or p(x, side, c) (pressure_at). kinks: points of (-a, a) where p is not
// smooth (split points of the quadrature). Returns q(x); 0 outside |x| < a.
// tol: the tanh-sinh termination tolerance (0: root epsilon of T); ts: an
// integrator to reuse (make_tanh_sinh), nullptr: a new one per zone integral.
template <class T, class P> T monotonic_traction(const P &p, const T &a, const T &f, const T &b1, const T &b2,
                                                 int dir1, int dir2, const T &x, const std::vector<T> &kinks = {},
                                                 T tol = T(0),
                                                 boost::math::quadrature::tanh_sinh<T> *ts = nullptr) {
  using std::atan;
  using std::sqrt;
  if (!(x > -a && x < a)) return T(0);
  const T d1 = a - b1, d2 = a - b2;
  if (d1 > 0 && x >= b1) return dir1 * f * pressure_at(p, x, +1, T(a - x));
  if (d2 > 0 && x <= -b2) return dir2 * f * pressure_at(p, x, -1, T(a + x));
  if (!(d1 > 0) && !(d2 > 0)) return T(0);  // fully stuck: Q = sigma = 0
  if (!(tol > 0)) tol = boost::math::tools::root_epsilon<T>();
  const T w = b1 + b2;
  auto zone = [&](int side) -> T {
    const T d = side > 0 ? d1 : d2;
    if (!(d > 0)) return T(0);
    const int dir = side > 0 ? dir1 : dir2;
    if (dir == 0) return T(0);
    const T ep = side > 0 ? b1 - x : x + b2;  // > 0 in the stick zone
    const T sd = sqrt(d);
    // g(u) = dir f p(xi) / sqrt(w + d u^2), xi = b +- d u^2
    auto g = [&](const T &u, const T &uc) {
      // the distance to the contact edge, d (1 - u^2): uc > 0 is 1 - u exact near
      // the edge; (1 - u)(1 + u) elsewhere (1 - u exact for u >= 1/2)
      const T cdist = uc > 0 ? T(d * uc * (2 - uc)) : T(d * (1 - u) * (1 + u));
      const T xi = side > 0 ? a - cdist : -a + cdist;
      return dir * f * pressure_at(p, xi, side, cdist) / sqrt(w + d * u * u);
    };
    const T g0 = dir * f * pressure_at(p, side > 0 ? b1 : -b2, side, d) / sqrt(w);
    std::vector<T> cuts;
    for (const T &k : kinks) {
      const T dist = side > 0 ? k - b1 : -b2 - k;
      if (dist > 0 && dist < d) cuts.push_back(sqrt(dist / d));
    }
    T sum = 2 * g0 / sqrt(ep) * atan(sd / sqrt(ep));  // int 2 sd g0/(ep + d u^2)
    cuts.push_back(T(0));
    cuts.push_back(T(1));
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const T lo = cuts[i], hi = cuts[i + 1];
      if (!(hi > lo)) continue;
      sum += integrate_ts<T>(
          [&](const T &u, const T &uc) {
            const T ue = (uc > 0 && hi == T(1)) ? uc : T(-1);
            return 2 * sd * (g(u, ue) - g0) / (ep + d * u * u);
          },
          lo, hi, tol, nullptr, nullptr, ts);
    }
    return sum;
  };
  const T R = sqrt((b1 - x) * (x + b2));
  return R / pi<T>() * (zone(+1) + zone(-1));
}

}}  // namespace hs::core
