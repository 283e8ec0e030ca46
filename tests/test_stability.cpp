// Issue 13, stability round two: scenes the landed code could not answer.
// Each case failed on the code before issue 13 (OVERFLOW, NO_CONVERGENCE or an
// estimate of 1e-3 for a result good to 1e-15) and is judged against a check
// that shares no code path with the solver under test: the MPFR reference
// (Hertz) or the sliding-stick-point balance (general pressures).
#include <doctest/doctest.h>
#include "testing.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/pressure.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/halfslip.h"

namespace core = hs::core;

namespace {

struct ref_values {
  double d1, d2, e1, e2;
};

// reference values of a scene (Hertz, or another geometry with its parameter as text)
// The reference solution of a scene, the doubles given as their exact decimals (the caller frees it).
hs_ref_solution *reference_solution(double q, double s, int geometry, const char *flat, int digits) {
  hs_ref_scene r;
  hs_ref_scene_default(&r);
  char qs[64], ss[64];
  std::snprintf(qs, 64, "%.45e", q);
  std::snprintf(ss, 64, "%.45e", s);
  r.Q_over_fP = qs;
  r.sigma_over_fp0 = ss;
  r.geometry = geometry;
  if (flat) r.flat_over_a = flat;
  hs_ref_solution *sol = nullptr;
  REQUIRE(hs_ref_solve(&r, digits, &sol) == HS_OK);
  return sol;
}
double reference_value(const hs_ref_solution *sol, int what) {
  char buf[128];
  REQUIRE(hs_ref_value(sol, what, buf, sizeof buf, nullptr, nullptr) == HS_OK);
  return std::strtod(buf, nullptr);
}

ref_values reference_values(double q, double s, int geometry = HS_GEOMETRY_HERTZ, const char *flat = nullptr,
                            int digits = 30) {
  hs_ref_solution *sol = reference_solution(q, s, geometry, flat, digits);
  ref_values v{reference_value(sol, HS_REF_D1), reference_value(sol, HS_REF_D2), reference_value(sol, HS_REF_ENERGY1),
               reference_value(sol, HS_REF_ENERGY2)};
  hs_ref_solution_free(sol);
  return v;
}
ref_values hertz_reference(double q, double s) { return reference_values(q, s); }

int solve_geometry(int kind, double par, double q, double s, int model, hs_solution **out) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = kind;
  g.flat_over_a = par;
  g.exponent = par;
  return hs_solve_geometry(&sc, &g, &o, out);
}

hs_summary summary(const hs_solution *sol) {
  hs_summary s;
  s.struct_size = sizeof s;
  REQUIRE(hs_solution_summary(sol, &s) == HS_OK);
  return s;
}

double rel(double v, double t) { return std::abs(v - t) / std::abs(t); }

// d_inf = 1 - x0 of the sliding stick point of a pressure (a = 1):
// int_{x0}^{1} p_hat = pi (1 - q)/4, by bisection on tanh-sinh quadrature of
// p_hat itself in long double (independent of the solver's zone integrals).
double sliding_d(const core::pressure_model<long double> &pm, long double q) {
  boost::math::quadrature::tanh_sinh<long double> ts;
  const long double pi = boost::math::constants::pi<long double>();
  // split at the pressure's kinks (the flat punch's log-singular p' at the
  // flat's ends): tanh-sinh across one is good to ~1e-11 only
  auto tail = [&](long double d) {
    std::vector<long double> cuts{1 - d};
    for (const auto &bp : pm.breakpoints())
      if (bp.x > 1 - d && bp.x < 1) cuts.push_back(bp.x);
    cuts.push_back(1);
    long double sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
      sum += ts.integrate([&](long double x) { return pm.p(x); }, cuts[i], cuts[i + 1]);
    return sum;
  };
  long double lo = 0, hi = 2;
  for (int i = 0; i < 70; ++i) {
    const long double m = (lo + hi) / 2;
    (tail(m) < pi * (1 - q) / 4 ? lo : hi) = m;
  }
  return double((lo + hi) / 2);
}

}  // namespace

TEST_CASE("issue 13: Hertz scenes whose stick zone is below the double range are answered, within the estimate") {
  // the scenes and reference values (d1/a), then the reference itself
  struct given {
    double q, s, d1;
  };
  for (const given g : {given{0.99999, 100, 4.109559542135504e-4}, given{0.5, 3000, 0.596027246700483},
                        given{0.5, 10000, 0.596027246700483}}) {
    CAPTURE(g.q);
    CAPTURE(g.s);
    hs_solution *sol = nullptr;
    REQUIRE(solve_geometry(HS_GEOMETRY_HERTZ, 0, g.q, g.s, HS_MODEL_DEFAULT, &sol) == HS_OK);  // was HS_ERR_OVERFLOW
    const auto s = summary(sol);
    CHECK(s.model == HS_MODEL_CLOSED_FORM);
    CHECK(s.regime == HS_REGIME_OPPOSITE_SIGN);
    // the given values have 16 digits: their own rounding is 5e-16 relative
    CHECK(rel(s.d1, g.d1) <= s.error_estimate + 5e-16);
    hs_solution_free(sol);
  }
}

TEST_CASE("issue 13: Hertz either side of where the stick zone leaves the double range, against the reference") {
  // For each q, the largest sigma of a geometric grid whose stick zone is
  // still representable and the next one (width 0, carried as its log): d1,
  // d2 and the zone energies (through the log-width slip) against MPFR.
  int checked = 0;
  for (double q : {0.3, 0.9, 0.999, 0.99999}) {
    double prev = 0;
    for (double s = 10; s < 1e5; s *= 1.1) {
      core::hertz_scene<double> sc;
      sc.q = q;
      sc.s = s;
      const auto h = core::solve_hertz(sc);
      if (h.width > 0) {
        prev = s;
        continue;
      }
      REQUIRE(prev > 0);
      for (double sv : {prev, s}) {
        CAPTURE(q);
        CAPTURE(sv);
        hs_solution *sol = nullptr;
        REQUIRE(solve_geometry(HS_GEOMETRY_HERTZ, 0, q, sv, HS_MODEL_DEFAULT, &sol) == HS_OK);
        const auto sm = summary(sol);
        double E[2];
        REQUIRE(hs_solution_energy(sol, E) == HS_OK);
        const ref_values t = hertz_reference(q, sv);
        const double err = std::max({rel(sm.d1, t.d1), rel(sm.d2, t.d2), rel(E[0], t.e1), rel(E[1], t.e2)});
        CAPTURE(err);
        CAPTURE(sm.error_estimate);
        CHECK(err <= sm.error_estimate);
        ++checked;
        hs_solution_free(sol);
      }
      break;
    }
  }
  CHECK(checked == 8);
}

TEST_CASE("issue 13: flat punch at large bulk tension follows the sliding stick point") {
  // As sigma grows the stick zone shrinks onto x0 with q pi/2 = int_{-1}^{x0} p -
  // int_{x0}^{1} p; then b1 = x0 + w/2, so |d1 - (1 - x0)| <= w/2 + the
  // balance's own error (bisection and tanh-sinh in long double, < 1e-17).
  // (b_f/a = 0.999 failed from sigma/fp0 = 100 until its pressure was evaluated
  // without the bracket's cancellation of ~4/g digits, 3.5e4 eps there)
  for (double bf : {0.01, 0.5, 0.99, 0.999}) {
    const core::flat_rounded_pressure<long double> pm(bf);
    const double q = 0.3;
    const double dinf = sliding_d(pm, q);
    for (double s : {50.0, 100.0, 200.0, 1000.0}) {
      if (bf >= 0.99 && s == 1000.0) continue;  // width below the double range: OVERFLOW (tested below)
      CAPTURE(bf);
      CAPTURE(s);
      hs_solution *sol = nullptr;
      REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, q, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
      const auto sm = summary(sol);
      CHECK(sm.regime == HS_REGIME_OPPOSITE_SIGN);
      const double w = sm.b1 + sm.b2;
      CAPTURE(w);
      CAPTURE(sm.error_estimate);
      // the landed code estimated 1.4e-3 at sigma = 50 (1/width conditioning)
      CHECK(sm.error_estimate < 1e-13);
      CHECK(std::abs(sm.d1 - dinf) <= sm.error_estimate * sm.d1 + w / 2 + 1e-17);
      CHECK(std::abs(sm.d2 - (2 - dinf)) <= sm.error_estimate * sm.d2 + w / 2 + 1e-17);
      hs_solution_free(sol);
    }
  }
}

