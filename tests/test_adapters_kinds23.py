"""Kinds 2 and 3 (RRP, RPR): one home each (issue 25).  fortran/groups.f90's rrp and rpr
stages serve sarkp.Mechanism (rrp_kernel, rpr_kernel) and the book's DPRM2/3, DSKOR2/3,
DUSKR2/3, DKNMA2/3 in corrected mode.

Pinned here:
- the kernels at any scale: a mechanism scaled by 2**k solves to the same bits times 2**k
  from k = -990 to 900 (the velocity and acceleration systems have unit-vector columns;
  with a length column a slider-crank of 2**600 m raised RangeError and a guide on a
  moving link at 2**-990 m lost its sliding velocity to underflow: E2 1.2% wrong);
- far from the origin: B - A formed from the group's own quantities, so that w2, e2 and
  B's motion keep their digits at 1e6 m (they lost about 1e-10 relative);
- the values against independent references: each group's position in closed form in
  mpmath (40 digits) from the same binary inputs moving on their Taylor paths in time,
  velocities and accelerations as mpmath's numerical derivatives of it;
- the book's routines (corrected mode) and a one-group Mechanism fed the same data give
  the same bits; as printed, the routines keep their own code.
"""

import math
import warnings

import mpmath as mp
import numpy as np
import pytest

import sarkp

mp.mp.dps = 40
TOL = 1e-13


def _mpv(p):
    return (mp.mpf(p[0]), mp.mpf(p[1]))


def _path(x, v, a):
    """x + v t + a t**2/2, componentwise (mp)."""
    x, v, a = _mpv(x), _mpv(v), _mpv(a)
    return lambda t: (x[0] + v[0] * t + a[0] * t * t / 2, x[1] + v[1] * t + a[1] * t * t / 2)


def rrp_motion(A, K, th, l2, off, branch):
    """The RRP group in closed form, for inputs moving in time: A = (x, v, a) of the rod's
    outer joint, K = (x, v, a) of a point of the guide, th = (angle, omega, epsilon) of
    the guide.  Returns f(t) = (Bx, By, angle of B - A, s) with B = K + s u + off n on
    the guide, |B - A| = l2, ahead of (branch +1) or behind the foot from A."""
    pa, pk = _path(*A), _path(*K)
    l2, off = mp.mpf(l2), mp.mpf(off)
    th = [mp.mpf(x) for x in th]

    def f(t):
        a, k = pa(t), pk(t)
        g = th[0] + th[1] * t + th[2] * t * t / 2
        u, n = (mp.cos(g), mp.sin(g)), (-mp.sin(g), mp.cos(g))
        p = (k[0] + off * n[0] - a[0], k[1] + off * n[1] - a[1])   # K + off n - A
        pu = p[0] * u[0] + p[1] * u[1]
        s = -pu + branch * mp.sqrt(pu * pu - (p[0] ** 2 + p[1] ** 2 - l2 * l2))
        b = (k[0] + off * n[0] + s * u[0], k[1] + off * n[1] + s * u[1])
        return (b[0], b[1], mp.atan2(b[1] - a[1], b[0] - a[0]), s)
    return f


def rpr_motion(A, C, h, branch):
    """The RPR group in closed form: link 3 turns about C = (x, v, a); A = (x, v, a) at
    |h| from its axis; B the foot of A on the axis, on the left (branch +1) of A->C.
    f(t) = (Bx, By, angle of C->B, |CB|)."""
    pa, pc = _path(*A), _path(*C)
    h = abs(mp.mpf(h))

    def f(t):
        a, c = pa(t), pc(t)
        d = mp.sqrt((c[0] - a[0]) ** 2 + (c[1] - a[1]) ** 2)
        u = ((c[0] - a[0]) / d, (c[1] - a[1]) / d)
        n = (-u[1], u[0])
        sq = h / d
        cq = mp.sqrt(1 - sq * sq)
        b = (a[0] + h * sq * u[0] + branch * h * cq * n[0],
             a[1] + h * sq * u[1] + branch * h * cq * n[1])
        return (b[0], b[1], mp.atan2(b[1] - c[1], b[0] - c[0]), d * cq)
    return f


