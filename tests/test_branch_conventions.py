"""The book routines keep the book's branch signs; the Mechanism has one geometric rule
(+1: the joint on the left of the directed line between the group's outer joints).  The
docstrings and docs/concepts.md state the correspondence; these tests pin it over a turn."""

import math

import numpy as np

import sarkp

PHI = np.linspace(0.0, 2.0 * math.pi, 73)


def _crank_tip():
    return 0.1 * np.cos(PHI), 0.1 * np.sin(PHI)


def test_rrr_dprm1_minus_and_dknma1_plus_are_branch_plus():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.4, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3, branch=1)
    b = m.solve(PHI, need="positions").position("B")
    xa, ya = _crank_tip()
    p = sarkp.DPRM1(xa, ya, 0.4, 0.0, 0.35, 0.3, -1)
    k = sarkp.DKNMA1(xa, ya, 0.4, 0.0, 0.35, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                     0.0, 1, 1.0)
    for r in (p, k):
        assert np.max(np.hypot(r.XB - b[:, 0], r.YB - b[:, 1])) < 1e-15
    # B is on the left of A -> C: the cross product (C - A) x (B - A) is positive
    assert np.all((0.4 - xa) * (b[:, 1] - ya) - (0.0 - ya) * (b[:, 0] - xa) > 0)


def test_rpr_dprm3_minus_and_dknma3_plus_are_branch_plus():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.05, math.pi / 2, branch=1)
    fi3 = m.solve(PHI, need="positions").angle("C", "B")
    xa, ya = _crank_tip()
    p = sarkp.DPRM3(xa, ya, 0.3, 0.0, 0.05, math.pi / 2, -1)
    k = sarkp.DKNMA3(xa, ya, 0.3, 0.0, 0.05, math.pi / 2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                     0.0, 0.0, 1, 1.0)
    for r in (p, k):
        d = np.remainder(r.FI3 - fi3 + math.pi, 2 * math.pi) - math.pi
        assert np.max(np.abs(d)) < 1e-14
