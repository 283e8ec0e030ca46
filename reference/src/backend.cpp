// Reference backend: tier dispatch and digit certification.
#include "halfslip/reference/backend.hpp"

#include <boost/multiprecision/mpfr.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "halfslip/core/general.hpp"
#include "halfslip/core/pressure.hpp"
#include "halfslip/core/status.hpp"

namespace hs { namespace reference {

// one factory per tier, each defined in its own generated translation unit;
// tiers.inc lists them (CMake option HALFSLIP_REF_TIERS)
#define HS_TIER(D) std::unique_ptr<tier_solution> make_tier_##D(const text_scene &, int);
#include "tiers.inc"
#undef HS_TIER

const std::vector<unsigned> &tiers() {
#define HS_TIER(D) D,
  static const std::vector<unsigned> t = {
#include "tiers.inc"
  };
#undef HS_TIER
  return t;
}

int max_digits() {
  const auto &t = tiers();
  return int(t[t.size() - 2]) - guard_digits;  // the top tier only checks
}

int max_digits(int geometry) {
  if (geometry == geometry_hertz) return max_digits();
  if (geometry != geometry_flat_rounded && geometry != geometry_power_law) return 0;
  // the largest work tier whose check tier is at most general_max_check_tier
  const auto &t = tiers();
  int cap = 0;
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if (t[i + 1] <= general_max_check_tier) cap = int(t[i]) - guard_digits;
  return cap;
}

int general_max_order(unsigned D) {
  // Orders accepted by the solver, measured (docs/reference.md): 128-512 at
  // 50 digits, 256-1024 at 120 (1024 near sliding, Q/fP = 0.99), 512-1024 at
  // 180 and 270. Allow 16x the digits (at least 1024): one or two doublings
  // beyond the largest measured.
  int n = 1024;
  while (n < 16 * int(D)) n *= 2;
  return n;
}

std::unique_ptr<tier_solution> solve_at(unsigned D, const text_scene &sc, int max_iterations) {
#define HS_TIER(DD) \
  if (D == DD) return make_tier_##DD(sc, max_iterations);
#include "tiers.inc"
#undef HS_TIER
  throw core::error(core::status::bad_option, "no such precision tier");
}

namespace {
// MPFR keeps per-thread caches (constants, exp/log tables) that it frees only
// when asked. Every public entry point releases the calling thread's caches
// on exit, so that threads the user creates and destroys do not leak them
// (recomputing a constant costs microseconds against a solve's milliseconds).
struct release_mpfr_thread_caches {
  ~release_mpfr_thread_caches() { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); }
};
}  // namespace

namespace {
// A decimal as a double for the start only: false unless it is a normal double
// or exactly zero (a value that underflows could change the canonical frame).
bool start_double(const std::string &s, double &v) {
  if (s.empty() || s.size() > 4096) return false;
  char *end = nullptr;
  v = std::strtod(s.c_str(), &end);
  if (end == nullptr || *end != 0 || !std::isfinite(v)) return false;
  if (std::isnormal(v)) return true;
  if (v != 0) return false;
  for (char c : s) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return false;
  }
  return true;
}

// The work tier's start (issue 16): the double solution of the same scene, whose
// canonical state is within ~1e-13 of the tier's root, so that Newton at the
// tier's precision needs about three steps (each doubling the digits) where it
// needed ten from the Hertz start. Any failure of the double solve (its own
// limits, NO_CONVERGENCE, bad input): no start, the tier's own starts answer.
void double_start(text_scene &sc) {
  double beta = 0, n = 0, q = 0, s = 0, a = 1, p0 = 1, f = 1, E = 1;
  if (!sc.P.empty() || !start_double(sc.q, q) || !start_double(sc.s, s) || !start_double(sc.a, a) ||
      !start_double(sc.p0, p0) || !start_double(sc.f, f) || !start_double(sc.Estar, E))
    return;
  try {
    std::unique_ptr<core::pressure_model<double>> pm;
    if (sc.geometry == geometry_flat_rounded) {
      if (!start_double(sc.flat_over_a, beta)) return;
      pm.reset(new core::flat_rounded_pressure<double>(beta));
    } else if (sc.geometry == geometry_power_law) {
      if (!start_double(sc.exponent, n)) return;
      pm.reset(new core::power_law_pressure<double>(n));
    } else {
      return;
    }
    core::general_scene<double> g;
    g.a = a;
    g.p0 = p0;
    g.f = f;
    g.Estar = E;
    g.q = q;
    g.s = s;
    const core::general_solution<double> sol = core::solve_general(*pm, g);
    if (sol.reg == core::regime::stuck) return;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17e", sol.reg == core::regime::opposite_sign ? -sol.delta1 : sol.delta1);
    sc.start_x1 = buf;
    std::snprintf(buf, sizeof buf, "%.17e", sol.log_width);
    sc.start_ln_e = buf;
    sc.start_order = 0;
  } catch (const std::exception &) {
    sc.start_x1.clear();
    sc.start_ln_e.clear();
  }
}
}  // namespace

