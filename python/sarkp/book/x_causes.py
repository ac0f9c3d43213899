"""The demonstrated causes of program X's differing cells (docs/ERRATA.md, section
"Program X"): each one computes what its cause gives for the cell, from the printed
figure and the listings, so the diff can show it (:class:`sarkp.book.figures.Cause`).

* E-FIG87-1, Fig. 87 SA of the gear z = 20: the row's printed S and SB pin the shift
  coefficient X (S = PI M/2 + 2 X M TAN(ALFA), SB = DB (PI/(2Z) + 2 X TAN(ALFA)/Z +
  inv ALFA), L4253-4256), and SA of that X, by the formula of Fig. 46 (E-DGMTZK-1),
  lies in an interval that excludes the printed 1.7100: a misprint.
"""

from __future__ import annotations

import math

from .figures import Cause, load_figure

PI = 3.14159                                   # the book's PI (DGMTZK's own, L4248)


def _inv(a):
    return math.tan(a) - a


def fig87_sa1_interval() -> tuple:
    """E-FIG87-1: the X that the printed S and SB of Fig. 87's first DGMTZK row allow
    (each to half a unit), and SA at both ends of it: ``(x_lo, x_hi, sa_lo, sa_hi)``."""
    p = {(c.row, c.column): c for c in load_figure("87").cells}
    m, z = p[("DGMTZK1", "M")].value, p[("DGMTZK1", "Z")].value
    alfa = PI / 9.0
    s, sb = p[("DGMTZK1", "S")], p[("DGMTZK1", "SB")]
    db = m * z * math.cos(alfa)

    def x_of_s(v):
        return (v - PI * m / 2.0) / (2.0 * m * math.tan(alfa))

    def x_of_sb(v):
        return (v / db - PI / (2.0 * z) - _inv(alfa)) * z / (2.0 * math.tan(alfa))
    lo = max(x_of_s(s.value - 0.5 * s.unit), x_of_sb(sb.value - 0.5 * sb.unit))
    hi = min(x_of_s(s.value + 0.5 * s.unit), x_of_sb(sb.value + 0.5 * sb.unit))
    if lo > hi:
        raise ValueError("Fig. 87: the printed S and SB allow no common X")

    def sa(x):
        da = m * (z + 2.0 + 2.0 * x)
        alfaa = math.acos(db / da)
        return da * (PI / (2.0 * z) + 2.0 * x * math.tan(alfa) / z + _inv(alfa)
                     - _inv(alfaa))
    ends = sorted((sa(lo), sa(hi)))
    return lo, hi, ends[0], ends[1]


def causes(number: str) -> dict:
    """``{(row, column): Cause}`` for program X's figure ``number``."""
    out = {}
    if str(number) == "87":
        x_lo, x_hi, lo, hi = fig87_sa1_interval()
        out[("DGMTZK1", "SA")] = Cause(
            "E-FIG87-1", f"the printed S and SB pin X to [{x_lo:.6f}, {x_hi:.6f}], so SA "
                         f"is in [{lo:.5f}, {hi:.5f}]: the printed 1.7100 is a misprint",
            misprint=(lo, hi))
    return out
