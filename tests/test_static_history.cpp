// Load histories by static solves of advancing segments (core/static_history.hpp, issue 14):
// against the monotonic closed forms and the general solver (the first segment from zero),
// the independent static-solve oracle (reference/reversal_oracle.hpp, tanh-sinh + Newton,
// no shared code), and the march (core/history.hpp) at fine steps.
#include <doctest/doctest.h>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include "testing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/core/history_fields.hpp"
#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/random_walk.hpp"
#include "halfslip/reference/reversal_oracle.hpp"

using namespace hs::core;

namespace {
std::shared_ptr<const pressure_model<double>> hertz_pm() { return std::make_shared<hertz_pressure<double>>(); }
hertz_solution<double> mono(double q, double s) {
  hertz_scene<double> sc;
  sc.q = q;
  sc.s = s;
  return solve_hertz<double>(sc);
}

// The march (core/history.hpp: time steps of the stuck-interval rates, no code shared with the
// static solves) along path at steps 1/256 (err[0]) and 1/512 (err[1]) against the static state h
// at the path's end: ends in a, the last segment's energies relative to the sum of both; the slip
// directions must agree
using path_t = std::vector<std::pair<double, double>>;
void march_errors(const std::shared_ptr<const pressure_model<double>> &pm, const path_t &path,
                  const static_history<double> &h, double err[2][4]) {
  const auto &sg = h.last_segment();
  const double E = std::fabs(sg.E1) + std::fabs(sg.E2);
  for (int r = 0; r < 2; ++r) {
    history_options<double> o;
    o.max_step = r == 0 ? 1.0 / 256 : 1.0 / 512;
    history<double> m(pm, o);
    for (const auto &v : path) m.add_vertex(v.first, v.second);
    const auto &v = m.vertices().back();
    CHECK(v.dir1 == h.dir1());
    CHECK(v.dir2 == h.dir2());
    err[r][0] = std::fabs(v.b1 - h.b1());
    err[r][1] = std::fabs(v.b2 - h.b2());
    err[r][2] = std::fabs(v.energy1 - sg.E1) / E;
    err[r][3] = std::fabs(v.energy2 - sg.E2) / E;
  }
}
}  // namespace

TEST_CASE("static history: the first segment from zero is the monotonic solution (Hertz closed forms)") {
  const double cases[][2] = {{0.5, 0.4}, {0.2, 0.6}, {0.0, 1.0}, {-0.3, 0.2}, {0.6, -0.1}};
  for (const auto &c : cases) {
    static_history<double> h(hertz_pm());
    h.add_vertex(c[0], c[1]);
    const auto m = mono(c[0], c[1]);
    CAPTURE(c[0]);
    CAPTURE(c[1]);
    CHECK(std::fabs(h.b1() - m.b1()) < 64 * 2.2e-16);
    CHECK(std::fabs(h.b2() - m.b2()) < 64 * 2.2e-16);
    CHECK(h.dir1() == m.dir1());
    CHECK(h.dir2() == m.dir2());
    const auto &sg = h.last_segment();
    const double E = m.energy(1) + m.energy(2);
    CHECK(std::fabs(sg.E1 - m.energy(1)) <= 1e-12 * E);
    CHECK(std::fabs(sg.E2 - m.energy(2)) <= 1e-12 * E);
    for (double x : {-0.99, -0.9, -0.5, 0.0, 0.3, 0.8, 0.95, 0.999}) {
      CAPTURE(x);
      CHECK(std::fabs(h.traction(x) - m.traction(x)) < 1e-12);
      CHECK(std::fabs(h.slip(x) - m.slip(x)) < 1e-12);
    }
  }
}

TEST_CASE("static history: the first segment of a general pressure is the monotonic general solution (flat punch)") {
  for (double bf : {0.3, 0.5, 0.9}) {
    auto pm = std::make_shared<flat_rounded_pressure<double>>(bf);
    for (const auto &c : {std::make_pair(0.3, 0.2), std::make_pair(0.1, 0.5), std::make_pair(-0.6, 0.1)}) {
      static_history<double> h(pm);
      h.add_vertex(c.first, c.second);
      general_scene<double> sc;
      sc.q = c.first;
      sc.s = c.second;
      const auto m = solve_general<double>(*pm, sc);
      CAPTURE(bf);
      CAPTURE(c.first);
      CAPTURE(c.second);
      CHECK(std::fabs(h.b1() - m.b1()) < 1e-12);
      CHECK(std::fabs(h.b2() - m.b2()) < 1e-12);
      const auto &sg = h.last_segment();
      const double E = m.energy(1) + m.energy(2);
      CHECK(std::fabs(sg.E1 - m.energy(1)) <= 1e-10 * E);
      CHECK(std::fabs(sg.E2 - m.energy(2)) <= 1e-10 * E);
      for (double x : {-0.95, -0.5, 0.0, 0.4, 0.9}) {
        CAPTURE(x);
        CHECK(std::fabs(h.traction(x) - m.traction(x)) < 1e-11);
        CHECK(std::fabs(h.slip(x) - m.slip(x)) < 1e-11);
      }
    }
  }
}

namespace {
struct seg_case {
  double q0, s0, q1, s1;
  int d1, d2;
};
// the cases of tests/test_history.cpp's oracle comparison: (q0, s0) reached by a ramp, then (q1, s1)
const seg_case seg_cases[] = {
    {0.14915544246907966, 0.12976720841044964, 0.037592776800771471, 0.27947936305003174, -1, -1},
    {0.5, 0.4, 0.2, 0.6, -1, -1},
    {0.3, 0.0, 0.25, 0.8, -1, 1},
    {0.4, 0.5, -0.1, 0.3, -1, -1},
    {0.6, 0.2, 0.3, -0.3, -1, -1},
    {0.2, 0.3, 0.1, 0.9, -1, 1},
    {0.45, 0.0, 0.0, 0.0, -1, -1},
};
}  // namespace

TEST_CASE("static history: segments after a ramp against the static-solve oracle (Hertz)") {
  for (const auto &c : seg_cases) {
    CAPTURE(c.q1);
    CAPTURE(c.s1);
    hs::reference::reversal_oracle<double> o(c.q0, c.s0, c.q1, c.s1, c.d1, c.d2);
    const auto b = o.solve(0.9, 0.9);
    static_history<double> h(hertz_pm());
    h.add_vertex(c.q0, c.s0);
    h.add_vertex(c.q1, c.s1);
    CHECK(h.dir1() == c.d1);
    CHECK(h.dir2() == c.d2);
    CHECK(std::fabs(h.b1() - b[0]) < 1e-12);
    CHECK(std::fabs(h.b2() - b[1]) < 1e-12);
    for (double t : {0.05, 0.3, 0.5, 0.7, 0.95}) {
      const double x = -b[1] + t * (b[0] + b[1]);
      CAPTURE(x);
      CHECK(std::fabs(h.traction(x) - o.traction(x, b[0], b[1])) < 1e-11);
    }
  }
}

