! numerics.f90 -- the numerical toolkit of the kinematics (chapter 4) and of the whole
! mechanism (mechanism.f90), written once for both: GELG's 2x2 elimination with the error
! estimate of the dead-centre policy (solve2e, factor2, solve2f; solve_kind5 for kind 5),
! the policy itself (policy, settle, failed), the triangle's apex (tri_apex, tri_angles,
! apex_vectors, unscale), angle helpers (wrap_pi, angle_sensitivity, acc_dir, turn,
! quarter, components).  The dead-centre policy and the numerical rewrites are described
! in the header of kinematics.f90.  Moved out of kinematics.f90 unchanged (issue 19).
module numerics
  use prmtr, only: dp, pi, printed_mode, st_ok, st_assembly, st_singular, &
                   st_significance, st_range, st_digits, norm2d
  use operators, only: dugl3
  use gelg_mod, only: gelg2_lu, gelg2_solve
  implicit none
  private

  real(dp), parameter :: uround = epsilon(1.0_dp)/2     ! unit roundoff, 2**-53
  ! A 2x2 system's matrix after GELG's elimination (factor2), with what solve2e's error
  ! estimate needs of it: |A|_F and det A of the entries as given.
  type :: system2
    real(dp) :: lu(2, 2), amax, r(2), na, det, nadet
    integer :: ipv, jpv, st
  end type system2
  public :: uround, system2
  public :: solve2e, factor2, solve2f, solve_kind5, policy, settle, failed, bound2
  public :: wrap_pi, angle_sensitivity, tri_angles, tri_apex, apex_vectors, unscale
  public :: acc_dir, turn, components, quarter

