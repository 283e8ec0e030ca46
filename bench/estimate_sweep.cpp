// Issue 13, "the estimate holds everywhere": a sweep of scenes per geometry
// (Hertz, flat punch with rounded corners, power law) that compares every
// double result of HS_MODEL_DEFAULT and HS_MODEL_AUTO (rtol 0 and 1e-10; AUTO
// also at 1e-15, and "apost": the closed form or full-precision quadrature
// with the a-posteriori estimate of issue 16) with the MPFR reference backend
// and counts the scenes whose true error exceeds the reported estimate
// (docs/validation.md, "Estimate sweep", "A-posteriori estimate").
//
// Scenes (category = row index mod 7, so that a run cut short by its time
// limit still covers every category):
//   0 random:     Q/fP uniform in (-1, 1), sigma/fp0 = +-10^U(-3, 1.5)
//   1 q -> 0:     |Q/fP| = 10^U(-12, -2), sigma = q 10^U(-2, 2) (a quarter with sigma = 0)
//   2 q -> 1:     1 - |Q/fP| = 10^U(-12, -2), sigma/fp0 = +-10^U(-3, 1)
//   3 boundary:   sigma = s_b (1 +- 10^U(-12, -1)), s_b where d1 -> 0 (the regime
//                 boundary): 4q/(1 + sqrt(1 - q)) for Hertz, otherwise located by
//                 bisection on the regime of the double quadrature (40 halvings)
//   4 small:      |Q/fP|, |sigma/fp0| = 10^U(-30, -8) (a fifth down to 10^-320)
//   5 large s:    |sigma/fp0| = 10^U(1, 4), Q/fP uniform in (-0.99, 0.99)
//   6 negative:   Q/fP in (-1, 0), sigma/fp0 uniform in (-8, 8)
// Signs are random in every category; a, p0, f, E* are uniform in [0.5, 2].
//
// Truth: hs_ref_solve (MPFR), inputs passed as the exact decimal of each
// double, read into long double (issue 16: errors of an ulp are measured). Hertz: 30 digits, d1, d2, E1, E2. Flat punch and power law: 20
// digits for d1, d2 (certified MPFR energies of the general path take
// 10-60 s a scene); their energies come from the same solver in long double
// (core::solve_general<long double>, bound 192 eps_LD (1 + a/d_min + 1/w),
// the quadrature estimate's form with long double's epsilon), whose d1, d2
// are checked against the MPFR ones in the same row.
//
// Error (docs/models.md): largest relative error of d_i and E_i over the
// zones that are nonempty in the truth. A zone empty in the truth (d_i = 0 in
// double after rounding the reference) contributes the length the double
// model reports for it in units of a (a zone that does not exist cannot be
// measured relative to itself; a reported length of 1e-17 a is harmless, one
// of 1e-3 a is an error of that size). A zone energy that underflows in the
// truth while the zone does not is left out. AUTO results that took the
// reference route for the flat punch or power law are checked on d1, d2 only.
//
// Each scene runs in a child process (fork) with a time limit per phase, so
// that a hang is counted, not waited for: double solves (--double-budget,
// default 120 s), reference (--ref-budget, default 20 s), long double truth.
//
//   usage: estimate_sweep [--geometry hertz|flat|power|all] [--n N] [--seed S]
//            [--time-limit SECONDS_PER_GEOMETRY] [--ref-budget S] [--double-budget S]
//            [--csv OUT.csv] [--summary OUT.md] [--sharp-corners]
// --sharp-corners: the flat punch with 1 - b_f/a = 10^U(-12, -3) (default b_f/a = 0.999 U)
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "halfslip/core/general.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/halfslip.h"

namespace core = hs::core;

namespace {

using clk = std::chrono::steady_clock;
double seconds_since(clk::time_point t0) { return std::chrono::duration<double>(clk::now() - t0).count(); }

std::string exact_decimal(double v) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%.800e", v);
  std::string s(buf);
  const size_t e = s.find('e');
  std::string mant = s.substr(0, e), ex = s.substr(e);
  while (!mant.empty() && mant.back() == '0') mant.pop_back();
  if (!mant.empty() && mant.back() == '.') mant.pop_back();
  return mant + ex;
}

