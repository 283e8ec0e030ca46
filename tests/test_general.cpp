// General pressures (issue #4): the general solver of core/general.hpp for
// Hertz (against the closed forms of core/hertz.hpp), the flat punch with
// rounded corners, the power law, sampled and callback pressures.
//
// Canonical units: a = 1, p0 = 1, f = 1, E* = 1 unless a scene says otherwise.
// Tolerances: the solver's lengths come from a Newton iteration stopped at
// the residual's rounding floor (residual terms O(pi (1 + s)), Jacobian O(1)),
// so lengths are good to a few eps absolute in double; bounds of 450 eps
// (= 1e-13) leave a factor ~100 for the conditioning of the scenes used.
// Independent checks integrate the raw side conditions in long double by
// tanh-sinh (reference/oracle.hpp integrate_ends, split at the pressure kinks)
// and are compared at the residual floor of the long double solution,
// 64 eps pi (1 + |s|) (observed: below 16 eps).
// Tolerances are in units of eps of the type under test (EPS: double, EPS_LD:
// long double; issue 12 item 7). The decimal figures left are not rounding
// bounds (quadrature termination rules, interpolation, continuity) and say why.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/reference/oracle.hpp"
#include "testing.hpp"

namespace core = hs::core;
namespace ref = hs::reference;
using LD = long double;
using mp50 =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<50>, boost::multiprecision::et_off>;
const double EPS = std::numeric_limits<double>::epsilon();  // 2.2e-16
const LD EPS_LD = std::numeric_limits<LD>::epsilon();       // 1.1e-19
// residual floor of a long double solution (64 eps pi (1 + |s|)): the bound on
// its raw side conditions and on its lengths against 50 digits
LD ld_floor(LD s) { return 64 * boost::math::constants::pi<LD>() * (1 + std::abs(s)) * EPS_LD; }

namespace {

template <class T> core::general_solution<T> gsolve(const core::pressure_model<T> &pm, T q, T s, T rtol = 0) {
  core::general_scene<T> sc;
  sc.q = q;
  sc.s = s;
  core::general_options<T> opt;
  opt.rtol = rtol;
  return core::solve_general(pm, sc, opt);
}

core::hertz_solution<double> hsolve(double q, double s) {
  core::hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  return core::solve_hertz(sc);
}

// Raw side conditions (11)/(12) for a general pressure, by tanh-sinh in T on
// the physical variable t, split at the pressure breakpoints. Canonical units.
//   r1 = sL int_L p/R - sR int_R p/R - pi s/4
//   r2 = sL int_L p t/R - sR int_R p t/R - pi s (b1-b2)/8 + pi q/2
template <class T>
std::array<T, 2> raw_side(const core::pressure_model<T> &pm, T q, T s, T b1, T b2, int sR, int sL) {
  using std::sqrt;
  const T pi = boost::math::constants::pi<T>();
  std::array<T, 2> r{};
  auto zone = [&](T lo, T hi, int j, bool right) {
    std::vector<T> cuts{lo, hi};
    for (const auto &bp : pm.breakpoints())
      if (bp.x > lo && bp.x < hi) cuts.push_back(bp.x);
    std::sort(cuts.begin(), cuts.end());
    T sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const T a = cuts[i], b = cuts[i + 1];
      sum += ref::integrate_ends<T>(
          [&](const T &t, const T &da, const T &db) {
            // exact distances where an end is a zone end
            const T dm = (a == T(-1)) ? da : 1 + t;
            const T dp = (b == T(1)) ? db : 1 - t;
            const T p = pm.p(t, dm, dp);
            const T u = right ? ((a == lo) ? da : t - b1) : ((b == hi) ? db : -b2 - t);
            const T v = right ? t + b2 : b1 - t;
            return p * (j == 1 ? T(1) : t) / sqrt(u * v);
          },
          a, b);
    }
    return sum;
  };
  for (int j = 1; j <= 2; ++j) {
    const T L = b2 < 1 ? zone(T(-1), -b2, j, false) : T(0);
    const T R = b1 < 1 ? zone(b1, T(1), j, true) : T(0);
    r[j - 1] = sL * L - sR * R;
  }
  r[0] -= pi * s / 4;
  r[1] += -pi * s * (b1 - b2) / 8 + pi * q / 2;
  return r;
}

}  // namespace

// ---------------------------------------------------------------------------
TEST_CASE("Gauss-Legendre rules in T integrate polynomials exactly") {
  for (int n : {3, 8, 17, 64}) {
    const auto r = core::gauss_legendre<LD>(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      LD sum = 0;
      for (int i = 0; i < n; ++i) sum += r->w[i] * std::pow(r->x[i], k);
      const LD exact = k % 2 ? 0 : LD(2) / (k + 1);
      CHECK(std::abs(double(sum - exact)) < 64 * EPS_LD);
    }
  }
}

TEST_CASE("pressure models: normalisation int p = pi/2, sqrt edges, Hertz limits") {
  const LD pi = boost::math::constants::pi<LD>();
  core::flat_rounded_pressure<LD> f0(0), f3(0.3L), f9(0.9L);
  core::power_law_pressure<LD> p15(1.5L), p2(2), p3(3), p4(4), p37(3.05L);
  core::hertz_pressure<LD> hz;
  for (const core::pressure_model<LD> *m :
       std::vector<const core::pressure_model<LD> *>{&hz, &f0, &f3, &f9, &p15, &p2, &p3, &p4, &p37}) {
    // total load: tail over the whole contact (quadrature split at kinks;
    // tanh-sinh stopped at sqrt(eps), converged quadratically: a sum of positive
    // terms with a few eps; observed <= 11 eps): 64 eps
    CHECK(std::abs(m->tail(+1, LD(2)) - pi / 2) < 64 * EPS_LD);
    // phi = p / sqrt(1 - x^2) finite and positive at both edges
    CHECK(m->phi(1 - 1e-12L, 2 - 1e-12L, 1e-12L) > 0);
    // continuity, not rounding: the change of phi over a distance 1e-6 is below 1e-4 when |phi'| < 100
    CHECK(std::abs(double(m->phi(1 - 1e-12L, 2 - 1e-12L, 1e-12L) - m->phi(1 - 1e-6L, 2 - 1e-6L, 1e-6L))) < 1e-4);
  }
  // b_f = 0 and n = 2 are Hertz (p <= 1: a few roundings of sqrt and the
  // series/polynomial; observed <= 5 eps): 8 eps absolute
  for (LD x : {0.0L, 0.3L, -0.77L, 0.999L}) {
    CHECK(std::abs(f0.p(x) - hz.p(x)) < 8 * EPS_LD);
    CHECK(std::abs(p2.p(x) - hz.p(x)) < 8 * EPS_LD);
    // n = 4: p = (2/3)(1 + 2x^2) sqrt(1 - x^2)
    CHECK(std::abs(p4.p(x) - (1 + 2 * x * x) * std::sqrt(1 - x * x) * 2 / 3) < 8 * EPS_LD);
  }
  // flat-rounded: continuous at the kink, p(x) from the original formula
  for (LD x : {0.1L, 0.5L, 0.95L}) {
    const LD ph0 = std::asin(0.3L), ph = std::asin(x);
    const LD br = (pi - 2 * ph0) * std::cos(ph) +
                  std::sin(ph) * std::log(std::abs(std::sin(ph + ph0) / std::sin(ph - ph0))) +
                  std::sin(ph0) * std::log(std::abs(std::tan((ph + ph0) / 2) * std::tan((ph - ph0) / 2)));
    // both sides: sums of O(1) logarithmic terms in long double, each a few eps
    // (the direct formula is evaluated in the type under test too): 64 eps
    CHECK(std::abs(f3.p(x) - br / (pi - 2 * ph0 - std::sin(2 * ph0))) < 64 * EPS_LD);
  }
  // continuity at the kink, not rounding: p' is log-singular there, so the jump
  // over 2e-12 is ~ 2e-12 |log 1e-12| ~ 6e-11
  CHECK(std::abs(double(f3.p(0.3L + 1e-12L) - f3.p(0.3L - 1e-12L))) < 1e-10);
}

