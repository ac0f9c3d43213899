"""Bad input raises ValueError naming the argument; never a NaN, never a crash."""

import math
import warnings

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


# -- issue 18's defects, each reproduced first ----------------------------------------------

def test_integer_messages_give_both_bounds():
    # was "M = 1099511627776 is not one of the integers >= 2"
    with pytest.raises(ValueError, match=r"DINTGR: M = 1099511627776 is not one of the "
                                         r"integers 2\.\.2147483646"):
        sarkp.DINTGR(2**40, 0.1, 1, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"DINTGR: NOMER = 4 is not one of the integers "
                                         r"1\.\.3"):
        sarkp.DINTGR(3, 0.1, 4, [1.0, 2.0, 3.0])


def test_scalar_errors_carry_no_index():
    # a 0-d array takes the array path; its error said "at index []"
    with pytest.raises(sarkp.AssemblyError) as info:
        sarkp.DPRM1(np.array(0.0), 0.0, 9.0, 0.0, 0.35, 0.3, 1)
    assert "index" not in str(info.value) and info.value.index is None
    with pytest.raises(ValueError, match=r"^DPRM1: RZ2 = -1\.0 is a length"):
        sarkp.DPRM1(np.array(0.0), 0.0, 9.0, 0.0, np.array(-1.0), 0.3, 1)


def test_ragged_lists_name_routine_and_argument():
    # a ragged list where a number belongs said only numpy's "setting an array element
    # with a sequence ..."
    with pytest.raises(ValueError, match=r"^DINTGR: H is not a regular array"):
        sarkp.DINTGR(3, [[1.0], [2.0, 3.0]], 1, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"^DINTGR: Y is not a regular array"):
        sarkp.DINTGR(3, 0.1, 1, [[1.0], [2.0, 3.0]])
    with pytest.raises(ValueError, match=r"^DVKT: X2 is not a regular array"):
        sarkp.DVKT(0.0, 0.0, [[1.0], [2.0, 3.0]], 1.0)


@pytest.mark.parametrize("huge", [10**400, -(10**400)], ids=["1e400", "-1e400"])
def test_huge_integers_are_value_errors_not_overflow_errors(huge):
    with pytest.raises(ValueError, match=r"^DPRM1: P = -?10000000\.\.\. \(an integer of "
                                         r"401 digits\) is too large for a double$"):
        sarkp.DPRM1(0.1, 0.0, 0.4, 0.0, 0.35, 0.3, huge)
    with pytest.raises(ValueError, match=r"DINTGR: H = .* too large"):
        sarkp.DINTGR(3, huge, 1, [1.0, 2.0, 3.0])


def test_nan_in_an_integer_input_of_a_sweep_is_missing():
    # P = NaN at one position of a sweep: MISSING there, the other position computed, and
    # no "invalid value encountered in cast" on the way
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = sarkp.DPRM1([0.1, 0.1], 0.0, 0.4, 0.0, 0.35, 0.3, [1, math.nan], on_error="nan")
        one = sarkp.DPRM1(0.1, 0.0, 0.4, 0.0, 0.35, 0.3, 1)
    assert r.status.tolist() == [sarkp.Status.OK, sarkp.Status.MISSING]
    assert r.XB[0] == one.XB and math.isnan(r.XB[1])
    with pytest.raises(ValueError, match=r"DPRM1: P\[1\] = nan is not a finite number"):
        sarkp.DPRM1([0.1, 0.1], 0.0, 0.4, 0.0, 0.35, 0.3, [1, math.nan])


def test_valid_numpy_scalars_draw_no_runtime_warning():
    # the fast path summed the inputs to test them: 1e308 + 1e308 overflowed with a
    # RuntimeWarning for NumPy scalars, which -W error turns into a failure
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = sarkp.DVKT(np.float64(1e308), 0.0, 1e308, 1.0)
    assert (r.RZ, r.FI) == (1.0, math.pi / 2)
