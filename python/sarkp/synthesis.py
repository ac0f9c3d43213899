"""Chapter 3: synthesis of linkages with lower pairs (listings III.1-III.4, III.6; book
lines L887-1440).

Angles are in radians, lengths in any one unit (the book's examples are in metres).
``PI`` is 3.14159 in as-printed mode, as in every listing of the book, and pi to
double precision in corrected mode.  The book's coefficient of speed change
``KW3 = omega_3x / omega_3p`` (return over working stroke, L1023) must exceed 1.

The four-bar of this chapter is A-B-C-D: crank AB (L1) about A, coupler BC (L2), rocker
DC (L3) about D, frame AD (LO).  The book writes every straight line through a slope
(``k = tan(angle)`` or ``k = -dx/dy``), which fails for a vertical line; sarkp keeps the
same lines in normal form (ERRATA E-SYN-1), so a symmetric swing such as the book's own
``FI31 = PI/6, FI32 = 5*PI/6`` works in both modes.

sarkp extension: every routine also returns ``GMIN_TURN`` and ``GMAX_TURN``, the
smallest and the largest transmission angle (the angle BCD between coupler and rocker,
in [0, pi]) that the mechanism it built reaches over a full turn of the crank, in closed
form: for a four-bar the extremes are where the crank is collinear with the frame, for a
crank-slider where it is perpendicular to the guide.  The book controls the transmission
angle at the extreme positions at most (DSNTZ2), and between them it can fall well below
what was asked.  0 or pi means the linkage locks (it cannot make a full turn).
"""

from __future__ import annotations

import numpy as np

from . import _wrap_synthesis as _w
from .library import ST_REQUIREMENT, ST_SINGULAR, Check, describe
from .report import fortran_write
# Dimensional synthesis over the Mechanism (function, path and motion generation):
from .dimensional import (FourBarPopulation, Synthesis, fourbar_search,
                          function_generation, grashof_type, motion_generation,
                          path_generation, slider_function_generation)

__all__ = ["DSNTZR", "DSNTZ1", "DSNTZ2", "DSNTZ3", "DSNTZK", "function_generation",
           "slider_function_generation", "path_generation", "motion_generation",
           "fourbar_search", "grashof_type", "Synthesis", "FourBarPopulation"]


# Requirements that the inputs alone decide, checked before the Fortran runs so that the
# error says which one is not met (the Fortran reports them too, as st_requirement).
_KW3_ABOVE_ONE = Check(lambda KW3, **_: KW3 <= 1.0, ST_REQUIREMENT,
                       "KW3 <= 1: the coefficient of speed change must exceed 1 "
                       "(BETA = PI (KW3 - 1)/(KW3 + 1) is the overtravel angle, > 0)")
_DISTINCT_EXTREMES = Check(
    lambda FI31, FI32, **_: np.abs(np.sin((FI31 - FI32) / 2.0)) < 1e-12, ST_REQUIREMENT,
    "FI31 = FI32 (mod 2 pi): the two extreme positions of the rocker coincide")


# ---- III.1 DSNTZR -------------------------------------------------------------------

_DSNTZR_MESSAGES = {
    ST_REQUIREMENT: "two of the three positions of C coincide in the crank's frame, or "
                    "the circle through them is centred on the crank pivot: no crank",
    ST_SINGULAR: "the three positions of C lie on one straight line (the perpendicular "
                 "bisectors are parallel): no circle passes through them",
}

_DSNTZR_FORMATS = (
    "(1X,'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/' ЧЕТЫРЕХЗВЕННИКА И КРИВОШИПНО-ПОЛЗУННОГО'/"
    "' МЕХАНИЗМА ПО ТРЕМ ПОЛОЖЕНИЯМ ВХОДНОГО И ВЫХОДНОГО'/' ЗВЕНЬЕВ.'//"
    "' ИСХОДНЫЕ ДАННЫЕ:'//' L3 = ',F7.3/)",
    "(4X,'LO',5X,'F11',4X,'F13')",
    "(1X,3F7.3)",
    "(1X,'ВЫХОДНЫЕ ПАРАМЕТРЫ: L1 = ',F7.3,' L2 = ',F7.3)",
)


