"""Chapter 8: dynamics of the machine (listings VIII.1-VIII.2, book lines L5935-6082).

``DZKNDV`` finds the steady-state law of motion omega(phi) of the reduction link from the
reduced moment and the reduced moment of inertia over one cycle, in the integral (energy)
form of the equation of motion, with the trapezoid rule; ``DMHVK`` the moment of inertia
of the flywheel that keeps the coefficient of speed fluctuation at a given delta
(Merkalov's method, which neglects the variable part of the inertia).

sarkp's extensions: ``DMHVK_EXACT`` (the flywheel with which DZKNDV's rerun has exactly
the delta asked for, beside DMHVK's value); ``motion`` (omega(phi) and t(phi) at fourth
order on any grid, from a given speed, from rest, or the steady cycle) and ``flywheel``
(the exact flywheel at fourth order), which ``sarkp.Mechanism.motion`` and ``.flywheel``
call with a mechanism's reduced inertia and moment.

Units (section 9.3): angles rad, omega rad/s, moments N*m, inertias kg*m^2, work and
energy J.  The tables span exactly one cycle of the reduction link, phi = 0 .. 2*pi with
both ends included: M points, step H = 2*pi/(M - 1).
"""

from __future__ import annotations

import math

import numpy as np

from .errors import RangeError, RequirementError, Status
from . import _wrap_dynamics as _w
from .library import ST_REQUIREMENT, Check, as_real_array, describe
from .modes import get_mode
from .results import Result, result_type

__all__ = ["DZKNDV", "DMHVK", "DMHVK_EXACT", "motion", "flywheel", "Motion", "Flywheel",
           "MotionWarning", "simulate", "Simulation", "Event"]

_COUNT = range(2, 2**31 - 1)

DZKNDV = describe(
    _w.DZKNDV, listing="VIII.1", lines="L5935-5990",
    checks=(Check(lambda M, ZM, **_: ZM != M, ST_REQUIREMENT,
                  "ZM must equal M: the book passes the number of points twice, as an "
                  "integer and as a real (the step is 2*pi/(ZM - 1))"),),
    messages={ST_REQUIREMENT: "the kinetic energy would go negative: no steady motion "
                              "with the mean speed W1 has real speeds (the machine would "
                              "stall). Size a flywheel from DEC (DEC does not depend on "
                              "ISC, and is still computed): DZKNDV(..., "
                              "on_error='nan').DEC (or this error's .result.DEC) into "
                              "DMHVK, or DMHVK_EXACT for the exact flywheel"},
    doc="""Steady-state law of motion of the reduction link, energy form (listing VIII.1).

    Listing VIII.1 (L5939-5990), block diagram Fig. 70, eqs. (8.13)-(8.17), operator
    function (8.18).  The book's call is ``CALL DZKNDV(M, ZM, W1, ISC, MPR, ISPR, AAA, AS,
    ASUM, EV, DEC, WPR, EPR)``.

    Returns
    -------
    DZKNDV(AS, ASUM, EV, DEC, WPR, EPR)
        Arrays of M values:

        * ``AS``: the trapezoid integral of MPR from phi = 0 (DINTGR, NOMER = 2), J;
        * ``ASUM``: ``AS - (k-1)*AS[M-1]/(M-1)``, the total work when the constant driving
          moment ``-AS[M-1]/(2*pi)`` that makes the cycle's work zero (steady state) is
          added; ``ASUM[0] = ASUM[M-1] = 0``;
        * ``EV``: ``ISPR*W1**2/2``, the kinetic energy of the variable-inertia links at
          the mean speed, J;
        * ``DEC``: ``(ASUM - EV) - (ASUM[0] - EV[0])``, the change of the kinetic energy of
          the constant-inertia links (DMHVK's input), J;
        * ``WPR``: omega(phi), rad/s;
        * ``EPR``: ``(WPR[k] - WPR[k-1])/H``, ``EPR[0] = EPR[1]`` (DFRNCL; 0 as
          printed, E-DFRNCL-1): the backward
          difference d(omega)/d(phi) in 1/s, NOT the angular acceleration the listing's
          comment and the text (L5929) call it (ERRATA E-DZKNDV-1); the angular
          acceleration is ``WPR*EPR``.

    Raises
    ------
    RequirementError
        Corrected mode: no steady motion with mean speed W1 has real speeds -- the kinetic
        energy would go negative somewhere in the cycle (the machine stalls).  AS, ASUM,
        EV and DEC are still computed (they do not depend on ISC): with
        ``on_error="nan"`` they are returned, with WPR and EPR NaN and ``status``
        REQUIREMENT; the error raised otherwise carries that result as ``.result``.  A
        flywheel sized from DEC (DMHVK, or DMHVK_EXACT) gives the steady motion.  Also
        raised when ZM differs from M (then every output is NaN under ``on_error="nan"``).

    Notes
    -----
    WPR, as printed, is eq. (8.17): ``W1 + (DEC - (C1 + C2)/2)/(W1*ISC)`` with C1, C2 the
    extremes of DEC, a linearisation (Delta E = J_c omega_sr Delta omega) that holds only
    for a vanishing fluctuation; it gives negative speeds when the fluctuation is large
    (Fig. 96 without flywheel: WPR = -290 rad/s).  As-printed mode keeps it (Fig. 96 depends
    on it).  Corrected mode solves the energy equation (8.13) itself,
    ``(ISC + ISPR[k])*WPR[k]**2/2 = E0 + ASUM[k]``, with E0 fixed by the same normalisation
    (max WPR + min WPR)/2 = W1, so that WPR is exact up to the trapezoid rule's O(H**2)
    (ERRATA E-DZKNDV-2; tests/test_dynamics.py checks it against a closed form and
    against scipy's solve_ivp).  E0 comes in closed form from the two points where DEC
    has its extremes (where omega has them, exactly so for ISPR = 0), checked by the pass
    that computes WPR (repeated with WPR's extremes if they sit elsewhere; Newton's method
    inside a bracket if that does not settle).  For a fourth-order law of motion on any
    grid, from rest too, see :func:`sarkp.motion`.  PI is 3.14159 as printed (the
    listing's local PI, L5955).
    The printed DINTGR writes a line to unit 3 on every call; nothing is printed here.
    """)

DMHVK = describe(
    _w.DMHVK, listing="VIII.2", lines="L6052-6082",
    checks=(Check(lambda DELTA, **_: not 0.0 < DELTA < 1.0, ST_REQUIREMENT,
                  "DELTA, the coefficient of speed fluctuation (omega_max - omega_min)/"
                  "omega_sr, must lie in (0, 1)"),),
    doc="""Moment of inertia of the flywheel (listing VIII.2).

    Listing VIII.2 (L6055-6082), eqs. (8.22)/(8.24): ``IMHVK = (max DEC - min DEC)/
    (DELTA*W1**2) - ISC``, the flywheel that keeps the coefficient of speed fluctuation
    (omega_max - omega_min)/W1 at DELTA, neglecting the variable part J_v of the reduced
    inertia (J_A = J_B = J_c, L6034).

    Returns
    -------
    DMHVK(IMHVK)
        The flywheel's moment of inertia on the reduction link's shaft (kg*m^2).  A
        negative value means that no flywheel is needed.

    Raises
    ------
    RequirementError
        DELTA not in (0, 1).

    Notes
    -----
    With DEC from DZKNDV, DZKNDV rerun with ``ISC + IMHVK`` gives exactly the coefficient
    DELTA: as printed for any ISPR (the linear law (8.17)), in corrected mode for
    ISPR = 0 (then the energy equation gives it exactly too, since
    (omega_max**2 - omega_min**2)/2 = delta*omega_sr**2); with a variable ISPR it is
    Merkalov's approximation (Fig. 96's machine: 0.00997 for 0.01; ERRATA E-T8-3), and
    :func:`DMHVK_EXACT` gives the exact flywheel beside it.  When the machine stalls
    without a flywheel, DZKNDV's ``on_error="nan"`` result (or its error's ``.result``)
    still holds DEC.  The printed ``C1 + ABS(C2)``
    is the swing C1 - C2 whenever C1 >= 0 >= C2, which DZKNDV's DEC (DEC[0] = 0) always
    satisfies; the swing is used for any DEC (ERRATA E-DMHVK-3).
    """)


# ---------------------------------------------------------------------------------------
# sarkp's extensions: the law of motion from a given start and the exact flywheel
# (the functions that sarkp.Mechanism.motion and .flywheel call)
# ---------------------------------------------------------------------------------------
#
# The energy equation (8.13) on any increasing grid phi:
#     J(phi) omega(phi)**2 / 2 = E0 + A(phi),   A(phi) = integral of M from phi[0],
#     t(phi) = t0 + integral of dphi / omega.
# Both integrals use the cubic rule: on each interval, the integral of the cubic through
# the four nearest grid points (the interval's two ends and one neighbour on each side,
# one-sided at the ends of the grid).  On a uniform grid it is
# h/24 (-f[k-1] + 13 f[k] + 13 f[k+1] - f[k+2]): error O(h**5) per interval, O(h**4)
# over the grid (the book's trapezoid rule, DINTGR, is O(h**2)).
#
# 1/omega has an integrable singularity when the crank starts from rest (omega ~ sqrt(s),
# s = phi - phi[0]), and is nearly singular when it starts slowly.  With M(phi[0]) > 0 and
# c = E0/M(phi[0]) >= 0, 1/omega = g(s)/sqrt(s + c) where g = sqrt(J (s + c)/(2 E)) is
# smooth (g(0) = sqrt(J[0]/(2 M[0])) at rest); t is the integral of the cubic through g
# against the weight 1/sqrt(s + c) ("product integration"), computed exactly: with
# u = sqrt(s + c) it is the integral of 2 g(u**2 - c) du, a polynomial of degree 6 in u,
# which the 4-point Gauss-Legendre rule in u integrates exactly.  No division by zero.

_GAUSS2 = np.polynomial.legendre.leggauss(2)
_GAUSS4 = np.polynomial.legendre.leggauss(4)


Motion = result_type(
    "Motion", ("phi", "omega", "t", "E0", "M_constant", "omega_mean", "delta", "status"),
    doc="""The law of motion of the crank over a grid (the result of :func:`motion`).

    Fields: ``phi``, ``omega``, ``t`` -- the grid (rad), the angular velocity there
    (rad/s), the time (s); ``E0`` -- the constant of the energy equation ``J omega**2/2 =
    E0 + A`` (J); ``M_constant`` -- the constant moment added to M (N*m): 0 from a given
    start; for the steady state ``-A(end)/(phi[-1] - phi[0])``, which makes the cycle's
    work zero (as DZKNDV's ASUM does); ``omega_mean`` -- ``(max omega + min omega)/2``
    over the grid (the book's mean, L6044); ``delta`` -- the coefficient of speed
    fluctuation ``(max omega - min omega)/omega_mean``; ``status`` -- sarkp.Status OK, or
    REQUIREMENT when (``on_error="nan"``) the crank stops inside the grid (omega and t
    NaN from there on) or the steady motion would stall (all NaN).
    A sarkp result: a named tuple that pickles, prints short and has ``to_frame()``.""")

Flywheel = result_type(
    "Flywheel", ("J_flywheel", "J_merkalov", "delta", "phi", "omega", "t"),
    doc="""The flywheel for a coefficient of speed fluctuation (:func:`flywheel`'s result).

    Fields: ``J_flywheel`` -- the moment of inertia to add on the crank (kg*m^2): the
    steady motion with ``J + J_flywheel`` has exactly the coefficient asked for
    (negative when the machine fluctuates less than that without a flywheel);
    ``J_merkalov`` -- DMHVK's approximation (Merkalov's method, eqs. (8.22)/(8.24)),
    which neglects the variable part of J: ``swing of (A - (J - J_c) omega_mean**2/2)/
    (delta omega_mean**2) - J_c`` with J_c the constant part; ``delta`` -- the
    coefficient of that steady motion, computed again; ``phi``, ``omega``, ``t`` -- that
    steady motion.  A sarkp result (pickles, prints short, ``to_frame()``).""")