solution::solution(const text_scene &sc, int digits, int max_iterations) : digits_(digits) {
  release_mpfr_thread_caches on_exit;
  if (digits < 1 || digits > max_digits())
    throw core::error(core::status::bad_option, "digits out of range (1 .. hs_ref_max_digits())");
  if (sc.geometry != geometry_hertz && digits > max_digits(sc.geometry)) {
    if (max_digits(sc.geometry) == 0) throw core::error(core::status::bad_geometry, "unknown geometry");
    throw core::error(core::status::bad_option,
                      "digits above the limit for non-Hertz geometries (hs_ref_max_digits_geometry())");
  }
  const auto &t = tiers();
  size_t i = 0;
  while (int(t[i]) < digits + guard_digits) ++i;
  if (sc.geometry == geometry_hertz || !sc.start_x1.empty()) {
    work_ = solve_at(t[i], sc, max_iterations);
    check_ = solve_at(t[i + 1], sc, max_iterations);
    return;
  }
  // Non-Hertz (issue 16): the work tier from the double solution, the check tier
  // from the work tier's state and Newton order (its order control still validates
  // the order at twice it, and its tolerances are its own: the start changes the
  // path, not the root; a start from which Newton fails falls back to the usual ones)
  text_scene w = sc;
  double_start(w);
  work_ = solve_at(t[i], w, max_iterations);
  text_scene c = sc;
  if (!work_->general_start(c.start_x1, c.start_ln_e, c.start_order)) {
    c.start_x1.clear();
    c.start_ln_e.clear();
    c.start_order = 0;
  }
  check_ = solve_at(t[i + 1], c, max_iterations);
}

namespace {
using big = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<HS_REF_TOP_TIER + 20>,
                                          boost::multiprecision::et_off>;
}

int agreeing_digits(const std::string &a, const std::string &b, int cap) {
  release_mpfr_thread_caches on_exit;
  // Largest k <= cap with |a - b| <= 0.5 ulp of b at k significant digits,
  // i.e. a is b correctly rounded to k digits (up to a tie).
  const big x(a), y(b);
  if (x == y) return cap;
  if (y == 0) return 0;
  const big err = abs(x - y);
  const big e = floor(log10(abs(y)));  // exponent of b
  const big k = floor(e + 1 - log10(2 * err));
  if (k < 0) return 0;
  return k > cap ? cap : int(k.convert_to<long>());
}

certified solution::certify(const std::string &work, const std::string &check) const {
  return {work, agreeing_digits(work, check, digits_)};
}

certified solution::value(quantity q) const {
  release_mpfr_thread_caches on_exit;
  return certify(work_->value(q, digits_), check_->value(q, int(check_->digits10())));
}

std::string solution::raw(quantity q, bool check) const {
  release_mpfr_thread_caches on_exit;
  const auto &t = check ? check_ : work_;
  return t->value(q, int(t->digits10()));
}

certified solution::eval(point_eval what, const std::string &x) const {
  release_mpfr_thread_caches on_exit;
  return certify(work_->eval(what, x, digits_), check_->eval(what, x, int(check_->digits10())));
}

certified solution::stress(int body, const std::string &bulk2, stress_component c, const std::string &x,
                           const std::string &y) const {
  release_mpfr_thread_caches on_exit;
  return certify(work_->stress(body, bulk2, c, x, y, digits_), check_->stress(body, bulk2, c, x, y, int(check_->digits10())));
}

}}  // namespace hs::reference
