"""The layer itself: every declared routine against its Fortran driver, the mode per
caller, and the edges of the input.  A routine gets the checks here by being declared."""

import asyncio
import inspect
import math
import re
import sys
import threading
import warnings
from pathlib import Path

import numpy as np
import pytest

import sarkp
from sarkp.library import declared_routines

ROUTINES = declared_routines()
NAMES = sorted(ROUTINES)


def f2py_signature(wrapper):
    """(required arguments, optional arguments, returned names) of an f2py wrapper, as
    its docstring's first line gives them (``a, b = f(x, y[, z])``)."""
    first = wrapper.__doc__.strip().splitlines()[0]
    m = re.match(r"(?:(.*?)\s*=\s*)?\w+\((.*)\)$", first)
    rets = [r.strip() for r in (m.group(1) or "").split(",") if r.strip()]
    args, optional = m.group(2), []
    if "[" in args:
        args, opt = args.split("[", 1)
        optional = [a.strip() for a in opt.rstrip("]").split(",") if a.strip()]
    required = [a.strip() for a in args.split(",") if a.strip()]
    # f2py renames the arguments that clash with C (DO, INDEX: do_bn, index_bn)
    return tuple([n[:-3] if n.endswith("_bn") else n for n in names]
                 for names in (required, optional, rets))


def test_every_book_routine_is_declared():
    """The 59 routines of Table 33, GELG, DPRM5 (an extension: the book has no kind-5
    positions) and DUGL6 (called by the book, never printed): 62, each exported."""
    table_33 = {"DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL",
                "DMOMNT", "DOMEGA", "DVKT", "DSMVKT", "DSNTZR", "DSNTZ1", "DSNTZ2",
                "DSNTZ3", "DSNTZK", "DKLCHK", "DPRFLP", "DPRFPL", "DPRFLK", "DZBPL",
                "DKRKT", "DUGINV", "DGMTZK", "DGMZPC", "DGMZVN", "DCHRVC", "DZKNDV",
                "DMHVK"}
    table_33 |= {f"D{g}{k}" for g in ("SKOR", "USKR", "KNMA", "NMAF", "NMA")
                 for k in range(1, 6)}
    table_33 |= {f"DPRM{k}" for k in range(1, 5)}
    assert len(table_33) == 59
    assert set(ROUTINES) == table_33 | {"GELG", "DPRM5", "DUGL6"}


@pytest.mark.parametrize("name", NAMES)
def test_the_wrapper_is_importable_typed_source(name):
    """The wrapper is generated source (no exec): its signature is the argument lines'
    inputs, annotated, then on_error (and out, for sweeps); the driver f2py built takes
    the same inputs in the same order and returns the declared outputs first."""
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    source = inspect.getsource(inspect.unwrap(routine))
    assert source.startswith(f"def {name}(") and "exec" not in source
    assert inspect.getsourcefile(inspect.unwrap(routine)).endswith(f"_wrap_{spec.chapter}.py")
    params = inspect.signature(routine).parameters
    assert list(params) == list(spec.inputs) + ["on_error"] + ([] if spec.sweeps_tables
                                                               else ["out"])
    assert all(p.annotation is not inspect.Parameter.empty for p in params.values())
    assert inspect.signature(routine).return_annotation in (f"{name}Result", "Output")
    required, optional, rets = f2py_signature(spec.one)
    assert required == ["sarkp_mode"] + [a.lower() for a in spec.inputs]
    assert optional == ["sarkp_skip"]
    tail = ["sarkp_bad", "sarkp_at"] if spec.sweeps_tables else ["sarkp_bad"]
    assert rets[-len(tail):] == tail
    assert rets[:-len(tail) - 1] == (["fres"] if spec.function
                                     else [o.lower() for o in spec.outputs])
    doc = routine.__doc__
    sections = re.findall(r"^    (\w[\w ]*)\n    -+$", doc, re.M)
    assert "Parameters" in sections
    assert sections.index("Parameters") < sections.index("Returns") if "Returns" in sections \
        else True
    for arg in spec.inputs:
        assert re.search(rf"^    (\w+, )*{arg}\b", doc, re.M), f"{name}: {arg} undocumented"
    assert "on_error" in doc and "status" in doc


