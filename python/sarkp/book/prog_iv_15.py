"""Program IV.15 (L2476-2545): kinematics of the mechanism of Fig. 29, groups of all five kinds.

The book's main program (described at L2380-2472, listed at L2476-2545, explained at
L2549) computes, for 25 positions of the crank, the positions, velocities and
accelerations of the mechanism of Fig. 29 by calling one routine of chapter 4 per group:

* crank 1 about the origin O: A at OA = ROA in the direction FI, M at OM = ROM in the
  direction FI + PI; the crank turns CLOCKWISE (``5 FI = FI - DFI``) at W1 = 2 rad/s,
  so v_A = W1*ROA at FI - PI/2, v_M = W1*ROM at FI + PI/2, a_A at FI - PI, a_M at FI;
* kind 1 (links 2, 3): AB = RAB, rocker FB = RBF about F = (ROF, 0), branch P = -1
  (DPRM1, DSKOR1, DUSKR1);
* kind 2 (links 4, 5): C on link 3 at FC = RCF, CD = RCD, slider D on the fixed guide
  y = A (DPRM2, DSKOR2, DUSKR2);
* kind 5 (links 6, 7): H on link 3 at FH = RFG, block in the vertical slot (T2 = PI/2) of
  a yoke that slides on the fixed guide y = 0; G is the yoke's point at H and L the
  guide's (DSKOR5, DUSKR5; the book has no DPRM5, L1659);
* kind 3 (links 8, 9): slider 8 pivoted at M slides along link 9 pivoted at
  O1 = (0, -C); N is the point of link 9 under M (DPRM3, DSKOR3, DUSKR3);
* kind 4 (links 10, 11): the joint P of a slider on link 9 and a slider on the fixed guide
  y = -(C + D) (DPRM4, DSKOR4, DUSKR4; R is the pair 10-9, S the pair 11-frame, L5566).

It prints five lines per position (PRINT 10, 11, 11, 11, 12 at L2534-2541), 125 lines in all.
The book prints no output of this program (chapter 4 has no result figure), so
:data:`FIGURES` is empty and nothing here is compared with printed numbers; the tests
hold it against geometry and physics instead (tests/test_iv15.py).

The listing as printed does not compile (docs/ERRATA.md, E-IV15-1..12): a lost comma
in the DPRM1 call, a missing argument of DUSKR5 and of DUSKR4, a DSKOR4 call with VPM
for VPN, ``RGD`` in DATA for the RCD of the body, ``2.0 VNM * A(W9)`` and the like.
Every one is corrected in both modes: no printed figure depends on them.  Corrected mode
also evaluates the main program's own formula of the direction of a_C with ``atan2``, so
that W3 = 0 (an extreme position of the rocker) does not divide by zero (E-IV15-13).

As-printed mode gives the program as the book ran it: PI = 3.14159 (L2489), the crank
angle accumulated by ``FI = FI - DFI`` in the ES EVM's REAL*4 arithmetic, and the
library routines' own as-printed switches -- notably DUSKR1's ``ABCT = ABS(Y(1))``
(ERRATA E-DUSKR1-1), which changes E3 and with it every acceleration of groups 2 and 5
(AC, BC, E4, AD, BD, AGH, BGH, AG, BG).  Corrected mode: exact pi, FI = -k*2*pi/24,
and the mechanism described once as a :class:`sarkp.Mechanism` (:func:`mechanism`) and
solved in one call (:func:`from_mechanism`); its joints and links are read as the book's
variables, each direction in the range its routine gives (DUGOL, DUGL3-5), and agree with
the book's call sequence (:func:`compute_by_groups`) to 1e-13 (tests/test_mechanism_book.py).

Two columns that are not in the book are computed for the tests: ``SGL`` and ``SGH``,
the positions of the kind-5 group from ``DPRM5`` (an extension of sarkp): H = (SGL, SGH),
i.e. the yoke's displacement along the guide and the block's along the slot.
"""

from __future__ import annotations

import numpy as np

from .. import DUGL3, get_mode
from ..kinematics import (DPRM1, DPRM2, DPRM3, DPRM4, DPRM5, DSKOR1, DSKOR2, DSKOR3,
                          DSKOR4, DSKOR5, DUSKR1, DUSKR2, DUSKR3, DUSKR4, DUSKR5)
from ..modes import book_pi
from ..report import fortran_write
from . import es_evm

