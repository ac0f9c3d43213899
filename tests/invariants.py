"""Random inputs and routine-independent invariants for every book routine, chapters 2-8,
shared by tests/test_fuzz.py (Hypothesis, bounded) and benchmarks/fuzz.py (the long
campaign).  Each section states its ranges; the paragraph below is chapters 2-4's.

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
    r = float(np.linalg.norm(residual))
    if scale > 0:
        return r / scale
    return 0.0 if r == 0 else math.inf


def angdiff(a, b):
    return abs((a - b + PI) % (2 * PI) - PI)


def worst(*ratios):
    """The largest violation; a NaN (a check that could not be evaluated) counts as
    infinite, never as passing."""
    values = [float(np.max(r)) for r in ratios]
    return max([0.0] + [math.inf if math.isnan(r) else r for r in values])


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
    """A vector with components of independent magnitudes, never (0, 0)."""
    t = angle(rng)
    return [length(rng) * math.cos(t), length(rng) * math.sin(t)]


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
    """Three positions of a crank-rocker with A at the origin and D = (LO, 0): crank
    angles increasing by 0.2 to 2 rad, the rocker angles where its pin C then is."""
    A, D, l1, l2, l3, lo, B1, C1, B2, C2 = crank_rocker(rng)
    flip = -1.0 if D[0] < A[0] else 1.0             # D to the right of A (mirror in x)
    A, D = np.array([0.0, 0.0]), np.array([lo, 0.0])
    branch = cross(D - B1, C1 - B1) * flip > 0
    fi1 = [angle(rng)]
    fi1 += [fi1[0] + float(rng.uniform(0.2, 2.0))]
    fi1 += [fi1[1] + float(rng.uniform(0.2, 2.0))]
    fi3 = []
    for th in fi1:
        B = A + l1 * e(th)
        C = [c for c in circle_points(B, l2, D, l3) if (cross(D - B, c - B) > 0) == branch]
        fi3.append(math.atan2(*(C[0] - D)[::-1]))
    return [[lo] * 3, l3, fi1, fi3]


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
    # the transmission angle's extremes over the turn (a four-bar: LO the same 3 times)
    mu = fourbar_mu(0.0, 0.0, lo[0], 0.0, out.L1, out.L2, l3)
    return worst(*viol, chk_turn(mu, out))


def circle_points(p, r1, q, r2):
    """Both intersections of the circles (p, r1) and (q, r2) (touching when they miss)."""
    d = float(np.hypot(*(q - p)))
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    u = (q - p) / d
    return [p + a * u + h * kx(u), p + a * u - h * kx(u)]


def angle_at(p, q, r):
    """The angle PQR in [0, pi]."""
    u, v = p - q, r - q
    return math.atan2(abs(cross(u, v)), float(u @ v))


def crank_rocker(rng):
    """A Grashof crank-rocker with both pivots on the x axis and its two extreme
    positions: (A, D, l1, l2, l3, lo, B1, C1, B2, C2), with C1 where crank and coupler
    are stretched out (|AC1| = l1 + l2) and C2 where they fold (|AC2| = l2 - l1), on
    one assembly branch.  The coupler and the frame are 0.7 to 1.5 rocker lengths, so the
    three form a triangle with room 0.2 l3 at least; the crank is shorter than that room
    (l1 + longest < sum of the other two: the crank turns fully)."""
    l3 = length(rng, -1, 1)
    l2, lo = l3 * float(rng.uniform(0.7, 1.5)), l3 * float(rng.uniform(0.7, 1.5))
    room = l2 + l3 + lo - 2 * max(l2, l3, lo)
    l1 = float(rng.uniform(0.1, 0.9)) * min(room, 0.7 * l3)
    xd = float(rng.uniform(-2, 2))
    D = np.array([xd, 0.0])
    A = np.array([xd + float(rng.choice([-1.0, 1.0])) * lo, 0.0])
    C1 = circle_points(A, l1 + l2, D, l3)[int(rng.integers(0, 2))]
    B1 = A + l1 * (C1 - A) / np.hypot(*(C1 - A))
    branch = cross(D - B1, C1 - B1) > 0
    for C2 in circle_points(A, l2 - l1, D, l3):
        B2 = A - l1 * (C2 - A) / np.hypot(*(C2 - A))
        if (cross(D - B2, C2 - B2) > 0) == branch:
            break
    return A, D, l1, l2, l3, lo, B1, C1, B2, C2


def kw3_of(A, C1, C2):
    """The coefficient of speed change of a crank-rocker from A and its extreme positions:
    the crank turns by pi + BETA one way and pi - BETA back, BETA = angle C1AC2."""
    beta = angle_at(C1, A, C2)
    return (PI + beta) / (PI - beta), beta


def _synthesizable(rng, accept):
    """A crank-rocker that ``accept`` takes: the corrected constructions of DSNTZ1 and
    DSNTZ2 put the crank pivot A on D's side of the chord C1C2 (about 9 mechanisms in 10
    are there; the rest are drawn again)."""
    for _ in range(50):
        m = crank_rocker(rng)
        A, D, l1, l2, l3, lo, B1, C1, B2, C2 = m
        kw3, beta = kw3_of(A, C1, C2)
        S = (C1 + C2) / 2
        E = S + np.hypot(*(C2 - C1)) / 2 / math.tan(beta) * (D - S) / np.hypot(*(D - S))
        if abs(np.hypot(*(E - A)) - np.hypot(*(E - C1))) <= 1e-9 * l3 and accept(m):
            return m, kw3, beta, E
    raise AssertionError("no synthesizable crank-rocker in 50 draws")


def gen_dsntz1(rng):
    """Inputs of DSNTZ1 made from a crank-rocker it can find: its extreme rocker angles,
    its coefficient of speed change, and the Q that picks its A (the intersection of the
    circle about E with the x axis on A's side of E)."""
    m, kw3, beta, E = _synthesizable(rng, lambda m: True)
    A, D, l1, l2, l3, lo, B1, C1, B2, C2 = m
    f31, f32 = math.atan2(*(C1 - D)[::-1]), math.atan2(*(C2 - D)[::-1])
    return [kw3, f31, f32, l3, float(D[0]), 1.0 if A[0] > E[0] else -1.0]


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
    """Inputs of DSNTZ2 made from a crank-rocker (mirrored in the x axis, if need be, so
    that the rocker swings counter-clockwise from C1 to C2): its first extreme rocker
    angle, its coefficient of speed change and its transmission angles BCD at the two
    extreme positions, which satisfy the routine's PSI = BETA + GMAX - GMIN."""
    m, kw3, beta, E = _synthesizable(rng, lambda m: True)
    A, D, l1, l2, l3, lo, B1, C1, B2, C2 = m
    f31, f32 = math.atan2(*(C1 - D)[::-1]), math.atan2(*(C2 - D)[::-1])
    if math.remainder(f32 - f31, 2 * PI) < 0:
        B1, C1, B2, C2 = (v * [1.0, -1.0] for v in (B1, C1, B2, C2))
        f31 = -f31
    return [kw3, f31, l3, float(D[0]), angle_at(B1, C1, D), angle_at(B2, C2, D)]


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
    """Two positions of a crank-rocker: the crank turned clockwise by FI1 (DSNTZ3's
    sense, E-DSNTZ3-5), ALC1 normal to DC1.  Two crank angles can give one rocker angle
    (C1 = C2: no answer): if the drawn turn moves the rocker by less than 2e-3 rad, the
    turn of 0.2, 0.5, ..., 2.5 rad that moves it most is taken."""
    A, D, l1, l2, l3, lo, B1, C1, _B2, _C2 = crank_rocker(rng)
    branch = cross(D - B1, C1 - B1) > 0

    def pin(th):
        B = A + l1 * e(th)
        C = [c for c in circle_points(B, l2, D, l3) if (cross(D - B, c - B) > 0) == branch]
        return B, C[0], math.atan2(*(C[0] - D)[::-1])

    def apart(fi1):
        return abs(math.sin((pin(th1 - fi1)[2] - pin(th1)[2]) / 2))

    th1 = angle(rng)
    fi1 = float(rng.uniform(0.2, 2.5))
    if apart(fi1) < 1e-3:
        fi1 = max(np.arange(0.2, 2.51, 0.3), key=apart)
    (B1, C1, psi1), (B2, C2, _) = pin(th1), pin(th1 - fi1)
    return [*map(float, (*B1, *B2, *C1, *C2)), float(fi1), psi1 + PI / 2]


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


def timescale(lengths, speeds, accelerations=()):
    """A time over which the motion stays nearly linear: the shortest length over the
    fastest speed, and over the square root of length / acceleration (inputs nearly at
    rest but accelerating would otherwise give a step far beyond the motion's scale)."""
    L = min(lengths)
    t = L / max(max(speeds), 1e-300)
    for a in accelerations:
        if a > 0:
            t = min(t, math.sqrt(L / a))
    return t


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
    if allowed == 0.0:                        # all at rest: the derivative is exactly 0
        return 0.0 if rel(d - np.asarray(got), 1.0) == 0.0 else math.inf
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
    # the angle ABC from 1e-3 to pi - 1e-3: near-flat triangles (dead centres) with
    # digits left, never a flat one (no answer)
    gamma = 10.0 ** float(rng.uniform(-3.0, math.log10(PI / 2)))
    if rng.random() < 0.5:
        gamma = PI - gamma
    C = B + vec(rz3, math.atan2(*(A - B)[::-1]) + float(rng.choice([-1.0, 1.0])) * gamma)
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
                 rz2, angdiff(out.FI3, math.atan2(*(B - C)[::-1])) / t * min(rz2, rz3) /
                 rz3, side_ok)


