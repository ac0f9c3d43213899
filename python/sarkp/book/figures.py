"""Printed figures as data, and the cell-by-cell comparison with a reproduction.

A figure is a CSV file in ``sarkp/book/data`` named ``fig<N>.csv``: ``#`` lines first
(figure, caption, program, book lines, printed format; ``printed input columns`` and
``repeated columns``), then one row per printed cell:

``row,column,printed,decimals,line,ocr,errata,reproducible``

``printed`` is the value as printed with OCR errors corrected (``ocr`` then holds what
the OCR read), ``decimals`` the digits printed after the point, ``errata`` the ids of
docs/ERRATA.md that discuss the cell (an id alone explains nothing: :func:`classify` says
what is shown), ``reproducible`` = ``no`` where the printed program computed the cell in
a way no run is known to repeat (the ``errata`` say why; the cell is compared all the
same), ``none`` where the program has no counterpart of the cell (only Fig. 4's VD: the
printed column is not what the listing computes for any input, E-II13-2),
``magnitude`` where only its absolute value is reproducible (its sign came from what no
run can repeat; the cell's ``errata`` say why): the diff then compares magnitudes.

How a cell is judged (docs/judging.md): a cell is within half a unit when the exact
difference between the computed binary value and the printed decimal is at most half a
unit of the last printed digit; an exact tie counts as the printer's rounding, half away
from zero, would print it (:func:`within_half`).  Every compared cell is exactly one of
(:func:`classify`): a printed input (the angle grid a program steps through; a column
that prints another one again is not counted at all); reproduced (double precision);
fitted (an input was fitted to it: program X's link lengths, scripts/fit_x_links.py);
reproduced under the book's arithmetic (the whole program run in the ES EVM's REAL*4 with
the one library model :data:`sarkp.book.es_evm.ROUNDED` reproduces it); differs, cause
shown (the cause, applied by shipped code, moves it within half a unit, or a printed
identity proves the print a misprint); differs, no cause shown.  Each figure also counts
the cells that the whole run in the book's arithmetic breaks (reproduced in double
precision, missed by it).  IEEE single is shown as a diagnostic, never counted.
"""

from __future__ import annotations

import csv
import math
from decimal import Decimal
from dataclasses import dataclass, field
from importlib import resources


@dataclass(frozen=True)
class Cell:
    row: str
    column: str
    printed: str
    decimals: int
    line: int
    ocr: str
    errata: str
    reproducible: bool
    magnitude: bool = False          # only |printed| is reproducible (reproducible is False)
    role: str = ""                   # "input": a printed input; "repeat": prints a column again
    counterpart: bool = True         # False: the program has no counterpart of the cell

    @property
    def value(self) -> float:
        return float(self.printed)

    @property
    def unit(self) -> float:
        """One unit of the last printed digit."""
        return 10.0 ** -self.decimals


@dataclass
class Figure:
    number: str
    meta: dict
    cells: list = field(default_factory=list)


def load_figure(number: str) -> Figure:
    """Read ``fig<number>.csv`` from the package data."""
    text = resources.files("sarkp.book").joinpath("data", f"fig{number}.csv").read_text(
        encoding="utf-8")
    meta, body = {}, []
    for line in text.splitlines():
        if line.startswith("#"):
            key, _, value = line[1:].partition(":")
            if value and not key.startswith(" "):
                meta[key.strip()] = value.strip()
            elif value and key.strip() and key.strip() not in meta:
                meta[key.strip()] = value.strip()
        elif line.strip():
            body.append(line)
    figure = Figure(str(number), meta)
    # a token is a column, or ROW:COLUMN for one cell
    inputs = set(meta.get("printed input columns", "").split())
    repeats = set(meta.get("repeated columns", "").split())
    for r in csv.DictReader(body):
        kind = r["reproducible"].strip().lower()
        if kind not in ("yes", "no", "magnitude", "none"):
            raise ValueError(f"fig{number}.csv row {r['row']} {r['column']}: reproducible "
                             f"must be yes, no, magnitude or none, not {kind!r}")
        tokens = {r["column"], f"{r['row']}:{r['column']}"}
        role = ("input" if tokens & inputs else "repeat" if tokens & repeats else "")
        figure.cells.append(Cell(r["row"], r["column"], r["printed"], int(r["decimals"]),
                                 int(r["line"]), r["ocr"], r["errata"], kind == "yes",
                                 kind == "magnitude", role, kind != "none"))
    return figure


