"""
Hodographs of joint reactions (program VII.10)
==============================================

The force analysis of the mechanism of Fig. 57 over the book's 25 crank positions: the
reaction of link 2 on the crank, F21, as the tip of its vector, numbered by position
and with arrows in the order of the positions.  Here two reactions are drawn side by
side on Axes of our own: every sarkp.plot function takes ``ax=``.
"""

from matplotlib.figure import Figure

from sarkp import plot
from sarkp.book import prog_vii_10

t = prog_vii_10.compute()
pair = Figure(figsize=(11, 6.5), layout="constrained")
left, right = pair.subplots(1, 2)
plot.reaction_hodograph(t["F21"], t["G21"], label="F21: link 2 on the crank", ax=left,
                        title="reaction at A (F21)")
plot.reaction_hodograph(t["F81"], t["G81"], label="F81: link 8 on the crank", ax=right,
                        title="reaction at the second crank pin (F81)")