// ---------------------------------------------------------------------------
TEST_CASE("Hertz through the general path matches the closed forms in every regime") {
  core::hertz_pressure<double> hp;
  struct sc {
    double q, s;
  };
  const double e34 = std::pow(EPS, 0.75);
  const std::vector<sc> scenes{{0.3, 0.2},  {0.7, 0.5},   {0.95, 0.1},  {0.3, 0.0},   {0.999, 0.0}, {0.0, 0.5},
                               {0.0, 3.0},  {0.6, 1.5},   {0.9, 3.0},   {0.2, 5.0},   {0.5, 20.0},  {-0.4, 0.3},
                               {0.4, -2.0}, {-0.6, -1.0}, {0.05, 0.09}, {1e-6, 1e-6}, {0.8, 2.21}};
  for (const auto &c : scenes) {
    CAPTURE(c.q);
    CAPTURE(c.s);
    const auto g = gsolve<double>(hp, c.q, c.s);
    const auto h = hsolve(c.q, c.s);
    CHECK(g.reg == h.reg);
    CHECK(g.dir1() == h.dir1());
    CHECK(g.dir2() == h.dir2());
    CHECK(std::abs(g.b1() - h.b1()) <= 450 * EPS);
    CHECK(std::abs(g.b2() - h.b2()) <= 450 * EPS);
    CHECK(g.order > 0);
    // B_x and slip at interior points of both zones. B_x is a sum of two
    // tanh-sinh integrals (termination eps^(2/3), quadratic convergence) of
    // O(1) size times R(x) <= 2: 1e-12 relative to max(1, |B|). The slip
    // integrates B_x once more (nested tanh-sinh): 1e-11. Both are kept as
    // absolute figures: they are set by the termination rule of the adaptive
    // quadrature (eps^(2/3) = 3.7e-11 per level), not by rounding; the B_x
    // bound is nearly reached (observed 9.9e-13 in this table).
    for (double frac : {0.1, 0.5, 0.9}) {
      for (double x : {g.b1() + frac * g.d1(), -g.b2() - frac * g.d2()}) {
        if (!(x > g.b1()) && !(x < -g.b2())) continue;
        CAPTURE(x);
        const double Bg = g.Bx(x), Bh = h.Bx(x);
        CHECK(std::abs(Bg - Bh) <= 1e-12 * std::max(1.0, std::abs(Bh)));
        CHECK(std::abs(g.slip(x) - h.slip(x)) <= 1e-11 * std::max(1.0, std::abs(h.slip(x))));
      }
    }
    if (c.q != 1e-6) {
      // energies: Gauss-Legendre orders doubled until two agree to eps^(3/4)
      // (general.hpp); 32 eps^(3/4) = 5.8e-11 (was 1e-10)
      CHECK(std::abs(g.energy(1) - h.energy(1)) <= 32 * e34 * std::max(1e-3, h.energy(1)));
      CHECK(std::abs(g.energy(2) - h.energy(2)) <= 32 * e34 * std::max(1e-3, h.energy(2)));
    }
  }
}

TEST_CASE("Hertz general path is dimensionally consistent (a, p0, f, E*)") {
  core::hertz_pressure<double> hp;
  core::general_scene<double> sc;
  sc.a = 2.5;
  sc.p0 = 3;
  sc.f = 0.4;
  sc.Estar = 7;
  sc.q = 0.5;
  sc.s = 0.8;
  core::hertz_scene<double> hs;
  hs.a = 2.5;
  hs.p0 = 3;
  hs.f = 0.4;
  hs.Estar = 7;
  hs.q = 0.5;
  hs.s = 0.8;
  const auto g = core::solve_general(hp, sc);
  const auto h = core::solve_hertz(hs);
  CHECK(std::abs(g.b1() - h.b1()) < 450 * EPS * 2.5);
  CHECK(std::abs(g.b2() - h.b2()) < 450 * EPS * 2.5);
  const double x = g.b1() + 0.4 * g.d1();
  CHECK(std::abs(g.Bx(x) - h.Bx(x)) < 1e-12 * std::abs(h.Bx(x)));
  CHECK(std::abs(g.slip(x) - h.slip(x)) < 1e-11 * std::abs(h.slip(x)));
  CHECK(std::abs(g.work(x) - h.work(x)) < 1e-11 * std::abs(h.work(x)));
  // (B_x, slip, work: adaptive-quadrature figures as above; energy: 32 eps^(3/4))
  CHECK(std::abs(g.energy(2) - h.energy(2)) < 32 * std::pow(EPS, 0.75) * h.energy(2));
}

// ---------------------------------------------------------------------------
TEST_CASE("shear only and bulk only: b1 = b2, eqs (15) and (18) by independent quadrature") {
  core::flat_rounded_pressure<double> f5(0.5);
  core::power_law_pressure<double> p3(3), p15(1.5);
  core::flat_rounded_pressure<LD> f5l(0.5L);
  core::power_law_pressure<LD> p3l(3), p15l(1.5L);
  const std::vector<std::pair<const core::pressure_model<double> *, const core::pressure_model<LD> *>> models{
      {&f5, &f5l}, {&p3, &p3l}, {&p15, &p15l}};
  const LD pi = boost::math::constants::pi<LD>();
  for (const auto &m : models) {
    // eq (15): int_b^1 t p/sqrt(t^2 - b^2) = Q/(2f) = pi q/4 (units p0 a)
    for (double q : {0.2, 0.6, 0.95}) {
      const auto g = gsolve<double>(*m.first, q, 0.0);
      CHECK(g.reg == core::regime::same_sign);
      CHECK(std::abs(g.b1() - g.b2()) < 45 * EPS);
      const LD b = g.b1();
      std::vector<LD> cuts{b, 1};
      for (const auto &bp : m.second->breakpoints())
        if (bp.x > b) cuts.push_back(bp.x);
      std::sort(cuts.begin(), cuts.end());
      LD I = 0;
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        I += ref::integrate_ends<LD>(
            [&](const LD &t, const LD &da, const LD &db) {
              const LD u = i == 0 ? da : t - b;
              const LD dp = (i + 2 == cuts.size()) ? db : 1 - t;
              return t * m.second->p(t, 1 + t, dp) / std::sqrt(u * (t + b));
            },
            cuts[i], cuts[i + 1]);
      CHECK(std::abs(double(I - pi * q / 4)) < 450 * EPS);
    }
    // eq (18): int_b^1 p/sqrt(t^2 - b^2) = sigma pi/(8 f) (units p0)
    for (double s : {0.3, 2.0, 8.0}) {
      const auto g = gsolve<double>(*m.first, 0.0, s);
      CHECK(g.reg == core::regime::opposite_sign);
      CHECK(std::abs(g.b1() - g.b2()) < 45 * EPS);
      CHECK(g.dir1() == -g.dir2());
      const LD b = g.b1();
      std::vector<LD> cuts{b, 1};
      for (const auto &bp : m.second->breakpoints())
        if (bp.x > b) cuts.push_back(bp.x);
      std::sort(cuts.begin(), cuts.end());
      LD I = 0;
      for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        I += ref::integrate_ends<LD>(
            [&](const LD &t, const LD &da, const LD &db) {
              const LD u = i == 0 ? da : t - b;
              const LD dp = (i + 2 == cuts.size()) ? db : 1 - t;
              return m.second->p(t, 1 + t, dp) / std::sqrt(u * (t + b));
            },
            cuts[i], cuts[i + 1]);
      // residual scale pi s/8; b has ~1e-16 error, dI/db ~ 1/b
      CHECK(std::abs(double(I - pi * s / 8)) < 450 * EPS * (1 + s));
    }
  }
}

