"""Chapter 2: the operator functions (listings II.1-II.12, book lines L425-700).

Angles are in radians (L166).  ``PI`` is 3.14159 in as-printed mode, as in every
listing of the book, and pi to double precision in corrected mode.
"""

from __future__ import annotations

from . import _wrap_operators as _w
from .library import ST_SINGULAR, Check, describe

__all__ = ["DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL",
           "DMOMNT", "DOMEGA", "DVKT", "DSMVKT", "NOMER_METHODS"]

#: DINTGR's methods, as the listing's code and comments number them (L443-447).
NOMER_METHODS = {1: "Simpson", 2: "trapezoids", 3: "rectangles"}

DINTGR = describe(
    _w.DINTGR, listing="II.1", lines="L435-480",
    doc="""Running integral of a tabulated function (listing II.1, L435-480).

    The book's call is ``CALL DINTGR(M, H, NOMER, Y, FINT)``.

    Returns
    -------
    DINTGR(FINT)
        ``FINT[k]`` is the integral from the first point to point k; ``FINT[0] = 0``.
        Rectangles use the right end of each step; trapezoids the two ends.  Simpson
        chains Simpson's rule over pairs of steps from the first point for ``FINT[2]``,
        ``FINT[4]``, ... and from ``FINT[1]`` for ``FINT[3]``, ``FINT[5]``, ...;
        ``FINT[1]``, the integral over the first step, is in corrected mode that of the
        parabola through the first three points, ``H (5 Y[0] + 8 Y[1] - Y[2])/12``, so
        that every point is of the fourth order (exact for cubics at the points of even
        index, for quadratics at the others); as-printed mode keeps the book's trapezoid
        ``H (Y[0] + Y[1])/2`` there, whose error of the third order every odd-index point
        carries (ERRATA E-DINTGR-4).  With M = 2 Simpson gives the trapezoid.
    """)

DFRNCL = describe(
    _w.DFRNCL, listing="II.2", lines="L490-509",
    doc="""Numerical derivative of a tabulated function (listing II.2, L490-509).

    The book's call is ``CALL DFRNCL(M, H, FDIF, Y)``: the output comes before the input
    (confirmed by the call at L5988); in Python the output is the result.

    Returns
    -------
    DFRNCL(FDIF)
        Backward differences assigned to the right-hand point:
        ``FDIF[k] = (Y[k] - Y[k-1]) / H`` for k >= 1.  The first point: corrected mode
        gives it the forward difference ``(Y[1] - Y[0]) / H``, i.e. ``FDIF[0] =
        FDIF[1]``, of the same first order as the others; as-printed mode keeps the
        book's ``FDIF[0] = 0`` whatever the derivative (ERRATA E-DFRNCL-1).
    """)


def _coincident(X1, Y1, X2, Y2):
    return (X1 == X2) & (Y1 == Y2)


_NO_DIRECTION = Check(_coincident, ST_SINGULAR,
                      "the points coincide: a segment of zero length has no direction")

