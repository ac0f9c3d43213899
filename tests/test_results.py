"""Result objects (sarkp.results) and the attributes of errors and warnings.

A result keeps the book's output names and order and behaves as a named tuple; it
pickles (also into a fresh interpreter that has not built the class yet), prints a repr
whose length does not grow with the number of positions, and converts to a DataFrame.
Errors carry status and index, a SignificanceWarning the digits left."""

import collections
import math
import pickle
import subprocess
import sys
import warnings

import numpy as np
import pytest

import sarkp
from sarkp.library import declared_routines
from sarkp.results import Result, result_type

FOURBAR = (0.1, 0.0, 0.4, 0.0, 0.35, 0.3, -1)        # DPRM1: a crank-rocker, B above AC


def crank_rocker(n):
    """DKNMA2 over n crank positions: crank 0.1 about O, rod 0.45 to a slider on the
    horizontal guide y = 0.25 (the README's slider, moved within reach)."""
    fi = np.linspace(0.0, 2 * np.pi, n)
    return sarkp.DKNMA2(0.1 * np.cos(fi), 0.1 * np.sin(fi), 0.0, 0.25, 0.0, 0.45, 0.0, 0.0,
                        1.0, fi + np.pi / 2, 0.0, 0.0, 0.0, 10.0, fi + np.pi, 0.0, 0.0, 1)


# -- the book's names and order, named-tuple behaviour -----------------------------------

def test_every_routine_returns_its_book_fields_in_order():
    routines = declared_routines()
    assert len(routines) >= 60
    for name, f in routines.items():
        spec = f.spec
        assert issubclass(spec.result, Result) and issubclass(spec.result, tuple), name
        assert spec.result._fields == tuple(spec.outputs), name
        assert spec.result_with_status._fields == tuple(spec.outputs) + ("status",), name
        assert spec.result.__name__ == name


def test_named_tuple_behaviour():
    r = sarkp.DPRM1(*FOURBAR)
    fi2, fi3, xb, yb = r
    # B from the two circles about A = (0.1, 0) and C = (0.4, 0) (radii 0.35 and 0.3)
    x = 0.1 + (0.35**2 - 0.3**2 + 0.3**2) / (2 * 0.3)
    assert xb == pytest.approx(x, rel=1e-15) and yb == pytest.approx(
        math.sqrt(0.35**2 - (x - 0.1) ** 2), rel=1e-14)
    assert (r[0], r[-1], r[1:3]) == (fi2, yb, (fi3, xb))
    assert r._fields == ("FI2", "FI3", "XB", "YB")
    assert r._asdict() == {"FI2": fi2, "FI3": fi3, "XB": xb, "YB": yb}
    assert r._replace(XB=0.0).XB == 0.0 and r.XB == xb
    assert type(r)._make([1, 2, 3, 4]) == (1, 2, 3, 4)
    assert isinstance(r, tuple) and r == (fi2, fi3, xb, yb) and len(r) == 4
    # a scalar result prints exactly as the named tuple it was before
    plain = collections.namedtuple("DPRM1", r._fields)(*r)
    assert repr(r) == repr(plain)
    match r:
        case sarkp.results.Result(FI2=a):
            assert a == fi2


# -- pickle -------------------------------------------------------------------------------

def test_scalar_and_array_results_pickle():
    r = sarkp.DPRM1(*FOURBAR)
    back = pickle.loads(pickle.dumps(r))
    assert back == r and type(back) is type(r) and back._fields == r._fields
    k = crank_rocker(37)
    back = pickle.loads(pickle.dumps(k))
    assert type(back) is type(k)
    for a, b in zip(k, back):
        np.testing.assert_array_equal(a, b)
    s = sarkp.DPRM1(0.0, 0.0, [1.0, 10.0], 0.0, 1.0, 1.0, 1, on_error="nan")
    back = pickle.loads(pickle.dumps(s))
    assert back._fields[-1] == "status"
    np.testing.assert_array_equal(back.status, [sarkp.Status.OK, sarkp.Status.ASSEMBLY])
    one = sarkp.DPRM1(0.0, 0.0, 10.0, 0.0, 1.0, 1.0, 1, on_error="nan")
    assert pickle.loads(pickle.dumps(one)).status is sarkp.Status.ASSEMBLY
    f = sarkp.DUGL1(0.0, 0.0, 1.0, 1.0, on_error="nan")       # a FUNCTION with status
    assert pickle.loads(pickle.dumps(f)) == (math.pi / 4, sarkp.Status.OK)


