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

#include "general.hpp"
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
    // without an intermediate overflow (issue 13: KN^2 ~ p0^2 overflowed at p0 ~ 1e200)
    return scaled_product({pi<T>(), f, f, KN, KN, dd, dd, dd}, Estar, T(1) / 12);
  }
};

// Edge intensities of a Hertz scene (user frame). side = +1: edge x = +a
// (slip zone 1), side = -1: edge x = -a (slip zone 2). K_T is taken in
// magnitude: the model's slip direction is the sign of Q/pi -+ sigma a/4.
// K_N = p0 sqrt(2/a) (= (1/pi) sqrt(2/a) dP/da, eq 27, for Hertz);
// q_st = (Q/pi - sigma x/4)/sqrt(a^2-x^2) -> (Q/pi - side sigma a/4)/sqrt(2 a z).
template <class T> edge_model<T> hertz_edge(const hertz_scene<T> &sc, int side) {
  using std::abs;
  using std::sqrt;
  edge_model<T> m;
  m.f = sc.f;
  m.Estar = sc.Estar;
  m.KN = sc.p0 * sqrt(2 / sc.a);
  const T P = pi<T>() * sc.a * sc.p0 / 2;
  const T Q = sc.q * sc.f * P, sigma = sc.s * sc.f * sc.p0;
  m.KT = abs(Q / pi<T>() - side * sigma * sc.a / 4) / sqrt(2 * sc.a);
  return m;
}

// Edge intensities for any pressure model (scene in user frame, p = p0 p_hat(x/a)):
// p ~ K_N sqrt(z) with K_N = p0 sqrt(2/a) phi(edge) (pressure_model::edge_phi;
// for a load-controlled family p(x; a) this equals eq 27's (1/pi) sqrt(2/a) dP/da,
// checked for the flat punch in tests/test_asymptotic.cpp), and
// q_st = (Q/pi - sigma x/4)/sqrt(a^2-x^2) for every geometry. K_T is signed
// here: its sign is the slip direction of the zone at that edge.
template <class T> edge_model<T> general_edge(const pressure_model<T> &pm, const general_scene<T> &sc, int side) {
  using std::sqrt;
  edge_model<T> m;
  m.f = sc.f;
  m.Estar = sc.Estar;
  m.KN = sc.p0 * sqrt(2 / sc.a) * pm.edge_phi(side);
  // Q/pi -+ sigma a/4 = f p0 a (q/2 -+ s/4)
  m.KT = sc.f * sc.p0 * sc.a * (sc.q / 2 - side * sc.s / 4) / sqrt(2 * sc.a);
  return m;
}

// The asymptotic model as a solution (paper section 5): each edge carries an
// independent edge model; the slip zones are (a - d1, a) and (-a, -a + d2)
// with d_i = 2 |K_T,i| / (f K_N,i), slipping in the direction sign(K_T,i).
// Same interface as hertz_solution / general_solution (user frame).
template <class T> class edge_solution {
 public:
  general_scene<T> scene;
  regime reg = regime::stuck;
  int iterations = 0, order = 0;
  edge_model<T> m1, m2;  // edge x = +a (zone 1), edge x = -a (zone 2)
  const pressure_model<T> *pm = nullptr;

  edge_solution(const pressure_model<T> &p, const general_scene<T> &sc) : scene(sc), pm(&p) {
    m1 = general_edge(p, sc, +1);
    m2 = general_edge(p, sc, -1);
    if (!(m1.KN > 0) || !(m2.KN > 0))
      throw error(status::bad_geometry, "asymptotic model: the pressure has no sqrt edge coefficient");
    if (!(d1() + d2() < 2 * sc.a))
      throw error(status::not_applicable, "asymptotic model does not apply: its slip zones cover the contact");
    const int s1 = dir1(), s2 = dir2();
    reg = (s1 == 0 && s2 == 0) ? regime::stuck : (s1 * s2 < 0 ? regime::opposite_sign : regime::same_sign);
  }
  static int sgn(const T &v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
  T d1() const {
    using std::abs;
    return abs(m1.d());
  }
  T d2() const {
    using std::abs;
    return abs(m2.d());
  }
  T b1() const { return scene.a - d1(); }
  T b2() const { return scene.a - d2(); }
  // an empty zone (d underflows to 0) has no direction (issue 13)
  int dir1() const { return d1() > 0 ? sgn(m1.KT) : 0; }
  int dir2() const { return d2() > 0 ? sgn(m2.KT) : 0; }
  // z: distance from the edge; 0 if x is in the stick zone
  int locate(const T &x, T &z) const {
    if (d1() > 0 && x >= b1()) {
      z = scene.a - x;
      return 1;
    }
    if (d2() > 0 && x <= -b2()) {
      z = scene.a + x;
      return 2;
    }
    z = 0;
    return 0;
  }
  const edge_model<T> &model(int zone) const { return zone == 1 ? m1 : m2; }
  edge_model<T> magnitude(int zone) const {
    using std::abs;
    edge_model<T> m = model(zone);
    m.KT = abs(m.KT);
    return m;
  }
  // h = dir |h|; B_x = dh/dx (x = a - z in zone 1, x = -a + z in zone 2)
  T slip(const T &x) const {
    T z;
    const int zone = locate(x, z);
    if (!zone) return T(0);
    return (zone == 1 ? dir1() : dir2()) * magnitude(zone).slip(z);
  }
  T Bx(const T &x) const {
    T z;
    const int zone = locate(x, z);
    if (!zone) return T(0);
    return zone == 1 ? dir1() * magnitude(1).Bx(z) : -dir2() * magnitude(2).Bx(z);
  }
  // the model's own pressure K_N sqrt(z) (consistent with its energy)
  T work(const T &x) const {
    T z;
    const int zone = locate(x, z);
    if (!zone) return T(0);
    return magnitude(zone).work(z);
  }
  T energy(int zone) const { return magnitude(zone).energy(); }
  // Shear traction: f p dir_i on the model's slip zones, and in between the
  // bounded stick-zone solution for those zones (traction.hpp). An
  // approximation like the model: its resultant is not exactly Q.
  T traction(const T &x) const {
    std::vector<T> k;
    for (const auto &bp : pm->breakpoints()) k.push_back(scene.a * bp.x);
    return monotonic_traction<T>([&](const T &v) { return pressure(v); }, scene.a, scene.f, b1(), b2(), dir1(),
                                 dir2(), x, k);
  }
  // the geometry's pressure
  T pressure(const T &x) const {
    const T xi = x / scene.a;
    if (!(xi > -1 && xi < 1)) return T(0);
    return scene.p0 * pm->p(xi);
  }
};

// The comparison of the paper's Figures 5 and 6: at the load that gives a
// slip zone b/a under pure shear (loading = +1: Q only) or pure bulk tension
// (loading = -1: sigma only), the full and the asymptotic energy dissipated
// in one slip zone (a = p0 = f = E* = 1). Held equal: the load.
template <class T> struct asymptotic_comparison {
  hertz_scene<T> scene;  // the load
  T d_full, d_asym;      // slip zone lengths (units of a)
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
    // (ln e as well: below the normal range the moments read it, and without it a
    // subnormal b gave s/fp0 = 4.9 for 1.8e3, d_full = 0.79 for 1; issue 13, fuzz_asymptotic)
    using std::log;
    opposite_state<T> st{1 - b, 1 - b, 2 * b, T(log(T(2)) + log(b))};
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
