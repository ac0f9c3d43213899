"""Pictures of mechanisms and their diagrams (matplotlib, an optional extra).

matplotlib is imported inside the functions only, so ``import sarkp`` never needs it.
Every function draws on a new ``matplotlib.figure.Figure`` (no pyplot state, no display
needed) and returns it; ``save(figure, path)`` writes a PNG.

Linkages (chapter 4, program X):

* :func:`mechanism`: a planar linkage drawn in several positions, with the paths of
  chosen points;
* :func:`diagrams`: quantities against the crank angle, one panel per unit.

Cams (chapter 5):

* :func:`cam_profile`: the profile, its base circle and the follower in one position;
* :func:`cam_diagrams`: the pressure angle and the radius of curvature against the cam
  angle.

Forces and dynamics (chapters 7-8):

* :func:`reaction_hodograph`: the hodograph of a joint reaction over a crank turn, the tip
  of the force vector (F cos G, F sin G) drawn from the origin (e.g. program VII.10's F21);
* :func:`speed_diagram`: omega(phi) of the reduction link from DZKNDV, with and without
  the flywheel of DMHVK (Fig. 96's WPR and WPRM).

Gears (chapter 6):

* :func:`gear_mesh`: an external spur mesh near its pitch point, both wheels' involute
  teeth, the line of action and its active length (DGMZPC, DGMTZK).
"""

from __future__ import annotations

import math

import numpy as np


def _figure(*, rows=1, size=(6.0, 6.0)):
    try:
        from matplotlib.figure import Figure
    except ImportError as exc:            # pragma: no cover - depends on the installation
        raise ImportError("sarkp.plot needs matplotlib: pip install matplotlib") from exc
    figure = Figure(figsize=size, layout="constrained")
    axes = figure.subplots(rows, 1, squeeze=False)[:, 0]
    return figure, axes


def save(figure, path) -> None:
    """Write ``figure`` as a PNG file."""
    figure.savefig(path, dpi=120)


def mechanism(points, links, *, fixed=(), guide=None, highlight=0, every=1, paths=(),
              title=""):
    """A planar linkage in several positions.

    ``points``: {name: (x, y)} with x, y arrays over the positions (m), or floats for a
    fixed point; ``links``: tuples of point names, each drawn as a polyline (a lever
    B-C-D as one tuple); ``fixed``: names drawn as frame pivots; ``guide``: the height
    (m) of a horizontal slider guide; ``highlight``: the position drawn in colour, with
    the point names; ``every``: draw every n-th other position in grey; ``paths``: names
    whose paths are drawn."""
    xy = {n: (np.atleast_1d(np.asarray(x, float)), np.atleast_1d(np.asarray(y, float)))
          for n, (x, y) in points.items()}
    count = max(v[0].size for v in xy.values())

    def at(name, k):
        x, y = xy[name]
        return (x[k] if x.size > 1 else x[0]), (y[k] if y.size > 1 else y[0])
    figure, (ax,) = _figure(size=(7.5, 6.0))
    for k in range(0, count, max(1, every)):
        if k == highlight:
            continue
        for link in links:
            c = [at(n, k) for n in link]
            ax.plot([p[0] for p in c], [p[1] for p in c], "-", color="0.75", lw=0.8)
    for i, name in enumerate(paths):
        x, y = xy[name]
        ax.plot(x, y, "-", color=f"C{i + 2}", lw=3.0, alpha=0.45, label=f"path of {name}")
    for i, link in enumerate(links):
        c = [at(n, highlight) for n in link]
        ax.plot([p[0] for p in c], [p[1] for p in c], "o-", color="C0", lw=2.2, ms=4,
                label="position 1" if i == 0 else None)
    for name in fixed:
        x, y = at(name, 0)
        ax.plot([x], [y], "^", color="k", ms=9)
    for name in xy:
        x, y = at(name, highlight)
        ax.annotate(name, (x, y), xytext=(7, -12), textcoords="offset points",
                    fontsize=10, color="C0", fontweight="bold", zorder=5,
                    bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8))
    if guide is not None:
        ax.axhline(guide, color="C3", lw=0.7, ls="--", label="guide of the slider")
    ax.set_aspect("equal")
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.grid(True, lw=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or "mechanism in its positions")
    return figure


