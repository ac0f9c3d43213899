"""Chapter 4: full kinematics over 10^5 crank positions, run time against error.

Two mechanisms, both driven by a crank at constant omega1 (corrected mode, exact pi):

* ``fourbar``: a crank-rocker four-bar, crank OA + one RRR group A-B-C
  (DPRM1/DSKOR1/DUSKR1, or DKNMA1);
* ``course``: the course-project mechanism of chapter 10 (Fig. 91, the conveyor feeder,
  with the fitted link lengths of docs/notes): the same crank + RRR group, the lever point
  D = C + RCD*e(FICB + pi), then the RRP group D-E with the slider E on a horizontal
  guide (DPRM2/DSKOR2/DUSKR2, or DKNMA2).

Paths timed, per crank position:

1. the sarkp array path: one call per routine over all positions (``split`` =
   DPRM/DSKOR/DUSKR, ``dknma`` = DKNMA), and the raw f2py sweeps for the four-bar;
2. a Python loop of scalar sarkp calls (on ``N_SCALAR`` positions);
3. the same Fortran routines driven by a pure-Fortran loop (``fortran_driver.f90``,
   compiled here with gfortran -O3 -llapack in a temporary directory);
4. the peers, installed only in the benchmark's own venv (never project dependencies):
   pylinkage (closed-form dyads; its numba kernel ``step_fast_with_kinematics`` and its
   Python-level ``step_with_derivatives``) and mechanism (loop equations with fsolve);
5. positions only and positions + velocities (DKNMA's ANALOG = 1) against the full cost.

Error: against an mpmath reference at 40 digits on a sample of ``N_SAMPLE`` positions:
closed-form positions (circle-circle and circle-line intersections), velocities and
accelerations by ``mpmath.diff`` of those positions (v = omega1*dX/dphi,
a = omega1**2*d2X/dphi2).  Each error is the largest |computed - exact| over the sample,
divided by the largest |exact| of that quantity over the sample, maximised over the
quantities of a class: points B (and E) for every method; the angles, omegas and epsilons
for sarkp as well.

Run: ``python benchmarks/bench_kinematics.py`` (from outside the source tree, with sarkp,
mpmath, pylinkage[numba] and mechanism installed; gfortran and LAPACK for the driver).
Prints a table and writes ``benchmarks/results/kinematics.csv``.
"""

from __future__ import annotations

import csv
import math
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import timeit
import warnings

import mpmath
import numpy as np

import sarkp
from sarkp import _sarkp
from sarkp import kinematics as K

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


def best(fn, number=1, repeat=REPEAT):
    return min(timeit.repeat(fn, number=number, repeat=repeat)) / number


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


def fourbar_dknma(phi, level, M, g=FOURBAR):
    """Crank + RRR group with DKNMA1 (P = +1 is DPRM1's P = -1; ANALOG = 1: no accel.)."""
    r = K.DKNMA1(g["roa"] * M.cos(phi), g["roa"] * M.sin(phi), g["xc"], g["yc"], g["rab"],
                 g["rcb"], W1 * g["roa"], phi + PID2, 0.0, 0.0, W1**2 * g["roa"], phi + PI,
                 0.0, 0.0, 1, 1.0 if level < 3 else 0.0)
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


def fourbar_raw_sweeps(phi, g=FOURBAR):
    """The full four-bar through the bare f2py sweeps (no checks, no named tuples)."""
    s = _sarkp.sweeps_kinematics
    n = phi.size
    full = lambda x: np.full(n, x)                                   # noqa: E731
    rab, rcb, zero = full(g["rab"]), full(g["rcb"]), np.zeros(n)
    fi2, fi3, xb, yb, _ = s.dprm1_sweep(g["roa"] * np.cos(phi), g["roa"] * np.sin(phi),
                                        full(g["xc"]), full(g["yc"]), rab, rcb, full(-1.0))
    v = s.dskor1_sweep(rab, fi2, rcb, fi3, full(W1 * g["roa"]), phi + PID2, zero, zero)
    a = s.duskr1_sweep(full(W1**2 * g["roa"]), phi + PI, zero, zero, rab, fi2, rcb, fi3,
                       v[6], v[7])
    return xb, yb, v, a


def fourbar_raw_scalar(phis, g=FOURBAR):
    """The full four-bar through the bare f2py scalar routines, in a Python loop."""
    k = _sarkp.kinematics
    roa, xc, yc, rab, rcb = g["roa"], g["xc"], g["yc"], g["rab"], g["rcb"]
    for f in phis:
        f = float(f)
        fi2, fi3, xb, yb, _ = k.dprm1(roa * math.cos(f), roa * math.sin(f), xc, yc, rab, rcb,
                                      -1.0, 1.0)
        v = k.dskor1(rab, fi2, rcb, fi3, W1 * roa, f + PID2, 0.0, 0.0, 1.0)
        k.duskr1(W1**2 * roa, f + PI, 0.0, 0.0, rab, fi2, rcb, fi3, v[6], v[7], 1.0)


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

