// Implementation of one precision tier: the core templates on a fixed
// precision MPFR type. Included by reference/src/tier.cpp only (compiled once per tier).
#pragma once
#include <boost/multiprecision/mpfr.hpp>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <sstream>

#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/pressure.hpp"
#include "halfslip/reference/backend.hpp"

namespace hs { namespace reference {

template <unsigned D> using mp_real =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D>, boost::multiprecision::et_off>;

template <class T> T parse_decimal(const std::string &s, const char *what) {
  // strict: optional sign, digits, optional fraction, optional exponent
  size_t i = 0, n = s.size();
  bool digits = false;
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) {
    ++i;
    digits = true;
  }
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) {
      ++i;
      digits = true;
    }
  }
  if (digits && i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    bool ed = false;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) {
      ++i;
      ed = true;
    }
    if (!ed) digits = false;
  }
  if (!digits || i != n || n > 4096) throw core::error(core::status::bad_number, what);
  return T(s);
}

template <class T> std::string to_text(const T &v, int sig) {
  if (sig == 1 && v != 0) {
    // iostream precision 0 means "all digits" for Boost's MPFR numbers: ask
    // MPFR for the one correctly rounded digit directly.
    mpfr_exp_t e = 0;
    char *d = mpfr_get_str(nullptr, &e, 10, 1, v.backend().data(), MPFR_RNDN);
    std::string s(d);
    mpfr_free_str(d);
    const bool neg = s[0] == '-';
    char buf[32];
    std::snprintf(buf, sizeof buf, "%se%c%02ld", s.c_str(), e - 1 < 0 ? '-' : '+', std::labs(long(e - 1)));
    (void)neg;
    return buf;
  }
  std::ostringstream os;
  os << std::scientific << std::setprecision(sig > 1 ? sig - 1 : 0) << v;
  return os.str();
}

