"""Program X's stages (section 10.8, L7228-7650), each a function of the earlier
stages' results: synthesis, teeth, gears, cam, kinematics, forces, dynamics, and
:func:`run`, which runs the stages asked for with every stage they need.

:mod:`sarkp.book.prog_x` is the program (its printout, its figures, the evidence);
this module is what it shares with the modules beside it -- :mod:`sarkp.book.x_arithmetic`
(the same stages in the book's arithmetic), :mod:`sarkp.book.x_mechanism` (the six-bar on
:class:`sarkp.Mechanism`) and :mod:`sarkp.book.x_report` (the corrected design's report)
-- so that none of them imports prog_x and prog_x imports them without a circle.  The
constants of the task card are :mod:`sarkp.book.x_data`'s.  Every name here is also
prog_x's (``prog_x.kinematics`` is :func:`kinematics`); the stages themselves are
documented in :mod:`sarkp.book.prog_x`.
"""

from __future__ import annotations

import math

import numpy as np

import sarkp
from .. import DSMVKT, DUGL3, DMOMNT, get_mode
from ..errors import SarkpError
from ..kinematics import DPRM1, DPRM2, DSKOR1, DSKOR2, DUSKR1, DUSKR2
from ..modes import book_pi
from ..synthesis import DSNTZ1, DSNTZR
from . import es_evm
from .es_evm import Real4
from .x_data import (
    X5, H5, FICD, FI5, DELTA, SKW, XD, Q, W1, DSMAX, GAMMA_DIVISOR, G, ML, POSITIONS,
    CAM_POINTS, FITTED_LINKS, DELTA_FLYWHEEL, STAGES, STAGE_FIGURE, NEEDS)


class StageError(SarkpError):
    """A stage of program X cannot run; the message names the stage and the cause."""


# ---- the main program's own arithmetic ----------------------------------------------------

def _number():
    """The main program's REAL: the ES EVM's as printed, a double corrected."""
    return Real4 if get_mode() == "as-printed" else float


def _fn(name: str):
    """A library function in the main program's arithmetic (see :func:`_number`): the
    ES EVM's of the stated model (:data:`sarkp.book.es_evm.ROUNDED`) as printed."""
    return getattr(es_evm, name) if get_mode() == "as-printed" else getattr(math, name.lower())


# ---- stage 1: synthesis (Fig. 84) -----------------------------------------------------------

def synthesis() -> dict:
    """DSNTZR for the crank-slider 3-4-5 by three slider positions, then DSNTZ1 for the
    four-bar 1-2-3 by the extreme positions of link 3 and K (operator functions 1-4,
    L6489-6503; L7310-7338)."""
    pi = book_pi()
    printed = get_mode() == "as-printed"
    try:
        r = DSNTZR(X5, H5, FICD, FI5, 1.0)
    except SarkpError as exc:
        raise StageError(f"program X, stage 'synthesis' (Fig. 84): DSNTZR finds no "
                         f"crank-slider for the task card: {exc}") from exc
    # E-X-FICD1-1: the printed run used 0 (Fig. 84 prints -0.000) for DSNTZR's 1.3563
    ficd1 = 0.0 if printed else r.FI11
    ficb1 = ficd1 + pi - (pi / 2.0 + DELTA)
    try:
        s = DSNTZ1(SKW, ficb1, ficb1 + DELTA, r.L1, XD, Q, 1.0)
    except SarkpError as exc:
        raise StageError(f"program X, stage 'synthesis' (Fig. 84): DSNTZ1 finds no "
                         f"four-bar for K = {SKW} and the extreme positions "
                         f"{ficb1:.4f}, {ficb1 + DELTA:.4f} rad: {exc}") from exc
    out = {"RCD": r.L1, "RDE": r.L2, "FICD1": ficd1, "FI11": r.FI11, "FICB1": ficb1,
           "DSNTZ1": (s.L1, s.L2, s.LO), "RCD_DSNTZR": r.L1, "RDE_DSNTZR": r.L2}
    if printed:                     # E-X-LINKS-1 (Fig. 84 prints DSNTZR's RCD, RDE)
        out.update(FITTED_LINKS)
    else:
        out.update(ROA=s.L1, RAB=s.L2, ROC=s.LO)
    out["RCB"] = out["RCD"]
    return out