LISTING = "IV.15"
TITLE = "Kinematics of the mechanism of Fig. 29 (Assur groups of all five kinds)"
FIGURES = ()

#: The DATA statement (L2482-2488), RGD read as RCD (E-IV15-1), ROI59, WI as RO1S9, W1
#: (E-IV15-2).  B, RFS3, RFS4, RO1S9, Q5 and Q2 are not used by the kinematics (they
#: serve the force analysis VII.10, L5596-5650).
CARD = {"ROA": 0.22, "RAB": 0.45, "RBF": 0.35, "RCF": 0.5, "RFG": 0.7, "RCD": 0.58,
        "ROM": 0.3, "A": 0.2, "B": 0.77, "C": 0.62, "D": 0.27, "RFS3": 0.17, "RFS4": 0.2,
        "RO1S9": 0.15, "W1": 2.0, "ROF": 0.42, "Q5": 100.0, "Q2": 50.0}
AAA = 5.0                                      # L2488: the print flag (5: silent)
STOP = -6.3                                    # L2494: IF(FI .LT. (-6.3)) GO TO 53

#: The five PRINT statements of one position (L2534-2541) and their FORMATs.
FORMAT_10 = "(1X,12F9.4)"                      # L2535
FORMAT_11 = "(1X,12F10.3)"                     # L2539
FORMAT_12 = "(1X,14F8.3)"                      # L2542
PRINTS = (
    (FORMAT_10, ("FI", "FI2", "FI3", "XB", "YB", "XD", "FI4", "RO1M", "FI9", "XP",
                 "RO1P", "FIO1P")),
    (FORMAT_11, ("FI", "VBA", "ALBA", "VB", "ALB", "W2", "W3", "VDC", "ALDC", "VD",
                 "ALD", "W4")),
    (FORMAT_11, ("FI", "ANM", "BNM", "E9", "AN", "BN", "APR", "BPR", "AP", "BP",
                 "ANO1T", "BNO1T")),
    (FORMAT_11, ("FI", "AB", "BB", "E2", "E3", "E4", "AD", "BD", "AGH", "BGH", "AG",
                 "BG")),
    (FORMAT_12, ("FI", "VGH", "ALGH", "VG", "ALG", "VNM", "ALNM", "VN", "ALN", "W9",
                 "VPM", "ALPM", "VP", "ALP")),   # E-IV15-12: the last item printed "A"
)
#: The printed variables, each once, in the order of the printout.
COLUMNS = tuple(dict.fromkeys(name for _, names in PRINTS for name in names))


def crank_angles(positions: int | None = None) -> np.ndarray:
    """FI = 0, -DFI, -2 DFI, ... with DFI = 2 PI/24, until FI < -6.3 (L2491-2494): 25 values.

    As printed, FI is accumulated by ``FI = FI - DFI`` in the ES EVM's REAL*4 arithmetic;
    corrected, FI = -k*DFI exactly.  ``positions`` overrides the stop test.
    """
    pi = book_pi()
    if get_mode() == "as-printed":
        dfi = es_evm.div(es_evm.real4(2.0 * es_evm.real4(pi)), 24.0)
        fi, angles = es_evm.real4(dfi), []
        while True:
            fi = es_evm.add(fi, -dfi)
            if (positions is None and fi < STOP) or len(angles) == positions:
                break
            angles.append(fi)
        return np.array(angles)
    dfi = 2.0 * pi / 24.0
    if positions is None:
        positions = int(np.floor(-STOP / dfi)) + 1
    return -np.arange(positions) * dfi


