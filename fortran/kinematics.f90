! kinematics.f90 -- chapter 4, kinematics of the class-II Assur groups (listings IV.1-IV.20,
! book lines L1440-3004): positions DPRM1-DPRM4 (+ DPRM5, an extension), velocities
! DSKOR1-DSKOR5, accelerations DUSKR1-DUSKR5, and the combined DKNMA1-DKNMA5.
!
! Group kinds (book section 4.2, Figs. 14-18):
!   1 RRR  external revolutes A, C; internal revolute B           (links 2 = AB, 3 = CB)
!   2 RRP  external revolute A; B on a slider in the guide of link M
!   3 RPR  slider 2 pivoted at A slides along link 3 pivoted at C (slotted lever)
!   4 PRP  sliders 2, 3 on the guides of links M, N, joined at revolute B
!   5 RPP  block 3 pivoted at C slides in link 2, which slides on the guide of link M
!
! Conventions (those of the book):
!   * angles in radians from +x, counter-clockwise positive; a velocity or acceleration is
!     a pair (modulus >= 0, direction angle); only omega (W*) and epsilon (E*) are signed;
!   * arguments before AAA (or ANALOG) are inputs, the ones after it are outputs; AAA is the
!     book's print flag and is not used here;
!   * PI and PID2 come from prmtr (the book's COMMON /PRMTR/): 3.14159 in as-printed mode;
!   * every 2x2 system is solved by GELG(Y, X, 2, 1, 0.0001, IER), as printed.
!
! Additions to the book (it reports no failure at all: ARCOS, SQRT or a division failed at
! run time): a trailing IER, set to a prmtr status code --
!   st_assembly     the links do not reach (the arccos/arcsin/sqrt argument is out of range);
!   st_singular     GELG IER = -1, an undefined position, or (dead-centre policy below) no
!                   significant digit of the result is left;
!   st_range        a result is not a finite double (an overflow);
!   st_digits + d   (101..107) the result is kept, with about d significant digits;
!   st_ok           at least 8 significant digits.
! On a failure every output is 0 (never NaN).
!
! The dead-centre policy (one rule for every routine of this module).  Each routine
! estimates the relative error EST of its results from what it solved:
!   * a 2x2 system (solve2e): the perturbation bound |A^-1|_F (|dA| |y| + |db|) with the
!     entries' errors dA (their directions known to a few roundings, plus, in DKNMA, the
!     sensitivity of the position found inside) and the right-hand side's db (a few
!     roundings of the sum of the moduli of its terms, plus the errors of the velocities
!     an acceleration system is built from), relative to max(|y|, size of the data);
!   * a position: how far it moves when its inputs move by one rounding, i.e. its
!     sensitivity (dc/sqrt(1 - c**2) for an angle found from a cosine or sine c known to
!     dc, sqrt(2 dc) at the flat position; the conditioning of the 2x2 system for DPRM4,
!     DPRM5), in radians of the link directions or relative to the group's size;
!   * kind 5 in the guide's frame (solve_kind5), where a small T2 costs no digits.
! EST is the largest of these, and d = floor(-log10(EST)) is the number of correct
! significant digits it vouches for (an error below 10**-d of the value changes the d-th
! digit by at most a unit).  Then: d < 1 (EST > 0.1): st_singular -- not even the first
! digit is assured, so nothing is returned (this is where the book returned rounding
! noise such as W2 = 2.6e15 at a dead centre); 1 <= d <= 7: st_digits + d, the results are
! kept and the Python layer warns with d; d >= 8: nothing is said.  GELG's own EPS = 1e-4
! pivot test stays in GELG (its IER), as in the book; it decides no status here.  The
! estimate is tested to bound the true error on sequences approaching every kind's dead
! centre (tests/test_reliability.py, mpmath references).
!
! Numerical rewrites that keep the book's mathematics (no ERRATA entry, the formulas are the
! same): the triangle angles of DPRM1 and DKNMA1 are computed as atan2(height, projection)
! with Kahan's stable Heron formula instead of ARCOS of the cosine law (ARCOS loses half the
! digits near a flat triangle); the foot of the perpendicular in DPRM2/DKNMA2 is computed by
! projection on the guide's unit vector instead of through TAN(FIM) (which fails for a
! vertical guide); DPRM4/DKNMA4 write the guide lines as n.B = n.A + offset (the printed rows
! multiplied by COS(FI)), so that a vertical guide works.  DPRM2, DPRM4 and DKNMA1-DKNMA4
! work in coordinates relative to the group's own points (A, or the guide's point K), so
! that a mechanism far from the origin keeps its digits (E-DKNMA1-3, E-DKNMA2-5,
! E-DKNMA4-5 for the directions the book took from absolute coordinates); lengths of
! 1e-300 or 1e300 neither underflow nor overflow where the answer is a double.
!
! One home per group kind (issue 25): in corrected mode every kind's routines are adapters
! over the kernels of groups.f90, the ones sarkp.Mechanism calls: DPRM and DKNMA 1-5 run
! the kind's kernel (or its stages in the kernel's order), DSKOR 1-5 its velocity stage
! and DUSKR 1-5 its acceleration stage from the positions and velocities they are given.
! The book's polar inputs become components, the kernel solves in Cartesian terms (kind
! 1: B from the triangle's apex, no cosine or sine of FI2; Cramer's rule), its results
! become the book's (modulus, direction) pairs, branch signs and angle ranges (DPRM1's up
! to 3 pi); the status is the dead-centre policy's for the kernel's estimate.  As-printed
! mode keeps each routine's own code, the book's sequence, which the printed figures
! depend on.
!
! For speed (issue 9; the same mathematics, no ERRATA entry; since issue 25 the
! as-printed path only): DSKOR1 and DUSKR1 take each direction's cosine and sine once and get e(FI + PI/2),
! e(FI + PI) by the exact identities (turn), and sum vectors by components where the
! book goes through DSMVKT's polar form and back.
!
! ERRATA ids of this chapter: E-<ROUTINE>-<n>, listed in docs/ERRATA.md.
module kinematics
  use prmtr, only: dp, pi, pid2, pi_exact, printed_mode, book_sign, st_ok, st_assembly, &
                   st_singular, st_range, st_digits, norm2d
  use operators, only: dugl1, dugl2, dugl3, dugl4, dugl5, dugol, domega, dvkt, dsmvkt
  use groups, only: rrr_kernel
  use groups, only: cram, prp_kernel, prp_position, prp_matrix, prp_velocity, &
                    prp_acceleration, rpp_kernel, rpp_velocity, rpp_acceleration
  use groups, only: rrr_system, rrr_velocity, rrr_acceleration
  use groups, only: rrp_position, rrp_system, rrp_velocity, rrp_acceleration, &
                    rpr_position, rpr_system, rpr_velocity, rpr_acceleration
  use numerics, only: uround, system2, solve2e, factor2, solve2f, solve_kind5, policy, &
                      settle, failed, wrap_pi, angle_sensitivity, tri_angles, tri_apex, &
                      apex_vectors, unscale, acc_dir, turn, components, quarter
  implicit none
  private
  public :: dprm1, dprm2, dprm3, dprm4, dprm5
  public :: dskor1, dskor2, dskor3, dskor4, dskor5
  public :: duskr1, duskr2, duskr3, duskr4, duskr5
  public :: dknma1, dknma2, dknma3, dknma4, dknma5