#: the rule for an exact tie (a computed value exactly half a unit from the print): the
#: printer rounds half away from zero, as FORTRAN's formatted output on the ES EVM did
TIE_RULE = "half away from zero"


def within_half(cell: Cell, value: float) -> bool:
    """Whether ``value`` prints as ``cell``: the exact difference between the binary
    ``value`` and the printed decimal is less than half a unit of the last printed digit,
    or exactly half a unit and :data:`TIE_RULE` (half away from zero) rounds ``value``
    to the print, i.e. the print is the farther of the two from zero.  A magnitude-only
    cell compares absolute values.  Exact decimal arithmetic: no tolerance."""
    if not math.isfinite(value):                   # a NaN or inf prints as no number
        return False
    printed, computed = Decimal(cell.printed), Decimal(value)
    if cell.magnitude:
        printed, computed = abs(printed), abs(computed)
    half = Decimal(5).scaleb(-cell.decimals - 1)
    gap = abs(computed - printed)
    if gap != half:
        return gap < half
    return abs(printed) > abs(computed)           # the tie rounds away from zero


@dataclass
class Comparison:
    cell: Cell
    computed: float | None
    units: float | None          # (computed - printed) in units of the last digit;
                                 # (|computed| - |printed|) for a magnitude-only cell

    @property
    def matches(self) -> bool:
        return self.computed is not None and within_half(self.cell, self.computed)


def compare(figure: Figure, computed: dict) -> list:
    """Compare every printed cell with ``computed[(row, column)]`` (a magnitude-only cell
    by absolute values)."""
    out = []
    for cell in figure.cells:
        value = computed.get((cell.row, cell.column))
        if value is None:
            units = None
        elif cell.magnitude:
            units = (abs(value) - abs(cell.value)) / cell.unit
        else:
            units = (value - cell.value) / cell.unit
        out.append(Comparison(cell, value, units))
    return out


def _counted(c: Comparison) -> bool:
    """A compared cell that the counts include: it has a computed counterpart and does
    not print a column again."""
    return c.cell.role != "repeat" and c.computed is not None and c.cell.counterpart


