"""The kinematic kernels of fortran/groups.f90 (issue 25: one home per group kind), each
reached through a Mechanism of one crank and one group (or one rigid point).

References, independent of the kernels' formulas: each group's position in closed form
written here in mpmath at 40 digits from the same binary inputs (the circle and line
intersections of the group's constraints), its velocity and acceleration analogues as
mpmath's numerical derivatives of that position with respect to the crank angle, the
links' angles as atan2 of the joints and their derivatives the same way.  The kernels
must agree to rounding: 1e-13 relative to the group's size (positions) or to the
largest analogue of the case (derivatives).  With omega and epsilon: v = x' omega,
a = x'' omega**2 + x' epsilon.
"""

import math

import mpmath as mp
import numpy as np
import pytest

import sarkp
from sarkp import Mechanism

mp.mp.dps = 40
PHI = [-2.9, -1.3, -0.2, 0.0, 0.45, 1.7, 2.6, 3.1]
W, E = 7.0, -3.0
TOL = 1e-13


def crank_point(o, r, phi):
    return (mp.mpf(o[0]) + mp.mpf(r) * mp.cos(phi), mp.mpf(o[1]) + mp.mpf(r) * mp.sin(phi))


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def derivatives(f, phi):
    """f(phi) -> tuple of mp numbers: values, first and second derivatives at phi."""
    phi = mp.mpf(phi)
    k = len(f(phi))
    d0 = f(phi)
    d1 = [mp.diff(lambda t, j=j: f(t)[j], phi, 1) for j in range(k)]
    d2 = [mp.diff(lambda t, j=j: f(t)[j], phi, 2) for j in range(k)]
    return [np.array([float(v) for v in d]) for d in (d0, d1, d2)]


def check(m, ref, point, links, size):
    """The Mechanism's point and links at PHI against ref(phi) = (x, y, angle, ...) in
    mpmath, at omega = 1 and at (W, E)."""
    phi = np.array(PHI)
    r1 = m.solve(phi, omega=1.0, epsilon=0.0, need="accelerations")
    r = m.solve(phi, omega=W, epsilon=E, need="accelerations")
    got = [r1.position(point), r1.velocity(point), r1.acceleration(point)]
    for i, p in enumerate(PHI):
        x, v, a = derivatives(ref, p)
        vscale = max(np.max(np.abs(v)), 1e-300)
        ascale = max(np.max(np.abs(a)), 1e-300)
        assert np.max(np.abs(got[0][i] - x[:2])) <= TOL * size, (p, got[0][i], x[:2])
        assert np.max(np.abs(got[1][i] - v[:2])) <= TOL * vscale, (p, got[1][i], v[:2])
        assert np.max(np.abs(got[2][i] - a[:2])) <= TOL * ascale, (p, got[2][i], a[:2])
        np.testing.assert_allclose(r.velocity(point)[i], W * v[:2], rtol=0,
                                   atol=TOL * W * vscale)
        np.testing.assert_allclose(r.acceleration(point)[i], W * W * a[:2] + E * v[:2],
                                   rtol=0, atol=TOL * (W * W * ascale + abs(E) * vscale))
        for j, lk in enumerate(links):
            th = r1.angle(*lk)[i]
            dth = (th - x[2 + j] + math.pi) % (2 * math.pi) - math.pi
            assert abs(dth) <= TOL, (p, lk, th, x[2 + j])
            assert abs(r1.omega(*lk)[i] - v[2 + j]) <= TOL * (1 + np.max(np.abs(v[2:]))), lk
            assert abs(r1.epsilon(*lk)[i] - a[2 + j]) <= TOL * (1 + np.max(np.abs(a[2:]))), lk
            assert abs(r.omega(*lk)[i] - W * v[2 + j]) <= TOL * W * (1 + np.max(np.abs(v[2:])))
    assert np.all(r.status == 0)


def test_crank_and_rigid_point():
    """A = O + r e(phi); D on the crank at dist from O, at angle from O->A."""
    o, rr, dist, ang = (0.25, -0.5), 0.3, 0.7, 0.4
    m = Mechanism()
    m.fixed("O", *o)
    m.crank("A", "O", rr)
    m.point("D", "O", "A", dist, ang)

    def ref_a(t):
        return (*crank_point(o, rr, t), t)

    def ref_d(t):
        return (*crank_point(o, dist, t + ang), t)
    check(m, ref_a, "A", [("O", "A")], rr)
    check(m, ref_d, "D", [], dist)


