// Sampled pressures at a cost linear in the sample count (issue 13 item 4): the
// knot path (core/knots.hpp: product rules on a tree over the interpolant's
// segments and cumulative tails; core/general_knots.hpp: energies and slips on
// knot panels with per-panel orders; core/fmm1d.hpp: fast Cauchy sums), taken
// from sampled_pressure::knot_tree_min interior samples on, against
//  - the Hertz closed forms (samples of a Hertz pressure: phi is constant, the
//    interpolant exact, so only rounding separates the two at any n),
//  - the n = 4 power-law model (its own closed-form F, the panel path): the
//    sampling error of the PCHIP interpolant falls like n^-3.5 (measured
//    n = 1e3 .. 3e4: 2.5e-9, 5.1e-11, 7.7e-13 in d1 relative; the slope errors
//    of the harmonic-mean derivative are O(h^2) and telescope in the integrals)
//    down to rounding,
//  - the panel path on the same samples (a panel end at every sample, the
//    O(n^2) method before issue 13), for rough and asymmetric samples,
//    mirrored and negated scenes and a large sigma,
//  - direct summation (the fast multipole sums).
// Observed: zones within 102 eps (q = 0.999, ill-conditioned near gross
// sliding; ~10 eps elsewhere), energies within 4e-14, slips within 4e-14.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "halfslip/core/fields.hpp"
#include "halfslip/core/fmm1d.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "testing.hpp"

namespace core = hs::core;

namespace {

const double EPS = std::numeric_limits<double>::epsilon();
// the energies' and slips' order control stops when two orders agree to
// max(rtol, eps^(3/4)) (general_post.hpp, energy_tol): their accuracy bound
const double ETOL = std::pow(EPS, 0.75);

core::general_scene<double> scene_of(double p0, double q, double s) {
  core::general_scene<double> sc;
  sc.a = 1;
  sc.p0 = p0;
  sc.f = 1;
  sc.Estar = 1;
  sc.q = q;
  sc.s = s;
  return sc;
}

// n + 1 samples of phi(x) sqrt(1 - x^2) at uniform or Chebyshev-Lobatto points, p = 0 at +-1
template <class F> void samples(std::size_t n, bool cheb, const F &phi, std::vector<double> &xs, std::vector<double> &ps) {
  xs.clear();
  ps.clear();
  for (std::size_t i = 0; i <= n; ++i) {
    double x = cheb ? -std::cos(M_PI * double(i) / double(n)) : -1.0 + 2.0 * double(i) / double(n);
    if (i == 0) x = -1;
    if (i == n) x = 1;
    xs.push_back(x);
    ps.push_back(i == 0 || i == n ? 0.0 : std::sqrt((1 - x) * (1 + x)) * phi(x));
  }
}

}  // namespace

TEST_CASE("knot path: samples of a Hertz pressure give the closed forms at n = 1e4 and 1e5") {
  struct scene {
    double q, s;
  };
  // same sign, opposite sign, mirrored (sigma < 0), negated (Q < 0), large sigma, near gross sliding, small loads
  const scene scenes[] = {{0.3, 1}, {0.9, 0.3}, {0.6, -2}, {-0.4, 0.7}, {0.5, 30}, {0.999, 0}, {0.02, 0}};
  std::vector<double> xs, ps;
  for (std::size_t n : {std::size_t(10000), std::size_t(100000)}) {
    const bool cheb = n == 100000;  // uniform, and clustered at the edges
    samples(n, cheb, [](double) { return 1.0; }, xs, ps);
    core::sampled_pressure<double> sp(xs, ps, 1.0);
    CHECK(sp.knots());
    // P = pi/2 from the compensated cumulative sums: p0 = 1 within rounding
    CHECK(std::abs(sp.p0() - 1) < 4 * EPS);
    for (const auto &c : scenes) {
      // n = 1e5: three scenes (run time)
      if (n == 100000 && !(c.s == 1 || c.s == -2 || c.s == 30)) continue;
      CAPTURE(n);
      CAPTURE(c.q);
      CAPTURE(c.s);
      const auto g = core::solve_general<double>(sp, scene_of(sp.p0(), c.q, c.s));
      core::hertz_scene<double> hs = scene_of(1, c.q, c.s);
      const auto h = core::solve_hertz(hs);
      CHECK(g.reg == h.reg);
      // 450 eps: the bound of the sampled-Hertz test of test_general.cpp (the
      // solver's residual tolerance, amplified by the conditioning near q = 1)
      CHECK(std::abs(g.d1() - h.d1()) < 450 * EPS);
      CHECK(std::abs(g.d2() - h.d2()) < 450 * EPS);
      const double s2 = sp.p0() * sp.p0();  // energies scale with p0^2, slips with p0
      CHECK(std::abs(g.energy(1) / s2 - h.energy(1)) <= ETOL * h.energy(1));
      CHECK(std::abs(g.energy(2) / s2 - h.energy(2)) <= ETOL * h.energy(2));
      if (n == 10000) {
        const double frac = c.q > 0.5 ? 0.93 : 0.37;
        const double x1 = h.b1() + frac * (1 - h.b1()), x2 = -h.b2() - frac * (1 - h.b2());
        if (h.d1() > 0) CHECK(std::abs(g.slip(x1) / sp.p0() - h.slip(x1)) <= ETOL * (std::abs(h.slip(x1)) + 1e-3));
        if (h.d2() > 0) CHECK(std::abs(g.slip(x2) / sp.p0() - h.slip(x2)) <= ETOL * (std::abs(h.slip(x2)) + 1e-3));
      }
    }
  }
}

