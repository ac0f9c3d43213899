"""The example of DGMTZK (listing VI.5, L4245-4308): Fig. 46, the dimensions of a gear
with m = 4 mm and z = 20 for four helix angles and shifts.

The calls are not printed; the echoes give ``DGMTZK(4.0, 20.0, BETA, X, 0.0, ...)`` with
(BETA, X) = (0, 0), (PI/18, 0), (PI/18, 1), (PI/18, -1).  The printed BETA = 0.1745 is
PI/18 = 0.174533 (E-FIG46-1: with 0.1745 itself SB, SA come out 7.1708, 3.5422 where the
figure has 7.1709, 3.5425).  Output: Fig. 46 (L4312-4392).

Corrected mode differs for the helical gears (E-DGMTZK-2: transverse thicknesses and the
tip diameter D + 2 (1 + x) m) and refuses the fourth gear, which is undercut
(E-DGMTZK-4).
"""

from __future__ import annotations

from ..errors import RequirementError
from ..gears import DGMTZK
from ..modes import book_pi

LISTING = "VI.5"
TITLE = "Dimensions of one gear (DGMTZK example, chapter 6)"
FIGURES = ("46",)
CORRECTED_DIFFERENCES = {"*": "E-DGMTZK-2 (corrected: helical gears in the transverse "
                              "section), E-DGMTZK-4 (corrected: the x = -1 gear is undercut)"}


def _runs():
    pi = book_pi()
    return [(0.0, 0.0), (pi / 18.0, 0.0), (pi / 18.0, 1.0), (pi / 18.0, -1.0)]


def _run():
    """Yield (inputs, outputs or the error)."""
    for beta, x in _runs():
        inputs = {"M": 4.0, "Z": 20.0, "BETA": beta, "X": x}
        try:
            yield inputs, DGMTZK(4.0, 20.0, beta, x)
        except RequirementError as err:
            yield inputs, err


def cells() -> dict:
    out = {}
    for k, (inputs, result) in enumerate(_run(), 1):
        for name, value in inputs.items():
            out[(str(k), name)] = float(value)
        if not isinstance(result, Exception):
            for name, value in zip(result._fields, result):
                out[(str(k), name)] = float(value)
    return out


def render() -> str:
    parts = []
    for inputs, result in _run():
        if isinstance(result, Exception):
            parts.append(f" (M = {inputs['M']}, Z = {inputs['Z']}, BETA = {inputs['BETA']:.4f},"
                         f" X = {inputs['X']}: {result})")
        else:
            parts.append(DGMTZK.spec.report(inputs, tuple(result)))
    return "\n".join(parts)
