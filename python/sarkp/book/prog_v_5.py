"""Program V.5 (L3358-3433): design of a cam mechanism with a translating knife-edge
follower.  Output: Fig. 35 (L3439-3554).

The book's main program sets (DATA and assignments, L3364-3384) the cam speed W = 5 1/s,
the amplitude of the follower's acceleration A1 = 15 m/s^2, the allowed pressure angle
ALFAD = 0.523 rad and BETA = 0.35 rad (COMMON /KLCHK/, INDEX = 1), the phase angles
FIU = FIV = 100 degrees (rise and return), FID = 50 degrees (dwell), and N = 51 cam
angles FI = 0, DFI, ... with DFI = 5 degrees, accumulated ``C = C + DFI`` (L3385-3387).
The motion law (5.7), as the loop DO 2 programs it (L3388-3402):

* ``FI <= FIU``: ``D2SDT = A1 sin(FI/TK1)``, TK1 = FIU/(2 PI) (one sine period);
* ``FI <= FIU + FID``: ``D2SDT = 0``;
* else: ``D2SDT = -A2 sin((FI - (FIU + FID))/TK2)``, TK2 = FIV/(2 PI), A2 = A1 FIU/FIV.

Then DINTGR (trapezoids) twice, divided by W, gives DSDT and S; DKLCHK the main
dimensions RKSH, EXCTST; DPRFLP the profile; the program prints both tables.

Printed errors corrected in both modes (docs/ERRATA.md): ``DATA PI/31.4159/``
(E-V5-1), the 12th argument of DPRFLP ``A`` for ``DELTA`` (E-V5-2), ``RKRVZN``/``ZN``
for RKRZVN (E-V5-3), lost continuation marks and apostrophes in COMMON and the FORMATs
(E-V5-4).  The prose's phase angles and ALFAD (L3332, L3620) are not the program's
(E-V5-5).

As-printed mode runs the program as the ES EVM did: PI = 3.14159, and the main program's
own arithmetic (its constants, the accumulated FI, the acceleration formula and the
divisions by W) in the machine's truncating hexadecimal REAL*4 (:mod:`sarkp.book.es_evm`);
the library routines run in double precision.  That puts FI(21) just below FIU (so row 21
is still on the rise, D2SDT = -0.00030) and FI(31) on the dwell.  The cells that need the
machine's arithmetic inside DINTGR, DKLCHK and DPRFLP as well (rounding-edge cells, and
the radius of curvature next to its sign change, 97.61586 at row 49) are marked in
data/fig35.csv with E-FIG35-8 and E-FIG35-9; :func:`emulate` runs the whole printed
program in that arithmetic and is the evidence for them.  Corrected mode: exact pi and
FI = (K-1) pi/36.
"""

from __future__ import annotations

import math

import numpy as np

from .. import DINTGR, DKLCHK, DPRFLP, get_mode
from ..modes import book_pi
from ..report import fortran_write
from . import es_evm

LISTING = "V.5"
TITLE = "Cam mechanism with a translating knife-edge follower (Fig. 34 motion law)"
FIGURES = ("35",)

N = 51                          # DATA PI, N/3.14159, 51/ (L3368, E-V5-1)
W = 5.0                         # L3369
A1 = 15.0                       # L3370
ALFAD = 0.523                   # L3371
BETA = 0.35                     # L3372

KINEMATICS = ("FI", "D2SDT", "DSDT", "S")
PROFILE = ("FI", "XPRFL", "YPRFL", "RPRFL", "DELTA", "ALFA", "RKRZVN")

#: Why a printed cell differs in corrected mode (see docs/ERRATA.md).
CORRECTED_DIFFERENCES = {"*": "E-PI-1; E-FIG35-8 (exact pi, IEEE double arithmetic)"}