TEST_CASE("Ciavarella-Jager: stick half-width = contact half-width under P(1 - Q/fP)") {
  for (double n : {1.5, 2.0, 3.0, 4.0}) {
    core::power_law_pressure<double> pm(n);
    for (double q : {0.1, 0.5, 0.9, 0.99}) {
      CAPTURE(n);
      CAPTURE(q);
      const auto g = gsolve<double>(pm, q, 0.0);
      const double c = std::pow(1 - q, 1 / n);  // P ~ a^n
      CHECK(std::abs(g.b1() - c) < 450 * EPS);
      CHECK(std::abs(g.b2() - c) < 450 * EPS);
    }
  }
  for (double bf : {0.3, 0.7, 0.95}) {
    core::flat_rounded_pressure<double> pm(bf);
    for (double q : {0.1, 0.5, 0.9, 0.999}) {
      CAPTURE(bf);
      CAPTURE(q);
      const auto g = gsolve<double>(pm, q, 0.0);
      const double c = core::flat_rounded_pressure<double>::reduced_load_half_width(bf, q);
      CHECK(c > bf);
      CHECK(std::abs(g.b1() - c) < 450 * EPS);
      CHECK(std::abs(g.b2() - c) < 450 * EPS);
      // c from the dimensional P(a) relation: a(P) and a(P(1-q)) for b_f = bf, A = R = 1
      const double P = 1.0 * 1.0 * core::flat_rounded_pressure<double>::load_factor(bf) / 2;  // a = 1
      const double a1 = core::flat_rounded_pressure<double>::half_width_from_load(P, 1.0, 1.0, bf);
      const double ac = core::flat_rounded_pressure<double>::half_width_from_load(P * (1 - q), 1.0, 1.0, bf);
      CHECK(std::abs(a1 - 1) < 45 * EPS);
      CHECK(std::abs(ac - c) < 45 * EPS);
    }
  }
}

// ---------------------------------------------------------------------------
// b_f/a from the load from 1e-20 (b_f/a = 1 - 4e-15) to 1e300, g(b_f/a)/(b_f/a)^2 = 2ARP/b_f^2
// (fuzz_dimensional, CI 2026-11-27: at 1.4e235 the root search stopped at b_f/a = 2.2e-103,
// 1e14 times the root, where its step overflowed). The residual of g(beta) = target beta^2
// is evaluated in 50-digit MPFR at the double beta: the root to a few ulps of beta.
TEST_CASE("flat-rounded: b_f/a from the load, targets 1e-20 to 1e300") {
  using fr = core::flat_rounded_pressure<double>;
  using M = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<50>>;
  for (int k = -20; k <= 300; k += 4) {
    for (double m : {1.0, 3.7}) {
      const double target = m * std::pow(10.0, k);
      CAPTURE(target);
      const double a = fr::half_width_from_load(target / 2, 1.0, 1.0, 1.0);  // b_f = 1: a = 1/beta
      const double b = 1 / a;
      REQUIRE(b > 0);
      REQUIRE(b < 1);
      // F(b) = g(b) - target b^2 and the change of F over one ulp of b: the root within 4 ulps
      const M bm(b), tm(target), y = 2 * acos(bm);
      const M F = (y - sin(y)) - tm * bm * bm;
      const M dF = abs(-4 * sqrt(1 - bm * bm) - 2 * tm * bm) * M(b) * EPS;
      CHECK(abs(F) <= 4 * dF);
    }
  }
}

// ---------------------------------------------------------------------------
TEST_CASE("flat-rounded and power law: double vs long double, and the raw side conditions") {
  struct sc {
    double q, s;
  };
  const std::vector<sc> scenes{{0.4, 0.1}, {0.4, 0.5}, {0.4, 2.0}, {0.8, 1.0}, {0.2, 6.0}, {0.0, 1.0}, {0.9, 0.05}};
  for (double bf : {0.3, 0.7, 0.95}) {
    core::flat_rounded_pressure<double> md(bf);
    core::flat_rounded_pressure<LD> ml(bf);
    for (const auto &c : scenes) {
      CAPTURE(bf);
      CAPTURE(c.q);
      CAPTURE(c.s);
      const auto gd = gsolve<double>(md, c.q, c.s);
      const auto gl = gsolve<LD>(ml, c.q, c.s);
      CHECK(gd.reg == gl.reg);
      CHECK(std::abs(double(gd.b1() - gl.b1())) < 450 * EPS);
      CHECK(std::abs(double(gd.b2() - gl.b2())) < 450 * EPS);
      const auto r = raw_side<LD>(ml, c.q, c.s, gl.b1(), gl.b2(), gl.dir1(), gl.dir2());
      CHECK(std::abs(r[0]) < ld_floor(c.s));
      CHECK(std::abs(r[1]) < ld_floor(c.s));
    }
  }
  for (double n : {1.5, 2.5, 3.0, 4.0, 6.0}) {
    core::power_law_pressure<double> md(n);
    core::power_law_pressure<LD> ml(n);
    for (const auto &c : scenes) {
      CAPTURE(n);
      CAPTURE(c.q);
      CAPTURE(c.s);
      const auto gd = gsolve<double>(md, c.q, c.s);
      const auto gl = gsolve<LD>(ml, c.q, c.s);
      CHECK(gd.reg == gl.reg);
      CHECK(std::abs(double(gd.b1() - gl.b1())) < 450 * EPS);
      CHECK(std::abs(double(gd.b2() - gl.b2())) < 450 * EPS);
      const auto r = raw_side<LD>(ml, c.q, c.s, gl.b1(), gl.b2(), gl.dir1(), gl.dir2());
      CHECK(std::abs(r[0]) < ld_floor(c.s));
      CHECK(std::abs(r[1]) < ld_floor(c.s));
    }
  }
}

TEST_CASE("MPFR 50 digits: flat-rounded and power law agree with long double") {
  const mp50 bf("0.7");
  core::flat_rounded_pressure<mp50> fm(bf);
  core::flat_rounded_pressure<LD> fl(0.7L);
  core::power_law_pressure<mp50> pm(mp50("1.5"));
  core::power_law_pressure<LD> pl(1.5L);
  const mp50 q("0.4"), s("2");
  const auto a = gsolve<mp50>(fm, q, s);
  const auto b = gsolve<LD>(fl, 0.4L, 2.0L);
  CHECK(a.reg == b.reg);
  // long double lengths carry ~1e-18 (residual floor 64 eps_ld pi (1+s), Jacobian O(1))
  CHECK(std::abs(LD(a.b1() - mp50(b.b1()))) < ld_floor(2));
  CHECK(std::abs(LD(a.b2() - mp50(b.b2()))) < ld_floor(2));
  // and the 50-digit solution satisfies its own 2n-order residual far below double eps
  // (absolute figure: the quadrature order is doubled until two orders agree to
  // eps^(3/4) ~ 1e-37 of the 50-digit type; 1e-40 checks it converged well past that)
  const auto r = core::general_residual<mp50>(
      fm, q, s, core::general_state<mp50>{a.reg == core::regime::opposite_sign ? mp50(-a.delta1) : a.delta1, a.width},
      2 * a.order, false);
  CHECK(abs(r.F1) < mp50("1e-40"));
  CHECK(abs(r.F2) < mp50("1e-40"));
  const auto c = gsolve<mp50>(pm, q, mp50("0.3"));
  const auto d = gsolve<LD>(pl, 0.4L, 0.3L);
  CHECK(std::abs(LD(c.b1() - mp50(d.b1()))) < ld_floor(0.3L));
  CHECK(std::abs(LD(c.b2() - mp50(d.b2()))) < ld_floor(0.3L));
  // Ciavarella-Jager at 50 digits: c/a = (1 - q)^(1/n) (absolute figure as above)
  const auto e = gsolve<mp50>(pm, q, mp50(0));
  CHECK(abs(e.b1() - pow(1 - q, 1 / mp50("1.5"))) < mp50("1e-40"));
}

