// Issue 14: segments that end with an interior slip zone open, taken by the two-interval static
// solve (core/include/halfslip/core/static_patch.hpp) inside core::static_history, and the path
// after them (docs/history.md, "Interior slip zones in hs_history"). Independent checks: the
// reference oracle of the two-interval solve (reference/patch_oracle.hpp, its own quadrature and
// Newton, no code shared with core/) and the BEM (reference/bem_history.hpp), which marches small
// load increments with stick/slip decided node by node.
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

namespace {
constexpr double pi = 3.141592653589793238462643383279502884;
double hertz(double x) { return std::sqrt(std::max(0.0, (1 - x) * (1 + x))); }
using path_t = std::vector<std::pair<double, double>>;

std::shared_ptr<hs::core::static_history<double>> walk(const path_t &path) {
  auto sh = std::make_shared<hs::core::static_history<double>>(std::make_shared<hs::core::hertz_pressure<double>>());
  for (const auto &v : path) sh->add_vertex(v.first, v.second);
  return sh;
}
// the reproducer of docs/history.md: (0, 1.5) -> (0.15, 1.5) -> (0.25, 1.2); zone 2 reverses at the
// edge while the inner part of the old zone 2 goes on slipping +1, with 2.3e-3 a of the stick zone
// beyond its old end
const path_t reproducer{{0.0, 1.5}, {0.15, 1.5}, {0.25, 1.2}};
// the same state: ends, patch, and the traction and slip at the points xs, to 1e-10 and 1e-9
void same_state(const hs::core::static_history<double> &one, const hs::core::static_history<double> &two,
                const std::vector<double> &xs) {
  CHECK(std::fabs(one.b1() - two.b1()) < 1e-10);
  CHECK(std::fabs(one.b2() - two.b2()) < 1e-10);
  CHECK(std::fabs(one.patch_l() - two.patch_l()) < 1e-10);
  CHECK(std::fabs(one.patch_r() - two.patch_r()) < 1e-10);
  for (double x : xs) {
    CAPTURE(x);
    CHECK(std::fabs(one.traction(x) - two.traction(x)) < 1e-9);
    CHECK(std::fabs(one.slip(x) - two.slip(x)) < 1e-9);
  }
}
// the BEM's patch at the end of path (N = 800): the run of its elements inside its stick zone at the
// friction limit with the sign of the library's patch lies at the library's patch to two element widths
void patch_against_bem(const path_t &path, const hs::core::static_history<double> &sh) {
  REQUIRE(sh.patch_dir() != 0);
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = 800;
  std::vector<double> xq, qq;
  const auto r = hs::reference::bem::run(hertz, path, bo, &qq, nullptr, &xq);
  REQUIRE(xq.size() == 800);
  double bl = 1, br = -1;
  for (size_t k = 0; k < xq.size(); ++k) {
    const double t0 = pi * double(k) / 800, t1 = pi * double(k + 1) / 800;
    const double l = -std::cos(t0), rr = -std::cos(t1);
    const double m = ((t1 - t0) / 2 - (std::sin(2 * t1) - std::sin(2 * t0)) / 4) / (rr - l);  // mean p
    if (xq[k] > -r.back().b2 && xq[k] < r.back().b1 && sh.patch_dir() * qq[k] >= m * (1 - 1e-9))
      bl = std::min(bl, l), br = std::max(br, rr);
  }
  auto width = [](double b) { return pi / 800 * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (800.0 * 800.0); };
  CHECK(std::fabs(bl - sh.patch_l()) < 2 * width(sh.patch_l()));
  CHECK(std::fabs(br - sh.patch_r()) < 2 * width(sh.patch_r()));
}
}  // namespace

