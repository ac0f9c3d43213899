"""Program VII.10 (L5596-5650): force analysis of the mechanism of Fig. 57 (IV.15's, Fig. 29).

The book's program is an add-on to the kinematics program IV.15 (L5652-5654): its DATA
statement follows IV.15's, its statements run before IV.15's ``GO TO 5``, once per
crank position.  The algorithm (steps 1-19, L5517-5592) works outward in, one group at a
time, with the projection-method routines of chapter 7:

* resistances (steps 1-3): FC1 = FS1 on link 7 and FC2 = FS2 on slider 5 while W3 <= 0
  (the code, ``IF(W3)20,20,21``; the text says W3 < 0), FC3 = FS3 on slider 11 while
  W9 > 0; each acts against the x axis (direction PI);
* group 6-7 (kind 5, DNMAF5): the yoke 7 carries FC1 and its weight Q5 (IV.15's DATA)
  at (XH, B);
* group 4-5 (kind 2, DNMAF2): rod CD with weight Q4 at its middle, slider D with FC2;
* link 3 reduced to S3 = F + RFS3 e(FI3): the forces of 6 and 4 on it and its weight Q3
  (steps 7-11);
* group 2-3 (kind 1, DNMAF1): coupler AB with weight Q2 at its middle, rocker 3 about F;
* group 10-11 (kind 4, DNMAF4): slider 11 on the fixed guide with FC3;
* link 9 reduced to S9 = O1 + RO1S9 e(FI9) (steps 14-15), group 8-9 (kind 3, DNMAF3);
* TMR = the moment about O of the forces of links 2 and 8 on the crank (steps 17-19).

It prints four lines per position (FORMATs 40-43), after IV.15's five.  The book prints no
output of this program, so :data:`FIGURES` is empty; tests/test_vii10.py holds it against
virtual work: the balancing moment on the crank, ``MY = -TMR`` (eq. 7.22), equals
``sum(F.v)/W1`` over every load (the crank turns clockwise at W1).

The listing as printed does not run (docs/ERRATA.md, E-VII10-1..5): the DNMAF2 call has 22
of its 23 arguments (``X`` for ``XD, Y``) and the DNMAF1 call lost ``-PID2`` (the minus
sign went to the next argument).  Both are corrected in both modes; as-printed mode
differs from corrected mode only by PI = 3.14159 (and by what IV.15's as-printed mode
changes: its accelerations, which the force analysis does not use).

Extension (not in the book): ``compute(..., inertia=...)`` adds the d'Alembert loads
-m a_S and -J_S epsilon of section 7.1 (L4863-4869) with the exact accelerations of IV.15.
"""

from __future__ import annotations

import math

import numpy as np

from ..forces import DNMAF1, DNMAF2, DNMAF3, DNMAF4, DNMAF5
from ..modes import book_pi
from ..operators import DMOMNT, DSMVKT
from ..report import fortran_write
from . import prog_iv_15

LISTING = "VII.10"
TITLE = "Force analysis of the mechanism of Fig. 57 (IV.15's mechanism, groups of all five kinds)"
FIGURES = ()

#: The DATA statement (L5602-5603): resistances FS1 (link 7), FS2 (link 5), FS3 (link 11)
#: and the weights Q4, Q3, Q9, N.  Q5 = 100 (the weight of link 7) and Q2 = 50 come from
#: IV.15's DATA (prog_iv_15.CARD).
CARD = {"FS1": 500.0, "FS2": 1000.0, "FS3": 750.0, "Q4": 200.0, "Q3": 300.0, "Q9": 200.0}

FORMAT_40 = "(1X,12F10.1)"                                  # L5640
FORMAT_41 = "(1X,12F10.3)"                                  # L5643
FORMAT_42 = "(1X,F20.3,F10.3,F30.3,F40.3,F20.3)"            # L5646 (E-VII10-4)
FORMAT_43 = "(1X,9F12.3)"                                   # L5648, then // (two blank lines)
PRINTS = (
    (FORMAT_40, ("F63", "F76", "F70", "F43", "F54", "F50", "F21", "F23", "F30", "F109",
                 "F1011", "F110")),
    (FORMAT_41, ("G63", "G76", "G70", "G43", "G54", "G50", "G21", "G23", "G30", "G109",
                 "G1011", "G110")),
    (FORMAT_42, ("H76", "H70", "H50", "H109", "H110")),
    (FORMAT_43, ("F81", "G81", "F89", "G89", "H89", "F90", "G90", "TMR", "FI")),
)
COLUMNS = tuple(dict.fromkeys(name for _, names in PRINTS for name in names))