// ---------------------------------------------------------------------------
// Full traction q = q_st + corrective traction of the dislocations (eq 3):
//   q(x) = (q/2 - s x/4)/sqrt(1-x^2) + 1/(2 pi sqrt(1-x^2)) int_zones sqrt(1-xi^2) B(xi)/(xi - x) dxi
// (canonical units; Q/pi = q/2 in units f p0 a). Stick zone: |q| <= p; slip
// zone: q = dir p (principal value by subtraction).
namespace {
// Zone integrals in u = d sin^2(theta) (smooth: sqrt(u) at the stick end,
// sqrt(d - u) at the contact edge), Gauss-Legendre of order 48 per piece;
// the principal value subtracts G(theta_x) (PV int_0^{pi/2} dth/(sin^2 th - c) = 0).
template <class T> T traction(const core::general_solution<T> &g, const T &q, const T &s, const T &x) {
  using std::asin;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T pi = boost::math::constants::pi<T>();
  const auto rule = core::gauss_legendre<T>(48);
  T sum = 0;
  for (int z : {+1, -1}) {
    const T d = g.zone_length(z);
    if (!(d > 0)) continue;
    // xi = b1 + u (z = +1), xi = -b2 - u (z = -1), u = d sin^2 th; dxi-measure du = 2 d sin cos dth
    auto G = [&](const T &th) {
      const T sn = sin(th), cs = cos(th);
      const T u = d * sn * sn, c = d * cs * cs;  // c: distance to the contact edge
      return sqrt(c * (2 - c)) * g.bhat(z, u) * 2 * d * sn * cs;
    };
    // pieces split at the pressure kinks (B_x has (t - k) log^2-type terms
    // there) with the sigmoidal map th = lo + L u^4/(u^4 + (1-u)^4) grading both ends
    std::vector<T> kth;
    for (const auto &bp : g.pm->breakpoints()) {
      const T dist = z > 0 ? bp.x - g.beta1 : -g.beta2 - bp.x;
      if (dist > 0 && dist < d) kth.push_back(asin(sqrt(dist / d)));
    }
    auto gl1 = [&](const T &lo, const T &hi, const auto &f) {
      T r = 0;
      for (std::size_t i = 0; i < rule->x.size(); ++i) {
        const T u = (1 + rule->x[i]) / 2, v = 1 - u;
        const T u4 = u * u * u * u, v4 = v * v * v * v, den = u4 + v4;
        const T ph = u4 / den, dph = 4 * u * u * u * v * v * v / (den * den);
        r += rule->w[i] * dph * f(lo + (hi - lo) * ph);
      }
      return r * (hi - lo) / 2;
    };
    auto gl = [&](const T &lo, const T &hi, const auto &f) {
      std::vector<T> c{lo, hi};
      for (const T &k : kth)
        if (k > lo && k < hi) c.push_back(k);
      std::sort(c.begin(), c.end());
      T r = 0;
      for (std::size_t i = 0; i + 1 < c.size(); ++i) r += gl1(c[i], c[i + 1], f);
      return r;
    };
    const bool inside = z > 0 ? (x > g.beta1) : (x < -g.beta2);
    if (!inside) {
      sum += gl(T(0), pi / 2, [&](const T &th) {
        const T sn = sin(th);
        const T xi = z > 0 ? g.beta1 + d * sn * sn : -g.beta2 - d * sn * sn;
        return G(th) / (xi - x);
      });
    } else {
      const T ux = z > 0 ? x - g.beta1 : -g.beta2 - x;
      const T thx = asin(sqrt(ux / d));
      const T Gx = G(thx);
      const T s2x = sin(thx) * sin(thx);
      // xi - x = z d (sin^2 th - sin^2 thx)
      auto f = [&](const T &th) {
        const T sn = sin(th);
        return (G(th) - Gx) / (z * d * (sn * sn - s2x));
      };
      sum += gl(T(0), thx, f) + gl(thx, pi / 2, f);
    }
  }
  const T w = sqrt((1 - x) * (1 + x));
  return (q / 2 - s * x / 4) / w + sum / (2 * pi * w);
}
}  // namespace

TEST_CASE("full traction: |q| <= f p in the stick zone, q = +-f p in the slip zones") {
  core::flat_rounded_pressure<double> fr(0.6);
  core::power_law_pressure<double> pl(3);
  struct sc {
    const core::pressure_model<double> *m;
    double q, s;
  };
  for (const auto &c : std::vector<sc>{{&fr, 0.5, 0.3}, {&fr, 0.4, 3.0}, {&pl, 0.6, 1.5}}) {
    CAPTURE(c.q);
    CAPTURE(c.s);
    const auto g = gsolve<double>(*c.m, c.q, c.s);
    // stick zone: strictly inside the friction limit away from its ends (1e-9:
    // the nested-quadrature accuracy of the traction, not rounding)
    int n_in = 0;
    for (int i = 1; i < 10; ++i) {
      const double x = -g.beta2 + (g.beta1 + g.beta2) * i / 10.0;
      const double t = traction<double>(g, c.q, c.s, x), p = c.m->p(x);
      CAPTURE(x);
      CHECK(std::abs(t) <= p * (1 + 1e-9));
      n_in += std::abs(t) < p;
    }
    CHECK(n_in >= 8);
    // slip zones: q = dir p. Nested tanh-sinh (B_x inside a principal value):
    // agreement to 1e-7 relative to p0 is what the nested tolerances give.
    for (double frac : {0.2, 0.5, 0.8}) {
      for (int z : {+1, -1}) {
        if (!(g.zone_length(z) > 0)) continue;
        const double x = z > 0 ? g.beta1 + frac * g.delta1 : -g.beta2 - frac * g.delta2;
        const int dir = z > 0 ? g.dirR : g.dirL;
        CAPTURE(x);
        CHECK(std::abs(traction<double>(g, c.q, c.s, x) - dir * c.m->p(x)) < 1e-7);
      }
    }
  }
}

