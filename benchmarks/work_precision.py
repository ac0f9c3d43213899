"""Work-precision of the motion in time (issue 26): error against CPU time.

Three problems, each a sarkp Mechanism (tests/machines.py):

* Andrews' squeezer from rest (A03): the error of beta(0.03) against the 20-digit
  reference 15.810771195153707097;
* the N-four-bar, N = 40 (A02), from vertical at 1 rad/s over 20 s: the largest error
  of phi at t = 5, 10, 15, 20 against the energy integral (mpmath);
* the pendulum (A01-like) from the horizontal at rest over 20 s (16 reversals): the
  largest error of phi at 41 times against the Jacobi elliptic solution (mpmath).

Methods: ``Mechanism.simulate`` at rtol 1e-4 .. 1e-12; scipy's ``solve_ivp`` with RK45,
DOP853, Radau and LSODA at rtol = atol 1e-4 .. 1e-12 (Radau and LSODA to 1e-10; on the N-four-bar to 1e-8,
and at most 30000 evaluations, a run that needs more being reported as failed), their
right-hand side one ``Mechanism.solve`` of the same mechanism per evaluation (omega as
given, epsilon 0: epsilon = -M_bal/J_red; for the N-four-bar the parallelogram's
branches set from the sign of sin(phi), which scipy cannot find by itself); and
``Mechanism.motion`` over the angle (squeezer: beta(0.03) from its t(phi), inverted by a
cubic spline; pendulum: the half period t(2 pi) from the grid pi .. 2 pi, whose end is a
turning point).

On the pendulum (no groups, so no tolerance cap) simulate also runs at rtol 1e-2 and 1e-3.

CPU time: time.process_time, best of REPEAT = 3 runs (one for the N-four-bar), the methods of one problem
interleaved in one process.  Writes results/work_precision.csv and .png.  Run from
outside the source tree: ``python benchmarks/work_precision.py`` (SARKP_BENCH_QUICK=1:
fewer tolerances, one repeat).
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import sys
import time
import warnings

import mpmath as mp
import numpy as np

import sarkp

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
import machines  # noqa: E402

QUICK = os.environ.get("SARKP_BENCH_QUICK") == "1"
REPEAT = 1 if QUICK else 3
G = 9.81
RTOLS = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12) if not QUICK else (1e-6, 1e-10)
SCIPY = ("RK45", "DOP853", "Radau", "LSODA")


def cpu(fn, repeat=None):
    best, out = math.inf, None
    for _ in range(REPEAT if repeat is None else repeat):
        t0 = time.process_time()
        out = fn()
        best = min(best, time.process_time() - t0)
    return best, out


class Budget(Exception):
    pass


def scipy_rhs(m, gravity, branch=None, budget=10**9):
    """The right-hand side from one Mechanism.solve per call; branch(phi) -> the
    mechanism to use (the N-four-bar's parallelogram), else m; more than ``budget``
    calls stop the run (a measured miss)."""
    count = [0]

    def rhs(t, y):
        count[0] += 1
        if count[0] > budget:
            raise Budget(f"more than {budget} evaluations")
        mm = m if branch is None else branch(y[0])
        r = mm.solve(np.array([y[0]]), omega=float(y[1]), epsilon=0.0, need="forces",
                     gravity=gravity)
        return [y[1], -r.balancing_moment[0] / r.reduced_inertia[0]]
    return rhs


def run_scipy(rhs, span, y0, t_eval, method, rtol):
    from scipy.integrate import solve_ivp
    sol = solve_ivp(rhs, span, y0, method=method, rtol=rtol, atol=rtol, t_eval=t_eval)
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol.y[0], sol.nfev


# -- problems ---------------------------------------------------------------------------
def squeezer_runs():
    m = machines.squeezer()
    b0, ref = machines.SQUEEZER_BETA0, machines.SQUEEZER_BETA_003
    rows = []
    for rtol in RTOLS:
        for method in ("simulate",) + SCIPY:
            if method in ("Radau", "LSODA") and rtol < 1e-10:
                continue
            if method == "simulate":
                sec, sim = cpu(lambda: m.simulate([0.0, 0.03], phi0=b0, rtol=rtol))
                err, nfev = abs(sim.phi[-1] - ref), sim.stats["calls"]
            else:
                sec, (y, nfev) = cpu(lambda: run_scipy(scipy_rhs(m, 0.0), (0.0, 0.03),
                                                       [b0, 0.0], None, method, rtol))
                err = abs(y[-1] - ref)
            rows.append(("squeezer", method, rtol, err, sec, nfev))
            print(*rows[-1], flush=True)
    from scipy.interpolate import CubicSpline
    for n in (101, 401, 1601, 6401):
        def mot():
            phi = np.linspace(b0, 16.5, n)
            r = m.motion(phi, omega0=0.0)
            return float(CubicSpline(r.t, phi)(0.03))
        sec, beta = cpu(mot)
        rows.append(("squeezer", "motion", n, abs(beta - ref), sec, n))
        print(*rows[-1], flush=True)
    return rows


def four_bar_runs(N=40):
    m = machines.n_four_bar(N)
    up = m
    down = machines.n_four_bar(N)
    for k in range(1, N + 1):
        down.set_branch(f"A{k}", -1)
    t = np.array([0.0, 5.0, 10.0, 15.0, 20.0])
    ref = machines.four_bar_exact(N, t)[0]
    def rhs_():
        return scipy_rhs(m, G, lambda p: up if math.sin(p) >= 0.0 else down, 30000)
    rows = []
    for rtol in RTOLS:
        for method in ("simulate",) + SCIPY:
            if method in ("Radau", "LSODA") and rtol < 1e-8:
                continue
            try:
                if method == "simulate":
                    sec, sim = cpu(lambda: m.simulate(t, phi0=math.pi / 2, omega0=1.0,
                                                      gravity=G, rtol=rtol), 1)
                    y, nfev = sim.phi, sim.stats["calls"]
                else:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        sec, (y, nfev) = cpu(lambda: run_scipy(
                            rhs_(), (0.0, 20.0), [math.pi / 2, 1.0], t, method, rtol), 1)
                err = float(np.max(np.abs(y - ref)))
            except Exception as e:                    # a failure is a measured point too
                print("four-bar", method, rtol, "failed:", str(e)[:100], flush=True)
                rows.append((f"four-bar N={N}", method, rtol, math.nan, math.nan, 0))
                continue
            rows.append((f"four-bar N={N}", method, rtol, err, sec, nfev))
            print(*rows[-1], flush=True)
    return rows


def pendulum_runs():
    m = machines.pendulum()
    t = np.linspace(0.0, 20.0, 41)
    ref = machines.pendulum_exact(t)
    rows = []
    # simulate's error at rtol 1e-4 is already 1e-7 here (its estimate is of the dense
    # output's order 8, the step ends are of order 16): looser tolerances too, for it
    for rtol in ((1e-2, 1e-3) if not QUICK else ()) + RTOLS:
        for method in ("simulate",) + SCIPY:
            if method in ("Radau", "LSODA") and rtol < 1e-10:
                continue
            if method != "simulate" and rtol > 1e-4:
                continue
            if method == "simulate":
                sec, sim = cpu(lambda: m.simulate(t, gravity=G, rtol=rtol))
                y, nfev = sim.phi, sim.stats["calls"]
            else:
                sec, (y, nfev) = cpu(lambda: run_scipy(scipy_rhs(m, G), (0.0, 20.0),
                                                       [0.0, 0.0], t, method, rtol))
            rows.append(("pendulum", method, rtol, float(np.max(np.abs(y - ref))), sec,
                         nfev))
            print(*rows[-1], flush=True)
    half = 2 * float(mp.ellipk(0.5)) / math.sqrt(G)
    for n in (101, 1001, 10001):
        def mot():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return m.motion(np.linspace(math.pi, 2 * math.pi, n), gravity=G).t[-1]
        try:
            sec, th = cpu(mot)
        except sarkp.RequirementError as e:            # a refusal: a measured point too
            print("pendulum motion", n, "refused:", str(e)[:80], flush=True)
            rows.append(("pendulum", "motion (half period)", n, math.nan, math.nan, n))
            continue
        rows.append(("pendulum", "motion (half period)", n, abs(th - half), sec, n))
        print(*rows[-1], flush=True)
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    problems = list(dict.fromkeys(r[0] for r in rows))
    fig, axes = plt.subplots(1, len(problems), figsize=(5.2 * len(problems), 4.4))
    styles = {"simulate": ("k", "o-"), "motion": ("tab:gray", "s--"),
              "motion (half period)": ("tab:gray", "s--"), "RK45": ("tab:blue", "^-"),
              "DOP853": ("tab:orange", "v-"), "Radau": ("tab:green", "d-"),
              "LSODA": ("tab:red", "x-")}
    for ax, prob in zip(np.atleast_1d(axes), problems):
        for method in dict.fromkeys(r[1] for r in rows if r[0] == prob):
            pts = [(r[4], max(r[3], 1e-16)) for r in rows
                   if r[0] == prob and r[1] == method and math.isfinite(r[3])]
            if not pts:
                continue
            x, y = zip(*pts)
            color, style = styles.get(method, ("k", "o-"))
            ax.loglog(x, y, style, color=color, label=method,
                      lw=2.5 if method == "simulate" else 1.2)
        ax.set_title(prob)
        ax.set_xlabel("CPU time (s)")
        ax.set_ylabel("error (rad)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("sarkp Mechanism.simulate vs scipy solve_ivp, same mechanism "
                 "evaluations (error vs CPU time)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    out = HERE / "results"
    out.mkdir(exist_ok=True)
    os.system("uptime")
    rows = squeezer_runs() + four_bar_runs() + pendulum_runs()
    with open(out / "work_precision.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["problem", "method", "rtol_or_points", "error", "cpu_s", "evaluations"])
        w.writerows(rows)
    plot(rows, out / "work_precision.png")
    print("wrote", out / "work_precision.csv", out / "work_precision.png")


if __name__ == "__main__":
    main()