// The library's two-interval solve against the oracle's, from the same start state: ends, the new
// stick traction, the slip change and the energies of the three zones. Measured: ends 1e-15,
// traction 1e-15, slip 3e-11 and energies 3e-12 to 3e-11 of their size (the oracle's 8- and
// 12-point rules; the library's 24).
TEST_CASE("static patch: the two-interval solve against the reference oracle") {
  const auto sh = walk({{0.0, 1.5}, {0.15, 1.5}});
  auto st = std::make_shared<const hs::core::sh_start<double>>(sh->start());
  hs::core::sh_patch<double> P(st, 0.1, -0.3, +1, -1, +1);
  REQUIRE(P.solve({0.9, 0.98, -0.75, -0.575}));
  const auto e = P.solved();
  for (double r : P.residual(e)) CHECK(std::fabs(r) < 1e-13);
  hs::reference::patch_oracle o([&](double x) { return sh->traction(x); }, hertz, sh->memory_points(), 0.1, -0.3, +1,
                                -1, +1);
  const auto eo = o.solve(hs::reference::patch_oracle::ends{0.8935, 0.9888, -0.7396, -0.5778});
  CHECK(std::fabs(e.b1 - eo.b1) < 1e-12);
  CHECK(std::fabs(e.b2 - eo.b2) < 1e-12);
  CHECK(std::fabs(e.pl - eo.pl) < 1e-12);
  CHECK(std::fabs(e.pr - eo.pr) < 1e-12);
  for (double x : {-0.95, -0.8, -0.5, 0.0, 0.5, 0.85, 0.89, -0.74, -0.57}) {
    CAPTURE(x);
    CHECK(std::fabs(P.traction(x) - o.traction(eo, x)) < 1e-12);
  }
  const double x0 = 0.5 * (eo.pr + eo.b1);
  for (double x : {-0.99, -0.9, 0.95, -0.7, -0.65, -0.6}) {
    CAPTURE(x);
    CHECK(std::fabs(P.dh(x) - o.slip_change(eo, {x}, x0)[0]) < 1e-9 * 0.05);
  }
  for (int z = 1; z <= 3; ++z) {
    CAPTURE(z);
    const double Eo = o.energy(eo, z, x0, 12);
    CHECK(std::fabs(P.energy(z) - Eo) < 1e-9 * std::fabs(Eo));
    CHECK(P.one_way(z));
  }
}

// The reproducer as a history: the static solves take the segment with the patch, and then a path
// on (the patch sticks at the turn, the old patch region then lies inside the stick zone at the
// limit: memory points at its ends). Against the BEM at N = 800 at every vertex: the zones'
// directions, ends within an element width, each segment's total energy within 1e-4 of the path's
// largest, the BEM's patch (elements in its stick zone at the limit) at the library's patch, and
// the slip at the end within 5e-5 (measured: energies 1.6e-5 of the segment's at the patch vertex,
// 3e-6 of the largest elsewhere; slip 2.3e-5 at N = 800, 1.0e-5 at N = 1600).
TEST_CASE("static patch: a segment with an interior slip zone and the path after it against the BEM" * HS_LONG) {
  const path_t path{{0.0, 1.5}, {0.15, 1.5}, {0.25, 1.2}, {0.1, 1.2}, {0.3, 1.0}, {0.0, 0.0}};
  auto sh = std::make_shared<hs::core::static_history<double>>(std::make_shared<hs::core::hertz_pressure<double>>());
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = 800;
  std::vector<double> xq, qq, hh;
  const auto r = hs::reference::bem::run(hertz, path, bo, &qq, &hh, &xq);
  auto width = [](double b) { return pi / 800 * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (800.0 * 800.0); };
  double big = 0;
  for (const auto &v : r) big = std::max(big, v.energy1 + v.energy2);
  for (size_t i = 0; i < path.size(); ++i) {
    CAPTURE(i);
    sh->add_vertex(path[i].first, path[i].second);
    const auto &sg = sh->last_segment();
    CHECK(sh->dir1() == r[i].dir1);
    CHECK(sh->dir2() == r[i].dir2);
    CHECK(std::fabs(sh->b1() - r[i].b1) < width(sh->b1()));
    CHECK(std::fabs(sh->b2() - r[i].b2) < width(sh->b2()));
    CHECK(std::fabs(sg.E1 + sg.E2 + sg.Ep - r[i].energy1 - r[i].energy2) < 1e-4 * big);
    CHECK(std::fabs(sg.E1 - r[i].energy1) < 1e-4 * big);
    CHECK((sh->patch_dir() != 0) == (i == 2));
    CHECK((sg.Ep > 0) == (i == 2));
  }
  CHECK(sh->patch_segments() == 1);
  double dh = 0;
  for (size_t k = 0; k < xq.size(); ++k) dh = std::max(dh, std::fabs(hh[k] - sh->slip(xq[k])));
  CHECK(dh < 5e-5);
}

