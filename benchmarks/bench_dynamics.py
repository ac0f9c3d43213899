"""Chapter 8: DZKNDV against a hand-written compiled loop of the same formula (issue 20),
and sarkp.motion / sarkp.flywheel (issue 19): run time and error.

1. DZKNDV, corrected mode, for M = 37 ... 10^6 points: ``sarkp.DZKNDV`` (the layer and
   the Fortran), the raw generated driver ``_sarkp.drv_dynamics.dzkndv_1`` (no layer),
   and ``dzkndv.c`` (hand-written: trapezoid work, ASUM, EV, DEC, E0 in closed form
   from DEC's extremes, one pass for WPR with the check of its extremes, EPR), compiled
   with cc -O3 -march=native into a temporary directory and called through ctypes, its
   six outputs allocated per call as f2py does.  Two cases: a constant inertia
   (ISPR = 0, MPR = 40 sin(phi) - 15) and a variable one (ISPR = 1 + sin(phi)^2).
2. sarkp.motion from rest and steady, sarkp.flywheel: run time against the error of
   omega (against closed forms: constant J and M from rest; constant J, M = a sin + c
   steady) for n = 37 ... 10^5 points.

Timings: best of REPEAT repeats of CPU time of the process (time.process_time), the
paths of one size interleaved (each repeat runs every path).  Run:
``python benchmarks/bench_dynamics.py`` from outside the source tree (sarkp installed).
"""

from __future__ import annotations

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
from sarkp import _sarkp

HERE = pathlib.Path(__file__).resolve().parent
_Q = os.environ.get("SARKP_BENCH_QUICK") == "1"
# odd sizes: phi = pi is a grid point, where the closed forms' omega has its extreme
SIZES = (37, 1001, 10**4 + 1, 10**5 + 1) + (() if _Q else (10**6 + 1,))
REPEAT = 3 if _Q else 7
C_FLAGS = ["-O3", "-march=native", "-shared", "-fPIC"]
W1, ISC = 3.0, 12.0


class CLoop:
    """dzkndv.c compiled into a temporary directory, called through ctypes."""

    def __init__(self):
        cc = shutil.which("cc") or shutil.which("gcc")
        if cc is None:
            raise OSError("no C compiler (cc) found")
        self._tmp = tempfile.TemporaryDirectory()
        lib = pathlib.Path(self._tmp.name) / "libdzkndv.so"
        subprocess.run([cc, *C_FLAGS, "-o", str(lib), str(HERE / "dzkndv.c"), "-lm"],
                       check=True)
        self.cmd = " ".join(["cc", *C_FLAGS, "dzkndv.c", "-lm"])
        self._lib = ctypes.CDLL(str(lib))
        arr = np.ctypeslib.ndpointer(np.float64, flags="C_CONTIGUOUS")
        self._lib.dzkndv.argtypes = [ctypes.c_int, ctypes.c_double, ctypes.c_double] + \
            [arr] * 8
        self._lib.dzkndv.restype = ctypes.c_int

    def __call__(self, m, w1, isc, mpr, ispr):
        out = [np.empty(m) for _ in range(6)]
        if self._lib.dzkndv(m, w1, isc, mpr, ispr, *out):
            raise ValueError("dzkndv.c: the extremes moved or no real root")
        return out


def interleaved(paths, repeat=REPEAT, min_time=0.05):
    """Best CPU time per call of each path, the paths interleaved in every repeat."""
    timers = {}
    for name, fn in paths.items():
        t = timeit.Timer(fn, timer=time.process_time)
        t.timeit(1)
        timers[name] = (t, max(1, int(min_time / max(t.timeit(1), 1e-7))))
    best = {name: math.inf for name in paths}
    for _ in range(repeat):
        for name, (t, number) in timers.items():
            best[name] = min(best[name], t.timeit(number) / number)
    return best


def dzkndv_table(cloop):
    print("\n1. DZKNDV, corrected mode: time per call (us) and ratio to the C loop")
    print(f"{'case':>9} {'M':>8} {'sarkp.DZKNDV':>13} {'raw driver':>11} {'C loop':>9} "
          f"{'DZKNDV/C':>9} {'raw/C':>6} {'max|WPR-C|':>11}")
    raw = _sarkp.drv_dynamics.dzkndv_1
    for case in ("ISPR=0", "variable"):
        for m in SIZES:
            phi = np.linspace(0.0, 2 * np.pi, m)
            mpr = 40 * np.sin(phi) - 15
            ispr = np.zeros(m) if case == "ISPR=0" else 1 + np.sin(phi) ** 2
            ref = cloop(m, W1, ISC, mpr, ispr)
            r = sarkp.DZKNDV(m, float(m), W1, ISC, mpr, ispr)
            diff = np.abs(r.WPR - ref[4]).max()
            t = interleaved({
                "sarkp": lambda: sarkp.DZKNDV(m, float(m), W1, ISC, mpr, ispr),
                "raw": lambda: raw(0, float(m), W1, ISC, mpr, ispr, 1.0),
                "C": lambda: cloop(m, W1, ISC, mpr, ispr)})
            print(f"{case:>9} {m:>8} {t['sarkp'] * 1e6:>13.1f} {t['raw'] * 1e6:>11.1f} "
                  f"{t['C'] * 1e6:>9.1f} {t['sarkp'] / t['C']:>9.2f} "
                  f"{t['raw'] / t['C']:>6.2f} {diff:>11.1e}")


def motion_table():
    print("\n2. sarkp.motion / sarkp.flywheel: time per call (us) and max |omega - exact|")
    print(f"{'n':>8} {'from rest':>10} {'error':>9} {'steady':>9} {'error':>9} "
          f"{'flywheel':>9} {'|delta-0.01|':>13}")
    a, c, j, wm = 40.0, -15.0, 12.0, 3.0
    s = wm * math.sqrt(2.0 * j)
    e0 = ((s - 2.0 * a / s) / 2.0) ** 2
    for n in SIZES[:-1] if not _Q else SIZES:
        phi = np.linspace(0.0, 2 * np.pi, n)
        m = a * np.sin(phi) + c
        jv = j + 0.0 * phi
        rest = sarkp.motion(phi, 3.0, 5.0)
        err_rest = np.abs(rest.omega - np.sqrt(2 * 5.0 * phi / 3.0)).max()
        st = sarkp.motion(phi, jv, m, omega_mean=wm)
        err_st = np.abs(st.omega - np.sqrt(2 * (e0 + a * (1 - np.cos(phi))) / j)).max()
        fw = sarkp.flywheel(phi, 0.2 + 0.1 * np.sin(phi) ** 2, m, delta=0.01, omega_mean=wm)
        t = interleaved({
            "rest": lambda: sarkp.motion(phi, 3.0, 5.0),
            "steady": lambda: sarkp.motion(phi, jv, m, omega_mean=wm),
            "flywheel": lambda: sarkp.flywheel(phi, 0.2 + 0.1 * np.sin(phi) ** 2, m,
                                               delta=0.01, omega_mean=wm)},
            repeat=3)
        print(f"{n:>8} {t['rest'] * 1e6:>10.1f} {err_rest:>9.1e} {t['steady'] * 1e6:>9.1f} "
              f"{err_st:>9.1e} {t['flywheel'] * 1e6:>9.1f} {abs(fw.delta - 0.01):>13.1e}")


def main():
    print(f"load average {os.getloadavg()}; CPU time of the process, best of {REPEAT}")
    cloop = CLoop()
    print(f"C loop: {cloop.cmd}")
    dzkndv_table(cloop)
    motion_table()
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
