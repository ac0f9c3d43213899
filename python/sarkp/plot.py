"""Drawings of sarkp's results (matplotlib, an optional extra: it is imported only inside
the functions that draw)."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["gear_mesh"]


def _involute_flank(rb, r_from, r_to, n=40):
    """Polar (r, theta) of an involute of the base circle rb from radius r_from to r_to,
    theta = inv(alpha_r) = tan(alpha_r) - alpha_r with cos(alpha_r) = rb/r."""
    r = np.linspace(max(r_from, rb), r_to, n)
    alpha = np.arccos(np.clip(rb / r, -1.0, 1.0))
    return r, np.tan(alpha) - alpha


def gear_mesh(M, Z1, Z2, X1=0.0, X2=0.0, *, teeth=3, ax=None):
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
    ax : matplotlib Axes, optional
        Where to draw (a new figure if None).

    Returns
    -------
    dict
        ``ax``; ``N1``, ``N2`` the ends of the line of action (tangent points on the base
        circles); ``A``, ``B`` the ends of its active part (where the tip circles of wheels
        2 and 1 cut it); ``active`` the active length |AB|, equal to eps_alpha times the
        base pitch pi m cos(alpha).
    """
    import matplotlib.pyplot as plt

    from .gears import DGMTZK, DGMZPC

    mesh = DGMZPC(M, Z1, Z2, 0.0, X1, X2, 0.0)
    aw, alfaw, dy = mesh.AW, mesh.ALFAW, mesh.XUR
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 7))
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
    return {"ax": ax, "N1": n1, "N2": n2, "A": a_point, "B": b_point,
            "active": float(np.linalg.norm(b_point - a_point))}
