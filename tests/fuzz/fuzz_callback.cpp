// libFuzzer target: callback pressures through the C ABI (hs_solve_geometry with
// HS_GEOMETRY_CALLBACK, issue 13). The input bytes give the scene (a, loads), the
// options and a pressure p(x) = A sqrt(1 - t^2) (1 + c1 t + ... + c4 t^4), t = x/a,
// with an optional narrow dip (which may go below zero anywhere inside the contact)
// and an optional poisoned value (NaN, Inf, a negative or a raw double) on a small
// interval. Asserts:
//   - a known status; a handle exactly on HS_OK;
//   - a value the solve met that is negative or not finite, at |x| < a, fails the solve;
//   - on success: finite zones in [0, 2a], p0 > 0, energies finite and >= 0, and
//     hs_eval_pressure equal to the callback's value (to rounding);
//   - a pure Hertz-shaped callback agrees with the Hertz closed forms (hs_solve with
//     p0 = A) within the two error estimates and zone resolutions.
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

struct shape {
  double a = 1, A = 1, c[4] = {0, 0, 0, 0};
  double dip_x = 0, dip_w = 0, dip_depth = 0;  // dip: A * depth * hat((x - dip_x)/dip_w)
  double poison_x = 0, poison_w = 0, poison = 0;
  bool hertz = true;
  // what the solve met
  bool met_bad = false;
  long calls = 0;
  double value(double x) const {
    const double t = x / a;
    const double s = 1 - t * t;
    double v = A * std::sqrt(s > 0 ? s : 0) * (1 + t * (c[0] + t * (c[1] + t * (c[2] + t * c[3]))));
    if (dip_w > 0) {
      const double h = 1 - std::fabs(x - dip_x) / dip_w;
      if (h > 0) v -= A * dip_depth * h;
    }
    if (poison_w > 0 && std::fabs(x - poison_x) < poison_w) v = poison;
    return v;
  }
};

double pressure(double x, void *user) {
  auto *s = static_cast<shape *>(user);
  const double v = s->value(x);
  ++s->calls;
  if (std::fabs(x) < s->a && !(v >= 0)) s->met_bad = true;
  return v;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  const uint8_t flags = r.byte();
  shape sh;
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = r.ranged(1.0);
  sc.sigma_over_fp0 = r.ranged(50.0);
  if (flags & 1) sc.a = std::pow(10.0, r.ranged(12.0));
  sh.a = sc.a;
  if (flags & 2) sh.A = std::pow(10.0, r.ranged(12.0));
  if (flags & 4) {
    sh.hertz = false;
    for (double &c : sh.c) c = r.ranged(2.0);
  }
  if (flags & 8) {
    sh.hertz = false;
    sh.dip_x = sc.a * r.ranged(1.0);
    sh.dip_w = sc.a * std::pow(10.0, -8 * double(r.byte()) / 255);
    sh.dip_depth = r.ranged(2.0);
  }
  if (flags & 16) {
    sh.hertz = false;
    sh.poison_x = sc.a * r.ranged(1.0);
    sh.poison_w = sc.a * std::pow(10.0, -10 * double(r.byte()) / 255);
    const uint8_t k = r.byte();
    sh.poison = k % 4 == 0 ? NAN : k % 4 == 1 ? INFINITY : k % 4 == 2 ? -sh.A * 1e-3 : r.real();
  }
  hs_options o;
  hs_options_default(&o);
  if (flags & 32) {
    const uint8_t m = r.byte();
    o.model = m % 3 == 0 ? HS_MODEL_DEFAULT : m % 3 == 1 ? HS_MODEL_QUADRATURE : HS_MODEL_ASYMPTOTIC;
    o.rtol = (m & 8) ? std::pow(10.0, -2 - 13 * double(r.byte()) / 255) : 0;
  }
  if (flags & 64) sc.f = std::pow(10.0, r.ranged(3.0));

  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_CALLBACK;
  g.pressure = pressure;
  g.user = &sh;
  hs_solution *sol = nullptr;
  const int st = hs_solve_geometry(&sc, &g, &o, &sol);
  if (std::getenv("HS_FUZZ_DEBUG"))
    std::fprintf(stderr, "q %.17g s %.17g status %d, %ld callback calls\n", sc.Q_over_fP, sc.sigma_over_fp0, st,
                 sh.calls);
  HS_REQUIRE(known(st) && (st == HS_OK) == (sol != nullptr));
  if (sh.met_bad) HS_REQUIRE(st != HS_OK);
  if (st != HS_OK) return 0;

  hs_summary sm;
  sm.struct_size = sizeof sm;
  HS_REQUIRE(hs_solution_summary(sol, &sm) == HS_OK);
  HS_REQUIRE(std::isfinite(sm.p0) && sm.p0 > 0 && sm.a == sc.a);
  HS_REQUIRE(std::isfinite(sm.d1) && std::isfinite(sm.d2) && sm.d1 >= 0 && sm.d2 >= 0 && sm.d1 <= 2 * sm.a &&
          sm.d2 <= 2 * sm.a);
  HS_REQUIRE(std::isfinite(sm.error_estimate) && sm.error_estimate >= 0);
  double e[2] = {-1, -1};
  const int es = hs_solution_energy(sol, e);
  HS_REQUIRE(known(es));
  if (es == HS_OK) HS_REQUIRE(std::isfinite(e[0]) && std::isfinite(e[1]) && e[0] >= 0 && e[1] >= 0);
  // the pressure the solution reports is the callback's (points where it is valid)
  double x[3] = {sc.a * r.ranged(1.0), sc.a * r.ranged(1.0), 0}, px[3] = {0, 0, 0};
  const int ps = hs_eval_pressure(sol, 3, x, px);
  HS_REQUIRE(known(ps));
  if (ps == HS_OK)
    for (int i = 0; i < 3; ++i) {
      const double v = sh.value(x[i]);
      if (std::isfinite(v) && v >= 0 && std::fabs(x[i]) < sc.a)
        HS_REQUIRE(std::fabs(px[i] - v) <= 8 * DBL_EPSILON * v + DBL_MIN);
    }
  // a Hertz-shaped callback against the Hertz closed forms
  if (sh.hertz && o.model != HS_MODEL_ASYMPTOTIC) {
    hs_scene hz = sc;
    hz.p0 = sh.A;
    hs_solution *hsol = nullptr;
    if (hs_solve(&hz, nullptr, &hsol) == HS_OK) {
      hs_summary hm;
      hm.struct_size = sizeof hm;
      HS_REQUIRE(hs_solution_summary(hsol, &hm) == HS_OK);
      const double est = sm.error_estimate + hm.error_estimate, res = sm.zone_resolution + hm.zone_resolution;
      HS_REQUIRE(std::fabs(sm.d1 - hm.d1) <= est * hm.d1 + res + 4 * DBL_EPSILON * sc.a);
      HS_REQUIRE(std::fabs(sm.d2 - hm.d2) <= est * hm.d2 + res + 4 * DBL_EPSILON * sc.a);
      HS_REQUIRE(std::fabs(sm.p0 - hm.p0) <= 1e-12 * hm.p0);
      hs_solution_free(hsol);
    }
  }
  hs_solution_free(sol);
  return 0;
}
