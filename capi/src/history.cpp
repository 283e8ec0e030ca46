// halfslip C ABI: load histories (issue #14). Thin shims over
// core/history.hpp: convert units, check struct_size, catch exceptions.
#include <halfslip/halfslip.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "halfslip/core/history.hpp"
#include "halfslip/core/ray_history.hpp"
#include "halfslip/core/static_history.hpp"
#include "solution.hpp"

namespace core = hs::core;
using hs::capi::guard;
using hs::capi::require;

// A vertex of a path along one ray (issue 14): its result and the monotonic
// solutions whose sum is the state after it.
struct ray_vertex_rec {
  core::ray_vertex_result<double> r;  // physical units
  double q = 0, s = 0;
  double error_estimate = 0;
  int cycle = 0;  // as hs_history_vertex.cycle
  std::vector<hs::capi::ray_state::part> parts;
};

struct hs_history {
  core::general_scene<double> scene;  // a, p0, f, E* (loads unused)
  hs_history_options opts;
  std::unique_ptr<core::refined_history<double>> h;
  core::cycle_result<double> cycles;
  bool has_cycles = false;
  // issue 14: while every vertex lies on one ray through the origin and no zone
  // recedes on the ramp, the states are sums of monotonic solutions (exact, no
  // march); the first vertex off the ray (or periodic loading) replays the
  // path in the march
  std::shared_ptr<const core::pressure_model<double>> pm;
  bool hertz = true;
  bool ray_mode = true;
  core::ray_path<double> ray;
  std::vector<ray_vertex_rec> ray_vertices;
  std::map<std::pair<double, double>, std::shared_ptr<const hs_solution>> mono_cache;
  std::vector<std::pair<double, double>> input;  // the vertices given, in order
  core::history_options<double> march_options;
  double march_rtol = 0;
  // the static solves' orders and tolerances, from opts->rtol (core::static_history_accuracy::for_rtol:
  // the result agrees with the full-accuracy static solve to within rtol)
  core::static_history_accuracy<double> static_accuracy;
  // issue 14: off the ray, while every segment advances, one static solve per segment
  // (core/static_history.hpp): a snapshot of the history after each vertex (cheap: the
  // segments are shared). The first segment it cannot take replays the path in the march.
  bool static_mode = false;
  std::shared_ptr<const core::static_history<double>> st;
  struct static_vertex_rec {
    std::shared_ptr<const core::static_history<double>> snap;
    double E1 = 0, E2 = 0;  // the segment ending here, canonical units
    double Ep = 0;          // ... in an interior slip zone (core/static_patch.hpp)
    int cycle = 0;          // periodic loading: the cycle this vertex belongs to (0: none)
    // a copy of a steady cycle's vertex (core::add_cycles): its loads (snap is the original's), and
    // what the copy adds to the error estimate (k times the copied cycle's change on the k-th copy)
    bool copy = false;
    double q = 0, s = 0, copy_estimate = 0;
    // the error estimate: the accuracy the static solves were set to (for_rtol), a copy's
    // distance, and how far the vertex put an end onto a memory point (core::static_history::
    // memory_snap, over a)
    double estimate(double rtol) const { return rtol + copy_estimate + snap->memory_snap(); }
  };
  std::vector<static_vertex_rec> static_vertices;
  // The march's disagreement with the superposition or the static solves on the vertices they
  // took before the path left them (to_march): the largest difference of an end (over a) or a
  // zone energy (over the largest of those vertices). Both are exact to rtol, so this is the
  // march's own error there, measured; every march vertex reports at least it.
  double march_measured = 0;
  // the message of the last failed hs_history_add_vertices / add_cycles ("" after a success)
  std::string last_error;
  // HS_PATCHES_MERGE: the vertices (input indices) whose segment the static solves refused for an
  // interior slip zone before the march took it; the march may not see that patch, so from each
  // such vertex on the result counts one more approximation (hs_history_vertex.interior_merges)
  std::vector<size_t> static_patch_at;
  size_t cycle_patch_at = size_t(-1);  // the same, found by the static solves of add_cycles (pending)
  // the static solves' reason for refusing the last segment they were given, and its vertex (1-based;
  // kept for the message if the march then fails too)
  std::string static_refusal;
  size_t static_refusal_at = 0;
  std::string last_error_note;  // appended to the next error's message in last_error
  // the cycle tag of vertex i (hs_history_vertex.cycle) in whichever method holds it
  int vertex_cycle(size_t i) const {
    if (ray_mode) return i < ray_vertices.size() ? ray_vertices[i].cycle : 0;
    if (static_mode) return i < static_vertices.size() ? static_vertices[i].cycle : 0;
    return h && i < h->fine().vertices().size() ? h->fine().vertices()[i].cycle : 0;
  }
  size_t vertex_count() const {
    return ray_mode ? ray_vertices.size() : static_mode ? static_vertices.size() : h->fine().vertices().size();
  }
};

namespace {

void check_finite_positive(double v, const char *what) {
  require(std::isfinite(v), core::status::not_finite, what);
  require(v > 0, core::status::bad_size, what);
}

}  // namespace

int hs_history_options_default(hs_history_options *o) {
  return guard([&] {
    require(o != nullptr, core::status::null_pointer, "NULL options");
    o->struct_size = sizeof *o;
    o->max_step = 1.0 / 32;
    o->rtol = 1e-8;
    o->max_steps = 20000;
    o->segments_per_cycle = 64;
    o->ramp_order = HS_RAMP_SIGMA_FIRST;
    o->steady_rtol = 1e-6;
    o->interior_patches = HS_PATCHES_ERROR;
  });
}

