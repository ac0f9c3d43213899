"""The book's kind-1 routines are adapters over the group kernel (fortran/groups.f90:
rrr_kernel) that sarkp.Mechanism calls too: fed the same Cartesian data, DKNMA1 and DPRM1
and a one-group Mechanism give the same bits; their statuses agree in kind (issue 25,
"one home for each Assur group kind").  Corrected mode; as printed, the book's own
sequence stays (its printed figures depend on it)."""

import math
import warnings

import numpy as np
import pytest

import sarkp


def _polar_exact(x, y):
    """(modulus, direction) whose components m*cos(a), m*sin(a) are x, y to the bit (the
    book routines take polar velocities and turn them into components so), or None when
    none is near: about 40% of vectors have one (a within a few ulps of atan2, m of x/c
    or y/s)."""
    a0 = math.atan2(y, x)
    for a in _ulps_around(a0):
        c, s = math.cos(a), math.sin(a)
        for m in set(_ulps_around(x / c, 3) + _ulps_around(y / s, 3)):
            if m * c == x and m * s == y:
                return m, a
    return None


def _ulps_around(t, k=6):
    """t, then its neighbours 1, 2, ..., k ulps away on either side."""
    up, down, out = t, t, [t]
    for _ in range(k):
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
        out += [up, down]
    return out


def _fourbar(xc, yc, r, l2, l3, branch):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, yc)
    m.crank("A", "O", r)
    m.rrr("B", "A", "C", l2, l3, branch=branch)
    return m


def _status_kind(s):
    return "ok" if s == 0 else "digits" if s == int(sarkp.Status.SIGNIFICANCE) else "error"


@pytest.mark.parametrize("seed", range(4))
def test_dknma1_and_the_mechanism_give_the_same_bits(seed):
    rng = np.random.default_rng(seed)
    xc, yc = rng.uniform(0.3, 0.6), rng.uniform(-0.2, 0.2)
    r = rng.uniform(0.05, 0.12)
    d = math.hypot(xc, yc)
    l2, l3 = rng.uniform(0.6, 1.0) * d, rng.uniform(0.6, 1.0) * d
    branch = int(rng.choice([-1, 1]))
    phi = rng.uniform(-math.pi, math.pi, 150)
    res = _fourbar(xc, yc, r, l2, l3, branch).solve(phi, on_error="nan")
    a, va, aa = res.position("A"), res.velocity("A"), res.acceleration("A")
    b, vb, ab = res.position("B"), res.velocity("B"), res.acceleration("B")
    w2, w3 = res.omega("A", "B"), res.omega("C", "B")
    e2, e3 = res.epsilon("A", "B"), res.epsilon("C", "B")
    compared = [0, 0]
    for i in range(phi.size):
        v, acc = _polar_exact(*va[i]), _polar_exact(*aa[i])
        if v is None:
            continue
        level = 2 if acc is None else 3           # ANALOG = 1: the velocities only
        acc = acc or (0.0, 0.0)
        k = sarkp.DKNMA1(a[i, 0], a[i, 1], xc, yc, l2, l3, v[0], v[1], 0.0, 0.0,
                         acc[0], acc[1], 0.0, 0.0, branch, 1.0 if level == 2 else 0.0,
                         on_error="nan")
        assert _status_kind(int(k.status)) == _status_kind(int(res.status[i]))
        if k.status != 0:
            continue
        compared[level - 2] += 1
        # the same kernel on the same data: the same bits
        assert (k.XB, k.YB) == (b[i, 0], b[i, 1])
        assert (k.W2, k.W3) == (w2[i], w3[i])
        # the polar outputs are those vectors' modulus and direction
        assert k.VB == pytest.approx(math.hypot(*vb[i]), rel=4e-16)
        for ang, vec in ((k.FI2, b[i] - a[i]), (k.ALB, vb[i])):
            turn = math.remainder(ang - math.atan2(vec[1], vec[0]), 2 * math.pi)
            assert abs(turn) < 4e-16 * (1 + abs(ang))
        # the book's relative velocity: W2*RZ2 along e(FI2 + pi/2) turned by W2's sign
        assert k.VBA == abs(k.W2) * l2
        assert k.ALBA == k.FI2 + math.copysign(math.pi / 2, k.W2)
        if level == 3:
            assert (k.E2, k.E3) == (e2[i], e3[i])
            assert k.AB == pytest.approx(math.hypot(*ab[i]), rel=4e-16)
            turn = math.remainder(k.BB - math.atan2(ab[i, 1], ab[i, 0]), 2 * math.pi)
            assert abs(turn) < 4e-16 * (1 + abs(k.BB))
    assert compared[0] + compared[1] >= 30 and compared[1] >= 8


