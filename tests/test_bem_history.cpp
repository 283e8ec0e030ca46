// The load-history BEM oracle (reference/include/halfslip/reference/bem_history.hpp) checked against
// closed forms, so that it can in turn check the library's load-history solver.
//
// Units: a = 1, p0 = 1, f = 1, E* = 1 (docs/conventions.md). The oracle's zone ends are mesh nodes of
// the cosine mesh x_k = -cos(pi k/N), whose spacing near x = b is about (pi/N) sqrt(1 - b^2); the
// tolerances on b below are stated in those element widths. Run `test_bem_history -s` to see the
// measured errors and timings.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "halfslip/reference/bem_history.hpp"

namespace bem = hs::reference::bem;

namespace {

const double pi = 3.141592653589793238462643383279502884;

double hertz(double x) { return std::sqrt(std::max(0.0, 1 - x * x)); }

// element width of the cosine mesh near x
double width(int n, double x) { return pi / n * std::sqrt(std::max(1 - x * x, 0.0)) + 2.0 / (n * n); }

struct timer {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double s() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};

std::string fmt(const char *f, double a, double b = 0, double c = 0, double d = 0, double e = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d, e);
  return buf;
}

// Closed-form monotonic Hertz energy per zone at sigma = 0 (stick half-width c = sqrt(1 - Q)):
// E = int_c^1 sqrt(1 - x^2) h(x) dx, h(x) = x sqrt(x^2 - c^2) - c^2 ln((x + sqrt(x^2 - c^2))/c),
// integrated by the midpoint rule in theta (x = cos theta), fine enough for 1e-10.
double hertz_energy(double Q) {
  const double c = std::sqrt(1 - Q), th0 = std::acos(c);
  const int n = 200000;
  double s = 0;
  for (int k = 0; k < n; ++k) {
    const double th = th0 * (k + 0.5) / n, x = std::cos(th), r = std::sqrt(std::max(x * x - c * c, 0.0));
    s += std::sin(th) * std::sin(th) * (x * r - c * c * std::log((x + r) / c));
  }
  return s * th0 / n;
}

}  // namespace

TEST_CASE("bem oracle: monotonic Hertz, sigma = 0") {
  // Reference value: `halfslip solve --Q-over-fP 0.5 --sigma-over-fp0 0` (closed form) prints
  // 0.01116302499 per zone; hertz_energy() reproduces it from the slip formula.
  const double E_cli = 0.01116302499;
  CHECK(std::fabs(hertz_energy(0.5) - E_cli) < 1e-11);
  bem::options o;  // 400 elements, 400 increments per unit load
  for (double Q : {0.3, 0.5}) {
    timer t;
    const auto r = bem::run(hertz, {{Q, 0.0}}, o);
    const double b = std::sqrt(1 - Q), E = hertz_energy(Q), w = width(o.nodes, b);
    MESSAGE((fmt("monotonic Q=%.1f: b1=%.6f b2=%.6f exact %.6f (|err| = %.2g element widths); ", Q, r[0].b1, r[0].b2,
                 b, std::max(std::fabs(r[0].b1 - b), std::fabs(r[0].b2 - b)) / w) +
             fmt("E1=%.8f E2=%.8f exact %.8f (rel err %.2g); %.3f s", r[0].energy1, r[0].energy2, E,
                 std::fabs(r[0].energy1 / E - 1), t.s())));
    CHECK(std::fabs(r[0].b1 - b) < 0.5 * w);
    CHECK(std::fabs(r[0].b2 - b) < 0.5 * w);
    CHECK(r[0].dir1 == 1);
    CHECK(r[0].dir2 == 1);
    // Energy error is second order in 1/N (see the convergence case: 1.4e-4, 3.5e-5, 8.6e-6 relative
    // at N = 200, 400, 800); 2e-4 leaves a factor ~5 at N = 400.
    CHECK(std::fabs(r[0].energy1 / E - 1) < 2e-4);
    CHECK(std::fabs(r[0].energy2 / E - 1) < 2e-4);
  }
}

