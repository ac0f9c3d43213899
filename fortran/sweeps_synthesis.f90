! sweeps_synthesis.f90 -- array drivers for chapter 3 (synthesis.f90): one Fortran loop
! over N independent syntheses per routine, so that the Python layer computes a whole
! array of designs in one call.  Scalar inputs are arrays of length N; the book's
! 3-vectors of DSNTZR (LO, FI1, FI3) are (3, N) arrays, column J holding design J.
! AAA (print flag) is left out.  STATUS(J) is the IER of design J (prmtr's st_* codes).
module sweeps_synthesis
  use prmtr, only: dp
  use synthesis, only: dsntzr, dsntz1, dsntz2, dsntz3, dsntzk
  implicit none
  private
  public :: dsntzr_sweep, dsntz1_sweep, dsntz2_sweep, dsntz3_sweep, dsntzk_sweep

  real(dp), parameter :: silent = 1.0_dp

contains

  subroutine dsntzr_sweep(n, lo, l3, fi1, fi3, l1, l2, fi11, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: lo(3, n), l3(n), fi1(3, n), fi3(3, n)
    real(dp), intent(out) :: l1(n), l2(n), fi11(n)
    integer, intent(out) :: status(n)
    integer :: j
    do j = 1, n
      call dsntzr(lo(:, j), l3(j), fi1(:, j), fi3(:, j), silent, l1(j), l2(j), fi11(j), &
                  status(j))
    end do
  end subroutine dsntzr_sweep

  subroutine dsntz1_sweep(n, kw3, fi31, fi32, l3, xd, q, l1, l2, lo, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: kw3(n), fi31(n), fi32(n), l3(n), xd(n), q(n)
    real(dp), intent(out) :: l1(n), l2(n), lo(n)
    integer, intent(out) :: status(n)
    integer :: j
    do j = 1, n
      call dsntz1(kw3(j), fi31(j), fi32(j), l3(j), xd(j), q(j), silent, l1(j), l2(j), &
                  lo(j), status(j))
    end do
  end subroutine dsntz1_sweep

  subroutine dsntz2_sweep(n, kw3, fi3, l3, xd, gmin, gmax, l1, l2, lo, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: kw3(n), fi3(n), l3(n), xd(n), gmin(n), gmax(n)
    real(dp), intent(out) :: l1(n), l2(n), lo(n)
    integer, intent(out) :: status(n)
    integer :: j
    do j = 1, n
      call dsntz2(kw3(j), fi3(j), l3(j), xd(j), gmin(j), gmax(j), silent, l1(j), l2(j), &
                  lo(j), status(j))
    end do
  end subroutine dsntz2_sweep

  subroutine dsntz3_sweep(n, xb1, yb1, xb2, yb2, xc1, yc1, xc2, yc2, fi1, alc1, &
                          l1, l3, lo, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xb1(n), yb1(n), xb2(n), yb2(n), xc1(n), yc1(n), xc2(n), &
                            yc2(n), fi1(n), alc1(n)
    real(dp), intent(out) :: l1(n), l3(n), lo(n)
    integer, intent(out) :: status(n)
    integer :: j
    do j = 1, n
      call dsntz3(xb1(j), yb1(j), xb2(j), yb2(j), xc1(j), yc1(j), xc2(j), yc2(j), &
                  fi1(j), alc1(j), silent, l1(j), l3(j), lo(j), status(j))
    end do
  end subroutine dsntz3_sweep

  subroutine dsntzk_sweep(n, kw3, s, h, q, l1, lo, l3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: kw3(n), s(n), h(n), q(n)
    real(dp), intent(out) :: l1(n), lo(n), l3(n)
    integer, intent(out) :: status(n)
    integer :: j
    do j = 1, n
      call dsntzk(kw3(j), s(j), h(j), q(j), silent, l1(j), lo(j), l3(j), status(j))
    end do
  end subroutine dsntzk_sweep

end module sweeps_synthesis
