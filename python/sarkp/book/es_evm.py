"""The arithmetic of the ES EVM (IBM System/360 compatible) that printed the book.

REAL*4 there is a hexadecimal floating-point number: a fraction of 6 hex digits
(24 bits) times a power of 16, and the arithmetic truncates instead of rounding.  A few
printed cells differ from a double-precision (or IEEE single) run only because of this,
e.g. the last crank angle of Fig. 4 (ERRATA E-FIG4-4).  The book's programs in
as-printed mode use :func:`real4` where such a cell depends on it.
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


def add(a: float, b: float) -> float:
    """``a + b`` as the ES EVM computed it: the exact sum truncated to a short float."""
    return real4(real4(a) + real4(b))


def div(a: float, b: float) -> float:
    """``a / b`` as the ES EVM computed it (quotient truncated to a short float)."""
    return real4(real4(a) / real4(b))
