"""Program X's corrected design against the book's run (``sarkp book run X --mode
corrected`` ends with it): the task card's measures of the mechanism (the slider's stroke,
the swing of link 3, the coefficient of speed change realized, the flywheel's delta) and
where the corrected design differs from the printed run, each with its ERRATA id.  The
physical checks of the corrected run (accelerations against numerical derivatives of the
velocities, forces against virtual work) are tests: tests/test_program_x.py."""

from __future__ import annotations

import math

import numpy as np

import sarkp
from . import x_data, x_stages


def design(done: dict) -> dict:
    """The task card's measures of a run: the slider's stroke, the swing of link 3, the
    working stroke (the crank's turn while link 3 turns clockwise, W3 < 0, between the
    rocker's extreme positions) and the coefficient of speed change it realizes, over a
    fine sweep of the mechanism (:func:`sarkp.book.x_mechanism.mechanism`); with the
    dynamics, the delta the flywheel realizes."""
    from . import x_mechanism
    out = {}
    if "kinematics" in done:
        # the six-bar as a sarkp.Mechanism (x_mechanism), swept in one compiled call
        # the task card's measures of the design: the Mechanism computes them corrected
        # in either mode (it has no as-printed mode), so it is asked to, without a warning
        from ..modes import mode
        fine = np.linspace(0.0, 2.0 * math.pi, 3601)
        with mode("corrected"):
            k = x_mechanism.mechanism(done["synthesis"]).solve(
                fine, omega=x_data.W1, epsilon=0.0, need="velocities")
        xe = k.position("E")[..., 0]
        ficb = np.unwrap(k.angle("C", "B"))            # continuous through +-pi
        out["stroke"] = float(xe.max() - xe.min())
        out["swing"] = float(ficb.max() - ficb.min())
        w3 = k.omega("C", "B")
        i = np.flatnonzero(np.sign(w3[:-1]) != np.sign(w3[1:]))
        zeros = fine[i] - w3[i] * (fine[i + 1] - fine[i]) / (w3[i + 1] - w3[i])
        if zeros.size != 2:
            raise x_stages.StageError(f"program X, stage 'kinematics' (Fig. 91): link 3 "
                                      f"stops {zeros.size} times per turn, not twice: "
                                      f"the mechanism is no crank-rocker")
        inside = (zeros[1] - zeros[0]) / (2.0 * math.pi)
        work = inside if w3[i[0] + 1] < 0.0 else 1.0 - inside
        out["working_stroke_deg"] = 360.0 * work
        out["K_realized"] = max(work, 1 - work) / min(work, 1 - work)
    if "dynamics" in done:
        w = done["dynamics"]["WPRM"]
        out["delta_realized"] = float((w.max() - w.min()) / x_data.W1)
    return out


def corrected_report(done: dict, stages) -> str:
    """Where the corrected design differs from the book's run, and its measures."""
    with sarkp.as_printed():
        book = x_stages.run([s for s in stages if s in x_data.STAGES])
        cb = design(book)
    c = design(done)
    lines = ["CORRECTED DESIGN (sarkp --mode corrected) AGAINST THE BOOK'S RUN",
             f"  {'quantity':40s} {'corrected':>12} {'book':>12}"]

    def row(name, ours, theirs, unit="", why=""):
        lines.append(f"  {name:40s} {ours:>12} {theirs:>12} {unit:6s} {why}")
    if "synthesis" in done:
        s, b = done["synthesis"], book["synthesis"]
        row("FICD1, angle of CD in position 1", f"{s['FICD1']:.4f}", f"{b['FICD1']:.4f}",
            "rad", "E-X-FICD1-1")
        for n in ("ROA", "RAB", "ROC"):
            row(n, f"{s[n]:.4f}", f"{b[n]:.4f}", "m", "E-X-LINKS-1")
    if "teeth" in done:
        found = sum(r is not None for _, r in done["teeth"]["variants"])
        row("teeth: DZBPL variants with a set", f"{found} of 8",
            f"{sum(r is not None for _, r in book['teeth']['variants'])} of 8", "",
            "E-DZBPL-4, E-FIG86-2")
    if "gears" in done:
        for block, name in (("DKRKT", "ALFAW"), ("DGMZPC", "AW"), ("DGMZVN", "AW")):
            row(f"gears: {block} {name}", f"{getattr(done['gears'][block][1], name):.4f}",
                f"{getattr(book['gears'][block][1], name):.4f}", "", "E-DUGINV-1")
    if "cam" in done:
        row("cam: working angle PI - BETA", f"{done['cam']['FIU'] / 0.4:.6f}",
            f"{book['cam']['FIU'] / 0.4:.6f}", "rad", "E-PI-1")
        row("cam: base radius RKSH (convex)", f"{done['cam']['RKSH']:.6f}",
            f"{book['cam']['RKSH']:.6f}", "m", "flat_base_radius; E-PI-1")
        row("cam: smallest radius of curvature", f"{done['cam']['ROKMIN']:.6f}",
            f"{book['cam']['ROKMIN']:.6f}", "m", "book: concave")
        row("cam: concave points", f"{done['cam']['NCONC']} of {len(done['cam']['ROK'])}",
            f"{book['cam']['NCONC']} of {len(book['cam']['ROK'])}", "")
    if "kinematics" in done:
        row("slider stroke (card: 0.40)", f"{c['stroke']:.4f}", f"{cb['stroke']:.4f}", "m")
        row("swing of link 3 (card: 0.698)", f"{c['swing']:.4f}", f"{cb['swing']:.4f}",
            "rad")
        row("K realized (card: 1.1)", f"{c['K_realized']:.4f}", f"{cb['K_realized']:.4f}")
        row("working stroke (cam: 171.43 deg)", f"{c['working_stroke_deg']:.2f}",
            f"{cb['working_stroke_deg']:.2f}", "deg")
        k, kb = done["kinematics"], book["kinematics"]
        for n in ("E3", "E4", "AE"):
            row(f"largest |{n}|", f"{np.abs(k[n]).max():.4f}",
                f"{np.abs(kb[n]).max():.4f}", "", "E-DUSKR1-1; E-X-W4")
    if "dynamics" in done:
        d, db = done["dynamics"], book["dynamics"]
        row("flywheel delta (card: 0.02)", f"{d['DELTA']:.2f}", f"{db['DELTA']:.2f}", "",
            "E-X-DELTA-1")
        row("delta realized with the flywheel", f"{c['delta_realized']:.4f}",
            f"{cb['delta_realized']:.4f}")
        row("steady motion without the flywheel", "stalls" if d["STALLS"] else "yes",
            "stalls" if db["STALLS"] else "printed", "", "E-DZKNDV-2")
        row("IMH", f"{d['IMH']:.2f}", f"{db['IMH']:.2f}", "kg m2", "E-X-IPR-1; E-X-DELTA-1")
        row("largest IPR", f"{d['IPR'].max():.2f}", f"{db['IPR'].max():.2f}", "kg m2",
            "E-X-IPR-1")
    return "\n".join(lines)
