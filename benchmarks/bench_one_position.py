"""The fixed cost of a Mechanism solve (issue 25: one position at most 4x a scalar DVKT).

    python benchmarks/bench_one_position.py            wall time, interleaved
    python benchmarks/bench_one_position.py CASE N     run CASE N times (for callgrind)
    python benchmarks/bench_one_position.py callgrind  instructions per call of each case
    python benchmarks/bench_one_position.py callgrind-phases [CASE ...]   the same, one run

Cases: the four-bar of bench_mechanism.py (OA 0.1, AB 0.35, CB 0.3, C = (0.4, 0)) solved
at one position, ``m.solve(0.3, omega=10.0)`` (the issue's call), with ``points=("B",),
links=()``, at need="positions" and "forces" (two masses, a torque, gravity), the same
call with ``phi`` a 1-element array (the general path); a scalar ``sarkp.DVKT`` call
(the target's unit); the six-bar of program X and the four-bar at 360 positions (full
kinematics) against the C loops of mechanism_loops.c (bench_mechanism.Loops).

Wall time: every case of a group called in turn, round after round, in one process
(time.perf_counter, best of ROUNDS rounds of at least 50 ms each); the load average is
printed.  Instructions: each case run under ``valgrind --tool=callgrind`` with 200 calls
and with 2200 calls; the difference over 2000 is the cost of one call (start-up and
warm-up cancel).  With SARKP_OLD=dir, the same cases of a second copy of the package
(importable as ``sarkp_old`` from dir) are interleaved too (before/after in one process).
"""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

import sarkp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROUNDS = int(os.environ.get("SARKP_BENCH_ROUNDS", "9"))
FOURBAR = dict(roa=0.1, rab=0.35, rcb=0.3, xc=0.4, yc=0.0)


def fourbar(pkg, loads=False):
    m = pkg.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", FOURBAR["xc"], FOURBAR["yc"])
    m.crank("A", "O", FOURBAR["roa"])
    m.rrr("B", "A", "C", FOURBAR["rab"], FOURBAR["rcb"], branch=1)
    if loads:
        m.mass("A", "B", mass=1.5, inertia=0.012, centre=0.175)
        m.mass("C", "B", mass=1.0, inertia=0.01, centre=0.15)
        m.torque("C", "B", -20.0)
    return m


def cases(pkg):
    """name -> a call without arguments, for the package ``pkg`` (sarkp or sarkp_old)."""
    from bench_mechanism import sixbar_geometry, sixbar_mechanism
    m4 = fourbar(pkg)
    mf = fourbar(pkg, loads=True)
    six = sixbar_mechanism(sixbar_geometry()) if pkg is sarkp else None
    if six is None:                     # the same six-bar, described with the other package
        g = sixbar_geometry()
        six = pkg.Mechanism()
        six.fixed("O", 0.0, 0.0)
        six.fixed("C", g["xc"], g["yc"])
        six.fixed("K", 0.0, g["yg"])
        six.crank("A", "O", g["roa"])
        six.rrr("B", "A", "C", g["rab"], g["rcb"], branch=1)
        six.point("D", "C", "B", g["rcd"], math.pi)
        six.rrp("E", "D", "K", 0.0, g["rde"], branch=1)
    one = np.array([0.3])
    ph = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    return {
        "solve": lambda: m4.solve(0.3, omega=10.0),
        "select": lambda: m4.solve(0.3, omega=10.0, points=("B",), links=()),
        "positions": lambda: m4.solve(0.3, omega=10.0, need="positions"),
        "forces": lambda: mf.solve(0.3, omega=10.0, need="forces", gravity=9.81),
        "array1": lambda: m4.solve(one, omega=10.0),
        "dvkt": lambda: pkg.DVKT(0.0, 0.0, FOURBAR["roa"], 0.3),
        "six360": lambda: six.solve(ph, omega=3.0),
        "four360": lambda: m4.solve(ph, omega=3.0),
    }


def best(fns, rounds=ROUNDS, min_time=0.05):
    """Best time per call of each of ``fns`` (name -> call), interleaved round by round."""
    reps = {}
    for k, f in fns.items():
        f()
        r = 1
        while True:
            t0 = time.perf_counter()
            for _ in range(r):
                f()
            if time.perf_counter() - t0 >= min_time:
                break
            r *= 2
        reps[k] = r
    out = {k: math.inf for k in fns}
    for _ in range(rounds):
        for k, f in fns.items():
            r = reps[k]
            t0 = time.perf_counter()
            for _ in range(r):
                f()
            out[k] = min(out[k], (time.perf_counter() - t0) / r)
    return out


