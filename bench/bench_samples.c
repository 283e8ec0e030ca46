/* Sampled pressure (issue 13 item 4): n + 1 uniform samples of a Hertz pressure on
 * |x| <= a, Q/fP = 0.3, sigma/fp0 = 1, through the C ABI. Times the solve (zones),
 * the zone energies and the two surface-stress extremes (what `halfslip solve`
 * reports), and prints d1, d2 and the energies against the Hertz closed forms.
 * Usage: bench_samples [n ...] (default 1000 4000 16000 100000 1000000).
 * Run by scripts/bench.sh; figures in docs/benchmarks.md. */
#include <halfslip/halfslip.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
static double rel(double a, double b) { return b == 0 ? fabs(a) : fabs(a - b) / fabs(b); }
int main(int argc, char **argv) {
  static const size_t def[] = {1000, 4000, 16000, 100000, 1000000};
  const int cnt = argc > 1 ? argc - 1 : 5;
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = 0.3;
  sc.sigma_over_fp0 = 1.0;
  hs_solution *h;
  if (hs_solve(&sc, NULL, &h)) return 1;
  hs_summary hsu;
  hsu.struct_size = sizeof hsu;
  hs_solution_summary(h, &hsu);
  double he[2];
  if (hs_solution_energy(h, he)) return 1;
  printf("n,solve_s,energy_s,surface_s,total_s,d1,d2,energy1,energy2,max_rel_diff_vs_hertz\n");
  for (int k = 0; k < cnt; ++k) {
    const size_t n = argc > 1 ? (size_t)strtoull(argv[k + 1], NULL, 10) : def[k];
    double *x = malloc((n + 1) * sizeof *x), *p = malloc((n + 1) * sizeof *p);
    for (size_t i = 0; i <= n; ++i) {
      x[i] = i == n ? 1.0 : -1.0 + 2.0 * (double)i / (double)n;
      p[i] = (i == 0 || i == n) ? 0.0 : sqrt((1 - x[i]) * (1 + x[i]));
    }
    hs_geometry g;
    hs_geometry_default(&g);
    g.kind = HS_GEOMETRY_SAMPLES;
    g.n_samples = n + 1;
    g.sample_x = x;
    g.sample_p = p;
    hs_solution *s;
    double t0 = now();
    int rc = hs_solve_geometry(&sc, &g, NULL, &s);
    if (rc) {
      printf("%zu,fail %d\n", n, rc);
      return 1;
    }
    double t1 = now(), e[2];
    if (hs_solution_energy(s, e)) return 1;
    double t2 = now(), out[5];
    for (int b = 1; b <= 2; ++b)
      if (hs_surface_stress_extremes(s, b, 0.0, 0.0, out)) return 1;
    double t3 = now();
    hs_summary su;
    su.struct_size = sizeof su;
    hs_solution_summary(s, &su);
    double m = rel(su.d1, hsu.d1);
    if (rel(su.d2, hsu.d2) > m) m = rel(su.d2, hsu.d2);
    if (rel(e[0], he[0]) > m) m = rel(e[0], he[0]);
    if (rel(e[1], he[1]) > m) m = rel(e[1], he[1]);
    printf("%zu,%.3g,%.3g,%.3g,%.3g,%.17g,%.17g,%.17g,%.17g,%.2g\n", n, t1 - t0, t2 - t1, t3 - t2, t3 - t0, su.d1,
           su.d2, e[0], e[1], m);
    fflush(stdout);
    hs_solution_free(s);
    free(x);
    free(p);
  }
  hs_solution_free(h);
  return 0;
}
