// libFuzzer target: load histories through the C ABI (issue 13 "fuzzing that reaches
// every input", issue 14). The input bytes become a contact (Hertz, flat punch or
// power law), history options and a path of up to 6 vertices: either raw doubles
// (NaN, Inf, |Q| >= fP, garbage) or bytes mapped into the valid range |Q/fP| < 0.95,
// |sigma/fp0| < 2.5, so that the march itself is exercised (reversals, receding
// zones, memory points, Masing returns). Asserts the ABI contract: a known status
// with a message, and on success self-consistent vertices, fields and states. The
// time per input is bounded by libFuzzer's -timeout (scripts/reliability.sh): a
// march that runs away is a failure, as a crash is.
#include <halfslip/halfslip.h>

#include "fuzz_input.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace {
using hs_fuzz::reader;
using hs_fuzz::require;
using hs_fuzz::known;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  const uint8_t flags = r.byte();
  hs_scene sc;
  hs_scene_default(&sc);
  hs_geometry g;
  hs_geometry_default(&g);
  switch (flags & 3) {
    case 1:
      g.kind = HS_GEOMETRY_FLAT_ROUNDED;
      g.flat_over_a = (flags & 4) ? r.real() : 0.05 + 0.9 * (r.byte() / 255.0);
      break;
    case 2:
      g.kind = HS_GEOMETRY_POWER_LAW;
      g.exponent = (flags & 4) ? r.real() : 1.5 + r.byte() / 32.0;
      break;
    default: break;  // Hertz
  }
  hs_history_options o;
  hs_history_options_default(&o);
  // coarse steps and no refinement keep an input fast; raw options probe the checks
  o.rtol = 0;
  o.max_step = 1.0 / (4 << (r.byte() % 3));  // 1/4, 1/8, 1/16
  o.max_steps = 4000;
  if (flags & 8) {
    o.max_step = r.real();
    o.rtol = r.real();
    o.max_steps = int(r.byte()) * 64 - 1;
  }
  if (flags & 16) o.struct_size = r.byte();
  hs_history *h = nullptr;
  const int st = hs_history_new(&sc, &g, &o, &h);
  require(known(st) && hs_strerror(st) && *hs_strerror(st));
  if (st != HS_OK) {
    require(h == nullptr);
    return 0;
  }
  const size_t nv = 1 + r.byte() % 6;
  double q[6], s[6];
  for (size_t i = 0; i < nv; ++i) {
    if (flags & 32) {
      q[i] = r.real();
      s[i] = r.real();
    } else {
      q[i] = r.ranged(0.95);
      s[i] = r.ranged(2.5);
    }
  }
  const int sa = hs_history_add_vertices(h, nv, q, s);
  require(known(sa) && hs_strerror(sa) && *hs_strerror(sa));
  size_t count = 0;
  require(hs_history_vertex_count(h, &count) == HS_OK && count <= nv);
  if (sa == HS_OK) require(count == nv);
  const double a = sc.a;
  for (size_t i = 0; i < count; ++i) {
    hs_history_vertex v;
    v.struct_size = sizeof v;
    require(hs_history_vertex_get(h, i, &v) == HS_OK);
    require(std::isfinite(v.b1) && std::isfinite(v.b2) && v.b1 <= a && v.b2 <= a && v.b1 + v.b2 >= -1e-12 * a);
    require(v.slip_dir1 >= -1 && v.slip_dir1 <= 1 && v.slip_dir2 >= -1 && v.slip_dir2 <= 1);
    require(std::isfinite(v.energy1) && std::isfinite(v.energy2));
    // energy dissipated against friction is never negative (to the march's error: a
    // reversal can leave -1e-8 of a segment's energy; the march refuses a step whose zone
    // dissipates clearly less than zero)
    const double tol = 1e-6 * (std::fabs(v.energy1) + std::fabs(v.energy2)) + 1e-12;
    require(v.energy1 >= -tol && v.energy2 >= -tol);
    require(v.interior_merges >= 0 && v.steps >= 0);
  }
  if (count > 0) {
    const size_t last = count - 1;
    double x[3] = {-0.9 * a, r.ranged(1.0) * a, 0.7 * a}, out[3];
    for (int field : {HS_FIELD_TRACTION, HS_FIELD_SLIP}) {
      const int es = hs_history_eval(h, last, field, 3, x, out);
      require(known(es));
      if (es == HS_OK)
        for (double y : out) require(std::isfinite(y));
    }
    // the traction never exceeds the friction limit f p (to the march's own error)
    double p[3], t[3];
    hs_solution *state = nullptr;
    const int ss = hs_history_state(h, last, &state);
    require(known(ss));
    if (ss == HS_OK) {
      if (hs_eval_pressure(state, 3, x, p) == HS_OK && hs_eval_traction(state, 3, x, t) == HS_OK)
        for (int k = 0; k < 3; ++k) require(std::isfinite(t[k]) && std::fabs(t[k]) <= sc.f * p[k] * (1 + 1e-3) + 1e-9);
      double e[2];
      require(hs_solution_energy(state, e) == HS_ERR_NOT_APPLICABLE);
      hs_solution_free(state);
    }
  }
  hs_history_free(h);
  return 0;
}
