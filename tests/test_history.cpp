// Load histories (issue #14): core/history.hpp against closed forms (monotonic
// solutions, Ciavarella-Jager unloading, 4x the monotonic energy per steady
// proportional cycle) and against the independent collocation BEM of
// reference/bem_history.hpp (non-proportional paths, the receding ray), and
// against the static-solve oracle of reference/reversal_oracle.hpp (a segment
// after a Hertz ramp along which both ends only advance, to ~1e-15).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <memory>
#include <string>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/reversal_oracle.hpp"

using namespace hs::core;

namespace {

std::shared_ptr<const pressure_model<double>> hertz_pm() { return std::make_shared<hertz_pressure<double>>(); }

// (interior slip patches merged, as before issue 14 made them an error by default:
// these tests measure the merge's accuracy against the BEM; the default is tested below)
history_options<double> opts(double step) {
  history_options<double> o;
  o.max_step = step;
  o.merge_interior_patches = true;
  return o;
}

// monotonic closed forms (canonical units)
hertz_solution<double> mono(double q, double s) {
  hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  return solve_hertz<double>(sc);
}

double bem_p(double x) { return std::sqrt(std::max(0.0, 1 - x * x)); }

// the independent BEM on the Hertz contact, 400 elements and 400 increments per unit of load
const int bem_nodes = 400;
std::vector<hs::reference::bem::vertex_state> bem_run(const std::vector<std::pair<double, double>> &path) {
  hs::reference::bem::options bo;
  bo.nodes = bem_nodes;
  bo.steps_per_unit = bem_nodes;
  return hs::reference::bem::run(bem_p, path, bo);
}

}  // namespace

TEST_CASE("history: a ramp from zero that does not recede is the monotonic solution (Hertz)") {
  // same sign, opposite sign short of receding (e > 2/lambda), pure bulk tension, negative loads
  const double cases[][2] = {{0.5, 0.4}, {0.2, 0.6}, {0.0, 1.0}, {-0.3, 0.2}, {0.6, -0.1}};
  for (const auto &c : cases) {
    history<double> h(hertz_pm(), opts(1.0 / 128));
    h.add_vertex(c[0], c[1]);
    const auto &v = h.vertices().back();
    const auto m = mono(c[0], c[1]);
    CAPTURE(c[0]);
    CAPTURE(c[1]);
    // march error at step 1/128 (falls like step^3.4; "converges like step^3" below)
    CHECK(std::fabs(v.b1 - m.b1()) < 5e-8);
    CHECK(std::fabs(v.b2 - m.b2()) < 5e-8);
    CHECK(v.dir1 == m.dir1());
    CHECK(v.dir2 == m.dir2());
    CHECK(std::fabs(v.energy1 - m.energy(1)) <= 5e-7 * (m.energy(1) + m.energy(2)));
    CHECK(std::fabs(v.energy2 - m.energy(2)) <= 5e-7 * (m.energy(1) + m.energy(2)));
  }
}

TEST_CASE("history: the ramp of a general pressure is the monotonic general solution (flat punch)") {
  auto pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
  for (const auto &c : {std::make_pair(0.3, 0.2), std::make_pair(0.1, 0.5)}) {
    history<double> h(pm, opts(1.0 / 128));
    h.add_vertex(c.first, c.second);
    general_scene<double> sc;
    sc.q = c.first;
    sc.s = c.second;
    const auto m = solve_general<double>(*pm, sc);
    const auto &v = h.vertices().back();
    CHECK(std::fabs(v.b1 - m.b1()) < 1e-7);
    CHECK(std::fabs(v.b2 - m.b2()) < 1e-7);
    CHECK(std::fabs(v.energy1 - m.energy(1)) <= 2e-6 * (m.energy(1) + m.energy(2)));
    CHECK(std::fabs(v.energy2 - m.energy(2)) <= 2e-6 * (m.energy(1) + m.energy(2)));
  }
}

TEST_CASE("history: unloading after monotonic loading (Ciavarella-Jager, Hertz, sigma = 0)") {
  history<double> h(hertz_pm(), opts(1.0 / 128));
  const double Qs = 0.6, Q = 0.2;
  h.add_vertex(Qs, 0);
  h.add_vertex(Q, 0);
  const auto &v = h.vertices().back();
  const double c = std::sqrt(1 - (Qs - Q) / 2), c1 = std::sqrt(1 - Qs);
  CHECK(std::fabs(v.b1 - c) < 1e-8);
  CHECK(std::fabs(v.b2 - c) < 1e-8);
  CHECK(v.dir1 == -1);
  CHECK(v.dir2 == -1);
  // traction q* - q_{2f}(dQ): fp0 [sqrt(1-x^2) - sqrt(c1^2-x^2)] - 2 fp0 [sqrt(1-x^2) - sqrt(c^2-x^2)]
  double worst = 0;
  for (int i = -20; i <= 20; ++i) {
    const double x = 0.999 * i / 20.0;
    auto cap = [](double r, double y) { return std::fabs(y) < r ? std::sqrt(r * r - y * y) : 0.0; };
    const double p = std::sqrt(1 - x * x);
    const double expect = (p - cap(c1, x)) - 2 * (p - cap(c, x));
    worst = std::max(worst, std::fabs(h.traction(x, v.step_end) - expect));
  }
  MESSAGE("unloading: largest traction error " << worst << " f p0");
  CHECK(worst < 1e-7);
  // energy of the unloading stroke: twice the monotonic energy at (Qs - Q)/2 (friction 2f)
  const auto m = mono((Qs - Q) / 2, 0);
  CHECK(std::fabs(v.energy1 - 2 * m.energy(1)) < 1e-7 * m.energy(1));
}

