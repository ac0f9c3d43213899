! groups.f90 -- one home for each Assur group kind (issue 25).
!
! Each kind -- the crank, a rigid point, and the book's dyads 1-5 (RRR, RRP, RPR, PRP, RPP)
! -- has its kernels here and nowhere else: positions, velocities, accelerations with the
! error estimates of the dead-centre policy (numerics.f90), and the chapter 7 force step.
! The kernels take and return named Cartesian quantities of one position.  Their callers:
! mechanism.f90 (sarkp.Mechanism, a whole mechanism in one call) and the book's routines,
! DPRM/DSKOR/DUSKR/DKNMA 1-5 (kinematics.f90) and DNMA/DNMAF 1-5 (forces.f90), adapters that
! keep the book's conventions (polar hand-offs, branch signs, argument order).
! A new kind is one kernel here plus its declaration in python/sarkp/mechanism.py.
module groups
  use prmtr, only: dp, st_ok, st_assembly, st_singular, st_range, norm2d
  use numerics, only: uround, bound2, failed, tri_apex, apex_vectors, unscale, &
                      angle_sensitivity, solve2e, solve_kind5
  implicit none
  private
  public :: pair_revolute, pair_slider, kind_pairs, group_reactions

  ! ---- the chapter 7 force step: the pairs of each kind (its declaration) ----
  ! A pair's type: a revolute carries a force (fx, fy) at its point; a slider (no
  ! friction) a force normal to its sliding direction and a couple.
  integer, parameter :: pair_revolute = 0, pair_slider = 1
  ! kind_pairs(:, kind): the types of a group's pairs 1 (the outside on link 2), 2 (link 2
  ! on link 3), 3 (the outside on link 3), for the kinds 1-5 as sarkp.Mechanism lays them
  ! out (link 2 the group's first link).  A new kind of two links and three lower pairs is
  ! one more column here: group_reactions serves every such kind.
  integer, parameter :: kind_pairs(3, 5) = reshape([ &
      pair_revolute, pair_revolute, pair_revolute, &   ! 1 RRR
      pair_revolute, pair_revolute, pair_slider, &     ! 2 RRP: the slider on its guide
      pair_revolute, pair_slider, pair_revolute, &     ! 3 RPR: the slider on link 3
      pair_slider, pair_revolute, pair_slider, &       ! 4 PRP: two sliders joined at B
      pair_slider, pair_slider, pair_revolute], [3, 5])  ! 5 RPP: yoke on its guide, block

  ! A 2x2 system for Cramer's rule: its entries, 1/det, and for the error estimate the
  ! scales s1, s2 of its columns (the lengths the columns are unit vectors times), so that
  ! the estimate is that of the unit-free system and the same in any length unit.
  type :: cram
    real(dp) :: a11, a12, a21, a22, rdet, na, rna, nadet, s1, s2
    integer :: st, e
  end type cram
  public :: cram, cramer_set, cramer, abs_err, carried
  public :: crank_kernel, rigid_kernel, rrr_kernel, rrp_kernel, rpr_kernel, prp_kernel, &
            rpp_kernel
  public :: prp_position, prp_matrix, prp_velocity, prp_acceleration, rpp_position, &
            rpp_velocity, rpp_acceleration
  public :: rrr_position, rrr_system, rrr_velocity, rrr_acceleration
  public :: rrp_position, rrp_system, rrp_velocity, rrp_acceleration, rpr_position, &
            rpr_system, rpr_velocity, rpr_acceleration

contains

  ! =====================================================================================
  ! Kinematics: positions, velocities, accelerations, error estimates
  ! =====================================================================================

  ! A 2x2 system by Cramer's rule (forward stable for n = 2), for the kernels' velocities
  ! and accelerations (and the force step's pair reactions), with solve2f's error bound
  ! (bound2) taken for the system whose columns are divided by their scales s1, s2 (unit
  ! vectors for the kinematics: the estimate is unit-free, as DKNMA1's with its unit
  ! vectors), so that the dead-centre policy is the same in any length unit: cramer_set
  ! once per matrix, cramer each right-hand side.  det A = 0: st_singular.
  ! Entries far from 1 (a mechanism of 1e200 m or 1e-200 m) are first scaled by a power
  ! of 2, 2**-e, so that det neither overflows nor underflows: exact, the same bits
  ! otherwise; cramer scales the solution back.
  pure subroutine cramer_set(a11, a12, a21, a22, f, s1, s2)
    real(dp), intent(in) :: a11, a12, a21, a22, s1, s2
    type(cram), intent(out) :: f
    real(dp) :: det, amax, r1, r2
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
    ! the columns' scales by their reciprocals (two divisions, not four: the estimate
    ! moves by a rounding, exact for the scales 1 and powers of 2), and 1/|A|_F for the
    ! bounds' denominators (cramer, abs_err: a product instead of a division each)
    r1 = 1.0_dp/f%s1
    r2 = 1.0_dp/f%s2
    f%na = sqrt((f%a11*r1)**2 + (f%a21*r1)**2 + (f%a12*r2)**2 + (f%a22*r2)**2)
    det = f%a11*f%a22 - f%a12*f%a21
    f%nadet = 0.0_dp
    f%rdet = 0.0_dp
    f%rna = 0.0_dp
    if (det /= 0.0_dp) then
      f%rdet = 1.0_dp/det
      f%nadet = f%na*abs(f%s1*(f%s2*f%rdet))
      f%rna = 1.0_dp/f%na
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
    real(dp) :: ny, den
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
    ! numerics' bound2 of the unit-free system, its denominator max(|y|, sb/|A|_F) by
    ! the reciprocal cramer_set keeps (one division here, not two)
    ny = norm2d(y1*f%s1, y2*f%s2)
    den = max(ny, sb*f%rna)
    if (den == 0.0_dp) then
      rel = 0.0_dp                          ! no data: y = 0 exactly
    else
      rel = f%nadet*((2.0_dp*da + 4.0_dp*uround*f%na)*ny + db)/den
    end if
  end subroutine cramer

  ! The absolute error (in the units of the scaled unknowns y1 s1, y2 s2) that cramer's
  ! relative estimate rel stands for: rel times bound2's denominator.
  pure real(dp) function abs_err(f, y1, y2, sb, rel)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: y1, y2, sb, rel
    abs_err = rel*max(norm2d(y1*f%s1, y2*f%s2), sb*f%rna)
  end function abs_err
  !
  ! Conventions of every kernel below (one position, one group):
  ! - level: 1 positions, 2 and velocities, 3 and accelerations; outputs beyond the level
  !   are not set.
  ! - A point's position x(2), velocity v(2) and acceleration a(2) are Cartesian (x, y) in
  !   any one length unit.  Velocities may be true (d/dt) or analogues (d/dphi, the crank
  !   turning at 1: sarkp.Mechanism's use): the kernels are the same.
  ! - A link's direction is its unit vector u = (cos, sin); w, e its angular velocity and
  !   acceleration, counter-clockwise positive (radians, per the velocities' time unit).
  ! - A guide (kinds 2, 4, 5) is a line of a link g, given by its unit vector ug (already
  !   turned by the link's angle) and one of its points: the point's x, v, a and the
  !   link's wg, eg carry the guide's motion (a guide of the frame: zeros).
  ! - st: prmtr's status (st_ok, st_assembly: the group does not assemble, st_singular: a
  !   dead centre or a degenerate input, st_range: a result out of the range of doubles).
  !   est: the estimated relative error of the results (unit-free: the same in any length
  !   unit), the input of numerics' dead-centre policy (numerics: policy); huge() when a
  !   2x2 solve failed.  On a failure the outputs are not all set.
  ! - The branch (kinds 1, 2, 3) is +1 or -1 (see each kernel).

  ! The motion of a point X carried by a link of angular velocity w, acceleration e whose
  ! point P (xp, vp, ap) is known: v = vp + w k x (X - P), a = ap + e k x (X - P) - w**2 (X - P).
  pure subroutine carried(xp, vp, ap, w, e, xx, vx, ax)
    real(dp), intent(in) :: xp(2), vp(2), ap(2), w, e, xx(2)
    real(dp), intent(out) :: vx(2), ax(2)
    real(dp) :: r(2)
    r = xx - xp
    vx = vp + w*[-r(2), r(1)]
    ax = ap + e*[-r(2), r(1)] - w**2*r
  end subroutine carried

  ! The crank: A = O + r (cos phi, sin phi), O fixed.
  ! In:  xo = the pivot O; r = the radius |OA|; phi = the crank angle (rad).
  ! Out: xa; va = dA/dphi, aa = d2A/dphi2 (analogues: the crank turns at w = 1, e = 0;
  !      times omega, omega**2 + ... by the caller); u = (cos phi, sin phi).
  pure subroutine crank_kernel(xo, r, phi, xa, va, aa, u)
    real(dp), intent(in) :: xo(2), r, phi
    real(dp), intent(out) :: xa(2), va(2), aa(2), u(2)
    real(dp) :: cp, sp
    cp = cos(phi)
    sp = sin(phi)
    xa = xo + r*[cp, sp]
    u = [cp, sp]
    va = r*[-sp, cp]
    aa = -r*[cp, sp]
  end subroutine crank_kernel

  ! A point D rigidly on a link: D = P + dist (the reference direction turned by the
  ! angle whose cosine and sine are cd, sd).  The reference direction: the link's own, ul,
  ! when own, else P->Q (xq).
  ! In:  level; xp, vp, ap = P; wl, el = the link's angular velocity, acceleration; ul =
  !      the link's direction; xq, own; dist, cd, sd.
  ! Out: xd, vd, ad; st = st_singular when Q = P (not own), else st_ok (no estimate:
  !      the point adds no error of its own).
  pure subroutine rigid_kernel(level, xp, vp, ap, wl, el, ul, xq, own, dist, cd, sd, &
                               xd, vd, ad, st)
    integer, intent(in) :: level
    real(dp), intent(in) :: xp(2), vp(2), ap(2), wl, el, ul(2), xq(2), dist, cd, sd
    logical, intent(in) :: own
    real(dp), intent(out) :: xd(2), vd(2), ad(2)
    integer, intent(out) :: st
    real(dp) :: dq(2), dn, u(2)
    st = st_ok
    if (own) then
      u = ul
    else
      dq = xq - xp
      dn = norm2d(dq(1), dq(2))
      if (dn == 0.0_dp) then
        st = st_singular
        return
      end if
      u = dq/dn
    end if
    xd = xp + dist*[u(1)*cd - u(2)*sd, u(2)*cd + u(1)*sd]
    if (level < 2) return
    call carried(xp, vp, ap, wl, el, xd, vd, ad)
  end subroutine rigid_kernel

  ! Kind 1, RRR (DPRM1/DSKOR1/DUSKR1/DKNMA1): the joint B at l2 from A (link 2 = A-B) and
  ! l3 from C (link 3 = C-B), in three stages -- rrr_position, rrr_velocity,
  ! rrr_acceleration, each taking the estimate of the stage before -- which rrr_kernel
  ! runs in order (sarkp.Mechanism, DPRM1, DKNMA1); DSKOR1 and DUSKR1, given the links'
  ! directions, call the velocity and acceleration stages alone.
  ! In:  level; xa, va, aa = A; xc, vc, ac = C; l2, l3 > 0 and rl2 = 1/l2, rl3 = 1/l3
  !      (the caller's, computed once); branch = +1: B on the left of the line A->C,
  !      -1 on its right.
  ! Out: xb, vb, ab = B; u2 = (B - A)/l2, u3 = (B - C)/l3; w2, w3, e2, e3 of links 2, 3;
  !      st (st_assembly: the links do not reach, or A = C with l2 /= l3; st_singular:
  !      A = C with l2 = l3, or a velocity system at a dead centre), est.
  ! The estimate: the angles' sensitivity to one rounding of the triangle's sides (tri_apex,
  ! widened when the coordinates are far from the origin), then the 2x2 systems with
  ! unit-vector columns (cramer), the velocities' error carried into the accelerations
  ! (as DKNMA1).
  pure subroutine rrr_kernel(level, xa, va, aa, xc, vc, ac, l2, l3, branch, rl2, rl3, &
                        xb, vb, ab, u2, u3, w2, w3, e2, e3, st, est)
    integer, intent(in) :: level
    real(dp), intent(in) :: xa(2), va(2), aa(2), xc(2), vc(2), ac(2), l2, l3, branch
    real(dp), intent(in) :: rl2, rl3
    real(dp), intent(out) :: xb(2), vb(2), ab(2), u2(2), u3(2), w2, w3, e2, e3, est
    integer, intent(out) :: st
    real(dp) :: r2(2), r3(2), dang, ev, rel
    type(cram) :: f
    call rrr_position(xa, xc, l2, l3, branch, rl2, rl3, xb, r2, r3, u2, u3, dang, st)
    est = dang
    if (failed(st) .or. level < 2) return
    call rrr_system(r2, r3, l2, l3, f)
    call rrr_velocity(f, r2, va, vc, dang, 4.0_dp*uround, vb, w2, w3, ev, st, rel)
    if (failed(st)) return
    est = max(est, rel)
    if (level < 3) return
    call rrr_acceleration(f, r2, r3, l2, l3, aa, ac, w2, w3, dang, ev, 4.0_dp*uround, &
                          ab, e2, e3, st, rel)
    if (failed(st)) return
    est = max(est, rel)
  end subroutine rrr_kernel

  ! Kind 1's positions: B from the triangle A, C (base d = |AC|) and l2, l3.
  ! Out: xb; r2 = B - A, r3 = B - C (the velocity stage's inputs); u2, u3 as rrr_kernel;
  !      dang = the links' directions' error (radians: the estimate of the position, 0 on
  !      a failure); st as rrr_kernel.
  pure subroutine rrr_position(xa, xc, l2, l3, branch, rl2, rl3, xb, r2, r3, u2, u3, &
                               dang, st)
    real(dp), intent(in) :: xa(2), xc(2), l2, l3, branch, rl2, rl3
    real(dp), intent(out) :: xb(2), r2(2), r3(2), u2(2), u3(2), dang
    integer, intent(out) :: st
    integer :: ex
    real(dp) :: dx, dy, d, pr, h, pq, sx, q2, q3
    dx = xc(1) - xa(1)
    dy = xc(2) - xa(2)
    d = norm2d(dx, dy)
    dang = 0.0_dp
    if (d == 0.0_dp) then
      st = st_singular
      if (l2 /= l3) st = st_assembly
      return
    end if
    call tri_apex(d, l2, l3, pr, h, pq, ex, dang, st)
    if (failed(st)) return
    call apex_vectors(dx, dy, d, pr, h, pq, branch, r2(1), r2(2), r3(1), r3(2))
    r2 = [unscale(r2(1), ex), unscale(r2(2), ex)]
    r3 = [unscale(r3(1), ex), unscale(r3(2), ex)]
    xb = xa + r2
    u2 = [r2(1)*rl2, r2(2)*rl2]
    u3 = [r3(1)*rl3, r3(2)*rl3]
    ! d carries the rounding of the coordinates it is the difference of (far from the
    ! origin more than that of d itself, which dang allows for): the angles move by
    ! 2u (sx d + l2**2 + l3**2)/(d h) instead of 2u (d**2 + l2**2 + l3**2)/(d h), i.e.
    ! 1 + (sx - d) d/(d**2 + l2**2 + l3**2) times as far: one division, where no square
    ! overflows or underflows (a huge l2 = l3 over a small d: the sum is inf, the factor
    ! 1, its limit); beyond, the same in ratios of d
    sx = abs(xa(1)) + abs(xa(2)) + abs(xc(1)) + abs(xc(2))
    if (sx > d) then
      if (sx < 2.0_dp**500 .and. d > 2.0_dp**(-500)) then
        dang = dang*(1.0_dp + (sx - d)*d/(d*d + l2*l2 + l3*l3))
      else
        q2 = l2/d
        q3 = l3/d
        dang = dang*(1.0_dp + (sx/d - 1.0_dp)/(1.0_dp + q2*q2 + q3*q3))
      end if
    end if
  end subroutine rrr_position

  ! Kind 1's velocity and acceleration systems share one matrix: the columns k x r2 and
  ! -k x r3, unit vectors times l2, l3 (cramer's scales: a unit-free estimate).
  pure subroutine rrr_system(r2, r3, l2, l3, f)
    real(dp), intent(in) :: r2(2), r3(2), l2, l3
    type(cram), intent(out) :: f
    call cramer_set(-r2(2), r3(2), r2(1), -r3(1), f, l2, l3)
  end subroutine rrr_system

  ! Kind 1's velocities: v_A + w2 k x r2 = v_C + w3 k x r3.
  ! In:  f = rrr_system's matrix; r2 = B - A; va, vc; dang = the position's estimate
  !      (the directions' error, radians); rv = the relative error of the components of
  !      va, vc (of the sum of their moduli; 4u when they are exact to rounding).
  ! Out: vb, w2, w3; ev = their absolute error (in w l units, the acceleration stage's
  !      input); st (st_singular: a dead centre; st_range: an overflow), rel = the
  !      estimated relative error.  On a failure only st, w2, w3 and rel are set.
  pure subroutine rrr_velocity(f, r2, va, vc, dang, rv, vb, w2, w3, ev, st, rel)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: r2(2), va(2), vc(2), dang, rv
    real(dp), intent(out) :: vb(2), w2, w3, ev, rel
    integer, intent(out) :: st
    real(dp) :: sb
    sb = abs(va(1)) + abs(va(2)) + abs(vc(1)) + abs(vc(2))
    call cramer(f, vc(1) - va(1), vc(2) - va(2), dang, rv*sb, sb, w2, w3, st, rel)
    if (failed(st)) return
    vb = va + w2*[-r2(2), r2(1)]
    ev = abs_err(f, w2, w3, sb, rel)
  end subroutine rrr_velocity

  ! Kind 1's accelerations: a_A + e2 k x r2 - w2**2 r2 = a_C + e3 k x r3 - w3**2 r3.
  ! In:  f, r2, r3 as rrr_velocity; l2, l3; aa, ac; w2, w3; dang as rrr_velocity; ev =
  !      the velocities' absolute error (rrr_velocity's; 0 for given w2, w3); ra = the
  !      relative error of the components of aa, ac (as rv).
  ! Out: ab, e2, e3; st, rel as rrr_velocity.  The right-hand side's error: ra times the
  !      accelerations' size, 4u of the normal terms w**2 l, the position's (dang) of
  !      them, and the velocities' through w**2 l (as DKNMA1's, L2640).
  pure subroutine rrr_acceleration(f, r2, r3, l2, l3, aa, ac, w2, w3, dang, ev, ra, &
                                   ab, e2, e3, st, rel)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: r2(2), r3(2), l2, l3, aa(2), ac(2), w2, w3, dang, ev, ra
    real(dp), intent(out) :: ab(2), e2, e3, rel
    integer, intent(out) :: st
    real(dp) :: sa, sn
    sa = abs(aa(1)) + abs(aa(2)) + abs(ac(1)) + abs(ac(2))
    sn = w2**2*l2 + w3**2*l3
    call cramer(f, ac(1) - aa(1) - w3**2*r3(1) + w2**2*r2(1), &
                ac(2) - aa(2) - w3**2*r3(2) + w2**2*r2(2), dang, &
                ra*sa + (4.0_dp*uround + dang)*sn &
                + ev*(2.0_dp*abs(w2) + ev/l2) + ev*(2.0_dp*abs(w3) + ev/l3), &
                sa + sn, e2, e3, st, rel)
    if (failed(st)) return
    ab = aa + e2*[-r2(2), r2(1)] - w2**2*r2
  end subroutine rrr_acceleration

  ! Kind 2, RRP (DPRM2/DKNMA2): the slider joint B on a guide, at off from its axis
  ! (along the guide's left normal), the rod A-B (link 2) of length l2; the slider block
  ! (link 3) turns with the guide.  The kernel runs the three stages rrp_position,
  ! rrp_velocity, rrp_acceleration, carrying the guide's motion from K to B between them;
  ! the book's DPRM2, DSKOR2, DUSKR2, DKNMA2 (corrected mode) call the stages, their guide's
  ! motion being given at B.
  ! In:  level; xa, va, aa = A; the guide: xk, vk, ak = its point K, ug its direction,
  !      wg, eg its link's motion; l2 > 0, rl2 = 1/l2; off; branch = +1: B ahead, along
  !      ug, of the foot of the perpendicular from A, -1 behind.
  ! Out: xb, vb, ab = B; u2 = (B - A)/l2, w2, e2 of the rod (the block's are ug, wg, eg);
  !      sv, sa = B's velocity and acceleration along the guide relative to it;
  !      st (st_assembly: the rod does not reach the guide), est.
  pure subroutine rrp_kernel(level, xa, va, aa, xk, vk, ak, ug, wg, eg, l2, rl2, off, branch, &
                        xb, vb, ab, u2, w2, e2, sv, sa, st, est)
    integer, intent(in) :: level
    real(dp), intent(in) :: xa(2), va(2), aa(2), xk(2), vk(2), ak(2), ug(2), wg, eg
    real(dp), intent(in) :: l2, rl2, off, branch
    real(dp), intent(out) :: xb(2), vb(2), ab(2), u2(2), w2, e2, sv, sa, est
    integer, intent(out) :: st
    real(dp) :: sl, rk(2), vg(2), ag(2), ev, dang
    type(cram) :: f
    call rrp_position(xa, xk, ug, l2, off, branch, xb, u2, sl, st, est)
    if (level < 2 .or. failed(st)) return
    dang = est + 4.0_dp*uround                   ! the error of the systems' directions
    ! the guide's point under B (B - K = sl ug + off n, formed from local quantities)
    rk = sl*ug + off*[-ug(2), ug(1)]
    vg = vk + wg*[-rk(2), rk(1)]
    call rrp_system(u2, ug, f)
    call rrp_velocity(f, va, vg, ug, rl2, dang, vb, w2, sv, ev, st, est)
    if (level < 3 .or. failed(st)) return
    ! its acceleration plus the Coriolis term 2 wg s' k x ug (known to 2 |wg| ev)
    ag = ak + eg*[-rk(2), rk(1)] - wg**2*rk + (2.0_dp*wg*sv)*[-ug(2), ug(1)]
    ! (the entries' error taken as the estimate so far, the velocities' included, as
    ! before the stages: the Mechanism's statuses as the promise tests pin them)
    call rrp_acceleration(f, aa, ag, 2.0_dp*abs(wg)*ev, u2, ug, l2, rl2, w2, ev, &
                          est + 4.0_dp*uround, ab, e2, sa, st, est)
  end subroutine rrp_kernel

  ! RRP positions: B on the guide (through K, direction ug) at off along its left normal
  ! n, at l2 from A.  B - A = branch root ug - perp n is formed from the quantities
  ! relative to A and K, then B = A + (B - A): far from the origin B - A keeps its digits.
  ! Out: xb; u2 = (B - A)/l2; sl = (B - K).ug, the slider's place on the guide (B - K =
  ! sl ug + off n); st (st_assembly); est, the direction's sensitivity (unit-free).
  pure subroutine rrp_position(xa, xk, ug, l2, off, branch, xb, u2, sl, st, est)
    real(dp), intent(in) :: xa(2), xk(2), ug(2), l2, off, branch
    real(dp), intent(out) :: xb(2), u2(2), sl, est
    integer, intent(out) :: st
    real(dp) :: nn(2), wv(2), along, perp, cq, sq, root, dc
    nn = [-ug(2), ug(1)]
    wv = xa - xk
    along = wv(1)*ug(1) + wv(2)*ug(2)
    perp = wv(1)*nn(1) + wv(2)*nn(2) - off
    cq = perp/l2
    est = 0.0_dp
    if (abs(cq) > 1.0_dp) then
      if (abs(cq) - 1.0_dp > 8.0_dp*epsilon(1.0_dp)) then
        st = st_assembly
        return
      end if
      cq = sign(1.0_dp, cq)
    end if
    sq = sqrt((1.0_dp - cq)*(1.0_dp + cq))
    root = l2*sq
    sl = along + branch*root
    xb = xa + ((branch*root)*ug - perp*nn)
    u2 = (branch*sq)*ug - cq*nn
    dc = 4.0_dp*uround*(abs(perp) + abs(off) + l2 + abs(wv(1)) + abs(wv(2)))/l2
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
  end subroutine rrp_position

  ! The matrix of the RRP's velocity and acceleration systems: the columns are the unit
  ! vectors k x u2 (the rod turning; unknown w l2, a velocity) and -ug (the sliding), so
  ! that the unknowns are of one kind and in range wherever the answer is (a mechanism of
  ! 2**600 m or 2**-990 m), and the estimate is unit-free.
  pure subroutine rrp_system(u2, ug, f)
    real(dp), intent(in) :: u2(2), ug(2)
    type(cram), intent(out) :: f
    call cramer_set(-u2(2), -ug(1), u2(1), -ug(2), f, 1.0_dp, 1.0_dp)
  end subroutine rrp_system

  ! RRP velocities: v_A + (w2 l2) k x u2 = v_G + s' ug, v_G the velocity of the guide's
  ! point under B.  In: f (rrp_system), va, vg, ug, rl2 = 1/l2; dang = the error of the
  ! matrix's directions (radians: the position's estimate and their rounding); est = the
  ! estimate so far.  Out: vb = v_G + s' ug (from the guide's side: along a fixed guide
  ! exactly); w2, sv = s'; ev = the absolute error of (w2 l2, s'); st; est, the larger of
  ! est and the system's.
  pure subroutine rrp_velocity(f, va, vg, ug, rl2, dang, vb, w2, sv, ev, st, est)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: va(2), vg(2), ug(2), rl2, dang
    real(dp), intent(out) :: vb(2), w2, sv, ev
    integer, intent(out) :: st
    real(dp), intent(inout) :: est
    real(dp) :: y1, y2, sb, rel
    sb = abs(va(1)) + abs(va(2)) + abs(vg(1)) + abs(vg(2))
    call cramer(f, vg(1) - va(1), vg(2) - va(2), dang, 4.0_dp*uround*sb, sb, &
                y1, y2, st, rel)
    if (failed(st)) return
    est = max(est, rel)
    w2 = y1*rl2
    sv = y2
    vb = vg + sv*ug
    ev = abs_err(f, y1, y2, sb, rel)
  end subroutine rrp_velocity

  ! RRP accelerations: a_A + (e2 l2) k x u2 - w2**2 l2 u2 = a_G + s'' ug, a_G the
  ! acceleration of the guide's point under B plus the Coriolis term (2 wg s' k x ug),
  ! known to dag (absolute).  In: f (rrp_system), aa, ag, dag, u2, ug, l2, rl2, w2 and ev
  ! (rrp_velocity's: the velocities' error enters through w2**2 l2), dang, est.  Out: ab =
  ! a_G + s'' ug (the guide's side); e2, sa = s''; st; est.
  pure subroutine rrp_acceleration(f, aa, ag, dag, u2, ug, l2, rl2, w2, ev, dang, ab, e2, sa, &
                                   st, est)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: aa(2), ag(2), dag, u2(2), ug(2), l2, rl2, w2, ev, dang
    real(dp), intent(out) :: ab(2), e2, sa
    integer, intent(out) :: st
    real(dp), intent(inout) :: est
    real(dp) :: an, y1, y2, sb, rel
    an = w2**2*l2
    sb = abs(aa(1)) + abs(aa(2)) + abs(ag(1)) + abs(ag(2)) + an
    call cramer(f, ag(1) - aa(1) + an*u2(1), ag(2) - aa(2) + an*u2(2), dang, &
                4.0_dp*uround*sb + ev*(2.0_dp*abs(w2) + ev*rl2) + dag, sb, y1, y2, st, rel)
    if (failed(st)) return
    est = max(est, rel)
    e2 = y1*rl2
    sa = y2
    ab = ag + sa*ug
  end subroutine rrp_acceleration

  ! Kind 3, RPR (DPRM3/DKNMA3): a slider (link 2) pivoted at A slides along link 3, which
  ! turns about C; A is at h from link 3's axis.  B = the foot of the perpendicular from A
  ! on the axis (a point of the slider; Thales: on the circle over AC).  The kernel runs
  ! the stages rpr_position, rpr_velocity, rpr_acceleration; the book's DPRM3, DSKOR3,
  ! DUSKR3, DKNMA3 (corrected mode) call them.
  ! In:  level; xa, va, aa = A; xc, vc, ac = C; h (its modulus is used); branch = +1: B on
  !      the left of the line A->C, -1 on its right.
  ! Out: xb, vb, ab = B; u3 = (B - C)/|B - C|, w3, e3 of link 3 (and of the slider);
  !      sv, sa = the sliding velocity and acceleration along u3 (d|CB|/dt, ...);
  !      st (st_singular: A = C, or B = C at a velocity level; st_assembly: h > |AC|),
  !      est.
  pure subroutine rpr_kernel(level, xa, va, aa, xc, vc, ac, h, branch, xb, vb, ab, u3, w3, e3, &
                        sv, sa, st, est)
    integer, intent(in) :: level
    real(dp), intent(in) :: xa(2), va(2), aa(2), xc(2), vc(2), ac(2), h, branch
    real(dp), intent(out) :: xb(2), vb(2), ab(2), u3(2), w3, e3, sv, sa, est
    integer, intent(out) :: st
    real(dp) :: uc(2), d, sl, eac, ev, dang
    type(cram) :: f
    call rpr_position(xa, xc, h, branch, xb, u3, uc, d, sl, eac, st, est)
    if (level < 2 .or. failed(st)) return
    dang = est + 4.0_dp*uround                   ! the error of the systems' directions
    call rpr_system(uc, u3, f)
    call rpr_velocity(f, va, vc, u3, d, sl, dang, vb, w3, sv, ev, st, est)
    if (level < 3 .or. failed(st)) return
    ! the Coriolis term 2 w3 s' k x u3, known to 2 (|w3| ev + |s'| ev/d); the entries'
    ! error as rrp_kernel's
    call rpr_acceleration(f, aa, ac, (2.0_dp*w3*sv)*[-u3(2), u3(1)], &
                          2.0_dp*(abs(w3)*ev + abs(sv)*(ev/d)), uc, u3, d, sl, w3, ev, eac, &
                          est + 4.0_dp*uround, ab, e3, sa, st, est)
  end subroutine rpr_kernel

  ! RPR positions.  B - A = h sq uac + branch h cq n (uac = (C - A)/d, n its left normal,
  ! sq = h/d, cq = sqrt(1 - sq**2)); the axis u3 = (B - C)/|B - C| = -cq uac + branch sq n
  ! from the triangle, not from the difference B - C (which loses digits far from the
  ! origin).  Out: xb; u3; uc = (A - C)/d; d = |AC|; sl = |CB|; eac = the rounding of A - C
  ! carried from the coordinates (absolute, uround (|A| + |C|)); st; est.
  pure subroutine rpr_position(xa, xc, h, branch, xb, u3, uc, d, sl, eac, st, est)
    real(dp), intent(in) :: xa(2), xc(2), h, branch
    real(dp), intent(out) :: xb(2), u3(2), uc(2), d, sl, eac, est
    integer, intent(out) :: st
    real(dp) :: dx, dy, hh, sq, cq, u(2), nn(2), ds, sx
    hh = abs(h)
    dx = xc(1) - xa(1)
    dy = xc(2) - xa(2)
    d = norm2e(dx, dy)
    est = 0.0_dp
    if (d == 0.0_dp) then
      st = st_singular
      return
    end if
    sq = hh/d
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
    xb = xa + ((hh*sq)*u + (branch*hh*cq)*nn)     ! Thales: on the circle over AC
    sl = d*cq                                    ! |B - C|
    ! the axis, defined at B = C too (h = d: it is square to AC there; the velocity
    ! system is then singular: k x uc and u3 are parallel)
    u3 = (branch*sq)*nn - cq*u
    uc = -u
    ds = 4.0_dp*uround*(1.0_dp + sq)
    est = angle_sensitivity(sq, ds)
    ! A - C carries the rounding of the coordinates it is the difference of (far from the
    ! origin more than d's own): its direction, link 3's, moves by about u sx/d, and the
    ! accelerations' term w3**2 (A - C) by w3**2 u sx
    sx = abs(xa(1)) + abs(xa(2)) + abs(xc(1)) + abs(xc(2))
    eac = uround*sx
    if (sx > d) est = est + uround*(sx/d)
    st = st_ok
  end subroutine rpr_position

  ! |(x, y)| as prmtr's norm2d (sqrt(x**2 + y**2) between 1e-150 and 1e150), and beyond
  ! it the same formula on (x, y) scaled by a power of 2: the same bits times 2**k for a
  ! vector times 2**k (norm2d's hypot is not), so that a mechanism scaled by 2**k
  ! solves to the same bits times 2**k at any k.
  pure real(dp) function norm2e(x, y)
    real(dp), intent(in) :: x, y
    real(dp) :: m
    integer :: e
    m = max(abs(x), abs(y))
    if (m > 1.0e-150_dp .and. m < 1.0e150_dp) then
      norm2e = sqrt(x*x + y*y)
    else if (m == 0.0_dp .or. .not. m <= huge(m)) then
      norm2e = m
    else
      e = exponent(m)
      norm2e = scale(sqrt(scale(x, -e)**2 + scale(y, -e)**2), e)
    end if
  end function norm2e

  ! The matrix of the RPR's velocity and acceleration systems: the unit columns k x uc
  ! (link 3 turning; unknown w3 d) and u3 (the sliding).
  pure subroutine rpr_system(uc, u3, f)
    real(dp), intent(in) :: uc(2), u3(2)
    type(cram), intent(out) :: f
    call cramer_set(-uc(2), u3(1), uc(1), u3(2), f, 1.0_dp, 1.0_dp)
  end subroutine rpr_system

  ! RPR velocities: v_A = v_C + (w3 d) k x uc + s' u3.  In: f (rpr_system), va, vc, u3,
  ! d, sl (rpr_position's), dang (as rrp_velocity's), est.  Out: vb (B's, of link 3's
  ! point at B plus the sliding), w3, sv = s'; ev = the absolute error of (w3 d, s'); st;
  ! est.
  pure subroutine rpr_velocity(f, va, vc, u3, d, sl, dang, vb, w3, sv, ev, st, est)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: va(2), vc(2), u3(2), d, sl, dang
    real(dp), intent(out) :: vb(2), w3, sv, ev
    integer, intent(out) :: st
    real(dp), intent(inout) :: est
    real(dp) :: y1, y2, sb, rel
    sb = abs(va(1)) + abs(va(2)) + abs(vc(1)) + abs(vc(2))
    call cramer(f, va(1) - vc(1), va(2) - vc(2), dang, 4.0_dp*uround*sb, sb, &
                y1, y2, st, rel)
    if (failed(st)) return
    est = max(est, rel)
    w3 = y1/d
    sv = y2
    vb = vc + (w3*sl)*[-u3(2), u3(1)] + sv*u3
    ev = abs_err(f, y1, y2, sb, rel)
  end subroutine rpr_velocity

  ! RPR accelerations: a_A = a_C + (e3 d) k x uc - w3**2 d uc + a_k + s'' u3, a_k the
  ! Coriolis term (2 w3 s' k x u3), known to dak.  In: f, aa, ac, ak, dak, uc, u3, d, sl,
  ! w3, ev (rpr_velocity's), eac (rpr_position's), dang, est.  Out: ab, e3, sa = s''; st;
  ! est.
  pure subroutine rpr_acceleration(f, aa, ac, ak, dak, uc, u3, d, sl, w3, ev, eac, dang, ab, &
                                   e3, sa, st, est)
    type(cram), intent(in) :: f
    real(dp), intent(in) :: aa(2), ac(2), ak(2), dak, uc(2), u3(2), d, sl, w3, ev, eac, dang
    real(dp), intent(out) :: ab(2), e3, sa
    integer, intent(out) :: st
    real(dp), intent(inout) :: est
    real(dp) :: an, y1, y2, sb, rel, ew
    an = w3**2*d
    sb = abs(aa(1)) + abs(aa(2)) + abs(ac(1)) + abs(ac(2)) + an + abs(ak(1)) + abs(ak(2))
    ew = ev/d                                    ! the error of w3
    call cramer(f, aa(1) - ac(1) + an*uc(1) - ak(1), aa(2) - ac(2) + an*uc(2) - ak(2), &
                dang, 4.0_dp*uround*sb + w3**2*eac &
                + ev*(2.0_dp*abs(w3) + ew) + dak, sb, y1, y2, st, rel)
    if (failed(st)) return
    est = max(est, rel)
    e3 = y1/d
    sa = y2
    ab = ac + (e3*sl)*[-u3(2), u3(1)] - (w3**2*sl)*u3 + sa*u3 + ak
  end subroutine rpr_acceleration

  ! Kind 4, PRP (DPRM4/DKNMA4): the joint B of two sliders, slider 2 on guide M through A,
  ! slider 3 on guide N through C; B at offm, offn from the guides' axes along their
  ! left normals.  One position.
  ! In:  level; guide M: xa, va, aa = its point A, um its direction, wm, em its link's
  !      motion, offm; guide N: xc, vc, ac, un, wn, en, offn.
  ! Out: xb, vb, ab = B (links 2, 3 turn with the guides: um, wm, em and un, wn, en);
  !      svm, svn = B's velocities along um, un relative to the guides, sam, san its
  !      accelerations (along um and un: the solve's unknowns); st (st_singular: parallel
  !      guides), est.
  ! The kernel calls its three stages in order (prp_position, prp_velocity,
  ! prp_acceleration); DPRM4 is an adapter over the kernel's position, DSKOR4 and DUSKR4
  ! over the velocity and acceleration stages, DKNMA4 over the kernel.
  subroutine prp_kernel(level, xa, va, aa, um, wm, em, offm, xc, vc, ac, un, wn, en, offn, &
                        xb, vb, ab, svm, svn, sam, san, st, est)
    integer, intent(in) :: level
    real(dp), intent(in) :: xa(2), va(2), aa(2), um(2), wm, em, offm
    real(dp), intent(in) :: xc(2), vc(2), ac(2), un(2), wn, en, offn
    real(dp), intent(out) :: xb(2), vb(2), ab(2), svm, svn, sam, san, est
    integer, intent(out) :: st
    real(dp) :: rb(2), sp, sx, sbv, relv, exb, kcm(2), kcn(2), est1
    type(cram) :: f
    call prp_position(xa, um, offm, xc, un, offn, xb, rb, sp, sx, st, est)
    if (failed(st)) return
    if (level < 2) return
    est1 = est
    call prp_velocity(xa, va, um, wm, xc, vc, un, wn, xb, rb, sp, sx, est1, &
                      vb, svm, svn, f, sbv, relv, exb, st, est)
    if (failed(st)) return
    if (level < 3) return
    est1 = est
    ! the Coriolis accelerations 2 w k x (s' u) of B relative to the guides
    kcm = 2.0_dp*wm*svm*[-um(2), um(1)]
    kcn = 2.0_dp*wn*svn*[-un(2), un(1)]
    call prp_acceleration(xa, aa, um, wm, em, xc, ac, un, wn, en, xb, svm, svn, kcm, kcn, &
                          2.0_dp*(abs(wn*svn) + abs(wm*svm)), f, sbv, relv, exb, sx, est1, &
                          ab, sam, san, st, est)
  end subroutine prp_kernel

  ! Kind 4, stage 1: B on both guides' offset lines.
  ! In:  xa, um, offm (guide M); xc, un, offn (guide N).
  ! Out: xb; rb = B - A as solved (B's offset from A, before A is added); sp = the
  !      group's size (the offsets and |C - A|), sx = the coordinates' size beyond it (for
  !      the rounding of points far from the origin); st (st_singular: parallel guides),
  !      est (relative to max(|B - A|, sp/sqrt(2))).
  subroutine prp_position(xa, um, offm, xc, un, offn, xb, rb, sp, sx, st, est)
    real(dp), intent(in) :: xa(2), um(2), offm, xc(2), un(2), offn
    real(dp), intent(out) :: xb(2), rb(2), sp, sx, est
    integer, intent(out) :: st
    real(dp) :: nm_(2), nn(2), dca(2)
    nm_ = [-um(2), um(1)]
    nn = [-un(2), un(1)]
    dca = xc - xa
    ! nM . (B - A) = offM,  nN . (B - A) = offN + nN . (C - A)
    sp = abs(offm) + abs(offn) + abs(dca(1)) + abs(dca(2))
    ! C - A carries the rounding of the coordinates it is the difference of (far from the
    ! origin more than its own), and so do B - A, B - C in the velocities below: u sx,
    ! sx = the coordinates' size beyond the group's (as rrr_kernel widens its estimate)
    sx = max(0.0_dp, abs(xa(1)) + abs(xa(2)) + abs(xc(1)) + abs(xc(2)) - sp)
    call solve2e(nm_(1), nm_(2), nn(1), nn(2), offm, offn + nn(1)*dca(1) + nn(2)*dca(2), &
                 4.0_dp*uround, 4.0_dp*uround*sp + 2.0_dp*uround*sx, sp, rb(1), rb(2), st, est)
    if (failed(st)) return
    xb = xa + rb
  end subroutine prp_position

  ! Kind 4's velocity (and acceleration) system: B's motion along the guides, columns um
  ! and -un (unit vectors, exact to rounding whatever B's error).
  pure subroutine prp_matrix(um, un, f)
    real(dp), intent(in) :: um(2), un(2)
    type(cram), intent(out) :: f
    call cramer_set(um(1), -un(1), um(2), -un(2), f, 1.0_dp, 1.0_dp)
  end subroutine prp_matrix

  ! Kind 4, stage 2: v_GM(B) + svm um = v_GN(B) + svn un, v_G the guide links' points
  ! under B.
  ! In:  xa, va, um, wm (guide M); xc, vc, un, wn (guide N); xb and rb, sp, sx, estp from
  !      prp_position (given positions: rb anything, sp = sx = estp = 0).
  ! Out: vb = B's velocity (vb = v_GM(B) + svm um); svm, svn; for prp_acceleration: f
  !      (the system), sbv (the size of its right-hand side's terms), relv (its relative
  !      error), exb (B's absolute error); st, est (the largest of estp and relv).
  pure subroutine prp_velocity(xa, va, um, wm, xc, vc, un, wn, xb, rb, sp, sx, estp, &
                               vb, svm, svn, f, sbv, relv, exb, st, est)
    real(dp), intent(in) :: xa(2), va(2), um(2), wm, xc(2), vc(2), un(2), wn, xb(2), rb(2)
    real(dp), intent(in) :: sp, sx, estp
    real(dp), intent(out) :: vb(2), svm, svn, sbv, relv, exb, est
    type(cram), intent(out) :: f
    integer, intent(out) :: st
    real(dp) :: r(2), vgm(2), vgn(2)
    ! B's absolute error (solve2e's est is relative to max(|B - A|, sp/|A|_F), |A|_F =
    ! sqrt(2) for unit vectors)
    exb = estp*max(norm2d(rb(1), rb(2)), sp/sqrt(2.0_dp))
    r = xb - xa                                   ! (carried's velocities)
    vgm = va + wm*[-r(2), r(1)]
    r = xb - xc
    vgn = vc + wn*[-r(2), r(1)]
    ! the matrix is the guides' directions, exact to rounding whatever B's error (4u);
    ! B's error enters the right-hand side as (wN - wM) k x dB, the coordinates' rounding
    ! through B - A and B - C
    call prp_matrix(um, un, f)
    ! the size of the terms vG = v + w k x (B - P) (their sum may cancel: B at rest)
    sbv = abs(va(1)) + abs(va(2)) + abs(vc(1)) + abs(vc(2)) &
          + abs(wm)*(abs(xb(1) - xa(1)) + abs(xb(2) - xa(2))) &
          + abs(wn)*(abs(xb(1) - xc(1)) + abs(xb(2) - xc(2)))
    call cramer(f, vgn(1) - vgm(1), vgn(2) - vgm(2), 4.0_dp*uround, &
                4.0_dp*uround*sbv + abs(wn - wm)*exb + 2.0_dp*uround*(abs(wm) + abs(wn))*sx, &
                sbv, svm, svn, st, relv)
    est = estp
    if (failed(st)) return
    est = max(estp, relv)
    vb = vgm + svm*um
  end subroutine prp_velocity

  ! Kind 4, stage 3: a_GM(B) + kcm + sam um = a_GN(B) + kcn + san un, kcm, kcn the
  ! Coriolis accelerations 2 w k x (s' u) of B relative to the guides.
  ! In:  xa, aa, um, wm, em (guide M); xc, ac, un, wn, en (guide N); xb; svm, svn (for
  !      the error estimate), kcm, kcn and sk (the size of the Coriolis terms); f, sbv,
  !      relv, exb from prp_velocity and sx from prp_position (given velocities: relv =
  !      exb = sx = 0), estv.
  ! Out: ab = a_GM(B) + kcm + sam um; sam, san; st, est (the largest of estv and this
  !      system's).
  pure subroutine prp_acceleration(xa, aa, um, wm, em, xc, ac, un, wn, en, xb, svm, svn, &
                                   kcm, kcn, sk, f, sbv, relv, exb, sx, estv, &
                                   ab, sam, san, st, est)
    real(dp), intent(in) :: xa(2), aa(2), um(2), wm, em, xc(2), ac(2), un(2), wn, en, xb(2)
    real(dp), intent(in) :: svm, svn, kcm(2), kcn(2), sk, sbv, relv, exb, sx, estv
    type(cram), intent(in) :: f
    real(dp), intent(out) :: ab(2), sam, san, est
    integer, intent(out) :: st
    real(dp) :: r(2), agm(2), agn(2), ev, sb, rel
    ev = abs_err(f, svm, svn, sbv, relv)
    r = xb - xa                                   ! (carried's accelerations)
    agm = aa + em*[-r(2), r(1)] - wm**2*r
    r = xb - xc
    agn = ac + en*[-r(2), r(1)] - wn**2*r
    sb = abs(aa(1)) + abs(aa(2)) + abs(ac(1)) + abs(ac(2)) &
         + (abs(em) + wm**2)*(abs(xb(1) - xa(1)) + abs(xb(2) - xa(2))) &
         + (abs(en) + wn**2)*(abs(xb(1) - xc(1)) + abs(xb(2) - xc(2))) + sk
    call cramer(f, agn(1) + kcn(1) - agm(1) - kcm(1), agn(2) + kcn(2) - agm(2) - kcm(2), &
                4.0_dp*uround, 4.0_dp*uround*sb + 2.0_dp*(abs(wn) + abs(wm))*ev &
                + (abs(en - em) + abs(wn**2 - wm**2))*exb &
                + 2.0_dp*uround*(abs(em) + abs(en) + wm**2 + wn**2)*sx, sb, sam, san, st, rel)
    est = estv
    if (failed(st)) return
    est = max(estv, rel)
    ab = agm + sam*um + kcm
  end subroutine prp_acceleration

  ! Kind 5, RPP (DPRM5/DKNMA5): link 2 slides on guide M through A; a block (link 3)
  ! pivoted at C slides in link 2's slot, whose direction is um turned by t2.  K = where
  ! the slot's axis meets the guide's axis (a point of link 2).  One position.
  ! In:  level; guide M: xa, va, aa = its point A, um its direction, wm, em its link's
  !      motion; t2 = the slot's angle to the guide and ct2, st2 its cosine and sine
  !      (the caller's, computed once); xc, vc, ac = C.
  ! Out: xk, vk, ak = K; us = the slot's direction (links 2, 3 turn with the guide: um,
  !      wm, em); sk = |AK| along um and sc = |KC| along us (C - A = sk um + sc us), svk,
  !      svc their rates, sak, sac their second rates (relative to the guide);
  !      st (st_singular: the slot parallel to the guide), est.  A small t2 keeps its
  !      digits (numerics' solve_kind5, in the guide's frame).
  ! The kernel calls its three stages in order (rpp_position, rpp_velocity,
  ! rpp_acceleration); DPRM5 is an adapter over the kernel's position, DSKOR5 and DUSKR5
  ! over the velocity and acceleration stages, DKNMA5 over the kernel.
  pure subroutine rpp_kernel(level, xa, va, aa, um, wm, em, t2, ct2, st2, xc, vc, ac, &
                        xk, vk, ak, us, sk, sc, svk, svc, sak, sac, st, est)
    integer, intent(in) :: level
    real(dp), intent(in) :: xa(2), va(2), aa(2), um(2), wm, em, t2, ct2, st2
    real(dp), intent(in) :: xc(2), vc(2), ac(2)
    real(dp), intent(out) :: xk(2), vk(2), ak(2), us(2), sk, sc, svk, svc, sak, sac, est
    integer, intent(out) :: st
    real(dp) :: sp, sx, estp, vr(2), rc(2), rk(2), sbv, relv, estv
    call rpp_position(xa, um, t2, ct2, st2, xc, xk, us, sk, sc, sp, sx, st, est)
    if (failed(st)) return
    if (level < 2) return
    estp = est
    call rpp_velocity(xa, va, um, wm, t2, xc, vc, xk, sx, estp, vk, svk, svc, vr, rc, rk, &
                      sbv, relv, st, est)
    if (failed(st)) return
    if (level < 3) return
    estv = est
    ! the Coriolis term 2 w (s2' nm + s3' ns) is 2 w k x vr: computed so, it is known to
    ! rounding, where s2', s3' each grow as 1/t2 and cancel
    call rpp_acceleration(aa, um, wm, em, t2, ac, rc, rk, svk, &
                          2.0_dp*wm*[-vr(2), vr(1)], 2.0_dp*abs(wm)*(abs(vr(1)) + abs(vr(2))), &
                          sk, sc, sp, sx, estp, svk, svc, sbv, relv, estv, ak, sak, sac, st, est)
  end subroutine rpp_kernel

  ! Kind 5, stage 1: C - A = sk um + sc us.
  ! In:  xa, um (guide M); t2, ct2, st2 (the slot); xc.
  ! Out: xk = A + sk um; us; sk, sc; sp = |C - A| (1-norm), sx = the coordinates' size
  !      beyond it; st (st_singular: the slot parallel to the guide), est.
  pure subroutine rpp_position(xa, um, t2, ct2, st2, xc, xk, us, sk, sc, sp, sx, st, est)
    real(dp), intent(in) :: xa(2), um(2), t2, ct2, st2, xc(2)
    real(dp), intent(out) :: xk(2), us(2), sk, sc, sp, sx, est
    integer, intent(out) :: st
    real(dp) :: dca(2)
    us = [um(1)*ct2 - um(2)*st2, um(2)*ct2 + um(1)*st2]
    dca = xc - xa
    sp = abs(dca(1)) + abs(dca(2))
    ! C - A carries the rounding of the coordinates far from the origin (as prp_kernel):
    ! u sx, sx = their size beyond the group's; C - A again in the velocities below
    sx = max(0.0_dp, abs(xa(1)) + abs(xa(2)) + abs(xc(1)) + abs(xc(2)) - sp)
    ! sk um + sc us = C - A, solved in the frame of the guide (DPRM5's solve_kind5: a
    ! small T2 keeps its digits)
    call kind5(t2, um, dca, 4.0_dp*uround*sp + 2.0_dp*uround*sx, sp, sk, sc, st, est)
    if (failed(st)) return
    xk = xa + sk*um
  end subroutine rpp_position

  ! Kind 5, stage 2: C's velocity relative to guide M's link, vr = vc - v_GM(C) =
  ! svk um + svc us.
  ! In:  xa, va, um, wm (guide M); t2; xc, vc; xk, sx, estp from rpp_position (given
  !      positions: xk anything, sx = estp = 0).
  ! Out: vk = K's velocity (a point of link 2); svk, svc; vr; for rpp_acceleration rc =
  !      C - A, rk = K - A, sbv (the size of vr's terms) and relv (svk's, svc's relative
  !      error, the position's added); st, est.
  pure subroutine rpp_velocity(xa, va, um, wm, t2, xc, vc, xk, sx, estp, vk, svk, svc, vr, &
                               rc, rk, sbv, relv, st, est)
    real(dp), intent(in) :: xa(2), va(2), um(2), wm, t2, xc(2), vc(2), xk(2), sx, estp
    real(dp), intent(out) :: vk(2), svk, svc, vr(2), rc(2), rk(2), sbv, relv, est
    integer, intent(out) :: st
    real(dp) :: vgc(2)
    rc = xc - xa                                  ! (carried's velocities)
    rk = xk - xa
    vgc = va + wm*[-rc(2), rc(1)]
    vr = vc - vgc
    sbv = abs(vc(1)) + abs(vc(2)) + abs(vgc(1)) + abs(vgc(2))
    call kind5(t2, um, vr, 4.0_dp*uround*sbv + 2.0_dp*uround*abs(wm)*sx, sbv, svk, svc, &
               st, relv)
    est = estp
    if (failed(st)) return
    relv = relv + estp                    ! the position's error moves K's velocity
    est = max(estp, relv)
    vk = (va + wm*[-rk(2), rk(1)]) + svk*um
  end subroutine rpp_velocity

  ! Kind 5, stage 3: C's acceleration relative to guide M's link, ac - a_GM(C) - kd =
  ! sak um + sac us, kd the Coriolis term 2 w k x vr.
  ! In:  aa, um, wm, em (guide M: A's acceleration); t2; ac; rc = C - A, rk = K - A (from
  !      rpp_velocity), dk (K's rate svk, for K's acceleration); kd and ks (the size of
  !      its terms); for the error estimate sk, sc, sp, sx, estp from rpp_position and
  !      svk, svc, sbv, relv from rpp_velocity (given positions and velocities: all 0);
  !      estv.
  ! Out: ak = K's acceleration; sak, sac; st, est.
  pure subroutine rpp_acceleration(aa, um, wm, em, t2, ac, rc, rk, dk, kd, ks, &
                                   sk, sc, sp, sx, estp, svk, svc, sbv, relv, estv, &
                                   ak, sak, sac, st, est)
    real(dp), intent(in) :: aa(2), um(2), wm, em, t2, ac(2), rc(2), rk(2), dk
    real(dp), intent(in) :: kd(2), ks, sk, sc, sp, sx, estp, svk, svc, sbv, relv, estv
    real(dp), intent(out) :: ak(2), sak, sac, est
    integer, intent(out) :: st
    real(dp) :: agc(2), agk(2), ar(2), sb, rel, ex, ev, eg
    ex = estp*max(norm2d(sk, sc), sp)      ! K's absolute error along the guide
    ev = relv*max(norm2d(svk, svc), sbv)
    agc = aa + em*[-rc(2), rc(1)] - wm**2*rc     ! (carried's accelerations)
    agk = aa + em*[-rk(2), rk(1)] - wm**2*rk
    ar = ac - agc - kd
    sb = abs(ac(1)) + abs(ac(2)) + abs(agc(1)) + abs(agc(2)) + ks
    call kind5(t2, um, ar, 4.0_dp*uround*sb + 2.0_dp*uround*(abs(em) + wm**2)*sx, sb, &
               sak, sac, st, rel)
    est = estv
    if (failed(st)) return
    ! K's acceleration agk + s2'' um + 2 w s2' nm: the errors of s2' and of K, relative
    ! to the size of its terms
    ! (none when they are 0: the group may be at rest, every term 0)
    eg = 2.0_dp*abs(wm)*ev + (abs(em) + wm**2)*ex
    if (eg > 0.0_dp) rel = rel + eg/max(norm2d(sak, sac), sb, &
                                        abs(agk(1)) + abs(agk(2)) + 2.0_dp*abs(wm*dk))
    est = max(estv, rel)
    ak = agk + sak*um + 2.0_dp*wm*dk*[-um(2), um(1)]
  end subroutine rpp_acceleration

  ! ym um + ys us = bb (us = um turned by t2) through numerics' solve_kind5, which solves
  ! y1 e(FIM+T2) - y2 e(FIM) = b in the guide's frame: ys = y1, ym = -y2.  A slot near
  ! +-pi is the same slot reversed: solved at t2 -+ pi (pi to twice double precision;
  ! t2 -+ pi_hi exact for pi/2 < |t2| <= 2 pi), ys negated: it keeps its digits as a
  ! small t2 does (solve_kind5 takes t2 as known to an ulp, 2u pi near pi)
  pure subroutine kind5(t2, um, bb, db, sbb, ym, ys, st5, rel5)
    real(dp), intent(in) :: t2, um(2), bb(2), db, sbb
    real(dp), intent(out) :: ym, ys, rel5
    integer, intent(out) :: st5
    real(dp), parameter :: pi_hi = 3.141592653589793_dp, pi_lo = 1.2246467991473532e-16_dp
    real(dp) :: z1, z2, tr, sgn, nm_(2)
    nm_ = [-um(2), um(1)]
    tr = t2
    sgn = 1.0_dp
    if (abs(t2) > 0.5_dp*pi_hi) then
      tr = (t2 - sign(pi_hi, t2)) - sign(pi_lo, t2)
      sgn = -1.0_dp
    end if
    call solve_kind5(tr, bb(1)*um(1) + bb(2)*um(2), bb(1)*nm_(1) + bb(2)*nm_(2), db, &
                     sbb, z1, z2, st5, rel5)
    ys = sgn*z1
    ym = -z2
  end subroutine kind5

  ! =====================================================================================
  ! The chapter 7 force step: a group's pair reactions from its links' loads
  ! =====================================================================================

  ! The reactions of a group's three pairs (the chapter 7 method, one position) from the
  ! loads of its two links: the six equilibrium equations (forces and moment of link 2,
  ! of link 3) in the pairs' unknowns.  Pair 1 acts between the outside and link 2,
  ! pair 2 between links 2 and 3, pair 3 between the outside and link 3.
  !   p(:, j)      the point of pair j (a revolute's centre; for a slider any point of
  !                its line: the couple is about it)
  !   ty(j)        pair_revolute or pair_slider
  !   u(:, j)      a slider's sliding direction, a unit vector (not read for a revolute)
  !   f2, m2, q2   link 2's load: its resultant (fx, fy), its moment about the point q2
  !   f3, m3, q3   the same for link 3
  !   r(:, j)      pair j's reaction (fx, fy, couple): pair 1's on link 2 (from the
  !                outside), pair 2's on link 3 (from link 2), pair 3's on link 3 (from
  !                the outside); a slider's force is normal to u, a revolute's couple 0
  !   st           st_ok; st_singular (the system has no unique solution: its
  !                determinant is 0 or so small that the solution overflows), st_range
  !                (a reaction is not a finite double); r is then 0
  ! Pair 1 drops out of one equation of link 2 (a revolute: the moments about its point;
  ! a slider: the forces along u1), pair 3 out of one of link 3: two equations in pair
  ! 2's two unknowns (a revolute: R = (z1, z2); a slider: R = z1 n2, n2 = u2 turned by
  ! +pi/2, and its couple C = z2), by Cramer's rule; then pairs 1 and 3 from the rest.
  pure subroutine group_reactions(p, ty, u, f2, m2, q2, f3, m3, q3, r, st)
    real(dp), intent(in) :: p(2, 3), u(2, 3), f2(2), m2, q2(2), f3(2), m3, q3(2)
    integer, intent(in) :: ty(3)
    real(dp), intent(out) :: r(3, 3)
    integer, intent(out) :: st
    real(dp) :: n2(2), a(2, 2), b(2), z(2), rr(2), c2, d(2), f(2)
    r = 0.0_dp
    n2 = [-u(2, 2), u(1, 2)]
    ! row 1: link 2 without pair 1
    if (ty(1) == pair_revolute) then
      d = p(:, 2) - p(:, 1)                    ! -(d x R) - C = -M2 (about p1)
      call coefficients(d(2), -d(1), -1.0_dp, ty(2), n2, a(1, 1), a(1, 2))
      b(1) = -moment(f2, m2, q2, p(:, 1))
    else                                       ! -R.u1 = -F2.u1
      call coefficients(-u(1, 1), -u(2, 1), 0.0_dp, ty(2), n2, a(1, 1), a(1, 2))
      b(1) = -(f2(1)*u(1, 1) + f2(2)*u(2, 1))
    end if
    ! row 2: link 3 without pair 3
    if (ty(3) == pair_revolute) then
      d = p(:, 2) - p(:, 3)                    ! d x R + C = -M3 (about p3)
      call coefficients(-d(2), d(1), 1.0_dp, ty(2), n2, a(2, 1), a(2, 2))
      b(2) = -moment(f3, m3, q3, p(:, 3))
    else                                       ! R.u3 = -F3.u3
      call coefficients(u(1, 3), u(2, 3), 0.0_dp, ty(2), n2, a(2, 1), a(2, 2))
      b(2) = -(f3(1)*u(1, 3) + f3(2)*u(2, 3))
    end if
    call cramer2(a, b, z, st)
    if (st /= st_ok) return
    if (ty(2) == pair_revolute) then
      rr = z
      c2 = 0.0_dp
    else
      rr = z(1)*n2
      c2 = z(2)
    end if
    r(:, 2) = [rr(1), rr(2), c2]
    ! pair 1: F2 + f1 - R = 0 (and, a slider, its couple from the moments about p1)
    f = rr - f2
    if (ty(1) == pair_revolute) then
      r(:, 1) = [f(1), f(2), 0.0_dp]
    else
      call normal(f, u(:, 1), r(:, 1))
      d = p(:, 2) - p(:, 1)
      r(3, 1) = -moment(f2, m2, q2, p(:, 1)) + (d(1)*rr(2) - d(2)*rr(1)) + c2
    end if
    ! pair 3: F3 + R + f3 = 0
    f = -rr - f3
    if (ty(3) == pair_revolute) then
      r(:, 3) = [f(1), f(2), 0.0_dp]
    else
      call normal(f, u(:, 3), r(:, 3))
      d = p(:, 2) - p(:, 3)
      r(3, 3) = -moment(f3, m3, q3, p(:, 3)) - (d(1)*rr(2) - d(2)*rr(1)) - c2
    end if
    if (.not. all(abs(r) <= huge(1.0_dp))) then
      r = 0.0_dp
      st = st_range
    end if
  end subroutine group_reactions

  ! The coefficients of pair 2's unknowns in one equation: (cx, cy) multiply R (a
  ! revolute's two unknowns; a slider's N through R = N n2), cc its couple C.
  pure subroutine coefficients(cx, cy, cc, t2, n2, c1, c2)
    real(dp), intent(in) :: cx, cy, cc, n2(2)
    integer, intent(in) :: t2
    real(dp), intent(out) :: c1, c2
    if (t2 == pair_revolute) then
      c1 = cx
      c2 = cy
    else
      c1 = cx*n2(1) + cy*n2(2)
      c2 = cc
    end if
  end subroutine coefficients

  ! A slider's reaction f: its normal part (the guide takes no force along u).
  pure subroutine normal(f, u, out)
    real(dp), intent(in) :: f(2), u(2)
    real(dp), intent(out) :: out(3)
    real(dp) :: nn
    nn = -f(1)*u(2) + f(2)*u(1)
    out = [-nn*u(2), nn*u(1), 0.0_dp]
  end subroutine normal

  ! The moment about the point c of a load: resultant f, moment m about the point q.
  pure real(dp) function moment(f, m, q, c)
    real(dp), intent(in) :: f(2), m, q(2), c(2)
    moment = m + (q(1) - c(1))*f(2) - (q(2) - c(2))*f(1)
  end function moment

  ! a z = b, 2x2, by Cramer's rule.  Entries far from 1 (a mechanism of 1e200 m or
  ! 1e-200 m) are first scaled by the power of 2 nearest their largest, exactly, so that
  ! the determinant neither overflows nor underflows.  st_singular: det = 0, or so small
  ! against the entries (|A|_F s**2/|det| > huge, s the largest entry) that no digit is
  ! left; st_range: z is not finite.  (The arithmetic of mechanism.f90's cramer_set and
  ! cramer, which solved this system before, with both column scales s.)
  pure subroutine cramer2(a, b, z, st)
    real(dp), intent(in) :: a(2, 2), b(2)
    real(dp), intent(out) :: z(2)
    integer, intent(out) :: st
    real(dp) :: s(2, 2), sc, det, rdet, na, t
    integer :: e
    z = 0.0_dp
    st = st_singular
    sc = max(abs(a(1, 1)), abs(a(1, 2)), abs(a(2, 1)), abs(a(2, 2)))
    if (.not. (sc > 0.0_dp .and. sc <= huge(sc))) sc = 1.0_dp
    e = 0
    if (sc > 2.0_dp**200 .or. sc < 2.0_dp**(-200)) e = exponent(sc)
    s = a
    if (e /= 0) then
      s = scale(a, -e)
      sc = scale(sc, -e)
    end if
    det = s(1, 1)*s(2, 2) - s(1, 2)*s(2, 1)
    if (det == 0.0_dp) return
    rdet = 1.0_dp/det
    ! na <= 2 (every entry / sc is at most 1): the norm is needed only near the limit
    t = abs(sc*(sc*rdet))
    if (.not. t <= huge(1.0_dp)/2) then
      na = sqrt((s(1, 1)/sc)**2 + (s(2, 1)/sc)**2 + (s(1, 2)/sc)**2 + (s(2, 2)/sc)**2)
      if (.not. na*t <= huge(1.0_dp)) return
    end if
    z(1) = (b(1)*s(2, 2) - s(1, 2)*b(2))*rdet
    z(2) = (s(1, 1)*b(2) - s(2, 1)*b(1))*rdet
    if (e /= 0) z = scale(z, -e)
    st = st_ok
    if (.not. (abs(z(1)) <= huge(z(1)) .and. abs(z(2)) <= huge(z(2)))) then
      z = 0.0_dp
      st = st_range
    end if
  end subroutine cramer2

end module groups