def _motion(phi, omega, t, e0, mc, status=Status.OK):
    ok = omega[np.isfinite(omega)]
    hi, lo = (float(ok.max()), float(ok.min())) if ok.size else (math.nan, math.nan)
    mean = (hi + lo) / 2.0
    delta = (hi - lo) / mean if mean else math.nan
    return Motion(phi, omega, t, float(e0), float(mc), mean, delta, status)


def _finite(who, r):
    """r, or RangeError where omega or t is not a finite double while the motion was
    computed there (NaN after the crank stops is the on_error="nan" policy; inf never)."""
    bad = np.isinf(r.omega) | np.isinf(r.t)
    if getattr(r, "status", Status.OK) == Status.OK:
        bad |= np.isnan(r.omega) | np.isnan(r.t)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise RangeError(f"{who}: omega or t would not be a finite double (overflow) at "
                         f"phi[{k}] = {float(r.phi[k])!r}; the inputs are too far apart in "
                         f"magnitude")
    return r


def _real_vector(who, arg, value, n=None):
    """``value`` as a 1-D float array (a number repeated n times when n is given), finite,
    of length n; else TypeError/ValueError naming ``arg``."""
    if np.asarray(value).dtype == bool:
        raise TypeError(f"{who}: {arg} must be real numbers, not booleans")
    a = as_real_array(who, arg, value)
    if n is not None and a.ndim == 0:
        a = np.full(n, float(a))
    if a.ndim != 1:
        raise ValueError(f"{who}: {arg} must be one-dimensional (or a number), not of "
                         f"shape {a.shape}")
    if n is not None and len(a) != n:
        raise ValueError(f"{who}: {arg} has {len(a)} values but phi has {n}")
    bad = ~np.isfinite(a)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{who}: {arg}[{k}] = {float(a[k])!r} is not a finite number")
    return np.array(a, dtype=float)


def _scalar(who, arg, value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{who}: {arg} must be a real number, not {type(value).__name__}")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{who}: {arg} = {v!r} is not a finite number")
    return v


def _grid(who, phi, J, M):
    """phi, J, M checked: a strictly increasing grid of >= 4 points, J > 0, all finite."""
    phi = _real_vector(who, "phi", phi)
    n = len(phi)
    if n < 4:
        raise ValueError(f"{who}: phi needs at least 4 points (the cubic rule), not {n}")
    steps = np.diff(phi)
    if not np.all(steps > 0):
        k = int(np.flatnonzero(~(steps > 0))[0])
        raise ValueError(f"{who}: phi must be strictly increasing: phi[{k + 1}] = "
                         f"{float(phi[k + 1])!r} <= phi[{k}] = {float(phi[k])!r}")
    J = _real_vector(who, "J", J, n)
    if not np.all(J > 0):
        k = int(np.flatnonzero(~(J > 0))[0])
        raise ValueError(f"{who}: J, the reduced moment of inertia, must be > 0: "
                         f"J[{k}] = {float(J[k])!r}")
    M = _real_vector(who, "M", M, n)
    return phi, J, M


def _weights(d, x, wg, scale):
    """Quadrature weights (n, 4) on each interval: the 4 Lagrange basis cubics of the
    nodes at offsets d (n, 4), at the offsets x (n, q) of the interval's quadrature
    points, times the point weights wg (q,), times scale (n,).  Basis j is the product of
    x - d[m] over m != j over that of d[j] - d[m]."""
    diff = [x - d[:, m, None] for m in range(4)]
    w = np.empty(d.shape)
    for j in range(4):
        others = [m for m in range(4) if m != j]
        num = diff[others[0]] * diff[others[1]] * diff[others[2]]
        den = ((d[:, j] - d[:, others[0]]) * (d[:, j] - d[:, others[1]])
               * (d[:, j] - d[:, others[2]]))
        w[:, j] = (num @ wg) * (scale / den)
    return w


def _stencils(n):
    """The first node of each interval's 4-point stencil."""
    return np.clip(np.arange(n - 1) - 1, 0, n - 4)


def _cubic_weights(phi):
    """Weights w (n-1, 4): integral over interval k = w[k] . f[first[k]:first[k]+4]."""
    n = len(phi)
    first = _stencils(n)
    h = np.diff(phi)
    d = phi[first[:, None] + np.arange(4)] - phi[:-1, None]        # node offsets
    x, wg = _GAUSS2
    pts = (h[:, None] / 2) * (1.0 + x[None, :])                       # Gauss points
    return first, _weights(d, pts, wg, h / 2)


def _singular_weights(phi, c):
    """Weights as _cubic_weights for the integral of f/sqrt(s + c), s = phi - phi[0],
    f the cubic through the stencil: exact (4-point Gauss-Legendre in u = sqrt(s + c))."""
    n = len(phi)
    first = _stencils(n)
    s = phi - phi[0]
    u = np.sqrt(s + c)
    du = np.diff(s) / (u[1:] + u[:-1])                   # u[k+1] - u[k], without cancelling
    x, wg = _GAUSS4
    ug = u[:-1, None] + (du[:, None] / 2) * (1.0 + x[None, :])
    off = (ug - u[:-1, None]) * (ug + u[:-1, None])     # s(ug) - s[k]
    d = phi[first[:, None] + np.arange(4)] - phi[:-1, None]
    return first, _weights(d, off, wg, du)


def _cumulative(first, w, f):
    """Cumulative integral from the first point: w and first from the weights above."""
    steps = np.einsum("nj,nj->n", w, f[first[:, None] + np.arange(4)])
    return np.concatenate(([0.0], np.cumsum(steps)))


def _pair_energy(a1, j1, a2, j2, w):
    """E0 with sqrt(2(E0 + a1)/j1) + sqrt(2(E0 + a2)/j2) = 2 w, or None.  With x = w + d,
    y = w - d: (j1 - j2) d^2 + 2 w (j1 + j2) d + (j1 - j2) w^2 - 2 (a1 - a2) = 0, divided
    by j1 + j2 (no overflow in the discriminant), the root that stays finite as
    j1 - j2 -> 0."""
    s = j1 + j2
    p1, p2 = j1 / s, j2 / s
    qa, da = p1 - p2, (a1 - a2) / s
    qc = qa * w * w - 2.0 * da
    disc = 16.0 * w * w * p1 * p2 + 8.0 * qa * da
    if not disc >= 0.0:
        return None
    d = -2.0 * qc / (2.0 * w + math.sqrt(disc))
    if not -w <= d <= w:
        return None
    x, y = w + d, w - d
    return 0.5 * ((0.5 * j1 * x * x - a1) + (0.5 * j2 * y * y - a2))


def _speeds(e0, a, j):
    return np.sqrt(np.maximum(2.0 * (e0 + a) / j, 0.0))


def _steady_energy(a, j, w):
    """E0 such that omega = sqrt(2(E0 + a)/j) has (max + min)/2 = w, or None when even the
    least E0 (omega = 0 somewhere) gives a larger mean: the machine stalls.

    The extremes of omega sit where those of a - (j - min j) w^2/2 (the book's DEC) sit,
    for a small fluctuation exactly: E0 in closed form from those two points, then one
    pass to check that omega's extremes are there (else again with the new extremes).
    Without a root, or with one below the least E0 = -min a, the pass is made there: a
    mean above w is a stall, else its extremes are tried next.  Bisection if that does
    not settle in 8 passes (DZKNDV's steady_speeds does the same in Fortran)."""
    lo = -float(a.min())
    dec = a - (j - j.min()) * (w * w / 2.0)
    k1, k2 = int(dec.argmax()), int(dec.argmin())
    for _ in range(8):
        e0 = _pair_energy(a[k1], j[k1], a[k2], j[k2], w)
        if e0 is None or e0 < lo:               # no root, or one below lo: look at lo,
            e0 = lo                             # and retry at its extremes
        om = _speeds(e0, a, j)
        n1, n2 = int(om.argmax()), int(om.argmin())
        if e0 == lo and 0.5 * (om[n1] + om[n2]) > w:
            return None                         # even the least E0 gives more than w
        if e0 > lo and om[k1] >= om[n1] and om[k2] <= om[n2] and \
                abs(0.5 * (om[k1] + om[k2]) - w) <= 1e-12 * w:
            return e0
        k1, k2 = n1, n2

    def excess(e0):
        om = _speeds(e0, a, j)
        return 0.5 * (om.max() + om.min()) - w

    if excess(lo) > 0.0:
        return None
    hi = lo + 2.0 * float(j.max()) * w * w                 # omega >= 2 w everywhere
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if excess(mid) > 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


class _Cycle:
    """The interpolants of one cycle: on interval k (u its fraction, 0..1) the work
    a(u) = asum[k] + h_k * integral of (M's cubic + mc) and J's cubic, each through the
    interval's 4-point stencil.  omega's extremes between grid points are the extremes
    of q = (E0 + a)/(J + jf) (omega^2/2), where q' = 0: a polynomial of degree 6."""

    def __init__(self, phi, J, M, asum, mc):
        P = np.polynomial.polynomial
        n = len(phi)
        first = _stencils(n)
        h = np.diff(phi)
        st = first[:, None] + np.arange(4)
        d = (phi[st] - phi[:-1, None]) / h[:, None]
        V = d[:, :, None] ** np.arange(4)
        self.cJ = np.linalg.solve(V, J[st][..., None])[..., 0]
        cM = np.linalg.solve(V, M[st][..., None])[..., 0]
        cM[:, 0] += mc
        self.cA = np.concatenate((asum[:-1, None], h[:, None] * cM / np.arange(1, 5)),
                                 axis=1)
        self.n, self.P = n, P

    def extreme(self, k, e0, jf, sign):
        """The largest (sign +1) or least (-1) q on the intervals next to grid point k:
        (q, a, j) there."""
        P = self.P
        ivs = {max(k - 1, 0), min(k, self.n - 2)}
        if k in (0, self.n - 1):                    # the cycle's ends are one point
            ivs = {0, self.n - 2}
        best = None
        for i in ivs:
            pa = self.cA[i].copy()
            pa[0] += e0
            pj = self.cJ[i].copy()
            pj[0] += jf
            pa, pj = pa / np.abs(pa).max(), pj / np.abs(pj).max()      # no overflow
            num = P.polysub(P.polymul(P.polyder(pa), pj), P.polymul(pa, P.polyder(pj)))
            roots = P.polyroots(num) if np.any(num[1:]) else np.array([])
            us = [0.0, 1.0] + [float(r.real) for r in roots
                               if abs(r.imag) <= 1e-9 and 0.0 <= r.real <= 1.0]
            for u in us:
                av = float(P.polyval(u, self.cA[i]))
                jv = float(P.polyval(u, self.cJ[i]))
                q = (e0 + av) / (jv + jf)
                if best is None or sign * q > sign * best[0]:
                    best = (q, av, jv)
        return best


def _continuous_energy(cyc, a, j, w, e0, jf=0.0):
    """E0 with (max + min)/2 of the interpolated omega = w: the grid's E0 corrected
    with the extremes located between the grid points (a few passes)."""
    for _ in range(6):
        om = _speeds(e0, a, j + jf)
        k1, k2 = int(om.argmax()), int(om.argmin())
        _, a1, j1 = cyc.extreme(k1, e0, jf, 1)
        _, a2, j2 = cyc.extreme(k2, e0, jf, -1)
        new = _pair_energy(a1, j1 + jf, a2, j2 + jf, w)
        if new is None:
            return e0
        if abs(new - e0) <= 1e-15 * (abs(e0) + abs(a1)):
            return new
        e0 = new
    return e0


