"""Chapter 7 as a designer uses it (sarkp extensions): the balancing moment at the crank
against virtual work, and the sense of the two families stated in every docstring."""

from __future__ import annotations

import math

import numpy as np
import pytest

import sarkp
from sarkp import DNMA1, DNMAF1, DPRM1, DSKOR1, balancing_moment

PI = math.pi
ROA, RAB, RCB, XC, YC, W1 = 0.1, 0.35, 0.3, 0.4, 0.05, 7.0
LOADS = dict(q2=120.0, g2=-PI / 2 + 0.3, m2=4.0, q3=80.0, g3=2.0, m3=-9.0, bs2=-0.12,
             bs3=-0.1)


def _crank_rocker(phi):
    """Positions and velocities of the crank-rocker O-A-B-C, crank counter-clockwise."""
    xa, ya = ROA * np.cos(phi), ROA * np.sin(phi)
    p = DPRM1(xa, ya, XC, YC, RAB, RCB, -1.0)
    v = DSKOR1(RAB, p.FI2, RCB, p.FI3, W1 * ROA, phi + PI / 2, 0.0, 0.0)
    return xa, ya, p, v


def _power(p, v):
    """The power of the loads: Q2 at S2 = B + bs2 e(FI2), M2 on link 2; Q3 at
    S3 = B + bs3 e(FI3), M3 on link 3 (link 3 turns about C)."""
    L = LOADS
    e = lambda a: np.array([np.cos(a), np.sin(a)])                  # noqa: E731
    vb = v.VB * e(v.ALB)
    r2 = L["bs2"] * e(p.FI2)                                       # S2 - B
    b_c = RCB * e(p.FI3)                                            # B - C
    r3 = b_c + L["bs3"] * e(p.FI3)                                  # S3 - C
    vs2 = vb + v.W2 * np.array([-r2[1], r2[0]])
    vs3 = v.W3 * np.array([-r3[1], r3[0]])
    q2, q3 = L["q2"] * e(L["g2"]), L["q3"] * e(L["g3"])
    return (q2[:, None] * vs2).sum(0) + L["m2"] * v.W2 + (q3[:, None] * vs3).sum(0) \
        + L["m3"] * v.W3


@pytest.mark.parametrize("family", ["DNMAF1", "DNMA1"])
def test_balancing_moment_is_virtual_work(family):
    """My W1 + P = 0: the drive's power balances the loads' over the whole turn."""
    phi = np.linspace(0.0, 2 * PI, 361)[:-1] + 1e-3
    xa, ya, p, v = _crank_rocker(phi)
    L = LOADS
    if family == "DNMAF1":
        s2 = (p.XB + L["bs2"] * np.cos(p.FI2), p.YB + L["bs2"] * np.sin(p.FI2))
        s3 = (p.XB + L["bs3"] * np.cos(p.FI3), p.YB + L["bs3"] * np.sin(p.FI3))
        g = DNMAF1(xa, ya, p.XB, p.YB, XC, YC, *s2, L["q2"], L["g2"], *s3, L["q3"], L["g3"],
                   L["m2"], L["m3"])
    else:
        g = DNMA1(RAB, p.FI2, RCB, p.FI3, L["bs2"], L["bs3"], L["m2"], L["q2"], L["g2"],
                  L["m3"], L["q3"], L["g3"])
    my = balancing_moment(g, 0.0, 0.0, xa, ya)
    power = _power(p, v)
    scale = np.abs(power).max() / W1
    assert np.all(np.abs(my * W1 + power) <= 1e-10 * scale * W1)
    # the crank's own loads enter with their moment M1
    assert np.allclose(balancing_moment(g, 0.0, 0.0, xa, ya, M1=2.5), my - 2.5,
                       rtol=0, atol=1e-12 * scale)


def test_balancing_moment_scalar_and_bad_groups():
    xa, ya, p, v = _crank_rocker(np.array([0.7]))
    g = DNMA1(RAB, float(p.FI2[0]), RCB, float(p.FI3[0]), -0.1, -0.1, 1.0, 10.0, 0.5, 2.0,
              20.0, 1.0)
    assert isinstance(balancing_moment(g, 0.0, 0.0, float(xa[0]), float(ya[0])), float)
    k4 = sarkp.DNMA4(0.3, 0.2, 1.5, 0.1, 0.05, 0.05, 1.0, 10.0, 0.5, 2.0, 20.0, 1.0)
    with pytest.raises(ValueError, match="kind-4"):
        balancing_moment(k4, 0.0, 0.0, 0.1, 0.0)
    with pytest.raises(ValueError, match="DNMAF1"):
        balancing_moment(sarkp.DVKT(0.0, 0.0, 1.0, 1.0), 0.0, 0.0, 0.1, 0.0)


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_each_family_states_its_sense(k):
    """One sentence in each docstring; tests/test_forces.py::test_kind{k}_families_agree
    holds it (DNMA*'s reactions are minus DNMAF*'s forces, vector for vector)."""
    f, v = getattr(sarkp, f"DNMAF{k}").__doc__, getattr(sarkp, f"DNMA{k}").__doc__
    assert "Sense: the projection family (DNMAF1-DNMAF5) returns the forces the group " \
           "exerts ON" in " ".join(f.split())
    assert "Sense: the vector family (DNMA1-DNMA5) returns the reactions ON the group's " \
           "links" in " ".join(v.split())


def test_balancing_moment_coordinates_are_checked():
    g = DNMA1(RAB, 0.5, RCB, 2.0, -0.1, -0.1, 1.0, 10.0, 0.5, 2.0, 20.0, 1.0)
    with pytest.raises(TypeError, match="XA"):
        balancing_moment(g, 0.0, 0.0, "0.1", 0.0)