int hs_history_new(const hs_scene *scene, const hs_geometry *geometry, const hs_history_options *opts,
                   hs_history **out) {
  return guard([&] {
    require(scene != nullptr && out != nullptr, core::status::null_pointer, "NULL argument");
    require(scene->struct_size == sizeof(hs_scene), core::status::struct_size, "scene struct_size");
    auto r = std::make_unique<hs_history>();
    hs_history_options_default(&r->opts);
    if (opts) {
      // a 0.4.0 caller's struct ends before interior_patches (that field keeps its default)
      const size_t v040 = offsetof(hs_history_options, interior_patches);
      require(opts->struct_size == sizeof(hs_history_options) || opts->struct_size == v040,
              core::status::struct_size, "options struct_size");
      std::memcpy(&r->opts, opts, opts->struct_size);
      r->opts.struct_size = sizeof(hs_history_options);
    }
    const auto &o = r->opts;
    require(std::isfinite(o.max_step) && o.max_step >= 1e-6 && o.max_step <= 1, core::status::bad_option,
            "max_step must be in [1e-6, 1]");
    require(o.max_steps >= 1, core::status::bad_option, "max_steps must be >= 1");
    require(o.segments_per_cycle >= 4 && o.segments_per_cycle <= 100000, core::status::bad_option,
            "segments_per_cycle must be in 4..100000");
    require(o.ramp_order >= HS_RAMP_SIGMA_FIRST && o.ramp_order <= HS_RAMP_Q_FIRST, core::status::bad_option,
            "ramp_order");
    require(std::isfinite(o.steady_rtol) && o.steady_rtol >= 0, core::status::bad_option, "steady_rtol");
    require(std::isfinite(o.rtol) && o.rtol >= 0, core::status::bad_option, "rtol");
    require(o.interior_patches == HS_PATCHES_ERROR || o.interior_patches == HS_PATCHES_MERGE,
            core::status::bad_option, "interior_patches must be HS_PATCHES_ERROR or HS_PATCHES_MERGE");
    std::shared_ptr<const core::pressure_model<double>> pm;
    if (geometry == nullptr || geometry->kind == HS_GEOMETRY_HERTZ) {
      if (geometry) require(geometry->struct_size == sizeof(hs_geometry), core::status::struct_size, "geometry");
      require(scene->geometry == HS_GEOMETRY_HERTZ || geometry != nullptr, core::status::bad_geometry,
              "scene geometry: pass an hs_geometry for non-Hertz contacts");
      r->scene.a = scene->a;
      r->scene.p0 = scene->p0;
      r->scene.f = scene->f;
      r->scene.Estar = scene->E_star;
      pm = std::make_shared<core::hertz_pressure<double>>();
    } else {
      require(geometry->struct_size == sizeof(hs_geometry), core::status::struct_size, "geometry struct_size");
      pm = hs::capi::pressure_of_geometry(*scene, *geometry, r->scene);
    }
    check_finite_positive(r->scene.a, "a");
    check_finite_positive(r->scene.p0, "p0");
    check_finite_positive(r->scene.Estar, "E*");
    require(std::isfinite(r->scene.f), core::status::not_finite, "f");
    require(r->scene.f > 0, core::status::bad_friction, "f");
    core::history_options<double> ho;
    ho.max_step = o.max_step;
    ho.max_steps = o.max_steps;
    ho.merge_interior_patches = o.interior_patches == HS_PATCHES_MERGE;
    r->h = std::make_unique<core::refined_history<double>>(pm, ho, o.rtol);
    r->pm = pm;
    r->march_options = ho;
    r->march_rtol = o.rtol;
    r->static_accuracy = core::static_history_accuracy<double>::for_rtol(o.rtol);
    r->hertz = geometry == nullptr || geometry->kind == HS_GEOMETRY_HERTZ;
    *out = r.release();
  });
}

void hs_history_free(hs_history *h) { delete h; }

