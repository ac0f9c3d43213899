"""The thin layer between Python and the Fortran routines.

Each book routine is declared once, with :func:`book_routine`: its book name, chapter,
listing, inputs and outputs in the book's order, which inputs are tables (and which count
argument gives their length), which are lengths, integers or otherwise bounded, and the
conditions the Fortran does not report itself.  The Fortran side needs nothing more: the
drivers ``NAME_1`` (one call) and ``NAME_n`` (a loop over positions) are generated at build
time from the chapter module's argument list (fortran/gen_drivers.py), and the declaration
is checked against the signature f2py reports when the module is imported.

The declared function

* takes the book's inputs in the book's order (``AAA`` last, defaulting to 1.0, "silent");
  a count (the book's ``N`` or ``M``) stays where the book has it and must equal the length
  of its tables;
* rejects bad input with ``TypeError`` (strings, None, complex, masked arrays, objects) or
  ``ValueError`` (NaN, inf, a non-positive length, an integer out of range, a wrong shape),
  naming the argument;
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

import math
import os
import re
import sys
import warnings
from typing import Callable, Mapping, Sequence

import numpy as np

from . import _sarkp
from .errors import (AssemblyError, RangeError, RequirementError, SignificanceWarning,
                     SingularError, Status)
from .modes import MODE_CODE
from .results import result_type

from .library import (ST_ASSEMBLY, ST_DIGITS, ST_MISSING, ST_OK,  # noqa: E402,F401
                      ST_RANGE, ST_REQUIREMENT, ST_SIGNIFICANCE, ST_SINGULAR)

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

_SCALAR_TYPES = (float, np.floating)
_FLOAT64 = np.dtype(np.float64)
#: what the scalar path takes (a bool is an int; complex, strings, arrays go the long way)
_SCALARS = frozenset({float, int, bool, np.float64, np.float32, np.int64, np.int32})
_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
_INT_MAX = 2**31 - 1


class Check:
    """A condition on the inputs that the Fortran routine does not report itself.

    ``bad`` receives the inputs by book name (floats, or arrays that broadcast) and
    returns a boolean (or boolean array) that is true where the condition holds;
    ``status`` is the status it gives there and ``message`` what the error says.
    """

    def __init__(self, bad: Callable[..., object], status: int, message: str):
        self.bad = bad
        self.status = status
        self.message = message


def f2py_signature(wrapper, raw=False):
    """(required arguments, optional arguments, returned names) of an f2py wrapper, with
    the Fortran names (f2py appends ``_bn`` to names such as ``index``; ``raw`` keeps it)."""
    first = wrapper.__doc__.strip().splitlines()[0]
    m = re.match(r"(?:(.*?)\s*=\s*)?\w+\((.*)\)$", first)
    rets = [r.strip() for r in (m.group(1) or "").split(",") if r.strip()]
    args = m.group(2)
    optional = []
    if "[" in args:
        args, opt = args.split("[", 1)
        optional = [a.strip() for a in opt.rstrip("]").split(",") if a.strip()]
    required = [a.strip() for a in args.split(",") if a.strip()]
    if raw:
        return required, optional, rets
    return ([_f2py_unbad(a) for a in names] for names in (required, optional, rets))


def _caller_stacklevel():
    """stacklevel for warnings.warn that points at the first frame outside sarkp."""
    frame, level = sys._getframe(1), 1
    while frame is not None and (frame.f_code.co_filename.startswith(_PACKAGE_DIR)
                                 or frame.f_code.co_filename == "<sarkp>"):
        frame, level = frame.f_back, level + 1
    return level


def _first_index(mask, shape):
    flat = int(np.flatnonzero(np.asarray(mask).ravel())[0])
    return tuple(int(i) for i in np.unravel_index(flat, shape)) if shape else ()


def _type_error(name, arg, value):
    return TypeError(f"{name}: {arg} must be a real number or an array of real numbers, "
                     f"not {type(value).__name__} {value!r:.60}")


def as_real_array(name, arg, value):
    """``value`` as a float ndarray, or TypeError/ValueError naming ``arg``."""
    if value is None or isinstance(value, (str, bytes, np.ma.MaskedArray)):
        raise _type_error(name, arg, value)
    try:
        a = np.asarray(value)
    except (ValueError, TypeError) as exc:          # ragged lists and the like
        raise ValueError(f"{name}: {arg} is not a regular array of numbers ({exc})") from None
    kind = a.dtype.kind
    if kind == "O":
        try:
            a = a.astype(float)
        except OverflowError:
            raise ValueError(f"{name}: {arg} holds an integer too large for a double") from None
        except (TypeError, ValueError):
            raise _type_error(name, arg, value) from None
    elif kind not in "biuf":
        raise _type_error(name, arg, value)
    return np.asarray(a, dtype=float)


class Routine:
    """The declaration of one book routine (see :func:`book_routine`)."""

    def __init__(self, name, *, listing, lines, chapter, inputs, outputs, tables=None,
                 lengths=(), nonnegative=(), nonzero=(), integers=None, checks=(),
                 messages=None, function=False, report=None, example=None, kept=None):
        self.name = name
        self.listing = listing
        self.lines = lines
        self.chapter = chapter
        self.inputs = tuple(inputs)
        self.outputs = tuple(outputs)
        self.tables = {}
        for arg, dims in (tables or {}).items():
            self.tables[arg] = dims if isinstance(dims, tuple) else (dims,)
        self.counts = {d for dims in self.tables.values() for d in dims if isinstance(d, str)}
        self.lengths = frozenset(lengths)
        self.nonnegative = frozenset(nonnegative)
        self.nonzero = frozenset(nonzero)
        self.integers = dict(integers or {})
        for c in self.counts:
            self.integers.setdefault(c, range(1, _INT_MAX))
        self.checks = tuple(checks)
        self.messages = dict(_DEFAULT_MESSAGES)
        self.messages.update(messages or {})
        #: {status: outputs that are still valid after a failure with that status}
        self.kept = {st: frozenset(names) for st, names in (kept or {}).items()}
        self.function = function
        self.report = report
        # a valid input row (book order), for routines whose valid inputs random values
        # rarely hit (tooth numbers, centre distances): tests/test_layer.py draws near it
        self.example = None if example is None else tuple(float(v) for v in example)
        for group in (self.lengths, self.nonnegative, self.nonzero, self.integers,
                      self.tables):
            unknown = set(group) - set(self.inputs)
            if unknown:
                raise TypeError(f"{name}: declared {sorted(unknown)} are not inputs")
        driver = getattr(_sarkp, "drv_" + chapter)
        self.one = getattr(driver, name.lower() + "_1")
        self.many = getattr(driver, name.lower() + "_n", None)
        self._bind_fortran()
        self.sweeps_tables = bool(self.counts)       # tables counted by an argument
        self._fixed = {a: d[0] for a, d in self.tables.items() if not self.counts & set(d)}
        self._strict = bool(self.lengths or self.nonnegative or self.nonzero or self.integers)
        self._positive_at = [i for i, a in enumerate(self.inputs) if a in self.lengths]
        self._nonnegative_at = [i for i, a in enumerate(self.inputs) if a in self.nonnegative]
        self._nonzero_at = [i for i, a in enumerate(self.inputs) if a in self.nonzero]
        self._integer_at = [i for i, a in enumerate(self.inputs) if a in self.integers]
        self._aaa_index = self.inputs.index("AAA") if "AAA" in self.inputs else None
        # what the Fortran sweep screens each input for (gen_drivers.py, ``screen``)
        self._kinds = np.array([_kind(self, a) for a in self.inputs], dtype=np.int32)
        self._python_checked = {a for a in self.integers if _kind(self, a) == 0}
        if self.report is not None and self._aaa_index is None:
            raise TypeError(f"{name}: a report needs the print flag AAA among the inputs")
        self.result = result_type(name, self.outputs)
        self.result_with_status = result_type(name, self.outputs + ("status",))

    # -- the declaration against the Fortran signature ----------------------------------
    def _bind_fortran(self):
        # f2py renames arguments that clash with C or its own names (INDEX -> index_bn)
        raw_required, raw_optional, _ = f2py_signature(self.one, raw=True)
        self._f2py_name = {_f2py_unbad(a): a for a in raw_required + raw_optional}
        required, optional, rets = f2py_signature(self.one)
        # tables that Fortran writes (intent(inout): f2py returns them) are copied before
        # the call, so that the caller's array is never changed; the others go as they are
        self._written = frozenset(rets)
        fortran_in = [a for a in required + optional if not a.startswith("sarkp_")]
        declared = [a.lower() for a in self.inputs]
        if sorted(fortran_in) != sorted(declared):
            raise TypeError(f"{self.name}: declared inputs {declared} do not match the "
                            f"Fortran arguments {fortran_in}")
        positional = [a for a in required if not a.startswith("sarkp_")]
        if positional != [a for a in declared if a in positional]:
            raise TypeError(f"{self.name}: the inputs are not in the Fortran order {positional}")
        self._positional = not optional             # every input in the book's order
        results = rets[:-1]                          # the last is the status
        if self.function:
            if len(self.outputs) != 1 or results != ["fres"]:
                raise TypeError(f"{self.name}: a FUNCTION has one output")
            self._pick = [0]
        else:
            missing = [o for o in self.outputs if o.lower() not in results]
            if missing:
                raise TypeError(f"{self.name}: declared outputs {missing} are not among the "
                                f"Fortran results {results}")
            extra = [r for r in results if r.upper() not in self.outputs
                     and r not in declared]          # destroyed inout inputs may be left out
            if extra:
                raise TypeError(f"{self.name}: Fortran results {extra} are not declared")
            self._pick = [results.index(o.lower()) for o in self.outputs]
        self._identity = self._pick == list(range(len(results)))
        if self.many is not None and not self._identity:
            # the sweep writes result k to row k of one array (gen_drivers.py, sarkp_out)
            raise TypeError(f"{self.name}: a sweep's outputs must be all of the Fortran "
                            f"results, in their order {results}")
        self.fortran_inputs = fortran_in
        self.fortran_results = rets

    # -- validation ----------------------------------------------------------------------
    def _check_value(self, arg, v):
        """Raise ValueError for a bad scalar input value ``v`` (a float) of ``arg``."""
        if arg in self.integers:
            allowed = self.integers[arg]
            if not math.isfinite(v) or v != int(v) or int(v) not in allowed:
                raise ValueError(f"{self.name}: {arg} = {v:g} is not one of "
                                 f"{_describe(allowed)}")
            return
        if not math.isfinite(v):
            raise ValueError(f"{self.name}: {arg} = {v!r} is not a finite number")
        if arg in self.lengths and not v > 0.0:
            raise ValueError(f"{self.name}: {arg} = {v!r} is a length and must be > 0")
        if arg in self.nonnegative and v < 0.0:
            raise ValueError(f"{self.name}: {arg} = {v!r} must be >= 0")
        if arg in self.nonzero and v == 0.0:
            raise ValueError(f"{self.name}: {arg} = {v!r} must not be 0")

    def _out_of_range(self, args):
        """True if a length is not positive, a bound is broken or an integer is wrong."""
        return (any(not args[i] > 0.0 for i in self._positive_at)
                or any(args[i] < 0.0 for i in self._nonnegative_at)
                or any(args[i] == 0.0 for i in self._nonzero_at)
                or any(args[i] != int(args[i]) or int(args[i]) not in
                       self.integers[self.inputs[i]] for i in self._integer_at))

    def _check_array(self, arg, a, allow_nan):
        """Raise ValueError for a bad element of input array ``a``; return its NaN mask
        (when NaN is allowed) or None."""
        nan = np.isnan(a) if allow_nan else None
        if arg in self.integers:
            allowed = self.integers[arg]
            finite = np.isfinite(a)
            v = np.where(finite, a, 0.0)
            if isinstance(allowed, range):
                ok = (v == np.round(v)) & (v >= allowed.start) & (v < allowed.stop)
            else:
                ok = np.isin(v, sorted(allowed))
            bad = ~(finite & ok)
            what = f"is not one of {_describe(allowed)}"
        else:
            bad = ~np.isfinite(a)
            what = "is not a finite number"
            if not bad.any():
                if arg in self.lengths:
                    bad, what = ~(a > 0.0), "is a length and must be > 0"
                elif arg in self.nonnegative:
                    bad, what = a < 0.0, "must be >= 0"
                elif arg in self.nonzero:
                    bad, what = a == 0.0, "must not be 0"
        if nan is not None:
            bad &= ~nan
        if bad.any():
            idx = _first_index(bad, a.shape)
            raise ValueError(f"{self.name}: {arg}{list(idx) if idx else ''} = {a[idx]!r} "
                             f"{what}")
        return nan if nan is not None and nan.any() else None

    # -- the call ------------------------------------------------------------------------
    def __call__(self, args, on_error="raise", out=None):
        if on_error != "raise" and on_error != "nan":
            raise ValueError(f"{self.name}: on_error must be 'raise' or 'nan', "
                             f"not {on_error!r}")
        if self.sweeps_tables:
            if out is not None:
                raise TypeError(f"{self.name}: out= is for the array sweeps of routines "
                                f"without counted tables; {self.name} returns its tables")
            return self._call_tables(args, on_error)
        if out is not None:
            return self._call_arrays(args, on_error, out)
        if not self._fixed and all(type(a) in _SCALARS for a in args):
            # Python or NumPy scalars: one call; their sum tells whether all are finite
            try:
                total = sum(args)
            except OverflowError:                             # an integer beyond a double
                total = None
            if isinstance(total, _SCALAR_TYPES):
                return self._call_scalar(args, total, on_error)
        return self._call_arrays(args, on_error)

    def _call_scalar(self, args, total, on_error):
        # The sum of the inputs is finite when every input is, except when it overflows:
        # only then, or when some input has a range to respect, look at each one.
        if not math.isfinite(total) or (self._strict and self._out_of_range(args)):
            if on_error == "nan" and math.isnan(total) and \
                    all(math.isnan(a) or math.isfinite(a) for a in args):
                return self._missing_scalar()
            for arg, v in zip(self.inputs, args):
                self._check_value(arg, float(v))
        status, failed_check, out = ST_OK, None, [math.nan] * len(self.outputs)
        if self.checks:
            named = dict(zip(self.inputs, args))
            for check in self.checks:
                if check.bad(**named):
                    status, failed_check = check.status, check
                    break
        if status == ST_OK:
            out = self.one(MODE_CODE.get(), *args)
            status = out[-1]
            out = out[:-1] if self._identity else [out[i] for i in self._pick]
        if status != ST_OK:
            out = self._settle_scalar(status, out, failed_check, on_error)
            status = _status_code(status)
        if self.report is not None and args[self._aaa_index] == 0.0 and \
                not math.isnan(out[0]):
            print(self.report(dict(zip(self.inputs, args)), tuple(out)))
        return self._result(out, Status(status) if on_error == "nan" else None)

    def _missing_scalar(self):
        return self._result([math.nan] * len(self.outputs), Status.MISSING)

    def _result(self, out, status):
        if self.function:
            return out[0] if status is None else \
                self.result_with_status(out[0], status)
        if status is None:
            return self.result(*out)
        return self.result_with_status(*out, status)

    def _settle_scalar(self, status, out, check, on_error):
        if status == ST_SIGNIFICANCE or status > ST_DIGITS:
            warnings.warn(SignificanceWarning(
                f"{self.name}: {_significance_message(self.messages, status)}",
                digits=_digits(status)), stacklevel=_caller_stacklevel())
            return out
        kept = self.kept.get(status, ())
        settled = [o if name in kept else _nan_like(o) for name, o in zip(self.outputs, out)]
        if on_error == "raise":
            message = check.message if check is not None else None
            if status == ST_RANGE:
                message = self._range_message(out)
            error = status_error(self.name, status, None, self.messages, message)
            if kept:            # what is still valid: the result of on_error="nan"
                error.result = self._result(settled, Status(_status_code(status)))
            raise error
        return settled

    def _range_message(self, out, index=None):
        names = [n for n, o in zip(self.outputs, out)
                 if not np.all(np.isfinite(o if index is None else o[index]))]
        return (f"{', '.join(names) or 'a result'} would not be a finite double "
                f"(overflow); the inputs are too far apart in magnitude")

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
                try:
                    values[k] = float(a)
                except OverflowError:
                    raise ValueError(f"{self.name}: {self.inputs[k]} = {a} is an integer "
                                     f"too large for a double") from None
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
        # the results: the rows of one array, the caller's out= or a new one (issue 9:
        # one allocation per call, none with out=); Fortran fills column k of its
        # transpose, sarkp_out(i, k)
        nres = len(self.outputs)
        if buffer is None:
            buffer = np.empty((nres,) + shape)
        else:
            buffer = self._out_buffer(buffer, shape)
        out = list(buffer) if buffer.ndim > 1 else [buffer[i, ...] for i in range(nres)]
        if n == 0:
            return self._result(out, np.zeros(shape, np.int32) if allow_nan else None)
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
        status, bad = self.many(MODE_CODE.get(), incs, self._kinds, allow_nan, *flat,
                                buffer.reshape(nres, n).T)     # f2py takes n from it
        if bad[0]:
            self._raise_bad_input(int(bad[0]) - 1, int(bad[1]) - 1, flat, incs, shape)
        status = status.reshape(shape)
        failures = bad[2]                               # positions whose status is not OK
        # integer results (DZBPL's tooth numbers) come as floats: a failure holds NaN
        if self._python_checked:                        # integer sets Fortran cannot screen
            for arg, a in zip(self.inputs, values):
                if arg in self._python_checked:
                    self._check_array(arg, np.asarray(a), allow_nan)
        failed_check = None                             # which check failed where
        if self.checks:
            named = dict(zip(self.inputs, values))
            for k, check in enumerate(self.checks):
                with np.errstate(all="ignore"):
                    fails = np.broadcast_to(np.asarray(check.bad(**named), dtype=bool), shape)
                fails = fails & (status != ST_MISSING)
                if fails.any():
                    if failed_check is None:
                        failed_check = np.full(shape, -1, dtype=np.int8)
                    status = np.where(fails, check.status, status).astype(np.int32)
                    failed_check[fails] = k
                    failures = True
        if failures:
            def message(code, index):
                if code == ST_RANGE:
                    return self._range_message(out, index)
                k = -1 if failed_check is None else int(failed_check[index])
                return self.checks[k].message if k >= 0 else None

            out, status = settle_arrays(self.name, out, status, on_error, self.messages,
                                        message)
        if shape == ():
            out = [float(o) if o.ndim == 0 else o for o in out]
            if self.report is not None and float(values[self._aaa_index]) == 0.0 and \
                    int(status) in (ST_OK, ST_SIGNIFICANCE):
                print(self.report(dict(zip(self.inputs, values)), tuple(out)))
            return self._result(out, Status(int(status)) if allow_nan else None)
        return self._result(out, status if allow_nan else None)

    def _raise_bad_input(self, k, j, flat, incs, shape):
        """The ValueError for input ``k``, element ``j`` of its flat array, that the
        Fortran screen rejected."""
        arg = self.inputs[k]
        a = np.asarray(flat[k])
        value = float(a.ravel()[j]) if arg not in self._fixed else a[:, j]
        where = ""
        if incs[k]:
            where = str([int(i) for i in np.unravel_index(j, shape)])
        if arg in self._fixed:
            bad = value[~np.isfinite(value)] if not np.all(np.isfinite(value)) else value
            value = float(bad.ravel()[0]) if bad.size else value
        if not math.isfinite(value):
            what = "is not a finite number"
        elif arg in self.lengths:
            what = "is a length and must be > 0"
        elif arg in self.nonnegative:
            what = "must be >= 0"
        elif arg in self.nonzero:
            what = "must not be 0"
        else:
            what = f"is not one of {_describe(self.integers[arg])}"
        raise ValueError(f"{self.name}: {arg}{where} = {value!r} {what}")

    def _call_tables(self, args, on_error):
        """A routine with tables counted by an argument: one Fortran call, no sweep."""
        named, kw = {}, {}
        for arg, value in zip(self.inputs, args):
            if arg in self.tables:
                a = as_real_array(self.name, arg, value)
                dims = self.tables[arg]
                if a.ndim == 1 and len(dims) == 2:       # a single column (GELG's R)
                    a = a.reshape(-1, 1)
                if a.ndim != len(dims):
                    raise ValueError(f"{self.name}: {arg} must be "
                                     f"{('one', 'two')[len(dims) - 1]}-dimensional, not of "
                                     f"shape {a.shape}")
                self._check_array(arg, a, allow_nan=False)
                named[arg] = a
                kw[self._f2py_name[arg.lower()]] = np.array(
                    a, order="F", copy=arg.lower() in self._written or None)
            else:
                if isinstance(value, (bool, np.bool_)) or not isinstance(
                        value, (int, float, np.integer, np.floating)):
                    if np.ndim(value) == 0 and not isinstance(value, (str, bytes)):
                        value = as_real_array(self.name, arg, value)[()]
                    else:
                        raise _type_error(self.name, arg, value)
                try:
                    v = float(value)
                except OverflowError:
                    raise ValueError(f"{self.name}: {arg} = {value} is too large for a "
                                     f"double") from None
                self._check_value(arg, v)
                named[arg] = int(v) if arg in self.integers else v
                kw[self._f2py_name[arg.lower()]] = named[arg]
        for arg, dims in self.tables.items():
            for axis, d in enumerate(dims):
                want = named[d] if isinstance(d, str) else d
                if named[arg].shape[axis] != want:
                    count = f"{d} = {want}" if isinstance(d, str) else f"{want}"
                    raise ValueError(f"{self.name}: {arg} has shape {named[arg].shape}: "
                                     f"{named[arg].shape[axis]} along axis {axis}, but "
                                     f"{count}")
        for check in self.checks:
            if check.bad(**named):
                if on_error == "raise":
                    raise status_error(self.name, check.status, None, self.messages,
                                       check.message)
                return self._result([math.nan] * len(self.outputs), Status(check.status))
        out = self.one(MODE_CODE.get(), **kw)
        status = int(out[-1])
        out = [out[i] for i in self._pick]
        for k, o in enumerate(out):
            name = self.outputs[k]
            if name in self.tables:                     # an inout table: the input's shape
                out[k] = np.asarray(o).reshape(np.shape(args[self.inputs.index(name)]))
            elif np.ndim(o) == 0:
                out[k] = o.item() if isinstance(o, np.ndarray) else o
        if status != ST_OK:
            out = self._settle_scalar(status, out, None, on_error)
            status = _status_code(status)
        if self.report is not None and args[self._aaa_index] == 0.0:
            print(self.report(named, tuple(out)))
        return self._result(out, Status(status) if on_error == "nan" else None)


def _kind(spec, arg):
    """The screen of input ``arg`` in the Fortran sweep: 0 a finite number, 1 a length,
    2 >= 0, 3 not 0, 4 an assembly branch (-1 or +1).  Other integer sets are checked in
    Python (kind 0 in Fortran)."""
    if arg in spec.lengths:
        return 1
    if arg in spec.nonnegative:
        return 2
    if arg in spec.nonzero:
        return 3
    allowed = spec.integers.get(arg)
    if allowed is not None and not isinstance(allowed, range) and set(allowed) == {-1, 1}:
        return 4
    return 0


def _f2py_unbad(name):
    """The Fortran name of an f2py argument (f2py appends _bn to names such as index)."""
    return name[:-3] if name.endswith("_bn") else name


def _describe(allowed):
    if isinstance(allowed, range):
        return f"the integers >= {allowed.start}"
    return str(sorted(allowed))


def _nan_like(o):
    if isinstance(o, np.ndarray):
        return np.full(o.shape, np.nan)
    if isinstance(o, (int, np.integer)):
        return o
    return math.nan


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
    """The exception for a failed ``status`` of routine ``name`` at ``index``."""
    where = "" if index is None else f" at index {list(index)}"
    code = _status_code(status)
    if message is None:
        message = messages.get(status) or messages.get(code) or \
            _DEFAULT_MESSAGES.get(code, f"status {status}")
    return _ERRORS.get(code, SingularError)(f"{name}{where}: {message}",
                                            status=code, index=index)


def settle_arrays(name, out, status, on_error, messages, message_at=None):
    """Apply the error policy to arrays ``out`` computed with ``status``.

    Raises the error of the first failed position (``on_error="raise"``) or puts NaN
    there (``"nan"``); warns once for a loss of significance.  ``message_at(status,
    index)`` may give a more precise message for a failed position.  Returns ``(out,
    status)`` with Fortran's 100 + d codes mapped to SIGNIFICANCE and its reason codes
    10 c + k to c.
    """
    lost = (status == ST_SIGNIFICANCE) | (status > ST_DIGITS)
    failed = (status != ST_OK) & ~lost
    if failed.any():
        if on_error == "raise":
            idx = _first_index(failed, status.shape)
            code = int(status[idx])
            raise status_error(name, code, idx, messages,
                               message_at(code, idx) if message_at else None)
        for o in out:
            o[failed] = np.nan
    if lost.any():
        idx = _first_index(lost, status.shape)
        digits = status[status > ST_DIGITS]
        worst = int(digits.min()) if digits.size else ST_SIGNIFICANCE
        warnings.warn(SignificanceWarning(
            f"{name}: {_significance_message(messages, worst)} (first at index "
            f"{list(idx)})", digits=_digits(worst), index=idx),
            stacklevel=_caller_stacklevel())
        status = np.where(status > ST_DIGITS, ST_SIGNIFICANCE, status).astype(np.int32)
    reason = (status >= 10) & (status < 100)             # 10 c + k: code c
    if reason.any():
        status = np.where(reason, status // 10, status).astype(np.int32)
    return out, status


def book_routine(name: str, *, listing: str, lines: str, chapter: str,
                 inputs: Sequence[str], outputs: Sequence[str], doc: str,
                 defaults: Mapping[str, float] | None = None, **options):
    """Declare a book routine and return its Python function.

    Parameters
    ----------
    name, listing, lines
        The book's name (``"DVKT"``), listing number (``"II.11"``) and book lines.
    chapter
        The Fortran module that holds the routine (``"kinematics"``); the generated
        drivers ``drv_<chapter>.<name>_1`` and ``_n`` are called.
    inputs, outputs
        The book's input and output names, in the book's order; COMMON results (and
        sarkp's marked extensions) follow the book's outputs.
    doc
        The numpydoc docstring; the description of ``on_error`` is appended.
    defaults
        Default values of trailing inputs (``AAA`` gets 1.0, "do not print", if present).
    options
        ``tables`` ({input: count name, a fixed size, or a tuple of them}), ``lengths``
        (> 0), ``nonnegative``, ``nonzero``, ``integers`` ({name: allowed values or a
        range}; counts default to the integers >= 1), ``checks`` (:class:`Check`),
        ``messages`` ({status: text}), ``function`` (a book FUNCTION: returns a number),
        ``report`` (callable(inputs, outputs) -> text, printed for AAA = 0), ``example``
        (a valid input row in the book's order, for the generic tests), ``kept``
        ({status: output names}: outputs still valid when the routine fails with that
        status -- kept under ``on_error="nan"``, and the error raised otherwise carries
        that result as ``.result``).
    """
    spec = Routine(name, listing=listing, lines=lines, chapter=chapter, inputs=inputs,
                   outputs=outputs, **options)
    defaults = dict(defaults or {})
    if "AAA" in spec.inputs:
        defaults.setdefault("AAA", 1.0)
    params = [f"{arg}={defaults[arg]!r}" if arg in defaults else arg for arg in spec.inputs]
    arglist = ", ".join(spec.inputs)
    sweeps = not spec.sweeps_tables                   # an array sweep: out= is offered
    source = [f"def {name}({', '.join(params)}, *, on_error='raise'"
              + (", out=None):" if sweeps else "):")]
    namespace = {"_spec": spec}
    if not spec.sweeps_tables and not spec._fixed:
        source += _fast_path(spec, namespace)
    source.append(f"    return _spec(({arglist},), on_error{', out' if sweeps else ''})")
    # a real signature, so that help() and inspect show the book's names
    exec(compile("\n".join(source) + "\n", "<sarkp>", "exec"), namespace)
    function = namespace[name]
    function.__doc__ = doc.rstrip() + "\n" + ON_ERROR_DOC + (OUT_DOC if sweeps else "")
    function.__module__ = "sarkp"
    function.spec = spec
    return function


def _fast_path(spec, namespace):
    """Source lines of the common case, Python floats in range with ``on_error="raise"``
    and a computed result: one Fortran call and a tuple, nothing else.  Every other case
    (arrays, NaN, a failure, a warning) falls through to ``Routine.__call__``."""
    args = ", ".join(spec.inputs)
    cond = ["on_error == 'raise'", "out is None", "_t - _t == 0.0"]
    cond += [f"{a} > 0.0" for a in spec.inputs if a in spec.lengths]
    cond += [f"{a} >= 0.0" for a in spec.inputs if a in spec.nonnegative]
    cond += [f"{a} != 0.0" for a in spec.inputs if a in spec.nonzero]
    for a in spec.inputs:
        if a in spec.integers:
            namespace[f"_allowed_{a}"] = frozenset(float(v) for v in spec.integers[a])
            cond.append(f"{a} in _allowed_{a}")
    for k, check in enumerate(spec.checks):
        namespace[f"_bad{k}"] = check.bad
        cond.append(f"not _bad{k}({', '.join(f'{a}={a}' for a in spec.inputs)})")
    if spec.report is not None:
        cond.append("AAA != 0.0")
    namespace.update(_one=spec.one, _mode=MODE_CODE.get, _new=tuple.__new__,
                     _cls=spec.result)
    if spec.function:
        result = "_o[0]"
    elif spec._identity:
        result = "_new(_cls, _o[:-1])"
    else:
        result = f"_new(_cls, ({', '.join(f'_o[{i}]' for i in spec._pick)},))"
    # exact types first: a NumPy array among the inputs must not be summed here
    types = [f"type({a}) is _F" if a not in spec.integers
             else f"(type({a}) is _F or type({a}) is _I)" for a in spec.inputs]
    namespace.update(_F=float, _I=int)
    return [f"    if {' and '.join(types)}:",
            f"        _t = {' + '.join(spec.inputs)}",
            f"        if {' and '.join(cond)}:",
            f"            _o = _one(_mode(), {args})",
            "            if _o[-1] == 0:",
            f"                return {result}"]


def declared_routines():
    """Every routine declared with :func:`book_routine`, by name (for the tests)."""
    import sarkp
    return {n: getattr(sarkp, n) for n in sarkp.__all__
            if hasattr(getattr(sarkp, n, None), "spec")}