TEST_CASE("knot path: the sampling error of a power-law pressure falls like n^-3.5, to rounding") {
  core::power_law_pressure<double> p4(4);  // phi = (2/3)(1 + 2x^2): PCHIP is not exact
  const double q = 0.3, s = 1;
  const auto m = core::solve_general<double>(p4, scene_of(1, q, s));
  const double E1 = m.energy(1), E2 = m.energy(2);
  std::vector<double> xs, ps;
  auto err = [&](std::size_t n, double &dd, double &de) {
    samples(n, false, [&](double x) { return p4.phi(x, 1 + x, 1 - x); }, xs, ps);
    core::sampled_pressure<double> sp(xs, ps, 1.0);
    const auto g = core::solve_general<double>(sp, scene_of(sp.p0(), q, s));
    const double s2 = sp.p0() * sp.p0();
    dd = std::max(std::abs(g.d1() - m.d1()), std::abs(g.d2() - m.d2()));
    de = std::max(std::abs(g.energy(1) / s2 - E1) / E1, std::abs(g.energy(2) / s2 - E2) / E2);
  };
  double d1k, e1k, d3k, e3k, dhk, ehk;
  err(1000, d1k, e1k);
  err(3000, d3k, e3k);
  err(100000, dhk, ehk);
  // order >= 3 between n = 1000 and 3000 (measured 3.5: ratio 48 in d, 44 in E)
  CHECK(d1k / d3k > 27);
  CHECK(e1k / e3k > 27);
  // and not yet at rounding there (so that the ratio measures the sampling error)
  CHECK(d3k > 1e-13);
  // n = 1e5: n^-3.5 puts the sampling error near 1e-19: rounding only
  CHECK(dhk < 450 * EPS);
  CHECK(ehk <= ETOL);
}

