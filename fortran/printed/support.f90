! support.f90 -- what the printed code (sarkp._printed) needs and the book does not print.
! The listings are compiled as printed, in their own types (REAL is single precision);
! these few routines stand in for the ES EVM's library and the main programs.

! COMMON /PRMTR/ is set by the book's main programs (PI = 3.14159, L2489).  The printer's
! unit 3 (WRITE(3, ...)) goes to DEVNULL and PRINT's unit 6 to a scratch file (one file
! cannot be open on two units): sarkp renders the book's layouts itself.
subroutine prinit(devnull)
  implicit none
  character(len=*), intent(in) :: devnull
  real :: pi, pid2
  common /prmtr/ pi, pid2
  pi = 3.14159
  pid2 = pi/2.0
  open(3, file=devnull)
  close(6)
  open(6, status='scratch')
end subroutine prinit

! ES FORTRAN's names of ACOS and ASIN.
real function arcos(x)
  implicit none
  real, intent(in) :: x
  arcos = acos(x)
end function arcos

real function arsin(x)
  implicit none
  real, intent(in) :: x
  arsin = asin(x)
end function arsin

! GELG (IBM SSP, not printed): sarkp's GELG, called with the listings' REAL arguments.
subroutine gelg(r, a, m, n, eps, ier)
  use gelg_mod, only: gelg_dp => gelg
  implicit none
  integer, intent(in) :: m, n
  real, intent(inout) :: r(m, n), a(m, m)
  real, intent(in) :: eps
  integer, intent(out) :: ier
  double precision :: rd(m, n), ad(m, m)
  rd = r
  ad = a
  call gelg_dp(rd, ad, m, n, dble(eps), ier)
  r = real(rd)
  a = real(ad)
end subroutine gelg
