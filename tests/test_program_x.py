"""Program X (chapter 10, the course project) against its printed figures and physics.

As printed (figure data in sarkp/book/data): Figs. 84, 89, 91 (86, 87, 94, 96 when their
chapters are built) -- every reproducible cell within half a unit of its last printed
digit, or differing for the reason its ERRATA id gives; the OCR fixes follow from the
printed table itself.  Corrected: the design meets the task card (stroke 0.40 m, K = 1.1,
the cam's working angle), accelerations are the derivatives of the velocities.  Stages
run alone; a stage that cannot run says which and why, and prints nothing.
"""

import math
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import sarkp
from sarkp import book
from sarkp.book import figures, prog_x
from sarkp.cli import main


def diff(number, mode="as-printed"):
    figure = figures.load_figure(number)
    with sarkp.mode(mode):
        computed = book.figure_cells(number)
    return figure, figures.compare(figure, computed)


def printed(number):
    """{(row, column): value} of a printed figure (OCR fixes applied)."""
    return {(c.row, c.column): c.value for c in figures.load_figure(number).cells}


def columns(number):
    """Fig. ``number``'s printed columns as arrays over the rows 1, 2, ..."""
    cols = {}
    for cell in figures.load_figure(number).cells:
        if cell.row.isdigit():
            cols.setdefault(cell.column, {})[int(cell.row)] = cell.value
    return {c: np.array([v[i] for i in sorted(v)]) for c, v in cols.items()}


# ---- as printed: the figures ----------------------------------------------------------------

def classes(number):
    """Fig. ``number``'s compared cells by class, as ``sarkp book diff`` sorts them."""
    figure, comparisons = diff(number)
    with sarkp.as_printed():
        evidence = book.figure_evidence(number)
    out = {}
    for c, kind, why in figures.classify(comparisons, evidence):
        out.setdefault(kind, []).append((c, why))
    return out


@pytest.mark.parametrize("number", ["84", "86", "87", "89", "91", "94", "96"])
def test_every_differing_cell_is_classified_with_an_errata_id(number):
    """Every compared cell is in exactly one class; a differing cell carries the ERRATA
    id that discusses it (which alone explains nothing: the class says what is shown)."""
    figure, comparisons = diff(number)
    compared = [c for c in comparisons if c.computed is not None and c.cell.counterpart
                and c.cell.role != "repeat"]
    assert len(compared) == len(comparisons) - sum(c.cell.role == "repeat"
                                                   for c in comparisons)
    got = classes(number)
    assert sum(len(v) for v in got.values()) == len(compared)
    with sarkp.as_printed():
        book_run = book.figure_evidence(number).book
    for kind, cells in got.items():
        assert kind in figures.CLASSES
        for c, why in cells:
            if kind == figures.FITTED:                 # in double or the book's arithmetic
                key = (c.cell.row, c.cell.column)
                assert c.matches or figures.within_half(c.cell, book_run[key])
            elif kind in (figures.REPRODUCED, figures.INPUT):
                assert c.matches
            else:
                assert not c.matches and c.cell.errata, (c.cell.row, c.cell.column)


def _printed_run_bound91():
    """Fig. 91 as-printed (double) and, per cell, the bound its difference from the print
    has by the stated cause: the machine printed its REAL*4 value rounded, so a cell's
    double-precision value lies within half a unit of the print plus the book's
    arithmetic's own error there (|ES EVM run - double run|, both with the fitted lengths)
    plus what the lengths' standard uncertainty moves it (sum over the lengths of
    |d cell / d length| sigma)."""
    from sarkp.book import x_arithmetic
    with sarkp.as_printed():
        double = book.figure_cells("91")
    es = x_arithmetic.figure_cells("91", "es-evm")
    base = dict(prog_x.FITTED_LINKS)

    def run(lengths):
        with sarkp.as_printed():
            s = prog_x.synthesis()
            s.update(lengths)
            s["RCB"] = s["RCD"]
            return prog_x.stage_cells("kinematics", prog_x.kinematics(s))
    moved = {}
    for name, sigma in prog_x.FITTED_UNCERTAINTY.items():
        up, down = run({**base, name: base[name] + 1e-7}), run({**base, name: base[name] - 1e-7})
        moved[name] = {k: abs(up[k] - down[k]) / 2e-7 * sigma for k in up}
    bound = {c.row + "/" + c.column: 0.5 * c.unit + abs(es[(c.row, c.column)]
                                                         - double[(c.row, c.column)])
             + sum(m[(c.row, c.column)] for m in moved.values())
             for c in figures.load_figure("91").cells}
    return double, bound


def test_fitted_cells_are_within_half_a_unit_plus_the_arithmetic():
    """E-X-LINKS-1: every fitted cell lies within the bound of its stated cause
    (:func:`_printed_run_bound91`: half a unit, the arithmetic's error, the lengths')."""
    double, bound = _printed_run_bound91()
    for c in prog_x.fitted_cells():
        key = (c.row, c.column)
        assert abs(double[key] - c.value) <= bound[c.row + "/" + c.column], key


def test_fit_script_gives_the_fitted_links():
    """prog_x.REFITTED_LINKS["double"] and prog_x.FITTED_LINKS (the fit in the book's
    arithmetic, from the double one) are scripts/fit_x_links.py's output (it refits from
    the printed Fig. 91 and compares, exit status 1 otherwise)."""
    pytest.importorskip("scipy")
    import pathlib
    script = pathlib.Path(__file__).resolve().parents[1] / "scripts" / "fit_x_links.py"
    done = subprocess.run([sys.executable, str(script), "--check"], capture_output=True,
                          text=True, cwd=tempfile.gettempdir(), timeout=300)
    assert done.returncode == 0, done.stderr
    assert "587 cells of Fig. 91" in done.stdout
    # the one set the program runs with: the fit in the book's arithmetic
    done = subprocess.run([sys.executable, str(script), "--check", "--arithmetic", "es-evm"],
                          capture_output=True, text=True, cwd=tempfile.gettempdir(),
                          timeout=300)
    assert done.returncode == 0, done.stderr


