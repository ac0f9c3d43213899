"""Dimensional synthesis over :class:`sarkp.Mechanism`: function, path and motion
generation for the four-bar, function generation for the crank-slider.

The four-bar of this module is O-A-B-C: the crank O-A (length ``a``) turns about the
frame point O, the coupler A-B (``b``) carries the coupler point P, the rocker C-B
(``c``) turns about the frame point C; the frame O-C has length ``d``.  Angles are in
radians counter-clockwise from +x, except the transmission angles (degrees, as the
``min_transmission`` requirement is given).  The transmission angle is the angle ABC
between coupler and rocker, in [0, 180] degrees; a mechanism meets ``min_transmission``
when it stays within [min_transmission, 180 - min_transmission] over its whole motion.

* Closed forms where they exist: Freudenstein's equation (function generation through
  three precision points, a linear system; four and five points free the dial zeros of
  the crank and the rocker), its crank-slider analogue, and the three-position
  construction of motion generation (each fixed pivot the centre of the circle through
  three positions of its moving pivot).
* Otherwise a global search, :func:`scipy.optimize.differential_evolution` over whole
  populations of designs (``vectorized=True``: one call evaluates a population), spread
  over processes or a dask cluster by ``workers=``, then a local refinement with
  :func:`scipy.optimize.least_squares` whose finite-difference Jacobian is one batched
  evaluation of the perturbed designs.

Every population is evaluated by :func:`_evaluate`, the one place that solves designs
through the Mechanism.  Requirements are hard: a design that does not assemble over the
motion, or breaks ``min_transmission``, is never returned; when no design meets them,
:class:`sarkp.RequirementError` says which requirement failed and the best deviation
found.  Every result reports its Grashof type and transmission angles.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from .errors import RequirementError, SignificanceWarning
from .mechanism import Mechanism

__all__ = ["function_generation", "slider_function_generation", "path_generation",
           "motion_generation", "fourbar_search", "grashof_type", "FourBarPopulation",
           "Synthesis"]

TWO_PI = 2.0 * math.pi
#: the crank angles of a whole turn at which assembly and the coupler curve are evaluated
TURN = np.linspace(0.0, TWO_PI, 360, endpoint=False)
#: the design vector of a four-bar with a coupler point
FOURBAR_VARIABLES = ("xO", "yO", "xC", "yC", "a", "b", "c", "p", "q", "branch")


# ---- input checks ------------------------------------------------------------------------

def _angles(name, value, minimum):
    a = np.asarray(value)
    if a.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be real numbers")
    a = np.asarray(a, dtype=float)
    if a.ndim != 1:
        raise ValueError(f"{name} must be a 1-d array of angles, not shape {a.shape}")
    if a.size < minimum:
        raise ValueError(f"{name}: {a.size} values given, the problem needs at least "
                         f"{minimum}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite")
    return a


def _positive(name, value):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating,
                                                          np.integer)):
        raise TypeError(f"{name} must be a real number, not {type(value).__name__}")
    value = float(value)
    if not math.isfinite(value) or value <= 0.0:
        raise ValueError(f"{name} must be a length > 0, not {value}")
    return value


def _monotone(name, a):
    d = np.diff(a)
    if not (np.all(d > 0) or np.all(d < 0)):
        raise ValueError(f"{name} must be strictly monotone (the crank turns one way "
                         f"through the precision points)")


def _wrap(x):
    """Angles into [-pi, pi)."""
    return np.remainder(np.asarray(x) + math.pi, TWO_PI) - math.pi


# ---- the result --------------------------------------------------------------------------

@dataclass
class Synthesis:
    """The result of a synthesis: a :class:`sarkp.Mechanism` ready to solve, plot and
    animate, and what it achieves.

    Attributes
    ----------
    mechanism : Mechanism
        The designed mechanism (joints O, A, B, C and, for path and motion
        generation, the coupler point P; a crank-slider has O, A and the slider B).
    error : float
        The largest deviation at the given points: rad for function generation, the
        length unit for path and motion generation.
    phi : ndarray
        The crank angles at which the requirement is met.
    lengths : dict
        ``a`` crank, ``b`` coupler, ``c`` rocker, ``d`` frame (crank-slider: ``a``,
        ``b``, ``e`` the guide's offset).
    grashof : str
        The Grashof type: "crank-rocker", "double-crank", "rocker-crank", "double-rocker",
        "change-point" or "triple-rocker" (non-Grashof); "crank-slider" or
        "rocking-slider" for a crank-slider.
    transmission : tuple of float
        The smallest and the largest transmission angle (degrees) over the motion: the
        whole turn when the crank turns fully, else the given range of the crank.
    deviations : ndarray
        The deviation at every given point (signed rad for function generation,
        distances for path and motion generation).
    extra : dict
        What a problem adds: ``psi`` and ``offsets`` (function generation), ``method``,
        the search's ``evaluations``, ...
    """

    mechanism: Mechanism
    error: float
    phi: np.ndarray
    lengths: dict
    grashof: str
    transmission: tuple
    deviations: np.ndarray
    extra: dict = field(default_factory=dict)

    def __repr__(self):
        lengths = ", ".join(f"{k}={v:.6g}" for k, v in self.lengths.items())
        return (f"Synthesis({self.grashof}; {lengths}; error {self.error:.3g}; "
                f"transmission {self.transmission[0]:.1f}..{self.transmission[1]:.1f} deg)")

    def __getattr__(self, name):
        extra = self.__dict__.get("extra", {})
        if name in extra:
            return extra[name]
        raise AttributeError(name)


def grashof_type(a, b, c, d):
    """The Grashof type of the four-bar with crank a, coupler b, rocker c and frame d.

    Grashof's criterion s + l <= p + q (shortest plus longest against the other two)
    decides whether a link turns fully; the shortest link names the type.
    """
    links = (a, b, c, d)
    s, l = min(links), max(links)
    pq = sum(links) - s - l
    if abs(s + l - pq) <= 1e-12 * l:
        return "change-point"
    if s + l > pq:
        return "triple-rocker"
    shortest = int(np.argmin(links))
    return ("crank-rocker", "double-rocker", "rocker-crank", "double-crank")[shortest]


def _turns(a, b, c, d):
    """Whether the crank of the four-bar turns fully (the rocker's group assembles at
    every crank angle): |A C| runs over [|d - a|, d + a], which must lie in
    [|b - c|, b + c].  Returns the violation (0 when it turns)."""
    return np.maximum(0.0, np.maximum(np.abs(b - c) - np.abs(d - a), a + d - (b + c)))


def _transmission_turn(a, b, c, d):
    """The extreme transmission angles (rad) over a whole turn, in closed form: they
    occur where the crank is collinear with the frame, |AC| = |d - a| and d + a."""
    def mu(ac):
        return np.arccos(np.clip((b * b + c * c - ac * ac) / (2.0 * b * c), -1.0, 1.0))
    return mu(np.abs(d - a)), mu(d + a)


def _transmission_of(result):
    """Transmission angles (deg) along a solved four-bar: angle ABC."""
    A, B, C = result.position("A"), result.position("B"), result.position("C")
    u, v = A - B, C - B
    cross = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    dot = (u * v).sum(-1)
    return np.degrees(np.abs(np.arctan2(cross, dot)))


# ---- building and evaluating four-bars -------------------------------------------------

def _fourbar(design):
    """The Mechanism of one design vector (FOURBAR_VARIABLES)."""
    xO, yO, xC, yC, a, b, c, p, q, br = (float(v) for v in design)
    m = Mechanism()
    m.fixed("O", xO, yO)
    m.fixed("C", xC, yC)
    m.crank("A", "O", a)
    m.rrr("B", "A", "C", b, c, branch=1 if br >= 0 else -1)
    m.point("P", "A", "B", math.hypot(p, q), math.atan2(q, p))
    return m


@dataclass
class FourBarPopulation:
    """A population of four-bars solved at the crank angles ``phi`` (positions only).

    ``designs`` (D, 10) the design vectors (FOURBAR_VARIABLES); ``ok`` (D, n) where the
    design assembles; ``position(name)`` (D, n, 2) for the joints "A", "B", "P" (NaN
    where a design does not assemble) and the frame points "O", "C"; ``lengths`` a dict
    of (D,) arrays a, b, c, d; ``transmission()`` (D, n) the angle ABC in degrees.
    """

    designs: np.ndarray
    phi: np.ndarray
    ok: np.ndarray
    points: dict

    def position(self, name):
        if name in ("O", "C"):
            col = (0, 1) if name == "O" else (2, 3)
            xy = self.designs[:, col]
            return np.broadcast_to(xy[:, None, :], self.points["A"].shape)
        return self.points[name]

    @property
    def lengths(self):
        x = self.designs
        return {"a": x[:, 4], "b": x[:, 5], "c": x[:, 6],
                "d": np.hypot(x[:, 2] - x[:, 0], x[:, 3] - x[:, 1])}

    def transmission(self):
        return _transmission_of(self)


def _evaluate(designs, phi):
    """Solve a population of four-bars (designs (D, 10)) at the crank angles phi (n,).

    The one place where designs meet the Mechanism: one description whose pivots,
    lengths and coupler point are arrays over the designs, solved in one compiled call
    per branch (the branch is a choice of the description, not a number)."""
    designs = np.atleast_2d(np.asarray(designs, dtype=float))
    phi = np.asarray(phi, dtype=float)
    D, n = designs.shape[0], phi.size
    pts = {k: np.full((D, n, 2), np.nan) for k in ("A", "B", "P")}
    ok = np.zeros((D, n), dtype=bool)
    valid = np.isfinite(designs).all(axis=1) & (designs[:, 4:7] > 0).all(axis=1)
    for branch in (1, -1):
        idx = np.flatnonzero(valid & ((designs[:, 9] >= 0) == (branch == 1)))
        if idx.size == 0:
            continue
        xO, yO, xC, yC, a, b, c, p, q = designs[idx, :9].T
        m = Mechanism()
        m.fixed("O", xO, yO)
        m.fixed("C", xC, yC)
        m.crank("A", "O", a)
        m.rrr("B", "A", "C", b, c, branch=branch)
        m.point("P", "A", "B", np.hypot(p, q), np.arctan2(q, p))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SignificanceWarning)
            r = m.solve(phi, need="positions", on_error="nan", points=("A", "B", "P"))
        ok[idx] = r.status == 0
        for k in pts:
            pts[k][idx] = r.position(k)
    return FourBarPopulation(designs, phi, ok, pts)


# ---- spreading a population over workers -------------------------------------------------

def _map(func, chunks, workers):
    """``[func(c) for c in chunks]``, in this process, a process pool, or on a dask
    distributed Client; the results do not depend on where they are computed."""
    if workers is None or workers == 1:
        return [func(c) for c in chunks]
    if hasattr(workers, "map") and hasattr(workers, "gather"):        # dask Client
        return workers.gather(workers.map(func, chunks, pure=False))
    return list(workers.map(func, chunks))                            # an executor


def _workers(workers):
    if workers is None:
        return None
    if isinstance(workers, bool):
        raise TypeError("workers must be an int, an executor or a dask Client")
    if isinstance(workers, (int, np.integer)):
        if workers < 1:
            raise ValueError(f"workers must be >= 1, not {workers}")
        return int(workers)
    if hasattr(workers, "map"):
        return workers
    raise TypeError(f"workers must be an int, an executor or a dask Client, not "
                    f"{type(workers).__name__}")


class _Pool:
    """A process pool kept open for one search (workers=int), else the given Client."""

    def __init__(self, workers):
        self.workers, self.pool = workers, None

    def __enter__(self):
        if isinstance(self.workers, int) and self.workers > 1:
            from concurrent.futures import ProcessPoolExecutor
            self.pool = ProcessPoolExecutor(max_workers=self.workers)
            return self.pool
        return self.workers

    def __exit__(self, *exc):
        if self.pool is not None:
            self.pool.shutdown()


# ---- function generation (Freudenstein) --------------------------------------------------

def _freudenstein_system(f, s, d, a, c):
    """Freudenstein's equation K1 cos(s) - K2 cos(f) + K3 = cos(f - s) at crank angles f
    and rocker angles s, as a linear system in the K of the free lengths: a known crank
    a (rocker c) moves its term d/a cos(s) (d/c cos(f)) to the right-hand side."""
    cols, rhs = [], np.cos(f - s)
    if a is None:
        cols.append(np.cos(s))
    else:
        rhs = rhs - (d / a) * np.cos(s)
    if c is None:
        cols.append(-np.cos(f))
    else:
        rhs = rhs + (d / c) * np.cos(f)
    cols.append(np.ones_like(f))
    return np.column_stack(cols), rhs


def _freudenstein_solve(phi, psi, d, a, c, free):
    """The four-bars whose rocker angle is ``psi + beta`` at the crank angle
    ``phi + alpha``, exactly, by Freudenstein's equation

        K1 cos(psi') - K2 cos(phi') + K3 = cos(phi' - psi'),
        K1 = d/a, K2 = d/c, K3 = (a^2 - b^2 + c^2 + d^2)/(2 a c),

    linear in the K of the free lengths; the offsets flagged in ``free`` (alpha, beta)
    are found by a multistart Gauss-Newton on the projected residual.  Returns a list
    of (a, b, c, alpha, beta)."""
    def system(off):
        it = iter(off)
        al = next(it) if free[0] else 0.0
        be = next(it) if free[1] else 0.0
        return (*_freudenstein_system(phi + al, psi + be, d, a, c), al, be)

    def unpack(k, al, be):
        j = 0
        if a is None:
            K1, j = k[j], j + 1
        else:
            K1 = d / a
        if c is None:
            K2, j = k[j], j + 1
        else:
            K2 = d / c
        K3 = k[j]
        if K1 == 0 or K2 == 0:
            return None
        aa, cc = d / K1, d / K2
        b2 = aa * aa + cc * cc + d * d - 2.0 * aa * cc * K3
        if b2 <= 0:
            return None
        # a negative crank (rocker) is the positive one half a turn on: a solution only
        # where that link's dial zero is free
        if aa < 0:
            if not free[0]:
                return None
            aa, al = -aa, al + math.pi
        if cc < 0:
            if not free[1]:
                return None
            cc, be = -cc, be + math.pi
        return aa, math.sqrt(b2), cc, float(_wrap(al)), float(_wrap(be))

    nfree = sum(free)
    if nfree == 0:
        M, rhs, al, be = system(())
        try:
            k = np.linalg.solve(M, rhs)
        except np.linalg.LinAlgError:
            return []
        sol = unpack(k, al, be)
        return [] if sol is None else [sol]

    from scipy.optimize import least_squares

    def residual(off):
        M, rhs, _, _ = system(off)
        k, *_ = np.linalg.lstsq(M, rhs, rcond=None)
        return M @ k - rhs

    grid = np.linspace(-math.pi, math.pi, 12 if nfree == 1 else 7, endpoint=False)
    starts = ([(g,) for g in grid] if nfree == 1 else
              [(g, h) for g in grid for h in grid])
    found = []
    for s0 in starts:
        r = least_squares(residual, np.array(s0, dtype=float), xtol=1e-15, ftol=1e-15,
                          gtol=1e-15, max_nfev=60)
        if np.max(np.abs(r.fun)) > 1e-11:
            continue
        M, rhs, al, be = system(r.x)
        k = np.linalg.solve(M, rhs) if M.shape[0] == M.shape[1] else \
            np.linalg.lstsq(M, rhs, rcond=None)[0]
        sol = unpack(k, al, be)
        if sol is None:
            continue
        if not any(np.allclose(sol, f, atol=1e-8) for f in found):
            found.append(sol)
    return found


def _fg_mechanism(a, b, c, d, branch):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", d, 0.0)
    m.crank("A", "O", a)
    m.rrr("B", "A", "C", b, c, branch=branch)
    return m


def _fg_branch(a, c, d, f, s):
    """The side of B (left +1 of A->C) at each precision point."""
    A = a * np.column_stack([np.cos(f), np.sin(f)])
    B = np.column_stack([d + c * np.cos(s), c * np.sin(s)])
    u, v = np.array([d, 0.0]) - A, B - A
    return np.sign(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])


def _motion_range(phi):
    """Crank angles through the motion from phi[0] to phi[-1] (at least every degree)."""
    k = max(int(abs(phi[-1] - phi[0]) / math.radians(1.0)) + 2, 50)
    return np.union1d(np.linspace(phi[0], phi[-1], k), phi) if phi[-1] > phi[0] else \
        np.union1d(np.linspace(phi[-1], phi[0], k), phi)[::-1]


def _fg_check(a, b, c, d, al, be, phi, psi, branch):
    """Solve the mechanism through the given range; return (result over the range,
    rocker angles at the points) or None when it does not assemble somewhere."""
    m = _fg_mechanism(a, b, c, d, branch)
    f = phi + al
    sweep = _motion_range(f)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SignificanceWarning)
        r = m.solve(sweep, need="positions", on_error="nan")
        if not (r.status == 0).all():
            return None
        at = m.solve(f, need="positions", on_error="nan")
    return m, r, at


def _rocker(result):
    B = result.position("B")
    xC = result.mechanism._fixed["C"]
    return np.arctan2(B[..., 1] - xC[1], B[..., 0] - xC[0])


def _fg_result(m, a, b, c, d, al, be, phi, psi, sweep_result, method):
    f, s = phi + al, psi + be
    at = m.solve(f, need="positions")
    dev = _wrap(_rocker(at) - s)
    tr = _transmission_of(sweep_result)
    g = grashof_type(a, b, c, d)
    if g in ("crank-rocker", "double-crank"):
        lo, hi = _transmission_turn(a, b, c, d)
        trans = (math.degrees(lo), math.degrees(hi))
    else:
        trans = (float(tr.min()), float(tr.max()))
    return Synthesis(m, float(np.max(np.abs(dev))), f, {"a": a, "b": b, "c": c, "d": d},
                     g, trans, dev, {"psi": s, "offsets": (al, be), "method": method,
                                     "branch": m.branch("B")})


def function_generation(phi, psi, ground=1.0, *, crank=None, rocker=None,
                        offsets="auto", method="least_squares"):
    """A four-bar whose rocker angle is ``psi`` when the crank angle is ``phi``.

    The four-bar O-A-B-C has O = (0, 0), C = (ground, 0), the crank O-A and the rocker
    C-B (angles counter-clockwise from +x).  Freudenstein's equation makes the problem
    linear in three constants: three precision points give the four-bar exactly.  A
    length given (``crank`` or ``rocker``, as DSNTZR gives its L3) and each point beyond
    three frees a dial zero -- the crank's offset (or, when that has no solution, the
    rocker's), then both -- so four and five points are met exactly too (``offsets``
    the angles added).  With more points
    than unknowns the design is fitted over them: ``method="least_squares"`` (the sum of
    squared rocker-angle errors) or ``"minimax"`` (the largest), starting from the
    least-squares solution of Freudenstein's equation.

    Parameters
    ----------
    phi, psi : array_like
        Crank and rocker angles (rad), at least 3 points; phi strictly monotone.
    ground : float
        The frame O-C.
    crank, rocker : float, optional
        Fixed lengths of the crank O-A and the rocker C-B.
    offsets : {"auto", "none", "crank", "rocker", "both"}
        Which dial zeros are free: "auto" frees as many as an exact solution needs
        (none beyond five points, where the given angles are fitted as they are).
    method : {"least_squares", "minimax"}
        The fit over more points than unknowns.

    Returns
    -------
    Synthesis
        ``mechanism`` (joints O, A, B, C), ``error`` the largest rocker-angle error at
        the points (rad), ``phi`` the crank angles met (phi plus the crank's offset),
        ``psi``, ``offsets``, ``lengths``, ``grashof``, ``transmission``; the
        mechanism assembles through the whole range of phi on one branch.

    Raises
    ------
    ValueError
        Fewer than 3 points, angles not finite, phi not monotone, more unknowns than
        points, a length not positive.
    RequirementError
        No four-bar: the linear system is singular, a length comes out negative, or
        the solution changes branch or fails to assemble between the points (the
        message says which).
    """
    phi = _angles("phi", phi, 3)
    psi = _angles("psi", psi, 3)
    if psi.size != phi.size:
        raise ValueError(f"psi has {psi.size} values for {phi.size} crank angles phi")
    _monotone("phi", phi)
    d = _positive("ground", ground)
    a, c = _positive("crank", crank), _positive("rocker", rocker)
    if method not in ("least_squares", "minimax"):
        raise ValueError(f"method must be 'least_squares' or 'minimax', not {method!r}")
    n, k = phi.size, (a is not None) + (c is not None)
    names = {"none": (False, False), "crank": (True, False), "rocker": (False, True),
             "both": (True, True)}
    if offsets == "auto":
        nfree = n + k - 3 if n + k <= 5 else 0
        free = (nfree >= 1, nfree >= 2)
    elif offsets in names:
        free = names[offsets]
        nfree = sum(free)
    else:
        raise ValueError(f"offsets must be 'auto', 'none', 'crank', 'rocker' or "
                         f"'both', not {offsets!r}")
    unknowns = 3 - k + nfree
    if n < unknowns:
        raise ValueError(f"phi, psi: {n} points for {unknowns} unknowns (3 Freudenstein "
                         f"constants less {k} given lengths plus {nfree} free offsets)")
    if n == unknowns:
        if offsets == "auto" and nfree == 1:        # the crank's zero, else the rocker's
            try:
                return _fg_exact(phi, psi, d, a, c, free)
            except RequirementError as first:
                try:
                    return _fg_exact(phi, psi, d, a, c, (False, True))
                except RequirementError:
                    raise first from None
        return _fg_exact(phi, psi, d, a, c, free)
    return _fg_fit(phi, psi, d, a, c, free, method)


def _fg_exact(phi, psi, d, a, c, free):
    sols = _freudenstein_solve(phi, psi, d, a, c, free)
    if not sols:
        raise RequirementError("function_generation: Freudenstein's equation has no "
                               "solution with positive lengths through these points "
                               "(best deviation: no four-bar found)")
    best, why = None, []
    for aa, bb, cc, al, be in sols:
        side = _fg_branch(aa, cc, d, phi + al, psi + be)
        if not (np.all(side == side[0]) and side[0] != 0):
            why.append("changes branch between the precision points")
            continue
        chk = _fg_check(aa, bb, cc, d, al, be, phi, psi, int(side[0]))
        if chk is None:
            why.append("does not assemble between the precision points")
            continue
        m, sweep, _ = chk
        res = _fg_result(m, aa, bb, cc, d, al, be, phi, psi, sweep, "exact")
        q = min(res.transmission[0], 180.0 - res.transmission[1])
        if best is None or q > best[0]:
            best = (q, res)
    if best is None:
        err = RequirementError(
            "function_generation: every four-bar through the points " + "; ".join(
                sorted(set(why))) + f" ({len(sols)} candidate(s), in the error's "
            f"candidates: (a, b, c, crank offset, rocker offset))")
        err.candidates = sols
        raise err
    return best[1]


def _fg_fit(phi, psi, d, a, c, free, method):
    """Fit the rocker angles in the least-squares or minimax sense."""
    from scipy.optimize import least_squares, minimize
    # start: Freudenstein's equation in the least-squares sense (linear), no offsets
    kk = np.linalg.lstsq(*_freudenstein_system(phi, psi, d, a, c), rcond=None)[0]
    j = 0
    K1 = kk[j] if a is None else d / a
    j += a is None
    K2 = kk[j] if c is None else d / c
    j += c is None
    K3 = kk[j]
    a0, c0 = (d / K1 if K1 else 1.0), (d / K2 if K2 else 1.0)
    b2 = a0 * a0 + c0 * c0 + d * d - 2 * a0 * c0 * K3
    al0 = be0 = 0.0
    if a0 < 0:          # the crank half a turn on, where its zero is free
        a0, al0 = -a0, (math.pi if free[0] else 0.0)
    if c0 < 0:
        c0, be0 = -c0, (math.pi if free[1] else 0.0)
    if b2 <= 0:
        raise RequirementError("function_generation: the least-squares solution of "
                               "Freudenstein's equation has no real coupler; no start "
                               "for the fit")
    b0 = math.sqrt(b2)
    side = _fg_branch(a0, c0, d, phi + al0, psi + be0)
    branch = int(np.sign(side.sum())) or 1
    # design variables: the free lengths (log scale), the free offsets
    free_a, free_c = a is None, c is None

    def lengths(x):
        j = 0
        aa = math.exp(x[j]) if free_a else a
        j += free_a
        bb = math.exp(x[j])
        j += 1
        cc = math.exp(x[j]) if free_c else c
        j += free_c
        al = x[j] if free[0] else al0
        be = x[j + free[0]] if free[1] else be0
        return aa, bb, cc, al, be

    x0 = ([math.log(a0)] if free_a else []) + [math.log(b0)] + \
        ([math.log(c0)] if free_c else []) + ([al0] if free[0] else []) + \
        ([be0] if free[1] else [])

    def errors_many(X):
        """Rocker-angle errors of several designs (rows of X), in one batched
        evaluation: a design's crank offset alpha is taken out by turning its frame by
        -alpha (C at d e(-alpha)), so that every design is solved at phi itself."""
        L = np.array([lengths(x) for x in X])          # a, b, c, alpha, beta per row
        al, be = L[:, 3], L[:, 4]
        designs = np.column_stack([np.zeros(len(X)), np.zeros(len(X)), d * np.cos(al),
                                   -d * np.sin(al), L[:, :3], np.zeros((len(X), 2)),
                                   np.full(len(X), float(branch))])
        pop = _evaluate(designs, phi)
        B = pop.position("B")
        rock = np.arctan2(B[..., 1] - designs[:, 3:4], B[..., 0] - designs[:, 2:3])
        e = _wrap(rock + al[:, None] - (psi + be[:, None]))
        return np.where(pop.ok, e, math.pi)

    def jac(x, e0=None):
        h = 1e-7 * np.maximum(1.0, np.abs(x))
        X = np.vstack([x] + [x + h[i] * np.eye(x.size)[i] for i in range(x.size)])
        E = errors_many(X)
        return ((E[1:] - E[0]) / h[:, None]).T

    x0 = np.array(x0)
    r = least_squares(lambda x: errors_many([x])[0], x0, jac=jac, xtol=1e-14,
                      ftol=1e-14, gtol=1e-14)
    x = r.x
    if method == "minimax":
        # epigraph form: minimize t subject to -t <= e_i(x) <= t
        def cons(z):
            e = errors_many([z[:-1]])[0]
            return np.concatenate([z[-1] - e, z[-1] + e])

        def cons_jac(z):
            J = jac(z[:-1])
            one = np.ones((J.shape[0], 1))
            return np.vstack([np.hstack([-J, one]), np.hstack([J, one])])
        z0 = np.append(x, np.max(np.abs(errors_many([x])[0])))
        mm = minimize(lambda z: z[-1], z0, jac=lambda z: np.eye(z.size)[-1],
                      constraints=[{"type": "ineq", "fun": cons, "jac": cons_jac}],
                      method="SLSQP", options={"maxiter": 200, "ftol": 1e-15})
        if np.max(np.abs(errors_many([mm.x[:-1]])[0])) < np.max(np.abs(r.fun)):
            x = mm.x[:-1]
    aa, bb, cc, al, be = lengths(x)
    chk = _fg_check(aa, bb, cc, d, al, be, phi, psi, branch)
    if chk is None:
        raise RequirementError("function_generation: the fitted four-bar does not "
                               "assemble through the range of phi (best deviation "
                               f"{np.max(np.abs(r.fun)):.3g} rad)")
    m, sweep, _ = chk
    return _fg_result(m, aa, bb, cc, d, float(_wrap(al)), float(_wrap(be)), phi, psi,
                      sweep, method)


# ---- crank-slider function generation --------------------------------------------------

def _slider_mechanism(a, b, e, branch):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, e)
    m.crank("A", "O", a)
    m.rrp("B", "A", "K", 0.0, b, branch=branch)
    return m


def slider_function_generation(phi, s, *, offset=None):
    """A crank-slider whose slider is at x = ``s`` when the crank angle is ``phi``.

    The crank O-A turns about O = (0, 0); the slider B runs on the guide y = ``offset``
    (direction +x); the rod A-B.  The loop (s - a cos phi)^2 + (e - a sin phi)^2 = b^2
    is linear in K1 = 2a, K2 = 2ae, K3 = a^2 + e^2 - b^2:

        s^2 = K1 s cos(phi) + K2 sin(phi) - K3,

    so three positions give the crank-slider exactly.  With the offset given (as
    DSNTZR's crank-slider gives it), the crank's dial zero is free instead, and
    ``phi`` holds the crank angles met.

    Parameters
    ----------
    phi : array_like
        Three crank angles (rad), strictly monotone.
    s : array_like
        The slider's three positions along the guide (x).
    offset : float, optional
        The guide's offset e (y of the guide); free when not given.

    Returns
    -------
    Synthesis
        ``mechanism`` (O, the guide's point K, A, slider B), ``error`` the largest
        slider error (length unit), ``phi`` the crank angles met, ``lengths`` a, b,
        e, ``offsets`` (alpha,), ``grashof`` "crank-slider" when the crank turns fully
        (b >= a + |e|), else "rocking-slider", ``transmission`` the smallest and
        largest transmission angle (degrees: 90 minus the angle between the rod and
        the guide, so 90 when the rod pushes along the guide).

    Raises
    ------
    ValueError
        Not three positions, values not finite, phi not monotone.
    RequirementError
        No crank-slider with a positive crank and rod, or every one changes branch or
        fails to assemble between the positions.
    """
    phi = _angles("phi", phi, 3)
    s = _angles("s", s, 3)
    if phi.size != 3 or s.size != 3:
        raise ValueError(f"phi, s: exactly 3 positions, not {phi.size}")
    _monotone("phi", phi)
    e = None if offset is None else float(offset)
    if e is not None and not math.isfinite(e):
        raise ValueError("offset must be finite")

    def system(al):
        f = phi + al
        if e is None:       # unknowns K1 = 2a, K2 = 2ae, K3 = a^2 + e^2 - b^2
            return np.column_stack([s * np.cos(f), np.sin(f), -np.ones(3)]), s * s
        # unknowns a and K3: 2 a (s cos + e sin) - K3 = s^2
        return np.column_stack([2 * (s * np.cos(f) + e * np.sin(f)), -np.ones(3)]), s * s

    cands = []                                  # (a, e, b^2, alpha)
    if e is None:
        M, rhs = system(0.0)
        try:
            K1, K2, K3 = np.linalg.solve(M, rhs)
        except np.linalg.LinAlgError:
            raise RequirementError("slider_function_generation: the three positions "
                                   "give a singular system") from None
        if K1 != 0:
            aa, ee = K1 / 2, K2 / K1
            cands.append((aa, ee, aa * aa + ee * ee - K3, 0.0))
    else:
        from scipy.optimize import least_squares

        def residual(x):
            M, rhs = system(x[0])
            k = np.linalg.lstsq(M, rhs, rcond=None)[0]
            return M @ k - rhs
        for g in np.linspace(-math.pi, math.pi, 24, endpoint=False):
            r = least_squares(residual, [g], xtol=1e-15, ftol=1e-15, gtol=1e-15)
            if np.max(np.abs(r.fun)) > 1e-11 * max(1.0, float(np.max(s * s))):
                continue
            M, rhs = system(r.x[0])
            aa, K3 = np.linalg.lstsq(M, rhs, rcond=None)[0]
            cands.append((aa, e, aa * aa + e * e - K3, float(_wrap(r.x[0]))))
    sols = []
    for aa, ee, b2, al in cands:
        if not (aa > 0 and b2 > 0 and math.isfinite(ee)):
            continue
        sol = (aa, math.sqrt(b2), ee, al)
        if not any(np.allclose(sol, q, atol=1e-8) for q in sols):
            sols.append(sol)
    if not sols:
        raise RequirementError("slider_function_generation: no crank-slider with a "
                               "positive crank and rod meets the three positions")
    out = []
    for aa, bb, ee, al in sols:
        f = phi + al
        A = aa * np.column_stack([np.cos(f), np.sin(f)])
        side = np.sign(s - A[:, 0])
        if not (np.all(side == side[0]) and side[0] != 0):
            continue
        m = _slider_mechanism(aa, bb, ee, int(side[0]))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SignificanceWarning)
            sweep = m.solve(_motion_range(f), need="positions", on_error="nan")
            if not (sweep.status == 0).all():
                continue
            at = m.solve(f, need="positions")
        dev = at.position("B")[:, 0] - s
        full = bb >= aa + abs(ee)
        # the rod's angle to the guide's normal: 90 deg when the rod is along the guide
        rod = sweep.position("A") - sweep.position("B")
        tr = np.degrees(np.arccos(np.clip(np.abs(rod[:, 1]) / bb, 0.0, 1.0)))
        if full:
            tr_lo = math.degrees(math.acos(min(1.0, (aa + abs(ee)) / bb)))
            trans = (tr_lo, 90.0)
        else:
            trans = (float(tr.min()), float(tr.max()))
        out.append(Synthesis(m, float(np.max(np.abs(dev))), f,
                             {"a": aa, "b": bb, "e": ee},
                             "crank-slider" if full else "rocking-slider", trans, dev,
                             {"offsets": (al,), "method": "exact",
                              "branch": int(side[0])}))
    if not out:
        raise RequirementError("slider_function_generation: every crank-slider through "
                               "the positions changes branch or fails to assemble "
                               "between them")
    return max(out, key=lambda r: r.transmission[0])


# ---- motion generation (three positions, closed form) ----------------------------------

def _circumcentre(p):
    (x1, y1), (x2, y2), (x3, y3) = p
    den = 2.0 * (x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2))
    scale = max(1.0, float(np.max(np.abs(p)))) ** 2
    if abs(den) <= 1e-12 * scale:
        return None
    s1, s2, s3 = x1 * x1 + y1 * y1, x2 * x2 + y2 * y2, x3 * x3 + y3 * y3
    ux = (s1 * (y2 - y3) + s2 * (y3 - y1) + s3 * (y1 - y2)) / den
    uy = (s1 * (x3 - x2) + s2 * (x1 - x3) + s3 * (x2 - x1)) / den
    return np.array([ux, uy])


def motion_generation(poses, moving=None):
    """A four-bar whose coupler passes through three given positions (the classic
    three-position construction).

    ``poses`` (3, 3): the coupler's reference point P and its angle, (x, y, theta), in
    each position.  ``moving`` ((ax, ay), (bx, by)): the moving pivots A and B in the
    coupler's frame (origin P, x along theta); by default (-L, 0) and (L, 0) with L the
    largest distance between two positions of P.  Each fixed pivot (O for A, C for B)
    is the centre of the circle through the three positions of its moving pivot.

    Returns
    -------
    Synthesis
        ``mechanism`` with the coupler point P, ``phi`` the crank angles of the three
        positions, ``error`` the largest distance of P from its positions,
        ``deviations`` per position, ``angle_error`` the largest coupler-angle error.

    Raises
    ------
    ValueError
        poses not (3, 3) or not finite, moving pivots that coincide.
    RequirementError
        A moving pivot's positions are collinear (its fixed pivot is at infinity: a
        slider would be needed), or the four-bar changes branch between the positions.
    """
    P = np.asarray(poses, dtype=float)
    if P.shape != (3, 3):
        raise ValueError(f"poses must have shape (3, 3) (x, y, theta per position), not "
                         f"{P.shape}")
    if not np.isfinite(P).all():
        raise ValueError("poses must be finite")
    if moving is None:
        L = max(np.hypot(*(P[i, :2] - P[j, :2])) for i in range(3) for j in range(i))
        if L == 0:
            raise ValueError("poses: the three positions of P coincide; give moving=")
        moving = ((-L, 0.0), (L, 0.0))
    mv = np.asarray(moving, dtype=float)
    if mv.shape != (2, 2) or not np.isfinite(mv).all():
        raise ValueError("moving must be two finite points ((ax, ay), (bx, by))")
    if np.hypot(*(mv[0] - mv[1])) == 0:
        raise ValueError("moving: the two moving pivots coincide")

    def world(local):
        c, s = np.cos(P[:, 2]), np.sin(P[:, 2])
        return np.column_stack([P[:, 0] + c * local[0] - s * local[1],
                                P[:, 1] + s * local[0] + c * local[1]])
    A, B = world(mv[0]), world(mv[1])
    O, C = _circumcentre(A), _circumcentre(B)
    for name, ctr in (("A", O), ("B", C)):
        if ctr is None:
            raise RequirementError(f"motion_generation: the three positions of the "
                                   f"moving pivot {name} are collinear (or two "
                                   f"coincide): no fixed pivot")
    a = float(np.hypot(*(A[0] - O)))
    c = float(np.hypot(*(B[0] - C)))
    b = float(np.hypot(*(mv[1] - mv[0])))
    u, v = C - A, B - A
    side = np.sign(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    if not (np.all(side == side[0]) and side[0] != 0):
        raise RequirementError("motion_generation: the four-bar changes branch between "
                               "the positions (the classic branch defect); choose other "
                               "moving pivots")
    phi = np.arctan2(A[:, 1] - O[1], A[:, 0] - O[0])
    # P in the frame of A->B
    e = (mv[1] - mv[0]) / b
    rel = -mv[0]
    p, q = rel @ e, e[0] * rel[1] - e[1] * rel[0]
    design = [O[0], O[1], C[0], C[1], a, b, c, p, q, side[0]]
    m = _fourbar(design)
    # the crank turns from the first position through the second to the third
    phi = np.unwrap(phi)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SignificanceWarning)
        sweep = m.solve(_motion_range(phi), need="positions", on_error="nan")
        if not (sweep.status == 0).all():
            raise RequirementError("motion_generation: the four-bar does not assemble "
                                   "between the positions (a dead centre lies between "
                                   "them); choose other moving pivots")
        at = m.solve(phi, need="positions")
    dev = np.hypot(*(at.position("P") - P[:, :2]).T)
    th = np.arctan2(*(at.position("B") - at.position("A"))[:, ::-1].T)
    ang = _wrap(th - np.arctan2(e[1], e[0]) - P[:, 2])
    d = float(np.hypot(*(C - O)))
    g = grashof_type(a, b, c, d)
    tr = _transmission_of(sweep)
    return Synthesis(m, float(dev.max()), phi, {"a": a, "b": b, "c": c, "d": d}, g,
                     (float(tr.min()), float(tr.max())), dev,
                     {"angle_error": float(np.max(np.abs(ang))), "design": np.array(design),
                      "method": "exact"})


# ---- path generation: global search + refinement -----------------------------------

@dataclass
class _Problem:
    """What one evaluation of a population needs (pickled to workers)."""

    targets: np.ndarray
    phi: np.ndarray | None         # prescribed timing, or None
    length: tuple
    gamma: float                   # min transmission (rad), 0 for none
    scale: float
    objective: object = None       # a user's callable over a FourBarPopulation

    def violation(self, X):
        """Hard requirements' violation (0 when met), per design (rows of X)."""
        a, b, c = X[:, 4], X[:, 5], X[:, 6]
        d = np.hypot(X[:, 2] - X[:, 0], X[:, 3] - X[:, 1])
        lo, hi = self.length
        v = _turns(a, b, c, d) + np.maximum(0.0, lo - d) + np.maximum(0.0, d - hi)
        if self.gamma > 0:
            m1, m2 = _transmission_turn(a, b, c, d)
            v = v + self.scale * np.maximum(0.0, np.maximum(self.gamma - m1,
                                                            m2 - (math.pi - self.gamma)))
        return v

    def __call__(self, X):
        """The cost of each design (rows of X): the largest deviation, plus a penalty
        for a broken requirement."""
        X = np.atleast_2d(X)
        v = self.violation(X)
        cost = np.full(X.shape[0], np.inf)
        good = np.flatnonzero(v == 0)
        if good.size:
            phi = TURN if self.phi is None else self.phi
            pop = _evaluate(X[good], phi)
            if self.objective is not None:
                cost[good] = np.asarray(self.objective(pop), dtype=float)
            else:
                dev = _deviations(pop, self.targets, self.phi is None)
                cost[good] = np.sqrt(np.mean(dev * dev, axis=1))
        bad = ~np.isfinite(cost)
        cost[bad] = 10.0 * self.scale * (1.0 + v[bad] / self.scale)
        return cost


def _deviations(pop, targets, free_timing):
    P = pop.position("P")                         # (D, n, 2)
    if not free_timing:
        dist = np.hypot(*(P - targets).transpose(2, 0, 1))
        return np.where(pop.ok, dist, np.inf)
    # the distance from each target to the sampled coupler curve
    dist = np.hypot(P[:, None, :, 0] - targets[None, :, None, 0],
                    P[:, None, :, 1] - targets[None, :, None, 1])       # (D, n, 360)
    dist = np.where(pop.ok[:, None, :], dist, np.inf)
    return dist.min(axis=2)


def _chunked(problem, X, workers, chunks):
    if workers is None:
        return problem(X)
    parts = np.array_split(X, chunks)
    return np.concatenate(_map(problem, parts, workers))


def _bounds_of(targets, bounds):
    lo_t, hi_t = targets.min(axis=0), targets.max(axis=0)
    span = float(max(np.max(hi_t - lo_t), 1e-300))
    if bounds is None:
        bounds = {}
    if not isinstance(bounds, dict):
        raise TypeError("bounds must be a dict(length=(lo, hi), pivot=((xlo, xhi), "
                        "(ylo, yhi)))")
    unknown = set(bounds) - {"length", "pivot"}
    if unknown:
        raise ValueError(f"bounds: unknown key(s) {sorted(unknown)} (length, pivot)")
    length = bounds.get("length", (0.05 * span, 3.0 * span))
    pivot = bounds.get("pivot", ((lo_t[0] - 2 * span, hi_t[0] + 2 * span),
                                 (lo_t[1] - 2 * span, hi_t[1] + 2 * span)))
    try:
        lo, hi = (float(v) for v in length)
        (xlo, xhi), (ylo, yhi) = ((float(u), float(v)) for u, v in pivot)
    except (TypeError, ValueError):
        raise ValueError("bounds: length must be (lo, hi) and pivot ((xlo, xhi), "
                         "(ylo, yhi))") from None
    vals = [lo, hi, xlo, xhi, ylo, yhi]
    if not all(math.isfinite(v) for v in vals):
        raise ValueError("bounds must be finite")
    if not (0 < lo < hi):
        raise ValueError(f"bounds: length must satisfy 0 < lo < hi, not ({lo}, {hi})")
    if not (xlo < xhi and ylo < yhi):
        raise ValueError("bounds: pivot ranges must be increasing (lo < hi)")
    # a crank that turns fully needs d + a <= b + c with a the shortest: at least the
    # frame must fit between the pivots' box
    dmax = math.hypot(xhi - xlo, yhi - ylo)
    if dmax < lo:
        raise ValueError(f"bounds: the pivot box (diagonal {dmax:.3g}) cannot hold a "
                         f"frame of the smallest length {lo:.3g}: no design")
    sb = [(xlo, xhi), (ylo, yhi), (xlo, xhi), (ylo, yhi), (lo, hi), (lo, hi), (lo, hi),
          (-hi, hi), (-hi, hi), (-1.0, 1.0)]
    return sb, (lo, hi), span


def _refine(problem, x, free_timing, phi0, sb):
    """least_squares from a design found by the search: the design's 9 continuous
    variables (the branch kept) and, for free timing, the crank angles of the targets.
    The Jacobian by forward differences is one batched evaluation of the perturbed
    designs (and, for free timing, one of the design at the perturbed angles: each
    target depends on its own angle only)."""
    from scipy.optimize import least_squares
    br = 1.0 if x[9] >= 0 else -1.0
    T = problem.targets
    n = T.shape[0]
    w = math.sqrt(1e3)

    def residuals(designs, phi):
        pop = _evaluate(designs, phi)
        P = pop.position("P")
        r = np.where(pop.ok[:, :, None], P - T, problem.scale).reshape(len(designs), -1)
        return np.column_stack([r, w * problem.violation(designs)])

    def split(z):
        return np.append(z[:9], br), (z[9:] if free_timing else problem.phi)

    def fun(z):
        design, phi = split(z)
        return residuals(design[None, :], phi)[0]

    def jac(z):
        design, phi = split(z)
        h = 1e-7 * np.maximum(problem.scale, np.abs(z[:9]))
        designs = np.vstack([design] + [design + np.append(h[i] * np.eye(9)[i], 0.0)
                                        for i in range(9)])
        R = residuals(designs, phi)
        J = np.zeros((R.shape[1], z.size))
        J[:, :9] = ((R[1:] - R[0]) / h[:, None]).T
        if free_timing:
            hp = 1e-7 * np.maximum(1.0, np.abs(phi))
            Rp = residuals(design[None, :], phi + hp)[0]
            d = (Rp - R[0])[:2 * n].reshape(n, 2) / hp[:, None]
            J[2 * np.arange(n), 9 + np.arange(n)] = d[:, 0]
            J[2 * np.arange(n) + 1, 9 + np.arange(n)] = d[:, 1]
        return J

    z0 = np.concatenate([x[:9], phi0]) if free_timing else np.array(x[:9])
    lo = np.array([b[0] for b in sb[:9]] + [-np.inf] * (z0.size - 9))
    hi = np.array([b[1] for b in sb[:9]] + [np.inf] * (z0.size - 9))
    r = least_squares(fun, np.clip(z0, lo, hi), jac=jac, bounds=(lo, hi), xtol=1e-13,
                      ftol=1e-13, gtol=1e-13, max_nfev=60)
    return split(r.x)


def _search(problem, bounds, seed, workers, popsize, maxiter, tol=1e-12):
    from scipy.optimize import differential_evolution
    workers = _workers(workers)
    with _Pool(workers) as pool:
        if isinstance(workers, int):
            chunks = workers
        elif hasattr(workers, "scheduler_info"):                      # dask Client
            chunks = max(1, len(workers.scheduler_info().get("workers", ())))
        else:
            chunks = getattr(workers, "_max_workers", 4)

        count = [0]

        def cost(Xt):                  # scipy passes (N, S): one column per design
            count[0] += np.shape(Xt)[1]
            return _chunked(problem, np.asarray(Xt).T, pool, chunks)
        res = differential_evolution(cost, bounds, popsize=popsize, maxiter=maxiter,
                                     seed=np.random.default_rng(seed), tol=tol,
                                     polish=False, vectorized=True, updating="deferred",
                                     init="sobol" if popsize * len(bounds) >= 16 else
                                     "latinhypercube")
    res.designs = count[0]
    return res


def _finish(problem, design, phi, targets, method, evaluations):
    m = _fourbar(design)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SignificanceWarning)
        turn = m.solve(TURN, need="positions", on_error="nan")
        at = m.solve(phi, need="positions", on_error="nan")
    dev = np.hypot(*(at.position("P") - targets).T)
    a, b, c = design[4:7]
    d = float(np.hypot(design[2] - design[0], design[3] - design[1]))
    lo, hi = _transmission_turn(a, b, c, d)
    return Synthesis(m, float(dev.max()), np.asarray(phi), {"a": a, "b": b, "c": c,
                     "d": d}, grashof_type(a, b, c, d),
                     (math.degrees(lo), math.degrees(hi)), dev,
                     {"design": np.asarray(design), "method": method,
                      "evaluations": evaluations, "turn_ok": bool((turn.status == 0).all()),
                      "turn_transmission": _transmission_of(turn)})


def _requirement_report(problem, res):
    """Which requirement the best designs fail, and by how much."""
    X = np.atleast_2d(res.population) if hasattr(res, "population") else res.x[None, :]
    v = problem.violation(X)
    k = int(np.argmin(v))
    x = X[k]
    a, b, c = x[4:7]
    d = math.hypot(x[2] - x[0], x[3] - x[1])
    parts = []
    t = float(_turns(a, b, c, d))
    if t > 0:
        parts.append(f"the crank does not turn fully (|b - c| <= |d - a| and a + d <= "
                     f"b + c missed by {t:.3g})")
    lo, hi = problem.length
    if d < lo or d > hi:
        parts.append(f"the frame {d:.3g} is outside the length bounds ({lo:.3g}, "
                     f"{hi:.3g})")
    if problem.gamma > 0:
        m1, m2 = _transmission_turn(a, b, c, d)
        worst = math.degrees(min(m1, math.pi - m2))
        if worst < math.degrees(problem.gamma):
            parts.append(f"min_transmission {math.degrees(problem.gamma):.3g} deg: the "
                         f"best design reaches {worst:.3g} deg")
    text = "; ".join(parts) or "no design assembles"
    if problem.objective is None:
        phi = TURN if problem.phi is None else problem.phi
        dev = _deviations(_evaluate(x[None, :], phi), problem.targets, problem.phi is None)
        if np.isfinite(dev).all():
            text += f" (that design's largest deviation from the targets: {dev.max():.3g})"
    return text


def _transmission_limit(min_transmission):
    """The least transmission angle asked for, rad (0: none), from degrees in (0, 90)."""
    if min_transmission is None:
        return 0.0
    mt = float(min_transmission)
    if not (0.0 < mt < 90.0):
        raise ValueError(f"min_transmission must be in (0, 90) degrees, not {mt}")
    return math.radians(mt)


def path_generation(targets, phi=None, bounds=None, min_transmission=None, seed=None,
                    workers=None, *, popsize=20, maxiter=300, refine=True):
    """A four-bar with a coupler point P passing through ``targets``.

    The crank turns fully (the design is a crank-rocker or a double-crank: the rocker's
    group assembles at every crank angle) and, with ``min_transmission``, the
    transmission angle stays within [min_transmission, 180 - min_transmission] degrees
    over the whole turn: these are hard requirements, never traded for accuracy.

    The search: :func:`scipy.optimize.differential_evolution` over the design (the
    pivots O and C, the crank a, coupler b, rocker c, the coupler point (p, q) in the
    coupler's frame -- along A->B and to its left -- and the branch), each generation a
    population evaluated at once and split over ``workers``; then
    :func:`scipy.optimize.least_squares` from the best design (with free timing also
    over the crank angles of the targets).

    Parameters
    ----------
    targets : array_like, shape (n, 2)
        The points P must pass through: at least 5 (9 unknowns, two equations each),
        with ``phi`` at least 5 as well.
    phi : array_like, optional
        Prescribed timing: the crank angles (rad, from +x) at which P is at the
        targets.  Without it, the targets may be reached at any crank angles (each
        target's distance from the coupler curve is measured).
    bounds : dict, optional
        ``length=(lo, hi)`` for the links and the frame, ``pivot=((xlo, xhi),
        (ylo, yhi))`` for both fixed pivots; by default from the targets' extent.
    min_transmission : float, optional
        Degrees (0 < min_transmission < 90).
    seed : int, optional
        The same seed gives the same design, with or without workers.
    workers : int or Executor or dask.distributed.Client, optional
        Spread each population's evaluation over that many processes (or the given
        executor's, or the dask cluster's workers).
    popsize, maxiter : int
        differential_evolution's population size (times 10 variables) and generations.
    refine : bool
        Polish the best design with least_squares.

    Returns
    -------
    Synthesis
        ``mechanism`` (O, C, A, B and the coupler point P), ``error`` the largest
        distance from a target, ``phi`` the crank angles met, ``deviations`` per
        target, ``lengths``, ``grashof``, ``transmission`` over the whole turn.

    Raises
    ------
    ValueError
        Fewer than 5 targets, targets or phi not finite or of the wrong shape, bounds
        that exclude every design, min_transmission outside (0, 90).
    RequirementError
        No design in the search meets the requirements (says which failed and the
        best deviation).
    """
    T = np.asarray(targets)
    if T.dtype.kind not in "fiu":
        raise TypeError("targets must be real numbers")
    T = np.asarray(T, dtype=float)
    if T.ndim != 2 or T.shape[1] != 2:
        raise ValueError(f"targets must have shape (n, 2), not {T.shape}")
    if not np.isfinite(T).all():
        raise ValueError("targets must be finite")
    if T.shape[0] < 5:
        raise ValueError(f"targets: {T.shape[0]} points given, path generation needs at "
                         f"least 5")
    if phi is not None:
        phi = _angles("phi", phi, 5)
        if phi.size != T.shape[0]:
            raise ValueError(f"phi has {phi.size} angles for {T.shape[0]} targets")
    gamma = _transmission_limit(min_transmission)
    sb, length, span = _bounds_of(T, bounds)
    for name, v in (("popsize", popsize), ("maxiter", maxiter)):
        if not isinstance(v, (int, np.integer)) or v < 1:
            raise ValueError(f"{name} must be a positive int, not {v!r}")
    problem = _Problem(T, phi, length, gamma, span)
    return _run(problem, sb, seed, workers, popsize, maxiter, refine, "path_generation")


def _phi_on_curve(problem, design):
    """The crank angles where the design's coupler curve comes closest to each target."""
    P = _evaluate(design[None, :], TURN).position("P")[0]
    j = np.argmin(np.hypot(P[None, :, 0] - problem.targets[:, None, 0],
                           P[None, :, 1] - problem.targets[:, None, 1]), axis=1)
    return TURN[j]


def _run(problem, sb, seed, workers, popsize, maxiter, refine, what, candidates=3):
    free = problem.phi is None
    res = _search(problem, sb, seed, workers, popsize, maxiter)
    best = np.array(res.x)
    if problem.violation(best[None, :])[0] > 0:
        raise RequirementError(f"{what}: no design in the search meets the "
                               f"requirements: " + _requirement_report(problem, res))
    phi0 = _phi_on_curve(problem, best) if free else problem.phi
    out = _finish(problem, best, phi0, problem.targets, "differential_evolution",
                  int(res.designs))
    if refine and problem.objective is None:
        # least_squares from the best few distinct designs of the last population
        order = np.argsort(res.population_energies)
        starts = [best]
        for k in order:
            x = res.population[k]
            if len(starts) >= candidates:
                break
            if problem.violation(x[None, :])[0] == 0 and not any(
                    np.allclose(x, y, rtol=1e-3, atol=1e-3 * problem.scale)
                    for y in starts):
                starts.append(x)
        for x in starts:
            p0 = _phi_on_curve(problem, x) if free else problem.phi
            d2, p2 = _refine(problem, x, free, p0, sb)
            if problem.violation(d2[None, :])[0] > 0:
                continue
            new = _finish(problem, d2, p2, problem.targets,
                          "differential_evolution+least_squares", int(res.designs))
            if new.extra["turn_ok"] and new.error < out.error:
                out = new
    if not out.extra["turn_ok"]:
        raise RequirementError(f"{what}: the best design does not assemble over the "
                               f"whole turn (best deviation {out.error:.3g})")
    if problem.objective is not None:
        out.extra["objective"] = float(res.fun)
    if free:
        out.phi = np.mod(out.phi, TWO_PI)
    return out


def fourbar_search(objective, phi, bounds, min_transmission=None, seed=None,
                   workers=None, *, popsize=20, maxiter=300):
    """A four-bar minimising a user's ``objective`` over batched results.

    ``objective(population)`` gets a :class:`FourBarPopulation` (a population of
    four-bars with a coupler point P, solved at the crank angles ``phi``:
    ``population.position("P")`` has shape (D, n, 2), NaN where a design does not
    assemble, ``population.ok`` (D, n), ``population.lengths``,
    ``population.transmission()``) and returns one cost per design (D,).  It must be
    picklable (a module-level function) for process or dask workers.  The crank turns
    fully and ``min_transmission`` holds, as in :func:`path_generation`; ``bounds``
    as there, but required (there are no targets to take a scale from): it must give
    ``length`` and ``pivot``.

    Returns
    -------
    Synthesis
        As :func:`path_generation`; ``objective`` the best cost, ``error`` and
        ``deviations`` are 0 (no targets).
    """
    if not callable(objective):
        raise TypeError("objective must be callable (population -> costs)")
    phi = _angles("phi", phi, 1)
    if not isinstance(bounds, dict) or set(bounds) != {"length", "pivot"}:
        raise ValueError("bounds must be dict(length=(lo, hi), pivot=((xlo, xhi), "
                         "(ylo, yhi)))")
    (xlo, xhi), (ylo, yhi) = bounds["pivot"]
    box = np.array([[xlo, ylo], [xhi, yhi]], dtype=float)
    sb, length, span = _bounds_of(box, bounds)
    gamma = _transmission_limit(min_transmission)
    T = np.zeros((phi.size, 2))
    problem = _Problem(T, phi, length, gamma, span, objective)
    out = _run(problem, sb, seed, workers, popsize, maxiter, False, "fourbar_search")
    out.error = 0.0
    out.deviations = np.zeros(phi.size)
    return out