def wall():
    print(f"load average before: {os.getloadavg()}")
    groups = [cases(sarkp)]
    old = os.environ.get("SARKP_OLD")
    if old:
        sys.path.insert(0, old)
        import sarkp_old
        groups.append(cases(sarkp_old))
    fns = {}
    for i, g in enumerate(groups):
        for k, f in g.items():
            if k not in ("six360", "four360"):
                fns[("new", "old")[i] + " " + k] = f
    t = best(fns)
    d = t["new dvkt"]
    print("| case | time per call | x DVKT (new) |")
    print("|---|---|---|")
    for k, v in t.items():
        print(f"| {k} | {v * 1e6:.2f} us | {v / d:.1f} |")
    from bench_mechanism import Loops, sixbar_geometry
    loops = Loops()
    g = sixbar_geometry()
    ph = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    FB = FOURBAR

    def c_four():
        return loops.fourbar_mech(ph)
    import bench_mechanism
    bench_mechanism.FOURBAR.update(FB)
    fns = {"six C": lambda: loops.sixbar(ph, 3, g), "four C": c_four}
    for i, grp in enumerate(groups):
        fns[("new", "old")[i] + " six360"] = grp["six360"]
        fns[("new", "old")[i] + " four360"] = grp["four360"]
    t = best(fns)
    print("| 360 positions | time per position | x C loop |")
    print("|---|---|---|")
    for k, v in t.items():
        ref = t["six C"] if "six" in k else t["four C"]
        print(f"| {k} | {v / 360 * 1e9:.1f} ns | {v / ref:.2f} |")
    print(f"load average after: {os.getloadavg()}")


def run(case, n):
    pkg = sarkp
    if os.environ.get("SARKP_OLD"):
        sys.path.insert(0, os.environ["SARKP_OLD"])
        import sarkp_old as pkg
    f = cases(pkg)[case]
    for _ in range(n):
        f()


def phases(names):
    """Each case: 200 calls, then 2000; os.getppid() between the phases, where
    ``valgrind --dump-before=getppid`` writes a dump (callgrind_phases)."""
    pkg = sarkp
    if os.environ.get("SARKP_OLD"):
        sys.path.insert(0, os.environ["SARKP_OLD"])
        import sarkp_old as pkg
    fs = cases(pkg)
    for name in names:
        f = fs[name]
        os.getppid()
        for _ in range(200):
            f()
        os.getppid()
        for _ in range(2000):
            f()
    os.getppid()


def callgrind_phases(names):
    """Instructions per call of each case in one valgrind run: the dump after a case's
    2000 calls (its 200 warm-up calls and the start-up are in other dumps)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                        "--dump-before=getppid", sys.executable, os.path.abspath(__file__),
                        "phases", *names], capture_output=True, text=True, check=True)
        dumps = sorted((f for f in os.listdir(tmp) if f.startswith("cg.out.")),
                       key=lambda f: int(f.rsplit(".", 1)[1]))
        totals = []
        for f in dumps:
            text = open(os.path.join(tmp, f)).read()
            totals.append(int(re.search(r"^(?:summary|totals): (\d+)", text, re.M).group(1)))
    # dumps: start-up, then per case (warm-up, 2000 calls), then the rest
    per = {name: totals[2 + 2 * i] / 2000 for i, name in enumerate(names)}
    print("| case | instructions per call | x DVKT |")
    print("|---|---|---|")
    for name, v in per.items():
        print(f"| {name} | {v / 1e3:.1f}k | {v / per.get('dvkt', v):.1f} |")
    return per


def instructions(case, n):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        p = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                            sys.executable, os.path.abspath(__file__), case, str(n)],
                           capture_output=True, text=True, check=True)
        m = re.search(r"Collected : (\d+)", p.stderr)
        return int(m.group(1))


def callgrind():
    print("| case | instructions per call | x DVKT |")
    print("|---|---|---|")
    per = {}
    for case in ("dvkt", "solve", "select", "positions", "forces", "array1", "four360",
                 "six360"):
        per[case] = (instructions(case, 2200) - instructions(case, 200)) / 2000
        print(f"| {case} | {per[case] / 1e3:.1f}k | {per[case] / per['dvkt']:.1f} |",
              flush=True)


if __name__ == "__main__":
    if sys.argv[1:2] == ["phases"]:
        phases(sys.argv[2:])
    elif sys.argv[1:2] == ["callgrind-phases"]:
        callgrind_phases(sys.argv[2:] or ["dvkt", "solve", "select", "positions", "forces",
                                          "array1", "four360", "six360"])
    elif len(sys.argv) == 3:
        run(sys.argv[1], int(sys.argv[2]))
    elif sys.argv[1:] == ["callgrind"]:
        callgrind()
    else:
        wall()