def test_fitted_cells_are_reported_as_fitted_not_reproduced():
    got = classes("91")
    fitted = {(c.row, c.column) for c in prog_x.fitted_cells()}
    assert {(c.cell.row, c.cell.column) for c, _ in got[figures.FITTED]} <= fitted
    assert not fitted & {(c.cell.row, c.cell.column) for c, _ in got[figures.REPRODUCED]}
    # what is left reproduced is the crank angle, which no length moves (E-FIG91-7),
    # and the cells the fit leaves out
    for c, _ in got[figures.REPRODUCED]:
        assert (c.cell.column in ("FI1", "FI1_V", "FI1_A")
                or prog_x.FIT_LEFT_OUT & set(c.cell.errata.split(";"))), c.cell


def test_arithmetic_runs_are_the_program_sarkp_runs():
    """x_arithmetic writes program X's chain from the listings, independent of sarkp's
    Fortran; run in IEEE double it must be sarkp's as-printed chain up to double
    precision's rounding (1e-9 of each column's scale), so that its ES EVM and IEEE
    single runs differ from sarkp by the arithmetic alone."""
    from sarkp.book import x_arithmetic
    other = x_arithmetic.run("double")
    with sarkp.as_printed():                        # at the double run's crank angles
        links = prog_x.synthesis()
        k = prog_x.kinematics(links, other["kinematics"]["FI1"])
        fo = prog_x.forces(links, k)
        done = {"kinematics": k, "forces": fo, "dynamics": prog_x.dynamics(links, k, fo)}
    for stage in ("kinematics", "forces", "dynamics"):
        for name, values in other[stage].items():
            ref = np.asarray(done[stage][name], float)
            gap = np.abs(values - ref)
            if name in ("ALE", "BE") or name.startswith("G"):       # directions: mod 2 pi
                gap = np.abs(np.angle(np.exp(1j * (values - ref))))
                scale = 2 * np.pi
            else:
                scale = np.abs(ref).max()
            assert np.max(gap) <= 1e-9 * scale, (stage, name)


def test_fig89_fastest_follower_speed_needs_a_rounding_sin_E_FIG89_4():
    """E-FIG89-4: VT = WO SK/W1 SIN(PSI/SK) at PSI/SK = PI/2 (rows 6 and 21).  The exact
    value is the tie 0.23625; with SIN's result truncated to REAL*4 (0.99999994) the
    machine's VT lies below it and prints 0.2362, with SIN rounded (to 1.0) it prints
    the printed 0.2363.  The one library model, chosen over every emulated figure,
    truncates SIN (a rounding SIN breaks cells of Fig. 35): the two cells differ with no
    cause shown, and no other model is credited."""
    from sarkp.book import es_evm
    p = printed("89")
    assert "SIN" not in es_evm.ROUNDED
    with sarkp.as_printed():
        truncated = prog_x.cam_law()
        with es_evm.library_model(es_evm.ROUNDED | {"SIN"}):
            rounded = prog_x.cam_law()
    for row in (6, 21):
        printed_vt = p[(str(row), "VT")]
        assert abs(abs(printed_vt) - 0.2363) < 1e-12
        assert abs(truncated["VT"][row - 1] - printed_vt) > 0.5e-4
        assert abs(rounded["VT"][row - 1] - printed_vt) <= 0.5e-4
    got = classes("89")
    assert {(c.cell.row, c.cell.column) for c, _ in got[figures.NO_CAUSE]} == {
        ("6", "VT"), ("21", "VT")}
    assert figures.ARITHMETIC not in got


def test_fig87_sa_is_a_misprint_E_FIG87_1():
    """E-FIG87-1: the printed S = 5.3776 and SB = 5.8936 of the same gear pin X (each
    known to half a unit) to an interval in which SA cannot print 1.7100: it prints
    1.7107 or 1.7108 (sarkp: 1.71076)."""
    from sarkp.book import x_causes
    x_lo, x_hi, lo, hi = x_causes.fig87_sa1_interval()
    assert 0.3045 < x_lo < x_hi < 0.3047
    sa = printed("87")[("DGMTZK1", "SA")]
    assert 1.71070 < lo < hi < 1.71085 and sa < lo - 0.5e-4
    got = classes("87")
    shown = [(c.cell.row, c.cell.column) for c, _ in got[figures.CAUSE_SHOWN]]
    assert shown == [("DGMTZK1", "SA")]


def test_one_set_of_lengths_with_the_arithmetic_spread_E_X_LINKS_1(capsys):
    """No cell has a length cause of its own: program X runs with one set of lengths.
    Its uncertainty is widened by the arithmetic-model spread (the refits in the ES EVM's
    arithmetic and IEEE single, scripts/fit_x_links.py --arithmetic), and each refit is
    the better minimax fit in its own arithmetic: its worst fitted cell there is smaller
    than the double fit's."""
    from sarkp.book import x_arithmetic
    widened = prog_x.links_uncertainty()
    for name, sigma in prog_x.FITTED_UNCERTAINTY.items():
        spread = max(abs(r[name] - prog_x.FITTED_LINKS[name])
                     for r in prog_x.REFITTED_LINKS.values())
        assert widened[name] >= max(sigma, spread)
    cells = prog_x.fitted_cells()
    for arithmetic, lengths in prog_x.REFITTED_LINKS.items():
        def worst(run):
            got = prog_x.stage_cells("kinematics", run["kinematics"])
            return max(abs(got[(c.row, c.column)] - c.value) / c.unit for c in cells)
        assert worst(x_arithmetic.run(arithmetic, lengths)) < worst(
            x_arithmetic.run(arithmetic)), arithmetic
    for number in ("91", "94", "96"):
        with sarkp.as_printed():
            assert not book.figure_evidence(number).causes
    main(["book", "diff", "91"])
    out = capsys.readouterr().out
    for name, value in prog_x.FITTED_LINKS.items():       # the diff prints the set
        assert f"{name} = {value:.8f} +- {widened[name] * 1e6:.1f} um" in out


