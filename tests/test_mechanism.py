"""sarkp.Mechanism (issue 19): a whole mechanism in one compiled call.

References: closed forms of each mechanism's positions, central differences of the
positions (velocity analogues) and of the velocity analogues (accelerations), the
equilibrium of every link written out here, the virtual-work balancing moment, J_red
summed directly, pylinkage's positions, and scipy's solve_ivp for the start-up.
"""

import math
import pickle
import re
import warnings

import numpy as np
import pytest

import sarkp
from sarkp import AssemblyError, Mechanism, SingularError

H = 1e-5          # step of the central differences: error ~ h**2 x''' ~ 1e-10 relative
PHI = np.linspace(0.0, 2 * math.pi, 37)
G = 9.81


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def rel(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300)


# -- mechanisms ---------------------------------------------------------------------------

def fourbar(branch=1, masses=True):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3, branch=branch)
    if masses:
        m.point("S2", "A", "B", 0.15, 0.2)         # centre of mass of A-B, off the line
        m.point("S3", "C", "B", 0.1)
        m.mass("O", "A", mass=0.5, inertia=0.001, centre=0.05)
        m.mass("S2", "A", mass=1.5, inertia=0.012)
        m.mass("S3", "C", mass=1.0, inertia=0.01)
        m.torque("C", "B", -20.0)
        m.force("B", 30.0, -10.0)
    return m


def slider_crank(offset=0.02, branch=1):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, offset)
    m.crank("A", "O", 0.1)
    m.rrp("B", "A", "K", 0.0, 0.4, branch=branch)
    return m


COURSE = dict(roa=0.16646893, rab=2.33535352, rcb=0.5787882, rcd=0.5787882, rde=0.7012536,
              delta=0.698, roc=2.09023145, h5=0.64)


def sixbar(loads=True):
    """Program X's six-bar (chapter 10): the four-bar O-A-B-C, the lever point D on C-B
    at angle pi, the RRP group D-E on the horizontal guide."""
    g = COURSE
    xc, yc = -g["roc"] * math.sin(g["delta"]), g["roc"] * math.cos(g["delta"])
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, yc)
    m.fixed("G", 0.0, g["h5"] + yc)
    m.crank("A", "O", g["roa"])
    m.rrr("B", "A", "C", g["rab"], g["rcb"], branch=1)
    m.point("D", "C", "B", g["rcd"], math.pi)
    m.rrp("E", "D", "G", 0.0, g["rde"], branch=1)
    if loads:
        m.point("S2", "A", "B", g["rab"] / 2)
        m.point("S4", "D", "E", g["rde"] / 2)
        m.mass("S2", "A", mass=20.0, inertia=9.0)
        m.mass("C", "B", mass=8.0, inertia=0.9)
        m.mass("S4", "D", mass=6.0, inertia=0.25)
        m.mass("E", mass=30.0)
        m.force("E", -400.0, 0.0)
        m.spring("E", "G", 800.0, 0.5)
    return m


# -- kinematics against closed forms and derivatives ----------------------------------------

def check_derivatives(m, names, phi=PHI, links=()):
    """velocities = central differences of positions; accelerations = of velocities."""
    r1 = m.solve(phi, omega=1.0, epsilon=0.0, need="accelerations")
    rp = m.solve(phi + H, omega=1.0, need="velocities")
    rm = m.solve(phi - H, omega=1.0, need="velocities")
    for n in names:
        scale = np.max(np.abs(r1.velocity(n))) + 1e-300
        dv = (rp.position(n) - rm.position(n)) / (2 * H)
        assert np.max(np.abs(dv - r1.velocity(n))) / scale < 1e-8, n
        da = (rp.velocity(n) - rm.velocity(n)) / (2 * H)
        scale = np.max(np.abs(r1.acceleration(n))) + 1e-300
        assert np.max(np.abs(da - r1.acceleration(n))) / scale < 1e-8, n
    for lk in links:
        dth = (rp.angle(*lk) - rm.angle(*lk)) / (2 * H)
        assert np.max(np.abs(dth - r1.omega(*lk))) < 1e-8 * (1 + np.max(np.abs(dth)))
        de = (rp.omega(*lk) - rm.omega(*lk)) / (2 * H)
        assert np.max(np.abs(de - r1.epsilon(*lk))) < 1e-8 * (1 + np.max(np.abs(de)))
    # omega, epsilon scale as omega, omega**2 + epsilon
    w, e = 7.0, -3.0
    r = m.solve(phi, omega=w, epsilon=e, need="accelerations")
    for n in names:
        np.testing.assert_allclose(r.velocity(n), w * r1.velocity(n), rtol=1e-14, atol=1e-14)
        a = w * w * r1.acceleration(n) + e * r1.velocity(n)
        assert np.max(np.abs(r.acceleration(n) - a)) <= 1e-13 * np.max(np.abs(a))