def _continuous_flywheel(cyc, a, j, w, delta, jf):
    """The flywheel with omega's extremes between grid points: the closed form of
    _exact_flywheel at the located extremes, a few passes from the grid's jf."""
    x, y = w * (1.0 + 0.5 * delta), w * (1.0 - 0.5 * delta)
    jf0 = jf
    for _ in range(8):
        e0 = _steady_energy(a, j + jf, w)
        if e0 is None:
            break
        om = _speeds(e0, a, j + jf)
        _, a1, j1 = cyc.extreme(int(om.argmax()), e0, jf, 1)
        _, a2, j2 = cyc.extreme(int(om.argmin()), e0, jf, -1)
        new = (a1 - a2 - 0.5 * (j1 * x * x - j2 * y * y)) / (delta * w * w)
        if not np.all(j + new > 0.0):
            break
        done = abs(new - jf) <= 1e-14 * (abs(jf) + float(j.max()))
        jf = new
        if done:
            break
    if abs(_cycle_delta(cyc, a, j, w, jf) - delta) <= 1e-13 * delta:
        return jf
    # the extremes moved between passes: bisection on jf (delta falls as jf grows)
    step = 1e-3 * (abs(jf0) + float(j.max()))
    lo, hi = jf0 - step, jf0 + step
    for _ in range(200):
        if _cycle_delta(cyc, a, j, w, lo) > delta or not np.all(j + lo > 0):
            break
        lo -= (hi - lo)
    for _ in range(200):
        if _cycle_delta(cyc, a, j, w, hi) < delta:
            break
        hi += (hi - lo)
    if not np.all(j + lo > 0):
        lo = -float(j.min()) * (1.0 - 1e-12)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if _cycle_delta(cyc, a, j, w, mid) > delta:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _cycle_delta(cyc, a, j, w, jf):
    """The coefficient of the steady motion with j + jf, extremes located."""
    e0 = _steady_energy(a, j + jf, w)
    if e0 is None:
        return math.inf
    e0 = _continuous_energy(cyc, a, j, w, e0, jf)
    hi, lo = _cycle_extremes(cyc, a, j, e0, jf)
    return (hi - lo) / w


def _cycle_extremes(cyc, a, j, e0, jf=0.0):
    om = _speeds(e0, a, j + jf)
    hi = cyc.extreme(int(om.argmax()), e0, jf, 1)[0]
    lo = cyc.extreme(int(om.argmin()), e0, jf, -1)[0]
    return math.sqrt(max(2.0 * hi, 0.0)), math.sqrt(max(2.0 * lo, 0.0))


def _stall_message(who, w):
    return (f"{who}: no steady motion with mean speed omega_mean = {w!r} rad/s has real "
            f"speeds: the kinetic energy would go negative (the machine stalls); add "
            f"inertia, e.g. a flywheel from sarkp.flywheel")


_GAUSS8 = np.polynomial.legendre.leggauss(8)


def _time_on_interpolants(phi, J, M, energy, first):
    """The time over each interval, the integral of sqrt(J/(2E)) with J the cubic
    through the interval's 4-point stencil and E the energy with M's cubic integrated
    exactly, by adaptive Gauss-Legendre (8 points, halving) in the variable v with
    u = 3v^2 - 2v^3 (u the interval's fraction), whose du/dv vanishes at both ends: an
    inverse square root at either end (a start from rest, a turning point at the end)
    becomes smooth, and a dip of omega between grid points is resolved.

    Returns (steps, where): steps (n-1,) and the first interval where the interpolated
    energy reaches zero (the crank stops there), or None."""
    n = len(phi)
    h = np.diff(phi)
    st = first[:, None] + np.arange(4)
    d = (phi[st] - phi[:-1, None]) / h[:, None]                  # stencil offsets in u
    V = d[:, :, None] ** np.arange(4)
    cJ = np.linalg.solve(V, J[st][..., None])[..., 0]            # cubics in u
    cM = np.linalg.solve(V, M[st][..., None])[..., 0]
    cE = np.concatenate((energy[:-1, None], h[:, None] * cM / np.arange(1, 5)), axis=1)
    x, wg = _GAUSS8
    xg, wg = 0.5 * (x + 1.0), 0.5 * wg

    def piece(k, a, b):
        """Gauss on [a, b] of v for the intervals k; (value, the least energy seen)."""
        v = a[:, None] + (b - a)[:, None] * xg
        u = v * v * (3.0 - 2.0 * v)
        du = 6.0 * v * (1.0 - v)
        jj = np.polynomial.polynomial.polyval(u.T, cJ[k].T, tensor=False).T
        ee = np.polynomial.polynomial.polyval(u.T, cE[k].T, tensor=False).T
        f = np.sqrt(np.maximum(jj, 0.0) / (2.0 * np.maximum(ee, 1e-300))) * du
        return (b - a) * (f @ wg), ee.min(axis=1)

    k = np.arange(n - 1)
    a, b = np.zeros(n - 1), np.ones(n - 1)
    whole, emin = piece(k, a, b)
    total = np.zeros(n - 1)
    low = np.full(n - 1, np.inf)
    np.minimum.at(low, k, emin)
    for _ in range(60):
        if k.size == 0:
            break
        mid = 0.5 * (a + b)
        left, e1 = piece(k, a, mid)
        right, e2 = piece(k, mid, b)
        np.minimum.at(low, k, np.minimum(e1, e2))
        both = left + right
        done = np.abs(both - whole) <= 1e-12 * np.abs(both) + 1e-300
        done |= (low[k] <= 0.0) | (b - a < 1e-9) | (k.size > 64 * n)
        np.add.at(total, k[done], both[done])
        keep = ~done
        k = np.concatenate((k[keep], k[keep]))
        a, b = np.concatenate((a[keep], mid[keep])), np.concatenate((mid[keep], b[keep]))
        whole = np.concatenate((left[keep], right[keep]))
    else:
        np.add.at(total, k, whole)
    stops = np.flatnonzero(low <= 0.0)
    return h * total, (int(stops[0]) if stops.size else None)


class MotionWarning(UserWarning):
    """motion: omega comes so close to zero between grid points that the grid does not
    resolve it; t is computed on the interpolants instead (see the message)."""


def motion(phi, J, M, *, omega0=0.0, t0=0.0, omega_mean=None, on_error="raise"):
    """Law of motion of the crank: omega(phi) and t(phi) from the energy equation.

    A sarkp extension of chapter 8 (eq. (8.13), the energy form of the equation of
    motion): ``J(phi) omega**2/2 = E0 + integral of M from phi[0]``, with the reduced
    moment of inertia J and the reduced moment M given on a grid (loads that depend on
    the position only, springs included), and ``t = t0 + integral of dphi/omega``.

    Either from a given start -- ``omega0`` at ``phi[0]``, 0 (the default) starting from
    rest -- or, with ``omega_mean``, the steady periodic motion over one cycle as DZKNDV
    finds it: the grid spans exactly one cycle (J[0] = J[-1]), a constant moment
    ``M_constant`` is added so that the cycle's work is zero, and ``(max omega + min
    omega)/2 = omega_mean`` (the book's mean, L6044); t then starts at t0 at phi[0].

    Both integrals use the cubic rule (the integral, on each interval, of the cubic
    through the four nearest grid points; on a uniform grid ``h/24 (-f[k-1] + 13 f[k] +
    13 f[k+1] - f[k+2])``), fourth order in the grid step; the book's trapezoid rule
    (DZKNDV) is second order.  From rest, 1/omega has an integrable singularity at phi[0]
    (omega ~ sqrt(phi - phi[0])): t is then integrated with the weight
    ``1/sqrt(phi - phi[0] + c)`` taken exactly (c = E0/M[0]; product integration), which
    keeps the fourth order and never divides by zero; a slow start (small omega0) is
    handled the same way.

    Parameters
    ----------
    phi : array_like, shape (n,)
        The crank angle (rad), strictly increasing, n >= 4 points; any spacing.
    J : array_like, shape (n,), or float
        The reduced moment of inertia about the crank (kg*m^2, > 0).
    M : array_like, shape (n,), or float
        The reduced moment of all the forces (N*m), positive when it drives the crank
        (its work over dphi is M dphi).
    omega0 : float, keyword-only
        The angular velocity at phi[0] (rad/s, >= 0; 0: from rest, then M[0] > 0).
    t0 : float, keyword-only
        The time at phi[0] (s).
    omega_mean : float, optional, keyword-only
        The mean speed of the steady motion (rad/s, > 0); not with omega0.
    on_error : {"raise", "nan"}, keyword-only
        When the crank comes to rest inside the grid (or the steady motion would stall):
        ``"raise"`` RequirementError; ``"nan"``: omega and t NaN from there (all of them
        for the steady motion; t after phi[0] too when fewer than 4 points precede the
        stop, too few for the rule) and ``status`` REQUIREMENT.

    Returns
    -------
    Motion
        ``.phi, .omega, .t``, and ``.E0``, ``.M_constant``, ``.omega_mean``, ``.delta``
        (the coefficient of speed fluctuation), ``.status`` (a sarkp result: a named
        tuple that pickles, prints short and has ``to_frame()``).

    Raises
    ------
    ValueError
        Bad input, naming the argument: phi not strictly increasing or shorter than 4
        points, J <= 0, lengths that differ, NaN or inf, omega0 < 0, omega_mean <= 0, a
        start from rest with M[0] <= 0, a steady motion over a grid with J[0] != J[-1].
    RequirementError
        The crank stops inside the grid (the kinetic energy reaches zero), or the steady
        motion with mean speed omega_mean would stall.
    RangeError
        omega or t would not be a finite double (inputs too far apart in magnitude).
    """
    with np.errstate(all="ignore"):
        r = _motion_law(phi, J, M, omega0, t0, omega_mean, on_error)
    return _finite("motion", r)


