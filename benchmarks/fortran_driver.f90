! fortran_driver.f90 -- the pure-Fortran baseline of benchmarks/bench_kinematics.py.
!
! Drives the same chapter-4 routines (kinematics.f90) as the Python paths, over N crank
! positions phi_i = 2*pi*(i-1)/N, with a plain DO loop: no Python, no f2py, no checks.
! bench_kinematics.py compiles it with gfortran -O3 against fortran/{prmtr,gelg,operators,
! kinematics}.f90 and -llapack, writes the namelist file given as the only argument, and
! reads the timings from standard output ("case level ns-per-position").  The results of
! the full kinematics of both mechanisms are dumped (stream access, real(8), array after
! array) so that the benchmark can check they are the array path's.
!
! Mechanisms (the geometry comes from the namelist):
!   fourbar: crank OA about O = (0, 0), RRR group A-B-C with C fixed (DPRM1 P = -1,
!            DKNMA1 P = +1: the same branch);
!   course : the course project of chapter 10 (Fig. 91): the same four-bar, the lever
!            point D = C + RCD*e(FI3 + pi), then the RRP group D-E with E on the
!            horizontal guide y = YG (DPRM2 FIM = 0, DKNMA2 P = +1).
! Levels: 1 positions, 2 positions + velocities, 3 full (with accelerations).
! Variants: split = DPRM/DSKOR/DUSKR; dknma = DKNMA (ANALOG = 1 for level 2).
program fortran_driver
  use prmtr, only: dp, pi, pid2, set_mode
  use operators, only: dugl3
  use kinematics, only: dprm1, dprm2, dskor1, dskor2, duskr1, duskr2, dknma1, dknma2
  implicit none

  integer :: n = 100000, reps = 7
  real(dp) :: w1 = 1.0_dp
  real(dp) :: fb_roa = 0, fb_rab = 0, fb_rcb = 0, fb_xc = 0, fb_yc = 0
  real(dp) :: cp_roa = 0, cp_rab = 0, cp_rcb = 0, cp_rcd = 0, cp_rde = 0, cp_xc = 0, &
              cp_yc = 0, cp_yg = 0
  character(len=1024) :: dumpfile = ''
  namelist /geom/ n, reps, w1, fb_roa, fb_rab, fb_rcb, fb_xc, fb_yc, cp_roa, cp_rab, &
                  cp_rcb, cp_rcd, cp_rde, cp_xc, cp_yc, cp_yg, dumpfile

  ! outputs, one array per quantity (kept so that no work can be optimised away)
  real(dp), allocatable :: phi(:), xb(:), yb(:), fi2(:), fi3(:), vb(:), alb(:), w2(:), &
                           w3(:), ab(:), bb(:), e2(:), e3(:), fide(:), xe(:), ve(:), &
                           ale(:), w4(:), ae(:), be(:), e4(:)
  integer, allocatable :: ier(:)
  character(len=1024) :: path
  integer :: u, i

  call get_command_argument(1, path)
  open (newunit=u, file=trim(path), status='old', action='read')
  read (u, nml=geom)
  close (u)
  call set_mode(0)                                ! corrected mode: exact pi

  allocate (phi(n), xb(n), yb(n), fi2(n), fi3(n), vb(n), alb(n), w2(n), w3(n), ab(n), &
            bb(n), e2(n), e3(n), fide(n), xe(n), ve(n), ale(n), w4(n), ae(n), be(n), &
            e4(n), ier(n))
  do i = 1, n
    phi(i) = 2.0_dp*pi*real(i - 1, dp)/real(n, dp)
  end do

  call time_case('fourbar_split', 1)
  call time_case('fourbar_split', 2)
  call time_case('fourbar_dknma', 2)
  call time_case('fourbar_dknma', 3)
  call time_case('fourbar_split', 3)                 ! last fourbar case: dumped
  if (len_trim(dumpfile) > 0) then
    open (newunit=u, file=trim(dumpfile)//'.fourbar', access='stream', form='unformatted', &
          status='replace', action='write')
    write (u) xb, yb, fi2, fi3, vb, alb, w2, w3, ab, bb, e2, e3
    close (u)
  end if
  call time_case('course_split', 1)
  call time_case('course_split', 2)
  call time_case('course_dknma', 2)
  call time_case('course_dknma', 3)
  call time_case('course_split', 3)
  if (len_trim(dumpfile) > 0) then
    open (newunit=u, file=trim(dumpfile)//'.course', access='stream', form='unformatted', &
          status='replace', action='write')
    write (u) xb, yb, fi2, fi3, vb, alb, w2, w3, ab, bb, e2, e3, fide, xe, ve, ale, w4, ae, &
              be, e4
    close (u)
  end if

