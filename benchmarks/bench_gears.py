"""Chapter 6: DZBPL's search time, DUGINV's iterations, time and error (the book's
fixed-point iteration against corrected mode's full-precision root).

Run: ``python benchmarks/bench_gears.py`` (from outside the source tree, with the package
installed; ``bash benchmarks/run.sh`` does both).  Prints tables and writes
``benchmarks/results/gears.csv``.
"""

from __future__ import annotations

import csv
import math
import pathlib
import timeit

import mpmath
import numpy as np

import sarkp
from sarkp import DUGINV, DZBPL, RequirementError
from sarkp.book import prog_vi_2

OUT = pathlib.Path(__file__).with_name("results")
N_ARRAY = 10**6
PI_BOOK = 3.14159


def best(stmt, number=1, repeat=5):
    return min(timeit.repeat(stmt, number=number, repeat=repeat)) / number


def dzbpl_rows():
    rows = []

    def all_calls():
        for call in prog_vi_2.CALLS:
            try:
                DZBPL(*call)
            except RequirementError:
                pass

    # the widest search the declaration allows: z1 from 1 to 10000 with no admissible set,
    # so every z1 is tried (the ratio 999/1000 with 6 blocks of planets 1000:999)
    widest = (6, 999, 1000, 1000, 999, 1, 10000, 1)
    for mode in ("as-printed", "corrected"):
        with sarkp.mode(mode):
            rows.append(("DZBPL", mode, "the 19 calls of VI.2", best(all_calls, 20), "s"))
            try:
                DZBPL(*widest)
                found = "found"
            except RequirementError:
                found = "none"
            rows.append(("DZBPL", mode, f"z1 = 1..10000, no set ({found})",
                         best(lambda: DZBPL(*widest, on_error="nan"), 5), "s"))
    return rows


def book_steps(v, tchnst, x0=PI_BOOK / 18):
    """Steps of the book's iteration (L4209-4215) until a step is below TCHNST."""
    x, n = x0, 0
    while True:
        x1 = math.atan(x + v)
        n += 1
        if abs(x1 - x) < tchnst:
            return n
        x = x1


def duginv_rows():
    rows = []
    mpmath.mp.dps = 40
    rng = np.random.default_rng(6)
    angles = rng.uniform(math.radians(5), math.radians(80), N_ARRAY)
    v = np.tan(angles) - angles
    sample = v[:2000]
    exact = np.array([float(mpmath.findroot(lambda t: mpmath.tan(t) - t - mpmath.mpf(x),
                                            mpmath.atan(x + 1))) for x in sample])
    # corrected: time per call and per element, error against mpmath
    got = DUGINV(sample, PI_BOOK / 18, 1e-5)
    err = float(np.max(np.abs(got - exact) / exact))
    rows.append(("DUGINV", "corrected", "scalar call",
                 best(lambda: DUGINV(0.0149, 0.1745, 1e-5), 20000, 5), "s per call"))
    rows.append(("DUGINV", "corrected", f"arrays of {N_ARRAY:.0e}, 5-80 deg",
                 best(lambda: DUGINV(v, 0.1745, 1e-5)) / N_ARRAY, "s per element"))
    rows.append(("DUGINV", "corrected", "max relative error, 5-80 deg", err, ""))
    small = np.geomspace(1e-8, math.radians(5), 2000)
    vs = np.array([float(mpmath.tan(mpmath.mpf(a)) - mpmath.mpf(a)) for a in small])
    exact_s = np.array([float(mpmath.findroot(
        lambda t: mpmath.tan(t) - t - mpmath.mpf(x), mpmath.cbrt(3 * mpmath.mpf(x))))
        for x in vs])
    err_s = float(np.max(np.abs(DUGINV(vs, 0.1745, 1e-5) - exact_s) / exact_s))
    rows.append(("DUGINV", "corrected", "max relative error, 1e-8 rad - 5 deg", err_s, ""))
    # as printed: the fixed-point iteration for several tolerances
    sub = v[:200000]
    for tchnst in (1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-10):
        with sarkp.as_printed():
            t = best(lambda: DUGINV(sub, PI_BOOK / 18, tchnst), 1, 3) / sub.size
            got = DUGINV(sample, PI_BOOK / 18, tchnst)
        steps = [book_steps(x, tchnst) for x in sample[:500]]
        err = float(np.max(np.abs(got - exact)))
        rows.append(("DUGINV", "as-printed", f"TCHNST = {tchnst:g}: steps mean/max",
                     f"{np.mean(steps):.1f}/{max(steps)}", ""))
        rows.append(("DUGINV", "as-printed", f"TCHNST = {tchnst:g}: time", t,
                     "s per element"))
        rows.append(("DUGINV", "as-printed", f"TCHNST = {tchnst:g}: max error", err, "rad"))
    return rows


def main():
    rows = dzbpl_rows() + duginv_rows()
    OUT.mkdir(exist_ok=True)
    with open(OUT / "gears.csv", "w", newline="") as f:
        csv.writer(f).writerows([("routine", "mode", "case", "value", "unit")] + rows)
    for routine, mode, case, value, unit in rows:
        shown = f"{value:.3g}" if isinstance(value, float) else value
        print(f"{routine:7s} {mode:10s} {case:45s} {shown} {unit}")


if __name__ == "__main__":
    main()
