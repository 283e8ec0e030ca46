// Issue 14: load paths along one ray through the origin by superposition
// (core/ray_history.hpp, hs_history_* in the C ABI; docs/history.md). Checked
// against the march (core/history.hpp, a different method: stuck-interval
// traction rates integrated in load steps) and against closed forms.
#include <doctest/doctest.h>
#include <boost/multiprecision/mpfr.hpp>
#include <halfslip/halfslip.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <memory>
#include <utility>
#include <vector>

#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/core/numerics.hpp"
#include "halfslip/core/ray_history.hpp"
#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/random_walk.hpp"
#include "testing.hpp"

using namespace hs::core;

namespace {

using path_t = std::vector<std::pair<double, double>>;

struct hist_handle {
  hs_history *h = nullptr;
  ~hist_handle() { hs_history_free(h); }
};

// geometry: 0 Hertz, else the flat-rounded punch with b_f/a = 0.5; canonical units; o: options
// (null: the defaults)
void new_history(hist_handle &hh, int geometry, const hs_history_options *o = nullptr) {
  hs_scene sc;
  REQUIRE(hs_scene_default(&sc) == HS_OK);
  sc.a = sc.p0 = sc.f = sc.E_star = 1;
  if (geometry == 0) {
    REQUIRE(hs_history_new(&sc, nullptr, o, &hh.h) == HS_OK);
    return;
  }
  hs_geometry g;
  REQUIRE(hs_geometry_default(&g) == HS_OK);
  g.kind = HS_GEOMETRY_FLAT_ROUNDED;
  g.flat_over_a = 0.5;
  REQUIRE(hs_history_new(&sc, &g, o, &hh.h) == HS_OK);
}

void add(hist_handle &hh, const path_t &p) {
  std::vector<double> q, s;
  for (const auto &v : p) {
    q.push_back(v.first);
    s.push_back(v.second);
  }
  REQUIRE(hs_history_add_vertices(hh.h, p.size(), q.data(), s.data()) == HS_OK);
}

// the default history options with interior slip patches merged (HS_PATCHES_MERGE)
hs_history_options merging() {
  hs_history_options o;
  REQUIRE(hs_history_options_default(&o) == HS_OK);
  o.interior_patches = HS_PATCHES_MERGE;
  return o;
}

// the width of the BEM's element at x (N elements, cosine spacing), plus its sub-element end's rounding
double bem_element_width(double x, int N) {
  return 3.141592653589793 / N * std::sqrt(std::max(1 - x * x, 0.0)) + 2.0 / (double(N) * N);
}

// whether vertex v's interior slip zone lies right of its stick zone's centre (its energy then counted
// with zone 1, as the BEM counts it)
bool patch_on_right(const hs_history_vertex &v) { return v.patch_dir != 0 && v.patch_l + v.patch_r > v.b1 - v.b2; }

hs_history_vertex vertex(const hist_handle &hh, size_t i) {
  hs_history_vertex v;
  v.struct_size = sizeof v;
  REQUIRE(hs_history_vertex_get(hh.h, i, &v) == HS_OK);
  return v;
}

}  // namespace

TEST_CASE("ray histories: superposition against the march (Hertz both regimes, flat punch)" * HS_LONG) {
  // tol: the march's accuracy in units of a (zones; traction and slip 10x, energies
  // 20x relative to the largest). Passing a closed loop (Masing) the march is good to
  // ~1e-6 only (docs/history.md: the end sweeps a region at the friction limit).
  struct ray_case {
    int geometry;
    path_t path;
    double tol;
  };
  const std::vector<ray_case> cases = {
      // sigma = 0: unload, reload below the turning point, then past two of them (Masing wipe)
      {0, {{0.6, 0}, {0.2, 0}, {0.5, 0}, {-0.3, 0}, {0.45, 0}, {0.7, 0}}, 5e-8},
      // same sign, sigma = Q/2 (f p0 / fP units): reversal through zero, reload past the first turn
      {0, {{0.5, 0.25}, {-0.3, -0.15}, {0.4, 0.2}, {0.6, 0.3}, {0.1, 0.05}}, 2e-6},
      // opposite sign, sigma/fp0 = 3 Q/fP, below the recede point (Q/fP = 0.46)
      // (the last vertex closes the loops at -0.4: Masing, 2e-6)
      {0, {{0.4, 1.2}, {-0.2, -0.6}, {0.3, 0.9}, {-0.4, -1.2}}, 2e-6},
      // flat-rounded punch
      {1, {{0.5, 0.5}, {-0.4, -0.4}, {0.2, 0.2}}, 5e-8},
  };
  for (const auto &c : cases) {
    CAPTURE(c.geometry);
    CAPTURE(c.path.front().first);
    hist_handle hh;
    new_history(hh, c.geometry);
    add(hh, c.path);
    std::shared_ptr<const pressure_model<double>> pm;
    if (c.geometry == 0) pm = std::make_shared<hertz_pressure<double>>();
    else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
    history_options<double> ho;
    ho.max_step = 1.0 / 32;
    refined_history<double> march(pm, ho, 1e-9);
    for (const auto &v : c.path) march.add_vertex(v.first, v.second);
    const auto &mv = march.fine().vertices();
    REQUIRE(mv.size() == c.path.size());
    double emax = 0;
    for (const auto &m : mv) emax = std::max(emax, std::max(std::abs(m.energy1), std::abs(m.energy2)));
    const std::vector<double> xs = {-0.99, -0.9, -0.6, -0.2, 0.0, 0.3, 0.7, 0.93, 0.995};
    for (size_t i = 0; i < c.path.size(); ++i) {
      CAPTURE(i);
      const auto v = vertex(hh, i);
      CHECK(v.steps == 0);  // no march
      CHECK(v.error_estimate < 1e-10);
      // the march at rtol 1e-9 is good to ~1e-8 a (its own estimate: a few 1e-9)
      CHECK(std::abs(v.b1 - mv[i].b1) <= c.tol);
      CHECK(std::abs(v.b2 - mv[i].b2) <= c.tol);
      if (v.b1 < 1 - 1e-6) CHECK(v.slip_dir1 == mv[i].dir1);
      if (v.b2 < 1 - 1e-6) CHECK(v.slip_dir2 == mv[i].dir2);
      CHECK(std::abs(v.energy1 - mv[i].energy1) <= 20 * c.tol * emax);
      CHECK(std::abs(v.energy2 - mv[i].energy2) <= 20 * c.tol * emax);
      std::vector<double> q(xs.size()), h(xs.size());
      REQUIRE(hs_history_eval(hh.h, i, HS_FIELD_TRACTION, xs.size(), xs.data(), q.data()) == HS_OK);
      REQUIRE(hs_history_eval(hh.h, i, HS_FIELD_SLIP, xs.size(), xs.data(), h.data()) == HS_OK);
      for (size_t k = 0; k < xs.size(); ++k) {
        CAPTURE(xs[k]);
        CHECK(std::abs(q[k] - march.fine().traction(xs[k], mv[i].step_end)) <= 10 * c.tol);
        CHECK(std::abs(h[k] - march.fine().slip(xs[k], mv[i].step_end)) <= 10 * c.tol);
      }
    }
  }
}