TEST_CASE("bem oracle: slip profile and equilibrium, monotonic Hertz") {
  bem::options o;
  o.nodes = 300;
  std::vector<double> q, h, x;
  bem::run(hertz, {{0.5, 0.0}}, o, &q, &h, &x);
  REQUIRE(q.size() == 300u);
  const double c = std::sqrt(0.5);
  double F = 0, herr = 0, hmax = 0;
  bool stuck_ok = true;
  for (int j = 0; j < 300; ++j) {
    F += q[j] * (std::cos(pi * j / 300) - std::cos(pi * (j + 1) / 300));  // element widths
    const double ax = std::fabs(x[j]);
    const double r = std::sqrt(std::max(ax * ax - c * c, 0.0));
    const double he = ax > c ? ax * r - c * c * std::log((ax + r) / c) : 0.0;  // >= 0 both zones
    herr = std::max(herr, std::fabs(h[j] - he));
    hmax = std::max(hmax, he);
    if (ax < c - 2 * width(300, c)) stuck_ok = stuck_ok && h[j] == 0.0;  // stick: never slipped
  }
  MESSAGE((fmt("equilibrium residual %.2g; max |h - h_exact| = %.3g (max h = %.3g)", F - 0.5 * pi / 2, herr, hmax)));
  CHECK(std::fabs(F - 0.5 * pi / 2) < 1e-12);
  CHECK(herr < 0.02 * hmax);
  CHECK(stuck_ok);
}

TEST_CASE("bem oracle: same-sign Hertz (Q, sigma) = (0.5, 0.4), eq (20)") {
  bem::options o;
  timer t;
  const auto r = bem::run(hertz, {{0.5, 0.4}}, o);
  const double b1 = std::sqrt(0.5) + 0.1, b2 = std::sqrt(0.5) - 0.1;
  MESSAGE((fmt("same sign: b1=%.6f (exact %.6f, %.2g widths) b2=%.6f (exact %.6f, ", r[0].b1, b1,
               (r[0].b1 - b1) / width(o.nodes, b1), r[0].b2, b2) +
           fmt("%.2g widths); %.3f s", (r[0].b2 - b2) / width(o.nodes, b2), t.s())));
  CHECK(std::fabs(r[0].b1 - b1) < 0.5 * width(o.nodes, b1));
  CHECK(std::fabs(r[0].b2 - b2) < 0.5 * width(o.nodes, b2));
  CHECK(r[0].dir1 == 1);
  CHECK(r[0].dir2 == 1);
  // the mirror (Q, -sigma) swaps the zones
  const auto m = bem::run(hertz, {{0.5, -0.4}}, o);
  CHECK(m[0].b1 == doctest::Approx(r[0].b2).epsilon(1e-12));
  CHECK(m[0].b2 == doctest::Approx(r[0].b1).epsilon(1e-12));
  CHECK(m[0].energy1 == doctest::Approx(r[0].energy2).epsilon(1e-9));
}

TEST_CASE("bem oracle: unloading Q 0 -> 0.6 -> 0.2 (Ciavarella-Jager)") {
  bem::options o;
  timer t;
  const auto r = bem::run(hertz, {{0.6, 0.0}, {0.2, 0.0}}, o);
  const double c = std::sqrt(1 - 0.4 / 2);
  MESSAGE((fmt("unloading: c1=%.6f c2=%.6f exact %.6f (%.2g widths); %.3f s", r[1].b1, r[1].b2, c,
               (r[1].b1 - c) / width(o.nodes, c), t.s()) +
           fmt(", energies on the unloading segment %.8g %.8g", r[1].energy1, r[1].energy2)));
  CHECK(r[0].dir1 == 1);
  CHECK(std::fabs(r[1].b1 - c) < 0.5 * width(o.nodes, c));
  CHECK(std::fabs(r[1].b2 - c) < 0.5 * width(o.nodes, c));
  CHECK(r[1].dir1 == -1);
  CHECK(r[1].dir2 == -1);
  // Ciavarella-Jager: the unloading increment is -2 times the monotonic solution at (Q* - Q)/2 = 0.2,
  // so the slip increment is -2 h_mono(0.2), monotonic in time at each point, and the dissipation
  // int p |dh| is 2 E_mono(0.2).
  const double E = 2 * hertz_energy(0.2);
  MESSAGE((fmt("unloading energy per zone %.8g, 2 E_mono(0.2) = %.8g (rel err %.2g)", r[1].energy1, E,
               r[1].energy1 / E - 1)));
  CHECK(std::fabs(r[1].energy1 / E - 1) < 1e-3);
}