TEST_CASE("history: steady proportional cycles dissipate 4x the monotonic energy per zone") {
  // in-phase cycles between -L and +L (no receding along the ray): every stroke is a
  // monotonic problem with friction 2f at L; per cycle, per zone, 4 E_mono(L)
  for (const auto &c : {std::make_pair(0.5, 0.4), std::make_pair(0.2, 0.6), std::make_pair(0.3, -0.3)}) {
    history<double> h(hertz_pm(), opts(1.0 / 128));
    const auto r = add_cycles<double>(h, 0, c.first, 0, c.second, 0, 3, ramp_order::sigma_first, 64, 1e-6);
    const auto m = mono(c.first, c.second);
    CAPTURE(c.first);
    CAPTURE(c.second);
    CHECK(r.cycles == 3);
    CHECK(r.cycles_to_steady == 2);  // cycle 1 holds the first loading from zero
    CHECK(!r.shakedown);
    const double E = m.energy(1) + m.energy(2);
    CHECK(std::fabs(r.energy1 - 4 * m.energy(1)) < 1e-6 * E);
    CHECK(std::fabs(r.energy2 - 4 * m.energy(2)) < 1e-6 * E);
    // the turning points have the monotonic zones, with alternating directions
    const auto &vs = h.vertices();
    const auto &peak = vs[vs.size() - 3], &trough = vs[vs.size() - 2];
    CHECK(std::fabs(peak.b1 - m.b1()) < 5e-7);
    CHECK(std::fabs(trough.b2 - m.b2()) < 5e-7);
    CHECK(peak.dir2 == m.dir2());
    CHECK(trough.dir2 == -m.dir2());
  }
}

TEST_CASE("history: an overload past a closed loop follows the virgin curve (Masing memory, Hertz)") {
  history<double> h(hertz_pm(), opts(1.0 / 128));
  for (double Q : {0.6, 0.2, 0.6, 0.8}) h.add_vertex(Q, 0);
  const auto &v = h.vertices().back();
  // at the closure the end sweeps a region at the friction limit: located to about 1e-6 of the load,
  // which limits these figures (4e-7 a and 4e-6 of dE at step 1/128, docs/history.md)
  CHECK(std::fabs(v.b1 - std::sqrt(0.2)) < 1e-6);
  // the last segment dissipates what the monotonic ramp does from 0.6 to 0.8
  const double dE = mono(0.8, 0).energy(1) - mono(0.6, 0).energy(1);
  CHECK(std::fabs(v.energy1 - dE) < 2e-5 * dE);
  // and the loop 0.6 -> 0.2 -> 0.6 dissipates 2 x 2 E_mono(0.2) per zone (two strokes, friction 2f)
  const auto &vs = h.vertices();
  CHECK(std::fabs(vs[1].energy1 + vs[2].energy1 - 4 * mono(0.2, 0).energy(1)) < 1e-6 * mono(0.2, 0).energy(1));
}

TEST_CASE("history: the march converges like step^3 or better") {
  double prev = 0, prev_err = 0;
  const auto m = mono(0.5, 0.4);
  for (int k = 0; k < 4; ++k) {
    history<double> h(hertz_pm(), opts(std::ldexp(1.0, -4 - k)));
    h.add_vertex(0.5, 0.4);
    const double err = std::fabs(h.vertices().back().b1 - m.b1());
    if (k > 0) {
      MESSAGE("step 2^-" << 4 + k << ": error " << err << ", ratio " << prev_err / err);
      CHECK(prev_err / err > 7.0);  // 2^3 = 8 would be third order
    }
    prev = err;
    prev_err = err;
  }
  (void)prev;
}

