// The input contract of the C ABI, table-driven: every entry point with every
// kind of bad input gets its specific status code, a message from
// hs_strerror, no crash, and untouched outputs.
#include <doctest/doctest.h>
#include <halfslip/halfslip.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace {

const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();
const double Den = std::numeric_limits<double>::denorm_min();
const double Huge = std::numeric_limits<double>::max();

hs_scene scene(std::function<void(hs_scene &)> edit) {
  hs_scene s;
  hs_scene_default(&s);
  edit(s);
  return s;
}

int solve_status(const hs_scene &s, const hs_options *o = nullptr) {
  hs_solution *sol = reinterpret_cast<hs_solution *>(0x1);  // must be left untouched on error
  const int st = hs_solve(&s, o, &sol);
  if (st == HS_OK) hs_solution_free(sol);
  else CHECK(sol == reinterpret_cast<hs_solution *>(0x1));
  return st;
}

struct row {
  const char *what;
  int expected;
  std::function<int()> call;
};

}  // namespace

TEST_CASE("C ABI input contract: every bad input has its status code and message") {
  hs_solution *good = nullptr;
  {
    hs_scene s;
    hs_scene_default(&s);
    s.Q_over_fP = 0.4;
    s.sigma_over_fp0 = 0.1;
    REQUIRE(hs_solve(&s, nullptr, &good) == HS_OK);
  }
  double x2[2] = {0.5, -0.5}, out2[2] = {7, 7};
  hs_options opts;
  hs_options_default(&opts);
  auto with_opts = [&](std::function<void(hs_options &)> edit) {
    hs_options o = opts;
    edit(o);
    return solve_status(scene([](hs_scene &) {}), &o);
  };
  const std::vector<row> rows = {
      // scene values
      {"Q/fP NaN", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = NaN; })); }},
      {"Q/fP +Inf", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = Inf; })); }},
      {"sigma -Inf", HS_ERR_NOT_FINITE,
       [] { return solve_status(scene([](hs_scene &s) { s.sigma_over_fp0 = -Inf; })); }},
      {"a NaN", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.a = NaN; })); }},
      {"p0 Inf", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.p0 = Inf; })); }},
      {"E* NaN", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.E_star = NaN; })); }},
      {"f NaN", HS_ERR_NOT_FINITE, [] { return solve_status(scene([](hs_scene &s) { s.f = NaN; })); }},
      {"a = 0", HS_ERR_BAD_SIZE, [] { return solve_status(scene([](hs_scene &s) { s.a = 0; })); }},
      {"a < 0", HS_ERR_BAD_SIZE, [] { return solve_status(scene([](hs_scene &s) { s.a = -1; })); }},
      {"p0 < 0", HS_ERR_BAD_SIZE, [] { return solve_status(scene([](hs_scene &s) { s.p0 = -2; })); }},
      {"E* = 0", HS_ERR_BAD_SIZE, [] { return solve_status(scene([](hs_scene &s) { s.E_star = 0; })); }},
      {"f = 0", HS_ERR_BAD_FRICTION, [] { return solve_status(scene([](hs_scene &s) { s.f = 0; })); }},
      {"f < 0", HS_ERR_BAD_FRICTION, [] { return solve_status(scene([](hs_scene &s) { s.f = -0.3; })); }},
      {"Q = fP", HS_ERR_GROSS_SLIDING, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = 1; })); }},
      {"Q = -fP", HS_ERR_GROSS_SLIDING, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = -1; })); }},
      {"Q > fP", HS_ERR_GROSS_SLIDING, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = 1e300; })); }},
      {"geometry 0", HS_ERR_BAD_GEOMETRY, [] { return solve_status(scene([](hs_scene &s) { s.geometry = 0; })); }},
      {"geometry 99", HS_ERR_BAD_GEOMETRY, [] { return solve_status(scene([](hs_scene &s) { s.geometry = 99; })); }},
      {"struct_size 0", HS_ERR_STRUCT_SIZE,
       [] { return solve_status(scene([](hs_scene &s) { s.struct_size = 0; })); }},
      {"struct_size +8", HS_ERR_STRUCT_SIZE,
       [] { return solve_status(scene([](hs_scene &s) { s.struct_size = sizeof(hs_scene) + 8; })); }},
      // valid extremes: denormal and huge sizes solve; the unrepresentable stick zone is reported
      {"a denormal", HS_OK, [] { return solve_status(scene([](hs_scene &s) { s.a = Den; })); }},
      {"a, p0 huge", HS_OK,
       [] {
         return solve_status(scene([](hs_scene &s) {
           s.a = Huge;
           s.p0 = Huge;
         }));
       }},
      {"Q/fP denormal", HS_OK, [] { return solve_status(scene([](hs_scene &s) { s.Q_over_fP = Den; })); }},
      // issue 13: the Hertz solver carries ln(width), so a stick zone below the double range is answered
      {"sigma huge", HS_OK, [] { return solve_status(scene([](hs_scene &s) { s.sigma_over_fp0 = 1e300; })); }},
      // options
      {"options struct_size", HS_ERR_STRUCT_SIZE,
       [&] { return with_opts([](hs_options &o) { o.struct_size = 1; }); }},
      {"max_iterations 0", HS_ERR_BAD_OPTION, [&] { return with_opts([](hs_options &o) { o.max_iterations = 0; }); }},
      {"max_iterations < 0", HS_ERR_BAD_OPTION,
       [&] { return with_opts([](hs_options &o) { o.max_iterations = -5; }); }},
      {"rtol NaN", HS_ERR_BAD_OPTION, [&] { return with_opts([](hs_options &o) { o.rtol = NaN; }); }},
      {"rtol negative", HS_ERR_BAD_OPTION, [&] { return with_opts([](hs_options &o) { o.rtol = -1e-8; }); }},
      {"rtol too small", HS_ERR_BAD_OPTION, [&] { return with_opts([](hs_options &o) { o.rtol = 1e-20; }); }},
      {"rtol too large", HS_ERR_BAD_OPTION, [&] { return with_opts([](hs_options &o) { o.rtol = 0.5; }); }},
      // null pointers
      {"solve scene NULL", HS_ERR_NULL_POINTER,
       [] {
         hs_solution *s = nullptr;
         return hs_solve(nullptr, nullptr, &s);
       }},
      {"solve out NULL", HS_ERR_NULL_POINTER,
       [] {
         hs_scene s;
         hs_scene_default(&s);
         return hs_solve(&s, nullptr, nullptr);
       }},
      {"scene_default NULL", HS_ERR_NULL_POINTER, [] { return hs_scene_default(nullptr); }},
      {"options_default NULL", HS_ERR_NULL_POINTER, [] { return hs_options_default(nullptr); }},
      {"version NULL", HS_ERR_NULL_POINTER,
       [] {
         int a, b;
         return hs_version(&a, &b, nullptr);
       }},
      {"summary NULL solution", HS_ERR_NULL_POINTER,
       [] {
         hs_summary m;
         m.struct_size = sizeof m;
         return hs_solution_summary(nullptr, &m);
       }},
      {"summary NULL out", HS_ERR_NULL_POINTER, [&] { return hs_solution_summary(good, nullptr); }},
      {"summary struct_size", HS_ERR_STRUCT_SIZE,
       [&] {
         hs_summary m;
         m.struct_size = 0;
         return hs_solution_summary(good, &m);
       }},
      {"energy NULL", HS_ERR_NULL_POINTER, [&] { return hs_solution_energy(good, nullptr); }},
      {"energy NULL solution", HS_ERR_NULL_POINTER,
       [] {
         double e[2];
         return hs_solution_energy(nullptr, e);
       }},
      // evaluations
      {"eval NULL solution", HS_ERR_NULL_POINTER, [&] { return hs_eval_Bx(nullptr, 2, x2, out2); }},
      {"eval NULL points", HS_ERR_NULL_POINTER, [&] { return hs_eval_slip(good, 2, nullptr, out2); }},
      {"eval NULL output", HS_ERR_NULL_POINTER, [&] { return hs_eval_work(good, 2, x2, nullptr); }},
      {"eval zero points", HS_OK, [&] { return hs_eval_pressure(good, 0, nullptr, nullptr); }},
      {"eval point NaN", HS_ERR_NOT_FINITE,
       [&] {
         double x[2] = {0.5, NaN};
         return hs_eval_Bx(good, 2, x, out2);
       }},
      {"eval point Inf", HS_ERR_NOT_FINITE,
       [&] {
         double x[1] = {-Inf};
         return hs_eval_slip(good, 1, x, out2);
       }},
      {"eval point outside", HS_ERR_POINT_OUTSIDE,
       [&] {
         double x[2] = {0.5, 1.0000001};
         return hs_eval_work(good, 2, x, out2);
       }},
      {"eval point in stick zone", HS_OK,
       [&] {
         double x[1] = {0.0};
         return hs_eval_Bx(good, 1, x, out2);
       }},
      // dimensional helper
      {"loads P = 0", HS_ERR_BAD_SIZE,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(0, 1, 1, 1, 0, 0, &s);
       }},
      {"loads R < 0", HS_ERR_BAD_SIZE,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(1, -1, 1, 1, 0, 0, &s);
       }},
      {"loads f = 0", HS_ERR_BAD_FRICTION,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(1, 1, 1, 0, 0, 0, &s);
       }},
      {"loads Q NaN", HS_ERR_NOT_FINITE,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(1, 1, 1, 1, NaN, 0, &s);
       }},
      {"loads |Q| >= fP", HS_ERR_GROSS_SLIDING,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(1, 1, 1, 0.5, 0.5, 0, &s);
       }},
      {"loads overflow", HS_ERR_OVERFLOW,
       [] {
         hs_scene s;
         return hs_scene_from_hertz_loads(Huge, Huge, 1e-300, 1, 0, 0, &s);
       }},
      {"loads NULL", HS_ERR_NULL_POINTER, [] { return hs_scene_from_hertz_loads(1, 1, 1, 1, 0, 0, nullptr); }},
      // reference backend
      {"ref scene NULL", HS_ERR_NULL_POINTER,
       [] {
         hs_ref_solution *s = nullptr;
         return hs_ref_solve(nullptr, 20, &s);
       }},
      {"ref digits 0", HS_ERR_BAD_OPTION,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 0, &o);
       }},
      {"ref digits > max", HS_ERR_BAD_OPTION,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, hs_ref_max_digits() + 1, &o);
       }},
      {"ref bad decimal", HS_ERR_BAD_NUMBER,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.sigma_over_fp0 = "1.2.3";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref nan text", HS_ERR_BAD_NUMBER,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.Q_over_fP = "nan";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref empty text", HS_ERR_BAD_NUMBER,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.a = "";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref gross sliding", HS_ERR_GROSS_SLIDING,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.Q_over_fP = "-1.5";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref a = 0", HS_ERR_BAD_SIZE,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.a = "0";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref dimensional incomplete", HS_ERR_NULL_POINTER,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.P = "1";
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref struct_size", HS_ERR_STRUCT_SIZE,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.struct_size = 3;
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
      {"ref geometry", HS_ERR_BAD_GEOMETRY,
       [] {
         hs_ref_scene s;
         hs_ref_scene_default(&s);
         s.geometry = 7;
         hs_ref_solution *o = nullptr;
         return hs_ref_solve(&s, 20, &o);
       }},
  };
  std::set<std::string> names;
  for (const auto &r : rows) {
    const std::string what = r.what;
    CAPTURE(what);
    CHECK(names.insert(r.what).second);
    out2[0] = out2[1] = 7;
    const int st = r.call();
    CHECK(st == r.expected);
    CHECK(std::strlen(hs_strerror(st)) > (st == HS_OK ? 0u : 10u));
    if (st != HS_OK) {
      CHECK(out2[0] == 7);  // outputs untouched on error
      CHECK(out2[1] == 7);
    }
  }
  // every code has its own message
  std::set<std::string> msgs;
  for (int c = HS_OK; c <= HS_ERR_BAD_NUMBER; ++c) CHECK(msgs.insert(hs_strerror(c)).second);
  hs_solution_free(good);
}

