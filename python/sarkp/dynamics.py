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
from .library import ST_REQUIREMENT, Check, as_real_array, book_routine
from .modes import get_mode
from .results import result_type

__all__ = ["DZKNDV", "DMHVK", "DMHVK_EXACT", "motion", "flywheel", "Motion", "Flywheel"]

_COUNT = range(2, 2**31 - 1)

DZKNDV = book_routine(
    "DZKNDV", listing="VIII.1", lines="L5935-5990", chapter="dynamics",
    inputs=("M", "ZM", "W1", "ISC", "MPR", "ISPR", "AAA"),
    outputs=("AS", "ASUM", "EV", "DEC", "WPR", "EPR"),
    tables={"MPR": "M", "ISPR": "M"}, integers={"M": _COUNT},
    nonnegative=("W1", "ISC", "ISPR"), nonzero=("W1", "ISC"),
    checks=(Check(lambda M, ZM, **_: ZM != M, ST_REQUIREMENT,
                  "ZM must equal M: the book passes the number of points twice, as an "
                  "integer and as a real (the step is 2*pi/(ZM - 1))"),),
    kept={ST_REQUIREMENT: ("AS", "ASUM", "EV", "DEC")},
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

    Parameters
    ----------
    M : int
        Number of points (>= 2), covering exactly one cycle phi = 0 .. 2*pi, both ends
        included; equals ``len(MPR)``.
    ZM : float
        M again, as a real (the book passes both); must equal M.
    W1 : float
        Mean angular velocity omega_sr = (omega_max + omega_min)/2 of the reduction link
        (rad/s, > 0; the book's definition, L6044).
    ISC : float
        Constant part J_c of the reduced moment of inertia (kg*m^2, > 0).
    MPR : array_like, shape (M,)
        Reduced moment of the forces at the M points (N*m), positive where it does
        positive work on the reduction link (in the book's program X the moment of the
        group reactions on the crank, M1 of Fig. 94).
    ISPR : array_like, shape (M,)
        Variable part J_v(phi) of the reduced moment of inertia (kg*m^2, >= 0).
    AAA : float, optional
        The book's print flag; unused.

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

DMHVK = book_routine(
    "DMHVK", listing="VIII.2", lines="L6052-6082", chapter="dynamics",
    inputs=("N", "DELTA", "ISC", "W1", "DEC", "AAA"), outputs=("IMHVK",),
    tables={"DEC": "N"}, integers={"N": range(1, 2**31 - 1)},
    nonnegative=("ISC", "W1"), nonzero=("ISC", "W1"),
    checks=(Check(lambda DELTA, **_: not 0.0 < DELTA < 1.0, ST_REQUIREMENT,
                  "DELTA, the coefficient of speed fluctuation (omega_max - omega_min)/"
                  "omega_sr, must lie in (0, 1)"),),
    doc="""Moment of inertia of the flywheel (listing VIII.2).

    Listing VIII.2 (L6055-6082), eqs. (8.22)/(8.24): ``IMHVK = (max DEC - min DEC)/
    (DELTA*W1**2) - ISC``, the flywheel that keeps the coefficient of speed fluctuation
    (omega_max - omega_min)/W1 at DELTA, neglecting the variable part J_v of the reduced
    inertia (J_A = J_B = J_c, L6034).

    Parameters
    ----------
    N : int
        Number of values in DEC; equals ``len(DEC)``.
    DELTA : float
        Coefficient of speed fluctuation, in (0, 1).
    ISC : float
        Constant part J_c of the reduced moment of inertia (kg*m^2, > 0).
    W1 : float
        Mean angular velocity of the reduction link (rad/s, > 0).
    DEC : array_like, shape (N,)
        The change of the kinetic energy of the constant-inertia links over the cycle,
        DZKNDV's ``DEC`` (J).  An input: the listing's comment puts it under RESULT
        (ERRATA E-DMHVK-2).
    AAA : float, optional
        The print flag, unused.  The listing has 6 arguments, without AAA; the only call
        in the book (program X, L7631) passes 7, with AAA before IMHVK as every routine of
        the library has it, and its printed result IMH = 4507.27 (L7203) shows that call
        ran: the flag is kept (ERRATA E-DMHVK-1).  ``DMHVK(N, DELTA, ISC, W1, DEC)`` works
        too.

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


def _stall_message(who, w):
    return (f"{who}: no steady motion with mean speed omega_mean = {w!r} rad/s has real "
            f"speeds: the kinetic energy would go negative (the machine stalls); add "
            f"inertia, e.g. a flywheel from sarkp.flywheel")


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
        if e0 is None:
            if on_error == "raise":
                raise RequirementError(_stall_message(who, wm))
            nan = np.full(n, np.nan)
            return _motion(phi, nan, nan.copy(), math.nan, mc, Status.REQUIREMENT)
        omega = _speeds(e0, asum, J)
        t = t0 + _cumulative(first, w, 1.0 / omega)
        return _motion(phi, omega, t, e0, mc)
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
    if M[0] > 0.0:                                       # 1/omega = g/sqrt(s + c)
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
