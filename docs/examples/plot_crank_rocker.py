"""
A crank-rocker over a full turn
===============================

The README's worked example: the RRR group ABC of a crank-rocker solved over a turn
of the crank in one call of ``DKNMA1``, drawn in its positions and as diagrams of the
rocker's angular velocity and acceleration against the crank angle.
"""

import numpy as np

import sarkp
from sarkp import plot

roa, rab, rcb, xc, yc, w1 = 0.1, 0.35, 0.3, 0.4, 0.0, 10.0
fi = np.linspace(0.0, 2 * np.pi, 361)               # one degree apart
xa, ya = roa * np.cos(fi), roa * np.sin(fi)
k = sarkp.DKNMA1(xa, ya, xc, yc, rab, rcb, w1 * roa, fi + np.pi / 2, 0.0, 0.0,
                 w1**2 * roa, fi + np.pi, 0.0, 0.0, 1)

# %%
# The mechanism every 30 degrees, the path of the coupler's midpoint M.
xm, ym = (xa + k.XB) / 2, (ya + k.YB) / 2
sheet = plot.mechanism({"O": (0.0, 0.0), "A": (xa, ya), "B": (k.XB, k.YB), "C": (xc, yc),
                        "M": (xm, ym)},
                       [("O", "A"), ("A", "M", "B"), ("B", "C")], fixed=("O", "C"),
                       every=30, paths=("A", "M"), positions=np.arange(1, 362),
                       title="Crank-rocker OA = 0.1 m, AB = 0.35 m, CB = 0.3 m")

# %%
# The rocker's angular velocity and acceleration (counter-clockwise positive).
curves = plot.diagrams(fi, [("angular velocity, rad/s", {"ω3 (rocker CB)": k.W3,
                                                          "ω2 (coupler AB)": k.W2}),
                            ("angular acceleration, rad/s²", {"ε3 (rocker CB)": k.E3,
                                                              "ε2 (coupler AB)": k.E2})],
                       degrees=True, title=f"Crank-rocker at ω1 = {w1:g} rad/s")
