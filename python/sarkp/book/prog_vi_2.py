"""Program VI.2 (L3808-3852): DZBPL on nineteen planetary trains (Fig. 39).

The main program sets the COMMON /ZUB/ inputs ZKRN = 20, ZKRW = 85, DZ = 8 (L3815-3817),
sarkp's values too, and calls ``DZBPL(KS, P, Q, L2, L3, Z1MIN, Z1MAX, SHEMA)`` nineteen
times: nine trains of scheme 1 (Fig. 38 а, б), five of scheme 2 (в), five of scheme 3 (г).
Each call prints the tooth numbers (FORMAT 11) or the message of FORMAT 10 when no set
is admissible.  Output: Fig. 39 (L3852-3936).

As printed, every printed tooth set comes back (ERRATA E-DZBPL-1, E-DZBPL-2 restore
what the run must have had; E-FIG39-1, E-FIG39-2 are two misprints of the figure, and
E-FIG39-3 its two missing messages).  Corrected mode checks what the text asks for
(ratio, coaxiality, assembly, neighbourhood: E-DZBPL-3..5) and finds other sets or none:
the printed 38/22/25/41 is not coaxial, the printed scheme-3 sets have overlapping
planets, and several printed ratios are only approximate.
"""

from __future__ import annotations

from ..errors import RequirementError
from ..gears import DZBPL, dzbpl_report

LISTING = "VI.2"
TITLE = "Tooth numbers of multi-satellite planetary trains (DZBPL, chapter 6)"
FIGURES = ("39",)

#: The calls of L3823-3850: (KS, P, Q, L2, L3, Z1MIN, Z1MAX, SHEMA).
CALLS = (
    (2, 4, 1, 1, 1, 13, 35, 1), (3, 4, 1, 1, 1, 13, 35, 1), (2, 4, 1, 2, 1, 13, 35, 1),
    (2, 4, 1, 4, 3, 13, 35, 1), (2, 4, 1, 4, 3, 13, 45, 1), (3, 4, 1, 4, 3, 13, 45, 1),
    (2, 11, 1, 4, 3, 13, 35, 1), (3, 23, 2, 4, 3, 13, 35, 1), (3, 26, 5, 1, 1, 17, 43, 1),
    (3, -19, 1, 25, 6, 13, 30, 2), (2, -19, 1, 25, 6, 13, 30, 2), (3, 19, 1, 25, 6, 13, 30, 2),
    (2, 1, 19, 7, 8, 15, 50, 2), (2, 1, 10, 3, 1, 13, 50, 2),
    (2, 1, 10, 3, 2, 20, 200, 3), (2, 1, 10, 2, 3, 20, 200, 3), (2, 1, 25, 4, 3, 30, 200, 3),
    (2, 1, 25, 3, 4, 30, 200, 3), (3, 1, 13, 2, 3, 20, 200, 3),
)
#: Why a printed cell differs in corrected mode (see docs/ERRATA.md).
CORRECTED_DIFFERENCES = {"*": "E-DZBPL-3, E-DZBPL-4, E-DZBPL-5 (corrected: exact ratio, "
                              "coaxiality, neighbourhood)"}


def _run():
    """Yield (call number, the call, the tooth numbers or None)."""
    for k, call in enumerate(CALLS, 1):
        try:
            result = tuple(DZBPL(*call))
        except RequirementError:
            result = None
        yield k, call, result


def cells() -> dict:
    """The computed figure as ``{(call, column): value}``, keyed as in data/fig39.csv."""
    out = {}
    for k, call, result in _run():
        row = str(k)
        out[(row, "found")] = 0.0 if result is None else 1.0
        if result is not None:
            out[(row, "SHEMA")] = float(call[7])
            out[(row, "KS")] = float(call[0])
            for name, value in zip(("Z1", "Z2", "Z3", "Z4"), result):
                out[(row, name)] = float(value)
    return out


def render() -> str:
    """The program's printout (Fig. 39) in the book's layout."""
    return "\n".join(dzbpl_report(call[0], call[7], result) for _, call, result in _run())
