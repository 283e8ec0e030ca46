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
#include "testing.hpp"

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

// A double scene as the reference backend's decimal strings (all the digits of each double), kept in
// txt for as long as r is used; par is b_f/a or the exponent for those geometries.
struct ref_text {
  char a[64], p0[64], f[64], E[64], q[64], s[64], p[64];
};
void to_ref_scene(int kind, double par, const hs_scene &sc, ref_text &txt, hs_ref_scene &r) {
  hs_ref_scene_default(&r);
  std::snprintf(txt.a, 64, "%.45e", sc.a);
  std::snprintf(txt.p0, 64, "%.45e", sc.p0);
  std::snprintf(txt.f, 64, "%.45e", sc.f);
  std::snprintf(txt.E, 64, "%.45e", sc.E_star);
  std::snprintf(txt.q, 64, "%.45e", sc.Q_over_fP);
  std::snprintf(txt.s, 64, "%.45e", sc.sigma_over_fp0);
  std::snprintf(txt.p, 64, "%.45e", par);
  r.geometry = kind;
  r.a = txt.a;
  r.p0 = txt.p0;
  r.f = txt.f;
  r.E_star = txt.E;
  r.Q_over_fP = txt.q;
  r.sigma_over_fp0 = txt.s;
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) r.flat_over_a = txt.p;
  if (kind == HS_GEOMETRY_POWER_LAW) r.exponent = txt.p;
}

