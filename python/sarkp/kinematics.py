"""Chapter 4: kinematics of the class-II Assur groups (listings IV.1-IV.20, L1440-3004).

Group kinds (book section 4.2, Figs. 14-18; links 2 and 3 belong to the group, the guides
to external links M and N):

====  =====  =============================================================================
kind  pairs  group
====  =====  =============================================================================
1     RRR    external revolutes A, C; internal revolute B (AB = RZ2, CB = RZ3)
2     RRP    external revolute A; internal revolute B; slider 3 on the guide of link M
3     RPR    slider 2 pivoted at A slides along link 3 pivoted at C (slotted lever)
4     PRP    sliders 2, 3 on the guides of links M, N, joined by the revolute B
5     RPP    block 3 pivoted at C slides in link 2, link 2 slides on the guide of link M
====  =====  =============================================================================

Routines: positions ``DPRM1``-``DPRM4`` (+ ``DPRM5``, an extension: the book has none,
L1659), velocities ``DSKOR1``-``DSKOR5``, accelerations ``DUSKR1``-``DUSKR5`` and the
combined ``DKNMA1``-``DKNMA5`` (``ANALOG = 1`` stops after the velocities).

Conventions, those of the book: lengths in any consistent unit (the book uses metres),
angles in radians from +x, counter-clockwise positive; a linear velocity or acceleration
is a pair (modulus, direction angle); only angular velocities ``W*`` and angular
accelerations ``E*`` are signed (counter-clockwise positive).  The inputs come before
``AAA`` (the print flag, unused by these routines) and the results are returned, in the
book's order, as a named tuple.  Velocities become velocity *analogues* (per unit input
angular velocity) when the inputs are analogues.

Dead centres: one policy for every routine of this module.  Each routine estimates the
relative error of its results from the conditioning of what it solved: for its 2x2
system the perturbation bound ``|A^-1| (|dA| |y| + |db|)`` (the errors of the matrix
and of the right-hand side: a few roundings of their data, plus, in DKNMA, the
sensitivity of the position found inside and the error of the velocities an
acceleration system is built from), relative to the larger of the result and the size
of the data; for a position its sensitivity (how far it moves when its inputs move by
one rounding).  With ``d = floor(-log10(estimate))`` correct significant digits:

* ``d < 1`` (estimate above 0.1): not even the first digit is assured, and
  ``SingularError`` is raised instead of returning rounding noise;
* ``1 <= d <= 7``: the results are returned with a ``SignificanceWarning`` that states
  ``d`` (status ``SIGNIFICANCE`` under ``on_error="nan"``);
* ``d >= 8``: nothing is said.

The estimate is an upper bound of the true error (tested against mpmath references on
sequences that approach each kind's dead centre from 1e-1 to 1e-15).  GELG's EPS = 1e-4
pivot test stays what it is in the book, GELG's IER.  Results that overflow raise
``RangeError``.  Kind 5 is solved in the frame of the guide, so that a small slot angle
``T2`` costs no digits, and every routine works relative to the group's own points, so
that a mechanism far from the origin keeps its digits.
"""

from __future__ import annotations


from . import _wrap_kinematics as _w
from .library import describe


__all__ = ["DPRM1", "DPRM2", "DPRM3", "DPRM4", "DPRM5",
           "DSKOR1", "DSKOR2", "DSKOR3", "DSKOR4", "DSKOR5",
           "DUSKR1", "DUSKR2", "DUSKR3", "DUSKR4", "DUSKR5",
           "DKNMA1", "DKNMA2", "DKNMA3", "DKNMA4", "DKNMA5"]

_RAISES_ASSEMBLY = """    AssemblyError
        The links do not reach: the group cannot be assembled in this position."""
_RAISES_SINGULAR = """    SingularError
        {what}"""
_WARNS = """    SignificanceWarning
        Near a dead centre: fewer than 8 significant digits are left (the warning states
        how many); the result is kept.  With none left, SingularError (module docstring:
        the dead-centre policy)."""


