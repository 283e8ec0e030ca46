// Implementation of one precision tier: the core templates on a fixed
// precision MPFR type. Included by reference/src/tier.cpp only (compiled once per tier).
#pragma once
#include <boost/multiprecision/mpfr.hpp>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <mutex>
#include <sstream>

#include "halfslip/core/field_hp.hpp"
#include "halfslip/core/fields.hpp"
#include "halfslip/core/general.hpp"
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/pressure.hpp"
#include "halfslip/reference/backend.hpp"

namespace hs { namespace reference {

// The limbs live inside the number (allocate_stack): no malloc/free per temporary.
// Issue 16: with the default allocate_dynamic every MPFR temporary of the core's
// et_off arithmetic was an mpfr_init2/mpfr_clear pair (malloc, free and a TLS lookup),
// ~15 % of a flat-punch solve at 50 digits (perf). Same precision, same MPFR calls:
// the results are bitwise the same.
template <unsigned D> using mp_real =
    boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D, boost::multiprecision::allocate_stack>,
                                  boost::multiprecision::et_off>;

}  // namespace reference

// sin and cos at once (core/numerics.hpp): MPFR's mpfr_sin_cos, each correctly
// rounded, so the values of mpfr_sin and mpfr_cos
namespace core {
template <unsigned D> struct sin_cos_of<reference::mp_real<D>> {
  static void apply(const reference::mp_real<D> &x, reference::mp_real<D> &s, reference::mp_real<D> &c) {
    mpfr_sin_cos(s.backend().data(), c.backend().data(), x.backend().data(), MPFR_RNDN);
  }
};
}  // namespace core

namespace reference {

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

// parse_decimal, and whether the rounding lowered the magnitude of the exact
// decimal (|exact| > |value|): MPFR's ternary value of the correctly rounded
// conversion (the same number as T(s), which also rounds to nearest).
template <class T> T parse_decimal_exact(const std::string &s, const char *what, bool &rounded_inwards) {
  T v = parse_decimal<T>(s, what);
  T w;
  char *end = nullptr;
  const int tern = mpfr_strtofr(w.backend().data(), s.c_str(), &end, 10, MPFR_RNDN);
  if (end == nullptr || *end != 0 || w != v) throw core::error(core::status::bad_number, what);
  // tern > 0: w > exact; for w >= 0 that lowers nothing, for w < 0 it lowers |exact| to |w|
  rounded_inwards = w > 0 ? tern > 0 ? false : tern < 0 : w < 0 ? tern > 0 : false;
  return v;
}

// |x| <= a for the exact decimal x (a as represented at the working
// precision): the rounding of x decides only when |x| rounds to a.
template <class T> bool within(const T &x, bool rounded_inwards, const T &a) {
  using std::abs;
  if (abs(x) < a) return true;
  return abs(x) == a && !rounded_inwards;
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
      if (!in.start_x1.empty()) {
        opt.has_start = true;
        opt.start_x1 = parse_decimal<T>(in.start_x1, "start x1 is not a decimal number");
        opt.start_ln_e = parse_decimal<T>(in.start_ln_e, "start ln e is not a decimal number");
        opt.start_order = in.start_order;
      }
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
  bool general_start(std::string &x1, std::string &ln_e, int &order) const override {
    if (!general_ || general_->reg == core::regime::stuck) return false;
    const auto &g = *general_;
    const T x = g.reg == core::regime::opposite_sign ? T(-g.delta1) : T(g.delta1);
    x1 = to_text(x, int(D));
    ln_e = to_text(g.log_width, int(D));
    order = g.order / 2;
    return true;
  }
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
    bool inwards = false;
    const T x = parse_decimal_exact<T>(xs, "evaluation point x is not a decimal number", inwards);
    return visit([&](const auto &s) -> std::string {
      // exact: a decimal x just beyond a that rounds to a is outside
      if (!within(x, inwards, s.scene.a))
        throw core::error(core::status::point_outside, "evaluation point x outside |x| <= a");
      switch (what) {
        case point_eval::Bx: return to_text(s.Bx(x), sig);
        case point_eval::slip: return to_text(s.slip(x), sig);
        case point_eval::work: return to_text(s.work(x), sig);
        case point_eval::pressure: return to_text(s.pressure(x), sig);
        case point_eval::traction: return to_text(traction_at(s, x), sig);
      }
      throw core::error(core::status::bad_option, "unknown evaluation");
    });
  }

