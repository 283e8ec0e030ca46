// halfslip core: the Cauchy integrals of a contact state at any precision
// (the reference backend's tractions and stresses; docs/fields.md).
//
// The same geometry as cauchy_numeric (fields.hpp): the contact is cut at its
// breakpoints, every piece halved, and on each half s = end + h t^2 removes
// the square roots at its end. What follows the precision of T:
//  - the Gauss-Legendre order of each panel (gauss.hpp, runtime orders) is
//    chosen from the Bernstein ellipse through the nearest singularity of the
//    integrand in t (the poles +-tau of the kernel, the images of all the
//    other breakpoints, a kink at t = 0), so that rho^(-2n) is below
//    eps/100: about 1.3 digits10 nodes next to a pole, 0.65 digits10 on the
//    panels graded towards a kink;
//  - the grading towards a kink of p (p' log-singular there, t^3 log t with
//    the weight of ds) reaches 2^-L with L = digits/3 + 4 (the innermost
//    panel then carries below eps of the integral);
//  - the grading towards the neighbouring breakpoint's image, as in
//    traction_panels, and towards the poles down to max(|Im|, 64 eps).
// The distance s - zeta is formed from the nearer exact point of the node's
// half-piece (its end, or the piece's midpoint m at t = 1), never as s - zeta,
// so that a point near the surface keeps the relative accuracy of its depth
// (docs/fields.md, "near the surface").
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "field_panels.hpp"
#include "gauss.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

// Bernstein ellipse parameter of [-1, 1] through u (>= 1; 1 on the segment).
template <class T> T bernstein_rho(const std::complex<T> &u) {
  using std::abs;
  const std::complex<T> w = u + std::sqrt(u - T(1)) * std::sqrt(u + T(1));
  const T r = abs(w);
  return r >= 1 ? r : T(1) / r;
}

// Gauss-Legendre order for a panel whose nearest singularity lies on the
// Bernstein ellipse rho: rho^(-2n) <= eps/100, a multiple of 4, at least 8.
// Above max_order: no_convergence (the loop limit is reported).
template <class T> int graded_order(const T &rho, int max_order) {
  using std::ceil;
  using std::log;
  const T digits = -log(eps<T>()) + log(T(100));
  const T n = ceil(digits / (2 * log(rho)));
  if (!(n <= T(max_order)))
    throw error(status::no_convergence, "field quadrature: Gauss-Legendre order above max_order (a pole too near)");
  const int m = std::max(8, int(static_cast<long>(n)));  // explicit conversion: double and MPFR alike
  return (m + 3) / 4 * 4;
}

// Adds the Cauchy integrals F0, F1 of p and q at zeta (Im zeta >= 0; on the
// real axis only off the contact). dens(s, p, q) gives the densities; pts:
// sorted breakpoints with pts[0] = -a, pts.back() = a; kinks: breakpoints
// where p is log-singular.
template <class T, class G> void cauchy_graded(const G &dens, const std::vector<T> &pts, const std::complex<T> &zeta,
                                               cauchy_pair<T> &P, cauchy_pair<T> &Q, const std::vector<T> &kinks = {},
                                               int max_order = 4096) {
  using std::abs;
  using std::ldexp;
  using std::sqrt;
  const T zr = zeta.real(), zi = zeta.imag();
  const int kink_levels = std::numeric_limits<T>::digits / 3 + 4;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const T lo = pts[i], hi = pts[i + 1];
    if (!(hi > lo)) continue;
    const T m = (lo + hi) / 2;
    for (int side = 0; side < 2; ++side) {
      const T end = side == 0 ? lo : hi;
      const T h = side == 0 ? m - lo : m - hi;  // s = end + h t^2
      const std::complex<T> tau = std::sqrt((zeta - end) / h);
      const bool kink = std::find(kinks.begin(), kinks.end(), end) != kinks.end();
      // the neighbouring breakpoint beyond the end lies at t = +-i r
      T r = -1;
      if (side == 0 && i > 0) r = sqrt((lo - pts[i - 1]) / abs(h));
      if (side == 1 && i + 2 < pts.size()) r = sqrt((pts[i + 2] - hi) / abs(h));
      // the images of the other breakpoints (square roots of the densities):
      // t = sqrt((b - end)/h), the piece's far end at t = sqrt(2), the
      // neighbour beyond the end at +-i r
      std::vector<std::complex<T>> sing;
      for (const T &b : pts)
        if (b != end) {
          const std::complex<T> tb = std::sqrt(std::complex<T>((b - end) / h, T(0)));
          sing.push_back(tb);
          sing.push_back(-tb);
        }
      std::vector<T> cuts{T(0), T(1)};
      if (kink)
        for (int k = 1; k <= kink_levels; ++k) cuts.push_back(ldexp(T(1), -k));
      if (r > 0)
        for (int k = 1; k < 200 && ldexp(T(1), -k) > r / 2; ++k) cuts.push_back(ldexp(T(1), -k));
      const T t0 = std::min(std::max(tau.real(), T(0)), T(1));
      const T delta = abs(tau - t0);
      grade_towards(cuts, t0, delta);
      std::sort(cuts.begin(), cuts.end());
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const T ta = cuts[k], tb = cuts[k + 1];
        const T mid = (ta + tb) / 2, hl = (tb - ta) / 2;
        // the nearest singularity on the Bernstein ellipses of this panel
        auto rho_of = [&](const std::complex<T> &sg) { return bernstein_rho<T>((sg - mid) / hl); };
        T rho = std::min(rho_of(tau), rho_of(-tau));
        for (const std::complex<T> &b : sing) rho = std::min(rho, rho_of(b));
        if (kink && ta > 0) rho = std::min(rho, rho_of(std::complex<T>(0, 0)));
        // the innermost kink panel [0, 2^-L] holds the singularity at its end:
        // its error is bounded by the grading, the order by the others
        if (!(rho > 1)) rho = T(1) + T(1) / 8;
        const auto rule = gauss_legendre<T>(graded_order<T>(rho, max_order));
        const std::size_t n = rule->x.size();
        T p0r = 0, p0i = 0, p1r = 0, p1i = 0, q0r = 0, q0i = 0, q1r = 0, q1i = 0;
        for (std::size_t j = 0; j < n; ++j) {
          const T t = mid + hl * rule->x[j];
          const T s = end + h * t * t;
          const T w = rule->w[j] * hl * 2 * abs(h) * t;
          // s - zeta from the nearer exact point: the end (t <= 1/2) or m (t = 1)
          const T dr = t <= T(0.5) ? T((end - zr) + h * t * t)
                                   : T((m - zr) + h * (((mid - 1) + hl * rule->x[j]) * (t + 1)));
          T pv, qv;
          dens(s, pv, qv);
          // 1/(s - zeta) = (dr + i zi)/(dr^2 + zi^2)
          const T den = 1 / (dr * dr + zi * zi);
          const T rr = dr * den, ri = zi * den;
          const T r2r = rr * rr - ri * ri, r2i = 2 * rr * ri;
          p0r += w * pv * rr;
          p0i += w * pv * ri;
          p1r += w * pv * r2r;
          p1i += w * pv * r2i;
          q0r += w * qv * rr;
          q0i += w * qv * ri;
          q1r += w * qv * r2r;
          q1i += w * qv * r2i;
        }
        P.F0 += std::complex<T>(p0r, p0i);
        P.F1 += std::complex<T>(p1r, p1i);
        Q.F0 += std::complex<T>(q0r, q0i);
        Q.F1 += std::complex<T>(q1r, q1i);
      }
    }
  }
}

}}  // namespace hs::core
