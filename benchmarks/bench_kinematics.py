"""Chapter 4: full kinematics over 10^5 crank positions, run time against error.

Two mechanisms, both driven by a crank at constant omega1 (corrected mode, exact pi):

* ``fourbar``: a crank-rocker four-bar, crank OA + one RRR group A-B-C
  (DPRM1/DSKOR1/DUSKR1, or DKNMA1);
* ``course``: the course-project mechanism of chapter 10 (Fig. 91, the conveyor feeder,
  with the fitted link lengths of docs/notes): the same crank + RRR group, the lever point
  D = C + RCD*e(FICB + pi), then the RRP group D-E with the slider E on a horizontal
  guide (DPRM2/DSKOR2/DUSKR2, or DKNMA2).

Paths timed (issue 9), per crank position unless stated:

1. the hand-written C loop ``fourbar.c`` (closed-form circle intersection, Cramer 2x2,
   the book's polar outputs), compiled here with cc -O3 -march=native into a temporary
   directory and called through ctypes on NumPy arrays;
2. the sarkp array path: one call per routine over all positions (DKNMA1, or
   DPRM1 + DSKOR1 + DUSKR1), positions only (DPRM1), positions + velocities (DKNMA1 with
   ANALOG = 1); the generated drivers ``_sarkp.drv_kinematics.NAME_n`` called bare; the
   same Fortran routines in a pure-Fortran loop (``fortran_driver.f90``, gfortran -O3);
3. per call: a 360-position sweep (one DKNMA1 call, three calls), the fixed cost (arrays
   of one position), the scalar calls DKNMA1, DPRM1 and DVKT, a Python loop of scalar calls;
4. two threads (ThreadPoolExecutor) over two chunks of a 10^6 sweep against one call;
5. the peers, installed only in the benchmark's own venv (never project dependencies):
   pylinkage (its numba kernel ``step_fast_with_kinematics`` and its Python-level
   ``step_with_derivatives``), mechanism (loop equations with fsolve), kinepy (vectorised
   positions; velocities only by its own central differences);
6. the course mechanism of chapter 10 in the same table;
7. time per position against the number of positions (10 to 10^6), plotted.

Times are the best of repeats in CPU time of the process (time.process_time), except the
threads (wall time); the load average is printed at the start and the end.

Error: against an mpmath reference at 40 digits on a sample of ``N_SAMPLE`` positions:
closed-form positions (circle-circle and circle-line intersections), velocities and
accelerations by ``mpmath.diff`` of those positions (v = omega1*dX/dphi,
a = omega1**2*d2X/dphi2).  Each error is the largest |computed - exact| over the sample,
divided by the largest |exact| of that quantity over the sample, maximised over the
quantities of a class: points B (and E) for every method; the angles, omegas and epsilons
for sarkp as well.

Run: ``python benchmarks/bench_kinematics.py`` (from outside the source tree, with sarkp,
mpmath, pylinkage[numba] and mechanism installed; gfortran and LAPACK for the driver).
Prints a Markdown table and the targets of issue 9, and writes
``benchmarks/results/kinematics.csv``, ``kinematics_sizes.csv`` and ``kinematics.png``.
"""

from __future__ import annotations

import concurrent.futures
import csv
import ctypes
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time
import timeit
import warnings

import mpmath
import numpy as np

import sarkp
from sarkp import _sarkp
from sarkp import kinematics as K
from sarkp.modes import MODE_CODE

HERE = pathlib.Path(__file__).resolve().parent
FORTRAN = HERE.parent / "fortran"
OUT = HERE / "results"

# SARKP_BENCH_QUICK=1 shrinks everything for a smoke test
_Q = os.environ.get("SARKP_BENCH_QUICK") == "1"
N = 10**4 if _Q else 10**5   # positions of the array, driver and numba paths
N_SCALAR = 200 if _Q else 2000   # positions of the Python scalar loop
N_PEER = 100 if _Q else 1000     # positions of the slow peers (mechanism, pylinkage loop)
N_SAMPLE = 20 if _Q else 200     # positions of the error sample (every N // N_SAMPLE-th)
REPEAT = 2 if _Q else 5
if _Q:                           # a smoke run does not overwrite the results
    OUT = OUT / "quick"
N_BIG = 10**5 if _Q else 10**6   # the threads benchmark
W1 = 3.0             # crank angular velocity, rad/s (the book's omega1)

# (a) a crank-rocker four-bar (Grashof: 0.1 + 0.4 < 0.35 + 0.3), O = (0, 0), C = (0.4, 0)
FOURBAR = dict(roa=0.1, rab=0.35, rcb=0.3, xc=0.4, yc=0.0)
# (b) the course project of chapter 10 (notes book-ch9-10.md 2.2, 2.5): fitted ROA, RAB,
# ROC, DSNTZR's RCD = RCB, RDE; C at 130 deg (formula 27, DELTA = 0.698); the guide of
# the slider at y = H5 + YC (formula 31)
_DELTA, _ROC, _H5 = 0.698, 2.09023145, 0.64
COURSE = dict(roa=0.16646893, rab=2.33535352, rcb=0.5787882, rcd=0.5787882, rde=0.7012536,
              xc=-_ROC * math.sin(_DELTA), yc=_ROC * math.cos(_DELTA))
COURSE["yg"] = _H5 + COURSE["yc"]


def best(fn, repeat=REPEAT, timer=time.process_time, min_time=0.05):
    """Best time of one call of ``fn`` over ``repeat`` repeats of at least ``min_time``.
    The default timer is this process's CPU time: time spent waiting for one of the two
    shared cores does not count (the threads benchmark passes time.perf_counter)."""
    t, number = calibrated(fn, timer, min_time)
    return min(t.repeat(repeat, number)) / number


def calibrated(fn, timer=time.process_time, min_time=0.05):
    """A warmed-up timeit.Timer of ``fn`` and the number of calls that take ``min_time``."""
    t = timeit.Timer(fn, timer=timer)
    t.timeit(1)                                               # warm up
    return t, max(1, int(min_time / max(t.timeit(1), 1e-7)))


def one_position_calls(g=FOURBAR, phi=0.3):
    """The fourbar at one crank angle: DKNMA1 and DPRM1 on arrays of one position (the
    fixed cost of a sweep) and on Python floats (the scalar calls), by name."""
    one = np.array([phi])
    xa, ya, ala, ba = g["roa"] * np.cos(one), g["roa"] * np.sin(one), one + PID2, one + PI
    fx, fy, fal, fb = (float(v[0]) for v in (xa, ya, ala, ba))
    return {
        "sarkp DKNMA1, arrays of 1": lambda: K.DKNMA1(
            xa, ya, g["xc"], g["yc"], g["rab"], g["rcb"], W1 * g["roa"], ala, 0.0, 0.0,
            W1**2 * g["roa"], ba, 0.0, 0.0, 1.0, 0.0),
        "sarkp DPRM1, arrays of 1": lambda: K.DPRM1(
            xa, ya, g["xc"], g["yc"], g["rab"], g["rcb"], -1.0),
        "sarkp DKNMA1, scalar call": lambda: K.DKNMA1(
            fx, fy, g["xc"], g["yc"], g["rab"], g["rcb"], W1 * g["roa"], fal, 0.0, 0.0,
            W1**2 * g["roa"], fb, 0.0, 0.0, 1.0, 0.0),
        "sarkp DPRM1, scalar call": lambda: K.DPRM1(
            fx, fy, g["xc"], g["yc"], g["rab"], g["rcb"], -1.0),
        "raw driver dknma1_1, scalar call": lambda: _DRV.dknma1_1(
            0, fx, fy, g["xc"], g["yc"], g["rab"], g["rcb"], W1 * g["roa"], fal, 0.0, 0.0,
            W1**2 * g["roa"], fb, 0.0, 0.0, 1.0, 0.0),
    }


def crank_angles(n):
    # the driver computes 2*pi*(i-1)/n in the same order
    return 2.0 * np.pi * np.arange(n, dtype=float) / n


