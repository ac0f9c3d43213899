"""Chapter 2 operator functions against exact references."""

import cmath
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import sarkp
from sarkp import (DFRNCL, DINTGR, DMOMNT, DOMEGA, DSMVKT, DUGL1, DUGL2, DUGL3, DUGL4,
                   DUGL5, DUGOL, DVKT)

coord = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)
angle = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)


# ---- DINTGR / DFRNCL ------------------------------------------------------------------

def test_dintgr_simpson_is_exact_on_cubics_at_the_odd_points():
    h = 0.1
    x = np.arange(11) * h
    y = 4 * x**3 - 3 * x**2 + 2 * x - 1
    exact = x**4 - x**3 + x**2 - x
    fint = DINTGR(11, h, 1, y).FINT
    # odd points (1, 3, 5, ... in the book's numbering) chain from FINT(1) = 0
    np.testing.assert_allclose(fint[0::2], exact[0::2], rtol=0, atol=1e-13)


def test_dintgr_simpson_even_chain_starts_from_a_trapezoid():
    y = np.array([0.0, 1.0, 4.0, 9.0, 16.0])            # x**2 at h = 1
    fint = DINTGR(5, 1.0, 1, y).FINT
    assert fint[1] == pytest.approx(0.5)               # trapezoid over [0, 1]
    assert fint[3] == pytest.approx(0.5 + (1 + 16 + 9) / 3)


def test_dintgr_trapezoid_is_exact_on_linears():
    x = np.linspace(0.0, 2.0, 9)
    fint = DINTGR(9, x[1] - x[0], 2, 3 * x - 1).FINT
    np.testing.assert_allclose(fint, 1.5 * x**2 - x, atol=1e-14)


def test_dintgr_rectangles_use_the_right_end():
    fint = DINTGR(4, 0.5, 3, [7.0, 1.0, 2.0, 3.0]).FINT
    np.testing.assert_allclose(fint, [0.0, 0.5, 1.5, 3.0])


@pytest.mark.parametrize("nomer, order", [(1, 4), (2, 2), (3, 1)])
def test_dintgr_error_order(nomer, order):
    def error(n):
        x = np.linspace(0.0, 1.0, n + 1)
        fint = DINTGR(n + 1, x[1] - x[0], nomer, np.exp(x)).FINT
        return abs(fint[-1] - (math.e - 1.0))          # n even: the last point is odd
    e1, e2 = error(32), error(64)
    assert math.log2(e1 / e2) == pytest.approx(order, abs=0.15)


def test_dintgr_both_ends_of_nomer():
    y = np.linspace(0, 1, 5) ** 2
    with pytest.raises(ValueError, match="NOMER"):
        DINTGR(5, 0.25, 0, y)
    with pytest.raises(ValueError, match="NOMER"):
        DINTGR(5, 0.25, 4, y)
    assert DINTGR(5, 0.25, 1, y).FINT[-1] != DINTGR(5, 0.25, 3, y).FINT[-1]


def test_dfrncl_on_polynomials():
    h = 0.25
    x = np.arange(9) * h
    fdif = DFRNCL(9, h, 2 * x + 1).FDIF
    assert fdif[0] == 0.0
    np.testing.assert_allclose(fdif[1:], 2.0, rtol=1e-14)
    # a backward difference of x**2 is exact at the midpoint: 2 (x - h/2)
    fdif = DFRNCL(9, h, x**2).FDIF
    np.testing.assert_allclose(fdif[1:], 2 * (x[1:] - h / 2), rtol=1e-14)


# ---- directions -------------------------------------------------------------------------

QUADRANTS = [(1, 1), (-1, 1), (-1, -1), (1, -1), (1, 0), (0, 1), (-1, 0), (0, -1)]


@pytest.mark.parametrize("dx, dy", QUADRANTS)
def test_dugl1_dugl2_in_every_quadrant_and_on_the_axes(dx, dy):
    x1, y1 = 0.3, -0.7
    exact = math.atan2(dy, dx)
    assert DUGL2(x1, y1, x1 + dx, y1 + dy) == pytest.approx(exact, abs=1e-15)
    assert DUGL1(x1, y1, x1 + dx, y1 + dy) == pytest.approx(exact % (2 * math.pi),
                                                                   abs=1e-15)


def test_dugl2_at_plus_minus_pi():
    assert DUGL2(0, 0, -1, 0) == math.pi           # Y2 - Y1 = 0 counts as positive
    assert DUGL2(0, 0, -1, -0.0) == math.pi        # -0.0 too, as on the ES EVM
    assert DUGL2(0, 0, -1, -1e-300) == pytest.approx(-math.pi)
    assert DUGL1(0, 0, -1, -1e-300) == pytest.approx(math.pi)


def test_dugl1_wraps_with_the_books_pi_as_printed():
    assert DUGL1(0, 0, 1, -1) == pytest.approx(-math.pi / 4 + 2 * math.pi, abs=1e-15)
    with sarkp.as_printed():
        assert DUGL1(0, 0, 1, -1) == pytest.approx(-math.pi / 4 + 2 * 3.14159,
                                                         abs=1e-15)


@given(coord, coord, coord, coord)
def test_dugl_against_atan2(x1, y1, x2, y2):
    if x1 == x2 and y1 == y2:
        return
    exact = math.atan2(y2 - y1, x2 - x1)
    assert DUGL2(x1, y1, x2, y2) == pytest.approx(exact, abs=1e-7 * max(1, abs(exact)))


