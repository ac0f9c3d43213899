"""The dead-centre promise of sarkp.Mechanism (issue 25), fuzzed: status OK means at least
8 correct significant digits, a SignificanceWarning's digits are never too many, and the
statuses are the same at every scale 2**k.

The reference is independent of sarkp: the four-bar's closed form (the apex of the
triangle A-B-C) and its velocity and acceleration systems solved in mpmath at 40 digits,
from the same binary inputs.  The errors are normwise, as the estimate's: the position of
B relative to the coupler's length, the angular velocities and accelerations as the
vector (w2 l2, w3 l3) relative to the larger of its norm and the crank's radius (the
size of the right-hand side; the crank turns at omega = 1).  Random four-bars, random
positions and positions within 1e-2 .. 1e-12 of a toggle; a seeded Hypothesis run.
"""

import math
import warnings

import mpmath as mp
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import sarkp

mp.mp.dps = 40


def fourbar(r, c, l2, l3, scale=1.0, off=(0.0, 0.0)):
    m = sarkp.Mechanism()
    m.fixed("O", off[0], off[1])
    m.fixed("C", off[0] + c * scale, off[1])
    m.crank("A", "O", r * scale)
    m.rrr("B", "A", "C", l2 * scale, l3 * scale, branch=1)
    return m


def reference(ox, oy, cx, cy, r, l2, l3, phi):
    """B, (w2, w3), (e2, e3) at omega = 1 in mpmath from the floats given."""
    ox, oy, cx, cy, r, l2, l3, phi = map(mp.mpf, (ox, oy, cx, cy, r, l2, l3, phi))
    ax, ay = ox + r * mp.cos(phi), oy + r * mp.sin(phi)
    dx, dy = cx - ax, cy - ay
    d = mp.sqrt(dx * dx + dy * dy)
    ux, uy = dx / d, dy / d
    pa = (d * d + l2 * l2 - l3 * l3) / (2 * d)
    h = mp.sqrt(l2 * l2 - pa * pa)
    bx, by = ax + pa * ux - h * uy, ay + pa * uy + h * ux        # left of A->C
    r2 = (bx - ax, by - ay)
    r3 = (bx - cx, by - cy)
    va = (-r * mp.sin(phi), r * mp.cos(phi))
    aa = (-r * mp.cos(phi), -r * mp.sin(phi))
    M = mp.matrix([[-r2[1], r3[1]], [r2[0], -r3[0]]])
    w = mp.lu_solve(M, mp.matrix([-va[0], -va[1]]))
    rhs = mp.matrix([-aa[0] - w[1] ** 2 * r3[0] + w[0] ** 2 * r2[0],
                     -aa[1] - w[1] ** 2 * r3[1] + w[0] ** 2 * r2[1]])
    e = mp.lu_solve(M, rhs)
    return (bx, by), (w[0], w[1]), (e[0], e[1])


def errors(m_args, res, ref):
    """The normwise relative errors of B, (w2 l2, w3 l3), (e2 l2, e3 l3)."""
    (ox, oy, cx, cy, r, l2, l3) = m_args
    B = res.position("B")
    eb = math.hypot(float(B[0] - ref[0][0]), float(B[1] - ref[0][1])) / l2
    out = [eb]
    for got, want in (((res.omega("A", "B"), res.omega("C", "B")), ref[1]),
                      ((res.epsilon("A", "B"), res.epsilon("C", "B")), ref[2])):
        dv = math.hypot(float((got[0] - want[0]) * l2), float((got[1] - want[1]) * l3))
        nv = max(float(mp.sqrt((want[0] * l2) ** 2 + (want[1] * l3) ** 2)), r)
        out.append(dv / nv)
    return max(out)


def solve(m, phi):
    """status, digits stated (None: OK), or None when the solve raised."""
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        try:
            res = m.solve(phi, need="accelerations")
        except (sarkp.SingularError, sarkp.AssemblyError):
            return None, None
    digits = [w.message.digits for w in rec if isinstance(w.message,
                                                         sarkp.SignificanceWarning)]
    return res, (digits[0] if digits else None)


