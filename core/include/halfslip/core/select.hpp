// halfslip core: error estimates of the models, for model selection by
// tolerance (issue #5, docs/models.md).
//
// The error of a solution is measured as the largest relative error of the
// slip-zone lengths d1, d2 and of the zone energies E1, E2 (nonempty zones
// only). Each model has an estimate of that error computed from its own
// output, without the exact solution:
//
// * asymptotic edge model (asymptotic.hpp). Per edge i, with phi_e = phi(edge)
//   the edge coefficient and the two load contributions to the zone length
//   dQ = |q|/(2 phi_e), dS = |s|/(4 phi_e) (units of a; d_i = |dQ -+ dS|),
//   D_i = dQ + dS, Dm = max(D_1, D_2), and w_i the largest relative change of
//   phi over the distances D_i/2, D_i, 2 D_i from the edge (the pressure's
//   departure from K_N sqrt(z) over the zone):
//     |d_i,model - d_i| <= C1 Dm^2 + C2 D_i w_i        (absolute, units of a)
//     rel_d,i = that / d_i,model,   rel_E,i = (1 + rel_d,i)^4 - 1
//   The Dm^2 term is the finite-contact/other-edge coupling (Hertz, same sign:
//   exactly |q/(1+sqrt(1-q)) - q/2| ~ q^2/8 = dQ^2/2), the D w term the
//   pressure shape; the power 4 because E ~ K_N^2 d^3 and one more factor
//   for the shape of the slip distribution when the model is far off (the cube
//   alone fell short by 2.2x at rel_d ~ 12). C1 = 2, C2 = 32 are twice
//   the largest coefficients needed over a sweep of 1800 scenes (Hertz, flat
//   punch b_f/a = 0.3, 0.6, 0.9, power law n = 1.5, 3, 6; d/a from 1e-7 to 1;
//   both regimes) against the full solution: measured/estimate <= 0.39 there
//   (bench/asymptotic_sweep.cpp regenerates it; tests/test_select.cpp checks
//   true error <= estimate against the reference on an independent sweep).
//   Plus rounding (issue 13, bench/estimate_sweep.cpp): the model's own
//   arithmetic is good to a few eps, relative to D_i when d_i = |dQ -+ dS|
//   cancels, so rel_d,i gets 16 eps D_i/d_i (>= 16 eps). Without it the
//   estimate fell to 1e-48 at Q/fP ~ 1e-195 (the shape terms vanish with the
//   loads) while d and E were off by up to 5.6 eps (1.2e-15), and AUTO
//   reported the model as meeting rtol below the double floor.
// * Hertz closed forms: b is accurate to a few eps a and d_i to
//   8 eps a + 16 eps d_i (tests/test_reference.cpp); the absolute part comes
//   from d_i = m -+ s/4 (m ~ q/2), so it scales with min(1, |q| + |s|/4):
//     rel_d = 32 eps + 16 eps min(1, |q| + |s|/4) a / d_min,  rel_E = 3 rel_d + 16 eps.
//   (the a/d term is the conditioning of d = m - s/4 near the regime boundary)
// * quadrature (general.hpp) at tolerance rt (0: full precision), with
//   w = (b1 + b2)/a the stick-zone width and acc the pressure's accuracy in
//   units of eps (pressure_model::accuracy_eps: 4 for the closed forms, n for
//   the power law):
//     rel_d = 16 (eps max(1, acc/4) + rt)(1 + a/d_min + 1/max(w, sqrt(1 - |q|)/4)),  rel_E = 3 rel_d.
//   The 1/w term is the conditioning near sliding (w -> 0): at 1 - Q/fP = 1e-8
//   (w = 2e-4) the error in d is 1.2e-12 (tests/test_select.cpp). A stick zone
//   made narrow by a large sigma (w ~ exp(-c s)) is not ill conditioned: the
//   zone sits at the sliding stick point, fixed by q alone (issue 13).
//   Measured against long double: at rt = 0 at most 1.3 eps (1 + a/d_min) in
//   d and 4.1 eps (1 + a/d_min) in E; at rt > 0 far below rt (the order
//   doubles past the tolerance).
// * reference backend rounded to double: half an ulp, 2^-53 (every value is
//   certified to >= 17 digits before it is accepted).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <boost/math/tools/precision.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "asymptotic.hpp"
#include "general.hpp"
#include "hertz.hpp"