def _motion_law(phi, J, M, omega0, t0, omega_mean, on_error):
    who = "motion"
    phi, J, M = _grid(who, phi, J, M)
    omega0 = _scalar(who, "omega0", omega0)
    t0 = _scalar(who, "t0", t0)
    if on_error not in ("raise", "nan"):
        raise ValueError(f"{who}: on_error must be 'raise' or 'nan', not {on_error!r}")
    first, w = _cubic_weights(phi)
    A = _cumulative(first, w, M)
    n = len(phi)
    if omega_mean is not None:
        wm = _scalar(who, "omega_mean", omega_mean)
        if not wm > 0.0:
            raise ValueError(f"{who}: omega_mean = {wm!r} must be > 0")
        if omega0 != 0.0:
            raise ValueError(f"{who}: give omega0 (a start) or omega_mean (the steady "
                             f"motion), not both")
        if abs(J[-1] - J[0]) > 1e-9 * J.max():
            raise ValueError(f"{who}: the steady motion needs a grid over exactly one "
                             f"cycle, but J[0] = {float(J[0])!r} differs from J[-1] = "
                             f"{float(J[-1])!r}")
        mc = -A[-1] / (phi[-1] - phi[0])
        asum = A + mc * (phi - phi[0])
        e0 = _steady_energy(asum, J, wm)
        cyc = None
        if e0 is not None:
            try:
                cyc = _Cycle(phi, J, M, asum, mc)
                e0 = _continuous_energy(cyc, asum, J, wm, e0)
            except (np.linalg.LinAlgError, ValueError, FloatingPointError):
                cyc = None                             # out of range: the grid's extremes
        if e0 is None:
            if on_error == "raise":
                raise RequirementError(_stall_message(who, wm))
            nan = np.full(n, np.nan)
            return _motion(phi, nan, nan.copy(), math.nan, mc, Status.REQUIREMENT)
        omega = _speeds(e0, asum, J)
        t = t0 + _cumulative(first, w, 1.0 / omega)
        if cyc is None:
            return _motion(phi, omega, t, e0, mc)
        hi, lo = _cycle_extremes(cyc, asum, J, e0)
        return Motion(phi, omega, t, float(e0), float(mc), 0.5 * (hi + lo),
                      (hi - lo) / (0.5 * (hi + lo)), Status.OK)
    if not omega0 >= 0.0:
        raise ValueError(f"{who}: omega0 = {omega0!r} must be >= 0 (the crank turns "
                         f"towards increasing phi)")
    e0 = 0.5 * J[0] * omega0 * omega0
    energy = e0 + A
    if omega0 == 0.0 and not M[0] > 0.0:
        raise ValueError(f"{who}: from rest (omega0 = 0) the crank starts only if "
                         f"M[0] > 0, but M[0] = {float(M[0])!r}")
    status = Status.OK
    stop = n
    dead = np.flatnonzero(energy[1:] <= 0.0)
    if dead.size:
        stop = int(dead[0]) + 1
        if on_error == "raise":
            raise RequirementError(
                f"{who}: the crank comes to rest between phi[{stop - 1}] = "
                f"{float(phi[stop - 1])!r} and phi[{stop}] = {float(phi[stop])!r} (the "
                f"kinetic energy "
                f"reaches zero); a larger omega0 or driving moment is needed to pass")
        status = Status.REQUIREMENT
    omega = np.full(n, np.nan)
    t = np.full(n, np.nan)
    p, Jp, Ep = phi[:stop], J[:stop], energy[:stop]
    omega[:stop] = np.sqrt(np.maximum(2.0 * Ep / Jp, 0.0))
    t[0] = t0
    if stop < 4:                                         # too few points for the rule
        return _motion(phi, omega, t, e0, 0.0, status)
    # 1/omega = g/sqrt(s + c): the weight taken exactly while c is not huge against the
    # grid (M[0] = 2e-308 made c overflow and t NaN or 4e-3 wrong: found by Hypothesis);
    # for a larger c the weight is smooth and the cubic rule is exact enough
    if M[0] > 0.0 and e0 / M[0] <= 1e6 * (phi[-1] - phi[0]):
        c = e0 / M[0]
        s = p - p[0]
        g = np.empty(stop)
        g[1:] = np.sqrt(Jp[1:] * (s[1:] + c) / (2.0 * Ep[1:]))
        g[0] = math.sqrt(Jp[0] / (2.0 * M[0]))          # the limit s -> 0, also for c > 0
        fs, ws = _singular_weights(p, c)
        t[:stop] = t0 + _cumulative(fs, ws, g)
    else:
        fs, ws = _cubic_weights(p)
        t[:stop] = t0 + _cumulative(fs, ws, 1.0 / omega[:stop])
    # the check: the time again on the interpolants of J and the energy, adaptively (a
    # turning point at the end, a dip of omega between grid points); where the two
    # differ the grid does not resolve omega: that time is taken, with a warning, and an
    # energy reaching zero between grid points is a stop
    steps, where = _time_on_interpolants(p, Jp, M[:stop], Ep, _stencils(stop))
    rule = np.diff(t[:stop])
    if where is not None:
        if on_error == "raise":
            raise RequirementError(
                f"{who}: the crank comes to rest between phi[{where}] = "
                f"{float(phi[where])!r} and phi[{where + 1}] = {float(phi[where + 1])!r} "
                f"(the interpolated kinetic energy reaches zero between these grid "
                f"points: a turning point); Mechanism.simulate follows the motion on")
        omega[where + 1:] = np.nan
        t[where + 1:] = np.nan
        return _motion(phi, omega, t, e0, 0.0, Status.REQUIREMENT)
    # where omega comes near zero (below a fifth of its largest value on the grid) the
    # cubic rule on 1/omega is not to be trusted when the two differ
    wk = omega[:stop]
    slow = np.minimum(wk[:-1], wk[1:]) < 0.2 * float(np.max(wk))
    off = slow & (np.abs(rule - steps) > 1e-4 * np.abs(steps))
    if off.any():
        k = int(np.argmax(np.where(off, np.abs(rule - steps), -1.0)))
        new = t0 + np.concatenate(([0.0], np.cumsum(steps)))
        import warnings
        warnings.warn(MotionWarning(
            f"{who}: omega comes close to zero near phi = {float(phi[k])!r} (omega = "
            f"{float(min(omega[k], omega[k + 1]))!r} at the grid points there) and the "
            f"grid does not resolve 1/omega: t is integrated on the interpolated J and "
            f"energy instead (t[-1] = {float(new[-1])!r} s; the cubic rule gave "
            f"{float(t[stop - 1])!r} s); refine the grid there, or use "
            f"Mechanism.simulate"), stacklevel=3)
        t[:stop] = new
    return _motion(phi, omega, t, e0, 0.0, status)


def _exact_flywheel(a, j, w, delta):
    """The constant inertia jf such that the steady motion with j + jf (energy equation,
    work table a, mean speed w) has (max - min)/w = delta exactly.

    With the extremes at points k1, k2: omega there is w (1 +- delta/2) and
    (j1 + jf) x^2/2 - a1 = (j2 + jf) y^2/2 - a2 (= E0) is linear in jf:
    jf = (a1 - a2 - (j1 x^2 - j2 y^2)/2)/(delta w^2), as (x^2 - y^2)/2 = delta w^2.
    Then one pass checks that the extremes are at k1, k2 (else again with the new ones;
    bisection on jf if that does not settle).  Returns (jf, E0)."""
    x, y = w * (1.0 + 0.5 * delta), w * (1.0 - 0.5 * delta)
    dec = a - (j - j.min()) * (w * w / 2.0)
    k1, k2 = int(dec.argmax()), int(dec.argmin())
    for _ in range(8):
        jf = (a[k1] - a[k2] - 0.5 * (j[k1] * x * x - j[k2] * y * y)) / (delta * w * w)
        if not np.all(j + jf > 0.0):
            break
        e0 = 0.5 * (j[k1] + jf) * x * x - a[k1]
        om = _speeds(e0, a, j + jf)
        n1, n2 = int(om.argmax()), int(om.argmin())
        if om[k1] >= om[n1] and om[k2] <= om[n2] and e0 + a.min() >= 0.0 and \
                abs(om[k1] - om[k2] - delta * w) <= 1e-12 * delta * w:
            return jf, e0
        k1, k2 = n1, n2

    def fluctuation(jf):                       # decreases as jf grows; inf at a stall
        e0 = _steady_energy(a, j + jf, w)
        if e0 is None:
            return math.inf
        om = _speeds(e0, a, j + jf)
        return (om.max() - om.min()) / w

    lo = -float(j.min()) * (1.0 - 1e-12)
    hi = max(1.0, 2.0 * float(np.ptp(dec)) / (delta * w * w))
    for _ in range(2100):                      # up to the largest double
        if not fluctuation(hi) > delta:
            break
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        if fluctuation(mid) > delta:
            lo = mid
        else:
            hi = mid
    jf = 0.5 * (lo + hi)
    return jf, _steady_energy(a, j + jf, w)


def _merkalov(a, j, w, delta, j_constant):
    """DMHVK's flywheel (eq. (8.22)/(8.24)): the swing of DEC = a - J_v w^2/2 over
    delta w^2, minus the constant part J_c (J_v = j - J_c)."""
    dec = a - (j - j_constant) * (w * w / 2.0)
    return float(dec.max() - dec.min()) / (delta * w * w) - j_constant


def flywheel(phi, J, M, *, delta, omega_mean, J_constant=None):
    """The flywheel that gives the steady motion exactly the coefficient delta.

    A sarkp extension of chapter 8: the moment of inertia ``J_flywheel`` to add on the
    crank so that the steady motion (:func:`motion` with ``omega_mean``) with
    ``J + J_flywheel`` has the coefficient of speed fluctuation ``(max omega - min
    omega)/omega_mean`` exactly ``delta`` (to rounding), with DMHVK's approximation
    (Merkalov's method, eqs. (8.22)/(8.24): it neglects the variable part of J) beside it.
    The work of M uses the cubic rule (fourth order, see :func:`motion`).

    The extremes of omega sit at two grid points; there the energy equation is linear in
    the added inertia, which gives it in closed form, and one pass over the grid checks
    that the extremes are where they were assumed (a bisection takes over if they move).

    Parameters
    ----------
    phi, J, M : array_like
        As for :func:`motion`, over exactly one cycle (J[0] = J[-1]).
    delta : float, keyword-only
        The coefficient of speed fluctuation, in (0, 1).
    omega_mean : float, keyword-only
        The mean speed (max omega + min omega)/2, rad/s, > 0.
    J_constant : float, optional, keyword-only
        The constant part J_c of J for Merkalov's value (DMHVK's ISC): by default min J,
        so that the variable part J - J_c is >= 0 as in the book.

    Returns
    -------
    Flywheel
        ``.J_flywheel`` (exact; negative when less fluctuation than delta needs no
        flywheel), ``.J_merkalov``, ``.delta`` (realized: the steady motion with
        ``J + J_flywheel`` computed again) and ``.phi, .omega, .t`` (that motion).

    Raises
    ------
    ValueError
        Bad input, naming the argument (as :func:`motion`; delta outside (0, 1),
        omega_mean <= 0, J_constant outside [0, min J]).
    RangeError
        delta*omega_mean**2 underflows, or the inertia needed is lost in the rounding of
        J (no double J_flywheel gives delta), or the motion overflows.
    """
    with np.errstate(all="ignore"):
        fw = _flywheel(phi, J, M, delta, omega_mean, J_constant)
    if not (math.isfinite(fw.J_flywheel) and math.isfinite(fw.J_merkalov)):
        raise RangeError("flywheel: J_flywheel would not be a finite double (overflow); "
                         "the inputs are too far apart in magnitude")
    _finite("flywheel", fw)
    if not abs(fw.delta - delta) <= 1e-9 * delta:
        raise RangeError(f"flywheel: no double J_flywheel gives delta = {delta!r} (it gives "
                         f"{fw.delta!r}): the inertia needed, J + J_flywheel, is lost in the "
                         f"rounding of J")
    return fw


