"""Chapter 4: kinematics of the Assur groups (IV.1-IV.20).

Physics: for every group kind and branch, on random well-conditioned groups,
* positions close the loop (to 1e-12 of the largest length) and sit on the requested branch;
* velocities equal the time derivative of the positions and accelerations the derivative
  of the velocities (8th-order central differences, 1e-8 relative);
* DKNMA* equal the PRM/SKOR/USKR chain (1e-13 relative).
Errors: non-assembly -> AssemblyError, dead centre -> SingularError, a sweep losing
assembly partway with on_error='nan'.  Fig. 91 of chapter 10 (program X) is pinned through
its figure data in tests/test_program_x.py.
"""

import math
import os
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import sarkp
from sarkp import kinematics as K

sys.path.insert(0, str(Path(__file__).resolve().parent))   # --import-mode=importlib
from strategies import rngs  # noqa: E402

TWO_PI = 2.0 * math.pi
RNGS = rngs()           # Hypothesis draws behind the numpy Generator methods used here
SETTINGS = settings(max_examples=int(os.environ.get("SARKP_EXAMPLES", "40")), deadline=None)

# 8th-order central difference weights, first derivative
D1 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
# 8th-order central difference weights, second derivative
D2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])
STEPS = np.arange(-4, 5)


def e(phi):
    return np.array([np.cos(phi), np.sin(phi)])


def vec(mod, ang):
    """(modulus, direction) -> components (last axis 2)."""
    return np.stack([mod * np.cos(ang), mod * np.sin(ang)], axis=-1)


def polar(v):
    """components -> (modulus, direction)."""
    return math.hypot(v[0], v[1]), math.atan2(v[1], v[0])


def ddt(samples, h):
    """First derivative at the centre of 9 samples (along axis 0)."""
    return np.tensordot(D1, samples, axes=(0, 0)) / h


def d2dt2(samples, h):
    return np.tensordot(D2, samples, axes=(0, 0)) / h**2


def angdiff(a, b):
    """a - b reduced to (-pi, pi]."""
    return (np.asarray(a) - np.asarray(b) + math.pi) % TWO_PI - math.pi


def close(a, b, scale, rtol):
    return np.all(np.abs(np.asarray(a) - np.asarray(b)) <= rtol * scale)


def same(m1, a1, m2, a2, scale, rtol=1e-13):
    """The vectors (modulus, direction) m1, a1 and m2, a2 agree to rtol*scale (a direction
    is compared through its vector: it has no meaning for a zero modulus)."""
    return close(vec(np.asarray(m1), np.asarray(a1)), vec(np.asarray(m2), np.asarray(a2)),
                 scale, rtol)


class Crank:
    """A point on a circle: P(t) = O + r*e(p + w*t + eps*t**2/2) -- known v and a."""

    def __init__(self, rng, scale=1.0):
        self.o = rng.uniform(-1, 1, 2) * scale
        self.r = rng.uniform(0.2, 1.0) * scale
        self.p = rng.uniform(-math.pi, math.pi)
        self.w = rng.uniform(0.5, 2.0) * rng.choice([-1, 1])
        self.eps = rng.uniform(-1.0, 1.0)

    def angle(self, t):
        return self.p + self.w * t + 0.5 * self.eps * t * t

    def pos(self, t):
        return self.o[:, None] + self.r * e(self.angle(np.atleast_1d(t)))

    def vel(self, t):
        """(modulus, direction) of the velocity at scalar t."""
        a, w = self.angle(t), self.w + self.eps * t
        return polar(self.r * w * e(a + math.pi / 2))

    def acc(self, t):
        a, w = self.angle(t), self.w + self.eps * t
        return polar(self.r * (-w * w * e(a) + self.eps * e(a + math.pi / 2)))


def step(w, length=1.0):
    return 5e-4 * min(length, 1.0) / max(abs(w), 1.0)


# ---------------------------------------------------------------------------------------
# kind 1 (RRR)
# ---------------------------------------------------------------------------------------

def away(c, pa, dmin):
    """Move crank c's circle by 0.5 away from pa if its point is within dmin of pa (a
    fixed step, not a new draw: Hypothesis's smallest draws would repeat forever)."""
    pc = c.pos(0.0)[:, 0]
    d = pc - pa
    if np.linalg.norm(d) < dmin:
        c.o = c.o + 0.5 * (d / np.linalg.norm(d) if np.any(d) else np.array([1.0, 0.0]))
        pc = c.pos(0.0)[:, 0]
    return pc


def kind1(rng):
    a, c = Crank(rng), Crank(rng)
    pa = a.pos(0.0)[:, 0]
    pc = away(c, pa, 0.1)
    for _ in range(10):              # B well away from the dead centres
        b = rng.uniform(-2, 2, 2)
        u, v = pa - b, pc - b
        s = (u[0] * v[1] - u[1] * v[0]) / (np.linalg.norm(u) * np.linalg.norm(v))
        if abs(s) > 0.3:
            break
    else:                            # the apex of a right angle over AC
        b = (pa + pc) / 2 + 0.5 * np.array([pa[1] - pc[1], pc[0] - pa[0]])
    rz2, rz3 = np.linalg.norm(b - pa), np.linalg.norm(b - pc)
    ac = pc - pa
    left = ac[0] * (b - pa)[1] - ac[1] * (b - pa)[0] > 0
    p = -1 if left else 1            # L1477: P = -1 <=> B on the left of A -> C
    return a, c, b, rz2, rz3, p


@SETTINGS
@given(RNGS)
def test_kind1_positions_branch_and_closure(rng):
    a, c, b, rz2, rz3, p = kind1(rng)
    (xa, ya), (xc, yc) = a.pos(0.0)[:, 0], c.pos(0.0)[:, 0]
    r = K.DPRM1(xa, ya, xc, yc, rz2, rz3, p)
    L = max(rz2, rz3, math.hypot(xc - xa, yc - ya))
    assert close([r.XB, r.YB], b, L, 1e-12)
    assert close(np.array([xc, yc]) + rz3 * e(r.FI3), [r.XB, r.YB], L, 1e-12)
    assert 0.0 <= r.FI2 < 3 * math.pi and 0.0 <= r.FI3 < 3 * math.pi
    # the other branch is the mirror image of B in the line AC
    m = K.DPRM1(xa, ya, xc, yc, rz2, rz3, -p)
    assert close([math.hypot(m.XB - xa, m.YB - ya)], [rz2], L, 1e-12)
    assert not close([m.XB, m.YB], b, L, 1e-6)


