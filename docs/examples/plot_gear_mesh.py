"""
An external spur mesh (DGMZPC, listing VI.6)
============================================

Example (a) of Fig. 47: z1 = 11, z2 = 26, m = 5 mm, both wheels shifted by 0.5.  The
line of action N1N2, its active part AB between the two tip circles, and the contact
ratio AB / p_b, which equals DGMZPC's ``E``.
"""

import sarkp
from sarkp import plot

mesh = plot.gear_mesh(5.0, 11, 26, 0.5, 0.5)
print(f"active length AB = {mesh.mesh['active']:.3f} mm, "
      f"DGMZPC's contact ratio E = {sarkp.DGMZPC(5.0, 11, 26, 0.0, 0.5, 0.5, 0.0).E:.4f}")
