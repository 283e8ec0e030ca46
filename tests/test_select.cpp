// Model selection by tolerance (issue #5, docs/models.md): every model's
// error estimate is honest (true error <= estimate) across a sweep, and
// HS_MODEL_AUTO picks the cheapest model that meets rtol.
//
// Error = largest relative error of d1, d2 and the zone energies (nonempty
// zones). Truth: the MPFR reference backend at 40 digits for Hertz (through
// the C ABI), the general solver in long double (error ~1e-19 (1 + a/d), far
// below every double estimate) for the flat punch and the power law. The
// sweep is independent of the one that fitted the asymptotic constants
// (other seed, other geometry parameters).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <memory>
#include <random>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "halfslip/core/general.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/halfslip.h"

namespace core = hs::core;

namespace {

// issue 16: the truths are kept in long double (a double-rounded truth is off by
// up to 2^-53 itself, as much as the error of a double result now estimated)
struct truth {
  long double d1, d2, e1, e2;
  bool energies;  // false: compare d1, d2 only
  double bound;   // the truth's own error bound (relative, d and E)
};

truth hertz_truth(const hs_scene &sc) {
  hs_ref_scene r;
  hs_ref_scene_default(&r);
  char a[64], p0[64], f[64], E[64], q[64], s[64];
  std::snprintf(a, 64, "%.45e", sc.a);
  std::snprintf(p0, 64, "%.45e", sc.p0);
  std::snprintf(f, 64, "%.45e", sc.f);
  std::snprintf(E, 64, "%.45e", sc.E_star);
  std::snprintf(q, 64, "%.45e", sc.Q_over_fP);
  std::snprintf(s, 64, "%.45e", sc.sigma_over_fp0);
  r.a = a;
  r.p0 = p0;
  r.f = f;
  r.E_star = E;
  r.Q_over_fP = q;
  r.sigma_over_fp0 = s;
  hs_ref_solution *sol = nullptr;
  REQUIRE(hs_ref_solve(&r, 40, &sol) == HS_OK);
  auto get = [&](int what) {
    char buf[128];
    REQUIRE(hs_ref_value(sol, what, buf, sizeof buf, nullptr, nullptr) == HS_OK);
    return std::strtold(buf, nullptr);
  };
  // 40 digits read into long double: within 2^-64 relative
  truth t{get(HS_REF_D1), get(HS_REF_D2), get(HS_REF_ENERGY1), get(HS_REF_ENERGY2), true, std::ldexp(1.0, -63)};
  hs_ref_solution_free(sol);
  return t;
}

truth general_truth(int kind, double par, const hs_scene &sc) {
  std::unique_ptr<core::pressure_model<long double>> pm;
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) pm.reset(new core::flat_rounded_pressure<long double>(par));
  else pm.reset(new core::power_law_pressure<long double>(par));
  core::general_scene<long double> g;
  g.a = sc.a;
  g.p0 = sc.p0;
  g.f = sc.f;
  g.Estar = sc.E_star;
  g.q = sc.Q_over_fP;
  g.s = sc.sigma_over_fp0;
  const auto sol = core::solve_general(*pm, g);
  // long double carries the quadrature estimate's form with its own epsilon
  // (docs/models.md): 16 eps_LD (1 + a/d_min + 1/w), w the stick width / a, times 4
  const long double dmin = std::min(sol.d1() > 0 ? sol.d1() : g.a, sol.d2() > 0 ? sol.d2() : g.a) / g.a;
  const double bound = double(64 * std::numeric_limits<long double>::epsilon() * (1 + 1 / dmin + 1 / sol.width));
  return {sol.d1(), sol.d2(), sol.energy(1), sol.energy(2), true, bound};
}

double rel(long double v, long double t) { return double(t == 0 ? std::abs(v) : std::abs(v - t) / std::abs(t)); }

// true error of a solution against the truth
double true_error(const hs_solution *sol, const truth &t) {
  hs_summary s;
  s.struct_size = sizeof s;
  REQUIRE(hs_solution_summary(sol, &s) == HS_OK);
  double e[2] = {0, 0};
  if (t.energies) REQUIRE(hs_solution_energy(sol, e) == HS_OK);
  double err = 0;
  // a zone at or below the model's resolution is bounded absolutely and has no
  // direction (issue 13, item 3); the relative error is that of the resolved zones
  const bool u1 = !(s.d1 > s.zone_resolution), u2 = !(s.d2 > s.zone_resolution);
  if (u1) CHECK(std::abs(s.d1 - t.d1) <= s.zone_resolution);
  if (u2) CHECK(std::abs(s.d2 - t.d2) <= s.zone_resolution);
  if (t.d1 > 0 && !u1) err = std::max({err, rel(s.d1, t.d1), t.energies ? rel(e[0], t.e1) : 0.0});
  if (t.d2 > 0 && !u2) err = std::max({err, rel(s.d2, t.d2), t.energies ? rel(e[1], t.e2) : 0.0});
  return err;
}

hs_summary summary(const hs_solution *sol) {
  hs_summary s;
  s.struct_size = sizeof s;
  REQUIRE(hs_solution_summary(sol, &s) == HS_OK);
  return s;
}

int solve(int kind, double par, const hs_scene &sc, int model, double rtol, hs_solution **out) {
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  o.rtol = rtol;
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = kind;
  g.flat_over_a = par;
  g.exponent = par;
  return hs_solve_geometry(&sc, &g, &o, out);
}

struct scene_case {
  int kind;
  double par;
  hs_scene sc;
};

// scenes with slip zones from 1e-7 a to ~a, both regimes, all sign combinations
std::vector<scene_case> sweep(int n_per_geometry) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> U(0, 1);
  const std::vector<std::pair<int, double>> geos = {{HS_GEOMETRY_HERTZ, 0},
                                                    {HS_GEOMETRY_FLAT_ROUNDED, 0.45},
                                                    {HS_GEOMETRY_FLAT_ROUNDED, 0.75},
                                                    {HS_GEOMETRY_POWER_LAW, 2.5},
                                                    {HS_GEOMETRY_POWER_LAW, 4.0}};
  std::vector<scene_case> v;
  for (const auto &g : geos)
    for (int k = 0; k < n_per_geometry; ++k) {
      hs_scene sc;
      hs_scene_default(&sc);
      sc.a = 0.5 + U(rng);
      sc.p0 = 0.5 + U(rng);
      sc.f = 0.2 + U(rng);
      sc.E_star = 0.5 + 2 * U(rng);
      const double q = U(rng) < 0.5 ? std::pow(10.0, -7 * U(rng)) : 0.95 * U(rng);
      const double r = U(rng);
      double s = r < 0.2 ? 0 : (r < 0.6 ? 4 * q * U(rng) : q * std::pow(10.0, 2 * U(rng) - 1));
      sc.Q_over_fP = U(rng) < 0.3 ? -q : q;
      sc.sigma_over_fp0 = U(rng) < 0.5 ? -s : s;
      v.push_back({g.first, g.second, sc});
    }
  return v;
}

}  // namespace