def _flywheel(phi, J, M, delta, omega_mean, J_constant):
    who = "flywheel"
    phi, J, M = _grid(who, phi, J, M)
    delta = _scalar(who, "delta", delta)
    if not 0.0 < delta < 1.0:
        raise ValueError(f"{who}: delta = {delta!r}, the coefficient of speed fluctuation "
                         f"(omega_max - omega_min)/omega_mean, must lie in (0, 1)")
    wm = _scalar(who, "omega_mean", omega_mean)
    if not wm > 0.0:
        raise ValueError(f"{who}: omega_mean = {wm!r} must be > 0")
    if not delta * wm * wm > 0.0:
        raise RangeError(f"{who}: delta*omega_mean**2 = {delta!r}*{wm!r}**2 is not a "
                         f"normal double (underflow)")
    if abs(J[-1] - J[0]) > 1e-9 * J.max():
        raise ValueError(f"{who}: the steady motion needs a grid over exactly one cycle, "
                         f"but J[0] = {float(J[0])!r} differs from J[-1] = "
                         f"{float(J[-1])!r}")
    if J_constant is None:
        jc = float(J.min())
    else:
        jc = _scalar(who, "J_constant", J_constant)
        if not 0.0 <= jc <= J.min():
            raise ValueError(f"{who}: J_constant = {jc!r} must lie in [0, min J = "
                             f"{float(J.min())!r}]")
    first, w = _cubic_weights(phi)
    A = _cumulative(first, w, M)
    mc = -A[-1] / (phi[-1] - phi[0])
    asum = A + mc * (phi - phi[0])
    jf, _ = _exact_flywheel(asum, J, wm, delta)
    if math.isfinite(jf) and np.isfinite(asum).all():
        try:
            jf = _continuous_flywheel(_Cycle(phi, J, M, asum, mc), asum, J, wm, delta, jf)
        except (np.linalg.LinAlgError, ValueError, FloatingPointError):
            pass                                       # out of range: the grid's extremes
    mo = motion(phi, J + jf, M, omega_mean=wm)
    return Flywheel(float(jf), _merkalov(asum, J, wm, delta, jc), mo.delta, mo.phi,
                    mo.omega, mo.t)


_DMHVK_EXACT = result_type("DMHVK_EXACT", ("IMHVK", "IMERK", "DELTA"))


def DMHVK_EXACT(M, ZM, W1, ISC, MPR, ISPR, DELTA):
    """The exact flywheel for DZKNDV (a sarkp extension beside DMHVK, listing VIII.2).

    The moment of inertia IMHVK to add to ISC so that DZKNDV rerun with ``ISC + IMHVK``
    gives the coefficient of speed fluctuation ``(max WPR - min WPR)/W1`` exactly DELTA
    (to rounding), where DMHVK (Merkalov's method, eqs. (8.22)/(8.24)) neglects the
    variable part ISPR of the inertia in corrected mode (its value, IMERK, is returned
    beside).  It works whether or not DZKNDV finds a steady motion with ISC alone.

    The arguments are DZKNDV's, in its order, and DELTA.  Corrected mode: at the two
    points where WPR has its extremes, W1 (1 +- DELTA/2), the energy equation of DZKNDV
    is linear in the added inertia, which gives it in closed form from DZKNDV's own ASUM
    (the same trapezoid rule); one pass over the table checks that the extremes are
    there (a bisection takes over if they move).  This is the book's own tangent
    construction on the energy-mass diagram, eqs. (8.20)-(8.21) (L6018-6030), with the
    tangent points found exactly; DMHVK's (8.22)/(8.24) takes them at DEC's extremes,
    which are omega's only for a constant inertia (ERRATA E-T8-3).  As printed,
    DZKNDV's linear law (8.17) makes DMHVK itself exact: IMHVK = IMERK.

    Parameters
    ----------
    M, ZM, W1, ISC, MPR, ISPR
        As for DZKNDV.
    DELTA : float
        The coefficient of speed fluctuation, in (0, 1).

    Returns
    -------
    DMHVK_EXACT(IMHVK, IMERK, DELTA)
        ``IMHVK``: the exact flywheel (kg*m^2; negative when no flywheel is needed);
        ``IMERK``: DMHVK's value from DZKNDV's DEC; ``DELTA``: the coefficient of
        DZKNDV rerun with ``ISC + IMHVK``.

    Raises
    ------
    ValueError
        Bad input, as DZKNDV and DMHVK raise it (DELTA outside (0, 1) among them).
    RequirementError
        No flywheel is needed and even ISC + IMHVK <= 0 would be (the fluctuation stays
        below DELTA).
    RangeError
        No double IMHVK gives DELTA (ISC + ISPR + IMHVK lost in the rounding).
    """
    delta = _scalar("DMHVK_EXACT", "DELTA", DELTA)
    if not 0.0 < delta < 1.0:
        raise ValueError(f"DMHVK_EXACT: DELTA = {delta!r}, the coefficient of speed "
                         f"fluctuation (omega_max - omega_min)/omega_sr, must lie in "
                         f"(0, 1)")
    first = DZKNDV(M, ZM, W1, ISC, MPR, ISPR, on_error="nan")
    if np.isnan(first.DEC).all():                      # ZM != M: raise its error
        DZKNDV(M, ZM, W1, ISC, MPR, ISPR)
    imerk = DMHVK(M, delta, ISC, W1, first.DEC)
    imerk = float(imerk[0] if isinstance(imerk, tuple) else imerk)
    if get_mode() == "as-printed":
        imh = imerk
    else:
        j = ISC + np.asarray(ISPR, dtype=float)
        imh, _ = _exact_flywheel(first.ASUM, j, float(W1), delta)
    if not ISC + imh > 0.0:
        raise RequirementError(
            f"DMHVK_EXACT: no flywheel is needed: the fluctuation would reach DELTA = "
            f"{delta!r} only with the constant inertia ISC + IMHVK = "
            f"{float(ISC + imh)!r} <= 0 (IMHVK = {float(imh)!r})")
    w = DZKNDV(M, ZM, W1, ISC + imh, MPR, ISPR).WPR
    realized = float((w.max() - w.min()) / W1)
    if get_mode() != "as-printed" and not abs(realized - delta) <= 1e-9 * delta:
        raise RangeError(f"DMHVK_EXACT: no double IMHVK gives DELTA = {delta!r} (it gives "
                         f"{realized!r}): ISC + ISPR + IMHVK is lost in the rounding")
    return _DMHVK_EXACT(float(imh), imerk, realized)


# -- motion in time ------------------------------------------------------------------------
#
# The crank's equation of motion J(phi) phi'' + J'(phi) phi'^2/2 = M_red(phi, phi', t) is
# integrated as the first-order system (phi, omega)' = (omega, epsilon).  One solve of the
# mechanism at (phi, omega) with epsilon = 0 gives the balancing moment, the moment that
# would hold the crank at epsilon = 0: M_bal = J'(phi) omega^2/2 - M_red, so that the free
# motion has epsilon = -M_bal/J.  The solve takes every stage of a step at once: the
# method is Gauss-Legendre collocation (s nodes, order 2s at the step's end, stage order
# s inside it), its equations solved by fixed-point (Picard) iteration, each sweep one
# vectorised call of the mechanism over the s nodes.  The collocation polynomial is the
# dense output; the error estimate is the size of its highest Legendre mode (the stage
# order's error, so that the dense output too is held to rtol).

_NODES = 8


def _collocation(s):
    """Gauss-Legendre nodes c and weights b on [0, 1], the barycentric weights of the
    nodes, and the weights of the highest Legendre mode of F on [0, 1]."""
    x, w = np.polynomial.legendre.leggauss(s)
    c, b = 0.5 * (x + 1.0), 0.5 * w
    bary = np.array([1.0 / np.prod(c[j] - np.delete(c, j)) for j in range(s)])
    p = np.polynomial.legendre.legval(x, np.eye(s)[s - 1])
    top = (2 * s - 1) * b * p
    return c, b, bary, top


def _lagrange(tau, c, bary):
    """L_j(tau): the Lagrange basis of the nodes c at the points tau, (len(tau), s)
    (the barycentric formula; exact at the nodes)."""
    tau = np.asarray(tau, dtype=float).reshape(-1)
    d = tau[:, None] - c[None, :]
    hit = d == 0.0
    d[hit] = 1.0
    q = bary / d
    L = q / q.sum(axis=1, keepdims=True)
    rows = hit.any(axis=1)
    if rows.any():
        L[rows] = hit[rows].astype(float)
    return L


def _integrals(tau, c, b, bary):
    """(L, P1, P2) at the points tau: L_j(tau), the integral of L_j over [0, tau] and of
    (tau - u) L_j(u) -- by the s-point Gauss rule on [0, tau], exact for these degrees."""
    tau = np.asarray(tau, dtype=float).reshape(-1)
    u = tau[:, None] * c[None, :]                               # (m, s) Gauss points
    Lu = _lagrange(u.reshape(-1), c, bary).reshape(len(tau), len(c), len(c))
    wt = tau[:, None] * b[None, :]
    P1 = np.einsum("mq,mqj->mj", wt, Lu)
    P2 = np.einsum("mq,mqj->mj", wt * (tau[:, None] - u), Lu)
    return _lagrange(tau, c, bary), P1, P2


class _Failed(Exception):
    """A mechanism evaluation failed (a stage beyond the reach of a group)."""


