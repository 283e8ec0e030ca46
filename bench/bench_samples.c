/* Sampled pressure (issue 13 item 4): n + 1 uniform samples on |x| <= a, Q/fP = 0.3,
 * sigma/fp0 = 1, through the C ABI. Times the solve (zones; the model's setup
 * included), the zone energies and the two surface-stress extremes (what
 * `halfslip solve` reports), and prints d1, d2 and the energies.
 *   --kind hertz   samples of a Hertz pressure (default): also the largest
 *                  relative difference from the Hertz closed forms
 *   --kind smooth  p = sqrt(1 - x^2)(1 + 0.3 x + 0.5 sin 3x)
 *   --kind noisy   Hertz samples with a relative perturbation of 1e-6 at every
 *                  sample (a finite-element export's discretisation noise):
 *                  the interpolant's curvature jumps are O(1e-6/h^2)
 *   --no-header    data lines only
 * Usage: bench_samples [--kind K] [--no-header] [n ...] (default 1000 10000 100000 1000000).
 * Run by scripts/bench_samples.sh (one process per n, with peak memory);
 * figures in docs/benchmarks.md. */
#include <halfslip/halfslip.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
static double rel(double a, double b) { return b == 0 ? fabs(a) : fabs(a - b) / fabs(b); }
/* a deterministic value in [-1, 1] from an index (no libc rand: reproducible everywhere) */
static double noise(size_t i) {
  unsigned long long z = (unsigned long long)i * 0x9E3779B97F4A7C15ULL + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return (double)(z >> 11) / 4503599627370496.0 - 1.0;
}
int main(int argc, char **argv) {
  static const size_t def[] = {1000, 10000, 100000, 1000000};
  const char *kind = "hertz";
  int header = 1, first = 1;
  size_t ns[64];
  int cnt = 0;
  for (int k = 1; k < argc; ++k) {
    if (!strcmp(argv[k], "--kind") && k + 1 < argc) kind = argv[++k];
    else if (!strcmp(argv[k], "--no-header")) header = 0;
    else if (cnt < 64) ns[cnt++] = (size_t)strtoull(argv[k], NULL, 10);
  }
  if (strcmp(kind, "hertz") && strcmp(kind, "smooth") && strcmp(kind, "noisy")) {
    fprintf(stderr, "bench_samples: --kind hertz, smooth or noisy\n");
    return 2;
  }
  if (cnt == 0)
    for (cnt = 0; cnt < 4; ++cnt) ns[cnt] = def[cnt];
  (void)first;
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
  if (header) printf("kind,n,solve_s,energy_s,surface_s,total_s,d1,d2,energy1,energy2,max_rel_diff_vs_hertz\n");
  for (int k = 0; k < cnt; ++k) {
    const size_t n = ns[k];
    double *x = malloc((n + 1) * sizeof *x), *p = malloc((n + 1) * sizeof *p);
    for (size_t i = 0; i <= n; ++i) {
      x[i] = i == n ? 1.0 : -1.0 + 2.0 * (double)i / (double)n;
      const double s = (i == 0 || i == n) ? 0.0 : sqrt((1 - x[i]) * (1 + x[i]));
      if (!strcmp(kind, "smooth")) p[i] = s * (1 + 0.3 * x[i] + 0.5 * sin(3 * x[i]));
      else if (!strcmp(kind, "noisy")) p[i] = s * (1 + 1e-6 * noise(i));
      else p[i] = s;
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
      printf("%s,%zu,fail %d\n", kind, n, rc);
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
    printf("%s,%zu,%.3g,%.3g,%.3g,%.3g,%.17g,%.17g,%.17g,%.17g,", kind, n, t1 - t0, t2 - t1, t3 - t2, t3 - t0, su.d1,
           su.d2, e[0], e[1]);
    if (!strcmp(kind, "hertz")) {
      double m = rel(su.d1, hsu.d1);
      if (rel(su.d2, hsu.d2) > m) m = rel(su.d2, hsu.d2);
      if (rel(e[0], he[0]) > m) m = rel(e[0], he[0]);
      if (rel(e[1], he[1]) > m) m = rel(e[1], he[1]);
      printf("%.2g\n", m);
    } else {
      printf("\n");
    }
    fflush(stdout);
    hs_solution_free(s);
    free(x);
    free(p);
  }
  hs_solution_free(h);
  return 0;
}