TEST_CASE("every model's error estimate is honest: true error <= estimate across a sweep") {
  int small_asymptotic = 0, checked = 0, refused = 0;
  for (const auto &c : sweep(24)) {
    const truth t = c.kind == HS_GEOMETRY_HERTZ ? hertz_truth(c.sc) : general_truth(c.kind, c.par, c.sc);
    std::vector<std::pair<int, double>> models = {
        {HS_MODEL_ASYMPTOTIC, 0}, {HS_MODEL_QUADRATURE, 0}, {HS_MODEL_QUADRATURE, 1e-8}};
    if (c.kind == HS_GEOMETRY_HERTZ) models.push_back({HS_MODEL_CLOSED_FORM, 0});
    for (const auto &m : models) {
      hs_solution *sol = nullptr;
      const int st = solve(c.kind, c.par, c.sc, m.first, m.second, &sol);
      CAPTURE(c.kind);
      CAPTURE(c.par);
      CAPTURE(c.sc.Q_over_fP);
      CAPTURE(c.sc.sigma_over_fp0);
      CAPTURE(m.first);
      CAPTURE(m.second);
      // zones cover the contact, or (issue 13) the expansion's first correction is as large as
      // a zone: no zone would be resolved, and the model refuses
      if (m.first == HS_MODEL_ASYMPTOTIC && st == HS_ERR_NOT_APPLICABLE) {
        ++refused;
        continue;
      }
      REQUIRE(st == HS_OK);
      const auto s = summary(sol);
      CHECK(s.model == m.first);
      const double err = true_error(sol, t);
      CAPTURE(err);
      CAPTURE(s.error_estimate);
      CAPTURE(t.bound);
      CHECK(err <= s.error_estimate + t.bound);
      ++checked;
      if (m.first == HS_MODEL_ASYMPTOTIC && s.error_estimate < 1e-2) ++small_asymptotic;
      hs_solution_free(sol);
    }
  }
  // the sweep exercises the regime where the asymptotic model is selected
  CHECK(small_asymptotic >= 20);
  // of 384 solves (5 geometries x 24 scenes x 3 models + 24 closed forms); the asymptotic model
  // refuses the scenes of large loads: 51 of its 120, 27 of them since issue 13's fuzz-findings
  // round (before, it answered those with no zone resolved; the check was checked >= 360)
  CHECK(checked + refused == 384);
  CHECK(checked >= 330);
}

TEST_CASE("closed-form and quadrature estimates near the failure regions: d/a -> 0, the regime boundary, sliding") {
  // Hertz against the 40-digit reference: tiny zones with and without
  // cancellation (d1 = m - s/4, m ~ q/2, near s = 4m), and 1 - Q/fP -> 0
  std::vector<std::pair<double, double>> qs;
  for (double q : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const double sb = 4 * q / (1 + std::sqrt(1 - q));  // regime boundary
    for (double s : {0.0, q, -q, sb * (1 - 1e-3), sb * (1 + 1e-3), sb * (1 - 1e-8), 50 * q}) qs.push_back({q, s});
  }
  for (double r : {1e-3, 1e-8, 1e-13}) qs.push_back({1 - r, 0.1});
  for (const auto &p : qs) {
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = p.first;
    sc.sigma_over_fp0 = p.second;
    const truth t = hertz_truth(sc);
    for (int model : {HS_MODEL_CLOSED_FORM, HS_MODEL_QUADRATURE}) {
      hs_solution *sol = nullptr;
      CAPTURE(p.first);
      CAPTURE(p.second);
      CAPTURE(model);
      REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, model, 0, &sol) == HS_OK);
      const double err = true_error(sol, t);
      CAPTURE(err);
      CHECK(err <= summary(sol).error_estimate);
      hs_solution_free(sol);
    }
  }
}

TEST_CASE("HS_MODEL_AUTO: the cheapest model that meets rtol, and the result meets it") {
  for (const auto &c : sweep(8)) {
    const truth t = c.kind == HS_GEOMETRY_HERTZ ? hertz_truth(c.sc) : general_truth(c.kind, c.par, c.sc);
    for (double rtol : {0.1, 1e-3, 1e-6, 1e-10, 1e-13, 1e-15}) {
      // below 1e-10 a flat punch or power law goes to the reference backend
      // (seconds per scene): covered once by the next test case
      if (c.kind != HS_GEOMETRY_HERTZ && rtol < 1e-10) continue;
      hs_solution *sol = nullptr;
      const int st = solve(c.kind, c.par, c.sc, HS_MODEL_AUTO, rtol, &sol);
      CAPTURE(c.kind);
      CAPTURE(c.par);
      CAPTURE(c.sc.Q_over_fP);
      CAPTURE(c.sc.sigma_over_fp0);
      CAPTURE(rtol);
      if (st == HS_ERR_TOLERANCE) {
        // only when no double model and no reference covers the geometry
        CHECK(c.kind != HS_GEOMETRY_HERTZ);
        continue;
      }
      REQUIRE(st == HS_OK);
      const auto s = summary(sol);
      CHECK(s.error_estimate <= rtol);
      const double err = true_error(sol, t);
      CAPTURE(err);
      CAPTURE(s.model);
      CHECK(err <= rtol + t.bound);
      // cheapest: the asymptotic model is used whenever its estimate meets rtol and it
      // resolves both zones (issue 13: an unresolved zone has no relative bound)
      hs_solution *asy = nullptr;
      if (solve(c.kind, c.par, c.sc, HS_MODEL_ASYMPTOTIC, 0, &asy) == HS_OK) {
        const hs_summary A = summary(asy);
        if (A.error_estimate <= rtol && A.d1 > A.zone_resolution && A.d2 > A.zone_resolution)
          CHECK(s.model == HS_MODEL_ASYMPTOTIC);
        hs_solution_free(asy);
      }
      // issue 16: the closed forms wherever their estimate (worst-case, or the
      // a-posteriori one below it) meets rtol, else the reference
      if (c.kind == HS_GEOMETRY_HERTZ && s.model != HS_MODEL_ASYMPTOTIC) {
        core::general_scene<double> g;
        g.a = c.sc.a;
        g.p0 = c.sc.p0;
        g.f = c.sc.f;
        g.Estar = c.sc.E_star;
        g.q = c.sc.Q_over_fP;
        g.s = c.sc.sigma_over_fp0;
        const auto cf = core::solve_hertz<double>(g);
        const auto wc = core::closed_form_estimate(cf.d1() / g.a, cf.d2() / g.a, g.q, g.s, cf.width);
        const auto ap = core::a_posteriori_closed_form(cf);
        const bool meets = (wc.value() <= rtol && wc.unresolved == 0) || (ap.value() <= rtol && ap.unresolved == 0);
        CHECK(s.model == (meets ? HS_MODEL_CLOSED_FORM : HS_MODEL_REFERENCE));
      }
      hs_solution_free(sol);
    }
  }
}

