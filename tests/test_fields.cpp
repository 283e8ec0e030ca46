// Issue 15: the shear traction q(x) and the stresses the contact puts into
// each body (docs/fields.md, conventions in docs/conventions.md).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "halfslip/core/asymptotic.hpp"
#include "halfslip/core/fields.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "testing.hpp"

using namespace hs::core;

namespace {

// (2/pi) PV int_{-a}^{a} q(t)/(x - t) dt by subtraction of q(x) (tanh-sinh
// on the pieces split at the stick boundaries and at x).
template <class S> double hilbert_q(const S &sol, double x, double tol = 1e-12) {
  const double a = sol.scene.a, qx = sol.traction(x);
  const double pv = integrate_pieces<double>(
      [&](double t, double) { return t == x ? 0.0 : (sol.traction(t) - qx) / (x - t); }, -a, a,
      {-sol.b2(), sol.b1(), x}, tol);
  return 2 / M_PI * (pv + qx * std::log((x + a) / (a - x)));
}

template <class S> void check_traction(const S &sol, double Q, double sigma, double tol_rel) {
  const double a = sol.scene.a, f = sol.scene.f, p0 = sol.scene.p0, E = sol.scene.Estar;
  const double b1 = sol.b1(), b2 = sol.b2();
  // continuity at the stick-slip boundaries: q(b -+ h) -> dir f p(b)
  for (int z : {1, 2}) {
    const double d = z == 1 ? sol.d1() : sol.d2();
    if (!(d > 0)) continue;
    const double b = z == 1 ? b1 : -b2;
    const int dir = z == 1 ? sol.dir1() : sol.dir2();
    const double inside = z == 1 ? b - 1e-9 * a : b + 1e-9 * a;
    const double jump = std::fabs(sol.traction(inside) - dir * f * sol.pressure(b));
    // q - q(b) ~ sqrt(distance): 1e-9 a gives ~ 3e-5 f p0 at most
    CHECK(jump < 1e-4 * f * p0);
  }
  // |q| <= f p in the stick zone
  for (int i = 1; i < 200; ++i) {
    const double x = -b2 + (b1 + b2) * i / 200;
    CHECK(std::fabs(sol.traction(x)) <= f * sol.pressure(x) * (1 + 1e-12));
  }
  // resultant Q
  const double I = integrate_pieces<double>([&](double x, double) { return sol.traction(x); }, -a, a, {-b2, b1},
                                            1e-12);
  CHECK(std::fabs(I - Q) <= tol_rel * f * p0 * a);
  // E* B_x = (2/pi) PV int q/(x - t) dt - sigma/2 (no slip in the stick zone, eqs (4)/(5) in the slip zones)
  for (double u : {-0.97, -0.6, -0.2, 0.1, 0.45, 0.8, 0.99}) {
    const double x = u * a;
    const double lhs = hilbert_q(sol, x) - sigma / 2;
    CHECK(std::fabs(lhs - E * sol.Bx(x)) <= tol_rel * f * p0);
  }
}

}  // namespace

TEST_CASE("traction: Hertz closed form (same sign) = the generic stick-zone solution") {
  for (double q : {0.1, 0.5, 0.95})
    for (double s : {0.0, 0.1, -0.3}) {
      hertz_scene<double> sc;
      sc.q = q;
      sc.s = s;
      sc.a = 1.3;
      sc.p0 = 2.0;
      sc.f = 0.4;
      sc.Estar = 5;
      const auto sol = solve_hertz(sc);
      if (sol.reg != regime::same_sign) continue;
      double worst = 0;
      for (int i = 0; i <= 400; ++i) {
        const double x = -sc.a + 2 * sc.a * i / 400.0;
        worst = std::max(worst, std::fabs(sol.traction(x) - sol.traction_generic(x)));
      }
      CAPTURE(q);
      CAPTURE(s);
      CHECK(worst <= 64 * hs_test::eps<double>() * sc.f * sc.p0);
    }
}

