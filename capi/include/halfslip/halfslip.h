/* The layout of this header (one #define a line, aligned) is parsed by
   tests/check_status_codes.sh and the Fortran and Python constant checks. */
/* clang-format off */
/*
 * halfslip: half-plane partial-slip contact under constant normal load,
 * shear force Q and differential bulk tension sigma.
 *
 * Public C ABI (C99). Every function returns an int status: HS_OK (0) or an
 * HS_ERR_* code; hs_strerror() gives the message. On error, outputs are left
 * untouched. No function aborts, prints, or lets a C++ exception escape.
 *
 * Sign conventions (signs of Q and sigma, which edge is b1, slip direction)
 * are defined once in docs/conventions.md. In short: the contact is |x| < a,
 * the stick zone is (-b2, b1), slip zone 1 is (b1, a), slip zone 2 is
 * (-a, -b2); the fully stuck traction is q_st(x) = (Q/pi - sigma x/4)/sqrt(a^2-x^2),
 * so that sigma > 0 moves the stick zone towards x = +a.
 *
 * Thread safety: distinct handles may be used from any threads; a solution
 * handle is immutable after hs_solve and may be read (evaluated) from several
 * threads at once. The only shared state is an internal, mutex-protected
 * cache of quadrature rules (general pressures); the MPFR precision is part
 * of each call, never global. A pressure callback (HS_GEOMETRY_CALLBACK) must
 * itself be thread-safe if its solution is evaluated from several threads.
 *
 * Structs carry a struct_size field and grow only at the end; functions that
 * fill a struct accept the sizes of earlier versions (documented per struct).
 */
#ifndef HALFSLIP_H
#define HALFSLIP_H

#include <stddef.h>

#if defined(HS_STATIC)
#  define HS_EXPORT
#elif defined(_WIN32)
#  if defined(HS_BUILDING_DLL)
#    define HS_EXPORT __declspec(dllexport)
#  else
#    define HS_EXPORT __declspec(dllimport)
#  endif
#elif defined(__GNUC__)
#  define HS_EXPORT __attribute__((visibility("default")))
#else
#  define HS_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- version ------------------------------------------------------------ */
#define HS_VERSION_MAJOR 0
#define HS_VERSION_MINOR 4
#define HS_VERSION_PATCH 0

/* Version of the library actually loaded (may differ from the header's). */
HS_EXPORT int hs_version(int *major, int *minor, int *patch);
HS_EXPORT const char *hs_version_string(void);

/* ---- status codes (values are part of the ABI; never renumbered) -------- */
#define HS_OK                     0
#define HS_ERR_NULL_POINTER       1  /* a required pointer argument is NULL */
#define HS_ERR_STRUCT_SIZE        2  /* struct_size field not set or unknown */
#define HS_ERR_NOT_FINITE         3  /* an input is NaN or infinite */
#define HS_ERR_BAD_SIZE           4  /* a, p0, E*, P or R not > 0 */
#define HS_ERR_BAD_FRICTION       5  /* friction coefficient f not > 0 */
#define HS_ERR_GROSS_SLIDING      6  /* |Q| >= fP: no stick zone, the contact slides */
#define HS_ERR_BAD_GEOMETRY       7  /* unknown geometry or invalid geometry parameter */
#define HS_ERR_POINT_OUTSIDE      8  /* an evaluation point lies outside |x| <= a */
#define HS_ERR_BUFFER_TOO_SMALL   9  /* an output buffer is too short */
#define HS_ERR_NO_CONVERGENCE    10  /* an iteration failed to converge */
#define HS_ERR_BAD_OPTION        11  /* an option value is out of range */
#define HS_ERR_OUT_OF_MEMORY     12  /* allocation failed */
#define HS_ERR_INTERNAL          13  /* unexpected internal error (please report) */
#define HS_ERR_OVERFLOW          14  /* a result is not representable (overflow) */
#define HS_ERR_BAD_NUMBER        15  /* a decimal string could not be parsed */
#define HS_ERR_TOLERANCE         16  /* no model meets the requested rtol in double precision */
#define HS_ERR_NOT_APPLICABLE    17  /* the requested model does not apply to this scene */

/* Message for a status code; never NULL. Unknown codes give a generic text. */
HS_EXPORT const char *hs_strerror(int status);

/* ---- geometry ----------------------------------------------------------- */
#define HS_GEOMETRY_HERTZ        1  /* cylinder on flat: p(x) = p0 sqrt(1 - x^2/a^2) (closed forms) */
#define HS_GEOMETRY_FLAT_ROUNDED 2  /* flat punch with rounded corners (Ciavarella, Hills & Monno 1998) */
#define HS_GEOMETRY_POWER_LAW    3  /* symmetric profile g(x) = A |x|^n, n > 1 */
#define HS_GEOMETRY_SAMPLES      4  /* user pressure samples (x_i, p_i), p ~ sqrt(distance) at both edges */
#define HS_GEOMETRY_CALLBACK     5  /* user pressure function p(x, user) */

/* ---- regimes -------------------------------------------------------------- */
#define HS_REGIME_STUCK         0  /* Q = sigma = 0: no slip */
#define HS_REGIME_SAME_SIGN     1  /* slip zones slip in the same direction */
#define HS_REGIME_OPPOSITE_SIGN 2  /* slip zones slip in opposite directions */
/* After 0.4 (issue 13): a slip zone is at or below the model's zone resolution
   (hs_summary.zone_resolution): it may be empty or slip either way, so the model
   cannot tell the regimes apart (the scene is at their boundary to within its
   accuracy); such a zone's slip direction is reported as 0. (Both zones of
   length exactly 0, e.g. loads that underflow: STUCK.) */