def derivs(f):
    """Values, first and second time derivatives at t = 0 (floats)."""
    k = len(f(mp.mpf(0)))
    return [np.array([float(mp.diff(lambda t, j=j: f(t)[j], mp.mpf(0), n)) for j in range(k)])
            for n in (0, 1, 2)]


# -- the Mechanism --------------------------------------------------------------------------

W, E = 10.0, -3.0
PHI = np.array([-2.7, -1.1, 0.3, 0.9, 2.2])


def slider_crank(scale=1.0, off=0.0):
    """Crank O-A, rod A-B, B on a frame guide through K at 0.3 rad, offset 0.015."""
    m = sarkp.Mechanism()
    m.fixed("O", off, off)
    m.fixed("K", off + 0.05 * scale, off + 0.02 * scale)
    m.crank("A", "O", 0.1 * scale)
    m.rrp("B", "A", "K", 0.3, 0.4 * scale, branch=1, offset=0.015 * scale)
    return m


def moving_guide(scale=1.0, off=0.0):
    """A guide carried by the crank O-A (through A, at 0.4 rad to it); the rod F-E from
    a frame pivot F slides E on it at offset 0.02 (the guide turns: Coriolis)."""
    m = sarkp.Mechanism()
    m.fixed("O", off, off)
    m.fixed("F", off + 0.3 * scale, off + 0.1 * scale)
    m.crank("A", "O", 0.1 * scale)
    m.rrp("E", "F", "A", 0.4, 0.5 * scale, branch=1, offset=0.02 * scale, guide=("O", "A"))
    return m


def inverted(scale=1.0, off=0.0):
    """Crank O-A, link 3 about C; A at 0.05 from its axis (an inverted slider-crank)."""
    m = sarkp.Mechanism()
    m.fixed("O", off, off)
    m.fixed("C", off, off - 0.25 * scale)
    m.crank("A", "O", 0.1 * scale)
    m.rpr("B", "A", "C", 0.05 * scale, 1.2, branch=1)
    return m


def _outputs(r, point, link):
    return [r.position(point), r.velocity(point), r.acceleration(point),
            r.omega(*link), r.epsilon(*link), r.status]


CASES = [(slider_crank, "B", ("A", "B")), (moving_guide, "E", ("F", "E")),
         (inverted, "B", ("C", "B"))]


@pytest.mark.parametrize("build, point, link", CASES)
@pytest.mark.parametrize("k", [-990, -600, -300, -30, 30, 300, 600, 900])
def test_the_mechanism_scales_exactly(build, point, link, k):
    """Scaled by 2**k: lengths, velocities and accelerations scale to the bit, angles,
    omega and epsilon and the statuses stay (before: RangeError at 2**600 for the rrp;
    the moving guide's E2 1.2% wrong at 2**-990)."""
    one = _outputs(build().solve(PHI, omega=W, epsilon=E), point, link)
    far = _outputs(build(2.0 ** k).solve(PHI, omega=W, epsilon=E), point, link)
    for j in range(3):
        np.testing.assert_array_equal(far[j], one[j] * 2.0 ** k)
    for j in range(3, 6):
        np.testing.assert_array_equal(far[j], one[j])


def _group_inputs(r, i, names):
    return [(r.position(n)[i], r.velocity(n)[i], r.acceleration(n)[i]) for n in names]


