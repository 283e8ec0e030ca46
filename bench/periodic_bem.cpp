// The independent BEM (reference/bem_history.hpp) on the path that `halfslip history --cycle
// Qm,Qa,Sm,Sa,phase_deg --cycles n` builds (core::add_cycles, ramp sigma first): (0, S0) and
// (Qm, S0), each where it moves the load; a straight-line cycle (Qa = 0, Sa = 0 or the phase a
// multiple of 180 degrees) through its turning points t = pi/2, 3 pi/2, 2 pi; otherwise 64 chords
// at t = 2 pi k / 64. Prints each cycle's energies per zone. Used by bench/periodic_survey.py.
//   periodic_bem Qm Qa Sm Sa phase_deg cycles N [hertz|flat]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "halfslip/core/pressure.hpp"
#include "halfslip/reference/bem_history.hpp"

int main(int argc, char **argv) {
  if (argc < 8) {
    std::fprintf(stderr, "usage: %s Qm Qa Sm Sa phase_deg cycles N [hertz|flat]\n", argv[0]);
    return 2;
  }
  const double qm = std::atof(argv[1]), qa = std::atof(argv[2]), sm = std::atof(argv[3]), sa = std::atof(argv[4]);
  const double phd = std::atof(argv[5]), ph = phd * M_PI / 180;
  const int ncyc = std::atoi(argv[6]), N = std::atoi(argv[7]);
  std::shared_ptr<const hs::core::pressure_model<double>> pm;
  if (argc > 8 && !std::strcmp(argv[8], "flat")) pm = std::make_shared<hs::core::flat_rounded_pressure<double>>(0.5);
  else pm = std::make_shared<hs::core::hertz_pressure<double>>();
  std::vector<std::pair<double, double>> w;
  double cq = 0, cs = 0;
  auto go = [&](double q, double s) {
    if (q != cq || s != cs) w.push_back({q, s}), cq = q, cs = s;
  };
  const double S0 = sm + sa * std::sin(ph);
  go(cq, S0);
  go(qm, S0);
  const bool line = qa == 0 || sa == 0 || std::fmod(std::fabs(phd), 180.0) == 0;
  std::vector<double> ths;
  if (line) ths = {M_PI / 2, 3 * M_PI / 2, 2 * M_PI};
  else
    for (int k = 1; k <= 64; ++k) ths.push_back(2 * M_PI * k / 64);
  for (int c = 0; c < ncyc; ++c)
    for (double t : ths) w.push_back({qm + qa * std::sin(t), sm + sa * std::sin(t + ph)});
  hs::reference::bem::options o;
  o.nodes = o.steps_per_unit = N;
  const auto r = hs::reference::bem::run([&](double x) { return pm->p(x); }, w, o);
  const size_t per = ths.size();
  for (int c = 0; c < ncyc; ++c) {
    double e1 = 0, e2 = 0;
    for (size_t k = 0; k < per; ++k) {
      const auto &v = r[w.size() - (ncyc - c) * per + k];
      e1 += v.energy1;
      e2 += v.energy2;
    }
    std::printf("N %d cycle %d: E1 %.9e E2 %.9e\n", N, c + 1, e1, e2);
  }
}
