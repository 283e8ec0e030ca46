// halfslip C ABI, private: the solution handle and the model driver
// (model selection by tolerance, docs/models.md). Not installed.
#pragma once
#include <cmath>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "halfslip/core/asymptotic.hpp"
#include "halfslip/core/field_panels.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/core/history_fields.hpp"
#include "halfslip/core/static_history.hpp"
#include "halfslip/core/select.hpp"
#include "halfslip/reference/backend.hpp"

namespace hs { namespace capi {

// The exception firewall: every extern "C" body goes through here.
template <class F> int guard(F &&body) noexcept {
  try {
    body();
    return 0;  // HS_OK
  } catch (const core::error &e) {
    return int(e.code());
  } catch (const std::bad_alloc &) {
    return int(core::status::out_of_memory);
  } catch (...) {
    return int(core::status::internal);
  }
}

// Throws the core's error (turned into the status by the ABI's firewall).
inline void require(bool ok, core::status s, const char *msg) {
  if (!ok) throw core::error(s, msg);
}

// The reference backend's certified solution rounded to double, with the
// interface of the core solutions (values certified to >= 17 digits at
// construction; point evaluations go through decimal strings).
class reference_double {
 public:
  reference_double(const reference::text_scene &t, const core::general_scene<double> &sc, int max_iterations);
  core::general_scene<double> scene;
  core::regime reg = core::regime::stuck;
  int iterations = 0;
  int dir1() const { return dir1_; }
  int dir2() const { return dir2_; }
  double b1() const { return b1_; }
  double b2() const { return b2_; }
  double d1() const { return d1_; }
  double d2() const { return d2_; }
  // computed on demand (certified MPFR quadrature: milliseconds to seconds)
  double energy(int zone) const {
    return take(sol_->value(zone == 1 ? reference::quantity::energy1 : reference::quantity::energy2));
  }
  double Bx(double x) const { return eval(reference::point_eval::Bx, x); }
  double slip(double x) const { return eval(reference::point_eval::slip, x); }
  double work(double x) const { return eval(reference::point_eval::work, x); }
  double pressure(double x) const { return eval(reference::point_eval::pressure, x); }
  // shear traction from the certified zones and the (certified) pressure,
  // by the double quadrature of core/traction.hpp
  double traction(double x) const {
    return core::monotonic_traction<double>([this](double v) { return pressure(v); }, scene.a, scene.f, b1_, b2_,
                                            dir1_, dir2_, x);
  }

 private:
  double take(const reference::certified &c) const;
  double eval(reference::point_eval what, double x) const;
  std::unique_ptr<reference::solution> sol_;
  int dir1_ = 0, dir2_ = 0;
  double b1_ = 0, b2_ = 0, d1_ = 0, d2_ = 0;
};

// What the states of a load history share (history_state, ray_state): the
// vertex's loads, stick zone and directions, and the monotonic-only quantities
// that report HS_ERR_NOT_APPLICABLE.
class vertex_state {
 public:
  // b1, b2 in the units of length; a direction counts only where its zone is not empty
  vertex_state(const core::general_scene<double> &sc, double q, double s, double b1, double b2, int dir1, int dir2)
      : scene(sc), b1_(b1), b2_(b2) {
    scene.q = q;
    scene.s = s;
    dir1_ = b1 < sc.a ? dir1 : 0;
    dir2_ = b2 < sc.a ? dir2 : 0;
    // regime of a state: stuck without slip zones, opposite sign when the two
    // zones slip in opposite directions, otherwise same sign
    reg = (dir1_ == 0 && dir2_ == 0) ? core::regime::stuck
          : (dir1_ * dir2_ < 0)      ? core::regime::opposite_sign
                                     : core::regime::same_sign;
  }
  core::general_scene<double> scene;  // a, p0, f, E*; q, s: the vertex's loads
  core::regime reg = core::regime::stuck;
  int iterations = 0;
  int dir1() const { return dir1_; }
  int dir2() const { return dir2_; }
  double b1() const { return b1_; }
  double b2() const { return b2_; }
  double d1() const { return scene.a - b1_; }
  double d2() const { return scene.a - b2_; }
  [[noreturn]] static void not_applicable(const char *what) { throw core::error(core::status::not_applicable, what); }
  double energy(int) const {
    not_applicable(
        "a load-history state has no monotonic zone energies (hs_history_vertex_get: energies per segment)");
  }
  double Bx(double) const { not_applicable("B_x is not evaluated for a load-history state (slip: hs_eval_slip)"); }
  double work(double) const { not_applicable("the work density f p |h| is that of monotonic loading only"); }