# ---- stage 2: tooth numbers (Fig. 86) -------------------------------------------------------

#: L7348-7363: the eight DZBPL calls (KS, P, Q, L2, L3, Z1MIN, Z1MAX, SHEMA); the COMMON
#: /ZUB/ limits ZKRN, ZKRW, DZ the program sets (L7344-7346) are DZBPL's own.  The printed
#: 5th call reads "6, 7, 3, 0, 200" for "6, 7, 30, 200" (OCR).
DZBPL_CALLS = ((1, 1, 25, 2, 3, 30, 200, 3), (1, 1, 25, 3, 4, 30, 200, 3),
               (1, 1, 25, 4, 5, 30, 200, 3), (1, 1, 25, 6, 7, 30, 200, 3),
               (2, 5, 1, 1, 1, 13, 35, 1), (3, 5, 1, 1, 1, 13, 35, 1),
               (2, 71, 10, 1, 1, 13, 35, 1), (3, 71, 10, 1, 1, 13, 35, 1))


def teeth() -> dict:
    """The eight DZBPL variants of the planetary reducer (L7344-7363); the COMMON
    /ZUB/ limits ZKRN, ZKRW, DZ of L7344-7346 are DZBPL's own (chapter 6)."""
    out = []
    for call in DZBPL_CALLS:
        try:
            result = sarkp.DZBPL(*call)
        except sarkp.RequirementError:
            # no admissible set: DZBPL prints its message and the program goes on
            # (corrected mode, variant 8: 30/76/76/183 is not coaxial, E-DZBPL-4)
            result = None
        except SarkpError as exc:
            raise StageError(f"program X, stage 'teeth' (Fig. 86): DZBPL{call}: "
                             f"{exc}") from exc
        out.append((dict(zip(sarkp.DZBPL.spec.inputs, call)), result))
    return {"variants": out}


# ---- stage 3: gear geometry (Fig. 87) -------------------------------------------------------

#: L7375-7405: DKRKT with AAA = 1.0 (it prints its input line all the same, L6590), the
#: geometry routines with AAA = 0.0 (they print their reports).  Here every call is
#: silent (AAA = 1) and :func:`render_gears` prints the reports afterwards, so that a
#: failure prints nothing and the order is the book's.
GEAR_CALLS = {
    "DKRKT": dict(M=3.0, Z1=20.0, Z2=51.0, AW=0.0, SDVIG=3, AAA=1.0),
    "DGMTZK1": dict(M=3.0, Z=20.0, BETA=0.0, AAA=1.0),            # X = X1
    "DGMTZK2": dict(M=3.0, Z=51.0, BETA=0.0, AAA=1.0),            # X = X2
    "DGMZPC": dict(M=3.0, Z1=20.0, Z2=51.0, BETA=0.0, BW=20.0, AAA=1.0),
    "DGMZVN": dict(M=3.0, Z1=51.0, Z2=122.0, X2=0.0, ZO2=25.0, DO=75.0, XO=0.17, DAO=83.8,
                   AAA=1.0),
}


def gears() -> dict:
    """Shift coefficients (DKRKT, equal specific sliding), the two gears (DGMTZK), the
    external mesh 20/51 (DGMZPC) and the internal mesh 51/122 cut by a shaper cutter
    (DGMZVN), L7365-7405."""
    out = {}
    try:
        args = GEAR_CALLS["DKRKT"]
        k = sarkp.DKRKT(**args)
        out["DKRKT"] = (args, k)
        for name, x in (("DGMTZK1", k.X1), ("DGMTZK2", k.X2)):
            args = dict(GEAR_CALLS[name], X=x)
            out[name] = (args, sarkp.DGMTZK(**args))
        args = dict(GEAR_CALLS["DGMZPC"], X1=k.X1, X2=k.X2)
        out["DGMZPC"] = (args, sarkp.DGMZPC(**args))
        args = dict(GEAR_CALLS["DGMZVN"], X1=k.X2)
        out["DGMZVN"] = (args, sarkp.DGMZVN(**args))
    except SarkpError as exc:
        raise StageError(f"program X, stage 'gears' (Fig. 87): {exc}") from exc
    return out


