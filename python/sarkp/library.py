"""The thin layer between Python and the Fortran routines.

Each book routine is declared once, with :func:`book_routine`: its book name, its inputs
in the book's order, its outputs in the book's order, the Fortran routine for one
position and the Fortran sweep for many.  The declaration makes a Python function that

* takes the book's inputs in the book's order (``AAA`` last, defaulting to 1.0, "silent");
* checks them: NaN or inf, a non-positive length, an integer out of range raise
  ``ValueError`` naming the argument;
* with scalars, calls the scalar routine and returns a named tuple of floats;
* with arrays (any broadcastable shapes), calls the sweep, one Fortran loop over all
  positions, and returns a named tuple of arrays of the broadcast shape;
* turns the Fortran status into an exception (see :mod:`sarkp.errors`), or with
  ``on_error="nan"`` into NaN at the failing positions plus a ``status`` field;
* with ``AAA = 0`` prints the book's report for the call, where the book prints one.
"""

from __future__ import annotations

import math
import warnings
from collections import namedtuple
from typing import Callable, Mapping, Sequence

import numpy as np

from . import _sarkp
from .errors import (AssemblyError, RequirementError, SignificanceWarning,
                     SingularError)

_prmtr = _sarkp.prmtr
ST_OK = int(_prmtr.st_ok)
ST_ASSEMBLY = int(_prmtr.st_assembly)
ST_SINGULAR = int(_prmtr.st_singular)
ST_SIGNIFICANCE = int(_prmtr.st_significance)
ST_REQUIREMENT = int(_prmtr.st_requirement)

#: Python-side status: an input was NaN, i.e. an earlier step of a chain failed and
#: returned NaN under ``on_error="nan"``; the outputs there are NaN as well.
ST_MISSING = 5

STATUS_NAMES = {ST_OK: "ok", ST_ASSEMBLY: "assembly", ST_SINGULAR: "singular",
                ST_SIGNIFICANCE: "significance", ST_REQUIREMENT: "requirement",
                ST_MISSING: "missing input"}

_ERRORS = {ST_ASSEMBLY: AssemblyError, ST_SINGULAR: SingularError,
           ST_REQUIREMENT: RequirementError}

_DEFAULT_MESSAGES = {
    ST_ASSEMBLY: "the group cannot be assembled: the links do not reach",
    ST_SINGULAR: "singular position (dead centre): the book's formulas have no finite answer",
    ST_SIGNIFICANCE: "GELG reported a loss of significance (IER > 0); the result was kept",
    ST_REQUIREMENT: "the requirement cannot be met by any mechanism",
}

_SCALAR_TYPES = (float, int, np.floating, np.integer)

ON_ERROR = ("raise", "nan")


class Check:
    """A condition on the inputs that the Fortran routine does not report itself.

    ``bad`` receives the inputs by book name (floats, or broadcast arrays) and returns a
    boolean (or boolean array) that is true where the condition holds; ``status`` is the
    status it gives there and ``message`` what the error says.
    """

    def __init__(self, bad: Callable[..., object], status: int, message: str):
        self.bad = bad
        self.status = status
        self.message = message


