// halfslip core: the asymptotic single-edge model (paper section 5).
//
// Near a contact edge, with z the distance from the edge, the pressure is
// p ~ K_N sqrt(z) and the fully stuck shear traction q_st ~ K_T / sqrt(z).
// A slip zone of length d at that edge, bounded at both ends, has
//   d   = 2 K_T / (f K_N)                                (paper eq 29, as printed)
//   B_x = (2 f K_N / E*) sqrt(d - z)                    (eq 29 prints f K_N/E*: erratum E9)
//   |h| = (4 f K_N / (3 E*)) (d - z)^{3/2},   W = f K_N sqrt(z) |h|,
//   energy = int_0^d W dz = pi f^2 K_N^2 d^3 / (12 E*)
// (int_0^d sqrt(z)(d-z)^{3/2} dz = d^3 B(3/2, 5/2) = pi d^3 / 16).
// The factor 2 in B_x is what the full Hertz solution (eq 21) gives as the
// slip zone shrinks: B = 2 f p0/(a E*) sqrt((x-b1)(x+b2)) -> 2 f p0 sqrt(2/a)/E* sqrt(d-z)
// with K_N = p0 sqrt(2/a); tests/test_asymptotic.cpp checks the limit.
#pragma once
#include <cmath>

#include "hertz.hpp"
#include "numerics.hpp"

namespace hs { namespace core {

template <class T> struct edge_model {
  T KN{0}, KT{0}, f{1}, Estar{1};
  T d() const { return 2 * KT / (f * KN); }
  // z: distance from the contact edge, 0 <= z <= d (0 outside)
  T Bx(const T &z) const {
    using std::sqrt;
    return z < d() ? 2 * f * KN / Estar * sqrt(d() - z) : T(0);
  }
  T slip(const T &z) const {
    using std::sqrt;
    if (!(z < d())) return T(0);
    const T r = d() - z;
    return 4 * f * KN / (3 * Estar) * r * sqrt(r);
  }
  T work(const T &z) const {
    using std::sqrt;
    return f * KN * sqrt(z) * slip(z);
  }
  T energy() const {
    const T dd = d();
    return pi<T>() * f * f * KN * KN * dd * dd * dd / (12 * Estar);
  }
};

// Edge intensities of a Hertz scene (user frame). side = +1: edge x = +a
// (slip zone 1), side = -1: edge x = -a (slip zone 2). K_T is taken in
// magnitude: the model's slip direction is the sign of Q/pi -+ sigma a/4.
// K_N = p0 sqrt(2/a) (= (1/pi) sqrt(2/a) dP/da, eq 27, for Hertz);
// q_st = (Q/pi - sigma x/4)/sqrt(a^2-x^2) -> (Q/pi - side sigma a/4)/sqrt(2 a z).
template <class T> edge_model<T> hertz_edge(const hertz_scene<T> &sc, int side) {
  using std::abs; using std::sqrt;
  edge_model<T> m;
  m.f = sc.f;
  m.Estar = sc.Estar;
  m.KN = sc.p0 * sqrt(2 / sc.a);
  const T P = pi<T>() * sc.a * sc.p0 / 2;
  const T Q = sc.q * sc.f * P, sigma = sc.s * sc.f * sc.p0;
  m.KT = abs(Q / pi<T>() - side * sigma * sc.a / 4) / sqrt(2 * sc.a);
  return m;
}

// The comparison of the paper's Figures 5 and 6: at the load that gives a
// slip zone b/a under pure shear (loading = +1: Q only) or pure bulk tension
// (loading = -1: sigma only), the full and the asymptotic energy dissipated
// in one slip zone (a = p0 = f = E* = 1). Held equal: the load.
template <class T> struct asymptotic_comparison {
  hertz_scene<T> scene;   // the load
  T d_full, d_asym;       // slip zone lengths (units of a)
  T energy_full, energy_asym;
  T fractional_error() const { return (energy_asym - energy_full) / energy_full; }
};

template <class T> asymptotic_comparison<T> compare_asymptotic(int loading, const T &b) {
  if (!(b > 0 && b < 1)) throw error(status::bad_option, "b/a must lie in (0, 1)");
  hertz_scene<T> sc;
  if (loading > 0) {
    sc.q = (1 - b) * (1 + b);  // b/a = sqrt(1 - Q/fP)
    sc.s = 0;
  } else {
    // eq (18): int_b^1 sqrt(1-t^2)/sqrt(t^2-b^2) dt = pi s / 8, the single-zone
    // moment A0 with b1 = b2 = b
    opposite_state<T> st{1 - b, 1 - b, 2 * b};
    T A0, A1;
    opposite_moments(st, A0, A1);
    sc.q = 0;
    sc.s = 8 * A0 / pi<T>();
  }
  const auto sol = solve_hertz(sc);
  asymptotic_comparison<T> c;
  c.scene = sc;
  c.d_full = sol.d1();
  c.energy_full = sol.energy(1);
  const auto m = hertz_edge(sc, +1);
  c.d_asym = m.d();
  c.energy_asym = m.energy();
  return c;
}

}}  // namespace hs::core
