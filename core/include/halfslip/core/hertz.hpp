// halfslip core: Hertz (cylinder) contact under constant normal load, shear
// force Q and differential bulk tension sigma, in every load regime.
//
// Generic in the real type T (double is the fast path; the reference backend
// instantiates the same code on MPFR). Conventions: docs/conventions.md.
//
// Internally every scene is mapped to a canonical one with q = Q/fP >= 0 and
// s = sigma/(f p0) >= 0 (negation Q,sigma -> -Q,-sigma flips every slip;
// the mirror x -> -x flips sigma and swaps the edges). All lengths are in
// units of a inside the canonical solution (beta = b/a, delta = 1 - beta).
#pragma once
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "frame.hpp"
#include "hertz_opposite.hpp"
#include "hertz_opposite_slip.hpp"
#include "numerics.hpp"
#include "status.hpp"

namespace hs { namespace core {

// One contact scene for every solver (Hertz and general pressures alike).
template <class T> struct contact_scene {
  T a{1}, p0{1}, f{1}, Estar{1};  // p0 = 2P/(pi a)
  T q{0};                         // Q / (f P), P = pi a p0 / 2
  T s{0};                         // sigma / (f p0)
};
template <class T> using hertz_scene = contact_scene<T>;
template <class T> using general_scene = contact_scene<T>;

template <class T> struct solve_options {
  int max_iterations = 100;
  T rtol = T(0);  // 0: full precision of T
};

template <class T> void validate(const hertz_scene<T> &sc) {
  using boost::math::isfinite;
  using std::abs;
  if (!isfinite(sc.a) || !isfinite(sc.p0) || !isfinite(sc.f) || !isfinite(sc.Estar) || !isfinite(sc.q) ||
      !isfinite(sc.s))
    throw error(status::not_finite, "scene has a NaN or infinite value");
  if (!(sc.a > 0)) throw error(status::bad_size, "contact half-width a must be > 0");
  if (!(sc.p0 > 0)) throw error(status::bad_size, "reference pressure p0 must be > 0");
  if (!(sc.Estar > 0)) throw error(status::bad_size, "modulus E* must be > 0");
  if (!(sc.f > 0)) throw error(status::bad_friction, "friction coefficient f must be > 0");
  if (!(abs(sc.q) < 1)) throw error(status::gross_sliding, "|Q| >= fP: gross sliding, no stick zone");
}

// The opposite-sign zone integrals of a solution with their tables (issue 16:
// the slip at a point reads 1 + 2G/pi from a Chebyshev table built once per
// zone, opposite_zone_integrals::tabulate_g), built on a zone's first slip and
// kept with the solution. Thread-safe without locks: a zone's object is
// published once by compare-and-swap (a thread that loses the race deletes its
// own) and is immutable afterwards. Each object records the state it was built
// for: a caller whose solution's lengths have since been changed gets nullptr
// (and evaluates without the table). A copy starts empty.
template <class T> class opposite_zone_cache {
 public:
  using zone = opposite_zone_integrals<T>;
  opposite_zone_cache() = default;
  opposite_zone_cache(const opposite_zone_cache &) noexcept {}
  opposite_zone_cache &operator=(const opposite_zone_cache &) noexcept {
    reset();
    return *this;
  }
  ~opposite_zone_cache() { reset(); }
  // the zone object for state st (i = 0: right zone, 1: left), or nullptr
  const zone *get(int i, const opposite_state<T> &st) const {
    const zone *z = p_[i].load(std::memory_order_acquire);
    if (!z) {
      const zone *fresh = new zone(st, true);
      const zone *expected = nullptr;
      if (p_[i].compare_exchange_strong(expected, fresh, std::memory_order_acq_rel, std::memory_order_acquire)) {
        z = fresh;
      } else {
        delete fresh;
        z = expected;
      }
    }
    return z->same_state(st) ? z : nullptr;
  }

 private:
  mutable std::atomic<const zone *> p_[2] = {nullptr, nullptr};
  void reset() noexcept {
    for (auto &p : p_) delete p.exchange(nullptr, std::memory_order_acq_rel);
  }
};

template <class T> struct hertz_solution : canonical_solution<hertz_solution<T>, T, hertz_scene<T>> {
  using base = canonical_solution<hertz_solution<T>, T, hertz_scene<T>>;
  using base::beta1;
  using base::beta2;
  using base::delta1;
  using base::delta2;
  using base::half_width;
  using base::reg;
  using base::rtol;
  using base::scene;
  using base::width;
  // ln(width): the stick zone of a large-sigma scene can be narrower than the
  // range of T (width = 0); the opposite-sign slip and energies need its log
  T log_width{0};

 private:
  opposite_zone_cache<T> zone_cache_;

 public:
  // Quadrature tolerance for the numerically integrated outputs.
  T quad_tol() const {
    using std::sqrt;
    return rtol > 0 ? sqrt(rtol) : boost::math::tools::root_epsilon<T>();
  }

  // --- canonical dimensionless dislocation density at distance dl >= 0 from
  // the stick boundary, in the right (zone = +1) or left (zone = -1) zone.
  // B_x = (f p0 / E*) * bhat.
  T bhat(int zone, const T &dl) const {
    using std::sqrt;
    const T w = half_width();
    const T Rh = sqrt(dl * (2 * w + dl));  // sqrt((xi - beta1)(xi + beta2))
    if (reg != regime::opposite_sign) return zone > 0 ? 2 * Rh : -2 * Rh;
    if (!(dl > 0)) return T(0);  // at the stick boundary (G may diverge there if width = 0)
    if (zone > 0) {
      // Right zone slips against the left one: b = -2 R (1 + 2/pi H),
      // H(x) = int_left sqrt(1-t^2)/(R(t)(x - t)) dt = G(-x; beta2, beta1).
      const T g = opposite_G_state<T>({delta2, delta1, width, log_width}, dl);
      return -2 * Rh * (1 + 2 * g / pi<T>());
    }
    const T g = opposite_G_state<T>({delta1, delta2, width, log_width}, dl);
    return -2 * Rh * (1 + 2 * g / pi<T>());
  }

  // The opposite-sign zone integrals of a canonical zone: the state with the
  // other zone first (as opposite_G_state takes it).
  opposite_state<T> zone_state(int zone) const {
    return zone > 0 ? opposite_state<T>{delta2, delta1, width, log_width}
                    : opposite_state<T>{delta1, delta2, width, log_width};
  }
  opposite_zone_integrals<T> zone_integrals(int zone) const { return opposite_zone_integrals<T>(zone_state(zone)); }
  // the same with the slip table, kept with the solution (opposite_zone_cache);
  // nullptr if the solution's lengths changed after the first call
  const opposite_zone_integrals<T> *cached_zone_integrals(int zone) const {
    return zone_cache_.get(zone > 0 ? 0 : 1, zone_state(zone));
  }
  // The fixed Gauss rules of hertz_opposite_slip.hpp are sized for <= 64-bit
  // significands (double, long double); wider types (the MPFR reference
  // backend) keep the adaptive tanh-sinh path.
  static constexpr bool fixed_rules = std::numeric_limits<T>::digits <= 64;

  // canonical dimensionless slip h = (f p0 a / E*) * hhat, zero at the stick boundary.
  T hhat(int zone, const T &dl) const {
    if constexpr (fixed_rules) {
      if (dl > 0 && reg == regime::opposite_sign)
        if (const auto *z = cached_zone_integrals(zone)) {
          const T I = z->slip(dl);
          return zone > 0 ? I : -I;
        }
    }
    return hhat_untabulated(zone, dl);
  }
  // The same without the table (the path of before the table; tests and bench/
  // compare the two)
  T hhat_untabulated(int zone, const T &dl) const {
    if (!(dl > 0)) return T(0);
    if (reg != regime::opposite_sign) return 2 * sqrt_quadratic_integral(dl, half_width());
    if constexpr (!fixed_rules) {
      return hhat_tanh_sinh(zone, dl);
    } else {
      const T I = zone_integrals(zone).slip(dl);
      return zone > 0 ? I : -I;
    }
  }
  // The slip by adaptive tanh-sinh quadrature of bhat (the path before issue
  // 16; kept for wide types and for bench/ to compare against).
  T hhat_tanh_sinh(int zone, const T &dl) const {
    if (!(dl > 0)) return T(0);
    // int_0^dl bhat(u) du; bhat ~ sqrt(u) at u = 0: tanh-sinh handles it.
    const T I = integrate_ts<T>([&](const T &u, const T &uc) { return bhat(zone, uc < 0 ? -uc : u); }, T(0), dl,
                                quad_tol());
    return zone > 0 ? I : -I;
  }

  // Zone length (canonical) in units of a.
  T zone_length(int zone) const { return zone > 0 ? delta1 : delta2; }

  // Dimensionless energy of a canonical zone: int p_hat |h_hat| dxi, by parts
  // int Pi(xi) b(xi) dxi with Pi the pressure tail beyond xi (Pi = 0 at the
  // contact edge, h = 0 at the stick edge).
  T energy_hat(int zone) const {
    using std::abs;
    if constexpr (fixed_rules) {
      if (reg == regime::opposite_sign) {
        const T L = zone_length(zone);
        return L > 0 ? T(abs(zone_integrals(zone).energy(L))) : T(0);
      }
    }
    return energy_hat_tanh_sinh(zone);
  }
  // The same by adaptive tanh-sinh (every regime; the path before issue 16).
  T energy_hat_tanh_sinh(int zone) const {
    using std::abs;
    const T L = zone_length(zone);
    if (!(L > 0)) return T(0);
    const T I = integrate_ts<T>(
        [&](const T &u, const T &uc) {
          // u: distance from stick edge; distance from contact edge = L - u
          const T dl = uc < 0 ? -uc : u;
          const T ce = uc > 0 ? uc : L - u;
          return pressure_tail(ce) * bhat(zone, dl);
        },
        T(0), L, quad_tol());
    return abs(I);
  }

  // The same on pieces graded away from the stick edge, [0, e], [e, 4e], ...,
  // [4^k e, L] (e the stick width; issue 16, the a-posteriori estimate): b has
  // its singularities at dl <= -e, which a zone much longer than e leaves next
  // to the end of a single tanh-sinh interval (near sliding the tanh-sinh above
  // stops at ~1e-15 in long double, its own error estimate far lower). err: the
  // sum of the pieces' error estimates (absolute, of the returned value).
  T energy_hat_graded(int zone, const T &tol, T &err) const {
    using std::abs;
    err = 0;
    const T L = zone_length(zone);
    if (!(L > 0)) return T(0);
    // the integrand and the interval scaled to O(1): the tanh-sinh error
    // estimate is not scale invariant (250 relative at zone energies of 1e-65;
    // 1.7e-9 off at 1e-31 with an estimate of 0)
    T S = abs(pressure_tail(L / 2) * bhat(zone, L / 2));
    if (!(S > 0) || !(S < boost::math::tools::max_value<T>())) S = 1;
    auto ts = make_tanh_sinh<T>();  // one integrator for every piece (its node tables)
    T sum = 0, lo = 0, hi = width > 0 ? T(width) : L;
    for (int k = 0; k < 200 && lo < L; ++k) {
      if (!(hi < L) || k == 199) hi = L;
      T e = 0;
      const T a = lo, b = hi, h = hi - lo;
      // on t in [0, 1], u = a + h t (the complements scale with h)
      sum += S * h *
             integrate_ts<T>(
                 [&](const T &t, const T &tc) {
                   const T u = a + h * t;
                   const T dl = (tc < 0 && a == 0) ? -tc * h : u;
                   const T ce = (tc > 0 && b == L) ? tc * h : L - u;
                   return pressure_tail(ce) * bhat(zone, dl) / S;
                 },
                 T(0), T(1), tol, &e, static_cast<T *>(nullptr), &ts);
      e *= h;
      err += abs(e) * S;
      lo = hi;
      hi *= 4;
    }
    return abs(sum);
  }

  // Shear traction q(x) on body 1. Same-sign regime: closed form
  // q = sgn(Q) f p0 [sqrt(1 - x^2/a^2) - sqrt((b1 - x)(x + b2))/a] in the stick zone
  // (a Hertz distribution minus a shifted, scaled one); otherwise the generic
  // form of traction.hpp.
  T traction(const T &x) const {
    using std::sqrt;
    if (reg != regime::same_sign) return this->traction_generic(x);
    if (!(x > -scene.a && x < scene.a)) return T(0);
    const T B1 = this->b1(), B2 = this->b2();
    const T sf = this->sign() * scene.f;
    if (x >= B1 || x <= -B2) return sf * pressure(x);
    return sf * (pressure(x) - scene.p0 * sqrt((B1 - x) * (x + B2)) / scene.a);
  }

  T pressure(const T &x) const {
    using std::sqrt;
    const T xi = x / scene.a;
    const T r = (1 - xi) * (1 + xi);
    return r > 0 ? scene.p0 * sqrt(r) : T(0);
  }
  // at distance c from an edge (the distance exact: traction.hpp)
  T pressure_near_edge(const T &, int, const T &c) const {
    using std::sqrt;
    const T dist = c / scene.a;
    return dist > 0 && dist < 2 ? scene.p0 * sqrt(dist * (2 - dist)) : T(0);
  }
};

// Solve a Hertz scene. Throws hs::core::error on bad input or failure.
template <class T> hertz_solution<T> solve_hertz(const hertz_scene<T> &sc, const solve_options<T> &opt = {}) {
  using std::log;
  using std::sqrt;
  validate(sc);
  if (opt.max_iterations < 1) throw error(status::bad_option, "max_iterations must be >= 1");
  hertz_solution<T> sol;
  sol.scene = sc;
  sol.rtol = opt.rtol;
  T q, s;
  sol.to_canonical(q, s);
  if (q == 0 && s == 0) {
    sol.reg = regime::stuck;
    return sol;  // beta = 1, delta = 0
  }
  // Same-sign closed form (paper eq 20, verified in tests/test_hertz.cpp):
  // beta = sqrt(1-q) +- s/4, with 1 - sqrt(1-q) = q/(1+sqrt(1-q)) (no cancellation).
  const T root = sqrt(1 - q);
  const T m = q / (1 + root);
  const T e = s / 4;
  if (e <= m) {
    sol.reg = regime::same_sign;
    sol.beta1 = root + e;
    sol.beta2 = root - e;
    sol.delta1 = m - e;
    sol.delta2 = m + e;
    sol.width = 2 * root;
    sol.log_width = log(sol.width);
    sol.dirR = 1;
    sol.dirL = 1;
    sol.settle_empty_zones();
    return sol;
  }
  sol.reg = regime::opposite_sign;
  const auto r = solve_opposite<T>(q, s, opt.max_iterations);
  sol.beta1 = r.beta1;
  sol.beta2 = r.beta2;
  sol.delta1 = r.delta1;
  sol.delta2 = r.delta2;
  sol.width = r.width;
  sol.log_width = r.log_width;
  sol.iterations = r.iterations;
  sol.dirR = -1;
  sol.dirL = 1;
  sol.settle_empty_zones();
  return sol;
}

}}  // namespace hs::core