def test_a_result_unpickles_in_a_fresh_interpreter():
    """The class is rebuilt from its name and fields: multiprocessing and joblib send
    results to processes that never made them."""
    data = pickle.dumps(sarkp.DPRM1(*FOURBAR))
    code = ("import pickle, sys; r = pickle.loads(sys.stdin.buffer.read()); "
            "print(type(r).__name__, r._fields, r.XB == 0.3041666666666667)")
    out = subprocess.run([sys.executable, "-c", code], input=data, capture_output=True,
                         check=True).stdout.decode().strip()
    assert out == "DPRM1 ('FI2', 'FI3', 'XB', 'YB') True"


# -- a short repr -------------------------------------------------------------------------

def test_array_repr_is_short_and_does_not_grow_with_positions():
    small, large = repr(crank_rocker(37)), repr(crank_rocker(3601))
    assert large.startswith("DKNMA2(shape (3601,),") and small.startswith("DKNMA2(shape (37,),")
    # 20 fields of 6 values each: the length is the same whatever the positions
    assert len(large) < 1500 and abs(len(large) - len(small)) < 100
    assert large.count("...") == len(sarkp.DKNMA2.spec.outputs)
    k = crank_rocker(3601)
    assert f"{k.XB[0]:.6g}" in large.splitlines()[1]
    assert str(k) == repr(k)


def test_repr_of_few_positions_shows_all_values():
    s = sarkp.DPRM1(0.0, 0.0, [1.0, 10.0], 0.0, 1.0, 1.0, 1, on_error="nan")
    text = repr(s)
    assert "XB=[0.5, nan]" in text and "status=[0, 1]" in text


# -- to_frame -----------------------------------------------------------------------------

def test_to_frame_columns_in_book_order_rows_per_position():
    pd = pytest.importorskip("pandas")
    k = crank_rocker(37)
    frame = k.to_frame()
    assert list(frame.columns) == list(k._fields) and len(frame) == 37
    np.testing.assert_array_equal(frame["XB"].to_numpy(), k.XB)
    one = sarkp.DPRM1(*FOURBAR).to_frame()
    assert one.shape == (1, 4) and one["YB"].iloc[0] == sarkp.DPRM1(*FOURBAR).YB
    grid = sarkp.DPRM1(0.0, 0.0, [[1.0], [10.0]], [0.0, 0.5], 1.0, 1.0, 1, on_error="nan")
    frame = grid.to_frame()
    assert isinstance(frame.index, pd.MultiIndex) and frame.shape == (4, 5)
    assert frame.loc[(1, 0), "status"] == sarkp.Status.ASSEMBLY
    assert frame["status"].dtype.kind == "i"
    assert frame.loc[(0, 1), "XB"] == grid.XB[0, 1]


def test_to_frame_without_pandas_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)          # import pandas fails
    with pytest.raises(ImportError, match=r"sarkp\[frame\]"):
        sarkp.DPRM1(*FOURBAR).to_frame()


# -- result_type: the base other results reuse ---------------------------------------------

class Point(Result):
    __slots__ = ()

    @property
    def norm(self):
        return math.hypot(self.X, self.Y)


def test_result_type_is_reusable_and_cached():
    cls = result_type("P", ("X", "Y"), base=Point)
    assert cls is result_type("P", ["X", "Y"], base=Point)
    p = cls(3.0, 4.0)
    assert p.norm == 5.0 and repr(p) == "P(X=3.0, Y=4.0)"
    back = pickle.loads(pickle.dumps(p))
    assert type(back) is cls and back.norm == 5.0
    class Local(cls):                       # not importable: unpickles as its result class
        __slots__ = ()
    back = pickle.loads(pickle.dumps(Local(6.0, 8.0)))
    assert type(back) is cls and back.norm == 10.0
    with pytest.raises(ValueError, match="_x"):
        result_type("Q", ("_x",))
    with pytest.raises(TypeError):
        result_type("Q", ("x",), base=tuple)


