"""What every course asks of a linkage, from a sweep of the crank: the extreme positions
and the stroke of a point or a slider, the swing of a rocker, the time ratio (the
coefficient of the change of the mean velocity), and the transmission angle over the
cycle with its worst value and where.

The functions here take plain arrays (the crank angles ``phi`` of a sweep and a quantity
sampled there); :class:`sarkp.MechanismResult` calls them for its joints and links
(``r.extremes("E")``, ``r.stroke("E")``, ``r.time_ratio("E")``,
``r.transmission_angle("B")``).  Extremes are located between the grid points: around
the grid point of the extreme, a polynomial of degree 4 through five neighbouring values
(fewer at the ends of a sweep that is not a full turn) is set stationary; on a grid of
one degree this puts the extreme value within about 1e-9 of the quantity's range.

Conventions: angles in radians, lengths in the units of the positions (metres for a
Mechanism); a full turn is a sweep whose crank angles span 2 pi (with or without the
closing point).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

__all__ = ["Extremes", "Transmission", "extremes", "point_extremes", "time_ratio",
           "transmission", "transmission_angle", "full_turn"]


class Extremes(NamedTuple):
    """The extreme values of a quantity over a sweep of the crank.

    Attributes
    ----------
    low, high : float
        The smallest and the largest value (for a point: its coordinate along ``along``,
        m; for a link: its angle, rad).
    phi_low, phi_high : float
        The crank angles (rad) of the two extreme positions, between grid points.
    stroke : float
        ``high - low``: a slider's or a point's stroke (m), a rocker's swing (rad).
    along : tuple of float, or None
        For a point: the unit vector (ux, uy) its coordinate is measured along.
    at_low, at_high : tuple of float, or None
        For a point: its (x, y) in the two extreme positions, m.
    """
    low: float
    high: float
    phi_low: float
    phi_high: float
    stroke: float
    along: tuple | None = None
    at_low: tuple | None = None
    at_high: tuple | None = None


class Transmission(NamedTuple):
    """The transmission angle over a sweep.

    Attributes
    ----------
    angle : ndarray
        At each position, the angle (rad, in [0, pi]) between the coupler (the line of
        the force it carries, from the joint to its other end) and the normal to the
        output's path at the joint: for a rocker (RRR) the rocker itself, for a slider
        (RRP) the guide's normal.  90 degrees transmits best.
    worst : float
        The smallest acute transmission angle over the sweep, ``min(angle, pi - angle)``
        at its worst (rad, in [0, pi/2]), located between the grid points.
    phi_worst : float
        The crank angle (rad) where it occurs.
    smallest, largest : float
        The extremes of ``angle`` (rad), located between the grid points.
    """
    angle: np.ndarray
    worst: float
    phi_worst: float
    smallest: float
    largest: float


def _sweep(who, phi, values):
    phi = np.asarray(phi, dtype=float)
    values = np.asarray(values, dtype=float)
    if phi.ndim != 1:
        raise ValueError(f"{who}: phi must be 1-D (one design at a time), not of shape "
                         f"{phi.shape}")
    if values.shape[:1] != phi.shape:
        raise ValueError(f"{who}: {values.shape[0] if values.ndim else 0} values for "
                         f"{phi.size} crank angles")
    if phi.size < 3:
        raise ValueError(f"{who}: a sweep of at least 3 positions is needed, not {phi.size}")
    if not (np.all(np.isfinite(phi)) and np.all(np.isfinite(values))):
        raise ValueError(f"{who}: the sweep has NaN or infinite values (a failed position?)")
    step = np.diff(phi)
    if not (np.all(step > 0) or np.all(step < 0)):
        raise ValueError(f"{who}: the crank angles must increase (or decrease) strictly")
    return phi, values


def full_turn(phi) -> bool:
    """Whether the crank angles ``phi`` (monotonic) cover one full turn: a span of 2 pi
    (the closing point repeated) or of 2 pi minus one step (a uniform grid without it)."""
    phi = np.asarray(phi, dtype=float)
    span = abs(phi[-1] - phi[0])
    step = abs(phi[-1] - phi[-2])
    tol = 1e-9 * 2 * math.pi
    return abs(span - 2 * math.pi) <= tol or abs(span + step - 2 * math.pi) <= tol


def _periodic(phi, values):
    """(phi, values, periodic): a full turn with its closing point dropped."""
    if not full_turn(phi):
        return phi, values, False
    if abs(abs(phi[-1] - phi[0]) - 2 * math.pi) <= 1e-9 * 2 * math.pi:
        return phi[:-1], values[:-1], True
    return phi, values, True


def _window(phi, s, k, periodic):
    """The crank angles (relative to ``phi[k]``) and values of the five grid points
    around ``k``: across the seam of a full turn when ``periodic``, else cut at the
    sweep's ends."""
    n = phi.size
    if periodic and n >= 5:
        turn = 2 * math.pi if phi[-1] > phi[0] else -2 * math.pi
        idx = np.arange(k - 2, k + 3)
        return phi[idx % n] + turn * np.floor_divide(idx, n) - phi[k], s[idx % n]
    lo, hi = max(0, k - 2), min(n, k + 3)
    return phi[lo:hi] - phi[k], s[lo:hi]