// ---------------------------------------------------------------------------
TEST_CASE("sampled and callback pressures: Hertz reproduced, bad pressures rejected") {
  const double a = 2.0, p0 = 3.0;
  // Hertz samples at Chebyshev-Lobatto points including the edges (p = 0 there)
  std::vector<double> xs, ps;
  const int N = 41;
  for (int i = 0; i < N; ++i) {
    const double x = -a * std::cos(M_PI * i / (N - 1));
    xs.push_back(i == 0 ? -a : (i == N - 1 ? a : x));
    ps.push_back(i == 0 || i == N - 1 ? 0.0 : p0 * std::sqrt((a - x) * (a + x)) / a);
  }
  core::sampled_pressure<double> sp(xs, ps, a);
  // phi = p / sqrt(a^2 - x^2) is the constant p0/a: interpolation is exact up
  // to the rounding of the samples, and P = pi a p0 / 2 to quadrature accuracy.
  CHECK(std::abs(sp.p0() - p0) < 45 * EPS * p0);
  for (const auto &c : std::vector<std::pair<double, double>>{{0.3, 0.2}, {0.6, 1.5}, {0.0, 0.7}, {0.5, 0.0}}) {
    const auto g = gsolve<double>(sp, c.first, c.second);
    const auto h = hsolve(c.first, c.second);
    CHECK(g.reg == h.reg);
    CHECK(std::abs(g.b1() - h.b1()) < 450 * EPS);
    CHECK(std::abs(g.b2() - h.b2()) < 450 * EPS);
  }
  // A non-constant phi: samples of the n = 4 power law (phi = (2/3)(1 + 2x^2)),
  // 201 uniform points. PCHIP interpolation of a smooth phi: O(h^3) away from
  // the extremum at 0, O(h^2) there (slope set to 0), h = 0.01 -> ~1e-5 in phi;
  // the lengths follow to the same order: bound 1e-4.
  {
    core::power_law_pressure<double> p4(4);
    std::vector<double> x4, q4;
    for (int i = 0; i <= 200; ++i) {
      const double x = -1 + i / 100.0;
      x4.push_back(x);
      q4.push_back(i == 0 || i == 200 ? 0.0 : p4.p(x));
    }
    core::sampled_pressure<double> s4(x4, q4, 1.0);
    for (const auto &c : std::vector<std::pair<double, double>>{{0.3, 0.2}, {0.6, 1.5}}) {
      const auto g = gsolve<double>(s4, c.first, c.second);
      const auto h = gsolve<double>(p4, c.first, c.second);
      CHECK(std::abs(g.b1() - h.b1()) < 1e-4);
      CHECK(std::abs(g.b2() - h.b2()) < 1e-4);
    }
  }
  // callback (std::function and function pointer + user data)
  core::callback_pressure<double> cb([&](const double &x) { return p0 * std::sqrt((a - x) * (a + x)) / a; }, a);
  CHECK(std::abs(cb.p0() - p0) < 450 * EPS * p0);
  {
    const auto g = gsolve<double>(cb, 0.6, 1.5);
    const auto h = hsolve(0.6, 1.5);
    CHECK(std::abs(g.b1() - h.b1()) < 450 * EPS);
    CHECK(std::abs(g.b2() - h.b2()) < 450 * EPS);
  }
  struct ud {
    double a;
  };
  ud u{1.0};
  core::callback_pressure<double> cb2(
      [](const double &x, void *p) {
        const double A = static_cast<ud *>(p)->a;
        return std::sqrt((A - x) * (A + x));
      },
      &u, 1.0);
  CHECK(std::abs(cb2.p0() - 2 / M_PI * M_PI / 2) < 450 * EPS);

  auto code_of = [](auto f) {
    try {
      f();
    } catch (const core::error &e) {
      return e.code();
    }
    return core::status::ok;
  };
  // negative pressure
  {
    auto bad = ps;
    bad[N / 2] = -1;
    CHECK(code_of([&] { core::sampled_pressure<double>(xs, bad, a); }) == core::status::bad_geometry);
  }
  // pressure vanishing linearly at the edges (flat-like exponent 1)
  {
    std::vector<double> lp;
    for (double x : xs) lp.push_back(a - std::abs(x));
    CHECK(code_of([&] { core::sampled_pressure<double>(xs, lp, a); }) == core::status::bad_geometry);
    CHECK(code_of([&] { core::callback_pressure<double>([&](const double &x) { return a - std::abs(x); }, a); }) ==
          core::status::bad_geometry);
  }
  // pressure not vanishing at the edges (rigid flat punch: 1/sqrt)
  {
    std::vector<double> fp;
    for (double x : xs) fp.push_back(std::abs(x) < a ? 1 / std::sqrt((a - x) * (a + x)) : 0.0);
    CHECK(code_of([&] { core::sampled_pressure<double>(xs, fp, a); }) == core::status::bad_geometry);
    std::vector<double> cp(xs.size(), 1.0);
    CHECK(code_of([&] { core::sampled_pressure<double>(xs, cp, a); }) == core::status::bad_geometry);
    CHECK(code_of([&] { core::callback_pressure<double>([](const double &) { return 1.0; }, a); }) ==
          core::status::bad_geometry);
  }
  // callback negative inside
  CHECK(code_of([&] {
          core::callback_pressure<double>(
              [&](const double &x) { return std::sqrt(a * a - x * x) * (x > 0.5 ? -1 : 1); }, a);
        }) == core::status::bad_geometry);
  // bad models
  CHECK(code_of([] { core::power_law_pressure<double>(1.0); }) == core::status::bad_geometry);
  CHECK(code_of([] { core::flat_rounded_pressure<double>(1.0); }) == core::status::bad_geometry);
}

TEST_CASE("asymmetric sampled pressure: sigma < 0 is the mirror image of sigma > 0") {
  // p = sqrt(1 - x^2)(1 + 0.3 x): asymmetric, positive, sqrt edges
  std::vector<double> xs, ps, xm, pm;
  for (int i = 0; i <= 100; ++i) {
    const double x = -std::cos(M_PI * i / 100);
    const double xx = i == 0 ? -1 : (i == 100 ? 1 : x);
    xs.push_back(xx);
    ps.push_back(i == 0 || i == 100 ? 0 : std::sqrt(1 - xx * xx) * (1 + 0.3 * xx));
  }
  for (int i = 100; i >= 0; --i) {
    xm.push_back(-xs[i]);
    pm.push_back(ps[i]);
  }
  core::sampled_pressure<double> A(xs, ps, 1.0), M(xm, pm, 1.0);
  CHECK(!A.symmetric());
  for (const auto &c : std::vector<std::pair<double, double>>{{0.4, 0.3}, {0.4, 2.0}, {0.5, 0.0}}) {
    const auto g = gsolve<double>(A, c.first, -c.second);
    const auto h = gsolve<double>(M, c.first, c.second);
    CHECK(std::abs(g.b1() - h.b2()) < 450 * EPS);
    CHECK(std::abs(g.b2() - h.b1()) < 450 * EPS);
    CHECK(g.dir1() == h.dir2());
    // the solution satisfies the raw side conditions of the unmirrored pressure
    core::sampled_pressure<LD> Al(std::vector<LD>(xs.begin(), xs.end()), std::vector<LD>(ps.begin(), ps.end()), 1.0L);
    const auto r = raw_side<LD>(Al, LD(c.first), LD(-c.second), LD(g.b1()), LD(g.b2()), g.dir1(), g.dir2());
    // (sigma < 0 in the user frame: the side conditions hold as written there;
    // the solution is double's: its residual floor 64 eps pi (1 + |s|))
    const double floor_d = 64 * M_PI * (1 + c.second) * EPS;
    CHECK(std::abs(double(r[0])) < floor_d);
    CHECK(std::abs(double(r[1])) < floor_d);
  }
}

