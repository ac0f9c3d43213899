"""Program X's six-bar (chapter 10, Fig. 91) as a :class:`sarkp.Mechanism`.

The same mechanism that :mod:`sarkp.book.prog_x` builds group by group (operator
functions 27-48, L6813-7096; the loop DO 30, L7503-7566): the crank O-A (formula 28), the
four-bar group A-B-C with C fixed at formula 27's point (DPRM1 with P = -1: B on the left
of A->C, branch +1 here), the lever point D on link C-B at RCD from C opposite B
(L7510), and the group D-E with the slider E on the horizontal guide through (0, H5 + YC)
(DPRM2 with FIM = 0: E ahead of the foot of the perpendicular from D, branch +1).

Masses as L7542-7550 (:func:`sarkp.book.x_stages.masses`): link 2 at its middle, the lever
B-C-D with its centre 0.15 RCD from C towards D, link 4 at 0.3 RDE from D, the slider
5 at E; the forces stage's loads: the weights (g = 9.81) and the resistance FS on the
slider against x (2000 N while W3 < 0, the working stroke, 400 N otherwise; L7551).
Program X's forces are static (no inertia loads): solve them with omega = 0.

:func:`solve` returns the book's variables (FI2, FICB, XE, FIDE, W2, W3, W4, VE, E2, E3,
E4, AE, BE; F43 ... M1 as (modulus, direction); IPR = J_red) from one Mechanism solve, so
that they can be compared with the group-by-group corrected path
(tests/test_mechanism_book.py holds them to 1e-13).
"""

from __future__ import annotations

import math

import numpy as np

from ..mechanism import Mechanism
from . import x_data, x_stages


def mechanism(links: dict, resistance=None, *, crank_inertia: bool = False) -> Mechanism:
    """Program X's six-bar with ``links`` (RCD = RCB, RDE, ROA, RAB, ROC of the
    synthesis), its masses and weights; ``resistance``: the slider's resistance FS (N,
    a number or one value per position; acts against x); ``crank_inertia``: add the
    crank's IS1 (the book keeps it apart, DZKNDV's ISC)."""
    roa, rab, roc = links["ROA"], links["RAB"], links["ROC"]
    rcd = links["RCD"]
    rde = links["RDE"]
    xc, yc = -roc * math.sin(x_data.DELTA), roc * math.cos(x_data.DELTA)   # formula 27
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, yc)
    m.fixed("K", 0.0, x_data.H5 + yc)
    m.crank("A", "O", roa)
    m.rrr("B", "A", "C", rab, rcd, branch=1)
    m.point("D", "C", "B", rcd, math.pi)
    m.rrp("E", "D", "K", 0.0, rde, branch=1)
    w = x_stages.masses(links)
    if crank_inertia:
        m.mass("O", "A", mass=0.0, inertia=w["IS1"])
    m.mass("A", "B", mass=w["M2"], inertia=w["IS2"], centre=0.5 * rab)
    m.mass("C", "B", mass=w["M3"], inertia=w["IS3"], centre=(0.15 * rcd, math.pi))
    m.mass("D", "E", mass=w["M4"], inertia=w["IS4"], centre=0.3 * rde)
    m.mass("E", mass=w["M5"])
    if resistance is not None:
        fs = np.asarray(resistance, dtype=float)
        m.force("E", -fs if fs.ndim else -float(fs), 0.0)
    return m


def _polar(v):
    return np.hypot(v[..., 0], v[..., 1]), np.arctan2(v[..., 1], v[..., 0])


def solve(links: dict, angles=None) -> dict:
    """Kinematics, static forces and J_red of program X's mechanism from Mechanism
    solves, with the book's names (the corrected path's conventions: directions as
    atan2 gives them, moduli >= 0)."""
    f = x_stages.crank_angles() if angles is None else np.asarray(angles, dtype=float)
    w1 = x_data.W1
    kin = mechanism(links).solve(f, omega=w1, epsilon=0.0, need="accelerations")
    w3 = kin.omega("C", "B")
    fs = np.where(w3 < 0.0, 2000.0, 400.0)                     # IF(W3(K))15,16,16
    m = mechanism(links, fs)
    st = m.solve(f, omega=0.0, epsilon=0.0, need="forces", gravity=x_data.G)
    out = {"FI1": f, "FI2": kin.angle("A", "B"), "FICB": kin.angle("C", "B"),
           "XE": kin.position("E")[..., 0], "YE": kin.position("E")[..., 1],
           "FIDE": kin.angle("D", "E"), "XB": kin.position("B")[..., 0],
           "YB": kin.position("B")[..., 1], "XD": kin.position("D")[..., 0],
           "YD": kin.position("D")[..., 1],
           "W2": kin.omega("A", "B"), "W3": w3, "W4": kin.omega("D", "E"),
           "E2": kin.epsilon("A", "B"), "E3": kin.epsilon("C", "B"),
           "E4": kin.epsilon("D", "E"), "FS": fs, "IPR": kin.reduced_inertia}
    out["VE"], out["ALE"] = _polar(kin.velocity("E"))
    out["AE"], out["BE"] = _polar(kin.acceleration("E"))
    # the program's forces: X on Y as the book names them (F43: 4 on 3, ...)
    named = {"F43": -st.reaction("D"),                     # 3 on 4 at D, reversed
             "F45": st.reaction("E", on="E", by=("D", "E")),
             "F50": -st.reaction("E", on="E", by="frame"),
             "F21": -st.reaction("A"),                     # 1 on 2 at A, reversed
             "F23": st.reaction("B"),
             "F30": -st.reaction("C")}
    for name, v in named.items():
        out[name], out["G" + name[1:]] = _polar(v)
    out["M1"] = -st.balancing_moment
    out["vectors"] = named
    return out


def flywheel(links: dict, delta: float | None = None, positions: int = 361):
    """The flywheel of program X's machine from the Mechanism (chapter 8 at the mechanism
    level, :meth:`sarkp.Mechanism.flywheel`): J_red with the crank's IS1 (the book's
    IPR + ISC), the reduced moment of the weights and of the resistance FS (the book's M1:
    the static balancing moment's opposite), over one turn at ``positions`` points;
    ``delta``: the program's corrected 0.02 by default.  Returns the
    :class:`sarkp.dynamics.Flywheel` (exact J_flywheel, DMHVK's J_merkalov, the realized
    delta)."""
    delta = x_data.DELTA_FLYWHEEL["corrected"] if delta is None else delta
    phi = np.linspace(0.0, 2.0 * math.pi, positions)
    w3 = mechanism(links).solve(phi, omega=1.0, need="velocities").omega("C", "B")
    fs = np.where(w3 < 0.0, 2000.0, 400.0)
    m = mechanism(links, fs, crank_inertia=True)
    return m.flywheel(delta, x_data.W1, phi, gravity=x_data.G)