namespace {

// The monotonic solution at (q, s) in the history's contact (default model),
// shared between the vertices and states that use it.
std::shared_ptr<const hs_solution> mono_at(hs_history &h, double q, double s) {
  const auto key = std::make_pair(q, s);
  const auto it = h.mono_cache.find(key);
  if (it != h.mono_cache.end()) return it->second;
  auto sol = std::make_shared<hs_solution>();
  core::general_scene<double> sc = h.scene;
  sc.q = q;
  sc.s = s;
  if (!h.hertz) sol->model = h.pm;
  hs::capi::solve_models(*sol, h.hertz, sc, hs::capi::request{}, hs::capi::reference_input{});
  h.mono_cache.emplace(key, sol);
  return sol;
}

// The monotonic stick half-width (units of a) at canonical loads, for the recede check.
double mono_half_width(hs_history &h, double q, double s) {
  const auto sol = mono_at(h, q, s);
  return (sol->visit([](const auto &v) { return double(v.b1()); }) +
          sol->visit([](const auto &v) { return double(v.b2()); })) /
         (2 * h.scene.a);
}

bool add_on_ray_solved(hs_history &h, double q, double s, core::ray_path<double> &next);

// Adds (q, s) to the path along one ray; false (nothing changed) when the
// superposition does not apply: off the ray, or a zone would recede on the
// ramp to the path's farthest vertex.
bool add_on_ray(hs_history &h, double q, double s) {
  require(std::isfinite(q) && std::isfinite(s), core::status::not_finite, "history: a path vertex is not finite");
  require(std::fabs(q) < 1, core::status::gross_sliding, "history: |Q| >= fP at a path vertex: gross sliding");
  core::ray_path<double> next = h.ray;
  if (!next.add(q, s)) return false;
  // a monotonic solve that fails (no convergence of the general solver, say) is not
  // the path's verdict: the march may still follow it
  try {
    return add_on_ray_solved(h, q, s, next);
  } catch (const core::error &) {
    return false;
  }
}

bool add_on_ray_solved(hs_history &h, double q, double s, core::ray_path<double> &next) {
  const auto far = next.farthest();
  double at = 0;
  if (!far.zero() &&
      core::ramp_recedes<double>(far.q, far.s, [&](double qq, double ss) { return mono_half_width(h, qq, ss); }, at))
    return false;
  const auto &plan = next.vertices().back();
  struct mono_values {
    double b1, b2, E1, E2;
    int dir1, dir2;
  };
  double est = 0;
  auto mono = [&](const core::ray_load<double> &l) {
    const auto sol = mono_at(h, l.q, l.s);
    mono_values m;
    sol->visit([&](const auto &v) {
      m.b1 = double(v.b1());
      m.b2 = double(v.b2());
      m.dir1 = v.dir1();
      m.dir2 = v.dir2();
      m.E1 = double(v.energy(1));
      m.E2 = double(v.energy(2));
    });
    est += 2 * sol->error_estimate;
    return m;
  };
  ray_vertex_rec rec;
  rec.q = q;
  rec.s = s;
  rec.r = core::ray_evaluate<double>(plan, mono, h.scene.a,
                                     h.ray_vertices.empty() ? nullptr : &h.ray_vertices.back().r);
  require(std::isfinite(rec.r.energy1) && std::isfinite(rec.r.energy2), core::status::overflow,
          "history: an energy is not representable");
  rec.error_estimate = est;
  for (const auto &t : plan.terms)
    if (!t.load.zero()) rec.parts.push_back({t.coef, mono_at(h, t.load.q, t.load.s)});
  if (rec.parts.empty()) rec.parts.push_back({1, mono_at(h, 0.0, 0.0)});  // unloaded: zero traction
  h.ray = std::move(next);
  h.ray_vertices.push_back(std::move(rec));
  return true;
}

// Leaves the superposition or the static solves: the march replays the path so far.
void to_march(hs_history &h) {
  if (!h.ray_mode && !h.static_mode) return;
  // the march models no interior slip zone: a path on which the static solves took one is not
  // replayed in it unless patches are merged (an approximation the caller asked for)
  if (h.static_mode && h.st && h.st->patch_segments() > 0 && h.opts.interior_patches == HS_PATCHES_ERROR)
    throw core::error(core::status::not_applicable,
                      "history: the static solves cannot take this segment, and the march cannot replay the path "
                      "before it: an interior slip zone opened on an earlier segment (interior_patches = "
                      "HS_PATCHES_MERGE marches the path, merging the patch into the edge zone, an approximation)");
  // into a fresh march: if the replay fails, the history stays as it was
  auto m = std::make_unique<core::refined_history<double>>(h.pm, h.march_options, h.march_rtol);
  for (size_t i = 0; i < h.input.size(); ++i) {
    m->add_vertex(h.input[i].first, h.input[i].second);
    m->tag_last_vertex(h.vertex_cycle(i));  // periodic loading's tags carried over
  }
  // the replay against the exact states of the vertices so far (ends over a, energies over the
  // largest): a march that misses an interior patch's slip (a patch that opened and merged with
  // an edge zone within a segment; random walk seed 8, vertex 3: zone 2's energy 20 % short, with
  // a local estimate of 1.2e-8) is off there, and says so in its estimate
  {
    const auto &sc = h.scene;
    const double escale = sc.f * sc.f * sc.p0 * sc.p0 * sc.a * sc.a / sc.Estar;
    std::vector<std::array<double, 4>> exact;  // b1/a, b2/a, E1, E2 (canonical)
    if (h.ray_mode)
      for (const auto &v : h.ray_vertices) exact.push_back({v.r.b1 / sc.a, v.r.b2 / sc.a, v.r.energy1 / escale, v.r.energy2 / escale});
    else
      for (const auto &v : h.static_vertices) {
        // (an interior slip zone's energy to the zone on whose side of the stick zone's centre it
        // lies: the march, merging it, counts it there)
        const auto &st = *v.snap;
        const bool right = st.patch_dir() != 0 && st.patch_l() + st.patch_r() > st.b1() - st.b2();
        exact.push_back({st.b1(), st.b2(), v.E1 + (right ? v.Ep : 0.0), v.E2 + (right ? 0.0 : v.Ep)});
      }
    double emax = 0, d = 0;
    for (const auto &e : exact) emax = std::max({emax, std::fabs(e[2]), std::fabs(e[3])});
    const auto &mv = m->fine().vertices();
    for (size_t i = 0; i < exact.size() && i < mv.size(); ++i) {
      d = std::max({d, std::fabs(mv[i].b1 - exact[i][0]), std::fabs(mv[i].b2 - exact[i][1])});
      if (emax > 0)
        d = std::max(d, std::max(std::fabs(mv[i].energy1 - exact[i][2]), std::fabs(mv[i].energy2 - exact[i][3])) / emax);
    }
    h.march_measured = std::isfinite(d) ? d : 1.0;
  }
  h.h = std::move(m);
  h.ray_mode = false;
  h.static_mode = false;
  h.ray_vertices.clear();
  h.static_vertices.clear();
  h.st.reset();
  h.mono_cache.clear();
}

// One vertex by a static solve from the history's static state (canonical loads); false
// (nothing changed) when the segment does not only advance (not_applicable).
// interior (optional): set when the segment was refused because its state leaves the stick traction
// past the friction limit inside the stick zone (an interior slip zone).
// A segment that the reduced accuracy asked (acc, from hs_history_options.rtol) refuses is solved
// again at full accuracy before it is refused: the reduced orders are chosen for accuracy, and a
// crossing or a limit check can fail at them where full accuracy takes the segment (Hertz random
// walk 21 of bench_history, vertex 7: "did not converge"). The next segments go on at acc.
bool add_static(const core::static_history<double> &from, double q, double s,
                std::shared_ptr<const core::static_history<double>> &to, hs_history::static_vertex_rec &rec,
                const core::static_history_accuracy<double> &acc, bool *interior = nullptr,
                std::string *why = nullptr) {
  auto attempt = [&](const core::static_history_accuracy<double> *full) -> std::shared_ptr<core::static_history<double>> {
    auto next = std::make_shared<core::static_history<double>>(from);
    if (full) next->set_accuracy(*full);
    try {
      next->add_vertex(q, s);
    } catch (const core::error &e) {
      if (e.code() == core::status::not_applicable || e.code() == core::status::no_convergence) {
        if (interior) *interior = std::strstr(e.what(), "interior slip zone") != nullptr;
        if (why) *why = e.what();
        return nullptr;
      }
      throw;
    }
    if (full) next->set_accuracy(acc);
    return next;
  };
  auto next = attempt(nullptr);
  if (!next && from.rtol() > 0) {
    const core::static_history_accuracy<double> full;
    next = attempt(&full);
  }
  if (!next) return false;
  rec.E1 = double(next->last_segment().E1);
  rec.E2 = double(next->last_segment().E2);
  rec.Ep = double(next->last_segment().Ep);
  require(std::isfinite(rec.E1) && std::isfinite(rec.E2) && std::isfinite(rec.Ep), core::status::overflow,
          "history: an energy is not representable");
  rec.snap = next;
  to = std::move(next);
  return true;
}

// Leaves the superposition for the static solves: they replay the path so far. False
// (nothing changed) if a segment of it cannot be taken that way.
bool to_static(hs_history &h) {
  if (!h.ray_mode) return h.static_mode;
  std::shared_ptr<const core::static_history<double>> cur =
      std::make_shared<core::static_history<double>>(h.pm, h.static_accuracy);
  std::vector<hs_history::static_vertex_rec> recs;
  for (size_t i = 0; i < h.input.size(); ++i) {
    hs_history::static_vertex_rec rec;
    std::shared_ptr<const core::static_history<double>> nx;
    if (!add_static(*cur, h.input[i].first, h.input[i].second, nx, rec, h.static_accuracy)) return false;
    rec.cycle = h.vertex_cycle(i);  // periodic loading's tags carried over
    cur = nx;
    recs.push_back(std::move(rec));
  }
  h.st = cur;
  h.static_vertices = std::move(recs);
  h.static_mode = true;
  h.ray_mode = false;
  h.ray_vertices.clear();
  h.mono_cache.clear();
  return true;
}

}  // namespace