TEST_CASE("reference buffers: zero-length and short buffers report the size needed") {
  hs_ref_scene s;
  hs_ref_scene_default(&s);
  hs_ref_solution *sol = nullptr;
  REQUIRE(hs_ref_solve(&s, 25, &sol) == HS_OK);
  size_t need = 0;
  int cd = -1;
  CHECK(hs_ref_value(sol, HS_REF_B1, nullptr, 0, &need, &cd) == HS_ERR_BUFFER_TOO_SMALL);
  CHECK(need > 25);
  CHECK(cd == -1);
  std::vector<char> buf(need - 1, 'x');
  CHECK(hs_ref_value(sol, HS_REF_B1, buf.data(), buf.size(), &need, &cd) == HS_ERR_BUFFER_TOO_SMALL);
  CHECK(std::string(buf.begin(), buf.end()) == std::string(need - 1, 'x'));
  buf.resize(need);
  CHECK(hs_ref_value(sol, HS_REF_B1, buf.data(), buf.size(), &need, &cd) == HS_OK);
  CHECK(cd == 25);
  CHECK(hs_ref_value(sol, HS_REF_B1, nullptr, 10, &need, &cd) == HS_ERR_NULL_POINTER);
  hs_ref_solution_summary(nullptr, nullptr);
  hs_ref_summary sm;
  sm.struct_size = 1;
  CHECK(hs_ref_solution_summary(sol, &sm) == HS_ERR_STRUCT_SIZE);
  hs_ref_solution_free(sol);
}

