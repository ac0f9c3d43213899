"""Program II.13 (L831-884): positions and velocities of the four-bar of Fig. 3.

The book's main program reads a card ``L1, L2, L3, LO, NU, LBD`` (FORMAT 6F8.4), sets
W1 = 2 rad/s and prints, for 18 crank angles 0, 10, ..., 170 degrees, one line
``FI, FI2, FI3, XB, YB, XD, YD, VD, ALD, W2, W3`` (FORMAT 1X,11F10.4): Fig. 4.

Geometry (Fig. 3): crank OA about the origin, coupler AB, rocker CB about C = (LO, 0),
coupler point D at distance LBD from B, at the angle PI - NU to BA.

The card is not printed; the values below were found by fitting all 126 printed
positions and come out as round numbers (L1 = 0.25, L2 = 0.65, L3 = 0.40, LO = 0.60,
LBD = 0, so D coincides with B and NU does not matter).

The printed program has three wrong calls (ERRATA E-II13-1..3): DUGL1 for DUGL3 at L859
(ALA reads a missing argument), DOMEGA with four arguments at L875-876 (W2, W3 wrong),
and the velocity of B passed to DSMVKT with its sign and its flipped direction both
applied (E-II13-4).  Corrected mode fixes all of them.  As-printed mode keeps E-II13-4,
on which the printed ALD column depends, keeps E-II13-3 (W2 = SIGN(FI2/L2, VBA),
W3 = SIGN(FI3/L3, VBC): the magnitudes Fig. 4 prints), and accumulates the crank angle
in the ES EVM's truncating arithmetic (E-FIG4-4).  The garbage ALA of E-II13-1 cannot be
reproduced: both modes use the corrected ALA, so VD and the signs of W2 and W3 are not
the printed ones (E-II13-2, E-II13-3; Fig. 4's diff compares W2, W3 in magnitude).

:func:`single` runs the same statements in IEEE single precision through the printed
routines of :mod:`sarkp.printed`, :func:`emulate` in the ES EVM's arithmetic, and
:func:`arithmetic_table` counts the printed cells each arithmetic reproduces.
"""

from __future__ import annotations

import math

import numpy as np

from .. import (DOMEGA, DSMVKT, DUGL1, DUGL3, DVKT, GELG, AssemblyError, SingularError,
                get_mode)
from ..modes import book_pi
from ..report import fortran_write
from . import es_evm

LISTING = "II.13"
TITLE = "Positions and velocities of the four-bar of Fig. 3"
FIGURES = ("4",)

#: The input card (L835, FORMAT 6F8.4), deduced from Fig. 4.
CARD = {"L1": 0.25, "L2": 0.65, "L3": 0.40, "LO": 0.60, "NU": 0.0, "LBD": 0.0}
W1 = 2.0                                       # L837: hard-coded crank speed, rad/s
COLUMNS = ("FI", "FI2", "FI3", "XB", "YB", "XD", "YD", "VD", "ALD", "W2", "W3")
FORMAT = "(1X,11F10.4)"                        # L881
#: Why a printed cell differs in corrected mode (see docs/ERRATA.md).
CORRECTED_DIFFERENCES = {"ALD": "E-II13-4; E-PI-1", "FI": "E-FIG4-4; E-PI-1",
                         "W2": "E-II13-3", "W3": "E-II13-3", "*": "E-PI-1"}


def crank_angles(positions: int = 18) -> np.ndarray:
    """FI1 = 0, DFI, 2 DFI, ... with DFI = PI/18 (L838-846).

    As printed, FI1 is accumulated in the ES EVM's REAL*4 arithmetic, which is what
    makes the last printed angle 2.9670 rather than 2.9671 (ERRATA E-FIG4-4).
    """
    pi = book_pi()
    if get_mode() == "as-printed":
        dfi = es_evm.div(pi, 18.0)
        fi1, angles = es_evm.real4(-dfi), []
        for _ in range(positions):
            fi1 = es_evm.add(fi1, dfi)
            angles.append(fi1)
        return np.array(angles)
    return np.arange(positions) * (pi / 18.0)


