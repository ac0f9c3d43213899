"""Kinds 4 (PRP) and 5 (RPP): the book's routines as adapters over groups.f90's kernels
(issue 25).

In corrected mode DPRM4, DKNMA4 are adapters over prp_kernel, DSKOR4, DUSKR4 over its
velocity and acceleration stages, and the same for kind 5 (DPRM5, DKNMA5 over
rpp_kernel; DSKOR5, DUSKR5 over its stages).  Checked here:
* against references independent of sarkp: the lines intersected in mpmath (50 digits)
  from the same binary inputs, and the velocities and accelerations as mpmath derivatives
  (mp.diff) of those closed forms with the guides turning in time;
* that each adapter gives the same bits as a one-group sarkp.Mechanism fed the same data,
  where both compute the same number (B's or K's position; the moduli of B's velocity and
  acceleration, sqrt(x*x + y*y) of the Mechanism's components);
* the promise of a small slot angle (DPRM5, DKNMA5: t2 = 1e-8, 1e-10 keep their digits),
  kept by the Mechanism's rpp with a turning guide too;
* an rpp whose guide and block pivot are both at rest solves (every term of its
  acceleration estimate 0), where it raised SingularError.
The as-printed paths keep the book's code (the printed figures' counts pin them).
"""

import math
import warnings

import mpmath as mp
import numpy as np
import pytest

import sarkp

mp.mp.dps = 50
TOL = 1e-13          # corrected mode: well-conditioned groups keep ~15 digits


def e(a):
    return (mp.cos(a), mp.sin(a))


def rot(v):          # k x v
    return (-v[1], v[0])