struct scene {
  int kind;
  double par;
  int category;
  hs_scene sc;
};

// one double solve (model, rtol)
struct dres {
  int status = -1, model = 0, regime = -1, dir1 = 0, dir2 = 0;
  double time = 0, d1 = NAN, d2 = NAN, e1 = NAN, e2 = NAN, est = NAN;
  double resolution = 0;  // hs_summary.zone_resolution (issue 13)
};

// the truths in long double (issue 16: errors of ~1 ulp of double are measured,
// so the truth is not rounded to double)
struct rres {
  int status = -1, regime = -1, dir1 = 0, dir2 = 0, cert = 0;
  double time = 0;
  long double d1 = NAN, d2 = NAN, e1 = NAN, e2 = NAN;
};

struct lres {
  int status = -1;
  double time = 0;
  long double d1 = NAN, d2 = NAN, e1 = NAN, e2 = NAN;
  double bound = NAN;
};

// issue 16: AUTO at rtol 1e-15, and "apost": the closed form (Hertz) or the
// full-precision quadrature (other geometries) with the a-posteriori estimate
// (core::a_posteriori_closed_form / a_posteriori_quadrature), whatever its size
constexpr int n_configs = 6;
constexpr int apost_config = 5;
const int config_model[n_configs] = {HS_MODEL_DEFAULT, HS_MODEL_DEFAULT, HS_MODEL_AUTO,
                                     HS_MODEL_AUTO,    HS_MODEL_AUTO,    HS_MODEL_QUADRATURE};
const double config_rtol[n_configs] = {0, 1e-10, 0, 1e-10, 1e-15, 0};
const char *config_name[n_configs] = {"default0", "default1e-10", "auto0", "auto1e-10", "auto1e-15", "apost"};

struct msg1 {
  double s;  // sigma/fp0 actually used (the boundary category locates it in the child)
  dres r[n_configs];
};

int solve(const scene &c, int model, double rtol, hs_solution **out) {
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  o.rtol = rtol;
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = c.kind;
  g.flat_over_a = c.par;
  g.exponent = c.par;
  return hs_solve_geometry(&c.sc, &g, &o, out);
}

dres run_double(const scene &c, int model, double rtol) {
  dres r;
  hs_solution *sol = nullptr;
  const auto t0 = clk::now();
  r.status = solve(c, model, rtol, &sol);
  if (r.status == HS_OK) {
    hs_summary s;
    s.struct_size = sizeof s;
    hs_solution_summary(sol, &s);
    r.model = s.model;
    r.regime = s.regime;
    r.dir1 = s.slip_dir1;
    r.dir2 = s.slip_dir2;
    r.d1 = s.d1;
    r.d2 = s.d2;
    r.est = s.error_estimate;
    r.resolution = s.zone_resolution;
    // certified energies of the general path through the reference take 10-60 s: d only
    if (!(s.model == HS_MODEL_REFERENCE && c.kind != HS_GEOMETRY_HERTZ)) {
      double e[2];
      if (hs_solution_energy(sol, e) == HS_OK) {
        r.e1 = e[0];
        r.e2 = e[1];
      }
    }
    hs_solution_free(sol);
  }
  r.time = seconds_since(t0);
  return r;
}

// the double model with the a-posteriori estimate (issue 16), through the core
dres run_apost(const scene &c) {
  dres r;
  const auto t0 = clk::now();
  try {
    core::general_scene<double> g;
    g.a = c.sc.a;
    g.p0 = c.sc.p0;
    g.f = c.sc.f;
    g.Estar = c.sc.E_star;
    g.q = c.sc.Q_over_fP;
    g.s = c.sc.sigma_over_fp0;
    core::error_estimate<double> e;
    auto fill = [&](const auto &s) {
      r.d1 = s.d1();
      r.d2 = s.d2();
      r.e1 = s.energy(1);
      r.e2 = s.energy(2);
      r.regime = int(s.reg);
    };
    if (c.kind == HS_GEOMETRY_HERTZ) {
      const auto s = core::solve_hertz<double>(g);
      e = core::a_posteriori_closed_form(s);
      fill(s);
      r.model = HS_MODEL_CLOSED_FORM;
    } else {
      const bool flat = c.kind == HS_GEOMETRY_FLAT_ROUNDED;
      const auto pm = core::parametrised_pressure<double>(flat, c.par);
      const auto pw = core::parametrised_pressure<long double>(flat, c.par);
      const auto s = core::solve_general<double>(*pm, g);
      e = core::a_posteriori_quadrature(s, *pw);
      fill(s);
      r.model = HS_MODEL_QUADRATURE;
    }
    r.est = e.value();
    r.resolution = e.resolution;
    r.status = HS_OK;
  } catch (const core::error &e) {
    r.status = int(e.code());
  }
  r.time = seconds_since(t0);
  return r;
}

