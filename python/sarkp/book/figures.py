"""Printed figures as data, and the cell-by-cell comparison with a reproduction.

A figure is a CSV file in ``sarkp/book/data`` named ``fig<N>.csv``: ``#`` lines first
(figure, caption, program, book lines, printed format), then one row per printed cell:

``row,column,printed,decimals,line,ocr,errata,reproducible``

``printed`` is the value as printed with OCR errors corrected (``ocr`` then holds what
the OCR read), ``decimals`` the digits printed after the point, ``errata`` the ids of
docs/ERRATA.md that explain the cell, ``reproducible`` = ``no`` where the printed
program computed the cell wrongly in a way no run can repeat, ``magnitude`` where only
its absolute value is reproducible (its sign came from what no run can repeat; the cell's
``errata`` say why): the diff then compares magnitudes and says so.
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
           corrected_differences: dict | None = None) -> tuple[str, int, int]:
    """The text of a diff, and (matching, compared) counts of the compared cells: the
    reproducible ones and the magnitude-only ones (the last line counts the former).

    ``corrected_differences`` ({column or "*": errata ids}) explains, in corrected mode,
    the cells that differ because corrected mode fixes what the printed run did.
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
    for c in compared + magnitudes:
        if not c.matches:
            why = c.cell.errata
            if not why and explain:
                why = explain.get(c.cell.column) or explain.get("*", "")
            why = why or "unexplained"
            got = "missing" if c.computed is None else f"{c.computed:.{c.cell.decimals + 2}f}"
            diff = "" if c.units is None else f" ({c.units:+.1f} units)"
            what = "DIFFERS" if c.cell.reproducible else "DIFFERS in magnitude"
            lines.append(f"  {what} row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                         f"printed {c.cell.printed}, computed {got}{diff} [{why}]")
    for c in comparisons:
        if (c.cell.reproducible or c.cell.magnitude) and c.matches and c.cell.ocr:
            lines.append(f"  note    row {c.cell.row} {c.cell.column} (L{c.cell.line}): "
                         f"OCR read {c.cell.ocr}, printed {c.cell.printed} "
                         f"[{c.cell.errata}]")
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


def summary(figure: Figure, comparisons: list, corrected_differences: dict | None = None
            ) -> dict:
    """Counts of a diff: cells compared, matching, differing with an ERRATA id of their
    own (explained), differing without one (unexplained), left out and the ids why.

    ``corrected_differences`` (the program's reasons for corrected mode, as for
    :func:`report`) also explains a differing cell, counted as "corrected mode";
    ``own_ids`` counts the differing cells with no ERRATA id of their own either way."""
    compared = [c for c in comparisons if c.cell.reproducible or c.cell.magnitude]
    differ = [c for c in compared if not c.matches]
    own = [c for c in differ if c.cell.errata]
    explain = corrected_differences or {}
    by_mode = [c for c in differ if not c.cell.errata
               and (explain.get(c.cell.column) or explain.get("*"))]
    skipped = [c for c in comparisons if not (c.cell.reproducible or c.cell.magnitude)]
    reasons = sorted({e for c in skipped for e in c.cell.errata.split(";") if e})
    because = sorted({e for c in own for e in c.cell.errata.split(";") if e})
    if by_mode:
        because.append(f"corrected mode: {len(by_mode)}")
    return {"figure": figure.number, "compared": len(compared), "because": ", ".join(because),
            "matching": len(compared) - len(differ), "explained": len(own) + len(by_mode),
            "unexplained": len(differ) - len(own) - len(by_mode),
            "own_ids": len(differ) - len(own), "left_out": len(skipped),
            "why": ", ".join(reasons)}


def summary_table(rows: list) -> str:
    """The summary of several diffs as a Markdown table."""
    out = ["| figure | cells compared | matching | explained differences | unexplained "
           "| cells left out (why) |", "|---|---|---|---|---|---|"]
    for r in rows:
        left = f"{r['left_out']} ({r['why']})" if r["left_out"] else "0"
        explained = f"{r['explained']} ({r['because']})" if r["explained"] else "0"
        out.append(f"| Fig. {r['figure']} | {r['compared']} | {r['matching']} | "
                   f"{explained} | {r['unexplained']} | {left} |")
    total = {k: sum(r[k] for r in rows) for k in ("compared", "matching", "explained",
                                                 "unexplained", "left_out")}
    out.append(f"| all | {total['compared']} | {total['matching']} | {total['explained']} "
               f"| {total['unexplained']} | {total['left_out']} |")
    return "\n".join(out)