@SETTINGS
@given(RNGS)
def test_kind1_velocities_and_accelerations_are_derivatives(rng):
    a, c, b, rz2, rz3, p = kind1(rng)
    # the step follows the group's own rates
    r0 = K.DPRM1(*a.pos(0.0)[:, 0], *c.pos(0.0)[:, 0], rz2, rz3, p)
    v0 = K.DSKOR1(rz2, r0.FI2, rz3, r0.FI3, *a.vel(0.0), *c.vel(0.0))
    h = step(max(abs(a.w), abs(c.w), abs(v0.W2), abs(v0.W3)), min(rz2, rz3))
    t = STEPS * h
    pa, pc = a.pos(t), c.pos(t)
    r = K.DPRM1(pa[0], pa[1], pc[0], pc[1], rz2, rz3, p)
    va, vc = [np.array([x.vel(ti) for ti in t]) for x in (a, c)]
    v = K.DSKOR1(rz2, r.FI2, rz3, r.FI3, va[:, 0], va[:, 1], vc[:, 0], vc[:, 1])
    vb = vec(v.VB, v.ALB)
    scale_v = max(np.abs(vb[4]).max(), a.r * abs(a.w), c.r * abs(c.w), 1e-3)
    assert close(ddt(np.stack([r.XB, r.YB], -1), h), vb[4], scale_v, 1e-8)
    wscale = scale_v / min(rz2, rz3)
    assert close(ddt(np.unwrap(r.FI2), h), v.W2[4], wscale, 1e-8)
    assert close(ddt(np.unwrap(r.FI3), h), v.W3[4], wscale, 1e-8)
    # relative velocities: v_B = v_A + v_BA = v_C + v_BC
    assert close(vec(va[4, 0], va[4, 1]) + vec(v.VBA[4], v.ALBA[4]), vb[4], scale_v, 1e-12)
    assert close(vec(vc[4, 0], vc[4, 1]) + vec(v.VBC[4], v.ALBC[4]), vb[4], scale_v, 1e-12)
    aa, ac = np.array(a.acc(0.0)), np.array(c.acc(0.0))
    u = K.DUSKR1(aa[0], aa[1], ac[0], ac[1], rz2, r.FI2[4], rz3, r.FI3[4], v.W2[4], v.W3[4])
    scale_a = max(abs(a.w) * scale_v, abs(c.w) * scale_v, abs(u.AB), 1e-3)
    assert close(ddt(vb, h), vec(u.AB, u.BB), scale_a, 1e-8)
    escale = scale_a / min(rz2, rz3)
    assert close(ddt(v.W2, h), u.E2, escale, 1e-8)
    assert close(ddt(v.W3, h), u.E3, escale, 1e-8)


@SETTINGS
@given(RNGS, st.sampled_from([-1, 1]), st.sampled_from([0.0, 1.0]))
def test_dknma1_equals_chain(rng, p, analog):
    a, c, b, rz2, rz3, _ = kind1(rng)
    (xa, ya), (xc, yc) = a.pos(0.0)[:, 0], c.pos(0.0)[:, 0]
    (va, ala), (vc, alc), (aa, ba), (ac, bc) = a.vel(0), c.vel(0), a.acc(0), c.acc(0)
    k = K.DKNMA1(xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p, analog)
    r = K.DPRM1(xa, ya, xc, yc, rz2, rz3, -p)       # DKNMA1's P is DPRM1's -P
    v = K.DSKOR1(rz2, r.FI2, rz3, r.FI3, va, ala, vc, alc)
    L = max(rz2, rz3, 1.0)
    assert close([k.XB, k.YB], [r.XB, r.YB], L, 1e-13)
    assert close(angdiff([k.FI2, k.FI3], [r.FI2, r.FI3]), 0, 1, 1e-13)
    V = max(v.VB, va, vc, 1.0)
    assert close([k.VBA, k.VBC, k.VB], [v.VBA, v.VBC, v.VB], V, 1e-13)
    assert same([k.VBA, k.VBC, k.VB], [k.ALBA, k.ALBC, k.ALB],
                [v.VBA, v.VBC, v.VB], [v.ALBA, v.ALBC, v.ALB], V)
    assert close([k.W2, k.W3], [v.W2, v.W3], V / min(rz2, rz3), 1e-13)
    if analog == 1.0:
        assert k.AB == k.E2 == k.E3 == 0.0        # not computed
        return
    u = K.DUSKR1(aa, ba, ac, bc, rz2, r.FI2, rz3, r.FI3, v.W2, v.W3)
    A = max(u.AB, aa, ac, 1.0)
    assert close([k.ABAT, k.ABCT, k.AB], [u.ABAT, u.ABCT, u.AB], A, 1e-13)
    assert close([k.E2, k.E3], [u.E2, u.E3], A / min(rz2, rz3), 1e-13)
    assert close([k.ABAN, k.ABCN], [v.W2**2 * rz2, v.W3**2 * rz3], A, 1e-13)


def test_kind1_branch_conventions_dprm1_vs_dknma1():
    # A = (0, 0), C = (1, 0), AB = 0.8, CB = 0.6: B = (0.64, -+0.48)
    r = K.DPRM1(0.0, 0.0, 1.0, 0.0, 0.8, 0.6, -1)
    assert r.XB == pytest.approx(0.64) and r.YB == pytest.approx(0.48)     # left of A->C
    k = K.DKNMA1(0.0, 0.0, 1.0, 0.0, 0.8, 0.6, 0, 0, 0, 0, 0, 0, 0, 0, 1)
    assert k.XB == pytest.approx(0.64) and k.YB == pytest.approx(0.48)


@pytest.mark.parametrize("ratio", [1e-6, 1e-3, 1.0, 1e3, 1e6])
def test_kind1_link_ratios(ratio):
    # AB = ratio, AC = 1, the angle at A 1 rad; CB from the cosine law
    rz2, d = ratio, 1.0
    rz3 = math.sqrt(d * d + rz2 * rz2 - 2 * d * rz2 * math.cos(1.0))
    for p in (-1, 1):
        r = K.DPRM1(0.3, -0.2, 0.3 + d, -0.2, rz2, rz3, p)
        L = max(rz2, rz3, d)
        assert abs(math.hypot(r.XB - 0.3, r.YB + 0.2) - rz2) <= 1e-12 * L
        assert abs(math.hypot(r.XB - 0.3 - d, r.YB + 0.2) - rz3) <= 1e-12 * L
        assert abs(angdiff(r.FI2, -p * 1.0)) <= 1e-12 * L / min(rz2, d)   # conditioning
        with warnings.catch_warnings():
            # with AB = 1e6 the angle at B is 1e-6 rad: GELG rightly warns (near dead centre)
            warnings.simplefilter("ignore", sarkp.SignificanceWarning)
            v = K.DSKOR1(rz2, r.FI2, rz3, r.FI3, 1.0, 0.3, 0.0, 0.0)
        assert all(math.isfinite(x) for x in v)


def test_dprm1_keeps_the_books_angle_ranges():
    """Corrected DPRM1 takes FI2, FI3 as the directions of B - A, B - C (two arctangents);
    the values must stay the book's: FIAC - P*angle A and FIAC + P*(angle C - pi), DUGOL'd
    once (L1497-1500), so up to 3 pi for P = -1.  Against those formulas evaluated here
    with the cosine law, on 20000 random triangles with A->C in every direction."""
    rng = np.random.default_rng(17)
    n = 20000
    xa, ya, ang = rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(-np.pi, np.pi, n)
    d = rng.uniform(0.2, 2.0, n)
    xc, yc = xa + d * np.cos(ang), ya + d * np.sin(ang)
    d = np.hypot(xc - xa, yc - ya)
    rz2 = rng.uniform(0.2, 2.0, n)
    rz3 = rng.uniform(np.abs(d - rz2) + 1e-3, d + rz2 - 1e-3)
    p = rng.choice([-1.0, 1.0], n)
    r = K.DPRM1(xa, ya, xc, yc, rz2, rz3, p)
    dugol = lambda f: np.where(f < 0, f + 2 * np.pi, f)                  # noqa: E731
    fiac = dugol(np.arctan2(yc - ya, xc - xa))
    a = np.arccos((d**2 + rz2**2 - rz3**2) / (2 * d * rz2))
    c = np.arccos((d**2 + rz3**2 - rz2**2) / (2 * d * rz3))
    fi2, fi3 = dugol(fiac - p * a), dugol(fiac + p * c - p * np.pi)
    assert (fi3 > 2 * np.pi).sum() > 1000 and (fi2 > 2 * np.pi).sum() > 1000
    np.testing.assert_allclose(r.FI2, fi2, rtol=0, atol=1e-11)  # arccos near 0 or pi
    np.testing.assert_allclose(r.FI3, fi3, rtol=0, atol=1e-11)


