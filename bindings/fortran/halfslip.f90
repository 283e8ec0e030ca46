! halfslip: Fortran 2003 bindings to the C ABI (capi/include/halfslip/halfslip.h).
!
! Conventions of this module:
! - The C functions are reached through private bind(c) interfaces (c_hs_*);
!   the public wrappers keep the C names (hs_solve, hs_eval_Bx, ...).
! - Every wrapper that can fail has an optional last argument ierr. When it
!   is present, it receives the status (HS_OK or an HS_ERR_* code) and the
!   caller decides. When it is absent and the call fails, the wrapper prints
!   "halfslip: <function>: <hs_strerror message>" on the error unit and
!   executes error stop.
! - On error, outputs are left untouched (as in C): output arguments are
!   intent(inout) for that reason.
! - Handles are type(c_ptr) inside hs_solution_t / hs_ref_solution_t /
!   hs_history_t, which start as C_NULL_PTR. Release them with
!   hs_solution_free / hs_ref_solution_free / hs_history_free (which reset
!   them to C_NULL_PTR). A solution handle is immutable after the solve and
!   may be evaluated from several threads; a history grows with each
!   hs_history_add_* call.
! - History vertices are numbered as in C, from 0 to count - 1.
! - Arrays of points are explicit-shape real(c_double) arrays x(n), out(n),
!   passed straight to the C pointers: no copy is made.
! - The status codes, regimes and quantity selectors are integer(c_int)
!   parameters with the values of the C header (checked by the test suite).
! The Fortran standard used is 2008 (error stop, c_sizeof); the interop itself
! is Fortran 2003.
module halfslip
  use, intrinsic :: iso_c_binding, only: c_int, c_long, c_double, c_size_t, c_char, c_ptr, c_funptr, &
                                         c_null_ptr, c_null_funptr, c_null_char, c_associated, c_f_pointer, &
                                         c_loc, c_funloc, c_sizeof
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  private

  ! ---- constants (same values as halfslip.h) ----------------------------------
  integer(c_int), parameter, public :: HS_VERSION_MAJOR = 0
  integer(c_int), parameter, public :: HS_VERSION_MINOR = 4
  integer(c_int), parameter, public :: HS_VERSION_PATCH = 0

  integer(c_int), parameter, public :: HS_OK                   = 0
  integer(c_int), parameter, public :: HS_ERR_NULL_POINTER     = 1
  integer(c_int), parameter, public :: HS_ERR_STRUCT_SIZE      = 2
  integer(c_int), parameter, public :: HS_ERR_NOT_FINITE       = 3
  integer(c_int), parameter, public :: HS_ERR_BAD_SIZE         = 4
  integer(c_int), parameter, public :: HS_ERR_BAD_FRICTION     = 5
  integer(c_int), parameter, public :: HS_ERR_GROSS_SLIDING    = 6
  integer(c_int), parameter, public :: HS_ERR_BAD_GEOMETRY     = 7
  integer(c_int), parameter, public :: HS_ERR_POINT_OUTSIDE    = 8
  integer(c_int), parameter, public :: HS_ERR_BUFFER_TOO_SMALL = 9
  integer(c_int), parameter, public :: HS_ERR_NO_CONVERGENCE   = 10
  integer(c_int), parameter, public :: HS_ERR_BAD_OPTION       = 11
  integer(c_int), parameter, public :: HS_ERR_OUT_OF_MEMORY    = 12
  integer(c_int), parameter, public :: HS_ERR_INTERNAL         = 13
  integer(c_int), parameter, public :: HS_ERR_OVERFLOW         = 14
  integer(c_int), parameter, public :: HS_ERR_BAD_NUMBER       = 15
  integer(c_int), parameter, public :: HS_ERR_TOLERANCE        = 16
  integer(c_int), parameter, public :: HS_ERR_NOT_APPLICABLE   = 17

  integer(c_int), parameter, public :: HS_MODEL_DEFAULT     = 0
  integer(c_int), parameter, public :: HS_MODEL_AUTO        = 1
  integer(c_int), parameter, public :: HS_MODEL_ASYMPTOTIC  = 2
  integer(c_int), parameter, public :: HS_MODEL_CLOSED_FORM = 3
  integer(c_int), parameter, public :: HS_MODEL_QUADRATURE  = 4
  integer(c_int), parameter, public :: HS_MODEL_REFERENCE   = 5

  integer(c_int), parameter, public :: HS_GEOMETRY_HERTZ        = 1
  integer(c_int), parameter, public :: HS_GEOMETRY_FLAT_ROUNDED = 2
  integer(c_int), parameter, public :: HS_GEOMETRY_POWER_LAW    = 3
  integer(c_int), parameter, public :: HS_GEOMETRY_SAMPLES      = 4
  integer(c_int), parameter, public :: HS_GEOMETRY_CALLBACK     = 5

  integer(c_int), parameter, public :: HS_LOADING_SHEAR = 1
  integer(c_int), parameter, public :: HS_LOADING_BULK  = 2

  integer(c_int), parameter, public :: HS_REGIME_STUCK         = 0
  integer(c_int), parameter, public :: HS_REGIME_SAME_SIGN     = 1
  integer(c_int), parameter, public :: HS_REGIME_OPPOSITE_SIGN = 2
  integer(c_int), parameter, public :: HS_REGIME_BOUNDARY      = 3  ! one zone below zone_resolution

  integer(c_int), parameter, public :: HS_REF_B1      = 1
  integer(c_int), parameter, public :: HS_REF_B2      = 2
  integer(c_int), parameter, public :: HS_REF_D1      = 3
  integer(c_int), parameter, public :: HS_REF_D2      = 4
  integer(c_int), parameter, public :: HS_REF_ENERGY1 = 5
  integer(c_int), parameter, public :: HS_REF_ENERGY2 = 6
  integer(c_int), parameter, public :: HS_REF_A       = 7
  integer(c_int), parameter, public :: HS_REF_P0      = 8

  integer(c_int), parameter, public :: HS_REF_EVAL_BX       = 1
  integer(c_int), parameter, public :: HS_REF_EVAL_SLIP     = 2
  integer(c_int), parameter, public :: HS_REF_EVAL_WORK     = 3
  integer(c_int), parameter, public :: HS_REF_EVAL_PRESSURE = 4
  integer(c_int), parameter, public :: HS_REF_EVAL_TRACTION = 5

  ! load histories (since 0.4)
  integer(c_int), parameter, public :: HS_RAMP_SIGMA_FIRST = 0
  integer(c_int), parameter, public :: HS_RAMP_TOGETHER    = 1
  integer(c_int), parameter, public :: HS_RAMP_Q_FIRST     = 2
  ! interior slip patches (hs_history_options%interior_patches, issue 14)
  integer(c_int), parameter, public :: HS_PATCHES_ERROR = 0
  integer(c_int), parameter, public :: HS_PATCHES_MERGE = 1
  ! how a history computes its states (hs_history_method)
  integer(c_int), parameter, public :: HS_HISTORY_SUPERPOSITION = 1
  integer(c_int), parameter, public :: HS_HISTORY_STATIC        = 2
  integer(c_int), parameter, public :: HS_HISTORY_MARCH         = 3

  integer(c_int), parameter, public :: HS_FIELD_TRACTION = 1
  integer(c_int), parameter, public :: HS_FIELD_SLIP     = 2

  ! stress scalars of hs_eval_stress_scalar
  integer(c_int), parameter, public :: HS_STRESS_XX            = 1
  integer(c_int), parameter, public :: HS_STRESS_YY            = 2
  integer(c_int), parameter, public :: HS_STRESS_XY            = 3
  integer(c_int), parameter, public :: HS_STRESS_VON_MISES     = 4
  integer(c_int), parameter, public :: HS_STRESS_MAX_PRINCIPAL = 5
  integer(c_int), parameter, public :: HS_STRESS_MIN_PRINCIPAL = 6
  integer(c_int), parameter, public :: HS_STRESS_MAX_SHEAR     = 7

  ! flags of hs_solve_batch (issue 16)
  integer(c_int), parameter, public :: HS_BATCH_ENERGIES = 1

  ! ---- plain-data structs passed to C (layouts of halfslip.h) -------------------
  ! Fill them with hs_scene_default / hs_options_default, then set fields.
  type, bind(c), public :: hs_scene
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: geometry = 0
    real(c_double)    :: a = 0, p0 = 0, f = 0, E_star = 0
    real(c_double)    :: Q_over_fP = 0, sigma_over_fp0 = 0
  end type hs_scene

  type, bind(c), public :: hs_options
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: max_iterations = 0
    real(c_double)    :: rtol = 0
    integer(c_int)    :: model = 0              ! HS_MODEL_* (since 0.3)
  end type hs_options

  ! One scene's result of hs_solve_batch (issue 16; no struct_size field).
  type, bind(c), public :: hs_batch_result
    integer(c_int) :: status = 0, regime = 0, slip_dir1 = 0, slip_dir2 = 0, model = 0, iterations = 0
    real(c_double) :: b1 = 0, b2 = 0, d1 = 0, d2 = 0, error_estimate = 0, energy1 = 0, energy2 = 0
  end type hs_batch_result

  ! Outputs: the wrappers set struct_size themselves.
  type, bind(c), public :: hs_summary
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: regime = -1, slip_dir1 = 0, slip_dir2 = 0, iterations = 0
    real(c_double)    :: a = 0, b1 = 0, b2 = 0, d1 = 0, d2 = 0
    real(c_double)    :: p0 = 0                 ! reference pressure 2P/(pi a) used
    integer(c_int)    :: quadrature_order = 0   ! Gauss-Legendre order per panel (0: closed forms)
    integer(c_int)    :: model = 0              ! HS_MODEL_* used (since 0.3)
    real(c_double)    :: error_estimate = 0     ! estimated largest relative error of d1, d2, E1, E2
    real(c_double)    :: zone_resolution = 0    ! absolute error bound of d1, d2 (after 0.4, issue 13)
  end type hs_summary

  ! Pressure of a non-Hertz geometry (hs_solve_geometry). Fill it with
  ! hs_geometry_default, then set kind and flat_over_a (HS_GEOMETRY_FLAT_ROUNDED)
  ! or exponent (HS_GEOMETRY_POWER_LAW). Samples and callbacks are easiest
  ! through hs_solve_samples and hs_solve_callback, which set the pointers.
  type, bind(c), public :: hs_geometry
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: kind = 0
    real(c_double)    :: flat_over_a = 0, exponent = 0
    integer(c_size_t) :: n_samples = 0
    type(c_ptr)       :: sample_x = c_null_ptr, sample_p = c_null_ptr
    type(c_funptr)    :: pressure = c_null_funptr
    type(c_ptr)       :: user = c_null_ptr
  end type hs_geometry

  ! The pressure callback of HS_GEOMETRY_CALLBACK: p(x) on (-a, a), in
  ! absolute units; user is passed through. It must be bind(c) and stay
  ! valid (and thread-safe) while the solution is used.
  abstract interface
    function hs_pressure_fn(x, user) bind(c) result(p)
      import :: c_double, c_ptr
      real(c_double), value :: x
      type(c_ptr), value :: user
      real(c_double) :: p
    end function hs_pressure_fn
  end interface
  public :: hs_pressure_fn

  type, bind(c), public :: hs_ref_summary
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: regime = -1, slip_dir1 = 0, slip_dir2 = 0, iterations = 0
    integer(c_int)    :: digits = 0, working_digits = 0, check_digits = 0
  end type hs_ref_summary

  ! Load histories (since 0.4). Fill the options with hs_history_options_default,
  ! then set fields. The vertex and the cycle summary are outputs: the wrappers
  ! set their struct_size themselves.
  type, bind(c), public :: hs_history_options
    integer(c_size_t) :: struct_size = 0
    real(c_double)    :: max_step = 0            ! largest load step (default 1/32)
    integer(c_int)    :: max_steps = 0           ! limit on the total number of steps
    integer(c_int)    :: segments_per_cycle = 0  ! chords per out-of-phase cycle
    integer(c_int)    :: ramp_order = 0          ! HS_RAMP_*
    real(c_double)    :: steady_rtol = 0         ! steady-cycle tolerance
    real(c_double)    :: rtol = 0                ! march refined until steps h and 2h agree to rtol
    integer(c_int)    :: interior_patches = 0    ! HS_PATCHES_ERROR (default) or HS_PATCHES_MERGE
  end type hs_history_options

  type, bind(c), public :: hs_history_vertex
    integer(c_size_t) :: struct_size = 0
    real(c_double)    :: Q_over_fP = 0, sigma_over_fp0 = 0
    real(c_double)    :: b1 = 0, b2 = 0          ! stick zone (-b2, b1)
    integer(c_int)    :: slip_dir1 = 0, slip_dir2 = 0  ! +1, -1, or 0 where that edge does not slip
    real(c_double)    :: energy1 = 0, energy2 = 0      ! over the segment ending here
    integer(c_int)    :: cycle = 0               ! 0: path or ramp; k >= 1: k-th cycle
    integer(c_long)   :: steps = 0               ! load steps marched up to this vertex
    real(c_double)    :: step = 0                ! load step after refinement
    real(c_double)    :: error_estimate = 0      ! estimated error (halfslip.h: hs_history_vertex)
    integer(c_long)   :: interior_merges = 0     ! interior slip patches merged so far
    integer(c_int)    :: patch_dir = 0           ! interior slip zone open at the vertex: +1, -1; 0: none
    real(c_double)    :: patch_l = 0, patch_r = 0  ! its ends
    real(c_double)    :: energy_patch = 0        ! dissipated in interior slip zones over the segment
  end type hs_history_vertex

  type, bind(c), public :: hs_cycle_summary
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: cycles = 0, cycles_to_steady = -1, shakedown = 0
    real(c_double)    :: energy_per_cycle1 = 0, energy_per_cycle2 = 0
    real(c_double)    :: energy_per_cycle_patch = 0  ! in interior slip zones
    integer(c_int)    :: cycles_repeated = 0       ! cycles copied from a steady one (session 21)
    real(c_double)    :: repeated_change = 0       ! that cycle's change of the state
  end type hs_cycle_summary

  type, bind(c), public :: hs_steady_cycle
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: valid = 0, cycles_to_steady = 1
    real(c_double)    :: energy_per_cycle1 = 0, energy_per_cycle2 = 0
  end type hs_steady_cycle

  ! ---- handles ------------------------------------------------------------------
  type, public :: hs_solution_t
    type(c_ptr) :: ptr = c_null_ptr
  end type hs_solution_t

  type, public :: hs_ref_solution_t
    type(c_ptr) :: ptr = c_null_ptr
  end type hs_ref_solution_t

  type, public :: hs_history_t
    type(c_ptr) :: ptr = c_null_ptr
  end type hs_history_t

  ! Reference-backend scene: decimal strings. An unallocated component means
  ! the C default ("1" for a, p0, f, E_star; "0.5" for the two ratios). When P
  ! is allocated, the dimensional input P, R, Q, sigma (all required) is used
  ! instead of a, p0 and the ratios (Hertz only). geometry HS_GEOMETRY_FLAT_ROUNDED
  ! reads flat_over_a (b_f/a, default "0.5"), HS_GEOMETRY_POWER_LAW reads
  ! exponent (n, default "2"); at most hs_ref_max_digits_geometry(geometry) digits.
  type, public :: hs_ref_scene_t
    integer(c_int) :: geometry = HS_GEOMETRY_HERTZ
    character(len=:), allocatable :: a, p0, f, E_star, Q_over_fP, sigma_over_fp0
    character(len=:), allocatable :: P, R, Q, sigma
    character(len=:), allocatable :: flat_over_a, exponent
  end type hs_ref_scene_t

  ! The C layout of hs_ref_scene (private: built from hs_ref_scene_t).
  type, bind(c) :: c_hs_ref_scene
    integer(c_size_t) :: struct_size = 0
    integer(c_int)    :: geometry = 0
    type(c_ptr)       :: a = c_null_ptr, p0 = c_null_ptr, f = c_null_ptr, E_star = c_null_ptr
    type(c_ptr)       :: Q_over_fP = c_null_ptr, sigma_over_fp0 = c_null_ptr
    type(c_ptr)       :: P = c_null_ptr, R = c_null_ptr, Q = c_null_ptr, sigma = c_null_ptr
    type(c_ptr)       :: flat_over_a = c_null_ptr, exponent = c_null_ptr  ! since 0.3
  end type c_hs_ref_scene

  ! A NUL-terminated copy of a Fortran string, kept alive during a C call.
  type :: c_string
    character(kind=c_char), allocatable :: s(:)
  end type c_string

  public :: hs_version, hs_version_string, hs_strerror
  public :: hs_model_name, hs_model_from_name
  public :: hs_scene_default, hs_scene_from_hertz_loads, hs_options_default
  public :: hs_scene_from_power_law_loads, hs_scene_from_flat_rounded_loads
  public :: hs_solve, hs_solution_free, hs_solution_summary, hs_solution_energy, hs_solve_batch
  public :: hs_geometry_default, hs_solve_geometry, hs_solve_samples, hs_solve_callback
  public :: hs_eval_Bx, hs_eval_slip, hs_eval_work, hs_eval_pressure
  public :: hs_eval_traction, hs_eval_surface_stress, hs_eval_stress, hs_surface_stress_extremes
  public :: hs_eval_stress_scalar
  public :: hs_ref_max_digits, hs_ref_max_digits_geometry, hs_ref_solve, hs_ref_solution_free
  public :: hs_ref_solution_summary
  public :: hs_ref_value, hs_ref_eval, hs_ref_eval_stress
  public :: hs_solution_ramp, hs_solution_steady_cycle
  public :: hs_history_options_default, hs_history_new, hs_history_free, hs_history_add_vertices
  public :: hs_history_last_error
  public :: hs_history_add_cycles, hs_history_vertex_count, hs_history_vertex_get, hs_history_eval
  public :: hs_history_method
  public :: hs_history_cycle_summary, hs_history_slip_range, hs_history_state
  public :: hs_associated

  interface hs_associated
    module procedure solution_associated, ref_solution_associated, history_associated
  end interface hs_associated

  ! ---- the C ABI ----------------------------------------------------------------
  interface
    function c_strlen(s) bind(c, name="strlen") result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: n
    end function c_strlen

    function c_hs_version(major, minor, patch) bind(c, name="hs_version") result(st)
      import :: c_int
      integer(c_int), intent(inout) :: major, minor, patch
      integer(c_int) :: st
    end function c_hs_version

    function c_hs_version_string() bind(c, name="hs_version_string") result(s)
      import :: c_ptr
      type(c_ptr) :: s
    end function c_hs_version_string

    function c_hs_strerror(status) bind(c, name="hs_strerror") result(s)
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: s
    end function c_hs_strerror

    function c_hs_model_name(model) bind(c, name="hs_model_name") result(s)
      import :: c_int, c_ptr
      integer(c_int), value :: model
      type(c_ptr) :: s
    end function c_hs_model_name

    function c_hs_model_from_name(name, model) bind(c, name="hs_model_from_name") result(st)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: name(*)
      integer(c_int), intent(inout) :: model
      integer(c_int) :: st
    end function c_hs_model_from_name

    function c_hs_scene_default(scene) bind(c, name="hs_scene_default") result(st)
      import :: c_int, hs_scene
      type(hs_scene), intent(inout) :: scene
      integer(c_int) :: st
    end function c_hs_scene_default

    function c_hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, scene) &
        bind(c, name="hs_scene_from_hertz_loads") result(st)
      import :: c_int, c_double, hs_scene
      real(c_double), value :: P, R, E_star, f, Q, sigma
      type(hs_scene), intent(inout) :: scene
      integer(c_int) :: st
    end function c_hs_scene_from_hertz_loads

    function c_hs_scene_from_power_law_loads(P, A, n, E_star, f, Q, sigma, scene) &
        bind(c, name="hs_scene_from_power_law_loads") result(st)
      import :: c_int, c_double, hs_scene
      real(c_double), value :: P, A, n, E_star, f, Q, sigma
      type(hs_scene), intent(inout) :: scene
      integer(c_int) :: st
    end function c_hs_scene_from_power_law_loads

    function c_hs_scene_from_flat_rounded_loads(P, R, flat_width, E_star, f, Q, sigma, scene, flat_over_a) &
        bind(c, name="hs_scene_from_flat_rounded_loads") result(st)
      import :: c_int, c_double, hs_scene
      real(c_double), value :: P, R, flat_width, E_star, f, Q, sigma
      type(hs_scene), intent(inout) :: scene
      real(c_double), intent(inout) :: flat_over_a
      integer(c_int) :: st
    end function c_hs_scene_from_flat_rounded_loads

    function c_hs_options_default(opts) bind(c, name="hs_options_default") result(st)
      import :: c_int, hs_options
      type(hs_options), intent(inout) :: opts
      integer(c_int) :: st
    end function c_hs_options_default

    function c_hs_solve(scene, opts, out) bind(c, name="hs_solve") result(st)
      import :: c_int, c_ptr, hs_scene
      type(hs_scene), intent(in) :: scene
      type(c_ptr), value :: opts     ! const hs_options * (may be NULL)
      type(c_ptr), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_solve

    function c_hs_geometry_default(geometry) bind(c, name="hs_geometry_default") result(st)
      import :: c_int, hs_geometry
      type(hs_geometry), intent(inout) :: geometry
      integer(c_int) :: st
    end function c_hs_geometry_default

    function c_hs_solve_geometry(scene, geometry, opts, out) bind(c, name="hs_solve_geometry") result(st)
      import :: c_int, c_ptr, hs_scene, hs_geometry
      type(hs_scene), intent(in) :: scene
      type(hs_geometry), intent(in) :: geometry
      type(c_ptr), value :: opts     ! const hs_options * (may be NULL)
      type(c_ptr), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_solve_geometry

    subroutine c_hs_solution_free(sol) bind(c, name="hs_solution_free")
      import :: c_ptr
      type(c_ptr), value :: sol
    end subroutine c_hs_solution_free

    function c_hs_solution_summary(sol, out) bind(c, name="hs_solution_summary") result(st)
      import :: c_int, c_ptr, hs_summary
      type(c_ptr), value :: sol
      type(hs_summary), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_solution_summary

    function c_hs_solve_batch(n, scenes, opts, flags, threads, out, result_size) &
        bind(c, name="hs_solve_batch") result(st)
      import :: c_int, c_ptr, c_size_t, hs_scene, hs_batch_result
      integer(c_size_t), value :: n
      type(hs_scene), intent(in) :: scenes(*)
      type(c_ptr), value :: opts     ! const hs_options * (may be NULL)
      integer(c_int), value :: flags, threads
      type(hs_batch_result), intent(inout) :: out(*)
      integer(c_size_t), value :: result_size
      integer(c_int) :: st
    end function c_hs_solve_batch

    function c_hs_solution_energy(sol, energy) bind(c, name="hs_solution_energy") result(st)
      import :: c_int, c_ptr, c_double
      type(c_ptr), value :: sol
      real(c_double), intent(inout) :: energy(2)
      integer(c_int) :: st
    end function c_hs_solution_energy

    ! hs_eval_Bx, hs_eval_slip, hs_eval_work, hs_eval_pressure share one shape.
    function c_hs_eval_Bx(sol, n, x, out) bind(c, name="hs_eval_Bx") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_Bx

    function c_hs_eval_slip(sol, n, x, out) bind(c, name="hs_eval_slip") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_slip

    function c_hs_eval_work(sol, n, x, out) bind(c, name="hs_eval_work") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_work

    function c_hs_eval_pressure(sol, n, x, out) bind(c, name="hs_eval_pressure") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_pressure

    function c_hs_eval_traction(sol, n, x, out) bind(c, name="hs_eval_traction") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_traction

    function c_hs_eval_surface_stress(sol, body, bulk2, n, x, out) bind(c, name="hs_eval_surface_stress") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_int), value :: body
      real(c_double), value :: bulk2
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_surface_stress

    function c_hs_eval_stress(sol, body, bulk2, n, x, y, out) bind(c, name="hs_eval_stress") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_int), value :: body
      real(c_double), value :: bulk2
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*), y(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_stress

    function c_hs_eval_stress_scalar(sol, body, bulk2, quantity, nu, n, x, y, out) &
        bind(c, name="hs_eval_stress_scalar") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: sol
      integer(c_int), value :: body, quantity
      real(c_double), value :: bulk2, nu
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*), y(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_eval_stress_scalar

    function c_hs_surface_stress_extremes(sol, body, bulk2, half_range, out) &
        bind(c, name="hs_surface_stress_extremes") result(st)
      import :: c_int, c_ptr, c_double
      type(c_ptr), value :: sol
      integer(c_int), value :: body
      real(c_double), value :: bulk2, half_range
      real(c_double), intent(inout) :: out(5)
      integer(c_int) :: st
    end function c_hs_surface_stress_extremes

    function c_hs_ref_scene_default(scene) bind(c, name="hs_ref_scene_default") result(st)
      import :: c_int, c_hs_ref_scene
      type(c_hs_ref_scene), intent(inout) :: scene
      integer(c_int) :: st
    end function c_hs_ref_scene_default

    function c_hs_ref_max_digits() bind(c, name="hs_ref_max_digits") result(n)
      import :: c_int
      integer(c_int) :: n
    end function c_hs_ref_max_digits

    function c_hs_ref_max_digits_geometry(geometry) bind(c, name="hs_ref_max_digits_geometry") result(n)
      import :: c_int
      integer(c_int), value :: geometry
      integer(c_int) :: n
    end function c_hs_ref_max_digits_geometry

    function c_hs_ref_solve(scene, digits, out) bind(c, name="hs_ref_solve") result(st)
      import :: c_int, c_ptr, c_hs_ref_scene
      type(c_hs_ref_scene), intent(in) :: scene
      integer(c_int), value :: digits
      type(c_ptr), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_ref_solve

    subroutine c_hs_ref_solution_free(sol) bind(c, name="hs_ref_solution_free")
      import :: c_ptr
      type(c_ptr), value :: sol
    end subroutine c_hs_ref_solution_free

    function c_hs_ref_solution_summary(sol, out) bind(c, name="hs_ref_solution_summary") result(st)
      import :: c_int, c_ptr, hs_ref_summary
      type(c_ptr), value :: sol
      type(hs_ref_summary), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_ref_solution_summary

    function c_hs_ref_value(sol, quantity, buf, size, needed, certified) &
        bind(c, name="hs_ref_value") result(st)
      import :: c_int, c_ptr, c_size_t, c_char
      type(c_ptr), value :: sol
      integer(c_int), value :: quantity
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: size
      integer(c_size_t), intent(inout) :: needed
      integer(c_int), intent(inout) :: certified
      integer(c_int) :: st
    end function c_hs_ref_value

    function c_hs_ref_eval(sol, what, x, buf, size, needed, certified) &
        bind(c, name="hs_ref_eval") result(st)
      import :: c_int, c_ptr, c_size_t, c_char
      type(c_ptr), value :: sol
      integer(c_int), value :: what
      character(kind=c_char), intent(in) :: x(*)
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: size
      integer(c_size_t), intent(inout) :: needed
      integer(c_int), intent(inout) :: certified
      integer(c_int) :: st
    end function c_hs_ref_eval

    function c_hs_ref_eval_stress(sol, body, bulk2, component, x, y, buf, size, needed, certified) &
        bind(c, name="hs_ref_eval_stress") result(st)
      import :: c_int, c_ptr, c_size_t, c_char
      type(c_ptr), value :: sol
      integer(c_int), value :: body, component
      character(kind=c_char), intent(in) :: bulk2(*), x(*), y(*)
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: size
      integer(c_size_t), intent(inout) :: needed
      integer(c_int), intent(inout) :: certified
      integer(c_int) :: st
    end function c_hs_ref_eval_stress

    function c_hs_solution_ramp(sol, recedes, at_Q_over_fP) bind(c, name="hs_solution_ramp") result(st)
      import :: c_int, c_ptr, c_double
      type(c_ptr), value :: sol
      integer(c_int), intent(inout) :: recedes
      real(c_double), intent(inout) :: at_Q_over_fP
      integer(c_int) :: st
    end function c_hs_solution_ramp

    function c_hs_solution_steady_cycle(sol, out) bind(c, name="hs_solution_steady_cycle") result(st)
      import :: c_int, c_ptr, hs_steady_cycle
      type(c_ptr), value :: sol
      type(hs_steady_cycle), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_solution_steady_cycle

    function c_hs_history_options_default(opts) bind(c, name="hs_history_options_default") result(st)
      import :: c_int, hs_history_options
      type(hs_history_options), intent(inout) :: opts
      integer(c_int) :: st
    end function c_hs_history_options_default

    function c_hs_history_new(scene, geometry, opts, out) bind(c, name="hs_history_new") result(st)
      import :: c_int, c_ptr, hs_scene
      type(hs_scene), intent(in) :: scene
      type(c_ptr), value :: geometry ! const hs_geometry * (may be NULL)
      type(c_ptr), value :: opts     ! const hs_history_options * (may be NULL)
      type(c_ptr), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_history_new

    subroutine c_hs_history_free(h) bind(c, name="hs_history_free")
      import :: c_ptr
      type(c_ptr), value :: h
    end subroutine c_hs_history_free

    function c_hs_history_add_vertices(h, n, Q_over_fP, sigma_over_fp0) &
        bind(c, name="hs_history_add_vertices") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: h
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: Q_over_fP(*), sigma_over_fp0(*)
      integer(c_int) :: st
    end function c_hs_history_add_vertices

    function c_hs_history_add_cycles(h, Qm, Qa, Sm, Sa, phase_deg, cycles) &
        bind(c, name="hs_history_add_cycles") result(st)
      import :: c_int, c_ptr, c_double
      type(c_ptr), value :: h
      real(c_double), value :: Qm, Qa, Sm, Sa, phase_deg
      integer(c_int), value :: cycles
      integer(c_int) :: st
    end function c_hs_history_add_cycles

    function c_hs_history_last_error(h, buf, size) bind(c, name="hs_history_last_error") result(st)
      import :: c_int, c_ptr, c_size_t, c_char
      type(c_ptr), value :: h
      character(kind=c_char), intent(inout) :: buf(*)
      integer(c_size_t), value :: size
      integer(c_int) :: st
    end function c_hs_history_last_error

    function c_hs_history_method(h, m) bind(c, name="hs_history_method") result(st)
      import :: c_int, c_ptr
      type(c_ptr), value :: h
      integer(c_int), intent(inout) :: m
      integer(c_int) :: st
    end function c_hs_history_method

    function c_hs_history_vertex_count(h, n) bind(c, name="hs_history_vertex_count") result(st)
      import :: c_int, c_ptr, c_size_t
      type(c_ptr), value :: h
      integer(c_size_t), intent(inout) :: n
      integer(c_int) :: st
    end function c_hs_history_vertex_count

    function c_hs_history_vertex_get(h, i, out) bind(c, name="hs_history_vertex_get") result(st)
      import :: c_int, c_ptr, c_size_t, hs_history_vertex
      type(c_ptr), value :: h
      integer(c_size_t), value :: i
      type(hs_history_vertex), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_history_vertex_get

    function c_hs_history_eval(h, vertex, field, n, x, out) bind(c, name="hs_history_eval") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: h
      integer(c_size_t), value :: vertex
      integer(c_int), value :: field
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_history_eval

    function c_hs_history_state(h, vertex, out) bind(c, name="hs_history_state") result(st)
      import :: c_int, c_ptr, c_size_t
      type(c_ptr), value :: h
      integer(c_size_t), value :: vertex
      type(c_ptr), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_history_state

    function c_hs_history_cycle_summary(h, out) bind(c, name="hs_history_cycle_summary") result(st)
      import :: c_int, c_ptr, hs_cycle_summary
      type(c_ptr), value :: h
      type(hs_cycle_summary), intent(inout) :: out
      integer(c_int) :: st
    end function c_hs_history_cycle_summary

    function c_hs_history_slip_range(h, n, x, out) bind(c, name="hs_history_slip_range") result(st)
      import :: c_int, c_ptr, c_size_t, c_double
      type(c_ptr), value :: h
      integer(c_size_t), value :: n
      real(c_double), intent(in) :: x(*)
      real(c_double), intent(inout) :: out(*)
      integer(c_int) :: st
    end function c_hs_history_slip_range
  end interface

contains

  ! ---- helpers --------------------------------------------------------------------

  ! Report status: into ierr when present, else stop on error with the message.
  subroutine check(st, fname, ierr)
    integer(c_int), intent(in) :: st
    character(len=*), intent(in) :: fname
    integer, intent(out), optional :: ierr
    if (present(ierr)) then
      ierr = int(st)
    else if (st /= HS_OK) then
      write (error_unit, '(a)') 'halfslip: ' // fname // ': ' // hs_strerror(int(st))
      error stop
    end if
  end subroutine check

  ! Fortran copy of a NUL-terminated C string ('' for NULL).
  function from_c(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer(c_size_t) :: n, i
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    n = c_strlen(p)
    call c_f_pointer(p, chars, [n])
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = chars(i)
    end do
  end function from_c

  ! NUL-terminated copy of a Fortran string (trailing blanks are kept).
  subroutine to_c(s, cs)
    character(len=*), intent(in) :: s
    character(kind=c_char), allocatable, intent(inout) :: cs(:)
    integer :: i
    if (allocated(cs)) deallocate (cs)
    allocate (cs(len(s) + 1))
    do i = 1, len(s)
      cs(i) = s(i:i)
    end do
    cs(len(s) + 1) = c_null_char
  end subroutine to_c

  ! Fortran copy of the first n characters of a C buffer.
  function buf_to_f(buf, n) result(s)
    character(kind=c_char), intent(in) :: buf(:)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    integer :: i
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = buf(i)
    end do
  end function buf_to_f

  ! Point to an optional string component's C copy (NULL if unallocated).
  subroutine set_c_string(src, store, p)
    character(len=:), allocatable, intent(in) :: src
    type(c_string), target, intent(inout) :: store
    type(c_ptr), intent(out) :: p
    if (allocated(src)) then
      call to_c(src, store%s)
      p = c_loc(store%s)
    else
      p = c_null_ptr
    end if
  end subroutine set_c_string

  logical function solution_associated(sol)
    type(hs_solution_t), intent(in) :: sol
    solution_associated = c_associated(sol%ptr)
  end function solution_associated

  logical function ref_solution_associated(sol)
    type(hs_ref_solution_t), intent(in) :: sol
    ref_solution_associated = c_associated(sol%ptr)
  end function ref_solution_associated

  logical function history_associated(hist)
    type(hs_history_t), intent(in) :: hist
    history_associated = c_associated(hist%ptr)
  end function history_associated

  ! ---- version and messages ---------------------------------------------------------

  ! Version of the library actually loaded.
  subroutine hs_version(major, minor, patch, ierr)
    integer, intent(out) :: major, minor, patch
    integer, intent(out), optional :: ierr
    integer(c_int) :: ma, mi, pa, st
    ma = 0
    mi = 0
    pa = 0
    st = c_hs_version(ma, mi, pa)
    if (st == HS_OK) then
      major = int(ma)
      minor = int(mi)
      patch = int(pa)
    end if
    call check(st, 'hs_version', ierr)
  end subroutine hs_version

  function hs_version_string() result(s)
    character(len=:), allocatable :: s
    s = from_c(c_hs_version_string())
  end function hs_version_string

  ! The message of a status code (the C library's one table).
  function hs_strerror(status) result(msg)
    integer, intent(in) :: status
    character(len=:), allocatable :: msg
    msg = from_c(c_hs_strerror(int(status, c_int)))
  end function hs_strerror

  ! Name of a model, HS_MODEL_* ('closed-form', ...; '' for another value):
  ! the C library's table, as the command line spells the names.
  function hs_model_name(model) result(name)
    integer, intent(in) :: model
    character(len=:), allocatable :: name
    name = from_c(c_hs_model_name(int(model, c_int)))
  end function hs_model_name

  ! HS_MODEL_* of a name (exact match, trailing blanks ignored); model is
  ! untouched on error (HS_ERR_BAD_OPTION: unknown name).
  subroutine hs_model_from_name(name, model, ierr)
    character(len=*), intent(in) :: name
    integer, intent(inout) :: model
    integer, intent(out), optional :: ierr
    character(kind=c_char), allocatable :: cs(:)
    integer(c_int) :: m, st
    call to_c(trim(name), cs)
    m = int(model, c_int)
    st = c_hs_model_from_name(cs, m)
    if (st == HS_OK) model = int(m)
    call check(st, 'hs_model_from_name', ierr)
  end subroutine hs_model_from_name

  ! ---- scenes and options ----------------------------------------------------------------

  ! Defaults: Hertz, a = p0 = f = E* = 1, Q/fP = 0.5, sigma/fp0 = 0.5.
  subroutine hs_scene_default(scene, ierr)
    type(hs_scene), intent(inout) :: scene
    integer, intent(out), optional :: ierr
    call check(c_hs_scene_default(scene), 'hs_scene_default', ierr)
  end subroutine hs_scene_default

  subroutine hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, scene, ierr)
    real(c_double), intent(in) :: P, R, E_star, f, Q, sigma
    type(hs_scene), intent(inout) :: scene
    integer, intent(out), optional :: ierr
    call check(c_hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, scene), &
               'hs_scene_from_hertz_loads', ierr)
  end subroutine hs_scene_from_hertz_loads

  ! Power-law profile g = A|x|^n under the load P (solve with exponent n).
  subroutine hs_scene_from_power_law_loads(P, A, n, E_star, f, Q, sigma, scene, ierr)
    real(c_double), intent(in) :: P, A, n, E_star, f, Q, sigma
    type(hs_scene), intent(inout) :: scene
    integer, intent(out), optional :: ierr
    call check(c_hs_scene_from_power_law_loads(P, A, n, E_star, f, Q, sigma, scene), &
               'hs_scene_from_power_law_loads', ierr)
  end subroutine hs_scene_from_power_law_loads

  ! Flat punch of half-width flat_width with corner radius R; also returns b_f/a.
  subroutine hs_scene_from_flat_rounded_loads(P, R, flat_width, E_star, f, Q, sigma, scene, flat_over_a, ierr)
    real(c_double), intent(in) :: P, R, flat_width, E_star, f, Q, sigma
    type(hs_scene), intent(inout) :: scene
    real(c_double), intent(inout) :: flat_over_a
    integer, intent(out), optional :: ierr
    call check(c_hs_scene_from_flat_rounded_loads(P, R, flat_width, E_star, f, Q, sigma, scene, flat_over_a), &
               'hs_scene_from_flat_rounded_loads', ierr)
  end subroutine hs_scene_from_flat_rounded_loads

  subroutine hs_options_default(opts, ierr)
    type(hs_options), intent(inout) :: opts
    integer, intent(out), optional :: ierr
    call check(c_hs_options_default(opts), 'hs_options_default', ierr)
  end subroutine hs_options_default

  ! ---- double-precision solve -----------------------------------------------------------

  ! Solve scene into sol (a new handle; free it with hs_solution_free). sol must
  ! not hold a live handle: it is overwritten on success, untouched on error.
  subroutine hs_solve(scene, sol, opts, ierr)
    type(hs_scene), intent(in) :: scene
    type(hs_solution_t), intent(inout) :: sol
    type(hs_options), intent(in), target, optional :: opts
    integer, intent(out), optional :: ierr
    type(c_ptr) :: h, po
    integer(c_int) :: st
    h = c_null_ptr
    po = c_null_ptr
    if (present(opts)) po = c_loc(opts)
    st = c_hs_solve(scene, po, h)
    if (st == HS_OK) sol%ptr = h
    call check(st, 'hs_solve', ierr)
  end subroutine hs_solve

  ! Solve size(scenes) Hertz scenes on `threads` threads (default 0: one per
  ! core); results(i) is bitwise what hs_solve + hs_solution_summary (+
  ! hs_solution_energy with flags = HS_BATCH_ENERGIES) give for scenes(i), with
  ! the scene's own status in results(i)%status. ierr: the call's status.
  subroutine hs_solve_batch(scenes, results, opts, flags, threads, ierr)
    type(hs_scene), intent(in) :: scenes(:)
    type(hs_batch_result), intent(inout) :: results(:)
    type(hs_options), intent(in), target, optional :: opts
    integer, intent(in), optional :: flags, threads
    integer, intent(out), optional :: ierr
    type(c_ptr) :: po
    integer(c_int) :: fl, nt
    type(hs_batch_result) :: probe
    if (size(results) < size(scenes)) then
      call check(HS_ERR_BUFFER_TOO_SMALL, 'hs_solve_batch', ierr)
      return
    end if
    po = c_null_ptr
    if (present(opts)) po = c_loc(opts)
    fl = 0
    if (present(flags)) fl = int(flags, c_int)
    nt = 0
    if (present(threads)) nt = int(threads, c_int)
    call check(c_hs_solve_batch(size(scenes, kind=c_size_t), scenes, po, fl, nt, results, c_sizeof(probe)), &
               'hs_solve_batch', ierr)
  end subroutine hs_solve_batch

  ! Defaults: Hertz, flat_over_a = 0.5, exponent = 2, no samples, no callback.
  subroutine hs_geometry_default(geometry, ierr)
    type(hs_geometry), intent(inout) :: geometry
    integer, intent(out), optional :: ierr
    call check(c_hs_geometry_default(geometry), 'hs_geometry_default', ierr)
  end subroutine hs_geometry_default

  ! Solve scene with the pressure of geometry (numerical Cauchy-kernel
  ! inversion; HS_GEOMETRY_HERTZ uses the closed forms). sol as in hs_solve.
  subroutine hs_solve_geometry(scene, geometry, sol, opts, ierr)
    type(hs_scene), intent(in) :: scene
    type(hs_geometry), intent(in) :: geometry
    type(hs_solution_t), intent(inout) :: sol
    type(hs_options), intent(in), target, optional :: opts
    integer, intent(out), optional :: ierr
    type(c_ptr) :: h, po
    integer(c_int) :: st
    h = c_null_ptr
    po = c_null_ptr
    if (present(opts)) po = c_loc(opts)
    st = c_hs_solve_geometry(scene, geometry, po, h)
    if (st == HS_OK) sol%ptr = h
    call check(st, 'hs_solve_geometry', ierr)
  end subroutine hs_solve_geometry

  ! Pressure samples p(i) at x(i), i = 1..n (n >= 6, x increasing over
  ! [-a, a], p vanishing like a square root at both edges, absolute units).
  ! The library copies them: they need not outlive the call.
  subroutine hs_solve_samples(scene, n, x, p, sol, opts, ierr)
    type(hs_scene), intent(in) :: scene
    integer, intent(in) :: n
    real(c_double), intent(in), target :: x(n), p(n)
    type(hs_solution_t), intent(inout) :: sol
    type(hs_options), intent(in), optional :: opts
    integer, intent(out), optional :: ierr
    type(hs_geometry) :: g
    integer(c_int) :: st
    st = c_hs_geometry_default(g)
    if (st == HS_OK) then
      g%kind = HS_GEOMETRY_SAMPLES
      g%n_samples = int(max(n, 0), c_size_t)
      if (n > 0) then
        g%sample_x = c_loc(x)
        g%sample_p = c_loc(p)
      end if
      call hs_solve_geometry(scene, g, sol, opts, ierr)
    else
      call check(st, 'hs_solve_samples', ierr)
    end if
  end subroutine hs_solve_samples

  ! Pressure given by a bind(c) function p(x, user) (absolute units). The
  ! function must stay valid while the solution is used; user is passed
  ! through (C_NULL_PTR when absent).
  subroutine hs_solve_callback(scene, pressure, sol, user, opts, ierr)
    type(hs_scene), intent(in) :: scene
    procedure(hs_pressure_fn) :: pressure
    type(hs_solution_t), intent(inout) :: sol
    type(c_ptr), intent(in), optional :: user
    type(hs_options), intent(in), optional :: opts
    integer, intent(out), optional :: ierr
    type(hs_geometry) :: g
    integer(c_int) :: st
    st = c_hs_geometry_default(g)
    if (st == HS_OK) then
      g%kind = HS_GEOMETRY_CALLBACK
      g%pressure = c_funloc(pressure)
      if (present(user)) g%user = user
      call hs_solve_geometry(scene, g, sol, opts, ierr)
    else
      call check(st, 'hs_solve_callback', ierr)
    end if
  end subroutine hs_solve_callback

  ! Release the handle (no-op for a null handle) and reset it to C_NULL_PTR.
  subroutine hs_solution_free(sol)
    type(hs_solution_t), intent(inout) :: sol
    call c_hs_solution_free(sol%ptr)
    sol%ptr = c_null_ptr
  end subroutine hs_solution_free

  subroutine hs_solution_summary(sol, summary, ierr)
    type(hs_solution_t), intent(in) :: sol
    type(hs_summary), intent(inout) :: summary
    integer, intent(out), optional :: ierr
    type(hs_summary) :: tmp
    integer(c_int) :: st
    tmp%struct_size = c_sizeof(tmp)
    st = c_hs_solution_summary(sol%ptr, tmp)
    if (st == HS_OK) summary = tmp
    call check(st, 'hs_solution_summary', ierr)
  end subroutine hs_solution_summary

  ! energy(1): zone 1 (b1, a); energy(2): zone 2 (-a, -b2).
  subroutine hs_solution_energy(sol, energy, ierr)
    type(hs_solution_t), intent(in) :: sol
    real(c_double), intent(inout) :: energy(2)
    integer, intent(out), optional :: ierr
    call check(c_hs_solution_energy(sol%ptr, energy), 'hs_solution_energy', ierr)
  end subroutine hs_solution_energy

  ! Point evaluations: out(i) at x(i), i = 1..n, |x(i)| <= a. No copies.
  subroutine hs_eval_Bx(sol, n, x, out, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_eval_Bx(sol%ptr, int(max(n, 0), c_size_t), x, out), 'hs_eval_Bx', ierr)
  end subroutine hs_eval_Bx

  subroutine hs_eval_slip(sol, n, x, out, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_eval_slip(sol%ptr, int(max(n, 0), c_size_t), x, out), 'hs_eval_slip', ierr)
  end subroutine hs_eval_slip

  subroutine hs_eval_work(sol, n, x, out, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_eval_work(sol%ptr, int(max(n, 0), c_size_t), x, out), 'hs_eval_work', ierr)
  end subroutine hs_eval_work

  subroutine hs_eval_pressure(sol, n, x, out, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_eval_pressure(sol%ptr, int(max(n, 0), c_size_t), x, out), 'hs_eval_pressure', ierr)
  end subroutine hs_eval_pressure

  ! ---- tractions and stresses (issue 15, docs/fields.md) ---------------------------
  ! Body 1 (the specimen) is y >= 0, body 2 (the pad) y <= 0. bulk2 is the bulk
  ! stress the pad carries (optional, default 0: the specimen carries all of sigma).

  ! Shear traction q(x(i)) that body 2 exerts on body 1 (positive in +x), |x(i)| <= a.
  subroutine hs_eval_traction(sol, n, x, out, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_eval_traction(sol%ptr, int(max(n, 0), c_size_t), x, out), 'hs_eval_traction', ierr)
  end subroutine hs_eval_traction

  ! Surface direct stress sigma_xx(x(i), 0) of body 1 or 2, on and off the contact.
  subroutine hs_eval_surface_stress(sol, body, n, x, out, bulk2, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: body, n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    real(c_double), intent(in), optional :: bulk2
    integer, intent(out), optional :: ierr
    real(c_double) :: b
    b = 0
    if (present(bulk2)) b = bulk2
    call check(c_hs_eval_surface_stress(sol%ptr, int(body, c_int), b, int(max(n, 0), c_size_t), x, out), &
               'hs_eval_surface_stress', ierr)
  end subroutine hs_eval_surface_stress

  ! Stress (sigma_xx, sigma_yy, sigma_xy) at (x(i), y(i)) into s(1:3, i);
  ! y(i) >= 0 for body 1, <= 0 for body 2.
  subroutine hs_eval_stress(sol, body, n, x, y, s, bulk2, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: body, n
    real(c_double), intent(in) :: x(n), y(n)
    real(c_double), intent(inout) :: s(3, n)
    real(c_double), intent(in), optional :: bulk2
    integer, intent(out), optional :: ierr
    real(c_double) :: b
    b = 0
    if (present(bulk2)) b = bulk2
    call check(c_hs_eval_stress(sol%ptr, int(body, c_int), b, int(max(n, 0), c_size_t), x, y, s), &
               'hs_eval_stress', ierr)
  end subroutine hs_eval_stress

  ! A scalar of the stress (quantity: HS_STRESS_*) at (x(i), y(i)) into out(i); nu
  ! (Poisson's ratio, optional, default 0.3) is used by HS_STRESS_VON_MISES only.
  subroutine hs_eval_stress_scalar(sol, body, quantity, n, x, y, out, nu, bulk2, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: body, quantity, n
    real(c_double), intent(in) :: x(n), y(n)
    real(c_double), intent(inout) :: out(n)
    real(c_double), intent(in), optional :: nu, bulk2
    integer, intent(out), optional :: ierr
    real(c_double) :: b, v
    b = 0
    v = 0.3_c_double
    if (present(bulk2)) b = bulk2
    if (present(nu)) v = nu
    call check(c_hs_eval_stress_scalar(sol%ptr, int(body, c_int), b, int(quantity, c_int), v, &
                                       int(max(n, 0), c_size_t), x, y, out), 'hs_eval_stress_scalar', ierr)
  end subroutine hs_eval_stress_scalar

  ! Extremes of sigma_xx(x, 0) of a body over |x| <= half_range (absent or <= 0: 3a):
  ! ext = [max, x_max, min, x_min, bulk].
  subroutine hs_surface_stress_extremes(sol, body, ext, bulk2, half_range, ierr)
    type(hs_solution_t), intent(in) :: sol
    integer, intent(in) :: body
    real(c_double), intent(inout) :: ext(5)
    real(c_double), intent(in), optional :: bulk2, half_range
    integer, intent(out), optional :: ierr
    real(c_double) :: b, L
    b = 0
    L = 0
    if (present(bulk2)) b = bulk2
    if (present(half_range)) L = half_range
    call check(c_hs_surface_stress_extremes(sol%ptr, int(body, c_int), b, L, ext), &
               'hs_surface_stress_extremes', ierr)
  end subroutine hs_surface_stress_extremes

  ! Whether a proportional ramp from zero to the solution's (Q, sigma) makes a
  ! slip zone recede on the way, and the Q/fP where that first happens (NaN if not).
  subroutine hs_solution_ramp(sol, recedes, at_Q_over_fP, ierr)
    type(hs_solution_t), intent(in) :: sol
    logical, intent(inout) :: recedes
    real(c_double), intent(inout) :: at_Q_over_fP
    integer, intent(out), optional :: ierr
    integer(c_int) :: r, st
    r = 0
    st = c_hs_solution_ramp(sol%ptr, r, at_Q_over_fP)
    if (st == HS_OK) recedes = r /= 0
    call check(st, 'hs_solution_ramp', ierr)
  end subroutine hs_solution_ramp

  ! Symmetric proportional cycling between +(Q, sigma) and -(Q, sigma) of the solution in
  ! closed form (Ciavarella-Jager); cycle%valid = 0 when a zone recedes on the ramp.
  subroutine hs_solution_steady_cycle(sol, cycle, ierr)
    type(hs_solution_t), intent(in) :: sol
    type(hs_steady_cycle), intent(inout) :: cycle
    integer, intent(out), optional :: ierr
    type(hs_steady_cycle) :: tmp
    integer(c_int) :: st
    tmp%struct_size = c_sizeof(tmp)
    st = c_hs_solution_steady_cycle(sol%ptr, tmp)
    if (st == HS_OK) cycle = tmp
    call check(st, 'hs_solution_steady_cycle', ierr)
  end subroutine hs_solution_steady_cycle

  ! ---- load histories (since 0.4) --------------------------------------------------------

  ! Defaults: max_step = 1/128, max_steps = 2000000, segments_per_cycle = 64,
  ! ramp_order = HS_RAMP_SIGMA_FIRST, steady_rtol = 1e-9.
  subroutine hs_history_options_default(opts, ierr)
    type(hs_history_options), intent(inout) :: opts
    integer, intent(out), optional :: ierr
    call check(c_hs_history_options_default(opts), 'hs_history_options_default', ierr)
  end subroutine hs_history_options_default

  ! A new history of the scene's contact (a, p0, f, E*; its ratios are ignored)
  ! into hist (free it with hs_history_free). Without geometry the contact is
  ! the scene's Hertz one. hist is overwritten on success, untouched on error.
  subroutine hs_history_new(scene, hist, geometry, opts, ierr)
    type(hs_scene), intent(in) :: scene
    type(hs_history_t), intent(inout) :: hist
    type(hs_geometry), intent(in), target, optional :: geometry
    type(hs_history_options), intent(in), target, optional :: opts
    integer, intent(out), optional :: ierr
    type(c_ptr) :: h, pg, po
    integer(c_int) :: st
    h = c_null_ptr
    pg = c_null_ptr
    po = c_null_ptr
    if (present(geometry)) pg = c_loc(geometry)
    if (present(opts)) po = c_loc(opts)
    st = c_hs_history_new(scene, pg, po, h)
    if (st == HS_OK) hist%ptr = h
    call check(st, 'hs_history_new', ierr)
  end subroutine hs_history_new

  ! Release the handle (no-op for a null handle) and reset it to C_NULL_PTR.
  subroutine hs_history_free(hist)
    type(hs_history_t), intent(inout) :: hist
    call c_hs_history_free(hist%ptr)
    hist%ptr = c_null_ptr
  end subroutine hs_history_free

  ! Append n vertices (Q_over_fP(i), sigma_over_fp0(i)) and march to them. On
  ! error the history keeps the vertices reached before the failing one.
  subroutine hs_history_add_vertices(hist, n, Q_over_fP, sigma_over_fp0, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(in) :: n
    real(c_double), intent(in) :: Q_over_fP(n), sigma_over_fp0(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_history_add_vertices(hist%ptr, int(max(n, 0), c_size_t), Q_over_fP, sigma_over_fp0), &
               'hs_history_add_vertices', ierr)
  end subroutine hs_history_add_vertices

  ! Q(t) = Qm + Qa sin(wt), sigma(t) = Sm + Sa sin(wt + phase), reached by the
  ! options' ramp_order, then `cycles` cycles.
  subroutine hs_history_add_cycles(hist, Qm_over_fP, Qa_over_fP, Sm_over_fp0, Sa_over_fp0, phase_deg, cycles, ierr)
    type(hs_history_t), intent(in) :: hist
    real(c_double), intent(in) :: Qm_over_fP, Qa_over_fP, Sm_over_fp0, Sa_over_fp0, phase_deg
    integer, intent(in) :: cycles
    integer, intent(out), optional :: ierr
    call check(c_hs_history_add_cycles(hist%ptr, Qm_over_fP, Qa_over_fP, Sm_over_fp0, Sa_over_fp0, phase_deg, &
                                       int(cycles, c_int)), 'hs_history_add_cycles', ierr)
  end subroutine hs_history_add_cycles

  ! Why the last hs_history_add_vertices / hs_history_add_cycles failed ('' after a success).
  subroutine hs_history_last_error(hist, message, ierr)
    type(hs_history_t), intent(in) :: hist
    character(len=:), allocatable, intent(out) :: message
    integer, intent(out), optional :: ierr
    character(kind=c_char) :: buf(512)
    integer(c_int) :: st
    integer :: n
    buf = c_null_char
    st = c_hs_history_last_error(hist%ptr, buf, int(size(buf), c_size_t))
    n = 0
    if (st == HS_OK) then
      do while (n < size(buf))
        if (buf(n + 1) == c_null_char) exit
        n = n + 1
      end do
    end if
    message = buf_to_f(buf, n)
    call check(st, 'hs_history_last_error', ierr)
  end subroutine hs_history_last_error

  ! How the history computes its states: HS_HISTORY_SUPERPOSITION, HS_HISTORY_STATIC or HS_HISTORY_MARCH.
  subroutine hs_history_method(hist, method, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(inout) :: method
    integer, intent(out), optional :: ierr
    integer(c_int) :: cm, st
    cm = 0
    st = c_hs_history_method(hist%ptr, cm)
    if (st == HS_OK) method = int(cm)
    call check(st, 'hs_history_method', ierr)
  end subroutine hs_history_method

  subroutine hs_history_vertex_count(hist, n, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(inout) :: n
    integer, intent(out), optional :: ierr
    integer(c_size_t) :: cn
    integer(c_int) :: st
    cn = 0
    st = c_hs_history_vertex_count(hist%ptr, cn)
    if (st == HS_OK) n = int(cn)
    call check(st, 'hs_history_vertex_count', ierr)
  end subroutine hs_history_vertex_count

  ! Vertex i, numbered as in C: 0 .. count - 1.
  subroutine hs_history_vertex_get(hist, i, vertex, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(in) :: i
    type(hs_history_vertex), intent(inout) :: vertex
    integer, intent(out), optional :: ierr
    type(hs_history_vertex) :: tmp
    integer(c_int) :: st
    tmp%struct_size = c_sizeof(tmp)
    st = c_hs_history_vertex_get(hist%ptr, int(i, c_size_t), tmp)
    if (st == HS_OK) vertex = tmp
    call check(st, 'hs_history_vertex_get', ierr)
  end subroutine hs_history_vertex_get

  ! Field (HS_FIELD_TRACTION or HS_FIELD_SLIP) after vertex `vertex` (0-based)
  ! at x(i), i = 1..n, |x(i)| <= a. No copies.
  subroutine hs_history_eval(hist, vertex, field, n, x, out, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(in) :: vertex, field, n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_history_eval(hist%ptr, int(vertex, c_size_t), int(field, c_int), int(max(n, 0), c_size_t), &
                                 x, out), 'hs_history_eval', ierr)
  end subroutine hs_history_eval

  ! Issue 15: the state after vertex `vertex` (0-based) as a new, read-only
  ! solution handle (free it with hs_solution_free). The stress, traction,
  ! slip, pressure and summary functions apply; hs_solution_energy, hs_eval_Bx
  ! and hs_eval_work give HS_ERR_NOT_APPLICABLE. It outlives the history.
  subroutine hs_history_state(hist, vertex, sol, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(in) :: vertex
    type(hs_solution_t), intent(inout) :: sol
    integer, intent(out), optional :: ierr
    type(c_ptr) :: h
    integer(c_int) :: st
    h = c_null_ptr
    if (vertex < 0) then
      st = HS_ERR_BAD_OPTION
    else
      st = c_hs_history_state(hist%ptr, int(vertex, c_size_t), h)
    end if
    if (st == HS_OK) sol%ptr = h
    call check(st, 'hs_history_state', ierr)
  end subroutine hs_history_state

  ! Summary of the periodic loading (HS_ERR_NOT_APPLICABLE without one).
  subroutine hs_history_cycle_summary(hist, summary, ierr)
    type(hs_history_t), intent(in) :: hist
    type(hs_cycle_summary), intent(inout) :: summary
    integer, intent(out), optional :: ierr
    type(hs_cycle_summary) :: tmp
    integer(c_int) :: st
    tmp%struct_size = c_sizeof(tmp)
    st = c_hs_history_cycle_summary(hist%ptr, tmp)
    if (st == HS_OK) summary = tmp
    call check(st, 'hs_history_cycle_summary', ierr)
  end subroutine hs_history_cycle_summary

  ! Slip range max h - min h over the vertices of the last cycle, at x(1..n).
  subroutine hs_history_slip_range(hist, n, x, out, ierr)
    type(hs_history_t), intent(in) :: hist
    integer, intent(in) :: n
    real(c_double), intent(in) :: x(n)
    real(c_double), intent(inout) :: out(n)
    integer, intent(out), optional :: ierr
    call check(c_hs_history_slip_range(hist%ptr, int(max(n, 0), c_size_t), x, out), 'hs_history_slip_range', ierr)
  end subroutine hs_history_slip_range

  ! ---- arbitrary-precision reference backend ---------------------------------------------

  integer function hs_ref_max_digits()
    hs_ref_max_digits = int(c_hs_ref_max_digits())
  end function hs_ref_max_digits

  ! Largest digits for a geometry (lower for the flat punch and the power law;
  ! 0 for a geometry the reference backend does not solve).
  integer function hs_ref_max_digits_geometry(geometry)
    integer, intent(in) :: geometry
    hs_ref_max_digits_geometry = int(c_hs_ref_max_digits_geometry(int(geometry, c_int)))
  end function hs_ref_max_digits_geometry

  ! Solve to `digits` significant digits. sol is overwritten on success.
  subroutine hs_ref_solve(scene, digits, sol, ierr)
    type(hs_ref_scene_t), intent(in) :: scene
    integer, intent(in) :: digits
    type(hs_ref_solution_t), intent(inout) :: sol
    integer, intent(out), optional :: ierr
    type(c_hs_ref_scene) :: cs
    type(c_string), target :: store(12)
    type(c_ptr) :: h
    integer(c_int) :: st
    st = c_hs_ref_scene_default(cs)
    if (st == HS_OK) then
      cs%geometry = scene%geometry
      call set_c_string(scene%a, store(1), cs%a)
      call set_c_string(scene%p0, store(2), cs%p0)
      call set_c_string(scene%f, store(3), cs%f)
      call set_c_string(scene%E_star, store(4), cs%E_star)
      call set_c_string(scene%Q_over_fP, store(5), cs%Q_over_fP)
      call set_c_string(scene%sigma_over_fp0, store(6), cs%sigma_over_fp0)
      call set_c_string(scene%P, store(7), cs%P)
      call set_c_string(scene%R, store(8), cs%R)
      call set_c_string(scene%Q, store(9), cs%Q)
      call set_c_string(scene%sigma, store(10), cs%sigma)
      call set_c_string(scene%flat_over_a, store(11), cs%flat_over_a)
      call set_c_string(scene%exponent, store(12), cs%exponent)
      h = c_null_ptr
      st = c_hs_ref_solve(cs, int(digits, c_int), h)
      if (st == HS_OK) sol%ptr = h
    end if
    call check(st, 'hs_ref_solve', ierr)
  end subroutine hs_ref_solve

  subroutine hs_ref_solution_free(sol)
    type(hs_ref_solution_t), intent(inout) :: sol
    call c_hs_ref_solution_free(sol%ptr)
    sol%ptr = c_null_ptr
  end subroutine hs_ref_solution_free

  subroutine hs_ref_solution_summary(sol, summary, ierr)
    type(hs_ref_solution_t), intent(in) :: sol
    type(hs_ref_summary), intent(inout) :: summary
    integer, intent(out), optional :: ierr
    type(hs_ref_summary) :: tmp
    integer(c_int) :: st
    tmp%struct_size = c_sizeof(tmp)
    st = c_hs_ref_solution_summary(sol%ptr, tmp)
    if (st == HS_OK) summary = tmp
    call check(st, 'hs_ref_solution_summary', ierr)
  end subroutine hs_ref_solution_summary

  ! value: the quantity (HS_REF_*) as a decimal string in scientific notation;
  ! certified: how many of its leading digits are certified.
  subroutine hs_ref_value(sol, quantity, value, certified, ierr)
    type(hs_ref_solution_t), intent(in) :: sol
    integer, intent(in) :: quantity
    character(len=:), allocatable, intent(inout) :: value
    integer, intent(out), optional :: certified
    integer, intent(out), optional :: ierr
    character(kind=c_char), allocatable :: buf(:)
    integer(c_size_t) :: needed
    integer(c_int) :: st, cd
    allocate (buf(64))
    cd = 0
    do
      needed = 0
      st = c_hs_ref_value(sol%ptr, int(quantity, c_int), buf, size(buf, kind=c_size_t), needed, cd)
      if (st /= HS_ERR_BUFFER_TOO_SMALL .or. needed <= size(buf, kind=c_size_t)) exit
      deallocate (buf)
      allocate (buf(needed))
    end do
    if (st == HS_OK) then
      value = buf_to_f(buf, int(needed) - 1)
      if (present(certified)) certified = int(cd)
    end if
    call check(st, 'hs_ref_value', ierr)
  end subroutine hs_ref_value

  ! Point evaluation (HS_REF_EVAL_*) at the decimal point x.
  subroutine hs_ref_eval(sol, what, x, value, certified, ierr)
    type(hs_ref_solution_t), intent(in) :: sol
    integer, intent(in) :: what
    character(len=*), intent(in) :: x
    character(len=:), allocatable, intent(inout) :: value
    integer, intent(out), optional :: certified
    integer, intent(out), optional :: ierr
    character(kind=c_char), allocatable :: buf(:), cx(:)
    integer(c_size_t) :: needed
    integer(c_int) :: st, cd
    call to_c(x, cx)
    allocate (buf(64))
    cd = 0
    do
      needed = 0
      st = c_hs_ref_eval(sol%ptr, int(what, c_int), cx, buf, size(buf, kind=c_size_t), needed, cd)
      if (st /= HS_ERR_BUFFER_TOO_SMALL .or. needed <= size(buf, kind=c_size_t)) exit
      deallocate (buf)
      allocate (buf(needed))
    end do
    if (st == HS_OK) then
      value = buf_to_f(buf, int(needed) - 1)
      if (present(certified)) certified = int(cd)
    end if
    call check(st, 'hs_ref_eval', ierr)
  end subroutine hs_ref_eval

  ! A stress component (HS_STRESS_XX, _YY or _XY) at the decimal point (x, y) of body 1
  ! (specimen, y >= 0) or 2 (pad, y <= 0); y = 0 is the surface. pad_bulk: the pad's
  ! decimal bulk stress (optional, default "0"; the specimen carries sigma + pad_bulk).
  subroutine hs_ref_eval_stress(sol, body, component, x, y, value, certified, ierr, pad_bulk)
    type(hs_ref_solution_t), intent(in) :: sol
    integer, intent(in) :: body, component
    character(len=*), intent(in) :: x, y
    character(len=:), allocatable, intent(inout) :: value
    integer, intent(out), optional :: certified
    integer, intent(out), optional :: ierr
    character(len=*), intent(in), optional :: pad_bulk
    character(kind=c_char), allocatable :: buf(:), cx(:), cy(:), cb(:)
    integer(c_size_t) :: needed
    integer(c_int) :: st, cd
    call to_c(x, cx)
    call to_c(y, cy)
    if (present(pad_bulk)) then
      call to_c(pad_bulk, cb)
    else
      call to_c('0', cb)
    end if
    allocate (buf(64))
    cd = 0
    do
      needed = 0
      st = c_hs_ref_eval_stress(sol%ptr, int(body, c_int), cb, int(component, c_int), cx, cy, buf, &
                                size(buf, kind=c_size_t), needed, cd)
      if (st /= HS_ERR_BUFFER_TOO_SMALL .or. needed <= size(buf, kind=c_size_t)) exit
      deallocate (buf)
      allocate (buf(needed))
    end do
    if (st == HS_OK) then
      value = buf_to_f(buf, int(needed) - 1)
      if (present(certified)) certified = int(cd)
    end if
    call check(st, 'hs_ref_eval_stress', ierr)
  end subroutine hs_ref_eval_stress

end module halfslip
