/* A C99 program built against the installed halfslip (CMake package or
 * pkg-config), linked either to the shared or to the static library. */
#include <halfslip/halfslip.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void) {
  hs_scene sc;
  hs_solution *sol = NULL;
  hs_summary sm;
  hs_ref_scene rs;
  hs_ref_solution *rsol = NULL;
  char b1[64];
  int certified = 0, st;

  hs_scene_default(&sc);
  sc.Q_over_fP = 0.5;
  sc.sigma_over_fp0 = 0.2;
  st = hs_solve(&sc, NULL, &sol);
  if (st != HS_OK) {
    fprintf(stderr, "hs_solve: %s\n", hs_strerror(st));
    return 1;
  }
  sm.struct_size = sizeof sm;
  hs_solution_summary(sol, &sm);
  hs_solution_free(sol);
  if (sm.regime != HS_REGIME_SAME_SIGN || fabs(sm.b1 - (sqrt(0.5) + 0.05)) > 1e-15) {
    fprintf(stderr, "wrong same-sign solution: b1 = %.17g\n", sm.b1);
    return 1;
  }

  /* the reference backend (MPFR) is inside the library too */
  hs_ref_scene_default(&rs);
  rs.Q_over_fP = "0.3";
  rs.sigma_over_fp0 = "2";
  st = hs_ref_solve(&rs, 30, &rsol);
  if (st == HS_OK) st = hs_ref_value(rsol, HS_REF_B1, b1, sizeof b1, NULL, &certified);
  hs_ref_solution_free(rsol);
  if (st != HS_OK || strncmp(b1, "7.490583629689906330026357657", 29) != 0 || certified != 30) {
    fprintf(stderr, "reference solve: status %d (%s), b1 = %s\n", st, hs_strerror(st), st ? "" : b1);
    return 1;
  }
  if (hs_solve(&sc, NULL, NULL) != HS_ERR_NULL_POINTER) return 1;
  printf("consumer c (halfslip %s): b1 = %.15f, reference b1 = %s: ok\n", hs_version_string(), sm.b1, b1);
  return 0;
}
