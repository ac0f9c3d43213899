"""The example of DGMZVN (listing VI.7, L4512-4631): Fig. 48, two internal meshes cut
by a shaper (z0 = 25, d0 = 75, x0 = 0.17, d_a0 = 83.8), calls L4650-4652.
Output: Fig. 48 (L4656-4730).  (а)'s AW = 52.4986 < A = 52.5 with XD = 0 is DUGINV's early
stop (E-DUGINV-1).
"""

from __future__ import annotations

from ..gears import DGMZVN

LISTING = "VI.7"
TITLE = "Internal involute mesh (DGMZVN example, chapter 6)"
FIGURES = ("48",)
CALLS = {"a": (3.0, 16.0, 51.0, 0.25, 0.25, 25.0, 75.0, 0.17, 83.8),
         "b": (3.0, 25.0, 31.0, 0.17, 1.2, 25.0, 75.0, 0.17, 83.8)}
CORRECTED_DIFFERENCES = {"*": "E-DUGINV-1 (corrected: the exact alpha_w and alpha_w02)"}


def cells() -> dict:
    out = {}
    for row, call in CALLS.items():
        result = DGMZVN(*call)
        for name, value in zip(result._fields, result):
            out[(row, name)] = float(value)
    return out


def render() -> str:
    return "\n".join(DGMZVN.spec.report({}, tuple(DGMZVN(*call))) for call in CALLS.values())