class Routine:
    """The declaration of one book routine (see :func:`book_routine`)."""

    def __init__(self, name, listing, lines, inputs, outputs, scalar, sweep, *,
                 lengths=(), integers=None, nonnegative=(), checks=(),
                 messages=None, has_status=True, function=False, report=None,
                 sweep_inputs=None):
        self.name = name
        self.listing = listing
        self.lines = lines
        self.inputs = tuple(inputs)
        self.outputs = tuple(outputs)
        self.scalar = scalar
        self.sweep = sweep
        self.lengths = frozenset(lengths)
        self.nonnegative = frozenset(nonnegative)
        self.integers = dict(integers or {})
        self.checks = tuple(checks)
        self.messages = dict(_DEFAULT_MESSAGES)
        self.messages.update(messages or {})
        self.has_status = has_status
        self.function = function
        self.report = report
        # which inputs the sweep takes (default: all but the print flag AAA, in order)
        self.sweep_inputs = (tuple(sweep_inputs) if sweep_inputs
                             else tuple(a for a in self.inputs if a != "AAA"))
        self._strict = bool(self.lengths or self.nonnegative or self.integers)
        self._positive_at = tuple(i for i, a in enumerate(self.inputs) if a in self.lengths)
        self._nonnegative_at = tuple(i for i, a in enumerate(self.inputs)
                                     if a in self.nonnegative)
        self._integer_at = tuple(i for i, a in enumerate(self.inputs) if a in self.integers)
        self._aaa_index = self.inputs.index("AAA") if "AAA" in self.inputs else None
        if self.report is not None and self._aaa_index is None:
            raise ValueError(f"{name}: a report needs the print flag AAA among the inputs")
        self.result = namedtuple(name, self.outputs)
        self.result_with_status = namedtuple(name + "_status", self.outputs + ("status",))

    # -- validation -------------------------------------------------------------------
    def _check_scalar(self, values):
        for arg, v in zip(self.inputs, values):
            if arg in self.integers:
                allowed = self.integers[arg]
                if v != int(v) or int(v) not in allowed:
                    raise ValueError(f"{self.name}: {arg} = {v!r} is not one of "
                                     f"{sorted(allowed)}")
                continue
            if not math.isfinite(v):
                raise ValueError(f"{self.name}: {arg} = {v!r} is not a finite number")
            if arg in self.lengths and not v > 0.0:
                raise ValueError(f"{self.name}: {arg} = {v!r} is a length and must be > 0")
            if arg in self.nonnegative and v < 0.0:
                raise ValueError(f"{self.name}: {arg} = {v!r} must be >= 0")

    def _out_of_range(self, args):
        """True if a length is not positive, a bound is broken or an integer is wrong."""
        return (any(not args[i] > 0.0 for i in self._positive_at)
                or any(args[i] < 0.0 for i in self._nonnegative_at)
                or any(args[i] != int(args[i]) or int(args[i]) not in
                       self.integers[self.inputs[i]] for i in self._integer_at))

    def _check_arrays(self, arrays, shape, allow_nan):
        """Raise ValueError for a bad input; return where an input is NaN (if allowed)."""
        missing = np.zeros(shape, dtype=bool)
        for arg, a in zip(self.inputs, arrays):
            nan = np.isnan(a) if allow_nan else missing
            if arg in self.integers:
                allowed = np.array(sorted(self.integers[arg]))
                bad = ~np.isin(a, allowed) & ~nan
                what = f"is not one of {allowed.tolist()}"
            else:
                bad = ~np.isfinite(a) & ~nan
                what = "is not a finite number"
                if not bad.any():
                    if arg in self.lengths:
                        bad = ~(a > 0.0) & ~nan
                        what = "is a length and must be > 0"
                    elif arg in self.nonnegative:
                        bad = (a < 0.0) & ~nan
                        what = "must be >= 0"
            if bad.any():
                idx = _first_index(bad, shape)
                raise ValueError(f"{self.name}: {arg}{list(idx)} = {a[idx]!r} {what}")
            if allow_nan:
                missing |= nan
        return missing

    # -- the call -----------------------------------------------------------------------
    def __call__(self, args, on_error="raise"):
        if on_error != "raise" and on_error != "nan":
            raise ValueError(f"{self.name}: on_error must be 'raise' or 'nan', "
                             f"not {on_error!r}")
        # Scalars add up to a Python or NumPy scalar; any array (or list) does not.
        try:
            total = sum(args)
        except TypeError:
            return self._call_arrays(args, on_error)
        if isinstance(total, np.ndarray) or not isinstance(total, _SCALAR_TYPES):
            return self._call_arrays(args, on_error)
        return self._call_scalar(args, total, on_error)

    def _call_scalar(self, args, total, on_error):
        # The sum of the inputs is finite when every input is, except when it overflows:
        # only then, or when some input has a range to respect, look at each one.
        if not math.isfinite(total) or (self._strict and self._out_of_range(args)):
            if on_error == "nan" and math.isnan(total):   # a failed earlier step
                return self.result_with_status(*(math.nan,) * len(self.outputs), ST_MISSING)
            values = [float(a) for a in args]
            self._check_scalar(values)
        if self._integer_at:
            args = list(args)
            for i in self._integer_at:
                args[i] = int(args[i])
        status, failed_check = ST_OK, None
        if self.checks:
            named = dict(zip(self.inputs, args))
            for check in self.checks:
                if check.bad(**named):
                    status, failed_check = check.status, check
                    break
        if status == ST_OK:
            out = self.scalar(*args)
            if self.function:
                out = (out,)
            elif self.has_status:
                status = out[-1]
                out = out[:-1]
        if status != ST_OK:
            if status != ST_SIGNIFICANCE:
                if on_error == "raise":
                    raise self._error(status, None, failed_check)
                out = (math.nan,) * len(self.outputs)
            else:
                warnings.warn(f"{self.name}: {self.messages[ST_SIGNIFICANCE]}",
                              SignificanceWarning, stacklevel=4)
        if self.report is not None and args[self._aaa_index] == 0.0:
            print(self.report(dict(zip(self.inputs, args)), out))
        if on_error == "nan":
            return self.result_with_status(*out, int(status))
        return self.result(*out)

    def _call_arrays(self, args, on_error):
        given = [np.asarray(a, dtype=float) for a in args]
        arrays = np.broadcast_arrays(*given)
        shape = arrays[0].shape
        status = None                                        # None: all positions ok
        if self._strict or not all(np.isfinite(a.sum()) for a in given):
            # under on_error="nan" a NaN input (an earlier failure in a chain) passes through
            missing = self._check_arrays(arrays, shape, allow_nan=on_error == "nan")
            if missing.any():
                status = np.where(missing, ST_MISSING, ST_OK).astype(np.int32)
        # (otherwise every input is finite: a finite sum cannot hide an inf or a NaN)
        named = dict(zip(self.inputs, arrays))
        failed_check = None                                  # which check failed where
        for k, check in enumerate(self.checks):
            bad = np.broadcast_to(np.asarray(check.bad(**named), dtype=bool), shape)
            if status is not None:
                bad = bad & (status == ST_OK)
            if bad.any():
                if status is None:
                    status = np.zeros(shape, dtype=np.int32)
                    failed_check = np.full(shape, -1, dtype=np.int8)
                elif failed_check is None:
                    failed_check = np.full(shape, -1, dtype=np.int8)
                status[bad] = check.status
                failed_check[bad] = k
        flat = [np.ascontiguousarray(named[n]).ravel() for n in self.sweep_inputs]
        out = self.sweep(*flat)
        if not isinstance(out, tuple):
            out = (out,)
        if self.has_status:
            computed = np.asarray(out[-1]).reshape(shape)
            # a failed check (or a missing input) outranks whatever the routine computed
            status = computed if status is None else np.where(status != ST_OK, status,
                                                              computed)
            out = out[:-1]
        out = [np.asarray(o, dtype=float).reshape(shape) for o in out]
        if status is None:
            status = np.zeros(shape, dtype=np.int32) if on_error == "nan" else None
        else:
            def message(code, index):
                k = -1 if failed_check is None else int(failed_check[index])
                return self.checks[k].message if k >= 0 else None

            out = settle_arrays(self.name, out, status, on_error, self.messages, message)
        if on_error == "nan":
            return self.result_with_status(*out, status)
        return self.result(*out)

    def _error(self, status, index, check=None):
        """The exception for ``status``: the failed check's words, else the routine's."""
        return status_error(self.name, status, index, self.messages,
                            None if check is None else check.message)


