// libFuzzer target: the CLI's pressure-file parser (bindings/cli/pressure_file.cpp)
// and what it feeds (issue 13). The input bytes are the file. Asserts: a
// rejection names the file and a line between 1 and the file's line count + 1;
// accepted samples are at least 6, finite, p >= 0, x strictly increasing, on
// increasing lines within the file; the rules that depend on a (a = 1) reject
// with a line of a sample; the library's hs_check_samples gives a known status
// and a sample index in range; when it accepts, hs_solve_geometry answers with a
// known status and, on success, zone lengths in [0, 2a].
#include <halfslip/halfslip.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "../../bindings/cli/pressure_file.hpp"

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}
bool known(int st) { return st >= HS_OK && st <= HS_ERR_NOT_APPLICABLE; }
bool starts_with(const std::string &s, const std::string &p) { return s.compare(0, p.size(), p) == 0; }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string bytes(reinterpret_cast<const char *>(data), size);
  int lines = 1;
  for (char c : bytes) lines += c == '\n';
  halfslip_cli::samples s;
  try {
    s = halfslip_cli::parse_samples(bytes, "F");
  } catch (const halfslip_cli::pressure_file_error &e) {
    require(starts_with(e.what(), "bad --pressure-file 'F', line "));
    require(e.line() >= 1 && e.line() <= lines + 1);
    return 0;
  }
  require(s.x.size() >= 6 && s.x.size() == s.p.size() && s.x.size() == s.line.size());
  for (size_t i = 0; i < s.x.size(); ++i) {
    require(std::isfinite(s.x[i]) && std::isfinite(s.p[i]) && s.p[i] >= 0);
    require(s.line[i] >= 1 && s.line[i] <= lines);
    if (i > 0) require(s.x[i] > s.x[i - 1] && s.line[i] > s.line[i - 1]);
  }
  try {
    halfslip_cli::check_samples(s, 1.0);
  } catch (const halfslip_cli::pressure_file_error &e) {
    bool of_a_sample = false;
    for (int l : s.line) of_a_sample = of_a_sample || l == e.line();
    require(of_a_sample);
    return 0;
  }
  int verdict = -1;
  size_t at = 0;
  char why[256] = {};
  require(hs_check_samples(s.x.size(), s.x.data(), s.p.data(), 1.0, &verdict, &at, why, sizeof why) == HS_OK);
  require(known(verdict) && at <= s.x.size() && std::memchr(why, 0, sizeof why) != nullptr);
  if (verdict != HS_OK) return 0;
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = 0.3;
  sc.sigma_over_fp0 = 1;
  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_SAMPLES;
  g.n_samples = s.x.size();
  g.sample_x = s.x.data();
  g.sample_p = s.p.data();
  hs_solution *sol = nullptr;
  const int st = hs_solve_geometry(&sc, &g, nullptr, &sol);
  require(known(st) && st != HS_ERR_BAD_GEOMETRY && st != HS_ERR_NOT_FINITE && st != HS_ERR_INTERNAL);
  if (st != HS_OK) {
    require(sol == nullptr);
    return 0;
  }
  hs_summary su;
  su.struct_size = sizeof su;
  require(hs_solution_summary(sol, &su) == HS_OK);
  require(su.d1 >= 0 && su.d1 <= 2 * su.a && su.d2 >= 0 && su.d2 <= 2 * su.a);
  hs_solution_free(sol);
  return 0;
}