TEST_CASE("history: the proportional ray sigma/fp0 = 3 Q/fP recedes, re-sticks and reverses (vs BEM)") {
  history<double> h(hertz_pm(), opts(1.0 / 128));
  std::vector<std::pair<double, double>> path;
  for (int k = 1; k <= 44; ++k) path.emplace_back(0.02 * k, 0.06 * k);
  for (const auto &p : path) h.add_vertex(p.first, p.second);
  const auto bem = bem_run(path);
  const auto &vs = h.vertices();
  // phases from the history solver: grows (dir -1, b1 decreasing) to ~0.46, recedes to b1 = 1, then dir +1
  double bmin = 2, qmin = 0;
  int first_rev = -1;
  for (size_t i = 0; i < vs.size(); ++i) {
    if (vs[i].dir1 == -1 && vs[i].b1 < bmin) {
      bmin = vs[i].b1;
      qmin = vs[i].q;
    }
    if (first_rev < 0 && vs[i].dir1 == +1) first_rev = int(i);
  }
  MESSAGE("zone 1 smallest stick end b1 = " << bmin << " at Q/fP = " << qmin
                                            << "; slips +1 from Q/fP = " << (first_rev >= 0 ? vs[first_rev].q : -1));
  CHECK(qmin == doctest::Approx(0.46).epsilon(0.03));
  CHECK(bmin == doctest::Approx(0.942).epsilon(1e-3));
  REQUIRE(first_rev >= 0);
  CHECK(vs[first_rev].q > 0.49);
  CHECK(vs[first_rev].q < 0.56);
  // receding: b1 grows between the minimum and the reversal, with dir -1
  for (size_t i = 1; i < size_t(first_rev); ++i)
    if (vs[i].q > qmin + 0.01) CHECK(vs[i].b1 > vs[i - 1].b1);
  // against the BEM at every vertex: zone ends within 1.5 element widths, same directions where the zone is
  // longer than the mesh
  for (size_t i = 0; i < vs.size(); ++i) {
    // a receding end leaves traction at the friction limit on both sides of it, and the BEM counts
    // the elements next to it with vanishing slip increments as slipping: there its ends lag by up to
    // 4e-3 a at 400 elements and close in on ours as the mesh refines (0.9663, 0.9694, 0.9693 at
    // 400/800/1600 elements against 0.9702 at Q/fP = 0.48): a band of 5e-3 a in that phase
    const bool receding = vs[i].dir1 == -1 && vs[i].q > qmin + 1e-9;
    const double w1 = receding ? 5e-3
                               : M_PI / bem_nodes * std::sqrt(std::max(1e-4, 1 - vs[i].b1 * vs[i].b1)) * 1.5 + 1e-4;
    const double w2 = M_PI / bem_nodes * std::sqrt(std::max(1e-4, 1 - vs[i].b2 * vs[i].b2)) * 1.5 + 1e-4;
    CAPTURE(vs[i].q);
    CHECK(std::fabs(vs[i].b1 - bem[i].b1) < w1);
    CHECK(std::fabs(vs[i].b2 - bem[i].b2) < w2);
    if (1 - vs[i].b1 > 0.01) CHECK(vs[i].dir1 == bem[i].dir1);
    CHECK(vs[i].dir2 == bem[i].dir2);
  }
  CHECK(vs.back().b1 == doctest::Approx(0.964).epsilon(1e-3));
}

namespace {

// history vs BEM along a path: zone ends and energies per segment
void compare_with_bem(const std::vector<std::pair<double, double>> &path, const std::string &what,
                      bool interior_patch) {
  history<double> h(hertz_pm(), opts(1.0 / 256));
  for (const auto &p : path) h.add_vertex(p.first, p.second);
  const auto bem = bem_run(path);
  const auto &vs = h.vertices();
  REQUIRE(vs.size() == bem.size());
  double eb = 0, ee = 0, etot = 0;
  for (size_t i = 0; i < vs.size(); ++i) etot = std::max(etot, vs[i].energy1 + vs[i].energy2);
  // an interior slip patch appears on the out-of-phase path (the BEM's traction shows it), not on the other
  CHECK((h.interior_merges() > 0) == interior_patch);
  for (size_t i = 0; i < vs.size(); ++i) {
    CAPTURE(i);
    // a segment on which an interior slip patch was merged with the edge zone (an approximation,
    // docs/history.md) and the two after it are compared to 1.5e-1 and 3e-2 of their energy (the
    // merge happens where the limit margin first crosses its threshold; moving it within that
    // threshold changes the next segment's energy by 0.2 %, and that segment is 2.04 % from the BEM)
    auto merged_at = [&](size_t k) { return vs[k].interior_merges != (k ? vs[k - 1].interior_merges : 0); };
    const bool merged = merged_at(i);
    const bool after = (i > 0 && merged_at(i - 1)) || (i > 1 && merged_at(i - 2));
    const double w1 = M_PI / bem_nodes * std::sqrt(std::max(1e-4, 1 - vs[i].b1 * vs[i].b1)) * 1.5 + 1e-4;
    const double w2 = M_PI / bem_nodes * std::sqrt(std::max(1e-4, 1 - vs[i].b2 * vs[i].b2)) * 1.5 + 1e-4;
    const double wm = merged || after ? 1e-2 : 0.0;
    CHECK(std::fabs(vs[i].b1 - bem[i].b1) < w1 + wm);
    CHECK(std::fabs(vs[i].b2 - bem[i].b2) < w2 + wm);
    if (1 - vs[i].b1 > 0.01) CHECK(vs[i].dir1 == bem[i].dir1);
    if (1 - vs[i].b2 > 0.01) CHECK(vs[i].dir2 == bem[i].dir2);
    eb = std::max(eb, std::max(std::fabs(vs[i].b1 - bem[i].b1), std::fabs(vs[i].b2 - bem[i].b2)));
    const double de = std::max(std::fabs(vs[i].energy1 - bem[i].energy1), std::fabs(vs[i].energy2 - bem[i].energy2));
    // the BEM's energy is second order in its mesh (3.5e-5 relative on monotonic loading): 2e-3 of the
    // largest segment energy
    if (merged) CHECK(de < 0.15 * (vs[i].energy1 + vs[i].energy2));
    else if (after) CHECK(de < 0.03 * (vs[i].energy1 + vs[i].energy2));
    else {
      CHECK(de < 2e-3 * etot);
      ee = std::max(ee, de / etot);
    }
  }
  MESSAGE(what << ": largest |b - b_BEM| = " << eb << ", energy difference " << ee
               << " of the largest (segments without interior merges); " << h.interior_merges() << " merges");
}

}  // namespace

