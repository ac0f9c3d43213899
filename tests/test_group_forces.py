"""The chapter 7 force step of every group kind: groups.f90's group_reactions, the one kernel
that sarkp.Mechanism and, in corrected mode, the book's DNMAF1-5 and DNMA1-5 call.

* Against an independent reference: the six equilibrium equations of the group's two links
  (forces, and moments about the origin), written here from the pair types alone and solved
  in mpmath at 40 digits, for random groups of each kind, through each book routine.
* Against physics on whole mechanisms of every kind: the balancing moment's power plus the
  power of every load (gravity, inertia, forces, torques) is zero.
* The book routine and the Mechanism on the same group and loads give the same reactions
  (to rounding: the book's interface takes each load as a modulus and a direction).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import sarkp
from sarkp import (DNMA1, DNMA2, DNMA3, DNMA4, DNMA5, DNMAF1, DNMAF2, DNMAF3, DNMAF4,
                   DNMAF5, Mechanism)

PI = math.pi
R, P = "R", "P"
# Each kind's pairs 1 (outside on link 2), 2 (link 2 on link 3), 3 (outside on link 3),
# as the book's routines lay them out (the kernel's kind_pairs, DNMA5/DNMAF5's links
# swapped: the book's link 2 is the pivoted block).
KINDS = {1: (R, R, R), 2: (R, R, P), 3: (R, P, R), 4: (P, R, P), 5: (R, P, P)}

coord = st.floats(-1.0, 1.0)
angle = st.floats(-PI, PI)
force = st.floats(1.0, 1000.0)
moment = st.floats(-200.0, 200.0)
SETTINGS = settings(max_examples=60, deadline=None)
# The kernel solves a 2x2 system whose condition is about 1/sin of the angle between the
# directions of the group (assumed > 0.05 below) times the ratio of its lengths: errors of
# a few ulps of the forces' scale.  Measured worst over 360 examples of each routine:
# 2.4e-15 (DNMAF1), 1.1e-15 (DNMAF4), at most 8.4e-16 for the others.
TOL = 3e-14
# The book routine against the Mechanism on one group: the kernel is shared, the loads
# reach the book's interface as a modulus and a direction (F cos G is not the Mechanism's
# component to the bit).  Measured worst 6.0e-16 (DNMAF1), 3.0e-16 (DNMAF2): 3 ulps.
ULPS8 = 8 * np.finfo(float).eps


def e(g):
    return np.array([math.cos(g), math.sin(g)])


def reference(kind, pts, dirs, f2, m2, q2, f3, m3, q3):
    """The reactions (R1, C1), (R2, C2), (R3, C3) of a group from its six equilibrium
    equations in mpmath: a revolute's unknowns are its force, a slider's the force along
    its guide's normal and the couple.  R1 acts on link 2, R2 on link 3 (from 2), R3 on
    link 3; couples about the pair's point."""
    mp = mpmath.mp
    with mpmath.workdps(40):
        cols, rows = [], []
        for j, t in enumerate(KINDS[kind]):
            p = [mpmath.mpf(float(v)) for v in pts[j]]
            if t == R:
                basis = [((1, 0), 0), ((0, 1), 0)]           # (force, couple) per unknown
            else:
                u = dirs[j]
                n = (mpmath.mpf(-float(u[1])), mpmath.mpf(float(u[0])))
                basis = [(n, 0), ((0, 0), 1)]
            for fvec, c in basis:
                fx, fy = mpmath.mpf(fvec[0]), mpmath.mpf(fvec[1])
                mom = p[0] * fy - p[1] * fx + c              # moment about the origin
                # link 2 feels +pair 1 and -pair 2; link 3 feels +pair 2 and +pair 3
                s2 = {0: 1, 1: -1, 2: 0}[j]
                s3 = {0: 0, 1: 1, 2: 1}[j]
                cols.append([s2 * fx, s2 * fy, s2 * mom, s3 * fx, s3 * fy, s3 * mom])
        A = mp.matrix(6, 6)
        for k, col in enumerate(cols):
            for i, v in enumerate(col):
                A[i, k] = v
        def load(f, m, q):
            fx, fy = (mpmath.mpf(float(v)) for v in f)
            qx, qy = (mpmath.mpf(float(v)) for v in q)
            return [fx, fy, mpmath.mpf(float(m)) + qx * fy - qy * fx]
        b = mp.matrix([-v for v in load(f2, m2, q2) + load(f3, m3, q3)])
        z = mpmath.lu_solve(A, b)
        out = []
        for j, t in enumerate(KINDS[kind]):
            z1, z2 = z[2 * j], z[2 * j + 1]
            if t == R:
                out.append((np.array([float(z1), float(z2)]), 0.0))
            else:
                u = dirs[j]
                out.append((float(z1) * np.array([-u[1], u[0]]), float(z2)))
        return out