@pytest.mark.parametrize("branch", [1, -1])
def test_rrr_kernel(branch):
    """B = the intersection of the circles (A, l2) and (C, l3) on the branch's side of
    A->C."""
    o, c, rr, l2, l3 = (0.0, 0.0), (0.3, 0.05), 0.1, 0.35, 0.3
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("C", *c)
    m.crank("A", "O", rr)
    m.rrr("B", "A", "C", l2, l3, branch=branch)
    m.point("D", "C", "B", 0.12, 0.5)            # a point on link 3, off its line

    def ref(t):
        ax, ay = crank_point(o, rr, t)
        cx, cy = mp.mpf(c[0]), mp.mpf(c[1])
        # the circles' radical line, then the two intersections
        d2 = (cx - ax) ** 2 + (cy - ay) ** 2
        d = mp.sqrt(d2)
        f = (d2 + mp.mpf(l2) ** 2 - mp.mpf(l3) ** 2) / (2 * d2)
        h = mp.sqrt(mp.mpf(l2) ** 2 / d2 - f * f)
        cands = [(ax + f * (cx - ax) - s * h * (cy - ay), ay + f * (cy - ay) + s * h * (cx - ax))
                 for s in (1, -1)]
        bx, by = [b for b in cands if cross((cx - ax, cy - ay), (b[0] - ax, b[1] - ay)) * branch > 0][0]
        return (bx, by, mp.atan2(by - ay, bx - ax), mp.atan2(by - cy, bx - cx))

    def ref_d(t):
        bx, by, _, th3 = ref(t)
        return (mp.mpf(c[0]) + mp.mpf(0.12) * mp.cos(th3 + mp.mpf(0.5)),
                mp.mpf(c[1]) + mp.mpf(0.12) * mp.sin(th3 + mp.mpf(0.5)))
    check(m, ref, "B", [("A", "B"), ("C", "B")], l2)
    check(m, ref_d, "D", [], 0.12)


@pytest.mark.parametrize("branch", [1, -1])
def test_rrp_kernel(branch):
    """B on the line through K at angle, offset along its left normal, at l2 from A: the
    line-circle intersection ahead of (branch +1) or behind the foot from A."""
    o, k, rr, angle, l2, off = (0.0, 0.0), (0.05, 0.02), 0.1, 0.3, 0.4, 0.015
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("K", *k)
    m.crank("A", "O", rr)
    m.rrp("B", "A", "K", angle, l2, branch=branch, offset=off)

    def ref(t):
        ax, ay = crank_point(o, rr, t)
        u = (mp.cos(angle), mp.sin(angle))
        n = (-u[1], u[0])
        # B = K + off n + s u, |B - A| = l2: s**2 + 2 s (P . u) + |P|**2 - l2**2 = 0
        px, py = mp.mpf(k[0]) + off * n[0] - ax, mp.mpf(k[1]) + off * n[1] - ay
        pu = px * u[0] + py * u[1]
        disc = pu * pu - (px * px + py * py - mp.mpf(l2) ** 2)
        s = -pu + branch * mp.sqrt(disc)
        bx, by = mp.mpf(k[0]) + off * n[0] + s * u[0], mp.mpf(k[1]) + off * n[1] + s * u[1]
        return (bx, by, mp.atan2(by - ay, bx - ax), mp.mpf(angle))
    check(m, ref, "B", [("A", "B"), ("B",)], l2)


@pytest.mark.parametrize("branch", [1, -1])
def test_rpr_kernel(branch):
    """Link 3 turns about C; the slider pivoted at A keeps A at h from its axis; B = the
    foot of the perpendicular from A: |CB| = sqrt(|AC|**2 - h**2), B on the branch's side
    of A->C."""
    o, c, rr, rz2, t = (0.0, 0.0), (0.0, -0.25), 0.1, 0.05, 1.2
    h = abs(rz2 * math.sin(t))
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("C", *c)
    m.crank("A", "O", rr)
    m.rpr("B", "A", "C", rz2, t, branch=branch)

    def ref(tt):
        ax, ay = crank_point(o, rr, tt)
        cx, cy = mp.mpf(c[0]), mp.mpf(c[1])
        d = mp.sqrt((ax - cx) ** 2 + (ay - cy) ** 2)
        psi = mp.atan2(ay - cy, ax - cx)
        sl = mp.sqrt(d * d - mp.mpf(h) ** 2)
        for s in (1, -1):
            th = psi + s * mp.asin(mp.mpf(h) / d)
            bx, by = cx + sl * mp.cos(th), cy + sl * mp.sin(th)
            if cross((cx - ax, cy - ay), (bx - ax, by - ay)) * branch > 0:
                return (bx, by, th, th)
    check(m, ref, "B", [("C", "B"), ("A", "B")], 0.25)


