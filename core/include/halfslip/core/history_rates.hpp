// halfslip core: the rates of a load history at an instant (issue 14), shared by the
// march (history.hpp) and the static solves of advancing segments (static_history.hpp).
//
// Canonical frame: a = p0 = f = E* = 1. At any instant the traction rate on the stick
// zone (c - e, c + e) is that of a fully stuck interval under the load rates (A = Qdot/2,
// B = Sdot/4): qdot = (A - B (x - c)) / sqrt(e^2 - (x - c)^2), so the slip rate at a point
// of a slip zone is that interval's (docs/history.md, "The march").
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "gauss.hpp"
#include "general_panels.hpp"
#include "numerics.hpp"
#include "pressure.hpp"

namespace hs { namespace core {

namespace hdetail {
template <class T> T acosh1p(const T &w) {  // acosh(1 + w), w >= 0, accurate for small w
  using std::log1p;
  using std::sqrt;
  return log1p(w + sqrt(w * (w + 2)));
}
}  // namespace hdetail

// The end coefficient of the traction rate at end i (1: b1 = c + e, 2: -b2 = c - e) under
// the load increments (dq, ds): the rate ~ r_i / sqrt(2 e d) at a distance d from the end.
template <class T> T hist_rate_end(int i, const T &dq, const T &ds, const T &e) {
  return i == 1 ? dq / 2 - ds * e / 4 : dq / 2 + ds * e / 4;
}

// slip rate (per unit load parameter) in zone z (+1 right of the stick zone, -1 left) at x
template <class T> T hist_hdot(int z, const T &A, const T &B, const T &c, const T &e, const T &x) {
  using std::sqrt;
  const T w = z > 0 ? x - (c + e) : (c - e) - x;  // distance from the stick end, >= 0
  if (!(w > 0)) return T(0);
  const T ach = hdetail::acosh1p(w / e);
  const T sq = sqrt(w * (w + 2 * e));
  return 2 * (A * ach + (z > 0 ? -B : B) * sq);
}

// int_lo^hi p(x) hdot(x) dx over a slip zone (n-point Gauss-Legendre panels): x = lo + d (1 -
// cos th)/2 takes both square-root ends; geometric panels in th near the stick end when
// e << d; the pressure's breakpoints are panel ends, and at a graded one (p' log-singular: the
// flat punch's corners) the panels are graded polynomially towards it in geometric layers
// (general_panels.hpp: as the general path's zone panels beyond double). Without that grading
// the (x - k) ln|x - k| term converged like n^-4: flat punch b_f/a = 0.5, a zone across its
// corner, relative errors 9.6e-7, 6.4e-8 and 1.7e-11 at n = 16, 32 (the static solves' orders at
// rtol 1e-8 and at full accuracy until session 23) and 256; graded, rounding from n = 16 or 20
// against tanh-sinh in long double (tests/test_static_history.cpp, "zone energy rates").
template <class T> T hist_zone_rate(const pressure_model<T> &pm, int n, int z, const T &A, const T &B, const T &c,
                                    const T &e, const T &lo, const T &hi, int layers = 4) {
  using std::abs;
  using std::acos;
  using std::cos;
  using std::sin;
  const T d = hi - lo;
  if (!(d > 0)) return T(0);
  const T pi_ = pi<T>();
  // th of a distance w from the stick end
  auto th_of = [&](const T &w) {
    const T wf = z > 0 ? w : d - w;  // distance from lo
    T cth = 1 - 2 * wf / d;
    if (cth > 1) cth = 1;
    if (cth < -1) cth = -1;
    return acos(cth);
  };
  std::vector<std::pair<T, bool>> kinks;
  T w0 = e;  // the stick end's grading starts here
  bool end_kink = false;
  for (const auto &bp : pm.breakpoints()) {
    if (bp.x > lo && bp.x < hi) kinks.push_back({th_of(z > 0 ? bp.x - lo : hi - bp.x), bp.graded});
    // a breakpoint beyond the stick end, in the stick zone, at a distance below e: a singularity at
    // th ~ i 2 sqrt(dist/d), towards which the grading starts (as the general path's grading_scale);
    // at the end to rounding (an end held on a breakpoint), the first panel graded towards it (flat
    // punch, the corner 6e-17 beyond: 1.7e-13 relative at order 16 without)
    const T dist = z > 0 ? lo - bp.x : bp.x - hi;
    if (!(dist >= 0) || !(dist < e)) continue;
    if (dist <= 8 * eps<T>() * (1 + abs(bp.x))) end_kink = end_kink || bp.graded;
    else w0 = std::min(w0, dist);
  }
  // (the stick end is th = 0 for zone 1, th = pi for zone 2)
  std::vector<std::pair<T, bool>> cuts{{T(0), z > 0 && end_kink}, {pi_, z < 0 && end_kink}};
  cuts.insert(cuts.end(), kinks.begin(), kinks.end());
  // grading towards the stick end, without a cut next to a kink (a cut 1 ulp from the flat punch's
  // corner, at w = e = 0.05, left an ungraded panel ending there: 1e-6 relative at order 20); the
  // kink's own cuts stand in for it
  for (T w = std::max(w0, d * eps<T>()); w < d / 4; w *= 8) {
    const T th = th_of(w), from_end = z > 0 ? th : pi_ - th;  // (from the stick end, in th)
    bool near = false;
    for (const auto &k : kinks) near = near || abs(th - k.first) <= from_end / 4;
    if (!near) cuts.push_back({th, false});
  }
  // and geometric layers at the graded kinks: a graded panel as long as the reach to the zone's end
  // squeezed the smooth factors' analyticity (the stick end's near singularity), 2.5e-6 relative at
  // order 16 with the corner 0.05 a from a stick end of width 0.1 a; 3.9e-11 with 4 layers
  gdetail::add_kink_layers(kinks, T(0), pi_, layers, cuts);
  T sum = 0;
  gdetail::for_nodes(gdetail::panels_between(std::move(cuts)), n, [&](const T &th, const T &wt) {
    const T x = lo + d * (1 - cos(th)) / 2;
    sum += wt * (d / 2) * sin(th) * pm.p(x) * hist_hdot(z, A, B, c, e, x);
  });
  return sum;
}

}}  // namespace hs::core
