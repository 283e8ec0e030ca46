// libFuzzer target: the reference (MPFR) C ABI with arbitrary decimal
// strings and digit counts. Asserts the contract: known status, message,
// NUL-terminated outputs that fit, certified digits within [0, digits].
#include <halfslip/halfslip.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}
bool known(int st) { return st >= HS_OK && st <= HS_ERR_BAD_NUMBER; }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  // fields separated by '|': q|s|x|digits-byte (strings may be anything)
  std::string in(reinterpret_cast<const char *>(data), size);
  std::string f[4];
  for (int i = 0, k = 0; i < int(in.size()) && k < 4; ++i) {
    if (in[size_t(i)] == '|') {
      ++k;
      continue;
    }
    f[k] += in[size_t(i)];
  }
  if (f[0].size() > 64 || f[1].size() > 64 || f[2].size() > 64) return 0;
  hs_ref_scene sc;
  hs_ref_scene_default(&sc);
  sc.Q_over_fP = f[0].c_str();
  sc.sigma_over_fp0 = f[1].c_str();
  const int digits = f[3].empty() ? 20 : int(uint8_t(f[3][0])) % 48 - 2;
  hs_ref_solution *sol = nullptr;
  const int st = hs_ref_solve(&sc, digits, &sol);
  require(known(st));
  if (st != HS_OK) {
    require(sol == nullptr);
    return 0;
  }
  char buf[128];
  for (int q = HS_REF_B1; q <= HS_REF_D2; ++q) {
    int cd = -1;
    size_t need = 0;
    require(hs_ref_value(sol, q, buf, sizeof buf, &need, &cd) == HS_OK);
    require(need == std::strlen(buf) + 1 && cd >= 0 && cd <= digits);
  }
  int cd = -1;
  const int es = hs_ref_eval(sol, HS_REF_EVAL_BX, f[2].c_str(), buf, sizeof buf, nullptr, &cd);
  require(known(es));
  if (es == HS_OK) require(std::strlen(buf) < sizeof buf && cd >= 0 && cd <= digits);
  hs_ref_solution_free(sol);
  return 0;
}