@pytest.mark.parametrize("branch", [1, -1])
def test_fourbar_closed_form_and_derivatives(branch):
    m = fourbar(branch, masses=False)
    r = m.solve(PHI, need="positions")
    A = np.stack([0.1 * np.cos(PHI), 0.1 * np.sin(PHI)], -1)
    np.testing.assert_allclose(r.position("A"), A, rtol=0, atol=1e-16)
    C = np.array([0.3, 0.05])
    d = C - A
    dn = np.hypot(d[:, 0], d[:, 1])[:, None]
    a = (0.35**2 - 0.3**2 + dn**2) / (2 * dn)
    h = np.sqrt(0.35**2 - a**2)
    B = A + a * d / dn + branch * h * np.stack([-d[:, 1], d[:, 0]], -1) / dn
    np.testing.assert_allclose(r.position("B"), B, rtol=0, atol=1e-15)
    # branch +1: B on the left of A->C
    assert np.all(branch * cross(C - A, r.position("B") - A) > 0)
    check_derivatives(m, ["A", "B"], links=[("A", "B"), ("C", "B"), ("O", "A")])


def test_slider_crank_closed_form():
    m = slider_crank(offset=0.02)
    r = m.solve(PHI, omega=5.0, epsilon=0.0, need="accelerations")
    xa, ya = 0.1 * np.cos(PHI), 0.1 * np.sin(PHI)
    xb = xa + np.sqrt(0.4**2 - (ya - 0.02) ** 2)
    np.testing.assert_allclose(r.position("B")[:, 0], xb, rtol=0, atol=2e-16)
    np.testing.assert_allclose(r.position("B")[:, 1], 0.02, rtol=0, atol=1e-17)
    # the slider's velocity in closed form: d xb / dt
    s = ya - 0.02
    vb = 5.0 * (-ya - s * xa / np.sqrt(0.4**2 - s**2))
    np.testing.assert_allclose(r.velocity("B")[:, 0], vb, rtol=0, atol=1e-14)
    np.testing.assert_allclose(r.velocity("B")[:, 1], 0.0, atol=1e-15)
    check_derivatives(m, ["B"], links=[("A", "B")])
    # branch -1: behind the foot of the perpendicular from A
    r = slider_crank(0.02, branch=-1).solve(PHI, need="positions")
    np.testing.assert_allclose(r.position("B")[:, 0], xa - np.sqrt(0.4**2 - (ya - 0.02)**2),
                               atol=2e-16)
    # the slider block's angle is the guide's
    assert np.all(r.angle("B") == 0.0)


def test_sixbar_derivatives_and_geometry():
    m = sixbar(loads=False)
    check_derivatives(m, ["B", "D", "E"], links=[("A", "B"), ("C", "B"), ("D", "E")])
    r = m.solve(PHI, need="positions")
    B, C, D, E = (r.position(n) for n in "BCDE")
    # D on the line C-B beyond C, at RCD; E on the guide, RDE from D, ahead of D's foot
    np.testing.assert_allclose(np.hypot(*(D - C).T), COURSE["rcd"], rtol=1e-15)
    np.testing.assert_allclose(cross(B - C, D - C), 0.0, atol=1e-15)
    assert np.all(np.sum((B - C) * (D - C), -1) < 0)
    np.testing.assert_allclose(np.hypot(*(E - D).T), COURSE["rde"], rtol=1e-15)
    assert np.all(E[:, 0] > D[:, 0])


def test_kind3_slotted_lever():
    """Crank-shaper: the slider pivoted at the crank pin A slides along link 3 about C."""
    for h, branch in ((0.0, 1), (0.03, 1), (0.03, -1)):
        m = Mechanism()
        m.fixed("O", 0.0, 0.0)
        m.fixed("C", 0.0, -0.25)
        m.crank("A", "O", 0.1)
        m.rpr("B", "A", "C", h, math.pi / 2, branch=branch)
        r = m.solve(PHI, need="positions")
        A, B, C = r.position("A"), r.position("B"), np.array([0.0, -0.25])
        np.testing.assert_allclose(np.hypot(*(B - A).T), h, atol=1e-16)
        np.testing.assert_allclose(np.sum((B - A) * (B - C), -1), 0.0, atol=1e-16)
        if h:
            assert np.all(branch * cross(C - A, B - A) > 0)   # B left of A->C for +1
        else:
            th = np.unwrap(np.arctan2(A[:, 1] + 0.25, A[:, 0]))
            np.testing.assert_allclose(r.angle("C", "B"), th, rtol=0, atol=1e-15)
        check_derivatives(m, ["B"], links=[("C", "B"), ("A", "B")])


def test_kind4_prp():
    """B on a guide carried by the crank (perpendicular to it, through A) and on the
    fixed horizontal guide through G."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, 0.05)
    m.crank("A", "O", 0.1)
    m.prp("B", "A", math.pi / 2, "G", 0.0, guide_m=("O", "A"))
    phi = np.linspace(-1.0, 1.0, 21)             # the guide is not horizontal there
    r = m.solve(phi, need="positions")
    A = r.position("A")
    u = np.stack([-np.sin(phi), np.cos(phi)], -1)
    t = (0.05 - A[:, 1]) / u[:, 1]
    np.testing.assert_allclose(r.position("B"), A + t[:, None] * u, rtol=0, atol=1e-15)
    np.testing.assert_allclose(r.angle("B", "A"), phi + math.pi / 2, atol=1e-15)
    check_derivatives(m, ["B"], phi=phi)


def test_kind5_scotch_yoke():
    """The yoke (link 2) slides on the horizontal guide through G; the block pivoted at
    the crank pin slides in its vertical slot: x_K = r cos phi."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.2, -0.3)
    m.crank("A", "O", 0.1)
    m.rpp("K", "G", 0.0, "A", math.pi / 2)
    w, e = 4.0, 1.5
    r = m.solve(PHI, omega=w, epsilon=e, need="accelerations")
    np.testing.assert_allclose(r.position("K"), np.stack([0.1 * np.cos(PHI),
                                                          np.full_like(PHI, -0.3)], -1),
                               atol=1e-16)
    np.testing.assert_allclose(r.velocity("K")[:, 0], -0.1 * w * np.sin(PHI), atol=1e-15)
    np.testing.assert_allclose(r.acceleration("K")[:, 0],
                               -0.1 * (w * w * np.cos(PHI) + e * np.sin(PHI)), atol=1e-15)
    np.testing.assert_allclose(r.velocity("K")[:, 1], 0.0, atol=1e-15)
    check_derivatives(m, ["K"])