TEST_CASE("traction: Hertz in every regime (continuity, |q| <= fp, resultant, no-slip relation)") {
  struct c {
    double q, s;
  };
  for (c k : {c{0.3, 0.0}, c{0.6, 0.2}, c{-0.4, 0.5}, c{0.5, 1.5}, c{0.5, -3.0}, c{0.9, 2.0}, c{0.2, 0.8}}) {
    hertz_scene<double> sc;
    sc.q = k.q;
    sc.s = k.s;
    sc.a = 0.7;
    sc.p0 = 3.0;
    sc.f = 0.6;
    sc.Estar = 2;
    const auto sol = solve_hertz(sc);
    CAPTURE(k.q);
    CAPTURE(k.s);
    const double P = M_PI * sc.a * sc.p0 / 2;
    check_traction(sol, k.q * sc.f * P, k.s * sc.f * sc.p0, 1e-9);
  }
}

TEST_CASE("traction: flat rounded punch in both regimes") {
  for (double s : {0.1, 2.0}) {
    flat_rounded_pressure<double> pm(0.5);
    general_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    const auto sol = solve_general<double>(pm, sc);
    CAPTURE(s);
    const double P = M_PI * sc.a * sc.p0 / 2;
    check_traction(sol, sc.q * sc.f * P, sc.s * sc.f * sc.p0, 1e-8);
  }
}

TEST_CASE("fields: Hertz closed forms = Flamant quadrature, near the surface and at the edges") {
  for (double s : {0.0, 0.3, -0.2}) {
    hertz_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    sc.a = 1.2;
    sc.p0 = 1.5;
    sc.f = 0.5;
    const auto sol = solve_hertz(sc);
    const auto cl = hertz_state(sol), nu = make_state<double>(sol);
    double worst = 0;
    for (int body : {1, 2})
      for (double x : {-3.0, -1.2, -1.0, -0.3, 0.0, 0.7, 1.19, 1.2, 1.25, 2.0})
        for (double z : {1e-6, 1e-3, 0.1, 1.0, 5.0}) {
          const auto A = stress_at(cl, body, x, z), B = stress_at(nu, body, x, z);
          worst = std::max({worst, std::fabs(A.xx - B.xx), std::fabs(A.yy - B.yy), std::fabs(A.xy - B.xy)});
        }
    CAPTURE(s);
    // 1e-10 relative to the peak pressure (measured: 4e-11 at z = 1e-6 a)
    CHECK(worst <= 1e-10 * sc.p0);
  }
}

TEST_CASE("fields: McEwen full-sliding check of the closed form (surface sigma_xx = -p - 2 f x p0 / a inside)") {
  // q -> f p when the stick zone vanishes: use the semi-ellipse pieces directly.
  contact_state<double> st;
  st.a = 1;
  st.p = [](double x) { return std::sqrt(1 - x * x); };
  st.q = [](double x) { return 0.3 * std::sqrt(1 - x * x); };
  st.closed = [](const std::complex<double> &z, cauchy_pair<double> &P, cauchy_pair<double> &Q) {
    add_semi_ellipse(1.0, 1.0, 0.0, z, P);
    add_semi_ellipse(0.3, 1.0, 0.0, z, Q);
    return true;
  };
  // Johnson eq 7.?: on the surface, sigma_x = -p0 (sqrt(1-x^2) + 2 f x) inside, body 1
  for (double x : {-0.9, -0.2, 0.4, 0.95}) {
    const double v = stress_at(st, 1, x, 0.0).xx;
    CHECK(std::fabs(v - (-(std::sqrt(1 - x * x) + 2 * 0.3 * x))) < 1e-14);
  }
  // outside: sigma_x = -2 f p0 (x - sgn(x) sqrt(x^2 - 1)); tensile at the trailing edge x = -a: 2 f p0
  for (double x : {-3.0, -1.0, 1.5}) {
    const double v = stress_at(st, 1, x, 0.0).xx;
    const double e = -2 * 0.3 * (x - (x > 0 ? 1 : -1) * std::sqrt(x * x - 1));
    CHECK(std::fabs(v - e) < 1e-14);
  }
}

