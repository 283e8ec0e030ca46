// libFuzzer target: the reference backend's field evaluations (issue 13):
// hs_ref_eval (B_x, slip, work, pressure, traction and unknown fields) and
// hs_ref_eval_stress at arbitrary decimal strings, buffer sizes and digit counts,
// on a Hertz scene (a = p0 = f = E* = 1) with fuzzed loads. Input: a byte of
// flags, a byte of digits, a byte of buffer size, then '|'-separated fields
// q|s|x|y|bulk2. Asserts:
//   - a known status; on an error the buffer is untouched;
//   - HS_ERR_BUFFER_TOO_SMALL exactly when the text does not fit (needed > size);
//     on success a NUL-terminated text of needed bytes, certified digits in [0, digits];
//   - the range check is exact: a plain decimal x with |x| > 1 = a gives
//     HS_ERR_POINT_OUTSIDE, and |x| <= 1 never does;
//   - an unknown field or stress component, or a body other than 1 and 2, gives
//     HS_ERR_BAD_OPTION (or HS_ERR_BAD_NUMBER for an unparsable string);
//   - routes agree: the pressure is sqrt(1 - x^2) (between the double values at
//     the neighbours of x, to its certified digits), and where x lies in a slip zone
//     of the double solution (away from its ends) the traction is dir f p(x).
#include <halfslip/halfslip.h>

#include "fuzz_input.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {
using hs_fuzz::known;

// +1 if the plain decimal t ([+-]digits[.digits], no exponent) has |t| > 1,
// 0 if |t| <= 1, -1 if t is not of that form
int beyond_one(const std::string &t) {
  size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  std::string ip, fp;
  while (i < t.size() && t[i] >= '0' && t[i] <= '9') ip += t[i++];
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') fp += t[i++];
  }
  if (i != t.size() || (ip.empty() && fp.empty())) return -1;
  const size_t nz = ip.find_first_not_of('0');
  const std::string in = nz == std::string::npos ? "" : ip.substr(nz);
  if (in.size() > 1 || (in.size() == 1 && in[0] > '1')) return 1;
  if (in == "1") return fp.find_first_not_of('0') != std::string::npos ? 1 : 0;
  return 0;
}