#define HS_REGIME_BOUNDARY      3

/* ---- scene -----------------------------------------------------------------
 * Dimensionless load ratios are the primary inputs, so that ratios close to
 * the limits (1 - Q/fP down to 1e-15) are not spoiled by rounding.
 * Units are any consistent set (forces per unit length in plane strain).
 * Fill with hs_scene_default() and then set fields, or use
 * hs_scene_from_hertz_loads(). */
typedef struct hs_scene {
  size_t struct_size;     /* = sizeof(hs_scene), set by hs_scene_default */
  int geometry;           /* HS_GEOMETRY_HERTZ */
  double a;               /* contact half-width, > 0 */
  double p0;              /* reference pressure 2P/(pi a) (Hertz peak pressure), > 0 */
  double f;               /* coefficient of friction, > 0 */
  double E_star;          /* composite plane-strain modulus: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 */
  double Q_over_fP;       /* shear force ratio Q/(fP), |.| < 1, P = pi a p0 / 2 */
  double sigma_over_fp0;  /* differential bulk tension ratio sigma/(f p0), any real */
} hs_scene;

/* Defaults: Hertz, a = 1, p0 = 1, f = 1, E* = 1, Q/fP = 0.5, sigma/fp0 = 0.5. */
HS_EXPORT int hs_scene_default(hs_scene *scene);

/* Dimensional Hertz input: normal load P (per unit length), radius of relative
 * curvature R, composite modulus E*, friction f, shear force Q, bulk tension
 * sigma. Computes a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a) and the ratios. */
HS_EXPORT int hs_scene_from_hertz_loads(double P, double R, double E_star, double f,
                                        double Q, double sigma, hs_scene *scene);

/* Dimensional power-law input (since 0.3), profile g(x) = A |x|^n (n > 1; the
 * gap between the bodies before loading): a from
 *   P = (E_star / 2) n A a^n sqrt(pi) Gamma((n+1)/2) / Gamma(n/2 + 1)
 * (n = 2, A = 1/(2R) is Hertz), p0 = 2P/(pi a) and the ratios. Use with an
 * hs_geometry of kind HS_GEOMETRY_POWER_LAW and exponent n. */
HS_EXPORT int hs_scene_from_power_law_loads(double P, double A, double n, double E_star, double f,
                                            double Q, double sigma, hs_scene *scene);

/* Dimensional flat punch with rounded corners (since 0.3): flat half-width
 * b_f >= 0, corner radius R; a from a^2 (pi - 2 phi0 - sin 2 phi0) = 4 R P / E_star
 * with b_f = a sin(phi0). Also writes b_f/a to *flat_over_a (for hs_geometry). */
HS_EXPORT int hs_scene_from_flat_rounded_loads(double P, double R, double flat_width, double E_star, double f,
                                               double Q, double sigma, hs_scene *scene, double *flat_over_a);

/* ---- options ---------------------------------------------------------------- */
/* Models (docs/models.md). The error of a solution is the largest relative
 * error of the slip-zone lengths d1, d2 and the zone energies (resolved zones:
 * longer than the model's hs_summary.zone_resolution); every model reports an
 * estimate of it (hs_summary.error_estimate). */
#define HS_MODEL_DEFAULT     0  /* closed forms (Hertz) or quadrature at rtol (other geometries) */
#define HS_MODEL_AUTO        1  /* the cheapest model whose error estimate is <= rtol, tried in
                                   the order asymptotic, closed form / quadrature, reference */
#define HS_MODEL_ASYMPTOTIC  2  /* single-edge asymptotic model (paper section 5), any geometry */
#define HS_MODEL_CLOSED_FORM 3  /* Hertz closed forms (Hertz only) */
#define HS_MODEL_QUADRATURE  4  /* numerical Cauchy-kernel inversion, any geometry (Hertz too) */
#define HS_MODEL_REFERENCE   5  /* MPFR reference backend, certified and rounded to double
                                   (Hertz, flat-rounded, power law) */

/* Since 0.4: the one table of model names, as the command line and the
   bindings spell them: "default", "auto", "asymptotic", "closed-form",
   "quadrature", "reference". hs_model_name gives NULL for a value that is no
   HS_MODEL_*; hs_model_from_name (exact match) gives HS_OK,
   HS_ERR_NULL_POINTER or HS_ERR_BAD_OPTION (unknown name, *model untouched). */
HS_EXPORT const char *hs_model_name(int model);
HS_EXPORT int hs_model_from_name(const char *name, int *model);

typedef struct hs_options {
  size_t struct_size;   /* = sizeof(hs_options), set by hs_options_default */
  int max_iterations;   /* Newton iteration cap, >= 1 (default 100) */
  double rtol;          /* HS_MODEL_DEFAULT / QUADRATURE: tolerance asked of the quadrature:
                             0 (default) = full double precision; else in [1e-15, 1e-2];
                           HS_MODEL_AUTO: the error the chosen model must meet, in
                             [2^-53, 0.5], or 0 = as accurate as double allows */
  /* since 0.3 (a caller may pass struct_size = offsetof(hs_options, model): HS_MODEL_DEFAULT) */
  int model;            /* HS_MODEL_* (default HS_MODEL_DEFAULT) */
} hs_options;

