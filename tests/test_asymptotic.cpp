// The asymptotic single-edge model (paper section 5) against the full Hertz
// solution, and erratum E9 (the constant in eq 29).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "halfslip/core/asymptotic.hpp"
#include "halfslip/reference/oracle.hpp"
#include "testing.hpp"

namespace core = hs::core;
using LD = long double;

TEST_CASE("eq (29) with the factor 2 is the near-edge limit of the full solution (erratum E9)") {
  // shear only, slip zones shrinking: B_full / B_asym -> 1 at fixed z/d, the
  // deviation O(d/a); with eq 29 as printed (f K_N/E*) the ratio tends to 2
  double prev = 1e9;
  for (double q : {1e-1, 1e-2, 1e-3, 1e-4}) {
    core::hertz_scene<double> sc;
    sc.q = q;
    const auto sol = core::solve_hertz(sc);
    const auto m = core::hertz_edge(sc, +1);
    const double d = sol.d1();
    CHECK(m.d() == doctest::Approx(d).epsilon(q));  // d_asym = q/2, d_full = q/2 + q^2/8 + ...
    const double z = 0.5 * d;                       // halfway into the zone, from the edge
    const double ratio = sol.Bx(1 - z) / m.Bx(0.5 * m.d());
    const double dev = std::abs(ratio - 1);
    CHECK(dev < 2 * q);
    CHECK(dev < prev);
    prev = dev;
    const double printed = sol.Bx(1 - z) / (m.Bx(0.5 * m.d()) / 2);  // eq 29 as printed
    CHECK(std::abs(printed - 2) < 4 * q);
  }
}

TEST_CASE("asymptotic slip and energy: closed forms against quadrature of the model itself") {
  core::edge_model<double> m;
  m.KN = 1.3;
  m.KT = 0.07;
  m.f = 0.6;
  m.Estar = 2.0;
  const double d = m.d();
  for (double t : {0.0, 0.25, 0.9}) {
    const LD h = hs::reference::integrate<LD>([&](LD z, LD, LD) { return LD(m.Bx(double(z))); }, LD(t * d), LD(d));
    CHECK(m.slip(t * d) == doctest::Approx(double(h)).epsilon(1e-14));
  }
  const LD E = hs::reference::integrate<LD>([&](LD z, LD, LD) { return LD(m.work(double(z))); }, LD(0), LD(d));
  CHECK(m.energy() == doctest::Approx(double(E)).epsilon(1e-14));
}

TEST_CASE("fractional energy error: under-estimate under shear, over-estimate under bulk tension, -> 0 as b/a -> 1") {
  double prev_shear = -1, prev_bulk = 1e9;
  for (double b : {0.6, 0.8, 0.9, 0.95, 0.99}) {
    const auto s = core::compare_asymptotic<double>(+1, b);
    const auto k = core::compare_asymptotic<double>(-1, b);
    CAPTURE(b);
    CHECK(s.d_full == doctest::Approx(1 - b).epsilon(1e-14));
    CHECK(k.d_full == doctest::Approx(1 - b).epsilon(1e-12));
    CHECK(s.fractional_error() < 0);  // the paper's statement in section 5.2
    CHECK(k.fractional_error() > 0);
    CHECK(s.fractional_error() > prev_shear);  // shrinking in magnitude
    CHECK(k.fractional_error() < prev_bulk);
    prev_shear = s.fractional_error();
    prev_bulk = k.fractional_error();
  }
  CHECK(std::abs(prev_shear) < 0.02);
  CHECK(std::abs(prev_bulk) < 0.05);
  // the paper: "b/a = 0.9 gives rise to a 10% error" (order of magnitude)
  const double e9 = std::max(std::abs(core::compare_asymptotic<double>(+1, 0.9).fractional_error()),
                             std::abs(core::compare_asymptotic<double>(-1, 0.9).fractional_error()));
  CHECK(e9 > 0.03);
  CHECK(e9 < 0.3);
}