TEST_CASE("issue 13: power law at large exponents and large sigma follows the sliding stick point, in bounded time") {
  // n = 999 at sigma/fp0 = 100 ran 18 s and failed (the landed code: NO_CONVERGENCE; the
  // edge layer of width ~1/n had no panel of its own, and the quadrature at orders 32
  // and 64 differed by 3e-4 in F2). Now plain splits at 2^k/n from each edge.
  for (double n : {50.0, 200.0, 999.0}) {
    const core::power_law_pressure<long double> pm(n);
    const double q = 0.3;
    const double dinf = sliding_d(pm, q);
    for (double s : {100.0, 200.0}) {
      CAPTURE(n);
      CAPTURE(s);
      const auto t0 = std::chrono::steady_clock::now();
      hs_solution *sol = nullptr;
      REQUIRE(solve_geometry(HS_GEOMETRY_POWER_LAW, n, q, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
      double E[2];
      REQUIRE(hs_solution_energy(sol, E) == HS_OK);
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      CAPTURE(secs);
      // a hang guard, not a speed test (bench/ measures speed): measured <= 1.4 s alone,
      // 12.8 s while the suite and two builds shared the 2 cores
      CHECK(secs < 120.0);
      const auto sm = summary(sol);
      CHECK(sm.regime == HS_REGIME_OPPOSITE_SIGN);
      const double w = sm.b1 + sm.b2;
      CAPTURE(sm.error_estimate);
      CHECK(std::abs(sm.d1 - dinf) <= sm.error_estimate * sm.d1 + w / 2 + 1e-17);
      CHECK(std::abs(sm.d2 - (2 - dinf)) <= sm.error_estimate * sm.d2 + w / 2 + 1e-17);
      CHECK(E[0] > 0);
      CHECK(E[1] > E[0]);
      hs_solution_free(sol);
    }
  }
}

namespace {
// double against long double (the core solver, the same pressure model in
// both: the pressures are checked against 50 digits in test_switches.cpp)
template <class PM> void check_against_long_double(const PM &pd, const core::pressure_model<long double> &pl,
                                                   double q, double s, bool energies = true) {
  CAPTURE(q);
  CAPTURE(s);
  core::general_scene<double> sd;
  sd.q = q;
  sd.s = s;
  core::general_scene<long double> sl;
  sl.q = q;
  sl.s = s;
  const auto a = core::solve_general(pd, sd);
  const auto b = core::solve_general(pl, sl);
  const auto est = core::quadrature_estimate(0.0, a.d1(), a.d2(), a.width, q, pd.accuracy_eps());
  auto r = [](double x, long double y) { return double(std::abs((x - y) / y)); };
  const double ed = std::max(r(a.d1(), b.d1()), r(a.d2(), b.d2()));
  CAPTURE(ed);
  CAPTURE(est.slip_zone);
  CHECK(ed <= est.slip_zone);
  if (energies) {
    const double ee = std::max(r(a.energy(1), b.energy(1)), r(a.energy(2), b.energy(2)));
    CAPTURE(ee);
    CAPTURE(est.energy);
    CHECK(ee <= est.energy);
  }
}
}  // namespace

TEST_CASE("issue 13: flat punch b_f/a = 0.999 with slip zones inside the rounded corner") {
  // At Q/fP = 0.3 and small sigma both zones (~2e-4 a) lie in the corner (1e-3 a wide),
  // where |J| ~ 2e3: no representable state had |F1| + |F2| below the fixed noise
  // floor 64 eps pi, and Newton reported NO_CONVERGENCE. The floor now includes the
  // residual's grain in the state (general_residual.hpp).
  const core::flat_rounded_pressure<double> pd(0.999);
  const core::flat_rounded_pressure<long double> pl(0.999L);
  for (double s : {0.0, 0.5, 1.0, -0.3}) check_against_long_double(pd, pl, 0.3, s);
  check_against_long_double(pd, pl, 0.01, 0.0);
  check_against_long_double(pd, pl, 0.9, 0.0);
}

TEST_CASE("issue 13: the quadrature estimate follows the pressure's accuracy (power law, n = 999)") {
  // F is good to ~n eps (docs/models.md); the estimate assumed a few eps and the solve at
  // Q/fP = 0.3, sigma/fp0 = -3 erred by 4.2e-13 in d2 against an estimate of 6.6e-14
  const core::power_law_pressure<double> pd(999);
  const core::power_law_pressure<long double> pl(999);
  check_against_long_double(pd, pl, 0.3, -3.0, false);
  check_against_long_double(pd, pl, 0.3, 0.0, false);
  check_against_long_double(pd, pl, 0.9, 1.0, false);
}

TEST_CASE("issue 13: zone energies at sigma/fp0 = 1000 (stick width 1e-291 a) in bounded time") {
  // The outer rule of the energies spanned all ~480 panels graded towards the
  // stick edge (down to theta ~ 1e-145): 4.3 s for the two energies. The panels
  // below theta = eps pi/2 carry ~eps^2 of the integral and are dropped from the
  // outer rule (general_panels.hpp): the energies are unchanged to the last bit
  // on this scene, 9x faster.
  const core::flat_rounded_pressure<double> pd(0.9);
  core::general_scene<double> sc;
  sc.q = 0.3;
  sc.s = 1000;
  const auto t0 = std::chrono::steady_clock::now();
  const auto a = core::solve_general(pd, sc);
  const double E1 = a.energy(1), E2 = a.energy(2);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CAPTURE(secs);
  CHECK(secs < 120.0);  // a hang guard (bench/ measures speed): measured 0.9 s (loaded machine)
  CHECK(a.width < 1e-290);
  // against long double (1.8 s), within the estimate (measured 4.4e-14 and 5.2e-14 against 8.1e-14)
  const core::flat_rounded_pressure<long double> pl(0.9L);
  core::general_scene<long double> sl;
  sl.q = 0.3L;
  sl.s = 1000;
  const auto b = core::solve_general(pl, sl);
  const auto est = core::quadrature_estimate(0.0, a.d1(), a.d2(), a.width, 0.3);
  CHECK(std::abs(E1 - b.energy(1)) <= est.energy * b.energy(1));
  CHECK(std::abs(E2 - b.energy(2)) <= est.energy * b.energy(2));
}

TEST_CASE("issue 13: a stick zone below the double range on the quadrature path: the point-stick continuation") {
  // The landed code returned HS_ERR_OVERFLOW once the width fell below ~1e-292 a (sigma/fp0
  // ~ 800-1600 at Q/fP = 0.3). Widths below eps^3 a are now the point-stick limit: every
  // zone integral is A + B ln(width), evaluated at two widths and continued in ln(width).
  // Checks that share nothing with it: the sliding stick point (d1, d2), and for the Hertz
  // pressure the closed forms, which carry ln(width) analytically (d and the energies).
  for (double bf : {0.5, 0.999}) {
    const core::flat_rounded_pressure<long double> pm(bf);
    const double dinf = sliding_d(pm, 0.3);
    for (double s : {2000.0, 1e4, 1e6}) {
      CAPTURE(bf);
      CAPTURE(s);
      const auto t0 = std::chrono::steady_clock::now();
      hs_solution *sol = nullptr;
      REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, 0.3, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
      double E[2];
      REQUIRE(hs_solution_energy(sol, E) == HS_OK);
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      CHECK(secs < 120.0);  // a hang guard (bench/ measures speed): measured <= 0.2 s
      const auto sm = summary(sol);
      CHECK(sm.regime == HS_REGIME_OPPOSITE_SIGN);
      CHECK(std::abs(sm.b1 + sm.b2) <= 4e-16);  // the width is below the range: b1 = -b2 = x0 in double
      CHECK(std::abs(sm.d1 - dinf) <= sm.error_estimate * sm.d1 + 1e-17);
      CHECK(std::abs(sm.d2 - (2 - dinf)) <= sm.error_estimate * sm.d2 + 1e-17);
      CHECK(E[1] > E[0]);
      CHECK(E[0] > s / 20);  // the energies grow like sigma (ln(1/width) ~ sigma)
      hs_solution_free(sol);
    }
  }
  for (double q : {0.3, 0.9}) {
    for (double s : {3000.0, 1e4}) {
      CAPTURE(q);
      CAPTURE(s);
      hs_solution *cf = nullptr, *qd = nullptr;
      REQUIRE(solve_geometry(HS_GEOMETRY_HERTZ, 0, q, s, HS_MODEL_CLOSED_FORM, &cf) == HS_OK);
      REQUIRE(solve_geometry(HS_GEOMETRY_HERTZ, 0, q, s, HS_MODEL_QUADRATURE, &qd) == HS_OK);
      const auto a = summary(cf), b = summary(qd);
      double Ea[2], Eb[2];
      REQUIRE(hs_solution_energy(cf, Ea) == HS_OK);
      REQUIRE(hs_solution_energy(qd, Eb) == HS_OK);
      const double tol = a.error_estimate + b.error_estimate;
      CAPTURE(b.error_estimate);
      CHECK(rel(b.d1, a.d1) <= tol);
      CHECK(rel(b.d2, a.d2) <= tol);
      CHECK(rel(Eb[0], Ea[0]) <= tol);
      CHECK(rel(Eb[1], Ea[1]) <= tol);
      hs_solution_free(cf);
      hs_solution_free(qd);
    }
  }
}

TEST_CASE("issue 13: the point-stick continuation is continuous at the switch width eps^3") {
  // sigma either side of where the width crosses eps^3 a = 1.1e-47 a (flat punch b_f/a = 0.5,
  // Q/fP = 0.3: sigma/fp0 ~ 201.8): d1 and the energies are smooth across it (the energies grow
  // linearly in sigma there: second differences at the rounding level)
  const core::flat_rounded_pressure<double> pd(0.5);
  auto at = [&](double s, double &d1, double &E1, double &w) {
    core::general_scene<double> sc;
    sc.q = 0.3;
    sc.s = s;
    const auto g = core::solve_general(pd, sc);
    d1 = g.d1();
    E1 = g.energy(1);
    w = g.width;
  };
  double prev_w = 1, d[5], E[5];
  bool crossed = false;
  for (int i = 0; i < 5; ++i) {
    double w;
    at(200.0 + i, d[i], E[i], w);
    if (i > 0 && (w < core::tiny_width<double>()) != (prev_w < core::tiny_width<double>())) crossed = true;
    prev_w = w;
  }
  CHECK(crossed);
  for (int i = 1; i < 5; ++i) CHECK(std::abs(d[i] - d[0]) <= 1e-15);
  for (int i = 1; i + 1 < 5; ++i) {
    CAPTURE(i);
    CHECK(std::abs(E[i + 1] - 2 * E[i] + E[i - 1]) <= 1e-12 * E[i]);
  }
}

TEST_CASE("issue 13: cel_log continues cel below the switch") {
  // where both are defined, the small-modulus form equals cel to rounding
  for (double p : {1e-6, 0.01, 1.0, 2.0, 50.0})
    for (double kc : {1e-10, 1e-14, 1e-30, 1e-150}) {
      CAPTURE(p);
      CAPTURE(kc);
      const double a = core::cel(kc, p, 0.0, 1.0), b = core::cel_log(kc, std::log(kc), p, 0.0, 1.0);
      CHECK(std::abs(a - b) <= 16 * 2.2e-16 * std::abs(a));
      const double c = core::cel(kc, p, 1.0, 1.0), d = core::cel_log(kc, std::log(kc), p, 1.0, 1.0);
      CHECK(std::abs(c - d) <= 16 * 2.2e-16 * std::abs(c));
    }
}

// The near-sliding sweep quoted in docs/models.md and the README (issue 13, "Near
// sliding"; skipped in ctest; run: build/tests/test_stability -tc="*near-sliding sweep*"
// --no-skip -s). DEFAULT (rtol 0) through the C ABI on 8 geometries x 7 distances from
// sliding x both signs of Q x 13 sigma; on a subset (1 - Q/fP = 1e-10 and 1e-13, sigma/fp0 =
// -3, 0.018, 1, 20) d1, d2 against the long double solver, whose own bound (the quadrature
// form at long double's epsilon) is added to the double estimate.
TEST_CASE("issue 13: near-sliding sweep of the general double solver" * doctest::skip()) {
  const std::vector<std::pair<int, double>> geos = {
      {HS_GEOMETRY_FLAT_ROUNDED, 0.1}, {HS_GEOMETRY_FLAT_ROUNDED, 0.5}, {HS_GEOMETRY_FLAT_ROUNDED, 0.8},
      {HS_GEOMETRY_FLAT_ROUNDED, 0.95}, {HS_GEOMETRY_POWER_LAW, 1.5},    {HS_GEOMETRY_POWER_LAW, 3},
      {HS_GEOMETRY_POWER_LAW, 6.79},    {HS_GEOMETRY_POWER_LAW, 9.875}};
  const double oms[] = {1e-6, 1e-8, 1e-10, 4.5e-11, 1e-11, 1e-12, 1e-13};
  const double sigmas[] = {-3, -2.2, -1, -0.3, -0.018, 0, 0.018, 0.3, 1, 2.2, 5, 10, 20};
  int total = 0, failed_total = 0, checked = 0, over = 0, ld_failed = 0;
  double tmax = 0, worst = 0;
  for (const auto &g : geos) {
    int failed = 0;
    double gmax = 0;
    for (double om : oms)
      for (int sgn : {+1, -1})
        for (double s : sigmas) {
          const double q = sgn * (1 - om);
          hs_solution *sol = nullptr;
          const auto t0 = std::chrono::steady_clock::now();
          const int st = solve_geometry(g.first, g.second, q, s, HS_MODEL_DEFAULT, &sol);
          const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          gmax = std::max(gmax, dt);
          ++total;
          if (st != HS_OK) {
            ++failed;
            std::printf("  FAIL %s %g: 1 - |Q/fP| = %g, Q/fP %s 0, sigma/fp0 = %g: %s (%.2f s)\n",
                        g.first == HS_GEOMETRY_FLAT_ROUNDED ? "flat-rounded" : "power-law", g.second, om,
                        sgn > 0 ? ">" : "<", s, hs_strerror(st), dt);
            continue;
          }
          const hs_summary sm = summary(sol);
          const bool subset = sgn > 0 && (om == 1e-10 || om == 1e-13) && (s == -3 || s == 0.018 || s == 1 || s == 20);
          if (subset) {
            std::unique_ptr<core::pressure_model<long double>> pm;
            if (g.first == HS_GEOMETRY_FLAT_ROUNDED) pm.reset(new core::flat_rounded_pressure<long double>(g.second));
            else pm.reset(new core::power_law_pressure<long double>(g.second));
            core::general_scene<long double> w;
            w.a = w.p0 = w.f = w.Estar = 1;
            w.q = q;
            w.s = s;
            try {
              const auto ws = core::solve_general(*pm, w);
              const long double dm = std::min(ws.d1() > 0 ? ws.d1() : 2, ws.d2() > 0 ? ws.d2() : 2);
              const double bound =
                  double(64 * std::numeric_limits<long double>::epsilon() * (1 + 1 / dm + 1 / ws.width)) +
                  double(ws.conditioning / dm);
              const double D[2] = {sm.d1, sm.d2};
              const long double W[2] = {ws.d1(), ws.d2()};
              for (int z = 0; z < 2; ++z) {
                if (!(D[z] > sm.zone_resolution)) continue;
                const double err = double(std::abs(D[z] - W[z]) / W[z]);
                ++checked;
                worst = std::max(worst, err / (sm.error_estimate + bound));
                if (err > sm.error_estimate + bound) {
                  ++over;
                  std::printf("  OVER %g: 1 - |Q/fP| = %g, sigma/fp0 = %g, zone %d: error %.2e, estimate %.2e\n",
                              g.second, om, s, z + 1, err, sm.error_estimate);
                }
              }
            } catch (const core::error &) {
              ++ld_failed;
            }
          }
          hs_solution_free(sol);
        }
    std::printf("%s %g: %d of %d scenes fail; slowest %.2f s\n",
                g.first == HS_GEOMETRY_FLAT_ROUNDED ? "flat-rounded b_f/a =" : "power law n =", g.second, failed,
                int(std::size(oms) * 2 * std::size(sigmas)), gmax);
    failed_total += failed;
    tmax = std::max(tmax, gmax);
  }
  std::printf("total: %d of %d scenes fail; slowest %.2f s; against long double: %d zones, %d above estimate + "
              "long double's bound (worst ratio %.2f), %d long double solves failed\n",
              failed_total, total, tmax, checked, over, worst, ld_failed);
}

// ---- near sliding, round two (issue 13): the causes of the sweep's failures above ----
namespace {

std::unique_ptr<core::pressure_model<long double>> ld_pressure(int kind, double par) {
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) return std::make_unique<core::flat_rounded_pressure<long double>>(par);
  return std::make_unique<core::power_law_pressure<long double>>(par);
}

}  // namespace

TEST_CASE("issue 13: the power law's phi' next to its cusp at x = 0 (n = 1.5), double and long double") {
  // phi' enters only the Newton Jacobian. Near sliding the moment condition's row of the
  // Jacobian is ~1e-9 (J21) and ~3e-10 (J22); the central difference of phi with step
  // cbrt(eps)/2 ~ 3e-6 straddles the cusp of p ~ |x|^(n-1) at nodes closer to x = 0 than
  // that, and J21 came out as -1.7e-5 for about -3e-9 (n = 1.5, 1 - Q/fP = 1e-10,
  // sigma/fp0 = 1): Newton stalled at every order, and 39 of 91 scenes of the near-sliding
  // sweep failed for n = 1.5. Truth: a central difference in long double with a step
  // 1e-4 |x| (relative error ~1e-9 from the step, rounding ~1e-10 at x = 1e-9). Bound:
  // 1e-6 relative plus the closed form's rounding, 16 eps (n/2)/|x| absolute (its
  // numerator cancels to ~|x|^(n-1) near the cusp; n = 2.5 at x = 1e-9: 8e-3 relative of
  // a phi' of 5e-5; the central difference there was off by 98 %).
  for (double n : {1.5, 1.2, 2.5}) {
    const core::power_law_pressure<double> pd(n);
    const core::power_law_pressure<long double> pl(n);
    for (double x : {1e-9, -1e-7, 1e-6, -1e-5, 1e-4, 3e-3, 0.3, -0.7}) {
      CAPTURE(n);
      CAPTURE(x);
      double d = 0;
      pd.phi_dphi(x, 1 + x, 1 - x, d);
      const long double X = x, h = 1e-4L * std::abs(X);
      const long double t = (pl.phi(X + h, 1 + X + h, 1 - X - h) - pl.phi(X - h, 1 + X - h, 1 - X + h)) / (2 * h);
      CAPTURE(d);
      CAPTURE(double(t));
      CHECK(std::abs(d - t) <= 1e-6L * std::abs(t) + 16 * std::numeric_limits<double>::epsilon() * n / 2 / std::abs(x));
    }
  }
}

namespace {
// A near-sliding scene of the tests below: geometry, its parameter, 1 - |Q/fP| and sigma/fp0
struct near_case {
  int kind;
  double par, om, s;
};
// its summary from HS_MODEL_DEFAULT at Q/fP = q (which must answer)
hs_summary default_summary(const near_case &c, double q) {
  CAPTURE(c.kind);
  CAPTURE(c.par);
  CAPTURE(q);
  CAPTURE(c.s);
  hs_solution *sol = nullptr;
  REQUIRE(solve_geometry(c.kind, c.par, q, c.s, HS_MODEL_DEFAULT, &sol) == HS_OK);
  const hs_summary sm = summary(sol);
  hs_solution_free(sol);
  return sm;
}
}  // namespace

TEST_CASE("issue 13: near sliding, same sign: scenes of the sweep that failed, against long double" * HS_LONG) {
  // Before: HS_ERR_NO_CONVERGENCE from DEFAULT on each (near-sliding sweep above). Causes:
  //  - the power law n = 1.5: the Jacobian near the cusp (test above);
  //  - the flat punch: the near-sliding start made at order 16, where F2 (~1e-11 signal) is
  //    not resolved: its ln e was off by 1.2 (b_f/a = 0.5, 1 - Q/fP = 1e-11, sigma/fp0 = -3),
  //    and Newton left for ln e ~ -17.6 at every order up to 128; now the start is made at
  //    the order where two successive orders agree.
  // Truth: the long double solver, with its own bound as in the sweep.
  const near_case cases[] = {
      {HS_GEOMETRY_POWER_LAW, 1.5, 1e-10, 1},        {HS_GEOMETRY_POWER_LAW, 1.5, 4.5e-11, -0.3},
      {HS_GEOMETRY_POWER_LAW, 1.5, 1e-13, 2.2},      {HS_GEOMETRY_FLAT_ROUNDED, 0.5, 1e-11, -3},
      {HS_GEOMETRY_FLAT_ROUNDED, 0.95, 4.5e-11, 10}, {HS_GEOMETRY_FLAT_ROUNDED, 0.8, 1e-11, 2.2},
  };
  for (const near_case &c : cases) {
    for (int sgn : {+1, -1}) {
      const double q = sgn * (1 - c.om);
      CAPTURE(c.kind);
      CAPTURE(c.par);
      CAPTURE(q);
      CAPTURE(c.s);
      const hs_summary sm = default_summary(c, q);
      CHECK(sm.model == HS_MODEL_QUADRATURE);
      CHECK(sm.regime == HS_REGIME_SAME_SIGN);
      CHECK(sm.error_estimate < 1e-6);
      const auto pm = ld_pressure(c.kind, c.par);
      core::general_scene<long double> w;
      w.a = w.p0 = w.f = w.Estar = 1;
      w.q = q;
      w.s = c.s;
      const auto ws = core::solve_general(*pm, w);
      const long double dm = std::min(ws.d1(), ws.d2());
      const double bound = double(64 * std::numeric_limits<long double>::epsilon() * (1 + 1 / dm + 1 / ws.width)) +
                           double(ws.conditioning / dm);
      const double D[2] = {sm.d1, sm.d2};
      const long double W[2] = {ws.d1(), ws.d2()};
      for (int z = 0; z < 2; ++z) {
        CAPTURE(z);
        CAPTURE(sm.error_estimate);
        CAPTURE(bound);
        CHECK(double(std::abs(D[z] - W[z]) / W[z]) <= sm.error_estimate + bound);
      }
    }
  }
}

TEST_CASE("issue 13: near sliding, opposite sign at larger sigma: follows the sliding stick point") {
  // Before: HS_ERR_NO_CONVERGENCE from DEFAULT (near-sliding sweep above). There the
  // stick zone sits at the sliding stick point next to the edge (d1 ~ 1e-5 .. 1e-8 a) and
  // is narrower than 1e-16 a; the large-sigma start was tried at order 16 only, which does
  // not resolve F1 there (power law n = 9.875, 1 - Q/fP = 1e-10, sigma/fp0 = 10: F1 at
  // orders 16 and 32 differs by 1.2e-7 at the start), and the near-sliding start follows
  // same-sign zones only. Now Newton from the large-sigma start at a raised order.
  // Check independent of the solver: the sliding stick point's balance (sliding_d), with
  // |d1 - (1 - x0)| <= w/2 + the estimate (as in "flat punch at large bulk tension").
  const near_case cases[] = {
      {HS_GEOMETRY_FLAT_ROUNDED, 0.8, 1e-6, 10}, {HS_GEOMETRY_FLAT_ROUNDED, 0.95, 1e-6, -20},
      {HS_GEOMETRY_POWER_LAW, 6.79, 1e-8, 20},   {HS_GEOMETRY_POWER_LAW, 9.875, 1e-10, 10},
      {HS_GEOMETRY_POWER_LAW, 9.875, 1e-11, 10},
  };
  for (const near_case &c : cases) {
    const double q = 1 - c.om;
    const auto pm = ld_pressure(c.kind, c.par);
    const double dinf = sliding_d(*pm, q);
    CAPTURE(c.kind);
    CAPTURE(c.par);
    CAPTURE(q);
    CAPTURE(c.s);
    CAPTURE(dinf);
    const hs_summary sm = default_summary(c, q);
    CHECK(sm.model == HS_MODEL_QUADRATURE);
    CHECK(sm.regime == HS_REGIME_OPPOSITE_SIGN);
    const double w = sm.b1 + sm.b2;
    const double dn = c.s > 0 ? sm.d1 : sm.d2, df = c.s > 0 ? sm.d2 : sm.d1;  // near and far zone
    CAPTURE(w);
    CAPTURE(dn);
    CAPTURE(sm.error_estimate);
    // the estimate is large here (the moment condition's O(1) terms cancel to pi (1 - q)/2
    // ~ 1.6e-11 and fix d1 ~ 1e-8 a through the tail ~ d1^(3/2)): 8.8e-4 at n = 9.875,
    // 1 - Q/fP = 1e-11 (error 3.5e-5); bounded here so that a growth is seen
    CHECK(sm.error_estimate < 2e-3);
    CHECK(std::abs(dn - dinf) <= sm.error_estimate * dn + w / 2 + 1e-17);
    CHECK(std::abs(df - (2 - dinf)) <= sm.error_estimate * df + w / 2 + 1e-15);
  }
}

// The domain sweep quoted in docs/models.md and the README (skipped in ctest;
// run: build/tests/test_stability -tc="*domain sweep*" --no-skip -s).
TEST_CASE("issue 13: domain sweep of the double paths" * doctest::skip()) {
  std::printf("Hertz closed forms, sigma/fp0 = 10^(-3 .. 9) in steps of 10^0.05:\n");
  for (double om : {0.7, 0.1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10, 1e-12, 1e-15}) {
    int n = 0, failed = 0;
    double first_fail = 0;
    for (double ls = -3; ls <= 9.001; ls += 0.05) {
      core::hertz_scene<double> sc;
      sc.q = 1 - om;
      sc.s = std::pow(10.0, ls);
      ++n;
      try {
        const auto h = core::solve_hertz(sc);
        if (!(std::isfinite(h.d1()) && h.d2() > 0)) throw core::error(core::status::internal, "bad");
      } catch (const core::error &) {
        if (!failed++) first_fail = sc.s;
      }
    }
    std::printf("  1 - Q/fP = %-8g: %3d of %d fail, the first at sigma/fp0 = %g\n", om, failed, n, first_fail);
  }
  std::printf("flat punch (quadrature), Q/fP = 0.3, sigma/fp0 = 1 .. 1e4 (x 1.25):\n");
  for (double bf : {0.01, 0.5, 0.99, 0.999}) {
    int ok = 0, overflow = 0, other = 0;
    double last_ok = 0, tmax = 0;
    for (double s = 1; s <= 1e4; s *= 1.25) {
      hs_solution *sol = nullptr;
      const auto t0 = std::chrono::steady_clock::now();
      const int st = solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, 0.3, s, HS_MODEL_DEFAULT, &sol);
      tmax = std::max(tmax, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (st == HS_OK) {
        ++ok;
        last_ok = s;
        hs_solution_free(sol);
      } else if (st == HS_ERR_OVERFLOW) ++overflow;
      else ++other;
    }
    std::printf("  b_f/a = %-5g: %d solved (up to sigma/fp0 = %.4g), %d OVERFLOW, %d other; slowest %.2f s\n", bf, ok,
                last_ok, overflow, other, tmax);
  }
}

// ---- small loads: slip zones below the resolution of the quadrature path --------------
namespace {

ref_values flat_reference(double bf, double q, double s) {
  char bs[64];
  std::snprintf(bs, 64, "%.45e", bf);
  return reference_values(q, s, HS_GEOMETRY_FLAT_ROUNDED, bs, 20);
}

}  // namespace

TEST_CASE("issue 13: small loads on the general path are answered within the estimate, never a spurious root") {
  // Before: flat punch b_f/a = 0.5, Q = 0, sigma/fp0 = 1e-30 returned d2/a = 1.38 (a stick zone
  // (0.38 a, a)) with status OK from the default model and AUTO; Q/fP = 1e-20 returned d1 = q/2 (the
  // Hertz start, 70 % off) and d2 = 0. The zones are narrower than the (x1, ln e) state resolves.
  struct scene {
    double q, s;
  };
  for (const scene &c : {scene{0, 1e-30}, scene{1e-20, 0}, scene{1e-25, 3e-25}, scene{0, -1e-12}}) {
    const ref_values r = flat_reference(0.5, c.q, c.s);
    for (int model : {HS_MODEL_DEFAULT, HS_MODEL_AUTO}) {
      hs_solution *sol = nullptr;
      REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, 0.5, c.q, c.s, model, &sol) == HS_OK);
      const hs_summary S = summary(sol);
      double E[2];
      REQUIRE(hs_solution_energy(sol, E) == HS_OK);
      CAPTURE(c.q);
      CAPTURE(c.s);
      CAPTURE(model);
      CHECK(S.error_estimate <= 1e-6);  // the asymptotic model is accurate here
      CHECK(rel(S.d1, r.d1) <= S.error_estimate);
      CHECK(rel(S.d2, r.d2) <= S.error_estimate);
      CHECK(rel(E[0], r.e1) <= S.error_estimate);
      CHECK(rel(E[1], r.e2) <= S.error_estimate);
      hs_solution_free(sol);
    }
    // the quadrature forced on such a scene: a clear status, not a spurious root
    if (c.s != -1e-12) {
      hs_solution *sol = nullptr;
      CHECK(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, 0.5, c.q, c.s, HS_MODEL_QUADRATURE, &sol) ==
            HS_ERR_NOT_APPLICABLE);
      hs_solution_free(sol);
    }
  }
  // beyond the reference's reach: Q = 0 is symmetric (d1 = d2 exactly) and the zones are linear in
  // sigma (d/sigma the same as at 1e-30 above), for the flat punch and the power law
  for (int kind : {HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW}) {
    const double par = kind == HS_GEOMETRY_FLAT_ROUNDED ? 0.5 : 3.0;
    hs_solution *s30 = nullptr, *s300 = nullptr;
    REQUIRE(solve_geometry(kind, par, 0, 1e-30, HS_MODEL_DEFAULT, &s30) == HS_OK);
    REQUIRE(solve_geometry(kind, par, 0, 1e-300, HS_MODEL_DEFAULT, &s300) == HS_OK);
    const hs_summary A = summary(s30), B = summary(s300);
    CAPTURE(kind);
    CHECK(B.regime == HS_REGIME_OPPOSITE_SIGN);
    CHECK(B.slip_dir1 == -1);
    CHECK(B.slip_dir2 == 1);
    CHECK(B.d1 == B.d2);
    CHECK(rel(B.d1 / 1e-300, A.d1 / 1e-30) <= 1e-12);
    hs_solution_free(s30);
    hs_solution_free(s300);
  }
}