@pytest.mark.parametrize("k", [-990, -500, -61, 61, 500, 600, 900])
@pytest.mark.parametrize("mode", ["corrected", "as-printed"])
def test_kinds_1_and_2_scale_by_powers_of_two(k, mode):
    """A mechanism scaled by 2**k (exact in binary): positions, velocities and accelerations
    scale by 2**k, angles, omegas and epsilons do not, from 1e-298 to 1e271 (DKNMA1, DPRM1,
    DKNMA2).  Beyond 2**60
    the triangle is solved in scaled units (tri_apex's exponent e /= 0).  At 2**600 the
    acceleration's error estimate squared the velocities' error (1e-16 V)**2 and overflowed
    (the position came back singular; now ev/RZ2*(2|Y1| + ev)).  The top is GELG's: like
    LAPACK's DGESC2 it declines a right-hand side above about 1e291 times the pivot
    (IER = -1), which DKNMA1's accelerations reach at 2**970."""
    s = 2.0**k
    a, c = (0.1 * math.cos(0.7), 0.1 * math.sin(0.7)), (0.4, 0.05)
    args = dict(XA=a[0], YA=a[1], XC=c[0], YC=c[1], RZ2=0.35, RZ3=0.3, VA=0.3, ALA=2.3,
                VC=0.0, ALC=0.0, AA=0.9, BA=3.8, AC=0.0, BC=0.0, P=1.0, ANALOG=0.0)
    lengths = {"XA", "YA", "XC", "YC", "RZ2", "RZ3", "VA", "VC", "AA", "AC"}
    scaled = {n: v * s if n in lengths else v for n, v in args.items()}
    with sarkp.mode(mode):
        base, big = K.DKNMA1(**scaled), K.DKNMA1(**args)
        pb, pr = K.DPRM1(a[0] * s, a[1] * s, c[0] * s, c[1] * s, 0.35 * s, 0.3 * s, -1), \
            K.DPRM1(a[0], a[1], c[0], c[1], 0.35, 0.3, -1)
    for name in base._fields:
        unit = s if name in {"XB", "YB", "VBA", "VBC", "VB", "ABCN", "ABAN", "ABAT", "ABCT",
                             "AB"} else 1.0
        assert getattr(base, name) / unit == pytest.approx(getattr(big, name), rel=1e-14,
                                                           abs=1e-14), name
    for name in pb._fields:
        unit = s if name in {"XB", "YB"} else 1.0
        assert getattr(pb, name) / unit == pytest.approx(getattr(pr, name), rel=1e-14,
                                                         abs=1e-14), name
    # DKNMA2 (its acceleration estimate had the same overflow), a case with the slider
    # moving against the guide (ALBBM = FIM - pi) and the guide turning (WM /= 0)
    args2 = dict(XA=0.1, YA=0.3, XK=0.0, YK=0.0, FIM=0.2, RZ2=0.5, RZ3=0.1, ETA=0.3, VA=0.4,
                 ALA=1.0, WM=0.5, VBM=0.2, ALBM=0.7, AA=0.3, BA=2.0, ABM=0.1, BBM=0.4, P=1.0,
                 ANALOG=0.0)
    lengths2 = {"XA", "YA", "XK", "YK", "RZ2", "RZ3", "VA", "VBM", "AA", "ABM"}
    with sarkp.mode(mode):
        k2 = K.DKNMA2(**{n: v * s if n in lengths2 else v for n, v in args2.items()})
        r2 = K.DKNMA2(**args2)
    for name in r2._fields:
        unit = s if name in {"XB", "YB", "VBA", "VBBM", "VB", "ABAN", "ABK", "ABAT", "ABBM",
                             "AB"} else 1.0
        assert getattr(k2, name) / unit == pytest.approx(getattr(r2, name), rel=1e-14,
                                                         abs=1e-14), name


# ---------------------------------------------------------------------------------------
# kind 2 (RRP)
# ---------------------------------------------------------------------------------------

class Guide:
    """A guide through K turning about the fixed centre V: angle fim0 + w t + eps t^2/2."""

    def __init__(self, rng, turning=True):
        self.v = rng.uniform(-1, 1, 2)
        self.k0 = rng.uniform(-1, 1, 2)
        self.f0 = rng.uniform(-math.pi, math.pi)
        self.w = rng.uniform(-1, 1) if turning else 0.0
        self.eps = rng.uniform(-1, 1) if turning else 0.0

    def rot(self, t):
        return self.w * t + 0.5 * self.eps * t * t

    def k(self, t):
        q = self.rot(np.atleast_1d(t))
        d = self.k0 - self.v
        return self.v[:, None] + np.array([d[0] * np.cos(q) - d[1] * np.sin(q),
                                           d[0] * np.sin(q) + d[1] * np.cos(q)])

    def fim(self, t):
        return self.f0 + self.rot(np.atleast_1d(t))

    def omega(self, t):
        return self.w + self.eps * t

    def point_vel(self, p, t):
        """velocity of the guide-link point at p (components)."""
        r = p - self.v
        return self.omega(t) * np.array([-r[1], r[0]])

    def point_acc(self, p, t):
        r = p - self.v
        w = self.omega(t)
        return -w * w * r + self.eps * np.array([-r[1], r[0]])


def kind2(rng, turning=True):
    a, g = Crank(rng), Guide(rng, turning)
    pa = a.pos(0.0)[:, 0]
    # A must not cross the guide while the derivatives are taken: DPRM2 offsets B towards
    # A, so the offset changes sides there (the book's convention)
    for _ in range(10):
        if abs(np.dot(pa - g.k0, e(g.f0 + math.pi / 2))) >= 0.1:
            break
        g.k0 = rng.uniform(-1, 1, 2)
    else:                                   # the guide 0.5 from A
        g.k0 = pa - 0.5 * e(g.f0 + math.pi / 2)
    f = g.f0
    n = e(f + math.pi / 2)
    side = 1.0 if np.dot(pa - g.k0, n) > 0 else -1.0
    off = rng.uniform(0.0, 0.3)             # RZ3*sin(T), towards A
    t = rng.uniform(0.3, 1.2)
    rz3 = off / math.sin(t)
    for _ in range(10):
        s = rng.uniform(-2, 2)
        b = g.k0 + s * e(f) + side * off * n
        ab = b - pa
        if np.linalg.norm(ab) > 0.3 and abs(np.dot(ab, e(f))) > 0.5 * np.linalg.norm(ab):
            break
    else:                  # ahead of A's foot by 1 + its distance from the guide: AB is
        dist = abs(np.dot(pa - g.k0, n))         # longer than 0.3 and within 60 deg of it
        b = g.k0 + (np.dot(pa - g.k0, e(f)) + 1.0 + dist) * e(f) + side * off * n
        ab = b - pa
    rz2 = np.linalg.norm(ab)
    ahead = np.dot(b - pa, e(f)) > 0          # B ahead of the foot of A along FIM
    return a, g, b, rz2, rz3, t, (0.0 if ahead else math.pi)


