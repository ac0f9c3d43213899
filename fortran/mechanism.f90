! mechanism.f90 -- a whole mechanism solved in one call (issue 19): the book's Assur-group
! method (chapter 4 for the kinematics, chapter 7 for the forces, the student's main program
! of chapter 10 carrying it out call by call) as a loop over the mechanism's list of
! groups, run for every position; each group's math is its kind's kernel in groups.f90
! (one home per kind, issue 25): here only the gathering of its inputs and the
! scattering of its outputs (step).
!
! The description (built and checked by python/sarkp/mechanism.py, its _group and point):
!   points 1..np  (joints, rigid points, centres of mass), each position kept as Cartesian x, y;
!   links 0..nl   (0 the frame, 1 the crank), each with its direction's cosine and sine,
!                 computed once per position from the points that define it;
!   steps gi(:, k), gr(:, k), k = 1..ns, in order (gi(1, k) = the kind):
!     0 crank   gi = 0, A, O, 1                       gr = r
!     1 RRR     gi = 1, B, A, C, L2, L3, 0, 0         gr = l2, l3, branch, 1/l2, 1/l3
!     2 RRP     gi = 2, B, A, K, L2, L3, LM, 0        gr = l2, branch, cos, sin (guide angle
!               on LM), offset, angle, 1/l2
!     3 RPR     gi = 3, B, A, C, L2, L3, 0, 0         gr = h, branch
!     4 PRP     gi = 4, B, A, C, L2, L3, LM, LN       gr = cos, sin (guide M), cos, sin (guide
!               N), offset M, offset N, angle M, angle N
!     5 RPP     gi = 5, K, A, C, L2, L3, LM, 0        gr = cos, sin (guide M), cos, sin (slot
!               T2), angle M, T2
!     6 point   gi = 6, D, P, Q, L                    gr = dist, cos, sin of the angle from P->Q
!               (Q = P: from the link's own direction)
!   Branch +1: the new joint on the left of A->C (kinds 1, 3), ahead along the guide of the
!   foot of the perpendicular from A (kind 2); kinds 4, 5 have one position.
!   Any other kind is an error (st_missing), never skipped.
!
! Kinematics in position analogues: the crank turns at d(phi)/dt = 1, so each point carries
! x, x' = dx/dphi, x'' = d2x/dphi2 and each link theta, w' , e''; the velocities asked for
! are x' omega and the accelerations x'' omega**2 + x' epsilon (the same for the links).
! The dead-centre policy of kinematics.f90 decides each position's status (policy): the
! estimate is the largest over the groups' kernels' estimates.
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
  use numerics, only: policy, failed
  use groups, only: crank_kernel, rigid_kernel, rrr_kernel, rrp_kernel, rpr_kernel, &
                    prp_kernel, rpp_kernel, kind_pairs, group_reactions
  implicit none
  private
  public :: mech_solve, mech_solve_many
  public :: mech_solve_packed, mech_solve_one, mech_solve_few


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
    ! work arrays: a block of up to nb positions for the kinematics (point p of the j-th
    ! position of the block at xb(:, p, j), link l's direction cosine at cb(l, j)), and
    ! the links' loads of the force step (fl, ml); allocated once per call
    integer, parameter :: nb = 64
    real(dp), allocatable :: xb(:, :, :), vb(:, :, :), ab(:, :, :)
    real(dp), allocatable :: cb(:, :), sb(:, :), wb(:, :), eb(:, :), maxest(:)
    integer, allocatable :: worst(:), fgb(:)
    real(dp), allocatable :: fl(:, :), ml(:)
    integer, allocatable :: gslot(:), mov(:)
    integer :: i, i0, j, m, k, jf, jt, js, fg, g, p, l, lev, st, nmov
    real(dp) :: wi, ei, w2, px, py
    logical :: masses, bad

    m = min(n, nb)
    allocate(xb(2, np, m), vb(2, np, m), ab(2, np, m), cb(0:nl, m), sb(0:nl, m), &
             wb(0:nl, m), eb(0:nl, m), maxest(m), worst(m), fgb(m))
    do j = 1, m
      xb(:, :, j) = x0
    end do
    vb = 0.0_dp; ab = 0.0_dp
    cb = 1.0_dp; sb = 0.0_dp; wb = 0.0_dp; eb = 0.0_dp
    allocate(fl(2, 0:nl), ml(0:nl))
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
    ! the moving points: the ones a step places (its first point); the others (the
    ! frame's) stay at rest in vb, ab, as link 0 in wb, eb
    allocate(mov(ns))
    nmov = 0
    do k = 1, ns
      if (gi(1, k) >= 0 .and. gi(1, k) <= 6) then
        nmov = nmov + 1
        mov(nmov) = gi(2, k)
      end if
    end do
    ! no masses (the caller's one neutral entry of zero mass and inertia): J_red = 0
    masses = any(mval /= 0.0_dp)
    lev = min(need, 3)
    wi = 0.0_dp
    ei = 0.0_dp
    w2 = 0.0_dp
    do i0 = 0, n - 1, nb
      m = min(nb, n - i0)
      ! the kinematics, step by step over the block (each step's slots read once, its
      ! kernel called for each position still standing)
      worst(1:m) = st_ok
      fgb(1:m) = 0
      maxest(1:m) = 0.0_dp
      do k = 1, ns
        call step(k, gi(1, k), i0, m)
      end do
      do j = 1, m
        i = i0 + j
        fg = fgb(j)
        st = worst(j)
        if (.not. failed(st)) then
          st = policy(maxest(j))
          if (st == st_ok) fg = 0
        end if
        if (failed(st)) then
          status(i) = st
          fgroup(i) = fg
          cycle
        end if
        ! the outputs: the moving points and links only (the caller knows the frame's),
        ! one scalar statement a number (cheaper than the little array sections), one
        ! loop over the points and one over the links for the level asked.  A position
        ! found out of range here (a position not finite, or velocities and
        ! accelerations beyond the range of doubles: in_range) gets st_range, and its
        ! outputs are overwritten with NaN by the caller (the order of the two findings
        ! does not matter: either gives st_range and fgroup 0)
        bad = .false.
        if (lev >= 2) then
          wi = omega(1 + (i - 1)*inc_w)
          ei = epsil(1 + (i - 1)*inc_e)
          w2 = wi*wi
        end if
        select case (lev)
        case (1)
          do k = 1, nop
            p = outp(k)
            px = xb(1, p, j)
            py = xb(2, p, j)
            pos(1, k, i) = px
            pos(2, k, i) = py
            if (.not. (abs(px) <= huge(px) .and. abs(py) <= huge(py))) bad = .true.
          end do
          do k = 1, nol
            l = outl(k)
            th(1, k, i) = cb(l, j)
            th(2, k, i) = sb(l, j)
          end do
        case (2)
          do k = 1, nop
            p = outp(k)
            px = xb(1, p, j)
            py = xb(2, p, j)
            pos(1, k, i) = px
            pos(2, k, i) = py
            if (.not. (abs(px) <= huge(px) .and. abs(py) <= huge(py))) bad = .true.
            vel(1, k, i) = vb(1, p, j)*wi
            vel(2, k, i) = vb(2, p, j)*wi
          end do
          do k = 1, nol
            l = outl(k)
            th(1, k, i) = cb(l, j)
            th(2, k, i) = sb(l, j)
            om(k, i) = wb(l, j)*wi
          end do
        case default
          do k = 1, nop
            p = outp(k)
            px = xb(1, p, j)
            py = xb(2, p, j)
            pos(1, k, i) = px
            pos(2, k, i) = py
            if (.not. (abs(px) <= huge(px) .and. abs(py) <= huge(py))) bad = .true.
            vel(1, k, i) = vb(1, p, j)*wi
            vel(2, k, i) = vb(2, p, j)*wi
            acc(1, k, i) = ab(1, p, j)*w2 + vb(1, p, j)*ei
            acc(2, k, i) = ab(2, p, j)*w2 + vb(2, p, j)*ei
          end do
          do k = 1, nol
            l = outl(k)
            th(1, k, i) = cb(l, j)
            th(2, k, i) = sb(l, j)
            om(k, i) = wb(l, j)*wi
            ep(k, i) = eb(l, j)*w2 + wb(l, j)*ei
          end do
        end select
        if (.not. bad .and. lev >= 2) bad = .not. in_range(j, wi, ei)
        if (bad) then
          st = st_range
          fg = 0
        end if
        ! status and fgroup come in zeroed (solve): a position that is fine is not
        ! written, which spares the kernel clearing their pages
        if (st /= st_ok .or. fg /= 0) then
          status(i) = st
          fgroup(i) = fg
          if (st == st_range) cycle
        end if
        if (lev >= 2) then
          jred(i) = 0.0_dp
          if (masses) jred(i) = reduced_inertia(j)
        end if
        ! the force step, on position j of the block's kinematics as they are (the
        ! inertia loads' accelerations formed where a mass needs them)
        if (need >= 4) call forces(i, j, w2, ei)
      end do
    end do
    deallocate(xb, vb, ab, cb, sb, wb, eb, maxest, worst, fgb)
    deallocate(fl, ml, gslot, mov)

  contains

    ! ------------------------------------------------------------------ kinematics

    ! Whether the velocities x' omega and accelerations x'' omega**2 + x' epsilon of
    ! every point and link of position j of the block stay below huge/16 (room for the
    ! sums of the force step).  The largest moduli by explicit loops over the moving
    ! points and links (maxval's NaN-aware loop over all of them cost ~200 instructions
    ! a position each): a NaN is passed over as maxval passes it over, and the frame's
    ! points and link 0, at rest, are the maxima's start 0: the same verdicts, cheaper
    logical function in_range(j, wi, ei)
      integer, intent(in) :: j
      real(dp), intent(in) :: wi, ei
      real(dp) :: vm, am, lim
      integer :: p, l, q
      lim = huge(1.0_dp)/16.0_dp
      vm = 0.0_dp
      do q = 1, nmov
        p = mov(q)
        if (abs(vb(1, p, j)) > vm) vm = abs(vb(1, p, j))
        if (abs(vb(2, p, j)) > vm) vm = abs(vb(2, p, j))
      end do
      do l = 1, nl
        if (abs(wb(l, j)) > vm) vm = abs(wb(l, j))
      end do
      in_range = abs(wi)*vm <= lim
      if (need < 3 .or. .not. in_range) return
      am = 0.0_dp
      do q = 1, nmov
        p = mov(q)
        if (abs(ab(1, p, j)) > am) am = abs(ab(1, p, j))
        if (abs(ab(2, p, j)) > am) am = abs(ab(2, p, j))
      end do
      do l = 1, nl
        if (abs(eb(l, j)) > am) am = abs(eb(l, j))
      end do
      in_range = wi*wi <= lim .and. (wi*wi)*am <= lim .and. abs(ei)*vm <= lim .and. &
                 (wi*wi)*am + abs(ei)*vm <= lim
    end function in_range

    ! The outcome of step k's kernel at position j of the block: a failure ends the
    ! position's kinematics (its later steps are not run), else the largest estimate and
    ! the step that made it are kept.  worst(j) holds st_ok or a failure, nothing else
    ! (the steps test it so)
    subroutine account(j, k, st, est)
      integer, intent(in) :: j, k
      integer, intent(inout) :: st
      real(dp), intent(in) :: est
      if (failed(st)) then
        ! a result out of range once no digit is left (a group at a dead centre: its
        ! velocities, finite but huge, squared in its accelerations) is that dead
        ! centre, not an overflow (an estimate of exactly huge is a failed solve's
        ! placeholder, not an estimate)
        if (st == st_range .and. ((.not. maxest(j) <= 0.1_dp .and. maxest(j) /= huge(est)) &
            .or. (.not. est <= 0.1_dp .and. est /= huge(est)))) st = st_singular
        worst(j) = st
        fgb(j) = k
      else if (est > maxest(j) .or. .not. est <= huge(est)) then
        maxest(j) = est
        fgb(j) = k
      end if
    end subroutine account

    ! One step of the description (k, of its kind) over the block's positions i0 + 1 ..
    ! i0 + m: its slots read once, then for each position still standing its inputs
    ! gathered from the work arrays, its kind's kernel (module groups: the math of every
    ! kind is there), its outputs scattered; links 2, 3 of a slider group turning with a
    ! guide take the guide's motion.  An unknown kind is an error, never skipped.
    subroutine step(k, kind, i0, m)
      integer, intent(in) :: k, kind, i0, m
      integer :: j, st, p1, p2, p3, l2, l3, lm, ln
      real(dp) :: est, u2(2), u3(2), um(2), un(2), q1, q2, q3, q4, q5, q6
      real(dp) :: r1, r2, r3, r4, r5, r6, r7
      p1 = gi(2, k); p2 = gi(3, k); p3 = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      lm = gi(7, k); ln = gi(8, k)
      r1 = gr(1, k); r2 = gr(2, k); r3 = gr(3, k); r4 = gr(4, k); r5 = gr(5, k)
      r6 = gr(6, k); r7 = gr(7, k)
      select case (kind)
      case (0)                              ! crank A (p1) about O (p2), link 1
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          call crank_kernel(xb(:, p2, j), r1, phi(i0 + j), xb(:, p1, j), vb(:, p1, j), &
                            ab(:, p1, j), u2)
          cb(1, j) = u2(1)
          sb(1, j) = u2(2)
          wb(1, j) = 1.0_dp
          eb(1, j) = 0.0_dp
        end do
      case (1)                              ! RRR: B (p1) from A (p2), C (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          call rrr_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), xb(:, p3, j), &
                          vb(:, p3, j), ab(:, p3, j), r1, r2, r3, r4, r5, &
                          xb(:, p1, j), vb(:, p1, j), ab(:, p1, j), u2, u3, &
                          wb(l2, j), wb(l3, j), eb(l2, j), eb(l3, j), st, est)
          call account(j, k, st, est)
          if (failed(st)) cycle
          cb(l2, j) = u2(1); sb(l2, j) = u2(2)
          cb(l3, j) = u3(1); sb(l3, j) = u3(2)
        end do
      case (2)                              ! RRP: B (p1) from A (p2), guide through K (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          um = guide(lm, j, r3, r4)
          call rrp_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), xb(:, p3, j), &
                          vb(:, p3, j), ab(:, p3, j), um, wb(lm, j), eb(lm, j), r1, r7, &
                          r5, r2, xb(:, p1, j), vb(:, p1, j), ab(:, p1, j), u2, &
                          wb(l2, j), eb(l2, j), q1, q2, st, est)
          call account(j, k, st, est)
          if (failed(st)) cycle
          cb(l2, j) = u2(1); sb(l2, j) = u2(2)
          cb(l3, j) = um(1); sb(l3, j) = um(2)
          call turns_with(l3, lm, j)
        end do
      case (3)                              ! RPR: B (p1) from A (p2), link 3 about C (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          call rpr_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), xb(:, p3, j), &
                          vb(:, p3, j), ab(:, p3, j), r1, r2, xb(:, p1, j), vb(:, p1, j), &
                          ab(:, p1, j), u3, wb(l3, j), eb(l3, j), q1, q2, st, est)
          call account(j, k, st, est)
          if (failed(st)) cycle
          cb(l3, j) = u3(1); sb(l3, j) = u3(2)
          cb(l2, j) = u3(1); sb(l2, j) = u3(2)
          call turns_with(l2, l3, j)
        end do
      case (4)                              ! PRP: B (p1) on guides through A (p2), C (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          um = guide(lm, j, r1, r2)
          un = guide(ln, j, r3, r4)
          call prp_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), um, wb(lm, j), &
                          eb(lm, j), r5, xb(:, p3, j), vb(:, p3, j), ab(:, p3, j), un, &
                          wb(ln, j), eb(ln, j), r6, xb(:, p1, j), vb(:, p1, j), &
                          ab(:, p1, j), q1, q2, q3, q4, st, est)
          call account(j, k, st, est)
          if (failed(st)) cycle
          cb(l2, j) = um(1); sb(l2, j) = um(2)
          cb(l3, j) = un(1); sb(l3, j) = un(2)
          call turns_with(l2, lm, j)
          call turns_with(l3, ln, j)
        end do
      case (5)                              ! RPP: K (p1) on the guide through A (p2), C (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          um = guide(lm, j, r1, r2)
          call rpp_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), um, wb(lm, j), &
                          eb(lm, j), r6, r3, r4, xb(:, p3, j), vb(:, p3, j), ab(:, p3, j), &
                          xb(:, p1, j), vb(:, p1, j), ab(:, p1, j), u3, q1, q2, q3, q4, &
                          q5, q6, st, est)
          call account(j, k, st, est)
          if (failed(st)) cycle
          cb(l2, j) = um(1); sb(l2, j) = um(2)
          cb(l3, j) = u3(1); sb(l3, j) = u3(2)
          call turns_with(l2, lm, j)
          call turns_with(l3, lm, j)
        end do
      case (6)                              ! a point D (p1) on link l2 from P (p2), Q (p3)
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          u2 = [cb(l2, j), sb(l2, j)]
          call rigid_kernel(lev, xb(:, p2, j), vb(:, p2, j), ab(:, p2, j), wb(l2, j), &
                            eb(l2, j), u2, xb(:, p3, j), p3 == p2, r1, r2, r3, &
                            xb(:, p1, j), vb(:, p1, j), ab(:, p1, j), st)
          call account(j, k, st, 0.0_dp)
        end do
      case default
        do j = 1, m
          if (worst(j) /= st_ok) cycle
          st = st_missing                   ! an unknown kind: an error, never skipped
          call account(j, k, st, 0.0_dp)
        end do
      end select
    end subroutine step

    ! link l turns with link g (a slider on g's guide): its omega and epsilon, to the
    ! level, at position j of the block
    subroutine turns_with(l, g, j)
      integer, intent(in) :: l, g, j
      if (lev >= 2) wb(l, j) = wb(g, j)
      if (lev >= 3) eb(l, j) = eb(g, j)
    end subroutine turns_with

    ! the guide of kinds 2, 4, 5 on link l, at the angle (cg, sg) to the link's direction,
    ! at position j of the block: its unit vector
    pure function guide(l, j, cg, sg) result(u)
      integer, intent(in) :: l, j
      real(dp), intent(in) :: cg, sg
      real(dp) :: u(2)
      u = [cb(l, j)*cg - sb(l, j)*sg, sb(l, j)*cg + cb(l, j)*sg]
    end function guide

    ! ------------------------------------------------------------------ dynamics

    ! J_red's analogue at position j of the block
    real(dp) function reduced_inertia(j)
      integer, intent(in) :: j
      integer :: q, p, l
      reduced_inertia = 0.0_dp
      do q = 1, nm
        p = mpoint(q); l = mlink(q)
        reduced_inertia = reduced_inertia + mval(1, q)*(vb(1, p, j)**2 + vb(2, p, j)**2) &
                          + mval(2, q)*wb(l, j)**2
      end do
    end function reduced_inertia

    ! load f at point p on link l: into the link's resultant and moment about its first
    ! point (position j of the block)
    subroutine load(j, l, p, fx, fy)
      integer, intent(in) :: j, l, p
      real(dp), intent(in) :: fx, fy
      integer :: b
      b = base(l)
      fl(1, l) = fl(1, l) + fx
      fl(2, l) = fl(2, l) + fy
      ml(l) = ml(l) + (xb(1, p, j) - xb(1, b, j))*fy - (xb(2, p, j) - xb(2, b, j))*fx
    end subroutine load

    ! The force step of position i, the block's position j (w2 = omega**2, ei = epsilon)
    subroutine forces(i, j, w2, ei)
      integer, intent(in) :: i, j
      real(dp), intent(in) :: w2, ei
      integer :: q, p, l, r, k
      real(dp) :: fx, fy, mr, dl(2), dn, ff, ax, ay
      logical :: ok
      fl = 0.0_dp
      ml = 0.0_dp
      mr = 0.0_dp
      do q = 1, nm
        p = mpoint(q); l = mlink(q)
        ! the inertia loads: -m a_S, -J_S eps
        ax = ab(1, p, j)*w2 + vb(1, p, j)*ei
        ay = ab(2, p, j)*w2 + vb(2, p, j)*ei
        fx = -mval(1, q)*ax
        fy = -mval(1, q)*(ay + gravity)
        call load(j, l, p, fx, fy)
        ml(l) = ml(l) - mval(2, q)*(eb(l, j)*w2 + wb(l, j)*ei)
        mr = mr - mval(1, q)*gravity*vb(2, p, j)
      end do
      jf = 1 + (i - 1)*min(nfv - 1, 1)
      do q = 1, nf
        p = fpoint(q); l = flink(q)
        call load(j, l, p, fval(1, q, jf), fval(2, q, jf))
        mr = mr + fval(1, q, jf)*vb(1, p, j) + fval(2, q, jf)*vb(2, p, j)
      end do
      jt = 1 + (i - 1)*min(ntv - 1, 1)
      do q = 1, nt
        l = tlink(q)
        ml(l) = ml(l) + tval(q, jt)
        mr = mr + tval(q, jt)*wb(l, j)
      end do
      js = 1 + (i - 1)*min(nspv - 1, 1)
      do q = 1, nsp
        p = spp(1, q); r = spp(2, q)
        dl = xb(:, r, j) - xb(:, p, j)
        dn = norm2d(dl(1), dl(2))
        if (dn == 0.0_dp) then
          ! the ends meet: a force k (0 - L0) /= 0 has no direction here, the position
          ! fails (fgroup = -q names the spring); with k L0 = 0 there is no force to drop
          if (spv(1, q, js)*spv(2, q, js) /= 0.0_dp) then
            status(i) = st_singular
            fgroup(i) = -q
          end if
          cycle
        end if
        ff = spv(1, q, js)*(dn - spv(2, q, js))   ! tension > 0 pulls P towards Q
        dl = dl/dn
        call load(j, spl(1, q), p, ff*dl(1), ff*dl(2))
        call load(j, spl(2, q), r, -ff*dl(1), -ff*dl(2))
        mr = mr + ff*(dl(1)*(vb(1, p, j) - vb(1, r, j)) + dl(2)*(vb(2, p, j) - vb(2, r, j)))
      end do
      mred(i) = mr
      ! the groups in reverse order (chapter 7)
      do k = ns, 1, -1
        if (gslot(k) > 0) call group_forces(k, gi(1, k), gslot(k), i, j)
      end do
      ! the crank (link 1), its loads gathered about O: M_b + M_1 = 0, the frame's
      ! reaction on it -F_1
      react(1, 1, i) = -fl(1, 1)
      react(2, 1, i) = -fl(2, 1)
      react(3, 1, i) = 0.0_dp
      mbal(i) = -ml(1)
      ! every force and moment a finite double, else the position is st_range
      ok = abs(mbal(i)) <= huge(1.0_dp) .and. abs(mred(i)) <= huge(1.0_dp)
      do k = 1, npair
        do q = 1, 3
          ok = ok .and. abs(react(q, k, i)) <= huge(1.0_dp)
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
    subroutine group_forces(k, kind, slot, i, j)
      integer, intent(in) :: k, kind, slot, i, j
      integer :: pt(3), ty(3), frl(3), l2, l3, q, st
      real(dp) :: dir(2, 3), pp(2, 3), out(3, 3)
      l2 = gi(5, k); l3 = gi(6, k)
      call pairs(k, kind, j, pt, ty, dir, frl)
      do q = 1, 3
        pp(1, q) = xb(1, pt(q), j)
        pp(2, q) = xb(2, pt(q), j)
      end do
      call group_reactions(pp, ty, dir, fl(:, l2), ml(l2), xb(:, base(l2), j), fl(:, l3), &
                           ml(l3), xb(:, base(l3), j), out, st)
      if (st /= st_ok) then
        status(i) = st
        fgroup(i) = k
      end if
      do q = 1, 3
        react(:, slot + q - 1, i) = out(:, q)
        if (q /= 2 .and. frl(q) > 0) then
          call load(j, frl(q), pt(q), -out(1, q), -out(2, q))   ! the outside bears the opposite
          ml(frl(q)) = ml(frl(q)) - out(3, q)
        end if
      end do
    end subroutine group_forces

    ! The pairs of a group, in group_reactions' order: their points, types (the kind's
    ! declaration, groups' kind_pairs) and sliding directions, and the outside links of
    ! pairs 1 and 3 (0: the frame)
    subroutine pairs(k, kind, j, pt, ty, dir, frl)
      integer, intent(in) :: k, kind, j
      integer, intent(out) :: pt(3), ty(3), frl(3)
      real(dp), intent(out) :: dir(2, 3)
      integer :: pb, pa, pc, l2, l3
      pb = gi(2, k); pa = gi(3, k); pc = gi(4, k); l2 = gi(5, k); l3 = gi(6, k)
      dir = 0.0_dp
      ty = kind_pairs(:, kind)
      frl = 0
      pt = pb                               ! (kinds 1-5 only reach here: gslot > 0)
      select case (kind)
      case (1)
        pt = [pa, pb, pc]
        frl(1) = owner(pa); frl(3) = owner(pc)
      case (2)
        pt = [pa, pb, pb]
        dir(:, 3) = [cb(l3, j), sb(l3, j)]
        frl(1) = owner(pa); frl(3) = gi(7, k)
      case (3)
        pt = [pa, pb, pc]
        dir(:, 2) = [cb(l3, j), sb(l3, j)]
        frl(1) = owner(pa); frl(3) = owner(pc)
      case (4)
        pt = [pb, pb, pb]
        dir(:, 1) = [cb(l2, j), sb(l2, j)]
        dir(:, 3) = [cb(l3, j), sb(l3, j)]
        frl(1) = gi(7, k); frl(3) = gi(8, k)
      case (5)
        pt = [pb, pc, pc]
        dir(:, 1) = [cb(l2, j), sb(l2, j)]
        dir(:, 2) = [cb(l3, j), sb(l3, j)]
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

  ! The packed entry (issue 25: the cost of a one-position solve is its call): mech_solve
  ! for nd designs with the description's tables in one integer and one real array (built
  ! once by mechanism.py and cached with its plan) and the outputs in one real and one
  ! integer array, so that the wrapper converts a dozen arguments, not forty.  The blocks
  ! are passed as their first elements (sequence association: no copies).
  !   ipk = np, nl, ns, nm, nf, nt, nsp, npair, nop, nol, pf, pt, ps  (pf, pt, ps: 1 when
  !         the forces, torques, springs have a value per position, else 0), then gi(8, ns),
  !         mlink(nm), mpoint(nm), fpoint(nf), flink(nf), tlink(nt), spp(2, nsp),
  !         spl(2, nsp), powner(np), lbase(0:nl), outp(nop), outl(nol);
  !   rpk = gr(8, ns, nd), x0(2, np, nd), mval(2, nm, nd), fval(2, nf, nfv, nd),
  !         tval(nt, ntv, nd), spv(2, nsp, nspv, nd), each whole before the next;
  !   rout = pos(2, nop, n, nd), vel(2, nop, nv, nd), acc(2, nop, na, nd),
  !         th(2, nol, n, nd), om(nol, nv, nd), ep(nol, na, nd), react(3, npair, nr, nd),
  !         mbal(nr, nd), jred(nv, nd), mred(nr, nd) (nv, na, nr: n when need asks for
  !         them, else 1);
  !   iout = status(n, nd), fgroup(n, nd), zeroed here.
  ! Sizes that do not add up leave iout(1) = -1 and compute nothing.
  subroutine mech_solve_packed(need, n, nd, ni, ipk, nrk, rpk, phi, omega, epsil, inc_w, &
                               inc_e, gravity, nro, rout, nio, iout)
    !f2py threadsafe
    integer, intent(in) :: need, n, nd, ni, nrk, nro, nio, inc_w, inc_e
    integer, intent(in) :: ipk(ni)
    real(dp), intent(in) :: rpk(nrk), phi(n), omega(*), epsil(*), gravity
    real(dp), intent(inout) :: rout(nro)
    integer, intent(inout) :: iout(nio)
    integer, parameter :: nh = 13
    integer :: np, nl, ns, nm, nf, nt, nsp, npair, nop, nol, nfv, ntv, nspv, nv, na, nr
    integer :: ogi, oml, omp, ofp, ofl, otl, osp, osl, opw, olb, oop, ool, iend
    integer :: sgr, sx0, smv, sfv, stv, ssv, spo, sve, sac, sth, som, sep, sre, sr1, sv1
    integer :: d, o, q
    if (nio < 1) return
    if (ni < nh .or. n < 1 .or. nd < 1 .or. need < 1 .or. need > 4) then
      iout(1) = -1
      return
    end if
    np = ipk(1); nl = ipk(2); ns = ipk(3); nm = ipk(4); nf = ipk(5); nt = ipk(6)
    nsp = ipk(7); npair = ipk(8); nop = ipk(9); nol = ipk(10)
    nfv = merge(n, 1, ipk(11) /= 0)
    ntv = merge(n, 1, ipk(12) /= 0)
    nspv = merge(n, 1, ipk(13) /= 0)
    nv = merge(n, 1, need >= 2)
    na = merge(n, 1, need >= 3)
    nr = merge(n, 1, need >= 4)
    ! the integer tables' first elements
    ogi = nh + 1
    oml = ogi + 8*ns
    omp = oml + nm
    ofp = omp + nm
    ofl = ofp + nf
    otl = ofl + nf
    osp = otl + nt
    osl = osp + 2*nsp
    opw = osl + 2*nsp
    olb = opw + np
    oop = olb + nl + 1
    ool = oop + nop
    iend = ool + nol - 1
    ! the real tables' and outputs' sizes per design
    sgr = 8*ns; sx0 = 2*np; smv = 2*nm; sfv = 2*nf*nfv; stv = nt*ntv; ssv = 2*nsp*nspv
    spo = 2*nop*n; sve = 2*nop*nv; sac = 2*nop*na; sth = 2*nol*n; som = nol*nv
    sep = nol*na; sre = 3*npair*nr; sr1 = nr; sv1 = nv
    if (min(np, nl, ns, nm, nf, nt, nsp, npair, nop, nol) < 1 .or. iend /= ni .or. &
        nd*(sgr + sx0 + smv + sfv + stv + ssv) /= nrk .or. &
        nd*(spo + sve + sac + sth + som + sep + sre + 2*sr1 + sv1) /= nro .or. &
        2*n*nd /= nio) then
      iout(1) = -1
      return
    end if
    iout = 0
    do d = 1, nd
      q = d - 1
      o = 1 + nd*(spo + sve + sac + sth + som + sep + sre)   ! mbal's first element
      call mech_solve(need, n, np, nl, ns, ipk(ogi), rpk(1 + q*sgr), phi, omega, epsil, &
                      inc_w, inc_e, nm, ipk(oml), ipk(omp), &
                      rpk(1 + nd*(sgr + sx0) + q*smv), gravity, nf, ipk(ofp), ipk(ofl), &
                      nfv, rpk(1 + nd*(sgr + sx0 + smv) + q*sfv), nt, ipk(otl), ntv, &
                      rpk(1 + nd*(sgr + sx0 + smv + sfv) + q*stv), nsp, ipk(osp), &
                      ipk(osl), nspv, rpk(1 + nd*(sgr + sx0 + smv + sfv + stv) + q*ssv), &
                      npair, ipk(opw), ipk(olb), rpk(1 + nd*sgr + q*sx0), nop, ipk(oop), &
                      nol, ipk(ool), nv, na, nr, &
                      rout(1 + q*spo), &
                      rout(1 + nd*spo + q*sve), &
                      rout(1 + nd*(spo + sve) + q*sac), &
                      rout(1 + nd*(spo + sve + sac) + q*sth), &
                      rout(1 + nd*(spo + sve + sac + sth) + q*som), &
                      rout(1 + nd*(spo + sve + sac + sth + som) + q*sep), &
                      rout(1 + nd*(spo + sve + sac + sth + som + sep) + q*sre), &
                      rout(o + q*sr1), rout(o + nd*sr1 + q*sv1), &
                      rout(o + nd*(sr1 + sv1) + q*sr1), &
                      iout(1 + q*n), iout(1 + n*nd + q*n))
    end do
  end subroutine mech_solve_packed

  ! One position (the fast way of Mechanism.solve(phi) for a number phi): the packed entry
  ! with phi, omega, epsilon and gravity as numbers, and status and fgroup returned in
  ! rout's last element (their two 32-bit integers' bits, which mechanism.py reads as
  ! such) besides st, the status.
  subroutine mech_solve_one(need, ni, ipk, nrk, rpk, phi, omega, epsil, gravity, nro, &
                            rout, st)
    !f2py threadsafe
    integer, intent(in) :: need, ni, nrk, nro
    integer, intent(in) :: ipk(ni)
    real(dp), intent(in) :: rpk(nrk), phi, omega, epsil, gravity
    real(dp), intent(inout) :: rout(nro)
    integer, intent(out) :: st
    integer :: io(2)
    real(dp) :: ph(1), w(1), e(1)
    st = -1
    if (nro < 2) return
    io = 0
    ph(1) = phi
    w(1) = omega
    e(1) = epsil
    call mech_solve_packed(need, 1, 1, ni, ipk, nrk, rpk, ph, w, e, 0, 0, gravity, &
                           nro - 1, rout, 2, io)
    rout(nro) = transfer(io, rout(nro))
    st = io(1)
  end subroutine mech_solve_one

  ! A 1-d phi (the fast way of Mechanism.solve for an array): the packed entry for one
  ! description with omega, epsilon and gravity as numbers; nz the number of positions
  ! whose status is not OK (-2: a phi that is not finite, -1: sizes that do not add up;
  ! nothing computed then).
  subroutine mech_solve_few(need, n, phi, ni, ipk, nrk, rpk, omega, epsil, gravity, nro, &
                            rout, nio, iout, nz)
    !f2py threadsafe
    integer, intent(in) :: need, n, ni, nrk, nro, nio
    integer, intent(in) :: ipk(ni)
    real(dp), intent(in) :: phi(n), rpk(nrk), omega, epsil, gravity
    real(dp), intent(inout) :: rout(nro)
    integer, intent(inout) :: iout(nio)
    integer, intent(out) :: nz
    real(dp) :: w(1), e(1)
    integer :: i
    nz = -2
    do i = 1, n
      if (.not. abs(phi(i)) <= huge(phi(i))) return
    end do
    nz = -1
    if (nio < 1) return
    w(1) = omega
    e(1) = epsil
    call mech_solve_packed(need, n, 1, ni, ipk, nrk, rpk, phi, w, e, 0, 0, gravity, nro, &
                           rout, nio, iout)
    if (iout(1) == -1) return
    nz = count(iout(1:n) /= 0)
  end subroutine mech_solve_few

end module mechanism
