"""Diagrams of the book's results (matplotlib, an optional extra: imported only inside the
functions, so ``import sarkp.plot`` works without it).

* :func:`reaction_hodograph` -- the hodograph of a joint reaction over a crank turn: the
  tip of the force vector (F cos G, F sin G) drawn from the origin, as in the force
  analysis of chapter 7 (e.g. program VII.10's F21, G21);
* :func:`speed_diagram` -- omega(phi) of the reduction link from DZKNDV, with and without
  the flywheel of DMHVK (chapter 8, Fig. 96's WPR and WPRM).

Each function draws on ``ax`` (a new figure when None) and returns the Axes.
"""

from __future__ import annotations

import numpy as np

__all__ = ["reaction_hodograph", "speed_diagram"]


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt
        _, ax = plt.subplots()
    return ax


def reaction_hodograph(F, G, *, ax=None, label=None, mark_every=None):
    """Draw the hodograph of a joint reaction over a crank turn.

    Parameters
    ----------
    F, G : array_like
        Modulus (N, >= 0) and direction (rad) of the reaction at each crank position, in
        order (e.g. ``F21``, ``G21`` of :func:`sarkp.book.prog_vii_10.compute`).
    ax : matplotlib Axes, optional
        Where to draw; a new figure when None.
    label : str, optional
        Legend label of the curve.
    mark_every : int, optional
        Mark every n-th position with a dot (the first one is always marked).

    Returns
    -------
    matplotlib.axes.Axes
        The curve (F cos G, F sin G), closed when the first and last positions coincide,
        with equal scales on both axes.
    """
    F = np.asarray(F, dtype=float)
    G = np.asarray(G, dtype=float)
    if F.shape != G.shape or F.ndim != 1:
        raise ValueError(f"F and G must be 1-D arrays of the same length, not {F.shape} "
                         f"and {G.shape}")
    ax = _axes(ax)
    x, y = F * np.cos(G), F * np.sin(G)
    (line,) = ax.plot(x, y, label=label)
    ax.plot(x[:1], y[:1], "o", color=line.get_color())
    if mark_every:
        ax.plot(x[::mark_every], y[::mark_every], ".", color=line.get_color())
    ax.plot([0.0], [0.0], "k+")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x component, N")
    ax.set_ylabel("y component, N")
    if label:
        ax.legend()
    return ax


def speed_diagram(phi, WPR, WPRM=None, *, W1=None, ax=None):
    """Draw omega(phi) of the reduction link, without and (optionally) with the flywheel.

    Parameters
    ----------
    phi : array_like
        Angle of the reduction link at each point (rad), e.g. ``np.linspace(0, 2*pi, M)``.
    WPR : array_like
        omega(phi) without the flywheel (DZKNDV's WPR), rad/s.
    WPRM : array_like, optional
        omega(phi) with the flywheel (DZKNDV rerun with ISC + IMHVK), rad/s.
    W1 : float, optional
        The mean speed, drawn as a dashed line.
    ax : matplotlib Axes, optional
        Where to draw; a new figure when None.

    Returns
    -------
    matplotlib.axes.Axes
    """
    phi = np.asarray(phi, dtype=float)
    ax = _axes(ax)
    ax.plot(phi, np.asarray(WPR, dtype=float), label="without flywheel")
    if WPRM is not None:
        ax.plot(phi, np.asarray(WPRM, dtype=float), label="with flywheel")
    if W1 is not None:
        ax.axhline(W1, color="0.5", linestyle="--", linewidth=0.8, label="mean speed W1")
    ax.set_xlabel("phi, rad")
    ax.set_ylabel("omega, rad/s")
    ax.legend()
    return ax
