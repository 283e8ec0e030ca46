// Stability charts for every geometry (issue 13, "What done looks like", second bullet):
// each user-selectable method swept to its failure along the hard parameter of the
// flat punch with rounded corners, the power law and sampled pressures, with its
// status (failures and timeouts are rows, not gaps), its error against a trusted value
// and its own error estimate.
//
//   usage: bench_stability OUT.csv [--quick] [--budget S] [--ref-budget S]
//
// Methods (what `halfslip solve --model/--rtol` offers for these geometries):
//   default            HS_MODEL_DEFAULT, rtol 0 (the quadrature at full precision)
//   quadrature 1e-8    HS_MODEL_QUADRATURE, rtol 1e-8
//   asymptotic         HS_MODEL_ASYMPTOTIC
//   auto 0, auto 1e-10 HS_MODEL_AUTO at rtol 0 and 1e-10
//   reference          HS_MODEL_REFERENCE (MPFR, rounded to double; not for samples)
// Every call runs in a child process (fork) with a time budget (--budget, default 10 s;
// the reference method --ref-budget, default 20 s): a hang is a row with status
// "timeout". After two consecutive timeouts of one method in one sweep its remaining
// points are written as "skipped" (also failures in the charts).
//
// Trusted values (docs/benchmarks.md, "Stability of the other geometries"):
//   reference  hs_ref_solve at 20 digits (inputs: the exact decimals of the doubles),
//              in its own child with --ref-budget.
//   limit      the sliding stick point. At large sigma the stick zone (-b2, b1) shrinks
//              onto x0 with Q = f (int_{-a}^{x0} p - int_{x0}^{a} p); x0 always lies in
//              the stick zone (the stick traction is bounded by f p), so |d_i - d_i(x0)| <= w,
//              the stick width. x0 is found here by Newton's method on a quadrature of the
//              pressure written for this program from the profile alone:
//                p(x) = E*/(2 pi) sqrt(a^2 - x^2) int_0^pi [g'(a cos t) - g'(x)] / (a cos t - x) dt,
//              (the bounded inversion of the half-plane integral equation; g the gap),
//              with divided differences formed without cancellation, composite Gauss-Legendre
//              in long double; its own error is the change under a finer rule (column
//              truth_unc, plus the width bound w/d where it is known: the width's decay
//              ln w = ln w_k - c (sigma - sigma_k) fitted to the last two reference widths
//              of the same sweep).
//   hertz      samples of a Hertz pressure: the MPFR Hertz solution (closed forms, 30 digits).
//              The samples' interpolant (PCHIP of p / sqrt(a^2 - x^2)) reproduces a Hertz
//              pressure up to the rounding of the samples, so the sampling error is the
//              samples' own rounding (a few eps; truth_unc = 4 eps).
//   samples of the flat punch (b_f/a = 0.5): the flat punch's reference; the difference is
//              the sampling error (PCHIP: O(h^2) at the kinks) plus the method's error, so that
//              curve shows convergence in n, not a bound.
// Error: the largest relative error of d1, d2 against the truth (zones nonempty in the truth).
// Energies are not scored (certified energies of the general path take 10-60 s a scene).
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
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "halfslip/core/pressure.hpp"
#include "halfslip/halfslip.h"

namespace {

using clk = std::chrono::steady_clock;
using ld = long double;
double seconds_since(clk::time_point t0) { return std::chrono::duration<double>(clk::now() - t0).count(); }

std::string exact_decimal(double v) {
  char buf[1100];
  std::snprintf(buf, sizeof buf, "%.800e", v);
  std::string s(buf);
  const size_t e = s.find('e');
  std::string mant = s.substr(0, e), ex = s.substr(e);
  while (!mant.empty() && mant.back() == '0') mant.pop_back();
  if (!mant.empty() && mant.back() == '.') mant.pop_back();
  return mant + ex;
}

// ---- child process with a time budget ---------------------------------------

constexpr int st_timeout = -2, st_crash = -3, st_skipped = -4;

template <class R> R in_child(const std::function<R()> &f, double budget, int &status) {
  R r{};
  int fds[2];
  if (pipe(fds) != 0) std::abort();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const R v = f();
    const char *c = reinterpret_cast<const char *>(&v);
    size_t n = sizeof v;
    while (n) {
      const ssize_t k = write(fds[1], c, n);
      if (k <= 0) break;
      c += k;
      n -= size_t(k);
    }
    _exit(0);
  }
  close(fds[1]);
  char *c = reinterpret_cast<char *>(&r);
  size_t n = sizeof r;
  const auto t0 = clk::now();
  status = 0;
  while (n) {
    const double left = budget - seconds_since(t0);
    if (left <= 0) {
      status = st_timeout;
      break;
    }
    pollfd pf{fds[0], POLLIN, 0};
    const int pr = poll(&pf, 1, int(std::ceil(left * 1000)));
    if (pr == 0) {
      status = st_timeout;
      break;
    }
    if (pr < 0) continue;
    const ssize_t k = read(fds[0], c, n);
    if (k <= 0) {
      status = st_crash;
      break;
    }
    c += k;
    n -= size_t(k);
  }
  if (status != 0) kill(pid, SIGKILL);
  int ws = 0;
  waitpid(pid, &ws, 0);
  close(fds[0]);
  return r;
}