def compute(card=None, positions: int = 18, angles=None) -> dict:
    """Run the program in the current mode; return the columns by name (arrays).

    ``card`` overrides values of :data:`CARD`; ``angles`` replaces the book's crank
    angles (radians) by any others.
    """
    c = dict(CARD, **(card or {}))
    L1, L2, L3, LO, NU, LBD = (c[k] for k in ("L1", "L2", "L3", "LO", "NU", "LBD"))
    pi = book_pi()
    printed = get_mode() == "as-printed"
    fi1 = crank_angles(positions) if angles is None else np.asarray(angles, dtype=float)
    xa, ya = L1 * np.cos(fi1), L1 * np.sin(fi1)
    lac, fiac = DVKT(xa, ya, LO, 0.0)
    cos_delta = (L2**2 + lac**2 - L3**2) / (2.0 * L2 * lac)
    if np.any(np.abs(cos_delta) > 1.0):
        k = int(np.flatnonzero(np.abs(cos_delta) > 1.0)[0])
        raise AssemblyError(f"II.13: the four-bar cannot be assembled at FI = {fi1[k]:.4f}")
    fi2 = fiac + np.arccos(cos_delta)          # L852: the "+ delta" branch, fixed
    xb, yb = xa + L2 * np.cos(fi2), ya + L2 * np.sin(fi2)
    fi3 = DUGL1(LO, 0.0, xb, yb)
    xd, yd = xb + LBD * np.cos(fi2 + (pi - NU)), yb + LBD * np.sin(fi2 + (pi - NU))

    va = abs(W1 * L1)
    ala = DUGL3(fi1, pi / 2.0, W1)       # E-II13-1: the listing calls DUGL1 here
    vbc, vba = np.empty_like(fi1), np.empty_like(fi1)
    for k in range(fi1.size):                  # eq. (2.17)-(2.19), one GELG per position
        a = [[math.cos(fi3[k] + pi / 2.0), -math.cos(fi2[k] + pi / 2.0)],
             [math.sin(fi3[k] + pi / 2.0), -math.sin(fi2[k] + pi / 2.0)]]
        r, ier = GELG([va * math.cos(ala[k]), va * math.sin(ala[k])], a, 2, 1, 0.0001)
        if ier < 0:
            raise SingularError(f"II.13: dead centre at FI = {fi1[k]:.4f}")
        vbc[k], vba[k] = r
    alba = DUGL3(fi2, pi / 2.0, vba)
    albc = DUGL3(fi3, pi / 2.0, vbc)
    if printed:
        # E-II13-3 as printed (L875-876): DOMEGA(L2, FI2, VBA, ALBA).  DOMEGA reads three
        # arguments (L648-660), so ALBA is ignored and W2 = SIGN(FI2/L2, VBA): the
        # magnitude FI2/L2 is what Fig. 4 prints; the sign is VBA's, here from the
        # corrected ALA (the printed signs are not reproducible, E-II13-3).
        w2 = DOMEGA(L2, fi2, vba)
        w3 = DOMEGA(L3, fi3, vbc)
    else:
        w2 = DOMEGA(L2, vba, alba - fi2)
        w3 = DOMEGA(L3, vbc, albc - fi3)
    # E-II13-4: v_B has magnitude |VBC| in the direction ALBC; the listing passes the
    # signed VBC with ALBC, reversing v_B whenever VBC < 0.  Fig. 4's ALD depends on it.
    vb = vbc if printed else np.abs(vbc)
    vd, ald = DSMVKT(vb, albc, np.abs(w2) * LBD, DUGL3(fi2 + pi - NU, pi / 2.0, w2))
    return dict(zip(COLUMNS, (fi1, fi2, fi3, xb, yb, xd, yd, vd, ald, w2, w3)))


def cells(card=None) -> dict:
    """The computed table as {(row, column): value}, rows numbered from 1 as printed."""
    table = compute(card)
    return {(str(k + 1), name): float(table[name][k])
            for name in COLUMNS for k in range(len(table["FI"]))}


def render(card=None) -> str:
    """The program's printout in the book's layout (PRINT 2, FORMAT 1X,11F10.4)."""
    table = compute(card)
    return "\n".join(fortran_write(FORMAT, [table[c][k] for c in COLUMNS])
                     for k in range(len(table["FI"])))


# --- The same statements in other arithmetics ------------------------------------------
# Both runs below follow the listing (L838-880) statement by statement, with ALA from the
# corrected call DUGL3(FI1, PI/2., W1) (E-II13-1: the printed DUGL1 call has no fourth
# argument to read) and W2, W3 from the printed DOMEGA calls (E-II13-3).