#: Masses (kg) and moments of inertia about the centres of mass (kg*m^2) for the
#: ``inertia`` extension: links 2, 3, 4, 5, 7, 9, 11 (6, 8, 10 are taken massless).
INERTIA_KEYS = ("M2", "J2", "M3", "J3", "M4", "J4", "M5", "M7", "M9", "J9", "M11")


def compute(card=None, positions: int | None = None, angles=None, on_error: str = "raise",
            inertia: dict | None = None) -> dict:
    """Run IV.15 and then VII.10 in the current mode; every variable by its book name.

    ``card`` overrides values of :data:`CARD` or of IV.15's ``CARD``; ``positions`` and
    ``angles`` are IV.15's.  The result holds IV.15's variables, the printed
    :data:`COLUMNS`, the resistances FC1, FC2, FC3, the reduced loads of links 3 and 9
    (F3, G3, TM3, F9, G9, TM9) and ``MY = -TMR``, the balancing moment on the crank
    (N*m, counter-clockwise positive).

    ``inertia`` (sarkp's extension): {name: value} for :data:`INERTIA_KEYS` (missing ones
    0); the d'Alembert loads -m a_S, -J epsilon are added to each link's loads, with
    g = 9.81 not involved (the weights stay the book's Q).
    """
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    kin_card = card
    t = prog_iv_15.compute(kin_card, positions, angles, on_error)
    c = dict(prog_iv_15.CARD, **kin_card)
    FS1, FS2, FS3, Q4, Q3, Q9 = (forces[k] for k in ("FS1", "FS2", "FS3", "Q4", "Q3", "Q9"))
    ROA, RCF, RFG, RFS3, ROM, RO1S9, ROF, B, C, Q5, Q2, W1 = (
        c[k] for k in ("ROA", "RCF", "RFG", "RFS3", "ROM", "RO1S9", "ROF", "B", "C", "Q5",
                       "Q2", "W1"))
    PI = book_pi()
    PID2 = PI / 2.0
    AAA = prog_iv_15.AAA
    FI, FI3, FI9 = t["FI"], t["FI3"], t["FI9"]
    XA, YA, XB, YB, XC, YC, XD, Y = (t[k] for k in ("XA", "YA", "XB", "YB", "XC", "YC",
                                                     "XD", "Y"))
    XH, YH, XM, YM, XP, YP, RO1P, FIO1P = (t[k] for k in ("XH", "YH", "XM", "YM", "XP",
                                                         "YP", "RO1P", "FIO1P"))
    zero = np.zeros_like(FI)

    def call(routine, *args):
        out = routine(*args, on_error=on_error)
        if routine.spec.function:                     # a FUNCTION returns its value
            return (out[0] if on_error == "nan" else out,)
        return tuple(out)[:len(routine.spec.outputs)]

    def load(f, g, fx, fy):
        """The force (f, g) plus the inertia force (fx, fy), as (modulus, direction)."""
        if not inertia:
            return f, g
        return call(DSMVKT, f, g, np.hypot(fx, fy), np.arctan2(fy, fx))

    # d'Alembert loads (extension): -m a_S as (x, y) components, -J epsilon
    m = {k: 0.0 for k in INERTIA_KEYS}
    for k, value in (inertia or {}).items():
        if k not in m:
            raise ValueError(f"VII.10: unknown inertia key {k!r}; known: "
                             f"{', '.join(INERTIA_KEYS)}")
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
            raise ValueError(f"VII.10: inertia {k} = {value!r} must be a finite number "
                             f">= 0 (a mass in kg or a moment of inertia in kg*m^2)")
        m[k] = float(value)
    acc = _centre_accelerations(t, c) if inertia else None

    def inertia_force(link, mass):
        if not inertia:
            return zero, zero
        ax, ay = acc[link]
        return -m[mass] * ax, -m[mass] * ay

    # steps 1-3 (L5604-5613): resistances
    FC1 = np.where(t["W3"] <= 0.0, FS1, 0.0)
    FC2 = np.where(t["W3"] <= 0.0, FS2, 0.0)
    FC3 = np.where(t["W9"] > 0.0, FS3, 0.0)

    # steps 4-5: group 6-7 (kind 5); link 7's loads at (XH, B)
    R, G = call(DSMVKT, FC1, PI, Q5, -PID2)
    R, G = load(R, G, *inertia_force(7, "M7"))
    F63, G63, F76, G76, H76, F70, G70, H70 = call(
        DNMAF5, XH, YH, 0.0, PID2, XH, YH, 0.0, 0.0, XH, B, R, G, 0.0, 0.0, AAA)

    # step 6: group 4-5 (kind 2); S4 the middle of CD, link 5's load at D (E-VII10-2)
    F4, G4 = load(Q4, -PID2, *inertia_force(4, "M4"))
    F5, G5 = load(FC2, PI, *inertia_force(5, "M5"))
    F43, G43, F54, G54, F50, G50, H50 = call(
        DNMAF2, XC, YC, XD, Y, 0.0, 0.5 * (XC + XD), 0.5 * (YC + Y), F4, G4, XD, Y, F5, G5,
        -m["J4"] * t["E4"], 0.0, AAA)

    # steps 7-11: link 3 reduced to S3
    F, G = call(DSMVKT, F63, G63, F43, G43)
    F3, G3 = call(DSMVKT, F, G, Q3, -PID2)
    F3, G3 = load(F3, G3, *inertia_force(3, "M3"))
    TM1 = call(DMOMNT, RFG - RFS3, FI3, F63, G63)[0]
    TM2 = call(DMOMNT, RCF - RFS3, FI3, F43, G43)[0]
    TM3 = TM1 + TM2 - m["J3"] * t["E3"]

    # step 12: group 2-3 (kind 1); S2 the middle of AB (E-VII10-3)
    F2, G2 = load(Q2, -PID2, *inertia_force(2, "M2"))
    F21, G21, F23, G23, F30, G30 = call(
        DNMAF1, XA, YA, XB, YB, ROF, 0.0, 0.5 * (XA + XB), 0.5 * (YA + YB), F2, G2,
        RFS3 * np.cos(FI3) + ROF, RFS3 * np.sin(FI3), F3, G3, -m["J2"] * t["E2"], TM3, AAA)

    # step 13: group 10-11 (kind 4); link 11's load at P
    F11, G11 = load(FC3, PI, *inertia_force(11, "M11"))
    F109, G109, H109, F1011, G1011, F110, G110, H110 = call(
        DNMAF4, FI9, 0.0, XP, YP, XP, YP, 0.0, 0.0, XP, YP, F11, G11, 0.0, 0.0, AAA)

    # steps 14-15: link 9 reduced to S9 (P and S9 lie on opposite sides of O1: FIO1P is
    # FI9 + PI, so P - S9 = (RO1P + RO1S9) e(FIO1P))
    F9, G9 = call(DSMVKT, F109, G109, Q9, -PID2)
    F9, G9 = load(F9, G9, *inertia_force(9, "M9"))
    TM9 = call(DMOMNT, RO1P + RO1S9, FIO1P, F109, G109)[0] - m["J9"] * t["E9"]

    # step 16: group 8-9 (kind 3)
    F81, G81, F89, G89, H89, F90, G90 = call(
        DNMAF3, XM, YM, 0.0, -C, FI9, XM, YM, 0.0, 0.0, RO1S9 * np.cos(FI9),
        RO1S9 * np.sin(FI9) - C, F9, G9, 0.0, TM9, AAA)

    # steps 17-19: the moment about O of the groups' forces on the crank
    TMR = call(DMOMNT, ROA, FI, F21, G21)[0] + call(DMOMNT, ROM, FI - PI, F81, G81)[0]
    MY = -TMR

    names = locals()
    result = dict(t)
    for k in COLUMNS + ("FC1", "FC2", "FC3", "F3", "G3", "TM3", "F9", "G9", "TM9", "MY"):
        result[k] = np.broadcast_to(np.asarray(names[k], dtype=float), FI.shape).copy()
    return result