truth hertz_truth(const hs_scene &sc) {
  hs_ref_scene r;
  ref_text txt;
  to_ref_scene(HS_GEOMETRY_HERTZ, 0, sc, txt, r);
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

int solve_with(const hs_scene &sc, const hs_geometry &g, int model, double rtol, hs_solution **out) {
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  o.rtol = rtol;
  return hs_solve_geometry(&sc, &g, &o, out);
}

int solve(int kind, double par, const hs_scene &sc, int model, double rtol, hs_solution **out) {
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = kind;
  g.flat_over_a = par;
  g.exponent = par;
  return solve_with(sc, g, model, rtol, out);
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
  ref_text txt;
  to_ref_scene(kind, par, sc, txt, r);
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

// ---- issue 13: the reduced estimate sweep ---------------------------------------
// The scene categories of bench/estimate_sweep.cpp (issue 13), fewer and with another
// seed: 0 random, 1 Q/fP -> 0, 2 Q/fP -> 1, 3 the regime boundary, 4 small loads (down
// to 1e-320), 5 large sigma, 6 negative Q. Geometries: Hertz (closed forms), the flat
// punch, the power law, and a user callback returning the Hertz pressure (the general
// solver on a pressure whose reference is the cheap Hertz one).
//
// Why the first version (56 scenes) did not finish in 17 min, measured scene by scene
// (2-core machine, load ~3): not the Hertz scenes (42 in 6.6 s) but a few general-path
// scenes, each for a different reason:
//  - the 20-digit reference of the power law at large sigma: 30 s to more than 40 s a
//    scene (n = 1.1 .. 3.2, sigma/fp0 = 30 .. 84); of the flat punch 2.5 to 5.2 s;
//  - the reference near sliding: 1 to 13 s (1 - |Q/fP| = 5.8e-3 .. 4.5e-11);
//  - power laws with (n - 1)/2 within 1/8 of an integer >= 1, where the pressure is a
//    tanh-sinh integral per value (docs/models.md): near sliding the double solve itself
//    took 12.6 s (n = 6.79, 1 - Q/fP = 1e-6, DEFAULT at rtol 1e-10) and 64 s before
//    NO_CONVERGENCE (1 - Q/fP = 4.5e-11), and its long double truth did not return in 240 s;
//  - n -> 1 (n < 1.25) under sigma: the long double truth threw after 18 s and the
//    reference ran past 40 s (n = 1.025, sigma/fp0 = -41; docs/models.md: n -> 1 is open).
// Hence the design here: the reference supplies d1, d2 of the general path only where it
// costs ~0.1-0.5 s (categories 0, 1, 3, 4, 6); near sliding and at large sigma the truth is
// the same solver in long double (bound 64 eps_LD (1 + a/d_min + 1/w), ~2^9 below the
// double estimate's form); the power law keeps 1.25 <= n <= 20 outside the near-integer
// bands (their 64 s solve was a finding, over the documented 3 s budget, since fixed: see
// "power law near an odd n" below; n -> 1 is documented open; bench/estimate_sweep.cpp keeps
// both). The bands stay out so that the draw of seed 1313 is unchanged: with them (tried
// after the fix) every error claim held, but the draw had two power-law scenes near sliding
// without a truth that DEFAULT answers with NO_CONVERGENCE (n = 1.5585 and 15.2575, neither
// near an odd n; the limit below is 1) and the case took 134 s instead of ~50 s. The boundary of the flat punch and the power
// law is located by bisection on the double regime (the Hertz value used before is not
// theirs: those scenes were 1e-3..1e-1 away from it). A scene without a truth is still
// solved (DEFAULT, rtol 0) and its status counted.
std::vector<scene_case> issue13_scenes(int kind, int n, unsigned seed);
bool power_law_cheap(double n) {
  const double m = (n - 1) / 2;
  return n >= 1.25 && n <= 20 && !(m >= 0.875 && std::abs(m - std::round(m)) < 0.125);
}

// the Hertz pressure p0 sqrt(1 - x^2/a^2) as a user callback (user: the hs_scene)
double hertz_callback(double x, void *user) {
  const hs_scene &sc = *static_cast<const hs_scene *>(user);
  const double u = x / sc.a;
  return sc.p0 * std::sqrt((1 - u) * (1 + u));
}

int solve_case(const scene_case &c, int model, double rtol, hs_solution **out) {
  if (c.kind != HS_GEOMETRY_CALLBACK) return solve(c.kind, c.par, c.sc, model, rtol, out);
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_CALLBACK;
  g.pressure = &hertz_callback;
  g.user = const_cast<hs_scene *>(&c.sc);
  return solve_with(c.sc, g, model, rtol, out);
}

// sigma > 0 where the double quadrature's regime turns from same sign to opposite sign, q > 0
double located_boundary(scene_case c, double q) {
  c.sc.Q_over_fP = q;
  auto regime = [&](double s) {
    c.sc.sigma_over_fp0 = s;
    hs_solution *sol = nullptr;
    if (solve_case(c, HS_MODEL_QUADRATURE, 0, &sol) != HS_OK) return -1;
    const int r = summary(sol).regime;
    hs_solution_free(sol);
    return r;
  };
  const double sh = 4 * q / (1 + std::sqrt(1 - q));
  double lo = 0.5 * sh, hi = 2 * sh;
  for (int k = 0; k < 20 && regime(lo) != HS_REGIME_SAME_SIGN; ++k) lo *= 0.5;
  for (int k = 0; k < 20 && regime(hi) != HS_REGIME_OPPOSITE_SIGN; ++k) hi *= 2;
  for (int k = 0; k < 50 && hi - lo > 4e-16 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    const int r = regime(mid);
    if (r == HS_REGIME_SAME_SIGN) lo = mid;
    else if (r == HS_REGIME_OPPOSITE_SIGN) hi = mid;
    else break;
  }
  return 0.5 * (lo + hi);
}

std::vector<scene_case> issue13_scenes(int kind, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  auto L = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * U(rng)); };
  auto sgn = [&] { return U(rng) < 0.5 ? -1.0 : 1.0; };
  const bool closed = kind == HS_GEOMETRY_HERTZ;
  std::vector<scene_case> v;
  for (int i = 0; i < n; ++i) {
    scene_case c;
    c.kind = kind;
    c.par = 0;
    if (kind == HS_GEOMETRY_FLAT_ROUNDED) c.par = 0.95 * U(rng);
    if (kind == HS_GEOMETRY_POWER_LAW)
      do c.par = 1.25 * std::pow(16.0, U(rng));
      while (!power_law_cheap(c.par));
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
        q = L(-10, -0.01);
        const double delta = sgn() * L(closed ? -17 : -12, -1);
        const double sb = kind == HS_GEOMETRY_HERTZ || kind == HS_GEOMETRY_CALLBACK
                              ? 4 * q / (1 + std::sqrt(1 - q))
                              : located_boundary(c, q);
        s = sb * (1 + delta);
        if (U(rng) < 0.5) q = -q, s = -s;
        break;
      }
      case 4:
        q = sgn() * (i % 2 ? L(-320, -30) : L(-30, -8));
        s = sgn() * (i % 2 ? L(-320, -30) : L(-30, -8));
        break;
      case 5: q = 0.99 * (2 * U(rng) - 1), s = sgn() * L(1, closed ? 4 : 3); break;
      case 6: q = -U(rng), s = 16 * U(rng) - 8; break;
    }
    c.sc.Q_over_fP = q;
    c.sc.sigma_over_fp0 = s;
    v.push_back(c);
  }
  return v;
}