// Regime boundary of a non-Hertz geometry at q > 0: the sigma > 0 where the
// regime of the double quadrature changes from same-sign to opposite-sign.
double locate_boundary(scene c) {
  const double q = std::abs(c.sc.Q_over_fP);
  c.sc.Q_over_fP = q;
  const double sh = 4 * q / (1 + std::sqrt(1 - q));
  auto regime = [&](double s) {
    c.sc.sigma_over_fp0 = s;
    hs_solution *sol = nullptr;
    if (solve(c, HS_MODEL_QUADRATURE, 0, &sol) != HS_OK) return -1;
    hs_summary sm;
    sm.struct_size = sizeof sm;
    hs_solution_summary(sol, &sm);
    hs_solution_free(sol);
    return sm.regime;
  };
  double lo = 0.5 * sh, hi = 2 * sh;
  for (int k = 0; k < 20 && regime(lo) != HS_REGIME_SAME_SIGN; ++k) lo *= 0.5;
  for (int k = 0; k < 20 && regime(hi) != HS_REGIME_OPPOSITE_SIGN; ++k) hi *= 2;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    const int r = regime(mid);
    if (r == HS_REGIME_SAME_SIGN) lo = mid;
    else if (r == HS_REGIME_OPPOSITE_SIGN) hi = mid;
    else break;
  }
  return 0.5 * (lo + hi);
}

rres run_reference(const scene &c) {
  rres r;
  hs_ref_scene rs;
  hs_ref_scene_default(&rs);
  const std::string a = exact_decimal(c.sc.a), p0 = exact_decimal(c.sc.p0), f = exact_decimal(c.sc.f),
                    E = exact_decimal(c.sc.E_star), q = exact_decimal(c.sc.Q_over_fP),
                    s = exact_decimal(c.sc.sigma_over_fp0), par = exact_decimal(c.par);
  rs.geometry = c.kind;
  rs.a = a.c_str();
  rs.p0 = p0.c_str();
  rs.f = f.c_str();
  rs.E_star = E.c_str();
  rs.Q_over_fP = q.c_str();
  rs.sigma_over_fp0 = s.c_str();
  if (c.kind == HS_GEOMETRY_FLAT_ROUNDED) rs.flat_over_a = par.c_str();
  if (c.kind == HS_GEOMETRY_POWER_LAW) rs.exponent = par.c_str();
  const bool hertz = c.kind == HS_GEOMETRY_HERTZ;
  const auto t0 = clk::now();
  hs_ref_solution *sol = nullptr;
  r.status = hs_ref_solve(&rs, 20, &sol);
  if (r.status == HS_OK) {
    hs_ref_summary sm;
    sm.struct_size = sizeof sm;
    hs_ref_solution_summary(sol, &sm);
    r.regime = sm.regime;
    r.dir1 = sm.slip_dir1;
    r.dir2 = sm.slip_dir2;
    r.cert = 1000;
    auto get = [&](int what, long double &v) {
      char buf[256];
      int cert = 0;
      const int st = hs_ref_value(sol, what, buf, sizeof buf, nullptr, &cert);
      if (st != HS_OK) {
        r.status = st;
        return;
      }
      v = std::strtold(buf, nullptr);
      // an exact zero needs no certified digits
      if (v != 0) r.cert = std::min(r.cert, cert);
    };
    get(HS_REF_D1, r.d1);
    get(HS_REF_D2, r.d2);
    if (hertz) {
      get(HS_REF_ENERGY1, r.e1);
      get(HS_REF_ENERGY2, r.e2);
    }
    hs_ref_solution_free(sol);
  }
  r.time = seconds_since(t0);
  return r;
}

