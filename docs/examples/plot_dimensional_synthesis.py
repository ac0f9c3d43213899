"""
Dimensional synthesis: a four-bar for a function, a four-bar for a path
=======================================================================

``sarkp.function_generation`` finds the four-bar whose rocker angle follows a function
of the crank angle: here y = log10 x on [1, 2], the crank turning from 15 to 105
degrees for x, the rocker from 300 to 240 degrees for y.  Three Chebyshev precision
points give it exactly through Freudenstein's equation (a linear system); between them
the structural error remains, which a minimax fit over many points spreads evenly.

``sarkp.path_generation`` finds a four-bar whose coupler point passes through target
points: a global search over populations of designs (each population one batched solve
of ``sarkp.Mechanism``), polished by least squares.  The targets here lie on the coupler
curve of a known four-bar, so a design through them exists.  (More in the page
"Dimensional synthesis".)
"""

import numpy as np
from matplotlib.figure import Figure

import sarkp
from sarkp import plot

x0, x1 = 1.0, 2.0
phi0, dphi = np.radians(15.0), np.radians(90.0)
psi0, dpsi = np.radians(300.0), np.radians(-60.0)


def crank(x):
    return phi0 + dphi * (x - x0) / (x1 - x0)


def rocker(y):
    return psi0 + dpsi * (y - np.log10(x0)) / (np.log10(x1) - np.log10(x0))


# three Chebyshev points on [1, 2]
xs = (x0 + x1) / 2 - (x1 - x0) / 2 * np.cos(np.pi * (2 * np.arange(3) + 1) / 6)
three = sarkp.function_generation(crank(xs), rocker(np.log10(xs)), ground=1.0)
xf = np.linspace(x0, x1, 41)
fitted = sarkp.function_generation(crank(xf), rocker(np.log10(xf)), ground=1.0,
                                   method="minimax")
for name, fg in (("three points", three), ("minimax, 41 points", fitted)):
    print(f"{name}: {fg.grashof}, lengths "
          + ", ".join(f"{k} = {v:.4f}" for k, v in fg.lengths.items())
          + f"; error at its points {fg.error:.4f} rad")

# %%
# The structural error over the whole range: solve each design at every crank angle
# and compare the rocker's angle with the function's.
x = np.linspace(x0, x1, 201)
errors = {}
for name, fg in (("three Chebyshev points", three), ("minimax over 41 points", fitted)):
    r = fg.mechanism.solve(crank(x), need="positions")        # no dial offsets here
    err = np.angle(np.exp(1j * (r.angle("C", "B") - rocker(np.log10(x)))))   # wrapped
    errors[name] = np.degrees(err)
    print(f"{name}: worst structural error {np.abs(err).max():.4f} rad")
structural = plot.diagrams(x, [("rocker angle error, degrees", errors)],
                           xlabel="x (the crank angle 15° + 90° (x − 1))",
                           title="Function generation: y = log10 x")

# %%
# Path generation: six targets on the coupler curve of a four-bar (O = (0, 0),
# C = (1, 0), crank 0.3, coupler 1.0, rocker 0.8, the coupler point 0.5 along A-B and
# 0.3 to its left), searched for without knowing it, the timing free.  Six points on a
# curve do not fix the linkage: the search returns another four-bar through them.
known = sarkp.Mechanism()
known.fixed("O", 0.0, 0.0)
known.fixed("C", 1.0, 0.0)
known.crank("A", "O", 0.3)
known.rrr("B", "A", "C", 1.0, 0.8)
known.point("P", "A", "B", 0.5, 0.3)
targets = known.solve(np.linspace(0.0, 2 * np.pi, 6, endpoint=False),
                      need="positions").position("P")
pg = sarkp.path_generation(targets, seed=2, popsize=15, maxiter=100)
print(f"path generation: {pg.grashof}, "
      + ", ".join(f"{k} = {v:.4f}" for k, v in pg.lengths.items())
      + f"; largest distance from a target {pg.error:.1e} m; transmission angle "
        f"{pg.transmission[0]:.0f} to {pg.transmission[1]:.0f} degrees")
turn = pg.mechanism.solve(np.linspace(0.0, 2 * np.pi, 181), need="positions")
coupler = Figure(figsize=(7.5, 6.8), layout="constrained")
ax = coupler.subplots()
ax.plot(targets[:, 0], targets[:, 1], "x", color="C3", ms=9, mew=2, label="targets")
turn.plot(paths=("P",), ax=ax, title="Path generation: a coupler curve through six targets")