// ---- geometries and methods -------------------------------------------------

struct geo {
  int kind = HS_GEOMETRY_HERTZ;
  double par = 0;                         // b_f/a or the exponent
  const std::vector<double> *sx = nullptr;  // samples
  const std::vector<double> *sp = nullptr;
};

struct method {
  const char *name;
  int model;
  double rtol;
};
const method methods[] = {{"default", HS_MODEL_DEFAULT, 0},       {"quadrature 1e-8", HS_MODEL_QUADRATURE, 1e-8},
                          {"asymptotic", HS_MODEL_ASYMPTOTIC, 0}, {"auto 0", HS_MODEL_AUTO, 0},
                          {"auto 1e-10", HS_MODEL_AUTO, 1e-10},   {"reference", HS_MODEL_REFERENCE, 0}};

struct dres {
  int status = 0, model = 0, regime = 0;
  double d1 = NAN, d2 = NAN, est = NAN, res = NAN, time = 0;
};

dres solve_double(const geo &g, double q, double s, int model, double rtol) {
  dres r;
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  hs_options o;
  hs_options_default(&o);
  o.model = model;
  o.rtol = rtol;
  hs_geometry G;
  hs_geometry_default(&G);
  G.kind = g.kind;
  if (g.kind == HS_GEOMETRY_FLAT_ROUNDED) G.flat_over_a = g.par;
  if (g.kind == HS_GEOMETRY_POWER_LAW) G.exponent = g.par;
  if (g.kind == HS_GEOMETRY_SAMPLES) {
    G.n_samples = g.sx->size();
    G.sample_x = g.sx->data();
    G.sample_p = g.sp->data();
  }
  hs_solution *sol = nullptr;
  const auto t0 = clk::now();
  r.status = hs_solve_geometry(&sc, &G, &o, &sol);
  r.time = seconds_since(t0);
  if (r.status == HS_OK) {
    hs_summary sm;
    sm.struct_size = sizeof sm;
    hs_solution_summary(sol, &sm);
    r.model = sm.model;
    r.regime = sm.regime;
    r.d1 = sm.d1;
    r.d2 = sm.d2;
    r.est = sm.error_estimate;
    r.res = sm.zone_resolution;
    hs_solution_free(sol);
  }
  return r;
}

struct rres {
  int status = 0;
  ld d1 = NAN, d2 = NAN;
  double time = 0;
};

// the MPFR reference: kind HERTZ / FLAT_ROUNDED / POWER_LAW
rres solve_reference(int kind, double par, double q, double s, int digits) {
  rres r;
  hs_ref_scene rs;
  hs_ref_scene_default(&rs);
  const std::string qs = exact_decimal(q), ss = exact_decimal(s), ps = exact_decimal(par);
  rs.geometry = kind;
  rs.Q_over_fP = qs.c_str();
  rs.sigma_over_fp0 = ss.c_str();
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) rs.flat_over_a = ps.c_str();
  if (kind == HS_GEOMETRY_POWER_LAW) rs.exponent = ps.c_str();
  hs_ref_solution *sol = nullptr;
  const auto t0 = clk::now();
  r.status = hs_ref_solve(&rs, digits, &sol);
  if (r.status == HS_OK) {
    char b[256];
    if (hs_ref_value(sol, HS_REF_D1, b, sizeof b, nullptr, nullptr) == HS_OK) r.d1 = std::strtold(b, nullptr);
    if (hs_ref_value(sol, HS_REF_D2, b, sizeof b, nullptr, nullptr) == HS_OK) r.d2 = std::strtold(b, nullptr);
    hs_ref_solution_free(sol);
  }
  r.time = seconds_since(t0);
  return r;
}