TEST_CASE("issue 13: loads that underflow: empty zones have no direction, energies that underflow are not claimed") {
  // Before: Q = 0, sigma/fp0 = 5e-324 (s/4 underflows) reported same-sign with slip direction +1 for
  // the empty zone 2; at sigma/fp0 = 4e-320 the zone energies underflowed to 0 with an estimate of 2.5e-14.
  for (int kind : {HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED}) {
    hs_solution *sol = nullptr;
    REQUIRE(solve_geometry(kind, 0.5, 0, 5e-324, HS_MODEL_DEFAULT, &sol) == HS_OK);
    const hs_summary S = summary(sol);
    CAPTURE(kind);
    CHECK(S.d1 == 0);
    CHECK(S.d2 == 0);
    CHECK(S.slip_dir1 == 0);
    CHECK(S.slip_dir2 == 0);
    CHECK(S.regime == HS_REGIME_STUCK);
    hs_solution_free(sol);
  }
  hs_solution *sol = nullptr;
  REQUIRE(solve_geometry(HS_GEOMETRY_HERTZ, 0.5, 0, 4e-320, HS_MODEL_DEFAULT, &sol) == HS_OK);
  const hs_summary S = summary(sol);
  double E[2];
  REQUIRE(hs_solution_energy(sol, E) == HS_OK);
  CHECK(S.regime == HS_REGIME_OPPOSITE_SIGN);
  CHECK(S.d1 > 0);
  // the exact energies are ~d^3 ~ 1e-960: in double they are 0, which the estimate must own
  CHECK(E[0] == 0);
  CHECK(S.error_estimate >= 1);
  // the zone length itself is a subnormal, good to its spacing (d = sigma/4 exactly for Hertz at Q = 0)
  const double d_exact = 0.25 * 4e-320;
  CHECK(rel(S.d1, d_exact) <= S.error_estimate);
  hs_solution_free(sol);
}