TEST_CASE("knot path and panel path agree on the same samples (rough, asymmetric, not reaching the edges)" * HS_LONG) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  const std::size_t n = 300;  // above knot_tree_min interior samples; the panel path costs O(n^2)
  REQUIRE(n - 1 >= core::sampled_pressure<double>::knot_tree_min);
  for (int kind = 0; kind < 3; ++kind) {
    std::vector<double> xs, ps;
    if (kind == 2) {
      // interior samples only, -0.95 .. 0.95: long linear end segments
      for (std::size_t i = 0; i <= n; ++i) {
        const double x = -0.95 + 1.9 * double(i) / double(n);
        xs.push_back(x);
        ps.push_back(std::sqrt((1 - x) * (1 + x)) * (1 + 0.4 * x));
      }
    } else if (kind == 1) {
      // asymmetric with relative noise 1e-3 at every sample (curvature jumps O(1/h^2))
      samples(n, false, [&](double x) { return (1 + 0.3 * x) * (1 + 1e-3 * U(rng)); }, xs, ps);
    } else {
      samples(n, true, [](double x) { return 1 + 0.3 * x + 0.5 * std::sin(3 * x); }, xs, ps);
    }
    core::sampled_pressure<double> K(xs, ps, 1.0), P(xs, ps, 1.0, nullptr, std::size_t(-1));
    REQUIRE(K.knots());
    REQUIRE(!P.knots());
    // the normalisations: compensated cumulative sums against tanh-sinh over every segment
    CHECK(std::abs(K.p0() - P.p0()) < 16 * EPS);
    for (double c : {1e-9, 0.003, 0.5, 1.3, 1.999})
      for (int side : {-1, 1}) CHECK(std::abs(K.tail(side, c) - P.tail(side, c)) <= 1e-14 * P.tail(side, c));
    const std::vector<std::pair<double, double>> all{{0.3, 1}, {0.6, -2}, {-0.4, 0.7}, {0.5, 30}};
    // two scenes per kind (the panel path's energies cost O(n^2)), every scene at least once
    for (const auto &qs : {all[kind % 4], all[(kind + 2 + kind / 2) % 4]}) {
      CAPTURE(kind);
      CAPTURE(qs.first);
      CAPTURE(qs.second);
      const auto a = core::solve_general<double>(K, scene_of(K.p0(), qs.first, qs.second));
      // the panel path at the same state (the quantities below, not a second solve)
      auto b = a;
      b.pm = &P;
      b.owned.reset();
      if (a.mirror && !P.symmetric()) {
        b.owned = std::make_shared<core::mirrored_pressure<double>>(P);
        b.pm = b.owned.get();
      }
      // and a solve of its own: zones
      const auto bs = core::solve_general<double>(P, scene_of(K.p0(), qs.first, qs.second));
      CHECK(a.reg == bs.reg);
      CHECK(std::abs(a.d1() - bs.d1()) < 450 * EPS);
      CHECK(std::abs(a.d2() - bs.d2()) < 450 * EPS);
      for (int z : {1, 2}) {
        const double ea = a.energy(z), eb = b.energy(z);
        CHECK(std::abs(ea - eb) <= 2 * ETOL * eb);
      }
      const double b1 = a.b1(), b2 = a.b2();
      for (double x : {b1 + 0.37 * (1 - b1), b1 + 1e-3 * (1 - b1), -b2 - 0.61 * (1 - b2), 0.999}) {
        if (!(std::abs(x) < 1)) continue;
        CAPTURE(x);
        CHECK(std::abs(a.slip(x) - b.slip(x)) <= 2 * ETOL * (std::abs(b.slip(x)) + 1e-3));
      }
      // B_x across both zones (the points of `halfslip solve --points 3` among them;
      // with rough samples a target next to a knot once missed the graded panels:
      // 7e-11): tanh-sinh terminated at eps^(2/3) on the panel path, 1e-12
      for (double fr : {1e-3, 0.05, 0.2, 1.0 / 3, 0.5, 2.0 / 3, 0.9, 0.999}) {
        for (double x : {b1 + fr * (1 - b1), -b2 - fr * (1 - b2)}) {
          if (!(std::abs(x) < 1)) continue;
          CAPTURE(x);
          CHECK(std::abs(a.Bx(x) - b.Bx(x)) <= 1e-12 * (std::abs(b.Bx(x)) + 1));
        }
      }
      // the stick-zone traction (tanh-sinh on both paths)
      for (double f : {0.5, 0.01}) {
        const double x = b1 - f * (b1 + b2);
        CHECK(std::abs(a.traction(x) - b.traction(x)) <= 1e-12 * (std::abs(b.traction(x)) + 1));
      }
      // surface and subsurface stresses: the knot path's tree Cauchy integrals
      // against the panel path's cached panels
      auto sa = core::general_state_of(a);
      auto sb = core::general_state_of(b);
      CHECK(!core::needs_panels(sa));
      sb.panels = core::make_panels(sb);
      for (double x : {-1.7, -0.99, 0.3, 1.2}) {
        for (int body : {1, 2}) {
          CAPTURE(x);
          CAPTURE(body);
          // the panels' quadrature: 20-point rules, error < 1e-13 (fields.hpp)
          CHECK(std::abs(core::surface_sxx(sa, body, x) - core::surface_sxx(sb, body, x)) < 1e-12);
        }
        const auto ta = core::stress_at(sa, 1, x, 0.1), tb = core::stress_at(sb, 1, x, 0.1);
        CHECK(std::abs(ta.xx - tb.xx) < 1e-12);
        CHECK(std::abs(ta.yy - tb.yy) < 1e-12);
        CHECK(std::abs(ta.xy - tb.xy) < 1e-12);
      }
    }
  }
}

