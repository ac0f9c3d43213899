"""The drawing-sheet pictures of program X (chapter 10's course project), stage by stage.

:func:`plots` runs the stages (:func:`sarkp.book.prog_x.run`) in the current mode and
writes their pictures; :data:`PICTURES` names them per stage, so that the command line can
say what it will write before it runs anything.  In as-printed mode every title says so,
and the curves that carry the book's errors say which (ERRATA ids in the caption).
"""

from __future__ import annotations

import numpy as np

from ..modes import get_mode
from . import prog_x

#: stage -> the names (without suffix) of the pictures :func:`plots` writes for it
PICTURES = {
    "gears": ("x_gear_mesh", "x_internal_mesh"),
    "kinematics": ("x_mechanism", "x_velocities", "x_accelerations"),
    "cam": ("x_cam_profile", "x_cam_curvature"),
    "forces": ("x_hodograph_21", "x_hodograph_23", "x_hodograph_30", "x_hodograph_43"),
    "dynamics": ("x_energy", "x_omega"),
}


def pictures(stage: str | None = None) -> tuple:
    """The names (without suffix) that :func:`plots` writes for ``stage`` (default:
    every stage this build can run)."""
    stages = [stage] if stage else [s for s in prog_x.STAGES if prog_x.available(s)]
    return tuple(n for s in stages for n in PICTURES.get(s, ()))


def _positions(fi1):
    """The book's position numbers: 1 at FI1 = 0, one per 10 degrees (L7503)."""
    return np.arange(1, len(fi1) + 1)


#: Every crank angle of the program's 37 positions split into this many steps: the
#: hodographs' curves are drawn from this sweep (10 degrees / 20 = half a degree).
DENSE = 20

#: What the hodographs' jumps are (L7551: FS = 2000 N while W3 < 0, 400 N otherwise).
JUMP = "jump: the resistance FS switches between 2000 and 400 N (ω3 changes sign)"


def sweep(links: dict, fi1) -> dict:
    """The kinematics and forces stages (:func:`prog_x.kinematics`, :func:`prog_x.forces`,
    in the current mode) over a dense sweep of the turn of ``fi1`` (the program's
    positions, each step split into :data:`DENSE`): what the hodographs are drawn from."""
    fi1 = np.asarray(fi1, dtype=float)
    parts = fi1[:-1, None] + np.diff(fi1)[:, None] * (np.arange(DENSE) / DENSE)
    dense = np.append(parts.ravel(), fi1[-1])
    return prog_x.forces(links, prog_x.kinematics(links, dense))