TEST_CASE("history: mean bulk tension, then shear cycling (non-proportional, vs BEM)") {
  compare_with_bem({{0.0, 1.0}, {0.4, 1.0}, {-0.4, 1.0}, {0.4, 1.0}, {-0.4, 1.0}}, "sigma then Q cycles", false);
}

TEST_CASE("history: out-of-phase Q and sigma (vs BEM)") {
  // Q = 0.4 sin(th), sigma = 0.8 + 0.6 sin(th + 90 deg), reached along sigma first; two cycles of 16 chords
  std::vector<std::pair<double, double>> path{{0.0, 1.4}};
  for (int c = 0; c < 2; ++c)
    for (int k = 1; k <= 16; ++k) {
      const double th = 2 * M_PI * k / 16;
      path.emplace_back(0.4 * std::sin(th), 0.8 + 0.6 * std::cos(th));
    }
  compare_with_bem(path, "out of phase (90 degrees)", true);
}

TEST_CASE("history: an interior slip patch is a clear status by default (issue 14)") {
  // the out-of-phase path above opens an interior patch (the BEM's traction shows a third zone):
  // by default the march stops there with not_applicable, keeping the vertices before; with
  // merge_interior_patches it merges the patch (counted) and goes on
  std::vector<std::pair<double, double>> path{{0.0, 1.4}};
  for (int k = 1; k <= 16; ++k) {
    const double th = 2 * M_PI * k / 16;
    path.emplace_back(0.4 * std::sin(th), 0.8 + 0.6 * std::cos(th));
  }
  history_options<double> strict = opts(1.0 / 64);
  strict.merge_interior_patches = false;
  history<double> a(hertz_pm(), strict), b(hertz_pm(), opts(1.0 / 64));
  size_t first_merge = path.size();
  for (size_t i = 0; i < path.size(); ++i) {
    b.add_vertex(path[i].first, path[i].second);
    if (b.interior_merges() > 0 && first_merge == path.size()) first_merge = i;
  }
  REQUIRE(first_merge < path.size());
  int st = 0;
  size_t failed_at = path.size();
  for (size_t i = 0; i < path.size() && failed_at == path.size(); ++i) {
    try {
      a.add_vertex(path[i].first, path[i].second);
    } catch (const error &e) {
      st = int(e.code());
      failed_at = i;
    }
  }
  CHECK(st == int(status::not_applicable));
  CHECK(failed_at == first_merge);
  CHECK(a.vertices().size() == first_merge);
  CHECK(a.interior_merges() == 0);
}

// Holding Q/fP = 0.95 while sigma goes from 0 to -2.5/fp0 (Hertz) opens an interior slip
// zone: the BEM's traction at sigma/fp0 = -0.25 shows a zone slipping +1 at about
// (-0.47, -0.21) a inside the stick zone (-0.98, 0.12) a, which later joins zone 1. The
// refined march merged it at every step and then lost its way: NO_CONVERGENCE after 5 s
// (rtol 1e-6), and on (0.95, 2.5) -> (0.95, -2.5) at rtol 0 after 0.9 s in release and 18 s
// under ASan (the fuzz corpus' hertz-interior-zone-near-gross-sliding, named slow-* until then). Now the status names
// the interior zone: at rtol 0 the single march is strict; under refinement, two marches
// that both fail after merging a patch stop the segment.
TEST_CASE("history: an interior slip zone met near gross sliding is named, not a failed iteration") {
  // the BEM: an interior slip zone (a run of elements at the friction limit, between stuck
  // elements, inside the stick zone)
  {
    hs::reference::bem::options bo;
    bo.nodes = 200;
    bo.steps_per_unit = 200;
    std::vector<double> qo, ho, xo;
    hs::reference::bem::run(bem_p, {{0.95, 0.0}, {0.95, -0.25}}, bo, &qo, &ho, &xo);
    std::vector<int> runs;  // the slip state of each run of equal states, left to right
    for (size_t k = 0; k < xo.size(); ++k) {
      const double p = bem_p(xo[k]);
      const int state = std::fabs(qo[k]) > 0.999 * p ? (qo[k] > 0 ? 1 : -1) : 0;
      if (runs.empty() || runs.back() != state) runs.push_back(state);
    }
    // stuck at the edge element, slip -1 (zone 2), stuck, slip +1 (interior), stuck, slip +1
    // (zone 1), stuck at the edge element: a slip run between two stuck runs, neither of them
    // the first or the last run (the BEM's edge elements)
    int interior = 0;
    for (size_t k = 2; k + 2 < runs.size(); ++k)
      if (runs[k] != 0 && runs[k - 1] == 0 && runs[k + 1] == 0) ++interior;
    CAPTURE(runs.size());
    CHECK(interior >= 1);
  }
  auto status_of = [](double rtol, const std::vector<std::pair<double, double>> &path, size_t &done) {
    history_options<double> o;
    o.max_step = 1.0 / 16;
    refined_history<double> h(hertz_pm(), o, rtol);
    done = 0;
    try {
      for (const auto &v : path) {
        h.add_vertex(v.first, v.second);
        ++done;
      }
    } catch (const error &e) {
      return int(e.code());
    }
    return 0;
  };
  size_t done = 0;
  CHECK(status_of(1e-6, {{0.95, 0.0}, {0.95, -2.5}}, done) == int(status::not_applicable));
  CHECK(done == 1);
  // (at rtol 0 and step 1/16 the march's first vertex is wrong: zone 1, reversed on the receding
  // ray, is left closed at the edge, b1 = 1, with the stick traction 7 times past the limit next to
  // it; the static solves and the march at step 1/32 give b1 = 0.8486 slipping +1. The check of the
  // vertex's state stops it there, session 15; before, vertex 2 stopped at the interior zone.)
  CHECK(status_of(0, {{0.95, 2.5}, {0.95, -2.5}}, done) == int(status::no_convergence));
  CHECK(done == 0);
}