HS_EXPORT int hs_options_default(hs_options *opts);

/* ---- solving ------------------------------------------------------------------ */
typedef struct hs_solution hs_solution;  /* opaque, immutable once made */

/* Solve a scene. opts may be NULL (defaults). On success *out is a new handle
 * to release with hs_solution_free. |Q|/fP >= 1 gives HS_ERR_GROSS_SLIDING. */
HS_EXPORT int hs_solve(const hs_scene *scene, const hs_options *opts, hs_solution **out);
HS_EXPORT void hs_solution_free(hs_solution *sol);  /* NULL is a no-op */

/* Summary of a solution (all lengths dimensional, in the units of a). */
typedef struct hs_summary {
  size_t struct_size;   /* caller sets = sizeof(hs_summary) */
  int regime;           /* HS_REGIME_* */
  int slip_dir1;        /* slip direction in zone 1 (b1, a): +1, -1, or 0 if empty */
  int slip_dir2;        /* slip direction in zone 2 (-a, -b2) */
  int iterations;       /* Newton iterations used (0 for closed forms) */
  double a;
  double b1;            /* stick zone is (-b2, b1) */
  double b2;
  double d1;            /* a - b1, to full relative accuracy */
  double d2;            /* a - b2 */
  /* since 0.2: (a caller may pass struct_size = offsetof(hs_summary, p0)) */
  double p0;            /* reference pressure 2P/(pi a) actually used */
  int quadrature_order; /* Gauss-Legendre order per panel (0: closed forms, or stuck) */
  /* since 0.3 (struct_size = offsetof(hs_summary, model) is accepted too) */
  int model;            /* HS_MODEL_* actually used (never DEFAULT or AUTO) */
  double error_estimate;/* estimated largest relative error of d1, d2, E1, E2 (resolved zones) */
  /* after 0.4, issue 13 (struct_size = offsetof(hs_summary, zone_resolution) is accepted too) */
  double zone_resolution;/* the model's bound on the absolute error of d1 and d2, in the units
                            of a; a zone with d <= zone_resolution is unresolved: slip direction
                            0, left out of error_estimate, regime BOUNDARY (STUCK if d1 = d2 = 0) */
} hs_summary;

HS_EXPORT int hs_solution_summary(const hs_solution *sol, hs_summary *out);

/* ---- any half-plane pressure --------------------------------------------------
 * The pressure of a non-Hertz geometry is described by an hs_geometry and
 * solved by hs_solve_geometry with numerical Cauchy-kernel inversion
 * (quadrature matched to the end behaviour of each slip zone, order chosen
 * from opts->rtol and reported in hs_summary.quadrature_order). The scene's
 * a, f, E*, Q/fP and sigma/(f p0) are used as for Hertz, with
 * p0 = 2P/(pi a) the reference pressure; for HS_GEOMETRY_SAMPLES and
 * HS_GEOMETRY_CALLBACK the pressure is given in absolute units, so P and p0
 * come from it and the scene's p0 is ignored. scene->geometry is ignored:
 * geometry->kind decides. HS_GEOMETRY_HERTZ here uses the closed forms. */
typedef struct hs_geometry {
  size_t struct_size;        /* = sizeof(hs_geometry), set by hs_geometry_default */
  int kind;                  /* HS_GEOMETRY_* */
  double flat_over_a;        /* FLAT_ROUNDED: flat half-width b_f over a, in [0, 1) */
  double exponent;           /* POWER_LAW: n > 1 (n = 2 is Hertz) */
  size_t n_samples;          /* SAMPLES: number of samples (>= 6), x increasing in [-a, a] */
  const double *sample_x;    /* SAMPLES: abscissae (copied; need not outlive the call) */
  const double *sample_p;    /* SAMPLES: pressures >= 0, vanishing like sqrt at both edges */
  double (*pressure)(double x, void *user);  /* CALLBACK: p(x) on (-a, a); must stay valid, and */
  void *user;                                /* thread-safe, while the solution is used */
} hs_geometry;

/* Defaults: Hertz, flat_over_a = 0.5, exponent = 2, no samples, no callback. */
HS_EXPORT int hs_geometry_default(hs_geometry *geometry);

HS_EXPORT int hs_solve_geometry(const hs_scene *scene, const hs_geometry *geometry, const hs_options *opts,
                                hs_solution **out);

/* Check n pressure samples (x[i], p[i]) on a contact of half-width a against the
 * rules of HS_GEOMETRY_SAMPLES, without solving, to name the sample a rule is
 * about (added after 0.4.0). *verdict receives the status hs_solve_geometry
 * gives for them: HS_OK, or the rule broken (HS_ERR_BAD_GEOMETRY,
 * HS_ERR_NOT_FINITE, HS_ERR_BAD_SIZE). *index (if not NULL) receives the index
 * of the sample the rule is about, n for a rule about the samples as a whole
 * (and for HS_OK). reason[size] (if not NULL and size > 0) receives the rule
 * as a NUL-terminated text, cut to fit ("" for HS_OK). Returns HS_OK, or
 * HS_ERR_NULL_POINTER when x, p or verdict is NULL. */
HS_EXPORT int hs_check_samples(size_t n, const double *x, const double *p, double a, int *verdict, size_t *index,
                               char *reason, size_t size);