def ang_diff(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


# ---- kind 4: B on two offset lines ---------------------------------------------------

def prp_ref(fim, xa, ya, fin, xc, yc, d2, d3, t=0):
    """B at time t (mpmath) on guide M through A (direction fim(t)) at d2 along its left
    normal and guide N through C (fin(t)) at d3; fim, fin: functions of t."""
    um, un = e(fim(t)), e(fin(t))
    nm, nn = rot(um), rot(un)
    # nm . B = nm . A + d2,  nn . B = nn . C + d3 (Cramer's rule)
    b1 = nm[0] * xa + nm[1] * ya + d2
    b2 = nn[0] * xc + nn[1] * yc + d3
    det = nm[0] * nn[1] - nm[1] * nn[0]
    return ((b1 * nn[1] - nm[1] * b2) / det, (nm[0] * b2 - nn[0] * b1) / det)


CASES4 = [  # fim, xa, ya, fin, xc, yc, d2, d3, wm, wn, em, en
    (0.3, 0.1, -0.2, 2.0, 1.1, 0.4, 0.15, -0.05, 1.3, -0.7, 0.4, 2.0),
    (-2.5, 3.0, 1.0, 0.9, -1.0, 2.0, 0.0, 0.3, 0.0, 2.5, -1.5, 0.0),
    (1.5707963267948966, 0.0, 0.0, 0.2, 2.0, -1.0, 0.4, 0.0, -3.0, 0.0, 0.0, 0.7),
]


@pytest.mark.parametrize("c", CASES4)
def test_dprm4_dknma4_against_mpmath(c):
    fim, xa, ya, fin, xc, yc, d2, d3, wm, wn, em, en = c
    # the guides turn about A and C (DKNMA4's model): fi(t) = fi + w t + e t**2/2
    fm = lambda t: mp.mpf(fim) + wm * t + em * t**2 / 2      # noqa: E731
    fn = lambda t: mp.mpf(fin) + wn * t + en * t**2 / 2      # noqa: E731
    B = lambda t: prp_ref(fm, xa, ya, fn, xc, yc, d2, d3, t)  # noqa: E731
    p = B(0)
    v = [mp.diff(lambda t: B(t)[i], 0) for i in range(2)]
    a = [mp.diff(lambda t: B(t)[i], 0, 2) for i in range(2)]
    # B's coordinates along the guides, in their turning frames: s' and s'' are B's
    # velocity and acceleration relative to the guides
    sm = lambda t: (B(t)[0] - xa) * mp.cos(fm(t)) + (B(t)[1] - ya) * mp.sin(fm(t))  # noqa
    sn = lambda t: (B(t)[0] - xc) * mp.cos(fn(t)) + (B(t)[1] - yc) * mp.sin(fn(t))  # noqa
    # |d|*sin(+-pi/2) = d: the offsets are d2, d3 exactly
    o = (abs(d2), math.copysign(math.pi / 2, d2), abs(d3), math.copysign(math.pi / 2, d3))
    r = sarkp.DPRM4(xa, ya, xa, ya, fim, xc, yc, xc, yc, fin, *o)
    size = max(abs(xc - xa) + abs(yc - ya), 1.0)
    assert abs(r.XB - p[0]) <= TOL * size and abs(r.YB - p[1]) <= TOL * size
    assert r.RVBM == pytest.approx(float(mp.hypot(p[0] - xa, p[1] - ya)), rel=TOL, abs=TOL)
    assert ang_diff(r.FIVBM, float(mp.atan2(p[1] - ya, p[0] - xa))) <= 1e-12
    assert 0.0 <= r.FIVBM < 2 * math.pi and 0.0 <= r.FIVBN < 2 * math.pi
    k = sarkp.DKNMA4(fim, xa, ya, fin, xc, yc, *o, wm, wn, em, en)
    assert (k.XB, k.YB) == (r.XB, r.YB)
    V = max(float(mp.hypot(*v)), 1.0)
    assert k.VB == pytest.approx(float(mp.hypot(*v)), abs=TOL * V)
    assert k.VB * math.cos(k.ALB) == pytest.approx(float(v[0]), abs=TOL * V)
    assert k.VB * math.sin(k.ALB) == pytest.approx(float(v[1]), abs=TOL * V)
    # the relative velocities along e(ALB2R), e(ALB3R) (FIM or FIM - pi: DUGL4)
    assert k.VB2R * math.cos(k.ALB2R - fim) == pytest.approx(float(mp.diff(sm, 0)), abs=TOL * V)
    assert k.VB3R * math.cos(k.ALB3R - fin) == pytest.approx(float(mp.diff(sn, 0)), abs=TOL * V)
    assert ang_diff(k.ALB2R, fim) in (0.0, pytest.approx(math.pi))
    A = max(float(mp.hypot(*a)), 1.0)
    assert k.AB * math.cos(k.BB) == pytest.approx(float(a[0]), abs=TOL * A)
    assert k.AB * math.sin(k.BB) == pytest.approx(float(a[1]), abs=TOL * A)
    assert k.AB2R * math.cos(k.BB2R - fim) == pytest.approx(float(mp.diff(sm, 0, 2)),
                                                             abs=TOL * A)
    assert k.AB3R * math.cos(k.BB3R - fin) == pytest.approx(float(mp.diff(sn, 0, 2)),
                                                             abs=TOL * A)
    # the Coriolis accelerations 2 |W| v_r, turned a quarter by W's sign
    assert k.AB2K == 2 * abs(wm) * k.VB2R
    assert k.BB2K == sarkp.DUGL3(k.ALB2R, math.pi / 2, wm)
    # DSKOR4, DUSKR4 (the stages) from DPRM4's radius vectors: the same answers
    s = sarkp.DSKOR4(r.RVBM, r.FIVBM, fim, r.RVBN, r.FIVBN, fin, wm, wn)
    assert s.VB == pytest.approx(k.VB, abs=TOL * V)
    assert ang_diff(s.ALB, k.ALB) <= 1e-12 and ang_diff(s.ALBBM, k.ALB2R) <= 1e-12
    assert s.VBBM == pytest.approx(k.VB2R, abs=TOL * V)
    u = sarkp.DUSKR4(r.RVBM, r.FIVBM, fim, r.RVBN, r.FIVBN, fin, wm, em, wn, en,
                     k.AB2K, k.BB2K, k.AB3K, k.BB3K)
    assert u.AB * math.cos(u.BB) == pytest.approx(float(a[0]), abs=TOL * A)
    assert u.AB * math.sin(u.BB) == pytest.approx(float(a[1]), abs=TOL * A)
    assert u.ABBMR * math.cos(u.BBBMR - fim) == pytest.approx(float(mp.diff(sm, 0, 2)),
                                                               abs=TOL * A)


# ---- kind 5: C - A = s2 e(fim) + s3 e(fim + t2) ----------------------------------------

def rpp_ref(fim, xa, ya, xc, yc, t2):
    """s2, s3 (mpmath) of C - A = s2 e(fim) + s3 e(fim + t2), in the guide's frame."""
    dx, dy = mp.mpf(xc) - xa, mp.mpf(yc) - ya
    d1 = dx * mp.cos(fim) + dy * mp.sin(fim)
    d2 = -dx * mp.sin(fim) + dy * mp.cos(fim)
    s3 = d2 / mp.sin(t2)
    return d1 - s3 * mp.cos(t2), s3


@pytest.mark.parametrize("t2", [0.7, -2.0, 1e-8, -1e-10, math.pi - 1e-9])
def test_dprm5_against_mpmath(t2):
    xa, ya, fim, xc, yc = 0.3, -1.2, 0.4, 1.7, 0.25
    r = sarkp.DPRM5(xa, ya, fim, xc, yc, t2)
    s2, s3 = rpp_ref(fim, xa, ya, xc, yc, t2)
    S = max(abs(float(s2)), abs(float(s3)), 1.0)
    assert r.S2 == pytest.approx(float(s2), abs=1e-14 * S)
    assert r.S3 == pytest.approx(float(s3), abs=1e-14 * S)
    assert r.XK == pytest.approx(float(xa + s2 * mp.cos(fim)), abs=1e-14 * S)
    assert r.YK == pytest.approx(float(ya + s2 * mp.sin(fim)), abs=1e-14 * S)


@pytest.mark.parametrize("t2", [0.7, -2.0, 1e-8, 1e-10])
def test_dknma5_against_mpmath(t2):
    """Link M turns about R (fim(t) = fim + wm t + em t**2/2), C moves with a given
    velocity and acceleration; s2, s3 of C - R in link M's frame, differentiated: the
    rates along e(FIM) (VC2CM) and e(FIM + ETA2) (VC2C3 = -s3'), and C2, link 2's point
    at C: v_C2 = v_C - s3' e(fim + t2), a_C2 = a_C - 2 wm s3' k x e(..) - s3'' e(..)."""
    fim, xc, yc, xr, yr, wm, em = 0.4, 1.0, 0.5, -0.3, 0.2, 2.0, 0.5
    vc3, alc3, ac3, bc3 = 1.0, 0.4, 3.0, 1.0
    vC = (vc3 * mp.cos(alc3), vc3 * mp.sin(alc3))
    aC = (ac3 * mp.cos(bc3), ac3 * mp.sin(bc3))
    f = lambda t: mp.mpf(fim) + wm * t + em * t**2 / 2              # noqa: E731
    C = lambda t: (xc + vC[0] * t + aC[0] * t**2 / 2, yc + vC[1] * t + aC[1] * t**2 / 2)  # noqa
    s = lambda t, i: rpp_ref(f(t), xr, yr, C(t)[0], C(t)[1], t2)[i]  # noqa: E731
    s2v, s3v = mp.diff(lambda t: s(t, 0), 0), mp.diff(lambda t: s(t, 1), 0)
    s2a, s3a = mp.diff(lambda t: s(t, 0), 0, 2), mp.diff(lambda t: s(t, 1), 0, 2)
    k = sarkp.DKNMA5(9.0, 9.0, fim, xc, yc, 0.0, t2, 0.0, xr, yr, wm, em, vc3, alc3, ac3,
                     bc3)
    V = float(max(abs(s2v), abs(s3v), 1))
    assert k.VC2CM * math.cos(k.ALC2CM - fim) == pytest.approx(float(s2v), abs=1e-14 * V)
    assert k.VC2C3 * math.cos(k.ALC2C3 - fim - t2) == pytest.approx(float(-s3v),
                                                                    abs=1e-14 * V)
    us = e(mp.mpf(fim) + t2)
    vC2 = (vC[0] - s3v * us[0], vC[1] - s3v * us[1])
    assert k.VC * math.cos(k.ALC) == pytest.approx(float(vC2[0]), abs=1e-14 * V)
    assert k.VC * math.sin(k.ALC) == pytest.approx(float(vC2[1]), abs=1e-14 * V)
    A = float(max(abs(s2a), abs(s3a), 1))
    # the book's relative accelerations along ALC2CM, ALC2C3 (the velocities' directions)
    assert k.AC2CMR * math.cos(k.BC2CMR - fim) == pytest.approx(float(s2a), abs=1e-14 * A)
    assert k.AC2C3R * math.cos(k.BC2C3R - fim - t2) == pytest.approx(float(-s3a),
                                                                     abs=1e-14 * A)
    n = rot(us)
    aC2 = [aC[i] - 2 * wm * s3v * n[i] - s3a * us[i] for i in range(2)]
    assert k.AC * math.cos(k.BC) == pytest.approx(float(aC2[0]), abs=1e-14 * A)
    assert k.AC * math.sin(k.BC) == pytest.approx(float(aC2[1]), abs=1e-14 * A)
    # DSKOR5, DUSKR5 (the stages) with the same data: the same answers
    v = sarkp.DSKOR5(xc, yc, xr, yr, fim, t2, wm, vc3, alc3)
    assert v.VC2CM * math.cos(v.ALC2CM - fim) == pytest.approx(float(s2v), abs=1e-14 * V)
    assert v.VC2 * math.cos(v.ALC2) == pytest.approx(float(vC2[0]), abs=1e-14 * V)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        u = sarkp.DUSKR5(xc, yc, xr, yr, fim, wm, em, t2, ac3, bc3, k.AC2CMK, k.BC2CMK,
                         k.AC2C3K, k.BC2C3K)
    # the Coriolis terms as given, each ~1/t2 and rounded as such (their difference is
    # not ~1/t2): digits are lost as u/t2**2, and the warning says how many are left
    digits = min([x.message.digits for x in w], default=None)
    assert (digits is None) == (abs(t2) > 1e-6)
    tol = (1e-13 if digits is None else 10.0**-digits) * A
    assert u.AC2CMR * math.cos(u.BC2CMR - fim) == pytest.approx(float(s2a), abs=tol)
    assert u.AC2 * math.cos(u.BC2) == pytest.approx(float(aC2[0]), abs=tol)


# ---- the adapters and a one-group Mechanism: the same bits -----------------------------

def _norm(v):
    """norm2d of the Fortran side: sqrt(x*x + y*y) (no overflow here)."""
    return np.sqrt(v[..., 0] * v[..., 0] + v[..., 1] * v[..., 1])


def test_dprm4_dknma4_are_the_mechanisms_prp_bit_for_bit():
    """Guide M through O turning with the crank (fim = 0: its direction is the crank's,
    cos phi, sin phi as DKNMA4 takes them from FIM = phi), guide N fixed through C;
    omega = 1, epsilon = 0 (the Mechanism's analogues are then the velocities)."""
    xc, yc, fin, d2, d3 = 0.7, -0.3, 2.0, 0.1, 0.2
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, yc)
    m.crank("A", "O", 0.4)
    m.prp("B", "O", 0.0, "C", fin, rz2=d2, t2=math.pi / 2, rz3=d3, t3=math.pi / 2,
          guide_m=("O", "A"))
    phi = np.linspace(0.05, 1.5, 41)        # the guides are parallel at phi = 2 - pi
    with warnings.catch_warnings():
        warnings.simplefilter("error")              # every status OK
        res = m.solve(phi, omega=1.0, epsilon=0.0)
        k = sarkp.DKNMA4(phi, 0.0, 0.0, fin, xc, yc, d2, math.pi / 2, d3, math.pi / 2,
                         1.0, 0.0, 0.0, 0.0)
        r = sarkp.DPRM4(0.0, 0.0, 0.0, 0.0, phi, xc, yc, xc, yc, fin, d2, math.pi / 2, d3,
                        math.pi / 2)
    x = res.position("B")
    assert np.array_equal(k.XB, x[:, 0]) and np.array_equal(k.YB, x[:, 1])
    assert np.array_equal(r.XB, x[:, 0]) and np.array_equal(r.YB, x[:, 1])
    assert np.array_equal(k.VB, _norm(res.velocity("B")))
    assert np.array_equal(k.AB, _norm(res.acceleration("B")))
    assert np.all(res.status == 0)


