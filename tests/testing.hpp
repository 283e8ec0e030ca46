// Shared helpers for the doctest suites: relative errors measured in units of
// the type's epsilon (Boost.Math style), NaN/Inf aware.
#pragma once
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace hs_test {

template <class T> T eps() { return std::numeric_limits<T>::epsilon(); }

// |a - b| / |b| in units of eps<T>; both NaN/Inf mismatches give +Inf.
template <class T> double rel_eps(T a, T b) {
  using std::abs;
  if (std::isnan(double(a)) || std::isnan(double(b))) return HUGE_VAL;
  if (a == b) return 0;
  if (b == 0) return HUGE_VAL;
  return double(abs(a - b) / abs(b) / eps<T>());
}
// |a - b| / scale in units of eps<T>.
template <class T> double abs_eps(T a, T b, T scale = T(1)) {
  using std::abs;
  if (std::isnan(double(a)) || std::isnan(double(b))) return HUGE_VAL;
  return double(abs(a - b) / scale / eps<T>());
}

// Deterministic pseudo-random stream for the tests.
struct rng {
  std::mt19937_64 g;
  explicit rng(unsigned long seed) : g(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  // log-uniform in [lo, hi], lo > 0
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
};

}  // namespace hs_test

// HS_LONG marks a test case that takes seconds in the release build (a sweep, a BEM at fine N) and
// repeats code paths that shorter cases of the same suite also run: TEST_CASE("name" * HS_LONG).
// The sanitizer builds of scripts/reliability.sh skip such cases (there they take minutes; CMake
// defines HS_TEST_SANITIZED), the release ctest runs every one. `--no-skip` runs them anyway.
#include <doctest/doctest.h>
#ifdef HS_TEST_SANITIZED
#define HS_LONG doctest::skip(true)
#else
#define HS_LONG doctest::skip(false)
#endif