@st.composite
def fourbars(draw):
    r = draw(st.floats(0.05, 1.0))
    c = draw(st.floats(0.5, 2.0))
    l2 = draw(st.floats(0.3, 2.5))
    l3 = draw(st.floats(0.3, 2.5))
    # a position: random, or near one of the four toggles (d = l2 + l3 or |l2 - l3|)
    toggles = []
    for D in (l2 + l3, abs(l2 - l3)):
        cosphi = (c * c + r * r - D * D) / (2 * c * r)
        if abs(cosphi) < 1:
            toggles += [math.acos(cosphi), -math.acos(cosphi)]
    near = draw(st.booleans()) and toggles
    if near:
        t = draw(st.sampled_from(toggles))
        phi = t + draw(st.sampled_from([-1, 1])) * 10.0 ** -draw(st.integers(2, 12))
    else:
        phi = draw(st.floats(-math.pi, math.pi))
    k = draw(st.integers(-30, 30))
    off = draw(st.sampled_from([0.0, 1.0, 1e3, 1e6]))
    return r, c, l2, l3, phi, k, off


@settings(max_examples=150, derandomize=True, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(fourbars())
def test_status_ok_means_eight_digits_and_digits_are_never_too_many(case):
    r, c, l2, l3, phi, k, off = case
    m = fourbar(r, c, l2, l3, off=(off, off))
    res, digits = solve(m, phi)
    if res is None:
        return
    if res.status != 0 and digits is None:
        return                             # failed with on_error: nothing promised
    err = errors((off, off, off + c, off, r, l2, l3), res,
                 reference(off, off, off + c, off, r, l2, l3, phi))
    if digits is None:
        assert err <= 1e-8, (case, err)
    else:
        assert err <= 10.0 ** -digits, (case, err, digits)


@settings(max_examples=100, derandomize=True, deadline=None)
@given(fourbars())
def test_statuses_and_digits_are_the_same_at_every_scale(case):
    r, c, l2, l3, phi, k, _ = case
    a, da = solve(fourbar(r, c, l2, l3), phi)
    b, db = solve(fourbar(r, c, l2, l3, scale=2.0 ** k), phi)
    assert (a is None) == (b is None), case
    if a is None:
        return
    assert a.status == b.status and da == db, (case, da, db)
    # and the results scale exactly
    np.testing.assert_array_equal(b.position("B"), a.position("B") * 2.0 ** k)
    assert b.epsilon("C", "B") == a.epsilon("C", "B")


def test_the_issue_reproducers():
    """Issue 25's cases: the same digits at f = 2**-10, 1, 2**10; the velocity error in
    the acceleration estimate; rounding far from the origin."""
    args = (0.49604743398254036, 1.0, 0.9083227042043158, 1.4122752701032877)
    stated = {solve(fourbar(*args, scale=f), 1e-4)[1] for f in (2.0 ** -10, 1.0, 2.0 ** 10)}
    assert len(stated) == 1
    for phi, off in ((1e-4, 0.0), (1e-3, 0.0), (0.01, 1e6)):
        res, digits = solve(fourbar(*args, off=(off, off)), phi)
        if res is None:
            continue                       # no digit promised: nothing to check
        err = errors((off, off, off + 1.0, off, args[0], args[2], args[3]), res,
                     reference(off, off, off + 1.0, off, args[0], args[2], args[3], phi))
        bound = 1e-8 if digits is None else 10.0 ** -digits
        assert err <= bound, (phi, off, err, digits)


@pytest.mark.parametrize("k", [-600, -300, 300, 600])
def test_far_scales_solve_exactly_scaled(k):
    """A four-bar of 2**600 m (or 2**-600 m) is the same mechanism: its statuses are the
    same and its results scale exactly (no det over- or underflowing into a RangeError or
    a SingularError; issue 27)."""
    phi = np.linspace(0.0, 2 * math.pi, 13)
    base = fourbar(0.1, 0.3, 0.35, 0.3)
    big = fourbar(0.1, 0.3, 0.35, 0.3, scale=2.0 ** k)
    for m in (base, big):
        m.mass("A", "B", mass=2.0, inertia=0.0, centre=0.1 * 2.0 ** (k if m is big else 0))
    # the forces' moments scale as 2**(2k): within range for |k| = 300 only (at 600
    # the balancing moment itself is out of the range of doubles)
    need = "forces" if abs(k) <= 300 else "accelerations"
    a = base.solve(phi, omega=3.0, epsilon=1.0, need=need)
    b = big.solve(phi, omega=3.0, epsilon=1.0, need=need)
    np.testing.assert_array_equal(a.status, b.status)
    if need == "forces":
        np.testing.assert_array_equal(b.reaction("B"), a.reaction("B") * 2.0 ** k)
        np.testing.assert_array_equal(b.balancing_moment, a.balancing_moment * 4.0 ** k)
    for name in ("A", "B"):
        np.testing.assert_array_equal(b.position(name), a.position(name) * 2.0 ** k)
        np.testing.assert_array_equal(b.velocity(name), a.velocity(name) * 2.0 ** k)
        np.testing.assert_array_equal(b.acceleration(name), a.acceleration(name) * 2.0 ** k)
    np.testing.assert_array_equal(b.epsilon("C", "B"), a.epsilon("C", "B"))


def test_a_size_out_of_range_raises_range_error():
    m = fourbar(0.1, 0.3, 0.35, 0.3, scale=1e300)
    with pytest.raises(sarkp.RangeError, match="overflows"):
        m.solve([0.3, 1.0], omega=1e10)
    m.mass("A", "B", mass=1.0)
    with pytest.raises(sarkp.RangeError, match="overflows"):     # M_b ~ 1e600
        m.solve([0.3, 1.0], need="forces")


@pytest.mark.parametrize("t2", [1e-8, 1e-10, 0.3, -2.0])
def test_rpp_small_slot_angle_keeps_its_digits(t2):
    """rpp (kind 5) with the slot nearly along the guide: K = A + s2 um, C = K + s3 us
    solved in the guide's frame as DPRM5/DKNMA5 do, so T2 = 1e-8 keeps every digit
    (issue 25: SingularError at need="velocities" before).  Reference: the same equations
    in mpmath, K's velocity and acceleration d2 um, d2' um with the crank at omega = 1."""
    fim = 0.4
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("A", -1.0, 0.5)
    m.crank("C", "O", 0.3)
    m.rpp("K", "A", fim, "C", t2)
    phi = np.linspace(0.1, 6.0, 7)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = m.solve(phi, need="accelerations")
    assert np.all(r.status == 0)
    um = (mp.cos(fim), mp.sin(fim))
    nm = (-um[1], um[0])
    for i, p in enumerate(phi):
        p = mp.mpf(p)
        c = (0.3 * mp.cos(p) + 1, 0.3 * mp.sin(p) - mp.mpf(0.5))        # C - A
        vc = (-0.3 * mp.sin(p), 0.3 * mp.cos(p))
        ac = (-0.3 * mp.cos(p), -0.3 * mp.sin(p))
        out = []
        for b in (c, vc, ac):
            s3 = (b[0] * nm[0] + b[1] * nm[1]) / mp.sin(t2)
            out.append((b[0] * um[0] + b[1] * um[1]) - s3 * mp.cos(t2))
        for got, s, base in ((r.position("K")[i], out[0], (-1.0, 0.5)),
                             (r.velocity("K")[i], out[1], (0, 0)),
                             (r.acceleration("K")[i], out[2], (0, 0))):
            want = [base[0] + s * um[0], base[1] + s * um[1]]
            scale = max(abs(s), 1.0)
            assert max(abs(float(got[0] - want[0])), abs(float(got[1] - want[1]))) \
                <= 1e-14 * scale, (t2, i)