def _refine(phi, s, k, periodic, sign):
    """(crank angle, value) of the extreme of ``s`` near the grid point ``k`` (sign +1 a
    maximum, -1 a minimum): the stationary point of the polynomial of degree 4 through
    the five values around ``k`` (fewer at a sweep's end), within one step of ``k``."""
    n = phi.size
    if not (periodic and n >= 5) and k in (0, n - 1):
        return float(phi[k]), float(s[k])          # an end of the sweep: no neighbours
    t, v = _window(phi, s, k, periodic)
    h = float(np.max(np.abs(t)))
    u = t / h
    degree = min(4, u.size - 1)
    coef = np.polyfit(u, v, degree)
    roots = np.roots(np.polyder(coef))
    best = (0.0, float(s[k]))
    near = float(np.min(np.abs(u[u != 0])))        # one step to the nearer neighbour
    for r in roots:
        if abs(r.imag) > 1e-9 or abs(r.real) > near:
            continue
        value = float(np.polyval(coef, r.real))
        if sign * (value - best[1]) > 0:
            best = (float(r.real), value)
    return float(phi[k] + best[0] * h), best[1]


def _wrap_angle(phi0, phi):
    """``phi`` in the turn that starts at ``phi0`` (a full turn of the sweep)."""
    return phi0 + math.remainder(phi - phi0 - math.pi, 2 * math.pi) + math.pi


def extremes(phi, s) -> Extremes:
    """The smallest and largest value of ``s`` over the sweep ``phi`` and the crank angles
    where they occur, located between the grid points.

    Parameters
    ----------
    phi : array_like
        Crank angles of the sweep, rad, strictly monotonic (a full turn, or a part).
    s : array_like
        The quantity at each crank angle (a coordinate, m; an angle, rad, continuous).

    Returns
    -------
    Extremes
        ``stroke = high - low``.
    """
    phi, s = _sweep("extremes", phi, s)
    if s.ndim != 1:
        raise ValueError(f"extremes: s must be 1-D, not of shape {s.shape}")
    p, v, periodic = _periodic(phi, s)
    phi_low, low = _refine(p, v, int(np.argmin(v)), periodic, -1)
    phi_high, high = _refine(p, v, int(np.argmax(v)), periodic, +1)
    if periodic:
        phi_low, phi_high = _wrap_angle(phi[0], phi_low), _wrap_angle(phi[0], phi_high)
    return Extremes(low, high, phi_low, phi_high, high - low)


def _direction(who, along):
    if np.ndim(along) == 0:
        a = float(along)
        if not math.isfinite(a):
            raise ValueError(f"{who}: along must be a finite angle (rad), not {along!r}")
        return np.array([math.cos(a), math.sin(a)])
    u = np.asarray(along, dtype=float)
    norm = float(np.hypot(*u)) if u.shape == (2,) else 0.0
    if not (math.isfinite(norm) and norm > 0):
        raise ValueError(f"{who}: along must be an angle (rad) or a nonzero vector "
                         f"(ux, uy), not {along!r}")
    return u / norm


def point_extremes(phi, xy, along=None) -> Extremes:
    """The extreme positions of a point and its stroke: the smallest and largest value of
    its coordinate along the unit vector ``along``.

    Parameters
    ----------
    phi : array_like
        Crank angles of the sweep, rad.
    xy : array_like
        The point's (x, y) at each crank angle, shape (n, 2).
    along : float or (float, float), optional
        A direction (an angle, rad, or a vector).  Default: the direction in which the
        path spreads most (its principal axis; for a slider on a fixed guide, the
        guide), turned to point into the half plane x > 0 (or up, when vertical).

    Returns
    -------
    Extremes
        With ``along`` and the point's (x, y) in both extreme positions.
    """
    phi, xy = _sweep("point_extremes", phi, xy)
    if xy.ndim != 2 or xy.shape[1] != 2:
        raise ValueError(f"point_extremes: xy must have shape (n, 2), not {xy.shape}")
    if along is None:
        centred = xy - xy.mean(axis=0)
        u = np.linalg.svd(centred, full_matrices=False)[2][0]
        if u[0] < 0 or (u[0] == 0 and u[1] < 0):
            u = -u
    else:
        u = _direction("point_extremes", along)
    e = extremes(phi, xy @ u)
    # the point in the extreme positions: along the path, interpolated as the extreme
    at = []
    for phi_e in (e.phi_low, e.phi_high):
        p, v, periodic = _periodic(phi, xy)
        k = int(np.argmin(np.abs(np.remainder(p - phi_e + math.pi, 2 * math.pi) - math.pi)))
        at.append(tuple(_refine_at(p, v[:, j], k, periodic, phi_e) for j in range(2)))
    return e._replace(along=tuple(map(float, u)), at_low=at[0], at_high=at[1])


