"""Dimensional synthesis (issue 28): designs per second and path generation against
pylinkage.

    python benchmarks/bench_synthesis.py              (against the installed sarkp)
    python benchmarks/bench_synthesis.py --pictures   (also docs/img/synthesis_*.png)

1. Designs per second: a population of D four-bars with a coupler point (random pivots,
   lengths, coupler points and branches around a crank-rocker), positions of A, B, P at
   360 crank angles, by
   * the batched Mechanism (sarkp.dimensional._evaluate: one description whose lengths
     and coordinates are arrays over the designs, one compiled call per branch),
   * a Python loop of Mechanism solves (a description built and solved per design),
   * a numba loop of the closed-form four-bar (when numba is installed),
   the paths interleaved round by round, best of REPEAT (process CPU time), and the
   largest difference between the paths' coupler points printed (the same work).
2. Path generation, prescribed timing: 12 positions of the rocker pin B of a known
   crank-rocker (O = (0, 0), C = (0.4, 0.05), a 0.1, b 0.35, c 0.3) at the crank angles
   30, 60, ..., 360 degrees.  pylinkage's ``differential_evolution_optimization`` (its
   Linkage simulated per candidate) searches the three lengths with the pivots given;
   sarkp.path_generation searches all ten variables (both pivots, three lengths, the
   coupler point, the branch: a harder problem) and refines with least_squares.  Wall
   time and the worst distance from a target, per seed.

The table goes to stdout and benchmarks/results/synthesis.csv.  The machine's load is
printed first: the two cores are shared.
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import sys
import time

import numpy as np

import sarkp
from sarkp import dimensional

HERE = pathlib.Path(__file__).resolve().parent
RESULTS = HERE / "results"
TURN = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
KNOWN = np.array([0.0, 0.0, 0.4, 0.05, 0.1, 0.35, 0.3, 0.2, 0.1, 1.0])
REPEAT = 3


def population(D, seed=0):
    rng = np.random.default_rng(seed)
    X = KNOWN + rng.uniform(-0.02, 0.02, (D, 10))
    X[:, 9] = np.where(rng.uniform(size=D) < 0.5, -1.0, 1.0)
    return X


def loop_of_solves(X, phi):
    """A description built and solved per design (what one writes by hand)."""
    out = np.full((len(X), phi.size, 2), np.nan)
    for i, (xO, yO, xC, yC, a, b, c, p, q, br) in enumerate(X):
        m = sarkp.Mechanism()
        m.fixed("O", xO, yO)
        m.fixed("C", xC, yC)
        m.crank("A", "O", a)
        m.rrr("B", "A", "C", b, c, branch=1 if br >= 0 else -1)
        m.point("P", "A", "B", math.hypot(p, q), math.atan2(q, p))
        out[i] = m.solve(phi, need="positions", on_error="nan").position("P")
    return out


def numba_loop():
    try:
        import numba
    except ImportError:
        return None

    @numba.njit(cache=False)
    def coupler(X, phi, out):
        for i in range(X.shape[0]):
            xO, yO, xC, yC, a, b, c, p, q, br = X[i]
            s = 1.0 if br >= 0 else -1.0
            for k in range(phi.size):
                ax, ay = xO + a * math.cos(phi[k]), yO + a * math.sin(phi[k])
                ux, uy = xC - ax, yC - ay
                L = math.hypot(ux, uy)
                x = (b * b - c * c + L * L) / (2 * L)
                h2 = b * b - x * x
                if h2 < 0:
                    out[i, k, 0] = out[i, k, 1] = math.nan
                    continue
                h = s * math.sqrt(h2)
                ex, ey = ux / L, uy / L
                bx, by = ax + x * ex - h * ey, ay + x * ey + h * ex
                tx, ty = (bx - ax) / b, (by - ay) / b
                out[i, k, 0] = ax + p * tx - q * ty
                out[i, k, 1] = ay + p * ty + q * tx
    return coupler


def best_time(f, repeat=REPEAT):
    best = math.inf
    for _ in range(repeat):
        t = time.process_time()
        f()
        best = min(best, time.process_time() - t)
    return best


def designs_per_second(rows):
    nb = numba_loop()
    for D in (100, 1000, 10000):
        X = population(D)
        batched = dimensional._evaluate(X, TURN).position("P")
        paths = {"batched Mechanism": lambda: dimensional._evaluate(X, TURN)}
        nloop = min(D, 1000)                        # the loop timed on up to 1000 designs
        looped = loop_of_solves(X[:nloop], TURN)
        paths["Python loop of solves"] = lambda: loop_of_solves(X[:nloop], TURN)
        diff = {"Python loop of solves": np.nanmax(np.abs(looped - batched[:nloop]))}
        if nb is not None:
            out = np.empty((D, TURN.size, 2))
            nb(X, TURN, out)
            diff["numba loop"] = np.nanmax(np.abs(out - batched))
            paths["numba loop"] = lambda: nb(X, TURN, out)
        times = {k: math.inf for k in paths}
        for _ in range(REPEAT):                     # interleaved, round by round
            for k, f in paths.items():
                times[k] = min(times[k], best_time(f, 1))
        for k, t in times.items():
            n = nloop if k == "Python loop of solves" else D
            rows.append({"case": "designs/s over 360 positions", "path": k, "D": D,
                         "value": n / t, "unit": "designs/s",
                         "check": f"{diff.get(k, 0.0):.1e} m vs batched"})
            print(f"D = {D:6d}  {k:24s} {n / t:12.0f} designs/s   "
                  f"(max |P - P_batched| {diff.get(k, 0.0):.1e})", flush=True)
    if nb is None:
        print("numba is not installed here: no numba loop", flush=True)


# ---- path generation against pylinkage ------------------------------------------------

def targets_of_B():
    phi = 2 * math.pi * np.arange(1, 13) / 12          # pylinkage steps: 30 .. 360 deg
    design = KNOWN.copy()
    design[7:9] = (0.35, 0.0)                          # P = B
    pop = dimensional._evaluate(design[None, :], phi)
    return phi, pop.position("B")[0]


def pylinkage_de(phi, T, seed, maxiter):
    from pylinkage.optimization import differential_evolution_optimization
    from pylinkage.synthesis.conversion import fourbar_from_lengths
    d = math.hypot(0.4, 0.05)
    # the frame along x, then the targets turned into that frame (pylinkage puts D on
    # the x axis); its crank's angle then counts from the frame
    g = math.atan2(0.05, 0.4)
    rot = np.array([[math.cos(-g), -math.sin(-g)], [math.sin(-g), math.cos(-g)]])
    Tl = T @ rot.T
    linkage = fourbar_from_lengths(0.12, 0.3, 0.32, d, initial_crank_angle=-g,
                                   iterations=12)

    def fitness(lk, dims, init):
        try:
            lk.set_constraints(dims)
            lk.set_coords(init)
            loci = np.array([step[-1] for step in lk.step(iterations=12)], dtype=float)
        except Exception:
            return math.inf
        if loci.shape != (12, 2) or not np.isfinite(loci).all():
            return math.inf
        return float(np.max(np.hypot(*(loci - Tl).T)))
    t = time.perf_counter()
    res = differential_evolution_optimization(
        fitness, linkage, bounds=([0.05] * 3, [0.5] * 3), order_relation=min,
        maxiter=maxiter, popsize=15, tol=1e-12, seed=seed, verbose=False)
    wall = time.perf_counter() - t
    return wall, float(res[0].score)


def path_vs_pylinkage(rows):
    phi, T = targets_of_B()
    bounds = dict(length=(0.05, 0.5), pivot=((-0.2, 0.5), (-0.2, 0.2)))
    try:
        import pylinkage  # noqa: F401
        have = True
    except ImportError:
        have = False
        print("pylinkage is not installed here: sarkp only", flush=True)
    for seed in range(3):
        t = time.perf_counter()
        pg = sarkp.path_generation(T, phi=phi, bounds=bounds, seed=seed, popsize=8,
                                   maxiter=40)
        wall = time.perf_counter() - t
        rows.append({"case": "path generation, 12 timed targets", "path": "sarkp",
                     "D": seed, "value": wall, "unit": "s",
                     "check": f"worst deviation {pg.error:.2e} m"})
        print(f"seed {seed}  sarkp.path_generation (10 variables)   {wall:6.2f} s   "
              f"worst deviation {pg.error:.2e} m", flush=True)
        if have:
            for maxiter in (20, 100):
                wall, err = pylinkage_de(phi, T, seed, maxiter)
                rows.append({"case": "path generation, 12 timed targets",
                             "path": f"pylinkage DE maxiter {maxiter}", "D": seed,
                             "value": wall, "unit": "s",
                             "check": f"worst deviation {err:.2e} m"})
                print(f"seed {seed}  pylinkage DE, maxiter {maxiter:3d} (3 lengths) "
                      f"{wall:6.2f} s   worst deviation {err:.2e} m", flush=True)


# ---- the docs' pictures -------------------------------------------------------------

def pictures():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out = HERE.parent / "docs" / "img"
    # function generation: log10 x
    x3 = 1.5 - 0.5 * np.cos((2 * np.arange(1, 4) - 1) * math.pi / 6)

    def crank(x):
        return math.radians(15.0) + math.radians(90.0) * (x - 1.0)

    def rocker(x):
        return math.radians(300.0) - math.radians(60.0) * np.log10(x) / math.log10(2.0)
    exact = sarkp.function_generation(crank(x3), rocker(x3))
    xs = np.linspace(1, 2, 41)
    mm = sarkp.function_generation(crank(xs), rocker(xs), method="minimax")
    fine = np.linspace(1, 2, 401)
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for res, label in ((exact, "3 Chebyshev points"), (mm, "minimax over 41 points")):
        r = res.mechanism.solve(crank(fine) + res.offsets[0], need="positions")
        e = np.angle(np.exp(1j * (r.angle("C", "B") - res.offsets[1] - rocker(fine))))
        ax.plot(fine, np.degrees(e), label=label)
    ax.plot(x3, 0 * x3, "ko", label="precision points")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("x")
    ax.set_ylabel("rocker angle error (deg)")
    ax.set_title("Function generation for y = log10 x on [1, 2]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "synthesis_function.png", dpi=110)
    plt.close(fig)
    # path generation without timing
    phi = np.linspace(0, 2 * math.pi, 12, endpoint=False)
    T = dimensional._evaluate(KNOWN[None, :], phi).position("P")[0]
    bounds = dict(length=(0.05, 0.5), pivot=((-0.2, 0.5), (-0.2, 0.2)))
    pg = sarkp.path_generation(T, bounds=bounds, seed=3, popsize=8, maxiter=60)
    for res, targets, name, title in (
            (pg, T, "synthesis_path.png",
             f"12 targets, no timing: worst deviation {pg.error:.1e} m"),
            (None, None, "synthesis_line.png", "")):
        if res is None:
            targets = np.column_stack([np.linspace(0.0, 0.2, 8), np.full(8, 0.3)])
            res = sarkp.path_generation(targets, min_transmission=40.0, seed=3,
                                        bounds=dict(length=(0.05, 0.6),
                                                    pivot=((-0.3, 0.5), (-0.3, 0.2))),
                                        popsize=15, maxiter=150)
            title = (f"straight line, transmission >= 40 deg: worst deviation "
                     f"{res.error * 1000:.1f} mm")
        r = res.mechanism.solve(res.phi[:1], need="positions")
        fig = r.plot(0, title=title)
        ax = fig.axes[0]
        curve = res.mechanism.solve(np.linspace(0, 2 * math.pi, 721),
                                    need="positions").position("P")
        ax.plot(*curve.T, color="C0", lw=1, label="coupler curve of P")
        ax.plot(*targets.T, "rx", ms=8, label="targets")
        ax.legend(loc="best")
        fig.savefig(out / name, dpi=110)
        plt.close(fig)
    print("pictures written to", out)


def main():
    print("load:", os.getloadavg(), "on", os.cpu_count(), "cores", flush=True)
    if "--pictures" in sys.argv:
        pictures()
    rows = []
    designs_per_second(rows)
    path_vs_pylinkage(rows)
    RESULTS.mkdir(exist_ok=True)
    with open(RESULTS / "synthesis.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["case", "path", "D", "value", "unit", "check"])
        w.writeheader()
        w.writerows(rows)
    print("table:", RESULTS / "synthesis.csv")


if __name__ == "__main__":
    main()
