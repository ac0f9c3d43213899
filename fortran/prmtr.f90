! prmtr.f90 -- the book's COMMON /PRMTR/ PI, PID2 (first used at L2152), reborn as a module.
!
! Chapters 1-3 of the book set PI = 3.14159 locally in each routine; chapter 4 on keeps
! PI and PID2 in COMMON /PRMTR/.  Here both live in this module, and the mode switch
! decides their value:
!   corrected  (default): PI is pi to double precision, every author error fixed;
!   as-printed          : PI = 3.14159, the book's value, and the author errors that a
!                         printed figure depends on come back (each site cites its ERRATA id).
module prmtr
  implicit none
  private
  integer, parameter, public :: dp = kind(1.0d0)
  real(dp), parameter, public :: pi_exact = 3.141592653589793238462643_dp
  real(dp), parameter, public :: pi_book = 3.14159_dp        ! L559: PI = 3.14159

  real(dp), public :: pi = pi_exact
  real(dp), public :: pid2 = pi_exact/2
  integer, public :: printed_mode = 0                        ! 0 corrected, 1 as-printed
  ! One copy per thread (thread-local storage): the generated drivers release the GIL and
  ! set the caller's mode at the start of every call, so threads must not share it.
  !$omp threadprivate(pi, pid2, printed_mode)

  ! Status codes returned in the trailing IER of every routine that can fail.
  ! (The book has no such argument: it let ARCOS or a division fail at run time.)
  integer, parameter, public :: st_ok = 0           ! result is valid
  integer, parameter, public :: st_assembly = 1     ! links do not reach: no assembly
  integer, parameter, public :: st_singular = 2     ! dead centre / singular system (GELG IER = -1)
  integer, parameter, public :: st_significance = 3 ! GELG IER > 0: loss of significance, result kept
  integer, parameter, public :: st_requirement = 4  ! synthesis requirement no mechanism can meet
  integer, parameter, public :: st_missing = 5      ! an input was NaN (a failed earlier step)
  integer, parameter, public :: st_range = 6        ! a result is not a finite double (overflow)
  ! 100 + d (d = 1..7): the result was kept, but only about d significant digits are left
  integer, parameter, public :: st_digits = 100

  public :: set_mode, as_printed, book_sign, succeeded, norm2d

contains

  subroutine set_mode(printed)
    ! printed = 0: corrected mode, exact pi; printed = 1: as-printed mode, PI = 3.14159.
    ! Every generated driver calls this first, with the caller's mode.
    integer, intent(in) :: printed
    if ((printed /= 0) .eqv. (printed_mode /= 0)) return
    if (printed /= 0) then
      printed_mode = 1
      pi = pi_book
    else
      printed_mode = 0
      pi = pi_exact
    end if
    pid2 = pi/2
  end subroutine set_mode

  ! A status whose results are kept: ok, or kept with a loss of significance.
  pure logical function succeeded(st)
    integer, intent(in) :: st
    succeeded = st == st_ok .or. st == st_significance .or. st > st_digits
  end function succeeded

  logical function as_printed()
    as_printed = printed_mode /= 0
  end function as_printed

  pure real(dp) function book_sign(a, b)
    ! FORTRAN IV SIGN(A, B): |A| if B >= 0, -|A| if B < 0.  A negative zero B counts as
    ! positive, as it did on the ES EVM (gfortran's SIGN would give -|A| there).
    real(dp), intent(in) :: a, b
    if (b < 0.0_dp) then
      book_sign = -abs(a)
    else
      book_sign = abs(a)
    end if
  end function book_sign

  ! |(x, y)| as the book writes it, SQRT(X**2 + Y**2), where neither square can overflow or
  ! underflow; the libm hypot (about three times the cost, issue 9's profile) only outside
  ! that range, but for (0, 0), whose hypot is 0 (the Mechanism's neutral spring of a
  ! mechanism without springs is one, at every position).  Within it the two differ by at
  ! most an ulp or so.
  pure real(dp) function norm2d(x, y)
    real(dp), intent(in) :: x, y
    real(dp) :: m
    m = max(abs(x), abs(y))
    if (m > 1.0e-150_dp .and. m < 1.0e150_dp) then
      norm2d = sqrt(x*x + y*y)
    else if (m == 0.0_dp) then
      norm2d = 0.0_dp
    else
      norm2d = hypot(x, y)
    end if
  end function norm2d

end module prmtr
