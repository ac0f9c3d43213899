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
  use numerics, only: uround, bound2
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

contains

  ! =====================================================================================
  ! Kinematics: positions, velocities, accelerations, error estimates
  ! =====================================================================================

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