namespace {
// A vertex whose static solve leaves an interior slip zone: the march's sparse check of the friction
// limit can miss it and return the zones with a patch's slip left out (Hertz (0, 1.5) -> (0.15, 1.5)
// -> (0.25, 1.2): zone 2's energy at the last vertex 1.47e-6 against the BEM's 6.6e-5, estimate
// 1.4e-8), so with HS_PATCHES_ERROR the history stops there.
constexpr const char *static_interior_message =
    "history: an interior slip zone opens on the segment to this vertex (the static solve's stick traction "
    "passes the friction limit inside the stick zone): more zones than the methods model (interior_patches = "
    "HS_PATCHES_MERGE marches it, merging the patch into the edge zone, an approximation)";

// The march after the static solves refused a segment: if it fails too, its error says also why
// the static solves stopped, and where (they may have gone further: the march models no interior
// slip zone and no slip back at the edge)
template <class F> void with_static_refusal(hs_history &h, F &&body) {
  const std::string why = std::move(h.static_refusal);
  const size_t at = h.static_refusal_at;
  h.static_refusal.clear();
  try {
    body();
  } catch (const core::error &) {
    // (core::error carries a static message: the note goes to hs_history_last_error's text)
    if (!why.empty())
      h.last_error_note = "; the static solves had stopped at vertex " + std::to_string(at) + " of the path: " + why;
    throw;
  }
}

// body() with its error's message kept in h->last_error (cleared on success)
template <class F> void keeping_error(hs_history *h, F &&body) {
  require(h != nullptr, core::status::null_pointer, "NULL history");
  try {
    body();
    h->last_error.clear();
  } catch (const std::exception &e) {
    h->last_error = e.what();
    h->last_error += h->last_error_note;
    h->last_error_note.clear();
    throw;
  }
}
}  // namespace

int hs_history_last_error(const hs_history *h, char *buf, size_t size) {
  return guard([&] {
    require(h != nullptr && buf != nullptr, core::status::null_pointer, "NULL");
    require(size >= 1, core::status::bad_size, "size must be >= 1");
    const size_t len = std::min(h->last_error.size(), size - 1);
    std::memcpy(buf, h->last_error.data(), len);
    buf[len] = '\0';
  });
}

int hs_history_add_vertices(hs_history *h, size_t n, const double *q, const double *s) {
  return guard([&] { keeping_error(h, [&] {
    require(h != nullptr && (n == 0 || (q != nullptr && s != nullptr)), core::status::null_pointer, "NULL");
    for (size_t i = 0; i < n; ++i) {
      if (h->ray_mode && add_on_ray(*h, q[i], s[i])) {
        h->input.emplace_back(q[i], s[i]);
        continue;
      }
      // off the ray: the static solves, while every segment advances
      require(std::isfinite(q[i]) && std::isfinite(s[i]), core::status::not_finite,
              "history: a path vertex is not finite");
      require(std::fabs(q[i]) < 1, core::status::gross_sliding, "history: |Q| >= fP at a path vertex: gross sliding");
      bool seen = false;  // the static solves saw an interior slip zone on this segment
      h->static_refusal.clear();
      if ((h->ray_mode || h->static_mode) && to_static(*h)) {
        hs_history::static_vertex_rec rec;
        std::shared_ptr<const core::static_history<double>> nx;
        bool interior = false;
        if (add_static(*h->st, q[i], s[i], nx, rec, h->static_accuracy, &interior, &h->static_refusal)) {
          h->st = nx;
          h->static_vertices.push_back(std::move(rec));
          h->input.emplace_back(q[i], s[i]);
          continue;
        }
        h->static_refusal_at = h->input.size() + 1;
        if (interior && h->opts.interior_patches == HS_PATCHES_ERROR)
          throw core::error(core::status::not_applicable, static_interior_message);
        seen = interior;
      }
      with_static_refusal(*h, [&] {
        to_march(*h);
        h->h->add_vertex(q[i], s[i]);
      });
      if (seen) h->static_patch_at.push_back(h->input.size());
      h->input.emplace_back(q[i], s[i]);
    }
  }); });
}

