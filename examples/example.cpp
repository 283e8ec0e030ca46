// halfslip from C++: the C ABI with RAII, on the scene of example.c (a steel
// cylinder, radius 50 mm, on a steel half-plane: P = 100 kN/m, Q = 18 kN/m,
// bulk tension 20 MPa; SI units, loads per unit length), plus the stick-zone
// edge b1 to 30 certified digits with the reference backend.
//
//   c++ -std=c++17 example.cpp $(pkg-config --cflags --libs halfslip)   (or CMake: halfslip::halfslip)
#include <halfslip/halfslip.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

void check(int status, const char *what) {
  if (status != HS_OK) throw std::runtime_error(std::string(what) + ": " + hs_strerror(status));
}

struct solution_deleter {
  void operator()(hs_solution *s) const { hs_solution_free(s); }
  void operator()(hs_ref_solution *s) const { hs_ref_solution_free(s); }
};
using solution = std::unique_ptr<hs_solution, solution_deleter>;
using ref_solution = std::unique_ptr<hs_ref_solution, solution_deleter>;

}  // namespace

int main() try {
  const double P = 1.0e5, R = 0.05, E_star = 1.154e11, f = 0.6, Q = 1.8e4, sigma = 2.0e7;  // SI
  hs_scene scene;
  check(hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, &scene), "scene");
  hs_solution *raw = nullptr;
  check(hs_solve(&scene, nullptr, &raw), "solve");
  const solution sol(raw);
  hs_summary sm{};
  sm.struct_size = sizeof sm;
  check(hs_solution_summary(sol.get(), &sm), "summary");
  double energy[2];
  check(hs_solution_energy(sol.get(), energy), "energy");
  std::printf("halfslip %s, C++ example\n", hs_version_string());
  std::printf("contact half-width a = %.7g mm, peak pressure p0 = %.7g MPa\n", sm.a * 1e3, sm.p0 * 1e-6);
  std::printf("stick zone: b1 = %.7g mm, b2 = %.7g mm\n", sm.b1 * 1e3, sm.b2 * 1e3);
  std::printf("energy dissipated: E1 = %.7g J/m, E2 = %.7g J/m\n", energy[0], energy[1]);

  // Work density along slip zone 1, from the stick boundary to the edge.
  std::vector<double> x(5), w(5);
  for (size_t i = 0; i < x.size(); ++i) x[i] = sm.b1 + (sm.a - sm.b1) * double(i) / double(x.size() - 1);
  check(hs_eval_work(sol.get(), x.size(), x.data(), w.data()), "work");
  for (size_t i = 0; i < x.size(); ++i) std::printf("  W(%.5g mm) = %.5g J/m^2\n", x[i] * 1e3, w[i]);

  // The same scene to 30 significant digits (inputs as exact decimal strings).
  hs_ref_scene rs;
  check(hs_ref_scene_default(&rs), "reference scene");
  rs.P = "1e5";
  rs.R = "0.05";
  rs.E_star = "1.154e11";
  rs.f = "0.6";
  rs.Q = "1.8e4";
  rs.sigma = "2e7";
  hs_ref_solution *rraw = nullptr;
  check(hs_ref_solve(&rs, 30, &rraw), "reference solve");
  const ref_solution ref(rraw);
  char buf[64];
  int certified = 0;
  check(hs_ref_value(ref.get(), HS_REF_B1, buf, sizeof buf, nullptr, &certified), "b1");
  std::printf("b1 = %s m (%d digits certified)\n", buf, certified);
  return 0;
} catch (const std::exception &e) {
  std::fprintf(stderr, "%s\n", e.what());
  return 1;
}
