"""
A whole mechanism in one call (sarkp.Mechanism)
===============================================

Program X's six-bar described once as a :class:`sarkp.Mechanism`
(:mod:`sarkp.book.x_mechanism`) and solved over a turn of the crank in one compiled call:
the drawing of its positions (``result.plot``, :func:`sarkp.plot.mechanism`) and the
slider's velocity against the crank angle, with the rocker's angular velocity.
"""

import numpy as np

import sarkp
from sarkp import plot
from sarkp.book import prog_x, x_mechanism

with sarkp.mode("corrected"):
    links = prog_x.run(["synthesis"])["synthesis"]
six_bar = x_mechanism.mechanism(links)
phi = np.radians(np.arange(0.0, 361.0, 10.0))
result = six_bar.solve(phi, omega=prog_x.W1, need="accelerations")
drawing = result.plot(0, paths=("A", "E"), title="Program X's six-bar, corrected design")

# %%
# The velocities: the rocker's angular velocity and the slider E's velocity along the
# guide (x), against the crank angle; the top axis numbers the positions as the book's
# program does (one every 10 degrees).
vE = result.velocity("E")                       # (vx, vy) per position, m/s
w3 = result.omega("C", "B")                     # the lever C-B-D, rad/s
speeds = plot.diagrams(phi, [("angular velocity, rad/s", {"ω3 (lever CBD)": w3}),
                             ("velocity of the slider E, m/s", {"v_E along x": vE[:, 0]})],
                       degrees=True, positions=np.arange(1, phi.size + 1),
                       title="Program X's six-bar: velocities from one Mechanism solve")
print(result)