def plots(directory, stage: str | None = None, *, format: str = "png",
          dpi: float | None = None) -> list:
    """Write the pictures of the stages run (``stage``, or every stage this build can run)
    in ``directory`` as ``format`` files (png, svg or pdf); return their paths.  Needs
    matplotlib.

    gears: the external mesh 20/51 with DKRKT's shifts, the internal mesh 51/122;
    kinematics: the mechanism in its
    positions, the velocity and the acceleration diagrams; cam: the profile with the flat
    follower, the radius of curvature; forces: the hodographs of the joint reactions;
    dynamics: work and energy, the crank's angular speed without and with the flywheel."""
    from pathlib import Path

    from .. import plot

    stages = [stage] if stage else [s for s in prog_x.STAGES if prog_x.available(s)]
    done = prog_x.run(stages)
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    mode = get_mode()
    printed = mode == "as-printed"
    title = plot.mode_title
    written = []

    def save(figure, name):
        written.append(plot.save(figure, directory / name, format=format, dpi=dpi))

    if "gears" in stages:
        args, _ = done["gears"]["DGMZPC"]
        save(plot.gear_mesh(args["M"], args["Z1"], args["Z2"], args["X1"], args["X2"],
                            title=title(f"Program X: the mesh z1 = {args['Z1']:g}, "
                                        f"z2 = {args['Z2']:g}, m = {args['M']:g} mm, "
                                        f"x1 = {args['X1']:.3f}, x2 = {args['X2']:.3f} "
                                        "(DKRKT)")), "x_gear_mesh")
        args, _ = done["gears"]["DGMZVN"]
        save(plot.internal_mesh(*(args[k] for k in ("M", "Z1", "Z2", "X1", "X2", "ZO2", "DO",
                                                     "XO", "DAO")),
                                title=title(f"Program X: the internal mesh z1 = {args['Z1']:g},"
                                            f" z2 = {args['Z2']:g}, m = {args['M']:g} mm, "
                                            f"x1 = {args['X1']:.3f}, x2 = {args['X2']:g}")),
             "x_internal_mesh")
    if "kinematics" in stages:
        k, s = done["kinematics"], done["synthesis"]
        numbers = _positions(k["FI1"])
        pts = {"O": (0.0, 0.0), "A": (k["XA"], k["YA"]), "B": (k["XB"], k["YB"]),
               "C": (k["XC"], k["YC"]), "D": (k["XD"], k["YD"]), "E": (k["XE"], k["YE"])}
        save(plot.mechanism(pts, [("O", "A"), ("A", "B"), ("B", "C", "D"), ("D", "E")],
                            fixed=("O", "C"), guide=float(k["YE"][0]), every=3,
                            paths=("A", "E"), slider="E", positions=numbers,
                            title=title(f"Program X: the mechanism every 30° of the crank "
                                        f"(OA {s['ROA']:.3f} m, AB {s['RAB']:.3f} m, "
                                        f"OC {s['ROC']:.3f} m)")),
             "x_mechanism")
        vex = k["VE"] * np.cos(k["ALE"])
        save(plot.diagrams(k["FI1"], [
            ("angular velocity, rad/s", {"ω2 (coupler AB)": k["W2"], "ω3 (lever CBD)": k["W3"],
                                         "ω4 (rod DE)": k["W4"]}),
            ("velocity of the slider E, m/s", {"v_E along the guide (x)": vex})],
            degrees=True, positions=numbers,
            title=title(f"Program X: velocities at ω1 = {prog_x.W1:g} rad/s")),
            "x_velocities")
        aex = k["AE"] * np.cos(k["BE"])
        save(plot.diagrams(k["FI1"], [
            ("angular acceleration, rad/s²", {"ε2 (coupler AB)": k["E2"],
                                              "ε3 (lever CBD)": k["E3"],
                                              "ε4 (rod DE)": k["E4"]}),
            ("acceleration of the slider E, m/s²", {"a_E along the guide (x)": aex})],
            degrees=True, positions=numbers,
            title=title("Program X: accelerations"),
            caption=("As printed, ε3 is computed with DUSKR1's ABS(Y(1)) (E-DUSKR1-1), and ε4 "
                     "and a_E with ω2 where ω4 belongs (E-X-W4): the jumps of these curves "
                     "are the book's errors, not the mechanism's motion; --mode corrected "
                     "draws the true accelerations.") if printed else None),
            "x_accelerations")
    if "cam" in stages:
        c = done["cam"]
        convex = int(np.sum(c["ROK"] < 0))
        save(plot.cam_profile(c["X"], c["Y"], c["FIK"], follower="flat",
                              base_radius=c["RKSH"],
                              title=title(f"Program X: cam with a flat-faced follower, "
                                          f"r0 = {c['RKSH'] * 1000:.1f} mm"
                                          + (f"; ρ < 0 at {convex} of {len(c['ROK'])} "
                                             "points: not convex (E-DPRFPL-1)"
                                             if convex else ""))),
             "x_cam_profile")
        save(plot.cam_diagrams(c["FIK"], c["ROK"], positions=np.arange(1, len(c["FIK"]) + 1),
                               title=title("Program X: radius of curvature of the cam")),
             "x_cam_curvature")
    if "forces" in stages:
        f = done["forces"]
        dense = sweep(done["synthesis"], f["FI1"])
        for name, where in (("21", "A (crank OA on coupler AB), F21"),
                            ("23", "B (coupler AB on lever CBD), F23"),
                            ("30", "C (lever CBD on the frame), F30"),
                            ("43", "D (rod DE on lever CBD), F43")):
            save(plot.reaction_hodograph(f["F" + name], f["G" + name],
                                         sweep=(dense["F" + name], dense["G" + name]),
                                         label=f"reaction at {where}",
                                         jump_label=JUMP,
                                         positions=_positions(f["FI1"]),
                                         title=title(f"Program X: hodograph of the reaction "
                                                     f"at {where.split(' (')[0]}")),
                 f"x_hodograph_{name}")
    if "dynamics" in stages:
        d = done["dynamics"]
        numbers = _positions(d["FI1"])
        save(plot.diagrams(d["FI1"], [
            ("work and energy, J", {"work of all forces ΣA": d["ASUM"],
                                    "kinetic energy of the links E_V": d["EV"],
                                    "surplus ΔE = ΣA − E_V": d["DEC"]}),
            ("reduced moment of inertia, kg·m²", {"J_pr of the links": d["IPR"]})],
            degrees=True, positions=numbers,
            title=title("Program X: work, energy and reduced inertia")), "x_energy")
        mean = {"mean speed ω1": np.full(len(d["FI1"]), prog_x.W1)}
        panels, notes = [], []
        if not d["STALLS"]:
            wpr = np.asarray(d["WPR"], dtype=float)
            panels.append(("angular speed ω1, rad/s", {"without flywheel (WPR)": wpr, **mean}))
            notes.append("Caveat: without a flywheel ω1 swings from "
                         f"{np.nanmin(wpr):.0f} to {np.nanmax(wpr):.0f} rad/s around a mean "
                         f"of {prog_x.W1:g}: eq. (8.17) linearised far outside its range; "
                         "no machine moves so -- it needs the flywheel."
                         if np.nanmin(wpr) < 0 else "")
        panels.append(("angular speed ω1, rad/s",
                       {f"with flywheel J = {d['IMH']:.1f} kg·m² (WPRM)": d["WPRM"], **mean}))
        notes.append(f"coefficient of fluctuation δ = {d['DELTA']:g} asked"
                     + ("; without the flywheel the machine stalls: there is no steady "
                        "motion to draw (E-DZKNDV-2)" if d["STALLS"] else ""))
        save(plot.diagrams(d["FI1"], panels, degrees=True, positions=numbers, notes=notes,
                           title=title("Program X: angular speed of the crank")), "x_omega")
    return written