TEST_CASE("treecode Cauchy sums equal the direct sums (uniform, clustered, one-sided, long double)") {
  // cauchy_treecode: one target at a time (static_history's new traction on sampled pressures)
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int mode = 0; mode < 3; ++mode) {
    const std::size_t nx = 5000, ny = 700;
    std::vector<std::pair<double, double>> src(nx);
    std::vector<double> y(ny);
    // 0: uniform; 1: clustered over 40 binades towards 0; 2: sources on (0, 1] graded towards 0
    // and targets on (-1, 0] (a band and the stick zone: the static history's layout)
    // (a continuous mantissa: with +-2^-k alone every target would equal a source and be skipped)
    auto clus = [&] { return std::ldexp((U(rng) > 0 ? 1.0 : -1.0) * (1.5 + U(rng) / 2), -int(40 * std::abs(U(rng)))); };
    for (auto &s : src) {
      s.first = mode == 0 ? U(rng) : mode == 1 ? clus() : std::abs(clus());
      s.second = U(rng);
    }
    for (auto &v : y) v = mode == 0 ? U(rng) : mode == 1 ? clus() : -std::abs(U(rng) > 0 ? clus() : U(rng));
    core::cauchy_treecode<double> tc(src, 16);
    double worst = 0;
    std::size_t checked = 0;
    for (const double yj : y) {
      double s = 0, a = 0;
      bool hit = false;
      for (const auto &p : src) {
        hit = hit || p.first == yj;
        s += p.second / (p.first - yj);
        a += std::abs(p.second / (p.first - yj));
      }
      if (hit) continue;
      ++checked;
      worst = std::max(worst, std::abs(tc(yj) - s) / a);
    }
    CAPTURE(mode);
    CAPTURE(tc.terms());
    REQUIRE(checked > 600);
    // truncation (5/3) 4^-m <= eps/4 (fmm1d.hpp) plus the rounding of both sums: measured up to
    // a few eps
    CHECK(worst < 64 * EPS);
  }
  // long double: the term count follows the type's epsilon (where it is longer than double)
  if (std::numeric_limits<long double>::digits <= std::numeric_limits<double>::digits) return;
  std::vector<std::pair<long double, long double>> src;
  for (int k = 0; k < 3000; ++k) src.emplace_back(0.001L + k / 3000.0L, 1.0L + (k % 7));
  core::cauchy_treecode<long double> tl(src, 16);
  CHECK(tl.terms() > core::cauchy_treecode<double>(std::vector<std::pair<double, double>>{{0.5, 1.0}}).terms());
  for (long double yv : {-0.7L, -1e-3L, -1e-9L}) {
    long double s = 0, a = 0;
    for (const auto &p : src) {
      s += p.second / (p.first - yv);
      a += std::abs(p.second / (p.first - yv));
    }
    CHECK(std::abs(tl(yv) - s) / a < 64 * std::numeric_limits<long double>::epsilon());
  }
  // no sources: zero
  CHECK(core::cauchy_treecode<double>(std::vector<std::pair<double, double>>{})(0.3) == 0);
}

TEST_CASE("fast multipole Cauchy sums equal the direct sums (uniform and clustered points)") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int mode = 0; mode < 2; ++mode) {
    const std::size_t nx = 3000, ny = 2000;
    std::vector<double> x(nx), y(ny), q0(nx), q1(nx);
    // clustered: geometric towards 0 over 40 binades (the graded panels at a stick edge)
    auto draw = [&] { return mode == 0 ? U(rng) : std::ldexp(U(rng) > 0 ? 1.0 : -1.0, -int(40 * std::abs(U(rng)))); };
    for (auto &v : x) v = draw();
    for (auto &v : y) v = draw();
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    for (std::size_t i = 0; i < nx; ++i) {
      q0[i] = U(rng);
      q1[i] = 1;
    }
    std::vector<double> f0(ny, 0), f1(ny, 0);
    core::cauchy_fmm<double> fmm(x.data(), nx, y.data(), ny, 16);
    const double *q[2] = {q0.data(), q1.data()};
    double *out[2] = {f0.data(), f1.data()};
    fmm.apply(2, q, out, [&](std::size_t ja, std::size_t jb, std::size_t ia, std::size_t ib) {
      for (std::size_t j = ja; j < jb; ++j)
        for (std::size_t i = ia; i < ib; ++i)
          if (x[i] != y[j]) {
            f0[j] += q0[i] / (x[i] - y[j]);
            f1[j] += q1[i] / (x[i] - y[j]);
          }
    });
    double worst = 0;
    for (std::size_t j = 0; j < ny; ++j) {
      double s0 = 0, s1 = 0, a0 = 0, a1 = 0;
      for (std::size_t i = 0; i < nx; ++i) {
        if (x[i] == y[j]) continue;
        const double k = 1 / (x[i] - y[j]);
        s0 += q0[i] * k;
        s1 += q1[i] * k;
        a0 += std::abs(q0[i] * k);
        a1 += std::abs(k);
      }
      worst = std::max({worst, std::abs(f0[j] - s0) / a0, std::abs(f1[j] - s1) / a1});
    }
    CAPTURE(mode);
    // truncation after p = 24 terms at separation 3 max(r): (1/4)^24/(3/4) =
    // 5e-15 per expansion relative to sum |q|/|x - y| (fmm1d.hpp), plus the
    // rounding of both sums and of the shifts down ~40 levels (clustered:
    // measured 1.8e-14)
    CHECK(worst < 256 * EPS);
  }
}
