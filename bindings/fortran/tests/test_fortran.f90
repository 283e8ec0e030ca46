! Test of the Fortran module halfslip against the C library: constants and
! struct layouts agree with the header, real results (same-sign closed form,
! opposite-sign value, reference digits, load histories), error codes through
! ierr, outputs untouched on error. Prints "fortran: N passed, M failed"; exit status 1 on
! any failure.
! Pressure callbacks for hs_solve_callback (bind(c) procedures of a module).
module test_fortran_pressures
  use, intrinsic :: iso_c_binding, only: c_double, c_ptr, c_associated, c_f_pointer
  implicit none
contains
  ! Hertz pressure p0 sqrt(1 - x^2/a^2) with p0 = 1 and a from user (a real(c_double)).
  function hertz_p(x, user) bind(c) result(p)
    real(c_double), value :: x
    type(c_ptr), value :: user
    real(c_double) :: p
    real(c_double), pointer :: a
    call c_f_pointer(user, a)
    p = 0
    if (abs(x) < a) p = sqrt((a - x) * (a + x)) / a
  end function hertz_p

  ! Not a pressure: negative on part of the contact.
  function negative_p(x, user) bind(c) result(p)
    real(c_double), value :: x
    type(c_ptr), value :: user
    real(c_double) :: p
    p = -1
    if (x < 0.2_c_double .and. .not. c_associated(user)) p = sqrt(1 - x * x)
  end function negative_p
end module test_fortran_pressures

program test_fortran
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_sizeof, c_loc, c_ptr
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, ieee_is_nan
  use halfslip
  use test_fortran_pressures
  implicit none

  interface
    function hstest_header_values(out, n) bind(c, name="hstest_header_values") result(total)
      import :: c_int
      integer(c_int), intent(inout) :: out(*)
      integer(c_int), value :: n
      integer(c_int) :: total
    end function hstest_header_values
    subroutine hstest_struct_sizes(out) bind(c, name="hstest_struct_sizes")
      import :: c_size_t
      integer(c_size_t), intent(inout) :: out(8)
    end subroutine hstest_struct_sizes
  end interface

  ! Same order as kValues in header_values.c.
  integer(c_int), parameter :: kConstants(62) = [ &
    HS_VERSION_MAJOR, HS_VERSION_MINOR, HS_VERSION_PATCH, &
    HS_OK, HS_ERR_NULL_POINTER, HS_ERR_STRUCT_SIZE, HS_ERR_NOT_FINITE, HS_ERR_BAD_SIZE, &
    HS_ERR_BAD_FRICTION, HS_ERR_GROSS_SLIDING, HS_ERR_BAD_GEOMETRY, HS_ERR_POINT_OUTSIDE, &
    HS_ERR_BUFFER_TOO_SMALL, HS_ERR_NO_CONVERGENCE, HS_ERR_BAD_OPTION, HS_ERR_OUT_OF_MEMORY, &
    HS_ERR_INTERNAL, HS_ERR_OVERFLOW, HS_ERR_BAD_NUMBER, HS_ERR_TOLERANCE, HS_ERR_NOT_APPLICABLE, &
    HS_MODEL_DEFAULT, HS_MODEL_AUTO, HS_MODEL_ASYMPTOTIC, HS_MODEL_CLOSED_FORM, HS_MODEL_QUADRATURE, &
    HS_MODEL_REFERENCE, &
    HS_GEOMETRY_HERTZ, HS_GEOMETRY_FLAT_ROUNDED, HS_GEOMETRY_POWER_LAW, HS_GEOMETRY_SAMPLES, &
    HS_GEOMETRY_CALLBACK, &
    HS_REGIME_STUCK, HS_REGIME_SAME_SIGN, HS_REGIME_OPPOSITE_SIGN, HS_REGIME_BOUNDARY, &
    HS_REF_B1, HS_REF_B2, HS_REF_D1, HS_REF_D2, HS_REF_ENERGY1, HS_REF_ENERGY2, HS_REF_A, HS_REF_P0, &
    HS_REF_EVAL_BX, HS_REF_EVAL_SLIP, HS_REF_EVAL_WORK, HS_REF_EVAL_PRESSURE, &
    HS_RAMP_SIGMA_FIRST, HS_RAMP_TOGETHER, HS_RAMP_Q_FIRST, HS_FIELD_TRACTION, HS_FIELD_SLIP, &
    HS_STRESS_XX, HS_STRESS_YY, HS_STRESS_XY, HS_STRESS_VON_MISES, HS_STRESS_MAX_PRINCIPAL, &
    HS_STRESS_MIN_PRINCIPAL, HS_STRESS_MAX_SHEAR, HS_PATCHES_ERROR, HS_PATCHES_MERGE]

  real(c_double), parameter :: pi = 3.141592653589793238462643383279503_c_double
  integer :: passed = 0, failed = 0

  call test_header_agreement()
  call test_version_and_messages()
  call test_same_sign()
  call test_opposite_sign()
  call test_regime_boundary()
  call test_errors()
  call test_hertz_loads()
  call test_geometries()
  call test_reference()
  call test_history()
  call test_fields()
  call test_batch()

  write (*, '(a,i0,a,i0,a)') 'fortran: ', passed, ' passed, ', failed, ' failed'
  if (failed /= 0) error stop 1