def compute(card=None, positions: int | None = None, angles=None,
            on_error: str = "raise") -> dict:
    """Run the program in the current mode; return every variable by its book name (arrays).

    Corrected mode solves :func:`mechanism` once (:meth:`sarkp.Mechanism.solve`) and
    reads the book's variables off it (:func:`from_mechanism`); as-printed mode runs the
    book's call sequence, one chapter 4 routine per group (:func:`compute_by_groups`),
    since its figures depend on the as-printed routines.

    ``card`` overrides values of :data:`CARD`; ``angles`` replaces the book's crank
    angles FI (radians; the crank still turns clockwise at W1).  The result holds the
    printed :data:`COLUMNS` and the program's other variables (XA, YA, XC, YC, Y (the
    book's name of y_D), XH, YH, XM, YM, YP, RV, FV, VBF, ALBF, VC, ALC, VDE, ALDE, VGL,
    ALGL, VNO1, ALNO1, VPN, ALPN, ABAT, BBAT, ABFT, BBFT, AC, BC, ADCT, BDCT, ADE, BDE,
    AGL, BGL, APS, BPS) and the extension columns SGL, SGH (module docstring).

    ``on_error``: ``"raise"`` (an ``AssemblyError`` or ``SingularError`` names the group
    -- corrected mode: the Mechanism's group by its new joint, e.g. ``group rrp 'D'``;
    as printed: the routine -- and the first bad position) or ``"nan"``: where a group
    does not assemble, its variables and those of the groups built on it are NaN; the
    groups before it and those on other branches keep their values (:data:`GROUPS`).
    """
    if get_mode() == "as-printed":
        return compute_by_groups(card, positions, angles, on_error)
    FI = (crank_angles(positions) if angles is None
          else np.atleast_1d(np.asarray(angles, dtype=float)))
    return from_mechanism(card, FI, on_error)


def compute_by_groups(card=None, positions: int | None = None, angles=None,
                      on_error: str = "raise") -> dict:
    """The book's call sequence (L2495-2533): the chapter 4 routines one group at a time,
    in the current mode (as-printed mode's :func:`compute`; in corrected mode the
    reference that tests/test_mechanism_book.py holds :func:`from_mechanism` to).
    Arguments and result as :func:`compute`; under ``on_error="nan"`` a group that does
    not assemble gives NaN in its own variables and in those of the groups built on it.
    """
    c = dict(CARD, **(card or {}))
    ROA, RAB, RBF, RCF, RFG, RCD, ROM, A, C, D, W1, ROF = (
        c[k] for k in ("ROA", "RAB", "RBF", "RCF", "RFG", "RCD", "ROM", "A", "C", "D",
                       "W1", "ROF"))
    PI = book_pi()
    PID2 = PI / 2.0
    FI = (crank_angles(positions) if angles is None
          else np.atleast_1d(np.asarray(angles, dtype=float)))

    def call(routine, *args):
        # under "nan" a position where an earlier group failed (NaN inputs) is NaN here too
        out = routine(*args, on_error=on_error)
        if routine.spec.function:                   # a number, or (number, status)
            return (out[0] if on_error == "nan" else out,)
        return tuple(out)[:len(routine.spec.outputs)]

    # positions (L2495-2507)
    YA = ROA * np.sin(FI)
    XA = ROA * np.cos(FI)
    FI2, FI3, XB, YB = call(DPRM1, XA, YA, ROF, 0.0, RAB, RBF, -1.0, AAA)   # E-IV15-3
    XC = RCF * np.cos(FI3) + ROF
    YC = RCF * np.sin(FI3)
    XD, Y, FI4 = call(DPRM2, XC, YC, 0.0, A, 0.0, RCD, 0.0, 0.0, AAA)
    XH = RFG * np.cos(FI3) + ROF
    YH = RFG * np.sin(FI3)
    XM = ROM * np.cos(FI + PI)
    YM = ROM * np.sin(FI + PI)
    RO1M, FI9, FIO1M = call(DPRM3, XM, YM, 0.0, -C, 0.0, 0.0, 1.0, AAA)   # E-IV15-4
    XP, YP, RO1P, FIO1P, RV, FV = call(DPRM4, 0.0, -C, 0.0, -C, FI9, 0.0, 0.0, 0.0,
                                       -(C + D), 0.0, 0.0, 0.0, 0.0, 0.0, AAA)
    # not in the book: where the kind-5 group is (H = (SGL, SGH))
    _, _, SGL, SGH = call(DPRM5, 0.0, 0.0, 0.0, XH, YH, PID2, AAA)

    # velocities (L2508-2519)
    VBA, ALBA, VBF, ALBF, VB, ALB, W2, W3 = call(
        DSKOR1, RAB, FI2, RBF, FI3, W1 * ROA, FI - PID2, 0.0, 0.0, AAA)
    VC = np.abs(W3) * RCF
    ALC = call(DUGL3, FI3, PID2, W3)[0]
    VDC, ALDC, VDE, ALDE, VD, ALD, W4 = call(
        DSKOR2, VC, ALC, 0.0, 0.0, RCD, FI4, 0.0, AAA)
    VGH, ALGH, VGL, ALGL, VG, ALG = call(
        DSKOR5, XH, YH, 0.0, 0.0, 0.0, PID2, 0.0, np.abs(W3) * RFG,
        ALC, AAA)                                 # the book: DUGL3(FI3, PID2, W3) = ALC, L2515
    VNM, ALNM, VNO1, ALNO1, VN, ALN, W9 = call(
        DSKOR3, XM, YM, 0.0, -C, W1 * ROM, FI + PID2, 0.0, 0.0, FI9, AAA)
    VPM, ALPM, VPN, ALPN, VP, ALP = call(                                  # E-IV15-5
        DSKOR4, RO1P, FIO1P, FI9, RV, FV, 0.0, W9, 0.0, AAA)

    # accelerations (L2520-2533)
    ABAT, BBAT, ABFT, BBFT, AB, BB, E2, E3 = call(                         # E-IV15-6
        DUSKR1, W1**2 * ROA, FI - PI, 0.0, 0.0, RAB, FI2, RBF, FI3, W2, W3, AAA)
    AC = RCF * np.sqrt(W3**4 + E3**2)
    # L2523 BC = DUGL3(FI3, PI - ATAN(ABS(E3)/W3 ** 2), E3); atan2: E-IV15-13
    BC = call(DUGL3, FI3, PI - np.arctan2(np.abs(E3), W3**2), E3)[0]
    ADCT, BDCT, ADE, BDE, E4, AD, BD = call(
        DUSKR2, AC, BC, 0.0, 0.0, 0.0, 0.0, RCD, FI4, W4, 0.0, AAA)
    AGH, BGH, AGL, BGL, AG, BG = call(                                     # E-IV15-7, -8
        DUSKR5, XH, YH, 0.0, 0.0, 0.0, 0.0, 0.0, PID2, RFG * np.sqrt(W3**4 + E3**2), BC,
        0.0, 0.0, 0.0, 0.0, AAA)
    ANM, BNM, ANO1T, BNO1T, E9, AN, BN = call(                             # E-IV15-9
        DUSKR3, W1**2 * ROM, FI, 0.0, 0.0, FI9, W9, RO1M, FIO1M,
        2.0 * VNM * np.abs(W9), call(DUGL3, ALNM, PID2, W9)[0], AAA)
    APR, BPR, APS, BPS, AP, BP = call(                                     # E-IV15-10, -11
        DUSKR4, RO1P, FIO1P, FIO1P, 0.0, 0.0, 0.0, W9, E9, 0.0, 0.0,
        2.0 * VPM * np.abs(W9), call(DUGL3, ALPM, PID2, W9)[0], 0.0, 0.0, AAA)

    names = locals()
    return {k: np.broadcast_to(np.asarray(names[k], dtype=float), FI.shape).copy()
            for k in _KEEP}