// The march models one slip zone per edge. Found by bench/stress_history.cpp (300 random
// paths, session 11): on these two paths part of an edge zone next to the contact edge
// would slip back against the zone's direction over the last segment. The BEM (400
// elements) shows what happens instead: that part sticks, a stuck band inside the edge zone,
// and (flat punch) the edge itself slips the other way; the march's zone end is then
// 0.54 a (Hertz) and 0.77 a (flat punch) from the BEM's, zone 1's energy 5 % off (Hertz) and
// zone 2's negative (flat punch: -2.8e-4 against the BEM's 6.4e-3), with status OK before. Now: status::not_applicable at that vertex (history_vertex::
// backslip_i beyond refined_history::backslip_limit), the vertices before kept and in
// agreement with the BEM; the back-slip itself does not shrink with the step (not an
// artefact of steps across an event, which shrinks like the step).
TEST_CASE("history: a zone part next to the contact edge that would slip back is a clear status") {
  struct pcase {
    std::shared_ptr<const pressure_model<double>> pm;
    std::vector<std::pair<double, double>> path;
    int zone;  // the zone that would slip back on the last segment
  };
  const std::vector<pcase> cases{
      {hertz_pm(),
       {{-0.49671017144313845, -0.00013050525576818739},
        {0.39142282007450102, -1.0001835708571032},
        {0.86819162547328688, 0.34382313637631667}},
       1},
      {std::make_shared<flat_rounded_pressure<double>>(0.29705882352941176),
       {{-0.71113624181515678, -2.2263521957782282},
        {-0.16576515266809239, 2.118560350230267},
        {0.61147350713629356, 0.862584913159824},
        {0.70402288353656561, 0.53515295938960983}},
       2}};
  for (const auto &c : cases) {
    CAPTURE(c.zone);
    const size_t last = c.path.size() - 1;
    // the BEM: the last vertex's edge zone is not the march's (a stuck band splits it)
    hs::reference::bem::options bo;
    bo.nodes = bem_nodes;
    bo.steps_per_unit = bem_nodes;
    const auto bem = hs::reference::bem::run([&](double x) { return c.pm->p(x); }, c.path, bo);
    // plain marches at two steps: the back-slip of the last segment stays as the step shrinks
    double ratio[2];
    for (int k = 0; k < 2; ++k) {
      history<double> h(c.pm, opts(k == 0 ? 1.0 / 32 : 1.0 / 128));
      for (const auto &v : c.path) h.add_vertex(v.first, v.second);
      double emax = 0;
      for (const auto &v : h.vertices()) emax = std::max({emax, std::fabs(v.energy1), std::fabs(v.energy2)});
      const auto &v = h.vertices().back();
      ratio[k] = (c.zone == 1 ? v.backslip1 : v.backslip2) / emax;
      CHECK(ratio[k] > 1e-3);
      // the march's zone end against the BEM's: far apart
      CHECK(std::fabs((c.zone == 1 ? v.b1 - bem[last].b1 : v.b2 - bem[last].b2)) > 0.3);
      // before the last segment no back-slip, and the ends within the BEM's accuracy
      for (size_t i = 0; i < last; ++i) {
        CHECK(h.vertices()[i].backslip1 <= 1e-6 * emax);
        CHECK(h.vertices()[i].backslip2 <= 1e-6 * emax);
        CHECK(std::fabs(h.vertices()[i].b1 - bem[i].b1) < 5e-3);
        CHECK(std::fabs(h.vertices()[i].b2 - bem[i].b2) < 5e-3);
      }
    }
    CHECK(ratio[1] > ratio[0] / 2);
    // the refined march (the C ABI's; at rtol 1e-5, as at its default 1e-8 the flat punch's
    // first segment alone refines for ~20 s, and at fixed steps): a status
    for (double rtol : {1e-5, 0.0}) {
      CAPTURE(rtol);
      history_options<double> o;
      o.max_step = 1.0 / 64;
      refined_history<double> h(c.pm, o, rtol);
      for (size_t i = 0; i < last; ++i) h.add_vertex(c.path[i].first, c.path[i].second);
      int st = 0;
      try {
        h.add_vertex(c.path[last].first, c.path[last].second);
      } catch (const error &e) {
        st = int(e.code());
      }
      CHECK(st == int(status::not_applicable));
      CHECK(h.vertices().size() == last);
    }
  }
}

// A band too small to matter (Hertz, the same stress run: back-slip 3.7e-7 of the largest
// energy at every step from 1/8 to 1/512, so the path's, not the march's): the segment is
// taken, with 3 times the back-slip in its error estimate (refined_history::backslip_estimate).
TEST_CASE("history: a small back-slip is taken into the error estimate, not a status") {
  refined_history<double> h(hertz_pm(), history_options<double>{}, 1e-8);
  h.add_vertex(-0.1593075220928715, 0.5136211451070738);
  h.add_vertex(-0.6021707079726667, -0.41043645081887986);
  const auto &v = h.vertices().back();
  const double emax = std::max({std::fabs(h.vertices()[0].energy1), std::fabs(h.vertices()[0].energy2),
                                std::fabs(v.energy1), std::fabs(v.energy2)});
  CHECK(v.backslip1 > 1e-7 * emax);
  CHECK(v.backslip1 < 1e-6 * emax);
  CHECK(v.error_estimate >= 3 * v.backslip1 / emax);
}