// ---------------------------------------------------------------------------
// Zone energies and slips by the fixed Gauss-Legendre rules (energy_hat,
// hhat: outer order M, inner M + 1, doubled until agreement to eps^(3/4))
// against (a) the Hertz closed forms through hertz_pressure, (b) the nested
// adaptive tanh-sinh evaluation (energy_hat_adaptive, hhat_adaptive; slow,
// independent quadrature) for the flat punch b_f/a = 0.45 and a power law,
// (c) long double and 50-digit MPFR. Observed agreement ~1e-15 (energies) and
// a few 1e-14 (slips, limited by the adaptive reference's eps^(2/3)
// termination); bounds 1e-13 and 1e-12.
TEST_CASE("zone energies and slips by fixed rules: Hertz, adaptive reference, long double, MPFR") {
  core::hertz_pressure<double> hp;
  for (const auto &c : std::vector<std::pair<double, double>>{
           {0.3, 0.2}, {0.7, 0.5}, {0.6, 1.5}, {0.3, 0.0}, {0.2, 5.0}, {-0.4, 0.3}, {0.4, -2.0}}) {
    CAPTURE(c.first);
    CAPTURE(c.second);
    const auto g = gsolve<double>(hp, c.first, c.second);
    const auto h = hsolve(c.first, c.second);
    for (int i : {1, 2}) {
      const double Eh = h.energy(i);
      CHECK(std::abs(g.energy(i) - Eh) <= 450 * EPS * Eh);
    }
    // (near the stick edge h ~ u^(3/2): the ~1e-16 difference of the stick
    // edges alone moves h by 1.5e-16/u relative; frac >= 0.05 keeps that small)
    for (double frac : {0.05, 0.3, 0.97}) {
      for (double x : {g.b1() + frac * g.d1(), -g.b2() - frac * g.d2()}) {
        if (!(x > g.b1()) && !(x < -g.b2())) continue;
        CAPTURE(x);
        CHECK(std::abs(g.slip(x) - h.slip(x)) <= 450 * EPS * std::abs(h.slip(x)));
      }
    }
  }
  core::flat_rounded_pressure<double> fd(0.45);
  core::flat_rounded_pressure<LD> fl(0.45L);
  core::power_law_pressure<double> pd(1.5);
  core::power_law_pressure<LD> pl(1.5L);
  struct sc {
    const core::pressure_model<double> *md;
    const core::pressure_model<LD> *ml;
    double q, s;
  };
  // (the adaptive references cost ~0.3 s each: four scenes, both regimes, two geometries)
  for (const auto &c :
       std::vector<sc>{{&fd, &fl, 1e-3, 3e-4}, {&fd, &fl, 0.5, 0.15}, {&fd, &fl, 0.4, 2.0}, {&pd, &pl, 0.6, 0.18}}) {
    CAPTURE(c.q);
    CAPTURE(c.s);
    const auto g = gsolve<double>(*c.md, c.q, c.s);
    for (int z : {+1, -1}) {
      CAPTURE(z);
      const double E = g.energy_hat(z), Ea = g.energy_hat_adaptive(z);
      CHECK(E > 0);
      CHECK(std::abs(E - Ea) <= 450 * EPS * Ea);
      for (double frac : {0.02, 0.6}) {
        const double dl = frac * g.zone_length(z);
        const double hs = g.hhat_adaptive(z, dl);
        // (absolute figure: the adaptive reference terminates at eps^(2/3) = 3.7e-11)
        CHECK(std::abs(g.hhat(z, dl) - hs) <= 1e-12 * std::abs(hs));
      }
    }
    // long double (the solution itself is conditioned to ~1e-15 for q >= 0.1)
    if (c.q >= 0.1) {
      const auto gl = gsolve<LD>(*c.ml, LD(c.q), LD(c.s));
      for (int i : {1, 2}) {
        const LD El = gl.energy(i);
        CHECK(std::abs(double((g.energy(i) - El) / El)) <= 450 * EPS);
      }
    }
  }
  // 50 digits: the order grows with the precision (flat punch, both regimes; beyond double the kinks get geometric
  // layers and a high-order inner rule, see general.hpp: ~0.5 s per scene)
  for (const auto &qs : std::vector<std::pair<const char *, const char *>>{{"0.4", "0.12"}, {"0.4", "2"}}) {
    const mp50 bf("0.45");
    core::flat_rounded_pressure<mp50> fm(bf);
    const auto gm = gsolve<mp50>(fm, mp50(qs.first), mp50(qs.second));
    const auto gl = gsolve<LD>(fl, std::stold(qs.first), std::stold(qs.second));
    for (int i : {1, 2}) {
      const mp50 Em = gm.energy(i);
      // long double energies (conditioned to a few tens of eps; observed < 58 eps): 512 eps
      CHECK(abs(Em - mp50(gl.energy(i))) / Em < mp50(512 * EPS_LD));
    }
  }
}