def test_continuous_angles():
    m = fourbar(masses=False)
    phi = np.linspace(0.0, 6 * math.pi, 301)     # three turns
    r = m.solve(phi, need="positions")
    for lk in (("O", "A"), ("A", "B"), ("C", "B")):
        th = r.angle(*lk)
        assert np.max(np.abs(np.diff(th))) < 0.2
        P, Q = r.position(lk[0]), r.position(lk[1])
        d = Q - P
        np.testing.assert_allclose(np.cos(th), d[:, 0] / np.hypot(*d.T), atol=1e-15)
        np.testing.assert_allclose(np.sin(th), d[:, 1] / np.hypot(*d.T), atol=1e-15)
    assert r.angle("O", "A")[-1] == pytest.approx(6 * math.pi)
    # the coupler of a crank-rocker returns after each turn
    assert r.angle("A", "B")[-1] == pytest.approx(r.angle("A", "B")[0], abs=1e-12)


# -- forces -------------------------------------------------------------------------------

def virtual_work_moment(m, r, w1, centres, loads):
    """-(sum F.v + M omega)/omega1 over gravity, inertia and the given loads."""
    total = 0.0
    for point, link, mass, inertia in centres:
        v, a = r.velocity(point), r.acceleration(point)
        F = -mass * a - mass * np.array([0.0, G])
        total = total + np.sum(F * v, -1) - inertia * r.epsilon(*link) * r.omega(*link)
    for kind, where, value in loads:
        if kind == "force":
            total = total + np.sum(np.asarray(value) * r.velocity(where), -1)
        else:
            total = total + value * r.omega(*where)
    return -total / w1


def test_fourbar_forces_equilibrium_and_virtual_work():
    m = fourbar()
    w1, e1 = 10.0, 2.0
    r = m.solve(PHI, omega=w1, epsilon=e1, need="forces", gravity=G)
    # the crank's centre: 0.05 along O->A
    S1 = r.position("A") * 0.5
    vS1, aS1 = r.velocity("A") * 0.5, r.acceleration("A") * 0.5
    mb = r.balancing_moment
    # each link: sum of forces and of moments (about the origin) = 0
    R_O = r.reaction("O")                  # frame on crank
    R_A = r.reaction("A")                  # crank on A-B
    R_B = r.reaction("B")                  # A-B on C-B
    R_C = r.reaction("C")                  # frame on C-B
    A, B, C = r.position("A"), r.position("B"), r.position("C")
    S2, S3 = r.position("S2"), r.position("S3")

    def inertia(mass, a):
        return -mass * a - mass * np.array([0.0, G])
    F1 = inertia(0.5, aS1)
    F2 = inertia(1.5, r.acceleration("S2"))
    F3 = inertia(1.0, r.acceleration("S3"))
    P = np.array([30.0, -10.0])
    eqs = {
        "crank": (R_O + F1 - R_A,
                  cross(S1, F1) - cross(A, R_A) + mb - 0.001 * r.epsilon("O", "A")),
        "A-B": (R_A + F2 - R_B + P,
                cross(A, R_A) + cross(S2, F2) - cross(B, R_B) + cross(B, P)
                - 0.012 * r.epsilon("A", "B")),
        "C-B": (R_B + R_C + F3,
                cross(B, R_B) + cross(C, R_C) + cross(S3, F3) - 20.0
                - 0.01 * r.epsilon("C", "B")),
    }
    scale = max(np.max(np.abs(R_A)), np.max(np.abs(R_B)), np.max(np.abs(mb)))
    for name, (f, mom) in eqs.items():
        assert np.max(np.abs(f)) < 1e-12 * scale, name
        assert np.max(np.abs(mom)) < 1e-12 * scale, name
    # the balancing moment is the virtual-work value
    centres = [("S2", ("A", "B"), 1.5, 0.012), ("S3", ("C", "B"), 1.0, 0.01)]
    vw = virtual_work_moment(m, r, w1, centres, [("force", "B", P), ("torque", ("C", "B"), -20.0)])
    vw = vw - (np.sum(F1 * vS1, -1) - 0.001 * e1 * w1) / w1
    assert np.max(np.abs(vw - mb)) < 1e-12 * np.max(np.abs(mb))
    # the same reactions named the other way round
    np.testing.assert_array_equal(r.reaction("B", on=("A", "B"), by=("C", "B")), -R_B)