def main():
    rows = []          # (mechanism, path, level, seconds per position, pos err, vel err, acc err)
    notes = []
    load0 = os.getloadavg()
    phi = crank_angles(N)
    idx = np.arange(0, N, N // N_SAMPLE)
    levels = {1: "positions", 2: "pos+vel", 3: "full"}

    print("building and running the Fortran driver ...", flush=True)
    try:
        drv_times, drv_dumps, drv_cmd = run_driver(N, REPEAT + 2)
    except (OSError, subprocess.CalledProcessError) as exc:
        drv_times, drv_dumps, drv_cmd = None, None, None
        notes.append(f"Fortran driver not run: {exc}")

    for mech in ("fourbar", "course"):
        split = fourbar_split if mech == "fourbar" else course_split
        dknma = fourbar_dknma if mech == "fourbar" else course_dknma
        print(f"mpmath reference, {mech} ...", flush=True)
        ref = reference(phi[idx], mech)
        ref0 = {k: v[0] for k, v in ref.items()}

        # 1. array path
        full_out = split(phi, 3, _NP)
        for name, fn, lv in (("split", split, (1, 2, 3)), ("dknma", dknma, (2, 3))):
            for level in lv:
                t = best(lambda: fn(phi, level, _NP)) / N
                out = fn(phi[idx], level, _NP)
                err = point_errors(sarkp_points(out, mech), ref, mech)
                rows.append((mech, f"sarkp array, {name}", levels[level], t,
                             err["pos"], err["vel"] if level >= 2 else math.nan,
                             err["acc"] if level >= 3 else math.nan))
        if mech == "fourbar":
            t = best(lambda: fourbar_raw_sweeps(phi)) / N
            rows.append((mech, "raw f2py sweeps, split", "full", t, math.nan, math.nan,
                         math.nan))
        e_ang, e_w, e_e = angle_errors(split(phi[idx], 3, _NP), ref, mech)
        notes.append(f"{mech}: sarkp split, angles FI* {e_ang:.1e} rad, omegas W* {e_w:.1e} "
                     f"relative, epsilons E* {e_e:.1e} relative")
        e_ang, e_w, e_e = angle_errors(dknma(phi[idx], 3, _NP), ref, mech)
        notes.append(f"{mech}: sarkp dknma, angles FI* {e_ang:.1e} rad, omegas W* {e_w:.1e} "
                     f"relative, epsilons E* {e_e:.1e} relative")

        # 2. scalar loop
        ps = phi[:N_SCALAR]
        for name, fn in (("split", split), ("dknma", dknma)):
            t = best(lambda: scalar_loop(fn, ps, 3), repeat=3) / N_SCALAR
            rows.append((mech, f"sarkp scalar loop, {name}", "full", t, math.nan, math.nan,
                         math.nan))
        t = best(lambda: scalar_loop(split, ps, 1), repeat=3) / N_SCALAR
        rows.append((mech, "sarkp scalar loop, split", "positions", t, math.nan, math.nan,
                     math.nan))
        if mech == "fourbar":
            t = best(lambda: fourbar_raw_scalar(ps), repeat=3) / N_SCALAR
            rows.append((mech, "raw f2py scalar loop, split", "full", t, math.nan,
                         math.nan, math.nan))

        # 3. pure-Fortran driver
        if drv_times is not None:
            for (name, level), (t, ier) in sorted(drv_times.items()):
                if name.startswith(mech):
                    rows.append((mech, f"Fortran driver, {name.split('_')[1]}",
                                 levels[level], t, math.nan, math.nan, math.nan))
            dump = drv_dumps[mech]
            diffs = {k: np.max(np.abs(dump[k] - full_out[k])) for k in dump}
            worst = max(diffs, key=diffs.get)
            notes.append(f"{mech}: Fortran driver's full results vs the array path's: "
                         f"largest difference {diffs[worst]:.1e} (in {worst}, whose largest "
                         f"magnitude is {np.max(np.abs(full_out[worst])):.2g})")

        # 4. peers: pylinkage
        try:
            linkage, names = pylinkage_linkage(mech, N, ref0)
            linkage.step_fast_with_kinematics(iterations=N)           # numba compile
            linkage, names = pylinkage_linkage(mech, N, ref0)
            pos, vel, acc = linkage.step_fast_with_kinematics(iterations=N)
            got = pylinkage_results(pos[idx], vel[idx], acc[idx], names, mech)
            err = point_errors(got, ref, mech)

            def run_fast():
                lk, _ = pylinkage_linkage(mech, N, ref0)
                lk.step_fast_with_kinematics(iterations=N)
            t = best(run_fast) / N
            rows.append((mech, "pylinkage step_fast_with_kinematics (numba)", "full", t,
                         err["pos"], err["vel"], err["acc"]))

            def run_fast_pos():
                lk, _ = pylinkage_linkage(mech, N, ref0)
                lk.step_fast(iterations=N)
            run_fast_pos()
            rows.append((mech, "pylinkage step_fast (numba)", "positions",
                         best(run_fast_pos) / N, err["pos"], math.nan, math.nan))
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
            t = best(run_slow, repeat=3) / N_PEER
            rows.append((mech, "pylinkage step_with_derivatives (Python)", "full", t,
                         math.nan, math.nan, math.nan))
        except Exception as exc:                                      # noqa: BLE001
            notes.append(f"{mech}: pylinkage failed: {type(exc).__name__}: {exc}")

        # 4. peers: mechanism
        try:
            got = mechanism_run(mech, phi[idx], ref0)
            err = point_errors(got, ref, mech)
            pm = phi[:N_PEER]
            t = best(lambda: mechanism_run(mech, pm, ref0), repeat=3) / N_PEER
            rows.append((mech, "mechanism (fsolve loop equations)", "full", t,
                         err["pos"], err["vel"], err["acc"]))
            t = best(lambda: mechanism_run(mech, pm, ref0, velocities=False),
                     repeat=3) / N_PEER
            rows.append((mech, "mechanism (fsolve loop equations)", "positions", t,
                         err["pos"], math.nan, math.nan))
        except Exception as exc:                                      # noqa: BLE001
            notes.append(f"{mech}: mechanism failed: {type(exc).__name__}: {exc}")

    load1 = os.getloadavg()
    OUT.mkdir(exist_ok=True)
    with open(OUT / "kinematics.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["mechanism", "path", "level", "seconds_per_position", "err_pos",
                    "err_vel", "err_acc"])
        w.writerows(rows)
    print(f"\nN = {N} positions (scalar loop {N_SCALAR}, slow peers {N_PEER}); error sample "
          f"{N_SAMPLE}; load average {load0[0]:.1f} at start, {load1[0]:.1f} at end")
    if drv_cmd:
        print(f"driver: {drv_cmd}")
    hdr = f"{'mech':8s} {'path':45s} {'level':10s} {'us/pos':>9s} {'pos':>8s} {'vel':>8s} {'acc':>8s}"
    print(hdr)
    fmt = lambda e: "" if math.isnan(e) else f"{e:.1e}"                 # noqa: E731
    for mech, path, level, t, ep, ev, ea in rows:
        print(f"{mech:8s} {path:45s} {level:10s} {t * 1e6:9.3f} {fmt(ep):>8s} {fmt(ev):>8s} "
              f"{fmt(ea):>8s}")
    for n_ in notes:
        print(n_)
    summary(rows)
    plot(rows)