@SETTINGS
@given(RNGS)
def test_kind2_positions_branch_and_closure(rng):
    a, g, b, rz2, rz3, t, flip = kind2(rng)
    xa, ya = a.pos(0.0)[:, 0]
    r = K.DPRM2(xa, ya, g.k0[0], g.k0[1], g.f0 + flip, rz2, rz3, t)
    L = max(rz2, 1.0)
    assert close([r.XB, r.YB], b, L, 1e-12)
    assert abs(math.hypot(r.XB - xa, r.YB - ya) - rz2) <= 1e-12 * L
    n = e(g.f0 + math.pi / 2)
    assert abs(abs(np.dot(np.array([r.XB, r.YB]) - g.k0, n)) - rz3 * math.sin(t)) <= 1e-12 * L


@SETTINGS
@given(RNGS)
def test_kind2_velocities_and_accelerations_are_derivatives(rng):
    a, g, b, rz2, rz3, t0, flip = kind2(rng)
    h = step(max(abs(a.w), abs(g.w)), rz2)
    t = STEPS * h
    pa, pk = a.pos(t), g.k(t)
    fim = g.fim(t) + flip
    r = K.DPRM2(pa[0], pa[1], pk[0], pk[1], fim, rz2, rz3, t0)
    bb = np.stack([r.XB, r.YB], -1)
    va = np.array([a.vel(ti) for ti in t])
    vbm = np.array([polar(g.point_vel(bb[i], ti)) for i, ti in enumerate(t)])
    v = K.DSKOR2(va[:, 0], va[:, 1], vbm[:, 0], vbm[:, 1], rz2, r.FI2, fim)
    vb = vec(v.VB, v.ALB)
    S = max(np.abs(vb[4]).max(), a.r * abs(a.w), 1e-3)
    assert close(ddt(bb, h), vb[4], S, 1e-8)
    assert close(ddt(np.unwrap(r.FI2), h), v.W2[4], S / rz2, 1e-8)
    # the sliding velocity: v_B = v_BM + v_BBM, along the guide
    assert close(vec(vbm[4, 0], vbm[4, 1]) + vec(v.VBBM[4], v.ALBBM[4]), vb[4], S, 1e-12)
    # accelerations
    aa = a.acc(0.0)
    abm = polar(g.point_acc(bb[4], 0.0))
    w = g.omega(0.0)
    abk, bvk = 2 * abs(w) * v.VBBM[4], sarkp.DUGL3(v.ALBBM[4], math.pi / 2, w)
    u = K.DUSKR2(aa[0], aa[1], abm[0], abm[1], abk, bvk, rz2, r.FI2[4], v.W2[4], fim[4])
    A = max(abs(u.AB), S * max(abs(a.w), 1.0), 1e-3)
    assert close(ddt(vb, h), vec(u.AB, u.BB), A, 1e-8)
    assert close(ddt(v.W2, h), u.E2, A / rz2, 1e-8)


@SETTINGS
@given(RNGS, st.sampled_from([-1, 1]), st.sampled_from([0.0, 1.0]))
def test_dknma2_equals_chain(rng, p, analog):
    a, g, b, rz2, rz3, t0, _ = kind2(rng)
    xa, ya = a.pos(0.0)[:, 0]
    # DKNMA2 offsets B to the left of the guide, DPRM2 towards A: put A on the left
    n = e(g.f0 + math.pi / 2)
    s = np.dot(np.array([xa, ya]) - g.k0, n)
    if s < 0:
        xa, ya = np.array([xa, ya]) - 2 * s * n
    rz2 = max(rz2, abs(s) + 0.2)
    (va, ala), (aa, ba) = a.vel(0), a.acc(0)
    wm, vbm, albm, abm, bbm = g.w, rng.uniform(0, 1), rng.uniform(-3, 3), rng.uniform(0, 1), \
        rng.uniform(-3, 3)
    k = K.DKNMA2(xa, ya, g.k0[0], g.k0[1], g.f0, rz2, rz3, t0, va, ala, wm, vbm, albm, aa, ba,
                 abm, bbm, p, analog)
    r = K.DPRM2(xa, ya, g.k0[0], g.k0[1], g.f0 + (0.0 if p == 1 else math.pi), rz2, rz3, t0)
    assert close([k.XB, k.YB], [r.XB, r.YB], rz2, 1e-13)
    assert close(angdiff(k.FI2, r.FI2), 0, 1, 1e-13)
    v = K.DSKOR2(va, ala, vbm, albm, rz2, r.FI2, g.f0)
    V = max(va, vbm, v.VB, 1.0)
    assert close([k.VBA, k.VBBM, k.VB, k.W2 * rz2], [v.VBA, v.VBBM, v.VB, v.W2 * rz2], V, 1e-13)
    assert same([k.VBA, k.VBBM, k.VB], [k.ALBA, k.ALBBM, k.ALB],
                [v.VBA, v.VBBM, v.VB], [v.ALBA, v.ALBBM, v.ALB], V)
    if analog == 1.0:
        assert k.AB == k.E2 == 0.0
        return
    abk, bbk = 2 * abs(wm) * v.VBBM, sarkp.DUGL3(v.ALBBM, math.pi / 2, wm)
    assert close([k.ABK, k.ABAN], [abk, v.W2**2 * rz2], V, 1e-13)
    u = K.DUSKR2(aa, ba, abm, bbm, abk, bbk, rz2, r.FI2, v.W2, g.f0)
    A = max(aa, abm, abk, u.AB, 1.0)
    assert close([k.ABAT, k.ABBM, k.AB, k.E2 * rz2], [u.ABAT, u.ABVM, u.AB, u.E2 * rz2], A, 1e-13)
    assert same([k.AB, k.ABAT, k.ABBM], [k.BB, k.BBAT, k.BBBM],
                [u.AB, u.ABAT, u.ABVM], [u.BB, u.VBAT, u.BVBM], A)


# ---------------------------------------------------------------------------------------
# kind 3 (RPR)
# ---------------------------------------------------------------------------------------

def kind3(rng):
    a, c = Crank(rng), Crank(rng)
    pa = a.pos(0.0)[:, 0]
    pc = away(c, pa, 0.2)
    d = np.linalg.norm(pa - pc)
    h = rng.uniform(-0.9, 0.9) * d                  # signed distance of A from the axis
    t = rng.uniform(0.4, 2.7)
    rz2 = abs(h) / math.sin(t)
    p = -1 if h > 0 else 1                          # L1565: P = -1 <=> A on the left
    fica = math.atan2(*(pa - pc)[::-1])
    fi3 = fica - math.asin(h / d)
    return a, c, rz2, t, p, fi3


