"""Bad input raises ValueError naming the argument; never a NaN, never a crash."""

import fractions
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


def test_integer_inputs_are_screened_before_the_loop():
    # DZBPL checked its integers after the Fortran loop: Z1MAX = 2**31 - 1 spun for 14-23 s
    # before a ValueError; the driver now rejects it before the loop starts
    with pytest.raises(ValueError, match=r"^DZBPL: Z1MAX = 2147483647 is not one of the "
                                         r"integers 1\.\.10000$"):
        sarkp.DZBPL(1, 1, 1, 1, 1, 8, 2**31 - 1, 1)


@pytest.mark.parametrize("call, message", [
    (lambda: sarkp.DGMTZK(4.0, 10001.0, 0.0, 0.0), r"DGMTZK: Z = 10001 .* 8\.\.10000"),
    (lambda: sarkp.DZBPL(101, 1, 1, 1, 1, 8, 20, 1), r"DZBPL: KS = 101 .* 1\.\.100"),
    (lambda: sarkp.DCHRVC(8.0, 10.0, 101, 39.0, 200.0), r"DCHRVC: Z1 = 101 .* 1\.\.100"),
], ids=["DGMTZK-Z", "DZBPL-KS", "DCHRVC-Z1"])
def test_integer_messages_give_upper_bounds(call, message):
    with pytest.raises(ValueError, match=message):
        call()


@pytest.mark.parametrize("call, message", [
    (lambda: sarkp.DZBPL(2, 2**31, 1, 1, 1, 13, 35, 1),
     r"DZBPL: P = 2147483648 is not one of the integers -1000\.\.1000"),
    (lambda: sarkp.DCHRVC(8.0, 10.0, 2, 10**400, 200.0), r"DCHRVC: Z2 = .* too large"),
    (lambda: sarkp.DKRKT(4.0, 13.0, 34.0, 0.0, 10**400), r"DKRKT: SDVIG = .* too large"),
], ids=["DZBPL-P", "DCHRVC-Z2", "DKRKT-SDVIG"])
def test_integers_beyond_a_fortran_integer_are_value_errors(call, message):
    # these were OverflowError from f2py's conversion to a Fortran integer
    with pytest.raises(ValueError, match=message):
        call()


def test_nan_in_a_fortran_integer_input_of_a_sweep_is_missing():
    # a NaN tooth number or shift system was cast to an integer: finite results with
    # status OK, and "invalid value encountered in cast"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        z = sarkp.DZBPL(1, 5, 1, 1, 2, 10, 300, [1, math.nan], on_error="nan")
        k = sarkp.DKRKT(4.0, 13.0, 34.0, 100.0, [math.nan, 0], on_error="nan")
    assert z.status.tolist() == [sarkp.Status.OK, sarkp.Status.MISSING]
    assert z.Z1[0] == sarkp.DZBPL(1, 5, 1, 1, 2, 10, 300, 1).Z1 and math.isnan(z.Z1[1])
    assert k.status.tolist() == [sarkp.Status.MISSING, sarkp.Status.OK]
    assert math.isnan(k.X1[0]) and k.X1[1] == sarkp.DKRKT(4.0, 13.0, 34.0, 100.0, 0).X1


def test_messages_name_routine_and_argument():
    with pytest.raises(ValueError, match=r"^DZKNDV: ISC is not a regular array"):
        sarkp.DZKNDV(3, 3.0, 10.0, [[1.0], [2.0, 3.0]], [0, 0, 0.0], [0, 0, 0.0])
    with pytest.raises(ValueError, match=r"^DZBPL: KS = nan is not a finite number$"):
        sarkp.DZBPL(math.nan, fractions.Fraction(1, 3), 1, 1, 1, 13, 35, 1)
    with pytest.raises(ValueError, match=r"^DZBPL: P = 0\.333.* is not one of the integers"):
        sarkp.DZBPL(1, fractions.Fraction(1, 3), 1, 1, 1, 13, 35, 1)


def test_dugl6_with_numpy_scalars_draws_no_runtime_warning():
    # the fast path's sum(args) overflowed for NumPy scalars (1 + 1e308 + 1e308)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        value = sarkp.DUGL6(np.float64(1.0), 1e308, 1e308, 0.0, 0.0)
    assert math.isfinite(value)
