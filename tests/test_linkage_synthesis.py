"""Dimensional synthesis over the Mechanism (sarkp.dimensional, issue 28): function,
path and motion generation, held against closed forms computed here independently, the
book's chapter 3 routines (Fig. 10's problems) and the requirements over the whole
turn."""

import math
import pickle

import numpy as np
import pytest

import sarkp
from sarkp.book import prog_iii_5

# ---- independent references -----------------------------------------------------------


def rocker_angle(a, b, c, d, phi, branch):
    """The rocker angle of the four-bar O(0,0)-A-B-C(d,0) at the crank angle phi, by
    intersecting the circles (A, b) and (C, c) (no sarkp code)."""
    A = np.stack([a * np.cos(phi), a * np.sin(phi)], -1)
    C = np.array([d, 0.0])
    u = C - A
    L = np.hypot(u[..., 0], u[..., 1])
    x = (b * b - c * c + L * L) / (2 * L)
    h = np.sqrt(b * b - x * x)
    e = u / L[..., None]
    n = np.stack([-e[..., 1], e[..., 0]], -1)
    B = A + x[..., None] * e + branch * h[..., None] * n
    return np.arctan2(B[..., 1], B[..., 0] - d)


def coupler_point(design, phi):
    """The coupler point of a design vector (O, C, a, b, c, p, q, branch) at phi."""
    xO, yO, xC, yC, a, b, c, p, q, br = design
    A = np.stack([xO + a * np.cos(phi), yO + a * np.sin(phi)], -1)
    u = np.array([xC, yC]) - A
    L = np.hypot(u[..., 0], u[..., 1])
    x = (b * b - c * c + L * L) / (2 * L)
    h = np.sqrt(b * b - x * x)
    e = u / L[..., None]
    n = np.stack([-e[..., 1], e[..., 0]], -1)
    B = A + x[..., None] * e + np.sign(br) * h[..., None] * n
    t = (B - A) / b
    tn = np.stack([-t[..., 1], t[..., 0]], -1)
    return A + p * t + q * tn


def wrap(x):
    return np.remainder(x + math.pi, 2 * math.pi) - math.pi


# ---- function generation: Freudenstein, y = log10 x on [1, 2] -------------------------

X0, X1 = 1.0, 2.0
PHI0, DPHI = math.radians(15.0), math.radians(90.0)      # crank: 15 .. 105 deg
PSI0, DPSI = math.radians(300.0), math.radians(-60.0)    # rocker: 300 .. 240 deg


def phi_of(x):
    return PHI0 + DPHI * (x - X0) / (X1 - X0)


def psi_of(x):
    return PSI0 + DPSI * np.log10(x) / math.log10(X1)


def chebyshev(n):
    j = np.arange(1, n + 1)
    return 0.5 * (X0 + X1) - 0.5 * (X1 - X0) * np.cos((2 * j - 1) * math.pi / (2 * n))


def freudenstein_closed_form(phi, psi, d):
    """Cramer's rule on K1 cos psi - K2 cos phi + K3 = cos(phi - psi)."""
    M = np.column_stack([np.cos(psi), -np.cos(phi), np.ones(3)])
    r = np.cos(phi - psi)
    det = np.linalg.det(M)
    K = [np.linalg.det(np.column_stack([r if j == i else M[:, j] for j in range(3)])) / det
         for i in range(3)]
    a, c = d / K[0], d / K[1]
    b = math.sqrt(a * a + c * c + d * d - 2 * a * c * K[2])
    return a, b, c


def test_freudenstein_three_chebyshev_points():
    x = chebyshev(3)
    phi, psi = phi_of(x), psi_of(x)
    fg = sarkp.function_generation(phi, psi, ground=1.0)
    a, b, c = freudenstein_closed_form(phi, psi, 1.0)
    L = fg.lengths
    assert abs(L["a"] - a) <= 1e-12 and abs(L["b"] - b) <= 1e-12
    assert abs(L["c"] - c) <= 1e-12 and L["d"] == 1.0
    np.testing.assert_array_equal(fg.phi, phi)               # no offset: 3 points
    # the rocker angle at the precision points, from the Mechanism
    r = fg.mechanism.solve(phi, need="positions")
    assert np.max(np.abs(wrap(r.angle("C", "B") - psi))) <= 1e-12
    assert fg.error <= 1e-12
    # the structural error over the range, against the circles' intersection
    xs = np.linspace(X0, X1, 201)
    r = fg.mechanism.solve(phi_of(xs), need="positions")
    mine = wrap(r.angle("C", "B") - psi_of(xs))
    ref = wrap(rocker_angle(a, b, c, 1.0, phi_of(xs), fg.branch) - psi_of(xs))
    np.testing.assert_allclose(mine, ref, rtol=0, atol=1e-12)
    # zero at the precision points, not zero between them
    assert np.max(np.abs(ref)) > 1e-4
    # reported: the Grashof type and the transmission angle over the motion
    assert fg.grashof == sarkp.grashof_type(a, b, c, 1.0)
    mu = np.degrees(np.arccos((b * b + c * c - (1 + a * a - 2 * a * np.cos(phi_of(xs))))
                              / (2 * b * c)))
    lo, hi = fg.transmission
    assert lo <= mu.min() + 1e-9 and hi >= mu.max() - 1e-9


@pytest.mark.parametrize("method, xs", [("least_squares", chebyshev(41)),
                                        ("minimax", np.linspace(X0, X1, 41))])
