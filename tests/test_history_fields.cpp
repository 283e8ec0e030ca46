// Issue 15: stresses of load-history states (hs_history_state,
// core/history_fields.hpp; docs/fields.md, docs/history.md).
#include <doctest/doctest.h>
#include <halfslip/halfslip.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "halfslip/core/history_fields.hpp"
#include "halfslip/core/numerics.hpp"
#include "testing.hpp"

using namespace hs::core;

namespace {

struct handle {
  hs_solution *s = nullptr;
  ~handle() { hs_solution_free(s); }
};
struct hist_handle {
  hs_history *h = nullptr;
  ~hist_handle() { hs_history_free(h); }
};

// stresses of a handle at points, body 1 for y >= 0
std::vector<double> stresses(const hs_solution *s, const std::vector<double> &x, const std::vector<double> &y) {
  std::vector<double> out(3 * x.size());
  REQUIRE(hs_eval_stress(s, 1, 0.0, x.size(), x.data(), y.data(), out.data()) == HS_OK);
  return out;
}

// A canonical history (a = p0 = f = E* = 1) marched at rtol 1e-8.
std::shared_ptr<const history<double>> march(int which) {
  auto pm = std::make_shared<hertz_pressure<double>>();
  history_options<double> ho;
  ho.max_step = 1.0 / 32;
  ho.merge_interior_patches = true;  // the out-of-phase cycles open interior patches
  refined_history<double> rh(pm, ho, 1e-8);
  if (which == 0) {  // unloading (Ciavarella-Jager)
    rh.add_vertex(0.6, 0);
    rh.add_vertex(0.2, 0);
  } else if (which == 1) {  // sigma, then Q back and forth (locked-in slip of both signs)
    for (auto v : {std::pair<double, double>{0, 0.8}, {0.5, 0.8}, {-0.3, 0.8}, {0.4, 0.8}, {0.1, 0.8}})
      rh.add_vertex(v.first, v.second);
  } else {  // Q and sigma 90 degrees out of phase (chords: many runs)
    rh.add_cycles(0.0, 0.4, 0.3, 0.4, 90.0, 2, ramp_order::sigma_first, 32, 1e-6);
  }
  return rh.fine().prefix(rh.fine().step_count());
}

}  // namespace

