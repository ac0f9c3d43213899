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

Corrected mode computes from the Mechanism (:func:`from_mechanism`): IV.15's solve, then
one force solve of the mechanism with the program's loads (:func:`mechanism`), read as the
book's (F, G, H) with the routines' ranges; the book's call sequence stays as
:func:`compute_by_groups` (as-printed mode; the reference the tests hold the Mechanism
to, 1e-13).

Extension (not in the book): ``compute(..., inertia=...)`` adds the d'Alembert loads
-m a_S and -J_S epsilon of section 7.1 (L4863-4869) with the exact accelerations of IV.15.
"""

from __future__ import annotations

import math

import numpy as np

from .. import get_mode
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

    ``on_error`` as IV.15's: under ``"nan"`` a group that does not assemble leaves NaN in
    its reactions, in those of the groups it loads and in MY (:data:`FORCE_GROUPS`).
    """
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    kin_card = card
    if get_mode() != "as-printed":
        FI = (prog_iv_15.crank_angles(positions) if angles is None
              else np.atleast_1d(np.asarray(angles, dtype=float)))
        return from_mechanism(dict(kin_card, **forces), FI, on_error, inertia)
    return compute_by_groups(dict(kin_card, **forces), positions, angles, on_error, inertia)


def compute_by_groups(card=None, positions: int | None = None, angles=None,
                      on_error: str = "raise", inertia: dict | None = None) -> dict:
    """The book's call sequence (L5604-5637): IV.15's :func:`~sarkp.book.prog_iv_15.
    compute_by_groups`, then the chapter 7 routines one group at a time, in the current
    mode (as-printed mode's :func:`compute`; in corrected mode the reference of
    :func:`from_mechanism`).  Arguments and result as :func:`compute`."""
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    kin_card = card
    t = prog_iv_15.compute_by_groups(kin_card, positions, angles, on_error)
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
    m = _inertia(inertia)
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


def _inertia(inertia):
    """The ``inertia`` extension's values, checked: {key: float} for every key."""
    m = {k: 0.0 for k in INERTIA_KEYS}
    for k, value in (inertia or {}).items():
        if k not in m:
            raise ValueError(f"VII.10: unknown inertia key {k!r}; known: "
                             f"{', '.join(INERTIA_KEYS)}")
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
            raise ValueError(f"VII.10: inertia {k} = {value!r} must be a finite number "
                             f">= 0 (a mass in kg or a moment of inertia in kg*m^2)")
        m[k] = float(value)
    return m


def mechanism(card=None, angles=None, inertia: dict | None = None):
    """The mechanism of Fig. 57 with the program's loads as a :class:`sarkp.Mechanism`
    (IV.15's :func:`~sarkp.book.prog_iv_15.mechanism` plus the weights Q2 .. Q9 at the
    centres the program uses and the resistances FC1 .. FC3 at the crank ``angles``
    (default IV.15's), on the links the program puts them on: FC1 and Q5 on the yoke 7
    at (XH, B), FC2 on the slider 5 at D, FC3 on the slider 11 at P).  Static: solve with
    ``need="forces"``; its balancing moment is the program's MY.  ``inertia``: the
    masses and moments of inertia of :data:`INERTIA_KEYS` at those centres (M5 at D,
    M11 at P), for the d'Alembert loads of a solve at the crank's speed.
    Returns ``(mechanism, FI)``."""
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    c = dict(prog_iv_15.CARD, **card)
    FI = (prog_iv_15.crank_angles() if angles is None
          else np.atleast_1d(np.asarray(angles, dtype=float)))
    r = prog_iv_15.mechanism(card).solve(FI, omega=-c["W1"], need="velocities")
    return _loaded(c, forces, r.omega("F", "B"), r.omega("O1", "N"), inertia), FI


