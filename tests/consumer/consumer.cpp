// A C++ program built against the installed halfslip with find_package.
#include <halfslip/halfslip.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

int main() {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = 0.3;
  sc.sigma_over_fp0 = 2.0;
  hs_solution *raw = nullptr;
  if (int st = hs_solve(&sc, nullptr, &raw)) {
    std::fprintf(stderr, "hs_solve: %s\n", hs_strerror(st));
    return 1;
  }
  std::unique_ptr<hs_solution, void (*)(hs_solution *)> sol(raw, hs_solution_free);
  hs_summary sm{};
  sm.struct_size = sizeof sm;
  if (hs_solution_summary(sol.get(), &sm) != HS_OK) return 1;
  if (sm.regime != HS_REGIME_OPPOSITE_SIGN || std::fabs(sm.b1 - 0.749058362968991) > 1e-14 || sm.slip_dir1 != -1) {
    std::fprintf(stderr, "wrong opposite-sign solution: b1 = %.17g\n", sm.b1);
    return 1;
  }
  std::vector<double> x{0.95, -0.95}, h(2, 0.0);
  if (hs_eval_slip(sol.get(), x.size(), x.data(), h.data()) != HS_OK || !(h[0] < 0 && h[1] > 0)) return 1;
  std::printf("consumer c++: b1 = %.15f, h(0.95) = %.6e: ok\n", sm.b1, h[0]);
  return 0;
}