@pytest.mark.parametrize("t2", [0.7, 1e-8, -1e-10])
def test_dprm5_is_the_mechanisms_rpp_bit_for_bit(t2):
    """A fixed guide through P, the block pivoted at the crank pin C: DPRM5 fed the
    Mechanism's C gives its K."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("P", -1.0, 0.5)
    m.crank("C", "O", 0.3)
    m.rpp("K", "P", 0.0, "C", t2)
    phi = np.linspace(0.1, 6.0, 25)
    with warnings.catch_warnings():
        warnings.simplefilter("error")              # every status OK
        res = m.solve(phi, need="positions")
        c = res.position("C")
        r = sarkp.DPRM5(-1.0, 0.5, 0.0, c[:, 0], c[:, 1], t2)
    k = res.position("K")
    assert np.array_equal(r.XK, k[:, 0]) and np.array_equal(r.YK, k[:, 1])
    assert np.all(res.status == 0)


@pytest.mark.parametrize("t2", [0.7, 1e-8, 1e-10, -1e-10])
def test_mechanism_rpp_turning_guide_small_slot_angle(t2):
    """The Mechanism's rpp with its guide turning with the crank (through O, fim = 0) and
    the block pivoted at a frame point keeps DKNMA5's promise for a small slot angle: at
    need="velocities" and "accelerations" OK and every digit (mpmath, phi as time), and
    its slider rates agree with DKNMA5's (link M turning about R = O)."""
    xc, yc = 1.0, 0.5
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("P", xc, yc)
    m.crank("A", "O", 0.4)
    m.rpp("K", "O", 0.0, "P", t2, guide=("O", "A"))
    phi = np.linspace(0.1, 6.0, 5)
    for need in ("velocities", "accelerations"):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            res = m.solve(phi, need=need)
        assert np.all(res.status == 0)
    for i, p in enumerate(phi):
        p = mp.mpf(p)
        K = lambda t: [rpp_ref(t, 0, 0, xc, yc, t2)[0] * c for c in e(t)]  # noqa: E731
        want = (K(p), [mp.diff(lambda t: K(t)[j], p) for j in range(2)],
                [mp.diff(lambda t: K(t)[j], p, 2) for j in range(2)])
        got = (res.position("K")[i], res.velocity("K")[i], res.acceleration("K")[i])
        for g, w in zip(got, want):
            S = float(max(abs(w[0]), abs(w[1]), 1))
            assert max(abs(float(g[0] - w[0])), abs(float(g[1] - w[1]))) <= 1e-14 * S, i
        k = sarkp.DKNMA5(0.0, 0.0, float(p), xc, yc, 0.0, t2, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                         0.0, 0.0, 0.0)
        # K's velocity: link M's point at K plus K's rate VC2CM along the guide
        s2 = rpp_ref(p, 0, 0, xc, yc, t2)[0]
        vk = [k.VC2CM * math.cos(k.ALC2CM) - float(s2 * mp.sin(p)),
              k.VC2CM * math.sin(k.ALC2CM) + float(s2 * mp.cos(p))]
        S = float(max(abs(want[1][0]), abs(want[1][1]), 1))
        assert np.allclose(vk, res.velocity("K")[i], rtol=0, atol=1e-14 * S)


def test_rpp_at_rest_solves():
    """Guide and block pivot both on the frame: the group does not move; its velocities
    and accelerations are 0, status OK (the acceleration estimate divided 0 by 0 before:
    SingularError)."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("P", 1.0, 0.5)
    m.fixed("Q", 2.0, -0.3)
    m.crank("A", "O", 0.4)
    m.rpp("K", "P", 0.3, "Q", 0.7)
    res = m.solve([0.1, 0.2], need="accelerations")
    assert np.all(res.status == 0)
    s2, _ = rpp_ref(0.3, 1.0, 0.5, 2.0, -0.3, 0.7)
    assert np.allclose(res.position("K"), [1.0 + float(s2) * math.cos(0.3),
                                           0.5 + float(s2) * math.sin(0.3)], rtol=0,
                       atol=1e-15)
    assert np.all(res.velocity("K") == 0.0) and np.all(res.acceleration("K") == 0.0)
