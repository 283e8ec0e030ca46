// halfslip C ABI: the model driver (docs/models.md). hs_solve and
// hs_solve_geometry validate their input and call solve_models, which runs
// the requested model or, for HS_MODEL_AUTO, the cheapest model whose error
// estimate (core/select.hpp) meets the tolerance.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "halfslip/halfslip.h"
#include "solution.hpp"

namespace hs { namespace capi {

namespace {
// digits asked of the reference backend when it stands in for double: 17
// are needed for a correctly rounded double, the rest is margin so that
// certification (which compares with a run one tier up) is never the limit
constexpr int reference_digits = 30;
}  // namespace

std::string exact_decimal(double v) {
  // glibc prints the exact binary value; 800 significant digits cover every
  // double (the longest exact expansion, of the smallest normal, has 715)
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%.800e", v);
  std::string s(buf);
  const size_t e = s.find('e');
  std::string mant = s.substr(0, e), ex = s.substr(e);
  while (!mant.empty() && mant.back() == '0') mant.pop_back();
  if (!mant.empty() && mant.back() == '.') mant.pop_back();
  return mant + ex;
}

reference::text_scene reference_input::text() const {
  reference::text_scene t;
  t.a = exact_decimal(scene.a);
  t.p0 = exact_decimal(scene.p0);
  t.f = exact_decimal(scene.f);
  t.Estar = exact_decimal(scene.Estar);
  t.q = exact_decimal(scene.q);
  t.s = exact_decimal(scene.s);
  t.geometry = geometry;
  if (geometry == HS_GEOMETRY_FLAT_ROUNDED) t.flat_over_a = exact_decimal(parameter);
  if (geometry == HS_GEOMETRY_POWER_LAW) t.exponent = exact_decimal(parameter);
  return t;
}

reference_double::reference_double(const reference::text_scene &t, const core::general_scene<double> &sc,
                                   int max_iterations)
    : scene(sc) {
  sol_.reset(new reference::solution(t, reference_digits, max_iterations));
  reg = core::regime(sol_->regime());
  iterations = sol_->iterations();
  dir1_ = sol_->dir1();
  dir2_ = sol_->dir2();
  using q = reference::quantity;
  b1_ = take(sol_->value(q::b1));
  b2_ = take(sol_->value(q::b2));
  d1_ = take(sol_->value(q::d1));
  d2_ = take(sol_->value(q::d2));
}

double reference_double::take(const reference::certified &c) const {
  // a zero is exact; anything else needs 17 certified digits to round correctly
  const double v = std::strtod(c.text.c_str(), nullptr);
  require(v == 0 || c.digits >= 17, core::status::no_convergence,
          "reference result could not be certified to double precision");
  require(std::isfinite(v), core::status::overflow, "result not representable");
  return v;
}

double reference_double::eval(reference::point_eval what, double x) const {
  return take(sol_->eval(what, exact_decimal(x)));
}

namespace {

const core::pressure_model<double> &pressure_of(hs_solution &h) {
  if (!h.model) h.model = std::make_shared<core::hertz_pressure<double>>();
  return *h.model;
}

// The model's estimate into the handle: the relative error of the resolved
// zones, the resolution and the number of zones at or below it (issue 13).
void take_estimate(hs_solution &h, const core::error_estimate<double> &e) {
  h.error_estimate = e.value();
  h.zone_resolution = e.resolution;
  h.unresolved = e.unresolved;
}

void run_asymptotic(hs_solution &h, const core::general_scene<double> &sc) {
  const auto &pm = pressure_of(h);
  // issue 13: where the expansion's first correction is as large as a zone, its
  // zones may be anywhere (the truth 1.97 a for a model zone of 0.018 a): no answer
  const auto e = core::asymptotic_estimate(pm, sc);
  if (core::asymptotic_bounds_nothing(e))
    throw core::error(core::status::not_applicable,
                      "asymptotic model does not apply: its first correction is as large as a slip zone, so it "
                      "cannot bound the zones (use the quadrature or the closed forms)");
  h.solution.emplace<core::edge_solution<double>>(pm, sc);
  h.model_used = HS_MODEL_ASYMPTOTIC;
  take_estimate(h, e);
}

void run_closed_form(hs_solution &h, const core::general_scene<double> &sc, const request &r) {
  core::solve_options<double> o;
  o.max_iterations = r.max_iterations;
  o.rtol = r.rtol;
  const auto &s = h.solution.emplace<core::hertz_solution<double>>(core::solve_hertz<double>(sc, o));
  h.model_used = HS_MODEL_CLOSED_FORM;
  take_estimate(h, core::closed_form_estimate(s.d1() / sc.a, s.d2() / sc.a, sc.q, sc.s, s.width));
  // rtol > 0 relaxes the quadrature of the opposite-sign slip and energies
  if (16 * r.rtol > h.error_estimate) h.error_estimate = 16 * r.rtol;
}

void run_quadrature(hs_solution &h, const core::general_scene<double> &sc, int max_iterations, double rt) {
  core::general_options<double> o;
  o.max_iterations = max_iterations;
  o.rtol = rt;
  const auto &pm = pressure_of(h);
  auto &s = h.solution.emplace<core::general_solution<double>>(core::solve_general<double>(pm, sc, o));
  h.model_used = HS_MODEL_QUADRATURE;
  const auto e = core::quadrature_estimate(rt, s.d1() / sc.a, s.d2() / sc.a, s.width, sc.q, pm.accuracy_eps(),
                                           s.conditioning);
  take_estimate(h, e);
  s.state_rtol = e.energy;  // the energies' orders need not agree beyond the state's error
}

// The quadrature, or the asymptotic edge model where that is more accurate:
// where the quadrature cannot resolve the slip zones (not_applicable: both
// narrower than 256 eps a) or its estimate, which grows like eps/d for small
// zones, is larger than the asymptotic one, which shrinks with them (issue 13:
// the default model must not return a result the asymptotic model beats by
// orders of magnitude, or a spurious one). True when the asymptotic model was taken.
bool run_quadrature_or_asymptotic(hs_solution &h, const core::general_scene<double> &sc, int max_iterations,
                                  double rt) {
  if (sc.q == 0 && sc.s == 0) {
    run_quadrature(h, sc, max_iterations, rt);  // stuck
    return false;
  }
  try {
    try {
      run_quadrature(h, sc, max_iterations, rt);
    } catch (const core::error &e) {
      // a relaxed tolerance can leave Newton without a path that full precision
      // finds (the estimate sweep: flat punch near sliding, rtol 1e-10)
      if (e.code() != core::status::no_convergence || rt == 0) throw;
      run_quadrature(h, sc, max_iterations, 0);
    }
  } catch (const core::error &e) {
    if (e.code() != core::status::not_applicable) throw;
    run_asymptotic(h, sc);
    return true;
  }
  const double quad = h.error_estimate;
  const double quad_resolution = h.zone_resolution;
  const int quad_unresolved = h.unresolved;
  const auto ae = core::asymptotic_estimate(pressure_of(h), sc);
  const double est = ae.value();
  // only where the asymptotic model is itself accurate: at the regime boundary
  // both estimates are large, and the asymptotic one does not bound its error
  // there (the sweep: estimate 1e5, error 1e10, a wrong slip direction); and
  // not where it would leave a zone unresolved that the quadrature resolves
  if (!(est < quad) || !(est <= 1e-6) || ae.unresolved > quad_unresolved) return false;
  auto kept = std::move(h.solution);
  try {
    run_asymptotic(h, sc);
    return true;
  } catch (const core::error &e) {
    if (e.code() != core::status::not_applicable) throw;
    h.solution = std::move(kept);  // zones cover the contact: keep the quadrature
    h.model_used = HS_MODEL_QUADRATURE;
    h.error_estimate = quad;
    h.zone_resolution = quad_resolution;
    h.unresolved = quad_unresolved;
    return false;
  }
}

void run_reference(hs_solution &h, const core::general_scene<double> &sc, const request &r,
                   const reference_input &ref) {
  require(ref.available, core::status::bad_geometry,
          "the reference backend supports the Hertz, flat-rounded and power-law geometries only");
  h.solution.emplace<reference_double>(ref.text(), sc, r.max_iterations < 1000 ? 1000 : r.max_iterations);
  h.model_used = HS_MODEL_REFERENCE;
  h.error_estimate = std::ldexp(1.0, -53);
  // certified relative values: a zone is resolved unless it rounds to 0
  // (a scene exactly on the regime boundary, or below the double range)
  const auto &s = std::get<reference_double>(h.solution);
  h.zone_resolution = std::numeric_limits<double>::denorm_min();
  h.unresolved = int(core::zone_unresolved(s.d1() / sc.a, h.zone_resolution)) +
                 int(core::zone_unresolved(s.d2() / sc.a, h.zone_resolution));
  if (sc.q == 0 && sc.s == 0) h.zone_resolution = 0, h.unresolved = 0;  // stuck: exact
}

// Issue 16: the a-posteriori estimate of a closed-form or quadrature result
// (core/select.hpp, a_posteriori_estimate): the same model solved again in long
// double, the double result's distance to it plus the long double's own
// worst-case bound. Taken where it is below the worst-case estimate (both bound
// the error; the smaller is kept, with its resolution). Only HS_MODEL_AUTO asks
// for it, and only when the worst-case estimate misses the tolerance: it costs
// a long double solve and both results' energies (microseconds for Hertz, about
// a millisecond for the general path), where the alternative is the reference
// backend (milliseconds to seconds). The geometries with a long double pressure
// of their own: Hertz, flat-rounded, power law (kind: HS_GEOMETRY_*; -1 other).
bool refine_estimate(hs_solution &h, int kind, double parameter, int max_iterations) {
  core::error_estimate<double> ap;
  try {
    if (h.model_used == HS_MODEL_CLOSED_FORM) {
      const auto *s = std::get_if<core::hertz_solution<double>>(&h.solution);
      if (!s) return false;
      ap = core::a_posteriori_closed_form(*s, max_iterations);
    } else if (h.model_used == HS_MODEL_QUADRATURE) {
      const auto *s = std::get_if<core::general_solution<double>>(&h.solution);
      if (!s || s->rtol != 0) return false;
      std::unique_ptr<core::pressure_model<long double>> pm;
      if (kind == HS_GEOMETRY_HERTZ) pm.reset(new core::hertz_pressure<long double>());
      else if (kind == HS_GEOMETRY_FLAT_ROUNDED) pm.reset(new core::flat_rounded_pressure<long double>(parameter));
      else if (kind == HS_GEOMETRY_POWER_LAW) pm.reset(new core::power_law_pressure<long double>(parameter));
      else return false;
      ap = core::a_posteriori_quadrature(*s, *pm, max_iterations);
    } else {
      return false;
    }
  } catch (const std::exception &) {
    return false;  // the wider solve failed (any reason): keep the worst-case estimate
  }
  if (!(ap.value() < h.error_estimate) || ap.unresolved > h.unresolved) return false;
  take_estimate(h, ap);
  return true;
}

// HS_MODEL_AUTO: cheapest first; each model is accepted when its estimate
// meets the tolerance. rtol = 0: the most accurate double model.
void run_auto(hs_solution &h, bool hertz, const core::general_scene<double> &sc, const request &r,
              const reference_input &ref) {
  const double tol = r.rtol;
  if (tol > 0 && (sc.q != 0 || sc.s != 0)) {
    const auto ae = core::asymptotic_estimate(pressure_of(h), sc);
    if (ae.value() <= tol && ae.unresolved == 0) {
      try {
        run_asymptotic(h, sc);
        return;
      } catch (const core::error &e) {
        if (e.code() != core::status::not_applicable) throw;  // zones cover the contact: go on
      }
    }
  }
  if (hertz) {
    request cf = r;
    cf.rtol = 0;
    try {
      run_closed_form(h, sc, cf);
    } catch (const core::error &e) {
      // double cannot answer (issue 13: the reference solves what is left
      // of the domain); the result says it took the reference route
      if ((e.code() != core::status::overflow && e.code() != core::status::no_convergence) || !ref.available) throw;
      run_reference(h, sc, r, ref);
      return;
    }
  } else {
    const double rt = core::quadrature_tolerance(tol, sc);
    try {
      if (!run_quadrature_or_asymptotic(h, sc, r.max_iterations, rt) && h.error_estimate > tol && rt > 0)
        run_quadrature_or_asymptotic(h, sc, r.max_iterations, 0);
    } catch (const core::error &e) {
      // double cannot answer near sliding (issue 13: the general solver within
      // ~1e-10 of it, as for Hertz above): the reference route, which the result
      // reports (HS_MODEL_REFERENCE). Only there (1 - |Q/fP| < 1e-6), where the
      // reference finishes (the near-sliding scenes of docs/models.md: 5 to 50 s
      // of CPU); elsewhere the status is passed on, as before: the reference does
      // not finish for the power law near n = 1 at large sigma (n = 1.1, Q/fP = 0.3,
      // sigma/fp0 = 10 ran past 400 s on that route; docs/benchmarks.md)
      const bool near_sliding = std::abs(sc.q) > 1 - 1e-6;
      if ((e.code() != core::status::overflow && e.code() != core::status::no_convergence) || !ref.available ||
          !near_sliding)
        throw;
      run_reference(h, sc, r, ref);
      return;
    }
  }
  // a relative tolerance is met only where every zone is resolved (issue 13:
  // at the regime boundary a zone below the resolution has no relative error
  // bound at all; the reference resolves it)
  if (tol == 0 || (h.error_estimate <= tol && h.unresolved == 0)) return;
  // issue 16: the worst-case estimate misses rtol; the a-posteriori one may not
  const int kind = hertz ? HS_GEOMETRY_HERTZ : ref.available ? ref.geometry : -1;
  if (refine_estimate(h, kind, ref.parameter, r.max_iterations) && h.error_estimate <= tol && h.unresolved == 0)
    return;
  if (ref.available) {
    run_reference(h, sc, r, ref);
    return;
  }
  throw core::error(core::status::tolerance, "no model meets the requested tolerance");
}

}  // namespace

void solve_models(hs_solution &h, bool hertz, const core::general_scene<double> &sc, const request &r,
                  const reference_input &ref) {
  switch (r.model) {
    case HS_MODEL_DEFAULT:
      if (hertz) run_closed_form(h, sc, r);
      else run_quadrature_or_asymptotic(h, sc, r.max_iterations, r.rtol);
      return;
    case HS_MODEL_AUTO: run_auto(h, hertz, sc, r, ref); return;
    case HS_MODEL_ASYMPTOTIC: run_asymptotic(h, sc); return;
    case HS_MODEL_CLOSED_FORM:
      require(hertz, core::status::bad_geometry, "closed forms exist for the Hertz geometry only");
      run_closed_form(h, sc, r);
      return;
    case HS_MODEL_QUADRATURE: run_quadrature(h, sc, r.max_iterations, r.rtol); return;
    case HS_MODEL_REFERENCE: run_reference(h, sc, r, ref); return;
    default: throw core::error(core::status::bad_option, "unknown model");
  }
}

}}  // namespace hs::capi