// The reference's d1, d2 (and E1, E2 if asked), directions and regime, read into long
// double; a value is trusted to its certified digits (>= 17 required).
struct ref_truth {
  truth t;
  int dir[2], regime;
};
bool reference_truth(const scene_case &c, int digits, bool energies, ref_truth &out) {
  hs_ref_scene r;
  ref_text txt;
  to_ref_scene(c.kind == HS_GEOMETRY_CALLBACK ? HS_GEOMETRY_HERTZ : c.kind, c.par, c.sc, txt, r);
  hs_ref_solution *sol = nullptr;
  if (hs_ref_solve(&r, digits, &sol) != HS_OK) return false;
  int least = digits;
  auto get = [&](int what) {
    char buf[128];
    int cert = 0;
    REQUIRE(hs_ref_value(sol, what, buf, sizeof buf, nullptr, &cert) == HS_OK);
    const long double v = std::strtold(buf, nullptr);
    if (v != 0) least = std::min(least, cert);
    return v;
  };
  out.t = truth{get(HS_REF_D1), get(HS_REF_D2), 0, 0, energies, 0};
  if (energies) out.t.e1 = get(HS_REF_ENERGY1), out.t.e2 = get(HS_REF_ENERGY2);
  hs_ref_summary rs;
  rs.struct_size = sizeof rs;
  REQUIRE(hs_ref_solution_summary(sol, &rs) == HS_OK);
  out.dir[0] = rs.slip_dir1;
  out.dir[1] = rs.slip_dir2;
  out.regime = rs.regime;
  hs_ref_solution_free(sol);
  CHECK(least >= 17);
  // certified to `least` digits, then read into long double (2^-64)
  out.t.bound = std::max(std::pow(10.0, 1 - least), std::ldexp(1.0, -63));
  return true;
}

int solve_status_only(const scene_case &c) {
  hs_solution *sol = nullptr;
  const int st = solve_case(c, HS_MODEL_DEFAULT, 0, &sol);
  hs_solution_free(sol);
  return st;
}

struct sweep_tally {
  int scenes = 0, solves = 0, resolved = 0, unresolved = 0, boundary = 0, from_reference = 0, from_long_double = 0;
  int energies_checked = 0, auto_reference = 0, callback_tolerance = 0, no_truth = 0, energy_status = 0;
  int solve_status = 0, vague = 0, undecided = 0, no_truth_failed = 0;
  double worst = 0;  // largest error / estimate of a resolved zone
};