def test_cli_diff_classifies_every_cell(capsys):
    for number in ("84", "89", "91", "94", "96"):
        main(["book", "diff", number])
        out = capsys.readouterr().out
        figure, comparisons = diff(number)
        with sarkp.as_printed():
            row = figures.summary(figure, comparisons, book.figure_evidence(number))
        assert out.rstrip().splitlines()[-1] == figures.summary_line(row)
        for line in out.splitlines():
            if "DIFFERS" in line or "differs in double" in line:
                assert any(k in line for k in figures.CLASSES[3:]), line


def test_fig84_as_printed():
    figure, comparisons = diff("84")
    left_out = {c.cell.column: c.cell.errata for c in comparisons if not c.cell.reproducible}
    assert left_out == {"FICD": "E-DSNTZR-3;E-X-FICD1-1",
                        **{n: "E-DSNTZ1-4;E-X-LINKS-1" for n in ("ROA", "RAB", "ROC")}}
    assert all(c.matches for c in comparisons if c.cell.reproducible)


def test_fitted_links_round_to_fig84_and_dsntz1_is_far():
    """E-X-LINKS-1: the lengths fitted to Fig. 91 round to Fig. 84's print; neither
    reading of DSNTZ1 comes near them."""
    p = printed("84")
    for name, value in prog_x.FITTED_LINKS.items():
        assert round(value, 3) == p[("1", name)]
    for mode in sarkp.MODES:
        with sarkp.mode(mode):
            pi = sarkp.modes.book_pi()
            ficb1 = pi - (pi / 2 + prog_x.DELTA)                         # FICD1 = 0
            got = sarkp.DSNTZ1(1.1, ficb1, ficb1 + prog_x.DELTA, 0.5787882, 0.7, -1.0)
        assert abs(got.L2 - p[("1", "RAB")]) > 0.5 and abs(got.LO - p[("1", "ROC")]) > 0.5


def test_fig89_ocr_fixes_follow_from_the_same_row():
    """X = sqrt(RK**2 - Y**2) of the same row (E-FIG89-1, -2), with RK and Y each known
    to half a unit: the allowance is their spread through the identity plus X's own half
    unit; the OCR readings lie outside it, the corrected values inside."""
    p = printed("89")
    ocr = {(c.row, c.column): float(c.ocr) for c in figures.load_figure("89").cells if c.ocr}

    def x(rk, y):
        return math.sqrt(rk**2 - y**2)
    for row in ("14", "16"):
        args = [p[(row, "RK")], p[(row, "Y")]]
        allowed = _spread(x, args, [0.5e-4, 0.5e-4]) + 0.5e-4
        assert abs(x(*args) - p[(row, "X")]) <= allowed
        assert abs(x(*args) - ocr[(row, "X")]) > allowed


def test_fig89_phase_rows_need_the_es_evm_arithmetic():
    """E-FIG89-3: rows 11 and 16 are the end of the rise and of the dwell only in the ES
    EVM's arithmetic; IEEE double puts FI on the thresholds and prints other values."""
    p = printed("89")
    with sarkp.as_printed():
        law = prog_x.cam_law()
        fiu, fid = law["FIU"], law["FID"]
        assert law["FIK"][10] < fiu and law["FIK"][15] < fiu + fid
    assert p[("11", "AT")] == -1.8605 and p[("16", "AT")] == 0.0
    pi = 3.14159                                    # the loop DO 5 in IEEE double
    beta = pi * (1.1 - 1.0) / (1.1 + 1.0)
    fiu, fid = (pi - beta) * 0.4, (pi - beta) * 0.2
    fi = -fiu / 10.0
    angles = []
    for _ in range(26):
        fi += fiu / 10.0
        angles.append(fi)
    assert angles[10] == fiu and angles[15] == fiu + fid


def test_fig89_fastest_follower_speed_is_a_tie():
    """E-FIG89-4: DSMAX W1 / (2 SK) = 0.23625 exactly, SK = 8/21 whatever PI is."""
    from fractions import Fraction
    sk = Fraction(4, 10) * (1 - Fraction(1, 10) / Fraction(21, 10))
    assert Fraction(6, 100) * 3 / (2 * sk) == Fraction(23625, 100000)
    assert printed("89")[("6", "VT")] == 0.2363


def test_fig91_fi1_is_one_array():
    """E-FIG91-6: the three tables print the same FI1(K); row 36 agrees once fixed."""
    p = printed("91")
    for row in range(1, 38):
        assert p[(str(row), "FI1")] == p[(str(row), "FI1_V")] == p[(str(row), "FI1_A")]


def test_fig91_crank_angle_needs_the_es_evm_arithmetic():
    """E-FIG91-7: F = F + DF in the ES EVM's REAL*4 gives the printed 2.9670 etc."""
    p = columns("91")["FI1"]
    with sarkp.as_printed():
        es = prog_x.crank_angles()
    double = np.arange(37) * (2 * 3.14159 / 36)
    assert np.all(np.abs(es - p) <= 0.5e-4 + 1e-12)
    assert np.sum(np.abs(double - p) > 0.5e-4) >= 5


def _spread(f, args, halves):
    """How far f(*args) can move when each argument moves by its half unit: the first-
    order worst case, sum of |f(.., x_i + h_i, ..) - f(.., x_i - h_i, ..)| / 2."""
    total = 0.0
    for i, h in enumerate(halves):
        up, down = list(args), list(args)
        up[i] += h
        down[i] -= h
        total += abs(f(*up) - f(*down)) / 2.0
    return total


