// halfslip core: the canonical-to-user frame mapping shared by every solution
// type (Hertz closed forms, general pressures).
//
// A solver works on the canonical scene q = Q/fP >= 0, s = sigma/(f p0) >= 0
// (docs/conventions.md): negation (Q, sigma) -> (-Q, -sigma) flips every slip,
// the mirror x -> -x swaps the edges. Derived supplies the canonical,
// dimensionless bhat(zone, dl), hhat(zone, dl) and energy_hat(zone), zone +1
// being (beta1, 1) and -1 being (-1, -beta2), dl the distance from the stick
// boundary in units of a, and pressure(x) in the user frame.
#pragma once
#include <cmath>
#include <vector>

#include "traction.hpp"

namespace hs { namespace core {

enum class regime : int { stuck = 0, same_sign = 1, opposite_sign = 2 };

template <class Derived, class T, class Scene> struct canonical_solution {
  Scene scene;
  regime reg = regime::stuck;
  bool negate = false;  // canonical q, s = -Q/fP, -sigma/fp0
  bool mirror = false;  // canonical x = -x (edges swapped)
  // canonical, dimensionless: right zone (beta1, 1), left zone (-1, -beta2)
  T beta1{1}, beta2{1}, delta1{0}, delta2{0};
  T width{2};              // beta1 + beta2 (stick-zone length / a), accurate when tiny
  int dirR = 0, dirL = 0;  // canonical slip directions
  int iterations = 0;
  T rtol{0};

  // The canonical loads q, s >= 0 of scene: (Q, sigma) -> (-Q, -sigma) flips every
  // slip (negate), then sigma -> -sigma mirrors x -> -x (mirror); sets both flags.
  void to_canonical(T &q, T &s) {
    q = scene.q;
    s = scene.s;
    if (q < 0) {
      negate = true;
      q = -q;
      s = -s;
    }
    if (s < 0) {
      mirror = true;
      s = -s;
    }
  }

  // An empty zone (delta = 0: a load so small that the zone underflows, or a
  // state on the regime boundary) has no slip direction; with both empty the
  // contact is stuck (issue 13: sigma/fp0 = 5e-324 reported same-sign with
  // direction +1 for an empty zone 2). Called by the solvers before they return.
  void settle_empty_zones() {
    if (!(delta1 > 0)) dirR = 0;
    if (!(delta2 > 0)) dirL = 0;
    if (dirR == 0 && dirL == 0) reg = regime::stuck;
  }

  // ---- user frame ----
  int sign() const { return negate ? -1 : 1; }
  T b1() const { return scene.a * (mirror ? beta2 : beta1); }
  T b2() const { return scene.a * (mirror ? beta1 : beta2); }
  T d1() const { return scene.a * (mirror ? delta2 : delta1); }
  T d2() const { return scene.a * (mirror ? delta1 : delta2); }
  int dir1() const { return sign() * (mirror ? dirL : dirR); }
  int dir2() const { return sign() * (mirror ? dirR : dirL); }
  T half_width() const { return width / 2; }  // stick half-width / a

  // Locate x: canonical zone (+1 right, -1 left, 0 stick) and the distance dl
  // from the stick boundary (units of a).
  int locate(const T &x, T &dl) const {
    const T xi = (mirror ? -x : x) / scene.a;
    if (delta1 > 0 && xi >= beta1) {
      dl = xi - beta1;
      return +1;
    }
    if (delta2 > 0 && xi <= -beta2) {
      dl = -beta2 - xi;
      return -1;
    }
    dl = T(0);
    return 0;
  }
  // B_x = (f p0/E*) bhat, h = (f p0 a/E*) hhat, energy = (f^2 p0^2 a^2/E*) energy_hat
  T Bx(const T &x) const {
    T dl;
    const int z = locate(x, dl);
    if (z == 0) return T(0);
    const T v = scaled_product({scene.f, scene.p0}, scene.Estar, self().bhat(z, dl));
    return (mirror ? -sign() : sign()) * v;
  }
  T slip(const T &x) const {
    T dl;
    const int z = locate(x, dl);
    if (z == 0) return T(0);
    return sign() * scaled_product({scene.f, scene.p0, scene.a}, scene.Estar, self().hhat(z, dl));
  }
  // Shear traction q(x) on body 1 (docs/conventions.md), generic form
  // (traction.hpp); kinks: user-frame points where the pressure is not smooth.
  T traction_generic(const T &x, const std::vector<T> &kinks = {}) const {
    return monotonic_traction<T>(
        [&](const T &v, int side, const T &c) { return self().pressure_near_edge(v, side, c); }, scene.a, scene.f,
        b1(), b2(), dir1(), dir2(), x, kinks);
  }
  // the pressure at x, at distance c from the contact edge on `side` (user frame):
  // solutions whose pressure can use the exact distance hide this (traction.hpp, pressure_at)
  T pressure_near_edge(const T &x, int, const T &) const { return self().pressure(x); }
  T work(const T &x) const {
    using std::abs;
    return scene.f * self().pressure(x) * abs(slip(x));
  }
  // Energy dissipated in user zone i (1: (b1, a), 2: (-a, -b2)).
  T energy(int i) const {
    const int z = ((i == 1) != mirror) ? +1 : -1;
    // without an intermediate overflow (issue 13: p0^2 overflowed at p0 ~ 1e200)
    return scaled_product({scene.f, scene.f, scene.p0, scene.p0, scene.a, scene.a}, scene.Estar,
                          self().energy_hat(z));
  }

 private:
  const Derived &self() const { return static_cast<const Derived &>(*this); }
};

}}  // namespace hs::core
