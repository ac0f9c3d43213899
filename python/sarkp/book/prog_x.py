"""Program X (section 10.8, L7228-7650): the course project of chapter 10, the
conveyor-feeder ("manipulator") mechanism, stage by stage as the book runs it.

=========== ======== ====================================================== =========
stage       figure   routines (program X's statements)                      chapter
=========== ======== ====================================================== =========
synthesis   Fig. 84  DSNTZR, DSNTZ1 (L7310-7338)                            3
teeth       Fig. 86  DZBPL x 8 (L7340-7363)                                 6
gears       Fig. 87  DKRKT, DGMTZK x 2, DGMZPC, DGMZVN (L7365-7405)         6
cam         Fig. 89  the motion law (loop DO 5), DPRFPL (L7407-7489)        5
kinematics  Fig. 91  DPRM1, DPRM2, DSKOR1, DSKOR2, DUSKR1, DUSKR2           4
                     (L7491-7531, printed L7584-7606)
forces      Fig. 94  DSMVKT, DNMAF2, DMOMNT, DNMAF1 (L7533-7566)            7
dynamics    Fig. 96  the reduced inertia IPR (L7568-7579), DZKNDV, DMHVK,   8
                     DZKNDV (L7622-7647)
=========== ======== ====================================================== =========

The task card (Fig. 75, L6157-6196, with the ch. 10 text): slider stroke 0.40 m
(x_E = 0.82, 0.62, 0.42 m while link 3 turns by 0, 20, 40 degrees), guide height
H5 = 0.64 m, coefficient of speed change K = 1.1, crank speed 3 rad/s, flat-faced cam
follower with a 0.06 m lift on a cosine acceleration law, resistance 2000 N / 400 N,
links of 50 kg/m, and a flywheel for delta = 0.02.

Each stage can run alone (``sarkp book run X --stage cam``), as the book recommends for
the dialogue mode (L7238-7252); a stage that needs an earlier stage's results (the
kinematics needs the link lengths, the forces the kinematics, the dynamics the forces)
runs that stage silently first.  When an earlier stage cannot run (its task card has no
mechanism), the stage raises a :class:`sarkp.SarkpError` naming both stages and the
cause, and prints nothing.  The stages themselves live in :mod:`sarkp.book.x_stages`
(shared with the modules below, which would otherwise import this one back; every name
is also this module's).  The printouts are :mod:`sarkp.book.x_render`'s, the corrected
design's report :mod:`sarkp.book.x_report`'s; :mod:`sarkp.book.x_arithmetic` runs the
kinematics, forces and dynamics in the ES EVM's arithmetic or IEEE single, and
:mod:`sarkp.book.x_causes` holds the demonstrated causes of differing cells.

As-printed mode reproduces the printed figures: PI = 3.14159, the main program's own
arithmetic that a printed cell depends on (the crank angle ``F = F + DF``, L7504, and
the cam's loop DO 5) in the ES EVM's truncating REAL*4 (:mod:`sarkp.book.es_evm`), and
the program's choices and errors the figures were computed with, each a row of
docs/ERRATA.md (section "Program X"):

* E-X-FICD1-1: FICD1 = 0 for the crank angle of DSNTZR's first position (1.3563 rad);
* E-X-LINKS-1: the five link lengths as fitted to Fig. 91 (scripts/fit_x_links.py; no
  DSNTZ1 gives them);
* E-DUSKR1-1 (DUSKR1's ``ABS(Y(1))``) and E-X-W4 (omega2 passed to DUSKR2 for omega4);
* E-X-IPR-1: the m3 term counted twice in the reduced inertia;
* E-X-DELTA-1: delta = 0.01 for the flywheel where the card asks 0.02.

Corrected mode is the design the task card asks for: exact pi, FICD1 from DSNTZR, the
lengths from DSNTZ1's construction, true accelerations, the reduced inertia counted
once, delta = 0.02; :func:`corrected_report` prints where it differs from the book and
the task card's measures (the stroke, the coefficient of speed change, the flywheel's
delta); tests/test_program_x.py holds it against physics (accelerations against numerical
derivatives of the velocities, the forces against virtual work).  Without a flywheel the corrected
machine stalls (E-DZKNDV-2): WPR, EPR are then not printed.
"""

from __future__ import annotations

import sarkp
from .. import get_mode
from .x_render import RENDER
from .x_report import corrected_report
from .x_data import (  # noqa: F401  (re-exported)
    X5, H5, FICD, FI5, DELTA, SKW, XD, Q, W1, DSMAX, GAMMA_DIVISOR, G, ML, POSITIONS,
    CAM_POINTS, FITTED_LINKS, FIT_LEFT_OUT, FITTED_UNCERTAINTY, DELTA_FLYWHEEL, STAGES,
    STAGE_FIGURE, NEEDS, CORRECTED_DIFFERENCES, REFITTED_LINKS, links_uncertainty)
# the stages, shared with x_arithmetic, x_mechanism and x_report (re-exported)
from .x_stages import (  # noqa: F401
    StageError, synthesis, DZBPL_CALLS, teeth, GEAR_CALLS, gears, cam_law, cam,
    crank_angles, kinematics, masses, forces, reduced_inertia, dynamics, run, stage_cells)

LISTING = "X"
TITLE = "Course project of chapter 10: the conveyor-feeder mechanism (program X)"


def available(stage: str) -> bool:
    """Whether ``stage`` can run: every stage's routines are in sarkp (kept for
    :func:`plots`)."""
    if stage not in STAGES:
        raise ValueError(f"program X has no stage {stage!r}; stages: {', '.join(STAGES)}")
    return True