TEST_CASE("fields: surface limit, equilibrium at depth and far field (Hertz opposite sign, flat punch)") {
  hertz_scene<double> sc;
  sc.q = 0.5;
  sc.s = 2.0;
  sc.a = 1.2;
  sc.p0 = 1.5;
  sc.f = 0.5;
  const auto hs_ = solve_hertz(sc);
  flat_rounded_pressure<double> pm(0.5);
  general_scene<double> gs;
  gs.q = 0.4;
  gs.s = 1.0;
  gs.a = 0.8;
  gs.p0 = 2.0;
  gs.f = 0.7;
  const auto gsol = solve_general<double>(pm, gs);
  auto run = [](const contact_state<double> &st, double P, double Q, double scale) {
    // surface limit: sigma_xx(x, y -> 0) -> surface_sxx (difference O(y/a) inside, O(sqrt(y/a)) at the edges)
    for (int body : {1, 2})
      for (double u : {-2.0, -0.7, 0.1, 0.6, 1.6}) {
        const double x = u * st.a;
        CAPTURE(body);
        CAPTURE(u);
        CHECK(std::fabs(stress_at(st, body, x, 1e-9 * st.a).xx - surface_sxx(st, body, x)) < 1e-6 * scale);
      }
    // equilibrium: on the line y = h, int sigma_yy dx = -P and int sigma_xy dx = -Q in body 1,
    // the same in body 2 (sigma_xy = -tau_xz there, traction -q)
    for (int body : {1, 2}) {
      const double h = 0.5 * st.a;
      // x = h tan(theta) maps the line onto (-pi/2, pi/2); the integrands decay like 1/x^2
      auto integ = [&](int comp) {
        return integrate_ts<double>(
            [&](double th, double) {
              const double x = h * std::tan(th), j = h / (std::cos(th) * std::cos(th));
              const auto s = stress_at(st, body, x, h);
              return (comp == 0 ? s.yy : s.xy) * j;
            },
            -M_PI / 2, M_PI / 2, 1e-10);
      };
      CAPTURE(body);
      CHECK(std::fabs(integ(0) + P) < 1e-8 * P);
      CHECK(std::fabs(integ(1) + Q) < 1e-8 * P);
    }
    // far field: at distance r >> a the Flamant point-load field of (P, Q)
    const double r = 1e3 * st.a;
    for (double th : {0.3, 1.0, 2.0}) {
      const double x = r * std::cos(th), z = r * std::sin(th);
      const auto s = stress_at(st, 1, x, z);
      // Flamant (Johnson 2.15/2.19): sigma_r = -2 (P sin th + Q cos th)/(pi r) radial
      const double sr = -2 * (P * std::sin(th) + Q * std::cos(th)) / (M_PI * r);
      const double c = std::cos(th), sn = std::sin(th);
      CHECK(std::fabs((s.xx - st.bulk1) - sr * c * c) < 1e-3 * std::fabs(sr) + 1e-12);
      CHECK(std::fabs(s.yy - sr * sn * sn) < 1e-3 * std::fabs(sr) + 1e-12);
      CHECK(std::fabs(s.xy - sr * sn * c) < 1e-3 * std::fabs(sr) + 1e-12);
    }
  };
  const double Ph = M_PI * sc.a * sc.p0 / 2, Pg = M_PI * gs.a * gs.p0 / 2;
  run(hertz_state(hs_), Ph, sc.q * sc.f * Ph, sc.p0);
  run(general_state_of(gsol), Pg, gs.q * gs.f * Pg, gs.p0);
  auto gp = general_state_of(gsol);  // the same through the cached panels
  gp.panels = make_panels(gp);
  run(gp, Pg, gs.q * gs.f * Pg, gs.p0);
  auto hp = hertz_state(hs_);
  hp.panels = make_panels(hp);
  run(hp, Ph, sc.q * sc.f * Ph, sc.p0);
}