// The patch at the vertex of the reproducer, against the BEM's: the run of elements inside the
// stick zone at the friction limit (+p) lies at (pl, pr) to two element widths.
TEST_CASE("static patch: the patch's ends against the BEM's") {
  const auto sh = walk(reproducer);
  REQUIRE(sh->patch_dir() == +1);
  patch_against_bem(reproducer, *sh);
}

// Along a straight segment on which every point slips one way, the end state does not depend on
// where the segment is cut: the reproducer's last segment in two halves (the second starts with the
// patch open and grows it) reaches the same ends and patch, and the energies add up.
TEST_CASE("static patch: a patch grown over two segments is the patch of one") {
  const auto one = walk(reproducer);
  const auto two = walk({{0.0, 1.5}, {0.15, 1.5}, {0.2, 1.35}, {0.25, 1.2}});
  REQUIRE(two->patch_dir() == +1);
  CHECK(two->patch_segments() == 2);
  same_state(*one, *two, {-0.99, -0.8, -0.7, -0.6, 0.0, 0.95});
  const auto &s1 = one->last_segment();
  const auto &a = two->segment(2), &b = two->segment(3);
  CHECK(std::fabs(a.E1 + b.E1 - s1.E1) < 1e-9 * s1.E1);
  CHECK(std::fabs(a.E2 + a.Ep + b.E2 + b.Ep - s1.E2 - s1.Ep) < 1e-9 * (s1.E2 + s1.Ep));
}

namespace {
// a path against the BEM at N elements: at every vertex the zones' directions, the ends within an
// element width, each zone's energy over the segment (the patch's counted with the zone on its side
// of the stick zone's centre, as the BEM counts it) within etol of the path's largest
void against_bem(const path_t &path, int N, double etol) {
  auto sh = std::make_shared<hs::core::static_history<double>>(std::make_shared<hs::core::hertz_pressure<double>>());
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = N;
  const auto r = hs::reference::bem::run(hertz, path, bo);
  double big = 0;
  for (const auto &v : r) big = std::max({big, v.energy1, v.energy2});
  auto width = [&](double b) { return pi / N * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (double(N) * N); };
  for (size_t i = 0; i < path.size(); ++i) {
    CAPTURE(i);
    sh->add_vertex(path[i].first, path[i].second);
    const auto &sg = sh->last_segment();
    const bool right = sh->patch_dir() != 0 && sh->patch_l() + sh->patch_r() > sh->b1() - sh->b2();
    CHECK(std::isfinite(sg.Ep));
    CHECK(sg.Ep >= 0);
    CHECK(sh->dir1() == r[i].dir1);
    CHECK(sh->dir2() == r[i].dir2);
    CHECK(std::fabs(sh->b1() - r[i].b1) < width(sh->b1()));
    CHECK(std::fabs(sh->b2() - r[i].b2) < width(sh->b2()));
    CHECK(std::fabs(sg.E1 + (right ? sg.Ep : 0.0) - r[i].energy1) < etol * big);
    CHECK(std::fabs(sg.E2 + (right ? 0.0 : sg.Ep) - r[i].energy2) < etol * big);
  }
}
// bench_history's periodic case 30 (Q/fP = 0.15 + 0.1 sin t, sigma/fp0 = 0.3 cos t, sigma first, 64
// chords a cycle), its first k chords
path_t case30(int k) {
  path_t p{{0.0, 0.3}, {0.15, 0.3}};
  for (int j = 1; j <= k; ++j) {
    const double th = 2 * pi * j / 64;
    p.push_back({0.15 + 0.1 * std::sin(th), 0.3 * std::cos(th)});
  }
  return p;
}
}  // namespace

