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


def test_rrp_dprm2_fim_and_dknma2_p_are_the_branch():
    # the guide through K = (0, -0.05) at FIM = 0.3 (and the reversed FIM + pi); B on the
    # guide's left normal at OFF (the Mechanism's offset, DKNMA2's RZ3*sin(ETA)), or on
    # A's side at |OFF| (DPRM2's RZ3*sin(T))
    xa, ya = _crank_tip()
    for fim in (0.3, 0.3 + math.pi):
        side = np.sign(-(xa - 0.0) * math.sin(fim) + (ya + 0.05) * math.cos(fim))
        for off in (0.0, 0.02, -0.02):
            for branch in (1, -1):
                m = sarkp.Mechanism()
                m.fixed("O", 0.0, 0.0)
                m.fixed("K", 0.0, -0.05)
                m.crank("A", "O", 0.1)
                m.rrp("B", "A", "K", fim, 0.3, branch=branch, offset=off)
                b = m.solve(PHI, need="positions").position("B")
                eta = math.copysign(math.pi / 2, off)
                k = sarkp.DKNMA2(xa, ya, 0.0, -0.05, fim, 0.3, abs(off), eta, 0.0, 0.0, 0.0,
                                 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, branch, 1.0)
                p = sarkp.DPRM2(xa, ya, 0.0, -0.05, fim + (0.0 if branch == 1 else math.pi),
                                0.3, abs(off), side * np.sign(off) * math.pi / 2)
                for r in (p, k):
                    assert np.max(np.hypot(r.XB - b[:, 0], r.YB - b[:, 1])) < 1e-15
                # branch +1: B ahead of A's foot on the guide, along FIM
                ahead = (b[:, 0] - xa) * math.cos(fim) + (b[:, 1] - ya) * math.sin(fim)
                assert np.all(branch * ahead > 0)


def test_docstrings_state_the_mechanism_branch():
    # each book routine with a branch says which Mechanism branch it is
    for name, call in (("DPRM1", "Mechanism.rrr"), ("DKNMA1", "Mechanism.rrr"),
                       ("DPRM2", "Mechanism.rrp"), ("DKNMA2", "Mechanism.rrp"),
                       ("DPRM3", "Mechanism.rpr"), ("DKNMA3", "Mechanism.rpr")):
        assert call in getattr(sarkp, name).__doc__, name
