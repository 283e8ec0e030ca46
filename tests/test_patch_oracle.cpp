// Issue 14: an advancing segment whose final stick set is two intervals, with an interior slip
// patch between them (reference/include/halfslip/reference/patch_oracle.hpp; docs/history.md,
// "Interior slip zones: the two-interval static solve (an oracle)"). The static solves of
// core/static_history.hpp have one stick interval and refuse such a segment; this oracle is the
// exact state the history should reach there. Its formulas are checked here by direct quadrature
// of the integrals they claim to evaluate, its one-interval form against core/static_history.hpp,
// and the reproducer of the session-14 interior stop against the independent BEM
// (reference/bem_history.hpp).
#include <doctest/doctest.h>
#include "testing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/patch_oracle.hpp"

using hs::reference::patch_oracle;
using ends = patch_oracle::ends;

namespace {
constexpr double pi = 3.141592653589793238462643383279502884;
double hertz(double x) { return std::sqrt(std::max(0.0, (1 - x) * (1 + x))); }

// the state at (0, 1.5) -> (0.15, 1.5) by the library's static solves (exact to ~1e-15), the
// start of the reproducer's last segment
std::shared_ptr<hs::core::static_history<double>> vertex2() {
  auto sh = std::make_shared<hs::core::static_history<double>>(std::make_shared<hs::core::hertz_pressure<double>>());
  sh->add_vertex(0.0, 1.5);
  sh->add_vertex(0.15, 1.5);
  return sh;
}
}  // namespace

// With no patch the oracle is the one-interval static solve: from the state at (0, 1.5), the
// segment to (0.15, 1.5) by 2x2 Newton on its two conditions gives the library's ends and stick
// traction (core/static_history.hpp; no shared code).
TEST_CASE("patch oracle: with one stick interval it is the library's static solve") {
  hs::core::static_history<double> s1(std::make_shared<hs::core::hertz_pressure<double>>());
  s1.add_vertex(0.0, 1.5);
  auto qS = [&](double x) { return s1.traction(x); };
  patch_oracle o(qS, hertz, s1.memory_points(), 0.15, 0.0, +1, +1, 0);
  double b1 = 0.95, b2 = 0.6;
  for (int it = 0; it < 30; ++it) {
    const double h = 1e-7;
    const auto r = o.residual1(b1, b2), ra = o.residual1(b1 + h, b2), rb = o.residual1(b1 - h, b2),
               rc = o.residual1(b1, b2 + h), rd = o.residual1(b1, b2 - h);
    const double j11 = (ra[0] - rb[0]) / (2 * h), j21 = (ra[1] - rb[1]) / (2 * h), j12 = (rc[0] - rd[0]) / (2 * h),
                 j22 = (rc[1] - rd[1]) / (2 * h), det = j11 * j22 - j12 * j21;
    b1 -= (r[0] * j22 - r[1] * j12) / det;
    b2 -= (j11 * r[1] - j21 * r[0]) / det;
  }
  const auto lib = vertex2();
  CHECK(std::fabs(b1 - lib->b1()) < 1e-13);
  CHECK(std::fabs(b2 - lib->b2()) < 1e-13);
  for (double x : {-0.5, -0.2, 0.1, 0.4, 0.7, 0.9}) {
    CAPTURE(x);
    CHECK(std::fabs(o.traction(ends{b1, b2, 0, 0}, x) - lib->traction(x)) < 1e-13);
  }
}