 private:
  int dir1_ = 0, dir2_ = 0;
  double b1_ = 0, b2_ = 0;
};

// The state at a vertex of a marched load history (hs_history_state, issue 15): a
// read-only solution handle. It shares a copy of the steps up to the vertex
// (history::prefix), so it outlives the history and does not change when the
// history grows. Physical units.
class history_state : public vertex_state {
 public:
  history_state(std::shared_ptr<const core::history<double>> h, const core::general_scene<double> &sc,
                const core::history_vertex<double> &v)
      : vertex_state(sc, v.q, v.s, sc.a * v.b1, sc.a * v.b2, v.dir1, v.dir2), hist(std::move(h)) {}
  std::shared_ptr<const core::history<double>> hist;  // the steps up to the vertex
  std::size_t nsteps() const { return hist->step_count(); }
  double slip(double x) const {
    return scene.f * scene.p0 * scene.a / scene.Estar * hist->slip(x / scene.a, nsteps());
  }
  double pressure(double x) const { return core::history_pressure_at(*hist, x, scene.a, scene.p0); }
  double traction(double x) const {
    return core::history_traction_at(*hist, nsteps(), x, scene.a, scene.p0, scene.f);
  }
};

// The state at a vertex of a load history along one ray, by superposition of
// monotonic solutions (core/ray_history.hpp, issue 14): q, h and the stresses
// are sums c_k (q_k, h_k, ...) of the parts (shared, immutable solutions), so
// the state outlives the history. Physical units.
class ray_state : public vertex_state {
 public:
  struct part {
    int coef;
    std::shared_ptr<const hs_solution> sol;
  };
  ray_state(std::vector<part> parts, const core::general_scene<double> &sc, double q, double s, double b1, double b2,
            int dir1, int dir2)
      : vertex_state(sc, q, s, b1, b2, dir1, dir2), parts_(std::move(parts)) {}
  const std::vector<part> &parts() const { return parts_; }
  inline double slip(double x) const;
  inline double pressure(double x) const;
  inline double traction(double x) const;

 private:
  std::vector<part> parts_;
};

// The state at a vertex of a load history taken by static solves of advancing
// segments (core/static_history.hpp, issue 14): a shared, immutable copy of the
// history after the vertex (the segments are shared), physical units.
class static_state : public vertex_state {
 public:
  static_state(std::shared_ptr<const core::static_history<double>> h, const core::general_scene<double> &sc)
      : vertex_state(sc, h->q(), h->s(), sc.a * h->b1(), sc.a * h->b2(), h->b1() < 1 ? h->dir1() : 0,
                     h->b2() < 1 ? h->dir2() : 0),
        hist(std::move(h)) {}
  std::shared_ptr<const core::static_history<double>> hist;
  double slip(double x) const { return scene.f * scene.p0 * scene.a / scene.Estar * hist->slip(x / scene.a); }
  double pressure(double x) const {
    const double xi = x / scene.a;
    return std::fabs(xi) < 1 ? scene.p0 * hist->pressure().p(xi) : 0.0;
  }
  double traction(double x) const {
    const double xi = x / scene.a;
    return std::fabs(xi) < 1 ? scene.f * scene.p0 * hist->traction(xi) : 0.0;
  }
};

// The exact decimal expansion of a double (so that the reference sees the
// very number the caller passed).
std::string exact_decimal(double v);

}}  // namespace hs::capi

