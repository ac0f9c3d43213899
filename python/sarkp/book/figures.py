"""Printed figures as data, and the cell-by-cell comparison with a reproduction.

A figure is a CSV file in ``sarkp/book/data`` named ``fig<N>.csv``: ``#`` lines first
(figure, caption, program, book lines, printed format), then one row per printed cell:

``row,column,printed,decimals,line,ocr,errata,reproducible``

``printed`` is the value as printed with OCR errors corrected (``ocr`` then holds what
the OCR read), ``decimals`` the digits printed after the point, ``errata`` the ids of
docs/ERRATA.md that discuss the cell (an id alone explains nothing: :func:`classify` says
what is shown), ``reproducible`` = ``no`` where the printed
program computed the cell wrongly in a way no run can repeat, ``magnitude`` where only
its absolute value is reproducible (its sign came from what no run can repeat; the cell's
``errata`` say why): the diff then compares magnitudes and says so.

Every compared cell is exactly one of (:func:`classify`): reproduced (within half a unit
of its last printed digit, double precision); fitted (the same, but an input was fitted
to it: program X's link lengths, scripts/fit_x_links.py); reproduced under a named
arithmetic (the ES EVM's emulation or IEEE single reproduces it); differs, cause shown
(the cause, applied by shipped code, moves it within half a unit, or a printed identity
proves the print a misprint); differs, no cause shown.  An ERRATA id alone explains
nothing.
"""

from __future__ import annotations

import csv
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
    for r in csv.DictReader(body):
        kind = r["reproducible"].strip().lower()
        if kind not in ("yes", "no", "magnitude"):
            raise ValueError(f"fig{number}.csv row {r['row']} {r['column']}: reproducible "
                             f"must be yes, no or magnitude, not {kind!r}")
        figure.cells.append(Cell(r["row"], r["column"], r["printed"], int(r["decimals"]),
                                 int(r["line"]), r["ocr"], r["errata"], kind == "yes",
                                 kind == "magnitude"))
    return figure


@dataclass
class Comparison:
    cell: Cell
    computed: float | None
    units: float | None          # (computed - printed) in units of the last digit;
                                 # (|computed| - |printed|) for a magnitude-only cell

    @property
    def matches(self) -> bool:
        return self.units is not None and abs(self.units) <= 0.5 + 1e-9


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


