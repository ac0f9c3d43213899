"""The thin layer between Python and the Fortran routines: broadcasting, the call and
the error policy.

Each book routine's interface is written once, beside its Fortran, as argument lines
(fortran/gen_drivers.py describes them).  At build time they give the drivers
``NAME_1`` (one call) and ``NAME_n`` (a loop over positions), and the module
``sarkp._wrap_<chapter>`` of typed Python wrappers, each holding a :class:`Routine`;
the chapter module adds the prose of the docstring, the checks (conditions on several
inputs that the Fortran does not report itself) and the report, with :func:`describe`.

Where each rule lives, once:

* the rule of every input VALUE (finite, > 0, >= 0, not 0, a branch, an integer in a
  range), for scalars, table elements and every position of a sweep alike: the
  generated Fortran drivers (``screen`` in gen_drivers.py), before any work;
* types, shapes, broadcasting and the counts of tables: here, :meth:`Routine.__call__`;
* the outputs of a failed position (NaN): the drivers;
* the status codes: prmtr.f90 (:class:`sarkp.Status` takes its values from it);
* the words of every message: here.

A wrapped routine

* takes the book's inputs in the book's order (``AAA`` last, defaulting to 1.0, "silent");
  a count (the book's ``N`` or ``M``) stays where the book has it and must equal the length
  of its tables;
* rejects bad input with ``TypeError`` (strings, None, complex, masked arrays, objects) or
  ``ValueError`` (NaN, inf, a non-positive length, an integer out of range, a wrong shape),
  naming the routine and the argument;
* with scalars returns a named tuple of floats (a book FUNCTION returns a float);
* with arrays of any broadcastable shapes computes every position in one Fortran loop and
  returns arrays of the broadcast shape (an input that is the same everywhere is passed to
  Fortran once, not broadcast into a full array);
* passes the caller's mode (:mod:`sarkp.modes`) into the same Fortran call;
* turns the Fortran status into an exception (:mod:`sarkp.errors`), or with
  ``on_error="nan"`` into NaN at the failing positions plus a ``status`` field
  (:class:`sarkp.Status`);
* with ``AAA = 0`` prints the book's report for the call, where the book prints one.
"""

from __future__ import annotations

import inspect
import math
import os
import re
import sys
import textwrap
import warnings
from typing import TYPE_CHECKING, Any, Callable, Literal, NamedTuple, Optional, TypeVar, Union

import numpy as np

from . import _sarkp
from .errors import (AssemblyError, RangeError, RequirementError, SignificanceWarning,
                     SingularError, Status)
from .modes import MODE_CODE

if TYPE_CHECKING:
    from numpy.typing import ArrayLike, NDArray
else:                                   # the annotations of the generated wrappers
    ArrayLike = NDArray = Any

#: a result: a float for scalar inputs, an array of the broadcast shape for arrays
Output = Union[float, "NDArray[np.float64]"]
OnError = Literal["raise", "nan"]
Out = Optional["NDArray[np.float64]"]

ST_OK = Status.OK
ST_ASSEMBLY = Status.ASSEMBLY
ST_SINGULAR = Status.SINGULAR
ST_SIGNIFICANCE = Status.SIGNIFICANCE
ST_REQUIREMENT = Status.REQUIREMENT
ST_MISSING = Status.MISSING
ST_RANGE = Status.RANGE
#: Fortran's 100 + d: kept, with about d significant digits left (prmtr's st_digits).
ST_DIGITS = int(_sarkp.prmtr.st_digits)

STATUS_NAMES = {s.value: s.name.lower() for s in Status}

_ERRORS = {ST_ASSEMBLY: AssemblyError, ST_SINGULAR: SingularError,
           ST_REQUIREMENT: RequirementError, ST_RANGE: RangeError}

_DEFAULT_MESSAGES = {
    ST_ASSEMBLY: "the group cannot be assembled: the links do not reach",
    ST_SINGULAR: "singular position (dead centre): the book's formulas have no finite answer",
    ST_SIGNIFICANCE: "GELG reported a loss of significance (IER > 0); the result was kept",
    ST_REQUIREMENT: "the requirement cannot be met by any mechanism",
    ST_RANGE: "the result overflows double precision",
}