struct hs_solution {
  // the pressure model, which the general and edge solutions refer to
  // (declared before them: destroyed after them); null for closed forms
  std::shared_ptr<const hs::core::pressure_model<double>> model;
  // the solution of the model that ran (monostate only while it runs)
  std::variant<std::monostate, hs::core::hertz_solution<double>, hs::core::general_solution<double>,
               hs::core::edge_solution<double>, hs::capi::reference_double, hs::capi::history_state,
               hs::capi::ray_state, hs::capi::static_state>
      solution;
  int model_used = 0;  // HS_MODEL_*
  double error_estimate = 0;  // relative, of the resolved zones (core/select.hpp)
  // issue 13: the model's zone resolution (units of a; 0: none, e.g. a load-history
  // state) and the number of zones at or below it
  double zone_resolution = 0;
  int unresolved = 0;
  // issue 15: p and q cached on graded panels for the stresses, built on the
  // first field evaluation that needs them (thread-safe; null: closed forms)
  mutable std::once_flag panels_once;
  mutable std::shared_ptr<const hs::core::traction_panels<double>> panels;
  // f(solution) for the solution that ran, whatever its type. A chain of
  // std::get_if rather than std::visit: GCC's std::visit dispatches through a
  // table of function pointers, which kept f from being inlined and cost ~2 ns
  // a call on the Hertz point evaluations (scripts/bench_compare.sh).
  template <class F> auto visit(F &&f) const { return visit_from<1>(f); }

 private:
  template <std::size_t I, class F> auto visit_from(F &f) const
      -> decltype(f(std::declval<const hs::core::hertz_solution<double> &>())) {
    if constexpr (I < std::variant_size<decltype(solution)>::value) {
      if (const auto *s = std::get_if<I>(&solution)) return f(*s);
      return visit_from<I + 1>(f);
    } else {
      throw hs::core::error(hs::core::status::internal, "solution handle holds no solution");
    }
  }
};

namespace hs { namespace capi {

inline double ray_state::slip(double x) const {
  double r = 0;
  for (const auto &p : parts_) r += p.coef * p.sol->visit([&](const auto &v) { return double(v.slip(x)); });
  return r;
}
inline double ray_state::pressure(double x) const {
  return parts_.front().sol->visit([&](const auto &v) { return double(v.pressure(x)); });
}
inline double ray_state::traction(double x) const {
  double r = 0;
  for (const auto &p : parts_) r += p.coef * p.sol->visit([&](const auto &v) { return double(v.traction(x)); });
  return r;
}

struct request {
  int max_iterations = 100;
  double rtol = 0;
  int model = 0;  // HS_MODEL_*
};

// What the reference backend needs to re-solve the scene (empty geometry:
// not available, e.g. sampled or callback pressures).
// The scene is kept in double and written out as exact decimals only when the
// reference runs (issue 16: the six 800-digit expansions cost ~15 us, 50x a
// Hertz closed-form solve, on every AUTO call).
struct reference_input {
  bool available = false;
  core::general_scene<double> scene;
  int geometry = 1;      // HS_GEOMETRY_*
  double parameter = 0;  // b_f/a or the exponent, as the caller passed it
  reference::text_scene text() const;
};

// Solve into h (h.model set for non-Hertz geometries; hertz = true for the
// Hertz geometry, whose pressure model is made on demand).
// The pressure model of a non-Hertz geometry, filling the canonical scene (halfslip.cpp).
std::shared_ptr<const core::pressure_model<double>> pressure_of_geometry(const hs_scene &scene,
                                                                         const hs_geometry &geometry,
                                                                         core::general_scene<double> &sc);

void solve_models(hs_solution &h, bool hertz, const core::general_scene<double> &sc, const request &r,
                  const reference_input &ref);

}}  // namespace hs::capi