def _columns(rows) -> dict:
    return {name: np.array([float(r[i]) for r in rows]) for i, name in enumerate(COLUMNS)}


def _single(function):
    """A library function of IEEE single precision: the exact value rounded to float32
    (not numpy's float32 kernels, whose last bit depends on the CPU)."""
    return lambda x: np.float32(function(float(x)))


def single() -> dict:
    """Program II.13 in IEEE single precision: the printed routines DVKT, DUGL1, DUGL3,
    DOMEGA and DSMVKT (:mod:`sarkp.printed`, REAL as on the ES EVM), the main program's
    own statements in float32 (its COS, SIN, ARCOS correctly rounded to single), and GELG
    as sarkp.printed calls it (sarkp's GELG on the REAL arguments, its result rounded to
    REAL).  The printed program itself cannot run (:func:`sarkp.printed.program`).
    Returns the columns by name."""
    from .. import printed
    f = np.float32
    cos, sin, arccos = (_single(math.cos), _single(math.sin), _single(math.acos))
    L1, L2, L3, LO, NU, LBD = (f(CARD[k]) for k in ("L1", "L2", "L3", "LO", "NU", "LBD"))
    w1, pi = f(2.0), f(3.14159)                                  # L837, L836
    dfi = pi / f(18.0)
    fi1, rows = -dfi, []
    for _ in range(18):
        fi1 = f(fi1 + dfi)
        xa, ya = L1 * cos(fi1), L1 * sin(fi1)
        lac, fiac = (f(v) for v in printed.DVKT(xa, ya, LO, 0.0))
        delta = arccos((L2**2 + lac**2 - L3**2) / (f(2.0) * L2 * lac))
        fi2 = fiac + delta
        xb, yb = xa + L2 * cos(fi2), ya + L2 * sin(fi2)
        fi3 = f(printed.DUGL1(LO, 0.0, xb, yb))
        xd = xb + LBD * cos(fi2 + (pi - NU))
        yd = yb + LBD * sin(fi2 + (pi - NU))
        va = abs(w1 * L1)
        ala = f(printed.DUGL3(fi1, pi / f(2.0), w1))               # E-II13-1 corrected
        a = np.array([[cos(fi3 + pi / f(2.0)), -cos(fi2 + pi / f(2.0))],
                      [sin(fi3 + pi / f(2.0)), -sin(fi2 + pi / f(2.0))]], dtype=f)
        c = np.array([va * cos(ala), va * sin(ala)], dtype=f)
        r, _ = GELG(c.astype(float), a.astype(float), 2, 1, float(f(0.0001)))
        vbc, vba = (f(v) for v in r)
        alba = f(printed.DUGL3(fi2, pi / f(2.0), vba))
        albc = f(printed.DUGL3(fi3, pi / f(2.0), vbc))
        w2 = f(printed.DOMEGA(L2, fi2, vba))                        # E-II13-3 as printed
        w3 = f(printed.DOMEGA(L3, fi3, vbc))
        vd, ald = printed.DSMVKT(vbc, albc, abs(w2) * LBD,
                                 printed.DUGL3(fi2 + pi - NU, pi / f(2.0), w2))
        rows.append((fi1, fi2, fi3, xb, yb, xd, yd, vd, ald, w2, w3))
    return _columns(rows)