lres run_long_double(const scene &c) {
  lres r;
  const auto t0 = clk::now();
  try {
    std::unique_ptr<core::pressure_model<long double>> pm;
    if (c.kind == HS_GEOMETRY_FLAT_ROUNDED) pm.reset(new core::flat_rounded_pressure<long double>(c.par));
    else pm.reset(new core::power_law_pressure<long double>(c.par));
    core::general_scene<long double> g;
    g.a = c.sc.a;
    g.p0 = c.sc.p0;
    g.f = c.sc.f;
    g.Estar = c.sc.E_star;
    g.q = c.sc.Q_over_fP;
    g.s = c.sc.sigma_over_fp0;
    const auto sol = core::solve_general(*pm, g);
    r.d1 = sol.d1();
    r.d2 = sol.d2();
    r.e1 = sol.energy(1);
    r.e2 = sol.energy(2);
    const long double dmin = std::min(sol.d1() > 0 ? sol.d1() : g.a, sol.d2() > 0 ? sol.d2() : g.a) / g.a;
    // the quadrature estimate's form in long double, 3x for energies (docs/models.md)
    r.bound = double(192 * std::numeric_limits<long double>::epsilon() * (1 + 1 / dmin + 1 / sol.width));
    r.status = HS_OK;
  } catch (const core::error &e) {
    r.status = 1000 + int(e.code());
  } catch (...) {
    r.status = 999;
  }
  r.time = seconds_since(t0);
  return r;
}

// ---- child process with per-phase time limits -----------------------------

bool write_all(int fd, const void *p, size_t n) {
  const char *c = static_cast<const char *>(p);
  while (n) {
    const ssize_t k = write(fd, c, n);
    if (k <= 0) return false;
    c += k;
    n -= size_t(k);
  }
  return true;
}

// 1: read, 0: timeout, -1: child gone
int read_within(int fd, void *p, size_t n, double budget) {
  char *c = static_cast<char *>(p);
  const auto t0 = clk::now();
  while (n) {
    const double left = budget - seconds_since(t0);
    if (left <= 0) return 0;
    pollfd pf{fd, POLLIN, 0};
    const int pr = poll(&pf, 1, int(std::ceil(left * 1000)));
    if (pr == 0) return 0;
    if (pr < 0) continue;
    const ssize_t k = read(fd, c, n);
    if (k <= 0) return -1;
    c += k;
    n -= size_t(k);
  }
  return 1;
}

struct outcome {
  scene c;
  msg1 m1{};
  rres ref;
  lres ld;
  int phase_timeout = 0;  // 1 double, 2 reference, 3 long double
  int crashed = 0;
};

outcome run_scene(scene c, double double_budget, double ref_budget) {
  outcome o;
  o.c = c;
  o.m1.s = c.sc.sigma_over_fp0;
  int fds[2];
  if (pipe(fds) != 0) std::abort();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    msg1 m{};
    if (c.category == 3 && c.kind != HS_GEOMETRY_HERTZ) {
      const double q = c.sc.Q_over_fP, delta = c.sc.sigma_over_fp0;  // the parent stored the relative offset
      const double sb = std::copysign(locate_boundary(c), q);
      c.sc.sigma_over_fp0 = sb * (1 + delta);
    }
    m.s = c.sc.sigma_over_fp0;
    for (int k = 0; k < n_configs; ++k)
      m.r[k] = k == apost_config ? run_apost(c) : run_double(c, config_model[k], config_rtol[k]);
    write_all(fds[1], &m, sizeof m);
    const rres r = run_reference(c);
    write_all(fds[1], &r, sizeof r);
    if (c.kind != HS_GEOMETRY_HERTZ) {
      const lres l = run_long_double(c);
      write_all(fds[1], &l, sizeof l);
    }
    _exit(0);
  }
  close(fds[1]);
  int rd = read_within(fds[0], &o.m1, sizeof o.m1, double_budget);
  if (rd == 1) {
    o.c.sc.sigma_over_fp0 = o.m1.s;
    rd = read_within(fds[0], &o.ref, sizeof o.ref, ref_budget);
    if (rd == 1 && c.kind != HS_GEOMETRY_HERTZ) {
      rd = read_within(fds[0], &o.ld, sizeof o.ld, double_budget);
      if (rd != 1) o.phase_timeout = 3;
    } else if (rd != 1) o.phase_timeout = 2;
  } else o.phase_timeout = 1;
  if (rd == -1) {
    o.crashed = o.phase_timeout;
    o.phase_timeout = 0;
  }
  if (rd != 1) kill(pid, SIGKILL);
  int st = 0;
  waitpid(pid, &st, 0);
  close(fds[0]);
  return o;
}