TEST_CASE("K_N from a pressure model: edge_phi equals eq 27's (1/pi) sqrt(2/a) dP/da for every model") {
  // flat punch: P = a^2 g(b_f/a)/(2AR), p0 = a g/(pi A R), so eq 27 gives
  // K_N/(p0 sqrt(2/a)) = 1 + 2 beta sqrt(1-beta^2)/g(beta); power law P ~ a^n gives n/2
  for (double beta : {0.0, 0.3, 0.6, 0.9}) {
    core::flat_rounded_pressure<double> pm(beta);
    const double g = core::flat_rounded_pressure<double>::load_factor(beta);
    const double expect = 1 + 2 * beta * std::sqrt(1 - beta * beta) / g;
    CAPTURE(beta);
    CHECK(pm.edge_phi(+1) == doctest::Approx(expect).epsilon(1e-12));
    CHECK(pm.edge_phi(-1) == doctest::Approx(expect).epsilon(1e-12));
    // the default (Richardson) rule agrees with the model's own edge value
    CHECK(pm.pressure_model<double>::edge_phi(+1) == doctest::Approx(expect).epsilon(1e-9));
  }
  for (double n : {1.5, 2.0, 3.0, 4.5}) {
    core::power_law_pressure<double> pm(n);
    CAPTURE(n);
    CHECK(pm.edge_phi(+1) == doctest::Approx(n / 2).epsilon(1e-15));
    CHECK(pm.pressure_model<double>::edge_phi(-1) == doctest::Approx(n / 2).epsilon(1e-9));
  }
}

TEST_CASE("edge_solution: zone lengths, slip directions and signs of B_x, h agree with the full solution as d -> 0") {
  // every sign combination of (Q, sigma), both regimes; the model's error is O(d/a)
  core::hertz_pressure<double> pm;
  for (double q : {2e-4, -2e-4})
    for (double s : {0.0, 1e-4, -1e-4, 3e-3, -3e-3}) {
      core::general_scene<double> sc;
      sc.a = 2.0;
      sc.p0 = 1.5;
      sc.f = 0.4;
      sc.Estar = 3.0;
      sc.q = q;
      sc.s = s;
      core::hertz_scene<double> hsc;
      hsc.a = sc.a;
      hsc.p0 = sc.p0;
      hsc.f = sc.f;
      hsc.Estar = sc.Estar;
      hsc.q = q;
      hsc.s = s;
      const auto full = core::solve_hertz(hsc);
      const core::edge_solution<double> m(pm, sc);
      CAPTURE(q);
      CAPTURE(s);
      CHECK(int(m.reg) == int(full.reg));
      CHECK(m.dir1() == full.dir1());
      CHECK(m.dir2() == full.dir2());
      CHECK(m.d1() == doctest::Approx(full.d1()).epsilon(1e-2));
      CHECK(m.d2() == doctest::Approx(full.d2()).epsilon(1e-2));
      for (double t : {0.3, 0.7}) {
        const double x1 = sc.a - t * full.d1(), x2 = -sc.a + t * full.d2();
        CHECK(m.Bx(x1) == doctest::Approx(full.Bx(x1)).epsilon(2e-2));
        CHECK(m.Bx(x2) == doctest::Approx(full.Bx(x2)).epsilon(2e-2));
        CHECK(m.slip(x1) == doctest::Approx(full.slip(x1)).epsilon(3e-2));
        CHECK(m.slip(x2) == doctest::Approx(full.slip(x2)).epsilon(3e-2));
        CHECK(m.work(x1) == doctest::Approx(full.work(x1)).epsilon(3e-2));
      }
      CHECK(m.energy(1) == doctest::Approx(full.energy(1)).epsilon(3e-2));
      CHECK(m.energy(2) == doctest::Approx(full.energy(2)).epsilon(3e-2));
    }
}

TEST_CASE("compare_asymptotic, bulk loading at a subnormal b/a: the load and d_full continue the normal range") {
  // Issue 13 (fuzz_asymptotic, corpus input crash-bulk-subnormal-b): the moment of eq (18) was
  // formed from a stick width 2b below the normal range without its logarithm (the basis reads
  // ln e there), so b = 5.4e-309 gave s = 4.86 (for ~1.8e3) and d_full = 0.789 a for 1 - b.
  // Check: as b -> 0, pi s / 8 = int_b^1 sqrt(1-t^2)/sqrt(t^2-b^2) dt = ln(2/b) - 1 + O(b^2 ln b),
  // so s(b) - s(b0) = (8/pi) ln(b0/b) to rounding (relative to s ~ 1.8e3: 1e-13).
  const double b0 = 1e-300;
  const auto c0 = hs::core::compare_asymptotic<double>(-1, b0);
  for (double b : {5.4377415341022824e-309, 1e-315, 4.9406564584124654e-324}) {
    CAPTURE(b);
    const auto c = hs::core::compare_asymptotic<double>(-1, b);
    CHECK(c.d_full == doctest::Approx(1 - b).epsilon(4 * std::numeric_limits<double>::epsilon()));
    const double want = c0.scene.s + 8 / hs::core::pi<double>() * std::log(b0 / b);
    CHECK(std::abs(c.scene.s - want) <= 1e-13 * want);
  }
}
