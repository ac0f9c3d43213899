! synthesis.f90 -- chapter 3, synthesis of linkages with lower pairs (listings III.1-III.4
! and III.6, book lines L887-1440; the example main program III.5 lives in the Python
! package, sarkp.book.prog_iii_5).
!
! Names and argument order are the book's, AAA included (it only steered printing; the
! Python layer prints the report).  Every routine ends with IER (not in the book):
!   st_ok           the mechanism meets the requirement;
!   st_requirement  the requirement cannot be met with these inputs (a coefficient of
!                   speed change KW3 <= 1, coinciding positions, a circle that does not
!                   reach the axis, a non-positive length, a crank that cannot make a full
!                   turn between the requested extreme positions, ...);
!   st_singular     GELG found the 2x2 system singular (collinear points, parallel lines);
!   st_significance GELG reported a loss of significance (IER > 0): result kept.
! On any failure but st_significance every output is 0.
!
! The book writes every straight line as y = k*x + b with a slope k = tan(angle) or
! k = -dx/dy, which divides by zero for a vertical line (E-SYN-1).  Here a line is kept
! as its normal form  n . (x, y) = n . p  with a unit normal n: the same line, the same
! 2x2 systems for GELG, no division.  Only DSNTZ3's as-printed path keeps the slopes,
! because its printed result depends on truncating two of them to integers.
module synthesis
  use prmtr, only: dp, pi, printed_mode, book_sign, st_ok, st_singular, &
                   st_significance, st_requirement
  use operators, only: dugl2
  use gelg_mod, only: gelg2
  implicit none
  private
  public :: dsntzr, dsntz1, dsntz2, dsntz3, dsntzk


  ! The crank pivot A found by the last DSNTZ2 call: the book prints XA, YA in DSNTZ2's
  ! report (L1174-1179) but does not return them; the Python layer reads them here.