def _raises(assembly=None, singular=None, warns=True):
    parts = []
    if assembly:
        parts.append(_RAISES_ASSEMBLY)
    if singular:
        parts.append(_RAISES_SINGULAR.format(what=singular))
    text = "\n    Raises\n    ------\n" + "\n".join(parts) if parts else ""
    if warns:
        text += "\n\n    Warns\n    -----\n" + _WARNS
    return text + "\n"


# ---------------------------------------------------------------------------------------
# positions
# ---------------------------------------------------------------------------------------

DPRM1 = describe(
    _w.DPRM1, listing="IV.1", lines="L1479-1505",
    doc="""Positions of a kind-1 group (RRR): the internal joint B of links AB and CB.

    Listing IV.1 (L1479-1505), operator function PRM1 (Table 7, Fig. 14).

    Branch: P keeps the book's sign (tests/test_branch_conventions.py): P = -1 places B
    on the left of the directed line A -> C, where ``Mechanism.rrr(..., branch=+1)``
    places it; the Mechanism's one rule is explained in the docs' concepts page.

    Returns
    -------
    DPRM1(FI2, FI3, XB, YB)
        ``FI2`` direction of A -> B and ``FI3`` direction of C -> B, rad, made
        non-negative by DUGOL as printed: in [0, 2*pi) for P = +1, up to 3*pi for
        P = -1 (Fig. 91 prints FICB = 3.14...3.84).  ``XB, YB`` the joint B, m.
""" + _raises(assembly=True, singular="A = C with RZ2 = RZ3 (B anywhere on a circle).",
              warns=False))

DPRM2 = describe(
    _w.DPRM2, listing="IV.2", lines="L1531-1558",
    doc="""Positions of a kind-2 group (RRP): link AB with a slider B on a guide.

    Listing IV.2 (L1531-1558), operator function PRM2 (Table 8, Fig. 15).  The guide
    axis passes through K with direction FIM; B is ``RZ3*sin(T)`` from the guide axis,
    on the side of A.

    Branch: FIM keeps the book's meaning (tests/test_branch_conventions.py): B lies
    ahead, along FIM, of the foot of the perpendicular from A, where
    ``Mechanism.rrp(..., angle=FIM, branch=+1)`` places it; ``DPRM2(FIM + pi)`` is
    ``branch=-1`` with the same angle.  The Mechanism's ``offset`` is measured along the
    guide's left normal: ``RZ3*sin(T)`` with the sign of A's side.  The Mechanism's one
    rule is explained in the docs' concepts page.

    Returns
    -------
    DPRM2(XB, YB, FI2)
        The joint B, m, and the direction of A -> B in (-pi/2, 3*pi/2) (DUGL5), rad.
        The output order is the code's; Table 8's signature lists FI2 first.
""" + _raises(assembly=True,
              singular="A lies on the guide axis and the offset is not 0 (side undefined).",
              warns=False))

DPRM3 = describe(
    _w.DPRM3, listing="IV.3", lines="L1577-1598",
    doc="""Positions of a kind-3 group (RPR, slotted lever): direction of link 3.

    Listing IV.3 (L1577-1598), operator function PRM3 (Table 9, Fig. 16).  The slider 2
    pivoted at A slides along link 3, which turns about C.

    Branch: P keeps the book's sign (tests/test_branch_conventions.py): P = -1 gives the
    direction of link 3 that ``Mechanism.rpr(..., branch=+1)`` gives; the Mechanism's
    one rule is explained in the docs' concepts page.

    Returns
    -------
    DPRM3(RZAC, FI3, FICA)
        ``RZAC`` = AC, m; ``FI3`` direction of the axis of link 3, rad (within pi/2 of
        FICA, not wrapped); ``FICA`` direction of C -> A in (-pi, pi], rad.  Pass FI3
        unchanged to ``DSKOR3`` (its sign test compares FI3 with FICA).
""" + _raises(assembly=True, singular="A = C with a zero offset (axis undefined).",
              warns=False))

