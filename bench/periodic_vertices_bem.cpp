// The static solves (core/static_history.hpp) against the independent BEM (reference/bem_history.hpp)
// vertex by vertex on one of bench/periodic_survey.py's periodic loadings (sigma first, 64 chords a
// cycle, 3 cycles), as far as the static solves take it: the largest difference of each zone's
// energy over a segment (a patch's counted with the zone on its side of the stick zone's centre),
// over the largest, of the ends, and the slip directions that differ. Not part of the suite; the
// figures quoted in tests/test_static_patch.cpp and docs/history.md (session 17):
//   g++ -std=c++17 -O2 -I core/include -I reference/include -I /usr/include/eigen3 \
//       bench/periodic_vertices_bem.cpp -o /tmp/pvb
//   /tmp/pvb QM QA SM SA PHASE_DEG N [VERTICES]   # e.g. /tmp/pvb 0.15 0.1 0 0.3 90 800 42 (case 30)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>
#include <vector>

#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"

int main(int argc, char **argv) {
  if (argc < 7) {
    std::fprintf(stderr, "usage: %s QM QA SM SA PHASE_DEG N [VERTICES]\n", argv[0]);
    return 2;
  }
  const double pi = 3.141592653589793238462643383279502884;
  const double qm = std::atof(argv[1]), qa = std::atof(argv[2]), sm = std::atof(argv[3]), sa = std::atof(argv[4]);
  const double ph = std::atof(argv[5]) * pi / 180;
  const int N = std::atoi(argv[6]);
  const size_t limit = argc > 7 ? size_t(std::atol(argv[7])) : size_t(-1);
  // the path as tests/test_static_patch.cpp's periodic(): the ramp (sigma first), then the chords
  std::vector<std::pair<double, double>> path;
  const double s0 = sm + sa * std::sin(ph);
  if (s0 != 0) path.push_back({0.0, s0});
  if (qm != 0) path.push_back({qm, s0});
  for (int j = 1; j <= 3 * 64; ++j) {
    const double th = 2 * pi * j / 64;
    path.push_back({qm + qa * std::sin(th), sm + sa * std::sin(th + ph)});
  }
  if (path.size() > limit) path.resize(limit);
  hs::core::static_history<double> sh(std::make_shared<hs::core::hertz_pressure<double>>());
  struct rec {
    double E1, E2, b1, b2;
    int d1, d2;
  };
  std::vector<rec> v;
  for (const auto &p : path) {
    try {
      sh.add_vertex(p.first, p.second);
    } catch (const std::exception &e) {
      std::printf("the static solves stop at vertex %zu: %s\n", v.size(), e.what());
      break;
    }
    const auto &sg = sh.last_segment();
    const bool right = sh.patch_dir() != 0 && sh.patch_l() + sh.patch_r() > sh.b1() - sh.b2();
    v.push_back({sg.E1 + (right ? sg.Ep : 0.0), sg.E2 + (right ? 0.0 : sg.Ep), sh.b1(), sh.b2(), sh.dir1(), sh.dir2()});
  }
  path.resize(v.size());
  auto hertz = [](double x) { return std::sqrt(std::max(0.0, (1 - x) * (1 + x))); };
  hs::reference::bem::options bo;
  bo.nodes = bo.steps_per_unit = N;
  const auto r = hs::reference::bem::run(hertz, path, bo);
  double big = 0, de = 0, db = 0;
  int dirs = 0;
  for (const auto &x : r) big = std::max({big, x.energy1, x.energy2});
  for (size_t i = 0; i < v.size(); ++i) {
    de = std::max({de, std::fabs(v[i].E1 - r[i].energy1), std::fabs(v[i].E2 - r[i].energy2)});
    db = std::max({db, std::fabs(v[i].b1 - r[i].b1), std::fabs(v[i].b2 - r[i].b2)});
    dirs += v[i].d1 != r[i].dir1 || v[i].d2 != r[i].dir2;
  }
  std::printf("%zu vertices, %zu patch segments; BEM N = %d: energies within %.2e of the largest, ends within %.2e a, "
              "%d vertices with a slip direction that differs\n",
              v.size(), sh.patch_segments(), N, de / big, db, dirs);
  return 0;
}