@SETTINGS
@given(RNGS)
def test_kind3_positions_branch(rng):
    a, c, rz2, t, p, fi3 = kind3(rng)
    (xa, ya), (xc, yc) = a.pos(0.0)[:, 0], c.pos(0.0)[:, 0]
    r = K.DPRM3(xa, ya, xc, yc, rz2, t, p)
    assert close(angdiff(r.FI3, fi3), 0, 1, 1e-12)
    # A is RZ2*sin(T) from the axis through C, on the side P says
    u = np.array([xa - xc, ya - yc])
    cross = math.cos(r.FI3) * u[1] - math.sin(r.FI3) * u[0]
    assert abs(abs(cross) - rz2 * math.sin(t)) <= 1e-12 * max(r.RZAC, 1.0)
    assert (cross > 0) == (p == -1) or rz2 * math.sin(t) < 1e-9


@SETTINGS
@given(RNGS)
def test_kind3_velocities_and_accelerations_are_derivatives(rng):
    a, c, rz2, t0, p, _ = kind3(rng)
    h = step(max(abs(a.w), abs(c.w)))
    t = STEPS * h
    pa, pc = a.pos(t), c.pos(t)
    r = K.DPRM3(pa[0], pa[1], pc[0], pc[1], rz2, t0, p)
    va, vc = [np.array([x.vel(ti) for ti in t]) for x in (a, c)]
    v = K.DSKOR3(pa[0], pa[1], pc[0], pc[1], va[:, 0], va[:, 1], vc[:, 0], vc[:, 1], r.FI3)
    S = max(a.r * abs(a.w), c.r * abs(c.w), v.VA3[4], 1e-3)
    w3 = ddt(np.unwrap(r.FI3), h)
    assert close(w3, v.W3[4], S / r.RZAC[4], 1e-8)
    # A3: the point of link 3 at A at t = 0, followed as a material point of link 3
    rel = (pa - pc)[:, 4]
    q = r.FI3 - r.FI3[4]
    p3 = pc + np.array([rel[0] * np.cos(q) - rel[1] * np.sin(q),
                        rel[0] * np.sin(q) + rel[1] * np.cos(q)])
    assert close(ddt(p3.T, h), vec(v.VA3[4], v.ALA3[4]), S, 1e-8)
    # sliding: v_A3 - v_A along the axis
    assert close(vec(va[4, 0], va[4, 1]) + vec(v.VA3A[4], v.ALA3A[4]), vec(v.VA3[4], v.ALA3[4]),
                 S, 1e-12)
    assert abs(math.sin(v.ALA3A[4] - r.FI3[4])) < 1e-12 or v.VA3A[4] < 1e-12 * S
    # accelerations
    aa, ac = a.acc(0.0), c.acc(0.0)
    w = v.W3[4]
    aak, bak = 2 * abs(w) * v.VA3A[4], sarkp.DUGL3(v.ALA3A[4], math.pi / 2, w)
    u = K.DUSKR3(aa[0], aa[1], ac[0], ac[1], r.FI3[4], w, r.RZAC[4], r.FICA[4], aak, bak)
    A = max(abs(u.AA3), S * max(abs(a.w), abs(c.w), 1.0), 1e-3)
    assert close(ddt(v.W3, h), u.E3, A / r.RZAC[4], 1e-8)
    # second differences on a 4x coarser grid (rounding grows like 1/h**2)
    H = 4 * h
    pa2, pc2 = a.pos(STEPS * H), c.pos(STEPS * H)
    fi3 = K.DPRM3(pa2[0], pa2[1], pc2[0], pc2[1], rz2, t0, p).FI3
    q = fi3 - fi3[4]
    p3 = pc2 + np.array([rel[0] * np.cos(q) - rel[1] * np.sin(q),
                         rel[0] * np.sin(q) + rel[1] * np.cos(q)])
    assert close(d2dt2(p3.T, H), vec(u.AA3, u.BA3), A, 1e-8)


@SETTINGS
@given(RNGS, st.sampled_from([-1, 1]), st.sampled_from([0.0, 1.0]))
def test_dknma3_equals_chain(rng, p, analog):
    a, c, rz2, t0, _, _ = kind3(rng)
    (xa, ya), (xc, yc) = a.pos(0.0)[:, 0], c.pos(0.0)[:, 0]
    (va, ala), (vc, alc), (aa, ba), (ac, bc) = a.vel(0), c.vel(0), a.acc(0), c.acc(0)
    r = K.DPRM3(xa, ya, xc, yc, rz2, t0, -p)          # DKNMA3's P is DPRM3's -P
    if t0 > math.pi / 2 and rz2 > r.RZAC:
        # DPRM3 only needs A's distance from the axis; DKNMA3's angle ABC = ETA cannot be
        # obtuse when AB > AC (E-DKNMA3-4)
        with pytest.raises(sarkp.AssemblyError):
            K.DKNMA3(xa, ya, xc, yc, rz2, t0, va, ala, vc, alc, aa, ba, ac, bc, p, analog)
        return
    k = K.DKNMA3(xa, ya, xc, yc, rz2, t0, va, ala, vc, alc, aa, ba, ac, bc, p, analog)
    # the same axis; DKNMA3's FI3 is the ray C -> B, which may point the other way
    assert close((k.FI3 - r.FI3 + math.pi / 2) % math.pi - math.pi / 2, 0, 1, 1e-13)
    assert abs(math.hypot(k.XB - xa, k.YB - ya) - rz2) <= 1e-12 * max(rz2, 1.0)
    v = K.DSKOR3(xa, ya, xc, yc, va, ala, vc, alc, r.FI3)
    V = max(va, vc, v.VA3, 1.0)
    assert close([k.VAR, k.VAC, k.VA3, k.W3 * r.RZAC], [v.VA3A, v.VA3C, v.VA3, v.W3 * r.RZAC],
                 V, 1e-13)
    assert same([k.VAR, k.VAC, k.VA3], [k.ALAR, k.ALAC, k.ALA3],
                [v.VA3A, v.VA3C, v.VA3], [v.ALA3A, v.ALA3C, v.ALA3], V)
    if analog == 1.0:
        assert k.AA3 == k.E3 == 0.0
        return
    aak, bak = 2 * abs(v.W3) * v.VA3A, sarkp.DUGL3(v.ALA3A, math.pi / 2, v.W3)
    u = K.DUSKR3(aa, ba, ac, bc, r.FI3, v.W3, r.RZAC, r.FICA, aak, bak)
    A = max(aa, ac, aak, u.AA3, 1.0)
    assert close([k.AAK, k.AAR, k.AACT, k.AA3, k.E3 * r.RZAC],
                 [aak, u.AA3AR, u.AA3CT, u.AA3, u.E3 * r.RZAC], A, 1e-13)
    assert same([k.AAR, k.AACT, k.AA3], [k.BAR, k.BACT, k.BA3],
                [u.AA3AR, u.AA3CT, u.AA3], [u.BA3AR, u.BA3CT, u.BA3], A)


# ---------------------------------------------------------------------------------------
# kind 4 (PRP)
# ---------------------------------------------------------------------------------------

