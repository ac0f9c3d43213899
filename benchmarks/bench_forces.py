"""Chapters 7-8: force analysis per position beside kinematics, and DZKNDV's run time
against its error.

1. Per crank position, the array path (one call per routine over all positions) of
   * the kinematics of one RRR group (DPRM1 + DSKOR1 + DUSKR1) and its force analysis
     (DNMAF1, DNMA1);
   * program IV.15 (all five groups, positions to accelerations) and program VII.10 on
     top of it (the five DNMAF calls and the reductions), over N crank positions.
2. DZKNDV on the closed-form case (constant inertia J, MPR = a sin(phi) + c, corrected
   mode: the energy equation solved exactly, so the only error is the trapezoid rule's):
   run time and max |WPR - exact| for M = 10 ... 10^6 points.
3. DMHVK's flywheel inertia against M on the same case: exact J_m = 2a/(delta W1^2) - J.

Run: ``python benchmarks/bench_forces.py`` from outside the source tree (sarkp installed).
Prints the tables and writes ``benchmarks/results/forces.csv``.
"""

from __future__ import annotations

import csv
import ctypes
import math
import os
import pathlib
import shutil
import subprocess
import tempfile
import time
import timeit

import numpy as np

import sarkp
from sarkp.book import prog_iv_15, prog_vii_10

HERE = pathlib.Path(__file__).resolve().parent
OUT = HERE / "results"
_Q = os.environ.get("SARKP_BENCH_QUICK") == "1"
N = 10**4 if _Q else 10**5
REPEAT = 3 if _Q else 5


def best(fn, number=1):
    """Best of REPEAT runs, in CPU time of the process (the two cores are shared)."""
    timer = timeit.Timer(fn, timer=time.process_time)
    return min(timer.repeat(number=number, repeat=REPEAT)) / number


def per_position():
    rows = []
    phi = np.linspace(0.0, 2 * np.pi, N, endpoint=False)
    roa, rab, rcb, xc = 0.1, 0.35, 0.3, 0.4
    xa, ya = roa * np.cos(phi), roa * np.sin(phi)
    fi2, fi3, xb, yb = sarkp.DPRM1(xa, ya, xc, 0.0, rab, rcb, -1.0)

    def kinematics():
        f2, f3, bx, by = sarkp.DPRM1(xa, ya, xc, 0.0, rab, rcb, -1.0)
        v = sarkp.DSKOR1(rab, f2, rcb, f3, 3.0 * roa, phi + np.pi / 2, 0.0, 0.0)
        sarkp.DUSKR1(9.0 * roa, phi + np.pi, 0.0, 0.0, rab, f2, rcb, f3, v.W2, v.W3)

    def dnmaf1():
        sarkp.DNMAF1(xa, ya, xb, yb, xc, 0.0, 0.5 * (xa + xb), 0.5 * (ya + yb), 50.0,
                     -np.pi / 2, 0.5 * (xc + xb), 0.5 * yb, 80.0, -np.pi / 2, 0.0, 5.0)

    l3 = np.hypot(xb - xc, yb)
    fcb = np.arctan2(yb, xb - xc)

    def dnma1():
        sarkp.DNMA1(rab, fi2, l3, fcb, -0.5 * rab, -0.5 * rcb, 0.0, 50.0, -np.pi / 2, 5.0,
                    80.0, -np.pi / 2)

    for name, fn in (("RRR kinematics (DPRM1+DSKOR1+DUSKR1)", kinematics),
                     ("RRR forces DNMAF1", dnmaf1), ("RRR forces DNMA1", dnma1)):
        rows.append((name, N, best(fn) / N * 1e9))
    angles = -np.arange(N) * 2 * np.pi / N
    t_kin = best(lambda: prog_iv_15.compute(angles=angles), 1)
    t_all = best(lambda: prog_vii_10.compute(angles=angles), 1)
    rows.append(("IV.15 kinematics, 5 groups", N, t_kin / N * 1e9))
    rows.append(("VII.10 forces on top of IV.15 (difference)", N, (t_all - t_kin) / N * 1e9))
    return rows


class DNMA1Loop:
    """dnma1.c (the same statics, written by hand) compiled with cc -O3 -march=native into
    a temporary directory, called through ctypes; the outputs allocated per call, as
    sarkp does.  ``loop`` takes every input per position, ``const`` the loads once."""

    FLAGS = ["-O3", "-march=native", "-shared", "-fPIC"]

    def __init__(self):
        cc = shutil.which("cc") or shutil.which("gcc")
        if cc is None:
            raise OSError("no C compiler (cc) found")
        self._tmp = tempfile.TemporaryDirectory()
        lib = pathlib.Path(self._tmp.name) / "libdnma1.so"
        subprocess.run([cc, *self.FLAGS, "-o", str(lib), str(HERE / "dnma1.c"), "-lm"],
                       check=True)
        self.cmd = " ".join(["cc", *self.FLAGS, "dnma1.c", "-lm"])
        self._lib = ctypes.CDLL(str(lib))
        arr = np.ctypeslib.ndpointer(np.float64, flags="C_CONTIGUOUS")
        self._lib.dnma1_loop.argtypes = [ctypes.c_long] + [arr] * 12 + [arr]
        self._lib.dnma1_const.argtypes = [ctypes.c_long] + [arr] * 4 + \
            [ctypes.c_double] * 8 + [arr]
        self._lib.dnma1_loop.restype = self._lib.dnma1_const.restype = ctypes.c_long

    def loop(self, *args):
        n = args[1].size
        out = np.empty((6, n))
        self._lib.dnma1_loop(n, *args, out)
        return out

    def const(self, *args):
        n = args[1].size
        out = np.empty((6, n))
        self._lib.dnma1_const(n, *args, out)
        return out


