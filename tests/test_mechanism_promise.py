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

The slider groups the same way: rrp (a slider-crank with an offset guide at any angle)
and rpr (an inverted slider-crank, A at h from link 3's axis), their positions in closed
form and their velocities and accelerations by differentiating it, in mpmath; B relative
to the rod (rrp) or to |C - B| (rpr), the group's vectors (w l, s') and (e l, s'')
relative to the larger of their norm and the crank's speed; statuses and digits the
same when scaled by 2**k and when moved off the origin.
"""

import math
import random
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


# -- the slider groups: rrp (slider-crank with offset) and rpr (inverted slider-crank) --

def slider_crank(r, kx, ky, angle, l2, offset, scale=1.0, off=0.0):
    """Crank O-A (O at the origin), rrp slider B on the frame guide through K."""
    m = sarkp.Mechanism()
    m.fixed("O", off, off)
    m.fixed("K", off + kx * scale, off + ky * scale)
    m.crank("A", "O", r * scale)
    m.rrp("B", "A", "K", angle, l2 * scale, branch=1, offset=offset * scale)
    return m


def inverted(r, c, h, scale=1.0, off=0.0):
    """Crank O-A, rpr: link 3 turns about C = (c, 0), A at h from its axis."""
    m = sarkp.Mechanism()
    m.fixed("O", off, off)
    m.fixed("C", off + c * scale, off)
    m.crank("A", "O", r * scale)
    m.rpr("B", "A", "C", h * scale, math.pi / 2, branch=1)
    return m


def crank_point(o, r, phi):
    """A, A', A'' at omega = 1 in mpmath."""
    c, s = mp.cos(phi), mp.sin(phi)
    return ((o[0] + r * c, o[1] + r * s), (-r * s, r * c), (-r * c, -r * s))


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def rrp_reference(o, k, r, angle, l2, offset, phi):
    """B = K + s u + offset n, |B - A| = l2, s ahead of A's foot; (w2 l2, s') and
    (e2 l2, s'') by differentiating h h' = g a_n' (h = s - a_u, g = offset - a_n)."""
    o, k = [tuple(map(mp.mpf, p)) for p in (o, k)]
    r, angle, l2, offset, phi = map(mp.mpf, (r, angle, l2, offset, phi))
    u = (mp.cos(angle), mp.sin(angle))
    n = (-u[1], u[0])
    A, A1, A2 = crank_point(o, r, phi)
    rel = (A[0] - k[0], A[1] - k[1])
    au, an = dot(rel, u), dot(rel, n)
    au1, an1, au2, an2 = dot(A1, u), dot(A1, n), dot(A2, u), dot(A2, n)
    g = offset - an
    h = mp.sqrt(l2 * l2 - g * g)
    s = au + h
    h1 = g * an1 / h
    h2 = (-an1 * an1 + g * an2 - h1 * h1) / h
    B = (k[0] + s * u[0] + offset * n[0], k[1] + s * u[1] + offset * n[1])
    rod = (h * u[0] + g * n[0], h * u[1] + g * n[1])            # B - A
    rod1 = (h1 * u[0] - an1 * n[0], h1 * u[1] - an1 * n[1])
    rod2 = (h2 * u[0] - an2 * n[0], h2 * u[1] - an2 * n[1])
    w2 = (rod[0] * rod1[1] - rod[1] * rod1[0]) / (l2 * l2)
    e2 = (rod[0] * rod2[1] - rod[1] * rod2[0]) / (l2 * l2)
    v, a = (w2 * l2, au1 + h1), (e2 * l2, au2 + h2)
    return B, v + (v,), a + (a,)


def rpr_reference(o, cpt, r, h, phi):
    """B the foot of A on link 3's axis through C, on the left of A->C; A = C + s e +
    hs n_e differentiated for (w3 s, s') and (e3 s, s'')."""
    # digits enough for |A - C| near 0 (A passing by the pivot)
    d0 = math.hypot(cpt[0] - o[0] - r * math.cos(phi), cpt[1] - o[1] - r * math.sin(phi))
    with mp.workdps(40 + max(0, int(-math.log10(max(d0, 1e-300))))):
        return _rpr_reference(o, cpt, r, h, phi)


