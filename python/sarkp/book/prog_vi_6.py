"""The example of DGMZPC (listing VI.6, L4410-4454): Fig. 47, two external meshes.

The calls as printed (L4482-4483) are garbled: (а) lost one 0.5 and (б) has one 0.0 too
many (E-FIG47-2); XS = 1.0000 and E = 2.7280 prove
(а) ``DGMZPC(5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0, 0.0)`` and
(б) ``DGMZPC(7.0, 18.0, 60.0, (PI/180.0)*16.0, 0.0, 0.0, 100.0, 0.0)``.
Output: Fig. 47 (L4456-4476).  (б)'s AW = 283.9946 < A with XS = 0 is DUGINV's early stop
(E-DUGINV-1); its last digit needs the ES EVM's hexadecimal arithmetic (E-FIG47-1).
"""

from __future__ import annotations

from ..gears import DGMZPC
from ..modes import book_pi

LISTING = "VI.6"
TITLE = "External involute mesh (DGMZPC example, chapter 6)"
FIGURES = ("47",)
CORRECTED_DIFFERENCES = {"*": "E-DUGINV-1 (corrected: the exact alpha_w), E-DGMZPC-3 "
                              "(corrected: the helical gear's tip and base circles)"}


def _calls():
    return {"a": (5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0),
            "b": (7.0, 18.0, 60.0, (book_pi() / 180.0) * 16.0, 0.0, 0.0, 100.0)}


def cells() -> dict:
    out = {}
    for row, call in _calls().items():
        result = DGMZPC(*call)
        for name, value in zip(result._fields, result):
            out[(row, name)] = float(value)
    return out


def render() -> str:
    return "\n".join(DGMZPC.spec.report({}, tuple(DGMZPC(*call))) for call in _calls().values())