TEST_CASE("ray histories: Hertz zones in closed form (Ciavarella-Jager, Masing), to rounding") {
  // sigma = 0: on the virgin curve c = sqrt(1 - Q/fP); on the branch from a turning
  // point Q_t, c = sqrt(1 - |Q - Q_t|/(2 fP)); past the previous turning point the
  // older branch continues.
  hist_handle hh;
  new_history(hh, 0);
  add(hh, {{0.6, 0}, {0.2, 0}, {0.5, 0}, {0.3, 0}, {0.55, 0}, {-0.1, 0}, {0.7, 0}});
  const double expect[] = {std::sqrt(0.4),         std::sqrt(1 - 0.4 / 2), std::sqrt(1 - 0.3 / 2),
                           std::sqrt(1 - 0.2 / 2),  // from 0.5
                           std::sqrt(1 - 0.35 / 2),  // past 0.5: the branch from 0.2 again
                           std::sqrt(1 - 0.7 / 2),   // past 0.2: the branch from 0.6
                           std::sqrt(0.3)};          // past 0.6: the virgin curve
  const int dir[] = {1, -1, 1, -1, 1, -1, 1};
  for (int i = 0; i < 7; ++i) {
    CAPTURE(i);
    const auto v = vertex(hh, i);
    CHECK(std::abs(v.b1 - expect[i]) <= 4 * eps<double>());
    CHECK(std::abs(v.b2 - expect[i]) <= 4 * eps<double>());
    CHECK(v.slip_dir1 == dir[i]);
    CHECK(v.slip_dir2 == dir[i]);
  }
  // the bookkeeping of a Masing wipe (the formula itself is checked against the march
  // above): the last segment runs up the branch of 0.6 from -0.1 and past 0.6
  hs_solution *m35 = nullptr, *m6 = nullptr, *m7 = nullptr;
  hs_scene sc;
  hs_scene_default(&sc);
  sc.a = sc.p0 = sc.f = sc.E_star = 1;
  sc.sigma_over_fp0 = 0;
  sc.Q_over_fP = 0.35;
  REQUIRE(hs_solve(&sc, nullptr, &m35) == HS_OK);
  sc.Q_over_fP = 0.6;
  REQUIRE(hs_solve(&sc, nullptr, &m6) == HS_OK);
  sc.Q_over_fP = 0.7;
  REQUIRE(hs_solve(&sc, nullptr, &m7) == HS_OK);
  double E35[2], E6[2], E7[2];
  REQUIRE(hs_solution_energy(m35, E35) == HS_OK);
  REQUIRE(hs_solution_energy(m6, E6) == HS_OK);
  REQUIRE(hs_solution_energy(m7, E7) == HS_OK);
  const auto v6 = vertex(hh, 6);
  // the last segment: from -0.1 up the branch of 0.6 to 0.6 (2 (E(0.35) - 0)), then virgin 0.6 -> 0.7
  CHECK(std::abs(v6.energy1 - (2 * E35[0] + E7[0] - E6[0])) <= 64 * eps<double>() * E7[0]);
  hs_solution_free(m35);
  hs_solution_free(m6);
  hs_solution_free(m7);
}

TEST_CASE("ray histories: a vertex off the ray, periodic loading or a receding ramp use the march") {
  SUBCASE("off the ray: the path so far is replayed by static solves (every segment advances)") {
    hist_handle hh;
    new_history(hh, 0);
    add(hh, {{0.6, 0}, {0.2, 0}});
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_SUPERPOSITION);
    const auto before = vertex(hh, 1);
    CHECK(before.steps == 0);
    add(hh, {{0.2, 0.5}});
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    size_t n = 0;
    REQUIRE(hs_history_vertex_count(hh.h, &n) == HS_OK);
    CHECK(n == 3);
    const auto after = vertex(hh, 1);
    CHECK(after.steps == 0);
    // both exact: the superposition's and the static solve's unloading (Ciavarella-Jager)
    CHECK(std::abs(after.b1 - before.b1) <= 64 * eps<double>());
    CHECK(std::abs(after.energy1 - before.energy1) <= 1e-10 * before.energy1);
  }
  SUBCASE("a segment that recedes: static solves (a receding phase), against the march") {
    // r_1 < 0 with e* = 2 dQ/dsigma = 0.8 > e: zone 1 recedes. Marched until session 15 (both zones
    // stick whole and zone 1 reopens over its own slip: "an end passed a memory point that was not
    // located"; docs/history.md, "At the start of a phase")
    const path_t path{{0.5, 0}, {0.1, -1.0}};
    hist_handle hh;
    new_history(hh, 0);
    add(hh, path);
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    CHECK(vertex(hh, 1).steps == 0);
    // the march (core/history.hpp) at step 1/512: within 7e-11 a and 1.5e-9 of the energy
    history_options<double> o;
    o.max_step = 1.0 / 512;
    history<double> m(std::make_shared<hertz_pressure<double>>(), o);
    for (const auto &v : path) m.add_vertex(v.first, v.second);
    const auto &mv = m.vertices().back();
    const auto v = vertex(hh, 1);
    CHECK(v.slip_dir1 == mv.dir1);
    CHECK(v.slip_dir2 == mv.dir2);
    CHECK(std::fabs(v.b1 - mv.b1) < 1e-8);
    CHECK(std::fabs(v.b2 - mv.b2) < 1e-8);
    CHECK(std::fabs(v.energy1 - mv.energy1) < 1e-8 * mv.energy2);
    CHECK(std::fabs(v.energy2 - mv.energy2) < 1e-8 * mv.energy2);
  }
  SUBCASE("a segment the static solves refuse: the path so far is replayed in the march") {
    // random walk 48, vertex 11: "a fold whose path does not come back to its load"; the march meets
    // an interior slip zone there, merged on request
    const hs_history_options o = merging();
    hist_handle hh;
    new_history(hh, 0, &o);
    const auto walk = hs::reference::random_walk(11, 48);
    add(hh, walk);
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_MARCH);
    CHECK(vertex(hh, 10).steps > vertex(hh, 9).steps);
  }
  SUBCASE("the ray sigma/fp0 = 3 Q/fP recedes before Q/fP = 0.88: static solves (a receding phase), zone 1 reversed") {
    hist_handle hh;
    new_history(hh, 0);
    add(hh, {{0.88, 2.64}});
    const auto v = vertex(hh, 0);
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    CHECK(v.steps == 0);
    CHECK(v.slip_dir1 == 1);  // the monotonic solution says -1 (docs/history.md)
    // the march at step 1/512 gives 0.963396712290 (tests/test_static_history.cpp checks the
    // static solves against the march on receding paths)
    CHECK(std::abs(v.b1 - 0.963396712290) <= 1e-9);
  }
  SUBCASE("a ray below the recede point, then past it: static solves, the same state as the ray at once") {
    // (the last segment folds where zone 1 reopens onto its old end; tests/test_static_history.cpp
    // checks such folds against the BEM)
    hist_handle hh;
    new_history(hh, 0);
    add(hh, {{0.4, 1.2}, {-0.2, -0.6}});
    CHECK(vertex(hh, 1).steps == 0);
    add(hh, {{0.88, 2.64}});
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    CHECK(vertex(hh, 2).slip_dir1 == 1);
    CHECK(std::abs(vertex(hh, 2).b1 - 0.963396712290) <= 1e-9);
  }
  SUBCASE("errors leave the history as it was") {
    hist_handle hh;
    new_history(hh, 0);
    add(hh, {{0.6, 0}});
    const double q = 1.0, s = 0.0;
    CHECK(hs_history_add_vertices(hh.h, 1, &q, &s) == HS_ERR_GROSS_SLIDING);
    const double qn = std::nan(""), sn = 0;
    CHECK(hs_history_add_vertices(hh.h, 1, &qn, &sn) == HS_ERR_NOT_FINITE);
    size_t n = 0;
    REQUIRE(hs_history_vertex_count(hh.h, &n) == HS_OK);
    CHECK(n == 1);
    CHECK(vertex(hh, 0).steps == 0);
  }
}