def _rpr_reference(o, cpt, r, h, phi):
    o, cpt = [tuple(map(mp.mpf, p)) for p in (o, cpt)]
    r, h, phi = map(mp.mpf, (r, h, phi))
    A, A1, A2 = crank_point(o, r, phi)
    ac = (cpt[0] - A[0], cpt[1] - A[1])
    d = mp.sqrt(dot(ac, ac))
    u = (ac[0] / d, ac[1] / d)
    nu = (-u[1], u[0])
    s = mp.sqrt(d * d - h * h)
    B = (A[0] + h * h / d * u[0] + h * s / d * nu[0], A[1] + h * h / d * u[1] + h * s / d * nu[1])
    e = ((B[0] - cpt[0]) / s, (B[1] - cpt[1]) / s)
    ne = (-e[1], e[0])
    hs = dot((A[0] - cpt[0], A[1] - cpt[1]), ne)
    t1 = dot(A1, ne) / s
    s1 = dot(A1, e) + hs * t1
    t2 = (dot(A2, ne) - (2 * s1 - hs * t1) * t1) / s
    s2 = dot(A2, e) + hs * t2 + s * t1 * t1
    # the group's vectors (w3 s, s'), (e3 s, s''); B's velocity and acceleration along
    # the axis: s', s'' - s w3**2
    return B, (t1 * s, s1, (t1 * s, s1)), (t2 * s, s2 - s * t1 * t1, (t2 * s, s2)), \
        (s * e[0], s * e[1])


def check_slider(m, phi, r, ref, length, link, along):
    """The promise at one position: OK within 1e-8, stated digits never too many.  B
    relative to ``length``; w l and B's velocity along ``along``, the same for the
    accelerations, relative to the larger of the group's vector (w l, s') or (e l, s'')
    and the crank's speed r (omega = 1)."""
    res, digits = solve(m, phi)
    if res is None or (res.status != 0 and digits is None):
        return None
    B = res.position("B")
    err = [math.hypot(float(B[0] - ref[0][0]), float(B[1] - ref[0][1])) / float(length)]
    for got_w, got_v, want in ((res.omega(*link), res.velocity("B"), ref[1]),
                               (res.epsilon(*link), res.acceleration("B"), ref[2])):
        got_s = float(got_v[0] * along[0] + got_v[1] * along[1])
        dv = math.hypot(float(got_w * length - want[0]), float(got_s - want[1]))
        nv = max(float(mp.sqrt(want[2][0] ** 2 + want[2][1] ** 2)), r)
        err.append(dv / nv)
    bound = 1e-8 if digits is None else 10.0 ** -digits
    assert max(err) <= bound, (max(err), digits)
    return res.status, digits


def near(draw, toggles):
    """A random crank angle, or one 1e-2 .. 1e-12 from a toggle."""
    if toggles and draw(st.booleans()):
        t = draw(st.sampled_from(toggles))
        return t + draw(st.sampled_from([-1, 1])) * 10.0 ** -draw(st.integers(2, 12))
    # normal numbers only: a subnormal result does not scale exactly by 2**k
    return draw(st.floats(-math.pi, math.pi, allow_subnormal=False))


@st.composite
def slider_cranks(draw):
    r = draw(st.floats(0.05, 1.0))
    kx, ky = draw(st.floats(-1.0, 1.0)), draw(st.floats(-1.0, 1.0))
    angle = draw(st.floats(-math.pi, math.pi, allow_subnormal=False))
    offset = draw(st.floats(-0.5, 0.5))
    # toggles: A's distance from the guide's axis a_n = offset +- l2, with
    # a_n = c0 + r cos(phi - beta), beta the normal's angle
    beta = angle + math.pi / 2
    c0 = -kx * math.cos(beta) - ky * math.sin(beta)
    l2 = draw(st.floats(0.3, 2.5))
    if draw(st.booleans()):                 # a rod that has a toggle at phi = psi
        psi = draw(st.floats(-math.pi, math.pi))
        l2 = max(abs(offset - c0 - r * math.cos(psi - beta)), 0.05)
    toggles = []
    for an in (offset + l2, offset - l2):
        cos = (an - c0) / r
        if abs(cos) < 1:
            toggles += [beta + math.acos(cos), beta - math.acos(cos)]
    return r, kx, ky, angle, l2, offset, near(draw, toggles)


