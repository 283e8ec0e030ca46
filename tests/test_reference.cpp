// The MPFR reference backend: agreement with the double fast path, with the
// raw-integral oracles at 50+ digits, honest digit certification, threads,
// and genericity of the core (cpp_bin_float archetype).
#include <doctest/doctest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "halfslip/core/hertz.hpp"
#include "halfslip/reference/backend.hpp"
#include "halfslip/reference/oracle.hpp"
#include "testing.hpp"

namespace core = hs::core;
namespace ref = hs::reference;
using mp80 = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<80>, boost::multiprecision::et_off>;

namespace {

// exact decimal expansion of a double (glibc prints exact digits)
std::string exact(double x) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.70e", x);
  return buf;
}

double boundary_s(double q) { return 4 * q / (1 + std::sqrt(1 - q)); }

double to_double(const std::string &s) { return std::strtod(s.c_str(), nullptr); }

// |double - reference| in units of eps * scale, the reference held at 40 digits
double err_eps(double v, const std::string &r, double scale) {
  const mp80 d = mp80(v) - mp80(r);
  return double(abs(d)) / (scale * 2.220446049250313e-16);
}

core::hertz_solution<double> solve_double(double q, double s) {
  core::hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  return core::solve_hertz(sc);
}

ref::text_scene text(double q, double s) {
  ref::text_scene t;
  t.q = exact(q);
  t.s = exact(s);
  return t;
}

}  // namespace

TEST_CASE("double fast path against the reference at 40 digits, 200 random scenes per regime") {
  hs_test::rng r(2024);
  for (int regime = 1; regime <= 2; ++regime) {
    double worst_b = 0, worst_d = 0, worst_B = 0, worst_h = 0, worst_E = 0;
    for (int i = 0; i < 200; ++i) {
      const double q = r.uniform(0.0, 0.95);
      const double sb = boundary_s(q);
      // same sign: away from the boundary by 10% of its value (d1 >= 0.1 m,
      // where the double's d1 = m - s/4 is conditioned within 10x)
      const double s = regime == 1 ? r.uniform(-0.9, 0.9) * sb : sb + r.uniform(0.05, 5.0);
      const auto dsol = solve_double(q, s);
      REQUIRE(int(dsol.reg) == regime);
      const ref::solution rsol(text(q, s), 40);
      REQUIRE(rsol.regime() == regime);
      CHECK(rsol.dir1() == dsol.dir1());
      CHECK(rsol.dir2() == dsol.dir2());
      const auto b1 = rsol.value(ref::quantity::b1), b2 = rsol.value(ref::quantity::b2);
      const auto d1 = rsol.value(ref::quantity::d1), d2 = rsol.value(ref::quantity::d2);
      CHECK(b1.digits == 40);
      CHECK(d2.digits == 40);
      worst_b = std::max({worst_b, err_eps(dsol.b1(), b1.text, 1), err_eps(dsol.b2(), b2.text, 1)});
      worst_d = std::max({worst_d, err_eps(dsol.d1(), d1.text, to_double(d1.text)),
                          err_eps(dsol.d2(), d2.text, to_double(d2.text))});
      // point values at the middle of each slip zone, 4 scenes in 10 (cost)
      if (i % 10 < 4) {
        for (double x : {dsol.b1() + 0.5 * dsol.d1(), -dsol.b2() - 0.5 * dsol.d2()}) {
          const auto Br = rsol.eval(ref::point_eval::Bx, exact(x));
          const auto hr = rsol.eval(ref::point_eval::slip, exact(x));
          // scale: the zone's peak |B| ~ |B(edge)|, and the peak slip
          const double Bs = std::abs(dsol.Bx(x > 0 ? 1.0 : -1.0)), hs_ = std::abs(dsol.slip(x > 0 ? 1.0 : -1.0));
          worst_B = std::max(worst_B, err_eps(dsol.Bx(x), Br.text, Bs));
          worst_h = std::max(worst_h, err_eps(dsol.slip(x), hr.text, hs_));
        }
      }
      if (i % 10 == 0) {
        const auto E1 = rsol.value(ref::quantity::energy1), E2 = rsol.value(ref::quantity::energy2);
        if (dsol.d1() > 0) worst_E = std::max(worst_E, err_eps(dsol.energy(1), E1.text, to_double(E1.text)));
        worst_E = std::max(worst_E, err_eps(dsol.energy(2), E2.text, to_double(E2.text)));
      }
    }
    MESSAGE("regime " << regime << ": max error in eps: b " << worst_b << ", d (rel) " << worst_d << ", B_x "
                      << worst_B << ", h " << worst_h << ", energy (rel) " << worst_E);
    CHECK(worst_b <= 8);
    CHECK(worst_d <= 16);
    // B_x: closed forms, a few roundings of O(1) terms (64 eps); h and the
    // energies come from tanh-sinh at tolerance sqrt(eps), whose quadratic
    // convergence leaves O(eps) errors plus the integrand's rounding (256 eps).
    CHECK(worst_B <= 64);
    CHECK(worst_h <= 256);
    CHECK(worst_E <= 256);
  }
}