@pytest.mark.parametrize("vel, expected", [(2.0, 1.0 + 0.5), (0.0, 1.5), (-0.0, 1.5),
                                           (-2.0, 1.0 - 0.5)])
def test_dugl3_sign_rule(vel, expected):
    assert DUGL3(1.0, -0.5, vel) == expected


@pytest.mark.parametrize("vel, expected", [(1.0, 1.0), (0.0, 1.0), (-1.0, 1.0 - math.pi)])
def test_dugl4_reverses_only_for_negative(vel, expected):
    assert DUGL4(1.0, math.pi, vel) == expected


@pytest.mark.parametrize("dx, dy", QUADRANTS)
def test_dugl5_is_a_direction_of_the_projections(dx, dy):
    a = DUGL5(float(dx), float(dy))
    assert -math.pi / 2 < a < 3 * math.pi / 2 or a == -math.pi / 2
    assert cmath.exp(1j * a) == pytest.approx(complex(dx, dy) / abs(complex(dx, dy)),
                                              abs=1e-15)


def test_dugl5_zero_vector_as_printed():
    assert DUGL5(0.0, 0.0) == math.pi / 2


def test_dugol_single_wrap():
    assert DUGOL(1.0) == 1.0
    assert DUGOL(-1.0) == pytest.approx(2 * math.pi - 1.0, abs=1e-15)
    assert DUGOL(-7.0) < 0                          # one wrap only, as printed


# ---- vectors ------------------------------------------------------------------------------

@given(coord, coord, coord, coord)
def test_dvkt_against_complex_arithmetic(x1, y1, x2, y2):
    if x1 == x2 and y1 == y2:
        return
    z = complex(x2 - x1, y2 - y1)
    rz, fi = DVKT(x1, y1, x2, y2)
    assert rz == pytest.approx(abs(z), rel=1e-14)
    assert cmath.exp(1j * fi) * rz == pytest.approx(z, rel=1e-14, abs=1e-14 * abs(z))


def test_dvkt_of_identical_points_is_the_books_guard():
    assert tuple(DVKT(2.0, 3.0, 2.0, 3.0)) == (0.0, 0.0)


@given(st.floats(-1e3, 1e3), angle, st.floats(-1e3, 1e3), angle)
def test_dsmvkt_against_complex_arithmetic(l1, f1, l2, f2):
    z = l1 * cmath.exp(1j * f1) + l2 * cmath.exp(1j * f2)
    l, fi = DSMVKT(l1, f1, l2, f2)
    scale = abs(l1) + abs(l2)
    assert l == pytest.approx(abs(z), abs=1e-14 * max(scale, 1e-300))
    assert l * cmath.exp(1j * fi) == pytest.approx(z, abs=1e-14 * max(scale, 1e-300))


@given(st.floats(0, 1e3), angle, st.floats(-1e3, 1e3), angle)
def test_dmomnt_is_the_cross_product(r, fi, f, g):
    rx, ry = r * math.cos(fi), r * math.sin(fi)
    fx, fy = f * math.cos(g), f * math.sin(g)
    assert DMOMNT(r, fi, f, g) == pytest.approx(rx * fy - ry * fx,
                                                        abs=1e-12 * (r * abs(f) + 1e-300))


def test_domega_sign_and_magnitude():
    assert DOMEGA(0.5, -1.0, 0.3) == 2.0
    assert DOMEGA(0.5, 1.0, -0.3) == -2.0


# ---- arrays broadcast, one Fortran loop -----------------------------------------------------

def test_arrays_broadcast_and_equal_the_scalar_results():
    x2 = np.linspace(-2, 2, 12).reshape(3, 4)
    y2 = np.array([[1.0], [-1.0], [0.5]])
    rz, fi = DVKT(0.0, 0.0, x2, y2)
    assert rz.shape == fi.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            assert (rz[i, j], fi[i, j]) == tuple(DVKT(0.0, 0.0, x2[i, j], y2[i, 0]))


def test_array_error_names_the_first_bad_index():
    with pytest.raises(sarkp.SingularError, match=r"index \[1\]"):
        DUGL1([0.0, 1.0], [0.0, 1.0], [1.0, 1.0], [0.0, 1.0])
    res = DUGL1([0.0, 1.0], [0.0, 1.0], [1.0, 1.0], [0.0, 1.0], on_error="nan")
    assert res.DUGL1[0] == 0.0 and math.isnan(res.DUGL1[1])
    assert list(res.status) == [0, 2]


@pytest.mark.parametrize("dy", [1e-10, -1e-10, 1e-3])
def test_directions_keep_full_precision_near_the_axis(dy):
    """The listing's arccosine would return 0 for 1e-10 (ERRATA E-DUGL2-1)."""
    assert DUGL2(0.0, 0.0, 1.0, dy) == pytest.approx(math.atan2(dy, 1.0), rel=1e-15)
    assert DUGL2(0.0, 0.0, -1.0, dy) == pytest.approx(math.atan2(dy, -1.0), rel=1e-15)
    assert DVKT(0.0, 0.0, 1.0, dy).FI == pytest.approx(math.atan2(dy, 1.0), rel=1e-15)