def report(figure: Figure, comparisons: list, mode: str,
           corrected_differences: dict | None = None,
           evidence: "Evidence | None" = None) -> tuple[str, int, int]:
    """The text of a diff, and (matching, compared) counts of the counted cells (every
    cell with a computed counterpart, less the repeated columns).  Every differing cell is
    printed with its class (:func:`classify`, with ``evidence``); the last line is the
    figure's row of the summary (:func:`summary_line`).

    ``corrected_differences`` ({column or "*": errata ids}) names, in corrected mode,
    what corrected mode changed for the cells that differ from the printed run.
    """
    explain = corrected_differences if mode == "corrected" else None
    lines = [f"Fig. {figure.number}: {figure.meta.get('caption', '')}",
             f"program {figure.meta.get('program', '?')}, {mode} mode; "
             f"printed as {figure.meta.get('printed format', '?')}; "
             f"book lines {figure.meta.get('book lines', '?')}"]
    counted = [c for c in comparisons if _counted(c)]
    magnitudes = [c for c in counted if c.cell.magnitude]
    for c, kind, why in classify(comparisons, evidence):
        if kind in (REPRODUCED, FITTED, INPUT):
            continue
        if kind == NO_CAUSE and explain:
            # corrected mode differs from the printed run by design: say what it corrects
            kind = "differs, corrected mode"
            why = explain.get(c.cell.column) or explain.get("*", "") or why
        got = "missing" if c.computed is None else f"{c.computed:.{c.cell.decimals + 2}f}"
        diff = "" if c.units is None else f" ({c.units:+.2f} units)"
        what = "DIFFERS in magnitude" if c.cell.magnitude else "DIFFERS"
        if kind == ARITHMETIC:
            what = "differs in double"
        lines.append(f"  {what} row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                     f"printed {c.cell.printed}, computed {got}{diff}; {kind} [{why}]")
    for c in counted:
        if c.matches and c.cell.ocr:
            lines.append(f"  note    row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                         f"OCR read {c.cell.ocr}, printed {c.cell.printed} "
                         f"[{c.cell.errata}]")
    if evidence is not None and evidence.book:
        for c in broken(comparisons, evidence):
            value = evidence.book[(c.cell.row, c.cell.column)]
            lines.append(f"  broken  row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                         f"printed {c.cell.printed}, reproduced in double, the book's "
                         f"arithmetic gives {value:.{c.cell.decimals + 2}f} "
                         f"({_units(c.cell, value):+.2f} units)")
    if evidence is not None:
        for name, run in evidence.diagnostic.items():
            fixed = sum(1 for c in counted if not c.matches and (c.cell.row, c.cell.column)
                        in run and within_half(c.cell, run[(c.cell.row, c.cell.column)]))
            lost = sum(1 for c in counted if c.matches and (c.cell.row, c.cell.column)
                       in run and not within_half(c.cell, run[(c.cell.row, c.cell.column)]))
            lines.append(f"  diagnostic, not counted: {name} run whole would reproduce "
                         f"{fixed} cells that double precision misses and miss {lost} "
                         f"that it reproduces")
    if evidence is not None and evidence.fitted:
        fitted = sum(1 for _, k, _ in classify(comparisons, evidence) if k == FITTED)
        lines.append(f"  {fitted} cells are inputs of a fit ({evidence.fit}) and within "
                     f"half a unit: counted as fitted, not reproduced")
    if magnitudes:
        reasons = sorted({e for c in magnitudes for e in c.cell.errata.split(";") if e})
        columns = sorted({c.cell.column for c in magnitudes})
        lines.append(f"  {len(magnitudes)} printed cells compared in magnitude only, their "
                     f"signs not reproducible (columns {' '.join(columns)}; "
                     f"{', '.join(reasons)}): {sum(c.matches for c in magnitudes)} match")
    repeats = [c for c in comparisons if c.cell.role == "repeat"]
    if repeats:
        columns = " ".join(dict.fromkeys(c.cell.column for c in repeats))
        lines.append(f"  {len(repeats)} printed cells print an input column again (columns "
                     f"{columns}; {figure.meta.get('input note', '')}): not counted, "
                     f"{sum(c.matches for c in repeats)} of them match")
    skipped = [c for c in comparisons if not _counted(c) and c.cell.role != "repeat"]
    if skipped:
        reasons = sorted({e for c in skipped for e in c.cell.errata.split(";") if e})
        columns = sorted({c.cell.column for c in skipped})
        lines.append(f"  {len(skipped)} printed cells have no computed counterpart, not "
                     f"compared (columns {' '.join(columns)}; {', '.join(reasons)})")
    row = summary(figure, comparisons, evidence, corrected_differences)
    lines.append(summary_line(row))
    matching = sum(c.matches for c in counted)
    return "\n".join(lines), matching, len(counted)


#: the classes of a compared cell, in the order of the summary's columns
INPUT = "printed input"
REPRODUCED = "reproduced"
FITTED = "fitted"
ARITHMETIC = "reproduced under the book's arithmetic"
CAUSE_SHOWN = "differs, cause shown"
NO_CAUSE = "differs, no cause shown"
CLASSES = (INPUT, REPRODUCED, FITTED, ARITHMETIC, CAUSE_SHOWN, NO_CAUSE)


@dataclass(frozen=True)
class Cause:
    """A demonstration that a differing cell's cause is real: ``errata`` names it,
    ``how`` says what was applied (a shipped script or test, or a printed identity).
    ``moved`` is the cell's value with the cause applied: the cause is shown when it lies
    within half a unit of the print.  ``misprint`` is the interval a printed identity
    allows the cell: the print is shown a misprint when it lies outside that interval
    (widened by half a unit) and the computed value inside it."""
    errata: str
    how: str
    moved: float | None = None
    misprint: tuple | None = None
    applied: dict | None = None       # the inputs the cause was applied with, if any

    def shown(self, comparison: Comparison) -> bool:
        cell = comparison.cell
        if self.moved is not None:
            return within_half(cell, self.moved)
        if self.misprint is not None and comparison.computed is not None:
            lo, hi = self.misprint
            half = 0.5 * cell.unit
            outside = cell.value < lo - half or cell.value > hi + half
            return outside and lo - half <= comparison.computed <= hi + half
        return False


@dataclass
class Evidence:
    """What a program shows about its figure's cells beyond the double-precision run:
    ``fitted`` the cells an input was fitted to, ``book`` ({(row, column): value}) the
    whole program run in the book's arithmetic (the ES EVM's REAL*4 under the one library
    model, :mod:`sarkp.book.es_evm`), ``diagnostic`` ({name: cells}) other arithmetics
    shown but never counted (IEEE single), ``causes`` ({(row, column): Cause}) the
    demonstrated causes of differing cells."""
    fitted: frozenset = frozenset()
    book: dict = field(default_factory=dict)
    diagnostic: dict = field(default_factory=dict)
    causes: dict = field(default_factory=dict)
    fit: str = ""                     # where the fit is (a shipped script)


def _units(cell: Cell, value: float) -> float:
    if cell.magnitude:
        return (abs(value) - abs(cell.value)) / cell.unit
    return (value - cell.value) / cell.unit


def broken(comparisons: list, evidence: Evidence | None) -> list:
    """The counted cells that double precision reproduces and the whole run in the
    book's arithmetic (``evidence.book``) does not."""
    if evidence is None or not evidence.book:
        return []
    return [c for c in comparisons if _counted(c) and c.matches
            and (c.cell.row, c.cell.column) in evidence.book
            and not within_half(c.cell, evidence.book[(c.cell.row, c.cell.column)])]


def classify(comparisons: list, evidence: Evidence | None = None) -> list:
    """``[(comparison, class, why)]`` for every counted cell (one with a computed
    counterpart that does not print a column again), ``class`` one of :data:`CLASSES`:
    a printed input (within half a unit), fitted (an input was fitted to it and it is
    within half a unit, in double precision or in the book's arithmetic), reproduced (within half a unit, double precision), reproduced
    under the book's arithmetic (``why`` gives its difference there), differs with its
    cause shown (``why``: the ERRATA id and how), or differs, no cause shown (``why``:
    the cell's ERRATA ids, which alone explain nothing)."""
    evidence = evidence or Evidence()
    out = []
    for c in comparisons:
        if not _counted(c):
            continue
        key = (c.cell.row, c.cell.column)
        if c.matches:
            kind = (INPUT if c.cell.role == "input" else
                    FITTED if key in evidence.fitted else REPRODUCED)
            out.append((c, kind, ""))
            continue
        value = evidence.book.get(key)
        if value is not None and within_half(c.cell, value):
            if key in evidence.fitted:        # an input of the fit all the same
                out.append((c, FITTED, f"the ES EVM: {_units(c.cell, value):+.2f} units"))
            else:
                out.append((c, ARITHMETIC, f"the ES EVM: {_units(c.cell, value):+.2f} units"))
            continue
        cause = evidence.causes.get(key)
        if cause is not None and cause.shown(c):
            out.append((c, CAUSE_SHOWN, f"{cause.errata}: {cause.how}"))
        else:
            out.append((c, NO_CAUSE, c.cell.errata or "no ERRATA id"))
    return out


def summary(figure: Figure, comparisons: list, evidence: Evidence | None = None,
            corrected_differences: dict | None = None) -> dict:
    """Counts of a diff by class (:func:`classify`), the cells the book's arithmetic
    breaks, the repeated cells and the cells without a computed counterpart (and the ids
    why), ``no_id``: differing cells that carry no ERRATA id of their own, and of those
    ``corrected_mode`` the ones that ``corrected_differences`` names a reason for."""
    explain = corrected_differences or {}
    classes = classify(comparisons, evidence)
    skipped = [c for c in comparisons if not _counted(c) and c.cell.role != "repeat"]
    reasons = sorted({e for c in skipped for e in c.cell.errata.split(";") if e})
    row = {"figure": figure.number, "compared": len(classes),
           "left_out": len(skipped), "why": ", ".join(reasons),
           "repeats": sum(c.cell.role == "repeat" for c in comparisons),
           "broken": len(broken(comparisons, evidence)),
           "emulated": bool(evidence is not None and evidence.book),
           "no_id": sum(k not in (REPRODUCED, FITTED, INPUT) and not c.cell.errata
                        for c, k, _ in classes),
           "corrected_mode": sum(k not in (REPRODUCED, FITTED, INPUT) and not c.cell.errata
                                 and bool(explain.get(c.cell.column) or explain.get("*"))
                                 for c, k, _ in classes)}
    for name in CLASSES:
        row[name] = sum(k == name for _, k, _ in classes)
    return row


def summary_line(row: dict) -> str:
    """A figure's counts in one line, the same categories as :func:`summary_table`."""
    broke = f" (that run breaks {row['broken']})" if row["emulated"] else " (not emulated)"
    extra = ""
    if row["repeats"]:
        extra += f"; {row['repeats']} repeated cells not counted"
    if row["left_out"]:
        extra += f"; {row['left_out']} without a computed counterpart ({row['why']})"
    return (f"Fig. {row['figure']}: {row['compared']} cells compared: {row[INPUT]} printed "
            f"inputs, {row[REPRODUCED]} reproduced, {row[FITTED]} fitted, {row[ARITHMETIC]} "
            f"reproduced under the book's arithmetic{broke}, {row[CAUSE_SHOWN]} differ with "
            f"cause shown, {row[NO_CAUSE]} differ with no cause shown{extra}")


def summary_table(rows: list) -> str:
    """The summary of several diffs as a Markdown table."""
    out = ["| figure | cells compared | printed inputs | reproduced | fitted | reproduced "
           "under the book's arithmetic (cells that run breaks) | differs, cause shown "
           "| differs, no cause shown | not counted: repeats; no counterpart (why) |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        left = f"{r['repeats']}; {r['left_out']}" + (f" ({r['why']})" if r["left_out"] else "")
        arith = f"{r[ARITHMETIC]} ({r['broken']})" if r["emulated"] else f"{r[ARITHMETIC]} (-)"
        out.append(f"| Fig. {r['figure']} | {r['compared']} | {r[INPUT]} | {r[REPRODUCED]} | "
                   f"{r[FITTED]} | {arith} | {r[CAUSE_SHOWN]} | {r[NO_CAUSE]} | {left} |")
    total = {k: sum(r[k] for r in rows)
             for k in ("compared", "left_out", "repeats", "broken") + CLASSES}
    out.append(f"| all | {total['compared']} | {total[INPUT]} | {total[REPRODUCED]} | "
               f"{total[FITTED]} | {total[ARITHMETIC]} ({total['broken']}) | "
               f"{total[CAUSE_SHOWN]} | {total[NO_CAUSE]} | "
               f"{total['repeats']}; {total['left_out']} |")
    return "\n".join(out)