DPRM4 = describe(
    _w.DPRM4, listing="IV.4", lines="L1622-1657",
    doc="""Positions of a kind-4 group (PRP): the joint B of two sliders on two guides.

    Listing IV.4 (L1622-1657), operator function PRM4 (Table 10, Fig. 17).  Corrected:
    the printed ``X(1,2) = TAN(FIM)`` lost its minus sign (E-DPRM4-1) and the line
    ``X(2,2) = -TAN(FIN)`` is missing (E-DPRM4-2).  Guides at +-pi/2 work (the lines are
    written without TAN).

    Returns
    -------
    DPRM4(XB, YB, RVBM, FIVBM, RVBN, FIVBN)
        The joint B, m; the distance (m) and direction in [0, 2*pi) (rad) of B from the
        centres VM and VN, as ``DSKOR4``/``DUSKR4`` take them.
""" + _raises(singular="The guides are parallel."))

DPRM5 = describe(
    _w.DPRM5, listing="extension (none in the book, L1659)", lines="L1659",
    doc="""Positions of a kind-5 group (RPP) -- an extension, not a book routine.

    The book prints no position routine for kind 5: "the coordinates of the joint centre
    C and of the guide fully determine the linear and angular coordinates of the links"
    (L1659; Table 33, L6287, lists DPRM1-DPRM4).  Both links turn with link M; this
    routine returns where they are along their guides.

    Returns
    -------
    DPRM5(XK, YK, S2, S3)
        ``XK, YK`` the point where the slot axis of link 2 through C meets the axis of
        guide M, m; ``S2`` the signed distance A -> K along FIM and ``S3`` the signed
        distance K -> C along FIM + T2, m: ``C = A + S2*e(FIM) + S3*e(FIM + T2)``.  For a
        fixed guide, dS2/dt and -dS3/dt are the signed sliding speeds VC2CM and VC2C3 of
        ``DSKOR5``.
""" + _raises(singular="sin(T2) = 0: the slot is parallel to the guide."))

# ---------------------------------------------------------------------------------------
# velocities
# ---------------------------------------------------------------------------------------

DSKOR1 = describe(
    _w.DSKOR1, listing="IV.5", lines="L1692-1719",
    doc="""Velocities of a kind-1 group (RRR): ``v_A + v_BA = v_C + v_BC``.

    Listing IV.5 (L1692-1719), operator function SKOR1 (Table 11, Fig. 19).

    Returns
    -------
    DSKOR1(VBA, ALBA, VBC, ALBC, VB, ALB, W2, W3)
        Velocity of B relative to A and to C (perpendicular to AB, CB), the absolute
        velocity of B (direction in (-pi/2, 3*pi/2)), and the signed angular velocities
        of links 2 and 3, rad/s.
""" + _raises(singular="Dead centre: AB and CB are collinear (FI2 = FI3 mod pi)."))

DSKOR2 = describe(
    _w.DSKOR2, listing="IV.6", lines="L1740-1774",
    doc="""Velocities of a kind-2 group (RRP): ``v_A + v_BA = v_BM + v_BBM``.

    Listing IV.6 (L1740-1774), operator function SKOR2 (Table 12, Fig. 20).  The printed
    header lacks the outputs VBA, ALBA that every call in the book passes (E-DSKOR2-1).

    Returns
    -------
    DSKOR2(VBA, ALBA, VBBM, ALBBM, VB, ALB, W2)
        Velocity of B relative to A; sliding velocity of B along the guide (direction
        FIM or FIM - pi); absolute velocity of B; signed angular velocity of AB, rad/s.
""" + _raises(singular="AB is perpendicular to the guide (dead centre)."))

DSKOR3 = describe(
    _w.DSKOR3, listing="IV.7", lines="L1805-1854",
    doc="""Velocities of a kind-3 group (RPR): ``v_A3 = v_A + v_A3A = v_C + v_A3C``.

    Listing IV.7 (L1805-1854), operator function SKOR3 (Table 13, Fig. 21).  A3 is the
    point of link 3 that coincides with A.

    Returns
    -------
    DSKOR3(VA3A, ALA3A, VA3C, ALA3C, VA3, ALA3, W3)
        Velocity of A3 relative to A (along the axis: FI3 or FI3 - pi), relative to C
        (perpendicular to CA), absolute; signed angular velocity of links 2 and 3, rad/s.
""" + _raises(singular="A = C."))