def diagrams(x, panels, *, xlabel="crank angle φ1, rad", title=""):
    """Curves against ``x``, one panel per entry of ``panels``: (ylabel with its unit,
    {curve label: values})."""
    x = np.asarray(x, dtype=float)
    figure, axes = _figure(rows=len(panels), size=(7.5, 2.5 * len(panels) + 0.6))
    for ax, (ylabel, curves) in zip(axes, panels):
        for i, (label, values) in enumerate(curves.items()):
            ax.plot(x, np.asarray(values, dtype=float), ".-", color=f"C{i}", lw=1.2,
                    ms=3, label=label)
        values = np.concatenate([np.asarray(v, dtype=float).ravel() for v in curves.values()])
        if np.nanmin(values) < 0.0 < np.nanmax(values):
            ax.axhline(0.0, color="k", lw=0.5)
        ax.set_ylabel(ylabel)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8, loc="best")
    axes[-1].set_xlabel(xlabel)
    if title:
        figure.suptitle(title)
    return figure


def _rotate(x, y, angle):
    c, s = math.cos(angle), math.sin(angle)
    return c * x - s * y, s * x + c * y


def cam_profile(XA, YA, FI, *, position=None, follower="knife", offset=0.0,
                base_radius=None, title=""):
    """The cam profile (points XA, YA in the cam's frame, m, at the cam angles FI, rad)
    turned to the cam angle ``FI[position]``, with its base circle, the cam centre, and
    the follower touching it there.

    ``follower``: ``"knife"`` (a translating knife-edge on the line x = ``offset``, as
    DPRFLP), ``"flat"`` (a flat face perpendicular to the y axis, as DPRFPL).
    ``position``: the index of the position drawn (default: the highest lift).
    ``base_radius``: the radius of the base circle (default: the smallest radius of the
    profile).
    """
    XA, YA, FI = (np.asarray(a, dtype=float) for a in (XA, YA, FI))
    radius = np.hypot(XA, YA)
    k = int(np.argmax(radius)) if position is None else int(position)
    x, y = _rotate(XA, YA, FI[k])                      # the fixed frame: the cam turned
    r0 = float(np.min(radius)) if base_radius is None else float(base_radius)
    size = float(np.max(radius))
    figure, (ax,) = _figure()
    ax.plot(x, y, "-", color="C0", lw=1.6, label="cam profile")
    ax.plot(x, y, ".", color="C0", ms=3)
    step = abs(FI[-1] - FI[-2]) if FI.size > 1 else 0.0
    gap = 2 * math.pi - abs(FI[-1] - FI[0])
    if gap > 1.5 * step:
        # the table stops before the turn is complete (V.5: 250 of 360 degrees): the rest
        # is a dwell at the last radius, an arc back to the first point
        a0, a1 = math.atan2(y[-1], x[-1]), math.atan2(y[0], x[0])
        turn = -1.0 if FI[-1] > FI[0] else 1.0          # the points turn against the cam
        sweep = (a1 - a0) % (2 * math.pi) if turn > 0 else -((a0 - a1) % (2 * math.pi))
        arc = a0 + np.linspace(0.0, sweep, 100)
        r = np.linspace(radius[-1], radius[0], 100)
        ax.plot(r * np.cos(arc), r * np.sin(arc), ":", color="C0", lw=1.6,
                label="dwell outside the table")
    t = np.linspace(0.0, 2 * math.pi, 361)
    ax.plot(r0 * np.cos(t), r0 * np.sin(t), "--", color="0.5", lw=0.9,
            label=f"base circle, r = {r0:.5f} m")
    ax.plot([0.0], [0.0], "+", color="k", ms=10)
    tip_x, tip_y = float(x[k]), float(y[k])
    if follower == "knife":
        ax.plot([offset, offset], [tip_y, tip_y + 0.6 * size], "-", color="C3", lw=3,
                solid_capstyle="butt", label="follower (knife edge)")
        ax.plot([tip_x], [tip_y], "v", color="C3", ms=8)
        ax.axvline(offset, color="C3", lw=0.6, ls=":")
    elif follower == "flat":
        half = 0.45 * size
        ax.plot([tip_x - half, tip_x + half], [tip_y, tip_y], "-", color="C3", lw=3,
                solid_capstyle="butt", label="follower (flat face)")
        ax.plot([0.0, 0.0], [tip_y, tip_y + 0.5 * size], "-", color="C3", lw=2)
        ax.plot([tip_x], [tip_y], "o", color="C3", ms=4)
    else:
        raise ValueError(f"follower must be 'knife' or 'flat', not {follower!r}")
    ax.set_aspect("equal")
    ax.locator_params(axis="x", nbins=6)
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.set_title(title or f"cam turned by {FI[k]:.4f} rad")
    ax.grid(True, lw=0.3)
    ax.legend(loc="lower left", fontsize=8)
    return figure


