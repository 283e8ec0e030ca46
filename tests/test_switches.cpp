// Spot values either side of every internal method switch of the core (issue 12
// item 7), as Boost.Math's spot tables do at its switch points: for each
// switch, the point itself, 1 and 4 ulps either side and 1/128 relative either
// side, in double and long double, each against an independent value computed
// at 50 significant digits (MPFR) from the *defining* formula, not from the
// core's code at a higher precision (which would take the same branches):
//   y_minus_sin, sinh_minus_y   (numerics.hpp, series below y = 1)     y - sin y, sinh y - y
//   sqrt_quadratic_integral     (numerics.hpp, asinh form for S <= w)  (U S - w^2 acosh(U/w))/2
//   power_law_pressure::F       (pressure.hpp: series for z <= 1/2;     int_0^1 (x^2 + z v^2)^((n-2)/2) dv
//                                odd-n recurrence; connection formula;  by tanh-sinh at 50 digits
//                                the recurrence from F at 1 + 2 delta
//                                when m = (n-1)/2 = k + delta is within
//                                1/8 of an integer (F_near_int);
//                                Euler-transformed series for z <= 1/2,
//                                binomial sum for n even, issue 13)
//   flat_rounded_pressure phi   (pressure.hpp, issue 13: closed forms   Ciavarella-Hills-Monno bracket
//   and dphi                     below tau* = 2 ep, Gauss ladder above   at 50 digits (derivative: central
//                                and its rungs; ln(1+u)/u series below   difference at 50 digits)
//                                u = 1/8; phi' series below tau* =
//                                ep eps^(1/9); phi = 1 at beta = 0;
//                                sin b = 0 at the kink)
//   cel_log                     (elliptic.hpp: log continuation below   Carlson R_F, R_J (Boost.Math) at
//                                kc = eps^0.6 min(1, sqrt p))            50 digits
//   add_semi_ellipse            (fields.hpp: real arithmetic on the     pi amp c (X - nu), pi amp (nu/X - 1)
//                                real axis for |nu| > 1, complex         with X = +-sqrt(nu^2 - 1) or
//                                otherwise)                              i sqrt(1 - nu^2), at 50 digits
//   sampled_pressure knot path  (pressure.hpp: from knot_tree_min = 256  the Hertz closed forms (long double)
//                                interior samples the knot quadrature,   for samples of a Hertz pressure
//                                knots.hpp, below a panel end at every
//                                sample; issue 13 item 4)
// Errors are measured in units of eps of the type under test. Every bound is
// justified where it is set. Each switch was checked to fail when the branch on
// one side is broken (see the commit message of this file).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "halfslip/core/elliptic.hpp"
#include "halfslip/core/fields.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/numerics.hpp"
#include "halfslip/core/pressure.hpp"
#include "testing.hpp"

namespace core = hs::core;
using mp =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<50>, boost::multiprecision::et_off>;

namespace {

template <class T> T eps() { return std::numeric_limits<T>::epsilon(); }

// |v - r| / |r| in units of eps<T> (r the 50-digit reference; T -> mp is exact)
template <class T> double rel_err(const T &v, const mp &r) {
  if (!std::isfinite(double(v))) return HUGE_VAL;
  return double(abs(mp(v) - r) / abs(r)) / double(eps<T>());
}

template <class T> T up(T x, int k = 1) {
  for (int i = 0; i < k; ++i) x = std::nextafter(x, std::numeric_limits<T>::infinity());
  return x;
}
template <class T> T down(T x, int k = 1) {
  for (int i = 0; i < k; ++i) x = std::nextafter(x, -std::numeric_limits<T>::infinity());
  return x;
}

// The spot points around a switch point s > 0: 1/128 below, 4 and 1 ulps
// below, s, 1 and 4 ulps above, 1/128 above.
template <class T> std::vector<T> spots(const T &s) {
  return {s * (1 - T(1) / 128), down(s, 4), down(s), s, up(s), up(s, 4), s * (1 + T(1) / 128)};
}

// 50-digit tanh-sinh (tables built once; the default smallest complement,
// 4 min_value, overflows the node tables for MPFR types, as in numerics.hpp)
boost::math::quadrature::tanh_sinh<mp> &ts50() {
  static boost::math::quadrature::tanh_sinh<mp> q(15, mp("1e-200"));
  return q;
}

// F(z) = 2F1(1, 1 - n/2; 3/2; z) = int_0^1 (x^2 + z v^2)^((n-2)/2) dv, x^2 = 1 - z
// (the definition in pressure.hpp); the integrand is analytic on [0, 1] for x^2 > 0.
mp power_law_F_ref(const mp &n, const mp &z) {
  const mp y = 1 - z, e = (n - 2) / 2;
  return ts50().integrate([&](const mp &v) { return pow(y + z * v * v, e); }, mp(0), mp(1), mp("1e-45"));
}

// Flat punch with rounded corners (Ciavarella, Hills & Monno 1998), as
// written in pressure.hpp: x = sin(phi), beta = sin(phi0),
//   bracket = (pi - 2 phi0) cos phi + sin phi ln|sin(phi+phi0)/sin(phi-phi0)|
//             + sin phi0 ln|tan((phi+phi0)/2) tan((phi-phi0)/2)|,
//   p_hat = bracket / (pi - 2 phi0 - sin 2 phi0),   phi_model = p_hat / cos(phi).
mp flat_phi_ref(const mp &x, const mp &beta) {
  const mp pi = boost::math::constants::pi<mp>();
  const mp f = asin(x), f0 = asin(beta);
  const mp br = (pi - 2 * f0) * cos(f) + sin(f) * log(abs(sin(f + f0) / sin(f - f0))) +
                sin(f0) * log(abs(tan((f + f0) / 2) * tan((f - f0) / 2)));
  return br / ((pi - 2 * f0 - sin(2 * f0)) * cos(f));
}
// d phi / dx by a central difference at 50 digits: step 1e-22 << the distance
// to the edge and the kink (>= 1e-8 here), error h^2 phi''' + 1e-50/h, both far
// below 1e-25 relative.
mp flat_dphi_ref(const mp &x, const mp &beta) {
  const mp h("1e-22");
  return (flat_phi_ref(x + h, beta) - flat_phi_ref(x - h, beta)) / (2 * h);
}

// cel(kc, p, a, b) = a R_F(0, kc^2, 1) + (b - p a)/3 R_J(0, kc^2, 1, p) (DLMF 19.25)
mp cel_ref(const mp &kc, const mp &p, const mp &a, const mp &b) {
  const mp k2 = kc * kc;
  return a * boost::math::ellint_rf(mp(0), k2, mp(1)) + (b - p * a) / 3 * boost::math::ellint_rj(mp(0), k2, mp(1), p);
}

}  // namespace