TRAPEZOIDS = " ИСПОЛЬЗУЕТСЯ МЕТОД ТРАПЕЦИЙ"      # DINTGR's message (L457), once per call
FORMAT_8 = "(' КИНЕМАТИЧЕСКИЕ ХАРАКТЕРИСТИКИ ДВИЖЕНИЯ ТОЛКАТЕЛЯ')"
FORMAT_9 = "(1X,5X,'FI',10X,'D2SDT',7X,'DSDT',10X,'S')"
FORMAT_10 = "(1X,4F12.5)"
FORMAT_11 = ("(1X,'ОСНОВНЫЕ РАЗМЕРЫ КУЛАЧКА: РАДИУС КУЛАЧКОВОЙ ШАЙБЫ -',F9.5,"
             "' ЭКСЦЕНТРИСИТЕТ -',F9.5//10X,'ХАРАКТЕРИСТИКИ ПРОФИЛЯ КУЛАЧКА')")
FORMAT_15 = ("(1X,5X,'FI',8X,'XPRFL',6X,'YPRFL',6X,'RPRFL',6X,'DELTA',6X,'ALFA',6X,"
             "'RKRZVN')")
FORMAT_16 = "(1X,7F11.5)"


# ---- the main program's own arithmetic ----------------------------------------------------

def _mul(a, b):
    return es_evm.real4(es_evm.real4(a) * es_evm.real4(b))


def _sub(a, b):
    return es_evm.real4(es_evm.real4(a) - es_evm.real4(b))


def motion_law() -> dict:
    """FI, D2SDT, DSDT, S of the loops DO 2, 6, 7 (L3385-3411), in the current mode."""
    pi = book_pi()
    if get_mode() == "as-printed":
        r4, add, div = es_evm.real4, es_evm.add, es_evm.div
        pi = r4(pi)
        fiu = div(_mul(5.0, pi), 9.0)                           # L3377-3384
        fid = _mul(div(pi, 18.0), 5.0)
        fiv = div(_mul(5.0, pi), 9.0)
        dfi = div(pi, 36.0)
        tk1 = div(div(fiu, 2.0), pi)
        tk2 = div(div(fiv, 2.0), pi)
        a2 = div(_mul(A1, fiu), fiv)
        fiud = add(fiu, fid)
        c, fi, acc = r4(-dfi), [], []
        for _ in range(N):
            c = add(c, dfi)
            fi.append(c)
            if c <= fiu:
                acc.append(_mul(A1, float(es_evm.SIN(div(c, tk1)))))
            elif c <= fiud:
                acc.append(0.0)
            else:
                acc.append(-_mul(a2, float(es_evm.SIN(div(_sub(c, fiud), tk2)))))
        fi, acc = np.array(fi), np.array(acc)
        dsdt = np.array([div(x, W) for x in DINTGR(N, dfi, 2, acc).FINT])
        s = np.array([div(x, W) for x in DINTGR(N, dfi, 2, dsdt).FINT])
        return {"FI": fi, "D2SDT": acc, "DSDT": dsdt, "S": s, "DFI": dfi}
    fiu, fid, fiv, dfi = 5.0 * pi / 9.0, pi / 18.0 * 5.0, 5.0 * pi / 9.0, pi / 36.0
    tk1, tk2, a2 = fiu / 2.0 / pi, fiv / 2.0 / pi, A1 * fiu / fiv
    fi = np.arange(N) * dfi
    acc = np.where(fi <= fiu, A1 * np.sin(fi / tk1),
                   np.where(fi <= fiu + fid, 0.0, -a2 * np.sin((fi - (fiu + fid)) / tk2)))
    dsdt = DINTGR(N, dfi, 2, acc).FINT / W
    s = DINTGR(N, dfi, 2, dsdt).FINT / W
    return {"FI": fi, "D2SDT": acc, "DSDT": dsdt, "S": s, "DFI": dfi}


def compute() -> dict:
    """Run the program in the current mode: the kinematics, RKSH, EXCTST and the profile
    (with DPRFLP's extensions ALFMAX, NOVER against ALFAD)."""
    law = motion_law()
    dims = DKLCHK(N, law["S"], law["DSDT"], law["D2SDT"], ALFAD, BETA, W)   # L3412
    profile = DPRFLP(N, dims.RO, dims.EXCST, W, law["FI"], law["D2SDT"], law["DSDT"],
                     law["S"], ALFAD)                                        # L3413-3414
    return {**law, "RKSH": dims.RO, "EXCTST": dims.EXCST, "XPRFL": profile.XA,
            "YPRFL": profile.YA, "RPRFL": profile.R1, "DELTA": profile.DELTA,
            "ALFA": profile.ALFA, "RKRZVN": profile.ROK, "ALFMAX": profile.ALFMAX,
            "NOVER": profile.NOVER}