TEST_CASE("bem oracle: Ciavarella-Jager for a non-Hertz pressure") {
  // p = (4/3)(1 - x^2)^{3/2} (P = pi/2). With sigma = 0 the reversed zone after unloading Q* -> Q is
  // the stick zone of a monotonic load (Q* - Q)/2, for any pressure.
  auto p = [](double x) {
    const double u = std::max(0.0, 1 - x * x);
    return 4.0 / 3.0 * u * std::sqrt(u);
  };
  bem::options o;
  o.nodes = 300;
  const auto u = bem::run(p, {{0.5, 0.0}, {0.1, 0.0}}, o);
  const auto m = bem::run(p, {{0.2, 0.0}}, o);
  MESSAGE((fmt("p ~ (1-x^2)^1.5: reversed zone %.6f, monotonic at 0.2: %.6f; energies %.8g vs 2x %.8g", u[1].b1,
               m[0].b1, u[1].energy1, 2 * m[0].energy1)));
  CHECK(std::fabs(u[1].b1 - m[0].b1) < 1.5 * width(o.nodes, m[0].b1));
  CHECK(u[1].dir1 == -1);
  CHECK(std::fabs(u[1].energy1 / (2 * m[0].energy1) - 1) < 1e-2);
}

TEST_CASE("bem oracle: convergence with nodes and steps") {
  const double E = hertz_energy(0.5);
  const double b1 = std::sqrt(0.5) + 0.1, b2 = std::sqrt(0.5) - 0.1, c = std::sqrt(0.8);
  double prevE = 1, prevB = 1;
  for (int n : {100, 200, 400}) {
    bem::options o;
    o.nodes = n;
    o.steps_per_unit = n;
    timer t;
    const auto a = bem::run(hertz, {{0.5, 0.0}}, o);
    const auto s = bem::run(hertz, {{0.5, 0.4}}, o);
    const auto u = bem::run(hertz, {{0.6, 0.0}, {0.2, 0.0}}, o);
    const double eE = std::fabs(a[0].energy1 / E - 1);
    const double eB = std::max({std::fabs(s[0].b1 - b1), std::fabs(s[0].b2 - b2), std::fabs(u[1].b1 - c)});
    MESSAGE((fmt("N = steps_per_unit = %g: energy rel err %.3g, max |b - exact| (same sign, unloading) %.3g; %.3f s",
                 n, eE, eB, t.s())));
    CHECK(eE < prevE);
    CHECK(eB < prevB);
    prevE = eE;
    prevB = eB;
  }
}

TEST_CASE("bem oracle: proportional ray sigma = 3Q, Hertz, to Q = 0.88") {
  // Measured (path step 0.001): zone 1 is smallest (b1 = 0.9425, 0.9422, 0.9418) at Q = 0.463, 0.460,
  // 0.460, is first fully stuck at Q = 0.504, 0.501, 0.502 and first slips +1 at Q = 0.523, 0.512, 0.507
  // for N = steps_per_unit = 200, 400, 800: the stuck interval shrinks with the mesh, i.e. the reversed
  // zone starts right after re-sticking (Q ~ 0.50) but stays tiny (d1 = 4e-4 at Q = 0.55, 1.8e-3 at 0.6).
  bem::options o;
  std::vector<std::pair<double, double>> path;
  for (int k = 1; k <= 176; ++k) path.push_back({0.005 * k, 0.015 * k});
  timer t;
  const auto r = bem::run(hertz, path, o);
  std::string traj = "zone 1 along sigma = 3Q (Q, b1, dir1):";
  for (size_t k = 0; k < r.size(); k += 4) traj += fmt("\n  %.3f %.6f %+g", r[k].Q, r[k].b1, r[k].dir1);
  MESSAGE(traj);
  MESSAGE((fmt("ray: %.3f s, %g vertices", t.s(), double(r.size()))));
  // phases: slipping negative and growing, receding, stuck, slipping positive
  size_t kmin = 0;  // smallest b1 while dir1 = -1
  for (size_t k = 0; k < r.size(); ++k)
    if (r[k].dir1 == -1 && r[k].b1 <= r[kmin].b1) kmin = k;
  size_t kst = r.size(), krev = r.size();
  for (size_t k = kmin; k < r.size(); ++k)
    if (r[k].dir1 == 0 && kst == r.size()) kst = k;
  for (size_t k = kst; k < r.size(); ++k)
    if (r[k].dir1 == 1 && krev == r.size()) krev = k;
  MESSAGE((fmt("smallest b1 %.6f at Q = %.3f; first fully stuck at Q = %.3f; reverse slip from Q = %.3f", r[kmin].b1,
               r[kmin].Q, kst < r.size() ? r[kst].Q : -1.0, krev < r.size() ? r[krev].Q : -1.0)));
  CHECK(r[kmin].Q == doctest::Approx(0.46).epsilon(0.05));
  CHECK(r[kmin].b1 == doctest::Approx(0.942).epsilon(0.003));
  bool growing = true, receding = true, reversed = true, tiny = true, from06 = true;
  for (size_t k = 0; k < kmin; ++k) growing = growing && r[k].dir1 == -1 && (k == 0 || r[k].b1 <= r[k - 1].b1);
  REQUIRE(kst < r.size());
  REQUIRE(krev < r.size());
  for (size_t k = kmin + 1; k < kst; ++k) receding = receding && r[k].dir1 == -1 && r[k].b1 >= r[k - 1].b1;
  for (size_t k = krev; k < r.size(); ++k) reversed = reversed && r[k].dir1 == 1;
  // the reversed zone is tiny at first (it grows roughly quadratically) and clearly there from Q = 0.6
  for (size_t k = 0; k < r.size(); ++k) {
    if (r[k].Q >= 0.505 && r[k].Q <= 0.55) tiny = tiny && 1 - r[k].b1 < 5e-4;
    if (r[k].Q >= 0.6) from06 = from06 && r[k].dir1 == 1 && 1 - r[k].b1 > 1e-3;
  }
  CHECK(growing);
  CHECK(receding);
  CHECK(r[kst - 1].b1 > r[kmin].b1 + 0.04);  // it did recede
  CHECK(reversed);
  CHECK(tiny);
  CHECK(from06);
  CHECK(r.back().b1 == doctest::Approx(0.964).epsilon(0.003));
  CHECK(r.back().dir2 == 1);
}

