! cams.f90 -- chapter 5, cam mechanisms (listings V.1-V.4, book lines L3053-3320):
! main dimensions DKLCHK, and the cam profile for a translating knife-edge follower
! (DPRFLP), a translating flat-faced follower (DPRFPL) and an oscillating follower
! (rocker, DPRFLK).
!
! Conventions (those of the book):
!   * the motion of the follower is given as tables over the cam angles FI(N) (rad):
!     acceleration A, velocity V, displacement S (translating follower, m/s^2, m/s, m) or
!     angular acceleration E2, angular velocity W2, angle PSI (rocker, rad/s^2, rad/s,
!     rad); the cam turns with the angular velocity W (W1) > 0, so that the transfer
!     functions are s' = V/W and s'' = A/W**2;
!   * the profile is given in the cam's own frame (principle of inversion, L3132): the
!     Cartesian coordinates XA, YA and the polar ones R1 and DELTA = ATAN(XA/YA) (the
!     principal value, as printed: DELTA jumps by pi where YA changes sign);
!   * a radius of curvature is positive where the profile is convex.
!
! Additions to the book (each a sarkp extension, after the book's arguments):
!   * DKLCHK takes the inputs of COMMON /KLCHK/ (ALD, BETA, W1, RSCNTR, RZMR, INDEX) as
!     arguments, in COMMON order, and leaves its results RO, EXCST, ETAO in the module
!     variables of the same names (returned in the Python result);
!   * DPRFLP and DPRFLK take the allowed pressure angle ALD and return the largest
!     |ALFA| (ALFMAX) and the number of points where |ALFA| > ALD (NOVER);
!   * DPRFPL returns the smallest radius of curvature (ROKMIN) and the number of points
!     where it is negative (NCONC): a flat-faced follower cannot follow a concave profile;
!   * DPRFLP takes cos(ALFA), sin(ALFA) from ALFA's tangent (exact near 90 degrees,
!     where COS(ATAN(t)) keeps only the digits of pi/2 - ALFA that ALFA holds);
!   * the Python layer adds motion laws, roller followers and exact sizing
!     (python/sarkp/cams.py, after the book's routines);
!   * a trailing IER (prmtr status): st_requirement where the book would divide by zero
!     or produce a profile that does not exist, st_singular for a point where the
!     pressure angle or the curvature radius is infinite.  On failure every output is 0.
!
! ERRATA ids of this chapter: E-<ROUTINE>-<n> and E-V5-<n>, E-FIG35-<n>, E-FIG36-<n>,
! listed in docs/ERRATA.md.  No routine of this chapter uses PI, and no printed figure
! depends on an author error of V.1-V.4, so both modes compute the same here (program
! V.5 differs between modes through PI and the ES EVM's arithmetic).
module cams
  use prmtr, only: dp, st_ok, st_singular, st_requirement
  implicit none
  private
  public :: dklchk, dprflp, dprfpl, dprflk

  ! COMMON /KLCHK/ ALD, BETA, W1, RSCNTR, RZMR, INDEX, RO, EXCST, ETAO (L3079): the
  ! results of DKLCHK.  (The inputs are DKLCHK's arguments.)
  real(dp), public :: ro = 0.0_dp      ! r0, radius of the cam (its base circle)
  real(dp), public :: excst = 0.0_dp   ! e, offset of the translating follower (INDEX = 1)
  real(dp), public :: etao = 0.0_dp    ! eta0, initial angle of the rocker (INDEX = 2)

  real(dp), parameter :: half_pi = 1.5707963267948966_dp

contains

  ! The book's DELTA(K) = ATAN(XA(K)/YA(K)), with its limit +-pi/2 where YA = 0.
  pure real(dp) function polar_angle(x, y)
    real(dp), intent(in) :: x, y
    if (y /= 0.0_dp) then
      polar_angle = atan(x/y)
    else
      polar_angle = sign(half_pi, x)
    end if
  end function polar_angle

  ! V.1, L3053-3100.  Main dimensions of the cam mechanism from the motion of the follower
  ! and the allowed pressure angle ALD (L3046-3052, eq. (5.2)).
  ! At the first (strict) maximum of the velocity VLST(L) (the transfer function
  ! IFI = VLST(L)/W1 = ds/dphi) and the displacement S = PRM(L) there:
  !   INDEX = 1 (translating follower, e = r0 sin(BETA) and axial offset r0 cos(BETA)
  !     solve tan(ALD) = (IFI - e)/(r0 cos(BETA) + S)):
  !       RO = (IFI/TAN(ALD) - S) SIN(ALD)/SIN(ALD + BETA),  EXCST = RO SIN(BETA);
  !   INDEX = 2 (rocker of length RZMR, centre distance RSCNTR; PRM, VLST angular):
  !       ETAO = IFI/TAN(ALD) - S,  RO = SQRT(RSCNTR**2 + RZMR**2 - 2 RSCNTR RZMR COS(ETAO)).
  ! The result not computed (ETAO for INDEX 1, EXCST for INDEX 2) is 0.
  ! AKSLRT (the acceleration) is not used, as printed.  When VLST(1) is the largest value
  ! the printed loop never sets L; here the first maximum, L = 1, is taken (E-DKLCHK-1).
  ! st_requirement: ALD outside (0, pi/2), W1 <= 0, SIN(ALD + BETA) <= 0, INDEX 2 with a
  ! non-positive length, or a non-positive RO (the book's rule gives no cam).
  subroutine dklchk(n, prm, vlst, akslrt, ald, beta, w1, rscntr, rzmr, index, ier)
    !sarkp common: ro, excst, etao
    integer, intent(in) :: n
    real(dp), intent(in) :: prm(n), vlst(n), akslrt(n)
    real(dp), intent(in) :: ald, beta, w1, rscntr, rzmr
    integer, intent(in) :: index
    integer, intent(out) :: ier
    real(dp) :: mksmm, ifi, s
    integer :: k, l
    ro = 0.0_dp
    excst = 0.0_dp
    etao = 0.0_dp
    ier = st_requirement
    if (n < 1 .or. .not. (ald > 0.0_dp .and. ald < half_pi) .or. .not. (w1 > 0.0_dp)) return
    ! labels 10-11: the first maximum of VLST
    mksmm = vlst(1)
    l = 1
    do k = 1, n
      if (vlst(k) > mksmm) then
        mksmm = vlst(k)
        l = k
      end if
    end do
    s = prm(l)
    ifi = mksmm/w1
    if (index == 2) then                                   ! label 30
      if (.not. (rscntr > 0.0_dp .and. rzmr > 0.0_dp)) return
      etao = ifi/tan(ald) - s
      ro = sqrt(max(rscntr**2 + rzmr**2 - 2.0_dp*rscntr*rzmr*cos(etao), 0.0_dp))
      if (.not. (ro > 0.0_dp)) then
        ro = 0.0_dp
        etao = 0.0_dp
        return
      end if
    else                                                   ! label 20 (INDEX = 1)
      if (.not. (sin(ald + beta) > 0.0_dp)) return
      ro = (ifi/tan(ald) - s)*sin(ald)/sin(ald + beta)
      if (.not. (ro > 0.0_dp)) then
        ro = 0.0_dp
        return
      end if
      excst = ro*sin(beta)
    end if
    ier = st_ok
  end subroutine dklchk

  ! V.2, L3149-3189.  Profile of the cam for a translating knife-edge follower with the
  ! offset EXCNTR.  RO is the follower's axial distance from the foot of the offset at
  ! S = 0 (so C = RO + S, L3183; the profile's smallest radius is SQRT(RO**2 + e**2)).
  !   XA = e COS(FI) + C SIN(FI),  YA = -e SIN(FI) + C COS(FI)            (L3178-3179)
  !   ALFA = ATAN((s' - e)/C)                                            (eq. (5.2))
  !   ROK = 1/OMEGA, OMEGA = (C COS(ALFA) + s' SIN(ALFA) COS(ALFA)**2
  !                          - s'' COS(ALFA)**3)/C**2                     (L3184, E-DPRFLP-2)
  ! The printed listing names the two transfer functions the other way round
  ! (D2SDFI = V/W, DSDFI = A/W**2: E-DPRFLP-1); Fig. 35 is computed with s' = V/W and
  ! s'' = A/W**2, as here, in both modes.
  ! sarkp extension: ALFMAX = max |ALFA|, NOVER = number of points with |ALFA| > ALD.
  ! st_requirement: W <= 0, or C = RO + S(K) <= 0 at some point (the follower would pass
  ! the cam centre: the pressure angle reaches 90 degrees); st_singular: OMEGA = 0
  ! exactly (a point of zero curvature has no finite radius).
  subroutine dprflp(n, ro, excntr, w, fi, a, v, s, ald, xa, ya, r1, delta, alfa, rok, &
                    alfmax, nover, ier)
    integer, intent(in) :: n
    real(dp), intent(in) :: ro, excntr, w, ald
    real(dp), intent(in) :: fi(n), a(n), v(n), s(n)
    real(dp), intent(out) :: xa(n), ya(n), r1(n), delta(n), alfa(n), rok(n)
    real(dp), intent(out) :: alfmax
    integer, intent(out) :: nover
    integer, intent(out) :: ier
    real(dp) :: dsdfi, d2sdfi, c, ca, sa, h, omega
    integer :: k
    call clear(xa, ya, r1, delta, alfa, rok)
    alfmax = 0.0_dp
    nover = 0
    ier = st_requirement
    if (.not. (w > 0.0_dp)) return
    if (any(.not. (ro + s > 0.0_dp))) return
    do k = 1, n
      dsdfi = v(k)/w                                       ! E-DPRFLP-1
      d2sdfi = a(k)/w**2
      c = ro + s(k)
      xa(k) = excntr*cos(fi(k)) + c*sin(fi(k))
      ya(k) = -excntr*sin(fi(k)) + c*cos(fi(k))
      r1(k) = sqrt(xa(k)**2 + ya(k)**2)
      delta(k) = polar_angle(xa(k), ya(k))
      alfa(k) = atan((dsdfi - excntr)/c)
      ! cos and sin of ALFA from its tangent (dsdfi - e)/C, not COS(ATAN(...)): near 90
      ! degrees COS(ALFA) would keep only the digits of pi/2 - ALFA that ALFA holds
      ! (E-DPRFLP-5, numerical)
      h = hypot(c, dsdfi - excntr)
      ca = c/h
      sa = (dsdfi - excntr)/h
      omega = (c*ca + dsdfi*sa*ca**2 - d2sdfi*ca**3)/c**2  ! E-DPRFLP-2
      if (omega == 0.0_dp) then
        call clear(xa, ya, r1, delta, alfa, rok)
        ier = st_singular
        return
      end if
      rok(k) = 1.0_dp/omega
    end do
    alfmax = maxval(abs(alfa))
    nover = count(abs(alfa) > ald)
    ier = st_ok
  end subroutine dprflp

  ! V.3, L3213-3257.  Profile of the cam for a translating flat-faced follower (face
  ! perpendicular to its axis, no offset); the routine chooses the radius RKSH itself.
  ! At the first (strict) minimum of A, L, with s''min = A(L)/W**2 (labels 10-11):
  !   RKSH = ABS(-(s''min/TAN(GAMMA) + S(L)))      (convexity rule (5.4), L3118)
  ! and for every point, with C = RKSH + S (L3250-3254, eq. at L3205-3209):
  !   XA = C SIN(FI) + s' COS(FI),  YA = C COS(FI) - s' SIN(FI),
  !   R1 = SQRT(C**2 + s'**2),  ROK = C + s''.
  ! GAMMA = pi/4 makes ROK = 0 at point L (Fig. 36); the listing's comment asks for a
  ! GAMMA "greater than PI/4" (L3225), which makes ROK < 0 there (E-DPRFPL-1).
  ! When A(1) is the smallest value the printed loop never sets L: L = 1 here
  ! (E-DPRFPL-2).  Program X calls DPRFPL without S (L7467): E-X-DPRFPL-1.
  ! sarkp extension: ROKMIN = min ROK, NCONC = number of points where ROK < 0 beyond
  ! rounding (ROK < -16 eps (RKSH + max|S| + max|s''|)): a flat face cannot touch a
  ! concave profile, so NCONC > 0 means the profile is not realizable.
  ! st_requirement: W <= 0, TAN(GAMMA) <= 0 (GAMMA outside (0, pi/2)), or RKSH + S(K)
  ! <= 0 at some point.
  subroutine dprfpl(n, gamma, w, fi, a, v, s, xa, ya, r1, delta, rok, rksh, rokmin, &
                    nconc, ier)
    integer, intent(in) :: n
    real(dp), intent(in) :: gamma, w
    real(dp), intent(in) :: fi(n), a(n), v(n), s(n)
    real(dp), intent(out) :: xa(n), ya(n), r1(n), delta(n), rok(n)
    real(dp), intent(out) :: rksh, rokmin
    integer, intent(out) :: nconc
    integer, intent(out) :: ier
    real(dp) :: mnmm, dsdfi, d2sdfi, c, tol
    integer :: k, l
    call clear(xa, ya, r1, delta, rok)
    rksh = 0.0_dp
    rokmin = 0.0_dp
    nconc = 0
    ier = st_requirement
    if (n < 1 .or. .not. (w > 0.0_dp) .or. .not. (gamma > 0.0_dp .and. gamma < half_pi)) return
    mnmm = a(1)
    l = 1
    do k = 1, n
      if (a(k) < mnmm) then
        mnmm = a(k)
        l = k
      end if
    end do
    d2sdfi = mnmm/w**2
    rksh = abs(-(d2sdfi/tan(gamma) + s(l)))
    if (any(.not. (rksh + s > 0.0_dp))) then
      rksh = 0.0_dp
      return
    end if
    do k = 1, n
      dsdfi = v(k)/w
      d2sdfi = a(k)/w**2
      c = rksh + s(k)
      xa(k) = c*sin(fi(k)) + dsdfi*cos(fi(k))
      ya(k) = c*cos(fi(k)) - dsdfi*sin(fi(k))
      r1(k) = sqrt(c**2 + dsdfi**2)
      delta(k) = polar_angle(xa(k), ya(k))
      rok(k) = c + d2sdfi
    end do
    rokmin = minval(rok)
    tol = 16.0_dp*epsilon(1.0_dp)*(rksh + maxval(abs(s)) + maxval(abs(a))/w**2)
    nconc = count(rok < -tol)
    ier = st_ok
  end subroutine dprfpl

  ! V.4, L3270-3320.  Profile of the cam for an oscillating (rocker) knife-edge follower:
  ! the rocker of length R turns about O2 at the distance L from the cam centre; its angle
  ! from the line O2-O1 is PSI + ETAO (PSI the motion, ETAO the initial angle).  With
  ! psi = PSI + ETAO, psi' = W2/W1, psi'' = E2/W1**2:
  !   XA = L COS(FI) - R COS(FI + psi),  YA = -L SIN(FI) + R SIN(FI + psi)   (L3302-3303)
  !   R1 = SQRT(L**2 - 2 L R COS(psi) + R**2)
  !   ALFA = ATAN(R (1 + psi')/(L SIN(psi)) - 1/TAN(psi))                   (eq. (5.5))
  !   RKRZVN = C1/C2,  C1 = (L**2 + R**2 (1+psi')**2 - 2 L R (1+psi') COS(psi))**1.5
  !                    C2 = L**2 + R**2 (1+psi')**3
  !                         - L R (COS(psi) (1+psi') (2+psi') + psi'' SIN(psi))
  ! C1 is garbled in print (L3312-3313, E-DPRFLK-2): it is |P'|**3 of the profile curve
  ! P(FI), as C2 is the cross product P' x P'' (tests/test_cams.py proves both).  The
  ! printed header names the 4th argument F1 (E-DPRFLK-1).  RO is not used, as printed.
  ! The prose's y_A = -l0 sin(phi) - r2 sin(phi + phi2) (L3266) has the wrong sign
  ! (E-DPRFLK-3); the listing's + is consistent with its R1.
  ! sarkp extension: ALFMAX = max |ALFA|, NOVER = number of points with |ALFA| > ALD.
  ! st_requirement: W1 <= 0, or R1 = 0 at some point (the rocker's tip on the cam
  ! centre); st_singular: SIN(psi) = 0 (the rocker along O1-O2: pressure angle 90
  ! degrees) or C2 = 0 (curvature radius infinite).
  subroutine dprflk(n, w1, etao, fi, ro, l, r, e2, w2, psi, ald, xa, ya, r1, delta, &
                    rkrzvn, alfa, alfmax, nover, ier)
    integer, intent(in) :: n
    real(dp), intent(in) :: w1, etao, ro, l, r, ald
    real(dp), intent(in) :: fi(n), e2(n), w2(n), psi(n)
    real(dp), intent(out) :: xa(n), ya(n), r1(n), delta(n), rkrzvn(n), alfa(n)
    real(dp), intent(out) :: alfmax
    integer, intent(out) :: nover
    integer, intent(out) :: ier
    real(dp) :: dpsifi, d2psif, p, sp, cp, c1, c2
    integer :: k
    call clear(xa, ya, r1, delta, rkrzvn, alfa)
    alfmax = 0.0_dp
    nover = 0
    ier = st_requirement
    if (.not. (w1 > 0.0_dp)) return
    do k = 1, n
      dpsifi = w2(k)/w1
      d2psif = e2(k)/w1**2
      p = psi(k) + etao
      sp = sin(p)
      cp = cos(p)
      xa(k) = l*cos(fi(k)) - r*cos(fi(k) + p)
      ya(k) = -l*sin(fi(k)) + r*sin(fi(k) + p)
      r1(k) = sqrt(l**2 - 2.0_dp*l*r*cp + r**2)
      if (.not. (r1(k) > 0.0_dp)) then
        call clear(xa, ya, r1, delta, rkrzvn, alfa)
        ier = st_requirement
        return
      end if
      delta(k) = polar_angle(xa(k), ya(k))
      c2 = l**2 + r**2*(1.0_dp + dpsifi)**3 &
           - l*r*(cp*(1.0_dp + dpsifi)*(2.0_dp + dpsifi) + d2psif*sp)
      if (sp == 0.0_dp .or. c2 == 0.0_dp) then
        call clear(xa, ya, r1, delta, rkrzvn, alfa)
        ier = st_singular
        return
      end if
      alfa(k) = atan(r*(1.0_dp + dpsifi)/l/sp - 1.0_dp/tan(p))
      c1 = (l**2 + r**2*(1.0_dp + dpsifi)**2 &
            - 2.0_dp*l*r*(1.0_dp + dpsifi)*cp)**1.5_dp   ! E-DPRFLK-2
      rkrzvn(k) = c1/c2
    end do
    alfmax = maxval(abs(alfa))
    nover = count(abs(alfa) > ald)
    ier = st_ok
  end subroutine dprflk

  ! Every output table to 0 (a failed call returns zeros, never NaN).
  subroutine clear(a, b, c, d, e, f)
    real(dp), intent(out) :: a(:), b(:), c(:), d(:), e(:)
    real(dp), intent(out), optional :: f(:)
    a = 0.0_dp
    b = 0.0_dp
    c = 0.0_dp
    d = 0.0_dp
    e = 0.0_dp
    if (present(f)) f = 0.0_dp
  end subroutine clear

end module cams