def kind4(rng):
    m, n = Guide(rng), Guide(rng)
    if abs(math.sin(m.f0 - n.f0)) < 0.3:       # guides 90 deg apart rather than parallel
        n.f0 = m.f0 + math.pi / 2
    rz2, t2, rz3, t3 = rng.uniform(0, 0.5), rng.uniform(-3, 3), rng.uniform(0, 0.5), \
        rng.uniform(-3, 3)
    return m, n, rz2, t2, rz3, t3


@SETTINGS
@given(RNGS)
def test_kind4_positions_velocities_accelerations(rng):
    m, n, rz2, t2, rz3, t3 = kind4(rng)
    h = step(max(abs(m.w), abs(n.w)))
    t = STEPS * h
    km, kn, fm, fn = m.k(t), n.k(t), m.fim(t), n.fim(t)
    r = K.DPRM4(m.v[0], m.v[1], km[0], km[1], fm, n.v[0], n.v[1], kn[0], kn[1], fn,
                rz2, t2, rz3, t3)
    bb = np.stack([r.XB, r.YB], -1)
    # B is on both offset lines (E-DPRM4-1/2: the printed matrix mirrors or drops a line)
    for kk, ff, d in ((km, fm, rz2 * math.sin(t2)), (kn, fn, rz3 * math.sin(t3))):
        nn = e(ff + math.pi / 2)
        assert close(((bb.T - kk) * nn).sum(0), d, 3.0, 1e-12)
    v = K.DSKOR4(r.RVBM, r.FIVBM, fm, r.RVBN, r.FIVBN, fn, m.omega(t), n.omega(t))
    vb = vec(v.VB, v.ALB)
    S = max(np.abs(vb[4]).max(), 1e-2)
    assert close(ddt(bb, h), vb[4], S, 1e-8)
    # sliding velocities: v_B = v_BM + v_BBM = v_BN + v_BBN
    assert close(m.point_vel(bb[4], 0.0) + vec(v.VBBM[4], v.ALBBM[4]), vb[4], S, 1e-12)
    assert close(n.point_vel(bb[4], 0.0) + vec(v.VBBN[4], v.ALBBN[4]), vb[4], S, 1e-12)
    wm, wn = m.omega(0.0), n.omega(0.0)
    u = K.DUSKR4(r.RVBM[4], r.FIVBM[4], fm[4], r.RVBN[4], r.FIVBN[4], fn[4], wm, m.eps, wn,
                 n.eps, 2 * abs(wm) * v.VBBM[4], sarkp.DUGL3(v.ALBBM[4], math.pi / 2, wm),
                 2 * abs(wn) * v.VBBN[4], sarkp.DUGL3(v.ALBBN[4], math.pi / 2, wn))
    A = max(abs(u.AB), S, 1e-2)
    assert close(ddt(vb, h), vec(u.AB, u.BB), A, 1e-8)


@SETTINGS
@given(RNGS, st.sampled_from([0.0, 1.0]))
def test_dknma4_equals_chain(rng, analog):
    m, n, rz2, t2, rz3, t3 = kind4(rng)
    # DKNMA4's guides turn about the points A, C it is given
    xa, ya, xc, yc = m.v[0], m.v[1], n.v[0], n.v[1]
    wm, wn, em, en = m.w, n.w, m.eps, n.eps
    k = K.DKNMA4(m.f0, xa, ya, n.f0, xc, yc, rz2, t2, rz3, t3, wm, wn, em, en, analog)
    r = K.DPRM4(xa, ya, xa, ya, m.f0, xc, yc, xc, yc, n.f0, rz2, t2, rz3, t3)
    assert close([k.XB, k.YB], [r.XB, r.YB], 3.0, 1e-13)
    v = K.DSKOR4(r.RVBM, r.FIVBM, m.f0, r.RVBN, r.FIVBN, n.f0, wm, wn)
    V = max(v.VB, 1.0)
    assert close([k.VB2R, k.VB3R, k.VB], [v.VBBM, v.VBBN, v.VB], V, 1e-13)
    assert same([k.VB2R, k.VB3R, k.VB], [k.ALB2R, k.ALB3R, k.ALB],
                [v.VBBM, v.VBBN, v.VB], [v.ALBBM, v.ALBBN, v.ALB], V)
    if analog == 1.0:
        assert k.AB == 0.0
        return
    ck = (2 * abs(wm) * v.VBBM, sarkp.DUGL3(v.ALBBM, math.pi / 2, wm),
          2 * abs(wn) * v.VBBN, sarkp.DUGL3(v.ALBBN, math.pi / 2, wn))
    u = K.DUSKR4(r.RVBM, r.FIVBM, m.f0, r.RVBN, r.FIVBN, n.f0, wm, em, wn, en, *ck)
    A = max(u.AB, 1.0)
    assert close([k.AB2K, k.AB3K, k.AB2R, k.AB3R, k.AB], [ck[0], ck[2], u.ABBMR, u.ABBNR, u.AB],
                 A, 1e-13)
    assert same([k.AB2R, k.AB3R, k.AB], [k.BB2R, k.BB3R, k.BB],
                [u.ABBMR, u.ABBNR, u.AB], [u.BBBMR, u.BBBNR, u.BB], A)


def test_dknma4_guide_acceleration_with_zero_omega():
    # E-DKNMA4-3: a guide starting from rest (WM = 0, EM /= 0) must give the tangential
    # direction, not 0; the result equals DUSKR4 with the same data
    k = K.DKNMA4(0.3, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0)
    r = K.DPRM4(0.0, 0.0, 0.0, 0.0, 0.3, 1.0, 0.0, 1.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0)
    u = K.DUSKR4(r.RVBM, r.FIVBM, 0.3, r.RVBN, r.FIVBN, 2.0, 0.0, 2.0, 0.0, 0.0, 0, 0, 0, 0)
    assert k.AB == pytest.approx(u.AB, rel=1e-13)
    assert angdiff(k.BB, u.BB) == pytest.approx(0.0, abs=1e-12)


# ---------------------------------------------------------------------------------------
# kind 5 (RPP)
# ---------------------------------------------------------------------------------------

def kind5(rng):
    c, m = Crank(rng), Guide(rng)
    t2 = rng.choice([-1, 1]) * rng.uniform(0.4, math.pi - 0.4)
    return c, m, t2


