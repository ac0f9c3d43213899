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
