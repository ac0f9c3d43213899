"""GELG, the IBM SSP linear solver the book calls (L519-528), rebuilt on LAPACK."""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from . import _sarkp

__all__ = ["GELG"]

_GELG_RESULT = namedtuple("GELG", ["R", "IER"])


def GELG(R, A, M, N, EPS):
    """Solve A X = R by Gauss elimination with complete pivoting (IBM SSP GELG).

    The book calls ``CALL GELG(Y, X, N, K, T, IER)`` (2.7, L523) with K = 1 and
    T = 0.0001.  In Fortran R is overwritten by the solution and A destroyed; here both
    are copied, and the solution is returned.

    Parameters
    ----------
    R : array_like, shape (M,) or (M, N)
        Right-hand sides.
    A : array_like, shape (M, M)
        Coefficient matrix.
    M : int
        Order of the system (M >= 1).
    N : int
        Number of right-hand sides (the book's gloss "method of computation" is wrong:
        ERRATA E-GELG-1).
    EPS : float
        Relative pivot tolerance, >= 0 (NaN or negative: ValueError).

    Returns
    -------
    GELG(R, IER)
        ``R`` the solution (shape of the input R) and ``IER``:
        0 no loss of significance; -1 ``M < 1`` or a pivot that is zero to working
        precision (``R`` is then the input, unchanged); ``K > 0``: the pivot of
        elimination step K+1 was at most ``EPS * max|a_ij|``, so A has numerical rank
        K at tolerance EPS (SSP's meaning; the solution is still returned).  The
        pivots are LAPACK's complete pivots (DGETC2), the solve DGESC2.
    """
    eps = float(EPS)
    if not eps >= 0.0:                      # NaN fails this too
        raise ValueError(f"GELG: EPS must be a nonnegative number, got {EPS!r}")
    r_in = np.asarray(R, dtype=float)
    a = np.array(A, dtype=float, order="F", copy=True)
    M, N = int(M), int(N)
    if M < 1 or N < 1:
        return _GELG_RESULT(r_in.copy(), -1)
    if a.shape != (M, M):
        raise ValueError(f"GELG: A has shape {a.shape}, expected ({M}, {M})")
    if r_in.size != M * N:
        raise ValueError(f"GELG: R has {r_in.size} elements, expected M*N = {M * N}")
    for name, v in (("A", a), ("R", r_in)):
        if not np.isfinite(v).all():
            raise ValueError(f"GELG: {name} holds a value that is not a finite number")
    r = np.array(r_in.reshape((M, N), order="F"), order="F", copy=True)
    ier = _sarkp.gelg_mod.gelg(r, a, eps)
    return _GELG_RESULT(r.reshape(r_in.shape, order="F"), int(ier))
