"""The arithmetic of the ES EVM (IBM System/360 compatible) that printed the book.

REAL*4 there is a hexadecimal floating-point number: a fraction of 6 hex digits
(24 bits) times a power of 16, and the arithmetic truncates instead of rounding.  A few
printed cells differ from a double-precision (or IEEE single) run only because of this,
e.g. the last crank angle of Fig. 4 (ERRATA E-FIG4-4).  The book's programs in
as-printed mode use :func:`real4` where such a cell depends on it; the emulations (a
printed program run statement by statement as the machine ran it: V.5, II.13, VI.6, VI.7,
X) compute with :class:`Real4` numbers and the library functions of :func:`fn`.  This module
is the one place that arithmetic is written.
"""

from __future__ import annotations

import math


def real4(x: float) -> float:
    """``x`` truncated (towards zero) to a System/360 short hexadecimal float."""
    if x == 0.0 or not math.isfinite(x):
        return x
    fraction, exponent = math.frexp(abs(x))          # abs(x) = fraction * 2**exponent
    # write abs(x) = f * 16**e with 1/16 <= f < 1
    e = -((-exponent) // 4)                            # ceil(exponent / 4)
    f = abs(x) / 16.0 ** e
    if f >= 1.0:
        f, e = f / 16.0, e + 1
    while f < 1.0 / 16.0:
        f, e = f * 16.0, e - 1
    f = math.floor(f * 16.0 ** 6) / 16.0 ** 6
    return math.copysign(f * 16.0 ** e, x)


def real4_rounded(x: float) -> float:
    """``x`` rounded to the nearest System/360 short hexadecimal float (as a library
    function that rounds its result, rather than truncating it, delivers it)."""
    down = real4(x)
    if down == x or x == 0.0 or not math.isfinite(x):
        return down
    step = 16.0 ** (math.floor(math.log(abs(down), 16)) + 1 - 6)   # one unit of the 6th
    up = math.copysign(abs(down) + step, x)                          # hex digit of down
    return real4(up) if abs(up - x) < abs(x - down) else down


def add(a: float, b: float) -> float:
    """``a + b`` as the ES EVM computed it: the exact sum truncated to a short float."""
    return real4(real4(a) + real4(b))


def div(a: float, b: float) -> float:
    """``a / b`` as the ES EVM computed it (quotient truncated to a short float)."""
    return real4(real4(a) / real4(b))


class Real4(float):
    """A REAL*4 of the ES EVM: every operation's exact result truncated to 6 hex digits
    (an operand that is a plain number is truncated first, as a REAL*4 constant is)."""

    def __new__(cls, x):
        return float.__new__(cls, real4(float(x)))

    def __add__(self, o):
        return Real4(float(self) + float(Real4(o)))

    def __radd__(self, o):
        return Real4(float(Real4(o)) + float(self))

    def __sub__(self, o):
        return Real4(float(self) - float(Real4(o)))

    def __rsub__(self, o):
        return Real4(float(Real4(o)) - float(self))

    def __mul__(self, o):
        return Real4(float(self) * float(Real4(o)))

    def __rmul__(self, o):
        return Real4(float(Real4(o)) * float(self))

    def __truediv__(self, o):
        return Real4(float(self) / float(Real4(o)))

    def __rtruediv__(self, o):
        return Real4(float(Real4(o)) / float(self))

    def __neg__(self):
        return Real4(-float(self))

    def __pos__(self):
        return self

    def __abs__(self):
        return Real4(abs(float(self)))

    def __pow__(self, n):
        # X**2 and X**4 of the listings: repeated multiplication, as FORTRAN compiles
        # an integer power
        if not isinstance(n, int) or n < 1:
            raise TypeError(f"Real4 ** {n!r}: only positive integer powers")
        out = self
        for _ in range(n - 1):
            out = out * self
        return out


def fn(function):
    """A function's exact value, truncated to a REAL*4 (a conversion, not the library:
    the library's functions are :data:`SIN`, :data:`COS`, ... of the stated model)."""
    return lambda *x: Real4(function(*(float(v) for v in x)))


# ---- the library's functions: one stated model ------------------------------------------------

#: the library functions the emulated programs call (FORTRAN names)
FUNCTIONS = ("SIN", "COS", "TAN", "ATAN", "ACOS", "SQRT")
_EXACT = {"SIN": math.sin, "COS": math.cos, "TAN": math.tan, "ATAN": math.atan,
          "ACOS": math.acos, "SQRT": math.sqrt}
#: THE model of the book's machine: the library functions whose result is rounded to the
#: nearest REAL*4; every other function's exact result is truncated, like the machine's
#: arithmetic.  Chosen once by the evidence of every emulated figure, each program run
#: whole under each of the 64 candidate models, program X with its link lengths refitted
#: in each of the best (scripts/choose_arithmetic.py; the tables are in docs/judging.md):
#: the model whose runs reproduce the most printed cells.
ROUNDED = frozenset({"ATAN", "COS", "SQRT"})
_current = [ROUNDED]


def rounded() -> frozenset:
    """The library functions that round in the model now in force."""
    return _current[0]


class library_model:
    """``with library_model({"ATAN"}): ...`` runs the emulations under another candidate
    model (scripts/choose_arithmetic.py); the book's figures use :data:`ROUNDED`."""

    def __init__(self, rounding):
        rounding = frozenset(rounding)
        unknown = rounding - set(FUNCTIONS)
        if unknown:
            raise ValueError(f"no library function {', '.join(sorted(unknown))}; "
                             f"known: {', '.join(FUNCTIONS)}")
        self.rounding = rounding

    def __enter__(self):
        self.saved = _current[0]
        _current[0] = self.rounding
        return self

    def __exit__(self, *exc):
        _current[0] = self.saved
        return False


def _library(name: str):
    exact = _EXACT[name]

    def function(x):
        value = exact(float(x))
        return Real4(real4_rounded(value) if name in _current[0] else value)
    function.__name__ = name
    function.__doc__ = (f"{name} of the ES EVM's library: the exact value, rounded to a "
                        f"REAL*4 if the model in force rounds {name}, else truncated")
    return function


SIN, COS, TAN, ATAN, ACOS, SQRT = (_library(n) for n in FUNCTIONS)