TEST_CASE("history state: unloading 0.6 -> 0.2 against Ciavarella-Jager, S(0.6) - 2 S(0.2) + 2 S(0)") {
  // Hertz, sigma = 0. The state's traction is q(0.6) - 2 q(0.2) (the monotonic
  // solution at 0.4 with friction 2f is twice that at 0.2 with f), the pressure
  // is the same, and the stresses are linear in the tractions: the state's
  // stresses are S(0.6) - 2 S(0.2) + 2 S(0), S(Q) those of monotonic solutions
  // (closed forms, McEwen's fields; S(0) the pressure alone). Units not 1.
  hs_scene sc;
  REQUIRE(hs_scene_default(&sc) == HS_OK);
  sc.a = 1.3;
  sc.p0 = 2.0;
  sc.f = 0.6;
  sc.E_star = 3.0;
  sc.sigma_over_fp0 = 0;
  hist_handle h;
  REQUIRE(hs_history_new(&sc, nullptr, nullptr, &h.h) == HS_OK);
  const double Q[2] = {0.6, 0.2}, S[2] = {0, 0};
  REQUIRE(hs_history_add_vertices(h.h, 2, Q, S) == HS_OK);
  handle st, s6, s2, s0;
  REQUIRE(hs_history_state(h.h, 1, &st.s) == HS_OK);
  hs_history_free(h.h);  // the state owns what it needs
  h.h = nullptr;
  sc.Q_over_fP = 0.6;
  REQUIRE(hs_solve(&sc, nullptr, &s6.s) == HS_OK);
  sc.Q_over_fP = 0.2;
  REQUIRE(hs_solve(&sc, nullptr, &s2.s) == HS_OK);
  sc.Q_over_fP = 0.0;
  REQUIRE(hs_solve(&sc, nullptr, &s0.s) == HS_OK);
  const double a = sc.a, fp0 = sc.f * sc.p0;
  hs_summary sm, m6;
  sm.struct_size = m6.struct_size = sizeof(hs_summary);
  REQUIRE(hs_solution_summary(st.s, &sm) == HS_OK);
  REQUIRE(hs_solution_summary(s6.s, &m6) == HS_OK);
  // unloading: both new zones slip negative, stick zone |x| < a sqrt(1 - 0.4/2)
  CHECK(sm.regime == HS_REGIME_SAME_SIGN);
  CHECK(sm.slip_dir1 == -1);
  CHECK(sm.slip_dir2 == -1);
  const double c_now = a * std::sqrt(0.8), c_old = a * std::sqrt(0.4);
  // the march's end positions: errors d (rtol 1e-8 in units of a, docs/history.md: 1e-8 a)
  const double d = std::max(std::fabs(sm.b1 - c_now), std::fabs(sm.b2 - c_now));
  CHECK(d < 2e-8 * a);
  // q near a sqrt point displaced by d is off by ~ f p0 d/sqrt(r a) at distance r:
  // tolerance 4 f p0 (d + 1e-8 a)/sqrt(a max(r, y)) (the memory point c_old is the
  // loading's end, marched to the same rtol), plus 2e-7 f p0 elsewhere: the
  // march's traction error is 3e-8 f p0 (docs/history.md), and the Flamant
  // stresses of a smooth error are a few times the error itself.
  std::vector<double> xs, ys;
  for (double u :
       {-1.5, -1.0, -0.9999, -0.99,    -0.95, -0.8944, -0.894427, -0.8, -0.6325, -0.632456, -0.6, -0.3, 0.0,
        0.2,  0.5,  0.6324,  0.632456, 0.7,   0.8944,  0.894427,  0.9,  0.97,    0.99999,   1.0,  1.2,  3.0})
    for (double v : {0.0, 1e-6, 1e-3, 0.05, 0.5}) {
      xs.push_back(u * a);
      ys.push_back(v * a);
    }
  const auto e = stresses(st.s, xs, ys), r6 = stresses(s6.s, xs, ys), r2 = stresses(s2.s, xs, ys),
             r0 = stresses(s0.s, xs, ys);
  double worst = 0, worst_ratio = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    double r = 1e300;
    for (double c : {c_now, c_old}) r = std::min({r, std::fabs(xs[i] - c), std::fabs(xs[i] + c)});
    const double tol = 2e-7 * fp0 + 4 * fp0 * (d + 1e-8 * a) / std::sqrt(a * std::max(r, ys[i]));
    for (int k = 0; k < 3; ++k) {
      const double ref = r6[3 * i + k] - 2 * r2[3 * i + k] + 2 * r0[3 * i + k];
      const double err = std::fabs(e[3 * i + k] - ref);
      CAPTURE(xs[i] / a);
      CAPTURE(ys[i] / a);
      CAPTURE(k);
      CHECK(err <= tol);
      worst = std::max(worst, err / fp0);
      worst_ratio = std::max(worst_ratio, err / tol);
    }
  }
  MESSAGE("Ciavarella-Jager: max |stress - closed form| = " << worst << " f p0 (worst error/tolerance " << worst_ratio
                                                            << "), end error " << d / a << " a");
  // the surface stress of both bodies, on and off the contact, through hs_eval_surface_stress
  for (int body : {1, 2}) {
    std::vector<double> x;
    for (double u : {-2.0, -1.0, -0.97, -0.7, -0.1, 0.3, 0.75, 0.98, 1.0, 1.4}) x.push_back(u * a);
    std::vector<double> v(x.size()), v6(x.size()), v2(x.size()), v0(x.size());
    REQUIRE(hs_eval_surface_stress(st.s, body, 0.0, x.size(), x.data(), v.data()) == HS_OK);
    REQUIRE(hs_eval_surface_stress(s6.s, body, 0.0, x.size(), x.data(), v6.data()) == HS_OK);
    REQUIRE(hs_eval_surface_stress(s2.s, body, 0.0, x.size(), x.data(), v2.data()) == HS_OK);
    REQUIRE(hs_eval_surface_stress(s0.s, body, 0.0, x.size(), x.data(), v0.data()) == HS_OK);
    for (size_t i = 0; i < x.size(); ++i) {
      CAPTURE(body);
      CAPTURE(x[i] / a);
      CHECK(std::fabs(v[i] - (v6[i] - 2 * v2[i] + 2 * v0[i])) <
            2e-7 * fp0);  // no point within 0.05 a of a sqrt point
    }
  }
  // traction, pressure and accumulated slip of the state: h = h(0.6) - 2 h(0.2)
  // (the slip of the 2f solution at 0.4 is twice that of f at 0.2); 3e-8 of the scales
  std::vector<double> x{-0.99 * a, -0.9 * a, -0.7 * a, 0.0, 0.5 * a, 0.75 * a, 0.95 * a};
  std::vector<double> q(x.size()), q6(x.size()), q2(x.size()), hs(x.size()), h6(x.size()), h2(x.size()), p(x.size()),
      p6(x.size());
  REQUIRE(hs_eval_traction(st.s, x.size(), x.data(), q.data()) == HS_OK);
  REQUIRE(hs_eval_traction(s6.s, x.size(), x.data(), q6.data()) == HS_OK);
  REQUIRE(hs_eval_traction(s2.s, x.size(), x.data(), q2.data()) == HS_OK);
  REQUIRE(hs_eval_slip(st.s, x.size(), x.data(), hs.data()) == HS_OK);
  REQUIRE(hs_eval_slip(s6.s, x.size(), x.data(), h6.data()) == HS_OK);
  REQUIRE(hs_eval_slip(s2.s, x.size(), x.data(), h2.data()) == HS_OK);
  REQUIRE(hs_eval_pressure(st.s, x.size(), x.data(), p.data()) == HS_OK);
  REQUIRE(hs_eval_pressure(s6.s, x.size(), x.data(), p6.data()) == HS_OK);
  const double hscale = fp0 * a / sc.E_star;
  for (size_t i = 0; i < x.size(); ++i) {
    CAPTURE(x[i] / a);
    CHECK(std::fabs(q[i] - (q6[i] - 2 * q2[i])) < 1e-7 * fp0);
    CHECK(std::fabs(hs[i] - (h6[i] - 2 * h2[i])) < 1e-7 * hscale);
    CHECK(std::fabs(p[i] - p6[i]) <= 8 * hs_test::eps<double>() * sc.p0);  // the same formula, other rounding
  }
}