@SETTINGS
@given(RNGS)
def test_kind5_positions_velocities_accelerations(rng):
    c, m, t2 = kind5(rng)
    h = step(max(abs(c.w), abs(m.w)))
    t = STEPS * h
    pc, km, fm = c.pos(t), m.k(t), m.fim(t)
    r = K.DPRM5(km[0], km[1], fm, pc[0], pc[1], t2)
    kk = np.stack([r.XK, r.YK], -1)
    assert close(kk + vec(r.S3, fm + t2), pc.T, 3.0, 1e-12)
    vc = np.array([c.vel(ti) for ti in t])
    v = K.DSKOR5(pc[0], pc[1], m.v[0], m.v[1], fm, t2, m.omega(t), vc[:, 0], vc[:, 1])
    # C2: the point of link 2 at C at t = 0, a material point of link 2 (K is one too)
    rel = pc[:, 4] - kk[4]
    q = fm - fm[4]
    p2 = kk + np.stack([rel[0] * np.cos(q) - rel[1] * np.sin(q),
                        rel[0] * np.sin(q) + rel[1] * np.cos(q)], -1)
    S = max(v.VC2[4], c.r * abs(c.w), 1e-2)
    assert close(ddt(p2, h), vec(v.VC2[4], v.ALC2[4]), S, 1e-8)
    w = m.omega(0.0)
    ck = (2 * abs(w) * v.VC2CM[4], sarkp.DUGL3(v.ALC2CM[4], math.pi / 2, w),
          2 * abs(w) * v.VC2C3[4], sarkp.DUGL3(v.ALC2C3[4], math.pi / 2, w))
    ac = c.acc(0.0)
    u = K.DUSKR5(pc[0, 4], pc[1, 4], m.v[0], m.v[1], fm[4], w, m.eps, t2, ac[0], ac[1], *ck)
    A = max(u.AC2, S, 1e-2)
    # second differences on a 4x coarser grid (rounding grows like 1/h**2)
    H = 4 * h
    pc, km, fm = c.pos(STEPS * H), m.k(STEPS * H), m.fim(STEPS * H)
    r = K.DPRM5(km[0], km[1], fm, pc[0], pc[1], t2)
    kk = np.stack([r.XK, r.YK], -1)
    q = fm - fm[4]
    p2 = kk + np.stack([rel[0] * np.cos(q) - rel[1] * np.sin(q),
                        rel[0] * np.sin(q) + rel[1] * np.cos(q)], -1)
    assert close(d2dt2(p2, H), vec(u.AC2, u.BC2), A, 1e-8)


@SETTINGS
@given(RNGS, st.sampled_from([0.0, 1.0]))
def test_dknma5_equals_chain(rng, analog):
    c, m, t2 = kind5(rng)
    xc, yc = c.pos(0.0)[:, 0]
    (vc, alc), (ac, bc) = c.vel(0), c.acc(0)
    wm, em = m.w, m.eps
    k = K.DKNMA5(9.0, 9.0, m.f0, xc, yc, 0.0, t2, 0.0, m.v[0], m.v[1], wm, em, vc, alc, ac, bc,
                 analog)
    v = K.DSKOR5(xc, yc, m.v[0], m.v[1], m.f0, t2, wm, vc, alc)
    V = max(vc, v.VC2, 1.0)
    assert close([k.VC2C3, k.VC2CM, k.VC], [v.VC2C3, v.VC2CM, v.VC2], V, 1e-13)
    assert same([k.VC2C3, k.VC2CM, k.VC], [k.ALC2C3, k.ALC2CM, k.ALC],
                [v.VC2C3, v.VC2CM, v.VC2], [v.ALC2C3, v.ALC2CM, v.ALC2], V)
    if analog == 1.0:
        assert k.AC == 0.0
        return
    ck = (2 * abs(wm) * v.VC2CM, sarkp.DUGL3(v.ALC2CM, math.pi / 2, wm),
          2 * abs(wm) * v.VC2C3, sarkp.DUGL3(v.ALC2C3, math.pi / 2, wm))
    u = K.DUSKR5(xc, yc, m.v[0], m.v[1], m.f0, wm, em, t2, ac, bc, *ck)
    A = max(u.AC2, ac, 1.0)
    assert close([k.AC2C3R, k.AC2CMR, k.AC], [u.AC2C3R, u.AC2CMR, u.AC2], A, 1e-13)
    assert same([k.AC2C3R, k.AC2CMR, k.AC], [k.BC2C3R, k.BC2CMR, k.BC],
                [u.AC2C3R, u.AC2CMR, u.AC2], [u.BC2C3R, u.BC2CMR, u.BC2], A)


# ---------------------------------------------------------------------------------------
# errors
# ---------------------------------------------------------------------------------------

def test_non_assembly_raises():
    with pytest.raises(sarkp.AssemblyError):
        K.DPRM1(0, 0, 3, 0, 1.0, 1.0, 1)                  # too far
    with pytest.raises(sarkp.AssemblyError):
        K.DPRM1(0, 0, 0.5, 0, 3.0, 1.0, 1)                # too near
    with pytest.raises(sarkp.AssemblyError):
        K.DPRM2(0, 2, 0, 0, 0.0, 1.0, 0.0, 0.0)           # A too far from the guide
    with pytest.raises(sarkp.AssemblyError):
        K.DPRM3(0, 0, 1, 0, 2.0, math.pi / 2, 1)          # offset larger than AC
    with pytest.raises(sarkp.AssemblyError):
        K.DKNMA1(0, 0, 3, 0, 1.0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0, 1)
    with pytest.raises(sarkp.AssemblyError):
        K.DKNMA2(0, 2, 0, 0, 0.0, 1.0, 0.0, 0.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1)
    with pytest.raises(sarkp.AssemblyError):
        K.DKNMA3(0, 0, 1, 0, 2.0, math.pi / 2, 0, 0, 0, 0, 0, 0, 0, 0, 1)


def test_dead_centre_raises():
    with pytest.raises(sarkp.SingularError):              # AB, CB collinear
        K.DSKOR1(1.0, 0.0, 1.0, math.pi, 1.0, 0.5, 0.0, 0.0)
    with pytest.raises(sarkp.SingularError):              # AB perpendicular to the guide
        K.DSKOR2(1.0, 0.0, 0.0, 0.0, 1.0, math.pi / 2, 0.0)
    with pytest.raises(sarkp.SingularError):              # parallel guides
        K.DPRM4(0, 0, 0, 0, 0.2, 0, 0, 0, 1, 0.2, 0, 0, 0, 0)
    with pytest.raises(sarkp.SingularError):              # slot parallel to the guide
        K.DSKOR5(1, 1, 0, 0, 0.3, 0.0, 1.0, 1.0, 0.0)
    with pytest.raises(sarkp.SingularError):              # flat four-bar: B on AC
        r = K.DPRM1(0, 0, 2, 0, 1.0, 1.0, 1)
        K.DSKOR1(1.0, r.FI2, 1.0, r.FI3, 1.0, math.pi / 2, 0.0, 0.0)
    with pytest.raises(sarkp.SingularError):
        K.DKNMA1(0, 0, 2, 0, 1.0, 1.0, 1.0, math.pi / 2, 0, 0, 0, 0, 0, 0, 1)


def test_failed_calls_give_nan_from_the_drivers():
    """The drivers set the results of a failed call to NaN, in one place (the routines
    leave them as they are); the status says why."""
    f = sarkp._sarkp.drv_kinematics
    *out, status, bad = f.dprm1_1(0, 0.0, 0.0, 3.0, 0.0, 1.0, 1.0, 1.0, 1.0)
    assert (status, bad) == (sarkp.Status.ASSEMBLY, 0) and all(math.isnan(x) for x in out)
    *out, status, bad = f.dskor1_1(0, 1.0, 0.0, 1.0, math.pi, 1.0, 0.5, 0.0, 0.0, 1.0)
    assert (status, bad) == (sarkp.Status.SINGULAR, 0) and all(math.isnan(x) for x in out)
    *out, status, bad = f.dprm1_1(0, 0.0, 0.0, 3.0, 0.0, -1.0, 1.0, 1.0, 1.0)
    assert bad == 5 and all(math.isnan(x) for x in out)     # RZ2 < 0: screened, not run