contains

  subroutine expect(cond, label)
    logical, intent(in) :: cond
    character(len=*), intent(in) :: label
    if (cond) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(a)') 'FAILED: ' // label
    end if
  end subroutine expect

  subroutine expect_code(got, want, label)
    integer, intent(in) :: got, want
    character(len=*), intent(in) :: label
    if (got == want) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(a,i0,a,i0,a)') 'FAILED: ' // label // ' (status ', got, ', expected ', want, ')'
    end if
  end subroutine expect_code

  subroutine expect_near(got, want, tol, label)
    real(c_double), intent(in) :: got, want, tol
    character(len=*), intent(in) :: label
    if (abs(got - want) <= tol) then
      passed = passed + 1
    else
      failed = failed + 1
      write (*, '(a,es25.17,a,es25.17,a,es9.2)') 'FAILED: ' // label // ': ', got, ' vs ', want, ', tol ', tol
    end if
  end subroutine expect_near

  type(hs_scene) function scene_qs(q, s) result(sc)
    real(c_double), intent(in) :: q, s
    call hs_scene_default(sc)
    sc%Q_over_fP = q
    sc%sigma_over_fp0 = s
  end function scene_qs

  integer function solve_status(sc) result(ierr)
    type(hs_scene), intent(in) :: sc
    type(hs_solution_t) :: sol
    call hs_solve(sc, sol, ierr=ierr)
    call expect(ierr == HS_OK .eqv. hs_associated(sol), 'handle set iff success')
    call hs_solution_free(sol)
  end function solve_status

  ! Every parameter of the module equals the C macro; every bind(c) type has
  ! the size of its C struct.
  subroutine test_header_agreement()
    integer(c_int) :: cvals(size(kConstants)), total
    integer(c_size_t) :: sizes(8)
    type(hs_geometry) :: g
    type(hs_scene) :: sc
    type(hs_options) :: op
    type(hs_summary) :: sm
    type(hs_ref_summary) :: rsm
    type(hs_history_options) :: ho
    type(hs_history_vertex) :: hv
    type(hs_cycle_summary) :: cs
    integer :: i
    cvals = -999
    total = hstest_header_values(cvals, int(size(cvals), c_int))
    call expect(total == size(kConstants), 'number of header constants')
    do i = 1, size(kConstants)
      if (cvals(i) /= kConstants(i)) then
        write (*, '(a,i0,a,i0,a,i0)') 'constant #', i, ': Fortran ', kConstants(i), ', C ', cvals(i)
      end if
    end do
    call expect(all(cvals == kConstants), 'Fortran parameters equal the header macros')
    sizes = 0
    call hstest_struct_sizes(sizes)
    call expect(c_sizeof(sc) == sizes(1), 'sizeof(hs_scene)')
    call expect(c_sizeof(op) == sizes(2), 'sizeof(hs_options)')
    call expect(c_sizeof(sm) == sizes(3), 'sizeof(hs_summary)')
    call expect(c_sizeof(rsm) == sizes(4), 'sizeof(hs_ref_summary)')
    call expect(c_sizeof(g) == sizes(5), 'sizeof(hs_geometry)')
    call expect(c_sizeof(ho) == sizes(6), 'sizeof(hs_history_options)')
    call expect(c_sizeof(hv) == sizes(7), 'sizeof(hs_history_vertex)')
    call expect(c_sizeof(cs) == sizes(8), 'sizeof(hs_cycle_summary)')
    call hs_history_options_default(ho)
    call expect(ho%struct_size == c_sizeof(ho) .and. ho%max_step == 1 / 32.0_c_double .and. ho%rtol == 1e-8_c_double .and. &
                ho%segments_per_cycle == 64 .and. ho%ramp_order == HS_RAMP_SIGMA_FIRST, 'hs_history_options_default')
    call hs_geometry_default(g)
    call expect(g%struct_size == c_sizeof(g) .and. g%kind == HS_GEOMETRY_HERTZ .and. &
                g%flat_over_a == 0.5_c_double .and. g%exponent == 2, 'hs_geometry_default')
    call hs_scene_default(sc)
    call expect(sc%struct_size == c_sizeof(sc), 'hs_scene_default sets struct_size')
    call expect(sc%geometry == HS_GEOMETRY_HERTZ .and. sc%a == 1 .and. sc%E_star == 1, 'scene defaults')
    call expect(sc%Q_over_fP == 0.5_c_double .and. sc%sigma_over_fp0 == 0.5_c_double, 'scene default ratios')
    call hs_options_default(op)
    call expect(op%struct_size == c_sizeof(op) .and. op%max_iterations == 100 .and. op%rtol == 0, &
                'hs_options_default')
  end subroutine test_header_agreement

  subroutine test_version_and_messages()
    integer :: ma, mi, pa, ierr
    character(len=:), allocatable :: msg
    ma = -1
    call hs_version(ma, mi, pa, ierr)
    call expect_code(ierr, HS_OK, 'hs_version status')
    call expect(ma == HS_VERSION_MAJOR .and. mi == HS_VERSION_MINOR .and. pa == HS_VERSION_PATCH, &
                'hs_version numbers')
    call expect(hs_version_string() == '0.4.0', 'hs_version_string')
    msg = hs_strerror(HS_ERR_GROSS_SLIDING)
    call expect(index(msg, '|Q| >= fP') > 0, 'hs_strerror(HS_ERR_GROSS_SLIDING): ' // msg)
    call expect(hs_strerror(HS_OK) == 'success', 'hs_strerror(HS_OK)')
    call expect(index(hs_strerror(12345), 'unknown') > 0, 'hs_strerror(unknown code)')
    call expect(hs_strerror(HS_ERR_BAD_FRICTION) /= hs_strerror(HS_ERR_BAD_SIZE), 'distinct messages')
    ! the model-name table of the C library (since 0.4)
    call expect(hs_model_name(HS_MODEL_CLOSED_FORM) == 'closed-form', 'hs_model_name(HS_MODEL_CLOSED_FORM)')
    call expect(hs_model_name(-1) == '', 'hs_model_name(unknown)')
    ma = -1
    call hs_model_from_name('quadrature', ma, ierr)
    call expect_code(ierr, HS_OK, 'hs_model_from_name status')
    call expect(ma == HS_MODEL_QUADRATURE, 'hs_model_from_name(quadrature)')
    call hs_model_from_name('no-such-model', ma, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'hs_model_from_name(unknown)')
    call expect(ma == HS_MODEL_QUADRATURE, 'hs_model_from_name: model untouched on error')
  end subroutine test_version_and_messages

  ! Same-sign closed form: b1/a = sqrt(1 - Q/fP) + sigma/(4 f p0), b2 with the minus sign.
  subroutine test_same_sign()
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    real(c_double) :: x(4), B(4), h(4), W(4), p(4), E(2)
    integer :: ierr
    call expect(.not. hs_associated(sol), 'handle starts null')
    call hs_solve(scene_qs(0.5_c_double, 0.2_c_double), sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'same-sign solve')
    call expect(hs_associated(sol), 'handle set')
    call hs_solution_summary(sol, sm, ierr)
    call expect_code(ierr, HS_OK, 'summary')
    call expect(sm%regime == HS_REGIME_SAME_SIGN, 'same-sign regime')
    call expect_near(sm%b1, sqrt(0.5_c_double) + 0.05_c_double, 1e-15_c_double, 'b1 same sign')
    call expect_near(sm%b2, sqrt(0.5_c_double) - 0.05_c_double, 1e-15_c_double, 'b2 same sign')
    call expect_near(sm%d1, 1 - sm%b1, 1e-15_c_double, 'd1 = a - b1')
    call expect(sm%slip_dir1 == 1 .and. sm%slip_dir2 == 1, 'same-sign slip directions')
    call expect(sm%a == 1 .and. sm%iterations == 0, 'a and closed-form iterations')

    x = [0.0_c_double, 0.99_c_double, -0.99_c_double, 1.0_c_double]
    call hs_eval_Bx(sol, 4, x, B, ierr)
    call expect_code(ierr, HS_OK, 'eval Bx')
    call hs_eval_slip(sol, 4, x, h)
    call hs_eval_work(sol, 4, x, W)
    call hs_eval_pressure(sol, 4, x, p)
    call expect(B(1) == 0 .and. h(1) == 0 .and. W(1) == 0, 'stick zone gives 0')
    ! eq (21): B = 2 f p0/(a E*) sqrt((x - b1)(x + b2)) in zone 1
    call expect_near(B(2), 2 * sqrt((0.99_c_double - sm%b1) * (0.99_c_double + sm%b2)), 1e-14_c_double, &
                     'Bx in zone 1 (eq 21)')
    call expect(B(3) < 0 .and. h(2) > 0 .and. h(3) > 0 .and. W(2) > 0, 'signs of Bx, h, W')
    call expect_near(p(2), sqrt(1 - 0.99_c_double**2), 1e-15_c_double, 'Hertz pressure')
    call expect(p(4) == 0, 'pressure at the edge')
    call hs_solution_energy(sol, E, ierr)
    call expect_code(ierr, HS_OK, 'energy')
    call expect(E(1) > 0 .and. E(2) > E(1), 'energies: zone 2 (longer) dissipates more')

    ! a point outside: HS_ERR_POINT_OUTSIDE and the output untouched
    B = 42
    x(4) = 1.5_c_double
    call hs_eval_Bx(sol, 4, x, B, ierr)
    call expect_code(ierr, HS_ERR_POINT_OUTSIDE, 'point outside')
    call expect(all(B == 42), 'output untouched on error')
    x(4) = ieee_value(x(4), ieee_quiet_nan)
    call hs_eval_slip(sol, 4, x, B, ierr)
    call expect_code(ierr, HS_ERR_NOT_FINITE, 'NaN point')
    call hs_eval_work(sol, 0, x, B, ierr)
    call expect_code(ierr, HS_OK, 'zero points')

    call hs_solution_free(sol)
    call expect(.not. hs_associated(sol), 'free resets the handle')
    call hs_solution_free(sol)   ! null handle: no-op
    call hs_solution_summary(sol, sm, ierr)
    call expect_code(ierr, HS_ERR_NULL_POINTER, 'summary of a null handle')
    call hs_eval_Bx(sol, 1, x, B, ierr)
    call expect_code(ierr, HS_ERR_NULL_POINTER, 'eval with a null handle')
  end subroutine test_same_sign

  subroutine test_opposite_sign()
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    type(hs_options) :: op
    real(c_double) :: x(2), h(2)
    integer :: ierr
    call hs_options_default(op)
    op%rtol = 1e-10_c_double
    call hs_solve(scene_qs(0.3_c_double, 2.0_c_double), sol, op, ierr)
    call expect_code(ierr, HS_OK, 'opposite-sign solve with options')
    call hs_solution_summary(sol, sm)
    call expect(sm%regime == HS_REGIME_OPPOSITE_SIGN, 'opposite-sign regime')
    call expect_near(sm%b1, 0.749058362968991_c_double, 1e-14_c_double, 'b1 opposite sign')
    call expect(sm%slip_dir1 == -1 .and. sm%slip_dir2 == 1, 'opposite-sign slip directions')
    call expect(sm%iterations >= 1, 'Newton iterations counted')
    x = [0.95_c_double, -0.95_c_double]
    call hs_eval_slip(sol, 2, x, h)
    call expect(h(1) < 0 .and. h(2) > 0, 'slip has the sign of the zone direction')
    call hs_solution_free(sol)
  end subroutine test_opposite_sign

  ! issue 13: a zone below the model's zone resolution has direction 0, regime BOUNDARY
  subroutine test_regime_boundary()
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    integer :: ierr
    call hs_solve(scene_qs(-0.45989658854377635_c_double, -1.0603308717987363_c_double), sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'boundary solve')
    call hs_solution_summary(sol, sm)
    call expect(sm%regime == HS_REGIME_BOUNDARY, 'boundary regime')
    call expect(sm%slip_dir1 == 0 .and. sm%slip_dir2 == -1, 'boundary slip directions')
    call expect(sm%zone_resolution > 0 .and. sm%zone_resolution < 1e-14_c_double, 'zone resolution')
    call expect(sm%d1 <= sm%zone_resolution, 'zone 1 unresolved')
    call hs_solution_free(sol)
  end subroutine test_regime_boundary

  subroutine test_errors()
    type(hs_scene) :: sc
    type(hs_options) :: op
    type(hs_solution_t) :: sol
    integer :: ierr
    real(c_double) :: nan, inf
    nan = ieee_value(nan, ieee_quiet_nan)
    inf = ieee_value(inf, ieee_positive_inf)
    call expect_code(solve_status(scene_qs(1.0_c_double, 0.0_c_double)), HS_ERR_GROSS_SLIDING, 'Q/fP = 1')
    call expect_code(solve_status(scene_qs(-1.0_c_double, 0.0_c_double)), HS_ERR_GROSS_SLIDING, 'Q/fP = -1')
    call expect_code(solve_status(scene_qs(nan, 0.0_c_double)), HS_ERR_NOT_FINITE, 'NaN ratio')
    call expect_code(solve_status(scene_qs(0.1_c_double, inf)), HS_ERR_NOT_FINITE, 'infinite sigma')
    sc = scene_qs(0.5_c_double, 0.2_c_double)
    sc%f = 0
    call expect_code(solve_status(sc), HS_ERR_BAD_FRICTION, 'f = 0')
    sc = scene_qs(0.5_c_double, 0.2_c_double)
    sc%a = -1
    call expect_code(solve_status(sc), HS_ERR_BAD_SIZE, 'a < 0')
    sc = scene_qs(0.5_c_double, 0.2_c_double)
    sc%geometry = 99
    call expect_code(solve_status(sc), HS_ERR_BAD_GEOMETRY, 'unknown geometry')
    sc = scene_qs(0.5_c_double, 0.2_c_double)
    sc%struct_size = 0
    call expect_code(solve_status(sc), HS_ERR_STRUCT_SIZE, 'struct_size not set')
    call hs_options_default(op)
    op%max_iterations = 0
    call hs_solve(scene_qs(0.5_c_double, 0.2_c_double), sol, op, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'max_iterations = 0')
    call expect(.not. hs_associated(sol), 'handle untouched on error')
    call hs_options_default(op)
    op%rtol = 0.5_c_double
    call hs_solve(scene_qs(0.5_c_double, 0.2_c_double), sol, op, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'rtol out of range')
  end subroutine test_errors

  ! Dimensional input: a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a).
  subroutine test_hertz_loads()
    type(hs_scene) :: sc
    integer :: ierr
    real(c_double), parameter :: P = 1000, R = 0.05_c_double, E = 1.15e11_c_double, f = 0.6_c_double
    call hs_scene_from_hertz_loads(P, R, E, f, 300.0_c_double, 2e6_c_double, sc, ierr)
    call expect_code(ierr, HS_OK, 'from_hertz_loads')
    call expect_near(sc%a, sqrt(4 * P * R / (pi * E)), 1e-15_c_double * sc%a, 'a from loads')
    call expect_near(sc%p0, 2 * P / (pi * sc%a), 1e-15_c_double * sc%p0, 'p0 from loads')
    call expect_near(sc%Q_over_fP, 300 / (f * P), 1e-16_c_double, 'Q/fP from loads')
    sc%a = -7
    call hs_scene_from_hertz_loads(P, R, E, f, 700.0_c_double, 0.0_c_double, sc, ierr)
    call expect_code(ierr, HS_ERR_GROSS_SLIDING, 'from_hertz_loads: gross sliding')
    call expect(sc%a == -7, 'scene untouched on error')
    call hs_scene_from_hertz_loads(-P, R, E, f, 0.0_c_double, 0.0_c_double, sc, ierr)
    call expect_code(ierr, HS_ERR_BAD_SIZE, 'from_hertz_loads: P < 0')
    call hs_scene_from_hertz_loads(P, R, E, 0.0_c_double, 0.0_c_double, 0.0_c_double, sc, ierr)
    call expect_code(ierr, HS_ERR_BAD_FRICTION, 'from_hertz_loads: f = 0')
    ! power law n = 2, A = 1/(2R) and the flat punch with b_f = 0 are Hertz
    call hs_scene_from_hertz_loads(P, R, E, f, 300.0_c_double, 2e6_c_double, sc, ierr)
    block
      type(hs_scene) :: pl, fl
      real(c_double) :: beta
      call hs_scene_from_power_law_loads(P, 1 / (2 * R), 2.0_c_double, E, f, 300.0_c_double, 2e6_c_double, pl, ierr)
      call expect_code(ierr, HS_OK, 'from_power_law_loads')
      call expect_near(pl%a, sc%a, 1e-15_c_double * sc%a, 'power law n = 2 is Hertz')
      beta = -1
      call hs_scene_from_flat_rounded_loads(P, R, 0.0_c_double, E, f, 300.0_c_double, 2e6_c_double, fl, beta, ierr)
      call expect_code(ierr, HS_OK, 'from_flat_rounded_loads')
      call expect_near(fl%a, sc%a, 1e-15_c_double * sc%a, 'flat punch b_f = 0 is Hertz')
      call expect(beta == 0, 'flat_over_a = 0')
      call hs_scene_from_power_law_loads(P, 1.0_c_double, 0.5_c_double, E, f, 0.0_c_double, 0.0_c_double, pl, ierr)
      call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'from_power_law_loads: n <= 1')
    end block
  end subroutine test_hertz_loads

  ! Non-Hertz pressures. The power law with n = 2, the flat punch with a zero
  ! flat, and the Hertz pressure given as a callback or as samples all
  ! reproduce the Hertz closed forms.
  subroutine test_geometries()
    type(hs_scene) :: sc
    type(hs_geometry) :: g
    type(hs_solution_t) :: hz, sol
    type(hs_summary) :: a, b
    real(c_double), target :: unit
    real(c_double) :: xs(41), ps(41), x1(1), B1(1), B2(1)
    integer :: i, ierr
    sc = scene_qs(0.3_c_double, 2.0_c_double)
    call hs_solve(sc, hz)
    call hs_solution_summary(hz, a)
    call expect(a%quadrature_order == 0 .and. a%p0 == 1, 'Hertz: closed forms, p0')

    call hs_geometry_default(g)
    g%kind = HS_GEOMETRY_POWER_LAW
    g%exponent = 2
    call hs_solve_geometry(sc, g, sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'power law n = 2')
    call hs_solution_summary(sol, b)
    call expect(b%regime == a%regime .and. b%quadrature_order > 0, 'power law: regime and quadrature order')
    call expect_near(b%b1, a%b1, 1e-13_c_double, 'power law n = 2: b1 = Hertz')
    call expect_near(b%b2, a%b2, 1e-13_c_double, 'power law n = 2: b2 = Hertz')
    x1 = 0.95_c_double
    call hs_eval_Bx(sol, 1, x1, B1)
    call hs_eval_Bx(hz, 1, x1, B2)
    call expect_near(B1(1), B2(1), 1e-10_c_double, 'power law n = 2: Bx = Hertz')
    call hs_solution_free(sol)

    g%kind = HS_GEOMETRY_FLAT_ROUNDED
    g%flat_over_a = 0
    call hs_solve_geometry(sc, g, sol)
    call hs_solution_summary(sol, b)
    call expect_near(b%b1, a%b1, 1e-13_c_double, 'flat punch, no flat: b1 = Hertz')
    call hs_solution_free(sol)
    ! a real flat: shear alone gives a centred stick zone beyond the flat
    g%flat_over_a = 0.6_c_double
    call hs_solve_geometry(scene_qs(0.5_c_double, 0.0_c_double), g, sol)
    call hs_solution_summary(sol, b)
    call expect(b%regime == HS_REGIME_SAME_SIGN .and. abs(b%b1 - b%b2) < 1e-14_c_double .and. &
                b%b1 > 0.6_c_double .and. b%b1 < 1, 'flat punch 0.6: centred stick zone')
    call hs_solution_free(sol)

    unit = 1
    call hs_solve_callback(sc, hertz_p, sol, user=c_loc(unit), ierr=ierr)
    call expect_code(ierr, HS_OK, 'callback pressure')
    call hs_solution_summary(sol, b)
    call expect_near(b%b1, a%b1, 1e-12_c_double, 'callback Hertz: b1')
    call expect_near(b%b2, a%b2, 1e-12_c_double, 'callback Hertz: b2')
    call expect_near(b%p0, 1.0_c_double, 1e-13_c_double, 'callback Hertz: p0 from the pressure')
    call hs_eval_Bx(sol, 1, x1, B1)   ! evaluation calls back into Fortran
    call expect_near(B1(1), B2(1), 1e-9_c_double, 'callback Hertz: Bx')
    call hs_solution_free(sol)

    do i = 1, 41
      xs(i) = -cos(pi * (i - 1) / 40)
      ps(i) = hertz_p(xs(i), c_loc(unit))
    end do
    xs(1) = -1
    xs(41) = 1
    call hs_solve_samples(sc, 41, xs, ps, sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'sampled pressure')
    call hs_solution_summary(sol, b)
    call expect_near(b%b1, a%b1, 1e-10_c_double, 'samples of Hertz: b1')
    call expect_near(b%b2, a%b2, 1e-10_c_double, 'samples of Hertz: b2')
    call hs_solution_free(sol)

    ! bad geometries
    ps(21) = -1
    call hs_solve_samples(sc, 41, xs, ps, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'negative sample')
    call hs_solve_samples(sc, 3, xs, ps, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'too few samples')
    call hs_solve_callback(sc, negative_p, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'negative callback pressure')
    call expect(.not. hs_associated(sol), 'handle untouched by failed geometry solves')
    g%kind = HS_GEOMETRY_FLAT_ROUNDED
    g%flat_over_a = 1
    call hs_solve_geometry(sc, g, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'flat_over_a = 1')
    g%kind = HS_GEOMETRY_POWER_LAW
    g%exponent = 1
    call hs_solve_geometry(sc, g, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'exponent = 1')
    g%kind = 42
    call hs_solve_geometry(sc, g, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'unknown geometry kind')
    g%struct_size = 0
    call hs_solve_geometry(sc, g, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_STRUCT_SIZE, 'geometry struct_size')
    call hs_geometry_default(g)
    g%kind = HS_GEOMETRY_POWER_LAW
    g%exponent = 3
    call hs_solve_geometry(scene_qs(1.0_c_double, 0.0_c_double), g, sol, ierr=ierr)
    call expect_code(ierr, HS_ERR_GROSS_SLIDING, 'power law: gross sliding')
    call hs_solution_free(hz)
  end subroutine test_geometries

  subroutine test_reference()
    type(hs_ref_scene_t) :: rs, rd, rg
    type(hs_ref_solution_t) :: rsol, rsol2
    type(hs_ref_summary) :: rsm
    type(hs_scene) :: sc
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    character(len=:), allocatable :: v, v200, bx
    integer :: ierr, cd, many
    real(c_double) :: b1
    call expect(hs_ref_max_digits() >= 60, 'hs_ref_max_digits')
    rs%Q_over_fP = '0.3'
    rs%sigma_over_fp0 = '2'
    call hs_ref_solve(rs, 30, rsol, ierr)
    call expect_code(ierr, HS_OK, 'reference solve at 30 digits')
    call hs_ref_solution_summary(rsol, rsm, ierr)
    call expect_code(ierr, HS_OK, 'reference summary')
    call expect(rsm%regime == HS_REGIME_OPPOSITE_SIGN .and. rsm%digits == 30 .and. rsm%working_digits >= 40 &
                .and. rsm%slip_dir1 == -1, 'reference summary values')
    cd = -1
    call hs_ref_value(rsol, HS_REF_B1, v, cd, ierr)
    call expect_code(ierr, HS_OK, 'reference b1')
    call expect(index(v, '7.490583629689906330026357657') == 1, 'reference b1 digits: ' // v)
    call expect(cd == 30, 'reference b1 certified to 30 digits')
    read (v, *) b1
    call expect_near(b1, 0.749058362968991_c_double, 1e-15_c_double, 'reference b1 read back')
    call hs_ref_eval(rsol, HS_REF_EVAL_BX, '0.9', bx, cd, ierr)
    call expect_code(ierr, HS_OK, 'reference Bx')
    call expect(bx(1:1) == '-' .and. cd == 30, 'reference Bx in zone 1 is negative')
    v = 'unchanged'
    call hs_ref_eval(rsol, HS_REF_EVAL_BX, '1.5', v, cd, ierr)
    call expect_code(ierr, HS_ERR_POINT_OUTSIDE, 'reference point outside')
    call expect(v == 'unchanged', 'reference value untouched on error')
    call hs_ref_eval(rsol, HS_REF_EVAL_BX, '0.9q', v, cd, ierr)
    call expect_code(ierr, HS_ERR_BAD_NUMBER, 'reference bad number')
    call hs_ref_value(rsol, 99, v, cd, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference unknown quantity')
    ! traction and stresses (issue 15) against the double path: 1e-12 of f p0 = 1, its accuracy
    ! away from the surface layer (docs/fields.md)
    block
      type(hs_solution_t) :: dsol
      real(c_double) :: xq(1), qd(1), xs(1), ys(1), sd(3, 1), val
      integer :: c
      call hs_solve(scene_qs(0.3_c_double, 2.0_c_double), dsol, ierr=ierr)
      call expect_code(ierr, HS_OK, 'double solve for the reference fields')
      xq(1) = -0.25_c_double
      call hs_eval_traction(dsol, 1, xq, qd, ierr)
      call hs_ref_eval(rsol, HS_REF_EVAL_TRACTION, '-0.25', v, cd, ierr)
      call expect_code(ierr, HS_OK, 'reference traction')
      read (v, *) val
      call expect(cd == 30, 'reference traction certified to 30 digits')
      call expect_near(val, qd(1), 1e-12_c_double, 'reference traction = double')
      xs(1) = 0.3_c_double
      ys(1) = -0.5_c_double
      call hs_eval_stress(dsol, 2, 1, xs, ys, sd, 0.5_c_double, ierr)
      do c = HS_STRESS_XX, HS_STRESS_XY
        call hs_ref_eval_stress(rsol, 2, c, '0.3', '-0.5', v, cd, ierr, pad_bulk='0.5')
        call expect_code(ierr, HS_OK, 'reference stress in the pad')
        read (v, *) val
        call expect(cd == 30, 'reference stress certified to 30 digits')
        call expect_near(val, sd(c, 1), 1e-12_c_double, 'reference stress = double')
      end do
      call hs_solution_free(dsol)
    end block
    v = 'unchanged'
    call hs_ref_eval_stress(rsol, 1, HS_STRESS_XX, '0.3', '-0.5', v, cd, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference stress: y on the pad side for body 1')
    call expect(v == 'unchanged', 'reference stress untouched on error')
    call hs_ref_eval_stress(rsol, 1, HS_STRESS_XX, '0.3', '0.5', v, cd, ierr, pad_bulk='0.5x')
    call expect_code(ierr, HS_ERR_BAD_NUMBER, 'reference stress: bad pad_bulk')
    call hs_ref_eval_stress(rsol, 1, HS_STRESS_VON_MISES, '0.3', '0.5', v, cd, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference stress: not a component')
    call hs_ref_solution_free(rsol)
    call expect(.not. hs_associated(rsol), 'reference free resets the handle')

    ! many digits (200, or fewer with a short precision ladder): the string
    ! outgrows the wrappers' first 64-byte buffer (resize path)
    many = min(200, hs_ref_max_digits())
    call hs_ref_solve(rs, many, rsol, ierr)
    call expect_code(ierr, HS_OK, 'reference solve at many digits')
    call hs_ref_value(rsol, HS_REF_B1, v200, cd, ierr)
    call expect_code(ierr, HS_OK, 'reference b1 at many digits')
    call expect(len(v200) > max(many, 64) .and. v200(1:31) == '7.49058362968990633002635765716' &
                .and. cd == many, 'reference b1 at many digits extends the 30-digit value')
    call hs_ref_solution_free(rsol)

    ! bad inputs
    call hs_ref_solve(rs, 0, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference digits = 0')
    call hs_ref_solve(rs, hs_ref_max_digits() + 1, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference digits too many')
    rs%Q_over_fP = 'abc'
    call hs_ref_solve(rs, 30, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_NUMBER, 'reference unparsable ratio')
    rs%Q_over_fP = '1'
    call hs_ref_solve(rs, 30, rsol, ierr)
    call expect_code(ierr, HS_ERR_GROSS_SLIDING, 'reference gross sliding')
    rs%Q_over_fP = '0.3'
    rs%f = '-1'
    call hs_ref_solve(rs, 30, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_FRICTION, 'reference f < 0')
    call expect(.not. hs_associated(rsol), 'reference handle untouched on error')
    rd%P = '1000'
    call hs_ref_solve(rd, 30, rsol2, ierr)
    call expect_code(ierr, HS_ERR_NULL_POINTER, 'reference P without R, Q, sigma')

    ! dimensional input agrees with the double solve of the same loads
    rd%R = '0.05'
    rd%E_star = '1.15e11'
    rd%f = '0.6'
    rd%Q = '300'
    rd%sigma = '2e6'
    call hs_ref_solve(rd, 30, rsol2, ierr)
    call expect_code(ierr, HS_OK, 'reference dimensional solve')
    call hs_ref_value(rsol2, HS_REF_B1, v, cd, ierr)
    read (v, *) b1
    call hs_scene_from_hertz_loads(1000.0_c_double, 0.05_c_double, 1.15e11_c_double, 0.6_c_double, &
                                   300.0_c_double, 2e6_c_double, sc)
    call hs_solve(sc, sol)
    call hs_solution_summary(sol, sm)
    call expect_near(b1, sm%b1, 4e-16_c_double * sm%a, 'reference and double b1 agree (dimensional)')
    call hs_solution_free(sol)
    call hs_ref_solution_free(rsol2)

    ! flat punch with rounded corners (value of the double solve: 0.89398873667117629)
    ! and the power law n = 2, which is Hertz
    rg%geometry = HS_GEOMETRY_FLAT_ROUNDED
    rg%flat_over_a = '0.3'
    rg%Q_over_fP = '0.3'
    rg%sigma_over_fp0 = '0.1'
    call hs_ref_solve(rg, 25, rsol, ierr)
    call expect_code(ierr, HS_OK, 'reference flat punch')
    call hs_ref_value(rsol, HS_REF_B1, v, cd, ierr)
    call expect(index(v, '8.9398873667117622057218') == 1 .and. cd == 25, 'reference flat punch b1: ' // v)
    call hs_ref_solution_free(rsol)
    rg%geometry = HS_GEOMETRY_POWER_LAW
    rg%exponent = '2'
    rg%Q_over_fP = '0.5'
    rg%sigma_over_fp0 = '0.5'
    call hs_ref_solve(rg, 25, rsol, ierr)
    call expect_code(ierr, HS_OK, 'reference power law')
    call hs_ref_value(rsol, HS_REF_B1, v, cd, ierr)
    call expect(index(v, '8.321067811865475244008444') == 1, 'reference power law n = 2 is Hertz: ' // v)
    call hs_ref_solution_free(rsol)
    rg%exponent = '1'
    call hs_ref_solve(rg, 25, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_GEOMETRY, 'reference power law n = 1')
    rg%exponent = '2x'
    call hs_ref_solve(rg, 25, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_NUMBER, 'reference power law n not a number')
    rg%exponent = '3'
    call hs_ref_solve(rg, hs_ref_max_digits_geometry(HS_GEOMETRY_POWER_LAW) + 1, rsol, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'reference power law above its digit cap')
    call expect(.not. hs_associated(rsol), 'reference handle untouched on error (geometry)')
    call expect(hs_ref_max_digits_geometry(HS_GEOMETRY_FLAT_ROUNDED) >= min(100, hs_ref_max_digits()) .and. &
                hs_ref_max_digits_geometry(HS_GEOMETRY_SAMPLES) == 0, 'hs_ref_max_digits_geometry')
  end subroutine test_reference

  ! Load histories (since 0.4): Mindlin unloading, the steady cycle of a
  ! symmetric proportional loading, the ramp flag, errors through ierr.
  subroutine test_history()
    type(hs_scene) :: sc
    type(hs_history_t) :: hist
    type(hs_history_options) :: ho
    type(hs_history_vertex) :: v0, v1, v
    type(hs_cycle_summary) :: cs
    type(hs_steady_cycle) :: cyc
    real(c_double) :: emono(2)
    type(hs_solution_t) :: sol
    real(c_double) :: x(2), q(2), h(2), E(2), c, at
    real(c_double) :: qs(2), ss(2)
    type(hs_solution_t) :: st, st2, m6, m2, m0
    real(c_double) :: px(4), py(4), s(3, 4), s6(3, 4), s2(3, 4), s0(3, 4), q2(2)
    logical :: recedes
    integer :: ierr, n
    character(len=:), allocatable :: why
    real(c_double) :: qbad(1), sbad(1)

    ! loading to Q = 0.6 fP, then unloading to 0.2 fP (sigma = 0): stick zone
    ! |x| < c', c'/a = sqrt(1 - (0.6 - 0.2)/2) (default max_step 1/128)
    call hs_scene_default(sc)
    call expect(.not. hs_associated(hist), 'history handle starts null')
    call hs_history_new(sc, hist, ierr=ierr)
    call expect_code(ierr, HS_OK, 'hs_history_new')
    call expect(hs_associated(hist), 'history handle set')
    qs = [0.6_c_double, 0.2_c_double]
    ss = 0
    call hs_history_add_vertices(hist, 2, qs, ss, ierr)
    call expect_code(ierr, HS_OK, 'history: add vertices')
    n = -1
    call hs_history_vertex_count(hist, n, ierr)
    call expect(ierr == HS_OK .and. n == 2, 'history: vertex count')
    n = -1
    call hs_history_method(hist, n, ierr)
    call expect(ierr == HS_OK .and. n == HS_HISTORY_SUPERPOSITION, 'history: method along one ray')
    ! the library's reason for a failed call (hs_history_last_error); '' after a success
    call hs_history_last_error(hist, why, ierr)
    call expect(ierr == HS_OK .and. len(why) == 0, 'history: no reason after a success')
    qbad = 1
    sbad = 0
    call hs_history_add_vertices(hist, 1, qbad, sbad, ierr)
    call expect_code(ierr, HS_ERR_GROSS_SLIDING, 'history: a vertex at Q = fP')
    call hs_history_last_error(hist, why, ierr)
    call expect(ierr == HS_OK .and. index(why, 'gross sliding') > 0, 'history: the reason names it: ' // why)
    call hs_history_vertex_get(hist, 0, v0, ierr)
    call expect_code(ierr, HS_OK, 'history: vertex 0')
    call hs_history_vertex_get(hist, 1, v1)
    call expect(v0%Q_over_fP == 0.6_c_double .and. v1%Q_over_fP == 0.2_c_double .and. v1%cycle == 0, &
                'history: vertex loads')
    ! a path along one ray: superposition of the closed forms (no march), to rounding
    call expect_near(v0%b1, sqrt(0.4_c_double), 4 * epsilon(c), 'history: loaded stick zone')
    c = sqrt(1 - 0.4_c_double / 2)
    call expect_near(v1%b1, c, 4 * epsilon(c), 'history: unloaded stick zone b1')
    call expect_near(v1%b2, c, 4 * epsilon(c), 'history: unloaded stick zone b2')
    call expect(v0%slip_dir1 == 1 .and. v0%slip_dir2 == 1 .and. v1%slip_dir1 == -1 .and. v1%slip_dir2 == -1, &
                'history: slip directions reverse on unloading')
    call expect(v1%steps == 0 .and. v0%steps == 0 .and. v1%energy1 > 0, 'history: no steps, energy')
    x = [0.0_c_double, 0.95_c_double]
    call hs_history_eval(hist, 1, HS_FIELD_TRACTION, 2, x, q, ierr)
    call expect_code(ierr, HS_OK, 'history: traction')
    call expect_near(q(1), 2 * c - 1 - sqrt(0.4_c_double), 1e-5_c_double, 'history: traction in the stick zone')
    call expect_near(q(2), -sqrt(1 - 0.95_c_double**2), 1e-7_c_double, 'history: traction in the slip zone')
    call hs_history_eval(hist, 1, HS_FIELD_SLIP, 2, x, h, ierr)
    call expect(ierr == HS_OK .and. h(1) == 0 .and. h(2) > 0, 'history: locked-in slip')
    ! issue 15: the state as a solution handle. By Ciavarella-Jager its stresses are
    ! S(0.6) - 2 S(0.2) + 2 S(0) of monotonic solutions (closed forms); a path along one
    ! ray is that superposition (the march, compared in tests/test_history.cpp, is good to
    ! ~1e-8 f p0): rounding of the sums only
    call hs_history_state(hist, 1, st, ierr)
    call expect_code(ierr, HS_OK, 'history state')
    call hs_solve(scene_qs(0.6_c_double, 0.0_c_double), m6)
    call hs_solve(scene_qs(0.2_c_double, 0.0_c_double), m2)
    call hs_solve(scene_qs(0.0_c_double, 0.0_c_double), m0)
    px = [-1.3_c_double, -0.5_c_double, 0.3_c_double, 0.7_c_double]
    py = [0.0_c_double, 0.2_c_double, 0.05_c_double, 0.0_c_double]
    call hs_eval_stress(st, 1, 4, px, py, s, ierr=ierr)
    call expect_code(ierr, HS_OK, 'history state: stress')
    call hs_eval_stress(m6, 1, 4, px, py, s6)
    call hs_eval_stress(m2, 1, 4, px, py, s2)
    call hs_eval_stress(m0, 1, 4, px, py, s0)
    call expect(maxval(abs(s - (s6 - 2 * s2 + 2 * s0))) < 1e-13_c_double, 'history state: Ciavarella-Jager stresses')
    call hs_eval_traction(st, 2, x, q2, ierr)
    call hs_history_eval(hist, 1, HS_FIELD_TRACTION, 2, x, q, ierr)
    call expect(all(q2 == q), 'history state: traction = hs_history_eval')
    call hs_solution_energy(st, E, ierr)
    call expect_code(ierr, HS_ERR_NOT_APPLICABLE, 'history state: no monotonic energies')
    call hs_history_state(hist, 2, st2, ierr)
    call expect(ierr == HS_ERR_BAD_OPTION .and. .not. hs_associated(st2), 'history state: vertex out of range')
    call hs_history_state(hist, -1, st2, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history state: negative vertex')
    call hs_solution_free(m6)
    call hs_solution_free(m2)
    call hs_solution_free(m0)
    ! errors: outputs untouched, the vertices before a failing one kept
    q = 42
    x(2) = 1.5_c_double
    call hs_history_eval(hist, 1, HS_FIELD_TRACTION, 2, x, q, ierr)
    call expect_code(ierr, HS_ERR_POINT_OUTSIDE, 'history: point outside')
    call expect(all(q == 42), 'history: output untouched on error')
    call hs_history_eval(hist, 2, HS_FIELD_SLIP, 1, x, q, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history: vertex out of range')
    call hs_history_eval(hist, 1, 7, 1, x, q, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history: unknown field')
    v = v1
    call hs_history_vertex_get(hist, 5, v, ierr)
    call expect(ierr == HS_ERR_BAD_OPTION .and. v%Q_over_fP == v1%Q_over_fP, 'history: vertex get out of range')
    qs = [0.5_c_double, 1.0_c_double]
    call hs_history_add_vertices(hist, 2, qs, ss, ierr)
    call expect_code(ierr, HS_ERR_GROSS_SLIDING, 'history: |Q| >= fP')
    call hs_history_vertex_count(hist, n)
    call expect(n == 3, 'history: vertices before the failing one kept')
    call hs_history_cycle_summary(hist, cs, ierr)
    call expect_code(ierr, HS_ERR_NOT_APPLICABLE, 'history: no cycles yet')
    call hs_history_slip_range(hist, 1, x, q, ierr)
    call expect_code(ierr, HS_ERR_NOT_APPLICABLE, 'history: slip range without cycles')
    call hs_history_free(hist)
    call expect(.not. hs_associated(hist), 'history free resets the handle')
    call hs_eval_stress(st, 1, 4, px, py, s6, ierr=ierr)
    call expect(ierr == HS_OK .and. all(s6 == s), 'history state outlives the history')
    call hs_solution_free(st)
    call hs_history_free(hist)   ! null handle: no-op
    call hs_history_vertex_count(hist, n, ierr)
    call expect_code(ierr, HS_ERR_NULL_POINTER, 'history: null handle')

    ! symmetric proportional cycle between +(0.5, 0.4) and -(0.5, 0.4): each
    ! zone dissipates 4 times its monotonic energy at (0.5, 0.4) per cycle
    call hs_solve(scene_qs(0.5_c_double, 0.4_c_double), sol)
    call hs_solution_energy(sol, E)
    call hs_solution_free(sol)
    call hs_history_options_default(ho)
    call hs_history_new(sc, hist, opts=ho, ierr=ierr)
    call expect_code(ierr, HS_OK, 'hs_history_new with options')
    call hs_history_add_cycles(hist, 0.0_c_double, 0.5_c_double, 0.0_c_double, 0.4_c_double, 0.0_c_double, 3, ierr)
    call expect_code(ierr, HS_OK, 'history: add cycles')
    call hs_history_cycle_summary(hist, cs, ierr)
    call expect_code(ierr, HS_OK, 'history: cycle summary')
    call expect(cs%cycles == 3 .and. cs%shakedown == 0, 'history: cycles computed, no shakedown')
    call expect_near(cs%energy_per_cycle1, 4 * E(1), 1e-4_c_double * 4 * E(1), 'history: energy per cycle, zone 1')
    call expect_near(cs%energy_per_cycle2, 4 * E(2), 1e-4_c_double * 4 * E(2), 'history: energy per cycle, zone 2')
    x = [0.0_c_double, 0.99_c_double]
    call hs_history_slip_range(hist, 2, x, h, ierr)
    call expect(ierr == HS_OK .and. h(1) == 0 .and. h(2) > 0, 'history: slip range')
    call hs_history_add_cycles(hist, 0.0_c_double, 0.5_c_double, 0.0_c_double, 0.4_c_double, 0.0_c_double, 0, ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history: zero cycles')
    call hs_history_free(hist)
    ! cycles_to_steady, "the first cycle that the next repeats": cycle 1 starts
    ! with the first loading from zero, so it is cycle 2. (With the default
    ! steady_rtol = 1e-9 it is not reached in 3 cycles: the stick-zone ends
    ! drift by ~3e-8 a cycle at max_step 1/128.)
    ho%steady_rtol = 1e-8_c_double
    call hs_history_new(sc, hist, opts=ho)
    call hs_history_add_cycles(hist, 0.0_c_double, 0.5_c_double, 0.0_c_double, 0.4_c_double, 0.0_c_double, 3)
    call hs_history_cycle_summary(hist, cs)
    call expect_code(int(cs%cycles_to_steady), 2, 'history: cycles to steady')
    call hs_history_free(hist)

    ! bad contacts and options
    ho%max_step = 0
    call hs_history_new(sc, hist, opts=ho, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history: max_step = 0')
    call hs_history_options_default(ho)
    ho%ramp_order = 3
    call hs_history_new(sc, hist, opts=ho, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'history: unknown ramp order')
    sc%f = 0
    call hs_history_new(sc, hist, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_FRICTION, 'history: f = 0')
    call expect(.not. hs_associated(hist), 'history handle untouched on error')

    ! the ramp flag: the ray sigma = 3Q to (0.88, 2.64) makes a zone recede near Q = 0.46 fP
    call hs_solve(scene_qs(0.88_c_double, 2.64_c_double), sol)
    recedes = .false.
    at = 0
    call hs_solution_ramp(sol, recedes, at, ierr)
    call expect_code(ierr, HS_OK, 'hs_solution_ramp')
    call expect(recedes .and. at > 0.44_c_double .and. at < 0.48_c_double, 'ramp recedes near Q = 0.46')
    call hs_solution_free(sol)
    call hs_solve(scene_qs(0.5_c_double, 0.5_c_double), sol)
    recedes = .true.
    call hs_solution_ramp(sol, recedes, at)
    call expect(.not. recedes .and. ieee_is_nan(at), 'ramp does not recede at (0.5, 0.5); NaN')
    call hs_solution_free(sol)
    call hs_solution_ramp(sol, recedes, at, ierr)
    call expect_code(ierr, HS_ERR_NULL_POINTER, 'hs_solution_ramp: null handle')
    ! the closed-form steady proportional cycle: 4 E_mono per cycle; invalid on a receding ray
    call hs_solve(scene_qs(0.5_c_double, 0.4_c_double), sol)
    call hs_solution_steady_cycle(sol, cyc, ierr)
    call expect_code(ierr, HS_OK, 'hs_solution_steady_cycle')
    call hs_solution_energy(sol, emono)
    call expect(cyc%valid == 1 .and. cyc%cycles_to_steady == 1 .and. &
                cyc%energy_per_cycle1 == 4 * emono(1), 'steady cycle: valid, 4 E_mono')
    call hs_solution_free(sol)
    call hs_solve(scene_qs(0.88_c_double, 2.64_c_double), sol)
    call hs_solution_steady_cycle(sol, cyc)
    call expect(cyc%valid == 0, 'steady cycle: not valid where the ramp recedes')
    call hs_solution_free(sol)
  end subroutine test_history

  ! Issue 15: traction and stresses through the wrappers, against closed forms
  ! written here (Hertz, a = p0 = f = E* = 1): the same-sign traction
  ! q = sqrt(1 - x^2) - sqrt((b1 - x)(x + b2)); the surface sigma_xx outside the
  ! contact of semi-ellipses, (1/pi) int sqrt(c^2 - (t-e)^2)/(x - t) dt =
  ! (x - e) - sgn(x - e) sqrt((x - e)^2 - c^2); the peak 2 sqrt(Q/fP) at x = -a
  ! (sigma = 0); McEwen's stresses on the axis x = 0 when stuck; the integral of
  ! q (= Q) in the opposite-sign regime by the midpoint rule in x = sin(theta).
  subroutine test_fields()
    real(c_double), parameter :: tol = 64 * epsilon(1.0_c_double)
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    real(c_double) :: x(5), q(5), sx(5), sx2(5), s(3, 5), y(5), ext(5), c, z, want, Qsum, th, xx(1), qq(1)
    integer :: ierr, i, m
    ! same sign, sigma = 0: b1 = b2 = c = sqrt(1 - Q/fP)
    call hs_solve(scene_qs(0.36_c_double, 0.0_c_double), sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: solve')
    call hs_solution_summary(sol, sm)
    c = sm%b1
    x = [-0.95_c_double, -0.3_c_double, 0.0_c_double, 0.5_c_double, 0.85_c_double]
    call hs_eval_traction(sol, 5, x, q, ierr)
    call expect_code(ierr, HS_OK, 'fields: traction')
    do i = 1, 5
      want = sqrt(1 - x(i)**2)
      if (abs(x(i)) < c) want = want - sqrt((c - x(i)) * (c + x(i)))
      call expect_near(q(i), want, tol, 'fields: same-sign traction (closed form)')
    end do
    ! surface sigma_xx outside the contact: body 1 = -(2/pi) int q/(x - t), body 2 = +
    x = [-3.0_c_double, -1.5_c_double, -1.0001_c_double, 1.2_c_double, 2.5_c_double]
    call hs_eval_surface_stress(sol, 1, 5, x, sx, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: surface stress')
    call hs_eval_surface_stress(sol, 2, 5, x, sx2, bulk2=0.25_c_double)
    do i = 1, 5
      want = -2 * ((x(i) - sign(sqrt(x(i)**2 - 1), x(i))) - (x(i) - sign(sqrt(x(i)**2 - c**2), x(i))))
      call expect_near(sx(i), want, 1e-13_c_double, 'fields: surface sigma_xx outside (semi-ellipses)')
      call expect_near(sx2(i), 0.25_c_double - want, 1e-13_c_double, 'fields: body 2 and its bulk stress')
    end do
    ! the peak at the trailing edge x = -a: 2 f p0 sqrt(Q/fP)
    call hs_surface_stress_extremes(sol, 1, ext, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: extremes')
    call expect_near(ext(1), 2 * sqrt(0.36_c_double), 1e-12_c_double, 'fields: peak 2 sqrt(Q/fP)')
    call expect_near(ext(2), -1.0_c_double, 1e-6_c_double, 'fields: peak at x = -a')
    call expect(ext(5) == 0, 'fields: bulk of body 1 (sigma = 0)')
    ! on the surface hs_eval_stress gives (sigma_xx, -p, -q)
    x = [-0.95_c_double, -0.3_c_double, 0.0_c_double, 0.5_c_double, 0.85_c_double]
    y = 0
    call hs_eval_stress(sol, 1, 5, x, y, s, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: stress')
    call hs_eval_surface_stress(sol, 1, 5, x, sx)
    call hs_eval_traction(sol, 5, x, q)
    do i = 1, 5
      call expect_near(s(1, i), sx(i), tol, 'fields: stress at y = 0 is the surface sigma_xx')
      call expect_near(s(2, i), -sqrt(1 - x(i)**2), tol, 'fields: sigma_yy = -p on the surface')
      call expect_near(s(3, i), -q(i), tol, 'fields: sigma_xy = -q on the surface')
    end do
    ! bad input: specific codes, outputs untouched
    s = 42
    call hs_eval_stress(sol, 3, 5, x, y, s, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'fields: body 3')
    y(2) = -0.5_c_double
    call hs_eval_stress(sol, 1, 5, x, y, s, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'fields: point outside body 1')
    call expect(all(s == 42), 'fields: output untouched on error')
    call hs_eval_surface_stress(sol, 1, 5, x, sx, bulk2=ieee_value(c, ieee_quiet_nan), ierr=ierr)
    call expect_code(ierr, HS_ERR_NOT_FINITE, 'fields: NaN bulk stress')
    call hs_surface_stress_extremes(sol, 1, ext, half_range=ieee_value(c, ieee_positive_inf), ierr=ierr)
    call expect_code(ierr, HS_ERR_NOT_FINITE, 'fields: infinite half range')
    ! the scalars against the components (x, y inside body 1)
    x = [-1.5_c_double, -0.9_c_double, 0.0_c_double, 0.4_c_double, 1.0_c_double]
    y = [0.5_c_double, 0.05_c_double, 0.3_c_double, 1.0_c_double, 1e-6_c_double]
    call hs_eval_stress(sol, 1, 5, x, y, s)
    call hs_eval_stress_scalar(sol, 1, HS_STRESS_VON_MISES, 5, x, y, sx, nu=0.25_c_double, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: stress scalar')
    call hs_eval_stress_scalar(sol, 1, HS_STRESS_MAX_SHEAR, 5, x, y, sx2)
    do i = 1, 5
      z = 0.25_c_double * (s(1, i) + s(2, i))   ! sigma_zz
      want = sqrt(((s(1, i) - s(2, i))**2 + (s(2, i) - z)**2 + (z - s(1, i))**2) / 2 + 3 * s(3, i)**2)
      call expect_near(sx(i), want, tol, 'fields: von Mises (plane strain)')
      call expect_near(sx2(i), sqrt(((s(1, i) - s(2, i)) / 2)**2 + s(3, i)**2), tol, 'fields: maximum shear')
    end do
    call hs_eval_stress_scalar(sol, 1, HS_STRESS_XY, 5, x, y, sx)
    call expect(all(sx == s(3, :)), 'fields: scalar sigma_xy is the component')
    sx = 42
    call hs_eval_stress_scalar(sol, 1, 99, 5, x, y, sx, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'fields: unknown stress quantity')
    call hs_eval_stress_scalar(sol, 1, HS_STRESS_VON_MISES, 5, x, y, sx, nu=0.7_c_double, ierr=ierr)
    call expect_code(ierr, HS_ERR_BAD_OPTION, 'fields: Poisson ratio above 1/2')
    call expect(all(sx == 42), 'fields: scalar output untouched on error')
    call hs_solution_free(sol)

    ! stuck (Q = sigma = 0): McEwen on the axis, sigma_xx = -((1 + 2z^2)/sqrt(1 + z^2) - 2z),
    ! sigma_yy = -1/sqrt(1 + z^2), sigma_xy = 0
    call hs_solve(scene_qs(0.0_c_double, 0.0_c_double), sol, ierr=ierr)
    call expect_code(ierr, HS_OK, 'fields: stuck solve')
    x = 0
    y = [0.01_c_double, 0.3_c_double, 0.78_c_double, 1.0_c_double, 4.0_c_double]
    call hs_eval_stress(sol, 1, 5, x, y, s)
    do i = 1, 5
      z = y(i)
      call expect_near(s(1, i), -((1 + 2 * z**2) / sqrt(1 + z**2) - 2 * z), 1e-14_c_double, 'fields: McEwen sigma_xx')
      call expect_near(s(2, i), -1 / sqrt(1 + z**2), 1e-14_c_double, 'fields: McEwen sigma_yy')
      call expect_near(s(3, i), 0.0_c_double, 1e-14_c_double, 'fields: McEwen sigma_xy')
    end do
    call hs_solution_free(sol)

    ! opposite sign (quadrature path): int q dx = Q/fP (f P = pi/2 here), midpoint
    ! rule in x = sin(theta); q has square roots at the stick boundaries, where the
    ! rule's error is O(h^1.5) = (pi/4000)^1.5 = 2.2e-5 (measured 2.9e-6)
    call hs_solve(scene_qs(0.3_c_double, 2.0_c_double), sol, ierr=ierr)
    call hs_solution_summary(sol, sm)
    call expect(sm%regime == HS_REGIME_OPPOSITE_SIGN, 'fields: opposite-sign regime')
    m = 4000
    Qsum = 0
    do i = 1, m
      th = -pi / 2 + pi * (i - 0.5_c_double) / m
      xx(1) = sin(th)
      call hs_eval_traction(sol, 1, xx, qq)
      Qsum = Qsum + qq(1) * cos(th) * pi / m
    end do
    call expect_near(Qsum / (pi / 2), 0.3_c_double, 2.2e-5_c_double, 'fields: opposite-sign int q = Q')
    call hs_solution_free(sol)
  end subroutine test_fields

  ! issue 16: hs_solve_batch against one hs_solve per scene, bitwise, with the
  ! failing scene's own status
  subroutine test_batch()
    type(hs_scene) :: sc(4)
    type(hs_batch_result) :: res(4)
    type(hs_solution_t) :: sol
    type(hs_summary) :: sm
    real(c_double) :: e(2)
    integer :: i, ierr
    sc(1) = scene_qs(0.3_c_double, 2.0_c_double)
    sc(2) = scene_qs(-0.5_c_double, 0.1_c_double)
    sc(3) = scene_qs(1.0_c_double, 0.5_c_double)      ! gross sliding
    sc(4) = scene_qs(0.9_c_double, -3.0_c_double)
    call hs_solve_batch(sc, res, flags=HS_BATCH_ENERGIES, threads=2, ierr=ierr)
    call expect(ierr == HS_OK, 'batch: call status')
    call expect(res(3)%status == HS_ERR_GROSS_SLIDING, 'batch: per-scene status')
    do i = 1, 4
      if (i == 3) cycle
      call hs_solve(sc(i), sol)
      call hs_solution_summary(sol, sm)
      call hs_solution_energy(sol, e)
      call expect(res(i)%status == HS_OK .and. res(i)%regime == sm%regime .and. res(i)%b1 == sm%b1 .and. &
                  res(i)%b2 == sm%b2 .and. res(i)%d1 == sm%d1 .and. res(i)%d2 == sm%d2 .and. &
                  res(i)%energy1 == e(1) .and. res(i)%energy2 == e(2), 'batch: equal to one solve per scene')
      call hs_solution_free(sol)
    end do
    call hs_solve_batch(sc, res, threads=-1, ierr=ierr)
    call expect(ierr == HS_ERR_BAD_OPTION, 'batch: threads < 0')
  end subroutine test_batch

end program test_fortran