TEST_CASE("history state: cached panels = quadrature from scratch split at every step end" * HS_LONG) {
  // The panels are cut at the memory points only (history::memory_points);
  // the quadrature from scratch (cauchy_numeric, graded panels built around
  // each point, q evaluated afresh at every node) splits at the ends of every
  // step, so a memory point the panels missed would show as a difference far
  // above their 1e-14 rule error. Target 1e-10 f p0 (issue 15): measured
  // 8e-14 (unloading, sigma then Q) and 4e-11 (out of phase, 32 chords per
  // cycle, where the ends' cubic interpolation in time leaves kinks at the
  // knots at the march's error level).
  for (int which : {0, 1, 2}) {
    const auto h = march(which);
    const size_t ns = h->step_count();
    auto st = history_contact_state<double>(h, ns, 1.0, 1.0, 1.0);
    st.panels = make_panels(st);
    std::vector<double> pts{-1.0, 1.0};
    for (const auto &s : h->steps())
      for (double v : {s.b1a, s.b1b(), -s.b2a, -s.b2b()})
        if (v > -1 && v < 1) pts.push_back(v);
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    auto dens = [&](double s, double &p, double &q) {
      p = st.p(s);
      q = st.q(s);
    };
    double worst = 0;
    for (double x : {-1.3, -0.97, -0.7, -0.2, 0.55, 0.8, 0.99, 1.2})
      for (double y : {0.0, 1e-3, 0.05, 0.5}) {
        if (y == 0 && std::fabs(x) < 1) continue;
        cauchy_pair<double> P, Q, P2, Q2;
        cauchy_numeric<double>(dens, pts, {x, y}, P, Q);
        st.panels->cauchy({x, y}, P2, Q2);
        // the stresses are (F0 + y F1)/pi of p and q
        const double e = std::max({std::abs(P.F0 - P2.F0), std::abs(Q.F0 - Q2.F0), y * std::abs(P.F1 - P2.F1),
                                   y * std::abs(Q.F1 - Q2.F1)}) /
                         M_PI;
        CAPTURE(which);
        CAPTURE(x);
        CAPTURE(y);
        CHECK(e < 1e-10);
        worst = std::max(worst, e);
      }
    // the principal value on the contact (surface sigma_xx) against tanh-sinh
    // on the pieces split at every step end and at x, by subtraction of q(x)
    if (which < 2) {
      for (double x : {-0.95, -0.5, 0.0, 0.3, 0.75}) {
        const double qx = st.q(x);
        std::vector<double> cuts(pts.begin() + 1, pts.end() - 1);
        cuts.push_back(x);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        const double pv = integrate_pieces<double>(
                              [&](double t, double) { return t == x ? 0.0 : (st.q(t) - qx) / (t - x); }, -1.0, 1.0,
                              cuts, 1e-13) +
                          qx * std::log((1 - x) / (1 + x));
        CAPTURE(which);
        CAPTURE(x);
        CHECK(std::fabs(st.panels->re_f0_q(x) - pv) / M_PI < 1e-10);
        worst = std::max(worst, std::fabs(st.panels->re_f0_q(x) - pv) / M_PI);
        // and through surface_sxx (body 2 - body 1 = -(4/pi) PV int q/(t - x) + bulk2 - bulk1)
        const double d21 = surface_sxx(st, 2, x) - surface_sxx(st, 1, x);
        CHECK(std::fabs(d21 - (-4 * pv / M_PI - st.bulk1)) < 4e-10);
      }
    }
    // At a breakpoint (memory point, stick end) the principal value comes from
    // re_f0_q_break. Quadrature from scratch cannot check it: q ~ qx + c sqrt|t - x|
    // on one side, and q cannot be evaluated closer to x than eps |x|, which leaves
    // O(c sqrt(eps)) = 1e-8 out (measured 1.3e-8). The principal value is continuous
    // at x and smooth on the side where q is: it must agree with re_f0_q (checked
    // above) at x -+ 1e-12 on that side to ~ 1e-12 of its derivative.
    // (Not for the out-of-phase history: there an end turned at some memory points,
    // which makes q non-smooth on both sides.)
    for (double m : which < 2 ? h->memory_points(ns) : std::vector<double>{}) {
      const double br = st.panels->re_f0_q_break(m, st.q(m));
      const double dl = std::fabs(st.panels->re_f0_q(m - 1e-12) - br);
      const double dr = std::fabs(st.panels->re_f0_q(m + 1e-12) - br);
      CAPTURE(which);
      CAPTURE(m);
      CHECK(std::min(dl, dr) < 1e-10);
      CHECK(std::max(dl, dr) > 1e-8);  // the sqrt side: the check above sees the breakpoint
      const double d21 = surface_sxx(st, 2, m) - surface_sxx(st, 1, m);
      CHECK(std::fabs(d21 - (-4 * br / M_PI - st.bulk1)) <= 64 * hs_test::eps<double>());
    }
    MESSAGE("history " << which << ": " << ns << " steps, " << st.panels->size() << " panel nodes, "
                       << st.breaks.size() << " breakpoints; max |panels - scratch| = " << worst << " f p0");
  }
}