// ---- scenes ---------------------------------------------------------------

scene make_scene(int kind, int index, std::mt19937_64 &rng, bool sharp = false) {
  std::uniform_real_distribution<double> U(0, 1);
  auto L = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * U(rng)); };
  auto sgn = [&] { return U(rng) < 0.5 ? -1.0 : 1.0; };
  scene c;
  c.kind = kind;
  c.category = index % 7;
  c.par = kind == HS_GEOMETRY_FLAT_ROUNDED ? 0.999 * U(rng) : kind == HS_GEOMETRY_POWER_LAW ? L(0, 3) : 2.0;
  // --sharp-corners (session 20): the flat punch's corner 1e-12 to 1e-3 a wide
  if (sharp && kind == HS_GEOMETRY_FLAT_ROUNDED) c.par = 1 - L(-12, -3);
  if (kind == HS_GEOMETRY_POWER_LAW && !(c.par > 1 && c.par < 1000)) c.par = 2;
  hs_scene_default(&c.sc);
  c.sc.a = 0.5 + 1.5 * U(rng);
  c.sc.p0 = 0.5 + 1.5 * U(rng);
  c.sc.f = 0.5 + 1.5 * U(rng);
  c.sc.E_star = 0.5 + 1.5 * U(rng);
  double q = 0, s = 0;
  switch (c.category) {
    case 0:
      q = 2 * U(rng) - 1;
      s = sgn() * L(-3, 1.5);
      break;
    case 1:
      q = sgn() * L(-12, -2);
      s = U(rng) < 0.25 ? 0.0 : sgn() * std::abs(q) * L(-2, 2);
      break;
    case 2:
      q = sgn() * (1 - L(-12, -2));
      s = sgn() * L(-3, 1);
      break;
    case 3: {
      q = sgn() * L(-10, std::log10(0.99));
      const double delta = sgn() * L(-12, -1);
      if (kind == HS_GEOMETRY_HERTZ) {
        const double sb = 4 * std::abs(q) / (1 + std::sqrt(1 - std::abs(q)));
        s = std::copysign(sb, q) * (1 + delta);
      } else s = delta;  // the child locates the boundary and applies the offset
      break;
    }
    case 4:
      if (U(rng) < 0.2) {
        q = sgn() * L(-320, -30);
        s = sgn() * L(-320, -30);
      } else {
        q = sgn() * L(-30, -8);
        s = sgn() * L(-30, -8);
      }
      break;
    case 5:
      q = 0.99 * (2 * U(rng) - 1);
      s = sgn() * L(1, 4);
      break;
    case 6:
      q = -U(rng);
      s = 16 * U(rng) - 8;
      break;
  }
  c.sc.Q_over_fP = q;
  c.sc.sigma_over_fp0 = s;
  return c;
}

// ---- comparison -----------------------------------------------------------

double rel(long double v, long double t) { return double(std::abs(v - t) / std::abs(t)); }

struct verdict {
  double err = NAN;      // true error (docs/models.md, empty zones as in the header)
  double bound = 0;      // the truth's own error bound
  bool dir_ok = true;    // resolved zones: the truth's direction; unresolved: 0, within the resolution
  bool energies = true;  // energies were compared
};

