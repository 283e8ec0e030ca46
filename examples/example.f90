! halfslip from Fortran: the scene of example.c (a steel cylinder, radius
! 50 mm, on a steel half-plane: P = 100 kN/m, Q = 18 kN/m, bulk tension
! 20 MPa; SI units, loads per unit length), with the slip along the contact.
!
!   gfortran example.f90 $(pkg-config --cflags --libs halfslip-fortran)   (or CMake: halfslip::fortran)
program example
  use, intrinsic :: iso_c_binding, only: c_double
  use halfslip
  implicit none
  integer, parameter :: n = 5
  real(c_double), parameter :: P = 1.0e5_c_double, R = 0.05_c_double, E_star = 1.154e11_c_double, &
                               f = 0.6_c_double, Q = 1.8e4_c_double, sigma = 2.0e7_c_double
  type(hs_scene) :: scene
  type(hs_solution_t) :: sol
  type(hs_summary) :: sm
  real(c_double) :: x(n), h(n), energy(2)
  integer :: i, ierr

  call hs_scene_from_hertz_loads(P, R, E_star, f, Q, sigma, scene)   ! no ierr: an error stops
  call hs_solve(scene, sol)
  call hs_solution_summary(sol, sm)
  call hs_solution_energy(sol, energy)
  write (*, '(a)') 'halfslip ' // hs_version_string() // ', Fortran example'
  write (*, '(a,es14.7,a,es14.7,a)') 'contact half-width a = ', sm%a * 1e3_c_double, ' mm, peak pressure p0 = ', &
    sm%p0 * 1e-6_c_double, ' MPa'
  write (*, '(a,f9.7,a,f9.7,a)') 'stick zone: b1 = ', sm%b1 * 1e3_c_double, ' mm, b2 = ', sm%b2 * 1e3_c_double, ' mm'
  write (*, '(a,es14.7,a,es14.7,a)') 'energy dissipated: E1 = ', energy(1), ' J/m, E2 = ', energy(2), ' J/m'

  ! slip across the contact, from -a to a
  do i = 1, n
    x(i) = sm%a * (-1 + 2 * real(i - 1, c_double) / (n - 1))
  end do
  call hs_eval_slip(sol, n, x, h)
  do i = 1, n
    write (*, '(a,f9.5,a,es12.5,a)') '  slip h(', x(i) * 1e3_c_double, ' mm) = ', h(i) * 1e6_c_double, ' um'
  end do

  ! errors can also be handled by the caller: Q above fP slides as a whole
  call hs_scene_from_hertz_loads(P, R, E_star, f, 2 * f * P, sigma, scene, ierr)
  if (ierr /= HS_OK) write (*, '(a)') 'Q = 2fP: ' // hs_strerror(ierr)
  call hs_solution_free(sol)
end program example