// ---------------------------------------------------------------------------
// Issue 16: B_x, the slip and the zone energies from the zone expansions
// (core/general_expansion.hpp) against the paths they replace, kept callable,
// run in long double on the long-double solution of the same scene (the
// double solution is given that state rounded to double, so that what is
// judged is the evaluation): the adaptive Cauchy integrals at the point
// (bhat_direct), the fixed-rule slip and energies (hhat_fixed,
// energy_hat_fixed; orders doubled until two agree; within 1e-6 of a kink,
// where no two orders agree, the nested adaptive hhat_adaptive); and, in double, the
// nested adaptive slip (hhat_adaptive, a different method). Flat punch
// (a kink inside zone L of the opposite-sign scene), power laws, a callback
// Hertz pressure and 41 samples (a plain kink at every sample); both regimes,
// a mirrored scene (sigma < 0), a negated one (Q < 0) and a large sigma
// (stick width 1e-10 a, ~18 panels per zone). Points from 1e-9 of the zone
// length next to the stick edge to 1e-9 next to the contact edge, and 1e-6
// on either side of every kink. The MPFR comparison is in test_reference.cpp.
// Bounds:
// - B_x: 2 R K_error(theta) + 32 eps |B_x|, K_error the expansion's estimate
//   (the node values' rounding, ~eps |K|/theta_1 next to the stick edge, and
//   the truncation; zone_expansion::K_error), the state's half-ulp rounding
//   and the long-double path's own error within the 32 eps;
// - h = int_0^dl B_x: 2 dl R K_error + 32 eps |h| (R K_error grows with dl);
// - energies: 32 eps (both converged to a few eps; observed <= 10 eps);
// - h against hhat_adaptive (double), away from the stick edge and large
//   sigma: 1e-12 |h|, the adaptive reference's eps^(2/3) termination (as the
//   test of the fixed rules above).
TEST_CASE("issue 16: expansions of B_x against the fixed-rule and adaptive paths" * HS_LONG) {
  core::flat_rounded_pressure<double> f5(0.5);
  core::flat_rounded_pressure<LD> f5l(0.5L);
  core::power_law_pressure<double> p15(1.5), p3(3);
  core::power_law_pressure<LD> p15l(1.5L), p3l(3);
  core::callback_pressure<double> cb([](const double &x) { return std::sqrt((1 - x) * (1 + x)); }, 1.0);
  core::callback_pressure<LD> cbl([](const LD &x) { return std::sqrt((1 - x) * (1 + x)); }, 1.0L);
  std::vector<double> xs, ps;
  std::vector<LD> xsl, psl;
  for (int i = 0; i <= 40; ++i) {
    const double x = -std::cos(M_PI * i / 40);
    xs.push_back(i == 0 ? -1.0 : (i == 40 ? 1.0 : x));
    ps.push_back(i == 0 || i == 40 ? 0.0 : p3.p(x));
    xsl.push_back(xs.back());
    psl.push_back(ps.back());
  }
  core::sampled_pressure<double> sp(xs, ps, 1.0);
  core::sampled_pressure<LD> spl(xsl, psl, 1.0L);
  struct sc {
    const core::pressure_model<double> *pm;
    const core::pressure_model<LD> *pl;
    const char *name;
    double q, s;
  };
  const std::vector<sc> scenes{{&f5, &f5l, "flat 0.5", 0.3, 0.0},       {&f5, &f5l, "flat 0.5", 0.5, 3.0},
                               {&f5, &f5l, "flat 0.5", 0.6, -0.5},      {&f5, &f5l, "flat 0.5", -0.4, 0.3},
                               {&f5, &f5l, "flat 0.5", 0.4, 50.0},      {&p15, &p15l, "power 1.5", 0.6, 0.18},
                               {&p3, &p3l, "power 3", 0.2, 2.0},        {&cb, &cbl, "callback Hertz", 0.5, 1.0},
                               {&sp, &spl, "41 samples", 0.3, 0.5}};
  double worst_B = 0, worst_h = 0, worst_E = 0, worst_ha = 0;
  int kinks = 0;
  for (const auto &c : scenes) {
    const std::string name = c.name;
    CAPTURE(name);
    CAPTURE(c.q);
    CAPTURE(c.s);
    auto g = gsolve<double>(*c.pm, c.q, c.s);
    const auto l = gsolve<LD>(*c.pl, LD(c.q), LD(c.s));
    REQUIRE(g.reg == l.reg);
    REQUIRE(g.mirror == l.mirror);
    g.delta1 = double(l.delta1);
    g.delta2 = double(l.delta2);
    g.beta1 = double(l.beta1);
    g.beta2 = double(l.beta2);
    g.width = double(l.width);
    g.log_width = double(l.log_width);
    const auto *x = g.expansion();  // made now, from this state
    REQUIRE(x != nullptr);
    for (int z : {+1, -1}) {
      CAPTURE(z);
      const double d = g.zone_length(z);
      if (!(d > 0)) continue;
      std::vector<double> dls;
      for (double f : {1e-9, 1e-4, 0.02, 0.3, 0.5, 0.9, 1 - 1e-4, 1 - 1e-9}) dls.push_back(f * d);
      for (const double k : g.kink_distances(z)) {
        ++kinks;
        for (double f : {1 - 1e-6, 1 + 1e-6}) dls.push_back(f * k);
      }
      for (const double dl : dls) {
        CAPTURE(dl / d);
        const double B = g.bhat(z, dl), h = g.hhat(z, dl);
        // (the fixed rules cut their panels at the point: within 1e-6 of a kink
        // no two orders agree; the nested adaptive slip answers there)
        const LD Bl = l.bhat_direct(z, LD(dl));
        LD hl;
        try {
          hl = l.hhat_fixed(z, LD(dl));
        } catch (const core::error &) {
          hl = l.hhat_adaptive(z, LD(dl));
        }
        const double R = std::sqrt(dl * (g.width + dl)), Ke = x->at(z).K_error(g.theta_of(z, dl));
        const double eB = double(std::abs(LD(B) - Bl)) / (2 * R * Ke + 32 * EPS * double(std::abs(Bl)));
        const double eh = double(std::abs(LD(h) - hl)) / (2 * dl * R * Ke + 32 * EPS * double(std::abs(hl)));
        INFO("B " << B << " (long double " << double(Bl) << "), h " << h << " (" << double(hl) << "), K_error "
                  << Ke);
        CHECK(eB <= 1);
        CHECK(eh <= 1);
        worst_B = std::max(worst_B, eB);
        worst_h = std::max(worst_h, eh);
        if (dl >= 0.02 * d && c.s < 10) {
          const double ha = g.hhat_adaptive(z, dl);
          const double ea = std::abs(h - ha) / std::abs(ha);
          CHECK(ea <= 1e-12);
          worst_ha = std::max(worst_ha, ea);
        }
      }
      const LD El = l.energy_hat_fixed(z);
      const double eE = double(std::abs((LD(g.energy_hat(z)) - El) / El)) / EPS;
      CHECK(eE <= 32);
      worst_E = std::max(worst_E, eE);
    }
  }
  CHECK(kinks >= 12);
  // beyond the set-up's budget (general_solution::expansion_max_pairs: a power
  // law of n = 200 at sigma/fp0 = 100, panels at 2^k/n from the edges and down
  // to the stick width ~1e-40 a) there is no expansion and the old paths answer
  {
    core::power_law_pressure<double> p200(200);
    const auto g = gsolve<double>(p200, 0.3, 100.0);
    CHECK(g.expansion() == nullptr);
    CHECK(g.energy_hat(-1) == g.energy_hat_fixed(-1));
    const double dl = 0.5 * g.zone_length(-1);
    CHECK(g.bhat(-1, dl) == g.bhat_direct(-1, dl));
  }
  MESSAGE("expansions vs the long-double old paths (fraction of the bound): B_x " << worst_B << ", h " << worst_h
                                                                                  << "; energies " << worst_E
                                                                                  << " eps; h vs hhat_adaptive "
                                                                                  << worst_ha);
}

// Issue 16 (the solve): Newton steps taken without evaluating the residual there
// (general_problem::shortcut: a step below the step tolerance on the first
// iteration, or one whose successor K s^2 is below it, with K carried from
// one quadrature order to the next; only for pressures with an exact phi').
// The check of the scratch grid (1458 solves over b_f/a 0 to 0.99, the power
// law and Hertz, Q/fP -0.5 to 0.999, sigma/fp0 -2 to 1e4) in small: same
// regime and order as before, b1 and b2 within max(16 eps, conditioning) of
// the long double solve (observed on the grid: at most 8.6 eps where the
// conditioning estimate is below 16 eps, as before the change), and the
// quadrature estimate bounds the true error (here within 0.19 of it). And the pressure evaluations of
// the four flat-punch scenes of bench_general (a count, deterministic, not a
// timing): 48, 160, 280, 376 at rtol 1e-12 (before: 64, 192, 328, 408).
namespace {
struct counting_pressure final : core::pressure_model<double> {
  const core::pressure_model<double> &b;
  mutable long calls = 0;
  explicit counting_pressure(const core::pressure_model<double> &b_) : b(b_) {}
  double phi(const double &x, const double &dm, const double &dp) const override {
    ++calls;
    return b.phi(x, dm, dp);
  }
  double phi_dphi(const double &x, const double &dm, const double &dp, double &d) const override {
    ++calls;
    return b.phi_dphi(x, dm, dp, d);
  }
  std::vector<core::breakpoint<double>> breakpoints() const override { return b.breakpoints(); }
  bool shear_only_half_width(const double &q, double &c) const override { return b.shear_only_half_width(q, c); }
  double accuracy_eps() const override { return b.accuracy_eps(); }
  bool symmetric() const override { return b.symmetric(); }
  bool exact_dphi() const override { return b.exact_dphi(); }
};
}  // namespace