def dnma1_head_to_head():
    """sarkp.DNMA1 (corrected mode: the adapter over the force kernel of groups.f90;
    as-printed: the printed form) on arrays against the hand-written C loop of the same
    statics over N positions of the crank-rocker above, (a) with loads that vary with the
    position (inertia loads: every input an array) and (b) with constant loads (G2, G3
    passed once: C hoists their sines and cosines, sarkp's Fortran takes them per
    position).  Also the largest difference between the two (rounding)."""
    phi = np.linspace(0.0, 2 * np.pi, N, endpoint=False)
    roa, rab, rcb, xc = 0.1, 0.35, 0.3, 0.4
    xa, ya = roa * np.cos(phi), roa * np.sin(phi)
    fi2, fi3, xb, yb = sarkp.DPRM1(xa, ya, xc, 0.0, rab, rcb, -1.0)
    l2 = np.full(N, rab)
    l3 = np.hypot(xb - xc, yb)
    fcb = np.arctan2(yb, xb - xc)
    loads = (-0.5 * rab, -0.5 * rcb, 0.0, 50.0, -np.pi / 2, 5.0, 80.0, -np.pi / 2)
    varying = tuple(np.full(N, v) + 0.01 * np.sin(phi) for v in loads)
    c = DNMA1Loop()
    rows, diff = [], 0.0
    for case, args, cfun in (("varying loads", (l2, fi2, l3, fcb) + varying, c.loop),
                             ("constant loads", (l2, fi2, l3, fcb) + loads, c.const)):
        t_c = best(lambda: cfun(*args))
        t_s = best(lambda: sarkp.DNMA1(*args))
        with sarkp.as_printed():
            t_p = best(lambda: sarkp.DNMA1(*args))
        r, o = sarkp.DNMA1(*args), cfun(*args)
        diff = max(diff, np.abs(r.RA - o[0]).max() / r.RA.max(),
                   np.abs(r.RC - o[4]).max() / r.RC.max(),
                   np.abs(np.cos(r.GA) - np.cos(o[1])).max())
        rows += [(f"{case}: hand-written C loop (dnma1.c)", N, t_c / N * 1e9),
                 (f"{case}: sarkp.DNMA1, corrected mode", N, t_s / N * 1e9),
                 (f"{case}: sarkp.DNMA1, as-printed (printed form)", N, t_p / N * 1e9)]
    return rows, diff, c.cmd


def closed_form(phi, a, j, w1):
    s = w1 * math.sqrt(2.0 * j)
    e0 = ((s - 2.0 * a / s) / 2.0) ** 2
    return np.sqrt(2.0 * (e0 + a * (1.0 - np.cos(phi))) / j)


def dzkndv_error():
    a, c, j, w1, delta = 40.0, -15.0, 12.0, 3.0, 0.02
    rows = []
    exact_jm = 2 * a / (delta * w1**2) - j
    for m in (10, 31, 101, 1001, 10**4, 10**5, 10**6):
        if _Q and m > 10**5:
            continue
        phi = np.linspace(0.0, 2 * np.pi, m)
        mpr, ispr = a * np.sin(phi) + c, np.zeros(m)
        number = max(1, 10**5 // m)
        t = best(lambda: sarkp.DZKNDV(m, float(m), w1, j, mpr, ispr), number)
        r = sarkp.DZKNDV(m, float(m), w1, j, mpr, ispr)
        err = np.abs(r.WPR - closed_form(phi, a, j, w1)).max()
        jm = sarkp.DMHVK(m, delta, j, w1, r.DEC).IMHVK
        rows.append((m, t * 1e6, err, abs(jm - exact_jm) / exact_jm))
    return rows


def main():
    OUT.mkdir(exist_ok=True)
    pos = per_position()
    print(f"{'per crank position (array path)':48s} {'N':>8s} {'ns/position':>12s}")
    for name, n, ns in pos:
        print(f"{name:48s} {n:8d} {ns:12.0f}")
    h2h, diff, cmd = dnma1_head_to_head()
    print()
    print(f"DNMA1 head to head ({cmd}); largest relative difference {diff:.1e}")
    for name, n, ns in h2h:
        print(f"{name:56s} {n:8d} {ns:12.0f}")
    print(f"ratio sarkp (corrected) / C loop: varying loads {h2h[1][2] / h2h[0][2]:.2f}, "
          f"constant loads {h2h[4][2] / h2h[3][2]:.2f}")
    pos += h2h
    dz = dzkndv_error()
    print()
    print(f"{'M':>8s} {'DZKNDV us':>10s} {'max|WPR-exact|':>15s} {'IMHVK rel.err':>14s}")
    for m, us, err, jerr in dz:
        print(f"{m:8d} {us:10.1f} {err:15.3e} {jerr:14.3e}")
    with open(OUT / "forces.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "N", "ns_per_position"])
        w.writerows(pos)
        w.writerow([])
        w.writerow(["M", "dzkndv_us", "max_abs_error_wpr", "imhvk_rel_error"])
        w.writerows(dz)


if __name__ == "__main__":
    main()
