// Static solves (core/static_history.hpp) against the march (core/history.hpp, step 1/128) on the
// periodic loadings of bench_history that the static solves complete: largest end and relative
// energy differences per loading (docs/history.md, session-9 comparison). Not part of the suite:
//   g++ -std=c++17 -O2 -I core/include bench/compare_static_march.cpp -o /tmp/cmp && /tmp/cmp
#include <cmath>
#include <cstdio>
#include "halfslip/core/static_history.hpp"
#include "halfslip/core/history.hpp"
using namespace hs::core;
int main(){
  auto pm = std::make_shared<hertz_pressure<double>>();
  int n = 0, cmp = 0; double worst = 0, worstE = 0;
  for (double qa : {0.1, 0.3, 0.6}) for (double qm : {0.0, 0.15}) for (double sm : {0.0, 0.5, 1.5}) for (double sa : {0.0, 0.3, 1.0}) for (double ph : {0.0, 45.0, 90.0, 180.0}) {
    if (sa == 0 && ph != 0) continue;
    ++n;
    std::vector<std::pair<double,double>> p;
    const double d2r = M_PI/180, s0 = sm + sa*std::sin(ph*d2r);
    p.emplace_back(0.0, s0); p.emplace_back(qm, s0);
    for (int c = 0; c < 3; ++c) for (int k = 1; k <= 16; ++k) { double th = 2*M_PI*k/16; p.emplace_back(qm + qa*std::sin(th), sm + sa*std::sin(th + ph*d2r)); }
    static_history<double> h(pm);
    std::vector<std::array<double,4>> sv;
    bool ok = true;
    try { for (auto&v: p) { h.add_vertex(v.first, v.second); sv.push_back({h.b1(), h.b2(), h.last_segment().E1, h.last_segment().E2}); } } catch (...) { ok = false; }
    if (!ok) continue;
    history_options<double> o; o.max_step = 1.0/128; o.merge_interior_patches = false;
    history<double> m(pm, o);
    double w = 0, wE = 0; size_t k = 0;
    try { for (auto&v: p) { m.add_vertex(v.first, v.second); auto&mv = m.vertices().back();
      w = std::max(w, std::max(std::fabs(mv.b1 - sv[k][0]), std::fabs(mv.b2 - sv[k][1])));
      double Es = std::fabs(sv[k][2]) + std::fabs(sv[k][3]) + 1e-6;
      wE = std::max(wE, (std::fabs(mv.energy1 - sv[k][2]) + std::fabs(mv.energy2 - sv[k][3])) / Es); ++k; } } catch (std::exception&e) { printf("march failed qa %g qm %g sm %g sa %g ph %g at %zu: %s\n", qa,qm,sm,sa,ph,k,e.what()); continue; }
    ++cmp;
    if (w > 1e-5 || wE > 1e-4) printf("qa %g qm %g sm %g sa %g ph %g: ends %.2e energies %.2e\n", qa,qm,sm,sa,ph, w, wE);
    worst = std::max(worst, w); worstE = std::max(worstE, wE);
  }
  printf("%d loadings compared; worst ends %.2e a, energies %.2e (relative)\n", cmp, worst, worstE);
}