def dsntzr_report(LO, L3, FI1, FI3, L1, L2) -> str:
    """DSNTZR's printout for AAA = 0 (FORMATs 1-4, L1007-1017)."""
    f1, f2, f3, f4 = _DSNTZR_FORMATS
    out = [fortran_write(f1, [L3]), fortran_write(f2)]
    out += [fortran_write(f3, [LO[k], FI1[k], FI3[k]]) for k in range(3)]
    out.append(fortran_write(f4, [L1, L2]))
    return "\n".join(out)


def _dsntzr_report(i, o):
    return dsntzr_report(i["LO"], i["L3"], i["FI1"], i["FI3"], o[0], o[1])


DSNTZR = describe(
    _w.DSNTZR, listing="III.1", lines="L887-1019",
    messages=_DSNTZR_MESSAGES,
    report=_dsntzr_report,
    doc="""Three-position synthesis of a four-bar or a crank-slider (listing III.1,
    L887-1019; Table 3, L897-917).

    The book's call is ``CALL DSNTZR(LO, L3, FI1, FI3, AAA, L1, L2)`` (III.1, printed
    as ``F11, F13``); program X calls it with an 8th argument, the crank angle
    ``FI11`` (L7316), which sarkp returns as the third result (ERRATA E-DSNTZR-3).

    Inversion about the crank (Table 3): with ``d = FI1[0] - FI1[i]`` the rocker pin in
    the crank's frame is ``C_i = LO[i] e(d) + L3 e(FI3[i] + d)``; the crank pin B is the
    centre of the circle through C_1, C_2, C_3.  The mechanism passes exactly through
    the three given positions.

    Returns
    -------
    DSNTZR(L1, L2, FI11, GMIN_TURN, GMAX_TURN)
        ``L1`` crank AB, ``L2`` coupler BC, ``FI11`` the crank angle of the first
        position in the frame with A at the origin and D (or the guide) along x
        (Table 3 step 12, taken over the full circle, ERRATA E-DSNTZR-4).  The crank
        angle of position i is ``FI11 + FI1[i] - FI1[0]``.  ``GMIN_TURN``,
        ``GMAX_TURN`` (sarkp extension): the extreme transmission angles over a full
        crank turn; three equal FI3 are taken as a crank-slider (guide at the offset
        ``L3 sin(FI3)``), otherwise a four-bar with the frame ``LO[0]``.

    Raises
    ------
    RequirementError
        Two positions of C coincide, or B falls on the crank pivot.
    SingularError
        The three positions of C are collinear: no circle passes through them.

    Notes
    -----
    Three positions of the same assembly branch are not guaranteed (the classical
    branch defect of three-position synthesis); nothing checks it, as in the book.
    """)


# ---- III.2 DSNTZ1 -------------------------------------------------------------------

_DSNTZ1_FORMAT = (
    "(1X,'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/' ЧЕТЫРЕХЗВЕННИКА ПО ДВУМ ПОЛОЖЕНИЯМ И KW3.'/"
    "' ВХОДНЫЕ ПАРАМЕТРЫ:'/' KW3 = ',F5.3,' FI31 = ',F7.4,' FI32 = ',F7.4,' L3 = ',F6.3,"
    "' XD = ',F7.3,' Q = ',F3.0//1X,'ВЫХОДНЫЕ ПАРАМЕТРЫ:'/"
    "' L1 = ',F7.3,' L2 = ',F7.3,' LO = ',F7.3)")


def _dsntz1_report(i, o):
    return fortran_write(_DSNTZ1_FORMAT, [i["KW3"], i["FI31"], i["FI32"], i["L3"], i["XD"],
                                   i["Q"], *o[:3]])