// Every claim of one double result against the truth: a resolved zone (d > r) within
// the relative estimate (d and, if the truth has them, E; plus the truth's own bound),
// with the reference's direction; an unresolved one within r of the truth (plus the
// truth's bound) with direction 0; one unresolved zone means BOUNDARY, none the
// reference's regime.
void check_claims(const hs_solution *sol, const hs_summary &s, const truth &t, const int *tdir, int tregime,
                  bool vague_direction_open, sweep_tally &n) {
  double E[2] = {0, 0};
  bool energies = t.energies;
  if (energies && hs_solution_energy(sol, E) != HS_OK) {
    // a status, not a wrong value: counted by the caller (the callback pressure's energies)
    ++n.energy_status;
    energies = false;
  }
  const double D[2] = {s.d1, s.d2};
  const long double TD[2] = {t.d1, t.d2}, TE[2] = {t.e1, t.e2};
  const int dir[2] = {s.slip_dir1, s.slip_dir2};
  int unresolved = 0;
  CAPTURE(s.zone_resolution);
  CAPTURE(s.error_estimate);
  CAPTURE(t.bound);
  for (int z = 0; z < 2; ++z) {
    CAPTURE(z);
    CAPTURE(D[z]);
    CAPTURE(double(TD[z]));
    if (!(D[z] > s.zone_resolution)) {
      ++unresolved;
      ++n.unresolved;
      CHECK(dir[z] == 0);
      CHECK(std::abs(D[z] - TD[z]) <= s.zone_resolution + t.bound * TD[z]);
      continue;
    }
    ++n.resolved;
    if (!(s.error_estimate < 1)) {
      // an estimate of 1 or more: the relative error against the truth is not bounded by it,
      // the documented |d - d_true| <= e d + r is (docs/models.md); the direction is still
      // claimed, except in the open callback class pinned below
      ++n.vague;
      CHECK(std::abs(D[z] - TD[z]) <= s.error_estimate * D[z] + s.zone_resolution + t.bound * TD[z]);
      if (tdir && !vague_direction_open) CHECK(dir[z] == tdir[z]);
      continue;
    }
    if (tdir) CHECK(dir[z] == tdir[z]);
    // a resolved zone that is empty in the truth has no relative bound: it breaks the claim
    CHECK(TD[z] > 0);
    if (!(TD[z] > 0)) continue;
    const double ed = rel(D[z], TD[z]);
    CHECK(ed <= s.error_estimate + t.bound);
    double worst = ed;
    // a zone energy that underflows in the truth is left out (docs/validation.md)
    if (energies && double(TE[z]) > 0) {
      const double ee = rel(E[z], TE[z]);
      CAPTURE(E[z]);
      CAPTURE(double(TE[z]));
      CHECK(ee <= s.error_estimate + t.bound);
      worst = std::max(worst, ee);
      ++n.energies_checked;
    }
    // the ratio only where the truth's own bound is below the estimate (elsewhere, e.g. the
    // asymptotic model's energies of tiny zones against long double, the truth cannot judge)
    if (t.bound < s.error_estimate) n.worst = std::max(n.worst, worst / s.error_estimate);
    else ++n.undecided;
  }
  if (unresolved == 1) CHECK(s.regime == HS_REGIME_BOUNDARY);
  if (unresolved == 0 && tregime >= 0 && (s.error_estimate < 1 || !vague_direction_open))
    CHECK(s.regime == tregime);
  n.boundary += s.regime == HS_REGIME_BOUNDARY;
}

}  // namespace

