// libFuzzer target: the dimensional entry points of the C ABI (issue 13):
// hs_scene_from_hertz_loads, hs_scene_from_power_law_loads and
// hs_scene_from_flat_rounded_loads. Each input value is either a raw double (NaN,
// Inf, denormals, huge values) or sign * 10^k with |k| <= 40. Asserts:
//   - a known status; on an error the scene and b_f/a are left untouched;
//   - on success: finite positive a and p0, f and E* as given, and the definitions
//     hold: P = pi a p0 / 2, Q/fP and sigma/(f p0) from Q and sigma, and each
//     geometry's relation between P and a (Hertz a^2 = 4PR/(pi E*); power law
//     P = (E*/2) n A a^n sqrt(pi) Gamma((n+1)/2)/Gamma(n/2+1); flat-rounded
//     a^2 (pi - 2 phi0 - sin 2 phi0) = 4RP/E* with b_f = a sin phi0, 0 <= b_f/a < 1);
//   - the routes agree: the power law with n = 2, A = 1/(2R) and the flat punch with
//     b_f = 0 are the Hertz scene (same a, p0 and ratios);
//   - the Hertz scene solves (hs_solve) with a known status, and its zone energies
//     are the dimensionless scene's times f^2 p0^2 a^2 / E* wherever that is a
//     double (HS_ERR_OVERFLOW only beyond it).
#include <halfslip/halfslip.h>

