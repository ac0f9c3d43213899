"""The long fuzz campaign of chapters 2-4 (issue 8): at least 1e5 random calls per
exported routine, in subprocesses (a crash is counted, not fatal), with the inputs and the
routine-independent invariants of tests/invariants.py, and, on a sample, the error
against a high-precision reference (mpmath, 40 digits, the physics written anew: loop
closure and the vector equations of velocities and accelerations solved exactly)
divided by the best achievable error (how far the exact answer moves when every input
moves by one rounding, or one rounding of the answer itself, whichever is larger).

    python benchmarks/fuzz.py                       # 1e5 calls per routine, 2 workers
    python benchmarks/fuzz.py --calls 2000 --refs 50 DKNMA1 DSKOR1   # a quick look

Writes the table (Markdown) to stdout; benchmarks/README.md holds the last run.
Columns: calls; crashes (a worker that died); silent NaN/inf (a non-finite result from
finite input with no error); wrong (an invariant violated beyond what the routine vouched
for: 1e-8 relative when silent, 10**-d when it warned with d digits); unclear (an
exception that is not a named sarkp/ValueError/TypeError, or has no message); errors (clear
errors: the inputs have no answer, e.g. the links do not reach); warned (results kept with
fewer than 8 digits vouched for); worst/best (the largest ratio of the error against the
reference to the best achievable, over the sample; "-" where no reference is written).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

CHUNK = 5000


# ------------------------------------------------------------------ references (mpmath)

def _mp():
    import mpmath
    mpmath.mp.dps = 40
    return mpmath


def _refs():
    mp = _mp()
    M = mp.mpf

    def e(t):
        return mp.matrix([mp.cos(t), mp.sin(t)])

    def kx(v):
        return mp.matrix([-v[1], v[0]])

    def pol(m, a):
        return M(m) * e(M(a))

    def solve(c1, c2, rhs):
        return mp.lu_solve(mp.matrix([[c1[0], c2[0]], [c1[1], c2[1]]]), rhs)

    def pt(x, y):
        return mp.matrix([M(x), M(y)])

    def norm(v):
        return mp.sqrt(v[0] ** 2 + v[1] ** 2)

    R = {}

    R["DUGL2"] = lambda a: [mp.atan2(M(a[3]) - M(a[1]), M(a[2]) - M(a[0]))]
    R["DUGL1"] = R["DUGL2"]                               # compared modulo 2 pi
    R["DUGL5"] = lambda a: [mp.atan2(M(a[1]), M(a[0]))]   # compared modulo 2 pi
    R["DUGOL"] = lambda a: [M(a[0])]                      # compared modulo 2 pi
    R["DUGL3"] = lambda a: [M(a[0]) + (1 if a[2] >= 0 else -1) * abs(M(a[1]))]
    R["DUGL4"] = lambda a: [M(a[0]) - M(a[1]) if a[2] < 0 else M(a[0])]

    def dintgr(a):
        m, h, nomer, y = a[0], M(a[1]), a[2], [M(v) for v in a[3]]
        f = [M(0)] * m
        if nomer == 1:                                   # corrected mode: E-DINTGR-4
            f[1] = h * (5 * y[0] + 8 * y[1] - y[2]) / 12 if m >= 3 else h * (y[0] + y[1]) / 2
            for k in range(2, m):
                f[k] = f[k - 2] + (y[k - 2] + 4 * y[k - 1] + y[k]) * h / 3
        for k in range(1, m):
            if nomer == 2:
                f[k] = f[k - 1] + h * (y[k - 1] + y[k]) / 2
            elif nomer == 3:
                f[k] = f[k - 1] + h * y[k]
        return f
    R["DINTGR"] = dintgr

    def dfrncl(a):
        m, h, y = a[0], M(a[1]), [M(v) for v in a[2]]
        d = [(y[k + 1] - y[k]) / h for k in range(m - 1)]
        return [d[0]] + d                                # corrected mode: E-DFRNCL-1
    R["DFRNCL"] = dfrncl

    def dsntzk(a):
        kw3, s, h, q = M(a[0]), M(a[1]), M(a[2]), a[3]
        beta = mp.pi / 2 * (kw3 - 1) / (kw3 + 1)
        lam, l3 = (1 / mp.sin(beta), s / 2) if q == 0 else (mp.sin(beta),
                                                            s / (2 * mp.sin(beta)))
        lo = (l3 - h) / (1 + lam)
        return [lam * lo, lo, l3]
    R["DSNTZK"] = dsntzk

    def circumcentre(p1, p2, p3):
        # |B - p1| = |B - p2| = |B - p3|: two linear equations
        m = mp.matrix([[2 * (p2[0] - p1[0]), 2 * (p2[1] - p1[1])],
                       [2 * (p3[0] - p1[0]), 2 * (p3[1] - p1[1])]])
        r = mp.matrix([p2[0]**2 + p2[1]**2 - p1[0]**2 - p1[1]**2,
                       p3[0]**2 + p3[1]**2 - p1[0]**2 - p1[1]**2])
        return mp.lu_solve(m, r)

    def dsntzr(a):
        lo, l3, fi1, fi3 = a
        cs = []
        for k in range(3):
            d = M(fi1[0]) - M(fi1[k])
            cs.append(M(lo[k]) * e(d) + M(l3) * e(M(fi3[k]) + d))
        b = circumcentre(*cs)
        return [norm(b), norm(cs[0] - b)]
    R["DSNTZR"] = dsntzr

    def crank_lengths(A, c1, c2):
        ac1, ac2 = norm(c1 - A), norm(c2 - A)
        l1 = (ac1 - ac2) / 2
        return l1, ac1 - l1

    def dsntz1(a):                                 # corrected mode (E-DSNTZ1-4)
        kw3, f31, f32, l3, xd, q = map(M, a)
        beta = mp.pi * (kw3 - 1) / (kw3 + 1)
        D = pt(xd, 0)
        c1, c2 = D + l3 * e(f31), D + l3 * e(f32)
        S = (c1 + c2) / 2
        h = norm(c2 - c1) / 2
        E = S + h * mp.cot(beta) * (D - S) / norm(D - S)
        r = norm(E - c1)
        xa = E[0] + mp.sign(q or 1) * mp.sqrt(r**2 - E[1]**2)
        l1, l2 = crank_lengths(pt(xa, 0), c1, c2)
        return [l1, l2, abs(xd - xa)]
    R["DSNTZ1"] = dsntz1

    def dsntz2(a):
        kw3, fi3, l3, xd, gmin, gmax = map(M, a)
        beta = mp.pi * (kw3 - 1) / (kw3 + 1)
        psi = beta + gmax - gmin
        D = pt(xd, 0)
        c1, c2 = D + l3 * e(fi3), D + l3 * e(fi3 + psi)
        st = solve(e(fi3 - gmin), -e(fi3 + psi - gmax), c2 - c1)
        A = c1 + st[0] * e(fi3 - gmin)
        l1, l2 = crank_lengths(A, c1, c2)
        return [l1, l2, norm(D - A), A[0], A[1]]
    R["DSNTZ2"] = dsntz2

    def dsntz3(a):                                 # corrected mode
        xb1, yb1, xb2, yb2, xc1, yc1, xc2, yc2, fi1, alc1 = map(M, a)
        b1, b2, c1, c2 = pt(xb1, yb1), pt(xb2, yb2), pt(xc1, yc1), pt(xc2, yc2)
        fib = mp.atan2(b2[1] - b1[1], b2[0] - b1[0])
        # A on the bisector of B1B2 (midpoint + s k x (B2 - B1)) and on the line through B1
        # at FIB1B2 - pi/2 + FI1/2
        mb = (b1 + b2) / 2
        st = solve(kx(b2 - b1), -e(fib - mp.pi / 2 + fi1 / 2), b1 - mb)
        A = mb + st[0] * kx(b2 - b1)
        mc = (c1 + c2) / 2
        st = solve(kx(c2 - c1), -e(alc1 + mp.pi / 2), c1 - mc)
        D = mc + st[0] * kx(c2 - c1)
        return [norm(A - b1), norm(c1 - D), norm(D - A)]
    R["DSNTZ3"] = dsntz3
    R["DVKT"] = lambda a: [mp.hypot(M(a[2]) - M(a[0]), M(a[3]) - M(a[1])),
                           mp.atan2(M(a[3]) - M(a[1]), M(a[2]) - M(a[0]))]
    R["DMOMNT"] = lambda a: [M(a[0]) * M(a[2]) * mp.sin(M(a[3]) - M(a[1]))]
    R["DOMEGA"] = lambda a: [mp.sign(M(a[2]) or 1) * M(a[1]) / M(a[0])]

    def dsmvkt(a):
        s = pol(a[0], a[1]) + pol(a[2], a[3])
        return [norm(s)]
    R["DSMVKT"] = dsmvkt

    def gelg(a):
        x = mp.lu_solve(mp.matrix(a[1].tolist()), mp.matrix([M(v) for v in a[0]]))
        return [x[i] for i in range(a[2])]
    R["GELG"] = gelg

    def kind1_pos(xa, ya, xc, yc, rz2, rz3, left):
        A, C = pt(xa, ya), pt(xc, yc)
        d = norm(C - A)
        fac = mp.atan2(C[1] - A[1], C[0] - A[0])
        ang = mp.acos((d**2 + M(rz2)**2 - M(rz3)**2) / (2 * d * M(rz2)))
        return A, C, A + M(rz2) * e(fac + (1 if left else -1) * ang)

    def dprm1(a):
        _, _, B = kind1_pos(*a[:6], a[6] < 0)
        return [B[0], B[1]]
    R["DPRM1"] = dprm1

    def dskor1(a):
        rz2, fi2, rz3, fi3, va, ala, vc, alc = map(M, a)
        w = solve(kx(rz2 * e(fi2)), -kx(rz3 * e(fi3)), pol(vc, alc) - pol(va, ala))
        return [w[0], w[1]]
    R["DSKOR1"] = dskor1

    def duskr1(a):
        aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3 = map(M, a)
        r2, r3 = rz2 * e(fi2), rz3 * e(fi3)
        x = solve(kx(r2), -kx(r3), pol(ac, bc) - pol(aa, ba) - w3**2 * r3 + w2**2 * r2)
        return [x[0], x[1]]
    R["DUSKR1"] = duskr1

    def dknma1(a):
        A, C, B = kind1_pos(*a[:6], a[14] > 0)
        r2, r3 = B - A, B - C
        w = solve(kx(r2), -kx(r3), pol(a[8], a[9]) - pol(a[6], a[7]))
        x = solve(kx(r2), -kx(r3), pol(a[12], a[13]) - pol(a[10], a[11]) - w[1]**2 * r3 +
                  w[0]**2 * r2)
        return [w[0], w[1], x[0], x[1]]
    R["DKNMA1"] = dknma1

    def dprm2(a):
        xa, ya, xk, yk, fim, rz2, rz3, t = a
        A, K = pt(xa, ya), pt(xk, yk)
        em, n = e(M(fim)), kx(e(M(fim)))
        so = (A - K)[0] * n[0] + (A - K)[1] * n[1]
        off = mp.sign(so) * M(rz3) * mp.sin(M(t))
        r = -(so - off)                                # B's offset minus A's, along n
        x = mp.sqrt(M(rz2)**2 - r**2)
        B = A + x * em + r * n
        return [B[0], B[1]]
    R["DPRM2"] = dprm2

    def dskor2(a):
        va, ala, vbm, albm, rz2, fi2, fim = map(M, a)
        x = solve(kx(rz2 * e(fi2)), -e(fim), pol(vbm, albm) - pol(va, ala))
        return [x[0], x[1]]
    R["DSKOR2"] = dskor2

    def duskr2(a):
        aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim = map(M, a)
        r = rz2 * e(fi2)
        x = solve(kx(r), -e(fim), pol(abm, bvm) + pol(abk, bvk) - pol(aa, ba) + w2**2 * r)
        return [x[0], x[1]]
    R["DUSKR2"] = duskr2

    def dknma2(a):
        A, K = pt(a[0], a[1]), pt(a[2], a[3])
        fim, rz2, rz3, eta, p = M(a[4]), M(a[5]), M(a[6]), M(a[7]), a[17]
        em, n = e(fim), kx(e(fim))
        so = (A - K)[0] * n[0] + (A - K)[1] * n[1]
        c = (so - rz3 * mp.sin(eta)) / rz2
        r = p * rz2 * mp.sqrt(1 - c**2) * em - rz2 * c * n
        w = solve(kx(r), -em, -pol(a[8], a[9]))
        x = solve(kx(r), -em, -pol(a[13], a[14]) + w[0]**2 * r)
        return [w[0], x[0]]
    R["DKNMA2"] = dknma2

    def dprm3(a):
        xa, ya, xc, yc, rz2, t, p = a
        A, C = pt(xa, ya), pt(xc, yc)
        d = norm(A - C)
        return [mp.atan2(A[1] - C[1], A[0] - C[0]) + p * mp.asin(M(rz2) * mp.sin(M(t)) / d)]
    R["DPRM3"] = dprm3

    def dskor3(a):
        xa, ya, xc, yc, va, ala, vc, alc, fi3 = a
        r = pt(xa, ya) - pt(xc, yc)
        x = solve(kx(r), e(M(fi3)), pol(va, ala) - pol(vc, alc))
        return [x[0]]
    R["DSKOR3"] = dskor3

    def duskr3(a):
        aa, ba, ac, bc, fi3, w3, rzac, fica, aak, bak = map(M, a)
        r = rzac * e(fica)
        x = solve(kx(r), -e(fi3), pol(aa, ba) + pol(aak, bak) - pol(ac, bc) + w3**2 * r)
        return [x[0]]
    R["DUSKR3"] = duskr3

    def dknma3(a):
        A, C = pt(a[0], a[1]), pt(a[2], a[3])
        rz2, eta, p = M(a[4]), M(a[5]), a[14]
        d = norm(A - C)
        fik = mp.atan2(C[1] - A[1], C[0] - A[0])
        fi3 = fik + mp.pi - p * mp.asin(rz2 * mp.sin(eta) / d)
        ax, r = e(fi3), A - C
        vrel = pol(a[6], a[7]) - pol(a[8], a[9])
        w = solve(kx(r), ax, vrel)
        x = solve(kx(r), ax, pol(a[10], a[11]) - pol(a[12], a[13]) + w[0]**2 * r -
                  2 * w[0] * w[1] * kx(ax))
        return [w[0], x[0]]
    R["DKNMA3"] = dknma3

    def kind4_b(xa, ya, fim, xc, yc, fin, rz2, t2, rz3, t3):
        nm, nn = kx(e(M(fim))), kx(e(M(fin)))
        A, C = pt(xa, ya), pt(xc, yc)
        m = mp.matrix([[nm[0], nm[1]], [nn[0], nn[1]]])
        return mp.lu_solve(m, mp.matrix([nm[0] * A[0] + nm[1] * A[1] + M(rz2) * mp.sin(M(t2)),
                                          nn[0] * C[0] + nn[1] * C[1] +
                                          M(rz3) * mp.sin(M(t3))]))

    def dprm4(a):
        B = kind4_b(a[2], a[3], a[4], a[7], a[8], a[9], a[10], a[11], a[12], a[13])
        return [B[0], B[1]]
    R["DPRM4"] = dprm4

    def dskor4(a):
        rvbm, fivbm, fim, rvbn, fivbn, fin, wm, wn = map(M, a)
        x = solve(e(fim), -e(fin), wn * kx(rvbn * e(fivbn)) - wm * kx(rvbm * e(fivbm)))
        return [x[0], x[1]]
    R["DSKOR4"] = dskor4

    def duskr4(a):
        rvbm, fivbm, fim, rvbn, fivbn, fin, wm, em, wn, en, amk, bmk, ank, bnk = map(M, a)
        rm, rn = rvbm * e(fivbm), rvbn * e(fivbn)
        x = solve(e(fim), -e(fin), en * kx(rn) - wn**2 * rn + pol(ank, bnk) -
                  em * kx(rm) + wm**2 * rm - pol(amk, bmk))
        return [x[0], x[1]]
    R["DUSKR4"] = duskr4

    def dknma4(a):
        fim, xa, ya, fin, xc, yc, rz2, t2, rz3, t3, wm, wn, em, en, an = a
        B = kind4_b(xa, ya, fim, xc, yc, fin, rz2, t2, rz3, t3)
        um, un = e(M(fim)), e(M(fin))
        rm, rn = B - pt(xa, ya), B - pt(xc, yc)
        wm, wn, em, en = M(wm), M(wn), M(em), M(en)
        s = solve(um, -un, wn * kx(rn) - wm * kx(rm))
        x = solve(um, -un, en * kx(rn) - wn**2 * rn + 2 * wn * s[1] * kx(un) -
                  em * kx(rm) + wm**2 * rm - 2 * wm * s[0] * kx(um))
        return [s[0], s[1], x[0], x[1]]
    R["DKNMA4"] = dknma4

    def dprm5(a):
        xa, ya, fim, xc, yc, t2 = a
        x = solve(e(M(fim)), e(M(fim) + M(t2)), pt(xc, yc) - pt(xa, ya))
        return [x[0], x[1]]
    R["DPRM5"] = dprm5

    def dskor5(a):
        xc3, yc3, xvm, yvm, fim, t2, wm, vc3, alc3 = a
        r = pt(xc3, yc3) - pt(xvm, yvm)
        x = solve(e(M(fim) + M(t2)), -e(M(fim)), M(wm) * kx(r) - pol(vc3, alc3))
        return [x[0], x[1]]
    R["DSKOR5"] = dskor5

    def duskr5(a):
        xc3, yc3, xvm, yvm, fim, wm, em, t2, ac3, bc3, a2mk, b2mk, a23k, b23k = a
        r = pt(xc3, yc3) - pt(xvm, yvm)
        x = solve(e(M(fim) + M(t2)), -e(M(fim)), M(em) * kx(r) - M(wm)**2 * r +
                  pol(a2mk, b2mk) - pol(ac3, bc3) - pol(a23k, b23k))
        return [x[0], x[1]]
    R["DUSKR5"] = duskr5

    def dknma5(a):
        fim, xc, yc, eta2, xr, yr, wm, em, vc3, alc3, ac3, bc3 = (a[2], a[3], a[4], a[6],
                                                                  a[8], a[9], a[10], a[11],
                                                                  a[12], a[13], a[14], a[15])
        r = pt(xc, yc) - pt(xr, yr)
        us, um = e(M(fim) + M(eta2)), e(M(fim))
        wm, em = M(wm), M(em)
        y = solve(us, -um, wm * kx(r) - pol(vc3, alc3))
        z = solve(us, -um, em * kx(r) - wm**2 * r + 2 * wm * y[1] * kx(um) - pol(ac3, bc3) -
                  2 * wm * y[0] * kx(us))
        return [y[0], y[1], z[0], z[1]]
    R["DKNMA5"] = dknma5
    return mp, R


def _signed(mod, ang, ref):
    return mod if math.cos(ang - ref) > 0 else -mod


def _got(name, args, out):
    """The routine's results in the reference's terms (signed scalars, coordinates)."""
    o = out
    if name == "GELG":
        return list(np.atleast_1d(o.R))
    if name in ("DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL"):
        return [o]
    if name == "DINTGR":
        return list(o.FINT)
    if name == "DFRNCL":
        return list(o.FDIF)
    if name == "DSNTZK":
        return [o.L1, o.LO, o.L3]
    if name == "DSNTZR":
        return [o.L1, o.L2]
    if name == "DSNTZ1":
        return [o.L1, o.L2, o.LO]
    if name == "DSNTZ2":
        return [o.L1, o.L2, o.LO, o.XA, o.YA]
    if name == "DSNTZ3":
        return [o.L1, o.L3, o.LO]
    if name in ("DMOMNT", "DOMEGA"):
        return [o]
    if name == "DVKT":
        return [o.RZ, o.FI]
    if name == "DSMVKT":
        return [o.L]
    if name in ("DPRM1", "DPRM2", "DPRM4"):
        return [o.XB, o.YB]
    if name == "DPRM3":
        return [o.FI3]
    if name == "DPRM5":
        return [o.S2, o.S3]
    if name == "DSKOR1":
        return [o.W2, o.W3]
    if name == "DSKOR2":
        return [o.W2, _signed(o.VBBM, o.ALBBM, args[6])]
    if name == "DSKOR3":
        return [o.W3]
    if name == "DSKOR4":
        return [_signed(o.VBBM, o.ALBBM, args[2]), _signed(o.VBBN, o.ALBBN, args[5])]
    if name == "DSKOR5":
        return [_signed(o.VC2C3, o.ALC2C3, args[4] + args[5]), _signed(o.VC2CM, o.ALC2CM,
                                                                       args[4])]
    if name == "DUSKR1":
        return [o.E2, o.E3]
    if name == "DUSKR2":
        return [o.E2, _signed(o.ABVM, o.BVBM, args[9])]
    if name == "DUSKR3":
        return [o.E3]
    if name == "DUSKR4":
        return [_signed(o.ABBMR, o.BBBMR, args[2]), _signed(o.ABBNR, o.BBBNR, args[5])]
    if name == "DUSKR5":
        return [_signed(o.AC2C3R, o.BC2C3R, args[4] + args[7]), _signed(o.AC2CMR, o.BC2CMR,
                                                                        args[4])]
    if name == "DKNMA1":
        return [o.W2, o.W3, o.E2, o.E3]
    if name == "DKNMA2":
        return [o.W2, o.E2]
    if name == "DKNMA3":
        return [o.W3, o.E3]
    if name == "DKNMA4":
        return [_signed(o.VB2R, o.ALB2R, args[0]), _signed(o.VB3R, o.ALB3R, args[3]),
                _signed(o.AB2R, o.BB2R, args[0]), _signed(o.AB3R, o.BB3R, args[3])]
    if name == "DKNMA5":
        s, m = args[2] + args[6], args[2]
        return [_signed(o.VC2C3, o.ALC2C3, s), _signed(o.VC2CM, o.ALC2CM, m),
                _signed(o.AC2C3R, o.BC2C3R, s), _signed(o.AC2CMR, o.BC2CMR, m)]
    return None


ANGLES = {"DUGL1": {0}, "DUGL2": {0}, "DUGL5": {0}, "DUGOL": {0}, "DVKT": {1},
          "DPRM3": {0}}
# the magnitudes that share one scale (a vector's components, a group's unknowns)


def _perturbations(args):
    """Every float input (every element of a table) moved by one rounding, up and down."""
    for k, v in enumerate(args):
        if isinstance(v, (int, np.integer)) and not isinstance(v, bool):
            continue
        if isinstance(v, (list, np.ndarray)):
            arr = np.array(v, dtype=float)
            for j in range(arr.size):
                for sgn in (-1, 1):
                    b = arr.copy()
                    b.flat[j] *= 1.0 + sgn * 2.0**-53
                    a = list(args)
                    a[k] = b
                    yield a
            continue
        for sgn in (-1, 1):
            a = list(args)
            a[k] = float(v) * (1.0 + sgn * 2.0**-53)
            yield a


def ratio(mp, ref, name, args, got):
    """Error against the reference divided by the best achievable (normwise)."""
    exact = ref(args)
    angles = ANGLES.get(name, set())

    def diff(x, y, i):
        d = mp.mpf(x) - y
        if i in angles:
            d = (d + mp.pi) % (2 * mp.pi) - mp.pi
        return d

    err = mp.sqrt(sum(diff(g, x, i) ** 2 for i, (g, x) in enumerate(zip(got, exact))))
    size = mp.sqrt(sum(x**2 for i, x in enumerate(exact) if i not in angles) or [0]) \
        if len(angles) < len(exact) else mp.mpf(1)
    best = 2.0**-53 * max(size, mp.mpf(2.0**-1074))
    for a in _perturbations(args):
        try:
            moved = ref(a)
        except (ZeroDivisionError, ValueError):
            continue
        dv = mp.sqrt(sum(diff(m, x, i) ** 2 for i, (m, x) in enumerate(zip(moved, exact))))
        best = max(best, dv)
    return float(err / best)


# ------------------------------------------------------------------ worker and driver

def worker(name, seed, calls, refs):
    import invariants as I
    gen, check = I.CASES[name]
    rng = np.random.default_rng(seed)
    counts = dict(calls=0, nan=0, wrong=0, unclear=0, errors=0, warned=0, refs=0)
    worst, worst_args, wrong_args = 0.0, None, None
    every = max(1, calls // refs) if refs else 0
    mp = R = None
    if refs:
        mp, R = _refs()
    for i in range(calls):
        args = gen(rng)
        kind, out, bound = I.call(name, args)
        counts["calls"] += 1
        if kind == "nan":
            counts["nan"] += 1
            wrong_args = args
        elif kind == "unclear":
            counts["unclear"] += 1
            wrong_args = args
        elif kind == "error":
            counts["errors"] += 1
        else:
            if bound > 1e-8:
                counts["warned"] += 1
            if check(args, out, bound) > 1.0:
                counts["wrong"] += 1
                wrong_args = args
            if every and i % every == 0 and name in R:
                got = _got(name, args, out)
                try:
                    r = ratio(mp, R[name], name, args, got)
                except (ZeroDivisionError, ValueError):
                    r = None
                if r is not None:
                    counts["refs"] += 1
                    if r > worst:
                        worst, worst_args = r, args
    counts["worst"] = worst
    counts["worst_args"] = _jsonable(worst_args)
    counts["wrong_args"] = _jsonable(wrong_args)
    print(json.dumps(counts), flush=True)


def _jsonable(a):
    if a is None:
        return None
    return [x.tolist() if isinstance(x, np.ndarray) else float(x) if isinstance(
        x, (float, np.floating)) else x for x in a]


def run_routine(name, calls, refs, seed):
    total = dict(calls=0, crashes=0, nan=0, wrong=0, unclear=0, errors=0, warned=0, refs=0,
                 worst=0.0, worst_args=None, wrong_args=None)
    chunks = max(1, math.ceil(calls / CHUNK))
    for c in range(chunks):
        n = min(CHUNK, calls - c * CHUNK)
        cmd = [sys.executable, __file__, "--worker", name, str(seed + c), str(n),
               str(math.ceil(refs / chunks))]
        p = subprocess.run(cmd, capture_output=True, text=True)
        lines = [ln for ln in p.stdout.splitlines() if ln.startswith("{")]
        if p.returncode != 0 or not lines:
            total["crashes"] += 1
            total["calls"] += n
            continue
        r = json.loads(lines[-1])
        for k in ("calls", "nan", "wrong", "unclear", "errors", "warned", "refs"):
            total[k] += r[k]
        if r["worst"] > total["worst"]:
            total["worst"], total["worst_args"] = r["worst"], r["worst_args"]
        if r["wrong_args"] is not None:
            total["wrong_args"] = r["wrong_args"]
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("routines", nargs="*")
    ap.add_argument("--calls", type=int, default=100_000)
    ap.add_argument("--refs", type=int, default=300, help="reference comparisons per routine")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=20261123)
    ap.add_argument("--worker", nargs=4, metavar=("NAME", "SEED", "CALLS", "REFS"))
    ap.add_argument("--json", help="also write the raw results here")
    a = ap.parse_args()
    if a.worker:
        name, seed, calls, refs = a.worker
        worker(name, int(seed), int(calls), int(refs))
        return
    import invariants as I
    names = a.routines or I.ROUTINES
    from concurrent.futures import ThreadPoolExecutor
    t0 = time.time()
    with ThreadPoolExecutor(a.jobs) as pool:
        results = dict(zip(names, pool.map(
            lambda n: run_routine(n, a.calls, a.refs, a.seed + 1000 * I.ROUTINES.index(n)),
            names)))
    print(f"| routine | calls | crashes | silent NaN/inf | wrong | unclear | errors | warned "
          f"| refs | worst/best |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n in names:
        r = results[n]
        w = f"{r['worst']:.3g}" if r["refs"] else "-"
        print(f"| {n} | {r['calls']} | {r['crashes']} | {r['nan']} | {r['wrong']} | "
              f"{r['unclear']} | {r['errors']} | {r['warned']} | {r['refs']} | {w} |")
    print(f"\n{sum(r['calls'] for r in results.values())} calls in {time.time() - t0:.0f} s")
    if a.json:
        Path(a.json).write_text(json.dumps(results, indent=1))


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