// Slip back at the contact edge (docs/history.md, "Slip back at the contact edge"). On case 30's
// chord 7 (to vertex 8 of the path) the slip rate of zone 2 changes sign along it: the part next to the edge would
// slip back. The BEM shows a reverse zone at the edge (b2 = 0.99985), a stuck band, and the inner
// part of the old zone 2 going on slipping +1; the static solves now take it as a patch, where until
// session 17 they stopped. Chord 38 is the mirror image, with a patch end 4.5e-7 from the memory
// point of the old stick end, where the patch's energy was -inf (a Gauss node of a piece of 6e-12
// rounded onto the root of Y; sh_patch::pv_own). Against the BEM at N = 800 on the 42 vertices:
// directions, ends within an element width, energies within 2.5e-4 of the largest (measured 1.8e-4
// at N = 800 and 4.3e-5 at N = 1600, the BEM's own error; bench/periodic_vertices_bem.cpp), and the BEM's patch at vertex 8 at the
// library's to two element widths.
TEST_CASE("static patch: slip back at the contact edge against the BEM" * HS_LONG) {
  const auto path = case30(40);
  against_bem(path, 800, 2.5e-4);
  const auto sh = walk(case30(7));
  CHECK(sh->patch_dir() == +1);
  CHECK(sh->dir2() == -1);
  CHECK(sh->b2() > 0.9998);
  const auto sh40 = walk(path);
  CHECK(sh40->patch_segments() == 2);
  patch_against_bem(case30(7), *sh);
}

// The slip-back segment cut in two: the second half starts with the patch and the band open and
// grows the patch; the same state and energies as in one segment (every point slipped one way).
TEST_CASE("static patch: a slip-back segment in two halves is the segment of one") {
  auto two = case30(7);
  const auto a = two[7], b = two[8];
  two.insert(two.begin() + 8, {(a.first + b.first) / 2, (a.second + b.second) / 2});
  const auto one = walk(case30(7)), tw = walk(two);
  REQUIRE(tw->patch_dir() == +1);
  same_state(*one, *tw, {-0.9999, -0.99, -0.9, -0.85, 0.0, 0.95});
  const auto &s1 = one->last_segment();
  const auto &p = tw->segment(8), &q = tw->segment(9);
  // (1e-9 of the segment's energy: zone 2's and the patch's, 2e-6, are 4 % of it)
  const double tot = s1.E1 + s1.E2 + s1.Ep;
  CHECK(std::fabs(p.E1 + q.E1 - s1.E1) < 1e-9 * tot);
  CHECK(std::fabs(p.E2 + p.Ep + q.E2 + q.Ep - s1.E2 - s1.Ep) < 1e-9 * tot);
}

// An open patch of which part sticks at once at a turn of the load: case 25 (Q/fP = 0.1 sin t,
// sigma/fp0 = 1.5 + cos t) after its slip back on chord 3 (patch (-0.8935, -0.4779)); on the next
// chord the BEM keeps (-0.5925, -0.4766) at the limit from its first quarter on, the rest of the old
// patch stuck. The static solves take it (until session 17 they asked the new patch to contain the
// old one); against the BEM at N = 800: the zones, energies, and the patch.
TEST_CASE("static patch: part of an open patch sticks at once" * HS_LONG) {
  path_t path{{0.0, 2.5}};  // (the ramp, sigma first; t = 0 is its end)
  for (int j = 1; j <= 4; ++j) {
    const double th = 2 * pi * j / 64;
    path.push_back({0.1 * std::sin(th), 1.5 + std::cos(th)});
  }
  against_bem(path, 800, 2.5e-4);
  const auto sh = walk(path);
  REQUIRE(sh->patch_dir() == +1);
  CHECK(sh->patch_l() > -0.6);
  patch_against_bem(path, *sh);
}

