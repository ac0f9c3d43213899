"""The two modes of sarkp: ``corrected`` (the default) and ``as-printed``.

* ``corrected``: pi to double precision and every author error of the book fixed.
* ``as-printed``: PI = 3.14159, the value the book's routines use, and the author
  errors that a printed figure depends on switched back on, so that the book's printed
  tables come back digit for digit.  Each such switch cites its row of docs/ERRATA.md.

The mode belongs to the caller: it is a context variable (:mod:`contextvars`), so every
thread and every asyncio task has its own, starting from ``corrected``.  Every call of a
book routine reads it and hands it to Fortran, where the generated driver sets the book's
COMMON /PRMTR/ inside the same call (fortran/gen_drivers.py): no other thread can change
it in between.  A generator should set the mode around its computations, not around a
``yield`` (while it is suspended its ``with`` block would still be in force for the code
that consumes it).
"""

from __future__ import annotations

import contextlib
import contextvars
import math

MODES = ("corrected", "as-printed")

#: The caller's mode as the Fortran code number: 0 corrected, 1 as-printed.
MODE_CODE: contextvars.ContextVar[int] = contextvars.ContextVar("sarkp_mode", default=0)

_PI_BOOK = 3.14159          # L559: PI = 3.14159


def _code(name: str) -> int:
    if name not in MODES:
        raise ValueError(f"mode must be one of {MODES}, not {name!r}")
    return MODES.index(name)


def set_mode(mode: str) -> None:
    """Set the mode of the calling thread (or task): ``"corrected"`` or ``"as-printed"``."""
    MODE_CODE.set(_code(mode))


def get_mode() -> str:
    """The mode of the calling thread (or task), ``"corrected"`` or ``"as-printed"``."""
    return MODES[MODE_CODE.get()]


@contextlib.contextmanager
def mode(name: str):
    """Run a block in the given mode and restore the previous one afterwards."""
    token = MODE_CODE.set(_code(name))
    try:
        yield
    finally:
        MODE_CODE.reset(token)


def as_printed():
    """Context manager: ``with sarkp.as_printed(): ...`` runs the block as printed."""
    return mode("as-printed")


def book_pi() -> float:
    """The PI of the caller's mode: 3.14159 as printed, pi to double precision corrected."""
    return _PI_BOOK if MODE_CODE.get() else math.pi
