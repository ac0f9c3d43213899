"""Reliability and accuracy of chapters 2-4 (issue 8): each case here was a wrong number,
a lost digit or noise returned as a result before it was fixed.

References are exact: closed forms, or mpmath at 50 digits on the exact double inputs."""

import math
import warnings

import mpmath
import numpy as np
import pytest

import sarkp
from sarkp import GELG

mpmath.mp.dps = 50


# ---------------------------------------------------------------------------- GELG

def test_gelg_elimination_that_overflows_is_solved_exactly():
    # 1e308 - (-1e308) overflows in the elimination; the solution is (1e-8, 0)
    x, ier = GELG([1e300, 1e300], [[1e308, -1e308], [1e308, 1e308]], 2, 1, 1e-4)
    assert ier == 0
    np.testing.assert_allclose(x, [1e-8, 0.0], rtol=1e-15, atol=1e-300)


def test_gelg_tiny_coefficients_do_not_underflow():
    x, ier = GELG([3e-300, 1e-300], [[1e-310, 2e-310], [3e-310, 1e-310]], 2, 1, 1e-4)
    # exact: A = 1e-310 [[1, 2], [3, 1]], b = 1e-300 [3, 1] -> x = 1e10 [-1/5, 8/5]
    assert ier == 0
    np.testing.assert_allclose(x, [-0.2e10, 1.6e10], rtol=1e-13)


def test_gelg_solution_that_overflows_is_an_error_not_a_number():
    x, ier = GELG([1e300, 0.0], [[1e-300, 0.0], [0.0, 1.0]], 2, 1, 1e-4)
    assert ier == -1
    assert np.all(np.isfinite(x))


@pytest.mark.parametrize("eps", [math.nan, -1e-4, -math.inf])
def test_gelg_eps_nan_or_negative_is_named(eps):
    with pytest.raises(ValueError, match="EPS"):
        GELG([1.0, 2.0], [[2.0, 1.0], [1.0, 3.0]], 2, 1, eps)


# ------------------------------------------------------------------ references (mpmath)

def mpf(x):
    return mpmath.mpf(float(x))


def e(t):
    return mpmath.matrix([mpmath.cos(t), mpmath.sin(t)])


def kx(v):
    """k x v: v turned by +90 degrees."""
    return mpmath.matrix([-v[1], v[0]])


def solve(c1, c2, rhs):
    """x1*c1 + x2*c2 = rhs."""
    m = mpmath.matrix([[c1[0], c2[0]], [c1[1], c2[1]]])
    return mpmath.lu_solve(m, rhs)


def vec(mod, ang):
    return mpf(mod) * e(mpf(ang))


def ref_kind1(xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p):
    """RRR with DKNMA1's branch (P = +1: B on the left of A -> C), exact for the doubles."""
    A, C = mpmath.matrix([mpf(xa), mpf(ya)]), mpmath.matrix([mpf(xc), mpf(yc)])
    l2, l3 = mpf(rz2), mpf(rz3)
    d = mpmath.norm(C - A)
    fac = mpmath.atan2(C[1] - A[1], C[0] - A[0])
    anga = mpmath.acos((d**2 + l2**2 - l3**2) / (2 * d * l2))
    B = A + l2 * e(fac + p * anga)
    r2, r3 = B - A, B - C
    w2, w3 = solve(kx(r2), -kx(r3), vec(vc, alc) - vec(va, ala))
    e2, e3 = solve(kx(r2), -kx(r3), vec(ac, bc) - vec(aa, ba) - w3**2 * r3 + w2**2 * r2)
    return dict(B=B, fi2=mpmath.atan2(r2[1], r2[0]), fi3=mpmath.atan2(r3[1], r3[0]),
                w2=w2, w3=w3, e2=e2, e3=e3)