TEST_CASE("issue 13: reduced estimate sweep: DEFAULT and AUTO within their estimates on every scene category" * HS_LONG) {
  // Full sweep: scripts/estimate_sweep.sh (docs/validation.md, "Estimate sweep").
  // Models: DEFAULT and AUTO, each at rtol 0 and 1e-10. Truths: Hertz and the callback
  // (Hertz pressure): the reference at 25 digits with energies; flat punch and power law:
  // see the comment above issue13_scenes.
  const std::vector<std::pair<int, double>> models = {
      {HS_MODEL_DEFAULT, 0}, {HS_MODEL_DEFAULT, 1e-10}, {HS_MODEL_AUTO, 0}, {HS_MODEL_AUTO, 1e-10}};
  const std::vector<std::pair<int, int>> plan = {{HS_GEOMETRY_HERTZ, 140},
                                                {HS_GEOMETRY_CALLBACK, 28},
                                                {HS_GEOMETRY_FLAT_ROUNDED, 42},
                                                {HS_GEOMETRY_POWER_LAW, 42}};
  std::map<int, sweep_tally> tally;
  for (const auto &g : plan) {
    const auto scenes = issue13_scenes(g.first, g.second, 1313);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const scene_case &c = scenes[i];
      const int cat = int(i % 7);
      sweep_tally &n = tally[c.kind];
      CAPTURE(c.kind);
      CAPTURE(cat);
      CAPTURE(c.par);
      CAPTURE(c.sc.a);
      CAPTURE(c.sc.p0);
      CAPTURE(c.sc.f);
      CAPTURE(c.sc.E_star);
      CAPTURE(c.sc.Q_over_fP);
      CAPTURE(c.sc.sigma_over_fp0);
      ref_truth rt;
      rt.regime = -1;
      bool have_ref = false;
      const bool general = c.kind == HS_GEOMETRY_FLAT_ROUNDED || c.kind == HS_GEOMETRY_POWER_LAW;
      if (!general) {
        REQUIRE(reference_truth(c, 25, true, rt));
        have_ref = true;
      } else {
        // energies (and, near sliding and at large sigma, d1, d2) from long double
        truth ld{0, 0, 0, 0, false, 0};
        bool have_ld = true;
        try {
          ld = general_truth(c.kind, c.par, c.sc);
        } catch (const std::exception &) {
          have_ld = false;  // its solver has no asymptotic fallback: zones below its resolution
        }
        if (cat == 2 || cat == 5) {
          if (!have_ld) {
            ++n.no_truth;
            n.no_truth_failed += solve_status_only(c) != HS_OK;
            continue;
          }
          rt.t = ld;
        } else {
          if (!reference_truth(c, 20, false, rt)) {
            ++n.no_truth;
            n.no_truth_failed += solve_status_only(c) != HS_OK;
            continue;
          }
          have_ref = true;
          if (have_ld) rt.t.e1 = ld.e1, rt.t.e2 = ld.e2, rt.t.energies = true, rt.t.bound = std::max(rt.t.bound, ld.bound);
        }
      }
      ++n.scenes;
      (have_ref ? n.from_reference : n.from_long_double)++;
      for (const auto &m : models) {
        CAPTURE(m.first);
        CAPTURE(m.second);
        hs_solution *sol = nullptr;
        const int st = solve_case(c, m.first, m.second, &sol);
        // a callback pressure has no reference route: AUTO may refuse a tolerance that an
        // unresolved zone (regime boundary) or the quadrature's floor does not meet
        if (c.kind == HS_GEOMETRY_CALLBACK && m.first == HS_MODEL_AUTO && m.second > 0 && st == HS_ERR_TOLERANCE) {
          ++n.callback_tolerance;
          continue;
        }
        if (st != HS_OK) {
          // the callback pressure at loads below ~1e-100: no double model answers (found here)
          if (c.kind == HS_GEOMETRY_CALLBACK && cat == 4 && st == HS_ERR_NOT_APPLICABLE) ++n.solve_status;
          else CHECK(st == HS_OK);
          continue;
        }
        const hs_summary s = summary(sol);
        CAPTURE(s.model);
        truth t = rt.t;
        // AUTO's reference route on the general path: d1, d2 (its energies take seconds)
        if (s.model == HS_MODEL_REFERENCE) {
          ++n.auto_reference;
          if (general) t.energies = false;
        }
        check_claims(sol, s, t, have_ref ? rt.dir : nullptr, have_ref ? rt.regime : -1,
                     c.kind == HS_GEOMETRY_CALLBACK, n);
        if (m.first == HS_MODEL_AUTO && m.second > 0) CHECK(s.error_estimate <= m.second);
        ++n.solves;
        hs_solution_free(sol);
      }
    }
  }
  for (const auto &k : tally) {
    const sweep_tally &n = k.second;
    MESSAGE("geometry " << k.first << ": " << n.scenes << " scenes (" << n.from_reference << " reference, "
                        << n.from_long_double << " long double truths; " << n.no_truth << " without a truth, "
                        << n.no_truth_failed << " of them not solved by DEFAULT), "
                        << n.solves << " solves, " << n.resolved << " resolved zones (" << n.energies_checked
                        << " with energies), " << n.unresolved << " unresolved, " << n.boundary << " BOUNDARY, "
                        << n.auto_reference << " AUTO reference routes, " << n.callback_tolerance
                        << " callback TOLERANCE, " << n.solve_status << " callback NOT_APPLICABLE, "
                        << n.energy_status << " energies refused, " << n.vague << " resolved zones with estimate >= 1, "
                        << n.undecided << " zones the truth cannot judge; worst error/estimate " << n.worst);
  }
  // every geometry reaches every kind of claim
  for (int kind : {HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW, HS_GEOMETRY_CALLBACK}) {
    CAPTURE(kind);
    const sweep_tally &n = tally[kind];
    // no truth: the reference's own NO_CONVERGENCE at loads below ~1e-60 on the general path
    // (and once at sigma/fp0 = 7.3), long double near sliding (1 - |Q/fP| <= 1.4e-10); 4 and 3
    // (5 and 4 before the near-sliding round of issue 13, whose long double solves one more each)
    CHECK(n.no_truth <= 4);
    // DEFAULT answers them all. Until the near-sliding round it gave NO_CONVERGENCE (and so
    // did long double) on one each: the flat punch b_f/a = 0.80 at 1 - Q/fP = 4.5e-11,
    // sigma/fp0 = 0.018 and the power law n = 9.875 at 1 + Q/fP = 1.4e-10, sigma/fp0 = -2.2
    // (found here, docs/validation.md; now checked against the reference in "near sliding" below)
    CHECK(n.no_truth_failed == 0);
    CHECK(n.resolved > 4 * n.scenes);
    CHECK(n.unresolved > 0);
    CHECK(n.energies_checked > 2 * n.scenes);
    CHECK(n.worst <= 1);
  }
  // the callback's statuses (found by this sweep, docs/validation.md): energies refused with
  // NO_CONVERGENCE next to the regime boundary and for zones below ~1e-6 a (17 of 92 solves),
  // NOT_APPLICABLE at loads below ~1e-20 (3 scenes x 4 solves); kept from growing unnoticed
  CHECK(tally[HS_GEOMETRY_CALLBACK].energy_status <= 17);
  CHECK(tally[HS_GEOMETRY_CALLBACK].solve_status <= 12);
  for (int kind : {HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW}) {
    CAPTURE(kind);
    CHECK(tally[kind].energy_status == 0);
    CHECK(tally[kind].solve_status == 0);
  }
}

