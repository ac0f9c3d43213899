"""
Gear meshes (DGMZPC, DGMZVN; listings VI.6, VI.7)
=================================================

Example (a) of Fig. 47: z1 = 11, z2 = 26, m = 5 mm, both wheels shifted by 0.5.  The
line of action N1N2, its active part AB between the two tip circles, and the contact
ratio AB / p_b, which equals DGMZPC's ``E``.
"""

import sarkp
from sarkp import plot

mesh = plot.gear_mesh(5.0, 11, 26, 0.5, 0.5)
print(f"active length AB = {mesh.mesh['active']:.3f} mm, "
      f"DGMZPC's contact ratio E = {sarkp.DGMZPC(5.0, 11, 26, 0.0, 0.5, 0.5, 0.0).E:.4f}")

# %%
# An internal mesh (DGMZVN, listing VI.7): Fig. 48's example (b), a pinion z1 = 25 in a
# ring z2 = 31 cut by a shaper z0 = 25.  With so few teeth between them the operating
# angle is almost 40 degrees and the whole contact AB lies on one side of P.
ring = plot.internal_mesh(3.0, 25, 31, 0.17, 1.2, 25, 75.0, 0.17, 83.8)
print(f"active length AB = {ring.mesh['active']:.3f} mm, DGMZVN's contact ratio "
      f"EALFA = {sarkp.DGMZVN(3.0, 25, 31, 0.17, 1.2, 25, 75.0, 0.17, 83.8).EALFA:.4f}")