def status_error(name, status, index, messages, message=None):
    """The exception for a failed ``status`` of routine ``name`` at ``index``."""
    where = "" if index is None else f" at index {list(index)}"
    if message is None:
        message = messages.get(status, _DEFAULT_MESSAGES.get(status, f"status {status}"))
    return _ERRORS.get(status, SingularError)(f"{name}{where}: {message}")


def settle_arrays(name, out, status, on_error, messages, message_at=None):
    """Apply the error policy to arrays ``out`` computed with ``status``.

    Raises the error of the first failed position (``on_error="raise"``) or puts NaN
    there (``"nan"``); warns once for a loss of significance.  ``message_at(status,
    index)`` may give a more precise message for a failed position.
    """
    if not status.any():                                 # the common case: all ok
        return out
    failed = (status != ST_OK) & (status != ST_SIGNIFICANCE)
    if failed.any():
        if on_error == "raise":
            idx = _first_index(failed, status.shape)
            code = int(status[idx])
            raise status_error(name, code, idx, messages,
                               message_at(code, idx) if message_at else None)
        for o in out:
            o[failed] = np.nan
    if (status == ST_SIGNIFICANCE).any():
        idx = _first_index(status == ST_SIGNIFICANCE, status.shape)
        warnings.warn(f"{name}: {messages.get(ST_SIGNIFICANCE, _DEFAULT_MESSAGES[ST_SIGNIFICANCE])}"
                      f" (first at index {list(idx)})", SignificanceWarning, stacklevel=4)
    return out


def _first_index(mask, shape):
    flat = int(np.flatnonzero(np.asarray(mask).ravel())[0])
    return tuple(int(i) for i in np.unravel_index(flat, shape)) if shape else ()


def book_routine(name: str, *, listing: str, lines: str, inputs: Sequence[str],
                 outputs: Sequence[str], scalar, sweep, doc: str,
                 defaults: Mapping[str, float] | None = None, **options):
    """Declare a book routine and return its Python function.

    Parameters
    ----------
    name, listing, lines
        The book's name (``"DVKT"``), listing number (``"II.11"``) and book lines.
    inputs, outputs
        The book's input and output names, in the book's order.
    scalar, sweep
        The f2py routine for one position (book argument order, trailing IER if
        ``has_status``) and the sweep routine over 1-D arrays.
    doc
        The numpydoc docstring.
    defaults
        Default values of trailing inputs (``AAA`` gets 1.0, "do not print", if present).
    options
        ``lengths`` (must be > 0), ``nonnegative``, ``integers`` ({name: allowed}),
        ``checks`` (:class:`Check`), ``messages`` ({status: text}), ``has_status``,
        ``function`` (the book routine is a FUNCTION), ``report`` (callable(inputs, outputs) -> text, printed for AAA = 0),
        ``sweep_inputs`` (the inputs the sweep takes, if not all).
    """
    spec = Routine(name, listing, lines, inputs, outputs, scalar, sweep, **options)
    defaults = dict(defaults or {})
    if "AAA" in spec.inputs:
        defaults.setdefault("AAA", 1.0)
    params = []
    for arg in spec.inputs:
        params.append(f"{arg}={defaults[arg]!r}" if arg in defaults else arg)
    arglist = ", ".join(spec.inputs)
    source = (f"def {name}({', '.join(params)}, *, on_error='raise'):\n"
              f"    return _spec(({arglist},), on_error)\n")
    namespace = {"_spec": spec}
    exec(source, namespace)  # a real signature: help() and inspect show the book's names
    function = namespace[name]
    function.__doc__ = doc
    function.__module__ = "sarkp"
    function.spec = spec
    return function
