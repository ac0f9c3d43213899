"""The ``sarkp`` command line (also ``python -m sarkp``).

    sarkp book list                       the reproduced programs and figures
    sarkp book run PROGRAM [--mode M] [--stage S] [--arithmetic A]
                   [--plots DIR [--format png|svg|pdf] [--dpi N]]
                                          a program's printout, in the book's layout
                                          (--stage: one stage of program X alone;
                                          --arithmetic es-evm|ieee-single: program X's
                                          chain in the ES EVM's REAL*4 or IEEE single;
                                          --plots: its pictures, the corrected design
                                          unless --mode as-printed)
    sarkp book diff FIG|all [--mode M] [--arithmetic A]
                                          compare a reproduction with the printed figure
                                          (all: ends with a summary table, every cell
                                          a printed input, reproduced, fitted,
                                          reproduced under the book's arithmetic,
                                          differing with its cause shown or not; the
                                          rules: docs/judging.md; status 0 when every
                                          difference has an ERRATA id)
    sarkp listing [NAME] [--modern|--corrected|--diff [side]]
                                          the book's code; sarkp's routine; that routine
                                          without its as-printed branches; the book's
                                          against it
    sarkp errata ID|NAME                  a row of docs/ERRATA.md, or every row of a routine
    sarkp book run PROGRAM --printed      the program compiled as printed (says why not)

Book programs run as printed by default (``--mode as-printed``: the book's PI = 3.14159
and the author errors its printed figures depend on); ``--mode corrected`` runs them with
every error fixed.  The pictures of ``--plots`` show the corrected design unless
``--mode as-printed`` is given (then every title says AS PRINTED).  A mistake on the
command line -- an unknown program or stage, a DIR that cannot be written, a program
without pictures -- gives a one-line message and exit status 2 before anything runs.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
import tempfile
from importlib import resources
from pathlib import Path

from . import book, listings, modes
from .errors import SarkpError
from .book import figures


def _version() -> str:
    from . import __version__
    return __version__


def _diff(number: str, mode: str, arithmetic: str = "double") -> tuple[str, dict]:
    program = _figure_program(number)
    figure = figures.load_figure(number)
    if arithmetic != "double":             # program X's chain emulated (as printed only)
        from .book import x_arithmetic
        if number not in x_arithmetic.FIGURES or mode != "as-printed":
            raise UsageError(f"--arithmetic {arithmetic}: Figs. "
                             f"{', '.join(x_arithmetic.FIGURES)} in as-printed mode only")
        comparisons = figures.compare(figure, x_arithmetic.figure_cells(number, arithmetic))
        text, _, _ = figures.report(figure, comparisons, f"{mode} ({arithmetic})")
        return text, figures.summary(figure, comparisons)
    with modes.mode(mode):
        computed = book.figure_cells(number)
    comparisons = figures.compare(figure, computed)
    # the evidence (emulations, fits, causes) is about the printed run: as-printed only
    evidence = book.figure_evidence(number) if mode == "as-printed" else None
    explain = getattr(program, "CORRECTED_DIFFERENCES", None) if mode == "corrected" else None
    text, _, _ = figures.report(figure, comparisons, mode, explain, evidence)
    return text, figures.summary(figure, comparisons, evidence, explain)


class UsageError(Exception):
    """A mistake of the user's on the command line (exit status 2)."""


def _figure_program(number: str):
    if number not in book.FIGURES:
        data = resources.files("sarkp.book") / "data" / f"fig{number}.csv"
        if data.is_file():
            raise UsageError(f"Fig. {number} is transcribed (sarkp/book/data/fig{number}.csv) "
                             f"but no book program reproduces it yet; figures with a diff: "
                             f"{', '.join(book.FIGURES)}")
        raise UsageError(f"no printed figure {number!r}; figures with a diff: "
                         f"{', '.join(book.FIGURES)}")
    return book.figure_program(number)


