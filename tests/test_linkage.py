"""sarkp.linkage and the result's linkage methods (issue 27): extreme positions, stroke,
swing, time ratio and transmission angle, against the closed forms of a crank-rocker
(the law of cosines at the positions where crank and coupler are collinear) and of an
offset slider-crank.
"""

import math

import numpy as np
import pytest

import sarkp
from sarkp import linkage

# a crank-rocker (Grashof: a + d < b + c): crank a about O, coupler b, rocker c about C
A_, B_, C_, D_ = 0.1, 0.35, 0.3, 0.32
# an offset slider-crank: crank r, rod l, the guide horizontal at height e
R_, L_, E_ = 0.08, 0.3, 0.04


def four_bar(n=361, branch=1):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", D_, 0.0)
    m.crank("A", "O", A_)
    m.rrr("B", "A", "C", B_, C_, branch=branch)
    return m.solve(np.linspace(0.0, 2 * math.pi, n), need="positions")


def slider_crank(n=361, e=E_):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, e)
    m.crank("A", "O", R_)
    m.rrp("B", "A", "K", 0.0, L_, branch=1)
    return m.solve(np.linspace(0.0, 2 * math.pi, n), need="positions")


def rocker_closed_form(branch):
    """The rocker's extreme positions: O, A, B collinear, OB = b + a or b - a; B from the
    triangle O B C by the law of cosines, on the side of the branch (+1: B left of A->C,
    above the x axis for this crank-rocker)."""
    out = []
    for ob, crank_turn in ((B_ + A_, 0.0), (B_ - A_, math.pi)):
        theta = math.acos((ob ** 2 + D_ ** 2 - C_ ** 2) / (2 * ob * D_))
        theta *= 1 if branch > 0 else -1
        b = ob * np.array([math.cos(theta), math.sin(theta)])
        rocker = math.atan2(b[1], b[0] - D_)          # direction C -> B
        out.append((rocker, (theta + crank_turn) % (2 * math.pi), b))
    return out


def test_crank_rocker_extreme_positions_by_the_law_of_cosines():
    r = four_bar()
    (psi1, phi1, b1), (psi2, phi2, b2) = rocker_closed_form(1)
    e = r.extremes(link=("C", "B"))
    assert {round(v, 9) for v in (e.low, e.high)} == {round(v, 9) for v in (psi1, psi2)}
    lo, hi = sorted([(psi1, phi1), (psi2, phi2)])
    assert e.low == pytest.approx(lo[0], abs=1e-10)
    assert e.high == pytest.approx(hi[0], abs=1e-10)
    # the crank angles of the extremes, between the one-degree grid points
    assert e.phi_low == pytest.approx(lo[1], abs=1e-6)
    assert e.phi_high == pytest.approx(hi[1], abs=1e-6)
    assert min(abs(e.phi_low - p) for p in r.phi) > 1e-3     # not at a grid point
    assert r.stroke(link=("C", "B")) == pytest.approx(abs(psi1 - psi2), abs=1e-10)


def test_extremes_between_grid_points_beat_the_grid():
    """The refined extreme is closer to the closed form than the best grid point."""
    r = four_bar(n=73)                                       # a 5-degree grid
    (psi1, _, _), (psi2, _, _) = rocker_closed_form(1)
    e = r.extremes(link=("C", "B"))
    grid = r.angle("C", "B")
    true_high = max(psi1, psi2)
    assert abs(e.high - true_high) < 1e-3 * abs(grid.max() - true_high)


def test_point_extremes_of_the_rocker_tip():
    """B's extremes along the x axis: B on its circle about C, its coordinate x."""
    r = four_bar()
    e = r.extremes("B", along=0.0)
    # on the arc of B about C, the extreme x among the rocker's swing are at the rocker's
    # extreme positions (the arc is within a half-turn below the vertical here)
    (_, _, b1), (_, _, b2) = rocker_closed_form(1)
    xs = sorted([b1[0], b2[0]])
    swing = r.angle("C", "B")
    assert np.all(np.cos(swing) < 1) and e.along == (1.0, 0.0)
    assert e.low == pytest.approx(xs[0], abs=1e-10)
    assert e.high == pytest.approx(xs[1], abs=1e-10)
    low = b1 if b1[0] < b2[0] else b2
    assert e.at_low == pytest.approx(tuple(low), abs=1e-9)