TEST_CASE(
    "HS_MODEL_AUTO below the double models' floor: the reference backend, for the flat punch and the power law too") {
  // d1, d2 certified and rounded to double (error <= 2^-53); energies are
  // left out here (certified MPFR energies of the general path take seconds)
  for (const auto &g :
       std::vector<std::pair<int, double>>{{HS_GEOMETRY_FLAT_ROUNDED, 0.45}, {HS_GEOMETRY_POWER_LAW, 3.0}}) {
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = 0.4;
    sc.sigma_over_fp0 = 0.3;
    truth t = general_truth(g.first, g.second, sc);
    t.energies = false;
    hs_solution *sol = nullptr;
    CAPTURE(g.first);
    // issue 16: the reference where the quadrature's a-posteriori estimate misses
    // rtol too (the power law here meets 1e-15 a posteriori: 6.4e-16; the
    // smallest rtol, 2^-53, sends both to the reference unless double is exact)
    const double rtol = std::ldexp(1.0, -53);
    REQUIRE(solve(g.first, g.second, sc, HS_MODEL_AUTO, rtol, &sol) == HS_OK);
    const auto s = summary(sol);
    {
      core::general_scene<double> gs;
      gs.q = sc.Q_over_fP;
      gs.s = sc.sigma_over_fp0;
      const bool flat = g.first == HS_GEOMETRY_FLAT_ROUNDED;
      const auto pm = core::parametrised_pressure<double>(flat, g.second);
      const auto pw = core::parametrised_pressure<long double>(flat, g.second);
      const auto ap = core::a_posteriori_quadrature(core::solve_general<double>(*pm, gs), *pw);
      CAPTURE(ap.value());
      REQUIRE(ap.value() > rtol);
    }
    CHECK(s.model == HS_MODEL_REFERENCE);
    CHECK(s.error_estimate == std::ldexp(1.0, -53));
    const double err = true_error(sol, t);
    CAPTURE(err);
    CAPTURE(t.bound);
    CHECK(err <= s.error_estimate + t.bound);
    // points go through the reference too: B_x agrees with the double quadrature
    hs_solution *dq = nullptr;
    REQUIRE(solve(g.first, g.second, sc, HS_MODEL_QUADRATURE, 0, &dq) == HS_OK);
    const double x = s.b1 + 0.5 * s.d1;
    double B = 0, Bq = 0;
    REQUIRE(hs_eval_Bx(sol, 1, &x, &B) == HS_OK);
    REQUIRE(hs_eval_Bx(dq, 1, &x, &Bq) == HS_OK);
    CHECK(std::abs(B - Bq) <= 1e-12 * std::abs(B));
    hs_solution_free(dq);
    hs_solution_free(sol);
  }
}

TEST_CASE("model options: contract") {
  hs_scene sc;
  hs_scene_default(&sc);
  hs_solution *sol = nullptr;
  // closed forms exist for Hertz only
  CHECK(solve(HS_GEOMETRY_FLAT_ROUNDED, 0.5, sc, HS_MODEL_CLOSED_FORM, 0, &sol) == HS_ERR_BAD_GEOMETRY);
  // unknown model; rtol outside [2^-53, 0.5] for AUTO
  CHECK(solve(HS_GEOMETRY_HERTZ, 0, sc, 6, 0, &sol) == HS_ERR_BAD_OPTION);
  CHECK(solve(HS_GEOMETRY_HERTZ, 0, sc, -1, 0, &sol) == HS_ERR_BAD_OPTION);
  CHECK(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_AUTO, 1e-17, &sol) == HS_ERR_BAD_OPTION);
  CHECK(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_AUTO, 0.6, &sol) == HS_ERR_BAD_OPTION);
  CHECK(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_AUTO, NAN, &sol) == HS_ERR_BAD_OPTION);
  CHECK(sol == nullptr);
  // a pressure the reference backend does not cover cannot go below double's quadrature
  const double xs[] = {-1, -0.9, -0.5, 0, 0.5, 0.9, 1};
  double ps[7];
  for (int i = 0; i < 7; ++i) ps[i] = std::sqrt(1 - xs[i] * xs[i]);
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_SAMPLES;
  g.n_samples = 7;
  g.sample_x = xs;
  g.sample_p = ps;
  hs_options o;
  hs_options_default(&o);
  o.model = HS_MODEL_AUTO;
  o.rtol = 2e-16;
  CHECK(hs_solve_geometry(&sc, &g, &o, &sol) == HS_ERR_TOLERANCE);
  CHECK(sol == nullptr);
  CHECK(std::string(hs_strerror(HS_ERR_TOLERANCE)).find("tolerance") != std::string::npos);
  o.model = HS_MODEL_REFERENCE;
  o.rtol = 0;
  CHECK(hs_solve_geometry(&sc, &g, &o, &sol) == HS_ERR_BAD_GEOMETRY);
  // a 0.2 caller (options without the model field) gets the default model
  hs_options_default(&o);
  o.struct_size = offsetof(hs_options, model);
  o.model = 12345;  // beyond the caller's struct: must not be read as a model
  REQUIRE(hs_solve(&sc, &o, &sol) == HS_OK);
  CHECK(summary(sol).model == HS_MODEL_CLOSED_FORM);
  hs_solution_free(sol);
  // the 0.2 summary size is still served
  REQUIRE(hs_solve(&sc, nullptr, &sol) == HS_OK);
  hs_summary s;
  std::memset(&s, 0x5a, sizeof s);
  s.struct_size = offsetof(hs_summary, model);
  REQUIRE(hs_solution_summary(sol, &s) == HS_OK);
  CHECK(s.model == 0x5a5a5a5a);  // untouched past the caller's size
  hs_solution_free(sol);
}