DSKOR4 = describe(
    _w.DSKOR4, listing="IV.8", lines="L1879-1918",
    doc="""Velocities of a kind-4 group (PRP): ``v_BM + v_BBM = v_BN + v_BBN``.

    Listing IV.8 (L1879-1918), operator function SKOR4 (Table 14, Fig. 22).  Corrected:
    the printed right-hand side uses ``ABS(WM)`` where ``ABS(WN)`` belongs (E-DSKOR4-3).

    Returns
    -------
    DSKOR4(VBBM, ALBBM, VBBN, ALBBN, VB, ALB)
        Sliding velocities of B along guides M and N (directions FIM or FIM - pi, FIN or
        FIN - pi) and the absolute velocity of B.
""" + _raises(singular="The guides are parallel."))

DSKOR5 = describe(
    _w.DSKOR5, listing="IV.9", lines="L1947-1978",
    doc="""Velocities of a kind-5 group (RPP): ``v_C2 = v_C3 + v_C2C3 = v_CM + v_C2CM``.

    Listing IV.9 (L1947-1978), operator function SKOR5 (Table 15, Fig. 23).  C2 is the
    point of link 2 at C; links M, 2 and 3 all turn with WM.

    Returns
    -------
    DSKOR5(VC2C3, ALC2C3, VC2CM, ALC2CM, VC2, ALC2)
        Velocity of C2 relative to C3 (along FIM + T2 or reversed), relative to the
        guide point CM (along FIM or reversed), and absolute.
""" + _raises(singular="sin(T2) = 0: the slot is parallel to the guide."))

# ---------------------------------------------------------------------------------------
# accelerations
# ---------------------------------------------------------------------------------------

DUSKR1 = describe(
    _w.DUSKR1, listing="IV.10", lines="L2017-2051",
    doc="""Accelerations of a kind-1 group (RRR).

    Listing IV.10 (L2017-2051), operator function USKR1 (Table 16, Fig. 24):
    ``a_A + a^n_BA + a^t_BA = a_C + a^n_BC + a^t_BC``.

    The printed line ``ABCT = ABS(Y(1))`` (L2043) should read ``Y(2)`` (ERRATA
    E-DUSKR1-1).  Corrected mode fixes it; as-printed mode keeps it, because the book's
    Fig. 91 (ch. 10) was computed with it (there ABCT = ABAT and E3 = +-|E2|*RZ2/RZ3).

    Returns
    -------
    DUSKR1(ABAT, BBAT, ABCT, BBCT, AB, BB, E2, E3)
        Tangential accelerations of B relative to A and to C, the absolute acceleration
        of B, and the signed angular accelerations of links 2, 3, rad/s**2.
""" + _raises(singular="Dead centre: AB and CB are collinear."))

DUSKR2 = describe(
    _w.DUSKR2, listing="IV.11", lines="L2077-2119",
    doc="""Accelerations of a kind-2 group (RRP).

    Listing IV.11 (L2077-2119), operator function USKR2 (Table 17, Fig. 25):
    ``a_A + a^n_BA + a^t_BA = a_BM + a^k + a^r``.  ``VBAT`` and ``BVBM`` are directions
    (the author's names, kept).

    Returns
    -------
    DUSKR2(ABAT, VBAT, ABVM, BVBM, E2, AB, BB)
        Tangential acceleration of B relative to A; relative (sliding) acceleration of B
        along the guide; the angular acceleration of AB, rad/s**2; the absolute
        acceleration of B.
""" + _raises(singular="AB is perpendicular to the guide."))

DUSKR3 = describe(
    _w.DUSKR3, listing="IV.12", lines="L2150-2184",
    doc="""Accelerations of a kind-3 group (RPR).

    Listing IV.12 (L2150-2184), operator function USKR3 (Table 18, Fig. 26):
    ``a_A3 = a_A + a^k + a^r = a_C + a^n_A3C + a^t_A3C``.

    Returns
    -------
    DUSKR3(AA3AR, BA3AR, AA3CT, BA3CT, E3, AA3, BA3)
        Relative acceleration of A3 along the axis; tangential acceleration of A3
        relative to C; angular acceleration of link 3, rad/s**2; absolute acceleration of
        A3.
""" + _raises(singular="The axis of link 3 is perpendicular to CA (only at the assembly limit)."))

