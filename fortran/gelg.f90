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
  subroutine gelg2(a, c, st)
    real(dp), intent(inout) :: a(2, 2), c(2)
    integer, intent(out) :: st
    integer :: ier
    call gelg(c, a, 2, 1, 0.0001_dp, ier)
    if (ier < 0 .or. .not. (abs(c(1)) <= huge(1.0_dp) .and. abs(c(2)) <= huge(1.0_dp))) then
      st = st_singular
      c = 0.0_dp
    else if (ier > 0) then
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
