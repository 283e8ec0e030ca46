/* The public header compiles alone as strict C99 (-pedantic -Werror, with
 * -Wstrict-prototypes), and every function has the signature the ABI
 * documents: a changed signature fails to compile here. */
#include <halfslip/halfslip.h>
#include <halfslip/halfslip.h> /* include guard */

/* Declares a pointer with the expected type and initialises it with the
 * function: a mismatch is a constraint violation (an error with -Werror). */
#define HS_CHECK_SIGNATURE(ret, fn, params) \
  ret(*fn##_ptr) params = fn;               \
  (void)fn##_ptr

int hs_header_check(void);
int hs_header_check(void) {
  HS_CHECK_SIGNATURE(int, hs_version, (int *, int *, int *));
  HS_CHECK_SIGNATURE(const char *, hs_version_string, (void));
  HS_CHECK_SIGNATURE(const char *, hs_strerror, (int));
  HS_CHECK_SIGNATURE(int, hs_scene_default, (hs_scene *));
  HS_CHECK_SIGNATURE(int, hs_scene_from_hertz_loads, (double, double, double, double, double, double, hs_scene *));
  HS_CHECK_SIGNATURE(int, hs_options_default, (hs_options *));
  HS_CHECK_SIGNATURE(int, hs_solve, (const hs_scene *, const hs_options *, hs_solution **));
  HS_CHECK_SIGNATURE(void, hs_solution_free, (hs_solution *));
  HS_CHECK_SIGNATURE(int, hs_geometry_default, (hs_geometry *));
  HS_CHECK_SIGNATURE(int, hs_solve_geometry,
                     (const hs_scene *, const hs_geometry *, const hs_options *, hs_solution **));
  HS_CHECK_SIGNATURE(int, hs_solution_summary, (const hs_solution *, hs_summary *));
  HS_CHECK_SIGNATURE(int, hs_solution_energy, (const hs_solution *, double *));
  HS_CHECK_SIGNATURE(int, hs_eval_Bx, (const hs_solution *, size_t, const double *, double *));
  HS_CHECK_SIGNATURE(int, hs_eval_slip, (const hs_solution *, size_t, const double *, double *));
  HS_CHECK_SIGNATURE(int, hs_eval_work, (const hs_solution *, size_t, const double *, double *));
  HS_CHECK_SIGNATURE(int, hs_eval_pressure, (const hs_solution *, size_t, const double *, double *));
  HS_CHECK_SIGNATURE(int, hs_ref_scene_default, (hs_ref_scene *));
  HS_CHECK_SIGNATURE(int, hs_ref_max_digits, (void));
  HS_CHECK_SIGNATURE(int, hs_ref_solve, (const hs_ref_scene *, int, hs_ref_solution **));
  HS_CHECK_SIGNATURE(void, hs_ref_solution_free, (hs_ref_solution *));
  HS_CHECK_SIGNATURE(int, hs_ref_solution_summary, (const hs_ref_solution *, hs_ref_summary *));
  HS_CHECK_SIGNATURE(int, hs_ref_value, (const hs_ref_solution *, int, char *, size_t, size_t *, int *));
  HS_CHECK_SIGNATURE(int, hs_ref_eval, (const hs_ref_solution *, int, const char *, char *, size_t, size_t *, int *));
  return 0;
}

/* struct_size comes first in every struct (compile-time checks in C99). */
#define HS_STATIC_CHECK(name, cond) typedef char name[(cond) ? 1 : -1]
HS_STATIC_CHECK(hs_check_scene, offsetof(hs_scene, struct_size) == 0);
HS_STATIC_CHECK(hs_check_options, offsetof(hs_options, struct_size) == 0);
HS_STATIC_CHECK(hs_check_summary, offsetof(hs_summary, struct_size) == 0);
HS_STATIC_CHECK(hs_check_geometry, offsetof(hs_geometry, struct_size) == 0);
HS_STATIC_CHECK(hs_check_ref_scene, offsetof(hs_ref_scene, struct_size) == 0);
HS_STATIC_CHECK(hs_check_ref_summary, offsetof(hs_ref_summary, struct_size) == 0);
HS_STATIC_CHECK(hs_check_version, HS_VERSION_MAJOR >= 0 && HS_OK == 0);