/* Energy dissipated against friction in each slip zone for monotonic loading
 * (per unit length out of plane): E_i = integral over zone i of f p |h| dx.
 * energy[0] is zone 1, energy[1] zone 2. */
HS_EXPORT int hs_solution_energy(const hs_solution *sol, double energy[2]);

/* Point evaluations at n points x[0..n-1] (|x| <= a), written to out[0..n-1].
 * Points in the stick zone give 0.
 *   Bx: dislocation density (slip-displacement gradient) B_x = dh/dx
 *   slip: relative slip h(x), zero at the stick boundaries
 *   work: friction work density W(x) = f p(x) |h(x)| for monotonic loading */
HS_EXPORT int hs_eval_Bx(const hs_solution *sol, size_t n, const double *x, double *out);
HS_EXPORT int hs_eval_slip(const hs_solution *sol, size_t n, const double *x, double *out);
HS_EXPORT int hs_eval_work(const hs_solution *sol, size_t n, const double *x, double *out);

/* Contact pressure p(x) of the scene's geometry at n points. */
HS_EXPORT int hs_eval_pressure(const hs_solution *sol, size_t n, const double *x, double *out);

/* Shear traction q(x) at n points (|x| <= a): the traction body 2 exerts on
 * body 1, positive in +x (docs/conventions.md); its integral is Q. In the slip
 * zones q = dir_i f p(x), in the stick zone the solution of the no-slip
 * condition bounded at both stick boundaries (docs/fields.md). */
HS_EXPORT int hs_eval_traction(const hs_solution *sol, size_t n, const double *x, double *out);

/* ---- stresses in each body (issue 15, docs/fields.md) -----------------------------
 * Body 1 (specimen) occupies y > 0, body 2 (pad) y < 0. bulk2 is the bulk stress
 * sigma_xx the pad carries; the specimen carries sigma + bulk2 (pass 0 for the
 * usual fretting-fatigue test: the pad carries none).
 *   surface_stress: sigma_xx(x, 0) of the body at any n points x (on and off the contact)
 *   stress: (sigma_xx, sigma_yy, sigma_xy) at (x[i], y[i]) written to out[3i..3i+2]
 *           (y[i] >= 0 for body 1, <= 0 for body 2)
 *   surface_stress_extremes: out = {max, x_max, min, x_min, bulk} of sigma_xx(x, 0) over
 *           |x| <= half_range (<= 0: 3a) */
HS_EXPORT int hs_eval_surface_stress(const hs_solution *sol, int body, double bulk2, size_t n, const double *x,
                                     double *out);
HS_EXPORT int hs_eval_stress(const hs_solution *sol, int body, double bulk2, size_t n, const double *x,
                             const double *y, double *out);
HS_EXPORT int hs_surface_stress_extremes(const hs_solution *sol, int body, double bulk2, double half_range,
                                         double out[5]);

/* A scalar of the stress at (x[i], y[i]) (body and bulk2 as above) written to out[i]:
 * quantity HS_STRESS_*; nu (Poisson's ratio, in [-1, 0.5]) is used by von Mises only,
 * with sigma_zz = nu (sigma_xx + sigma_yy) (plane strain). Added after 0.4.0. */
#define HS_STRESS_XX            1  /* sigma_xx */
#define HS_STRESS_YY            2  /* sigma_yy */
#define HS_STRESS_XY            3  /* sigma_xy */
#define HS_STRESS_VON_MISES     4  /* plane-strain von Mises stress */
#define HS_STRESS_MAX_PRINCIPAL 5  /* larger in-plane principal stress */
#define HS_STRESS_MIN_PRINCIPAL 6  /* smaller in-plane principal stress */
#define HS_STRESS_MAX_SHEAR     7  /* in-plane maximum shear sqrt(((sxx - syy)/2)^2 + sxy^2) */
HS_EXPORT int hs_eval_stress_scalar(const hs_solution *sol, int body, double bulk2, int quantity, double nu,
                                    size_t n, const double *x, const double *y, double *out);

/* ---- asymptotic single-edge model (paper section 5) ------------------------------
 * Hertz, a = p0 = f = E* = 1. For the load that gives a slip zone b/a under
 * pure shear (HS_LOADING_SHEAR) or pure bulk tension (HS_LOADING_BULK), the
 * energy dissipated in one slip zone by the full solution and by the
 * asymptotic edge model at the same load (docs/asymptotic.md). */
#define HS_LOADING_SHEAR 1
#define HS_LOADING_BULK  2

typedef struct hs_asymptotic_comparison {
  size_t struct_size;       /* caller sets = sizeof(hs_asymptotic_comparison) */
  double Q_over_fP;         /* the load */
  double sigma_over_fp0;
  double d_full;            /* slip zone length of the full solution (= 1 - b/a) */
  double d_asymptotic;      /* slip zone length of the edge model, 2 K_T/(f K_N) */
  double energy_full;       /* energy dissipated in the zone, units f^2 p0^2 a^2 / E* */
  double energy_asymptotic;
  double fractional_error;  /* (asymptotic - full) / full */
} hs_asymptotic_comparison;

HS_EXPORT int hs_asymptotic_error(int loading, double b_over_a, hs_asymptotic_comparison *out);