DUSKR4 = describe(
    _w.DUSKR4, listing="IV.13", lines="L2221-2275",
    doc="""Accelerations of a kind-4 group (PRP).

    Listing IV.13 (L2221-2275), operator function USKR4 (Table 19, Fig. 27):
    ``a_BM + a^k_M + a^r_M = a_BN + a^k_N + a^r_N``.  The guide points under B are taken
    to rotate about VM, VN (exact when these are fixed pivots).  Corrected: the printed
    direction of the guide point's acceleration has a stray ``PID2 +`` that turns it by
    pi (E-DUSKR4-1, E-DUSKR4-2).  Note the order WM, EM, WN, EN (``DKNMA4``: WM, WN, EM, EN).

    Returns
    -------
    DUSKR4(ABBMR, BBBMR, ABBNR, BBBNR, AB, BB)
        Relative accelerations of B along guides M and N, and the absolute acceleration
        of B.
""" + _raises(singular="The guides are parallel."))

DUSKR5 = describe(
    _w.DUSKR5, listing="IV.14", lines="L2308-2378",
    doc="""Accelerations of a kind-5 group (RPP).

    Listing IV.14 (L2308-2378), operator function USKR5 (Table 20, Fig. 28):
    ``a_C2 = a_C3 + a^k_23 + a^r_23 = a_CM + a^k_2M + a^r_2M``.  Corrected: the stray
    ``PID2 +`` of DUSKR4 is here too (E-DUSKR5-1).  Note the order FIM, WM, EM, T2
    (``DSKOR5``: FIM, T2, WM).

    Returns
    -------
    DUSKR5(AC2C3R, BC2C3R, AC2CMR, BC2CMR, AC2, BC2)
        Relative accelerations of C2 with respect to C3 and to the guide, and the
        absolute acceleration of C2.
""" + _raises(singular="sin(T2) = 0."))

# ---------------------------------------------------------------------------------------
# combined
# ---------------------------------------------------------------------------------------

DKNMA1 = describe(
    _w.DKNMA1, listing="IV.16", lines="L2553-2658",
    doc="""Kind-1 group (RRR): positions, velocities and accelerations in one call.

    Listing IV.16 (L2553-2658), operator function KNMA1 of textbook [1] (L2551).  The
    printed call of a four-argument ``DUGL1`` that the book never defines is read from
    the geometry as the direction C -> A (E-DKNMA1-2).

    Branch: P keeps the book's sign (tests/test_branch_conventions.py): P = +1 places B
    on the left of the directed line A -> C, where ``Mechanism.rrr(..., branch=+1)`` and
    ``DPRM1(..., P=-1)`` place it; the Mechanism's one rule is explained in the docs'
    concepts page.

    Returns
    -------
    DKNMA1(XB, YB, FI2, FI3, VBA, ALBA, VBC, ALBC, VB, ALB, W2, W3, ABCN, ABAN, ABAT,
    BBAT, ABCT, BBCT, AB, BB, E2, E3)
        B; directions A -> B and C -> B in (-pi, pi]; velocities as ``DSKOR1``; the
        normal accelerations ``ABCN = W3**2*RZ3``, ``ABAN = W2**2*RZ2``; the rest as
        ``DUSKR1`` (corrected: here ABCT = |y2| as printed).
""" + _raises(assembly=True, singular="Dead centre (AB, CB collinear) or A = C."))

DKNMA2 = describe(
    _w.DKNMA2, listing="IV.17", lines="L2660-2747",
    doc="""Kind-2 group (RRP): positions, velocities and accelerations in one call.

    Listing IV.17 (L2660-2747), operator function KNMA2 of textbook [1].  Corrected: the
    side of A relative to the guide (E-DKNMA2-3) and the sign of E2 when W2 < 0
    (E-DKNMA2-4).

    Branch: P keeps the book's sign (tests/test_branch_conventions.py): P = +1 places B
    ahead, along FIM, of the foot of the perpendicular from A, where
    ``Mechanism.rrp(..., angle=FIM, branch=+1, offset=RZ3*sin(ETA))`` and ``DPRM2(FIM)``
    place it; P = -1 is ``branch=-1`` and ``DPRM2(FIM + pi)``.  The Mechanism's one rule is
    explained in the docs' concepts page.

    Returns
    -------
    DKNMA2(XB, YB, FI2, VBA, ALBA, VBBM, ALBBM, VB, ALB, W2, ABAN, ABK, BBK, ABAT, BBAT,
    ABBM, BBBM, AB, BB, E2)
        B and the direction A -> B in (-pi, pi]; velocities as ``DSKOR2``; normal
        acceleration ``ABAN = W2**2*RZ2``; Coriolis acceleration ``ABK, BBK``;
        tangential acceleration of B relative to A; relative acceleration along the
        guide; absolute acceleration of B; angular acceleration of AB.
""" + _raises(assembly=True, singular="AB perpendicular to the guide."))