#: The variables :func:`compute` returns.
_KEEP = ("FI XA YA FI2 FI3 XB YB XC YC XD Y FI4 XH YH XM YM RO1M FI9 FIO1M XP YP RO1P "
         "FIO1P RV FV SGL SGH VBA ALBA VBF ALBF VB ALB W2 W3 VC ALC VDC ALDC VDE ALDE "
         "VD ALD W4 VGH ALGH VGL ALGL VG ALG VNM ALNM VNO1 ALNO1 VN ALN W9 VPM ALPM "
         "VPN ALPN VP ALP ABAT BBAT ABFT BBFT AB BB E2 E3 AC BC ADCT BDCT ADE BDE E4 "
         "AD BD AGH BGH AGL BGL AG BG ANM BNM ANO1T BNO1T E9 AN BN APR BPR APS BPS AP "
         "BP").split()


#: The groups of Fig. 29 by their new joint (:func:`mechanism`), each with the groups it
#: is built on: B (kind 1) carries C and H on link 3, so D (kind 2) and K (kind 5) stand
#: on it; N (kind 3) stands on the crank's M, P (kind 4) on link 9 of N.
GROUPS = {"B": ("B",), "D": ("B", "D"), "K": ("B", "K"), "N": ("N",), "P": ("N", "P")}


