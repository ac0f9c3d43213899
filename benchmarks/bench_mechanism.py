"""sarkp.Mechanism against hand-written compiled loops (issues 19 and 25).

    python benchmarks/bench_mechanism.py             (against the installed sarkp)
    python benchmarks/bench_mechanism.py contract    (designs, points=/links=, one position)
    python benchmarks/bench_mechanism.py reused      (outputs reused on both sides)

Cases (corrected mode, crank at omega = 3 rad/s, phi_k = 2 pi k / N, N = 1e5 and 360),
each at need="positions", "velocities" and "accelerations", against a C loop of
mechanism_loops.c storing the same numbers in the same layout at that level:

1. the four-bar of bench_kinematics.py (OA 0.1, AB 0.35, CB 0.3, C = (0.4, 0)):
   ``fourbar_mech`` (A and B's position, velocity, acceleration, the three moving links'
   cosine, sine, omega, epsilon: 20 numbers per position at full kinematics);
2. program X's six-bar (sarkp.book.x_mechanism's geometry, no loads): ``sixbar`` (A, B,
   D, E and five links: 44 numbers);
3. the inverted slider-crank (rpr: OA 0.1, C = (0.05, -0.25), A at h = 0.02 from link
   3's axis): ``rpr_mech`` (A, B and the crank, the slider, link 3: 20 numbers);
4. the loaded four-bar (two masses, gravity, a torque) at need="forces": against
   ``fourbar_forces_full`` (the 38 numbers the Mechanism stores: the kinematics' 20, the
   four pairs' reactions with their couples, M_b, J_red, M_red) and ``fourbar_forces``
   (9 numbers: the reactions by moments about B and Cramer's rule, M_b).

At need >= "velocities" the Mechanism also stores J_red (0 without masses), which the
kinematic C loops do not: one number of 20-44.  The C loops are built twice, with
``cc -O3 -march=native`` (column "C") and with ``-O3`` alone, as meson builds sarkp
(x86-64 baseline: no FMA; column "C generic").  Extra rows: fourbar.c (the book's polar
outputs) and pylinkage's numba kernel ``step_fast_with_kinematics`` when installed.

Every C loop's outputs are checked against the Mechanism's, value by value (column
"check": the largest difference, relative to the largest value for accelerations,
epsilons and forces), so the same work is compared.  Times: best of REPEAT runs of at
least 50 ms of this process's CPU time (time.process_time: the two cores are shared), the
paths of a case (every need, both C builds) interleaved round by round.  Outputs are
allocated per call on both sides.  The table goes to stdout (markdown) and
benchmarks/results/bench_mechanism.csv.
"""

from __future__ import annotations

import ctypes
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

import sarkp
from sarkp.book import prog_x

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
QUICK = os.environ.get("SARKP_BENCH_QUICK") == "1"
REPEAT = 3 if QUICK else 7
W1 = 3.0
FOURBAR = dict(roa=0.1, rab=0.35, rcb=0.3, xc=0.4, yc=0.0)
LINKS = dict(prog_x.FITTED_LINKS, RCD=0.5787882, RDE=0.7012536)   # bench_kinematics' COURSE
RPR = dict(roa=0.1, xc=0.05, yc=-0.25, h=0.02)
LOADS = dict(m2=1.5, j2=0.012, f2=0.5, m3=1.0, j3=0.01, f3=0.5, g=9.81, t3=-20.0)


def best_of(fns, repeat=REPEAT, min_time=0.05):
    """{name: best time of one call}, the functions run in turn, round by round."""
    counts = {}
    for name, fn in fns.items():
        k, t0 = 0, time.process_time()
        while time.process_time() - t0 < min_time / 4 or k == 0:
            fn()
            k += 1
        counts[name] = max(1, int(k * 4))
    best = {name: math.inf for name in fns}
    for _ in range(repeat):
        for name, fn in fns.items():
            t0 = time.process_time()
            for _ in range(counts[name]):
                fn()
            best[name] = min(best[name], (time.process_time() - t0) / counts[name])
    return best


