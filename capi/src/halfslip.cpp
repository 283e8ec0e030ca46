// halfslip C ABI: extern "C" shims over the templated core, instantiated on
// double. Every entry point runs inside guard(): no C++ exception crosses the
// ABI, every failure becomes an HS_ERR_* status, outputs are untouched on error.
#include "halfslip/halfslip.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <initializer_list>
#include <new>
#include <vector>

#include "halfslip/core/asymptotic.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/reference/backend.hpp"
#include "solution.hpp"
#include "halfslip/core/fields.hpp"
#include "halfslip/core/history_fields.hpp"
#include "halfslip/core/ray_fields.hpp"
#include "halfslip/reference/ray_history.hpp"

namespace core = hs::core;

static_assert(HS_OK == int(core::status::ok), "status table");
static_assert(HS_ERR_NULL_POINTER == int(core::status::null_pointer), "status table");
static_assert(HS_ERR_STRUCT_SIZE == int(core::status::struct_size), "status table");
static_assert(HS_ERR_NOT_FINITE == int(core::status::not_finite), "status table");
static_assert(HS_ERR_BAD_SIZE == int(core::status::bad_size), "status table");
static_assert(HS_ERR_BAD_FRICTION == int(core::status::bad_friction), "status table");
static_assert(HS_ERR_GROSS_SLIDING == int(core::status::gross_sliding), "status table");
static_assert(HS_ERR_BAD_GEOMETRY == int(core::status::bad_geometry), "status table");
static_assert(HS_ERR_POINT_OUTSIDE == int(core::status::point_outside), "status table");
static_assert(HS_ERR_BUFFER_TOO_SMALL == int(core::status::buffer_too_small), "status table");
static_assert(HS_ERR_NO_CONVERGENCE == int(core::status::no_convergence), "status table");
static_assert(HS_ERR_BAD_OPTION == int(core::status::bad_option), "status table");
static_assert(HS_ERR_OUT_OF_MEMORY == int(core::status::out_of_memory), "status table");
static_assert(HS_ERR_INTERNAL == int(core::status::internal), "status table");
static_assert(HS_ERR_OVERFLOW == int(core::status::overflow), "status table");
static_assert(HS_ERR_BAD_NUMBER == int(core::status::bad_number), "status table");
static_assert(HS_ERR_TOLERANCE == int(core::status::tolerance), "status table");
static_assert(HS_ERR_NOT_APPLICABLE == int(core::status::not_applicable), "status table");

struct hs_ref_solution {
  hs::reference::solution sol;
};

namespace {

using hs::capi::guard;

using hs::capi::require;

// hs_*_default: a zeroed struct with its struct_size, then set(s); written
// to *out only when out is not NULL.
template <class S, class F> int fill_default(S *out, F &&set) {
  if (!out) return HS_ERR_NULL_POINTER;
  S s;
  std::memset(&s, 0, sizeof s);
  s.struct_size = sizeof(S);
  set(s);
  *out = s;
  return HS_OK;
}

// Validated solver options (NULL: the defaults). A 0.2 caller passes the
// size without the model field and gets HS_MODEL_DEFAULT.
hs::capi::request read_options(const hs_options *opts) {
  hs::capi::request r;
  if (!opts) return r;
  const size_t n = opts->struct_size;
  require(n == sizeof(hs_options) || n == offsetof(hs_options, model), core::status::struct_size,
          "options struct_size");
  require(opts->max_iterations >= 1 && opts->max_iterations <= 100000, core::status::bad_option,
          "max_iterations out of range");
  r.model = n == sizeof(hs_options) ? opts->model : HS_MODEL_DEFAULT;
  require(r.model >= HS_MODEL_DEFAULT && r.model <= HS_MODEL_REFERENCE, core::status::bad_option, "unknown model");
  require(core::tolerance_in_range(opts->rtol, r.model == HS_MODEL_AUTO), core::status::bad_option,
          "rtol out of range");
  r.max_iterations = opts->max_iterations;
  r.rtol = opts->rtol;
  return r;
}

// The scene as the reference backend reads it (written out on use: reference_input::text).
hs::capi::reference_input reference_of(const core::general_scene<double> &sc) {
  hs::capi::reference_input in;
  in.available = true;
  in.scene = sc;
  return in;
}

core::hertz_scene<double> to_core(const hs_scene *sc) {
  require(sc != nullptr, core::status::null_pointer, "scene is NULL");
  require(sc->struct_size == sizeof(hs_scene), core::status::struct_size, "scene struct_size");
  require(sc->geometry == HS_GEOMETRY_HERTZ, core::status::bad_geometry, "unknown geometry");
  core::hertz_scene<double> c;
  c.a = sc->a;
  c.p0 = sc->p0;
  c.f = sc->f;
  c.Estar = sc->E_star;
  c.q = sc->Q_over_fP;
  c.s = sc->sigma_over_fp0;
  core::validate(c);
  return c;
}

// Evaluate fn at every point into a scratch vector first, so that out is
// untouched unless every point succeeds.
template <class Fn> int eval_points(const hs_solution *sol, size_t n, const double *x, double *out, Fn fn) {
  return guard([&] {
    require(sol != nullptr, core::status::null_pointer, "solution is NULL");
    if (n == 0) return;
    require(x != nullptr && out != nullptr, core::status::null_pointer, "point or output array is NULL");
    std::vector<double> tmp(n);
    sol->visit([&](const auto &s) {  // one dispatch for all the points
      const double a = double(s.scene.a);
      for (size_t i = 0; i < n; ++i) {
        require(std::isfinite(x[i]), core::status::not_finite, "evaluation point is NaN or infinite");
        require(std::fabs(x[i]) <= a, core::status::point_outside, "evaluation point outside |x| <= a");
      }
      for (size_t i = 0; i < n; ++i) {
        tmp[i] = fn(s, x[i]);
        require(std::isfinite(tmp[i]), core::status::overflow, "result not representable");
      }
    });
    std::memcpy(out, tmp.data(), n * sizeof(double));
  });
}

}  // namespace