// ---------------------------------------------------------------------------
TEST_CASE_TEMPLATE("switch: y_minus_sin and sinh_minus_y at y = 1 (series below, direct above)", T, double,
                   long double) {
  std::vector<T> ys = spots(T(1));
  // far on each side: where the direct form would lose everything, and well above
  for (T y : {T(1e-6), T(1e-3), T(0.25), T(3), T(40)}) ys.push_back(y);
  double worst = 0;
  for (const T &y : ys) {
    CAPTURE(double(y));
    const mp Y(y);
    // Direct form (y > 1): sin y and the subtraction are each correctly rounded
    // to within an ulp; the cancellation amplifies sin's rounding by
    // sin(y)/(y - sin y) <= 5.3 (at y = 1), so <= ~7 eps. Series (y <= 1):
    // alternating, terms decreasing by y^2/20 at least, about 9 terms in
    // double and 10 in long double at y = 1, each adding <= 1 eps of the sum:
    // <= ~4 eps in practice. Bound 8 eps.
    const double e1 = rel_err(core::y_minus_sin(y), Y - sin(Y));
    // sinh: no cancellation above y = 1 beyond sinh(y)/(sinh(y) - y) <= 6.4; series all positive.
    const double e2 = rel_err(core::sinh_minus_y(y), sinh(Y) - Y);
    CHECK(e1 <= 8);
    CHECK(e2 <= 8);
    worst = std::max(worst, std::max(e1, e2));
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("switch: sqrt_quadratic_integral at S = w (asinh form below, log form above)", T, double,
                   long double) {
  // S = sqrt(delta (2w + delta)) = w at delta = (sqrt 2 - 1) w
  double worst = 0;
  for (T w : {T(1), T(0.3), T(1e-3), T(7)}) {
    const T ds = (std::sqrt(T(2)) - 1) * w;
    // the points must straddle the switch as the code evaluates it
    const auto S = [&](const T &d) { return std::sqrt(d * (2 * w + d)); };
    T lo = ds, hi = ds;
    while (!(S(lo) <= w)) lo = down(lo);
    hi = up(lo);
    while (S(hi) <= w) hi = up(hi);
    lo = down(hi);
    REQUIRE(S(lo) <= w);
    REQUIRE(!(S(hi) <= w));
    std::vector<T> ds_v{lo * (1 - T(1) / 128), down(lo, 4), lo,       hi, up(hi, 4),
                        hi * (1 + T(1) / 128), w * T(1e-6), w * T(50)};
    for (const T &d : ds_v) {
      CAPTURE(double(w));
      CAPTURE(double(d));
      const mp W(w), D(d), U = W + D, SS = sqrt(D * (2 * W + D));
      const mp ref = (U * SS - W * W * log((U + SS) / W)) / 2;
      // asinh form: w^2/4 * sinh_minus_y(2 theta) (<= 8 eps, above) with theta = asinh(S/w)
      // carrying ~2 eps (sqrt, division, asinh); (sinh 2t - 2t) has condition
      // <= 3 in t: <= ~16 eps. Log form: U S - w^2 log(..) loses at most the
      // factor U S / (U S - w^2 Theta) <= 2.7 (at the switch) on ~3 eps inputs.
      // Bound 16 eps.
      const double e = rel_err(core::sqrt_quadratic_integral(d, w), ref);
      CHECK(e <= 16);
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

// ---------------------------------------------------------------------------
// Power law: F(x, z) takes z = 1 - x^2 from the caller; the points are chosen
// with z exact and x = sqrt(1 - z) rounded, or x exact with z = 1 - x^2 exact.
// The reference is F at the exact z. The connection formula uses x^2 (off by
// an ulp from 1 - z), which moves F by at most ~ (2m) eps relative.
namespace {
template <class T> double power_law_err(const T &n, const T &x, const T &z) {
  const core::power_law_pressure<T> pl(n);
  return rel_err(pl.F(x, z), power_law_F_ref(mp(n), mp(z)));
}
}  // namespace

TEST_CASE_TEMPLATE("switch: power-law F at z = 1 - x^2 = 1/2 (series below, other forms above)", T, double,
                   long double) {
  // n = 2.5: connection formula above; 3, 5: odd recurrence; 3.1, 4.9: F_near_int (m near an integer);
  // n = 1.5: connection with 2m < 1.
  double worst = 0;
  for (T n : {T(1.5), T(2.5), T(3), T(3.1), T(4.9), T(5)}) {
    for (const T &z : spots(T(0.5))) {
      CAPTURE(double(n));
      CAPTURE(double(z));
      const T x = std::sqrt(1 - z);
      // Series: terms of ratio <= z <= 1/2, ~55 (double) to ~65 (long double)
      // terms each adding <= 1 eps, the sum dominated by its first terms: few eps.
      // Recurrence: asinh and the recurrence with factors 2 p x^2/(2p+1) < 1 (stable).
      // Connection: two terms of like sign for these n. F_near_int: <= 16 eps (the
      // near-odd-n test below). Bound 32 eps for all (measured worst printed below).
      const double e = power_law_err(n, x, z);
      CHECK(e <= 32);
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("switch: power-law F at the exponent switches (odd, near-integer m, even)", T, double,
                   long double) {
  // For z > 1/2 the method depends on n only: m = (n-1)/2 an integer: recurrence;
  // |m - round(m)| < 1/8: F_near_int; n even: binomial sum; otherwise the
  // connection formula. Switch points: n = 3 (odd), n = 2.75, 3.25, 1.25
  // (|m - round m| = 1/8, connection at the point, F_near_int inside), n = 4 (even).
  double worst = 0;
  for (T ns : {T(1.25), T(2.75), T(3), T(3.25), T(4)}) {
    std::vector<T> nv = spots(ns);
    for (const T &n : nv) {
      if (!(n > 1)) continue;
      for (T x : {T(0.125), T(0.25), T(0.5)}) {  // z = 1 - x^2 exact
        const T z = 1 - x * x;
        CAPTURE(double(n));
        CAPTURE(double(x));
        // Bound as above: 32 eps.
        const double e = power_law_err(n, x, z);
        CHECK(e <= 32);
        worst = std::max(worst, e);
      }
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("power-law F for 1 < n < 1.25 (m near 0: the regrouped connection formula, issue 13)", T, double,
                   long double) {
  // Before: tanh-sinh quadrature per value (a solve at n = 1.05 took 4.5-8.9 s). Now the
  // connection formula regrouped around m = 0 (F_near_int at k = 0, F_delta): a series of negative terms
  // and one expm1; checked against 50-digit quadrature of the definition, down to
  // n - 1 = 2^-20 (where the two parts of the plain connection formula are ~2^19 times F)
  // and |x| = 2^-20 (the |x|^(2m) cusp), and on both sides of the switch n = 1.25.
  // Bound 16 eps below the switch (the prototype measured <= 2 eps); at and above it the
  // plain connection formula, whose two parts cancel by up to ~1/(2m) = 4: 32 eps as in
  // the switch tests above (worst printed below).
  double worst = 0;
  std::vector<T> ns{T(1) + std::ldexp(T(1), -20), T(1.001), T(1.01), T(1.05), T(1.1), T(1.2)};
  for (const T &n : spots(T(1.25))) ns.push_back(n);
  for (const T &n : ns) {
    for (T x : {std::ldexp(T(1), -20), T(0.0078125), T(0.125), T(0.25), T(0.5), T(0.703125)}) {
      const T z = 1 - x * x;  // exact
      CAPTURE(double(n));
      CAPTURE(double(x));
      const double e = power_law_err(n, x, z);
      CHECK(e <= (n < T(1.25) ? 16 : 32));
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("switch: power-law F at large exponents, every form (issue 13)", T, double, long double) {
  // Before issue 13 the series in z alternated (terms up to ~e^(n z/2)) and the even-n polynomial
  // likewise: F was off by 1e-9 relative at n = 50 and by 1e13 at n = 200; the Gamma ratio of the
  // connection formula was 0/0 (NaN) at n = 999.1. Now: Euler's transformation for z <= 1/2, the
  // binomial sum for even n, and the connection formula with the Gammas by reflection; where m is
  // within 1/8 of an integer F_near_int (before: a quadrature where m was also within n 2^-m of it,
  // elsewhere the connection formula, which stopped before its pole term). n = 60.99, 61.05, 307.2
  // and 999.1 put m within 1/8 of an integer (F_near_int; the connection formula before for all but
  // 307.2); 200.1 and 999.4 the reflected Gammas. Points either side of z = 1/2 and across the
  // contact. Every form sums ~n/2 positive terms (or raises |x| to 2m): a bound of 2 n eps.
  double worst = 0;
  for (T n : {T(50), T(60.99), T(61.05), T(200), T(200.1), T(307.2), T(500), T(999), T(999.1), T(999.4)}) {
    std::vector<T> zs = spots(T(0.5));
    for (T x : {T(0), T(0.125), T(0.5), T(0.9), T(0.99)}) zs.push_back(1 - x * x);
    for (const T &z : zs) {
      const T x = std::sqrt(1 - z);
      CAPTURE(double(n));
      CAPTURE(double(z));
      const double e = power_law_err(n, x, z);
      CHECK(e <= 2 * double(n));
      worst = std::max(worst, e / double(n));
    }
  }
  MESSAGE("worst relative error in units of n eps: " << worst);
}

// ---------------------------------------------------------------------------
// Power law near odd n (issue 13): for m = (n-1)/2 = k + delta, 0 < |delta| < 1/8, and
// z > 1/2, F was a tanh-sinh integral per value for k >= 1 (a double solve at n = 6.79
// near sliding took 6-13 s, and 30-64 s before NO_CONVERGENCE), and from m ~ 7 on only
// for |delta| < n 2^-int(m): outside that band the connection formula, whose series
// stopped before its pole term (n = 61 + 2^-19, x = 1/2: off by 1e4 eps, found by the
// k = 30 points below). Now (F_near_int) for every k: k steps of the recurrence
// I_p = (1 + 2 p y I_(p-1))/(2p + 1) from F at the exponent 1 + 2 delta, that by the
// connection formula regrouped around delta = 0 (as F_near_zero for 1 < n < 1.25 was,
// now for either sign of delta).
namespace {
using mp30 =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<30>, boost::multiprecision::et_off>;

// the branch predicate of power_law_pressure, repeated (z > 1/2 is the caller's part)
template <class T> bool power_law_near_int(const T &n) {
  using std::abs;
  using std::floor;
  const T m = (n - 1) / 2, mr = floor(m + T(0.5));
  return mr != m && abs(m - mr) < T(0.125);
}

// Bounds, in eps of T. The new branch: F_delta sums ~log(eps)/log(y) negative terms
// (each <= 1 eps of the sum, the sum dominated by its first terms) and adds one expm1
// (a few eps: the argument 2 delta ln|x| + ln c carries a few eps of itself, ln c from
// series of ~log(eps)/log(4 |delta|) terms); A + B cancels by at most ~1.2x (y = 1/2).
// Each recurrence step adds ~3 roundings and passes on at most ~1/2 of the old error
// (2 p y I_(p-1) <= ~y/z < 1 of 1 + that): a few eps whatever k. Bound 16 eps (the
// F_near_zero bound). Other forms as in the tests above: 32 eps, or 2 n eps for large n.
template <class T> double power_law_bound(const T &n, const T &z) {
  if (z > T(0.5) && power_law_near_int(n)) return 16;
  return std::max(32.0, 2 * double(n));
}

template <class T> void power_law_near_odd_points(double &worst_new, double &worst_other, int &n_new) {
  using std::ldexp;
  using std::sqrt;
  double wn = 0, wo = 0;
  int cnt = 0;
  const std::vector<T> deltas{T(0),          ldexp(T(1), -40), -ldexp(T(1), -40), ldexp(T(1), -20), -ldexp(T(1), -20),
                              T(1) / 1000,   -T(1) / 1000,     T(1) / 10,         -T(1) / 10,       T(124) / 1000,
                              -T(124) / 1000};
  for (int k : {1, 2, 3, 4, 10, 30, 100, 499}) {
    for (const T &d : deltas) {
      const T n = T(2 * k + 1) + 2 * d;
      const core::power_law_pressure<T> pl(n);
      // (x, z) with z = 1 - x^2 exact (x dyadic), or z exact and x = sqrt(1 - z) rounded
      // (near the edge and at the switch z = 1/2); x = 1e-100: z rounds to 1, y far below
      // eps; x = 0: F = 1/(n - 1).
      std::vector<std::pair<T, T>> pts;
      for (T x : {T(0), T(1e-100), ldexp(T(1), -20), T(0.0078125), T(0.125), T(0.5), T(0.703125)})
        pts.push_back({x, T(1 - x * x)});
      for (T z : {T(0.5) * (1 - T(1) / 128), T(0.5), T(0.5) * (1 + T(1) / 128), ldexp(T(1), -4), ldexp(T(1), -20)})
        pts.push_back({T(sqrt(T(1 - z))), z});
      for (const auto &p : pts) {
        CAPTURE(k);
        CAPTURE(double(d));
        CAPTURE(double(p.first));
        CAPTURE(double(p.second));
        const double e = rel_err(pl.F(p.first, p.second), power_law_F_ref(mp(n), mp(p.second)));
        const double b = power_law_bound(n, p.second);
        CHECK(e <= b);
        if (b == 16) {
          wn = std::max(wn, e);
          ++cnt;
        } else {
          wo = std::max(wo, e / b);
        }
      }
    }
  }
  worst_new = wn;
  worst_other = wo;
  n_new = cnt;
}
}  // namespace

TEST_CASE_TEMPLATE("power-law F near odd n: m = k + delta, k = 1, 2, 3, 4, 10, 30, 100, 499 (issue 13)" * HS_LONG, T, double,
                   long double, mp30) {
  double wn = 0, wo = 0;
  int cnt = 0;
  power_law_near_odd_points<T>(wn, wo, cnt);
  // the new branch: every k, every delta != 0, the 8 points with z > 1/2
  CHECK(cnt == 8 * 10 * 8);
  MESSAGE("near-integer branch: " << cnt << " points, worst " << wn << " eps; other forms: worst " << wo
                                  << " of their bound");
}

TEST_CASE("power-law F: a NaN x with z > 1/2 gives NaN, not a series run out (issue 13)") {
  // F_near_int's series stops on a small term, which never holds for NaN (it ran 100000 terms
  // and threw); the connection formula's series had the guard already.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double n : {1.05, 2.5, 3.1, 6.79, 61.05}) {
    CAPTURE(n);
    const core::power_law_pressure<double> pl(n);
    double v = 0;
    CHECK_NOTHROW(v = pl.F(nan, 0.75));
    CHECK(std::isnan(v));
  }
}

// The switches of the near-integer branch in n (z > 1/2): |delta| = 1/8 (k = 1 .. 6, 10, 30,
// 200, 499, both signs: n = 2k + 1 -+ 1/4), each straddled by adjacent n as the code rounds
// them, with the spots 4 ulps and 1/128 relative either side.
TEST_CASE_TEMPLATE("switch: power-law F at the edges of the near-odd-n band (issue 13)" * HS_LONG, T, double, long double) {
  double worst_in = 0, worst_out = 0;
  int switches = 0;
  std::vector<std::pair<T, T>> brackets;  // (inside, outside) of the band
  for (int k : {1, 2, 3, 4, 5, 6, 10, 30, 200, 499})
    for (int s : {-1, 1}) brackets.push_back({T(2 * k + 1) + s * T(0.2), T(2 * k + 1) + s * T(0.3)});
  for (auto br : brackets) {
    T in = br.first, out = br.second;
    REQUIRE(power_law_near_int(in));
    REQUIRE(!power_law_near_int(out));
    // bisection to adjacent values
    for (int i = 0; i < 200 && up(std::min(in, out)) != std::max(in, out); ++i) {
      const T mid = (in + out) / 2;
      if (mid == in || mid == out) break;
      (power_law_near_int(mid) ? in : out) = mid;
    }
    REQUIRE(up(std::min(in, out)) == std::max(in, out));
    ++switches;
    const bool rising = in < out;  // inside below the switch
    std::vector<T> ns{rising ? down(in, 4) : up(in, 4),
                      in,
                      out,
                      rising ? up(out, 4) : down(out, 4),
                      rising ? in * (1 - T(1) / 128) : in * (1 + T(1) / 128),
                      rising ? out * (1 + T(1) / 128) : out * (1 - T(1) / 128)};
    for (const T &n : ns) {
      if (!(n < 1000)) continue;  // the domain (k = 499: 1/128 above 999.25)
      for (T x : {ldexp(T(1), -20), T(0.125), T(0.5)}) {
        const T z = 1 - x * x;
        CAPTURE(double(n));
        CAPTURE(double(x));
        const double e = power_law_err(n, x, z);
        const double b = power_law_bound(n, z);
        CHECK(e <= b);
        if (b == 16) worst_in = std::max(worst_in, e);
        else worst_out = std::max(worst_out, e / b);
      }
    }
  }
  CHECK(switches == 20);
  MESSAGE(switches << " switches; worst inside " << worst_in << " eps, outside " << worst_out << " of the bound");
}

// ---------------------------------------------------------------------------
// Flat punch (issue 13: the evaluation from the inversion integral in tau,
// pressure.hpp): phi = [T(|x|) + T(-|x|)]/g, each T by closed forms below
// tau* = 2 ep and by a ladder of Gauss rules above; in the corner ln(1+u)/u
// by its series for u < 1/8, and phi' by the even series in tau* near the edge.
namespace {
// adjacent x_lo < x_hi with pred(x_lo) != pred(x_hi) (x >= 1/2: dp = 1 - x is exact;
// below, the predicates repeat the code's own rounding of min(1 + x, 1 - x))
template <class T, class P> void straddle(T x, const P &pred, T &lo, T &hi) {
  const bool p0 = pred(x);
  T y = x;
  // walk up until the predicate changes (at most a few ulps from the rounded switch point)
  for (int i = 0; i < 100000 && pred(y) == p0; ++i) y = up(y);
  if (pred(y) != p0) {
    lo = down(y);
    hi = y;
    return;
  }
  y = x;
  for (int i = 0; i < 100000 && pred(y) == p0; ++i) y = down(y);
  lo = y;
  hi = up(y);
}
template <class T> std::vector<T> spots_pair(const T &lo, const T &hi) {
  const T d = 1 - lo;  // distance to the edge: the 1/128 steps are taken in it
  return {1 - d * (1 + T(1) / 128), down(lo, 4), lo, hi, up(hi, 4), 1 - (1 - hi) * (1 - T(1) / 128)};
}
}  // namespace

namespace {
// The value spots of one switch of the flat punch: adjacent lo < hi straddling
// pred, then phi (relative, eps of T) and phi' (against `dscale`, eps of T)
// at spots_pair(lo, hi), against the 50-digit bracket and its central difference.
template <class T, class P, class S>
void flat_switch_spots(const core::flat_rounded_pressure<T> &fp, const T &beta, const T &x0, const P &pred,
                       const S &dscale, double bound_p, double bound_d, double &worst_p, double &worst_d) {
  T lo, hi;
  straddle(x0, pred, lo, hi);
  REQUIRE(pred(lo) != pred(hi));
  for (const T &x : spots_pair(lo, hi)) {
    CAPTURE(double(beta));
    CAPTURE(double(x));
    const mp X(x), B(beta);
    T d;
    const T ph = fp.phi_dphi(x, 1 + x, 1 - x, d);
    const mp pref = flat_phi_ref(X, B), dref = flat_dphi_ref(X, B);
    const double ep = rel_err(ph, pref);
    const double ed = double(abs(mp(d) - dref) / dscale(X, pref, dref)) / double(eps<T>());
    CHECK(ep <= bound_p);
    CHECK(ed <= bound_d);
    CHECK(fp.phi(x, 1 + x, 1 - x) == ph);
    worst_p = std::max(worst_p, ep);
    worst_d = std::max(worst_d, ed);
  }
}
// phi' is measured against phi/c^2 (the size of its terms; phi' itself
// vanishes where the two T terms balance)
const auto flat_dscale = [](const mp &X, const mp &p, const mp &) { return mp(p / (1 - X * X)); };
}  // namespace

// Issue 13: phi = [T(|x|) + T(-|x|)]/g (pressure.hpp), each T by a closed form
// for tau* < 2 ep and by the Gauss ladder above, i.e. a switch at D = 1 - X =
// closed_form_distance(): for X = |x| at x = cos(2 ep) (every beta), for
// X = -|x| at |x| = -cos(2 ep) (beta < cos(pi/4), where 2 ep > pi/2).
TEST_CASE_TEMPLATE("switch: flat-punch phi at tau* = 2 ep (closed forms below, Gauss ladder above)", T, double,
                   long double) {
  double worst_p = 0, worst_d = 0;
  int switches = 0;
  for (T beta : {T(0.05), T(0.3), T(0.6), T(0.9), T(0.999), T(0.9999)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    const T D0 = fp.closed_form_distance();
    // the predicates as evaluated in pressure.hpp: dist = min(dm, dp), D = dist or 2 - dist
    const auto plus = [&](const T &x) { return std::min(1 + x, 1 - x) >= D0; };
    const auto minus = [&](const T &x) { return 2 - std::min(1 + x, 1 - x) >= D0; };
    // closed side: T = ep - (2 sin a sin b / sin tau*) ln(sin a / sin b), cancelling at most
    // ~6x at tau* = 2 ep (the product is 0.82 ep there) on a few ulps per factor; Gauss
    // side: <= 10 positive terms (truncation eps/64 by the ladder's choice); g to ~3 eps.
    // Bound 32 eps. phi': the closed side's [ln(..)(1 - cos ep cos tau*) - sin ep sin tau*]
    // / sin^3 tau* cancels ~2.4x: bound 64 eps of phi/c^2.
    if (D0 <= 1) {
      flat_switch_spots(fp, beta, T(1 - D0), plus, flat_dscale, 32, 64, worst_p, worst_d);
      ++switches;
    }
    if (D0 >= 1 && D0 < 2) {
      flat_switch_spots(fp, beta, T(1 - (2 - D0)), minus, flat_dscale, 32, 64, worst_p, worst_d);
      ++switches;
    }
  }
  CHECK(switches == 6);  // X = -|x| for beta = 0.05, 0.3, 0.6; X = |x| for 0.9, 0.999, 0.9999
  MESSAGE("worst error in eps: phi " << worst_p << " (relative), dphi " << worst_d << " (of phi/c^2)");
}

// The rungs of the Gauss ladder: the order rises as tau* approaches 2 ep.
TEST_CASE_TEMPLATE("switch: flat-punch phi at the rungs of the Gauss ladder", T, double, long double) {
  double worst_p = 0, worst_d = 0;
  int rungs = 0;
  for (T beta : {T(0.9), T(0.999), T(0.9999)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    const auto dists = fp.ladder_distances();
    REQUIRE(dists.size() >= 2);
    for (std::size_t j = 0; j + 1 < dists.size(); ++j) {
      const T Dj = dists[j];
      if (!(Dj < 1)) continue;  // the rung serves X = |x| only from x = 1 - Dj > 0
      const auto pred = [&](const T &x) { return std::min(1 + x, 1 - x) >= Dj; };
      // both sides: positive Gauss terms, truncation <= eps/64 by construction: bound 16 eps
      // (phi' the same sums with squared denominators: 16 eps of phi/c^2)
      flat_switch_spots(fp, beta, T(1 - Dj), pred, flat_dscale, 16, 16, worst_p, worst_d);
      ++rungs;
    }
  }
  CHECK(rungs >= 8);
  MESSAGE("worst error in eps: phi " << worst_p << " (relative), dphi " << worst_d << " (of phi/c^2)");
}

// The rounded corner: ln(1 + u)/u by its series for u < 1/8, by log1p above;
// and phi' by the even series in tau* below series_distance(), by the product
// rule above.
TEST_CASE_TEMPLATE("switch: flat-punch corner: ln(1+u)/u at u = 1/8 and phi' at tau* = ep eps^(1/9)", T, double,
                   long double) {
  double worst_p = 0, worst_d = 0;
  for (T beta : {T(0.05), T(0.3), T(0.9), T(0.999)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    // u as pressure.hpp forms it from D = dist (X = |x| > beta)
    const T ce2 = std::sqrt((1 + beta) / 2), se2 = std::sqrt((1 - beta) / 2), omb = 1 - beta;
    const auto u_of = [&](const T &x) {
      const T D = std::min(1 + x, 1 - x);
      const T sh = std::sqrt(D / 2), ch = std::sqrt((2 - D) / 2);
      const T sa = sh * ce2 + ch * se2, nb = (omb - D) / (2 * sa);
      return 2 * ce2 * sh / nb;
    };
    // u = 1/8: tau*/ep ~ 1/16 (u ~ tau* cot(ep/2) for small tau*); find it by bisection in dist
    T lo = 0, hi = omb;
    for (int i = 0; i < 200; ++i) {
      const T m = (lo + hi) / 2;
      (u_of(T(1 - m)) < T(0.125) ? lo : hi) = m;
    }
    // series side: alternating, terms falling by u <= 1/8, ~18 terms in double; log1p side
    // as accurate: bound 16 eps for phi. phi' (product rule there): bound 64 eps of phi/c^2.
    flat_switch_spots(
        fp, beta, T(1 - lo), [&](const T &x) { return u_of(x) < T(0.125); }, flat_dscale, 16, 64, worst_p, worst_d);
    // phi': series below D = series_distance(), product rule above; both measured
    // ~60 eps relative at the switch (pressure.hpp) where phi' is of the size of its
    // terms (b_f -> a: phi' ~ phi/(1 - beta)); for small beta the two T' nearly cancel
    // (phi' = 0.022 phi at beta = 0.05). Bound 256 eps of max(|phi'|, phi).
    const T Ds = fp.series_distance();
    flat_switch_spots(
        fp, beta, T(1 - Ds), [&](const T &x) { return std::min(1 + x, 1 - x) < Ds; },
        [](const mp &, const mp &p, const mp &d) { return abs(d) > p ? mp(abs(d)) : p; }, 16, 256, worst_p, worst_d);
  }
  MESSAGE("worst error in eps: phi " << worst_p << " (relative), dphi " << worst_d);
}

// Issue 13: the bracket form cancelled ~4/g of its digits as b_f -> a (g = 2 ep - sin 2 ep;
// measured 1.1e3 eps at b_f/a = 0.99, 3.5e4 at 0.999, 1.6e6 at 0.9999); the solver lost
// the stick zone at b_f/a = 0.999 from sigma/fp0 = 100. Every x of a fine grid, the flat,
// the kink's neighbourhood and the corner down to 1e-12 (1 - beta) from the edge.
TEST_CASE_TEMPLATE("flat-punch phi as b_f -> a: every x within 16 eps (issue 13)", T, double, long double) {
  double worst = 0;
  for (T beta : {T(0.5), T(0.99), T(0.999), T(0.9999)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    std::vector<T> xs;
    for (int i = 0; i < 64; ++i) xs.push_back(T(i) / 64 * beta);  // the flat (the kink itself: its own test)
    for (int k = 1; k <= 12; ++k) {
      const T h = (1 - beta) * std::pow(T(10), -T(k));
      xs.push_back(beta - h);  // next to the kink
      xs.push_back(beta + h);
      xs.push_back(1 - h);  // the corner, at the edge
    }
    for (int i = 1; i < 16; ++i) xs.push_back(beta + (1 - beta) * T(i) / 16);  // the corner
    for (const T &x : xs) {
      CAPTURE(double(beta));
      CAPTURE(double(x));
      const T dp = 1 - x;
      // every form: positive Gauss terms, or a closed form cancelling at most ~6x (r = 2): 16 eps
      const double e = rel_err(fp.phi(x, 1 + x, dp), flat_phi_ref(mp(x), mp(beta)));
      CHECK(e <= 16);
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("switch: flat-punch phi at the kink x = beta (D = 0 handled apart)", T, double, long double) {
  double worst = 0;
  for (T beta : {T(0.3), T(0.6), T(0.9)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    for (const T &x : {down(beta, 4), down(beta), beta, up(beta), up(beta, 4)}) {
      CAPTURE(double(beta));
      CAPTURE(double(x));
      // at x = beta exactly the reference's two logarithms diverge: evaluated
      // 1e-40 away (phi is continuous, modulus ~ |dx log dx| ~ 1e-38)
      const mp X = x == beta ? mp(x) + mp("1e-40") : mp(x);
      const double e = rel_err(fp.phi(x, 1 + x, 1 - x), flat_phi_ref(X, mp(beta)));
      // at the kink sin b = (D - (1 - beta))/(2 sin a) is exactly 0 and T(|x|) = ep; next to
      // it T = ep - (2 sin a sin b/sin tau*) ln(sin a/sin b) with the product << ep: no
      // cancellation. Bound 16 eps.
      CHECK(e <= 16);
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE_TEMPLATE("switch: flat-punch phi at beta = 0 (Hertz, phi = 1) and just above", T, double, long double) {
  // beta == 0 returns phi = 1 (Hertz); any beta > 0 takes the logarithmic forms, whose
  // terms of size beta ln(..) must then vanish smoothly: beta = 1e-300 .. 1e-3.
  double worst = 0;
  for (T beta : {T(0), std::numeric_limits<T>::min(), T(1e-300), T(1e-30), T(1e-10), T(1e-3)}) {
    const core::flat_rounded_pressure<T> fp(beta);
    for (T x : {T(0), T(0.25), T(0.5), T(0.875), T(1) - T(1) / 1024}) {
      CAPTURE(double(beta));
      CAPTURE(double(x));
      const T ph = fp.phi(x, 1 + x, 1 - x);
      // the reference: phi = 1 at beta = 0; at x = 0 < beta the formula's |x| = 0 is fine
      const mp ref = beta == 0 ? mp(1) : flat_phi_ref(mp(x), mp(beta));
      // both forms as above, no cancellation for small beta: bound 16 eps
      const double e = rel_err(ph, ref);
      CHECK(e <= 16);
      worst = std::max(worst, e);
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

// ---------------------------------------------------------------------------
TEST_CASE_TEMPLATE("switch: cel_log at kc = eps^0.6 min(1, sqrt p) (cel above, log continuation below)", T, double,
                   long double) {
  double worst = 0;
  for (T p : {T(1), T(0.25), T(4), T(1e-4)}) {
    const T ks = std::pow(eps<T>(), T(0.6)) * std::min(T(1), std::sqrt(p));
    std::vector<T> kv = spots(ks);
    kv.push_back(ks * T(1e-3));
    kv.push_back(ks * T(1e3));
    for (const T &kc : kv) {
      for (const auto &ab : std::vector<std::pair<T, T>>{{T(1), T(1)}, {T(0), T(1)}, {T(1), T(0)}}) {
        CAPTURE(double(p));
        CAPTURE(double(kc));
        CAPTURE(double(ab.first));
        CAPTURE(double(ab.second));
        const T v = core::cel_log(kc, T(std::log(kc)), p, ab.first, ab.second);
        const mp r = cel_ref(mp(kc), mp(p), mp(ab.first), mp(ab.second));
        // cel: ~6 AGM steps each a few roundings (test_elliptic.cpp: < 64 eps
        // against Carlson, both sides counted); below the switch the dropped
        // remainder O(kc^2/p ln kc) is < eps by the choice of ks and ln kc
        // carries 1/2 ulp of ~ln(1/kc) absolute. Bound 32 eps.
        const double e = rel_err(v, r);
        CHECK(e <= 32);
        worst = std::max(worst, e);
      }
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

// ---------------------------------------------------------------------------
TEST_CASE_TEMPLATE("switch: add_semi_ellipse on the real axis at |nu| = 1 (real form outside, complex inside)", T,
                   double, long double) {
  // c = 1, e = 0: nu = zeta exactly. Outside the support X = sign(nu) sqrt(nu^2 - 1);
  // on it (the limit from Im zeta > 0) X = i sqrt(1 - nu^2). nu = +-1 itself has F1 infinite: skipped.
  double worst = 0;
  for (T side : {T(1), T(-1)}) {
    for (const T &m : spots(T(1))) {
      const T nu = side * m;
      if (std::abs(nu) == 1) continue;
      CAPTURE(double(nu));
      const T amp = T(0.3);
      core::cauchy_pair<T> out;
      core::add_semi_ellipse<T>(amp, T(1), T(0), std::complex<T>(nu, T(0)), out);
      const mp N(nu), A(amp), pi = boost::math::constants::pi<mp>();
      mp f0r, f0i, f1r, f1i;
      if (abs(N) > 1) {
        const mp X = (N > 0 ? 1 : -1) * sqrt(N * N - 1);
        f0r = pi * A * (X - N);
        f0i = 0;
        f1r = pi * A * (N / X - 1);
        f1i = 0;
      } else {
        const mp Y = sqrt(1 - N * N);  // X = i Y
        f0r = -pi * A * N;
        f0i = pi * A * Y;
        f1r = -pi * A;
        f1i = -pi * A * N / Y;  // nu / (i Y) = -i nu / Y
      }
      // |F - ref| / |ref| (complex moduli): sqrt of a product with nu - 1 exact
      // (Sterbenz), a division and a product with pi: a few ulps. Bound 8 eps.
      const auto err = [&](const std::complex<T> &v, const mp &re, const mp &im) {
        const mp dr = mp(v.real()) - re, di = mp(v.imag()) - im;
        return double(sqrt(dr * dr + di * di) / sqrt(re * re + im * im)) / double(eps<T>());
      };
      const double e0 = err(out.F0, f0r, f0i), e1 = err(out.F1, f1r, f1i);
      CHECK(e0 <= 8);
      CHECK(e1 <= 8);
      worst = std::max(worst, std::max(e0, e1));
    }
  }
  MESSAGE("worst relative error in eps: " << worst);
}

TEST_CASE("switch: sampled pressure at knot_tree_min interior samples (panels below, knot quadrature from there)") {
  // Hertz samples (phi constant: the interpolant is exact), 254 .. 258 interior
  // samples, and the samples at the switch solved on both paths (tree_min
  // moved): every result against the long-double Hertz closed forms. Bounds:
  // zones 450 eps (test_general.cpp's sampled-Hertz bound: the solver's
  // residual tolerance), energies eps^(3/4) relative (the energies' order
  // control). Observed: zones within 9 eps, energies within 3e-14, on both
  // sides; the two paths differ by a few ulps (the normalisation, the
  // quadrature of the zone integrals).
  const std::size_t K = core::sampled_pressure<double>::knot_tree_min;
  const double e34 = std::pow(eps<double>(), 0.75);
  core::hertz_scene<long double> hs;
  hs.q = 0.3L;
  hs.s = 1.0L;
  const auto h = core::solve_hertz(hs);
  for (std::size_t m = K - 2; m <= K + 2; ++m) {
    std::vector<double> xs, ps;
    const std::size_t n = m + 1;  // m interior samples and the two edges
    for (std::size_t i = 0; i <= n; ++i) {
      const double x = i == 0 ? -1.0 : (i == n ? 1.0 : -std::cos(M_PI * double(i) / double(n)));
      xs.push_back(x);
      ps.push_back(i == 0 || i == n ? 0.0 : std::sqrt((1 - x) * (1 + x)));
    }
    for (std::size_t tree_min : {K, m, m + 1}) {
      core::sampled_pressure<double> sp(xs, ps, 1.0, nullptr, tree_min);
      CAPTURE(m);
      CAPTURE(tree_min);
      CHECK(bool(sp.knots()) == (m >= tree_min));
      core::general_scene<double> sc;
      sc.p0 = sp.p0();
      sc.q = 0.3;
      sc.s = 1.0;
      const auto g = core::solve_general<double>(sp, sc);
      CHECK(std::abs(g.d1() - double(h.delta1)) < 450 * eps<double>());
      CHECK(std::abs(g.d2() - double(h.delta2)) < 450 * eps<double>());
      const double s2 = sp.p0() * sp.p0();
      CHECK(std::abs(g.energy(1) / s2 - double(h.energy(1))) <= e34 * double(h.energy(1)));
      CHECK(std::abs(g.energy(2) / s2 - double(h.energy(2))) <= e34 * double(h.energy(2)));
    }
  }
}