TEST_CASE("fields: in the stick zone both bodies have the same surface sigma_xx; bulk split") {
  hertz_scene<double> sc;
  sc.q = 0.3;
  sc.s = 0.4;
  const auto sol = solve_hertz(sc);
  const auto st = hertz_state(sol, 0.25);  // the pad carries 0.25, the specimen sigma + 0.25
  CHECK(st.bulk1 - st.bulk2 == doctest::Approx(0.4));
  for (double x : {-0.3, 0.0, 0.5}) CHECK(std::fabs(surface_sxx(st, 1, x) - surface_sxx(st, 2, x)) < 1e-15);
  // far away the surface stress tends to the bulk stress
  CHECK(std::fabs(surface_sxx(st, 1, 1e6) - st.bulk1) < 1e-6);
  CHECK(std::fabs(surface_sxx(st, 2, -1e6) - st.bulk2) < 1e-6);
}

TEST_CASE(
    "fields: Hertz same-sign trailing-edge peak, sigma_xx(-a) = 2 f p0 sqrt(d2 (a + b1))/a + sigma1 - sigma/2") {
  // From the closed form: (2/pi) int q/(x - t) at x = -a is 2 f p0 (e - sqrt((a+e)^2 - c^2))/a, e = sigma/(4 f p0) a.
  // (Ciavarella & Macina 2003 give the same peak; their paper was not at hand to compare term by term.)
  for (double s : {0.0, 0.2, 0.5}) {
    hertz_scene<double> sc;
    sc.q = 0.6;
    sc.s = s;
    sc.a = 1.5;
    sc.p0 = 2.0;
    sc.f = 0.3;
    const auto sol = solve_hertz(sc);
    REQUIRE(sol.reg == regime::same_sign);
    const auto st = hertz_state(sol);
    const double sigma = s * sc.f * sc.p0;
    const double expect = 2 * sc.f * sc.p0 * std::sqrt(sol.d2() * (sc.a + sol.b1())) / sc.a + sigma / 2;
    const auto e = surface_summary(st, 1, 3 * sc.a, {-sc.a, sc.a, -sol.b2(), sol.b1()});
    CAPTURE(s);
    CHECK(std::fabs(surface_sxx(st, 1, -sc.a) - expect) <= 16 * hs_test::eps<double>() * sc.p0);
    CHECK(std::fabs(e.max - expect) <= 16 * hs_test::eps<double>() * sc.p0);
    CHECK(e.x_max == -sc.a);
  }
}

// ---- cached panels (field_panels.hpp): the fast path of the C ABI ----------------------