def test_fig91_identities_of_the_printed_columns():
    """The evidence for E-FIG91-1..5 and -9, from the printed table alone (and the
    printed 4-digit neighbours), with the link lengths of E-X-LINKS-1.  Each identity is
    evaluated on printed cells, each known to half a unit (0.5e-4), and on the fitted
    lengths, each known to its uncertainty (widened by the arithmetic-model spread,
    prog_x.links_uncertainty): the allowance is what those move the identity by
    (:func:`_spread`), plus the half unit of the cell it is compared with."""
    c = columns("91")
    L, sigma = prog_x.FITTED_LINKS, prog_x.links_uncertainty()
    h = 0.5e-4

    def w2(f1, f2, fcb, roa, rab):          # v_B = v_A + W2 k x AB = W3 k x CB
        return -(3.0 * roa * (-math.sin(f1) * math.cos(fcb) + math.cos(f1) * math.sin(fcb))
                 / (rab * math.sin(fcb - f2)))

    def w3(f1, f2, fcb, roa, rcd):
        return (3.0 * roa * (-math.sin(f1) * math.cos(f2) + math.cos(f1) * math.sin(f2))
                / (rcd * math.sin(f2 - fcb)))
    for fn, row, column, lengths, ocr in ((w3, 13, "W3", ("ROA", "RCD"), -0.6037),
                                          (w2, 35, "W2", ("ROA", "RAB"), 0.1928)):
        args = [c[n][row - 1] for n in ("FI1", "FI2", "FICB")] + [L[n] for n in lengths]
        halves = [h, h, h] + [sigma[n] for n in lengths]
        value, allowed = fn(*args), _spread(fn, args, halves) + h
        assert abs(value - c[column][row - 1]) <= allowed        # E-FIG91-1, -4
        assert abs(value - ocr) > allowed                        # what the OCR read
    # E3/E2 = RAB/RCB in every row (E-DUSKR1-1), which fixes E2 rows 16, 20 (-3, -5)
    ratio = L["RAB"] / L["RCD"]
    ratio_sigma = ratio * (sigma["RAB"] / L["RAB"] + sigma["RCD"] / L["RCD"])
    allowed = h * (1 + ratio) + ratio_sigma * np.abs(c["E2"])
    assert np.all(np.abs(np.abs(c["E3"]) - ratio * np.abs(c["E2"])) <= allowed + 1e-12)
    for row, ocr in ((16, 0.8588), (20, 0.5868)):
        e2 = abs(c["E3"][row - 1]) / ratio
        allowed = h / ratio + e2 * ratio_sigma / ratio + h
        assert abs(e2 - c["E2"][row - 1]) <= allowed and abs(e2 - ocr) > allowed

    # E4 from the vertical component of DUSKR2's equation (omega2 for omega4, E-X-W4)
    def e4(e3, w3p, w2p, fcb, fde, rcd, rde):
        ady = -e3 * rcd * math.cos(fcb) + w3p**2 * rcd * math.sin(fcb)
        return (w2p**2 * rde * math.sin(fde) - ady) / (rde * math.cos(fde))
    names = ("E3", "W3", "W2", "FICB", "FIDE")
    for row in (5,):
        args = [c[n][row - 1] for n in names] + [L["RCD"], L["RDE"]]
        halves = [h] * 5 + [sigma["RCD"], sigma["RDE"]]
        value, allowed = e4(*args), _spread(e4, args, halves) + h
        assert abs(value - c["E4"][row - 1]) <= allowed          # 3.8884, E-FIG91-2
        assert abs(value - 3.8804) > allowed
    # E-FIG91-9: the table's most sensitive cells (cos FIDE = 0.41 divides), left out of
    # the fit: with the lengths fitted in the book's arithmetic, row 16 is reproduced in
    # double precision and row 15 under the book's arithmetic
    got = {(c.cell.row, c.cell.column): kind for c, kind, _ in
           figures.classify(diff("91")[1], book.figure_evidence("91"))}
    assert got[("16", "E4")] == figures.REPRODUCED
    assert got[("15", "E4")] == figures.ARITHMETIC


def test_fig91_needs_the_duskr1_error():
    """Corrected mode (E-DUSKR1-1 fixed) does not reproduce the printed E3.  As printed,
    DUSKR1 takes ABS(Y(1)) for both angular accelerations, so |E3| RCB = |E2| RAB in
    every row (the relative gap is double precision's rounding of two divisions)."""
    c = columns("91")
    with sarkp.as_printed():
        links = prog_x.synthesis()
        printed_run = prog_x.kinematics(links)
    got = prog_x.kinematics(links)                  # corrected routines, book's mechanism
    assert np.abs(got["E3"] - c["E3"]).max() > 0.5
    lhs = np.abs(printed_run["E3"]) * links["RCB"]
    rhs = np.abs(printed_run["E2"]) * links["RAB"]
    assert np.all(np.abs(lhs - rhs) <= 4 * np.finfo(float).eps * rhs)
    assert not np.allclose(np.abs(got["E3"]) * links["RCB"], rhs)


def test_fig91_slider_directions_are_0_or_pi():
    """E-FIG91-10: VE and AE are along the horizontal guide, up to the book's PI: each
    vector summed into them has a direction with at most two of the book's PI or PI/2
    added (ALD = FICB + PI + PI/2, BD = FICB + PI + (PI - ...), FIDE + PI/2, FI2 - PI),
    each off by at most pi - 3.14159, so the sum's direction is off the guide by at most
    2 (pi - 3.14159) times the sum of the terms' magnitudes over the result's: VE = VD +
    VED with |VED| <= |VD| + |VE|; AE = AD + the normal W2**2 RDE (E-X-W4) + the
    tangential |E4| RDE."""
    with sarkp.as_printed():
        links = prog_x.synthesis()
        k = prog_x.run(["kinematics"])["kinematics"]
    off = 2.0 * (math.pi - 3.14159)
    ad = links["RCD"] * np.sqrt(k["W3"]**4 + k["E3"]**2)
    bounds = {"ALE": off * (2.0 * np.abs(k["VD"]) + np.abs(k["VE"])) / np.abs(k["VE"]),
              "BE": off * (ad + k["W2"]**2 * links["RDE"] + np.abs(k["E4"]) * links["RDE"])
              / np.abs(k["AE"])}
    for name, bound in bounds.items():
        assert np.all(np.abs(np.sin(k[name])) <= bound), name


