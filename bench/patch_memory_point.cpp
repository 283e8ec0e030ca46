// The two-interval solve (core/static_patch.hpp) on one chord of a periodic loading with the patch's
// inner end pr held near a memory point m (the old stick end): (b1, b2, pl) solving r0, r1, r2 for pr
// at offsets from m, with r3 (the patch's slip closure) printed, then the four-condition Newton from
// starts with pr just beyond m. Not part of the suite; the figures of docs/history.md, "A patch end just
// beyond a memory point" (session 18), come from
//   g++ -std=c++17 -O2 -I core/include -I reference/include -I /usr/include/eigen3 \
//       bench/patch_memory_point.cpp -o /tmp/pmp
//   /tmp/pmp 0 0.1 0 0.3 90 39 -1 1 -1 -0.915 0.9671 0.9998
// arguments: QM QA SM SA PHASE_DEG V (the chord to vertex V, sigma first, 64 chords a cycle) D1 D2 DP
// (zone and patch directions after the turn) PL B1 B2 (starts of the held-pr solves).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>
#include <Eigen/Dense>
#include "halfslip/core/static_history.hpp"
using namespace hs::core;
int main(int argc, char **argv) {
  const double pi = 3.141592653589793238462643383279502884;
  const double qm = std::atof(argv[1]), qa = std::atof(argv[2]), sm = std::atof(argv[3]), sa = std::atof(argv[4]);
  const double ph = std::atof(argv[5]) * pi / 180; const size_t V = std::atoi(argv[6]);
  const int d1 = std::atoi(argv[7]), d2 = std::atoi(argv[8]), dp = std::atoi(argv[9]);
  const double pl0 = std::atof(argv[10]), b10 = std::atof(argv[11]), b20 = std::atof(argv[12]);
  std::vector<std::pair<double, double>> path;
  const double s0 = sm + sa * std::sin(ph);
  if (s0 != 0) path.push_back({0.0, s0});
  if (qm != 0) path.push_back({qm, s0});
  for (int j = 1; j <= 3 * 64; ++j) { const double th = 2 * pi * j / 64; path.push_back({qm + qa * std::sin(th), sm + sa * std::sin(th + ph)}); }
  static_history<double> sh(std::make_shared<hertz_pressure<double>>());
  for (size_t i = 0; i < V; ++i) sh.add_vertex(path[i].first, path[i].second);
  auto st = std::make_shared<const sh_start<double>>(sh.start());
  const double dq = path[V].first - sh.q(), ds = path[V].second - sh.s();
  auto mp = sh.memory_points();
  std::printf("memory points:"); for (double m : mp) std::printf(" %.6f", m); std::printf("\n");
  const double m = -sh.b2();
  double b1 = b10, b2 = b20, pl = pl0;
  std::vector<double> offs{-1e-5, -1e-7, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5}; for (double off : offs) {
    const double pr = m + off;
    double x[3] = {b1, b2, std::min(pl, pr - 0.001)};
    bool ok = false; std::array<double,4> r{};
    for (int it = 0; it < 40; ++it) {
      sh_patch<double> P(st, dq, ds, d1, d2, dp, 24);
      auto R = [&](const double *y) { sh_patch_ends<double> e{y[0], y[1], y[2], pr}; return P.residual(e); };
      r = R(x);
      double n = std::fabs(r[0]) + std::fabs(r[1]) + std::fabs(r[2]);
      if (n < 1e-13) { ok = true; break; }
      Eigen::Matrix3d J; for (int j = 0; j < 3; ++j) { double y[3] = {x[0], x[1], x[2]}; double h = 1e-7; y[j] += h; auto rp = R(y); y[j] -= 2*h; auto rm = R(y); for (int i = 0; i < 3; ++i) J(i,j) = (rp[i]-rm[i])/(2*h); }
      Eigen::Vector3d F(r[0], r[1], r[2]); Eigen::Vector3d dx = J.fullPivLu().solve(F);
      double lam = 1; for (int k = 0; k < 30; ++k, lam /= 2) { double y[3] = {x[0]-lam*dx(0), x[1]-lam*dx(1), x[2]-lam*dx(2)}; if (!(y[2] < pr && y[0] > pr && -y[1] < y[2] && y[0] <= 1 && y[1] <= 1)) continue; auto rt = R(y); if (std::fabs(rt[0])+std::fabs(rt[1])+std::fabs(rt[2]) < n) { x[0]=y[0]; x[1]=y[1]; x[2]=y[2]; break; } }
    }
    std::printf("pr = m %+g: ok %d b1 %.6f b2 %.6f pl %.6f  r %.2e %.2e %.2e r3 %.3e\n", off, ok, x[0], x[1], x[2], r[0], r[1], r[2], r[3]);
    if (ok) { b1 = x[0]; b2 = x[1]; pl = x[2]; }
  }

  for (double off : {1e-5, 1e-4}) {
    for (double plx : {-0.928, -0.946, -0.9725}) {
      sh_patch<double> P(st, dq, ds, d1, d2, dp, 24);
      sh_patch_ends<double> e0{0.967145, 0.999811, plx, m + off};
      bool ok = P.solve(e0);
      if (ok) { auto e = P.solved(); std::printf("4D from pr=m+%g pl=%g: ok b1 %.7f b2 %.7f pl %.7f pr-m %.3e one_way %d %d %d E %g %g %g\n", off, plx, e.b1, e.b2, e.pl, e.pr - m, P.one_way(1), P.one_way(2), P.one_way(3), P.energy(1), P.energy(2), P.energy(3)); }
      else std::printf("4D from pr=m+%g pl=%g: fail\n", off, plx);
    }
  }
}
