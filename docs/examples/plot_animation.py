"""
A six-bar in motion
===================

The six-bar of the tutorial (a crank, a four-bar whose rocker is a lever B-C-D, a rod
D-E driving a slider E along a horizontal guide), solved over a turn of the crank by
:meth:`sarkp.Mechanism.solve` and written as an animated GIF by
:meth:`sarkp.MechanismResult.animate` (matplotlib's Pillow writer; an ``.mp4`` path uses
ffmpeg).  First the mechanism in its positions, the picture :meth:`plot` draws.
"""

import math
import tempfile
from pathlib import Path

import numpy as np

import sarkp

m = sarkp.Mechanism()
m.fixed("O", 0.0, 0.0)                      # the crank's pivot, m
m.fixed("C", -0.25, 0.35)                   # the lever's pivot
m.fixed("K", 0.0, 0.5)                      # a point of the slider's guide
m.crank("A", "O", 0.1)
m.rrr("B", "A", "C", 0.5, 0.3)              # coupler A-B, rocker C-B
m.point("D", "C", "B", 0.3, math.pi)        # lever B-C-D
m.rrp("E", "D", "K", 0.0, 0.4)              # rod D-E, slider E
r = m.solve(np.radians(np.arange(360.0)), need="positions")   # one degree apart
positions = r.plot(every=30, paths=("B", "E"), title="The six-bar every 30 degrees")

# %%
# The animation: one frame every 15 degrees of the crank (24 frames, 8 per second,
# so one turn of the crank takes 3 seconds and the GIF loops without a repeated frame;
# the path is drawn from all 360 positions).  ``animate`` returns the path it wrote.
folder = Path(tempfile.mkdtemp(prefix="sarkp-gallery-"))
animation = r.animate(folder / "sixbar.gif", fps=8, every=15, paths=("E",))