def test_fig86_ocr_fix_from_coaxiality():
    """E-FIG86-1: scheme 3 needs z1 - z2 = z4 - z3 and i = 1 - z2 z4/(z1 z3) = P/Q."""
    from fractions import Fraction
    p = printed("86")
    ocr = {(c.row, c.column): int(c.ocr) for c in figures.load_figure("86").cells if c.ocr}
    for row, call in enumerate(prog_x.DZBPL_CALLS, 1):
        z1, z2, z3, z4 = (int(p[(str(row), f"Z{i}")]) for i in range(1, 5))
        if call[-1] == 3:
            assert z1 - z2 == z4 - z3
            assert 1 - Fraction(z2 * z4, z1 * z3) == Fraction(call[1], call[2])
    assert ocr[("2", "Z4")] == 126 and 100 - 84 != 126 - 112
    # E-FIG86-2: the eighth set (scheme 1) meets ratio and assembly, not coaxiality
    z1, z2, z3, z4 = (int(p[("8", f"Z{i}")]) for i in range(1, 5))
    assert 1 + Fraction(z4, z1) == Fraction(71, 10) and (z1 + z4) % 3 == 0
    assert z1 + z2 != z4 - z3
    with sarkp.mode("corrected"):
        variants = prog_x.run(["teeth"])["teeth"]["variants"]
    assert [r is None for _, r in variants] == [False] * 7 + [True]


def test_fig87_identities_of_the_printed_cells():
    """E-FIG87-2, -3: the printed cells agree with each other through the book's
    formulas; SA1 is on its rounding edge for any DA1 the print allows."""
    p = printed("87")
    a, aw, xu, xur = (p[("DGMZPC", n)] for n in ("A", "AW", "XU", "XUR"))
    assert abs((aw - a) / 3.0 - xu) <= 0.5e-4 and abs(-xu - xur) <= 1e-12
    for h, hi, lo in (("H1", "DA1", "DF1"), ("H2", "DF2", "DA2")):
        half = (p[("DGMZVN", hi)] - p[("DGMZVN", lo)]) / 2.0
        assert abs(half - p[("DGMZVN", h)]) <= 0.5e-4 + 1e-9


def test_fig87_sa1_is_on_its_rounding_edge():
    """E-FIG87-3: SA1 of the internal mesh, for any DA1 within the printed 157.2092's
    interval, straddles the rounding edge of the printed 2.4346 (x of the gear 51 from
    DKRKT: the printed -0.305 is too coarse for this)."""
    p = printed("87")
    with sarkp.as_printed():
        x1 = sarkp.DKRKT(3.0, 20.0, 51.0, 0.0, 3).X2
    pi, m, z1 = 3.14159, 3.0, 51.0
    alfa = pi / 9.0

    def sa1(da1):
        ala = math.acos(m * z1 * math.cos(alfa) / da1)
        return da1 * ((0.5 * pi + 2 * x1 * math.tan(alfa)) / z1
                      + (math.tan(alfa) - alfa) - (math.tan(ala) - ala))
    da1 = p[("DGMZVN", "DA1")]
    lo, hi = sorted((sa1(da1 - 0.5e-4), sa1(da1 + 0.5e-4)))
    assert lo < p[("DGMZVN", "SA1")] - 0.5e-4 < hi


def test_fig87_internal_mesh_cells_are_what_the_es_evm_computed():
    """E-FIG87-3: DGMZVN run statement by statement in the ES EVM's REAL*4 with the one
    library model (prog_vi_7.emulate, independent of sarkp's Fortran) with program X's
    call gives the printed DA1, DA2, DF2, H2, SA1 that sarkp's double precision misses;
    H1 neither run gives: no cause shown."""
    from sarkp.book import prog_vi_7
    with sarkp.as_printed():
        x = sarkp.DKRKT(3.0, 20.0, 51.0, 0.0, 3).X2
    call = prog_x.GEAR_CALLS["DGMZVN"]
    inputs = tuple(dict(call, X1=x)[n] for n in sarkp.DGMZVN.spec.inputs if n != "AAA")
    emulated = prog_vi_7.emulate({"X": inputs})
    _, comparisons = diff("87")
    cells = {c.cell.column: c for c in comparisons if c.cell.row == "DGMZVN"}
    for name in ("DA1", "DA2", "DF2", "H2", "SA1", "H1"):
        cell = cells[name]
        assert not cell.matches
        assert figures.within_half(cell.cell, emulated[("X", name)]) == (name != "H1"), name
    got = classes("87")
    assert {c.cell.column for c, _ in got[figures.ARITHMETIC] if c.cell.row == "DGMZVN"} == {
        "DA1", "DA2", "DF2", "H2", "SA1"}
    assert {c.cell.column for c, _ in got[figures.NO_CAUSE] if c.cell.row == "DGMZVN"} == {
        "H1"}


def test_fig87_dgmzpc_cells_need_a_rounding_atan_E_FIG87_2():
    """E-FIG87-2: DGMZPC run statement by statement in the ES EVM's REAL*4
    (prog_vi_6.emulate, program X's call): with ATAN truncating its result, DUGINV's
    iteration stops on another alpha_w and AW misses the printed 106.4972 (XU, XUR with
    it); with the one library model (ATAN rounds) the run gives the printed AW, XU, XUR,
    which double precision misses."""
    from sarkp.book import es_evm
    p = printed("87")
    assert "ATAN" in es_evm.ROUNDED
    cells = {n: c for c in figures.load_figure("87").cells if c.row == "DGMZPC"
             for n in [c.column]}
    with sarkp.as_printed():
        book_run = book.figure_evidence("87").book
        with es_evm.library_model(es_evm.ROUNDED - {"ATAN"}):
            truncating = book.figure_evidence("87").book
    assert not figures.within_half(cells["AW"], truncating[("DGMZPC", "AW")])
    for name in ("AW", "XU", "XUR"):
        assert figures.within_half(cells[name], book_run[("DGMZPC", name)]), name
    assert abs(book_run[("DGMZPC", "AW")] - p[("DGMZPC", "AW")]) <= 0.5e-4
    got = classes("87")
    assert {c.cell.column for c, _ in got[figures.ARITHMETIC] if c.cell.row == "DGMZPC"} == {
        "AW", "XU", "XUR"}


