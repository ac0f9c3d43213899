"""Bad input raises ValueError naming the argument; never a NaN, never a crash."""

import math

import numpy as np
import pytest

import sarkp


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_non_finite_scalar_names_the_argument(bad):
    with pytest.raises(ValueError, match="Y2"):
        sarkp.DVKT(0.0, 0.0, 1.0, bad)


def test_non_finite_array_names_argument_and_index():
    with pytest.raises(ValueError, match=r"X1\[2\]"):
        sarkp.DVKT([0.0, 1.0, np.nan], 0.0, 1.0, 1.0)


def test_non_positive_length():
    with pytest.raises(ValueError, match="RAZMER"):
        sarkp.DOMEGA(0.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="RAZMER"):
        sarkp.DOMEGA(-1.0, 1.0, 1.0)


def test_shapes_that_do_not_broadcast():
    with pytest.raises(ValueError):
        sarkp.DVKT([0.0, 1.0], [0.0, 1.0, 2.0], 1.0, 1.0)


def test_tables_need_two_points_and_matching_m():
    with pytest.raises(ValueError, match=r"M = 1 is not one of the integers 2\.\.2147483646"):
        sarkp.DINTGR(1, 0.1, 2, [1.0])
    with pytest.raises(ValueError, match=r"M = 1 is not one of the integers 2\.\.2147483646"):
        sarkp.DFRNCL(1, 0.1, [1.0])
    with pytest.raises(ValueError, match="M"):
        sarkp.DINTGR(4, 0.1, 2, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="Y"):
        sarkp.DFRNCL(3, 0.1, [1.0, np.inf, 3.0])
    with pytest.raises(ValueError, match="H"):
        sarkp.DFRNCL(3, 0.0, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="one-dimensional"):
        sarkp.DINTGR(4, 0.1, 2, [[1.0, 2.0], [3.0, 4.0]])


def test_on_error_must_be_known():
    with pytest.raises(ValueError, match="on_error"):
        sarkp.DVKT(0.0, 0.0, 1.0, 1.0, on_error="ignore")


def test_unknown_mode():
    with pytest.raises(ValueError, match="mode"):
        sarkp.set_mode("approximately")


def test_modes_switch_pi_and_restore():
    assert sarkp.get_mode() == "corrected"
    with sarkp.as_printed():
        assert sarkp.get_mode() == "as-printed"
        assert sarkp.DUGOL(-1.0) == pytest.approx(2 * 3.14159 - 1.0, abs=1e-15)
    assert sarkp.get_mode() == "corrected"
    assert sarkp.DUGOL(-1.0) == pytest.approx(2 * math.pi - 1.0, abs=1e-15)


def test_nan_from_a_failed_step_passes_through_a_chain_with_on_error_nan():
    first = sarkp.DUGL1([0.0, 1.0], [0.0, 1.0], [1.0, 1.0], [0.0, 1.0], on_error="nan")
    assert list(first.status) == [0, 2]
    second = sarkp.DUGL3(first.DUGL1, 1.0, 1.0, on_error="nan")
    assert second.DUGL3[0] == 1.0 and np.isnan(second.DUGL3[1])
    assert list(second.status) == [0, 5]                   # 5: an input was missing
    scalar = sarkp.DVKT(0.0, 0.0, math.nan, 1.0, on_error="nan")
    assert np.isnan(scalar.RZ) and scalar.status == 5
    with pytest.raises(ValueError, match="X2"):           # but never silently by default
        sarkp.DVKT(0.0, 0.0, math.nan, 1.0)
    with pytest.raises(ValueError, match="X2"):           # and inf is never a missing value
        sarkp.DVKT(0.0, 0.0, [math.inf], 1.0, on_error="nan")
