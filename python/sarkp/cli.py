"""The ``sarkp`` command line (also ``python -m sarkp``).

    sarkp book list                       the reproduced programs and figures
    sarkp book run PROGRAM [--mode M]     a program's printout, in the book's layout
    sarkp book diff FIG|all [--mode M]    compare a reproduction with the printed figure
    sarkp listing [NAME] [--modern|--diff [side]]   the book's code; sarkp's routine; both
    sarkp errata ID|NAME                  a row of docs/ERRATA.md, or every row of a routine

Book programs run as printed by default (``--mode as-printed``).
"""

from __future__ import annotations

import argparse
import sys

from . import book, listings, modes
from .book import figures


def _diff(number: str, mode: str) -> tuple[str, int, int]:
    figure = figures.load_figure(number)
    program = book.figure_program(number)
    with modes.mode(mode):
        computed = program.cells()
    return figures.report(figure, figures.compare(figure, computed), mode,
                          getattr(program, "CORRECTED_DIFFERENCES", None))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="sarkp", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    book_parser = sub.add_parser("book", help="the book's programs and printed figures")
    book_sub = book_parser.add_subparsers(dest="action", required=True)
    book_sub.add_parser("list", help="list the reproduced programs and figures")
    run = book_sub.add_parser("run", help="run a book program and print its output")
    run.add_argument("program", help="listing number, e.g. II.13")
    diff = book_sub.add_parser("diff", help="compare a reproduction with a printed figure")
    diff.add_argument("figure", help="figure number, e.g. 4, or 'all'")
    for p in (run, diff):
        p.add_argument("--mode", choices=modes.MODES, default="as-printed")
    listing = sub.add_parser("listing", help="the book's listing of a routine or program")
    listing.add_argument("name", nargs="?", help="e.g. DPRM1 or IV.1; none lists them all")
    shown = listing.add_mutually_exclusive_group()
    shown.add_argument("--modern", action="store_true", help="sarkp's Fortran 90 routine")
    shown.add_argument("--diff", nargs="?", const="unified", choices=("unified", "side"),
                       help="book against sarkp, each deviation with its ERRATA ids")
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
                text = listings.listing(args.name, modern=args.modern, diff=args.diff)
        except ValueError as exc:
            print(f"sarkp: {exc}", file=sys.stderr)
            return 2
        print(text.rstrip("\n"))
        return 0
    if args.action == "list":
        for listing, name in book.PROGRAMS.items():
            prog = book.program(listing)
            figs = ", ".join(f"Fig. {f}" for f in prog.FIGURES) or "no printed output"
            print(f"{listing:8s} {prog.TITLE} ({figs})")
        return 0
    if args.action == "run":
        prog = book.program(args.program)
        with modes.mode(args.mode):
            print(prog.render())
        return 0
    numbers = list(book.FIGURES) if args.figure == "all" else [args.figure]
    total_match = total = 0
    for number in numbers:
        text, matching, compared = _diff(number, args.mode)
        print(text)
        print()
        total_match, total = total_match + matching, total + compared
    if len(numbers) > 1:
        print(f"all figures: {total_match} of {total} cells match")
    return 0 if total_match == total else 1


if __name__ == "__main__":
    sys.exit(main())
