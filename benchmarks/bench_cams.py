"""Chapter 5: the cam profile of program V.5, run time against error.

The pipeline of V.5 (L3385-3414): the follower's acceleration tabulated over the working
angle (rise 100 deg, dwell 50 deg, return 100 deg; sine acceleration, a0 = 15 m/s^2,
omega = 5 1/s), DINTGR twice for the velocity and the displacement, then DPRFLP for the
knife-edge profile (fixed r0 = 0.28 m, e = 0.096 m, so that every run draws the same
cam).  The law has a closed form (the cycloidal motion), so every quantity has an exact
value at every cam angle.

Varied: the number of table points N = 11 ... 100001 (the step is 250 deg/(N - 1)) and
DINTGR's method (NOMER 1 Simpson, 2 trapezoids as in V.5, 3 rectangles).  Measured:

* time: the whole pipeline (two DINTGR calls, the divisions by omega, DPRFLP), best of
  repeats, per call and per table point; and DPRFLP alone on exact tables;
* error, the largest over the table: of the profile point (m), of the pressure angle
  (rad), of the curvature 1/ROK (1/m; the radius itself is unbounded where the curvature
  changes sign), and of the displacement S (m).

Run: ``python benchmarks/bench_cams.py`` (from outside the source tree).  Prints a table
and writes ``benchmarks/results/cams.csv`` and, with matplotlib, ``cams.png``.
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import timeit

import numpy as np

import sarkp

HERE = pathlib.Path(__file__).resolve().parent
OUT = HERE / "results"

W, A1 = 5.0, 15.0
FIU, FID, FIV = 5 * math.pi / 9, 5 * math.pi / 18, 5 * math.pi / 9
RO, E = 0.28, 0.096
SIZES = (11, 31, 51, 101, 301, 1001, 3001, 10001, 30001, 100001)
METHODS = {1: "Simpson", 2: "trapezoids", 3: "rectangles"}


def exact(fi):
    """The closed form of V.5's law: a, v, s (m/s^2, m/s, m) at the cam angles fi."""
    k1, k2 = FIU / (2 * math.pi), FIV / (2 * math.pi)
    h = A1 * k1 * FIU / W**2                                   # the lift
    a, v, s = np.zeros_like(fi), np.zeros_like(fi), np.zeros_like(fi)
    up = fi <= FIU
    a[up] = A1 * np.sin(fi[up] / k1)
    v[up] = A1 * k1 * (1 - np.cos(fi[up] / k1)) / W
    s[up] = A1 * k1 * (fi[up] - k1 * np.sin(fi[up] / k1)) / W**2
    top = (fi > FIU) & (fi <= FIU + FID)
    s[top] = h
    down = fi > FIU + FID
    x = fi[down] - (FIU + FID)
    a[down] = -A1 * np.sin(x / k2)
    v[down] = -A1 * k2 * (1 - np.cos(x / k2)) / W
    s[down] = h - A1 * k2 * (x - k2 * np.sin(x / k2)) / W**2
    return a, v, s


def pipeline(n, nomer, fi, a):
    h = fi[1] - fi[0]
    v = sarkp.DINTGR(n, h, nomer, a).FINT / W
    s = sarkp.DINTGR(n, h, nomer, v).FINT / W
    return s, sarkp.DPRFLP(n, RO, E, W, fi, a, v, s)


def best_time(function, budget=0.5):
    timer = timeit.Timer(function)
    number, elapsed = 1, timer.timeit(1)
    while elapsed < 0.05:
        number *= 4
        elapsed = timer.timeit(number)
    repeats = max(3, min(7, int(budget / max(elapsed, 1e-9))))
    return min(timer.repeat(repeats, number)) / number


def main():
    rows = []
    for n in SIZES:
        fi = np.linspace(0.0, FIU + FID + FIV, n)
        a, v, s = exact(fi)
        ref = sarkp.DPRFLP(n, RO, E, W, fi, a, v, s)          # the exact profile
        t_profile = best_time(lambda: sarkp.DPRFLP(n, RO, E, W, fi, a, v, s))
        for nomer, method in METHODS.items():
            s_n, p = pipeline(n, nomer, fi, a)
            t = best_time(lambda: pipeline(n, nomer, fi, a))
            rows.append({
                "N": n, "method": method, "time_s": t, "ns_per_point": 1e9 * t / n,
                "profile_only_ns_per_point": 1e9 * t_profile / n,
                "err_S_m": float(np.max(np.abs(s_n - s))),
                "err_point_m": float(np.max(np.hypot(p.XA - ref.XA, p.YA - ref.YA))),
                "err_alfa_rad": float(np.max(np.abs(p.ALFA - ref.ALFA))),
                "err_curvature_1_per_m": float(np.max(np.abs(1 / p.ROK - 1 / ref.ROK))),
            })
    OUT.mkdir(exist_ok=True)
    with open(OUT / "cams.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"load average {os.getloadavg()[0]:.2f}")
    print(f"{'N':>7} {'method':>10} {'time':>10} {'ns/pt':>7} {'DPRFLP ns/pt':>12} "
          f"{'err S, m':>9} {'err point, m':>12} {'err alfa':>9} {'err 1/rho':>9}")
    for r in rows:
        print(f"{r['N']:>7} {r['method']:>10} {r['time_s'] * 1e6:>8.1f}us "
              f"{r['ns_per_point']:>7.0f} {r['profile_only_ns_per_point']:>12.0f} "
              f"{r['err_S_m']:>9.1e} {r['err_point_m']:>12.1e} {r['err_alfa_rad']:>9.1e} "
              f"{r['err_curvature_1_per_m']:>9.1e}")
    try:
        from matplotlib.figure import Figure
    except ImportError:
        return
    fig = Figure(figsize=(10, 4), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    for method in METHODS.values():
        sel = [r for r in rows if r["method"] == method]
        ax1.loglog([r["N"] for r in sel], [r["err_point_m"] for r in sel], "o-",
                   label=method)
        ax2.loglog([r["time_s"] for r in sel], [r["err_point_m"] for r in sel], "o-",
                   label=method)
    ax1.set_xlabel("table points N")
    ax2.set_xlabel("run time of the pipeline (2 x DINTGR + DPRFLP), s")
    for ax in (ax1, ax2):
        ax.set_ylabel("largest error of a profile point, m")
        ax.grid(True, which="both", lw=0.3)
        ax.legend()
    fig.suptitle("V.5's cam: error against table size and run time")
    fig.savefig(OUT / "cams.png", dpi=110)


if __name__ == "__main__":
    main()