namespace {
// Periodic loading whose every vertex lies on the path's ray (in phase or one
// amplitude zero, with means on the same ray, e.g. zero): core::add_cycles on the
// superposition. The adapter is the history interface add_cycles needs; its
// vertices are canonical (b / a, energies / f^2 p0^2 a^2 / E*), as the march's.
struct leave_ray {};
struct ray_cycles_adapter {
  struct view {
    double energy1, energy2, b1, b2, energyp;
  };
  hs_history &h;
  std::vector<view> vs;
  double escale;
  explicit ray_cycles_adapter(hs_history &hh) : h(hh) {
    const auto &sc = h.scene;
    escale = sc.f * sc.f * sc.p0 * sc.p0 * sc.a * sc.a / sc.Estar;
    for (const auto &v : h.ray_vertices) vs.push_back(of(v));
  }
  view of(const ray_vertex_rec &v) const {
    return {v.r.energy1 / escale, v.r.energy2 / escale, v.r.b1 / h.scene.a, v.r.b2 / h.scene.a, 0.0};
  }
  void add_vertex(double q, double s) {
    if (!add_on_ray(h, q, s)) throw leave_ray{};
    h.input.emplace_back(q, s);
    vs.push_back(of(h.ray_vertices.back()));
  }
  const std::vector<view> &vertices() const { return vs; }
  void tag_last_vertex(int c) { h.ray_vertices.back().cycle = c; }
  double q() const { return h.input.empty() ? 0.0 : h.input.back().first; }
  double s() const { return h.input.empty() ? 0.0 : h.input.back().second; }
};

// Periodic loading off the ray by static solves (issue 14): core::add_cycles on them while
// every segment is one they take, as hs_history_add_vertices does vertex by vertex; the
// first segment they cannot take leaves them (the march replays the path).
struct leave_static {};
struct static_interior {};  // a static solve found an interior slip zone (HS_PATCHES_ERROR: stop)
struct static_cycles_adapter {
  struct view {
    double energy1, energy2, b1, b2, energyp;
  };
  hs_history &h;
  std::vector<view> vs;
  explicit static_cycles_adapter(hs_history &hh) : h(hh) {
    for (const auto &v : h.static_vertices) vs.push_back(of(v));
  }
  static view of(const hs_history::static_vertex_rec &v) { return {v.E1, v.E2, v.snap->b1(), v.snap->b2(), v.Ep}; }
  void add_vertex(double q, double s) {
    hs_history::static_vertex_rec rec;
    std::shared_ptr<const core::static_history<double>> nx;
    bool interior = false;
    if (!add_static(*h.st, q, s, nx, rec, h.static_accuracy, &interior, &h.static_refusal)) {
      h.static_refusal_at = h.input.size() + 1;
      if (interior && h.opts.interior_patches == HS_PATCHES_ERROR) throw static_interior{};
      if (interior) h.cycle_patch_at = h.input.size();
      throw leave_static{};
    }
    h.st = nx;
    h.static_vertices.push_back(std::move(rec));
    h.input.emplace_back(q, s);
    vs.push_back(of(h.static_vertices.back()));
  }
  const std::vector<view> &vertices() const { return vs; }
  void tag_last_vertex(int c) { h.static_vertices.back().cycle = c; }
  double q() const { return h.input.empty() ? 0.0 : h.input.back().first; }
  double s() const { return h.input.empty() ? 0.0 : h.input.back().second; }

  // The steady cycle (core::add_cycles, hdetail::repeats_cycles). The change of the state over the
  // cycle whose vertices start at first: the larger of the ends' moves (over a) and the L1 distance
  // of the tractions over the contact, relative to that of the friction limit p (2001 points:
  // the difference of two states, so its sampling error is relative to it). -1 where no point
  // stays stuck through the cycle (the intersection of the stick zones of its start and every
  // vertex, less the interior slip zones open at them, is empty; a segment that dissipated in a
  // patch closed by its vertex counts as covering the whole stick zone): the slip over the cycle
  // could then be a rigid drift, which copies would not carry.
  double cycle_change(size_t first) const {
    const auto &V = h.static_vertices;
    if (first == 0 || first > V.size() || V.size() - first < 2) return -1;
    const auto &A = *V[first - 1].snap, &B = *V.back().snap;
    double lo = -A.b2(), hi = A.b1();
    std::vector<std::pair<double, double>> patches;
    for (size_t k = first - 1; k < V.size(); ++k) {
      const auto &st = *V[k].snap;
      lo = std::max(lo, -st.b2());
      hi = std::min(hi, st.b1());
      if (st.patch_dir() != 0) patches.push_back({st.patch_l(), st.patch_r()});
      else if (k >= first && V[k].Ep != 0) return -1;
    }
    // (a point of (lo, hi) outside every patch: a gap left of the next patch, or right of all)
    std::sort(patches.begin(), patches.end());
    double at = lo;
    bool stuck = false;
    for (const auto &p : patches) {
      if (p.first > at) {
        stuck = at < hi;
        break;
      }
      at = std::max(at, p.second);
    }
    if (!stuck) stuck = at < hi;
    if (!(hi > lo) || !stuck) return -1;
    const int n = 2000;
    double dq = 0, pl = 0;
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, w = (i == 0 || i == n) ? 0.5 : 1.0;
      dq += w * std::fabs(B.traction(x) - A.traction(x));
      pl += w * std::fabs(A.pressure().p(x));
    }
    if (!std::isfinite(dq) || !(pl > 0) || !std::isfinite(pl)) return -1;
    const double d = std::max({std::fabs(B.b1() - A.b1()), std::fabs(B.b2() - A.b2()), dq / pl});
    return std::isfinite(d) ? d : -1;
  }
  double state_accuracy() const { return h.march_rtol; }
  // add_vertex's refusals of a segment (the march would otherwise replay the path, or the history
  // stop at an interior slip zone); any other exception is an error
  static bool refused(std::exception_ptr e) {
    try {
      std::rethrow_exception(e);
    } catch (const leave_static &) {
      return true;
    } catch (const static_interior &) {
      return true;
    } catch (...) {
      return false;
    }
  }
  // back to the first n vertices (a cycle that failed part way)
  void truncate(size_t n) {
    h.static_vertices.resize(n);
    h.input.resize(n);
    vs.resize(n);
    if (n > 0) h.st = h.static_vertices.back().snap;
  }
  // vertices [first, end) again, as cycle c
  void repeat_cycle(size_t first, size_t end, int c, double extra) {
    for (size_t k = first; k < end; ++k) {
      hs_history::static_vertex_rec rec = h.static_vertices[k];
      rec.copy = true;
      rec.q = h.input[k].first;
      rec.s = h.input[k].second;
      rec.copy_estimate = std::max(rec.copy_estimate, extra);
      rec.cycle = c;
      h.input.push_back(h.input[k]);
      h.static_vertices.push_back(rec);
      vs.push_back(of(rec));
    }
    h.st = h.static_vertices.back().snap;
  }
};

