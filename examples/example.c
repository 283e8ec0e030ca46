/* halfslip from C: a steel cylinder (radius 50 mm) pressed on a steel
 * half-plane by 100 kN per metre of length, then a shear force of 18 kN/m
 * and a bulk tension of 20 MPa in the half-plane. SI units throughout: loads
 * per unit length (plane strain) in N/m, lengths in m, stresses in Pa.
 *
 *   cc example.c $(pkg-config --cflags --libs halfslip) -lm      (or CMake: halfslip::halfslip)
 */
#include <halfslip/halfslip.h>

#include <stdio.h>
#include <stdlib.h>

static void check(int status, const char *what) {
  if (status != HS_OK) {
    fprintf(stderr, "%s: %s\n", what, hs_strerror(status));
    exit(1);
  }
}

int main(void) {
  const double P = 1.0e5;         /* normal load, N/m */
  const double R = 0.05;          /* radius of the cylinder, m */
  const double E_star = 1.154e11; /* composite modulus of two steel bodies, E/(2(1 - nu^2)), Pa */
  const double f = 0.6;           /* coefficient of friction */
  const double Q = 1.8e4;         /* shear force, N/m */
  const double sigma = 2.0e7;     /* differential bulk tension, Pa */
  hs_scene scene;
  hs_solution *sol = NULL;
  hs_summary sm;
  double energy[2], x[3], h[3];
  int i;

  check(hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, &scene), "scene");
  check(hs_solve(&scene, NULL, &sol), "solve");
  sm.struct_size = sizeof sm;
  check(hs_solution_summary(sol, &sm), "summary");
  check(hs_solution_energy(sol, energy), "energy");
  printf("halfslip %s, C example\n", hs_version_string());
  printf("contact half-width a = %.7g mm, peak pressure p0 = %.7g MPa\n", sm.a * 1e3, sm.p0 * 1e-6);
  printf("stick zone: b1 = %.7g mm, b2 = %.7g mm\n", sm.b1 * 1e3, sm.b2 * 1e3);
  printf("slip directions %+d, %+d\n", sm.slip_dir1, sm.slip_dir2);
  printf("energy dissipated: E1 = %.7g J/m, E2 = %.7g J/m\n", energy[0], energy[1]);
  /* slip at the middle of each slip zone and at the edge x = a */
  x[0] = 0.5 * (sm.b1 + sm.a);
  x[1] = -0.5 * (sm.b2 + sm.a);
  x[2] = sm.a;
  check(hs_eval_slip(sol, 3, x, h), "slip");
  for (i = 0; i < 3; ++i) printf("  slip h(%.5g mm) = %.5g um\n", x[i] * 1e3, h[i] * 1e6);
  hs_solution_free(sol);
  return 0;
}
