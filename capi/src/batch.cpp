// halfslip C ABI: hs_solve_batch (issue 16). A thin loop over the same calls a
// user would make per scene (hs_solve, hs_solution_summary,
// hs_solution_energy), so that every result is bitwise what one call per scene
// gives; the scenes are cut into fixed contiguous chunks, one per std::thread.
// No state outlives the call; no exception leaves it (each scene's calls are
// guarded, thread start-up failures fall back to the calling thread).
#include <cstring>
#include <exception>
#include <thread>
#include <vector>

#include "halfslip/halfslip.h"

namespace hs { namespace capi {
// HS_OK or the status hs_solve would give for these options (halfslip.cpp)
int validate_options(const hs_options *opts);
}}  // namespace hs::capi

namespace {

hs_batch_result solve_one(const hs_scene &scene, const hs_options *opts, int flags) {
  hs_batch_result r;
  std::memset(&r, 0, sizeof r);
  hs_solution *sol = nullptr;
  int st = hs_solve(&scene, opts, &sol);
  if (st == HS_OK) {
    hs_summary su;
    su.struct_size = sizeof su;
    st = hs_solution_summary(sol, &su);
    double e[2] = {0, 0};
    if (st == HS_OK && (flags & HS_BATCH_ENERGIES)) st = hs_solution_energy(sol, e);
    if (st == HS_OK) {
      r.regime = su.regime;
      r.slip_dir1 = su.slip_dir1;
      r.slip_dir2 = su.slip_dir2;
      r.model = su.model;
      r.iterations = su.iterations;
      r.b1 = su.b1;
      r.b2 = su.b2;
      r.d1 = su.d1;
      r.d2 = su.d2;
      r.error_estimate = su.error_estimate;
      r.energy1 = e[0];
      r.energy2 = e[1];
    }
    hs_solution_free(sol);
  }
  r.status = st;
  return r;
}

void solve_range(size_t lo, size_t hi, const hs_scene *scenes, const hs_options *opts, int flags,
                 hs_batch_result *out) noexcept {
  for (size_t i = lo; i < hi; ++i) out[i] = solve_one(scenes[i], opts, flags);
}

}  // namespace

extern "C" int hs_solve_batch(size_t n, const hs_scene *scenes, const hs_options *opts, int flags, int threads,
                              hs_batch_result *out, size_t result_size) {
  if (result_size != sizeof(hs_batch_result)) return HS_ERR_STRUCT_SIZE;
  if (threads < 0 || threads > 1024) return HS_ERR_BAD_OPTION;
  if (flags & ~HS_BATCH_ENERGIES) return HS_ERR_BAD_OPTION;
  if (n == 0) return HS_OK;
  if (!scenes || !out) return HS_ERR_NULL_POINTER;
  // the options are the same for every scene: checked once, so that a bad
  // option fails the call rather than n scenes alike
  if (const int st = hs::capi::validate_options(opts)) return st;
  size_t nt = threads > 0 ? size_t(threads) : size_t(std::thread::hardware_concurrency());
  if (nt == 0) nt = 1;
  if (nt > n) nt = n;
  const size_t chunk = (n + nt - 1) / nt;
  std::vector<std::thread> pool;
  size_t started = 1;  // chunks 1 .. started-1 run on their own threads, chunk 0 here
  try {
    pool.reserve(nt - 1);
    for (; started < nt && started * chunk < n; ++started) {
      const size_t lo = started * chunk, hi = lo + chunk < n ? lo + chunk : n;
      pool.emplace_back(solve_range, lo, hi, scenes, opts, flags, out);
    }
  } catch (const std::exception &) {
    // a thread could not be started (resources): its chunks run here
  }
  solve_range(0, chunk < n ? chunk : n, scenes, opts, flags, out);
  if (started * chunk < n) solve_range(started * chunk, n, scenes, opts, flags, out);
  for (auto &th : pool) th.join();
  return HS_OK;
}
