// Methods benchmark (issue #5, "Charts"): speed and accuracy of every way to
// solve a scene, and the stability of the double methods as each failure
// region of the Hertz solution is approached.
//
//   argv[1]  methods.csv   method,geometry,scene,median_ns,error
//   argv[2]  stability.csv sweep,method,param,error,error_stick
//
// error_stick is the relative error of the stick width b1 + b2 = 2 - d1 - d2
// formed from the returned d1, d2: meaningful while the stick zone is wide,
// pure cancellation once it is below eps (the tiny_stick sweep).
//
// Error = largest relative error of the slip-zone lengths d1, d2 (energies are
// left out: they are slow on the general path). Truth: Hertz, the MPFR
// reference (hs_ref_solve) at 120 digits for the methods table (so that the
// reference at 20..100 digits can be scored too) and at 40 digits for the
// sweeps; flat punch (b_f/a = 0.5), hs::core::solve_general<long double> at
// full precision (the reference backend does not take a flat punch yet). A failed solve is written as error "fail". Errors are computed
// in MPFR from the exact double result and the decimal reference string.
// See docs/benchmarks.md; run by scripts/bench.sh, never by ctest.
#include <mpfr.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "baselines.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/halfslip.h"

namespace {

volatile double g_sink;

// median over reps of the time per call, the inner count calibrated so that
// one rep lasts at least min_ms
double median_ns(const std::function<void()> &f, int reps, double min_ms) {
  using clk = std::chrono::steady_clock;
  auto t0 = clk::now();
  f();  // warm-up and calibration
  const double one = std::chrono::duration<double, std::milli>(clk::now() - t0).count();
  const int inner = std::max(1, int(std::min(1e6, min_ms / std::max(one, 1e-6))));
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    t0 = clk::now();
    for (int i = 0; i < inner; ++i) f();
    t.push_back(std::chrono::duration<double, std::nano>(clk::now() - t0).count() / inner);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// exact decimal of a double (glibc prints the exact expansion)
std::string exact(double x) {
  char b[160];
  std::snprintf(b, sizeof b, "%.120g", x);
  return b;
}

struct truth {
  std::string d1, d2;
  bool ok = false;
};

// relative error |x - ref| / |ref| in MPFR (absolute if ref = 0)
double rel_err(const std::string &x, const std::string &ref) {
  mpfr_t a, b;
  mpfr_init2(a, 1400);
  mpfr_init2(b, 1400);
  mpfr_set_str(a, x.c_str(), 10, MPFR_RNDN);
  mpfr_set_str(b, ref.c_str(), 10, MPFR_RNDN);
  mpfr_sub(a, a, b, MPFR_RNDN);
  mpfr_abs(a, a, MPFR_RNDN);
  if (!mpfr_zero_p(b)) mpfr_div(a, a, b, MPFR_RNDN);
  mpfr_abs(a, a, MPFR_RNDN);
  const double r = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clear(a);
  mpfr_clear(b);
  return r;
}

std::string ref_value(hs_ref_solution *s, int what) {
  char buf[512];
  if (hs_ref_value(s, what, buf, sizeof buf, nullptr, nullptr) != HS_OK) return "";
  return buf;
}

truth hertz_truth(double q, double s, int digits) {
  hs_ref_scene rs;
  hs_ref_scene_default(&rs);
  const std::string qs = exact(q), ss = exact(s);
  rs.Q_over_fP = qs.c_str();
  rs.sigma_over_fp0 = ss.c_str();
  hs_ref_solution *sol = nullptr;
  truth t;
  if (hs_ref_solve(&rs, digits, &sol) != HS_OK) return t;
  t.d1 = ref_value(sol, HS_REF_D1);
  t.d2 = ref_value(sol, HS_REF_D2);
  t.ok = !t.d1.empty() && !t.d2.empty();
  hs_ref_solution_free(sol);
  return t;
}

// a method's answer: d1, d2 as decimal strings (exact for doubles). A double
// answer keeps the doubles and is formatted only when scored, so that the
// timed call measures the solve and not the formatting (~1 us).
struct answer {
  std::string d1, d2;
  double x1 = NAN, x2 = NAN;
  bool ok = false;
  void text() {
    if (d1.empty() && ok) {
      d1 = exact(x1);
      d2 = exact(x2);
    }
  }
};
answer from_double(double d1, double d2, bool ok) {
  answer a;
  a.ok = ok && std::isfinite(d1) && std::isfinite(d2);
  if (a.ok) {
    a.x1 = d1;
    a.x2 = d2;
  }
  return a;
}

double score(answer a, const truth &t) {
  if (!a.ok || !t.ok) return NAN;
  a.text();
  return std::max(rel_err(a.d1, t.d1), rel_err(a.d2, t.d2));
}

hs_geometry flat_geometry() {
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_FLAT_ROUNDED;
  g.flat_over_a = 0.5;
  return g;
}

// the C ABI with a model; geometry NULL: Hertz via hs_solve
answer capi(double q, double s, int model, double rtol, const hs_geometry *geo) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  o.rtol = rtol;
  hs_solution *sol = nullptr;
  const int st = geo ? hs_solve_geometry(&sc, geo, &o, &sol) : hs_solve(&sc, &o, &sol);
  if (st != HS_OK) return {};
  hs_summary sm;
  sm.struct_size = sizeof sm;
  hs_solution_summary(sol, &sm);
  hs_solution_free(sol);
  return from_double(sm.d1, sm.d2, true);
}

answer refsolve(double q, double s, int digits) {
  truth t = hertz_truth(q, s, digits);
  answer a;
  a.ok = t.ok;
  a.d1 = t.d1;
  a.d2 = t.d2;
  return a;
}

answer gsl_carlson(double q, double s) {
  const auto r = baselines::solve_closed<baselines::gsl_basis>(q, s);
  return from_double(1 - r.b1, 1 - r.b2, r.ok);
}
answer boost_carlson(double q, double s) {
  const auto r = baselines::solve_closed<baselines::boost_basis>(q, s);
  return from_double(1 - r.b1, 1 - r.b2, r.ok);
}

struct method {
  std::string name;
  std::function<answer(double, double)> solve;
  int reps;
  double min_ms;
};

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string fmt(double e) {
  if (!std::isfinite(e)) return "fail";
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", e);
  return b;
}

}  // namespace

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  const std::string csv_m = argc > 1 ? argv[1] : "bench/results/methods.csv";
  const std::string csv_s = argc > 2 ? argv[2] : "bench/results/stability.csv";
  const bool quick = std::getenv("HS_BENCH_QUICK") != nullptr;
  const hs_geometry flat = flat_geometry();

  // ---- 1. speed and accuracy ----------------------------------------------
  struct scene {
    double q, s;
  };
  // same sign (s/4 <= q/(1+sqrt(1-q))): 4 scenes; opposite sign: 4 scenes
  const std::vector<scene> hertz = {{0.05, 0},  {0.3, 0.2}, {0.6, -0.5}, {0.9, 1.5},
                                    {0.0, 1.0}, {0.3, 2.0}, {0.5, 3.0},  {0.7, 8.0}};
  const std::vector<scene> flats = {{0.3, 0}, {0.6, 0.3}, {0.2, 2.0}, {0.5, 3.0}};

  baselines::qaws Qw;
  baselines::tanh_sinh_q Tq;
  const double fast = quick ? 1 : 5;
  std::vector<method> hm = {
      {"asymptotic", [](double q, double s) { return capi(q, s, HS_MODEL_ASYMPTOTIC, 0, nullptr); }, 9, fast},
      {"closed-form", [](double q, double s) { return capi(q, s, HS_MODEL_CLOSED_FORM, 0, nullptr); }, 9, fast},
      {"gsl-carlson", gsl_carlson, 9, fast},
      {"boost-carlson", boost_carlson, 9, fast},
  };
  for (double rt : {1e-4, 1e-8, 1e-12, 0.0}) {
    char nm[40];
    std::snprintf(nm, sizeof nm, rt > 0 ? "quadrature rtol=%.0e" : "quadrature rtol=0", rt);
    hm.push_back({nm, [rt](double q, double s) { return capi(q, s, HS_MODEL_QUADRATURE, rt, nullptr); }, 7, fast});
  }
  for (int dg : {20, 30, 50, 100})
    hm.push_back({"reference " + std::to_string(dg) + " digits",
                  [dg](double q, double s) { return refsolve(q, s, dg); }, 3, 0});
  hm.push_back({"naive-qaws",
                [&](double q, double s) {
                  const auto r = baselines::solve_naive(Qw, q, s);
                  return from_double(1 - r.b1, 1 - r.b2, r.ok);
                },
                3, 0});
  hm.push_back({"naive-tanh-sinh",
                [&](double q, double s) {
                  const auto r = baselines::solve_naive(Tq, q, s);
                  return from_double(1 - r.b1, 1 - r.b2, r.ok);
                },
                3, 0});

  std::vector<method> fm = {
      {"asymptotic", [&](double q, double s) { return capi(q, s, HS_MODEL_ASYMPTOTIC, 0, &flat); }, 9, fast}};
  for (double rt : {1e-4, 1e-8, 1e-12, 0.0}) {
    char nm[40];
    std::snprintf(nm, sizeof nm, rt > 0 ? "quadrature rtol=%.0e" : "quadrature rtol=0", rt);
    fm.push_back(
        {nm, [rt, &flat](double q, double s) { return capi(q, s, HS_MODEL_QUADRATURE, rt, &flat); }, 5, fast});
  }

  std::ofstream om(csv_m);
  om << "method,geometry,scene,median_ns,error\n";
  std::printf("%-24s %-6s %-14s %14s %11s\n", "method", "geom", "scene", "median [ns]", "error");
  auto run = [&](const std::vector<method> &ms, const std::vector<scene> &scenes, const char *geo,
                 const std::vector<truth> &tr) {
    for (const auto &M : ms)
      for (size_t i = 0; i < scenes.size(); ++i) {
        const auto &c = scenes[i];
        const double err = score(M.solve(c.q, c.s), tr[i]);
        const double ns = median_ns([&] { g_sink = double(M.solve(c.q, c.s).ok); }, quick ? 3 : M.reps, M.min_ms);
        char sc[48];
        std::snprintf(sc, sizeof sc, "q=%g s=%g", c.q, c.s);
        std::printf("%-24s %-6s %-14s %14.4g %11s\n", M.name.c_str(), geo, sc, ns, fmt(err).c_str());
        om << M.name << "," << geo << "," << sc << "," << ns << "," << fmt(err) << "\n";
      }
  };
  {
    std::vector<truth> tr;
    for (const auto &c : hertz) tr.push_back(hertz_truth(c.q, c.s, 120));
    run(hm, hertz, "hertz", tr);
  }
  {
    std::vector<truth> tr;
    for (const auto &c : flats) {
      // The reference C ABI does not take a flat punch yet (HS_MODEL_REFERENCE
      // gives HS_ERR_BAD_GEOMETRY): truth is the quadrature in long double at
      // full precision (error ~ 1e-19 (1 + a/d), far below double's).
      truth t;
      try {
        const hs::core::flat_rounded_pressure<long double> fp(0.5L);
        hs::core::general_scene<long double> g;
        g.q = c.q;
        g.s = c.s;
        const auto sol = hs::core::solve_general<long double>(fp, g, hs::core::general_options<long double>());
        char b1[64], b2[64];
        std::snprintf(b1, sizeof b1, "%.21Le", sol.d1());
        std::snprintf(b2, sizeof b2, "%.21Le", sol.d2());
        t.d1 = b1;
        t.d2 = b2;
        t.ok = true;
      } catch (...) {}
      tr.push_back(t);
    }
    run(fm, flats, "flat", tr);
  }
  om.close();
  std::printf("CSV written to %s\n", csv_m.c_str());

  // ---- 2. stability sweeps (Hertz, truth: reference at 40 digits) ------------
  std::ofstream os(csv_s);
  os << "sweep,method,param,error,error_stick\n";
  const std::vector<method> sm = {hm[0], hm[1], hm[2], {"quadrature rtol=0", hm[7].solve, 1, 0}};
  auto point = [&](const char *sweep, double param, double q, double s) {
    const truth t = hertz_truth(q, s, 40);
    for (const auto &M : sm) {
      answer a = M.solve(q, s);
      a.text();
      const double err = score(a, t);
      // relative error of the stick-zone width b1 + b2 = 2 - d1 - d2
      double es = NAN;
      if (a.ok && t.ok) {
        mpfr_t x, y;
        mpfr_inits2(1400, x, y, (mpfr_ptr)0);
        mpfr_set_str(x, a.d1.c_str(), 10, MPFR_RNDN);
        mpfr_set_str(y, a.d2.c_str(), 10, MPFR_RNDN);
        mpfr_add(x, x, y, MPFR_RNDN);
        mpfr_ui_sub(x, 2, x, MPFR_RNDN);
        mpfr_set_str(y, t.d1.c_str(), 10, MPFR_RNDN);
        mpfr_t z;
        mpfr_init2(z, 1400);
        mpfr_set_str(z, t.d2.c_str(), 10, MPFR_RNDN);
        mpfr_add(y, y, z, MPFR_RNDN);
        mpfr_ui_sub(y, 2, y, MPFR_RNDN);
        mpfr_sub(x, x, y, MPFR_RNDN);
        mpfr_div(x, x, y, MPFR_RNDN);
        mpfr_abs(x, x, MPFR_RNDN);
        es = mpfr_get_d(x, MPFR_RNDN);
        mpfr_clears(x, y, z, (mpfr_ptr)0);
      }
      if (!t.ok)  // the reference itself did not converge: no verdict on the method
        os << sweep << "," << M.name << "," << num(param) << ",no-truth,no-truth\n";
      else os << sweep << "," << M.name << "," << num(param) << "," << fmt(err) << "," << fmt(es) << "\n";
    }
  };
  // d/a -> 0: Q/fP = 1e-1 .. 1e-14, sigma = 0
  for (int k = 1; k <= 14; ++k) point("small_zone", std::pow(10.0, -k), std::pow(10.0, -k), 0);
  // Q/fP -> 1: 1 - Q/fP = 1e-1 .. 1e-14
  for (int k = 1; k <= 14; ++k) point("near_sliding", std::pow(10.0, -k), 1 - std::pow(10.0, -k), 0);
  // regime boundary at Q/fP = 0.5: s = s_b (1 + delta), s_b = 4q/(1+sqrt(1-q)); param = delta (signed)
  {
    const double q = 0.5, sb = 4 * q / (1 + std::sqrt(1 - q));
    for (int k = 1; k <= 13; ++k)
      for (int sg : {-1, +1}) {
        const double delta = sg * std::pow(10.0, -k);
        point("regime_boundary", delta, q, sb * (1 + delta));
      }
  }
  // k -> 1: tiny stick zone, sigma/fp0 = 1 .. 1e4 at Q/fP = 0.3
  for (int k = 0; k <= 16; ++k) {
    const double s = std::pow(10.0, k / 4.0);
    point("tiny_stick", s, 0.3, s);
  }
  os.close();
  std::printf("CSV written to %s\n", csv_s.c_str());
  return 0;
}