# ---- stage 4: cam (Fig. 89) -----------------------------------------------------------------

def cam_law() -> dict:
    """The follower's motion law, loop DO 5 (L7414-7463), formulas (10.1)-(10.3).

    As printed, in the ES EVM's arithmetic: it puts FI(11) just below FIU (row 11 is the
    end of the rise, AT = -1.8605) and FI(16) just below FIU + FID (row 16 is still on
    the dwell, AT = 0), as Fig. 89 prints (E-FIG89-3).  Corrected: the same phases by
    the row number, exact pi, double precision.  As printed, SIN and COS are the ES EVM's
    library of the stated model (:data:`sarkp.book.es_evm.ROUNDED`; E-FIG89-4)."""
    R = _number()
    cos, sin = _fn("COS"), _fn("SIN")
    pi = R(book_pi())
    beta = pi * (R(SKW) - R(1.0)) / (R(SKW) + R(1.0))
    fiu = (pi - beta) * R(0.4)
    fid = (pi - beta) * R(0.2)
    sk = fiu / pi
    w1 = R(W1)
    wo = R(DSMAX) * w1 * w1 / (R(2.0) * (sk * sk))
    dfi = fiu / R(10.0)
    printed = get_mode() == "as-printed"
    fik, at, vt, st = [], [], [], []
    fi = -dfi
    ao = R(0.0)
    for k in range(1, CAM_POINTS + 1):
        if printed:
            fi = fi + dfi
            rise = fi <= fiu
            dwell = fiu < fi < fiu + fid
            ret = fi > fiu + fid
        else:
            fi = (k - 1) * dfi
            rise, dwell, ret = k <= 11, 11 < k <= 16, k > 16
        if rise:
            ao = wo
        if dwell:
            ao = R(0.0)
        if ret:
            ao = -wo
        if (fi < fiu) if printed else k <= 11:        # IF(FI-FIU)25,26,26
            psi, smax = fi, R(0.0)
        else:
            psi, smax = fi - (fiu + fid), R(2.0) * wo * ((sk / w1) * (sk / w1))
        fik.append(fi)
        at.append(ao * cos(psi / sk))
        vt.append(ao * sk / w1 * sin(psi / sk))
        st.append(ao * ((sk / w1) * (sk / w1)) * (R(1.0) - cos(psi / sk)) + smax)
    return {"FIK": np.array(fik, float), "AT": np.array(at, float),
            "VT": np.array(vt, float), "ST": np.array(st, float),
            "FIU": float(fiu), "FID": float(fid), "BETA": float(beta), "WO": float(wo)}


def cam() -> dict:
    """The motion law and the flat-faced follower's cam (DPRFPL with GAMMA = PI/3,
    L7467; ERRATA E-X-DPRFPL-1 for its ST argument).

    As printed, the book's GAMMA = PI/3 gives a cam that is concave at 7 of the 26 points
    (radius of curvature < 0: a flat face cannot follow it).  Corrected, the cam is sized
    convex by :func:`sarkp.flat_base_radius` (the smallest RKSH with RKSH + S + A/W**2 >= 0
    everywhere) and DPRFPL draws it with the GAMMA that gives that RKSH by its own rule
    (V.3, L3240-3255: RKSH = |A_min/W**2| / tan(GAMMA) - S at A_min); ``RKSH_BOOK`` and
    ``ROKMIN_BOOK`` are the book's rule's beside it."""
    from ..cams import flat_base_radius
    law = cam_law()
    gamma = book_pi() / GAMMA_DIVISOR
    extra = {}
    try:
        if get_mode() == "corrected":
            fr = flat_base_radius(CAM_POINTS, law["FIK"], law["AT"], law["VT"], law["ST"],
                                  W1, GAMMA=gamma)
            low = int(np.argmin(law["AT"]))
            gamma = math.atan(-law["AT"][low] / W1**2 / (fr.RKSH + law["ST"][low]))
            extra = {"RKSH_BOOK": fr.RKSH_BOOK, "ROKMIN_BOOK": fr.ROKMIN_BOOK}
        p = sarkp.DPRFPL(CAM_POINTS, gamma, W1, law["FIK"], law["AT"], law["VT"], law["ST"])
    except SarkpError as exc:
        raise StageError(f"program X, stage 'cam' (Fig. 89): DPRFPL: {exc}") from exc
    return {**law, "X": p.XA, "Y": p.YA, "RK": p.R1, "DLT": p.DELTA, "ROK": p.ROK,
            "RKSH": p.RKSH, "ROKMIN": p.ROKMIN, "NCONC": p.NCONC, "GAMMA": gamma, **extra}