TEST_CASE("history: degenerate vertices and bad input") {
  history<double> h(hertz_pm(), opts(1.0 / 64));
  h.add_vertex(0.3, 0.2);
  const auto a = h.vertices().back();
  h.add_vertex(0.3, 0.2);  // zero-length segment: nothing moves, nothing dissipated
  const auto &b = h.vertices().back();
  CHECK(b.b1 == a.b1);
  CHECK(b.b2 == a.b2);
  CHECK(b.energy1 == 0);
  CHECK(b.energy2 == 0);
  h.add_vertex(0, 0);  // back to zero: the zones reverse, locked-in slip stays
  const auto &z = h.vertices().back();
  CHECK(z.dir1 == -1);
  CHECK(z.dir2 == -1);
  CHECK(z.b1 < 1);
  double lock = 0;
  for (double x : {-0.3, 0.0, 0.3}) lock = std::max(lock, std::fabs(h.slip(x, z.step_end)));
  CHECK(lock == 0);                                // the central stick zone never slipped
  CHECK(std::fabs(h.slip(0.99, z.step_end)) > 0);  // the edge keeps slip
  CHECK_THROWS_AS(h.add_vertex(1.0, 0), error);
  CHECK_THROWS_AS(h.add_vertex(std::nan(""), 0), error);
}

TEST_CASE("history: the same template in long double agrees with double") {
  auto pmd = std::make_shared<hertz_pressure<double>>();
  auto pml = std::make_shared<hertz_pressure<long double>>();
  history_options<long double> ol;
  ol.merge_interior_patches = true;
  ol.max_step = 1.0L / 64;
  history<double> hd(pmd, opts(1.0 / 64));
  history<long double> hl(pml, ol);
  for (const auto &p : {std::make_pair(0.4, 0.3), std::make_pair(-0.2, 0.1), std::make_pair(0.1, 0.9)}) {
    hd.add_vertex(p.first, p.second);
    hl.add_vertex(p.first, p.second);
  }
  for (size_t i = 0; i < hd.vertices().size(); ++i) {
    CHECK(std::fabs(hd.vertices()[i].b1 - double(hl.vertices()[i].b1)) < 1e-12);
    CHECK(std::fabs(hd.vertices()[i].b2 - double(hl.vertices()[i].b2)) < 1e-12);
    CHECK(hd.vertices()[i].dir1 == hl.vertices()[i].dir1);
  }
}

TEST_CASE("history: ramp_recedes finds where e = 2/lambda along the ray") {
  auto e_of = [](double q, double s) { return mono(q, s).half_width(); };
  double at = 0;
  CHECK(ramp_recedes<double>(0.88, 2.64, e_of, at));
  CHECK(at == doctest::Approx(0.4603).epsilon(1e-3));
  // the march recedes exactly there: dir -1 zone stops advancing at that Q/fP
  CHECK(std::fabs(mono(at, 3 * at).half_width() - 2.0 / 3) < 1e-12);
  CHECK(!ramp_recedes<double>(0.5, 0.5, e_of, at));  // lambda = 1 < 2: never
  CHECK(!ramp_recedes<double>(0.2, 0.6, e_of, at));  // lambda = 3, but e(0.2) > 2/3
  CHECK(ramp_recedes<double>(-0.88, -2.64, e_of, at));
  CHECK(at == doctest::Approx(-0.4603).epsilon(1e-3));
}

// ---- non-proportional segments after a ramp: the static-solve oracle ---------------------------
// reference/reversal_oracle.hpp solves the state after a segment whose stick-zone ends only
// advance by one static solve (no time stepping): an independent check to ~1e-15 where the BEM
// gives ~1e-3. Cases: (q0, s0) reached by a ramp, then (q1, s1), and the new directions.
namespace {
struct seg_case {
  double q0, s0, q1, s1;
  int d1, d2;
};
const seg_case seg_cases[] = {
    // both zones reverse; zone 1's new end passes the ramp's end (from a random walk of bench_history)
    {0.14915544246907966, 0.12976720841044964, 0.037592776800771471, 0.27947936305003174, -1, -1},
    {0.5, 0.4, 0.2, 0.6, -1, -1},  // both reverse, new zones inside the old ones
    {0.3, 0.0, 0.25, 0.8, -1, 1},  // zone 1 reverses, zone 2 keeps advancing
    {0.4, 0.5, -0.1, 0.3, -1, -1},  // (this and the first and sixth: a new end passes the ramp's end)
    {0.6, 0.2, 0.3, -0.3, -1, -1},
    {0.2, 0.3, 0.1, 0.9, -1, 1},
    {0.45, 0.0, 0.0, 0.0, -1, -1},  // Ciavarella-Jager unloading to zero
};
std::array<double, 2> oracle_ends(const seg_case &c) {
  hs::reference::reversal_oracle<double> o(c.q0, c.s0, c.q1, c.s1, c.d1, c.d2);
  const auto b = o.solve(0.9, 0.9);
  // the static solution is the state only if the stick traction stays inside the limit
  REQUIRE(o.traction_margin(1, b[0], b[1]) < 0);
  REQUIRE(o.traction_margin(2, b[0], b[1]) < 0);
  return b;
}
}  // namespace

