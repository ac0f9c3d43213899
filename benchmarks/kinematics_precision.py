"""Work-precision of the kinematics (issue 26): error against ns per position.

One four-bar for every method -- the crank-rocker of bench_kinematics.py (OA = 0.1,
AB = 0.35, CB = 0.3, O = (0, 0), C = (0.4, 0)), the crank at omega = 3 rad/s, over
N = 400 .. 400000 crank positions 2 pi k / N (fewer for the slow peers) -- and one
exact reference: the point B and its velocity and acceleration at the 200 sample
angles 2 pi m / 200 (in every grid) from mpmath at 40 digits (the closed-form circle
intersection, derivatives by mpmath.diff; bench_kinematics.reference).

Two panels:

* positions: sarkp ``Mechanism.solve(need="positions")``, the book's DPRM1 on arrays,
  pylinkage ``step_fast`` (numba), kinepy ``solve_kinematics``;
* full kinematics (positions, velocities, accelerations): sarkp
  ``Mechanism.solve(need="accelerations")``, the book's DKNMA1 on arrays (the array
  path), pylinkage ``step_fast_with_kinematics`` (numba), mechanism (its loop equations
  solved by scipy's fsolve at every position), kinepy positions + its central
  differences (kinepy has no analytic velocities; its dynamics differentiates positions
  numerically, kinepy.math.calculus).

The error of a method is the largest of |computed - exact| / max|exact| over the sample,
for the positions of B (and, in the second panel, its velocities and accelerations).
The peers are installed only in the benchmark's environment (never dependencies of
sarkp): a peer that is missing or fails is reported, with its error message, in the
notes and the CSV, not drawn.

Time: CPU time of this process (time.process_time) per position, the best of ROUNDS
rounds, the rounds interleaving every (method, N) so that a slow spell of the shared
machine falls on all of them alike.  Writes results/kinematics_precision.csv and .png.
Run from outside the source tree: ``python benchmarks/kinematics_precision.py``
(SARKP_BENCH_QUICK=1: smaller grids, two rounds, writes to results/quick/).
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import sys
import time
import timeit
import warnings

import numpy as np

import sarkp

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import bench_kinematics as bk  # noqa: E402

QUICK = os.environ.get("SARKP_BENCH_QUICK") == "1"
ROUNDS = 2 if QUICK else 5
OUT = HERE / "results" / ("quick" if QUICK else "")
G = bk.FOURBAR
W1 = bk.W1
S = 200                                          # the sample: every N/S-th position
NS = (400, 4000) if QUICK else (400, 4000, 40000, 400000)
NS_KINEPY = (400, 4000) if QUICK else (400, 4000, 40000)
NS_MECHANISM = (200,) if QUICK else (200, 1000)


def mechanism_sarkp():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", G["xc"], G["yc"])
    m.crank("A", "O", G["roa"])
    # branch +1: B left of the directed line A -> C, the reference's (DPRM1's P = -1)
    m.rrr("B", "A", "C", G["rab"], G["rcb"], branch=1)
    return m


def _xy(p, v=None, a=None):
    out = {"XB": p[..., 0], "YB": p[..., 1]}
    if v is not None:
        out.update(VXB=v[..., 0], VYB=v[..., 1], AXB=a[..., 0], AYB=a[..., 1])
    return out


def cases(notes):
    """(panel, method, N, run, result): run() is what is timed, result(out) the
    Cartesian B (and its derivatives) at the sample positions of run's output."""
    out = []
    m = mechanism_sarkp()
    for n in NS:
        phi = bk.crank_angles(n)
        idx = np.arange(0, n, n // S)
        out.append(("positions", "sarkp Mechanism", n,
                    lambda phi=phi: m.solve(phi, omega=W1, need="positions"),
                    lambda r, idx=idx: _xy(r.position("B")[idx])))
        out.append(("positions", "sarkp DPRM1 (book, array)", n,
                    lambda phi=phi: bk.fourbar_split(phi, 1, bk._NP),
                    lambda r, idx=idx: {k: r[k][idx] for k in ("XB", "YB")}))
        out.append(("full", "sarkp Mechanism", n,
                    lambda phi=phi: m.solve(phi, omega=W1, need="accelerations"),
                    lambda r, idx=idx: _xy(r.position("B")[idx], r.velocity("B")[idx],
                                           r.acceleration("B")[idx])))
        out.append(("full", "sarkp DKNMA1 (book, array)", n,
                    lambda phi=phi: bk.fourbar_dknma(phi, 3, bk._NP),
                    lambda r, idx=idx: bk.sarkp_points({k: v[idx] for k, v in r.items()},
                                                       "fourbar")))
    # pylinkage: a linkage per N (its crank turns by 2 pi / N per step); the branch of B
    # is set by the position hint at phi = 0, the reference's
    try:
        import pylinkage
        ref0 = bk._ref_points(0.0, "fourbar")
        ref0 = {k: float(v) for k, v in ref0.items()}
        for n in NS:
            idx = np.arange(0, n, n // S)
            lk, names = bk.pylinkage_linkage("fourbar", n, ref0)
            lk.step_fast_with_kinematics(iterations=n)        # numba compiles here
            lk.step_fast(iterations=n)
            # a linkage per case: its state goes on from call to call (a whole turn
            # per call), the errors are those of the first turn
            lk, names = bk.pylinkage_linkage("fourbar", n, ref0)
            lk2, _ = bk.pylinkage_linkage("fourbar", n, ref0)
            j = names.index("B")
            out.append(("positions", "pylinkage (numba)", n,
                        lambda lk=lk, n=n: lk.step_fast(iterations=n),
                        lambda r, idx=idx, j=j: _xy(r[idx, j])))
            out.append(("full", "pylinkage (numba)", n,
                        lambda lk=lk2, n=n: lk.step_fast_with_kinematics(iterations=n),
                        lambda r, idx=idx, j=j: _xy(r[0][idx, j], r[1][idx, j],
                                                    r[2][idx, j])))
        notes.append(f"pylinkage {pylinkage.__version__}: B's branch from the position "
                     f"hint at phi = 0; its crank angle is accumulated step by step "
                     f"(2 pi / N added to atan2 of the previous crank point), so it "
                     f"drifts from 2 pi k / N, which shows in its error")
    except Exception as exc:                                       # noqa: BLE001
        notes.append(f"pylinkage not run: {type(exc).__name__}: {exc}")
    try:
        kp = bk.KinepyFourbar()
        import importlib.metadata as md
        for n in NS_KINEPY:
            phi = bk.crank_angles(n)
            idx = np.arange(0, n, n // S)
            out.append(("positions", "kinepy", n, lambda phi=phi: kp.positions(phi),
                        lambda r, idx=idx: {k: r[k][idx] for k in ("XB", "YB")}))
            out.append(("full", "kinepy + central differences", n,
                        lambda phi=phi: kp.derivatives(phi),
                        lambda r, idx=idx: {k: v[idx] for k, v in r.items()}))
        notes.append(f"kinepy {md.version('kinepy')}: the RRR group's sign chosen "
                     f"(change_signs(-1)) so that B is on the reference's branch; B from "
                     f"the coupler's origin and angle; velocities and accelerations by its "
                     f"central differences (derivative_vec, derivative2_vec over time at "
                     f"omega = 3 rad/s), one-sided at the first and last position of the "
                     f"grid, so the sample position 0 is compared on positions only")
    except Exception as exc:                                       # noqa: BLE001
        notes.append(f"kinepy not run: {type(exc).__name__}: {exc}")
    try:
        import importlib.metadata as md
        md.version("mechanism")
        ref0 = bk.reference(np.array([0.0]), "fourbar")
        ref0 = {k: float(v[0]) for k, v in ref0.items()}
        for n in NS_MECHANISM:
            phi = bk.crank_angles(n)
            idx = np.arange(0, n, n // S)
            out.append(("full", "mechanism (fsolve)", n,
                        lambda phi=phi: bk.mechanism_run("fourbar", phi, ref0),
                        lambda r, idx=idx: {k: np.asarray(v)[idx] for k, v in r.items()}))
        notes.append(f"mechanism {md.version('mechanism')}: the loop equation "
                     f"OA + AB - CB - OC = 0 solved by fsolve at each position, started "
                     f"from the exact angles at phi = 0 and then from the previous "
                     f"position; scipy fsolve's default tolerance")
    except Exception as exc:                                       # noqa: BLE001
        notes.append(f"mechanism not run: {type(exc).__name__}: {exc}")
    return out


def errors(got, ref, skip0=False):
    """The largest relative error of B's positions (and velocities, accelerations);
    skip0: the derivatives not at the first sample position."""
    worst = 0.0
    for pre in (("X", "Y"), ("VX", "VY"), ("AX", "AY")):
        if pre[0] + "B" not in got:
            continue
        scale = max(np.max(np.abs(ref[p + "B"])) for p in pre)
        for p in pre:
            d = np.abs(np.asarray(got[p + "B"], dtype=float) - ref[p + "B"])
            if skip0 and p not in ("X", "Y"):
                d = d[1:]
            worst = max(worst, float(np.max(d)) / scale)
    return worst


def one_call_time(fn, min_time=0.05):
    """The CPU time of one call of fn: calls repeated to at least min_time."""
    t = timeit.Timer(fn, timer=time.process_time)
    t0 = t.timeit(1)
    number = max(1, int(min_time / max(t0, 1e-7)))
    return t.timeit(number) / number if number > 1 else t0


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    up0 = os.getloadavg()
    print("load average %.2f %.2f %.2f" % up0, flush=True)
    notes = []
    todo = cases(notes)
    # the reference, once per distinct set of sample angles (2 pi m / 200 rounded)
    print("mpmath reference ...", flush=True)
    refs = {}
    rows = []
    for panel, method, n, run, result in todo:
        phi = bk.crank_angles(n)[np.arange(0, n, n // S)]
        key = phi.tobytes()
        if key not in refs:
            refs[key] = bk.reference(phi, "fourbar")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            got = result(run())
        err = errors(got, refs[key], skip0="central" in method)
        rows.append([panel, method, n, err, math.inf])
        print(panel, method, n, f"error {err:.2e}", flush=True)
    print(f"timing: {ROUNDS} rounds over {len(todo)} cases ...", flush=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for _ in range(ROUNDS):
            for row, (_, _, n, run, _) in zip(rows, todo):
                row[4] = min(row[4], one_call_time(run) / n)
    up1 = os.getloadavg()
    for r in rows:
        print(f"{r[0]:10s} {r[1]:32s} N={r[2]:7d}  {r[4] * 1e9:10.1f} ns/pos  "
              f"error {r[3]:.2e}")
    for n_ in notes:
        print("note:", n_)
    with open(OUT / "kinematics_precision.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["panel", "method", "positions", "error", "ns_per_position"])
        for r in rows:
            w.writerow([r[0], r[1], r[2], f"{r[3]:.3e}", f"{r[4] * 1e9:.1f}"])
        for n_ in notes:
            w.writerow(["note", n_, "", "", ""])
        w.writerow(["note", "load average %.2f %.2f %.2f at the start, %.2f %.2f %.2f at "
                    "the end (2 shared cores)" % (up0 + up1), "", "", ""])
    plot(rows, OUT / "kinematics_precision.png")
    print("wrote", OUT / "kinematics_precision.csv", OUT / "kinematics_precision.png")


STYLES = {"sarkp Mechanism": ("k", "o-"), "sarkp DPRM1 (book, array)": ("tab:gray", "s--"),
          "sarkp DKNMA1 (book, array)": ("tab:gray", "s--"),
          "pylinkage (numba)": ("tab:blue", "^-"), "kinepy": ("tab:green", "d-"),
          "kinepy + central differences": ("tab:green", "d-"),
          "mechanism (fsolve)": ("tab:red", "x-")}


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    for ax, panel, title in zip(axes, ("positions", "full"),
                                ("positions of B", "positions, velocities and "
                                                   "accelerations of B")):
        for method in dict.fromkeys(r[1] for r in rows if r[0] == panel):
            pts = sorted((r[2], r[4] * 1e9, max(r[3], 1e-17)) for r in rows
                         if r[0] == panel and r[1] == method)
            _, x, y = zip(*pts)
            color, style = STYLES.get(method, ("k", "o-"))
            ax.loglog(x, y, style, color=color, label=method,
                      lw=2.5 if method == "sarkp Mechanism" else 1.2)
            ax.annotate(f"N={pts[0][0]}", (x[0], y[0]), fontsize=6, color=color,
                        xytext=(3, 3), textcoords="offset points")
        ax.set_title(f"four-bar: {title}")
        ax.set_xlabel("CPU time per position (ns)")
        ax.set_ylabel("largest relative error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("kinematics work-precision: error against a 40-digit reference vs time "
                 "(N = 400 .. 400000 positions; the first point of each line labelled)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