TEST_CASE("dimensional power-law and flat-punch input") {
  const double P = 1000, E = 1.15e11, f = 0.6, Q = 300, sg = 2e6, R = 0.05;
  hs_scene h, p, fl;
  REQUIRE(hs_scene_from_hertz_loads(P, R, E, f, Q, sg, &h) == HS_OK);
  // n = 2, A = 1/(2R) is Hertz: a^2 from ~6 roundings (lgamma/exp included),
  // the square root halves them: 4 eps in a, one more rounding in p0 and s
  REQUIRE(hs_scene_from_power_law_loads(P, 1 / (2 * R), 2.0, E, f, Q, sg, &p) == HS_OK);
  const double e4 = 4 * 2.22e-16;
  CHECK(std::abs(p.a / h.a - 1) < e4);
  CHECK(std::abs(p.p0 / h.p0 - 1) < 2 * e4);
  CHECK(std::abs(p.Q_over_fP / h.Q_over_fP - 1) < e4);
  CHECK(std::abs(p.sigma_over_fp0 / h.sigma_over_fp0 - 1) < 2 * e4);
  // b_f = 0 is Hertz
  double beta = -1;
  REQUIRE(hs_scene_from_flat_rounded_loads(P, R, 0.0, E, f, Q, sg, &fl, &beta) == HS_OK);
  CHECK(beta == 0);
  CHECK(std::abs(fl.a / h.a - 1) < e4);
  // general n: the load recomputed from a by independent quadrature of
  // P = (E*/2) int x g'(x)/sqrt(a^2-x^2) dx = E* n A a^n int_0^{pi/2} sin^n(t) dt (Simpson)
  for (double n : {1.3, 2.5, 3.7, 6.0}) {
    const double A = 2e3;
    REQUIRE(hs_scene_from_power_law_loads(P, A, n, E, f, Q, sg, &p) == HS_OK);
    const int m = 20000;
    double sum = 0;
    for (int i = 0; i <= m; ++i) {
      const double t = M_PI / 2 * i / m, w = (i == 0 || i == m) ? 1 : (i % 2 ? 4 : 2);
      sum += w * std::pow(std::sin(t), n);
    }
    const double I = sum * (M_PI / 2 / m) / 3;
    CAPTURE(n);
    CHECK(E * n * A * std::pow(p.a, n) * I == doctest::Approx(P).epsilon(1e-10));
    CHECK(std::abs(p.p0 / (2 * P / (M_PI * p.a)) - 1) < e4);
  }
  // flat punch: P = a^2 g(b_f/a) E*/(4R), g(beta) = pi - 2 asin(beta) - sin(2 asin(beta))
  REQUIRE(hs_scene_from_flat_rounded_loads(P, R, 5e-5, E, f, Q, sg, &fl, &beta) == HS_OK);
  const double ph = std::asin(beta), g = M_PI - 2 * ph - std::sin(2 * ph);
  CHECK(fl.a * fl.a * g * E / (4 * R) == doctest::Approx(P).epsilon(1e-13));
  CHECK(beta * fl.a == doctest::Approx(5e-5).epsilon(1e-14));
  // contract: specific codes, outputs untouched
  hs_scene keep = p;
  CHECK(hs_scene_from_power_law_loads(NAN, 1, 2, E, f, Q, sg, &p) == HS_ERR_NOT_FINITE);
  CHECK(hs_scene_from_power_law_loads(P, 0, 2, E, f, Q, sg, &p) == HS_ERR_BAD_SIZE);
  CHECK(hs_scene_from_power_law_loads(P, 1, 1, E, f, Q, sg, &p) == HS_ERR_BAD_GEOMETRY);
  CHECK(hs_scene_from_power_law_loads(P, 1, 2, E, 0, Q, sg, &p) == HS_ERR_BAD_FRICTION);
  CHECK(hs_scene_from_power_law_loads(P, 1, 2, E, f, f * P, sg, &p) == HS_ERR_GROSS_SLIDING);
  CHECK(hs_scene_from_power_law_loads(P, 1, 2, E, f, Q, sg, nullptr) == HS_ERR_NULL_POINTER);
  CHECK(std::memcmp(&keep, &p, sizeof p) == 0);
  CHECK(hs_scene_from_flat_rounded_loads(P, R, -1, E, f, Q, sg, &fl, &beta) == HS_ERR_BAD_GEOMETRY);
  CHECK(hs_scene_from_flat_rounded_loads(P, 0, 1e-5, E, f, Q, sg, &fl, &beta) == HS_ERR_BAD_SIZE);
  CHECK(hs_scene_from_flat_rounded_loads(P, R, 1e-5, E, f, Q, sg, &fl, nullptr) == HS_ERR_NULL_POINTER);
}

namespace {

// d1, d2 of the MPFR reference at 20 digits for any geometry it solves
// (the general path's certified energies take seconds: energies come from
// long double, as in general_truth)
// false where the reference itself does not solve the scene (counted, skipped)
bool reference_lengths(int kind, double par, const hs_scene &sc, truth &t) {
  hs_ref_scene r;
  hs_ref_scene_default(&r);
  char a[64], p0[64], f[64], E[64], q[64], s[64], p[64];
  std::snprintf(a, 64, "%.45e", sc.a);
  std::snprintf(p0, 64, "%.45e", sc.p0);
  std::snprintf(f, 64, "%.45e", sc.f);
  std::snprintf(E, 64, "%.45e", sc.E_star);
  std::snprintf(q, 64, "%.45e", sc.Q_over_fP);
  std::snprintf(s, 64, "%.45e", sc.sigma_over_fp0);
  std::snprintf(p, 64, "%.45e", par);
  r.geometry = kind;
  r.a = a;
  r.p0 = p0;
  r.f = f;
  r.E_star = E;
  r.Q_over_fP = q;
  r.sigma_over_fp0 = s;
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) r.flat_over_a = p;
  if (kind == HS_GEOMETRY_POWER_LAW) r.exponent = p;
  hs_ref_solution *sol = nullptr;
  if (hs_ref_solve(&r, 20, &sol) != HS_OK) return false;
  auto get = [&](int what) {
    char buf[128];
    int cert = 0;
    REQUIRE(hs_ref_value(sol, what, buf, sizeof buf, nullptr, &cert) == HS_OK);
    const long double v = std::strtold(buf, nullptr);
    CHECK((v == 0 || cert >= 17));
    return v;
  };
  t.d1 = get(HS_REF_D1);
  t.d2 = get(HS_REF_D2);
  hs_ref_solution_free(sol);
  t.bound = std::max(t.bound, 1e-19);
  return true;
}

// The scene categories of bench/estimate_sweep.cpp (issue 13), fewer and with
// another seed: random, Q/fP -> 0, Q/fP -> 1, the regime boundary (Hertz value
// as the centre), small loads (down to 1e-320), large sigma, negative Q.
std::vector<scene_case> issue13_scenes(int kind, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  auto L = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * U(rng)); };
  auto sgn = [&] { return U(rng) < 0.5 ? -1.0 : 1.0; };
  const bool hertz = kind == HS_GEOMETRY_HERTZ;
  std::vector<scene_case> v;
  for (int i = 0; i < n; ++i) {
    scene_case c;
    c.kind = kind;
    // power law kept to n <= 20 here: the cost of F grows with n (docs/models.md)
    c.par = kind == HS_GEOMETRY_FLAT_ROUNDED ? 0.95 * U(rng) : kind == HS_GEOMETRY_POWER_LAW ? 1 + L(-2, 1.28) : 0;
    hs_scene_default(&c.sc);
    c.sc.a = 0.5 + 1.5 * U(rng);
    c.sc.p0 = 0.5 + 1.5 * U(rng);
    c.sc.f = 0.5 + 1.5 * U(rng);
    c.sc.E_star = 0.5 + 1.5 * U(rng);
    double q = 0, s = 0;
    switch (i % 7) {
      case 0: q = 2 * U(rng) - 1, s = sgn() * L(-3, 1.5); break;
      case 1: q = sgn() * L(-12, -2), s = sgn() * std::abs(q) * L(-2, 2); break;
      case 2: q = sgn() * (1 - L(-12, -2)), s = sgn() * L(-3, 1); break;
      case 3: {
        q = sgn() * L(-10, -0.01);
        const double sb = 4 * std::abs(q) / (1 + std::sqrt(1 - std::abs(q)));
        s = std::copysign(sb, q) * (1 + sgn() * (hertz ? L(-12, -1) : L(-3, -1)));
        break;
      }
      case 4:
        q = sgn() * (i % 2 ? L(-320, -30) : L(-30, -8));
        s = sgn() * (i % 2 ? L(-320, -30) : L(-30, -8));
        break;
      // large sigma: Hertz to 1e4, the quadrature to 300 (it overflows from ~800, docs/models.md)
      case 5: q = 0.99 * (2 * U(rng) - 1), s = sgn() * L(1, hertz ? 4 : 2.5); break;
      case 6: q = -U(rng), s = 16 * U(rng) - 8; break;
    }
    c.sc.Q_over_fP = q;
    c.sc.sigma_over_fp0 = s;
    v.push_back(c);
  }
  return v;
}