// ---- callback pressure negative in a narrow region -------------------------------------
namespace {
// Hertz minus a narrow dip: negative on |x - 0.3| < ~1.3e-3 a only (between the
// old check's 64 Chebyshev points, which are ~0.05 a apart there)
double dipped_pressure(double x, void *) {
  const double u = (x - 0.3) / 1e-3;
  return std::sqrt((1 - x) * (1 + x)) - 2 * std::exp(-u * u);
}
}  // namespace

TEST_CASE("issue 13: a callback pressure negative in a narrow region inside the contact is rejected") {
  CHECK(dipped_pressure(0.3, nullptr) < 0);
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = 0.3;
  sc.sigma_over_fp0 = 0.5;
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_CALLBACK;
  g.pressure = &dipped_pressure;
  for (int model : {HS_MODEL_DEFAULT, HS_MODEL_AUTO, HS_MODEL_QUADRATURE}) {
    hs_options o;
    hs_options_default(&o);
    o.model = model;
    hs_solution *sol = nullptr;
    CAPTURE(model);
    CHECK(hs_solve_geometry(&sc, &g, &o, &sol) == HS_ERR_BAD_GEOMETRY);
    CHECK(sol == nullptr);
    hs_solution_free(sol);
  }
}

TEST_CASE("issue 13: dimensional energies near 1e200 without an intermediate overflow") {
  // p0 = 1e200 Pa, E* = 1e200 Pa, a = 1 m: the energies are ~1e200 J/m, but the old scaling
  // f^2 p0^2 a^2 / E* overflowed in p0^2: hs_solution_energy said HS_ERR_OVERFLOW ("energy
  // not representable") for every geometry and model. Check: the solve is dimensionless, so
  // the energies are those of the unit scene (p0 = E* = 1) times p0^2/E* = 1e200 (in long
  // double, exact but for its rounding), slip and B_x those of the unit scene times
  // p0/E* = 1; the scalings round a few times (16 eps).
  const double big = 1e200;
  for (int kind : {HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW})
    for (int model : {HS_MODEL_DEFAULT, HS_MODEL_ASYMPTOTIC}) {
      CAPTURE(kind);
      CAPTURE(model);
      hs_scene unit;
      hs_scene_default(&unit);
      unit.a = 1;
      unit.p0 = 1;
      unit.E_star = 1;
      unit.f = 0.5;
      unit.Q_over_fP = model == HS_MODEL_ASYMPTOTIC ? 0.01 : 0.3;
      unit.sigma_over_fp0 = 0.1;
      hs_scene large = unit;
      large.p0 = big;
      large.E_star = big;
      hs_options o;
      hs_options_default(&o);
      o.model = model;
      hs_geometry g;
      hs_geometry_default(&g);
      g.kind = kind;
      g.exponent = 3;
      hs_solution *su = nullptr, *sl = nullptr;
      REQUIRE(hs_solve_geometry(&unit, &g, &o, &su) == HS_OK);
      REQUIRE(hs_solve_geometry(&large, &g, &o, &sl) == HS_OK);
      double eu[2], el[2];
      REQUIRE(hs_solution_energy(su, eu) == HS_OK);
      REQUIRE(hs_solution_energy(sl, el) == HS_OK);  // HS_ERR_OVERFLOW before
      const double e = std::numeric_limits<double>::epsilon();
      for (int i = 0; i < 2; ++i) {
        REQUIRE(eu[i] > 0);
        const long double want = (long double)eu[i] * big;
        CHECK(std::abs((el[i] - want) / want) <= 16 * e);
      }
      const double x[2] = {-0.995, 0.995};
      double hu[2], hl[2], bu[2], bl[2];
      REQUIRE(hs_eval_slip(su, 2, x, hu) == HS_OK);
      REQUIRE(hs_eval_slip(sl, 2, x, hl) == HS_OK);
      REQUIRE(hs_eval_Bx(su, 2, x, bu) == HS_OK);
      REQUIRE(hs_eval_Bx(sl, 2, x, bl) == HS_OK);
      for (int i = 0; i < 2; ++i) {
        CHECK(hu[i] != 0);
        CHECK(std::abs(hl[i] - hu[i]) <= 16 * e * std::abs(hu[i]));
        CHECK(std::abs(bl[i] - bu[i]) <= 16 * e * std::abs(bu[i]));
      }
      hs_solution_free(su);
      hs_solution_free(sl);
    }
  // an energy beyond the double range is still the status, naming no value it cannot hold
  hs_scene s;
  hs_scene_default(&s);
  s.p0 = 1e300;
  s.E_star = 1e-10;
  hs_solution *sol = nullptr;
  REQUIRE(hs_solve(&s, nullptr, &sol) == HS_OK);
  double E[2] = {-1, -1};
  CHECK(hs_solution_energy(sol, E) == HS_ERR_OVERFLOW);
  CHECK(E[0] == -1);
  hs_solution_free(sol);
}

