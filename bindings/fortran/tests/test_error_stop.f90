! Without ierr, a failing call prints "halfslip: <function>: <message>" on
! the error unit and stops with error stop. ctest checks the message and that
! the line after the call is never reached.
program test_error_stop
  use, intrinsic :: iso_c_binding, only: c_double
  use halfslip
  implicit none
  type(hs_scene) :: sc
  type(hs_solution_t) :: sol
  call hs_scene_default(sc)
  sc%Q_over_fP = 1.0_c_double   ! gross sliding
  call hs_solve(sc, sol)
  write (*, '(a)') 'UNREACHABLE: hs_solve returned after an error without ierr'
end program test_error_stop
