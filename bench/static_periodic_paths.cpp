// bench_history's 162 periodic loadings (bench/periodic_survey.py, periodic_cases()) given to the static
// solves (core/static_history.hpp) as paths, vertex by vertex: sigma first from zero to sigma(0), then
// Q_m, then 3 cycles of 64 chords (no copies of a steady cycle, no march: what the static solves take
// alone; issue 14, docs/history.md "Degenerate returns"). Prints how many are taken whole; with OUT,
// every vertex's ends and segment energies in hex (case vertex b1 b2 E1 E2 Ep), or the reason a case
// stopped, to compare two header trees line by line. Not part of the suite:
//   g++ -std=c++17 -O2 -DNDEBUG -I core/include -I /usr/include/eigen3 bench/static_periodic_paths.cpp \
//       -o /tmp/spp
//   /tmp/spp 0 1e-8 [OUT]    # Hertz at rtol 1e-8 (0: full accuracy); 1: flat punch b_f/a = 0.5 (~25 s)
//   git archive REV core | tar -x -C /tmp/rev   # the same against revision REV: -I /tmp/rev/core/include
//   /tmp/spp 1 1e-8 OUT case=28 band=12          # one case, with fields of the accuracy overridden
//     (case=N; theta, lambda, band, band_theta, zone, slip, panel_tol, rtol, memory_snap: the fields of
//     static_history_accuracy; how session 23 found which order or tolerance caused a difference)
//   python3 bench/static_paths_compare.py OUT_A OUT_B [N]   # the N cases whose energies differ most
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "halfslip/core/static_history.hpp"

using namespace hs::core;

int main(int argc, char **argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s G RTOL [OUT]   (G: 0 Hertz, 1 flat punch b_f/a = 0.5; RTOL 0: full accuracy)\n",
                 argv[0]);
    return 2;
  }
  const int g = std::atoi(argv[1]);
  const double rtol = std::atof(argv[2]);
  std::FILE *out = argc > 3 ? std::fopen(argv[3], "w") : nullptr;
  auto acc = rtol > 0 ? static_history_accuracy<double>::for_rtol(rtol) : static_history_accuracy<double>();
  int only = -1;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    if (eq == std::string::npos) {
      std::fprintf(stderr, "not key=value: %s\n", argv[i]);
      return 2;
    }
    const std::string k = a.substr(0, eq);
    const double v = std::atof(a.c_str() + eq + 1);
    if (k == "case") only = int(v);
    else if (k == "theta") acc.theta = int(v);
    else if (k == "lambda") acc.lambda = int(v);
    else if (k == "band") acc.band = int(v);
    else if (k == "band_theta") acc.band_theta = int(v);
    else if (k == "zone") acc.zone = int(v);
    else if (k == "slip") acc.slip = int(v);
    else if (k == "panel_tol") acc.panel_tol = v;
    else if (k == "rtol") acc.rtol = v;
    else if (k == "memory_snap") acc.memory_snap = v;
    else {
      std::fprintf(stderr, "unknown key: %s\n", k.c_str());
      return 2;
    }
  }
  std::shared_ptr<const pressure_model<double>> pm;
  if (g == 0) pm = std::make_shared<hertz_pressure<double>>();
  else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
  const double pi = 3.14159265358979323846;
  int idx = 0, whole = 0;
  for (double qa : {0.1, 0.3, 0.6})
    for (double qm : {0.0, 0.15})
      for (double sm : {0.0, 0.5, 1.5})
        for (double sa : {0.0, 0.3, 1.0})
          for (double phd : {0.0, 45.0, 90.0, 180.0}) {
            if (sa == 0 && phd != 0) continue;
            const int c = idx++;
            if (only >= 0 && c != only) continue;
            const double ph = phd * pi / 180, s0 = sm + sa * std::sin(ph);
            std::vector<std::pair<double, double>> w{{0, s0}};
            if (qm != 0) w.push_back({qm, s0});
            for (int cy = 0; cy < 3; ++cy)
              for (int k = 1; k <= 64; ++k) {
                const double t = 2 * pi * k / 64;
                w.push_back({qm + qa * std::sin(t), sm + sa * std::sin(t + ph)});
              }
            static_history<double> h(pm, acc);
            size_t k = 0;
            try {
              for (; k < w.size(); ++k) {
                h.add_vertex(w[k].first, w[k].second);
                const auto &sg = h.last_segment();
                if (out)
                  std::fprintf(out, "%d %zu %a %a %a %a %a\n", c, k, double(h.b1()), double(h.b2()), double(sg.E1),
                               double(sg.E2), double(sg.Ep));
              }
              ++whole;
            } catch (const error &e) {
              if (out) std::fprintf(out, "%d %zu stop %s\n", c, k, e.what());
            }
          }
  if (only >= 0)
    std::printf("%s, rtol %g, case %d: %s\n", g == 0 ? "Hertz" : "flat punch b_f/a = 0.5", rtol, only,
                whole ? "taken whole as a path by the static solves" : "stopped (OUT gives the vertex)");
  else
    std::printf("%s, rtol %g: %d of %d periodic loadings taken whole as paths by the static solves\n",
                g == 0 ? "Hertz" : "flat punch b_f/a = 0.5", rtol, whole, idx);
  if (out) std::fclose(out);
  return 0;
}