DSNTZ1 = describe(
    _w.DSNTZ1, listing="III.2", lines="L1023-1105",
    checks=(_KW3_ABOVE_ONE, _DISTINCT_EXTREMES),
    messages={
        ST_REQUIREMENT: "no crank-rocker with the crank pivot on the x axis meets the "
                        "requirement: the circle through C1 and C2 misses "
                        "the x axis, or (corrected mode) it meets the axis only where it "
                        "sees C1C2 under PI - BETA or the swing is half a turn, or with "
                        "this Q the crank comes out <= 0 (C1 must be the farther extreme "
                        "position: try the other Q), or the crank cannot make a full turn "
                        "between the two extreme positions",
        ST_SINGULAR: "as-printed mode: the listing's line through C1 at FI31 + BETA is "
                     "parallel to the perpendicular bisector of C1C2"},
    report=_dsntz1_report,
    doc="""Four-bar from the two extreme rocker positions and the coefficient of speed
    change (listing III.2, L1023-1105; Table 4, L1034-1051).

    The book's call is ``CALL DSNTZ1(KW3, FI31, FI32, L3, XD, Q, AAA, L1, L2, LO)``.

    C1, C2 = D + L3 e(FI31), D + L3 e(FI32) with D = (XD, 0),
    ``BETA = PI (KW3 - 1)/(KW3 + 1)``; E is a point of the perpendicular bisector SD of
    C1C2 (S its midpoint); the crank pivot A is where the circle (E, |EC1|) meets the
    x axis, ``XA = XE + sign(Q) sqrt(R**2 - YE**2)``; ``L1 = (|AC1| - |AC2|)/2``,
    ``L2 = |AC1| - L1``, ``LO = |XD - XA|``.  The two modes differ in E
    (ERRATA E-DSNTZ1-4):

    * corrected (default): the construction of the prose (L1029, L1053).  The lines
      through C1 and C2 at the angle BETA to SD meet on SD at E, on D's side:
      ``E = S + (|C1C2|/2) cot(BETA) (D - S)/|SD|``.  The angle C1EC2 is 2 BETA, so
      from A (on D's side of the chord) C1C2 is seen under BETA and the mechanism has
      exactly the requested KW3 = (PI + BETA)/(PI - BETA) as well as the requested
      extreme positions.  For the book's example (Fig. 10 inputs, exact pi):
      L1, L2, LO = 0.3903, 0.7216, 0.6504.
    * as-printed: the listing, ``KC1E = TAN(FI31 + BETA)`` (L1078): E on SD and on the
      line through C1 at the fixed direction FI31 + BETA.  The extreme positions are
      right, but the angle C1AC2 is PSI/2 - BETA instead of BETA, so KW3 is in general
      not met (the book's example realizes 1.3077 for 1.5): 0.4056, 0.8347, 0.7818.

    Returns
    -------
    DSNTZ1(L1, L2, LO, GMIN_TURN, GMAX_TURN)
        Crank AB, coupler BC, frame AD; ``GMIN_TURN``, ``GMAX_TURN`` (sarkp extension):
        the extreme transmission angles (angle BCD) over a full crank turn.

    Raises
    ------
    RequirementError
        KW3 <= 1, FI31 = FI32, the circle misses the axis, a crank <= 0 (wrong Q), a
        crank that cannot make a full turn between the extreme positions; in corrected
        mode also a swing of half a turn, or an A on the far side of the chord C1C2
        (where the circle sees C1C2 under PI - BETA).
    SingularError
        As-printed mode only: the two lines that define E are parallel.

    Notes
    -----
    Neither mode reproduces the book's printed 0.411 / 0.904 / 0.858 (Fig. 10), nor the
    course project's ROA 0.166, RAB 2.335, ROC 2.090 (ch. 10); no reading of the
    listing or the prose that was tried gives both (ERRATA E-DSNTZ1-4).  The mirror
    arc of the circle beyond the chord also sees C1C2 under BETA; where the x axis
    meets it there may be a further, less common, solution, which the book does not
    consider and DSNTZ1 does not return.  The book's unconditional debug ``PRINT 5``
    (L1094) is dropped (E-DSNTZ1-2).
    """)


# ---- III.3 DSNTZ2 -------------------------------------------------------------------

_DSNTZ2_FORMATS = (
    "(1X,'СИНТЕЗ ШАРНИРНОГО ЧЕТЫРЕХЗВЕННИКА ПО'/' УГЛУ ПЕРЕДАЧИ ДВИЖЕНИЯ И КОЭФФИЦИЕНТУ "
    "ИЗМЕНЕНИЯ'/' СКОРОСТИ ВЫХОДНОГО ЗВЕНА'//)",
    "(1X,'ВХОДНЫЕ ПАРАМЕТРЫ СИНТЕЗА:'/' KW3 = ',F6.4,' FI3 = ',F6.4,' L3 = ',F7.4,"
    "' XD = ',F7.4,' GMIN = ',F6.4,' GMAX = ',F6.4/1X,'ВЫХОДНЫЕ ПАРАМЕТРЫ СИНТЕЗА:'/"
    "' L1 = ',F7.4,' L2 = ',F7.4,' LO = ',F7.4,' XA = ',F7.4,' YA = ',F7.4//)",
)


