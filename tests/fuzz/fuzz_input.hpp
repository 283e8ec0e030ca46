// Shared by the libFuzzer targets that read raw bytes: a reader that turns the
// input into doubles (raw: NaN, Inf, denormals, huge values all occur) and
// bytes, zero once the input runs out, and an abort on a broken contract.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <halfslip/halfslip.h>

namespace hs_fuzz {
struct reader {
  const uint8_t *p;
  size_t n;
  double real() {
    double v = 0;
    if (n >= sizeof v) {
      std::memcpy(&v, p, sizeof v);
      p += sizeof v;
      n -= sizeof v;
    }
    return v;
  }
  uint8_t byte() {
    if (!n) return 0;
    --n;
    return *p++;
  }
  // a value in [-r, r] from two bytes
  double ranged(double r) {
    const int v = int(byte()) << 8 | int(byte());
    return r * (double(v) / 32767.5 - 1);
  }
};
// a status the C ABI may return (any other value breaks its contract)
inline bool known(int st) { return st >= HS_OK && st <= HS_ERR_NOT_APPLICABLE; }
inline void require(bool ok) {
  if (!ok) std::abort();
}
// require with the broken condition named on stderr (HS_REQUIRE)
inline void require_at(bool ok, const char *what, const char *file, int line) {
  if (ok) return;
  std::fprintf(stderr, "%s:%d: broken: %s\n", file, line, what);
  std::abort();
}
}  // namespace hs_fuzz
#define HS_REQUIRE(c) hs_fuzz::require_at(bool(c), #c, __FILE__, __LINE__)