class Check:
    """Differences from the reference, relative to the forces' scale (and a length)."""

    def __init__(self, ref, loads, length=2.0):
        self.ref = ref
        self.scale = max([1.0] + list(loads) + [float(np.hypot(*r)) for r, _ in ref])
        self.length = length
        self.worst = 0.0

    def force(self, j, vec):
        self.worst = max(self.worst, float(np.abs(vec - self.ref[j][0]).max()) / self.scale)

    def moment(self, value, expected):
        self.worst = max(self.worst, abs(value - expected) / (self.scale * self.length))

    def done(self):
        assert self.worst < TOL, self.worst


def cross(a, b):
    return float(a[0] * b[1] - a[1] * b[0])


def vec(f, g):
    return f * e(g)


def far_apart(*pairs, limit=0.05):
    return all(abs(math.sin(a - b)) > limit for a, b in pairs)


# ---------------------------------------------------------------------------------------
# the projection family (forces of the group ON the chain: F21 = -R1, F34 = -R3)
# ---------------------------------------------------------------------------------------

@SETTINGS
@given(coord, coord, coord, coord, coord, coord, coord, coord, force, angle, coord, coord,
       force, angle, moment, moment)
def test_dnmaf1_is_the_reference(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3,
                                 t2, t3):
    A, B, C = np.array([xa, ya]), np.array([xb, yb]), np.array([xc, yc])
    assume(min(np.hypot(*(B - A)), np.hypot(*(C - A)), np.hypot(*(B - C))) > 0.05)
    assume(far_apart((math.atan2(*(B - A)[::-1]), math.atan2(*(A - C)[::-1]))))
    r = DNMAF1(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    ref = reference(1, (A, B, C), (None,) * 3, vec(f2, g2), t2, (xs2, ys2), vec(f3, g3), t3,
                    (xs3, ys3))
    c = Check(ref, (f2, f3, abs(t2), abs(t3)))
    c.force(0, -vec(r.F21, r.G21))
    c.force(1, vec(r.F23, r.G23))
    c.force(2, -vec(r.F34, r.G34))
    c.done()


@SETTINGS
@given(coord, coord, coord, coord, angle, coord, coord, force, angle, coord, coord, force,
       angle, moment, moment)
def test_dnmaf2_is_the_reference(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                 t3):
    A, B = np.array([xa, ya]), np.array([xb, yb])
    assume(np.hypot(*(B - A)) > 0.05 and far_apart((math.atan2(*(A - B)[::-1]), fim + PI / 2)))
    r = DNMAF2(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    ref = reference(2, (A, B, B), (None, None, e(fim)), vec(f2, g2), t2, (xs2, ys2),
                    vec(f3, g3), t3, (xs3, ys3))
    c = Check(ref, (f2, f3, abs(t2), abs(t3)))
    c.force(0, -vec(r.F21, r.G21))
    c.force(1, vec(r.F23, r.G23))
    c.force(2, -vec(r.F34, r.G34))
    c.moment(r.H34 * r.F34, ref[2][1])                 # the guide's couple about B
    c.done()


@SETTINGS
@given(coord, coord, coord, coord, angle, coord, coord, force, angle, coord, coord, force,
       angle, moment, moment)
def test_dnmaf3_is_the_reference(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                 t3):
    A, C = np.array([xa, ya]), np.array([xc, yc])
    assume(np.hypot(*(C - A)) > 0.05 and far_apart((math.atan2(*(A - C)[::-1]), fi3 + PI / 2)))
    r = DNMAF3(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    ref = reference(3, (A, C, C), (None, e(fi3), None), vec(f2, g2), t2, (xs2, ys2),
                    vec(f3, g3), t3, (xs3, ys3))
    c = Check(ref, (f2, f3, abs(t2), abs(t3)))
    c.force(0, -vec(r.F21, r.G21))
    c.force(1, vec(r.F23, r.G23))
    c.moment(r.H23 * r.F23, ref[1][1])                 # F23's moment about C
    c.force(2, -vec(r.F34, r.G34))
    c.done()


@SETTINGS
@given(angle, angle, coord, coord, coord, coord, force, angle, coord, coord, force, angle,
       moment, moment)
def test_dnmaf4_is_the_reference(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                 t3):
    assume(far_apart((fim, fin)))
    B = np.array([xb, yb])
    r = DNMAF4(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    ref = reference(4, (B, B, B), (e(fim), None, e(fin)), vec(f2, g2), t2, (xs2, ys2),
                    vec(f3, g3), t3, (xs3, ys3))
    c = Check(ref, (f2, f3, abs(t2), abs(t3)))
    c.force(0, -vec(r.F21, r.G21))
    c.moment(r.H21 * r.F21, ref[0][1])                 # arms about B
    c.force(1, vec(r.F23, r.G23))
    c.force(2, -vec(r.F34, r.G34))
    c.moment(r.H34 * r.F34, ref[2][1])
    c.done()


@SETTINGS
@given(coord, coord, angle, angle, coord, coord, force, angle, coord, coord, force, angle,
       moment, moment)
def test_dnmaf5_is_the_reference(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                 t3):
    assume(abs(math.sin(tt3)) > 0.05)
    A = np.array([xa, ya])
    r = DNMAF5(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    ref = reference(5, (A, A, A), (None, e(fim + tt3), e(fim)), vec(f2, g2), t2, (xs2, ys2),
                    vec(f3, g3), t3, (xs3, ys3))
    c = Check(ref, (f2, f3, abs(t2), abs(t3)))
    c.force(0, -vec(r.F21, r.G21))
    c.force(1, -vec(r.F32, r.G32))                     # F32 acts on 2: R2 = -F32
    c.moment(r.H32 * r.F32, -ref[1][1])                # arms about A
    c.force(2, -vec(r.F34, r.G34))
    c.moment(r.H34 * r.F34, ref[2][1])
    c.done()


# ---------------------------------------------------------------------------------------
# the vector family (reactions ON the group's links: RA = R1, RC = R3; RB = -R2 on link 2)
# ---------------------------------------------------------------------------------------

@SETTINGS
@given(st.floats(0.1, 2.0), angle, st.floats(0.1, 2.0), angle, coord, coord, moment, force,
       angle, moment, force, angle)
def test_dnma1_is_the_reference(l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3):
    assume(far_apart((fi2, fi3)))
    r = DNMA1(l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3)
    B = np.zeros(2)
    ref = reference(1, (B - l2 * e(fi2), B, B - l3 * e(fi3)), (None,) * 3, vec(q2, g2), m2,
                    bs2 * e(fi2), vec(q3, g3), m3, bs3 * e(fi3))
    c = Check(ref, (q2, q3, abs(m2), abs(m3)), 4.0)
    c.force(0, vec(r.RA, r.GA))
    c.force(1, -vec(r.RB, r.GB))
    c.force(2, vec(r.RC, r.GC))
    c.done()


@SETTINGS
@given(st.floats(0.1, 2.0), angle, angle, angle, coord, coord, moment, force, angle, moment,
       force, angle)
def test_dnma2_is_the_reference(l2, fi2, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3):
    assume(far_apart((fi2, fio + PI / 2)))
    r = DNMA2(l2, fi2, 1.0, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3)
    B = np.zeros(2)
    ref = reference(2, (B - l2 * e(fi2), B, B), (None, None, e(fio)), vec(q2, g2), m2,
                    bs2 * e(fi2), vec(q3, g3), m3, bs3 * e(fio + eta))
    c = Check(ref, (q2, q3, abs(m2), abs(m3)), 4.0)
    c.force(0, vec(r.RA, r.GA))
    c.force(1, -vec(r.RB, r.GB))
    c.force(2, vec(r.RC, r.GC))
    c.moment(r.HC * r.RC, ref[2][1])                   # RC's moment about B
    c.done()


@SETTINGS
@given(angle, st.floats(0.0, 1.0), angle, st.floats(0.0, 1.0), angle, st.floats(0.1, 2.0),
       angle, moment, force, angle, moment, force, angle)
def test_dnma3_is_the_reference(fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3,
                                g3):
    assume(far_apart((fiac, fi3 + PI / 2)))
    r = DNMA3(1.0, 0.0, fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3)
    C = np.zeros(2)
    A = C - ac * e(fiac)                               # FIAC runs from A to C (E-DNMA3-4)
    ref = reference(3, (A, A, C), (None, e(fi3), None), vec(q2, g2), m2, cs2 * e(fics2),
                    vec(q3, g3), m3, cs3 * e(fics3))
    c = Check(ref, (q2, q3, abs(m2), abs(m3)), 4.0)
    c.force(0, vec(r.RA, r.GA))
    c.force(1, -vec(r.RB, r.GB))
    # HB*RB: the moment about C of the force on 3 from 2 (couple about A plus A x R2)
    c.moment(r.HB * r.RB, ref[1][1] + cross(A - C, ref[1][0]))
    c.force(2, vec(r.RC, r.GC))
    c.done()


@SETTINGS
@given(angle, angle, angle, angle, coord, coord, moment, force, angle, moment, force, angle)
def test_dnma4_is_the_reference(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3):
    assume(far_apart((fim, fin)))
    r = DNMA4(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3)
    B = np.zeros(2)
    ref = reference(4, (B, B, B), (e(fim), None, e(fin)), vec(q2, g2), m2,
                    bs2 * e(fim + eta2), vec(q3, g3), m3, bs3 * e(fin + eta3))
    c = Check(ref, (q2, q3, abs(m2), abs(m3)))
    c.force(0, vec(r.RA, r.GA))
    c.moment(r.HA * r.RA, ref[0][1])
    c.force(1, -vec(r.RB, r.GB))
    c.force(2, vec(r.RC, r.GC))
    c.moment(r.HC * r.RC, ref[2][1])
    c.done()


@SETTINGS
@given(angle, angle, st.floats(0.0, 1.0), st.floats(0.0, 1.0), angle, angle, moment, force,
       angle, moment, force, angle)
def test_dnma5_is_the_reference(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3):
    assume(abs(math.sin(eta3)) > 0.05)
    r = DNMA5(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3)
    A = np.zeros(2)
    ref = reference(5, (A, A, A), (None, e(fim + eta3), e(fim)), vec(q2, g2), m2,
                    -as2 * e(fias2), vec(q3, g3), m3, -as3 * e(fias3))
    c = Check(ref, (q2, q3, abs(m2), abs(m3)))
    c.force(0, vec(r.RA, r.GA))
    c.force(1, vec(r.RB, r.GB))                        # RB acts on 3 from 2 (E-DNMA5-2)
    c.moment(r.HB * r.RB, -ref[1][1])                  # of -RB (on 2 from 3) about A
    c.force(2, vec(r.RC, r.GC))
    c.moment(r.HC * r.RC, ref[2][1])
    c.done()


def test_reference_is_independent_of_the_origin():
    """The reference itself: moving the group and its reduction points moves nothing."""
    A, B, C = np.array([0.1, 0.2]), np.array([0.5, 0.4]), np.array([0.7, -0.1])
    d = np.array([3.0, -2.0])
    r0 = reference(1, (A, B, C), (None,) * 3, vec(100, 1.0), 5.0, (0.3, 0.3), vec(50, 2.0),
                   -8.0, (0.6, 0.1))
    r1 = reference(1, (A + d, B + d, C + d), (None,) * 3, vec(100, 1.0), 5.0,
                   (0.3 + d[0], 0.3 + d[1]), vec(50, 2.0), -8.0, (0.6 + d[0], 0.1 + d[1]))
    for (f0, _), (f1, _) in zip(r0, r1):
        np.testing.assert_allclose(f0, f1, rtol=1e-14, atol=1e-12)


# ---------------------------------------------------------------------------------------
# whole mechanisms: power balance, and the book routine on the Mechanism's groups
# ---------------------------------------------------------------------------------------

G = 9.81


def _fourbar():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3, branch=1)
    m.point("S2", "A", "B", 0.15, 0.2)
    m.point("S3", "C", "B", 0.1)
    masses = [("S2", "A", 1.5, 0.012), ("S3", "C", 1.0, 0.01)]
    forces = [("S2", ("A", "B"), 30.0, -10.0)]
    torques = [(("C", "B"), -20.0)]
    return m, masses, forces, torques


def _slider_crank():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, 0.02)
    m.crank("A", "O", 0.1)
    m.rrp("B", "A", "K", 0.3, 0.4, branch=1, offset=0.01)
    m.point("S2", "A", "B", 0.2, 0.1)
    masses = [("S2", "A", 1.2, 0.02), ("B", None, 2.0, 0.003)]
    forces = [("B", ("B",), -50.0, 7.0)]
    torques = [(("A", "B"), 3.0)]
    return m, masses, forces, torques


def _rpr():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.0, -0.25)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.03, PI / 2, branch=1)
    m.point("S3", "C", "B", 0.2, 0.1)
    masses = [("S3", "C", 3.0, 0.05), ("A", "B", 0.5, 0.001)]
    forces = [("S3", ("C", "B"), 10.0, -40.0)]
    torques = [(("C", "B"), 5.0)]
    return m, masses, forces, torques


def _prp():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, 0.05)
    m.crank("A", "O", 0.1)
    m.prp("B", "A", PI / 2, "G", 0.0, guide_m=("O", "A"), rz2=0.01, t2=0.4)
    masses = [("B", "A", 0.8, 0.004), ("B", "G", 1.5, 0.002)]
    forces = [("B", ("B", "G"), 25.0, -5.0)]
    torques = [(("B", "A"), 2.0)]
    return m, masses, forces, torques