@pytest.mark.parametrize("e", [E_, 0.0, -0.03])
def test_offset_slider_crank_stroke_and_time_ratio(e):
    r = slider_crank(e=e)
    stroke = math.sqrt((L_ + R_) ** 2 - e ** 2) - math.sqrt((L_ - R_) ** 2 - e ** 2)
    psi = abs(math.asin(e / (L_ - R_)) - math.asin(e / (L_ + R_)))
    k = (math.pi + psi) / (math.pi - psi)
    ext = r.extremes("B")                      # default: the guide (the path's axis)
    assert ext.along == pytest.approx((1.0, 0.0), abs=1e-12)
    assert ext.stroke == pytest.approx(stroke, rel=1e-9)
    assert r.stroke("B") == ext.stroke
    assert ext.high == pytest.approx(math.sqrt((L_ + R_) ** 2 - e ** 2), rel=1e-9)
    assert ext.at_high == pytest.approx((ext.high, e), abs=1e-9)
    # the extended and folded positions: crank along and against O->B
    assert ext.phi_high == pytest.approx(math.atan2(e, ext.high) % (2 * math.pi), abs=1e-6)
    assert ext.phi_low == pytest.approx(math.atan2(-e, -ext.low) % (2 * math.pi), abs=1e-6)
    assert r.time_ratio("B") == pytest.approx(k, rel=1e-6)


def test_slider_crank_transmission_angle():
    """mu = 90 deg minus the rod's angle to the guide; worst where the crank is normal to
    the guide on the side away from it: sin(90 - mu) = (r + |e|) / l."""
    r = slider_crank()
    t = r.transmission_angle("B")
    assert t.worst == pytest.approx(math.pi / 2 - math.asin((R_ + E_) / L_), abs=1e-9)
    assert t.phi_worst == pytest.approx(3 * math.pi / 2, abs=1e-5)
    a, b = r.position("A"), r.position("B")
    rod = np.arctan2(a[:, 1] - b[:, 1], a[:, 0] - b[:, 0])
    assert np.allclose(np.sin(t.angle), np.abs(np.cos(rod)), atol=1e-12)


@pytest.mark.parametrize("branch", [1, -1])
def test_crank_rocker_transmission_angle_by_the_law_of_cosines(branch):
    r = four_bar(branch=branch)
    gamma = lambda ac: math.acos((B_ ** 2 + C_ ** 2 - ac ** 2) / (2 * B_ * C_))
    g0, g1 = gamma(D_ - A_), gamma(D_ + A_)              # crank at 0 and at pi
    t = r.transmission_angle("B")
    assert t.smallest == pytest.approx(g0, abs=1e-10)
    assert t.largest == pytest.approx(g1, abs=1e-10)
    worst = min(g0, math.pi - g1)
    assert t.worst == pytest.approx(worst, abs=1e-10)
    assert t.phi_worst == pytest.approx(0.0 if g0 <= math.pi - g1 else math.pi, abs=1e-5)
    # the angle at each position, from the law of cosines with |AC|
    ac = np.hypot(*(r.position("A") - r.position("C")).T)
    assert np.allclose(t.angle, np.arccos((B_ ** 2 + C_ ** 2 - ac ** 2) / (2 * B_ * C_)),
                       atol=1e-12)


def test_time_ratio_of_the_crank_rocker():
    r = four_bar()
    (_, phi1, _), (_, phi2, _) = rocker_closed_form(1)
    forward = (phi2 - phi1) % (2 * math.pi)
    k = max(forward, 2 * math.pi - forward) / min(forward, 2 * math.pi - forward)
    assert r.time_ratio(link=("C", "B")) == pytest.approx(k, rel=1e-6)


def test_a_sweep_without_the_closing_point_is_a_full_turn():
    phi = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    s = np.cos(phi - 1.234)
    e = linkage.extremes(phi, s)
    assert e.high == pytest.approx(1.0, abs=1e-9)
    assert e.phi_high == pytest.approx(1.234, abs=1e-6)
    assert e.phi_low == pytest.approx(1.234 + math.pi, abs=1e-6)
    assert linkage.time_ratio(phi, s) == pytest.approx(1.0, abs=1e-6)


def test_part_of_a_turn_keeps_its_end_points():
    phi = np.linspace(0.0, 1.0, 50)
    e = linkage.extremes(phi, np.sin(phi))
    assert (e.phi_low, e.low) == (0.0, 0.0)
    assert e.phi_high == 1.0 and e.high == pytest.approx(math.sin(1.0), rel=1e-15)
    with pytest.raises(ValueError, match="full turn"):
        linkage.time_ratio(phi, np.sin(phi))


def test_bad_input_is_refused_by_name():
    r = four_bar(n=37)
    with pytest.raises(ValueError, match="name a point"):
        r.extremes()
    with pytest.raises(ValueError, match="name a point"):
        r.extremes("B", link=("C", "B"))
    with pytest.raises(ValueError, match="along"):
        r.extremes("B", along=(0.0, 0.0))
    with pytest.raises(ValueError, match="no group places"):
        r.transmission_angle("A")
    with pytest.raises(ValueError, match="NaN"):
        linkage.extremes([0.0, 1.0, 2.0], [0.0, math.nan, 1.0])
    with pytest.raises(ValueError, match="increase"):
        linkage.extremes([0.0, 1.0, 1.0], [0.0, 1.0, 2.0])
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.0)
    rr = m.solve(np.linspace(0, 2 * math.pi, 37), need="positions")
    with pytest.raises(ValueError, match="kind 3"):
        rr.transmission_angle("B")