TEST_CASE("history state: equilibrium on y = a/2 and both bodies on the stick zone (sigma, then Q cycling)") {
  // Physical units through the C ABI: a, p0, f, E* not 1.
  hs_scene sc;
  REQUIRE(hs_scene_default(&sc) == HS_OK);
  sc.a = 0.7;
  sc.p0 = 1.7;
  sc.f = 0.4;
  sc.E_star = 2.5;
  hist_handle h;
  REQUIRE(hs_history_new(&sc, nullptr, nullptr, &h.h) == HS_OK);
  // sigma first (zones of opposite directions), then Q up, down and up again:
  // locked-in slip of both directions, 7 memory points
  const double Qv[4] = {0, 0.3, 0.1, 0.25}, Sv[4] = {0.6, 0.6, 0.6, 0.6};
  REQUIRE(hs_history_add_vertices(h.h, 4, Qv, Sv) == HS_OK);
  // every segment advances: the states are static solves (issue 14), so the equilibrium
  // below holds to the quadrature's 1e-8 (error_estimate 0)
  int method = 0;
  REQUIRE(hs_history_method(h.h, &method) == HS_OK);
  CHECK(method == HS_HISTORY_STATIC);
  handle st;
  REQUIRE(hs_history_state(h.h, 3, &st.s) == HS_OK);
  hs_history_vertex vx;
  vx.struct_size = sizeof vx;
  REQUIRE(hs_history_vertex_get(h.h, 3, &vx) == HS_OK);
  const double a = sc.a, P = M_PI * a * sc.p0 / 2, fp0 = sc.f * sc.p0, Qnow = 0.25 * sc.f * P;
  // (the march of an other sigma-then-Q path, {0.8: 0.5, -0.3, ...}, is erratic: error estimate 4e-4, and
  // int q - Q = 8e-5 f P; this one has 1.2e-7)
  REQUIRE(vx.error_estimate < 1e-6);
  for (int body : {1, 2}) {
    const double y = (body == 1 ? 0.5 : -0.5) * a;
    auto integ = [&](int comp) {
      return integrate_ts<double>(
          [&](double th, double) {
            const double x = std::fabs(y) * std::tan(th), j = std::fabs(y) / (std::cos(th) * std::cos(th));
            double s[3];
            REQUIRE(hs_eval_stress(st.s, body, 0.0, 1, &x, &y, s) == HS_OK);
            return s[comp] * j;
          },
          -M_PI / 2, M_PI / 2, 1e-10);
    };
    const double ryy = integ(1) + P;
    // body 2 carries -q, and its sigma_xy = -tau_xz: int sigma_xy = -Q in both
    const double rxy = integ(2) + Qnow;
    MESSAGE("body " << body << ": int syy + P = " << ryy / P << " P, int sxy + Q = " << rxy / P << " P");
    CAPTURE(body);
    // sigma_yy: the pressure alone, quadrature tolerance 1e-10 (1e-8 as for monotonic solutions);
    // sigma_xy: int q = Q holds to the march's accuracy, which its error estimate bounds
    // (zone ends in units of a and energies: an error d of the ends moves int q by ~ d f P)
    CHECK(std::fabs(ryy) < 1e-8 * P);
    CHECK(std::fabs(rxy) < (2 * vx.error_estimate + 1e-8) * sc.f * P);
  }
  // surface sigma_xx: body 2 - body 1 = 2 E* dh/dx (the relative strain; docs/conventions.md). On the
  // stick zone that is zero where the point has never slipped, and 2 E* times the locked-in slip gradient
  // elsewhere: the two bodies do NOT have equal sigma_xx where slip is locked in. h from hs_eval_slip
  // (the march's slip rates, not the stresses), dh/dx by a central difference with step 1e-3 a.
  hs_summary sm;
  sm.struct_size = sizeof sm;
  REQUIRE(hs_solution_summary(st.s, &sm) == HS_OK);
  int locked = 0, virgin = 0;
  for (int i = 1; i < 40; ++i) {
    const double x = -sm.b2 + (sm.b1 + sm.b2) * i / 40.0;
    const double dx = 1e-3 * a;
    const double xp[3] = {x - dx, x, x + dx};
    double hv[3], s1[3], s2[3];
    REQUIRE(hs_eval_slip(st.s, 3, xp, hv) == HS_OK);
    REQUIRE(hs_eval_surface_stress(st.s, 1, 0.0, 1, &x, s1) == HS_OK);
    REQUIRE(hs_eval_surface_stress(st.s, 2, 0.0, 1, &x, s2) == HS_OK);
    const double dh = (hv[2] - hv[0]) / (2 * dx);
    if (hv[0] == 0 && hv[1] == 0 && hv[2] == 0) {
      ++virgin;
      // never slipped: equal in both bodies, to the march's accuracy (its stuck-interval rates are
      // integrated in time by Gauss-Legendre: measured 7e-8 f p0, rtol 1e-8)
      CHECK(std::fabs(s2[0] - s1[0]) < 2e-7 * fp0);
    } else {
      ++locked;
      CAPTURE(x / a);
      // not a rounding bound: the march's slip is a sum of per-step slips with kinks at the steps' knots
      // (a central difference at 1e-4 a varies by 5e-4 of h'), and near a memory point h ~ r^(3/2), whose
      // truncation error h''' dx^2/6 reaches 4e-4 of h' at r = 0.01 a (measured)
      CHECK(std::fabs((s2[0] - s1[0]) - 2 * sc.E_star * dh) < 1e-3 * std::fabs(2 * sc.E_star * dh) + 1e-6 * fp0);
    }
  }
  CHECK(locked > 5);
  CHECK(virgin > 5);
  MESSAGE("stick zone: " << locked << " points with locked-in slip, " << virgin << " never slipped");
}