def _rpp():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.2, -0.3)
    m.crank("A", "O", 0.1)
    m.rpp("K", "G", 0.3, "A", PI / 2 + 0.2)
    masses = [("K", "G", 2.0, 0.01), ("A", "K", 0.4, 0.001)]
    forces = [("K", ("K", "G"), -60.0, 3.0)]
    torques = [(("K", "G"), 4.0)]
    return m, masses, forces, torques


MACHINES = {1: _fourbar, 2: _slider_crank, 3: _rpr, 4: _prp, 5: _rpp}


def _build(kind):
    m, masses, forces, torques = MACHINES[kind]()
    m.mass("O", "A", mass=0.3, inertia=0.001, centre=0.05)
    for p, q, mass, inertia in masses:
        m.mass(p, q, mass=mass, inertia=inertia)
    for p, link, fx, fy in forces:
        m.force(p, fx, fy, link=link)
    for link, t in torques:
        m.torque(*link, t)
    return m, masses, forces, torques


@pytest.mark.parametrize("kind", [1, 2, 3, 4, 5])
def test_power_balance(kind):
    """Virtual work: the balancing moment's power M_b omega plus the power of every load
    (weights, inertia forces -m a_S and moments -J epsilon, forces, torques) is zero at
    every position: the force step of every group and the crank's, end to end."""
    m, masses, forces, torques = _build(kind)
    phi = np.linspace(-1.2, 1.2, 25) if kind == 4 else np.linspace(0.0, 2 * PI, 37)
    w, eps = 7.0, -3.0
    r = m.solve(phi, omega=w, epsilon=eps, need="forces", gravity=G)
    terms = [r.balancing_moment * w]
    terms.append(np.full_like(phi, -0.001 * eps * w))   # the crank's inertia moment
    A_c = 0.05 * np.stack([np.cos(phi), np.sin(phi)], -1)  # the crank's centre
    vA = w * np.stack([-A_c[:, 1], A_c[:, 0]], -1)
    aA = -w * w * A_c + eps * np.stack([-A_c[:, 1], A_c[:, 0]], -1)
    terms.append(np.sum(-0.3 * (aA + [0.0, G]) * vA, -1))
    for p, q, mass, inertia in masses:
        terms.append(np.sum(-mass * (r.acceleration(p) + [0.0, G]) * r.velocity(p), -1))
        terms.append(-inertia * r.epsilon(p, q) * r.omega(p, q))
    for p, link, fx, fy in forces:
        terms.append(fx * r.velocity(p)[:, 0] + fy * r.velocity(p)[:, 1])
    for link, t in torques:
        terms.append(t * r.omega(*link))
    terms = np.array(terms)
    scale = np.abs(terms).sum(0)
    assert np.all(scale > 1.0)
    assert np.abs(terms.sum(0)).max() / scale.max() < 1e-14    # measured <= 3.0e-16