namespace hs { namespace capi {

// The sampled pressure of n samples (x, p) on a contact of half-width a, with
// the rules of HS_GEOMETRY_SAMPLES; where (if not null) receives the index of
// the sample a broken rule is about (n: the samples as a whole).
std::shared_ptr<const core::sampled_pressure<double>> samples_model(size_t n, const double *x, const double *p,
                                                                    double a, size_t *where) {
  if (where) *where = n;
  require(x != nullptr && p != nullptr, core::status::null_pointer, "sample arrays are NULL");
  require(n >= 6 && n <= 10000000, core::status::bad_geometry, "need at least 6 pressure samples");
  for (size_t i = 0; i < n; ++i) {
    if (std::isfinite(x[i]) && std::isfinite(p[i])) continue;
    if (where) *where = i;
    throw core::error(core::status::not_finite, "sample is not finite");
  }
  return std::make_shared<core::sampled_pressure<double>>(std::vector<double>(x, x + n), std::vector<double>(p, p + n),
                                                          a, where);
}

// The pressure model of a geometry (not Hertz) and the canonical scene: a, f,
// E*, loads from the scene; p0 from the scene, or from the pressure for samples
// and callbacks.
std::shared_ptr<const core::pressure_model<double>> pressure_of_geometry(const hs_scene &scn, const hs_geometry &g,
                                                                         core::general_scene<double> &sc) {
  const hs_scene *scene = &scn;
  const hs_geometry *geometry = &g;
  std::shared_ptr<const core::pressure_model<double>> model;
  require(scene->struct_size == sizeof(hs_scene), core::status::struct_size, "scene struct_size");
  sc.a = scene->a;
  sc.p0 = scene->p0;
  sc.f = scene->f;
  sc.Estar = scene->E_star;
  sc.q = scene->Q_over_fP;
  sc.s = scene->sigma_over_fp0;
  require(std::isfinite(sc.a) && sc.a > 0, std::isfinite(sc.a) ? core::status::bad_size : core::status::not_finite,
          "contact half-width a must be finite and > 0");
  switch (geometry->kind) {
    case HS_GEOMETRY_FLAT_ROUNDED:
      require(std::isfinite(geometry->flat_over_a), core::status::not_finite, "flat_over_a is not finite");
      model = std::make_shared<core::flat_rounded_pressure<double>>(geometry->flat_over_a);
      break;
    case HS_GEOMETRY_POWER_LAW:
      require(std::isfinite(geometry->exponent), core::status::not_finite, "exponent is not finite");
      model = std::make_shared<core::power_law_pressure<double>>(geometry->exponent);
      break;
    case HS_GEOMETRY_SAMPLES: {
      auto m = samples_model(geometry->n_samples, geometry->sample_x, geometry->sample_p, sc.a, nullptr);
      sc.p0 = m->p0();
      model = m;
      break;
    }
    case HS_GEOMETRY_CALLBACK: {
      require(geometry->pressure != nullptr, core::status::null_pointer, "pressure callback is NULL");
      double (*fn)(double, void *) = geometry->pressure;
      void *user = geometry->user;
      auto m = std::make_shared<core::callback_pressure<double>>(
          [fn, user](const double &x) {
            const double v = fn(x, user);
            if (!std::isfinite(v)) throw core::error(core::status::not_finite, "pressure callback returned NaN/Inf");
            return v;
          },
          sc.a);
      sc.p0 = m->p0();
      model = m;
      break;
    }
    default: throw core::error(core::status::bad_geometry, "unknown geometry");
  }
  return model;
}

}}  // namespace hs::capi

namespace hs { namespace capi {
// hs_solve_batch checks its options once (batch.cpp)
int validate_options(const hs_options *opts) {
  return guard([&] { read_options(opts); });
}
}}  // namespace hs::capi

