// halfslip -- the random non-proportional load paths of bench_history, shared by the benchmarks
// and tests that use them (bench/bench_history.cpp, bench/static_walks.cpp,
// tests/test_static_history.cpp): n vertices (Q/fP, sigma/fp0) from (0, 0), each move a uniform
// step of at most 0.15 in both, |Q/fP| <= 0.5 and 0 <= sigma/fp0 <= 1.2 (clamped). std::mt19937 is
// fully specified by the standard; std::uniform_real_distribution is not, so the walks are those
// of libstdc++ (GCC), on which the quoted figures were made.
#ifndef HALFSLIP_REFERENCE_RANDOM_WALK_HPP
#define HALFSLIP_REFERENCE_RANDOM_WALK_HPP

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace hs { namespace reference {

inline std::vector<std::pair<double, double>> random_walk(int n, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::pair<double, double>> p;
  double q = 0, s = 0;
  for (int i = 0; i < n; ++i) {
    q = std::max(-0.5, std::min(0.5, q + 0.15 * u(g)));
    s = std::max(0.0, std::min(1.2, s + 0.15 * u(g)));
    p.emplace_back(q, s);
  }
  return p;
}

}}  // namespace hs::reference

#endif
