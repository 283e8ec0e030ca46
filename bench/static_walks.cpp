// Random non-proportional walks through the static solves (core/static_history.hpp, issue 14): how far
// they take each walk, what stops them, and their agreement with the independent BEM
// (reference/bem_history.hpp) as far as they go. The walks are bench_history's (100 vertices,
// |Q/fP| <= 0.5, sigma/fp0 in [0, 1.2], moves up to 0.15). Not part of the suite (docs/history.md,
// "Folds", and the CHANGELOG quote its figures):
//   g++ -std=c++17 -O2 -I core/include -I reference/include -I /usr/include/eigen3 \
//       bench/static_walks.cpp -o /tmp/static_walks
//   /tmp/static_walks count 0 60       # Hertz: vertices taken and the reasons, 60 walks (~20 s)
//   /tmp/static_walks count 1 60       # flat punch b_f/a = 0.5 (~40 s)
//   /tmp/static_walks bem 0 400 1 20   # Hertz walks 1..20 against the BEM at N = 400 (~2 min)
//   /tmp/static_walks bem 1 400 1 20
//   /tmp/static_walks time 0 60        # CPU time of the walks taken whole, at rtol 1e-8 and full accuracy
//   /tmp/static_walks patchtime 0 60   # CPU per segment: those that end with an interior slip zone, others
//   /tmp/static_walks count 0 60 1e-8  # the same count at an accuracy asked (static_history_accuracy::for_rtol)
//   /tmp/static_walks count 0 60 1e-8 retry   # ... and a refused segment solved again at full accuracy, as
//                                             # hs_history does (capi/src/history.cpp, add_static)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"
#include "halfslip/reference/random_walk.hpp"

using namespace hs::core;
using path_t = std::vector<std::pair<double, double>>;

static path_t random_path(int n, unsigned seed) { return hs::reference::random_walk(n, seed); }