def _gelg_es_evm(r, a, m, eps, R):
    """IBM SSP's GELG (one right-hand side) in the arithmetic ``R``, statement by statement
    as SSP writes it: complete pivoting, the pivot row multiplied by the reciprocal pivot,
    back substitution from the saved column interchanges.  ``r``, ``a`` are flat lists in
    Fortran (column) order; returns the solution."""
    r, a = list(r), list(a)
    mm = m * m
    piv, i = R(0.0), 0
    for ll in range(1, mm + 1):                       # search for the greatest element
        if abs(a[ll - 1]) > piv:
            piv, i = abs(a[ll - 1]), ll
    lst = 1
    for k in range(1, m + 1):
        if piv <= 0.0:
            raise SingularError("GELG: singular matrix")
        pivi = R(1.0) / a[i - 1]
        j = (i - 1) // m
        i = i - j * m - k
        j = j + 1 - k
        ll = k + i                                    # pivot row reduction, row swap in R
        tb = pivi * r[ll - 1]
        r[ll - 1] = r[k - 1]
        r[k - 1] = tb
        if k >= m:
            break
        lend = lst + m - k
        if j > 0:                                     # column interchange in A
            ii = j * m
            for l in range(lst, lend + 1):
                a[l - 1], a[l + ii - 1] = a[l + ii - 1], a[l - 1]
        for l in range(lst, mm + 1, m):               # row interchange, pivot row reduction
            ll = l + i
            tb = pivi * a[ll - 1]
            a[ll - 1] = a[l - 1]
            a[l - 1] = tb
        a[lst - 1] = R(j)                             # column interchange information
        piv = R(0.0)
        lst += 1
        j = 0
        for ii in range(lst, lend + 1):               # element reduction, next pivot
            pivi = -a[ii - 1]
            j += 1
            for l in range(ii + m, mm + 1, m):
                ll = l - j
                a[l - 1] = a[l - 1] + pivi * a[ll - 1]
                if abs(a[l - 1]) > piv:
                    piv, i = abs(a[l - 1]), l
            ll = k + j
            r[ll - 1] = r[ll - 1] + pivi * r[k - 1]
        lst += m
    ist, lst = mm + m, m + 1                          # back substitution and interchange
    for i in range(2, m + 1):
        ii = lst - i
        ist = ist - lst
        shift = int(float(a[ist - m - 1]) + 0.5)
        tb = r[ii - 1]
        ll = ii
        for k in range(ist, mm + 1, m):
            ll += 1
            tb = tb - a[k - 1] * r[ll - 1]
        k = ii + shift
        r[ii - 1] = r[k - 1]
        r[k - 1] = tb
    return r


def emulate() -> dict:
    """Program II.13 in the ES EVM's truncating hexadecimal REAL*4, statement by statement
    and left to right as written, with the printed routines (DVKT, DUGL1, DUGL3, DOMEGA,
    DSMVKT, DUGL5: L551-698) and IBM SSP's GELG written out the same way; library functions
    are the exact values truncated (as in :func:`sarkp.book.prog_v_5.emulate`).
    Independent of sarkp's Fortran.  Returns the columns by name."""
    from .es_evm import ACOS as acos, ATAN as atan, COS as cos, Real4 as R, SIN as sin, \
        SQRT as sqrt
    pi_r = R(3.14159)

    def sign(a, b):                                   # FORTRAN SIGN
        return R(abs(a)) if b >= 0.0 else R(-abs(a))

    def dvkt(x1, y1, x2, y2):                         # II.11, L664-680
        rz = sqrt((x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1))
        if rz == 0.0:
            return rz, R(0.0)
        return rz, sign(acos((x2 - x1) / rz), y2 - y1)

    def dugl1(x1, y1, x2, y2):                        # II.3, L551-569
        rr = sqrt((x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1))
        c = sign(acos((x2 - x1) / rr), y2 - y1)
        return c if c >= 0.0 else c + R(2.0) * pi_r

    def dugl3(ugol1, ugold, vel):                     # II.5, L590-599
        return ugol1 + sign(ugold, vel)

    def domega(razmer, vektor, ugol):                 # II.10, L648-660
        return sign(vektor / razmer, ugol)

    def dugl5(prx, pry):                              # II.7
        if prx == 0.0:
            return sign(pi_r / R(2.0), pry)
        d = pry / prx
        return atan(d) if prx >= 0.0 else pi_r + atan(d)

    def dsmvkt(l1, fi1, l2, fi2):                     # II.12, L684-698
        lx = l1 * cos(fi1) + l2 * cos(fi2)
        ly = l1 * sin(fi1) + l2 * sin(fi2)
        return sqrt(lx * lx + ly * ly), dugl5(lx, ly)

    L1, L2, L3, LO, NU, LBD = (R(CARD[k]) for k in ("L1", "L2", "L3", "LO", "NU", "LBD"))
    w1, pi = R(2.0), pi_r
    dfi = pi / R(18.0)
    fi1, rows = -dfi, []
    for _ in range(18):
        fi1 = fi1 + dfi
        xa, ya = L1 * cos(fi1), L1 * sin(fi1)
        lac, fiac = dvkt(xa, ya, LO, R(0.0))
        delta = acos((L2 * L2 + lac * lac - L3 * L3) / (R(2.0) * L2 * lac))
        fi2 = fiac + delta
        xb, yb = xa + L2 * cos(fi2), ya + L2 * sin(fi2)
        fi3 = dugl1(LO, R(0.0), xb, yb)
        xd = xb + LBD * cos(fi2 + (pi - NU))
        yd = yb + LBD * sin(fi2 + (pi - NU))
        va = R(abs(w1 * L1))
        ala = dugl3(fi1, pi / R(2.0), w1)                           # E-II13-1 corrected
        a = [cos(fi3 + pi / R(2.0)), sin(fi3 + pi / R(2.0)),      # A(1,1), A(2,1),
             -cos(fi2 + pi / R(2.0)), -sin(fi2 + pi / R(2.0))]    # A(1,2), A(2,2)
        vbc, vba = _gelg_es_evm([va * cos(ala), va * sin(ala)], a, 2, R(0.0001), R)
        alba = dugl3(fi2, pi / R(2.0), vba)
        albc = dugl3(fi3, pi / R(2.0), vbc)
        w2 = domega(L2, fi2, vba)                                   # E-II13-3 as printed
        w3 = domega(L3, fi3, vbc)
        vd, ald = dsmvkt(vbc, albc, R(abs(w2)) * LBD, dugl3(fi2 + pi - NU, pi / R(2.0), w2))
        rows.append((fi1, fi2, fi3, xb, yb, xd, yd, vd, ald, w2, w3))
    return _columns(rows)


