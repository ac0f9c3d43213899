! sweeps_kinematics.f90 -- array drivers for chapter 4 (kinematics.f90): one Fortran loop
! over positions per routine, so that the Python layer computes a whole sweep in one call.
! Every input is an array of length N (the Python layer broadcasts); AAA, the book's print
! flag, is left out; ANALOG of the DKNMA routines stays a scalar (one choice per sweep).
! STATUS(i) is the IER of element i (prmtr status codes); failed elements hold zeros.
! No allocation inside the loops.
module sweeps_kinematics
  use prmtr, only: dp
  use kinematics
  implicit none
  private
  public :: dprm1_sweep, dprm2_sweep, dprm3_sweep, dprm4_sweep, dprm5_sweep, &
            dskor1_sweep, dskor2_sweep, dskor3_sweep, dskor4_sweep, dskor5_sweep, &
            duskr1_sweep, duskr2_sweep, duskr3_sweep, duskr4_sweep, duskr5_sweep, &
            dknma1_sweep, dknma2_sweep, dknma3_sweep, dknma4_sweep, dknma5_sweep

contains

  subroutine dprm1_sweep(n, xa, ya, xc, yc, rz2, rz3, p, fi2, fi3, xb, yb, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xc(n), yc(n), rz2(n), rz3(n), p(n)
    real(dp), intent(out) :: fi2(n), fi3(n), xb(n), yb(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dprm1(xa(i), ya(i), xc(i), yc(i), rz2(i), rz3(i), p(i), 1.0_dp, fi2(i), fi3(i), &
          xb(i), yb(i), status(i))
    end do
  end subroutine dprm1_sweep

  subroutine dprm2_sweep(n, xa, ya, xk, yk, fim, rz2, rz3, t, xb, yb, fi2, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xk(n), yk(n), fim(n), rz2(n), rz3(n), t(n)
    real(dp), intent(out) :: xb(n), yb(n), fi2(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dprm2(xa(i), ya(i), xk(i), yk(i), fim(i), rz2(i), rz3(i), t(i), 1.0_dp, xb(i), &
          yb(i), fi2(i), status(i))
    end do
  end subroutine dprm2_sweep

  subroutine dprm3_sweep(n, xa, ya, xc, yc, rz2, t, p, rzac, fi3, fica, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xc(n), yc(n), rz2(n), t(n), p(n)
    real(dp), intent(out) :: rzac(n), fi3(n), fica(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dprm3(xa(i), ya(i), xc(i), yc(i), rz2(i), t(i), p(i), 1.0_dp, rzac(i), fi3(i), &
          fica(i), status(i))
    end do
  end subroutine dprm3_sweep

  subroutine dprm4_sweep(n, xvm, yvm, xa, ya, fim, xvn, yvn, xc, yc, fin, rz2, t2, rz3, t3, &
      xb, yb, rvbm, fivbm, rvbn, fivbn, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xvm(n), yvm(n), xa(n), ya(n), fim(n), xvn(n), yvn(n), xc(n), &
        yc(n), fin(n), rz2(n), t2(n), rz3(n), t3(n)
    real(dp), intent(out) :: xb(n), yb(n), rvbm(n), fivbm(n), rvbn(n), fivbn(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dprm4(xvm(i), yvm(i), xa(i), ya(i), fim(i), xvn(i), yvn(i), xc(i), yc(i), fin(i), &
          rz2(i), t2(i), rz3(i), t3(i), 1.0_dp, xb(i), yb(i), rvbm(i), fivbm(i), rvbn(i), &
          fivbn(i), status(i))
    end do
  end subroutine dprm4_sweep

  subroutine dprm5_sweep(n, xa, ya, fim, xc, yc, t2, xk, yk, s2, s3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), fim(n), xc(n), yc(n), t2(n)
    real(dp), intent(out) :: xk(n), yk(n), s2(n), s3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dprm5(xa(i), ya(i), fim(i), xc(i), yc(i), t2(i), 1.0_dp, xk(i), yk(i), s2(i), &
          s3(i), status(i))
    end do
  end subroutine dprm5_sweep

  subroutine dskor1_sweep(n, rz2, fi2, rz3, fi3, va, ala, vc, alc, vba, alba, vbc, albc, vb, &
      alb, w2, w3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: rz2(n), fi2(n), rz3(n), fi3(n), va(n), ala(n), vc(n), alc(n)
    real(dp), intent(out) :: vba(n), alba(n), vbc(n), albc(n), vb(n), alb(n), w2(n), w3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dskor1(rz2(i), fi2(i), rz3(i), fi3(i), va(i), ala(i), vc(i), alc(i), 1.0_dp, &
          vba(i), alba(i), vbc(i), albc(i), vb(i), alb(i), w2(i), w3(i), status(i))
    end do
  end subroutine dskor1_sweep

  subroutine dskor2_sweep(n, va, ala, vbm, albm, rz2, fi2, fim, vba, alba, vbbm, albbm, vb, &
      alb, w2, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: va(n), ala(n), vbm(n), albm(n), rz2(n), fi2(n), fim(n)
    real(dp), intent(out) :: vba(n), alba(n), vbbm(n), albbm(n), vb(n), alb(n), w2(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dskor2(va(i), ala(i), vbm(i), albm(i), rz2(i), fi2(i), fim(i), 1.0_dp, vba(i), &
          alba(i), vbbm(i), albbm(i), vb(i), alb(i), w2(i), status(i))
    end do
  end subroutine dskor2_sweep

  subroutine dskor3_sweep(n, xa, ya, xc, yc, va, ala, vc, alc, fi3, va3a, ala3a, va3c, ala3c, &
      va3, ala3, w3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xc(n), yc(n), va(n), ala(n), vc(n), alc(n), fi3(n)
    real(dp), intent(out) :: va3a(n), ala3a(n), va3c(n), ala3c(n), va3(n), ala3(n), w3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dskor3(xa(i), ya(i), xc(i), yc(i), va(i), ala(i), vc(i), alc(i), fi3(i), 1.0_dp, &
          va3a(i), ala3a(i), va3c(i), ala3c(i), va3(i), ala3(i), w3(i), status(i))
    end do
  end subroutine dskor3_sweep

  subroutine dskor4_sweep(n, rvbm, fivbm, fim, rvbn, fivbn, fin, wm, wn, vbbm, albbm, vbbn, &
      albbn, vb, alb, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: rvbm(n), fivbm(n), fim(n), rvbn(n), fivbn(n), fin(n), wm(n), wn(n)
    real(dp), intent(out) :: vbbm(n), albbm(n), vbbn(n), albbn(n), vb(n), alb(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dskor4(rvbm(i), fivbm(i), fim(i), rvbn(i), fivbn(i), fin(i), wm(i), wn(i), 1.0_dp, &
          vbbm(i), albbm(i), vbbn(i), albbn(i), vb(i), alb(i), status(i))
    end do
  end subroutine dskor4_sweep

  subroutine dskor5_sweep(n, xc3, yc3, xvm, yvm, fim, t2, wm, vc3, alc3, vc2c3, alc2c3, &
      vc2cm, alc2cm, vc2, alc2, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xc3(n), yc3(n), xvm(n), yvm(n), fim(n), t2(n), wm(n), vc3(n), &
        alc3(n)
    real(dp), intent(out) :: vc2c3(n), alc2c3(n), vc2cm(n), alc2cm(n), vc2(n), alc2(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dskor5(xc3(i), yc3(i), xvm(i), yvm(i), fim(i), t2(i), wm(i), vc3(i), alc3(i), &
          1.0_dp, vc2c3(i), alc2c3(i), vc2cm(i), alc2cm(i), vc2(i), alc2(i), status(i))
    end do
  end subroutine dskor5_sweep

  subroutine duskr1_sweep(n, aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3, abat, bbat, abct, &
      bbct, ab, bb, e2, e3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: aa(n), ba(n), ac(n), bc(n), rz2(n), fi2(n), rz3(n), fi3(n), &
        w2(n), w3(n)
    real(dp), intent(out) :: abat(n), bbat(n), abct(n), bbct(n), ab(n), bb(n), e2(n), e3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call duskr1(aa(i), ba(i), ac(i), bc(i), rz2(i), fi2(i), rz3(i), fi3(i), w2(i), w3(i), &
          1.0_dp, abat(i), bbat(i), abct(i), bbct(i), ab(i), bb(i), e2(i), e3(i), status(i))
    end do
  end subroutine duskr1_sweep

  subroutine duskr2_sweep(n, aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim, abat, vbat, abvm, &
      bvbm, e2, ab, bb, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: aa(n), ba(n), abm(n), bvm(n), abk(n), bvk(n), rz2(n), fi2(n), &
        w2(n), fim(n)
    real(dp), intent(out) :: abat(n), vbat(n), abvm(n), bvbm(n), e2(n), ab(n), bb(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call duskr2(aa(i), ba(i), abm(i), bvm(i), abk(i), bvk(i), rz2(i), fi2(i), w2(i), &
          fim(i), 1.0_dp, abat(i), vbat(i), abvm(i), bvbm(i), e2(i), ab(i), bb(i), status(i))
    end do
  end subroutine duskr2_sweep

  subroutine duskr3_sweep(n, aa, ba, ac, bc, fi3, w3, rzac, fica, aa3ak, ba3ak, aa3ar, ba3ar, &
      aa3ct, ba3ct, e3, aa3, ba3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: aa(n), ba(n), ac(n), bc(n), fi3(n), w3(n), rzac(n), fica(n), &
        aa3ak(n), ba3ak(n)
    real(dp), intent(out) :: aa3ar(n), ba3ar(n), aa3ct(n), ba3ct(n), e3(n), aa3(n), ba3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call duskr3(aa(i), ba(i), ac(i), bc(i), fi3(i), w3(i), rzac(i), fica(i), aa3ak(i), &
          ba3ak(i), 1.0_dp, aa3ar(i), ba3ar(i), aa3ct(i), ba3ct(i), e3(i), aa3(i), ba3(i), &
          status(i))
    end do
  end subroutine duskr3_sweep

  subroutine duskr4_sweep(n, rvbm, fivbm, fim, rvbn, fivbn, fin, wm, em, wn, en, abbmk, &
      bbbmk, abbnk, bbbnk, abbmr, bbbmr, abbnr, bbbnr, ab, bb, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: rvbm(n), fivbm(n), fim(n), rvbn(n), fivbn(n), fin(n), wm(n), &
        em(n), wn(n), en(n), abbmk(n), bbbmk(n), abbnk(n), bbbnk(n)
    real(dp), intent(out) :: abbmr(n), bbbmr(n), abbnr(n), bbbnr(n), ab(n), bb(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call duskr4(rvbm(i), fivbm(i), fim(i), rvbn(i), fivbn(i), fin(i), wm(i), em(i), wn(i), &
          en(i), abbmk(i), bbbmk(i), abbnk(i), bbbnk(i), 1.0_dp, abbmr(i), bbbmr(i), &
          abbnr(i), bbbnr(i), ab(i), bb(i), status(i))
    end do
  end subroutine duskr4_sweep

  subroutine duskr5_sweep(n, xc3, yc3, xvm, yvm, fim, wm, em, t2, ac3, bc3, ac2mk, bc2mk, &
      ac23k, bc23k, ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac2, bc2, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xc3(n), yc3(n), xvm(n), yvm(n), fim(n), wm(n), em(n), t2(n), &
        ac3(n), bc3(n), ac2mk(n), bc2mk(n), ac23k(n), bc23k(n)
    real(dp), intent(out) :: ac2c3r(n), bc2c3r(n), ac2cmr(n), bc2cmr(n), ac2(n), bc2(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call duskr5(xc3(i), yc3(i), xvm(i), yvm(i), fim(i), wm(i), em(i), t2(i), ac3(i), &
          bc3(i), ac2mk(i), bc2mk(i), ac23k(i), bc23k(i), 1.0_dp, ac2c3r(i), bc2c3r(i), &
          ac2cmr(i), bc2cmr(i), ac2(i), bc2(i), status(i))
    end do
  end subroutine duskr5_sweep

  subroutine dknma1_sweep(n, xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p, &
      analog, xb, yb, fi2, fi3, vba, alba, vbc, albc, vb, alb, w2, w3, abcn, aban, abat, &
      bbat, abct, bbct, ab, bb, e2, e3, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xc(n), yc(n), rz2(n), rz3(n), va(n), ala(n), vc(n), &
        alc(n), aa(n), ba(n), ac(n), bc(n), p(n)
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb(n), yb(n), fi2(n), fi3(n), vba(n), alba(n), vbc(n), albc(n), &
        vb(n), alb(n), w2(n), w3(n), abcn(n), aban(n), abat(n), bbat(n), abct(n), bbct(n), &
        ab(n), bb(n), e2(n), e3(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dknma1(xa(i), ya(i), xc(i), yc(i), rz2(i), rz3(i), va(i), ala(i), vc(i), alc(i), &
          aa(i), ba(i), ac(i), bc(i), p(i), analog, xb(i), yb(i), fi2(i), fi3(i), vba(i), &
          alba(i), vbc(i), albc(i), vb(i), alb(i), w2(i), w3(i), abcn(i), aban(i), abat(i), &
          bbat(i), abct(i), bbct(i), ab(i), bb(i), e2(i), e3(i), status(i))
    end do
  end subroutine dknma1_sweep

  subroutine dknma2_sweep(n, xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala, wm, vbm, albm, aa, &
      ba, abm, bbm, p, analog, xb, yb, fi2, vba, alba, vbbm, albbm, vb, alb, w2, aban, abk, &
      bbk, abat, bbat, abbm, bbbm, ab, bb, e2, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xk(n), yk(n), fim(n), rz2(n), rz3(n), eta(n), &
        va(n), ala(n), wm(n), vbm(n), albm(n), aa(n), ba(n), abm(n), bbm(n), p(n)
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb(n), yb(n), fi2(n), vba(n), alba(n), vbbm(n), albbm(n), vb(n), &
        alb(n), w2(n), aban(n), abk(n), bbk(n), abat(n), bbat(n), abbm(n), bbbm(n), ab(n), &
        bb(n), e2(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dknma2(xa(i), ya(i), xk(i), yk(i), fim(i), rz2(i), rz3(i), eta(i), va(i), ala(i), &
          wm(i), vbm(i), albm(i), aa(i), ba(i), abm(i), bbm(i), p(i), analog, xb(i), yb(i), &
          fi2(i), vba(i), alba(i), vbbm(i), albbm(i), vb(i), alb(i), w2(i), aban(i), abk(i), &
          bbk(i), abat(i), bbat(i), abbm(i), bbbm(i), ab(i), bb(i), e2(i), status(i))
    end do
  end subroutine dknma2_sweep

  subroutine dknma3_sweep(n, xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p, &
      analog, xb, yb, rzbc, fi3, var, alar, vac, alac, w3, va3, ala3, aak, bak, aar, bar, &
      aact, bact, aa3, ba3, e3, aacn, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), xc(n), yc(n), rz2(n), eta(n), va(n), ala(n), vc(n), &
        alc(n), aa(n), ba(n), ac(n), bc(n), p(n)
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb(n), yb(n), rzbc(n), fi3(n), var(n), alar(n), vac(n), alac(n), &
        w3(n), va3(n), ala3(n), aak(n), bak(n), aar(n), bar(n), aact(n), bact(n), aa3(n), &
        ba3(n), e3(n), aacn(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dknma3(xa(i), ya(i), xc(i), yc(i), rz2(i), eta(i), va(i), ala(i), vc(i), alc(i), &
          aa(i), ba(i), ac(i), bc(i), p(i), analog, xb(i), yb(i), rzbc(i), fi3(i), var(i), &
          alar(i), vac(i), alac(i), w3(i), va3(i), ala3(i), aak(i), bak(i), aar(i), bar(i), &
          aact(i), bact(i), aa3(i), ba3(i), e3(i), aacn(i), status(i))
    end do
  end subroutine dknma3_sweep

  subroutine dknma4_sweep(n, fim, xa, ya, fin, xc, yc, rz2, eta2, rz3, eta3, wm, wn, em, en, &
      analog, xb, yb, vb2r, alb2r, vb3r, alb3r, vb, alb, ab2k, bb2k, ab3k, bb3k, ab2r, bb2r, &
      ab3r, bb3r, ab, bb, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: fim(n), xa(n), ya(n), fin(n), xc(n), yc(n), rz2(n), eta2(n), &
        rz3(n), eta3(n), wm(n), wn(n), em(n), en(n)
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: xb(n), yb(n), vb2r(n), alb2r(n), vb3r(n), alb3r(n), vb(n), &
        alb(n), ab2k(n), bb2k(n), ab3k(n), bb3k(n), ab2r(n), bb2r(n), ab3r(n), bb3r(n), &
        ab(n), bb(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dknma4(fim(i), xa(i), ya(i), fin(i), xc(i), yc(i), rz2(i), eta2(i), rz3(i), &
          eta3(i), wm(i), wn(i), em(i), en(i), analog, xb(i), yb(i), vb2r(i), alb2r(i), &
          vb3r(i), alb3r(i), vb(i), alb(i), ab2k(i), bb2k(i), ab3k(i), bb3k(i), ab2r(i), &
          bb2r(i), ab3r(i), bb3r(i), ab(i), bb(i), status(i))
    end do
  end subroutine dknma4_sweep

  subroutine dknma5_sweep(n, xa, ya, fim, xc, yc, rz3, eta2, eta3, xr, yr, wm, em, vc3, alc3, &
      ac3, bc3, analog, vc2c3, alc2c3, vc2cm, alc2cm, vc, alc, ac2c3k, bc2c3k, ac2cmk, &
      bc2cmk, ac2c3r, bc2c3r, ac2cmr, bc2cmr, ac, bc, status)
    integer, intent(in) :: n
    real(dp), intent(in) :: xa(n), ya(n), fim(n), xc(n), yc(n), rz3(n), eta2(n), eta3(n), &
        xr(n), yr(n), wm(n), em(n), vc3(n), alc3(n), ac3(n), bc3(n)
    real(dp), intent(in) :: analog
    real(dp), intent(out) :: vc2c3(n), alc2c3(n), vc2cm(n), alc2cm(n), vc(n), alc(n), &
        ac2c3k(n), bc2c3k(n), ac2cmk(n), bc2cmk(n), ac2c3r(n), bc2c3r(n), ac2cmr(n), &
        bc2cmr(n), ac(n), bc(n)
    integer, intent(out) :: status(n)
    integer :: i
    do i = 1, n
      call dknma5(xa(i), ya(i), fim(i), xc(i), yc(i), rz3(i), eta2(i), eta3(i), xr(i), yr(i), &
          wm(i), em(i), vc3(i), alc3(i), ac3(i), bc3(i), analog, vc2c3(i), alc2c3(i), &
          vc2cm(i), alc2cm(i), vc(i), alc(i), ac2c3k(i), bc2c3k(i), ac2cmk(i), bc2cmk(i), &
          ac2c3r(i), bc2c3r(i), ac2cmr(i), bc2cmr(i), ac(i), bc(i), status(i))
    end do
  end subroutine dknma5_sweep

end module sweeps_kinematics
