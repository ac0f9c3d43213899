"""Chapter 7: force analysis of the Assur groups (DNMAF1-5, DNMA1-5, DUGL6).

Every result is held against statics: for random valid groups of each kind and random
loads, the forces and moments on each link of the group sum to zero (to 1e-10 of the
loads' scale), with the outputs read under the conventions each docstring states.  The
conventions themselves are pinned by showing that the other reading does not balance.
DNMA* and DNMAF* give the same reactions with their opposite sign conventions.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import sarkp
from sarkp import (DNMA1, DNMA2, DNMA3, DNMA4, DNMA5, DNMAF1, DNMAF2, DNMAF3, DNMAF4,
                   DNMAF5, DUGL6)

PI = math.pi
PID2 = PI / 2
TOL = 1e-10

coord = st.floats(-1.0, 1.0)
angle = st.floats(-PI, PI)
# Loads of at least 1 N: a prismatic pair whose force is exactly zero carries a pure
# couple, which an arm cannot express (the routines then return the arm 0).
force = st.floats(1.0, 1000.0)
moment = st.floats(-200.0, 200.0)
SETTINGS = settings(max_examples=150, deadline=None)


def e(g):
    return np.array([math.cos(g), math.sin(g)])


def vec(f, g):
    return f * e(g)


def cross(r, f):
    return float(r[0] * f[1] - r[1] * f[0])


def sin_between(g1, g2):
    return abs(math.sin(g1 - g2))


class Balance:
    """Collects force and moment residuals of one group and their scales."""

    def __init__(self, loads, length):
        self.force_scale = max(1.0, *loads)
        self.length = max(1.0, length)
        self.residuals = []

    def forces(self, *vectors):
        self.residuals.append(np.abs(sum(vectors)).max() / self.force_scale)

    def moments(self, *terms):
        self.residuals.append(abs(sum(terms)) / (self.force_scale * self.length))

    def arm_moments(self, force, *terms):
        """A moment balance that uses an arm of ``force``: skipped when the force vanishes
        (the pair then carries a pure couple, which no arm expresses; the arm is 0)."""
        if force > 1e-9 * self.force_scale:
            self.moments(*terms)

    def check(self, tol=TOL):
        worst = max(self.residuals)
        assert worst < tol, f"residuals {self.residuals}"


def quiet(routine, *args):
    """Call a routine, letting a near-singular warning pass (the test checks the result)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sarkp.SignificanceWarning)
        return routine(*args)


# ---------------------------------------------------------------------------------------
# DUGL6: the direction of a vector sum
# ---------------------------------------------------------------------------------------

@SETTINGS
@given(force, angle, force, angle, angle)
def test_dugl6_is_the_direction_of_the_sum(rn, gn, rt, gt, fi):
    total = vec(rn, gn) + vec(rt, gt)
    assume(np.hypot(*total) > 1e-6 * max(rn, rt, 1.0))
    g = DUGL6(rn, gn, rt, gt, fi)
    assert -PID2 < g < 1.5 * PI + 1e-15
    assert np.allclose(np.hypot(*total) * e(g), total, rtol=0, atol=1e-12 * max(rn, rt))


# ---------------------------------------------------------------------------------------
# projection method: F21, F34 are the forces the group exerts on the chain
# ---------------------------------------------------------------------------------------

@SETTINGS
@given(coord, coord, coord, coord, coord, coord, coord, coord, force, angle, coord, coord,
       force, angle, moment, moment)
