"""Program III.5 (L1270-1296): the chapter-3 synthesis routines on the book's examples.

The book's main program calls, with AAA = 0 (print), in this order:

1. ``DSNTZR`` for a four-bar: LO = (0.9, 0.9, 0.9), L3 = 0.6, FI1 = (0.349, 1.047,
   1.745), FI3 = (0.524, 1.57, 2.793) (DATA, L1277-1278);
2. ``DSNTZ1(1.5, PI/6., (PI/6.)*5., 0.5, 0.75, -1., 0.0, ...)`` (L1281);
3. ``DSNTZ2(1.5, PI/6., 0.5, 0.75, PI/18., PI/3., 0.0, ...)`` (L1282);
4. ``DSNTZ3(0.2, 0.4, 0.6, 0.5, 0.8, 0.85, 1.343, 0.6, PI/3, PI/9., 0.0, ...)`` (L1283);
5. ``DSNTZR`` for a crank-slider, from a card READ with FORMAT(F6.3, 9F7.4) (L1292-1294).

The card is not printed; its values are the printed echo, with the third slider
position 0.535 where the OCR reads 0.525 (ERRATA E-FIG10-1: only 0.535 gives the
printed L1 = 0.399, L2 = 0.564).  Output: Fig. 10 (L1300-1369).

Known differences from the printed figure: DSNTZ1's printed 0.411 / 0.904 / 0.858 is
reproduced by neither mode (ERRATA E-DSNTZ1-4): as-printed runs the listing
(0.406 / 0.835 / 0.782, which misses the requested KW3), corrected runs the prose's
construction (0.390 / 0.722 / 0.650, which meets it); the three cells are marked not
reproducible in data/fig10.csv.  DSNTZ3's printed 0.401 / 0.0 / 0.574 comes from
implicit-INTEGER truncation, which as-printed mode repeats and corrected mode fixes
(0.412 / 0.425 / 0.575, E-DSNTZ3-2).
"""

from __future__ import annotations

from ..modes import book_pi
from ..synthesis import DSNTZ1, DSNTZ2, DSNTZ3, DSNTZR, dsntzr_report

LISTING = "III.5"
TITLE = "Synthesis of four-bar and crank-slider mechanisms (chapter 3 examples)"
FIGURES = ("10",)

#: DATA of the four-bar case (L1277-1278): CD = L3, FI1, FI3, AD = LO.
FOURBAR = {"LO": (0.9, 0.9, 0.9), "L3": 0.6, "FI1": (0.349, 1.047, 1.745),
           "FI3": (0.524, 1.57, 2.793)}
#: The crank-slider card (FORMAT(F6.3, 9F7.4), L1293), deduced from the printed echo.
SLIDER_CARD = {"L3": 0.150, "FI1": (0.3490, 1.0470, 1.7450),
               "FI3": (1.5700, 1.5700, 1.5700), "LO": (0.9500, 0.8250, 0.5350)}
#: Why a printed cell differs in corrected mode (see docs/ERRATA.md).
#: (The DSNTZ1 cells differ in both modes and carry E-DSNTZ1-4 in the figure data.)
CORRECTED_DIFFERENCES = {"*": "E-DSNTZ3-2 (DSNTZ3 cells: corrected typing)"}


def _calls():
    """The five calls of the program, as (case, routine, inputs)."""
    pi = book_pi()
    return [
        ("DSNTZR", DSNTZR, FOURBAR),
        ("DSNTZ1", DSNTZ1, {"KW3": 1.5, "FI31": pi / 6.0, "FI32": (pi / 6.0) * 5.0,
                            "L3": 0.5, "XD": 0.75, "Q": -1.0}),
        ("DSNTZ2", DSNTZ2, {"KW3": 1.5, "FI3": pi / 6.0, "L3": 0.5, "XD": 0.75,
                            "GMIN": pi / 18.0, "GMAX": pi / 3.0}),
        ("DSNTZ3", DSNTZ3, {"XB1": 0.2, "YB1": 0.4, "XB2": 0.6, "YB2": 0.5, "XC1": 0.8,
                            "YC1": 0.85, "XC2": 1.343, "YC2": 0.6, "FI1": pi / 3,
                            "ALC1": pi / 9.0}),
        ("DSNTZR-slider", DSNTZR, SLIDER_CARD),
    ]


def _run():
    """Run the program silently; yield (case, inputs, outputs as a dict)."""
    for case, routine, inputs in _calls():
        if routine is DSNTZR:
            out = DSNTZR(inputs["LO"], inputs["L3"], inputs["FI1"], inputs["FI3"], 1.0)
            yield case, inputs, {"L1": out.L1, "L2": out.L2}
        else:
            out = routine(**inputs, AAA=1.0)
            values = dict(out._asdict())
            yield case, inputs, values


def compute() -> dict:
    """Run the program in the current mode; return ``{(case, quantity): value}`` for every
    printed cell of Fig. 10 (input echoes included), keyed as in ``data/fig10.csv``."""
    cells = {}
    for case, inputs, outputs in _run():
        for name, value in inputs.items():
            if isinstance(value, tuple):
                for k, v in enumerate(value, 1):
                    cells[(case, f"{name}({k})")] = float(v)
            else:
                cells[(case, name)] = float(value)
        for name, value in outputs.items():
            cells[(case, name)] = float(value)
    return cells


def cells() -> dict:
    """The computed figure as {(row, column): value} (the common program interface)."""
    return compute()


def render() -> str:
    """The program's printout (Fig. 10) in the book's layout."""
    parts = []
    for case, inputs, outputs in _run():
        if case.startswith("DSNTZR"):
            parts.append(dsntzr_report(inputs["LO"], inputs["L3"], inputs["FI1"],
                                       inputs["FI3"], outputs["L1"], outputs["L2"]))
        else:
            routine = {"DSNTZ1": DSNTZ1, "DSNTZ2": DSNTZ2, "DSNTZ3": DSNTZ3}[case]
            spec = routine.spec
            values = [outputs[n] for n in spec.outputs]
            parts.append(spec.report(inputs, values))
    return "\n".join(parts)
