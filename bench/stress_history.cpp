// Stress run of load histories through the C ABI (issue 14, session 9): N random paths of 1-6
// vertices, |Q/fP| < 0.95, |sigma/fp0| < 2.5, Hertz / flat punch / power law, with fuzz_history's
// checks (energies >= -1e-6 of the segment's, ends finite and <= a); prints the method counts,
// the failures and the slowest path. Not part of the suite (the closing note's figures):
//   g++ -std=c++17 -O2 -I capi/include bench/stress_history.cpp -L build -lhalfslip -Wl,-rpath,$PWD/build \
//       -o /tmp/stress && /tmp/stress 300 1000 && /tmp/stress 600 5000
#include <halfslip/halfslip.h>
#include <cstdio>
#include <cmath>
#include <chrono>
#include <random>
int main(int argc, char **argv) {
  int N = atoi(argv[1]); unsigned seed0 = atoi(argv[2]);
  double worst_t = 0; int bad = 0, statics = 0, marches = 0, errs = 0;
  for (int t = 0; t < N; ++t) {
    std::mt19937 g(seed0 + t);
    std::uniform_real_distribution<double> u(-1, 1);
    int geo = g() % 3;
    hs_scene sc; hs_scene_default(&sc);
    hs_geometry gm; hs_geometry_default(&gm);
    if (geo == 1) { gm.kind = HS_GEOMETRY_FLAT_ROUNDED; gm.flat_over_a = 0.05 + 0.9 * (g() % 256) / 255.0; }
    if (geo == 2) { gm.kind = HS_GEOMETRY_POWER_LAW; gm.exponent = 1.5 + (g() % 256) / 32.0; }
    hs_history_options o; hs_history_options_default(&o);
    o.rtol = 0; o.max_step = 1.0 / (4 << (g() % 3)); o.max_steps = 4000;
    hs_history *h = nullptr;
    if (hs_history_new(&sc, &gm, &o, &h) != HS_OK) { printf("new failed\n"); continue; }
    int nv = 1 + g() % 6; double q[6], s[6];
    for (int i = 0; i < nv; ++i) { q[i] = 0.95 * u(g); s[i] = 2.5 * u(g); }
    auto t0 = std::chrono::steady_clock::now();
    int st = hs_history_add_vertices(h, nv, q, s);
    double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int method = 0; hs_history_method(h, &method);
    if (method == HS_HISTORY_STATIC) ++statics; if (method == HS_HISTORY_MARCH) ++marches;
    if (st != HS_OK) ++errs;
    size_t cnt = 0; hs_history_vertex_count(h, &cnt);
    for (size_t i = 0; i < cnt; ++i) { hs_history_vertex v; v.struct_size = sizeof v; hs_history_vertex_get(h, i, &v);
      double tol = 1e-6 * (std::fabs(v.energy1) + std::fabs(v.energy2)) + 1e-12;
      if (!(v.energy1 >= -tol && v.energy2 >= -tol) || !std::isfinite(v.b1) || !std::isfinite(v.b2) || v.b1 > 1 || v.b2 > 1) { ++bad; printf("BAD t=%d geo %d v%zu E %.3e %.3e method %d\n", t, geo, i, v.energy1, v.energy2, method); } }
    if (dt > worst_t) worst_t = dt;
    if (dt > 2) printf("slow t=%d geo %d %.2fs method %d st %d\n", t, geo, dt, method, st);
    hs_history_free(h);
  }
  printf("N %d: static %d march %d errors %d bad %d worst %.2fs\n", N, statics, marches, errs, bad, worst_t);
}