// The march (core/history.hpp) converges to the static solution as its step shrinks. Path:
// sigma first, then Q cycles. In the third segment both zones reverse and zone 1's new end
// passes two memory points; there the march converges only to first order or erratically
// (flat punch: 2.3e-4, 7.4e-5, 2.0e-5, 9.2e-6 a at steps 1/128 ... 1/1024; Hertz: 1.9e-7 a at
// 1/128 to 1/512, 1.2e-6 at 1/1024), so only the march's shrinking error (or agreement to
// 5e-7) is checked there and in what it carries to the next vertex (traction, slip).
// Elsewhere they agree to 2e-8.
TEST_CASE("static history: the march converges to it (Hertz and flat punch, sigma then Q cycles)") {
  std::vector<std::shared_ptr<const pressure_model<double>>> pms{hertz_pm(),
                                                                 std::make_shared<flat_rounded_pressure<double>>(0.5)};
  const std::vector<std::pair<double, double>> path{{0, 0.6}, {0.4, 0.6}, {-0.3, 0.6}, {0.35, 0.6}};
  for (const auto &pm : pms) {
    static_history<double> h(pm);
    std::vector<std::array<double, 6>> st;
    for (const auto &v : path) {
      h.add_vertex(v.first, v.second);
      const auto &sg = h.last_segment();
      st.push_back({h.b1(), h.b2(), sg.E1, sg.E2, h.traction(0.5), h.slip(0.97)});
    }
    CHECK(h.segment(2).pieces.size() == 3);  // two crossings
    std::vector<std::vector<std::array<double, 6>>> mr;
    for (double step : {1.0 / 128, 1.0 / 512}) {
      history_options<double> o;
      o.max_step = step;
      history<double> m(pm, o);
      std::vector<std::array<double, 6>> r;
      for (const auto &v : path) {
        m.add_vertex(v.first, v.second);
        const auto &mv = m.vertices().back();
        r.push_back({mv.b1, mv.b2, mv.energy1, mv.energy2, history_traction_at(m, m.step_count(), 0.5, 1.0, 1.0, 1.0),
                     m.slip(0.97, m.step_count())});
      }
      mr.push_back(r);
    }
    for (size_t k = 0; k < path.size(); ++k) {
      CAPTURE(k);
      for (int j = 0; j < 6; ++j) {
        CAPTURE(j);
        const double e128 = std::fabs(mr[0][k][j] - st[k][j]), e512 = std::fabs(mr[1][k][j] - st[k][j]);
        const double scale = (j == 2 || j == 3) ? st[k][2] + st[k][3] : 1.0;
        // (there the Hertz march is erratic at 1.7e-6 of the energy and 1.9e-7 a, so the floor
        // is the march's own error; the static side is checked against the oracle above)
        if (k == 2 || (k == 3 && j >= 4)) CHECK(e512 < std::max(0.5 * e128, 5e-6 * scale));
        else CHECK(e512 < 2e-8 * scale);
      }
    }
    // the fourth segment reverses both zones inside the third's: Ciavarella-Jager at 2f
    if (pm == pms[0]) {
      const double c = std::sqrt(1 - (0.35 + 0.3) / 2);
      CHECK(std::fabs(st[3][0] - c) < 64 * 2.2e-16);
      CHECK(std::fabs(st[3][1] - c) < 64 * 2.2e-16);
    }
  }
}

// Steady shear cycling at a constant bulk tension: after the first cycle every half cycle
// returns to the turning point before (Masing), and by the superposition at constant normal
// load the state at +-Qa is that at -+Qa plus twice the monotonic solution of Qa alone (no
// sigma increment): the stick zone is the monotonic one of (Qa, 0), centred, and each zone
// dissipates twice its monotonic energy at (Qa, 0) per half cycle. Closed forms for Hertz,
// the general solver for the flat punch: independent of the static solves.
TEST_CASE("static history: steady Q cycles at constant sigma (Masing returns, Ciavarella-Jager)") {
  std::vector<std::shared_ptr<const pressure_model<double>>> pms{hertz_pm(),
                                                                 std::make_shared<flat_rounded_pressure<double>>(0.5)};
  for (const auto &pm : pms) {
    for (const auto &c : {std::make_pair(0.3, 0.6), std::make_pair(0.2, 1.0), std::make_pair(0.45, 0.2)}) {
      const double qa = c.first, sm = c.second;
      CAPTURE(qa);
      CAPTURE(sm);
      general_scene<double> sc;
      sc.q = qa;
      sc.s = 0;
      const auto m = solve_general<double>(*pm, sc);
      static_history<double> h(pm);
      h.add_vertex(0, sm);
      for (int k = 0; k < 10; ++k) {
        h.add_vertex(k % 2 ? qa : -qa, sm);
        if (k < 2) continue;
        const auto &sg = h.last_segment();
        CAPTURE(k);
        CHECK(std::fabs(h.b1() - m.b1()) < 1e-12);
        CHECK(std::fabs(h.b2() - m.b2()) < 1e-12);
        CHECK(std::fabs(sg.E1 - 2 * m.energy(1)) < 1e-10 * m.energy(1));
        CHECK(std::fabs(sg.E2 - 2 * m.energy(2)) < 1e-10 * m.energy(2));
      }
    }
  }
}

namespace {
// a piece on which an end moves outwards: the segment had a receding phase
bool has_receding_piece(const sh_segment<double> &sg) {
  for (const auto &pc : sg.pieces)
    for (size_t j = 1; j < pc.b1.size(); ++j)
      if (pc.b1[j] > pc.b1[j - 1] + 1e-9 || pc.b2[j] > pc.b2[j - 1] + 1e-9) return true;
  return false;
}
}  // namespace

