// The march (core/history.hpp) at steps 2^-7 .. 2^-12 against the static solves on a path given
// as vertices "q s q s ..." (docs/history.md: the march converges towards the static state on a
// random walk's reopening zone, and is erratic at a fold). Not part of the suite:
//   g++ -std=c++17 -O2 -I core/include -I /usr/include/eigen3 bench/march_convergence.cpp -o /tmp/conv
//   /tmp/conv 0.056814995100830532 0.071682684769338811 -0.084586195122613936 0.29839205822467929 \
//             -0.10845946807048669 0.43782179835999091          (b2 0.951063 .. 0.950059 against 0.950048)
//   /tmp/conv -0.045517236661488734 0.18251664855221592 -0.036373579579636328 0.014701545775238661 \
//             -0.044572900770694188 0.2500291447517029          (the fold of tests/test_static_history.cpp)
#include <cstdio>
#include <cmath>
#include <memory>
#include <vector>
#include "halfslip/core/hertz.hpp"
#include "halfslip/core/history.hpp"
#include "halfslip/core/static_history.hpp"
using namespace hs::core;
int main(int argc, char **argv) {
  auto pm = std::make_shared<hertz_pressure<double>>();
  std::vector<double> v; for (int i = 1; i < argc; ++i) v.push_back(atof(argv[i]));
  static_history<double> h(pm);
  for (size_t k = 0; k + 1 < v.size(); k += 2) h.add_vertex(v[k], v[k+1]);
  printf("static: b %.12f %.12f d %d %d E %.10e %.10e\n", h.b1(), h.b2(), h.dir1(), h.dir2(), h.last_segment().E1, h.last_segment().E2);
  for (int p = 7; p <= 12; ++p) {
    history_options<double> o; o.max_step = std::ldexp(1.0, -p); o.max_steps = 2000000;
    history<double> m(pm, o);
    try { for (size_t k = 0; k + 1 < v.size(); k += 2) m.add_vertex(v[k], v[k+1]);
      auto &x = m.vertices().back(); printf("march 2^-%d: b %.12f %.12f d %d %d E %.10e %.10e\n", p, x.b1, x.b2, x.dir1, x.dir2, x.energy1, x.energy2); }
    catch (std::exception &e) { printf("march 2^-%d: %s\n", p, e.what()); }
  }
}