#include "fuzz_input.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace {
using hs_fuzz::reader;
using hs_fuzz::known;
bool close(long double x, long double y, long double rel) {
  return std::fabs(x - y) <= rel * std::fmax(std::fabs(x), std::fabs(y));
}
// The scene's definitions of the ratios and p0 (relative 1e-12, in long double)
void check_scene(const hs_scene &s, double P, double E, double f, double Q, double sigma) {
  HS_REQUIRE(s.struct_size == sizeof s);
  HS_REQUIRE(std::isfinite(s.a) && s.a > 0 && std::isfinite(s.p0) && s.p0 > 0);
  HS_REQUIRE(s.f == f && s.E_star == E && std::isfinite(s.Q_over_fP) && std::isfinite(s.sigma_over_fp0));
  const long double pi = 3.141592653589793238462643383279502884L;
  HS_REQUIRE(close(pi * s.a * s.p0 / 2, P, 1e-12L));
  // the ratios (a quotient that underflows below DBL_MIN keeps only absolute accuracy)
  const long double q = (long double)Q / ((long double)f * P), sg = (long double)sigma / ((long double)f * s.p0);
  HS_REQUIRE(std::fabs(s.Q_over_fP - q) <= 1e-12L * std::fabs(q) + 1e-300L);
  HS_REQUIRE(std::fabs(s.sigma_over_fp0 - sg) <= 1e-12L * std::fabs(sg) + 1e-300L);
}
bool same_scene(const hs_scene &x, const hs_scene &y, long double rel) {
  return close(x.a, y.a, rel) && close(x.p0, y.p0, rel) && close(x.Q_over_fP, y.Q_over_fP, rel) &&
         close(x.sigma_over_fp0, y.sigma_over_fp0, rel) && x.f == y.f && x.E_star == y.E_star;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  const uint8_t which = r.byte(), raw = r.byte();
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = (raw >> i & 1) ? r.real() : std::pow(10.0, r.ranged(40.0));
  // signs of Q and sigma from the input; the others positive unless raw
  const uint8_t signs = r.byte();
  if (!(raw & 16) && (signs & 1)) v[4] = -v[4];
  if (!(raw & 32) && (signs & 2)) v[5] = -v[5];
  double P = v[0], R = v[1], E = v[2], f = v[3], Q = v[4], sigma = v[5], n = v[6], bf = v[7];
  // loads that make sense (|Q| < fP) are the interesting case: tie Q to f P unless raw
  if (!(raw & 16)) Q = (signs & 1 ? -1 : 1) * f * P * (0.999 * double(r.byte()) / 255);
  if (!(raw & 64)) n = 1 + 1e-3 + 998 * double(r.byte()) / 255;
  if (!(raw & 128)) bf = R * double(r.byte()) / 64;

  hs_scene s, sentinel;
  std::memset(&sentinel, 0xA5, sizeof sentinel);
  s = sentinel;
  double flat = 12345;
  int st = HS_OK;
  const long double pi = 3.141592653589793238462643383279502884L;
  switch (which % 3) {
    case 0: {
      st = hs_scene_from_hertz_loads(P, R, E, f, Q, sigma, &s);
      HS_REQUIRE(known(st));
      if (st != HS_OK) {
        HS_REQUIRE(std::memcmp(&s, &sentinel, sizeof s) == 0);
        return 0;
      }
      if (std::getenv("HS_FUZZ_DEBUG"))
        std::fprintf(stderr, "P %.17g R %.17g E %.17g: a %.17g a^2 %.17Lg 4PR/(pi E) %.17Lg\n", P, R, E, s.a,
                     (long double)s.a * s.a, 4.0L * P * R / (pi * E));
      check_scene(s, P, E, f, Q, sigma);
      HS_REQUIRE(close((long double)s.a * s.a, 4.0L * P * R / (pi * E), 1e-12L));
      // the same contact through the other two entry points
      hs_scene pl = sentinel, fr = sentinel;
      const int pst = hs_scene_from_power_law_loads(P, 1 / (2 * R), 2, E, f, Q, sigma, &pl);
      HS_REQUIRE(known(pst));
      if (pst == HS_OK) HS_REQUIRE(same_scene(s, pl, 1e-12L));
      const int fst = hs_scene_from_flat_rounded_loads(P, R, 0, E, f, Q, sigma, &fr, &flat);
      HS_REQUIRE(known(fst));
      if (std::getenv("HS_FUZZ_DEBUG"))
        std::fprintf(stderr, "P %.17g R %.17g E %.17g f %.17g Q %.17g sigma %.17g\n hertz a %.17g p0 %.17g q %.17g s %.17g\n flat(%d) a %.17g p0 %.17g q %.17g s %.17g b_f/a %g\n power(%d) a %.17g\n",
                     P, R, E, f, Q, sigma, s.a, s.p0, s.Q_over_fP, s.sigma_over_fp0, fst, fr.a, fr.p0, fr.Q_over_fP,
                     fr.sigma_over_fp0, flat, pst, pl.a);
      if (fst == HS_OK) HS_REQUIRE(same_scene(s, fr, 1e-12L) && flat == 0);
      // the scene solves (closed forms: cheap for any load)
      hs_solution *sol = nullptr;
      const int ss = hs_solve(&s, nullptr, &sol);
      HS_REQUIRE(known(ss) && (ss == HS_OK) == (sol != nullptr));
      // the energies are those of the dimensionless scene times f^2 p0^2 a^2 / E*
      // (issue 13: p0^2 overflowed in an intermediate for p0 ~ 1e200, E* ~ 1e200)
      if (ss == HS_OK) {
        hs_scene u = s;
        u.a = u.p0 = u.f = u.E_star = 1;
        hs_solution *us = nullptr;
        double eu[2], e[2] = {-1, -1};
        if (hs_solve(&u, nullptr, &us) == HS_OK && hs_solution_energy(us, eu) == HS_OK) {
          const int es = hs_solution_energy(sol, e);
          HS_REQUIRE(known(es));
          // one status for both zones: both are given, or neither (OVERFLOW where one is not
          // representable: found by the fresh-clone reliability run, energy 2 at 1e308 and beyond
          // while energy 1 was 3e307)
          long double want[2];
          bool fits[2];
          for (int i = 0; i < 2; ++i) {
            want[i] = eu[i] * ((long double)s.f * s.f * s.p0 * s.p0 * s.a * s.a / s.E_star);
            fits[i] = want[i] < 0.999L * DBL_MAX && (want[i] == 0 || want[i] > 1e3L * DBL_MIN);
            if (std::getenv("HS_FUZZ_DEBUG"))
              std::fprintf(stderr, "energy %d: status %d %.17g want %.17Lg\n", i, es, e[i], want[i]);
          }
          for (int i = 0; i < 2; ++i) {
            // representable with room for the rounding: must be given, to 1e-13
            if (fits[i] && es == HS_OK) HS_REQUIRE(std::fabs(e[i] - want[i]) <= 1e-13L * want[i]);
            if (want[i] > 1.001L * DBL_MAX) HS_REQUIRE(es == HS_ERR_OVERFLOW);
          }
          if (fits[0] && fits[1]) HS_REQUIRE(es == HS_OK);
        }
        hs_solution_free(us);
      }
      hs_solution_free(sol);
      break;
    }
    case 1: {
      const double A = R;
      st = hs_scene_from_power_law_loads(P, A, n, E, f, Q, sigma, &s);
      HS_REQUIRE(known(st));
      if (st != HS_OK) {
        HS_REQUIRE(std::memcmp(&s, &sentinel, sizeof s) == 0);
        return 0;
      }
      check_scene(s, P, E, f, Q, sigma);
      // log P = log(E*/2 n A) + n log a + log(sqrt(pi) Gamma((n+1)/2) / Gamma(n/2 + 1))
      const long double lhs = std::log((long double)P);
      const long double rhs = std::log((long double)E / 2 * n * A) + n * std::log((long double)s.a) +
                              0.5L * std::log(pi) + std::lgamma((n + 1) / 2.0L) - std::lgamma(n / 2.0L + 1);
      if (std::getenv("HS_FUZZ_DEBUG"))
        std::fprintf(stderr, "P %.17g A %.17g n %.17g E %.17g: a %.17g log P %.17Lg rhs %.17Lg\n", P, A, n, E, s.a, lhs, rhs);
      HS_REQUIRE(std::fabs(lhs - rhs) <= 1e-12L * (std::fabs(n * std::log((long double)s.a)) + std::fabs(lhs) + 1));
      break;
    }
    default: {
      st = hs_scene_from_flat_rounded_loads(P, R, bf, E, f, Q, sigma, &s, &flat);
      HS_REQUIRE(known(st));
      if (st != HS_OK) {
        HS_REQUIRE(std::memcmp(&s, &sentinel, sizeof s) == 0 && flat == 12345);
        return 0;
      }
      if (std::getenv("HS_FUZZ_DEBUG"))
        std::fprintf(stderr, "P %.17g R %.17g bf %.17g E %.17g: a %.17g b_f/a %.17g (b_f/a) a %.17g\n", P, R, bf, E, s.a,
                     flat, flat * s.a);
      check_scene(s, P, E, f, Q, sigma);
      HS_REQUIRE(flat >= 0 && flat < 1);
      // b_f/a as given (a quotient below the normal range keeps only absolute accuracy)
      HS_REQUIRE(std::fabs((long double)flat - (long double)bf / s.a) <= 1e-12L * flat + 1e-300L);
      // a^2 (pi - 2 phi0 - sin 2 phi0) = 4 R P / E*, where the left side is well conditioned
      if (flat < 0.9) {
        const long double phi = std::asin((long double)flat);
        HS_REQUIRE(close((long double)s.a * s.a * (pi - 2 * phi - std::sin(2 * phi)), 4.0L * R * P / E, 1e-10L));
      }
      break;
    }
  }
  return 0;
}
