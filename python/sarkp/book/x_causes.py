"""The demonstrated causes of program X's differing cells (docs/ERRATA.md, section
"Program X"): each one computes what its cause gives for the cell, from the printed
figure and the listings, so the diff can show it (:class:`sarkp.book.figures.Cause`).

* E-FIG87-1, Fig. 87 SA of the gear z = 20: the row's printed S and SB pin the shift
  coefficient X (S = PI M/2 + 2 X M TAN(ALFA), SB = DB (PI/(2Z) + 2 X TAN(ALFA)/Z +
  inv ALFA), L4253-4256), and SA of that X, by the formula of Fig. 46 (E-DGMTZK-1),
  lies in an interval that excludes the printed 1.7100: a misprint.
* E-X-LINKS-1, Figs. 91, 94, 96: the fitted link lengths are known to their standard
  uncertainty only; a differing cell that lengths within it put within half a unit
  (:func:`length_causes`, rerunning program X's chain with them).
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


# ---- the fitted lengths' uncertainty (E-X-LINKS-1) --------------------------------------------

#: the largest change of the lengths a cause may take, in standard uncertainties (the
#: Mahalanobis distance from the fitted lengths under their covariance)
WITHIN_SIGMA = 1.0
#: where the moved cell is aimed: a tenth of a half unit inside the edge, so that the rerun's
#: own rounding and the chain's curvature cannot leave it on the edge
AIM = 0.45
_NAMES = ("ROA", "RAB", "ROC", "RCD", "RDE")
_STAGE = {"91": "kinematics", "94": "forces", "96": "dynamics"}


def _chain(lengths) -> dict:
    """Figs. 91, 94, 96 as cells, program X's chain run as printed with ``lengths``."""
    from .. import as_printed
    from . import prog_x
    with as_printed():
        s = prog_x.synthesis()
        s.update(zip(_NAMES, lengths))
        s["RCB"] = s["RCD"]
        k = prog_x.kinematics(s)
        f = prog_x.forces(s, k)
        d = prog_x.dynamics(s, k, f)
    return {"91": prog_x.stage_cells("kinematics", k), "94": prog_x.stage_cells("forces", f),
            "96": prog_x.stage_cells("dynamics", d)}


def _gradients(step=1e-7):
    """The chain's cells at the fitted lengths and their derivatives by each length."""
    import numpy as np
    from . import prog_x
    base = np.array([prog_x.FITTED_LINKS[n] for n in _NAMES])
    runs = []
    for i in range(len(_NAMES)):
        d = np.zeros(len(_NAMES))
        d[i] = step
        runs.append((_chain(base + d), _chain(base - d)))
    grad = {}
    for number in _STAGE:
        for key in runs[0][0][number]:
            grad[(number, key)] = np.array([(p[number][key] - m[number][key]) / (2 * step)
                                            for p, m in runs])
    return base, grad


def length_causes(comparisons_by_figure: dict) -> dict:
    """``{figure: {(row, column): Cause}}`` for the differing cells of Figs. 91, 94, 96 that
    the fitted lengths, moved within their uncertainty, put within half a unit.

    The lengths' covariance is the fit's (scripts/fit_x_links.py): the fitted cells'
    rounding, uniform over +-0.5 units (variance 1/12), propagated through their Jacobian
    J, C = (J^T J)^-1 / 12.  For a cell of sensitivity g (value per metre) the smallest
    change of the lengths (in C's metric) that moves it to :data:`AIM` units of its print
    is dL = C g t / (g^T C g), of Mahalanobis length |t| / sqrt(g^T C g); the cause is shown
    when that length is at most :data:`WITHIN_SIGMA` and the chain rerun with the moved
    lengths puts the cell within half a unit (``moved`` is that rerun's value)."""
    import numpy as np
    from . import prog_x
    base, grad = _gradients()
    fitted = prog_x.fitted_cells()
    jac = np.array([grad[("91", (c.row, c.column))] / c.unit for c in fitted])
    cov = np.linalg.inv(jac.T @ jac) / 12.0
    out = {}
    for number, comparisons in comparisons_by_figure.items():
        out[number] = {}
        for c in comparisons:
            if c.matches or c.units is None or not c.cell.reproducible:
                continue
            g = grad[(number, (c.cell.row, c.cell.column))] / c.cell.unit
            gcg = float(g @ cov @ g)
            if gcg <= 0.0:
                continue
            t = -(c.units - math.copysign(AIM, c.units))
            distance = abs(t) / math.sqrt(gcg)
            if distance > WITHIN_SIGMA:
                continue
            lengths = base + cov @ g * t / gcg
            moved = _chain(lengths)[number][(c.cell.row, c.cell.column)]
            if abs(moved - c.cell.value) <= 0.5 * c.cell.unit:
                out[number][(c.cell.row, c.cell.column)] = Cause(
                    "E-X-LINKS-1", f"the fitted lengths moved by {distance:.2f} of their "
                                   f"standard uncertainty (x_causes.length_causes) give "
                                   f"{moved:.{c.cell.decimals + 2}f}", moved=moved,
                    applied=dict(zip(_NAMES, map(float, lengths))))
    return out