def _valid_value(spec, arg, rng):
    if arg == "AAA":
        return 1.0
    if arg in spec.integers:
        allowed = spec.integers[arg]
        if isinstance(allowed, range):
            return float(allowed.start)
        return float(rng.choice(sorted(allowed)))
    if arg in spec.lengths or arg in getattr(spec, "positive", ()):
        return float(rng.uniform(0.2, 2.0))
    if arg in spec.nonnegative:
        return float(rng.uniform(0.0, 2.0))
    if arg in spec.nonzero:
        return float(rng.choice([-1, 1]) * rng.uniform(0.1, 2.0))
    return float(rng.uniform(-2.0, 2.0))


def _valid_inputs(spec, rng):
    """Random inputs that pass the layer's checks (the routine may still fail on them);
    half of them near the declaration's example row, where it has one."""
    if spec.example is not None and rng.random() < 0.5:
        return [v if a in spec.integers or a == "AAA" else v * rng.uniform(0.999, 1.001)
                for a, v in zip(spec.inputs, spec.example)]
    values = {}
    for arg in spec.inputs:
        if arg in spec.tables:
            continue
        values[arg] = _valid_value(spec, arg, rng)
    for arg, dims in spec.tables.items():
        for d in dims:                         # a count: a few more than its minimum
            if isinstance(d, str):
                values[d] = float(spec.integers[d].start + 2)
        shape = tuple(int(values[d]) if isinstance(d, str) else d for d in dims)
        square = len(shape) == 2 and shape[0] == shape[1]
        values[arg] = rng.uniform(0.5, 2.0, shape) + (3.0 * np.eye(shape[0]) if square else 0)
    return [values[a] for a in spec.inputs]


SWEEPABLE = [n for n in NAMES if not ROUTINES[n].spec.sweeps_tables]


def _seven_rows(name):
    """Up to seven rows of random valid inputs of a sweepable routine: four that it
    computes, then up to three that it may reject."""
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    rng = np.random.default_rng(sum(map(ord, name)))
    computed, other = [], []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for _ in range(200):
            row = _valid_inputs(spec, rng)
            ok = int(routine(*row, on_error="nan").status) in (0, 3)
            (computed if ok else other).append(row)
            if len(computed) >= 4 and len(other) >= 3:
                break
    return computed, computed[:4] + other[:3]


@pytest.mark.parametrize("name", SWEEPABLE)
def test_scalar_and_array_paths_agree_bit_for_bit(name):
    """Random valid inputs, seven positions (four that the routine computes, three that
    it may reject): one array call equals seven scalar calls, values and status."""
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    computed, rows = _seven_rows(name)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        columns = [np.array([r[k] for r in rows]) for k in range(len(spec.inputs))]
        arrays = routine(*columns, on_error="nan")
        scalars = [routine(*r, on_error="nan") for r in rows]
    for k, one in enumerate(scalars):
        for field, value in zip(arrays._fields, one):
            got = np.asarray(getattr(arrays, field))[k]
            np.testing.assert_array_equal(got, value, err_msg=f"{name}.{field}[{k}]")
    for row, one in zip(computed[:4], scalars):      # the fast path of plain floats too
        fast = routine(*row)
        assert (fast,) == tuple(one[:-1]) if spec.function else tuple(fast) == tuple(one[:-1])
    assert any(int(s) in (0, 3) for s in arrays.status), f"{name}: no valid position drawn"