// Known open (docs/validation.md, "Estimate sweep"): Hertz closed forms in the
// opposite-sign regime at |sigma/fp0| ~ 4.2..56 (excluded here: 3..80), where the
// energies (tanh-sinh terminated at sqrt(eps), or sqrt(rtol), over a zone whose
// B_x has a feature at the scale of the stick width) are off by up to ~4e-12
// against an estimate of ~4e-14, 1.3e-5 against 3.5e-7 at 1 - Q/fP = 6.5e-12, sigma/fp0 = 4.16
// (2.4e-8 against 1.6e-9 at rtol = 1e-10).
// Excluded from the energy check of the reduced sweep below and pinned by the
// should_fail test case after it.
bool hertz_energy_open(const scene_case &c, const hs_summary &s) {
  return c.kind == HS_GEOMETRY_HERTZ && s.regime == HS_REGIME_OPPOSITE_SIGN && std::abs(c.sc.sigma_over_fp0) > 3 &&
         std::abs(c.sc.sigma_over_fp0) < 80;
}

}  // namespace

// Skipped for now: its first run in ctest did not finish within 17 min on the shared
// machine (a scene of the general path, probably AUTO's reference route or a
// long double truth near sliding, is slow), and the flat-punch findings 3 and 4 of
// docs/validation.md ("Estimate sweep") are expected to fail it. Run:
//   build/tests/test_select -tc="issue 13: reduced*" --no-skip -s
TEST_CASE("issue 13: reduced estimate sweep: DEFAULT and AUTO within their estimates on every scene category" *
          doctest::skip()) {
  // Full sweep: scripts/estimate_sweep.sh. Every scene must be solved (the
  // reference solves all of them) and its true error must be within the
  // estimate; AUTO at 1e-10 also within rtol.
  int checked = 0, energies_skipped = 0, reference_failed = 0;
  const std::vector<std::pair<int, int>> plan = {
      {HS_GEOMETRY_HERTZ, 42}, {HS_GEOMETRY_FLAT_ROUNDED, 7}, {HS_GEOMETRY_POWER_LAW, 7}};
  for (const auto &g : plan)
    for (const auto &c : issue13_scenes(g.first, g.second, 1313)) {
      truth t0{0, 0, 0, 0, false, 0};
      if (c.kind == HS_GEOMETRY_HERTZ) t0 = hertz_truth(c.sc);
      else {
        // long double energies where its solver answers (it has no asymptotic fallback for
        // zones below its own resolution: small loads), the reference's d1, d2 always
        try {
          t0 = general_truth(c.kind, c.par, c.sc);
        } catch (const std::exception &) {
          ++energies_skipped;
        }
        if (!reference_lengths(c.kind, c.par, c.sc, t0)) {
          ++reference_failed;
          continue;
        }
      }
      for (const auto &m : std::vector<std::pair<int, double>>{
               {HS_MODEL_DEFAULT, 0}, {HS_MODEL_DEFAULT, 1e-10}, {HS_MODEL_AUTO, 0}, {HS_MODEL_AUTO, 1e-10}}) {
        CAPTURE(c.kind);
        CAPTURE(c.par);
        CAPTURE(c.sc.Q_over_fP);
        CAPTURE(c.sc.sigma_over_fp0);
        CAPTURE(m.first);
        CAPTURE(m.second);
        hs_solution *sol = nullptr;
        REQUIRE(solve(c.kind, c.par, c.sc, m.first, m.second, &sol) == HS_OK);
        const auto s = summary(sol);
        truth t = t0;
        // the reference route of AUTO for the general path: d1, d2 only (its energies take seconds)
        if (s.model == HS_MODEL_REFERENCE && c.kind != HS_GEOMETRY_HERTZ) t.energies = false;
        if (hertz_energy_open(c, s)) t.energies = false, ++energies_skipped;
        const double err = true_error(sol, t);
        CAPTURE(err);
        CAPTURE(s.error_estimate);
        CAPTURE(s.model);
        CHECK(err <= s.error_estimate + t.bound);
        if (m.first == HS_MODEL_AUTO && m.second > 0) {
          CHECK(s.error_estimate <= m.second);
          CHECK(err <= m.second + t.bound);
        }
        ++checked;
        hs_solution_free(sol);
      }
    }
  CHECK(reference_failed <= 2);  // the reference's own NO_CONVERGENCE (small loads, general path)
  CHECK(checked == 4 * (56 - reference_failed));
  CHECK(energies_skipped <= 16);  // the open class and the small loads stay a small part of the set
}

TEST_CASE("issue 13: asymptotic estimate includes rounding: tiny loads are not claimed below eps") {
  // Before: the shape terms vanish with the loads, and the estimate fell to
  // 5e-20 (Q/fP ~ 1e-21) while d, E were off by ~1e-15 in rounding; AUTO at
  // rtol 1e-10 took the asymptotic model with that estimate.
  hs_scene sc;
  hs_scene_default(&sc);
  sc.a = 1.619515213903773;
  sc.p0 = 0.9886594223958195;
  sc.f = 1.5928152471492705;
  sc.E_star = 1.7299812637952618;
  sc.Q_over_fP = -2.1170702187050182e-28;
  sc.sigma_over_fp0 = 2.0267283197786418e-19;
  const truth t = hertz_truth(sc);
  hs_solution *sol = nullptr;
  REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_ASYMPTOTIC, 0, &sol) == HS_OK);
  const auto s = summary(sol);
  const double err = true_error(sol, t);
  CAPTURE(err);
  CAPTURE(s.error_estimate);
  CHECK(err <= s.error_estimate);
  // the floor is 16 eps relative to D_i/d_i >= 1: never below 16 eps
  CHECK(s.error_estimate >= 16 * std::numeric_limits<double>::epsilon());
  hs_solution_free(sol);
}