/* ---- arbitrary-precision reference backend ---------------------------------
 * The same algorithms on MPFR, for benchmark tables to 30-390 digits. Inputs
 * are decimal strings (exact decimals stay exact); outputs are decimal
 * strings in scientific notation with the requested number of significant
 * digits, each with the number of leading digits that are certified: the
 * solve is repeated at a wider precision and a digit is certified only if the
 * printed value is the wider result correctly rounded to that many digits.
 * Each call chooses its own precision; no global MPFR state is touched. */
typedef struct hs_ref_scene {
  size_t struct_size;      /* = sizeof(hs_ref_scene), set by hs_ref_scene_default */
  int geometry;            /* HS_GEOMETRY_HERTZ (default), _FLAT_ROUNDED or _POWER_LAW */
  /* dimensionless input (defaults "1", "1", "1", "1", "0.5", "0.5") */
  const char *a, *p0, *f, *E_star, *Q_over_fP, *sigma_over_fp0;
  /* dimensional Hertz input, used instead of a, p0 and the ratios when P is
   * not NULL: then R, Q and sigma are required too (and E_star, f are used).
   * Hertz only: with another geometry, HS_ERR_BAD_GEOMETRY. */
  const char *P, *R, *Q, *sigma;
  /* since 0.3: the parameter of the geometry (NULL: the default; the other
   * one is ignored). A caller built against 0.2 may pass
   * struct_size = offsetof(hs_ref_scene, flat_over_a): it is served as
   * before, Hertz only (another geometry gives HS_ERR_BAD_GEOMETRY). */
  const char *flat_over_a; /* HS_GEOMETRY_FLAT_ROUNDED: b_f/a in [0, 1) (default "0.5") */
  const char *exponent;    /* HS_GEOMETRY_POWER_LAW: n with 1 < n < 1000 (default "2") */
} hs_ref_scene;

HS_EXPORT int hs_ref_scene_default(hs_ref_scene *scene);
/* Largest number of digits hs_ref_solve accepts (Hertz). */
HS_EXPORT int hs_ref_max_digits(void);
/* Largest number of digits hs_ref_solve accepts for a geometry: as
 * hs_ref_max_digits() for HS_GEOMETRY_HERTZ; lower for HS_GEOMETRY_FLAT_ROUNDED
 * and HS_GEOMETRY_POWER_LAW (170 with the default precision ladder), whose
 * numerical solve costs about D^3 at D digits (docs/reference.md); 0 for a
 * geometry the reference backend does not solve. A request above it gives
 * HS_ERR_BAD_OPTION. */
HS_EXPORT int hs_ref_max_digits_geometry(int geometry);

typedef struct hs_ref_solution hs_ref_solution;  /* opaque, immutable once made */

/* Solve to `digits` significant digits (1 .. hs_ref_max_digits_geometry(scene->geometry)). */
HS_EXPORT int hs_ref_solve(const hs_ref_scene *scene, int digits, hs_ref_solution **out);
HS_EXPORT void hs_ref_solution_free(hs_ref_solution *sol);

typedef struct hs_ref_summary {
  size_t struct_size;   /* caller sets = sizeof(hs_ref_summary) */
  int regime, slip_dir1, slip_dir2, iterations;
  int digits;           /* requested significant digits */
  int working_digits;   /* decimal digits of the working precision */
  int check_digits;     /* decimal digits of the certifying run */
} hs_ref_summary;
HS_EXPORT int hs_ref_solution_summary(const hs_ref_solution *sol, hs_ref_summary *out);

#define HS_REF_B1      1
#define HS_REF_B2      2
#define HS_REF_D1      3
#define HS_REF_D2      4
#define HS_REF_ENERGY1 5
#define HS_REF_ENERGY2 6
#define HS_REF_A       7
#define HS_REF_P0      8

/* Write a quantity as a NUL-terminated decimal string into buf[size].
 * *needed (if not NULL) receives the size required, NUL included; if size is
 * too small, HS_ERR_BUFFER_TOO_SMALL and buf is untouched. digits + 16 bytes
 * always suffice. *certified (if not NULL) receives the certified digits. */
HS_EXPORT int hs_ref_value(const hs_ref_solution *sol, int quantity, char *buf, size_t size, size_t *needed,
                           int *certified);

/* ---- certified load histories along one ray (issue 14, added after 0.4.0) ----
 * A load path whose vertices all lie on one ray through the origin (unloading,
 * reloading, proportional cycles of any amplitudes), with no slip zone receding
 * on the ramp to the farthest vertex: each state is a sum of monotonic
 * solutions (Jager's memory rule; docs/history.md), each certified by the
 * reference backend. Vertices are decimal strings, as hs_ref_scene's ratios;
 * the scene gives the contact (geometry, a, p0, f, E*; dimensional input is not
 * taken: HS_ERR_BAD_OPTION) and its Q/fP and sigma/fp0 are ignored. A vertex
 * off the ray, or a ramp on which a zone recedes, gives HS_ERR_NOT_APPLICABLE
 * (march the path in double, hs_history_*); |Q/fP| >= 1 HS_ERR_GROSS_SLIDING.
 * On error the history keeps the vertices added before. */
typedef struct hs_ref_history hs_ref_history;
HS_EXPORT int hs_ref_history_new(const hs_ref_scene *scene, int digits, hs_ref_history **out);
HS_EXPORT void hs_ref_history_free(hs_ref_history *h); /* NULL is a no-op */
HS_EXPORT int hs_ref_history_add_vertices(hs_ref_history *h, size_t n, const char *const *Q_over_fP,
                                          const char *const *sigma_over_fp0);
