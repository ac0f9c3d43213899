"""Random inputs and routine-independent invariants for every exported routine of
chapters 2-4, shared by tests/test_fuzz.py (Hypothesis, bounded) and benchmarks/fuzz.py
(the long campaign).

``CASES[name] = (generate, check)``: ``generate(rng)`` draws valid inputs over wide
ranges (lengths from 1e-3 to 1e3, so link ratios up to 1e6; a third of the mechanisms
moved by up to 1e6 from the origin; angles of any size); ``check(args, out, bound)``
returns the worst violation of the routine's invariants, relative to the tolerance
(> 1 means a wrong number), where ``bound`` is the relative error the routine vouched
for (1e-8 when silent, 10**-d when it warned with d digits).  The invariants do not use
the routine's own formulas: loop closure, the given lengths and angles recovered,
velocities and accelerations against finite differences of positions and velocities,
the operators' definitions.

``call(name, args)`` runs a routine and classifies the outcome: ``("ok", out, bound)``,
``("error", exc, None)`` for a SarkpError/ValueError whose message says something,
``("unclear", exc, None)`` for any other exception or an empty message, ``("nan", out,
None)`` for a non-finite result from finite input without an error.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

import sarkp

U = 2.0**-53
PI = math.pi

__all__ = ["CASES", "call", "ROUTINES"]


# ---------------------------------------------------------------------------- calling

def call(name, args):
    f = getattr(sarkp, name)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            out = f(*args)
        except (sarkp.SarkpError, ValueError, TypeError) as exc:
            if str(exc).strip():
                return "error", exc, None
            return "unclear", exc, None
        except Exception as exc:                      # noqa: BLE001 - classified, counted
            return "unclear", exc, None
    bound = 1e-8
    for w in caught:
        if issubclass(w.category, sarkp.SignificanceWarning):
            digits = w.message.digits                 # None: the routine cannot say
            bound = max(bound, 1.0 if digits is None else 10.0 ** -digits)
    values = np.concatenate([np.ravel(np.asarray(v, dtype=float)) for v in
                             (out if isinstance(out, tuple) else (out,))])
    if not np.all(np.isfinite(values)):
        return "nan", out, None
    return "ok", out, bound


# ---------------------------------------------------------------------------- helpers

def length(rng, lo=-3.0, hi=3.0):
    return float(10.0 ** rng.uniform(lo, hi))


def angle(rng, big=False):
    if big and rng.random() < 0.2:
        return float(rng.uniform(-50.0, 50.0))
    return float(rng.uniform(-PI, PI))


def offset(rng):
    """A third of the mechanisms stand far from the origin."""
    if rng.random() < 1 / 3:
        return float(rng.uniform(-1e6, 1e6)), float(rng.uniform(-1e6, 1e6))
    return 0.0, 0.0


def e(t):
    return np.array([math.cos(t), math.sin(t)])


def vec(mod, ang):
    return mod * e(ang)


def cross(a, b):
    return float(a[0] * b[1] - a[1] * b[0])


def kx(v):
    return np.array([-v[1], v[0]])


def rel(residual, scale):
    return float(np.linalg.norm(residual)) / scale if scale > 0 else float(
        np.linalg.norm(residual) > 0) * math.inf


def angdiff(a, b):
    return abs((a - b + PI) % (2 * PI) - PI)


def worst(*ratios):
    return max([0.0] + [float(r) for r in ratios])


def tol(bound, coords=0.0, scale=1.0):
    """Allowed relative violation: what the routine vouched for, plus the rounding of
    absolute coordinates of size `coords` relative to `scale`, plus a few ulps."""
    return bound + 64 * U * (1.0 + coords / scale)


def fd_ok(f, h):
    """Central difference of f at 0 with the step h/2, and how far it is from those with
    the steps h and 0.7 h: the larger disagreement estimates its own error (truncation and
    rounding noise); a difference quotient that disagrees with itself judges nothing."""
    def d(k):
        return (np.asarray(f(k)) - np.asarray(f(-k))) / (2 * k)
    d1, d2, d3 = d(h), d(h / 2), d(0.7 * h)
    return d2, max(float(np.linalg.norm(d2 - d1)), float(np.linalg.norm(d2 - d3)))


# ------------------------------------------------------------------ chapter 2 operators

def gen_gelg(rng):
    m = int(rng.integers(1, 6))
    a = rng.standard_normal((m, m)) * 10.0 ** rng.uniform(-100, 100)
    x = rng.standard_normal(m)
    return [a @ x, a, m, 1, 1e-4]


def chk_gelg(args, out, bound):
    r, a, m = args[0], args[1], args[2]
    x, ier = out
    if ier < 0:
        return 0.0
    scale = np.abs(a).max() * np.abs(x).max() + np.abs(r).max()
    # backward error: a stable solver leaves a residual of a few ulps of |A| |x|
    return rel(a @ np.atleast_1d(x) - r, scale) / (64 * m * U)


def gen_dintgr(rng):
    m = int(rng.integers(3, 30))
    h = length(rng, -2, 1)
    c0, c1 = rng.standard_normal(2)
    x = np.arange(m) * h
    return [m, h, int(rng.integers(1, 4)), c0 + c1 * x]


def chk_dintgr(args, out, bound):
    m, h, nomer, y = args
    x = np.arange(m) * h
    c1 = (y[1] - y[0]) / h
    exact = y[0] * x + c1 * x**2 / 2
    if nomer == 3:                                    # right rectangles: exact sum
        exact = np.concatenate([[0.0], np.cumsum(h * y[1:])])
    scale = np.abs(y).max() * x[-1] + 1e-300
    return rel(out - exact, scale) / (64 * m * U)


def gen_dfrncl(rng):
    m = int(rng.integers(2, 30))
    h = length(rng, -2, 1)
    c0, c1 = rng.standard_normal(2)
    return [m, h, c0 + c1 * np.arange(m) * h]


def chk_dfrncl(args, out, bound):
    m, h, y = args
    c1 = (y[1] - y[0]) / h
    scale = np.abs(y).max() / h
    return rel(out - c1, scale) / (64 * U)


def gen_points(rng):
    ox, oy = offset(rng)
    L = length(rng)
    t = angle(rng)
    return [ox, oy, ox + L * math.cos(t), oy + L * math.sin(t)]


def chk_dugl12(lo, hi):
    def chk(args, out, bound):
        x1, y1, x2, y2 = args
        L = math.hypot(x2 - x1, y2 - y1)
        if not lo <= out <= hi:
            return math.inf
        return angdiff(out, math.atan2(y2 - y1, x2 - x1)) / (8 * U * (1 + abs(x1) / L +
                                                                   abs(y1) / L))
    return chk


def gen_dugl34(rng):
    return [angle(rng, True), angle(rng, True), float(rng.standard_normal())]


def chk_dugl3(args, out, bound):
    u1, ud, v = args
    return abs(out - (u1 + math.copysign(abs(ud), v if v != 0 else 1.0))) / (
        8 * U * (abs(u1) + abs(ud) + 1))


def chk_dugl4(args, out, bound):
    u1, ud, v = args
    return abs(out - (u1 - ud if v < 0 else u1)) / (8 * U * (abs(u1) + abs(ud) + 1))


def gen_dugl5(rng):
    return [float(rng.standard_normal() * length(rng)),
            float(rng.standard_normal() * length(rng))]


def chk_dugl5(args, out, bound):
    px, py = args
    if not -PI / 2 <= out <= 3 * PI / 2 + 1e-15:
        return math.inf
    return angdiff(out, math.atan2(py, px)) / (8 * U)


def gen_dugol(rng):
    return [float(rng.uniform(-2 * PI, 2 * PI))]


def chk_dugol(args, out, bound):
    fi = args[0]
    if out < 0:
        return math.inf
    return angdiff(out, fi) / (8 * U * (1 + abs(fi)))


def gen_dmomnt(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_dmomnt(args, out, bound):
    r, fi, f, g = args
    exact = r * f * math.sin(g - fi)
    return abs(out - exact) / (8 * U * r * f * (2 + abs(fi) + abs(g)))


def gen_domega(rng):
    return [length(rng), length(rng), angle(rng, True)]


def chk_domega(args, out, bound):
    r, v, ug = args
    return abs(out - math.copysign(v / r, ug if ug != 0 else 1.0)) / (4 * U * v / r)


def chk_dvkt(args, out, bound):
    x1, y1, x2, y2 = args
    L = math.hypot(x2 - x1, y2 - y1)
    rz, fi = out
    return worst(abs(rz - L) / (8 * U * (L + abs(x1) + abs(y1))),
                 angdiff(fi, math.atan2(y2 - y1, x2 - x1)) /
                 (8 * U * (1 + (abs(x1) + abs(y1)) / L)))


def gen_dsmvkt(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_dsmvkt(args, out, bound):
    l1, f1, l2, f2 = args
    s = vec(l1, f1) + vec(l2, f2)
    got = vec(out[0], out[1])
    return rel(got - s, l1 + l2) / (16 * U * (2 + abs(f1) + abs(f2)))


# ------------------------------------------------------------------ chapter 3 synthesis

def fourbar_mu(xa, ya, xd, yd, l1, l2, l3, n=4001):
    th = np.linspace(0.0, 2 * PI, n)
    bd = np.hypot(xa + l1 * np.cos(th) - xd, ya + l1 * np.sin(th) - yd)
    return np.arccos(np.clip((l2**2 + l3**2 - bd**2) / (2 * l2 * l3), -1, 1))


def chk_turn(mu, out):
    """The reported extremes of the transmission angle against a sweep (the sweep's
    grid resolves them to about 1e-3 rad)."""
    return worst(abs(out.GMIN_TURN - mu.min()) / 2e-3 if out.GMIN_TURN <= mu.min() + 1e-9
                 else math.inf,
                 abs(out.GMAX_TURN - mu.max()) / 2e-3 if out.GMAX_TURN >= mu.max() - 1e-9
                 else math.inf)


def gen_dsntzr(rng):
    l0, l1 = length(rng, -1, 1), length(rng, -1, 1)
    l2, l3 = length(rng, -1, 1), length(rng, -1, 1)
    fi1 = sorted(rng.uniform(-PI, PI, 3))
    fi3 = list(rng.uniform(-PI, PI, 3))
    return [[l0] * 3, l3, list(fi1), fi3]


def chk_dsntzr(args, out, bound):
    lo, l3, fi1, fi3 = args
    # the crank pin B (in the crank's frame at FI11 + FI1[i] - FI1[0]) is at distance L2
    # from every position of C: closure of the three positions
    viol = []
    for k in range(3):
        th = out.FI11 + fi1[k] - fi1[0]
        b = vec(out.L1, th)
        c = vec(lo[k], 0.0) + vec(l3, fi3[k])
        viol.append(abs(np.linalg.norm(c - b) - out.L2) /
                    (max(out.L1, out.L2, l3, lo[k]) * tol(1e-10)))
    return worst(*viol)


def gen_dsntz1(rng):
    f31 = rng.uniform(-PI, PI)
    return [float(rng.uniform(1.01, 3.0)), float(f31), float(f31 + rng.uniform(0.2, 2.5)),
            length(rng, -1, 1), float(rng.uniform(-2, 2)), float(rng.choice([-1.0, 1.0]))]


def chk_dsntz1(args, out, bound):
    kw3, f31, f32, l3, xd, q = args
    # A on the x axis at distance LO from D; both extreme positions of C reached with
    # crank and coupler collinear: |AC1| = L1 + L2, |AC2| = L2 - L1 (either order)
    best = math.inf
    for xa in (xd - out.LO, xd + out.LO):
        c1 = np.array([xd, 0.0]) + vec(l3, f31)
        c2 = np.array([xd, 0.0]) + vec(l3, f32)
        a1 = np.hypot(*(c1 - [xa, 0.0]))
        a2 = np.hypot(*(c2 - [xa, 0.0]))
        s = max(a1, a2, l3)
        v = max(abs(max(a1, a2) - (out.L1 + out.L2)), abs(min(a1, a2) - (out.L2 - out.L1)))
        viol = v / (s * 1e-10)
        mu = fourbar_mu(xa, 0.0, xd, 0.0, out.L1, out.L2, l3)
        best = min(best, worst(viol, chk_turn(mu, out)))
    return best


def gen_dsntz2(rng):
    return [float(rng.uniform(1.01, 3.0)), angle(rng), length(rng, -1, 1),
            float(rng.uniform(-2, 2)), float(rng.uniform(0.1, 1.4)), float(rng.uniform(0.1, 2.0))]


def chk_dsntz2(args, out, bound):
    kw3, fi3, l3, xd, gmin, gmax = args
    beta = PI * (kw3 - 1) / (kw3 + 1)
    psi = beta + gmax - gmin
    d = np.array([xd, 0.0])
    c1, c2 = d + vec(l3, fi3), d + vec(l3, fi3 + psi)
    a = np.array([out.XA, out.YA])
    s = max(out.L1, out.L2, l3, out.LO)
    viol = [abs(np.hypot(*(c1 - a)) - (out.L1 + out.L2)) / (s * 1e-10),
            abs(np.hypot(*(c2 - a)) - (out.L2 - out.L1)) / (s * 1e-10),
            abs(np.hypot(*(d - a)) - out.LO) / (s * 1e-10)]
    # transmission angle BCD at the two extreme positions
    b1 = a + (c1 - a) * out.L1 / (out.L1 + out.L2)
    b2 = a - (c2 - a) * out.L1 / (out.L2 - out.L1)
    for b, c, g in ((b1, c1, gmin), (b2, c2, gmax)):
        u, v = b - c, d - c
        mu = math.acos(max(-1, min(1, u @ v / np.linalg.norm(u) / np.linalg.norm(v))))
        viol.append(abs(mu - g) / 1e-7)
    mu = fourbar_mu(out.XA, out.YA, xd, 0.0, out.L1, out.L2, l3)
    return worst(*viol, chk_turn(mu, out))


def gen_dsntz3(rng):
    p = rng.uniform(-1, 1, 8)
    return [*map(float, p), float(rng.uniform(0.2, 2.5)), angle(rng)]


def chk_dsntz3(args, out, bound):
    xb1, yb1, xb2, yb2, xc1, yc1, xc2, yc2, fi1, alc1 = args
    # A is equidistant (L1) from B1, B2 and sees B1B2 under FI1; D equidistant (L3) from
    # C1, C2: only the lengths are returned, so check |B1B2| = 2 L1 sin(FI1/2)
    chord = math.hypot(xb2 - xb1, yb2 - yb1)
    mu = fourbar_mu(0.0, 0.0, out.LO, 0.0, out.L1, math.hypot(xc1 - xb1, yc1 - yb1), out.L3)
    return worst(abs(chord - 2 * out.L1 * abs(math.sin(fi1 / 2))) / (chord * 1e-10),
                 chk_turn(mu, out))


def gen_dsntzk(rng):
    return [float(rng.uniform(1.01, 3.0)), length(rng, -1, 1), 0.0,
            float(rng.choice([0.0, 1.0]))]


def chk_dsntzk(args, out, bound):
    kw3, s, h, q = args
    beta = PI / 2 * (kw3 - 1) / (kw3 + 1)
    # oscillating: stroke S = 2 L3 sin(swing/2) with sin(swing/2) = L1/LO
    if q != 0.0:
        v = abs(2 * out.L3 * out.L1 / out.LO - s) / (s * 1e-12)
        v2 = abs(out.L1 / out.LO - math.sin(beta)) / 1e-12
    else:
        v = abs(2 * out.L3 - s) / (s * 1e-12)
        v2 = abs(out.LO / out.L1 - math.sin(beta)) / 1e-12
    return worst(v, v2, abs(out.GMIN_TURN - PI / 2) / 1e-15, abs(out.GMAX_TURN - PI / 2) / 1e-15)


# ------------------------------------------------------------------ chapter 4 kinematics
# Each kind: a random group with its driving points moving (velocity, acceleration); the
# invariants are checked on the position routine, on the velocity and acceleration
# routines fed with exact angles, and on DKNMA (positions closed, velocities and
# accelerations against finite differences of its own positions and velocities).

def polar(mod, ang):
    return vec(mod, ang)


def quiet(f, *args):
    """The routine's result, or None where it refuses or warns (finite differences are
    taken only through positions the routine computes without reservation)."""
    kind, out, bound = call(f, args)
    return out if kind == "ok" and bound <= 1e-8 else None


def moved(p, v, a, t):
    return p + v * t + a * t * t / 2


def timescale(lengths, speeds):
    return min(lengths) / max(max(speeds), 1e-300)


def fd_vs(f, h, got, scale, bound, coords=0.0):
    """Compare got with the central difference of f (None where f fails), within 1e-4 of
    scale (or 100 times what the routine vouched for): a check that catches a wrong
    formula, branch or sign, not the last digits (the references of benchmarks/fuzz.py
    judge those).  The difference quotient is used only where it is good to a sixteenth
    of that: its three steps agree, and the rounding of absolute coordinates of size
    `coords` (the inputs of the routine at t = +-h), divided by h, is small enough."""
    def g(t):
        r = f(t)
        if r is None:
            raise _NoFD
        return r
    try:
        d, err = fd_ok(g, h)
    except _NoFD:
        return 0.0
    allowed = max(1e-4, 100 * bound) * scale
    noise = err + 16 * U * coords / h
    if not noise <= allowed / 16:
        return 0.0
    return rel(d - np.asarray(got), 1.0) / allowed


class _NoFD(Exception):
    pass


def unit_dir_ok(ang, ref):
    """A modulus-and-direction output whose direction must be ref or ref - pi."""
    return min(angdiff(ang, ref), angdiff(ang, ref + PI))


# ---- kind 1 (RRR) ----------------------------------------------------------------------

def _kind1(rng):
    ox, oy = offset(rng)
    L = length(rng)
    A = np.array([ox, oy])
    rz2, rz3 = L, L * length(rng)
    B = A + vec(rz2, angle(rng))
    C = B + vec(rz3, angle(rng))
    rz3 = float(np.hypot(*(B - C)))
    side = 1.0 if cross(C - A, B - A) > 0 else -1.0      # +1: B left of A -> C
    return A, B, C, rz2, rz3, side, max(rz2, rz3)


def gen_dprm1(rng):
    A, B, C, rz2, rz3, side, _ = _kind1(rng)
    return [A[0], A[1], C[0], C[1], rz2, rz3, -side]        # DPRM1: P = -1 <=> left


def chk_dprm1(args, out, bound):
    xa, ya, xc, yc, rz2, rz3, p = args
    A, C, B = np.array([xa, ya]), np.array([xc, yc]), np.array([out.XB, out.YB])
    t = tol(bound, max(abs(xa), abs(ya), abs(xc), abs(yc)), min(rz2, rz3))
    L = max(rz2, rz3)
    left = cross(C - A, B - A) > 0
    side_ok = 0.0 if (left == (p < 0)) or abs(cross(C - A, B - A)) <= t * L * L * 4 \
        else math.inf
    return worst(abs(np.hypot(*(B - A)) - rz2) / (L * t), abs(np.hypot(*(B - C)) - rz3) /
                 (L * t), angdiff(out.FI2, math.atan2(*(B - A)[::-1])) / t * min(rz2, rz3) /
                 rz2, side_ok)


def gen_dskor1(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True),
            length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_dskor1(args, out, bound):
    rz2, fi2, rz3, fi3, va, ala, vc, alc = args
    r2, r3 = vec(rz2, fi2), vec(rz3, fi3)
    vb1 = polar(va, ala) + out.W2 * kx(r2)
    vb2 = polar(vc, alc) + out.W3 * kx(r3)
    scale = va + vc + abs(out.W2) * rz2 + abs(out.W3) * rz3
    t = tol(bound, abs(fi2) + abs(fi3) + abs(ala) + abs(alc), 1.0)
    return worst(rel(vb1 - vb2, scale) / t, rel(polar(out.VB, out.ALB) - vb1, scale) / t,
                 abs(out.VBA - abs(out.W2) * rz2) / (scale * t),
                 rel(polar(out.VBA, out.ALBA) - out.W2 * kx(r2), scale) / t)


def gen_duskr1(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True), length(rng),
            angle(rng, True), length(rng), angle(rng, True), float(rng.standard_normal()),
            float(rng.standard_normal())]


def chk_duskr1(args, out, bound):
    aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3 = args
    r2, r3 = vec(rz2, fi2), vec(rz3, fi3)
    ab1 = polar(aa, ba) + out.E2 * kx(r2) - w2**2 * r2
    ab2 = polar(ac, bc) + out.E3 * kx(r3) - w3**2 * r3
    scale = aa + ac + w2**2 * rz2 + w3**2 * rz3 + abs(out.E2) * rz2 + abs(out.E3) * rz3
    t = tol(bound, abs(fi2) + abs(fi3) + abs(ba) + abs(bc), 1.0)
    return worst(rel(ab1 - ab2, scale) / t, rel(polar(out.AB, out.BB) - ab1, scale) / t)


def gen_dknma1(rng):
    A, B, C, rz2, rz3, side, L = _kind1(rng)
    V = length(rng)
    va, vc = rng.standard_normal(2) * V, rng.standard_normal(2) * V
    aa, ac = rng.standard_normal(2) * V * V / L, rng.standard_normal(2) * V * V / L
    return [A[0], A[1], C[0], C[1], rz2, rz3, float(np.hypot(*va)), math.atan2(va[1], va[0]),
            float(np.hypot(*vc)), math.atan2(vc[1], vc[0]), float(np.hypot(*aa)),
            math.atan2(aa[1], aa[0]), float(np.hypot(*ac)), math.atan2(ac[1], ac[0]), side,
            0.0]


def _dknma1_at(args, t):
    xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p, an = args
    A = moved(np.array([xa, ya]), polar(va, ala), polar(aa, ba), t)
    C = moved(np.array([xc, yc]), polar(vc, alc), polar(ac, bc), t)
    VA = polar(va, ala) + polar(aa, ba) * t
    VC = polar(vc, alc) + polar(ac, bc) * t
    return [A[0], A[1], C[0], C[1], rz2, rz3, float(np.hypot(*VA)), math.atan2(VA[1], VA[0]),
            float(np.hypot(*VC)), math.atan2(VC[1], VC[0]), aa, ba, ac, bc, p, an]


def chk_dknma1(args, out, bound):
    xa, ya, xc, yc, rz2, rz3, va, ala, vc, alc, aa, ba, ac, bc, p, an = args
    A, C, B = np.array([xa, ya]), np.array([xc, yc]), np.array([out.XB, out.YB])
    L = max(rz2, rz3)
    t = tol(bound, max(np.abs(A).max(), np.abs(C).max()), min(rz2, rz3))
    left = cross(C - A, B - A) > 0
    side_ok = 0.0 if left == (p > 0) or abs(cross(C - A, B - A)) <= t * L * L * 4 \
        else math.inf
    v = [abs(np.hypot(*(B - A)) - rz2) / (L * t), abs(np.hypot(*(B - C)) - rz3) / (L * t),
         side_ok]
    V = max(va, vc, out.VB, 1e-300)
    h = 1e-4 * timescale([rz2, rz3], [va, vc])
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [o.XB - out.XB, o.YB - out.YB])(
        quiet("DKNMA1", *_dknma1_at(args, s))), h, polar(out.VB, out.ALB), V, bound,
        np.abs(np.r_[A, C]).max()))
    W = max(abs(out.W2), abs(out.W3), V / min(rz2, rz3))
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [math.remainder(o.FI2 - out.FI2, 2 * PI),
                               math.remainder(o.FI3 - out.FI3, 2 * PI)])(
        quiet("DKNMA1", *_dknma1_at(args, s))), h, [out.W2, out.W3], W, bound,
        np.abs(np.r_[A, C]).max() / min(rz2, rz3)))
    if an != 1.0:
        Aa = max(aa, ac, out.AB, W * W * L)
        v.append(fd_vs(lambda s: (lambda o: None if o is None else
                                  list(polar(o.VB, o.ALB)))(
            quiet("DKNMA1", *_dknma1_at(args, s))), h, polar(out.AB, out.BB), Aa, bound,
            np.abs(np.r_[A, C]).max() * W))
    return worst(*v)


# ---- kind 2 (RRP) ----------------------------------------------------------------------

def _kind2(rng):
    ox, oy = offset(rng)
    L = length(rng)
    fim = angle(rng)
    K = np.array([ox, oy])
    em, n = e(fim), kx(e(fim))
    rz3, eta = L * length(rng, -1, 1), angle(rng)
    off = rz3 * math.sin(eta)
    B = K + rng.uniform(-3, 3) * L * em + off * n
    rz2 = L * length(rng, -1, 1)
    A = B + vec(rz2, angle(rng))
    return A, B, K, fim, rz2, rz3, eta, L


def gen_dprm2(rng):
    A, B, K, fim, rz2, rz3, eta, L = _kind2(rng)
    return [A[0], A[1], K[0], K[1], fim, rz2, rz3, eta]


def chk_dprm2(args, out, bound):
    xa, ya, xk, yk, fim, rz2, rz3, t_ = args
    A, K, B = np.array([xa, ya]), np.array([xk, yk]), np.array([out.XB, out.YB])
    n = kx(e(fim))
    so = (A - K) @ n
    off = math.copysign(1.0, so) * rz3 * math.sin(t_)
    L = max(rz2, abs(rz3))
    t = tol(bound, np.abs(np.r_[A, K]).max() + abs(fim) * np.hypot(*(A - K)), L)
    foot = A - so * n
    ahead = (B - foot) @ e(fim)
    return worst(abs(np.hypot(*(B - A)) - rz2) / (L * t), abs((B - K) @ n - off) / (L * t),
                 0.0 if ahead >= -t * L * 4 else math.inf)


def gen_dskor2(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True), length(rng),
            angle(rng, True), angle(rng, True)]


def chk_dskor2(args, out, bound):
    va, ala, vbm, albm, rz2, fi2, fim = args
    r2 = vec(rz2, fi2)
    vb1 = polar(va, ala) + out.W2 * kx(r2)
    vb2 = polar(vbm, albm) + polar(out.VBBM, out.ALBBM)
    scale = va + vbm + abs(out.W2) * rz2 + out.VBBM
    t = tol(bound, abs(fi2) + abs(fim) + abs(ala) + abs(albm), 1.0)
    return worst(rel(vb1 - vb2, scale) / t, rel(polar(out.VB, out.ALB) - vb1, scale) / t,
                 unit_dir_ok(out.ALBBM, fim) / t if out.VBBM > t * scale else 0.0)


def gen_duskr2(rng):
    return [length(rng), angle(rng, True), length(rng), angle(rng, True), length(rng),
            angle(rng, True), length(rng), angle(rng, True), float(rng.standard_normal()),
            angle(rng, True)]


def chk_duskr2(args, out, bound):
    aa, ba, abm, bvm, abk, bvk, rz2, fi2, w2, fim = args
    r2 = vec(rz2, fi2)
    ab1 = polar(aa, ba) + out.E2 * kx(r2) - w2**2 * r2
    ab2 = polar(abm, bvm) + polar(abk, bvk) + polar(out.ABVM, out.BVBM)
    scale = aa + abm + abk + w2**2 * rz2 + abs(out.E2) * rz2 + out.ABVM
    t = tol(bound, abs(fi2) + abs(fim) + abs(ba) + abs(bvm) + abs(bvk), 1.0)
    return worst(rel(ab1 - ab2, scale) / t, rel(polar(out.AB, out.BB) - ab1, scale) / t,
                 unit_dir_ok(out.BVBM, fim) / t if out.ABVM > t * scale else 0.0)


def gen_dknma2(rng):
    A, B, K, fim, rz2, rz3, eta, L = _kind2(rng)
    n = kx(e(fim))
    # DKNMA2 offsets B along the LEFT normal: B's offset is rz3 sin(eta) whatever A's side;
    # P: +1 B ahead of the foot of A along FIM
    foot = A - ((A - K) @ n) * n
    p = 1.0 if (B - foot) @ e(fim) >= 0 else -1.0
    V = length(rng)
    va, aa = rng.standard_normal(2) * V, rng.standard_normal(2) * V * V / L
    return [A[0], A[1], K[0], K[1], fim, rz2, rz3, eta, float(np.hypot(*va)),
            math.atan2(va[1], va[0]), 0.0, 0.0, 0.0, float(np.hypot(*aa)),
            math.atan2(aa[1], aa[0]), 0.0, 0.0, p, 0.0]


def _dknma2_at(args, t):
    a = list(args)
    A = moved(np.array(a[0:2]), polar(a[8], a[9]), polar(a[13], a[14]), t)
    VA = polar(a[8], a[9]) + polar(a[13], a[14]) * t
    a[0], a[1] = A
    a[8], a[9] = float(np.hypot(*VA)), math.atan2(VA[1], VA[0])
    return a


def chk_dknma2(args, out, bound):
    xa, ya, xk, yk, fim, rz2, rz3, eta, va, ala = args[:10]
    aa, ba, p, an = args[13], args[14], args[17], args[18]
    A, K, B = np.array([xa, ya]), np.array([xk, yk]), np.array([out.XB, out.YB])
    n = kx(e(fim))
    L = max(rz2, abs(rz3))
    t = tol(bound, np.abs(np.r_[A, K]).max() + abs(fim) * np.hypot(*(A - K)), L)
    foot = A - ((A - K) @ n) * n
    ahead = (B - foot) @ e(fim) * p
    v = [abs(np.hypot(*(B - A)) - rz2) / (L * t),
         abs((B - K) @ n - rz3 * math.sin(eta)) / (L * t),
         0.0 if ahead >= -t * L * 4 else math.inf]
    h = 1e-4 * timescale([rz2], [va])
    V = max(va, out.VB, 1e-300)
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [o.XB - out.XB, o.YB - out.YB])(
        quiet("DKNMA2", *_dknma2_at(args, s))), h, polar(out.VB, out.ALB), V, bound,
        np.abs(np.r_[A, K]).max()))
    W = max(abs(out.W2), V / rz2)
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [math.remainder(o.FI2 - out.FI2, 2 * PI)])(
        quiet("DKNMA2", *_dknma2_at(args, s))), h, [out.W2], W, bound,
        np.abs(np.r_[A, K]).max() / rz2))
    if an != 1.0:
        v.append(fd_vs(lambda s: (lambda o: None if o is None else [o.W2])(
            quiet("DKNMA2", *_dknma2_at(args, s))), h, [out.E2],
            max(abs(out.E2), W * W, aa / rz2), bound, np.abs(np.r_[A, K]).max() * W / rz2))
    return worst(*v)


# ---- kind 3 (RPR) ----------------------------------------------------------------------

def _kind3(rng):
    ox, oy = offset(rng)
    L = length(rng)
    C = np.array([ox, oy])
    A = C + vec(L, angle(rng))
    fica = math.atan2(*(A - C)[::-1])
    h = L * rng.uniform(-0.95, 0.95)                 # signed distance of A from the axis
    return A, C, h, fica, L


def gen_dprm3(rng):
    A, C, h, fica, L = _kind3(rng)
    t = float(rng.uniform(0.2, PI - 0.2))
    rz2 = abs(h) / math.sin(t)
    p = -1.0 if h > 0 else 1.0                     # P = -1: A on the left of the axis
    return [A[0], A[1], C[0], C[1], rz2, t, p]


def chk_dprm3(args, out, bound):
    xa, ya, xc, yc, rz2, t_, p = args
    A, C = np.array([xa, ya]), np.array([xc, yc])
    L = np.hypot(*(A - C))
    t = tol(bound, np.abs(np.r_[A, C]).max(), L)
    cr = cross(e(out.FI3), A - C)                # signed distance of A from the axis
    return worst(abs(out.RZAC - L) / (L * t), angdiff(out.FICA, math.atan2(*(A - C)[::-1])) / t,
                 abs(abs(cr) - abs(rz2 * math.sin(t_))) / (L * t),
                 0.0 if (cr > 0) == (p < 0) or abs(cr) <= 4 * t * L else math.inf)


def gen_dskor3(rng):
    A, C, h, fica, L = _kind3(rng)
    fi3 = fica + math.asin(h / L)
    V = length(rng)
    return [A[0], A[1], C[0], C[1], V * rng.uniform(0, 1), angle(rng, True),
            V * rng.uniform(0, 1), angle(rng, True), fi3]


def chk_dskor3(args, out, bound):
    xa, ya, xc, yc, va, ala, vc, alc, fi3 = args
    A, C = np.array([xa, ya]), np.array([xc, yc])
    r = A - C
    va3_1 = polar(vc, alc) + out.W3 * kx(r)
    va3_2 = polar(va, ala) + polar(out.VA3A, out.ALA3A)
    L = np.hypot(*r)
    scale = va + vc + abs(out.W3) * L + out.VA3A
    t = tol(bound, np.abs(np.r_[A, C]).max() / L + abs(fi3) + abs(ala) + abs(alc), 1.0)
    return worst(rel(va3_1 - va3_2, scale) / t, rel(polar(out.VA3, out.ALA3) - va3_2, scale) / t,
                 unit_dir_ok(out.ALA3A, fi3) / t if out.VA3A > t * scale else 0.0)


def gen_duskr3(rng):
    L = length(rng)
    return [length(rng), angle(rng, True), length(rng), angle(rng, True), angle(rng, True),
            float(rng.standard_normal()), L, angle(rng, True), length(rng), angle(rng, True)]


def chk_duskr3(args, out, bound):
    aa, ba, ac, bc, fi3, w3, rzac, fica, aak, bak = args
    r = vec(rzac, fica)
    a1 = polar(ac, bc) + out.E3 * kx(r) - w3**2 * r
    a2 = polar(aa, ba) + polar(aak, bak) + polar(out.AA3AR, out.BA3AR)
    scale = aa + ac + aak + w3**2 * rzac + abs(out.E3) * rzac + out.AA3AR
    t = tol(bound, abs(fi3) + abs(fica) + abs(ba) + abs(bc) + abs(bak), 1.0)
    return worst(rel(a1 - a2, scale) / t, rel(polar(out.AA3, out.BA3) - a1, scale) / t,
                 unit_dir_ok(out.BA3AR, fi3) / t if out.AA3AR > t * scale else 0.0)


def gen_dknma3(rng):
    A, C, h, fica, L = _kind3(rng)
    eta = float(rng.uniform(0.2, PI - 0.2))
    rz2 = abs(h) / math.sin(eta)
    V = length(rng)
    va, aa = rng.standard_normal(2) * V, rng.standard_normal(2) * V * V / L
    vc, ac = rng.standard_normal(2) * V, rng.standard_normal(2) * V * V / L
    return [A[0], A[1], C[0], C[1], rz2, eta, float(np.hypot(*va)), math.atan2(va[1], va[0]),
            float(np.hypot(*vc)), math.atan2(vc[1], vc[0]), float(np.hypot(*aa)),
            math.atan2(aa[1], aa[0]), float(np.hypot(*ac)), math.atan2(ac[1], ac[0]),
            float(rng.choice([-1.0, 1.0])), 0.0]


def _dknma3_at(args, t):
    a = list(args)
    for i, j in ((0, 6), (2, 8)):
        P = moved(np.array(a[i:i + 2]), polar(a[j], a[j + 1]), polar(a[j + 4], a[j + 5]), t)
        Vv = polar(a[j], a[j + 1]) + polar(a[j + 4], a[j + 5]) * t
        a[i], a[i + 1] = P
        a[j], a[j + 1] = float(np.hypot(*Vv)), math.atan2(Vv[1], Vv[0])
    return a


def chk_dknma3(args, out, bound):
    xa, ya, xc, yc, rz2, eta, va, ala, vc, alc, aa, ba, ac, bc, p, an = args
    A, C, B = np.array([xa, ya]), np.array([xc, yc]), np.array([out.XB, out.YB])
    L = np.hypot(*(A - C))
    t = tol(bound, np.abs(np.r_[A, C]).max(), min(L, rz2))
    ax = e(out.FI3)
    # B on the axis of link 3 through C, AB = RZ2, angle between B->A and the axis = ETA
    ang = math.acos(max(-1, min(1, ((A - B) @ -ax) / rz2)))
    v = [abs(cross(ax, B - C)) / (max(L, rz2) * t), abs(np.hypot(*(A - B)) - rz2) /
         (max(L, rz2) * t), abs(ang - eta) / t * 1e-2]
    h = 1e-4 * timescale([L, rz2], [va, vc])
    V = max(va, vc, 1e-300)
    W = max(abs(out.W3), V / L)
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [math.remainder(o.FI3 - out.FI3, 2 * PI)])(
        quiet("DKNMA3", *_dknma3_at(args, s))), h, [out.W3], W, bound,
        np.abs(np.r_[A, C]).max() / min(L, rz2)))
    # the velocity of A3 (link 3's point at A) = v_C + W3 k x CA
    v.append(rel(polar(out.VA3, out.ALA3) - polar(vc, alc) - out.W3 * kx(A - C),
                 V + W * L) / t)
    if an != 1.0:
        v.append(fd_vs(lambda s: (lambda o: None if o is None else [o.W3])(
            quiet("DKNMA3", *_dknma3_at(args, s))), h, [out.E3],
            max(abs(out.E3), W * W, (aa + ac) / L), bound,
            np.abs(np.r_[A, C]).max() * W / min(L, rz2)))
    return worst(*v)


# ---- kind 4 (PRP) ----------------------------------------------------------------------

def _kind4(rng):
    ox, oy = offset(rng)
    L = length(rng)
    B = np.array([ox, oy]) + rng.uniform(-1, 1, 2) * L
    fim = angle(rng)
    fin = fim + math.copysign(rng.uniform(0.05, PI - 0.05), rng.uniform(-1, 1))
    rz2, t2, rz3, t3 = L * length(rng, -1, 1), angle(rng), L * length(rng, -1, 1), angle(rng)
    A = B - rz2 * math.sin(t2) * kx(e(fim)) + rng.uniform(-2, 2) * L * e(fim)
    C = B - rz3 * math.sin(t3) * kx(e(fin)) + rng.uniform(-2, 2) * L * e(fin)
    return A, C, fim, fin, rz2, t2, rz3, t3, L


def gen_dprm4(rng):
    A, C, fim, fin, rz2, t2, rz3, t3, L = _kind4(rng)
    VM = A + rng.uniform(-2, 2, 2) * L
    VN = C + rng.uniform(-2, 2, 2) * L
    return [VM[0], VM[1], A[0], A[1], fim, VN[0], VN[1], C[0], C[1], fin, rz2, t2, rz3, t3]


def chk_dprm4(args, out, bound):
    xvm, yvm, xa, ya, fim, xvn, yvn, xc, yc, fin, rz2, t2, rz3, t3 = args
    A, C, B = np.array([xa, ya]), np.array([xc, yc]), np.array([out.XB, out.YB])
    VM, VN = np.array([xvm, yvm]), np.array([xvn, yvn])
    L = max(np.hypot(*(B - A)), np.hypot(*(B - C)), abs(rz2), abs(rz3))
    t = tol(bound, np.abs(np.r_[A, C, VM, VN]).max(), L)
    return worst(abs((B - A) @ kx(e(fim)) - rz2 * math.sin(t2)) / (L * t),
                 abs((B - C) @ kx(e(fin)) - rz3 * math.sin(t3)) / (L * t),
                 abs(out.RVBM - np.hypot(*(B - VM))) / (L * t),
                 abs(out.RVBN - np.hypot(*(B - VN))) / (L * t),
                 angdiff(out.FIVBM, math.atan2(*(B - VM)[::-1])) * out.RVBM / (L * t),
                 angdiff(out.FIVBN, math.atan2(*(B - VN)[::-1])) * out.RVBN / (L * t),
                 0.0 if 0.0 <= out.FIVBM < 2 * PI + 1e-12 else math.inf)


def gen_dskor4(rng):
    fim = angle(rng, True)
    fin = fim + math.copysign(rng.uniform(0.05, PI - 0.05), rng.uniform(-1, 1))
    return [length(rng), angle(rng, True), fim, length(rng), angle(rng, True), fin,
            float(rng.standard_normal()), float(rng.standard_normal())]


def chk_dskor4(args, out, bound):
    rvbm, fivbm, fim, rvbn, fivbn, fin, wm, wn = args
    vb1 = wm * kx(vec(rvbm, fivbm)) + polar(out.VBBM, out.ALBBM)
    vb2 = wn * kx(vec(rvbn, fivbn)) + polar(out.VBBN, out.ALBBN)
    scale = abs(wm) * rvbm + abs(wn) * rvbn + out.VBBM + out.VBBN
    t = tol(bound, abs(fivbm) + abs(fivbn) + abs(fim) + abs(fin), 1.0)
    return worst(rel(vb1 - vb2, scale) / t, rel(polar(out.VB, out.ALB) - vb1, scale) / t,
                 unit_dir_ok(out.ALBBM, fim) / t if out.VBBM > t * scale else 0.0,
                 unit_dir_ok(out.ALBBN, fin) / t if out.VBBN > t * scale else 0.0)


def gen_duskr4(rng):
    fim = angle(rng, True)
    fin = fim + math.copysign(rng.uniform(0.05, PI - 0.05), rng.uniform(-1, 1))
    return [length(rng), angle(rng, True), fim, length(rng), angle(rng, True), fin,
            float(rng.standard_normal()), float(rng.standard_normal()),
            float(rng.standard_normal()), float(rng.standard_normal()),
            length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_duskr4(args, out, bound):
    rvbm, fivbm, fim, rvbn, fivbn, fin, wm, em, wn, en, abmk, bbmk, abnk, bbnk = args
    rm, rn = vec(rvbm, fivbm), vec(rvbn, fivbn)
    a1 = em * kx(rm) - wm**2 * rm + polar(abmk, bbmk) + polar(out.ABBMR, out.BBBMR)
    a2 = en * kx(rn) - wn**2 * rn + polar(abnk, bbnk) + polar(out.ABBNR, out.BBBNR)
    scale = (abs(em) + wm**2) * rvbm + (abs(en) + wn**2) * rvbn + abmk + abnk + \
        out.ABBMR + out.ABBNR
    t = tol(bound, abs(fivbm) + abs(fivbn) + abs(fim) + abs(fin) + abs(bbmk) + abs(bbnk), 1.0)
    return worst(rel(a1 - a2, scale) / t, rel(polar(out.AB, out.BB) - a1, scale) / t)


def gen_dknma4(rng):
    A, C, fim, fin, rz2, t2, rz3, t3, L = _kind4(rng)
    W = 1.0 / length(rng, -1, 1)
    return [fim, A[0], A[1], fin, C[0], C[1], rz2, t2, rz3, t3,
            float(rng.standard_normal() * W), float(rng.standard_normal() * W),
            float(rng.standard_normal() * W * W), float(rng.standard_normal() * W * W), 0.0]


def _dknma4_at(args, t):
    a = list(args)
    wm, wn, em, en = a[10:14]
    a[0] = a[0] + wm * t + em * t * t / 2
    a[3] = a[3] + wn * t + en * t * t / 2
    a[10], a[11] = wm + em * t, wn + en * t
    return a


def chk_dknma4(args, out, bound):
    fim, xa, ya, fin, xc, yc, rz2, t2, rz3, t3, wm, wn, em, en, an = args
    A, C, B = np.array([xa, ya]), np.array([xc, yc]), np.array([out.XB, out.YB])
    L = max(np.hypot(*(B - A)), np.hypot(*(B - C)), abs(rz2), abs(rz3))
    t = tol(bound, np.abs(np.r_[A, C]).max(), L)
    v = [abs((B - A) @ kx(e(fim)) - rz2 * math.sin(t2)) / (L * t),
         abs((B - C) @ kx(e(fin)) - rz3 * math.sin(t3)) / (L * t)]
    h = 1e-4 / max(abs(wm), abs(wn), 1e-300)
    V = max(out.VB, (abs(wm) + abs(wn)) * L)
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [o.XB - out.XB, o.YB - out.YB])(
        quiet("DKNMA4", *_dknma4_at(args, s))), h, polar(out.VB, out.ALB), V, bound,
        np.abs(np.r_[A, C]).max()))
    if an != 1.0:
        v.append(fd_vs(lambda s: (lambda o: None if o is None else list(polar(o.VB, o.ALB)))(
            quiet("DKNMA4", *_dknma4_at(args, s))), h, polar(out.AB, out.BB),
            max(out.AB, V * max(abs(wm), abs(wn)), (abs(em) + abs(en)) * L), bound,
            np.abs(np.r_[A, C]).max() * max(abs(wm), abs(wn))))
    return worst(*v)


# ---- kind 5 (RPP) ----------------------------------------------------------------------

def gen_dprm5(rng):
    ox, oy = offset(rng)
    L = length(rng)
    t2 = math.copysign(10.0 ** rng.uniform(-8, 0.5), rng.uniform(-1, 1))
    return [ox, oy, angle(rng, True), ox + rng.uniform(-1, 1) * L, oy + rng.uniform(-1, 1) * L,
            t2]


def chk_dprm5(args, out, bound):
    xa, ya, fim, xc, yc, t2 = args
    A, C = np.array([xa, ya]), np.array([xc, yc])
    c = A + out.S2 * e(fim) + out.S3 * e(fim + t2)
    scale = abs(out.S2) + abs(out.S3)
    t = tol(bound, np.abs(np.r_[A, C]).max(), max(scale, 1e-300)) * (1 + abs(fim))
    return worst(rel(c - C, scale) / t, rel(np.array([out.XK, out.YK]) - A - out.S2 * e(fim),
                                            scale) / t)


def gen_dskor5(rng):
    ox, oy = offset(rng)
    L = length(rng)
    t2 = math.copysign(10.0 ** rng.uniform(-8, 0.5), rng.uniform(-1, 1))
    return [ox + rng.uniform(-1, 1) * L, oy + rng.uniform(-1, 1) * L, ox, oy, angle(rng, True),
            t2, float(rng.standard_normal()), length(rng), angle(rng, True)]


def chk_dskor5(args, out, bound):
    xc3, yc3, xvm, yvm, fim, t2, wm, vc3, alc3 = args
    r = np.array([xc3 - xvm, yc3 - yvm])
    v1 = polar(vc3, alc3) + polar(out.VC2C3, out.ALC2C3)
    v2 = wm * kx(r) + polar(out.VC2CM, out.ALC2CM)
    scale = vc3 + abs(wm) * np.hypot(*r) + out.VC2C3 + out.VC2CM
    t = tol(bound, abs(fim) + abs(alc3), 1.0)
    return worst(rel(v1 - v2, scale) / t, rel(polar(out.VC2, out.ALC2) - v1, scale) / t,
                 unit_dir_ok(out.ALC2CM, fim) / t if out.VC2CM > t * scale else 0.0)


def gen_duskr5(rng):
    ox, oy = offset(rng)
    L = length(rng)
    t2 = math.copysign(10.0 ** rng.uniform(-8, 0.5), rng.uniform(-1, 1))
    return [ox + rng.uniform(-1, 1) * L, oy + rng.uniform(-1, 1) * L, ox, oy, angle(rng, True),
            float(rng.standard_normal()), float(rng.standard_normal()), t2, length(rng),
            angle(rng, True), length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_duskr5(args, out, bound):
    xc3, yc3, xvm, yvm, fim, wm, em, t2, ac3, bc3, a2mk, b2mk, a23k, b23k = args
    r = np.array([xc3 - xvm, yc3 - yvm])
    a1 = polar(ac3, bc3) + polar(a23k, b23k) + polar(out.AC2C3R, out.BC2C3R)
    a2 = em * kx(r) - wm**2 * r + polar(a2mk, b2mk) + polar(out.AC2CMR, out.BC2CMR)
    scale = ac3 + a23k + a2mk + (abs(em) + wm**2) * np.hypot(*r) + out.AC2C3R + out.AC2CMR
    t = tol(bound, abs(fim) + abs(bc3) + abs(b2mk) + abs(b23k), 1.0)
    return worst(rel(a1 - a2, scale) / t, rel(polar(out.AC2, out.BC2) - a1, scale) / t)


def gen_dknma5(rng):
    ox, oy = offset(rng)
    L = length(rng)
    t2 = math.copysign(10.0 ** rng.uniform(-8, 0.5), rng.uniform(-1, 1))
    return [ox, oy, angle(rng, True), ox + rng.uniform(-1, 1) * L, oy + rng.uniform(-1, 1) * L,
            L, t2, 0.0, ox + rng.uniform(-1, 1) * L, oy + rng.uniform(-1, 1) * L,
            float(rng.standard_normal()), float(rng.standard_normal()), length(rng),
            angle(rng, True), length(rng), angle(rng, True), 0.0]


def chk_dknma5(args, out, bound):
    xa, ya, fim, xc, yc, rz3, eta2, eta3, xr, yr, wm, em, vc3, alc3, ac3, bc3, an = args
    r = np.array([xc - xr, yc - yr])
    # velocities: v_C2 = v_C3 + v_C2C3 = w_M x RC + v_C2CM
    v1 = polar(vc3, alc3) + polar(out.VC2C3, out.ALC2C3)
    v2 = wm * kx(r) + polar(out.VC2CM, out.ALC2CM)
    sv = vc3 + abs(wm) * np.hypot(*r) + out.VC2C3 + out.VC2CM
    t = tol(bound, abs(fim) + abs(alc3), 1.0)
    v = [rel(v1 - v2, sv) / t, rel(polar(out.VC, out.ALC) - v2, sv) / t,
         unit_dir_ok(out.ALC2C3, fim + eta2) / t if out.VC2C3 > t * sv else 0.0]
    if an != 1.0:
        # accelerations, with the Coriolis terms 2 w_M x v_rel of both relative motions
        k1 = 2 * wm * kx(polar(out.VC2C3, out.ALC2C3))
        k2 = 2 * wm * kx(polar(out.VC2CM, out.ALC2CM))
        a1 = polar(ac3, bc3) + k1 + polar(out.AC2C3R, out.BC2C3R)
        a2 = em * kx(r) - wm**2 * r + k2 + polar(out.AC2CMR, out.BC2CMR)
        sa = ac3 + (abs(em) + wm**2) * np.hypot(*r) + 2 * abs(wm) * sv + out.AC2C3R + \
            out.AC2CMR
        ta = tol(bound, abs(fim) + abs(bc3), 1.0)
        v += [rel(a1 - a2, sa) / ta, rel(polar(out.AC, out.BC) - a2, sa) / ta]
    return worst(*v)


KINEMATICS = {
    "DPRM1": (gen_dprm1, chk_dprm1), "DSKOR1": (gen_dskor1, chk_dskor1),
    "DUSKR1": (gen_duskr1, chk_duskr1), "DKNMA1": (gen_dknma1, chk_dknma1),
    "DPRM2": (gen_dprm2, chk_dprm2), "DSKOR2": (gen_dskor2, chk_dskor2),
    "DUSKR2": (gen_duskr2, chk_duskr2), "DKNMA2": (gen_dknma2, chk_dknma2),
    "DPRM3": (gen_dprm3, chk_dprm3), "DSKOR3": (gen_dskor3, chk_dskor3),
    "DUSKR3": (gen_duskr3, chk_duskr3), "DKNMA3": (gen_dknma3, chk_dknma3),
    "DPRM4": (gen_dprm4, chk_dprm4), "DSKOR4": (gen_dskor4, chk_dskor4),
    "DUSKR4": (gen_duskr4, chk_duskr4), "DKNMA4": (gen_dknma4, chk_dknma4),
    "DPRM5": (gen_dprm5, chk_dprm5), "DSKOR5": (gen_dskor5, chk_dskor5),
    "DUSKR5": (gen_duskr5, chk_duskr5), "DKNMA5": (gen_dknma5, chk_dknma5),
}

ROUTINES = []
CASES = {}


def _register(name, gen, chk):
    ROUTINES.append(name)
    CASES[name] = (gen, chk)


_register("GELG", gen_gelg, chk_gelg)
_register("DINTGR", gen_dintgr, chk_dintgr)
_register("DFRNCL", gen_dfrncl, chk_dfrncl)
_register("DUGL1", gen_points, chk_dugl12(0.0, 2 * PI))
_register("DUGL2", gen_points, chk_dugl12(-PI, PI))
_register("DUGL3", gen_dugl34, chk_dugl3)
_register("DUGL4", gen_dugl34, chk_dugl4)
_register("DUGL5", gen_dugl5, chk_dugl5)
_register("DUGOL", gen_dugol, chk_dugol)
_register("DMOMNT", gen_dmomnt, chk_dmomnt)
_register("DOMEGA", gen_domega, chk_domega)
_register("DVKT", gen_points, chk_dvkt)
_register("DSMVKT", gen_dsmvkt, chk_dsmvkt)
_register("DSNTZR", gen_dsntzr, chk_dsntzr)
_register("DSNTZ1", gen_dsntz1, chk_dsntz1)
_register("DSNTZ2", gen_dsntz2, chk_dsntz2)
_register("DSNTZ3", gen_dsntz3, chk_dsntz3)
_register("DSNTZK", gen_dsntzk, chk_dsntzk)
for _name in ("DPRM1", "DPRM2", "DPRM3", "DPRM4", "DPRM5", "DSKOR1", "DSKOR2", "DSKOR3",
              "DSKOR4", "DSKOR5", "DUSKR1", "DUSKR2", "DUSKR3", "DUSKR4", "DUSKR5",
              "DKNMA1", "DKNMA2", "DKNMA3", "DKNMA4", "DKNMA5"):
    _register(_name, *KINEMATICS[_name])