def _dpi(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if not 10 <= value <= 2400:
        raise argparse.ArgumentTypeError(f"must be a whole number from 10 to 2400, "
                                         f"not {text!r}")
    return value


def _pictures(listing: str, prog, stage):
    """(the function that writes the program's pictures, the names it will write), or a
    UsageError when the program (or the stage) has none."""
    if listing == "X":
        from .book import x_plots
        names = x_plots.pictures(stage)
        if not names:
            raise UsageError(f"--plots: stage {stage!r} of program X has no pictures; "
                             f"the stages with pictures: {', '.join(x_plots.PICTURES)}")
        return (lambda d, **kw: x_plots.plots(d, stage, **kw)), names
    if not hasattr(prog, "plots"):
        with_pictures = [p for p in book.PROGRAMS
                         if p == "X" or hasattr(book.program(p), "plots")]
        raise UsageError(f"--plots: program {listing} has no pictures; the programs with "
                         f"pictures: {', '.join(with_pictures)}")
    return prog.plots, tuple(prog.PICTURES)


def _writable_directory(path: str) -> Path:
    """``path`` as a directory that exists (created if needed) and takes a file, or a
    UsageError saying why not."""
    directory = Path(path)
    if directory.exists() and not directory.is_dir():
        raise UsageError(f"--plots {path}: exists and is not a directory")
    try:
        directory.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=directory):
            pass
    except OSError as exc:
        raise UsageError(f"--plots {path}: cannot write there "
                         f"({exc.strerror or exc})") from None
    return directory


def _run(args) -> int:
    """``sarkp book run``: every argument checked before anything runs."""
    listing = args.program.upper().replace("П", "II")
    if listing not in book.PROGRAMS:
        raise UsageError(f"no book program {args.program!r}; known: "
                         f"{', '.join(book.PROGRAMS)}")
    prog = book.program(listing)
    stages = getattr(prog, "STAGES", ())
    if args.stage is not None and args.stage not in stages:
        raise UsageError(f"--stage {args.stage!r}: " + (
            f"program {args.program} has the stages {', '.join(stages)}" if stages
            else f"program {args.program} has no stages"))
    printout_mode = args.mode or "as-printed"
    if args.arithmetic != "double" and (not stages or printout_mode != "as-printed"):
        raise UsageError(f"--arithmetic {args.arithmetic}: program X in as-printed mode "
                         f"only (the emulation of the printed run)")
    if args.plots is None:
        for option in ("format", "dpi"):
            if getattr(args, option) is not None:
                raise UsageError(f"--{option} is for the pictures: give --plots DIR too")
    else:
        if importlib.util.find_spec("matplotlib") is None:
            raise UsageError("--plots needs matplotlib: pip install 'sarkp[plot]'")
        draw, names = _pictures(listing, prog, args.stage)
        directory = _writable_directory(args.plots)
    with modes.mode(printout_mode):
        try:
            if args.arithmetic != "double":
                text = prog.render(args.stage, arithmetic=args.arithmetic)
            else:
                text = prog.render(args.stage) if stages else prog.render()
        except SarkpError as exc:       # a stage that cannot run: nothing printed
            print(f"sarkp: error: {exc}", file=sys.stderr)
            return 1
    print(text)
    if args.plots is None:
        return 0
    picture_mode = args.mode or "corrected"
    fmt = args.format or "png"
    print(f"pictures ({picture_mode} mode, {fmt}): " + ", ".join(f"{n}.{fmt}" for n in names),
          file=sys.stderr)
    with modes.mode(picture_mode):
        try:
            paths = draw(directory, format=fmt, dpi=args.dpi)
        except (SarkpError, OSError) as exc:
            print(f"sarkp: error: the pictures: {exc}", file=sys.stderr)
            return 1
    for path in paths:
        print(f"wrote {path}", file=sys.stderr)
    return 0