def _cells(table) -> dict:
    out = {("dims", "RKSH"): float(table["RKSH"]), ("dims", "EXCTST"): float(table["EXCTST"])}
    for k in range(N):
        row = str(k + 1)
        for name in KINEMATICS:
            out[(row, name)] = float(table[name][k])
        out[(row, "FI_P")] = float(table["FI"][k])
        for name in PROFILE[1:]:
            out[(row, name)] = float(table[name][k])
    return out


def cells() -> dict:
    """The computed Fig. 35 as {(row, column): value}, keyed as in data/fig35.csv."""
    return _cells(compute())


def render() -> str:
    """The program's printout in the book's layout (two DINTGR messages, FORMATs 8-16)."""
    t = compute()
    lines = [TRAPEZOIDS, TRAPEZOIDS, fortran_write(FORMAT_8), fortran_write(FORMAT_9)]
    lines += [fortran_write(FORMAT_10, [t[c][k] for c in KINEMATICS]) for k in range(N)]
    lines.append(fortran_write(FORMAT_11, [t["RKSH"], t["EXCTST"]]))
    lines.append(fortran_write(FORMAT_15))
    lines += [fortran_write(FORMAT_16, [t[c][k] for c in PROFILE]) for k in range(N)]
    return "\n".join(lines)


# ---- the whole printed program in the ES EVM's arithmetic (evidence, not the library) ----

_R4 = es_evm.Real4
_SIN, _COS, _TAN, _ATAN, _SQRT = es_evm.SIN, es_evm.COS, es_evm.TAN, es_evm.ATAN, es_evm.SQRT


def emulate(flat: bool = False) -> dict:
    """The printed program V.5 (with the corrections E-V5-1..3, E-DPRFLP-1, -2), DINTGR,
    DKLCHK and DPRFLP (``flat``: DPRFPL with GAMMA = PI/4) statement by statement in the
    ES EVM's truncating hexadecimal REAL*4, left to right as written; library functions
    are the exact values truncated.  Independent of sarkp's Fortran: the evidence for the
    cells of Figs. 35-36 that only the machine's arithmetic explains."""
    R = _R4
    pi, w, a1, alfad, beta = R(3.14159), R(5.0), R(15.0), R(0.523), R(0.35)
    fiu = R(5.0) * pi / R(9.0)
    fid = pi / R(18.0) * R(5.0)
    fiv = R(5.0) * pi / R(9.0)
    dfi = pi / R(36.0)
    c = -dfi
    tk1 = fiu / R(2.0) / pi
    tk2 = fiv / R(2.0) / pi
    a2 = a1 * fiu / fiv
    fi, acc = [], []
    for _ in range(N):
        c = c + dfi
        fi.append(c)
        if c <= fiu:
            acc.append(a1 * _SIN(c / tk1))
        elif c <= fiu + fid:
            acc.append(R(0.0))
        else:
            acc.append(-a2 * _SIN((c - (fiu + fid)) / tk2))

    def dintgr(h, y):                                   # II.1, NOMER = 2 (L469-471)
        out = [R(0.0)]
        for k in range(1, N):
            out.append(out[k - 1] + R(0.5) * h * (y[k - 1] + y[k]))
        return out

    dsdt = [x / w for x in dintgr(dfi, acc)]
    s = [x / w for x in dintgr(dfi, dsdt)]
    table = {"FI": fi, "D2SDT": acc, "DSDT": dsdt, "S": s}
    if flat:                                            # V.3, L3240-3255
        mnmm, L = acc[0], 0
        for k in range(N):
            if acc[k] < mnmm:
                mnmm, L = acc[k], k
        d2 = mnmm / (w * w)
        rksh = R(abs(-(d2 / _TAN(pi / R(4.0)) + s[L])))
        cols = {n: [] for n in ("XPRFL", "YPRFL", "RPRFL", "DELTA", "RKRZVN")}
        for k in range(N):
            ds, d2 = dsdt[k] / w, acc[k] / (w * w)
            xa = (rksh + s[k]) * _SIN(fi[k]) + ds * _COS(fi[k])
            ya = (rksh + s[k]) * _COS(fi[k]) - ds * _SIN(fi[k])
            cols["XPRFL"].append(xa)
            cols["YPRFL"].append(ya)
            cols["RPRFL"].append(_SQRT((rksh + s[k]) * (rksh + s[k]) + ds * ds))
            cols["DELTA"].append(_ATAN(xa / ya))
            cols["RKRZVN"].append(rksh + s[k] + d2)
        return {**table, **cols, "RKSH": rksh}
    mksmm, L = dsdt[0], 0                               # V.1, L3083-3093
    for k in range(N):
        if dsdt[k] > mksmm:
            mksmm, L = dsdt[k], k
    ifi = mksmm / w
    ro = (ifi / _TAN(alfad) - s[L]) * _SIN(alfad) / _SIN(alfad + beta)
    e = ro * _SIN(beta)
    cols = {n: [] for n in PROFILE[1:]}
    for k in range(N):                                  # V.2, L3175-3187
        ds, d2 = dsdt[k] / w, acc[k] / (w * w)
        xa = e * _COS(fi[k]) + (ro + s[k]) * _SIN(fi[k])
        ya = -e * _SIN(fi[k]) + (ro + s[k]) * _COS(fi[k])
        alfa = _ATAN((ds - e) / (ro + s[k]))
        cc = ro + s[k]
        ca = _COS(alfa)
        omega = (cc * ca + ds * _SIN(alfa) * (ca * ca) - d2 * (ca * ca * ca)) / (cc * cc)
        cols["XPRFL"].append(xa)
        cols["YPRFL"].append(ya)
        cols["RPRFL"].append(_SQRT(xa * xa + ya * ya))
        cols["DELTA"].append(_ATAN(xa / ya))
        cols["ALFA"].append(alfa)
        cols["RKRZVN"].append(R(1.0) / omega)
    return {**table, **cols, "RKSH": ro, "EXCTST": e}