namespace {
// The contact state of each kind of solution (issue 15; C++ overloads, so
// outside extern "C")
core::contact_state<double> state_of_solution(const core::hertz_solution<double> &s, double bulk2) {
  return core::hertz_state(s, bulk2);
}
core::contact_state<double> state_of_solution(const core::general_solution<double> &s, double bulk2) {
  return core::general_state_of(s, bulk2);
}
core::contact_state<double> state_of_solution(const hs::capi::history_state &s, double bulk2) {
  return core::history_contact_state<double>(s.hist, s.nsteps(), s.scene.a, s.scene.p0, s.scene.f, bulk2);
}
core::contact_state<double> state_of_solution(const hs::capi::static_state &s, double bulk2) {
  return core::static_contact_state<double>(s.hist, s.scene.a, s.scene.p0, s.scene.f, bulk2);
}
template <class S> core::contact_state<double> state_of_solution(const S &s, double bulk2) {
  return core::make_state<double>(s, bulk2);
}
core::contact_state<double> state_of(const hs_solution &h, double bulk2);
// issue 14: a state along one ray, the sum of its monotonic parts' states
core::contact_state<double> state_of_solution(const hs::capi::ray_state &s, double bulk2) {
  std::vector<core::superposed_part<double>> parts;
  for (const auto &p : s.parts()) parts.push_back({double(p.coef), state_of(*p.sol, bulk2)});
  return core::superposed_state<double>(std::move(parts), s.scene.s * s.scene.f * s.scene.p0, bulk2, -s.b2(),
                                        s.b1());
}

// issue 15: the contact state of a solution (bulk2: stress the pad carries)
core::contact_state<double> state_of(const hs_solution &h, double bulk2) {
  auto st = h.visit([&](const auto &s) { return state_of_solution(s, bulk2); });
  // the panels do not depend on bulk2: one set per solution, made on first use
  std::call_once(h.panels_once, [&] {
    if (hs::core::needs_panels(st)) h.panels = hs::core::make_panels(st);
  });
  st.panels = h.panels;
  return st;
}

// The one solve behind hs_solve and hs_solve_geometry: the Hertz geometry
// (geometry NULL; the scene carries it) or another geometry.
hs_solution *solve_scene(const hs_scene &scene, const hs_geometry *geometry, const hs_options *opts) {
  core::general_scene<double> sc;
  hs::capi::request req;
  hs::capi::reference_input ref;
  auto h = std::make_unique<hs_solution>();
  if (!geometry) {
    sc = to_core(&scene);  // hertz_scene and general_scene are one type (core/hertz.hpp)
    req = read_options(opts);
    if (req.model == HS_MODEL_AUTO || req.model == HS_MODEL_REFERENCE) ref = reference_of(sc);
  } else {
    req = read_options(opts);
    h->model = hs::capi::pressure_of_geometry(scene, *geometry, sc);
    if ((req.model == HS_MODEL_AUTO || req.model == HS_MODEL_REFERENCE) &&
        (geometry->kind == HS_GEOMETRY_FLAT_ROUNDED || geometry->kind == HS_GEOMETRY_POWER_LAW)) {
      ref = reference_of(sc);
      ref.geometry = geometry->kind;
      ref.parameter = geometry->kind == HS_GEOMETRY_FLAT_ROUNDED ? geometry->flat_over_a : geometry->exponent;
    }
  }
  hs::capi::solve_models(*h, !geometry, sc, req, ref);
  return h.release();
}
}  // namespace

