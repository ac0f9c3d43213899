"""Chapter 6: gear trains and involute gearing (listings VI.1, VI.3-VI.8; book lines
L3620-4857).

Lengths in mm (any one unit), angles in radians; the tool is the standard rack (profile
angle alpha = 20 deg = ``PI/9``, addendum h_a* = 1, clearance c* = 0.25).  ``PI`` is
3.14159 in as-printed mode, as in every listing of the book, and pi to double precision
in corrected mode.  Tooth numbers are whole numbers; the geometry routines take them as
floats (as the book's REAL Z1, Z2 do) and refuse a fraction.

COMMON results come back as fields of the result, after the routine's own outputs:
/ZUB/ (DZBPL), /ZPC/ (DGMZPC), /ZVN/ (DGMZVN), /CHRVC/ (DCHRVC).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .errors import RequirementError
from . import _wrap_gears as _w
from .library import ST_REQUIREMENT, Check, describe
from .results import result_type
from .modes import book_pi, get_mode
from .report import fortran_write

__all__ = ["DZBPL", "DKRKT", "DUGINV", "DGMTZK", "DGMZPC", "DGMZVN", "DCHRVC", "dkrkt_splits"]


# ---- reasons and checks ----------------------------------------------------------------

# The Fortran's reasons for ST_REQUIREMENT (10 * ST_REQUIREMENT + k, fortran/gears.f90).
ST_UNDERCUT, ST_POINTED, ST_CORRECTION, ST_INSIDE_BASE, ST_NO_MESH = (
    10 * ST_REQUIREMENT + k for k in range(1, 6))

_POINTED = ("pointed tooth: the flanks meet below the tip circle (tip thickness <= 0, the "
            "limit (6.18), L3985)")
_INSIDE_BASE = "a tip circle lies inside its base circle: the tooth has no involute flank"

# (checks on the inputs: closed forms; the Fortran checks the same again)

def _alpha():
    return book_pi() / 9.0


# The checks get floats (a scalar call) or arrays; math is 20x faster on floats.  (NaN
# never reaches them: the layer screens it first, so "a <= b" can stand for "not a > b".)
def _either(name):
    f_math, f_np = getattr(math, name), getattr(np, name)
    return lambda x: f_math(x) if isinstance(x, (float, int)) else f_np(x)


_sin, _cos, _tan, _atan = (_either(f) for f in ("sin", "cos", "tan", "atan"))


#: Tooth numbers of a gear cut by the standard rack: below 8 teeth every shift of a spur
#: gear either undercuts the tooth (6.15) or makes it pointed (6.18), so no such gear exists.
#: (The upper bound only keeps the layer's sets of allowed values small.)
TEETH = range(8, 10001)


def _helix_ok(name="BETA"):
    return Check(lambda **kw: abs(kw[name]) >= math.pi / 2,
                 ST_REQUIREMENT, f"{name}, the helix angle, must lie in (-pi/2, pi/2)")


def _alpha_t(beta):
    return _atan(math.tan(_alpha()) / _cos(beta))


def _undercut_limit(z, beta):
    """(6.17) x_min = 1 - z sin^2(alpha_t) / (2 cos beta); (6.15) for beta = 0."""
    return 1.0 - 0.5 * z * _sin(_alpha_t(beta)) ** 2 / _cos(beta)


def _undercut(xname, zname, beta=None):
    """x below the undercut limit (6.15)/(6.17): corrected mode only (E-DGMTZK-4)."""
    def bad(**kw):
        b = 0.0 if beta is None else kw[beta]
        return (get_mode() == "corrected") & (
            kw[xname] < _undercut_limit(kw[zname], b))
    return Check(bad, ST_REQUIREMENT,
                 f"undercut: {xname} is below x_min = 1 - {zname} sin^2(alpha_t)/(2 cos "
                 f"beta) of (6.15)/(6.17) (L3967, L3977): the standard rack cuts away the "
                 f"root of the tooth")


def _inv(x):
    return _tan(x) - x


# ---- VI.1 DZBPL ------------------------------------------------------------------------

_DZBPL_FORMAT = ("(1X,'ЧИСЛА ЗУБЬЕВ КОЛЕС ПЛАНЕТАРНОГО РЕДУКТОРА'/1X,'SHEMA=',I1/' Z1=',I3,"
                 "' Z2=',I3,' Z3=',I3,' Z4=',I3/' КОЛИЧЕСТВО БЛОКОВ САТЕЛЛИТОВ KS=',I2)")
DZBPL_NO_SOLUTION = "(1X,'ПРИ ЗАДАННЫХ УСЛОВИЯХ ПОДБОР ЧИСЕЛ ЗУБЬЕВ НЕВОЗМОЖЕН')"


def dzbpl_report(KS, SHEMA, result=None) -> str:
    """DZBPL's printout (FORMAT 11, L3793-3796, or FORMAT 10, L3789, when ``result`` is
    None: no admissible set)."""
    if result is None:
        return fortran_write(DZBPL_NO_SOLUTION)
    z1, z2, z3, z4 = (int(round(v)) for v in result)
    return fortran_write(_DZBPL_FORMAT, [int(SHEMA), z1, z2, z3, z4, int(KS)])


DZBPL = describe(
    _w.DZBPL, listing="VI.1", lines="L3720-3798",
    checks=(
        Check(lambda P, **_: P == 0, ST_REQUIREMENT,
              "P = 0: the ratio i_1h = P/Q of the train must not be 0"),
        Check(lambda Z1MIN, Z1MAX, **_: Z1MAX < Z1MIN,
              ST_REQUIREMENT, "Z1MAX < Z1MIN: the range of z1 is empty"),
        Check(lambda L2, L3, SHEMA, **_: (SHEMA != 1) & (L2 == L3), ST_REQUIREMENT,
              "L2 = L3 in scheme 2 or 3: Table 21 divides by L3 - L2 (equal planet wheels "
              "give these trains the ratio 0 only)"),
    ),
    messages={ST_REQUIREMENT:
              "no admissible tooth numbers: no z1 in [Z1MIN, Z1MAX] meets the ratio, "
              "coaxiality, assembly and neighbourhood conditions within ZKRN, ZKRW, DZ "
              "(the book prints 'ПРИ ЗАДАННЫХ УСЛОВИЯХ ПОДБОР ЧИСЕЛ ЗУБЬЕВ НЕВОЗМОЖЕН')"},
    example=(2, 4, 1, 1, 1, 13, 35, 1, 20, 85, 8),
    doc="""Tooth numbers of a multi-satellite planetary train (listing VI.1, L3720-3798;
    Table 21, L3707-3714; text L3636-3806).

    ``CALL DZBPL(KS, P, Q, L2, L3, Z1MIN, Z1MAX, SHEMA)``: the train of scheme SHEMA
    (Fig. 38) with KS satellite blocks, the ratio i_1h = P/Q from wheel 1 to the carrier
    h (wheel 4 fixed), and planet wheels z2 : z3 = L2 : L3.  The results are the book's
    COMMON /ZUB/ Z1, Z2, Z3, Z4.

    Schemes: 1 = (a), (b): 1-2 external, 3-4 internal mesh, z1 + z2 = z4 - z3;
    2 = (v): both external, z1 + z2 = z4 + z3; 3 = (g): both internal (1 and 4 have
    internal teeth), z1 - z2 = z4 - z3.

    Returns
    -------
    DZBPL(Z1, Z2, Z3, Z4)
        The tooth numbers (COMMON /ZUB/): the first admissible set in increasing z1.
        A scalar call returns Python ints; array inputs give float arrays (NaN where a
        position fails under ``on_error="nan"``), as does a failed scalar call then.

    Raises
    ------
    RequirementError
        No z1 in [Z1MIN, Z1MAX] gives an admissible set (the book prints its message 10,
        «ПРИ ЗАДАННЫХ УСЛОВИЯХ ПОДБОР ЧИСЕЛ ЗУБЬЕВ НЕВОЗМОЖЕН»); P = 0; Z1MAX < Z1MIN;
        L2 = L3 in scheme 2 or 3.
    ValueError
        An input that is not a whole number in its range.

    Notes
    -----
    The COMMON inputs ZKRN = 20 (least external wheel meshing with an internal one),
    ZKRW = 85 (least internal wheel) and DZ = 8 (least tooth difference of an internal
    pair) are program VI.2's values (L3815-3817).

    Corrected mode returns, for the least z1 in range, a set that meets every condition
    of the text exactly: the assembly condition (6.4) (z1 P/(k Q) whole), the ratio
    P/Q and z2 : z3 = L2 : L3 (Table 21 divides without remainder), coaxiality (6.2),
    positive tooth numbers (no IABS), the limits ZKRN, ZKRW, DZ (z2 >= ZKRN also when
    L2 != L3, and z4 - z3 >= DZ in scheme 1), and the neighbourhood condition (6.5)
    ``sin(pi/k) > (max(z2, z3) + 2)/(z1 +- z2)`` that the listing's comment promises but
    never tests (ERRATA E-DZBPL-3, E-DZBPL-4, E-DZBPL-5).  As-printed mode runs the
    listing with its missing ``GO TO 6`` and scheme-3 ``Z4`` restored (E-DZBPL-1,
    E-DZBPL-2): truncating integer division, IABS, no neighbourhood test, so that the
    ratio may be approximate and a result may not be coaxial (Fig. 39's 38/22/25/41).
    The book's trace line ``PRINT 20`` (L3760) is not reproduced.
    """)


# ---- VI.3 DKRKT ------------------------------------------------------------------------

_DKRKT_FORMATS = {
    25: "(' ИСХОДНЫЕ ДАННЫЕ: M = ',F5.2,' Z1 = ',F3.0,' Z2 = ',F3.0,' AW = ',F7.2,"
        "' SDVIG = ',I1/)",
    52: "(1X,'КОЭФФИЦИЕНТ СМЕЩЕНИЯ X1 = ',F6.3,' КОЭФФИЦИЕНТ СМЕЩЕНИЯ X2 = ',F6.3,"
        "' УГОЛ ЗАЦЕПЛЕНИЯ ','ALFAW = ',F6.4//)",
    50: "(1X,'ПРИ ЗАДАННЫХ ПАРАМЕТРАХ КОЛЕСА БУДУТ ','ИЗГОТОВЛЕННЫ С ПОДРЕЗАННЫМИ ЗУБЬЯМИ'//)",
    51: "(1X,'ПРИ ЗАДАННЫХ ПАРАМЕТРАХ КОЛЕСА БУДУТ ','ИЗГОТОВЛЕННЫ С ЗАОСТРЕННЫМИ ЗУБЬЯМИ')",
    54: "(1X,'ЗАДАВАЕМЫЕ ПАРАМЕТРЫ ТРЕБУЮТ ','КОРРЕКТИРОВКИ')",
    55: "(1X,'AO = ',F6.2,' X1Z = ',F6.3,' X2Z = ',F6.3,' X1P = ',F6.3,' X2P = ',F6.3,"
        "' Y = ',F6.3,' ALFAW = ',F6.2,' XS = ',F6.3/' X1 = ',F6.3,' X2 = ',F6.3,"
        "' SDVIG = ',I2,' AW = ',F6.2/)",
}


def dkrkt_limits(M, Z1, Z2, AW):
    """The quantities DKRKT prints in its FORMAT 55 dump that depend on the inputs only:
    AO = m (z1 + z2)/2, X1Z, X2Z = 0.15 z^0.7 (6.19), X1P, X2P = 1 - 0.5 z sin^2(alpha)
    (6.15), and Y = (AW - AO)/M (0 when AW = 0, as the listing sets it, L4103)."""
    alfa = _alpha()
    ao = M * (Z1 + Z2) / 2.0
    return {"AO": ao, "X1Z": 0.15 * Z1 ** 0.7, "X2Z": 0.15 * Z2 ** 0.7,
            "X1P": 1.0 - 0.5 * Z1 * math.sin(alfa) ** 2,
            "X2P": 1.0 - 0.5 * Z2 * math.sin(alfa) ** 2,
            "Y": (AW - ao) / M if AW != 0.0 else 0.0}


def dkrkt_report(inputs, outputs=None, message=None) -> str:
    """DKRKT's printout: the header (FORMAT 25), the result line (FORMAT 52) or the
    message ``message`` (50 undercut, 51 pointed, 54 correction), and the FORMAT 55 dump.
    Without ``outputs`` (a refused call) the dump shows only what the inputs decide."""
    M, Z1, Z2, AW, SDVIG = (inputs[k] for k in ("M", "Z1", "Z2", "AW", "SDVIG"))
    out = [fortran_write(_DKRKT_FORMATS[25], [M, Z1, Z2, AW, int(SDVIG)])]
    lim = dkrkt_limits(M, Z1, Z2, AW)
    if outputs is not None:
        x1, x2, alfaw = (float(v) for v in outputs[:3])
        if message is None:
            out.append(fortran_write(_DKRKT_FORMATS[52], [x1, x2, alfaw]))
    else:
        x1 = x2 = alfaw = float("nan")
    if message is not None:
        out.append(fortran_write(_DKRKT_FORMATS[message]))
    dump = fortran_write(_DKRKT_FORMATS[55], [lim["AO"], lim["X1Z"], lim["X2Z"], lim["X1P"],
                                              lim["X2P"], lim["Y"], alfaw, x1 + x2, x1, x2,
                                              int(SDVIG), AW])
    out.append(dump)
    return "\n".join(out)


DKRKT = describe(
    _w.DKRKT, listing="VI.3", lines="L4019-4137",
    checks=(
        Check(lambda AW, SDVIG, **_: (AW == 0.0) & (SDVIG == 0),
              ST_REQUIREMENT, "AW = 0 asks for a system of shifts: SDVIG must be 1, 2 or 3 "
              "(E-DKRKT-4)"),
        Check(lambda M, Z1, Z2, AW, **_: (AW > 0.0)
              & (AW <= 0.5 * M * (Z1 + Z2) * math.cos(_alpha())),
              ST_REQUIREMENT, "AW is not above r_b1 + r_b2 = m (z1 + z2) cos(alpha)/2: no "
              "involute mesh has this centre distance ((6.12) has no angle)"),
        Check(lambda Z2, AW, SDVIG, **_: (AW == 0.0) & (SDVIG == 3) & (Z2 < 17.0),
              ST_REQUIREMENT,
              "SDVIG = 3 needs z2 >= 17 ((6.22); the book prints 'ЗАДАВАЕМЫЕ ПАРАМЕТРЫ "
              "ТРЕБУЮТ КОРРЕКТИРОВКИ', L4096)"),
    ),
    messages={
        ST_UNDERCUT: "undercut: x1 < X1P or x2 < X2P = 1 - 0.5 z sin^2(alpha) (6.15) (the "
                     "book's message 20, '... С ПОДРЕЗАННЫМИ ЗУБЬЯМИ')",
        ST_POINTED: "pointed teeth: x1 > X1Z or x2 > X2Z = 0.15 z^0.7 (6.19) (the book's "
                    "message 21, '... С ЗАОСТРЕННЫМИ ЗУБЬЯМИ')",
        ST_CORRECTION: "no system of shifts serves these tooth numbers (the book's message "
                       "22, 'ЗАДАВАЕМЫЕ ПАРАМЕТРЫ ТРЕБУЮТ КОРРЕКТИРОВКИ')",
        ST_NO_MESH: "AW is not above r_b1 + r_b2 = m (z1 + z2) cos(alpha)/2: no involute "
                    "mesh has this centre distance"},
    report=lambda i, o: dkrkt_report(i, o),
    example=(4.0, 13.0, 34.0, 100.0, 0, 1.0),
    doc="""Profile-shift coefficients of a pair of spur gears and their operating pressure
    angle (listing VI.3, L4019-4137; (6.12)-(6.23), L3946-4009).

    ``CALL DKRKT(M, Z1, Z2, AW, SDVIG, AAA, X1, X2, ALFAW)``.  With ``AW != 0`` the
    shifts fit the pair into the centre distance AW ((6.12)-(6.14): alpha_w =
    arccos(a cos(alpha)/AW), x1 + x2 = (z1 + z2)(inv alpha_w - inv alpha)/(2 tan alpha),
    x1 = (x1 + x2 - y (z2 - z1)/(z1 + z2))/2).  With ``AW = 0`` SDVIG chooses a system:
    1 avoids undercut (x = 1 - 0.5 z sin^2(alpha) below 17 teeth, else 0); 2 raises the
    contact strength (6.21); 3 equalizes the specific sliding (6.22)-(6.23); alpha_w then
    follows from inv alpha_w = inv alpha + 2 (x1 + x2) tan(alpha)/(z1 + z2) by DUGINV.

    Returns
    -------
    DKRKT(X1, X2, ALFAW)
        The shift coefficients and the operating pressure angle (rad).

    Raises
    ------
    RequirementError
        The teeth would be undercut (x < X1P, the book's message 20) or pointed (x > X1Z
        = 0.15 z^0.7, message 21; with AW > 0 the message says which of x1, x2 and
        which split of the same x1 + x2 would do, or that none would:
        :func:`dkrkt_splits`); SDVIG = 1 with both x above X1Z or SDVIG = 3 with
        z2 < 17 (message 22); AW at or below the sum of the base radii; AW = 0 with
        SDVIG = 0.
    ValueError
        M <= 0, AW < 0, a tooth number that is not a whole number from 8 to 10000.

    Notes
    -----
    The listing's ``ARCOS(0.5*ZS*(COS(ALFAO)))/(Y + 0.5*ZS)`` and ``1.0/(1.0 + 0.086*
    (Z1 - 19.0))**2`` are misplaced parentheses (E-DKRKT-1, E-DKRKT-2; Fig. 44's 0.4879 and
    0.244 prove the fix).  Corrected mode finds alpha_w to full precision; as-printed
    mode runs DUGINV's iteration with TCHNST = 0.00001, the tolerance Fig. 44 was computed
    with, where the listing prints 0.000001 (E-DKRKT-3).  The book prints the header and
    the diagnostics whatever AAA; sarkp prints only for AAA = 0.
    """)


Splits = result_type("Splits", ("XS", "X1_BOOK", "X2_BOOK", "X1_LOW", "X1_HIGH", "X1", "X2",
                               "REASON"))


def dkrkt_splits(M, Z1, Z2, AW):
    """Every split of the shift sum that DKRKT's centre distance AW needs -- a sarkp
    extension, what DKRKT says when its own split is refused.

    DKRKT fits the pair into AW with x1 + x2 = XS ((6.12)-(6.13)) and splits XS by
    (6.14).  That split can fall below the undercut limit X1P (6.15) or above the pointed
    limit X1Z (6.19) of one gear while another split of the same XS keeps both gears
    within ``X1P <= x1 <= X1Z``, ``X2P <= XS - x1 <= X2Z``: ``x1`` in ``[X1_LOW, X1_HIGH]``.

    Returns
    -------
    Splits(XS, X1_BOOK, X2_BOOK, X1_LOW, X1_HIGH, X1, X2, REASON)
        ``XS`` the shift sum AW needs; DKRKT's split ``X1_BOOK, X2_BOOK``; the range of x1
        that avoids undercut and pointed teeth (``X1_LOW > X1_HIGH``: no split does);
        ``X1, X2`` the admissible split nearest to the book's (NaN if none) and
        ``REASON``, one sentence: why the book's split is refused (or "") and which split
        would do, or why none would.
    """
    for arg, value in (("M", M), ("Z1", Z1), ("Z2", Z2), ("AW", AW)):
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer,
                                                             np.floating)):
            raise TypeError(f"dkrkt_splits: {arg} must be a real number, not "
                            f"{type(value).__name__}")
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"dkrkt_splits: {arg} = {value!r} must be a finite number > 0")
    if not (AW > 0.5 * M * (Z1 + Z2) * math.cos(_alpha())):
        raise ValueError(f"dkrkt_splits: AW = {AW!r} must be above r_b1 + r_b2 = "
                         f"{0.5 * M * (Z1 + Z2) * math.cos(_alpha())!r}")
    lim = dkrkt_limits(M, Z1, Z2, AW)
    alfa, zs, y = _alpha(), Z1 + Z2, lim["Y"]
    alfaw = math.acos(0.5 * zs * math.cos(alfa) / (y + 0.5 * zs))
    xs = zs * (_inv(alfaw) - _inv(alfa)) / (2.0 * math.tan(alfa))
    x1b = 0.5 * (xs - (Z2 - Z1) / zs * y)
    x2b = xs - x1b
    low = max(lim["X1P"], xs - lim["X2Z"])
    high = min(lim["X1Z"], xs - lim["X2P"])
    why = []
    if x1b < lim["X1P"]:
        why.append(f"x1 = {x1b:.4f} is below X1P = {lim['X1P']:.4f} (undercut)")
    if x2b < lim["X2P"]:
        why.append(f"x2 = {x2b:.4f} is below X2P = {lim['X2P']:.4f} (undercut)")
    if x1b > lim["X1Z"]:
        why.append(f"x1 = {x1b:.4f} is above X1Z = {lim['X1Z']:.4f} (pointed)")
    if x2b > lim["X2Z"]:
        why.append(f"x2 = {x2b:.4f} is above X2Z = {lim['X2Z']:.4f} (pointed)")
    head = ("The book's split (6.14): " + "; ".join(why) + ". ") if why else ""
    if low <= high:
        x1 = min(max(x1b, low), high)
        # xs - x1 at a bound of x1 can round past the x2 limit that set it: clamp
        x2 = min(max(xs - x1, lim["X2P"]), lim["X2Z"])
        reason = (f"{head}The split x1 = {x1:.4f}, x2 = {x2:.4f} (any x1 from "
                  f"{low:.4f} to {high:.4f} with x2 = {xs:.4f} - x1) fits AW without "
                  f"undercut or pointed teeth")
        return Splits(xs, x1b, x2b, low, high, x1, x2, reason)
    reason = (f"{head}No split of x1 + x2 = {xs:.4f} keeps both gears between undercut and "
              f"pointed teeth (x1 would need {lim['X1P']:.4f}..{lim['X1Z']:.4f} and x2 "
              f"{lim['X2P']:.4f}..{lim['X2Z']:.4f}): change AW or the tooth numbers")
    return Splits(xs, x1b, x2b, low, high, math.nan, math.nan, reason)


def _explained(routine):
    """DKRKT with the reason and the split that would do in its error (scalar AW > 0)."""
    @functools.wraps(routine)
    def DKRKT(M, Z1, Z2, AW, SDVIG, AAA=1.0, *, on_error="raise", out=None):
        try:
            return routine(M, Z1, Z2, AW, SDVIG, AAA, on_error=on_error, out=out)
        except RequirementError as exc:
            if not all(isinstance(v, (int, float)) for v in (M, Z1, Z2, AW)) or not AW > 0 \
                    or "undercut" not in str(exc) and "pointed" not in str(exc):
                raise
            raise type(exc)(f"{exc}. {dkrkt_splits(M, Z1, Z2, AW).REASON}") from None
    return DKRKT


DKRKT = _explained(DKRKT)


# ---- VI.4 DUGINV -----------------------------------------------------------------------

DUGINV = describe(
    _w.DUGINV, listing="VI.4", lines="L4153-4164, L4201-4217",
    checks=(Check(lambda INVX, **_: INVX < 0.0, ST_REQUIREMENT,
                  "INVX < 0: the involute tan x - x is never negative for 0 <= x < pi/2, "
                  "no angle has this involute"),),
    doc="""The angle x (rad) whose involute ``inv x = tan x - x`` is INVX (listing VI.4,
    L4153-4164, L4201-4217; (6.24)-(6.25)).

    ``X = DUGINV(INVX, XNACH, TCHNST)``, a FUNCTION as in the book.

    Returns
    -------
    float or ndarray
        The angle in [0, pi/2).

    Raises
    ------
    RequirementError
        INVX < 0.

    Notes
    -----
    As printed the book iterates x = atan(x + INVX) from XNACH until a step is below
    TCHNST.  The iteration contracts by cos^2(x) per step, so it stops short of the root
    by about 6 TCHNST at 20 deg (E-DUGINV-1: this is why the book prints ALFAW = 0.3490,
    not 0.3491, for zero shifts) and crawls for small angles; it is bounded here at 10**6
    steps (E-DUGINV-2).  Corrected mode ignores XNACH and TCHNST and returns the root to
    full double precision: relative error below 1e-15 for every normal INVX (from
    2.2e-308 up; the series of tan x - x below 0.4 rad where tan x - x cancels, then
    Newton steps).  A subnormal INVX (below 2.2e-308) holds fewer than 53 significant
    bits and so does the cube x**3/3 the step compares it with: there the error grows to
    2.8e-14 (at INVX = 1.05e-312; measured against the exact (3 INVX)**(1/3) in
    tests/test_gears.py).
    """)


# ---- VI.5 DGMTZK -----------------------------------------------------------------------

_DGMTZK_FORMATS = (
    "(20X,'ГЕОМЕТРИЧЕСКИЕ РАЗМЕРЫ ЗУБЧАТОГО КОЛЕСА')",
    "(20X,'ИСХОДНЫЕ ПАРАМЕТРЫ:')",
    "(1X,'МОДУЛЬ ЗАЦЕПЛЕНИЯ M = ',F5.2,' ЧИСЛО ЗУБЬЕВ Z = ',F3.0/' УГОЛ НАКЛОНА ЗУБЬЕВ "
    "BETA = ',F6.4,' КОЭФФИЦИЕНТ СМЕЩЕНИЯ X = ',F6.3//)",
    "(1X,'ДИАМЕТР ДЕЛИТЕЛЬНОЙ ОКРУЖНОСТИ D = ',F7.2,' ТОЛЩИНА ЗУБА ПО ДЕЛИТЕЛЬНОЙ "
    "ОКРУЖНОСТИ S = ',F7.4)",
    "(1X,'ДИАМЕТР ОСНОВНОЙ ОКРУЖНОСТИ DB = ',F7.2,' ТОЛЩИНА ЗУБА ПО ОСНОВНОЙ ОКРУЖНОСТИ "
    "SB = ',F7.4/)",
    "(1X,'ДИАМЕТР ОКРУЖНОСТИ ВЕРШИН DA = ',F7.2,' ТОЛЩИНА ЗУБА ПО ОКРУЖНОСТИ ВЕРШИНЫ "
    "SA = ',F7.4/)",
    "(1X,'ДИАМЕТР ОКРУЖНОСТИ ВПАДИН DF = ',F7.2/)",
)


def _dgmtzk_report(i, o):
    f1, f2, f3, f4, f5, f6, f7 = _DGMTZK_FORMATS
    d, s, db, sb, da, sa, df = (float(v) for v in o[:7])
    return "\n".join([fortran_write(f1), fortran_write(f2),
                      fortran_write(f3, [i["M"], i["Z"], i["BETA"], i["X"]]),
                      fortran_write(f4, [d, s]), fortran_write(f5, [db, sb]),
                      fortran_write(f6, [da, sa]), fortran_write(f7, [df])])


DGMTZK = describe(
    _w.DGMTZK, listing="VI.5", lines="L4245-4308",
    checks=(_helix_ok(), _undercut("X", "Z", "BETA")),
    messages={ST_UNDERCUT: "undercut: X is below x_min of (6.15)/(6.17)",
              ST_POINTED: _POINTED, ST_INSIDE_BASE: _INSIDE_BASE},
    report=_dgmtzk_report,
    example=(4.0, 20.0, 0.1745, 0.0, 1.0),
    doc="""Dimensions of one external involute gear (listing VI.5, L4245-4308; Table 22,
    L4230-4241).

    ``CALL DGMTZK(M, Z, BETA, X, AAA, D, S, DB, SB, DA, SA, DF)``.

    Returns
    -------
    DGMTZK(D, S, DB, SB, DA, SA, DF, XUR)
        Diameters of the reference (D = m z/cos beta), base (DB = D cos alpha_t), tip
        (DA) and root (DF = D - 2 (1.25 - x) m) circles, and the tooth thickness (arc, in
        the transverse plane) on the reference (S), base (SB) and tip (SA) circles.
        Then a sarkp extension, ``XUR``: the tip shortening coefficient that DA and SA
        include, always 0.  DA is the gear's own tip circle, with no shortening:
        DGMTZK does not know its mate.  In a mesh whose shifts are not zero the tips are
        shortened by ``dy m`` each (DGMZPC's XUR), and the mesh's tip diameters are
        DGMZPC's ``DA1, DA2`` (e.g. 65.409 against this DA of 65.449 for program X's
        20-tooth gear).

    Raises
    ------
    RequirementError
        Undercut: X below x_min = 1 - z sin^2(alpha_t)/(2 cos beta) of (6.17) (corrected
        mode; the book does not check it, and Fig. 46's x = -1 gear is undercut); a
        pointed tooth (SA <= 0); a tip circle inside the base circle.
    RangeError
        A diameter beyond double precision (M Z near 1e308).
    ValueError
        M <= 0; Z not a whole number from 8 to 10000 (below 8 teeth every shift of a
        standard spur gear undercuts or points the tooth).

    Notes
    -----
    alpha_t = atan(tan(alpha)/cos(beta)).  Corrected mode uses the transverse section
    throughout: S = m (pi/(2 cos beta) + 2 x tan alpha_t), SB = DB (S/D + inv alpha_t),
    SA = DA (S/D + inv alpha_t - inv alpha_at) with cos alpha_at = DB/DA, and DA = D +
    2 (1 + x) m as Table 22 has it.  The listing mixes the sections for helical gears
    (S = pi m/2 + 2 x m tan alpha_t, thicknesses with 2 x tan(alpha_t)/z, DA = m (z + 2 +
    2x)); as-printed mode keeps it, Fig. 46 depends on it (E-DGMTZK-2).  Both agree for
    spur gears.  The listing's SA statement has a misplaced parenthesis (E-DGMTZK-1).
    """)


# ---- VI.6 DGMZPC -----------------------------------------------------------------------

_DGMZPC_FORMAT = (
    "(10X,'ОСНОВНЫЕ ПАРАМЕТРЫ ЗАЦЕПЛЕНИЯ'//' ДЕЛИТЕЛЬНОЕ МЕЖОСЕВОЕ РАССТОЯНИЕ - A = ',F10.4/"
    "' КОЭФФИЦИЕНТ СУММАРНОГО СМЕЩЕНИЯ - XS = ',F7.4/' УГОЛ ЗАЦЕПЛЕНИЯ',18X,' - ALFAW = ',"
    "F7.4/' МЕЖОСЕВОЕ РАССТОЯНИЕ',15X,' - AW = ',F10.4/' КОЭФФИЦИЕНТ ВОСПРИНИМАЕМОГО "
    "СМЕЩЕНИЯ - XY = ',F7.4/' КОЭФФИЦИЕНТ УРАВНИТЕЛЬНОГО СМЕЩЕНИЯ - XUR = ',F7.4/"
    "' КОЭФФИЦИЕНТ ПЕРЕКРЫТИЯ',15X,'E = ',F7.4//)")


def _involute_negative(xs_of, z_sum_of, beta=None):
    def bad(**kw):
        b = 0.0 if beta is None else kw[beta]
        return (2.0 * xs_of(kw) * math.tan(_alpha()) / z_sum_of(kw)
                + _inv(_alpha_t(b))) < 0.0
    return bad


DGMZPC = describe(
    _w.DGMZPC, listing="VI.6", lines="L4410-4454",
    checks=(
        _helix_ok(), _undercut("X1", "Z1", "BETA"), _undercut("X2", "Z2", "BETA"),
        Check(_involute_negative(lambda k: k["X1"] + k["X2"], lambda k: k["Z1"] + k["Z2"],
                                 "BETA"),
              ST_REQUIREMENT, "no mesh: X1 + X2 is so negative that inv alpha_w = inv "
              "alpha_t + 2 (X1 + X2) tan(alpha)/(Z1 + Z2) < 0"),
    ),
    messages={ST_UNDERCUT: "undercut: X1 or X2 is below x_min of (6.15)/(6.17)",
              ST_POINTED: _POINTED + " (on the tip circle shortened by XUR)",
              ST_INSIDE_BASE: _INSIDE_BASE,
              ST_NO_MESH: "no mesh: inv alpha_w < 0 (X1 + X2 too negative)"},
    report=lambda i, o: fortran_write(_DGMZPC_FORMAT, [float(v) for v in o[:7]]),
    example=(5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0, 1.0),
    doc="""Geometry of an external involute mesh (listing VI.6, L4410-4454; Table 23,
    L4398-4408).

    ``CALL DGMZPC(M, Z1, Z2, BETA, X1, X2, BW, AAA)``; the results are the book's
    COMMON /ZPC/ A, XS, ALFAW, AW, XY, XUR, E.

    Returns
    -------
    DGMZPC(A, XS, ALFAW, AW, XY, XUR, E, DA1, DA2, ALFAA1, ALFAA2, SA1, SA2)
        A = m (z1 + z2)/(2 cos beta) reference centre distance; XS = x1 + x2; ALFAW the
        operating transverse pressure angle, inv alpha_w = inv alpha_t + 2 XS tan(alpha)/
        (z1 + z2); AW = A cos(alpha_t)/cos(alpha_w); XY = y = (AW - A)/m; XUR = dy = XS
        - y, the tip shortening; E = eps_alpha + eps_beta, the contact ratio with
        eps_alpha = (z1 tan alpha_a1 + z2 tan alpha_a2 - (z1 + z2) tan alpha_w)/(2 pi) on
        the operating centre distance and eps_beta = BW |sin beta|/(pi m).
        Then what the routine computes and the book does not return (a sarkp extension):
        ``DA1, DA2`` the tip diameters with the tip shortening, d + 2 (1 + x - dy) m;
        ``ALFAA1, ALFAA2`` the (transverse) pressure angles on them, cos alpha_a = d_b/d_a;
        ``SA1, SA2`` the (transverse, arc) tooth thicknesses there, d_a ((pi/2 + 2 x
        tan alpha)/z + inv alpha_t - inv alpha_a).  In as-printed mode these follow the
        listing's spur formulas, as E does.

    Raises
    ------
    RequirementError
        Undercut (corrected mode), X1 + X2 so negative that inv alpha_w < 0, a pointed
        tooth or a tip circle inside its base circle.
    ValueError
        M <= 0, BW < 0, a tooth number that is not a whole number from 8 to 10000.

    Notes
    -----
    The tip diameters are d + 2 (1 + x - dy) m.  Corrected mode uses the helical gear's
    d = m z/cos beta and base diameter d cos(alpha_t); the listing uses the spur m z and
    m z cos(alpha) for every beta, and as-printed mode keeps that, Fig. 47b (beta = 16
    deg) depends on it (E-DGMZPC-3).  The listing's DUGINV call and AW statement are
    garbled (E-DGMZPC-1, E-DGMZPC-2); as printed DUGINV stops at TCHNST = 0.00001, which
    makes Fig. 47b's AW = 283.9946 fall below A = 284.0017 with XS = 0 (E-DUGINV-1).
    """)


# ---- VI.7 DGMZVN -----------------------------------------------------------------------

_DGMZVN_FORMATS = (
    "(5X,'ОСНОВНЫЕ ПАРАМЕТРЫ ЗУБЧАТЫХ КОЛЕС С'/5X,'ВНУТРЕННИМ ЗАЦЕПЛЕНИЕМ.'/5X,"
    "'КОЛЕСА НАРЕЗАЮТСЯ ','ДОЛБЯКОМ'//' ДЕЛИТЕЛЬНОЕ МЕЖОСЕВОЕ РАССТОЯНИЕ - A = ',F10.4/"
    "' КОЭФФИЦИЕНТ РАЗНОСТИ СМЕЩЕНИЙ - XD = ',F7.4/' УГОЛ ЗАЦЕПЛЕНИЯ - ALFAW = ',F7.4/"
    "' МЕЖОСЕВОЕ РАССТОЯНИЕ - AW = ',F10.4/' ДЕЛИТЕЛЬНЫЕ ДИАМЕТРЫ: '/' ШЕСТЕРНИ - D1 = ',"
    "F10.4/' КОЛЕСА - D2 = ',F10.4/' КОЭФФИЦИЕНТ ВОСПРИНИМАЕМОГО СМЕЩЕНИЯ - XY = ',F7.4/"
    "' КОЭФФИЦИЕНТ УРАВНИТЕЛЬНОГО СМЕЩЕНИЯ - XUR = ',F7.4/' ДИАМЕТРЫ ВЕРШИН ЗУБЬЕВ: '/"
    "' ШЕСТЕРНИ - DA1 = ',F10.4/' КОЛЕСА - DA2 = ',F10.4/' ДИАМЕТРЫ ВПАДИН ЗУБЬЕВ: '/"
    "' ШЕСТЕРНИ - DF1 = ',F10.4/' КОЛЕСА - DF2 = ',F10.4)",
    "(' ВЫСОТА ЗУБА: '/' ШЕСТЕРНИ - H1 = ',F7.4/' КОЛЕСА - H2 = ',F7.4/' ТОЛЩИНА ЗУБА НА "
    "ОКРУЖНОСТИ ВЕРШИН: '/' ШЕСТЕРНИ - SA1 = ',F10.4/' КОЛЕСА - SA2 = ',F10.4/"
    "' КОЭФФИЦИЕНТ ПЕРЕКРЫТИЯ - EALFA = ',F7.4//)",
)

_ZVN = ("A", "XD", "ALFAW", "AW", "D1", "D2", "DW1", "DW2", "XY", "XUR", "DA1", "DA2",
        "DF1", "DF2", "H1", "H2", "SA1", "SA2", "EALFA")


def _dgmzvn_report(i, o):
    v = dict(zip(_ZVN, (float(x) for x in o)))
    first = [v[k] for k in ("A", "XD", "ALFAW", "AW", "D1", "D2", "XY", "XUR", "DA1", "DA2",
                            "DF1", "DF2")]
    second = [v[k] for k in ("H1", "H2", "SA1", "SA2", "EALFA")]
    return "\n".join([fortran_write(_DGMZVN_FORMATS[0], first),
                      fortran_write(_DGMZVN_FORMATS[1], second)])


def _internal_involute_negative(shift_of, z_diff_of):
    def bad(**kw):
        return _inv(_alpha()) + 2.0 * shift_of(kw) * math.tan(_alpha()) / z_diff_of(kw) < 0.0
    return bad


DGMZVN = describe(
    _w.DGMZVN, listing="VI.7", lines="L4512-4631",
    checks=(
        Check(lambda Z1, Z2, **_: Z2 <= Z1, ST_REQUIREMENT,
              "Z2, the wheel with internal teeth, must have more teeth than the pinion Z1"),
        Check(lambda Z2, ZO2, **_: Z2 <= ZO2, ST_REQUIREMENT,
              "the shaper ZO2 must have fewer teeth than the internal wheel Z2 it cuts"),
        _undercut("X1", "Z1"),
        Check(_internal_involute_negative(lambda k: k["X2"] - k["X1"],
                                          lambda k: k["Z2"] - k["Z1"]),
              ST_REQUIREMENT, "no mesh: X2 - X1 is so negative that inv alpha_w = inv "
              "alpha + 2 (X2 - X1) tan(alpha)/(Z2 - Z1) < 0"),
        Check(_internal_involute_negative(lambda k: k["X2"] - k["XO"],
                                          lambda k: k["Z2"] - k["ZO2"]),
              ST_REQUIREMENT, "the shaper cannot cut the wheel: inv alpha_w02 = inv alpha + "
              "2 (X2 - XO) tan(alpha)/(Z2 - ZO2) < 0"),
    ),
    messages={ST_UNDERCUT: "undercut: X1 is below x_min of (6.15)",
              ST_POINTED: _POINTED + " (SA1 or SA2 <= 0)", ST_INSIDE_BASE: _INSIDE_BASE,
              ST_NO_MESH: "no mesh: inv alpha_w < 0 or inv alpha_w02 < 0"},
    report=_dgmzvn_report,
    example=(3.0, 16.0, 51.0, 0.25, 0.25, 25.0, 75.0, 0.17, 83.8, 1.0),
    doc="""Geometry of an internal involute mesh whose wheel is cut by a shaper (listing
    VI.7, L4512-4631; Tables 24-25, L4489-4510, L4637-4646).  Spur gears.

    ``CALL DGMZVN(M, Z1, Z2, X1, X2, ZO2, DO, XO, DAO, AAA)``; the results are the
    book's COMMON /ZVN/.

    Returns
    -------
    DGMZVN(A, XD, ALFAW, AW, D1, D2, DW1, DW2, XY, XUR, DA1, DA2, DF1, DF2, H1, H2, SA1, SA2, EALFA)
        A = m (z2 - z1)/2; XD = x2 - x1; ALFAW from inv alpha_w = inv alpha + 2 XD
        tan(alpha)/(z2 - z1); AW = A cos(alpha)/cos(alpha_w); D1, D2 reference and DW1,
        DW2 operating pitch diameters; XY = (AW - A)/m; XUR = XD - XY; tip (DA1, DA2) and
        root (DF1, DF2) diameters (DF2 = 2 a_w02 + DAO from the machine mesh with the
        shaper, Table 25), tooth depths H1, H2, tip thicknesses SA1, SA2 and the contact
        ratio EALFA = (z1 tan alpha_a1 - z2 tan alpha_a2 + (z2 - z1) tan alpha_w)/(2 pi).

    Raises
    ------
    RequirementError
        Z2 <= Z1 or Z2 <= ZO2, a negative involute (X2 - X1 or X2 - XO too negative), an
        undercut pinion (corrected mode), a pointed tooth, a tip circle inside its base
        circle.
    ValueError
        M, DO or DAO <= 0; a tooth number that is not a whole number (Z1, ZO2 from 8,
        Z2 from 9, up to 10000).

    Notes
    -----
    The book's COMMON /ZVN/ names its 3rd and 14th words ALFA (the constant tool angle)
    and DF (never set); they hold ALFAW and DF2 here, the quantities the report prints
    (E-DGMZVN-4).  Three garbled statements are rebuilt as Fig. 48 proves (E-DGMZVN-1:
    the DUGINV calls, E-DGMZVN-2: EALFA and SA1 merged, E-DGMZVN-3: SA2).  As printed,
    DUGINV stops at TCHNST = 0.00001 (Fig. 48a's AW = 52.4986 < A = 52.5 with XD = 0).
    """)


# ---- VI.8 DCHRVC -----------------------------------------------------------------------

_CHRVC = ("X", "D1", "D2", "DW1", "G", "GW", "H1", "HA1", "DA1", "DA2", "DAM2", "B1", "B2",
          "R")
_DCHRVC_FORMAT = (
    "(10X,'ГЕОМЕТРИЧЕСКИЕ ПАРАМЕТРЫ ЧЕРВЯЧНОГО ','ЗАЦЕПЛЕНИЯ'//' КОЭФФИЦИЕНТ СМЕЩЕНИЯ "
    "ЧЕРВЯКА - X = ',F7.4/' ДЕЛИТЕЛЬНЫЙ ДИАМЕТР:'/' ЧЕРВЯКА - D1 = ',F7.3/' ЧЕРВЯЧНОГО "
    "КОЛЕСА - D2 = ',F8.3/' НАЧАЛЬНЫЙ ДИАМЕТР ЧЕРВЯКА - DW1 = ',F8.3/' ДЕЛИТЕЛЬНЫЙ УГОЛ "
    "ПОДЪЕМА - G = ',F7.4/' НАЧАЛЬНЫЙ УГОЛ ПОДЪЕМА - GW = ',F7.4/' ВЫСОТА ВИТКА ЧЕРВЯКА - "
    "H1 = ',F7.3/' ВЫСОТА ГОЛОВКИ ЧЕРВЯКА - HA1 = ',F7.3/' ДИАМЕТР ВЕРШИН:'/' ЧЕРВЯКА - "
    "DA1 = ',F7.3/' ЧЕРВЯЧНОГО КОЛЕСА - DA2 = ',F8.3/' НАИБОЛЬШИЙ ДИАМЕТР ЧЕРВЯЧНОГО "
    "КОЛЕСА - DAM2 = ',F8.3/' ДЛИНА НАРЕЗАННОЙ ЧАСТИ ЧЕРВЯКА - B1 = ',F7.3/' ШИРИНА ВЕНЦА "
    "ЧЕРВЯЧНОГО КОЛЕСА - B2 = ',F7.3/' РАДИУС ВЫЕМКИ ПОВЕРХНОСТИ ВЕРШИН'/' ЗУБЬЕВ "
    "ЧЕРВЯЧНОГО КОЛЕСА - R = ',F7.3//)")

DCHRVC = describe(
    _w.DCHRVC, listing="VI.8", lines="L4737-4824",
    checks=(
        Check(lambda M, Z2, AW, **_: 2.0 * AW <= M * Z2,
              ST_REQUIREMENT, "AW <= M Z2/2: the worm's operating diameter DW1 = 2 AW - "
              "M Z2 would not be positive"),
    ),
    messages={ST_NO_MESH: "the worm's operating diameter DW1 = (q + 2x) m or the wheel's "
                          "tip diameter DA2 = m (z2 + 2 + 2x) would not be positive"},
    report=lambda i, o: fortran_write(_DCHRVC_FORMAT, [float(v) for v in o[:14]]),
    example=(8.0, 10.0, 2.0, 39.0, 200.0, 1.0),
    doc="""Geometry of a cylindrical worm gear pair (listing VI.8, L4737-4824; Table 26,
    L4687-4703).

    ``CALL DCHRVC(M, Q, Z1, Z2, AW, AAA)``; the results are the book's COMMON /CHRVC/.

    Returns
    -------
    DCHRVC(X, D1, D2, DW1, G, GW, H1, HA1, DA1, DA2, DAM2, B1, B2, R)
        X = AW/m - (z2 + q)/2 the wheel's shift coefficient; D1 = q m, D2 = z2 m
        reference diameters; DW1 = (q + 2x) m the worm's operating diameter; G =
        atan(z1/q), GW = atan(z1 m/DW1) the lead angles; H1 = 2.2 m thread depth, HA1 = m
        addendum; DA1 = D1 + 2m, DA2 = D2 + 2 (1 + x) m tip diameters; DAM2 = DA2 +
        6m/(z1 + 2) the wheel's largest diameter; B1 = (11 + 0.1 z2) m threaded length;
        B2 = 0.75 DA1 face width; R = D1/2 - m throat radius.

    Raises
    ------
    RequirementError
        AW <= M Z2/2 (DW1 <= 0), DA2 <= 0.
    ValueError
        M, Q or AW <= 0; Z1 not a whole number from 1 to 100, Z2 not one from 1 to
        10000.

    Notes
    -----
    The same formulas in both modes (no PI is involved).  Table 33 (L6317) spells the
    name DCHRCV.
    """)
