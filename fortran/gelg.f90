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
!   IER = -1  M < 1, EPS negative or NaN, or a pivot that is zero to working precision,
!             or a solution that overflows (no solution: R is left unchanged);
!   IER = K   (K >= 1) complete-pivoting Gauss elimination met, at step K+1, a pivot
!             |p| <= EPS * max|a_ij|: the first K steps were sound, so A has numerical
!             rank K at tolerance EPS.  The solution is still returned, as in SSP.
! Complete pivoting is LAPACK's DGETC2 (A = P L U Q), the solve DGESC2.  SSP's pivots are
! the same complete pivots, so the step K reported is SSP's step.
! A and each column of R are scaled by powers of 2 before the elimination (exact, same
! pivots and IER) so that huge or tiny coefficients neither overflow nor underflow in it.
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
    real(dp) :: amax, rmax, tol, scl, work(max(m, 1)), sol(m, n)
    integer :: ea, er
    external :: dgetc2, dgesc2

    ier = -1
    if (m < 1 .or. n < 1) return
    if (.not. (eps >= 0.0_dp)) return        ! NaN or negative EPS (the Python layer names it)
    amax = maxval(abs(a))
    if (.not. (amax > 0.0_dp) .or. amax > huge(amax)) return   ! zero, NaN or inf matrix
    ! Scale A by a power of 2 so that max|a_ij| is about 1: exact, leaves the pivot order
    ! and every pivot ratio (hence IER) unchanged, and keeps the elimination from
    ! overflowing (1e308 - (-1e308)) or underflowing.
    ea = exponent(amax)
    a = scale(a, -ea)
    tol = eps*maxval(abs(a))

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
      ! each right-hand side scaled by a power of 2 as well (exact); DGESC2 solves
      ! A x = scl*b when it must scale to avoid overflow, so x/scl is the solution.
      rmax = maxval(abs(r(:, j)))
      if (.not. (rmax <= huge(rmax))) then
        ier = -1
        return
      end if
      er = 0
      if (rmax > 0.0_dp) er = exponent(rmax)
      work = scale(r(:, j), -er)
      call dgesc2(m, a, m, work, ipiv, jpiv, scl)
      ! the solution of the original system is work/scl * 2**(er - ea): representable?
      if (.not. (scl > 0.0_dp)) then
        ier = -1
        return
      end if
      if (maxval(abs(work)) > 0.0_dp) then
        if (exponent(maxval(abs(work))) - exponent(scl) + er - ea >= maxexponent(1.0_dp)) then
          ier = -1                               ! the solution overflows
          return
        end if
      end if
      sol(:, j) = scale(work, er - ea - exponent(scl))/fraction(scl)
    end do
    r = sol
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