namespace hs { namespace core {

template <class T> struct error_estimate {
  T slip_zone{0};  // relative error of d1, d2 (resolved zones)
  T energy{0};     // relative error of E1, E2 (resolved zones)
  // issue 13 (item 3): the model's resolution r, a bound on the absolute error
  // of either zone length (units of a), and the number of zones at or below it
  // (zone_unresolved): those are left out of the relative errors above
  T resolution{0};
  int unresolved{0};
  T value() const {
    using std::max;
    return max(slip_zone, energy);
  }
};

template <class T> T infinite() { return std::numeric_limits<T>::infinity(); }

// Zone resolution (issue 13, item 3). Each model bounds the error of a zone
// length (units of a) by |d_i - d_i,true| <= rel d_i + r: r, its resolution,
// is the absolute part of the bound (the closed forms' d_i = m -+ s/4 cancelling
// at the regime boundary; the quadrature's state resolving lengths to ~eps;
// the asymptotic model's own error). A zone with d_i <= r (d_i = 0 included) is
// not resolved: it may be empty or not, and slip either way (the regime
// boundary, where one zone closes and changes direction). Such a zone is left
// out of the relative estimate, and the C ABI reports it with slip direction 0
// (regime HS_REGIME_BOUNDARY when it is the only one, STUCK when both are).
// r = 0: the model is exact for empty zones (a stuck scene).
template <class T> bool zone_unresolved(const T &d, const T &r) { return r > 0 && !(d > r); }
// d if resolved, else 0 (counted in n)
template <class T> T resolved_zone(const T &d, const T &r, int &n) {
  if (!zone_unresolved(d, r)) return d;
  ++n;
  return T(0);
}
// a length below the spacing of the smallest numbers cannot be resolved
template <class T> T length_floor() { return 4 * boost::math::tools::min_value<T>() * eps<T>(); }

// Floors for lengths and energies near the bottom of T's range (issue 13): a
// zone length d (units of a) is known at best to the spacing of the smallest
// numbers, min_value * eps (the subnormal spacing in double), and a zone energy,
// ~ d^3 in units of f^2 p0^2 a^2/E* (slip ~ d^(3/2) times traction ~ d^(1/2)
// over a length d), reaches that spacing first. Relative error floors of d and
// of E; infinite once d^3 underflows (at sigma/fp0 = 4e-320 the energies were 0
// with an estimate of 2.5e-14).
template <class T> T tiny_length_floor(const T &d) { return 4 * boost::math::tools::min_value<T>() * eps<T>() / d; }
template <class T> T tiny_energy_floor(const T &d) {
  const T d3 = d * d * d;
  return d3 > 0 ? 256 * boost::math::tools::min_value<T>() * eps<T>() / d3 : infinite<T>();
}

// Asymptotic model's estimate for the scene (units: the scene's a).
template <class T> error_estimate<T> asymptotic_estimate(const pressure_model<T> &pm, const general_scene<T> &sc) {
  using std::abs;
  using std::max;
  using std::min;
  error_estimate<T> e;
  if (sc.q == 0 && sc.s == 0) return e;  // stuck: exact
  T D[2], d[2], w[2];
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? +1 : -1;
    const T ph = pm.edge_phi(side);
    if (!(ph > 0)) return {infinite<T>(), infinite<T>()};
    const T dQ = abs(sc.q) / (2 * ph), dS = abs(sc.s) / (4 * ph);
    D[i] = dQ + dS;
    d[i] = abs(sc.q / 2 - side * sc.s / 4) / ph;
    T om = 0;
    for (const T &z0 : {D[i] / 2, D[i], 2 * D[i]}) {
      const T z = min(z0, T(1));
      const T x = side > 0 ? 1 - z : z - 1;
      const T v = side > 0 ? pm.phi(x, 2 - z, z) : pm.phi(x, z, 2 - z);
      om = max(om, T(abs(v / ph - 1)));
    }
    w[i] = om;
  }
  const T Dm = max(D[0], D[1]);
  T ab[2], corr[2];
  for (int i = 0; i < 2; ++i) {
    corr[i] = 2 * Dm * Dm + 32 * D[i] * w[i];
    ab[i] = corr[i] + 16 * eps<T>() * D[i];
    e.resolution = max(e.resolution, T(ab[i] + length_floor<T>()));
  }
  // The bound is a first correction to the edge expansion; where it is as large as
  // the zone it corrects (2 Dm^2 + 32 D_i w_i >= D_i at either edge), the expansion has left its
  // domain and bounds nothing: near sliding or under sigma the true zone can then
  // leave the edge region altogether (issue 13, fuzz_asymptotic: flat punch
  // b_f/a = 0.982, Q/fP = -0.9977, sigma/fp0 = -1: d2 = 0.018 a with r = 0.457 a,
  // the truth 1.97 a; over 15,000 zones of two sweeps every zone outside
  // |d - d_true| <= r had ab/D >= 21). The estimate then claims only what holds
  // for any lengths in [0, 2a]: r = 2, no zone resolved, infinite relative errors
  // (asymptotic_bounds_nothing; the C ABI's model refuses such scenes).
  // A resolved zone has D_i >= d_i > r >= ab_i, so no scene with every zone
  // resolved is affected.
  // (D_i = 0: no load at that edge, nothing to correct)
  if ((D[0] > 0 && !(corr[0] < D[0])) || (D[1] > 0 && !(corr[1] < D[1]))) {
    e.resolution = 2;
    e.unresolved = 2;
    e.slip_zone = e.energy = infinite<T>();
    return e;
  }
  for (int i = 0; i < 2; ++i) d[i] = resolved_zone(d[i], e.resolution, e.unresolved);
  if (!(d[0] > 0) && !(d[1] > 0)) return e;  // no zone resolved (the loads underflow): nothing to bound relatively
  for (int i = 0; i < 2; ++i) {
    if (!(d[i] > 0)) continue;
    const T rd = ab[i] / d[i] + tiny_length_floor(d[i]);
    const T r2 = (1 + rd) * (1 + rd), re = r2 * r2 - 1;
    e.slip_zone = max(e.slip_zone, rd);
    e.energy = max(e.energy, T(re + tiny_energy_floor(d[i])));
  }
  return e;
}

// The asymptotic estimate's verdict that the edge expansion bounds nothing for
// the scene (its first correction as large as a zone: asymptotic_estimate).
template <class T> bool asymptotic_bounds_nothing(const error_estimate<T> &e) { return !(e.resolution < 2); }

// smallest nonempty zone length in units of a (0 if both empty)
template <class T> T smallest_zone(const T &d1, const T &d2) {
  using std::min;
  if (d1 > 0 && d2 > 0) return min(d1, d2);
  return d1 > 0 ? d1 : d2;
}

// width: the stick width (b1 + b2)/a (2: not known). Where it is below the smaller
// zone, the stick zone sits at the sliding stick point x0 (large sigma), whose
// position the moment condition alone fixes, with slope 2 p_hat(x0) =
// 2 sqrt(d1 d2): a rounding of ~4 pi eps in it moves x0 by 4 pi eps/(2 sqrt(d1 d2)),
// large next to an edge (issue 13: 1 - Q/fP = 1e-12, sigma/fp0 = 5 to 100, d1 =
// 8.9e-9 a off by 1.1e-4 against an estimate of 1.2e-6; the same term as the
// quadrature's conditioning, general_solver.hpp).
template <class T>
error_estimate<T> closed_form_estimate(const T &d1, const T &d2, const T &q, const T &s, const T &width = T(2)) {
  using std::abs;
  using std::max;
  using std::min;
  using std::sqrt;
  error_estimate<T> e;
  const T ep = eps<T>();
  // d_i = m -+ s/4 (m ~ q/2): rounding of the two terms, relative to d_i
  const T scale = min(T(1), T(abs(q) + abs(s) / 4));
  e.resolution = (q == 0 && s == 0) ? T(0) : T(16 * ep * scale + length_floor<T>());
  const T dm = smallest_zone(resolved_zone(d1, e.resolution, e.unresolved),
                             resolved_zone(d2, e.resolution, e.unresolved));
  if (!(dm > 0)) return e;  // stuck, or no zone resolved
  e.slip_zone = 32 * ep + 16 * ep * scale / dm + tiny_length_floor(dm);
  if (width < dm && d1 > 0 && d2 > 0)
    e.slip_zone = max(e.slip_zone, T(4 * pi<T>() * ep / (2 * sqrt(d1 * d2) * dm) + tiny_length_floor(dm)));
  e.energy = 3 * e.slip_zone + 16 * ep + tiny_energy_floor(dm);
  return e;
}

// acc: the pressure's accuracy in units of eps (pressure_model::accuracy_eps;
// 4 for the closed forms): the eps term grows with it beyond 4 (issue 13: the
// power law at n = 999, Q/fP = 0.3, sigma/fp0 = -3 erred by 4.2e-13 in d2
// against an estimate of 6.6e-14 that assumed a pressure good to a few eps).
// conditioning: the solution's own bound on the zone lengths' absolute error
// from its Jacobian (general_solution::conditioning, units of a; 0: not known)
template <class T> error_estimate<T> quadrature_estimate(const T &rt, const T &d1, const T &d2, const T &width,
                                                         const T &q, const T &acc = T(4),
                                                         const T &conditioning = T(0)) {
  using std::max;
  error_estimate<T> e;
  const T pe = eps<T>() * max(T(1), T(acc / 4));
  // the resolution is the absolute part of the bound below: the state's 16 (pe + rt)
  // and the conditioning, itself a bound on |d_i - d_i,true| (units of a). Without
  // the latter, a zone 1e3 times shorter than the conditioning was "resolved" with
  // a relative estimate of 1.2e4 and the wrong slip direction (issue 13: a callback
  // at the regime boundary, tests/test_select.cpp)
  e.resolution = (d1 == 0 && d2 == 0 && q == 0) ? T(0) : T(max(T(16 * (pe + rt)), conditioning) + length_floor<T>());
  const T dm = smallest_zone(resolved_zone(d1, e.resolution, e.unresolved),
                             resolved_zone(d2, e.resolution, e.unresolved));
  if (!(dm > 0)) return e;  // stuck, or no zone resolved
  // conditioning near sliding: the stick zone is narrow because q -> 1 (then
  // width ~ 2 sqrt(1 - q)), not when large sigma shrinks it onto the sliding
  // stick point, where d1, d2 are well conditioned (issue 13: at sigma/fp0 =
  // 50, width 7e-12 gave an estimate of 1.4e-3 for a result good to 1e-15)
  using std::abs;
  using std::sqrt;
  // (/4: margin for pressures whose shear-only stick zone is narrower than Hertz's)
  const T wc = max(width, T(sqrt(T(abs(1 - abs(q)))) / 4));
  // or, where larger, the solution's conditioning (the sliding stick point next to an
  // edge, Q -> fP at large sigma, issue 13)
  e.slip_zone = max(T(16 * (pe + rt) * (1 + 1 / dm + 1 / wc)), T(conditioning / dm)) + tiny_length_floor(dm);
  e.energy = 3 * e.slip_zone + tiny_energy_floor(dm);
  return e;
}

// A-posteriori estimate from a second solve in a wider type W (issue 16). The
// estimates above are worst-case bounds, 10-700x above the true error of a
// double result (docs/validation.md); none reaches 1e-15, so HS_MODEL_AUTO at
// rtol 1e-15 took the reference route (~1 s for the flat punch) on scenes that
// double solves to 1e-16. The same model solved in W (long double: 11 more
// bits) has a worst-case bound of its own, 2^11 below the double one; the
// double result's true error is then bounded by its distance to the wider
// result plus that bound:
//   |d_i - d_i,true| <= A_i = |d_i - d_i,W| + Aw_i             (units of a)
//   |E_i - E_i,true| <= |E_i - E_i,W| + rE_i E_i,W
// with Aw_i, rE_i the wider solve's worst-case bounds per zone (the forms
// above at W's epsilon, closed_form_zone_bounds, quadrature_zone_bounds: their
// a/d_min terms are absolute errors of every zone, here not divided by the
// smaller zone and applied to the larger). Resolution: r = max_i A_i (each
// zone's length is within r of the truth); a zone with d_i > r is resolved
// and its relative errors are taken against the truth's lower bounds d_i - A_i
// and (1 - rE_i) E_i,W. NaN-safe: a NaN or infinite difference gives an
// infinite estimate. d, E: the double result (dimensional, as reported); dw,
// Ew: the wider one; a: the contact half-width; exact: both solves stuck.
template <class T, class W>
error_estimate<T> a_posteriori_estimate(const T (&d)[2], const T (&E)[2], const W (&dw)[2], const W (&Ew)[2],
                                        const W &a, const W (&Aw)[2], const W (&rE)[2], bool exact = false) {
  using std::abs;
  using std::max;
  error_estimate<T> e;
  if (exact && d[0] == 0 && d[1] == 0) return e;  // stuck: exact
  const W big = W(infinite<T>());
  W A[2], r = 0;
  for (int i = 0; i < 2; ++i) {
    A[i] = abs(W(d[i]) - dw[i]) / a + Aw[i];
    if (!(A[i] <= big)) A[i] = big;  // NaN or overflow
    r = max(r, A[i]);
  }
  // rounding the W figures to T: up by a few ulps of T
  const W up = 1 + 4 * W(eps<T>());
  const W top = W(boost::math::tools::max_value<T>());
  r *= up;
  e.resolution = r > top ? infinite<T>() : T(r);
  W rd = 0, re = 0;
  for (int i = 0; i < 2; ++i) {
    const W di = W(d[i]) / a;
    if (zone_unresolved(di, r)) {
      ++e.unresolved;
      continue;
    }
    rd = max(rd, W(A[i] / (di - A[i])));
    if (!(rE[i] < W(0.5)) || !(Ew[i] > 0)) {
      re = big;
      continue;
    }
    const W rel = (abs(W(E[i]) - Ew[i]) + rE[i] * Ew[i]) / ((1 - rE[i]) * Ew[i]);
    re = max(re, rel <= big ? rel : big);
  }
  e.slip_zone = rd * up > top ? infinite<T>() : T(rd * up);
  e.energy = re * up > top ? infinite<T>() : T(re * up);
  return e;
}

// closed_form_estimate's bound per zone (d1, d2 in units of a): the absolute
// error Aw_i of d_i (units of a) and the relative error rE_i of E_i
template <class T> void closed_form_zone_bounds(const T &d1, const T &d2, const T &q, const T &s, const T &width,
                                                T (&Aw)[2], T (&rE)[2]) {
  using std::abs;
  using std::min;
  using std::sqrt;
  const T ep = eps<T>();
  const T scale = min(T(1), T(abs(q) + abs(s) / 4));
  const T dm = smallest_zone(d1, d2);
  const T d[2] = {d1, d2};
  for (int i = 0; i < 2; ++i) {
    Aw[i] = 32 * ep * d[i] + 16 * ep * scale + length_floor<T>();
    if (width < dm && d1 > 0 && d2 > 0) Aw[i] += 4 * pi<T>() * ep / (2 * sqrt(d1 * d2));
    rE[i] = d[i] > 0 ? T(3 * Aw[i] / d[i] + 16 * ep + tiny_energy_floor(d[i])) : infinite<T>();
  }
}

// quadrature_estimate's bound per zone at rt = 0 (as closed_form_zone_bounds)
template <class T> void quadrature_zone_bounds(const T &d1, const T &d2, const T &width, const T &q, const T &acc,
                                               const T &conditioning, T (&Aw)[2], T (&rE)[2]) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const T pe = eps<T>() * max(T(1), T(acc / 4));
  const T wc = max(width, T(sqrt(T(abs(1 - abs(q)))) / 4));
  const T d[2] = {d1, d2};
  for (int i = 0; i < 2; ++i) {
    Aw[i] = max(T(16 * pe * (d[i] + 1 + d[i] / wc)), conditioning) + length_floor<T>();
    rE[i] = d[i] > 0 ? T(3 * Aw[i] / d[i] + tiny_energy_floor(d[i])) : infinite<T>();
  }
}