class _Machine:
    """The mechanism's acceleration epsilon(phi, omega, t) in one call for many states,
    with the branches the continuous motion has reached."""

    def __init__(self, m, gravity):
        import copy
        from .errors import SarkpError, SignificanceWarning
        self.m = copy.deepcopy(m)
        self.gravity = gravity
        self.calls = 0
        self.points = 0
        self._errors = (SarkpError, FloatingPointError)
        self._warning = SignificanceWarning
        # the groups whose branch follows the motion: (B, A, C) of each rrr and rpr
        # group, (B, A, K) of each rrp group; rrp: its slider block's link, which turns
        # with the guide (the guide's direction and its rate from the results)
        self.groups = _groups(self.m)
        self.rrp, self.blocks = _guides(self.m)
        self._cfg = None
        # loads that are callables (of phi, omega, t): the solves pass t, and the
        # patches near a crossing take M_red at each stage's own omega and t
        self.dynamic = bool(self.m._tables()["dynamic"])

    def config(self):
        if self._cfg is None:
            self._cfg = tuple(self.m.branch(B) for B, _, _ in self.groups)
        return self._cfg

    def set_config(self, cfg):
        now = self.config()
        if cfg == now:
            return
        for (B, _, _), b, was in zip(self.groups, cfg, now):
            if b != was:
                self.m.set_branch(B, b)
        self._cfg = tuple(cfg)

    def solve(self, phi, omega, t, need):
        import warnings
        self.calls += 1
        self.points += np.size(phi)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", self._warning)
            try:
                return self.m.solve(phi, omega=omega, epsilon=0.0, need=need,
                                    gravity=self.gravity,
                                    t=t if self.dynamic else None)
            except self._errors as e:
                raise _Failed(str(e)) from e

    def solve_with(self, phi, cfg, need):
        """The solve at omega = 1, epsilon = 0 with the branches cfg."""
        self.set_config(cfg)
        return self.solve(np.asarray(phi, dtype=float), 1.0, 0.0, need)

    def epsilon(self, phi, omega, t, cfgs=None):
        """epsilon at the states; cfgs: a branch configuration per state (None: the
        current one).  Returns (epsilon, results by configuration)."""
        if cfgs is None or len(set(cfgs)) == 1:
            if cfgs is not None:
                self.set_config(cfgs[0])
            r = self.solve(phi, omega, t, "forces")
            eps = -r.balancing_moment / r.reduced_inertia
            if not np.isfinite(eps).all():
                raise _Failed("epsilon is not finite")
            return eps, [(np.arange(len(phi)), r)]
        eps = np.empty(len(phi))
        parts = []
        for cfg in dict.fromkeys(cfgs):
            idx = np.array([i for i, c in enumerate(cfgs) if c == cfg])
            self.set_config(cfg)
            r = self.solve(phi[idx], omega[idx], t[idx], "forces")
            eps[idx] = -r.balancing_moment / r.reduced_inertia
            parts.append((idx, r))
        if not np.isfinite(eps).all():
            raise _Failed("epsilon is not finite")
        return eps, parts

    def _columns(self, r):
        """Where the groups' joints are in a result's positions (a frame point: its
        fixed coordinates)."""
        if getattr(self, "_cols", None) is None:
            moving, fixed = r.columns[:2]      # ({joint: column}, {frame point: (x, y)}, ...)
            nop = r.positions.shape[-2]
            xy = np.array([fixed.get(nm, (0.0, 0.0)) for g in self.groups for nm in g])
            idx = np.array([moving.get(nm, nop) for g in self.groups for nm in g])
            links = r.columns[2]               # {link index: column}: all links stored
            blocks = np.array([links[li] if li >= 0 else 0 for li in self.blocks],
                              dtype=int)
            self._cols = (idx, xy, idx == nop, blocks)
        return self._cols

    def sides(self, r):
        """The signed side of each group at every position of the result r, a number
        of order 1 whose sign is the geometric branch: rrr, rpr -- B left of A->C;
        rrp -- B ahead of the foot of the perpendicular from A along the guide."""
        n = np.size(r.phi)
        if not self.groups:
            return np.zeros((n, 0))
        P = self._joints(r, "positions")
        return self._side(P, np.zeros_like(P), self._guide(r, False))[0]

    def _guide(self, r, rate):
        """The rrp groups' guide directions (n, G, 2) (other groups: zeros) and, with
        rate, their angular rates (n, G) (the slider block turns with its guide)."""
        if not self.rrp.any():
            return None
        n = np.size(r.phi)
        blocks = self._columns(r)[3]
        D = np.asarray(r.directions).reshape(n, -1, 2)[:, blocks, :] * self.rrp[:, None]
        if not rate:
            return D, np.zeros(D.shape[:-1])
        return D, np.asarray(r.omegas).reshape(n, -1)[:, blocks] * self.rrp

    def _side(self, P, V, guide=None):
        """The side and its rate from the joints' positions P and velocities V,
        (..., G, 3, 2) each (the rate with each group's scale held fixed); guide: the
        rrp groups' guide directions and rates (:meth:`_guide`)."""
        b, a, c = P[..., 0, :], P[..., 1, :], P[..., 2, :]
        u, v = c - a, b - a
        du, dv = V[..., 2, :] - V[..., 1, :], V[..., 0, :] - V[..., 1, :]
        lab = np.hypot(v[..., 0], v[..., 1])
        scale = lab * (lab + np.hypot((b - c)[..., 0], (b - c)[..., 1]))
        s = (u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]) / scale
        ds = (du[..., 0] * v[..., 1] - du[..., 1] * v[..., 0] + u[..., 0] * dv[..., 1]
              - u[..., 1] * dv[..., 0]) / scale
        if guide is not None:
            # rrp: (B - A).g / l2, g the guide's direction, turning at the rate wg
            # (on a moving link): d g = wg k x g
            g, wg = guide
            dg = wg[..., None] * np.stack((-g[..., 1], g[..., 0]), axis=-1)
            s = np.where(self.rrp, (v * g).sum(axis=-1) / lab, s)
            ds = np.where(self.rrp, ((dv * g).sum(axis=-1) + (v * dg).sum(axis=-1)) / lab,
                          ds)
        return s, ds

    def _joints(self, r, field):
        """The groups' (B, A, C) from a result's positions or velocities: (n, G, 3, 2)."""
        n = np.size(r.phi)
        idx, xy, frame, _ = self._columns(r)
        a = getattr(r, field).reshape(n, -1, 2)
        P = np.concatenate((a, np.zeros((n, 1, 2))), axis=1)[:, idx, :]
        if field == "positions":
            P[:, frame, :] = xy[frame]
        return P.reshape(n, -1, 3, 2)

    def side_rate(self, phi, groups):
        """The side of group groups[k] and its derivative with respect to phi at the
        angle phi[k] (the current branches)."""
        r = self.solve(np.asarray(phi, dtype=float), 1.0, 0.0, "velocities")
        rows = np.arange(len(groups))
        s, ds = self._side(self._joints(r, "positions"), self._joints(r, "velocities"),
                           self._guide(r, True))
        return s[rows, groups], ds[rows, groups]


# Near a toggle or a change point the group kernels lose digits (positions as eps/d,
# velocities eps/d^2, accelerations and so J' as eps/d^3, d the distance to it), though
# the continuous motion is smooth there: within _ZONE of the crossing J, J' and M_red come
# from the polynomial through 8 samples at phi* +- k _ZETA (k = 1..4), each on its side's
# branches (interpolation error of order (_ZETA)^8).
_ZETA = 0.02
_ZONE = 0.75 * _ZETA
_STRIDE = 0.5


class _Crossing:
    """A toggle or change point: the groups ``groups`` change branch where phi passes
    ``phi``; ``side`` is the side the motion is on (+1: phi > it); J, J', M_red near it
    from the samples (nodes, values)."""

    def __init__(self, phi, side, groups, nodes, values, cfgs):
        self.phi, self.side, self.groups = phi, side, groups
        self.nodes, self.values = nodes, values
        self.cfgs = cfgs                  # the branches of the two halves of the nodes
        self.bary = np.array([1.0 / np.prod(x - np.delete(nodes, j))
                              for j, x in enumerate(nodes)])

    def passed(self, phi):
        return (phi - self.phi) * self.side < 0.0

    def patch(self, phi, mach=None, omega=None, t=None):
        """(J, J', M_red) at the angles phi (interpolated); with loads that depend on
        omega or t (mach.dynamic), M_red from the nodes solved at each state's own
        omega and t."""
        L = _lagrange(phi, self.nodes, self.bary)
        J, Jp, M = (L @ self.values).T
        if mach is not None and mach.dynamic:
            k, half = len(phi), len(self.nodes) // 2
            Mn = np.empty((k, len(self.nodes)))
            for part, cfg in ((slice(0, half), self.cfgs[0]),
                              (slice(half, None), self.cfgs[1])):
                nodes = self.nodes[part]
                mach.set_config(cfg)
                r = mach.solve(np.tile(nodes, k), np.repeat(omega, len(nodes)),
                               np.repeat(t, len(nodes)), "forces")
                Mn[:, part] = r.reduced_moment.reshape(k, len(nodes))
            M = np.sum(L * Mn, axis=1)
        return J, Jp, M


def _flip(cfg, groups):
    cfg = list(cfg)
    for j in groups:
        cfg[j] = -cfg[j]
    return tuple(cfg)


def _stage_configs(base, crossings, phis):
    """The branch configuration at each angle: the base one, flipped for the groups of
    every crossing the angle lies beyond."""
    cfgs = []
    for p in phis:
        cfg = base
        for cr in crossings:
            if cr.passed(p):
                cfg = _flip(cfg, cr.groups)
        cfgs.append(cfg)
    return cfgs


def _rhs(mach, base, crossings, ph, om, ts, y):
    """epsilon at the stages (the step from phi = y), and the direct results [(indices,
    result)]."""
    lo, hi = min(y, float(ph.min())) - _ZETA, max(y, float(ph.max())) + _ZETA
    crossings = [cr for cr in crossings if lo < cr.phi < hi]
    if not crossings:
        mach.set_config(base)
        return mach.epsilon(ph, om, ts)
    F = np.empty(len(ph))
    zone = np.zeros(len(ph), dtype=bool)
    for cr in crossings:
        near = np.abs(ph - cr.phi) < _ZONE
        if near.any():
            J, Jp, M = cr.patch(ph[near], mach, om[near], ts[near])
            F[near] = (M - 0.5 * Jp * om[near] ** 2) / J
            zone |= near
    parts = []
    idx = np.flatnonzero(~zone)
    if idx.size:
        cfgs = _stage_configs(base, crossings, ph[idx])
        F[idx], sub = mach.epsilon(ph[idx], om[idx], ts[idx], cfgs)
        parts = [(idx[i], r) for i, r in sub]
    return F, parts


def _crossing(mach, base, groups, rough, side):
    """The crossing of ``groups`` near ``rough`` (the motion on ``side`` of it): its
    angle, the root of the polynomial through the groups' signed side at 8 samples, and
    the samples of J, J', M_red there; None when the mechanism does not assemble."""
    k = np.arange(1, 5) * _ZETA
    g0 = groups[0]
    for _ in range(3):
        near, far = rough + side * k, rough - side * k
        try:
            rn = mach.solve_with(near, base, "forces")
            rf = mach.solve_with(far, _flip(base, groups), "forces")
        except _Failed:
            return None
        x = np.concatenate((near, far))
        sv = np.concatenate((mach.sides(rn)[:, g0], mach.sides(rf)[:, g0])) * base[g0]
        # the root of the interpolating polynomial (in units of _ZETA about rough)
        u = (x - rough) / _ZETA
        coef = np.polynomial.polynomial.polyfit(u, sv, len(u) - 1)
        der = np.polynomial.polynomial.polyder(coef)
        r = 0.0
        for _ in range(50):
            step = np.polynomial.polynomial.polyval(r, coef) / \
                np.polynomial.polynomial.polyval(r, der)
            r -= step
            if not abs(step) > 1e-15:
                break
        if not (math.isfinite(r) and abs(r) <= 1.0):
            return None
        star = rough + r * _ZETA
        if abs(r) <= 0.25:
            vals = []
            for res in (rn, rf):
                J, Mr, Mb = res.reduced_inertia, res.reduced_moment, res.balancing_moment
                vals.append(np.stack((J, 2.0 * (Mb + Mr), Mr), axis=1))
            return _Crossing(float(star), side, list(groups), x, np.concatenate(vals),
                             (base, _flip(base, groups)))
        rough = star
    return None


_LEGENDRE = {}


def _series(F, c):
    """A step's F(tau) through its values at the nodes c, as a Legendre series on
    [0, 1], and its first and second integrals from 0: cheap scalar evaluations (by
    Clenshaw's recurrence) for the roots of omega and phi inside the step."""
    n = len(c)
    if _LEGENDRE.get(n) is None:            # coefficients from the Gauss rule, exact
        x, wg = np.polynomial.legendre.leggauss(n)
        V = np.polynomial.legendre.legvander(x, n - 1)             # V[i, k] = P_k(x_i)
        _LEGENDRE[n] = (V * wg[:, None]).T * (np.arange(n) + 0.5)[:, None]
    L = np.polynomial.legendre
    a0 = _LEGENDRE[n] @ F                      # in x = 2 tau - 1: dtau = dx / 2
    a1 = L.legint(a0, lbnd=-1.0, scl=0.5)
    a2 = L.legint(a1, lbnd=-1.0, scl=0.5)
    return tuple((lambda u, a=a: float(L.legval(2.0 * u - 1.0, a))) for a in (a0, a1, a2))


def _root(f, a, b, fa, df=None):
    """A root of f in [a, b] where f changes sign: bisection to rounding, or with the
    derivative df Newton's method kept inside the bracket (bisecting where it leaves)."""
    x = 0.5 * (a + b)
    for _ in range(200):
        if not a < x < b:
            break
        fx = f(x)
        if fx == 0.0:
            return x
        if (fx > 0.0) == (fa > 0.0):
            a, fa = x, fx
        else:
            b = x
        mid = 0.5 * (a + b)
        if df is None:
            x = mid
            continue
        d = df(x)
        step = fx / d if d != 0.0 else math.inf
        new = x - step
        if not a < new < b:
            x = mid
        elif abs(step) <= 1e-15 * max(abs(x), 1e-300) + 1e-300:
            return new
        else:
            x = new
    return 0.5 * (a + b)


Event = result_type("Event", ("kind", "t", "phi", "omega", "epsilon", "note"),
                    doc="""An event of a simulation: ``kind`` "turning point" (the crank
    stops and turns back: omega = 0, epsilon != 0), "stall" (it stops and stays: the
    loads at rest hold it), or "branch" (a group passed a toggle or change point and
    took the other geometric branch, which is the continuation of the motion), at time
    ``t`` and angle ``phi``; ``note`` says which groups and why.""")


