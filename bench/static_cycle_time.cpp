// CPU of core::static_history on bench_history's periodic row (Hertz, sigma/fp0 = 0.6, then 99 half
// cycles Q/fP = -+0.3) at rtol 1e-8, best of 7, with no C ABI in between: compiled against two header
// trees it compares two versions of the core side by side on one machine (docs/benchmarks.md,
// session 17). Not part of the suite:
//   g++ -std=c++17 -O2 -DNDEBUG -I core/include -I /usr/include/eigen3 bench/static_cycle_time.cpp -o /tmp/sct
//   git archive REV core | tar -x -C /tmp/rev && g++ ... -I /tmp/rev/core/include ... -o /tmp/sct_rev
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "halfslip/core/static_history.hpp"

int main() {
  double best = 1e9;
  for (int rep = 0; rep < 7; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    hs::core::static_history<double> sh(std::make_shared<hs::core::hertz_pressure<double>>(),
                                        hs::core::static_history_accuracy<double>::for_rtol(1e-8));
    sh.add_vertex(0, 0.6);
    for (int k = 0; k < 100; ++k) sh.add_vertex(k % 2 == 0 ? 0.3 : -0.3, 0.6);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  std::printf("sigma 0.6, then 99 half cycles Q = -+0.3, Hertz, rtol 1e-8: %.2f ms (best of 7)\n", best * 1e3);
  return 0;
}