TEST_CASE("issue 13: HS_MODEL_ASYMPTOTIC bounds every zone it answers, or refuses (unresolved far zones)") {
  // Before: where the edge expansion's first correction was as large as the zone (flat
  // punch b_f/a >= 0.9, power law n = 30, near sliding or under sigma) the model answered
  // with no zone resolved and a resolution r that the true zone missed by up to 1.96 a
  // (the fuzz input tests/fuzz/corpus/asymptotic/asymptotic-unresolved-far-zone: d2 =
  // 0.018 a, r = 0.457 a, the truth 1.97 a); on this grid 61 zones broke |d - d_true| <= r.
  // Now such scenes get HS_ERR_NOT_APPLICABLE. Truth: the default model (the quadrature,
  // a different method) within its own estimate and resolution.
  struct geo {
    int kind;
    double par;
  };
  std::vector<geo> geos;
  for (double b : {0.3, 0.9, 0.95, 0.98, 0.99, 0.995}) geos.push_back({HS_GEOMETRY_FLAT_ROUNDED, b});
  for (double n : {1.2, 3.0, 10.0, 30.0}) geos.push_back({HS_GEOMETRY_POWER_LAW, n});
  struct sc_t {
    geo g;
    double q, s;
  };
  std::vector<sc_t> scenes;
  for (const geo &g : geos)
    for (double q : {0.001, 0.05, 0.5, 0.99})
      for (double s : {-0.5, 0.0, 0.01, 3.0})
        for (double sg : {1.0, -1.0}) scenes.push_back({g, sg * q, s});
  scenes.push_back({{HS_GEOMETRY_FLAT_ROUNDED, 0.9822352941176471}, -0.99770006382255327, -1});  // the fuzz input
  int answered = 0, refused = 0, compared = 0;
  for (const auto &c : scenes) {
    CAPTURE(c.g.kind);
    CAPTURE(c.g.par);
    CAPTURE(c.q);
    CAPTURE(c.s);
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = c.q;
    sc.sigma_over_fp0 = c.s;
    hs_solution *as = nullptr;
    const int st = solve(c.g.kind, c.g.par, sc, HS_MODEL_ASYMPTOTIC, 0, &as);
    if (st == HS_ERR_NOT_APPLICABLE) {
      ++refused;
      continue;
    }
    REQUIRE(st == HS_OK);
    ++answered;
    const auto am = summary(as);
    hs_solution_free(as);
    hs_solution *ds = nullptr;
    if (solve(c.g.kind, c.g.par, sc, HS_MODEL_DEFAULT, 0, &ds) != HS_OK) continue;
    const auto dm = summary(ds);
    hs_solution_free(ds);
    ++compared;
    const double ad[2] = {am.d1, am.d2}, dd[2] = {dm.d1, dm.d2};
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      CAPTURE(ad[i]);
      CAPTURE(dd[i]);
      CAPTURE(am.zone_resolution);
      // |d - d_true| <= est d + r for the model; the truth within its own bound
      const double truth_bound = dm.error_estimate * dd[i] + dm.zone_resolution;
      CHECK(std::abs(ad[i] - dd[i]) <= am.error_estimate * ad[i] + am.zone_resolution + truth_bound);
    }
  }
  MESSAGE("asymptotic model: " << answered << " answered (" << compared << " compared), " << refused << " refused");
  CHECK(compared > 50);  // the check is not vacuous
  CHECK(refused > 0);
}

TEST_CASE("issue 13: Hertz opposite-sign energies at sigma/fp0 ~ 4-50 are within the closed-form estimate") {
  // Reproducers from the sweep (a = p0 = f = E* = 1). With the old tanh-sinh energies (stopped at
  // sqrt(eps)) the error was 4.1e-12 against an estimate of 4.2e-14, and 1.3e-5 against 3.5e-7 next
  // to sliding; the fixed Gauss rules in tau (issue 16, core/hertz_opposite_slip.hpp) meet it.
  struct qs {
    double q, s;
  };
  for (const qs &c : {qs{-0.47459191710000309, 33.064265366394963}, qs{1 - 6.5e-12, 4.16}}) {
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = c.q;
    sc.sigma_over_fp0 = c.s;
    const truth t = hertz_truth(sc);
    hs_solution *sol = nullptr;
    REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_DEFAULT, 0, &sol) == HS_OK);
    const double err = true_error(sol, t);
    CAPTURE(c.q);
    CAPTURE(err);
    CHECK(err <= summary(sol).error_estimate);
    hs_solution_free(sol);
  }
}

namespace {
struct flat_case {
  double bf, q, s, rtol;
};
void check_flat_case(const flat_case &c) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = c.q;
  sc.sigma_over_fp0 = c.s;
  const truth t = general_truth(HS_GEOMETRY_FLAT_ROUNDED, c.bf, sc);
  hs_solution *sol = nullptr;
  CAPTURE(c.bf);
  CAPTURE(c.q);
  REQUIRE(solve(HS_GEOMETRY_FLAT_ROUNDED, c.bf, sc, HS_MODEL_DEFAULT, c.rtol, &sol) == HS_OK);
  const double err = true_error(sol, t);
  const hs_summary S = summary(sol);
  CAPTURE(err);
  CAPTURE(S.error_estimate);
  CHECK(err <= S.error_estimate + t.bound);
  hs_solution_free(sol);
}
}  // namespace

TEST_CASE("issue 13: flat punch reproducers of the estimate sweep (regime boundary, near sliding)") {
  // From bench/results/estimate_sweep_summary.md (a = p0 = f = E* = 1). Before:
  //  (1) regime boundary, DEFAULT at rtol 1e-10: the asymptotic model was preferred because its
  //      estimate (~1e5) was below the quadrature's; its error was 1e10 and a slip direction wrong
  //      (the asymptotic model is now taken only where its estimate is <= 1e-6);
  //  (2) near sliding, DEFAULT at rtol 1e-10: NO_CONVERGENCE on a scene that rtol 0 solves (now
  //      retried at full precision).
  check_flat_case({0.13028743694897107, -9.4435358479099608e-5, -1.8887477619797805e-4, 1e-10});
  check_flat_case({0.28772376914164277, 0.99999999997029587, -0.008318825000170697, 1e-10});
}

TEST_CASE("issue 13: flat punch with a stick end next to the flat's kink, near sliding, within its estimate") {
  // The stick zone (-0.57243, -0.33313) ends 2.7e-3 a from the kink x = -b_f of the pressure, at
  // 1 - |Q/fP| = 9.4e-5: d1 was off by 9.9e-13 against an estimate of 8.0e-14 (pinned by a should_fail
  // test). With the pressure's bracket replaced (its ~4/g cancellation) the error is 3.9e-13, and the
  // estimate now includes the solution's conditioning from its Jacobian (the two side conditions are
  // nearly parallel near sliding): 3.5e-11.
  check_flat_case({0.56968661074729521, -0.99990574901082097, 0.0015827170304935766, 0});
}

// ---- issue 13, item 3: the regime boundary ------------------------------------
namespace {

struct ref_state {
  double d1, d2, e1, e2;
  int dir1, dir2, regime;
};

ref_state reference_state(int kind, double par, double q, double s, bool energies, int digits) {
  hs_ref_scene r;
  hs_ref_scene_default(&r);
  char qs[64], ss[64], ps[64];
  std::snprintf(qs, 64, "%.45e", q);
  std::snprintf(ss, 64, "%.45e", s);
  std::snprintf(ps, 64, "%.45e", par);
  r.geometry = kind;
  r.Q_over_fP = qs;
  r.sigma_over_fp0 = ss;
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) r.flat_over_a = ps;
  hs_ref_solution *sol = nullptr;
  REQUIRE(hs_ref_solve(&r, digits, &sol) == HS_OK);
  auto get = [&](int what) {
    char buf[128];
    int cert = 0;
    REQUIRE(hs_ref_value(sol, what, buf, sizeof buf, nullptr, &cert) == HS_OK);
    const double v = std::strtod(buf, nullptr);
    CHECK((v == 0 || cert >= 17));
    return v;
  };
  hs_ref_summary rs;
  rs.struct_size = sizeof rs;
  REQUIRE(hs_ref_solution_summary(sol, &rs) == HS_OK);
  ref_state t{get(HS_REF_D1), get(HS_REF_D2), 0, 0, rs.slip_dir1, rs.slip_dir2, rs.regime};
  if (energies) t.e1 = get(HS_REF_ENERGY1), t.e2 = get(HS_REF_ENERGY2);
  hs_ref_solution_free(sol);
  return t;
}