TEST_CASE(
    "panels: Hertz closed forms = cached panels, at y = 1e-6 a, at the edges, the stick boundaries and "
    "the middle of each piece") {
  for (double s : {0.0, 0.3, -0.2}) {
    hertz_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    sc.a = 1.2;
    sc.p0 = 1.5;
    sc.f = 0.5;
    const auto sol = solve_hertz(sc);
    REQUIRE(sol.reg == regime::same_sign);
    const auto cl = hertz_state(sol);
    auto nu = make_state<double>(sol);  // no closed forms: the panels
    nu.panels = make_panels(nu);
    const double b1 = sol.b1(), b2 = sol.b2();
    std::vector<double> xs{-3.0,
                           -1.2,
                           -1.19999,
                           -1.0,
                           -0.3,
                           0.0,
                           0.7,
                           1.19,
                           1.2,
                           1.2000001,
                           2.0,
                           b1,
                           -b2,
                           (b1 - b2) / 2,
                           (b1 + 1.2) / 2,
                           (-b2 - 1.2) / 2,
                           b1 + 1e-7,
                           -b2 - 1e-7};
    double worst = 0;
    for (int body : {1, 2})
      for (double x : xs)
        for (double z : {1e-6, 1e-5, 1e-3, 0.1, 1.0, 5.0}) {
          const auto A = stress_at(cl, body, x, z), B = stress_at(nu, body, x, z);
          worst = std::max({worst, std::fabs(A.xx - B.xx), std::fabs(A.yy - B.yy), std::fabs(A.xy - B.xy)});
        }
    CAPTURE(s);
    // measured 5e-12 p0 (at y = 1e-6 a); the issue asks 1e-10 of the peak
    CHECK(worst <= 2e-11 * sc.p0);
    // the surface: principal value from the panels against the closed forms, on and off the contact
    nu.hilbert_fast = false;
    nu.stick_lo = nu.stick_hi = 0;  // the panels on the stick zone too
    double ws = 0;
    for (int i = 0; i <= 1000; ++i) {
      const double x = -2.5 + 5.0 * i / 1000 + 1e-9;
      for (int body : {1, 2}) ws = std::max(ws, std::fabs(surface_sxx(cl, body, x) - surface_sxx(nu, body, x)));
    }
    // a piece's middle and one ulp off it (the two halves must treat the pole alike)
    for (double x : {(b1 - b2) / 2, std::nextafter((b1 - b2) / 2, 9.0), (b1 + 1.2) / 2, 0.0})
      ws = std::max(ws, std::fabs(surface_sxx(cl, 1, x) - surface_sxx(nu, 1, x)));
    CHECK(ws <= 1e-11 * sc.p0);  // measured 2e-12 p0
    // 1e-12 a from a stick boundary sigma_xx varies like sqrt(x - b1): one ulp of x changes it by
    // eps a f p0 / sqrt((x - b1) a) = 2e-10 f p0 (measured 1.8e-11 p0)
    const double xb = b1 + 1e-12;
    CHECK(std::fabs(surface_sxx(cl, 1, xb) - surface_sxx(nu, 1, xb)) <= hs_test::eps<double>() * 1e6 * sc.f * sc.p0);
  }
}

TEST_CASE("panels: flat punch and Hertz opposite sign against quadrature from scratch and the solver's B_x") {
  // quadrature from scratch (cauchy_numeric: graded panels around each point and towards the kinks, q from
  // traction.hpp at every node) is accurate away from the surface; on the contact the surface stress from
  // the panels' principal value is checked against -p -+ (E* B_x + sigma/2) from the solver
  auto run = [](contact_state<double> st, double scale) {
    auto slow = st;
    st.panels = make_panels(st);
    double worst = 0;
    for (int body : {1, 2})
      for (double u : {-3.0, -1.0, -0.999, -0.5, -0.3, 0.0, 0.25, 0.5, 0.71, 0.99, 1.0001, 2.0})
        for (double z : {1e-3, 0.1, 1.0}) {
          const double x = u * st.a;
          const auto A = stress_at(st, body, x, z * st.a), B = stress_at(slow, body, x, z * st.a);
          worst = std::max({worst, std::fabs(A.xx - B.xx), std::fabs(A.yy - B.yy), std::fabs(A.xy - B.xy)});
        }
    CHECK(worst <=
          1024 * hs_test::eps<double>() * scale);  // measured 2.4e-14 (2e-11 before the slow path graded its kinks)
    st.hilbert_fast = false;
    st.stick_lo = st.stick_hi = 0;
    double ws = 0;
    for (int body : {1, 2})
      for (int i = 0; i <= 300; ++i) {
        const double x = st.a * (-0.999 + 1.998 * i / 300 + 1e-7);
        ws = std::max(ws, std::fabs(surface_sxx(st, body, x) - surface_sxx(slow, body, x)));
      }
    CHECK(ws <= 1024 * hs_test::eps<double>() * scale);  // measured 7.9e-14
  };
  flat_rounded_pressure<double> pm(0.5);
  for (double s : {0.1, 2.0}) {
    general_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    const auto sol = solve_general<double>(pm, sc);
    CAPTURE(s);
    run(general_state_of(sol), sc.p0);
  }
  hertz_scene<double> hc;
  hc.q = 0.5;
  hc.s = 2.0;
  hc.a = 1.2;
  hc.p0 = 1.5;
  hc.f = 0.5;
  const auto hsol = solve_hertz(hc);
  REQUIRE(hsol.reg == regime::opposite_sign);
  auto st = hertz_state(hsol);
  REQUIRE(needs_panels(st));
  run(st, hc.p0);
}