def test_centre_keyword_is_a_rigid_point():
    a, b = Mechanism(), Mechanism()
    for m in (a, b):
        m.fixed("O", 0.0, 0.0)
        m.fixed("C", 0.3, 0.05)
        m.crank("A", "O", 0.1)
        m.rrr("B", "A", "C", 0.35, 0.3)
    a.mass("A", "B", mass=1.5, inertia=0.012, centre=(0.15, 0.2))
    b.point("S", "A", "B", 0.15, 0.2)
    b.mass("S", "A", mass=1.5, inertia=0.012)
    ra = a.solve(PHI, omega=3.0, need="forces", gravity=G)
    rb = b.solve(PHI, omega=3.0, need="forces", gravity=G)
    np.testing.assert_allclose(ra.balancing_moment, rb.balancing_moment, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(ra.reduced_inertia, rb.reduced_inertia, rtol=1e-14)


def test_sixbar_forces_virtual_work_and_slider_equilibrium():
    m = sixbar()
    w1 = 12.0
    r = m.solve(PHI, omega=w1, epsilon=0.0, need="forces", gravity=G)
    E, Gp = r.position("E"), r.position("G")
    spring = 800.0 * (np.hypot(*(Gp - E).T) - 0.5)[:, None] * (Gp - E) / np.hypot(*(Gp - E).T)[:, None]
    centres = [("S2", ("A", "B"), 20.0, 9.0), ("C", ("C", "B"), 8.0, 0.9),
               ("S4", ("D", "E"), 6.0, 0.25), ("E", ("E",), 30.0, 0.0)]
    vw = virtual_work_moment(m, r, w1, centres,
                             [("force", "E", np.array([-400.0, 0.0])), ("force", "E", spring)])
    mb = r.balancing_moment
    assert np.max(np.abs(vw - mb)) < 1e-12 * np.max(np.abs(mb))
    # the slider block: rod force + guide normal + loads = 0; the guide's force is normal
    R_rod = r.reaction("E", on="E", by=("D", "E"))
    R_guide = r.reaction("E", on="E", by="frame")
    F = -30.0 * r.acceleration("E") - 30.0 * np.array([0.0, G]) + [-400.0, 0.0] + spring
    scale = np.max(np.abs(R_rod))
    assert np.max(np.abs(R_rod + R_guide + F)) < 1e-12 * scale
    assert np.max(np.abs(R_guide[:, 0])) < 1e-12 * scale


@pytest.mark.parametrize("kind", [3, 4, 5])
def test_slider_kinds_virtual_work(kind):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.crank("A", "O", 0.1)
    if kind == 3:
        m.fixed("C", 0.0, -0.25)
        m.rpr("B", "A", "C", 0.02, math.pi / 2)
        m.point("T", "C", "B", 0.4)
        m.point("S3", "C", "B", 0.15)
        centres = [("S3", ("C", "B"), 2.0, 0.05), ("A", ("A", "B"), 0.3, 1e-4)]
        link, pt = ("C", "B"), "T"
        phi = PHI
    elif kind == 4:
        m.fixed("G", 0.0, 0.05)
        m.prp("B", "A", math.pi / 2, "G", 0.0, guide_m=("O", "A"))
        centres = [("B", ("B", "G"), 1.2, 2e-3), ("B", ("B", "A"), 0.4, 1e-3)]
        link, pt = ("B", "G"), "B"
        phi = np.linspace(-1.0, 1.0, 21)
    else:
        m.fixed("G", 0.2, -0.3)
        m.rpp("K", "G", 0.0, "A", math.pi / 2)
        centres = [("K", ("K", "G"), 2.5, 0.1), ("A", ("A", "K"), 0.2, 1e-4)]
        link, pt = ("K", "G"), "K"
        phi = PHI
    for point, lk, mass, inertia in centres:
        m.mass(point, lk[1] if lk[0] == point else lk[0], mass=mass, inertia=inertia)
    m.force(pt, -50.0, 20.0)
    m.torque(*link, 3.0)
    w1, e1 = 6.0, -1.0
    r = m.solve(phi, omega=w1, epsilon=e1, need="forces", gravity=G)
    total = 0.0
    for point, lk, mass, inertia in centres:
        v, a = r.velocity(point), r.acceleration(point)
        total = total + np.sum((-mass * a - mass * np.array([0.0, G])) * v, -1) \
            - inertia * r.epsilon(*lk) * r.omega(*lk)
    total = total + np.sum(np.array([-50.0, 20.0]) * r.velocity(pt), -1) \
        + 3.0 * r.omega(*link)
    vw = -total / w1
    mb = r.balancing_moment
    assert np.max(np.abs(vw - mb)) < 1e-12 * np.max(np.abs(mb))


def test_reduced_inertia_and_moment_direct():
    m = sixbar()
    w1 = 12.0
    r = m.solve(PHI, omega=w1, need="forces", gravity=G)
    J = (20.0 * np.sum(r.velocity("S2") ** 2, -1) + 9.0 * r.omega("A", "B") ** 2
         + 8.0 * np.sum(r.velocity("C") ** 2, -1) + 0.9 * r.omega("C", "B") ** 2
         + 6.0 * np.sum(r.velocity("S4") ** 2, -1) + 0.25 * r.omega("D", "E") ** 2
         + 30.0 * np.sum(r.velocity("E") ** 2, -1)) / w1**2
    np.testing.assert_allclose(r.reduced_inertia, J, rtol=1e-13)
    # M_red: the external loads' power per unit crank speed (no inertia)
    E, Gp = r.position("E"), r.position("G")
    d = np.hypot(*(Gp - E).T)
    spring = (800.0 * (d - 0.5) / d)[:, None] * (Gp - E)
    P = (-G * (20.0 * r.velocity("S2")[:, 1] + 8.0 * r.velocity("C")[:, 1]
               + 6.0 * r.velocity("S4")[:, 1] + 30.0 * r.velocity("E")[:, 1])
         + np.sum(([-400.0, 0.0] + spring) * r.velocity("E"), -1)) / w1
    np.testing.assert_allclose(r.reduced_moment, P, rtol=1e-12,
                               atol=1e-13 * np.max(np.abs(P)))
    # J_red needs velocities only and does not depend on omega
    r2 = m.solve(PHI, omega=0.5, need="velocities")
    np.testing.assert_allclose(r2.reduced_inertia, r.reduced_inertia, rtol=1e-14)


# -- levels, results, pickling --------------------------------------------------------------

def test_need_levels_compute_only_what_is_asked():
    m = sixbar()
    for phi in (PHI, 0.3, [0.3]):           # one position too (no uninitialised memory)
        r = m.solve(phi, need="positions")
        for get, need in ((lambda: r.velocities, "velocities"),
                          (lambda: r.velocity("E"), "velocities"),
                          (lambda: r.omega("D", "E"), "velocities"),
                          (lambda: r.reduced_inertia, "velocities"),
                          (lambda: r.accelerations, "accelerations"),
                          (lambda: r.epsilon("D", "E"), "accelerations"),
                          (lambda: r.reactions, "forces"),
                          (lambda: r.reaction("B"), "forces"),
                          (lambda: r.balancing_moment, "forces"),
                          (lambda: r.reduced_moment, "forces")):
            with pytest.raises(ValueError, match=f"need='{need}'"):
                get()
    r = m.solve(PHI, need="velocities")
    assert r.velocities.shape == (37, len(r.columns[0]), 2)
    assert r.reduced_inertia.shape == (37,)
    with pytest.raises(ValueError, match="need='forces'"):
        r.balancing_moment
    full = m.solve(PHI, omega=2.0, need="forces", gravity=G)
    np.testing.assert_array_equal(r.position("E"), full.position("E"))


def test_result_pickles_prints_short_and_converts():
    m = sixbar()
    r = m.solve(PHI, omega=12.0, need="forces", gravity=G)
    text = repr(r)
    assert "37 positions" in text and len(text) < 200
    r2 = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(r2.position("E"), r.position("E"))
    np.testing.assert_array_equal(r2.balancing_moment, r.balancing_moment)
    m2 = pickle.loads(pickle.dumps(m))
    np.testing.assert_array_equal(m2.solve(PHI, need="positions").position("E"),
                                  r.position("E"))
    pd = pytest.importorskip("pandas")
    f = r.to_frame()
    assert isinstance(f, pd.DataFrame) and len(f) == 37
    np.testing.assert_array_equal(f["x_E"], r.position("E")[:, 0])
    np.testing.assert_array_equal(f["balancing_moment"], r.balancing_moment)


def test_scalar_phi_and_shapes():
    m = fourbar(masses=False)
    r = m.solve(0.3, omega=2.0)
    assert r.position("B").shape == (2,)
    grid = np.linspace(0, 1, 6).reshape(2, 3)
    r2 = m.solve(grid, omega=2.0)
    assert r2.position("B").shape == (2, 3, 2)
    assert r2.omega("A", "B").shape == (2, 3)
    np.testing.assert_array_equal(m.solve(np.array([0.3]), omega=2.0).position("B")[0],
                                  r.position("B"))


def test_plot_and_animate(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    r = sixbar().solve(np.linspace(0, 2 * math.pi, 8), need="positions")
    fig = r.plot(paths=("E",))
    assert fig is not None
    # on a given Axes: drawn there, and that Axes' figure comes back
    import matplotlib.pyplot as plt
    own, ax = plt.subplots()
    assert r.plot(ax=ax) is own and ax.lines
    plt.close("all")
    pytest.importorskip("PIL")
    out = r.animate(tmp_path / "six.gif", fps=4)
    from PIL import Image
    with Image.open(out) as im:
        assert im.n_frames == 8


# -- pylinkage ------------------------------------------------------------------------------

def test_positions_agree_with_pylinkage():
    pytest.importorskip("pylinkage")
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage
    n = 72
    m = fourbar(masses=False)
    phi = 2 * math.pi * np.arange(n) / n
    ours = m.solve(phi, need="positions").position("B")
    O = Ground(0.0, 0.0, name="O")
    C = Ground(0.3, 0.05, name="C")
    crank = Crank(anchor=O, radius=0.1, angular_velocity=2 * math.pi / n,
                  initial_angle=-2 * math.pi / n, name="A")
    B = RRRDyad(crank.output, C, distance1=0.35, distance2=0.3, x=ours[0, 0], y=ours[0, 1],
                name="B")
    linkage = Linkage([O, C, crank, B], name="fourbar")
    pos = np.array([[c for c in step] for step in linkage.step(iterations=n)])
    names = [c.name for c in linkage.components]
    theirs = pos[:, names.index("B")]
    np.testing.assert_allclose(theirs, ours, rtol=0, atol=1e-12)


def test_sixbar_positions_agree_with_pylinkage():
    """Program X's six-bar: a lever point (pylinkage's FixedDyad) and an RRP group."""
    pytest.importorskip("pylinkage")
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import FixedDyad, RRPDyad, RRRDyad
    from pylinkage.simulation import Linkage
    n = 72
    g = COURSE
    xc, yc = -g["roc"] * math.sin(g["delta"]), g["roc"] * math.cos(g["delta"])
    phi = 2 * math.pi * np.arange(n) / n
    r = sixbar(loads=False).solve(phi, need="positions")
    O, C = Ground(0.0, 0.0, name="O"), Ground(xc, yc, name="C")
    G1, G2 = Ground(0.0, g["h5"] + yc, name="G1"), Ground(1.0, g["h5"] + yc, name="G2")
    crank = Crank(anchor=O, radius=g["roa"], angular_velocity=2 * math.pi / n,
                  initial_angle=-2 * math.pi / n, name="A")
    B = RRRDyad(crank.output, C, distance1=g["rab"], distance2=g["rcb"],
                x=r.position("B")[0, 0], y=r.position("B")[0, 1], name="B")
    D = FixedDyad(C, B, distance=g["rcd"], angle=math.pi, name="D")
    E = RRPDyad(D, G1, G2, distance=g["rde"], name="E")
    E.x, E.y = r.position("E")[0]
    linkage = Linkage([O, C, crank, B, G1, G2, D, E], name="sixbar")
    pos = np.array([[c for c in step] for step in linkage.step(iterations=n)])
    names = [c.name for c in linkage.components]
    for p in "BDE":
        np.testing.assert_allclose(pos[:, names.index(p)], r.position(p), rtol=0,
                                   atol=1e-12, err_msg=p)


# -- law of motion ----------------------------------------------------------------------------

def test_startup_from_rest_with_spring_against_solve_ivp():
    """A multi-loop mechanism (the six-bar: a group on the ternary link C-B-D) with a
    spring, driven by a constant torque from rest, against the equation of motion
    J(phi) phi'' + J'(phi) phi'**2/2 = M(phi) integrated by solve_ivp."""
    from scipy.integrate import solve_ivp
    m = sixbar()
    m.torque("O", "A", 400.0)

    def rhs(t, y):
        p = y[0]
        r = m.solve(np.array([p - 1e-6, p, p + 1e-6]), omega=1.0, need="forces", gravity=G)
        J = r.reduced_inertia
        dJ = (J[2] - J[0]) / 2e-6
        return [y[1], (r.reduced_moment[1] - 0.5 * dJ * y[1] ** 2) / J[1]]

    def passed(t, y):
        return y[0] - 2 * math.pi
    passed.terminal = True
    sol = solve_ivp(rhs, (0.0, 10.0), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-12,
                    dense_output=True, events=passed)
    T = sol.t_events[0][0]
    errors = []
    for n in (91, 181, 361):
        mo = m.motion(np.linspace(0.0, 2 * math.pi, n), omega0=0.0, gravity=G)
        # at the time the quadrature gives for each grid angle, the integrated motion is
        # at that angle, with that speed
        ys = sol.sol(mo.t[1:])
        errors.append(max(np.max(np.abs(ys[1] - mo.omega[1:])) / np.max(mo.omega),
                          np.max(np.abs(ys[0] - mo.phi[1:])), abs(mo.t[-1] - T) / T))
    # the quadrature is fourth order: halving the step divides the error by about 16
    assert errors[0] / errors[1] > 12 and errors[1] / errors[2] > 12, errors


def test_flywheel_realizes_delta():
    m = sixbar()
    mean = 12.0
    phi = np.linspace(0.0, 2 * math.pi, 361)
    r = m.solve(phi, omega=mean, need="forces", gravity=G)
    fw = m.flywheel(0.05, mean, phi, gravity=G)
    assert fw.delta == pytest.approx(0.05, rel=1e-9)
    # the same as sarkp.dynamics.flywheel on the result's J_red and M_red
    ref = sarkp.dynamics.flywheel(phi, r.reduced_inertia, r.reduced_moment, delta=0.05,
                                  omega_mean=mean)
    assert fw.J_flywheel == pytest.approx(ref.J_flywheel, rel=1e-12)


# -- errors and bad input -----------------------------------------------------------------------

def test_assembly_error_names_group_and_angle():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.5, 0.0)
    m.crank("A", "O", 0.2)
    m.rrr("B", "A", "C", 0.2, 0.2)                # reaches only near phi = 0
    phi = np.linspace(0.0, math.pi, 7)
    reach = np.hypot(0.5 - 0.2 * np.cos(phi), 0.2 * np.sin(phi)) <= 0.4
    first = int(np.argmin(reach))
    assert reach[0] and not reach[first]
    with pytest.raises(AssemblyError, match=rf"rrr 'B'.*phi = {re.escape(repr(float(phi[first])))}") as info:
        m.solve(phi)
    assert info.value.index == (first,)
    r = m.solve(phi, on_error="nan")
    np.testing.assert_array_equal(r.status, np.where(reach, 0, sarkp.Status.ASSEMBLY))
    assert np.all(np.isnan(r.position("B")[~reach]))
    assert np.all(np.isfinite(r.position("B")[reach]))


def test_dead_centre_singular_or_warning():
    # a four-bar whose links A-B, C-B stretch out in line at phi = pi (A-C = 0.7 = 0.3 + 0.4)
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.6, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.3, 0.4)
    with pytest.raises(SingularError, match=r"rrr 'B'.*dead centre"):
        m.solve(math.pi, need="velocities")
    r = m.solve([math.pi, 1.0], need="velocities", on_error="nan")
    assert list(r.status) == [sarkp.Status.SINGULAR, sarkp.Status.OK]
    with pytest.warns(sarkp.SignificanceWarning, match="digits left") as caught:
        r = m.solve(math.pi - 1e-4, need="velocities")
    assert 1 <= caught[0].message.digits <= 7
    assert r.status == sarkp.Status.SIGNIFICANCE