def _clip(values, spread=3.0):
    """y limits that keep the bulk of ``values`` visible (a radius of curvature runs off
    to infinity where the curvature changes sign): the data's range, cut at ``spread``
    times the 10-90 percentile range beyond those percentiles."""
    v = np.asarray(values, dtype=float)
    lo, hi = np.percentile(v, [10, 90])
    pad = spread * max(hi - lo, 1e-12)
    low, high = max(v.min(), lo - pad), min(v.max(), hi + pad)
    margin = 0.08 * max(high - low, 1e-12)
    return low - margin, high + margin


def cam_diagrams(FI, ROK, ALFA=None, *, ALD=None, title=""):
    """The pressure angle ALFA (rad; omitted for a flat-faced follower, where it is 0)
    and the radius of curvature ROK (m) against the cam angle FI (rad).  ``ALD``, the
    allowed pressure angle, is drawn as two limits."""
    FI, ROK = np.asarray(FI, dtype=float), np.asarray(ROK, dtype=float)
    rows = 1 if ALFA is None else 2
    figure, axes = _figure(rows=rows, size=(7.0, 2.8 * rows + 0.6))
    if ALFA is not None:
        ax = axes[0]
        ax.plot(FI, ALFA, ".-", color="C0", lw=1.2, ms=4, label="pressure angle")
        if ALD is not None:
            for limit in (ALD, -ALD):
                ax.axhline(limit, color="C3", ls="--", lw=0.9)
            ax.plot([], [], "--", color="C3", label=f"allowed, ±{ALD:.3f} rad")
        ax.set_ylabel("pressure angle α, rad")
        ax.legend(fontsize=8)
        ax.grid(True, lw=0.3)
    ax = axes[-1]
    ax.plot(FI, ROK, ".-", color="C2", lw=1.2, ms=4, label="radius of curvature")
    ax.axhline(0.0, color="k", lw=0.6)
    low, high = _clip(ROK)
    off = (ROK < low) | (ROK > high)
    if off.any():
        ax.plot(FI[off], np.clip(ROK[off], low, high), "^", color="C3", ms=6,
                label="off scale: " + ", ".join(f"{r:.4g}" for r in ROK[off]) + " m")
    ax.set_ylim(low, high)
    ax.set_ylabel("radius of curvature ρ, m")
    ax.set_xlabel("cam angle φ1, rad")
    ax.legend(fontsize=8)
    ax.grid(True, lw=0.3)
    if title:
        figure.suptitle(title)
    return figure