  std::string stress(int body, const std::string &bulk2s, stress_component c, const std::string &xs,
                     const std::string &ys, int sig) const override {
    if (body != 1 && body != 2)
      throw core::error(core::status::bad_option, "body must be 1 or 2");
    if (c != stress_component::xx && c != stress_component::yy && c != stress_component::xy)
      throw core::error(core::status::bad_option, "stress component must be HS_STRESS_XX, _YY or _XY");
    const T x = parse_decimal<T>(xs, "stress point x is not a decimal number");
    const T y = parse_decimal<T>(ys, "stress point y is not a decimal number");
    const T bulk2 = parse_decimal<T>(bulk2s, "bulk stress bulk2 is not a decimal number");
    if (body == 1 ? y < 0 : y > 0)
      throw core::error(core::status::bad_option, "stress point y outside the body (body 1: y >= 0, body 2: y <= 0)");
    using std::abs;
    return visit([&](const auto &s) -> std::string {
      const core::contact_state<T> st = field_state(s, bulk2);
      const core::stress_tensor<T> t = core::stress_at(st, body, x, T(abs(y)));
      return to_text(c == stress_component::xx ? t.xx : c == stress_component::yy ? t.yy : t.xy, sig);
    });
  }

  // The contact state of a solution at this precision: the Hertz closed forms
  // where they exist, else q from the cached stick-zone series and the Cauchy
  // integrals by cauchy_graded (field_hp.hpp).
  template <class S> core::contact_state<T> field_state(const S &s, const T &bulk2) const {
    core::contact_state<T> st;
    if constexpr (std::is_same<S, core::hertz_solution<T>>::value) st = core::hertz_state<T>(s, bulk2);
    else st = core::general_state_of<T>(s, bulk2);
    const fields_cache &fc = fields(s);
    st.q = [this, &s, &fc](const T &v) { return fast_traction(s, fc, v); };
    const std::vector<T> pts = st.points(), kinks = st.kinks;
    st.numeric = [this, &s, &fc, pts, kinks](const std::complex<T> &z, core::cauchy_pair<T> &P,
                                             core::cauchy_pair<T> &Q) {
      core::cauchy_graded<T>(
          [&](const T &v, T &pv, T &qv) {
            pv = s.pressure(v);
            qv = fast_traction(s, fc, v);
          },
          pts, z, P, Q, kinks, general_max_order(D));
    };
    return st;
  }

 private:
  // What the fields share between calls: a tanh-sinh integrator (its node
  // tables cost ten integrals) and q on the stick zone as a Chebyshev series
  // (stick_series, ~500 evaluations of q at 80 digits), built once per tier
  // on the first field request (std::call_once: the solution stays shareable).
  struct fields_cache {
    mutable boost::math::quadrature::tanh_sinh<T> ts = core::make_tanh_sinh<T>();
    std::unique_ptr<core::stick_series<T>> ser;
  };
  static std::vector<T> kinks_of(const core::hertz_solution<T> &) { return {}; }
  template <class S> static std::vector<T> kinks_of(const S &s) { return s.user_kinks(); }
  // closed forms where they exist (Hertz same sign, stuck), else traction.hpp
  // at the tanh-sinh tolerance root-eps of T (quadratic convergence: the
  // error is about eps; the series' coefficients level off at 1e-79 at 80 digits)
  template <class S> T direct_traction(const S &s, const fields_cache &fc, const T &x) const {
    if constexpr (std::is_same<S, core::hertz_solution<T>>::value)
      if (s.reg != core::regime::opposite_sign) return s.traction(x);
    return core::monotonic_traction<T>([&](const T &v) { return s.pressure(v); }, s.scene.a, s.scene.f, s.b1(),
                                       s.b2(), s.dir1(), s.dir2(), x, kinks_of(s), T(0), &fc.ts);
  }
  // q(x) alone needs only an integrator, not the stick series that fields() builds for the
  // stresses (issue 13 fuzzing: HS_REF_EVAL_TRACTION at x = -a, Hertz Q/fP = 0.3,
  // sigma/fp0 = 1, 20 digits, took 19 s building a series it did not use; now milliseconds)
  template <class S> T traction_at(const S &s, const T &x) const {
    const fields_cache fc;
    return direct_traction(s, fc, x);
  }
  template <class S> T fast_traction(const S &s, const fields_cache &fc, const T &x) const {
    if (fc.ser && fc.ser->inside(x)) return (*fc.ser)(x);
    return direct_traction(s, fc, x);
  }
  template <class S> const fields_cache &fields(const S &s) const {
    std::call_once(fields_once_, [&] {
      auto fc = std::make_unique<fields_cache>();
      const bool generic =
          !std::is_same<S, core::hertz_solution<T>>::value || s.reg == core::regime::opposite_sign;
      if (generic && s.b1() + s.b2() > 0) {
        // the degree the series needs grows with the digits (512 at 80 for
        // Hertz opposite sign and the flat punch): allow 16 D, as the solver
        int max_degree = 256;
        while (max_degree < 16 * int(D)) max_degree *= 2;
        const fields_cache &f = *fc;
        fc->ser = std::make_unique<core::stick_series<T>>([&](const T &v) { return direct_traction(s, f, v); },
                                                          -s.b2(), s.b1(), max_degree);
        if (!fc->ser->ok()) fc->ser.reset();  // q directly at every node (slow, still exact)
      }
      fields_ = std::move(fc);
    });
    return *fields_;
  }
  mutable std::once_flag fields_once_;
  mutable std::unique_ptr<fields_cache> fields_;

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