def _loaded(c, forces, w3, w9, inertia=None, groups=None):
    """IV.15's mechanism (only ``groups``, as prog_iv_15.mechanism) with the loads of
    steps 1-16 on its links (W3, W9: the signs that switch the resistances, steps 1-3)
    and the ``inertia`` extension's masses."""
    fc1 = np.where(w3 <= 0.0, forces["FS1"], 0.0)                 # steps 1-3
    fc2 = np.where(w3 <= 0.0, forces["FS2"], 0.0)
    fc3 = np.where(w9 > 0.0, forces["FS3"], 0.0)
    m = prog_iv_15.mechanism(c, groups)
    has = set(m.joints)
    w = _inertia(inertia)
    if "B" in has:
        m.point("S3", "F", "B", c["RFS3"])
        m.force("S3", 0.0, -forces["Q3"])
        m.point("S2", "A", "B", 0.5 * c["RAB"])
        m.force("S2", 0.0, -c["Q2"])
    if "K" in has:
        m.point("Y7", "K", None, c["B"], math.pi / 2)             # (XH, B) on the yoke
        m.force("Y7", -fc1, -c["Q5"] + 0.0 * fc1)
    if "D" in has:
        m.point("S4", "C", "D", 0.5 * c["RCD"])
        m.force("S4", 0.0, -forces["Q4"])
        m.force("D", -fc2, 0.0 * fc2)
    if "N" in has:
        m.point("S9", "O1", "N", c["RO1S9"])
        m.force("S9", 0.0, -forces["Q9"])
    if "P" in has:
        m.force("P", -fc3, 0.0 * fc3, link=("P", "Q"))
    if inertia:
        for joint, args, kw in (
                ("B", ("A", "B"), dict(mass=w["M2"], inertia=w["J2"], centre=0.5 * c["RAB"])),
                ("B", ("F", "B"), dict(mass=w["M3"], inertia=w["J3"], centre=c["RFS3"])),
                ("D", ("C", "D"), dict(mass=w["M4"], inertia=w["J4"], centre=0.5 * c["RCD"])),
                ("D", ("D",), dict(mass=w["M5"])),
                ("K", ("K", "Y7"), dict(mass=w["M7"], centre=c["B"])),
                ("N", ("O1", "N"), dict(mass=w["M9"], inertia=w["J9"], centre=c["RO1S9"])),
                ("P", ("P", "Q"), dict(mass=w["M11"]))):
            if joint in has:
                m.mass(*args, **kw)
    return m


#: VII.10's reactions from a Mechanism solve: name -> (joint, on, by, sign), the force of
#: link i on link j for Fij (the book's numbers: 1 crank, 2 AB, 3 FB, 4 CD, 5 slider D,
#: 6 block at H, 7 yoke, 8 slider at M, 9 link O1-N, 10 slider P on 9, 11 slider P on
#: the guide, 0 the frame)
REACTIONS = {
    "F63": ("H", ("H", "K"), ("F", "B"), -1.0), "F76": ("H", ("H", "K"), ("K", "L"), 1.0),
    "F70": ("K", ("K", "L"), "frame", -1.0), "F43": ("C", None, None, -1.0),
    "F54": ("D", "D", ("C", "D"), 1.0), "F50": ("D", "D", "frame", -1.0),
    "F21": ("A", None, None, -1.0), "F23": ("B", None, None, 1.0),
    "F30": ("F", None, None, -1.0),
    "F109": ("P", ("P", "O1"), ("O1", "N"), -1.0),
    "F1011": ("P", ("P", "Q"), ("P", "O1"), 1.0),
    "F110": ("P", ("P", "Q"), "frame", -1.0), "F81": ("M", None, None, -1.0),
    "F89": ("N", ("O1", "N"), ("M", "N"), 1.0), "F90": ("O1", None, None, -1.0)}
#: directions "g - pi" of DNMAF1-3's first reaction (DSMVKT's DUGL5 of the opposite force,
#: less pi: in (-3 pi/2, pi/2)); DNMAF5's G70 and DNMAF4's G109 are DUGL3(FIM, PI/2, F)
#: - PI; the others DSMVKT's DUGL5
OPPOSITE = ("F43", "F21", "F81")
#: the slider pairs' arms H (DNMAF's ARM: a moment about the routine's point over the
#: force): name -> (reaction, the routine's point, sign).  DNMAF5's H34 (H70) balances the
#: group's loads about A, so it is the arm of the frame's force on the yoke, -F70.
ARMS = {"H76": ("F76", "H", 1.0), "H70": ("F70", "H", -1.0), "H50": ("F50", "D", 1.0),
        "H109": ("F109", "P", 1.0), "H110": ("F110", "P", 1.0), "H89": ("F89", "O1", 1.0)}


def _cross(r, f):
    return r[..., 0] * f[..., 1] - r[..., 1] * f[..., 0]


#: The reactions of each group and the groups whose kinematics and loads they need
#: (IV.15's GROUPS: a group, the groups it stands on and those that load it): a group
#: that does not assemble leaves the others' forces valid (the crank's MY needs all).
FORCE_GROUPS = {
    "K": (("F63", "F76", "F70"), ("B", "K")),
    "D": (("F43", "F54", "F50"), ("B", "D")),
    "B": (("F21", "F23", "F30"), ("B", "D", "K")),
    "P": (("F109", "F1011", "F110"), ("N", "P")),
    "N": (("F81", "F89", "F90"), ("N", "P")),
}