def mechanism(card=None, angles=None):
    """The mechanism of Fig. 57 with the program's loads as a :class:`sarkp.Mechanism`
    (IV.15's :func:`~sarkp.book.prog_iv_15.mechanism` plus the weights Q2 .. Q9 at the
    centres the program uses and the resistances FC1 .. FC3 at the crank ``angles``
    (default IV.15's), on the links the program puts them on: FC1 and Q5 on the yoke 7
    at (XH, B), FC2 on the slider 5 at D, FC3 on the slider 11 at P).  Static: solve with
    ``need="forces"``; its balancing moment is the program's MY."""
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    c = dict(prog_iv_15.CARD, **card)
    FI = (prog_iv_15.crank_angles() if angles is None
          else np.atleast_1d(np.asarray(angles, dtype=float)))
    m = prog_iv_15.mechanism(card)
    r = m.solve(FI, omega=-c["W1"], need="velocities")
    w3, w9 = r.omega("F", "B"), r.omega("O1", "N")
    fc1 = np.where(w3 <= 0.0, forces["FS1"], 0.0)                 # steps 1-3
    fc2 = np.where(w3 <= 0.0, forces["FS2"], 0.0)
    fc3 = np.where(w9 > 0.0, forces["FS3"], 0.0)
    m.point("Y7", "K", None, c["B"], math.pi / 2)                 # (XH, B) on the yoke
    m.force("Y7", -fc1, -c["Q5"] + 0.0 * fc1)
    m.point("S4", "C", "D", 0.5 * c["RCD"])
    m.force("S4", 0.0, -forces["Q4"])
    m.force("D", -fc2, 0.0 * fc2)
    m.point("S3", "F", "B", c["RFS3"])
    m.force("S3", 0.0, -forces["Q3"])
    m.point("S2", "A", "B", 0.5 * c["RAB"])
    m.force("S2", 0.0, -c["Q2"])
    m.force("P", -fc3, 0.0 * fc3, link=("P", "Q"))
    m.point("S9", "O1", "N", c["RO1S9"])
    m.force("S9", 0.0, -forces["Q9"])
    return m, FI


