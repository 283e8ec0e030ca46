// The independent BEM (reference/bem_history.hpp) on one chord of a periodic loading in K equal parts:
// where it slips during each part (runs of elements with a slip increment, and its sign). Not part of the
// suite; the BEM's picture of case 3's chord 38 in docs/history.md ("A patch end just beyond a memory
// point", session 18) comes from
//   g++ -std=c++17 -O2 -I reference/include -I /usr/include/eigen3 bench/bem_chord_parts.cpp -o /tmp/bcp
//   /tmp/bcp 0 0.1 0 0.3 90 1600 40 8      # QM QA SM SA PHASE_DEG N V K (the chord to path entry V, 1-based)
// BEM: march a periodic path to vertex V-1, then the segment to V in K sub-steps, printing slip runs
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "halfslip/reference/bem_history.hpp"
int main(int argc, char **argv) {
  const double pi = 3.141592653589793238462643383279502884;
  const double qm = std::atof(argv[1]), qa = std::atof(argv[2]), sm = std::atof(argv[3]), sa = std::atof(argv[4]);
  const double ph = std::atof(argv[5]) * pi / 180;
  const int N = std::atoi(argv[6]); const size_t V = std::atoi(argv[7]); const int K = std::atoi(argv[8]);
  const int chords = 64;
  std::vector<std::pair<double, double>> path;
  const double s0 = sm + sa * std::sin(ph);
  if (s0 != 0) path.push_back({0.0, s0});
  if (qm != 0) path.push_back({qm, s0});
  for (int j = 1; j <= 3 * chords; ++j) { const double th = 2 * pi * j / chords; path.push_back({qm + qa * std::sin(th), sm + sa * std::sin(th + ph)}); }
  auto hertz = [](double x) { return std::sqrt(std::max(0.0, (1 - x) * (1 + x))); };
  hs::reference::bem::detail::marcher m(hertz, N);
  double Q0 = 0, S0 = 0, e1 = 0, e2 = 0; int itm = 0;
  auto seg = [&](double Q, double S, int steps) { m.segment(Q, S, steps, 200, e1, e2, itm); Q0 = Q; S0 = S; };
  for (size_t i = 0; i + 1 < V; ++i) { double len = std::max(std::fabs(path[i].first - Q0), std::fabs(path[i].second - S0) / 4); seg(path[i].first, path[i].second, std::max(1, int(std::ceil(N * len)))); }
  const double Qa = Q0, Sa = S0; const double Qb = path[V-1].first, Sb = path[V-1].second;
  double len = std::max(std::fabs(Qb - Qa), std::fabs(Sb - Sa) / 4);
  int steps = std::max(K, int(std::ceil(4 * N * len / K)) * K) / K;
  auto x = m.x();
  for (int k = 1; k <= K; ++k) {
    std::vector<double> h0(m.h().data(), m.h().data() + m.h().size());
    seg(Qa + (Qb - Qa) * k / K, Sa + (Sb - Sa) * k / K, steps);
    const auto &h1 = m.h();
    double hs_ = 0; for (size_t i = 0; i < h0.size(); ++i) hs_ = std::max(hs_, std::fabs(h1[i] - h0[i]));
    std::printf("sub %d/%d:", k, K);
    int cur = 2; double start = 0;
    for (size_t i = 0; i <= h0.size(); ++i) {
      int s = 2;
      if (i < h0.size()) { double d = h1[i] - h0[i]; s = std::fabs(d) > 1e-9 * hs_ ? (d > 0 ? 1 : -1) : 0; }
      if (s != cur) { if (i > 0 && cur != 0) std::printf(" [%.5f,%.5f]%+d", start, x[i-1], cur); cur = s; if (i < h0.size()) start = x[i]; }
    }
    std::printf("\n");
  }
}