TEST_CASE("issue 13: near sliding, the general double solver answers within its estimate (reference truths)") {
  // Before: HS_ERR_NO_CONVERGENCE from DEFAULT and from AUTO on every scene here (the
  // first two are the sweep's no-truth scenes above, the third the power law near odd n of
  // docs/models.md, the fourth from the near-sliding sweep of tests/test_stability.cpp). Newton at the order the tolerance gives (16) stalled where that
  // order's residual jumps or is off (the moment condition is ~1e-11 near sliding), and
  // for the flat punch the starts put the stick zone in the flat part. Truths: the
  // reference backend, `halfslip solve --geometry G ... --digits 20 --no-energy` (25 for
  // the first), certified digits as printed; energies against long double.
  struct near_case {
    int kind;
    double par, q, s;
    const char *d1, *d2;
  };
  const near_case cases[] = {
      {HS_GEOMETRY_FLAT_ROUNDED, 0.8, 0.999999999955, 0.018, "1.995294395797927650408973e-01",
       "1.800466231927749215768497e+00"},
      {HS_GEOMETRY_POWER_LAW, 9.875, -0.99999999986, -2.2, "1.3632481371067564530e-01", "1.8636652321788179879e+00"},
      {HS_GEOMETRY_POWER_LAW, 6.79, 0.999999999955, 1, "2.8140088007283800589e-01", "1.7185896669441237723e+00"},
      {HS_GEOMETRY_FLAT_ROUNDED, 0.95, 0.9999999999999, 1, "4.6669960750874423544e-02",
       "1.9533299662559450453e+00"},
  };
  for (const near_case &k : cases) {
    scene_case c;
    c.kind = k.kind;
    c.par = k.par;
    hs_scene_default(&c.sc);
    c.sc.Q_over_fP = k.q;
    c.sc.sigma_over_fp0 = k.s;
    CAPTURE(k.kind);
    CAPTURE(k.par);
    CAPTURE(k.q);
    CAPTURE(k.s);
    const long double T[2] = {std::strtold(k.d1, nullptr), std::strtold(k.d2, nullptr)};
    const truth ld = general_truth(c.kind, c.par, c.sc);
    const long double TE[2] = {ld.e1, ld.e2};
    for (int model : {HS_MODEL_DEFAULT, HS_MODEL_AUTO}) {
      CAPTURE(model);
      hs_solution *sol = nullptr;
      const int st = solve_case(c, model, 0, &sol);
      REQUIRE(st == HS_OK);
      const hs_summary s = summary(sol);
      CAPTURE(s.error_estimate);
      CAPTURE(s.zone_resolution);
      CHECK(s.model == HS_MODEL_QUADRATURE);  // double answers: no reference route
      CHECK(s.d1 > s.zone_resolution);  // both zones resolved
      CHECK(s.d2 > s.zone_resolution);
      CHECK(s.error_estimate < 1e-6);
      double E[2];
      REQUIRE(hs_solution_energy(sol, E) == HS_OK);
      const double D[2] = {s.d1, s.d2};
      for (int z = 0; z < 2; ++z) {
        CAPTURE(z);
        CAPTURE(D[z]);
        CAPTURE(double(T[z]));
        CAPTURE(E[z]);
        CAPTURE(double(TE[z]));
        CHECK(rel(D[z], T[z]) <= s.error_estimate);
        CHECK(rel(E[z], TE[z]) <= s.error_estimate + ld.bound);
      }
      hs_solution_free(sol);
    }
  }
}