TEST_CASE("issue 13: power law with 1 < n < 1.25 in bounded time (no quadrature per pressure value)") {
  // The pressure for m = (n-1)/2 < 1/8 was a tanh-sinh integral per value: n = 1.05 at
  // Q/fP = 0.9977, sigma/fp0 = 1.435 took 4.5-8.9 s; n = 1.2 at sigma/fp0 = 3 ran 3 s and
  // failed (NO_CONVERGENCE), n = 1.02 there 38 s before failing. Now the regrouped
  // connection formula (checked against 50 digits in test_switches.cpp). Each scene
  // below solves, within its estimate of the long double solve; the times are a hang
  // guard only (bench/ measures speed).
  struct sc_t {
    double n, q, s;
  };
  // (1.2, 0.9977, 3) is checked for its status only: the long double solver's continuation
  // in sigma fails there (the band of sigma where zone 1 closes and reopens, docs/models.md)
  // (1.001 and 1.01 at Q/fP = 0.9977, sigma/fp0 = 3 put the stick end next to the cusp: the
  // next test case)
  for (const sc_t &c : {sc_t{1.05, 0.9977, 1.435}, sc_t{1.2, 0.9977, 3}, sc_t{1.001, 0.5, 1},
                        sc_t{1.01, 0.3, 0}, sc_t{1.1, -0.6, 2}}) {
    CAPTURE(c.n);
    CAPTURE(c.q);
    CAPTURE(c.s);
    const auto t0 = std::chrono::steady_clock::now();
    hs_solution *sol = nullptr;
    REQUIRE(solve_geometry(HS_GEOMETRY_POWER_LAW, c.n, c.q, c.s, HS_MODEL_DEFAULT, &sol) == HS_OK);
    double E[2];
    REQUIRE(hs_solution_energy(sol, E) == HS_OK);
    hs_solution_free(sol);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CAPTURE(secs);
    CHECK(secs < 120.0);  // hang guard
    if (c.n == 1.2) continue;
    const core::power_law_pressure<double> pd(c.n);
    const core::power_law_pressure<long double> pl(c.n);
    check_against_long_double(pd, pl, c.q, c.s);
  }
  // Where the solver still fails for n -> 1 under large sigma (the stick zone crossing the
  // pressure's cusp at x = 0; docs/models.md), it says so promptly: a status, not a hang.
  hs_solution *sol = nullptr;
  const auto t0 = std::chrono::steady_clock::now();
  const int st = solve_geometry(HS_GEOMETRY_POWER_LAW, 1.02, 0.9977, 3, HS_MODEL_DEFAULT, &sol);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK((st == HS_OK || st == HS_ERR_NO_CONVERGENCE));
  if (st == HS_OK) hs_solution_free(sol);
  CHECK(secs < 120.0);  // hang guard (38 s before)
}