class Loops:
    """mechanism_loops.c and fourbar.c compiled with cc -O3 -march=native, via ctypes."""

    FLAGS = ["-O3", "-march=native", "-shared", "-fPIC"]

    def __init__(self, native=True):
        cc = shutil.which("cc") or shutil.which("gcc")
        self._tmp = tempfile.TemporaryDirectory()
        lib = pathlib.Path(self._tmp.name) / "libloops.so"
        flags = self.FLAGS if native else [f for f in self.FLAGS if f != "-march=native"]
        subprocess.run([cc, *flags, "-o", str(lib), str(HERE / "mechanism_loops.c"),
                        str(HERE / "fourbar.c"), "-lm"], check=True)
        self.lib = ctypes.CDLL(str(lib))
        arr = np.ctypeslib.ndpointer(np.float64, flags="C_CONTIGUOUS")
        d = ctypes.c_double
        self.lib.sixbar.argtypes = [ctypes.c_long, ctypes.c_int, arr] + [d] * 9 + [arr] * 6
        self.lib.fourbar.argtypes = [ctypes.c_long, ctypes.c_int, arr] + [d] * 6 + [arr]
        self.lib.fourbar_forces.argtypes = [ctypes.c_long, arr] + [d] * 14 + [arr]
        self.lib.fourbar_mech.argtypes = [ctypes.c_long, ctypes.c_int, arr] + [d] * 6 + \
            [arr] * 6
        self.lib.rpr_mech.argtypes = [ctypes.c_long, ctypes.c_int, arr] + [d] * 5 + [arr] * 6
        self.lib.fourbar_forces_full.argtypes = [ctypes.c_long, arr] + [d] * 14 + [arr] * 10

    def sixbar(self, phi, level, g):
        n = phi.size
        out = [np.empty((n, 4, 2)), np.empty((n, 4, 2)), np.empty((n, 4, 2)),
               np.empty((n, 5, 2)), np.empty((n, 5)), np.empty((n, 5))]
        if self.lib.sixbar(n, level, phi, g["roa"], g["rab"], g["rcb"], g["rcd"], g["rde"],
                           g["xc"], g["yc"], g["yg"], W1, *out):
            raise ValueError("sixbar: does not assemble")
        return out

    def fourbar(self, phi):
        out = np.empty((12, phi.size))
        self.lib.fourbar(phi.size, 3, phi, *(FOURBAR[k] for k in ("roa", "rab", "rcb",
                                                                  "xc", "yc")), W1, out)
        return out

    def fourbar_mech(self, phi, level=3):
        n = phi.size
        out = [np.empty((n, 2, 2)), np.empty((n, 2, 2)), np.empty((n, 2, 2)),
               np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3))]
        self.lib.fourbar_mech(n, level, phi, *(FOURBAR[k] for k in ("roa", "rab", "rcb",
                                                                    "xc", "yc")), W1, *out)
        return out

    def rpr(self, phi, level=3):
        n = phi.size
        out = [np.empty((n, 2, 2)), np.empty((n, 2, 2)), np.empty((n, 2, 2)),
               np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3))]
        if self.lib.rpr_mech(n, level, phi, *(RPR[k] for k in ("roa", "xc", "yc", "h")), W1,
                             *out):
            raise ValueError("rpr_mech: does not assemble")
        return out

    def forces_full(self, phi):
        n = phi.size
        out = [np.empty((n, 2, 2)), np.empty((n, 2, 2)), np.empty((n, 2, 2)),
               np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 4, 3)),
               np.empty(n), np.empty(n), np.empty(n)]
        L = LOADS
        self.lib.fourbar_forces_full(n, phi, *(FOURBAR[k] for k in ("roa", "rab", "rcb",
                                                                    "xc", "yc")), W1,
                                     L["m2"], L["j2"], L["f2"], L["m3"], L["j3"], L["f3"],
                                     L["g"], L["t3"], *out)
        return out

    def forces(self, phi):
        out = np.empty((phi.size, 9))
        L = LOADS
        self.lib.fourbar_forces(phi.size, phi, *(FOURBAR[k] for k in ("roa", "rab", "rcb",
                                                                      "xc", "yc")), W1,
                                L["m2"], L["j2"], L["f2"], L["m3"], L["j3"], L["f3"],
                                L["g"], L["t3"], out)
        return out


def _max_error(r, out, level=3):
    """The largest difference of a Mechanism's kinematics from a C loop's at a level
    (positions, velocities, accelerations relative to their largest, directions, omegas,
    epsilons relative to their largest)."""
    pos, vel, acc, dr, om, ep = out
    err = max(np.max(np.abs(r.positions - pos)), np.max(np.abs(r.directions - dr)))
    if level >= 2:
        err = max(err, np.max(np.abs(r.velocities - vel)), np.max(np.abs(r.omegas - om)))
    if level >= 3:
        err = max(err, np.max(np.abs(r.accelerations - acc)) / np.max(np.abs(acc)),
                  np.max(np.abs(r.epsilons - ep)) / np.max(np.abs(ep)))
    return err