// One tier: the Hertz closed forms, or the general-pressure solver with the
// pressure model built at precision T and owned here (general_solution keeps
// a pointer to it). Tiers above general_max_check_tier never run a non-Hertz
// geometry (max_digits(geometry)), so the general solver is not instantiated
// there (it triples a tier's compile time).
template <unsigned D> class tier_solution_impl final : public tier_solution {
  using T = mp_real<D>;
  static constexpr bool has_general = D <= general_max_check_tier;

 public:
  tier_solution_impl(const text_scene &in, int max_iterations) {
    if (in.geometry != geometry_hertz && in.geometry != geometry_flat_rounded && in.geometry != geometry_power_law)
      throw core::error(core::status::bad_geometry,
                        "unknown geometry (reference backend: Hertz, flat-rounded, power law)");
    core::hertz_scene<T> sc;
    sc.f = parse_decimal<T>(in.f, "friction coefficient f is not a decimal number");
    sc.Estar = parse_decimal<T>(in.Estar, "E* is not a decimal number");
    if (!in.P.empty()) {
      if (in.geometry != geometry_hertz)
        throw core::error(core::status::bad_geometry, "dimensional input (P, R, Q, sigma) is for Hertz only");
      const T P = parse_decimal<T>(in.P, "P is not a decimal number");
      const T R = parse_decimal<T>(in.R, "R is not a decimal number");
      const T Q = parse_decimal<T>(in.Q, "Q is not a decimal number");
      const T sg = parse_decimal<T>(in.sigma, "sigma is not a decimal number");
      if (!(P > 0 && R > 0 && sc.Estar > 0)) throw core::error(core::status::bad_size, "P, R, E* must be > 0");
      if (!(sc.f > 0)) throw core::error(core::status::bad_friction, "f must be > 0");
      sc.a = core::hertz_pressure<T>::half_width_from_load(P, R, sc.Estar);
      sc.p0 = core::pressure_unit(P, sc.a);
      sc.q = Q / (sc.f * P);
      sc.s = sg / (sc.f * sc.p0);
    } else {
      sc.a = parse_decimal<T>(in.a, "a is not a decimal number");
      sc.p0 = parse_decimal<T>(in.p0, "p0 is not a decimal number");
      sc.q = parse_decimal<T>(in.q, "Q/fP is not a decimal number");
      sc.s = parse_decimal<T>(in.s, "sigma/(f p0) is not a decimal number");
    }
    if (in.geometry == geometry_hertz) {
      core::solve_options<T> opt;
      opt.max_iterations = max_iterations;
      hertz_.reset(new core::hertz_solution<T>(core::solve_hertz(sc, opt)));
      return;
    }
    if constexpr (has_general) {
      // the model's constructor checks the range (bad_geometry)
      if (in.geometry == geometry_flat_rounded)
        model_.reset(new core::flat_rounded_pressure<T>(
            parse_decimal<T>(in.flat_over_a, "flat_over_a (b_f/a) is not a decimal number")));
      else
        model_.reset(
            new core::power_law_pressure<T>(parse_decimal<T>(in.exponent, "exponent n is not a decimal number")));
      core::general_options<T> opt;
      opt.max_iterations = max_iterations;
      opt.rtol = 0;  // full precision of T
      opt.max_order = general_max_order(D);
      general_.reset(new core::general_solution<T>(core::solve_general(*model_, sc, opt)));
    } else {
      throw core::error(core::status::bad_option, "digits above the limit for non-Hertz geometries");
    }
  }
  unsigned digits10() const override { return D; }
  int regime() const override {
    return visit([](const auto &s) { return int(s.reg); });
  }
  int dir1() const override {
    return visit([](const auto &s) { return s.dir1(); });
  }
  int dir2() const override {
    return visit([](const auto &s) { return s.dir2(); });
  }
  int iterations() const override {
    return visit([](const auto &s) { return s.iterations; });
  }
  int quadrature_order() const override { return general_ ? general_->order : 0; }
  std::string value(quantity q, int sig) const override {
    return visit([&](const auto &s) -> std::string {
      switch (q) {
        case quantity::b1: return to_text(s.b1(), sig);
        case quantity::b2: return to_text(s.b2(), sig);
        case quantity::d1: return to_text(s.d1(), sig);
        case quantity::d2: return to_text(s.d2(), sig);
        case quantity::energy1: return to_text(s.energy(1), sig);
        case quantity::energy2: return to_text(s.energy(2), sig);
        case quantity::a: return to_text(s.scene.a, sig);
        case quantity::p0: return to_text(s.scene.p0, sig);
      }
      throw core::error(core::status::bad_option, "unknown quantity");
    });
  }
  std::string eval(point_eval what, const std::string &xs, int sig) const override {
    const T x = parse_decimal<T>(xs, "evaluation point is not a decimal number");
    return visit([&](const auto &s) -> std::string {
      if (!(abs(x) <= s.scene.a)) throw core::error(core::status::point_outside, "evaluation point outside |x| <= a");
      switch (what) {
        case point_eval::Bx: return to_text(s.Bx(x), sig);
        case point_eval::slip: return to_text(s.slip(x), sig);
        case point_eval::work: return to_text(s.work(x), sig);
        case point_eval::pressure: return to_text(s.pressure(x), sig);
      }
      throw core::error(core::status::bad_option, "unknown evaluation");
    });
  }

 private:
  template <class F> auto visit(F &&f) const {
    if constexpr (has_general) {
      if (general_) return f(*general_);
    }
    return f(*hertz_);
  }
  std::unique_ptr<core::hertz_solution<T>> hertz_;
  // declared before general_, which refers to it (destroyed after it)
  std::unique_ptr<const core::pressure_model<T>> model_;
  std::unique_ptr<core::general_solution<T>> general_;
};

template <unsigned D> std::unique_ptr<tier_solution> make_tier(const text_scene &sc, int max_iterations) {
  return std::unique_ptr<tier_solution>(new tier_solution_impl<D>(sc, max_iterations));
}

}}  // namespace hs::reference
