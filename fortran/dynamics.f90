! dynamics.f90 -- chapter 8, dynamics of the machine (listings VIII.1-VIII.2, book lines
! L5935-6082): the steady-state law of motion of the reduction link in the integral
! (energy) form, DZKNDV, and the moment of inertia of a flywheel, DMHVK.
!
! Units (section 9.3): angles rad, omega rad/s, moments N*m, inertias kg*m^2, energy J.
! The tables span exactly one cycle of the reduction link, phi = 0 .. 2*pi, both ends
! included: M points, step H = 2*pi/(M - 1).
!
! ERRATA ids of this chapter: E-DZKNDV-<n>, E-DMHVK-<n>, listed in docs/ERRATA.md.
module dynamics
  use prmtr, only: dp, pi, printed_mode, st_ok, st_requirement
  use operators, only: dintgr, dfrncl
  implicit none
  private
  public :: dzkndv, dmhvk

contains

  ! Midrange (max + min)/2 of omega_k = sqrt(2 (e0 + asum_k)/j_k) minus w1, and its
  ! derivative with respect to e0 (d omega_k/d e0 = 1/(j_k omega_k); 0 where omega_k = 0,
  ! which only the bisection then uses).  e0 + asum >= 0.
  pure subroutine midrange_excess(e0, asum, j, w1, g, dg)
    real(dp), intent(in) :: e0, asum(:), j(:), w1
    real(dp), intent(out) :: g, dg
    real(dp) :: w(size(asum))
    integer :: kmax, kmin
    w = sqrt(max(2.0_dp*(e0 + asum)/j, 0.0_dp))
    kmax = maxloc(w, 1)
    kmin = minloc(w, 1)
    g = 0.5_dp*(w(kmax) + w(kmin)) - w1
    dg = 0.0_dp
    if (w(kmin) > 0.0_dp) dg = 0.5_dp*(1.0_dp/(j(kmax)*w(kmax)) + 1.0_dp/(j(kmin)*w(kmin)))
  end subroutine midrange_excess

  ! E0 such that omega_1 + omega_2 = 2 W (omega_i = sqrt(2 (E0 + a_i)/j_i)) in closed
  ! form: with omega_1 = W + d, omega_2 = W - d, j_1 omega_1**2 - j_2 omega_2**2 =
  ! 2 (a_1 - a_2) is (j1 - j2) d**2 + 2 W (j1 + j2) d + (j1 - j2) W**2 - 2 (a1 - a2) = 0,
  ! divided by j1 + j2 (so that the discriminant does not overflow), whose root that
  ! stays finite as j1 -> j2 is taken.  ok = .false.: no root with |d| <= W (both speeds
  ! real and >= 0).
  pure subroutine pair_energy(a1, j1, a2, j2, w, e0, ok)
    real(dp), intent(in) :: a1, j1, a2, j2, w
    real(dp), intent(out) :: e0
    logical, intent(out) :: ok
    real(dp) :: p1, p2, qa, da, qc, disc, d
    e0 = 0.0_dp
    p1 = j1/(j1 + j2)
    p2 = j2/(j1 + j2)
    qa = p1 - p2
    da = (a1 - a2)/(j1 + j2)
    qc = qa*w*w - 2.0_dp*da
    disc = 16.0_dp*w*w*p1*p2 + 8.0_dp*qa*da
    ok = disc >= 0.0_dp
    if (.not. ok) return
    d = -2.0_dp*qc/(2.0_dp*w + sqrt(disc))
    ok = abs(d) <= w
    e0 = 0.5_dp*((0.5_dp*j1*(w + d)**2 - a1) + (0.5_dp*j2*(w - d)**2 - a2))
  end subroutine pair_energy

  ! The constant E0 of the energy equation (ISC + ISPR_k) omega_k**2/2 = E0 + ASUM_k with
  ! (max omega + min omega)/2 = W1 (the book's mean), and omega = WPR; ok = .false. when
  ! no E0 gives real speeds (even the least, omega = 0 somewhere, gives a larger mean).
  ! The extremes of omega are where those of DEC are (exactly so for ISPR = 0): E0 in
  ! closed form from those two points, then one pass that computes WPR and checks that
  ! its extremes are there -- else again with WPR's extremes.  When the pair has no root
  ! or one below the least E0 = -min ASUM, the pass is made at that least E0: a mean
  ! above W1 there is a stall, else its extremes are tried next.  Newton's method inside
  ! a bracket if that does not settle in 8 passes.
  ! k1, k2: where DEC has its largest and smallest value; amin = min ASUM.
  subroutine steady_speeds(m, w1, isc, ispr, asum, k1, k2, amin, wpr, ok)
    integer, intent(in) :: m
    real(dp), intent(in) :: w1, isc, ispr(m), asum(m), amin
    integer, value :: k1, k2
    real(dp), intent(out) :: wpr(m)
    logical, intent(out) :: ok
    real(dp) :: lo, hi, mid, g, dg, e0, wmax, wmin
    real(dp), allocatable :: j(:)
    integer :: k, it
    logical :: root
    lo = -amin                                       ! the least E0: omega = 0 somewhere
    ok = .true.
    do it = 1, 8
      call pair_energy(asum(k1), isc + ispr(k1), asum(k2), isc + ispr(k2), w1, e0, root)
      if (.not. root) e0 = lo                        ! no root, or one below lo: look at
      e0 = max(e0, lo)                               ! lo, and retry at its extremes
      wmax = 0.0_dp
      wmin = huge(1.0_dp)
      do k = 1, m                                    ! the speeds and their extremes
        wpr(k) = sqrt(max(2.0_dp*(e0 + asum(k))/(isc + ispr(k)), 0.0_dp))
        wmax = max(wmax, wpr(k))
        wmin = min(wmin, wpr(k))
      end do
      if (e0 == lo .and. 0.5_dp*(wmax + wmin) > w1) then
        ok = .false.                                 ! even the least E0 gives more than W1
        return
      end if
      if (e0 > lo .and. wpr(k1) >= wmax .and. wpr(k2) <= wmin .and. &
          abs(0.5_dp*(wmax + wmin) - w1) <= 1e-12_dp*w1) return
      k1 = maxloc(wpr, 1)
      k2 = minloc(wpr, 1)
    end do
    ! Newton's method on the midrange, kept inside the bracket [lo, hi] (bisection when
    ! a step would leave it), to the last bit of E0
    allocate (j(m))
    j = isc + ispr
    call midrange_excess(lo, asum, j, w1, g, dg)
    if (g > 0.0_dp) then                             ! even then the mean exceeds W1
      ok = .false.
      return
    end if
    hi = lo + 2.0_dp*maxval(j)*w1**2                 ! omega >= 2*W1 everywhere
    e0 = hi
    do it = 1, 200
      call midrange_excess(e0, asum, j, w1, g, dg)
      if (g > 0.0_dp) then
        hi = e0
      else
        lo = e0
      end if
      if (g == 0.0_dp .or. .not. (hi - lo > 4.0_dp*epsilon(1.0_dp)*max(abs(lo), abs(hi)))) &
        exit
      mid = e0 - g/max(dg, tiny(1.0_dp))
      if (.not. (mid > lo .and. mid < hi)) mid = 0.5_dp*(lo + hi)
      if (abs(mid - e0) <= 4.0_dp*epsilon(1.0_dp)*abs(e0)) then
        e0 = mid
        exit
      end if
      e0 = mid
    end do
    wpr = sqrt(max(2.0_dp*(e0 + asum)/j, 0.0_dp))
  end subroutine steady_speeds

  ! VIII.1 DZKNDV, L5939-5990 (block diagram Fig. 70, eqs. (8.13)-(8.17)).
  ! Inputs: M points (ZM = M as a real, the book passes both), W1 = the mean angular
  ! velocity omega_sr = (omega_max + omega_min)/2 (L6044), ISC = the constant part J_c of
  ! the reduced moment of inertia, MPR(M) = the reduced moment of the forces (positive when
  ! it does positive work on the reduction link), ISPR(M) = the variable part J_v(phi).
  ! Outputs:
  !   AS   = the trapezoid integral of MPR from 0 (DINTGR, NOMER = 2), the work of MPR;
  !   ASUM = AS - (K-1)*AS(M)/(M-1): the total work when a constant driving moment
  !          -AS(M)/(2*pi) is added, so that the work over the cycle is zero (steady state);
  !   EV   = ISPR*W1**2/2, the kinetic energy of the variable-inertia links at W1;
  !   DEC  = (ASUM - EV) - (ASUM(1) - EV(1)), the change of the kinetic energy of the
  !          constant-inertia links (DEC(1) = 0);
  !   WPR  = omega(phi);
  !   EPR  = DFRNCL(WPR) = (WPR(K) - WPR(K-1))/H, EPR(1) = EPR(2) (0 as printed,
  !          E-DFRNCL-1): d(omega)/d(phi) in 1/s, NOT
  !          the angular acceleration the comment (L5949) and text (L5929) call it
  !          (E-DZKNDV-1); epsilon = omega*d(omega)/d(phi) = WPR*EPR.
  ! WPR: as printed, eq. (8.17) linearised, omega = W1 + (DEC - (C1 + C2)/2)/(W1*ISC) with
  ! C1, C2 = max, min DEC; it is exact only for a vanishing fluctuation and gives negative
  ! speeds when the fluctuation is large (Fig. 96: WPR = -290).  Corrected mode
  ! (E-DZKNDV-2) solves the energy equation (8.13) itself, (ISC + ISPR(K))*omega_K**2/2 =
  ! E0 + ASUM(K), with E0 fixed by the book's own normalisation (max + min)/2 = W1, so
  ! that WPR is exact up to the trapezoid rule's O(H**2) (steady_speeds).  When no E0
  ! gives real speeds (the kinetic energy would go negative: the machine stalls) IER =
  ! st_requirement, and AS, ASUM, EV, DEC are still returned (they do not depend on ISC:
  ! DEC is what DMHVK sizes the flywheel from); WPR, EPR are 0 (the Python layer puts
  ! NaN there).
  ! The book sets PI = 3.14159 locally (L5955): prmtr's PI does the same as printed.
  ! ERRATA: E-DZKNDV-1 (comment), E-DZKNDV-2 (as-printed keeps the linear WPR).
  subroutine dzkndv(m, zm, w1, isc, mpr, ispr, aaa, as, asum, ev, dec, wpr, epr, ier)
    integer, intent(in) :: m
    real(dp), intent(in) :: zm, w1, isc, mpr(m), ispr(m), aaa
    real(dp), intent(out) :: as(m), asum(m), ev(m), dec(m), wpr(m), epr(m)
    integer, intent(out) :: ier
    real(dp) :: h, dad, c1, c2, decsr, ev1, hw, amin
    integer :: k, k1, k2
    logical :: ok
    ier = st_requirement
    if (m < 2 .or. .not. (zm > 1.0_dp .and. w1 > 0.0_dp .and. isc > 0.0_dp)) then
      as = 0.0_dp; asum = 0.0_dp; ev = 0.0_dp; dec = 0.0_dp; wpr = 0.0_dp; epr = 0.0_dp
      return
    end if
    ier = st_ok
    h = 2.0_dp*pi/(zm - 1.0_dp)
    call dintgr(m, h, 2, mpr, as)
    dad = as(m)/(zm - 1.0_dp)
    hw = w1**2/2.0_dp
    ev1 = ispr(1)*hw
    k1 = 1
    k2 = 1
    amin = 0.0_dp
    do k = 1, m                                      ! DEC(1) = ASUM(1) - EV(1) = -EV(1)
      asum(k) = as(k) - dad*real(k - 1, dp)
      ev(k) = ispr(k)*hw
      dec(k) = (asum(k) - ev(k)) + ev1
      if (dec(k) > dec(k1)) k1 = k                   ! the extremes of DEC, min ASUM
      if (dec(k) < dec(k2)) k2 = k
      amin = min(amin, asum(k))
    end do
    c1 = dec(k1)
    c2 = dec(k2)
    if (printed_mode /= 0) then                      ! E-DZKNDV-2: eq. (8.17), L5980-5986
      decsr = (c1 + c2)/2.0_dp
      wpr = w1 + (dec - decsr)/w1/isc
    else
      call steady_speeds(m, w1, isc, ispr, asum, k1, k2, amin, wpr, ok)
      if (.not. ok) then
        wpr = 0.0_dp; epr = 0.0_dp
        ier = st_requirement
        return
      end if
    end if
    call dfrncl(m, h, epr, wpr)
  end subroutine dzkndv

  ! VIII.2 DMHVK, L6055-6082, eq. (8.22)/(8.24): J_m = (max DEC - min DEC)/(DELTA*W1**2)
  ! - ISC, the flywheel that keeps the coefficient of speed fluctuation
  ! (omega_max - omega_min)/W1 at DELTA, neglecting the variable part J_v (J_A = J_B = J_c,
  ! L6034).  DEC is an input (the comment lists it under RESULT: E-DMHVK-2).  A negative
  ! IMHVK means that no flywheel is needed.  With DEC from DZKNDV, DZKNDV rerun with ISC +
  ! IMHVK gives exactly DELTA: as printed for any ISPR, corrected for ISPR = 0 (otherwise
  ! Merkalov's approximation, E-T8-3; the Python layer's DMHVK_EXACT is the exact one).
  ! The listing has 6 arguments; the only call in the book (L7631), whose printed result
  ! IMH = 4507.27 (L7203) shows that it ran, passes AAA before IMHVK, as every routine of
  ! the library does: the print flag is kept (E-DMHVK-1).
  ! The printed C1 + ABS(C2) is the swing C1 - C2 whenever C1 >= 0 >= C2, which DEC(1) = 0
  ! guarantees for DZKNDV's DEC; C1 - C2 is used for any DEC (E-DMHVK-3).
  subroutine dmhvk(n, delta, isc, w1, dec, aaa, imhvk)
    integer, intent(in) :: n
    real(dp), intent(in) :: delta, isc, w1, dec(n), aaa
    real(dp), intent(out) :: imhvk
    imhvk = 0.0_dp
    if (n < 1 .or. .not. (delta > 0.0_dp .and. abs(w1) > 0.0_dp)) return
    imhvk = (maxval(dec) - minval(dec))/delta/w1**2 - isc
  end subroutine dmhvk

end module dynamics