@st.composite
def inverted_cranks(draw):
    r = draw(st.floats(0.05, 1.0))
    c = draw(st.floats(0.3, 2.0))
    # h below |c - r| always assembles; in [|c - r|, c + r] it has toggles (s = 0)
    h = draw(st.one_of(st.floats(0.0, 0.9 * abs(c - r)),
                       st.floats(abs(c - r), c + r)))
    cos = (c * c + r * r - h * h) / (2 * c * r)
    toggles = [math.acos(cos), -math.acos(cos)] if abs(cos) < 1 else []
    return r, c, h, near(draw, toggles)


SLIDER = dict(max_examples=60, derandomize=True, deadline=None,
              suppress_health_check=[HealthCheck.too_slow])


def rrp_case(case, scale=1.0, off=0.0):
    r, kx, ky, angle, l2, offset, phi = case
    m = slider_crank(r, kx, ky, angle, l2, offset, scale, off)
    ref = rrp_reference((off, off), (off + kx, off + ky), r, angle, l2, offset, phi)
    return m, phi, r, ref, l2, ("A", "B"), (math.cos(angle), math.sin(angle))


def rpr_case(case, scale=1.0, off=0.0):
    r, c, h, phi = case
    m = inverted(r, c, h, scale, off)
    ref = rpr_reference((off, off), (off + c, off), r, h, phi)
    cb = ref[3]                                                 # B - C, along link 3
    length = float(mp.sqrt(cb[0] ** 2 + cb[1] ** 2))
    e = (float(cb[0] / length), float(cb[1] / length))
    return m, phi, r, ref, length, ("C", "B"), e


@settings(**SLIDER)
@given(slider_cranks(), st.sampled_from([0.0, 1.0, 1e3]))
def test_rrp_status_ok_means_eight_digits(case, off):
    r, kx, ky, angle, l2, offset, phi = case
    if abs(offset - ((math.cos(phi) * r - kx) * -math.sin(angle)
                     + (math.sin(phi) * r - ky) * math.cos(angle))) >= l2:
        return                              # does not assemble
    check_slider(*rrp_case(case, off=off))


@settings(**SLIDER)
@given(inverted_cranks(), st.sampled_from([0.0, 1.0, 1e3]))
def test_rpr_status_ok_means_eight_digits(case, off):
    r, c, h, phi = case
    if math.hypot(c - r * math.cos(phi), r * math.sin(phi)) <= h:
        return                              # does not assemble
    check_slider(*rpr_case(case, off=off))


@settings(**SLIDER)
@given(st.one_of(slider_cranks(), inverted_cranks()), st.integers(-30, 30),
       st.sampled_from([0.5, 1.0, 1e3]))
def test_slider_statuses_are_the_same_at_every_scale_and_offset(case, k, off):
    """Scaled by 2**k: the same statuses and digits, the results scaled exactly; moved
    by an offset: the same statuses and digits."""
    build = (lambda sc, o: slider_crank(*case[:6], sc, o)) if len(case) == 7 else \
        (lambda sc, o: inverted(*case[:3], sc, o))
    phi = case[-1]
    a, da = solve(build(1.0, 0.0), phi)
    b, db = solve(build(2.0 ** k, 0.0), phi)
    c, dc = solve(build(1.0, off), phi)
    assert (a is None) == (b is None) == (c is None), case
    if a is None:
        return
    assert a.status == b.status == c.status and da == db == dc, (case, da, db, dc)
    np.testing.assert_array_equal(b.position("B"), a.position("B") * 2.0 ** k)
    np.testing.assert_array_equal(b.acceleration("B"), a.acceleration("B") * 2.0 ** k)


