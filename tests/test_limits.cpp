// Issue 12 item 3: every loop of the core that can run out reports it
// (status::no_convergence, HS_ERR_NO_CONVERGENCE at the C ABI) instead of
// returning an unconverged value. Each loop is driven to its limit here by
// its iteration/term/order argument set low.
#include <doctest/doctest.h>

#include "halfslip/core/elliptic.hpp"
#include "halfslip/core/gauss.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz_opposite.hpp"
#include "halfslip/core/numerics.hpp"

namespace core = hs::core;

namespace {
template <class F> core::status status_of(const F &f) {
  try {
    f();
  } catch (const core::error &e) {
    return e.code();
  }
  return core::status::ok;
}
}  // namespace

TEST_CASE("limits: cel reports an exhausted AGM loop") {
  CHECK(status_of([] { core::cel(0.3, 0.7, 1.0, 0.2, 2); }) == core::status::no_convergence);
  CHECK(status_of([] { core::cel(0.3, 0.7, 1.0, 0.2); }) == core::status::ok);
}

TEST_CASE("limits: odd Taylor series (y - sin y, sinh y - y) report running out of terms") {
  CHECK(status_of([] { core::detail::odd_tail_series(0.9, -1, 3); }) == core::status::no_convergence);
  CHECK(status_of([] { core::detail::odd_tail_series(0.9, +1, 3); }) == core::status::no_convergence);
  CHECK(status_of([] { core::detail::odd_tail_series(0.9, -1); }) == core::status::ok);
  CHECK(core::detail::odd_tail_series(0.9, -1) == core::y_minus_sin(0.9));
}

TEST_CASE("limits: sliding stick point Newton reports an exhausted loop") {
  double c = 0, w = 0;
  CHECK(status_of([&] { core::sliding_stick_point(0.5, c, w, 1); }) == core::status::no_convergence);
  CHECK(status_of([&] { core::sliding_stick_point(0.5, c, w); }) == core::status::ok);
}

TEST_CASE("limits: Gauss-Legendre node Newton reports an exhausted loop") {
  CHECK(status_of([] { core::gauss_detail::make_rule<double>(40, 1); }) == core::status::no_convergence);
  CHECK(status_of([] { core::gauss_detail::make_rule<double>(40); }) == core::status::ok);
}

TEST_CASE("limits: zone energy and slip report the order limit (max_order)") {
  core::flat_rounded_pressure<double> pm(0.5);
  core::general_scene<double> sc;
  sc.q = 0.4;
  sc.s = 0.3;
  core::general_options<double> opt;
  const auto ok = core::solve_general(pm, sc, opt);
  CHECK(status_of([&] { ok.energy_hat(-1); }) == core::status::ok);
  opt.max_order = 16;  // the energy starts at order 16 in double: no second order to compare
  const auto sol = core::solve_general(pm, sc, opt);
  CHECK(status_of([&] { sol.energy_hat(-1); }) == core::status::no_convergence);
  CHECK(status_of([&] { sol.hhat(-1, sol.delta2 / 2); }) == core::status::no_convergence);
}