def test_fig91_slider_is_on_the_guide_E_X_DPRM2_1():
    """E-X-DPRM2-1: the 13-argument DPRM2 call (L7512) is read as the guide y = H5 + YC
    (K = (0, H5 + YC), FIM = 0, RZ2 = RDE): the printed FICB and FIDE of every row of
    Fig. 91 satisfy RDE sin(FIDE) = H5 + YC - YD, YD = YC + RCD sin(FICB + PI).  The
    printed angles are known to half a unit (0.5e-4 rad): the identity's residual in FIDE
    is bounded by 0.5e-4 (FIDE) + 0.5e-4 RCD |cos FICB| / (RDE cos FIDE) (FICB), and the
    lengths' uncertainty (E-X-LINKS-1, < 5e-6 m) adds less than 1e-5 rad."""
    c = columns("91")
    links = prog_x.FITTED_LINKS
    rcd, rde = links["RCD"], links["RDE"]
    yc = links["ROC"] * math.cos(prog_x.DELTA)
    yd = yc + rcd * np.sin(c["FICB"] + 3.14159)
    fide = np.arcsin((prog_x.H5 + yc - yd) / rde)
    bound = (0.5e-4 + 0.5e-4 * rcd * np.abs(np.cos(c["FICB"])) / (rde * np.cos(c["FIDE"]))
             + 1e-5)
    assert np.all(np.abs(fide - c["FIDE"]) <= bound)
    # the call as written (XK = 0, YK = 0, FIM = H5 + YC, RZ2 = 0) has no link DE
    assert sarkp.listing("X").count("CALL DPRM2(XD, YD, 0.0, 0.0, H5 + YC, 0.0, RDE,") == 1


def test_fig94_ocr_fixes_from_the_printed_columns():
    """E-FIG94-5: cos(G45) = FS/F45 (the guide holds 5 vertically); E-FIG94-6:
    M1 = ROA F21 sin(G21 - FI1) with the printed M1, F21 of the row."""
    p = printed("94")
    ocr = {(c.row, c.column): float(c.ocr) for c in figures.load_figure("94").cells if c.ocr}
    g45 = math.acos(400.0 / p[("28", "F45")])
    # G45 is known to half a unit, F45 to half a unit: d G45 = FS dF45 / (F45**2 sin G45)
    allowance = 0.5e-3 + 400.0 * 0.05 / (p[("28", "F45")] ** 2 * math.sin(g45))
    assert abs(g45 - p[("28", "G45")]) <= allowance < abs(g45 - ocr[("28", "G45")])
    # E-FIG94-6: G21 = FI1 + asin(M1 / (ROA F21)) - 2 pi (the branch of the row); FI1 is
    # the program's own crank angle (exact), M1 and F21 are each known to half a unit,
    # ROA to its widened uncertainty: the G21 they allow is an interval
    roa = prog_x.FITTED_LINKS["ROA"]
    with sarkp.as_printed():
        fi1 = float(prog_x.crank_angles()[18])
    ends = []
    for m1 in (p[("19", "M1")] - 0.05, p[("19", "M1")] + 0.05):
        for f21 in (p[("19", "F21")] - 0.05, p[("19", "F21")] + 0.05):
            for r in (roa - prog_x.links_uncertainty()["ROA"],
                      roa + prog_x.links_uncertainty()["ROA"]):
                ends.append(fi1 + math.asin(m1 / (r * f21)) - 2.0 * math.pi)
    lo, hi = min(ends), max(ends)
    # the corrected -2.383 lies inside with its whole half-unit interval; the OCR's
    # -2.385 only touches it (less than a tenth of its interval): the fix is probable,
    # not proven (docs/ERRATA.md says so)
    g = p[("19", "G21")]
    assert lo <= g - 0.5e-3 and g + 0.5e-3 <= hi
    g = ocr[("19", "G21")]
    assert 0.0 < hi - (g - 0.5e-3) and min(hi, g + 0.5e-3) - max(lo, g - 0.5e-3) < 0.1e-3


# ---- corrected mode: the design the task card asks for ---------------------------------------

def checks(done):
    """The task card's measures of a run (x_report.design) and its physical checks:
    the accelerations against central differences of the velocities over a fine sweep,
    and the moment M1 against the virtual work of the loads (relative to each quantity's
    largest value)."""
    from sarkp.book import x_report
    out = x_report.design(done)
    W1, G = prog_x.W1, prog_x.G
    if "kinematics" in done:
        links = done["synthesis"]
        fine = np.linspace(0.0, 2.0 * math.pi, 3601)
        k = prog_x.kinematics(links, fine)
        h = 1e-5
        plus, minus = prog_x.kinematics(links, fine + h), prog_x.kinematics(links, fine - h)

        def rel(a, b):
            return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))

        def vex(t):
            return t["VE"] * np.cos(t["ALE"])

        def aex(t):
            return t["AE"] * np.cos(t["BE"])
        out["E2_vs_dW2/dt"] = rel(k["E2"], W1 * (plus["W2"] - minus["W2"]) / (2 * h))
        out["E3_vs_dW3/dt"] = rel(k["E3"], W1 * (plus["W3"] - minus["W3"]) / (2 * h))
        out["E4_vs_dW4/dt"] = rel(k["E4"], W1 * (plus["W4"] - minus["W4"]) / (2 * h))
        out["AE_vs_dVE/dt"] = rel(aex(k), W1 * (vex(plus) - vex(minus)) / (2 * h))
    if "forces" in done:
        # virtual work (no inertia loads): the moment M1 of link 2's force on the crank
        # about O times omega1 is the power of the loads, FS on 5 and the weights of 2-5;
        # the points' velocities as central differences of their positions
        links = done["synthesis"]
        fine = np.linspace(0.0, 2.0 * math.pi, 721)[:-1]
        h = 1e-6
        k, kp, km = (prog_x.kinematics(links, fine + d) for d in (0.0, h, -h))
        fo = prog_x.forces(links, k)
        m = prog_x.masses(links)
        pi = sarkp.modes.book_pi()

        def centres(t):
            c3 = (t["XC"] + 0.15 * links["RCD"] * np.cos(t["FICB"] + pi),
                  t["YC"] + 0.15 * links["RCD"] * np.sin(t["FICB"] + pi))
            s4y = t["YD"] + 0.3 * links["RDE"] * np.sin(t["FIDE"])
            s2y = t["YA"] + 0.5 * links["RAB"] * np.sin(t["FI2"])
            return t["XE"], s2y, c3[1], s4y
        (xe_p, s2_p, s3_p, s4_p), (xe_m, s2_m, s3_m, s4_m) = centres(kp), centres(km)
        rate = W1 / (2.0 * h)
        power = (-fo["FS"] * (xe_p - xe_m) * rate
                 - G * (m["M2"] * (s2_p - s2_m) + m["M3"] * (s3_p - s3_m)
                        + m["M4"] * (s4_p - s4_m)) * rate)      # slider 5 moves level
        out["virtual_work"] = float(np.max(np.abs(fo["M1"] * W1 - power))
                                    / np.max(np.abs(power)))
    return out