int main(int argc, char **argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s count G WALKS | bem G N FIRST LAST   (G: 0 Hertz, 1 flat punch 0.5)\n", argv[0]);
    return 2;
  }
  const bool bem = std::strcmp(argv[1], "bem") == 0, timing = std::strcmp(argv[1], "time") == 0;
  const int g = std::atoi(argv[2]);
  std::shared_ptr<const pressure_model<double>> pm;
  if (g == 0) pm = std::make_shared<hertz_pressure<double>>();
  else pm = std::make_shared<flat_rounded_pressure<double>>(0.5);
  if (std::strcmp(argv[1], "patchtime") == 0) {
    // CPU per segment at rtol 1e-8, those that end with an interior slip zone open (Ep > 0) and
    // the others, as far as the static solves take each walk
    const unsigned n = unsigned(std::atoi(argv[3]));
    std::vector<double> tp, tn;
    for (unsigned seed = 1; seed <= n; ++seed) {
      const path_t w = random_path(100, seed);
      static_history<double> h(pm, static_history_accuracy<double>::for_rtol(1e-8));
      for (const auto &p : w) {
        const std::clock_t c0 = std::clock();
        try {
          h.add_vertex(p.first, p.second);
        } catch (const error &) {
          break;
        }
        const double t = double(std::clock() - c0) / CLOCKS_PER_SEC * 1e3;
        (h.last_segment().Ep > 0 ? tp : tn).push_back(t);
      }
    }
    std::sort(tp.begin(), tp.end());
    std::sort(tn.begin(), tn.end());
    auto at = [](const std::vector<double> &v, double f) { return v.empty() ? 0.0 : v[size_t(f * double(v.size() - 1))]; };
    std::printf("%s: %zu segments with a patch: median %.1f ms, 90th percentile %.1f, largest %.1f; %zu others: "
                "median %.2f ms, 90th percentile %.2f\n", g == 0 ? "Hertz" : "flat punch", tp.size(), at(tp, 0.5),
                at(tp, 0.9), at(tp, 1.0), tn.size(), at(tn, 0.5), at(tn, 0.9));
    return 0;
  }
  if (timing) {
    const unsigned n = unsigned(std::atoi(argv[3]));
    for (unsigned seed = 1; seed <= n; ++seed) {
      const path_t w = random_path(100, seed);
      double t[2] = {0, 0};
      bool whole = true;
      for (int a = 0; a < 2 && whole; ++a) {
        double best = 1e30;
        for (int r = 0; r < 3 && whole; ++r) {
          const std::clock_t c0 = std::clock();
          try {
            static_history<double> h(pm, a == 0 ? static_history_accuracy<double>::for_rtol(1e-8)
                                                : static_history_accuracy<double>());
            for (const auto &p : w) h.add_vertex(p.first, p.second);
          } catch (const error &) {
            whole = false;
          }
          best = std::min(best, double(std::clock() - c0) / CLOCKS_PER_SEC);
        }
        t[a] = best;
      }
      if (whole)
        std::printf("walk %u (100 vertices): %.1f ms CPU at rtol 1e-8, %.1f ms at full accuracy (best of 3)\n", seed,
                    t[0] * 1e3, t[1] * 1e3);
    }
    return 0;
  }
  if (!bem) {
    const unsigned n = unsigned(std::atoi(argv[3]));
    std::map<std::string, int> why;
    size_t taken = 0;
    int whole = 0, retried = 0;
    for (unsigned seed = 1; seed <= n; ++seed) {
      const path_t w = random_path(100, seed);
      const double rtol = argc > 4 ? std::atof(argv[4]) : 0;
      const bool retry = argc > 5 && std::strcmp(argv[5], "retry") == 0;
      const auto acc = static_history_accuracy<double>::for_rtol(rtol);
      static_history<double> h(pm, acc);
      size_t k = 0;
      try {
        for (; k < w.size(); ++k) {
          if (!retry || !(rtol > 0)) {
            h.add_vertex(w[k].first, w[k].second);
            continue;
          }
          static_history<double> t(h);
          try {
            t.add_vertex(w[k].first, w[k].second);
          } catch (const error &) {
            t = h;
            t.set_accuracy(static_history_accuracy<double>());
            t.add_vertex(w[k].first, w[k].second);
            t.set_accuracy(acc);
            ++retried;
          }
          h = t;
        }
        ++whole;
      } catch (const error &e) {
        ++why[e.what()];
      }
      taken += k;
    }
    std::printf("%s: %zu of %u vertices taken, %d walks whole, %d segments taken at full accuracy after a refusal; "
                "stopped by:\n", g ? "flat punch" : "Hertz", taken, 100 * n, whole, retried);
    for (const auto &kv : why) std::printf("  %3d  %s\n", kv.second, kv.first.c_str());
    return 0;
  }
  const int N = std::atoi(argv[3]);
  const unsigned s0 = unsigned(std::atoi(argv[4])), s1 = unsigned(argc > 5 ? std::atoi(argv[5]) : std::atoi(argv[4]));
  double worst_b = 0, worst_e = 0;
  for (unsigned seed = s0; seed <= s1; ++seed) {
    const path_t w = random_path(100, seed);
    static_history<double> h(pm);
    std::vector<std::array<double, 6>> st;
    path_t done;
    for (const auto &p : w) {
      try {
        h.add_vertex(p.first, p.second);
      } catch (const error &) {
        break;
      }
      // (an interior slip zone's energy, Ep, to the zone whose side of the stick zone's centre it lies
      // on, as the BEM counts it)
      const auto &sg = h.last_segment();
      const bool right = h.patch_dir() != 0 && (h.patch_l() + h.patch_r()) / 2 > (h.b1() - h.b2()) / 2;
      st.push_back({h.b1(), h.b2(), double(h.dir1()), double(h.dir2()), sg.E1 + (right ? sg.Ep : 0.0),
                    sg.E2 + (right ? 0.0 : sg.Ep)});
      done.push_back(p);
    }
    if (done.empty()) continue;
    hs::reference::bem::options o;
    o.nodes = o.steps_per_unit = N;
    const auto r = hs::reference::bem::run([&](double x) { return pm->p(x); }, done, o);
    double Emax = 0;
    for (const auto &x : st) Emax = std::max({Emax, x[4], x[5]});
    double wb = 0, we = 0;
    int dirs = 0;
    for (size_t k = 0; k < done.size(); ++k)
      for (int i = 0; i < 2; ++i) {
        const double b = st[k][i], bb = i ? r[k].b2 : r[k].b1;
        const double width = 3.141592653589793 / N * std::sqrt(std::max(1 - b * b, 0.0)) + 2.0 / (double(N) * N);
        wb = std::max(wb, std::fabs(b - bb) / width);
        we = std::max(we, std::fabs(st[k][4 + i] - (i ? r[k].energy2 : r[k].energy1)) / Emax);
        if (int(st[k][2 + i]) != (i ? r[k].dir2 : r[k].dir1) && 1 - b > 2 * width) ++dirs;
      }
    std::printf("walk %u: %zu vertices; ends within %.2f element widths, energies within %.2e of the largest; "
                "%d slip directions differ\n", seed, done.size(), wb, we, dirs);
    worst_b = std::max(worst_b, wb);
    worst_e = std::max(worst_e, we);
  }
  std::printf("worst: %.2f element widths, %.2e of the largest energy\n", worst_b, worst_e);
}