TEST_CASE("reversal oracle: monotonic closed forms and Ciavarella-Jager unloading") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (const auto &qs : {std::make_pair(0.3, 0.2), std::make_pair(0.7, -0.4), std::make_pair(0.05, 0.1)}) {
    hs::reference::reversal_oracle<double> o(0, 0, qs.first, qs.second, 1, 1);
    const auto b = o.solve(0.9, 0.9);
    const auto m = mono(qs.first, qs.second);
    // a few ulps: the ends come from quadrature (tanh-sinh to ~eps) through a Newton solve
    CHECK(std::fabs(b[0] - m.b1()) < 64 * eps);
    CHECK(std::fabs(b[1] - m.b2()) < 64 * eps);
    const double e = std::sqrt(1 - qs.first), c = qs.second / 4;
    for (double x : {c - 0.5 * e, c, c + 0.9 * e}) {
      const double exact = std::sqrt(1 - x * x) - std::sqrt(e * e - (x - c) * (x - c));
      CHECK(std::fabs(o.traction(x, b[0], b[1]) - exact) < 64 * eps);
    }
  }
  // unloading q* -> q at sigma = 0: the reversed zones end at sqrt(1 - (q* - q)/2)
  for (double q : {0.3, 0.0, -0.2}) {
    hs::reference::reversal_oracle<double> o(0.45, 0, q, 0, -1, -1);
    const auto b = o.solve(0.9, 0.9);
    const double c = std::sqrt(1 - (0.45 - q) / 2);
    CHECK(std::fabs(b[0] - c) < 64 * eps);
    CHECK(std::fabs(b[1] - c) < 64 * eps);
  }
  // symmetries: all loads, tractions and directions negated gives the same ends; sigma
  // negated mirrors the contact (b1 <-> b2, zone 1 <-> zone 2)
  for (const auto &c : seg_cases) {
    const auto b = oracle_ends(c);
    hs::reference::reversal_oracle<double> neg(-c.q0, -c.s0, -c.q1, -c.s1, -c.d1, -c.d2);
    const auto bn = neg.solve(0.9, 0.9);
    CHECK(std::fabs(bn[0] - b[0]) < 64 * eps);
    CHECK(std::fabs(bn[1] - b[1]) < 64 * eps);
    hs::reference::reversal_oracle<double> mir(c.q0, -c.s0, c.q1, -c.s1, c.d2, c.d1);
    const auto bm = mir.solve(0.9, 0.9);
    CHECK(std::fabs(bm[0] - b[1]) < 64 * eps);
    CHECK(std::fabs(bm[1] - b[0]) < 64 * eps);
  }
  // long double through the same template: double's result to its own rounding
  hs::reference::reversal_oracle<long double> ol(0.4L, 0.5L, -0.1L, 0.3L, -1, -1);
  const auto bl = ol.solve(0.9L, 0.9L);
  const auto bd = oracle_ends(seg_cases[3]);
  CHECK(std::fabs(double(bl[0]) - bd[0]) < 64 * eps);
  CHECK(std::fabs(double(bl[1]) - bd[1]) < 64 * eps);
}

TEST_CASE("history: segments after a ramp against the static-solve oracle, fixed step 1/512") {
  // At step 1/512 the march's own truncation error on these segments is 1e-11 to 1e-9
  // (it falls like step^2.3-step^3 here); 1e-8 is a convergence bound, not a rounding
  // bound. Before the memory-point events (an advancing end restarts its run where it
  // reaches an earlier end position, a cusp of the traction), the crossing cases were
  // off by 5e-6 to 3e-5 at this step.
  for (const auto &c : seg_cases) {
    const auto b = oracle_ends(c);
    history<double> h(hertz_pm(), opts(1.0 / 512));
    h.add_vertex(c.q0, c.s0);
    h.add_vertex(c.q1, c.s1);
    const auto &v = h.vertices().back();
    INFO("case (" << c.q0 << ", " << c.s0 << ") -> (" << c.q1 << ", " << c.s1 << ")");
    CHECK(v.dir1 == c.d1);
    CHECK(v.dir2 == c.d2);
    CHECK(std::fabs(v.b1 - b[0]) < 1e-8);
    CHECK(std::fabs(v.b2 - b[1]) < 1e-8);
  }
}

TEST_CASE("history: refined march at rtol 1e-8 within twice its estimate (oracle)") {
  // The estimate is the difference of the last two marches over 7 (third order). Here the
  // march converges like step^2.3 (ratio 5 per halving), so the finer march's true error is
  // that difference over 4 = 1.75 x the estimate: 2 x bounds it. Two of these cases failed
  // before the refinement stopped only on two non-shrinking differences in a row (errors
  // 1.3e-5 and 1.1e-7 a against estimates 2.7e-6 and 2.9e-8) and before a step that ends
  // within 1 % of its move short of a memory point counted as reaching it.
  for (const auto &c : seg_cases) {
    const auto b = oracle_ends(c);
    refined_history<double> h(hertz_pm(), opts(1.0 / 32), 1e-8);
    h.add_vertex(c.q0, c.s0);
    h.add_vertex(c.q1, c.s1);
    const auto &v = h.vertices().back();
    INFO("case (" << c.q0 << ", " << c.s0 << ") -> (" << c.q1 << ", " << c.s1 << "), estimate "
                  << v.error_estimate);
    const double err = std::max(std::fabs(v.b1 - b[0]), std::fabs(v.b2 - b[1]));
    CHECK(err <= 2 * v.error_estimate);
    CHECK(err < 1e-7);
  }
}

