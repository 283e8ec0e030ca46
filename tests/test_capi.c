/* C-only test of the public ABI: compiled as C99 -pedantic -Werror.
 * Exercises every entry point, the status codes for bad input, and checks
 * that outputs are untouched on error. Prints "N passed, M failed". */
#include <halfslip/halfslip.h>

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

static const double kPi = 3.14159265358979323846;

static int passed = 0, failed = 0;
#define CHECK(cond)                                                            \
  do {                                                                         \
    if (cond) {                                                                \
      ++passed;                                                                \
    } else {                                                                   \
      ++failed;                                                                \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
    }                                                                          \
  } while (0)

static hs_scene scene_qs(double q, double s) {
  hs_scene sc;
  hs_scene_default(&sc);
  sc.Q_over_fP = q;
  sc.sigma_over_fp0 = s;
  return sc;
}

static double hertz_p(double x, void *user) {
  const double a = *(const double *)user;
  return x > -a && x < a ? sqrt((a - x) * (a + x)) / a : 0.0;
}
static double negative_p(double x, void *user) {
  (void)user;
  return x < 0.2 ? sqrt(1 - x * x) : -1.0;
}

static int solve_status(hs_scene sc) {
  hs_solution *sol = NULL;
  int st = hs_solve(&sc, NULL, &sol);
  hs_solution_free(sol);
  return st;
}