ON_ERROR_DOC = """
    Other Parameters
    ----------------
    on_error : {"raise", "nan"}, keyword-only
        ``"raise"`` (default): a failure raises its error (for arrays, naming the first
        failing index).  ``"nan"``: failing positions give NaN and the result gets a last
        field ``status`` (an int, or an int32 array of the broadcast shape) holding a
        :class:`sarkp.Status` code per position: 0 OK, 1 ASSEMBLY, 2 SINGULAR,
        3 SIGNIFICANCE (kept, digits lost), 4 REQUIREMENT, 5 MISSING (a NaN input, e.g.
        from a failed earlier step, passes through), 6 RANGE (overflow).
"""

OUT_DOC = """    out : ndarray, optional, keyword-only
        For sweeps over arrays (routines without counted tables): a writeable
        C-contiguous float64 array of shape ``(number of results,) + broadcast shape``.
        Result k is computed into ``out[k]`` and returned as that row (a view), so a
        loop of calls on the same shape allocates nothing.  Where a position fails, its
        cells hold NaN with ``on_error="nan"``; after an error the contents are undefined.
"""

_FLOAT64 = np.dtype(np.float64)
_NDARRAY = np.ndarray
_BIG = 2**53                    # ints below it are exactly floats
_NUMBER, _COUNT, _TABLE, _WRITTEN = range(4)
#: what the scalar path takes (a bool is an int; complex, strings, arrays go the long way)
_SCALARS = frozenset({float, int, bool, np.float64, np.float32, np.int64, np.int32})
_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
# for the generated wrappers' common case
_F, _I, _new, _mode = float, int, tuple.__new__, MODE_CODE.get
_A, _D = np.ndarray, np.dtype(np.float64)

# the screen kinds of gen_drivers.py
K_REAL, K_POSITIVE, K_NONNEGATIVE, K_NONZERO, K_BRANCH, K_INTEGER = range(6)


class Rule(NamedTuple):
    """The rule of one input, from its argument line (fortran/gen_drivers.py)."""
    name: str                   # the book's name
    kind: int                   # K_*
    word: str                   # as written: real, length, real > 0, integer 1..3, ...
    lo: int = 0
    hi: int = 0
    table: tuple = ()           # the dims of a table (count names, or sizes as text)
    destroyed: bool = False     # an inout table the routine overwrites, not returned

    def broken(self) -> str:
        """What a value outside this rule is told (after ``ARG = value``)."""
        if self.kind == K_POSITIVE:
            return "is a length and must be > 0" if self.word == "length" else "must be > 0"
        if self.kind == K_NONNEGATIVE:
            return "must be >= 0"
        if self.kind == K_NONZERO:
            return "must not be 0"
        if self.kind == K_BRANCH:
            return "is not one of [-1, 1] (an assembly branch)"
        if self.kind == K_INTEGER:
            return f"is not one of the integers {self.lo}..{self.hi}"
        return "is not a finite number"

    def holds(self, v: float) -> bool:
        """The rule, for a count of tables (the only values checked in Python: the
        drivers screen every other)."""
        return (self.kind != K_INTEGER or (v == int(v) and self.lo <= v <= self.hi)) \
            if math.isfinite(v) else False


class Check:
    """A condition on several inputs that the Fortran routine does not report itself.

    ``bad`` receives the inputs by book name (floats, or arrays that broadcast) and
    returns a boolean (or boolean array) that is true where the condition holds;
    ``status`` is the status it gives there and ``message`` what the error says.  Checks
    are evaluated before the Fortran call, which screens the inputs and then skips the
    positions they ruled out, in the scalar and the array paths alike.
    """

    def __init__(self, bad: Callable[..., object], status: int, message: str):
        self.bad = bad
        self.status = status
        self.message = message


class _Broken(Check):
    """A check that raised: the call is ruled out; if the driver finds no input outside
    its rule, the check's exception is raised after all."""

    def __init__(self, exc):
        super().__init__(None, ST_REQUIREMENT, str(exc))
        self.exc = exc


def _caller_stacklevel():
    """stacklevel for warnings.warn that points at the first frame outside sarkp."""
    frame, level = sys._getframe(1), 1
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE_DIR):
        frame, level = frame.f_back, level + 1
    return level