namespace {
// bench/periodic_survey.py's periodic loading (Q/fP = qm + qa sin t, sigma/fp0 = sm + sa sin(t +
// phase), sigma first, 64 chords a cycle), its first n vertices
path_t periodic(double qm, double qa, double sm, double sa, double ph_deg, size_t n) {
  const double ph = ph_deg * pi / 180, s0 = sm + sa * std::sin(ph);
  path_t p;
  if (s0 != 0) p.push_back({0.0, s0});
  if (qm != 0) p.push_back({qm, s0});
  for (int j = 1; p.size() < n; ++j) {
    const double th = 2 * pi * j / 64;
    p.push_back({qm + qa * std::sin(th), sm + sa * std::sin(th + ph)});
  }
  return p;
}
}  // namespace

// An open patch that merges with the edge zone of its direction (static_history::merge_segment):
// at once at a turn of the load (case 21, Q/fP = 0.1 sin t, sigma/fp0 = 1.5 + 0.3 cos t: the patch
// (0.600, 0.910) and zone 1 (0.918, 1) after chord 51 are one zone (0.596, 1) after chord 52), and
// within a chord after the patch has grown on it (case 25, sigma_a = 1: the BEM's patch (0.483,
// 0.741) half way along chord 58 has merged by three quarters). The one-interval phases stopped at the
// fold over the patch ("does not come back to its load"). Against the BEM at N = 800 on every vertex
// up to there (measured: energies within 2.0e-5 and 1.8e-5 of the largest, ends within 1.7e-3 a;
// bench/periodic_vertices_bem.cpp 0 0.1 1.5 SA 90 800 N).
TEST_CASE("static patch: a patch that merges with an edge zone, against the BEM" * HS_LONG) {
  for (const double sa : {0.3, 1.0}) {
    CAPTURE(sa);
    const size_t n = sa == 0.3 ? 53 : 60;  // (the merge at the last vertex)
    const auto path = periodic(0.0, 0.1, 1.5, sa, 90.0, n);
    against_bem(path, 800, 1e-4);
    path_t before(path.begin(), path.end() - 1);
    const auto sb = walk(before), sh = walk(path);
    CHECK(sb->patch_dir() == -1);
    CHECK(sh->patch_dir() == 0);
    CHECK(sh->b1() < sb->patch_l());
  }
}

// A fold whose path comes back to its load steeply next to a cusp (static_history::fold_jump): case
// 84 (Q/fP = 0.15 + 0.3 sin t, sigma/fp0 = 0.3 cos t), chord 83. End 1 reaches a memory point at
// 0.8192 and the path inwards falls below the load; it comes back between d = 0.0940 (lambda 0.899)
// and 0.0958 (1.305) and has no point from 0.117, so the scan doubling d from 0.06 to 0.12 missed
// it, and the segment was refused ("a fold whose path does not come back to its load"). The BEM
// jumps there too (b1 from 0.8204 to 0.7235 in the last quarter of the chord). Against the BEM at N
// = 800 on every vertex to there: energies within 5e-4 of the largest (measured 3.5e-4 at N = 800 and
// 7.5e-5 at N = 1600, the BEM's own error, as large on the first chords as at the fold;
// bench/periodic_vertices_bem.cpp 0.15 0.3 0 0.3 90 N 86).
TEST_CASE("static history: a fold whose path comes back steeply, against the BEM" * HS_LONG) {
  const auto path = periodic(0.15, 0.3, 0.0, 0.3, 90.0, 86);
  against_bem(path, 800, 5e-4);
  const auto sh = walk(path);
  CHECK(sh->b1() < 0.73);
  CHECK(sh->b1() > 0.72);
}