int main(void) {
  int maj = -1, min = -1, pat = -1;
  CHECK(hs_version(&maj, &min, &pat) == HS_OK);
  CHECK(maj == HS_VERSION_MAJOR && min == HS_VERSION_MINOR && pat == HS_VERSION_PATCH);
  CHECK(hs_version(NULL, &min, &pat) == HS_ERR_NULL_POINTER);
  CHECK(strlen(hs_version_string()) > 0);

  /* every code has its own message; unknown codes still give text */
  {
    int c;
    for (c = 0; c <= HS_ERR_OVERFLOW; ++c) CHECK(hs_strerror(c) != NULL && strlen(hs_strerror(c)) > 0);
    CHECK(strcmp(hs_strerror(HS_ERR_GROSS_SLIDING), hs_strerror(HS_ERR_BAD_FRICTION)) != 0);
    CHECK(strstr(hs_strerror(12345), "unknown") != NULL);
    CHECK(strstr(hs_strerror(-1), "unknown") != NULL);
  }

  /* a same-sign solve */
  {
    hs_scene sc = scene_qs(0.5, 0.2);
    hs_solution *sol = NULL;
    hs_summary sm;
    double x[3], B[3], h[3], W[3], E[2];
    CHECK(hs_solve(&sc, NULL, &sol) == HS_OK);
    CHECK(sol != NULL);
    sm.struct_size = sizeof sm;
    CHECK(hs_solution_summary(sol, &sm) == HS_OK);
    CHECK(sm.regime == HS_REGIME_SAME_SIGN);
    CHECK(fabs(sm.b1 - (sqrt(0.5) + 0.05)) < 1e-15);
    CHECK(fabs(sm.b2 - (sqrt(0.5) - 0.05)) < 1e-15);
    CHECK(sm.slip_dir1 == 1 && sm.slip_dir2 == 1);
    x[0] = 0.0;   /* stick zone */
    x[1] = 0.99;  /* slip zone 1 */
    x[2] = -0.99; /* slip zone 2 */
    CHECK(hs_eval_Bx(sol, 3, x, B) == HS_OK);
    CHECK(hs_eval_slip(sol, 3, x, h) == HS_OK);
    CHECK(hs_eval_work(sol, 3, x, W) == HS_OK);
    CHECK(B[0] == 0 && h[0] == 0 && W[0] == 0);
    /* eq (21): B = 2 f p0/(a E*) sqrt((x-b1)(x+b2)) in zone 1 */
    CHECK(fabs(B[1] - 2 * sqrt((0.99 - sm.b1) * (0.99 + sm.b2))) < 1e-14);
    CHECK(B[2] < 0 && h[1] > 0 && h[2] > 0 && W[1] > 0);
    CHECK(hs_solution_energy(sol, E) == HS_OK);
    CHECK(E[0] > 0 && E[1] > E[0]);

    /* bad evaluation inputs: specific code, output untouched */
    {
      double xo[2], out[2];
      xo[0] = 0.5;
      xo[1] = 1.5;
      out[0] = out[1] = 42.0;
      CHECK(hs_eval_Bx(sol, 2, xo, out) == HS_ERR_POINT_OUTSIDE);
      CHECK(out[0] == 42.0 && out[1] == 42.0);
      xo[1] = NAN;
      CHECK(hs_eval_slip(sol, 2, xo, out) == HS_ERR_NOT_FINITE);
      CHECK(out[0] == 42.0);
      CHECK(hs_eval_work(sol, 2, NULL, out) == HS_ERR_NULL_POINTER);
      CHECK(hs_eval_work(sol, 2, xo, NULL) == HS_ERR_NULL_POINTER);
      CHECK(hs_eval_work(NULL, 2, xo, out) == HS_ERR_NULL_POINTER);
      CHECK(hs_eval_Bx(sol, 0, NULL, NULL) == HS_OK); /* zero points: no-op */
    }
    sm.struct_size = 3;
    CHECK(hs_solution_summary(sol, &sm) == HS_ERR_STRUCT_SIZE);
    /* a caller built against the 0.1 header (summary without p0, quadrature_order) */
    {
      hs_summary old;
      memset(&old, 0xab, sizeof old);
      old.struct_size = offsetof(hs_summary, p0);
      CHECK(hs_solution_summary(sol, &old) == HS_OK);
      CHECK(old.struct_size == offsetof(hs_summary, p0) && fabs(old.b1 - (sqrt(0.5) + 0.05)) < 1e-15);
      CHECK(old.quadrature_order == (int)0xabababab); /* beyond the old size: untouched */
    }
    CHECK(hs_solution_summary(NULL, &sm) == HS_ERR_NULL_POINTER);
    CHECK(hs_solution_energy(sol, NULL) == HS_ERR_NULL_POINTER);
    hs_solution_free(sol);
  }

  /* an opposite-sign solve */
  {
    hs_scene sc = scene_qs(0.3, 2.0);
    hs_solution *sol = NULL;
    hs_summary sm;
    CHECK(hs_solve(&sc, NULL, &sol) == HS_OK);
    sm.struct_size = sizeof sm;
    CHECK(hs_solution_summary(sol, &sm) == HS_OK);
    CHECK(sm.regime == HS_REGIME_OPPOSITE_SIGN);
    CHECK(sm.slip_dir1 == -1 && sm.slip_dir2 == 1);
    CHECK(sm.b1 > sm.b2);
    CHECK(sm.iterations >= 1);
    hs_solution_free(sol);
  }

  /* bad scenes */
  {
    hs_scene sc = scene_qs(0.5, 0.2);
    hs_solution *sol = (hs_solution *)0;
    CHECK(hs_solve(NULL, NULL, &sol) == HS_ERR_NULL_POINTER);
    CHECK(hs_solve(&sc, NULL, NULL) == HS_ERR_NULL_POINTER);
    CHECK(solve_status(scene_qs(1.0, 0.0)) == HS_ERR_GROSS_SLIDING);
    CHECK(solve_status(scene_qs(-1.0, 0.0)) == HS_ERR_GROSS_SLIDING);
    CHECK(solve_status(scene_qs(NAN, 0.0)) == HS_ERR_NOT_FINITE);
    CHECK(solve_status(scene_qs(0.1, INFINITY)) == HS_ERR_NOT_FINITE);
    sc = scene_qs(0.5, 0.2);
    sc.f = 0;
    CHECK(solve_status(sc) == HS_ERR_BAD_FRICTION);
    sc = scene_qs(0.5, 0.2);
    sc.f = -1;
    CHECK(solve_status(sc) == HS_ERR_BAD_FRICTION);
    sc = scene_qs(0.5, 0.2);
    sc.a = -1;
    CHECK(solve_status(sc) == HS_ERR_BAD_SIZE);
    sc = scene_qs(0.5, 0.2);
    sc.p0 = 0;
    CHECK(solve_status(sc) == HS_ERR_BAD_SIZE);
    sc = scene_qs(0.5, 0.2);
    sc.E_star = 0;
    CHECK(solve_status(sc) == HS_ERR_BAD_SIZE);
    sc = scene_qs(0.5, 0.2);
    sc.geometry = 99;
    CHECK(solve_status(sc) == HS_ERR_BAD_GEOMETRY);
    sc = scene_qs(0.5, 0.2);
    sc.struct_size = 1;
    CHECK(solve_status(sc) == HS_ERR_STRUCT_SIZE);
    {
      hs_options o;
      hs_options_default(&o);
      o.max_iterations = 0;
      sc = scene_qs(0.5, 0.2);
      sol = NULL;
      CHECK(hs_solve(&sc, &o, &sol) == HS_ERR_BAD_OPTION);
      CHECK(sol == NULL);
      hs_options_default(&o);
      o.rtol = -1;
      CHECK(hs_solve(&sc, &o, &sol) == HS_ERR_BAD_OPTION);
      o.struct_size = 0;
      CHECK(hs_solve(&sc, &o, &sol) == HS_ERR_STRUCT_SIZE);
    }
    CHECK(hs_scene_default(NULL) == HS_ERR_NULL_POINTER);
    CHECK(hs_options_default(NULL) == HS_ERR_NULL_POINTER);
    hs_solution_free(NULL);
  }

  /* dimensional input: a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a) */
  {
    hs_scene sc;
    const double P = 1000, R = 0.05, E = 1.15e11, f = 0.6;
    CHECK(hs_scene_from_hertz_loads(P, R, E, f, 300, 2e6, &sc) == HS_OK);
    CHECK(fabs(sc.a - sqrt(4 * P * R / (kPi * E))) < 1e-15 * sc.a);
    CHECK(fabs(sc.p0 - 2 * P / (kPi * sc.a)) < 1e-15 * sc.p0);
    CHECK(fabs(sc.Q_over_fP - 300 / (f * P)) < 1e-16);
    CHECK(hs_scene_from_hertz_loads(P, R, E, f, 700, 0, &sc) == HS_ERR_GROSS_SLIDING);
    CHECK(hs_scene_from_hertz_loads(-P, R, E, f, 0, 0, &sc) == HS_ERR_BAD_SIZE);
    CHECK(hs_scene_from_hertz_loads(P, R, E, 0, 0, 0, &sc) == HS_ERR_BAD_FRICTION);
    CHECK(hs_scene_from_hertz_loads(P, NAN, E, f, 0, 0, &sc) == HS_ERR_NOT_FINITE);
    CHECK(hs_scene_from_hertz_loads(P, R, E, f, 0, 0, NULL) == HS_ERR_NULL_POINTER);
  }

  /* general pressures through hs_solve_geometry */
  {
    hs_scene sc = scene_qs(0.3, 2.0);
    hs_geometry g;
    hs_solution *hz = NULL, *sol = NULL;
    hs_summary a, b;
    double xs[41], ps[41], unit = 1.0, x1[1] = {0.95}, B1[1], B2[1];
    int i;
    CHECK(hs_geometry_default(&g) == HS_OK && g.kind == HS_GEOMETRY_HERTZ);
    CHECK(hs_solve(&sc, NULL, &hz) == HS_OK);
    a.struct_size = sizeof a;
    b.struct_size = sizeof b;
    hs_solution_summary(hz, &a);
    CHECK(a.quadrature_order == 0);
    /* power law n = 2 and the flat punch with b_f = 0 are Hertz */
    g.kind = HS_GEOMETRY_POWER_LAW;
    g.exponent = 2.0;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_OK);
    CHECK(hs_solution_summary(sol, &b) == HS_OK);
    CHECK(b.regime == a.regime && fabs(b.b1 - a.b1) < 1e-13 && fabs(b.b2 - a.b2) < 1e-13 && b.quadrature_order > 0);
    CHECK(hs_eval_Bx(sol, 1, x1, B1) == HS_OK && hs_eval_Bx(hz, 1, x1, B2) == HS_OK && fabs(B1[0] - B2[0]) < 1e-10);
    hs_solution_free(sol);
    g.kind = HS_GEOMETRY_FLAT_ROUNDED;
    g.flat_over_a = 0.0;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_OK);
    hs_solution_summary(sol, &b);
    CHECK(fabs(b.b1 - a.b1) < 1e-13 && fabs(b.b2 - a.b2) < 1e-13);
    hs_solution_free(sol);
    /* a real flat punch: shear only gives b1 = b2 and the stick zone shrinks with Q */
    g.flat_over_a = 0.6;
    sc = scene_qs(0.5, 0.0);
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_OK);
    hs_solution_summary(sol, &b);
    CHECK(b.regime == HS_REGIME_SAME_SIGN && fabs(b.b1 - b.b2) < 1e-14 && b.b1 > 0.6 && b.b1 < 1);
    hs_solution_free(sol);
    /* callback and samples of the Hertz pressure */
    sc = scene_qs(0.3, 2.0);
    g.kind = HS_GEOMETRY_CALLBACK;
    g.pressure = hertz_p;
    g.user = &unit;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_OK);
    hs_solution_summary(sol, &b);
    CHECK(fabs(b.b1 - a.b1) < 1e-12 && fabs(b.b2 - a.b2) < 1e-12 && fabs(b.p0 - 1) < 1e-13);
    hs_solution_free(sol);
    for (i = 0; i < 41; ++i) {
      xs[i] = -cos(kPi * i / 40.0);
      ps[i] = hertz_p(xs[i], &unit);
    }
    xs[0] = -1;
    xs[40] = 1;
    g.kind = HS_GEOMETRY_SAMPLES;
    g.n_samples = 41;
    g.sample_x = xs;
    g.sample_p = ps;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_OK);
    hs_solution_summary(sol, &b);
    CHECK(fabs(b.b1 - a.b1) < 1e-10 && fabs(b.b2 - a.b2) < 1e-10);
    hs_solution_free(sol);
    /* bad geometries */
    g.sample_x = NULL;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_NULL_POINTER);
    g.sample_x = xs;
    ps[20] = -1;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    g.n_samples = 3;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    {
      /* hs_check_samples names the sample a broken rule is about (issue 13 item 5) */
      int verdict = -1;
      size_t at = 99;
      char why[128];
      CHECK(hs_check_samples(41, xs, ps, 1.0, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_ERR_BAD_GEOMETRY && at == 20 && strstr(why, "negative") != NULL);
      ps[20] = hertz_p(xs[20], &unit);
      CHECK(hs_check_samples(41, xs, ps, 1.0, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_OK && at == 41 && why[0] == '\0');
      /* a pressure vanishing linearly at x = -a: about the sample nearest that edge (index 1) */
      ps[1] = 1 + xs[1];
      ps[2] = 1 + xs[2];
      CHECK(hs_check_samples(41, xs, ps, 1.0, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_ERR_BAD_GEOMETRY && at == 1 && strstr(why, "edge x = -a") != NULL);
      CHECK(hs_check_samples(41, xs, ps, 1.0, &verdict, NULL, why, 8) == HS_OK && strlen(why) == 7);
      ps[1] = hertz_p(xs[1], &unit);
      ps[2] = hertz_p(xs[2], &unit);
      ps[7] = NAN;
      CHECK(hs_check_samples(41, xs, ps, 1.0, &verdict, &at, NULL, 0) == HS_OK);
      CHECK(verdict == HS_ERR_NOT_FINITE && at == 7);
      ps[7] = hertz_p(xs[7], &unit);
      CHECK(hs_check_samples(41, xs, ps, 0.5, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_ERR_BAD_GEOMETRY && at == 0 && strstr(why, "outside") != NULL);
      CHECK(hs_check_samples(41, xs, ps, -1.0, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_ERR_BAD_SIZE && at == 41);
      CHECK(hs_check_samples(5, xs, ps, 1.0, &verdict, &at, why, sizeof why) == HS_OK);
      CHECK(verdict == HS_ERR_BAD_GEOMETRY && at == 5);
      CHECK(hs_check_samples(41, xs, NULL, 1.0, &verdict, &at, why, sizeof why) == HS_ERR_NULL_POINTER);
      CHECK(hs_check_samples(41, xs, ps, 1.0, NULL, &at, why, sizeof why) == HS_ERR_NULL_POINTER);
      ps[20] = -1;
    }
    g.kind = HS_GEOMETRY_CALLBACK;
    g.pressure = negative_p;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    g.pressure = NULL;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_NULL_POINTER);
    g.kind = HS_GEOMETRY_FLAT_ROUNDED;
    g.flat_over_a = 1.0;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    g.flat_over_a = NAN;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_NOT_FINITE);
    g.kind = HS_GEOMETRY_POWER_LAW;
    g.exponent = 1.0;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    g.kind = 42;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_BAD_GEOMETRY);
    g.struct_size = 0;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_STRUCT_SIZE);
    CHECK(hs_solve_geometry(&sc, NULL, NULL, &sol) == HS_ERR_NULL_POINTER);
    sc.Q_over_fP = 1.0;
    hs_geometry_default(&g);
    g.kind = HS_GEOMETRY_POWER_LAW;
    g.exponent = 3;
    CHECK(hs_solve_geometry(&sc, &g, NULL, &sol) == HS_ERR_GROSS_SLIDING);
    CHECK(hs_geometry_default(NULL) == HS_ERR_NULL_POINTER);
    hs_solution_free(hz);
  }

  /* reference backend */
  {
    hs_ref_scene rs;
    hs_ref_solution *rsol = NULL;
    hs_ref_summary rsm;
    char buf[128], tiny[4];
    size_t need = 0;
    int cd = -1;
    CHECK(hs_ref_scene_default(&rs) == HS_OK);
    rs.Q_over_fP = "0.3";
    rs.sigma_over_fp0 = "2";
    CHECK(hs_ref_max_digits() >= 40); /* 380 in the default build; shorter ladders in sanitizer builds */
    CHECK(hs_ref_solve(&rs, 30, &rsol) == HS_OK);
    rsm.struct_size = sizeof rsm;
    CHECK(hs_ref_solution_summary(rsol, &rsm) == HS_OK);
    CHECK(rsm.regime == HS_REGIME_OPPOSITE_SIGN && rsm.digits == 30 && rsm.working_digits >= 40);
    CHECK(hs_ref_value(rsol, HS_REF_B1, buf, sizeof buf, &need, &cd) == HS_OK);
    CHECK(strncmp(buf, "7.49058362968990633002635765716", 31) == 0);
    CHECK(cd == 30 && need == strlen(buf) + 1);
    memcpy(tiny, "xyz", 4);
    CHECK(hs_ref_value(rsol, HS_REF_B1, tiny, sizeof tiny, &need, &cd) == HS_ERR_BUFFER_TOO_SMALL);
    CHECK(strcmp(tiny, "xyz") == 0 && need == strlen(buf) + 1);
    CHECK(hs_ref_value(rsol, 99, buf, sizeof buf, NULL, NULL) == HS_ERR_BAD_OPTION);
    CHECK(hs_ref_eval(rsol, HS_REF_EVAL_BX, "0.9", buf, sizeof buf, NULL, &cd) == HS_OK);
    CHECK(buf[0] == '-' && cd == 30);
    CHECK(hs_ref_eval(rsol, HS_REF_EVAL_BX, "1.5", buf, sizeof buf, NULL, &cd) == HS_ERR_POINT_OUTSIDE);
    CHECK(hs_ref_eval(rsol, HS_REF_EVAL_BX, "0.9q", buf, sizeof buf, NULL, &cd) == HS_ERR_BAD_NUMBER);
    CHECK(hs_ref_eval(rsol, HS_REF_EVAL_BX, NULL, buf, sizeof buf, NULL, &cd) == HS_ERR_NULL_POINTER);
    hs_ref_solution_free(rsol);
    rsol = NULL;
    /* one significant digit, correctly rounded (0.749... -> 7e-01) */
    CHECK(hs_ref_solve(&rs, 1, &rsol) == HS_OK);
    CHECK(hs_ref_value(rsol, HS_REF_B1, buf, sizeof buf, &need, &cd) == HS_OK);
    CHECK(strcmp(buf, "7e-01") == 0 && cd == 1);
    hs_ref_solution_free(rsol);
    rsol = NULL;
    CHECK(hs_ref_solve(&rs, 0, &rsol) == HS_ERR_BAD_OPTION && rsol == NULL);
    CHECK(hs_ref_solve(&rs, hs_ref_max_digits() + 1, &rsol) == HS_ERR_BAD_OPTION);
    rs.Q_over_fP = "abc";
    CHECK(hs_ref_solve(&rs, 30, &rsol) == HS_ERR_BAD_NUMBER);
    rs.Q_over_fP = "1";
    CHECK(hs_ref_solve(&rs, 30, &rsol) == HS_ERR_GROSS_SLIDING);
    rs.Q_over_fP = "0.3";
    rs.f = "-1";
    CHECK(hs_ref_solve(&rs, 30, &rsol) == HS_ERR_BAD_FRICTION);
    rs.f = NULL;
    rs.struct_size = 0;
    CHECK(hs_ref_solve(&rs, 30, &rsol) == HS_ERR_STRUCT_SIZE);
    CHECK(hs_ref_solve(NULL, 30, &rsol) == HS_ERR_NULL_POINTER);
    hs_ref_solution_free(NULL);
  }

  /* the model-name table (since 0.4): names and values both ways */
  {
    int m, k = -7;
    for (m = HS_MODEL_DEFAULT; m <= HS_MODEL_REFERENCE; ++m) {
      const char *name = hs_model_name(m);
      CHECK(name != NULL);
      if (name) CHECK(hs_model_from_name(name, &k) == HS_OK && k == m);
    }
    CHECK(strcmp(hs_model_name(HS_MODEL_CLOSED_FORM), "closed-form") == 0);
    CHECK(strcmp(hs_model_name(HS_MODEL_AUTO), "auto") == 0);
    CHECK(hs_model_name(-1) == NULL && hs_model_name(HS_MODEL_REFERENCE + 1) == NULL);
    k = -7;
    CHECK(hs_model_from_name("Closed-Form", &k) == HS_ERR_BAD_OPTION && k == -7);
    CHECK(hs_model_from_name("", &k) == HS_ERR_BAD_OPTION && k == -7);
    CHECK(hs_model_from_name(NULL, &k) == HS_ERR_NULL_POINTER && k == -7);
    CHECK(hs_model_from_name("auto", NULL) == HS_ERR_NULL_POINTER);
  }

  printf("capi: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