_POSITIVE_SWING = Check(
    lambda KW3, GMIN, GMAX, **_: np.logical_not(
        np.pi * (KW3 - 1.0) / (KW3 + 1.0) + GMAX - GMIN > 0.0),
    ST_REQUIREMENT,
    "GMIN - GMAX >= BETA = PI (KW3 - 1)/(KW3 + 1): the rocker's swing PSI = BETA + GMAX - "
    "GMIN would not be positive, and no four-bar has the transmission angle GMIN in the "
    "stretched-out and GMAX in the folded position (ERRATA E-DSNTZ2-4)")


def _dsntz2_report(i, o):
    return "\n".join([fortran_write(_DSNTZ2_FORMATS[0]),
                      fortran_write(_DSNTZ2_FORMATS[1], [i["KW3"], i["FI3"], i["L3"], i["XD"],
                                                  i["GMIN"], i["GMAX"], *o[:5]])])


DSNTZ2 = describe(
    _w.DSNTZ2, listing="III.3", lines="L1109-1181",
    checks=(_KW3_ABOVE_ONE, _POSITIVE_SWING),
    messages={
        ST_REQUIREMENT: "no crank-rocker meets the requirement: the swing "
                        "PSI = BETA + GMAX - GMIN is 0, or the crank comes out <= 0, or "
                        "the crank cannot make a full turn between the two extreme "
                        "positions, or they lie on different assembly branches",
        ST_SINGULAR: "the lines C1A and C2A are parallel"},
    report=_dsntz2_report,
    doc="""Four-bar from the coefficient of speed change and the transmission angles at
    the extreme positions (listing III.3, L1109-1181; Table 5, L1114-1130).

    The book's call is ``CALL DSNTZ2(KW3, FI3, L3, XD, GMIN, GMAX, AAA, L1, L2, LO)``.

    ``BETA = PI (KW3 - 1)/(KW3 + 1)``, swing ``PSI = BETA + GMAX - GMIN``;
    C1 = D + L3 e(FI3), C2 = D + L3 e(FI3 + PSI) with D = (XD, 0); the crank pivot A is
    the intersection of the line through C1 at ``FI3 - GMIN`` with the line through C2
    at ``FI3 + PSI - GMAX``; ``L1 = (|AC1| - |AC2|)/2``, ``L2 = |AC1| - L1``,
    ``LO = |AD|``.  The resulting crank-rocker has its extreme rocker angles at FI3
    and FI3 + PSI, the coefficient of speed change KW3, and the transmission angle
    (angle BCD) GMIN in the stretched-out and GMAX in the folded extreme position
    (verified in tests/test_synthesis.py).

    Returns
    -------
    DSNTZ2(L1, L2, LO, XA, YA, GMIN_TURN, GMAX_TURN)
        Crank AB, coupler BC, frame AD, and the crank pivot A = (XA, YA), which the
        book prints in the report (L1173) but has no argument for.  ``GMIN_TURN``,
        ``GMAX_TURN`` (sarkp extension): the extreme transmission angles over a full
        crank turn, which lie beyond GMIN and GMAX in general (the book's example asks
        10 and 60 degrees and gets 9.0 to 65.1).

    Raises
    ------
    RequirementError
        KW3 <= 1, a swing PSI = BETA + GMAX - GMIN that is not positive (E-DSNTZ2-4),
        a crank <= 0, or a crank that cannot make a full turn between the extreme
        positions (or they lie on different assembly branches).
    SingularError
        The lines C1A and C2A are parallel.
    """)


# ---- III.4 DSNTZ3 -------------------------------------------------------------------

_DSNTZ3_FORMAT = (
    "(1X,'СИНТЕЗ МЕХАНИЗМА ШАРНИРНОГО'/' ЧЕТЫРЕХЗВЕННИКА ПО ДВУМ ПОЛОЖЕНИЯМ ШАТУНА.'//"
    "1X,'ВХОДНЫЕ ПАРАМЕТРЫ:'//' XB1 = ',F7.3,' YB1 = ',F7.3,' XB2 = ',F7.3,"
    "' YB2 = ',F7.3,' F11 = ',F7.3,' ALC1 = ',F7.3//1X,'ВЫХОДНЫЕ ПАРАМЕТРЫ:'//"
    "' L1 = ',F7.3,' L3 = ',F7.3,' LO = ',F7.3//)")


def _dsntz3_report(i, o):
    return fortran_write(_DSNTZ3_FORMAT, [i["XB1"], i["YB1"], i["XB2"], i["YB2"], i["FI1"],
                                   i["ALC1"], *o[:3]])


