"""A double with 16 significant digits survives every wrapper where the routine is the
identity on it.  Without .f2py_f2cmap, f2py maps real(dp) to C float and this fails."""

import math

import numpy as np
import pytest

import sarkp

X = 0.1234567890123456          # 16 significant digits; as a float it would be 0.12345679
ARR = np.array([X, 2 * X, 3 * X])

# (routine, arguments, index of the output that must equal X)
IDENTITIES = [
    ("DUGL3", (X, 0.0, 1.0)),                 # UGOL1 + |0|
    ("DUGL4", (X, 1.0, 1.0)),                 # UGOL1 for VEL >= 0
    ("DUGOL", (X,)),                          # non-negative: unchanged
    ("DOMEGA", (1.0, X, 1.0)),                # |X / 1|
    ("DMOMNT", (1.0, 0.0, X, math.pi / 2)),   # 1 * cos 0 * X * sin(pi/2) - 0
    ("DVKT", (0.0, 0.0, X, 0.0)),             # RZ = X
    ("DSMVKT", (X, 0.0, 0.0, 0.0)),           # L = X
]


@pytest.mark.parametrize("name, args", IDENTITIES, ids=[i[0] for i in IDENTITIES])
def test_scalar_round_trip(name, args):
    out = getattr(sarkp, name)(*args)
    assert (out if isinstance(out, float) else out[0]) == X


@pytest.mark.parametrize("name, args", IDENTITIES, ids=[i[0] for i in IDENTITIES])
def test_array_round_trip(name, args):
    arrays = [ARR * (a / X) if a == X else a for a in args]
    out = getattr(sarkp, name)(*arrays)
    np.testing.assert_array_equal(out if isinstance(out, np.ndarray) else out[0], ARR)


def test_direction_functions_keep_double_precision():
    assert sarkp.DUGL2(0.0, 0.0, 1.0, X) == math.atan2(X, 1.0)
    assert sarkp.DUGL1(0.0, 0.0, 1.0, X) == math.atan2(X, 1.0)
    assert sarkp.DUGL5(1.0, X) == math.atan(X)


def test_tables_round_trip():
    assert sarkp.DINTGR(2, 1.0, 3, [0.0, X]).FINT[1] == X          # H * Y(2)
    assert sarkp.DFRNCL(2, 1.0, [0.0, X]).FDIF[1] == X             # (Y(2) - Y(1)) / 1
    assert sarkp.GELG([X], [[1.0]], 1, 1, 1e-4).R[0] == X


def _wrappers():
    from sarkp import _sarkp
    for module in dir(_sarkp):
        if not module.startswith("drv_"):
            continue
        mod = getattr(_sarkp, module)
        for name in dir(mod):
            obj = getattr(mod, name)
            if callable(obj) and getattr(obj, "__doc__", None) and "Wrapper for" in obj.__doc__:
                yield f"{module}.{name}", obj.__doc__


def test_every_array_argument_of_every_wrapper_is_double():
    """f2py writes array('f') for a real(dp) it mapped to C float."""
    docs = dict(_wrappers())
    assert len(docs) > 60
    single = [name for name, doc in docs.items() if "array('f')" in doc]
    assert single == []


def test_scalar_and_array_paths_agree_bit_for_bit_in_every_chapter():
    """The scalar wrappers pass doubles too: the same positions through both paths."""
    fi = np.array([0.1234567890123456, 1.2345678901234567, 4.567890123456789])
    xa, ya = 0.1 * np.cos(fi), 0.1 * np.sin(fi)
    arrays = sarkp.DPRM1(xa, ya, 0.4, 0.0, 0.35, 0.3, 1)
    for k in range(fi.size):
        assert tuple(sarkp.DPRM1(float(xa[k]), float(ya[k]), 0.4, 0.0, 0.35, 0.3, 1)) == \
            tuple(float(a[k]) for a in arrays)
    kw = np.array([1.2345678901234567, 1.5, 1.75])
    arrays = sarkp.DSNTZ2(kw, math.pi / 6, 0.5, 0.75, math.pi / 18, math.pi / 3)
    for k in range(kw.size):
        scalar = sarkp.DSNTZ2(float(kw[k]), math.pi / 6, 0.5, 0.75, math.pi / 18, math.pi / 3)
        assert tuple(scalar) == tuple(float(a[k]) for a in arrays)