def _link_loads(r, i, mass, inertia, point, fext=(0.0, 0.0), torque=0.0, link=None):
    """One link's loads at position i, reduced to its centre of mass (the book's F, G, T)."""
    f = -mass * (r.acceleration(point)[i] + [0.0, G]) + np.asarray(fext)
    t = -inertia * r.epsilon(*link)[i] + torque
    return r.position(point)[i], float(np.hypot(*f)), math.atan2(f[1], f[0]), t


def test_dnmaf1_on_the_mechanisms_four_bar():
    """The book's DNMAF1 on the Mechanism's RRR group, fed its positions and loads, gives
    the Mechanism's reactions to rounding (the kernel is shared; the loads pass through
    the book's polar form)."""
    m, *_ = _build(1)
    phi = np.linspace(0.0, 2 * PI, 13)
    r = m.solve(phi, omega=7.0, epsilon=-3.0, need="forces", gravity=G)
    worst = 0.0
    for i in range(len(phi)):
        A, B, C = (r.position(n)[i] for n in "ABC")
        s2, f2, g2, t2 = _link_loads(r, i, 1.5, 0.012, "S2", (30.0, -10.0), 0.0, ("A", "B"))
        s3, f3, g3, t3 = _link_loads(r, i, 1.0, 0.01, "S3", (0.0, 0.0), -20.0, ("C", "B"))
        b = DNMAF1(*A, *B, *C, *s2, f2, g2, *s3, f3, g3, t2, t3)
        scale = max(f2, f3, b.F21, b.F34)
        for book, mech in ((-vec(b.F21, b.G21), r.reaction("A")[i]),
                           (vec(b.F23, b.G23), r.reaction("B")[i]),
                           (-vec(b.F34, b.G34), r.reaction("C")[i])):
            worst = max(worst, float(np.abs(book - mech).max()) / scale)
    assert worst < ULPS8, worst


