"""sarkp.Mechanism against hand-written compiled loops (issue 19).

    python benchmarks/bench_mechanism.py        (against the installed sarkp)

Cases (corrected mode, crank at omega = 3 rad/s, phi_k = 2 pi k / N):

1. program X's six-bar (sarkp.book.x_mechanism's geometry, no loads), full kinematics
   (positions, velocities, accelerations of every moving point and link), Mechanism.solve
   against ``sixbar`` of mechanism_loops.c (the same outputs in the same layout), at
   N = 1e5 and N = 360 (the C loop also built without -march=native, as meson builds
   sarkp);
2. the same six-bar, positions only against full kinematics (both through Mechanism);
3. the four-bar of bench_kinematics.py (OA 0.1, AB 0.35, CB 0.3, C = (0.4, 0)), full
   kinematics, Mechanism against fourbar.c (the issue's baseline, which forms the book's
   polar outputs instead: four more atan2 and two hypot per position, and no crank
   outputs), against ``fourbar_mech`` of mechanism_loops.c (exactly the Mechanism's twenty
   numbers per position: A and B's position, velocity, acceleration, the three moving
   links' cosine, sine, omega, epsilon) and against pylinkage's numba kernel
   ``step_fast_with_kinematics`` when pylinkage and numba are installed;
4. forces: that four-bar with two masses, gravity and a torque, need="forces", against
   ``fourbar_forces`` of mechanism_loops.c (kinematics, then the reactions by moments about
   B and Cramer's rule, the balancing moment: 9 numbers stored per position) and against
   ``fourbar_forces_full`` (the same, storing what the Mechanism stores: the twenty
   numbers of the kinematics, the four pairs' reactions with their couples, M_b, J_red,
   M_red: 38 numbers).

Every C loop's outputs are checked against the Mechanism's (the maximum difference is
printed), so the same work is compared.  Times: best of REPEAT runs of at least 50 ms of
this process's CPU time (time.process_time: the two cores are shared), the paths of a
case interleaved round by round.  Outputs are allocated per call on both sides.  The
table goes to stdout (markdown) and benchmarks/results/bench_mechanism.csv.
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
        self.lib.fourbar_mech.argtypes = [ctypes.c_long, arr] + [d] * 6 + [arr] * 6
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

    def fourbar_mech(self, phi):
        n = phi.size
        out = [np.empty((n, 2, 2)), np.empty((n, 2, 2)), np.empty((n, 2, 2)),
               np.empty((n, 3, 2)), np.empty((n, 3)), np.empty((n, 3))]
        self.lib.fourbar_mech(n, phi, *(FOURBAR[k] for k in ("roa", "rab", "rcb", "xc",
                                                             "yc")), W1, *out)
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


def _max_error(r, out):
    """The largest difference of a Mechanism's kinematics from a C loop's (positions,
    velocities, accelerations relative to their largest, directions, omegas, epsilons
    relative to their largest)."""
    pos, vel, acc, dr, om, ep = out
    return max(np.max(np.abs(r.positions - pos)), np.max(np.abs(r.velocities - vel)),
               np.max(np.abs(r.accelerations - acc)) / np.max(np.abs(acc)),
               np.max(np.abs(r.directions - dr)), np.max(np.abs(r.omegas - om)),
               np.max(np.abs(r.epsilons - ep)) / np.max(np.abs(ep)))


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


def main():
    loops = Loops()
    generic = Loops(native=False)
    rows = []

    def add(case, path, n, t, ref=None, err=None):
        rows.append((case, path, n, t, ref, err))

    g = sixbar_geometry()
    six = sixbar_mechanism(g)
    for n in (100_000, 360):
        phi = 2 * math.pi * np.arange(n) / n
        r = six.solve(phi, omega=W1, need="accelerations")
        pos, vel, acc, dr, om, ep = loops.sixbar(phi, 3, g)
        err = _max_error(r, (pos, vel, acc, dr, om, ep))
        t = best_of({"mech": lambda: six.solve(phi, omega=W1, need="accelerations"),
                     "c": lambda: loops.sixbar(phi, 3, g),
                     "cgen": lambda: generic.sixbar(phi, 3, g),
                     "mechpos": lambda: six.solve(phi, omega=W1, need="positions"),
                     "mechvel": lambda: six.solve(phi, omega=W1, need="velocities"),
                     "cpos": lambda: loops.sixbar(phi, 1, g)})
        case = f"six-bar (program X), N = {n}"
        add(case, "C loop (mechanism_loops.c sixbar), full", n, t["c"])
        add(case, "Mechanism.solve, full (accelerations)", n, t["mech"], t["c"], err)
        add(case, "C loop, full, -O3 without -march=native (as sarkp is built)", n,
            t["cgen"])
        add(case, "Mechanism.solve, full, against that C loop", n, t["mech"], t["cgen"])
        add(case, "C loop, positions only", n, t["cpos"])
        add(case, "Mechanism.solve, positions only", n, t["mechpos"], t["mech"])
        add(case, "Mechanism.solve, velocities", n, t["mechvel"], t["mech"])

    n = 100_000
    phi = 2 * math.pi * np.arange(n) / n
    four = fourbar_mechanism()
    r = four.solve(phi, omega=W1, need="accelerations")
    out = loops.fourbar(phi)
    err = max(np.max(np.abs(r.position("B") - out[2:4].T)),
              np.max(np.abs(r.omega("A", "B") - out[4])))
    same = loops.fourbar_mech(phi)
    err_same = _max_error(r, same)
    fns = {"mech": lambda: four.solve(phi, omega=W1, need="accelerations"),
           "c": lambda: loops.fourbar(phi),
           "csame": lambda: loops.fourbar_mech(phi)}
    pyl = None
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
    case = f"four-bar, N = {n}"
    add(case, "C loop (fourbar.c, with polar outputs), full", n, t["c"])
    add(case, "Mechanism.solve, full", n, t["mech"], t["c"], err)
    add(case, "C loop (mechanism_loops.c fourbar_mech: the Mechanism's outputs)", n,
        t["csame"])
    add(case, "Mechanism.solve, full, against that C loop", n, t["mech"], t["csame"],
        err_same)
    if "pylinkage" in t:
        add(case, "pylinkage step_fast_with_kinematics (numba)", n, t["pylinkage"],
            t["mech"])

    fl = fourbar_mechanism(loads=True)
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
    t = best_of({"mech": lambda: fl.solve(phi, omega=W1, need="forces", gravity=LOADS["g"]),
                 "c": lambda: loops.forces(phi),
                 "cfull": lambda: loops.forces_full(phi)})
    case = f"four-bar forces, N = {n}"
    add(case, "C loop (mechanism_loops.c fourbar_forces: 9 numbers)", n, t["c"])
    add(case, "Mechanism.solve, need='forces'", n, t["mech"], t["c"], err)
    add(case, "C loop (fourbar_forces_full: the Mechanism's 38 numbers)", n, t["cfull"])
    add(case, "Mechanism.solve, need='forces', against that C loop", n, t["mech"],
        t["cfull"], err_full)

    print(f"load average {os.getloadavg()}")
    print("| case | path | time per position | ratio | check |")
    print("|---|---|---|---|---|")
    for case, path, n, t, ref, err in rows:
        ratio = "" if ref is None else f"{t / ref:.2f}"
        check = "" if err is None else f"{err:.1e}"
        print(f"| {case} | {path} | {t / n * 1e9:.1f} ns ({t * 1e6:.1f} us per call) | "
              f"{ratio} | {check} |")
    res = HERE / "results"
    res.mkdir(exist_ok=True)
    with open(res / "bench_mechanism.csv", "w") as f:
        f.write("case,path,n,seconds,ratio,check\n")
        for case, path, n, t, ref, err in rows:
            f.write(f'"{case}","{path}",{n},{t:.6e},{"" if ref is None else t / ref},'
                    f'{"" if err is None else err}\n')
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(11, 6.5))
    labels = [f"{case}: {path}" for case, path, *_ in rows]
    ax.barh(range(len(rows)), [t / n * 1e9 for _, _, n, t, _, _ in rows],
            color=["C1" if "Mechanism" in p else "C0" for _, p, *_ in rows])
    ax.set_yticks(range(len(rows)), labels, fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("time per position, ns (CPU time of the process)")
    ax.set_title("sarkp.Mechanism (orange) against hand-written loops and peers")
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


if __name__ == "__main__":
    if sys.argv[1:] == ["contract"]:
        contract()
    else:
        main()