def test_dnmaf1_every_link_balances(xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3,
                                    g3, t2, t3):
    A, B, C, S2, S3 = (np.array(p) for p in ((xa, ya), (xb, yb), (xc, yc), (xs2, ys2),
                                             (xs3, ys3)))
    assume(min(np.hypot(*(B - A)), np.hypot(*(B - C)), np.hypot(*(C - A))) > 0.05)
    assume(abs(cross((B - A) / np.hypot(*(B - A)), (C - A) / np.hypot(*(C - A)))) > 0.05)
    r = quiet(DNMAF1, xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    F12, F32 = -vec(r.F21, r.G21), -vec(r.F23, r.G23)
    F23, F43 = vec(r.F23, r.G23), -vec(r.F34, r.G34)
    bal = Balance((f2, f3, r.F21, r.F23, r.F34, abs(t2), abs(t3)), 2.0)
    bal.forces(F12, vec(f2, g2), F32)                             # link 2
    bal.moments(t2, cross(A, F12), cross(S2, vec(f2, g2)), cross(B, F32))
    bal.forces(F23, vec(f3, g3), F43)                             # link 3
    bal.moments(t3, cross(B, F23), cross(S3, vec(f3, g3)), cross(C, F43))
    bal.check()


@SETTINGS
@given(coord, coord, coord, coord, angle, coord, coord, force, angle, coord, coord, force,
       angle, moment, moment)
def test_dnmaf2_every_link_balances(xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3,
                                    t2, t3):
    A, B, S2, S3 = (np.array(p) for p in ((xa, ya), (xb, yb), (xs2, ys2), (xs3, ys3)))
    ab = np.hypot(*(B - A))
    assume(ab > 0.05 and abs(np.dot((B - A) / ab, e(fim))) > 0.05)
    r = quiet(DNMAF2, xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    F12, F32 = -vec(r.F21, r.G21), -vec(r.F23, r.G23)
    F23, F43 = vec(r.F23, r.G23), -vec(r.F34, r.G34)
    bal = Balance((f2, f3, r.F21, r.F23, r.F34, abs(t2), abs(t3)), 2.0)
    bal.forces(F12, vec(f2, g2), F32)
    bal.moments(t2, cross(A, F12), cross(S2, vec(f2, g2)), cross(B, F32))
    bal.forces(F23, vec(f3, g3), F43)
    bal.forces(np.dot(F43, e(fim)) * e(fim))                      # F34 normal to the guide
    # H34*F34 is the moment about B of the guide's reaction F43 on link 3
    bal.arm_moments(r.F34, t3, cross(S3 - B, vec(f3, g3)), r.H34 * r.F34)
    bal.check()


@SETTINGS
@given(coord, coord, coord, coord, angle, coord, coord, force, angle, coord, coord, force,
       angle, moment, moment)
def test_dnmaf3_every_link_balances(xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3,
                                    t2, t3):
    A, C, S2, S3 = (np.array(p) for p in ((xa, ya), (xc, yc), (xs2, ys2), (xs3, ys3)))
    ac = np.hypot(*(C - A))
    assume(ac > 0.05 and abs(np.dot((C - A) / ac, e(fi3))) > 0.05)
    r = quiet(DNMAF3, xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    F12, F23 = -vec(r.F21, r.G21), vec(r.F23, r.G23)
    F43 = -vec(r.F34, r.G34)
    bal = Balance((f2, f3, r.F21, r.F23, r.F34, abs(t2), abs(t3)), 2.0)
    bal.forces(F12, vec(f2, g2), -F23)
    bal.forces(np.dot(F23, e(fi3)) * e(fi3))                      # F23 normal to the guide
    bal.forces(F23, vec(f3, g3), F43)
    # H23*F23 = moment about C of F23 (2 on 3); on link 2 the same line carries -F23
    bal.arm_moments(r.F23, t3, cross(S3 - C, vec(f3, g3)), r.H23 * r.F23)
    bal.arm_moments(r.F23, t2, cross(A - C, F12), cross(S2 - C, vec(f2, g2)),
                    -r.H23 * r.F23)
    bal.check()


@SETTINGS
@given(angle, angle, coord, coord, coord, coord, force, angle, coord, coord, force, angle,
       moment, moment)
def test_dnmaf4_every_link_balances(fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                    t3):
    B, S2, S3 = (np.array(p) for p in ((xb, yb), (xs2, ys2), (xs3, ys3)))
    assume(sin_between(fim, fin) > 0.05)
    r = quiet(DNMAF4, fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    F12, F32 = -vec(r.F21, r.G21), -vec(r.F23, r.G23)
    F23, F43 = vec(r.F23, r.G23), -vec(r.F34, r.G34)
    bal = Balance((f2, f3, r.F21, r.F23, r.F34, abs(t2), abs(t3)), 2.0)
    bal.forces(F12, vec(f2, g2), F32)
    bal.forces(np.dot(F12, e(fim)) * e(fim))
    bal.forces(F23, vec(f3, g3), F43)
    bal.forces(np.dot(F43, e(fin)) * e(fin))
    # arms about B: H21*F21 = moment of F12, H34*F34 = moment of F43 (E-DNMAF4-3)
    bal.arm_moments(r.F21, t2, cross(S2 - B, vec(f2, g2)), r.H21 * r.F21)
    bal.arm_moments(r.F34, t3, cross(S3 - B, vec(f3, g3)), r.H34 * r.F34)
    bal.check()


@SETTINGS
@given(coord, coord, angle, angle, coord, coord, force, angle, coord, coord, force, angle,
       moment, moment)
def test_dnmaf5_every_link_balances(xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2,
                                    t3):
    A, S2, S3 = (np.array(p) for p in ((xa, ya), (xs2, ys2), (xs3, ys3)))
    assume(abs(math.sin(tt3)) > 0.05)
    r = quiet(DNMAF5, xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3)
    F12, F32 = -vec(r.F21, r.G21), vec(r.F32, r.G32)
    F43 = -vec(r.F34, r.G34)
    bal = Balance((f2, f3, r.F21, r.F32, r.F34, abs(t2), abs(t3)), 2.0)
    bal.forces(F12, vec(f2, g2), F32)
    bal.forces(np.dot(F32, e(fim + tt3)) * e(fim + tt3))          # F32 normal to the inner guide
    bal.forces(-F32, vec(f3, g3), F43)
    bal.forces(np.dot(F43, e(fim)) * e(fim))
    # arms about A: H32*F32 = moment of F32, H34*F34 = moment of F43
    bal.arm_moments(r.F32, t2, cross(S2 - A, vec(f2, g2)), r.H32 * r.F32)
    bal.arm_moments(r.F34, t2 + t3, cross(S2 - A, vec(f2, g2)), cross(S3 - A, vec(f3, g3)),
                    r.H34 * r.F34)
    bal.check()


# ---------------------------------------------------------------------------------------
# vector method: RA, RC are the reactions on the group's links
# ---------------------------------------------------------------------------------------

def _dnma1_case(A, B, C, bs2, bs3, loads):
    l2, fi2 = np.hypot(*(B - A)), math.atan2(*(B - A)[::-1])
    l3, fi3 = np.hypot(*(B - C)), math.atan2(*(B - C)[::-1])
    r = quiet(DNMA1, l2, fi2, l3, fi3, bs2, bs3, *loads)
    return r, fi2, fi3


def _dnma1_balance(A, B, C, S2, S3, loads, r):
    m2, q2, g2, m3, q3, g3 = loads
    RA, RB, RC = vec(r.RA, r.GA), vec(r.RB, r.GB), vec(r.RC, r.GC)
    bal = Balance((q2, q3, r.RA, r.RB, r.RC, abs(m2), abs(m3)), 2.0)
    bal.forces(RA, vec(q2, g2), RB)
    bal.moments(m2, cross(A, RA), cross(S2, vec(q2, g2)), cross(B, RB))
    bal.forces(-RB, vec(q3, g3), RC)
    bal.moments(m3, cross(B, -RB), cross(S3, vec(q3, g3)), cross(C, RC))
    return bal


@SETTINGS
@given(coord, coord, coord, coord, coord, coord, st.floats(-1, 1), st.floats(-1, 1),
       moment, force, angle, moment, force, angle)
def test_dnma1_balances_with_s_beyond_b(xa, ya, xb, yb, xc, yc, k2, k3, m2, q2, g2, m3, q3,
                                        g3):
    """E-DNMA1-3: S2 = B + BS2 e(FI2), S3 = B + BS3 e(FI3) (FI2 = A->B, FI3 = C->B)."""
    A, B, C = np.array([xa, ya]), np.array([xb, yb]), np.array([xc, yc])
    assume(np.hypot(*(B - A)) > 0.05 and np.hypot(*(B - C)) > 0.05)
    assume(abs(cross((B - A) / np.hypot(*(B - A)), (B - C) / np.hypot(*(B - C)))) > 0.05)
    loads = (m2, q2, g2, m3, q3, g3)
    bs2, bs3 = k2 * np.hypot(*(B - A)), k3 * np.hypot(*(B - C))
    r, fi2, fi3 = _dnma1_case(A, B, C, bs2, bs3, loads)
    _dnma1_balance(A, B, C, B + bs2 * e(fi2), B + bs3 * e(fi3), loads, r).check()


def test_dnma1_does_not_balance_with_s_towards_a():
    """The other reading of BS2 (measured from B towards A) breaks the moment balance."""
    A, B, C = np.array([0.1, 0.2]), np.array([0.5, 0.4]), np.array([0.7, -0.1])
    loads = (5.0, 100.0, -PID2, -8.0, 200.0, PI)
    r, fi2, fi3 = _dnma1_case(A, B, C, 0.1, 0.15, loads)
    bal = _dnma1_balance(A, B, C, B - 0.1 * e(fi2), B - 0.15 * e(fi3), loads, r)
    assert max(bal.residuals) > 1e-3


def _dnma2_balance(A, B, fi2, fio, eta, bs2, bs3, loads, r):
    m2, q2, g2, m3, q3, g3 = loads
    S2, S3 = B + bs2 * e(fi2), B + bs3 * e(fio + eta)
    RA, RB, RC = vec(r.RA, r.GA), vec(r.RB, r.GB), vec(r.RC, r.GC)
    bal = Balance((q2, q3, r.RA, r.RB, r.RC, abs(m2), abs(m3)), 2.0)
    bal.forces(RA, vec(q2, g2), RB)
    bal.moments(m2, cross(A - B, RA), cross(S2 - B, vec(q2, g2)))
    bal.forces(-RB, vec(q3, g3), RC)
    bal.forces(np.dot(RC, e(fio)) * e(fio))
    bal.arm_moments(r.RC, m3, cross(S3 - B, vec(q3, g3)), r.HC * r.RC)  # HC*RC: of RC about B
    return bal


@SETTINGS
@given(coord, coord, coord, coord, angle, angle, st.floats(-1, 1), st.floats(-1, 1), moment,
       force, angle, moment, force, angle)
def test_dnma2_balances(xa, ya, xb, yb, fio, eta, bs2, bs3, m2, q2, g2, m3, q3, g3):
    """E-DNMA2-3: S2 = B + BS2 e(FI2), S3 = B + BS3 e(FIO + ETA); L3 is not used."""
    A, B = np.array([xa, ya]), np.array([xb, yb])
    l2 = np.hypot(*(B - A))
    assume(l2 > 0.05 and abs(np.dot((B - A) / l2, e(fio))) > 0.05)
    fi2 = math.atan2(*(B - A)[::-1])
    loads = (m2, q2, g2, m3, q3, g3)
    r = quiet(DNMA2, l2, fi2, 0.3, eta, fio, bs2, bs3, *loads)
    _dnma2_balance(A, B, fi2, fio, eta, bs2, bs3, loads, r).check()


def _dnma3_balance(A, C, fi3, S2, S3, loads, r):
    m2, q2, g2, m3, q3, g3 = loads
    RA, RB, RC = vec(r.RA, r.GA), vec(r.RB, r.GB), vec(r.RC, r.GC)
    bal = Balance((q2, q3, r.RA, r.RB, r.RC, abs(m2), abs(m3)), 2.0)
    bal.forces(RA, vec(q2, g2), RB)
    bal.forces(np.dot(RB, e(fi3)) * e(fi3))                       # RB normal to the guide
    bal.forces(-RB, vec(q3, g3), RC)
    # HB*RB = moment about C of the force on 3 from 2 (-RB); link 2 carries +RB on that line
    bal.arm_moments(r.RB, m3, cross(S3 - C, vec(q3, g3)), r.HB * r.RB)
    bal.arm_moments(r.RB, m2, cross(A - C, RA), cross(S2 - C, vec(q2, g2)), -r.HB * r.RB)
    return bal


@SETTINGS
@given(coord, coord, coord, coord, angle, st.floats(0, 1), angle, st.floats(0, 1), angle,
       moment, force, angle, moment, force, angle)
def test_dnma3_balances_with_fiac_from_a_to_c(xa, ya, xc, yc, fi3, cs2, fics2, cs3, fics3,
                                              m2, q2, g2, m3, q3, g3):
    """E-DNMA3-4: FIAC is the direction A->C; E-DNMA3-1: Q2, G2 follow M2."""
    A, C = np.array([xa, ya]), np.array([xc, yc])
    ac = np.hypot(*(C - A))
    assume(ac > 0.05 and abs(np.dot((C - A) / ac, e(fi3))) > 0.05)
    fiac = math.atan2(*(C - A)[::-1])
    loads = (m2, q2, g2, m3, q3, g3)
    r = quiet(DNMA3, 0.3, 0.0, fi3, cs2, fics2, cs3, fics3, ac, fiac, *loads)
    _dnma3_balance(A, C, fi3, C + cs2 * e(fics2), C + cs3 * e(fics3), loads, r).check()


def test_dnma3_does_not_balance_with_fiac_from_c_to_a():
    """The printed DUGL3(FIAC, -PID2, RAT) reads as if FIAC ran C->A; it does not balance
    that way, because Fortran's SIGN(-PID2, RAT) drops the minus."""
    A, C = np.array([0.1, 0.2]), np.array([0.7, -0.1])
    fi3, loads = 2.0, (5.0, 100.0, -PID2, -8.0, 200.0, -1.2)
    ac, fica = np.hypot(*(A - C)), math.atan2(*(A - C)[::-1])
    r = DNMA3(0.3, 0.0, fi3, 0.2, 1.0, 0.25, 2.5, ac, fica, *loads)
    bal = _dnma3_balance(A, C, fi3, C + 0.2 * e(1.0), C + 0.25 * e(2.5), loads, r)
    assert max(bal.residuals) > 1e-3


def _dnma4_balance(fim, eta2, fin, eta3, bs2, bs3, loads, r):
    m2, q2, g2, m3, q3, g3 = loads
    RA, RB, RC = vec(r.RA, r.GA), vec(r.RB, r.GB), vec(r.RC, r.GC)
    bal = Balance((q2, q3, r.RA, r.RB, r.RC, abs(m2), abs(m3)), 2.0)
    bal.forces(RA, vec(q2, g2), RB)
    bal.forces(np.dot(RA, e(fim)) * e(fim))
    bal.forces(-RB, vec(q3, g3), RC)
    bal.forces(np.dot(RC, e(fin)) * e(fin))
    bal.arm_moments(r.RA, m2, cross(bs2 * e(fim + eta2), vec(q2, g2)), r.HA * r.RA)
    bal.arm_moments(r.RC, m3, cross(bs3 * e(fin + eta3), vec(q3, g3)), r.HC * r.RC)
    return bal


@SETTINGS
@given(angle, angle, angle, angle, st.floats(-1, 1), st.floats(-1, 1), moment, force, angle,
       moment, force, angle)
def test_dnma4_balances(fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3):
    """E-DNMA4-2: S2 = B + BS2 e(FIM + ETA2), S3 = B + BS3 e(FIN + ETA3);
    E-DNMA4-1 (FIN, not FIM, in HC's moment) is what makes link 3 balance."""
    assume(sin_between(fim, fin) > 0.05)
    loads = (m2, q2, g2, m3, q3, g3)
    r = quiet(DNMA4, fim, eta2, fin, eta3, bs2, bs3, *loads)
    _dnma4_balance(fim, eta2, fin, eta3, bs2, bs3, loads, r).check()


def _dnma5_balance(fim, eta3, S2, S3, A, loads, r):
    m2, q2, g2, m3, q3, g3 = loads
    RA, RB, RC = vec(r.RA, r.GA), vec(r.RB, r.GB), vec(r.RC, r.GC)
    bal = Balance((q2, q3, r.RA, r.RB, r.RC, abs(m2), abs(m3)), 2.0)
    bal.forces(RA, vec(q2, g2), -RB)                              # RB acts on 3, from 2
    bal.forces(np.dot(RB, e(fim + eta3)) * e(fim + eta3))
    bal.forces(RB, vec(q3, g3), RC)
    bal.forces(np.dot(RC, e(fim)) * e(fim))
    bal.arm_moments(r.RB, m2, cross(S2 - A, vec(q2, g2)), r.HB * r.RB)
    bal.arm_moments(r.RC, m2 + m3, cross(S2 - A, vec(q2, g2)), cross(S3 - A, vec(q3, g3)),
                    r.HC * r.RC)
    return bal


@SETTINGS
@given(angle, angle, st.floats(0, 1), st.floats(0, 1), angle, angle, moment, force, angle,
       moment, force, angle)
def test_dnma5_balances_with_fias_from_s_to_a(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2,
                                              m3, q3, g3):
    """E-DNMA5-3: FIAS2, FIAS3 are the directions S2->A, S3->A; E-DNMA5-2: RB acts on 3."""
    assume(abs(math.sin(eta3)) > 0.05)
    A = np.array([0.1, 0.2])
    loads = (m2, q2, g2, m3, q3, g3)
    r = quiet(DNMA5, eta3, fim, as2, as3, fias2, fias3, *loads)
    _dnma5_balance(fim, eta3, A - as2 * e(fias2), A - as3 * e(fias3), A, loads, r).check()


def test_dnma5_does_not_balance_with_fias_from_a_to_s():
    A, loads = np.array([0.1, 0.2]), (5.0, 100.0, -PID2, -8.0, 200.0, -1.2)
    r = DNMA5(1.2, 0.3, 0.1, 0.2, 2.0, -2.5, *loads)
    bal = _dnma5_balance(0.3, 1.2, A + 0.1 * e(2.0), A + 0.2 * e(-2.5), A, loads, r)
    assert max(bal.residuals) > 1e-3


# ---------------------------------------------------------------------------------------
# the two families agree: DNMA* = -DNMAF* (reactions on, not forces of, the group)
# ---------------------------------------------------------------------------------------

def same(v1, v2, scale):
    return np.abs(v1 - v2).max() <= TOL * max(scale, 1.0)


def same_moment(h1, f1, h2, f2, scale):
    """Two arms give the same moment (unless the force vanishes: a pure couple, arm 0)."""
    if min(f1, f2) <= 1e-9 * max(scale, 1.0):
        return True
    return abs(h1 * f1 - h2 * f2) <= TOL * max(scale, 1.0)


@SETTINGS
@given(coord, coord, coord, coord, coord, coord, st.floats(-1, 1), st.floats(-1, 1), moment,
       force, angle, moment, force, angle)
def test_kind1_families_agree(xa, ya, xb, yb, xc, yc, k2, k3, m2, q2, g2, m3, q3, g3):
    A, B, C = np.array([xa, ya]), np.array([xb, yb]), np.array([xc, yc])
    assume(np.hypot(*(B - A)) > 0.05 and np.hypot(*(B - C)) > 0.05)
    assume(abs(cross((B - A) / np.hypot(*(B - A)), (B - C) / np.hypot(*(B - C)))) > 0.05)
    bs2, bs3 = k2 * np.hypot(*(B - A)), k3 * np.hypot(*(B - C))
    v, fi2, fi3 = _dnma1_case(A, B, C, bs2, bs3, (m2, q2, g2, m3, q3, g3))
    S2, S3 = B + bs2 * e(fi2), B + bs3 * e(fi3)
    f = quiet(DNMAF1, *A, *B, *C, *S2, q2, g2, *S3, q3, g3, m2, m3)
    scale = max(q2, q3, abs(m2), abs(m3), f.F21, f.F23, f.F34)
    assert same(vec(v.RA, v.GA), -vec(f.F21, f.G21), scale)
    assert same(vec(v.RB, v.GB), -vec(f.F23, f.G23), scale)
    assert same(vec(v.RC, v.GC), -vec(f.F34, f.G34), scale)


@SETTINGS
@given(coord, coord, coord, coord, angle, angle, st.floats(-1, 1), st.floats(-1, 1), moment,
       force, angle, moment, force, angle)
def test_kind2_families_agree(xa, ya, xb, yb, fio, eta, bs2, bs3, m2, q2, g2, m3, q3, g3):
    A, B = np.array([xa, ya]), np.array([xb, yb])
    l2 = np.hypot(*(B - A))
    assume(l2 > 0.05 and abs(np.dot((B - A) / l2, e(fio))) > 0.05)
    fi2 = math.atan2(*(B - A)[::-1])
    v = quiet(DNMA2, l2, fi2, 0.3, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3)
    S2, S3 = B + bs2 * e(fi2), B + bs3 * e(fio + eta)
    f = quiet(DNMAF2, *A, *B, fio, *S2, q2, g2, *S3, q3, g3, m2, m3)
    scale = max(q2, q3, abs(m2), abs(m3), f.F21, f.F23, f.F34)
    assert same(vec(v.RA, v.GA), -vec(f.F21, f.G21), scale)
    assert same(vec(v.RB, v.GB), -vec(f.F23, f.G23), scale)
    assert same(vec(v.RC, v.GC), -vec(f.F34, f.G34), scale)
    assert same_moment(v.HC, v.RC, f.H34, f.F34, scale)


@SETTINGS
@given(coord, coord, coord, coord, angle, st.floats(0, 1), angle, st.floats(0, 1), angle,
       moment, force, angle, moment, force, angle)
def test_kind3_families_agree(xa, ya, xc, yc, fi3, cs2, fics2, cs3, fics3, m2, q2, g2, m3,
                              q3, g3):
    A, C = np.array([xa, ya]), np.array([xc, yc])
    ac = np.hypot(*(C - A))
    assume(ac > 0.05 and abs(np.dot((C - A) / ac, e(fi3))) > 0.05)
    v = quiet(DNMA3, 0.3, 0.0, fi3, cs2, fics2, cs3, fics3, ac, math.atan2(*(C - A)[::-1]),
              m2, q2, g2, m3, q3, g3)
    S2, S3 = C + cs2 * e(fics2), C + cs3 * e(fics3)
    f = quiet(DNMAF3, *A, *C, fi3, *S2, q2, g2, *S3, q3, g3, m2, m3)
    scale = max(q2, q3, abs(m2), abs(m3), f.F21, f.F23, f.F34)
    assert same(vec(v.RA, v.GA), -vec(f.F21, f.G21), scale)
    assert same(vec(v.RB, v.GB), -vec(f.F23, f.G23), scale)
    assert same(vec(v.RC, v.GC), -vec(f.F34, f.G34), scale)
    assert same_moment(v.HB, v.RB, f.H23, f.F23, scale)


@SETTINGS
@given(angle, angle, angle, angle, coord, coord, st.floats(-1, 1), st.floats(-1, 1), moment,
       force, angle, moment, force, angle)
def test_kind4_families_agree(fim, eta2, fin, eta3, xb, yb, bs2, bs3, m2, q2, g2, m3, q3, g3):
    assume(sin_between(fim, fin) > 0.05)
    B = np.array([xb, yb])
    v = quiet(DNMA4, fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3)
    S2, S3 = B + bs2 * e(fim + eta2), B + bs3 * e(fin + eta3)
    f = quiet(DNMAF4, fim, fin, *B, *S2, q2, g2, *S3, q3, g3, m2, m3)
    scale = max(q2, q3, abs(m2), abs(m3), f.F21, f.F23, f.F34)
    assert same(vec(v.RA, v.GA), -vec(f.F21, f.G21), scale)
    assert same(vec(v.RB, v.GB), -vec(f.F23, f.G23), scale)
    assert same(vec(v.RC, v.GC), -vec(f.F34, f.G34), scale)
    assert same_moment(v.HA, v.RA, f.H21, f.F21, scale)
    assert same_moment(v.HC, v.RC, f.H34, f.F34, scale)


@SETTINGS
@given(angle, angle, st.floats(0, 1), st.floats(0, 1), angle, angle, moment, force, angle,
       moment, force, angle)
def test_kind5_families_agree(eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3):
    assume(abs(math.sin(eta3)) > 0.05)
    A = np.array([0.1, 0.2])
    v = quiet(DNMA5, eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3)
    S2, S3 = A - as2 * e(fias2), A - as3 * e(fias3)
    f = quiet(DNMAF5, *A, fim, eta3, *S2, q2, g2, *S3, q3, g3, m2, m3)
    scale = max(q2, q3, abs(m2), abs(m3), f.F21, f.F32, f.F34)
    assert same(vec(v.RA, v.GA), -vec(f.F21, f.G21), scale)
    assert same(vec(v.RB, v.GB), -vec(f.F32, f.G32), scale)      # DNMA5's RB acts on 3
    assert same(vec(v.RC, v.GC), -vec(f.F34, f.G34), scale)
    assert same_moment(v.HB, v.RB, f.H32, f.F32, scale)
    assert same_moment(v.HC, v.RC, f.H34, f.F34, scale)


# ---------------------------------------------------------------------------------------
# the corrections that change results, each pinned by the balance it restores
# ---------------------------------------------------------------------------------------

def test_dnmaf4_uses_g12_E_DNMAF4_2():
    """With the printed G21 in the first DSMVKT, F23 would be F2 - F12: link 2 would not
    balance.  Table 29 step 6 (L5101) has gamma_12."""
    r = DNMAF4(1.0, 0.0, 0.5, 0.4, 0.45, 0.45, 100.0, -PID2, 0.5, 0.4, 200.0, PI, 5.0, -8.0)
    F12, F32 = -vec(r.F21, r.G21), -vec(r.F23, r.G23)
    assert np.abs(F12 + vec(100.0, -PID2) + F32).max() < 1e-10 * 300
    printed_f23 = vec(r.F21, r.G21) + vec(100.0, -PID2)       # what G21 would give
    assert np.abs(printed_f23 - vec(r.F23, r.G23)).max() > 100.0


def test_arms_of_zero_forces_are_zero_E_DNMA_1():
    """No load on link 3 of a PRP group: RC = 0, and HC is 0 rather than 0/0."""
    r = DNMA4(0.3, 0.0, 1.4, 0.0, 0.1, 0.1, 2.0, 100.0, -PID2, 0.0, 0.0, 0.0)
    assert r.RC == pytest.approx(0.0, abs=1e-12) or r.HC == 0.0
    assert all(math.isfinite(x) for x in r)
    f = DNMAF4(0.3, 1.4, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert f.H21 == 0.0 and f.H34 == 0.0 and f.F21 == 0.0


# ---------------------------------------------------------------------------------------
# singular positions and modes
# ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda: DNMAF1(0, 0, 1, 0, 2, 0, 0.5, 0, 10, 1, 1.5, 0, 10, 1, 0, 0),   # A, B, C collinear
    lambda: DNMAF2(0, 0, 0, 1, 0.0, 0, 0.5, 10, 1, 0, 1, 10, 1, 0, 0),      # AB normal to guide
    lambda: DNMAF3(0, 0, 1, 0, PID2, 0, 0, 10, 1, 1, 0, 10, 1, 0, 0),       # CA normal to guide
    lambda: DNMAF4(0.5, 0.5, 0, 0, 0, 0, 10, 1, 0, 0, 10, 1, 0, 0),         # parallel guides
    lambda: DNMAF5(0, 0, 0.5, 0.0, 0, 0, 10, 1, 0, 0, 10, 1, 0, 0),         # parallel guides
    lambda: DNMA1(1.0, 0.3, 1.0, 0.3, 0.1, 0.1, 1, 10, 1, 1, 10, 1),        # links aligned
    lambda: DNMA2(1.0, 0.3, 1.0, 0.0, 0.3 + PID2, 0.1, 0.1, 1, 10, 1, 1, 10, 1),
    lambda: DNMA3(1.0, 0.0, 0.3 + PID2, 0.1, 0, 0.1, 0, 1.0, 0.3, 1, 10, 1, 1, 10, 1),
    lambda: DNMA4(0.4, 0, 0.4, 0, 0.1, 0.1, 1, 10, 1, 1, 10, 1),
    lambda: DNMA5(0.0, 0.4, 0.1, 0.1, 0, 0, 1, 10, 1, 1, 10, 1),
], ids=["DNMAF1", "DNMAF2", "DNMAF3", "DNMAF4", "DNMAF5", "DNMA1", "DNMA2", "DNMA3",
        "DNMA4", "DNMA5"])
def test_singular_positions_raise(call):
    with pytest.raises(sarkp.SingularError):
        call()


def test_near_singular_warns_and_still_balances():
    """A dyad 1e-6 rad from folded: digits remain, the book's 1e-4 test warns."""
    d = 1e-6
    with pytest.warns(sarkp.SignificanceWarning):
        r = DNMAF1(0, 0, 1, 0, 2, d, 0.5, 0, 10, 1, 1.5, 0, 10, 1, 0, 0)
    assert all(math.isfinite(x) for x in r)


def test_as_printed_differs_only_by_pi():
    """No printed figure depends on an error of chapter 7: as-printed mode only changes PI,
    so the results move by ~1e-6 relative, not more."""
    args = (0.1, 0.2, 0.5, 0.4, 0.7, -0.1, 0.3, 0.3, 100.0, -PID2, 0.6, 0.15, 200.0, PI, 5.0,
            -8.0)
    c = DNMAF1(*args)
    with sarkp.as_printed():
        p = DNMAF1(*args)
    assert c != p
    assert np.allclose(c, p, rtol=1e-4, atol=1e-4)


# ---------------------------------------------------------------------------------------
# bad input and arrays
# ---------------------------------------------------------------------------------------

_DNMAF1_ARGS = (0.1, 0.2, 0.5, 0.4, 0.7, -0.1, 0.3, 0.3, 100.0, -PID2, 0.6, 0.15, 200.0, PI,
                5.0, -8.0)


@pytest.mark.parametrize("routine, args, name", [
    (DNMAF1, _DNMAF1_ARGS[:8] + (-1.0,) + _DNMAF1_ARGS[9:], "F2"),
    (DNMAF1, _DNMAF1_ARGS[:12] + (float("nan"),) + _DNMAF1_ARGS[13:], "F3"),
    (DNMAF2, (0, 0, 1, 1, 0.0, 0, 0, 10, 1, 1, 1, -5, 1, 0, 0), "F3"),
    (DNMA1, (0.0, 0.3, 1.0, 1.3, 0.1, 0.1, 1, 10, 1, 1, 10, 1), "L2"),
    (DNMA1, (1.0, 0.3, -1.0, 1.3, 0.1, 0.1, 1, 10, 1, 1, 10, 1), "L3"),
    (DNMA3, (1.0, 0.0, 2.0, 0.1, 0, 0.1, 0, 0.0, 0.3, 1, 10, 1, 1, 10, 1), "AC"),
    (DNMA5, (1.0, 0.4, -0.1, 0.1, 0, 0, 1, 10, 1, 1, 10, 1), "AS2"),
    (DNMA4, (0.4, 0, 1.4, 0, 0.1, 0.1, 1, -10, 1, 1, 10, 1), "Q2"),
    (DNMAF4, (0.3, 1.4, 0, 0, 0, 0, 10, float("inf"), 0, 0, 10, 1, 0, 0), "G2"),
])
def test_bad_input_names_the_argument(routine, args, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        routine(*args)


def test_arrays_match_scalars_and_report_the_singular_index():
    """One Fortran loop over positions; a singular position raises naming its index, or
    gives NaN with on_error='nan'."""
    xc = np.array([0.7, 0.9, 2.0 * 0.5 - 0.1])        # the last puts C on the line AB
    args = list(_DNMAF1_ARGS)
    args[0], args[1], args[2], args[3] = 0.0, 0.0, 0.5, 0.0
    args[5] = 0.0
    many = np.array([1.3, 0.9])
    a = list(args)
    a[4] = many
    a[5] = np.array([0.3, -0.2])
    r = DNMAF1(*a)
    for i in range(2):
        s = list(args)
        s[4], s[5] = float(many[i]), float(a[5][i])
        assert np.array_equal(np.array([x[i] for x in r]), np.array(DNMAF1(*s)))
    a[4], a[5] = xc, np.array([0.3, -0.2, 0.0])
    with pytest.raises(sarkp.SingularError, match=r"index \[2\]"):
        DNMAF1(*a)
    out = DNMAF1(*a, on_error="nan")
    assert list(out.status) == [0, 0, int(sarkp.Status.SINGULAR)]
    assert np.isnan(out.F21[2]) and np.isfinite(out.F21[:2]).all()


# ---------------------------------------------------------------------------------------
# virtual work along the course project of chapter 10 (program X's force analysis)
# ---------------------------------------------------------------------------------------

def _course_project(f):
    """Program X's kinematics (L7499-7531) and force analysis (L7540-7570) of the Fig. 91
    mechanism, with the link sizes fitted to Fig. 91 (fig91.csv): crank OA turning
    counter-clockwise at W1 = 3, RRR group A-B-C, lever point D, RRP group D-E with the
    slider E on a horizontal guide; weights g*m with m = 50 kg/m times the length (41),
    the resistance FS = 2000 N while W3 < 0, else 400 N, on the slider."""
    from sarkp import kinematics as K
    pi, pid2 = PI, PID2
    roa, rab, roc, rcb, rde, h5, delta, w1 = (0.16646893, 2.33535352, 2.09023145, 0.5787882,
                                              0.7012536, 0.64, 0.698, 3.0)
    g, ml = 9.81, 50.0
    m4, m3, m2 = ml * rde, 2 * rcb * ml, ml * rab
    xc, yc = -roc * math.sin(delta), roc * math.cos(delta)
    xa, ya = roa * np.cos(f), roa * np.sin(f)
    p1 = K.DPRM1(xa, ya, xc, yc, rab, rcb, -1)
    xd, yd = xc + rcb * np.cos(p1.FI3 + pi), yc + rcb * np.sin(p1.FI3 + pi)
    ye = h5 + yc
    p2 = K.DPRM2(xd, yd, 0.0, ye, 0.0, rde, 0.0, pid2)
    v1 = K.DSKOR1(rab, p1.FI2, rcb, p1.FI3, w1 * roa, f + pid2, 0.0, 0.0)
    vd, ald = rcb * np.abs(v1.W3), sarkp.DUGL3(p1.FI3 + pi, pid2, v1.W3)
    v2 = K.DSKOR2(vd, ald, 0.0, 0.0, rde, p2.FI2, 0.0)
    fs = np.where(v1.W3 < 0, 2000.0, 400.0)
    f5, g5 = sarkp.DSMVKT(fs, pi, 2 * g * m4, -pid2)
    s4 = 0.3 * rde * np.array([np.cos(p2.FI2), np.sin(p2.FI2)])
    r2 = DNMAF2(xd, yd, p2.XB, ye, 0.0, xd + s4[0], yd + s4[1], g * m4, -pid2, p2.XB, ye,
                f5, g5, 0.0, 0.0)
    f3, g3 = sarkp.DSMVKT(r2.F21, r2.G21, g * m3, -pid2)
    t3 = sarkp.DMOMNT(0.85 * rcb, p1.FI3 + pi, r2.F21, r2.G21)
    s3 = 0.15 * rcb * np.array([np.cos(p1.FI3 + pi), np.sin(p1.FI3 + pi)])
    r1 = DNMAF1(xa, ya, p1.XB, p1.YB, xc, yc, xa + 0.5 * rab * np.cos(p1.FI2),
                ya + 0.5 * rab * np.sin(p1.FI2), g * m2, -pid2, xc + s3[0], yc + s3[1], f3,
                g3, 0.0, t3)
    m1 = sarkp.DMOMNT(roa, f, r1.F21, r1.G21)
    # velocities of the load points
    v_a = w1 * roa * np.array([np.cos(f + pid2), np.sin(f + pid2)])
    v_b = v1.VB * np.array([np.cos(v1.ALB), np.sin(v1.ALB)])
    v_d = vd * np.array([np.cos(ald), np.sin(ald)])
    v_s4 = v_d + v2.W2 * np.array([-s4[1], s4[0]])
    v_s3 = v1.W3 * np.array([-s3[1], s3[0]])
    v_e = v2.VB * np.array([np.cos(v2.ALB), np.sin(v2.ALB)])
    terms = np.array([-fs * v_e[0] - 2 * g * m4 * v_e[1], -g * m4 * v_s4[1],
                      -g * m3 * v_s3[1], -g * m2 * (v_a + v_b)[1] / 2])
    return m1, terms, w1


def test_course_project_moment_equals_virtual_work():
    """Chapter 10's M1 (the moment of the groups' forces on the crank, the balancing
    moment's negative) equals the loads' power over W1 (the crank turns counter-clockwise:
    M_y W1 + P = 0 with M_y = -M1) over a fine sweep of the whole turn."""
    f = np.linspace(0.0, 2 * PI, 721)[:-1] + 1e-3
    m1, terms, w1 = _course_project(f)
    scale = np.abs(terms).sum(axis=0) / w1
    assert np.all(np.abs(m1 - terms.sum(axis=0) / w1) <= 1e-9 * scale)


def test_fig94_f21_ocr_fix_E_FIG94_2():
    """F21 at FI1 = 3.665 prints 442.5 between 488.0 and 595.3: the column's second
    differences stay below 10 with 542.5 (4 read for 5) and jump to 200 with 442.5."""
    from sarkp.book import load_figure
    cells = {int(c.row): c for c in load_figure("94").cells if c.column == "F21"}
    assert (cells[22].ocr, cells[22].printed, cells[22].errata) == ("442.5", "542.5",
                                                                   "E-FIG94-2")
    f21 = np.array([cells[k].value for k in range(20, 27)])
    assert np.abs(np.diff(f21, 2)).max() < 12.0
    f21[22 - 20] = 442.5
    assert np.abs(np.diff(f21, 2)).max() > 100.0