def _first_index(mask, shape):
    flat = int(np.flatnonzero(np.asarray(mask).ravel())[0])
    return tuple(int(i) for i in np.unravel_index(flat, shape)) if shape else ()


def _where(index):
    """``[i, j]`` after an argument's name, or nothing for a scalar."""
    return f"[{', '.join(map(str, index))}]" if index else ""


def _type_error(name, arg, value):
    return TypeError(f"{name}: {arg} must be a real number or an array of real numbers, "
                     f"not {type(value).__name__} {value!r:.60}")


def as_real_array(name, arg, value):
    """``value`` as a float ndarray, or TypeError/ValueError naming ``name`` and ``arg``."""
    if value is None or isinstance(value, (str, bytes, np.ma.MaskedArray)):
        raise _type_error(name, arg, value)
    try:
        a = np.asarray(value)
    except (ValueError, TypeError):                 # ragged lists and the like
        raise ValueError(f"{name}: {arg} is not a regular array of numbers (its rows "
                         f"differ in length, or it mixes numbers and sequences)") from None
    kind = a.dtype.kind
    if kind == "O":
        try:
            a = a.astype(float)
        except OverflowError:
            raise ValueError(f"{name}: {arg} holds an integer too large for a double") \
                from None
        except (TypeError, ValueError):
            raise _type_error(name, arg, value) from None
    elif kind not in "biuf":
        raise _type_error(name, arg, value)
    return np.asarray(a, dtype=float)


def _too_large(name, arg, value):
    digits = str(abs(int(value)))
    sign = "-" if value < 0 else ""
    return ValueError(f"{name}: {arg} = {sign}{digits[:8]}... (an integer of {len(digits)} "
                      f"digits) is too large for a double")


