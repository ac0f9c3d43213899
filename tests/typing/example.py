"""A small user script that mypy checks against the installed sarkp (tests/test_layer.py):
the wrappers are typed source, so a type checker follows every call."""

import numpy as np

import sarkp
from sarkp import DKNMA1, DPRM1, DUGL1, DVKT, GELG

r = DPRM1(0.1, 0.0, 0.4, 0.0, 0.35, 0.3, -1)
fi2: float = float(r.FI2)
xb, yb = r.XB, r.YB
frame_maker = r.to_frame

phi = np.linspace(0.0, 2 * np.pi, 37)
k = DKNMA1(0.1 * np.cos(phi), 0.1 * np.sin(phi), 0.4, 0.0, 0.35, 0.3, 0.1, phi + np.pi / 2,
           0.0, 0.0, 0.1, phi + np.pi, 0.0, 0.0, 1, on_error="nan")
w2 = np.asarray(k.W2) * 2.0
status = k[-1]

angle = DUGL1(0.0, 0.0, 1.0, 1.0) + 1.0
solution = GELG([1.0, 2.0], [[2.0, 0.0], [0.0, 4.0]], 2, 1, 1e-4).R
buf = np.empty((2, 3))
d = DVKT(0.0, 0.0, [1.0, 2.0, 3.0], 4.0, out=buf)
print(fi2, xb, yb, w2, status, angle, solution, d.RZ, sarkp.Status.OK)