@pytest.mark.parametrize("build, match", [
    (lambda m: m.rrr("B", "A", "X", 1, 1), "unknown joint 'X'"),
    (lambda m: m.rrr("A", "A", "C", 1, 1), "joint 'A' is defined twice"),
    (lambda m: m.rrr("B", "A", "C", -1, 1), "l2 must be a length > 0"),
    (lambda m: m.rrr("B", "A", "C", 1, 0.0), "l3 must be a length > 0"),
    (lambda m: m.rrr("B", "A", "C", 1, 1, branch=0), "branch"),
    (lambda m: m.mass("O", "C", mass=1.0), "not on one link"),
    (lambda m: m.mass("O", "A", mass=-1.0), "mass must be >= 0"),
    (lambda m: m.mass("O", "A", mass=1.0, inertia=-2.0), "inertia must be >= 0"),
    (lambda m: m.rrp("E", "A", "A", 0.0, 0.3), "not a frame point"),
    (lambda m: m.fixed("Z", float("nan"), 0.0), "x must be finite"),
    (lambda m: m.torque("A", "Y", 1.0), "unknown joint 'Y'"),
    (lambda m: m.force("O", 1.0, 0.0), "frame point"),
    (lambda m: m.spring("A", "A", 1.0, 0.1), "two different points"),
])
def test_bad_description(build, match):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    with pytest.raises(ValueError, match=match):
        build(m)


