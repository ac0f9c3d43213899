"""Choose the one arithmetic model of the book's machine by the evidence of every
emulated figure (sarkp.book.judging): run every emulated program whole under each of
the 64 library models (which of SIN, COS, TAN, ATAN, ACOS, SQRT round their result to
REAL*4; the rest truncate) and print, per model, the cells reproduced, fixed and broken
(against double precision), best first.  The last line names the choice, which
sarkp.book.es_evm.ROUNDED must hold (tests/test_book_figures.py checks it against its
neighbours).  Run: python scripts/choose_arithmetic.py [--top N]"""

import argparse

from sarkp.book import judging


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=64, help="print the best N models")
    args = parser.parse_args()
    best, table = judging.choose()
    rows = sorted(table, key=lambda m: (-judging.score(table[m]), len(m)))
    figures = judging.EMULATED
    print("| rounding functions | reproduced | fixed | broken | "
          + " | ".join(f"Fig. {n}" for n in figures) + " |")
    print("|---" * (4 + len(figures)) + "|")
    for m in rows[:args.top]:
        c = table[m]
        print(f"| {' '.join(sorted(m)) or 'none (all truncate)'} | {judging.score(c)} | "
              f"{sum(f for _, f, _ in c.values())} | {sum(b for _, _, b in c.values())} | "
              + " | ".join(f"{c[n][0]} (+{c[n][1]} -{c[n][2]})" for n in figures) + " |")
    print(f"chosen: {' '.join(sorted(best)) or 'none'} rounds; every other function "
          f"truncates")


if __name__ == "__main__":
    main()