# ---- stage 5: kinematics (Fig. 91) ----------------------------------------------------------

def crank_angles(positions: int = POSITIONS) -> np.ndarray:
    """F = 0, DF, 2 DF, ... with DF = 2 PI/36 (L7500-7505).  As printed accumulated
    ``F = F + DF`` in the ES EVM's REAL*4, as program II.13 does (E-FIG4-4): the
    printed FI1 = 2.9670, 3.4906, ... (E-FIG91-7)."""
    if get_mode() == "as-printed":
        R = Real4
        df = R(2.0) * R(book_pi()) / R(36.0)
        f, out = -df, []
        for _ in range(positions):
            f = f + df
            out.append(float(f))
        return np.array(out)
    return np.arange(positions) * (2.0 * math.pi / 36.0)


def kinematics(links: dict, angles=None) -> dict:
    """Positions, velocities and accelerations of the mechanism (operator functions
    27-39, L6813-6855; loop DO 30, L7503-7531) at the crank angles ``angles`` (default:
    the program's 37).  ``links``: RCD (= RCB), RDE, ROA, RAB, ROC of the synthesis."""
    pi = book_pi()
    pid2 = pi / 2.0
    printed = get_mode() == "as-printed"
    f = crank_angles() if angles is None else np.asarray(angles, dtype=float)
    roa, rab, roc = links["ROA"], links["RAB"], links["ROC"]
    rcb = rcd = links["RCD"]
    rde = links["RDE"]
    xc, yc = -roc * math.sin(DELTA), roc * math.cos(DELTA)          # formula 27
    xa, ya = roa * np.cos(f), roa * np.sin(f)                       # formula 28
    try:
        p1 = DPRM1(xa, ya, xc, yc, rab, rcb, -1.0)
        xd, yd = xc + rcd * np.cos(p1.FI3 + pi), yc + rcd * np.sin(p1.FI3 + pi)
        p2 = DPRM2(xd, yd, 0.0, H5 + yc, 0.0, rde, 0.0, pid2)
        va, ala = W1 * roa, f + pid2
        v1 = DSKOR1(rab, p1.FI2, rcb, p1.FI3, va, ala, 0.0, 0.0)
        vd, ald = rcd * np.abs(v1.W3), DUGL3(p1.FI3 + pi, pid2, v1.W3)
        v2 = DSKOR2(vd, ald, 0.0, 0.0, rde, p2.FI2, 0.0)
        a1 = DUSKR1(W1**2 * roa, f + pi, 0.0, 0.0, rab, p1.FI2, rcb, p1.FI3, v1.W2, v1.W3)
        ad = rcd * np.sqrt(v1.W3**4 + a1.E3**2)
        # L7528: PI - ATAN(ABS(E3)/W3**2); atan2 keeps it finite where W3 = 0
        bd = DUGL3(p1.FI3 + pi, pi - np.arctan2(np.abs(a1.E3), v1.W3**2), a1.E3)
        # E-X-W4: L7530 passes W2(K) where omega4 belongs; the printed Fig. 91 used it
        a2 = DUSKR2(ad, bd, 0.0, 0.0, 0.0, 0.0, rde, p2.FI2, v1.W2 if printed else v2.W2,
                    0.0)
    except SarkpError as exc:
        raise StageError(f"program X, stage 'kinematics' (Fig. 91): the mechanism "
                         f"ROA = {roa:.4f}, RAB = {rab:.4f}, ROC = {roc:.4f} m: {exc}") from exc
    return {"FI1": f, "FI2": p1.FI2, "FICB": p1.FI3, "XE": p2.XB, "YE": p2.YB,
            "FIDE": p2.FI2, "XB": p1.XB, "YB": p1.YB, "XA": xa, "YA": ya, "XC": xc,
            "YC": yc, "XD": xd, "YD": yd, "W2": v1.W2, "W3": v1.W3, "VE": v2.VB,
            "ALE": v2.ALB, "W4": v2.W2, "VA": va, "ALA": ala, "VD": vd, "ALD": ald,
            "ALBA": v1.ALBA, "ALED": v2.ALBA, "E2": a1.E2, "E3": a1.E3, "E4": a2.E2,
            "AE": a2.AB, "BE": a2.BB}