def sixbar_geometry():
    g = {"roa": LINKS["ROA"], "rab": LINKS["RAB"], "rcb": LINKS["RCD"], "rcd": LINKS["RCD"],
         "rde": LINKS["RDE"], "xc": -LINKS["ROC"] * math.sin(prog_x.DELTA),
         "yc": LINKS["ROC"] * math.cos(prog_x.DELTA)}
    g["yg"] = prog_x.H5 + g["yc"]
    return g


def sixbar_mechanism(g):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", g["xc"], g["yc"])
    m.fixed("K", 0.0, g["yg"])
    m.crank("A", "O", g["roa"])
    m.rrr("B", "A", "C", g["rab"], g["rcb"], branch=1)
    m.point("D", "C", "B", g["rcd"], math.pi)
    m.rrp("E", "D", "K", 0.0, g["rde"], branch=1)
    return m


def fourbar_mechanism(loads=False):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", FOURBAR["xc"], FOURBAR["yc"])
    m.crank("A", "O", FOURBAR["roa"])
    m.rrr("B", "A", "C", FOURBAR["rab"], FOURBAR["rcb"], branch=1)
    if loads:
        L = LOADS
        m.mass("A", "B", mass=L["m2"], inertia=L["j2"], centre=L["f2"] * FOURBAR["rab"])
        m.mass("C", "B", mass=L["m3"], inertia=L["j3"], centre=L["f3"] * FOURBAR["rcb"])
        m.torque("C", "B", L["t3"])
    return m


def rpr_mechanism():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", RPR["xc"], RPR["yc"])
    m.crank("A", "O", RPR["roa"])
    m.rpr("B", "A", "C", RPR["h"], math.pi / 2, branch=1)
    return m


NEEDS = ("positions", "velocities", "accelerations")