def not_parallel(rng, fi):
    """A direction at least 1e-3 rad from fi and from fi + pi (links in line: the book's
    velocity and acceleration equations have no answer)."""
    return fi + float(rng.choice([-1.0, 1.0])) * float(rng.uniform(1e-3, PI - 1e-3))


def oblique(rng, fi):
    """A direction at least 1e-3 rad from fi and fi + pi, and 1e-2 from fi +- pi/2."""
    a = float(rng.uniform(1e-3, PI / 2 - 1e-2))
    return fi + float(rng.choice([-1.0, 1.0])) * (a if rng.random() < 0.5 else PI - a)


def gen_dskor1(rng):
    fi2 = angle(rng, True)
    return [length(rng), fi2, length(rng), not_parallel(rng, fi2),
            length(rng), angle(rng, True), length(rng), angle(rng, True)]


def chk_dskor1(args, out, bound):
    rz2, fi2, rz3, fi3, va, ala, vc, alc = args
    r2, r3 = vec(rz2, fi2), vec(rz3, fi3)
    vb1 = polar(va, ala) + out.W2 * kx(r2)
    vb2 = polar(vc, alc) + out.W3 * kx(r3)
    scale = va + vc + abs(out.W2) * rz2 + abs(out.W3) * rz3
    t = tol(bound, abs(fi2) + abs(fi3) + abs(ala) + abs(alc), 1.0)
    return worst(rel(polar(out.VBC, out.ALBC) - out.W3 * kx(r3), scale) / t,
                 rel(vb1 - vb2, scale) / t, rel(polar(out.VB, out.ALB) - vb1, scale) / t,
                 abs(out.VBA - abs(out.W2) * rz2) / (scale * t),
                 rel(polar(out.VBA, out.ALBA) - out.W2 * kx(r2), scale) / t)


def gen_duskr1(rng):
    fi2 = angle(rng, True)
    return [length(rng), angle(rng, True), length(rng), angle(rng, True), length(rng),
            fi2, length(rng), not_parallel(rng, fi2), float(rng.standard_normal()),
            float(rng.standard_normal())]


def chk_duskr1(args, out, bound):
    aa, ba, ac, bc, rz2, fi2, rz3, fi3, w2, w3 = args
    r2, r3 = vec(rz2, fi2), vec(rz3, fi3)
    ab1 = polar(aa, ba) + out.E2 * kx(r2) - w2**2 * r2
    ab2 = polar(ac, bc) + out.E3 * kx(r3) - w3**2 * r3
    scale = aa + ac + w2**2 * rz2 + w3**2 * rz3 + abs(out.E2) * rz2 + abs(out.E3) * rz3
    t = tol(bound, abs(fi2) + abs(fi3) + abs(ba) + abs(bc), 1.0)
    return worst(rel(polar(out.ABAT, out.BBAT) - out.E2 * kx(r2), scale) / t,
                 rel(polar(out.ABCT, out.BBCT) - out.E3 * kx(r3), scale) / t,
                 rel(ab1 - ab2, scale) / t, rel(polar(out.AB, out.BB) - ab1, scale) / t)


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
    # the link directions, and the relative motions of B about A and about C: velocity
    # W x r, normal acceleration W^2 r, tangential E x r (r = A->B, C->B)
    r2, r3 = B - A, B - C
    s = min(rz2, rz3)
    v += [angdiff(out.FI2, math.atan2(*r2[::-1])) * s / rz2 / t,
          angdiff(out.FI3, math.atan2(*r3[::-1])) * s / rz3 / t]
    Vr = max(abs(out.W2) * rz2, abs(out.W3) * rz3, 1e-300)
    v += [rel(polar(out.VBA, out.ALBA) - out.W2 * kx(r2), Vr) / t,
          rel(polar(out.VBC, out.ALBC) - out.W3 * kx(r3), Vr) / t]
    if an != 1.0:
        Ar = max(out.W2**2 * rz2 + abs(out.E2) * rz2, out.W3**2 * rz3 + abs(out.E3) * rz3,
                 1e-300)
        v += [abs(out.ABAN - out.W2**2 * rz2) / (Ar * t),
              abs(out.ABCN - out.W3**2 * rz3) / (Ar * t),
              rel(polar(out.ABAT, out.BBAT) - out.E2 * kx(r2), Ar) / t,
              rel(polar(out.ABCT, out.BBCT) - out.E3 * kx(r3), Ar) / t]
    V = max(va, vc, out.VB, 1e-300)
    h = 1e-4 * timescale([rz2, rz3], [va, vc], [aa, ac])
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
    # AB at least 1e-3 rad from the guide's direction (along it: the dead centre) and
    # 1e-2 from its normal (AB normal to the guide: the two branches meet, B moves as a
    # square root of A)
    A = B + vec(rz2, oblique(rng, fim))
    return A, B, K, fim, rz2, rz3, eta, L