def test_dead_centre_is_singular_at_every_need():
    """The fuzz's find: an rrp one part in 1e213 from its toggle (guide angle 5.5e-213,
    the rod square to the guide at phi = 0) has velocities ~1e212 whose estimate leaves
    no digit (SingularError at need="velocities"); at need="accelerations" their squares
    overflowed and the position raised RangeError ("a result overflows") -- a dead
    centre reported as an overflow.  Now SingularError at both needs."""
    m = slider_crank(1.0, 0.0, 0.0, 5.544778607073185e-213, 0.5, 0.5)
    for need in ("velocities", "accelerations"):
        with pytest.raises(sarkp.SingularError, match="dead centre"):
            m.solve(0.0, need=need)
    r = m.solve([0.0, 1.0], need="accelerations", on_error="nan")
    assert list(r.status) == [sarkp.Status.SINGULAR, sarkp.Status.OK]


def test_rpr_near_its_pivot_at_the_origin():
    """The case below at the origin: within the promise."""
    assert check_slider(*rpr_case((1.0, 1.0, 0.0, 0.001953125), off=0.0)) == (0, None)


def test_rpr_near_its_pivot_far_from_the_origin():
    """The fuzz's find: an inverted slider-crank with r = c = 1, h = 0 (A passes through
    the pivot C at phi = 0), at phi = 2**-9 (|C - B| = 0.00195) and moved to (1e3, 1e3):
    (e3 s, s'') is off by 1.99e-8 of the crank's acceleration (the position 2.8e-11 of s,
    the velocities 1.9e-11), which the rpr kernel called OK: its estimate left out the
    rounding of A's and C's coordinates in A - C (link 3's direction, and w3**2 (A - C)
    in the accelerations).  Now it warns (5 digits); at the origin the same case is OK."""
    status, digits = check_slider(*rpr_case((1.0, 1.0, 0.0, 0.001953125), off=1000.0))
    assert status == sarkp.Status.SIGNIFICANCE and digits is not None


def digits_left(m, phi):
    """The digits a solve states: 16 for OK, 0 when it raises SingularError."""
    res, digits = solve(m, phi)
    return 0 if res is None else (16 if digits is None else digits)


@pytest.mark.parametrize("phi", [2.0 ** -23, 1.3e-7, 1e-5])
def test_rpr_near_its_pivot_digits_when_moved(phi):
    """r = c = 1, h = 0 with A 1e-7 .. 1e-5 from the pivot C: honest at the origin and
    moved to (1e3, 1e3); the same digits at the scale 2**7; moved, never
    more digits than at the origin.  (Moved, A's coordinates round 1e3 times worse: at
    phi = 2**-23 B's acceleration keeps no correct digit there -- error 1.0 against
    mpmath -- where the kernel used to state 7 digits, one more than at the origin.)"""
    case = (1.0, 1.0, 0.0, phi)
    for off in (0.0, 1000.0):
        check_slider(*rpr_case(case, off=off))
    here = digits_left(inverted(*case[:3]), phi)
    assert digits_left(inverted(*case[:3], scale=2.0 ** 7), phi) == here
    assert digits_left(inverted(*case[:3], off=1000.0), phi) <= here


@pytest.mark.parametrize("seed", range(3))
def test_rpr_through_its_pivot_is_honest_anywhere(seed):
    """Seeded inverted slider-cranks whose A passes through the pivot (r = c, h = 0), at
    1e-1 .. 1e-9 rad from it, at the origin, at (1, 1) and at (1e3, 1e3): OK within
    1e-8, stated digits never too many (the fuzz that found the two cases above: 273
    violations in 900 such checks before the kernel allowed for the coordinates'
    rounding, none after in 1800)."""
    rng = random.Random(seed)
    for _ in range(10):
        r = rng.uniform(0.05, 1.0)
        phi = rng.choice([-1, 1]) * 10.0 ** -rng.uniform(1, 9)
        for off in (0.0, 1.0, 1e3):
            check_slider(*rpr_case((r, r, 0.0, phi), off=off))