def report(figure: Figure, comparisons: list, mode: str,
           corrected_differences: dict | None = None,
           evidence: "Evidence | None" = None) -> tuple[str, int, int]:
    """The text of a diff, and (matching, compared) counts of the compared cells: the
    reproducible ones and the magnitude-only ones (the last line counts the former).
    Every differing cell is printed with its class (:func:`classify`, with ``evidence``).

    ``corrected_differences`` ({column or "*": errata ids}) names, in corrected mode,
    what corrected mode changed for the cells that differ from the printed run.
    """
    explain = corrected_differences if mode == "corrected" else None
    lines = [f"Fig. {figure.number}: {figure.meta.get('caption', '')}",
             f"program {figure.meta.get('program', '?')}, {mode} mode; "
             f"printed as {figure.meta.get('printed format', '?')}; "
             f"book lines {figure.meta.get('book lines', '?')}"]
    compared = [c for c in comparisons if c.cell.reproducible]
    magnitudes = [c for c in comparisons if c.cell.magnitude]
    skipped = [c for c in comparisons if not (c.cell.reproducible or c.cell.magnitude)]
    matching = [c for c in compared if c.matches]
    for c, kind, why in classify(comparisons, evidence):
        if kind in (REPRODUCED, FITTED):
            continue
        if kind == NO_CAUSE and explain:
            # corrected mode differs from the printed run by design: say what it corrects
            kind = "differs, corrected mode"
            why = explain.get(c.cell.column) or explain.get("*", "") or why
        got = "missing" if c.computed is None else f"{c.computed:.{c.cell.decimals + 2}f}"
        diff = "" if c.units is None else f" ({c.units:+.2f} units)"
        what = "DIFFERS" if c.cell.reproducible else "DIFFERS in magnitude"
        lines.append(f"  {what} row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                     f"printed {c.cell.printed}, computed {got}{diff}; {kind} [{why}]")
    for c in comparisons:
        if (c.cell.reproducible or c.cell.magnitude) and c.matches and c.cell.ocr:
            lines.append(f"  note    row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                         f"OCR read {c.cell.ocr}, printed {c.cell.printed} "
                         f"[{c.cell.errata}]")
    if evidence is not None and evidence.fitted:
        fitted = sum(1 for c in compared + magnitudes
                     if (c.cell.row, c.cell.column) in evidence.fitted)
        lines.append(f"  {fitted} compared cells are inputs of a fit ({evidence.fit}): "
                     f"counted as fitted, not reproduced")
    if magnitudes:
        reasons = sorted({e for c in magnitudes for e in c.cell.errata.split(";") if e})
        columns = sorted({c.cell.column for c in magnitudes})
        lines.append(f"  {len(magnitudes)} printed cells compared in magnitude only, their "
                     f"signs not reproducible (columns {' '.join(columns)}; "
                     f"{', '.join(reasons)}): {sum(c.matches for c in magnitudes)} match")
    if skipped:
        reasons = sorted({e for c in skipped for e in c.cell.errata.split(";") if e})
        columns = sorted({c.cell.column for c in skipped})
        lines.append(f"  {len(skipped)} printed cells not reproducible, not compared "
                     f"(columns {' '.join(columns)}; {', '.join(reasons)})")
    lines.append(f"{len(matching)} of {len(compared)} cells match")
    magnitude_matching = sum(c.matches for c in magnitudes)
    return ("\n".join(lines), len(matching) + magnitude_matching,
            len(compared) + len(magnitudes))


#: the classes of a compared cell, in the order of the summary's columns
REPRODUCED = "reproduced"
FITTED = "fitted"
ARITHMETIC = "reproduced under a named arithmetic"
CAUSE_SHOWN = "differs, cause shown"
NO_CAUSE = "differs, no cause shown"
CLASSES = (REPRODUCED, FITTED, ARITHMETIC, CAUSE_SHOWN, NO_CAUSE)


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
        half = 0.5 * cell.unit * (1 + 1e-9)
        if self.moved is not None:
            value = abs(self.moved) if cell.magnitude else self.moved
            return abs(value - (abs(cell.value) if cell.magnitude else cell.value)) <= half
        if self.misprint is not None and comparison.computed is not None:
            lo, hi = self.misprint
            outside = cell.value < lo - half or cell.value > hi + half
            return outside and lo - half <= comparison.computed <= hi + half
        return False


@dataclass
class Evidence:
    """What a program shows about its figure's cells beyond the double-precision run:
    ``fitted`` the cells an input was fitted to, ``arithmetics`` ({name: {(row, column):
    value}}) the figure run in another arithmetic (the ES EVM's emulation, IEEE single),
    ``causes`` ({(row, column): Cause}) the demonstrated causes of differing cells."""
    fitted: frozenset = frozenset()
    arithmetics: dict = field(default_factory=dict)
    causes: dict = field(default_factory=dict)
    fit: str = ""                     # where the fit is (a shipped script)


def _units(cell: Cell, value: float) -> float:
    if cell.magnitude:
        return (abs(value) - abs(cell.value)) / cell.unit
    return (value - cell.value) / cell.unit


def classify(comparisons: list, evidence: Evidence | None = None) -> list:
    """``[(comparison, class, why)]`` for every compared cell (reproducible or
    magnitude-only), ``class`` one of :data:`CLASSES`: fitted (an input was fitted to it
    and it is within half a unit), reproduced (within half a unit, double precision),
    reproduced under a named arithmetic (``why`` names it and its difference), differs
    with its cause shown (``why``: the ERRATA id and how), or differs, no cause shown
    (``why``: the cell's ERRATA ids, which alone explain nothing)."""
    evidence = evidence or Evidence()
    out = []
    for c in comparisons:
        if not (c.cell.reproducible or c.cell.magnitude):
            continue
        key = (c.cell.row, c.cell.column)
        if c.matches:
            out.append((c, FITTED if key in evidence.fitted else REPRODUCED, ""))
            continue
        done = False
        for name, run in evidence.arithmetics.items():
            value = run.get(key)
            if value is not None and abs(_units(c.cell, value)) <= 0.5 + 1e-9:
                out.append((c, ARITHMETIC, f"{name}: {_units(c.cell, value):+.2f} units"))
                done = True
                break
        if done:
            continue
        cause = evidence.causes.get(key)
        if cause is not None and cause.shown(c):
            out.append((c, CAUSE_SHOWN, f"{cause.errata}: {cause.how}"))
        else:
            out.append((c, NO_CAUSE, c.cell.errata or "no ERRATA id"))
    return out


def summary(figure: Figure, comparisons: list, evidence: Evidence | None = None,
            corrected_differences: dict | None = None) -> dict:
    """Counts of a diff by class (:func:`classify`), the cells left out and the ids why,
    ``no_id``: differing cells that carry no ERRATA id of their own, and of those
    ``corrected_mode`` the ones that ``corrected_differences`` names a reason for."""
    explain = corrected_differences or {}
    classes = classify(comparisons, evidence)
    skipped = [c for c in comparisons if not (c.cell.reproducible or c.cell.magnitude)]
    reasons = sorted({e for c in skipped for e in c.cell.errata.split(";") if e})
    row = {"figure": figure.number, "compared": len(classes),
           "left_out": len(skipped), "why": ", ".join(reasons),
           "no_id": sum(k not in (REPRODUCED, FITTED) and not c.cell.errata
                        for c, k, _ in classes),
           "corrected_mode": sum(k not in (REPRODUCED, FITTED) and not c.cell.errata
                                 and bool(explain.get(c.cell.column) or explain.get("*"))
                                 for c, k, _ in classes),
           "arithmetic_names": ", ".join(sorted({w.split(":")[0] for _, k, w in classes
                                                 if k == ARITHMETIC}))}
    for name in CLASSES:
        row[name] = sum(k == name for _, k, _ in classes)
    return row


def summary_table(rows: list) -> str:
    """The summary of several diffs as a Markdown table."""
    out = ["| figure | cells compared | reproduced | fitted | reproduced under a named "
           "arithmetic | differs, cause shown | differs, no cause shown "
           "| cells left out (why) |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        left = f"{r['left_out']} ({r['why']})" if r["left_out"] else "0"
        arith = (f"{r[ARITHMETIC]} ({r['arithmetic_names']})" if r[ARITHMETIC] else "0")
        out.append(f"| Fig. {r['figure']} | {r['compared']} | {r[REPRODUCED]} | "
                   f"{r[FITTED]} | {arith} | {r[CAUSE_SHOWN]} | {r[NO_CAUSE]} | {left} |")
    total = {k: sum(r[k] for r in rows) for k in ("compared", "left_out") + CLASSES}
    out.append(f"| all | {total['compared']} | {total[REPRODUCED]} | {total[FITTED]} | "
               f"{total[ARITHMETIC]} | {total[CAUSE_SHOWN]} | {total[NO_CAUSE]} | "
               f"{total['left_out']} |")
    return "\n".join(out)