DUGL1 = describe(
    _w.DUGL1, listing="II.3", lines="L551-569",
    checks=(_NO_DIRECTION,),
    doc="""Direction angle of the segment from (X1, Y1) to (X2, Y2), in [0, 2*PI).

    Listing II.3 (L551-569), operator function UGL1 of Table 2.

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

DUGL2 = describe(
    _w.DUGL2, listing="II.4", lines="L572-588",
    checks=(_NO_DIRECTION,),
    doc="""Signed direction angle of the segment from (X1, Y1) to (X2, Y2), in [-pi, pi].

    Listing II.4 (L572-588), operator function UGL2 of Table 2:
    ``SIGN(ACOS((X2-X1)/L), Y2-Y1)``.  A horizontal segment pointing left gives +pi.

    Returns
    -------
    DUGL2(DUGL2)
        The angle in radians.

    Raises
    ------
    SingularError
        The points coincide.
    """)

DUGL3 = describe(
    _w.DUGL3, listing="II.5", lines="L590-599",
    doc="""Direction set by the sign of a parameter: ``UGOL1 + sign(VEL)*|UGOLD|``.

    Listing II.5 (L590-599), operator function UGL3 of Table 2.  Typical use: the
    direction of a velocity omega x r is the link angle plus or minus pi/2, by the
    sign of omega.

    Returns
    -------
    DUGL3(DUGL3)
        The angle in radians (not wrapped).
    """)

DUGL4 = describe(
    _w.DUGL4, listing="II.6", lines="L601-612",
    doc="""Direction of a vector on its line of action: UGOL1, reversed if VEL < 0.

    Listing II.6 (L601-612), operator function UGL4 of Table 2.  Returns
    ``UGOL1 - UGOLD`` when VEL < 0 and ``UGOL1`` otherwise.  The printed arithmetic IF
    names a label 111 that does not exist (ERRATA E-DUGL4-1): VEL > 0 is taken like
    VEL = 0, as Table 2 says.  Table 2 adds UGOLD where the listing subtracts it
    (E-DUGL4-2); the listing is kept.  The book almost always passes UGOLD = PI, where
    both give the same direction.

    Returns
    -------
    DUGL4(DUGL4)
        The angle in radians.
    """)

DUGL5 = describe(
    _w.DUGL5, listing="II.7", lines="L614-628",
    doc="""Direction angle of a vector from its projections, in (-pi/2, 3*pi/2).

    Listing II.7 (L614-628), eq. (2.2) at L383: ``atan(PRY/PRX)`` for PRX > 0,
    ``PI + atan(PRY/PRX)`` for PRX < 0, and ``sign(PRY)*PI/2`` for PRX = 0 (+PI/2 for
    the zero vector, as printed).

    Returns
    -------
    DUGL5(DUGL5)
        The angle in radians.
    """)

DUGOL = describe(
    _w.DUGOL, listing="II.8", lines="L630-639",
    doc="""An angle made non-negative: FI if FI >= 0, else FI + 2*PI.

    Listing II.8 (L630-639), operator function UGOL.  One wrap only, as printed, so an
    angle below -2*PI stays negative.

    Returns
    -------
    DUGOL(DUGOL)
        The angle in radians.
    """)

DMOMNT = describe(
    _w.DMOMNT, listing="II.9", lines="L641-644",
    doc="""Moment of a force about the origin: the z-component of r x F.

    Listing II.9 (L641-644), operator function MOMNT of Table 2:
    ``R*cos(FI)*F*sin(G) - R*sin(FI)*F*cos(G) = R*F*sin(G - FI)``.

    Returns
    -------
    DMOMNT(DMOMNT)
        The moment, counter-clockwise positive.
    """)

DOMEGA = describe(
    _w.DOMEGA, listing="II.10", lines="L648-660",
    doc="""Angular velocity (or acceleration) of a link from a relative velocity.

    Listing II.10 (L648-660), eq. (2.8) at L543: ``|VEKTOR/RAZMER|`` with the sign of
    UGOL.  The book's correct call (L1716) passes UGOL = (direction of the vector) -
    (direction of the link), e.g. ``DOMEGA(L2, VBA, ALBA - FI2)``.

    Returns
    -------
    DOMEGA(DOMEGA)
        rad/s (or rad/s**2), counter-clockwise positive.
    """)

DVKT = describe(
    _w.DVKT, listing="II.11", lines="L664-680",
    doc="""Length and signed direction of the segment from (X1, Y1) to (X2, Y2).

    Listing II.11 (L664-680), operator function VKT of Table 2, eq. (2.10).

    Returns
    -------
    DVKT(RZ, FI)
        ``RZ`` the length, ``FI`` the direction in [-pi, pi].  Coincident points give
        RZ = 0 and FI = 0: that is the book's own guard (L673), kept because the
        chapter 4 routines rely on it; the direction of a zero vector is undefined, so a
        caller must not read FI when RZ = 0.
    """)

DSMVKT = describe(
    _w.DSMVKT, listing="II.12", lines="L684-700",
    doc="""Sum of two vectors given by magnitudes and directions.

    Listing II.12 (L684-700), operator function SMVKT, eq. (2.3).

    Returns
    -------
    DSMVKT(L, FI)
        ``L >= 0`` the magnitude of the sum and ``FI`` its direction by DUGL5, in
        (-pi/2, 3*pi/2).
    """)