# ---------------------------------------------------------------------------------------
# sarkp: one code for the array path (NumPy) and the scalar loop (math)
# ---------------------------------------------------------------------------------------

class _NP:
    cos, sin, sqrt, atan2, abs = np.cos, np.sin, np.sqrt, np.arctan2, np.abs


class _M:
    cos, sin, sqrt, atan2, abs = math.cos, math.sin, math.sqrt, math.atan2, abs


PI, PID2 = math.pi, math.pi / 2


def fourbar_split(phi, level, M, g=FOURBAR):
    """Crank + RRR group with DPRM1 / DSKOR1 / DUSKR1 (book argument order)."""
    xa, ya = g["roa"] * M.cos(phi), g["roa"] * M.sin(phi)
    p = K.DPRM1(xa, ya, g["xc"], g["yc"], g["rab"], g["rcb"], -1)
    out = {"XB": p.XB, "YB": p.YB, "FI2": p.FI2, "FI3": p.FI3}
    if level < 2:
        return out
    v = K.DSKOR1(g["rab"], p.FI2, g["rcb"], p.FI3, W1 * g["roa"], phi + PID2, 0.0, 0.0)
    out.update(VB=v.VB, ALB=v.ALB, W2=v.W2, W3=v.W3)
    if level < 3:
        return out
    a = K.DUSKR1(W1**2 * g["roa"], phi + PI, 0.0, 0.0, g["rab"], p.FI2, g["rcb"], p.FI3,
                 v.W2, v.W3)
    out.update(AB=a.AB, BB=a.BB, E2=a.E2, E3=a.E3)
    return out


def fourbar_dknma(phi, level, M, g=FOURBAR, out=None):
    """Crank + RRR group with DKNMA1 (P = +1 is DPRM1's P = -1; ANALOG = 1: no accel.);
    ``out``: the caller's result array, reused from call to call."""
    r = K.DKNMA1(g["roa"] * M.cos(phi), g["roa"] * M.sin(phi), g["xc"], g["yc"], g["rab"],
                 g["rcb"], W1 * g["roa"], phi + PID2, 0.0, 0.0, W1**2 * g["roa"], phi + PI,
                 0.0, 0.0, 1, 1.0 if level < 3 else 0.0, **({} if out is None else {"out": out}))
    return {"XB": r.XB, "YB": r.YB, "FI2": r.FI2, "FI3": r.FI3, "VB": r.VB, "ALB": r.ALB,
            "W2": r.W2, "W3": r.W3, "AB": r.AB, "BB": r.BB, "E2": r.E2, "E3": r.E3}


def _lever_d(fi3, M, g):
    return g["xc"] + g["rcd"] * M.cos(fi3 + PI), g["yc"] + g["rcd"] * M.sin(fi3 + PI)


def _acc_dir_d(fi3, w3, e3, M):
    # the book's DUGL3(FICB + PI, PI - ATAN(ABS(E3)/W3**2), E3), with atan2 for W3 = 0
    return sarkp.DUGL3(fi3 + PI, PI - M.atan2(M.abs(e3), w3 * w3), e3)


def course_split(phi, level, M, g=COURSE):
    """The chapter-10 mechanism with DPRM1, DPRM2 / DSKOR1, DSKOR2 / DUSKR1, DUSKR2."""
    out = fourbar_split(phi, level, M, g)
    xd, yd = _lever_d(out["FI3"], M, g)
    p = K.DPRM2(xd, yd, 0.0, g["yg"], 0.0, g["rde"], 0.0, PID2)
    out.update(XE=p.XB, FIDE=p.FI2)
    if level < 2:
        return out
    w3 = out["W3"]
    v = K.DSKOR2(g["rcd"] * M.abs(w3), sarkp.DUGL3(out["FI3"] + PI, PID2, w3), 0.0, 0.0,
                 g["rde"], p.FI2, 0.0)
    out.update(VE=v.VB, ALE=v.ALB, W4=v.W2)
    if level < 3:
        return out
    e3 = out["E3"]
    a = K.DUSKR2(g["rcd"] * M.sqrt(w3**4 + e3**2), _acc_dir_d(out["FI3"], w3, e3, M),
                 0.0, 0.0, 0.0, 0.0, g["rde"], p.FI2, v.W2, 0.0)
    out.update(AE=a.AB, BE=a.BB, E4=a.E2)
    return out


def course_dknma(phi, level, M, g=COURSE):
    """The chapter-10 mechanism with DKNMA1 + DKNMA2."""
    out = fourbar_dknma(phi, level, M, g)
    xd, yd = _lever_d(out["FI3"], M, g)
    w3, e3 = out["W3"], out["E3"]
    ad = bd = 0.0
    if level >= 3:
        ad, bd = g["rcd"] * M.sqrt(w3**4 + e3**2), _acc_dir_d(out["FI3"], w3, e3, M)
    r = K.DKNMA2(xd, yd, 0.0, g["yg"], 0.0, g["rde"], 0.0, PID2,
                 g["rcd"] * M.abs(w3), sarkp.DUGL3(out["FI3"] + PI, PID2, w3), 0.0, 0.0,
                 0.0, ad, bd, 0.0, 0.0, 1, 1.0 if level < 3 else 0.0)
    out.update(XE=r.XB, FIDE=r.FI2, VE=r.VB, ALE=r.ALB, W4=r.W2, AE=r.AB, BE=r.BB, E4=r.E2)
    return out


_DRV = _sarkp.drv_kinematics
_INC = {}        # (routine, array inputs) -> the sarkp_inc vector of its NAME_n driver


def _raw_n(name, n, *args):
    """Call the generated driver NAME_n directly: no Python layer (no conversion, no
    broadcasting, no status handling).  Arrays advance by 1, floats are passed once.
    Returns the result rows, then the status and sarkp_bad, as the driver fills them."""
    spec = getattr(sarkp, name.upper()).spec
    key = (name, tuple(type(a) is not float for a in args))
    if key not in _INC:
        _INC[key] = np.array(key[1], dtype=np.int32)
    out = np.empty((len(spec.outputs), n))
    status = np.zeros(n, np.int32)                  # in: nothing ruled out; out: statuses
    bad = getattr(_DRV, name + "_n")(MODE_CODE.get(), _INC[key], 0, *args, out.T, status)
    return [*out, status, bad]


def fourbar_raw_dknma(phi, g=FOURBAR):
    """The full four-bar through the bare driver dknma1_n."""
    return _raw_n("dknma1", phi.size, g["roa"] * np.cos(phi), g["roa"] * np.sin(phi),
                  g["xc"], g["yc"], g["rab"], g["rcb"], W1 * g["roa"], phi + PID2, 0.0, 0.0,
                  W1**2 * g["roa"], phi + PI, 0.0, 0.0, 1.0, 0.0)


def fourbar_raw_split(phi, g=FOURBAR):
    """The full four-bar through the bare drivers dprm1_n, dskor1_n, duskr1_n."""
    n = phi.size
    fi2, fi3, xb, yb, _, _ = _raw_n("dprm1", n, g["roa"] * np.cos(phi),
                                    g["roa"] * np.sin(phi), g["xc"], g["yc"], g["rab"],
                                    g["rcb"], -1.0, 1.0)
    v = _raw_n("dskor1", n, g["rab"], fi2, g["rcb"], fi3, W1 * g["roa"], phi + PID2, 0.0,
               0.0, 1.0)
    a = _raw_n("duskr1", n, W1**2 * g["roa"], phi + PI, 0.0, 0.0, g["rab"], fi2, g["rcb"],
               fi3, v[6], v[7], 1.0)
    return xb, yb, v, a


