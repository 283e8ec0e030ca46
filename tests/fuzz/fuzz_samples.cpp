// libFuzzer target: sampled pressures through the C ABI (issue 13), below and
// above the knot path's threshold (256 interior samples). The input bytes
// choose a sample count (up to 3000), a pressure shape (Hertz, skewed, a
// power, a flat top, with relative noise), where the samples stop short of the
// edges, a scene (raw doubles: NaN, Inf, denormals occur), and a few raw
// overwrites of single samples (x or p). Asserts the contract:
// hs_check_samples' verdict and sample index are in range, and
// hs_solve_geometry fails exactly when it does (with the same status) when
// the scene is otherwise valid; on success zone lengths in [0, 2a], finite
// energies (or a status), finite B_x, slip and traction at a few points.
#include <halfslip/halfslip.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "fuzz_input.hpp"

namespace {
using hs_fuzz::reader;
using hs_fuzz::require;
using hs_fuzz::known;
double noise(size_t i, unsigned seed) {
  unsigned long long z = (unsigned long long)(i + 1) * 0x9E3779B97F4A7C15ULL + seed;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return double(z >> 11) / 4503599627370496.0 - 1.0;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  reader r{data, size};
  const uint8_t flags = r.byte();
  const size_t n = 6 + (size_t(r.byte()) << 4 | r.byte() >> 4) % 2995;  // 6 .. 3000 samples
  const uint8_t shape = r.byte(), noise_exp = r.byte(), seed = r.byte();
  const double inset = (flags & 1) ? 0.01 * (r.byte() % 50) : 0.0;  // samples stop short of the edges
  const double amp = noise_exp % 17 == 0 ? 0.0 : std::ldexp(1.0, -int(noise_exp % 17) * 3);
  std::vector<double> x(n), p(n);
  for (size_t i = 0; i < n; ++i) {
    const double u = double(i) / double(n - 1);
    double xi = (flags & 2) ? -std::cos(M_PI * u) : -1 + 2 * u;
    xi *= 1 - inset;
    if (inset == 0 && i == 0) xi = -1;
    if (inset == 0 && i == n - 1) xi = 1;
    double phi = 1;
    switch (shape % 4) {
      case 1: phi = 1 + 0.6 * xi; break;             // skewed
      case 2: phi = 0.2 + xi * xi * xi * xi; break;  // power-law like, a minimum at 0
      case 3: phi = 1 / (1.05 - xi * xi); break;     // a flat punch with soft corners
      default: break;                                // Hertz
    }
    phi *= 1 + amp * noise(i, seed);
    x[i] = xi;
    p[i] = std::fabs(xi) < 1 ? std::sqrt((1 - xi) * (1 + xi)) * phi : 0.0;
  }
  // raw overwrites of single samples
  for (int k = 0, m = r.byte() % 4; k < m; ++k) {
    const size_t i = (size_t(r.byte()) * 257 + r.byte()) % n;
    const double v = r.real();
    (r.byte() & 1 ? x[i] : p[i]) = v;
  }
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = (flags & 4) ? r.real() : 0.01 * (r.byte() % 100) - 0.5;
  sc.sigma_over_fp0 = (flags & 8) ? r.real() : 0.1 * (int(r.byte()) - 128);
  if (flags & 16) sc.a = r.real();

  int verdict = -1;
  size_t at = 0;
  char why[128] = {};
  require(hs_check_samples(n, x.data(), p.data(), sc.a, &verdict, &at, why, sizeof why) == HS_OK);
  require(known(verdict) && at <= n && std::memchr(why, 0, sizeof why) != nullptr);

  hs_geometry g;
  hs_geometry_default(&g);
  g.kind = HS_GEOMETRY_SAMPLES;
  g.n_samples = n;
  g.sample_x = x.data();
  g.sample_p = p.data();
  hs_solution *sol = nullptr;
  const int st = hs_solve_geometry(&sc, &g, nullptr, &sol);
  require(known(st) && hs_strerror(st) && *hs_strerror(st));
  // the samples are checked before the scene: the same verdict
  if (verdict != HS_OK) require(st == verdict);
  if (st != HS_OK) {
    require(sol == nullptr);
    return 0;
  }
  require(verdict == HS_OK);
  hs_summary su;
  su.struct_size = sizeof su;
  require(hs_solution_summary(sol, &su) == HS_OK);
  require(su.d1 >= 0 && su.d1 <= 2 * su.a && su.d2 >= 0 && su.d2 <= 2 * su.a);
  if (flags & 32) {
    double e[2];
    const int se = hs_solution_energy(sol, e);
    require(known(se));
    if (se == HS_OK) require(std::isfinite(e[0]) && std::isfinite(e[1]) && e[0] >= 0 && e[1] >= 0);
  }
  const double pts[4] = {su.b1 + 0.5 * su.d1, -su.b2 - 0.5 * su.d2, 0.5 * (su.b1 - su.b2), 0.999 * su.a};
  double out[4];
  for (auto fn : {hs_eval_Bx, hs_eval_traction}) {
    const int se = fn(sol, 4, pts, out);
    require(known(se));
    if (se == HS_OK)
      for (double v : out) require(std::isfinite(v));
  }
  if (flags & 64) {
    const int se = hs_eval_slip(sol, 2, pts, out);
    require(known(se));
    if (se == HS_OK) require(std::isfinite(out[0]) && std::isfinite(out[1]));
  }
  hs_solution_free(sol);
  return 0;
}