// Every claim of a double solution near the boundary against the reference:
// a resolved zone (d > zone_resolution) has the reference's direction and its
// d (and E) within the relative estimate; an unresolved one has direction 0 and
// |d - d_ref| <= zone_resolution; the regime is the reference's unless BOUNDARY
// (one zone unresolved). Returns 1 if the solution reported BOUNDARY.
int check_near_boundary(const hs_solution *sol, const ref_state &t, bool energies) {
  const hs_summary s = summary(sol);
  double E[2] = {0, 0};
  if (energies) REQUIRE(hs_solution_energy(sol, E) == HS_OK);
  const double D[2] = {s.d1, s.d2}, TD[2] = {t.d1, t.d2}, TE[2] = {t.e1, t.e2};
  const int dir[2] = {s.slip_dir1, s.slip_dir2}, tdir[2] = {t.dir1, t.dir2};
  int unresolved = 0;
  CAPTURE(s.zone_resolution);
  CAPTURE(s.error_estimate);
  for (int z = 0; z < 2; ++z) {
    CAPTURE(z);
    CAPTURE(D[z]);
    CAPTURE(TD[z]);
    if (!(D[z] > s.zone_resolution)) {
      ++unresolved;
      CHECK(dir[z] == 0);
      CHECK(std::abs(D[z] - TD[z]) <= s.zone_resolution);
    } else {
      CHECK(dir[z] == tdir[z]);
      CHECK(std::abs(D[z] - TD[z]) <= s.error_estimate * TD[z]);
      if (energies && TE[z] > 0) CHECK(std::abs(E[z] - TE[z]) <= s.error_estimate * TE[z]);
    }
  }
  if (unresolved == 1) CHECK(s.regime == HS_REGIME_BOUNDARY);
  else if (unresolved == 0) CHECK(s.regime == t.regime);
  return s.regime == HS_REGIME_BOUNDARY;
}

}  // namespace

TEST_CASE("issue 13: the issue's regime-boundary scene: BOUNDARY with direction 0, every bound holds") {
  // Before: same sign, d1 = 0, "largest relative error 3.9e-14"; the reference says opposite
  // sign with d1/a = 2.08e-17 and direction +1. The closed forms resolve zone lengths to
  // 16 eps min(1, |q| + |s|/4) a = 2.6e-15 a only: zone 1 is below that.
  const double q = -0.45989658854377635, s = -1.0603308717987363;
  const ref_state t = reference_state(HS_GEOMETRY_HERTZ, 0, q, s, true, 30);
  CHECK(t.regime == HS_REGIME_OPPOSITE_SIGN);
  CHECK(t.dir1 == 1);
  CHECK(std::abs(t.d1 - 2.0783680568091259e-17) <= 1e-30);
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  for (int model : {HS_MODEL_DEFAULT, HS_MODEL_QUADRATURE}) {
    CAPTURE(model);
    hs_solution *sol = nullptr;
    REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, model, 0, &sol) == HS_OK);
    const hs_summary S = summary(sol);
    CHECK(S.regime == HS_REGIME_BOUNDARY);
    CHECK(S.slip_dir1 == 0);
    CHECK(S.slip_dir2 == -1);
    CHECK(S.zone_resolution > 0);
    CHECK(S.zone_resolution < 1e-14);
    check_near_boundary(sol, t, true);
    hs_solution_free(sol);
  }
  // a relative tolerance cannot be met by an unresolved zone: AUTO takes the reference,
  // which resolves it; at rtol = 0 AUTO keeps the most accurate double model
  hs_solution *sol = nullptr;
  REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_AUTO, 1e-10, &sol) == HS_OK);
  hs_summary S = summary(sol);
  CHECK(S.model == HS_MODEL_REFERENCE);
  CHECK(S.regime == HS_REGIME_OPPOSITE_SIGN);
  CHECK(S.slip_dir1 == 1);
  CHECK(S.d1 == t.d1);
  hs_solution_free(sol);
  REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_AUTO, 0, &sol) == HS_OK);
  S = summary(sol);
  CHECK(S.model == HS_MODEL_CLOSED_FORM);
  CHECK(S.regime == HS_REGIME_BOUNDARY);
  hs_solution_free(sol);
  // the 0.4 summary size is still served, without the new field
  REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, HS_MODEL_DEFAULT, 0, &sol) == HS_OK);
  hs_summary old;
  std::memset(&old, 0x5a, sizeof old);
  old.struct_size = offsetof(hs_summary, zone_resolution);
  REQUIRE(hs_solution_summary(sol, &old) == HS_OK);
  CHECK(old.regime == HS_REGIME_BOUNDARY);
  unsigned char tail[sizeof(double)];
  std::memcpy(tail, &old.zone_resolution, sizeof tail);
  for (unsigned char c : tail) CHECK(c == 0x5a);  // untouched past the caller's size
  hs_solution_free(sol);
}

TEST_CASE(
    "issue 13: a scene exactly on the regime boundary (Q/fP = 0.75, sigma/fp0 = 2) is BOUNDARY in every model") {
  // s_b = 4q/(1 + sqrt(1 - q)) = 2 exactly: d1 = 0, b2 = 0 exactly (the reference too)
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = 0.75;
  sc.sigma_over_fp0 = 2;
  for (int model : {HS_MODEL_DEFAULT, HS_MODEL_QUADRATURE, HS_MODEL_REFERENCE}) {
    CAPTURE(model);
    hs_solution *sol = nullptr;
    REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, model, 0, &sol) == HS_OK);
    const hs_summary S = summary(sol);
    CHECK(S.regime == HS_REGIME_BOUNDARY);
    CHECK(S.slip_dir1 == 0);
    CHECK(S.slip_dir2 == 1);
    CHECK(std::abs(S.d1) <= S.zone_resolution);
    hs_solution_free(sol);
  }
}

TEST_CASE("issue 13: scenes near the regime boundary against the reference: every estimate holds") {
  // Hertz: sigma = s_b (1 + delta), |delta| from 1e-17 to 1e-8, q from 1e-6 to 0.99,
  // all four sign combinations; closed forms (DEFAULT) and the quadrature. The issue's
  // sweep found ~8 in 2500 such scenes with the regime wrong and a relative error claimed.
  std::mt19937_64 rng(1313);
  std::uniform_real_distribution<double> U(0, 1);
  int n = 0, boundary = 0;
  for (int i = 0; i < 300; ++i) {
    double q = 0.99 * std::pow(10.0, -6 * U(rng));
    const double sb = 4 * q / (1 + std::sqrt(1 - q));
    double s = sb * (1 + (U(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -17 + 9 * U(rng)));
    if (U(rng) < 0.5) q = -q, s = -s;
    const bool energies = i < 12;  // the reference's opposite-sign energies cost ~0.1-1 s
    const ref_state t = reference_state(HS_GEOMETRY_HERTZ, 0, q, s, energies, 30);
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = q;
    sc.sigma_over_fp0 = s;
    for (int model : {HS_MODEL_DEFAULT, HS_MODEL_QUADRATURE}) {
      CAPTURE(q);
      CAPTURE(s);
      CAPTURE(model);
      hs_solution *sol = nullptr;
      REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, sc, model, 0, &sol) == HS_OK);
      boundary += check_near_boundary(sol, t, energies && model == HS_MODEL_DEFAULT);
      ++n;
      hs_solution_free(sol);
    }
  }
  MESSAGE(n << " solves near the Hertz boundary, " << boundary << " reported BOUNDARY");
  CHECK(boundary > n / 10);  // the sweep reaches below the resolution
  CHECK(boundary < n);       // and above it
}