HS_EXPORT int hs_ref_history_vertex_count(const hs_ref_history *h, size_t *n);
/* HS_REF_B1, HS_REF_B2 (stick zone (-b2, b1) after the vertex), HS_REF_ENERGY1,
 * HS_REF_ENERGY2 (dissipated in each zone over the segment ending at the vertex),
 * as hs_ref_value: the energies are sums of differences of monotonic energies,
 * formed at the work and the check tier and certified by their agreement. */
HS_EXPORT int hs_ref_history_value(const hs_ref_history *h, size_t vertex, int quantity, char *buf, size_t size,
                                   size_t *needed, int *certified);
/* slip directions after the vertex (+1, -1; 0 where that edge does not slip) */
HS_EXPORT int hs_ref_history_slip_dirs(const hs_ref_history *h, size_t vertex, int *dir1, int *dir2);

#define HS_REF_EVAL_BX       1
#define HS_REF_EVAL_SLIP     2
#define HS_REF_EVAL_WORK     3
#define HS_REF_EVAL_PRESSURE 4
#define HS_REF_EVAL_TRACTION 5  /* shear traction q(x) on body 1 (added after 0.4.0) */

/* Point evaluation at the decimal point x (|x| <= a), as hs_ref_value. The
 * range check is exact: a decimal x beyond a that rounds to a at the working
 * precision gives HS_ERR_POINT_OUTSIDE. */
HS_EXPORT int hs_ref_eval(const hs_ref_solution *sol, int what, const char *x, char *buf, size_t size,
                          size_t *needed, int *certified);

/* A stress component (HS_STRESS_XX, HS_STRESS_YY or HS_STRESS_XY) at the decimal
 * point (x, y) of body 1 (y >= 0) or body 2 (y <= 0), as hs_eval_stress; y = 0 is
 * the surface (on and off the contact). bulk2: decimal bulk stress of body 2
 * (NULL: "0"); body 1 carries sigma + bulk2. Output as hs_ref_value, certified
 * by the work and check tiers. Bad strings: HS_ERR_BAD_NUMBER; body not 1 or 2,
 * another component, or y on the other body's side: HS_ERR_BAD_OPTION.
 * Added after 0.4.0 (docs/fields.md). */
HS_EXPORT int hs_ref_eval_stress(const hs_ref_solution *sol, int body, const char *bulk2, int component,
                                 const char *x, const char *y, char *buf, size_t size, size_t *needed,
                                 int *certified);


/* ---- load histories (since 0.4; docs/history.md) ------------------------------
 * The normal load is applied first and held; then (Q, sigma) moves along
 * straight segments between vertices, starting from (0, 0). Each vertex
 * reports the stick zone, the slip direction of each edge zone (0: that edge
 * does not slip at the vertex) and the energy dissipated in each zone over
 * the segment that ends there. Locked-in slip, receding and reversing zones
 * are followed exactly; the path is marched in load steps (max_step). */
typedef struct hs_history hs_history;

#define HS_RAMP_SIGMA_FIRST 0  /* periodic loading reached by sigma first, then Q (default) */
#define HS_RAMP_TOGETHER    1  /* both together along a straight line */
#define HS_RAMP_Q_FIRST     2  /* Q first, then sigma */

typedef struct hs_history_options {
  size_t struct_size;       /* = sizeof(hs_history_options), set by hs_history_options_default */
  double max_step;          /* first load step, in max(|dQ/fP|, |dsigma/fp0|/4), in [1e-6, 1]; default 1/32 */
  int max_steps;            /* limit on the total number of steps; default 20000; the cost grows like its square */
  int segments_per_cycle;   /* periodic loading with Q and sigma out of phase: chords per cycle (default 64) */
  int ramp_order;           /* HS_RAMP_*: how the periodic loading is reached from zero */
  double steady_rtol;       /* cycles are steady when the zone ends and energies repeat to this (default 1e-6) */
  double rtol;              /* the step is halved (path replayed) until steps h and 2h agree to rtol at every
                               vertex (zone ends / a, energies / the largest one); 0: march at max_step
                               only. Default 1e-8. The static solves (off the ray, advancing segments)
                               take their quadrature orders from it: within rtol of the exact static
                               solve; 0 or below 1e-12: full accuracy. */
  /* issue 14 (added after 0.4.0; a 0.4.0 caller's smaller struct_size still
   * works, with the default): where the friction limit is reached inside the
   * stick zone, away from its ends, a third slip zone would open, which the
   * march does not model. HS_PATCHES_ERROR (default): HS_ERR_NOT_APPLICABLE at
   * that vertex; HS_PATCHES_MERGE: the patch and the band between it and the end
   * slip with the edge zone, an approximation (hs_history_vertex.interior_merges
   * counts them; docs/history.md). */
  int interior_patches;
} hs_history_options;
#define HS_PATCHES_ERROR 0
#define HS_PATCHES_MERGE 1

HS_EXPORT int hs_history_options_default(hs_history_options *opts);
/* A new history of the scene's contact (a, p0, f, E*; its Q/fP and sigma/fp0 are
 * ignored). geometry: NULL for the scene's Hertz contact, or any hs_geometry. */
HS_EXPORT int hs_history_new(const hs_scene *scene, const hs_geometry *geometry, const hs_history_options *opts,
                             hs_history **out);
HS_EXPORT void hs_history_free(hs_history *h);  /* NULL is a no-op */
/* Append n vertices (Q/fP, sigma/fp0) and march to them. On error the history
 * keeps the vertices reached before the failing one. */