def _as_float(name, arg, value):
    """A scalar input as a float, or TypeError/ValueError naming ``arg``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        if isinstance(value, (str, bytes)) or as_real_array(name, arg, value).ndim:
            raise _type_error(name, arg, value)
        return float(as_real_array(name, arg, value)[()])
    try:
        return float(value)
    except OverflowError:
        raise _too_large(name, arg, value) from None


class Routine:
    """One book routine: its interface (generated from its argument lines), and what
    its chapter module adds (:func:`describe`)."""

    def __init__(self, name, chapter, *, function, inputs, outputs, integer_outputs, one,
                 many, result, result_with_status, kept=None):
        self.name = name
        self.chapter = chapter
        self.function = function
        self.rules = tuple(Rule(*r) for r in inputs)
        self.inputs = tuple(r.name for r in self.rules)
        self.outputs = tuple(outputs)
        self.integer_outputs = frozenset(integer_outputs)
        #: {status: outputs still valid after a failure with that status}
        self.kept = {st: frozenset(names) for st, names in (kept or {}).items()}
        self.one = one
        self.many = many
        self.result = result
        self.result_with_status = result_with_status
        self.tables = {r.name: tuple(int(d) if d.isdigit() else d for d in r.table)
                       for r in self.rules if r.table}
        self.counts = {d for dims in self.tables.values() for d in dims if isinstance(d, str)}
        self.sweeps_tables = bool(self.counts)       # tables counted by an argument
        self._fixed = {a: d[0] for a, d in self.tables.items() if not self.counts & set(d)}
        self._returned_tables = [k for k, o in enumerate(self.outputs) if o in self.tables]
        self._shape_rules = [(a, axis, d) for a, dims in self.tables.items()
                             for axis, d in enumerate(dims)]
        # how the table path takes each input: a number, a count, a table, a table the
        # routine writes (copied first); with the table's number of dimensions
        self._table_plan = [
            (r.name, (_WRITTEN if r.destroyed or r.name in self.outputs else _TABLE)
             if r.table else _COUNT if r.name in self.counts else _NUMBER, len(r.table), r)
            for r in self.rules]
        self._aaa_index = self.inputs.index("AAA") if "AAA" in self.inputs else None
        self.listing = self.lines = ""
        self.checks = ()
        self.messages = dict(_DEFAULT_MESSAGES)
        self.report = None
        self.example = None
        self.fast = not self._fixed and not self.counts

    # -- what the tests and the book's programs read (the rules, by kind) -----------------
    @property
    def lengths(self):
        return frozenset(r.name for r in self.rules if r.word == "length")

    @property
    def nonnegative(self):
        """>= 0 (a ``real > 0`` input is too: it was declared >= 0 and != 0)."""
        return frozenset(r.name for r in self.rules if r.kind == K_NONNEGATIVE
                         or r.word == "real > 0")

    @property
    def nonzero(self):
        return frozenset(r.name for r in self.rules if r.kind == K_NONZERO
                         or r.word == "real > 0")

    @property
    def positive(self):
        return frozenset(r.name for r in self.rules if r.kind == K_POSITIVE)

    @property
    def integers(self):
        """{input: the allowed values} of the integer inputs (a range, or (-1, 1))."""
        return {r.name: (-1, 1) if r.kind == K_BRANCH else range(r.lo, r.hi + 1)
                for r in self.rules if r.kind in (K_INTEGER, K_BRANCH)}

    # -- messages ------------------------------------------------------------------------
    def _bad_input(self, k, value, index=()):
        rule = self.rules[k]
        what = "is not a finite number" if not math.isfinite(value) else rule.broken()
        if rule.kind in (K_INTEGER, K_BRANCH) and math.isfinite(value) and value == int(value):
            value = int(value)
        return ValueError(f"{self.name}: {rule.name}{_where(index)} = {value!r} {what}")

    def _range_message(self, mask):
        """The message of status RANGE; ``mask`` (the driver's -sarkp_bad) has bit k - 1
        set for result k that is not a finite double."""
        names = [n for k, n in enumerate(self.outputs[:30]) if mask >> k & 1]
        return (f"{', '.join(names) or 'a result'} would not be a finite double "
                f"(overflow); the inputs are too far apart in magnitude")

    def _range_mask(self, values, index):
        """The mask of the results that overflow at position ``index`` of a sweep: that
        position computed again, alone, by the one-call driver (only for the message)."""
        one = [float(np.asarray(v)[index]) if np.ndim(v) else float(v) for v in
               np.broadcast_arrays(*[np.asarray(v, dtype=float) for v in values])]
        return -int(self.one(MODE_CODE.get(), *one)[-1])

    def _result(self, out, status):
        if self.function:
            return out[0] if status is None else self.result_with_status(out[0], status)
        if status is None:
            return self.result(*out)
        return self.result_with_status(*out, status)

    # -- the call ------------------------------------------------------------------------
    def __call__(self, args, on_error="raise", out=None):
        if on_error != "raise" and on_error != "nan":
            raise ValueError(f"{self.name}: on_error must be 'raise' or 'nan', "
                             f"not {on_error!r}")
        if self.sweeps_tables:
            return self._call_tables(args, on_error)
        if out is None and not self._fixed and all(type(a) in _SCALARS for a in args):
            return self._call_scalar(args, on_error)
        return self._call_arrays(args, on_error, out)

    def _skip(self, named, quiet=True):
        """The first check that rules the inputs out, or None.  The checks see the
        inputs before the driver screens them: a check that fails on a value outside
        its rule (math.sin(inf), say) rules the call out, and the driver's screen then
        names the value; should the inputs pass the screen, the check's own error is
        raised (:class:`_Broken`).  ``quiet``: NumPy's floating-point warnings off (the
        sweeps; the table path's checks do no arithmetic that could warn)."""
        try:
            if quiet:
                with np.errstate(all="ignore"):
                    for check in self.checks:
                        if check.bad(**named):
                            return check
            else:
                for check in self.checks:
                    if check.bad(**named):
                        return check
        except (ArithmeticError, ValueError, TypeError, Warning) as exc:
            return _Broken(exc)
        return None

    def _call_scalar(self, args, on_error):
        check = None
        if self.checks:
            check = self._skip({a: np.float64(_as_float(self.name, a, v))
                                for a, v in zip(self.inputs, args)})
        try:
            o = self.one(MODE_CODE.get(), *args, check.status if check else 0)
        except OverflowError:                           # an integer beyond a double
            for a, v in zip(self.inputs, args):
                _as_float(self.name, a, v)
            raise
        if type(check) is _Broken and o[-1] == 0:
            raise check.exc
        return self._settle_one(args, list(o[:-2]), int(o[-2]), int(o[-1]), -1, check,
                                on_error)

    def _settle_one(self, args, out, status, bad, at, check, on_error):
        """The error policy for one call: ``status`` and ``bad`` (input number + 1, its
        element ``at``) from the driver, whose outputs are NaN where it failed."""
        mask = 0
        if bad < 0:                                 # the results that overflowed
            bad, mask = 0, -bad
        if (bad or status != ST_OK) and self.integer_outputs:
            # an integer result cannot hold the driver's NaN: a failure gives NaN here
            failed = bad or not (status == ST_SIGNIFICANCE or status > ST_DIGITS)
            if failed:
                out = [math.nan if name in self.integer_outputs else o
                       for name, o in zip(self.outputs, out)]
        if bad:
            k = bad - 1
            value = args[k]
            if self.rules[k].table:
                index = tuple(int(i) for i in np.unravel_index(at - 1, value.shape, order="F"))
                value = float(value[index])
            else:
                index, value = (), float(value)
            if math.isnan(value) and on_error == "nan":
                return self._result(out, Status.MISSING)
            raise self._bad_input(k, value, index)
        if status != ST_OK:
            if status == ST_SIGNIFICANCE or status > ST_DIGITS:
                warnings.warn(SignificanceWarning(
                    f"{self.name}: {_significance_message(self.messages, status)}",
                    digits=_digits(status)), stacklevel=_caller_stacklevel())
            elif on_error == "raise":
                message = check.message if check is not None else None
                if status == ST_RANGE:
                    message = self._range_message(mask)
                error = status_error(self.name, status, None, self.messages, message)
                if self.kept.get(status) and check is None:
                    # what is still valid (the driver kept it): on_error="nan"'s result
                    error.result = self._result(out, Status(_status_code(status)))
                raise error
            status = _status_code(status)
        if self.report is not None and args[self._aaa_index] == 0.0 and \
                status in (ST_OK, ST_SIGNIFICANCE):
            print(self.report(dict(zip(self.inputs, args)), tuple(out)))
        return self._result(out, Status(status) if on_error == "nan" else None)

    def _out_buffer(self, out, shape):
        """The caller's ``out=``, checked: one row per result, each of the broadcast
        shape, written in place (C order, float64)."""
        want = (len(self.outputs),) + shape
        if type(out) is not np.ndarray or out.dtype != _FLOAT64 or out.shape != want \
                or not out.flags.c_contiguous or not out.flags.writeable:
            got = (f"a {out.dtype} array of shape {out.shape}"
                   + ("" if out.flags.c_contiguous else ", not C-contiguous")
                   + ("" if out.flags.writeable else ", read-only")
                   if isinstance(out, np.ndarray) else type(out).__name__)
            raise ValueError(f"{self.name}: out must be a writeable C-contiguous float64 "
                             f"array of shape {want} (a row for each of "
                             f"{', '.join(self.outputs)}), not {got}")
        return out

    def _call_arrays(self, args, on_error, buffer=None):
        allow_nan = on_error == "nan"
        # pass 1: Python numbers stay as they are (Fortran gets them once, inc 0); the
        # rest become float64 arrays, whose shapes broadcast
        values, arrays, shapes, fixed = list(args), [], set(), self._fixed
        for k, a in enumerate(args):
            t = type(a)
            if t is float:
                continue
            if t is int:
                values[k] = _as_float(self.name, self.inputs[k], a)
                continue
            if t is not np.ndarray or a.dtype != _FLOAT64:
                a = values[k] = as_real_array(self.name, self.inputs[k], a)
            arrays.append(k)
            if fixed and self.inputs[k] in fixed:
                size = fixed[self.inputs[k]]
                if a.ndim < 1 or a.shape[-1] != size:
                    raise ValueError(f"{self.name}: {self.inputs[k]} must hold {size} values "
                                     f"(last axis of length {size}), not shape {a.shape}")
                shapes.add(a.shape[:-1])
            elif a.ndim:
                shapes.add(a.shape)
        if len(shapes) == 1:
            (shape,) = shapes
        else:
            try:
                shape = np.broadcast_shapes(*shapes)
            except ValueError:
                raise ValueError(f"{self.name}: the shapes of the inputs do not broadcast: "
                                 + ", ".join(f"{a} {np.shape(v)}" for a, v in
                                             zip(self.inputs, values))) from None
        n = math.prod(shape)
        # the results: the rows of one array, the caller's out= or a new one (one
        # allocation per call, none with out=); Fortran fills column k of its transpose
        nres = len(self.outputs)
        if buffer is None:
            buffer = np.empty((nres,) + shape)
        else:
            buffer = self._out_buffer(buffer, shape)
        out = list(buffer) if buffer.ndim > 1 else [buffer[i, ...] for i in range(nres)]
        if n == 0:
            return self._result(out, np.zeros(shape, np.int32) if allow_nan else None)
        # the checks rule positions out before the call (the driver screens them first)
        status = np.zeros(shape, np.int32)
        failed_check = None
        if self.checks:
            named = dict(zip(self.inputs, values))
            with np.errstate(all="ignore"):
                for k, check in enumerate(self.checks):
                    fails = np.broadcast_to(np.asarray(check.bad(**named), dtype=bool),
                                            shape) & (status == 0)
                    if fails.any():
                        if failed_check is None:
                            failed_check = np.full(shape, -1, dtype=np.int8)
                        status[fails] = check.status
                        failed_check[fails] = k
        # pass 2: each array as Fortran walks it, one element per position (inc 1) or
        # one for all (inc 0)
        flat, incs = list(values), [0] * len(values)
        for k in arrays:
            a = values[k]
            if fixed and self.inputs[k] in fixed:
                size = fixed[self.inputs[k]]
                if math.prod(a.shape[:-1]) == 1:
                    flat[k] = a.reshape(size, 1)
                else:
                    flat[k] = np.broadcast_to(a, shape + (size,)).reshape(n, size).T
                    incs[k] = 1
            elif a.size == 1:
                if a.ndim != 1:
                    flat[k] = a.reshape(1)
            else:
                if a.shape != shape:
                    a = np.broadcast_to(a, shape)
                flat[k] = a if a.ndim == 1 else a.reshape(n)
                incs[k] = 1
        bad = self.many(MODE_CODE.get(), incs, allow_nan, *flat, buffer.reshape(nres, n).T,
                        status.reshape(n))              # f2py takes n from sarkp_out
        if bad[0]:
            k, j = int(bad[0]) - 1, int(bad[1]) - 1
            a = np.asarray(flat[k])
            if self.inputs[k] in fixed:                 # element l of position j
                j, l = divmod(j, fixed[self.inputs[k]])
                value = float(a[l, j])
            else:
                value = float(a.ravel()[j])
            where = tuple(int(i) for i in np.unravel_index(j, shape)) if incs[k] else ()
            raise self._bad_input(k, value, where)
        if bad[2]:                                      # positions whose status is not OK
            def message(code, index):
                if code == ST_RANGE and not self._fixed:
                    return self._range_message(self._range_mask(values, index))
                k = -1 if failed_check is None else int(failed_check[index])
                return self.checks[k].message if k >= 0 else None

            status = settle_arrays(self.name, status, on_error, self.messages, message)
        if shape == ():
            out = [float(o) for o in out]
            if self.report is not None and float(values[self._aaa_index]) == 0.0 and \
                    int(status) in (ST_OK, ST_SIGNIFICANCE):
                print(self.report(dict(zip(self.inputs, values)), tuple(out)))
            return self._result(out, Status(int(status)) if allow_nan else None)
        return self._result(out, status if allow_nan else None)

    def _table(self, arg, ndim, value):
        """A table input as a float64 array of ``ndim`` dimensions (a column for a
        one-dimensional value where two are wanted), or TypeError/ValueError."""
        a = np.asarray(as_real_array(self.name, arg, value), dtype=_FLOAT64)
        if a.ndim == 1 and ndim == 2:                       # a single column (GELG's R)
            a = a.reshape(-1, 1)
        if a.ndim != ndim:
            raise ValueError(f"{self.name}: {arg} must be {('one', 'two')[ndim - 1]}-"
                             f"dimensional, not of shape {np.shape(value)}")
        return a

    def _call_tables(self, args, on_error):
        """A routine with tables counted by an argument: one Fortran call, no sweep.
        Here only types and shapes are looked at (and the counts, which are shapes);
        the driver screens every value."""
        named, actual, given = {}, [], {}
        if on_error != "raise" and on_error != "nan":
            raise ValueError(f"{self.name}: on_error must be 'raise' or 'nan', "
                             f"not {on_error!r}")
        for (arg, what, ndim, rule), value in zip(self._table_plan, args):
            if what >= _TABLE:
                if type(value) is _NDARRAY and value.dtype is _FLOAT64 and \
                        value.ndim == ndim:
                    a = value
                else:
                    a = self._table(arg, ndim, value)
                named[arg] = a
                if what == _WRITTEN:                        # the routine overwrites it
                    given[arg] = np.shape(value)
                    a = np.array(a, order="F")
                actual.append(a.ravel(order="F") if ndim > 1 else a)
            else:
                t = type(value)
                v = value if t is float else float(value) if t is int and \
                    -_BIG < value < _BIG else _as_float(self.name, arg, value)
                if what == _COUNT:                          # a count: the shapes' business
                    if not rule.holds(v):
                        raise self._bad_input(self.inputs.index(arg), v)
                    v = int(v)
                named[arg] = v
                actual.append(v)
        for arg, axis, d in self._shape_rules:
            want = named[d] if d.__class__ is str else d
            if named[arg].shape[axis] != want:
                count = f"{d} = {want}" if isinstance(d, str) else f"{want}"
                raise ValueError(f"{self.name}: {arg} has shape {named[arg].shape}: "
                                 f"{named[arg].shape[axis]} along axis {axis}, but {count}")
        check = self._skip(named, quiet=False) if self.checks else None
        o = self.one(MODE_CODE.get(), *actual, check.status if check else 0)
        if type(check) is _Broken and o[-2] == 0:
            raise check.exc
        if o[-3] == 0 and o[-2] == 0 and self.report is None and on_error == "raise" and \
                not self._returned_tables:
            return _new(self.result, o[:-3])
        out = list(o[:-3])
        for k in self._returned_tables:             # an inout table: the input's shape
            out[k] = out[k].reshape(given[self.outputs[k]], order="F")
        return self._settle_one([named[a] for a in self.inputs], out, int(o[-3]), int(o[-2]),
                                int(o[-1]), check, on_error)


def _describe_doc(func, doc, sweeps):
    """The docstring: the chapter's prose with the generated Parameters section put
    before its Returns (or Raises, Warns, Notes; else at its end), and the keyword-only
    arguments after it all."""
    generated = inspect.cleandoc(func.__doc__ or "")
    params = generated[generated.index("Parameters\n"):] if "Parameters\n" in generated \
        else ""
    prose = inspect.cleandoc(doc)
    m = re.search(r"^(Returns|Raises|Warns|Notes)\n-+$", prose, re.M)
    if m:
        prose = prose[:m.start()] + params + "\n\n" + prose[m.start():]
    else:
        prose += "\n\n" + params
    tail = textwrap.dedent(ON_ERROR_DOC) + (textwrap.dedent(OUT_DOC) if sweeps else "")
    text = prose.rstrip() + "\n" + tail
    first, *rest = text.splitlines()
    return "\n".join([first] + [("    " + line).rstrip() for line in rest]) + "\n"


F = TypeVar("F", bound=Callable[..., Any])


def describe(func: F, *, listing: str, lines: str, doc: str, checks=(), messages=None,
             report=None, example=None) -> F:
    """Complete the generated wrapper ``func`` of a book routine with what its chapter
    module knows and its argument lines do not; return it.

    Parameters
    ----------
    func
        The generated wrapper (``sarkp._wrap_<chapter>.NAME``).
    listing, lines
        The book's listing number (``"II.11"``) and book lines.
    doc
        The numpydoc docstring without its Parameters section (generated from the
        argument lines and put before the Returns section); the description of
        ``on_error`` (and ``out``) is appended.
    checks
        :class:`Check` conditions on several inputs, evaluated before the Fortran call.
    messages
        ``{status: text}`` for the routine's failures.
    report
        ``callable(inputs, outputs) -> text``, printed for ``AAA = 0``.
    example
        A valid input row in the book's order, for the generic tests.
    """
    spec = getattr(sys.modules[func.__module__], "_" + func.__name__)
    spec.listing, spec.lines = listing, lines
    spec.checks = tuple(checks)
    spec.messages.update(messages or {})
    spec.report = report
    spec.example = None if example is None else tuple(float(v) for v in example)
    if report is not None and spec._aaa_index is None:
        raise TypeError(f"{spec.name}: a report needs the print flag AAA among the inputs")
    spec.fast = spec.fast and not spec.checks and report is None
    func.__doc__ = _describe_doc(func, doc, not spec.sweeps_tables)
    func.spec = spec                                    # type: ignore[attr-defined]
    return func


def _status_code(status):
    """The public code of a Fortran status (100 + d is a loss of significance; 10 c + k,
    k = 1..9, is code c for the k-th of a routine's reasons, each with its message)."""
    if status > ST_DIGITS:
        return ST_SIGNIFICANCE
    return int(status) // 10 if 10 <= status < 100 else int(status)


def _digits(status):
    """The significant digits left by a Fortran status 100 + d, or None (GELG IER > 0)."""
    return int(status) - ST_DIGITS if status > ST_DIGITS else None


def _significance_message(messages, status):
    if status > ST_DIGITS:
        d = int(status) - ST_DIGITS
        return (f"near a singular position only about {d} significant digit"
                f"{'s' if d != 1 else ''} of the result can be trusted "
                f"(estimated relative error 1e-{d}); the result was kept")
    return messages.get(ST_SIGNIFICANCE, _DEFAULT_MESSAGES[ST_SIGNIFICANCE])


def status_error(name, status, index, messages, message=None):
    """The exception for a failed ``status`` of routine ``name`` at ``index`` (None or
    () for a scalar)."""
    where = f" at index {list(index)}" if index else ""
    code = _status_code(status)
    if message is None:
        message = messages.get(status) or messages.get(code) or \
            _DEFAULT_MESSAGES.get(code, f"status {status}")
    return _ERRORS.get(code, SingularError)(f"{name}{where}: {message}", status=code,
                                            index=index or None)


def settle_arrays(name, status, on_error, messages, message_at=None):
    """Apply the error policy to a ``status`` array (the outputs of failed positions
    are NaN already: the drivers set them).

    Raises the error of the first failed position (``on_error="raise"``); warns once
    for a loss of significance.  ``message_at(status, index)`` may give a more precise
    message for a failed position.  Returns ``status`` with Fortran's 100 + d codes
    mapped to SIGNIFICANCE and its reason codes 10 c + k to c.
    """
    lost = (status == ST_SIGNIFICANCE) | (status > ST_DIGITS)
    failed = (status != ST_OK) & ~lost
    if on_error == "raise" and failed.any():
        idx = _first_index(failed, status.shape)
        code = int(status[idx])
        raise status_error(name, code, idx, messages,
                           message_at(code, idx) if message_at else None)
    if lost.any():
        idx = _first_index(lost, status.shape)
        digits = status[status > ST_DIGITS]
        worst = int(digits.min()) if digits.size else ST_SIGNIFICANCE
        warnings.warn(SignificanceWarning(
            f"{name}: {_significance_message(messages, worst)}"
            + (f" (first at index {list(idx)})" if idx else ""), digits=_digits(worst),
            index=idx or None), stacklevel=_caller_stacklevel())
        status = np.where(status > ST_DIGITS, ST_SIGNIFICANCE, status).astype(np.int32)
    reason = (status >= 10) & (status < 100)             # 10 c + k: code c
    if reason.any():
        status = np.where(reason, status // 10, status).astype(np.int32)
    return status


def declared_routines():
    """Every book routine, by name (for the tests)."""
    import sarkp
    return {n: getattr(sarkp, n) for n in sarkp.__all__
            if hasattr(getattr(sarkp, n, None), "spec")}