DKNMA3 = describe(
    _w.DKNMA3, listing="IV.18", lines="L2749-2829",
    doc="""Kind-3 group (RPR, slotted lever): positions, velocities, accelerations.

    Listing IV.18 (L2749-2829), operator function KNMA3 of textbook [1].  The printed
    header lost two outputs, ALAR and VAC (E-DKNMA3-1); BAR is corrected (E-DKNMA3-3).

    Branch: P keeps the book's sign (tests/test_branch_conventions.py): P = +1 gives the
    direction of link 3 that ``Mechanism.rpr(..., branch=+1)`` and ``DPRM3(..., P=-1)``
    give; the Mechanism's one rule is explained in the docs' concepts page.

    Returns
    -------
    DKNMA3(XB, YB, RZBC, FI3, VAR, ALAR, VAC, ALAC, W3, VA3, ALA3, AAK, BAK, AAR, BAR,
    AACT, BACT, AA3, BA3, E3, AACN)
        B, CB and the axis direction C -> B in (-pi, pi] (taken from the points, so it
        loses accuracy as B nears C; ``DPRM3`` gives the axis from A and C and does not);
        velocity of A3 relative to A
        (along the axis) and to C; W3; absolute velocity of A3; Coriolis, relative and
        tangential accelerations; absolute acceleration of A3; E3; ``AACN = W3**2*AC``.
""" + _raises(assembly=True, singular="A = C or B = C."))

DKNMA4 = describe(
    _w.DKNMA4, listing="IV.19", lines="L2831-2929",
    doc="""Kind-4 group (PRP): positions, velocities and accelerations in one call.

    Listing IV.19 (L2831-2929), operator function KNMA4 of textbook [1].  The guide links
    are taken to rotate about A and C (the book's model: exact when A, C are their fixed
    pivots, or the guides do not turn).  Corrected: ``BB`` from the acceleration, not the
    velocity, components (E-DKNMA4-2); the guide points' acceleration direction when
    WM = 0 or WN = 0 (E-DKNMA4-3).  Note the order WM, WN, EM, EN.

    Returns
    -------
    DKNMA4(XB, YB, VB2R, ALB2R, VB3R, ALB3R, VB, ALB, AB2K, BB2K, AB3K, BB3K, AB2R, BB2R,
    AB3R, BB3R, AB, BB)
        B; velocities of B relative to guides M and N; absolute velocity; Coriolis and
        relative accelerations; absolute acceleration of B.
""" + _raises(singular="The guides are parallel."))

DKNMA5 = describe(
    _w.DKNMA5, listing="IV.20", lines="L2931-3002",
    doc="""Kind-5 group (RPP): velocities and accelerations in one call (no positions).

    Listing IV.20 (L2931-3002), operator function KNMA5 of textbook [1].  Corrected: the
    direction from the centre of link M to C (E-DKNMA5-2) and the direction of that
    point's acceleration (E-DKNMA5-4).

    Returns
    -------
    DKNMA5(VC2C3, ALC2C3, VC2CM, ALC2CM, VC, ALC, AC2C3K, BC2C3K, AC2CMK, BC2CMK, AC2C3R,
    BC2C3R, AC2CMR, BC2CMR, AC, BC)
        Velocities of C2 relative to C3 and to the guide; absolute velocity of C2;
        Coriolis and relative accelerations; absolute acceleration of C2.
""" + _raises(singular="sin(ETA2) = 0."))