def test_bad_solve_input():
    m = fourbar()
    with pytest.raises(ValueError, match="need"):
        m.solve(PHI, need="everything")
    with pytest.raises(ValueError, match="omega has 3 values for 37"):
        m.solve(PHI, omega=[1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="phi must be finite"):
        m.solve([0.0, float("nan")])
    with pytest.raises(TypeError, match="phi"):
        m.solve("a")
    m.force("A", np.ones(5), 0.0)
    with pytest.raises(ValueError, match="force at 'A': fx has 5 values for 37 positions"):
        m.solve(PHI, need="forces")
    with pytest.raises(ValueError, match="no crank"):
        Mechanism().solve(PHI)
    with pytest.raises(ValueError, match="define the crank first"):
        n = Mechanism()
        n.fixed("O", 0, 0)
        n.rrr("B", "O", "O", 1, 1)


def test_bad_description_other_kinds():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, 0.05)
    m.crank("A", "O", 0.1)
    with pytest.raises(ValueError, match="joint 'A' is not a frame point"):
        m.prp("B", "A", 0.0, "G", 0.5)
    with pytest.raises(ValueError, match="parallel to the guide"):
        m.rpp("K", "G", 0.0, "A", 0.0)
    with pytest.raises(ValueError, match="unknown joint 'Z'"):
        m.rpr("B", "A", "Z", 0.1)
    m.prp("B", "A", math.pi / 2, "G", 0.0, guide_m=("O", "A"))
    with pytest.raises(ValueError, match="does not turn with the link"):
        m.point("X", "B", "A", 0.1)
    with pytest.raises(ValueError, match="centre off joint 'B'"):
        m.mass("B", "A", mass=1.0, centre=0.1)
    with pytest.raises(ValueError, match="not on link"):
        m.force("A", 1.0, 0.0, link=("B", "G"))
    with pytest.raises(ValueError, match="several links"):
        m.mass("B", mass=1.0)                       # two sliders meet at B: name one
    r = m.solve(np.linspace(-1.0, 1.0, 5), need="forces")
    with pytest.raises(ValueError, match="several pairs at 'B' match"):
        r.reaction("B")


