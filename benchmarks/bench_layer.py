"""The cost of the layer: a sarkp call against the bare f2py call of its generated driver.

Issue 18's targets: a table routine's call within 3x of its bare driver call (DZKNDV on 37
points, DPRFLP on 26 points), a one-position DKNMA1 call within 1.5x of its bare call.
Times are CPU time of the process (``time.process_time``), the best of 7 repeats of a
``timeit`` loop; the bare call passes the same inputs, already converted, by keyword
(so the same script measures layers whose drivers order their arguments differently).

    python benchmarks/bench_layer.py        (against the installed sarkp)
"""

from __future__ import annotations

import math
import os
import time
import timeit

import numpy as np

import sarkp
from sarkp import _sarkp


def best(f, number):
    t = timeit.Timer(f, timer=time.process_time)
    return min(t.repeat(7, number)) / number


def case_dknma1():
    args = (0.1, 0.0, 0.4, 0.0, 0.35, 0.3, 0.3, 1.57, 0.0, 0.0, 0.9, 3.14, 0.0, 0.0, 1.0, 0.0)
    drv = _sarkp.drv_kinematics.dknma1_1
    return (lambda: sarkp.DKNMA1(*args)), (lambda: drv(0, *args)), 20000


def case_dzkndv(m=37):
    phi = np.linspace(0.0, 2 * math.pi, m)
    mpr, ispr = 40.0 * np.sin(phi), np.zeros(m)
    drv = _sarkp.drv_dynamics.dzkndv_1
    kw = dict(m=m, zm=float(m), w1=10.0, isc=12.0, mpr=mpr, ispr=ispr, aaa=1.0)
    return (lambda: sarkp.DZKNDV(m, float(m), 10.0, 12.0, mpr, ispr)), \
        (lambda: drv(0, **kw)), 5000


def case_dprflp(n=26):
    fi = np.linspace(0.0, 2 * math.pi, n)
    s = 0.02 * (1 - np.cos(fi))
    v, a = 0.02 * np.sin(fi), 0.02 * np.cos(fi)
    drv = _sarkp.drv_cams.dprflp_1
    kw = dict(n=n, ro=0.05, excntr=0.0, w=10.0, fi=fi, a=a, v=v, s=s, ald=math.pi / 6)
    return (lambda: sarkp.DPRFLP(n, 0.05, 0.0, 10.0, fi, a, v, s)), \
        (lambda: drv(0, **kw)), 5000


def main():
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print(f"{'case':<28s} {'sarkp':>10s} {'bare f2py':>10s} {'ratio':>6s}")
    for name, case in [("DKNMA1, one position", case_dknma1),
                       ("DZKNDV, 37 points", case_dzkndv),
                       ("DPRFLP, 26 points", case_dprflp)]:
        layer, bare, number = case()
        layer(), bare()
        t_layer, t_bare = best(layer, number), best(bare, number)
        print(f"{name:<28s} {t_layer * 1e6:8.2f}us {t_bare * 1e6:8.2f}us "
              f"{t_layer / t_bare:6.2f}")


if __name__ == "__main__":
    main()