def rel_err(got, exact, scale):
    """Normwise error of the vector got relative to max(|exact|, scale)."""
    num = mpmath.sqrt(sum((mpf(g) - x) ** 2 for g, x in zip(got, exact)))
    den = max(mpmath.sqrt(sum(x**2 for x in exact)), mpf(scale))
    return float(num / den) if den else float(num)


def angle_err(got, exact):
    return float(abs((mpf(got) - exact + mpmath.pi) % (2 * mpmath.pi) - mpmath.pi))


def raw(name, *args):
    """The Fortran routine itself: its outputs and its status (ier)."""
    out = getattr(sarkp._sarkp.kinematics, name.lower())(*[float(a) for a in args])
    return out[:-1], int(out[-1])


def bound(ier):
    """The error the routine vouches for: 1e-8 when silent, 10**-d for status 100 + d."""
    if ier == 0:
        return 1e-8
    assert 101 <= ier <= 107, f"unexpected status {ier}"
    return 10.0 ** -(ier - 100)


# ---------------------------------------------------------------------------- DKNMA3

def test_dknma3_obtuse_eta_with_ab_longer_than_ac_does_not_assemble():
    # angle ABC = 2.0 rad with AB = 1.05 > AC = 1: the angle at C would be
    # asin(1.05 sin 2.0) = 1.27 rad, and 2.0 + 1.27 > pi: no triangle (the book put B
    # where angle ABC = pi - 2.0)
    with pytest.raises(sarkp.AssemblyError):
        sarkp.DKNMA3(0, 0, 1, 0, 1.05, 2.0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0)
    # the same with the acute ETA = pi - 2.0 assembles, and angle ABC is ETA
    k = sarkp.DKNMA3(0, 0, 1, 0, 1.05, math.pi - 2.0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0)
    ba = (0 - k.XB, 0 - k.YB)
    bc = (1 - k.XB, 0 - k.YB)
    ang = math.acos((ba[0] * bc[0] + ba[1] * bc[1]) / math.hypot(*ba) / math.hypot(*bc))
    assert ang == pytest.approx(math.pi - 2.0, abs=1e-12)


def test_dknma3_at_b_equal_c_takes_the_axis_from_the_angle():
    # B = C is a regular position: W3 as DPRM3 + DSKOR3 give it (0.843), no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        k = sarkp.DKNMA3(1, 0, 0, 0, 1, 2.0, 1, 1.5, 0, 0, 0, 0, 0, 0, -1, 0)
        r = sarkp.DPRM3(1, 0, 0, 0, 1, 2.0, 1)
        v = sarkp.DSKOR3(1, 0, 0, 0, 1, 1.5, 0, 0, r.FI3)
    assert k.RZBC < 1e-15
    assert k.W3 == pytest.approx(v.W3, rel=1e-14)
    assert k.W3 == pytest.approx(0.8429313811445545, rel=1e-14)
    # exact: the axis leaves C at f = pi - 2.0; v_A = w3 k x CA + s e(f) with CA = (1, 0)
    # and v_A = e(1.5) gives w3 = sin(1.5 - f)/cos(f)
    f = math.pi - 2.0
    assert k.W3 == pytest.approx(math.sin(1.5 - f) / math.cos(f), rel=1e-14)


# ------------------------------------------------------------ far from the origin

def test_dknma1_far_from_the_origin_keeps_its_digits():
    k = sarkp.DKNMA1(1e6, 1e6, 1e6 + 1.3e-3, 1e6 + 0.4e-3, 1e-3, 0.8e-3, 1e-3, 0, 0, 0,
                     1e-3, math.pi / 2, 0, 0, 1, 0)
    ref = ref_kind1(1e6, 1e6, 1e6 + 1.3e-3, 1e6 + 0.4e-3, 1e-3, 0.8e-3, 1e-3, 0, 0, 0,
                    1e-3, math.pi / 2, 0, 0, 1)
    assert float(ref["w2"]) == pytest.approx(0.876318466233726, rel=1e-14)
    assert k.W2 == pytest.approx(float(ref["w2"]), rel=1e-12)
    assert k.W3 == pytest.approx(float(ref["w3"]), rel=1e-12)
    assert k.E2 == pytest.approx(float(ref["e2"]), rel=1e-11)
    assert k.E3 == pytest.approx(float(ref["e3"]), rel=1e-11)