# ---- stage 6: forces (Fig. 94) --------------------------------------------------------------

def masses(links: dict) -> dict:
    """L7542-7550: masses of 50 kg per metre of link (link 3 is the lever BCD, 2 RCD long),
    J_S = m l**2, m5 = 2 m4; J_S1 = (ML ROA) ROA**2 is the crank's."""
    rcd, rde, roa, rab = links["RCD"], links["RDE"], links["ROA"], links["RAB"]
    m4 = ML * rde
    m3 = 2.0 * rcd * ML
    m2 = ML * rab
    return {"M4": m4, "M5": 2.0 * m4, "M3": m3, "M2": m2, "IS4": m4 * rde**2,
            "IS3": m3 * (2.0 * rcd)**2, "IS2": m2 * rab**2, "IS1": (ML * roa) * roa**2}


def forces(links: dict, kin: dict) -> dict:
    """Static forces in the joints, without inertia loads (operator functions 40-48,
    L6994-7096; L7551-7566): the resistance FS = 2000 N while W3 < 0 (working stroke),
    400 N otherwise, gravity of links 2-5, DNMAF2 for the group 4-5, DNMAF1 for 2-3,
    the moment M1 of F21 about O."""
    pi = book_pi()
    pid2 = pi / 2.0
    m = masses(links)
    rcd, rde, rab, roa = links["RCD"], links["RDE"], links["RAB"], links["ROA"]
    fs = np.where(kin["W3"] < 0.0, 2000.0, 400.0)                   # IF(W3(K))15,16,16
    f5, g5 = DSMVKT(fs, pi, 2.0 * G * m["M4"], -pid2)
    xs4 = kin["XD"] + 0.3 * rde * np.cos(kin["FIDE"])
    ys4 = kin["YD"] + 0.3 * rde * np.sin(kin["FIDE"])
    try:
        # group 4-5 (L7556-7558): DNMAF2's F21, F23, F34 are the program's F43 (4 on 3),
        # F45 (4 on 5) and F50 (5 on the guide)
        g45 = sarkp.DNMAF2(kin["XD"], kin["YD"], kin["XE"], kin["YE"], 0.0, xs4, ys4,
                           G * m["M4"], -pid2, kin["XE"], kin["YE"], f5, g5, 0.0, 0.0)
        f3, g3 = DSMVKT(g45.F21, g45.G21, G * m["M3"], -pid2)
        t3 = DMOMNT(0.85 * rcd, kin["FICB"] + pi, g45.F21, g45.G21)   # F43 moved to S3
        # group 2-3 (L7561-7565): DNMAF1's F21, F23, F34 are F21 (2 on 1), F23 (2 on 3)
        # and F30 (3 on the frame)
        g23 = sarkp.DNMAF1(kin["XA"], kin["YA"], kin["XB"], kin["YB"], kin["XC"], kin["YC"],
                           kin["XA"] + 0.5 * rab * np.cos(kin["FI2"]),
                           kin["YA"] + 0.5 * rab * np.sin(kin["FI2"]), G * m["M2"], -pid2,
                           kin["XC"] + 0.15 * rcd * np.cos(kin["FICB"] + pi),
                           kin["YC"] + 0.15 * rcd * np.sin(kin["FICB"] + pi), f3, g3, 0.0,
                           t3)
    except SarkpError as exc:
        raise StageError(f"program X, stage 'forces' (Fig. 94): {exc}") from exc
    m1 = DMOMNT(roa, kin["FI1"], g23.F21, g23.G21)                       # L7566
    return {"FI1": kin["FI1"], "FS": fs, "F43": g45.F21, "G43": g45.G21, "F45": g45.F23,
            "G45": g45.G23, "F50": g45.F34, "G50": g45.G34, "F21": g23.F21, "G21": g23.G21,
            "F23": g23.F23, "G23": g23.G23, "F30": g23.F34, "G30": g23.G34, "M1": m1,
            "T3": t3, **m}