// ---- the sliding stick point, independently ----------------------------------
// Gauss-Legendre nodes and weights on [-1, 1] in long double (Newton on P_m).
struct gauss {
  std::vector<ld> x, w;
  explicit gauss(int m) {
    x.resize(m);
    w.resize(m);
    const ld pi = 3.14159265358979323846264338327950288L;
    for (int i = 0; i < m; ++i) {
      ld z = std::cos(pi * (i + 0.75L) / (m + 0.5L)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        ld p0 = 1, p1 = z;
        for (int k = 2; k <= m; ++k) {
          const ld p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = m * (z * p1 - p0) / (z * z - 1);
        const ld dz = p1 / dp;
        z -= dz;
        if (std::fabs(dz) < 1e-21L) break;
      }
      ld p0 = 1, p1 = z;
      for (int k = 2; k <= m; ++k) {
        const ld p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = m * (z * p1 - p0) / (z * z - 1);
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};

// a composite rule: uniform panels of width <= h between the breakpoints, each
// graded geometrically (halving, `levels` times) towards the points in `graded`
struct rule {
  const gauss &G;
  ld h;
  int levels;
  template <class F> ld panel(const F &f, ld lo, ld hi) const {
    const ld c = (lo + hi) / 2, r = (hi - lo) / 2;
    ld s = 0;
    for (size_t i = 0; i < G.x.size(); ++i) s += G.w[i] * f(c + r * G.x[i]);
    return s * r;
  }
  template <class F> ld integrate(const F &f, std::vector<ld> bps, const std::vector<ld> &graded) const {
    std::sort(bps.begin(), bps.end());
    bps.erase(std::unique(bps.begin(), bps.end()), bps.end());
    auto is_graded = [&](ld p) {
      for (ld g : graded)
        if (std::fabs(g - p) <= 1e-30L) return true;
      return false;
    };
    ld s = 0;
    for (size_t k = 0; k + 1 < bps.size(); ++k) {
      const ld lo = bps[k], hi = bps[k + 1];
      if (!(hi > lo)) continue;
      const bool gl = is_graded(lo), gr = is_graded(hi);
      int np = std::max(1, int(std::ceil((hi - lo) / h)));
      if (gl && gr) np = std::max(np, 2);
      const ld step = (hi - lo) / np;
      for (int i = 0; i < np; ++i) {
        const ld a = lo + i * step, b = (i + 1 == np) ? hi : lo + (i + 1) * step;
        if (i == 0 && gl) {  // halve towards lo
          ld right = b;
          for (int l = 0; l < levels; ++l) {
            const ld mid = lo + (right - lo) / 2;
            s += panel(f, mid, right);
            right = mid;
          }
          s += panel(f, lo, right);
        } else if (i + 1 == np && gr) {  // halve towards hi
          ld left = a;
          for (int l = 0; l < levels; ++l) {
            const ld mid = left + (hi - left) / 2;
            s += panel(f, left, mid);
            left = mid;
          }
          s += panel(f, left, hi);
        } else s += panel(f, a, b);
      }
    }
    return s;
  }
};

// the gap's slope g'(t) on a = 1 and the divided difference [g'(c) - g'(x)]/(c - x),
// formed without cancellation (the constant factors of g cancel in x0). omc = 1 - |c|,
// computed by the caller from the angle (2 sin^2), so that the flat punch's |c| - b_f
// = (1 - b_f) - omc keeps its digits as b_f -> 1 (cos t - b_f cancels to ~1e-19 / (1 - b_f)).
struct profile {
  bool flat;
  ld par;  // b_f/a or n
  ld gp(ld t, ld omt) const {
    if (flat) {
      const ld u = (1 - par) - omt;  // |t| - b_f; 1 - par is exact (par is a double)
      return u > 0 ? std::copysign(u, t) : 0;
    }
    return std::copysign(par * std::pow(std::fabs(t), par - 1), t);
  }
  ld dd(ld c, ld omc, ld x, ld omx) const {
    if (flat) {
      const bool rc = (1 - par) - omc > 0, rx = (1 - par) - omx > 0;
      if (rc && rx && ((c > 0) == (x > 0))) return 1;
      if (!rc && !rx) return 0;
      if (c == x) return 0.5L;  // at the kink, a null set (both sides within rounding of b_f)
      return (gp(c, omc) - gp(x, omx)) / (c - x);
    }
    const ld m = par - 1;
    if (x == 0) return par * std::pow(std::fabs(c), m - 1);
    if ((c > 0) != (x > 0) || c == 0) return (gp(c, omc) - gp(x, omx)) / (c - x);
    const ld ac = std::fabs(c), ax = std::fabs(x), u = (ac - ax) / ax;
    if (std::fabs(u) > 0.5L) return (gp(c, omc) - gp(x, omx)) / (c - x);  // no cancellation
    if (u == 0) return par * m * std::pow(ax, m - 1);
    return par * std::pow(ax, m - 1) * std::expm1(m * std::log1p(u)) / u;
  }
};

const ld PI = 3.14159265358979323846264338327950288L;

// 1 - |cos t| for t in [0, pi], without cancellation
ld one_minus_abs_cos(ld t) {
  const ld s = std::min(t, PI - t);
  const ld h = std::sin(s / 2);
  return 2 * h * h;
}

// h(x) = int_0^pi dd(cos t, x) dt, so that p(x) = E*/(2 pi) sqrt(1 - x^2) h(x); folded onto
// s in [0, pi/2] (t = s and t = pi - s), so that 1 - |cos| is formed from a small angle
// that is not the rounded difference pi - t
ld h_of(const profile &P, const rule &R, ld x, ld omx) {
  // breakpoints: the kink of g' (flat punch, graded from both sides); for the power law
  // s = pi/2 (|cos|^(n-1)) and |cos s| = |x| (the divided difference varies on the scale
  // |x| there), both graded
  std::vector<ld> bps = {0, PI / 2, std::acos(std::fabs(x))}, graded;
  if (P.flat) {
    const ld tb = 2 * std::asin(std::sqrt((1 - P.par) / 2));  // acos(b_f), accurate as b_f -> 1
    bps.push_back(tb);
    graded = {tb};
  } else graded = {PI / 2, std::acos(std::fabs(x))};
  return R.integrate(
      [&](ld t) {
        const ld c = std::cos(t), h = std::sin(t / 2), om = 2 * h * h;
        return P.dd(c, om, x, omx) + P.dd(-c, om, x, omx);
      },
      bps, graded);
}

// G(x0) = int_0^x0 p / int_0^1 p (x = sin phi), and int_0^1 p = E*/4 J with
// J = 2 int_0^{pi/2} cos t g'(cos t) dt
struct balance {
  profile P;
  rule R;
  ld J;
  balance(const profile &p, const rule &r) : P(p), R(r) {
    std::vector<ld> bps = {0, PI / 2}, graded;
    if (P.flat) bps.push_back(2 * std::asin(std::sqrt((1 - P.par) / 2)));
    else graded.push_back(PI / 2);
    J = 2 * R.integrate([&](ld t) { return std::cos(t) * P.gp(std::cos(t), one_minus_abs_cos(t)); }, bps, graded);
  }
  // x = sin ph, 1 - x = 2 sin^2((pi/2 - ph)/2)
  static ld omx_of(ld ph) {
    const ld h = std::sin((PI / 2 - ph) / 2);
    return 2 * h * h;
  }
  ld G(ld x0) const {
    const ld top = x0 >= 1 ? PI / 2 : std::asin(x0);
    std::vector<ld> bps = {0, top}, graded;
    if (P.flat) {
      if (P.par < x0) {
        const ld pb = PI / 2 - 2 * std::asin(std::sqrt((1 - P.par) / 2));  // asin(b_f)
        bps.push_back(pb);
        graded.push_back(pb);
      }
    } else graded.push_back(0);
    const ld I = R.integrate(
        [&](ld ph) {
          const ld c = std::cos(ph);
          return c * c * h_of(P, R, std::sin(ph), omx_of(ph));
        },
        bps, graded);
    return 2 * I / (PI * J);
  }
  ld dG(ld x0) const { return 2 * std::sqrt(1 - x0 * x0) * h_of(P, R, x0, 1 - x0) / (PI * J); }
};

struct limit_result {
  ld x0 = NAN;
  double unc = NAN, time = 0, total_check = NAN;  // unc: |x0(fine) - x0| bound; total_check = G(1) - 1
  int iterations = 0;
  bool ok = false;
};

// x0 > 0 with G(x0) = q (q > 0): Newton from the Hertz point; then one Newton
// correction with the finer rule gives the quadrature's own error of x0
limit_result sliding_point(bool flat, double par, double q, bool total_check = false) {
  static const gauss g20(20), g30(30);
  limit_result L;
  const auto t0 = clk::now();
  const profile P{flat, par};
  const balance B(P, rule{g20, 0.05L, 40});
  // Hertz: G(x) = (2/pi)(asin x + x sqrt(1 - x^2)); start by bisection on it
  ld lo = 0, hi = 1;
  for (int k = 0; k < 64; ++k) {
    const ld m = (lo + hi) / 2;
    ((2 / PI) * (std::asin(m) + m * std::sqrt(1 - m * m)) < q ? lo : hi) = m;
  }
  ld x = (lo + hi) / 2;
  ld lo_b = 0, hi_b = 1;  // bracket kept for safety
  for (int it = 0; it < 40; ++it) {
    const ld f = B.G(x) - q;
    L.iterations = it + 1;
    if (f == 0) {
      L.ok = true;
      break;
    }
    (f < 0 ? lo_b : hi_b) = x;
    ld step = f / B.dG(x);
    if (std::getenv("HS_DEBUG_X0")) std::printf("  it %d x %.21Lf f %.3Lg step %.3Lg\n", it, x, f, step);
    ld nx = x - step;
    if (!(nx >= lo_b && nx <= hi_b)) nx = (lo_b + hi_b) / 2;
    // converged: a step at the quadrature's noise, or the bracket closed
    const ld tol = 64 * std::numeric_limits<ld>::epsilon() * x;
    const bool done = std::fabs(nx - x) <= tol || hi_b - lo_b <= tol;
    x = nx;
    if (done) {
      L.ok = true;
      break;
    }
  }
  L.x0 = x;
  const balance F(P, rule{g30, 0.025L, 60});
  L.unc = double(std::fabs((F.G(x) - q) / F.dG(x)));
  if (total_check) L.total_check = double(B.G(1) - 1);
  L.time = seconds_since(t0);
  return L;
}

// ---- rows -----------------------------------------------------------------

struct truth {
  const char *kind = "none";  // reference, limit, hertz, none
  ld d1 = NAN, d2 = NAN;
  double unc = NAN;  // relative uncertainty of the truth (NaN: not bounded here)
  int status = 0;
  double time = 0;
};

std::string fmt(double v, const char *f = "%.4g") {
  if (std::isnan(v)) return "";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}
std::string fmtl(ld v) {
  if (std::isnan(v)) return "";
  char b[64];
  std::snprintf(b, sizeof b, "%.21Lg", v);
  return b;
}

const char *status_text(int st) {
  switch (st) {
    case st_timeout: return "timeout";
    case st_crash: return "crash";
    case st_skipped: return "skipped";
    default: return st == 0 ? "ok" : hs_strerror(st);
  }
}

struct options {
  double budget = 10, ref_budget = 20;
  bool quick = false;
};

struct sweep_runner {
  std::ofstream &out;
  const options &opt;
  int exceeded = 0, auto_fail_ref_ok = 0, rows = 0;
  std::vector<std::string> notes;

  void header() {
    out << "chart,sweep,param,q,sigma,geometry,geo_par,n_samples,method,status,model,d1,d2,estimate,"
           "resolution,time_s,truth,truth_d1,truth_d2,truth_unc,error,ratio\n";
  }
  // one sweep: points (param, geometry, q, s, truth) and the methods to run
  struct point {
    double param;
    geo g;
    double q, s;
    truth t;
  };
  void run(const char *chart, const char *sweep, const std::vector<point> &pts, bool with_reference_method) {
    for (const auto &M : methods) {
      if (M.model == HS_MODEL_REFERENCE && !with_reference_method) continue;
      int consecutive_timeouts = 0;
      for (const auto &p : pts) {
        dres r;
        int cst = 0;
        if (consecutive_timeouts >= 2) cst = st_skipped;
        else {
          const double budget = M.model == HS_MODEL_REFERENCE ? opt.ref_budget : opt.budget;
          r = in_child<dres>([&] { return solve_double(p.g, p.q, p.s, M.model, M.rtol); }, budget, cst);
          consecutive_timeouts = cst == st_timeout ? consecutive_timeouts + 1 : 0;
        }
        const int status = cst != 0 ? cst : r.status;
        double err = NAN;
        if (status == 0 && std::string(p.t.kind) != "none") {
          ld e = 0;
          if (p.t.d1 > 0) e = std::max(e, std::fabs(ld(r.d1) - p.t.d1) / p.t.d1);
          if (p.t.d2 > 0) e = std::max(e, std::fabs(ld(r.d2) - p.t.d2) / p.t.d2);
          err = double(e);
        }
        const double ratio = std::isnan(err) ? NAN : err / r.est;
        // the result's claim (hs_summary): a zone longer than zone_resolution is within the
        // relative estimate, a shorter one (unresolved) within zone_resolution in units of a.
        // Violated beyond what the truth's own uncertainty can explain: a finding.
        bool real_excess = false;
        if (!std::isnan(err) && std::string(p.t.kind) != "samples-flat") {
          const double tu = std::fabs(p.t.unc);
          const double dm[2] = {r.d1, r.d2};
          const ld dt[2] = {p.t.d1, p.t.d2};
          for (int z = 0; z < 2; ++z) {
            const double abs_err = double(std::fabs(ld(dm[z]) - dt[z]));
            if (dm[z] > r.res) {
              if (dt[z] > 0 && abs_err / double(dt[z]) > r.est && abs_err / double(dt[z]) > 2 * tu) real_excess = true;
            } else if (abs_err > r.res && abs_err > 2 * tu * double(dt[z])) real_excess = true;
          }
        }
        if (real_excess) {
          ++exceeded;
          notes.push_back(std::string("ESTIMATE EXCEEDED ") + chart + "/" + sweep + " " + M.name +
                          " param=" + fmt(p.param, "%.17g") + " q=" + fmt(p.q, "%.17g") +
                          " s=" + fmt(p.s, "%.17g") + " err=" + fmt(err) + " est=" + fmt(r.est) +
                          (p.t.unc < 0 ? " (truth: sliding point, stick width not bounded here)" : ""));
        }
        // (the flat punch's reference is no truth for coarse samples of it: they may break the
        // samples' rules, a status that names the reason)
        if ((M.model == HS_MODEL_AUTO || M.model == HS_MODEL_DEFAULT) && status != 0 &&
            std::string(p.t.kind) != "none" && std::string(p.t.kind) != "samples-flat") {
          ++auto_fail_ref_ok;
          notes.push_back(std::string("FAILED WHERE A TRUTH EXISTS ") + chart + "/" + sweep + " " +
                          M.name + " param=" + fmt(p.param, "%.17g") + ": " + status_text(status));
        }
        out << chart << "," << sweep << "," << fmt(p.param, "%.17g") << "," << fmt(p.q, "%.17g") << ","
            << fmt(p.s, "%.17g") << ","
            << (p.g.kind == HS_GEOMETRY_FLAT_ROUNDED ? "flat-rounded"
                : p.g.kind == HS_GEOMETRY_POWER_LAW  ? "power-law"
                                                     : "samples")
            << "," << fmt(p.g.par, "%.17g") << "," << (p.g.sx ? p.g.sx->size() : 0) << "," << M.name << ","
            << '"' << status_text(status) << '"' << "," << (status == 0 ? hs_model_name(r.model) : "") << ","
            << (status == 0 ? fmt(r.d1, "%.17g") : "") << "," << (status == 0 ? fmt(r.d2, "%.17g") : "") << ","
            << (status == 0 ? fmt(r.est, "%.3g") : "") << "," << (status == 0 ? fmt(r.res, "%.3g") : "") << ","
            << fmt(r.time, "%.3g") << "," << p.t.kind << "," << fmtl(p.t.d1) << "," << fmtl(p.t.d2) << ","
            << fmt(p.t.unc, "%.3g") << "," << fmt(err, "%.4g") << "," << fmt(ratio, "%.3g") << "\n";
        out.flush();
        ++rows;
        std::printf("%-8s %-16s %-12s %-16s %-10s %-10s err %-10s est %-10s %s %.2fs\n", chart, sweep,
                    fmt(p.param, "%.6g").c_str(), M.name, status_text(status),
                    status == 0 ? hs_model_name(r.model) : "-", fmt(err).c_str(), fmt(r.est, "%.3g").c_str(),
                    p.t.kind, r.time);
        std::fflush(stdout);
      }
    }
  }
};

truth reference_truth(int kind, double par, double q, double s, double budget) {
  truth t;
  int cst = 0;
  const rres r = in_child<rres>([&] { return solve_reference(kind, par, q, s, 20); }, budget, cst);
  t.status = cst ? cst : r.status;
  t.time = r.time;
  if (t.status == 0 && std::isfinite(double(r.d1)) && std::isfinite(double(r.d2))) {
    t.kind = "reference";
    t.d1 = r.d1;
    t.d2 = r.d2;
    t.unc = 1e-19;
  }
  return t;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_stability OUT.csv [--quick] [--budget S] [--ref-budget S]\n");
    return 2;
  }
  options opt;
  for (int k = 2; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--quick")) opt.quick = true;
    else if (!std::strcmp(argv[k], "--budget") && k + 1 < argc) opt.budget = std::atof(argv[++k]);
    else if (!std::strcmp(argv[k], "--ref-budget") && k + 1 < argc) opt.ref_budget = std::atof(argv[++k]);
  }
  if (!std::strcmp(argv[1], "--selftest")) {
    // the sliding-point quadrature against Hertz, where x0 is known in closed form:
    // the flat punch at b_f/a = 0 and the power law at n = 2 are Hertz pressures
    for (double qq : {0.05, 0.3, 0.9}) {
      ld lo = 0, hi = 1;
      for (int k = 0; k < 80; ++k) {
        const ld m = (lo + hi) / 2;
        ((2 / PI) * (std::asin(m) + m * std::sqrt(1 - m * m)) < qq ? lo : hi) = m;
      }
      const ld xh = (lo + hi) / 2;
      for (int flat = 0; flat < 2; ++flat) {
        const limit_result L = sliding_point(flat, flat ? 0.0 : 2.0, qq, true);
        std::printf("selftest q=%g %s: x0 = %.21Lf, Hertz %.21Lf, diff %.3Lg, unc %.3g, G(1)-1 %.3g, %.2fs\n", qq,
                    flat ? "flat b=0" : "power n=2", L.x0, xh, L.x0 - xh, L.unc, L.total_check, L.time);
      }
    }
    for (double n : {4.0}) {
      const limit_result L = sliding_point(false, n, 0.3, true);
      std::printf("power n=%g: x0 = %.21Lf, unc %.3g, G(1)-1 %.3g, %d its, %.2fs\n", n, L.x0, L.unc,
                  L.total_check, L.iterations, L.time);
    }
    for (double b : {0.5, 1 - 1e-6, 1 - 1e-12}) {
      const limit_result L = sliding_point(true, b, 0.3, true);
      std::printf("flat b=%.17g: x0 = %.21Lf, unc %.3g, G(1)-1 %.3g, %d its, %.2fs\n", b, L.x0, L.unc,
                  L.total_check, L.iterations, L.time);
    }
    return 0;
  }
  std::ofstream out(argv[1]);
  sweep_runner S{out, opt, 0, 0, 0, {}};
  S.header();
  const auto t_all = clk::now();
  const double q = 0.3;

  // orientation of the sliding stick point: which zone is a - x0 for sigma > 0
  // (q > 0), from the Hertz reference at sigma/fp0 = 30 (geometry-independent: the
  // pressures are symmetric); the Hertz sliding point x0 = G^-1(q) in closed form.
  bool d1_is_short = true;
  {
    const rres h = solve_reference(HS_GEOMETRY_HERTZ, 0, q, 30, 20);
    d1_is_short = h.d1 < h.d2;
    std::printf("orientation: sigma > 0, q > 0: d1 = a %s x0 (Hertz reference d1 = %.6Lg, d2 = %.6Lg)\n",
                d1_is_short ? "-" : "+", h.d1, h.d2);
  }
  std::vector<std::pair<std::pair<bool, double>, limit_result>> limit_cache;
  auto limit_truth = [&](bool flat, double par, double qq, double decay_w0, double decay_s0, double decay_c,
                         double s) {
    truth t;
    limit_result L;
    bool cached = false;
    for (const auto &e : limit_cache)
      if (e.first.first == flat && e.first.second == par) {
        L = e.second;
        cached = true;
      }
    if (!cached) {
      L = sliding_point(flat, par, qq);
      limit_cache.push_back({{flat, par}, L});
    }
    if (!cached)
      std::printf("sliding point %s %.17g q=%g: x0 = %.21Lf (+- %.2g, %d Newton steps, %.2fs)\n",
                  flat ? "flat" : "power", par, qq, L.x0, L.unc, L.iterations, L.time);
    if (!L.ok) return t;
    t.kind = "limit";
    t.d1 = d1_is_short ? 1 - L.x0 : 1 + L.x0;
    t.d2 = d1_is_short ? 1 + L.x0 : 1 - L.x0;
    const double dmin = double(std::min(t.d1, t.d2));
    // the quadrature's own error plus the stick width w(s) (NaN where no decay is known)
    double w = NAN;
    if (decay_c > 0) w = decay_w0 * std::exp(-decay_c * (s - decay_s0));
    t.unc = (L.unc + (std::isnan(w) ? 0 : w)) / dmin;
    if (std::isnan(w)) t.unc = -t.unc;  // negative: the width is not bounded here (see docs)
    return t;
  };

  // sigma sweeps: reference up to sigma_ref_max, the sliding point from sigma_lim_min;
  // both in the overlap (a cross-check row "truth-check")
  auto sigma_sweep = [&](const char *chart, geo g, double par) {
    std::vector<sweep_runner::point> pts;
    const bool flat = g.kind == HS_GEOMETRY_FLAT_ROUNDED;
    const int kmax = opt.quick ? 8 : 16;
    std::vector<std::pair<double, ld>> widths;  // (sigma, w) from the reference
    std::vector<truth> refs;
    for (int k = 0; k <= kmax; ++k) {
      const double s = std::pow(10.0, k / 4.0);
      truth t;
      if (s <= 60) {
        t = reference_truth(g.kind, par, q, s, opt.ref_budget);
        std::printf("truth %s sigma=%g: %s %s (%.2fs)\n", chart, s, t.kind, status_text(t.status), t.time);
        if (std::string(t.kind) == "reference") {
          const ld w = 2 - t.d1 - t.d2;
          if (w > 1e-17L) widths.push_back({s, w});
        }
      }
      refs.push_back(t);
    }
    double w0 = NAN, s0 = NAN, c = NAN;
    if (widths.size() >= 2) {
      const auto &A = widths[widths.size() - 2], &B = widths.back();
      c = double(std::log(A.second / B.second) / (B.first - A.first));
      w0 = double(B.second);
      s0 = B.first;
      std::printf("%s: stick width from the reference %.3Lg at sigma %g, decay ln w ~ -%.4f sigma\n", chart,
                  B.second, B.first, c);
    }
    for (int k = 0; k <= kmax; ++k) {
      const double s = std::pow(10.0, k / 4.0);
      truth t = refs[size_t(k)];
      if (s >= 30) {
        const truth l = limit_truth(flat, par, q, w0, s0, c, s);
        if (std::string(t.kind) == "reference" && std::string(l.kind) == "limit") {
          const double diff =
              double(std::max(std::fabs(l.d1 - t.d1) / t.d1, std::fabs(l.d2 - t.d2) / t.d2));
          S.out << chart << ",truth-check," << fmt(s, "%.17g") << "," << q << "," << fmt(s, "%.17g") << ","
                << (flat ? "flat-rounded" : "power-law") << "," << par << ",0,limit vs reference,ok,,,,,,,"
                << "limit," << fmtl(l.d1) << "," << fmtl(l.d2) << "," << fmt(std::fabs(l.unc), "%.3g") << ","
                << fmt(diff, "%.4g") << ",\n";
          std::printf("truth-check %s sigma=%g: limit vs reference %.3g (limit unc %.3g)\n", chart, s, diff,
                      l.unc);
        }
        if (std::string(t.kind) != "reference") t = l;
      }
      pts.push_back({s, g, q, s, t});
    }
    S.run(chart, "sigma", pts, true);
  };

  // ---- flat punch -----------------------------------------------------------
  {
    geo g;
    g.kind = HS_GEOMETRY_FLAT_ROUNDED;
    g.par = 0.5;
    sigma_sweep("flat", g, 0.5);
    // b_f/a -> 0 and -> 1 at sigma/fp0 = 1 (reference), and -> 1 at sigma/fp0 = 1000 (sliding point)
    std::vector<sweep_runner::point> to0, to1, to1big;
    std::vector<double> small = {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-12, 0};
    std::vector<double> near1 = {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-15};
    if (opt.quick) {
      small = {1e-2, 0};
      near1 = {1e-2, 1e-6};
    }
    for (double b : small) {
      geo gb = g;
      gb.par = b;
      to0.push_back({b, gb, q, 1.0, reference_truth(g.kind, b, q, 1.0, opt.ref_budget)});
    }
    for (double e : near1) {
      geo gb = g;
      gb.par = 1 - e;
      to1.push_back({e, gb, q, 1.0, reference_truth(g.kind, 1 - e, q, 1.0, opt.ref_budget)});
      to1big.push_back({e, gb, q, 1000.0, limit_truth(true, 1 - e, q, NAN, NAN, NAN, 1000)});
    }
    S.run("flat", "bf_to_0", to0, true);
    S.run("flat", "bf_to_1", to1, true);
    S.run("flat", "bf_to_1_sigma1000", to1big, true);
  }
  std::printf("flat done at %.0f s\n", seconds_since(t_all));

  // ---- power law ------------------------------------------------------------
  {
    geo g;
    g.kind = HS_GEOMETRY_POWER_LAW;
    g.par = 4;
    sigma_sweep("power", g, 4);
    // the sliding point costs 10-90 s per exponent here (long double pow, on this loaded 2-core
    // machine): a sparser grid at sigma 1000
    std::vector<double> ns = {1.1, 1.5, 2, 3, 5, 10, 20, 50, 100, 200, 500, 999, 999.9};
    std::vector<double> nsbig = {1.1, 2, 10, 100, 999.9};
    if (opt.quick) ns = nsbig = {1.5, 50};
    std::vector<sweep_runner::point> ex, exbig;
    for (double n : ns) {
      geo gn = g;
      gn.par = n;
      ex.push_back({n, gn, q, 1.0, reference_truth(g.kind, n, q, 1.0, opt.ref_budget)});
    }
    for (double n : nsbig) {
      geo gn = g;
      gn.par = n;
      exbig.push_back({n, gn, q, 1000.0, limit_truth(false, n, q, NAN, NAN, NAN, 1000)});
    }
    S.run("power", "exponent", ex, true);
    S.run("power", "exponent_sigma1000", exbig, true);
  }
  std::printf("power done at %.0f s\n", seconds_since(t_all));

  // ---- samples ----------------------------------------------------------------
  {
    std::vector<size_t> counts = {10, 30, 100, 300, 1000, 3000, 10000, 100000, 1000000};
    if (opt.quick) counts = {10, 1000};
    struct scene {
      const char *sweep;
      double q, s;
      bool flat;
    };
    const scene scenes[] = {{"hertz_q0.3_s1", 0.3, 1.0, false},
                            {"hertz_q0.3_s100", 0.3, 100.0, false},
                            {"hertz_near_sliding", 1 - 1e-6, 0.0, false},
                            {"flat0.5_q0.3_s1", 0.3, 1.0, true}};
    const hs::core::flat_rounded_pressure<double> fp(0.5);
    std::vector<std::vector<double>> xs(counts.size()), ps(counts.size()), fps(counts.size());
    for (size_t i = 0; i < counts.size(); ++i) {
      const size_t n = counts[i];
      xs[i].resize(n + 1);
      ps[i].resize(n + 1);
      fps[i].resize(n + 1);
      for (size_t k = 0; k <= n; ++k) {
        const double x = k == n ? 1.0 : -1.0 + 2.0 * double(k) / double(n);
        const double dm = 1 + x, dp = 1 - x;
        xs[i][k] = x;
        ps[i][k] = std::sqrt(dm * dp);
        fps[i][k] = (k == 0 || k == n) ? 0.0 : fp.phi(x, dm, dp) * std::sqrt(dm * dp);
      }
    }
    for (const auto &sc : scenes) {
      truth t = sc.flat ? reference_truth(HS_GEOMETRY_FLAT_ROUNDED, 0.5, sc.q, sc.s, opt.ref_budget)
                        : reference_truth(HS_GEOMETRY_HERTZ, 0, sc.q, sc.s, opt.ref_budget);
      if (std::string(t.kind) == "reference") {
        t.kind = sc.flat ? "samples-flat" : "hertz";
        t.unc = sc.flat ? NAN : 4 * std::numeric_limits<double>::epsilon();
      }
      std::vector<sweep_runner::point> pts;
      for (size_t i = 0; i < counts.size(); ++i) {
        geo g;
        g.kind = HS_GEOMETRY_SAMPLES;
        g.sx = &xs[i];
        g.sp = sc.flat ? &fps[i] : &ps[i];
        pts.push_back({double(counts[i]), g, sc.q, sc.s, t});
      }
      S.run("samples", sc.sweep, pts, false);
    }
  }
  std::printf("done: %d rows, %.0f s; claim (estimate / zone resolution) exceeded beyond the truth's "
              "uncertainty: %d; DEFAULT or AUTO failed where a truth exists: %d\n",
              S.rows, seconds_since(t_all), S.exceeded, S.auto_fail_ref_ok);
  for (const auto &n : S.notes) std::printf("%s\n", n.c_str());
  return 0;
}
