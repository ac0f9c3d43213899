"""The two modes of sarkp: ``corrected`` (the default) and ``as-printed``.

* ``corrected``: pi to double precision and every author error of the book fixed.
* ``as-printed``: PI = 3.14159, the value the book's routines use, and the author
  errors that a printed figure depends on switched back on, so that the book's printed
  tables come back digit for digit.  Each such switch cites its row of docs/ERRATA.md.

The mode lives in the Fortran module ``prmtr`` (the book's COMMON /PRMTR/), so it is
one setting for the whole process, as COMMON was for the book's programs.
"""

from __future__ import annotations

import contextlib

from . import _sarkp

MODES = ("corrected", "as-printed")

_current = "corrected"


def set_mode(mode: str) -> None:
    """Set the mode: ``"corrected"`` or ``"as-printed"``."""
    global _current
    if mode not in MODES:
        raise ValueError(f"mode must be one of {MODES}, not {mode!r}")
    _sarkp.prmtr.set_mode(1 if mode == "as-printed" else 0)
    _current = mode


def get_mode() -> str:
    """The current mode, ``"corrected"`` or ``"as-printed"``."""
    return _current


@contextlib.contextmanager
def mode(name: str):
    """Run a block in the given mode and restore the previous one afterwards."""
    previous = get_mode()
    set_mode(name)
    try:
        yield
    finally:
        set_mode(previous)


def as_printed():
    """Context manager: ``with sarkp.as_printed(): ...`` runs the block as printed."""
    return mode("as-printed")


def book_pi() -> float:
    """The PI in force: 3.14159 as printed, pi to double precision when corrected."""
    return float(_sarkp.prmtr.pi)