def main(argv=None) -> int:
    """Run the command line; return the exit status."""
    try:
        return _main(argv)
    except UsageError as exc:
        print(f"sarkp: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # the reader went away (``sarkp book run II.13 | head``): not an error
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


class _Parser(argparse.ArgumentParser):
    """argparse, with its errors in one line (the usage is in ``--help``)."""

    def error(self, message):
        raise UsageError(f"{message} (see {self.prog} --help)")


def _main(argv=None) -> int:
    parser = _Parser(
        prog="sarkp", description=__doc__.split("\n\n")[0].splitlines()[0],
        epilog="Book programs run as printed by default (--mode as-printed: PI = 3.14159 "
               "and the author errors the printed figures depend on); --mode corrected "
               "fixes every error.")
    parser.add_argument("--version", action="version", version=f"sarkp {_version()}")
    sub = parser.add_subparsers(dest="command", required=True)
    book_parser = sub.add_parser("book", help="the book's programs and printed figures")
    book_sub = book_parser.add_subparsers(dest="action", required=True)
    book_sub.add_parser("list", help="list the reproduced programs and figures")
    run = book_sub.add_parser("run", help="run a book program and print its output")
    run.add_argument("program", help="listing number, e.g. II.13")
    run.add_argument("--stage", metavar="STAGE",
                     help="program X only: run one stage alone (synthesis, teeth, gears, "
                          "cam, kinematics, forces, dynamics)")
    run.add_argument("--arithmetic", choices=("double", "es-evm", "ieee-single"),
                     default="double",
                     help="program X only, as printed: run kinematics, forces and "
                          "dynamics statement by statement in the ES EVM's REAL*4 or IEEE "
                          "single (default: sarkp's double precision)")
    run.add_argument("--printed", action="store_true",
                     help="the book's main program compiled as printed (sarkp.printed)")
    run.add_argument("--plots", metavar="DIR",
                     help="also write the program's pictures in DIR (needs matplotlib); "
                          "they show the corrected design unless --mode as-printed is given")
    run.add_argument("--format", choices=("png", "svg", "pdf"),
                     help="file format of the pictures (default png)")
    run.add_argument("--dpi", type=_dpi, help="resolution of PNG pictures (default 150)")
    diff = book_sub.add_parser("diff", help="compare a reproduction with a printed figure")
    diff.add_argument("figure", help="figure number, e.g. 4, or 'all'")
    diff.add_argument("--arithmetic", choices=("double", "es-evm", "ieee-single"),
                      default="double",
                      help="Figs. 91, 94, 96 only: diff program X's chain run in the ES "
                           "EVM's REAL*4 or IEEE single instead of sarkp's double")
    run.add_argument("--mode", choices=modes.MODES,
                     help="as-printed (the printout's default): the book's arithmetic and "
                          "errors; corrected (the pictures' default): every error fixed")
    diff.add_argument("--mode", choices=modes.MODES, default="as-printed",
                      help="as-printed (default): the book's arithmetic and errors; "
                           "corrected: every error fixed")
    listing = sub.add_parser("listing", help="the book's listing of a routine or program")
    listing.add_argument("name", nargs="?", help="e.g. DPRM1 or IV.1; none lists them all")
    shown = listing.add_mutually_exclusive_group()
    shown.add_argument("--modern", action="store_true", help="sarkp's Fortran 90 routine")
    shown.add_argument("--corrected", action="store_true",
                       help="sarkp's Fortran 90 routine as corrected mode runs it: the "
                            "as-printed branches left out")
    shown.add_argument("--diff", nargs="?", const="unified", choices=("unified", "side"),
                       help="book against sarkp's corrected routine, each deviation with "
                            "its ERRATA ids (side: two columns, long statements wrapped)")
    errata = sub.add_parser("errata", help="rows of docs/ERRATA.md")
    errata.add_argument("key", help="an id (E-DUSKR1-1) or a routine (DUSKR1)")
    args = parser.parse_args(argv)

    if args.command in ("listing", "errata"):
        try:
            if args.command == "errata":
                text = listings.errata(args.key)
            elif args.name is None:
                text = listings.table()
            else:
                text = listings.listing(args.name, modern=args.modern, diff=args.diff,
                                        corrected=args.corrected)
        except ValueError as exc:
            raise UsageError(str(exc)) from None
        print(text.rstrip("\n"))
        return 0
    if args.action == "list":
        for listing, name in book.PROGRAMS.items():
            prog = book.program(listing)
            figs = ", ".join(f"Fig. {f}" for f in prog.FIGURES) or "no printed output"
            pictures = "; pictures: --plots" if listing == "X" or hasattr(prog, "plots") else ""
            print(f"{listing:8s} {prog.TITLE} ({figs}{pictures})")
        return 0
    if args.action == "run" and args.printed:
        from . import printed
        try:
            printed.program(args.program)
        except ValueError as exc:             # PrintedCodeError, or an unknown name
            raise UsageError(str(exc)) from None
    if args.action == "run":
        return _run(args)
    numbers = list(book.FIGURES) if args.figure == "all" else [args.figure]
    if args.figure == "all" and args.arithmetic != "double":
        from .book import x_arithmetic
        numbers = list(x_arithmetic.FIGURES)
    for number in numbers:
        _figure_program(number)
    rows = []
    for number in numbers:
        text, row = _diff(number, args.mode, args.arithmetic)
        print(text)
        print()
        rows.append(row)
    if len(numbers) > 1:
        print(f"Summary ({args.mode} mode):")
        print(figures.summary_table(rows))
        shown = {k: sum(r[k] for r in rows) for k in figures.CLASSES}
        print(f"all figures: {sum(r['compared'] for r in rows)} cells compared: "
              + "; ".join(f"{shown[k]} {k}" for k in figures.CLASSES))
    # 0: every differing cell carries an ERRATA id (whether or not its cause is shown:
    # the table says that)
    return 0 if all(r["no_id"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