def main():
    loops = Loops()
    generic = Loops(native=False)
    rows = []

    def add(case, n, need, t, tc, tg, err, ref="C loop"):
        rows.append((case, n, need, t, tc, tg, err, ref))

    g = sixbar_geometry()
    cases = (("four-bar", fourbar_mechanism(), "fourbar_mech",
              lambda lp, phi, lev: lp.fourbar_mech(phi, lev)),
             ("six-bar (program X)", sixbar_mechanism(g), "sixbar",
              lambda lp, phi, lev: lp.sixbar(phi, lev, g)),
             ("inverted slider-crank (rpr)", rpr_mechanism(), "rpr_mech",
              lambda lp, phi, lev: lp.rpr(phi, lev)))
    for case, mech, cname, cfun in cases:
        for n in (100_000, 360):
            phi = 2 * math.pi * np.arange(n) / n
            fns, errs = {}, {}
            for lev, need in enumerate(NEEDS, 1):
                r = mech.solve(phi, omega=W1, need=need)
                errs[need] = _max_error(r, cfun(loops, phi, lev), lev)
                fns["m" + need] = lambda need=need: mech.solve(phi, omega=W1, need=need)
                fns["c" + need] = lambda lev=lev: cfun(loops, phi, lev)
                fns["g" + need] = lambda lev=lev: cfun(generic, phi, lev)
            t = best_of(fns)
            for need in NEEDS:
                add(f"{case} (`{cname}`)", n, need, t["m" + need], t["c" + need],
                    t["g" + need], errs[need])

    fl = fourbar_mechanism(loads=True)
    for n in (100_000, 360):
        phi = 2 * math.pi * np.arange(n) / n
        r = fl.solve(phi, omega=W1, need="forces", gravity=LOADS["g"])
        out = loops.forces(phi)
        err = max(np.max(np.abs(r.balancing_moment - out[:, 8])) / np.max(np.abs(out[:, 8])),
                  np.max(np.abs(r.reaction("B") - out[:, 4:6])) / np.max(np.abs(out[:, 4:6])))
        full = loops.forces_full(phi)
        err_full = max(_max_error(r, full[:6]),
                       np.max(np.abs(r.reactions - full[6])) / np.max(np.abs(full[6])),
                       *(np.max(np.abs(a - b)) / np.max(np.abs(b)) for a, b in
                         ((r.balancing_moment, full[7]), (r.reduced_inertia, full[8]),
                          (r.reduced_moment, full[9]))))
        t = best_of({"mech": lambda: fl.solve(phi, omega=W1, need="forces",
                                              gravity=LOADS["g"]),
                     "c": lambda: loops.forces_full(phi),
                     "g": lambda: generic.forces_full(phi),
                     "c9": lambda: loops.forces(phi),
                     "g9": lambda: generic.forces(phi)})
        add("loaded four-bar (`fourbar_forces_full`, 38 numbers)", n, "forces", t["mech"],
            t["c"], t["g"], err_full)
        add("loaded four-bar (`fourbar_forces`, 9 numbers)", n, "forces", t["mech"],
            t["c9"], t["g9"], err)

    n = 100_000
    phi = 2 * math.pi * np.arange(n) / n
    four = fourbar_mechanism()
    r = four.solve(phi, omega=W1, need="accelerations")
    out = loops.fourbar(phi)
    err = max(np.max(np.abs(r.position("B") - out[2:4].T)),
              np.max(np.abs(r.omega("A", "B") - out[4])))
    fns = {"mech": lambda: four.solve(phi, omega=W1, need="accelerations"),
           "c": lambda: loops.fourbar(phi), "g": lambda: generic.fourbar(phi)}
    try:
        import numba  # noqa: F401
        from bench_kinematics import pylinkage_linkage
        ref0 = {"XB": r.position("B")[0, 0], "YB": r.position("B")[0, 1]}
        pyl, _ = pylinkage_linkage("fourbar", n, ref0)
        pyl.step_fast_with_kinematics(iterations=n)              # numba compiles here
        fns["pylinkage"] = lambda: pyl.step_fast_with_kinematics(iterations=n)
    except Exception as exc:                                     # not installed
        print(f"pylinkage numba kernel not measured: {exc!r}")
    t = best_of(fns)
    add("four-bar (`fourbar.c`, the book's polar outputs)", n, "accelerations", t["mech"],
        t["c"], t["g"], err)
    if "pylinkage" in t:
        add("four-bar (pylinkage `step_fast_with_kinematics`, numba)", n, "accelerations",
            t["mech"], t["pylinkage"], math.nan, None, ref="pylinkage")

    print(f"load average {os.getloadavg()}")
    print("| case | N | need | Mechanism | C loop | ratio | C generic | ratio | check |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case, n, need, t, tc, tg, err, _ in rows:
        check = "" if err is None else f"{err:.1e}"
        print(f"| {case} | {n} | {need} | {t / n * 1e9:.1f} ns | {tc / n * 1e9:.1f} ns | "
              f"{t / tc:.2f} | {tg / n * 1e9:.1f} ns | {t / tg:.2f} | {check} |")
    res = HERE / "results"
    res.mkdir(exist_ok=True)
    with open(res / "bench_mechanism.csv", "w") as f:
        f.write("case,n,need,mechanism_s,c_s,ratio,c_generic_s,ratio_generic,check\n")
        for case, n, need, t, tc, tg, err, _ in rows:
            f.write(f'"{case}",{n},{need},{t:.6e},{tc:.6e},{t / tc:.4f},{tg:.6e},'
                    f'{t / tg:.4f},{"" if err is None else err}\n')
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(10, 7))
    labels = [f"{case}, N = {n}, {need}" for case, n, need, *_ in rows]
    ax.barh(range(len(rows)), [t / tc for _, _, _, t, tc, *_ in rows],
            color=["C1" if n == 360 else "C0" for _, n, *_ in rows])
    ax.axvline(1.5, color="k", lw=0.8, ls="--")
    ax.set_yticks(range(len(rows)), labels, fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("Mechanism.solve time / hand-written loop's (CPU time of the process; "
                  "dashed: issue 25's 1.5x)")
    ax.set_title("sarkp.Mechanism against hand-written loops storing the same numbers")
    fig.tight_layout()
    fig.savefig(res / "mechanism.png", dpi=110)


def contract():
    """Issue 25's contract, measured in one interleaved run: D designs in one call against
    a Python loop of D solves and against the C loop ``fourbar_mech`` called once per
    design (ctypes: about 2 us of call overhead each, included); points=/links= against
    storing everything; out= against fresh outputs; a one-position solve against a
    scalar DVKT call.  ``python benchmarks/bench_mechanism.py contract``."""
    loops = Loops()
    D, n = 200, 361
    phi = np.linspace(0.0, 2 * math.pi, n)
    rab = np.linspace(0.34, 0.36, D)
    many = sarkp.Mechanism()
    many.fixed("O", 0.0, 0.0)
    many.fixed("C", FOURBAR["xc"], FOURBAR["yc"])
    many.crank("A", "O", FOURBAR["roa"])
    many.rrr("B", "A", "C", rab, FOURBAR["rcb"], branch=1)
    singles = []
    for d in range(D):
        m = sarkp.Mechanism()
        m.fixed("O", 0.0, 0.0)
        m.fixed("C", FOURBAR["xc"], FOURBAR["yc"])
        m.crank("A", "O", FOURBAR["roa"])
        m.rrr("B", "A", "C", rab[d], FOURBAR["rcb"], branch=1)
        singles.append(m)
    saved = FOURBAR["rab"]

    def c_loop():
        out = []
        for d in range(D):
            FOURBAR["rab"] = rab[d]
            out.append(loops.fourbar_mech(phi))
        FOURBAR["rab"] = saved
        return out
    r = many.solve(phi, omega=W1)
    ref = c_loop()
    err = max(_max_error(r._replace(**{f: getattr(r, f)[d] for f in (
        "positions", "velocities", "accelerations", "directions", "omegas", "epsilons")}),
        ref[d]) for d in range(D))
    t = best_of({"designs": lambda: many.solve(phi, omega=W1),
                 "loop": lambda: [m.solve(phi, omega=W1) for m in singles],
                 "c": c_loop})
    print(f"| {D} four-bars x {n} positions, full kinematics | C loop (`fourbar_mech`) per "
          f"design | {t['c'] / (D * n) * 1e9:.1f} ns | | |")
    print(f"| | Mechanism.solve, {D} designs in one call | {t['designs'] / (D * n) * 1e9:.1f}"
          f" ns | {t['designs'] / t['c']:.2f} x C | {err:.1e} |")
    print(f"| | Python loop of {D} solves | {t['loop'] / (D * n) * 1e9:.1f} ns | "
          f"{t['loop'] / t['designs']:.2f} x designs | |")
    g = sixbar_geometry()
    six = sixbar_mechanism(g)
    for N in (10 ** 5, 360):
        ph = np.linspace(0.0, 2 * math.pi, N, endpoint=False)
        sel = dict(points=("E",), links=(("D", "E"),))
        keep = six.solve(ph, omega=W1, **sel)
        t = best_of({"full": lambda: six.solve(ph, omega=W1),
                     "sel": lambda: six.solve(ph, omega=W1, **sel),
                     "out": lambda: six.solve(ph, omega=W1, out=keep, **sel),
                     "c": lambda: loops.sixbar(ph, 3, g)})
        print(f"| six-bar, N = {N} | C loop (`sixbar`), full (44 numbers) | "
              f"{t['c'] / N * 1e9:.1f} ns | | |")
        print(f"| | Mechanism.solve, full | {t['full'] / N * 1e9:.1f} ns | "
              f"{t['full'] / t['c']:.2f} x C | |")
        print(f"| | Mechanism.solve, points=('E',), links=(('D', 'E'),) (10 numbers) | "
              f"{t['sel'] / N * 1e9:.1f} ns | {t['sel'] / t['c']:.2f} x C | |")
        print(f"| | the same with out= | {t['out'] / N * 1e9:.1f} ns | "
              f"{t['out'] / t['c']:.2f} x C | |")
    m4 = fourbar_mechanism()
    R = FOURBAR
    t = best_of({"solve": lambda: m4.solve(0.3, omega=W1),
                 "sel": lambda: m4.solve(0.3, omega=W1, points=("B",), links=()),
                 "dvkt": lambda: sarkp.DVKT(0.0, 0.0, R["roa"], 0.3)})
    print(f"| one position, four-bar | DVKT (scalar) | {t['dvkt'] * 1e6:.2f} us | | |")
    print(f"| | Mechanism.solve(0.3) | {t['solve'] * 1e6:.2f} us | "
          f"{t['solve'] / t['dvkt']:.1f} x DVKT | |")
    print(f"| | Mechanism.solve(0.3, points=('B',), links=()) | {t['sel'] * 1e6:.2f} us | "
          f"{t['sel'] / t['dvkt']:.1f} x DVKT | |")


def reused():
    """The cases of main() with the outputs reused on both sides: the C loops write into
    arrays allocated once, the Mechanism into a result by out=, so that neither pays the
    first touch of fresh pages (how often the allocator hands out fresh pages differs
    between a call's one packed buffer and the C loops' six arrays, and decides the
    fresh-output ratios at 10^5 positions).  Also the minor page faults per call."""
    import resource

    loops = Loops()
    g = sixbar_geometry()
    cases = [("four-bar", fourbar_mechanism(), "fourbar_mech",
              lambda n: [np.empty((n, 2, 2)) for _ in range(3)] + [
                  np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3))],
              lambda lev, ph, out: loops.lib.fourbar_mech(
                  ph.size, lev, ph, *(FOURBAR[k] for k in ("roa", "rab", "rcb", "xc", "yc")),
                  W1, *out)),
             ("six-bar (program X)", sixbar_mechanism(g), "sixbar",
              lambda n: [np.empty((n, 4, 2)) for _ in range(3)] + [
                  np.empty((n, 5, 2)), np.empty((n, 5)), np.empty((n, 5))],
              lambda lev, ph, out: loops.lib.sixbar(
                  ph.size, lev, ph, g["roa"], g["rab"], g["rcb"], g["rcd"], g["rde"],
                  g["xc"], g["yc"], g["yg"], W1, *out)),
             ("inverted slider-crank (rpr)", rpr_mechanism(), "rpr_mech",
              lambda n: [np.empty((n, 2, 2)) for _ in range(3)] + [
                  np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3))],
              lambda lev, ph, out: loops.lib.rpr_mech(
                  ph.size, lev, ph, *(RPR[k] for k in ("roa", "xc", "yc", "h")), W1, *out))]
    print(f"load average {os.getloadavg()}")
    print("| case | N | need | Mechanism, out= | C loop, outputs reused | ratio "
          "| page faults per call (Mechanism fresh / C fresh) |")
    print("|---|---|---|---|---|---|---|")
    needs = ("positions", "velocities", "accelerations")
    for name, mech, cname, alloc, call in cases:
        for N in (100000, 360):
            ph = np.linspace(0.0, 2.0 * math.pi, N, endpoint=False)
            for lev, need in enumerate(needs, 1):
                keep = mech.solve(ph, omega=W1, need=need)
                out = alloc(N)
                t = best_of({"m": lambda: mech.solve(ph, omega=W1, need=need, out=keep),
                             "c": lambda: call(lev, ph, out)})

                def faults(f, k=5):
                    f0 = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
                    for _ in range(k):
                        f()
                    return (resource.getrusage(resource.RUSAGE_SELF).ru_minflt - f0) / k
                pm = faults(lambda: mech.solve(ph, omega=W1, need=need))
                pc = faults(lambda: call(lev, ph, alloc(N)))
                print(f"| {name} (`{cname}`) | {N} | {need} | {t['m'] / N * 1e9:.1f} ns | "
                      f"{t['c'] / N * 1e9:.1f} ns | {t['m'] / t['c']:.2f} | {pm:.0f} / {pc:.0f} |")
    fl = fourbar_mechanism(loads=True)
    L = LOADS
    for N in (100000, 360):
        ph = np.linspace(0.0, 2.0 * math.pi, N, endpoint=False)
        keep = fl.solve(ph, omega=W1, need="forces", gravity=L["g"])
        n = N
        out = [np.empty((n, 2, 2)), np.empty((n, 2, 2)), np.empty((n, 2, 2)),
               np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3)), np.empty((n, 4, 3)),
               np.empty(n), np.empty(n), np.empty(n)]

        def cf():
            loops.lib.fourbar_forces_full(
                n, ph, *(FOURBAR[k] for k in ("roa", "rab", "rcb", "xc", "yc")), W1,
                L["m2"], L["j2"], L["f2"], L["m3"], L["j3"], L["f3"], L["g"], L["t3"], *out)
        t = best_of({"m": lambda: fl.solve(ph, omega=W1, need="forces", gravity=L["g"],
                                           out=keep),
                     "c": cf})
        print(f"| loaded four-bar (`fourbar_forces_full`) | {N} | forces | "
              f"{t['m'] / N * 1e9:.1f} ns | {t['c'] / N * 1e9:.1f} ns | "
              f"{t['m'] / t['c']:.2f} | |")
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    if sys.argv[1:] == ["contract"]:
        contract()
    elif sys.argv[1:] == ["reused"]:
        reused()
    else:
        main()
