/* Values of the header's macros and struct sizes, as the C compiler sees
 * them, for the Fortran test to compare with the module's parameters and
 * bind(c) types. The order is the one of kConstants in test_fortran.f90. */
#include <halfslip/halfslip.h>

static const int kValues[] = {
  HS_VERSION_MAJOR, HS_VERSION_MINOR, HS_VERSION_PATCH,
  HS_OK, HS_ERR_NULL_POINTER, HS_ERR_STRUCT_SIZE, HS_ERR_NOT_FINITE, HS_ERR_BAD_SIZE,
  HS_ERR_BAD_FRICTION, HS_ERR_GROSS_SLIDING, HS_ERR_BAD_GEOMETRY, HS_ERR_POINT_OUTSIDE,
  HS_ERR_BUFFER_TOO_SMALL, HS_ERR_NO_CONVERGENCE, HS_ERR_BAD_OPTION, HS_ERR_OUT_OF_MEMORY,
  HS_ERR_INTERNAL, HS_ERR_OVERFLOW, HS_ERR_BAD_NUMBER, HS_ERR_TOLERANCE, HS_ERR_NOT_APPLICABLE,
  HS_MODEL_DEFAULT, HS_MODEL_AUTO, HS_MODEL_ASYMPTOTIC, HS_MODEL_CLOSED_FORM, HS_MODEL_QUADRATURE, HS_MODEL_REFERENCE,
  HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW, HS_GEOMETRY_SAMPLES, HS_GEOMETRY_CALLBACK,
  HS_REGIME_STUCK, HS_REGIME_SAME_SIGN, HS_REGIME_OPPOSITE_SIGN, HS_REGIME_BOUNDARY,
  HS_REF_B1, HS_REF_B2, HS_REF_D1, HS_REF_D2, HS_REF_ENERGY1, HS_REF_ENERGY2, HS_REF_A, HS_REF_P0,
  HS_REF_EVAL_BX, HS_REF_EVAL_SLIP, HS_REF_EVAL_WORK, HS_REF_EVAL_PRESSURE,
  HS_RAMP_SIGMA_FIRST, HS_RAMP_TOGETHER, HS_RAMP_Q_FIRST, HS_FIELD_TRACTION, HS_FIELD_SLIP,
  HS_STRESS_XX, HS_STRESS_YY, HS_STRESS_XY, HS_STRESS_VON_MISES, HS_STRESS_MAX_PRINCIPAL,
  HS_STRESS_MIN_PRINCIPAL, HS_STRESS_MAX_SHEAR, HS_PATCHES_ERROR, HS_PATCHES_MERGE,
};

int hstest_header_values(int *out, int n);
int hstest_header_values(int *out, int n) {
  int i, total = (int)(sizeof kValues / sizeof kValues[0]);
  for (i = 0; i < n && i < total; ++i) out[i] = kValues[i];
  return total;
}

/* sizeof of hs_scene, hs_options, hs_summary, hs_ref_summary, hs_geometry,
 * hs_history_options, hs_history_vertex, hs_cycle_summary */
void hstest_struct_sizes(size_t out[8]);
void hstest_struct_sizes(size_t out[8]) {
  out[0] = sizeof(hs_scene);
  out[1] = sizeof(hs_options);
  out[2] = sizeof(hs_summary);
  out[3] = sizeof(hs_ref_summary);
  out[4] = sizeof(hs_geometry);
  out[5] = sizeof(hs_history_options);
  out[6] = sizeof(hs_history_vertex);
  out[7] = sizeof(hs_cycle_summary);
}
