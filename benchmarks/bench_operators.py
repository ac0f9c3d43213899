"""Chapter 2: call overhead and array throughput of DVKT and DSMVKT, with their error.

Run: ``python benchmarks/bench_operators.py`` (from outside the source tree, or with
the package installed; ``bash benchmarks/run.sh`` does both).  Prints a table and
writes ``benchmarks/results/operators.csv``.
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import time
import timeit

import mpmath
import numpy as np

import sarkp
from sarkp import _sarkp
from sarkp.modes import MODE_CODE

N_ARRAY = 10**6
OUT = pathlib.Path(__file__).with_name("results")


def best_per_call(stmt, number, repeat=7):
    """Best of ``repeat`` in CPU time of this process (time.process_time), so that time
    spent waiting for one of the shared cores does not count."""
    return min(timeit.repeat(stmt, number=number, repeat=repeat,
                             timer=time.process_time)) / number


def dvkt_error(n=2000, seed=1):
    """Largest error of DVKT's RZ (relative) and FI (absolute) against mpmath."""
    rng = np.random.default_rng(seed)
    pts = rng.uniform(-10, 10, (n, 4))
    rz, fi = sarkp.DVKT(*pts.T)
    mpmath.mp.dps = 40
    err_rz = err_fi = 0.0
    for (x1, y1, x2, y2), r, f in zip(pts, rz, fi):
        dx, dy = mpmath.mpf(x2) - x1, mpmath.mpf(y2) - y1
        err_rz = max(err_rz, float(abs(r - mpmath.hypot(dx, dy)) / mpmath.hypot(dx, dy)))
        err_fi = max(err_fi, float(abs(f - mpmath.atan2(dy, dx))))
    return err_rz, err_fi


def main():
    rows = []
    drv = _sarkp.drv_operators          # the generated drivers DVKT_1 and DVKT_n
    mode = MODE_CODE.get()
    f_dvkt = drv.dvkt_1
    rows.append(("DVKT scalar, sarkp.DVKT", best_per_call(
        lambda: sarkp.DVKT(0.1, 0.2, 3.0, 4.0), 20000), "per call"))
    rows.append(("DVKT scalar, raw f2py call", best_per_call(
        lambda: f_dvkt(mode, 0.1, 0.2, 3.0, 4.0), 20000), "per call"))
    rows.append(("DVKT scalar, pure Python math", best_per_call(
        lambda: (math.hypot(2.9, 3.8), math.atan2(3.8, 2.9)), 20000), "per call"))

    rng = np.random.default_rng(0)
    a = [rng.uniform(-1, 1, N_ARRAY) for _ in range(4)]
    rows.append((f"DVKT arrays of {N_ARRAY:.0e}, sarkp.DVKT",
                 best_per_call(lambda: sarkp.DVKT(*a), 1, 5) / N_ARRAY, "per element"))
    inc = np.ones(4, np.int32)
    rows.append((f"DVKT arrays of {N_ARRAY:.0e}, raw driver dvkt_n",
                 best_per_call(lambda: drv.dvkt_n(mode, inc, 0, *a, np.empty((2, N_ARRAY)).T,
                                                  np.zeros(N_ARRAY, np.int32)), 1, 5)
                 / N_ARRAY,
                 "per element"))
    rows.append((f"DVKT arrays of {N_ARRAY:.0e}, NumPy hypot+arctan2",
                 best_per_call(lambda: (np.hypot(a[2] - a[0], a[3] - a[1]),
                                        np.arctan2(a[3] - a[1], a[2] - a[0])), 1, 5)
                 / N_ARRAY, "per element"))
    rows.append((f"DSMVKT arrays of {N_ARRAY:.0e}, sarkp.DSMVKT",
                 best_per_call(lambda: sarkp.DSMVKT(*a), 1, 5) / N_ARRAY, "per element"))
    err_rz, err_fi = dvkt_error()

    OUT.mkdir(exist_ok=True)
    with open(OUT / "operators.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "seconds", "per"])
        w.writerows(rows)
    print("load average %.2f, %.2f, %.2f" % os.getloadavg())
    print(f"{'case':48s} {'time':>12s}")
    for name, sec, per in rows:
        print(f"{name:48s} {sec * 1e9:9.1f} ns  {per}")
    print(f"DVKT error against mpmath (2000 random segments): RZ {err_rz:.1e} relative, "
          f"FI {err_fi:.1e} rad")


if __name__ == "__main__":
    main()