TEST_CASE("ray histories: the state's stresses against the march's state") {
  // same sign ray, sigma/fp0 = Q/(2 fP): unload through zero. The march's state
  // (forced by a vertex off the ray, which replays the path) agrees to its accuracy.
  hist_handle ray, marched;
  new_history(ray, 0);
  new_history(marched, 0);
  add(ray, {{0.5, 0.25}, {-0.3, -0.15}});
  add(marched, {{0.5, 0.25}, {-0.3, -0.15}, {-0.3, 0.4}});
  hs_solution *a = nullptr, *b = nullptr;
  REQUIRE(hs_history_state(ray.h, 1, &a) == HS_OK);
  REQUIRE(hs_history_state(marched.h, 1, &b) == HS_OK);
  const std::vector<double> x = {-1.4, -0.95, -0.5, 0.1, 0.45, 0.8, 1.2}, y = {0, 0.05, 0.2, 0, 0.3, 0.02, 0};
  std::vector<double> sa(3 * x.size()), sb(3 * x.size());
  REQUIRE(hs_eval_stress(a, 1, 0.0, x.size(), x.data(), y.data(), sa.data()) == HS_OK);
  REQUIRE(hs_eval_stress(b, 1, 0.0, x.size(), x.data(), y.data(), sb.data()) == HS_OK);
  for (size_t k = 0; k < sa.size(); ++k) {
    CAPTURE(k);
    CHECK(std::abs(sa[k] - sb[k]) <= 2e-7);
  }
  std::vector<double> ta(x.size()), tb(x.size());
  const std::vector<double> xs = {-0.97, -0.5, 0.0, 0.6, 0.98};
  REQUIRE(hs_eval_surface_stress(a, 1, 0.0, xs.size(), xs.data(), ta.data()) == HS_OK);
  REQUIRE(hs_eval_surface_stress(b, 1, 0.0, xs.size(), xs.data(), tb.data()) == HS_OK);
  for (size_t k = 0; k < xs.size(); ++k) {
    CAPTURE(xs[k]);
    CHECK(std::abs(ta[k] - tb[k]) <= 2e-7);
  }
  hs_summary s;
  s.struct_size = sizeof s;
  REQUIRE(hs_solution_summary(a, &s) == HS_OK);
  CHECK(s.regime == HS_REGIME_SAME_SIGN);
  CHECK(s.slip_dir1 == -1);
  double E[2];
  CHECK(hs_solution_energy(a, E) == HS_ERR_NOT_APPLICABLE);
  hs_solution_free(a);
  hs_solution_free(b);
}

TEST_CASE("ray histories: the same templates in long double (closed forms to its rounding)") {
  using L = long double;
  ray_path<L> path;
  const std::vector<std::pair<L, L>> p = {{0.6L, 0}, {0.2L, 0}, {0.5L, 0}, {0.3L, 0}, {0.55L, 0}, {-0.1L, 0}, {0.7L, 0}};
  struct mono_values {
    L b1, b2, E1, E2;
    int dir1, dir2;
  };
  auto mono = [](const ray_load<L> &l) {
    hertz_scene<L> sc;
    sc.q = l.q;
    sc.s = l.s;
    const auto m = solve_hertz<L>(sc);
    return mono_values{m.b1(), m.b2(), m.energy(1), m.energy(2), m.dir1(), m.dir2()};
  };
  const L expect[] = {std::sqrt(0.4L),          std::sqrt(1 - 0.4L / 2), std::sqrt(1 - 0.3L / 2), std::sqrt(1 - 0.2L / 2),
                      std::sqrt(1 - 0.35L / 2), std::sqrt(1 - 0.7L / 2), std::sqrt(0.3L)};
  ray_vertex_result<L> prev;
  for (size_t i = 0; i < p.size(); ++i) {
    CAPTURE(i);
    REQUIRE(path.add(p[i].first, p[i].second));
    const auto r = ray_evaluate<L>(path.vertices().back(), mono, L(1), i ? &prev : nullptr);
    CHECK(std::abs(r.b1 - expect[i]) <= 8 * eps<L>());
    CHECK(r.energy1 > 0);
    prev = r;
  }
  CHECK_FALSE(path.add(0.3L, 0.3L));  // off the ray
  // at 0.7, past every turning point: the virgin curve alone
  CHECK(path.vertices().back().terms.size() == 1);
  CHECK(path.vertices().back().terms[0].coef == 1);
}

TEST_CASE("ray histories: certified digits from the reference backend (hs_ref_history)") {
  using M = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<80>,
                                          boost::multiprecision::et_off>;
  hs_ref_scene sc;
  REQUIRE(hs_ref_scene_default(&sc) == HS_OK);
  hs_ref_history *h = nullptr;
  const int digits = 40;
  REQUIRE(hs_ref_history_new(&sc, digits, &h) == HS_OK);
  // Hertz, sigma = 0: virgin 0.6, unload to 0.2, reload to 0.5, past 0.6 to 0.7 (Masing)
  const char *q[] = {"0.6", "0.2", "0.5", "0.7"}, *s[] = {"0", "0", "0", "0"};
  REQUIRE(hs_ref_history_add_vertices(h, 4, q, s) == HS_OK);
  const M expect[] = {sqrt(M("0.4")), sqrt(1 - M("0.4") / 2), sqrt(1 - M("0.3") / 2), sqrt(M("0.3"))};
  char buf[128];
  for (int i = 0; i < 4; ++i) {
    CAPTURE(i);
    int cd = 0;
    REQUIRE(hs_ref_history_value(h, i, HS_REF_B1, buf, sizeof buf, nullptr, &cd) == HS_OK);
    CHECK(cd == digits);
    CHECK(abs(M(buf) - expect[i]) <= M("1e-39") * expect[i]);
    int d1 = 0, d2 = 0;
    REQUIRE(hs_ref_history_slip_dirs(h, i, &d1, &d2) == HS_OK);
    CHECK(d1 == (i == 1 ? -1 : 1));
  }
  // the energies against the double route (superposition of the closed forms), and
  // the segment past the turning points: 2 E(0.2) (back up the branch of 0.2 to 0.6)
  // + E(0.7) - E(0.6), each certified
  hist_handle dh;
  new_history(dh, 0);
  add(dh, {{0.6, 0}, {0.2, 0}, {0.5, 0}, {0.7, 0}});
  for (int i = 0; i < 4; ++i) {
    CAPTURE(i);
    int cd = 0;
    REQUIRE(hs_ref_history_value(h, i, HS_REF_ENERGY1, buf, sizeof buf, nullptr, &cd) == HS_OK);
    CHECK(cd >= digits - 2);
    const double e = vertex(dh, i).energy1;
    CHECK(std::abs(double(M(buf)) - e) <= 64 * eps<double>() * std::abs(e));
  }
  // errors: off the ray, a receding ramp, bad numbers; the history keeps its vertices
  const char *qo[] = {"0.3"}, *so[] = {"0.1"};
  CHECK(hs_ref_history_add_vertices(h, 1, qo, so) == HS_ERR_NOT_APPLICABLE);
  const char *qb[] = {"0.x"};
  CHECK(hs_ref_history_add_vertices(h, 1, qb, s) == HS_ERR_BAD_NUMBER);
  const char *qg[] = {"1"};
  CHECK(hs_ref_history_add_vertices(h, 1, qg, s) == HS_ERR_GROSS_SLIDING);
  size_t n = 0;
  REQUIRE(hs_ref_history_vertex_count(h, &n) == HS_OK);
  CHECK(n == 4);
  CHECK(hs_ref_history_value(h, 4, HS_REF_B1, buf, sizeof buf, nullptr, nullptr) == HS_ERR_BAD_OPTION);
  CHECK(hs_ref_history_value(h, 0, HS_REF_D1, buf, sizeof buf, nullptr, nullptr) == HS_ERR_BAD_OPTION);
  hs_ref_history_free(h);
  hs_ref_history *r = nullptr;
  REQUIRE(hs_ref_history_new(&sc, 30, &r) == HS_OK);
  const char *qr[] = {"0.88"}, *sr[] = {"2.64"};  // sigma/fp0 = 3 Q/fP recedes before 0.88
  CHECK(hs_ref_history_add_vertices(r, 1, qr, sr) == HS_ERR_NOT_APPLICABLE);
  const char *qk[] = {"0.4", "-0.2"}, *sk[] = {"1.2", "-0.6"};  // below the recede point: certified
  CHECK(hs_ref_history_add_vertices(r, 2, qk, sk) == HS_OK);
  hs_ref_history_free(r);
  CHECK(hs_ref_history_new(&sc, 0, &r) == HS_ERR_BAD_OPTION);
}