// Issue 14's gap: along the ray sigma/fp0 = 3 Q/fP from zero (Hertz) zone 1 grows, recedes
// over its own slip once the stick half-width reaches e* = 2 |dq/ds| = 2/3 (r_1 = 0: the
// half-width is held there while zone 2 advances), sticks whole when b1 reaches a (so b2 =
// 2 e* - 1 = 1/3 exactly), and then slips the other way, in zone 2's direction. Once the reversed
// zone 1 has grown past the largest extent the first one reached (b1 < 0.9419...), every point
// of the stick zone has been stuck since the start and both zones slip +1: the state is the
// monotonic same-sign one, e = sqrt(1 - q), c = s/4 (closed forms, eq 20; independent of
// the static solves and of the order of the phases).
TEST_CASE("static history: a zone recedes, sticks whole and reverses on the ray sigma = 3 Q (Hertz)") {
  static_history<double> h(hertz_pm());
  h.add_vertex(0.95, 2.85);
  const auto &sg = h.last_segment();
  CHECK(has_receding_piece(sg));
  CHECK(h.dir1() == 1);
  CHECK(h.dir2() == 1);
  CHECK(std::fabs(h.b1() - (2.85 / 4 + std::sqrt(0.05))) < 64 * 2.2e-16);
  CHECK(std::fabs(h.b2() - (std::sqrt(0.05) - 2.85 / 4)) < 64 * 2.2e-16);
  // the phases: while zone 1 recedes the half-width is e* = 2/3; it closes at b2 = 1/3
  double bmin = 1, b2close = 0;
  bool receding_seen = false;
  for (const auto &pc : sg.pieces) {
    bool rec = false;
    for (size_t j = 1; j < pc.b1.size(); ++j) rec = rec || pc.b1[j] > pc.b1[j - 1];
    for (size_t j = 0; j < pc.b1.size(); ++j) {
      if (pc.d1 == -1) bmin = std::min(bmin, pc.b1[j]);
      if (rec) CHECK(std::fabs((pc.b1[j] + pc.b2[j]) / 2 - 2.0 / 3) < 64 * 2.2e-16);
    }
    if (rec) {
      receding_seen = true;
      CHECK(pc.d1 == -1);
      b2close = pc.b2.back();
    }
  }
  CHECK(receding_seen);
  // zone 1's largest extent: the monotonic state where e reaches 2/3 (the independent BEM of
  // tests/test_history.cpp puts the stick end near 0.942 a there)
  CHECK(bmin > 0.9419);
  CHECK(bmin < 0.9421);
  // (the phase's last Gauss node, within 1e-4 a of the closure)
  CHECK(b2close > 1.0 / 3);
  CHECK(b2close < 1.0 / 3 + 1e-4);
  // the traction at the state: the limit p at both ends (both zones +1; the gap grows like the
  // square root of the distance), below it inside
  for (double x : {h.b1() - 1e-14, -h.b2() + 1e-14}) CHECK(std::fabs(h.traction(x) - hertz_pressure<double>().p(x)) < 1e-6);
  for (double x : {0.5, 0.7, 0.9}) CHECK(std::fabs(h.traction(x)) < hertz_pressure<double>().p(x));  // the stick zone (0.489, 0.936)
  // the same state reached in two segments along the ray (a vertex in the receding phase)
  static_history<double> h2(hertz_pm());
  h2.add_vertex(0.48, 1.44);
  CHECK(has_receding_piece(h2.last_segment()));
  h2.add_vertex(0.95, 2.85);
  CHECK(std::fabs(h2.b1() - h.b1()) < 1e-12);
  CHECK(std::fabs(h2.b2() - h.b2()) < 1e-12);
  const double E = sg.E1 + sg.E2;
  CHECK(std::fabs(h2.segment(0).E1 + h2.segment(1).E1 - sg.E1) < 1e-10 * E);
  CHECK(std::fabs(h2.segment(0).E2 + h2.segment(1).E2 - sg.E2) < 1e-10 * E);
  // a vertex late in the receding phase, where zone 1 is short (1 - b1 = 1.5e-3, 4.5e-4, 1.6e-4):
  // the slide from there is resolved to its noise, the state's panel noise over the root of the
  // slide (found by review: a short slide never met 1e5 eps; measured 4e-14, 2.6e-12, 4.2e-11)
  for (double qv : {0.4996, 0.5003, 0.5005}) {
    CAPTURE(qv);
    static_history<double> h3(hertz_pm());
    h3.add_vertex(qv, 3 * qv);
    CHECK(1 - h3.b1() < 2e-3);
    h3.add_vertex(0.95, 2.85);
    CHECK(std::fabs(h3.b1() - h.b1()) < 1e-10);
    CHECK(std::fabs(h3.b2() - h.b2()) < 1e-10);
  }
}

// The same template in long double (Eigen's LU, the Abel panels, the phases): the ray s = 3q in
// one segment ends on the same-sign closed form to 64 eps of long double.
TEST_CASE("static history: the receding ray in long double") {
  static_history<long double> h(std::make_shared<hertz_pressure<long double>>());
  const long double q = 0.95L, s = 2.85L;
  h.add_vertex(q, s);
  const long double ep = std::numeric_limits<long double>::epsilon();
  CHECK(std::fabs(double(h.b1() - (s / 4 + std::sqrt(1 - q)))) < double(64 * ep));
  CHECK(std::fabs(double(h.b2() - (std::sqrt(1 - q) - s / 4))) < double(64 * ep));
}

// Segments with a receding phase (one end recedes with r_i = 0 while the other advances; for
// some, a jump of the receding end at the vertex first), against the march (core/history.hpp,
// a different method: time steps of the stuck-interval rates) at steps 1/256 and 1/512: the
// march converges towards the static state. Measured: the march at 1/512 is within 1.4e-8 a and
// 3e-8 of the energy of the static state on these paths.
TEST_CASE("static history: receding phases against the march (Hertz and flat punch)") {
  struct path {
    int geo;
    double q1, s1, q2, s2;
  };
  const path paths[] = {{0, 0.012, 0.277, 0.099, 0.462},
                        {0, -0.189, 0.473, -0.071, 0.740},
                        {1, -0.148, 0.770, -0.015, 1.072},
                        {1, 0.285, 0.726, 0.391, 0.974}};
  for (const auto &p : paths) {
    CAPTURE(p.geo);
    CAPTURE(p.q1);
    std::shared_ptr<const pressure_model<double>> pm;
    if (p.geo == 0) pm = hertz_pm();
    else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
    static_history<double> h(pm);
    h.add_vertex(p.q1, p.s1);
    h.add_vertex(p.q2, p.s2);
    CHECK(has_receding_piece(h.last_segment()));
    double err[2][4];
    march_errors(pm, {{p.q1, p.s1}, {p.q2, p.s2}}, h, err);
    for (int j = 0; j < 4; ++j) {
      CAPTURE(j);
      CHECK(err[1][j] < 5e-8);
      // converging: the finer march no farther than the coarser, within the march's floor
      CHECK(err[1][j] <= std::max(err[0][j], 1e-8));
    }
    // the traction of the state: at the limit at each end of a slipping zone, within it inside
    for (double x : {-0.999, -0.9, -0.5, 0.0, 0.5, 0.9, 0.999}) {
      if (x > -h.b2() && x < h.b1()) CHECK(std::fabs(h.traction(x)) <= pm->p(x) * (1 + 1e-9) + 1e-10);
    }
    if (h.dir1() != 0) CHECK(std::fabs(h.traction(h.b1() - 1e-10) - h.dir1() * pm->p(h.b1())) < 1e-4);
    if (h.dir2() != 0) CHECK(std::fabs(h.traction(-h.b2() + 1e-10) - h.dir2() * pm->p(-h.b2())) < 1e-4);
  }
}

// The slip of a static state from its phase's start, outside the stick zone, by the outer values
// of the finite Hilbert inversion (sh_start, used for the phases with a fold): from the zero state
// it is the monotonic slip, against the Hertz closed forms and the general solver (independent).
TEST_CASE("static history: slip and energy of a static state from its start (sh_start) against monotonic solutions") {
  std::vector<std::shared_ptr<const pressure_model<double>>> pms{hertz_pm(),
                                                                 std::make_shared<flat_rounded_pressure<double>>(0.5)};
  for (const auto &pm : pms) {
    sh_start<double> S;
    S.pm = pm;
    S.rule = std::make_shared<shdetail::trule<double>>(24);
    sh_panel<double> P;
    P.l = -1;
    P.r = 1;
    P.analytic = true;
    P.c = 0;
    S.panels = {P};
    for (const auto &bp : pm->breakpoints())
      if (bp.x > -1 && bp.x < 1) S.cusps.push_back(bp.x);
    for (const auto &c : {std::make_pair(0.5, 0.4), std::make_pair(0.3, 2.0), std::make_pair(-0.4, 0.3)}) {
      general_scene<double> sc;
      sc.q = c.first;
      sc.s = c.second;
      const auto m = solve_general<double>(*pm, sc);
      const double b1 = m.b1(), b2 = m.b2();
      const int d1 = m.dir1(), d2 = m.dir2();
      CAPTURE(c.first);
      CAPTURE(c.second);
      for (int i = 1; i <= 2; ++i) CHECK(std::fabs(S.energy(i, b1, b2, d1, d2) - m.energy(i)) < 1e-11 * m.energy(i));
      for (double x : {b1 + 0.3 * (1 - b1), 0.999, -b2 - 0.5 * (1 - b2), -0.999}) {
        CAPTURE(x);
        CHECK(std::fabs(S.dh(x, b1, b2, d1, d2) - m.slip(x)) < 1e-11);
      }
    }
  }
}