def test_dnmaf2_on_the_mechanisms_slider_crank():
    m, *_ = _build(2)
    phi = np.linspace(0.0, 2 * PI, 13)
    r = m.solve(phi, omega=7.0, epsilon=-3.0, need="forces", gravity=G)
    worst = 0.0
    for i in range(len(phi)):
        A, B = r.position("A")[i], r.position("B")[i]
        s2, f2, g2, t2 = _link_loads(r, i, 1.2, 0.02, "S2", (0.0, 0.0), 3.0, ("A", "B"))
        s3, f3, g3, t3 = _link_loads(r, i, 2.0, 0.003, "B", (-50.0, 7.0), 0.0, ("B",))
        b = DNMAF2(*A, *B, 0.3, *s2, f2, g2, *s3, f3, g3, t2, t3)
        scale = max(f2, f3, b.F21, b.F34)
        for book, mech in ((-vec(b.F21, b.G21), r.reaction("A")[i]),
                           (vec(b.F23, b.G23), r.reaction("B", on=("B",), by=("A", "B"))[i])):
            worst = max(worst, float(np.abs(book - mech).max()) / scale)
    assert worst < ULPS8, worst


def test_as_printed_is_not_the_kernel():
    """As-printed mode keeps the printed arithmetic (PI = 3.14159 inside it): the two modes
    differ by about 1e-6 relative, the size of PI's error, not by rounding."""
    args = (0.1, 0.2, 0.5, 0.4, 0.7, -0.1, 0.3, 0.3, 100.0, -PI / 2, 0.6, 0.15, 200.0, PI,
            5.0, -8.0)
    c = np.array(DNMAF1(*args))
    with sarkp.as_printed():
        p = np.array(DNMAF1(*args))
    d = np.abs(c - p).max() / np.abs(c).max()
    assert 1e-8 < d < 1e-4