TEST_CASE("reference against the raw-integral oracle at 80 digits: side conditions to 1e-45") {
  struct Case { const char *q, *s; int sR; };
  // same sign, opposite sign, bulk only, near sliding
  for (Case c : {Case{"0.5", "0.2", 1}, Case{"0.3", "2", -1}, Case{"0", "1", -1}, Case{"0.9", "3.5", -1},
                 Case{"0.99", "0.5", 1}}) {
    ref::text_scene t;
    t.q = c.q;
    t.s = c.s;
    const ref::solution sol(t, 50);
    const auto b1 = sol.value(ref::quantity::b1), b2 = sol.value(ref::quantity::b2);
    REQUIRE(b1.digits == 50);
    const auto res = ref::side_residuals<mp80>(mp80(c.q), mp80(c.s), mp80(b1.text), mp80(b2.text), c.sR, +1);
    // b carries 50 digits (error <= 5e-51) and |dF/db| <= ~10
    CHECK(abs(res[0]) < 1e-45);
    CHECK(abs(res[1]) < 1e-45);
  }
}

TEST_CASE("certification is honest: claimed digits agree with a run at twice the precision") {
  hs_test::rng r(99);
  int checked = 0;
  for (int i = 0; i < 12; ++i) {
    const double q = r.uniform(0.0, 0.95);
    const double s = i % 2 ? r.uniform(-1, 1) * boundary_s(q) : boundary_s(q) + r.log_uniform(1e-6, 4);
    for (int N : {20, std::min(45, ref::max_digits() / 2)}) {
      const ref::solution lo(text(q, s), N), hi(text(q, s), 2 * N);
      for (auto qu : {ref::quantity::b1, ref::quantity::b2, ref::quantity::d1, ref::quantity::d2,
                      ref::quantity::energy1, ref::quantity::energy2}) {
        if (qu == ref::quantity::energy1 && lo.value(ref::quantity::d1).text[0] == '0') continue;
        const auto a = lo.value(qu), b = hi.value(qu);
        const int agree = ref::agreeing_digits(a.text, b.text, N);
        CHECK_MESSAGE(a.digits <= agree, "q=" << q << " s=" << s << " quantity " << int(qu) << ": claims "
                                               << a.digits << ", agrees to " << agree);
        ++checked;
      }
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("agreeing_digits counts correctly rounded digits") {
  CHECK(ref::agreeing_digits("1.234", "1.2344999", 10) == 4);
  CHECK(ref::agreeing_digits("1.235", "1.2344999", 10) == 3);
  CHECK(ref::agreeing_digits("1.2345", "1.2345", 4) == 4);
  CHECK(ref::agreeing_digits("0", "0", 7) == 7);
  CHECK(ref::agreeing_digits("1e-3", "0", 7) == 0);
  CHECK(ref::agreeing_digits("2", "1", 7) == 0);
}

TEST_CASE("two threads at different precisions give the results they give alone") {
  ref::text_scene t;
  t.q = "0.3";
  t.s = "2";
  auto run = [&](int digits) {
    const ref::solution s(t, digits);
    return s.value(ref::quantity::b1).text + s.value(ref::quantity::d2).text + s.value(ref::quantity::energy2).text;
  };
  const int hi_digits = std::min(150, ref::max_digits());  // short tier ladders in sanitizer builds
  const std::string alone40 = run(40), alone150 = run(hi_digits);
  for (int rep = 0; rep < 3; ++rep) {
    std::string r40, r150;
    std::thread a([&] { for (int k = 0; k < 3; ++k) r40 = run(40); });
    std::thread b([&] { r150 = run(hi_digits); });
    a.join();
    b.join();
    CHECK(r40 == alone40);
    CHECK(r150 == alone150);
  }
}

TEST_CASE("the core is generic: cpp_bin_float_50 archetype agrees with MPFR at 50 digits") {
  using bf = boost::multiprecision::cpp_bin_float_50;
  core::hertz_scene<bf> sc;
  sc.q = bf("0.3");
  sc.s = bf("2");
  const auto sol = core::solve_hertz(sc);
  ref::text_scene t;
  t.q = "0.3";
  t.s = "2";
  const ref::solution rs(t, 45);
  const mp80 diff = mp80(sol.b1().str(60)) - mp80(rs.value(ref::quantity::b1).text);
  CHECK(abs(diff) < 1e-44);
}

TEST_CASE("bad reference inputs are rejected with codes") {
  ref::text_scene t;
  t.q = "0.3x";
  try {
    ref::solution s(t, 30);
    FAIL("no exception");
  } catch (const core::error &e) {
    CHECK(e.code() == core::status::bad_number);
  }
  t.q = "1";
  try {
    ref::solution s(t, 30);
    FAIL("no exception");
  } catch (const core::error &e) {
    CHECK(e.code() == core::status::gross_sliding);
  }
  t.q = "0.3";
  CHECK_THROWS_AS(ref::solution(t, 0), core::error);
  CHECK_THROWS_AS(ref::solution(t, ref::max_digits() + 1), core::error);
}

TEST_CASE("stability sweeps towards every failure region: double within its bound of the reference") {
  // |b - b_ref| <= 8 eps a, and |d - d_ref| <= 8 eps a + 16 eps d_ref: a slip
  // zone that is itself a small difference of the inputs (near the regime
  // boundary) is only defined to absolute accuracy eps a by them.
  const double eps = 2.220446049250313e-16;
  struct Case { double q, s; const char *what; };
  std::vector<Case> cases;
  for (double d = 1e-1; d >= 1e-15; d /= 10) cases.push_back({d * (2 - d), 0.0, "tiny slip zone (Q only)"});
  for (double omq = 1e-3; omq >= 1e-15; omq /= 100) cases.push_back({1 - omq, 0.0, "near sliding (Q only)"});
  for (double q : {0.01, 0.3, 0.75, 0.9, 0.999}) {
    const double sb = boundary_s(q);
    for (double rel : {-1e-12, -1e-15, 1e-15, 1e-12, 1e-9, 1e-6}) cases.push_back({q, sb * (1 + rel), "regime boundary"});
    for (double ds : {0.1, 1.0, 4.0, 8.0}) cases.push_back({q, sb + ds, "towards k -> 1 (large sigma)"});
  }
  for (const auto &c : cases) {
    CAPTURE(c.what);
    CAPTURE(c.q);
    CAPTURE(c.s);
    const auto dsol = solve_double(c.q, c.s);
    CHECK(std::isfinite(dsol.b1()));
    CHECK(std::isfinite(dsol.b2()));
    const ref::solution rsol(text(c.q, c.s), 30);
    CHECK(rsol.regime() == int(dsol.reg));
    const double b1 = to_double(rsol.value(ref::quantity::b1).text), b2 = to_double(rsol.value(ref::quantity::b2).text);
    const double d1 = to_double(rsol.value(ref::quantity::d1).text), d2 = to_double(rsol.value(ref::quantity::d2).text);
    CHECK(std::abs(dsol.b1() - b1) <= 8 * eps);
    CHECK(std::abs(dsol.b2() - b2) <= 8 * eps);
    CHECK(std::abs(dsol.d1() - d1) <= 8 * eps + 16 * eps * d1);
    CHECK(std::abs(dsol.d2() - d2) <= 8 * eps + 16 * eps * d2);
  }
}