verdict compare(const outcome &o, const dres &r) {
  verdict v;
  const bool hertz = o.c.kind == HS_GEOMETRY_HERTZ;
  const double a = o.c.sc.a;
  long double te1 = o.ref.e1, te2 = o.ref.e2;
  v.bound = 1e-19;
  if (!hertz) {
    te1 = o.ld.e1;
    te2 = o.ld.e2;
    if (o.ld.status != HS_OK) v.energies = false;
    else v.bound = std::max(v.bound, o.ld.bound);
  }
  if (std::isnan(r.e1)) v.energies = false;
  double err = 0;
  const long double td[2] = {o.ref.d1, o.ref.d2}, te[2] = {te1, te2};
  const double rd[2] = {r.d1, r.d2}, re[2] = {r.e1, r.e2};
  const int tdir[2] = {o.ref.dir1, o.ref.dir2}, rdir[2] = {r.dir1, r.dir2};
  for (int i = 0; i < 2; ++i) {
    // a zone at or below the model's resolution (issue 13): bounded absolutely, direction 0
    if (!(rd[i] > r.resolution) && r.resolution > 0) {
      if (std::abs(rd[i] - td[i]) > r.resolution || rdir[i] != 0) v.dir_ok = false;
      continue;
    }
    if (td[i] == 0) {
      err = std::max(err, std::abs(rd[i]) / a);
      continue;
    }
    err = std::max(err, rel(rd[i], td[i]));
    if (tdir[i] != rdir[i]) v.dir_ok = false;
    if (v.energies && double(te[i]) > 0) err = std::max(err, rel(re[i], te[i]));
  }
  v.err = std::isnan(err) ? INFINITY : err;
  return v;
}

const char *geo_name(int kind) {
  return kind == HS_GEOMETRY_HERTZ ? "hertz" : kind == HS_GEOMETRY_FLAT_ROUNDED ? "flat-rounded" : "power-law";
}

struct stats {
  int scenes = 0, ref_ok = 0, ref_fail = 0, ref_timeout = 0, ref_uncertified = 0, double_timeout = 0, crashed = 0,
      ld_fail = 0;
  int status_fail[n_configs][32] = {};
  int bugs_status[n_configs] = {};  // non-OK where the reference solves
  int violations[n_configs] = {}, wrong_dir[n_configs] = {}, rtol_miss[n_configs] = {};
  double worst_ratio[n_configs] = {}, slowest[n_configs] = {}, slowest_ref = 0;
  std::string worst_scene[n_configs], slowest_scene[n_configs];
  double ld_dev = 0;  // largest relative deviation of the long double d from the MPFR d (non-Hertz)
  std::vector<std::string> examples;
};

std::string describe(const outcome &o) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "%s par=%.17g cat=%d a=%.17g p0=%.17g f=%.17g E=%.17g q=%.17g s=%.17g",
                geo_name(o.c.kind), o.c.par, o.c.category, o.c.sc.a, o.c.sc.p0, o.c.sc.f, o.c.sc.E_star,
                o.c.sc.Q_over_fP, o.c.sc.sigma_over_fp0);
  return buf;
}

}  // namespace