# ---- stage 7: dynamics (Fig. 96) ------------------------------------------------------------

def reduced_inertia(links: dict, kin: dict) -> np.ndarray:
    """J_pr of formula 51 (L7156; L7573-7579).  As printed the translation of link 3's
    centre of mass is counted twice (E-X-IPR-1); corrected once."""
    m = masses(links)
    rcd, rde, rab = links["RCD"], links["RDE"], links["RAB"]
    vs4, _ = DSMVKT(kin["VD"], kin["ALD"], np.abs(kin["W4"]) * 0.3 * rde, kin["ALED"])
    vs2, _ = DSMVKT(kin["VA"], kin["ALA"], np.abs(kin["W2"]) * rab / 2.0, kin["ALBA"])
    w3 = kin["W3"]
    twice = m["M3"] * (w3 * 0.15 * rcd)**2 if get_mode() == "as-printed" else 0.0
    return (m["M5"] * kin["VE"]**2 + m["M4"] * vs4**2 + m["IS4"] * kin["W4"]**2 + twice
            + (m["IS3"] + m["M3"] * (0.15 * rcd)**2) * w3**2 + m["M2"] * vs2**2
            + m["IS2"] * kin["W2"]**2) / W1**2


def dynamics(links: dict, kin: dict, fo: dict) -> dict:
    """The equation of motion in energy form (DZKNDV, trapezoids), the flywheel (DMHVK)
    and the motion with it (DZKNDV again), L7622-7633."""
    ipr = reduced_inertia(links, kin)
    is1 = fo["IS1"]
    delta = DELTA_FLYWHEEL[get_mode()]
    n = len(ipr)
    try:
        # corrected mode (E-DZKNDV-2): without a flywheel the crank's inertia alone may not
        # keep a steady motion at W1 -- the machine stalls: WPR, EPR are NaN, and DEC,
        # which does not depend on ISC, is still returned for DMHVK.
        d1 = sarkp.DZKNDV(n, float(n), W1, is1, fo["M1"], ipr, on_error="nan")
        stalls = d1.status == sarkp.Status.REQUIREMENT
        if d1.status not in (sarkp.Status.OK, sarkp.Status.REQUIREMENT):
            sarkp.DZKNDV(n, float(n), W1, is1, fo["M1"], ipr)          # raises its error
        imh = sarkp.DMHVK(n, delta, is1, W1, d1.DEC)
        imh = float(imh[0] if isinstance(imh, tuple) else imh)
        d2 = sarkp.DZKNDV(n, float(n), W1, is1 + imh, fo["M1"], ipr)
    except SarkpError as exc:
        raise StageError(f"program X, stage 'dynamics' (Fig. 96): {exc}") from exc
    return {"FI1": kin["FI1"], "IPR": ipr, "AS": d1.AS, "ASUM": d1.ASUM, "EV": d1.EV,
            "DEC": d1.DEC, "WPR": d1.WPR, "EPR": d1.EPR, "WPRM": d2.WPR, "EPRM": d2.EPR,
            "IMH": imh, "DELTA": delta, "IS1": is1, "STALLS": stalls}



# ---- running the program ---------------------------------------------------------------------

def _cannot(stage: str, why: str) -> StageError:
    return StageError(f"program X, stage '{stage}' (Fig. {STAGE_FIGURE[stage]}): {why}")