// The a-posteriori estimates of a double closed-form or quadrature solution
// (issue 16): the same model in long double, its worst-case bounds, and the
// distance of the two. Throws what the long double solve throws.
inline general_scene<long double> widen_scene(const general_scene<double> &sc) {
  general_scene<long double> w;
  w.a = sc.a;
  w.p0 = sc.p0;
  w.f = sc.f;
  w.Estar = sc.Estar;
  w.q = sc.q;
  w.s = sc.s;
  return w;
}
// The closed forms in long double are brought to long double's own accuracy
// first: the opposite-sign state gets the refinement step double gets in long
// double (refine_opposite) in binary128 (without it the residual's O(pi s)
// terms leave ~0.1 eps_LD pi s in d: 3e-16 at sigma/fp0 = 8e3, above the double
// result's own error), and the energies come from the adaptive tanh-sinh path
// on pieces graded away from the stick edge, with the quadrature's own error
// estimate added to the bound (the fixed Gauss rules are sized for double:
// 1e-17 to 5e-17 relative in long double, half an ulp of double; one tanh-sinh
// interval near sliding stopped at 4e-15 in long double, 1 - Q/fP = 1.2e-9).
inline error_estimate<double> a_posteriori_closed_form(const hertz_solution<double> &s, int max_iterations = 100) {
  using W = long double;
  using std::abs;
  const auto sw = widen_scene(s.scene);
  solve_options<W> o;
  o.max_iterations = max_iterations;
  auto w = solve_hertz<W>(sw, o);
  if (w.reg == regime::opposite_sign) {
    opposite_state<W> st{w.delta1, w.delta2, w.width, w.log_width};
    st = refine_opposite<W, boost::multiprecision::cpp_bin_float_quad>(abs(sw.q), abs(sw.s), st);
    w.delta1 = st.d1;
    w.delta2 = st.d2;
    w.width = st.e;
    w.log_width = st.le;
    w.beta1 = 1 - st.d1;
    w.beta2 = 1 - st.d2;
    if (w.beta1 + w.beta2 < 0) w.beta2 = -w.beta1;  // as finish_opposite
  }
  W Aw[2], rE[2];
  closed_form_zone_bounds<W>(w.delta1, w.delta2, abs(sw.q), abs(sw.s), w.width, Aw, rE);
  if (w.mirror) {
    std::swap(Aw[0], Aw[1]);
    std::swap(rE[0], rE[1]);
  }
  const double d[2] = {s.d1(), s.d2()}, E[2] = {s.energy(1), s.energy(2)};
  const W dw[2] = {w.d1(), w.d2()};
  const W scale = sw.f * sw.f * sw.p0 * sw.p0 * sw.a * sw.a / sw.Estar;
  W Ew[2];
  for (int i = 0; i < 2; ++i) {
    W err = 0;
    const W eh = w.energy_hat_graded(((i == 0) != w.mirror) ? +1 : -1, 64 * eps<W>(), err);
    Ew[i] = scale * eh;
    // the closed forms' energy bound and the quadrature's own error estimate
    if (eh > 0) rE[i] += err / eh;
  }
  return a_posteriori_estimate(d, E, dw, Ew, sw.a, Aw, rE, w.reg == regime::stuck);
}
// pm: the double solution's pressure in long double; s solved at full precision (rtol 0)
inline error_estimate<double> a_posteriori_quadrature(const general_solution<double> &s,
                                                      const pressure_model<long double> &pm,
                                                      int max_iterations = 100) {
  using W = long double;
  const auto sw = widen_scene(s.scene);
  general_options<W> o;
  o.max_iterations = max_iterations;
  const auto w = solve_general<W>(pm, sw, o);
  W Aw[2], rE[2];
  quadrature_zone_bounds<W>(w.d1() / sw.a, w.d2() / sw.a, w.width, sw.q, pm.accuracy_eps(), w.conditioning, Aw, rE);
  const double d[2] = {s.d1(), s.d2()}, E[2] = {s.energy(1), s.energy(2)};
  const W dw[2] = {w.d1(), w.d2()}, Ew[2] = {w.energy(1), w.energy(2)};
  return a_posteriori_estimate(d, E, dw, Ew, sw.a, Aw, rE, sw.q == 0 && sw.s == 0);
}

