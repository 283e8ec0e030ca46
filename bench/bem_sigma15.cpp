// The sigma_m = 1.5 disagreement of docs/history.md settled by the independent BEM: the segment
// energies of the BEM (reference/bem_history.hpp) at N = 200 .. 1600 elements (and as many increments
// per unit load) against the static solves (core/static_history.hpp) and the march at step 1/128
// (core/history.hpp), on two of bench_history's periodic loadings (sigma first, then chords of 16 per
// cycle): A (Q_a 0.3, Q_m 0.15, sigma_m 1.5, sigma_a 0) and B (Q_a 0.6, sigma_m 1.5, sigma_a 0.3,
// phase 180), their first 14 vertices. Per loading: the largest relative difference of a segment's
// energy E1 + E2 from the static one, over all segments and on the disputed one. About 3 minutes:
//   g++ -std=c++17 -O2 -I core/include -I reference/include -I /usr/include/eigen3 \
//       bench/bem_sigma15.cpp -o /tmp/bem15 && /tmp/bem15
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "halfslip/core/history.hpp"
#include "halfslip/core/static_history.hpp"
#include "halfslip/reference/bem_history.hpp"

using namespace hs::core;

int main() {
  struct loading {
    const char *name;
    double qa, qm, sm, sa, ph;
    size_t disputed;
  };
  const loading cases[] = {{"A (Q_a 0.3, Q_m 0.15, sigma 1.5)", 0.3, 0.15, 1.5, 0.0, 0.0, 12},
                           {"B (Q_a 0.6, sigma_m 1.5, sigma_a 0.3, phase 180)", 0.6, 0.0, 1.5, 0.3, 180.0, 10}};
  auto pm = std::make_shared<hertz_pressure<double>>();
  for (const auto &c : cases) {
    std::vector<std::pair<double, double>> p;
    const double d2r = M_PI / 180, s0 = c.sm + c.sa * std::sin(c.ph * d2r);
    p.emplace_back(0.0, s0);
    p.emplace_back(c.qm, s0);
    for (int k = 1; k <= 12; ++k) {
      const double th = 2 * M_PI * k / 16;
      p.emplace_back(c.qm + c.qa * std::sin(th), c.sm + c.sa * std::sin(th + c.ph * d2r));
    }
    static_history<double> sh(pm);
    std::vector<std::array<double, 2>> se;
    for (const auto &v : p) {
      sh.add_vertex(v.first, v.second);
      se.push_back({sh.last_segment().E1, sh.last_segment().E2});
    }
    auto rel = [&](size_t k, double e1, double e2) {
      const double E = se[k][0] + se[k][1];
      return E > 0 ? (std::fabs(e1 - se[k][0]) + std::fabs(e2 - se[k][1])) / E : 0.0;
    };
    std::printf("%s; disputed segment %zu: static E1 = %.8e, E2 = %.8e\n", c.name, c.disputed, se[c.disputed][0],
                se[c.disputed][1]);
    history_options<double> o;
    o.max_step = 1.0 / 128;
    history<double> m(pm, o);
    for (const auto &v : p) m.add_vertex(v.first, v.second);
    double wm = 0;
    for (size_t k = 0; k < p.size(); ++k) wm = std::max(wm, rel(k, m.vertices()[k].energy1, m.vertices()[k].energy2));
    std::printf("  march 1/128: largest %.2e, disputed %.2e\n", wm,
                rel(c.disputed, m.vertices()[c.disputed].energy1, m.vertices()[c.disputed].energy2));
    for (int n : {200, 400, 800, 1600}) {
      hs::reference::bem::options bo;
      bo.nodes = n;
      bo.steps_per_unit = n;
      const auto b = hs::reference::bem::run([](double x) { return std::sqrt(std::max(0.0, 1 - x * x)); }, p, bo);
      double w = 0;
      for (size_t k = 0; k < p.size(); ++k) w = std::max(w, rel(k, b[k].energy1, b[k].energy2));
      std::printf("  BEM N = %4d: largest %.2e, disputed %.2e (E1 = %.8e)\n", n, w,
                  rel(c.disputed, b[c.disputed].energy1, b[c.disputed].energy2), b[c.disputed].energy1);
    }
  }
}
