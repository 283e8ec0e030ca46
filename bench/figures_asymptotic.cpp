// The paper's Figures 5 and 6 (section 5.2), recomputed with the corrected
// asymptotic model (erratum E9) and the full Hertz solution:
//   fig5.csv: work done against friction W along one slip zone at b/a = 0.9,
//             shear only and bulk only, full solution and asymptotic model at
//             the same load, against z/d (z from the contact edge, d the
//             slip-zone length of each model);
//   fig6.csv: fractional error of the asymptotic energy (asymptotic - full)/full
//             against b/a, both loadings.
// a = p0 = f = E* = 1. usage: figures_asymptotic OUTDIR
#include <cstdio>
#include <string>

#include "halfslip/core/asymptotic.hpp"

namespace core = hs::core;

int main(int argc, char **argv) {
  const std::string dir = argc > 1 ? argv[1] : "docs/figures";
  FILE *f5 = std::fopen((dir + "/fig5.csv").c_str(), "w");
  FILE *f6 = std::fopen((dir + "/fig6.csv").c_str(), "w");
  if (!f5 || !f6) {
    std::fprintf(stderr, "cannot write to %s\n", dir.c_str());
    return 1;
  }
  std::fprintf(f5, "z_over_d,W_full_shear,W_asymptotic_shear,W_full_bulk,W_asymptotic_bulk\n");
  const double b = 0.9;
  const auto cs = core::compare_asymptotic<double>(+1, b), cb = core::compare_asymptotic<double>(-1, b);
  const auto ss = core::solve_hertz(cs.scene), sb = core::solve_hertz(cb.scene);
  const auto ms = core::hertz_edge(cs.scene, +1), mb = core::hertz_edge(cb.scene, +1);
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;  // z/d, z measured from the contact edge x = +a
    std::fprintf(f5, "%.4f,%.10e,%.10e,%.10e,%.10e\n", t, ss.work(1 - t * ss.d1()), ms.work(t * ms.d()),
                 sb.work(1 - t * sb.d1()), mb.work(t * mb.d()));
  }
  std::fprintf(f6, "b_over_a,fractional_error_shear,fractional_error_bulk\n");
  for (int i = 0; i <= 60; ++i) {
    const double bb = 0.4 + 0.59 * i / 60.0;
    std::fprintf(f6, "%.6f,%.10e,%.10e\n", bb, core::compare_asymptotic<double>(+1, bb).fractional_error(),
                 core::compare_asymptotic<double>(-1, bb).fractional_error());
  }
  std::fclose(f5);
  std::fclose(f6);
  std::printf("b/a = 0.9: fractional energy error %.4f (shear), %.4f (bulk)\n", cs.fractional_error(),
              cb.fractional_error());
  std::printf("wrote %s/fig5.csv and %s/fig6.csv\n", dir.c_str(), dir.c_str());
  return 0;
}