// The march's own check of the friction limit samples 8 points from each advancing end with that
// end's sign, and missed a patch of the other sign: Hertz (0, 1.5) -> (0.15, 1.5) -> (0.25, 1.2),
// where a patch slipping +1 lies at (-0.739, -0.578) a while zone 2 slips -1 (the two-interval oracle
// and the BEM, tests/test_patch_oracle.cpp); the march returned zone 2's energy as 1.47e-6 against
// 6.58e-5, with an estimate of 1.4e-8. The state at each vertex is now checked at 64 points of the
// stick zone, both signs (history::interior_excess): the history stops there, naming the zone, unless
// patches are merged.
TEST_CASE("history: an interior slip zone open at a vertex stops the march (the reproducer)") {
  refined_history<double> h(hertz_pm(), history_options<double>{}, 1e-8);
  h.add_vertex(0.0, 1.5);
  h.add_vertex(0.15, 1.5);
  CHECK(h.fine().interior_excess() < 0);
  try {
    h.add_vertex(0.25, 1.2);
    FAIL("the march took a vertex with an interior slip zone");
  } catch (const error &e) {
    CHECK(e.code() == status::not_applicable);
    CHECK(std::string(e.what()).find("interior slip zone") != std::string::npos);
  }
  CHECK(h.fine().vertices().size() == 2);  // the vertices before are kept
  // merging, the march goes on (an approximation, as documented)
  history_options<double> o;
  o.merge_interior_patches = true;
  refined_history<double> m(hertz_pm(), o, 1e-8);
  for (const auto &v : {std::make_pair(0.0, 1.5), std::make_pair(0.15, 1.5), std::make_pair(0.25, 1.2)})
    m.add_vertex(v.first, v.second);
  CHECK(m.fine().interior_excess() > 1e-6);  // (the patch is there, unmodelled)
}

// A segment shorter than the march's step (0.02 to 0.09 in max(|dq|, |ds|/4) at max_step 1/32: a
// chord of a periodic loading, a small reversal) was marched in one step at both of the first two
// steps of the refinement; the two marches were the same, their difference 0 was the estimate, and
// the one-step march was accepted. Against the independent oracle the ends were 1.3e-8 and 1.1e-7 a
// off, with the vertex's estimate that of the ramp before it (9.3e-9); hs_history's march at rtol
// 1e-12 on the periodic loading (0, 0.3, 0, 0.3, 90 deg) was 5.7e-6 off in its energies per cycle so
// (estimate 2.8e-8). The refinement now starts at the segment's length.
TEST_CASE("refined march: a segment shorter than the step is refined; its estimate covers its error (oracle)") {
  struct seg {
    double q0, s0, q1, s1;
    int d1, d2;
  };
  // Ciavarella-Jager unloading by 0.02; zone 1 reversing while zone 2 goes on (sigma up by 0.09)
  for (const seg &c : {seg{0.3, 0.2, 0.28, 0.2, -1, -1}, seg{0.3, 0.2, 0.3, 0.29, -1, 1}}) {
    CAPTURE(c.q1);
    CAPTURE(c.s1);
    history_options<double> o;
    o.max_step = 1.0 / 32;
    refined_history<double> h(hertz_pm(), o, 1e-8);
    h.add_vertex(c.q0, c.s0);
    h.add_vertex(c.q1, c.s1);
    const auto &vs = h.fine().vertices();
    REQUIRE(vs.size() == 2);
    hs::reference::reversal_oracle<double> orc(c.q0, c.s0, c.q1, c.s1, c.d1, c.d2);
    const auto b = orc.solve(0.9, 0.9);
    REQUIRE(orc.traction_margin(1, b[0], b[1]) < 0);
    REQUIRE(orc.traction_margin(2, b[0], b[1]) < 0);
    const auto &v = vs.back();
    CAPTURE(v.b1 - b[0]);
    CAPTURE(v.b2 - b[1]);
    CAPTURE(v.error_estimate);
    CHECK(v.dir1 == c.d1);
    CHECK(v.dir2 == c.d2);
    CHECK(v.step < std::max(std::fabs(c.q1 - c.q0), std::fabs(c.s1 - c.s0) / 4));  // below the segment's length
    CHECK(v.error_estimate > vs.front().error_estimate);  // the segment's own estimate is added
    MESSAGE("ends off the oracle by ", std::fabs(v.b1 - b[0]), ", ", std::fabs(v.b2 - b[1]), " a; estimate ",
            v.error_estimate);
    // (measured 6.1e-9 and 1.4e-9 a, estimates 1.2e-8 and 1.6e-8)
    CHECK(std::fabs(v.b1 - b[0]) <= v.error_estimate);
    CHECK(std::fabs(v.b2 - b[1]) <= v.error_estimate);
    CHECK(std::fabs(v.b1 - b[0]) <= 1e-8);
    CHECK(std::fabs(v.b2 - b[1]) <= 1e-8);
  }
}
