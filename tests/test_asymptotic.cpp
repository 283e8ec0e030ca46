// The asymptotic single-edge model (paper section 5) against the full Hertz
// solution, and erratum E9 (the constant in eq 29).
#include <doctest/doctest.h>

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