def test_omega_per_position_is_each_position_alone():
    m = fourbar()
    w = np.linspace(1.0, 5.0, PHI.size)
    e = np.linspace(-2.0, 2.0, PHI.size)
    r = m.solve(PHI, omega=w, epsilon=e, need="forces", gravity=G)
    for i in (0, 7, 20):
        ri = m.solve(PHI[i], omega=w[i], epsilon=e[i], need="forces", gravity=G)
        np.testing.assert_array_equal(r.acceleration("B")[i], ri.acceleration("B"))
        assert r.balancing_moment[i] == ri.balancing_moment


def test_nan_positions_with_forces():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.5, 0.0)
    m.crank("A", "O", 0.2)
    m.rrr("B", "A", "C", 0.2, 0.2)
    m.mass("A", "B", mass=1.0, centre=0.1)
    phi = np.linspace(0.0, math.pi, 7)
    r = m.solve(phi, omega=2.0, need="forces", gravity=G, on_error="nan")
    bad = r.status != 0
    assert bad.any() and not bad.all()
    assert np.all(np.isnan(r.balancing_moment[bad])) and np.all(np.isnan(r.reaction("B")[bad]))
    assert np.all(np.isfinite(r.balancing_moment[~bad]))


def test_guides_on_moving_links_coriolis():
    """Kinds 2 and 5 with their guides on a turning link: the Coriolis and transport terms
    against central differences; the slider stays on the turning guide."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.5, 0.1)
    m.crank("A", "O", 0.15)
    m.rrr("B", "A", "C", 0.45, 0.3)
    # a slider E on a guide carried by the rocker C-B (through C, at 0.3 rad from C->B),
    # pushed by the rod A-E
    m.rrp("E", "A", "C", 0.3, 0.5, guide=("C", "B"))
    # a slotted link on a guide through B along A-B, with a block pivoted at the crank pin
    m.rpp("K", "B", 0.2, "A", 1.2, guide=("A", "B"))
    phi = np.linspace(0.0, 2 * math.pi, 25)
    check_derivatives(m, ["E", "K"], phi=phi, links=[("A", "E"), ("K", "B"), ("A", "K")])
    r = m.solve(phi, need="positions")
    C, E = np.array([0.5, 0.1]), r.position("E")
    u = np.stack([np.cos(r.angle("C", "B") + 0.3), np.sin(r.angle("C", "B") + 0.3)], -1)
    np.testing.assert_allclose(cross(u, E - C), 0.0, atol=1e-15)
    np.testing.assert_allclose(np.hypot(*(E - r.position("A")).T), 0.5, rtol=1e-15)


def test_crank_alone_closed_form():
    """A crank with its own mass: M_b = J_O epsilon + m g x_S, the pivot's force
    m (a_S + g) with J_O = J_S + m s**2; J_red = J_O."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.crank("A", "O", 0.2)
    m.mass("O", "A", mass=2.0, inertia=0.1, centre=0.1)
    w, e = 2.0, 1.5
    r = m.solve(PHI, omega=w, epsilon=e, need="forces", gravity=G)
    J_O = 0.1 + 2.0 * 0.1**2
    np.testing.assert_allclose(r.balancing_moment, J_O * e + 2.0 * G * 0.1 * np.cos(PHI),
                               rtol=1e-13, atol=1e-14)
    aS = 0.1 * np.stack([-w * w * np.cos(PHI) - e * np.sin(PHI),
                         -w * w * np.sin(PHI) + e * np.cos(PHI)], -1)
    np.testing.assert_allclose(r.reaction("O"), 2.0 * (aS + [0.0, G]), rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(r.reduced_inertia, J_O, rtol=1e-15)


def _spring_fourbar(dist, L0, k=100.0):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3)
    m.point("D", "A", "B", dist, 0.4)             # D on A-B, ``dist`` from A
    m.mass("A", "B", mass=1.5, inertia=0.01, centre=0.1)
    if k is not None:
        m.spring("A", "D", k, L0)
    return m


