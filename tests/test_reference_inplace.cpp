// Issue 16, the reference backend's fast paths against the plain code they replace:
//  - the tiers' MPFR type keeps its limbs inside the number (allocate_stack), the
//    flat punch's Gauss-ladder sum and the energies' Cauchy sums run in place
//    (core::inplace_loops), and the nodes' sine and cosine come from one
//    mpfr_sin_cos (core::sin_cos_of): the same operations, rounded alike, so the
//    solutions and energies must be bitwise those of the plain code, which an MPFR
//    type with the default allocation, inplace_loops off and separate sin, cos runs;
//  - a tier started from another tier's root takes its first Newton step unevaluated
//    when K s^2 is far below the tolerance (general_options::start_shortcut): the
//    root must agree with the one of the old path (every step evaluated) to the
//    tier's precision, in fewer iterations.
#include <doctest/doctest.h>
#include "testing.hpp"

#include <boost/multiprecision/mpfr.hpp>
#include <ios>
#include <memory>
#include <string>
#include <tuple>

#include "tier_impl.hpp"

namespace core = hs::core;
namespace ref = hs::reference;

// the plain code: dynamic allocation, no in-place loops, separate sin and cos
using plain60 =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<60>, boost::multiprecision::et_off>;
namespace hs { namespace core {
template <> struct inplace_loops<plain60> : std::false_type {};
}}  // namespace hs::core
// the tiers' type (reference/src/tier_impl.hpp)
using fast60 = ref::mp_real<60>;

namespace {

template <class T> std::string full(const T &v) { return v.str(80, std::ios_base::scientific); }

struct scene {
  bool flat;
  const char *param, *q, *s;
};

template <class T> std::unique_ptr<core::pressure_model<T>> model(const scene &c) {
  if (c.flat) return std::make_unique<core::flat_rounded_pressure<T>>(T(c.param));
  return std::make_unique<core::power_law_pressure<T>>(T(c.param));
}

template <class T> core::general_solution<T> solve(const core::pressure_model<T> &pm, const scene &c,
                                                   const core::general_options<T> &opt) {
  core::general_scene<T> g;
  g.q = T(c.q);
  g.s = T(c.s);
  return core::solve_general(pm, g, opt);
}

template <class T> core::general_options<T> options() {
  core::general_options<T> o;
  o.rtol = 0;
  o.max_order = ref::general_max_order(60);
  return o;
}

const scene scenes[] = {{true, "0.5", "0.5", "0.5"},
                        {true, "0.5", "0.3", "2"},
                        {false, "3", "0.5", "0.5"},
                        {false, "1.5", "0.3", "2"}};

}  // namespace

TEST_CASE("reference fast paths (stack limbs, in-place sums, sin_cos) are bitwise the plain code") {
  for (const scene &c : scenes) {
    const auto pp = model<plain60>(c);
    const auto pf = model<fast60>(c);
    const auto a = solve(*pp, c, options<plain60>());
    const auto b = solve(*pf, c, options<fast60>());
    INFO((c.flat ? "flat " : "power ") << c.param << " q=" << c.q << " s=" << c.s);
    CHECK(a.iterations == b.iterations);
    CHECK(a.order == b.order);
    CHECK(full(a.b1()) == full(b.b1()));
    CHECK(full(a.b2()) == full(b.b2()));
    CHECK(full(a.d1()) == full(b.d1()));
    CHECK(full(a.d2()) == full(b.d2()));
    // the pressure and its derivative at points of the ladder and of the closed forms
    for (const char *x : {"0", "0.3", "0.49", "0.5", "0.51", "0.7", "0.9", "0.999", "-0.6"}) {
      plain60 dp;
      fast60 df;
      const plain60 xp(x);
      const fast60 xf(x);
      const plain60 vp = pp->phi_dphi(xp, plain60(1 + xp), plain60(1 - xp), dp);
      const fast60 vf = pf->phi_dphi(xf, fast60(1 + xf), fast60(1 - xf), df);
      CHECK(full(vp) == full(vf));
      CHECK(full(dp) == full(df));
    }
    // the zone energies by the fixed rules (hgrad_nodes: in place against plain)
    CHECK(full(a.energy_hat_fixed(1)) == full(b.energy_hat_fixed(1)));
    CHECK(full(a.energy_hat_fixed(-1)) == full(b.energy_hat_fixed(-1)));
    CHECK(full(a.energy(1)) == full(b.energy(1)));
    CHECK(full(a.energy(2)) == full(b.energy(2)));
  }
}

TEST_CASE("a start from another tier's root: the unevaluated first step finds the same root") {
  for (const scene &c : scenes) {
    INFO((c.flat ? "flat " : "power ") << c.param << " q=" << c.q << " s=" << c.s);
    // the start: a root at 40 digits (as the check tier starts from the work tier's)
    using lo_t = ref::mp_real<40>;
    const auto pl = model<lo_t>(c);
    const auto lo = solve(*pl, c, options<lo_t>());
    const auto pf = model<fast60>(c);
    core::general_options<fast60> o = options<fast60>();
    o.has_start = true;
    o.start_x1 = fast60(lo.reg == core::regime::opposite_sign ? lo_t(-lo.delta1) : lo_t(lo.delta1));
    o.start_ln_e = fast60(lo.log_width);
    o.start_order = lo.order / 2;
    core::general_options<fast60> old = o;
    old.start_shortcut = false;
    const auto a = solve(*pf, c, old);
    const auto b = solve(*pf, c, o);
    const auto z = solve(*pf, c, options<fast60>());  // no start at all
    CHECK(b.iterations <= a.iterations);
    for (const auto &[u, v, w] : {std::tuple{a.b1(), b.b1(), z.b1()}, std::tuple{a.b2(), b.b2(), z.b2()},
                                  std::tuple{a.d1(), b.d1(), z.d1()}, std::tuple{a.d2(), b.d2(), z.d2()}}) {
      const fast60 tol = 1e4 * core::eps<fast60>() * (1 + abs(u));
      CHECK_MESSAGE(abs(u - v) <= tol, full(u) << " vs " << full(v));
      CHECK_MESSAGE(abs(u - w) <= tol, full(u) << " vs " << full(w));
    }
  }
}