// core::add_cycles on one of the cheaper methods (its adapter); on any failure the history is
// put back as it was (restore) and false returned, for the next method to replay the path
template <class Adapter, class Restore>
bool cycles_by(hs_history &h, const Restore &restore, double qm, double qa, double sm, double sa, double phase_deg,
               int cycles) {
  try {
    Adapter ad(h);
    h.cycles = core::add_cycles<double>(ad, qm, qa, sm, sa, phase_deg, cycles, core::ramp_order(h.opts.ramp_order),
                                        h.opts.segments_per_cycle, h.opts.steady_rtol);
    h.has_cycles = true;
    return true;
  } catch (const static_interior &) {
    restore();
    throw core::error(core::status::not_applicable, static_interior_message);
  } catch (...) {
    restore();
    return false;
  }
}
}  // namespace

int hs_history_add_cycles(hs_history *h, double qm, double qa, double sm, double sa, double phase_deg, int cycles) {
  return guard([&] { keeping_error(h, [&] {
    // bad arguments first: each method below is tried and undone on any failure
    core::check_cycles<double>(qm, qa, sm, sa, phase_deg, cycles, h->opts.segments_per_cycle);
    const size_t ni0 = h->input.size();
    h->cycle_patch_at = size_t(-1);
    h->static_refusal.clear();
    // on the ray: the superposition
    if (h->ray_mode) {
      const auto ray0 = h->ray;
      const size_t nv0 = h->ray_vertices.size();
      auto restore = [&] {
        h->ray = ray0;
        h->ray_vertices.resize(nv0);
        h->input.resize(ni0);
      };
      if (cycles_by<ray_cycles_adapter>(*h, restore, qm, qa, sm, sa, phase_deg, cycles)) return;
    }
    // off the ray: the static solves while they take every segment
    if ((h->ray_mode || h->static_mode) && to_static(*h)) {
      const auto st0 = h->st;
      const size_t nv0 = h->static_vertices.size();
      auto restore = [&] {
        h->st = st0;
        h->static_vertices.resize(nv0);
        h->input.resize(ni0);
      };
      if (cycles_by<static_cycles_adapter>(*h, restore, qm, qa, sm, sa, phase_deg, cycles)) return;
    }
    // else the march replays the whole path
    with_static_refusal(*h, [&] {
      to_march(*h);
      h->cycles = h->h->add_cycles(qm, qa, sm, sa, phase_deg, cycles, core::ramp_order(h->opts.ramp_order),
                                   h->opts.segments_per_cycle, h->opts.steady_rtol);
    });
    h->has_cycles = true;
    if (h->cycle_patch_at != size_t(-1)) h->static_patch_at.push_back(h->cycle_patch_at);
  }); });
}

int hs_history_method(const hs_history *h, int *method) {
  return guard([&] {
    require(h != nullptr && method != nullptr, core::status::null_pointer, "NULL");
    *method = h->ray_mode ? HS_HISTORY_SUPERPOSITION : h->static_mode ? HS_HISTORY_STATIC : HS_HISTORY_MARCH;
  });
}

int hs_history_vertex_count(const hs_history *h, size_t *n) {
  return guard([&] {
    require(h != nullptr && n != nullptr, core::status::null_pointer, "NULL");
    *n = h->vertex_count();
  });
}

namespace {
// hs_history_vertex as it was in 0.4.0 (before the patch fields): its size, with the tail padding of
// the platform (on LLP64 the last long leaves 4 bytes after it, which offsetof(patch_dir) misses)
struct history_vertex_v040 {
  size_t struct_size;
  double Q_over_fP, sigma_over_fp0;
  double b1, b2;
  int slip_dir1, slip_dir2;
  double energy1, energy2;
  int cycle;
  long steps;
  double step;
  double error_estimate;
  long interior_merges;
};
static_assert(offsetof(history_vertex_v040, interior_merges) == offsetof(hs_history_vertex, interior_merges),
              "the 0.4.0 layout of hs_history_vertex");
// hs_cycle_summary as it was in 0.4.0
struct cycle_summary_v040 {
  size_t struct_size;
  int cycles, cycles_to_steady, shakedown;
  double energy_per_cycle1, energy_per_cycle2;
};
static_assert(offsetof(cycle_summary_v040, energy_per_cycle2) == offsetof(hs_cycle_summary, energy_per_cycle2),
              "the 0.4.0 layout of hs_cycle_summary");
}  // namespace