contains

  ! ---- private helpers -------------------------------------------------------------

  ! Row of a 2x2 system for the line through (px, py) with direction angle ang:
  ! -sin(ang)*x + cos(ang)*y = -sin(ang)*px + cos(ang)*py.
  subroutine line_dir(px, py, ang, a1, a2, c)
    real(dp), intent(in) :: px, py, ang
    real(dp), intent(out) :: a1, a2, c
    a1 = -sin(ang)
    a2 = cos(ang)
    c = a1*px + a2*py
  end subroutine line_dir

  ! Row for the perpendicular bisector of (x1,y1)-(x2,y2): unit normal along the chord.
  ! ok = .false. when the two points coincide (to rounding).
  subroutine line_bisector(x1, y1, x2, y2, a1, a2, c, ok)
    real(dp), intent(in) :: x1, y1, x2, y2
    real(dp), intent(out) :: a1, a2, c
    logical, intent(out) :: ok
    real(dp) :: d, scale
    d = hypot(x2 - x1, y2 - y1)
    scale = max(abs(x1), abs(y1), abs(x2), abs(y2))
    ok = d > 64.0_dp*epsilon(1.0_dp)*scale .and. d > 0.0_dp
    a1 = 0.0_dp
    a2 = 0.0_dp
    c = 0.0_dp
    if (.not. ok) return
    a1 = (x2 - x1)/d
    a2 = (y2 - y1)/d
    c = a1*0.5_dp*(x1 + x2) + a2*0.5_dp*(y1 + y2)
  end subroutine line_bisector

  ! The four-bar A-B-C-D (crank l1 = AB, coupler l2 = BC, rocker l3 = DC, frame l0 = AD)
  ! found from the extreme rocker positions C1 (crank and coupler stretched out) and C2
  ! (folded) meets its requirement only if the crank makes full turns (Grashof crank-
  ! rocker, no change point) and both extreme positions lie on the same assembly branch,
  ! i.e. on the same side of the frame line AD.
  logical function crank_rocker_ok(l1, l2, l3, l0, xa, ya, xd, yd, xc1, yc1, xc2, yc2)
    real(dp), intent(in) :: l1, l2, l3, l0, xa, ya, xd, yd, xc1, yc1, xc2, yc2
    real(dp) :: s1, s2
    crank_rocker_ok = .false.
    if (.not. (l1 > 0.0_dp .and. l2 > 0.0_dp .and. l3 > 0.0_dp .and. l0 > 0.0_dp)) return
    if (.not. (l0 + l1 < l2 + l3)) return            ! |BD| never exceeds l2 + l3
    if (.not. (abs(l0 - l1) > abs(l2 - l3))) return  ! |BD| never falls below |l2 - l3|
    s1 = (xd - xa)*(yc1 - ya) - (yd - ya)*(xc1 - xa)
    s2 = (xd - xa)*(yc2 - ya) - (yd - ya)*(xc2 - xa)
    crank_rocker_ok = (s1 > 0.0_dp .and. s2 > 0.0_dp) .or. (s1 < 0.0_dp .and. s2 < 0.0_dp)
  end function crank_rocker_ok

  ! ---- sarkp extension: the transmission angle over the full crank turn --------------
  ! Every synthesis routine also returns GMIN_TURN, GMAX_TURN, the smallest and largest
  ! transmission angle the mechanism it built reaches over a full turn of the crank (the
  ! book controls it at most at the two extreme positions).  The transmission angle is the
  ! angle BCD between the coupler and the rocker, in [0, pi] (DSNTZ2's GMIN, GMAX); a
  ! transmission is poor where it nears 0 or pi, and 0 or pi means the linkage locks
  ! there (it cannot make a full turn).

  ! Four-bar, crank l1 = AB about A, coupler l2 = BC, rocker l3 = DC about D, frame l0:
  ! cos(BCD) = (l2**2 + l3**2 - BD**2)/(2 l2 l3) grows with BD, and BD runs over
  ! [|l0 - l1|, l0 + l1], its ends where the crank is collinear with the frame.
  subroutine fourbar_turn(l1, l2, l3, l0, gmin, gmax)
    real(dp), intent(in) :: l1, l2, l3, l0
    real(dp), intent(out) :: gmin, gmax
    gmin = 0.0_dp
    gmax = 0.0_dp
    if (.not. (l1 > 0.0_dp .and. l2 > 0.0_dp .and. l3 > 0.0_dp .and. l0 > 0.0_dp)) return
    gmin = angle_bcd(l2, l3, abs(l0 - l1))
    gmax = angle_bcd(l2, l3, l0 + l1)
  end subroutine fourbar_turn

  pure real(dp) function angle_bcd(l2, l3, bd)
    real(dp), intent(in) :: l2, l3, bd
    real(dp) :: c
    c = ((l2*l2 + l3*l3) - bd*bd)/(2.0_dp*l2*l3)
    angle_bcd = acos(max(-1.0_dp, min(1.0_dp, c)))
  end function angle_bcd

  ! Crank-slider, crank l1, coupler l2, guide at the signed offset e from the crank pivot
  ! (along the normal n): the rocker is at infinity along -n, and cos(BCD) =
  ! (e - l1 sin(theta))/l2 with theta the crank angle from the guide; its extremes are
  ! where the crank is perpendicular to the guide.
  subroutine slider_turn(l1, l2, e, gmin, gmax)
    real(dp), intent(in) :: l1, l2, e
    real(dp), intent(out) :: gmin, gmax
    gmin = 0.0_dp
    gmax = 0.0_dp
    if (.not. (l1 > 0.0_dp .and. l2 > 0.0_dp)) return
    gmin = acos(max(-1.0_dp, min(1.0_dp, (e + l1)/l2)))
    gmax = acos(max(-1.0_dp, min(1.0_dp, (e - l1)/l2)))
  end subroutine slider_turn

  ! ---- III.1 --------------------------------------------------------------------------

  ! III.1 DSNTZR, L887-1019 (Table 3, L897-917).  Three-position synthesis of a four-bar
  ! (LO = three equal frame lengths, L3 = rocker, FI3 = rocker angles) or of a crank-
  ! slider (LO = the three slider positions along the guide, L3 = the offset of the guide,
  ! FI3 = three equal angles of the offset, 1.570 in the book).  Inversion about the
  ! crank: C_i = LO(i)*e(d) + L3*e(FI3(i) + d), d = FI1(1) - FI1(i); B = centre of the
  ! circle through C_1, C_2, C_3; L1 = |AB|, L2 = |BC_1|.
  ! FI11 (8th argument, not in the listing): Table 3 step 12, the crank angle of the first
  ! position in the frame A = origin, D (or the guide) along x.  Program X calls DSNTZR
  ! with it (L7316, "FICD1"); program III.5 passes 7 arguments and ignores it.  The
  ! table's arctg(yB/xB) is taken over the full circle (atan2), E-DSNTZR-4.
  ! ERRATA: E-DSNTZR-1 (names F11/F13 = FI1/FI3), E-DSNTZR-2 (dead F11 = F11(K) lines),
  ! E-DSNTZR-3 (8th argument), E-DSNTZR-4 (atan2), E-SYN-1 (no division by yC2 - yC1).
  subroutine dsntzr(lo, l3, fi1, fi3, aaa, l1, l2, fi11, gmin_turn, gmax_turn, ier)
    !: LO : table(3) real -- Four-bar: the frame length AD three times. Crank-slider: the
    !:     three positions of the slider pin along the guide (abscissae measured from the
    !:     crank pivot).
    !: L3 : real -- Four-bar: the rocker length DC. Crank-slider: the offset of the slider
    !:     pin (the guide is the line at distance L3 in the direction FI3); any sign.
    !: FI1 : table(3) real -- Crank angles of the three positions; only the differences
    !:     count.
    !: FI3 : table(3) real -- Four-bar: the rocker angles. Crank-slider: three equal angles
    !:     giving the direction of the offset (1.570 in the book's example, L1366).
    !: AAA : flag -- 0 prints the book's report (L1006-1017); anything else is silent
    !:     (default).
    real(dp), intent(in) :: lo(3), l3, fi1(3), fi3(3), aaa
    real(dp), intent(out) :: l1, l2, fi11, gmin_turn, gmax_turn
    integer, intent(out) :: ier
    real(dp) :: xc(3), yc(3), a(2, 2), c(2), d, scale, t1, t2, t3
    logical :: ok1, ok2, ok3
    integer :: k

    l1 = 0.0_dp
    l2 = 0.0_dp
    fi11 = 0.0_dp
    gmin_turn = 0.0_dp
    gmax_turn = 0.0_dp
    do k = 1, 3
      d = fi1(1) - fi1(k)
      xc(k) = lo(k)*cos(d) + l3*cos(fi3(k) + d)
      yc(k) = lo(k)*sin(d) + l3*sin(fi3(k) + d)
    end do
    call line_bisector(xc(1), yc(1), xc(2), yc(2), a(1, 1), a(1, 2), c(1), ok1)
    call line_bisector(xc(2), yc(2), xc(3), yc(3), a(2, 1), a(2, 2), c(2), ok2)
    call line_bisector(xc(1), yc(1), xc(3), yc(3), t1, t2, t3, ok3)
    if (.not. (ok1 .and. ok2 .and. ok3)) then       ! two positions of C coincide
      ier = st_requirement
      return
    end if
    call gelg2(a, c, ier)
    if (ier == st_singular) return                   ! C_1, C_2, C_3 on one line
    scale = maxval(abs(xc)) + maxval(abs(yc))
    l1 = hypot(c(1), c(2))
    l2 = hypot(xc(1) - c(1), yc(1) - c(2))
    if (.not. (l1 > 64.0_dp*epsilon(1.0_dp)*scale)) then   ! B at the crank pivot A
      l1 = 0.0_dp
      l2 = 0.0_dp
      ier = st_requirement
      return
    end if
    fi11 = atan2(c(2), c(1))
    ! extension: equal FI3 = a crank-slider (guide along the frame at the offset
    ! L3 sin(FI3)), else a four-bar with the frame LO(1)
    if (fi3(1) == fi3(2) .and. fi3(2) == fi3(3)) then
      call slider_turn(l1, l2, l3*sin(fi3(1)), gmin_turn, gmax_turn)
    else
      call fourbar_turn(l1, l2, l3, lo(1), gmin_turn, gmax_turn)
    end if
  end subroutine dsntzr

  ! ---- III.2 --------------------------------------------------------------------------

  ! III.2 DSNTZ1, L1023-1105 (Table 4, L1034-1051).  Four-bar from the two extreme rocker
  ! angles FI31, FI32, the rocker L3 with pivot D = (XD, 0), and the coefficient of speed
  ! change KW3, BETA = PI (KW3 - 1)/(KW3 + 1); the crank pivot A on the x axis, Q picks
  ! the intersection (sign only, Q = 0 acts as +1): XA = XE + SIGN(SQRT(R**2 - YE**2), Q),
  ! Q = -1 the smaller XA ("A between O and D" in the book's example, L1055).
  ! Both modes: C1 = D + L3 e(FI31), C2 = D + L3 e(FI32); E on the perpendicular bisector
  ! SD of C1C2; circle (E, R = |EC1|); A where it meets the x axis; L1 = (|AC1|-|AC2|)/2,
  ! L2 = |AC1| - L1, LO = |XD - XA| (Table 4 rows 9-13).  They differ in E (E-DSNTZ1-4):
  !   corrected (printed_mode == 0): the prose's construction (L1029, L1053): the lines
  !     through C1 and C2 at the angle BETA to SD meet on SD at E, so angle C1EC2 =
  !     2 BETA and every point of the circle on D's side of the chord C1C2 sees it under
  !     the inscribed angle C1AC2 = BETA, the angle the crank must turn beyond a half
  !     turn: KW3 = (PI + BETA)/(PI - BETA) exactly.  With S the midpoint and
  !     h = |C1C2|/2, E = S + h cot(BETA) (D - S)/|SD|, written as vectors (no slopes).
  !     E is taken towards D: the x axis passes through D, which a crank-rocker's swing
  !     (< PI) keeps off the chord, and this side gives the book's Q convention.  (The
  !     mirror arc, beyond the chord, also sees C1C2 under BETA; where the axis meets it
  !     a further, less common, solution may exist, which the book does not consider.)  An A
  !     on the far side of the chord (there the circle sees C1C2 under PI - BETA) is
  !     st_requirement, and so is |SD| = 0 (a swing of PI: no crank-rocker).
  !   as-printed (printed_mode /= 0): the LISTING (L1077-1078, Table 4 rows 4-8): E on SD
  !     and on the line through C1 at the fixed direction FI31 + BETA.  It keeps the
  !     extreme positions but makes C1AC2 = PSI/2 - BETA, not BETA (book example:
  !     K = 1.3077 for 1.5).  Both lines in normal form (E-SYN-1), solved by GELG.
  ! Neither reproduces Fig. 10's 0.411/0.904/0.858 (corrected 0.390/0.722/0.650, listing
  ! 0.406/0.835/0.782): E-DSNTZ1-4.
  ! ERRATA: E-DSNTZ1-1 (KCIE = KC1E), E-DSNTZ1-2 (debug PRINT 5 dropped), E-DSNTZ1-3
  ! (vertical bisector: YC2 = YC1 in the book's own example), E-DSNTZ1-4, E-DSNTZ1-6,
  ! E-SYN-1, E-SYN-2.
  subroutine dsntz1(kw3, fi31, fi32, l3, xd, q, aaa, l1, l2, lo, gmin_turn, gmax_turn, ier)
    !: KW3 : real -- Coefficient of speed change of the rocker, omega_return / omega_work (>
    !:     1).
    !: FI31, FI32 : real -- Rocker angles of the two extreme positions: C1 (crank and
    !:     coupler stretched out) and C2 (folded).
    !: L3 : length -- Rocker length DC (> 0).
    !: XD : real -- Abscissa of the rocker pivot D = (XD, 0); the crank pivot A is on the x
    !:     axis.
    !: Q : real -- Assembly variant, by its sign only (0 acts as +1): -1 takes the smaller
    !:     XA (A "between O and D" in the book's example, L1055), +1 the other intersection.
    !: AAA : flag -- 0 prints the book's report (L1097-1103); anything else is silent
    !:     (default).
    real(dp), intent(in) :: kw3, fi31, fi32, l3, xd, q, aaa
    real(dp), intent(out) :: l1, l2, lo, gmin_turn, gmax_turn
    integer, intent(out) :: ier
    real(dp) :: beta, xc1, yc1, xc2, yc2, a(2, 2), c(2), xe, ye, r, disc, xa, ac1, ac2
    real(dp) :: xs, ys, h, sd, t
    logical :: ok

    l1 = 0.0_dp
    l2 = 0.0_dp
    lo = 0.0_dp
    gmin_turn = 0.0_dp
    gmax_turn = 0.0_dp
    ier = st_requirement
    if (.not. (kw3 > 1.0_dp .and. l3 > 0.0_dp)) return
    beta = pi*(kw3 - 1.0_dp)/(kw3 + 1.0_dp)
    xc1 = xd + l3*cos(fi31)
    yc1 = l3*sin(fi31)
    xc2 = xd + l3*cos(fi32)
    yc2 = l3*sin(fi32)
    call line_bisector(xc1, yc1, xc2, yc2, a(1, 1), a(1, 2), c(1), ok)
    if (.not. ok) return                             ! FI31 = FI32: one position only
    xs = 0.5_dp*(xc1 + xc2)
    ys = 0.5_dp*(yc1 + yc2)
    sd = hypot(xd - xs, ys)
    if (printed_mode /= 0) then
      ! E-DSNTZ1-4, as printed: KC1E = TAN(FI31 + BETA) (L1078), E on SD and on that line.
      call line_dir(xc1, yc1, fi31 + beta, a(2, 1), a(2, 2), c(2))
      call gelg2(a, c, ier)
      if (ier == st_singular) return
      xe = c(1)
      ye = c(2)
    else
      ! E-DSNTZ1-4, corrected: the prose (L1029, L1053), angle C1EC2 = 2 BETA, E towards D.
      if (.not. sd > 64.0_dp*epsilon(1.0_dp)*l3) return   ! D on C1C2: a swing of PI
      h = 0.5_dp*hypot(xc2 - xc1, yc2 - yc1)
      t = h*cos(beta)/sin(beta)                      ! signed |SE| along S -> D
      xe = xs + t*(xd - xs)/sd
      ye = ys + t*(0.0_dp - ys)/sd
      ier = st_ok
    end if
    r = hypot(xe - xc1, ye - yc1)
    disc = (r - ye)*(r + ye)
    if (disc < 0.0_dp) then                          ! the circle misses the x axis
      ier = st_requirement
      return
    end if
    xa = xe + book_sign(sqrt(disc), q)
    if (printed_mode == 0) then
      ! A must be on the arc seen under BETA: on D's side of the chord C1C2.
      if (.not. ((xa - xs)*(xd - xs) + (0.0_dp - ys)*(0.0_dp - ys) > 0.0_dp)) then
        ier = st_requirement
        return
      end if
    end if
    ac1 = hypot(xa - xc1, yc1)
    ac2 = hypot(xa - xc2, yc2)
    l1 = 0.5_dp*(ac1 - ac2)
    l2 = ac1 - l1
    lo = abs(xd - xa)
    if (.not. crank_rocker_ok(l1, l2, l3, lo, xa, 0.0_dp, xd, 0.0_dp, xc1, yc1, xc2, yc2)) then
      l1 = 0.0_dp
      l2 = 0.0_dp
      lo = 0.0_dp
      ier = st_requirement
      return
    end if
    call fourbar_turn(l1, l2, l3, lo, gmin_turn, gmax_turn)   ! extension
  end subroutine dsntz1

  ! ---- III.3 --------------------------------------------------------------------------

  ! III.3 DSNTZ2, L1109-1181 (Table 5, L1114-1130).  Four-bar from KW3, the first extreme
  ! rocker angle FI3, the rocker L3 with pivot D = (XD, 0) and the transmission angles
  ! GMIN, GMAX at the two extreme positions: PSI = BETA + GMAX - GMIN, C2 at FI3 + PSI,
  ! A = intersection of the lines through C1 at FI3 - GMIN and through C2 at
  ! FI3 + PSI - GMAX.  The book prints the crank pivot XA, YA (L1173) but has no argument
  ! for it: sarkp returns it after LO.
  ! ERRATA: E-DSNTZ2-1 (KC1A + TAN = KC1A = TAN), E-DSNTZ2-4 (PSI <= 0), E-SYN-1.
  subroutine dsntz2(kw3, fi3, l3, xd, gmin, gmax, aaa, l1, l2, lo, xa, ya, gmin_turn, &
                    gmax_turn, ier)
    !: KW3 : real -- Coefficient of speed change of the rocker (> 1).
    !: FI3 : real -- Rocker angle of the first (stretched-out) extreme position.
    !: L3 : length -- Rocker length DC (> 0).
    !: XD : real -- Abscissa of the rocker pivot D = (XD, 0).
    !: GMIN, GMAX : real -- Transmission angles at the two extreme positions.
    !: AAA : flag -- 0 prints the book's report with XA and YA (L1169-1179); else silent
    !:     (default).
    real(dp), intent(in) :: kw3, fi3, l3, xd, gmin, gmax, aaa
    real(dp), intent(out) :: l1, l2, lo, xa, ya, gmin_turn, gmax_turn
    integer, intent(out) :: ier
    real(dp) :: beta, psi, xc1, yc1, xc2, yc2, a(2, 2), c(2), ac1, ac2, t1, t2, t3
    logical :: ok

    l1 = 0.0_dp
    l2 = 0.0_dp
    lo = 0.0_dp
    xa = 0.0_dp
    ya = 0.0_dp
    gmin_turn = 0.0_dp
    gmax_turn = 0.0_dp
    ier = st_requirement
    if (.not. (kw3 > 1.0_dp .and. l3 > 0.0_dp)) return
    beta = pi*(kw3 - 1.0_dp)/(kw3 + 1.0_dp)
    psi = beta + gmax - gmin
    ! E-DSNTZ2-4 (L1143): the construction turns the rocker counter-clockwise by PSI from C1 to C2;
    ! with PSI <= 0 the lines through C1, C2 make the angles pi - GMIN, pi - GMAX with the
    ! rocker, and no four-bar has GMIN at the extended and GMAX at the folded position
    ! (any that has swings by BETA + GMAX - GMIN): the requirement cannot be met.
    if (.not. (psi > 0.0_dp)) return
    xc1 = xd + l3*cos(fi3)
    yc1 = l3*sin(fi3)
    xc2 = xd + l3*cos(fi3 + psi)
    yc2 = l3*sin(fi3 + psi)
    call line_bisector(xc1, yc1, xc2, yc2, t1, t2, t3, ok)
    if (.not. ok) return                             ! PSI = 0 (mod 2 pi)
    call line_dir(xc1, yc1, fi3 - gmin, a(1, 1), a(1, 2), c(1))
    call line_dir(xc2, yc2, fi3 + psi - gmax, a(2, 1), a(2, 2), c(2))
    call gelg2(a, c, ier)
    if (ier == st_singular) return                   ! the two lines are parallel
    xa = c(1)
    ya = c(2)
    ac1 = hypot(xc1 - xa, yc1 - ya)
    ac2 = hypot(xc2 - xa, yc2 - ya)
    l1 = 0.5_dp*(ac1 - ac2)
    l2 = ac1 - l1
    lo = hypot(xd - xa, ya)
    if (.not. crank_rocker_ok(l1, l2, l3, lo, xa, ya, xd, 0.0_dp, xc1, yc1, xc2, yc2)) then
      l1 = 0.0_dp
      l2 = 0.0_dp
      lo = 0.0_dp
      xa = 0.0_dp
      ya = 0.0_dp
      ier = st_requirement
      return
    end if
    call fourbar_turn(l1, l2, l3, lo, gmin_turn, gmax_turn)   ! extension
  end subroutine dsntz2

  ! ---- III.4 --------------------------------------------------------------------------

  ! III.4 DSNTZ3, L1185-1264 (Table 6, L1192-1212).  Four-bar from two positions of the
  ! coupler, B1 C1 and B2 C2 (B the crank pin, C the rocker pin), the crank rotation FI1
  ! between them and the direction ALC1 of the velocity of C1.  A = intersection of the
  ! perpendicular bisector of B1B2 with the line through B1 at FIB1B2 - PI/2 + FI1/2
  ! (triangle A B1 B2 is isosceles with apex angle FI1); D = intersection of the
  ! perpendicular bisector of C1C2 with the normal to the velocity of C1.  Outputs
  ! L1 = |AB1|, L3 = |DC1|, LO = |AD| (Table 6; the listing's header says L2, E-DSNTZ3-1).
  ! As-printed (printed_mode /= 0): the run behind Fig. 10 had KB1A, KS2D and the local
  ! L3 as implicit INTEGERs (E-DSNTZ3-2): KB1A and KS2D truncated to integers, L3 too
  ! (Fig. 10 prints L3 = 0.0).  That path keeps the book's slopes.
  ! ERRATA: E-DSNTZ3-1, E-DSNTZ3-2, E-DSNTZ3-3 (GELG call missing M = 2), E-SYN-1.
  subroutine dsntz3(xb1, yb1, xb2, yb2, xc1, yc1, xc2, yc2, fi1, alc1, aaa, l1, l3, lo, &
                    gmin_turn, gmax_turn, ier)
    !: XB1, YB1, XB2, YB2 : real -- The crank pin B in the two positions.
    !: XC1, YC1, XC2, YC2 : real -- The rocker pin C in the two positions (|B1C1| should
    !:     equal |B2C2|; not checked, the routine does not use the coupler length).
    !: FI1 : real -- Crank rotation from position 1 to position 2. With the listing's line
    !:     direction the crank turns from B1 to B2 clockwise by FI1 (i.e. by -FI1 in the
    !:     counter-clockwise sense; verified in tests).
    !: ALC1 : real -- Direction of the velocity of C in position 1.
    !: AAA : flag -- 0 prints the book's report (L1256-1262); anything else is silent
    !:     (default).
    real(dp), intent(in) :: xb1, yb1, xb2, yb2, xc1, yc1, xc2, yc2, fi1, alc1, aaa
    real(dp), intent(out) :: l1, l3, lo, gmin_turn, gmax_turn
    integer, intent(out) :: ier
    real(dp) :: a1(2, 2), c1(2), a2(2, 2), c2(2), fib1b2, fic1c2, t1, t2, t3
    real(dp) :: ks1a, ks2d, kb1a, kc1d, tb, tc, ta
    logical :: okb, okc
    integer :: st1, st2

    l1 = 0.0_dp
    l3 = 0.0_dp
    lo = 0.0_dp
    gmin_turn = 0.0_dp
    gmax_turn = 0.0_dp
    ier = st_requirement
    call line_bisector(xb1, yb1, xb2, yb2, t1, t2, t3, okb)
    call line_bisector(xc1, yc1, xc2, yc2, t1, t2, t3, okc)
    if (.not. (okb .and. okc)) return                ! B1 = B2 or C1 = C2
    fib1b2 = dugl2(xb1, yb1, xb2, yb2)
    fic1c2 = dugl2(xc1, yc1, xc2, yc2)

    if (printed_mode /= 0) then
      ! The book's slopes (L1226-1229); E-DSNTZ3-2: KB1A, KS2D implicit INTEGER.
      tb = tan(fib1b2)
      tc = tan(fic1c2)
      ta = tan(alc1)
      if (tb == 0.0_dp .or. tc == 0.0_dp .or. ta == 0.0_dp) then   ! a vertical line
        ier = st_singular
        return
      end if
      ks1a = -1.0_dp/tb
      ks2d = aint(-1.0_dp/tc)
      kb1a = aint(tan(fib1b2 - pi/2.0_dp + fi1/2.0_dp))
      kc1d = -1.0_dp/ta
      a1 = reshape([-kb1a, -ks1a, 1.0_dp, 1.0_dp], [2, 2])
      c1 = [yb1 - kb1a*xb1, 0.5_dp*(yb1 + yb2) - ks1a*0.5_dp*(xb1 + xb2)]
      a2 = reshape([-kc1d, -ks2d, 1.0_dp, 1.0_dp], [2, 2])
      c2 = [yc1 - kc1d*xc1, 0.5_dp*(yc1 + yc2) - ks2d*0.5_dp*(xc1 + xc2)]
    else
      call line_dir(xb1, yb1, fib1b2 - pi/2.0_dp + fi1/2.0_dp, a1(1, 1), a1(1, 2), c1(1))
      call line_bisector(xb1, yb1, xb2, yb2, a1(2, 1), a1(2, 2), c1(2), okb)
      call line_dir(xc1, yc1, alc1 + pi/2.0_dp, a2(1, 1), a2(1, 2), c2(1))
      call line_bisector(xc1, yc1, xc2, yc2, a2(2, 1), a2(2, 2), c2(2), okc)
    end if
    call gelg2(a1, c1, st1)
    call gelg2(a2, c2, st2)
    if (st1 == st_singular .or. st2 == st_singular) then
      ier = st_singular
      return
    end if
    l1 = hypot(c1(1) - xb1, c1(2) - yb1)
    l3 = hypot(xc1 - c2(1), yc1 - c2(2))
    lo = hypot(c2(1) - c1(1), c2(2) - c1(2))
    if (printed_mode /= 0) l3 = aint(l3)             ! E-DSNTZ3-2: INTEGER L3
    ier = max(st1, st2)
    if (.not. (l1 > 0.0_dp .and. lo > 0.0_dp .and. (l3 > 0.0_dp .or. printed_mode /= 0))) then
      l1 = 0.0_dp
      l3 = 0.0_dp
      lo = 0.0_dp
      ier = st_requirement
    end if
    ! extension: the coupler is B1C1
    call fourbar_turn(l1, hypot(xc1 - xb1, yc1 - yb1), l3, lo, gmin_turn, gmax_turn)
  end subroutine dsntz3

  ! ---- III.6 --------------------------------------------------------------------------

  ! III.6 DSNTZK, L1397-1437.  Slotted-link (crank and slotted lever) mechanism from KW3,
  ! the stroke S, the reserve H and Q (Q = 0: rotating slotted link, otherwise
  ! oscillating).  BETA = (PI/2)(KW3-1)/(KW3+1) is half the swing; oscillating:
  ! LAMBDA = sin(BETA), L3 = S/(2 LAMBDA); rotating: LAMBDA = 1/sin(BETA), L3 = S/2;
  ! then LO = (L3 - H)/(1 + LAMBDA), L1 = LAMBDA*LO.  No printed example.
  ! ERRATA: E-DSNTZK-1 (statement order), E-DSNTZK-2 (S and H glosses).
  subroutine dsntzk(kw3, s, h, q, aaa, l1, lo, l3, gmin_turn, gmax_turn, ier)
    !: KW3 : real -- Coefficient of speed change of the output (> 1).
    !: S : length -- Stroke (> 0): the chord swept by the end of the oscillating slotted
    !:     link, or the stroke 2 L3 of a slider driven by the end of the rotating one along
    !:     a line through the link's pivot perpendicular to the centre line. The listing's
    !:     comment says "stroke of the slotted link", the prose (L1399) "stroke of the
    !:     driven link" (ERRATA E-DSNTZK-2).
    !: H : real >= 0 -- Reserve (>= 0): how much longer the slotted link is than the largest
    !:     distance LO + L1 from its pivot to the crank pin.
    !: Q : real -- 0 for a rotating slotted link, any other value for an oscillating one
    !:     (L1401).
    !: AAA : flag -- 0 prints the book's report (L1432-1435); anything else is silent
    !:     (default).
    real(dp), intent(in) :: kw3, s, h, q, aaa
    real(dp), intent(out) :: l1, lo, l3, gmin_turn, gmax_turn
    integer, intent(out) :: ier
    real(dp) :: beta, lyamda

    l1 = 0.0_dp
    lo = 0.0_dp
    l3 = 0.0_dp
    gmin_turn = 0.0_dp
    gmax_turn = 0.0_dp
    ier = st_requirement
    if (.not. (kw3 > 1.0_dp .and. s > 0.0_dp .and. h >= 0.0_dp)) return
    beta = pi/2.0_dp*((kw3 - 1.0_dp)/(kw3 + 1.0_dp))
    if (q == 0.0_dp) then
      lyamda = 1.0_dp/sin(beta)
      l3 = s/2.0_dp
    else
      lyamda = sin(beta)
      l3 = s/(2.0_dp*lyamda)
    end if
    lo = (l3 - h)/(1.0_dp + lyamda)
    l1 = lyamda*lo
    if (.not. (lo > 0.0_dp .and. l1 > 0.0_dp)) then  ! the reserve H eats the whole link
      l1 = 0.0_dp
      lo = 0.0_dp
      l3 = 0.0_dp
      return
    end if
    ! extension: the block on the crank pin pushes the slotted link along the normal to
    ! the slot, the direction in which the link's point under it moves: the transmission
    ! angle is a right angle in every position
    gmin_turn = pi/2.0_dp
    gmax_turn = pi/2.0_dp
    ier = st_ok
  end subroutine dsntzk

end module synthesis