def run(stages=None) -> dict:
    """Run the stages ``stages`` (default: all, in the book's order) in the current
    mode, with every stage they need; return ``{stage: results}`` for the stages run
    (needed stages included).  A stage that cannot run raises :class:`StageError`."""
    wanted = list(STAGES if stages is None else stages)
    for s in wanted:
        if s not in STAGES:
            raise ValueError(f"program X has no stage {s!r}; stages: {', '.join(STAGES)}")
    todo = [s for s in STAGES if s in wanted or any(s in NEEDS[w] for w in wanted)]
    done: dict = {}
    for s in todo:
        try:
            if s == "synthesis":
                done[s] = synthesis()
            elif s == "teeth":
                done[s] = teeth()
            elif s == "gears":
                done[s] = gears()
            elif s == "cam":
                done[s] = cam()
            elif s == "kinematics":
                done[s] = kinematics(done["synthesis"])
            elif s == "forces":
                done[s] = forces(done["synthesis"], done["kinematics"])
            elif s == "dynamics":
                done[s] = dynamics(done["synthesis"], done["kinematics"], done["forces"])
        except StageError as exc:
            users = [w for w in wanted if s in NEEDS[w]]
            if s in wanted or not users:
                raise
            raise _cannot(users[0], f"needs the results of stage '{s}', which failed: "
                                    f"{exc}") from exc
    return done



# ---- the figures as cells ----------------------------------------------------------------------

def stage_cells(stage: str, results: dict) -> dict:
    """The computed figure of ``stage`` as {(row, column): value}, keyed as in its data
    file (data/fig<N>.csv)."""
    out = {}
    if stage == "synthesis":
        s = results
        for name, key in (("RCD", "RCD_DSNTZR"), ("RDE", "RDE_DSNTZR"), ("FICD", "FICD1"),
                          ("ROA", "ROA"),
                          ("RAB", "RAB"), ("ROC", "ROC")):
            out[("1", name)] = float(s[key])
    elif stage == "cam":
        c = results
        out[("RKSH", "RKSH")] = float(c["RKSH"])
        for k in range(CAM_POINTS):
            row = str(k + 1)
            for name in ("FIK", "AT", "VT", "ST", "X", "Y", "RK", "DLT", "ROK"):
                out[(row, name)] = float(c[name][k])
            out[(row, "FIK_P")] = float(c["FIK"][k])
    elif stage == "kinematics":
        k = results
        for i in range(len(k["FI1"])):
            row = str(i + 1)
            for name in ("FI1", "FI2", "FICB", "XE", "FIDE", "XB", "YB", "W2", "W3", "VE",
                         "ALE", "W4", "E2", "E3", "E4", "AE", "BE"):
                out[(row, name)] = float(k[name][i])
            out[(row, "FI1_V")] = out[(row, "FI1_A")] = float(k["FI1"][i])
    elif stage in ("forces", "dynamics"):
        t = results
        for i in range(len(t["FI1"])):
            row = str(i + 1)
            for name, v in t.items():
                if isinstance(v, np.ndarray) and v.shape == t["FI1"].shape:
                    out[(row, name)] = float(v[i])
            if stage == "forces":
                out[(row, "FI1_G")] = out[(row, "FI1")]
        if stage == "dynamics":
            out[("IMH", "IMH")] = float(t["IMH"])
    elif stage == "teeth":
        for n, (args, r) in enumerate(results["variants"], 1):
            out[(str(n), "SHEMA")] = float(args["SHEMA"])
            out[(str(n), "KS")] = float(args["KS"])
            for name in ("Z1", "Z2", "Z3", "Z4"):
                if r is not None:                   # no admissible set: nothing printed
                    out[(str(n), name)] = float(getattr(r, name))
    elif stage == "gears":
        rename = {"ALFAW": "ALFA", "XY": "XU"}           # the printed names
        for block, (args, r) in results.items():
            for name, v in args.items():
                if name != "AAA":
                    out[(block, name)] = float(v)
            for name, v in r._asdict().items():
                out[(block, rename.get(name, name))] = float(v)
        out[("DKRKT", "AL12")] = out[("DKRKT", "ALFA")]
    return out