def mechanism(card=None, groups=None):
    """The mechanism of Fig. 29 as a :class:`sarkp.Mechanism` (the groups of
    :func:`compute`, described once; solve it with ``omega = -W1``: the crank turns
    clockwise).  Joints: O, A (crank pin), M (on the crank opposite A), F = (ROF, 0),
    B (kind 1, DPRM1's P = -1: B on the left of A->F, branch +1), C and H on link 3
    (F-B) at RCF and RFG, D (kind 2, slider on the guide y = A through GA = (0, A)),
    K (kind 5: the yoke on the guide y = 0 through L = (0, 0), the block pivoted at H in
    its vertical slot), N (kind 3: the slider pivoted at M on link 9 about O1 = (0, -C),
    offset 0, so N = M), P (kind 4: on the axis of link 9 through O1 and on the guide
    y = -(C + D) through Q = (0, -(C + D))).  ``groups``: only these groups (new joints
    of :data:`GROUPS`, each with the groups it stands on); all by default."""
    from ..mechanism import Mechanism
    c = dict(CARD, **(card or {}))
    want = set(GROUPS) if groups is None else {g for k in groups for g in GROUPS[k]}
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("F", c["ROF"], 0.0)
    m.fixed("GA", 0.0, c["A"])
    m.fixed("L", 0.0, 0.0)
    m.fixed("O1", 0.0, -c["C"])
    m.fixed("Q", 0.0, -(c["C"] + c["D"]))
    m.crank("A", "O", c["ROA"])
    m.point("M", "O", "A", c["ROM"], np.pi)
    if "B" in want:
        m.rrr("B", "A", "F", c["RAB"], c["RBF"], branch=1)
        m.point("C", "F", "B", c["RCF"])
        m.point("H", "F", "B", c["RFG"])
    if "D" in want:
        m.rrp("D", "C", "GA", 0.0, c["RCD"], branch=1)
    if "K" in want:
        m.rpp("K", "L", 0.0, "H", np.pi / 2)
    if "N" in want:
        m.rpr("N", "M", "O1", 0.0, 0.0)
    if "P" in want:
        m.prp("P", "O1", 0.0, "Q", 0.0, guide_m=("O1", "N"))
    return m


# -- the book's variables from a Mechanism solve ------------------------------------------
# Each direction the routines print is put in the range the book's routine gives it:
# DUGL5 (L614-628) in (-pi/2, 3 pi/2); DUGOL (L630-639) in [0, 2 pi); DUGL3(FI, PI/2, Y)
# = FI +- pi/2 (the nearest to FI of the direction); DUGL4(FIM, PI, Y) = FIM or FIM - PI
# (the nearest to FIM - pi/2).