// check one text output against the buffer contract
void check_text(int st, const char *buf, const char *before, size_t size, size_t needed, int cd, int digits) {
  HS_REQUIRE(known(st));
  if (st == HS_OK) {
    HS_REQUIRE(std::memchr(buf, 0, size) != nullptr && needed == std::strlen(buf) + 1 && needed <= size);
    HS_REQUIRE(cd >= 0 && cd <= digits);
  } else {
    HS_REQUIRE(std::memcmp(buf, before, size) == 0);
    if (st == HS_ERR_BUFFER_TOO_SMALL) HS_REQUIRE(needed > size);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 3) return 0;
  const uint8_t flags = data[0];
  const int digits = 1 + data[1] % 40;
  const size_t bufsize = data[2] % 96;
  std::string in(reinterpret_cast<const char *>(data + 3), size - 3);
  std::string f[5];
  for (size_t i = 0, k = 0; i < in.size() && k < 5; ++i) {
    if (in[i] == '|') {
      ++k;
      continue;
    }
    f[k] += in[i];
  }
  for (const auto &s : f)
    if (s.size() > 64 || s.find('\0') != std::string::npos) return 0;
  hs_ref_scene sc;
  hs_ref_scene_default(&sc);
  if (!f[0].empty()) sc.Q_over_fP = f[0].c_str();
  if (!f[1].empty()) sc.sigma_over_fp0 = f[1].c_str();
  hs_ref_solution *sol = nullptr;
  const int st = hs_ref_solve(&sc, digits, &sol);
  HS_REQUIRE(known(st) && (st == HS_OK) == (sol != nullptr));
  if (st != HS_OK) return 0;

  const std::string &x = f[2];
  const double xd = std::strtod(x.c_str(), nullptr);
  char buf[96], before[96];
  std::memset(before, 0x77, sizeof before);
  const int what = (flags & 7) - 1;  // -1 .. 6: unknown values included
  std::memcpy(buf, before, sizeof buf);
  size_t needed = 0;
  int cd = -1;
  const int es = hs_ref_eval(sol, what, x.c_str(), buf, bufsize, &needed, &cd);
  check_text(es, buf, before, bufsize, needed, cd, digits);
  const bool known_what = what >= HS_REF_EVAL_BX && what <= HS_REF_EVAL_TRACTION;
  if (!known_what) HS_REQUIRE(es == HS_ERR_BAD_OPTION || es == HS_ERR_BAD_NUMBER);
  const int beyond = beyond_one(x);
  if (known_what && beyond == 1) HS_REQUIRE(es == HS_ERR_POINT_OUTSIDE);
  if (beyond == 0) HS_REQUIRE(es != HS_ERR_POINT_OUTSIDE && es != HS_ERR_BAD_NUMBER);
  if (es == HS_OK && what == HS_REF_EVAL_PRESSURE && cd >= 1) {
    // p(x) = sqrt(1 - x^2) increases towards 0: the exact x lies between the double
    // neighbours of x's rounding, so p lies between their pressures
    const double v = std::strtod(buf, nullptr);
    const double lo = std::fabs(xd) == 0 ? 0 : std::nextafter(std::fabs(xd), 0.0);
    const double hi = std::nextafter(std::fabs(xd), 2.0);
    const double plo = hi >= 1 ? 0 : std::sqrt((1 - hi) * (1 + hi)), phi = std::sqrt((1 - lo) * (1 + lo));
    const double tol = std::pow(10.0, 1 - cd) * std::fabs(v) + 4 * DBL_EPSILON;
    HS_REQUIRE(v >= plo - tol && v <= phi + tol);
  }
  if (es == HS_OK && what == HS_REF_EVAL_TRACTION && cd >= 12 && std::fabs(xd) < 1) {
    // traction in a slip zone of the double solution (well inside it): dir f p(x)
    hs_scene ds;
    hs_scene_default(&ds);
    // (a NULL ratio is the C default "0.5", hs_ref_scene_default; found by the
    // reliability stage's run: UBSan, strtod(NULL))
    ds.Q_over_fP = sc.Q_over_fP ? std::strtod(sc.Q_over_fP, nullptr) : 0.5;
    ds.sigma_over_fp0 = sc.sigma_over_fp0 ? std::strtod(sc.sigma_over_fp0, nullptr) : 0.5;
    hs_solution *dsol = nullptr;
    if (hs_solve(&ds, nullptr, &dsol) == HS_OK) {
      hs_summary m;
      m.struct_size = sizeof m;
      HS_REQUIRE(hs_solution_summary(dsol, &m) == HS_OK);
      const double margin = 1e-6;
      int dir = 0;
      if (m.slip_dir1 != 0 && xd > m.b1 + margin && xd < 1 - margin) dir = m.slip_dir1;
      if (m.slip_dir2 != 0 && xd < -m.b2 - margin && xd > -1 + margin) dir = m.slip_dir2;
      if (dir != 0) {
        const double v = std::strtod(buf, nullptr), p = std::sqrt((1 - xd) * (1 + xd));
        HS_REQUIRE(std::fabs(v - dir * p) <= 1e-9 * p);
      }
      hs_solution_free(dsol);
    }
  }
  hs_ref_summary rs;
  rs.struct_size = sizeof rs;
  HS_REQUIRE(hs_ref_solution_summary(sol, &rs) == HS_OK);
  if ((flags & 8) && rs.regime != HS_REGIME_OPPOSITE_SIGN) {
    // a stress component, Hertz same sign or stuck (the closed forms): in the opposite-sign
    // regime the first field request builds a stick series in every tier (seconds even in a
    // release build, docs/fields.md "Cost"), too slow to fuzz
    const int body = int(flags >> 4 & 3);      // 0 .. 3
    const int comp = int(flags >> 6 & 3) + 1;  // 1 .. 4
    std::memcpy(buf, before, sizeof buf);
    needed = 0;
    cd = -1;
    const std::string &y = f[3].empty() ? std::string("0") : f[3];
    const int ss = hs_ref_eval_stress(sol, body, f[4].empty() ? nullptr : f[4].c_str(), comp, x.c_str(),
                                      y.c_str(), buf, bufsize, &needed, &cd);
    check_text(ss, buf, before, bufsize, needed, cd, digits);
    if (std::getenv("HS_FUZZ_DEBUG"))
      std::fprintf(stderr, "stress body %d component %d at (%s, %s): status %d %s\n", body, comp, x.c_str(), y.c_str(),
                   ss, ss == HS_OK ? buf : "");
    if (ss != HS_ERR_BAD_NUMBER && (body < 1 || body > 2 || comp > HS_STRESS_XY)) HS_REQUIRE(ss == HS_ERR_BAD_OPTION);
  }
  hs_ref_solution_free(sol);
  return 0;
}