OFFSET = 2.0**20        # translations by 2**20 of points on a 2**-30 grid are exact


def shift(args, idx):
    return [a + OFFSET if i in idx else a for i, a in enumerate(args)]


def grid(x):
    return round(x * 2**30) / 2**30


# (routine, arguments with small coordinates on the 2**-30 grid, indices of coordinates)
FAR_CASES = [
    ("DKNMA1", [grid(0.1), grid(0.2), grid(1.4), grid(0.6), 1.0, 0.8, 1.0, 0.3, 0.5, 2.0,
                2.0, 1.0, 0.7, -1.0, 1, 0], (0, 1, 2, 3)),
    ("DKNMA2", [grid(0.1), grid(0.9), grid(-0.3), grid(0.2), 0.4, 1.2, 0.2, 0.7, 1.0, 0.3,
                0.2, 0.0, 0.0, 1.5, 0.4, 0.0, 0.0, 1, 0], (0, 1, 2, 3)),
    ("DKNMA3", [grid(0.1), grid(0.2), grid(1.4), grid(0.6), 0.9, 1.1, 1.0, 0.3, 0.5, 2.0,
                2.0, 1.0, 0.7, -1.0, 1, 0], (0, 1, 2, 3)),
    ("DKNMA4", [0.3, grid(0.1), grid(0.2), 1.9, grid(1.4), grid(0.6), 0.2, 0.5, 0.3, -0.4,
                0.8, -0.6, 1.5, 0.4, 0], (1, 2, 4, 5)),
    ("DPRM2", [grid(0.1), grid(0.9), grid(-0.3), grid(0.2), 0.4, 1.2, 0.2, 0.7], (0, 1, 2, 3)),
    ("DPRM4", [grid(-0.5), grid(0.1), grid(0.1), grid(0.2), 0.3, grid(1.0), grid(0.3),
               grid(1.4), grid(0.6), 1.9, 0.2, 0.5, 0.3, -0.4], (0, 1, 2, 3, 5, 6, 7, 8)),
]

# outputs that are absolute coordinates (they move with the offset)
COORDS = {"XB", "YB", "XK", "YK"}


@pytest.mark.parametrize("name, args, idx", FAR_CASES, ids=[c[0] for c in FAR_CASES])
def test_results_do_not_depend_on_where_the_mechanism_stands(name, args, idx):
    f = getattr(sarkp, name)
    near = f(*args)
    far = f(*shift(args, idx))
    for field, a, b in zip(near._fields, near, far):
        if field in COORDS:
            assert b - OFFSET == pytest.approx(a, abs=1e-15 * OFFSET), field
        elif field.startswith(("FI", "AL", "B")):                # directions
            assert abs((b - a + math.pi) % (2 * math.pi) - math.pi) <= 1e-13, field
        else:
            assert b == pytest.approx(a, rel=1e-13, abs=1e-13 * max(map(abs, near))), field


def test_kind5_small_slot_angle_keeps_its_digits():
    # C - A = s2 e(FIM) + s3 e(FIM + T2); the book's matrix rounds FIM + T2
    r = sarkp.DPRM5(0, 0, 3.0, 0.7, 0.9, 1e-8)
    fim, t2 = mpf(3.0), mpf(1e-8)
    s2, s3 = solve(e(fim), e(fim + t2), mpmath.matrix([mpf(0.7), mpf(0.9)]))
    assert r.S2 == pytest.approx(float(s2), rel=4e-16 * 8)
    assert r.S3 == pytest.approx(float(s3), rel=4e-16 * 8)