#: the figures program X prints
FIGURES = tuple(STAGE_FIGURE[s] for s in STAGES)



def render(stage: str | None = None, arithmetic: str | None = None) -> str:
    """The program's printout in the book's layout: every stage that this build can run
    (a note names the others and why), or one ``stage`` alone.  Everything is computed
    before anything is returned, so a failure prints nothing.

    ``arithmetic`` ("es-evm" or "ieee-single", as-printed mode only) runs the stages
    kinematics, forces and dynamics statement by statement in that arithmetic
    (:mod:`sarkp.book.x_arithmetic`) instead of sarkp's double precision."""
    if arithmetic is not None:
        from . import x_arithmetic
        if arithmetic not in x_arithmetic.ARITHMETICS:
            raise ValueError(f"arithmetic must be one of "
                             f"{', '.join(x_arithmetic.ARITHMETICS)}, not {arithmetic!r}")
        if get_mode() != "as-printed":
            raise ValueError("an arithmetic other than double emulates the printed run: "
                             "as-printed mode only")
        stages = list(STAGES) if stage is None else [stage]
        done = run(stages)
        other = x_arithmetic.run(arithmetic)
        for s in ("kinematics", "forces", "dynamics"):
            if s in done:
                done[s] = other[s]
        return "\n".join(RENDER[s](done[s]) for s in STAGES
                         if s in done and (stage is None or s == stage))
    stages = list(STAGES) if stage is None else [stage]
    done = run(stages)
    text = "\n".join(RENDER[s](done[s]) for s in STAGES if s in stages)
    if get_mode() == "corrected":
        text += "\n\n" + corrected_report(done, stages)
    return text



def figure_cells(number: str) -> dict:
    """Figure ``number`` of program X as computed, {(row, column): value}."""
    stage = next(s for s, f in STAGE_FIGURE.items() if f == str(number))
    return stage_cells(stage, run([stage])[stage])


def fitted_cells() -> list:
    """The printed cells of Fig. 91 that :data:`FITTED_LINKS` were fitted to: every cell
    that depends on the lengths (all but FI1), less those of :data:`FIT_LEFT_OUT`."""
    from .figures import load_figure
    return [c for c in load_figure("91").cells
            if c.reproducible and not c.column.startswith("FI1")
            and not FIT_LEFT_OUT & set(c.errata.split(";"))]


def evidence(number: str):
    """What shows more about a printed figure than the double-precision run
    (:class:`sarkp.book.figures.Evidence`): the cells the link lengths were fitted to
    (Fig. 91; Fig. 84 prints the fitted lengths and FICD1, which the program takes from
    the print, E-X-FICD1-1), program X's chain run whole in the book's arithmetic
    (:mod:`sarkp.book.x_arithmetic`; Figs. 91, 94, 96) with IEEE single as a diagnostic,
    the ES EVM's DGMZPC and DGMZVN (Fig. 87) and the demonstrated causes.  Fig. 89's
    loop DO 5 already runs in the book's arithmetic as printed (:func:`cam_law`)."""
    from . import x_arithmetic
    from .figures import Evidence
    from .x_causes import causes
    number = str(number)
    book, diagnostic = {}, {}
    if number in x_arithmetic.FIGURES:
        book = x_arithmetic.figure_cells(number, "es-evm")
        diagnostic = {"IEEE single": x_arithmetic.figure_cells(number, "ieee-single")}
    elif number == "87":
        book = _gears_es_evm()
    fitted, fit = frozenset(), ""
    if number == "91":
        fitted = frozenset((c.row, c.column) for c in fitted_cells())
        spread = links_uncertainty()
        fit = ("scripts/fit_x_links.py, one set for program X: " + ", ".join(
            f"{n} = {v:.8f} +- {spread[n] * 1e6:.1f} um" for n, v in FITTED_LINKS.items())
            + "; the uncertainty is the fit's, widened by the refits in the ES EVM's "
              "arithmetic and IEEE single")
    elif number == "84":
        fitted = frozenset(("1", n) for n in ("ROA", "RAB", "ROC", "FICD"))
        fit = ("ROA, RAB, ROC are the lengths fitted to Fig. 91 (E-X-LINKS-1), FICD1 = 0 "
               "is taken from this print (E-X-FICD1-1)")
    return Evidence(fitted=fitted, book=book, diagnostic=diagnostic, causes=causes(number),
                    fit=fit)


def _gears_es_evm() -> dict:
    """Fig. 87's DGMZPC and DGMZVN blocks as the ES EVM computed them (prog_vi_6.emulate,
    prog_vi_7.emulate with program X's calls; the shifts from as-printed DKRKT)."""
    from .. import as_printed
    from . import prog_vi_6, prog_vi_7
    with as_printed():
        x = sarkp.DKRKT(**GEAR_CALLS["DKRKT"]).X2
    call = dict(GEAR_CALLS["DGMZVN"], X1=x)
    inputs = tuple(call[n] for n in sarkp.DGMZVN.spec.inputs if n != "AAA")
    out = {("DGMZVN", name): v for (_, name), v in prog_vi_7.emulate({"X": inputs}).items()}
    pc = GEAR_CALLS["DGMZPC"]
    with as_printed():
        k = sarkp.DKRKT(**GEAR_CALLS["DKRKT"])
    call = (pc["M"], pc["Z1"], pc["Z2"], pc["BETA"], k.X1, k.X2, pc["BW"])
    rename = {"ALFAW": "ALFA", "XY": "XU"}               # the printed names
    out.update((("DGMZPC", rename.get(name, name)), v)
               for (_, name), v in prog_vi_6.emulate({"X": call}).items())
    return out