TEST_CASE("bem oracle: non-proportional cycle reaches a steady cyclic state") {
  // Elastically similar bodies, constant P: the stick/slip history settles after the first cycle, so the
  // energies of cycles 2 and 3 must agree (to the time discretization; 1e-4 relative leaves a factor
  // ~10 over what is observed at the defaults).
  std::vector<std::pair<double, double>> cyc;
  for (int c = 0; c < 3; ++c) {
    cyc.push_back({0.5, 0.3});
    cyc.push_back({-0.2, 0.6});
    cyc.push_back({-0.4, -0.5});
    cyc.push_back({0.1, -0.2});
  }
  timer t;
  const auto r = bem::run(hertz, cyc, bem::options());
  std::string s = "cycle (Q, sigma, b1, dir1, b2, dir2, E1, E2):";
  double worst = 0;
  for (size_t k = 0; k < r.size(); ++k) {
    s += fmt("\n  %5.2f %5.2f", r[k].Q, r[k].sigma) + fmt(" %.5f %+g", r[k].b1, r[k].dir1) +
         fmt(" %.5f %+g", r[k].b2, r[k].dir2) + fmt(" %.8f %.8f", r[k].energy1, r[k].energy2);
    if (k >= 8) {
      worst = std::max(worst, std::fabs(r[k].energy1 - r[k - 4].energy1) / std::max(r[k].energy1, 1e-4));
      worst = std::max(worst, std::fabs(r[k].energy2 - r[k - 4].energy2) / std::max(r[k].energy2, 1e-4));
      CHECK(r[k].dir1 == r[k - 4].dir1);
      CHECK(r[k].dir2 == r[k - 4].dir2);
      CHECK(std::fabs(r[k].b1 - r[k - 4].b1) < 1e-4);
      CHECK(std::fabs(r[k].b2 - r[k - 4].b2) < 1e-4);
    }
  }
  MESSAGE(s);
  MESSAGE((fmt("cycle 3 vs cycle 2 energies: largest relative difference %.2g; %.3f s", worst, t.s())));
  CHECK(worst < 1e-4);
  // the first segment is monotonic loading from zero, so it dissipates in the direction of Q
  CHECK(r[0].dir1 == 1);
  CHECK(r[0].dir2 == 1);
}

TEST_CASE("bem oracle: failures are reported") {
  bem::options o;
  o.nodes = 50;
  o.max_iterations = 1;  // loading from the stuck state needs at least one switch
  CHECK_THROWS_AS(bem::run(hertz, {{0.5, 0.0}}, o), std::runtime_error);
  CHECK_THROWS_AS(bem::run(hertz, {{1.0, 0.0}}, bem::options()), std::invalid_argument);
  o.nodes = 2;
  CHECK_THROWS_AS(bem::run(hertz, {{0.5, 0.0}}, o), std::invalid_argument);
}