// The closed-form steady proportional cycle against the marched one (an independent
// method: the march knows nothing of the superposition), its validity flag on the
// ray that recedes, and its input contract.
TEST_CASE("hs_solution_steady_cycle: Ciavarella-Jager closed form vs the marched cycle") {
  for (const auto &qs : {std::make_pair(0.5, 0.4), std::make_pair(0.3, 1.0)}) {
    CAPTURE(qs.first);
    hs_scene s;
    hs_scene_default(&s);
    s.Q_over_fP = qs.first;
    s.sigma_over_fp0 = qs.second;
    hs_solution *sol = nullptr;
    REQUIRE(hs_solve(&s, nullptr, &sol) == HS_OK);
    hs_steady_cycle c;
    std::memset(&c, 0, sizeof c);
    c.struct_size = sizeof c;
    REQUIRE(hs_solution_steady_cycle(sol, &c) == HS_OK);
    CHECK(c.valid == 1);
    CHECK(c.cycles_to_steady == 1);
    double e[2];
    REQUIRE(hs_solution_energy(sol, e) == HS_OK);
    CHECK(c.energy_per_cycle1 == 4 * e[0]);
    hs_history_options o;
    hs_history_options_default(&o);
    hs_history *h = nullptr;
    // a max_step so small that the march's budgets (~1/step) would overflow (fuzz_history)
    o.max_step = 1e-300;
    CHECK(hs_history_new(&s, nullptr, &o, &h) == HS_ERR_BAD_OPTION);
    CHECK(h == nullptr);
    o.max_step = 1.0 / 32;
    // a vertex so far away that the segment needs more steps than max_steps: a status at
    // once (its step budgets, ~1e111, overflowed size_t before: fuzz_history)
    REQUIRE(hs_history_new(&s, nullptr, &o, &h) == HS_OK);
    const double qv = 0.1, sv = 1e111;
    CHECK(hs_history_add_vertices(h, 1, &qv, &sv) == HS_ERR_NO_CONVERGENCE);
    size_t nv = 99;
    CHECK(hs_history_vertex_count(h, &nv) == HS_OK);
    CHECK(nv == 0);
    hs_history_free(h);
    h = nullptr;
    o.rtol = 1e-6;
    REQUIRE(hs_history_new(&s, nullptr, &o, &h) == HS_OK);
    REQUIRE(hs_history_add_cycles(h, 0, qs.first, 0, qs.second, 0, 2) == HS_OK);
    hs_cycle_summary m;
    std::memset(&m, 0, sizeof m);
    m.struct_size = sizeof m;
    REQUIRE(hs_history_cycle_summary(h, &m) == HS_OK);
    // the march at rtol 1e-6 (energies relative to the largest, as rtol is defined) was within
    // 1e-7 of 4 E_mono on bench_history's cycle; 2e-6 of the larger zone's energy
    const double scale = std::max(c.energy_per_cycle1, c.energy_per_cycle2);
    CHECK(std::fabs(m.energy_per_cycle1 - c.energy_per_cycle1) <= 2e-6 * scale);
    CHECK(std::fabs(m.energy_per_cycle2 - c.energy_per_cycle2) <= 2e-6 * scale);
    hs_history_free(h);
    // contract
    CHECK(hs_solution_steady_cycle(nullptr, &c) == HS_ERR_NULL_POINTER);
    CHECK(hs_solution_steady_cycle(sol, nullptr) == HS_ERR_NULL_POINTER);
    c.struct_size = sizeof c - 1;
    CHECK(hs_solution_steady_cycle(sol, &c) == HS_ERR_STRUCT_SIZE);
    hs_solution_free(sol);
  }
  // the ray s = 3q recedes before Q/fP = 0.88: the closed form does not apply
  hs_scene s;
  hs_scene_default(&s);
  s.Q_over_fP = 0.88;
  s.sigma_over_fp0 = 2.64;
  hs_solution *sol = nullptr;
  REQUIRE(hs_solve(&s, nullptr, &sol) == HS_OK);
  hs_steady_cycle c;
  std::memset(&c, 0, sizeof c);
  c.struct_size = sizeof c;
  REQUIRE(hs_solution_steady_cycle(sol, &c) == HS_OK);
  CHECK(c.valid == 0);
  int rec = 0;
  double at = 0;
  REQUIRE(hs_solution_ramp(sol, &rec, &at) == HS_OK);
  CHECK(rec == 1);
  hs_solution_free(sol);
}

