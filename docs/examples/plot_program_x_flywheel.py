"""
The course project's flywheel (program X)
=========================================

Chapter 10's conveyor-feeder, corrected design: the work of the forces and the kinetic
energy of the links over a turn, and the crank's angular speed with the flywheel that
DMHVK sizes for the coefficient of fluctuation the task card asks (0.02).  Without the
flywheel the machine stalls (ERRATA E-DZKNDV-2): there is no curve to draw.
"""

import numpy as np

import sarkp
from sarkp import plot
from sarkp.book import prog_x

with sarkp.mode("corrected"):
    d = prog_x.run(["dynamics"])["dynamics"]
positions = np.arange(1, len(d["FI1"]) + 1)
energy = plot.diagrams(d["FI1"], [("work and energy, J",
                                   {"work of all forces ΣA": d["ASUM"],
                                    "kinetic energy of the links E_V": d["EV"],
                                    "surplus ΔE = ΣA − E_V": d["DEC"]})],
                       degrees=True, positions=positions,
                       title="Program X: work and energy over a turn")

# %%
speed = plot.diagrams(d["FI1"], [("angular speed ω1, rad/s",
                                  {f"with the flywheel J = {d['IMH']:.0f} kg·m²": d["WPRM"],
                                   "mean speed": np.full(len(d["FI1"]), prog_x.W1)})],
                      degrees=True, positions=positions,
                      title="Program X: the crank's angular speed with the flywheel")
print(f"realized fluctuation: {(d['WPRM'].max() - d['WPRM'].min()) / prog_x.W1:.4f}")