# -- errors and warnings carry status, index, digits -----------------------------------------

def test_scalar_error_has_status_and_no_index():
    with pytest.raises(sarkp.AssemblyError) as info:
        sarkp.DPRM1(0.0, 0.0, 10.0, 0.0, 1.0, 1.0, 1)
    assert info.value.status is sarkp.Status.ASSEMBLY and info.value.index is None
    back = pickle.loads(pickle.dumps(info.value))
    assert (back.status, back.index, str(back)) == (sarkp.Status.ASSEMBLY, None,
                                                    str(info.value))


def test_array_error_names_first_failing_index():
    xc = np.array([[1.0, 1.5], [10.0, 20.0]])                # [1, 0] is the first too far
    with pytest.raises(sarkp.AssemblyError) as info:
        sarkp.DPRM1(0.0, 0.0, xc, 0.0, 1.0, 1.0, 1)
    assert info.value.index == (1, 0) and info.value.status == sarkp.Status.ASSEMBLY
    assert "[1, 0]" in str(info.value)


def test_singular_and_requirement_errors_have_their_status():
    with pytest.raises(sarkp.SingularError) as info:           # a dead centre (test_forces)
        sarkp.DNMA5(0.0, 0.4, 0.1, 0.1, 0, 0, 1, 10, 1, 1, 10, 1)
    assert info.value.status == sarkp.Status.SINGULAR
    for cls, status in ((sarkp.AssemblyError, 1), (sarkp.SingularError, 2),
                        (sarkp.RequirementError, 4), (sarkp.RangeError, 6)):
        assert cls("x").status == status and cls("x").index is None


def test_significance_warning_carries_digits():
    """A flat triangle: B is found from a sine of about 1e-17 relative to the links."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sarkp.DPRM1(0.0, 0.0, 2.0, -1e-17, 1.0, 1.0, 1)
        sarkp.DPRM1(0.0, 0.0, [1.0, 2.0], [0.0, -1e-17], 1.0, 1.0, 1)
    scalar, array = [w.message for w in caught
                     if issubclass(w.category, sarkp.SignificanceWarning)]
    for w in (scalar, array):
        assert w.status == sarkp.Status.SIGNIFICANCE
        assert isinstance(w.digits, int) and 1 <= w.digits <= 7
        assert f"about {w.digits} significant digit" in str(w)
    assert scalar.index is None and array.index == (1,)


def test_readme_section_runs(capsys):
    """README.md's 'Results and errors as objects' example runs and prints what it says."""
    import re
    from pathlib import Path
    text = (Path(__file__).resolve().parent.parent / "README.md").read_text()
    section = text.split("## Results and errors as objects", 1)[1].split("\n## ", 1)[0]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    namespace = {}
    exec(compile(code, "README.md", "exec"), namespace)
    printed = capsys.readouterr().out
    assert printed.startswith("DPRM1(shape (361,),") and len(printed) < 600
    assert namespace["frame"].shape == (361, 4)
    assert namespace["same"].XB.tolist() == namespace["r"].XB.tolist()
    assert printed.rstrip().endswith("1 (1,)")


def test_every_routine_result_pickles_and_converts():
    """One valid call of each of the 62 routines (the fuzz generators of
    tests/invariants.py, seed 0): the result pickles to equal values and converts to a
    frame with a column per field and a row per position."""
    from pathlib import Path
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from invariants import CASES
    pytest.importorskip("pandas")
    for name, (gen, _) in CASES.items():
        args = gen(np.random.default_rng(0))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sarkp.SignificanceWarning)
            r = getattr(sarkp, name)(*args, on_error="nan")
        back = pickle.loads(pickle.dumps(r))
        assert type(back) is type(r) and back._fields == r._fields, name
        for a, b in zip(r, back):
            np.testing.assert_array_equal(a, b, err_msg=name)
        frame = r.to_frame()
        shape = np.broadcast_shapes(*(np.shape(v) for v in r))
        assert list(frame.columns) == list(r._fields), name
        assert len(frame) == max(1, math.prod(shape)), name
        assert len(repr(r)) < 3000, name
