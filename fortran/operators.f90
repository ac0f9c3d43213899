! operators.f90 -- chapter 2, the operator functions of SARKP-TMM (listings II.1-II.12,
! book lines L425-700).  Names and argument order are the book's.  The Python layer
! validates the input (finite numbers, positive lengths, coincident points) before it
! calls these routines; guards below only keep a NaN from ever being produced.
module operators
  use prmtr, only: dp, pi, book_sign, printed_mode, norm2d
  implicit none
  private
  public :: dintgr, dfrncl, dugl1, dugl2, dugl3, dugl4, dugl5, dugol, dmomnt, domega, &
            dvkt, dsmvkt

contains

  ! II.1, L435-480.  Running integral of a tabulated function with step H.
  ! NOMER as in the listing's code and comments (L443-447): 1 Simpson, 2 trapezoids,
  ! 3 rectangles.  The prose at L431 lists them the other way round (ERRATA E-DINTGR-2).
  ! The printed header names the step N (ERRATA E-DINTGR-1).  Needs M >= 2; an unknown
  ! NOMER leaves FINT zero (the Python layer rejects it first).
  ! Simpson: the odd points chain Simpson's rule from FINT(1) = 0; the even points chain it
  ! from FINT(2).  The book starts that chain with a trapezoid over the first interval
  ! (error h**3 y''/12, carried to every even point: 3rd order there, 4th at odd points).
  ! Corrected mode starts it with the integral over [x1, x2] of the parabola through the
  ! first three points, h (5 y1 + 8 y2 - y3)/12 (error h**4 y'''/24), so every point is
  ! 4th order (E-DINTGR-4, numerical); as-printed keeps the trapezoid.  M = 2: trapezoid.
  subroutine dintgr(m, h, nomer, y, fint)
    !: M : integer 2..2147483646 -- Number of points; must equal ``len(Y)`` (at least 2).
    !: H : real != 0 -- Step of the table, non-zero (the printed header names it ``N``:
    !:     ERRATA E-DINTGR-1).
    !: NOMER : integer 1..3 -- Method, numbered as the listing's code does (L443-447): 1
    !:     Simpson, 2 trapezoids, 3 rectangles. The prose at L431 numbers them the other way
    !:     round (1 rectangles, 3 Simpson); the code is followed (ERRATA E-DINTGR-2).
    !: Y : table(M) real -- The values of the integrand at the M points.
    integer, intent(in) :: m, nomer
    real(dp), intent(in) :: h
    real(dp), intent(in) :: y(m)
    real(dp), intent(out) :: fint(m)
    integer :: k
    fint = 0.0_dp
    if (m < 2) return
    select case (nomer)
    case (1)                                            ! Simpson, labels 10-12
      if (printed_mode == 0 .and. m >= 3) then
        fint(2) = h*(5.0_dp*y(1) + 8.0_dp*y(2) - y(3))/12.0_dp   ! E-DINTGR-4: corrected
      else
        fint(2) = h*(y(1) + y(2))/2.0_dp                         ! E-DINTGR-4: as printed
      end if
      if (m >= 3) fint(3) = (y(1) + 4.0_dp*y(2) + y(3))*h/3.0_dp
      do k = 4, m
        fint(k) = fint(k - 2) + (y(k - 2) + 4.0_dp*y(k - 1) + y(k))*h/3.0_dp
      end do
    case (2)                                            ! trapezoids, labels 13-15
      do k = 2, m
        fint(k) = fint(k - 1) + 0.5_dp*h*(y(k - 1) + y(k))
      end do
    case (3)                                            ! right rectangles, labels 16-18
      do k = 2, m
        fint(k) = fint(k - 1) + h*y(k)
      end do
    end select
  end subroutine dintgr

  ! II.2, L490-509.  Backward difference.  Output before input, as printed and as called
  ! at L5988.  The book sets FDIF(1) = 0 whatever the derivative; corrected mode gives
  ! the first point the forward difference (Y(2) - Y(1))/H, of the same (first) order as
  ! the backward differences at the others (E-DFRNCL-1, numerical); as-printed keeps 0.
  subroutine dfrncl(m, h, fdif, y)
    !: M : integer 2..2147483646 -- Number of points; must equal ``len(Y)`` (at least 2).
    !: H : real != 0 -- Step of the table, non-zero.
    !: Y : table(M) real -- The function values.
    integer, intent(in) :: m
    real(dp), intent(in) :: h
    real(dp), intent(out) :: fdif(m)
    real(dp), intent(in) :: y(m)
    integer :: k
    fdif = 0.0_dp
    do k = 1, m - 1
      fdif(k + 1) = (y(k + 1) - y(k))/h
    end do
    if (printed_mode == 0 .and. m >= 2) fdif(1) = fdif(2)      ! E-DFRNCL-1: corrected
  end subroutine dfrncl

  ! II.3, L551-569.  Direction of the segment (X1,Y1) -> (X2,Y2) in [0, 2*PI).
  ! Coincident points have no direction: the book divides 0 by 0; here 0 is returned.
  ! A direction a hair below 0 wraps to 2*PI in rounding; it is 0 then (E-DUGOL-1).
  pure real(dp) function dugl1(x1, y1, x2, y2)
    !: X1, Y1 : real -- Start of the segment.
    !: X2, Y2 : real -- End of the segment.
    real(dp), intent(in) :: x1, y1, x2, y2
    dugl1 = dugol(dugl2(x1, y1, x2, y2))
  end function dugl1

  ! II.4, L572-588.  Signed direction of (X1,Y1) -> (X2,Y2) in [-pi, pi].
  ! The listing computes SIGN(ACOS((X2-X1)/DL), Y2-Y1), which is atan2 written with an
  ! arccosine: near 0 and pi the arccosine loses up to half the digits (a direction of
  ! 1e-10 rad comes out as 0).  ATAN2 gives the same angle to full precision (ERRATA
  ! E-DUGL2-1).  Adding +0 turns a -0.0 into +0.0, so Y2 = Y1 still gives +pi, as
  ! FORTRAN IV's SIGN did.  Coincident points give 0 (the Python layer raises first).
  pure real(dp) function dugl2(x1, y1, x2, y2)
    !: X1, Y1, X2, Y2 : real -- Start and end of the segment.
    real(dp), intent(in) :: x1, y1, x2, y2
    if (x2 == x1 .and. y2 == y1) then
      dugl2 = 0.0_dp
    else
      dugl2 = atan2((y2 - y1) + 0.0_dp, x2 - x1)
    end if
  end function dugl2

  ! II.5, L590-599.  UGOL1 + sign(VEL) * |UGOLD|  (VEL = 0 counts as positive).
  pure real(dp) function dugl3(ugol1, ugold, vel)
    !: UGOL1 : real -- Base angle, radians.
    !: UGOLD : real -- Added angle; only its magnitude is used.
    !: VEL : real -- The parameter whose sign decides; zero (and -0.0, as on the ES EVM)
    !:     counts as positive.
    real(dp), intent(in) :: ugol1, ugold, vel
    dugl3 = ugol1 + book_sign(ugold, vel)
  end function dugl3

  ! II.6, L601-612.  UGOL1 - UGOLD if VEL < 0, else UGOL1.  The printed arithmetic IF
  ! jumps to a label 111 that does not exist (ERRATA E-DUGL4-1); Table 2 (L537) says
  ! "psi = phi for v >= 0", so VEL > 0 goes where VEL = 0 goes.  The listing subtracts
  ! where Table 2 adds (E-DUGL4-2): the listing is kept.
  pure real(dp) function dugl4(ugol1, ugold, vel)
    !: UGOL1 : real -- Angle of the assumed direction, radians.
    !: UGOLD : real -- Angle subtracted when VEL < 0 (usually PI).
    !: VEL : real -- The solved magnitude whose sign decides.
    real(dp), intent(in) :: ugol1, ugold, vel
    if (vel < 0.0_dp) then
      dugl4 = ugol1 - ugold
    else
      dugl4 = ugol1
    end if
  end function dugl4

  ! II.7, L614-628.  Direction from the projections, in (-pi/2, 3*pi/2).
  ! PRX = 0 gives +-pi/2 by the sign of PRY (+pi/2 for the zero vector).
  pure real(dp) function dugl5(prx, pry)
    !: PRX, PRY : real -- Projections on the x and y axes.
    real(dp), intent(in) :: prx, pry
    if (prx == 0.0_dp) then
      dugl5 = book_sign(pi/2.0_dp, pry)
    else if (prx < 0.0_dp) then
      dugl5 = pi + atan(pry/prx)
    else
      dugl5 = atan(pry/prx)
    end if
  end function dugl5

  ! II.8, L630-639.  FI if FI >= 0, else FI + 2*PI (one wrap only, as printed).
  ! FI in (-ulp, 0) would round to FI + 2*PI = 2*PI, outside [0, 2*PI): 0 is returned,
  ! the same direction to within |FI| (E-DUGOL-1).
  pure real(dp) function dugol(fi)
    !: FI : real -- Angle, radians.
    real(dp), intent(in) :: fi
    if (fi < 0.0_dp) then
      dugol = fi + 2.0_dp*pi
      if (dugol >= 2.0_dp*pi) dugol = 0.0_dp
    else
      dugol = fi
    end if
  end function dugol

  ! II.9, L641-644.  z-component of r x F: R*F*sin(G - FI), written as printed.
  pure real(dp) function dmomnt(r, fi, f, g)
    !: R, FI : real -- Magnitude and direction of the arm (radius vector of the point of
    !:     application).
    !: F, G : real -- Magnitude and direction of the force.
    real(dp), intent(in) :: r, fi, f, g
    dmomnt = r*cos(fi)*f*sin(g) - r*sin(fi)*f*cos(g)
  end function dmomnt

  ! II.10, L648-660.  Angular velocity (or acceleration) |VEKTOR/RAZMER| with the sign of
  ! UGOL (normally the vector's direction minus the link's).
  pure real(dp) function domega(razmer, vektor, ugol)
    !: RAZMER : length -- Link length, > 0.
    !: VEKTOR : real -- Relative velocity (or tangential acceleration); only its magnitude
    !:     is used.
    !: UGOL : real -- The angle whose sign gives the sense of rotation ("logical flag").
    real(dp), intent(in) :: razmer, vektor, ugol
    if (razmer == 0.0_dp) then
      domega = 0.0_dp
    else
      domega = book_sign(vektor/razmer, ugol)
    end if
  end function domega

  ! II.11, L664-680.  Length and signed direction of (X1,Y1) -> (X2,Y2).  The book's own
  ! guard: coincident points give RZ = 0 and FI = 0.
  pure subroutine dvkt(x1, y1, x2, y2, rz, fi)
    !: X1, Y1, X2, Y2 : real -- Start and end of the segment.
    real(dp), intent(in) :: x1, y1, x2, y2
    real(dp), intent(out) :: rz, fi
    rz = norm2d(x2 - x1, y2 - y1)
    fi = dugl2(x1, y1, x2, y2)
  end subroutine dvkt

  ! II.12, L684-700.  Sum of two vectors given by magnitude and direction (a negative
  ! magnitude means the reversed direction); L >= 0, FI = DUGL5 of the projections.
  pure subroutine dsmvkt(l1, fi1, l2, fi2, l, fi)
    !: L1, FI1 : real -- First vector: magnitude (negative means reversed) and direction,
    !:     radians.
    !: L2, FI2 : real -- Second vector.
    real(dp), intent(in) :: l1, fi1, l2, fi2
    real(dp), intent(out) :: l, fi
    real(dp) :: lx, ly
    lx = l1*cos(fi1) + l2*cos(fi2)
    ly = l1*sin(fi1) + l2*sin(fi2)
    l = norm2d(lx, ly)
    fi = dugl5(lx, ly)
  end subroutine dsmvkt

end module operators