int hs_history_vertex_get(const hs_history *h, size_t i, hs_history_vertex *user) {
  return guard([&] {
    require(h != nullptr && user != nullptr, core::status::null_pointer, "NULL");
    // (a caller's struct from before the patch fields gets the fields it has)
    const size_t size = user->struct_size;
    require(size == sizeof *user || size == sizeof(history_vertex_v040), core::status::struct_size,
            "vertex struct_size");
    require(i < h->vertex_count(), core::status::bad_option, "vertex index out of range");
    hs_history_vertex full{};
    full.struct_size = size;
    // the fields into full, then the caller's part of it (on error the caller's struct is untouched)
    [&](hs_history_vertex *out) {
    const auto &sc = h->scene;
    if (h->ray_mode) {  // superposition: physical units already, no steps
      const auto &v = h->ray_vertices[i];
      out->Q_over_fP = v.q;
      out->sigma_over_fp0 = v.s;
      out->b1 = v.r.b1;
      out->b2 = v.r.b2;
      out->slip_dir1 = v.r.b1 < sc.a ? v.r.dir1 : 0;
      out->slip_dir2 = v.r.b2 < sc.a ? v.r.dir2 : 0;
      out->energy1 = v.r.energy1;
      out->energy2 = v.r.energy2;
      out->cycle = v.cycle;
      out->steps = 0;
      out->step = 0;
      out->error_estimate = v.error_estimate;
      out->interior_merges = 0;
      return;
    }
    const double escale = sc.f * sc.f * sc.p0 * sc.p0 * sc.a * sc.a / sc.Estar;
    if (h->static_mode) {  // static solves: within rtol of the exact static solve (tests/test_static_history.cpp), no steps
      const auto &v = h->static_vertices[i];
      const auto &st = *v.snap;
      out->Q_over_fP = v.copy ? v.q : st.q();
      out->sigma_over_fp0 = v.copy ? v.s : st.s();
      out->b1 = sc.a * st.b1();
      out->b2 = sc.a * st.b2();
      out->slip_dir1 = st.b1() < 1 ? st.dir1() : 0;
      out->slip_dir2 = st.b2() < 1 ? st.dir2() : 0;
      out->energy1 = escale * v.E1;
      out->energy2 = escale * v.E2;
      out->cycle = v.cycle;
      out->steps = 0;
      out->step = 0;
      out->error_estimate = v.estimate(h->march_rtol);
      out->interior_merges = 0;
      out->patch_dir = st.patch_dir();
      out->patch_l = st.patch_dir() ? sc.a * st.patch_l() : 0.0;
      out->patch_r = st.patch_dir() ? sc.a * st.patch_r() : 0.0;
      out->energy_patch = escale * v.Ep;
      return;
    }
    const auto &v = h->h->fine().vertices()[i];
    out->Q_over_fP = v.q;
    out->sigma_over_fp0 = v.s;
    out->b1 = sc.a * v.b1;
    out->b2 = sc.a * v.b2;
    out->slip_dir1 = v.dir1;
    out->slip_dir2 = v.dir2;
    out->energy1 = escale * v.energy1;
    out->energy2 = escale * v.energy2;
    out->cycle = v.cycle;
    out->steps = long(v.step_end);
    out->step = v.step > 0 ? v.step : h->h->step();
    out->error_estimate = std::max(v.step > 0 ? v.error_estimate : h->h->error_estimate(), h->march_measured);
    out->interior_merges = long(v.interior_merges) +
                           long(std::count_if(h->static_patch_at.begin(), h->static_patch_at.end(),
                                              [&](size_t k) { return k <= i; }));
    }(&full);
    std::memcpy(static_cast<void *>(user), &full, std::min(size, sizeof full));
  });
}

namespace {

// q or h at x after vertex i of a path along one ray: the sums over its parts
double ray_field_at(const hs_history &h, size_t i, int field, double x) {
  require(std::isfinite(x), core::status::not_finite, "x");
  require(std::fabs(x) <= h.scene.a, core::status::point_outside, "x outside the contact");
  double r = 0;
  for (const auto &p : h.ray_vertices[i].parts)
    r += p.coef * p.sol->visit([&](const auto &v) { return double(field == HS_FIELD_TRACTION ? v.traction(x) : v.slip(x)); });
  return r;
}

double field_at(const hs_history &h, size_t nsteps, int field, double x) {
  const auto &sc = h.scene;
  require(std::isfinite(x), core::status::not_finite, "x");
  require(std::fabs(x) <= sc.a, core::status::point_outside, "x outside the contact");
  const double xi = x / sc.a;
  if (field == HS_FIELD_TRACTION) return sc.f * sc.p0 * h.h->fine().traction(xi, nsteps);
  return sc.f * sc.p0 * sc.a / sc.Estar * h.h->fine().slip(xi, nsteps);
}

}  // namespace

int hs_history_eval(const hs_history *h, size_t vertex, int field, size_t n, const double *x, double *out) {
  return guard([&] {
    require(h != nullptr && (n == 0 || (x != nullptr && out != nullptr)), core::status::null_pointer, "NULL");
    require(vertex < h->vertex_count(), core::status::bad_option, "vertex index out of range");
    require(field == HS_FIELD_TRACTION || field == HS_FIELD_SLIP, core::status::bad_option, "field");
    std::vector<double> tmp(n);
    if (h->ray_mode) {
      for (size_t i = 0; i < n; ++i) tmp[i] = ray_field_at(*h, vertex, field, x[i]);
      std::copy(tmp.begin(), tmp.end(), out);
      return;
    }
    if (h->static_mode) {
      const auto &sc = h->scene;
      const auto &st = *h->static_vertices[vertex].snap;
      for (size_t i = 0; i < n; ++i) {
        require(std::isfinite(x[i]), core::status::not_finite, "x");
        require(std::fabs(x[i]) <= sc.a, core::status::point_outside, "x outside the contact");
        const double xi = x[i] / sc.a;
        tmp[i] = field == HS_FIELD_TRACTION ? sc.f * sc.p0 * st.traction(xi)
                                            : sc.f * sc.p0 * sc.a / sc.Estar * st.slip(xi);
      }
      std::copy(tmp.begin(), tmp.end(), out);
      return;
    }
    const size_t ns = h->h->fine().vertices()[vertex].step_end;
    for (size_t i = 0; i < n; ++i) tmp[i] = field_at(*h, ns, field, x[i]);
    std::copy(tmp.begin(), tmp.end(), out);
  });
}

int hs_history_state(const hs_history *h, size_t vertex, hs_solution **out) {
  return guard([&] {
    require(h != nullptr && out != nullptr, core::status::null_pointer, "NULL");
    require(vertex < h->vertex_count(), core::status::bad_option, "vertex index out of range");
    if (h->ray_mode) {
      const auto &v = h->ray_vertices[vertex];
      auto r = std::make_unique<hs_solution>();
      r->solution.emplace<hs::capi::ray_state>(v.parts, h->scene, v.q, v.s, v.r.b1, v.r.b2, v.r.dir1, v.r.dir2);
      r->model_used = 0;
      r->error_estimate = v.error_estimate;
      *out = r.release();
      return;
    }
    if (h->static_mode) {
      auto r = std::make_unique<hs_solution>();
      r->solution.emplace<hs::capi::static_state>(h->static_vertices[vertex].snap, h->scene);
      r->model_used = 0;
      r->error_estimate = h->static_vertices[vertex].estimate(h->march_rtol);
      *out = r.release();
      return;
    }
    const auto &vs = h->h->fine().vertices();
    const auto &v = vs[vertex];
    auto r = std::make_unique<hs_solution>();
    r->solution.emplace<hs::capi::history_state>(h->h->fine().prefix(v.step_end), h->scene, v);
    r->model_used = 0;
    r->error_estimate = std::max(v.step > 0 ? v.error_estimate : h->h->error_estimate(), h->march_measured);
    *out = r.release();
  });
}