// The tolerances a caller may ask for (hs_options.rtol): 0 (full precision);
// for model selection (HS_MODEL_AUTO) the error the chosen model must meet,
// in [2^-53, 0.5]; for one model, the quadrature's tolerance in [1e-15, 1e-2].
template <class T> bool tolerance_in_range(const T &rtol, bool model_selection) {
  using std::isfinite;
  using std::ldexp;
  if (!isfinite(rtol)) return false;
  if (rtol == 0) return true;
  if (model_selection) return rtol >= ldexp(T(1), -53) && rtol <= T(0.5);
  return rtol >= T(1e-15) && rtol <= T(1e-2);
}

// The quadrature tolerance rt for which the quadrature's estimate meets tol
// (model selection, HS_MODEL_AUTO): the estimate's form 16 (eps + rt)(1 + a/d_min)
// inverted with a margin of 4, with d_min guessed by the Hertz closed form
// under the same loads. 0 (full precision) for tol = 0, for a stuck contact
// and when rt would be below 1e-15.
template <class T> T quadrature_tolerance(const T &tol, const hertz_scene<T> &sc) {
  if (!(tol > 0)) return T(0);
  const auto g = solve_hertz<T>(sc);
  const T dm = smallest_zone(T(g.d1() / sc.a), T(g.d2() / sc.a));
  T rt = dm > 0 ? T(tol / (64 * (1 + 1 / dm))) : T(0);
  if (rt < T(1e-15)) rt = 0;
  return rt;
}

}}  // namespace hs::core
