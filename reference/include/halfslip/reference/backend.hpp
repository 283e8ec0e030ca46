// halfslip reference backend: the core templates instantiated on MPFR at a
// precision chosen per call, with digit certification.
//
// Precision tiers. Boost 1.74's variable-precision mpfr_float keeps its
// default precision in one process-wide variable, so two threads working
// at different precisions would interfere. The reference therefore uses
// fixed-precision MPFR types, number<mpfr_float_backend<D, allocate_stack>, et_off>
// (the limbs inside the number: no allocation per temporary), for a
// ladder of D (decimal digits). Each tier is explicitly instantiated in its
// own translation unit (reference/src/tier.cpp, compiled once per tier with
// -DHS_TIER_DIGITS=D). A request for N digits
// runs at the smallest tier with D >= N + guard, and again at the next tier;
// the agreement of the two runs certifies the digits. The precision is in
// the type, so it is per call by construction and there is no global state.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace hs { namespace reference {

// Geometries of the reference backend (the values of HS_GEOMETRY_*).
constexpr int geometry_hertz = 1;         // closed forms (core/hertz.hpp)
constexpr int geometry_flat_rounded = 2;  // flat punch with rounded corners, b_f/a = flat_over_a
constexpr int geometry_power_law = 3;     // profile g = A|x|^n, n = exponent

// Decimal inputs, parsed at the working precision (exact decimals stay
// exact up to the last bit of the tier).
struct text_scene {
  std::string a = "1", p0 = "1", f = "1", Estar = "1", q = "0.5", s = "0.5";
  // Dimensional Hertz input instead of a, p0, q, s when P is not empty
  // (Hertz only: with another geometry, bad_geometry).
  std::string P, R, Q, sigma;
  // Non-Hertz geometries are solved by core::solve_general at the full
  // precision of the tier (rtol = 0). Only the parameter of the chosen
  // geometry is read: b_f/a in [0, 1), or 1 < n < 1000.
  int geometry = geometry_hertz;
  std::string flat_over_a = "0.5", exponent = "2";
  // Non-Hertz only: a start for the solver from a solve at a lower precision
  // (core::general_options::has_start; issue 16), the canonical x1 = +-d1 and
  // ln e as decimals (empty: the solver's own starts) and the order at which
  // Newton begins (0: from the tolerance). Set by solution (the double
  // solution for the work tier, the work tier's for the check tier); a start
  // changes the path to the tier's root, not the root.
  std::string start_x1, start_ln_e;
  int start_order = 0;
};

enum class quantity : int { b1 = 1, b2 = 2, d1 = 3, d2 = 4, energy1 = 5, energy2 = 6, a = 7, p0 = 8 };
enum class point_eval : int { Bx = 1, slip = 2, work = 3, pressure = 4, traction = 5 };
// Stress components (the values of HS_STRESS_XX, _YY, _XY).
enum class stress_component : int { xx = 1, yy = 2, xy = 3 };

// One solve at one fixed precision tier (type-erased).
class tier_solution {
 public:
  virtual ~tier_solution() = default;
  virtual unsigned digits10() const = 0;
  virtual int regime() const = 0;
  virtual int dir1() const = 0;
  virtual int dir2() const = 0;
  virtual int iterations() const = 0;
  // Gauss-Legendre order per panel of the accepted residual (0: Hertz closed forms).
  virtual int quadrature_order() const = 0;
  // Non-Hertz: the canonical state (x1 = +-d1, ln e) at all the digits of the
  // tier and the Newton order before the accepted residual's, as a start for
  // a wider tier (text_scene::start_x1); false for Hertz.
  virtual bool general_start(std::string &x1, std::string &ln_e, int &order) const = 0;
  // Value printed in scientific notation with `sig` significant digits.
  virtual std::string value(quantity q, int sig) const = 0;
  virtual std::string eval(point_eval what, const std::string &x, int sig) const = 0;
  // Stress component at (x, y) in body 1 (y >= 0) or body 2 (y <= 0); body 2
  // carries the bulk stress bulk2, body 1 sigma + bulk2 (docs/fields.md).
  virtual std::string stress(int body, const std::string &bulk2, stress_component c, const std::string &x,
                             const std::string &y, int sig) const = 0;
};

// Precision ladder (decimal digits) and the largest certifiable request.
const std::vector<unsigned> &tiers();
int max_digits();
constexpr int guard_digits = 10;
// Non-Hertz geometries cost far more per tier (Gauss-Legendre orders growing
// with the digits, ~D^3 overall: about 3 s at 180 digits, 50 s at 400): their
// requests are capped where the check run would need a tier above this
// (docs/reference.md). max_digits(geometry) is the cap, max_digits() for
// Hertz, 0 for an unknown geometry.
constexpr unsigned general_max_check_tier = 270;
int max_digits(int geometry);
// Largest Gauss-Legendre order per panel allowed to the general solver at a
// tier of D digits (the order it needs grows about linearly with D).
int general_max_order(unsigned D);

// Solve at tier D (must be one of tiers()). Throws hs::core::error.
std::unique_ptr<tier_solution> solve_at(unsigned D, const text_scene &sc, int max_iterations);

// A certified value: the working-precision result rounded to the requested
// digits, and how many of its leading significant digits are certified.
struct certified {
  std::string text;
  int digits;
};

// Certified solution: work tier plus check tier.
class solution {
 public:
  solution(const text_scene &sc, int digits, int max_iterations = 1000);
  int digits() const { return digits_; }
  unsigned working_digits() const { return work_->digits10(); }
  unsigned check_digits() const { return check_->digits10(); }
  int regime() const { return work_->regime(); }
  int dir1() const { return work_->dir1(); }
  int dir2() const { return work_->dir2(); }
  int iterations() const { return work_->iterations(); }
  int quadrature_order() const { return work_->quadrature_order(); }
  certified value(quantity q) const;
  certified eval(point_eval what, const std::string &x) const;
  certified stress(int body, const std::string &bulk2, stress_component c, const std::string &x,
                   const std::string &y) const;
  // a quantity at all the digits of the work (check = false) or check tier,
  // for sums of solutions certified by the same two tiers (ray_history.hpp)
  std::string raw(quantity q, bool check) const;

 private:
  certified certify(const std::string &work, const std::string &check) const;
  int digits_;
  std::unique_ptr<tier_solution> work_, check_;
};

// Number of leading significant decimal digits in which a agrees with b
// (both decimal strings), capped at cap; cap when both are exactly zero.
int agreeing_digits(const std::string &a, const std::string &b, int cap);

}}  // namespace hs::reference