@pytest.mark.parametrize("off", [0.0, 1e6])
def test_the_mechanisms_rrp_against_the_closed_form(off):
    """The slider-crank and the moving guide: B's motion, w2 and e2 against the closed
    form fed the group's own binary inputs (A from the crank; the guide's point and
    angle from the four-bar), at the origin and 1e6 m from it (where B - A formed as a
    difference of coordinates lost ~1e-10 relative)."""
    for build, rod in ((slider_crank, ("A", "B")), (moving_guide, ("F", "E"))):
        m = build(off=off)
        r = m.solve(PHI, omega=W, epsilon=E)
        assert np.all(r.status == 0)
        for i in range(PHI.size):
            A, K = _group_inputs(r, i, [rod[0], "A" if build is moving_guide else "K"])
            if build is slider_crank:
                th, l2, offset = (0.3, 0.0, 0.0), 0.4, 0.015
            else:                                   # the crank's angle, omega, epsilon
                th, l2, offset = (PHI[i] + 0.4, W, E), 0.5, 0.02
            x, v, a = derivs(rrp_motion(A, K, th, l2, offset, 1))
            vs, as_ = np.max(np.abs(v[:2])), np.max(np.abs(a[:2]))
            # B itself is a coordinate of size |off|: half an ulp of it is its rounding
            point = rod[1]
            assert np.max(np.abs(r.position(point)[i] - x[:2])) <= TOL * l2 + np.spacing(off)
            assert np.max(np.abs(r.velocity(point)[i] - v[:2])) <= TOL * vs
            assert np.max(np.abs(r.acceleration(point)[i] - a[:2])) <= TOL * as_
            assert abs(r.omega(*rod)[i] - v[2]) * l2 <= TOL * vs
            assert abs(r.epsilon(*rod)[i] - a[2]) * l2 <= TOL * as_


@pytest.mark.parametrize("off", [0.0, 1e6])
def test_the_mechanisms_rpr_against_the_closed_form(off):
    m = inverted(off=off)
    r = m.solve(PHI, omega=W, epsilon=E)
    for i in range(PHI.size):
        (A,) = _group_inputs(r, i, ["A"])
        C = ((off, off - 0.25), (0.0, 0.0), (0.0, 0.0))
        x, v, a = derivs(rpr_motion(A, C, 0.05 * math.sin(1.2), 1))
        vs, as_ = np.max(np.abs(v[:2])), np.max(np.abs(a[:2]))
        # far off, the estimate allows for the rounding of A's and C's coordinates
        assert r.status[i] == 0 or off and r.status[i] == sarkp.Status.SIGNIFICANCE
        assert np.max(np.abs(r.position("B")[i] - x[:2])) <= TOL * 0.25 + np.spacing(off)
        assert np.max(np.abs(r.velocity("B")[i] - v[:2])) <= TOL * vs
        assert np.max(np.abs(r.acceleration("B")[i] - a[:2])) <= TOL * as_
        assert abs(r.omega("C", "B")[i] - v[2]) * x[3] <= TOL * vs
        assert abs(r.epsilon("C", "B")[i] - a[2]) * x[3] <= TOL * as_


# -- the book's kind-2 routines (corrected mode) ---------------------------------------------

def _dknma2_case(rng):
    """Random DKNMA2 inputs: A on the left of a guide through K at fim, a moving guide
    (its point under B moving as (VBM, ALBM), (ABM, BBM), turning at WM)."""
    fim = rng.uniform(-3, 3)
    xk, yk = rng.uniform(-1, 1, 2)
    so, along = rng.uniform(0.05, 0.3), rng.uniform(-0.5, 0.5)
    xa = xk + along * math.cos(fim) - so * math.sin(fim)
    ya = yk + along * math.sin(fim) + so * math.cos(fim)
    off = rng.uniform(-0.05, 0.05)
    rz2 = abs(so - off) * rng.uniform(1.2, 3.0)
    return dict(xa=xa, ya=ya, xk=xk, yk=yk, fim=fim, rz2=rz2, rz3=abs(off),
                eta=math.copysign(math.pi / 2, off), va=rng.uniform(0, 2),
                ala=rng.uniform(-3, 3), wm=rng.uniform(-2, 2), vbm=rng.uniform(0, 1),
                albm=rng.uniform(-3, 3), aa=rng.uniform(0, 5), ba=rng.uniform(-3, 3),
                abm=rng.uniform(0, 2), bbm=rng.uniform(-3, 3), p=float(rng.choice([-1, 1])))