def _dugl5(v):
    x, y = v[..., 0], v[..., 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.arctan(y / x)
    d = np.where(x > 0, t, np.where(x < 0, t + np.pi, np.where(y < 0, -np.pi / 2, np.pi / 2)))
    return np.where(np.isnan(x + y), np.nan, d)


def _dugol(a):
    return np.where(a >= 0.0, a, a + 2.0 * np.pi)


def _near(v, ref):
    """The direction of v that lies within pi of ref."""
    d = np.arctan2(v[..., 1], v[..., 0])
    return ref + np.remainder(d - ref + np.pi, 2.0 * np.pi) - np.pi


def _turn(w, r):
    """w k x r."""
    return w[..., None] * np.stack([-r[..., 1], r[..., 0]], -1)


def _polar(out, mod, ang, v, direction):
    out[mod] = np.hypot(v[..., 0], v[..., 1])
    out[ang] = direction


def _group_columns(r, group):
    """The book's variables of one group from the Mechanism result r."""
    pos, vel, acc = r.position, r.velocity, r.acceleration
    out = {}
    if group == "B":                                             # DPRM1, DSKOR1, DUSKR1
        A, B, F = pos("A"), pos("B"), pos("F")
        fi2, fi3 = _dugol(np.arctan2(*(B - A).T[::-1])), _dugol(np.arctan2(*(B - F).T[::-1]))
        # DPRM1 with P = -1 (corrected): above 2 pi when A->F points below the x axis
        up = (F[..., 1] - A[..., 1]) < 0.0
        fi2 = np.where(up & (fi2 < np.pi), fi2 + 2.0 * np.pi, fi2)
        fi3 = np.where(up & (fi3 < np.pi), fi3 + 2.0 * np.pi, fi3)
        W2, W3 = r.omega("A", "B"), r.omega("F", "B")
        E2, E3 = r.epsilon("A", "B"), r.epsilon("F", "B")
        out.update(FI2=fi2, FI3=fi3, XB=B[..., 0], YB=B[..., 1], W2=W2, W3=W3, E2=E2, E3=E3)
        for p in "CH":
            out["X" + p], out["Y" + p] = pos(p)[..., 0], pos(p)[..., 1]
        _polar(out, "VBA", "ALBA", vel("B") - vel("A"), _near(vel("B") - vel("A"), fi2))
        _polar(out, "VBF", "ALBF", vel("B"), _near(vel("B"), fi3))
        _polar(out, "VB", "ALB", vel("B"), _dugl5(vel("B")))
        _polar(out, "VC", "ALC", vel("C"), _near(vel("C"), fi3))
        _polar(out, "ABAT", "BBAT", _turn(E2, B - A), _near(_turn(E2, B - A), fi2))
        _polar(out, "ABFT", "BBFT", _turn(E3, B - F), _near(_turn(E3, B - F), fi3))
        _polar(out, "AB", "BB", acc("B"), _dugl5(acc("B")))
        # L2523: BC = DUGL3(FI3, PI - ATAN(ABS(E3)/W3**2), E3), within pi/2 of FI3 +- pi/2
        _polar(out, "AC", "BC", acc("C"),
               _near(acc("C"), fi3 + np.where(E3 >= 0.0, np.pi / 2, -np.pi / 2)))
    elif group == "D":                                           # DPRM2, DSKOR2, DUSKR2
        C, D = pos("C"), pos("D")
        fi4 = _dugl5(D - C)
        W4, E4 = r.omega("C", "D"), r.epsilon("C", "D")
        out.update(XD=D[..., 0], Y=D[..., 1], FI4=fi4, W4=W4, E4=E4)
        _polar(out, "VDC", "ALDC", vel("D") - vel("C"), _near(vel("D") - vel("C"), fi4))
        _polar(out, "VDE", "ALDE", vel("D"), _near(vel("D"), -np.pi / 2 + 0.0 * fi4))
        _polar(out, "VD", "ALD", vel("D"), _dugl5(vel("D")))
        _polar(out, "ADCT", "BDCT", _turn(E4, D - C), _near(_turn(E4, D - C), fi4))
        _polar(out, "ADE", "BDE", acc("D"), _near(acc("D"), -np.pi / 2 + 0.0 * fi4))
        _polar(out, "AD", "BD", acc("D"), _dugl5(acc("D")))
    elif group == "K":                                           # DPRM5, DSKOR5, DUSKR5
        # G: the yoke's point at H (it translates with K); the slot is vertical
        H, K = pos("H"), pos("K")
        zero = 0.0 * K[..., 0]
        out.update(SGL=K[..., 0], SGH=H[..., 1] - K[..., 1])
        vgh, agh = vel("K") - vel("H"), acc("K") - acc("H")
        _polar(out, "VGH", "ALGH", vgh, _near(vgh, zero))
        _polar(out, "VGL", "ALGL", vel("K"), _near(vel("K"), zero - np.pi / 2))
        _polar(out, "VG", "ALG", vel("K"), _dugl5(vel("K")))
        _polar(out, "AGH", "BGH", agh, _near(agh, zero))
        _polar(out, "AGL", "BGL", acc("K"), _near(acc("K"), zero - np.pi / 2))
        _polar(out, "AG", "BG", acc("K"), _dugl5(acc("K")))
    elif group == "N":                                           # DPRM3, DSKOR3, DUSKR3
        # N: link 9's point under M (offset 0: N = M); FI9 = FIO1M = DUGL2(O1 -> M)
        rm = pos("M") - pos("O1")
        fi9 = np.arctan2(rm[..., 1], rm[..., 0])
        W9, E9 = r.omega("O1", "N"), r.epsilon("O1", "N")
        vn = _turn(W9, rm)
        an = _turn(E9, rm) - (W9**2)[..., None] * rm
        vnm = vn - vel("M")
        anm = an - acc("M") - _turn(2.0 * W9, vnm)         # relative, less Coriolis
        out.update(RO1M=np.hypot(rm[..., 0], rm[..., 1]), FI9=fi9, FIO1M=fi9, W9=W9, E9=E9)
        _polar(out, "VNM", "ALNM", vnm, _near(vnm, fi9 - np.pi / 2))
        _polar(out, "VNO1", "ALNO1", vn, _near(vn, fi9))
        _polar(out, "VN", "ALN", vn, _dugl5(vn))
        _polar(out, "ANM", "BNM", anm, _near(anm, fi9 - np.pi / 2))
        _polar(out, "ANO1T", "BNO1T", _turn(E9, rm), _near(_turn(E9, rm), fi9))
        _polar(out, "AN", "BN", an, _dugl5(an))
    elif group == "P":                                           # DPRM4, DSKOR4, DUSKR4
        P, rp = pos("P"), pos("P") - pos("O1")
        W9, E9 = r.omega("O1", "N"), r.epsilon("O1", "N")
        fio1p = _dugol(np.arctan2(rp[..., 1], rp[..., 0]))
        rm = pos("M") - pos("O1")
        fi9 = np.arctan2(rm[..., 1], rm[..., 0])
        vpm = vel("P") - _turn(W9, rp)                      # along link 9
        apr = acc("P") - (_turn(E9, rp) - (W9**2)[..., None] * rp) - _turn(2.0 * W9, vpm)
        out.update(XP=P[..., 0], YP=P[..., 1], RO1P=np.hypot(rp[..., 0], rp[..., 1]),
                   FIO1P=fio1p, RV=np.hypot(P[..., 0], P[..., 1]),
                   FV=_dugol(np.arctan2(P[..., 1], P[..., 0])))
        # DSKOR4's guide M is link 9's axis at FI9, DUSKR4's at FIO1P (L2519, L2533)
        _polar(out, "VPM", "ALPM", vpm, _near(vpm, fi9 - np.pi / 2))
        _polar(out, "VPN", "ALPN", vel("P"), _near(vel("P"), 0.0 * fio1p - np.pi / 2))
        _polar(out, "VP", "ALP", vel("P"), _dugl5(vel("P")))
        _polar(out, "APR", "BPR", apr, _near(apr, fio1p - np.pi / 2))
        _polar(out, "APS", "BPS", acc("P"), _near(acc("P"), 0.0 * fio1p - np.pi / 2))
        _polar(out, "AP", "BP", acc("P"), _dugl5(acc("P")))
    return out


def from_mechanism(card, FI, on_error: str = "raise") -> dict:
    """Corrected mode's :func:`compute`: one :meth:`sarkp.Mechanism.solve` of
    :func:`mechanism` at the crank angles FI (clockwise at W1), its joints and links read
    as the book's variables with the book's ranges of directions.  Where a group does
    not assemble (``on_error="nan"``), only those positions are solved again, each group
    with the groups it stands on (:data:`GROUPS`), so that groups before the failing one
    and on other branches keep their values."""
    c = dict(CARD, **(card or {}))
    W1 = c["W1"]
    r = mechanism(c).solve(FI, omega=-W1, need="accelerations", on_error=on_error)
    # the crank's points (L2495-2496, L2502-2503) do not depend on any group
    out = {"FI": FI, "XA": c["ROA"] * np.cos(FI), "YA": c["ROA"] * np.sin(FI),
           "XM": c["ROM"] * np.cos(FI + np.pi), "YM": c["ROM"] * np.sin(FI + np.pi)}
    bad = np.isnan(r.positions).any(axis=(-1, -2))
    for g in GROUPS:
        cols = _group_columns(r, g)
        if bad.any():
            sub = mechanism(c, groups=(g,)).solve(FI[bad], omega=-W1, need="accelerations",
                                                  on_error="nan")
            for k, v in _group_columns(sub, g).items():
                cols[k] = np.array(cols[k], dtype=float)
                cols[k][bad] = v
        out.update(cols)
    return {k: np.broadcast_to(np.asarray(out[k], dtype=float), FI.shape).copy()
            for k in _KEEP}


def cells(card=None) -> dict:
    """The computed table as {(row, column): value}; row = position number from 1."""
    table = compute(card)
    return {(str(k + 1), name): float(table[name][k])
            for name in COLUMNS for k in range(len(table["FI"]))}


def render(card=None) -> str:
    """The program's printout in the book's layout: five lines per position
    (PRINT 10, 11, 11, 11, 12 with FORMATs 10, 11, 12; L2534-2542), 125 lines."""
    table = compute(card)
    lines = []
    for k in range(len(table["FI"])):
        for fmt, names in PRINTS:
            lines.append(fortran_write(fmt, [table[n][k] for n in names]))
    return "\n".join(lines)