TEST_CASE("issue 13: power law n -> 1, stick end next to the pressure's cusp: panels graded to the cusp") {
  // n = 1.01 at Q/fP = 0.9977, sigma/fp0 = 3: the stick zone (-1.9e-5 a, 0.124 a) ends 1.9e-5 a
  // from the cusp |x|^0.01 of the pressure at x = 0. The panels of zone 2 were graded towards
  // its stick edge only down to the scale of the stick width, blind to the cusp just beyond
  // the edge: E1 was off by 5.4e-6 (double's expansion and adaptive paths; the fixed rules and
  // long double agreed with each other) against an estimate of 1.8e-13. Now they are graded
  // to the nearer of the two (gdetail::grading_scale). Check: the long double solve (its own
  // error ~2^-11 of double's). Tolerance: the zone ends are good to a few eps absolute and
  // the energies depend on the distance delta = 1.9e-5 from the cusp like eps/delta ~ 1.2e-11
  // (the open class of a stick end next to a pressure kink, docs/validation.md: measured
  // 3.2e-13 and 5.5e-13 here, above the quadrature estimate's 1.8e-13).
  for (double n : {1.01, 1.001}) {
    CAPTURE(n);
    const core::power_law_pressure<double> pd(n);
    const core::power_law_pressure<long double> pl(n);
    core::general_scene<double> sd;
    sd.q = 0.9977;
    sd.s = 3;
    core::general_scene<long double> sl;
    sl.q = sd.q;
    sl.s = sd.s;
    const auto a = core::solve_general(pd, sd);
    const auto b = core::solve_general(pl, sl);
    const double delta = a.b2();  // the cusp at x = 0 from the stick end -b2
    CAPTURE(delta);
    REQUIRE(delta > 0);
    REQUIRE(delta < 1e-4);
    const double tol = std::numeric_limits<double>::epsilon() / delta;
    // the zones within the quadrature's own estimate
    const auto est = core::quadrature_estimate(0.0, a.d1(), a.d2(), a.width, sd.q, pd.accuracy_eps(), a.conditioning);
    CHECK(double(std::abs(a.d1() - b.d1())) <= est.slip_zone * a.d1());
    CHECK(double(std::abs(a.d2() - b.d2())) <= est.slip_zone * a.d2());
    for (int z : {1, 2}) {
      CAPTURE(z);
      const double r = double(std::abs((a.energy(z) - b.energy(z)) / b.energy(z)));
      CAPTURE(r);
      CHECK(r <= tol);
    }
  }
}