def _dknma2(c, scale=1.0, shift=0.0, analog=0.0):
    s = scale
    return sarkp.DKNMA2(c["xa"] * s + shift, c["ya"] * s + shift, c["xk"] * s + shift,
                        c["yk"] * s + shift, c["fim"], c["rz2"] * s, c["rz3"] * s, c["eta"],
                        c["va"] * s, c["ala"], c["wm"], c["vbm"] * s, c["albm"], c["aa"] * s,
                        c["ba"], c["abm"] * s, c["bbm"], c["p"], analog, on_error="nan")


def _dknma2_reference(c, shift=0.0):
    """The group in closed form: A moves as (VA, ALA), (AA, BA); the guide's link turns
    at WM and its point G under B (B at t = 0) moves as (VBM, ALBM), (ABM, BBM).  Then
    B = G(t) + s u(t) with s(0) = 0: the closed form with K = G and no offset (the
    link's angular acceleration, which DKNMA2 does not take, enters only through s u''
    and drops out at t = 0)."""
    pol = lambda m, t: (mp.mpf(m) * mp.cos(mp.mpf(t)), mp.mpf(m) * mp.sin(mp.mpf(t)))
    A = ((c["xa"] + shift, c["ya"] + shift), pol(c["va"], c["ala"]), pol(c["aa"], c["ba"]))
    off = c["rz3"] * mp.sin(mp.mpf(c["eta"]))
    K = ((c["xk"] + shift, c["yk"] + shift), (0, 0), (0, 0))
    b = rrp_motion((A[0], (0, 0), (0, 0)), K, (c["fim"], 0, 0), c["rz2"], off, c["p"])(0)
    G = ((b[0], b[1]), pol(c["vbm"], c["albm"]), pol(c["abm"], c["bbm"]))
    return rrp_motion(A, G, (c["fim"], c["wm"], 0), c["rz2"], 0, c["p"])


def test_dknma2_against_the_closed_form():
    rng = np.random.default_rng(25)
    checked = 0
    for _ in range(40):
        c = _dknma2_case(rng)
        k = _dknma2(c)
        if k.status != 0:
            continue
        x, v, a = derivs(_dknma2_reference(c))
        checked += 1
        vs = max(abs(v[2]) * c["rz2"], abs(v[3]), c["va"] + c["vbm"])
        as_ = max(abs(a[2]) * c["rz2"], abs(a[3]), c["aa"] + c["abm"])
        assert math.hypot(k.XB - x[0], k.YB - x[1]) <= TOL * c["rz2"]
        assert abs(math.remainder(k.FI2 - x[2], 2 * math.pi)) <= TOL
        assert abs(k.W2 - v[2]) * c["rz2"] <= TOL * vs
        assert abs(k.E2 - a[2]) * c["rz2"] <= TOL * as_
        # the sliding velocity and acceleration along the guide, as the book's pairs
        sv = k.VBBM * math.cos(k.ALBBM - c["fim"])
        sa = k.ABBM * math.cos(k.BBBM - c["fim"])
        assert abs(sv - v[3]) <= TOL * vs and abs(sa - a[3]) <= TOL * as_
        # the book's ranges and pairs: FI2 in (-pi, pi], ALBA = FI2 +- pi/2 by W2's sign
        assert -math.pi < k.FI2 <= math.pi
        assert k.ALBA == k.FI2 + math.copysign(math.pi / 2, k.W2)
        assert k.ALBBM in (c["fim"], c["fim"] - math.pi)
        assert k.ABK == pytest.approx(2 * k.VBBM * abs(c["wm"]), rel=1e-15)
    assert checked >= 30