def reaction_hodograph(F, G, *, label=None, mark_every=None, title=""):
    """The hodograph of a joint reaction over a crank turn.

    ``F, G``: the modulus (N, >= 0) and direction (rad) of the reaction at each crank
    position, in order (e.g. ``F21``, ``G21`` of :func:`sarkp.book.prog_vii_10.compute`).
    The curve is (F cos G, F sin G), with the first position marked (and every
    ``mark_every``-th one, if given) and the origin as a cross; equal scales on both axes.
    """
    F = np.asarray(F, dtype=float)
    G = np.asarray(G, dtype=float)
    if F.shape != G.shape or F.ndim != 1:
        raise ValueError(f"F and G must be 1-D arrays of the same length, not {F.shape} "
                         f"and {G.shape}")
    figure, (ax,) = _figure()
    x, y = F * np.cos(G), F * np.sin(G)
    ax.plot(x, y, "-", color="C0", lw=1.4, label=label)
    ax.plot(x[:1], y[:1], "o", color="C0")
    if mark_every:
        ax.plot(x[::mark_every], y[::mark_every], ".", color="C0")
    ax.plot([0.0], [0.0], "k+")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x component, N")
    ax.set_ylabel("y component, N")
    if label:
        ax.legend()
    if title:
        ax.set_title(title)
    return figure


def speed_diagram(phi, WPR, WPRM=None, *, W1=None, title=""):
    """omega(phi) of the reduction link: DZKNDV's WPR without the flywheel and, if given,
    WPRM with it (DZKNDV rerun with ISC + IMHVK); ``W1``, the mean speed, as a dashed line.
    ``phi`` in rad (e.g. ``np.linspace(0, 2*pi, M)``), speeds in rad/s.
    """
    phi = np.asarray(phi, dtype=float)
    figure, (ax,) = _figure(size=(7.0, 4.0))
    ax.plot(phi, np.asarray(WPR, dtype=float), "-", color="C0", label="without flywheel")
    if WPRM is not None:
        ax.plot(phi, np.asarray(WPRM, dtype=float), "-", color="C1", label="with flywheel")
    if W1 is not None:
        ax.axhline(W1, color="0.5", linestyle="--", linewidth=0.8, label="mean speed W1")
    ax.set_xlabel("phi, rad")
    ax.set_ylabel("omega, rad/s")
    ax.legend()
    if title:
        ax.set_title(title)
    return figure


def _involute_flank(rb, r_from, r_to, n=40):
    """Polar (r, theta) of an involute of the base circle rb from radius r_from to r_to,
    theta = inv(alpha_r) = tan(alpha_r) - alpha_r with cos(alpha_r) = rb/r."""
    r = np.linspace(max(r_from, rb), r_to, n)
    alpha = np.arccos(np.clip(rb / r, -1.0, 1.0))
    return r, np.tan(alpha) - alpha


