// The sweep behind the asymptotic model's error estimate (core/select.hpp):
// for Hertz, the flat punch (b_f/a = 0.3, 0.6, 0.9) and the power law
// (n = 1.5, 3, 6), random loads with slip zones from ~1e-7 a to ~a in both
// regimes, the asymptotic model's d_i and zone energies against the full
// solution (quadrature at full double precision). Writes one CSV row per
// zone and prints, per geometry, the largest true/estimate ratios (must stay
// below 1; the constants C1 = 2, C2 = 32 were chosen as twice the needed ones).
//   usage: asymptotic_sweep OUT.csv [scenes_per_geometry = 200]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "halfslip/core/asymptotic.hpp"
#include "halfslip/core/select.hpp"

using namespace hs::core;

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: asymptotic_sweep OUT.csv [scenes_per_geometry]\n");
    return 2;
  }
  const int n = argc > 2 ? std::atoi(argv[2]) : 200;
  std::FILE *out = std::fopen(argv[1], "w");
  if (!out) return 1;
  std::fprintf(out, "geometry,parameter,zone,q,s,d_full,d_asym,rel_err_d,rel_err_energy,est_d,est_energy\n");
  struct geo {
    std::string name;
    double par;
    std::shared_ptr<pressure_model<double>> pm;
  };
  std::vector<geo> geos = {{"hertz", 2, std::make_shared<hertz_pressure<double>>()}};
  for (double b : {0.3, 0.6, 0.9})
    geos.push_back({"flat-rounded", b, std::make_shared<flat_rounded_pressure<double>>(b)});
  for (double e : {1.5, 3.0, 6.0}) geos.push_back({"power-law", e, std::make_shared<power_law_pressure<double>>(e)});
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(0, 1);
  std::printf("%-14s %6s %8s %14s %14s %16s\n", "geometry", "param", "zones", "max d/est", "max E/est",
              "max d/est<1e-2");
  for (const auto &g : geos) {
    double rd = 0, re = 0, rsmall = 0;
    int zones = 0;
    for (int k = 0; k < n; ++k) {
      general_scene<double> sc;
      sc.q = std::pow(10.0, -6 * U(rng));
      const double r = U(rng);
      sc.s = r < 0.2 ? 0 : (r < 0.6 ? 2 * sc.q * (U(rng) * 2) : sc.q * std::pow(10.0, 2 * U(rng) - 1));
      if (U(rng) < 0.5) sc.s = -sc.s;
      try {
        const auto full = solve_general(*g.pm, sc);
        const edge_solution<double> as(*g.pm, sc);
        const auto est = asymptotic_estimate(*g.pm, sc);
        for (int z = 1; z <= 2; ++z) {
          const double df = z == 1 ? full.d1() : full.d2(), da = z == 1 ? as.d1() : as.d2();
          if (!(df > 0)) continue;
          const double Ef = full.energy(z), Ea = as.energy(z);
          const double ed = std::abs(da - df) / df, ee = std::abs(Ea - Ef) / Ef;
          std::fprintf(out, "%s,%g,%d,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e\n", g.name.c_str(), g.par, z, sc.q,
                       sc.s, df, da, ed, ee, est.slip_zone, est.energy);
          rd = std::max(rd, ed / est.slip_zone);
          re = std::max(re, ee / est.energy);
          if (est.value() < 1e-2) rsmall = std::max(rsmall, std::max(ed / est.slip_zone, ee / est.energy));
          ++zones;
        }
      } catch (const error &) {
        // asymptotic zones covering the contact: no comparison
      }
    }
    std::printf("%-14s %6g %8d %14.3g %14.3g %16.3g\n", g.name.c_str(), g.par, zones, rd, re, rsmall);
  }
  std::fclose(out);
  return 0;
}