contains

  subroutine time_case(name, level)
    character(len=*), intent(in) :: name
    integer, intent(in) :: level
    real(dp) :: best, t, t0, t1
    integer :: r
    best = huge(1.0_dp)
    do r = 1, reps                      ! CPU time of the process, as the Python timings
      call cpu_time(t0)
      select case (name)
      case ('fourbar_split')
        call fourbar_split(level)
      case ('fourbar_dknma')
        call fourbar_dknma(level)
      case ('course_split')
        call course_split(level)
      case ('course_dknma')
        call course_dknma(level)
      end select
      call cpu_time(t1)
      t = t1 - t0
      best = min(best, t)
    end do
    write (*, '(a, 1x, i1, 1x, es12.5, 1x, i0, 1x, es23.15)') name, level, best/n*1.0e9_dp, &
        maxval(ier), sum(xb) + sum(vb) + sum(ab) + sum(xe) + sum(ve) + sum(ae)
  end subroutine time_case

  subroutine fourbar_split(level)
    integer, intent(in) :: level
    real(dp) :: xa, ya, va, ala, aa, ba, vba, alba, vbc, albc, abat, bbat, abct, bbct
    integer :: i, st
    do i = 1, n
      xa = fb_roa*cos(phi(i))
      ya = fb_roa*sin(phi(i))
      call dprm1(xa, ya, fb_xc, fb_yc, fb_rab, fb_rcb, -1.0_dp, 1.0_dp, fi2(i), fi3(i), &
                 xb(i), yb(i), ier(i))
      if (level < 2) cycle
      va = w1*fb_roa
      ala = phi(i) + pid2
      call dskor1(fb_rab, fi2(i), fb_rcb, fi3(i), va, ala, 0.0_dp, 0.0_dp, 1.0_dp, vba, alba, &
                  vbc, albc, vb(i), alb(i), w2(i), w3(i), st)
      ier(i) = max(ier(i), st)
      if (level < 3) cycle
      aa = w1**2*fb_roa
      ba = phi(i) + pi
      call duskr1(aa, ba, 0.0_dp, 0.0_dp, fb_rab, fi2(i), fb_rcb, fi3(i), w2(i), w3(i), &
                  1.0_dp, abat, bbat, abct, bbct, ab(i), bb(i), e2(i), e3(i), st)
      ier(i) = max(ier(i), st)
    end do
  end subroutine fourbar_split

  subroutine fourbar_dknma(level)
    integer, intent(in) :: level
    real(dp) :: xa, ya, va, ala, aa, ba, vba, alba, vbc, albc, abcn, aban, abat, bbat, abct, &
                bbct, analog
    integer :: i
    analog = merge(1.0_dp, 0.0_dp, level < 3)
    do i = 1, n
      xa = fb_roa*cos(phi(i))
      ya = fb_roa*sin(phi(i))
      va = w1*fb_roa
      ala = phi(i) + pid2
      aa = w1**2*fb_roa
      ba = phi(i) + pi
      call dknma1(xa, ya, fb_xc, fb_yc, fb_rab, fb_rcb, va, ala, 0.0_dp, 0.0_dp, aa, ba, &
                  0.0_dp, 0.0_dp, 1.0_dp, analog, xb(i), yb(i), fi2(i), fi3(i), vba, alba, &
                  vbc, albc, vb(i), alb(i), w2(i), w3(i), abcn, aban, abat, bbat, abct, bbct, &
                  ab(i), bb(i), e2(i), e3(i), ier(i))
    end do
  end subroutine fourbar_dknma

  subroutine course_split(level)
    integer, intent(in) :: level
    real(dp) :: xa, ya, va, ala, aa, ba, vba, alba, vbc, albc, abat, bbat, abct, bbct
    real(dp) :: xd, yd, ye, vd, ald, ad, bd, ved, aled, veg, aleg, aedt, bedt, aeg, beg
    integer :: i, st
    do i = 1, n
      xa = cp_roa*cos(phi(i))
      ya = cp_roa*sin(phi(i))
      call dprm1(xa, ya, cp_xc, cp_yc, cp_rab, cp_rcb, -1.0_dp, 1.0_dp, fi2(i), fi3(i), &
                 xb(i), yb(i), ier(i))
      xd = cp_xc + cp_rcd*cos(fi3(i) + pi)
      yd = cp_yc + cp_rcd*sin(fi3(i) + pi)
      call dprm2(xd, yd, 0.0_dp, cp_yg, 0.0_dp, cp_rde, 0.0_dp, pid2, 1.0_dp, xe(i), ye, &
                 fide(i), st)
      ier(i) = max(ier(i), st)
      if (level < 2) cycle
      va = w1*cp_roa
      ala = phi(i) + pid2
      call dskor1(cp_rab, fi2(i), cp_rcb, fi3(i), va, ala, 0.0_dp, 0.0_dp, 1.0_dp, vba, alba, &
                  vbc, albc, vb(i), alb(i), w2(i), w3(i), st)
      ier(i) = max(ier(i), st)
      vd = cp_rcd*abs(w3(i))
      ald = dugl3(fi3(i) + pi, pid2, w3(i))
      call dskor2(vd, ald, 0.0_dp, 0.0_dp, cp_rde, fide(i), 0.0_dp, 1.0_dp, ved, aled, veg, &
                  aleg, ve(i), ale(i), w4(i), st)
      ier(i) = max(ier(i), st)
      if (level < 3) cycle
      aa = w1**2*cp_roa
      ba = phi(i) + pi
      call duskr1(aa, ba, 0.0_dp, 0.0_dp, cp_rab, fi2(i), cp_rcb, fi3(i), w2(i), w3(i), &
                  1.0_dp, abat, bbat, abct, bbct, ab(i), bb(i), e2(i), e3(i), st)
      ier(i) = max(ier(i), st)
      ad = cp_rcd*sqrt(w3(i)**4 + e3(i)**2)
      bd = dugl3(fi3(i) + pi, pi - atan2(abs(e3(i)), w3(i)**2), e3(i))
      call duskr2(ad, bd, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, cp_rde, fide(i), w4(i), 0.0_dp, &
                  1.0_dp, aedt, bedt, aeg, beg, e4(i), ae(i), be(i), st)
      ier(i) = max(ier(i), st)
    end do
  end subroutine course_split

  subroutine course_dknma(level)
    integer, intent(in) :: level
    real(dp) :: xa, ya, va, ala, aa, ba, vba, alba, vbc, albc, abcn, aban, abat, bbat, abct, &
                bbct, analog
    real(dp) :: xd, yd, vd, ald, ad, bd, ye, ved, aled, vbbm, albbm, aban2, abk, bbk, abat2, &
                bbat2, abbm, bbbm
    integer :: i, st
    analog = merge(1.0_dp, 0.0_dp, level < 3)
    do i = 1, n
      xa = cp_roa*cos(phi(i))
      ya = cp_roa*sin(phi(i))
      va = w1*cp_roa
      ala = phi(i) + pid2
      aa = w1**2*cp_roa
      ba = phi(i) + pi
      call dknma1(xa, ya, cp_xc, cp_yc, cp_rab, cp_rcb, va, ala, 0.0_dp, 0.0_dp, aa, ba, &
                  0.0_dp, 0.0_dp, 1.0_dp, analog, xb(i), yb(i), fi2(i), fi3(i), vba, alba, &
                  vbc, albc, vb(i), alb(i), w2(i), w3(i), abcn, aban, abat, bbat, abct, bbct, &
                  ab(i), bb(i), e2(i), e3(i), ier(i))
      xd = cp_xc + cp_rcd*cos(fi3(i) + pi)
      yd = cp_yc + cp_rcd*sin(fi3(i) + pi)
      vd = cp_rcd*abs(w3(i))
      ald = dugl3(fi3(i) + pi, pid2, w3(i))
      ad = 0.0_dp
      bd = 0.0_dp
      if (level == 3) then
        ad = cp_rcd*sqrt(w3(i)**4 + e3(i)**2)
        bd = dugl3(fi3(i) + pi, pi - atan2(abs(e3(i)), w3(i)**2), e3(i))
      end if
      call dknma2(xd, yd, 0.0_dp, cp_yg, 0.0_dp, cp_rde, 0.0_dp, pid2, vd, ald, 0.0_dp, &
                  0.0_dp, 0.0_dp, ad, bd, 0.0_dp, 0.0_dp, 1.0_dp, analog, xe(i), ye, fide(i), &
                  ved, aled, vbbm, albbm, ve(i), ale(i), w4(i), aban2, abk, bbk, abat2, bbat2, &
                  abbm, bbbm, ae(i), be(i), e4(i), st)
      ier(i) = max(ier(i), st)
    end do
  end subroutine course_dknma

end program fortran_driver