def test_prp_kernel():
    """B on the guide through A carried by the crank (at fim to it) and on the fixed guide
    through G (at fin), each at its offset: two lines' intersection."""
    o, g, rr, fim, fin, d2, d3 = (0.0, 0.0), (0.0, 0.05), 0.1, 1.3, 0.2, 0.01, -0.02
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("G", *g)
    m.crank("A", "O", rr)
    m.prp("B", "A", fim, "G", fin, rz2=d2, t2=math.pi / 2, rz3=d3, t3=math.pi / 2,
          guide_m=("O", "A"))

    def ref(t):
        ax, ay = crank_point(o, rr, t)
        am = t + fim
        nm_ = (-mp.sin(am), mp.cos(am))
        nn = (-mp.sin(fin), mp.cos(fin))
        # nm . (B - A) = d2, nn . (B - G) = d3
        M = mp.matrix([[nm_[0], nm_[1]], [nn[0], nn[1]]])
        rhs = mp.matrix([d2 + nm_[0] * ax + nm_[1] * ay, d3 + nn[0] * g[0] + nn[1] * g[1]])
        b = mp.lu_solve(M, rhs)
        return (b[0], b[1], am, mp.mpf(fin))
    check(m, ref, "B", [("B", "A"), ("B", "G")], 0.1)


@pytest.mark.parametrize("t2", [math.pi / 2, 0.3, 1e-6])
def test_rpp_kernel(t2):
    """Link 2 slides on the fixed guide through G (at fim); the block pivoted at the crank
    pin A slides in link 2's slot at fim + t2: K = G + s um with A - G = s um + q us.
    A small slot angle keeps its digits (DPRM5's frame of the guide)."""
    o, g, rr, fim = (0.0, 0.0), (0.2, -0.3), 0.1, 0.25
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("G", *g)
    m.crank("A", "O", rr)
    m.rpp("K", "G", fim, "A", t2)

    def ref(t):
        ax, ay = crank_point(o, rr, t)
        um = (mp.cos(fim), mp.sin(fim))
        us = (mp.cos(mp.mpf(fim) + mp.mpf(t2)), mp.sin(mp.mpf(fim) + mp.mpf(t2)))
        M = mp.matrix([[um[0], us[0]], [um[1], us[1]]])
        sq = mp.lu_solve(M, mp.matrix([ax - g[0], ay - g[1]]))
        return (g[0] + sq[0] * um[0], g[1] + sq[0] * um[1], mp.mpf(fim),
                mp.mpf(fim) + mp.mpf(t2))
    # K's motion is of the size of the crank's divided by sin(t2)
    check(m, ref, "K", [("K", "G"), ("A", "K")], rr / math.sin(t2))


def test_guides_on_moving_links():
    """rrp with its guide on the rocker of a four-bar: B's motion against the four-bar's
    closed form carried through the guide (the kernel's guide inputs x, v, a, w, e)."""
    o, c, rr, l2, l3 = (0.0, 0.0), (0.3, 0.05), 0.1, 0.35, 0.3
    dist, ang, gang, lr, off = 0.2, 0.3, 0.4, 0.3, 0.01
    m = Mechanism()
    m.fixed("O", *o)
    m.fixed("C", *c)
    m.crank("A", "O", rr)
    m.rrr("B", "A", "C", l2, l3)
    m.point("D", "C", "B", dist, ang)
    m.rrp("E", "A", "D", gang, lr, branch=-1, offset=off, guide=("C", "B"))

    def ref(t):
        ax, ay = crank_point(o, rr, t)
        cx, cy = mp.mpf(c[0]), mp.mpf(c[1])
        d2 = (cx - ax) ** 2 + (cy - ay) ** 2
        f = (d2 + mp.mpf(l2) ** 2 - mp.mpf(l3) ** 2) / (2 * d2)
        h = mp.sqrt(mp.mpf(l2) ** 2 / d2 - f * f)
        bx, by = ax + f * (cx - ax) - h * (cy - ay), ay + f * (cy - ay) + h * (cx - ax)
        th3 = mp.atan2(by - cy, bx - cx)
        dx, dy = cx + dist * mp.cos(th3 + ang), cy + dist * mp.sin(th3 + ang)
        u = (mp.cos(th3 + gang), mp.sin(th3 + gang))
        n = (-u[1], u[0])
        px, py = dx + off * n[0] - ax, dy + off * n[1] - ay
        pu = px * u[0] + py * u[1]
        s = -pu - mp.sqrt(pu * pu - (px * px + py * py - mp.mpf(lr) ** 2))
        ex, ey = dx + off * n[0] + s * u[0], dy + off * n[1] + s * u[1]
        return (ex, ey, mp.atan2(ey - ay, ex - ax), th3 + gang)
    check(m, ref, "E", [("A", "E"), ("E",)], lr)


def test_unknown_kind_is_an_error_never_skipped():
    """A step of a kind no kernel knows: solve raises (on_error='nan': NaN and the
    status), at every need."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3)
    m.solve(0.3)                                   # fine as described
    kind, ints, reals, name = m._steps[1]
    assert kind == 1
    m._steps[1] = (17, ints, reals, name)
    m._cache = None
    for need in ("positions", "velocities", "accelerations", "forces"):
        with pytest.raises(ValueError, match="unknown group kind"):
            m.solve([0.3, 1.0], need=need)
        r = m.solve([0.3, 1.0], need=need, on_error="nan")
        assert np.all(r.status == int(sarkp.Status.MISSING))
        assert np.all(np.isnan(r.position("B")))
