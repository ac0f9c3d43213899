"""Fuzz tests of every exported routine of chapters 2-4 (Hypothesis; bounded to well under
a minute).  Inputs and invariants are in tests/invariants.py: valid inputs over wide
ranges (link ratios up to 1e6, mechanisms up to 1e6 from the origin, angles of any size)
must give a result whose invariants hold within what the routine vouched for, or a clear
error -- never a crash, never a silent NaN; a NaN, an infinity or a string in any input
must be named in the error.  The long campaign is benchmarks/fuzz.py."""

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

FUZZ = settings(max_examples=150, deadline=None, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow])
SEEDS = st.integers(0, 2**63 - 1)


@pytest.mark.parametrize("name", ROUTINES)
@FUZZ
@given(seed=SEEDS)
def test_valid_inputs_give_right_numbers_or_clear_errors(name, seed):
    gen, check = CASES[name]
    args = gen(np.random.default_rng(seed))
    kind, out, bound = call(name, args)
    assert kind in ("ok", "error"), (name, args, kind, out)
    if kind == "ok":
        violation = check(args, out, bound)
        assert violation <= 1.0, (name, args, out, bound, violation)


def _inputs(name):
    return list(getattr(sarkp, name).spec.inputs)


@pytest.mark.parametrize("name", ROUTINES)
@FUZZ
@given(seed=SEEDS, bad=st.sampled_from([math.nan, math.inf, -math.inf, "x"]))
def test_bad_inputs_are_named(name, seed, bad):
    gen, _ = CASES[name]
    rng = np.random.default_rng(seed)
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