int hs_history_cycle_summary(const hs_history *h, hs_cycle_summary *user) {
  return guard([&] {
    require(h != nullptr && user != nullptr, core::status::null_pointer, "NULL");
    const size_t size = user->struct_size;
    require(size == sizeof *user || size == sizeof(cycle_summary_v040) ||
                size == offsetof(hs_cycle_summary, cycles_repeated),
            core::status::struct_size, "summary struct_size");
    hs_cycle_summary full{};
    full.struct_size = size;
    hs_cycle_summary *out = &full;
    require(h->has_cycles, core::status::not_applicable, "no periodic loading in this history");
    const auto &sc = h->scene;
    const double escale = sc.f * sc.f * sc.p0 * sc.p0 * sc.a * sc.a / sc.Estar;
    out->cycles = h->cycles.cycles;
    out->cycles_to_steady = h->cycles.cycles_to_steady;
    out->shakedown = h->cycles.shakedown ? 1 : 0;
    out->energy_per_cycle1 = escale * h->cycles.energy1;
    out->energy_per_cycle2 = escale * h->cycles.energy2;
    out->energy_per_cycle_patch = escale * h->cycles.energyp;
    out->cycles_repeated = h->cycles.cycles_repeated;
    out->repeated_change = h->cycles.repeated_change;
    std::memcpy(static_cast<void *>(user), &full, std::min(size, sizeof full));
  });
}

namespace {
// the slip h at x (dimensional) after vertex k, whichever method holds the states
double vertex_slip(const hs_history &h, size_t k, double x) {
  if (h.ray_mode) return ray_field_at(h, k, HS_FIELD_SLIP, x);  // the superposed states
  if (h.static_mode) {
    const auto &sc = h.scene;
    require(std::isfinite(x), core::status::not_finite, "x");
    require(std::fabs(x) <= sc.a, core::status::point_outside, "x outside the contact");
    return sc.f * sc.p0 * sc.a / sc.Estar * h.static_vertices[k].snap->slip(x / sc.a);
  }
  return field_at(h, h.h->fine().vertices()[k].step_end, HS_FIELD_SLIP, x);
}
}  // namespace

int hs_history_slip_range(const hs_history *h, size_t n, const double *x, double *out) {
  return guard([&] {
    require(h != nullptr && (n == 0 || (x != nullptr && out != nullptr)), core::status::null_pointer, "NULL");
    require(h->has_cycles, core::status::not_applicable, "no periodic loading in this history");
    const auto &c = h->cycles;
    std::vector<double> tmp(n);
    for (size_t i = 0; i < n; ++i) {
      // from the state before the cycle (the unloaded start when the cycle begins the history)
      double lo = 0, hi = 0;
      bool first = c.last_cycle_first > 0;
      for (size_t k = c.last_cycle_first > 0 ? c.last_cycle_first - 1 : 0; k < c.last_cycle_end; ++k) {
        const double v = vertex_slip(*h, k, x[i]);
        if (first || v < lo) lo = v;
        if (first || v > hi) hi = v;
        first = false;
      }
      tmp[i] = hi - lo;
    }
    std::copy(tmp.begin(), tmp.end(), out);
  });
}

namespace {
// The monotonic stick half-width (units of a) at canonical loads, for the solution's pressure.
double half_width_at(const hs_solution &sol, double q, double s) {
  if (sol.model && !std::holds_alternative<core::hertz_solution<double>>(sol.solution)) {
    core::general_scene<double> g;  // canonical units: a = p0 = f = E* = 1
    g.q = q;
    g.s = s;
    return core::solve_general<double>(*sol.model, g).half_width();
  }
  core::hertz_scene<double> hz;
  hz.q = q;
  hz.s = s;
  return core::solve_hertz<double>(hz).half_width();
}
}  // namespace

int hs_solution_ramp(const hs_solution *sol, int *recedes, double *at) {
  return guard([&] {
    require(sol != nullptr && recedes != nullptr && at != nullptr, core::status::null_pointer, "NULL");
    require(!std::holds_alternative<hs::capi::history_state>(sol->solution) &&
                !std::holds_alternative<hs::capi::ray_state>(sol->solution) &&
                !std::holds_alternative<hs::capi::static_state>(sol->solution),
            core::status::not_applicable,
            "a load-history state is not a monotonic solution");
    const double q = sol->visit([](const auto &v) { return double(v.scene.q); });
    const double s = sol->visit([](const auto &v) { return double(v.scene.s); });
    double where = std::numeric_limits<double>::quiet_NaN();
    const bool r = core::ramp_recedes<double>(
        q, s, [&](double qq, double ss) { return half_width_at(*sol, qq, ss); }, where);
    *recedes = r ? 1 : 0;
    *at = r ? where : std::numeric_limits<double>::quiet_NaN();
  });
}

int hs_solution_steady_cycle(const hs_solution *sol, hs_steady_cycle *out) {
  return guard([&] {
    require(sol != nullptr && out != nullptr, core::status::null_pointer, "NULL");
    require(!std::holds_alternative<hs::capi::history_state>(sol->solution) &&
                !std::holds_alternative<hs::capi::ray_state>(sol->solution) &&
                !std::holds_alternative<hs::capi::static_state>(sol->solution),
            core::status::not_applicable,
            "a load-history state is not a monotonic solution");
    require(out->struct_size == sizeof *out, core::status::struct_size, "steady cycle struct_size");
    const double q = sol->visit([](const auto &v) { return double(v.scene.q); });
    const double s = sol->visit([](const auto &v) { return double(v.scene.s); });
    const double e1 = sol->visit([](const auto &v) { return double(v.energy(1)); });
    const double e2 = sol->visit([](const auto &v) { return double(v.energy(2)); });
    require(std::isfinite(e1) && std::isfinite(e2), core::status::overflow, "energy not representable");
    const auto c = core::proportional_steady_cycle<double>(
        q, s, [&] { return half_width_at(*sol, q, s); }, e1, e2);
    out->valid = c.valid ? 1 : 0;
    out->cycles_to_steady = c.cycles_to_steady;
    out->energy_per_cycle1 = c.energy1;
    out->energy_per_cycle2 = c.energy2;
  });
}