def _check_time(who, t):
    t = _real_vector(who, "t", t)
    if len(t) < 2:
        raise ValueError(f"{who}: t needs at least 2 times (the start and an end), not "
                         f"{len(t)}")
    steps = np.diff(t)
    if not np.all(steps > 0):
        k = int(np.flatnonzero(~(steps > 0))[0])
        raise ValueError(f"{who}: t must be strictly increasing: t[{k + 1}] = "
                         f"{float(t[k + 1])!r} <= t[{k}] = {float(t[k])!r}")
    return t


# with groups followed, steps of looser tolerances can leap past a crossing's warning
_FOLLOW_RTOL = 1e-6


def simulate(m, t, *, phi0=0.0, omega0=0.0, gravity=0.0, rtol=1e-8,
             branches="continuous", max_steps=1_000_000):
    """The motion of a mechanism in time from a start (phi0, omega0) at t[0]; see
    :meth:`sarkp.Mechanism.simulate`."""
    who = "simulate"
    t = _check_time(who, t)
    phi0 = _scalar(who, "phi0", phi0)
    omega0 = _scalar(who, "omega0", omega0)
    g = _scalar(who, "gravity", gravity)
    rtol = _scalar(who, "rtol", rtol)
    if not 1e-14 <= rtol <= 0.1:
        raise ValueError(f"{who}: rtol = {rtol!r} must lie in [1e-14, 0.1]")
    if branches not in ("continuous", "geometric"):
        raise ValueError(f"{who}: branches must be 'continuous' or 'geometric', not "
                         f"{branches!r}")
    if m._crank is None:
        raise ValueError(f"{who}: the mechanism has no crank (m.crank)")
    mach = _Machine(m, g)
    follow = branches == "continuous" and bool(mach.groups)
    try:
        eps0 = float(mach.epsilon(np.array([phi0]), np.array([omega0]),
                                  np.array([t[0]]))[0][0])
    except _Failed as e:
        raise ValueError(f"{who}: the mechanism cannot start at phi0 = {phi0!r}: {e}") \
            from None
    if follow:
        # steps of looser tolerances can leap past a crossing's warning (a missed
        # branch change at rtol 1e-4 on the N-four-bar): at most 1e-6 then
        rtol = min(rtol, _FOLLOW_RTOL)
    with np.errstate(all="ignore"):
        return _integrate(mach, t, phi0, omega0, eps0, rtol, follow, max_steps)


def _integrate(mach, t_out, phi0, omega0, eps0, rtol, follow, max_steps):
    s = _NODES
    c, b, bary, top = _collocation(s)
    _, a1, a2 = _integrals(c, c, b, bary)
    b2 = b * (1.0 - c)
    L1 = _lagrange([1.0], c, bary)[0]
    n = len(t_out)
    phi_o, om_o, ep_o = np.empty(n), np.empty(n), np.empty(n)
    phi_o[0], om_o[0], ep_o[0] = phi0, omega0, eps0
    start_cfg = mach.config()
    events, branch_log = [], [(float(t_out[0]), start_cfg)]
    tcur, tend = float(t_out[0]), float(t_out[-1])
    y, w, e = phi0, omega0, eps0
    wref = max(abs(omega0), math.sqrt(abs(eps0)), 1e-300)
    span = tend - tcur
    # the first step: the crank turns by about 0.05 rad
    h = min(span, 0.05 / max(abs(w) + math.sqrt(abs(e)), 1e-300))
    F = np.full(s, e)
    ko = 1                                    # the next output
    crossings = []
    base = start_cfg                          # the branches at phi = y
    status = "ok"
    steps = rejected = in_row = 0
    h_acc = h
    stall = _stall_check(mach, y, w, e, wref, start_cfg, tcur)
    if stall:
        events.append(Event("stall", tcur, y, 0.0, 0.0, "at rest and held there by "
                                                        "the loads"))
        status = "stalled"
    while not stall and tcur < tend:
        if steps + rejected >= max_steps:
            raise RangeError(f"simulate: more than {max_steps} steps before t = {tend!r} "
                             f"(reached t = {tcur!r})")
        h = min(h, tend - tcur)
        if tcur + h >= tend * (1.0 - 1e-15) - 1e-300 or tend - (tcur + h) < 1e-9 * h:
            h = tend - tcur
        ts = tcur + c * h
        ok, rho, it = False, 0.0, 0
        sc_p = rtol * max(1.0, abs(y))
        sc_w = rtol * max(wref, abs(w))
        prev = math.inf
        parts = None
        try:
            for it in range(1, 30):
                ph = y + h * w * c + h * h * (a2 @ F)
                om = w + h * (a1 @ F)
                Fn, parts = _rhs(mach, base, crossings, ph, om, ts, y)
                d = float(np.max(np.abs(Fn - F)))
                F = Fn
                size = max(h * d / sc_w, h * h * d / sc_p)
                if it > 1 and prev > 0.0:
                    rho = d / prev
                prev = d
                if size < 1e-3 or d <= 1e-15 * float(np.max(np.abs(F))):
                    ok = True
                    break
                if it > 2 and rho > 0.8:
                    break
        except _Failed:
            ok = False
        if ok:
            w1 = w + h * float(b @ F)
            y1 = y + h * w + h * h * float(b2 @ F)
            sc_p = rtol * max(1.0, abs(y), abs(y1))
            sc_w = rtol * max(wref, abs(w), abs(w1))
            amp = abs(float(top @ F))
            err = max(h * amp / sc_w, 0.5 * h * h * amp / sc_p)
            ok = err <= 1.0
        else:
            err = math.inf
        if not ok:
            rejected += 1
            in_row += 1
            tau = _stop_ahead(w, e, h, F, c, b, a1) if mach.dynamic else None
            if tau is not None:
                # the trial step passes a stop of the crank, where a load of omega (dry
                # friction, a pawl) may jump: step to the stop it predicts; once the
                # stop is nearer than rounding, stop there (a stall or a turning point)
                if abs(w) > 1e-3 * rtol * wref and tau * h > 1e-12 * span:
                    h *= tau
                    continue
                dt = -w / e if e * w < 0.0 else tau * h
                ts_, ys_ = float(tcur + dt), float(y + w * dt + 0.5 * e * dt * dt)
                ke = ko + int(np.searchsorted(t_out[ko:], ts_, side="left"))
                d_ = t_out[ko:ke] - tcur
                phi_o[ko:ke], om_o[ko:ke], ep_o[ko:ke] = y + w * d_ + 0.5 * e * d_**2, \
                    w + e * d_, e
                ko = ke
                cfg = _stage_configs(base, crossings, [ys_])[0]
                held, after = _at_rest(mach, ys_, wref, cfg, ts_, -1.0 if w > 0 else 1.0)
                if held:
                    events.append(Event("stall", ts_, ys_, 0.0, 0.0,
                                        "stopped and held at rest by the loads"))
                    phi_o[ko:], om_o[ko:], ep_o[ko:] = ys_, 0.0, 0.0
                    ko, status = n, "stalled"
                    break
                events.append(Event("turning point", ts_, ys_, 0.0, after,
                                    "omega = 0, epsilon != 0: the crank turns back"))
                tcur, y, w, e = ts_, ys_, 0.0, after
                F = np.full(s, e)
                h, in_row = h_acc, 0
                continue
            h *= 0.5 if not math.isfinite(err) else max(0.2, 0.8 * err ** (-1.0 / s))
            if h < 1e-12 * span or in_row > 40:
                raise RangeError(f"simulate: the step size fell to {h!r} s at t = {tcur!r}, "
                                 f"phi = {y!r}: the mechanism's motion cannot be followed "
                                 f"there (a dead centre it cannot pass?)")
            F = np.full(s, e) if not np.isfinite(F).all() else F
            continue
        steps += 1
        in_row = 0
        h_acc = h
        t1 = tcur + h

        def at(tau, F=F, y=y, w=w, h=h):
            """phi, omega, epsilon at the fractions tau of the step (the collocation
            polynomial)."""
            shape = np.shape(tau)
            L, P1, P2 = _integrals(tau, c, b, bary)
            tau = np.asarray(tau, dtype=float).reshape(-1)
            out = (y + h * w * tau + h * h * (P2 @ F), w + h * (P1 @ F), L @ F)
            return tuple(v.reshape(shape) for v in out)

        series = []

        def omega_at(u, F=F, w=w, h=h):
            """omega at the fraction u of the step (scalar; for root finding)."""
            if not series:
                series.extend(_series(F, c))
            return w + h * series[1](u)

        def phi_at(u, F=F, y=y, w=w, h=h):
            if not series:
                series.extend(_series(F, c))
            return y + h * w * u + h * h * series[2](u)

        def rates(u, which, h=h):
            """d(omega)/du (which 1) or d(phi)/du (which 2) at u."""
            return h * series[0](u) if which == 1 else h * omega_at(u)

        # turning points and stalls: omega's sign changes inside the step
        taus = np.concatenate(([0.0], c, [1.0]))
        wt = np.concatenate(([w], w + h * (a1 @ F), [w1]))
        stop = None
        for i in range(len(taus) - 1):
            a_, b_ = wt[i], wt[i + 1]
            if i == 0 and a_ == 0.0:
                continue
            if (a_ > 0.0 and b_ <= 0.0) or (a_ < 0.0 and b_ >= 0.0):
                tau = _root(omega_at, taus[i], taus[i + 1], a_, lambda u: rates(u, 1))
                pt, _, et = (float(v) for v in at(tau))
                tt = float(tcur + tau * h)
                if _stall_check(mach, pt, 0.0, et, wref,
                                _stage_configs(base, crossings, [pt])[0], tt):
                    events.append(Event("stall", tt, pt, 0.0, 0.0,
                                        "stopped and held at rest by the loads"))
                    stop = (tau, pt)
                    break
                events.append(Event("turning point", tt, pt, 0.0, et,
                                    "omega = 0, epsilon != 0: the crank turns back"))
        # outputs inside the step
        ke = ko + int(np.searchsorted(t_out[ko:], t1, side="right"))
        if ke > ko:
            tau = (t_out[ko:ke] - tcur) / h
            pp, ww, ee = at(tau)
            phi_o[ko:ke], om_o[ko:ke], ep_o[ko:ke] = pp, ww, ee
            if stop is not None:
                late = tau >= stop[0]
                phi_o[ko:ke][late], om_o[ko:ke][late], ep_o[ko:ke][late] = stop[1], 0.0, 0.0
            ko = ke
        if stop is not None:
            phi_o[ko:], om_o[ko:], ep_o[ko:] = stop[1], 0.0, 0.0
            ko, status = n, "stalled"
            break
        # branches: the crossings passed in this step take effect
        cfg = base
        for cr in crossings:
            if cr.passed(y1):
                tau = _root(lambda u: phi_at(u) - cr.phi, 0.0, 1.0, y - cr.phi,
                            lambda u: rates(u, 2))
                pt, wt_, et = (float(v) for v in at(tau))
                cfg = _flip(cfg, cr.groups)
                cr.side = -cr.side
                names = ", ".join(repr(mach.groups[j][0]) for j in cr.groups)
                events.append(Event(
                    "branch", float(tcur + tau * h), cr.phi, wt_, et,
                    f"group(s) {names} passed a toggle or change point (the signed "
                    f"side of the new joint went through zero): the continuous motion "
                    f"takes the other geometric branch"))
                branch_log.append((float(tcur + tau * h), cfg))
        base = cfg
        mach.set_config(base)
        # the next step
        y_prev = y
        tcur, y, w, e = t1, y1, w1, float(L1 @ F)
        wref = max(wref, abs(w))
        grow = 0.85 * err ** (-1.0 / s) if err > 0 else 4.0
        hn = h * min(4.0, max(0.2, grow))
        if rho > 0.0:
            hn = min(hn, h * max(0.2, 0.12 / rho))
        if follow and abs(y1 - y_prev) > _STRIDE:
            # the crank turns at most _STRIDE per step, so that a group's side seen
            # falling over the step's last nodes warns of a crossing before a step
            # reaches it (at loose tolerances steps would otherwise leap past one)
            hn = min(hn, h * _STRIDE / abs(y1 - y_prev))
        if not follow and mach.groups and parts:
            S = np.abs(mach.sides(parts[-1][1]))
            if S.min() < 1e-4:
                B = mach.groups[int(S[-1].argmin())][0]
                raise RangeError(
                    f"simulate: the group placing {B!r} reaches a toggle or change "
                    f"point at t = {tcur!r}, phi = {y!r}: the geometric branch rule "
                    f"(branches='geometric') cannot follow the motion there; "
                    f"branches='continuous' does")
        if follow:
            reach = abs(hn * w) + 0.5 * hn * hn * abs(e) + abs(y1 - float(ph[0]))
            crossings = [cr for cr in crossings if abs(cr.phi - y) < 8.0 * reach + _ZETA]
            crossings = _predict(mach, base, crossings, parts, ph, y, reach)
        # predictor: the collocation polynomial of this step extrapolated
        F = _lagrange(1.0 + c * (hn / h), c, bary) @ F
        h = hn
    if ko < n:
        phi_o[ko:], om_o[ko:], ep_o[ko:] = y, w, e
    stats = {"steps": steps, "rejected": rejected, "calls": mach.calls,
             "positions": mach.points, "order": 2 * s, "stage_order": s}
    mach.set_config(start_cfg)
    return Simulation(t_out, phi_o, om_o, ep_o, tuple(events), tuple(branch_log), status,
                      stats, mach.m, mach.gravity)


