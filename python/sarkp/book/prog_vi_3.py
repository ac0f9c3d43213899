"""The example of DKRKT (listing VI.3, L4019-4137): Fig. 44, five choices of the shift
coefficients for m = 4 mm, z1 = 13, z2 = 34 (text L4219-4221).

The calls are not printed; the echoed headers give them:
``DKRKT(4.0, 13.0, 34.0, AW, SDVIG, 0.0, X1, X2, ALFAW)`` with (AW, SDVIG) = (100, 0),
(0, 1), (0, 3), (110, 0), (0, 2).  Each run prints the header (FORMAT 25), the result
(FORMAT 52) or a message, and the dump of FORMAT 55.  Output: Fig. 44 (L4166-4197).

The fourth run (AW = 110) gives pointed teeth: the book prints its message 21 and the
rejected coefficients.  As printed, the program does what the printed code does: it
prints the message and computes the dump's X1, X2, XS and ALFAW by the listing's formulas
(:func:`rejected_run`), with a :class:`PointedTeethWarning`; corrected, sarkp refuses the
call (RequirementError) and those cells are not computed (ERRATA E-FIG44-1).  As printed, DUGINV stops at
TCHNST = 0.00001 (E-DKRKT-3): ALFAW = 0.3490 for zero shifts; corrected mode gives the
exact 0.3491 (E-DUGINV-1).
"""

from __future__ import annotations

import warnings

from ..errors import RequirementError
from ..gears import DKRKT, dkrkt_limits, dkrkt_report
from ..modes import get_mode

LISTING = "VI.3"
TITLE = "Shift coefficients and the operating angle (DKRKT example, chapter 6)"
FIGURES = ("44",)

M, Z1, Z2 = 4.0, 13.0, 34.0
#: (AW, SDVIG) of the five runs, in print order.
RUNS = ((100.0, 0), (0.0, 1), (0.0, 3), (110.0, 0), (0.0, 2))
#: the book's message number for sarkp's reasons (FORMATs 50, 51, 54 after labels 20-22)
_MESSAGES = (("undercut", 50), ("pointed", 51), ("no system of shifts", 54))
CORRECTED_DIFFERENCES = {"ALFAW": "E-DUGINV-1 (corrected: the exact root)",
                         "ALFAW/55": "E-DUGINV-1 (corrected: the exact root)"}


class PointedTeethWarning(UserWarning):
    """As printed, a run the corrected library refuses (pointed teeth) is computed all the
    same, as the printed code computes it (E-FIG44-1)."""


def _run():
    """Yield (inputs, outputs or None, FORMAT of the line after the header)."""
    for aw, sdvig in RUNS:
        inputs = {"M": M, "Z1": Z1, "Z2": Z2, "AW": aw, "SDVIG": sdvig}
        try:
            yield inputs, DKRKT(M, Z1, Z2, aw, sdvig), 52
        except RequirementError as err:
            # the reason opens the message (what follows it may name the other limit)
            reason = str(err).partition(": ")[2]
            fmt = next((f for word, f in _MESSAGES if reason.startswith(word)), 54)
            yield inputs, None, fmt


def cells() -> dict:
    """The computed figure as ``{(run, column): value}``, keyed as in data/fig44.csv."""
    out = {}
    for k, (inputs, result, fmt) in enumerate(_run(), 1):
        row = str(k)
        for name, value in inputs.items():
            out[(row, name)] = float(value)
        out[(row, "FORMAT")] = float(fmt)
        lim = dkrkt_limits(M, Z1, Z2, inputs["AW"])
        for name in ("AO", "X1Z", "X2Z", "X1P", "X2P", "Y"):
            out[(row, name)] = float(lim[name])
        out[(row, "SDVIG/55")] = float(inputs["SDVIG"])
        out[(row, "AW/55")] = inputs["AW"]
        if result is not None:
            for name, value in zip(("X1", "X2", "ALFAW"), result):
                out[(row, name)] = out[(row, name + "/55")] = float(value)
            out[(row, "XS")] = float(result.X1 + result.X2)
        elif fmt == 51 and get_mode() == "as-printed":
            # E-FIG44-1: the printed code prints message 21 and dumps what it computed
            warnings.warn(f"DKRKT run {row} (AW = {inputs['AW']}): pointed teeth; computed "
                          f"as the printed code computes it (as-printed mode, E-FIG44-1)",
                          PointedTeethWarning, stacklevel=2)
            got = rejected_run(inputs["AW"])
            for column, name in (("ALFAW/55", "ALFAW"), ("XS", "XS"), ("X1/55", "X1"),
                                 ("X2/55", "X2")):
                out[(row, column)] = float(got[name])
    return out


def render() -> str:
    """The printout (Fig. 44) in the book's layout."""
    parts = []
    for k, (inputs, result, fmt) in enumerate(_run(), 1):
        if result is None and fmt == 51 and get_mode() == "as-printed":
            # E-FIG44-1: the printed code dumps what it computed after message 21
            warnings.warn(f"DKRKT run {k} (AW = {inputs['AW']}): pointed teeth; computed "
                          f"as the printed code computes it (as-printed mode, E-FIG44-1)",
                          PointedTeethWarning, stacklevel=2)
            got = rejected_run(inputs["AW"])
            result = (got["X1"], got["X2"], got["ALFAW"])
        parts.append(dkrkt_report(inputs, result, None if fmt == 52 else fmt))
    return "\n".join(parts)


def rejected_run(aw: float = 110.0) -> dict:
    """E-FIG44-1: what the listing computes (L4053-4060, the ALFAW statement with its
    parenthesis where formula (6.12) has it, PI = 3.14159) for a run that sarkp refuses
    (pointed teeth) and the book prints all the same: ALFAW, XS, X1, X2."""
    import math
    pi = 3.14159
    alfao = pi / 9.0
    zs = Z1 + Z2
    y = (aw - M * zs / 2.0) / M
    alfaw = math.acos(0.5 * zs * math.cos(alfao) / (y + 0.5 * zs))
    xs = zs * (math.tan(alfaw) - alfaw - math.tan(alfao) + alfao) / (2.0 * math.tan(alfao))
    x1 = 0.5 * (xs - (Z2 - Z1) / zs * y)
    return {"ALFAW": alfaw, "XS": xs, "X1": x1, "X2": xs - x1}
