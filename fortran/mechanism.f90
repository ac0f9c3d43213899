! mechanism.f90 -- a whole mechanism solved in one call (issue 19): the book's Assur-group
! method (chapter 4 for the kinematics, chapter 7 for the forces, the student's main program
! of chapter 10 carrying it out call by call) as an interpreter over the mechanism's list of
! groups, run for every position in one loop.
!
! The description (built and checked by python/sarkp/mechanism.py):
!   points 1..np  (joints, rigid points, centres of mass), each position kept as Cartesian x, y;
!   links 0..nl   (0 the frame, 1 the crank), each with its direction's cosine and sine,
!                 computed once per position from the points that define it;
!   steps gi(:, k), gr(:, k), k = 1..ns, in order (gi(1, k) = the kind):
!     0 crank   gi = 0, A, O, 1                       gr = r
!     1 RRR     gi = 1, B, A, C, L2, L3, 0, 0         gr = l2, l3, branch, 1/l2, 1/l3
!     2 RRP     gi = 2, B, A, K, L2, L3, LM           gr = l2, branch, cos, sin (guide angle
!               on LM), offset, angle, 1/l2
!     3 RPR     gi = 3, B, A, C, L2, L3               gr = h, branch
!     4 PRP     gi = 4, B, A, C, L2, L3, LM, LN       gr = cos, sin (guide M), cos, sin (guide
!               N), offset M, offset N
!     5 RPP     gi = 5, K, A, C, L2, L3, LM           gr = cos, sin (guide M), cos, sin (slot T2)
!     6 point   gi = 6, D, P, Q, L                    gr = dist, cos, sin of the angle from P->Q
!               (Q = P: from the link's own direction)
!   Branch +1: the new joint on the left of A->C (kinds 1, 3), ahead along the guide of the
!   foot of the perpendicular from A (kind 2); kinds 4, 5 have one position.
!
! Kinematics in position analogues: the crank turns at d(phi)/dt = 1, so each point carries
! x, x' = dx/dphi, x'' = d2x/dphi2 and each link theta, w' , e''; the velocities asked for
! are x' omega and the accelerations x'' omega**2 + x' epsilon (the same for the links).
! Each group's velocities and accelerations are one 2x2 system with one matrix, GELG's
! elimination done once (numerics' factor2, solve2f: the kernel and error estimate of
! DKNMA1), positions by numerics' tri_apex / apex_vectors (kind 1), solve2e (kinds 4, 5).
! The dead-centre policy of kinematics.f90 decides each position's status (policy): the
! estimate is the largest over the groups.
!
! Forces (need = 4), in reverse order of the groups (chapter 7): each link's load is gathered
! as a force and a moment about its first point (gravity, inertia -m a_S and -J_S eps,
! external forces, torques, springs, and the reactions of the groups already solved); each
! group's six equilibrium equations (forces and moment of its two links) give its three
! pairs' reactions: a revolute (fx, fy), a slider (the normal force and the couple).  The
! crank's moment about O gives the balancing moment.  J_red = sum (m v_S'**2 + J w'**2),
! M_red = sum (F . v' + M w') over the external loads (no inertia).
module mechanism
  use prmtr, only: dp, st_ok, st_assembly, st_singular, st_range, st_missing, st_digits, &
                   norm2d
  use numerics, only: uround, bound2, solve_kind5, solve2e, tri_apex, apex_vectors, &
                      unscale, angle_sensitivity, policy, failed
  use groups, only: kind_pairs, group_reactions
  implicit none
  private
  public :: mech_solve, mech_solve_many

  ! A 2x2 system for Cramer's rule: its entries, 1/det, and for the error estimate the
  ! scales s1, s2 of its columns (the lengths the columns are unit vectors times), so that
  ! the estimate is that of the unit-free system and the same in any length unit.
  type :: cram
    real(dp) :: a11, a12, a21, a22, rdet, na, nadet, s1, s2
    integer :: st, e
  end type cram

contains

  ! One call for all positions.  need: 1 positions, 2 velocities, 3 accelerations, 4 forces.
  ! Outputs whose level is not asked for are not touched (the caller passes 1-long arrays).
  ! status(i): the worst of the groups (prmtr codes, 100 + d = d digits left), fgroup(i) the
  ! first step that failed or lost digits (0: none).
  subroutine mech_solve(need, n, np, nl, ns, gi, gr, phi, omega, epsil, inc_w, inc_e, &
                        nm, mlink, mpoint, mval, gravity, &
                        nf, fpoint, flink, nfv, fval, nt, tlink, ntv, tval, &
                        nsp, spp, spl, nspv, spv, npair, powner, lbase, x0, nop, outp, nol, &
                        outl, nv, na, nr, pos, vel, acc, th, om, ep, react, mbal, jred, mred, &
                        status, fgroup)
    !f2py threadsafe
    integer, intent(in) :: need, n, np, nl, ns, nm, nf, nfv, nt, ntv, nsp, nspv, npair
    integer, intent(in) :: nv, na, nr
    integer, intent(in) :: inc_w, inc_e, nop, nol, outp(nop), outl(nol)
    integer, intent(in) :: gi(8, ns)
    real(dp), intent(in) :: gr(8, ns), phi(n), omega(*), epsil(*)
    integer, intent(in) :: powner(np), lbase(0:nl)
    real(dp), intent(in) :: x0(2, np)
    integer, intent(in) :: mlink(nm), mpoint(nm)
    real(dp), intent(in) :: mval(2, nm), gravity
    integer, intent(in) :: fpoint(nf), flink(nf)
    real(dp), intent(in) :: fval(2, nf, nfv)
    integer, intent(in) :: tlink(nt)
    real(dp), intent(in) :: tval(nt, ntv)
    integer, intent(in) :: spp(2, nsp), spl(2, nsp)
    real(dp), intent(in) :: spv(2, nsp, nspv)
    real(dp), intent(inout) :: pos(2, nop, n), vel(2, nop, nv), acc(2, nop, na)
    real(dp), intent(inout) :: th(2, nol, n), om(nol, nv), ep(nol, na)
    real(dp), intent(inout) :: react(3, npair, nr), mbal(nr), jred(nv), mred(nr)
    integer, intent(inout) :: status(n), fgroup(n)
    ! work arrays of one position (allocated once per call, none per group)
    real(dp), allocatable :: x(:, :), v(:, :), a(:, :), c(:), s(:), w(:), e(:)
    real(dp), allocatable :: fl(:, :), ml(:), aa(:, :), ee(:)
    integer, allocatable :: gslot(:)
    integer :: i, k, kind, st, worst, jf, jt, js, fg, g, p, l
    real(dp) :: est, maxest, wi, ei, w2, px, py
    logical :: masses

    allocate(x(2, np), v(2, np), a(2, np), c(0:nl), s(0:nl), w(0:nl), e(0:nl))
    allocate(fl(2, 0:nl), ml(0:nl), aa(2, np), ee(0:nl))
    x = x0; v = 0.0_dp; a = 0.0_dp
    c = 1.0_dp; s = 0.0_dp; w = 0.0_dp; e = 0.0_dp
    ! the reaction slots of the groups: 1 the crank's O, then three per group in order
    allocate(gslot(ns))
    g = 0
    do k = 1, ns
      gslot(k) = 0
      if (gi(1, k) >= 1 .and. gi(1, k) <= 5) then
        gslot(k) = 2 + 3*g
        g = g + 1
      end if
    end do
    ! no masses (the caller's one neutral entry of zero mass and inertia): J_red = 0
    masses = any(mval /= 0.0_dp)
    wi = 0.0_dp
    do i = 1, n
      worst = st_ok
      fg = 0
      maxest = 0.0_dp
      do k = 1, ns
        kind = gi(1, k)
        call step(k, kind, i, st, est)
        if (failed(st)) then
          ! a result out of range once no digit is left (a group at a dead centre: its
          ! velocities, finite but huge, squared in its accelerations) is that dead
          ! centre, not an overflow (an estimate of exactly huge is a failed solve's
          ! placeholder, not an estimate)
          if (st == st_range .and. ((.not. maxest <= 0.1_dp .and. maxest /= huge(est)) &
              .or. (.not. est <= 0.1_dp .and. est /= huge(est)))) st = st_singular
          worst = st
          fg = k
          exit
        end if
        if (est > maxest .or. .not. est <= huge(est)) then
          maxest = est
          fg = k
        end if
      end do
      if (.not. failed(worst)) then
        worst = policy(maxest)
        if (worst == st_ok) fg = 0
      end if
      if (failed(worst)) then
        status(i) = worst
        fgroup(i) = fg
        cycle
      end if
      ! the outputs: the moving points and links only (the caller knows the frame's), one
      ! scalar statement a number (cheaper than the little array sections); a position
      ! found out of range here is overwritten with NaN by the caller
      do k = 1, nop
        p = outp(k)
        px = x(1, p)
        py = x(2, p)
        pos(1, k, i) = px
        pos(2, k, i) = py
        if (.not. (abs(px) <= huge(px) .and. abs(py) <= huge(py))) then
          worst = st_range
          fg = 0
        end if
      end do
      ! status and fgroup come in zeroed (solve): a position that is fine is not written,
      ! which spares the kernel clearing their pages
      if (worst /= st_ok .or. fg /= 0) then
        status(i) = worst
        fgroup(i) = fg
        if (worst == st_range) cycle
      end if
      do k = 1, nol
        l = outl(k)
        th(1, k, i) = c(l)
        th(2, k, i) = s(l)
      end do
      if (need >= 2) then
        wi = omega(1 + (i - 1)*inc_w)
        ! velocities and accelerations (and the loads they make) within the range of
        ! doubles: else the position is st_range (the caller raises RangeError)
        if (.not. in_range(wi, epsil(1 + (i - 1)*inc_e))) then
          status(i) = st_range
          fgroup(i) = 0
          cycle
        end if
        do k = 1, nop
          p = outp(k)
          vel(1, k, i) = v(1, p)*wi
          vel(2, k, i) = v(2, p)*wi
        end do
        do k = 1, nol
          om(k, i) = w(outl(k))*wi
        end do
        jred(i) = 0.0_dp
        if (masses) jred(i) = reduced_inertia()
      end if
      if (need >= 3) then
        ei = epsil(1 + (i - 1)*inc_e)
        w2 = wi*wi
        if (need >= 4) then
          ! every point's and link's acceleration, for the inertia loads (explicit loops:
          ! the whole-array form cost gfortran a temporary)
          do p = 1, np
            aa(1, p) = a(1, p)*w2 + v(1, p)*ei
            aa(2, p) = a(2, p)*w2 + v(2, p)*ei
          end do
          do l = 0, nl
            ee(l) = e(l)*w2 + w(l)*ei
          end do
        end if
        do k = 1, nop
          p = outp(k)
          acc(1, k, i) = a(1, p)*w2 + v(1, p)*ei
          acc(2, k, i) = a(2, p)*w2 + v(2, p)*ei
        end do
        do k = 1, nol
          l = outl(k)
          ep(k, i) = e(l)*w2 + w(l)*ei
        end do
      end if
      if (need >= 4) call forces(i)
    end do
    deallocate(x, v, a, c, s, w, e, fl, ml, aa, ee, gslot)

  contains

    ! ------------------------------------------------------------------ kinematics

    ! Whether the velocities x' omega and accelerations x'' omega**2 + x' epsilon of
    ! every point and link stay below huge/16 (room for the sums of the force step)
    logical function in_range(wi, ei)
      real(dp), intent(in) :: wi, ei
      real(dp) :: vm, am, lim
      lim = huge(1.0_dp)/16.0_dp
      vm = max(maxval(abs(v)), maxval(abs(w)))
      in_range = abs(wi)*vm <= lim
      if (need < 3 .or. .not. in_range) return
      am = max(maxval(abs(a)), maxval(abs(e)))
      in_range = wi*wi <= lim .and. (wi*wi)*am <= lim .and. abs(ei)*vm <= lim .and. &
                 (wi*wi)*am + abs(ei)*vm <= lim
    end function in_range

    ! A link's direction (cosine cl, sine sl): the angle itself is not computed here (the
    ! Python layer takes it, continuous along the sweep, only for the links asked for)
    subroutine set_link(l, cl, sl)
      integer, intent(in) :: l
      real(dp), intent(in) :: cl, sl
      c(l) = cl
      s(l) = sl
    end subroutine set_link

    ! velocity analogue of a point X moving with link l, whose point p is known:
    ! v'_p + w'_l k x (X - p); acceleration analogue a''_p + e''_l k x (X - p) - w'^2 (X - p)
    pure subroutine carried(l, p, xx, vx, ax)
      integer, intent(in) :: l, p
      real(dp), intent(in) :: xx(2)
      real(dp), intent(out) :: vx(2), ax(2)
      real(dp) :: r(2)
      r = xx - x(:, p)
      if (l == 0) then
        vx = 0.0_dp
        ax = 0.0_dp
        return
      end if
      vx = v(:, p) + w(l)*[-r(2), r(1)]
      ax = a(:, p) + e(l)*[-r(2), r(1)] - w(l)**2*r
    end subroutine carried

    subroutine step(k, kind, i, st, est)
      integer, intent(in) :: k, kind, i
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      select case (kind)
      case (0)
        call crank(k, i, st, est)
      case (1)
        call rrr(k, st, est)
      case (2)
        call rrp(k, st, est)
      case (3)
        call rpr(k, st, est)
      case (4)
        call prp(k, st, est)
      case (5)
        call rpp(k, st, est)
      case (6)
        call rigid(k, st, est)
      case default
        st = st_missing                     ! an unknown kind: an error, never skipped
        est = 0.0_dp
      end select
    end subroutine step

    subroutine crank(k, i, st, est)
      integer, intent(in) :: k, i
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pa, po
      real(dp) :: r, cp, sp
      pa = gi(2, k); po = gi(3, k)
      r = gr(1, k)
      cp = cos(phi(i))
      sp = sin(phi(i))
      x(:, pa) = x(:, po) + r*[cp, sp]
      c(1) = cp; s(1) = sp
      w(1) = 1.0_dp
      e(1) = 0.0_dp
      v(:, pa) = r*[-sp, cp]
      a(:, pa) = -r*[cp, sp]
      st = st_ok
      est = 0.0_dp
    end subroutine crank

    ! kind 1 (RRR, DPRM1/DKNMA1): B at l2 from A, l3 from C
    subroutine rrr(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pb, pa, pc, l2, l3, ex
      real(dp) :: dx, dy, d, pr, h, pq, dang, r2(2), r3(2), len2, len3, y1, y2, rel, sb, sx, ev
      type(cram) :: f
      pb = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      len2 = gr(1, k); len3 = gr(2, k)
      dx = x(1, pc) - x(1, pa)
      dy = x(2, pc) - x(2, pa)
      d = norm2d(dx, dy)
      est = 0.0_dp
      if (d == 0.0_dp) then
        st = st_singular
        if (len2 /= len3) st = st_assembly
        return
      end if
      call tri_apex(d, len2, len3, pr, h, pq, ex, dang, st)
      if (failed(st)) return
      call apex_vectors(dx, dy, d, pr, h, pq, gr(3, k), r2(1), r2(2), r3(1), r3(2))
      r2 = [unscale(r2(1), ex), unscale(r2(2), ex)]
      r3 = [unscale(r3(1), ex), unscale(r3(2), ex)]
      x(:, pb) = x(:, pa) + r2
      call set_link(l2, r2(1)*gr(4, k), r2(2)*gr(4, k))      ! gr(4:5) = 1/l2, 1/l3
      call set_link(l3, r3(1)*gr(5, k), r3(2)*gr(5, k))
      ! d carries the rounding of the coordinates it is the difference of (far from the
      ! origin more than that of d itself, which dang allows for): the angles move by
      ! 2u (sx d + l2**2 + l3**2)/(d h) instead of 2u (d**2 + l2**2 + l3**2)/(d h)
      sx = abs(x(1, pa)) + abs(x(2, pa)) + abs(x(1, pc)) + abs(x(2, pc))
      if (sx > d) dang = dang*((sx/d)*(d/len2)*(d/len3) + len2/len3 + len3/len2)/ &
                             ((d/len2)*(d/len3) + len2/len3 + len3/len2)
      est = dang
      if (need < 2) return
      ! v_A + w2 k x r2 = v_C + w3 k x r3 (columns: unit vectors times l2, l3)
      call cramer_set(-r2(2), r3(2), r2(1), -r3(1), f, len2, len3)
      sb = abs(v(1, pa)) + abs(v(2, pa)) + abs(v(1, pc)) + abs(v(2, pc))
      call cramer(f, v(1, pc) - v(1, pa), v(2, pc) - v(2, pa), dang, 4.0_dp*uround*sb, sb, &
                   y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      w(l2) = y1
      w(l3) = y2
      v(:, pb) = v(:, pa) + y1*[-r2(2), r2(1)]
      if (need < 3) return
      ! the velocities' error (absolute, in w' l units) enters through w'**2 l
      ev = abs_err(f, y1, y2, sb, rel)
      call cramer(f, a(1, pc) - a(1, pa) - y2**2*r3(1) + y1**2*r2(1), &
                   a(2, pc) - a(2, pa) - y2**2*r3(2) + y1**2*r2(2), dang, &
                   4.0_dp*uround*(sb + y1**2*len2 + y2**2*len3) &
                   + ev*(2.0_dp*abs(y1) + ev/len2) + ev*(2.0_dp*abs(y2) + ev/len3), &
                   sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      e(l2) = y1
      e(l3) = y2
      a(:, pb) = a(:, pa) + y1*[-r2(2), r2(1)] - w(l2)**2*r2
    end subroutine rrr

    ! the guide of kind 2, 4, 5: through point p of link l, direction (cg, sg) turned by
    ! the link's direction: unit vector u
    pure function guide(l, cg, sg) result(u)
      integer, intent(in) :: l
      real(dp), intent(in) :: cg, sg
      real(dp) :: u(2)
      u = [c(l)*cg - s(l)*sg, s(l)*cg + c(l)*sg]
    end function guide

    ! kind 2 (RRP, DPRM2/DKNMA2): B on the guide through K (link LM), rod A-B of length l2
    subroutine rrp(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pb, pa, pk, l2, l3, lm
      real(dp) :: u(2), nn(2), wv(2), along, perp, off, len2, cq, root, sl, r2(2), dc, sq
      real(dp) :: vg(2), ag(2), y1, y2, rel, sb, ev
      type(cram) :: f
      pb = gi(2, k); pa = gi(3, k); pk = gi(4, k); l2 = gi(5, k); l3 = gi(6, k); lm = gi(7, k)
      len2 = gr(1, k); off = gr(5, k)
      u = guide(lm, gr(3, k), gr(4, k))
      nn = [-u(2), u(1)]
      wv = x(:, pa) - x(:, pk)
      along = wv(1)*u(1) + wv(2)*u(2)
      perp = wv(1)*nn(1) + wv(2)*nn(2) - off
      cq = perp/len2
      est = 0.0_dp
      if (abs(cq) > 1.0_dp) then
        if (abs(cq) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          st = st_assembly
          return
        end if
        cq = sign(1.0_dp, cq)
      end if
      sq = sqrt((1.0_dp - cq)*(1.0_dp + cq))
      root = len2*sq
      sl = along + gr(2, k)*root
      x(:, pb) = x(:, pk) + sl*u + off*nn
      r2 = x(:, pb) - x(:, pa)
      call set_link(l2, r2(1)*gr(7, k), r2(2)*gr(7, k))      ! gr(7) = 1/l2
      call set_link(l3, u(1), u(2))
      dc = 4.0_dp*uround*(abs(perp) + abs(off) + len2 + abs(wv(1)) + abs(wv(2)))/len2
      ! numerics' angle_sensitivity(cq, dc) = min(dc/sq, sqrt(2 dc)), its square root sq
      ! shared with the position's, sqrt(2 dc) taken only when it may be the smaller
      ! (est**2 < 2 dc (1 - 8u) assures est < the rounded sqrt(2 dc)): the same bits
      if (sq > 0.0_dp) then
        est = dc/sq
        if (.not. est*est < 2.0_dp*dc*(1.0_dp - 8.0_dp*uround)) est = min(dc/sq, sqrt(2.0_dp*dc))
      else
        est = sqrt(2.0_dp*dc)
      end if
      st = st_ok
      if (need < 2) return
      ! v_A + w2 k x r2 = v_G(B) + s' u
      call carried(lm, pk, x(:, pb), vg, ag)
      call cramer_set(-r2(2), -u(1), r2(1), -u(2), f, len2, 1.0_dp)
      sb = abs(v(1, pa)) + abs(v(2, pa)) + abs(vg(1)) + abs(vg(2))
      call cramer(f, vg(1) - v(1, pa), vg(2) - v(2, pa), est + 4.0_dp*uround, &
                   4.0_dp*uround*sb, sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      w(l2) = y1
      w(l3) = w(lm)
      v(:, pb) = v(:, pa) + y1*[-r2(2), r2(1)]
      if (need < 3) return
      ev = abs_err(f, y1, y2, sb, rel)
      ag = ag + 2.0_dp*w(lm)*y2*nn - a(:, pa) + y1**2*r2
      call cramer(f, ag(1), ag(2), est + 4.0_dp*uround, &
                   4.0_dp*uround*(sb + y1**2*len2) + ev*(2.0_dp*abs(y1) + ev/len2) &
                   + 2.0_dp*abs(w(lm))*ev, sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      e(l2) = y1
      e(l3) = e(lm)
      a(:, pb) = a(:, pa) + y1*[-r2(2), r2(1)] - w(l2)**2*r2
    end subroutine rrp

    ! kind 3 (RPR, DPRM3/DKNMA3): slider 2 pivoted at A slides along link 3 through C, A at
    ! h from its axis; B = the foot of the perpendicular from A on the axis
    subroutine rpr(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pb, pa, pc, l2, l3
      real(dp) :: dx, dy, d, h, sq, cq, u(2), nn(2), fb(2), e3(2), n3(2), sl, ds
      real(dp) :: rac(2), y1, y2, rel, sb, sd, ev
      type(cram) :: f
      pb = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      h = abs(gr(1, k))
      dx = x(1, pc) - x(1, pa)
      dy = x(2, pc) - x(2, pa)
      d = norm2d(dx, dy)
      est = 0.0_dp
      if (d == 0.0_dp) then
        st = st_singular
        return
      end if
      sq = h/d
      if (sq > 1.0_dp) then
        if (sq - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
          st = st_assembly
          return
        end if
        sq = 1.0_dp
      end if
      cq = sqrt((1.0_dp - sq)*(1.0_dp + sq))
      u = [dx, dy]/d
      nn = [-u(2), u(1)]
      fb = (h*sq)*u + (gr(2, k)*h*cq)*nn          ! B - A (Thales: on the circle over AC)
      x(:, pb) = x(:, pa) + fb
      sl = d*cq                                    ! |B - C|
      if (sl == 0.0_dp) then
        st = st_singular
        return
      end if
      e3 = (x(:, pb) - x(:, pc))/sl
      n3 = [-e3(2), e3(1)]
      call set_link(l3, e3(1), e3(2))
      call set_link(l2, e3(1), e3(2))
      ds = 4.0_dp*uround*(1.0_dp + sq)
      est = angle_sensitivity(sq, ds)
      st = st_ok
      if (need < 2) return
      ! v_A = v_C + w3 k x (A - C) + s' e3
      rac = x(:, pa) - x(:, pc)
      call cramer_set(-rac(2), e3(1), rac(1), e3(2), f, d, 1.0_dp)
      sb = abs(v(1, pa)) + abs(v(2, pa)) + abs(v(1, pc)) + abs(v(2, pc))
      call cramer(f, v(1, pa) - v(1, pc), v(2, pa) - v(2, pc), est + 4.0_dp*uround, &
                   4.0_dp*uround*sb, sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      w(l3) = y1
      w(l2) = y1
      sd = y2
      v(:, pb) = v(:, pc) + y1*sl*n3 + sd*e3
      if (need < 3) return
      ev = abs_err(f, y1, sd, sb, rel)
      call cramer(f, a(1, pa) - a(1, pc) + y1**2*rac(1) - 2.0_dp*y1*sd*n3(1), &
                   a(2, pa) - a(2, pc) + y1**2*rac(2) - 2.0_dp*y1*sd*n3(2), &
                   est + 4.0_dp*uround, 4.0_dp*uround*(sb + y1**2*d + abs(y1*sd)) &
                   + ev*(2.0_dp*abs(y1) + ev/d) + 2.0_dp*(abs(y1)*ev + abs(sd)*ev/d), sb, &
                   y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      e(l3) = y1
      e(l2) = y1
      a(:, pb) = a(:, pc) + y1*sl*n3 - w(l3)**2*sl*e3 + y2*e3 + 2.0_dp*w(l3)*sd*n3
    end subroutine rpr

    ! kind 4 (PRP, DPRM4/DKNMA4): B at the offsets from the guides through A (link LM) and
    ! C (link LN)
    subroutine prp(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pb, pa, pc, l2, l3, lm, ln
      real(dp) :: um(2), un(2), nm_(2), nn(2), dca(2), bx, by, sb, rel
      real(dp) :: vgm(2), agm(2), vgn(2), agn(2), y1, y2, s2, s3, ev
      type(cram) :: f
      pb = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      lm = gi(7, k); ln = gi(8, k)
      um = guide(lm, gr(1, k), gr(2, k))
      un = guide(ln, gr(3, k), gr(4, k))
      nm_ = [-um(2), um(1)]
      nn = [-un(2), un(1)]
      dca = x(:, pc) - x(:, pa)
      ! nM . (B - A) = offM,  nN . (B - A) = offN + nN . (C - A)
      sb = abs(gr(5, k)) + abs(gr(6, k)) + abs(dca(1)) + abs(dca(2))
      call solve2e(nm_(1), nm_(2), nn(1), nn(2), gr(5, k), gr(6, k) + nn(1)*dca(1) + nn(2)*dca(2), &
                   4.0_dp*uround, 4.0_dp*uround*sb, sb, bx, by, st, est)
      if (failed(st)) return
      x(:, pb) = x(:, pa) + [bx, by]
      call set_link(l2, um(1), um(2))
      call set_link(l3, un(1), un(2))
      if (need < 2) return
      call carried(lm, pa, x(:, pb), vgm, agm)
      call carried(ln, pc, x(:, pb), vgn, agn)
      call cramer_set(um(1), -un(1), um(2), -un(2), f, 1.0_dp, 1.0_dp)
      sb = abs(vgm(1)) + abs(vgm(2)) + abs(vgn(1)) + abs(vgn(2))
      call cramer(f, vgn(1) - vgm(1), vgn(2) - vgm(2), est + 4.0_dp*uround, &
                   4.0_dp*uround*sb, sb, s2, s3, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      w(l2) = w(lm)
      w(l3) = w(ln)
      v(:, pb) = vgm + s2*um
      if (need < 3) return
      ev = abs_err(f, s2, s3, sb, rel)
      call cramer(f, agn(1) + 2.0_dp*w(ln)*s3*nn(1) - agm(1) - 2.0_dp*w(lm)*s2*nm_(1), &
                   agn(2) + 2.0_dp*w(ln)*s3*nn(2) - agm(2) - 2.0_dp*w(lm)*s2*nm_(2), &
                   est + 4.0_dp*uround, 4.0_dp*uround*(sb + abs(w(ln)*s3) + abs(w(lm)*s2)) &
                   + 2.0_dp*(abs(w(ln)) + abs(w(lm)))*ev, sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel)
      e(l2) = e(lm)
      e(l3) = e(ln)
      a(:, pb) = agm + y1*um + 2.0_dp*w(lm)*s2*nm_
    end subroutine prp

    ! kind 5 (RPP, DPRM5/DKNMA5): link 2 slides on the guide through A (link LM), block 3
    ! pivoted at C slides in link 2 along the guide's direction + T2; K = where the slot
    ! axis meets the guide axis
    subroutine rpp(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pk, pa, pc, l2, l3, lm
      real(dp) :: um(2), us(2), nm_(2), ns_(2), dca(2), s2, s3, sb, rel, t2
      real(dp) :: vgc(2), agc(2), vgk(2), agk(2), y1, y2, d2, d3, ev
      pk = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k); lm = gi(7, k)
      t2 = gr(6, k)
      um = guide(lm, gr(1, k), gr(2, k))
      us = [um(1)*gr(3, k) - um(2)*gr(4, k), um(2)*gr(3, k) + um(1)*gr(4, k)]
      nm_ = [-um(2), um(1)]
      ns_ = [-us(2), us(1)]
      dca = x(:, pc) - x(:, pa)
      sb = abs(dca(1)) + abs(dca(2))
      ! s2 um + s3 us = C - A, solved in the frame of the guide (DPRM5's solve_kind5: a
      ! small T2 keeps its digits)
      call kind5(t2, um, nm_, dca, 4.0_dp*uround*sb, sb, s2, s3, st, est)
      if (failed(st)) return
      x(:, pk) = x(:, pa) + s2*um
      call set_link(l2, um(1), um(2))
      call set_link(l3, us(1), us(2))
      if (need < 2) return
      call carried(lm, pa, x(:, pc), vgc, agc)
      call carried(lm, pa, x(:, pk), vgk, agk)
      sb = abs(v(1, pc)) + abs(v(2, pc)) + abs(vgc(1)) + abs(vgc(2))
      call kind5(t2, um, nm_, v(:, pc) - vgc, 4.0_dp*uround*sb, sb, d2, d3, st, rel)
      if (failed(st)) return
      rel = rel + est                       ! the position's error moves the system
      est = max(est, rel)
      w(l2) = w(lm)
      w(l3) = w(lm)
      v(:, pk) = vgk + d2*um
      if (need < 3) return
      ev = rel*max(norm2d(d2, d3), sb)
      call kind5(t2, um, nm_, a(:, pc) - agc - 2.0_dp*w(lm)*(d2*nm_ + d3*ns_), &
                 4.0_dp*uround*(sb + abs(w(lm))*(abs(d2) + abs(d3))) + 4.0_dp*abs(w(lm))*ev, &
                 sb, y1, y2, st, rel)
      if (failed(st)) return
      est = max(est, rel + est)
      e(l2) = e(lm)
      e(l3) = e(lm)
      a(:, pk) = agk + y1*um + 2.0_dp*w(lm)*d2*nm_
    end subroutine rpp

    ! ym um + ys us = bb (us = um turned by t2) through numerics' solve_kind5, which solves
    ! y1 e(FIM+T2) - y2 e(FIM) = b in the guide's frame: ys = y1, ym = -y2
    subroutine kind5(t2, um, nm_, bb, db, sbb, ym, ys, st5, rel5)
      real(dp), intent(in) :: t2, um(2), nm_(2), bb(2), db, sbb
      real(dp), intent(out) :: ym, ys, rel5
      integer, intent(out) :: st5
      real(dp) :: z1, z2
      call solve_kind5(t2, bb(1)*um(1) + bb(2)*um(2), bb(1)*nm_(1) + bb(2)*nm_(2), db, &
                       sbb, z1, z2, st5, rel5)
      ys = z1
      ym = -z2
    end subroutine kind5

    ! a point rigidly on link L: D = P + dist * (the direction P->Q turned by the angle)
    subroutine rigid(k, st, est)
      integer, intent(in) :: k
      integer, intent(out) :: st
      real(dp), intent(out) :: est
      integer :: pd, pp, pq, l
      real(dp) :: dq(2), dn, u(2), vx(2), ax(2)
      pd = gi(2, k); pp = gi(3, k); pq = gi(4, k); l = gi(5, k)
      est = 0.0_dp
      st = st_ok
      if (pq == pp) then
        u = [c(l), s(l)]                           ! along the link's own direction
      else
        dq = x(:, pq) - x(:, pp)
        dn = norm2d(dq(1), dq(2))
        if (dn == 0.0_dp) then
          st = st_singular
          return
        end if
        u = dq/dn
      end if
      x(:, pd) = x(:, pp) + gr(1, k)*[u(1)*gr(2, k) - u(2)*gr(3, k), u(2)*gr(2, k) + u(1)*gr(3, k)]
      if (need < 2) return
      call carried(l, pp, x(:, pd), vx, ax)
      v(:, pd) = vx
      a(:, pd) = ax
    end subroutine rigid

    ! ------------------------------------------------------------------ dynamics

    real(dp) function reduced_inertia()
      integer :: j, p, l
      reduced_inertia = 0.0_dp
      do j = 1, nm
        p = mpoint(j); l = mlink(j)
        reduced_inertia = reduced_inertia + mval(1, j)*(v(1, p)**2 + v(2, p)**2) &
                          + mval(2, j)*w(l)**2
      end do
    end function reduced_inertia

    ! load f at point p on link l: into the link's resultant and moment about its first point
    subroutine load(l, p, fx, fy)
      integer, intent(in) :: l, p
      real(dp), intent(in) :: fx, fy
      integer :: b
      b = base(l)
      fl(1, l) = fl(1, l) + fx
      fl(2, l) = fl(2, l) + fy
      ml(l) = ml(l) + (x(1, p) - x(1, b))*fy - (x(2, p) - x(2, b))*fx
    end subroutine load

    subroutine forces(i)
      integer, intent(in) :: i
      integer :: j, p, l, q, k
      real(dp) :: fx, fy, mr, dl(2), dn, ff
      logical :: ok
      fl = 0.0_dp
      ml = 0.0_dp
      mr = 0.0_dp
      do j = 1, nm
        p = mpoint(j); l = mlink(j)
        fx = -mval(1, j)*aa(1, p)
        fy = -mval(1, j)*(aa(2, p) + gravity)
        call load(l, p, fx, fy)
        ml(l) = ml(l) - mval(2, j)*ee(l)
        mr = mr - mval(1, j)*gravity*v(2, p)
      end do
      jf = 1 + (i - 1)*min(nfv - 1, 1)
      do j = 1, nf
        p = fpoint(j); l = flink(j)
        call load(l, p, fval(1, j, jf), fval(2, j, jf))
        mr = mr + fval(1, j, jf)*v(1, p) + fval(2, j, jf)*v(2, p)
      end do
      jt = 1 + (i - 1)*min(ntv - 1, 1)
      do j = 1, nt
        l = tlink(j)
        ml(l) = ml(l) + tval(j, jt)
        mr = mr + tval(j, jt)*w(l)
      end do
      js = 1 + (i - 1)*min(nspv - 1, 1)
      do j = 1, nsp
        p = spp(1, j); q = spp(2, j)
        dl = x(:, q) - x(:, p)
        dn = norm2d(dl(1), dl(2))
        if (dn == 0.0_dp) cycle
        ff = spv(1, j, js)*(dn - spv(2, j, js))   ! tension > 0 pulls P towards Q
        dl = dl/dn
        call load(spl(1, j), p, ff*dl(1), ff*dl(2))
        call load(spl(2, j), q, -ff*dl(1), -ff*dl(2))
        mr = mr + ff*(dl(1)*(v(1, p) - v(1, q)) + dl(2)*(v(2, p) - v(2, q)))
      end do
      mred(i) = mr
      ! the groups in reverse order (chapter 7)
      do k = ns, 1, -1
        if (gslot(k) > 0) call group_forces(k, gi(1, k), gslot(k), i)
      end do
      ! the crank (link 1), its loads gathered about O: M_b + M_1 = 0, the frame's
      ! reaction on it -F_1
      react(:, 1, i) = [-fl(1, 1), -fl(2, 1), 0.0_dp]
      mbal(i) = -ml(1)
      ! every force and moment a finite double, else the position is st_range
      ok = abs(mbal(i)) <= huge(1.0_dp) .and. abs(mred(i)) <= huge(1.0_dp)
      do k = 1, npair
        do j = 1, 3
          ok = ok .and. abs(react(j, k, i)) <= huge(1.0_dp)
        end do
      end do
      if (.not. ok) then
        status(i) = st_range
        fgroup(i) = 0
      end if
    end subroutine forces

    integer function base(l)
      integer, intent(in) :: l
      base = lbase(l)
    end function base

    integer function owner(p)
      integer, intent(in) :: p
      owner = powner(p)
    end function owner

    ! One group's reactions: its pairs' points, types and sliding directions and its two
    ! links' loads (gathered about their first points) gathered for groups'
    ! group_reactions (the chapter 7 kernel of every kind); the reactions scattered into
    ! react and, opposite, onto the outside links.
    subroutine group_forces(k, kind, slot, i)
      integer, intent(in) :: k, kind, slot, i
      integer :: pt(3), ty(3), frl(3), l2, l3, j, st
      real(dp) :: dir(2, 3), pp(2, 3), out(3, 3)
      l2 = gi(5, k); l3 = gi(6, k)
      call pairs(k, kind, pt, ty, dir, frl)
      do j = 1, 3
        pp(:, j) = x(:, pt(j))
      end do
      call group_reactions(pp, ty, dir, fl(:, l2), ml(l2), x(:, base(l2)), fl(:, l3), &
                           ml(l3), x(:, base(l3)), out, st)
      if (st /= st_ok) then
        status(i) = st
        fgroup(i) = k
      end if
      do j = 1, 3
        react(:, slot + j - 1, i) = out(:, j)
        if (j /= 2 .and. frl(j) > 0) then
          call load(frl(j), pt(j), -out(1, j), -out(2, j))   ! the outside bears the opposite
          ml(frl(j)) = ml(frl(j)) - out(3, j)
        end if
      end do
    end subroutine group_forces

    ! The pairs of a group, in group_reactions' order: their points, types (the kind's
    ! declaration, groups' kind_pairs) and sliding directions, and the outside links of
    ! pairs 1 and 3 (0: the frame)
    subroutine pairs(k, kind, pt, ty, dir, frl)
      integer, intent(in) :: k, kind
      integer, intent(out) :: pt(3), ty(3), frl(3)
      real(dp), intent(out) :: dir(2, 3)
      integer :: pb, pa, pc, l2, l3
      pb = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      dir = 0.0_dp
      ty = kind_pairs(:, kind)
      frl = 0
      select case (kind)
      case (1)
        pt = [pa, pb, pc]
        frl(1) = owner(pa); frl(3) = owner(pc)
      case (2)
        pt = [pa, pb, pb]
        dir(:, 3) = [c(l3), s(l3)]
        frl(1) = owner(pa); frl(3) = gi(7, k)
      case (3)
        pt = [pa, pb, pc]
        dir(:, 2) = [c(l3), s(l3)]
        frl(1) = owner(pa); frl(3) = owner(pc)
      case (4)
        pt = [pb, pb, pb]
        dir(:, 1) = [c(l2), s(l2)]
        dir(:, 3) = [c(l3), s(l3)]
        frl(1) = gi(7, k); frl(3) = gi(8, k)
      case (5)
        pt = [pb, pc, pc]
        dir(:, 1) = [c(l2), s(l2)]
        dir(:, 2) = [c(l3), s(l3)]
        frl(1) = gi(7, k); frl(3) = owner(pc)
      end select
    end subroutine pairs

  end subroutine mech_solve

  ! D designs in one call (issue 25): every numeric table of the description carries a
  ! last axis over the designs, the outputs too; the designs share phi, omega, epsilon,
  ! the kinds, the joints and the selection.  Each design is one mech_solve over its
  ! slices (contiguous: no copies).
  subroutine mech_solve_many(need, n, np, nl, ns, nd, gi, gr, phi, omega, epsil, inc_w, &
                             inc_e, nm, mlink, mpoint, mval, gravity, &
                             nf, fpoint, flink, nfv, fval, nt, tlink, ntv, tval, &
                             nsp, spp, spl, nspv, spv, npair, powner, lbase, x0, nop, outp, &
                             nol, outl, nv, na, nr, pos, vel, acc, th, om, ep, react, mbal, &
                             jred, mred, status, fgroup)
    !f2py threadsafe
    integer, intent(in) :: need, n, np, nl, ns, nd, nm, nf, nfv, nt, ntv, nsp, nspv, npair
    integer, intent(in) :: nv, na, nr
    integer, intent(in) :: inc_w, inc_e, nop, nol, outp(nop), outl(nol)
    integer, intent(in) :: gi(8, ns)
    real(dp), intent(in) :: gr(8, ns, nd), phi(n), omega(*), epsil(*)
    integer, intent(in) :: powner(np), lbase(0:nl)
    real(dp), intent(in) :: x0(2, np, nd)
    integer, intent(in) :: mlink(nm), mpoint(nm)
    real(dp), intent(in) :: mval(2, nm, nd), gravity
    integer, intent(in) :: fpoint(nf), flink(nf)
    real(dp), intent(in) :: fval(2, nf, nfv, nd)
    integer, intent(in) :: tlink(nt)
    real(dp), intent(in) :: tval(nt, ntv, nd)
    integer, intent(in) :: spp(2, nsp), spl(2, nsp)
    real(dp), intent(in) :: spv(2, nsp, nspv, nd)
    real(dp), intent(inout) :: pos(2, nop, n, nd), vel(2, nop, nv, nd), acc(2, nop, na, nd)
    real(dp), intent(inout) :: th(2, nol, n, nd), om(nol, nv, nd), ep(nol, na, nd)
    real(dp), intent(inout) :: react(3, npair, nr, nd), mbal(nr, nd), jred(nv, nd)
    real(dp), intent(inout) :: mred(nr, nd)
    integer, intent(inout) :: status(n, nd), fgroup(n, nd)
    integer :: d
    do d = 1, nd
      call mech_solve(need, n, np, nl, ns, gi, gr(:, :, d), phi, omega, epsil, inc_w, inc_e, &
                      nm, mlink, mpoint, mval(:, :, d), gravity, &
                      nf, fpoint, flink, nfv, fval(:, :, :, d), nt, tlink, ntv, &
                      tval(:, :, d), nsp, spp, spl, nspv, spv(:, :, :, d), npair, powner, &
                      lbase, x0(:, :, d), nop, outp, nol, outl, nv, na, nr, &
                      pos(:, :, :, d), vel(:, :, :, d), acc(:, :, :, d), th(:, :, :, d), &
                      om(:, :, d), ep(:, :, d), react(:, :, :, d), mbal(:, d), jred(:, d), &
                      mred(:, d), status(:, d), fgroup(:, d))
    end do
  end subroutine mech_solve_many

  ! A 2x2 system by Cramer's rule (forward stable for n = 2), for the whole-mechanism
  ! solver's velocities and accelerations, with solve2f's error bound (bound2) taken for
  ! the system whose columns are divided by their scales s1, s2 (unit vectors for the
  ! kinematics: the estimate is unit-free, as DKNMA1's with its unit vectors), so that the
  ! dead-centre policy is the same in any length unit: cramer_set once per matrix, cramer
  ! each right-hand side.  det A = 0: st_singular.  (Here, beside their one caller, so
  ! that the compiler inlines them.)
  ! Entries far from 1 (a mechanism of 1e200 m or 1e-200 m) are first scaled by a power
  ! of 2, 2**-e, so that det neither overflows nor underflows: exact, the same bits
  ! otherwise; cramer scales the solution back.
  pure subroutine cramer_set(a11, a12, a21, a22, f, s1, s2)
    real(dp), intent(in) :: a11, a12, a21, a22, s1, s2
    type(cram), intent(out) :: f
    real(dp) :: det, amax
    f%e = 0
    amax = max(abs(a11), abs(a12), abs(a21), abs(a22))
    if (amax > 2.0_dp**200 .or. (amax < 2.0_dp**(-200) .and. amax > 0.0_dp)) then
      if (amax <= huge(amax)) f%e = exponent(amax)
    end if
    if (f%e == 0) then
      f%a11 = a11
      f%a21 = a21
      f%a12 = a12
      f%a22 = a22
      f%s1 = s1
      f%s2 = s2
    else
      f%a11 = scale(a11, -f%e)
      f%a21 = scale(a21, -f%e)
      f%a12 = scale(a12, -f%e)
      f%a22 = scale(a22, -f%e)
      f%s1 = scale(s1, -f%e)                ! only nadet below uses them so
      f%s2 = scale(s2, -f%e)
    end if
    f%na = sqrt((f%a11/f%s1)**2 + (f%a21/f%s1)**2 + (f%a12/f%s2)**2 + (f%a22/f%s2)**2)
    det = f%a11*f%a22 - f%a12*f%a21
    f%nadet = 0.0_dp
    f%rdet = 0.0_dp
    if (det /= 0.0_dp) then
      f%rdet = 1.0_dp/det
      f%nadet = f%na*abs(f%s1*(f%s2*f%rdet))
    end if
    f%s1 = s1
    f%s2 = s2
    f%st = st_ok
    if (det == 0.0_dp .or. .not. f%nadet <= huge(1.0_dp)) f%st = st_singular
  end subroutine cramer_set

  pure subroutine cramer(f, b1, b2, da, db, sb, y1, y2, st, rel)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: b1, b2, da, db, sb
    real(dp), intent(out) :: y1, y2, rel
    integer, intent(out) :: st
    y1 = 0.0_dp; y2 = 0.0_dp
    rel = huge(1.0_dp)
    st = f%st
    if (st /= st_ok) return
    y1 = (b1*f%a22 - f%a12*b2)*f%rdet
    y2 = (f%a11*b2 - f%a21*b1)*f%rdet
    if (f%e /= 0) then
      y1 = scale(y1, -f%e)
      y2 = scale(y2, -f%e)
    end if
    if (.not. (abs(y1) <= huge(y1) .and. abs(y2) <= huge(y2))) then
      y1 = 0.0_dp; y2 = 0.0_dp
      st = st_range
      return
    end if
    rel = bound2(f%na, f%nadet, y1*f%s1, y2*f%s2, da, db, sb)
  end subroutine cramer

  ! The absolute error (in the units of the scaled unknowns y1 s1, y2 s2) that cramer's
  ! relative estimate rel stands for: rel times bound2's denominator.
  pure real(dp) function abs_err(f, y1, y2, sb, rel)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: y1, y2, sb, rel
    abs_err = rel*max(norm2d(y1*f%s1, y2*f%s2), sb/f%na)
  end function abs_err

end module mechanism