// A fold on a random walk (Hertz): zone 2 reopens and reaches an earlier end position (a memory
// point) behind which the traction is close to the limit with its sign, left by an earlier zone
// of the same direction; there the path's load would fall as the end goes on, so the ends jump
// at that load to where the path goes on. The state at the vertex is the static one, and the
// phase's slip and energy come from its start and end states (every band point slips one way).
// Against the march, which sweeps such a region at once too: it is erratic there (steps 2^-9 to
// 2^-12: b1 0.9153604469 to 0.9153605502, E2 3.17114e-5 to 3.17117e-5 against 3.17135e-5 here),
// so the comparison is at its floor.
TEST_CASE("static history: a fold (the ends jump at a near-Masing return), against the march") {
  const double path[][2] = {{-0.045517236661488734, 0.18251664855221592},
                            {-0.036373579579636328, 0.014701545775238661},
                            {-0.044572900770694188, 0.2500291447517029}};
  static_history<double> h(hertz_pm());
  for (const auto &p : path) h.add_vertex(p[0], p[1]);
  const auto &sg = h.last_segment();
  CHECK(sg.jumps.size() == 1);
  history_options<double> o;
  o.max_step = 1.0 / 512;
  history<double> m(hertz_pm(), o);
  for (const auto &p : path) m.add_vertex(p[0], p[1]);
  const auto &v = m.vertices().back();
  CHECK(v.dir1 == h.dir1());
  CHECK(v.dir2 == h.dir2());
  CHECK(std::fabs(v.b1 - h.b1()) < 1e-6);
  CHECK(std::fabs(v.b2 - h.b2()) < 1e-6);
  const double E = sg.E1 + sg.E2;
  CHECK(std::fabs(v.energy1 - sg.E1) < 1e-4 * E);
  CHECK(std::fabs(v.energy2 - sg.E2) < 1e-4 * E);
  for (double x : {0.95, 0.99, -0.97, -0.99}) {
    CAPTURE(x);
    CHECK(std::fabs(m.slip(x, m.step_count()) - h.slip(x)) < 1e-6);
  }
  // the state: within the friction limit inside the stick zone, at it at the ends
  for (double x = -h.b2() + 0.01; x < h.b1(); x += 0.05) CHECK(std::fabs(h.traction(x)) < hertz_pressure<double>().p(x));
}

// Paths that return to zero after a ramp and a turn at high bulk tension (session 15). Before, the
// static solves refused the last segment and the march replayed the path:
// - (0.3, 0), (0.3, 1.5), (0.6, 1.5), (0, 0): both zones stick whole at the vertex and reopen, zone 1
//   in its old direction over a region already at the limit (g = 0): its end sweeps onto the old end
//   at no load (a crossing at lambda = 0, which the search took for one before the phase), and Newton
//   then ran the end through the flat region ("an end passed a memory point that was not located");
// - (0.3, 0), (0.3, 1), (0.5, 1), (0, 0): r_1 = 0 exactly at e = 1 (e* = 1), so zone 1's direction
//   was undecided ("an edge stays stuck (r_i = 0)"); it takes the sign r_1 gets as end 2 advances.
// Against the march (core/history.hpp: time steps of the stuck-interval rates, no shared code) at
// steps 1/256 and 1/512. Measured: the march at 1/512 within 1.3e-10 a and 3e-9 of the energy.
TEST_CASE("static history: paths back to zero after a turn at high bulk tension, against the march (Hertz)") {
  const std::vector<path_t> paths{{{0.3, 0}, {0.3, 1.5}, {0.6, 1.5}, {0, 0}}, {{0.3, 0}, {0.3, 1.0}, {0.5, 1.0}, {0, 0}}};
  for (const auto &path : paths) {
    CAPTURE(path[1].second);
    static_history<double> h(hertz_pm());
    for (const auto &v : path) h.add_vertex(v.first, v.second);
    double err[2][4];
    march_errors(hertz_pm(), path, h, err);
    for (int j = 0; j < 4; ++j) {
      CAPTURE(j);
      CHECK(err[1][j] < 1e-8);
      CHECK(err[1][j] <= std::max(err[0][j], 1e-9));
    }
    // the state within the friction limit inside the stick zone
    for (double x = -h.b2() + 0.01; x < h.b1(); x += 0.05) CHECK(std::fabs(h.traction(x)) < hertz_pressure<double>().p(x));
  }
}

// An accuracy asked (static_history_accuracy::for_rtol, what hs_history passes from its
// rtol): the cheaper orders agree with the full-accuracy solve to within rtol on every
// vertex: ends in units of a, segment energies relative to the path's largest, the traction
// in f p0, the slip relative to its largest value. Paths: sigma then Q cycles (the issue's
// non-proportional path), a steady Q cycle, and two segments after a ramp.
TEST_CASE("static history: an rtol-driven solve agrees with the full-accuracy one to within rtol") {
  std::vector<std::shared_ptr<const pressure_model<double>>> pms{hertz_pm(),
                                                                 std::make_shared<flat_rounded_pressure<double>>(0.5)};
  using path = std::vector<std::pair<double, double>>;
  std::vector<path> paths{{{0, 0.6}, {0.4, 0.6}, {-0.3, 0.6}, {0.35, 0.6}},
                          {{0, 0.2}, {0.45, 0.2}, {-0.45, 0.2}, {0.45, 0.2}, {-0.45, 0.2}},
                          {{0.5, 0.4}, {0.2, 0.6}},
                          {{0.4, 0.5}, {-0.1, 0.3}}};
  struct out {
    std::vector<double> b, E, q, h;
  };
  auto run = [](const std::shared_ptr<const pressure_model<double>> &pm, const static_history_accuracy<double> &acc,
                const path &p) {
    out o;
    static_history<double> h(pm, acc);
    for (const auto &v : p) {
      h.add_vertex(v.first, v.second);
      o.b.push_back(h.b1());
      o.b.push_back(h.b2());
      o.E.push_back(h.last_segment().E1);
      o.E.push_back(h.last_segment().E2);
      for (int k = -19; k <= 19; ++k) o.q.push_back(h.traction(0.05 * k + 0.001));
    }
    for (int k = -19; k <= 19; ++k) o.h.push_back(h.slip(0.05 * k + 0.001));
    return o;
  };
  // (below 1e-6 the orders are the full ones, the panels resolved less finely)
  CHECK(static_history_accuracy<double>::for_rtol(1e-6).lambda < static_history_accuracy<double>{}.lambda);
  CHECK(static_history_accuracy<double>::for_rtol(1e-8).panel_tol > static_history_accuracy<double>{}.panel_tol);
  for (const auto &pm : pms) {
    for (const auto &p : paths) {
      const out full = run(pm, static_history_accuracy<double>{}, p);
      double Emax = 0, hmax = 0;
      for (double e : full.E) Emax = std::max(Emax, e);
      for (double v : full.h) hmax = std::max(hmax, std::fabs(v));
      // below 1e-12 the full orders themselves
      {
        const out o = run(pm, static_history_accuracy<double>::for_rtol(1e-14), p);
        CHECK(o.b == full.b);
        CHECK(o.E == full.E);
      }
      for (double rtol : {1e-6, 1e-8, 1e-10, 1e-12}) {
        CAPTURE(rtol);
        CAPTURE(p.front().second);
        CAPTURE(p.back().first);
        const out o = run(pm, static_history_accuracy<double>::for_rtol(rtol), p);
        double eb = 0, eE = 0, eq = 0, eh = 0;
        for (size_t k = 0; k < o.b.size(); ++k) eb = std::max(eb, std::fabs(o.b[k] - full.b[k]));
        for (size_t k = 0; k < o.E.size(); ++k) eE = std::max(eE, std::fabs(o.E[k] - full.E[k]) / Emax);
        for (size_t k = 0; k < o.q.size(); ++k) eq = std::max(eq, std::fabs(o.q[k] - full.q[k]));
        for (size_t k = 0; k < o.h.size(); ++k) eh = std::max(eh, std::fabs(o.h[k] - full.h[k]) / hmax);
        CHECK(eb <= rtol);
        CHECK(eE <= rtol);
        CHECK(eq <= rtol);
        CHECK(eh <= rtol);
      }
    }
  }
}