@pytest.mark.parametrize("k", [-990, -600, -300, 300, 600, 900])
def test_dknma2_and_dprm2_scale_exactly(k):
    rng = np.random.default_rng(7)
    for _ in range(10):
        c = _dknma2_case(rng)
        one, far = _dknma2(c), _dknma2(c, 2.0 ** k)
        assert far.status == one.status
        for name in one._fields:
            got, want = getattr(far, name), getattr(one, name)
            if name == "status":
                continue
            if name in ("XB", "YB", "VBA", "VBBM", "VB", "ABAN", "ABK", "ABAT", "ABBM", "AB"):
                want = want * 2.0 ** k
            if name in ("VB", "AB"):
                # moduli: prmtr's norm2d takes hypot beyond 1e+-150 (its own rounding)
                assert abs(got - want) <= abs(np.spacing(want)), (name, got, want)
            else:
                assert got == want, (name, got, want)
        s = 2.0 ** k
        p1 = sarkp.DPRM2(c["xa"], c["ya"], c["xk"], c["yk"], c["fim"], c["rz2"], c["rz3"],
                         abs(c["eta"]), on_error="nan")
        p2 = sarkp.DPRM2(c["xa"] * s, c["ya"] * s, c["xk"] * s, c["yk"] * s, c["fim"],
                         c["rz2"] * s, c["rz3"] * s, abs(c["eta"]), on_error="nan")
        assert (p2.XB, p2.YB, p2.FI2, p2.status) == (p1.XB * s, p1.YB * s, p1.FI2, p1.status)


def test_dknma2_far_from_the_origin_keeps_its_digits():
    """1e6 m from the origin: W2, E2 and the sliding motion against the closed form of
    the same binary inputs (B - A from the group's own quantities)."""
    rng = np.random.default_rng(11)
    checked = 0
    for _ in range(20):
        c = _dknma2_case(rng)
        k = _dknma2(c, shift=1e6)
        if k.status != 0:
            continue
        checked += 1
        x, v, a = derivs(_dknma2_reference(c, shift=1e6))
        vs = max(abs(v[2]) * c["rz2"], abs(v[3]), c["va"] + c["vbm"])
        as_ = max(abs(a[2]) * c["rz2"], abs(a[3]), c["aa"] + c["abm"])
        assert math.hypot(k.XB - x[0], k.YB - x[1]) <= TOL * c["rz2"] + 2 * np.spacing(1e6)
        assert abs(k.W2 - v[2]) * c["rz2"] <= TOL * vs
        assert abs(k.E2 - a[2]) * c["rz2"] <= TOL * as_
    assert checked >= 15


def _polar_exact(x, y):
    """(modulus, direction) whose m*cos(a), m*sin(a) are x, y to the bit, or None."""
    a0 = math.atan2(y, x)
    for a in _around(a0):
        c, s = math.cos(a), math.sin(a)
        for m in set(_around(x / c, 3) + _around(y / s, 3)):
            if m * c == x and m * s == y:
                return m, a
    return None


def _around(t, k=6):
    up, down, out = t, t, [t]
    for _ in range(k):
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
        out += [up, down]
    return out