// Issue 13: the flat punch with a sharp corner (1 - b_f/a from 1e-8 to 1e-12) at small sigma, where
// both slip zones lie in the rounded corner, 1e-13 to 1e-8 a wide. The continuation's start at
// sigma = 0 bracketed d to sqrt(eps) absolutely, larger than the zones, and every 0 < sigma/fp0 < 3 at
// b_f/a = 1 - 1e-8, Q/fP = 0.9 ended in NO_CONVERGENCE (also b_f/a = 1 - 1e-10 and 1 - 1e-12 at
// Q/fP = 0.01 and 0.3). The zones are known to about eps/6 a absolutely there (the residual's
// coordinates near the edge), 5e-9 of d: the estimate must cover it. The reference is given the
// double value of b_f/a exactly (a decimal of 45 digits): the zones scale with the corner width
// 1 - b_f/a, which the decimal 0.99999999 and its double differ in by ~1e-9.
namespace {
// the flat punch (b_f/a = bf) by the default model: its summary, and the zone energies into E where given
hs_summary flat_default_summary(double bf, double q, double s, double *E = nullptr) {
  hs_solution *sol = nullptr;
  REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, q, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
  const hs_summary S = summary(sol);
  const int st = E ? hs_solution_energy(sol, E) : HS_OK;
  hs_solution_free(sol);
  REQUIRE(st == HS_OK);
  return S;
}

// a double's exact value as a decimal (45 digits), for the reference's geometry parameter
std::string exact_decimal(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.45e", v);
  return buf;
}
}  // namespace

TEST_CASE("issue 13: flat punch with a sharp corner, slip zones inside it at small sigma, against the reference") {
  struct scene {
    double bf, q, s;
  };
  for (const scene &c : {scene{0.99999999, 0.9, 0.01}, scene{0.99999999, 0.9, 0.1}, scene{0.9999999999, 0.01, 0.1},
                         scene{0.999999999999, 0.3, 0.1}}) {
    CAPTURE(c.bf);
    CAPTURE(c.q);
    CAPTURE(c.s);
    double E[2] = {-1, -1};
    const hs_summary S = flat_default_summary(c.bf, c.q, c.s, E);
    const ref_values R = reference_values(c.q, c.s, HS_GEOMETRY_FLAT_ROUNDED, exact_decimal(c.bf).c_str(), 20);
    const double e1 = rel(S.d1, R.d1), e2 = rel(S.d2, R.d2);
    CHECK(e1 <= S.error_estimate);
    CHECK(e2 <= S.error_estimate);
    CHECK(rel(E[0], R.e1) <= S.error_estimate);
    CHECK(rel(E[1], R.e2) <= S.error_estimate);
    MESSAGE("b_f/a = 1 - " << 1 - c.bf << ", q = " << c.q << ", s = " << c.s << ": d1 = " << S.d1 << " (rel. error "
                           << e1 << "), d2 = " << S.d2 << " (" << e2 << "), energies " << rel(E[0], R.e1) << ", "
                           << rel(E[1], R.e2) << "; estimate " << S.error_estimate);
  }
}