// Both ends reach their turning points at the same load (Hertz, sigma = 0: a symmetric reload past
// the last maximum). Each end then sweeps its own Masing region, and past the maximum the state
// is the monotonic one, c = sqrt(1 - Q/fP) (the memory is erased). Found on a random walk
// (bench_history's seed 6), where the static solve failed.
TEST_CASE("static history: both ends return to their turning points at once (symmetric reload)") {
  const double path[][2] = {{0.1342428229208705, 0}, {0.0035192051702706839, 0}, {0.14902785051300274, 0}};
  static_history<double> h(hertz_pm());
  for (const auto &p : path) h.add_vertex(p[0], p[1]);
  const double c = std::sqrt(1 - path[2][0]);
  CHECK(std::fabs(h.b1() - c) <= 64 * eps<double>());
  CHECK(std::fabs(h.b2() - c) <= 64 * eps<double>());
  CHECK(h.dir1() == 1);
  CHECK(h.dir2() == 1);
  // the reload's energy: per zone, the Masing reload to the old maximum (the unloading's energy,
  // by symmetry of the 2f superposition) plus the monotonic energy from the maximum on
  const auto m1 = mono(path[0][0], 0), m2 = mono(path[2][0], 0);
  const double Eun = h.segment(1).E1, Ere = h.last_segment().E1;
  CHECK(std::fabs(h.last_segment().E2 - Ere) <= 1e-13);
  CHECK(std::fabs(Ere - (Eun + m2.energy(1) - m1.energy(1))) <= 1e-10 * m2.energy(1));
}

namespace {
// The static solves and the independent BEM (reference/bem_history.hpp) along a path: ends within
// 0.5 element widths of the BEM's cosine mesh (its accuracy, tests/test_bem_history.cpp), the same
// slip directions (where the zone is longer than an element), and the energy of every segment within
// 1e-3 of the path's largest (the BEM's energies are first order in its step: 5.6e-4 at N = 400).
void check_against_bem(const std::shared_ptr<const pressure_model<double>> &pm,
                       const std::vector<std::pair<double, double>> &path, int N = 400) {
  static_history<double> h(pm);
  std::vector<std::array<double, 6>> st;
  for (const auto &p : path) {
    h.add_vertex(p.first, p.second);
    st.push_back({h.b1(), h.b2(), double(h.dir1()), double(h.dir2()), h.last_segment().E1, h.last_segment().E2});
  }
  hs::reference::bem::options o;
  o.nodes = o.steps_per_unit = N;
  const auto r = hs::reference::bem::run([&](double x) { return pm->p(x); }, path, o);
  double Emax = 0;
  for (const auto &x : st) Emax = std::max({Emax, x[4], x[5]});
  for (size_t k = 0; k < path.size(); ++k) {
    CAPTURE(k);
    const double bb[2] = {r[k].b1, r[k].b2}, EB[2] = {r[k].energy1, r[k].energy2};
    const int db[2] = {r[k].dir1, r[k].dir2};
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      const double b = st[k][i];
      const double width = 3.141592653589793 / N * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (N * N);
      CHECK(std::fabs(b - bb[i]) <= 0.5 * width);
      if (1 - b > 2 * width) CHECK(int(st[k][2 + i]) == db[i]);
      CHECK(std::fabs(st[k][4 + i] - EB[i]) <= 1e-3 * Emax);
    }
  }
}
}  // namespace

// A reopened zone lands on a memory point behind which the traction is just short of the limit
// (bench_history's random walk, seed 3): the path folds, and on the way back to the fold's load the
// other end's root lies just OUTSIDE its value at the fold (it moved by 2.7e-3 a), where the
// crossing search looked only inwards and the segment failed. The jump lands on the monotonic
// state (sigma = 0, every memory erased): c = sqrt(1 - Q/fP) exactly; and the BEM agrees on the way.
TEST_CASE("static history: a fold whose path back runs outside the other end (against the BEM)") {
  const std::vector<std::pair<double, double>> path{{-0.128782535864683, 0.10198471274050987},
                                                    {-0.24238396206579382, 0.12277811047753615},
                                                    {-0.26126537997732058, 0},
                                                    {-0.39907615870282276, 0}};
  static_history<double> h(hertz_pm());
  for (const auto &p : path) h.add_vertex(p.first, p.second);
  CHECK(h.last_segment().jumps.size() == 1);
  const double c = std::sqrt(1 + path[3].first);
  CHECK(std::fabs(h.b1() - c) <= 1e-12);
  CHECK(std::fabs(h.b2() - c) <= 1e-12);
  // the fold inside the segment: cut the last segment into 10 vertices, each against the BEM
  std::vector<std::pair<double, double>> cut(path.begin(), path.end() - 1);
  for (int k = 1; k <= 10; ++k)
    cut.push_back({path[2].first + (path[3].first - path[2].first) * k / 10, 0.0});
  check_against_bem(hertz_pm(), cut);
}

// A patch merged with an edge zone by the vertex (bench_history's random walk, seed 8, vertex 3).
// Zone 2 slipped -1 to 0.9238 a (vertex 1), then +1 in a thin band to 0.9979 a (vertex 2); at vertex 3
// it slips -1 again from the edge, and the band (-0.9979, -0.9238), just short of the limit with
// that sign since vertex 1, slips as a patch that merges with the edge zone. The ends' own root at
// the vertex (b2 = 0.99803 a) leaves the stick traction 3e-5 p past the limit at x = -0.987 a, and
// the segment was refused (the march took the path and gave zone 2's energy as 3.43e-6, 20 % short
// of the BEM's 4.34e-6, 4.31e-6, 4.36e-6 at N = 400, 800, 1600, with an estimate of 1.2e-8). The
// state is the root further in, b2 = 0.9228 a: within the limit, both bands slipped one way.
TEST_CASE("static history: a patch merged with an edge zone by the vertex (against the BEM)") {
  const auto path = hs::reference::random_walk(3, 8);
  static_history<double> h(hertz_pm());
  for (const auto &p : path) h.add_vertex(p.first, p.second);
  CHECK(h.last_segment().jumps.size() == 1);  // slip and energy from the start and end states
  CHECK(h.dir2() == -1);
  CHECK(h.b2() < 0.93);
  check_against_bem(hertz_pm(), path, 800);
  hs::reference::bem::options o;
  o.nodes = o.steps_per_unit = 800;
  const auto pm = hertz_pm();
  const auto r = hs::reference::bem::run([&](double x) { return pm->p(x); }, path, o);
  // (the BEM's spread over N = 400 to 1600 is 1.2 % of this energy; the march's miss was 20 %)
  CHECK(std::fabs(h.last_segment().E2 - r[2].energy2) <= 0.03 * r[2].energy2);
}