def emulated_cells() -> dict:
    """Fig. 35 as the ES EVM computed it (see :func:`emulate`), keyed as :func:`cells`."""
    return _cells({k: (np.array(v, dtype=float) if isinstance(v, list) else float(v))
                   for k, v in emulate().items()})


#: the names (without suffix) of the pictures :func:`plots` writes
PICTURES = ("v5_profile", "v5_alfa_rok")


def plots(directory, *, format: str = "png", dpi: float | None = None) -> list:
    """Write the profile (with the base circle and the follower at the highest lift) and
    the pressure angle and radius of curvature against the cam angle as ``format`` files
    (png, svg or pdf) in ``directory``; return their paths.  Needs matplotlib."""
    from pathlib import Path

    from .. import plot

    t = compute()
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    numbers = np.arange(1, len(t["FI"]) + 1)            # the rows K of Fig. 35
    return [
        plot.save(plot.cam_profile(t["XPRFL"], t["YPRFL"], t["FI"], follower="knife",
                                   offset=t["EXCTST"],
                                   base_radius=math.hypot(t["RKSH"], t["EXCTST"]),
                                   title=plot.mode_title(
                                       f"V.5: cam with a knife-edge follower, offset e = "
                                       f"{t['EXCTST'] * 1000:.2f} mm")),
                  Path(directory, PICTURES[0]), format=format, dpi=dpi),
        plot.save(plot.cam_diagrams(t["FI"], t["RKRZVN"], t["ALFA"], ALD=ALFAD,
                                    positions=numbers,
                                    title=plot.mode_title("V.5: pressure angle and radius "
                                                          "of curvature")),
                  Path(directory, PICTURES[1]), format=format, dpi=dpi)]


def evidence(number: str = "35"):
    """Fig. 35 run in the ES EVM's arithmetic (:func:`emulate`), for
    :func:`sarkp.book.figures.classify`."""
    from .figures import Evidence
    return Evidence(book=emulated_cells())