def test_corrected_design_meets_the_task_card():
    with sarkp.mode("corrected"):
        done = prog_x.run(["synthesis", "cam", "kinematics"])
        c = checks(done)
    s = done["synthesis"]
    # E-X-FICD1-1: with CD at FICD1 to the guide the slider is at the card's x_E = 0.82
    ficd1 = s["FICD1"]
    xe = s["RCD"] * math.cos(ficd1) + math.sqrt(
        s["RDE"]**2 - (prog_x.H5 - s["RCD"] * math.sin(ficd1))**2)
    # (to 1e-3: the DATA's FI5 = 1.57 and 0.349, 0.698 rad are the card's 90, 20, 40
    # degrees to 3 digits; DSNTZR meets them exactly, the horizontal guide here nearly)
    assert xe == pytest.approx(prog_x.X5[0], abs=1e-3)
    assert c["stroke"] == pytest.approx(0.40, abs=1e-6)             # x_E 0.82 -> 0.42
    assert c["swing"] == pytest.approx(prog_x.DELTA, abs=1e-6)
    assert c["K_realized"] == pytest.approx(1.1, abs=1e-5)
    # the working stroke is the cam's working angle PI - BETA (L6695-6697)
    assert math.radians(c["working_stroke_deg"]) == pytest.approx(
        done["cam"]["FIU"] / 0.4, abs=1e-5)
    for key in ("E2_vs_dW2/dt", "E3_vs_dW3/dt", "E4_vs_dW4/dt", "AE_vs_dVE/dt"):
        assert c[key] < 1e-7, key


def test_corrected_forces_and_flywheel():
    """Virtual work: M1 w1 is the loads' power; the flywheel for the card's delta = 0.02
    gives it (E-X-DELTA-1); without it the machine stalls (E-DZKNDV-2)."""
    with sarkp.mode("corrected"):
        done = prog_x.run(["dynamics"])
        c = checks(done)
    assert c["virtual_work"] < 1e-6
    d = done["dynamics"]
    assert d["DELTA"] == 0.02 and d["STALLS"] and np.isnan(d["WPR"]).all()
    assert c["delta_realized"] == pytest.approx(0.02, rel=0.01)


def test_the_book_run_fails_the_task_card():
    with sarkp.as_printed():
        done = prog_x.run(["synthesis", "kinematics"])
        c = checks(done)
    # the printed 10-degree table brackets the stroke: from below by its range less the
    # two extremes' half units; from above by what XE can exceed its samples by between
    # them, max |d2 XE / dphi2| (dphi/2)**2 / 2 at each extreme
    xe = columns("91")["XE"]
    with sarkp.as_printed():
        fine = np.linspace(0.0, 2.0 * math.pi, 3601)
        sweep = prog_x.kinematics(done["synthesis"], fine)["XE"]
    step = fine[1] - fine[0]
    curvature = np.abs(np.diff(sweep, 2)).max() / step**2
    between = 2 * curvature * (math.pi / 36) ** 2 / 2
    assert xe.max() - xe.min() - 1e-4 <= c["stroke"] <= xe.max() - xe.min() + 1e-4 + between
    assert c["stroke"] < 0.3                 # the card asks 0.40 m
    assert abs(c["K_realized"] - 1.1) > 0.03
    assert c["E3_vs_dW3/dt"] > 0.1 and c["E2_vs_dW2/dt"] < 1e-4


def test_corrected_reduced_inertia_counts_m3_once():
    """E-X-IPR-1: as printed, IPR has M3 (0.15 RCD W3)**2 / W1**2 twice."""
    with sarkp.as_printed():
        links = prog_x.synthesis()
        kin = prog_x.kinematics(links)
        twice = prog_x.reduced_inertia(links, kin)
    once = prog_x.reduced_inertia(links, kin)
    m3 = prog_x.masses(links)["M3"]
    extra = m3 * (0.15 * links["RCD"] * kin["W3"])**2 / prog_x.W1**2
    assert np.allclose(twice - once, extra, rtol=1e-9, atol=1e-12)


def test_corrected_diff_names_the_design_changes(capsys):
    main(["book", "diff", "91", "--mode", "corrected"])
    out = capsys.readouterr().out
    assert "unexplained" not in out and "E-X-LINKS-1" in out


# ---- stages ------------------------------------------------------------------------------------

def test_stage_alone_prints_only_that_stage():
    with sarkp.as_printed():
        text = prog_x.render("cam")
    assert text.splitlines()[0].strip() == "КИНЕМАТИЧЕСКИЕ ХАРАКТЕРИСТИКИ ДВИЖЕНИЯ ТОЛКАТЕЛЯ"
    numbers = [ln for ln in text.splitlines() if ln.strip()[:1].isdigit()]
    assert "РАЗМЕРЫ" not in text and len(numbers) == 2 * 26
    with sarkp.as_printed():
        kin = prog_x.render("kinematics")
    assert "РАЗМЕРЫ" not in kin and kin.count("\n") > 111


def test_task_card_without_a_mechanism(monkeypatch):
    from sarkp.book import x_stages              # where the synthesis reads the task card
    monkeypatch.setattr(x_stages, "X5", (0.82, 0.82, 0.82))
    with pytest.raises(sarkp.SarkpError, match="stage 'synthesis'.*DSNTZR"):
        prog_x.run(["kinematics"])