TEST_CASE("panels: surface limit at the contact edges, the stick boundaries and the kinks, y = 1e-9 a (flat punch)") {
  // the subsurface field tends to the surface values: sigma_yy -> -p, sigma_xy -> -q
  flat_rounded_pressure<double> pm(0.5);
  general_scene<double> sc;
  sc.q = 0.5;
  sc.s = 0.1;
  const auto sol = solve_general<double>(pm, sc);
  auto st = general_state_of(sol);
  st.panels = make_panels(st);
  const double y = 1e-9;
  for (double x : {-0.9999, -0.5001, -0.2, 0.3, 0.4999, sol.b1() + 1e-6, sol.b1() - 1e-6, 0.9999}) {
    const auto s = stress_at(st, 1, x, y);
    // the smoothing of a square root sqrt(|x - b|) at depth y differs from it by about y/sqrt(|x - b|)
    // (b: the nearest edge or stick boundary); 4 y / sqrt(|x - b| a) p0 bounds it (measured up to 2.0)
    double dist = 1 - std::fabs(x);
    for (double b : {sol.b1(), -sol.b2(), 0.5, -0.5}) dist = std::min(dist, std::fabs(x - b));  // (and the kinks)
    const double tol = 4 * y / std::sqrt(dist) * sc.p0 + 1e-11 * sc.p0;
    CAPTURE(x);
    CHECK(std::fabs(s.yy + sol.pressure(x)) < tol);
    CHECK(std::fabs(s.xy + sol.traction(x)) < tol);
    CHECK(std::fabs(s.xx - surface_sxx(st, 1, x)) < tol);
  }
}

TEST_CASE("panels: q on the stick zone as a Chebyshev series in theta (flat punch, Hertz opposite sign)") {
  // q is analytic on the stick zone, kinks of p included, with square roots at both ends
  auto check = [](const contact_state<double> &st, double fp0) {
    stick_series<double> ser(st.q, st.stick_lo, st.stick_hi);
    REQUIRE(ser.ok());
    double worst = 0;
    const double lo = st.stick_lo, hi = st.stick_hi;
    for (int i = 1; i < 200; ++i) {
      const double x = lo + (hi - lo) * i / 200;
      worst = std::max(worst, std::fabs(ser(x) - st.q(x)));
    }
    for (double d : {1e-12, 1e-8, 1e-4}) {
      worst = std::max(worst, std::fabs(ser(lo + d) - st.q(lo + d)));
      worst = std::max(worst, std::fabs(ser(hi - d) - st.q(hi - d)));
    }
    CHECK(worst <= 64 * hs_test::eps<double>() * fp0);  // measured 4e-15
  };
  flat_rounded_pressure<double> pm(0.5);
  for (double s : {0.1, 2.0}) {
    general_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    const auto sol = solve_general<double>(pm, sc);
    CAPTURE(s);
    check(general_state_of(sol), sc.f * sc.p0);
  }
  hertz_scene<double> hc;
  hc.q = 0.5;
  hc.s = 2.0;
  const auto hsol = solve_hertz(hc);
  check(make_state<double>(hsol), hc.f * hc.p0);
  // a tiny slip zone puts a singularity next to the real theta axis: no series (q is used directly)
  hertz_scene<double> tc;
  tc.q = 1e-4;
  tc.s = 0.0;  // d1 = d2 = 5e-5 a
  const auto tsol = solve_hertz(tc);
  const auto tst = make_state<double>(tsol);
  stick_series<double> tser(tst.q, tst.stick_lo, tst.stick_hi);
  CAPTURE(tsol.d1());
  CAPTURE(tsol.d2());
  CHECK(!tser.ok());
}
