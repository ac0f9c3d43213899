"""Fuzz tests of all 62 book routines, chapters 2-8 (Hypothesis; about a minute).
Inputs and invariants are in tests/invariants.py: valid inputs over wide ranges (for
chapters 2-4 link ratios up to 1e6, mechanisms up to 1e6 from the origin, angles of any
size; each section there states its ranges) must give a result whose invariants hold
within what the routine vouched for -- an error for an input built to be valid is a
failure, and so are a crash and a silent NaN; a NaN, an infinity or a string in any
input must be named in the error.  The inputs are Hypothesis draws (tests/strategies.py:
each number on a grid of 2**-32 of its range), so a failure shrinks to a small example.
The CI policy (derandomized under CI) is tests/conftest.py's.  The long campaign is
benchmarks/fuzz.py; the defects the fuzzing found and that are not fixed yet are kept
as strict xfails at the end of this file."""

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import sarkp

sys.path.insert(0, str(Path(__file__).resolve().parent))   # --import-mode=importlib
from invariants import CASES, ROUTINES, call  # noqa: E402
from strategies import DrawnRandom, inputs  # noqa: E402

FUZZ = settings(max_examples=100, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
BAD = settings(FUZZ, max_examples=60)


@pytest.mark.parametrize("name", ROUTINES)
@FUZZ
@given(data=st.data())
def test_valid_inputs_give_right_numbers(name, data):
    gen, check = CASES[name]
    args = data.draw(inputs(gen), label="args")
    kind, out, bound = call(name, args)
    assert kind == "ok", (name, args, kind, out)
    violation = check(args, out, bound)
    assert violation <= 1.0, (name, args, out, bound, violation)



def test_nearly_at_rest_but_accelerating_dknma3():
    """Found by the exploring profile: links nearly at rest (speeds 1e-7) but
    accelerating (1e-2).  DKNMA3's E3 is right (a central difference of W3 over 1e-3 s
    agrees to 1e-11); the check's time step, built from the speeds alone (200 s), was
    far beyond the motion's scale.  The step now also respects sqrt(length/acceleration)."""
    args = [1.0, 0.0, 0.0, 0.0, 0.20929175721840348, 0.2, 9.565004886425697e-08,
            1.4536875822280324, 9.258114773197209e-08, 1.4801364395941514,
            0.013856306093564637, 0.15763033464309842, 0.000929525146033492,
            1.570784303590112, -1.0, 0.0]
    kind, out, bound = call("DKNMA3", args)
    assert kind == "ok"
    assert CASES["DKNMA3"][1](args, out, bound) <= 1.0

def _inputs(name):
    return list(getattr(sarkp, name).spec.inputs)


@pytest.mark.parametrize("name", ROUTINES)
@BAD
@given(data=st.data(), bad=st.sampled_from([math.nan, math.inf, -math.inf, "x"]))
def test_bad_inputs_are_named(name, data, bad):
    gen, _ = CASES[name]
    rng = DrawnRandom.of(data.draw)
    args = gen(rng)
    k = int(rng.integers(0, len(args)))
    if isinstance(args[k], (list, np.ndarray)) and not isinstance(bad, str):
        value = np.array(args[k], dtype=float)
        value.flat[int(rng.integers(0, value.size))] = bad
        args[k] = value
    else:
        args[k] = bad
    with pytest.raises((ValueError, TypeError)) as info:
        getattr(sarkp, name)(*args)
    names = _inputs(name)
    assert names[k] in str(info.value), (name, names[k], str(info.value))


# -- defects the fuzzing found, kept as tests until they are fixed ---------------------------

@pytest.mark.xfail(strict=True, raises=sarkp.SingularError,
                   reason="DKNMA4 refuses a slider within a rounding of the pivot of a "
                          "rotating guide; its docstring promises SingularError only for "
                          "parallel guides (found by test_valid_inputs_give_right_numbers)")
def test_dknma4_slider_at_the_pivot():
    """Guide M: the x axis through A = (0.5, 0), turning about A with EM = 6; guide N
    through C = (0, 0) at 0.05 rad, turning about C.  Both offsets are 0 (ETA3 = pi: a
    sine of 1.2e-16), so B is at C, which guide N's rotation leaves in place; B moves
    only along N as M turns: |a_B| = EM |AB| / sin(0.05) (the normal acceleration of
    M's point under B, carried along N)."""
    r = sarkp.DKNMA4(0.0, 0.5, 0.0, 0.05, 0.0, 0.0, 1.0, 0.0, 1.0, math.pi, 0.0, 1.0, 6.0,
                     0.0, 0.0)
    assert abs(r.XB) < 1e-15 and abs(r.YB) < 1e-15
    assert r.VB < 1e-15
    assert r.AB == pytest.approx(6.0 * 0.5 / math.sin(0.05), rel=1e-12)


def test_every_book_routine_is_fuzzed():
    from sarkp.library import declared_routines
    assert sorted(ROUTINES) == sorted(declared_routines())


@settings(max_examples=50, deadline=None)
@given(data=st.data(), low=st.floats(-1e3, 1e3), width=st.floats(0.0, 1e3),
       n=st.integers(1, 50))
def test_drawn_random_keeps_numpy_ranges(data, low, width, n):
    """The Hypothesis-backed generator keeps numpy's ranges: uniform in [low, high]
    (numpy: [low, high)), integers in [low, high), choice among the options."""
    rng = DrawnRandom.of(data.draw)
    high = low + width
    u = rng.uniform(low, high, 3)
    assert u.shape == (3,) and np.all((low <= u) & (u <= high))
    assert 0 <= rng.integers(n) < n and -n <= rng.integers(-n, n) < n
    assert rng.choice(["a", "b"]) in ("a", "b") and 0.0 <= rng.random() <= 1.0
    assert abs(rng.standard_normal()) <= 6.0
