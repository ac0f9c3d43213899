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
!   IER = -1  M < 1, EPS negative or NaN, or a pivot that is zero to working precision
!             (no solution: R is left unchanged), or a solution that overflows (R holds
!             +-inf where it overflows: the Python layer raises RangeError);
!   IER = K   (K >= 1) complete-pivoting Gauss elimination met, at step K+1, a pivot
!             |p| <= EPS * max|a_ij|: the first K steps were sound, so A has numerical
!             rank K at tolerance EPS.  The solution is still returned, as in SSP.
! Complete pivoting is LAPACK's DGETC2 (A = P L U Q), the solve DGESC2.  SSP's pivots are
! the same complete pivots, so the step K reported is SSP's step.
! A and each column of R are scaled by powers of 2 before the elimination (exact, same
! pivots and IER) so that huge or tiny coefficients neither overflow nor underflow in it.
module gelg_mod
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use prmtr, only: dp, st_ok, st_singular, st_significance
  implicit none
  private
  public :: gelg, gelg2, gelg2_lu, gelg2_solve, xerbla_calls, xerbla_last_routine, xerbla_last_info, lapack_probe

  integer :: xerbla_calls = 0                 ! how often LAPACK reported a bad argument
  character(len=32) :: xerbla_last_routine = ''
  integer :: xerbla_last_info = 0

contains

  subroutine gelg(r, a, m, n, eps, ier)
    !sarkp ier-is-output
    !: R : table(M, N) real -- Right-hand sides.
    !: A : table(M, M) real destroyed -- Coefficient matrix (destroyed in Fortran; here a copy is).
    !: M : integer 1..2147483646 -- Order of the system (M >= 1); must match the shapes of R
    !:     and A.
    !: N : integer 1..2147483646 -- Number of right-hand sides (the book's gloss "method of
    !:     computation" is wrong: ERRATA E-GELG-1); must match the shape of R.
    !: EPS : real >= 0 -- Relative pivot tolerance, >= 0.
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
          ! the solution overflows: IER = -1, and R holds +-inf where it does (the Python
          ! layer's RangeError names R), the rest of the solution where it does not
          ier = -1
          do k = 1, m
            if (exponent(work(k)) - exponent(scl) + er - ea >= maxexponent(1.0_dp)) then
              sol(k, j) = sign(ieee_value(1.0_dp, ieee_positive_inf), work(k))
            else
              sol(k, j) = scale(work(k), er - ea - exponent(scl))/fraction(scl)
            end if
          end do
          r(:, j) = sol(:, j)
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
    real(dp) :: amax, r(2)
    integer :: ipv, jpv
    call gelg2_lu(a, ipv, jpv, amax, r, st)
    if (st /= st_ok) then
      c = 0.0_dp
      return
    end if
    call gelg2_solve(a, ipv, jpv, amax, r, c, st)
  end subroutine gelg2

  ! gelg2's elimination (DGETC2): A is overwritten by its factors, IPV, JPV are the pivot's
  ! row and column, AMAX the largest |a| for GELG's EPS test, R the reciprocals of the
  ! pivots that DGESC2 multiplies by.  st_singular (A unusable) or st_ok.  A system solved twice with one matrix (DKNMA1's velocities and accelerations)
  ! factors it once: the factors do not depend on the right-hand side, so the results are
  ! bit for bit those of two gelg2 calls.
  subroutine gelg2_lu(a, ipv, jpv, amax, r, st)
    real(dp), intent(inout) :: a(2, 2)
    integer, intent(out) :: ipv, jpv, st
    real(dp), intent(out) :: amax, r(2)
    real(dp), parameter :: prec = epsilon(1.0_dp), smlnum = tiny(1.0_dp)/epsilon(1.0_dp)
    real(dp) :: xmax, smin, t
    integer :: i, j

    st = st_singular
    ipv = 1
    jpv = 1
    r = 0.0_dp
    amax = max(abs(a(1, 1)), abs(a(2, 1)), abs(a(1, 2)), abs(a(2, 2)))
    if (.not. (amax > 0.0_dp) .or. amax > huge(amax)) return   ! zero, NaN or inf matrix
    ! DGETC2, step 1: the pivot is the last largest element in row order
    xmax = 0.0_dp
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
    if (ipv /= 1) then                       ! swap the rows (the right-hand sides in the solve)
      do j = 1, 2
        t = a(1, j)
        a(1, j) = a(2, j)
        a(2, j) = t
      end do
    end if
    if (jpv /= 1) then                       ! swap the columns (undone on the solution)
      do i = 1, 2
        t = a(i, 1)
        a(i, 1) = a(i, 2)
        a(i, 2) = t
      end do
    end if
    if (abs(a(1, 1)) < smin) return          ! DGETC2 INFO = 1: GELG's IER = -1
    a(2, 1) = a(2, 1)/a(1, 1)
    if (a(1, 2) /= 0.0_dp) a(2, 2) = a(2, 2) + a(2, 1)*(-a(1, 2))   ! DGER
    if (abs(a(2, 2)) < smin) return          ! DGETC2 INFO = 2
    r(1) = 1.0_dp/a(1, 1)
    r(2) = 1.0_dp/a(2, 2)
    st = st_ok
  end subroutine gelg2_lu

  ! gelg2's solve (DGESC2) with the factors of gelg2_lu; the status as for gelg2.
  subroutine gelg2_solve(a, ipv, jpv, amax, r, c, st)
    real(dp), intent(in) :: a(2, 2), amax, r(2)
    integer, intent(in) :: ipv, jpv
    real(dp), intent(inout) :: c(2)
    integer, intent(out) :: st
    real(dp), parameter :: smlnum = tiny(1.0_dp)/epsilon(1.0_dp)
    real(dp) :: t

    st = st_singular
    if (ipv /= 1) then
      t = c(1)
      c(1) = c(2)
      c(2) = t
    end if
    ! DGESC2: L, the scaling test (a scaled solution is GELG's IER = -1), then U
    c(2) = c(2) - a(2, 1)*c(1)
    if (2.0_dp*smlnum*max(abs(c(1)), abs(c(2))) > abs(a(2, 2))) then
      c = 0.0_dp
      return
    end if
    c(2) = c(2)*r(2)
    c(1) = c(1)*r(1)
    c(1) = c(1) - c(2)*(a(1, 2)*r(1))
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
  end subroutine gelg2_solve

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