DSNTZ3 = describe(
    _w.DSNTZ3, listing="III.4", lines="L1185-1264",
    messages={
        ST_REQUIREMENT: "the two positions of B (or of C) coincide, or a length comes out "
                        "zero",
        ST_SINGULAR: "the line B1A is parallel to the bisector of B1B2 (FI1 = 0 mod 2 PI), "
                     "or the normal to the velocity of C1 is parallel to the bisector of "
                     "C1C2"},
    report=_dsntz3_report,
    doc="""Four-bar from two positions of the coupler (listing III.4, L1185-1264;
    Table 6, L1192-1212).

    The book's call is
    ``CALL DSNTZ3(XB1, YB1, XB2, YB2, XC1, YC1, XC2, YC2, FI1, ALC1, AAA, L1, L3, LO)``
    (the printed header ends ``L1, L2, LO``; the body computes L3, Table 6 too:
    ERRATA E-DSNTZ3-1).

    The crank pivot A is the intersection of the perpendicular bisector of B1B2 with the
    line through B1 at ``FIB1B2 - PI/2 + FI1/2`` (AB1B2 is isosceles with apex angle
    FI1); the rocker pivot D is the intersection of the perpendicular bisector of C1C2
    with the normal to the velocity of C1.  ``L1 = |AB1|``, ``L3 = |DC1|``,
    ``LO = |AD|``.

    Returns
    -------
    DSNTZ3(L1, L3, LO, GMIN_TURN, GMAX_TURN)
        Crank AB, rocker DC, frame AD; ``GMIN_TURN``, ``GMAX_TURN`` (sarkp extension):
        the extreme transmission angles (angle BCD, coupler B1C1) over a full crank
        turn.

    Notes
    -----
    As printed, the run behind Fig. 10 had KB1A, KS2D and L3 as implicit INTEGERs
    (ERRATA E-DSNTZ3-2): as-printed mode truncates them and gives the printed
    0.401 / 0.0 / 0.574; corrected mode gives 0.412 / 0.425 / 0.575.

    Raises
    ------
    RequirementError
        Coincident positions of B or C, or a zero length.
    SingularError
        Parallel lines (FI1 = 0, or the normal at C1 parallel to the bisector of C1C2).
    """)


# ---- III.6 DSNTZK -------------------------------------------------------------------

_DSNTZK_FORMAT = ("(1X,'ДЛИНА КРИВОШИПА L1 = ',F6.4,'МЕЖЦЕНТРОВОЕ РАССТОЯНИЕ LO = ',F6.4,"
                  "'ДЛИНА КУЛИСЫ L3 = ',F6.4)")


def _dsntzk_report(i, o):
    return fortran_write(_DSNTZK_FORMAT, list(o[:3]))


DSNTZK = describe(
    _w.DSNTZK, listing="III.6", lines="L1397-1437",
    checks=(_KW3_ABOVE_ONE,),
    messages={ST_REQUIREMENT: "the reserve H is not smaller than the slotted link "
                              "L3 = S/(2 sin BETA) (oscillating) or S/2 (rotating): "
                              "no room for the crank and the centre distance"},
    report=_dsntzk_report,
    doc="""Slotted-link (crank and slotted lever) mechanism (listing III.6, L1397-1437;
    operator function SNTZK, eq. (3.3)).

    The book's call is ``CALL DSNTZK(KW3, S, H, Q, AAA, L1, LO, L3)``.

    ``BETA = (PI/2)(KW3 - 1)/(KW3 + 1)`` is half the swing of the slotted link.
    Oscillating link (Q != 0): ``LAMBDA = sin(BETA)``, ``L3 = S/(2 LAMBDA)``; rotating
    link (Q = 0): ``LAMBDA = 1/sin(BETA)``, ``L3 = S/2``; then
    ``LO = (L3 - H)/(1 + LAMBDA)``, ``L1 = LAMBDA LO``, so that ``L3 = LO + L1 + H``.

    Returns
    -------
    DSNTZK(L1, LO, L3, GMIN_TURN, GMAX_TURN)
        Crank, centre distance, slotted-link length; ``GMIN_TURN``, ``GMAX_TURN``
        (sarkp extension): both pi/2, since the block on the crank pin pushes the
        slotted link along the normal to the slot, the direction its point moves in.

    Raises
    ------
    RequirementError
        KW3 <= 1, or H >= L3 (no room left for the crank).

    Notes
    -----
    The book prints no example of DSNTZK.
    """)
