// Thread safety (issue 7; the reliability stage runs this suite under ThreadSanitizer,
// scripts/reliability.sh): threads that solve or evaluate concurrently give bitwise the
// results of one thread, with no data race. One small suite, so that the TSan build
// compiles little besides the library.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/reference/backend.hpp"
#include "testing.hpp"

namespace core = hs::core;
namespace ref = hs::reference;

TEST_CASE("threads: many threads solving different scenes give bitwise the single-thread results") {
  hs_test::rng r(31);
  struct scene {
    double q, s;
  };
  std::vector<scene> scenes;
  for (int i = 0; i < 64; ++i) scenes.push_back({r.uniform(-0.95, 0.95), r.uniform(-6, 6)});
  auto digest = [](const scene &c) {
    core::hertz_scene<double> sc;
    sc.q = c.q;
    sc.s = c.s;
    const auto sol = core::solve_hertz(sc);
    const double x1 = sol.b1() + 0.5 * sol.d1(), x2 = -sol.b2() - 0.5 * sol.d2();
    return std::vector<double>{sol.b1(),   sol.b2(),     sol.d1(),     sol.d2(),      sol.Bx(x1),
                               sol.Bx(x2), sol.slip(x1), sol.slip(x2), sol.energy(1), sol.energy(2)};
  };
  std::vector<std::vector<double>> serial;
  for (const auto &c : scenes) serial.push_back(digest(c));
  for (int rep = 0; rep < 2; ++rep) {
    std::vector<std::vector<double>> par(scenes.size());
    std::vector<std::thread> pool;
    for (int t = 0; t < 4; ++t)
      pool.emplace_back([&, t] {
        for (size_t i = size_t(t); i < scenes.size(); i += 4) par[i] = digest(scenes[i]);
      });
    for (auto &th : pool) th.join();
    for (size_t i = 0; i < scenes.size(); ++i)
      CHECK(std::memcmp(par[i].data(), serial[i].data(), serial[i].size() * sizeof(double)) == 0);
  }
}

// The general path keeps state made on first use: the expansion of B_x per zone (std::call_once,
// shared by the copies of a solution) and the tables of the pressure. Four threads evaluate the
// same solution at once (the first evaluation of each races to make the expansion), and each
// result equals the one of a fresh copy evaluated alone.
TEST_CASE("threads: the general path's shared expansion, evaluated by four threads at once") {
  const core::flat_rounded_pressure<double> pm(0.5);
  for (const double s : {0.4, 2.0}) {
    core::general_scene<double> sc;
    sc.q = 0.5;
    sc.s = s;
    const auto fresh = core::solve_general(pm, sc);
    auto digest = [](const core::general_solution<double> &sol, int k) {
      std::vector<double> v;
      for (int i = 0; i < 16; ++i) {
        const double t = (i + 0.5 + 0.01 * k) / 16;
        const double x1 = sol.b1() + t * sol.d1(), x2 = -sol.b2() - t * sol.d2();
        v.push_back(sol.Bx(x1));
        v.push_back(sol.slip(x2));
        v.push_back(sol.traction(0.1 * t));
      }
      v.push_back(sol.energy(1));
      v.push_back(sol.energy(2));
      return v;
    };
    std::vector<std::vector<double>> alone;
    for (int k = 0; k < 4; ++k) {
      const core::general_solution<double> copy = core::solve_general(pm, sc);
      alone.push_back(digest(copy, k));
    }
    std::vector<std::vector<double>> par(4);
    std::vector<std::thread> pool;
    for (int k = 0; k < 4; ++k) pool.emplace_back([&, k] { par[k] = digest(fresh, k); });
    for (auto &th : pool) th.join();
    CAPTURE(s);
    for (int k = 0; k < 4; ++k)
      CHECK(std::memcmp(par[k].data(), alone[k].data(), alone[k].size() * sizeof(double)) == 0);
  }
}

TEST_CASE("threads: two threads at different precisions give the results they give alone (reference)") {
  ref::text_scene t;
  t.q = "0.3";
  t.s = "2";
  auto run = [&](int digits) {
    const ref::solution s(t, digits);
    return s.value(ref::quantity::b1).text + s.value(ref::quantity::d2).text + s.value(ref::quantity::energy2).text;
  };
  const int hi_digits = std::min(150, ref::max_digits());  // short tier ladders in sanitizer builds
  const std::string alone40 = run(40), alone150 = run(hi_digits);
  for (int rep = 0; rep < 3; ++rep) {
    std::string r40, r150;
    std::thread a([&] {
      for (int k = 0; k < 3; ++k) r40 = run(40);
    });
    std::thread b([&] { r150 = run(hi_digits); });
    a.join();
    b.join();
    CHECK(r40 == alone40);
    CHECK(r150 == alone150);
  }
}