// Issue 16: hs_solve_batch gives, bitwise, what one hs_solve + summary (+
// energy) per scene gives, for any thread count, with per-scene statuses.
TEST_CASE("hs_solve_batch: bitwise equal to one call per scene, per-scene status, argument checks") {
  std::vector<hs_scene> scenes;
  for (int i = 0; i < 97; ++i) {
    hs_scene sc;
    hs_scene_default(&sc);
    const double q = -0.95 + 1.9 * ((i * 37) % 97) / 96.0;
    const double s = -6 + 12 * ((i * 53) % 97) / 96.0;  // same-sign and opposite-sign scenes, both signs
    sc.Q_over_fP = q;
    sc.sigma_over_fp0 = s;
    scenes.push_back(sc);
  }
  // failing scenes among them: gross sliding, NaN, bad size, wrong struct_size
  scenes[5].Q_over_fP = 1.0;
  scenes[17].sigma_over_fp0 = std::nan("");
  scenes[40].a = -1;
  scenes[63].struct_size = 3;
  for (int flags : {0, HS_BATCH_ENERGIES}) {
    std::vector<hs_batch_result> expect(scenes.size());
    for (size_t i = 0; i < scenes.size(); ++i) {
      hs_batch_result &r = expect[i];
      std::memset(&r, 0, sizeof r);
      hs_solution *sol = nullptr;
      r.status = hs_solve(&scenes[i], nullptr, &sol);
      if (r.status != HS_OK) continue;
      hs_summary su;
      su.struct_size = sizeof su;
      REQUIRE(hs_solution_summary(sol, &su) == HS_OK);
      r.regime = su.regime;
      r.slip_dir1 = su.slip_dir1;
      r.slip_dir2 = su.slip_dir2;
      r.model = su.model;
      r.iterations = su.iterations;
      r.b1 = su.b1;
      r.b2 = su.b2;
      r.d1 = su.d1;
      r.d2 = su.d2;
      r.error_estimate = su.error_estimate;
      if (flags & HS_BATCH_ENERGIES) {
        double e[2];
        REQUIRE(hs_solution_energy(sol, e) == HS_OK);
        r.energy1 = e[0];
        r.energy2 = e[1];
      }
      hs_solution_free(sol);
    }
    CHECK(expect[5].status == HS_ERR_GROSS_SLIDING);
    CHECK(expect[17].status == HS_ERR_NOT_FINITE);
    CHECK(expect[40].status == HS_ERR_BAD_SIZE);
    CHECK(expect[63].status == HS_ERR_STRUCT_SIZE);
    for (int threads : {1, 2, 3, 0, 200}) {
      CAPTURE(threads);
      std::vector<hs_batch_result> got(scenes.size());
      std::memset(got.data(), 0xab, got.size() * sizeof(hs_batch_result));  // no field left unwritten
      REQUIRE(hs_solve_batch(scenes.size(), scenes.data(), nullptr, flags, threads, got.data(),
                             sizeof(hs_batch_result)) == HS_OK);
      for (size_t i = 0; i < scenes.size(); ++i) {
        CAPTURE(i);
        CHECK(std::memcmp(&got[i], &expect[i], sizeof(hs_batch_result)) == 0);
      }
    }
  }
  // argument checks: out untouched
  hs_batch_result one;
  std::memset(&one, 0x5a, sizeof one);
  hs_batch_result keep = one;
  CHECK(hs_solve_batch(1, scenes.data(), nullptr, 0, 1, &one, sizeof one - 8) == HS_ERR_STRUCT_SIZE);
  CHECK(hs_solve_batch(1, scenes.data(), nullptr, 0, -1, &one, sizeof one) == HS_ERR_BAD_OPTION);
  CHECK(hs_solve_batch(1, scenes.data(), nullptr, 4, 1, &one, sizeof one) == HS_ERR_BAD_OPTION);
  CHECK(hs_solve_batch(1, nullptr, nullptr, 0, 1, &one, sizeof one) == HS_ERR_NULL_POINTER);
  CHECK(hs_solve_batch(1, scenes.data(), nullptr, 0, 1, nullptr, sizeof one) == HS_ERR_NULL_POINTER);
  hs_options o;
  hs_options_default(&o);
  o.max_iterations = 0;
  CHECK(hs_solve_batch(1, scenes.data(), &o, 0, 1, &one, sizeof one) == HS_ERR_BAD_OPTION);
  o.max_iterations = 100;
  o.struct_size = 1;
  CHECK(hs_solve_batch(1, scenes.data(), &o, 0, 1, &one, sizeof one) == HS_ERR_STRUCT_SIZE);
  CHECK(std::memcmp(&one, &keep, sizeof one) == 0);
  CHECK(hs_solve_batch(0, nullptr, nullptr, 0, 1, nullptr, sizeof one) == HS_OK);
}