TEST_CASE("issue 13: flat punch near its regime boundary against the reference") {
  // The boundary s_b(q) of the flat punch (b_f/a = 0.5) by bisection on the double regime,
  // then sigma = s_b (1 + delta), |delta| from 1e-16 to 1e-8; the 20-digit reference's d1, d2.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> U(0, 1);
  int boundary = 0;
  for (int i = 0; i < 6; ++i) {
    double q = 0.05 + 0.9 * U(rng);
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = q;
    double lo = 0, hi = 4;
    for (int it = 0; it < 200 && hi - lo > 1e-16 * hi; ++it) {
      sc.sigma_over_fp0 = (lo + hi) / 2;
      hs_solution *sol = nullptr;
      REQUIRE(solve(HS_GEOMETRY_FLAT_ROUNDED, 0.5, sc, HS_MODEL_DEFAULT, 0, &sol) == HS_OK);
      (summary(sol).regime == HS_REGIME_SAME_SIGN ? lo : hi) = sc.sigma_over_fp0;
      hs_solution_free(sol);
    }
    double s = (lo + hi) / 2 * (1 + (U(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -16 + 8 * U(rng)));
    if (U(rng) < 0.5) q = -q, s = -s;
    sc.Q_over_fP = q;
    sc.sigma_over_fp0 = s;
    CAPTURE(q);
    CAPTURE(s);
    const ref_state t = reference_state(HS_GEOMETRY_FLAT_ROUNDED, 0.5, q, s, false, 20);
    hs_solution *sol = nullptr;
    REQUIRE(solve(HS_GEOMETRY_FLAT_ROUNDED, 0.5, sc, HS_MODEL_DEFAULT, 0, &sol) == HS_OK);
    boundary += check_near_boundary(sol, t, false);
    hs_solution_free(sol);
  }
  MESSAGE(boundary << " of 6 flat-punch scenes reported BOUNDARY");
}

namespace {
// the error of a core solution against the truth over the zones resolved at r
template <class S> double core_error(const S &s, double r, const truth &t, double a) {
  const double d[2] = {s.d1(), s.d2()};
  const long double td[2] = {t.d1, t.d2}, te[2] = {t.e1, t.e2};
  double err = 0;
  for (int i = 0; i < 2; ++i) {
    if (!(d[i] / a > r) || !(td[i] > 0)) continue;
    err = std::max(err, rel(d[i], td[i]));
    if (t.energies) err = std::max(err, rel(s.energy(i + 1), te[i]));
  }
  return err;
}
core::general_scene<double> core_scene(const hs_scene &sc) {
  core::general_scene<double> g;
  g.a = sc.a;
  g.p0 = sc.p0;
  g.f = sc.f;
  g.Estar = sc.E_star;
  g.q = sc.Q_over_fP;
  g.s = sc.sigma_over_fp0;
  return g;
}
}  // namespace

TEST_CASE("issue 16: the a-posteriori estimate bounds the error within 30x, and AUTO at rtol 1e-15 stays in double") {
  // Hertz: the closed forms against the 40-digit reference (d1, d2, E1, E2)
  int in_double = 0, hertz = 0, ratio_checked = 0;
  const double u = std::ldexp(1.0, -53);  // a double result is at best within half an ulp
  for (const auto &c : sweep(24)) {
    if (c.kind != HS_GEOMETRY_HERTZ) continue;
    ++hertz;
    const truth t = hertz_truth(c.sc);
    const auto g = core_scene(c.sc);
    const auto cf = core::solve_hertz<double>(g);
    const auto ap = core::a_posteriori_closed_form(cf);
    CAPTURE(c.sc.Q_over_fP);
    CAPTURE(c.sc.sigma_over_fp0);
    CAPTURE(ap.value());
    // every unresolved zone within the resolution
    for (const auto &p : {std::make_pair(cf.d1(), t.d1), std::make_pair(cf.d2(), t.d2)})
      if (!(p.first / g.a > ap.resolution)) CHECK(std::abs(p.first - p.second) / g.a <= ap.resolution);
    const double err = core_error(cf, ap.resolution, t, g.a);
    CAPTURE(err);
    CHECK(err <= ap.value() + t.bound);
    if (ap.unresolved == 0) {
      CHECK(ap.value() <= 30 * std::max(err, u));
      ++ratio_checked;
    }
    // AUTO at 1e-15: in double exactly where an estimate meets it
    hs_solution *sol = nullptr;
    REQUIRE(solve(HS_GEOMETRY_HERTZ, 0, c.sc, HS_MODEL_AUTO, 1e-15, &sol) == HS_OK);
    const auto s = summary(sol);
    CAPTURE(s.model);
    if (ap.value() <= 1e-15 && ap.unresolved == 0) {
      CHECK(s.model != HS_MODEL_REFERENCE);
      ++in_double;
    }
    if (s.model != HS_MODEL_REFERENCE) {
      CHECK(s.error_estimate <= 1e-15);
      CHECK(true_error(sol, t) <= 1e-15 + t.bound);
    }
    hs_solution_free(sol);
  }
  MESSAGE(in_double << " of " << hertz << " Hertz scenes stay in double at rtol 1e-15");
  CHECK(in_double >= hertz / 2);
  CHECK(ratio_checked >= hertz / 2);
  // flat punch and power law: the full-precision quadrature, d1, d2 against the
  // MPFR reference (20 digits), energies against long double (as above); the
  // first 4 scenes of each (the reference takes ~1 s a scene)
  int general = 0;
  std::map<double, int> per;
  for (const auto &c : sweep(24)) {
    if (c.kind == HS_GEOMETRY_HERTZ || per[c.kind * 10 + c.par]++ >= 4) continue;
    truth t = general_truth(c.kind, c.par, c.sc);
    if (!reference_lengths(c.kind, c.par, c.sc, t)) continue;
    ++general;
    const bool flat = c.kind == HS_GEOMETRY_FLAT_ROUNDED;
    const auto pm = core::parametrised_pressure<double>(flat, c.par);
    const auto pw = core::parametrised_pressure<long double>(flat, c.par);
    const auto g = core_scene(c.sc);
    const auto qs = core::solve_general<double>(*pm, g);
    const auto ap = core::a_posteriori_quadrature(qs, *pw);
    CAPTURE(c.kind);
    CAPTURE(c.par);
    CAPTURE(c.sc.Q_over_fP);
    CAPTURE(c.sc.sigma_over_fp0);
    CAPTURE(ap.value());
    const double err = core_error(qs, ap.resolution, t, g.a);
    CAPTURE(err);
    CHECK(err <= ap.value() + t.bound);
    if (ap.unresolved == 0) CHECK(ap.value() <= 30 * std::max(err, u));
  }
  CHECK(general >= 12);
}
