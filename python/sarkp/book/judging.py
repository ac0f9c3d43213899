"""The choice of the one arithmetic model of the book's machine (docs/judging.md).

The ES EVM computed in REAL*4, a hexadecimal float of 6 hex digits whose operations
truncate (:mod:`sarkp.book.es_evm`).  How its library functions delivered their results
is not known digit for digit: each of SIN, COS, TAN, ATAN, ACOS, SQRT may truncate or
round its exact value.  That gives 64 candidate models.  Each is judged by running every
emulated program whole under it and counting the printed cells the runs reproduce
(:func:`model_counts`); the model with the most is the book's (ties: the fewer rounding
functions), chosen once for every figure.  EXP is called by no emulated program, so no
printed cell can tell how it rounds.

``python scripts/choose_arithmetic.py`` prints the whole table; :data:`es_evm.ROUNDED`
holds the choice.
"""

from __future__ import annotations

from itertools import combinations

from . import es_evm
from .figures import compare, load_figure, within_half

#: the figures whose programs run whole in the ES EVM's arithmetic (Fig. 89: the cam's
#: loop DO 5 is that arithmetic in as-printed mode itself)
EMULATED = ("4", "35", "36", "47", "48", "87", "89", "91", "94", "96")


def candidates() -> list:
    """Every subset of :data:`es_evm.FUNCTIONS` (the functions that round), fewest first."""
    return [frozenset(c) for k in range(len(es_evm.FUNCTIONS) + 1)
            for c in combinations(es_evm.FUNCTIONS, k)]


def model_counts(rounding) -> dict:
    """``{figure: (reproduced, fixed, broken)}`` with the library functions ``rounding``
    rounding: the counted cells (less the inputs of a fit: the cells of Fig. 91 that the
    link lengths are fitted to are no evidence) the whole run in the book's arithmetic
    reproduces, and
    of them the cells double precision misses (fixed), and the cells double precision
    reproduces that it misses (broken).  Fig. 89's run is its as-printed run."""
    from .. import as_printed
    from . import figure_cells, figure_evidence
    out = {}
    with es_evm.library_model(rounding), as_printed():
        for number in EMULATED:
            figure = load_figure(number)
            double = compare(figure, figure_cells(number))
            evidence = figure_evidence(number)
            run = figure_cells(number) if number == "89" else evidence.book
            got = fixed = lost = 0
            for c in double:
                key = (c.cell.row, c.cell.column)
                if (c.computed is None or c.cell.role == "repeat" or not c.cell.counterpart
                        or key not in run or key in evidence.fitted):
                    continue                  # not counted, or an input of a fit
                ok = within_half(c.cell, run[key])
                got += ok
                fixed += ok and not c.matches
                lost += c.matches and not ok
            out[number] = (got, fixed, lost)
    return out


def score(counts: dict) -> int:
    """The evidence for a model: the cells its whole runs reproduce, all figures."""
    return sum(got for got, _, _ in counts.values())


def choose(models=None) -> tuple:
    """``(model, {model: counts})``: the candidate with the highest :func:`score`, ties
    to the fewer rounding functions (the machine's arithmetic truncates)."""
    table = {m: model_counts(m) for m in (candidates() if models is None else models)}
    best = max(table, key=lambda m: (score(table[m]), -len(m)))
    return best, table