def fourbar_raw_scalar(phis, g=FOURBAR):
    """The full four-bar through the bare scalar drivers NAME_1, in a Python loop."""
    mode = MODE_CODE.get()
    roa, xc, yc, rab, rcb = g["roa"], g["xc"], g["yc"], g["rab"], g["rcb"]
    for f in phis:
        f = float(f)
        _DRV.dknma1_1(mode, roa * math.cos(f), roa * math.sin(f), xc, yc, rab, rcb, W1 * roa,
                      f + PID2, 0.0, 0.0, W1**2 * roa, f + PI, 0.0, 0.0, 1.0, 0.0)


# ---------------------------------------------------------------------------------------
# the hand-written C loop (fourbar.c)
# ---------------------------------------------------------------------------------------

C_OUTPUTS = ("FI2", "FI3", "XB", "YB", "W2", "W3", "E2", "E3", "VB", "ALB", "AB", "BB")
C_FLAGS = ["-O3", "-march=native", "-shared", "-fPIC"]


class CLoop:
    """fourbar.c compiled with cc -O3 -march=native into a temporary directory and called
    through ctypes on NumPy arrays (the outputs allocated per call, as sarkp does)."""

    def __init__(self):
        cc = shutil.which("cc") or shutil.which("gcc")
        if cc is None:
            raise OSError("no C compiler (cc) found")
        self._tmp = tempfile.TemporaryDirectory()
        lib = pathlib.Path(self._tmp.name) / "libfourbar.so"
        subprocess.run([cc, *C_FLAGS, "-o", str(lib), str(HERE / "fourbar.c"), "-lm"],
                       check=True)
        self.cmd = " ".join(["cc", *C_FLAGS, "fourbar.c", "-lm"])
        self._lib = ctypes.CDLL(str(lib))
        arr = np.ctypeslib.ndpointer(np.float64, flags="C_CONTIGUOUS")
        self._lib.fourbar.argtypes = [ctypes.c_long, ctypes.c_int, arr] + \
            [ctypes.c_double] * 6 + [arr]
        self._lib.fourbar.restype = ctypes.c_int

    def __call__(self, phi, level=3, g=FOURBAR):
        out = np.empty((len(C_OUTPUTS), phi.size))
        if self._lib.fourbar(phi.size, level, phi, g["roa"], g["rab"], g["rcb"], g["xc"],
                             g["yc"], W1, out):
            raise ValueError("fourbar.c: the links do not reach")
        names = C_OUTPUTS[:4] + (("W2", "W3", "VB", "ALB") if level >= 2 else ()) + \
            (("E2", "E3", "AB", "BB") if level >= 3 else ())
        return {k: out[C_OUTPUTS.index(k)] for k in names}


# ---------------------------------------------------------------------------------------
# kinepy (positions by NumPy-vectorised closed forms; no analytic velocities)
# ---------------------------------------------------------------------------------------

class KinepyFourbar:
    """The four-bar in kinepy 0.1.7: solids crank, coupler, rocker and four revolutes; the
    RRR group's sign chosen so that B is the reference's branch.  kinepy computes positions
    only; its dynamics differentiates them numerically (kinepy.math.calculus, central
    differences), which is what ``derivatives`` does here."""

    def __init__(self, g=FOURBAR):
        import contextlib
        import io
        import kinepy.units as ku
        from kinepy import System
        ku.SYSTEM.set(ku.LENGTH, *ku.METER)
        self.g = g
        with contextlib.redirect_stdout(io.StringIO()):      # kinepy prints as it compiles
            s = System()
            crank, coupler, rocker = (s.add_solid(n) for n in ("crank", "coupler", "rocker"))
            j0 = s.add_revolute(0, crank, (0.0, 0.0), (0.0, 0.0))
            s.add_revolute(crank, coupler, (g["roa"], 0.0), (0.0, 0.0))
            s.add_revolute(coupler, rocker, (g["rab"], 0.0), (g["rcb"], 0.0))
            s.add_revolute(rocker, 0, (0.0, 0.0), (g["xc"], g["yc"]))
            s.pilot(j0)
            s.compile()
            s.change_signs(-1)
        self.system, self.coupler = s, coupler._object

    def positions(self, phi):
        self.system.solve_kinematics(phi[None, :].copy())
        c = self.coupler
        r = self.g["rab"]
        return {"XB": c.origin[0] + r * np.cos(c.angle), "YB": c.origin[1] + r * np.sin(c.angle)}

    def derivatives(self, phi):
        from kinepy.math.calculus import derivative2_vec, derivative_vec
        p = self.positions(phi)
        xy = np.array([p["XB"], p["YB"]])
        dt = (phi[1] - phi[0]) / W1                         # crank at constant W1
        v, a = derivative_vec(xy, dt), derivative2_vec(xy, dt)
        p.update(VXB=v[0], VYB=v[1], AXB=a[0], AYB=a[1])
        return p


def scalar_loop(fn, phis, level):
    for f in phis:
        fn(float(f), level, _M)


# ---------------------------------------------------------------------------------------
# the pure-Fortran driver
# ---------------------------------------------------------------------------------------

def run_driver(n, reps):
    """Compile fortran_driver.f90 with gfortran -O3 -llapack in a temp dir and run it."""
    gfortran = shutil.which("gfortran")
    if gfortran is None:
        return None, None, "gfortran not found"
    srcs = [FORTRAN / f for f in ("prmtr.f90", "gelg.f90", "operators.f90",
                                  "kinematics.f90")] + [HERE / "fortran_driver.f90"]
    with tempfile.TemporaryDirectory() as tmp:
        exe = pathlib.Path(tmp) / "driver"
        cmd = [gfortran, "-O3", "-J", tmp, "-o", str(exe)] + [str(s) for s in srcs] + \
              ["-llapack"]
        subprocess.run(cmd, check=True, cwd=tmp)
        nml = pathlib.Path(tmp) / "geom.nml"
        fb, cp = FOURBAR, COURSE
        nml.write_text(
            f"&geom n={n}, reps={reps}, w1={W1!r},\n"
            f" fb_roa={fb['roa']!r}, fb_rab={fb['rab']!r}, fb_rcb={fb['rcb']!r},"
            f" fb_xc={fb['xc']!r}, fb_yc={fb['yc']!r},\n"
            f" cp_roa={cp['roa']!r}, cp_rab={cp['rab']!r}, cp_rcb={cp['rcb']!r},"
            f" cp_rcd={cp['rcd']!r}, cp_rde={cp['rde']!r},\n"
            f" cp_xc={cp['xc']!r}, cp_yc={cp['yc']!r}, cp_yg={cp['yg']!r},\n"
            f" dumpfile='{tmp}/dump' /\n")
        res = subprocess.run([str(exe), str(nml)], check=True, capture_output=True,
                             text=True, cwd=tmp)
        times = {}
        for line in res.stdout.splitlines():
            name, level, ns, ier, _ = line.split()
            times[(name, int(level))] = (float(ns) * 1e-9, int(ier))
        names = ["XB", "YB", "FI2", "FI3", "VB", "ALB", "W2", "W3", "AB", "BB", "E2", "E3"]
        dumps = {}
        for mech, extra in (("fourbar", []),
                            ("course", ["FIDE", "XE", "VE", "ALE", "W4", "AE", "BE", "E4"])):
            data = np.fromfile(f"{tmp}/dump.{mech}", dtype=np.float64).reshape(-1, n)
            dumps[mech] = dict(zip(names + extra, data))
    return times, dumps, " ".join(["gfortran", "-O3"] + [s.name for s in srcs] + ["-llapack"])


# ---------------------------------------------------------------------------------------
# peers
# ---------------------------------------------------------------------------------------