TEST_CASE("history state: contract (bad input, functions that do not apply, lifetime)") {
  hs_scene sc;
  REQUIRE(hs_scene_default(&sc) == HS_OK);
  hist_handle h;
  REQUIRE(hs_history_new(&sc, nullptr, nullptr, &h.h) == HS_OK);
  hs_solution *out = reinterpret_cast<hs_solution *>(&sc);  // must stay untouched on error
  hs_solution *const sentinel = out;
  CHECK(hs_history_state(h.h, 0, &out) == HS_ERR_BAD_OPTION);  // no vertex yet
  CHECK(out == sentinel);
  const double Q[2] = {0.5, 0.1}, S[2] = {0.3, 0.3};
  REQUIRE(hs_history_add_vertices(h.h, 2, Q, S) == HS_OK);
  CHECK(hs_history_state(h.h, 2, &out) == HS_ERR_BAD_OPTION);
  CHECK(hs_history_state(h.h, size_t(-1), &out) == HS_ERR_BAD_OPTION);
  CHECK(hs_history_state(nullptr, 0, &out) == HS_ERR_NULL_POINTER);
  CHECK(hs_history_state(h.h, 0, nullptr) == HS_ERR_NULL_POINTER);
  CHECK(out == sentinel);
  handle st;
  REQUIRE(hs_history_state(h.h, 1, &st.s) == HS_OK);
  // monotonic-loading quantities do not apply
  double e[2] = {7, 7}, v = 7, x = 0.5;
  CHECK(hs_solution_energy(st.s, e) == HS_ERR_NOT_APPLICABLE);
  CHECK(hs_eval_Bx(st.s, 1, &x, &v) == HS_ERR_NOT_APPLICABLE);
  CHECK(hs_eval_work(st.s, 1, &x, &v) == HS_ERR_NOT_APPLICABLE);
  CHECK((e[0] == 7 && v == 7));
  int rec = 0;
  hs_steady_cycle cyc;
  cyc.struct_size = sizeof cyc;
  CHECK(hs_solution_ramp(st.s, &rec, &v) == HS_ERR_NOT_APPLICABLE);
  CHECK(hs_solution_steady_cycle(st.s, &cyc) == HS_ERR_NOT_APPLICABLE);
  // the evaluators check their input as for any solution
  const double xo = 1.5, yo = -0.1, nan = std::nan("");
  CHECK(hs_eval_traction(st.s, 1, &xo, &v) == HS_ERR_POINT_OUTSIDE);
  CHECK(hs_eval_stress(st.s, 1, 0.0, 1, &xo, &yo, e) == HS_ERR_BAD_OPTION);
  CHECK(hs_eval_surface_stress(st.s, 3, 0.0, 1, &x, &v) == HS_ERR_BAD_OPTION);
  CHECK(hs_eval_surface_stress(st.s, 1, nan, 1, &x, &v) == HS_ERR_NOT_FINITE);
  // the traction equals hs_history_eval's, and the state outlives a growing and a freed history
  double q0 = 0, q1 = 0, s0[3], s1[3];
  const double px = 0.3, py = 0.2;
  REQUIRE(hs_history_eval(h.h, 1, HS_FIELD_TRACTION, 1, &px, &q1) == HS_OK);
  REQUIRE(hs_eval_traction(st.s, 1, &px, &q0) == HS_OK);
  CHECK(q0 == q1);
  REQUIRE(hs_eval_stress(st.s, 1, 0.0, 1, &px, &py, s0) == HS_OK);
  const double Q2[1] = {-0.4}, S2[1] = {0.0};
  REQUIRE(hs_history_add_vertices(h.h, 1, Q2, S2) == HS_OK);
  hs_history_free(h.h);
  h.h = nullptr;
  REQUIRE(hs_eval_traction(st.s, 1, &px, &q1) == HS_OK);
  REQUIRE(hs_eval_stress(st.s, 1, 0.0, 1, &px, &py, s1) == HS_OK);
  CHECK(q0 == q1);
  CHECK((s0[0] == s1[0] && s0[1] == s1[1] && s0[2] == s1[2]));
  hs_summary sm;
  sm.struct_size = sizeof sm;
  REQUIRE(hs_solution_summary(st.s, &sm) == HS_OK);
  CHECK(sm.model == 0);
  CHECK(sm.iterations == 0);
  CHECK(sm.a == sc.a);
  double ext[5];
  REQUIRE(hs_surface_stress_extremes(st.s, 1, 0.0, 0.0, ext) == HS_OK);
  CHECK(ext[0] > ext[2]);
}
