"""The example of DCHRVC (listing VI.8, L4737-4824): Fig. 50, a worm pair with m = 8,
q = 10, z1 = 2, z2 = 39, a_w = 200, call L4829.  Output: Fig. 50 (L4831-4851).
"""

from __future__ import annotations

from ..gears import DCHRVC

LISTING = "VI.8"
TITLE = "Cylindrical worm gearing (DCHRVC example, chapter 6)"
FIGURES = ("50",)
CALL = (8.0, 10.0, 2.0, 39.0, 200.0)


def cells() -> dict:
    result = DCHRVC(*CALL)
    return {("1", name): float(value) for name, value in zip(result._fields, result)}


def render() -> str:
    return DCHRVC.spec.report({}, tuple(DCHRVC(*CALL)))
