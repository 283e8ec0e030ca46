// libFuzzer target: the double C ABI. The input bytes become a scene, options
// and evaluation points (raw doubles, so NaN, Inf, denormals, huge values and
// garbage struct sizes all occur). Asserts the ABI contract: a known status,
// a message for it, and on success self-consistent outputs.
#include <halfslip/halfslip.h>

#include "fuzz_input.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace {
using hs_fuzz::reader;
using hs_fuzz::require;
using hs_fuzz::known;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  hs_scene sc;
  hs_scene_default(&sc);
  const uint8_t flags = r.byte();
  sc.Q_over_fP = r.real();
  sc.sigma_over_fp0 = r.real();
  if (flags & 1) sc.a = r.real();
  if (flags & 2) sc.p0 = r.real();
  if (flags & 4) sc.f = r.real();
  if (flags & 8) sc.E_star = r.real();
  if (flags & 16) sc.geometry = r.byte();
  if (flags & 32) sc.struct_size = r.byte();
  hs_options o;
  hs_options_default(&o);
  if (flags & 64) {
    o.rtol = r.real();
    o.max_iterations = int(r.byte()) - 1;
  }
  hs_solution *sol = nullptr;
  const int st = hs_solve(&sc, (flags & 128) ? &o : nullptr, &sol);
  require(known(st) && hs_strerror(st) && *hs_strerror(st));
  if (st != HS_OK) {
    require(sol == nullptr);
    return 0;
  }
  hs_summary sm;
  sm.struct_size = sizeof sm;
  require(hs_solution_summary(sol, &sm) == HS_OK);
  require(std::isfinite(sm.b1) && std::isfinite(sm.b2) && sm.d1 >= 0 && sm.d2 >= 0);
  require(sm.b1 <= sm.a && sm.b2 <= sm.a && sm.b1 + sm.b2 >= 0);
  double x[4], out[4];
  const size_t n = r.byte() % 5;
  for (size_t i = 0; i < n; ++i) x[i] = r.real();
  for (int k = 0; k < 4; ++k) {
    for (size_t i = 0; i < n; ++i) out[i] = 12345.0;
    int (*fn)(const hs_solution *, size_t, const double *, double *) = k == 0   ? hs_eval_Bx
                                                                       : k == 1 ? hs_eval_slip
                                                                       : k == 2 ? hs_eval_work
                                                                                : hs_eval_pressure;
    const int es = fn(sol, n, x, out);
    require(known(es));
    for (size_t i = 0; i < n; ++i) require(es == HS_OK ? std::isfinite(out[i]) : out[i] == 12345.0);
  }
  if (r.byte() & 1) {
    double e[2] = {-1, -1};
    const int es = hs_solution_energy(sol, e);
    require(known(es));
    if (es == HS_OK) require(e[0] >= 0 && e[1] >= 0);
  }
  hs_solution_free(sol);
  // the general-pressure path on the same scene: flat punch or power law with
  // a fuzzed parameter (bounded loads keep one input's cost in milliseconds)
  const uint8_t g = r.byte();
  [&] {
    if ((g & 1) && std::fabs(sc.sigma_over_fp0) < 50 && std::fabs(sc.Q_over_fP) < 0.999) {
      hs_geometry geo;
      hs_geometry_default(&geo);
      geo.kind = (g & 2) ? HS_GEOMETRY_POWER_LAW : HS_GEOMETRY_FLAT_ROUNDED;
      const double par = r.real();
      if (geo.kind == HS_GEOMETRY_POWER_LAW) geo.exponent = par;
      else geo.flat_over_a = par;
      hs_solution *gs = nullptr;
      const int gst = hs_solve_geometry(&sc, &geo, nullptr, &gs);
      require(known(gst));
      if (gst != HS_OK) {
        require(gs == nullptr);
        return;
      }
      hs_summary gm;
      gm.struct_size = sizeof gm;
      require(hs_solution_summary(gs, &gm) == HS_OK);
      require(std::isfinite(gm.b1) && std::isfinite(gm.b2) && gm.d1 >= 0 && gm.d2 >= 0);
      // nothing is integrated when Q = sigma = 0 (stuck), nor by the asymptotic model that the
      // default takes for small loads (issue 13); otherwise the order is reported
      require(gm.regime == HS_REGIME_STUCK || gm.model == HS_MODEL_ASYMPTOTIC || gm.quadrature_order > 0);
      double gx[1] = {0.999 * gm.a}, gout[1];
      // HS_ERR_OVERFLOW is a correct answer when, e.g., E* is denormal
      const int bs = hs_eval_Bx(gs, 1, gx, gout);
      require(known(bs) && (bs != HS_OK || std::isfinite(gout[0])));
      hs_solution_free(gs);
    }
  }();
  // model selection (read last, so that earlier corpus inputs decode as before):
  // any model, rtol from the options above; AUTO must meet rtol when it succeeds
  const uint8_t m = r.byte();
  if (m & 1) {
    hs_options mo = o;
    mo.model = int(m >> 1) % 8 - 1;  // -1 .. 6: unknown values included
    hs_solution *ms = nullptr;
    const int mst = hs_solve(&sc, &mo, &ms);
    require(known(mst) && (mst == HS_OK) == (ms != nullptr));
    if (mst == HS_OK) {
      hs_summary mm;
      mm.struct_size = sizeof mm;
      require(hs_solution_summary(ms, &mm) == HS_OK);
      require(mm.model >= HS_MODEL_ASYMPTOTIC && mm.model <= HS_MODEL_REFERENCE);
      require(mm.error_estimate >= 0);
      if (mo.model == HS_MODEL_AUTO && mo.rtol > 0) require(mm.error_estimate <= mo.rtol);
      hs_solution_free(ms);
    }
  }
  return 0;
}