namespace {
// d1, d2 of the reference at `digits` (no energies: those are the reference's slow part)
std::pair<double, double> reference_zones(double q, double s, int geometry, const char *par, int digits = 20) {
  hs_ref_solution *sol = reference_solution(q, s, geometry, par, digits);
  const std::pair<double, double> v{reference_value(sol, HS_REF_D1), reference_value(sol, HS_REF_D2)};
  hs_ref_solution_free(sol);
  return v;
}
}  // namespace

// Issue 13 (session 20, a random probe of the flat punch with 1 - b_f/a down to 1e-12 and
// 1 - |Q/fP| down to 1e-8): the stick zone next to a sharp corner, Q near fP, under bulk tension.
// The order control accepted an order whose residual at twice the order was below the residual's
// grain in the state (the rounding floor), although the root at twice the order moved the small
// zone by 8e-5 of itself: d2 was off by 1.1e-7 against an estimate of 1.8e-8 (first scene), 3.4e-5
// against 1.6e-5 (second) and 8e-3 against 2.3e-6 (third; 5e-5 against 6.7e-9 in the fourth).
// Below the grain the zones' move must now be within the estimate's resolution or have stopped
// shrinking (general_solver.hpp). Judged against the reference, given the doubles exactly.
TEST_CASE("issue 13: flat punch with a sharp corner next to sliding under bulk tension, against the reference") {
  struct scene {
    double bf, q, s;
  };
  for (const scene &c : {scene{0.9999993847545946, 0.9999954899275122, -22.287187060712938},
                         scene{0.9999999993347098, -0.9999997307775017, 21.490333673292437},
                         scene{0.9999999937441786, 0.9999999878746825, -9432.3164360606},
                         scene{0.9999959020463169, 0.9999999800489725, -0.8456780523170698},
                         // a small flat, the stick a point (width 6e-71 a): F1 at the orders 512 and 1024
                         // sat at 2.6e-11 and 3.6e-11, above qtol 1.8e-11, while x1 moved by 2e-14 (the
                         // order limit, NO_CONVERGENCE)
                         scene{0.011927369160584362, -0.27689637475305107, -403.59083187188236}}) {
    CAPTURE(c.bf);
    CAPTURE(c.q);
    CAPTURE(c.s);
    const hs_summary S = flat_default_summary(c.bf, c.q, c.s);
    const auto R = reference_zones(c.q, c.s, HS_GEOMETRY_FLAT_ROUNDED, exact_decimal(c.bf).c_str());
    const double e1 = rel(S.d1, R.first), e2 = rel(S.d2, R.second);
    CAPTURE(e1);
    CAPTURE(e2);
    CAPTURE(S.error_estimate);
    // (every zone here is resolved: the estimate's relative bound applies to both; a = 1)
    REQUIRE(S.d1 > S.zone_resolution);
    REQUIRE(S.d2 > S.zone_resolution);
    CHECK(e1 <= S.error_estimate);
    CHECK(e2 <= S.error_estimate);
  }
}

// Issue 13 (session 20): the zone energies of a state known only to ~1e-7 (1 - b_f/a = 2.1e-6,
// 1 - Q/fP = 4.1e-6: the stick zone 2.8e-4 a wide at the corner) came back NO_CONVERGENCE: the
// orders 64 to 1024 of the fixed rules scatter by 3e-11 of E1 (the rounding of the Cauchy sums next
// to the corner) and were asked to agree to eps^(3/4). They now need agree only to a 32nd of
// the energies' estimate, which the state's own error already sets (general_solution::state_rtol).
TEST_CASE("issue 13: zone energies agree to the state's error, not beyond (flat punch, sharp corner, near sliding)") {
  // (the second scene: the first of the test case above, whose energies failed alike)
  for (const auto &c : {std::array<double, 3>{0.9999979312645223, 0.9999959195942304, -0.05775322224775767},
                        std::array<double, 3>{0.9999993847545946, 0.9999954899275122, -22.287187060712938}}) {
    const double bf = c[0], q = c[1], s = c[2];
    CAPTURE(bf);
    CAPTURE(q);
    CAPTURE(s);
    hs_solution *sol = nullptr;
    REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, q, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
    const hs_summary S = summary(sol);
    double E[2] = {-1, -1};
    REQUIRE(hs_solution_energy(sol, E) == HS_OK);
    hs_solution_free(sol);
    // the long double solve (its rounding ~2000 times below): E1 agrees with the 20-digit reference
    // 4.5296198712077972751e-2 to 2e-15 (measured)
    const core::flat_rounded_pressure<long double> pl(static_cast<long double>(bf));
    core::general_scene<long double> sl;
    sl.q = q;
    sl.s = s;
    // (where long double is double the check would be the double solve's own)
    if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) continue;
    const auto b = core::solve_general(pl, sl);
    const double r1 = rel(E[0], double(b.energy(1))), r2 = rel(E[1], double(b.energy(2)));
    CAPTURE(r1);
    CAPTURE(r2);
    CAPTURE(S.error_estimate);
    CHECK(r1 <= S.error_estimate);
    CHECK(r2 <= S.error_estimate);
  }
}

// Issue 13 (session 20): slip zones of 2e-13 and 3e-12 a inside a corner 4.5e-12 a wide. The
// traction's zone integrals formed the pressure at x = b1 + d u^2, whose distance to the edge had
// lost all but ~3 digits: the tanh-sinh ran to its last level on the staircase, 25 ms a point, and
// the CLI's surface stresses took 27 s (3 min for the 2000 points below). The pressure is now taken
// at its exact distance from the edge (traction.hpp, pressure_at): 0.1 ms a point.
TEST_CASE("issue 13: traction of slip zones 1e-13 a wide in a sharp corner, against the reference") {
  const double bf = 0.9999999999955057, q = 0.41345080329245576, s = 0.6805874883686964;
  const auto t0 = std::chrono::steady_clock::now();
  hs_solution *sol = nullptr;
  REQUIRE(solve_geometry(HS_GEOMETRY_FLAT_ROUNDED, bf, q, s, HS_MODEL_DEFAULT, &sol) == HS_OK);
  const hs_summary S = summary(sol);
  std::vector<double> xs(2000), qs(2000);
  for (int i = 0; i < 2000; ++i) xs[i] = -1 + 2 * (i + 0.5) / 2000;
  REQUIRE(hs_eval_traction(sol, xs.size(), xs.data(), qs.data()) == HS_OK);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CAPTURE(secs);
  CHECK(secs < 20.0);  // hang guard (0.2 s in the release build; bench/ measures speed)
  hs_ref_solution *ref = reference_solution(q, s, HS_GEOMETRY_FLAT_ROUNDED, exact_decimal(bf).c_str(), 20);
  // the stick zone (its middle, next to both stick ends) and both slip zones
  for (const double x :
       {0.0, 0.5, -0.7, 0.9999999999, -0.99999999999, 0.99999999999, 0.9999999999999, -0.999999999998}) {
    CAPTURE(x);
    double qd = 0;
    REQUIRE(hs_eval_traction(sol, 1, &x, &qd) == HS_OK);
    char buf[128];
    REQUIRE(hs_ref_eval(ref, HS_REF_EVAL_TRACTION, exact_decimal(x).c_str(), buf, sizeof buf, nullptr, nullptr) ==
            HS_OK);
    const double qr = std::strtod(buf, nullptr), e = rel(qd, qr);
    CAPTURE(qd);
    CAPTURE(qr);
    CAPTURE(S.error_estimate);
    // q has no estimate of its own: on the stick zone it moves with the zone ends, known here to
    // 1.4e-6 (d1) and 3.9e-5 (d2) of themselves (measured against the reference; the estimate,
    // 4.8e-2, is 16 eps over d1). Measured: 3.5e-5 at x = 0, 1e-4 next to the stick ends, 0 in
    // the slip zones (q = f p there). The bound: 1e-3, ten times the largest.
    CHECK(e <= 1e-3);
  }
  hs_ref_solution_free(ref);
  hs_solution_free(sol);
}