def pylinkage_linkage(mech, n, phi0_ref):
    """Build the mechanism in pylinkage; the branch is set by position hints at phi = 0."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import FixedDyad, RRPDyad, RRRDyad
    from pylinkage.simulation import Linkage
    g = FOURBAR if mech == "fourbar" else COURSE
    O = Ground(0.0, 0.0, name="O")
    C = Ground(g["xc"], g["yc"], name="C")
    # one step turns the crank by 2*pi/n: step k (from 0) reports phi_{k+1}; start one
    # step back so that the trajectory is phi_0, phi_1, ...
    crank = Crank(anchor=O, radius=g["roa"], angular_velocity=2 * math.pi / n,
                  initial_angle=-2 * math.pi / n, name="A")
    B = RRRDyad(crank.output, C, distance1=g["rab"], distance2=g["rcb"],
                x=phi0_ref["XB"], y=phi0_ref["YB"], name="B")
    parts = [O, C, crank, B]
    if mech == "course":
        G1 = Ground(0.0, g["yg"], name="G1")
        G2 = Ground(1.0, g["yg"], name="G2")
        D = FixedDyad(C, B, distance=g["rcd"], angle=math.pi, name="D")
        E = RRPDyad(D, G1, G2, distance=g["rde"], name="E")
        E.x, E.y = phi0_ref["XE"], g["yg"]
        parts += [G1, G2, D, E]
    linkage = Linkage(parts, name=mech)
    linkage.set_input_velocity(crank, omega=W1, alpha=0.0)
    names = [c.name for c in linkage.components]
    return linkage, names


def pylinkage_results(pos, vel, acc, names, mech):
    out = {}
    for p in ("B", "E") if mech == "course" else ("B",):
        j = names.index(p)
        out[f"X{p}"], out[f"Y{p}"] = pos[:, j, 0], pos[:, j, 1]
        out[f"VX{p}"], out[f"VY{p}"] = vel[:, j, 0], vel[:, j, 1]
        out[f"AX{p}"], out[f"AY{p}"] = acc[:, j, 0], acc[:, j, 1]
    return out


def mechanism_run(mech, phis, ref0, velocities=True):
    """Loop equations solved by fsolve at every position (package ``mechanism``)."""
    from mechanism import Mechanism, Vector, get_joints
    g = FOURBAR if mech == "fourbar" else COURSE
    O, A, B, C, D, E, G = get_joints("O A B C D E G")
    a = Vector((O, A), r=g["roa"])
    b = Vector((A, B), r=g["rab"])
    c = Vector((O, C), r=math.hypot(g["xc"], g["yc"]), theta=math.atan2(g["yc"], g["xc"]))
    d = Vector((C, B), r=g["rcb"])
    fi2, fi3 = ref0["FI2"], ref0["FI3"]
    if mech == "fourbar":
        vectors = (a, b, c, d)

        def loops(x, inp):
            return (a(inp) + b(x[0]) - d(x[1]) - c()).flatten()
        guess = [np.array([fi2, fi3])]
        gv = [np.array([ref0["W2"], ref0["W3"]]), np.array([ref0["E2"], ref0["E3"]])]
    else:
        e = Vector((C, D), r=g["rcd"])          # the lever: same omega and epsilon as CB
        f = Vector((D, E), r=g["rde"])
        s = Vector((G, E), theta=0.0)           # slider position along the guide
        h = Vector((O, G), r=g["yg"], theta=math.pi / 2)
        vectors = (a, b, c, d, e, f, s, h)

        def loops(x, inp):
            out = np.empty(4)
            out[:2] = a(inp) + b(x[0]) - d(x[1]) - c()
            ang = x[1] + math.pi if e.get == e.pos.get else x[1]
            out[2:] = c() + e(ang) + f(x[2]) - s(x[3]) - h()
            return out
        guess = [np.array([fi2, fi3, ref0["FIDE"], ref0["XE"]])]
        gv = [np.array([ref0["W2"], ref0["W3"], ref0["W4"], ref0["VXE"]]),
              np.array([ref0["E2"], ref0["E3"], ref0["E4"], ref0["AXE"]])]
    if velocities:
        guess += gv
    m = Mechanism(vectors=vectors, origin=O, loops=loops, pos=phis,
                  vel=np.full(phis.size, W1) if velocities else None,
                  acc=np.zeros(phis.size) if velocities else None, guess=tuple(guess))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m.iterate()
    out = {}
    for p, j in (("B", B), ("E", E)) if mech == "course" else (("B", B),):
        out[f"X{p}"], out[f"Y{p}"] = j.x_positions, j.y_positions
        if velocities:
            out[f"VX{p}"], out[f"VY{p}"] = j.x_velocities, j.y_velocities
            out[f"AX{p}"], out[f"AY{p}"] = j.x_accelerations, j.y_accelerations
    return out


# ---------------------------------------------------------------------------------------
# the mpmath reference
# ---------------------------------------------------------------------------------------

def _ref_points(phi, mech):
    g = FOURBAR if mech == "fourbar" else COURSE
    mp = mpmath
    roa, rab, rcb = (mp.mpf(g[k]) for k in ("roa", "rab", "rcb"))
    xc, yc = mp.mpf(g["xc"]), mp.mpf(g["yc"])
    xa, ya = roa * mp.cos(phi), roa * mp.sin(phi)
    dx, dy = xc - xa, yc - ya
    d = mp.hypot(dx, dy)
    fi2 = mp.atan2(dy, dx) + mp.acos((d * d + rab * rab - rcb * rcb) / (2 * d * rab))
    xb, yb = xa + rab * mp.cos(fi2), ya + rab * mp.sin(fi2)   # B left of A -> C (P = -1)
    pts = {"XB": xb, "YB": yb, "FI2": fi2, "FI3": mp.atan2(yb - yc, xb - xc)}
    if mech == "course":
        rcd, rde, yg = mp.mpf(g["rcd"]), mp.mpf(g["rde"]), mp.mpf(g["yg"])
        xd, yd = xc - rcd * (xb - xc) / rcb, yc - rcd * (yb - yc) / rcb
        xe = xd + mp.sqrt(rde * rde - (yg - yd) ** 2)             # E ahead of D (FIM = 0)
        pts.update(XE=xe, YE=yg, FIDE=mp.atan2(yg - yd, xe - xd))
    return pts


ANGLES = ("FI2", "FI3", "FIDE")


def reference(phis, mech):
    """Exact positions, velocities and accelerations at the float64 angles phis."""
    mpmath.mp.dps = 40
    w = mpmath.mpf(W1)
    rows = []
    for f in phis:
        phi0 = mpmath.mpf(float(f))
        p0 = _ref_points(phi0, mech)
        row = {}
        for q, v0 in p0.items():
            if q in ANGLES:    # unwrap around the value at phi0 before differentiating
                fn = lambda t, q=q, v0=v0: v0 + mpmath.atan2(          # noqa: E731
                    mpmath.sin(_ref_points(t, mech)[q] - v0),
                    mpmath.cos(_ref_points(t, mech)[q] - v0))
            else:
                fn = lambda t, q=q: _ref_points(t, mech)[q]             # noqa: E731
            d1, d2 = mpmath.diff(fn, phi0, 1), mpmath.diff(fn, phi0, 2)
            row[q] = float(v0)
            row["D1" + q] = float(w * d1)
            row["D2" + q] = float(w * w * d2)
        rows.append(row)
    ref = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    # in the names of the routines' outputs
    out = {"XB": ref["XB"], "YB": ref["YB"], "FI2": ref["FI2"], "FI3": ref["FI3"],
           "W2": ref["D1FI2"], "W3": ref["D1FI3"], "E2": ref["D2FI2"], "E3": ref["D2FI3"],
           "VXB": ref["D1XB"], "VYB": ref["D1YB"], "AXB": ref["D2XB"], "AYB": ref["D2YB"]}
    if mech == "course":
        out.update(XE=ref["XE"], YE=ref["YE"], FIDE=ref["FIDE"], W4=ref["D1FIDE"],
                   E4=ref["D2FIDE"], VXE=ref["D1XE"], VYE=np.zeros(len(rows)),
                   AXE=ref["D2XE"], AYE=np.zeros(len(rows)))
    return out


def sarkp_points(out, mech):
    """Cartesian points, velocities and accelerations from the routines' outputs (the
    velocities and accelerations only where that level was computed)."""
    pts = {}
    for p, x, v, alv, a, ala in (("B", "XB", "VB", "ALB", "AB", "BB"),
                                 ("E", "XE", "VE", "ALE", "AE", "BE")):
        if x not in out:
            continue
        pts["X" + p] = out[x]
        pts["Y" + p] = out["YB"] if p == "B" else np.full_like(out["XE"], COURSE["yg"])
        if v in out:
            pts["VX" + p], pts["VY" + p] = out[v] * np.cos(out[alv]), out[v] * np.sin(out[alv])
        if a in out and np.any(out[a] != 0.0):
            pts["AX" + p], pts["AY" + p] = out[a] * np.cos(out[ala]), out[a] * np.sin(out[ala])
    return pts


CLASSES = {"pos": ("X", "Y"), "vel": ("VX", "VY"), "acc": ("AX", "AY")}


def point_errors(got, ref, mech):
    """Largest relative error of the points B (and E), per class (pos, vel, acc)."""
    res = {}
    for cls, pre in CLASSES.items():
        errs = []
        for p in ("B", "E") if mech == "course" else ("B",):
            scale = max(np.max(np.abs(ref[pr + p])) for pr in pre)
            for pr in pre:
                if pr + p in got:
                    errs.append(np.max(np.abs(np.asarray(got[pr + p]) - ref[pr + p])) / scale)
        res[cls] = max(errs) if errs else math.nan
    return res


def angle_errors(out, ref, mech):
    """sarkp only: angles (rad, absolute), omegas and epsilons (relative)."""
    angs = [a for a in ANGLES if a in out]
    e_ang = max(np.max(np.abs(np.angle(np.exp(1j * (out[a] - ref[a]))))) for a in angs)
    ws = ["W2", "W3"] + (["W4"] if mech == "course" else [])
    es = ["E2", "E3"] + (["E4"] if mech == "course" else [])
    rel = lambda q: np.max(np.abs(out[q] - ref[q])) / np.max(np.abs(ref[q]))  # noqa: E731
    return e_ang, max(rel(q) for q in ws), max(rel(q) for q in es)


# ---------------------------------------------------------------------------------------

class Table:
    """The rows of the run: time per position ("pos"), per call ("call") or a ratio."""

    def __init__(self):
        self.rows = []

    def add(self, mech, path, level, t, per="pos", n=N, err=None, note=""):
        err = err or {}
        self.rows.append(dict(mech=mech, path=path, level=level, t=t, per=per, n=n,
                              ep=err.get("pos", math.nan), ev=err.get("vel", math.nan),
                              ea=err.get("acc", math.nan), note=note))
        r = self.rows[-1]
        print(f"  {mech:8s} {path:48s} {level:10s} {_fmt_time(r)}", flush=True)
        return t

    def get(self, mech, path, level):
        return next((r["t"] for r in self.rows
                     if (r["mech"], r["path"], r["level"]) == (mech, path, level)), None)


def _fmt_time(r):
    if r["per"] == "ratio":
        return f"{r['t']:.2f}x"
    if r["per"] == "pos":
        return f"{r['t'] * 1e9:.0f} ns/pos" if r["t"] < 1e-6 else f"{r['t'] * 1e6:.1f} us/pos"
    return f"{r['t'] * 1e6:.2f} us/call"


def _fmt_err(r):
    es = [f"{e:.1e}" for e in (r["ep"], r["ev"], r["ea"]) if not math.isnan(e)]
    return " / ".join(es)


def uptime():
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return "load average %.2f, %.2f, %.2f" % os.getloadavg()


def main():
    tab, notes = Table(), []
    add = tab.add
    up0 = uptime()
    print(f"start: {up0}", flush=True)
    phi = crank_angles(N)
    idx = np.arange(0, N, N // N_SAMPLE)

    try:
        cloop = CLoop()
    except (OSError, subprocess.CalledProcessError) as exc:
        cloop = None
        notes.append(f"C loop not run: {exc}")
    print("building and running the Fortran driver ...", flush=True)
    try:
        drv_times, drv_dumps, drv_cmd = run_driver(N, REPEAT + 2)
    except (OSError, subprocess.CalledProcessError) as exc:
        drv_times, drv_dumps, drv_cmd = None, None, None
        notes.append(f"Fortran driver not run: {exc}")

    print("mpmath reference, fourbar ...", flush=True)
    ref = reference(phi[idx], "fourbar")
    ref0 = {k: v[0] for k, v in ref.items()}
    mech = "fourbar"
    levels = {1: "positions", 2: "pos+vel", 3: "full"}

    # -- 1. full kinematics, 10^5 positions ---------------------------------------------
    if cloop is not None:
        for level in (3, 2, 1):
            err = point_errors(sarkp_points(cloop(phi[idx], level), mech), ref, mech)
            add(mech, "C loop (fourbar.c)", levels[level], best(lambda: cloop(phi, level)) / N,
                err=err)
    err = point_errors(sarkp_points(fourbar_dknma(phi[idx], 3, _NP), mech), ref, mech)
    add(mech, "sarkp DKNMA1, array", "full", best(lambda: fourbar_dknma(phi, 3, _NP)) / N,
        err=err)
    buf = np.empty((len(K.DKNMA1.spec.outputs), N))
    add(mech, "sarkp DKNMA1, array, out= reused", "full",
        best(lambda: fourbar_dknma(phi, 3, _NP, out=buf)) / N, err=err)
    err = point_errors(sarkp_points(fourbar_split(phi[idx], 3, _NP), mech), ref, mech)
    add(mech, "sarkp DPRM1+DSKOR1+DUSKR1, array", "full",
        best(lambda: fourbar_split(phi, 3, _NP)) / N, err=err)
    err = point_errors(sarkp_points(fourbar_dknma(phi[idx], 2, _NP), mech), ref, mech)
    add(mech, "sarkp DKNMA1 ANALOG=1, array", "pos+vel",
        best(lambda: fourbar_dknma(phi, 2, _NP)) / N, err=err)
    err = point_errors(sarkp_points(fourbar_split(phi[idx], 1, _NP), mech), ref, mech)
    add(mech, "sarkp DPRM1, array", "positions", best(lambda: fourbar_split(phi, 1, _NP)) / N,
        err=err)
    add(mech, "raw driver dknma1_n (no layer)", "full", best(lambda: fourbar_raw_dknma(phi)) / N)
    add(mech, "raw drivers dprm1_n+dskor1_n+duskr1_n", "full",
        best(lambda: fourbar_raw_split(phi)) / N)
    if drv_times is not None:
        for (name, level), (t, ier) in sorted(drv_times.items()):
            if name.startswith(mech):
                add(mech, f"Fortran driver loop, {name.split('_')[1]}", levels[level], t)
    if drv_dumps is not None:
        for m_, split_ in (("fourbar", fourbar_split), ("course", course_split)):
            full_out = split_(phi, 3, _NP)
            dump = drv_dumps[m_]
            diffs = {k: np.max(np.abs(dump[k] - full_out[k])) for k in dump}
            worst = max(diffs, key=diffs.get)
            notes.append(f"{m_}: the Fortran driver loop's split results against the array "
                         f"path's: largest difference {diffs[worst]:.1e} (in {worst}, largest "
                         f"magnitude {np.max(np.abs(full_out[worst])):.2g})")
    e_ang, e_w, e_e = angle_errors(fourbar_dknma(phi[idx], 3, _NP), ref, mech)
    notes.append(f"fourbar: sarkp DKNMA1, angles FI2, FI3 within {e_ang:.1e} rad, W2, W3 "
                 f"{e_w:.1e} and E2, E3 {e_e:.1e} relative")
    if cloop is not None:
        e_ang, e_w, e_e = angle_errors(cloop(phi[idx], 3), ref, mech)
        notes.append(f"fourbar: C loop, angles FI2, FI3 within {e_ang:.1e} rad, W2, W3 "
                     f"{e_w:.1e} and E2, E3 {e_e:.1e} relative")

    # -- 2. small sweeps, fixed cost, scalar calls --------------------------------------
    p360 = crank_angles(360)
    if cloop is not None:
        add(mech, "C loop, 360 positions", "full", best(lambda: cloop(p360)), "call", 360)
    add(mech, "sarkp DKNMA1, 360 positions (one call)", "full",
        best(lambda: fourbar_dknma(p360, 3, _NP)), "call", 360)
    buf360 = np.empty((len(K.DKNMA1.spec.outputs), 360))
    add(mech, "sarkp DKNMA1, 360 positions (one call, out= reused)", "full",
        best(lambda: fourbar_dknma(p360, 3, _NP, out=buf360)), "call", 360)
    add(mech, "sarkp split, 360 positions (three calls)", "full",
        best(lambda: fourbar_split(p360, 3, _NP)), "call", 360)
    calls = one_position_calls()
    add(mech, "sarkp DKNMA1, arrays of 1 (fixed cost)", "full",
        best(calls["sarkp DKNMA1, arrays of 1"]), "call", 1)
    add(mech, "sarkp DPRM1, arrays of 1 (fixed cost)", "positions",
        best(calls["sarkp DPRM1, arrays of 1"]), "call", 1)
    add(mech, "raw driver dknma1_n, n = 1", "full",
        best(lambda: fourbar_raw_dknma(np.array([0.3]))), "call", 1)
    add(mech, "sarkp DKNMA1, scalar call", "full", best(calls["sarkp DKNMA1, scalar call"]),
        "call", 1)
    add(mech, "sarkp DPRM1, scalar call", "positions", best(calls["sarkp DPRM1, scalar call"]),
        "call", 1)
    add(mech, "raw driver dknma1_1, scalar call", "full",
        best(calls["raw driver dknma1_1, scalar call"]), "call", 1)
    add("-", "sarkp DVKT, scalar call", "-",
        best(lambda: sarkp.DVKT(0.1, 0.2, 3.0, 4.0)), "call", 1)
    ps = phi[:N_SCALAR]
    add(mech, "sarkp scalar loop, DPRM1+DSKOR1+DUSKR1", "full",
        best(lambda: scalar_loop(fourbar_split, ps, 3), repeat=3) / N_SCALAR, n=N_SCALAR)
    add(mech, "sarkp scalar loop, DKNMA1", "full",
        best(lambda: scalar_loop(fourbar_dknma, ps, 3), repeat=3) / N_SCALAR, n=N_SCALAR)

    # -- 3. two threads over two chunks of a 10^6 sweep ---------------------------------
    big = crank_angles(N_BIG)
    halves = np.array_split(big, 2)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        wall = time.perf_counter
        t1 = best(lambda: fourbar_dknma(big, 3, _NP), repeat=3, timer=wall)
        two = lambda: list(pool.map(lambda h: fourbar_dknma(h, 3, _NP), halves))  # noqa: E731
        t2 = best(two, repeat=3, timer=wall)
        c0, w0 = time.process_time(), wall()
        two()
        cores = (time.process_time() - c0) / (wall() - w0)
        if cloop is not None:      # the control: ctypes releases the GIL for the C loop
            c1 = best(lambda: cloop(big), repeat=3, timer=wall)
            c2 = best(lambda: list(pool.map(cloop, halves)), repeat=3, timer=wall)
    notes.append(f"fourbar: 2 threads x 2 chunks of {N_BIG} positions kept {cores:.2f} cores "
                 f"busy (CPU time / wall time of one run); load average "
                 f"{os.getloadavg()[0]:.2f} then")
    add(mech, f"sarkp DKNMA1, 10^{round(math.log10(N_BIG))} positions, one call (wall)",
        "full", t1 / N_BIG, n=N_BIG)
    add(mech, "the same, 2 threads x 2 chunks (wall)", "full", t2 / N_BIG, n=N_BIG)
    add(mech, "thread speedup of sarkp (one call / 2 threads)", "full", t1 / t2, "ratio",
        N_BIG)
    if cloop is not None:
        add(mech, "thread speedup of the C loop, the control", "full", c1 / c2, "ratio", N_BIG)

    # -- 4. peers, four-bar -------------------------------------------------------------
    peers(tab, notes, mech, phi, idx, ref, ref0)
    try:
        kp = KinepyFourbar()
        err = point_errors(kp.positions(phi[idx]), ref, mech)
        add(mech, "kinepy solve_kinematics (NumPy)", "positions",
            best(lambda: kp.positions(phi), repeat=3) / N, err=err)
        # central differences need neighbours: the sample points and their neighbours
        d = kp.derivatives(phi)
        sub = {k: v[1:] for k, v in ref.items()}
        err = point_errors({k: v[idx[1:]] for k, v in d.items()}, sub, mech)
        add(mech, "kinepy + its central differences", "full",
            best(lambda: kp.derivatives(phi), repeat=3) / N, err=err)
    except Exception as exc:                                          # noqa: BLE001
        notes.append(f"kinepy failed: {type(exc).__name__}: {exc}")

    # -- 5. the course mechanism ---------------------------------------------------------
    mech = "course"
    print("mpmath reference, course ...", flush=True)
    cref = reference(phi[idx], mech)
    cref0 = {k: v[0] for k, v in cref.items()}
    for name, fn in (("DKNMA1+DKNMA2", course_dknma), ("split (DPRM/DSKOR/DUSKR 1 and 2)",
                                                      course_split)):
        err = point_errors(sarkp_points(fn(phi[idx], 3, _NP), mech), cref, mech)
        add(mech, f"sarkp {name}, array", "full", best(lambda: fn(phi, 3, _NP)) / N, err=err)
    err = point_errors(sarkp_points(course_split(phi[idx], 1, _NP), mech), cref, mech)
    add(mech, "sarkp DPRM1+DPRM2, array", "positions",
        best(lambda: course_split(phi, 1, _NP)) / N, err=err)
    err = point_errors(sarkp_points(course_dknma(phi[idx], 2, _NP), mech), cref, mech)
    add(mech, "sarkp DKNMA1+DKNMA2 ANALOG=1, array", "pos+vel",
        best(lambda: course_dknma(phi, 2, _NP)) / N, err=err)
    p360c = crank_angles(360)
    add(mech, "sarkp DKNMA1+DKNMA2, 360 positions", "full",
        best(lambda: course_dknma(p360c, 3, _NP)), "call", 360)
    if drv_times is not None:
        for (name, level), (t, ier) in sorted(drv_times.items()):
            if name.startswith(mech) and level == 3:
                add(mech, f"Fortran driver loop, {name.split('_')[1]}", levels[level], t)
    e_ang, e_w, e_e = angle_errors(course_dknma(phi[idx], 3, _NP), cref, mech)
    notes.append(f"course: sarkp DKNMA1+2, angles within {e_ang:.1e} rad, W2-W4 {e_w:.1e} "
                 f"and E2-E4 {e_e:.1e} relative")
    peers(tab, notes, mech, phi, idx, cref, cref0)

    print("head to head ...", flush=True)
    tab.h2h = head_to_head(cloop, ref0)
    up1 = uptime()
    report(tab, notes, up0, up1, cloop, drv_cmd)
    try:
        sizes = size_sweep(cloop, ref0)
        plot(sizes)
    except ImportError as exc:
        notes.append(f"no plot: {exc}")


def peers(tab, notes, mech, phi, idx, ref, ref0):
    add = tab.add
    try:
        linkage, names = pylinkage_linkage(mech, N, ref0)
        linkage.step_fast_with_kinematics(iterations=N)           # numba compile
        linkage, names = pylinkage_linkage(mech, N, ref0)
        pos, vel, acc = linkage.step_fast_with_kinematics(iterations=N)
        err = point_errors(pylinkage_results(pos[idx], vel[idx], acc[idx], names, mech),
                           ref, mech)
        add(mech, "pylinkage step_fast_with_kinematics (numba)", "full",
            best(lambda: linkage.step_fast_with_kinematics(iterations=N)) / N, err=err)
        linkage.step_fast(iterations=N)
        add(mech, "pylinkage step_fast (numba)", "positions",
            best(lambda: linkage.step_fast(iterations=N)) / N, err={"pos": err["pos"]})
        lk360, _ = pylinkage_linkage(mech, 360, ref0)
        add(mech, "pylinkage numba, 360 positions", "full",
            best(lambda: lk360.step_fast_with_kinematics(iterations=360)), "call", 360)
        ja = names.index("A")
        drift = np.max(np.abs(np.angle(np.exp(1j * (
            np.arctan2(pos[:, ja, 1], pos[:, ja, 0]) - phi)))))
        notes.append(f"{mech}: pylinkage's crank angle drifts from 2*pi*k/N by up to "
                     f"{drift:.1e} rad over {N} steps (it adds 2*pi/N to atan2 of the "
                     f"previous crank point)")

        def run_slow():
            lk, _ = pylinkage_linkage(mech, N, ref0)
            for _ in zip(range(N_PEER), lk.step_with_derivatives(iterations=N_PEER)):
                pass
        add(mech, "pylinkage step_with_derivatives (Python)", "full",
            best(run_slow, repeat=3) / N_PEER, n=N_PEER)
    except Exception as exc:                                          # noqa: BLE001
        notes.append(f"{mech}: pylinkage failed: {type(exc).__name__}: {exc}")
    try:
        err = point_errors(mechanism_run(mech, phi[idx], ref0), ref, mech)
        pm = phi[:N_PEER]
        add(mech, "mechanism (fsolve loop equations)", "full",
            best(lambda: mechanism_run(mech, pm, ref0), repeat=2) / N_PEER, n=N_PEER, err=err)
    except Exception as exc:                                          # noqa: BLE001
        notes.append(f"{mech}: mechanism failed: {type(exc).__name__}: {exc}")


TARGET_ERR = 2e-15      # "about 1e-15" (issue 9): today's error, within a rounding or two


HEAD_ROUNDS = 3 if _Q else 15


def head_to_head(cloop, ref0, rounds=HEAD_ROUNDS):
    """The paths the targets compare, timed in turn: every round times each path once
    (as ``best`` does, at least 0.05 s of calls), and each path keeps its best round.  A
    slow spell of the shared host then falls on all of them alike, which timing one path
    after the other (the main table) does not ensure.  Returns {name: seconds per call}."""
    phi, p360 = crank_angles(N), crank_angles(360)
    nres = len(K.DKNMA1.spec.outputs)
    buf, buf360 = np.empty((nres, N)), np.empty((nres, 360))
    calls = one_position_calls()
    paths = {
        "sarkp DKNMA1, array": lambda: fourbar_dknma(phi, 3, _NP),
        "sarkp DKNMA1, array, out=": lambda: fourbar_dknma(phi, 3, _NP, out=buf),
        "sarkp DPRM1, array": lambda: fourbar_split(phi, 1, _NP),
        "sarkp DKNMA1, 360 positions": lambda: fourbar_dknma(p360, 3, _NP),
        "sarkp DKNMA1, 360 positions, out=": lambda: fourbar_dknma(p360, 3, _NP, out=buf360),
        "sarkp DKNMA1, arrays of 1": calls["sarkp DKNMA1, arrays of 1"],
        "sarkp DKNMA1, scalar call": calls["sarkp DKNMA1, scalar call"],
        "sarkp DPRM1, scalar call": calls["sarkp DPRM1, scalar call"],
        "sarkp DVKT, scalar call": lambda: sarkp.DVKT(0.1, 0.2, 3.0, 4.0),
    }
    if cloop is not None:
        paths["C loop"] = lambda: cloop(phi)
        paths["C loop, 360 positions"] = lambda: cloop(p360)
    try:
        lk, _ = pylinkage_linkage("fourbar", N, ref0)
        lk360, _ = pylinkage_linkage("fourbar", 360, ref0)
        lk.step_fast_with_kinematics(iterations=N)                   # numba compile
        paths["pylinkage numba"] = lambda: lk.step_fast_with_kinematics(iterations=N)
        paths["pylinkage numba, 360 positions"] = \
            lambda: lk360.step_fast_with_kinematics(iterations=360)
    except ImportError:
        pass
    timers, numbers = {}, {}
    for name, fn in paths.items():
        timers[name], numbers[name] = calibrated(fn)
    found = {name: math.inf for name in paths}
    for _ in range(rounds):
        for name, t in timers.items():
            found[name] = min(found[name], t.timeit(numbers[name]) / numbers[name])
    return found


def targets(tab):
    """(target, value, met) for the targets of issue 9, from the head-to-head timings
    (``head_to_head``) where they were taken, else from the main table."""
    t = lambda path, level="full", mech="fourbar": tab.get(mech, path, level)   # noqa: E731
    h = getattr(tab, "h2h", None)
    if h:
        return targets_head_to_head(tab, h)
    res = []
    c = t("C loop (fourbar.c)")
    paths = {"DKNMA1": "sarkp DKNMA1, array", "DKNMA1, out=": "sarkp DKNMA1, array, out= reused",
             "split": "sarkp DPRM1+DSKOR1+DUSKR1, array"}
    name = min(paths, key=lambda k: t(paths[k]))
    fast, dk = t(paths[name]), t(paths["DKNMA1"])
    errs = next(max(r["ep"], r["ev"], r["ea"]) for r in tab.rows if r["path"] == paths[name])
    if c:
        res.append(("full four-bar, best sarkp array path / C loop <= 3",
                    f"{fast / c:.2f} ({name})", fast / c <= 3))
    pl = t("pylinkage step_fast_with_kinematics (numba)")
    if pl:
        res.append(("pylinkage numba / best sarkp array path >= 1.5",
                    f"{pl / fast:.2f}", pl / fast >= 1.5))
    res.append((f"error of that path <= ~1e-15 (taken as {TARGET_ERR:.0e})", f"{errs:.1e}",
                errs <= TARGET_ERR))
    s1 = t("sarkp DKNMA1, 360 positions (one call)")
    so = t("sarkp DKNMA1, 360 positions (one call, out= reused)")
    s3 = t("sarkp split, 360 positions (three calls)")
    res.append(("360-position sweep <= 100 us (one call / with out= / three calls)",
                f"{s1 * 1e6:.0f} / {so * 1e6:.0f} / {s3 * 1e6:.0f} us",
                min(s1, so, s3) <= 100e-6))
    fc = t("sarkp DKNMA1, arrays of 1 (fixed cost)")
    res.append(("fixed cost per call (DKNMA1 on arrays of 1) <= 20 us", f"{fc * 1e6:.1f} us",
                fc <= 20e-6))
    pos = t("sarkp DPRM1, array", "positions")
    pv = t("sarkp DKNMA1 ANALOG=1, array", "pos+vel")
    res.append(("positions only (DPRM1) <= 40% of full (DKNMA1)",
                f"{pos / dk:.0%} (pos+vel {pv / dk:.0%})", pos / dk <= 0.40))
    dv = t("sarkp DVKT, scalar call", "-", "-")
    res.append(("scalar DVKT <= 1 us", f"{dv * 1e6:.2f} us", dv <= 1e-6))
    kd = t("sarkp DKNMA1, scalar call")
    kp = t("sarkp DPRM1, scalar call", "positions")
    res.append(("kinematics scalar call <= 2 us (DKNMA1 / DPRM1)",
                f"{kd * 1e6:.2f} / {kp * 1e6:.2f} us", max(kd, kp) <= 2e-6))
    return res


def targets_head_to_head(tab, h):
    """The targets of issue 9 from the interleaved timings ``h`` (seconds per call); the
    error of the sarkp path is the main table's (the same computation)."""
    res = []
    full = min(h["sarkp DKNMA1, array"], h["sarkp DKNMA1, array, out="])
    name = "DKNMA1, out=" if h["sarkp DKNMA1, array, out="] <= h["sarkp DKNMA1, array"] \
        else "DKNMA1"
    if "C loop" in h:
        res.append(("full four-bar, best sarkp array path / C loop <= 3",
                    f"{full / h['C loop']:.2f} ({name})", full / h["C loop"] <= 3))
    if "pylinkage numba" in h:
        r = h["pylinkage numba"] / full
        res.append(("pylinkage numba / best sarkp array path >= 1.5", f"{r:.2f}", r >= 1.5))
    err = next(max(r["ep"], r["ev"], r["ea"]) for r in tab.rows
               if r["path"] == "sarkp DKNMA1, array")
    res.append((f"error of that path <= ~1e-15 (taken as {TARGET_ERR:.0e})", f"{err:.1e}",
                err <= TARGET_ERR))
    s1, so = h["sarkp DKNMA1, 360 positions"], h["sarkp DKNMA1, 360 positions, out="]
    res.append(("360-position sweep <= 100 us (one call / with out=)",
                f"{s1 * 1e6:.0f} / {so * 1e6:.0f} us", min(s1, so) <= 100e-6))
    fc = h["sarkp DKNMA1, arrays of 1"]
    res.append(("fixed cost per call (DKNMA1 on arrays of 1) <= 20 us", f"{fc * 1e6:.1f} us",
                fc <= 20e-6))
    pos = h["sarkp DPRM1, array"] / h["sarkp DKNMA1, array"]
    res.append(("positions only (DPRM1) <= 40% of full (DKNMA1)", f"{pos:.0%}", pos <= 0.40))
    dv = h["sarkp DVKT, scalar call"]
    res.append(("scalar DVKT <= 1 us", f"{dv * 1e6:.2f} us", dv <= 1e-6))
    kd, kp = h["sarkp DKNMA1, scalar call"], h["sarkp DPRM1, scalar call"]
    res.append(("kinematics scalar call <= 2 us (DKNMA1 / DPRM1)",
                f"{kd * 1e6:.2f} / {kp * 1e6:.2f} us", max(kd, kp) <= 2e-6))
    return res


