! forces.f90 -- chapter 7, force analysis of the class-II Assur groups (listings VII.1-VII.9
! and the DNMA5 listing the book heads "VII.9" a second time, book lines L4986-5513):
! the projection method DNMAF1-DNMAF5 and the vector method DNMA1-DNMA5 of textbook [1],
! plus DUGL6, which DNMA1-DNMA3 call and the book never prints (an extension of sarkp).
!
! Group kinds and links as in chapter 4: links 2 and 3 form the group, 1 and 4 are the
! chain links (or the frame) it is attached to.  No friction: a prismatic pair's reaction
! is perpendicular to its guide.  Angles in radians from +x, counter-clockwise positive;
! a force is a pair (modulus >= 0, direction); moments counter-clockwise positive.
! F2/G2 (Q2/G2) and T2 (M2) are the resultant and the main moment of the loads on link 2
! (inertia loads included by the caller: d'Alembert, L4863-4869), reduced to the point S2;
! the same for link 3.
!
! Directions of the outputs (L4986, L6423):
!   DNMAF*  forces exerted BY the group's links ON the chain: F21 = force of 2 on 1,
!           F34 = force of 3 on 4; the internal F23 = force of 2 on 3 (DNMAF5: F32 = of 3 on 2);
!   DNMA*   reactions ON the group's links: RA on 2 from 1, RC on 3 from 4; RB on 2 from 3
!           (DNMA5: RB on 3 from 2, ERRATA E-DNMA5-2).
! Each routine's header states where its reduction points lie and what its arms mean: the
! printed code balances exactly under those conventions and no other (ERRATA E-DNMA1-3,
! E-DNMA2-3, E-DNMA3-4, E-DNMA4-2, E-DNMA5-3; tests/test_forces.py checks each).
!
! Additions to the book (it reports no failure): a trailing IER --
!   st_singular     a division by zero or a singular 2x2 system (no digit of the result
!                   left): the group is at a singular position (links or guides aligned)
!                   or two of its points coincide;
!   st_digits + d   near a singular position only about d (1..7) digits are left: kept;
!   st_significance the denominator (a sine or cosine of the angle between two directions,
!                   or GELG's pivot) is below 1e-4, the book's GELG tolerance: result kept;
!   st_ok.
! On st_singular every output is 0 (never NaN).  An arm of a zero force is 0 (the DNMAF
! routines' own guard, extended to DNMA2-DNMA5: E-DNMA-1).
! No as-printed switch for an author error here: no printed figure depends on the errors
! corrected below.  The modes differ in the arithmetic:
!   corrected: each routine is an adapter over the force step of groups.f90
!     (group_reactions, the kernel sarkp.Mechanism calls for every kind): it lays the
!     group out in Cartesian coordinates (points, loads as vectors, sliding directions),
!     calls the kernel with its kind's pair declaration (kind_pairs) and returns the
!     reactions in the book's form: its argument order, moduli and directions (in the
!     ranges each routine's printed code gives), signs and arms, and the status of the
!     book's denominator (den_status below; the GELG pivot test for DNMA2-DNMA5);
!   as-printed: the printed code, PI = 3.14159 inside it, as the book's figures need.
module forces
  use prmtr, only: dp, pi, pid2, pi_exact, printed_mode, st_ok, st_singular, &
                   st_significance, st_digits, book_sign, norm2d, succeeded
  use operators, only: dugl3, dugl4, dugl5, dvkt, dsmvkt
  use gelg_mod, only: gelg2
  use groups, only: kind_pairs, group_reactions
  implicit none
  private
  public :: dnmaf1, dnmaf2, dnmaf3, dnmaf4, dnmaf5
  public :: dnma1, dnma2, dnma3, dnma4, dnma5
  public :: dugl6

  ! The book's GELG tolerance (EPS = 0.0001, L525): a smaller denominator is reported.
  real(dp), parameter :: eps_den = 1.0e-4_dp
  ! The kernel's points of DNMA4/DNMAF4 and DNMA5/DNMAF5, all at the origin of the
  ! adapter's coordinates (B, A).
  real(dp), parameter :: origin(2, 3) = 0.0_dp

  ! The argument lines of the loads, shared by DNMAF1-DNMAF5 (loads_f) and DNMA1-DNMA5
  ! (loads_q): gen_drivers puts them where a routine says !:insert.
  !:define loads_f
  !: XS2, YS2 : real -- Reduction point S2 of link 2 (m).
  !: F2, G2 : real >= 0; real -- Resultant of the loads on link 2 (N, >= 0) and its
  !:     direction (rad).
  !: XS3, YS3, F3, G3 : real; real; real >= 0; real -- The same for link 3.
  !: T2, T3 : real -- Main moments of the loads on links 2 and 3 about S2, S3 (N*m, CCW
  !:     +).
  !: AAA : flag -- The book's print flag; unused (the routine prints nothing).
  !:end
  !:define loads_q
  !: M2, Q2, G2 : real; real >= 0; real -- Main moment (N*m, CCW +), resultant (N, >= 0)
  !:     and its direction (rad) of the loads on link 2, reduced to S2.
  !: M3, Q3, G3 : real; real >= 0; real -- The same for link 3, reduced to S3.
  !:end

contains

  ! ============================================================================
  ! private helpers
  ! ============================================================================

  ! Status of a division by s, a sine or cosine (|s| <= 1) of an angle between two
  ! directions that were computed to rounding: the result's relative error is about
  ! epsilon/|s|, so d = log10(|s|/epsilon) digits are left.  No digit (|s| < 10 epsilon):
  ! singular.  1 to 7 digits: st_digits + d (kept, with a warning that says how many).
  ! Otherwise |s| <= 1e-4, the book's GELG tolerance: st_significance; else st_ok.
  pure integer function den_status(s)
    real(dp), intent(in) :: s
    integer :: d
    if (.not. abs(s) >= 10.0_dp*epsilon(1.0_dp)) then
      den_status = st_singular
      return
    end if
    if (abs(s) < 1.0e8_dp*epsilon(1.0_dp)) then        ! fewer than 8 digits: how many
      d = min(int(log10(abs(s)/epsilon(1.0_dp))), 7)
      den_status = st_digits + d
    else if (abs(s) <= eps_den) then
      den_status = st_significance
    else
      den_status = st_ok
    end if
  end function den_status

  ! DUGL5 of corrected mode (exact pi, a constant here: the mode's pi is thread-local and
  ! costs a lookup per use): the direction of (prx, pry) in (-pi/2, 3*pi/2).
  pure real(dp) function direction(prx, pry)
    real(dp), intent(in) :: prx, pry
    if (prx == 0.0_dp) then
      direction = book_sign(pi_exact/2.0_dp, pry)
    else if (prx < 0.0_dp) then
      direction = pi_exact + atan(pry/prx)
    else
      direction = atan(pry/prx)
    end if
  end function direction

  ! An arm: moment/force, 0 for a zero force (the book's guard, L5014).
  pure real(dp) function arm(moment, force)
    real(dp), intent(in) :: moment, force
    if (force == 0.0_dp) then
      arm = 0.0_dp
    else
      arm = moment/force
    end if
  end function arm

  ! GELG(Y, X, 2, 1, 0.0001, IER) on a11*y1 + a12*y2 = b1, a21*y1 + a22*y2 = b2, whose
  ! columns are unit vectors in every call of the book: the determinant is the sine of the
  ! angle between them, judged as the DNMAF denominators are (a GELG pivot of rounding
  ! size alone would not say that no digit is left).
  subroutine solve2(a11, a12, a21, a22, b1, b2, y1, y2, st)
    real(dp), intent(in) :: a11, a12, a21, a22, b1, b2
    real(dp), intent(out) :: y1, y2
    integer, intent(out) :: st
    real(dp) :: x(2, 2), y(2)
    integer :: st_gelg
    y1 = 0.0_dp
    y2 = 0.0_dp
    st = den_status(a11*a22 - a12*a21)
    if (st == st_singular) return
    x = reshape([a11, a21, a12, a22], [2, 2])
    y = [b1, b2]
    call gelg2(x, y, st_gelg)
    if (st_gelg == st_singular .or. (st == st_ok .and. st_gelg /= st_ok)) st = st_gelg
    if (st == st_singular) return
    y1 = y(1)
    y2 = y(2)
  end subroutine solve2


  ! ---- the adapters' conversions between the book's polar forms and the kernel's vectors

  ! A force (modulus f, direction g) as a vector.
  pure function vec(f, g) result(v)
    real(dp), intent(in) :: f, g
    real(dp) :: v(2)
    v = [f*cos(g), f*sin(g)]
  end function vec

  ! A unit vector e(g).
  pure function unit(g) result(u)
    real(dp), intent(in) :: g
    real(dp) :: u(2)
    u = [cos(g), sin(g)]
  end function unit

  ! The modulus and DUGL5 direction of the vector (x, y) (what DSMVKT returns).
  pure subroutine polar(x, y, f, g)
    real(dp), intent(in) :: x, y
    real(dp), intent(out) :: f, g
    f = norm2d(x, y)
    g = direction(x, y)
  end subroutine polar

  ! A slider's force v, normal to its guide e(fi), as the book writes it: its modulus and
  ! the direction DUGL3(FI, PID2, N) = FI +- PI/2 by the sign of its component N along
  ! e(FI + PI/2), u = e(fi).
  pure subroutine normal_polar(v, u, fi, f, g)
    real(dp), intent(in) :: v(2), u(2), fi
    real(dp), intent(out) :: f, g
    f = norm2d(v(1), v(2))
    g = fi + book_sign(pi_exact/2.0_dp, -v(1)*u(2) + v(2)*u(1))
  end subroutine normal_polar

  ! The status of the sine of the angle between the directions of (ax, ay) and (bx, by):
  ! den_status of it; st_singular for a zero vector.
  pure integer function sine_status(ax, ay, bx, by)
    real(dp), intent(in) :: ax, ay, bx, by
    real(dp) :: na, nb
    na = norm2d(ax, ay)
    nb = norm2d(bx, by)
    if (na == 0.0_dp .or. nb == 0.0_dp) then
      sine_status = st_singular
    else
      sine_status = den_status((ax/na)*(by/nb) - (ay/na)*(bx/nb))
    end if
  end function sine_status

  ! The status solve2 (GELG) gives the 2x2 matrix of DNMA2-DNMA5 (it depends on the
  ! matrix alone).
  integer function gelg_status(a11, a12, a21, a22)
    real(dp), intent(in) :: a11, a12, a21, a22
    real(dp) :: y1, y2
    call solve2(a11, a12, a21, a22, 0.0_dp, 0.0_dp, y1, y2, gelg_status)
  end function gelg_status

  ! ============================================================================
  ! DUGL6 -- not printed (ERRATA E-DUGL6-1): an extension of sarkp
  ! ============================================================================

  ! DUGL6(RN, GN, RT, GT, FI), called by DNMA1 (L5311-5312), DNMA2 (L5359), DNMA3 (L5401)
  ! right after RA = SQRT(RAN**2 + RAT**2): the direction of the reaction whose normal
  ! component is RN at GN and tangential component RT at GT, i.e. of the vector sum
  ! RN e(GN) + RT e(GT), in the DUGL5 range (-pi/2, 3*pi/2) -- what DSMVKT returns for the
  ! same sum in the DNMAF routines.  FI (the link's direction) is not needed.  That this
  ! is the book's meaning is shown by equilibrium: with it every DNMA1-DNMA3 result
  ! balances (tests/test_forces.py).
  pure real(dp) function dugl6(rn, gn, rt, gt, fi)
    !: RN, GN : real -- Modulus and direction of the first (normal) component.
    !: RT, GT : real -- Modulus and direction of the second (tangential) component.
    !: FI : real -- The link's direction, passed by the book's calls; not needed.
    real(dp), intent(in) :: rn, gn, rt, gt, fi
    dugl6 = dugl5(rn*cos(gn) + rt*cos(gt), rn*sin(gn) + rt*sin(gt))
  end function dugl6

  ! ============================================================================
  ! corrected mode: the routines as adapters over the kernel (groups.f90)
  ! ============================================================================
  ! Each lays its group out for group_reactions -- the pair points p, the sliding
  ! directions u, each link's load as a vector and its moment about the reduction point
  ! -- with its kind's pair declaration, and turns the kernel's reactions r(:, j)
  ! (pair 1's on link 2 from the outside, pair 2's on link 3 from link 2, pair 3's on
  ! link 3 from the outside; a slider's couple about its point p(:, j)) into the book's
  ! outputs, which come in as the calling routine's zeros and stay so where it fails.  The
  ! status is the book's denominator's, as the printed code divides by it; the kernel's
  ! own (st_singular, st_range) where that fails.

  ! DNMAF1: kind 1, pairs A, B, C.
  subroutine dnmaf1_adapter(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, &
                           t3, f21, g21, f23, g23, f34, g34, ier)
    real(dp), intent(in) :: xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3
    real(dp), intent(inout) :: f21, g21, f23, g23, f34, g34
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3)
    integer :: st
    ier = sine_status(xa - xc, ya - yc, xb - xa, yb - ya)   ! SIN(FI - FICA)
    if (ier == st_singular) return
    u = 0.0_dp
    p(:, 1) = [xa, ya]
    p(:, 2) = [xb, yb]
    p(:, 3) = [xc, yc]
    call group_reactions(p, kind_pairs(:, 1), u, vec(f2, g2), t2, [xs2, ys2], vec(f3, g3), &
                         t3, [xs3, ys3], r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), f21, g21)                  ! F12, the reaction on 2
    g21 = g21 - pi_exact
    call polar(r(1, 2), r(2, 2), f23, g23)
    call polar(-r(1, 3), -r(2, 3), f34, g34)
  end subroutine dnmaf1_adapter

  ! DNMAF2: kind 2, pairs A, B and the slider on the guide, its couple about B (H34).
  subroutine dnmaf2_adapter(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                           f21, g21, f23, g23, f34, g34, h34, ier)
    real(dp), intent(in) :: xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3
    real(dp), intent(inout) :: f21, g21, f23, g23, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3)
    integer :: st
    u = 0.0_dp
    u(:, 3) = unit(fim)
    ier = sine_status(-u(2, 3), u(1, 3), xa - xb, ya - yb)  ! SIN(FIM + PID2 - FI)
    if (ier == st_singular) return
    p(:, 1) = [xa, ya]
    p(:, 2) = [xb, yb]
    p(:, 3) = [xb, yb]
    call group_reactions(p, kind_pairs(:, 2), u, vec(f2, g2), t2, [xs2, ys2], vec(f3, g3), &
                         t3, [xs3, ys3], r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), f21, g21)
    g21 = g21 - pi_exact
    call polar(r(1, 2), r(2, 2), f23, g23)
    call polar(-r(1, 3), -r(2, 3), f34, g34)
    h34 = arm(r(3, 3), f34)
  end subroutine dnmaf2_adapter

  ! DNMAF3: kind 3, pairs A, the slider on link 3 (its couple about C: H23), C.
  subroutine dnmaf3_adapter(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                           f21, g21, f23, g23, h23, f34, g34, ier)
    real(dp), intent(in) :: xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3
    real(dp), intent(inout) :: f21, g21, f23, g23, h23, f34, g34
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3)
    integer :: st
    u = 0.0_dp
    u(:, 2) = unit(fi3)
    ier = sine_status(xa - xc, ya - yc, -u(2, 2), u(1, 2))  ! SIN(FI3 + PID2 - FICA)
    if (ier == st_singular) return
    p(:, 1) = [xa, ya]
    p(:, 2) = [xc, yc]
    p(:, 3) = [xc, yc]
    call group_reactions(p, kind_pairs(:, 3), u, vec(f2, g2), t2, [xs2, ys2], vec(f3, g3), &
                         t3, [xs3, ys3], r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), f21, g21)
    g21 = g21 - pi_exact
    call polar(r(1, 2), r(2, 2), f23, g23)
    h23 = arm(r(3, 2), f23)
    call polar(-r(1, 3), -r(2, 3), f34, g34)
  end subroutine dnmaf3_adapter

  ! DNMA4 and DNMAF4: kind 4, the sliders on the guides u1 (FIM) and u3 (FIN) joined at
  ! the origin; every couple about it.  ier comes in as the caller's status of the
  ! book's denominator: nothing is done for st_singular, the kernel's failure replaces it.
  subroutine prp_reactions(u1, u3, s2, v2, t2, s3, v3, t3, r, ier)
    real(dp), intent(in) :: u1(2), u3(2), s2(2), v2(2), t2, s3(2), v3(2), t3
    real(dp), intent(out) :: r(3, 3)
    integer, intent(inout) :: ier
    real(dp) :: u(2, 3)
    integer :: st
    r = 0.0_dp
    if (ier == st_singular) return
    u(:, 1) = u1
    u(:, 2) = 0.0_dp
    u(:, 3) = u3
    call group_reactions(origin, kind_pairs(:, 4), u, v2, t2, s2, v3, t3, s3, r, st)
    if (st /= st_ok) ier = st
  end subroutine prp_reactions

  ! DNMAF4 (B at the origin of the kernel's coordinates).
  subroutine dnmaf4_adapter(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                           f21, g21, h21, f23, g23, f34, g34, h34, ier)
    real(dp), intent(in) :: fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3
    real(dp), intent(inout) :: f21, g21, h21, f23, g23, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: r(3, 3), u1(2), u3(2)
    u1 = unit(fim)
    u3 = unit(fin)
    ier = sine_status(u1(1), u1(2), u3(1), u3(2))           ! COS(FIM + PID2 - FIN)
    call prp_reactions(u1, u3, [xs2 - xb, ys2 - yb], vec(f2, g2), t2, [xs3 - xb, ys3 - yb], &
                    vec(f3, g3), t3, r, ier)
    if (.not. succeeded(ier)) return
    call normal_polar(r(1:2, 1), u1, fim, f21, g21)         ! F12 = DUGL3(FIM, PID2, .)
    g21 = g21 - pi_exact
    h21 = arm(r(3, 1), f21)
    call polar(r(1, 2), r(2, 2), f23, g23)
    call polar(-r(1, 3), -r(2, 3), f34, g34)
    h34 = arm(r(3, 3), f34)
  end subroutine dnmaf4_adapter

  ! DNMA5 and DNMAF5: the book's kind 5 has links 2 and 3 the other way round from the
  ! kernel's (kind_pairs(:, 5): link 2 the slotted link on the guide): the kernel's link
  ! 2 is the book's link 3 (sliding on the guide u1, FIM), its link 3 the book's link 2
  ! (pivoted at the origin A, sliding in the slot u2, FIM + ETA3); every couple about
  ! A.  r(:, 1): the guide's reaction on link 3, r(:, 2): the force of 3 on 2, r(:, 3):
  ! the reaction on 2 at A.  ier as prp_reactions's.
  subroutine rpp_reactions(u1, u2, s2, v2, t2, s3, v3, t3, r, ier)
    real(dp), intent(in) :: u1(2), u2(2), s2(2), v2(2), t2, s3(2), v3(2), t3
    real(dp), intent(out) :: r(3, 3)
    integer, intent(inout) :: ier
    real(dp) :: u(2, 3)
    integer :: st
    r = 0.0_dp
    if (ier == st_singular) return
    u(:, 1) = u1
    u(:, 2) = u2
    u(:, 3) = 0.0_dp
    call group_reactions(origin, kind_pairs(:, 5), u, v3, t3, s3, v2, t2, s2, r, st)
    if (st /= st_ok) ier = st
  end subroutine rpp_reactions

  ! DNMAF5 (A at the origin).
  subroutine dnmaf5_adapter(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                           f21, g21, f32, g32, h32, f34, g34, h34, ier)
    real(dp), intent(in) :: xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3
    real(dp), intent(inout) :: f21, g21, f32, g32, h32, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: r(3, 3), u1(2)
    u1 = unit(fim)
    ier = den_status(sin(tt3))                               ! COS(PID2 - TT3)
    call rpp_reactions(u1, unit(fim + tt3), [xs2 - xa, ys2 - ya], vec(f2, g2), t2, &
                    [xs3 - xa, ys3 - ya], vec(f3, g3), t3, r, ier)
    if (.not. succeeded(ier)) return
    call polar(-r(1, 3), -r(2, 3), f21, g21)
    call polar(r(1, 2), r(2, 2), f32, g32)
    h32 = arm(r(3, 2), f32)
    call normal_polar(r(1:2, 1), u1, fim, f34, g34)         ! F43 = DUGL3(FIM, PID2, .)
    g34 = g34 - pi_exact
    h34 = arm(r(3, 1), f34)
  end subroutine dnmaf5_adapter

  ! DNMA1: kind 1 with B at the origin, A = -L2 e(FI2), C = -L3 e(FI3).
  subroutine dnma1_adapter(l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                          ra, ga, rb, gb, rc, gc, ier)
    real(dp), intent(in) :: l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(inout) :: ra, ga, rb, gb, rc, gc
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3), e2(2), e3(2)
    integer :: st
    e2 = unit(fi2)
    e3 = unit(fi3)
    ier = den_status(e2(1)*e3(2) - e3(1)*e2(2))             ! the links' sine (GELG)
    if (ier == st_singular) return
    u = 0.0_dp
    p(:, 1) = -l2*e2
    p(:, 2) = 0.0_dp
    p(:, 3) = -l3*e3
    call group_reactions(p, kind_pairs(:, 1), u, vec(q2, g2), m2, bs2*e2, vec(q3, g3), m3, &
                         bs3*e3, r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), ra, ga)
    call polar(-r(1, 2), -r(2, 2), rb, gb)                  ! on 2 from 3
    call polar(r(1, 3), r(2, 3), rc, gc)
  end subroutine dnma1_adapter

  ! DNMA2: kind 2 with B at the origin, A = -L2 e(FI2), S3 on the line B + s e(FIO + ETA).
  subroutine dnma2_adapter(l2, fi2, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                          ra, ga, rb, gb, rc, hc, gc, ier)
    real(dp), intent(in) :: l2, fi2, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(inout) :: ra, ga, rb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3), e2(2)
    integer :: st
    e2 = unit(fi2)
    u = 0.0_dp
    u(:, 3) = unit(fio)
    ier = gelg_status(e2(1), -u(2, 3), e2(2), u(1, 3))
    if (ier == st_singular) return
    p(:, 1) = -l2*e2
    p(:, 2:3) = 0.0_dp
    call group_reactions(p, kind_pairs(:, 2), u, vec(q2, g2), m2, bs2*e2, vec(q3, g3), m3, &
                         bs3*unit(fio + eta), r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), ra, ga)
    call polar(-r(1, 2), -r(2, 2), rb, gb)
    call normal_polar(r(1:2, 3), u(:, 3), fio, rc, gc)
    hc = arm(r(3, 3), rc)
  end subroutine dnma2_adapter

  ! DNMA3: kind 3 with C at the origin, A = -AC e(FIAC); the slider's couple about A.
  subroutine dnma3_adapter(fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3, &
                          ra, ga, rb, hb, gb, rc, gc, ier)
    real(dp), intent(in) :: fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3
    real(dp), intent(inout) :: ra, ga, rb, hb, gb, rc, gc
    integer, intent(out) :: ier
    real(dp) :: p(2, 3), r(3, 3), u(2, 3), eac(2), a(2)
    integer :: st
    eac = unit(fiac)
    u = 0.0_dp
    u(:, 2) = unit(fi3)
    ier = gelg_status(eac(1), -u(2, 2), eac(2), u(1, 2))
    if (ier == st_singular) return
    a = -ac*eac
    p(:, 1) = a
    p(:, 2) = a
    p(:, 3) = 0.0_dp
    call group_reactions(p, kind_pairs(:, 3), u, vec(q2, g2), m2, cs2*unit(fics2), &
                         vec(q3, g3), m3, cs3*unit(fics3), r, st)
    if (st /= st_ok) then
      ier = st
      return
    end if
    call polar(r(1, 1), r(2, 1), ra, ga)
    call normal_polar(-r(1:2, 2), u(:, 2), fi3, rb, gb)     ! on 2 from 3
    ! HB*RB: the moment about C of the force on 3 from 2, whose couple is about A
    hb = arm(r(3, 2) + (a(1)*r(2, 2) - a(2)*r(1, 2)), rb)
    call polar(r(1, 3), r(2, 3), rc, gc)
  end subroutine dnma3_adapter

  ! DNMA4 (B at the origin).
  subroutine dnma4_adapter(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                          ra, ha, ga, rb, gb, rc, hc, gc, ier)
    real(dp), intent(in) :: fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(inout) :: ra, ha, ga, rb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: r(3, 3), u1(2), u3(2)
    u1 = unit(fim)
    u3 = unit(fin)
    ier = gelg_status(-u1(2), -u3(2), u1(1), u3(1))
    call prp_reactions(u1, u3, bs2*unit(fim + eta2), vec(q2, g2), m2, bs3*unit(fin + eta3), &
                    vec(q3, g3), m3, r, ier)
    if (.not. succeeded(ier)) return
    call normal_polar(r(1:2, 1), u1, fim, ra, ga)
    ha = arm(r(3, 1), ra)
    call polar(-r(1, 2), -r(2, 2), rb, gb)
    call normal_polar(r(1:2, 3), u3, fin, rc, gc)
    hc = arm(r(3, 3), rc)
  end subroutine dnma4_adapter

  ! DNMA5 (A at the origin; S2 = -AS2 e(FIAS2), S3 = -AS3 e(FIAS3): E-DNMA5-3).
  subroutine dnma5_adapter(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3, &
                          ra, ga, rb, hb, gb, rc, hc, gc, ier)
    real(dp), intent(in) :: eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3
    real(dp), intent(inout) :: ra, ga, rb, hb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: r(3, 3), u1(2), u2(2)
    u1 = unit(fim)
    u2 = unit(fim + eta3)
    ier = gelg_status(-u1(2), -u2(2), u1(1), u2(1))
    call rpp_reactions(u1, u2, -as2*unit(fias2), vec(q2, g2), m2, -as3*unit(fias3), &
                    vec(q3, g3), m3, r, ier)
    if (.not. succeeded(ier)) return
    call polar(-r(1, 3), -r(2, 3), ra, ga)                  ! the printed DSMVKT's RA + PI
    ga = ga + pi_exact
    call normal_polar(-r(1:2, 2), u2, fim + eta3, rb, gb)   ! on 3 from 2
    hb = arm(r(3, 2), rb)
    call normal_polar(r(1:2, 1), u1, fim, rc, gc)
    hc = arm(r(3, 1), rc)
  end subroutine dnma5_adapter

  ! ============================================================================
  ! projection method (F21, F34: forces of the group ON the chain)
  ! ============================================================================

  ! VII.1 DNMAF2, L4992-5020 (Table 27, Fig. 52).  Kind 2 (RRP): revolute A (link 2 on 1),
  ! internal revolute B, slider 3 on the guide of link 4 with direction FIM.
  ! S2, S3 anywhere (given by coordinates).  F34 is perpendicular to the guide.  The arm:
  ! H34*F34 = moment about B of the guide's reaction on link 3 (-F34): the line of action
  ! crosses the guide at the distance |H34| from B.
  ! Singular: A = B, or AB perpendicular to the guide (cos(FIM - FI) = 0).
  ! ERRATA: none in the code.
  subroutine dnmaf2(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa, &
                    f21, g21, f23, g23, f34, g34, h34, ier)
    !: XA, YA, XB, YB : real -- Centres of the revolutes A (link 2 on link 1) and B (links
    !:     2, 3), m.
    !: FIM : real -- Direction of the guide m of the prismatic pair C (slider 3 on link 4),
    !:     rad.
    !:insert loads_f
    real(dp), intent(in) :: xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                            aaa
    real(dp), intent(out) :: f21, g21, f23, g23, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: f12m, g12m, r, fi, rbs2, fibs2, rbs3, fibs3, f12nm, g12nm, f12, g, den
    f21 = 0.0_dp; g21 = 0.0_dp; f23 = 0.0_dp; g23 = 0.0_dp; f34 = 0.0_dp; g34 = 0.0_dp
    h34 = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnmaf2_adapter(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, &
                         t3, f21, g21, f23, g23, f34, g34, h34, ier)
      return
    end if
    ! the group projected on the guide m (F43 has no component along it)
    f12m = -(f2*cos(g2 - fim) + f3*cos(g3 - fim))
    g12m = dugl4(fim, pi, f12m)
    call dvkt(xb, yb, xa, ya, r, fi)
    call dvkt(xb, yb, xs2, ys2, rbs2, fibs2)
    den = sin(fim + pid2 - fi)
    ier = den_status(den)
    if (r == 0.0_dp) ier = st_singular
    if (ier == st_singular) return
    ! link 2, moments about B: the component of F12 normal to m
    f12nm = -(t2 + rbs2*f2*sin(g2 - fibs2) + r*abs(f12m)*sin(g12m - fi))/(r*den)
    g12nm = dugl3(fim, pid2, f12nm)
    call dsmvkt(abs(f12m), g12m, abs(f12nm), g12nm, f12, g)
    g21 = g - pi
    f21 = f12
    call dsmvkt(f12, g, f2, g2, f23, g23)          ! link 2: F32 = -(F12 + F2)
    call dsmvkt(f23, g23, f3, g3, f34, g34)        ! link 3: F43 = -(F23 + F3)
    call dvkt(xb, yb, xs3, ys3, rbs3, fibs3)
    h34 = arm(-(rbs3*f3*sin(g3 - fibs3) + t3), f34)
  end subroutine dnmaf2

  ! VII.2 DNMAF1, L5059-5087 (Table 28, Fig. 53).  Kind 1 (RRR): revolutes A (2 on 1),
  ! B (internal), C (3 on 4).  S2, S3 anywhere (given by coordinates).
  ! Singular: A = B, A = C, or A, B, C collinear (sin(FI - FICA) = 0: the dyad stretched
  ! or folded).
  ! ERRATA: none in the code.
  subroutine dnmaf1(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa, &
                    f21, g21, f23, g23, f34, g34, ier)
    !: XA, YA, XB, YB, XC, YC : real -- Centres of the revolutes A (link 2 on link 1), B
    !:     (links 2, 3) and C (link 3 on link 4), m.
    !:insert loads_f
    real(dp), intent(in) :: xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, &
                            t3, aaa
    real(dp), intent(out) :: f21, g21, f23, g23, f34, g34
    integer, intent(out) :: ier
    real(dp) :: rbs2, fibs2, rcs2, fics2, rcs3, fics3, rca, fica, r, fi, f12t, g12t, f12n, &
                g12n, g, den
    f21 = 0.0_dp; g21 = 0.0_dp; f23 = 0.0_dp; g23 = 0.0_dp; f34 = 0.0_dp; g34 = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnmaf1_adapter(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, &
                         t2, t3, f21, g21, f23, g23, f34, g34, ier)
      return
    end if
    call dvkt(xb, yb, xs2, ys2, rbs2, fibs2)
    call dvkt(xc, yc, xs2, ys2, rcs2, fics2)
    call dvkt(xc, yc, xs3, ys3, rcs3, fics3)
    call dvkt(xc, yc, xa, ya, rca, fica)
    call dvkt(xa, ya, xb, yb, r, fi)
    den = sin(fi - fica)
    ier = den_status(den)
    if (r == 0.0_dp .or. rca == 0.0_dp) ier = st_singular
    if (ier == st_singular) return
    ! link 2, moments about B: the component of F12 normal to AB
    f12t = -(rbs2*f2*sin(g2 - fibs2) + t2)/r
    g12t = dugl4(fi - pid2, -pi, f12t)
    f12t = abs(f12t)
    ! the group, moments about C: the component along AB
    f12n = -(f12t*rca*sin(g12t - fica) + f2*rcs2*sin(g2 - fics2) + f3*rcs3*sin(g3 - fics3) &
             + t2 + t3)/(rca*den)
    g12n = dugl4(fi, pi, f12n)
    call dsmvkt(abs(f12t), g12t, abs(f12n), g12n, f21, g)
    g21 = g - pi
    call dsmvkt(f21, g, f2, g2, f23, g23)
    call dsmvkt(f23, g23, f3, g3, f34, g34)
  end subroutine dnmaf1

  ! VII.3 DNMAF4, L5118-5149 (Table 29, Fig. 54).  Kind 4 (PRP): slider 2 on the guide of
  ! link 1 (direction FIM), slider 3 on the guide of link 4 (FIN), joined at revolute B.
  ! F21 is perpendicular to FIM, F34 to FIN.  Arms about B (the printed comment says C,
  ! E-DNMAF4-3): H21*F21 = moment about B of F12 (the reaction on link 2), H34*F34 = moment
  ! about B of F43 (the reaction on link 3).  Singular: parallel guides.
  ! ERRATA: E-DNMAF4-1 (the division sign lost by the OCR), E-DNMAF4-2 (G21 for G12 in
  ! the first DSMVKT: corrected in both modes, no printed figure depends on it).
  subroutine dnmaf4(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa, &
                    f21, g21, h21, f23, g23, f34, g34, h34, ier)
    !: FIM, FIN : real -- Directions of the guides of the prismatic pairs A (link 2 on link
    !:     1) and C (link 3 on link 4), rad.
    !: XB, YB : real -- Centre of the revolute B joining links 2 and 3, m.
    !:insert loads_f
    real(dp), intent(in) :: fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa
    real(dp), intent(out) :: f21, g21, h21, f23, g23, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: rbs2, fibs2, rbs3, fibs3, f12, g12, den
    f21 = 0.0_dp; g21 = 0.0_dp; h21 = 0.0_dp; f23 = 0.0_dp; g23 = 0.0_dp; f34 = 0.0_dp
    g34 = 0.0_dp; h34 = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnmaf4_adapter(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                         f21, g21, h21, f23, g23, f34, g34, h34, ier)
      return
    end if
    call dvkt(xb, yb, xs2, ys2, rbs2, fibs2)
    call dvkt(xb, yb, xs3, ys3, rbs3, fibs3)
    den = cos(fim + pid2 - fin)
    ier = den_status(den)
    if (ier == st_singular) return
    ! the group projected on the guide n (F43 has no component along it)
    f12 = -(f2*cos(g2 - fin) + f3*cos(g3 - fin))/den        ! E-DNMAF4-1
    g12 = dugl3(fim, pid2, f12)
    g21 = g12 - pi
    f21 = abs(f12)
    call dsmvkt(abs(f12), g12, f2, g2, f23, g23)            ! E-DNMAF4-2: printed G21
    call dsmvkt(f23, g23, f3, g3, f34, g34)
    h21 = arm(-(t2 + f2*rbs2*sin(g2 - fibs2)), f21)
    h34 = arm(-(t3 + f3*rbs3*sin(g3 - fibs3)), f34)
  end subroutine dnmaf4

  ! VII.4 DNMAF3, L5181-5210 (Table 30, Fig. 55).  Kind 3 (RPR): slider 2 pivoted at A
  ! (on link 1) slides along link 3 (guide direction FI3), which is pivoted at C (on 4).
  ! F23 is perpendicular to the guide; H23*F23 = moment about C of F23 (force of 2 on 3).
  ! Singular: A = C, or CA perpendicular to the guide.
  ! ERRATA: E-DNMAF3-1 (F/3, F13 for FI3: OCR).
  subroutine dnmaf3(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa, &
                    f21, g21, f23, g23, h23, f34, g34, ier)
    !: XA, YA, XC, YC : real -- Centres of the revolutes A (link 2 on link 1) and C (link 3
    !:     on link 4), m.
    !: FI3 : real -- Direction of the guide on link 3 along which link 2 slides, rad
    !:     (printed ``F/3`` and ``F13``: ERRATA E-DNMAF3-1).
    !:insert loads_f
    real(dp), intent(in) :: xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                            aaa
    real(dp), intent(out) :: f21, g21, f23, g23, h23, f34, g34
    integer, intent(out) :: ier
    real(dp) :: f12t3, g12t3, rca, fica, rcs2, fics2, rcs3, fics3, f12n3, g12n3, g, den
    f21 = 0.0_dp; g21 = 0.0_dp; f23 = 0.0_dp; g23 = 0.0_dp; h23 = 0.0_dp; f34 = 0.0_dp
    g34 = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnmaf3_adapter(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, &
                         t3, f21, g21, f23, g23, h23, f34, g34, ier)
      return
    end if
    ! link 2 projected on the guide (F32 has no component along it)
    f12t3 = -f2*cos(g2 - fi3)
    g12t3 = dugl4(fi3, pi, f12t3)
    call dvkt(xc, yc, xa, ya, rca, fica)
    call dvkt(xc, yc, xs2, ys2, rcs2, fics2)
    call dvkt(xc, yc, xs3, ys3, rcs3, fics3)
    den = sin(fi3 + pid2 - fica)
    ier = den_status(den)
    if (rca == 0.0_dp) ier = st_singular
    if (ier == st_singular) return
    ! the group, moments about C: the component normal to the guide
    f12n3 = -(rca*abs(f12t3)*sin(g12t3 - fica) + rcs2*f2*sin(g2 - fics2) &
              + rcs3*f3*sin(g3 - fics3) + t2 + t3)/(rca*den)
    g12n3 = dugl3(fi3, pid2, f12n3)
    call dsmvkt(abs(f12t3), g12t3, abs(f12n3), g12n3, f21, g)
    g21 = g - pi
    call dsmvkt(f21, g, f2, g2, f23, g23)
    call dsmvkt(f23, g23, f3, g3, f34, g34)
    h23 = arm(-(t3 + rcs3*f3*sin(g3 - fics3)), f23)
  end subroutine dnmaf3

  ! VII.5 DNMAF5, L5235-5268 (Table 31, Fig. 56).  Kind 5 (RPP): link 2 pivoted at A (on 1)
  ! slides in link 3 along the direction FIM + TT3 (TT3 relative to the guide); link 3
  ! slides on the guide of link 4 (direction FIM).
  ! Outputs F32, G32 (force of 3 on 2, perpendicular to FIM + TT3; the printed comment
  ! names them F23, E-DNMAF5-1) and F34 (perpendicular to FIM).  Arms about A:
  ! H32*F32 = moment about A of F32; H34*F34 = moment about A of F43 (the guide's reaction
  ! on link 3).  Singular: the two guides parallel (cos(PID2 - TT3) = 0).
  ! ERRATA: E-DNMAF5-1 (comment only).
  subroutine dnmaf5(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa, &
                    f21, g21, f32, g32, h32, f34, g34, h34, ier)
    !: XA, YA : real -- Centre of the revolute A (link 2 on link 1), m.
    !: FIM : real -- Direction of the guide of pair C (link 3 slides on link 4), rad.
    !: TT3 : real -- Direction of the inner guide (pair B, link 2 slides in link 3) relative
    !:     to FIM; its absolute direction is FIM + TT3.
    !:insert loads_f
    real(dp), intent(in) :: xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, aaa
    real(dp), intent(out) :: f21, g21, f32, g32, h32, f34, g34, h34
    integer, intent(out) :: ier
    real(dp) :: ras2, fias2, ras3, fias3, f43, g43, den
    f21 = 0.0_dp; g21 = 0.0_dp; f32 = 0.0_dp; g32 = 0.0_dp; h32 = 0.0_dp; f34 = 0.0_dp
    g34 = 0.0_dp; h34 = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnmaf5_adapter(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3, &
                         f21, g21, f32, g32, h32, f34, g34, h34, ier)
      return
    end if
    call dvkt(xa, ya, xs2, ys2, ras2, fias2)
    call dvkt(xa, ya, xs3, ys3, ras3, fias3)
    den = cos(pid2 - tt3)
    ier = den_status(den)
    if (ier == st_singular) return
    ! link 3 projected on the inner guide (F23 has no component along it)
    f43 = -f3*cos(g3 - fim - tt3)/den
    g43 = dugl3(fim, pid2, f43)
    g34 = g43 - pi
    f34 = abs(f43)
    call dsmvkt(f34, g34 - pi, f3, g3, f32, g32)   ! link 3: F32 = F43 + F3
    call dsmvkt(f32, g32, f2, g2, f21, g21)        ! link 2: F21 = F32 + F2
    h34 = arm(-(t2 + t3 + ras3*f3*sin(g3 - fias3) + ras2*f2*sin(g2 - fias2)), f34)
    h32 = arm(-(t2 + ras2*f2*sin(g2 - fias2)), f32)
  end subroutine dnmaf5

  ! ============================================================================
  ! vector method (RA, RC: reactions ON the group's links)
  ! ============================================================================

  ! VII.6 DNMA1, L5274-5318.  Kind 1 (RRR).  L2 = AB, FI2 = direction A->B, L3 = CB,
  ! FI3 = direction C->B (as DPRM1 returns them).
  ! Reduction points (E-DNMA1-3): S2 = B + BS2 e(FI2), S3 = B + BS3 e(FI3), i.e. BS2 is
  ! measured from B AWAY from A (the printed moment is r x F with r at FI2, though it is
  ! written with PI + FI2); a point between A and B has a negative BS2.  The same for BS3.
  ! RB = force on 2 from 3.  Singular: links 2 and 3 parallel (GELG IER = -1).
  ! ERRATA: E-DNMA1-1 (F12, F13, RI2 for FI2, FI3: OCR), E-DUGL6-1.
  ! Corrected mode: dnma1_adapter (the sine and cosine of each of FI2, FI3, G2, G3 once,
  ! the kernel's Cramer solve, DUGL5's 3 arctangents; the printed form takes 16 sines and
  ! cosines before its directions, DUGL6 4 more each, then re-projects RA).  The printed
  ! form, with PI = 3.14159 inside SIN(PI + FI2) and DUGL3/DUGL4's PI/2 and PI, is kept
  ! for as-printed mode.
  subroutine dnma1(l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                   ra, ga, rb, gb, rc, gc, ier)
    !: L2, FI2 : length; real -- Length AB (m, > 0) and direction A->B (rad), as DPRM1
    !:     returns FI2.
    !: L3, FI3 : length; real -- Length CB and direction C->B, as DPRM1 returns FI3.
    !: BS2, BS3 : real -- Signed distances from B to the reduction points: **S2 = B + BS2
    !:     e(FI2)** and **S3 = B + BS3 e(FI3)**, i.e. measured from B away from A (from C);
    !:     a point between A and B has a negative BS2 (ERRATA E-DNMA1-3).
    !:insert loads_q
    real(dp), intent(in) :: l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(out) :: ra, ga, rb, gb, rc, gc
    integer, intent(out) :: ier
    real(dp) :: mbq2, mbq3, rat, gat, rct, gct, y1, y2, gan, ran, gcn, rcn, rbx, rby
    ra = 0.0_dp; ga = 0.0_dp; rb = 0.0_dp; gb = 0.0_dp; rc = 0.0_dp; gc = 0.0_dp
    if (.not. (l2 > 0.0_dp .and. l3 > 0.0_dp)) then
      ier = st_singular
      return
    end if
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnma1_adapter(l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3, ra, ga, &
                        rb, gb, rc, gc, ier)
      return
    end if
    ! links 2 and 3, moments about B: the components of RA, RC normal to the links
    mbq2 = q2*cos(g2)*bs2*sin(pi + fi2) - q2*sin(g2)*bs2*cos(pi + fi2)
    rat = (m2 + mbq2)/l2
    gat = dugl3(fi2, pid2, rat)
    mbq3 = q3*cos(g3)*bs3*sin(pi + fi3) - q3*sin(g3)*bs3*cos(pi + fi3)
    rct = (m3 + mbq3)/l3
    gct = dugl3(fi3, pid2, rct)
    rat = abs(rat)
    rct = abs(rct)
    ! the group's forces: the components along the links
    call solve2(cos(fi2), cos(fi3), sin(fi2), sin(fi3), &
                -(rat*cos(gat) + q2*cos(g2) + q3*cos(g3) + rct*cos(gct)), &
                -(rat*sin(gat) + q2*sin(g2) + q3*sin(g3) + rct*sin(gct)), y1, y2, ier)
    if (ier == st_singular) return
    gan = dugl4(fi2, pi, y1)
    ran = abs(y1)
    gcn = dugl4(fi3, pi, y2)
    rcn = abs(y2)
    ra = sqrt(ran**2 + rat**2)
    rc = sqrt(rcn**2 + rct**2)
    ga = dugl6(ran, gan, rat, gat, fi2)
    gc = dugl6(rcn, gcn, rct, gct, fi3)
    rbx = -(ra*cos(ga) + q2*cos(g2))
    rby = -(ra*sin(ga) + q2*sin(g2))
    rb = sqrt(rbx**2 + rby**2)
    gb = dugl5(rbx, rby)
  end subroutine dnma1

  ! VII.7 DNMA2, L5322-5368.  Kind 2 (RRP).  L2 = AB, FI2 = direction A->B; L3 is not used;
  ! FIO = the guide's direction (printed F10, read FIO as in the body: E-DNMA2-1); ETA =
  ! the angle of link 3's line through B and S3 relative to the guide.
  ! Reduction points (E-DNMA2-3): S2 = B + BS2 e(FI2), S3 = B + BS3 e(FIO + ETA).
  ! RB = force on 2 from 3; RC perpendicular to the guide; HC*RC = moment about B of RC.
  ! Singular: AB perpendicular to the guide.
  ! ERRATA: E-DNMA2-1, E-DNMA2-2 (OCR), E-DUGL6-1, E-DNMA-1 (HC for RC = 0).
  subroutine dnma2(l2, fi2, l3, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                   ra, ga, rb, gb, rc, hc, gc, ier)
    !: L2, FI2 : length; real -- Length AB (m, > 0) and direction A->B (rad).
    !: L3 : real -- Length of link 3; not used by the listing (kept in the book's argument
    !:     list).
    !: ETA : real -- Direction of the line from B to S3 relative to the guide, rad.
    !: FIO : real -- Direction of the guide of pair C (printed ``F10`` in the header,
    !:     ``FIO`` in the body: ERRATA E-DNMA2-1), rad.
    !: BS2, BS3 : real -- Signed distances: **S2 = B + BS2 e(FI2)**, **S3 = B + BS3 e(FIO +
    !:     ETA)** (ERRATA E-DNMA2-3).
    !:insert loads_q
    real(dp), intent(in) :: l2, fi2, l3, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(out) :: ra, ga, rb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: mbq2, mbq3, rat, gat, y1, y2, gan, ran, rx, ry
    ra = 0.0_dp; ga = 0.0_dp; rb = 0.0_dp; gb = 0.0_dp; rc = 0.0_dp; hc = 0.0_dp
    gc = 0.0_dp
    if (.not. (l2 > 0.0_dp)) then
      ier = st_singular
      return
    end if
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnma2_adapter(l2, fi2, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3, ra, ga, &
                        rb, gb, rc, hc, gc, ier)
      return
    end if
    mbq2 = q2*cos(g2)*bs2*sin(pi + fi2) - q2*sin(g2)*bs2*cos(pi + fi2)
    rat = (m2 + mbq2)/l2
    gat = dugl3(fi2, pid2, rat)
    rat = abs(rat)
    call solve2(cos(fi2), cos(fio + pid2), sin(fi2), sin(fio + pid2), &
                -(rat*cos(gat) + q2*cos(g2) + q3*cos(g3)), &
                -(rat*sin(gat) + q2*sin(g2) + q3*sin(g3)), y1, y2, ier)
    if (ier == st_singular) return
    gan = dugl4(fi2, pi, y1)
    ran = abs(y1)
    gc = dugl3(fio, pid2, y2)
    rc = abs(y2)
    ra = sqrt(ran**2 + rat**2)
    ga = dugl6(ran, gan, rat, gat, fi2)
    mbq3 = q3*cos(g3)*bs3*sin(pi + fio + eta) - q3*sin(g3)*bs3*cos(pi + fio + eta)
    hc = arm(-(m3 + mbq3), rc)                                 ! E-DNMA-1
    rx = -(ra*cos(ga) + q2*cos(g2))
    ry = -(ra*sin(ga) + q2*sin(g2))
    rb = sqrt(rx**2 + ry**2)
    gb = dugl5(rx, ry)
  end subroutine dnma2

  ! VII.8 DNMA3, L5376-5413.  Kind 3 (RPR).  L2, ETA2 are not used.  FI3 = the guide's
  ! direction on link 3; (CS2, FICS2), (CS3, FICS3) = the vectors C->S2, C->S3; AC = |AC|.
  ! FIAC must be the direction A->C (E-DNMA3-4): the printed DUGL3(FIAC, -PID2, RAT) acts
  ! as DUGL3(FIAC, +PID2, RAT), because SIGN drops the sign of its first argument.
  ! RB = force on 2 from 3, perpendicular to the guide; HB*RB = moment about C of the force
  ! on 3 from 2 (-RB).  Singular: A = C, or AC perpendicular to the guide.
  ! ERRATA: E-DNMA3-1 (Q2, G2 missing from the header), E-DNMA3-2 (X(1,2) for X(1,1)),
  ! E-DNMA3-3 (GR for GB: OCR), E-DUGL6-1, E-DNMA-1 (HB for RB = 0).
  subroutine dnma3(l2, eta2, fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3, &
                   ra, ga, rb, hb, gb, rc, gc, ier)
    !: L2, ETA2 : real -- Not used by the listing (kept in the book's argument list).
    !: FI3 : real -- Direction of the guide on link 3, rad.
    !: CS2, FICS2, CS3, FICS3 : real >= 0; real; real >= 0; real -- Lengths (m, >= 0) and
    !:     directions of the vectors C->S2 and C->S3.
    !: AC, FIAC : length; real -- Length of AC (m, > 0) and its direction, which must be
    !:     **A->C** (ERRATA E-DNMA3-4): the printed ``DUGL3(FIAC, -PID2, RAT)`` acts as
    !:     ``DUGL3(FIAC, +PID2, RAT)`` because Fortran's SIGN keeps only the magnitude of
    !:     its first argument.
    !:insert loads_q
    real(dp), intent(in) :: l2, eta2, fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, &
                            q3, g3
    real(dp), intent(out) :: ra, ga, rb, hb, gb, rc, gc
    integer, intent(out) :: ier
    real(dp) :: mcq2, mcq3, rat, gat, y1, y2, gan, ran, rx, ry
    ra = 0.0_dp; ga = 0.0_dp; rb = 0.0_dp; hb = 0.0_dp; gb = 0.0_dp; rc = 0.0_dp
    gc = 0.0_dp
    if (.not. (ac > 0.0_dp)) then
      ier = st_singular
      return
    end if
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnma3_adapter(fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3, &
                        ra, ga, rb, hb, gb, rc, gc, ier)
      return
    end if
    ! the group, moments about C: the component of RA normal to AC
    mcq2 = q2*sin(g2)*cs2*cos(fics2) - q2*cos(g2)*cs2*sin(fics2)
    mcq3 = q3*sin(g3)*cs3*cos(fics3) - q3*cos(g3)*cs3*sin(fics3)
    rat = (m2 + m3 + mcq2 + mcq3)/ac
    gat = dugl3(fiac, -pid2, rat)
    rat = abs(rat)
    ! link 2's forces: the component of RA along AC and RB
    call solve2(cos(fiac), cos(fi3 + pid2), sin(fiac), sin(fi3 + pid2), &   ! E-DNMA3-2
                -(rat*cos(gat) + q2*cos(g2)), -(rat*sin(gat) + q2*sin(g2)), y1, y2, ier)
    if (ier == st_singular) return
    gan = dugl4(fiac, pi, y1)
    ran = abs(y1)
    gb = dugl3(fi3, pid2, y2)
    rb = abs(y2)
    ra = sqrt(ran**2 + rat**2)
    ga = dugl6(ran, gan, rat, gat, fiac)
    rx = -(rb*cos(gb + pi) + q3*cos(g3))
    ry = -(rb*sin(gb + pi) + q3*sin(g3))
    rc = sqrt(rx**2 + ry**2)
    gc = dugl5(rx, ry)
    hb = arm(-(m3 + mcq3), rb)                                 ! E-DNMA-1
  end subroutine dnma3

  ! VII.9 DNMA4, L5419-5460 (no heading printed; Table 33 numbers it VII.9).  Kind 4
  ! (PRP): guides FIM (pair A, link 2 on 1) and FIN (pair C, link 3 on 4); ETA2, ETA3 =
  ! the directions of the lines B->S2, B->S3 relative to the guides.
  ! Reduction points (E-DNMA4-2): S2 = B + BS2 e(FIM + ETA2), S3 = B + BS3 e(FIN + ETA3).
  ! RA perpendicular to FIM, RC to FIN; HA*RA = moment about B of RA, HC*RC = moment
  ! about B of RC.  RB = force on 2 from 3.  Singular: parallel guides.
  ! ERRATA: E-DNMA4-1 (FIM for FIN in HC's moment), E-DNMA-1 (HA, HC for zero forces).
  subroutine dnma4(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3, &
                   ra, ha, ga, rb, gb, rc, hc, gc, ier)
    !: FIM : real -- Direction of the guide of pair A (link 2 on link 1), rad.
    !: ETA2 : real -- Direction of the line B->S2 relative to FIM, rad.
    !: FIN : real -- Direction of the guide of pair C (link 3 on link 4), rad.
    !: ETA3 : real -- Direction of the line B->S3 relative to FIN, rad.
    !: BS2, BS3 : real -- Signed distances: **S2 = B + BS2 e(FIM + ETA2)**, **S3 = B + BS3
    !:     e(FIN + ETA3)** (ERRATA E-DNMA4-2).
    !:insert loads_q
    real(dp), intent(in) :: fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3
    real(dp), intent(out) :: ra, ha, ga, rb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: y1, y2, sm, rx, ry
    ra = 0.0_dp; ha = 0.0_dp; ga = 0.0_dp; rb = 0.0_dp; gb = 0.0_dp; rc = 0.0_dp
    hc = 0.0_dp; gc = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnma4_adapter(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3, ra, &
                        ha, ga, rb, gb, rc, hc, gc, ier)
      return
    end if
    call solve2(cos(fim + pid2), cos(fin + pid2), sin(fim + pid2), sin(fin + pid2), &
                -(q2*cos(g2) + q3*cos(g3)), -(q2*sin(g2) + q3*sin(g3)), y1, y2, ier)
    if (ier == st_singular) return
    ra = abs(y1)
    ga = dugl3(fim, pid2, y1)
    rc = abs(y2)
    gc = dugl3(fin, pid2, y2)
    sm = m2 + q2*cos(g2)*bs2*sin(pi + fim + eta2) - q2*sin(g2)*bs2*cos(pi + fim + eta2)
    ha = arm(-sm, ra)                                          ! E-DNMA-1
    sm = m3 + q3*cos(g3)*bs3*sin(pi + fin + eta3) &
         - q3*sin(g3)*bs3*cos(pi + fin + eta3)                 ! E-DNMA4-1: printed FIM
    hc = arm(-sm, rc)
    rx = -(ra*cos(ga) + q2*cos(g2))
    ry = -(ra*sin(ga) + q2*sin(g2))
    rb = sqrt(rx**2 + ry**2)
    gb = dugl5(rx, ry)
  end subroutine dnma4

  ! DNMA5, L5468-5513 (printed heading "VII.9"; Table 33 numbers it VII.10: E-DNMA5-1).
  ! Kind 5 (RPP): link 2 pivoted at A slides in link 3 along FIM + ETA3; link 3 slides on
  ! the guide FIM of link 4.
  ! Reduction points (E-DNMA5-3): FIAS2, FIAS3 are the directions S2->A, S3->A, i.e.
  ! S2 = A - AS2 e(FIAS2), S3 = A - AS3 e(FIAS3).
  ! RB = force on 3 from 2 (E-DNMA5-2: DNMA1-DNMA4 give the force on 2 from 3),
  ! perpendicular to FIM + ETA3; HB*RB = moment about A of the force on 2 from 3 (-RB);
  ! RC perpendicular to FIM, HC*RC = moment about A of RC.  Singular: parallel guides.
  ! ERRATA: E-DNMA5-4 (GELG tolerance 8.00001 for 0.0001: OCR), E-DNMA-1.
  subroutine dnma5(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3, &
                   ra, ga, rb, hb, gb, rc, hc, gc, ier)
    !: ETA3 : real -- Direction of the inner guide (link 2 slides in link 3) relative to
    !:     FIM.
    !: FIM : real -- Direction of the guide of link 3 on link 4.
    !: AS2, AS3, FIAS2, FIAS3 : real >= 0; real >= 0; real; real -- Lengths (m, >= 0) and
    !:     directions of the segments joining A and the reduction points; the directions run
    !:     **from S to A**: S2 = A - AS2 e(FIAS2), S3 = A - AS3 e(FIAS3) (ERRATA E-DNMA5-3).
    !:insert loads_q
    real(dp), intent(in) :: eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3
    real(dp), intent(out) :: ra, ga, rb, hb, gb, rc, hc, gc
    integer, intent(out) :: ier
    real(dp) :: y1, y2, sm1, sm
    ra = 0.0_dp; ga = 0.0_dp; rb = 0.0_dp; hb = 0.0_dp; gb = 0.0_dp; rc = 0.0_dp
    hc = 0.0_dp; gc = 0.0_dp
    if (printed_mode == 0) then                ! corrected: over the kernel
      call dnma5_adapter(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3, ra, &
                        ga, rb, hb, gb, rc, hc, gc, ier)
      return
    end if
    ! link 3's forces: RC and the force from 2, both normal to their guides
    call solve2(cos(fim + pid2), cos(fim + eta3 + pid2), sin(fim + pid2), &
                sin(fim + eta3 + pid2), -q3*cos(g3), -q3*sin(g3), y1, y2, ier)
    if (ier == st_singular) return
    rc = abs(y1)
    gc = dugl3(fim, pid2, y1)
    rb = abs(y2)
    gb = dugl3(fim + eta3, pid2, y2)
    call dsmvkt(rb, gb + pi, q2, g2, ra, ga)       ! link 2: RA = RB - Q2
    ga = ga + pi
    sm1 = m2 + q2*cos(g2)*as2*sin(fias2) - q2*sin(g2)*cos(fias2)*as2
    hb = arm(-sm1, rb)                                         ! E-DNMA-1
    sm = m3 + sm1 + q3*cos(g3)*as3*sin(fias3) - q3*sin(g3)*as3*cos(fias3)
    hc = arm(-sm, rc)
  end subroutine dnma5

end module forces