contains

  ! GELG(Y, X, 2, 1, 0.0001, IER) on the system a11*y1 + a12*y2 = b1, a21*y1 + a22*y2 = b2
  ! (X(i,j) = aij, as the book fills X), the GELG code mapped to a status, plus the error
  ! estimate of the dead-centre policy (module header).  The matrix
  ! entries are components of unit vectors whose directions are known to +-da (radians);
  ! the right-hand side is known to +-db (absolute, as a vector) and sb is the size of the
  ! data it was built from (the sum of the moduli of its terms).  By the perturbation bound
  ! |dy| <= |A^-1| (|dA| |y| + |db|) with Frobenius norms (|A^-1|_F = |A|_F/|det A| for a
  ! 2x2), plus the elimination's own backward error (a few units of roundoff of |A|):
  !   rel = |A^-1|_F ((2 da + 4u |A|_F) |y| + db) / max(|y|, sb/|A|_F),
  ! the error relative to the larger of the result and the size of the data.
  ! A GELG loss-of-significance flag (pivot <= 1e-4 of the largest) is not a status here:
  ! rel measures what is left.
  subroutine solve2e(a11, a12, a21, a22, b1, b2, da, db, sb, y1, y2, st, rel)
    real(dp), intent(in) :: a11, a12, a21, a22, b1, b2, da, db, sb
    real(dp), intent(out) :: y1, y2, rel
    integer, intent(out) :: st
    type(system2) :: f
    call factor2(a11, a12, a21, a22, f)
    call solve2f(f, b1, b2, da, db, sb, y1, y2, st, rel)
  end subroutine solve2e

  ! solve2e in two steps, for two systems with one matrix (DKNMA1's velocities and
  ! accelerations): factor2 does GELG's elimination once, solve2f each right-hand side;
  ! the results are bit for bit those of two solve2e calls.
  subroutine factor2(a11, a12, a21, a22, f)
    real(dp), intent(in) :: a11, a12, a21, a22
    type(system2), intent(out) :: f
    f%lu(1, 1) = a11
    f%lu(2, 1) = a21
    f%lu(1, 2) = a12
    f%lu(2, 2) = a22
    call gelg2_lu(f%lu, f%ipv, f%jpv, f%amax, f%r, f%st)
    f%na = sqrt(a11**2 + a12**2 + a21**2 + a22**2)
    f%det = a11*a22 - a12*a21
    f%nadet = 0.0_dp
    if (f%det /= 0.0_dp) f%nadet = f%na/abs(f%det)  ! |A^-1|_F
  end subroutine factor2

  subroutine solve2f(f, b1, b2, da, db, sb, y1, y2, st, rel)
    type(system2), intent(in) :: f
    real(dp), intent(in) :: b1, b2, da, db, sb
    real(dp), intent(out) :: y1, y2, rel
    integer, intent(out) :: st
    real(dp) :: y(2)
    rel = huge(1.0_dp)
    y1 = 0.0_dp; y2 = 0.0_dp
    if (.not. (abs(b1) <= huge(b1) .and. abs(b2) <= huge(b2))) then
      st = st_range                               ! a term of the right-hand side overflowed
      return
    end if
    st = f%st
    if (failed(st)) return
    y(1) = b1
    y(2) = b2
    call gelg2_solve(f%lu, f%ipv, f%jpv, f%amax, f%r, y, st)
    ! the matrix factored (f%st ok): a refusal of the solve is DGESC2's scaling test or
    ! an overflow, a right-hand side too large for the answer -- a range problem, not a
    ! dead centre (DSKOR1 with VA = 1e300, where W2 = 1.41e300: issue 27)
    if (st == st_singular) st = st_range
    if (failed(st)) return
    y1 = y(1)
    y2 = y(2)
    st = st_ok
    if (f%det == 0.0_dp) then
      st = st_singular
      y1 = 0.0_dp; y2 = 0.0_dp
      return
    end if
    rel = bound2(f%na, f%nadet, y1, y2, da, db, sb)
  end subroutine solve2f

  ! solve2f's error bound of a 2x2 solution y (module kinematics' header): |A|_F = na,
  ! |A^-1|_F = nadet, the entries' direction errors da, the right-hand side's db, the
  ! size of the data sb; relative to max(|y|, sb/|A|_F).
  pure real(dp) function bound2(na, nadet, y1, y2, da, db, sb)
    real(dp), intent(in) :: na, nadet, y1, y2, da, db, sb
    real(dp) :: ny, den
    ny = norm2d(y1, y2)
    den = max(ny, sb/na)
    if (den == 0.0_dp) then
      bound2 = 0.0_dp                             ! no data: y = 0 exactly
    else
      bound2 = nadet*((2.0_dp*da + 4.0_dp*uround*na)*ny + db)/den
    end if
  end function bound2

  ! The kind-5 system  y1*e(FIM + T2) - y2*e(FIM) = b  written in the frame of the guide
  ! (b1, b2 = components of b along e(FIM), e(FIM + pi/2)):  y1*cos(T2) - y2 = b1,
  ! y1*sin(T2) = b2.  FIM + T2 is never formed, so a small T2 keeps its digits.  db, sb
  ! as for solve2e; the error bound is propagated through the two formulas (sin and cos
  ! of T2 to an ulp, T2 itself known to an ulp).  SIN(T2) = 0: st_singular.
  pure subroutine solve_kind5(t2, b1, b2, db, sb, y1, y2, st, rel)
    real(dp), intent(in) :: t2, b1, b2, db, sb
    real(dp), intent(out) :: y1, y2, rel
    integer, intent(out) :: st
    real(dp) :: s, c, ds, dc, e1, e2, den
    y1 = 0.0_dp; y2 = 0.0_dp
    rel = huge(1.0_dp)
    st = st_singular
    s = sin(t2)
    c = cos(t2)
    if (s == 0.0_dp) return                       ! slot parallel to the guide
    y1 = b2/s
    y2 = y1*c - b1
    if (.not. (abs(y1) <= huge(y1) .and. abs(y2) <= huge(y2))) then
      y1 = 0.0_dp; y2 = 0.0_dp
      st = st_range
      return
    end if
    st = st_ok
    ds = 2.0_dp*uround*(abs(s) + abs(t2*c))
    dc = 2.0_dp*uround*(abs(c) + abs(t2*s))
    e1 = db/abs(s) + abs(y1)*(ds/abs(s) + 2.0_dp*uround)
    e2 = e1*abs(c) + abs(y1)*dc + db + 2.0_dp*uround*(abs(y1*c) + abs(b1) + abs(y2))
    den = max(norm2d(y1, y2), sb)
    if (den == 0.0_dp) then
      rel = 0.0_dp
    else
      rel = norm2d(e1, e2)/den
    end if
  end subroutine solve_kind5

  ! The status of the dead-centre policy from the estimated relative error est:
  !   est > 0.1 (or NaN): st_singular -- not even the first significant digit is assured;
  !   1e-8 < est <= 0.1 : 100 + d, d = floor(-log10(est)) in 1..7 correct digits;
  !   est <= 1e-8       : st_ok.
  pure integer function policy(est)
    real(dp), intent(in) :: est
    integer :: d
    if (.not. (est <= 0.1_dp)) then
      policy = st_singular
    else if (est > 1.0e-8_dp) then
      d = int(floor(-log10(est)))
      policy = st_digits + max(1, min(7, d))
    else
      policy = st_ok
    end if
  end function policy

  ! The final status: a failure already found, else a non-finite result (an overflow of
  ! an intermediate or of the answer: st_range), else the policy's verdict on est.
  pure integer function settle(st, est, outs)
    integer, intent(in) :: st
    real(dp), intent(in) :: est, outs(:)
    if (failed(st)) then
      settle = st
    else if (.not. all(abs(outs) <= huge(1.0_dp))) then
      settle = st_range
    else
      settle = policy(est)
    end if
  end function settle

  pure logical function failed(st)
    integer, intent(in) :: st
    failed = st /= st_ok .and. st /= st_significance .and. st <= st_digits
  end function failed

  ! Angle in (-pi, pi] (the DUGL2 range) of an angle in (-5 pi, 5 pi].
  pure real(dp) function wrap_pi(x)
    real(dp), intent(in) :: x
    wrap_pi = x
    do while (wrap_pi > pi)
      wrap_pi = wrap_pi - 2.0_dp*pi
    end do
    do while (wrap_pi <= -pi)
      wrap_pi = wrap_pi + 2.0_dp*pi
    end do
  end function wrap_pi

  ! Error (radians) of an angle found as arccos/arcsin of a quantity c known to +-dc:
  ! dc/sqrt(1 - c**2) away from |c| = 1, sqrt(2 dc) at it (second order).
  pure real(dp) function angle_sensitivity(c, dc)
    real(dp), intent(in) :: c, dc
    real(dp) :: sn
    sn = sqrt(max(0.0_dp, (1.0_dp - abs(c))*(1.0_dp + abs(c))))
    if (sn > 0.0_dp) then
      angle_sensitivity = min(dc/sn, sqrt(2.0_dp*dc))
    else
      angle_sensitivity = sqrt(2.0_dp*dc)
    end if
  end function angle_sensitivity

  ! Angles of the triangle with base d = AC and sides l2 = AB, l3 = CB:
  !   anga = angle BAC, angc = angle BCA   (the book's UGBAC, UGBCA of the cosine law).
  ! Height by Kahan's Heron formula, angles by atan2: accurate for flat triangles too.
  ! The sides are first scaled by a power of 2 (exact; the angles do not change), so that
  ! lengths of 1e-300 or 1e300 neither underflow nor overflow.
  ! dang: how far the angles move when d, l2, l3 move by one rounding (the sensitivity of
  ! the position, radians; h = the triangle's height on d), plus a few roundings of the
  ! computation itself.
  ! st_assembly when the sides violate the triangle inequality by more than rounding.
  pure subroutine tri_angles(d0, l20, l30, anga, angc, dang, st)
    real(dp), intent(in) :: d0, l20, l30
    real(dp), intent(out) :: anga, angc, dang
    integer, intent(out) :: st
    real(dp) :: pa, h, pc
    integer :: e
    call tri_apex(d0, l20, l30, pa, h, pc, e, dang, st)
    anga = 0.0_dp
    angc = 0.0_dp
    if (st /= st_ok) return
    anga = atan2(h, pa)
    angc = atan2(h, pc)
  end subroutine tri_angles

  ! The apex B of the triangle with base d = AC and sides l2 = AB, l3 = CB, in the frame of
  ! the base: pa = projection of AB on AC, pc = d - pa that of CB on CA, h = the height
  ! (>= 0).  tri_angles' angles are atan2(h, pa) and atan2(h, pc); corrected DPRM1 and
  ! DKNMA1 use the apex itself (issue 9: no angle and back).  pa, h, pc are in units of 2**e (the
  ! sides are scaled by a power of 2 first, see below).  dang and st as for tri_angles.
  pure subroutine tri_apex(d0, l20, l30, pa, h, pc, e, dang, st)
    real(dp), intent(in) :: d0, l20, l30
    real(dp), intent(out) :: pa, h, pc, dang
    integer, intent(out) :: e, st
    real(dp) :: d, l2, l3, a, b, c, t, f1, f2, f3, f4, area, tol, dc
    e = 0
    pa = 0.0_dp
    h = 0.0_dp
    pc = 0.0_dp
    dang = 0.0_dp
    if (.not. (d0 > 0.0_dp .and. l20 > 0.0_dp .and. l30 > 0.0_dp)) then
      st = st_assembly
      return
    end if
    if (.not. (max(d0, l20, l30) <= huge(1.0_dp))) then
      st = st_assembly
      return
    end if
    e = 0                                         ! exponent(t) is libm's frexp: call it
    t = max(d0, l20, l30)                         ! only outside [2**-61, 2**60), where
    if (.not. (t >= 2.0_dp**(-61) .and. t < 2.0_dp**60)) e = exponent(t)   ! |e| > 60
    if (abs(e) <= 60) then
      ! no scaling needed (and none done, the costly part): the squares and the product of
      ! four below stay normal, since f2 is 0 or at least an ulp of the largest side
      e = 0
      d = d0
      l2 = l20
      l3 = l30
    else
      d = scale(d0, -e)
      l2 = scale(l20, -e)
      l3 = scale(l30, -e)
    end if
    ! sort a >= b >= c
    a = d
    b = l2
    c = l3
    if (a < b) then
      t = a; a = b; b = t
    end if
    if (b < c) then
      t = b; b = c; c = t
    end if
    if (a < b) then
      t = a; a = b; b = t
    end if
    tol = 8.0_dp*epsilon(1.0_dp)*a
    f1 = a + (b + c)
    f2 = c - (a - b)
    f3 = c + (a - b)
    f4 = a + (b - c)
    if (f2 < -tol) then
      st = st_assembly                            ! the links do not reach
      return
    end if
    f2 = max(f2, 0.0_dp)
    area = 0.25_dp*sqrt(f1*f2*f3*f4)
    h = 2.0_dp*area/d
    pa = (d*d + (l2 - l3)*(l2 + l3))/(2.0_dp*d)  ! projection of AB on AC
    pc = d - pa
    ! first order both angles move by 2u(d^2+l2^2+l3^2)/(d h); second order (flat triangle)
    ! by sqrt(2 dc), dc the larger move of the two cosines
    dc = 2.0_dp*uround*(d*d + l2*l2 + l3*l3)/(d*min(l2, l3))
    dang = huge(1.0_dp)
    if (h > 0.0_dp) dang = 2.0_dp*uround*(d*d + l2*l2 + l3*l3)/(d*h)
    if (.not. dang*dang <= 2.0_dp*dc) dang = sqrt(2.0_dp*dc)   ! min(first, second order)
    dang = dang + 16.0_dp*uround
    st = st_ok
  end subroutine tri_apex

  ! The apex of tri_apex as vectors, in its units of 2**e: B - A = pa u + side h n and
  ! B - C = -pc u + side h n, where u = (dx, dy)/d is the unit vector A->C and n is u turned
  ! by +pi/2; side = +1 puts B on the left of A->C.
  pure subroutine apex_vectors(dx, dy, d, pa, h, pc, side, r2x, r2y, r3x, r3y)
    real(dp), intent(in) :: dx, dy, d, pa, h, pc, side
    real(dp), intent(out) :: r2x, r2y, r3x, r3y
    real(dp) :: ux, uy, sh
    ux = dx/d
    uy = dy/d
    sh = side*h
    r2x = pa*ux - sh*uy
    r2y = pa*uy + sh*ux
    r3x = -pc*ux - sh*uy
    r3y = -pc*uy + sh*ux
  end subroutine apex_vectors

  ! x * 2**e, exactly: tri_apex's units back to the caller's (e = 0, the usual case, costs
  ! no library call).
  pure real(dp) function unscale(x, e)
    real(dp), intent(in) :: x
    integer, intent(in) :: e
    unscale = x
    if (e /= 0) unscale = scale(x, e)
  end function unscale

  ! Direction of the acceleration of a point at direction FI from the centre of a link
  ! rotating with W, E: FI + sign(E)*(pi - atan(|E|/W**2)), i.e. the book's
  ! DUGL3(FI, PI - ATAN(ABS(E)/W**2), E) (L2523, L2902), written with atan2 so that W = 0
  ! gives FI +- pi/2 and E = 0 gives FI + pi (ERRATA E-DKNMA4-3, E-DKNMA5-4).
  pure real(dp) function acc_dir(fi, w, e)
    real(dp), intent(in) :: fi, w, e
    acc_dir = dugl3(fi, pi - atan2(abs(e), w*w), e)
  end function acc_dir

  ! The unit vector e(BOOK) of an angle the book forms as BOOK = FI + K*PI/2 (FI + PID2,
  ! FI - PI, DUGL3's FI +- PI/2, ...), given C = cos FI and S = sin FI.  As printed: the
  ! cosine and sine of BOOK itself, the book's sequence (with PI = 3.14159 the two ways
  ! differ by up to 3e-6, which a printed figure can show).  Corrected: (C, S) turned by K
  ! quarter turns, exactly, with no library call and no rounding of the sum (issue 9: one
  ! sincos per angle).
  pure subroutine turn(book, c, s, k, ct, st)
    real(dp), intent(in) :: book, c, s
    integer, intent(in) :: k
    real(dp), intent(out) :: ct, st
    if (printed_mode /= 0) then
      ct = cos(book)
      st = sin(book)
      return
    end if
    select case (modulo(k, 4))
    case (0)
      ct = c
      st = s
    case (1)
      ct = -s
      st = c
    case (2)
      ct = -c
      st = -s
    case default
      ct = s
      st = -c
    end select
  end subroutine turn

  ! The Cartesian components m*e(FI) of a vector given as (modulus, direction); a zero
  ! modulus (a fixed pivot's velocity) costs no cosine and no sine.
  pure subroutine components(m, fi, x, y)
    real(dp), intent(in) :: m, fi
    real(dp), intent(out) :: x, y
    if (m == 0.0_dp) then
      x = 0.0_dp
      y = 0.0_dp
    else
      x = m*cos(fi)
      y = m*sin(fi)
    end if
  end subroutine components

  ! The quarter turn K = +-1 of DUGL3(FI, PI/2, V): +1 for V >= 0 (the book's SIGN).
  pure integer function quarter(v)
    real(dp), intent(in) :: v
    quarter = 1
    if (v < 0.0_dp) quarter = -1
  end function quarter

end module numerics
