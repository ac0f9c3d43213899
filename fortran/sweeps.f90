! sweeps.f90 -- array drivers: one Fortran loop over positions per routine, so that the
! Python layer computes a whole array (a sweep of positions) in one call.  Every input
! is an array of the same length N (the Python layer broadcasts); scalar book arguments
! that only steer printing (AAA) are left out.
module sweeps
  use prmtr, only: dp
  use operators
  implicit none
  private
  public :: dugl1_sweep, dugl2_sweep, dugl3_sweep, dugl4_sweep, dugl5_sweep, &
            dugol_sweep, dmomnt_sweep, domega_sweep, dvkt_sweep, dsmvkt_sweep

contains

  ! ---- chapter 2 -----------------------------------------------------------------

  subroutine dugl1_sweep(n, x1, y1, x2, y2, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: x1(n), y1(n), x2(n), y2(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugl1(x1(i), y1(i), x2(i), y2(i))
    end do
  end subroutine dugl1_sweep

  subroutine dugl2_sweep(n, x1, y1, x2, y2, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: x1(n), y1(n), x2(n), y2(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugl2(x1(i), y1(i), x2(i), y2(i))
    end do
  end subroutine dugl2_sweep

  subroutine dugl3_sweep(n, ugol1, ugold, vel, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: ugol1(n), ugold(n), vel(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugl3(ugol1(i), ugold(i), vel(i))
    end do
  end subroutine dugl3_sweep

  subroutine dugl4_sweep(n, ugol1, ugold, vel, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: ugol1(n), ugold(n), vel(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugl4(ugol1(i), ugold(i), vel(i))
    end do
  end subroutine dugl4_sweep

  subroutine dugl5_sweep(n, prx, pry, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: prx(n), pry(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugl5(prx(i), pry(i))
    end do
  end subroutine dugl5_sweep

  subroutine dugol_sweep(n, fi, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: fi(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dugol(fi(i))
    end do
  end subroutine dugol_sweep

  subroutine dmomnt_sweep(n, r, fi, f, g, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: r(n), fi(n), f(n), g(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = dmomnt(r(i), fi(i), f(i), g(i))
    end do
  end subroutine dmomnt_sweep

  subroutine domega_sweep(n, razmer, vektor, ugol, res)
    integer, intent(in) :: n
    real(dp), intent(in) :: razmer(n), vektor(n), ugol(n)
    real(dp), intent(out) :: res(n)
    integer :: i
    do i = 1, n
      res(i) = domega(razmer(i), vektor(i), ugol(i))
    end do
  end subroutine domega_sweep

  subroutine dvkt_sweep(n, x1, y1, x2, y2, rz, fi)
    integer, intent(in) :: n
    real(dp), intent(in) :: x1(n), y1(n), x2(n), y2(n)
    real(dp), intent(out) :: rz(n), fi(n)
    integer :: i
    do i = 1, n
      call dvkt(x1(i), y1(i), x2(i), y2(i), rz(i), fi(i))
    end do
  end subroutine dvkt_sweep

  subroutine dsmvkt_sweep(n, l1, fi1, l2, fi2, l, fi)
    integer, intent(in) :: n
    real(dp), intent(in) :: l1(n), fi1(n), l2(n), fi2(n)
    real(dp), intent(out) :: l(n), fi(n)
    integer :: i
    do i = 1, n
      call dsmvkt(l1(i), fi1(i), l2(i), fi2(i), l(i), fi(i))
    end do
  end subroutine dsmvkt_sweep

end module sweeps
