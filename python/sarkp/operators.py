"""Chapter 2: the operator functions (listings II.1-II.12, book lines L425-700).

Angles are in radians (L166).  ``PI`` is 3.14159 in as-printed mode, as in every
listing of the book, and pi to double precision in corrected mode.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from . import _sarkp
from .library import ST_SINGULAR, Check, book_routine

_f = _sarkp.operators
_s = _sarkp.sweeps

__all__ = ["DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL",
           "DMOMNT", "DOMEGA", "DVKT", "DSMVKT", "NOMER_METHODS"]

#: DINTGR's methods, as the listing's code and comments number them (L443-447).
NOMER_METHODS = {1: "Simpson", 2: "trapezoids", 3: "rectangles"}

_DINTGR_RESULT = namedtuple("DINTGR", ["FINT"])
_DFRNCL_RESULT = namedtuple("DFRNCL", ["FDIF"])


def _table(name, arg, values):
    y = np.asarray(values, dtype=float)
    if y.ndim != 1:
        raise ValueError(f"{name}: {arg} must be one-dimensional, not of shape {y.shape}")
    if y.size < 2:
        raise ValueError(f"{name}: {arg} needs at least 2 points, has {y.size}")
    bad = ~np.isfinite(y)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name}: {arg}[{i}] = {y[i]!r} is not a finite number")
    return y


def _step(name, h):
    h = float(h)
    if not np.isfinite(h) or h == 0.0:
        raise ValueError(f"{name}: H = {h!r} must be a finite, non-zero step")
    return h


def DINTGR(M, H, NOMER, Y):
    """Running integral of a tabulated function (listing II.1, L435-480).

    The book's call is ``CALL DINTGR(M, H, NOMER, Y, FINT)``.

    Parameters
    ----------
    M : int
        Number of points; must equal ``len(Y)`` (at least 2).
    H : float
        Step of the table (the printed header names it ``N``: ERRATA E-DINTGR-1).
    NOMER : int
        Method, numbered as the listing's code does (L443-447): 1 Simpson,
        2 trapezoids, 3 rectangles.  The prose at L431 numbers them the other way
        round (1 rectangles, 3 Simpson); the code is followed (ERRATA E-DINTGR-2).
    Y : array_like
        The values of the integrand at the M points.

    Returns
    -------
    DINTGR(FINT)
        ``FINT[k]`` is the integral from the first point to point k; ``FINT[0] = 0``.
        Rectangles use the right end of each step; Simpson integrates the odd points
        from the first and the even points from a trapezoid over the first step, as
        printed (so it is exact for cubics at the odd points only).
    """
    y = _table("DINTGR", "Y", Y)
    if int(M) != M or int(M) != y.size:
        raise ValueError(f"DINTGR: M = {M!r} must equal the number of points in Y ({y.size})")
    if NOMER not in NOMER_METHODS:
        raise ValueError(f"DINTGR: NOMER = {NOMER!r} is not one of {sorted(NOMER_METHODS)} "
                         f"({NOMER_METHODS})")
    fint = _f.dintgr(_step("DINTGR", H), int(NOMER), y)
    return _DINTGR_RESULT(fint)


def DFRNCL(M, H, Y):
    """Numerical derivative of a tabulated function (listing II.2, L490-509).

    The book's call is ``CALL DFRNCL(M, H, FDIF, Y)``: the output comes before the input
    (confirmed by the call at L5988); in Python the output is the result.

    Parameters
    ----------
    M : int
        Number of points; must equal ``len(Y)`` (at least 2).
    H : float
        Step of the table, non-zero.
    Y : array_like
        The function values.

    Returns
    -------
    DFRNCL(FDIF)
        Backward differences assigned to the right-hand point:
        ``FDIF[k] = (Y[k] - Y[k-1]) / H``, and ``FDIF[0] = 0``.
    """
    y = _table("DFRNCL", "Y", Y)
    if int(M) != M or int(M) != y.size:
        raise ValueError(f"DFRNCL: M = {M!r} must equal the number of points in Y ({y.size})")
    return _DFRNCL_RESULT(_f.dfrncl(_step("DFRNCL", H), y))


def _coincident(X1, Y1, X2, Y2):
    return (X1 == X2) & (Y1 == Y2)


_NO_DIRECTION = Check(_coincident, ST_SINGULAR,
                      "the points coincide: a segment of zero length has no direction")

DUGL1 = book_routine(
    "DUGL1", listing="II.3", lines="L551-569",
    inputs=("X1", "Y1", "X2", "Y2"), outputs=("DUGL1",),
    scalar=_f.dugl1, sweep=_s.dugl1_sweep, function=True, has_status=False,
    checks=(_NO_DIRECTION,),
    doc="""Direction angle of the segment from (X1, Y1) to (X2, Y2), in [0, 2*PI).

    Listing II.3 (L551-569), operator function UGL1 of Table 2.

    Parameters
    ----------
    X1, Y1 : float or array_like
        Start of the segment.
    X2, Y2 : float or array_like
        End of the segment.

    Returns
    -------
    DUGL1(DUGL1)
        The angle in radians, measured from the x-axis, in [0, 2*PI).  A negative
        angle is wrapped by ``2*PI``, with the PI of the mode in force.

    Raises
    ------
    SingularError
        The points coincide (the book divides 0 by 0 there).
    """)

DUGL2 = book_routine(
    "DUGL2", listing="II.4", lines="L572-588",
    inputs=("X1", "Y1", "X2", "Y2"), outputs=("DUGL2",),
    scalar=_f.dugl2, sweep=_s.dugl2_sweep, function=True, has_status=False,
    checks=(_NO_DIRECTION,),
    doc="""Signed direction angle of the segment from (X1, Y1) to (X2, Y2), in [-pi, pi].

    Listing II.4 (L572-588), operator function UGL2 of Table 2:
    ``SIGN(ACOS((X2-X1)/L), Y2-Y1)``.  A horizontal segment pointing left gives +pi.

    Parameters
    ----------
    X1, Y1, X2, Y2 : float or array_like
        Start and end of the segment.

    Returns
    -------
    DUGL2(DUGL2)
        The angle in radians.

    Raises
    ------
    SingularError
        The points coincide.
    """)

DUGL3 = book_routine(
    "DUGL3", listing="II.5", lines="L590-599",
    inputs=("UGOL1", "UGOLD", "VEL"), outputs=("DUGL3",),
    scalar=_f.dugl3, sweep=_s.dugl3_sweep, function=True, has_status=False,
    doc="""Direction set by the sign of a parameter: ``UGOL1 + sign(VEL)*|UGOLD|``.

    Listing II.5 (L590-599), operator function UGL3 of Table 2.  Typical use: the
    direction of a velocity omega x r is the link angle plus or minus pi/2, by the
    sign of omega.

    Parameters
    ----------
    UGOL1 : float or array_like
        Base angle, radians.
    UGOLD : float or array_like
        Added angle; only its magnitude is used.
    VEL : float or array_like
        The parameter whose sign decides; zero (and -0.0, as on the ES EVM) counts as
        positive.

    Returns
    -------
    DUGL3(DUGL3)
        The angle in radians (not wrapped).
    """)

DUGL4 = book_routine(
    "DUGL4", listing="II.6", lines="L601-612",
    inputs=("UGOL1", "UGOLD", "VEL"), outputs=("DUGL4",),
    scalar=_f.dugl4, sweep=_s.dugl4_sweep, function=True, has_status=False,
    doc="""Direction of a vector on its line of action: UGOL1, reversed if VEL < 0.

    Listing II.6 (L601-612), operator function UGL4 of Table 2.  Returns
    ``UGOL1 - UGOLD`` when VEL < 0 and ``UGOL1`` otherwise.  The printed arithmetic IF
    names a label 111 that does not exist (ERRATA E-DUGL4-1): VEL > 0 is taken like
    VEL = 0, as Table 2 says.  Table 2 adds UGOLD where the listing subtracts it
    (E-DUGL4-2); the listing is kept.  The book almost always passes UGOLD = PI, where
    both give the same direction.

    Parameters
    ----------
    UGOL1 : float or array_like
        Angle of the assumed direction, radians.
    UGOLD : float or array_like
        Angle subtracted when VEL < 0 (usually PI).
    VEL : float or array_like
        The solved magnitude whose sign decides.

    Returns
    -------
    DUGL4(DUGL4)
        The angle in radians.
    """)

DUGL5 = book_routine(
    "DUGL5", listing="II.7", lines="L614-628",
    inputs=("PRX", "PRY"), outputs=("DUGL5",),
    scalar=_f.dugl5, sweep=_s.dugl5_sweep, function=True, has_status=False,
    doc="""Direction angle of a vector from its projections, in (-pi/2, 3*pi/2).

    Listing II.7 (L614-628), eq. (2.2) at L383: ``atan(PRY/PRX)`` for PRX > 0,
    ``PI + atan(PRY/PRX)`` for PRX < 0, and ``sign(PRY)*PI/2`` for PRX = 0 (+PI/2 for
    the zero vector, as printed).

    Parameters
    ----------
    PRX, PRY : float or array_like
        Projections on the x and y axes.

    Returns
    -------
    DUGL5(DUGL5)
        The angle in radians.
    """)

DUGOL = book_routine(
    "DUGOL", listing="II.8", lines="L630-639",
    inputs=("FI",), outputs=("DUGOL",),
    scalar=_f.dugol, sweep=_s.dugol_sweep, function=True, has_status=False,
    doc="""An angle made non-negative: FI if FI >= 0, else FI + 2*PI.

    Listing II.8 (L630-639), operator function UGOL.  One wrap only, as printed, so an
    angle below -2*PI stays negative.

    Parameters
    ----------
    FI : float or array_like
        Angle, radians.

    Returns
    -------
    DUGOL(DUGOL)
        The angle in radians.
    """)

DMOMNT = book_routine(
    "DMOMNT", listing="II.9", lines="L641-644",
    inputs=("R", "FI", "F", "G"), outputs=("DMOMNT",),
    scalar=_f.dmomnt, sweep=_s.dmomnt_sweep, function=True, has_status=False,
    doc="""Moment of a force about the origin: the z-component of r x F.

    Listing II.9 (L641-644), operator function MOMNT of Table 2:
    ``R*cos(FI)*F*sin(G) - R*sin(FI)*F*cos(G) = R*F*sin(G - FI)``.

    Parameters
    ----------
    R, FI : float or array_like
        Magnitude and direction of the arm (radius vector of the point of application).
    F, G : float or array_like
        Magnitude and direction of the force.

    Returns
    -------
    DMOMNT(DMOMNT)
        The moment, counter-clockwise positive.
    """)

DOMEGA = book_routine(
    "DOMEGA", listing="II.10", lines="L648-660",
    inputs=("RAZMER", "VEKTOR", "UGOL"), outputs=("DOMEGA",),
    scalar=_f.domega, sweep=_s.domega_sweep, function=True, has_status=False,
    lengths=("RAZMER",),
    doc="""Angular velocity (or acceleration) of a link from a relative velocity.

    Listing II.10 (L648-660), eq. (2.8) at L543: ``|VEKTOR/RAZMER|`` with the sign of
    UGOL.  The book's correct call (L1716) passes UGOL = (direction of the vector) -
    (direction of the link), e.g. ``DOMEGA(L2, VBA, ALBA - FI2)``.

    Parameters
    ----------
    RAZMER : float or array_like
        Link length, > 0.
    VEKTOR : float or array_like
        Relative velocity (or tangential acceleration); only its magnitude is used.
    UGOL : float or array_like
        The angle whose sign gives the sense of rotation ("logical flag").

    Returns
    -------
    DOMEGA(DOMEGA)
        rad/s (or rad/s**2), counter-clockwise positive.
    """)

DVKT = book_routine(
    "DVKT", listing="II.11", lines="L664-680",
    inputs=("X1", "Y1", "X2", "Y2"), outputs=("RZ", "FI"),
    scalar=_f.dvkt, sweep=_s.dvkt_sweep, has_status=False,
    doc="""Length and signed direction of the segment from (X1, Y1) to (X2, Y2).

    Listing II.11 (L664-680), operator function VKT of Table 2, eq. (2.10).

    Parameters
    ----------
    X1, Y1, X2, Y2 : float or array_like
        Start and end of the segment.

    Returns
    -------
    DVKT(RZ, FI)
        ``RZ`` the length, ``FI`` the direction in [-pi, pi].  Coincident points give
        RZ = 0 and FI = 0: that is the book's own guard (L673), kept because the
        chapter 4 routines rely on it; the direction of a zero vector is undefined, so a
        caller must not read FI when RZ = 0.
    """)

DSMVKT = book_routine(
    "DSMVKT", listing="II.12", lines="L684-700",
    inputs=("L1", "FI1", "L2", "FI2"), outputs=("L", "FI"),
    scalar=_f.dsmvkt, sweep=_s.dsmvkt_sweep, has_status=False,
    doc="""Sum of two vectors given by magnitudes and directions.

    Listing II.12 (L684-700), operator function SMVKT, eq. (2.3).

    Parameters
    ----------
    L1, FI1 : float or array_like
        First vector: magnitude (negative means reversed) and direction, radians.
    L2, FI2 : float or array_like
        Second vector.

    Returns
    -------
    DSMVKT(L, FI)
        ``L >= 0`` the magnitude of the sum and ``FI`` its direction by DUGL5, in
        (-pi/2, 3*pi/2).
    """)