def test_spring_whose_ends_always_coincide_is_an_error():
    """A spring between two points of one link at one place (L0 > 0) pushes with
    k L0 in no direction: ValueError naming it at the forces' solve (issue 25: it was
    dropped silently).  With L0 = 0 (or k = 0) its force is zero: the same results as
    without it, bit for bit; a spring of length 0.1 along the link is not refused."""
    phi = np.linspace(0.0, 2 * math.pi, 7)
    with pytest.raises(ValueError, match=r"spring\('A', 'D'\).*coincide at every position"):
        _spring_fourbar(0.0, 0.05).solve(phi, omega=10.0, need="forces")
    with pytest.raises(ValueError, match=r"spring\('A', 'D'\)"):    # one design of two
        _spring_fourbar(np.array([0.1, 0.0]), 0.05).solve(0.3, need="forces")
    with pytest.raises(ValueError, match=r"spring\('A', 'D'\)"):    # L0 a callable
        _spring_fourbar(0.0, lambda phi: 0.05 + 0 * phi).solve(phi, need="forces")
    bare = _spring_fourbar(0.0, 0.0, k=None).solve(phi, omega=10.0, need="forces")
    for L0, k in ((0.0, 100.0), (0.05, 0.0)):
        r = _spring_fourbar(0.0, L0, k).solve(phi, omega=10.0, need="forces")
        np.testing.assert_array_equal(r.balancing_moment, bare.balancing_moment)
        np.testing.assert_array_equal(r.reaction("B"), bare.reaction("B"))
    # apart: the spring A-D (0.1 long) is a pair of opposite forces on one link: the
    # balancing moment is the one without it (no moment, no work)
    r = _spring_fourbar(0.1, 0.05).solve(phi, omega=10.0, need="forces")
    np.testing.assert_allclose(r.balancing_moment, _spring_fourbar(0.1, 0.0, k=None).solve(
        phi, omega=10.0, need="forces").balancing_moment, rtol=1e-12, atol=1e-12)
    # kinematics never need the spring: no error there
    _spring_fourbar(0.0, 0.05).solve(phi, need="accelerations")
    # two frame points at one place
    m = _spring_fourbar(0.1, 0.0, k=None)
    m.fixed("P", 0.3, 0.05)
    m.spring("C", "P", 10.0, 0.2)
    with pytest.raises(ValueError, match=r"spring\('C', 'P'\)"):
        m.solve(phi, need="forces")