// A segment that no single solve takes, taken in halves (static_history::add_vertex, "Segments taken
// in parts" in docs/history.md). Each half is a segment of its own with every check of one, so the
// vertex is the path with the chord's midpoint as a vertex: the same state, traction and slip to
// rounding (the slip sums the halves' pieces on the chord's lambda), the energies the sums of the
// halves'; one segment record for the vertex. Until session 23 the case was case 160 of
// bench/periodic_survey.py (Q/fP = 0.15 + 0.6 sin t, sigma/fp0 = 1.5 + cos t), chord 47, where until
// session 18 the static solves stopped ("an interior slip zone"; against the BEM at N = 800, energies
// 1.8e-5 of the largest). With the panels resolved to the traction's rounding next to the edges
// (session 23) that chord is refused at full accuracy, whole and in parts, and its midpoint path
// takes the second half in halves; the case is now (Q/fP, sigma/fp0) = (0.15 + 0.1 sin t,
// 1.5 + 0.3 sin t), chord 23 (vertex 24), found by searching the 162 loadings for a chord taken in
// halves. Against the BEM at N = 800 at that vertex: directions, ends within an element width,
// energies within 1e-4 of the path's largest.
TEST_CASE("static history: a segment taken in halves, against the BEM" * HS_LONG) {
  const auto path = periodic(0.15, 0.1, 1.5, 0.3, 0.0, 25);
  const auto sh = walk(path);
  REQUIRE(sh->split_segments() == 1);
  CHECK(walk(path_t(path.begin(), path.end() - 1))->split_segments() == 0);
  CHECK(sh->segment_count() == path.size());
  auto two = path;
  const size_t n = path.size();
  const auto a = two[n - 2], b = two[n - 1];
  two.insert(two.begin() + long(n - 1), {a.first + (b.first - a.first) / 2, a.second + (b.second - a.second) / 2});
  const auto tw = walk(two);
  CHECK(tw->split_segments() == 0);
  same_state(*sh, *tw, {-0.99, -0.9, -0.6, -0.3, 0.0, 0.3, 0.55, 0.65, 0.9, 0.99});
  const auto &s = sh->last_segment(), &p = tw->segment(n - 1), &q = tw->segment(n);
  const double tot = s.E1 + s.E2 + s.Ep;
  CHECK(std::fabs(p.E1 + q.E1 - s.E1) < 1e-12 * tot);
  CHECK(std::fabs(p.E2 + q.E2 - s.E2) < 1e-12 * tot);
  CHECK(std::fabs(p.Ep + q.Ep - s.Ep) < 1e-12 * tot);
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = 800;
  const auto r = hs::reference::bem::run(hertz, path, bo);
  double big = 0;
  for (const auto &v : r) big = std::max({big, v.energy1, v.energy2});
  const auto &v = r.back();
  auto width = [&](double x) { return pi / 800 * std::sqrt(std::max(1 - x * x, 0.0)) + 2.0 / (800.0 * 800.0); };
  CHECK(sh->dir1() == v.dir1);
  CHECK(sh->dir2() == v.dir2);
  CHECK(std::fabs(sh->b1() - v.b1) < width(sh->b1()));
  CHECK(std::fabs(sh->b2() - v.b2) < width(sh->b2()));
  const bool right = sh->patch_dir() != 0 && sh->patch_l() + sh->patch_r() > sh->b1() - sh->b2();
  CHECK(std::fabs(s.E1 + (right ? s.Ep : 0.0) - v.energy1) < 1e-4 * big);
  CHECK(std::fabs(s.E2 + (right ? 0.0 : s.Ep) - v.energy2) < 1e-4 * big);
}