@pytest.mark.parametrize("branch", [1, -1])
def test_dknma2_and_the_mechanism_give_the_same_bits(branch):
    """A slider-crank on a frame guide: DKNMA2 fed the Mechanism's A (the velocity and
    acceleration as polar pairs whose components are the Mechanism's bits) gives its B,
    W2, E2 to the bit; DPRM2 (branch +1, A on the guide's left) its B."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", -0.2, -0.3)
    m.crank("A", "O", 0.1)
    m.rrp("B", "A", "K", 0.25, 0.45, branch=branch, offset=0.03)
    phi = np.linspace(-3.1, 3.1, 300)
    r = m.solve(phi)
    a, va, aa = r.position("A"), r.velocity("A"), r.acceleration("A")
    b, w2, e2 = r.position("B"), r.omega("A", "B"), r.epsilon("A", "B")
    compared = 0
    for i in range(phi.size):
        v, acc = _polar_exact(*va[i]), _polar_exact(*aa[i])
        if v is None or acc is None:
            continue
        k = sarkp.DKNMA2(a[i, 0], a[i, 1], -0.2, -0.3, 0.25, 0.45, 0.03, math.pi / 2,
                         v[0], v[1], 0.0, 0.0, 0.0, acc[0], acc[1], 0.0, 0.0, branch, 0.0,
                         on_error="nan")
        assert int(k.status) == int(r.status[i])
        assert (k.XB, k.YB, k.W2, k.E2) == (b[i, 0], b[i, 1], w2[i], e2[i])
        compared += 1
    assert compared >= 20
    if branch == 1:
        p = sarkp.DPRM2(a[:, 0], a[:, 1], -0.2, -0.3, 0.25, 0.45, 0.03, math.pi / 2)
        assert np.array_equal(p.XB, b[:, 0]) and np.array_equal(p.YB, b[:, 1])


def test_dskor2_duskr2_chain_against_the_closed_form():
    """DPRM2 -> DSKOR2 -> DUSKR2 (the book's sequence, IV.15) on a slider-crank with an
    offset: W2, E2, the sliding velocity and acceleration against the closed form."""
    r, xk, yk, fim, l2, off = 0.1, -0.2, -0.3, 0.25, 0.45, 0.03
    for phi in (-2.5, -0.7, 0.4, 1.9):
        A = ((r * math.cos(phi), r * math.sin(phi)), (-r * math.sin(phi), r * math.cos(phi)),
             (-r * math.cos(phi), -r * math.sin(phi)))
        x, v, a = derivs(rrp_motion(A, ((xk, yk), (0, 0), (0, 0)), (fim, 0, 0), l2, off, 1))
        p = sarkp.DPRM2(A[0][0], A[0][1], xk, yk, fim, l2, off, math.pi / 2, on_error="nan")
        s = sarkp.DSKOR2(r, phi + math.pi / 2, 0.0, 0.0, l2, p.FI2, fim, on_error="nan")
        u = sarkp.DUSKR2(r, phi + math.pi, 0.0, 0.0, 0.0, 0.0, l2, p.FI2, s.W2, fim,
                         on_error="nan")
        assert (p.status, s.status, u.status) == (0, 0, 0)
        assert abs(s.W2 - v[2]) * l2 <= TOL * r
        assert abs(s.VBBM * math.cos(s.ALBBM - fim) - v[3]) <= TOL * r
        assert abs(u.E2 - a[2]) * l2 <= TOL * r
        assert abs(u.ABVM * math.cos(u.BVBM - fim) - a[3]) <= TOL * r
        assert s.ALBA == p.FI2 + math.copysign(math.pi / 2, s.W2)
        assert u.VBAT == p.FI2 + math.copysign(math.pi / 2, u.E2)


def test_kind2_as_printed_keeps_the_books_code():
    """As printed, DKNMA2 keeps its own sequence (PI = 3.14159 in its directions): ALBA
    moves by about the 1.3e-6 of PID2 against corrected mode, B does not."""
    c = _dknma2_case(np.random.default_rng(3))
    corrected = _dknma2(c)
    with sarkp.as_printed():
        printed = _dknma2(c)
    assert math.hypot(printed.XB - corrected.XB, printed.YB - corrected.YB) < 1e-12
    assert 1e-7 < abs(printed.ALBA - corrected.ALBA) < 1e-5


# -- the book's kind-3 routines (corrected mode) ---------------------------------------------

def _dknma3_case(rng):
    xc, yc = rng.uniform(-1, 1, 2)
    d, psi = rng.uniform(0.2, 1.0), rng.uniform(-3, 3)
    eta = rng.uniform(0.3, 2.8) * rng.choice([-1, 1])
    rz2 = d * abs(math.sin(rng.uniform(0.05, 1.4))) / abs(math.sin(eta)) * 0.95
    return dict(xa=xc + d * math.cos(psi), ya=yc + d * math.sin(psi), xc=xc, yc=yc, rz2=rz2,
                eta=eta, va=rng.uniform(0, 2), ala=rng.uniform(-3, 3), vc=rng.uniform(0, 1),
                alc=rng.uniform(-3, 3), aa=rng.uniform(0, 5), ba=rng.uniform(-3, 3),
                ac=rng.uniform(0, 2), bc=rng.uniform(-3, 3), p=float(rng.choice([-1, 1])))


def _dknma3(c, scale=1.0, analog=0.0):
    s = scale
    return sarkp.DKNMA3(c["xa"] * s, c["ya"] * s, c["xc"] * s, c["yc"] * s, c["rz2"] * s,
                        c["eta"], c["va"] * s, c["ala"], c["vc"] * s, c["alc"], c["aa"] * s,
                        c["ba"], c["ac"] * s, c["bc"], c["p"], analog, on_error="nan")


def test_dknma3_against_the_closed_form():
    """Link 3's axis, W3, E3, the sliding of A3 along the axis and the book's B (angle
    ABC = ETA, AB = RZ2) against the closed form (DKNMA3's P is the kernel's branch for
    RZ2*SIN(ETA) > 0, its mirror below)."""
    rng = np.random.default_rng(33)
    pol = lambda m, t: (m * math.cos(t), m * math.sin(t))
    checked = 0
    for _ in range(40):
        c = _dknma3_case(rng)
        k = _dknma3(c)
        if k.status != 0:
            continue
        checked += 1
        h = c["rz2"] * math.sin(c["eta"])
        A = ((c["xa"], c["ya"]), pol(c["va"], c["ala"]), pol(c["aa"], c["ba"]))
        C = ((c["xc"], c["yc"]), pol(c["vc"], c["alc"]), pol(c["ac"], c["bc"]))
        x, v, a = derivs(rpr_motion(A, C, h, c["p"] * math.copysign(1, h)))
        d = math.hypot(c["xa"] - c["xc"], c["ya"] - c["yc"])
        vs = max(abs(v[2]) * d, abs(v[3]), c["va"] + c["vc"])
        as_ = max(abs(a[2]) * d, abs(a[3]), c["aa"] + c["ac"])
        assert abs(math.remainder(k.FI3 - x[2], 2 * math.pi)) <= TOL
        assert -math.pi < k.FI3 <= math.pi
        assert abs(k.W3 - v[2]) * d <= TOL * vs
        assert abs(k.E3 - a[2]) * d <= TOL * as_
        # A3 slides along the axis opposite to A: VAR along ALAR = FI3 or FI3 - pi
        assert abs(k.VAR * math.cos(k.ALAR - x[2]) + v[3]) <= TOL * vs
        assert k.ALAR in (k.FI3, k.FI3 - math.pi)
        # the book's B: AB = RZ2 and angle ABC = ETA
        ab = math.hypot(k.XB - c["xa"], k.YB - c["ya"])
        assert abs(ab - c["rz2"]) <= TOL * d
        ba = (c["xa"] - k.XB, c["ya"] - k.YB)
        bc = (c["xc"] - k.XB, c["yc"] - k.YB)
        ang = math.atan2(abs(ba[0] * bc[1] - ba[1] * bc[0]), ba[0] * bc[0] + ba[1] * bc[1])
        assert abs(ang - abs(math.remainder(c["eta"], 2 * math.pi))) <= 1e-12
        assert abs(k.RZBC - math.hypot(*bc)) <= TOL * d
    assert checked >= 30


@pytest.mark.parametrize("k", [-990, -300, 300, 900])
def test_dknma3_scales_exactly(k):
    rng = np.random.default_rng(5)
    for _ in range(10):
        c = _dknma3_case(rng)
        one, far = _dknma3(c), _dknma3(c, 2.0 ** k)
        assert far.status == one.status
        if one.status != 0:
            continue
        for name in one._fields:
            got, want = getattr(far, name), getattr(one, name)
            if name == "status":
                continue
            if name in ("XB", "YB", "RZBC", "VAR", "VAC", "VA3", "AAK", "AAR", "AACT", "AA3",
                        "AACN"):
                want = want * 2.0 ** k
            if name in ("VA3", "AA3", "XB", "YB", "RZBC"):
                # |A - C| and the moduli come from prmtr's norm2d, which takes hypot
                # beyond 1e+-150 (its own rounding): to an ulp
                assert abs(got - want) <= abs(np.spacing(want)), (name, got, want)
            else:
                assert got == want, (name, got, want)


@pytest.mark.parametrize("branch", [1, -1])
def test_dknma3_and_the_mechanism_give_the_same_bits(branch):
    """An inverted slider-crank: DKNMA3 (ETA = pi/2, RZ2 the offset, P the branch) fed
    the Mechanism's A gives its W3, E3 to the bit, and B (the foot of A on the axis) to
    the rounding of RZ2*COS(pi/2) = 6e-17 RZ2."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.02, -0.25)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.05, math.pi / 2, branch=branch)
    phi = np.linspace(-3.1, 3.1, 300)
    r = m.solve(phi)
    a, va, aa = r.position("A"), r.velocity("A"), r.acceleration("A")
    b, w3, e3 = r.position("B"), r.omega("C", "B"), r.epsilon("C", "B")
    compared = 0
    for i in range(phi.size):
        v, acc = _polar_exact(*va[i]), _polar_exact(*aa[i])
        if v is None or acc is None:
            continue
        k = sarkp.DKNMA3(a[i, 0], a[i, 1], 0.02, -0.25, 0.05, math.pi / 2, v[0], v[1], 0.0,
                         0.0, acc[0], acc[1], 0.0, 0.0, branch, 0.0, on_error="nan")
        assert int(k.status) == int(r.status[i])
        assert (k.W3, k.E3) == (w3[i], e3[i])
        assert abs(k.XB - b[i, 0]) <= 1e-17 and abs(k.YB - b[i, 1]) <= 1e-17
        compared += 1
    assert compared >= 20
    # DPRM3 (its P the opposite sign): the axis is the Mechanism's link 3
    p = sarkp.DPRM3(a[:, 0], a[:, 1], 0.02, -0.25, 0.05, math.pi / 2, -branch)
    d = np.remainder(p.FI3 - r.angle("C", "B"), 2 * np.pi)
    assert np.all(np.minimum(d, 2 * np.pi - d) <= 1e-15)


def test_dprm3_dskor3_duskr3_chain_against_the_closed_form():
    """DPRM3 -> DSKOR3 -> DUSKR3 (the book's sequence, IV.15) on an inverted
    slider-crank: W3, E3 and A3's sliding along the axis against the closed form."""
    r, xc, yc, h = 0.1, 0.02, -0.25, 0.05
    for phi in (-2.5, -0.7, 0.4, 1.9):
        A = ((r * math.cos(phi), r * math.sin(phi)), (-r * math.sin(phi), r * math.cos(phi)),
             (-r * math.cos(phi), -r * math.sin(phi)))
        x, v, a = derivs(rpr_motion(A, ((xc, yc), (0, 0), (0, 0)), h, 1))
        p = sarkp.DPRM3(A[0][0], A[0][1], xc, yc, h, math.pi / 2, -1.0, on_error="nan")
        s = sarkp.DSKOR3(A[0][0], A[0][1], xc, yc, r, phi + math.pi / 2, 0.0, 0.0, p.FI3,
                         on_error="nan")
        # the Coriolis term of A3 relative to A (IV.15, L2529)
        ak = 2 * abs(s.W3) * s.VA3A
        bk = s.ALA3A + math.copysign(math.pi / 2, s.W3)
        u = sarkp.DUSKR3(r, phi + math.pi, 0.0, 0.0, p.FI3, s.W3, p.RZAC, p.FICA, ak, bk,
                         on_error="nan")
        assert (p.status, s.status, u.status) == (0, 0, 0)
        assert abs(math.remainder(p.FI3 - x[2], 2 * math.pi)) <= TOL
        assert abs(s.W3 - v[2]) * p.RZAC <= TOL * r
        assert abs(s.VA3A * math.cos(s.ALA3A - p.FI3) + v[3]) <= TOL * r
        assert abs(u.E3 - a[2]) * p.RZAC <= TOL * r
        assert abs(u.AA3AR * math.cos(u.BA3AR - p.FI3) + a[3]) <= TOL * r