TEST_CASE("issue 16: the solve's unevaluated Newton steps keep double within a few eps of long double") {
  core::flat_rounded_pressure<double> f5(0.5), f9(0.9), f99(0.99);
  core::flat_rounded_pressure<LD> f5l(0.5L), f9l(0.9L), f99l(0.99L);
  core::hertz_pressure<double> hz;
  core::hertz_pressure<LD> hzl;
  struct geo {
    const core::pressure_model<double> *pm;
    const core::pressure_model<LD> *pl;
  };
  const std::vector<geo> geos{{&f5, &f5l}, {&f9, &f9l}, {&f99, &f99l}, {&hz, &hzl}};
  const double qs[] = {-0.5, 0.2, 0.3, 0.5, 0.6, 0.99};
  const double ss[] = {0.0, 0.3, 2.0, 3.0, 100.0};
  int n = 0;
  for (const auto &g : geos)
    for (double q : qs)
      for (double s : ss) {
        const auto gl = gsolve<LD>(*g.pl, q, s);
        for (double rt : {0.0, 1e-12}) {
          CAPTURE(q);
          CAPTURE(s);
          CAPTURE(rt);
          const auto gd = gsolve<double>(*g.pm, q, s, rt);
          CHECK(gd.reg == gl.reg);
          // the conditioning (units of a) where larger: near sliding and at large sigma.
          // The final Newton step's residual is known to its rounding, which moves b
          // by up to ~the conditioning: over the grid at most 0.85 of it, before and
          // after this change; here at most 0.55 (b_f/a = 0.99, Q/fP = 0.99,
          // sigma/fp0 = 0.3, rtol 0: 64 eps, 28 eps before) and 0.26 elsewhere
          const double tol = std::max(16 * EPS, gd.conditioning);
          CHECK(std::abs(double(gd.b1() - gl.b1())) <= tol);
          CHECK(std::abs(double(gd.b2() - gl.b2())) <= tol);
          const auto e = core::quadrature_estimate<double>(rt, gd.d1(), gd.d2(), gd.width, q, g.pm->accuracy_eps(),
                                                           gd.conditioning);
          if (gd.d1() > 0) CHECK(std::abs(double(gd.d1() - gl.d1())) <= e.slip_zone * gd.d1());
          if (gd.d2() > 0) CHECK(std::abs(double(gd.d2() - gl.d2())) <= e.slip_zone * gd.d2());
          ++n;
        }
      }
  CHECK(n == 240);
  // the pressure evaluations of the four flat-punch scenes of bench_general
  const struct {
    double q, s;
    long calls;
  } bench[] = {{0.3, 0.0, 48}, {0.6, 0.3, 160}, {0.2, 2.0, 280}, {0.5, 3.0, 376}};
  for (const auto &b : bench) {
    CAPTURE(b.q);
    CAPTURE(b.s);
    counting_pressure cp(f5);
    gsolve<double>(cp, b.q, b.s, 1e-12);
    CHECK(cp.calls <= b.calls);  // (before the unevaluated steps: 64, 192, 328, 408; <=: the count may
                                 // move with a compiler's rounding, not up past these)
  }
}

// Issue 13 (bounded time): at high orders h' at the outer nodes goes by the fast multipole sum of the
// knot path (general_solution::hgrad_nodes; a kinked callback's energies at order 1024 took 10 s by
// the direct sums). Both against the same discrete sum in long double (the same nodes, weights and
// densities, converted exactly: only the summation's rounding differs), many panels per zone (flat
// punch kinks, a callback with declared kinks, the power law's cusp at n = 1.05), orders on both
// sides of the switch. The direct sums themselves round to up to ~300 eps of max |h'| next to the
// cusp (a review's measurement); the fast sum's truncation is ~1e-16 of sum |q|/distance
// (fmm1d.hpp). Asserted: the fast sum within its direct sums' own error plus 32 eps of max |h'|, and
// hgrad_nodes is the fast sum above the switch and the direct sums below it (bitwise).
namespace {
std::vector<long double> hgrad_ld(const core::general_solution<double> &sol, int z,
                                  const core::gdetail::zone_nodes<double> &O,
                                  const core::gdetail::zone_nodes<double> &IR,
                                  const core::gdetail::zone_nodes<double> &IL) {
  using LD = long double;
  const LD e = sol.width;
  std::vector<LD> g(O.s2.size());
  for (std::size_t j = 0; j < O.s2.size(); ++j) {
    const LD sj = O.s2[j], cj = O.c2[j], u = LD(O.d) * sj;
    LD br = 0;
    for (int Z : {+1, -1}) {
      const int dir = Z > 0 ? sol.dirR : sol.dirL;
      const auto &I = Z > 0 ? IR : IL;
      if (dir == 0 || !(I.d > 0)) continue;
      LD sum = 0;
      for (std::size_t i = 0; i < I.s2.size(); ++i) {
        if (Z == z) {
          const LD den = (LD(I.s2[i]) + sj < 1) ? LD(I.s2[i]) - sj : cj - LD(I.c2[i]);
          if (den != 0) sum += LD(I.w[i]) * (LD(I.H[i]) - LD(O.H[j])) / den;
        } else {
          sum += LD(I.w[i]) * LD(I.H[i]) / (e + u + LD(I.d) * LD(I.s2[i]));
        }
      }
      if (Z == z) sum /= LD(I.d);
      br += LD(dir) * sum;
    }
    g[j] = -2 * std::sqrt(u * (e + u)) * br / boost::math::constants::pi<LD>();
  }
  return g;
}
}  // namespace

TEST_CASE("issue 13: h' by the fast multipole sum against the direct sums at high orders") {
  core::flat_rounded_pressure<double> f5(0.5);
  core::power_law_pressure<double> p15(1.5), p105(1.05);
  core::callback_pressure<double> cb(
      [](const double &x) {
        const double h = 1 - std::abs(x - 0.3) / 0.05;
        return std::sqrt((1 - x) * (1 + x)) - (h > 0 ? 0.2 * h : 0.0);
      },
      1.0, std::vector<double>{0.25, 0.3, 0.35});
  const struct {
    const core::pressure_model<double> *pm;
    double q, s;
  } cases[] = {{&f5, 0.5, 0.5}, {&f5, 0.3, 2.0}, {&p15, 0.3, 2.0}, {&p105, 0.9, 2.0}, {&p105, 0.99, 3.6},
               {&cb, 0.6, 0.4}, {&cb, 0.2, 1.5}};
  int fmm_used = 0;
  double worst_fmm = 0, worst_direct = 0;
  for (const auto &c : cases) {
    core::general_scene<double> sc;
    sc.q = c.q;
    sc.s = c.s;
    const auto sol = core::solve_general(*c.pm, sc);
    for (int z : {+1, -1})
      for (int M : {128, 512, 1024}) {
        const double d = sol.zone_length(z);
        if (!(d > 0)) continue;
        CAPTURE(c.q);
        CAPTURE(c.s);
        CAPTURE(z);
        CAPTURE(M);
        auto O = core::gdetail::make_zone_nodes<double>(*sol.pm, z, d, sol.width, M);
        const auto IR = core::gdetail::make_zone_nodes<double>(*sol.pm, +1, sol.delta1, sol.width, M + 1);
        const auto IL = core::gdetail::make_zone_nodes<double>(*sol.pm, -1, sol.delta2, sol.width, M + 1);
        const auto a = sol.hgrad_nodes_direct(z, O, IR, IL, O.s2.size());
        const auto b = core::gdetail::knot_hgrad(z, O, IR, IL, O.s2.size(), sol.dirR, sol.dirL, sol.width);
        const auto t = hgrad_ld(sol, z, O, IR, IL);
        REQUIRE(a.size() == t.size());
        REQUIRE(b.size() == t.size());
        double scale = 0, ea = 0, eb = 0;
        for (std::size_t j = 0; j < t.size(); ++j) scale = std::max(scale, double(std::fabs(t[j])));
        for (std::size_t j = 0; j < t.size(); ++j) {
          ea = std::max(ea, double(std::fabs(a[j] - t[j])));
          eb = std::max(eb, double(std::fabs(b[j] - t[j])));
        }
        CHECK(eb <= ea + 32 * EPS * scale);
        worst_fmm = std::max(worst_fmm, eb / scale / EPS);
        worst_direct = std::max(worst_direct, ea / scale / EPS);
        const bool fmm = double(O.s2.size()) * double(IR.s2.size() + IL.s2.size()) >
                         core::general_solution<double>::fmm_pairs();
        fmm_used += fmm;
        const auto g = sol.hgrad_nodes(z, O, IR, IL, O.s2.size());
        CHECK(g == (fmm ? b : a));
      }
  }
  MESSAGE("largest error against the long double sums, units of eps of max |h'|: fast " << worst_fmm << ", direct "
                                                                                         << worst_direct);
  CHECK(fmm_used > 0);
}
