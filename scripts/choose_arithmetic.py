"""Choose the one arithmetic model of the book's machine by the evidence of every
emulated figure (sarkp.book.judging).

1. Every emulated program runs whole under each of the 64 library models (which of SIN,
   COS, TAN, ATAN, ACOS, SQRT round their result to REAL*4; the rest truncate), program
   X with the link lengths of its double-precision fit; the cells the runs reproduce are
   counted (the cells the lengths are fitted to are no evidence).
2. The lengths are inputs fitted in some arithmetic, so the best ``--refit`` models of
   step 1 are judged again, each with program X's lengths refitted in that model's
   arithmetic (scripts/fit_x_links.py's minimax fit, from the double fit).  The best of
   these is the book's model (ties: fewer rounding functions); its lengths are the one
   set program X runs with (prog_x.FITTED_LINKS; sarkp.book.es_evm.ROUNDED holds the
   model; tests/test_book_figures.py checks it against its neighbours).

Prints both tables, best first, and the choice.  Run: python scripts/choose_arithmetic.py
[--refit N] (a few minutes: each refit runs the emulated chain some hundred times).
"""

import argparse
import pathlib
import sys

import numpy as np

from sarkp.book import es_evm, judging, x_arithmetic, x_data

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import fit_x_links  # noqa: E402  (the fit, a script beside this one)


def table(rows, counts, title):
    figures = judging.EMULATED
    print(title)
    print("| rounding functions | reproduced | fixed | broken | "
          + " | ".join(f"Fig. {n}" for n in figures) + " |")
    print("|---" * (4 + len(figures)) + "|")
    for m in rows:
        c = counts[m]
        print(f"| {' '.join(sorted(m)) or 'none (all truncate)'} | {judging.score(c)} | "
              f"{sum(f for _, f, _ in c.values())} | {sum(b for _, _, b in c.values())} | "
              + " | ".join(f"{c[n][0]} (+{c[n][1]} -{c[n][2]})" for n in figures) + " |")
    print()


def use_lengths(lengths):
    x_data.FITTED_LINKS.clear()
    x_data.FITTED_LINKS.update(lengths)
    x_arithmetic._run.cache_clear()


def refit(model) -> dict:
    """Program X's lengths fitted with the chain in the ES EVM's arithmetic under
    ``model``, from the double fit."""
    double = x_data.REFITTED_LINKS["double"]
    fit_x_links.ARITHMETIC[0] = "es-evm"
    with es_evm.library_model(model):
        _, x, _, _ = fit_x_links.fit(np.array([double[n] for n in fit_x_links.NAMES]))
    return dict(zip(fit_x_links.NAMES, map(float, x)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refit", type=int, default=8,
                        help="judge the best N models again with refitted lengths")
    parser.add_argument("--top", type=int, default=16, help="rows of the first table")
    args = parser.parse_args()
    use_lengths(x_data.REFITTED_LINKS["double"])
    _, first = judging.choose()
    rows = sorted(first, key=lambda m: (-judging.score(first[m]), len(m)))
    table(rows[:args.top], first, "1. program X with the double fit's lengths")
    second, lengths = {}, {}
    for m in rows[:args.refit]:
        lengths[m] = refit(m)
        use_lengths(lengths[m])
        second[m] = judging.model_counts(m)
    best = max(second, key=lambda m: (judging.score(second[m]), -len(m)))
    table(sorted(second, key=lambda m: (-judging.score(second[m]), len(m))), second,
          "2. program X with the lengths refitted under each model")
    print(f"chosen: {' '.join(sorted(best)) or 'none'} round; every other function "
          f"truncates")
    print("FITTED_LINKS = {" + ", ".join(f'"{n}": {v:.8f}' for n, v in lengths[best].items())
          + "}")


if __name__ == "__main__":
    main()
