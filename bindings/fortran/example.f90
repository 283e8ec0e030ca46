! halfslip from Fortran: solve one scene, print the stick zone, evaluate the
! slip along the contact, solve a flat punch, and compute b1 to 40 certified
! digits.
!
!   gfortran example.f90 $(pkg-config --cflags --libs halfslip-fortran)
program example
  use, intrinsic :: iso_c_binding, only: c_double
  use halfslip
  implicit none
  integer, parameter :: n = 9
  type(hs_scene) :: scene
  type(hs_solution_t) :: sol
  type(hs_summary) :: sm
  type(hs_geometry) :: geometry
  type(hs_ref_scene_t) :: rscene
  type(hs_ref_solution_t) :: rsol
  real(c_double) :: x(n), h(n), energy(2)
  character(len=:), allocatable :: b1
  integer :: i, ierr, certified

  write (*, '(a)') 'halfslip ' // hs_version_string()

  ! Q/fP = 0.3 and sigma/(f p0) = 2 on the unit scene: slip zones of opposite sign.
  call hs_scene_default(scene)
  scene%Q_over_fP = 0.3_c_double
  scene%sigma_over_fp0 = 2.0_c_double
  call hs_solve(scene, sol)          ! no ierr: any error stops with its message
  call hs_solution_summary(sol, sm)
  write (*, '(a,i0,a,2f19.15)') 'regime ', sm%regime, ', stick zone (-b2, b1): b2, b1 =', sm%b2, sm%b1
  write (*, '(a,2i3)') 'slip directions of zones 1 and 2:', sm%slip_dir1, sm%slip_dir2

  do i = 1, n
    x(i) = -1 + 2 * real(i - 1, c_double) / (n - 1)
  end do
  call hs_eval_slip(sol, n, x, h)
  do i = 1, n
    write (*, '(a,f6.2,a,es12.4)') '  h(', x(i), ') =', h(i)
  end do
  call hs_solution_energy(sol, energy)
  write (*, '(a,2es14.6)') 'energy dissipated in zones 1 and 2:', energy

  ! Errors can also be handled by the caller.
  scene%Q_over_fP = 1.5_c_double
  call hs_solve(scene, sol, ierr=ierr)
  if (ierr /= HS_OK) write (*, '(a)') 'Q/fP = 1.5: ' // hs_strerror(ierr)
  call hs_solution_free(sol)

  ! Another pressure: a flat punch with rounded corners (flat half-width 0.6 a), shear only.
  call hs_geometry_default(geometry)
  geometry%kind = HS_GEOMETRY_FLAT_ROUNDED
  geometry%flat_over_a = 0.6_c_double
  scene%Q_over_fP = 0.5_c_double
  scene%sigma_over_fp0 = 0
  call hs_solve_geometry(scene, geometry, sol)
  call hs_solution_summary(sol, sm)
  write (*, '(a,f17.15,a,i0,a)') 'flat punch: b1 = b2 = ', sm%b1, ' (quadrature order ', sm%quadrature_order, ')'
  call hs_solution_free(sol)

  ! The same scene to 40 digits with the MPFR reference backend.
  rscene%Q_over_fP = '0.3'
  rscene%sigma_over_fp0 = '2'
  call hs_ref_solve(rscene, 40, rsol)
  call hs_ref_value(rsol, HS_REF_B1, b1, certified)
  write (*, '(a,i0,a)') 'b1 = ' // b1 // ' (', certified, ' digits certified)'
  call hs_ref_solution_free(rsol)
  deallocate (b1)   ! main-program allocatables are not freed automatically
end program example
