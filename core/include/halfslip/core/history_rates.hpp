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
// e << d; the pressure's breakpoints are panel ends.
template <class T>
T hist_zone_rate(const pressure_model<T> &pm, int n, int z, const T &A, const T &B, const T &c, const T &e,
                 const T &lo, const T &hi) {
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
  std::vector<T> cuts{T(0), pi_};
  // grading towards the stick end
  for (T w = std::max(e, d * eps<T>()); w < d / 4; w *= 8) cuts.push_back(th_of(w));
  for (const auto &bp : pm.breakpoints()) {
    if (bp.x > lo && bp.x < hi) cuts.push_back(th_of(z > 0 ? bp.x - lo : hi - bp.x));
  }
  std::sort(cuts.begin(), cuts.end());
  const auto rule = gauss_legendre<T>(n);
  T sum = 0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const T a = cuts[k], b = cuts[k + 1];
    if (!(b > a)) continue;
    const T hw = (b - a) / 2, mid = (a + b) / 2;
    for (size_t j = 0; j < rule->x.size(); ++j) {
      const T th = mid + hw * rule->x[j];
      const T x = lo + d * (1 - cos(th)) / 2;
      sum += hw * rule->w[j] * (d / 2) * sin(th) * pm.p(x) * hist_hdot(z, A, B, c, e, x);
    }
  }
  return sum;
}

}}  // namespace hs::core