def report(tab, notes, up0, up1, cloop, drv_cmd):
    OUT.mkdir(parents=True, exist_ok=True)
    with open(OUT / "kinematics.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["mechanism", "path", "level", "n", "seconds", "per", "err_pos", "err_vel",
                    "err_acc"])
        for r in tab.rows:
            w.writerow([r["mech"], r["path"], r["level"], r["n"], r["t"], r["per"], r["ep"],
                        r["ev"], r["ea"]])
    print(f"\n{up0}  (start)\n{up1}  (end)")
    print(f"N = {N} positions unless stated; error sample {N_SAMPLE}; CPU time of the "
          f"process (time.process_time), best of {REPEAT}")
    if cloop is not None:
        print(f"C loop: {cloop.cmd}")
    if drv_cmd:
        print(f"Fortran driver: {drv_cmd}")
    full = {m: tab.get(m, p, "full") for m, p in
            (("fourbar", "sarkp DKNMA1, array"), ("course", "sarkp DKNMA1+DKNMA2, array"))}
    print("\n| mechanism | path | level | n | time | vs sarkp DKNMA | error pos / vel / acc |")
    print("|---|---|---|---|---|---|---|")
    for r in tab.rows:
        rel = ""
        if r["per"] == "pos" and r["mech"] in full:
            rel = f"{r['t'] / full[r['mech']]:.2f}"
        print(f"| {r['mech']} | {r['path']} | {r['level']} | {r['n']:g} | {_fmt_time(r)} | "
              f"{rel} | {_fmt_err(r)} |")
    h = getattr(tab, "h2h", None)
    if h:
        print(f"\nHead to head: the targets' paths timed in turn, {HEAD_ROUNDS} rounds, the "
              f"best round of each (N = {N} unless stated):\n")
        print("| path | time per call | per position |")
        print("|---|---|---|")
        for name, sec in h.items():
            n = 360 if "360" in name else (1 if "scalar" in name or "arrays of 1" in name
                                           else N)
            per = f"{sec / n * 1e9:.0f} ns" if n > 1 else ""
            print(f"| {name} | {sec * 1e6:.2f} us | {per} |")
    print("\n| target (issue 9) | this run | met? |")
    print("|---|---|---|")
    for name, value, met in targets(tab):
        print(f"| {name} | {value} | {'**met**' if met else '**not met**'} |")
    print()
    for n_ in notes:
        print("*", n_)


