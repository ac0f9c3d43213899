"""The book's example programs as runnable reproductions, and its printed figures.

Each program module has ``LISTING``, ``TITLE``, ``FIGURES`` (the figure numbers it
prints), ``cells()`` (the computed table as ``{(row, column): value}``, keyed as in the
figure's data file; program X, which prints seven figures, has ``figure_cells(N)``) and
``render()`` (the printout in the book's layout).  Both run in
the current mode (see :mod:`sarkp.modes`); the book's programs are meant to be run
as printed.
"""

from __future__ import annotations

import importlib

from .figures import Figure, compare, load_figure

#: listing -> module of sarkp.book
PROGRAMS = {
    "II.13": "prog_ii_13",
    "III.5": "prog_iii_5",
    "IV.15": "prog_iv_15",
    "V.5": "prog_v_5",
    "V.5-FLAT": "prog_v_5_flat",
    "VI.2": "prog_vi_2",
    "VI.3": "prog_vi_3",
    "VI.5": "prog_vi_5",
    "VI.6": "prog_vi_6",
    "VI.7": "prog_vi_7",
    "VI.8": "prog_vi_8",
    "VII.10": "prog_vii_10",
    "X": "prog_x",
}

#: figure number -> listing of the program that prints it
FIGURES = {
    "4": "II.13",
    "10": "III.5",
    "35": "V.5",
    "36": "V.5-FLAT",
    "39": "VI.2",
    "44": "VI.3",
    "46": "VI.5",
    "47": "VI.6",
    "48": "VI.7",
    "50": "VI.8",
}
# program X (chapter 10): the figures whose stages this build can run
FIGURES.update((f, "X") for f in importlib.import_module(".prog_x", __name__).FIGURES)


def program(listing: str):
    """The module of the program with this listing number (e.g. ``"II.13"``)."""
    key = listing.upper().replace("П", "II")
    if key not in PROGRAMS:
        raise ValueError(f"no book program {listing!r}; known: {', '.join(PROGRAMS)}")
    return importlib.import_module(f".{PROGRAMS[key]}", __name__)


def figure_program(number: str):
    """The program module that prints figure ``number``."""
    key = str(number)
    if key not in FIGURES:
        raise ValueError(f"no figure {number!r} is reproduced; known: {', '.join(FIGURES)}")
    return program(FIGURES[key])


def figure_cells(number: str) -> dict:
    """Figure ``number`` as reproduced in the current mode, ``{(row, column): value}``."""
    prog = figure_program(number)
    if hasattr(prog, "figure_cells"):
        return prog.figure_cells(str(number))
    return prog.cells()


def figure_evidence(number: str):
    """What the figure's program shows beyond its double-precision run, as-printed mode
    (:class:`sarkp.book.figures.Evidence`: fitted cells, the whole run in the book's
    arithmetic, IEEE single as a diagnostic, demonstrated causes); empty for a program
    that has none."""
    from .figures import Evidence
    from ..modes import as_printed
    prog = figure_program(number)
    if hasattr(prog, "evidence"):
        with as_printed():
            return prog.evidence(str(number))
    return Evidence()


__all__ = ["figure_evidence", "PROGRAMS", "FIGURES", "program", "figure_program", "figure_cells", "Figure",
           "load_figure", "compare"]