// Random non-proportional walks of 100 vertices (bench_history's, |Q/fP| <= 0.5, sigma/fp0 in
// [0, 1.2]), which the static solves now take whole (before: 7 and 2 vertices; folds at which the
// other end moves out on the way back, symmetric returns), against the BEM, Hertz and the flat punch.
TEST_CASE("static history: random walks against the BEM (Hertz and flat punch)" * HS_LONG) {
  auto walk = [](unsigned seed, int n) { return hs::reference::random_walk(n, seed); };
  SUBCASE("Hertz, seed 1") { check_against_bem(hertz_pm(), walk(1, 100)); }
  // vertex 11 of seed 16: end 1 reopens at the edge and passes its old end at 0.9967 a, a crossing
  // the coarse scan stepped over; taken with zone 1's energy 3.2e-5 against the BEM's 8.2e-5 before
  // the finer search (same at N = 400, 800, 1600)
  SUBCASE("Hertz, seed 16, 12 vertices") { check_against_bem(hertz_pm(), walk(16, 12)); }
  SUBCASE("flat punch b_f/a = 0.5, seed 7") {
    check_against_bem(std::make_shared<flat_rounded_pressure<double>>(0.5), walk(7, 100));
  }
}

TEST_CASE("static history: copies share their segments; a long history is released without recursion") {
  // a copy (hs_history's snapshot at each vertex) must not copy the earlier segments: their memory
  // grew like the square of the vertex count when it did
  static_history<double> h(hertz_pm());
  h.add_vertex(0.0, 0.6);
  h.add_vertex(-0.3, 0.6);
  h.add_vertex(0.3, 0.6);
  static_history<double> c(h);
  REQUIRE(c.segment_count() == 3);
  for (size_t k = 0; k < 3; ++k) CHECK(&c.segment(k) == &h.segment(k));
  // the copy goes on alone: the original keeps its segments and its state
  const double b1 = h.b1(), b2 = h.b2(), slip = h.slip(0.95);
  c.add_vertex(-0.3, 0.6);
  CHECK(c.segment_count() == 4);
  CHECK(h.segment_count() == 3);
  CHECK(h.b1() == b1);
  CHECK(h.b2() == b2);
  CHECK(h.slip(0.95) == slip);
  CHECK(&c.segment(2) == &h.segment(2));
  CHECK(&c.last_segment() != &h.last_segment());
  CHECK(c.segment(1).dq == doctest::Approx(-0.3));
  // the slip sums the segments oldest first, as before (the copy at the same state agrees bitwise)
  static_history<double> d(h);
  CHECK(d.slip(0.95) == slip);
  CHECK_THROWS_AS(h.segment(3), error);
  // a history of 3e5 segments (zero-length vertices cost nothing to solve; about 80 MB) and a
  // copy of it: both are released node by node (a recursive release overflowed the 8 MB stack at
  // this length, in the Release build and under ASan)
  {
    static_history<double> g(hertz_pm());
    g.add_vertex(0.2, 0.1);
    for (int k = 0; k < 300000; ++k) g.add_vertex(0.2, 0.1);
    CHECK(g.segment_count() == 300001);
    static_history<double> gc(g);
    CHECK(&gc.segment(0) == &g.segment(0));
  }
}

TEST_CASE("static history: a sampled pressure's new traction by the treecode equals the direct sums") {
  // either side of static_history_accuracy::far_min (the treecode of the bands' fixed nodes,
  // fmm1d.hpp): a sampled pressure cuts the bands at every sample; direct sums cost the cube of
  // the sample count over a ramp (each end crosses every sample), the treecode about its square
  auto run = [](auto zero, int n, std::size_t far_min) {
    using R = decltype(zero);
    std::vector<R> xs, ps;
    for (int i = 0; i <= n; ++i) {
      const R x = i == n ? R(1) : R(-1) + R(2 * i) / R(n);
      xs.push_back(x);
      ps.push_back(i == 0 || i == n ? R(0) : std::sqrt((1 - x) * (1 + x)) * (1 + x / 5));
    }
    auto pm = std::make_shared<sampled_pressure<R>>(xs, ps, R(1));
    auto acc = static_history_accuracy<R>::for_rtol(R(1e-8));
    acc.far_min = far_min;
    static_history<R> h(pm, acc);
    std::vector<R> out;
    const R path[][2] = {{R(0.3), R(0.5)}, {R(0.1), R(0.2)}, {R(0.25), R(0.2)}};
    for (const auto &v : path) {
      h.add_vertex(v[0], v[1]);
      out.insert(out.end(), {h.b1(), h.b2(), h.last_segment().E1, h.last_segment().E2});
      for (const R x : {R(-0.95), R(-0.5), R(0.2), R(0.7), R(0.97)}) out.insert(out.end(), {h.traction(x), h.slip(x)});
    }
    return out;
  };
  for (int n : {300}) {
    const auto a = run(0.0, n, 0), b = run(0.0, n, std::size_t(-1));
    REQUIRE(a.size() == b.size());
    double scale = 0;
    for (double v : b) scale = std::max(scale, std::fabs(v));
    for (size_t k = 0; k < a.size(); ++k) {
      CAPTURE(k);
      // the treecode's sums agree with the direct ones to a few eps of sum |terms|; through the
      // ends' Newton and the panels' resolution (1e-10 at rtol 1e-8) they move the state by far
      // less than the accuracy asked
      CHECK(std::fabs(a[k] - b[k]) <= 1e-11 * scale);
    }
  }
  // long double: the treecode takes more terms (its epsilon)
  const auto al = run(0.0L, 120, 0), bl = run(0.0L, 120, std::size_t(-1));
  for (size_t k = 0; k < al.size(); ++k) CHECK(std::fabs(double(al[k] - bl[k])) <= 1e-11);
}

TEST_CASE("static history: slip at a sample after a fold (cuts within rounding merged)") {
  // a sampled Hertz pressure (201 samples); the last segment reverses both zones with a fold, so
  // its slip comes from its start and end states (sh_start). At x = 0.91, a sample lies at
  // 0.90999999999999992: the slip's pieces had one of an ulp, whose nodes fell on its ends, and
  // the slip was NaN at 0.9, 0.91, 0.92, 0.93 (not at 0.901, 0.905, 0.94)
  const int n = 200;
  std::vector<double> xs, ps;
  for (int i = 0; i <= n; ++i) {
    const double x = i == n ? 1.0 : -1.0 + 2.0 * i / n;
    xs.push_back(x);
    ps.push_back(i == 0 || i == n ? 0.0 : std::sqrt((1 - x) * (1 + x)));
  }
  static_history<double> h(std::make_shared<sampled_pressure<double>>(xs, ps, 1.0),
                           static_history_accuracy<double>::for_rtol(1e-8));
  const double path[][2] = {{0.3, 0.5}, {0.1, 0.2}, {0.25, 0.2}, {-0.2, 0.3}};
  for (const auto &v : path) h.add_vertex(v[0], v[1]);
  REQUIRE(h.last_segment().jumps.size() == 1);
  for (const double x : {0.9, 0.91, 0.92, 0.93, -1.0 + 2.0 * 183 / n, -1.0 + 2.0 * 195 / n}) {
    CAPTURE(x);
    const double v = h.slip(x);
    REQUIRE(std::isfinite(v));
    // continuous: against points 1e-9 either side (the slip's slope here is about 1)
    CHECK(std::fabs(v - (h.slip(x - 1e-9) + h.slip(x + 1e-9)) / 2) <= 1e-12);
    CHECK(v < 0);  // zone 1 slips back (direction -1) over the reversal
  }
}