def test_cli_stage(capsys):
    assert main(["book", "run", "X", "--stage", "synthesis"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(" РАЗМЕРЫ ЗВЕНЬЕВ МАНИПУЛЯТОРА")
    assert "RCD =   0.579 RDE =   0.701 FICD =   0.000" in out


def test_cli_run_in_the_es_evm_arithmetic(capsys):
    """``sarkp book run X --arithmetic es-evm``: the kinematics, forces and dynamics
    printed from x_arithmetic's ES EVM run (the printed Fig. 91's first row, and rows the
    ES EVM reproduces where double does not)."""
    from sarkp.book import x_arithmetic
    assert main(["book", "run", "X", "--arithmetic", "es-evm", "--stage", "kinematics"]) == 0
    out = capsys.readouterr().out
    es = x_arithmetic.run("es-evm")["kinematics"]
    with sarkp.as_printed():
        double = prog_x.run(["kinematics"])["kinematics"]
    assert prog_x.RENDER["kinematics"](es) == out.rstrip("\n")
    assert prog_x.RENDER["kinematics"](double) != out.rstrip("\n")
    assert main(["book", "run", "X", "--arithmetic", "es-evm", "--mode", "corrected"]) == 2
    assert "as-printed mode only" in capsys.readouterr().err


def test_cli_diff_in_the_es_evm_arithmetic(capsys):
    """``sarkp book diff 91 --arithmetic es-evm`` compares x_arithmetic's run cell by cell:
    its count is the emulation's own (computed here from the same data)."""
    from sarkp.book import x_arithmetic
    for number in x_arithmetic.FIGURES:
        main(["book", "diff", number, "--arithmetic", "es-evm"])
        out = capsys.readouterr().out
        figure = figures.load_figure(number)
        comparisons = figures.compare(figure, x_arithmetic.figure_cells(number, "es-evm"))
        row = figures.summary(figure, comparisons)
        assert out.rstrip().splitlines()[-1] == figures.summary_line(row)
        assert "(es-evm)" in out
    assert main(["book", "diff", "4", "--arithmetic", "es-evm"]) == 2


@pytest.mark.parametrize("args, message, status", [
    (["book", "run", "X", "--stage", "gearbox"], "program X has the stages", 2),
    (["book", "run", "II.13", "--stage", "cam"], "program II.13 has no stages", 2),
])
def test_cli_stage_mistakes(args, message, status):
    done = subprocess.run([sys.executable, "-m", "sarkp"] + args, capture_output=True,
                          text=True, cwd=tempfile.gettempdir())
    assert done.returncode == status and done.stdout == ""
    assert message in done.stderr and "Traceback" not in done.stderr


def test_plots_are_written(tmp_path):
    pytest.importorskip("matplotlib")
    from sarkp.book import x_plots
    with sarkp.as_printed():
        paths = x_plots.plots(tmp_path)
    names = {p.name for p in paths}
    assert {"x_mechanism.png", "x_velocities.png", "x_accelerations.png",
            "x_cam_profile.png", "x_cam_curvature.png"} <= names
    for p in paths:
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and p.stat().st_size > 10_000
    with sarkp.mode("corrected"):
        assert [p.name for p in x_plots.plots(tmp_path / "c", "cam")] == [
            "x_cam_profile.png", "x_cam_curvature.png"]


def test_readme_summary_is_the_diff_summary():
    """README.md's summary table is what ``sarkp book diff all`` prints now."""
    import pathlib
    import re
    readme = (pathlib.Path(__file__).resolve().parents[1] / "README.md").read_text("utf-8")
    shown = re.search(r"<!-- summary:.*?-->\n(.*?)\n<!-- end of summary -->", readme,
                      re.S).group(1)
    rows = []
    for number in book.FIGURES:
        figure, comparisons = diff(number)
        rows.append(figures.summary(figure, comparisons, book.figure_evidence(number)))
    assert shown == figures.summary_table(rows)


def test_corrected_cam_is_convex_with_the_books_radius_beside():
    """Issue 27: the corrected design sizes the flat-faced follower's cam convex: its
    radius is the smallest with RKSH + S + A/W**2 >= 0 at every point (computed here from
    the motion law), so no point is concave, where the book's GAMMA = PI/3 leaves 7 of the
    26 concave; the report prints the book's rule's radius beside it."""
    with sarkp.mode("corrected"):
        c = prog_x.run(["cam"])["cam"]
        text = prog_x.render("cam")
    need = np.max(-np.asarray(c["ST"]) - np.asarray(c["AT"]) / prog_x.W1**2)
    eps = np.finfo(float).eps
    assert abs(c["RKSH"] - need) <= 8 * eps * need
    assert np.min(c["ROK"]) >= -8 * eps * c["RKSH"] and c["NCONC"] == 0
    assert c["RKSH_BOOK"] < c["RKSH"] and c["ROKMIN_BOOK"] < 0.0
    with sarkp.as_printed():
        book_cam = prog_x.run(["cam"])["cam"]
    assert book_cam["NCONC"] == int(np.sum(np.asarray(book_cam["ROK"]) < 0.0)) > 0
    assert f"{c['RKSH']:.6f}" in text and f"{book_cam['RKSH']:.6f}" in text


def test_program_x_modules_import_no_circle():
    """prog_x and its x_* modules form no import circle (issue 25): the stages are
    x_stages', the constants x_data's, and neither imports prog_x.  The graph is read
    from every import statement of the installed modules, inside functions too."""
    import ast
    from pathlib import Path
    here = Path(book.__file__).parent
    names = {p.stem for p in here.glob("*.py")}
    graph = {}
    for name in names:
        seen = set()
        for node in ast.walk(ast.parse((here / f"{name}.py").read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                targets = [node.module] if node.module else [a.name for a in node.names]
                seen.update(t.split(".")[0] for t in targets)
        graph[name] = seen & names

    def reaches(start, goal):
        todo, done = [start], set()
        while todo:
            for n in graph[todo.pop()] - done:
                if n == goal:
                    return True
                done.add(n)
                todo.append(n)
        return False

    ours = sorted(n for n in names if n == "prog_x" or n.startswith("x_"))
    assert "x_stages" in ours and graph["x_mechanism"] >= {"x_stages"}
    assert [n for n in ours if reaches(n, n)] == []
