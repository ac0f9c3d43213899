"""GELG, the IBM SSP linear solver the book calls (L519-528), rebuilt on LAPACK."""

from __future__ import annotations

from . import _wrap_gelg_mod as _w
from .library import describe

__all__ = ["GELG"]

GELG = describe(
    _w.GELG, listing="SSP", lines="L519-528",
    doc="""Solve A X = R by Gauss elimination with complete pivoting (IBM SSP GELG).

    The book calls ``CALL GELG(Y, X, N, K, T, IER)`` (2.7, L523) with K = 1 and
    T = 0.0001.  In Fortran R is overwritten by the solution and A destroyed; here both
    are copied, and the solution is returned.

    Returns
    -------
    GELG(R, IER)
        ``R`` the solution (shape of the input R) and ``IER``, the book's flag, returned
        as in the book rather than raised: 0 no loss of significance; -1 a pivot that is
        zero to working precision (``R`` is then the input, unchanged); ``K > 0``: the
        pivot of elimination step K+1 was at most ``EPS * max|a_ij|``, so A has
        numerical rank K at tolerance EPS (SSP's meaning; the solution is still
        returned).  The pivots are LAPACK's complete pivots (DGETC2), the solve DGESC2.

    Raises
    ------
    RangeError
        The solution overflows double precision.
    """)