HS_EXPORT int hs_history_add_vertices(hs_history *h, size_t n, const double *Q_over_fP,
                                      const double *sigma_over_fp0);
/* Periodic loading Q(t) = Qm + Qa sin(wt), sigma(t) = Sm + Sa sin(wt + phase),
 * reached from the current state by opts->ramp_order, then `cycles` cycles. By
 * static solves, the cycles after one that leaves the state as it found it are
 * copies of it, not solved again (hs_cycle_summary.cycles_repeated; their
 * error_estimate includes the bound of the copy; docs/history.md, "The steady cycle"). */
HS_EXPORT int hs_history_add_cycles(hs_history *h, double Qm_over_fP, double Qa_over_fP, double Sm_over_fp0,
                                    double Sa_over_fp0, double phase_deg, int cycles);
HS_EXPORT int hs_history_vertex_count(const hs_history *h, size_t *n);

typedef struct hs_history_vertex {
  size_t struct_size;       /* = sizeof(hs_history_vertex) */
  double Q_over_fP, sigma_over_fp0;
  double b1, b2;            /* stick zone (-b2, b1), units of length */
  int slip_dir1, slip_dir2; /* +1, -1, or 0 where that edge is not slipping at the vertex */
  double energy1, energy2;  /* dissipated in zone 1 (x > b1) and zone 2 over the segment ending here */
  int cycle;                /* 0: path or ramp; k >= 1: the k-th cycle of hs_history_add_cycles */
  long steps;               /* load steps marched up to this vertex */
  double step;              /* the load step of the segment ending here (after refinement) */
  double error_estimate;    /* estimated error at this vertex (units as for rtol): the sum over the
                               segments so far of the differences of their marches at steps 2h
                               and h over 7 (each from the state before it: local error control),
                               plus 3 times any back-slip at a contact edge over the largest energy
                               (docs/history.md, "Slip back near the edge"; at rtol 0 that part alone);
                               and at least the march's measured difference from the superposition or
                               the static solves on the vertices they took before the path left them
                               (ends over a, energies over the largest; docs/history.md) */
  long interior_merges;     /* interior slip patches merged with an edge zone so far (an approximation;
                               0: none; docs/history.md) */
  /* added after 0.4.0 (a caller's struct from 0.4.0, struct_size = its sizeof, on LP64
     offsetof(hs_history_vertex, patch_dir), gets the fields above): an interior slip zone open at the vertex, taken by the static solves'
     two-interval solve (docs/history.md, "Interior slip zones in hs_history") */
  int patch_dir;            /* its slip direction, +1 or -1; 0: none */
  double patch_l, patch_r;  /* its ends, units of length (0 where patch_dir is 0) */
  double energy_patch;      /* dissipated in interior slip zones over the segment ending here (not part
                               of energy1, energy2) */
} hs_history_vertex;
HS_EXPORT int hs_history_vertex_get(const hs_history *h, size_t i, hs_history_vertex *out);

#define HS_FIELD_TRACTION 1  /* shear traction q(x) */
#define HS_FIELD_SLIP     2  /* accumulated slip h(x), locked-in slip included */
/* Field at n points |x| <= a in the state after vertex i. */
HS_EXPORT int hs_history_eval(const hs_history *h, size_t vertex, int field, size_t n, const double *x,
                              double *out);

typedef struct hs_cycle_summary {
  size_t struct_size;          /* = sizeof(hs_cycle_summary) */
  int cycles;                  /* cycles computed */
  int cycles_to_steady;        /* first cycle that the next repeats (steady_rtol); -1: not reached */
  int shakedown;               /* 1: the last cycle dissipates nothing */
  double energy_per_cycle1;    /* zone 1 over the last cycle */
  double energy_per_cycle2;
  double energy_per_cycle_patch; /* in interior slip zones over the last cycle (added after 0.4.0; a caller's
                                    struct from 0.4.0, struct_size = its sizeof, gets the fields above) */
  /* added after 0.4.0, session 21 (a struct_size of offsetof(hs_cycle_summary, cycles_repeated) gets the
     fields above): cycles taken as copies of a cycle that left the state as it found it, not solved
     again, and that cycle's change of the state (ends over a, traction relative to the friction
     limit's; 0 without copies). docs/history.md, "The steady cycle" */
  int cycles_repeated;
  double repeated_change;
} hs_cycle_summary;
HS_EXPORT int hs_history_cycle_summary(const hs_history *h, hs_cycle_summary *out);
/* Slip range max h - min h over the vertices of the last cycle, at n points. */
HS_EXPORT int hs_history_slip_range(const hs_history *h, size_t n, const double *x, double *out);

/* Issue 15 (unreleased): the state after vertex i of the history as a new,
 * read-only solution handle (free it with hs_solution_free). It holds a copy of
 * the steps up to the vertex: it stays valid after the history is freed or
 * grows. These functions apply to it: hs_solution_summary (stick zone and slip
 * directions of the vertex; regime STUCK without slip zones, OPPOSITE_SIGN when
 * the two zones slip in opposite directions, otherwise SAME_SIGN; error_estimate
 * the vertex's; model, iterations and quadrature_order 0), hs_eval_traction,
 * hs_eval_slip (accumulated slip, locked-in slip included), hs_eval_pressure,
 * hs_eval_surface_stress, hs_eval_stress, hs_eval_stress_scalar and
 * hs_surface_stress_extremes. hs_solution_energy, hs_eval_Bx, hs_eval_work,
 * hs_solution_ramp and hs_solution_steady_cycle return HS_ERR_NOT_APPLICABLE
 * (monotonic-loading quantities). Errors: NULL_POINTER, BAD_OPTION (vertex out
 * of range), OUT_OF_MEMORY; *out untouched on error. */