#: The column groups of :func:`arithmetic_table` (VD is left out: E-II13-2).
_GROUPS = (("FI FI2 FI3 XB YB XD YD", ("FI", "FI2", "FI3", "XB", "YB", "XD", "YD")),
           ("ALD", ("ALD",)), ("\\|W2\\| (magnitude)", ("W2",)),
           ("\\|W3\\| (magnitude)", ("W3",)))


def arithmetic_table() -> str:
    """Fig. 4's printed cells reproduced by the same statements in three arithmetics:
    as-printed mode (double precision), IEEE single precision (:func:`single`) and the
    ES EVM's (:func:`emulate`); a Markdown table of the cells within half a unit of the
    last printed digit (W2, W3 in magnitude; VD is not reproducible, E-II13-2), then the cells
    that differ.  The README's table is this function's output."""
    from . import figures
    from .. import as_printed
    figure = figures.load_figure("4")
    with as_printed():
        runs = {"as-printed (double)": compute()}
    runs["IEEE single (sarkp.printed)"] = single()
    runs["ES EVM emulation"] = emulate()
    missed = {name: [] for name in runs}
    counts = {name: [] for name in runs}
    for label, columns in _GROUPS:
        cells = [c for c in figure.cells if c.column in columns]
        for name, run in runs.items():
            ok = 0
            for c in cells:
                value = run[c.column][int(c.row) - 1]
                if c.column in ("W2", "W3"):
                    units = (abs(value) - abs(c.value)) / c.unit
                else:
                    units = (value - c.value) / c.unit
                if figures.within_half(c, value):
                    ok += 1
                else:
                    missed[name].append(f"row {c.row} {c.column} ({units:+.2f})")
            counts[name].append(f"{ok} of {len(cells)}")
    lines = ["| printed cells | " + " | ".join(runs) + " |",
             "|---" * (len(runs) + 1) + "|"]
    for k, (label, _) in enumerate(_GROUPS):
        lines.append(f"| {label} | " + " | ".join(counts[n][k] for n in runs) + " |")
    lines.append("")
    for name in runs:
        lines.append(f"- {name} misses: {', '.join(missed[name]) or 'none'}")
    return "\n".join(lines)


def evidence(number: str = "4"):
    """Fig. 4 run in the ES EVM's arithmetic (:func:`emulate`) and in IEEE single
    (:func:`single`), for :func:`sarkp.book.figures.classify`."""
    from .figures import Evidence

    def keyed(table):
        return {(str(k + 1), name): float(table[name][k])
                for name in COLUMNS for k in range(len(table["FI"]))}
    return Evidence(book=keyed(emulate()), diagnostic={"IEEE single": keyed(single())})