TEST_CASE("ray histories: periodic loading on a ray through the origin by superposition" * HS_LONG) {
  // in phase, zero means: +-(0.5, 0.4). The steady cycle in closed form (Ciavarella-Jager:
  // 4 E_i per cycle, slip range 2 h(x), hs_solution_steady_cycle) and the march
  hist_handle hh;
  new_history(hh, 0);
  REQUIRE(hs_history_add_cycles(hh.h, 0, 0.5, 0, 0.4, 0, 3) == HS_OK);
  size_t n = 0;
  REQUIRE(hs_history_vertex_count(hh.h, &n) == HS_OK);
  REQUIRE(n == 9);
  for (size_t i = 0; i < n; ++i) CHECK(vertex(hh, i).steps == 0);
  CHECK(vertex(hh, 8).cycle == 3);
  hs_cycle_summary cs;
  cs.struct_size = sizeof cs;
  REQUIRE(hs_history_cycle_summary(hh.h, &cs) == HS_OK);
  hs_scene sc;
  hs_scene_default(&sc);
  sc.a = sc.p0 = sc.f = sc.E_star = 1;
  sc.Q_over_fP = 0.5;
  sc.sigma_over_fp0 = 0.4;
  hs_solution *m = nullptr;
  REQUIRE(hs_solve(&sc, nullptr, &m) == HS_OK);
  hs_steady_cycle st;
  st.struct_size = sizeof st;
  REQUIRE(hs_solution_steady_cycle(m, &st) == HS_OK);
  REQUIRE(st.valid == 1);
  CHECK(cs.cycles_to_steady == 2);  // cycle 1 holds the first loading from zero
  CHECK(std::abs(cs.energy_per_cycle1 - st.energy_per_cycle1) <= 64 * eps<double>() * st.energy_per_cycle1);
  CHECK(std::abs(cs.energy_per_cycle2 - st.energy_per_cycle2) <= 64 * eps<double>() * st.energy_per_cycle2);
  const std::vector<double> xs = {-0.99, -0.7, 0.0, 0.8, 0.97};
  std::vector<double> dh(xs.size()), h(xs.size());
  REQUIRE(hs_history_slip_range(hh.h, xs.size(), xs.data(), dh.data()) == HS_OK);
  REQUIRE(hs_eval_slip(m, xs.size(), xs.data(), h.data()) == HS_OK);
  for (size_t k = 0; k < xs.size(); ++k) {
    CAPTURE(xs[k]);
    CHECK(std::abs(dh[k] - 2 * std::abs(h[k])) <= 1e-14);
  }
  hs_solution_free(m);
  // the march of the same cycles agrees to its accuracy
  auto pm = std::make_shared<hertz_pressure<double>>();
  history_options<double> ho;
  ho.max_step = 1.0 / 32;
  refined_history<double> march(pm, ho, 1e-9);
  const auto r = march.add_cycles(0, 0.5, 0, 0.4, 0, 3, ramp_order::sigma_first, 64, 1e-6);
  CHECK(std::abs(r.energy1 - cs.energy_per_cycle1) <= 1e-6 * cs.energy_per_cycle1);
}

namespace {
// the march's (core::refined_history, rtol 1e-9) cycle summary and slip range of the same
// periodic loading: the independent method for the static solves' cycles
struct march_cycles {
  cycle_result<double> r;
  std::vector<double> dh;
};
march_cycles march_of(int geometry, const double (&c)[5], int cycles, const std::vector<double> &xs) {
  std::shared_ptr<const pressure_model<double>> pm;
  if (geometry == 0) pm = std::make_shared<hertz_pressure<double>>();
  else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
  history_options<double> ho;
  ho.max_step = 1.0 / 32;
  refined_history<double> m(pm, ho, 1e-9);
  march_cycles out;
  out.r = m.add_cycles(c[0], c[1], c[2], c[3], c[4], cycles, ramp_order::sigma_first, 64, 1e-6);
  const auto &vs = m.fine().vertices();
  for (double x : xs) {
    double lo = 0, hi = 0;
    bool first = out.r.last_cycle_first > 0;
    for (size_t k = out.r.last_cycle_first > 0 ? out.r.last_cycle_first - 1 : 0; k < out.r.last_cycle_end; ++k) {
      const double v = m.fine().slip(x, vs[k].step_end);
      if (first || v < lo) lo = v;
      if (first || v > hi) hi = v;
      first = false;
    }
    out.dh.push_back(hi - lo);
  }
  return out;
}
}  // namespace