namespace {
// the path of a periodic loading (Hertz frame: q = Q/fP, s = sigma/fp0), sigma first from zero
// (Qm = 0: one ramp vertex), then `cycles` cycles of 64 chords, as hs_history_add_cycles builds it
std::vector<std::pair<double, double>> chord_cycles(double qm, double qa, double sm, double sa, double phase_deg,
                                                    int cycles) {
  const double pi = 3.14159265358979323846, ph = phase_deg * pi / 180;
  std::vector<std::pair<double, double>> w{{0, sm + sa * std::sin(ph)}};
  if (qm != 0) w.push_back({qm, w.back().second});
  for (int c = 0; c < cycles; ++c)
    for (int k = 1; k <= 64; ++k) {
      const double t = 2 * pi * k / 64;
      w.push_back({qm + qa * std::sin(t), sm + sa * std::sin(t + ph)});
    }
  return w;
}
struct path_run {
  std::vector<std::array<double, 4>> v;  // b1, b2, E1, E2 at each vertex taken
  std::vector<double> snap;              // memory_snap() at each vertex
  double gap = 1;                        // the smallest distance between memory points (ends included)
  double largest = 0;                    // the largest zone energy of a segment
};
path_run run_path(const std::shared_ptr<const pressure_model<double>> &pm,
                  const std::vector<std::pair<double, double>> &w, double rtol) {
  static_history<double> h(
      pm, rtol > 0 ? static_history_accuracy<double>::for_rtol(rtol) : static_history_accuracy<double>());
  path_run r;
  for (const auto &p : w) {
    h.add_vertex(p.first, p.second);
    const auto &sg = h.last_segment();
    r.v.push_back({h.b1(), h.b2(), sg.E1, sg.E2});
    r.snap.push_back(h.memory_snap());
    r.largest = std::max({r.largest, std::fabs(sg.E1), std::fabs(sg.E2)});
    const auto m = h.memory_points();
    for (size_t i = 0; i + 1 < m.size(); ++i) r.gap = std::min(r.gap, m[i + 1] - m[i]);
  }
  return r;
}
}  // namespace

// A degenerate return: an end stops, at the same load, where an end stopped a cycle (or by
// symmetry half a cycle) before. The solves landed next to that memory point, not on it, and each
// return added a cusp beside the last (0.801690369705, 0.801690370983, 0.801690372260 a at vertices
// 38, 70, 102 of the first path below); the path was refused at vertex 134 at full accuracy and at
// 198 at rtol 1e-8, where vertex 134 had put 1.5e-6 of the path's largest energy more into zone 1
// than the full-accuracy solve (estimate 1e-8). An end within memory_snap (1e-8 a) short of a
// memory point is now put on it (static_history::return_to_memory), and one that the last crossing
// put on a memory point and the vertex's solve leaves within that distance short of it stays there.
TEST_CASE("static history: degenerate returns (a periodic path given vertex by vertex)") {
  {
    // Hertz (Qm, Qa, sigma_m, sigma_a, phase) = (0, 0.1, 0, 1, 45 deg), 4 cycles: 257 vertices
    const auto w = chord_cycles(0, 0.1, 0, 1, 45, 4);
    path_run full, r8;
    REQUIRE_NOTHROW(full = run_path(hertz_pm(), w, 0));
    REQUIRE_NOTHROW(r8 = run_path(hertz_pm(), w, 1e-8));
    REQUIRE(full.v.size() == w.size());
    REQUIRE(r8.v.size() == w.size());
    // no memory points piled up next to each other or to an end (the cusps of the path's first
    // ramp lie 5.3e-7 a apart)
    CHECK(full.gap > 1e-7);
    CHECK(r8.gap > 1e-7);
    int snaps = 0;
    double dend = 0, den = 0, smax = 0;  // (printed with -s)
    for (size_t i = 0; i < w.size(); ++i) {
      CAPTURE(i);
      snaps += full.snap[i] > 0;
      smax = std::max(smax, full.snap[i]);
      for (int k = 0; k < 2; ++k) dend = std::max(dend, std::fabs(r8.v[i][k] - full.v[i][k]));
      for (int k = 2; k < 4; ++k) den = std::max(den, std::fabs(r8.v[i][k] - full.v[i][k]) / full.largest);
      // rtol 1e-8 against full accuracy: ends within 1e-8 a and both moves, energies within 1e-8 of
      // the largest (measured 1.9e-10 a and 2.1e-10)
      for (int k = 0; k < 2; ++k) CHECK(std::fabs(r8.v[i][k] - full.v[i][k]) <= 1e-8 + full.snap[i] + r8.snap[i]);
      for (int k = 2; k < 4; ++k) CHECK(std::fabs(r8.v[i][k] - full.v[i][k]) <= 1e-8 * full.largest);
    }
    CHECK(snaps >= 3);  // (the returns at vertices 70, 102, ...: 1.28e-9 to 2.56e-9 a)
    MESSAGE("rtol 1e-8 against full accuracy: ends ", dend, " a, energies ", den, " of the largest; ", snaps,
            " returns put on their memory points, the largest move ", smax, " a");
    // the steady cycle: the fourth cycle's vertices repeat the third's (the state is periodic)
    for (size_t i = 1 + 64 * 3; i < w.size(); ++i)
      for (int k = 0; k < 4; ++k)
        CHECK(std::fabs(full.v[i][k] - full.v[i - 64][k]) <= 1e-8 * (k < 2 ? 1 : full.largest));
  }
  {
    // From the other side: Hertz (0, 0.3, 0, 0.3, 45 deg), 3 cycles at rtol 1e-8: at vertex 174 the
    // crossing puts end 2 on its memory point at lambda = 1 - 6e-10 (then sweeps a region at the
    // limit) and the vertex's solve left it 1e-12 short: "a stick-zone end recedes" before. The
    // energies agree with full accuracy from there on within the accuracy asked, 1e-8 of the
    // largest (measured 1.4e-12); the ends within the region at the limit (q = d p over 2.6e-5 a,
    // neither slipping nor resisting: the stick end is not unique there) are not compared.
    const auto w = chord_cycles(0, 0.3, 0, 0.3, 45, 3);
    path_run full, r8;
    REQUIRE_NOTHROW(full = run_path(hertz_pm(), w, 0));
    REQUIRE_NOTHROW(r8 = run_path(hertz_pm(), w, 1e-8));
    REQUIRE(r8.v.size() == w.size());
    CHECK(r8.snap[174] > 0);  // (the end kept on the point, the distance in the estimate)
    CHECK(r8.snap[174] <= 1e-8);
    for (size_t i = 170; i < w.size(); ++i)
      for (int k = 2; k < 4; ++k) CHECK(std::fabs(r8.v[i][k] - full.v[i][k]) <= 1e-8 * full.largest);
  }
}