def test_non_grashof_sweep_loses_assembly():
    # crank 1, coupler 2, rocker 1.5, frame 3: no full turn (1 + 3 > 2 + 1.5)
    fi = np.linspace(0, TWO_PI, 73)
    xa, ya = np.cos(fi), np.sin(fi)
    r = K.DPRM1(xa, ya, 3.0, 0.0, 2.0, 1.5, -1, on_error="nan")
    bad = r.status != 0
    assert bad.any() and (~bad).any()
    assert np.all(r.status[bad] == sarkp.library.ST_ASSEMBLY)
    assert np.all(np.isnan(r.XB[bad])) and np.all(np.isfinite(r.XB[~bad]))
    reach = np.hypot(xa - 3.0, ya) <= 3.5
    assert np.array_equal(~bad, reach)
    first = int(np.flatnonzero(bad)[0])
    with pytest.raises(sarkp.AssemblyError, match=rf"\[{first}\]"):
        K.DPRM1(xa, ya, 3.0, 0.0, 2.0, 1.5, -1)


def test_sweep_equals_scalar_calls():
    rng = np.random.default_rng(7)
    xa, ya = rng.uniform(-0.3, 0.3, (2, 20))
    r = K.DKNMA1(xa, ya, 1.0, 0.2, 0.9, 0.7, 1.0, 0.3, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 1)
    for i in range(20):
        s = K.DKNMA1(xa[i], ya[i], 1.0, 0.2, 0.9, 0.7, 1.0, 0.3, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 1)
        assert tuple(x[i] for x in r) == tuple(s)
    # a mixed ANALOG array: accelerations only where ANALOG != 1
    an = np.where(np.arange(20) % 2 == 0, 1.0, 0.0)
    m = K.DKNMA1(xa, ya, 1.0, 0.2, 0.9, 0.7, 1.0, 0.3, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 1, an)
    assert np.all(m.AB[an == 1.0] == 0.0) and np.array_equal(m.AB[an == 0.0], r.AB[an == 0.0])


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="RZ2"):
        K.DPRM1(0, 0, 1, 0, -1.0, 1.0, 1)
    with pytest.raises(ValueError, match="P"):
        K.DPRM1(0, 0, 1, 0, 1.0, 1.0, 0)
    with pytest.raises(ValueError, match="XA"):
        K.DSKOR3(math.nan, 0, 1, 0, 1, 0, 0, 0, 0)


# ---------------------------------------------------------------------------------------
# the as-printed switch (E-DUSKR1-1)
# ---------------------------------------------------------------------------------------

def test_duskr1_as_printed_switch():
    args = (1.0, 0.3, 0.5, 2.0, 0.8, 0.6435, 0.6, 2.2143, 0.75, -1.3333)
    fixed = K.DUSKR1(*args)
    with sarkp.as_printed():
        book = K.DUSKR1(*args)
    assert sarkp.get_mode() == "corrected"
    assert book.ABCT == pytest.approx(book.ABAT, rel=1e-15)     # ABCT = ABS(Y(1)), L2043
    assert fixed.ABCT != pytest.approx(fixed.ABAT, rel=1e-3)
    assert book.E3 == pytest.approx(math.copysign(book.ABAT / 0.6, book.E3))
    assert abs(fixed.E3) == pytest.approx(fixed.ABCT / 0.6)


# ---------------------------------------------------------------------------------------
# special positions and guides
# ---------------------------------------------------------------------------------------

def test_dknma2_a_on_the_right_of_the_guide():
    # E-DKNMA2-3: A below a guide along +x (on its right), offset 0.2 to the guide's left:
    # the printed SIGN(AO1, FIK - FIM) takes A for being on the left and misses |AB| = RZ2
    k = K.DKNMA2(0.0, -0.5, 0.0, 0.0, 0.0, 1.0, 0.4, 0.5 * math.pi, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1)
    assert math.hypot(k.XB, k.YB + 0.5) == pytest.approx(1.0, abs=1e-14)
    assert k.YB == pytest.approx(0.4, abs=1e-14)          # left normal of FIM = 0
    assert k.XB > 0


def test_dknma5_guide_acceleration_with_zero_epsilon():
    # E-DKNMA5-4: EM = 0 must give the centripetal direction (the book sets BCM = 0)
    k = K.DKNMA5(0, 0, 0.3, 1.0, 0.5, 0, 1.2, 0, 0.0, 0.0, 2.0, 0.0, 1.0, 0.4, 3.0, 1.0)
    v = K.DSKOR5(1.0, 0.5, 0.0, 0.0, 0.3, 1.2, 2.0, 1.0, 0.4)
    ck = (4 * v.VC2CM, sarkp.DUGL3(v.ALC2CM, math.pi / 2, 2.0),
          4 * v.VC2C3, sarkp.DUGL3(v.ALC2C3, math.pi / 2, 2.0))
    u = K.DUSKR5(1.0, 0.5, 0.0, 0.0, 0.3, 2.0, 0.0, 1.2, 3.0, 1.0, *ck)
    assert k.AC == pytest.approx(u.AC2, rel=1e-13)
    assert angdiff(k.BC, u.BC2) == pytest.approx(0.0, abs=1e-12)


def test_dprm2_a_on_the_guide_with_offset_is_singular():
    with pytest.raises(sarkp.SingularError):
        K.DPRM2(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.2, 1.0)
    r = K.DPRM2(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0)   # no offset: B = A + (1, 0)
    assert (r.XB, r.YB) == pytest.approx((2.0, 0.0))


def test_vertical_guides():
    # the book's TAN(FIM) formulation fails at FIM = pi/2; the rewrite does not
    r = K.DPRM2(0.0, 0.0, 1.0, 5.0, math.pi / 2, 2.0, 0.0, 0.0)
    assert (r.XB, r.YB) == pytest.approx((1.0, math.sqrt(3.0)), abs=1e-14)
    q = K.DPRM4(0, 0, 2.0, 0.0, math.pi / 2, 0, 0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert (q.XB, q.YB) == pytest.approx((2.0, 1.0), abs=1e-14)


def test_dskor1_too_fast_is_a_range_error_not_a_dead_centre():
    """Far from a dead centre (FI2 = 1, FI3 = 2) the answer is linear in VA: W2 scales
    exactly with it as long as it is a double (VA = 1e300: W2 = 1.41e300, which GELG's
    DGESC2 refused before the kind-1 kernel's Cramer solve, issue 27); a W2 beyond the
    doubles (links 100 times shorter, VA = 1e306: 1.4e310) is a range problem, not a
    singular position."""
    slow = sarkp.DSKOR1(0.35, 1.0, 0.3, 2.0, 1.0, 0.0, 0.0, 0.0)
    for va in (1e250, 1e300):
        fast = sarkp.DSKOR1(0.35, 1.0, 0.3, 2.0, va, 0.0, 0.0, 0.0)
        assert fast.W2 == pytest.approx(slow.W2 * va, rel=1e-14)
    with pytest.raises(sarkp.RangeError):
        sarkp.DSKOR1(0.0035, 1.0, 0.003, 2.0, 1e306, 0.0, 0.0, 0.0)