contains

  ! ============================================================================
  ! notes on the book's helpers
  ! ============================================================================

  ! The four-argument DUGL1 that DKNMA1-DKNMA3 call (L2598, L2698, L2775) is not the book's
  ! II.3 DUGL1(X1, Y1, X2, Y2); the DKNMA comments name the helpers of textbook [1] (L2578).
  ! From the geometry of all three calls (ERRATA E-DKNMA1-2) DUGL1(Y1, Y2, DX, FI) is the
  ! direction, in [0, 2*PI), of the vector from point 1 (ordinate Y1) to point 2 (ordinate
  ! Y2), where DX = X1 - X2 and FI is that direction modulo pi (its arctangent, redundant
  ! and dropped here): DKNMA1 with it puts B at AB = RZ2, CB = RZ3; the opposite reading does
  ! not.  That is II.3 DUGL1 on the two points, DUGL1(X1, Y1, X2, Y2), which is what
  ! DKNMA3 calls (direction A->C); DKNMA1 takes its directions from the triangle's angles.


  ! ============================================================================
  ! positions
  ! ============================================================================

  ! IV.1 DPRM1, L1479-1505 (Table 7, Fig. 14).  Kind 1 (RRR) positions.
  ! P is the assembly condition (L1477): P = -1 when A, B, C go clockwise, i.e. B lies on
  ! the left of the directed line A -> C; P = +1 the mirror branch (only the sign of P is
  ! used).  FI2 = direction A->B, FI3 = direction C->B, both DUGOL'd: in [0, 2*pi) for P = +1,
  ! up to 3*pi for P = -1, as printed (Fig. 91 prints FICB = 3.14..3.84).
  ! ERRATA: E-DPRM1-1 (corrected mode): the cosine-law ARCOS replaced by the apex of tri_apex.
  subroutine dprm1(xa, ya, xc, yc, rz2, rz3, p, aaa, fi2, fi3, xb, yb, ier)
    !: XA, YA : real -- Centre of the external revolute A (link 2), m.
    !: XC, YC : real -- Centre of the external revolute C (link 3), m.
    !: RZ2, RZ3 : length -- Link lengths AB and CB, m (> 0).
    !: P : branch -- Assembly branch (L1477): -1 when A, B, C go clockwise, i.e. B on the
    !:     left of the directed line A -> C; +1 the mirror image. Note: ``DKNMA1`` uses the
    !:     opposite sign.
    !: AAA : flag -- The book's print flag; unused (no report for this routine).
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, rz3, p, aaa
    real(dp), intent(out) :: fi2, fi3, xb, yb
    integer, intent(out) :: ier
    real(dp) :: rzac, fiac, ugbac, ugbca, q, dang, pa, h, pc
    real(dp) :: x_b(2), v_b(2), a_b(2), z(2), u2(2), u3(2), w2, w3, e2, e3, est
    integer :: e
    fi2 = 0.0_dp; fi3 = 0.0_dp; xb = 0.0_dp; yb = 0.0_dp
    q = book_sign(1.0_dp, p)
    if (printed_mode == 0) then
      ! Corrected: the kind-1 kernel's position (groups: rrr_kernel; its branch is -P), B
      ! from the triangle's apex (issue 9), and FI2, FI3 as the directions of B - A, B - C
      ! in the book's ranges.  The book's values are FIAC - P*angle A and FIAC + P*(angle
      ! C - pi), DUGOL'd once: for P = +1 the direction in [0, 2 pi); for P = -1 the sum
      ! turns counter-clockwise from FIAC by at most pi and passes 2 pi (stays above it, up
      ! to 3 pi) exactly when A->C points below the x axis and the direction found is below
      ! pi.
      z = 0.0_dp
      call rrr_kernel(1, [xa, ya], z, z, [xc, yc], z, z, rz2, rz3, -q, 1.0_dp/rz2, &
                      1.0_dp/rz3, x_b, v_b, a_b, u2, u3, w2, w3, e2, e3, ier, est)
      if (failed(ier)) return
      fi2 = dugol(atan2(u2(2), u2(1)))
      fi3 = dugol(atan2(u3(2), u3(1)))
      if (q < 0.0_dp .and. yc - ya < 0.0_dp) then   ! A->C below the x axis
        if (fi2 < pi) fi2 = fi2 + 2.0_dp*pi
        if (fi3 < pi) fi3 = fi3 + 2.0_dp*pi
      end if
      xb = x_b(1)
      yb = x_b(2)
      ier = policy(est)
    else
      ! As printed: the book's FIAC and angles (from the same apex, E-DPRM1-1)
      call dvkt(xa, ya, xc, yc, rzac, fiac)
      if (rzac == 0.0_dp) then
        if (rz2 == rz3) then
          ier = st_singular                         ! A = C, AB = CB: B anywhere on a circle
        else
          ier = st_assembly
        end if
        return
      end if
      call tri_apex(rzac, rz2, rz3, pa, h, pc, e, dang, ier)
      if (failed(ier)) return
      ugbac = atan2(h, pa)                          ! tri_angles' angles
      ugbca = atan2(h, pc)
      fiac = dugol(fiac)
      fi2 = dugol(fiac - q*ugbac)
      fi3 = dugol(fiac + q*ugbca - q*pi)
      xb = xa + rz2*cos(fi2)
      yb = ya + rz2*sin(fi2)
      ier = settle(ier, dang + 8.0_dp*uround*(1.0_dp + abs(fiac)), [xb, yb])
    end if
  end subroutine dprm1

  ! IV.2 DPRM2, L1531-1558 (Table 8, Fig. 15).  Kind 2 (RRP) positions.
  ! The guide passes through K with direction FIM; B is RZ3*SIN(T) from the guide axis, on
  ! the side of A.  Branch (L1543 "FIM is chosen along AB from A to B"): B lies ahead of the
  ! foot O' of the perpendicular from A, in the direction FIM; pass FIM + pi for the other
  ! branch.  Output order XB, YB, FI2 as in the code (Table 8's signature lists FI2 first).
  ! FI2 in the DUGL5 range (-pi/2, 3*pi/2).
  ! O' by projection on e(FIM) (the book's TAN(FIM) formula, same point, fails at FIM = pi/2).
  ! ERRATA: none in the code.
  subroutine dprm2(xa, ya, xk, yk, fim, rz2, rz3, t, aaa, xb, yb, fi2, ier)
    !: XA, YA : real -- Centre of the external revolute A, m.
    !: XK, YK : real -- Any point of the guide axis, m.
    !: FIM : real -- Direction of the guide, rad. It also selects the branch (L1543, "FIM is
    !:     chosen along AB from A to B"): B lies ahead, in the direction FIM, of the foot of
    !:     the perpendicular from A, as ``Mechanism.rrp(..., angle=FIM, branch=+1)`` places
    !:     it; pass ``FIM + pi`` for the other branch (``branch=-1``).
    !: RZ2 : length -- Length AB, m (> 0).
    !: RZ3, T : real >= 0; real -- Linear (m, >= 0) and angular (rad) size of the slider:
    !:     the offset of B from the guide axis is ``RZ3*sin(T)``.
    !: AAA : flag -- The book's print flag; unused.
    real(dp), intent(in) :: xa, ya, xk, yk, fim, rz2, rz3, t, aaa
    real(dp), intent(out) :: xb, yb, fi2
    integer, intent(out) :: ier
    real(dp) :: cm, sm, dx, dy, so, r, b, x, y, off, c, dc, tow
    if (printed_mode == 0) then
      call dprm2_rrp(xa, ya, xk, yk, fim, rz2, rz3, t, xb, yb, fi2, ier)   ! the kind-2 stages
    else
      xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp
      ier = st_ok
      if (.not. (rz2 > 0.0_dp .and. rz2 <= huge(rz2))) then
        ier = st_assembly
        return
      end if
      cm = cos(fim)
      sm = sin(fim)
      dx = xa - xk
      dy = ya - yk
      so = -dx*sm + dy*cm                           ! signed offset of A from the guide axis
      off = rz3*sin(t)
      if (so == 0.0_dp .and. off /= 0.0_dp) then
        ier = st_singular                           ! A on the guide: side of the offset undefined
        return
      end if
      ! A -> O' (foot of the perpendicular) is -sign(so) along the left normal (-sm, cm)
      tow = -sign(1.0_dp, so)
      r = abs(so) - off
      c = r/rz2
      if (abs(c) > 1.0_dp) then
        if (abs(c) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          ier = st_assembly                         ! B cannot reach the guide
          return
        end if
        c = sign(1.0_dp, c)
      end if
      b = rz2*sqrt((1.0_dp - c)*(1.0_dp + c))
      x = tow*rz2*c*(-sm) + b*cm
      y = tow*rz2*c*cm + b*sm
      fi2 = dugl5(x, y)
      xb = xa + rz2*cos(fi2)
      yb = ya + rz2*sin(fi2)
      ! sensitivity: c moves with the offsets and, through FIM, with the lever |A - K|
      dc = 4.0_dp*uround*(abs(so) + abs(off) + abs(rz3) + rz2 &
                          + (1.0_dp + abs(fim) + abs(t))*(abs(dx) + abs(dy)))/rz2
      ier = settle(ier, angle_sensitivity(c, dc) + 8.0_dp*uround*(1.0_dp + abs(fim)), [xb, yb])
    end if
  end subroutine dprm2

  ! IV.3 DPRM3, L1577-1598 (Table 9, Fig. 16).  Kind 3 (RPR, slotted lever) positions.
  ! RZ2*SIN(T) is the distance of A from the axis of link 3.  FI3 = FICA + P*angle BCA
  ! (L1565): P = -1 puts A on the left of the axis direction FI3, P = +1 on the right.
  ! FICA = direction C->A in (-pi, pi]; FI3 within pi/2 of FICA.
  ! ERRATA: E-DPRM3-1 (OCR FIZ for FI3).
  subroutine dprm3(xa, ya, xc, yc, rz2, t, p, aaa, rzac, fi3, fica, ier)
    !: XA, YA : real -- Centre of the revolute A of slider 2, m.
    !: XC, YC : real -- Centre of the revolute C of link 3, m.
    !: RZ2, T : real >= 0; real -- Linear (m, >= 0) and angular (rad) size of link 2: A is
    !:     ``RZ2*sin(T)`` from the axis of link 3 (with T = pi/2, RZ2 is that perpendicular,
    !:     L1563).
    !: P : branch -- Assembly branch (L1565): ``FI3 = FICA + P*angle BCA``; -1 puts A on the
    !:     left of the axis direction FI3, +1 on the right. ``DKNMA3`` uses the opposite
    !:     sign.
    !: AAA : flag -- The book's print flag; unused.
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, t, p, aaa
    real(dp), intent(out) :: rzac, fi3, fica
    integer, intent(out) :: ier
    real(dp) :: h, s, ugbca, ds
    if (printed_mode == 0) then
      call dprm3_rpr(xa, ya, xc, yc, rz2, t, p, rzac, fi3, fica, ier)   ! the kind-3 stages
    else
      rzac = 0.0_dp; fi3 = 0.0_dp; fica = 0.0_dp
      ier = st_ok
      h = rz2*sin(t)
      rzac = norm2d(xa - xc, ya - yc)
      if (rzac == 0.0_dp) then
        if (h == 0.0_dp) then
          ier = st_singular                         ! A = C: the axis direction is undefined
        else
          ier = st_assembly
        end if
        rzac = 0.0_dp
        return
      end if
      s = h/rzac
      if (abs(s) > 1.0_dp) then
        if (abs(s) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          ier = st_assembly                         ! A farther from the axis than from C
          rzac = 0.0_dp
          return
        end if
        s = sign(1.0_dp, s)
      end if
      fica = dugl2(xc, yc, xa, ya)
      ugbca = asin(s)
      fi3 = fica + book_sign(1.0_dp, p)*ugbca
      ds = 4.0_dp*uround*(abs(s)*(1.0_dp + abs(t)) + abs(rz2/rzac)*abs(t))
      ier = settle(ier, angle_sensitivity(s, ds) + 8.0_dp*uround*(1.0_dp + abs(fica)), [rzac])
    end if
  end subroutine dprm3

  ! IV.4 DPRM4, L1622-1657 (Table 10, Fig. 17).  Kind 4 (PRP) positions.
  ! Guide M through A with direction FIM, guide N through C with direction FIN; B is offset
  ! RZ2*SIN(T2) (RZ3*SIN(T3)) along the left normal e(FIM + pi/2) (e(FIN + pi/2)).  VM, VN
  ! are the instantaneous centres of the guide links; RVBM, FIVBM (RVBN, FIVBN) the radius
  ! vector of B from them, FIV* = DUGOL(DUGL2(...)) in [0, 2*pi).  Unique position.
  ! ERRATA: E-DPRM4-1 (X(1,2) = TAN(FIM): minus sign lost), E-DPRM4-2 (the line
  ! X(2,2) = -TAN(FIN) missing), E-DPRM4-3 (OCR 1, 0 for 1.0).  Rows of the printed system
  ! multiplied by COS(FIM), COS(FIN) (same lines; vertical guides allowed).
  ! Parallel guides: st_singular.
  ! Corrected mode (issue 25): an adapter over the kind-4 kernel of groups.f90 (the
  ! Mechanism's prp): its position stage prp_position (prp_kernel at level 1) solves B - A
  ! from the guides' unit vectors, A put at the origin (the kernel is the same in any
  ! frame; the given coordinates are exact, so only C - A is rounded, and a group far
  ! from the origin keeps its digits, as the book's code here does: E-DKNMA4-5); the
  ! radius vectors of B from VM, VN as before.  As printed: the code below, unchanged.
  ! The same holds for DSKOR4, DUSKR4 (over the stages prp_velocity, prp_acceleration, B
  ! put at the origin), DKNMA4 (over prp_kernel), and for kind 5: DPRM5, DKNMA5 over
  ! rpp_kernel, DSKOR5, DUSKR5 over rpp_velocity, rpp_acceleration.
  subroutine dprm4(xvm, yvm, xa, ya, fim, xvn, yvn, xc, yc, fin, rz2, t2, rz3, t3, aaa, &
                   xb, yb, rvbm, fivbm, rvbn, fivbn, ier)
    !: XVM, YVM : real -- Instantaneous centre of rotation of link M (carrying guide M), m.
    !: XA, YA, FIM : real -- A point of the axis of guide M (m) and its direction (rad).
    !: XVN, YVN : real -- Instantaneous centre of rotation of link N, m.
    !: XC, YC, FIN : real -- A point of the axis of guide N (m) and its direction (rad).
    !: RZ2, T2 : real >= 0; real -- B is ``RZ2*sin(T2)`` from guide M along its left normal,
    !:     direction FIM + pi/2.
    !: RZ3, T3 : real >= 0; real -- The same for guide N.
    !: AAA : flag -- The book's print flag; unused.
    real(dp), intent(in) :: xvm, yvm, xa, ya, fim, xvn, yvn, xc, yc, fin, rz2, t2, rz3, t3, aaa
    real(dp), intent(out) :: xb, yb, rvbm, fivbm, rvbn, fivbn
    integer, intent(out) :: ier
    real(dp) :: sm, cm, sn, cn, dxc, dyc, bx, by, d2, d3, sb, da, rel, mx, my, nx, ny
    real(dp) :: x_b(2), r_b(2), sx
    xb = 0.0_dp; yb = 0.0_dp; rvbm = 0.0_dp; fivbm = 0.0_dp; rvbn = 0.0_dp; fivbn = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-4 kernel's position
      call prp_position([0.0_dp, 0.0_dp], [cos(fim), sin(fim)], rz2*sin(t2), &
                        [xc - xa, yc - ya], [cos(fin), sin(fin)], rz3*sin(t3), x_b, r_b, &
                        sb, sx, ier, rel)
      if (failed(ier)) return
      xb = xa + r_b(1)
      yb = ya + r_b(2)
      mx = r_b(1) + (xa - xvm); my = r_b(2) + (ya - yvm)
      nx = r_b(1) - (xc - xa) + (xc - xvn); ny = r_b(2) - (yc - ya) + (yc - yvn)
      rvbm = norm2d(mx, my)
      fivbm = dugol(dugl2(0.0_dp, 0.0_dp, mx, my))
      rvbn = norm2d(nx, ny)
      fivbn = dugol(dugl2(0.0_dp, 0.0_dp, nx, ny))
      ier = settle(ier, rel, [xb, yb, rvbm, rvbn])
      return
    end if
    sm = sin(fim); cm = cos(fim)
    sn = sin(fin); cn = cos(fin)
    ! unknowns (YB - YA, XB - XA), the printed rows relative to A:
    !   cos(FI)*(YB - YA) - sin(FI)*(XB - XA) = cos(FI)*(Y - YA) - sin(FI)*(X - XA) + d
    dxc = xc - xa
    dyc = yc - ya
    d2 = rz2*sin(t2)
    d3 = rz3*sin(t3)
    sb = abs(d2) + abs(dxc) + abs(dyc) + abs(d3)
    da = 4.0_dp*uround*(1.0_dp + max(abs(fim), abs(fin)))
    call solve2e(cm, -sm, cn, -sn, d2, cn*dyc - sn*dxc + d3, da, &
                 4.0_dp*uround*(2.0_dp + abs(fin) + abs(t2) + abs(t3))*sb, sb, by, bx, ier, rel)
    if (failed(ier)) return
    xb = xa + bx
    yb = ya + by
    mx = bx + (xa - xvm); my = by + (ya - yvm)
    nx = bx - dxc + (xc - xvn); ny = by - dyc + (yc - yvn)
    rvbm = norm2d(mx, my)
    fivbm = dugol(dugl2(0.0_dp, 0.0_dp, mx, my))
    rvbn = norm2d(nx, ny)
    fivbn = dugol(dugl2(0.0_dp, 0.0_dp, nx, ny))
    ier = settle(ier, rel, [xb, yb, rvbm, rvbn])
  end subroutine dprm4

  ! DPRM5 -- EXTENSION, not in the book.  The book prints no position routine for kind 5
  ! (L1659: "the coordinates of the joint centre C and of the guide fully determine the
  ! linear and angular coordinates of the links"; Table 33, L6287, lists DPRM1-4 only).
  ! Kind 5 (RPP): link 2 slides on the guide of link M (through A, direction FIM) and turns
  ! with it; block 3, pivoted at C, slides in link 2 along FIM + T2.  Returned: K = (XK, YK),
  ! the point where the slot axis through C meets the guide axis, and the slider
  ! coordinates S2 (A -> K along e(FIM)) and S3 (K -> C along e(FIM + T2)), so that
  ! C = A + S2*e(FIM) + S3*e(FIM + T2).  Argument order after DKNMA5 (XA, YA, FIM, XC, YC,
  ! then T2 = ETA2).  SIN(T2) = 0 (slot parallel to the guide): st_singular.
  ! For a fixed guide dS2/dt and -dS3/dt are the signed VC2CM, VC2C3 of DSKOR5.
  subroutine dprm5(xa, ya, fim, xc, yc, t2, aaa, xk, yk, s2, s3, ier)
    !: XA, YA, FIM : real -- A point of the axis of guide M (m) and its direction (rad);
    !:     link 2 slides on it.
    !: XC, YC : real -- Centre of the revolute C of block 3, m.
    !: T2 : real -- Angular size of link 2: block 3 slides in link 2 along FIM + T2, rad.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: xa, ya, fim, xc, yc, t2, aaa
    real(dp), intent(out) :: xk, yk, s2, s3
    integer, intent(out) :: ier
    real(dp) :: cm, sm, dx, dy, d1, d2, sb, rel
    real(dp) :: z(2), x_k(2), v_k(2), a_k(2), us(2), q1, q2, q3, q4
    xk = 0.0_dp; yk = 0.0_dp; s2 = 0.0_dp; s3 = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-5 kernel (DPRM4)
      z = 0.0_dp
      call rpp_kernel(1, z, z, z, [cos(fim), sin(fim)], 0.0_dp, 0.0_dp, t2, cos(t2), &
                      sin(t2), [xc - xa, yc - ya], z, z, x_k, v_k, a_k, us, d1, d2, q1, q2, &
                      q3, q4, ier, rel)                ! A at the origin (DPRM4)
      if (failed(ier)) return
      xk = xa + x_k(1)
      yk = ya + x_k(2)
      s2 = d1
      s3 = d2
      ier = settle(ier, rel, [xk, yk, s2, s3])
      return
    end if
    cm = cos(fim)
    sm = sin(fim)
    dx = xc - xa
    dy = yc - ya
    d1 = dx*cm + dy*sm                            ! C - A in the frame of the guide
    d2 = -dx*sm + dy*cm
    sb = abs(dx) + abs(dy)
    ! s3*e(T2) - (-s2)*e(0) = (d1, d2)
    call solve_kind5(t2, d1, d2, 4.0_dp*uround*(2.0_dp + abs(fim))*sb, sb, s3, s2, ier, rel)
    if (failed(ier)) return
    s2 = -s2
    xk = xa + s2*cm
    yk = ya + s2*sm
    ier = settle(ier, rel, [xk, yk, s2, s3])
  end subroutine dprm5

  ! ============================================================================
  ! velocities
  ! ============================================================================

  ! IV.5 DSKOR1, L1692-1719 (Table 11, Fig. 19).  Kind 1 velocities:
  ! v_A + v_BA = v_C + v_BC, v_BA _|_ AB, v_BC _|_ CB.  W2, W3 signed (ccw +).
  ! ERRATA: none in the code.  Dead centre (FI2 = FI3 mod pi): st_singular.
  ! Corrected mode: an adapter over the kind-1 kernel's velocity stage (groups:
  ! rrr_velocity, the stage sarkp.Mechanism and DKNMA1 run): the links' vectors
  ! RZ e(FI) and the velocities' components in, W2, W3 and v_B out, turned into the
  ! book's (modulus, direction) pairs as DKNMA1's (dknma1_rrr).  As printed: the book's
  ! sequence (PID2 = 3.14159/2 in the directions).
  subroutine dskor1(rz2, fi2, rz3, fi3, va, ala, vc, alc, aaa, vba, alba, vbc, albc, vb, alb, &
                    w2, w3, ier)
    !: RZ2, FI2 : length; real -- Length AB (m, > 0) and direction A -> B (rad), from
    !:     ``DPRM1``.
    !: RZ3, FI3 : length; real -- Length CB and direction C -> B.
    !: VA, ALA : real -- Velocity of A: modulus (m/s) and direction (rad).
    !: VC, ALC : real -- Velocity of C (0, 0 for a fixed pivot).
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: rz2, fi2, rz3, fi3, va, ala, vc, alc, aaa
    real(dp), intent(out) :: vba, alba, vbc, albc, vb, alb, w2, w3
    integer, intent(out) :: ier
    real(dp) :: y1, y2, sb, rel, c2, s2, c3, s3, n2x, n2y, n3x, n3y, vax, vay, vcx, vcy
    real(dp) :: tx, ty, prx, pry
    vba = 0.0_dp; alba = 0.0_dp; vbc = 0.0_dp; albc = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp
    w2 = 0.0_dp; w3 = 0.0_dp
    if (printed_mode == 0) then
      call dskor1_rrr(rz2, fi2, rz3, fi3, va, ala, vc, alc, vba, alba, vbc, albc, vb, alb, &
                      w2, w3, ier)
      return
    end if
    ! each direction's cosine and sine once (turn, components; issue 9)
    c2 = cos(fi2)
    s2 = sin(fi2)
    c3 = cos(fi3)
    s3 = sin(fi3)
    call turn(fi2 + pid2, c2, s2, 1, n2x, n2y)      ! e(FI2 + PID2), e(FI3 + PID2)
    call turn(fi3 + pid2, c3, s3, 1, n3x, n3y)
    call components(va, ala, vax, vay)
    call components(vc, alc, vcx, vcy)
    sb = abs(va) + abs(vc)
    call solve2e(n2x, -n3x, n2y, -n3y, vcx - vax, vcy - vay, &
                 4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fi3))), &
                 4.0_dp*uround*(1.0_dp + max(abs(ala), abs(alc)))*sb, sb, y1, y2, ier, rel)
    if (failed(ier)) return
    alba = dugl3(fi2, pid2, y1)
    vba = abs(y1)
    albc = dugl3(fi3, pid2, y2)
    vbc = abs(y2)
    ! DSMVKT(VA, ALA, VBA, ALBA, VB, ALB) on the components already at hand
    call turn(alba, c2, s2, quarter(y1), tx, ty)    ! e(ALBA)
    prx = vax + vba*tx
    pry = vay + vba*ty
    vb = norm2d(prx, pry)
    alb = dugl5(prx, pry)
    w2 = domega(rz2, vba, alba - fi2)
    w3 = domega(rz3, vbc, albc - fi3)
    ier = settle(ier, rel, [vba, vbc, vb, w2, w3])
  end subroutine dskor1

  ! DSKOR1's corrected mode over rrr_velocity.  The directions FI2, FI3 are data known
  ! to an ulp (their error 4u (2 + |FI|), as the book's own path estimates it), and so are
  ! ALA, ALC (the components' error 4u (1 + |AL|) of their size).  W2, W3 are the
  ! stage's; VBA = |W2| RZ2 along FI2 + pi/2 turned by the sign of W2 (DUGL3, L1712).
  subroutine dskor1_rrr(rz2, fi2, rz3, fi3, va, ala, vc, alc, vba, alba, vbc, albc, vb, &
                        alb, w2, w3, ier)
    real(dp), intent(in) :: rz2, fi2, rz3, fi3, va, ala, vc, alc
    real(dp), intent(out) :: vba, alba, vbc, albc, vb, alb, w2, w3
    integer, intent(out) :: ier
    real(dp) :: r2(2), r3(2), v_a(2), v_c(2), v_b(2), om2, om3, ev, rel, dang
    type(cram) :: f
    vba = 0.0_dp; alba = 0.0_dp; vbc = 0.0_dp; albc = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp
    w2 = 0.0_dp; w3 = 0.0_dp
    r2 = rz2*[cos(fi2), sin(fi2)]
    r3 = rz3*[cos(fi3), sin(fi3)]
    call components(va, ala, v_a(1), v_a(2))
    call components(vc, alc, v_c(1), v_c(2))
    dang = 4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fi3)))
    call rrr_system(r2, r3, rz2, rz3, f)
    call rrr_velocity(f, r2, v_a, v_c, dang, 4.0_dp*uround*(1.0_dp + max(abs(ala), abs(alc))), &
                      v_b, om2, om3, ev, ier, rel)
    ! links that are not parallel make no dead centre: a singular system then comes of
    ! their lengths (one of 5e-324 beside one of 1: W2 = 2e323 is no double), a range
    ! problem
    if (ier == st_singular .and. abs(sin(fi2 - fi3)) > 4.0_dp*dang) ier = st_range
    if (failed(ier)) return
    call rrr_book_pairs(om2, om3, v_b, rz2, fi2, rz3, fi3, ier, rel, vba, alba, vbc, albc, &
                        vb, alb, w2, w3)
  end subroutine dskor1_rrr

  ! The book's pairs of a kind-1 stage's results (DSKOR1's and DUSKR1's adapters): y2, y3
  ! the rates of links 2, 3 (W or E), yb B's vector.  m2 = |y2| RZ2 along FI2 + pi/2 turned
  ! by the sign of y2 (DUGL3, L1712 and L2041), the same for link 3; mb, db = yb's modulus
  ! and direction (DUGL5); o2, o3 = y2, y3 (-0 made +0, as DOMEGA gives it).  A failing
  ! status (settle: an overflow) leaves every output 0.
  subroutine rrr_book_pairs(y2, y3, yb, rz2, fi2, rz3, fi3, ier, rel, m2, d2, m3, d3, mb, &
                            db, o2, o3)
    real(dp), intent(in) :: y2, y3, yb(2), rz2, fi2, rz3, fi3, rel
    integer, intent(inout) :: ier
    real(dp), intent(out) :: m2, d2, m3, d3, mb, db, o2, o3
    real(dp), parameter :: half_pi = pi_exact/2.0_dp     ! corrected mode's PID2
    o2 = y2 + 0.0_dp
    o3 = y3 + 0.0_dp
    m2 = abs(y2)*rz2
    m3 = abs(y3)*rz3
    d2 = fi2 + book_sign(half_pi, y2)             ! DUGL3(FI2, PID2, Y2)
    d3 = fi3 + book_sign(half_pi, y3)
    mb = norm2d(yb(1), yb(2))
    db = dugl5(yb(1), yb(2))
    ier = settle(ier, rel, [m2, m3, mb, o2, o3])
    if (failed(ier)) then
      m2 = 0.0_dp; d2 = 0.0_dp; m3 = 0.0_dp; d3 = 0.0_dp; mb = 0.0_dp; db = 0.0_dp
      o2 = 0.0_dp; o3 = 0.0_dp
    end if
  end subroutine rrr_book_pairs

  ! IV.6 DSKOR2, L1740-1774 (Table 12, Fig. 20).  Kind 2 velocities:
  ! v_A + v_BA = v_BM + v_BBM; VBM, ALBM = velocity of the guide point under B (0, 0 for a
  ! fixed guide); VBBM, ALBBM = sliding velocity along FIM (ALBBM = FIM or FIM - pi).
  ! ERRATA: E-DSKOR2-1 (printed header lacks VBA, ALBA: every call passes 15 arguments),
  ! E-DSKOR2-2 (OCR DOMECA).  AB perpendicular to the guide: st_singular.
  subroutine dskor2(va, ala, vbm, albm, rz2, fi2, fim, aaa, vba, alba, vbbm, albbm, vb, alb, &
                    w2, ier)
    !: VA, ALA : real -- Velocity of A: modulus (m/s), direction (rad).
    !: VBM, ALBM : real -- Velocity of the point of the guide link under B (0, 0 for a fixed
    !:     guide).
    !: RZ2, FI2 : length; real -- Length AB (m, > 0) and direction A -> B (rad), from
    !:     ``DPRM2``.
    !: FIM : real -- Direction of the guide, rad.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: va, ala, vbm, albm, rz2, fi2, fim, aaa
    real(dp), intent(out) :: vba, alba, vbbm, albbm, vb, alb, w2
    integer, intent(out) :: ier
    real(dp) :: y1, y2, sb, rel
    if (printed_mode == 0) then
      call dskor2_rrp(va, ala, vbm, albm, rz2, fi2, fim, vba, alba, vbbm, albbm, vb, alb, &
                      w2, ier)                           ! the kind-2 velocity stage
    else
      vba = 0.0_dp; alba = 0.0_dp; vbbm = 0.0_dp; albbm = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp
      w2 = 0.0_dp
      sb = abs(va) + abs(vbm)
      call solve2e(cos(fi2 + pid2), -cos(fim), sin(fi2 + pid2), -sin(fim), &
                   vbm*cos(albm) - va*cos(ala), vbm*sin(albm) - va*sin(ala), &
                   4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fim))), &
                   4.0_dp*uround*(1.0_dp + max(abs(ala), abs(albm)))*sb, sb, y1, y2, ier, rel)
      if (failed(ier)) return
      alba = dugl3(fi2, pid2, y1)
      vba = abs(y1)
      albbm = dugl4(fim, pi, y2)
      vbbm = abs(y2)
      w2 = domega(rz2, vba, alba - fi2)
      call dsmvkt(va, ala, vba, alba, vb, alb)
      ier = settle(ier, rel, [vba, vbbm, vb, w2])
    end if
  end subroutine dskor2

  ! IV.7 DSKOR3, L1805-1854 (Table 13, Fig. 21).  Kind 3 velocities:
  ! v_A3 = v_A + v_A3A (along the axis FI3) = v_C + v_A3C (_|_ CA).  A3 = point of link 3 at A.
  ! Pass FI3 as DPRM3 returned it (W3's sign is taken from ALA3C - FI3, as printed).
  ! ERRATA: none in the code.  Singular only for A = C.
  subroutine dskor3(xa, ya, xc, yc, va, ala, vc, alc, fi3, aaa, va3a, ala3a, va3c, ala3c, &
                    va3, ala3, w3, ier)
    !: XA, YA, XC, YC : real -- Joints A (slider pivot) and C (pivot of link 3), m.
    !: VA, ALA : real -- Velocity of A: modulus (m/s), direction (rad).
    !: VC, ALC : real -- Velocity of C.
    !: FI3 : real -- Direction of the axis of link 3, rad, as ``DPRM3`` returned it (the
    !:     sign of W3 is taken from ALA3C - FI3, as printed: FI3 must be within pi/2 of
    !:     FICA).
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: xa, ya, xc, yc, va, ala, vc, alc, fi3, aaa
    real(dp), intent(out) :: va3a, ala3a, va3c, ala3c, va3, ala3, w3
    integer, intent(out) :: ier
    real(dp) :: rzac, fica, y1, y2, sb, rel
    if (printed_mode == 0) then
      call dskor3_rpr(xa, ya, xc, yc, va, ala, vc, alc, fi3, va3a, ala3a, va3c, ala3c, &
                      va3, ala3, w3, ier)                ! the kind-3 velocity stage
    else
      va3a = 0.0_dp; ala3a = 0.0_dp; va3c = 0.0_dp; ala3c = 0.0_dp; va3 = 0.0_dp; ala3 = 0.0_dp
      w3 = 0.0_dp
      rzac = norm2d(xa - xc, ya - yc)
      if (rzac == 0.0_dp) then
        ier = st_singular
        return
      end if
      fica = dugl2(xc, yc, xa, ya)
      sb = abs(va) + abs(vc)
      call solve2e(cos(fi3), -cos(fica + pid2), sin(fi3), -sin(fica + pid2), &
                   vc*cos(alc) - va*cos(ala), vc*sin(alc) - va*sin(ala), &
                   4.0_dp*uround*(2.0_dp + max(abs(fi3), abs(fica))), &
                   4.0_dp*uround*(1.0_dp + max(abs(ala), abs(alc)))*sb, sb, y1, y2, ier, rel)
      if (failed(ier)) return
      ala3a = dugl4(fi3, pi, y1)
      va3a = abs(y1)
      ala3c = dugl3(fica, pid2, y2)
      va3c = abs(y2)
      w3 = domega(rzac, va3c, ala3c - fi3)
      call dsmvkt(va, ala, va3a, ala3a, va3, ala3)
      ier = settle(ier, rel, [va3a, va3c, va3, w3])
    end if
  end subroutine dskor3

  ! IV.8 DSKOR4, L1879-1918 (Table 14, Fig. 22).  Kind 4 velocities:
  ! v_BM + v_BBM = v_BN + v_BBN, v_BM = WM x (B - VM), v_BN = WN x (B - VN).
  ! ERRATA: E-DSKOR4-1 (header VBVM, ALBVM for VBBM, ALBBM), E-DSKOR4-2 (ALBVM = for
  ! ALBM =), E-DSKOR4-3 (author: Y(1) uses ABS(WM) where ABS(WN) is meant),
  ! E-DSKOR4-4 (OCR 8, 0, 0, 1 for 0.0001).  Parallel guides: st_singular.
  subroutine dskor4(rvbm, fivbm, fim, rvbn, fivbn, fin, wm, wn, aaa, vbbm, albbm, vbbn, albbn, &
                    vb, alb, ier)
    !: RVBM, FIVBM : real >= 0; real -- Distance (m) and direction (rad) of B from the
    !:     centre VM of link M (``DPRM4``).
    !: FIM : real -- Direction of guide M, rad.
    !: RVBN, FIVBN, FIN : real >= 0; real; real -- The same for link N.
    !: WM, WN : real -- Signed angular velocities of links M and N, rad/s.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: rvbm, fivbm, fim, rvbn, fivbn, fin, wm, wn, aaa
    real(dp), intent(out) :: vbbm, albbm, vbbn, albbn, vb, alb
    integer, intent(out) :: ier
    real(dp) :: vbm, vbn, albm, albn, y1, y2, sb, rel
    real(dp) :: z(2), r_m(2), r_n(2), v_b(2), relv, exb
    type(cram) :: f
    vbbm = 0.0_dp; albbm = 0.0_dp; vbbn = 0.0_dp; albbn = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-4 velocity stage
      ! B at the origin, VM at -r_m, VN at -r_n (points of the guide links at rest)
      z = 0.0_dp
      call components(rvbm, fivbm, r_m(1), r_m(2))
      call components(rvbn, fivbn, r_n(1), r_n(2))
      call prp_velocity(-r_m, z, [cos(fim), sin(fim)], wm, -r_n, z, [cos(fin), sin(fin)], wn, &
                        z, z, 0.0_dp, 0.0_dp, 0.0_dp, v_b, y1, y2, f, sb, relv, exb, ier, rel)
      if (failed(ier)) return
      albbm = dugl4(fim, pi, y1)
      vbbm = abs(y1)
      albbn = dugl4(fin, pi, y2)
      vbbn = abs(y2)
      vb = norm2d(v_b(1), v_b(2))                 ! v_BM + v_BBM (DSMVKT)
      alb = dugl5(v_b(1), v_b(2))
      ier = settle(ier, rel, [vbbm, vbbn, vb])
      return
    end if
    vbm = abs(wm)*rvbm
    vbn = abs(wn)*rvbn
    albm = dugl3(fivbm, pid2, wm)
    albn = dugl3(fivbn, pid2, wn)
    sb = vbm + vbn
    ! E-DSKOR4-3: the book's first factor is ABS(WM)
    call solve2e(cos(fim), -cos(fin), sin(fim), -sin(fin), &
                 vbn*cos(albn) - vbm*cos(albm), vbn*sin(albn) - vbm*sin(albm), &
                 4.0_dp*uround*(1.0_dp + max(abs(fim), abs(fin))), &
                 4.0_dp*uround*(2.0_dp + max(abs(fivbm), abs(fivbn)))*sb, sb, y1, y2, ier, rel)
    if (failed(ier)) return
    albbm = dugl4(fim, pi, y1)
    vbbm = abs(y1)
    albbn = dugl4(fin, pi, y2)
    vbbn = abs(y2)
    call dsmvkt(vbm, albm, vbbm, albbm, vb, alb)
    ier = settle(ier, rel, [vbbm, vbbn, vb])
  end subroutine dskor4

  ! IV.9 DSKOR5, L1947-1978 (Table 15, Fig. 23).  Kind 5 velocities:
  ! v_C2 = v_C3 + v_C2C3 (along FIM + T2) = v_CM + v_C2CM (along FIM), v_CM = WM x (C - VM).
  ! Link M, link 2 and block 3 all turn with WM.
  ! ERRATA: E-DSKOR5-1 (ALC3CM = for ALC2CM =).  SIN(T2) = 0: st_singular.
  subroutine dskor5(xc3, yc3, xvm, yvm, fim, t2, wm, vc3, alc3, aaa, vc2c3, alc2c3, vc2cm, &
                    alc2cm, vc2, alc2, ier)
    !: XC3, YC3 : real -- Centre of the revolute C of block 3, m.
    !: XVM, YVM : real -- Instantaneous centre of rotation of link M, m.
    !: FIM : real -- Direction of guide M, rad.
    !: T2 : real -- Angular size of link 2: block 3 slides along FIM + T2, rad.
    !: WM : real -- Signed angular velocity of link M, rad/s.
    !: VC3, ALC3 : real -- Velocity of C: modulus (m/s), direction (rad).
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: xc3, yc3, xvm, yvm, fim, t2, wm, vc3, alc3, aaa
    real(dp), intent(out) :: vc2c3, alc2c3, vc2cm, alc2cm, vc2, alc2
    integer, intent(out) :: ier
    real(dp) :: vcm, alcm, y1, y2, sb, rel
    real(dp) :: z(2), um(2), v_c(2), v_k(2), vr(2), v2(2), relv, r_c(2), r_k(2)
    vc2c3 = 0.0_dp; alc2c3 = 0.0_dp; vc2cm = 0.0_dp; alc2cm = 0.0_dp; vc2 = 0.0_dp; alc2 = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-5 velocity stage
      ! link M turns about VM (at rest); v_C3 - v_CM = vr = y2 e(FIM) - y1 e(FIM + T2)
      z = 0.0_dp
      um = [cos(fim), sin(fim)]
      call components(vc3, alc3, v_c(1), v_c(2))
      call rpp_velocity([xvm, yvm], z, um, wm, t2, [xc3, yc3], v_c, [xc3, yc3], 0.0_dp, &
                        0.0_dp, v_k, y2, y1, vr, r_c, r_k, sb, relv, ier, rel)
      if (failed(ier)) return
      y1 = -y1
      alc2c3 = dugl4(fim + t2, pi, y1)
      vc2c3 = abs(y1)
      alc2cm = dugl4(fim, pi, y2)
      vc2cm = abs(y2)
      v2 = (v_c - vr) + y2*um                     ! v_C2 = v_CM + v_C2CM
      vc2 = norm2d(v2(1), v2(2))
      alc2 = dugl5(v2(1), v2(2))
      ier = settle(ier, rel, [vc2c3, vc2cm, vc2])
      return
    end if
    vcm = abs(wm)*norm2d(xc3 - xvm, yc3 - yvm)
    alcm = dugl3(dugl2(xvm, yvm, xc3, yc3), pid2, wm)
    sb = vcm + abs(vc3)
    ! y1*e(FIM + T2) - y2*e(FIM) = v_CM - v_C3, in the guide's frame
    call solve_kind5(t2, vcm*cos(alcm - fim) - vc3*cos(alc3 - fim), &
                     vcm*sin(alcm - fim) - vc3*sin(alc3 - fim), &
                     4.0_dp*uround*(2.0_dp + abs(fim) + max(abs(alcm), abs(alc3)))*sb, sb, &
                     y1, y2, ier, rel)
    if (failed(ier)) return
    alc2c3 = dugl4(fim + t2, pi, y1)
    vc2c3 = abs(y1)
    alc2cm = dugl4(fim, pi, y2)
    vc2cm = abs(y2)
    call dsmvkt(vc3, alc3, vc2c3, alc2c3, vc2, alc2)
    ier = settle(ier, rel, [vc2c3, vc2cm, vc2])
  end subroutine dskor5

  ! ============================================================================
  ! accelerations
  ! ============================================================================

  ! IV.10 DUSKR1, L2017-2051 (Table 16, Fig. 24).  Kind 1 accelerations:
  ! a_A + a^n_BA + a^t_BA = a_C + a^n_BC + a^t_BC.
  ! ERRATA: E-DUSKR1-1 (author: ABCT = ABS(Y(1)) where Y(2) is meant; as-printed mode keeps
  ! it, Fig. 91 was computed with it), E-DUSKR1-2 (OCR 8.0001), E-DUSKR1-3 (OCR DOMEQA).
  ! Corrected mode: an adapter over the kind-1 kernel's acceleration stage (groups:
  ! rrr_acceleration), as DSKOR1's over its velocity stage.  As printed: the book's
  ! sequence.
  subroutine duskr1(aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3, aaa, abat, bbat, abct, bbct, &
                    ab, bb, e2, e3, ier)
    !: AA, BA : real -- Acceleration of A: modulus (m/s**2), direction (rad).
    !: AC, BC : real -- Acceleration of C.
    !: RZ2, FI2, RZ3, FI3 : length; real; length; real -- As for ``DSKOR1``.
    !: W2, W3 : real -- Angular velocities of links 2, 3 (from ``DSKOR1``), rad/s.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3, aaa
    real(dp), intent(out) :: abat, bbat, abct, bbct, ab, bb, e2, e3
    integer, intent(out) :: ier
    real(dp) :: y1, y2, a, b, an2, an3, sb, rel, c2, s2, c3, s3, n2x, n2y, n3x, n3y
    real(dp) :: m2x, m2y, m3x, m3y, aax, aay, acx, acy, tx, ty, prx, pry
    abat = 0.0_dp; bbat = 0.0_dp; abct = 0.0_dp; bbct = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp
    e2 = 0.0_dp; e3 = 0.0_dp
    if (printed_mode == 0) then
      call duskr1_rrr(aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3, abat, bbat, abct, bbct, &
                      ab, bb, e2, e3, ier)
      return
    end if
    an2 = w2**2*rz2
    an3 = w3**2*rz3
    sb = abs(aa) + abs(ac) + an2 + an3
    ! each direction's cosine and sine once (turn, components; issue 9)
    c2 = cos(fi2)
    s2 = sin(fi2)
    c3 = cos(fi3)
    s3 = sin(fi3)
    call turn(fi2 + pid2, c2, s2, 1, n2x, n2y)      ! e(FI2 + PID2), e(FI3 + PID2)
    call turn(fi3 + pid2, c3, s3, 1, n3x, n3y)
    call turn(fi2 - pi, c2, s2, -2, m2x, m2y)       ! e(FI2 - PI), e(FI3 - PI)
    call turn(fi3 - pi, c3, s3, -2, m3x, m3y)
    call components(aa, ba, aax, aay)
    call components(ac, bc, acx, acy)
    call solve2e(n2x, -n3x, n2y, -n3y, &
                 acx + an3*m3x - aax - an2*m2x, &
                 acy + an3*m3y - aay - an2*m2y, &
                 4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fi3))), &
                 4.0_dp*uround*(4.0_dp + max(abs(ba), abs(bc), abs(fi2), abs(fi3)))*sb, sb, &
                 y1, y2, ier, rel)
    if (failed(ier)) return
    bbat = dugl3(fi2, pid2, y1)
    abat = abs(y1)
    bbct = dugl3(fi3, pid2, y2)
    if (printed_mode /= 0) then
      abct = abs(y1)          ! E-DUSKR1-1: as printed (L2043), Fig. 91's E3 depends on it
    else
      abct = abs(y2)          ! E-DUSKR1-1: corrected
    end if
    if (printed_mode /= 0) then
      ! as printed: two DSMVKT, the partial sum AA + ABAN through its polar form
      call dsmvkt(aa, ba, an2, fi2 - pi, a, b)
      call dsmvkt(a, b, abat, bbat, ab, bb)
    else
      ! corrected (issue 9): the same vector AA + ABAN + ABAT summed by components
      call turn(bbat, c2, s2, quarter(y1), tx, ty)  ! e(BBAT)
      prx = aax + an2*m2x + abat*tx
      pry = aay + an2*m2y + abat*ty
      ab = norm2d(prx, pry)
      bb = dugl5(prx, pry)
    end if
    e2 = domega(rz2, abat, bbat - fi2)
    e3 = domega(rz3, abct, bbct - fi3)
    ier = settle(ier, rel, [abat, abct, ab, e2, e3])
  end subroutine duskr1

  ! DUSKR1's corrected mode over rrr_acceleration: FI2, FI3, BA, BC as DSKOR1's
  ! adapter takes its directions; W2, W3 are data (exact: no velocity error carried).
  ! ABAT = |E2| RZ2 along FI2 + pi/2 turned by the sign of E2 (DUGL3, L2041), ABCT =
  ! |E3| RZ3 (E-DUSKR1-1 corrected).
  subroutine duskr1_rrr(aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3, abat, bbat, abct, bbct, &
                        ab, bb, e2, e3, ier)
    real(dp), intent(in) :: aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3
    real(dp), intent(out) :: abat, bbat, abct, bbct, ab, bb, e2, e3
    integer, intent(out) :: ier
    real(dp) :: r2(2), r3(2), a_a(2), a_c(2), a_b(2), ep2, ep3, rel
    type(cram) :: f
    abat = 0.0_dp; bbat = 0.0_dp; abct = 0.0_dp; bbct = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp
    e2 = 0.0_dp; e3 = 0.0_dp
    r2 = rz2*[cos(fi2), sin(fi2)]
    r3 = rz3*[cos(fi3), sin(fi3)]
    call components(aa, ba, a_a(1), a_a(2))
    call components(ac, bc, a_c(1), a_c(2))
    call rrr_system(r2, r3, rz2, rz3, f)
    call rrr_acceleration(f, r2, r3, rz2, rz3, a_a, a_c, w2, w3, &
                          4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fi3))), 0.0_dp, &
                          4.0_dp*uround*(1.0_dp + max(abs(ba), abs(bc))), a_b, ep2, ep3, &
                          ier, rel)
    if (failed(ier)) return
    call rrr_book_pairs(ep2, ep3, a_b, rz2, fi2, rz3, fi3, ier, rel, abat, bbat, abct, bbct, &
                        ab, bb, e2, e3)
  end subroutine duskr1_rrr

  ! IV.11 DUSKR2, L2077-2119 (Table 17, Fig. 25).  Kind 2 accelerations:
  ! a_A + a^n_BA + a^t_BA = a_BM + a^k + a^r.  ABM, BVM: acceleration of the guide point
  ! under B; ABK, BVK: Coriolis acceleration of B relative to the guide, supplied by the
  ! caller (2*|WM|*VBBM at DUGL3(ALBBM, pi/2, WM); 0, 0 for a non-rotating guide).
  ! VBAT is the direction of a^t_BA, BVBM that of a^r (the author's B/V names, kept).
  ! ERRATA: E-DUSKR2-1 (OCR F12, 1ER, DSMVKI).
  subroutine duskr2(aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim, aaa, abat, vbat, abvm, &
                    bvbm, e2, ab, bb, ier)
    !: AA, BA : real -- Acceleration of A: modulus (m/s**2), direction (rad).
    !: ABM, BVM : real -- Acceleration of the point of the guide link under B (0, 0 for a
    !:     fixed guide).
    !: ABK, BVK : real -- Coriolis acceleration of B relative to the guide, supplied by the
    !:     caller: ``2*|WM|*VBBM`` at ``DUGL3(ALBBM, pi/2, WM)`` (0, 0 for a non-rotating
    !:     guide).
    !: RZ2, FI2 : length; real -- Length AB (m, > 0) and direction A -> B, rad.
    !: W2 : real -- Angular velocity of AB (from ``DSKOR2``), rad/s.
    !: FIM : real -- Direction of the guide, rad.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim, aaa
    real(dp), intent(out) :: abat, vbat, abvm, bvbm, e2, ab, bb
    integer, intent(out) :: ier
    if (printed_mode == 0) then
      call duskr2_rrp(aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim, abat, vbat, abvm, &
                      bvbm, e2, ab, bb, ier)             ! the kind-2 acceleration stage
    else
      ! the turning side A-B (a_A, link AB), the sliding side the guide (a_BM, Coriolis)
      call turn_slide(aa, ba, rz2, fi2, w2, abm, bvm, abk, bvk, fim, .true., &
                      abat, vbat, abvm, bvbm, e2, ab, bb, ier)
    end if
  end subroutine duskr2

  ! IV.12 DUSKR3, L2150-2184 (Table 18, Fig. 26).  Kind 3 accelerations:
  ! a_A3 = a_A + a^k + a^r (along FI3) = a_C + a^n_A3C + a^t_A3C.  AA3AK, BA3AK: Coriolis
  ! acceleration of A3 relative to A, supplied by the caller (2*|W3|*VA3A at
  ! DUGL3(ALA3A, pi/2, W3), IV.15 L2529).
  ! ERRATA: E-DUSKR3-1 (OCR BAZAR, BAZAK for BA3AR, BA3AK; DSMVWT).
  subroutine duskr3(aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak, aaa, aa3ar, ba3ar, &
                    aa3ct, ba3ct, e3, aa3, ba3, ier)
    !: AA, BA, AC, BC : real -- Accelerations of A and C: modulus (m/s**2), direction (rad).
    !: FI3, W3 : real -- Direction of the axis of link 3 (rad) and its angular velocity
    !:     (rad/s).
    !: RZAC, FICA : length; real -- AC (m, > 0) and the direction C -> A (rad), from
    !:     ``DPRM3``.
    !: AA3AK, BA3AK : real -- Coriolis acceleration of A3 relative to A, supplied by the
    !:     caller: ``2*|W3|*VA3A`` at ``DUGL3(ALA3A, pi/2, W3)`` (IV.15, L2529).
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak, aaa
    real(dp), intent(out) :: aa3ar, ba3ar, aa3ct, ba3ct, e3, aa3, ba3
    integer, intent(out) :: ier
    if (printed_mode == 0) then
      call duskr3_rpr(aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak, aa3ar, ba3ar, &
                      aa3ct, ba3ct, e3, aa3, ba3, ier)   ! the kind-3 acceleration stage
    else
      ! the turning side C-A3 (a_C, C -> A on link 3), the sliding side A (a_A, Coriolis)
      call turn_slide(ac, bc, rzac, fica, w3, aa, ba, aa3ak, ba3ak, fi3, .false., &
                      aa3ct, ba3ct, aa3ar, ba3ar, e3, aa3, ba3, ier)
    end if
  end subroutine duskr3

  ! DUSKR2 and DUSKR3 solve one equation (written once here): a point reached two ways,
  !   a_P + a^n + a^t  (turning: P's acceleration, then a link of length R, direction FR,
  !                     angular velocity W, about P)
  !   = a_Q + a^k + a^r (sliding: Q's acceleration, the Coriolis term, and a^r along FS).
  ! Returned: a^t (AT, BT), a^r (AR, BR), the link's E and the point's acceleration
  ! a_P + a^n + a^t (AX, BX).  TFIRST: the printed unknowns are (a^t, a^r) with the
  ! right-hand side a_Q + a^k - a_P - a^n (DUSKR2, L2098-2104); otherwise (a^r, a^t) with
  ! a_P + a^n - a_Q - a^k (DUSKR3, L2161-2168).  Each keeps the printed order of terms.
  subroutine turn_slide(ap, bp, r, fr, w, aq, bq, ak, bk, fs, tfirst, at, bt, ar, br, e, &
                        ax, bx, ier)
    real(dp), intent(in) :: ap, bp, r, fr, w, aq, bq, ak, bk, fs
    logical, intent(in) :: tfirst
    real(dp), intent(out) :: at, bt, ar, br, e, ax, bx
    integer, intent(out) :: ier
    real(dp) :: an, sb, da, db, y1, y2, yt, yr, rel, a, b
    at = 0.0_dp; bt = 0.0_dp; ar = 0.0_dp; br = 0.0_dp; e = 0.0_dp; ax = 0.0_dp; bx = 0.0_dp
    an = w**2*r
    sb = abs(ap) + abs(aq) + abs(ak) + an
    da = 4.0_dp*uround*(2.0_dp + max(abs(fr), abs(fs)))
    db = 4.0_dp*uround*(4.0_dp + max(abs(bp), abs(bq), abs(bk), abs(fr)))*sb
    if (tfirst) then
      call solve2e(cos(fr + pid2), -cos(fs), sin(fr + pid2), -sin(fs), &
                   aq*cos(bq) + ak*cos(bk) - ap*cos(bp) - an*cos(fr - pi), &
                   aq*sin(bq) + ak*sin(bk) - ap*sin(bp) - an*sin(fr - pi), &
                   da, db, sb, y1, y2, ier, rel)
      yt = y1
      yr = y2
    else
      call solve2e(cos(fs), -cos(fr + pid2), sin(fs), -sin(fr + pid2), &
                   ap*cos(bp) + an*cos(fr - pi) - aq*cos(bq) - ak*cos(bk), &
                   ap*sin(bp) + an*sin(fr - pi) - aq*sin(bq) - ak*sin(bk), &
                   da, db, sb, y1, y2, ier, rel)
      yr = y1
      yt = y2
    end if
    if (failed(ier)) return
    bt = dugl3(fr, pid2, yt)
    at = abs(yt)
    br = dugl4(fs, pi, yr)
    ar = abs(yr)
    e = domega(r, at, bt - fr)
    call dsmvkt(ap, bp, an, fr - pi, a, b)
    call dsmvkt(a, b, at, bt, ax, bx)
    if (tfirst) then
      ier = settle(ier, rel, [at, ar, e, ax])
    else
      ier = settle(ier, rel, [ar, at, e, ax])
    end if
  end subroutine turn_slide

  ! IV.13 DUSKR4, L2221-2275 (Table 19, Fig. 27).  Kind 4 accelerations:
  ! a_BM + a^k_M + a^r_M = a_BN + a^k_N + a^r_N; the guide points under B accelerate as
  ! points of links rotating about VM, VN (exact when VM, VN are fixed pivots).
  ! ABBMK, BBBMK (ABBNK, BBBNK): Coriolis accelerations, supplied by the caller.
  ! ERRATA: E-DUSKR4-1 (author: DLT = PID2 + ATAN(...) -- the stray PID2 turns the guide
  ! point's acceleration by pi), E-DUSKR4-2 (same for DLTA), E-DUSKR4-3 (header ABVMR,
  ! BBVMR for ABBMR, BBBMR), E-DUSKR4-4 (ABBMK = ABS(Y(1)) for ABBMR =), E-DUSKR4-5
  ! (DSMVKT(ABM, BVM, ...) for BBM).
  subroutine duskr4(rvbm, fivbm, fim, rvbn, fivbn, fin, wm, em, wn, en, abbmk, bbbmk, abbnk, &
                    bbbnk, aaa, abbmr, bbbmr, abbnr, bbbnr, ab, bb, ier)
    !: RVBM, FIVBM, FIM, RVBN, FIVBN, FIN : real >= 0; real; real; real >= 0; real; real -- As
    !:     for ``DSKOR4``.
    !: WM, EM : real -- Angular velocity (rad/s) and acceleration (rad/s**2) of link M.
    !: WN, EN : real -- The same for link N.
    !: ABBMK, BBBMK : real -- Coriolis acceleration of B relative to guide M, supplied by
    !:     the caller: ``2*|WM|*VBBM`` at ``DUGL3(ALBBM, pi/2, WM)``.
    !: ABBNK, BBBNK : real -- The same for guide N.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: rvbm, fivbm, fim, rvbn, fivbn, fin, wm, em, wn, en, abbmk, bbbmk
    real(dp), intent(in) :: abbnk, bbbnk, aaa
    real(dp), intent(out) :: abbmr, bbbmr, abbnr, bbbnr, ab, bb
    integer, intent(out) :: ier
    real(dp) :: abn, abm, dlt, dlta, bbm, bbn, y1, y2, a, b, sb, rel
    real(dp) :: z(2), r_m(2), r_n(2), um(2), un(2), k_m(2), k_n(2), a_b(2)
    type(cram) :: f
    abbmr = 0.0_dp; bbbmr = 0.0_dp; abbnr = 0.0_dp; bbbnr = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-4 acceleration stage
      ! B at the origin, VM at -r_m, VN at -r_n (points of the guide links at rest); the
      ! Coriolis accelerations as given
      z = 0.0_dp
      um = [cos(fim), sin(fim)]
      un = [cos(fin), sin(fin)]
      call components(rvbm, fivbm, r_m(1), r_m(2))
      call components(rvbn, fivbn, r_n(1), r_n(2))
      call components(abbmk, bbbmk, k_m(1), k_m(2))
      call components(abbnk, bbbnk, k_n(1), k_n(2))
      call prp_matrix(um, un, f)
      call prp_acceleration(-r_m, z, um, wm, em, -r_n, z, un, wn, en, z, 0.0_dp, 0.0_dp, &
                            k_m, k_n, abs(abbmk) + abs(abbnk), f, 0.0_dp, 0.0_dp, 0.0_dp, &
                            0.0_dp, 0.0_dp, a_b, y1, y2, ier, rel)
      if (failed(ier)) return
      bbbmr = dugl4(fim, pi, y1)
      abbmr = abs(y1)
      bbbnr = dugl4(fin, pi, y2)
      abbnr = abs(y2)
      ab = norm2d(a_b(1), a_b(2))                 ! a_BM + a^k_M + a^r_M
      bb = dugl5(a_b(1), a_b(2))
      ier = settle(ier, rel, [abbmr, abbnr, ab])
      return
    end if
    abn = rvbn*norm2d(wn*wn, en)                   ! = RVBN*SQRT(WN**4 + EN**2), no overflow
    abm = rvbm*norm2d(wm*wm, em)
    if (em == 0.0_dp) then
      dlt = pid2
    else
      dlt = atan(wm**2/abs(em))                   ! E-DUSKR4-1: book PID2 + ATAN(...)
    end if
    bbm = dugl3(fivbm, pid2 + dlt, em)
    if (en == 0.0_dp) then
      dlta = pid2
    else
      dlta = atan(wn**2/abs(en))                  ! E-DUSKR4-2: book PID2 + ATAN(...)
    end if
    bbn = dugl3(fivbn, pid2 + dlta, en)
    sb = abn + abm + abs(abbnk) + abs(abbmk)
    call solve2e(cos(fim), -cos(fin), sin(fim), -sin(fin), &
                 abn*cos(bbn) + abbnk*cos(bbbnk) - abm*cos(bbm) - abbmk*cos(bbbmk), &
                 abn*sin(bbn) + abbnk*sin(bbbnk) - abm*sin(bbm) - abbmk*sin(bbbmk), &
                 4.0_dp*uround*(1.0_dp + max(abs(fim), abs(fin))), &
                 4.0_dp*uround*(6.0_dp + max(abs(fivbm), abs(fivbn), abs(bbbmk), abs(bbbnk)))*sb, &
                 sb, y1, y2, ier, rel)
    if (failed(ier)) return
    bbbmr = dugl4(fim, pi, y1)
    abbmr = abs(y1)
    bbbnr = dugl4(fin, pi, y2)
    abbnr = abs(y2)
    call dsmvkt(abm, bbm, abbmk, bbbmk, a, b)
    call dsmvkt(a, b, abbmr, bbbmr, ab, bb)
    ier = settle(ier, rel, [abbmr, abbnr, ab])
  end subroutine duskr4

  ! IV.14 DUSKR5, L2308-2378 (Table 20, Fig. 28).  Kind 5 accelerations:
  ! a_C2 = a_C3 + a^k_23 + a^r_23 = a_CM + a^k_2M + a^r_2M; the guide point under C
  ! accelerates as a point of link M rotating about VM.  Argument order differs from DSKOR5
  ! (FIM, WM, EM, T2 here; FIM, T2, WM there), as printed.
  ! ERRATA: E-DUSKR5-1 (author: DLT = PID2 + ATAN(...), stray PID2 as in DUSKR4),
  ! E-DUSKR5-2 (OCR WM * / *4 for WM ** 4).
  subroutine duskr5(xc3, yc3, xvm, yvm, fim, wm, em, t2, ac3, bc3, ac2mk, bc2mk, ac23k, bc23k, &
                    aaa, ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac2, bc2, ier)
    !: XC3, YC3 : real -- Centre of the revolute C, m.
    !: XVM, YVM : real -- Centre of rotation of link M, m.
    !: FIM : real -- Direction of guide M, rad.
    !: WM, EM : real -- Angular velocity and acceleration of link M.
    !: T2 : real -- Slot direction of link 2 relative to the guide, rad.
    !: AC3, BC3 : real -- Acceleration of C: modulus (m/s**2), direction (rad).
    !: AC2MK, BC2MK : real -- Coriolis acceleration of C2 relative to the guide:
    !:     ``2*|WM|*VC2CM`` at ``DUGL3(ALC2CM, pi/2, WM)``.
    !: AC23K, BC23K : real -- Coriolis acceleration of C2 relative to C3: ``2*|WM|*VC2C3``
    !:     at ``DUGL3(ALC2C3, pi/2, WM)``.
    !: AAA : flag -- Print flag; unused.
    real(dp), intent(in) :: xc3, yc3, xvm, yvm, fim, wm, em, t2, ac3, bc3, ac2mk, bc2mk
    real(dp), intent(in) :: ac23k, bc23k, aaa
    real(dp), intent(out) :: ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac2, bc2
    integer, intent(out) :: ier
    real(dp) :: acm, dlt, bcm, y1, y2, a, b, sb, rel
    real(dp) :: z(2), um(2), us(2), a_c(2), k_2m(2), k_23(2), a_k(2), a2(2), r_c(2)
    ac2c3r = 0.0_dp; bc2c3r = 0.0_dp; ac2cmr = 0.0_dp; bc2cmr = 0.0_dp; ac2 = 0.0_dp
    bc2 = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-5 acceleration stage
      ! link M turns about VM (at rest); a_C3 - a_CM - (a^k_2M - a^k_23) =
      ! y2 e(FIM) - y1 e(FIM + T2), the Coriolis accelerations as given
      z = 0.0_dp
      um = [cos(fim), sin(fim)]
      call components(ac3, bc3, a_c(1), a_c(2))
      call components(ac2mk, bc2mk, k_2m(1), k_2m(2))
      call components(ac23k, bc23k, k_23(1), k_23(2))
      r_c = [xc3 - xvm, yc3 - yvm]                ! C - VM (K not needed: r_k = r_c)
      call rpp_acceleration(z, um, wm, em, t2, a_c, r_c, r_c, 0.0_dp, k_2m - k_23, &
                            abs(ac2mk) + abs(ac23k), 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, a_k, y2, y1, &
                            ier, rel)
      if (failed(ier)) return
      y1 = -y1
      bc2c3r = dugl4(fim + t2, pi, y1)
      ac2c3r = abs(y1)
      bc2cmr = dugl4(fim, pi, y2)
      ac2cmr = abs(y2)
      us = [um(1)*cos(t2) - um(2)*sin(t2), um(2)*cos(t2) + um(1)*sin(t2)]
      a2 = (a_c + k_23) + y1*us                   ! a_C2 = a_C3 + a^k_23 + a^r_23
      ac2 = norm2d(a2(1), a2(2))
      bc2 = dugl5(a2(1), a2(2))
      ier = settle(ier, rel, [ac2c3r, ac2cmr, ac2])
      return
    end if
    acm = norm2d(xc3 - xvm, yc3 - yvm)*norm2d(wm*wm, em)   ! = |C - VM| SQRT(WM**4 + EM**2)
    if (em == 0.0_dp) then
      dlt = pid2
    else
      dlt = atan(wm**2/abs(em))                   ! E-DUSKR5-1: book PID2 + ATAN(...)
    end if
    bcm = dugl3(dugl2(xvm, yvm, xc3, yc3), pid2 + dlt, em)
    sb = acm + abs(ac2mk) + abs(ac3) + abs(ac23k)
    ! y1*e(FIM + T2) - y2*e(FIM) = right-hand side, in the guide's frame
    call solve_kind5(t2, &
          acm*cos(bcm - fim) + ac2mk*cos(bc2mk - fim) - ac3*cos(bc3 - fim) - ac23k*cos(bc23k - fim), &
          acm*sin(bcm - fim) + ac2mk*sin(bc2mk - fim) - ac3*sin(bc3 - fim) - ac23k*sin(bc23k - fim), &
          4.0_dp*uround*(6.0_dp + abs(fim) + max(abs(bcm), abs(bc2mk), abs(bc3), abs(bc23k)))*sb, &
          sb, y1, y2, ier, rel)
    if (failed(ier)) return
    bc2c3r = dugl4(fim + t2, pi, y1)
    ac2c3r = abs(y1)
    bc2cmr = dugl4(fim, pi, y2)
    ac2cmr = abs(y2)
    call dsmvkt(ac3, bc3, ac23k, bc23k, a, b)
    call dsmvkt(a, b, ac2c3r, bc2c3r, ac2, bc2)
    ier = settle(ier, rel, [ac2c3r, ac2cmr, ac2])
  end subroutine duskr5

  ! ============================================================================
  ! combined: positions, velocities and (unless ANALOG = 1) accelerations
  ! ============================================================================
  ! The DKNMA routines come from textbook [1] (L2551): "in essence PRM, SKOR and USKR
  ! combined, with essential differences in detail".  With ANALOG = 1.0 they return after
  ! the velocities (the book's way of skipping work); the acceleration outputs are then 0.

  ! IV.16 DKNMA1, L2553-2658.  Kind 1 (RRR).
  ! Branch: P = +1 puts B on the LEFT of the directed line A -> C (A, B, C clockwise), the
  ! opposite of DPRM1's P (checked: B = A + RZ2*e(FI_AC + P*angle A)); DKNMA1(P) = DPRM1(-P).
  ! FI2, FI3 = DUGL2 directions in (-pi, pi] (DPRM1 gives DUGOL'd ones).
  ! ABAN, ABCN: normal accelerations of B relative to A, C (directions FI2 + pi, FI3 + pi).
  ! ERRATA: E-DKNMA1-1 (header AVAT, BVAT, AVCT, BVCT, VB for ABAT, BBAT, ABCT, BBCT, BB),
  ! E-DKNMA1-2 (four-argument DUGL1, see the note before acc_dir; FI = ATAN((YC-YA)/DX) not needed).
  subroutine dknma1(xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p, analog, &
                    xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3, abcn, aban, &
                    abat, bbat, abct, bbct, ab, bb, e2, e3, ier)
    !: XA, YA, XC, YC : real -- External revolutes A and C, m.
    !: RZ2, RZ3 : length -- AB and CB, m (> 0).
    !: VA, ALA, VC, ALC : real -- Velocities of A and C: modulus, direction.
    !: AA, BA, AC, BC : real -- Accelerations of A and C: modulus, direction.
    !: P : branch -- Assembly branch, the OPPOSITE sign of ``DPRM1``: +1 puts B on the left
    !:     of the directed line A -> C (A, B, C clockwise). ``DKNMA1(P) = DPRM1(-P)``.
    !: ANALOG : real = 0.0 -- 1.0: stop after the velocities (the book's way of skipping the
    !:     acceleration work, e.g. for velocity analogues); the acceleration outputs are
    !:     then 0. Anything else: compute the accelerations too.
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3
    real(dp), intent(out) :: abcn, aban, abat, bbat, abct, bbct, ab, bb, e2, e3
    integer, intent(out) :: ier
    real(dp) :: rac, fik, ugbac, ugbca, y1, y2, prx, pry, q, dang, da, sb, relv, rela, ev
    real(dp) :: est, c2, s2, c3, s3, n2x, n2y, n3x, n3y, m2x, m2y, m3x, m3y, tx, ty
    real(dp) :: vax, vay, vcx, vcy, aax, aay, acx, acy
    integer :: st2
    type(system2) :: sys
    q = book_sign(1.0_dp, p)
    if (printed_mode == 0) then                   ! corrected: the kind-1 kernel
      call dknma1_rrr(xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, q, &
                      analog, xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3, &
                      abcn, aban, abat, bbat, abct, bbct, ab, bb, e2, e3, ier)
    else
      xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp; fi3 = 0.0_dp; vba = 0.0_dp; alba = 0.0_dp
      vbc = 0.0_dp; albc = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp; w2 = 0.0_dp; w3 = 0.0_dp
      abcn = 0.0_dp; aban = 0.0_dp; abat = 0.0_dp; bbat = 0.0_dp; abct = 0.0_dp; bbct = 0.0_dp
      ab = 0.0_dp; bb = 0.0_dp; e2 = 0.0_dp; e3 = 0.0_dp
      rac = norm2d(xc - xa, yc - ya)
      if (rac == 0.0_dp) then
        if (rz2 == rz3) then
          ier = st_singular
        else
          ier = st_assembly
        end if
        return
      end if
      ! As printed: the book's sequence (the angles of the triangle, their cosines and sines)
      call tri_angles(rac, rz2, rz3, ugbac, ugbca, dang, ier)
      if (failed(ier)) return
      ! The book rotates B's coordinates in the frame of C->A (E-DKNMA1-2) and takes FI2,
      ! FI3 from the rounded absolute coordinates of B; the same directions come here
      ! straight from the triangle: B = A + RZ2 e(FI_AC + P*angle A),
      ! C->B = FI_AC + pi - P*angle C.
      fik = atan2(yc - ya, xc - xa)                 ! direction A->C
      fi2 = wrap_pi(fik + q*ugbac)
      fi3 = wrap_pi(fik + pi - q*ugbca)
      c2 = cos(fi2)
      s2 = sin(fi2)
      c3 = cos(fi3)
      s3 = sin(fi3)
      xb = xa + rz2*c2
      yb = ya + rz2*s2
      da = dang + 4.0_dp*uround*(2.0_dp + abs(fik))
      est = da
      ! The velocity and acceleration systems have the columns e(FI2 + PI/2), -e(FI3 + PI/2)
      ! (L2615, L2640); each direction's cosine and sine is taken once (turn, components).
      call turn(fi2 + pid2, c2, s2, 1, n2x, n2y)
      call turn(fi3 + pid2, c3, s3, 1, n3x, n3y)
      call components(va, ala, vax, vay)
      call components(vc, alc, vcx, vcy)
      sb = abs(va) + abs(vc)
      call factor2(n2x, -n3x, n2y, -n3y, sys)     ! one matrix for both systems (L2615, L2640)
      call solve2f(sys, vcx - vax, vcy - vay, da, &
                   4.0_dp*uround*(1.0_dp + max(abs(ala), abs(alc)))*sb, sb, y1, y2, ier, relv)
      if (failed(ier)) return
      est = max(est, relv)
      ev = relv*max(norm2d(y1, y2), sb/sqrt(2.0_dp))   ! absolute error of (y1, y2)
      alba = dugl3(fi2, pi/2.0_dp, y1)
      albc = dugl3(fi3, pi/2.0_dp, y2)
      vba = abs(y1)
      vbc = abs(y2)
      call turn(alba, c2, s2, quarter(y1), tx, ty)    ! e(ALBA)
      prx = vax + vba*tx
      pry = vay + vba*ty
      vb = norm2d(prx, pry)
      alb = dugl5(prx, pry)
      w2 = domega(rz2, vba, alba - fi2)
      w3 = domega(rz3, vbc, albc - fi3)
      if (analog /= 1.0_dp) then
        aban = w2**2*rz2
        abcn = w3**2*rz3
        call components(aa, ba, aax, aay)
        call components(ac, bc, acx, acy)
        call turn(fi2 + pi, c2, s2, 2, m2x, m2y)      ! e(FI2 + PI), e(FI3 + PI)
        call turn(fi3 + pi, c3, s3, 2, m3x, m3y)
        sb = abs(aa) + abs(ac) + aban + abcn
        call solve2f(sys, acx + abcn*m3x - aax - aban*m2x, acy + abcn*m3y - aay - aban*m2y, da, &
                     4.0_dp*uround*(4.0_dp + max(abs(ba), abs(bc)))*sb &
                     + ev/rz2*(2.0_dp*abs(y1) + ev) + ev/rz3*(2.0_dp*abs(y2) + ev), &
                     sb, y1, y2, st2, rela)
        ier = st2
        if (failed(ier)) return
        est = max(est, rela)
        bbat = dugl3(fi2, pi/2.0_dp, y1)
        bbct = dugl3(fi3, pi/2.0_dp, y2)
        abat = abs(y1)
        abct = abs(y2)
        call turn(bbat, c2, s2, quarter(y1), tx, ty)  ! e(BBAT)
        prx = aax + aban*m2x + abat*tx
        pry = aay + aban*m2y + abat*ty
        ab = norm2d(prx, pry)
        bb = dugl5(prx, pry)
        e2 = domega(rz2, abat, bbat - fi2)
        e3 = domega(rz3, abct, bbct - fi3)
      end if
      ier = settle(ier, est, [xb, yb, vba, vbc, vb, w2, w3, abcn, aban, abat, abct, ab, e2, e3])
    end if
  end subroutine dknma1

  ! DKNMA1's corrected mode: the book's interface over the kind-1 kernel (groups:
  ! rrr_kernel, the Mechanism's rrr).  In: the book's polar velocities and accelerations
  ! of A and C, as (x, y); Q = DKNMA1's P, which is the kernel's branch (+1: B on the left
  ! of A -> C).  Out: FI2, FI3 as DUGL2 directions in (-pi, pi]; each linear velocity or
  ! acceleration as (modulus, direction), the relative ones along e(FI + pi/2) turned by
  ! the sign of W or E (DUGL3, L2617-2620); ANALOG = 1: the kernel's velocity level, the
  ! accelerations 0.  A failure: every output 0.  The status is the policy's for the
  ! kernel's estimate (the drivers turn a result that is not finite into st_range).
  subroutine dknma1_rrr(xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, q, &
                        analog, xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3, &
                        abcn, aban, abat, bbat, abct, bbct, ab, bb, e2, e3, ier)
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, q
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3
    real(dp), intent(out) :: abcn, aban, abat, bbat, abct, bbct, ab, bb, e2, e3
    integer, intent(out) :: ier
    real(dp), parameter :: half_pi = pi_exact/2.0_dp     ! corrected mode's PID2
    real(dp) :: x_a(2), x_c(2), v_a(2), v_c(2), a_a(2), a_c(2), x_b(2), v_b(2), a_b(2)
    real(dp) :: u2(2), u3(2), om2, om3, ep2, ep3, est
    integer :: level
    level = 3
    if (analog == 1.0_dp) level = 2
    x_a(1) = xa
    x_a(2) = ya
    x_c(1) = xc
    x_c(2) = yc
    call components(va, ala, v_a(1), v_a(2))
    call components(vc, alc, v_c(1), v_c(2))
    a_a = 0.0_dp
    a_c = 0.0_dp
    if (level == 3) then
      call components(aa, ba, a_a(1), a_a(2))
      call components(ac, bc, a_c(1), a_c(2))
    end if
    call rrr_kernel(level, x_a, v_a, a_a, x_c, v_c, a_c, rz2, rz3, q, 1.0_dp/rz2, &
                    1.0_dp/rz3, x_b, v_b, a_b, u2, u3, om2, om3, ep2, ep3, ier, est)
    if (failed(ier)) then
      xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp; fi3 = 0.0_dp; vba = 0.0_dp; alba = 0.0_dp
      vbc = 0.0_dp; albc = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp; w2 = 0.0_dp; w3 = 0.0_dp
      abcn = 0.0_dp; aban = 0.0_dp; abat = 0.0_dp; bbat = 0.0_dp; abct = 0.0_dp
      bbct = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp; e2 = 0.0_dp; e3 = 0.0_dp
      return
    end if
    ier = policy(est)
    xb = x_b(1)
    yb = x_b(2)
    fi2 = atan2(u2(2), u2(1))
    fi3 = atan2(u3(2), u3(1))
    if (fi2 == -pi_exact) fi2 = pi_exact          ! the range (-pi, pi] of DUGL2
    if (fi3 == -pi_exact) fi3 = pi_exact
    w2 = om2 + 0.0_dp                             ! (-0 is +0, as DOMEGA gives it)
    w3 = om3 + 0.0_dp
    vba = abs(om2)*rz2
    vbc = abs(om3)*rz3
    alba = fi2 + book_sign(half_pi, om2)          ! DUGL3(FI2, PID2, W2)
    albc = fi3 + book_sign(half_pi, om3)
    vb = norm2d(v_b(1), v_b(2))
    alb = dugl5(v_b(1), v_b(2))
    if (level == 3) then
      e2 = ep2 + 0.0_dp
      e3 = ep3 + 0.0_dp
      abat = abs(ep2)*rz2
      abct = abs(ep3)*rz3
      aban = om2**2*rz2
      abcn = om3**2*rz3
      bbat = fi2 + book_sign(half_pi, ep2)
      bbct = fi3 + book_sign(half_pi, ep3)
      ab = norm2d(a_b(1), a_b(2))
      bb = dugl5(a_b(1), a_b(2))
    else                                          ! ANALOG = 1: no accelerations
      e2 = 0.0_dp; e3 = 0.0_dp; abat = 0.0_dp; abct = 0.0_dp; aban = 0.0_dp; abcn = 0.0_dp
      bbat = 0.0_dp; bbct = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp
    end if
  end subroutine dknma1_rrr

  ! IV.17 DKNMA2, L2660-2747.  Kind 2 (RRP).
  ! The guide passes through K with direction FIM and belongs to link M (omega WM); VBM, ALBM
  ! and ABM, BBM are the velocity and acceleration of the guide point under B (exact for a
  ! fixed guide: pass 0).  RZ3*SIN(ETA) offsets B from the guide axis along its LEFT normal
  ! e(FIM + pi/2) (DPRM2 offsets towards A: the two agree when A is on the left or the
  ! offset is 0).  Branch: P = +1 puts B ahead of the foot O' of the perpendicular from A
  ! along FIM, P = -1 behind: DKNMA2(FIM, P = +1) = DPRM2(FIM), DKNMA2(FIM, P = -1) =
  ! DPRM2(FIM + pi).  Coriolis ABK, BBK computed inside.  FI2 = DUGL2 direction A->B.
  ! ERRATA: E-DKNMA2-1 (header ABBM, VBBM, AB, VB for ABBM, BBBM, AB, BB), E-DKNMA2-2
  ! (OCR AA ** COS(BA), AE =, IF(ANALOG, EQ, 1.0)), E-DKNMA2-3 (author: the side of A is
  ! taken as SIGN(AO1, FIK - FIM) with FIK from the four-argument DUGL1 in [0, 2*pi):
  ! wrong for A on the right of a guide with FIM in (-pi/2, pi/2); fixed: signed offset
  ! (A - O').e(FIM + pi/2)), E-DKNMA2-4 (author: E2 = DOMEGA(.., BBAT - FI2) with BBAT =
  ! DUGL4(ALBA, PI, Y(1)) gets the wrong sign when ALBA = FI2 - pi/2 and Y(1) < 0; fixed:
  ! the sign of SIN(BBAT - FI2)).
  subroutine dknma2(xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa, ba, abm, &
                    bbm, p, analog, xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, w2, aban, &
                    abk, bbk, abat, bbat, abbm, bbbm, ab, bb, e2, ier)
    !: XA : real -- External revolute A, m.
    !: YA : real -- External revolute A, m.
    !: XK : real -- A point of the guide axis (m) and the guide direction (rad).
    !: YK : real -- A point of the guide axis (m) and the guide direction (rad).
    !: FIM : real -- A point of the guide axis (m) and the guide direction (rad).
    !: RZ2 : length -- AB, m (> 0).
    !: RZ3 : real >= 0 -- B is ``RZ3*sin(ETA)`` from the guide axis along its LEFT normal
    !:     e(FIM + pi/2) (``DPRM2`` offsets towards A; the two agree when A is on the left
    !:     or the offset is 0).
    !: ETA : real -- B is ``RZ3*sin(ETA)`` from the guide axis along its LEFT normal e(FIM +
    !:     pi/2) (``DPRM2`` offsets towards A; the two agree when A is on the left or the
    !:     offset is 0).
    !: VA : real -- Velocity of A.
    !: ALA : real -- Velocity of A.
    !: WM : real -- Angular velocity of the guide link (for the Coriolis acceleration),
    !:     rad/s.
    !: VBM : real -- Velocity and acceleration of the guide point under B (0 for a fixed
    !:     guide).
    !: ALBM : real -- Velocity and acceleration of the guide point under B (0 for a fixed
    !:     guide).
    !: AA : real -- Acceleration of A.
    !: BA : real -- Acceleration of A.
    !: ABM : real -- Velocity and acceleration of the guide point under B (0 for a fixed
    !:     guide).
    !: BBM : real -- Velocity and acceleration of the guide point under B (0 for a fixed
    !:     guide).
    !: P : branch -- Branch: +1 puts B ahead of the foot of the perpendicular from A along
    !:     FIM, -1 behind: ``DKNMA2(FIM, P=1) = DPRM2(FIM)``, ``DKNMA2(FIM, P=-1) =
    !:     DPRM2(FIM + pi)``; P is the branch of ``Mechanism.rrp(..., angle=FIM,
    !:     offset=RZ3*sin(ETA))``.
    !: ANALOG : real = 0.0 -- 1.0: stop after the velocities (the book's way of skipping the
    !:     acceleration work, e.g. for velocity analogues); the acceleration outputs are
    !:     then 0. Anything else: compute the accelerations too.
    real(dp), intent(in) :: xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa
    real(dp), intent(in) :: ba, abm, bbm, p, analog
    real(dp), intent(out) :: xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, w2, aban, abk, bbk
    real(dp), intent(out) :: abat, bbat, abbm, bbbm, ab, bb, e2
    integer, intent(out) :: ier
    real(dp) :: cm, sm, dx, dy, so, yb1, xb1, c, y1, y2, vbx, vby, abx, aby, bxa, bya
    real(dp) :: dc, da, sb, relv, rela, ev, est, c2, s2, n2x, n2y, vax, vay, vmx, vmy, tx, ty
    real(dp) :: ux, uy, kx, ky, wx, wy, m2x, m2y, amx, amy, aax, aay
    integer :: st2, kbm
    if (printed_mode == 0) then
      call dknma2_rrp(xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa, ba, &
                      abm, bbm, p, analog, xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, &
                      w2, aban, abk, bbk, abat, bbat, abbm, bbbm, ab, bb, e2, ier)
                                                         ! the kind-2 stages
    else
      xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp; vba = 0.0_dp; alba = 0.0_dp; vbbm = 0.0_dp
      albbm = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp; w2 = 0.0_dp; aban = 0.0_dp; abk = 0.0_dp
      bbk = 0.0_dp; abat = 0.0_dp; bbat = 0.0_dp; abbm = 0.0_dp; bbbm = 0.0_dp; ab = 0.0_dp
      bb = 0.0_dp; e2 = 0.0_dp
      ier = st_ok
      if (.not. (rz2 > 0.0_dp .and. rz2 <= huge(rz2))) then
        ier = st_assembly
        return
      end if
      cm = cos(fim)
      sm = sin(fim)
      dx = xa - xk
      dy = ya - yk
      so = -dx*sm + dy*cm                              ! E-DKNMA2-3: signed offset of A
      yb1 = rz3*sin(eta)
      c = (so - yb1)/rz2
      if (abs(c) > 1.0_dp) then
        if (abs(c) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          ier = st_assembly
          return
        end if
        c = sign(1.0_dp, c)
      end if
      xb1 = book_sign(1.0_dp, p)*rz2*sqrt((1.0_dp - c)*(1.0_dp + c))   ! = P*RZ2*SIN(ARCOS(c))
      ! B - A = XB1*e(FIM) + (YB1 - SO)*e(FIM + pi/2): the book's B = O' + rotated (XB1, YB1),
      ! taken relative to A so that no digit is lost far from the origin
      bxa = xb1*cm - (yb1 - so)*sm
      bya = xb1*sm + (yb1 - so)*cm
      xb = xa + bxa
      yb = ya + bya
      fi2 = dugl2(0.0_dp, 0.0_dp, bxa, bya)
      dc = 4.0_dp*uround*(abs(so) + abs(yb1) + abs(rz3) + rz2 &
                          + (1.0_dp + abs(fim) + abs(eta))*(abs(dx) + abs(dy)))/rz2
      da = angle_sensitivity(c, dc) + 4.0_dp*uround*(2.0_dp + abs(fim) + abs(fi2))
      est = da
      ! e(FI2) = (B - A)/RZ2; each direction's cosine and sine once (turn; issue 9)
      c2 = bxa/rz2
      s2 = bya/rz2
      call turn(fi2 + pi/2.0_dp, c2, s2, 1, n2x, n2y)
      call components(va, ala, vax, vay)
      call components(vbm, albm, vmx, vmy)
      sb = abs(va) + abs(vbm)
      call solve2e(n2x, -cm, n2y, -sm, vmx - vax, vmy - vay, da, &
                   4.0_dp*uround*(1.0_dp + max(abs(ala), abs(albm)))*sb, sb, y1, y2, ier, relv)
      if (failed(ier)) return
      est = max(est, relv)
      ev = relv*max(norm2d(y1, y2), sb/sqrt(2.0_dp))
      vba = abs(y1)
      alba = dugl3(fi2, pi/2.0_dp, y1)
      vbbm = abs(y2)
      albbm = dugl4(fim, pi, y2)
      kbm = 0                                          ! ALBBM = FIM + KBM*PI/2
      if (y2 < 0.0_dp) kbm = -2
      call turn(alba, c2, s2, quarter(y1), tx, ty)     ! e(ALBA)
      vbx = vax + vba*tx
      vby = vay + vba*ty
      vb = norm2d(vbx, vby)
      alb = dugl5(vbx, vby)
      w2 = domega(rz2, vba, alba - fi2)
      if (analog /= 1.0_dp) then
        aban = w2**2*rz2
        abk = 2.0_dp*vbbm*abs(wm)
        bbk = dugl3(albbm, pi/2.0_dp, wm)
        sb = abs(aa) + abs(abm) + aban + abk
        call turn(albbm, cm, sm, kbm, ux, uy)            ! e(ALBBM)
        call turn(bbk, cm, sm, kbm + quarter(wm), kx, ky) ! e(BBK)
        call turn(fi2 + pi, c2, s2, 2, m2x, m2y)         ! e(FI2 + PI)
        call components(abm, bbm, amx, amy)
        call components(aa, ba, aax, aay)
        call solve2e(tx, -ux, ty, -uy, &
                     amx + abk*kx - aax - aban*m2x, &
                     amy + abk*ky - aay - aban*m2y, da, &
                     4.0_dp*uround*(6.0_dp + max(abs(ba), abs(bbm), abs(fim), abs(fi2)))*sb &
                     + ev/rz2*(2.0_dp*abs(y1) + ev) + 2.0_dp*abs(wm)*ev, sb, y1, y2, st2, rela)
        ier = st2
        if (failed(ier)) return
        est = max(est, rela)
        abat = abs(y1)
        bbat = dugl4(alba, pi, y1)
        abbm = abs(y2)
        bbbm = dugl4(albbm, pi, y2)
        call turn(bbbm, cm, sm, kbm + quarter(y2) - 1, wx, wy)  ! e(BBBM)
        abx = amx + abk*kx + abbm*wx
        aby = amy + abk*ky + abbm*wy
        ab = norm2d(abx, aby)
        bb = dugl5(abx, aby)
        e2 = domega(rz2, abat, sin(bbat - fi2))          ! E-DKNMA2-4: book BBAT - FI2
      end if
      ier = settle(ier, est, [xb, yb, vba, vbbm, vb, w2, aban, abk, abat, abbm, ab, e2])
    end if
  end subroutine dknma2

  ! The kind-2 routines' corrected mode: the book's interface over the RRP stages of
  ! groups.f90 (rrp_position, rrp_system, rrp_velocity, rrp_acceleration), which
  ! sarkp.Mechanism's rrp_kernel runs too.  The book gives the guide's motion at the point
  ! under B (VBM, ALBM; ABM, BBM) where the kernel carries it from K: the adapters call the
  ! stages, the same sequence as the kernel past its carrying.  Polar inputs become
  ! components, the stages' results the book's (modulus, direction) pairs: a relative
  ! velocity or acceleration along the direction it is drawn in (DUGL3, DUGL4), turned
  ! by its sign; FI2 in the routine's range.  A failure: every output 0.  The status is
  ! the policy's for the stages' estimate.

  ! DPRM2: B on the side of A (the book's offset RZ3*SIN(T) towards A: along the left
  ! normal when A is on the left), ahead of the foot along FIM (the kernel's branch +1).
  subroutine dprm2_rrp(xa, ya, xk, yk, fim, rz2, rz3, t, xb, yb, fi2, ier)
    real(dp), intent(in) :: xa, ya, xk, yk, fim, rz2, rz3, t
    real(dp), intent(out) :: xb, yb, fi2
    integer, intent(out) :: ier
    real(dp) :: ug(2), so, off, x_b(2), u2(2), sl, est
    xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp
    if (.not. (rz2 > 0.0_dp .and. rz2 <= huge(rz2))) then
      ier = st_assembly
      return
    end if
    ug = [cos(fim), sin(fim)]
    so = -(xa - xk)*ug(2) + (ya - yk)*ug(1)       ! signed offset of A from the guide axis
    off = rz3*sin(t)
    if (so == 0.0_dp .and. off /= 0.0_dp) then
      ier = st_singular                           ! A on the guide: side of the offset undefined
      return
    end if
    call rrp_position([xa, ya], [xk, yk], ug, rz2, sign(1.0_dp, so)*off, 1.0_dp, x_b, u2, sl, &
                      ier, est)
    if (failed(ier)) return
    xb = x_b(1)
    yb = x_b(2)
    fi2 = dugl5(u2(1), u2(2))
    ier = settle(ier, est, [xb, yb])
  end subroutine dprm2_rrp

  ! DSKOR2: the velocity stage on the directions FI2, FIM (their rounding, 4u (2 + |FI|),
  ! the error of the system's directions, as the book routine's).
  subroutine dskor2_rrp(va, ala, vbm, albm, rz2, fi2, fim, vba, alba, vbbm, albbm, vb, alb, &
                        w2, ier)
    real(dp), intent(in) :: va, ala, vbm, albm, rz2, fi2, fim
    real(dp), intent(out) :: vba, alba, vbbm, albbm, vb, alb, w2
    integer, intent(out) :: ier
    real(dp) :: u2(2), ug(2), v_a(2), v_g(2), v_b(2), om2, sv, ev, est
    type(cram) :: f
    vba = 0.0_dp; alba = 0.0_dp; vbbm = 0.0_dp; albbm = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp
    w2 = 0.0_dp
    u2 = [cos(fi2), sin(fi2)]
    ug = [cos(fim), sin(fim)]
    call components(va, ala, v_a(1), v_a(2))
    call components(vbm, albm, v_g(1), v_g(2))
    est = 0.0_dp
    call rrp_system(u2, ug, f)
    call rrp_velocity(f, v_a, v_g, ug, 1.0_dp/rz2, 4.0_dp*uround*(2.0_dp + max(abs(fi2), &
                      abs(fim))), v_b, om2, sv, ev, ier, est)
    if (failed(ier)) return
    w2 = om2 + 0.0_dp                             ! (-0 is +0, as DOMEGA gives it)
    vba = abs(om2)*rz2
    alba = dugl3(fi2, pid2, om2)
    vbbm = abs(sv)
    albbm = dugl4(fim, pi, sv)
    vb = norm2d(v_b(1), v_b(2))
    alb = dugl5(v_b(1), v_b(2))
    ier = settle(ier, est, [vba, vbbm, vb, w2])
  end subroutine dskor2_rrp

  ! DUSKR2: the acceleration stage; the Coriolis term is the caller's (ABK, BVK), W2 is
  ! taken as exact (no velocity error carried).
  subroutine duskr2_rrp(aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim, abat, vbat, abvm, &
                        bvbm, e2, ab, bb, ier)
    real(dp), intent(in) :: aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim
    real(dp), intent(out) :: abat, vbat, abvm, bvbm, e2, ab, bb
    integer, intent(out) :: ier
    real(dp) :: u2(2), ug(2), a_a(2), a_g(2), a_k(2), a_b(2), ep2, sa, est
    type(cram) :: f
    abat = 0.0_dp; vbat = 0.0_dp; abvm = 0.0_dp; bvbm = 0.0_dp; e2 = 0.0_dp; ab = 0.0_dp
    bb = 0.0_dp
    u2 = [cos(fi2), sin(fi2)]
    ug = [cos(fim), sin(fim)]
    call components(aa, ba, a_a(1), a_a(2))
    call components(abm, bvm, a_g(1), a_g(2))
    call components(abk, bvk, a_k(1), a_k(2))
    est = 0.0_dp
    call rrp_system(u2, ug, f)
    call rrp_acceleration(f, a_a, a_g + a_k, 0.0_dp, u2, ug, rz2, 1.0_dp/rz2, w2, 0.0_dp, &
                          4.0_dp*uround*(2.0_dp + max(abs(fi2), abs(fim))), a_b, ep2, sa, ier, est)
    if (failed(ier)) return
    e2 = ep2 + 0.0_dp
    abat = abs(ep2)*rz2
    vbat = dugl3(fi2, pid2, ep2)
    abvm = abs(sa)
    bvbm = dugl4(fim, pi, sa)
    ab = norm2d(a_b(1), a_b(2))
    bb = dugl5(a_b(1), a_b(2))
    ier = settle(ier, est, [abat, abvm, e2, ab])
  end subroutine duskr2_rrp

  ! DKNMA2: the stages in the kernel's order; the guide's motion at B is the book's
  ! (VBM, ALBM; ABM, BBM), its Coriolis term 2 WM s' k x e(FIM) (ABK, BBK as the book
  ! draws it).  Q = P is the kernel's branch; the offset RZ3*SIN(ETA) along the left
  ! normal is the kernel's.  FI2 in (-pi, pi] (DUGL2); the relative velocity and
  ! acceleration of B about A along e(FI2 + pi/2) turned by the sign of W2 (ALBA) and the
  ! tangential acceleration along ALBA turned by its sign (BBAT); the sliding ones along
  ! FIM turned by the sign of s' (ALBBM) and s'' along ALBBM (BBBM), as printed.
  subroutine dknma2_rrp(xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa, ba, &
                        abm, bbm, p, analog, xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, &
                        w2, aban, abk, bbk, abat, bbat, abbm, bbbm, ab, bb, e2, ier)
    real(dp), intent(in) :: xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa
    real(dp), intent(in) :: ba, abm, bbm, p, analog
    real(dp), intent(out) :: xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, w2, aban, abk, bbk
    real(dp), intent(out) :: abat, bbat, abbm, bbbm, ab, bb, e2
    integer, intent(out) :: ier
    real(dp) :: ug(2), x_b(2), u2(2), sl, est, v_a(2), v_g(2), v_b(2), om2, sv, ev
    real(dp) :: a_a(2), a_g(2), a_b(2), ep2, sa, rl2, dang
    type(cram) :: f
    xb = 0.0_dp; yb = 0.0_dp; fi2 = 0.0_dp; vba = 0.0_dp; alba = 0.0_dp; vbbm = 0.0_dp
    albbm = 0.0_dp; vb = 0.0_dp; alb = 0.0_dp; w2 = 0.0_dp; aban = 0.0_dp; abk = 0.0_dp
    bbk = 0.0_dp; abat = 0.0_dp; bbat = 0.0_dp; abbm = 0.0_dp; bbbm = 0.0_dp; ab = 0.0_dp
    bb = 0.0_dp; e2 = 0.0_dp
    if (.not. (rz2 > 0.0_dp .and. rz2 <= huge(rz2))) then
      ier = st_assembly
      return
    end if
    rl2 = 1.0_dp/rz2
    ug = [cos(fim), sin(fim)]
    call rrp_position([xa, ya], [xk, yk], ug, rz2, rz3*sin(eta), book_sign(1.0_dp, p), x_b, &
                      u2, sl, ier, est)
    if (failed(ier)) return
    dang = est + 4.0_dp*uround
    call components(va, ala, v_a(1), v_a(2))
    call components(vbm, albm, v_g(1), v_g(2))
    call rrp_system(u2, ug, f)
    call rrp_velocity(f, v_a, v_g, ug, rl2, dang, v_b, om2, sv, ev, ier, est)
    if (failed(ier)) return
    if (analog /= 1.0_dp) then
      call components(aa, ba, a_a(1), a_a(2))
      call components(abm, bbm, a_g(1), a_g(2))
      a_g = a_g + (2.0_dp*wm*sv)*[-ug(2), ug(1)]
      call rrp_acceleration(f, a_a, a_g, 2.0_dp*abs(wm)*ev, u2, ug, rz2, rl2, om2, ev, dang, &
                            a_b, ep2, sa, ier, est)
      if (failed(ier)) return
    end if
    xb = x_b(1)
    yb = x_b(2)
    fi2 = atan2(u2(2), u2(1))
    if (fi2 == -pi) fi2 = pi                      ! the range (-pi, pi] of DUGL2
    w2 = om2 + 0.0_dp                             ! (-0 is +0, as DOMEGA gives it)
    vba = abs(om2)*rz2
    alba = dugl3(fi2, pid2, om2)
    vbbm = abs(sv)
    albbm = dugl4(fim, pi, sv)
    vb = norm2d(v_b(1), v_b(2))
    alb = dugl5(v_b(1), v_b(2))
    if (analog /= 1.0_dp) then
      aban = om2**2*rz2
      abk = 2.0_dp*vbbm*abs(wm)
      bbk = dugl3(albbm, pid2, wm)
      e2 = ep2 + 0.0_dp
      abat = abs(ep2)*rz2
      bbat = dugl4(alba, pi, book_sign(1.0_dp, om2)*ep2)
      abbm = abs(sa)
      bbbm = dugl4(albbm, pi, book_sign(1.0_dp, sv)*sa)
      ab = norm2d(a_b(1), a_b(2))
      bb = dugl5(a_b(1), a_b(2))
    end if
    ier = settle(ier, est, [xb, yb, vba, vbbm, vb, w2, aban, abk, abat, abbm, ab, e2])
  end subroutine dknma2_rrp

  ! IV.18 DKNMA3, L2749-2829.  Kind 3 (RPR, slotted lever).
  ! B is the point of the axis of link 3 with AB = RZ2 and angle ABC = ETA (ETA = pi/2: B is
  ! the foot of the perpendicular from A, RZ2 the offset).  Branch: P = +1 turns AB from AC
  ! counter-clockwise, B = A + RZ2*e(FI_AC + P*angle A); DKNMA3(P) = DPRM3(-P) (opposite of
  ! DPRM3's P).  RZBC = CB, FI3 = DUGL2 direction C->B (axis of link 3).  VAR, ALAR:
  ! velocity of A3 relative to A (along the axis); VAC, ALAC: of A3 relative to C; VA3, ALA3
  ! = v_C + v_A3C; AAK, BAK Coriolis; AAR, BAR relative; AACT, BACT tangential;
  ! AA3, BA3 = a_A + a^k + a^r; AACN = W3**2*AC.
  ! ERRATA: E-DKNMA3-1 (header lost ALAR, VAC between L2754 and L2755: 35 of 37
  ! arguments), E-DKNMA3-2 (OMEGA for DOMEGA; X(1.1) for X(1,1)), E-DKNMA1-2 (the
  ! four-argument DUGL1), E-DKNMA3-3 (author: BAR = DUGL4(ALAR, PID2, Y(1)), fixed to PI).
  subroutine dknma3(xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p, analog, &
                    xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, aak, bak, aar, &
                    bar, aact, bact, aa3, ba3, e3, aacn, ier)
    !: XA, YA : real -- Revolute A of the slider 2, m.
    !: XC, YC : real -- Revolute C of link 3, m.
    !: RZ2, ETA : real >= 0; real -- B is the point of the axis of link 3 with AB = RZ2 and
    !:     angle ABC = ETA (with ETA = pi/2, B is the foot of the perpendicular from A and
    !:     RZ2 the offset).
    !: VA, ALA, VC, ALC, AA, BA, AC, BC : real -- Velocities and accelerations of A and C.
    !: P : branch -- Branch, the OPPOSITE sign of ``DPRM3``: +1 turns AB counter-clockwise
    !:     from AC. ``DKNMA3(P) = DPRM3(-P)``.
    !: ANALOG : real = 0.0 -- 1.0: stop after the velocities (the book's way of skipping the
    !:     acceleration work, e.g. for velocity analogues); the acceleration outputs are
    !:     then 0. Anything else: compute the accelerations too.
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, aak, bak
    real(dp), intent(out) :: aar, bar, aact, bact, aa3, ba3, e3, aacn
    integer, intent(out) :: ier
    real(dp) :: rac, fik, s, ugbac, angc, q, bxa, bya, y1, y2, prx, pry, aa3x, aa3y
    real(dp) :: ds, da, sb, relv, rela, ev, ew, est
    integer :: st2
    if (printed_mode == 0) then
      call dknma3_rpr(xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p, &
                      analog, xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, &
                      aak, bak, aar, bar, aact, bact, aa3, ba3, e3, aacn, ier)
                                                         ! the kind-3 stages
    else
      xb = 0.0_dp; yb = 0.0_dp; rzbc = 0.0_dp; fi3 = 0.0_dp; var = 0.0_dp; alar = 0.0_dp
      vac = 0.0_dp; alac = 0.0_dp; w3 = 0.0_dp; va3 = 0.0_dp; ala3 = 0.0_dp; aak = 0.0_dp
      bak = 0.0_dp; aar = 0.0_dp; bar = 0.0_dp; aact = 0.0_dp; bact = 0.0_dp; aa3 = 0.0_dp
      ba3 = 0.0_dp; e3 = 0.0_dp; aacn = 0.0_dp
      ier = st_ok
      rac = norm2d(xa - xc, ya - yc)
      if (rac == 0.0_dp) then
        ier = st_singular
        return
      end if
      fik = dugl1(xa, ya, xc, yc)                   ! E-DKNMA1-2: direction A->C in [0, 2 pi)
      ! triangle A B C: angle B = ETA, AB = RZ2, AC = RAC; sine law: sin(angle C) = s
      s = rz2/rac*sin(eta)
      if (abs(s) > 1.0_dp) then
        if (abs(s) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          ier = st_assembly
          return
        end if
        s = sign(1.0_dp, s)
      end if
      angc = asin(s)
      ugbac = pi - eta - angc
      ! E-DKNMA3-4: for an obtuse ETA and RZ2 > AC the angles ETA and asin(s) already exceed
      ! pi: no triangle (the book would put B where angle ABC = pi - ETA).
      if (ugbac < 0.0_dp) then
        if (ugbac < -8.0_dp*epsilon(1.0_dp)*(pi + abs(eta))) then
          ier = st_assembly
          return
        end if
        ugbac = 0.0_dp
      end if
      q = book_sign(1.0_dp, p)
      ! B = A + RZ2 e(FIK + P*UGBAC) (the book's XB1, YB1 rotated by FIK), relative to A
      bxa = rz2*cos(fik + q*ugbac)
      bya = rz2*sin(fik + q*ugbac)
      xb = xa + bxa
      yb = ya + bya
      rzbc = norm2d(bxa + (xa - xc), bya + (ya - yc))
      ! E-DKNMA3-5: the axis of link 3 from the triangle's angle at C, C->B = C->A - P*angle C
      ! (the book's DUGL2(XC, YC, XB, YB) loses digits as CB shrinks and fails at B = C)
      fi3 = wrap_pi(fik + pi - q*angc)
      ds = 4.0_dp*uround*(abs(s)*(2.0_dp + abs(eta)) + abs(rz2/rac)*abs(eta))
      da = angle_sensitivity(s, ds) + 4.0_dp*uround*(4.0_dp + abs(fik) + abs(eta))
      est = da
      sb = abs(va) + abs(vc)
      call solve2e(cos(fi3), -cos((fik + pi) + pid2), sin(fi3), -sin((fik + pi) + pid2), &
                   vc*cos(alc) - va*cos(ala), vc*sin(alc) - va*sin(ala), da, &
                   4.0_dp*uround*(1.0_dp + max(abs(ala), abs(alc)))*sb, sb, y1, y2, ier, relv)
      if (failed(ier)) return
      est = max(est, relv)
      ev = relv*max(norm2d(y1, y2), sb/sqrt(2.0_dp))
      var = abs(y1)
      alar = dugl4(fi3, pi, y1)
      vac = abs(y2)
      alac = dugl3(fik + pi, pid2, y2)
      w3 = domega(rac, vac, alac - (fik + pi))
      prx = vc*cos(alc) + vac*cos(alac)
      pry = vc*sin(alc) + vac*sin(alac)
      va3 = norm2d(prx, pry)
      ala3 = dugl5(prx, pry)
      if (analog /= 1.0_dp) then
        aak = 2.0_dp*var*abs(w3)
        bak = dugl3(alar, pid2, w3)
        aacn = w3**2*rac
        ew = ev/rac                                 ! error of W3
        sb = abs(aa) + abs(ac) + aacn + aak
        call solve2e(cos(alar), -cos((fik + pi) + pid2), sin(alar), -sin((fik + pi) + pid2), &
                     ac*cos(bc) + aacn*cos(fik) - aa*cos(ba) - aak*cos(bak), &
                     ac*sin(bc) + aacn*sin(fik) - aa*sin(ba) - aak*sin(bak), da, &
                     4.0_dp*uround*(6.0_dp + max(abs(ba), abs(bc), abs(fik), abs(fi3)))*sb &
                     + (2.0_dp*abs(w3)*ew + ew*ew)*rac + 2.0_dp*(abs(w3)*ev + var*ew + ev*ew), &
                     sb, y1, y2, st2, rela)
        ier = st2
        if (failed(ier)) return
        est = max(est, rela)
        aar = abs(y1)
        bar = dugl4(alar, pi, y1)                     ! E-DKNMA3-3: book DUGL4(ALAR, PID2, Y(1))
        aact = abs(y2)
        bact = dugl3(fik + pi, pid2, y2)
        aa3x = aa*cos(ba) + aak*cos(bak) + aar*cos(bar)
        aa3y = aa*sin(ba) + aak*sin(bak) + aar*sin(bar)
        aa3 = norm2d(aa3x, aa3y)
        ba3 = dugl5(aa3x, aa3y)
        e3 = domega(rac, aact, bact - (fik + pi))
      end if
      ier = settle(ier, est, [xb, yb, rzbc, var, vac, w3, va3, aak, aar, aact, aa3, e3, aacn])
    end if
  end subroutine dknma3

  ! The kind-3 routines' corrected mode: the book's interface over the RPR stages of
  ! groups.f90 (rpr_position, rpr_system, rpr_velocity, rpr_acceleration), which
  ! sarkp.Mechanism's rpr_kernel runs too.  The book's A3 is the point of link 3 at A: its
  ! velocity v_A - s' u3 and acceleration a_C + e3 (A - C)_|_ - w3**2 (A - C); the book's
  ! relative motion of A3 along the axis is the kernel's sliding of A reversed, its
  ! Coriolis term the kernel's reversed.  A failure: every output 0.

  ! The kernel's branch for the book's sign P (DPRM3's; DKNMA3 passes -P) and offset h:
  ! the kernel's +1 puts B on the left of A -> C, i.e. turns C->B clockwise from C->A.
  pure real(dp) function rpr_branch(p, h)
    real(dp), intent(in) :: p, h
    rpr_branch = -book_sign(1.0_dp, p)*book_sign(1.0_dp, h)
  end function rpr_branch

  ! DPRM3: FI3 = FICA + the angle from C->A to the axis C->B (the kernel's uc, u3), in the
  ! book's range (within pi/2 of FICA).
  subroutine dprm3_rpr(xa, ya, xc, yc, rz2, t, p, rzac, fi3, fica, ier)
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, t, p
    real(dp), intent(out) :: rzac, fi3, fica
    integer, intent(out) :: ier
    real(dp) :: h, x_b(2), u3(2), uc(2), d, sl, eac, est
    rzac = 0.0_dp; fi3 = 0.0_dp; fica = 0.0_dp
    h = rz2*sin(t)
    call rpr_position([xa, ya], [xc, yc], h, rpr_branch(p, h), x_b, u3, uc, d, sl, eac, &
                      ier, est)
    if (failed(ier)) then
      if (d == 0.0_dp .and. h /= 0.0_dp) ier = st_assembly     ! A = C, the book's codes
      return
    end if
    rzac = d
    fica = dugl2(xc, yc, xa, ya)
    fi3 = fica + atan2(uc(1)*u3(2) - uc(2)*u3(1), uc(1)*u3(1) + uc(2)*u3(2))
    ier = settle(ier, est, [rzac])
  end subroutine dprm3_rpr

  ! DSKOR3: the velocity stage on the axis FI3 and A - C.
  subroutine dskor3_rpr(xa, ya, xc, yc, va, ala, vc, alc, fi3, va3a, ala3a, va3c, ala3c, &
                        va3, ala3, w3, ier)
    real(dp), intent(in) :: xa, ya, xc, yc, va, ala, vc, alc, fi3
    real(dp), intent(out) :: va3a, ala3a, va3c, ala3c, va3, ala3, w3
    integer, intent(out) :: ier
    real(dp) :: rzac, fica, uc(2), u3(2), v_a(2), v_c(2), v_b(2), om3, sv, ev, est, v3(2)
    type(cram) :: f
    va3a = 0.0_dp; ala3a = 0.0_dp; va3c = 0.0_dp; ala3c = 0.0_dp; va3 = 0.0_dp; ala3 = 0.0_dp
    w3 = 0.0_dp
    rzac = norm2d(xa - xc, ya - yc)
    if (rzac == 0.0_dp) then
      ier = st_singular
      return
    end if
    fica = dugl2(xc, yc, xa, ya)
    uc = [xa - xc, ya - yc]/rzac
    u3 = [cos(fi3), sin(fi3)]
    call components(va, ala, v_a(1), v_a(2))
    call components(vc, alc, v_c(1), v_c(2))
    est = 0.0_dp
    call rpr_system(uc, u3, f)
    call rpr_velocity(f, v_a, v_c, u3, rzac, 0.0_dp, 4.0_dp*uround*(2.0_dp + max(abs(fi3), &
                      abs(fica))), v_b, om3, sv, ev, ier, est)
    if (failed(ier)) return
    va3a = abs(sv)
    ala3a = dugl4(fi3, pi, -sv)
    va3c = abs(om3)*rzac
    ala3c = dugl3(fica, pid2, om3)
    w3 = domega(rzac, va3c, ala3c - fi3)          ! the sign as printed (FI3 near FICA)
    v3 = v_a - sv*u3
    va3 = norm2d(v3(1), v3(2))
    ala3 = dugl5(v3(1), v3(2))
    ier = settle(ier, est, [va3a, va3c, va3, w3])
  end subroutine dskor3_rpr

  ! DUSKR3: the acceleration stage; the Coriolis term is the caller's (AA3AK, BA3AK, of A3
  ! relative to A), W3 taken as exact.
  subroutine duskr3_rpr(aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak, aa3ar, ba3ar, &
                        aa3ct, ba3ct, e3, aa3, ba3, ier)
    real(dp), intent(in) :: aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak
    real(dp), intent(out) :: aa3ar, ba3ar, aa3ct, ba3ct, e3, aa3, ba3
    integer, intent(out) :: ier
    real(dp) :: uc(2), u3(2), a_a(2), a_c(2), a_k(2), a_b(2), ep3, sa, est, a3(2)
    type(cram) :: f
    aa3ar = 0.0_dp; ba3ar = 0.0_dp; aa3ct = 0.0_dp; ba3ct = 0.0_dp; e3 = 0.0_dp; aa3 = 0.0_dp
    ba3 = 0.0_dp
    uc = [cos(fica), sin(fica)]
    u3 = [cos(fi3), sin(fi3)]
    call components(aa, ba, a_a(1), a_a(2))
    call components(ac, bc, a_c(1), a_c(2))
    call components(aa3ak, ba3ak, a_k(1), a_k(2))
    est = 0.0_dp
    call rpr_system(uc, u3, f)
    call rpr_acceleration(f, a_a, a_c, -a_k, 0.0_dp, uc, u3, rzac, 0.0_dp, w3, 0.0_dp, 0.0_dp, &
                          4.0_dp*uround*(2.0_dp + max(abs(fica), abs(fi3))), a_b, ep3, sa, ier, &
                          est)
    if (failed(ier)) return
    e3 = ep3 + 0.0_dp
    aa3ar = abs(sa)
    ba3ar = dugl4(fi3, pi, -sa)
    aa3ct = abs(ep3)*rzac
    ba3ct = dugl3(fica, pid2, ep3)
    a3 = a_c + (ep3*rzac)*[-uc(2), uc(1)] - (w3**2*rzac)*uc
    aa3 = norm2d(a3(1), a3(2))
    ba3 = dugl5(a3(1), a3(2))
    ier = settle(ier, est, [aa3ar, aa3ct, e3, aa3])
  end subroutine duskr3_rpr

  ! DKNMA3: the stages in the kernel's order (the kernel's B is the foot of A on the axis;
  ! the book's B, where angle ABC = ETA, is RZ2*COS(ETA) beyond it along C->B).  FI3 in
  ! (-pi, pi] (DUGL2).  The book's relative motion of A3 along the axis, drawn along FI3
  ! turned by its sign (ALAR), its acceleration along ALAR turned by its sign (BAR).
  subroutine dknma3_rpr(xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p, &
                        analog, xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, aak, &
                        bak, aar, bar, aact, bact, aa3, ba3, e3, aacn, ier)
    real(dp), intent(in) :: xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, aak, bak
    real(dp), intent(out) :: aar, bar, aact, bact, aa3, ba3, e3, aacn
    integer, intent(out) :: ier
    real(dp) :: h, x_b(2), u3(2), uc(2), d, sl, eac, est, dang, fik, ce
    real(dp) :: v_a(2), v_c(2), v_b(2), om3, sv, ev, v3(2), a_a(2), a_c(2), a_b(2), ep3, sa
    real(dp) :: a3(2), y1
    type(cram) :: f
    xb = 0.0_dp; yb = 0.0_dp; rzbc = 0.0_dp; fi3 = 0.0_dp; var = 0.0_dp; alar = 0.0_dp
    vac = 0.0_dp; alac = 0.0_dp; w3 = 0.0_dp; va3 = 0.0_dp; ala3 = 0.0_dp; aak = 0.0_dp
    bak = 0.0_dp; aar = 0.0_dp; bar = 0.0_dp; aact = 0.0_dp; bact = 0.0_dp; aa3 = 0.0_dp
    ba3 = 0.0_dp; e3 = 0.0_dp; aacn = 0.0_dp
    h = rz2*sin(eta)
    call rpr_position([xa, ya], [xc, yc], h, -rpr_branch(p, h), x_b, u3, uc, d, sl, eac, &
                      ier, est)
    if (failed(ier)) return
    ! E-DKNMA3-4: the book's B beyond C (an obtuse ETA with RZ2 > AC): no triangle
    ce = rz2*cos(eta)
    rzbc = sl + ce
    if (rzbc < 0.0_dp) then
      if (rzbc < -8.0_dp*epsilon(1.0_dp)*(sl + abs(ce))) then
        ier = st_assembly
        return
      end if
      rzbc = 0.0_dp
    end if
    dang = est + 4.0_dp*uround*(4.0_dp + abs(eta))
    call components(va, ala, v_a(1), v_a(2))
    call components(vc, alc, v_c(1), v_c(2))
    call rpr_system(uc, u3, f)
    call rpr_velocity(f, v_a, v_c, u3, d, sl, dang, v_b, om3, sv, ev, ier, est)
    if (failed(ier)) return
    if (analog /= 1.0_dp) then
      call components(aa, ba, a_a(1), a_a(2))
      call components(ac, bc, a_c(1), a_c(2))
      call rpr_acceleration(f, a_a, a_c, (2.0_dp*om3*sv)*[-u3(2), u3(1)], &
                            2.0_dp*(abs(om3)*ev + abs(sv)*(ev/d)), uc, u3, d, sl, om3, ev, &
                            eac, dang, a_b, ep3, sa, ier, est)
      if (failed(ier)) return
    end if
    xb = x_b(1) + ce*u3(1)
    yb = x_b(2) + ce*u3(2)
    fi3 = atan2(u3(2), u3(1))
    if (fi3 == -pi) fi3 = pi                      ! the range (-pi, pi] of DUGL2
    fik = dugl1(xa, ya, xc, yc)                   ! A->C in [0, 2 pi), as printed
    w3 = om3 + 0.0_dp
    var = abs(sv)
    alar = dugl4(fi3, pi, -sv)
    vac = abs(om3)*d
    alac = dugl3(fik + pi, pid2, om3)
    v3 = v_a - sv*u3
    va3 = norm2d(v3(1), v3(2))
    ala3 = dugl5(v3(1), v3(2))
    if (analog /= 1.0_dp) then
      aak = 2.0_dp*var*abs(om3)
      bak = dugl3(alar, pid2, om3)
      aacn = om3**2*d
      e3 = ep3 + 0.0_dp
      y1 = -sa*book_sign(1.0_dp, -sv)             ! a^r = -s'' u3 along ALAR
      aar = abs(sa)
      bar = dugl4(alar, pi, y1)
      aact = abs(ep3)*d
      bact = dugl3(fik + pi, pid2, ep3)
      a3 = a_c + (ep3*d)*[-uc(2), uc(1)] - aacn*uc
      aa3 = norm2d(a3(1), a3(2))
      ba3 = dugl5(a3(1), a3(2))
    end if
    ier = settle(ier, est, [xb, yb, rzbc, var, vac, w3, va3, aak, aar, aact, aa3, e3, aacn])
  end subroutine dknma3_rpr

  ! IV.19 DKNMA4, L2831-2929.  Kind 4 (PRP).
  ! Guide M through A (direction FIM), guide N through C (FIN); offsets RZ2*SIN(ETA2),
  ! RZ3*SIN(ETA3) along the left normals, as DPRM4.  The guide links are taken to rotate
  ! about A and C (the book's model: exact when A, C are their fixed pivots, or WM = WN = 0).
  ! Argument order WM, WN, EM, EN (DUSKR4: WM, EM, WN, EN), as printed.
  ! VB2R, ALB2R (VB3R, ALB3R): velocity of B relative to guide M (N); AB2K.. Coriolis;
  ! AB2R.. relative accelerations; AB, BB = a_BM + a^k_M + a^r_M.
  ! ERRATA: E-DKNMA4-1 (header: missing comma after RZ3, MN for WN, missing parenthesis;
  ! PAB for RAB; "- -"), E-DKNMA4-2 (BB = DUGL5(VBX, VBY) for DUGL5(ABX, ABY)),
  ! E-DKNMA4-3 (author: IF (WM .EQ. 0) BBM = 0 -- wrong direction when WM = 0, EM /= 0;
  ! same for N; fixed with acc_dir), E-DPRM4-1 analogue not needed (the DKNMA4 matrix has
  ! its minus signs).  Rows multiplied by COS(FI) as in DPRM4.
  subroutine dknma4(fim, xa, ya, fin, xc, yc, rz2, eta2, rz3, eta3, wm, wn, em, en, analog, &
                    xb, yb, vb2r, alb2r, vb3r, alb3r, vb, alb, ab2k, bb2k, ab3k, bb3k, ab2r, &
                    bb2r, ab3r, bb3r, ab, bb, ier)
    !: FIM, XA, YA : real -- Direction of guide M and a point of its axis (its centre of
    !:     rotation).
    !: FIN, XC, YC : real -- The same for guide N.
    !: RZ2, ETA2, RZ3, ETA3 : real >= 0; real; real >= 0; real -- Offsets ``RZ2*sin(ETA2)``,
    !:     ``RZ3*sin(ETA3)`` of B along the left normals.
    !: WM, WN, EM, EN : real -- Angular velocities and accelerations of links M and N.
    !: ANALOG : real = 0.0 -- 1.0: stop after the velocities (the book's way of skipping the
    !:     acceleration work, e.g. for velocity analogues); the acceleration outputs are
    !:     then 0. Anything else: compute the accelerations too.
    real(dp), intent(in) :: fim, xa, ya, fin, xc, yc, rz2, eta2, rz3, eta3, wm, wn, em, en
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb, yb, vb2r, alb2r, vb3r, alb3r, vb, alb, ab2k, bb2k, ab3k, bb3k
    real(dp), intent(out) :: ab2r, bb2r, ab3r, bb3r, ab, bb
    integer, intent(out) :: ier
    real(dp) :: sm, cm, sn, cn, rab, cb, fi2, fi3, vbm, albm, vbn, albn, y1, y2, vbx, vby
    real(dp) :: abm, abn, bbm, bbn, abx, aby, dxc, dyc, bxa, bya, d2, d3, sb, da, relp, relv
    real(dp) :: rela, eb, ev, est, hm, hn
    real(dp) :: z(2), x_b(2), v_b(2), a_b(2), s2, s3
    integer :: st2, level
    xb = 0.0_dp; yb = 0.0_dp; vb2r = 0.0_dp; alb2r = 0.0_dp; vb3r = 0.0_dp; alb3r = 0.0_dp
    vb = 0.0_dp; alb = 0.0_dp; ab2k = 0.0_dp; bb2k = 0.0_dp; ab3k = 0.0_dp; bb3k = 0.0_dp
    ab2r = 0.0_dp; bb2r = 0.0_dp; ab3r = 0.0_dp; bb3r = 0.0_dp; ab = 0.0_dp; bb = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-4 kernel
      ! the guides turn about A and C (at rest), A put at the origin (DPRM4); the
      ! kernel's relative velocities s2, s3
      ! and accelerations y1, y2 are along e(FIM), e(FIN), the book's accelerations along
      ! ALB2R, ALB3R (e(FIM) or e(FIM - pi) by the sign of s2, DUGL4)
      level = 3
      if (analog == 1.0_dp) level = 2
      z = 0.0_dp
      call prp_kernel(level, z, z, z, [cos(fim), sin(fim)], wm, em, rz2*sin(eta2), &
                      [xc - xa, yc - ya], z, z, [cos(fin), sin(fin)], wn, en, rz3*sin(eta3), &
                      x_b, v_b, a_b, s2, s3, y1, y2, ier, est)
      if (failed(ier)) return
      xb = xa + x_b(1)
      yb = ya + x_b(2)
      vb2r = abs(s2)
      alb2r = dugl4(fim, pi, s2)
      vb3r = abs(s3)
      alb3r = dugl4(fin, pi, s3)
      vb = norm2d(v_b(1), v_b(2))
      alb = dugl5(v_b(1), v_b(2))
      if (level == 3) then
        ab2k = 2.0_dp*vb2r*abs(wm)
        ab3k = 2.0_dp*vb3r*abs(wn)
        bb2k = dugl3(alb2r, pid2, wm)
        bb3k = dugl3(alb3r, pid2, wn)
        ab2r = abs(y1)
        bb2r = dugl4(alb2r, pi, book_sign(1.0_dp, s2)*y1)
        ab3r = abs(y2)
        bb3r = dugl4(alb3r, pi, book_sign(1.0_dp, s3)*y2)
        ab = norm2d(a_b(1), a_b(2))
        bb = dugl5(a_b(1), a_b(2))
      end if
      ier = settle(ier, est, [xb, yb, vb2r, vb3r, vb, ab2k, ab3k, ab2r, ab3r, ab])
      return
    end if
    sm = sin(fim); cm = cos(fim)
    sn = sin(fin); cn = cos(fin)
    ! the printed rows relative to A (unknowns YB - YA, XB - XA), as in DPRM4
    dxc = xc - xa
    dyc = yc - ya
    d2 = rz2*sin(eta2)
    d3 = rz3*sin(eta3)
    sb = abs(d2) + abs(dxc) + abs(dyc) + abs(d3)
    da = 4.0_dp*uround*(1.0_dp + max(abs(fim), abs(fin)))
    call solve2e(cm, -sm, cn, -sn, d2, cn*dyc - sn*dxc + d3, da, &
                 4.0_dp*uround*(2.0_dp + abs(fin) + abs(eta2) + abs(eta3))*sb, sb, bya, bxa, &
                 ier, relp)
    if (failed(ier)) return
    est = relp
    eb = relp*max(norm2d(bxa, bya), sb/2.0_dp)       ! absolute error of B
    xb = xa + bxa
    yb = ya + bya
    rab = norm2d(bxa, bya)
    cb = norm2d(bxa - dxc, bya - dyc)
    fi2 = dugl2(0.0_dp, 0.0_dp, bxa, bya)
    fi3 = dugl2(0.0_dp, 0.0_dp, bxa - dxc, bya - dyc)
    vbm = abs(wm)*rab
    albm = dugl3(fi2, pid2, wm)
    vbn = abs(wn)*cb
    albn = dugl3(fi3, pid2, wn)
    sb = vbm + vbn
    call solve2e(cm, -cn, sm, -sn, vbn*cos(albn) - vbm*cos(albm), vbn*sin(albn) - vbm*sin(albm), &
                 da, 4.0_dp*uround*(4.0_dp + max(abs(fi2), abs(fi3)))*sb &
                 + (abs(wm) + abs(wn))*eb, sb, y1, y2, st2, relv)
    ier = st2
    if (failed(ier)) return
    est = max(est, relv)
    ev = relv*max(norm2d(y1, y2), sb/2.0_dp)
    vb2r = abs(y1)
    alb2r = dugl4(fim, pi, y1)
    vb3r = abs(y2)
    alb3r = dugl4(fin, pi, y2)
    vbx = vbm*cos(albm) + vb2r*cos(alb2r)
    vby = vbm*sin(albm) + vb2r*sin(alb2r)
    vb = norm2d(vbx, vby)
    alb = dugl5(vbx, vby)
    if (analog /= 1.0_dp) then
      hm = norm2d(wm*wm, em)                       ! = SQRT(WM**4 + EM**2), no overflow
      hn = norm2d(wn*wn, en)
      abm = rab*hm
      abn = cb*hn
      bbn = acc_dir(fi3, wn, en)                    ! E-DKNMA4-3: book BBN = 0 if WN = 0
      bbm = acc_dir(fi2, wm, em)                    ! E-DKNMA4-3: book BBM = 0 if WM = 0
      ab2k = 2.0_dp*vb2r*abs(wm)
      ab3k = 2.0_dp*vb3r*abs(wn)
      bb2k = dugl3(alb2r, pid2, wm)
      bb3k = dugl3(alb3r, pid2, wn)
      sb = abm + abn + ab2k + ab3k
      call solve2e(cos(alb2r), -cos(alb3r), sin(alb2r), -sin(alb3r), &
                   abn*cos(bbn) + ab3k*cos(bb3k) - abm*cos(bbm) - ab2k*cos(bb2k), &
                   abn*sin(bbn) + ab3k*sin(bb3k) - abm*sin(bbm) - ab2k*sin(bb2k), da, &
                   4.0_dp*uround*(8.0_dp + max(abs(fi2), abs(fi3), abs(fim), abs(fin)))*sb &
                   + (hm + hn)*eb + 2.0_dp*(abs(wm) + abs(wn))*ev, sb, y1, y2, st2, rela)
      ier = st2
      if (failed(ier)) return
      est = max(est, rela)
      ab2r = abs(y1)
      bb2r = dugl4(alb2r, pi, y1)
      ab3r = abs(y2)
      bb3r = dugl4(alb3r, pi, y2)
      abx = abm*cos(bbm) + ab2k*cos(bb2k) + ab2r*cos(bb2r)
      aby = abm*sin(bbm) + ab2k*sin(bb2k) + ab2r*sin(bb2r)
      ab = norm2d(abx, aby)
      bb = dugl5(abx, aby)                          ! E-DKNMA4-2: book DUGL5(VBX, VBY)
    end if
    ier = settle(ier, est, [xb, yb, vb2r, vb3r, vb, ab2k, ab3k, ab2r, ab3r, ab])
  end subroutine dknma4

  ! IV.20 DKNMA5, L2931-3002.  Kind 5 (RPP).  No position part (there is no DPRM5 in the
  ! book).  XA, YA (a point of the guide), RZ3 and ETA3 are accepted and not used, as
  ! printed.  ETA2 = T2 of DSKOR5 (slot direction FIM + ETA2); XR, YR = instantaneous centre
  ! of link M.  VC, ALC = v_CM + v_C2CM (absolute velocity of C2); AC, BC = a_CM + a^k_2M +
  ! a^r_2M.
  ! ERRATA: E-DKNMA5-1 (header VC, AC for VC, ALC), E-DKNMA5-2 (FIRC = DUGL2(RC, PID2, WM)
  ! -- wrong arguments; the direction VM->C as in DSKOR5 L1962), E-DKNMA5-3 (OCR ALMC,
  ! DUGL4(FIM + ETA2), PI..), E-DKNMA5-4 (author: BCM = DUGL3(FIRC, PI - ATAN(EM/WM**2), EM)
  ! lacks ABS, and EM = 0 gives BCM = 0 instead of FIRC + PI; fixed with acc_dir),
  ! E-DSKOR5-2 (solved in the guide's frame), E-DKNMA5-6 (Coriolis difference from the
  ! velocity equation).
  subroutine dknma5(xa, ya, fim, xc, yc, rz3, eta2, eta3, xr, yr, wm, em, vc3, alc3, ac3, bc3, &
                    analog, vc2c3, alc2c3, vc2cm, alc2cm, vc, alc, ac2c3k, bc2c3k, ac2cmk, &
                    bc2cmk, ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac, bc, ier)
    !: XA : real -- A point of the guide axis; accepted and not used, as printed.
    !: YA : real -- A point of the guide axis; accepted and not used, as printed.
    !: FIM : real -- Direction of guide M, rad.
    !: XC : real -- Revolute C of block 3, m.
    !: YC : real -- Revolute C of block 3, m.
    !: RZ3 : real -- Sizes of block 3; accepted and not used, as printed.
    !: ETA2 : real -- Slot direction of link 2 relative to the guide (T2 of ``DSKOR5``),
    !:     rad.
    !: ETA3 : real -- Sizes of block 3; accepted and not used, as printed.
    !: XR : real -- Centre of rotation of link M, m.
    !: YR : real -- Centre of rotation of link M, m.
    !: WM : real -- Angular velocity and acceleration of link M.
    !: EM : real -- Angular velocity and acceleration of link M.
    !: VC3 : real -- Velocity and acceleration of C.
    !: ALC3 : real -- Velocity and acceleration of C.
    !: AC3 : real -- Velocity and acceleration of C.
    !: BC3 : real -- Velocity and acceleration of C.
    !: ANALOG : real = 0.0 -- 1.0: stop after the velocities (the book's way of skipping the
    !:     acceleration work, e.g. for velocity analogues); the acceleration outputs are
    !:     then 0. Anything else: compute the accelerations too.
    real(dp), intent(in) :: xa, ya, fim, xc, yc, rz3, eta2, eta3, xr, yr, wm, em, vc3, alc3
    real(dp), intent(in) :: ac3, bc3, analog
    real(dp), intent(out) :: vc2c3, alc2c3, vc2cm, alc2cm, vc, alc, ac2c3k, bc2c3k, ac2cmk
    real(dp), intent(out) :: bc2cmk, ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac, bc
    integer, intent(out) :: ier
    real(dp) :: rc, vcm, firc, alcm, y1, y2, acm, bcm, a, b, sb, relv, rela, est, sv1, sv2
    real(dp) :: sbv, bv1, bv2
    real(dp) :: z(2), um(2), v_c(2), a_c(2), x_k(2), v_k(2), a_k(2), us(2), sk, sc, svk, svc
    real(dp) :: sak, sac, w(2)
    integer :: st2, level
    vc2c3 = 0.0_dp; alc2c3 = 0.0_dp; vc2cm = 0.0_dp; alc2cm = 0.0_dp; vc = 0.0_dp; alc = 0.0_dp
    ac2c3k = 0.0_dp; bc2c3k = 0.0_dp; ac2cmk = 0.0_dp; bc2cmk = 0.0_dp; ac2c3r = 0.0_dp
    bc2c3r = 0.0_dp; ac2cmr = 0.0_dp; bc2cmr = 0.0_dp; ac = 0.0_dp; bc = 0.0_dp
    if (printed_mode == 0) then                   ! corrected: the kind-5 kernel
      ! link M turns about R (at rest, put at the origin: DPRM4), its guide taken through
      ! R (the relative motion is the same for every line of link M along FIM: XA, YA
      ! unused, as printed); the
      ! kernel's rates along e(FIM), e(FIM + ETA2) are y2 and -y1 of the book's
      ! y1 e(FIM + ETA2) - y2 e(FIM) = v_CM - v_C3, its accelerations the same, the book's
      ! accelerations along ALC2C3, ALC2CM (DUGL4 of the velocities' signs)
      level = 3
      if (analog == 1.0_dp) level = 2
      z = 0.0_dp
      um = [cos(fim), sin(fim)]
      call components(vc3, alc3, v_c(1), v_c(2))
      a_c = 0.0_dp
      if (level == 3) call components(ac3, bc3, a_c(1), a_c(2))
      call rpp_kernel(level, z, z, z, um, wm, em, eta2, cos(eta2), sin(eta2), &
                      [xc - xr, yc - yr], v_c, a_c, x_k, v_k, a_k, us, sk, sc, svk, svc, sak, sac, &
                      ier, est)
      if (failed(ier)) return
      y1 = -svc
      y2 = svk
      vc2c3 = abs(y1)
      alc2c3 = dugl4(fim + eta2, pi, y1)
      vc2cm = abs(y2)
      alc2cm = dugl4(fim, pi, y2)
      w = v_c + y1*us                             ! v_C2 = v_C3 + v_C2C3
      vc = norm2d(w(1), w(2))
      alc = dugl5(w(1), w(2))
      if (level == 3) then
        ac2c3k = 2.0_dp*vc2c3*abs(wm)
        bc2c3k = dugl3(alc2c3, pid2, wm)
        ac2cmk = 2.0_dp*vc2cm*abs(wm)
        bc2cmk = dugl3(alc2cm, pid2, wm)
        ac2c3r = abs(sac)
        bc2c3r = dugl4(alc2c3, pi, -book_sign(1.0_dp, y1)*sac)
        ac2cmr = abs(sak)
        bc2cmr = dugl4(alc2cm, pi, book_sign(1.0_dp, y2)*sak)
        ! a_C2 = a_C3 + a^k_23 + a^r_23, a^k_23 = 2 WM k x v_C2C3
        w = a_c + 2.0_dp*wm*y1*[-us(2), us(1)] - sac*us
        ac = norm2d(w(1), w(2))
        bc = dugl5(w(1), w(2))
      end if
      ier = settle(ier, est, [vc2c3, vc2cm, vc, ac2c3k, ac2cmk, ac2c3r, ac2cmr, ac])
      return
    end if
    rc = norm2d(xc - xr, yc - yr)
    vcm = abs(wm)*rc
    firc = dugl2(xr, yr, xc, yc)                  ! E-DKNMA5-2: book DUGL2(RC, PID2, WM)
    alcm = dugl3(firc, pid2, wm)
    sbv = vcm + abs(vc3)
    ! y1*e(FIM + ETA2) - y2*e(FIM) = v_CM - v_C3, solved in the guide's frame (E-DSKOR5-2:
    ! the book's matrix holds COS(FIM + ETA2), which rounds a small ETA2 against FIM)
    bv1 = vcm*cos(alcm - fim) - vc3*cos(alc3 - fim)
    bv2 = vcm*sin(alcm - fim) - vc3*sin(alc3 - fim)
    call solve_kind5(eta2, bv1, bv2, &
                     4.0_dp*uround*(2.0_dp + abs(fim) + max(abs(alcm), abs(alc3)))*sbv, sbv, &
                     y1, y2, ier, relv)
    if (failed(ier)) return
    est = relv
    sv1 = book_sign(1.0_dp, y1)                   ! ALC2C3 = FIM + ETA2 (+1) or that - pi (-1)
    sv2 = book_sign(1.0_dp, y2)                   ! ALC2CM = FIM (+1) or FIM - pi (-1)
    vc2c3 = abs(y1)
    alc2c3 = dugl4(fim + eta2, pi, y1)
    vc2cm = abs(y2)
    alc2cm = dugl4(fim, pi, y2)
    call dsmvkt(vcm, alcm, vc2cm, alc2cm, vc, alc)
    if (analog /= 1.0_dp) then
      acm = rc*norm2d(wm*wm, em)                   ! = RC*SQRT(WM**4 + EM**2), no overflow
      bcm = acc_dir(firc, wm, em)                   ! E-DKNMA5-4
      ac2c3k = 2.0_dp*vc2c3*abs(wm)
      bc2c3k = dugl3(alc2c3, pid2, wm)
      bc2cmk = dugl3(alc2cm, pid2, wm)
      ac2cmk = 2.0_dp*vc2cm*abs(wm)
      ! E-DKNMA5-6: the two Coriolis terms nearly cancel when the slot is nearly parallel
      ! to the guide (both grow like 1/sin(ETA2)); their difference is taken from the
      ! velocity equation instead, a^k_2M - a^k_23 = -2 WM k x (v_CM - v_C3), whose
      ! components in the guide's frame are (2 WM bv2, -2 WM bv1)
      sb = acm + abs(ac3) + 2.0_dp*abs(wm)*sbv
      call solve_kind5(eta2, &
          acm*cos(bcm - fim) - ac3*cos(bc3 - fim) + 2.0_dp*wm*bv2, &
          acm*sin(bcm - fim) - ac3*sin(bc3 - fim) - 2.0_dp*wm*bv1, &
          4.0_dp*uround*(6.0_dp + abs(fim) + max(abs(bcm), abs(bc3), abs(alcm), abs(alc3)))*sb, &
          sb, y1, y2, st2, rela)
      ier = st2
      if (failed(ier)) return
      est = max(est, rela)
      ! the book's unknowns are along ALC2C3 and ALC2CM, these along FIM + ETA2 and FIM
      ac2c3r = abs(y1)
      bc2c3r = dugl4(alc2c3, pi, sv1*y1)
      ac2cmr = abs(y2)
      bc2cmr = dugl4(alc2cm, pi, sv2*y2)
      call dsmvkt(acm, bcm, ac2cmk, bc2cmk, a, b)
      call dsmvkt(a, b, ac2cmr, bc2cmr, ac, bc)
    end if
    ier = settle(ier, est, [vc2c3, vc2cm, vc, ac2c3k, ac2cmk, ac2c3r, ac2cmr, ac])
  end subroutine dknma5

end module kinematics