def test_fit_over_the_range_no_worse_than_precision_points(method, xs):
    """A fit over the range is no worse in its worst error than the three Chebyshev
    points (0.0274 rad here): minimax over uniform samples (0.0173), least squares over
    Chebyshev-spaced samples (0.0204).  (Least squares over uniform samples minimises the
    mean square, not the worst error: 0.0303 rad, worse -- not asserted.)"""
    x3 = chebyshev(3)
    exact = sarkp.function_generation(phi_of(x3), psi_of(x3))
    fit = sarkp.function_generation(phi_of(xs), psi_of(xs), method=method)
    assert fit.extra["method"] == method
    # the worst error over the range, each measured by the circles' intersection
    fine = np.linspace(X0, X1, 401)

    def worst(res):
        L = res.lengths
        e = wrap(rocker_angle(L["a"], L["b"], L["c"], L["d"], phi_of(fine), res.branch)
                 - psi_of(fine))
        return np.max(np.abs(e))
    assert worst(fit) <= worst(exact)
    # the reported error is the largest error at the given points
    L = fit.lengths
    e = wrap(rocker_angle(L["a"], L["b"], L["c"], L["d"], phi_of(xs), fit.branch)
             - psi_of(xs))
    assert abs(fit.error - np.max(np.abs(e))) <= 1e-12


@pytest.mark.parametrize("n", [4, 5])
def test_four_and_five_precision_points_free_the_dial_zeros(n):
    x = chebyshev(n)
    phi, psi = phi_of(x), psi_of(x)
    fg = sarkp.function_generation(phi, psi)
    al, be = fg.offsets
    if n == 4:          # the crank's zero has no solution here: the rocker's is freed
        assert al == 0.0 and be != 0.0
        with pytest.raises(sarkp.RequirementError, match="no solution"):
            sarkp.function_generation(phi, psi, offsets="crank")
    np.testing.assert_allclose(fg.phi, phi + al, atol=1e-15)
    L = fg.lengths
    ref = rocker_angle(L["a"], L["b"], L["c"], L["d"], phi + al, fg.branch)
    assert np.max(np.abs(wrap(ref - psi - be))) <= 1e-10
    assert fg.error <= 1e-10


# ---- the book's chapter 3 problems (Fig. 10) -----------------------------------------

def test_fig10_dsntzr_fourbar_agrees_and_has_a_branch_defect():
    """DSNTZR's four-bar: frame 0.9, rocker 0.6, crank angles known up to the crank's
    zero -- the function generation with the rocker given frees the crank's offset and
    finds DSNTZR's L1, L2, FI11.  That four-bar meets the third position only on the
    other assembly branch (B on the other side of A->C), which DSNTZR does not check:
    function_generation refuses it, naming the branch change."""
    p = prog_iii_5.FOURBAR
    ref = sarkp.DSNTZR(p["LO"], p["L3"], p["FI1"], p["FI3"], 1.0)
    phi, psi = np.array(p["FI1"]), np.array(p["FI3"])
    with pytest.raises(sarkp.RequirementError, match="changes branch") as info:
        sarkp.function_generation(phi, psi, ground=p["LO"][0], rocker=p["L3"],
                                  offsets="crank")
    (a, b, c, al, be), = info.value.candidates
    assert abs(a - ref.L1) <= 1e-9 and abs(b - ref.L2) <= 1e-9 and c == p["L3"]
    assert abs(wrap(phi[0] + al - ref.FI11)) <= 1e-9 and be == 0.0
    # the branch defect, independently: the circles' intersection on one branch meets
    # the first two rocker angles and misses the third
    f = ref.FI11 + phi - phi[0]
    for branch in (1, -1):
        e = np.abs(wrap(rocker_angle(a, b, c, 0.9, f, branch) - psi))
        assert (e < 1e-9).sum() in (1, 2) and (e > 1e-3).any()


def test_fig10_dsntzr_slider_agrees():
    p = prog_iii_5.SLIDER_CARD
    ref = sarkp.DSNTZR(p["LO"], p["L3"], p["FI1"], p["FI3"], 1.0)
    th = p["FI3"][0]
    s = np.array(p["LO"]) + p["L3"] * math.cos(th)
    sg = sarkp.slider_function_generation(np.array(p["FI1"]), s,
                                          offset=p["L3"] * math.sin(th))
    assert abs(sg.lengths["a"] - ref.L1) <= 1e-9
    assert abs(sg.lengths["b"] - ref.L2) <= 1e-9
    assert abs(wrap(sg.phi[0] - ref.FI11)) <= 1e-9
    r = sg.mechanism.solve(sg.phi, need="positions")
    np.testing.assert_allclose(r.position("B")[:, 0], s, atol=1e-10)


def test_slider_three_positions_exact():
    a, b, e = 0.1, 0.35, 0.03
    phi = np.array([0.3, 1.1, 2.0])
    s = a * np.cos(phi) + np.sqrt(b * b - (e - a * np.sin(phi)) ** 2)
    sg = sarkp.slider_function_generation(phi, s)
    L = sg.lengths
    assert abs(L["a"] - a) <= 1e-12 and abs(L["b"] - b) <= 1e-12
    assert abs(L["e"] - e) <= 1e-12
    assert sg.grashof == "crank-slider"
    assert sg.error <= 1e-12