def plot(rows):
    """Run time against acceleration error (full kinematics), if matplotlib is there."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, mech in zip(axes, ("fourbar", "course")):
        same = next(r[6] for r in rows if r[:3] == (mech, "sarkp array, split", "full"))
        for m, path, level, t, ep, ev, ea in rows:
            if m != mech or level != "full":
                continue
            # the scalar loops, raw calls and the driver run the same Fortran code as the
            # array path: hollow, at its error; peers without a measured error: left out
            measured = not math.isnan(ea)
            if measured:
                ax.scatter(t * 1e6, ea, color="C0" if path.startswith("sarkp") else "C3")
                ax.annotate(path, (t * 1e6, ea), fontsize=7)
            elif path.startswith(("sarkp", "raw", "Fortran")):
                ax.scatter(t * 1e6, same, facecolors="none", edgecolors="C0")
                ax.annotate(path.split(",")[0], (t * 1e6, same), fontsize=6, rotation=60)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("us per position (full kinematics)")
        ax.set_title(mech)
    axes[0].set_ylabel("acceleration error of B (and E), relative")
    fig.tight_layout()
    OUT.mkdir(exist_ok=True)
    fig.savefig(OUT / "kinematics.png", dpi=120)


def summary(rows):
    t = {(m, p, lv): s for m, p, lv, s, *_ in rows}
    print("\ntargets:")
    for mech in ("fourbar", "course"):
        arr = t[(mech, "sarkp array, split", "full")]
        drv = t.get((mech, "Fortran driver, split", "full"))
        sca = t[(mech, "sarkp scalar loop, split", "full")]
        pl = t.get((mech, "pylinkage step_fast_with_kinematics (numba)", "full"))
        pls = t.get((mech, "pylinkage step_with_derivatives (Python)", "full"))
        pos = t[(mech, "sarkp array, split", "positions")]
        pv = t[(mech, "sarkp array, split", "pos+vel")]
        print(f"  {mech}: array / driver = {arr / drv:.2f} (<= 2)" if drv else
              f"  {mech}: no driver")
        print(f"  {mech}: scalar loop / array = {sca / arr:.0f} (>= 20)")
        if pl:
            print(f"  {mech}: pylinkage numba / array = {pl / arr:.2f}, "
                  f"pylinkage Python / array = {pls / arr:.0f} (>= 50)")
        print(f"  {mech}: positions / full = {pos / arr:.0%} (<= 40%), "
              f"pos+vel / full = {pv / arr:.0%}")


if __name__ == "__main__":
    sys.exit(main())
