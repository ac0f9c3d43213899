#!/usr/bin/env python3
"""Fit program X's link lengths to the printed Fig. 91 (docs/ERRATA.md E-X-LINKS-1).

No DSNTZ1 gives the lengths the printed run used (E-DSNTZ1-4), and Fig. 84 prints them to
3 decimals only, so as-printed mode takes them from this fit (one set for the whole
program: the fit in the book's arithmetic, ``--arithmetic es-evm``, from the double fit):

* unknowns: ROA, RAB, ROC, RCD (= RCB) and RDE, in metres;
* cells: every printed cell of Fig. 91's 37 positions that depends on the lengths, 587
  of them: the 16 columns but FI1 (positions FI2 FICB XE FIDE XB YB, velocities W2 W3 VE
  ALE W4, accelerations E2 E3 E4 AE BE), less five: the three slider directions of
  E-FIG91-10 (exactly 0 or pi for any lengths: no length moves them) and the two E4
  cells of E-FIG91-9 (no lengths bring them within a unit; with them the minimax is
  decided by these two alone).  Computed by ``prog_x.kinematics`` in as-printed mode
  (PI = 3.14159, the ES EVM's crank angle, E-DUSKR1-1, E-X-W4).  The diff reports these
  cells as "fitted", not as reproduced;
* objective: minimax, the largest |computed - printed| over those cells in units of the
  last printed digit (a printed cell is known to half a unit, so the fit looks for
  lengths that put every cell within half a unit, and otherwise as close as it can);
* method: sequential linear programming (the cells' Jacobian by central differences,
  each step a linear program for the minimax, scipy.optimize.linprog), from the least-
  squares start, until a step no longer lowers the worst cell;
* uncertainty of each length: the printed cells are the true values rounded, an error
  uniform over +-0.5 units (standard deviation 1/sqrt(12) units); propagated through the
  fit's Jacobian J (cells x lengths, units per metre) the covariance of the lengths is
  (J^T J)^-1 / 12 and each length's standard uncertainty the square root of its diagonal.

* the arithmetic-model spread: ``--arithmetic es-evm`` (the book's ES EVM model) or
  ``ieee-single`` refits the same minimax with the chain in that arithmetic
  (sarkp.book.x_arithmetic), steered by the double chain's Jacobian, from the double fit;
  ``prog_x.FITTED_LINKS`` holds the ES EVM fit, ``prog_x.REFITTED_LINKS`` the others, and
  ``prog_x.links_uncertainty()`` widens the standard uncertainty by the larger move from
  the ES EVM fit (``--check`` compares).

Prints the lengths (as ``prog_x`` holds them), the worst cell, the number of fitted cells
within half a unit, and (double) the uncertainties.  ``--check`` compares with what
``prog_x`` holds (exit status 1 when they differ by more than 1e-8 m, or the
uncertainties to the two digits ``prog_x.FITTED_UNCERTAINTY`` keeps).
Run: ``python scripts/fit_x_links.py`` (needs scipy; a few seconds).
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

import sarkp
import sarkp.book.figures
from sarkp.book import prog_x

NAMES = ("ROA", "RAB", "ROC", "RCD", "RDE")


def fitted_cells():
    """The printed cells of Fig. 91 the fit uses: ``prog_x.fitted_cells()``, the one
    definition the diff uses too (see the module's docstring)."""
    return prog_x.fitted_cells()


#: the arithmetic the chain runs in: "double" (sarkp, as-printed mode), or "es-evm" /
#: "ieee-single" (sarkp.book.x_arithmetic, for the refits that widen the uncertainty)
ARITHMETIC = ["double"]


def units(lengths, cells) -> np.ndarray:
    """(computed - printed) / unit for ``cells`` with ``lengths`` (ROA RAB ROC RCD RDE)."""
    got = computed(lengths)
    return np.array([(got[(c.row, c.column)] - c.value) / c.unit for c in cells])


def within(lengths, cells) -> int:
    """How many of ``cells`` the chain with ``lengths`` puts within half a unit (the
    diff's exact rule, sarkp.book.figures.within_half)."""
    got = computed(lengths)
    return sum(sarkp.book.figures.within_half(c, got[(c.row, c.column)]) for c in cells)


def computed(lengths) -> dict:
    """Fig. 91's cells computed with ``lengths`` in the chosen arithmetic."""
    links = dict(zip(NAMES, lengths))
    if ARITHMETIC[0] == "double":
        with sarkp.as_printed():
            k = prog_x.kinematics(links)
    else:
        from sarkp.book import x_arithmetic
        k = x_arithmetic.run(ARITHMETIC[0], links)["kinematics"]
    return prog_x.stage_cells("kinematics", k)


def jacobian(lengths, cells, step=1e-7) -> np.ndarray:
    """The cells' derivatives by the lengths, always of the double-precision chain: a
    step of 1e-7 m is below REAL*4's resolution (a length near 2 m has a last hex digit
    of 9.5e-7 m), so a refit in another arithmetic steers by the smooth chain and judges
    each step by the other arithmetic's cells."""
    arithmetic, ARITHMETIC[0] = ARITHMETIC[0], "double"
    try:
        return _jacobian(lengths, cells, step)
    finally:
        ARITHMETIC[0] = arithmetic


def _jacobian(lengths, cells, step) -> np.ndarray:
    out = np.empty((len(cells), len(lengths)))
    for i in range(len(lengths)):
        d = np.zeros(len(lengths))
        d[i] = step
        out[:, i] = (units(lengths + d, cells) - units(lengths - d, cells)) / (2 * step)
    return out


def least_squares(start, cells, rounds=5) -> np.ndarray:
    x = np.array(start, float)
    for _ in range(rounds):
        x = x - np.linalg.lstsq(jacobian(x, cells), units(x, cells), rcond=None)[0]
    return x


def minimax(start, cells, trust=1e-5, rounds=60) -> np.ndarray:
    """Sequential linear programming for min over lengths of max |units|."""
    from scipy.optimize import linprog
    x = np.array(start, float)
    u = units(x, cells)
    worst = np.abs(u).max()
    n = len(x)
    for _ in range(rounds):
        j = jacobian(x, cells)
        # variables (dx, t): minimize t with -t <= u + J dx <= t, |dx_i| <= trust
        c = np.zeros(n + 1)
        c[-1] = 1.0
        ones = np.ones((len(u), 1))
        a = np.vstack([np.hstack([j, -ones]), np.hstack([-j, -ones])])
        b = np.concatenate([-u, u])
        res = linprog(c, A_ub=a, b_ub=b, bounds=[(-trust, trust)] * n + [(0, None)],
                      method="highs")
        trial = x + res.x[:n]
        ut = units(trial, cells)
        if np.abs(ut).max() < worst - 1e-6:
            x, u, worst = trial, ut, np.abs(ut).max()
        else:
            trust /= 4.0
            if trust < 1e-10:
                break
    return x


def uncertainty(lengths, cells) -> np.ndarray:
    """Standard uncertainty of each length from the printed cells' rounding (+-0.5 units,
    uniform: variance 1/12 unit**2), propagated through the fit's Jacobian."""
    j = jacobian(lengths, cells)
    return np.sqrt(np.diag(np.linalg.inv(j.T @ j) / 12.0))


def fit(start=None):
    cells = fitted_cells()
    with sarkp.as_printed():
        s = prog_x.synthesis()
    if start is None:
        start = np.array([0.166, 2.335, 2.090, s["RCD_DSNTZR"], s["RDE_DSNTZR"]])
    x = minimax(least_squares(start, cells), cells)
    u = units(x, cells)
    return cells, x, u, uncertainty(x, cells)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless prog_x holds this fit's result")
    parser.add_argument("--arithmetic", choices=("double", "es-evm", "ieee-single"),
                        default="double",
                        help="double: the fit from the printed 3-decimal lengths "
                             "(prog_x.REFITTED_LINKS['double'], FITTED_UNCERTAINTY); "
                             "es-evm: from it, the fit in the book's arithmetic, the one "
                             "set the program runs with (prog_x.FITTED_LINKS); "
                             "ieee-single: from it, the fit in IEEE single "
                             "(REFITTED_LINKS['ieee-single'])")
    args = parser.parse_args(argv)
    ARITHMETIC[0] = args.arithmetic
    double = prog_x.REFITTED_LINKS["double"]
    if args.arithmetic != "double":
        start = np.array([double[n] for n in NAMES])
        cells, x, u, sigma = fit(start)
        print(f"refit under {args.arithmetic}: minimax over {len(cells)} cells of Fig. 91")
        print(f'"{args.arithmetic}": {{' + ", ".join(f'"{n}": {v:.8f}' for n, v in zip(NAMES, x))
              + "}")
        print(f"worst cell {np.abs(u).max():.3f} units; {within(x, cells)} of {len(cells)} "
              f"within half a unit")
        for n, v in zip(NAMES, x):
            print(f"  {n}: moves {1e6 * (v - double[n]):+.1f} um from the double fit")
        if args.check:
            kept = (prog_x.FITTED_LINKS if args.arithmetic == "es-evm"
                    else prog_x.REFITTED_LINKS[args.arithmetic])
            if max(abs(kept[n] - v) for n, v in zip(NAMES, x)) > 1e-8:
                print(f"prog_x does not hold this {args.arithmetic} fit's result",
                      file=sys.stderr)
                return 1
        return 0
    cells, x, u, sigma = fit()
    print(f"minimax fit of {', '.join(NAMES)} to {len(cells)} cells of Fig. 91 (all but "
          f"FI1 and {', '.join(sorted(prog_x.FIT_LEFT_OUT))}), double precision")
    print('"double": {' + ", ".join(f'"{n}": {v:.8f}' for n, v in zip(NAMES, x)) + "}")
    print(f"worst cell {np.abs(u).max():.3f} units; {within(x, cells)} "
          f"of {len(cells)} within half a unit")
    for n, v, e in zip(NAMES, x, sigma):
        print(f"  {n} = {v:.8f} m +- {e:.1e} m (standard uncertainty)")
    if args.check:
        used = np.array([double[n] for n in NAMES])
        if np.abs(used - x).max() > 1e-8:
            print("prog_x.REFITTED_LINKS['double'] is not this fit's result", file=sys.stderr)
            return 1
        if any(float(f"{e:.1e}") != prog_x.FITTED_UNCERTAINTY[n]
               for n, e in zip(NAMES, sigma)):
            print("prog_x.FITTED_UNCERTAINTY is not this fit's result (to two digits)",
                  file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
