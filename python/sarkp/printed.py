"""The book's code as printed, compiled and callable: ``sarkp.printed.DPRM1(...)``.

The extension ``sarkp._printed`` is built from the listings in ``sarkp/listings/`` (the OCR's
misreadings corrected, nothing else) as legacy fixed-form FORTRAN in the book's own types:
REAL is single precision, as on the ES EVM, and the printed code calls sarkp's GELG in that
precision.  ``COMMON /PRMTR/`` holds the book's PI = 3.14159, as its main programs set it.
What the printed code writes to the printer (``WRITE(3, ...)``, ``PRINT``) is discarded:
importing this module connects the Fortran units 3 and 6 of the process to ``os.devnull``
and a scratch file.

Each routine takes sarkp's Python signature (``sarkp.printed.DPRM1(XA, YA, XC, YC, RZ2,
RZ3, P, AAA=1.0)``) and returns the same named tuple (a FUNCTION, a float), computed by the
printed code (COMMON results: the words of the listing's COMMON block, in order).
Arrays broadcast as in sarkp's routines (one printed call per element; the results are
arrays of the broadcast shape); a routine with tables takes numbers only and refuses an
array by name.  No checks, no errors: whatever the printed code does with bad input, it
does here.  A routine whose printed code cannot run as printed raises
:class:`PrintedCodeError` saying why (``listings/printed.csv``).
"""

from __future__ import annotations

import csv
import io
import math
import os
import re
from importlib import resources

import numpy as np

from . import _printed, listings

__all__ = ["PrintedCodeError", "names", "excluded", "program"]

_printed.prinit(os.devnull)


class PrintedCodeError(ValueError):
    """The printed code of this routine cannot run as printed (the reason is the message)."""


def _excluded() -> dict[str, str]:
    text = resources.files("sarkp").joinpath("listings", "printed.csv").read_text(
        encoding="utf-8")
    return {r["name"]: r["reason"] for r in csv.DictReader(io.StringIO(text))
            if r["runs"] != "yes"}


def excluded() -> dict[str, str]:
    """Every routine and program whose printed code does not run here, with the reason."""
    return _excluded()


def program(name: str):
    """The book's main program NAME (``"II.13"``) as printed.  None of the seven can run as
    printed: this raises :class:`PrintedCodeError` with the reason (sarkp runs the programs
    in Python: ``sarkp book run``; :func:`sarkp.book.prog_ii_13.single` runs II.13's
    statements in single precision through this module's routines)."""
    item = listings._find(name)
    if item.kind != "program":
        raise ValueError(f"{name} is a routine, not a program: sarkp.printed.{item.name}")
    raise PrintedCodeError(f"program {item.name}: the printed code cannot run as printed: "
                           f"{_excluded()[item.name]}")


def names() -> list[str]:
    """The routines whose printed code runs, in the book's order."""
    return [i.name for i in listings.listings()
            if i.kind != "program" and hasattr(_printed, i.name.lower())]


def _make(name: str):
    import sarkp
    spec = getattr(sarkp, name).spec
    fortran = getattr(_printed, name.lower())
    inputs = [a for a in spec.inputs]
    aaa = "AAA" in inputs
    # COMMON results: the words of the listing's COMMON block, in order (gen_printed.py)
    block = re.search(r"^ {6}COMMON\s*/\s*(\w+)\s*/(.*(?:\n {5}\S.*)*)",
                      listings._find(name).text(), re.M)
    words = [w.strip().lower() for w in re.sub(r"\n {5}\S", "", block.group(2)).split(",")
             ] if block else []

    def routine(*args, **kwargs):
        if aaa and len(args) == len(inputs) - 1 and "AAA" not in kwargs:
            kwargs["AAA"] = 1.0
        values = dict(zip(inputs, args))
        for key, value in kwargs.items():
            if key not in inputs or key in values:
                raise TypeError(f"{name}() got an unexpected or repeated argument {key!r}")
            values[key] = value
        missing = [a for a in inputs if a not in values]
        if missing:
            raise TypeError(f"{name}() missing {', '.join(missing)}")
        arrays = [a for a in inputs if a not in spec.tables and np.ndim(values[a])]
        if arrays:
            return sweep(values, arrays)
        return one(values)

    def sweep(values, arrays):
        """Arrays broadcast as sarkp's routines do: one printed call per element."""
        if spec.tables:
            raise ValueError(f"sarkp.printed.{name}: {', '.join(arrays)} must be a number, "
                             f"not an array: a routine with tables takes one call at a "
                             f"time here (call it in a loop)")
        try:
            grid = np.broadcast_arrays(*[np.asarray(values[a], dtype=float)
                                         for a in arrays])
        except ValueError:
            raise ValueError(f"sarkp.printed.{name}: the shapes of "
                             f"{', '.join(arrays)} do not broadcast") from None
        shape = grid[0].shape
        results = []
        for index in np.ndindex(shape):
            results.append(one({**values, **{a: float(g[index])
                                             for a, g in zip(arrays, grid)}}))
        if spec.function:
            return np.array(results, dtype=float).reshape(shape)
        fields = zip(*results) if results else [[]] * len(spec.outputs)
        return spec.result(*[np.array(f, dtype=float).reshape(shape + np.shape(f[0]))
                             if len(f) else np.empty(shape) for f in fields])

    def one(values):
        call = {}
        for a in inputs:
            v = values[a]
            call[a.lower()] = np.asarray(v, dtype=np.float32) if a in spec.tables else v
        out = fortran(**call)
        if spec.function:
            return float(out)
        out = out if isinstance(out, tuple) else () if out is None else (out,)
        if len(out) < len(spec.outputs) and block:
            common = getattr(_printed, block.group(1).lower())
            out = out + tuple(getattr(common, w) for w in words)
        # sarkp's extension outputs, which the printed code does not compute: NaN
        out = out + (math.nan,) * (len(spec.outputs) - len(out))
        return spec.result(*[np.array(o, dtype=float) if np.ndim(o) else float(o)
                             for o in out])

    routine.__name__ = routine.__qualname__ = name
    routine.__doc__ = (f"The book's printed {name} (listing {spec.listing}, {spec.lines}), "
                       f"compiled as printed in single precision.\n\nSame arguments and "
                       f"result as sarkp.{name}; see help(sarkp.{name}).")
    return routine


_cache: dict[str, object] = {}


def __getattr__(attr: str):
    if attr in _cache:
        return _cache[attr]
    key = attr.upper()
    if attr == key and hasattr(_printed, attr.lower()):
        _cache[attr] = _make(attr)
        return _cache[attr]
    reasons = excluded()
    if attr in reasons:
        raise PrintedCodeError(f"{attr}: the printed code cannot run as printed: "
                               f"{reasons[attr]}")
    raise AttributeError(f"module 'sarkp.printed' has no attribute {attr!r}")


def __dir__():
    return sorted(set(__all__) | set(names()))