def _refine_at(phi, s, k, periodic, phi_e):
    """The value at ``phi_e`` of the polynomial through the values around ``k``."""
    t, v = _window(phi, s, k, periodic)
    d = phi_e - phi[k]
    if periodic and phi.size >= 5:
        d = math.remainder(d, 2 * math.pi)
    h = float(np.max(np.abs(t)))
    coef = np.polyfit(t / h, v, min(4, t.size - 1))
    return float(np.polyval(coef, d / h))


def time_ratio(phi, s) -> float:
    """The time ratio K (coefficient of the change of the mean velocity): the crank angle
    turned on the slower stroke over that of the faster one, ``K >= 1``, from the crank
    angles of the two extreme positions of ``s`` (a turn at constant speed: the ratio of
    the strokes' times).

    Parameters
    ----------
    phi : array_like
        Crank angles of a full turn, rad.
    s : array_like
        The output's coordinate or angle at each crank angle.

    Raises
    ------
    ValueError
        When ``phi`` is not a full turn.
    """
    phi, s = _sweep("time_ratio", phi, s)
    if not full_turn(phi):
        raise ValueError(f"time_ratio: the sweep must be a full turn of the crank (its "
                         f"crank angles span {abs(phi[-1] - phi[0]):.6g} rad, not 2 pi)")
    e = extremes(phi, s)
    forward = (e.phi_high - e.phi_low) % (2 * math.pi)
    back = 2 * math.pi - forward
    if min(forward, back) <= 0:
        raise ValueError("time_ratio: the two extreme positions coincide (no stroke)")
    return max(forward, back) / min(forward, back)


def transmission(phi, angle) -> Transmission:
    """The transmission angle over a sweep, its worst acute value and where.

    Parameters
    ----------
    phi : array_like
        Crank angles of the sweep, rad.
    angle : array_like
        The transmission angle (rad, in [0, pi]) at each crank angle.

    Returns
    -------
    Transmission
    """
    phi, angle = _sweep("transmission", phi, angle)
    e = extremes(phi, angle)
    if e.low <= math.pi - e.high:
        worst, where = e.low, e.phi_low
    else:
        worst, where = math.pi - e.high, e.phi_high
    return Transmission(angle, max(0.0, worst), where, e.low, e.high)


def _between(u, v):
    """The angle (rad, in [0, pi]) between vectors u and v (arrays (..., 2))."""
    cross = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    dot = np.sum(u * v, axis=-1)
    return np.abs(np.arctan2(cross, dot))


def transmission_angle(result, joint) -> Transmission:
    """The transmission angle at ``joint``, the new joint of a group of kind 1 (RRR: the
    angle at B between B->A and B->C) or kind 2 (RRP: the angle between the rod B->A and
    the guide's normal), over the sweep of ``result`` (a :class:`sarkp.MechanismResult`
    solved over crank angles).  Other kinds raise ValueError."""
    m = result.mechanism
    who = f"transmission_angle({joint!r})"
    step = [s for s in m._steps if s[3] == joint and 1 <= s[0] <= 5]
    if not step:
        raise ValueError(f"{who}: no group places joint {joint!r}")
    kind, ints = step[0][0], step[0][1]
    rod = m._links[ints[3]].name                    # (A, B): link 2 of the group
    b = result.position(joint)
    to_a = result.position(rod[0]) - b
    if kind == 1:
        other = m._links[ints[4]].name              # (C, B)
        normal = result.position(other[0]) - b
    elif kind == 2:
        g = result.angle(joint)                     # the slider block's guide direction
        normal = np.stack([-np.sin(g), np.cos(g)], axis=-1)
    else:
        raise ValueError(f"{who}: defined here for a rocker (rrr) or a slider (rrp), not "
                         f"a group of kind {kind} ({('rpr', 'prp', 'rpp')[kind - 3]})")
    return transmission(result.phi, _between(to_a, normal))


# ---- for sarkp.MechanismResult's methods -------------------------------------------------

def _output(result, who, point, link, along):
    """(phi, values) of a result's point (its coordinate along ``along``) or link (its
    angle); exactly one of ``point`` and ``link``."""
    if (point is None) == (link is None):
        raise ValueError(f"{who}: name a point (a joint's name) or a link (link=(P, Q), "
                         f"or a slider's name), one of them")
    if link is not None:
        if along is not None:
            raise ValueError(f"{who}: along is for a point; a link's angle has no direction")
        names = (link,) if isinstance(link, str) else tuple(link)
        return "link", result.angle(*names)
    return "point", result.position(point)


def result_extremes(result, point=None, link=None, along=None) -> Extremes:
    """:meth:`sarkp.MechanismResult.extremes`."""
    what, values = _output(result, "extremes", point, link, along)
    if what == "link":
        return extremes(result.phi, values)
    return point_extremes(result.phi, values, along)


def result_time_ratio(result, point=None, link=None, along=None) -> float:
    """:meth:`sarkp.MechanismResult.time_ratio`."""
    what, values = _output(result, "time_ratio", point, link, along)
    if what == "point":
        u = np.array(point_extremes(result.phi, values, along).along)
        values = np.asarray(values) @ u
    return time_ratio(result.phi, values)
