! A Fortran program built against the installed halfslip (module and library).
program consumer
  use, intrinsic :: iso_c_binding, only: c_double
  use halfslip
  implicit none
  type(hs_scene) :: sc
  type(hs_solution_t) :: sol
  type(hs_summary) :: sm
  type(hs_ref_scene_t) :: rs
  type(hs_ref_solution_t) :: rsol
  character(len=:), allocatable :: b1
  integer :: ierr, certified
  call hs_scene_default(sc)
  sc%Q_over_fP = 0.3_c_double
  sc%sigma_over_fp0 = 2.0_c_double
  call hs_solve(sc, sol)
  call hs_solution_summary(sol, sm)
  call hs_solution_free(sol)
  if (abs(sm%b1 - 0.749058362968991_c_double) > 1e-14_c_double .or. sm%slip_dir1 /= -1) then
    write (*, *) 'wrong opposite-sign solution: b1 =', sm%b1
    error stop 1
  end if
  sc%Q_over_fP = 2
  call hs_solve(sc, sol, ierr=ierr)
  if (ierr /= HS_ERR_GROSS_SLIDING) error stop 2
  rs%Q_over_fP = '0.3'
  rs%sigma_over_fp0 = '2'
  call hs_ref_solve(rs, 30, rsol)
  call hs_ref_value(rsol, HS_REF_B1, b1, certified)
  call hs_ref_solution_free(rsol)
  if (index(b1, '7.490583629689906330026357657') /= 1 .or. certified /= 30) error stop 3
  write (*, '(a,f17.15,a)') 'consumer fortran: b1 = ', sm%b1, ', reference b1 = ' // b1 // ': ok'
  deallocate (b1)
end program consumer