extern "C" {

int hs_version(int *major, int *minor, int *patch) {
  if (!major || !minor || !patch) return HS_ERR_NULL_POINTER;
  *major = HS_VERSION_MAJOR;
  *minor = HS_VERSION_MINOR;
  *patch = HS_VERSION_PATCH;
  return HS_OK;
}

#define HS_STR_(x) #x
#define HS_STR(x)  HS_STR_(x)
const char *hs_version_string(void) {
  return HS_STR(HS_VERSION_MAJOR) "." HS_STR(HS_VERSION_MINOR) "." HS_STR(HS_VERSION_PATCH);
}

const char *hs_strerror(int status) {
  switch (status) {
    case HS_OK: return "success";
    case HS_ERR_NULL_POINTER: return "a required pointer argument is NULL";
    case HS_ERR_STRUCT_SIZE:
      return "struct_size field is not sizeof the struct (initialise it with its hs_*_default function)";
    case HS_ERR_NOT_FINITE: return "an input value is NaN or infinite";
    case HS_ERR_BAD_SIZE: return "a size or modulus (a, p0, E*, P, R) is not strictly positive";
    case HS_ERR_BAD_FRICTION: return "the friction coefficient f is not strictly positive";
    case HS_ERR_GROSS_SLIDING: return "|Q| >= fP: the contact slides as a whole (no stick zone)";
    case HS_ERR_BAD_GEOMETRY: return "unknown geometry or invalid geometry parameter";
    case HS_ERR_POINT_OUTSIDE: return "an evaluation point lies outside the contact |x| <= a";
    case HS_ERR_BUFFER_TOO_SMALL: return "an output buffer is too small";
    case HS_ERR_NO_CONVERGENCE: return "the iteration for the stick-zone boundaries did not converge";
    case HS_ERR_BAD_OPTION: return "an option value is out of range";
    case HS_ERR_OUT_OF_MEMORY: return "out of memory";
    case HS_ERR_INTERNAL: return "internal error in halfslip (please report)";
    case HS_ERR_OVERFLOW: return "a result is not representable in double precision (overflow)";
    case HS_ERR_BAD_NUMBER: return "a decimal number string could not be parsed";
    case HS_ERR_NOT_APPLICABLE:
      return "the requested model or function does not apply (e.g. asymptotic slip zones that cover the contact; "
             "energies, work or B_x of a load-history state; a slip zone opening inside the stick zone of a load "
             "history; a certified history off one ray)";
    case HS_ERR_TOLERANCE:
      return "no model meets the requested tolerance in double precision (use the reference backend, hs_ref_solve)";
    default: return "unknown halfslip status code";
  }
}

namespace {
// The model names, indexed by HS_MODEL_* (the only copy: the CLI and the
// bindings ask hs_model_name / hs_model_from_name).
const char *const model_names[] = {"default", "auto", "asymptotic", "closed-form", "quadrature", "reference"};
static_assert(HS_MODEL_DEFAULT == 0 && HS_MODEL_AUTO == 1 && HS_MODEL_ASYMPTOTIC == 2 && HS_MODEL_CLOSED_FORM == 3 &&
                  HS_MODEL_QUADRATURE == 4 && HS_MODEL_REFERENCE == 5 &&
                  sizeof model_names / sizeof *model_names == HS_MODEL_REFERENCE + 1,
              "model name table");
}  // namespace

const char *hs_model_name(int model) {
  return model >= HS_MODEL_DEFAULT && model <= HS_MODEL_REFERENCE ? model_names[model] : nullptr;
}

int hs_model_from_name(const char *name, int *model) {
  return guard([&] {
    require(name != nullptr && model != nullptr, core::status::null_pointer, "NULL argument");
    for (int m = HS_MODEL_DEFAULT; m <= HS_MODEL_REFERENCE; ++m)
      if (std::strcmp(name, model_names[m]) == 0) {
        *model = m;
        return;
      }
    throw core::error(core::status::bad_option, "unknown model name");
  });
}

int hs_scene_default(hs_scene *scene) {
  return fill_default(scene, [](hs_scene &s) {
    s.geometry = HS_GEOMETRY_HERTZ;
    s.a = 1.0;
    s.p0 = 1.0;
    s.f = 1.0;
    s.E_star = 1.0;
    s.Q_over_fP = 0.5;
    s.sigma_over_fp0 = 0.5;
  });
}

namespace {
// The scene of a contact of half-width a under the load P (shared by the
// dimensional constructors); *scene is written only on success.
// (x y)/(u v) for finite x, y and finite nonzero u, v, without overflow or underflow in
// the products (issue 13, fuzz_dimensional: Q/(f P) with f P beyond the double range gave
// 0 or an overflow status for a representable ratio, and with f P subnormal lost digits).
// The plain formula where its intermediates are normal, so that ordinary inputs round as before.
double ratio_of_products(double x, double y, double u, double v) {
  const double num = x * y, den = u * v, plain = num / den;
  if ((num == 0 || std::isnormal(num)) && std::isnormal(den) && (plain == 0 || std::isnormal(plain)) &&
      (num != 0 || x == 0 || y == 0))
    return plain;
  int ex, ey, eu, ev;
  const double m = (std::frexp(x, &ex) * std::frexp(y, &ey)) / (std::frexp(u, &eu) * std::frexp(v, &ev));
  return std::ldexp(m, ex + ey - eu - ev);
}
// sqrt((x y)/(u v)) as above (the Hertz half-width a = sqrt(4 P R / (pi E*)), whose
// square may lie beyond the double range when a does not)
double sqrt_ratio_of_products(double x, double y, double u, double v) {
  const double num = x * y, den = u * v, plain = num / den;
  if (std::isnormal(num) && std::isnormal(den) && std::isnormal(plain)) return std::sqrt(plain);
  int ex, ey, eu, ev;
  double m = (std::frexp(x, &ex) * std::frexp(y, &ey)) / (std::frexp(u, &eu) * std::frexp(v, &ev));
  int k = ex + ey - eu - ev;
  if (k % 2 != 0) {
    m *= 2;
    k -= 1;
  }
  return std::ldexp(std::sqrt(m), k / 2);
}

// The flat punch's half-width from a^2 g(b_f/a) = 2 A R P
// (core::flat_rounded_pressure::half_width_from_load), where 2ARP or 2ARP/b_f^2 leaves the
// normal range of double (issue 13, fuzz_dimensional: P = 1e-314 gave a off by 7e-10):
// with 2ARP = m 4^j, a = 2^j a' where a'^2 g(b_f 2^-j / a') = m (the relation is
// homogeneous: a and b_f scale together, the load as their square).
double flat_rounded_half_width(double P, double A, double R, double bf) {
  using fr = core::flat_rounded_pressure<double>;
  const double load = 2 * A * R * P, target = bf > 0 ? load / (bf * bf) : 1.0;
  if (std::isnormal(2 * A * R) && std::isnormal(load) && std::isnormal(target) && (bf == 0 || std::isnormal(bf * bf)))
    return fr::half_width_from_load(P, A, R, bf);
  int eA, eR, eP;
  const double m = 2 * std::frexp(A, &eA) * std::frexp(R, &eR) * std::frexp(P, &eP);
  const int k = eA + eR + eP;
  const int j = k >= 0 ? k / 2 : -((1 - k) / 2);  // floor(k/2)
  return std::ldexp(fr::half_width_from_load(std::ldexp(m, k - 2 * j), 1.0, 0.5, std::ldexp(bf, -j)), j);
}

void scene_from_loads(double a, double P, double E_star, double f, double Q, double sigma, hs_scene *scene) {
  // p0 = 2P/(pi a), without the overflow of 2P
  const double p0 = ratio_of_products(2, P, core::pi<double>(), a);
  // a subnormal a or p0 carries only a few bits (issue 13, fuzz_dimensional: P = 2.9e-306,
  // R = 4.3e-312 gave a = 1.5e-318, 2e-6 off): not representable to double precision
  require(std::isnormal(a) && a > 0 && std::isnormal(p0) && p0 > 0, core::status::overflow,
          "contact size not representable");
  const double q = ratio_of_products(Q, 1, f, P);
  const double s = ratio_of_products(sigma, 1, f, p0);
  require(std::isfinite(q) && std::isfinite(s), core::status::overflow, "load ratio not representable");
  require(std::fabs(q) < 1, core::status::gross_sliding, "|Q| >= fP");
  hs_scene out;
  hs_scene_default(&out);
  out.a = a;
  out.p0 = p0;
  out.f = f;
  out.E_star = E_star;
  out.Q_over_fP = q;
  out.sigma_over_fp0 = s;
  *scene = out;
}

void check_loads(std::initializer_list<double> values, double P, double E_star, double f) {
  for (double v : values) require(std::isfinite(v), core::status::not_finite, "load value is NaN or infinite");
  require(P > 0 && E_star > 0, core::status::bad_size, "P and E* must be > 0");
  require(f > 0, core::status::bad_friction, "f must be > 0");
}
}  // namespace

int hs_scene_from_power_law_loads(double P, double A, double n, double E_star, double f, double Q, double sigma,
                                  hs_scene *scene) {
  return guard([&] {
    require(scene != nullptr, core::status::null_pointer, "scene is NULL");
    check_loads({P, A, n, E_star, f, Q, sigma}, P, E_star, f);
    const double a = core::power_law_pressure<double>::half_width_from_load(P, E_star, A, n);
    scene_from_loads(a, P, E_star, f, Q, sigma, scene);
  });
}

int hs_scene_from_flat_rounded_loads(double P, double R, double flat_width, double E_star, double f, double Q,
                                     double sigma, hs_scene *scene, double *flat_over_a) {
  return guard([&] {
    require(scene != nullptr && flat_over_a != nullptr, core::status::null_pointer, "NULL argument");
    check_loads({P, R, flat_width, E_star, f, Q, sigma}, P, E_star, f);
    require(R > 0, core::status::bad_size, "corner radius R must be > 0");
    require(flat_width >= 0, core::status::bad_geometry, "flat half-width must be >= 0");
    // a^2 g(b_f/a) = 2 A R P with the plane-strain compliance A = 2/E*
    const double a = flat_rounded_half_width(P, 2 / E_star, R, flat_width);
    hs_scene tmp;
    scene_from_loads(a, P, E_star, f, Q, sigma, &tmp);
    *scene = tmp;
    *flat_over_a = flat_width / a;
  });
}

int hs_scene_from_hertz_loads(double P, double R, double E_star, double f, double Q, double sigma, hs_scene *scene) {
  return guard([&] {
    require(scene != nullptr, core::status::null_pointer, "scene is NULL");
    check_loads({P, R, E_star, f, Q, sigma}, P, E_star, f);
    require(R > 0, core::status::bad_size, "R must be > 0");
    // a = sqrt(4PR/(pi E*)) (core::hertz_pressure::half_width_from_load), without the
    // overflow or underflow of 4PR where a is representable
    scene_from_loads(sqrt_ratio_of_products(P, R, core::pi<double>() / 4, E_star), P, E_star, f, Q, sigma, scene);
  });
}

int hs_options_default(hs_options *opts) {
  return fill_default(opts, [](hs_options &o) {
    o.max_iterations = 100;
    o.rtol = 0.0;
  });
}

int hs_solve(const hs_scene *scene, const hs_options *opts, hs_solution **out) {
  return guard([&] {
    require(out != nullptr, core::status::null_pointer, "output handle pointer is NULL");
    require(scene != nullptr, core::status::null_pointer, "scene is NULL");
    *out = solve_scene(*scene, nullptr, opts);
  });
}

void hs_solution_free(hs_solution *sol) { delete sol; }

int hs_solution_summary(const hs_solution *sol, hs_summary *out) {
  return guard([&] {
    require(sol != nullptr && out != nullptr, core::status::null_pointer, "NULL argument");
    // structs grow at the end: a caller built against the 0.1 header (before
    // p0 and quadrature_order) passes the shorter size and gets those fields
    const size_t n = out->struct_size;
    require(n == sizeof(hs_summary) || n == offsetof(hs_summary, zone_resolution) ||
                n == offsetof(hs_summary, model) || n == offsetof(hs_summary, p0),
            core::status::struct_size, "summary struct_size");
    hs_summary r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof(hs_summary);
    sol->visit([&](const auto &s) {
      r.regime = int(s.reg);
      r.slip_dir1 = s.dir1();
      r.slip_dir2 = s.dir2();
      r.iterations = s.iterations;
      r.a = s.scene.a;
      r.b1 = s.b1();
      r.b2 = s.b2();
      r.d1 = s.d1();
      r.d2 = s.d2();
      r.p0 = s.scene.p0;
      return 0;
    });
    const auto *general = std::get_if<core::general_solution<double>>(&sol->solution);
    r.quadrature_order = general ? general->order : 0;
    r.model = sol->model_used;
    r.error_estimate = sol->error_estimate;
    // issue 13 (item 3): a zone at or below the model's resolution has no
    // direction the model can vouch for; one such zone is the regime boundary
    r.zone_resolution = sol->zone_resolution * r.a;
    const bool u1 = core::zone_unresolved(r.d1 / r.a, sol->zone_resolution);
    const bool u2 = core::zone_unresolved(r.d2 / r.a, sol->zone_resolution);
    if (u1) r.slip_dir1 = 0;
    if (u2) r.slip_dir2 = 0;
    if (u1 || u2) r.regime = (r.d1 == 0 && r.d2 == 0) ? HS_REGIME_STUCK : HS_REGIME_BOUNDARY;
    r.struct_size = n;
    std::memcpy(out, &r, n);
  });
}

int hs_solution_energy(const hs_solution *sol, double energy[2]) {
  return guard([&] {
    require(sol != nullptr && energy != nullptr, core::status::null_pointer, "NULL argument");
    const double e1 = sol->visit([](const auto &s) { return double(s.energy(1)); });
    const double e2 = sol->visit([](const auto &s) { return double(s.energy(2)); });
    require(std::isfinite(e1) && std::isfinite(e2), core::status::overflow, "energy not representable");
    energy[0] = e1;
    energy[1] = e2;
  });
}

int hs_geometry_default(hs_geometry *geometry) {
  return fill_default(geometry, [](hs_geometry &g) {
    g.kind = HS_GEOMETRY_HERTZ;
    g.flat_over_a = 0.5;
    g.exponent = 2.0;
  });
}

int hs_solve_geometry(const hs_scene *scene, const hs_geometry *geometry, const hs_options *opts, hs_solution **out) {
  return guard([&] {
    require(out != nullptr && scene != nullptr && geometry != nullptr, core::status::null_pointer, "NULL argument");
    require(geometry->struct_size == sizeof(hs_geometry), core::status::struct_size, "geometry struct_size");
    if (geometry->kind == HS_GEOMETRY_HERTZ) {
      hs_scene h = *scene;  // the geometry argument decides, not scene->geometry
      h.geometry = HS_GEOMETRY_HERTZ;
      *out = solve_scene(h, nullptr, opts);
    } else {
      *out = solve_scene(*scene, geometry, opts);
    }
  });
}

int hs_eval_Bx(const hs_solution *sol, size_t n, const double *x, double *out) {
  return eval_points(sol, n, x, out, [](const auto &s, double v) { return double(s.Bx(v)); });
}
int hs_eval_slip(const hs_solution *sol, size_t n, const double *x, double *out) {
  return eval_points(sol, n, x, out, [](const auto &s, double v) { return double(s.slip(v)); });
}
int hs_eval_work(const hs_solution *sol, size_t n, const double *x, double *out) {
  return eval_points(sol, n, x, out, [](const auto &s, double v) { return double(s.work(v)); });
}
int hs_eval_pressure(const hs_solution *sol, size_t n, const double *x, double *out) {
  return eval_points(sol, n, x, out, [](const auto &s, double v) { return double(s.pressure(v)); });
}

namespace {
// The points (x, y) of a stress evaluation, each in its body; false: none (n = 0).
bool check_body_points(int body, size_t n, const double *x, const double *y, const double *out) {
  if (n == 0) return false;
  require(x != nullptr && y != nullptr && out != nullptr, core::status::null_pointer,
          "point or output array is NULL");
  for (size_t i = 0; i < n; ++i) {
    require(std::isfinite(x[i]) && std::isfinite(y[i]), core::status::not_finite, "point is NaN or infinite");
    require(body == 1 ? y[i] >= 0 : y[i] <= 0, core::status::bad_option,
            "point outside the body (body 1: y >= 0, body 2: y <= 0)");
  }
  return true;
}
void check_fields_input(const hs_solution *sol, int body, double bulk2) {
  require(sol != nullptr, core::status::null_pointer, "solution is NULL");
  require(body == 1 || body == 2, core::status::bad_option, "body must be 1 or 2");
  require(std::isfinite(bulk2), core::status::not_finite, "bulk stress is NaN or infinite");
}
}  // namespace

int hs_eval_surface_stress(const hs_solution *sol, int body, double bulk2, size_t n, const double *x, double *out) {
  return guard([&] {
    check_fields_input(sol, body, bulk2);
    if (n == 0) return;
    require(x != nullptr && out != nullptr, core::status::null_pointer, "point or output array is NULL");
    for (size_t i = 0; i < n; ++i) require(std::isfinite(x[i]), core::status::not_finite, "point is NaN or infinite");
    const auto st = state_of(*sol, bulk2);
    std::vector<double> tmp(n);
    for (size_t i = 0; i < n; ++i) tmp[i] = core::surface_sxx(st, body, x[i]);
    std::memcpy(out, tmp.data(), n * sizeof(double));
  });
}

int hs_eval_stress(const hs_solution *sol, int body, double bulk2, size_t n, const double *x, const double *y,
                   double *out) {
  return guard([&] {
    check_fields_input(sol, body, bulk2);
    if (!check_body_points(body, n, x, y, out)) return;
    const auto st = state_of(*sol, bulk2);
    std::vector<double> tmp(3 * n);
    for (size_t i = 0; i < n; ++i) {
      const auto s = core::stress_at(st, body, x[i], std::fabs(y[i]));
      tmp[3 * i] = s.xx;
      tmp[3 * i + 1] = s.yy;
      tmp[3 * i + 2] = s.xy;
    }
    std::memcpy(out, tmp.data(), 3 * n * sizeof(double));
  });
}

int hs_eval_stress_scalar(const hs_solution *sol, int body, double bulk2, int quantity, double nu, size_t n,
                          const double *x, const double *y, double *out) {
  return guard([&] {
    check_fields_input(sol, body, bulk2);
    require(quantity >= HS_STRESS_XX && quantity <= HS_STRESS_MAX_SHEAR, core::status::bad_option,
            "quantity must be one of HS_STRESS_XX .. HS_STRESS_MAX_SHEAR");
    require(std::isfinite(nu), core::status::not_finite, "Poisson's ratio nu is NaN or infinite");
    require(nu >= -1 && nu <= 0.5, core::status::bad_option, "Poisson's ratio nu must lie in [-1, 0.5]");
    if (!check_body_points(body, n, x, y, out)) return;
    const auto st = state_of(*sol, bulk2);
    std::vector<double> tmp(n);
    for (size_t i = 0; i < n; ++i) {
      const auto s = core::stress_at(st, body, x[i], std::fabs(y[i]));
      switch (quantity) {
        case HS_STRESS_XX: tmp[i] = s.xx; break;
        case HS_STRESS_YY: tmp[i] = s.yy; break;
        case HS_STRESS_XY: tmp[i] = s.xy; break;
        case HS_STRESS_VON_MISES: tmp[i] = s.von_mises(nu); break;
        case HS_STRESS_MAX_PRINCIPAL: tmp[i] = s.max_principal(); break;
        case HS_STRESS_MIN_PRINCIPAL: tmp[i] = s.min_principal(); break;
        default: tmp[i] = s.max_shear(); break;
      }
    }
    std::memcpy(out, tmp.data(), n * sizeof(double));
  });
}

int hs_surface_stress_extremes(const hs_solution *sol, int body, double bulk2, double half_range, double out[5]) {
  return guard([&] {
    check_fields_input(sol, body, bulk2);
    require(out != nullptr, core::status::null_pointer, "output is NULL");
    require(std::isfinite(half_range), core::status::not_finite, "half_range is NaN or infinite");
    const auto st = state_of(*sol, bulk2);
    const double L = half_range > 0 ? half_range : 3 * st.a;
    // search grid: 800 points plus the special points. Each evaluation costs
    // O(panels); a sampled pressure has a panel end (a break) at every sample,
    // and with all of them in the grid the search cost O(n^2) (issue 13 item
    // 4: 9 s at n = 1000). Beyond 64 breaks only the stick ends join the grid
    // (sigma_xx is continuous at the knots, where phi is C^1).
    std::vector<double> special{-st.a, st.a, st.stick_lo, st.stick_hi};
    if (st.breaks.size() <= 64)
      for (double b : st.breaks) special.push_back(b);
    const auto e = core::surface_summary(st, body, L, special);
    out[0] = e.max;
    out[1] = e.x_max;
    out[2] = e.min;
    out[3] = e.x_min;
    out[4] = e.bulk;
  });
}

// issue 15: shear traction
int hs_eval_traction(const hs_solution *sol, size_t n, const double *x, double *out) {
  return eval_points(sol, n, x, out, [](const auto &s, double v) { return double(s.traction(v)); });
}

int hs_asymptotic_error(int loading, double b_over_a, hs_asymptotic_comparison *out) {
  return guard([&] {
    require(out != nullptr, core::status::null_pointer, "output is NULL");
    require(out->struct_size == sizeof(hs_asymptotic_comparison), core::status::struct_size, "struct_size");
    require(loading == HS_LOADING_SHEAR || loading == HS_LOADING_BULK, core::status::bad_option,
            "loading must be HS_LOADING_SHEAR or HS_LOADING_BULK");
    require(std::isfinite(b_over_a), core::status::not_finite, "b/a is not finite");
    require(b_over_a > 0 && b_over_a < 1, core::status::bad_option, "b/a must lie in (0, 1)");
    const auto c = core::compare_asymptotic<double>(loading == HS_LOADING_SHEAR ? +1 : -1, b_over_a);
    hs_asymptotic_comparison r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof r;
    r.Q_over_fP = c.scene.q;
    r.sigma_over_fp0 = c.scene.s;
    r.d_full = c.d_full;
    r.d_asymptotic = c.d_asym;
    r.energy_full = c.energy_full;
    r.energy_asymptotic = c.energy_asym;
    r.fractional_error = c.fractional_error();
    *out = r;
  });
}

int hs_check_samples(size_t n, const double *x, const double *p, double a, int *verdict, size_t *index,
                     char *reason, size_t size) {
  return guard([&] {
    require(x != nullptr && p != nullptr && verdict != nullptr, core::status::null_pointer, "NULL argument");
    size_t where = n;
    int v = HS_OK;
    const char *why = "";
    try {
      require(std::isfinite(a), core::status::not_finite, "contact half-width a is NaN or infinite");
      require(a > 0, core::status::bad_size, "contact half-width a must be > 0");
      hs::capi::samples_model(n, x, p, a, &where);
    } catch (const core::error &e) {
      v = int(e.code());
      why = e.what();
    }
    *verdict = v;
    if (index) *index = v == HS_OK ? n : where;
    if (reason && size > 0) {
      const size_t len = std::min(std::strlen(why), size - 1);
      std::memcpy(reason, why, len);
      reason[len] = '\0';
    }
  });
}

int hs_ref_scene_default(hs_ref_scene *scene) {
  // NULL strings mean the defaults of hs::reference::text_scene
  return fill_default(scene, [](hs_ref_scene &s) { s.geometry = HS_GEOMETRY_HERTZ; });
}

int hs_ref_max_digits(void) { return hs::reference::max_digits(); }

int hs_ref_max_digits_geometry(int geometry) {
  static_assert(HS_GEOMETRY_HERTZ == hs::reference::geometry_hertz &&
                    HS_GEOMETRY_FLAT_ROUNDED == hs::reference::geometry_flat_rounded &&
                    HS_GEOMETRY_POWER_LAW == hs::reference::geometry_power_law,
                "geometry table");
  return hs::reference::max_digits(geometry);
}

namespace {
// The reference backend's text scene of an hs_ref_scene (struct_size, geometry
// and dimensional input checked).
hs::reference::text_scene text_of(const hs_ref_scene *scene) {
  // 0.2 callers pass the size without the geometry parameters: Hertz only
  const bool v02 = scene->struct_size == offsetof(hs_ref_scene, flat_over_a);
  require(scene->struct_size == sizeof(hs_ref_scene) || v02, core::status::struct_size, "scene struct_size");
  require(scene->geometry == HS_GEOMETRY_HERTZ ||
              (!v02 && (scene->geometry == HS_GEOMETRY_FLAT_ROUNDED || scene->geometry == HS_GEOMETRY_POWER_LAW)),
          core::status::bad_geometry, "unknown geometry");
  hs::reference::text_scene t;
  auto take = [](std::string &dst, const char *src) {
    if (src) dst = src;
  };
  t.geometry = scene->geometry;
  if (!v02) {
    take(t.flat_over_a, scene->flat_over_a);
    take(t.exponent, scene->exponent);
  }
  take(t.a, scene->a);
  take(t.p0, scene->p0);
  take(t.f, scene->f);
  take(t.Estar, scene->E_star);
  take(t.q, scene->Q_over_fP);
  take(t.s, scene->sigma_over_fp0);
  if (scene->P) {
    require(scene->R && scene->Q && scene->sigma, core::status::null_pointer,
            "dimensional input needs P, R, Q and sigma");
    t.P = scene->P;
    t.R = scene->R;
    t.Q = scene->Q;
    t.sigma = scene->sigma;
  }
  return t;
}
}  // namespace

int hs_ref_solve(const hs_ref_scene *scene, int digits, hs_ref_solution **out) {
  return guard([&] {
    require(scene != nullptr && out != nullptr, core::status::null_pointer, "NULL argument");
    const hs::reference::text_scene t = text_of(scene);
    *out = new hs_ref_solution{hs::reference::solution(t, digits)};
  });
}

void hs_ref_solution_free(hs_ref_solution *sol) { delete sol; }

// issue 14: certified load histories along one ray (reference/ray_history.hpp)
struct hs_ref_history {
  std::unique_ptr<hs::reference::ray_history> h;
};

int hs_ref_history_new(const hs_ref_scene *scene, int digits, hs_ref_history **out) {
  return guard([&] {
    require(scene != nullptr && out != nullptr, core::status::null_pointer, "NULL argument");
    auto r = std::make_unique<hs_ref_history>();
    r->h = std::make_unique<hs::reference::ray_history>(text_of(scene), digits);
    *out = r.release();
  });
}

void hs_ref_history_free(hs_ref_history *h) { delete h; }

int hs_ref_history_add_vertices(hs_ref_history *h, size_t n, const char *const *Q_over_fP,
                                const char *const *sigma_over_fp0) {
  return guard([&] {
    require(h != nullptr && (n == 0 || (Q_over_fP != nullptr && sigma_over_fp0 != nullptr)),
            core::status::null_pointer, "NULL argument");
    for (size_t i = 0; i < n; ++i) {
      require(Q_over_fP[i] != nullptr && sigma_over_fp0[i] != nullptr, core::status::null_pointer,
              "NULL vertex string");
      h->h->add(Q_over_fP[i], sigma_over_fp0[i]);
    }
  });
}

int hs_ref_history_vertex_count(const hs_ref_history *h, size_t *n) {
  return guard([&] {
    require(h != nullptr && n != nullptr, core::status::null_pointer, "NULL argument");
    *n = h->h->size();
  });
}

int hs_ref_history_slip_dirs(const hs_ref_history *h, size_t vertex, int *dir1, int *dir2) {
  return guard([&] {
    require(h != nullptr && dir1 != nullptr && dir2 != nullptr, core::status::null_pointer, "NULL argument");
    const int d1 = h->h->dir1(vertex), d2 = h->h->dir2(vertex);
    *dir1 = d1;
    *dir2 = d2;
  });
}

int hs_ref_solution_summary(const hs_ref_solution *sol, hs_ref_summary *out) {
  return guard([&] {
    require(sol != nullptr && out != nullptr, core::status::null_pointer, "NULL argument");
    require(out->struct_size == sizeof(hs_ref_summary), core::status::struct_size, "summary struct_size");
    hs_ref_summary r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof r;
    r.regime = sol->sol.regime();
    r.slip_dir1 = sol->sol.dir1();
    r.slip_dir2 = sol->sol.dir2();
    r.iterations = sol->sol.iterations();
    r.digits = sol->sol.digits();
    r.working_digits = int(sol->sol.working_digits());
    r.check_digits = int(sol->sol.check_digits());
    *out = r;
  });
}

namespace {
void put_text(const hs::reference::certified &c, char *buf, size_t size, size_t *needed, int *certified) {
  const size_t n = c.text.size() + 1;
  if (needed) *needed = n;
  require(buf != nullptr || size == 0, core::status::null_pointer, "buffer is NULL");
  require(size >= n, core::status::buffer_too_small, "buffer too small");
  std::memcpy(buf, c.text.c_str(), n);
  if (certified) *certified = c.digits;
}
}  // namespace

int hs_ref_value(const hs_ref_solution *sol, int quantity, char *buf, size_t size, size_t *needed, int *certified) {
  return guard([&] {
    require(sol != nullptr, core::status::null_pointer, "solution is NULL");
    require(quantity >= HS_REF_B1 && quantity <= HS_REF_P0, core::status::bad_option, "unknown quantity");
    put_text(sol->sol.value(hs::reference::quantity(quantity)), buf, size, needed, certified);
  });
}

int hs_ref_history_value(const hs_ref_history *h, size_t vertex, int quantity, char *buf, size_t size, size_t *needed,
                         int *certified) {
  return guard([&] {
    require(h != nullptr, core::status::null_pointer, "history is NULL");
    require(quantity == HS_REF_B1 || quantity == HS_REF_B2 || quantity == HS_REF_ENERGY1 || quantity == HS_REF_ENERGY2,
            core::status::bad_option, "quantity: HS_REF_B1, HS_REF_B2, HS_REF_ENERGY1 or HS_REF_ENERGY2");
    put_text(h->h->value(vertex, hs::reference::quantity(quantity)), buf, size, needed, certified);
  });
}

int hs_ref_eval(const hs_ref_solution *sol, int what, const char *x, char *buf, size_t size, size_t *needed,
                int *certified) {
  return guard([&] {
    require(sol != nullptr && x != nullptr, core::status::null_pointer, "NULL argument");
    require(what >= HS_REF_EVAL_BX && what <= HS_REF_EVAL_TRACTION, core::status::bad_option, "unknown evaluation");
    put_text(sol->sol.eval(hs::reference::point_eval(what), x), buf, size, needed, certified);
  });
}

int hs_ref_eval_stress(const hs_ref_solution *sol, int body, const char *bulk2, int component, const char *x,
                       const char *y, char *buf, size_t size, size_t *needed, int *certified) {
  return guard([&] {
    require(sol != nullptr && x != nullptr && y != nullptr, core::status::null_pointer, "NULL argument");
    require(body == 1 || body == 2, core::status::bad_option, "body must be 1 or 2");
    require(component >= HS_STRESS_XX && component <= HS_STRESS_XY, core::status::bad_option,
            "component must be HS_STRESS_XX, HS_STRESS_YY or HS_STRESS_XY");
    put_text(sol->sol.stress(body, bulk2 ? bulk2 : "0", hs::reference::stress_component(component), x, y), buf, size,
             needed, certified);
  });
}

}  // extern "C"
