"""Chapter 2: the operator functions (listings II.1-II.12, book lines L425-700).

Angles are in radians (L166).  ``PI`` is 3.14159 in as-printed mode, as in every
listing of the book, and pi to double precision in corrected mode.
"""

from __future__ import annotations

from .library import ST_SINGULAR, Check, book_routine

__all__ = ["DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL",
           "DMOMNT", "DOMEGA", "DVKT", "DSMVKT", "NOMER_METHODS"]

#: DINTGR's methods, as the listing's code and comments number them (L443-447).
NOMER_METHODS = {1: "Simpson", 2: "trapezoids", 3: "rectangles"}

DINTGR = book_routine(
    "DINTGR", listing="II.1", lines="L435-480", chapter="operators",
    inputs=("M", "H", "NOMER", "Y"), outputs=("FINT",),
    tables={"Y": "M"}, integers={"M": range(2, 2**31 - 1), "NOMER": tuple(NOMER_METHODS)},
    nonzero=("H",),
    doc="""Running integral of a tabulated function (listing II.1, L435-480).

    The book's call is ``CALL DINTGR(M, H, NOMER, Y, FINT)``.

    Parameters
    ----------
    M : int
        Number of points; must equal ``len(Y)`` (at least 2).
    H : float
        Step of the table, non-zero (the printed header names it ``N``: ERRATA
        E-DINTGR-1).
    NOMER : {1, 2, 3}
        Method, numbered as the listing's code does (L443-447): 1 Simpson,
        2 trapezoids, 3 rectangles.  The prose at L431 numbers them the other way
        round (1 rectangles, 3 Simpson); the code is followed (ERRATA E-DINTGR-2).
    Y : array_like, shape (M,)
        The values of the integrand at the M points.

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

DFRNCL = book_routine(
    "DFRNCL", listing="II.2", lines="L490-509", chapter="operators",
    inputs=("M", "H", "Y"), outputs=("FDIF",),
    tables={"Y": "M"}, integers={"M": range(2, 2**31 - 1)}, nonzero=("H",),
    doc="""Numerical derivative of a tabulated function (listing II.2, L490-509).

    The book's call is ``CALL DFRNCL(M, H, FDIF, Y)``: the output comes before the input
    (confirmed by the call at L5988); in Python the output is the result.

    Parameters
    ----------
    M : int
        Number of points; must equal ``len(Y)`` (at least 2).
    H : float
        Step of the table, non-zero.
    Y : array_like, shape (M,)
        The function values.

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

DUGL1 = book_routine(
    "DUGL1", listing="II.3", lines="L551-569",
    inputs=("X1", "Y1", "X2", "Y2"), outputs=("DUGL1",),
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators", function=True,
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
    chapter="operators",
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
    chapter="operators",
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