@pytest.mark.parametrize("name", SWEEPABLE)
def test_out_is_written_in_place(name):
    """out=: the results are the rows of the caller's array, equal bit for bit to those of
    a call without it, whatever the array held before (failed positions too)."""
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    _, rows = _seven_rows(name)
    m = len(rows)
    columns = [np.array([r[k] for r in rows]) for k in range(len(spec.inputs))]
    # an m x m broadcast: the first input along the second axis, the rest along the first
    columns = [c.reshape(((1, m) if k == 0 else (m, 1)) + c.shape[1:])
               for k, c in enumerate(columns)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fresh = routine(*columns, on_error="nan")
        shape = np.shape(fresh.status)                           # (m, m), or (1, m)
        buf = np.full((len(spec.outputs),) + shape, 12345.0)
        again = routine(*columns, on_error="nan", out=buf)
    values = again[:-1]
    assert len(values) == len(spec.outputs)
    for k, (a, b) in enumerate(zip(fresh[:-1], values)):
        assert b.shape == shape and np.shares_memory(b, buf[k])
        np.testing.assert_array_equal(a, b, err_msg=f"{name}.{spec.outputs[k]}")
        np.testing.assert_array_equal(buf[k], a)
    np.testing.assert_array_equal(fresh.status, again.status)


@pytest.mark.parametrize("out, what", [
    (np.empty((22, 5)), r"shape \(22, 4\)"),
    (np.empty((22, 4), np.float32), "float32"),
    (np.empty((4, 22)).T, "not C-contiguous"),
    ([[0.0] * 4] * 22, "list"),
])
def test_bad_out_is_named(out, what):
    xa = np.linspace(0.0, 0.1, 4)
    with pytest.raises(ValueError, match=f"DKNMA1: out must be .*{what}"):
        sarkp.DKNMA1(xa, 0.1, 0.4, 0.0, 0.35, 0.3, 0.3, 1.57, 0, 0, 0.9, 3.14, 0, 0, 1, 0,
                     out=out)
    frozen = np.empty((22, 4))
    frozen.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        sarkp.DKNMA1(xa, 0.1, 0.4, 0.0, 0.35, 0.3, 0.3, 1.57, 0, 0, 0.9, 3.14, 0, 0, 1, 0,
                     out=frozen)


def test_out_with_scalar_inputs_and_no_out_for_tables():
    buf = np.empty(2)
    r = sarkp.DVKT(0.0, 0.0, 3.0, 4.0, out=buf)
    assert (r.RZ, r.FI) == (5.0, math.atan2(4.0, 3.0)) and buf[0] == 5.0
    assert "out" not in inspect.signature(sarkp.GELG).parameters


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_nan_and_inf_are_named(name, bad):
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    rng = np.random.default_rng(1)
    for k, arg in enumerate(spec.inputs):
        args = _valid_inputs(spec, rng)
        if arg in spec.tables:
            args[k] = np.array(args[k], dtype=float)
            args[k].flat[0] = bad
        else:
            args[k] = bad
        with pytest.raises(ValueError, match=rf"{name}: {arg}\b"):
            routine(*args)


@pytest.mark.parametrize("name", NAMES)
def test_wrong_shapes_are_named(name):
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    rng = np.random.default_rng(2)
    args = _valid_inputs(spec, rng)
    if spec.sweeps_tables:
        table = next(iter(spec.tables))
        k = spec.inputs.index(table)
        args[k] = np.zeros(np.shape(args[k]) + (2, 2))          # one dimension too many
        with pytest.raises(ValueError, match=rf"{name}: {table}"):
            routine(*args)
        return
    k = next(i for i, a in enumerate(spec.inputs) if a not in spec.tables)
    j = next((i for i, a in enumerate(spec.inputs) if i != k and a not in spec.tables), None)
    if j is None:
        pytest.skip("a single array input broadcasts with anything")
    args[k] = np.full(2, args[k])
    args[j] = np.full(3, args[j])
    with pytest.raises(ValueError, match="do not broadcast"):
        routine(*args)


# -- the book's FUNCTIONs give numbers ---------------------------------------------------

def test_functions_return_numbers():
    fi = sarkp.DUGL1(0.0, 0.0, 1.0, 1.0)
    assert type(fi) is float and math.cos(fi) == pytest.approx(math.sqrt(0.5))
    assert sarkp.DUGL3(1.0, 0.5, -1.0) * 3 == pytest.approx(1.5)
    a = sarkp.DUGL1(0.0, 0.0, [1.0, 0.0], [0.0, 1.0])
    assert isinstance(a, np.ndarray) and a.shape == (2,)
    value, status = sarkp.DUGL1(0.0, 0.0, 0.0, 0.0, on_error="nan")
    assert math.isnan(value) and status == sarkp.Status.SINGULAR


def test_directions_stay_below_two_pi():
    """E-DUGOL-1: a direction a hair below 0 is 0, not 2*pi."""
    assert sarkp.DUGL1(0, 0, 1, -1e-17) == 0.0
    assert sarkp.DUGOL(-1e-17) == 0.0
    assert sarkp.DUGOL(-1e-3) == 2 * math.pi - 1e-3
    with sarkp.as_printed():
        assert sarkp.DUGL1(0, 0, 1, -1e-17) < 2 * 3.14159
    # DPRM1 (P = +1) wraps its directions with DUGOL: B straight below A, C on the axis
    with pytest.warns(sarkp.SignificanceWarning):     # a flat triangle: the policy warns
        r = sarkp.DPRM1(0.0, 0.0, 2.0, -1e-17, 1.0, 1.0, 1)
    assert 0.0 <= r.FI2 < 2 * math.pi and 0.0 <= r.FI3 < 3 * math.pi


# -- the mode belongs to the caller -------------------------------------------------------

PRINTED_FI = -math.pi / 4 + 2 * 3.14159          # DUGL1(0, 0, 1, -1) as printed
CORRECTED_FI = -math.pi / 4 + 2 * math.pi


def _hammer(mode, results, n, barrier):
    barrier.wait()
    with sarkp.mode(mode):
        for _ in range(n):
            results.append(sarkp.DUGL1(0.0, 0.0, 1.0, -1.0))
            results.append(float(sarkp.DUGL1(0.0, 0.0, [1.0], -1.0)[0]))


def test_threads_never_see_each_others_mode():
    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    try:
        printed, corrected, plain = [], [], []
        barrier = threading.Barrier(3)
        threads = [threading.Thread(target=_hammer, args=("as-printed", printed, 5000, barrier)),
                   threading.Thread(target=_hammer, args=("corrected", corrected, 5000, barrier))]
        for t in threads:
            t.start()
        barrier.wait()
        for _ in range(5000):                      # this thread never sets a mode
            plain.append(sarkp.DUGL1(0.0, 0.0, 1.0, -1.0))
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(old)
    assert set(printed) == {PRINTED_FI} and len(printed) == 10000
    assert set(corrected) == {CORRECTED_FI} and len(corrected) == 10000
    assert set(plain) == {CORRECTED_FI}
    assert sarkp.get_mode() == "corrected"


def test_set_mode_in_a_thread_stays_in_that_thread():
    seen = {}

    def worker():
        sarkp.set_mode("as-printed")
        seen["worker"] = sarkp.DUGL1(0.0, 0.0, 1.0, -1.0)

    t = threading.Thread(target=worker)
    t.start()
    t.join()
    assert seen["worker"] == PRINTED_FI
    assert sarkp.get_mode() == "corrected" and sarkp.DUGL1(0, 0, 1, -1) == CORRECTED_FI


def test_asyncio_tasks_have_their_own_mode():
    async def task(mode):
        with sarkp.mode(mode):
            out = []
            for _ in range(50):
                out.append(sarkp.DUGL1(0.0, 0.0, 1.0, -1.0))
                await asyncio.sleep(0)
            return set(out)

    async def main():
        return await asyncio.gather(task("as-printed"), task("corrected"))

    printed, corrected = asyncio.run(main())
    assert printed == {PRINTED_FI} and corrected == {CORRECTED_FI}


def test_mode_is_restored_after_an_exception():
    with pytest.raises(ZeroDivisionError):
        with sarkp.as_printed():
            assert sarkp.get_mode() == "as-printed"
            1 / 0
    assert sarkp.get_mode() == "corrected"
    with pytest.raises(ValueError, match="mode"):
        sarkp.set_mode("printed")


# -- the edges of the input ---------------------------------------------------------------

def test_empty_arrays_give_empty_results():
    r = sarkp.DVKT(np.zeros(0), 0.0, 1.0, 1.0)
    assert r.RZ.shape == (0,) and r.FI.shape == (0,)
    r = sarkp.DPRM1(np.zeros((0, 3)), 0.0, 0.4, 0.0, 0.35, 0.3, 1, on_error="nan")
    assert r.FI2.shape == (0, 3) and r.status.shape == (0, 3)
    assert sarkp.DUGL1([], 0.0, 1.0, 1.0).shape == (0,)


@pytest.mark.parametrize("bad", ["1.5", b"1.5", None, 1 + 2j, np.array([1 + 1j]),
                                 np.ma.masked_array([1.0, 2.0], mask=[0, 1]), object(),
                                 ["a", "b"], {"x": 1}])
def test_non_numbers_raise_type_errors_naming_the_argument(bad):
    with pytest.raises(TypeError, match="DVKT: Y2 must be a real number"):
        sarkp.DVKT(0.0, 0.0, 1.0, bad)


def test_table_routines_reject_non_numbers():
    with pytest.raises(TypeError, match="DINTGR: H"):
        sarkp.DINTGR(3, "0.1", 1, [1.0, 2.0, 3.0])
    with pytest.raises(TypeError, match="DINTGR: Y"):
        sarkp.DINTGR(3, 0.1, 1, ["1", "2", "3"])
    with pytest.raises(TypeError, match="GELG: A"):
        sarkp.GELG([1.0], [[1j]], 1, 1, 1e-4)


def test_integers_too_large_for_a_double():
    with pytest.raises(ValueError, match="DVKT: X2 .*too large"):
        sarkp.DVKT(0.0, 0.0, 10**400, 0.0)
    with pytest.raises(ValueError, match="DVKT: X2 .*too large"):
        sarkp.DVKT(0, 0, 10**400, 0)
    with pytest.raises(ValueError, match="GELG: EPS .*too large"):
        sarkp.GELG([1.0], [[1.0]], 1, 1, 10**400)


@pytest.mark.parametrize("call, field", [
    (lambda **k: sarkp.DMOMNT(1e308, 0.0, 1e308, math.pi / 2, **k), "DMOMNT"),
    (lambda **k: sarkp.DVKT(-1e308, 0.0, 1e308, 0.0, **k), "RZ"),
    (lambda **k: sarkp.DOMEGA(1e-308, 1e10, 1.0, **k), "DOMEGA"),
])
def test_overflow_is_a_named_error_never_inf(call, field):
    with pytest.raises(sarkp.RangeError, match=rf": {field}\b.* would not be a finite"):
        call()
    out = call(on_error="nan")
    assert out.status == sarkp.Status.RANGE and math.isnan(getattr(out, field))


def test_overflow_in_arrays_gets_a_status():
    out = sarkp.DVKT([0.0, -1e308], 0.0, [1.0, 1e308], 0.0, on_error="nan")
    assert out.status.tolist() == [0, sarkp.Status.RANGE]
    assert out.RZ[0] == 1.0 and np.isnan(out.RZ[1])
    with pytest.raises(sarkp.RangeError, match=r"DVKT at index \[1\]: RZ would not be"):
        sarkp.DVKT([0.0, -1e308], 0.0, [1.0, 1e308], 0.0)


@pytest.mark.parametrize("m", [math.nan, math.inf, 2.5, 0, -1])
def test_counts_are_integers_in_range(m):
    with pytest.raises(ValueError, match="DINTGR: M = "):
        sarkp.DINTGR(m, 0.1, 1, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="GELG: N = "):
        sarkp.GELG([1.0], [[1.0]], 1, m, 1e-4)


@pytest.mark.parametrize("nomer", [math.nan, math.inf, 1.5, 0, 4])
def test_methods_are_named(nomer):
    with pytest.raises(ValueError, match="DINTGR: NOMER = "):
        sarkp.DINTGR(3, 0.1, nomer, [1.0, 2.0, 3.0])


def test_integer_valued_floats_are_accepted():
    assert sarkp.DINTGR(3.0, 0.5, 2.0, [0.0, 1.0, 2.0]).FINT.tolist() == [0.0, 0.25, 1.0]


# -- what a caller reads ------------------------------------------------------------------

def test_status_codes_are_exported():
    assert [s.name for s in sarkp.Status] == ["OK", "ASSEMBLY", "SINGULAR", "SIGNIFICANCE",
                                              "REQUIREMENT", "MISSING", "RANGE"]
    r = sarkp.DPRM1([0.0, 0.0], 0.0, [0.4, 9.0], 0.0, 0.35, 0.3, 1, on_error="nan")
    assert r.status.tolist() == [sarkp.Status.OK, sarkp.Status.ASSEMBLY]


NEAR_DEAD_CENTRE = (1.0, 0.3, 1.0, 0.3 + math.pi - 1e-10, 1.0, 0.0, 0.0, 0.0)


def test_warnings_point_at_the_callers_line():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sarkp.DSKOR1(*NEAR_DEAD_CENTRE); line_scalar = inspect.currentframe().f_lineno  # noqa: E702
        sarkp.DSKOR1(*[np.array([v, v]) for v in NEAR_DEAD_CENTRE]); line_array = inspect.currentframe().f_lineno  # noqa: E702,E501
    found = [(w.filename, w.lineno) for w in caught
             if issubclass(w.category, sarkp.SignificanceWarning)]
    assert (__file__, line_scalar) in found and (__file__, line_array) in found


# -- a type checker follows the calls (the wrappers are typed source; py.typed ships) ----

def test_mypy_checks_a_script_against_the_typed_wrappers(tmp_path):
    """A user's script passes mypy; the same calls made wrong are caught (one mypy run
    over both files)."""
    from mypy import api                        # the [test] extra installs mypy
    example = Path(__file__).parent / "typing" / "example.py"
    bad = tmp_path / "bad.py"
    bad.write_text("from sarkp import DPRM1, DUGL1\n"
                   "r = DPRM1(0.1, 0.0, 0.4, 0.0, 0.35, 0.3, -1)\n"
                   "r.FI4\n"
                   "DPRM1(0.1, 0.0)\n"
                   "DUGL1(0.0, 0.0, 1.0, 1.0, on_error='ignore')\n")
    out, err, code = api.run([str(example), str(bad), "--no-incremental", "--cache-dir",
                              str(tmp_path / "cache"), "--config-file", ""])
    report = out + err
    assert code == 1 and "example.py" not in report, report
    assert 'bad.py:3: error: "DPRM1Result" has no attribute "FI4"' in report
    assert "bad.py:4: error: Too few arguments" in report
    assert 'bad.py:5: error: Argument "on_error" has incompatible type' in report
    assert "Found 3 errors in 1 file" in report


TABLES = [n for n in NAMES if ROUTINES[n].spec.sweeps_tables]


@pytest.mark.parametrize("name", TABLES)
def test_table_fast_path_and_general_path_agree(name):
    """Float64 arrays and int counts take the generated fast path; the same values as
    lists and floats take the general one: the same result, bit for bit, or the same
    error."""
    routine, spec = ROUTINES[name], ROUTINES[name].spec
    rng = np.random.default_rng(sum(map(ord, name)) + 7)
    for _ in range(5):
        fast = [int(v) if a in spec.counts else
                np.asarray(v, dtype=float) if a in spec.tables else float(v)
                for a, v in zip(spec.inputs, _valid_inputs(spec, rng))]
        slow = [float(v) if a in spec.counts else
                np.asarray(v).tolist() if a in spec.tables else v for a, v in
                zip(spec.inputs, fast)]
        outcome = []
        for args in (fast, slow):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                try:
                    outcome.append(routine(*args))
                except (ValueError, TypeError) as exc:
                    outcome.append((type(exc), str(exc)))
        if isinstance(outcome[0], tuple) and type(outcome[0][0]) is type:
            assert outcome[0] == outcome[1], name
            continue
        for field, a, b in zip(outcome[0]._fields, outcome[0], outcome[1]):
            np.testing.assert_array_equal(a, b, err_msg=f"{name}.{field}")