// The two-interval formulas against direct quadrature of what they claim: from q_S = 0 with a patch
// held (its g scaled so that the first solvability condition holds, and sigma from the second), the
// recovered dq leaves the slip gradient unchanged on the stick set, (2/pi) PV int dq/(x - xi) = ds/2
// (quadrature of the Cauchy integral over the whole contact), its force is the one the third
// condition gives, and the patch condition r3 (the kernel K) is the slip change across the patch by
// the log kernel. Measured: 1.3e-13, 9e-14, 3e-14.
TEST_CASE("patch oracle: the inversion on two intervals against direct quadrature") {
  auto qS = [](double) { return 0.0; };
  const double dQ = 0.3;
  for (int d2 : {+1, -1})
    for (double pl : {-0.4, 0.1}) {
      CAPTURE(d2);
      CAPTURE(pl);
      const ends e{0.8, 0.7, pl, pl + 0.05};
      // r0 is linear in g and independent of the loads: the patch's scale a with r0 = 0
      patch_oracle oa(qS, hertz, {}, dQ, 0.0, +1, d2, 0.0), ob(qS, hertz, {}, dQ, 0.0, +1, d2, 1.0);
      const double ra = oa.residual(e)[0], rb = ob.residual(e)[0], a = -ra / (rb - ra);
      const double ds = -4 * patch_oracle(qS, hertz, {}, dQ, 0.0, +1, d2, a).residual(e)[1];
      patch_oracle o(qS, hertz, {}, dQ, ds, +1, d2, a);
      const auto r = o.residual(e);
      CHECK(std::fabs(r[0]) < 1e-14);
      CHECK(std::fabs(r[1]) < 1e-14);
      for (double x : {-0.65, -0.5, -0.45, -0.2, 0.0, 0.05, 0.3, 0.5, 0.75}) {
        if (o.where(e, x) != 0) continue;
        CAPTURE(x);
        CHECK(std::fabs(o.slip_gradient_term(e, x) - ds / 2) < 1e-11);
      }
      CHECK(std::fabs(o.force(e) - (dQ + 2 * r[2]) * pi / 2) < 1e-12);
      const double x0 = 0.5 * (e.pr + e.b1);
      const auto h = o.slip_change(e, {e.pl, e.pr, 0.5 * (e.pr + x0), -e.b2 + 0.1 * (e.pl + e.b2)}, x0);
      CHECK(std::fabs(h[1] - h[0] - r[3]) < 1e-12);
      CHECK(std::fabs(h[2]) < 1e-12);  // no slip change within a stick interval
      CHECK(std::fabs(h[3] - h[0]) < 1e-12);
    }
}