TEST_CASE("issue 13: callback (Hertz pressure) near its regime boundary: a zone below the solve's conditioning is "
          "unresolved, not given a direction") {
  // Found by the reduced sweep above: the general solver on a callback returning the Hertz
  // pressure, 1.4e-16 above the regime boundary (sigma = s_b (1 + delta)). The reference:
  // opposite sign, d1 = 8.63e-19 (units of a), direction +1. DEFAULT (the quadrature) gives
  // d1 = 8.70e-12. Its solve's conditioning bounds |d_i - d_i,true| by ~3.5e-8 a, but the
  // resolution left it out (3.5e-15): zone 1 was reported resolved, same sign, direction -1,
  // error_estimate 1.2e4 (a relative error of 1.0e7 against the truth; pinned by a
  // should_fail test until session 12). The resolution now takes the conditioning: the zone
  // is unresolved (direction 0, regime BOUNDARY) and the estimate covers zone 2.
  scene_case c;
  c.kind = HS_GEOMETRY_CALLBACK;
  c.par = 0;
  hs_scene_default(&c.sc);
  c.sc.a = 0.97193189851012163;
  c.sc.p0 = 1.62000321920526;
  c.sc.f = 0.50789612459327205;
  c.sc.E_star = 1.8171087039050142;
  c.sc.Q_over_fP = 3.9699871353655001e-07;
  c.sc.sigma_over_fp0 = 7.9399750587355301e-07;
  ref_truth rt;
  REQUIRE(reference_truth(c, 25, false, rt));
  CHECK(rt.dir[0] == 1);
  hs_solution *sol = nullptr;
  REQUIRE(solve_case(c, HS_MODEL_DEFAULT, 0, &sol) == HS_OK);
  const hs_summary s = summary(sol);
  CAPTURE(s.d1);
  CAPTURE(s.d2);
  CAPTURE(s.zone_resolution);
  CAPTURE(s.error_estimate);
  CAPTURE(double(rt.t.d1));
  CAPTURE(double(rt.t.d2));
  // the bound |d - d_true| <= e d + r holds for both zones
  CHECK(std::abs(s.d1 - double(rt.t.d1)) <= s.error_estimate * s.d1 + s.zone_resolution);
  CHECK(std::abs(s.d2 - double(rt.t.d2)) <= s.error_estimate * s.d2 + s.zone_resolution);
  // zone 1 is within the resolution of empty: no direction claimed, regime BOUNDARY
  CHECK(s.d1 <= s.zone_resolution);
  CHECK(s.slip_dir1 == 0);
  CHECK(s.regime == HS_REGIME_BOUNDARY);
  // zone 2 is resolved, with the truth's direction
  CHECK(s.d2 > s.zone_resolution);
  CHECK(s.slip_dir2 == rt.dir[1]);
  CHECK(s.error_estimate < 1);
  hs_solution_free(sol);
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

TEST_CASE("issue 13: power law near an odd n, near sliding (n = 6.79): solves, within its estimate") {
  // (n - 1)/2 = 2.895, within 1/8 of 3: the pressure was a tanh-sinh integral per value and
  // the double solve at 1 - Q/fP = 1e-6 took 12.6 s (estimate sweep, DEFAULT at rtol 1e-10; the
  // sweep's scene's sigma was not recorded; the CLI: 6.2 s at sigma/fp0 = 1), its long double
  // truth did not return in 240 s. Now F is a series and 3 steps of a recurrence
  // (power_law_pressure::F_near_int): 0.3 s. The scenes: a = p0 = f = E* = 1, sigma/fp0 in
  // {0, 1, -2.2}; truth: the same solver in long double. (At 1 - Q/fP = 4.5e-11 and sigma/fp0 = 1
  // or -2.2 the solve still ends in NO_CONVERGENCE, now after 0.5-2 s instead of 30-64 s, as it
  // does for n = 6.5 and 7, whose pressure did not change: the general solver near sliding, open.)
  for (double q : {1 - 1e-6}) {
    for (double s : {0.0, 1.0, -2.2}) {
      hs_scene sc;
      hs_scene_default(&sc);
      sc.Q_over_fP = q;
      sc.sigma_over_fp0 = s;
      const truth t = general_truth(HS_GEOMETRY_POWER_LAW, 6.79, sc);
      hs_solution *sol = nullptr;
      CAPTURE(q);
      CAPTURE(s);
      REQUIRE(solve(HS_GEOMETRY_POWER_LAW, 6.79, sc, HS_MODEL_DEFAULT, 1e-10, &sol) == HS_OK);
      const double err = true_error(sol, t);
      const hs_summary S = summary(sol);
      CAPTURE(err);
      CAPTURE(S.error_estimate);
      CAPTURE(t.bound);
      CHECK(err <= S.error_estimate + t.bound);
      MESSAGE("n = 6.79, 1 - Q/fP = " << 1 - q << ", sigma/fp0 = " << s << ": error " << err << ", estimate "
                                      << S.error_estimate);
      hs_solution_free(sol);
    }
  }
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
