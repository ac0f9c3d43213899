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
(VD depends on memory garbage), DOMEGA with four arguments at L875-876 (W2, W3 wrong),
and the velocity of B passed to DSMVKT with its sign and its flipped direction both
applied (E-II13-4).  Corrected mode fixes all of them.  As-printed mode keeps E-II13-4,
on which the printed ALD column depends, and accumulates the crank angle in the ES EVM's
truncating arithmetic (E-FIG4-4); the garbage of E-II13-2/3 cannot be reproduced, so the
VD, W2 and W3 columns are computed correctly in both modes.
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
                         "*": "E-PI-1"}


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
    w2 = DOMEGA(L2, vba, alba - fi2)    # E-II13-3: the listing passes 4 arguments
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