def _stall_check(mach, phi, w, e, wref, cfg, t):
    """At rest (w = 0) at time t: whether the loads hold the crank there -- epsilon
    just after the stop, on either side, points back to rest (or is zero)."""
    if w != 0.0:
        return False
    return _at_rest(mach, phi, wref, cfg, t, 1.0)[0]


def _at_rest(mach, phi, wref, cfg, t, going):
    """At rest at (phi, t): (held, epsilon as the crank starts to move in the
    direction ``going``, +1 or -1) -- held: epsilon just after the stop, on either
    side, points back to rest (or is zero)."""
    d = 1e-9 * wref
    try:
        ee = mach.epsilon(np.array([phi, phi]), np.array([d, -d]), np.full(2, t),
                          [cfg, cfg])[0]
    except _Failed:
        return False, 0.0
    return bool(ee[0] <= 0.0 <= ee[1]), float(ee[0] if going > 0 else ee[1])


def _stop_ahead(w, e, h, F, c, b, a1):
    """Where a trial step (its stage values F) brings the crank to a stop: the fraction
    of the step at which its omega reaches zero, None if it keeps its sign."""
    if w == 0.0 or not np.isfinite(F).all():
        return None
    taus = np.concatenate(([0.0], c, [1.0]))
    wt = np.concatenate(([w], w + h * (a1 @ F), [w + h * float(b @ F)]))
    cross = np.flatnonzero(wt * w <= 0.0)
    if not cross.size:
        return None
    k = int(cross[0])
    integral = _series(F, c)[1]
    tau = _root(lambda u: w + h * integral(u), taus[k - 1], taus[k], wt[k - 1])
    if not 0.0 < tau < 1.0 and e * w < 0.0:
        tau = -w / (e * h)
    return min(max(tau, 1e-3), 0.9)


def _predict(mach, base, crossings, parts, ph, y1, reach):
    """The crossings ahead: groups whose signed side, falling towards zero over the
    last nodes of the step, would reach it within ``reach`` of phi = y1; Newton's method
    on |side| from this side (the one-sided derivative) brings the angle within _ZETA,
    :func:`_crossing` finds it."""
    G = len(mach.groups)
    S = np.full((len(ph), G), np.nan)
    last = {len(ph) - 2, len(ph) - 1}
    for idx, r in parts:
        if last & set(np.atleast_1d(idx).tolist()):
            S[idx] = np.abs(mach.sides(r))
    pa, pb = float(ph[-2]), float(ph[-1])
    # a group is busy with a crossing ahead (or just passed); one behind the motion
    # does not hide the group's next crossing (the N-four-bar's change point at 2 pi
    # behind its toggle at pi: found only when a rejected step had shrunk to it)
    ahead = 1.0 if pb >= pa else -1.0
    busy = {j for cr in crossings if abs(cr.phi - y1) < 4.0 * reach + _ZETA
            and (cr.phi - y1) * ahead > -_ZETA for j in cr.groups}
    sa, sb = S[-2], S[-1]
    cand, P = [], []
    for j in range(G):
        if j in busy or not sb[j] < sa[j] or pa == pb:
            continue
        p = pb - sb[j] * (pb - pa) / (sb[j] - sa[j])
        if abs(p - y1) <= 2.0 * reach + _ZETA and (p - pb) * (pb - pa) > 0.0:
            cand.append(j)
            P.append(p)
    if not cand:
        return crossings
    guess = np.array(P)
    P = guess.copy()
    good = np.full(len(P), y1)                 # the last angles where it assembled
    mach.set_config(base)
    for _ in range(20):
        for _ in range(12):
            # damped: a step past the crossing where the mechanism does not assemble
            # on these branches goes back halfway to the last angle where it did (the
            # N-four-bar: halving towards y1 made Newton cycle 20 times per crossing)
            try:
                sv, dv = mach.side_rate(P, cand)
                break
            except _Failed:
                P = 0.5 * (P + good)
        else:
            return crossings
        good = P.copy()
        sv, dv = np.abs(sv), dv * np.sign(sv)
        with np.errstate(all="ignore"):
            step = np.where(dv != 0.0, sv / dv, 0.0)
        P = P - step
        if np.all(np.abs(step) <= 0.05 * _ZETA):
            break
    new = list(crossings)
    done = set()
    for i, j in enumerate(cand):
        if j in done or not (np.isfinite(P[i]) and abs(P[i] - y1) <= 4.0 * reach + _ZETA
                             and abs(P[i] - y1) <= 1.5 * abs(guess[i] - y1) + _ZETA
                             and (P[i] - y1) * (guess[i] - y1) > 0.0):
            continue
        together = [cand[k] for k in range(len(cand))
                    if abs(P[k] - P[i]) <= 0.1 * _ZETA and cand[k] not in done]
        done.update(together)
        cr = _crossing(mach, base, together, float(P[i]), 1 if y1 > P[i] else -1)
        mach.set_config(base)
        if cr is not None:
            new.append(cr)
    return new


class _SimulationBase(Result):
    """What :meth:`Mechanism.simulate` returns."""

    __slots__ = ()

    def _repr_header(self):
        kinds = [e.kind for e in self.events]
        parts = [f"{len(self.t)} times", f"status {self.status!r}"]
        for k in ("turning point", "stall", "branch"):
            if k in kinds:
                parts.append(f"{kinds.count(k)} {k} event(s)")
        return ", ".join(parts)

    def __repr__(self):
        return f"Simulation({self._repr_header()})"

    __str__ = __repr__

    def _frame_columns(self):
        return {"t": self.t, "phi": self.phi, "omega": self.omega,
                "epsilon": self.epsilon}, np.shape(self.t)

    def events_of(self, kind):
        """The events of one kind ("turning point", "stall", "branch")."""
        return [e for e in self.events if e.kind == kind]

    def solve(self, need="forces", *, on_error="raise"):
        """The mechanism solved along the motion: positions, velocities, accelerations,
        forces at the simulated phi, omega and epsilon, each time with the branches the
        motion had then (a :class:`sarkp.MechanismResult` over the times t)."""
        m = self.mechanism
        cuts = [tb for tb, _ in self.branches[1:]]
        seg = np.searchsorted(np.asarray(cuts, dtype=float), self.t, side="right")
        results, order = [], []
        try:
            for k in np.unique(seg):
                idx = np.flatnonzero(seg == k)
                for (B, _, _), b in zip(_groups(m), self.branches[k][1]):
                    if m.branch(B) != b:
                        m.set_branch(B, b)
                results.append(m.solve(self.phi[idx], omega=self.omega[idx],
                                       epsilon=self.epsilon[idx], need=need,
                                       gravity=self.gravity, on_error=on_error))
                order.append(idx)
        finally:
            for (B, _, _), b in zip(_groups(m), self.branches[0][1]):
                if m.branch(B) != b:
                    m.set_branch(B, b)
        if len(results) == 1:
            return results[0]
        n = len(self.t)
        first = results[0]
        fields = []
        for name, v in zip(first._fields, first):
            if isinstance(v, np.ndarray) and v.ndim and v.shape[0] == len(order[0]):
                out = np.empty((n,) + v.shape[1:], dtype=v.dtype)
                for idx, r in zip(order, results):
                    out[idx] = getattr(r, name)
                fields.append(out)
            else:
                fields.append(v)
        return type(first)._make(fields)

    def animate(self, path, *, fps=None, paths=()):
        """An animation of the motion in real time (one frame per time of t, or every
        k-th so that at most 30 frames a second are drawn): .gif or .mp4."""
        dt = float(np.median(np.diff(self.t)))
        every = max(1, int(round(1.0 / (30.0 * dt)))) if fps is None else 1
        rate = 1.0 / (dt * every) if fps is None else fps
        return self.solve(need="positions").animate(path, fps=rate, every=every,
                                                    paths=paths)


def _followed(kind, ints, reals):
    """Whether simulate follows a group's branch through toggles: rrr; rrp (its guide
    on the frame or on a moving link); rpr with its slider off link 3's axis (h != 0:
    else B = A, no branch)."""
    return kind in (1, 2) or (kind == 3 and np.all(np.asarray(reals[0]) != 0.0))


def _groups(m):
    names = {i: nm for nm, i in m._points.items()}
    return [(B, names[ints[1]], names[ints[2]]) for kind, ints, reals, B in m._steps
            if _followed(kind, ints, reals)]


def _guides(m):
    """For the followed groups: which are rrp, and the link index of each rrp group's
    slider block (-1 for the others): the block's direction is the guide's."""
    rows = [ints[4] if kind == 2 else -1
            for kind, ints, reals, _ in m._steps if _followed(kind, ints, reals)]
    return np.array([r >= 0 for r in rows], dtype=bool), np.array(rows, dtype=int)


Simulation = result_type(
    "Simulation", ("t", "phi", "omega", "epsilon", "events", "branches", "status",
                   "stats", "mechanism", "gravity"),
    base=_SimulationBase,
    doc="""A motion in time (:meth:`sarkp.Mechanism.simulate`).

    Fields: ``t`` -- the times asked for (s); ``phi``, ``omega``, ``epsilon`` -- the
    crank's angle (rad), angular velocity (rad/s) and acceleration (rad/s^2) there;
    ``events`` -- the turning points, stalls and branch changes, in time order (each an
    :data:`Event`); ``branches`` -- ``(t, branches)`` from the start and at each branch
    change, the branches (+1/-1) of the followed groups (rrr, rrp, rpr) in their
    order; ``status`` -- "ok" or
    "stalled"; ``stats`` -- steps, rejected steps, mechanism calls and positions solved,
    the method's order; ``mechanism`` -- a copy of the mechanism at the start;
    ``gravity``.  ``sim.solve(need)`` gives positions and forces along the motion,
    ``sim.animate(path)`` draws it in real time.""")