// The accuracy asked, on periodic loadings given as 64-chord paths (bench/static_periodic_paths.cpp,
// whose case numbers these are): each against the full-accuracy solve, ends within rtol a and
// segment energies within rtol of the path's largest. Each part failed before session 23:
// - the full-accuracy solve itself: the stick traction's panels stopped subdividing at a cap of 400,
//   wherever the cap fell, because next to an edge (p small) the tolerance lay below the traction's
//   rounding and the panels there split down to 1e-6 a. Hertz case 67 (0, 0.3, 0.5, 0.3, 180 deg),
//   vertex 18: the panel (-0.787, 0.879) was left as one, its traction 6.8e-5 off; by vertex 35 the
//   ends were 1.1e-6 a off and the energies 6.2e-6 of the largest, where rtol 1e-8 was right;
// - rtol 1e-8, orders reduced below the full ones: flat punch case 28 (0.15, 0.1, 0, 0.3, 0),
//   vertex 81 (a fold at the turn; the band's graded intervals at 12), 2.9e-7; flat case 150
//   (0.15, 0.6, 0.5, 1, 45 deg), vertex 8 (lambda at 12), 8.5e-8;
// - rtol 1e-8, panels resolved only to 1e-10: Hertz case 2 (0, 0.1, 0, 0.3, 45 deg), vertex 107,
//   5.2e-8;
// - the zone rates' quadrature, not graded at the flat punch's corners: flat case 158
//   (0.15, 0.6, 1.5, 1, 0) 1.2e-6 at rtol 1e-8 (order 16), flat case 77 (0, 0.3, 1.5, 1, 0) 1.03e-6
//   at rtol 1e-6 (order 12).
TEST_CASE("static history: 64-chord periodic paths at rtol 1e-8 and 1e-6 against full accuracy") {
  struct pcase {
    int geometry;  // 0 Hertz, 1 flat punch b_f/a = 0.5
    double qm, qa, sm, sa, phase;
    size_t vertices;  // the first this many
    double rtol;
  };
  const pcase cases[] = {{0, 0, 0.3, 0.5, 0.3, 180, 49, 1e-8}, {1, 0.15, 0.1, 0, 0.3, 0, 83, 1e-8},
                         {1, 0.15, 0.6, 0.5, 1, 45, 12, 1e-8}, {0, 0, 0.1, 0, 0.3, 45, 109, 1e-8},
                         {1, 0.15, 0.6, 1.5, 1, 0, 16, 1e-8},  {1, 0, 0.3, 1.5, 1, 0, 13, 1e-6}};
  for (const auto &c : cases) {
    CAPTURE(c.geometry);
    CAPTURE(c.qm);
    CAPTURE(c.qa);
    CAPTURE(c.sm);
    CAPTURE(c.sa);
    CAPTURE(c.phase);
    CAPTURE(c.rtol);
    auto w = chord_cycles(c.qm, c.qa, c.sm, c.sa, c.phase, 2);
    w.resize(c.vertices);
    std::shared_ptr<const pressure_model<double>> pm = hertz_pm();
    if (c.geometry == 1) pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
    path_run full, r;
    REQUIRE_NOTHROW(full = run_path(pm, w, 0));
    REQUIRE_NOTHROW(r = run_path(pm, w, c.rtol));
    double dend = 0, den = 0;
    for (size_t i = 0; i < w.size(); ++i) {
      CAPTURE(i);
      for (int k = 0; k < 2; ++k) {
        CHECK(std::fabs(r.v[i][k] - full.v[i][k]) <= c.rtol + full.snap[i] + r.snap[i]);
        dend = std::max(dend, std::fabs(r.v[i][k] - full.v[i][k]));
      }
      for (int k = 2; k < 4; ++k) {
        CHECK(std::fabs(r.v[i][k] - full.v[i][k]) <= c.rtol * full.largest);
        den = std::max(den, std::fabs(r.v[i][k] - full.v[i][k]) / full.largest);
      }
    }
    MESSAGE("ends ", dend, " a, energies ", den, " of the largest");
  }
}

// hist_zone_rate (the energy rate of a slip zone) across the flat punch's corner against tanh-sinh in
// long double on the two sides of the corner (an independent quadrature of the same integral): the
// panels graded polynomially towards the corner, in geometric layers, reach rounding by order 20;
// ungraded, the (x - k) ln|x - k| term converged like n^-4 (9.6e-7 relative at 16, 6.4e-8 at 32).
TEST_CASE("static history: zone energy rates across a flat punch corner (graded) against tanh-sinh") {
  using L = long double;
  const flat_rounded_pressure<double> pm(0.5);
  const flat_rounded_pressure<L> pml(0.5);
  boost::math::quadrature::tanh_sinh<L> ts;
  struct zc {
    int z;
    double c, e, A, B;
  };
  // (the last three: a stick-end grading cut at the corner, the corner at the stick end to rounding,
  // and beyond a stick end by 1e-4 a)
  for (const zc &k : {zc{+1, -0.1, 0.3, 0.3, 0.2}, zc{+1, 0.1, 0.35, -0.2, 0.5}, zc{-1, 0.2, 0.6, 0.4, -0.3},
                      zc{+1, -0.6, 0.05, 0.3, 0.1}, zc{+1, -0.7, 0.2, 0.3, 0.1}, zc{-1, 0.5999, 0.1, 0.2, 0.4}}) {
    CAPTURE(k.z);
    CAPTURE(k.c);
    CAPTURE(k.e);
    const double lo = k.z > 0 ? k.c + k.e : -1, hi = k.z > 0 ? 1 : k.c - k.e;
    auto f = [&](L x) { return pml.p(x) * hist_hdot<L>(k.z, k.A, k.B, k.c, k.e, x); };
    L ref = 0, a = lo;
    for (L bp : {L(-0.5), L(0.5), L(hi)}) {
      if (!(bp > a) || bp > L(hi)) continue;
      ref += ts.integrate(f, a, bp);
      a = bp;
    }
    for (int n : {20, 24, 32}) {
      CAPTURE(n);
      const double v = hist_zone_rate(pm, n, k.z, k.A, k.B, k.c, k.e, lo, hi);
      CHECK(std::fabs(v - double(ref)) <= 64 * std::numeric_limits<double>::epsilon() * std::fabs(double(ref)));
    }
  }
}

// The panel cap counts the panels beyond one a cusp interval: a sampled pressure has a breakpoint at
// every sample, so 1000 samples give ~1000 intervals before any split (a first version of session
// 23's cap refused this path at its second vertex, and hs_history marched it). Samples of the Hertz
// pressure: phi = p / sqrt(1 - x^2) is the constant 1, which the samples' interpolant reproduces, so
// the sampled and the Hertz histories agree to rounding (measured 2.2e-16 a and 1.4e-15 of the energy).
TEST_CASE("static history: 1000 Hertz samples (more panels than the cap, one a sample) as Hertz") {
  const int n = 1000;
  std::vector<double> xs, ps;
  for (int i = 0; i <= n; ++i) {
    const double x = -1 + 2.0 * i / n;
    xs.push_back(x);
    ps.push_back(std::sqrt(std::max(0.0, 1 - x * x)));
  }
  const auto acc = static_history_accuracy<double>::for_rtol(1e-8);
  static_history<double> h(std::make_shared<sampled_pressure<double>>(xs, ps, 1.0), acc);
  static_history<double> g(hertz_pm(), acc);
  for (const auto &v : {std::pair<double, double>{0.3, 0.5}, {0.1, 0.2}}) {
    CAPTURE(v.first);
    REQUIRE_NOTHROW(h.add_vertex(v.first, v.second));
    g.add_vertex(v.first, v.second);
    CHECK(h.panel_count() > 400);  // (static_history::max_panels)
    CHECK(std::fabs(h.b1() - g.b1()) <= 1e-12);
    CHECK(std::fabs(h.b2() - g.b2()) <= 1e-12);
    CHECK(std::fabs(h.last_segment().E1 - g.last_segment().E1) <= 1e-12 * g.last_segment().E2);
    CHECK(std::fabs(h.last_segment().E2 - g.last_segment().E2) <= 1e-12 * g.last_segment().E2);
  }
}
