// libFuzzer target: the asymptotic path (issue 13): hs_asymptotic_error (the edge
// model against the full Hertz solution) and the asymptotic model HS_MODEL_ASYMPTOTIC
// with its error estimate, for every geometry. Asserts:
//   - hs_asymptotic_error: a known status, the output untouched on an error; on
//     success finite values, d_full = 1 - b/a, pure shear (sigma = 0) or pure bulk
//     (Q = 0) as asked, positive energies, the fractional error as defined, and the
//     full solution agrees with hs_solve at the reported load (d_full is that
//     scene's slip zone, within the closed forms' estimate);
//   - HS_MODEL_ASYMPTOTIC: a known status (HS_ERR_NOT_APPLICABLE where its first
//     correction is as large as a zone: issue 13, corpus input
//     asymptotic-unresolved-far-zone); on success its error estimate bounds its
//     distance from the default model (closed forms or quadrature) for every zone
//     that both resolve, for the zone lengths and the energies (the two estimates
//     and zone resolutions added), and the slip directions of such zones agree.
#include <halfslip/halfslip.h>

#include "fuzz_input.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace {
using hs_fuzz::reader;
using hs_fuzz::known;

void comparison(reader &r, uint8_t flags) {
  const int loading = (flags & 2) ? int(r.byte() % 4) : (flags & 4) ? HS_LOADING_BULK : HS_LOADING_SHEAR;
  const double b = (flags & 8) ? r.real() : 1 - std::pow(10.0, -15 * double(r.byte() << 8 | r.byte()) / 65535);
  hs_asymptotic_comparison c, sentinel;
  std::memset(&sentinel, 0x5A, sizeof sentinel);
  sentinel.struct_size = (flags & 16) ? size_t(r.byte()) : sizeof sentinel;
  c = sentinel;
  const int st = hs_asymptotic_error(loading, b, &c);
  HS_REQUIRE(known(st));
  if (st != HS_OK) {
    HS_REQUIRE(std::memcmp(&c, &sentinel, sizeof c) == 0);
    return;
  }
  HS_REQUIRE(b > 0 && b < 1 && (loading == HS_LOADING_SHEAR || loading == HS_LOADING_BULK));
  for (double v : {c.Q_over_fP, c.sigma_over_fp0, c.d_full, c.d_asymptotic, c.energy_full, c.energy_asymptotic,
                   c.fractional_error})
    HS_REQUIRE(std::isfinite(v));
  // d_full is the full solution's zone at the reported load, which is rounded to double:
  // 1 - b to that load's conditioning (shear: 1 - q = (b/a)^2, dd/dq = 1/(2b); bulk: dd/ds <= 1)
  const double lc = loading == HS_LOADING_SHEAR ? 1 / b : std::fabs(c.sigma_over_fp0);
  HS_REQUIRE(std::fabs(c.d_full - (1 - b)) <= 4 * DBL_EPSILON * (1 - b) + 2 * DBL_EPSILON * (1 + lc));
  HS_REQUIRE(loading == HS_LOADING_SHEAR ? c.sigma_over_fp0 == 0 : c.Q_over_fP == 0);
  HS_REQUIRE(c.d_asymptotic > 0 && c.energy_full > 0 && c.energy_asymptotic > 0);
  HS_REQUIRE(std::fabs(c.fractional_error - (c.energy_asymptotic - c.energy_full) / c.energy_full) <=
          4 * DBL_EPSILON * std::fabs(c.fractional_error) + DBL_MIN);
  // the full solution at that load, through hs_solve
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = c.Q_over_fP;
  sc.sigma_over_fp0 = c.sigma_over_fp0;
  hs_solution *sol = nullptr;
  const int ss = hs_solve(&sc, nullptr, &sol);
  HS_REQUIRE(ss == HS_OK);
  hs_summary sm;
  sm.struct_size = sizeof sm;
  HS_REQUIRE(hs_solution_summary(sol, &sm) == HS_OK);
  hs_solution_free(sol);
  // shear: both zones are d_full long; bulk: one zone is
  const double d = std::fmax(sm.d1, sm.d2);
  // the load is found to give d_full: as close as the closed forms resolve d
  // (their estimate, the load's rounding: dd/dq <= 1/(2 sqrt(1-q)) for shear)
  const double cond = loading == HS_LOADING_SHEAR ? 1 / std::sqrt(std::fmax(1 - std::fabs(c.Q_over_fP), 1e-300)) : 4;
  HS_REQUIRE(std::fabs(d - c.d_full) <= sm.error_estimate * c.d_full + sm.zone_resolution + 8 * DBL_EPSILON * cond);
}

