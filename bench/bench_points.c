/* Point evaluations (B_x, slip) and zone energies on the general path (flat punch
 * b_f/a = 0.5), per point, through the C ABI. Run by scripts/bench.sh. */
#include <halfslip/halfslip.h>
#include <stdio.h>
#include <time.h>
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
int main(void) {
  double qs[2][2] = {{0.3, 0.0}, {0.5, 3.0}};
  for (int k = 0; k < 2; k++) {
    hs_scene sc;
    hs_scene_default(&sc);
    sc.Q_over_fP = qs[k][0];
    sc.sigma_over_fp0 = qs[k][1];
    hs_geometry g;
    hs_geometry_default(&g);
    g.kind = HS_GEOMETRY_FLAT_ROUNDED;
    g.flat_over_a = 0.5;
    hs_solution *s;
    if (hs_solve_geometry(&sc, &g, NULL, &s)) return 1;
    hs_summary su;
    su.struct_size = sizeof su;
    hs_solution_summary(s, &su);
    double x[20];
    for (int i = 0; i < 20; i++) {
      x[i] = (i < 10) ? su.b1 + su.d1 * (i + 0.5) / 10 : -su.b2 - su.d2 * (i - 9.5) / 10;
    }
    double out[20];
    double t0 = now();
    int N = 5;
    for (int r = 0; r < N; r++) hs_eval_Bx(s, 20, x, out);
    double tb = (now() - t0) / N / 20;
    t0 = now();
    for (int r = 0; r < N; r++) hs_eval_slip(s, 20, x, out);
    double ts = (now() - t0) / N / 20;
    t0 = now();
    double e[2];
    for (int r = 0; r < N; r++) hs_solution_energy(s, e);
    double te = (now() - t0) / N;
    printf("flat 0.5 q=%g s=%g regime %d: Bx %.1f us/pt, slip %.1f us/pt, energies %.1f us\n", qs[k][0], qs[k][1],
           su.regime, tb * 1e6, ts * 1e6, te * 1e6);
    hs_solution_free(s);
  }
}