TEST_CASE("periodic loading off the ray by static solves, against the march" * HS_LONG) {
  // Before session 12 hs_history_add_cycles marched every periodic loading off the ray; the
  // same path given vertex by vertex was taken by the static solves. Now the cycles are too,
  // while every segment is one they take (method STATIC, steps 0), else the march replays.
  const std::vector<double> xs = {-0.95, -0.6, -0.2, 0.3, 0.7, 0.97};
  int method = -1;
  struct periodic {
    int geometry;
    double c[5];  // Qm, Qa, Sm, Sa, phase (degrees)
    int cycles;
  };
  const periodic cases[] = {
      {0, {0, 0.3, 0.5, 0, 0}, 3},     // mean bulk tension, shear cycling (a line off the ray)
      {0, {0.2, 0.3, 0.4, 0.2, 0}, 3}, // mean shear and tension, in phase off the ray
      {1, {0, 0.3, 0.5, 0, 0}, 3},     // the flat punch
  };
  for (const auto &pc : cases) {
    CAPTURE(pc.geometry);
    CAPTURE(pc.c[1]);
    CAPTURE(pc.c[2]);
    hist_handle h;
    new_history(h, pc.geometry);
    REQUIRE(hs_history_add_cycles(h.h, pc.c[0], pc.c[1], pc.c[2], pc.c[3], pc.c[4], pc.cycles) == HS_OK);
    REQUIRE(hs_history_method(h.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    size_t n = 0;
    REQUIRE(hs_history_vertex_count(h.h, &n) == HS_OK);
    CHECK(vertex(h, n - 1).steps == 0);
    CHECK(vertex(h, n - 1).cycle == pc.cycles);
    hs_cycle_summary cs;
    cs.struct_size = sizeof cs;
    REQUIRE(hs_history_cycle_summary(h.h, &cs) == HS_OK);
    std::vector<double> dh(xs.size());
    REQUIRE(hs_history_slip_range(h.h, xs.size(), xs.data(), dh.data()) == HS_OK);
    const march_cycles m = march_of(pc.geometry, pc.c, pc.cycles, xs);
    CHECK(cs.cycles_to_steady == m.r.cycles_to_steady);
    // the march's accuracy at rtol 1e-9 with Masing returns: ~1e-7 relative (docs/history.md)
    const double emax = std::max(m.r.energy1, m.r.energy2);
    CHECK(emax > 0);
    CHECK(std::abs(cs.energy_per_cycle1 - m.r.energy1) <= 1e-6 * emax);
    CHECK(std::abs(cs.energy_per_cycle2 - m.r.energy2) <= 1e-6 * emax);
    double dmax = 0;
    for (double d : m.dh) dmax = std::max(dmax, d);
    CHECK(dmax > 0);
    for (size_t k = 0; k < xs.size(); ++k) {
      CAPTURE(xs[k]);
      CHECK(std::abs(dh[k] - m.dh[k]) <= 1e-6 * dmax);
    }
  }
  // out of phase, Q/fP = 0.2 + 0.2 sin t, sigma/fp0 = 0.3 + 0.2 cos t: an interior slip zone opens
  // at chord 13 (0.116 a wide, next to zone 2, which has reversed at the edge). Until session 16 the
  // history stopped there; the static solves' two-interval solve takes it (docs/history.md,
  // "Interior slip zones in hs_history"). Against the BEM at N = 400 on the same vertices: every
  // slip direction, b1 within an element width, each zone's energy within 5e-4 of the largest
  // (measured 2.9e-4), the patch's energy counted with zone 2 (its side of the stick zone's centre,
  // as the BEM counts it)
  {
    hist_handle dh;
    new_history(dh, 0);
    REQUIRE(hs_history_add_cycles(dh.h, 0.2, 0.2, 0.3, 0.2, 90, 1) == HS_OK);
    REQUIRE(hs_history_method(dh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    size_t nd = 0;
    REQUIRE(hs_history_vertex_count(dh.h, &nd) == HS_OK);
    CHECK(nd == 2 + 64);  // sigma first, then Q: 2 ramp vertices, then 64 chords
    path_t vs;
    int patches = 0;
    double ep = 0;
    for (size_t i = 0; i < nd; ++i) {
      const auto v = vertex(dh, i);
      vs.push_back({v.Q_over_fP, v.sigma_over_fp0});
      patches += v.patch_dir != 0;
      if (v.cycle == 1) ep += v.energy_patch;
      CHECK((v.patch_dir != 0) == (v.energy_patch > 0));
    }
    CHECK(patches == 1);
    hs_cycle_summary cs;
    cs.struct_size = sizeof cs;
    REQUIRE(hs_history_cycle_summary(dh.h, &cs) == HS_OK);
    CHECK(cs.energy_per_cycle_patch > 0);
    CHECK(std::fabs(cs.energy_per_cycle_patch - ep) <= 1e-15 * ep);
    hs::reference::bem::options bo;
    bo.nodes = bo.steps_per_unit = 400;
    const auto r = hs::reference::bem::run([](double x) { return std::sqrt(std::max(1 - x * x, 0.0)); }, vs, bo);
    double big = 0;
    for (const auto &b : r) big = std::max({big, b.energy1, b.energy2});
    for (size_t i = 0; i < nd; ++i) {
      CAPTURE(i);
      const auto v = vertex(dh, i);
      const bool right = patch_on_right(v);
      CHECK(v.slip_dir1 == r[i].dir1);
      CHECK(v.slip_dir2 == r[i].dir2);
      CHECK(std::fabs(v.b1 - r[i].b1) < bem_element_width(v.b1, 400));
      CHECK(std::fabs(v.energy1 + (right ? v.energy_patch : 0.0) - r[i].energy1) < 5e-4 * big);
      CHECK(std::fabs(v.energy2 + (right ? 0.0 : v.energy_patch) - r[i].energy2) < 5e-4 * big);
    }
  }
  // a cycle the static solves do not take (anti-phase Q and sigma about (0.15, 1.5), bench_history's
  // case 49): by default the history stops where the march meets the interior slip zone, keeping
  // the vertices before it (the ramp's two); merging, the march replays the whole path, ramp and
  // cycle, and the history holds no trace of the static attempt
  {
    hist_handle dh;
    new_history(dh, 0);
    CHECK(hs_history_add_cycles(dh.h, 0.15, 0.1, 1.5, 0.3, 180, 3) == HS_ERR_NOT_APPLICABLE);
    size_t nd = 0;
    REQUIRE(hs_history_vertex_count(dh.h, &nd) == HS_OK);
    CHECK(nd == 2);
    CHECK(vertex(dh, 1).cycle == 0);
  }
  hist_handle oh;
  const hs_history_options om = merging();
  new_history(oh, 0, &om);
  REQUIRE(hs_history_add_cycles(oh.h, 0.15, 0.1, 1.5, 0.3, 180, 3) == HS_OK);
  REQUIRE(hs_history_method(oh.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_MARCH);
  size_t no = 0;
  REQUIRE(hs_history_vertex_count(oh.h, &no) == HS_OK);
  CHECK(no > 2);
  CHECK(vertex(oh, 0).steps > 0);
  CHECK(vertex(oh, no - 1).cycle == 3);
  // a ray path, then cycles off it: the path is replayed by the static solves
  hist_handle rh;
  new_history(rh, 0);
  add(rh, {{0.3, 0}});
  REQUIRE(hs_history_method(rh.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_SUPERPOSITION);
  REQUIRE(hs_history_add_cycles(rh.h, 0, 0.3, 0.5, 0, 0, 1) == HS_OK);
  REQUIRE(hs_history_method(rh.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_STATIC);
  CHECK(vertex(rh, 0).steps == 0);
}

TEST_CASE("periodic loading: bad arguments leave the history as it was; cycle tags survive a change of method") {
  // (review of session 12) add_cycles checked its arguments inside each method's attempt: a bad
  // argument made the superposition replay the path in the static solves and then the march
  // before the error came back, and left the history in the march
  hist_handle h;
  new_history(h, 0);
  add(h, {{0.3, 0.2}, {0, 0}});  // on the ray of the cycles below, back at zero
  int method = -1;
  REQUIRE(hs_history_method(h.h, &method) == HS_OK);
  REQUIRE(method == HS_HISTORY_SUPERPOSITION);
  CHECK(hs_history_add_cycles(h.h, 0, 0.3, 0, 0.2, 0, 0) == HS_ERR_BAD_OPTION);
  CHECK(hs_history_add_cycles(h.h, 0.6, 0.5, 0, 0.2, 0, 2) == HS_ERR_GROSS_SLIDING);
  CHECK(hs_history_add_cycles(h.h, 0, std::nan(""), 0, 0.2, 0, 2) == HS_ERR_NOT_FINITE);
  REQUIRE(hs_history_method(h.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_SUPERPOSITION);
  size_t n = 0;
  REQUIRE(hs_history_vertex_count(h.h, &n) == HS_OK);
  CHECK(n == 2);
  // cycles on the ray, tagged 1 and 2; a vertex off the ray then replays the path in the
  // static solves, and the tags go with it
  REQUIRE(hs_history_add_cycles(h.h, 0, 0.3, 0, 0.2, 0, 2) == HS_OK);
  REQUIRE(hs_history_method(h.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_SUPERPOSITION);
  REQUIRE(hs_history_vertex_count(h.h, &n) == HS_OK);
  std::vector<int> tags;
  for (size_t i = 0; i < n; ++i) tags.push_back(vertex(h, i).cycle);
  CHECK(tags.back() == 2);
  add(h, {{0.1, 0.5}});
  REQUIRE(hs_history_method(h.h, &method) == HS_OK);
  CHECK(method != HS_HISTORY_SUPERPOSITION);
  for (size_t i = 0; i < n; ++i) {
    CAPTURE(i);
    CHECK(vertex(h, i).cycle == tags[i]);
  }
  CHECK(vertex(h, n).cycle == 0);
}

// A path the static solves leave (random walk seed 8: an interior slip zone open at vertex 36) is
// replayed in the march, which at vertex 3 misses the slip of a patch that opened and merged with
// zone 2 within the segment: zone 2's energy 3.43e-6 against the BEM's 4.31e-6 (N = 800; 4.34e-6
// and 4.36e-6 at N = 400 and 1600), with a local estimate of 1.2e-8. The march's disagreement with
// the static solves on the vertices they took is its error there, measured: every march vertex
// reports at least it. Checked against the independent BEM at vertex 3 (hs_history before this:
// estimates of 5e-5 at most over the path, `halfslip history --rtol 1e-6`).
TEST_CASE("a path left by the static solves: the march's estimate covers its measured error (BEM)") {
  // (since session 16 the static solves take vertex 36 with its interior slip zone and stop at
  // vertex 83, "the slide of a receding phase is not resolved"; by default the history then stops,
  // as the march cannot replay the patch; merging, the march replays the path)
  auto walk = hs::reference::random_walk(83, 8);
  hist_handle hh;
  hs_history_options o = merging();
  o.rtol = 1e-6;  // (the march's cost; its local estimates are then about 1e-6)
  new_history(hh, 0, &o);
  add(hh, walk);
  int method = 0;
  REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_MARCH);
  double emax = 0;
  for (size_t i = 0; i < walk.size(); ++i) emax = std::max({emax, vertex(hh, i).energy1, vertex(hh, i).energy2});
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = 800;
  const std::vector<std::pair<double, double>> first3(walk.begin(), walk.begin() + 3);
  const auto r = hs::reference::bem::run([](double x) { return std::sqrt(std::max(1 - x * x, 0.0)); }, first3, bo);
  const auto v = vertex(hh, 2);
  // the march's error at vertex 3 beyond the BEM's own (3 % of this energy: its spread over N = 400
  // to 1600 is 1.2 %)
  const double err = (std::fabs(v.energy2 - r[2].energy2) - 0.03 * r[2].energy2) / emax;
  CAPTURE(v.energy2);
  CAPTURE(err);
  // (the case still shows the miss: 7.6e-5 of the path's largest energy, above the march's own
  // estimates on this path, at most 5e-5 at rtol 1e-6)
  REQUIRE(err > 5e-5);
  for (size_t i = 0; i < walk.size(); ++i) {
    CAPTURE(i);
    CHECK(vertex(hh, i).error_estimate >= err);
  }
}

// The static solves at the accuracy asked (hs_history_options.rtol, default 1e-8) use cheaper orders
// (static_history_accuracy::for_rtol), at which a crossing or a Newton solve can fail where full
// accuracy takes the segment; the march then replayed the whole path. Hertz random walk 21, vertex 6
// ("the static solve of the segment did not converge"), and the flat punch's walk 50, vertex 18 ("an end
// passed a memory point that was not located"). Such a segment is now solved again at full accuracy;
// `bench/static_walks.cpp count G 60 1e-8 [retry]`: Hertz 2408 -> 2588 vertices of 6000 (full
// accuracy 2588), flat punch 2914 -> 3101 (full 3157). Since session 23 rtol 1e-8 keeps the full orders
// (panels resolved less finely) and takes those two; random walk 0, vertex 8, is refused at rtol 1e-8
// by both geometries and taken at full accuracy.
TEST_CASE("a segment refused at the accuracy asked is solved at full accuracy, not marched") {
  struct walk_case {
    int geometry;
    unsigned seed;
    size_t n;
  };
  for (const walk_case wc : {walk_case{0, 0, 9}, walk_case{1, 0, 9}}) {
    CAPTURE(wc.geometry);
    const auto full = hs::reference::random_walk(100, wc.seed);
    const path_t walk(full.begin(), full.begin() + long(wc.n));
    // the reduced accuracy alone refuses the last vertex (so that the case tests the retry)
    std::shared_ptr<const pressure_model<double>> pm;
    if (wc.geometry == 0) pm = std::make_shared<hertz_pressure<double>>();
    else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
    static_history<double> reduced(pm, static_history_accuracy<double>::for_rtol(1e-8));
    static_history<double> exact(pm);
    for (size_t k = 0; k + 1 < walk.size(); ++k) {
      reduced.add_vertex(walk[k].first, walk[k].second);
      exact.add_vertex(walk[k].first, walk[k].second);
    }
    CHECK_THROWS_AS(reduced.add_vertex(walk.back().first, walk.back().second), error);
    exact.add_vertex(walk.back().first, walk.back().second);
    hist_handle hh;
    new_history(hh, wc.geometry);  // rtol 1e-8
    add(hh, walk);
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    // the vertex agrees with full accuracy (it was solved there) to rounding, the ones before to
    // the accuracy asked: ends in a, energies relative to the largest
    const auto v = vertex(hh, walk.size() - 1);
    const double emax = std::max(std::fabs(exact.last_segment().E1), std::fabs(exact.last_segment().E2));
    CHECK(std::fabs(v.b1 - exact.b1()) <= 1e-8);
    CHECK(std::fabs(v.b2 - exact.b2()) <= 1e-8);
    CHECK(std::fabs(v.energy1 - exact.last_segment().E1) <= 1e-8 * emax);
    CHECK(std::fabs(v.energy2 - exact.last_segment().E2) <= 1e-8 * emax);
    // and the history goes on at the accuracy asked: the next vertex by the static solves too
    const double q = full[wc.n].first, s = full[wc.n].second;
    REQUIRE(hs_history_add_vertices(hh.h, 1, &q, &s) == HS_OK);
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
  }
}

// hs_history_last_error: the library's reason for a failed call. bench_history's periodic loadings
// stop for different reasons that share HS_ERR_NOT_APPLICABLE (case 133: part of zone 2 next to the
// edge would slip back; case 47: an interior slip zone opens in the second cycle; case 3 until session
// 21, whose third cycle, a steady one, is now copied; case 16 until session 17), and the CLI guessed
// "interior" for both (41 of the 69 Hertz stops were slip back in session 14; since session 17 the
// static solves take most of them, case 12 of this test until then among them).
TEST_CASE("hs_history_last_error names the reason of the last failed call") {
  char why[512];
  auto reason = [&](const hist_handle &hh) {
    REQUIRE(hs_history_last_error(hh.h, why, sizeof why) == HS_OK);
    return std::string(why);
  };
  hist_handle a;
  new_history(a, 0);
  CHECK(reason(a).empty());
  CHECK(hs_history_add_cycles(a.h, 0, 0.6, 1.5, 1.0, 90, 3) == HS_ERR_NOT_APPLICABLE);
  CHECK(reason(a).find("slip back") != std::string::npos);
  CHECK(reason(a).find("interior") == std::string::npos);
  hist_handle b;
  new_history(b, 0);
  CHECK(hs_history_add_cycles(b.h, 0.15, 0.1, 1.5, 0.3, 45, 3) == HS_ERR_NOT_APPLICABLE);
  CHECK(reason(b).find("interior") != std::string::npos);
  // a success clears it; bad vertices name themselves
  add(b, {{0.3, 0}});
  CHECK(reason(b).empty());
  const double q = 1.0, s = 0.0;
  CHECK(hs_history_add_vertices(b.h, 1, &q, &s) == HS_ERR_GROSS_SLIDING);
  CHECK(reason(b).find("gross sliding") != std::string::npos);
  // truncated to the buffer, NUL-terminated; bad arguments
  char small[8];
  REQUIRE(hs_history_last_error(b.h, small, sizeof small) == HS_OK);
  CHECK(std::strlen(small) == 7);
  CHECK(hs_history_last_error(b.h, small, 0) == HS_ERR_BAD_SIZE);
  CHECK(hs_history_last_error(b.h, nullptr, 8) == HS_ERR_NULL_POINTER);
  CHECK(hs_history_last_error(nullptr, small, 8) == HS_ERR_NULL_POINTER);
}

// A segment whose static solve finds an interior slip zone is not handed to the march: the march's
// friction-limit check samples 8 points and can miss the patch. Hertz (0, 1.5) -> (0.15, 1.5) ->
// (0.25, 1.2): the march returned zone 2's energy at the last vertex as 1.47e-6 with an estimate of
// 1.4e-8, where the independent BEM gives 6.38e-5, 6.59e-5, 6.60e-5 at N = 400, 800, 1600 (the ends
// agree). Sessions 14-15 stopped there (HS_ERR_NOT_APPLICABLE); since session 16 the static solves
// take it with the patch (core/static_patch.hpp; tests/test_static_patch.cpp against the oracle and
// the BEM), with or without merging, and report it: patch_dir, its ends, energy_patch. A caller's
// struct from before those fields gets the others.
TEST_CASE("a vertex with an interior slip zone: the static solves take it and report the patch") {
  const path_t path{{0, 1.5}, {0.15, 1.5}, {0.25, 1.2}};
  for (int merge = 0; merge < 2; ++merge) {
    CAPTURE(merge);
    hist_handle hh;
    const hs_history_options o = merging();
    new_history(hh, 0, merge ? &o : nullptr);
    add(hh, path);
    int method = 0;
    REQUIRE(hs_history_method(hh.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    const auto v1 = vertex(hh, 1), v = vertex(hh, 2);
    CHECK(v1.patch_dir == 0);
    CHECK(v1.energy_patch == 0);
    CHECK(v.patch_dir == +1);
    CHECK(v.interior_merges == 0);
    // the oracle's patch (tests/test_patch_oracle.cpp), the BEM's energies (N = 3200: zone 1
    // 1.143357e-3, zone 2 with the patch 6.582687e-5)
    CHECK(std::fabs(v.patch_l + 0.739387794347220) < 1e-9);
    CHECK(std::fabs(v.patch_r + 0.577893425337990) < 1e-9);
    CHECK(std::fabs(v.energy1 - 1.143357e-3) < 2e-4 * 1.143357e-3);
    CHECK(std::fabs(v.energy2 + v.energy_patch - 6.582687e-5) < 2e-3 * 6.582687e-5);
    CHECK(v.energy_patch > 0.9 * (v.energy2 + v.energy_patch));
    // a struct without the patch fields
    hs_history_vertex old;
    std::memset(&old, 0x5a, sizeof old);
    old.struct_size = offsetof(hs_history_vertex, patch_dir);
    REQUIRE(hs_history_vertex_get(hh.h, 2, &old) == HS_OK);
    CHECK(old.b1 == v.b1);
    CHECK(old.interior_merges == 0);
    unsigned char tail[sizeof old - offsetof(hs_history_vertex, patch_dir)];
    std::memset(tail, 0x5a, sizeof tail);
    CHECK(std::memcmp(reinterpret_cast<const unsigned char *>(&old) + offsetof(hs_history_vertex, patch_dir), tail,
                      sizeof tail) == 0);
    old.struct_size = offsetof(hs_history_vertex, patch_dir) + 1;
    CHECK(hs_history_vertex_get(hh.h, 2, &old) == HS_ERR_STRUCT_SIZE);
  }
  // periodic loading that meets a patch the static solves do not take (anti-phase Q and sigma about
  // (0.15, 1.5), bench_history's case 49: they stop at another segment, and the march meets the
  // patch): by default HS_ERR_NOT_APPLICABLE, naming the interior slip zone
  char why[512];
  hist_handle hc;
  new_history(hc, 0);
  CHECK(hs_history_add_cycles(hc.h, 0.15, 0.1, 1.5, 0.3, 180, 3) == HS_ERR_NOT_APPLICABLE);
  REQUIRE(hs_history_last_error(hc.h, why, sizeof why) == HS_OK);
  CHECK(std::string(why).find("interior slip zone") != std::string::npos);
  // merging: the march takes it, flagged as an approximation; the last vertex carries it
  hist_handle hcm;
  const hs_history_options o = merging();
  new_history(hcm, 0, &o);
  REQUIRE(hs_history_add_cycles(hcm.h, 0.15, 0.1, 1.5, 0.3, 180, 3) == HS_OK);
  size_t nc = 0;
  REQUIRE(hs_history_vertex_count(hcm.h, &nc) == HS_OK);
  CHECK(vertex(hcm, nc - 1).interior_merges >= 1);
}

// Issue 14 (session 21): out-of-phase cycling about zero means, Hertz. The third cycle's static
// solves stopped (the history said "interior slip zone", HS_ERR_NOT_APPLICABLE): in a steady cycle
// every end meets the memory point its zone left one cycle before at the same load, a degenerate
// return (at 45 degrees the fold's energy was NaN: a theta node on the stick end, now dh' = 0 there;
// at 90 degrees the stick traction passed the limit by 1e-9 at such a point). The contact is a
// Tresca friction problem (the limit f p(x) is fixed at constant P), whose evolution does not
// increase the distance between states under the same loads: a cycle after one that leaves the
// state as it found it repeats it, and core::add_cycles now copies it (docs/history.md, "The steady
// cycle"). Judged against the independent BEM (reference/bem_history.hpp) at N = 400 on the same
// vertices (two Hertz loadings and one of the flat punch, b_f/a = 0.5): every slip direction, the ends
// within an element width, each cycle's zone energies within 1e-3 of the larger; and the copies
// against the cycles solved one by one where the static solves take them (a line cycle and a chord
// cycle with a patch).
TEST_CASE("periodic loading: a steady cycle is copied, not solved again (out of phase, zero means; BEM)") {
  struct periodic {
    double c[5];  // Qm, Qa, Sm, Sa, phase (degrees)
    int geometry = 0;  // as new_history
  };
  // (the flat punch b_f/a = 0.5 stopped the same way: bench/results/periodic_flat_error.md, case 6)
  for (const periodic &pc :
       {periodic{{0, 0.1, 0, 0.3, 45}}, periodic{{0, 0.1, 0, 1.0, 90}}, periodic{{0, 0.1, 0, 1.0, 45}, 1}}) {
    CAPTURE(pc.geometry);
    CAPTURE(pc.c[3]);
    CAPTURE(pc.c[4]);
    const int cycles = 4;
    hist_handle h;
    new_history(h, pc.geometry);
    REQUIRE(hs_history_add_cycles(h.h, pc.c[0], pc.c[1], pc.c[2], pc.c[3], pc.c[4], cycles) == HS_OK);
    int method = -1;
    REQUIRE(hs_history_method(h.h, &method) == HS_OK);
    CHECK(method == HS_HISTORY_STATIC);
    size_t n = 0;
    REQUIRE(hs_history_vertex_count(h.h, &n) == HS_OK);
    REQUIRE(n == 1 + 64 * cycles);  // sigma first (Q0 = 0: one ramp vertex), then 64 chords a cycle
    hs_cycle_summary cs;
    cs.struct_size = sizeof cs;
    REQUIRE(hs_history_cycle_summary(h.h, &cs) == HS_OK);
    CHECK(cs.cycles == cycles);
    CHECK(cs.cycles_to_steady >= 1);
    CHECK(cs.cycles_repeated >= 1);
    CHECK(cs.repeated_change >= 0);
    CHECK(cs.repeated_change <= 1e-6);
    // a caller's struct from before the copies' fields gets the fields it has
    hs_cycle_summary old;
    std::memset(&old, 0x5a, sizeof old);
    old.struct_size = offsetof(hs_cycle_summary, cycles_repeated);
    REQUIRE(hs_history_cycle_summary(h.h, &old) == HS_OK);
    CHECK(old.energy_per_cycle_patch == cs.energy_per_cycle_patch);
    CHECK(old.cycles_repeated == 0x5a5a5a5a);
    old.struct_size = offsetof(hs_cycle_summary, cycles_repeated) + 1;
    CHECK(hs_history_cycle_summary(h.h, &old) == HS_ERR_STRUCT_SIZE);
    // the last cycle is a copy of the third (solved, or itself a copy of the second): the same
    // states and energies at the same loads, with an estimate at least the one it copies
    double emax = 0;
    for (size_t k = 0; k < 64; ++k) {
      const auto a = vertex(h, 1 + 64 * 2 + k), b = vertex(h, 1 + 64 * 3 + k);
      CHECK(b.cycle == cycles);
      CHECK(std::fabs(b.Q_over_fP - a.Q_over_fP) <= 1e-15);
      CHECK(std::fabs(b.sigma_over_fp0 - a.sigma_over_fp0) <= 1e-15);
      CHECK(b.b1 == a.b1);
      CHECK(b.b2 == a.b2);
      CHECK(b.energy1 == a.energy1);
      CHECK(b.energy2 == a.energy2);
      CHECK(b.error_estimate >= a.error_estimate);
      CHECK(b.error_estimate < 1e-6);
      emax = std::max({emax, b.energy1, b.energy2});
    }
    CHECK(emax > 0);
    path_t vs;
    for (size_t i = 0; i < n; ++i) {
      const auto v = vertex(h, i);
      vs.push_back({v.Q_over_fP, v.sigma_over_fp0});
    }
    hs::reference::bem::options bo;
    bo.nodes = bo.steps_per_unit = 400;
    const flat_rounded_pressure<double> flat(0.5);
    const auto r = hs::reference::bem::run(
        [&](double x) { return pc.geometry == 0 ? std::sqrt(std::max(1 - x * x, 0.0)) : flat.p(x); }, vs, bo);
    REQUIRE(r.size() == n);
    // each cycle's energy per zone (an interior slip zone's counted with the zone on its side of the
    // stick zone's centre, as the BEM counts it); a vertex's own energy at N = 400 moves by up to 2 %
    // with the element its zone end lies in, the cycle's sum by ~1e-4 (the BEM's spread from N = 400
    // to 800 on these loadings, bench/results/periodic_hertz_*.md: at most 4.7e-4 of the larger zone)
    for (int c = 1; c <= cycles; ++c) {
      CAPTURE(c);
      double E[2] = {0, 0}, B[2] = {0, 0};
      for (size_t i = 1 + 64 * size_t(c - 1); i < 1 + 64 * size_t(c); ++i) {
        CAPTURE(i);
        const auto v = vertex(h, i);
        const bool right = patch_on_right(v);
        E[0] += v.energy1 + (right ? v.energy_patch : 0.0);
        E[1] += v.energy2 + (right ? 0.0 : v.energy_patch);
        B[0] += r[i].energy1;
        B[1] += r[i].energy2;
        CHECK(v.slip_dir1 == r[i].dir1);
        CHECK(v.slip_dir2 == r[i].dir2);
        CHECK(std::fabs(v.b1 - r[i].b1) < bem_element_width(v.b1, 400));
        CHECK(std::fabs(v.b2 - r[i].b2) < bem_element_width(v.b2, 400));
      }
      const double big = std::max(B[0], B[1]);
      CAPTURE(E[0]);
      CAPTURE(B[0]);
      CAPTURE(E[1]);
      CAPTURE(B[1]);
      CHECK(std::fabs(E[0] - B[0]) < 1e-3 * big);
      CHECK(std::fabs(E[1] - B[1]) < 1e-3 * big);
      if (c == cycles) {
        const double total = cs.energy_per_cycle1 + cs.energy_per_cycle2 + cs.energy_per_cycle_patch;
        CHECK(std::fabs(total - (E[0] + E[1])) <= 1e-12 * big);
      }
    }
  }
  // steady_rtol decides what is reported steady, not whether a cycle that cannot be solved becomes a
  // copy: (0, 0.3, 1.5, 0.3, 45 deg) stops in its third cycle (survey case 74; its second changed the
  // state by 1.4e-3), with steady_rtol 0.05 as by default (a first version copied the second cycle there,
  // 0.9 % off the BEM's zone 1 energy against an estimate of 1.4e-3: found by a review)
  {
    hs_history_options o;
    REQUIRE(hs_history_options_default(&o) == HS_OK);
    o.steady_rtol = 0.05;
    hist_handle h;
    new_history(h, 0, &o);
    CHECK(hs_history_add_cycles(h.h, 0, 0.3, 1.5, 0.3, 45, 3) == HS_ERR_NOT_APPLICABLE);
  }
  // copies against the same vertices solved one by one (hs_history_add_vertices copies nothing):
  // a line cycle (mean bulk tension, shear cycling: steady after one cycle, to rounding), and a
  // chord cycle with interior slip zones (its copies need a point that stays stuck outside them),
  // whose second cycle changes the state by 1.3e-9: its third and fourth are copies. Given as a
  // path, its returns to earlier memory points are degenerate (tests/test_static_history.cpp,
  // "degenerate returns"); all four cycles are compared.
  struct copied {
    periodic pc;
    int cycles, per, compared;  // cycles, vertices a cycle, cycles compared
  };
  for (const copied &cc : {copied{{{0, 0.3, 0.5, 0, 0}}, 3, 3, 3}, copied{{{0, 0.1, 0, 1.0, 45}}, 4, 64, 4}}) {
    const periodic &pc = cc.pc;
    CAPTURE(pc.c[1]);
    CAPTURE(pc.c[4]);
    hist_handle hc, hp;
    new_history(hc, 0);
    new_history(hp, 0);
    REQUIRE(hs_history_add_cycles(hc.h, pc.c[0], pc.c[1], pc.c[2], pc.c[3], pc.c[4], cc.cycles) == HS_OK);
    size_t nall = 0;
    REQUIRE(hs_history_vertex_count(hc.h, &nall) == HS_OK);
    // the last cycle is a copy: its vertices are the cycle's before, to the bit
    const size_t per = size_t(cc.per), n = nall - per * size_t(cc.cycles - cc.compared);
    for (size_t k = nall - per; k < nall; ++k) CHECK(vertex(hc, k).b2 == vertex(hc, k - per).b2);
    path_t vs;
    int patches = 0;
    for (size_t i = 0; i < n; ++i) {
      const auto v = vertex(hc, i);
      vs.push_back({v.Q_over_fP, v.sigma_over_fp0});
      patches += v.patch_dir != 0;
    }
    CHECK((patches > 0) == (cc.per == 64));
    add(hp, vs);
    int method = -1;
    REQUIRE(hs_history_method(hp.h, &method) == HS_OK);
    REQUIRE(method == HS_HISTORY_STATIC);
    // every vertex: the same zones, ends within the two estimates (rtol 1e-8 for the solved path,
    // plus k times the state's change for a copy)
    double E[2][3] = {{0, 0, 0}, {0, 0, 0}};  // (copies, solved) x (zone 1, zone 2, patches), the last cycle compared
    for (size_t i = 0; i < n; ++i) {
      CAPTURE(i);
      const auto a = vertex(hc, i), b = vertex(hp, i);
      const double tol = a.error_estimate + b.error_estimate;
      CHECK(std::fabs(a.b1 - b.b1) <= tol);
      CHECK(std::fabs(a.b2 - b.b2) <= tol);
      CHECK(a.slip_dir1 == b.slip_dir1);
      CHECK(a.slip_dir2 == b.slip_dir2);
      CHECK(a.patch_dir == b.patch_dir);
      if (i >= n - per) {
        E[0][0] += a.energy1, E[0][1] += a.energy2, E[0][2] += a.energy_patch;
        E[1][0] += b.energy1, E[1][1] += b.energy2, E[1][2] += b.energy_patch;
      }
    }
    // the path's returns put on their memory points (1.3e-9 to 2.6e-9 a) are in its vertices'
    // estimates, above the rtol of 1e-8 (hs_history_vertex.error_estimate: core memory_snap())
    if (cc.per == 64) {
      double est = 0;
      for (size_t i = 0; i < n; ++i) est = std::max(est, vertex(hp, i).error_estimate);
      CHECK(est > 1e-8 + 1e-9);
      CHECK(est <= 2e-8);
    }
    // the last cycle compared, zone by zone: within 1e-8 of the larger zone, the accuracy asked.
    // (Before the degenerate returns were put on their memory points, the solved third cycle of the
    // chord case put 3.7e-9 more energy into zone 1 at vertex 134 than the second did, 2e-7 of the
    // cycle's, and the path stopped in its fourth.)
    const double big = std::max(E[1][0], E[1][1]);
    CHECK(big > 0);
    for (int z = 0; z < 3; ++z) {
      CAPTURE(z);
      CAPTURE(E[0][z] - E[1][z]);
      CHECK(std::fabs(E[0][z] - E[1][z]) <= 1e-8 * big);
    }
  }
}