int main(int argc, char **argv) {
  std::string geometry = "all", csv = "bench/results/estimate_sweep.csv", summary = "";
  bool sharp = false;  // --sharp-corners: flat punch b_f/a = 1 - 10^U(-12, -3)
  int n = 10000;
  unsigned long seed = 13;
  double time_limit = 1e30, ref_budget = 20, double_budget = 120;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto next = [&]() -> const char * {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", k.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (k == "--geometry") geometry = next();
    else if (k == "--n") n = std::atoi(next());
    else if (k == "--seed") seed = std::strtoul(next(), nullptr, 10);
    else if (k == "--time-limit") time_limit = std::atof(next());
    else if (k == "--ref-budget") ref_budget = std::atof(next());
    else if (k == "--double-budget") double_budget = std::atof(next());
    else if (k == "--csv") csv = next();
    else if (k == "--summary") summary = next();
    else if (k == "--sharp-corners") sharp = true;
    else {
      std::fprintf(stderr, "unknown argument %s\n", k.c_str());
      return 2;
    }
  }
  std::vector<int> kinds;
  if (geometry == "all" || geometry == "hertz") kinds.push_back(HS_GEOMETRY_HERTZ);
  if (geometry == "all" || geometry == "flat") kinds.push_back(HS_GEOMETRY_FLAT_ROUNDED);
  if (geometry == "all" || geometry == "power") kinds.push_back(HS_GEOMETRY_POWER_LAW);
  if (kinds.empty()) return 2;
  std::FILE *out = std::fopen(csv.c_str(), "w");
  if (!out) {
    std::perror(csv.c_str());
    return 1;
  }
  std::fprintf(out,
               "geometry,parameter,category,index,a,p0,f,E_star,Q_over_fP,sigma_over_fp0,phase_timeout,crashed,"
               "ref_status,ref_time,ref_cert,ref_regime,ref_dir1,ref_dir2,ref_d1,ref_d2,ref_e1,ref_e2,"
               "ld_status,ld_time,ld_d1,ld_d2,ld_e1,ld_e2,ld_bound");
  for (auto nm : config_name)
    std::fprintf(out,
                 ",%s_status,%s_model,%s_time,%s_regime,%s_dir1,%s_dir2,%s_d1,%s_d2,%s_e1,%s_e2,%s_est,%s_err,"
                 "%s_ratio",
                 nm, nm, nm, nm, nm, nm, nm, nm, nm, nm, nm, nm, nm);
  std::fprintf(out, "\n");
  std::vector<stats> all;
  int total_violations = 0;
  for (int kind : kinds) {
    std::mt19937_64 rng(seed * 1000003ULL + kind);
    stats st;
    const auto t0 = clk::now();
    for (int i = 0; i < n && seconds_since(t0) < time_limit; ++i) {
      const scene c = make_scene(kind, i, rng, sharp);
      const outcome o = run_scene(c, double_budget, ref_budget);
      ++st.scenes;
      const bool ref_ok = o.phase_timeout == 0 && !o.crashed && o.ref.status == HS_OK && o.ref.cert >= 17;
      if (o.phase_timeout == 1) ++st.double_timeout;
      if (o.phase_timeout == 2) ++st.ref_timeout;
      if (o.crashed) ++st.crashed;
      if (o.phase_timeout == 0 && !o.crashed && o.ref.status != HS_OK) ++st.ref_fail;
      if (o.phase_timeout == 0 && !o.crashed && o.ref.status == HS_OK && o.ref.cert < 17) ++st.ref_uncertified;
      if (ref_ok) ++st.ref_ok;
      st.slowest_ref = std::max(st.slowest_ref, o.ref.time);
      if (ref_ok && kind != HS_GEOMETRY_HERTZ) {
        if (o.ld.status != HS_OK) ++st.ld_fail;
        else {
          for (double p : {o.ref.d1 > 0 ? rel(o.ld.d1, o.ref.d1) : 0.0, o.ref.d2 > 0 ? rel(o.ld.d2, o.ref.d2) : 0.0})
            st.ld_dev = std::max(st.ld_dev, p);
        }
      }
      std::fprintf(out,
                   "%s,%.17g,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%d,%.4g,%d,%d,%d,%d,%.17g,%.17g,%.17g,%."
                   "17g,%d,%.4g,%.17g,%.17g,%.17g,%.17g,%.3g",
                   geo_name(kind), c.par, c.category, i, c.sc.a, c.sc.p0, c.sc.f, c.sc.E_star, o.c.sc.Q_over_fP,
                   o.c.sc.sigma_over_fp0, o.phase_timeout, o.crashed, o.ref.status, o.ref.time, o.ref.cert,
                   o.ref.regime, o.ref.dir1, o.ref.dir2, double(o.ref.d1), double(o.ref.d2), double(o.ref.e1),
                   double(o.ref.e2), o.ld.status, o.ld.time, double(o.ld.d1), double(o.ld.d2), double(o.ld.e1),
                   double(o.ld.e2), o.ld.bound);
      for (int k = 0; k < n_configs; ++k) {
        const dres &r = o.m1.r[k];
        double err = NAN, ratio = NAN;
        if (o.phase_timeout != 1 && !(o.crashed == 1)) {
          if (r.time > st.slowest[k]) {
            st.slowest[k] = r.time;
            st.slowest_scene[k] = describe(o);
          }
          if (r.status != HS_OK) ++st.status_fail[k][std::min(r.status, 31)];
        }
        if (ref_ok) {
          if (r.status != HS_OK) {
            ++st.bugs_status[k];
            if (st.examples.size() < 40)
              st.examples.push_back(std::string(config_name[k]) + " status " + std::to_string(r.status) + ": " +
                                    describe(o));
          }
          if (r.status == HS_OK) {
            const verdict v = compare(o, r);
            err = v.err;
            ratio = err / r.est;
            if (ratio > st.worst_ratio[k]) {
              st.worst_ratio[k] = ratio;
              st.worst_scene[k] = describe(o);
            }
            if (err > r.est + v.bound) {
              ++st.violations[k];
              ++total_violations;
              if (st.examples.size() < 40) {
                char b[160];
                std::snprintf(b, sizeof b, " err=%.3g est=%.3g model=%d", err, r.est, r.model);
                st.examples.push_back(std::string(config_name[k]) + " VIOLATION" + b + ": " + describe(o));
              }
            }
            if (config_rtol[k] > 0 && config_model[k] == HS_MODEL_AUTO &&
                (r.est > config_rtol[k] || err > config_rtol[k] + v.bound))
              ++st.rtol_miss[k];
            if (!v.dir_ok && k != apost_config) {
              ++st.wrong_dir[k];
              if (st.examples.size() < 40)
                st.examples.push_back(std::string(config_name[k]) + " WRONG DIRECTION: " + describe(o));
            }
          }
        }
        std::fprintf(out, ",%d,%d,%.4g,%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.3g,%.3g,%.3g", r.status, r.model, r.time,
                     r.regime, r.dir1, r.dir2, r.d1, r.d2, r.e1, r.e2, r.est, err, ratio);
      }
      std::fprintf(out, "\n");
      std::fflush(out);
    }
    st.examples.insert(st.examples.begin(), "elapsed " + std::to_string(seconds_since(t0)) + " s");
    all.push_back(st);
  }
  std::fclose(out);
  // summary
  std::string md;
  char line[1200];
  md +=
      "| geometry | scenes | reference solved | ref. failed / timed out / uncertified | config | non-OK statuses "
      "(all scenes) | non-OK where the reference solves | estimate exceeded | wrong direction | AUTO rtol missed | "
      "worst err/est | slowest solve (s) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t g = 0; g < all.size(); ++g) {
    const stats &st = all[g];
    for (int k = 0; k < n_configs; ++k) {
      std::string fails;
      for (int c = 0; c < 32; ++c)
        if (st.status_fail[k][c])
          fails += (fails.empty() ? "" : ", ") + std::to_string(st.status_fail[k][c]) + " x " + std::to_string(c);
      if (fails.empty()) fails = "0";
      std::snprintf(
          line, sizeof line, "| %s | %d | %d | %d / %d / %d | %s | %s | %d | %d | %d | %s | %.3g | %.3g |\n",
          k == 0 ? geo_name(kinds[g]) : "", st.scenes, st.ref_ok, st.ref_fail, st.ref_timeout, st.ref_uncertified,
          config_name[k], fails.c_str(), st.bugs_status[k], st.violations[k], st.wrong_dir[k],
          config_model[k] == HS_MODEL_AUTO && config_rtol[k] > 0 ? std::to_string(st.rtol_miss[k]).c_str() : "-",
          st.worst_ratio[k], st.slowest[k]);
      md += line;
    }
  }
  md += "\n";
  for (size_t g = 0; g < all.size(); ++g) {
    const stats &st = all[g];
    std::snprintf(line, sizeof line,
                  "%s: double-phase timeouts %d, crashes %d, slowest reference %.3g s, long double truth failed %d, "
                  "largest |d_LD - d_ref|/d_ref %.3g\n",
                  geo_name(kinds[g]), st.double_timeout, st.crashed, st.slowest_ref, st.ld_fail, st.ld_dev);
    md += line;
    for (int k = 0; k < n_configs; ++k)
      md += "  worst ratio " + std::string(config_name[k]) + ": " + st.worst_scene[k] + "\n  slowest " +
            config_name[k] + ": " + st.slowest_scene[k] + "\n";
    for (const auto &e : st.examples) md += "  " + e + "\n";
  }
  std::fputs(md.c_str(), stdout);
  if (!summary.empty()) {
    std::FILE *s = std::fopen(summary.c_str(), "w");
    if (s) {
      std::fputs(md.c_str(), s);
      std::fclose(s);
    }
  }
  return total_violations ? 1 : 0;
}
