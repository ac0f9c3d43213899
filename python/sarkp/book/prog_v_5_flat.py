"""The flat-faced follower of Fig. 36 (L3556-3612): program V.5's motion law with DPRFPL.

The book prints the table (Fig. 36, "the parameters of the mechanism with a flat-faced
follower realizing the same motion law", L3620) but not the program that printed it.
This variant runs V.5 up to label 7 (the motion law, :func:`sarkp.book.prog_v_5.motion_law`,
in the current mode) and then

    CALL DPRFPL(N, GAMMA, W, FI, D2SDT, DSDT, S, XPRFL, YPRFL, RPRFL, DELTA, RKRZVN, RKSH)

with GAMMA = PI/4: the printed radius 0.33810 = 0.6/tan(GAMMA) - S(16) = 0.6 - 0.26190
fixes tan(GAMMA) = 1, and the printed RKRZVN = 0.00000 at row 16 is the design point
ROK = 0 of that choice.  It prints the radius (F9.5) and a table FI XPRFL YPRFL RPRFL
DELTA RKRZVN (1X,6F11.5), as the figure shows.

The design is on the edge of realizability: ROK = 0 at rows 16 and 36 (the two minima of
the acceleration).  The ES EVM got ROK = -1.3e-6 m at row 36 (printed -0.00000, as
:func:`sarkp.book.prog_v_5.emulate` confirms); sarkp's runs get 1e-16 (corrected) and
+3e-8 (as-printed), so DPRFPL's flag NCONC stays 0.
"""

from __future__ import annotations

from .. import DPRFPL, get_mode
from ..modes import book_pi
from ..report import fortran_write
from . import es_evm
from .prog_v_5 import N, W, motion_law

LISTING = "V.5-FLAT"
TITLE = "Cam mechanism with a translating flat-faced follower (V.5's law with DPRFPL)"
FIGURES = ("36",)

COLUMNS = ("FI", "XPRFL", "YPRFL", "RPRFL", "DELTA", "RKRZVN")
FORMAT_RKSH = "(1X,'РАДИУС КУЛАЧКОВОЙ ШАЙБЫ-',F9.5)"
FORMAT_HEAD = "(1X,5X,'FI',8X,'XPRFL',6X,'YPRFL',6X,'RPRFL',6X,'DELTA',6X,'RKRZVN')"
FORMAT_ROW = "(1X,6F11.5)"

#: Why a printed cell differs in corrected mode (see docs/ERRATA.md).
CORRECTED_DIFFERENCES = {"*": "E-PI-1; E-FIG36-3 (exact pi, IEEE double arithmetic)"}


def gamma() -> float:
    """PI/4 of the current mode (the ES EVM's quotient as printed)."""
    if get_mode() == "as-printed":
        return es_evm.div(book_pi(), 4.0)
    return book_pi() / 4.0


def compute() -> dict:
    """Run the variant in the current mode: the law, RKSH, the profile, ROKMIN, NCONC."""
    law = motion_law()
    p = DPRFPL(N, gamma(), W, law["FI"], law["D2SDT"], law["DSDT"], law["S"])
    return {**law, "XPRFL": p.XA, "YPRFL": p.YA, "RPRFL": p.R1, "DELTA": p.DELTA,
            "RKRZVN": p.ROK, "RKSH": p.RKSH, "ROKMIN": p.ROKMIN, "NCONC": p.NCONC}


def cells() -> dict:
    """The computed Fig. 36 as {(row, column): value}, keyed as in data/fig36.csv."""
    t = compute()
    out = {("dims", "RKSH"): float(t["RKSH"])}
    for k in range(N):
        for name in COLUMNS:
            out[(str(k + 1), name)] = float(t[name][k])
    return out


def render() -> str:
    """The printout as Fig. 36 shows it."""
    t = compute()
    lines = [fortran_write(FORMAT_RKSH, [t["RKSH"]]), fortran_write(FORMAT_HEAD)]
    lines += [fortran_write(FORMAT_ROW, [t[c][k] for c in COLUMNS]) for k in range(N)]
    return "\n".join(lines)


#: the names (without suffix) of the pictures :func:`plots` writes
PICTURES = ("v5_flat_profile", "v5_flat_rok")


def plots(directory, *, format: str = "png", dpi: float | None = None) -> list:
    """Write the profile with the flat follower at the highest lift, and the radius of
    curvature against the cam angle, as ``format`` files (png, svg or pdf) in
    ``directory``; return their paths.  Needs matplotlib."""
    from pathlib import Path

    import numpy as np

    from .. import plot

    t = compute()
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    return [
        plot.save(plot.cam_profile(t["XPRFL"], t["YPRFL"], t["FI"], follower="flat",
                                   base_radius=t["RKSH"],
                                   title=plot.mode_title("V.5-FLAT: cam with a flat-faced "
                                                         "follower")),
                  Path(directory, PICTURES[0]), format=format, dpi=dpi),
        plot.save(plot.cam_diagrams(t["FI"], t["RKRZVN"],
                                    positions=np.arange(1, len(t["FI"]) + 1),
                                    title=plot.mode_title("V.5-FLAT: radius of curvature")),
                  Path(directory, PICTURES[1]), format=format, dpi=dpi)]


def evidence(number: str = "36"):
    """Fig. 36 run in the ES EVM's arithmetic (:func:`sarkp.book.prog_v_5.emulate` with
    the flat follower), for :func:`sarkp.book.figures.classify`."""
    from .figures import Evidence
    from .prog_v_5 import emulate
    e = emulate(flat=True)
    out = {("dims", "RKSH"): float(e["RKSH"])}
    for k in range(N):
        for name in COLUMNS:
            out[(str(k + 1), name)] = float(e[name][k])
    return Evidence(book=out)
