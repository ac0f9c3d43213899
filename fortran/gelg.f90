! gelg.f90 -- GELG(R, A, M, N, EPS, IER), the IBM SSP solver the book calls (L519-528),
! rebuilt on LAPACK.
!
! Book call (2.7), L523: CALL GELG(Y, X, N, K, T, IER); every example passes K = 1 and
! T = 0.0001.  The book's gloss of K ("sposob vychisleniya", method of computation) is wrong: in SSP it is the
! number of right-hand-side columns (ERRATA E-GELG-1).
!
! Meaning kept from SSP:
!   R(M,N)  right-hand sides in, solution out;   A(M,M)  destroyed;
!   EPS     relative pivot tolerance;
!   IER = 0   no loss of significance;
!   IER = -1  M < 1, or a pivot that is zero to working precision (no solution: R is
!             left unchanged);
!   IER = K   (K >= 1) complete-pivoting Gauss elimination met, at step K+1, a pivot
!             |p| <= EPS * max|a_ij|: the first K steps were sound, so A has numerical
!             rank K at tolerance EPS.  The solution is still returned, as in SSP.
! Complete pivoting is LAPACK's DGETC2 (A = P L U Q), the solve DGESC2.  SSP's pivots are
! the same complete pivots, so the step K reported is SSP's step.
module gelg_mod
  use prmtr, only: dp, st_ok, st_singular, st_significance
  implicit none
  private
  public :: gelg, gelg2, xerbla_calls, xerbla_last_routine, xerbla_last_info, lapack_probe

  integer :: xerbla_calls = 0                 ! how often LAPACK reported a bad argument
  character(len=32) :: xerbla_last_routine = ''
  integer :: xerbla_last_info = 0