def _centre_accelerations(t, c):
    """Accelerations (x, y) of the centres of mass of links 2, 3, 4, 5, 7, 9, 11 from
    IV.15's exact accelerations."""
    def vec(a, b):
        return a * np.cos(b), a * np.sin(b)

    def rotating(w, e, rx, ry):                       # e k x r - w^2 r
        return -e * ry - w * w * rx, e * rx - w * w * ry

    W1 = c["W1"]
    aax, aay = vec(W1**2 * c["ROA"], t["FI"] - book_pi())      # the crank turns evenly
    abx, aby = vec(t["AB"], t["BB"])
    acx, acy = vec(t["AC"], t["BC"])
    adx, ady = vec(t["AD"], t["BD"])
    r3 = c["RFS3"]
    r9 = c["RO1S9"]
    return {
        2: ((aax + abx) / 2, (aay + aby) / 2),
        3: rotating(t["W3"], t["E3"], r3 * np.cos(t["FI3"]), r3 * np.sin(t["FI3"])),
        4: ((acx + adx) / 2, (acy + ady) / 2),
        5: (adx, ady),
        7: vec(t["AG"], t["BG"]),
        9: rotating(t["W9"], t["E9"], r9 * np.cos(t["FI9"]), r9 * np.sin(t["FI9"])),
        11: vec(t["AP"], t["BP"]),
    }


def cells(card=None) -> dict:
    """The computed table as {(row, column): value}; row = position number from 1."""
    table = compute(card)
    return {(str(k + 1), name): float(table[name][k])
            for name in COLUMNS for k in range(len(table["FI"]))}


def render(card=None) -> str:
    """The combined program's printout: per position IV.15's five lines, then VII.10's
    four (PRINT 40-43, L5639-5648) and the two blank lines of FORMAT 43's ``//``."""
    table = compute(card)
    lines = []
    for k in range(len(table["FI"])):
        for fmt, names in prog_iv_15.PRINTS + PRINTS:
            lines.append(fortran_write(fmt, [table[n][k] for n in names]))
        lines += ["", ""]
    return "\n".join(lines)


#: the names (without suffix) of the pictures :func:`plots` writes
PICTURES = ("vii10_hodograph_21", "vii10_hodograph_81", "vii10_hodograph_30",
            "vii10_hodograph_90")


def plots(directory, *, format: str = "png", dpi: float | None = None) -> list:
    """Write the hodographs of the reactions at the crank's two joints (F21, F81) and at
    the frame pivots of links 3 and 9 (F30, F90) over the book's 25 positions, as
    ``format`` files (png, svg or pdf) in ``directory``; return their paths.  Needs
    matplotlib."""
    from pathlib import Path

    from .. import plot

    t = compute()
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    numbers = np.arange(1, len(t["FI"]) + 1)
    written = []
    for name in PICTURES:
        ij = name.rsplit("_", 1)[1]
        i, j = ij[0], ij[1:]
        on = "the frame" if j == "0" else f"link {j}"
        figure = plot.reaction_hodograph(
            t["F" + ij], t["G" + ij], positions=numbers,
            label=f"F{ij}: link {i} on {on}",
            title=plot.mode_title(f"VII.10: hodograph of the reaction F{ij} (link {i} on "
                                  f"{on}), crank turning clockwise"))
        written.append(plot.save(figure, directory / name, format=format, dpi=dpi))
    return written