def gear_mesh(M, Z1, Z2, X1=0.0, X2=0.0, *, teeth=3):
    """Draw an external spur mesh near its pitch point: both wheels' involute teeth, their
    tip, operating pitch and base circles, the line of action N1N2 and its active length.

    The geometry is sarkp's: DGMZPC (operating angle, centre distance, tip shortening) and
    DGMTZK (reference thickness), in the current mode.  Wheel 1 is below, wheel 2 above,
    the pitch point P at the origin, the centre line vertical.

    Parameters
    ----------
    M : float
        Module (mm).
    Z1, Z2 : int
        Tooth numbers.
    X1, X2 : float
        Shift coefficients.
    teeth : int
        Teeth drawn on each side of the centre line.

    Returns
    -------
    matplotlib.figure.Figure
        The drawing; its attribute ``mesh`` is a dict: ``N1``, ``N2`` the ends of the line
        of action (tangent points on the base circles), ``A``, ``B`` the ends of its active
        part (where the tip circles of wheels 2 and 1 cut it), ``active`` the active length
        |AB|, equal to eps_alpha times the base pitch pi m cos(alpha).
    """
    from .gears import DGMTZK, DGMZPC

    mesh = DGMZPC(M, Z1, Z2, 0.0, X1, X2, 0.0)
    aw, alfaw, dy = mesh.AW, mesh.ALFAW, mesh.XUR
    figure, (ax,) = _figure(size=(7.0, 7.0))
    u = Z2 / Z1
    rw1, rw2 = aw / (1.0 + u), aw * u / (1.0 + u)         # operating pitch radii
    centres = (np.array([0.0, -rw1]), np.array([0.0, rw2]))
    wheels = []
    for k, (z, x, c) in enumerate(((Z1, X1, centres[0]), (Z2, X2, centres[1]))):
        g = DGMTZK(M, z, 0.0, x)
        rb, r = g.DB / 2, g.D / 2
        ra = r + (1.0 + x - dy) * M                        # tip shortened by dy
        rf = g.DF / 2
        alpha0 = math.acos(rb / r)
        half = g.S / (2 * r) + (math.tan(alpha0) - alpha0)  # half tooth angle on the base
        wheels.append((c, rb, ra, rf, half, z))
    for k, (c, rb, ra, rf, half, z) in enumerate(wheels):
        towards_p = math.pi / 2 if k == 0 else -math.pi / 2
        # wheel 1 has a tooth on the centre line, wheel 2 a space there
        offset = 0.0 if k == 0 else math.pi / z
        rr, th = _involute_flank(rb, max(rb, rf), ra)
        root = [min(rf, rb)]                  # a radial line below the base circle
        for j in range(-teeth, teeth + 1):
            axis = towards_p + offset + 2 * math.pi * j / z
            for side in (-1, 1):
                ang = axis + side * (half - th)
                xs = np.concatenate([np.multiply(root, math.cos(axis + side * half)),
                                     rr * np.cos(ang)])
                ys = np.concatenate([np.multiply(root, math.sin(axis + side * half)),
                                     rr * np.sin(ang)])
                ax.plot(c[0] + xs, c[1] + ys, color=("tab:blue", "tab:red")[k], lw=1.2)
            tip = np.linspace(axis - (half - th[-1]), axis + (half - th[-1]), 8)
            ax.plot(c[0] + ra * np.cos(tip), c[1] + ra * np.sin(tip),
                    color=("tab:blue", "tab:red")[k], lw=1.2)
        span = np.linspace(towards_p - (teeth + 1) * 2 * math.pi / z,
                           towards_p + (teeth + 1) * 2 * math.pi / z, 200)
        for radius, style in ((ra, ":"), (rb, "--"), ((rw1, rw2)[k], "-.")):
            ax.plot(c[0] + radius * np.cos(span), c[1] + radius * np.sin(span), style,
                    color="0.5", lw=0.7)
    # the line of action through P, at alpha_w to the common tangent (the x axis)
    direction = np.array([math.cos(alfaw), math.sin(alfaw)])
    n1 = centres[0] + wheels[0][1] * np.array([-math.sin(alfaw), math.cos(alfaw)])
    n2 = centres[1] + wheels[1][1] * np.array([math.sin(alfaw), -math.cos(alfaw)])

    def cut(centre, radius):
        """The point of the line P + t*direction on the circle (centre, radius)."""
        b = direction @ (-centre)
        cc = centre @ centre - radius ** 2
        roots = (-b + np.array([-1.0, 1.0]) * math.sqrt(b * b - cc))
        t = roots[np.argmin(np.abs(roots))]
        return t * direction

    a_point = cut(centres[1], wheels[1][2])               # wheel 2's tip: contact begins
    b_point = cut(centres[0], wheels[0][2])               # wheel 1's tip: contact ends
    ax.plot(*zip(n1, n2), color="k", lw=0.8)
    ax.plot(*zip(a_point, b_point), color="k", lw=3)
    for name, p in (("N1", n1), ("N2", n2), ("A", a_point), ("B", b_point),
                    ("P", np.zeros(2))):
        ax.annotate(name, p, textcoords="offset points", xytext=(4, 4))
    ax.set_aspect("equal")
    width = (teeth + 1.5) * math.pi * M
    ax.set_xlim(-width, width)
    ax.set_ylim(-width, width)
    ax.set_title(f"z1 = {Z1:g}, z2 = {Z2:g}, m = {M:g}, x1 = {X1:g}, x2 = {X2:g}: "
                 f"alpha_w = {math.degrees(alfaw):.2f} deg, eps_alpha = {mesh.E:.3f}")
    figure.mesh = {"N1": n1, "N2": n2, "A": a_point, "B": b_point,
                   "active": float(np.linalg.norm(b_point - a_point))}
    return figure