def test_dknma1_statuses_agree_in_kind_near_the_dead_centre():
    # crank 0.1, C at 0.4, AB + CB just above the largest |AC| = 0.5: the stretched
    # dead centre at phi = pi is approached; both say OK far from it, warn or fail near
    xc, r, l3 = 0.4, 0.1, 0.2
    phi = math.pi - np.geomspace(1e-1, 1e-7, 13)
    for eps in (1e-3, 1e-6, 1e-9):
        l2 = 0.5 - l3 + eps
        res = _fourbar(xc, 0.0, r, l2, l3, 1).solve(phi, on_error="nan")
        a = res.position("A")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            k = sarkp.DKNMA1(a[:, 0], a[:, 1], xc, 0.0, l2, l3, r, phi + math.pi / 2,
                             0.0, 0.0, r, phi + math.pi, 0.0, 0.0, 1, 0.0, on_error="nan")
        kinds = [(_status_kind(s), _status_kind(t)) for s, t in zip(k.status, res.status)]
        assert all(x == y for x, y in kinds), kinds
        assert np.array_equal(k.XB, res.position("B")[:, 0], equal_nan=True)


def test_dknma1_as_printed_is_not_the_kernel():
    # as printed, DKNMA1 keeps the book's sequence, its PI = 3.14159 in the directions
    # (e(FI2 + PID2), ALBA = FI2 + PID2): ALBA moves by the 1.3e-6 of PID2, B does not
    args = (0.1 * math.cos(0.7), 0.1 * math.sin(0.7), 0.4, 0.0, 0.35, 0.3,
            0.3, 0.7 + math.pi / 2, 0.0, 0.0, 0.9, 0.7 + math.pi, 0.0, 0.0, 1, 0.0)
    corrected = sarkp.DKNMA1(*args)
    with sarkp.as_printed():
        printed = sarkp.DKNMA1(*args)
    assert math.hypot(printed.XB - corrected.XB, printed.YB - corrected.YB) < 1e-12
    assert 1e-7 < abs(printed.ALBA - corrected.ALBA) < 1e-5


def test_dprm1_positions_are_the_mechanisms_to_the_bit():
    phi = np.linspace(-3.1, 3.1, 63)
    for branch in (1, -1):
        m = _fourbar(0.4, 0.05, 0.1, 0.35, 0.3, branch)
        res = m.solve(phi, need="positions")
        a, b = res.position("A"), res.position("B")
        p = sarkp.DPRM1(a[:, 0], a[:, 1], 0.4, 0.05, 0.35, 0.3, -branch)   # P = -branch
        assert np.array_equal(p.XB, b[:, 0]) and np.array_equal(p.YB, b[:, 1])
        # the book's range: FI2 is the direction of B - A, DUGOL'd (up to 3 pi)
        d = np.remainder(p.FI2 - np.arctan2(b[:, 1] - a[:, 1], b[:, 0] - a[:, 0]), 2 * np.pi)
        assert np.all(np.minimum(d, 2 * np.pi - d) < 1e-15) and np.all(p.FI2 >= 0)
