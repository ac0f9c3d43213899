! gears.f90 -- chapter 6, gear trains and involute gearing (listings VI.1 and VI.3-VI.8,
! book lines L3720-4824; the example main program VI.2 and the examples of Figs. 44-50 live
! in the Python package, sarkp.book).
!
!   DZBPL   VI.1  tooth numbers of a multi-satellite planetary train (COMMON /ZUB/)
!   DKRKT   VI.3  profile-shift coefficients and the operating pressure angle
!   DUGINV  VI.4  the angle from its involute, inv x = tan x - x (a FUNCTION)
!   DGMTZK  VI.5  dimensions of one external gear
!   DGMZPC  VI.6  external involute mesh (COMMON /ZPC/)
!   DGMZVN  VI.7  internal involute mesh, wheel cut by a shaper (COMMON /ZVN/)
!   DCHRVC  VI.8  cylindrical worm gearing (COMMON /CHRVC/)
!
! Names and argument order are the book's, AAA included (AAA only steered printing; the
! Python layer prints the reports).  Gear lengths in mm (any one unit), angles in radians,
! the tool's profile angle alpha = 20 deg = PI/9 (h_a* = 1, c* = 0.25) throughout.
!
! COMMON results are public module variables named <block>_<book name> (the blocks share
! names such as A, AW, D1), returned under the book's names (`!sarkp common: a => zpc_a`).
! /ZUB/ also holds the book's COMMON inputs ZKRN, ZKRW, DZ (set by the main program,
! L3815-3817).
!
! Additions to the book (it reports nothing: ARCOS failed or nonsense was printed): a
! trailing IER, a prmtr status code, st_ok or a requirement no gear can meet, with its
! reason as 10*st_requirement + k (the Python layer raises RequirementError with the
! reason's message):
!   st_requirement  no admissible tooth numbers (DZBPL), a worm with DW1 <= 0 (DCHRVC);
!   st_undercut     a shift below the undercut limit (6.15)/(6.17) (DKRKT's message 20);
!   st_pointed      a tooth whose flanks meet below its tip circle (DKRKT's message 21);
!   st_correction   DKRKT's message 22 (no shift system serves these tooth numbers);
!   st_inside_base  a tip circle inside its base circle (no involute flank at all);
!   st_no_mesh      a centre distance or shifts that no involute mesh has (a negative
!                   involute, AW at or below the sum of the base radii).
! On failure every output (and COMMON result) is 0.
!
! as-printed mode (printed_mode /= 0) keeps what the printed figures depend on: PI =
! 3.14159, DUGINV's fixed-point iteration stopped at TCHNST = 0.00001 (E-DUGINV-1,
! E-DKRKT-3), DZBPL's truncating search with IABS (E-DZBPL-3..5), the spur formulas that
! DGMTZK and DGMZPC apply to helical gears (E-DGMTZK-2, E-DGMZPC-3), and no undercut check
! in DGMTZK (E-DGMTZK-4).  Garbled statements that every printed figure contradicts are
! fixed in both modes (E-DZBPL-1, E-DZBPL-2, E-DKRKT-1, E-DKRKT-2, E-DGMTZK-1,
! E-DGMZPC-1, E-DGMZPC-2, E-DGMZVN-1..3).
module gears
  use prmtr, only: dp, pi, printed_mode, st_ok, st_requirement, st_range
  implicit none
  private
  public :: dzbpl, dkrkt, duginv, dgmtzk, dgmzpc, dgmzvn, dchrvc

  ! ---- COMMON /ZUB/ ZKRN, ZKRW, DZ, Z1, Z2, Z3, Z4 (L3748) --------------------------------
  ! Inputs, set by the main program (VI.2, L3815-3817): the least tooth number of an
  ! external wheel meshing with an internal one (jamming), of an internal wheel, and the
  ! least tooth difference of an internal pair (interference).
  integer, public :: zub_zkrn = 20, zub_zkrw = 85, zub_dz = 8
  ! Results: the tooth numbers found.
  integer, public :: zub_z1 = 0, zub_z2 = 0, zub_z3 = 0, zub_z4 = 0

  ! ---- COMMON /ZPC/ A, XS, ALFAW, AW, XY, XUR, E (L4423) ---------------------------------
  real(dp), public :: zpc_a = 0.0_dp, zpc_xs = 0.0_dp, zpc_alfaw = 0.0_dp, zpc_aw = 0.0_dp, &
                      zpc_xy = 0.0_dp, zpc_xur = 0.0_dp, zpc_e = 0.0_dp
  ! sarkp extension, returned after /ZPC/: what DGMZPC computes and the book drops, the tip
  ! diameters with the tip shortening, the pressure angles and tooth thicknesses there.
  real(dp), public :: zpc_da1 = 0.0_dp, zpc_da2 = 0.0_dp, zpc_alfaa1 = 0.0_dp, &
                      zpc_alfaa2 = 0.0_dp, zpc_sa1 = 0.0_dp, zpc_sa2 = 0.0_dp

  ! ---- COMMON /ZVN/ A, XD, ALFA(W), AW, D1, D2, DW1, DW2, XY, XUR, DA1, DA2, DF1, DF(2),
  !      H1, H2, SA1, SA2, EALFA (L4540-4542; words 3 and 14 hold ALFAW and DF2, E-DGMZVN-4)
  real(dp), public :: zvn_a = 0.0_dp, zvn_xd = 0.0_dp, zvn_alfaw = 0.0_dp, zvn_aw = 0.0_dp, &
                      zvn_d1 = 0.0_dp, zvn_d2 = 0.0_dp, zvn_dw1 = 0.0_dp, zvn_dw2 = 0.0_dp, &
                      zvn_xy = 0.0_dp, zvn_xur = 0.0_dp, zvn_da1 = 0.0_dp, zvn_da2 = 0.0_dp, &
                      zvn_df1 = 0.0_dp, zvn_df2 = 0.0_dp, zvn_h1 = 0.0_dp, zvn_h2 = 0.0_dp, &
                      zvn_sa1 = 0.0_dp, zvn_sa2 = 0.0_dp, zvn_ealfa = 0.0_dp

  ! ---- COMMON /CHRVC/ X, D1, D2, DW1, G, GW, H1, HA1, DA1, DA2, DAM2, B1, B2, R (L4779) ---
  real(dp), public :: chrvc_x = 0.0_dp, chrvc_d1 = 0.0_dp, chrvc_d2 = 0.0_dp, &
                      chrvc_dw1 = 0.0_dp, chrvc_g = 0.0_dp, chrvc_gw = 0.0_dp, &
                      chrvc_h1 = 0.0_dp, chrvc_ha1 = 0.0_dp, chrvc_da1 = 0.0_dp, &
                      chrvc_da2 = 0.0_dp, chrvc_dam2 = 0.0_dp, chrvc_b1 = 0.0_dp, &
                      chrvc_b2 = 0.0_dp, chrvc_r = 0.0_dp

  ! Reasons of st_requirement (see the header).
  integer, parameter :: st_undercut = 10*st_requirement + 1, st_pointed = 10*st_requirement + 2, &
                        st_correction = 10*st_requirement + 3, &
                        st_inside_base = 10*st_requirement + 4, st_no_mesh = 10*st_requirement + 5

  ! The book's DUGINV tolerance: Figs. 44, 47, 48 were computed with 0.00001 (E-DKRKT-3).
  real(dp), parameter :: book_tchnst = 0.00001_dp
  ! as-printed DUGINV: the book's loop has no bound; this one stops here (E-DUGINV-2).
  integer, parameter :: book_max_iterations = 1000000

  ! Taylor coefficients of tan x - x = sum c(k) x**(2k+1), k = 1..15 (c(k) = T_k of tan x).
  real(dp), parameter :: inv_series(15) = (/ &
    0.3333333333333333_dp, 0.13333333333333333_dp, 0.05396825396825397_dp, &
    0.021869488536155203_dp, 0.008863235529902197_dp, 0.003592128036572481_dp, &
    0.0014558343870513183_dp, 0.000590027440945586_dp, 0.00023912911424355248_dp, &
    9.691537956929451e-05_dp, 3.927832388331683e-05_dp, 1.5918905069328964e-05_dp, &
    6.451689215655431e-06_dp, 2.6147711512907546e-06_dp, 1.0597268320104654e-06_dp /)

contains

  ! ============================================================================
  ! private helpers
  ! ============================================================================

  ! inv x = tan x - x: in corrected mode to full relative precision (below 0.4 rad tan x - x
  ! cancels, at 0.01 rad it keeps 11 digits, so the Taylor series is summed there,
  ! E-DUGINV-3); in as-printed mode the book's TAN(X) - X.
  pure real(dp) function involute(x)
    real(dp), intent(in) :: x
    if (printed_mode /= 0) then
      involute = tan(x) - x
    else
      involute = involute_from_tan(x, tan(x))
    end if
  end function involute

  ! inv x from x and t = tan x: the Taylor series of tan x - x below 0.4 rad (8 terms below
  ! 0.1 rad, where they fall by 0.004 each; 15 above, where they fall by up to 0.065),
  ! else t - x.
  pure real(dp) function involute_from_tan(x, t)
    real(dp), intent(in) :: x, t
    real(dp) :: x2, s
    integer :: k
    if (abs(x) >= 0.4_dp) then
      involute_from_tan = t - x
      return
    end if
    x2 = x*x
    if (x2 < 0.01_dp) then
      s = inv_series(8)
      do k = 7, 1, -1
        s = s*x2 + inv_series(k)
      end do
    else
      s = inv_series(15)
      do k = 14, 1, -1
        s = s*x2 + inv_series(k)
      end do
    end if
    involute_from_tan = s*x2*x
  end function involute_from_tan

  ! The root x in [0, pi/2) of tan x - x = v (v >= 0) to full double precision.
  ! Up to v = 10 (84.6 deg): a rational start in u = (3v)**(1/3), x ~ u for small v,
  ! fitted by least squares to within 2e-8 relative, then one Halley step on inv x - v
  ! (cubic: the error falls below 1e-20).  Above: Newton from the right of the root, where
  ! it descends monotonically on the convex tan x - x.  Called in corrected mode only.
  pure real(dp) function inverse_involute(v) result(x)
    real(dp), intent(in) :: v
    ! (/ /), not [ ]: fortran/gen_drivers.py splits declarations at commas outside ( )
    real(dp), parameter :: a(5) = (/ -3.28300649e-01_dp, 1.88154669e-01_dp, &
                                     -7.76490192e-03_dp, 3.01734269e-03_dp, -2.96782362e-04_dp /)
    real(dp), parameter :: b(5) = (/ -0.32830103_dp, 0.32149542_dp, -0.05159022_dp, &
                                     0.02892033_dp, -0.00189592_dp /)
    real(dp) :: u, t, f, df, dx
    integer :: k
    if (v <= 0.0_dp) then
      x = 0.0_dp
      return
    end if
    if (v > 1.0e8_dp) then
      ! x = pi/2 - d with cot d = v + x: d = 1/(v + pi/2) + O(d**3)
      x = pi/2.0_dp - 1.0_dp/(v + pi/2.0_dp)
      return
    end if
    if (v > 10.0_dp) then
      x = atan(v + pi/2.0_dp)
      do k = 1, 40
        t = tan(x)
        dx = (involute_from_tan(x, t) - v)/(t*t)
        x = x - dx
        ! the error after a step is about tan(x) dx**2: below 1e-11 x it is < 1e-18
        if (abs(dx) <= 1.0e-11_dp*x) exit
      end do
      return
    end if
    u = exp(log(3.0_dp*v)/3.0_dp)        ! the cube root (half the cost of **(1/3))
    x = u*(1.0_dp + u*(a(1) + u*(a(2) + u*(a(3) + u*(a(4) + u*a(5)))))) &
         /(1.0_dp + u*(b(1) + u*(b(2) + u*(b(3) + u*(b(4) + u*b(5))))))
    t = tan(x)
    f = involute_from_tan(x, t) - v
    df = t*t
    x = x - f/df/(1.0_dp - f*(1.0_dp + df)/(t*df))     ! Halley: f'' = 2 t (1 + t**2)
  end function inverse_involute

  ! The book's DUGINV loop (L4209-4215): x_{i+1} = ATAN(x_i + INVX) until the step is below
  ! TCHNST; the value returned is x_{i+1}.
  pure real(dp) function book_duginv(invx, xnach, tchnst) result(x1)
    real(dp), intent(in) :: invx, xnach, tchnst
    real(dp) :: x
    integer :: k
    x = xnach
    x1 = x
    do k = 1, book_max_iterations
      x1 = atan(x + invx)
      if (abs(x1 - x) - tchnst < 0.0_dp) return
      x = x1
    end do
  end function book_duginv

  ! alpha_w from its involute as the routines of this chapter call DUGINV: the exact root
  ! in corrected mode, the book's iteration from PI/18 with TCHNST = 0.00001 as printed.
  pure real(dp) function angle_of_involute(v)
    real(dp), intent(in) :: v
    if (printed_mode /= 0) then
      angle_of_involute = book_duginv(v, pi/18.0_dp, book_tchnst)
    else
      angle_of_involute = inverse_involute(v)
    end if
  end function angle_of_involute

  ! The least shift coefficient without undercut by the standard rack, (6.15)/(6.17):
  ! x_min = h_a* - z sin^2(alpha_t)/(2 cos beta)  (L3967, L3977; E-DKRKT-5).
  pure real(dp) function undercut_limit(z, alfat, beta)
    real(dp), intent(in) :: z, alfat, beta
    undercut_limit = 1.0_dp - 0.5_dp*z*sin(alfat)**2/cos(beta)
  end function undercut_limit

  ! Integer helpers of DZBPL (64-bit products: the book's ranges times P, Q, L2, L3).
  logical function divides(d, n)
    integer(8), intent(in) :: d, n
    divides = d /= 0_8
    if (divides) divides = mod(n, d) == 0_8
  end function divides

  ! The neighbourhood condition (6.5): sin(pi/k) > (z + 2)/s, with z the larger planet
  ! wheel and s = z1 +- z2 twice the planets' centre radius in modules.  sin(pi/k) is
  ! rational only for k = 1, 2, 6 (Niven): those are compared exactly.
  logical function neighbours_clear(k, zmax, s)
    integer, intent(in) :: k
    integer(8), intent(in) :: zmax, s
    real(dp), parameter :: pi_dp = 3.141592653589793238462643_dp
    select case (k)
    case (1)
      neighbours_clear = .true.
    case (2)
      neighbours_clear = s > zmax + 2_8
    case (6)
      neighbours_clear = s > 2_8*(zmax + 2_8)
    case default
      neighbours_clear = sin(pi_dp/real(k, dp))*real(s, dp) > real(zmax + 2_8, dp)
    end select
  end function neighbours_clear

  ! ============================================================================
  ! VI.1 DZBPL (L3720-3798): tooth numbers of a multi-satellite planetary train
  ! ============================================================================
  ! Schemes (Fig. 38, Table 21, L3707-3714): 1 = (a),(b) sun 1 - planet 2 external, planet 3
  ! - ring 4 internal, z1 + z2 = z4 - z3; 2 = (v) both external, z1 + z2 = z4 + z3;
  ! 3 = (g) both internal, z1 - z2 = z4 - z3.  i_1h = P/Q, z2 : z3 = L2 : L3.
  ! Corrected: z1 runs from Z1MIN to Z1MAX; the first z1 that meets the assembly condition
  ! (6.4) (z1 P/(k Q) whole), whose z2, z3, z4 come out whole and positive from Table 21
  ! (so that the ratio P/Q, z2 : z3 = L2 : L3 and coaxiality (6.2) hold exactly), within the
  ! book's limits ZKRN/ZKRW/DZ and clear of the neighbourhood condition (6.5), is returned
  ! (E-DZBPL-3, E-DZBPL-4, E-DZBPL-5).
  ! as-printed: the listing with its GO TO 6 (E-DZBPL-1) and Z4 of scheme 3 (E-DZBPL-2)
  ! restored: truncating integer division, IABS(Z2), no neighbourhood test.
  ! No admissible set: st_requirement (the book prints its message 10, L3789).
  subroutine dzbpl(ks, p, q, l2, l3, z1min, z1max, shema, zkrn, zkrw, dz, ier)
    !sarkp common: z1 => zub_z1, z2 => zub_z2, z3 => zub_z3, z4 => zub_z4
    !: KS : integer 1..100 -- Number of satellite blocks k (1..100).
    !: P, Q : integer -1000..1000; integer 1..1000 -- The ratio i_1h = P/Q in lowest terms
    !:     (P != 0 may be negative, Q >= 1).
    !: L2, L3 : integer 1..1000 -- z2 : z3 = L2 : L3, coprime (L2 != L3 for schemes 2 and
    !:     3).
    !: Z1MIN, Z1MAX : integer 1..10000 -- The range of z1 (undercut, jamming, size).
    !: SHEMA : integer 1..3 -- 1, 2 or 3 (see above).
    !: ZKRN, ZKRW, DZ : integer 1..10000 = 20; integer 1..10000 = 85; integer 1..10000 = 8 -- The
    !:     book's COMMON /ZUB/ inputs, here arguments (sarkp extension), defaults the book's
    !:     (VI.2, L3815-3817): the least tooth number of an external wheel (20; the classic
    !:     undercut limit z >= 17 can be asked with 17) and of an internal wheel (85), and
    !:     the least tooth difference of an internal pair (8). Each limit applies where the
    !:     book applies it: scheme 1, z2, z3 >= ZKRN, z4 >= ZKRW, z4 - z3 >= DZ; scheme 2,
    !:     z2, z3, z4 >= ZKRN; scheme 3, z1, z4 >= ZKRW, z2, z3 >= ZKRN, z1 - z2, z4 - z3 >=
    !:     DZ.
    integer, intent(in) :: ks, p, q, l2, l3, z1min, z1max, shema, zkrn, zkrw, dz
    integer, intent(out) :: ier
    logical :: found
    ! COMMON /ZUB/'s inputs, the book's limits (VI.2 sets 20, 85, 8): sarkp takes them as
    ! arguments (defaults the book's) and keeps them in the COMMON's variables
    zub_zkrn = zkrn
    zub_zkrw = zkrw
    zub_dz = dz
    zub_z1 = 0
    zub_z2 = 0
    zub_z3 = 0
    zub_z4 = 0
    ier = st_requirement
    if (ks < 1 .or. q < 1 .or. p == 0 .or. l2 < 1 .or. l3 < 1 .or. z1min < 1 &
        .or. z1max < z1min) return
    if (shema /= 1 .and. l2 == l3) return    ! Table 21 (v), (g) divide by L3 - L2
    if (printed_mode /= 0) then
      call dzbpl_printed(ks, p, q, l2, l3, z1min, z1max, shema, found)
    else
      call dzbpl_corrected(ks, p, q, l2, l3, z1min, z1max, shema, found)
    end if
    if (found) then
      ier = st_ok
    else
      zub_z1 = 0
      zub_z2 = 0
      zub_z3 = 0
      zub_z4 = 0
    end if
  end subroutine dzbpl

  subroutine dzbpl_corrected(ks, p, q, l2, l3, z1min, z1max, shema, found)
    integer, intent(in) :: ks, p, q, l2, l3, z1min, z1max, shema
    logical, intent(out) :: found
    integer(8) :: k, pp, qq, a2, a3, z1, z2, z3, z4, n2, d2, n4, d4, s, zkrn, zkrw, dz
    k = ks
    pp = p
    qq = q
    a2 = l2
    a3 = l3
    zkrn = zub_zkrn
    zkrw = zub_zkrw
    dz = zub_dz
    found = .false.
    do z1 = z1min, z1max
      if (.not. divides(k*qq, z1*abs(pp))) cycle          ! assembly (6.4): C0 whole
      select case (shema)
      case (2)                                           ! (v): Table 21
        n2 = z1*(pp*a3 - qq*a3 + qq*a2)
        d2 = qq*(a3 - a2)
        n4 = z1*a3*(qq - pp)
      case (3)                                           ! (g)
        n2 = z1*(pp*a3 - qq*a3 + qq*a2)
        d2 = qq*(a2 - a3)
        n4 = z1*a3*(qq - pp)
      case default                                       ! (a), (b): (6.11)
        n2 = z1*(pp*a3 - qq*a3 - qq*a2)
        d2 = qq*(a2 + a3)
        n4 = z1*a3*(pp - qq)
      end select
      d4 = a2*qq
      if (.not. (divides(d2, n2) .and. divides(d4, n4))) cycle   ! the ratio exactly
      z2 = n2/d2
      z4 = n4/d4
      if (.not. divides(a2, z2*a3)) cycle                         ! z2 : z3 = L2 : L3
      z3 = z2*a3/a2
      if (z2 <= 0 .or. z3 <= 0 .or. z4 <= 0) cycle                ! no IABS (E-DZBPL-4)
      select case (shema)
      case (2)
        if (z1 + z2 /= z4 + z3) cycle                             ! coaxiality (6.2)
        if (z2 < zkrn .or. z3 < zkrn .or. z4 < zkrn) cycle        ! L3771-3773
        s = z1 + z2
      case (3)
        if (z1 - z2 /= z4 - z3) cycle
        if (z1 < zkrw .or. z2 < zkrn .or. z1 - z2 < dz .or. z4 < zkrw .or. z3 < zkrn &
            .or. z4 - z3 < dz) cycle                              ! L3779-3784
        s = z1 - z2
      case default
        if (z1 + z2 /= z4 - z3) cycle
        ! the listing tests Z2 only when L2 = L3 (L3761-3762, E-DZBPL-5)
        if (z2 < zkrn .or. z3 < zkrn .or. z4 < zkrw .or. z4 - z3 < dz) cycle
        s = z1 + z2
      end select
      if (.not. neighbours_clear(ks, max(z2, z3), s)) cycle       ! (6.5), E-DZBPL-3
      zub_z1 = int(z1)
      zub_z2 = int(z2)
      zub_z3 = int(z3)
      zub_z4 = int(z4)
      found = .true.
      return
    end do
  end subroutine dzbpl_corrected

  ! The listing (L3749-3791), FORTRAN integer arithmetic (division truncates toward 0).
  subroutine dzbpl_printed(ks, p, q, l2, l3, z1min, z1max, shema, found)
    integer, intent(in) :: ks, p, q, l2, l3, z1min, z1max, shema
    logical, intent(out) :: found
    integer(8) :: cot, cok, co, c1, z1, z2, z3, z4, pa
    found = .false.
    pa = abs(p)
    cot = (int(z1min, 8)*pa)/(int(ks, 8)*q)
    cok = (int(z1max, 8)*pa)/(int(ks, 8)*q)
    do co = cot, cok
      c1 = (int(ks, 8)*co*q)/pa
      if (c1 < z1min) cycle
      if (c1*pa - int(ks, 8)*q*co /= 0) cycle
      z1 = c1
      select case (shema)
      case (2)
        z2 = abs((z1*(int(p, 8)*l3 - int(q, 8)*l3 + int(q, 8)*l2))/(int(q, 8)*(l3 - l2)))
        z3 = z2*l3/l2
        z4 = (z1*l3*(int(q, 8) - p))/(int(l2, 8)*q)
        if (z2 < zub_zkrn .or. z3 < zub_zkrn .or. z4 < zub_zkrn) cycle
      case (3)
        z2 = abs((z1*(int(p, 8)*l3 - int(q, 8)*l3 + int(q, 8)*l2))/(int(q, 8)*(l2 - l3)))
        z3 = z2*l3/l2
        z4 = (z1*l3*(int(q, 8) - p))/(int(l2, 8)*q)        ! missing in print (E-DZBPL-2)
        if (z1 < zub_zkrw .or. z2 < zub_zkrn .or. z1 - z2 < zub_dz .or. z4 < zub_zkrw &
            .or. z3 < zub_zkrn .or. z4 - z3 < zub_dz) cycle
      case default
        z2 = abs((z1*(int(p, 8)*l3 - int(q, 8)*l3 - int(q, 8)*l2))/(int(q, 8)*(l2 + l3)))
        z3 = z2*l3/l2
        z4 = z1*l3*(int(p, 8) - q)/(int(l2, 8)*q)
        if (l2 == l3 .and. z2 < zub_zkrn) cycle
        if (z3 < zub_zkrn .or. z4 < zub_zkrw) cycle
        ! here the printed listing lacks GO TO 6 and falls into scheme 2 (E-DZBPL-1)
      end select
      zub_z1 = int(z1)
      zub_z2 = int(z2)
      zub_z3 = int(z3)
      zub_z4 = int(z4)
      found = .true.
      return
    end do
  end subroutine dzbpl_printed

  ! ============================================================================
  ! VI.3 DKRKT (L4019-4137): profile-shift coefficients and the operating angle
  ! ============================================================================
  ! AW /= 0: x1, x2 that fit the centre distance AW, (6.12)-(6.14).  AW = 0: SDVIG = 1 no
  ! undercut (x = x_min below 17 teeth, else 0); 2 contact strength (6.21); 3 wear (6.22),
  ! (6.23); then inv alpha_w = 2 (x1 + x2) tan(alpha)/(z1 + z2) + inv alpha.
  ! Checks (label 2, L4108-4112): x < X1P (undercut), x > X1Z = 0.15 z^0.7 (pointed); the
  ! book's message 22 (L4085, L4096: SDVIG = 1 with both x above X1Z, SDVIG = 3 with z2 < 17)
  ! and an AW at or below the sum of the base radii are st_requirement too.
  ! AW = 0 with SDVIG not 1, 2, 3: the computed GO TO falls through to SDVIG = 1 as printed;
  ! corrected mode refuses it (st_requirement).
  subroutine dkrkt(m, z1, z2, aw, sdvig, aaa, x1, x2, alfaw, ier)
    !: M : length -- Module (mm), > 0.
    !: Z1, Z2 : integer 8..10000 -- Tooth numbers of pinion and wheel (whole numbers, 8 to
    !:     10000).
    !: AW : real >= 0 -- Required centre distance (mm), or 0 to choose the shifts by SDVIG.
    !: SDVIG : integer 0..3 -- 0, 1, 2 or 3 (used only when AW = 0, where it must be 1, 2 or
    !:     3).
    !: AAA : flag -- 0 prints the book's report (FORMATs 25, 52, 55); anything else is
    !:     silent.
    real(dp), intent(in) :: m, z1, z2, aw, aaa
    integer, intent(in) :: sdvig
    real(dp), intent(out) :: x1, x2, alfaw
    integer, intent(out) :: ier
    real(dp) :: alfa0, a0, zs, x1z, x2z, x1p, x2p, y, c, xs, d, invw
    integer :: system
    x1 = 0.0_dp
    x2 = 0.0_dp
    alfaw = 0.0_dp
    ier = st_requirement
    if (.not. (m > 0.0_dp .and. z1 >= 1.0_dp .and. z2 >= 1.0_dp .and. aw >= 0.0_dp)) return
    alfa0 = pi/9.0_dp
    a0 = m*(z1 + z2)/2.0_dp
    zs = z1 + z2
    x1z = 0.15_dp*z1**0.7_dp
    x2z = 0.15_dp*z2**0.7_dp
    x1p = 1.0_dp - 0.5_dp*z1*sin(alfa0)**2
    x2p = 1.0_dp - 0.5_dp*z2*sin(alfa0)**2
    if (aw /= 0.0_dp) then
      y = (aw - a0)/m
      c = 0.5_dp*zs*cos(alfa0)/(y + 0.5_dp*zs)        ! (6.12), E-DKRKT-1
      if (.not. (c < 1.0_dp)) then                    ! AW <= r_b1 + r_b2: no mesh
        ier = st_no_mesh
        return
      end if
      alfaw = acos(c)
      xs = zs*(involute(alfaw) - involute(alfa0))/(2.0_dp*tan(alfa0))   ! (6.13)
      x1 = 0.5_dp*(xs - (z2 - z1)/zs*y)                                ! (6.14)
      x2 = xs - x1
    else
      system = sdvig
      if (system < 1 .or. system > 3) then
        ! as printed, GO TO (7, 8, 9) would fall through to SDVIG = 1 (E-DKRKT-4)
        ier = st_correction
        return
      end if
      select case (system)
      case (1)
        x1 = 0.0_dp
        if (z1 < 17.0_dp) x1 = x1p
        x2 = 0.0_dp
        if (z2 < 17.0_dp) x2 = x2p
        if (x1 - x1z > 0.0_dp .and. x2 - x2z > 0.0_dp) then
          x1 = 0.0_dp
          x2 = 0.0_dp
          ier = st_correction                         ! message 22
          return
        end if
      case (2)
        x1 = 0.0_dp
        if (.not. (z1 > 19.0_dp)) x1 = 1.0_dp/(1.0_dp + 0.086_dp*(z1 - 19.0_dp)**2) ! E-DKRKT-2
        x2 = -x1
      case (3)
        if (z2 < 17.0_dp) then
          ier = st_correction                         ! message 22
          return
        end if
        if (z1 > 17.0_dp) then
          d = -0.015_dp*(z1 - 17.0_dp)
        else
          d = -0.025_dp*(z1 - 17.0_dp)
        end if
        x1 = (z2 - 17.0_dp)/(2.05_dp*z2 - 7.3_dp) + d
        x2 = -x1
      end select
      invw = (x1 + x2)/zs*2.0_dp*tan(alfa0) + involute(alfa0)
      alfaw = angle_of_involute(invw)                 ! E-DKRKT-3
    end if
    ! label 2 (L4108-4112): undercut (message 20), then pointed teeth (message 21)
    if (x1 < x1p .or. x2 < x2p .or. x1 > x1z .or. x2 > x2z) then
      ier = st_pointed
      if (x1 < x1p .or. x2 < x2p) ier = st_undercut
      x1 = 0.0_dp
      x2 = 0.0_dp
      alfaw = 0.0_dp
      return
    end if
    ier = st_ok
  end subroutine dkrkt

  ! ============================================================================
  ! VI.4 DUGINV (L4153-4164, L4201-4217): the angle x from inv x = tan x - x
  ! ============================================================================
  ! as-printed: the book's fixed-point iteration x = ATAN(x + INVX) from XNACH, stopped
  ! when a step falls below TCHNST (or after 10**6 steps, E-DUGINV-2); it stops short of
  ! the root by about 6 TCHNST near 20 deg (E-DUGINV-1).
  ! corrected: the root to full double precision for every INVX >= 0 (a rational start
  ! and one Halley step on the series-accurate involute, inverse_involute above); XNACH and
  ! TCHNST are not needed.
  ! INVX < 0 (no angle of [0, pi/2)) is refused by the Python layer.
  real(dp) function duginv(invx, xnach, tchnst)
    !: INVX : real -- The involute, >= 0.
    !: XNACH : real -- Start of the book's iteration (every call of the book passes PI/18).
    !: TCHNST : length -- The book's tolerance on the step, > 0 (its comment: 0.00001 gives
    !:     one second of arc).
    real(dp), intent(in) :: invx, xnach, tchnst
    if (printed_mode /= 0) then
      if (tchnst > 0.0_dp) then
        duginv = book_duginv(invx, xnach, tchnst)
      else
        duginv = book_duginv(invx, xnach, epsilon(1.0_dp))
      end if
    else
      duginv = inverse_involute(max(invx, 0.0_dp))
    end if
  end function duginv

  ! ============================================================================
  ! VI.5 DGMTZK (L4245-4308): dimensions of one external gear (Table 22, L4230-4241)
  ! ============================================================================
  ! M normal module, Z teeth, BETA helix angle, X shift coefficient.  D reference, DB
  ! base, DA tip, DF root diameter; S, SB, SA tooth thickness (arc) on the reference, base
  ! and tip circles.
  ! corrected: transverse quantities throughout (alpha_t = atan(tan(alpha)/cos(beta)),
  ! S = m (pi/(2 cos beta) + 2 x tan(alpha_t)), DA = D + 2 (1 + x) m as Table 22 has it),
  ! E-DGMTZK-2; undercut (x below (6.17)), a tip circle inside the base circle and a
  ! pointed tooth (SA <= 0) are st_requirement.
  ! as-printed: S = pi m/2 + 2 x m tan(alpha_t), DA = m (z + 2 + 2x) and thicknesses with
  ! 2 x tan(alpha_t)/z, exact for spur gears only (Fig. 46 depends on them); no undercut
  ! check (Fig. 46's x = -1 gear is undercut, E-DGMTZK-4).
  ! sarkp extension: XUR, the tip shortening coefficient DA includes: always 0 (DA is
  ! Table 22's, with no shortening: DGMTZK does not know the mating gear; DGMZPC's DA1, DA2
  ! are the mesh's).  A diameter beyond double precision is st_range.
  subroutine dgmtzk(m, z, beta, x, aaa, d, s, db, sb, da, sa, df, xur, ier)
    !: M : length -- Normal module (mm), > 0.
    !: Z : integer 8..10000 -- Number of teeth (a whole number, 8 to 10000).
    !: BETA : real -- Helix angle (rad), |BETA| < pi/2; 0 for a spur gear.
    !: X : real -- Profile-shift coefficient.
    !: AAA : flag -- 0 prints the book's report (FORMATs 1-7, L4281-4306).
    real(dp), intent(in) :: m, z, beta, x, aaa
    real(dp), intent(out) :: d, s, db, sb, da, sa, df, xur
    integer, intent(out) :: ier
    real(dp) :: alfa, alfaa, p, invt
    call zero7(d, s, db, sb, da, sa, df)
    xur = 0.0_dp
    ier = st_requirement
    if (.not. (m > 0.0_dp .and. z >= 1.0_dp .and. abs(beta) < pi/2.0_dp)) return
    alfa = atan(tan(pi/9.0_dp)/cos(beta))
    p = pi*m
    d = m*z/cos(beta)
    db = d*cos(alfa)
    df = d - 2.0_dp*(1.25_dp - x)*m
    invt = involute(alfa)
    if (printed_mode /= 0) then
      s = p/2.0_dp + 2.0_dp*x*m*tan(alfa)
      da = m*(z + 2.0_dp + 2.0_dp*x)
      if (overflowed(d, db, da, df)) then
        ier = st_range
        return
      end if
      if (.not. (db < da)) then
        call zero7(d, s, db, sb, da, sa, df)
        ier = st_inside_base
        return
      end if
      alfaa = acos(db/da)
      sa = da*(pi/(2.0_dp*z) + 2.0_dp*x*tan(alfa)/z + invt - involute(alfaa))  ! E-DGMTZK-1
      sb = db*(pi/(2.0_dp*z) + 2.0_dp*x*tan(alfa)/z + invt)
    else
      if (x < undercut_limit(z, alfa, beta)) then
        call zero7(d, s, db, sb, da, sa, df)
        ier = st_undercut
        return
      end if
      s = m*(pi/(2.0_dp*cos(beta)) + 2.0_dp*x*tan(alfa))
      da = d + 2.0_dp*(1.0_dp + x)*m
      if (overflowed(d, db, da, df)) then
        ier = st_range
        return
      end if
      if (.not. (db < da)) then
        call zero7(d, s, db, sb, da, sa, df)
        ier = st_inside_base
        return
      end if
      alfaa = acos(db/da)
      sa = da*(s/d + invt - involute(alfaa))
      sb = db*(s/d + invt)
    end if
    if (.not. (sa > 0.0_dp)) then                     ! pointed: the flanks cross below DA
      call zero7(d, s, db, sb, da, sa, df)
      ier = st_pointed
      return
    end if
    ier = st_ok
  end subroutine dgmtzk

  ! A diameter that is not a finite double: DGMTZK's st_range (RangeError), its values
  ! left in place so that the error can name them.
  logical function overflowed(d, db, da, df)
    real(dp), intent(in) :: d, db, da, df
    overflowed = .not. (abs(d) <= huge(d) .and. abs(db) <= huge(db) .and. &
                        abs(da) <= huge(da) .and. abs(df) <= huge(df))
  end function overflowed

  subroutine zero7(a, b, c, d, e, f, g)
    real(dp), intent(out) :: a, b, c, d, e, f, g
    a = 0.0_dp
    b = 0.0_dp
    c = 0.0_dp
    d = 0.0_dp
    e = 0.0_dp
    f = 0.0_dp
    g = 0.0_dp
  end subroutine zero7

  ! ============================================================================
  ! VI.6 DGMZPC (L4410-4454): external involute mesh (Table 23, L4398-4408)
  ! ============================================================================
  ! Results in COMMON /ZPC/: A reference centre distance, XS = x1 + x2, ALFAW operating
  ! (transverse) pressure angle, AW centre distance, XY = y centre-distance coefficient,
  ! XUR = dy tip shortening, E = eps_alpha + eps_beta.  sarkp extension, after them: the tip
  ! diameters DA1, DA2 (with the shortening), the pressure angles ALFAA1, ALFAA2 and the
  ! (transverse, arc) tooth thicknesses SA1, SA2 on those circles.
  ! corrected: alpha_w to full precision; the tip diameters d + 2 (1 + x - dy) m and base
  ! diameters d cos(alpha_t) of helical gears (E-DGMZPC-3), eps_beta = BW |sin beta|/(pi m);
  ! undercut, pointed teeth (tip thickness <= 0 on the shortened tip), a tip inside the
  ! base circle and inv alpha_w < 0 are st_requirement.
  ! as-printed: DUGINV's iteration (E-DUGINV-1), the spur tip formulas m z + 2(1+x-dy) m
  ! and arccos(m z cos(alpha)/DA) for every beta (Fig. 47b, beta = 16 deg, depends on them).
  subroutine dgmzpc(m, z1, z2, beta, x1, x2, bw, aaa, ier)
    !sarkp common: a => zpc_a, xs => zpc_xs, alfaw => zpc_alfaw, aw => zpc_aw
    !sarkp common: xy => zpc_xy, xur => zpc_xur, e => zpc_e
    !sarkp common: da1 => zpc_da1, da2 => zpc_da2, alfaa1 => zpc_alfaa1
    !sarkp common: alfaa2 => zpc_alfaa2, sa1 => zpc_sa1, sa2 => zpc_sa2
    !: M : length -- Normal module (mm), > 0.
    !: Z1, Z2 : integer 8..10000 -- Tooth numbers (whole numbers, 8 to 10000).
    !: BETA : real -- Helix angle (rad), |BETA| < pi/2.
    !: X1, X2 : real -- Shift coefficients.
    !: BW : real >= 0 -- Face width (mm), >= 0.
    !: AAA : flag -- 0 prints the book's report (FORMAT 1, L4445-4452).
    real(dp), intent(in) :: m, z1, z2, beta, x1, x2, bw, aaa
    integer, intent(out) :: ier
    real(dp) :: alfa, alfat, invalw, alfaw, aw, xy, xur, da1, da2, db1, db2, ala1, ala2, &
                ealfa, ebeta, d1, d2, a, xs, s1, s2
    call zpc_zero()
    ier = st_requirement
    if (.not. (m > 0.0_dp .and. z1 >= 1.0_dp .and. z2 >= 1.0_dp .and. &
               abs(beta) < pi/2.0_dp .and. bw >= 0.0_dp)) return
    alfa = pi/9.0_dp
    alfat = atan(tan(alfa)/cos(beta))
    a = (z1 + z2)*m/(2.0_dp*cos(beta))
    xs = x1 + x2
    invalw = (2.0_dp*xs*tan(alfa))/(z1 + z2) + involute(alfat)
    if (.not. (invalw >= 0.0_dp)) then                ! x1 + x2 too negative: no mesh
      ier = st_no_mesh
      return
    end if
    alfaw = angle_of_involute(invalw)                 ! E-DGMZPC-1
    aw = (z1 + z2)*m*cos(alfat)/(2.0_dp*cos(beta)*cos(alfaw))   ! E-DGMZPC-2
    xy = (aw - a)/m
    xur = xs - xy
    if (printed_mode /= 0) then                       ! spur formulas (E-DGMZPC-3)
      d1 = m*z1
      d2 = m*z2
      db1 = m*z1*cos(alfa)
      db2 = m*z2*cos(alfa)
    else
      if (x1 < undercut_limit(z1, alfat, beta) .or. x2 < undercut_limit(z2, alfat, beta)) then
        ier = st_undercut
        return
      end if
      d1 = m*z1/cos(beta)
      d2 = m*z2/cos(beta)
      db1 = d1*cos(alfat)
      db2 = d2*cos(alfat)
    end if
    da1 = d1 + 2.0_dp*(1.0_dp + x1 - xur)*m
    da2 = d2 + 2.0_dp*(1.0_dp + x2 - xur)*m
    if (.not. (db1 < da1 .and. db2 < da2)) then
      ier = st_inside_base
      return
    end if
    ala1 = acos(db1/da1)
    ala2 = acos(db2/da2)
    ! tooth thickness on the (shortened) tip circles: pointed teeth are refused
    s1 = da1*((pi/2.0_dp + 2.0_dp*x1*tan(alfa))/z1 + involute(alfat) - involute(ala1))
    s2 = da2*((pi/2.0_dp + 2.0_dp*x2*tan(alfa))/z2 + involute(alfat) - involute(ala2))
    if (.not. (s1 > 0.0_dp .and. s2 > 0.0_dp)) then
      ier = st_pointed
      return
    end if
    ealfa = (z1*tan(ala1) + z2*tan(ala2) - (z1 + z2)*tan(alfaw))/(2.0_dp*pi)
    if (printed_mode /= 0) then
      ebeta = bw*sin(beta)/(pi*m)
    else
      ebeta = bw*abs(sin(beta))/(pi*m)
    end if
    zpc_a = a
    zpc_xs = xs
    zpc_alfaw = alfaw
    zpc_aw = aw
    zpc_xy = xy
    zpc_xur = xur
    zpc_e = ealfa + ebeta
    zpc_da1 = da1
    zpc_da2 = da2
    zpc_alfaa1 = ala1
    zpc_alfaa2 = ala2
    zpc_sa1 = s1
    zpc_sa2 = s2
    ier = st_ok
  end subroutine dgmzpc

  subroutine zpc_zero()
    zpc_a = 0.0_dp
    zpc_xs = 0.0_dp
    zpc_alfaw = 0.0_dp
    zpc_aw = 0.0_dp
    zpc_xy = 0.0_dp
    zpc_xur = 0.0_dp
    zpc_e = 0.0_dp
    zpc_da1 = 0.0_dp
    zpc_da2 = 0.0_dp
    zpc_alfaa1 = 0.0_dp
    zpc_alfaa2 = 0.0_dp
    zpc_sa1 = 0.0_dp
    zpc_sa2 = 0.0_dp
  end subroutine zpc_zero

  ! ============================================================================
  ! VI.7 DGMZVN (L4512-4631): internal involute mesh, wheel cut by a shaper
  ! (Tables 24-25, L4489-4510, L4637-4646)
  ! ============================================================================
  ! Z1 pinion (external teeth), Z2 wheel (internal teeth), X1, X2 their shifts; the
  ! shaper that cuts the wheel: ZO2 teeth, DO reference diameter (unused, as printed),
  ! XO shift, DAO tip diameter.  Spur gears.  Results in COMMON /ZVN/.
  ! Internal-mesh formulas throughout: inv alpha_w = inv alpha + 2 (x2 - x1) tan(alpha) /
  ! (z2 - z1), a = m (z2 - z1)/2, eps_alpha = (z1 tan alpha_a1 - z2 tan alpha_a2 +
  ! (z2 - z1) tan alpha_w)/(2 pi), the wheel's tip thickness with the internal signs.
  ! Refused (st_requirement): z2 <= z1, z2 <= ZO2, a negative involute, a tip circle inside
  ! its base circle, pointed teeth (SA1 or SA2 <= 0), and (corrected) an undercut pinion.
  subroutine dgmzvn(m, z1, z2, x1, x2, zo2, do, xo, dao, aaa, ier)
    !sarkp common: a => zvn_a, xd => zvn_xd, alfaw => zvn_alfaw, aw => zvn_aw
    !sarkp common: d1 => zvn_d1, d2 => zvn_d2, dw1 => zvn_dw1, dw2 => zvn_dw2
    !sarkp common: xy => zvn_xy, xur => zvn_xur, da1 => zvn_da1, da2 => zvn_da2
    !sarkp common: df1 => zvn_df1, df2 => zvn_df2, h1 => zvn_h1, h2 => zvn_h2
    !sarkp common: sa1 => zvn_sa1, sa2 => zvn_sa2, ealfa => zvn_ealfa
    !: M : length -- Module (mm), > 0.
    !: Z1 : integer 8..10000 -- Teeth of the pinion (external teeth).
    !: Z2 : integer 9..10000 -- Teeth of the wheel (internal teeth), > Z1.
    !: X1, X2 : real -- Shift coefficients of pinion and wheel (for the wheel positive away
    !:     from its axis: its teeth get thinner).
    !: ZO2, DO, XO, DAO : integer 8..10000; length; real; length -- The shaper that cuts the
    !:     wheel: teeth (< Z2), reference diameter (> 0, unused, as in the book), shift
    !:     coefficient, tip diameter (> 0).
    !: AAA : flag -- 0 prints the book's report (FORMATs 1, 2, L4604-4630).
    real(dp), intent(in) :: m, z1, z2, x1, x2, zo2, do, xo, dao, aaa
    integer, intent(out) :: ier
    real(dp) :: alfa, a, xd, invalw, alfaw, aw, d1, d2, u, dw1, dw2, xy, xur, invo2, alfao2, &
                awo2, xyo2, xuro2, k2, da1, da2, df1, df2, h1, h2, ala1, ala2, ealfa, sa1, sa2
    call zvn_zero()
    ier = st_requirement
    if (.not. (m > 0.0_dp .and. z1 >= 1.0_dp .and. z2 > z1 .and. zo2 >= 1.0_dp .and. &
               z2 > zo2 .and. dao > 0.0_dp)) return
    alfa = pi/9.0_dp
    a = m*(z2 - z1)/2.0_dp
    xd = x2 - x1
    invalw = involute(alfa) + 2.0_dp*xd*tan(alfa)/(z2 - z1)
    if (.not. (invalw >= 0.0_dp)) then
      ier = st_no_mesh
      return
    end if
    alfaw = angle_of_involute(invalw)                 ! E-DGMZVN-1
    aw = a*cos(alfa)/cos(alfaw)
    d1 = m*z1
    d2 = m*z2
    u = z2/z1
    dw1 = 2.0_dp*aw/(u - 1.0_dp)
    dw2 = 2.0_dp*aw*u/(u - 1.0_dp)
    xy = (aw - a)/m
    xur = xd - xy
    ! machine mesh of the wheel with the shaper (Table 25)
    invo2 = 2.0_dp*(x2 - xo)*tan(alfa)/(z2 - zo2) + involute(alfa)
    if (.not. (invo2 >= 0.0_dp)) then
      ier = st_no_mesh
      return
    end if
    alfao2 = angle_of_involute(invo2)
    awo2 = (z2 - zo2)*m*cos(alfa)/(2.0_dp*cos(alfao2))
    xyo2 = awo2/m - (z2 - zo2)/2.0_dp
    xuro2 = x2 - xo - xyo2
    k2 = 0.25_dp - 0.125_dp*x2
    da1 = d1 + 2.0_dp*(1.0_dp + x1 + xur - xuro2)*m
    da2 = d2 - 2.0_dp*(1.0_dp - x2 + xur - k2)*m
    df1 = d1 - 2.0_dp*(1.25_dp - x1)*m
    df2 = 2.0_dp*awo2 + dao
    h1 = (da1 - df1)/2.0_dp
    h2 = (df2 - da2)/2.0_dp
    if (printed_mode == 0 .and. x1 < undercut_limit(z1, alfa, 0.0_dp)) then
      ier = st_undercut
      return
    end if
    if (.not. (m*z1*cos(alfa) < da1 .and. m*z2*cos(alfa) < da2)) then
      ier = st_inside_base
      return
    end if
    ala1 = acos(m*z1*cos(alfa)/da1)
    ala2 = acos(m*z2*cos(alfa)/da2)
    ealfa = (z1*tan(ala1) - z2*tan(ala2) + (z2 - z1)*tan(alfaw))/(2.0_dp*pi)  ! E-DGMZVN-2
    sa1 = da1*((0.5_dp*pi + 2.0_dp*x1*tan(alfa))/z1 + involute(alfa) - involute(ala1))
    sa2 = da2*((0.5_dp*pi - 2.0_dp*x2*tan(alfa))/z2 - involute(alfa) + involute(ala2)) ! E-DGMZVN-3
    if (.not. (sa1 > 0.0_dp .and. sa2 > 0.0_dp)) then
      ier = st_pointed
      return
    end if
    zvn_a = a
    zvn_xd = xd
    zvn_alfaw = alfaw
    zvn_aw = aw
    zvn_d1 = d1
    zvn_d2 = d2
    zvn_dw1 = dw1
    zvn_dw2 = dw2
    zvn_xy = xy
    zvn_xur = xur
    zvn_da1 = da1
    zvn_da2 = da2
    zvn_df1 = df1
    zvn_df2 = df2
    zvn_h1 = h1
    zvn_h2 = h2
    zvn_sa1 = sa1
    zvn_sa2 = sa2
    zvn_ealfa = ealfa
    ier = st_ok
  end subroutine dgmzvn

  subroutine zvn_zero()
    zvn_a = 0.0_dp
    zvn_xd = 0.0_dp
    zvn_alfaw = 0.0_dp
    zvn_aw = 0.0_dp
    zvn_d1 = 0.0_dp
    zvn_d2 = 0.0_dp
    zvn_dw1 = 0.0_dp
    zvn_dw2 = 0.0_dp
    zvn_xy = 0.0_dp
    zvn_xur = 0.0_dp
    zvn_da1 = 0.0_dp
    zvn_da2 = 0.0_dp
    zvn_df1 = 0.0_dp
    zvn_df2 = 0.0_dp
    zvn_h1 = 0.0_dp
    zvn_h2 = 0.0_dp
    zvn_sa1 = 0.0_dp
    zvn_sa2 = 0.0_dp
    zvn_ealfa = 0.0_dp
  end subroutine zvn_zero

  ! ============================================================================
  ! VI.8 DCHRVC (L4737-4824): cylindrical worm gearing (Table 26, L4687-4703)
  ! ============================================================================
  ! M axial module, Q diameter factor, Z1 worm starts, Z2 wheel teeth, AW centre distance.
  ! Results in COMMON /CHRVC/: X wheel shift, D1, D2 reference diameters, DW1 worm's
  ! operating diameter, G, GW lead angles (reference, operating), H1 thread depth, HA1
  ! addendum, DA1, DA2 tip diameters, DAM2 the wheel's largest diameter, B1 worm's
  ! threaded length, B2 wheel face width, R throat radius.  The same in both modes.
  ! Refused (st_requirement): DW1 <= 0 (x <= -q/2), a wheel tip diameter <= 0.
  subroutine dchrvc(m, q, z1, z2, aw, aaa, ier)
    !sarkp common: x => chrvc_x, d1 => chrvc_d1, d2 => chrvc_d2, dw1 => chrvc_dw1
    !sarkp common: g => chrvc_g, gw => chrvc_gw, h1 => chrvc_h1, ha1 => chrvc_ha1
    !sarkp common: da1 => chrvc_da1, da2 => chrvc_da2, dam2 => chrvc_dam2, b1 => chrvc_b1
    !sarkp common: b2 => chrvc_b2, r => chrvc_r
    !: M : length -- Axial module (mm), > 0.
    !: Q : length -- Diameter factor q of the worm, > 0.
    !: Z1 : integer 1..100 -- Number of starts of the worm (whole).
    !: Z2 : integer 1..10000 -- Teeth of the worm wheel (whole).
    !: AW : length -- Centre distance (mm), > M Z2/2.
    !: AAA : flag -- 0 prints the book's report (FORMAT 1, L4795-4822).
    real(dp), intent(in) :: m, q, z1, z2, aw, aaa
    integer, intent(out) :: ier
    real(dp) :: x, dw1, da2
    call chrvc_zero()
    ier = st_requirement
    if (.not. (m > 0.0_dp .and. q > 0.0_dp .and. z1 >= 1.0_dp .and. z2 >= 1.0_dp .and. &
               aw > 0.0_dp)) return
    x = aw/m - 0.5_dp*(z2 + q)
    dw1 = (q + 2.0_dp*x)*m
    da2 = z2*m + 2.0_dp*(1.0_dp + x)*m
    if (.not. (dw1 > 0.0_dp .and. da2 > 0.0_dp)) then
      ier = st_no_mesh
      return
    end if
    chrvc_x = x
    chrvc_d1 = q*m
    chrvc_d2 = z2*m
    chrvc_dw1 = dw1
    chrvc_g = atan(z1/q)
    chrvc_gw = atan(z1*m/dw1)
    chrvc_h1 = 2.2_dp*m
    chrvc_ha1 = m
    chrvc_da1 = chrvc_d1 + 2.0_dp*m
    chrvc_da2 = da2
    chrvc_dam2 = da2 + 6.0_dp*m/(z1 + 2.0_dp)
    chrvc_b1 = (11.0_dp + 0.1_dp*z2)*m
    chrvc_b2 = 0.75_dp*chrvc_da1
    chrvc_r = 0.5_dp*chrvc_d1 - m
    ier = st_ok
  end subroutine dchrvc

  subroutine chrvc_zero()
    chrvc_x = 0.0_dp
    chrvc_d1 = 0.0_dp
    chrvc_d2 = 0.0_dp
    chrvc_dw1 = 0.0_dp
    chrvc_g = 0.0_dp
    chrvc_gw = 0.0_dp
    chrvc_h1 = 0.0_dp
    chrvc_ha1 = 0.0_dp
    chrvc_da1 = 0.0_dp
    chrvc_da2 = 0.0_dp
    chrvc_dam2 = 0.0_dp
    chrvc_b1 = 0.0_dp
    chrvc_b2 = 0.0_dp
    chrvc_r = 0.0_dp
  end subroutine chrvc_zero

end module gears