// A patch whose inner end lies just beyond a memory point: case 3 of bench/periodic_survey.py (Q/fP =
// 0.1 sin t, sigma/fp0 = 0.3 sin(t + 90 deg)), chord 38 (vertex 39). Zone 2 reverses at the edge and
// the inner part of the old zone goes on slipping -1 as a patch whose inner end lies 7.1e-7 beyond the
// old stick end (a memory point; the BEM at N = 1600 in eighths of the chord: the patch (-0.9134,
// -0.9110) growing outwards to (-0.9150, -0.9110), the element next to the old end stuck). The
// residuals change steeply within 1e-6 of the point (the patch's outer end moves 3e3 times as fast as
// the inner), and Newton from the inner end W/100 beyond it, the only start until session 18, did not
// reach the root; from 1e-5 W it does. Against the BEM at N = 800 on the 40 vertices: energies within
// 6e-4 of the largest (measured 5.2e-4 at N = 800, at vertex 38, and 1.1e-4 at N = 1600: the BEM's own
// error; below 1e-4 at both at vertex 39; bench/periodic_vertices_bem.cpp 0 0.1 0 0.3 90 N 40), and
// the BEM's patch at the library's to two element widths.
TEST_CASE("static patch: a patch end just beyond a memory point, against the BEM" * HS_LONG) {
  const auto path = periodic(0.0, 0.1, 0.0, 0.3, 90.0, 40);
  const auto before = walk(path_t(path.begin(), path.end() - 1));
  const double m = -before->b2();  // the old stick end of zone 2
  const auto sh = walk(path);
  REQUIRE(sh->patch_dir() == -1);
  CHECK(sh->dir2() == +1);
  CHECK(sh->patch_r() > m);
  CHECK(sh->patch_r() - m < 1e-5);
  CHECK(sh->patch_l() < -0.915);
  against_bem(path, 800, 6e-4);
  patch_against_bem(path, *sh);
}

// The same in quarters and eighths: case 101 (Q/fP = 0.15 + 0.3 sin t, sigma/fp0 = 1.5 + 0.3 sin(t + 45
// deg)), chord 142 (vertex 143), taken as a half, a quarter and two eighths (a patch opens in the
// third part and zone 1 takes it in the fourth), against the path with those points as vertices:
// the slip sums the parts' pieces on the chord's lambda (mapped from each part's own), and the state
// and energies are the parts'. (A review's check: slip within 2.2e-16 on this and two other cases.)
TEST_CASE("static history: a segment taken in quarters and eighths is the path through its parts") {
  const auto path = periodic(0.15, 0.3, 1.5, 0.3, 45.0, 144);
  const auto sh = walk(path);
  REQUIRE(sh->split_segments() == 1);
  auto parts = path;
  const auto a = parts[142], b = parts[143];
  parts.pop_back();
  for (const double f : {0.5, 0.75, 0.875})
    parts.push_back({a.first + f * (b.first - a.first), a.second + f * (b.second - a.second)});
  parts.push_back(b);
  const auto pw = walk(parts);
  CHECK(pw->split_segments() == 0);
  same_state(*sh, *pw, {-0.99, -0.9, -0.6, -0.3, 0.0, 0.3, 0.5, 0.7, 0.9, 0.99});
  double e1 = 0, e2 = 0, ep = 0;
  for (size_t k = 143; k < 147; ++k) e1 += pw->segment(k).E1, e2 += pw->segment(k).E2, ep += pw->segment(k).Ep;
  const auto &s = sh->last_segment();
  const double tot = s.E1 + s.E2 + s.Ep;
  CHECK(std::fabs(e1 - s.E1) < 1e-12 * tot);
  CHECK(std::fabs(e2 - s.E2) < 1e-12 * tot);
  CHECK(std::fabs(ep - s.Ep) < 1e-12 * tot);
}

// The slip of segments made at one accuracy and read at another (static_history::set_accuracy, as
// hs_history does after a vertex retried at full accuracy, which every segment taken in parts is):
// each piece keeps its own lambda rule. A review's reproducer: at full accuracy (16 nodes), then
// read with rtol 1e-8's 12, the slip was off by 1.8e-2 of its largest, 9.6e-2.
TEST_CASE("static history: the slip of earlier segments does not change with the accuracy") {
  const path_t path{{0.0, 0.3}, {0.2, 0.3}, {0.05, 0.5}, {0.25, 0.2}, {-0.1, 0.4}};
  const auto full = walk(path);
  auto reduced = *full;
  reduced.set_accuracy(hs::core::static_history_accuracy<double>::for_rtol(1e-8));
  for (double x = -0.995; x < 1; x += 0.05) {
    CAPTURE(x);
    CHECK(std::fabs(reduced.slip(x) - full->slip(x)) <= 1e-15 * (1 + std::fabs(full->slip(x))));
  }
}
