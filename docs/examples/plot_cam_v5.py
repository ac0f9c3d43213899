"""
A cam for a knife-edge follower (program V.5)
=============================================

The book's program V.5 (Fig. 35) in corrected mode: the profile with its base circle
and the follower at the highest lift, then the pressure angle against its allowed
limit and the radius of curvature, the non-convex part shaded.
"""

import math

from sarkp import plot
from sarkp.book import prog_v_5

t = prog_v_5.compute()
profile = plot.cam_profile(t["XPRFL"], t["YPRFL"], t["FI"], follower="knife",
                           offset=t["EXCTST"], base_radius=math.hypot(t["RKSH"], t["EXCTST"]),
                           title="V.5: cam with a knife-edge follower")

# %%
# The positions beyond the allowed pressure angle are marked; the top axis numbers
# the rows as Fig. 35 does.
import numpy as np

limits = plot.cam_diagrams(t["FI"], t["RKRZVN"], t["ALFA"], ALD=prog_v_5.ALFAD,
                           positions=np.arange(1, len(t["FI"]) + 1),
                           title="V.5: pressure angle and radius of curvature")