// The reproducer of session 14 (docs/history.md, Limits): Hertz (0, 1.5) -> (0.15, 1.5) ->
// (0.25, 1.2). The library's static solve refuses the last segment (interior slip zone). The oracle:
// zone 2 reverses at the edge (-1) while the inner part of the old zone 2 goes on slipping (+1) as a
// patch; the stick traction is within the limit, every zone slips one way, and the BEM (N = 800, an
// independent discretisation marching small increments) agrees to its accuracy: ends within an
// element width (0.08 and 0.1 of one), energies within 2e-3 (its own change from N = 400 is 3e-2 on
// zone 2; at N = 3200 it is within 2e-4), traction at nine points within 5e-6 f p0 (N = 400: 5e-5).
TEST_CASE("patch oracle: the interior slip zone of the reproducer against the BEM" * HS_LONG) {
  const auto st = vertex2();
  {
    // (the one-interval phases of core/static_history.hpp refuse the segment; since session 16
    // its two-interval solve takes it: tests/test_static_patch.cpp)
    hs::core::static_history<double> cp(*st);
    cp.add_vertex(0.25, 1.2);
    CHECK(cp.patch_dir() == +1);
  }
  auto qS = [&](double x) { return st->traction(x); };
  const auto cusps = st->memory_points();
  patch_oracle o(qS, hertz, cusps, 0.1, -0.3, +1, -1, +1);
  const ends e = o.solve(ends{0.8935, 0.9888, -0.7396, -0.5778});
  for (double r : o.residual(e)) CHECK(std::fabs(r) < 1e-14);
  CHECK(e.pl > -e.b2);
  CHECK(e.pr < e.b1);
  // the end state: slip gradient and slip unchanged on the stick set, the force, the limit
  const double x0 = 0.5 * (e.pr + e.b1);
  for (double x : {-0.95, -0.85, -0.75, -0.5, -0.2, 0.2, 0.5, 0.85})
    if (o.where(e, x) == 0) CHECK(std::fabs(o.slip_gradient_term(e, x) + 0.3 / 2) < 1e-12);
  CHECK(std::fabs(o.force(e) - 0.1 * pi / 2) < 1e-12);
  for (double h : o.slip_change(e, {e.pl, e.pr, -0.9, -0.8, 0.5, 0.8}, x0))
    if (std::fabs(h) > 0) CHECK(std::fabs(h) < 1e-12);
  double excess = -1;
  for (int k = 1; k < 2000; ++k) {
    const double x = -1 + k / 1000.0;
    if (o.where(e, x) == 0) excess = std::max(excess, std::fabs(o.traction(e, x)) / hertz(x) - 1);
  }
  CHECK(excess < -1e-3);  // (-1.26e-3 at x = -0.740, next to the patch)
  // every point of each zone slipped one way over the segment: the same solve at load fractions
  // 1, 0.75, 0.5, 0.25 (the ends advance), and the slip change between them has the zone's sign
  std::vector<double> xs;
  std::vector<int> dirs;
  for (int k = 1; k < 20; ++k) {
    xs.push_back(e.b1 + (1 - e.b1) * k / 20.0), dirs.push_back(+1);
    xs.push_back(-1 + (1 - e.b2) * k / 20.0), dirs.push_back(-1);
    xs.push_back(e.pl + (e.pr - e.pl) * k / 20.0), dirs.push_back(+1);
  }
  std::vector<std::vector<double>> H;
  ends ek = e, prev = e;
  for (double lam : {1.0, 0.75, 0.5, 0.25}) {
    CAPTURE(lam);
    patch_oracle ol(qS, hertz, cusps, lam * 0.1, -lam * 0.3, +1, -1, +1);
    ek = ol.solve(ek);
    CHECK(ek.b1 >= prev.b1 - 1e-14);  // (going back in load the zones shrink)
    CHECK(ek.b2 >= prev.b2 - 1e-14);
    CHECK(ek.pl >= prev.pl - 1e-14);
    CHECK(ek.pr <= prev.pr + 1e-14);
    prev = ek;
    H.push_back(ol.slip_change(ek, xs, 0.5 * (ek.pr + ek.b1)));
  }
  H.push_back(std::vector<double>(xs.size(), 0.0));
  double worst = 1;
  for (size_t j = 0; j < xs.size(); ++j)
    for (size_t k = 0; k + 1 < H.size(); ++k) worst = std::min(worst, dirs[j] * (H[k][j] - H[k + 1][j]));
  CHECK(worst > -1e-12);
  const double E1 = o.energy(e, 1, x0, 12), E2 = o.energy(e, 2, x0, 12), Ep = o.energy(e, 3, x0, 12);
  CHECK(E1 > 0);
  CHECK(E2 > 0);
  CHECK(Ep > 0);
  // against the BEM
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = 800;
  std::vector<double> xq, qq;
  const auto r = hs::reference::bem::run(hertz, {{0.0, 1.5}, {0.15, 1.5}, {0.25, 1.2}}, bo, &qq, nullptr, &xq);
  const auto &v = r[2];
  CHECK(v.dir1 == +1);
  CHECK(v.dir2 == -1);
  auto width = [](double b) { return pi / 800 * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (800.0 * 800.0); };
  CHECK(std::fabs(v.b1 - e.b1) < width(e.b1));
  CHECK(std::fabs(v.b2 - e.b2) < width(e.b2));
  CHECK(std::fabs(v.energy1 - E1) < 2e-3 * E1);
  CHECK(std::fabs(v.energy2 - (E2 + Ep)) < 2e-3 * (E2 + Ep));
  // the BEM's patch: the elements inside its stick zone at the limit with +p (its elements are the
  // arcs x = -cos(theta), theta in pi (j, j + 1)/N, and carry the element's mean pressure)
  REQUIRE(xq.size() == 800);
  double bl = 1, br = -1;
  for (size_t k = 0; k < xq.size(); ++k) {
    const double t0 = pi * double(k) / 800, t1 = pi * double(k + 1) / 800;
    const double l = -std::cos(t0), rr = -std::cos(t1);
    // the mean Hertz pressure over the element: p dx = sin^2(theta) dtheta
    const double m = ((t1 - t0) / 2 - (std::sin(2 * t1) - std::sin(2 * t0)) / 4) / (rr - l);
    if (xq[k] > -v.b2 && xq[k] < v.b1 && qq[k] >= m * (1 - 1e-9)) bl = std::min(bl, l), br = std::max(br, rr);
  }
  CHECK(std::fabs(bl - e.pl) < 2 * width(e.pl));
  CHECK(std::fabs(br - e.pr) < 2 * width(e.pr));
  for (double x : {-0.95, -0.85, -0.76, -0.66, -0.5, -0.2, 0.2, 0.5, 0.8}) {
    size_t k = 0;
    for (size_t j = 0; j < xq.size(); ++j)
      if (std::fabs(xq[j] - x) < std::fabs(xq[k] - x)) k = j;
    CAPTURE(x);
    CHECK(std::fabs(qq[k] - o.traction(e, xq[k])) < 5e-6);
  }
}