HS_EXPORT int hs_history_state(const hs_history *h, size_t vertex, hs_solution **out);

/* How the history computes its states (issue 14, unreleased), as chosen by itself:
 * HS_HISTORY_SUPERPOSITION: every vertex on one ray through the origin, sums of
 * monotonic solutions; HS_HISTORY_STATIC: every segment so far advances (no zone
 * recedes), one static solve per segment from the state before it (no steps; its
 * quadrature orders are chosen from opts->rtol, and error_estimate reports that rtol,
 * 0 at full accuracy, plus k times the copied cycle's change on the k-th copy of a
 * steady cycle);
 * HS_HISTORY_MARCH: load steps (steps, step and error_estimate of hs_history_vertex).
 * The first vertex that a method cannot take replays the whole path in the next one. */
#define HS_HISTORY_SUPERPOSITION 1
#define HS_HISTORY_STATIC        2
#define HS_HISTORY_MARCH         3
HS_EXPORT int hs_history_method(const hs_history *h, int *method);
/* Why the last hs_history_add_vertices or hs_history_add_cycles on h failed, as
 * text (e.g. which zone structure a method does not model: an interior slip zone,
 * part of an edge zone slipping back); "" after a call that succeeded. Copies at
 * most size - 1 bytes and a terminating NUL into buf (size >= 1). */
HS_EXPORT int hs_history_last_error(const hs_history *h, char *buf, size_t size);

/* Whether a proportional ramp from zero to the solution's (Q, sigma) would make a
 * slip zone recede on the way (the monotonic solution then is not the state such a
 * ramp reaches; docs/history.md), and the Q/fP where that first happens (NaN if not). */
HS_EXPORT int hs_solution_ramp(const hs_solution *sol, int *recedes, double *at_Q_over_fP);

/* Symmetric proportional cycling between +(Q, sigma) and -(Q, sigma) of the
 * solution, reached by the proportional ramp from zero, in closed form
 * (Ciavarella-Jager superposition; docs/history.md). valid = 0 when a zone
 * recedes on the ramp (march the cycle with hs_history_add_cycles instead). The
 * cycle is steady from the first reversal; the stick zone at +(Q, sigma) is the
 * solution's (at -(Q, sigma) the same, directions flipped); each zone dissipates
 * 4 times its monotonic energy per cycle (hs_solution_energy units); the slip
 * range over a cycle is 2 h(x) (hs_eval with HS_FIELD_SLIP). The solution's
 * model carries over: a reference-backend solution gives certified energies. */
typedef struct hs_steady_cycle {
  size_t struct_size;          /* = sizeof(hs_steady_cycle) */
  int valid;                   /* 1: the closed form applies */
  int cycles_to_steady;        /* 1 */
  double energy_per_cycle1;    /* zone 1, units f^2 p0^2 a^2 / E* (as hs_solution_energy) */
  double energy_per_cycle2;
} hs_steady_cycle;
HS_EXPORT int hs_solution_steady_cycle(const hs_solution *sol, hs_steady_cycle *out);

/* ---- batches (issue 16) ------------------------------------------------------
 * Solve n Hertz scenes (scene->geometry must be HS_GEOMETRY_HERTZ) with the same
 * options on `threads` threads (0: std::thread::hardware_concurrency(); never
 * more than n). Each out[i] is exactly what hs_solve + hs_solution_summary
 * (+ hs_solution_energy with HS_BATCH_ENERGIES) give for scenes[i], bitwise,
 * whatever the thread count: the scenes are split into fixed contiguous
 * chunks and solved independently. A scene that fails (bad input, no
 * convergence, ...) gets its HS_ERR_* in out[i].status (hs_strerror gives the
 * message), its other fields zero, and does not stop the others. The call
 * itself returns HS_OK once the arguments are valid, or HS_ERR_NULL_POINTER
 * (scenes or out NULL with n > 0), HS_ERR_STRUCT_SIZE (result_size is not
 * sizeof(hs_batch_result), or opts->struct_size), HS_ERR_BAD_OPTION (threads
 * < 0 or > 1024, unknown flags, an invalid opts field); then out is untouched.
 * No state is kept between calls. */
#define HS_BATCH_ENERGIES 1 /* flags: also compute the zone energies */
typedef struct hs_batch_result {
  int status;           /* HS_OK or the scene's HS_ERR_* */
  int regime;           /* HS_REGIME_* */
  int slip_dir1, slip_dir2;
  int model;            /* HS_MODEL_* actually used */
  int iterations;
  double b1, b2, d1, d2;     /* as hs_summary */
  double error_estimate;     /* as hs_summary */
  double energy1, energy2;   /* with HS_BATCH_ENERGIES, else 0 (as hs_solution_energy) */
} hs_batch_result;
HS_EXPORT int hs_solve_batch(size_t n, const hs_scene *scenes, const hs_options *opts, int flags, int threads,
                             hs_batch_result *out, size_t result_size);

#ifdef __cplusplus
}
#endif
#endif /* HALFSLIP_H */