void model(reader &r, uint8_t flags) {
  hs_scene sc;
  hs_scene_default(&sc);
  // small loads, where the edge model is meant to be used, and now and then large ones
  const double big = (flags & 2) ? 0 : 15;
  sc.Q_over_fP = (r.byte() & 1 ? -1 : 1) * std::pow(10.0, -big * double(r.byte()) / 255 - 1e-3);
  sc.sigma_over_fp0 = (r.byte() & 1 ? -1 : 1) * std::pow(10.0, 1 - (big + 1) * double(r.byte()) / 255);
  if (r.byte() & 1) sc.sigma_over_fp0 = 0;
  if (std::fabs(sc.Q_over_fP) >= 0.999) sc.Q_over_fP = std::copysign(0.999, sc.Q_over_fP);
  hs_geometry g;
  hs_geometry_default(&g);
  const uint8_t k = r.byte();
  g.kind = k % 3 == 0 ? HS_GEOMETRY_HERTZ : k % 3 == 1 ? HS_GEOMETRY_FLAT_ROUNDED : HS_GEOMETRY_POWER_LAW;
  g.flat_over_a = 0.99 * double(r.byte()) / 255;
  g.exponent = 1.05 + 30 * double(r.byte()) / 255;
  hs_options o;
  hs_options_default(&o);
  o.model = HS_MODEL_ASYMPTOTIC;
  hs_solution *as = nullptr;
  const int st = hs_solve_geometry(&sc, &g, &o, &as);
  HS_REQUIRE(known(st) && (st == HS_OK) == (as != nullptr));
  if (st != HS_OK) return;
  hs_summary am;
  am.struct_size = sizeof am;
  HS_REQUIRE(hs_solution_summary(as, &am) == HS_OK && am.model == HS_MODEL_ASYMPTOTIC);
  HS_REQUIRE(std::isfinite(am.error_estimate) && am.error_estimate >= 0 && am.zone_resolution >= 0);
  HS_REQUIRE(std::isfinite(am.d1) && std::isfinite(am.d2) && am.d1 >= 0 && am.d2 >= 0);
  double ae[2] = {-1, -1};
  const int aes = hs_solution_energy(as, ae);
  HS_REQUIRE(known(aes));
  hs_solution_free(as);
  o.model = HS_MODEL_DEFAULT;
  hs_solution *ds = nullptr;
  if (hs_solve_geometry(&sc, &g, &o, &ds) != HS_OK) return;
  hs_summary dm;
  dm.struct_size = sizeof dm;
  HS_REQUIRE(hs_solution_summary(ds, &dm) == HS_OK);
  double de[2] = {-1, -1};
  const int des = hs_solution_energy(ds, de);
  hs_solution_free(ds);
  const double est = am.error_estimate + dm.error_estimate * (1 + 2 * am.error_estimate);
  const double ad[2] = {am.d1, am.d2}, dd[2] = {dm.d1, dm.d2};
  const int adir[2] = {am.slip_dir1, am.slip_dir2}, ddir[2] = {dm.slip_dir1, dm.slip_dir2};
  if (std::getenv("HS_FUZZ_DEBUG"))
    std::fprintf(stderr,
                 "kind %d flat %.17g n %.17g q %.17g s %.17g\n asym d %.17g %.17g est %.3g res %.3g E %.17g %.17g\n "
                 "default(model %d) d %.17g %.17g est %.3g res %.3g E %.17g %.17g\n",
                 g.kind, g.flat_over_a, g.exponent, sc.Q_over_fP, sc.sigma_over_fp0, am.d1, am.d2, am.error_estimate,
                 am.zone_resolution, ae[0], ae[1], dm.model, dm.d1, dm.d2, dm.error_estimate, dm.zone_resolution, de[0],
                 de[1]);
  for (int i = 0; i < 2; ++i) {
    const bool both = ad[i] > am.zone_resolution && dd[i] > dm.zone_resolution;
    // lengths: |d_a - d_true| <= max(est_a d, r_a), and likewise for the default model
    HS_REQUIRE(std::fabs(ad[i] - dd[i]) <=
            est * dd[i] * (1 + 2 * dm.error_estimate) + am.zone_resolution + dm.zone_resolution + 4 * DBL_MIN);
    if (!both) continue;
    HS_REQUIRE(adir[i] == ddir[i]);
    if (aes == HS_OK && des == HS_OK)
      HS_REQUIRE(std::fabs(ae[i] - de[i]) <= est * de[i] * (1 + 2 * dm.error_estimate) + 4 * DBL_MIN);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  const uint8_t flags = r.byte();
  if (flags & 1) model(r, flags);
  else comparison(r, flags);
  return 0;
}