def gen_dprm2(rng):
    """DPRM2 puts B RZ3 sin(T) from the guide on A's side (the other side when it is
    negative): draw the side of A, B at that offset, then A at RZ2 from B on its side,
    at least 5% of RZ2 from the axis (so that its side is not a rounding)."""
    ox, oy = offset(rng)
    L = length(rng)
    fim = angle(rng)
    K = np.array([ox, oy])
    em, n = e(fim), kx(e(fim))
    rz2, rz3, eta = L * length(rng, -1, 1), L * length(rng, -1, 1), angle(rng)
    off = rz3 * math.sin(eta)
    if off <= -0.8 * rz2:              # B that far on the other side: A cannot reach it
        eta = -eta
        off = -off
    side = float(rng.choice([-1.0, 1.0]))
    B = K + float(rng.uniform(-3, 3)) * L * em + side * off * n
    # A = B + rz2 e(fim + side*phi), A's offset side*(off + rz2 sin phi) with sin phi above
    # -off/rz2 (+ 5%) and below 0.95 (AB normal to the guide: the two branches meet, B
    # moves as a square root of A, and a rounding decides whether it reaches)
    lo = max(-1.0, -off / rz2) + 0.05
    phi = math.asin(float(rng.uniform(lo, 0.95)))
    if rng.random() < 0.5:
        phi = PI - phi
    A = B + rz2 * e(fim + side * phi)
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
    return worst(angdiff(out.FI2, math.atan2(*(B - A)[::-1])) * rz2 / (L * t),
                 abs(np.hypot(*(B - A)) - rz2) / (L * t), abs((B - K) @ n - off) / (L * t),
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
    return worst(rel(polar(out.VBA, out.ALBA) - out.W2 * kx(r2), scale) / t,
                 rel(vb1 - vb2, scale) / t, rel(polar(out.VB, out.ALB) - vb1, scale) / t,
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
    return worst(rel(polar(out.ABAT, out.VBAT) - out.E2 * kx(r2), scale) / t,
                 rel(ab1 - ab2, scale) / t, rel(polar(out.AB, out.BB) - ab1, scale) / t,
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
    # B about A: the direction of AB, the relative velocity W2 x r and v_B = v_A + W2 x r;
    # the normal and tangential accelerations and a_B = a_A - W2^2 r + E2 x r
    r2 = B - A
    t2 = tol(bound, np.abs(np.r_[A, K]).max() + abs(fim) * np.hypot(*(A - K)), rz2)
    Vr = max(abs(out.W2) * rz2, va, 1e-300)
    v += [angdiff(out.FI2, math.atan2(*r2[::-1])) / t2,
          rel(polar(out.VBA, out.ALBA) - out.W2 * kx(r2), Vr) / t2,
          rel(polar(out.VB, out.ALB) - polar(va, ala) - out.W2 * kx(r2), Vr) / t2]
    if an != 1.0:
        Ar = max(out.W2**2 * rz2 + abs(out.E2) * rz2 + aa, 1e-300)
        v += [abs(out.ABAN - out.W2**2 * rz2) / (Ar * t2),
              rel(polar(out.ABAT, out.BBAT) - out.E2 * kx(r2), Ar) / t2,
              rel(polar(out.AB, out.BB) - polar(aa, ba) + out.W2**2 * r2
                  - out.E2 * kx(r2), Ar) / t2]
    h = 1e-4 * timescale([rz2], [va], [aa])
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
    return worst(rel(polar(out.VA3C, out.ALA3C) - out.W3 * kx(r), scale) / t,
                 rel(va3_1 - va3_2, scale) / t, rel(polar(out.VA3, out.ALA3) - va3_2, scale) / t,
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
    return worst(rel(polar(out.AA3CT, out.BA3CT) - out.E3 * kx(r), scale) / t,
                 rel(a1 - a2, scale) / t, rel(polar(out.AA3, out.BA3) - a1, scale) / t,
                 unit_dir_ok(out.BA3AR, fi3) / t if out.AA3AR > t * scale else 0.0)


def gen_dknma3(rng):
    A, C, h, fica, L = _kind3(rng)
    eta = float(rng.uniform(0.2, PI - 0.2))
    if eta > PI / 2:
        # angle ABC obtuse: AC is the longest side, AB = |h|/sin(eta) < AC = L, i.e.
        # |h| < L sin(eta) (E-DKNMA3-4: otherwise there is no triangle)
        h *= math.sin(eta)
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
    lengths = [L, rz2] if rz2 > 0 else [L]          # RZ2 = 0: A itself is on the axis
    t = tol(bound, np.abs(np.r_[A, C]).max(), min(lengths))
    ax = e(out.FI3)
    # B on the axis of link 3 through C, AB = RZ2, angle between B->A and the axis = ETA
    ang = math.acos(max(-1, min(1, ((A - B) @ -ax) / rz2))) if rz2 > 0 else eta
    v = [abs(cross(ax, B - C)) / (max(L, rz2) * t), abs(np.hypot(*(A - B)) - rz2) /
         (max(L, rz2) * t), abs(ang - eta) / t * 1e-2]
    h = 1e-4 * timescale(lengths, [va, vc], [aa, ac])
    V = max(va, vc, 1e-300)
    W = max(abs(out.W3), V / L)
    v.append(fd_vs(lambda s: (lambda o: None if o is None else
                              [math.remainder(o.FI3 - out.FI3, 2 * PI)])(
        quiet("DKNMA3", *_dknma3_at(args, s))), h, [out.W3], W, bound,
        np.abs(np.r_[A, C]).max() / min(lengths)))
    # the velocity of A3 (link 3's point at A) = v_C + W3 k x CA
    v.append(rel(polar(out.VA3, out.ALA3) - polar(vc, alc) - out.W3 * kx(A - C),
                 V + W * L) / t)
    # CB and the axis; A3 relative to C (W3 x CA) and to A (along the axis, v_A3 - v_A)
    rca = A - C
    vrel = polar(out.VA3, out.ALA3) - polar(va, ala)
    v += [abs(out.RZBC - np.hypot(*(B - C))) / (max(L, rz2) * t),
          abs(math.sin(out.FI3 - math.atan2(*(B - C)[::-1]))) * np.hypot(*(B - C)) /
          (max(L, rz2) * t),
          rel(polar(out.VAC, out.ALAC) - out.W3 * kx(rca), V + W * L) / t,
          rel(polar(out.VAR, out.ALAR) - vrel, V + W * L) / t,
          abs(cross(polar(out.VAR, out.ALAR), e(out.FI3))) / ((V + W * L) * t)]
    if an != 1.0:
        # in link 3's frame: a_A3 = a_C - W3^2 CA + E3 x CA, the Coriolis term 2 W3 x
        # (v_A3 - v_A), the relative acceleration a_A3 - a_A - Coriolis (along the axis)
        a3 = polar(ac, bc) - out.W3**2 * rca + out.E3 * kx(rca)
        cor = 2 * out.W3 * kx(vrel)
        Ar = aa + ac + (out.W3**2 + abs(out.E3)) * L + 2 * abs(out.W3) * np.hypot(*vrel) + \
            1e-300
        v += [abs(out.AACN - out.W3**2 * L) / (Ar * t),
              rel(polar(out.AACT, out.BACT) - out.E3 * kx(rca), Ar) / t,
              rel(polar(out.AA3, out.BA3) - a3, Ar) / t,
              rel(polar(out.AAK, out.BAK) - cor, Ar) / t,
              rel(polar(out.AAR, out.BAR) - (a3 - polar(aa, ba) - cor), Ar) / t]
    if an != 1.0:
        v.append(fd_vs(lambda s: (lambda o: None if o is None else [o.W3])(
            quiet("DKNMA3", *_dknma3_at(args, s))), h, [out.E3],
            max(abs(out.E3), W * W, (aa + ac) / L), bound,
            np.abs(np.r_[A, C]).max() * W / min(lengths)))
    return worst(*v)


# ---- kind 4 (PRP) ----------------------------------------------------------------------

def _kind4(rng):
    ox, oy = offset(rng)
    L = length(rng)
    B = np.array([ox, oy]) + rng.uniform(-1, 1, 2) * L
    fim = angle(rng)
    fin = fim + math.copysign(rng.uniform(0.05, PI - 0.05), rng.uniform(-1, 1))
    rz2, t2, rz3, t3 = L * length(rng, -1, 1), angle(rng), L * length(rng, -1, 1), angle(rng)
    # A and C 0.05 L to 2 L along their guides from B's foot: B at a guide's pivot
    # within a rounding is refused by DKNMA4 (test_fuzz.py::test_dknma4_slider_at_the_pivot)
    A = B - rz2 * math.sin(t2) * kx(e(fim)) + apart(rng) * L * e(fim)
    C = B - rz3 * math.sin(t3) * kx(e(fin)) + apart(rng) * L * e(fin)
    return A, C, fim, fin, rz2, t2, rz3, t3, L


def apart(rng):
    """A signed factor from 0.05 to 2 in size."""
    return float(rng.choice([-1.0, 1.0])) * float(rng.uniform(0.05, 2.0))


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
    # B in the frames of the two turning guides: v_B = W x r + v_rel (v_rel along the
    # guide), a_B = E x r - W^2 r + 2 W x v_rel + a_rel (a_rel along the guide)
    rm, rn = B - A, B - C
    vm, vn, vb = polar(out.VB2R, out.ALB2R), polar(out.VB3R, out.ALB3R), polar(out.VB, out.ALB)
    Vs = max(out.VB, (abs(wm) + abs(wn)) * L, 1e-300)
    v += [rel(vb - wm * kx(rm) - vm, Vs) / t, rel(vb - wn * kx(rn) - vn, Vs) / t,
          abs(cross(vm, e(fim))) / (Vs * t), abs(cross(vn, e(fin))) / (Vs * t)]
    if an != 1.0:
        km, kn = 2 * wm * kx(vm), 2 * wn * kx(vn)
        am, aN = polar(out.AB2R, out.BB2R), polar(out.AB3R, out.BB3R)
        As = out.AB + (abs(em) + wm**2 + abs(en) + wn**2) * L + \
            2 * (abs(wm) + abs(wn)) * Vs + 1e-300
        ab = polar(out.AB, out.BB)
        v += [rel(polar(out.AB2K, out.BB2K) - km, As) / t,
              rel(polar(out.AB3K, out.BB3K) - kn, As) / t,
              rel(ab - (em * kx(rm) - wm**2 * rm + km + am), As) / t,
              rel(ab - (en * kx(rn) - wn**2 * rn + kn + aN), As) / t,
              abs(cross(am, e(fim))) / (As * t), abs(cross(aN, e(fin))) / (As * t)]
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


# ------------------------------------------------------------------ chapter 7 forces
# Groups of 0.05 to 20 m within 10 m of the origin, loads of 1e-2 to 1e4 N and moments up
# to 1e4 N*m, directions at least 0.05 rad from a singular position (test_forces.py
# holds the conventions; here statics is checked over the wider ranges).  The invariant:
# every link of the group balances, forces and moments (about a joint of the group), to
# what the routine vouched for, relative to the largest force times the largest length.

def force(rng):
    return length(rng, -2, 4)


def moment(rng):
    return float(rng.uniform(-1, 1)) * length(rng, -2, 4)


def point(rng):
    return np.array([float(rng.uniform(-10, 10)), float(rng.uniform(-10, 10))])


def oblique_to(rng, fi, lo=0.05):
    """A direction at least ``lo`` rad from fi and fi + pi."""
    return fi + float(rng.choice([-1.0, 1.0])) * float(rng.uniform(lo, PI - lo))


def loads_f(rng, S2, S3):
    """The DNMAF loads: S2, F2, G2, S3, F3, G3, T2, T3."""
    return [*S2, force(rng), angle(rng), *S3, force(rng), angle(rng), moment(rng),
            moment(rng)]


class Statics:
    """Residuals of the balance of the group's links, relative to force x length."""

    def __init__(self, bound, forces, lengths, coords):
        self.F = max([1e-300] + [float(f) for f in forces])
        self.L = max(lengths)
        self.t = tol(bound, coords, min(lengths))
        self.v = []

    def forces(self, *vectors):
        self.v.append(rel(sum(vectors), self.F) / self.t)

    def moments(self, *terms):
        self.v.append(abs(sum(terms)) / (self.F * self.L) / self.t)

    def arm(self, f, *terms):
        """A moment balance through an arm of the force f (no arm when f is 0)."""
        if f > 1e-9 * self.F:
            self.moments(*terms)

    def normal(self, f, direction):
        """A prismatic pair's reaction has no component along its guide."""
        self.v.append(abs(f @ e(direction)) / self.F / self.t)

    def worst(self):
        return worst(*self.v)


def gen_dnmaf1(rng):
    A = point(rng)
    B = A + vec(length(rng, -1.3, 1.3), angle(rng))
    fab = math.atan2(*(A - B)[::-1])
    C = B + vec(length(rng, -1.3, 1.3), oblique_to(rng, fab))
    return [*A, *B, *C, *loads_f(rng, point(rng), point(rng))]


def chk_dnmaf1(args, out, bound):
    xa, ya, xb, yb, xc, yc, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3 = args
    A, B, C, S2, S3 = (np.array(p) for p in ((xa, ya), (xb, yb), (xc, yc), (xs2, ys2),
                                             (xs3, ys3)))
    F12, F23, F43 = -vec(out.F21, out.G21), vec(out.F23, out.G23), -vec(out.F34, out.G34)
    P2, P3 = vec(f2, g2), vec(f3, g3)
    s = Statics(bound, (f2, f3, out.F21, out.F23, out.F34, abs(t2) / 20, abs(t3) / 20),
                (np.hypot(*(B - A)), np.hypot(*(C - B)), 20.0), 10.0)
    s.forces(F12, P2, -F23)
    s.moments(t2, cross(A - B, F12), cross(S2 - B, P2))
    s.forces(F23, P3, F43)
    s.moments(t3, cross(S3 - B, P3), cross(C - B, F43))
    return s.worst()


def gen_dnmaf2(rng):
    A = point(rng)
    fim = angle(rng)
    B = A + vec(length(rng, -1.3, 1.3), oblique_to(rng, fim + PI / 2))
    return [*A, *B, fim, *loads_f(rng, point(rng), point(rng))]


def chk_dnmaf2(args, out, bound):
    xa, ya, xb, yb, fim, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3 = args
    A, B, S2, S3 = (np.array(p) for p in ((xa, ya), (xb, yb), (xs2, ys2), (xs3, ys3)))
    F12, F23, F43 = -vec(out.F21, out.G21), vec(out.F23, out.G23), -vec(out.F34, out.G34)
    P2, P3 = vec(f2, g2), vec(f3, g3)
    s = Statics(bound, (f2, f3, out.F21, out.F23, out.F34, abs(t2) / 20, abs(t3) / 20),
                (np.hypot(*(B - A)), 20.0), 10.0)
    s.forces(F12, P2, -F23)
    s.moments(t2, cross(A - B, F12), cross(S2 - B, P2))
    s.forces(F23, P3, F43)
    s.normal(F43, fim)
    s.arm(out.F34, t3, cross(S3 - B, P3), out.H34 * out.F34)   # H34: arm of F43 about B
    return s.worst()


def gen_dnmaf3(rng):
    A = point(rng)
    C = A + vec(length(rng, -1.3, 1.3), angle(rng))
    fi3 = oblique_to(rng, math.atan2(*(C - A)[::-1]) + PI / 2)
    return [*A, *C, fi3, *loads_f(rng, point(rng), point(rng))]


def chk_dnmaf3(args, out, bound):
    xa, ya, xc, yc, fi3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3 = args
    A, C, S2, S3 = (np.array(p) for p in ((xa, ya), (xc, yc), (xs2, ys2), (xs3, ys3)))
    F12, F23, F43 = -vec(out.F21, out.G21), vec(out.F23, out.G23), -vec(out.F34, out.G34)
    P2, P3 = vec(f2, g2), vec(f3, g3)
    s = Statics(bound, (f2, f3, out.F21, out.F23, out.F34, abs(t2) / 20, abs(t3) / 20),
                (np.hypot(*(C - A)), 20.0), 10.0)
    s.forces(F12, P2, -F23)
    s.normal(F23, fi3)
    s.forces(F23, P3, F43)
    s.arm(out.F23, t3, cross(S3 - C, P3), out.H23 * out.F23)   # H23: arm of F23 about C
    s.arm(out.F23, t2, cross(A - C, F12), cross(S2 - C, P2), -out.H23 * out.F23)
    return s.worst()


def gen_dnmaf4(rng):
    fim = angle(rng)
    return [fim, oblique_to(rng, fim), *point(rng), *loads_f(rng, point(rng), point(rng))]


def chk_dnmaf4(args, out, bound):
    fim, fin, xb, yb, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3 = args
    B, S2, S3 = (np.array(p) for p in ((xb, yb), (xs2, ys2), (xs3, ys3)))
    F12, F23, F43 = -vec(out.F21, out.G21), vec(out.F23, out.G23), -vec(out.F34, out.G34)
    P2, P3 = vec(f2, g2), vec(f3, g3)
    s = Statics(bound, (f2, f3, out.F21, out.F23, out.F34, abs(t2) / 20, abs(t3) / 20),
                (20.0,), 10.0)
    s.forces(F12, P2, -F23)
    s.normal(F12, fim)
    s.forces(F23, P3, F43)
    s.normal(F43, fin)
    s.arm(out.F21, t2, cross(S2 - B, P2), out.H21 * out.F21)   # arms about B (E-DNMAF4-3)
    s.arm(out.F34, t3, cross(S3 - B, P3), out.H34 * out.F34)
    return s.worst()


def gen_dnmaf5(rng):
    return [*point(rng), angle(rng), oblique_to(rng, 0.0),
            *loads_f(rng, point(rng), point(rng))]


def chk_dnmaf5(args, out, bound):
    xa, ya, fim, tt3, xs2, ys2, f2, g2, xs3, ys3, f3, g3, t2, t3 = args
    A, S2, S3 = (np.array(p) for p in ((xa, ya), (xs2, ys2), (xs3, ys3)))
    F12, F32, F43 = -vec(out.F21, out.G21), vec(out.F32, out.G32), -vec(out.F34, out.G34)
    P2, P3 = vec(f2, g2), vec(f3, g3)
    s = Statics(bound, (f2, f3, out.F21, out.F32, out.F34, abs(t2) / 20, abs(t3) / 20),
                (20.0,), 10.0)
    s.forces(F12, P2, F32)
    s.normal(F32, fim + tt3)
    s.forces(-F32, P3, F43)
    s.normal(F43, fim)
    s.arm(out.F32, t2, cross(S2 - A, P2), out.H32 * out.F32)   # arms about A
    s.arm(out.F34, t2 + t3, cross(S2 - A, P2), cross(S3 - A, P3), out.H34 * out.F34)
    return s.worst()


def loads_q(rng):
    """The DNMA loads: M2, Q2, G2, M3, Q3, G3."""
    return [moment(rng), force(rng), angle(rng), moment(rng), force(rng), angle(rng)]


def gen_dnma1(rng):
    fi2 = angle(rng)
    return [length(rng, -1.3, 1.3), fi2, length(rng, -1.3, 1.3), oblique_to(rng, fi2),
            float(rng.uniform(-20, 20)), float(rng.uniform(-20, 20)), *loads_q(rng)]


def chk_dnma1(args, out, bound):
    l2, fi2, l3, fi3, bs2, bs3, m2, q2, g2, m3, q3, g3 = args
    # B at the origin, A = B - L2 e(FI2), C = B - L3 e(FI3), S = B + BS e(FI) (E-DNMA1-3)
    A, C = -vec(l2, fi2), -vec(l3, fi3)
    S2, S3 = vec(bs2, fi2), vec(bs3, fi3)
    RA, RB, RC = vec(out.RA, out.GA), vec(out.RB, out.GB), vec(out.RC, out.GC)
    P2, P3 = vec(q2, g2), vec(q3, g3)
    s = Statics(bound, (q2, q3, out.RA, out.RB, out.RC, abs(m2) / 20, abs(m3) / 20),
                (l2, l3, 20.0), 0.0)
    s.forces(RA, P2, RB)
    s.moments(m2, cross(A, RA), cross(S2, P2))
    s.forces(-RB, P3, RC)
    s.moments(m3, cross(S3, P3), cross(C, RC))
    return s.worst()


def gen_dnma2(rng):
    fi2 = angle(rng)
    return [length(rng, -1.3, 1.3), fi2, length(rng, -1.3, 1.3), angle(rng),
            oblique_to(rng, fi2 + PI / 2), float(rng.uniform(-20, 20)),
            float(rng.uniform(-20, 20)), *loads_q(rng)]


def chk_dnma2(args, out, bound):
    l2, fi2, l3, eta, fio, bs2, bs3, m2, q2, g2, m3, q3, g3 = args
    A, S2, S3 = -vec(l2, fi2), vec(bs2, fi2), vec(bs3, fio + eta)     # B at the origin
    RA, RB, RC = vec(out.RA, out.GA), vec(out.RB, out.GB), vec(out.RC, out.GC)
    P2, P3 = vec(q2, g2), vec(q3, g3)
    s = Statics(bound, (q2, q3, out.RA, out.RB, out.RC, abs(m2) / 20, abs(m3) / 20),
                (l2, 20.0), 0.0)
    s.forces(RA, P2, RB)
    s.moments(m2, cross(A, RA), cross(S2, P2))
    s.forces(-RB, P3, RC)
    s.normal(RC, fio)
    s.arm(out.RC, m3, cross(S3, P3), out.HC * out.RC)          # HC: arm of RC about B
    return s.worst()


def gen_dnma3(rng):
    fiac = angle(rng)
    return [length(rng, -1.3, 1.3), angle(rng), oblique_to(rng, fiac + PI / 2),
            float(rng.uniform(0, 20)), angle(rng), float(rng.uniform(0, 20)), angle(rng),
            length(rng, -1.3, 1.3), fiac, *loads_q(rng)]


def chk_dnma3(args, out, bound):
    l2, eta2, fi3, cs2, fics2, cs3, fics3, ac, fiac, m2, q2, g2, m3, q3, g3 = args
    A, S2, S3 = -vec(ac, fiac), vec(cs2, fics2), vec(cs3, fics3)   # C at the origin
    RA, RB, RC = vec(out.RA, out.GA), vec(out.RB, out.GB), vec(out.RC, out.GC)
    P2, P3 = vec(q2, g2), vec(q3, g3)
    s = Statics(bound, (q2, q3, out.RA, out.RB, out.RC, abs(m2) / 20, abs(m3) / 20),
                (ac, 20.0), 0.0)
    s.forces(RA, P2, RB)
    s.normal(RB, fi3)
    s.forces(-RB, P3, RC)
    s.arm(out.RB, m3, cross(S3, P3), out.HB * out.RB)          # HB: of -RB about C
    s.arm(out.RB, m2, cross(A, RA), cross(S2, P2), -out.HB * out.RB)
    return s.worst()


def gen_dnma4(rng):
    fim = angle(rng)
    return [fim, angle(rng), oblique_to(rng, fim), angle(rng), float(rng.uniform(-20, 20)),
            float(rng.uniform(-20, 20)), *loads_q(rng)]


def chk_dnma4(args, out, bound):
    fim, eta2, fin, eta3, bs2, bs3, m2, q2, g2, m3, q3, g3 = args
    RA, RB, RC = vec(out.RA, out.GA), vec(out.RB, out.GB), vec(out.RC, out.GC)
    P2, P3 = vec(q2, g2), vec(q3, g3)
    s = Statics(bound, (q2, q3, out.RA, out.RB, out.RC, abs(m2) / 20, abs(m3) / 20),
                (20.0,), 0.0)
    s.forces(RA, P2, RB)
    s.normal(RA, fim)
    s.forces(-RB, P3, RC)
    s.normal(RC, fin)
    s.arm(out.RA, m2, cross(bs2 * e(fim + eta2), P2), out.HA * out.RA)   # E-DNMA4-2
    s.arm(out.RC, m3, cross(bs3 * e(fin + eta3), P3), out.HC * out.RC)
    return s.worst()


def gen_dnma5(rng):
    return [oblique_to(rng, 0.0), angle(rng), float(rng.uniform(0, 20)),
            float(rng.uniform(0, 20)), angle(rng), angle(rng), *loads_q(rng)]


def chk_dnma5(args, out, bound):
    eta3, fim, as2, as3, fias2, fias3, m2, q2, g2, m3, q3, g3 = args
    S2, S3 = -vec(as2, fias2), -vec(as3, fias3)          # A at the origin (E-DNMA5-3)
    RA, RB, RC = vec(out.RA, out.GA), vec(out.RB, out.GB), vec(out.RC, out.GC)
    P2, P3 = vec(q2, g2), vec(q3, g3)
    s = Statics(bound, (q2, q3, out.RA, out.RB, out.RC, abs(m2) / 20, abs(m3) / 20),
                (20.0,), 0.0)
    s.forces(RA, P2, -RB)                                # RB acts on 3, from 2
    s.normal(RB, fim + eta3)
    s.forces(RB, P3, RC)
    s.normal(RC, fim)
    s.arm(out.RB, m2, cross(S2, P2), out.HB * out.RB)
    s.arm(out.RC, m2 + m3, cross(S2, P2), cross(S3, P3), out.HC * out.RC)
    return s.worst()


def gen_dugl6(rng):
    rn, rt = force(rng), force(rng)
    gn = angle(rng)
    return [rn, gn, rt, oblique_to(rng, gn, 0.05) if rng.random() < 0.5 else angle(rng),
            angle(rng, True)]


def chk_dugl6(args, out, bound):
    rn, gn, rt, gt, fi = args
    total = vec(rn, gn) + vec(rt, gt)
    size = float(np.hypot(*total))
    if size <= 1e-6 * (rn + rt):                         # the sum vanishes: no direction
        return 0.0
    if not -PI / 2 < out < 1.5 * PI + 1e-15:
        return math.inf
    return rel(size * e(out) - total, rn + rt) / tol(bound)


for _name in ("DNMAF1", "DNMAF2", "DNMAF3", "DNMAF4", "DNMAF5",
              "DNMA1", "DNMA2", "DNMA3", "DNMA4", "DNMA5", "DUGL6"):
    _register(_name, globals()["gen_" + _name.lower()], globals()["chk_" + _name.lower()])


# ------------------------------------------------------------------ chapter 6 gears
# Standard involute relations (ALPHA = 20 deg, addendum 1, root clearance 0.25), written
# from the textbook formulas (6.12)-(6.24), not from sarkp: tooth numbers 17 to 200, shifts
# from -0.5 (or the undercut limit) to 0.3, helix angles up to 0.6 rad, modules 0.1 to 100.

ALPHA = PI / 9


def inv(x):
    return math.tan(x) - x


def gen_duginv(rng):
    x = float(rng.uniform(1e-3, 1.5))
    return [inv(x), PI / 18, 1e-5]


def chk_duginv(args, out, bound):
    invx = args[0]
    if not 0.0 <= out < PI / 2:
        return math.inf
    # the angle is exact when inv(out) = INVX to a few roundings of tan(out), whose
    # derivative is 1/cos^2 (corrected mode: full precision)
    return abs(inv(out) - invx) / (16 * U * (math.tan(out) + out) / math.cos(out) ** 2)


def teeth(rng):
    return float(rng.integers(17, 201))


def gen_dgmtzk(rng):
    z = teeth(rng)
    beta = float(rng.uniform(0.0, 0.6)) * float(rng.choice([-1.0, 1.0]))
    at = math.atan(math.tan(ALPHA) / math.cos(beta))
    xmin = 1 - z * math.sin(at) ** 2 / (2 * math.cos(beta))
    return [length(rng, -1, 2), z, beta, float(rng.uniform(max(xmin + 0.01, -0.5), 0.3))]


def chk_dgmtzk(args, out, bound):
    m, z, beta, x = args
    at = math.atan(math.tan(ALPHA) / math.cos(beta))
    d = m * z / math.cos(beta)
    db = d * math.cos(at)
    da, df = d + 2 * (1 + x) * m, d - 2 * (1.25 - x) * m
    s = m * (PI / 2 + 2 * x * math.tan(ALPHA)) / math.cos(beta)     # transverse thickness
    aat = math.acos(db / da)
    sb = db * (s / d + inv(at))
    sa = da * (s / d + inv(at) - inv(aat))
    got = (out.D, out.S, out.DB, out.SB, out.DA, out.SA, out.DF)
    want = (d, s, db, sb, da, sa, df)
    return worst(*(abs(g - w) / (1e-12 * da) for g, w in zip(got, want)))


def gen_dgmzpc(rng):
    beta = float(rng.uniform(0.0, 0.6)) * float(rng.choice([-1.0, 1.0]))
    at = math.atan(math.tan(ALPHA) / math.cos(beta))
    args = [length(rng, -1, 2)]
    shifts = []
    for _ in range(2):
        z = teeth(rng)
        xmin = 1 - z * math.sin(at) ** 2 / (2 * math.cos(beta))
        args.append(z)
        shifts.append(float(rng.uniform(max(xmin + 0.01, -0.5), 0.3)))
    return args + [beta, *shifts, float(rng.uniform(0, 100))]


def chk_dgmzpc(args, out, bound):
    m, z1, z2, beta, x1, x2, bw = args
    at = math.atan(math.tan(ALPHA) / math.cos(beta))
    a = m * (z1 + z2) / (2 * math.cos(beta))
    xs = x1 + x2
    inv_w = inv(at) + 2 * xs * math.tan(ALPHA) / (z1 + z2)
    aw = a * math.cos(at) / math.cos(out.ALFAW)
    y = (aw - a) / m
    dy = xs - y
    eps = 0.0
    tips = []                          # (DA, ALFAA, SA) of each wheel, tips shortened by dy
    for z, x in ((z1, x1), (z2, x2)):
        d = m * z / math.cos(beta)
        da = d + 2 * (1 + x - dy) * m
        aa = math.acos(d * math.cos(at) / da)
        st = m * (PI / 2 + 2 * x * math.tan(ALPHA)) / math.cos(beta)     # transverse
        tips.append((da, aa, da * (st / d + inv(at) - inv(aa))))
        eps += z * math.tan(aa)
    eps = (eps - (z1 + z2) * math.tan(out.ALFAW)) / (2 * PI) + \
        bw * abs(math.sin(beta)) / (PI * m)
    got = ((out.DA1, out.ALFAA1, out.SA1), (out.DA2, out.ALFAA2, out.SA2))
    tip_v = [abs(g - w) / (1e-9 * (1 + abs(w))) for gs, ws in zip(got, tips)
             for g, w in zip(gs, ws)]
    # ALFAW through the involute equation (its root, to roundings of tan), the rest
    # from it; E to 1e-9 (the tip angles' arccos near their base circles)
    return worst(abs(inv(out.ALFAW) - inv_w) / (16 * U * (1 + inv_w) /
                                                math.cos(out.ALFAW) ** 2),
                 abs(out.A - a) / (1e-13 * a), abs(out.XS - xs) / (1e-13 * (1 + abs(xs))),
                 abs(out.AW - aw) / (1e-12 * a), abs(out.XY - y) / (1e-9 * (1 + abs(y))),
                 abs(out.XUR - dy) / (1e-9 * (1 + abs(dy))), abs(out.E - eps) / (1e-9 * eps),
                 *tip_v)


def gen_dkrkt(rng):
    m, z1, z2 = length(rng, -1, 2), float(rng.integers(18, 201)), float(rng.integers(18, 201))
    # a centre distance 0 to 0.4 modules above the standard one: shifts from 0 to about
    # 0.45, neither undercut (x >= 0 > X1P = 1 - 0.5 z sin^2(alpha) from 18 teeth up; 17
    # teeth undercut at x = 0) nor pointed (x < 0.15 z^0.7)
    return [m, z1, z2, m * (z1 + z2) / 2 + float(rng.uniform(0.0, 0.4)) * m, 0]


def chk_dkrkt(args, out, bound):
    m, z1, z2, aw, sdvig = args
    a = m * (z1 + z2) / 2
    alfaw = math.acos(a * math.cos(ALPHA) / aw)                           # (6.12)
    xs = (z1 + z2) * (inv(alfaw) - inv(ALPHA)) / (2 * math.tan(ALPHA))      # (6.13)
    return worst(abs(out.ALFAW - alfaw) / 1e-12, abs(out.X1 + out.X2 - xs) / 1e-10)


for _name in ("DUGINV", "DGMTZK", "DGMZPC", "DKRKT"):
    _register(_name, globals()["gen_" + _name.lower()], globals()["chk_" + _name.lower()])


# ------------------------------------------------------------------ chapter 8 dynamics
# One cycle of a machine: a smooth periodic reduced moment and variable inertia on 5 to
# 60 points, a constant inertia large enough that the speed stays positive.  The
# invariants: the trapezoid work, the steady-state work, the energy equation (8.13)
# (J_c + J_v) omega^2 / 2 - work = constant with (max + min)/2 = W1, the difference
# quotient of omega; the flywheel formula (8.22).

def periodic(rng, m, scale):
    phi = np.linspace(0.0, 2 * PI, m)
    out = np.full(m, float(rng.uniform(-0.5, 0.5)) * scale)
    for k in (1, 2, 3):
        # the first harmonic is never 0: the cycle has a swing
        a = apart(rng) / 2 if k == 1 else float(rng.uniform(-1, 1))
        out += a * scale * np.sin(k * phi + angle(rng))
    return out


def gen_dzkndv(rng):
    m = int(rng.integers(5, 61))
    w1, q = length(rng, -1, 3), length(rng, -2, 4)
    mpr = periodic(rng, m, q)
    ispr = np.abs(periodic(rng, m, q / w1**2)) * float(rng.uniform(0, 2))
    # the energy swing over the cycle is below 2 pi * 3.5 q; an inertia 20 to 1000 times
    # that over W1^2 keeps the speed within a few percent of W1
    isc = 22 * q * float(10.0 ** rng.uniform(1.3, 3)) / w1**2
    return [m, float(m), w1, isc, mpr, ispr]


def chk_dzkndv(args, out, bound):
    m, zm, w1, isc, mpr, ispr = args
    h = 2 * PI / (m - 1)
    work = np.concatenate([[0.0], np.cumsum((mpr[1:] + mpr[:-1]) * h / 2)])
    asum = work - np.arange(m) * work[-1] / (m - 1)
    ev = ispr * w1**2 / 2
    dec = (asum - ev) - (asum[0] - ev[0])
    scale = np.abs(mpr).max() * 2 * PI + np.abs(ev).max() + 1e-300
    wpr = np.asarray(out.WPR)
    energy = (isc + ispr) * wpr**2 / 2 - asum
    e0 = energy.mean()
    epr = np.diff(wpr) / h
    return worst(rel(out.AS - work, scale) / 1e-12, rel(out.ASUM - asum, scale) / 1e-12,
                 rel(out.EV - ev, scale) / 1e-12, rel(out.DEC - dec, scale) / 1e-12,
                 np.abs(energy - e0).max() / (abs(e0) * 1e-11),
                 abs((wpr.max() + wpr.min()) / 2 - w1) / (w1 * 1e-12),
                 rel(out.EPR[1:] - epr, np.abs(epr).max() + w1 / h * 1e-12) / 1e-9,
                 0.0 if out.EPR[0] == out.EPR[1] else math.inf)


def gen_dmhvk(rng):
    n = int(rng.integers(3, 61))
    dec = periodic(rng, n, length(rng, -2, 4))
    delta, w1 = float(rng.uniform(0.001, 0.5)), length(rng, -1, 3)
    swing = dec.max() - dec.min()
    return [n, delta, swing / (delta * w1**2) * float(rng.uniform(0.01, 0.99)), w1, dec]


def chk_dmhvk(args, out, bound):
    n, delta, isc, w1, dec = args
    want = (dec.max() - dec.min()) / (delta * w1**2) - isc
    return abs(out.IMHVK - want) / (1e-13 * (want + isc))


for _name in ("DZKNDV", "DMHVK"):
    _register(_name, globals()["gen_" + _name.lower()], globals()["chk_" + _name.lower()])


# ------------------------------------------------------------------ chapter 5 cams
# A cycle of 5 to 60 cam angles (any order), a harmonic rise and return of the follower
# (its displacement, velocity W s' and acceleration W^2 s'' exact for the angles), the
# cam at W of 0.1 to 1e3.  The invariants, in the cam's frame P(FI) = Rot(-FI) T, T the
# follower's point in the fixed frame: P turned back by FI is T; the pressure angle is
# the angle between the profile's normal (normal to P', by the chain rule from s', or
# psi') and the follower point's velocity; the radius of curvature is |P'|^3/(P' x P''),
# positive where the profile turns towards the cam centre (convex); sarkp's extensions
# ALFMAX/NOVER and ROKMIN/NCONC from those.

def cycle(rng, amplitude):
    """Cam angles and the follower's s, s', s'' = amplitude (1 - cos(k FI))/2 and its
    derivatives, k = 1 or 2 (one or two rises per turn)."""
    n = int(rng.integers(5, 61))
    fi = np.sort(rng.uniform(0.0, 2 * PI, n)) if rng.random() < 0.5 else \
        np.linspace(0.0, 2 * PI, n)
    k = float(rng.integers(1, 3))
    s = amplitude * (1 - np.cos(k * fi)) / 2
    s1 = amplitude * k * np.sin(k * fi) / 2
    s2 = amplitude * k * k * np.cos(k * fi) / 2
    return n, fi, s, s1, s2


def turned(fi, x, y):
    """Rot(FI) (x, y): a point of the cam's frame in the fixed frame."""
    return x * np.cos(fi) - y * np.sin(fi), x * np.sin(fi) + y * np.cos(fi)


def curve_checks(fi, tx, ty, dtx, dty, d2tx, d2ty, out_x, out_y, r1, delta, radius, scale):
    """The profile P = Rot(-FI) T against the outputs: the point, R1, DELTA, and the
    radius of curvature from P' and P'' (T, T', T'' given in the fixed frame; the frame
    turns, so P' = Rot(-FI) (T' - J T), P'' = Rot(-FI) (T'' - 2 J T' - T), J = +90 deg)."""
    px, py = turned(-fi, tx, ty)
    ax, ay = dtx + ty, dty - tx                     # T' - J T
    bx, by = d2tx + 2 * dty - tx, d2ty - 2 * dtx - ty
    d1x, d1y = turned(-fi, ax, ay)
    d2x, d2y = turned(-fi, bx, by)
    speed = np.hypot(d1x, d1y)
    bend = d1x * d2y - d1y * d2x
    turning = np.sign(px * d1y - py * d1x)          # the sense the profile goes round O
    kappa = turning * bend / speed**3                # > 0: convex
    v = [np.abs(out_x - px).max() / scale, np.abs(out_y - py).max() / scale,
         np.abs(r1 - np.hypot(px, py)).max() / scale,
         np.abs(np.sin(delta - np.arctan(px / py))).max()]
    # curvature compared as 1/radius, relative to the curvature of a circle of R1
    v.append(np.abs(1.0 / radius - kappa).max() * scale)
    return v, (d1x, d1y), (px, py)


def line_angle(u, v):
    """The angle between the lines of vectors u and v, in [0, pi/2]."""
    return np.arctan2(np.abs(u[0] * v[1] - u[1] * v[0]), np.abs(u[0] * v[0] + u[1] * v[1]))


def gen_dprflp(rng):
    h = length(rng, -2, 0)
    n, fi, s, s1, s2 = cycle(rng, h)
    w = length(rng, -1, 3)
    ro = h * float(rng.uniform(1.5, 5.0))
    return [n, ro, float(rng.uniform(-0.5, 0.5)) * ro, w, fi, s2 * w * w, s1 * w, s,
            float(rng.uniform(0.1, 1.4))]


def chk_dprflp(args, out, bound):
    n, ro, e_, w, fi, a, v, s, ald = args
    s1, s2 = v / w, a / w**2
    c = ro + s
    # the tip (e, RO + S) moves along the axis x = e: T' = (0, s'), T'' = (0, s'')
    z = np.zeros_like(fi)
    checks, d1, p = curve_checks(fi, e_ + z, c, z, s1, z, s2, out.XA, out.YA, out.R1,
                                 out.DELTA, out.ROK, ro + abs(e_) + np.abs(s).max())
    # the pressure angle: the profile's normal (in the fixed frame, Rot(FI) J P') against
    # the axis (0, 1)
    nx, ny = turned(fi, -d1[1], d1[0])
    alfa = line_angle((nx, ny), (z, z + 1.0))
    checks.append(np.abs(np.abs(out.ALFA) - alfa).max())
    checks.append(abs(out.ALFMAX - np.abs(out.ALFA).max()))
    checks.append(float(out.NOVER != np.count_nonzero(np.abs(out.ALFA) > ald)))
    return worst(*checks) / 1e-9


def gen_dprfpl(rng):
    h = length(rng, -2, 0)
    n, fi, s, s1, s2 = cycle(rng, h)
    w = length(rng, -1, 3)
    return [n, float(rng.uniform(0.05, 1.5)), w, fi, s2 * w * w, s1 * w, s]


def chk_dprfpl(args, out, bound):
    n, gamma, w, fi, a, v, s = args
    s1, s2 = v / w, a / w**2
    low = int(np.argmin(a))                          # the first smallest acceleration
    rksh = abs(s2[low] / math.tan(gamma) + s[low])   # the convexity rule (5.4), as printed
    c = rksh + s
    # the contact point (s', RKSH + S) on the face y = RKSH + S: T' = (s'', s'),
    # T'' = (s''', s''), s''' from the tables' law is not given: use the envelope
    # instead -- the profile's tangent lies along the face (P' turned back has y = 0)
    # and the radius of curvature of an envelope of lines is RKSH + S + s''
    px, py = turned(-fi, s1, c)
    tx, ty = turned(fi, out.XA, out.YA)
    scale = rksh + np.abs(s).max() + np.abs(s1).max() + np.abs(s2).max()
    checks = [abs(out.RKSH - rksh) / scale, np.abs(tx - s1).max() / scale,
              np.abs(ty - c).max() / scale, np.abs(out.R1 - np.hypot(px, py)).max() / scale,
              np.abs(np.sin(out.DELTA - np.arctan(px / py))).max(),
              np.abs(out.ROK - (c + s2)).max() / scale,
              abs(out.ROKMIN - np.min(out.ROK)) / scale,
              float(out.NCONC != np.count_nonzero(out.ROK < -16 * 2.2e-16 * (
                  rksh + np.abs(s).max() + np.abs(s2).max())))]
    return worst(*checks) / 1e-9


def gen_dprflk(rng):
    amp = float(rng.uniform(0.05, 0.6))
    n, fi, psi, p1, p2 = cycle(rng, amp)
    w1 = length(rng, -1, 3)
    big, r = length(rng, -2, 1), 0.0
    r = big * float(rng.uniform(0.2, 0.8))
    etao = float(rng.uniform(0.2, PI - 0.2 - amp))    # psi + ETAO within (0.2, pi - 0.2)
    return [n, w1, etao, fi, big, big, r, p2 * w1 * w1, p1 * w1, psi,
            float(rng.uniform(0.1, 1.4))]


def chk_dprflk(args, out, bound):
    n, w1, etao, fi, ro, big, r, e2, w2, psi, ald = args
    p1, p2 = w2 / w1, e2 / w1**2
    q = psi + etao
    # the tip O2 + R (-cos q, sin q), O2 = (L, 0): T' = R (sin q, cos q) psi', T'' by psi''
    tx, ty = big - r * np.cos(q), r * np.sin(q)
    dtx, dty = r * np.sin(q) * p1, r * np.cos(q) * p1
    d2tx = r * (np.cos(q) * p1**2 + np.sin(q) * p2)
    d2ty = r * (-np.sin(q) * p1**2 + np.cos(q) * p2)
    checks, d1, p = curve_checks(fi, tx, ty, dtx, dty, d2tx, d2ty, out.XA, out.YA, out.R1,
                                 out.DELTA, out.RKRZVN, big + r)
    # the pressure angle: the normal against the tip's velocity (normal to O2 -> tip)
    nx, ny = turned(fi, -d1[1], d1[0])
    alfa = line_angle((nx, ny), (np.sin(q), np.cos(q)))
    checks.append(np.abs(np.abs(out.ALFA) - alfa).max())
    checks.append(abs(out.ALFMAX - np.abs(out.ALFA).max()))
    checks.append(float(out.NOVER != np.count_nonzero(np.abs(out.ALFA) > ald)))
    return worst(*checks) / 1e-9


for _name in ("DPRFLP", "DPRFPL", "DPRFLK"):
    _register(_name, globals()["gen_" + _name.lower()], globals()["chk_" + _name.lower()])


def gen_dchrvc(rng):
    m, q = length(rng, -1, 2), float(rng.uniform(6.0, 20.0))
    z2 = float(rng.integers(20, 201))
    aw = m * (z2 + q) / 2 + float(rng.uniform(-0.7, 0.7)) * m      # shift -0.7 .. 0.7
    return [m, q, float(rng.choice([1.0, 2.0, 4.0])), z2, aw]


def chk_dchrvc(args, out, bound):
    """The worm's operating circle and the wheel's reference circle touch at AW; the lead
    angles from the pitch m z1 over the diameters; Table 26's proportions."""
    m, q, z1, z2, aw = args
    x = out.X
    want = {"D1": q * m, "D2": z2 * m, "DW1": 2 * aw - z2 * m, "H1": 2.2 * m, "HA1": m,
            "DA1": q * m + 2 * m, "DA2": z2 * m + 2 * (1 + x) * m,
            "DAM2": z2 * m + 2 * (1 + x) * m + 6 * m / (z1 + 2), "B1": (11 + 0.1 * z2) * m,
            "B2": 0.75 * (q + 2) * m, "R": q * m / 2 - m}
    v = [abs(getattr(out, k) - w) / (1e-13 * aw) for k, w in want.items()]
    v.append(abs(math.tan(out.G) - z1 / q) / 1e-14)
    v.append(abs(math.tan(out.GW) * out.DW1 - z1 * m) / (1e-13 * aw))
    v.append(abs((out.DW1 + out.D2) / 2 - aw) / (1e-13 * aw))
    v.append(abs(out.DW1 - (q + 2 * x) * m) / (1e-13 * aw))
    return worst(*v)


_register("DCHRVC", gen_dchrvc, chk_dchrvc)


def _planetary(z1, l2, l3, t, k, scheme):
    """The set of scheme 1 (1-2 external, 3-4 internal) or 2 (both external) with
    z2 = L2 t, z3 = L3 t, coaxial, and its ratio i_1h = 1 -+ z2 z4/(z1 z3) (Willis, wheel
    4 fixed) as P/Q in lowest terms; None if a condition of the text fails."""
    z2, z3 = l2 * t, l3 * t
    z4 = z1 + z2 + z3 if scheme == 1 else z1 + z2 - z3
    sign = 1 if scheme == 1 else -1
    num, den = z1 * z3 + sign * z2 * z4, z1 * z3
    g = math.gcd(num, den)
    p, q = num // g, den // g
    ok = (min(z2, z3) >= 20 and (z4 >= 85 if scheme == 1 else z4 >= 20) and p != 0
          and abs(p) <= 1000 and q <= 1000                              # DZBPL's ranges
          and (z1 * p) % (k * q) == 0                                   # assembly (6.4)
          and math.sin(PI / k) > (max(z2, z3) + 2) / (z1 + z2))          # neighbours (6.5)
    return (z1, z2, z3, z4, p, q) if ok else None


def gen_dzbpl(rng):
    """A train that exists: scheme 1 or 2, k = 2..4 satellites, z2 : z3 = L2 : L3
    coprime, z1 20..120; Z1MIN..Z1MAX around its z1 (the routine returns the first
    admissible set in that range, which need not be this one)."""
    for _ in range(40):
        scheme = int(rng.integers(1, 3))
        k = int(rng.integers(2, 5))
        l2, l3 = int(rng.integers(1, 6)), int(rng.integers(1, 6))
        if math.gcd(l2, l3) != 1 or (scheme == 2 and l2 == l3):
            continue
        t0 = -(-20 // min(l2, l3))                 # the least t with z2, z3 >= 20
        t = int(rng.integers(t0, t0 + 10))
        z1 = int(rng.integers(20, 121))
        found = _planetary(z1, l2, l3, t, k, scheme)
        if found:
            z1, z2, z3, z4, p, q = found
            return [k, p, q, l2, l3, max(8, z1 - int(rng.integers(0, 30))),
                    z1 + int(rng.integers(0, 30)), scheme]
    return [3, 4, 1, 1, 1, 20, 200, 1]        # i = 4 with z2 = z3 (Fig. 38a's kind)


def chk_dzbpl(args, out, bound):
    k, p, q, l2, l3, z1min, z1max, scheme = args
    z1, z2, z3, z4 = (int(round(v)) for v in out)
    sign = 1 if scheme == 1 else -1
    conditions = [
        all(float(v).is_integer() for v in out),
        z1min <= z1 <= z1max,
        z2 * l3 == z3 * l2,                                             # z2 : z3 = L2 : L3
        (z1 + z2 + z3 == z4) if scheme == 1 else (z1 + z2 == z4 + z3),  # coaxial (6.2)
        p * z1 * z3 == q * (z1 * z3 + sign * z2 * z4),                   # the ratio
        (z1 * p) % (k * q) == 0,                                         # assembly (6.4)
        math.sin(PI / k) > (max(z2, z3) + 2) / (z1 + z2),                # neighbours (6.5)
        min(z2, z3) >= 20 and (z4 >= 85 if scheme == 1 else z4 >= 20),
        scheme != 1 or z4 - z3 >= 8]
    return 0.0 if all(conditions) else math.inf


_register("DZBPL", gen_dzbpl, chk_dzbpl)


def gen_dklchk(rng):
    """A harmonic rise (one or two per turn) on 13 to 60 equal steps and, half the time,
    a rocker (INDEX = 2) with its centre distance and length.  ALD up to 0.6 rad keeps
    the rule's RO > 0: at the sampled largest velocity (within pi/12 of the true one)
    s'/tan(ALD) > s.  BETA keeps sin(ALD + BETA) > 0."""
    index = int(rng.integers(1, 3))
    h = length(rng, -2, 0) if index == 1 else float(rng.uniform(0.05, 0.6))
    n = int(rng.integers(13, 61))
    fi = np.linspace(0.0, 2 * PI, n)
    k = float(rng.integers(1, 3))
    s, s1, s2 = (h * (1 - np.cos(k * fi)) / 2, h * k * np.sin(k * fi) / 2,
                 h * k * k * np.cos(k * fi) / 2)
    w1 = length(rng, -1, 3)
    ald = float(rng.uniform(0.1, 0.6))
    beta = float(rng.uniform(-0.8 * ald, 0.5)) if index == 1 else 0.0
    big = length(rng, -2, 1)
    return [n, s, s1 * w1, s2 * w1 * w1, ald, beta, w1, big,
            big * float(rng.uniform(0.2, 0.8)), index]


def chk_dklchk(args, out, bound):
    n, prm, vlst, akslrt, ald, beta, w1, rscntr, rzmr, index = args
    k = int(np.argmax(vlst))                         # the first largest velocity
    ifi, s = vlst[k] / w1, prm[k]
    if index == 1:
        # offset e = RO sin(BETA) and axial distance RO cos(BETA): the pressure angle at
        # that point is ALD exactly, tan = (s' - e)/(RO cos(BETA) + s)
        tan_alpha = (ifi - out.EXCST) / (out.RO * math.cos(beta) + s)
        return worst(abs(tan_alpha - math.tan(ald)) / (1e-13 * (1 + math.tan(ald))),
                     abs(out.EXCST - out.RO * math.sin(beta)) / (1e-15 * out.RO),
                     0.0 if out.ETAO == 0.0 and out.RO > 0 else math.inf)
    # the rocker: the book's initial angle, and RO the distance from the cam centre of
    # the rocker's tip at that angle from the line of centres (law of cosines)
    etao = ifi / math.tan(ald) - s
    tip = np.array([rscntr - rzmr * math.cos(etao), rzmr * math.sin(etao)])
    return worst(abs(out.ETAO - etao) / (1e-14 * (1 + abs(etao))),
                 abs(out.RO - np.hypot(*tip)) / (1e-14 * (rscntr + rzmr)),
                 0.0 if out.EXCST == 0.0 else math.inf)


_register("DKLCHK", gen_dklchk, chk_dklchk)


def gen_dgmzvn(rng):
    """A pinion of 18-60 teeth in a wheel of 20-80 more, cut by a standard shaper of
    18-40 teeth, 10 fewer than the wheel's at least (DAO = m (ZO2 + 2.5), XO = 0), shifts
    0 to 0.3 with X2 >= X1."""
    m, z1 = length(rng, -1, 2), float(rng.integers(18, 61))
    z2 = z1 + float(rng.integers(20, 81))
    zo2 = float(rng.integers(18, min(41, int(z2) - 9)))      # 10 teeth fewer than z2 at least
    x1 = float(rng.uniform(0.0, 0.3))
    return [m, z1, z2, x1, float(rng.uniform(x1, 0.3)), zo2, m * zo2, 0.0, m * (zo2 + 2.5)]


def chk_dgmzvn(args, out, bound):
    """The mesh: A, XD, the involute equation of the internal mesh for ALFAW, AW, the
    reference and operating pitch circles (their radii differ by AW, in the ratio of the
    teeth), y and dy; then the teeth (_dgmzvn_teeth).  The tip and root diameters
    themselves are not derived here (test_gears.py compares them with Fig. 48)."""
    m, z1, z2, x1, x2, zo2, do, xo, dao = args
    a = m * (z2 - z1) / 2
    xd = x2 - x1
    inv_w = inv(ALPHA) + 2 * xd * math.tan(ALPHA) / (z2 - z1)
    aw = a * math.cos(ALPHA) / math.cos(out.ALFAW)
    dw1, dw2 = 2 * aw * z1 / (z2 - z1), 2 * aw * z2 / (z2 - z1)
    y = (aw - a) / m
    d = m * z2
    return worst(abs(inv(out.ALFAW) - inv_w) / (16 * U * (1 + inv_w) /
                                                math.cos(out.ALFAW) ** 2),
                 abs(out.A - a) / (1e-13 * d), abs(out.XD - xd) / 1e-13,
                 abs(out.AW - aw) / (1e-12 * d), abs(out.D1 - m * z1) / (1e-13 * d),
                 abs(out.D2 - d) / (1e-13 * d), abs(out.DW1 - dw1) / (1e-12 * d),
                 abs(out.DW2 - dw2) / (1e-12 * d), abs(out.XY - y) / (1e-9 * (1 + abs(y))),
                 abs(out.XUR - (xd - y)) / (1e-9 * (1 + abs(y))),
                 *_dgmzvn_teeth(m, z1, z2, x1, x2, out))


def _dgmzvn_teeth(m, z1, z2, x1, x2, out):
    """Depths as tip-to-root; tip thicknesses from the involute, s_a = d_a (s/d -+ (inv
    alpha - inv alpha_a)) with s = m (pi/2 +- 2 x tan alpha) (+ the pinion, - the
    internal wheel); the contact ratio from the tip circles the routine gives."""
    out_v = []
    d1, d2 = m * z1, m * z2
    aa1 = math.acos(d1 * math.cos(ALPHA) / out.DA1)
    aa2 = math.acos(d2 * math.cos(ALPHA) / out.DA2)
    s1 = m * (PI / 2 + 2 * x1 * math.tan(ALPHA))
    s2 = m * (PI / 2 - 2 * x2 * math.tan(ALPHA))
    sa1 = out.DA1 * (s1 / d1 + inv(ALPHA) - inv(aa1))
    sa2 = out.DA2 * (s2 / d2 - inv(ALPHA) + inv(aa2))
    eps = (z1 * math.tan(aa1) - z2 * math.tan(aa2) + (z2 - z1) * math.tan(out.ALFAW)) / (2 * PI)
    for got, want in ((out.H1, (out.DA1 - out.DF1) / 2), (out.H2, (out.DF2 - out.DA2) / 2),
                      (out.SA1, sa1), (out.SA2, sa2)):
        out_v.append(abs(got - want) / (1e-12 * d2))
    out_v.append(abs(out.EALFA - eps) / (1e-10 * eps))
    return out_v


_register("DGMZVN", gen_dgmzvn, chk_dgmzvn)