contains

  subroutine gelg(r, a, m, n, eps, ier)
    !sarkp ier-is-output
    integer, intent(in) :: m, n
    real(dp), intent(inout) :: r(m, n)
    real(dp), intent(inout) :: a(m, m)
    real(dp), intent(in) :: eps
    integer, intent(out) :: ier
    integer :: ipiv(max(m, 1)), jpiv(max(m, 1)), info, k, j
    real(dp) :: amax, tol, scale, work(max(m, 1))
    external :: dgetc2, dgesc2

    ier = -1
    if (m < 1 .or. n < 1) return
    amax = maxval(abs(a))
    if (.not. (amax > 0.0_dp) .or. amax > huge(amax)) return   ! zero, NaN or inf matrix
    tol = eps*amax

    call dgetc2(m, a, m, ipiv, jpiv, info)
    ! DGETC2 sets INFO = k when it had to replace a pivot smaller than eps*max|a|:
    ! that pivot is zero to working precision, and SSP's answer would be rounding noise.
    if (info > 0) return

    ier = 0
    ! SSP tests every step but can only warn from step 2 on (IER = K-1, and step 1's pivot
    ! is max|a| itself); it keeps the first warning.
    do k = 2, m
      if (abs(a(k, k)) <= tol) then
        ier = k - 1
        exit
      end if
    end do

    do j = 1, n
      work = r(:, j)
      call dgesc2(m, a, m, work, ipiv, jpiv, scale)
      if (scale /= 1.0_dp) then                 ! DGESC2 scaled to avoid overflow
        ier = -1
        return
      end if
      r(:, j) = work
    end do
  end subroutine gelg

  ! The 2x2 call every routine of the book makes, CALL GELG(C, A, 2, 1, 0.0001, IER)
  ! (L525), with IER mapped to a status: st_singular for IER = -1 or a solution that
  ! overflowed (C is then zero), st_significance for IER > 0 (C kept), else st_ok.
  ! It is GELG's own algorithm written out for M = 2, without the library calls: LAPACK's
  ! DGETC2 (complete pivoting, the last largest element in row order; a pivot below
  ! max(eps*max|a|, tiny/eps) flags a singular matrix) and DGESC2 (the solve, multiplying
  ! by the reciprocal pivots, and its scaling test), operation for operation, so that the
  ! results are bit for bit those of GELG (tests/test_gelg.py checks it).  The library
  ! calls redid their machine-constant set-up on every call, which cost more than the
  ! 2x2 solve itself.
  subroutine gelg2(a, c, st)
    real(dp), intent(inout) :: a(2, 2), c(2)
    integer, intent(out) :: st
    real(dp), parameter :: prec = epsilon(1.0_dp), smlnum = tiny(1.0_dp)/epsilon(1.0_dp)
    real(dp) :: amax, xmax, smin, t, temp
    integer :: i, j, ipv, jpv

    st = st_singular
    amax = max(abs(a(1, 1)), abs(a(2, 1)), abs(a(1, 2)), abs(a(2, 2)))
    if (.not. (amax > 0.0_dp) .or. amax > huge(amax)) then   ! zero, NaN or inf matrix
      c = 0.0_dp
      return
    end if
    ! DGETC2, step 1: the pivot is the last largest element in row order
    xmax = 0.0_dp
    ipv = 1
    jpv = 1
    do i = 1, 2
      do j = 1, 2
        if (abs(a(i, j)) >= xmax) then
          xmax = abs(a(i, j))
          ipv = i
          jpv = j
        end if
      end do
    end do
    smin = max(prec*xmax, smlnum)
    if (ipv /= 1) then                       ! swap the rows, and the right-hand sides
      do j = 1, 2
        t = a(1, j)
        a(1, j) = a(2, j)
        a(2, j) = t
      end do
      t = c(1)
      c(1) = c(2)
      c(2) = t
    end if
    if (jpv /= 1) then                       ! swap the columns (undone on the solution)
      do i = 1, 2
        t = a(i, 1)
        a(i, 1) = a(i, 2)
        a(i, 2) = t
      end do
    end if
    if (abs(a(1, 1)) < smin) then            ! DGETC2 INFO = 1: GELG's IER = -1
      c = 0.0_dp
      return
    end if
    a(2, 1) = a(2, 1)/a(1, 1)
    if (a(1, 2) /= 0.0_dp) a(2, 2) = a(2, 2) + a(2, 1)*(-a(1, 2))   ! DGER
    if (abs(a(2, 2)) < smin) then            ! DGETC2 INFO = 2
      c = 0.0_dp
      return
    end if
    ! DGESC2: L, the scaling test (a scaled solution is GELG's IER = -1), then U
    c(2) = c(2) - a(2, 1)*c(1)
    if (2.0_dp*smlnum*max(abs(c(1)), abs(c(2))) > abs(a(2, 2))) then
      c = 0.0_dp
      return
    end if
    temp = 1.0_dp/a(2, 2)
    c(2) = c(2)*temp
    temp = 1.0_dp/a(1, 1)
    c(1) = c(1)*temp
    c(1) = c(1) - c(2)*(a(1, 2)*temp)
    if (jpv /= 1) then
      t = c(1)
      c(1) = c(2)
      c(2) = t
    end if
    if (.not. (abs(c(1)) <= huge(1.0_dp) .and. abs(c(2)) <= huge(1.0_dp))) then
      c = 0.0_dp
      return
    end if
    ! GELG's significance test at step 2 (SSP's IER = 1): the second pivot against EPS
    if (abs(a(2, 2)) <= 0.0001_dp*amax) then
      st = st_significance
    else
      st = st_ok
    end if
  end subroutine gelg2

  subroutine lapack_probe(info)
    ! Call LAPACK with an invalid argument on purpose (DGETRF with M = -1) and return
    ! the INFO it reports.  With our XERBLA in force, the process neither prints nor stops.
    integer, intent(out) :: info
    real(dp) :: a(1, 1)
    integer :: ipiv(1)
    external :: dgetrf
    a = 1.0_dp
    call dgetrf(-1, 1, a, 1, ipiv, info)
  end subroutine lapack_probe

end module gelg_mod

! XERBLA override: LAPACK's own prints a message and STOPs the process.  This one only
! records the call; the caller sees LAPACK's negative INFO as usual.
subroutine xerbla(srname, info)
  use gelg_mod, only: xerbla_calls, xerbla_last_routine, xerbla_last_info
  implicit none
  character(len=*), intent(in) :: srname
  integer, intent(in) :: info
  xerbla_calls = xerbla_calls + 1
  xerbla_last_routine = srname
  xerbla_last_info = info
end subroutine xerbla