SIZES = [10, 30, 100, 300, 1000, 3000, 10**4, 3 * 10**4, 10**5, 3 * 10**5, 10**6]


def size_sweep(cloop, ref0):
    """Time per position against the number of positions, for sarkp and the peers."""
    import matplotlib                                                 # noqa: F401
    print("\ntime per position against n ...", flush=True)
    sizes = SIZES if not _Q else SIZES[:6]
    curves = {}

    def curve(label, fn, nmax=10**6, repeat=3):
        pts = []
        for n in sizes:
            if n > nmax:
                break
            p = crank_angles(n)
            run = fn(n, p)
            pts.append((n, best(run, repeat=repeat, min_time=0.02) / n))
        curves[label] = pts
        print(f"  {label}: " + ", ".join(f"{n:g}: {t * 1e9:.0f}" for n, t in pts) + " ns/pos",
              flush=True)

    if cloop is not None:
        curve("C loop (fourbar.c), full", lambda n, p: lambda: cloop(p))
    curve("sarkp DKNMA1, full", lambda n, p: lambda: fourbar_dknma(p, 3, _NP))
    curve("sarkp DPRM1+DSKOR1+DUSKR1, full", lambda n, p: lambda: fourbar_split(p, 3, _NP))
    curve("sarkp DPRM1, positions", lambda n, p: lambda: fourbar_split(p, 1, _NP))
    try:
        def pl(n, p):
            lk, _ = pylinkage_linkage("fourbar", n, ref0)
            lk.step_fast_with_kinematics(iterations=n)
            return lambda: lk.step_fast_with_kinematics(iterations=n)
        curve("pylinkage numba, full", pl)

        def pls(n, p):
            def run():
                lk, _ = pylinkage_linkage("fourbar", n, ref0)
                for _ in zip(range(n), lk.step_with_derivatives(iterations=n)):
                    pass
            return run
        curve("pylinkage Python API, full", pls, nmax=10**4, repeat=2)
    except ImportError:
        pass
    try:
        kp = KinepyFourbar()
        curve("kinepy, positions", lambda n, p: lambda: kp.positions(p), nmax=10**5, repeat=2)
    except ImportError:
        pass
    try:
        import mechanism                                              # noqa: F401
        curve("mechanism (fsolve), full", lambda n, p: lambda: mechanism_run("fourbar", p, ref0),
              nmax=1000, repeat=1)
    except ImportError:
        pass
    with open(OUT / "kinematics_sizes.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["path", "n", "seconds_per_position"])
        for label, pts in curves.items():
            w.writerows([label, n, t] for n, t in pts)
    return curves


def plot(curves):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(11, 5.5))
    for label, pts in curves.items():
        n, t = zip(*pts)
        style = "-o" if label.startswith("sarkp") else ("-s" if label.startswith("C") else "--^")
        ax.plot(n, np.array(t) * 1e9, style, label=label, ms=4)
    c = curves.get("C loop (fourbar.c), full")
    if c:
        n, t = zip(*c)
        ax.plot(n, 3e9 * np.array(t), ":", color="C0", label="target: 3x the C loop")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("positions per call (n)")
    ax.set_ylabel("time per position (ns), CPU time, best of repeats")
    ax.set_title(f"four-bar kinematics, time per position against n "
                 f"(load {os.getloadavg()[0]:.1f} on 2 cores)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    OUT.mkdir(exist_ok=True)
    fig.savefig(OUT / "kinematics.png", dpi=110)
    print(f"plot: {OUT / 'kinematics.png'}")


if __name__ == "__main__":
    sys.exit(main())