def _force_columns(r, t, group, forces, w):
    """The book's variables of one group's reactions from the force solve r."""
    from .prog_iv_15 import _dugl5, _near
    out, vec = {}, {}
    for name in FORCE_GROUPS[group][0]:
        joint, on, by, sign = REACTIONS[name]
        v = vec[name] = sign * r.reaction(joint, on=on, by=by)
        out[name] = np.hypot(v[..., 0], v[..., 1])
        g = "G" + name[1:]
        if name in OPPOSITE:
            out[g] = _dugl5(-v) - np.pi
        elif name == "F70":
            out[g] = _near(v, 0.0 * out[name] - np.pi)
        elif name == "F109":
            out[g] = _near(v, t["FI9"] - np.pi)
        else:
            out[g] = _dugl5(v)
    for h, (name, at, arm) in ARMS.items():
        if name in vec:
            joint, on, by, sign = REACTIONS[name]
            moment = arm * (sign * r.couple(joint, on=on, by=by)
                            + _cross(r.position(joint) - r.position(at), vec[name]))
            f = out[name]
            out[h] = np.where(f == 0.0, 0.0, moment / np.where(f == 0.0, 1.0, f))
    # steps 7-11 and 14-15: links 3 and 9 reduced to S3 and S9 (their weights, the
    # forces of the outer groups on them, the extension's inertia loads)
    pos, acc = r.position, r.acceleration
    down = np.array([0.0, -1.0])
    if group == "B":
        f63 = REACTIONS["F63"][3] * r.reaction(*REACTIONS["F63"][:3])
        f43 = REACTIONS["F43"][3] * r.reaction(*REACTIONS["F43"][:3])
        f3 = f63 + f43 + forces["Q3"] * down - w["M3"] * acc("S3")
        out["F3"], out["G3"] = np.hypot(f3[..., 0], f3[..., 1]), _dugl5(f3)
        out["TM3"] = (_cross(pos("H") - pos("S3"), f63) + _cross(pos("C") - pos("S3"), f43)
                      - w["J3"] * t["E3"])
    if group == "N":
        f109 = REACTIONS["F109"][3] * r.reaction(*REACTIONS["F109"][:3])
        f9 = f109 + forces["Q9"] * down - w["M9"] * acc("S9")
        out["F9"], out["G9"] = np.hypot(f9[..., 0], f9[..., 1]), _dugl5(f9)
        out["TM9"] = _cross(pos("P") - pos("S9"), f109) - w["J9"] * t["E9"]
    return out


def from_mechanism(card, FI, on_error: str = "raise", inertia: dict | None = None) -> dict:
    """Corrected mode's :func:`compute`: IV.15's variables from its Mechanism solve
    (:func:`sarkp.book.prog_iv_15.from_mechanism`), then one force solve of the loaded
    mechanism (:func:`mechanism`), its reactions read as the book's (modulus, direction,
    arm) with the directions in the routines' ranges.  Where a group does not assemble
    (``on_error="nan"``), those positions are solved again per group
    (:data:`FORCE_GROUPS`), so that forces that do not depend on it keep their values."""
    card = dict(card or {})
    forces = {k: card.pop(k) if k in card else v for k, v in CARD.items()}
    c = dict(prog_iv_15.CARD, **card)
    w = _inertia(inertia)
    t = prog_iv_15.from_mechanism(card, FI, on_error)
    r = _loaded(c, forces, t["W3"], t["W9"], inertia).solve(
        FI, omega=-c["W1"], epsilon=0.0, need="forces", on_error=on_error)
    out = dict(t)
    bad = np.isnan(r.positions).any(axis=(-1, -2))
    for g, (_, needs) in FORCE_GROUPS.items():
        cols = _force_columns(r, t, g, forces, w)
        if bad.any():
            sub_t = {k: v[bad] for k, v in t.items()}
            sub = _loaded(c, forces, sub_t["W3"], sub_t["W9"], inertia, needs).solve(
                FI[bad], omega=-c["W1"], epsilon=0.0, need="forces", on_error="nan")
            for k, v in _force_columns(sub, sub_t, g, forces, w).items():
                cols[k] = np.array(cols[k], dtype=float)
                cols[k][bad] = v
        out.update(cols)
    # steps 1-3 and 17-19
    out["FC1"] = np.where(t["W3"] <= 0.0, forces["FS1"], 0.0)
    out["FC2"] = np.where(t["W3"] <= 0.0, forces["FS2"], 0.0)
    out["FC3"] = np.where(t["W9"] > 0.0, forces["FS3"], 0.0)
    out["MY"] = r.balancing_moment
    out["TMR"] = -r.balancing_moment
    return {k: np.broadcast_to(np.asarray(out[k], dtype=float), FI.shape).copy()
            for k in list(t) + list(COLUMNS) + ["FC1", "FC2", "FC3", "F3", "G3", "TM3",
                                                 "F9", "G9", "TM9", "MY"]}


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
