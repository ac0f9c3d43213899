"""Program VII.10 (L5596-5650): the force analysis of IV.15's mechanism, against virtual work.

The book prints no output of VII.10.  Its balancing moment MY = -TMR (eq. 7.22) must equal
what the power balance of the loads demands: MY*omega1 + sum(F.v) + sum(M*omega) = 0,
with omega1 = -W1 (the crank turns clockwise, ``FI = FI - DFI``), i.e. MY = P/W1 -- over
the whole sweep, with the velocities of IV.15, to 1e-9 of the loads' power.  In corrected
mode both come from sarkp.Mechanism solves (tests/test_mechanism_book.py holds them to the
book's call sequence).
"""

from __future__ import annotations

import numpy as np
import pytest

import sarkp
from sarkp import DMOMNT, DNMAF1
from sarkp.book import prog_iv_15, prog_vii_10 as prog

KIN = prog_iv_15.CARD
W1 = KIN["W1"]
RTOL = 1e-9
INERTIA = {"M2": 5.1, "J2": 0.09, "M3": 8.0, "J3": 0.25, "M4": 6.0, "J4": 0.17, "M5": 4.0,
           "M7": 10.2, "M9": 7.5, "J9": 0.12, "M11": 3.0}


def e(angle):
    return np.array([np.cos(angle), np.sin(angle)])


def fine_angles():
    return np.linspace(0.0, -2.0 * np.pi, 721)[:-1] - 1e-3 * np.pi   # off the grid


def powers(t, inertia=None):
    """The power of every load (W) at each position, from IV.15's velocities (and, for the
    d'Alembert loads, its exact accelerations)."""
    q2, q5 = KIN["Q2"], KIN["Q5"]
    c = prog.CARD
    v_a = W1 * KIN["ROA"] * e(t["FI"] - np.pi / 2)
    v_b = t["VB"] * e(t["ALB"])
    v_c = t["W3"] * KIN["RCF"] * e(t["FI3"] + np.pi / 2)
    v_d = t["VD"] * e(t["ALD"])
    v = {2: (v_a + v_b) / 2,
         3: t["W3"] * KIN["RFS3"] * e(t["FI3"] + np.pi / 2),
         4: (v_c + v_d) / 2,
         5: v_d,
         7: t["VG"] * e(t["ALG"]),
         9: t["W9"] * KIN["RO1S9"] * e(t["FI9"] + np.pi / 2),
         11: t["VP"] * e(t["ALP"])}
    down = np.array([0.0, -1.0])[:, None]
    back = np.array([-1.0, 0.0])[:, None]
    loads = {2: q2 * down, 3: c["Q3"] * down, 4: c["Q4"] * down, 5: t["FC2"] * back,
             7: t["FC1"] * back + q5 * down, 9: c["Q9"] * down, 11: t["FC3"] * back}
    terms = [np.sum(loads[k] * v[k], axis=0) for k in loads]
    if inertia:
        acc = prog._centre_accelerations(t, KIN)
        mass = {2: "M2", 3: "M3", 4: "M4", 5: "M5", 7: "M7", 9: "M9", 11: "M11"}
        for k, name in mass.items():
            a = np.array(acc[k])
            terms.append(-inertia[name] * np.sum(a * v[k], axis=0))
        for link in (2, 3, 4, 9):
            terms.append(-inertia[f"J{link}"] * t[f"E{link}"] * t[f"W{link}"])
    return np.array(terms)


@pytest.mark.parametrize("sweep", ["book", "fine"])
def test_balancing_moment_equals_virtual_work(sweep):
    angles = None if sweep == "book" else fine_angles()
    t = prog.compute(angles=angles)
    p = powers(t)
    scale = np.abs(p).sum(axis=0) / W1
    assert np.all(np.abs(t["MY"] - p.sum(axis=0) / W1) <= RTOL * scale)
    assert np.all(np.abs(t["MY"] + t["TMR"]) == 0.0)
    assert (t["FC1"] > 0).any() and (t["FC1"] == 0).any() and (t["FC3"] > 0).any()


def test_with_inertia_loads_exact_accelerations_balance_to_rounding():
    """The d'Alembert loads (extension) with IV.15's exact accelerations: the balancing
    moment equals -(sum F.v + sum M omega)/omega1 to rounding, inertia power included;
    tools that difference the velocities for accelerations only reach O(h^2)."""
    t = prog.compute(angles=fine_angles(), inertia=INERTIA)
    p = powers(t, INERTIA)
    scale = np.abs(p).sum(axis=0) / W1
    assert np.all(np.abs(t["MY"] - p.sum(axis=0) / W1) <= RTOL * scale)
    # the inertia loads matter here: without them the moment differs by far more
    bare = prog.compute(angles=fine_angles())
    assert np.abs(t["MY"] - bare["MY"]).max() > 1e3 * RTOL * scale.max()


def test_inertia_power_is_minus_the_rate_of_kinetic_energy():
    """The exact accelerations are the derivatives of the velocities: the inertia loads'
    power equals -dT/dt, with T from the velocities alone differentiated by a 4th-order
    central difference (error O(h^4): the agreement improves 16-fold when h halves)."""
    def kinetic(angles):
        t = prog_iv_15.compute(angles=angles)
        v = powers_velocities(t)
        m = INERTIA
        return 0.5 * (m["M2"] * v[2] + m["M3"] * v[3] + m["M4"] * v[4] + m["M5"] * v[5]
                      + m["M7"] * v[7] + m["M9"] * v[9] + m["M11"] * v[11]
                      + m["J2"] * t["W2"] ** 2 + m["J3"] * t["W3"] ** 2
                      + m["J4"] * t["W4"] ** 2 + m["J9"] * t["W9"] ** 2)

    phi = np.linspace(-0.3, -5.9, 15)
    t = prog.compute(angles=phi, inertia=INERTIA)
    p_inertia = powers(t, INERTIA).sum(axis=0) - powers(t).sum(axis=0)
    errors = []
    for h in (4e-3, 2e-3):
        d = (kinetic(phi - 2 * h) - 8 * kinetic(phi - h) + 8 * kinetic(phi + h)
             - kinetic(phi + 2 * h)) / (12 * h)
        dt_dt = -W1 * d                                   # d/dt = -W1 d/dFI
        errors.append(np.abs(p_inertia + dt_dt).max())
    assert errors[0] / errors[1] > 10.0
    assert errors[1] < 1e-6 * np.abs(p_inertia).max()


def powers_velocities(t):
    """Squared speeds of the centres of mass, from positions' velocities only."""
    v_a = W1 * KIN["ROA"] * e(t["FI"] - np.pi / 2)
    v_b = t["VB"] * e(t["ALB"])
    v_c = t["W3"] * KIN["RCF"] * e(t["FI3"] + np.pi / 2)
    v_d = t["VD"] * e(t["ALD"])
    sq = lambda u: np.sum(u * u, axis=0)                              # noqa: E731
    return {2: sq((v_a + v_b) / 2), 3: (t["W3"] * KIN["RFS3"]) ** 2, 4: sq((v_c + v_d) / 2),
            5: t["VD"] ** 2, 7: t["VG"] ** 2, 9: (t["W9"] * KIN["RO1S9"]) ** 2,
            11: t["VP"] ** 2}


def test_printed_dnmaf1_call_breaks_virtual_work_E_VII10_3():
    """As printed (L5628-5629), G2 = -PID2 is lost and its minus sign lands on XS3:
    ``Q2, -RFS3*COS(FI3) + ROF, RFS3*SIN(FI3), F3, ...``.  Reading the 22 arguments with
    the missing direction supplied but the minus kept puts S3 on the wrong side of F,
    and the balancing moment no longer matches the virtual work."""
    t = prog.compute()
    p = powers(t).sum(axis=0) / W1
    xs3 = -KIN["RFS3"] * np.cos(t["FI3"]) + KIN["ROF"]
    f21, g21 = DNMAF1(t["XA"], t["YA"], t["XB"], t["YB"], KIN["ROF"], 0.0,
                      0.5 * (t["XA"] + t["XB"]), 0.5 * (t["YA"] + t["YB"]), KIN["Q2"],
                      -np.pi / 2, xs3, KIN["RFS3"] * np.sin(t["FI3"]), t["F3"], t["G3"],
                      0.0, t["TM3"])[:2]
    tmr = DMOMNT(KIN["ROA"], t["FI"], f21, g21) + DMOMNT(KIN["ROM"], t["FI"] - np.pi,
                                                         t["F81"], t["G81"])
    assert np.abs(-tmr - p).max() > 1.0


def test_as_printed_runs_and_differs_by_pi_only():
    c = prog.compute()
    with sarkp.as_printed():
        p = prog.compute()
        text = prog.render()
    scale = np.abs(c["MY"]).max()
    assert 0 < np.abs(p["MY"] - c["MY"]).max() < 1e-4 * scale
    lines = text.split("\n")
    assert len(lines) == 25 * 11
    assert len(lines[7]) == 1 + 5 * 0 + 20 + 10 + 30 + 40 + 20        # FORMAT 42


def test_cli_runs_vii10_in_both_modes(capsys):
    from sarkp.cli import main
    for mode in ("as-printed", "corrected"):
        assert main(["book", "run", "VII.10", "--mode", mode]) == 0
        out = capsys.readouterr().out
        assert len(out.rstrip("\n").split("\n")) == 25 * 11 - 2


def test_plots_draw_the_computed_data(tmp_path):
    """sarkp.plot (optional matplotlib): the hodograph is (F cos G, F sin G) of the
    reaction, the speed diagram DZKNDV's omega with and without the flywheel."""
    pytest.importorskip("matplotlib")
    from sarkp import plot

    t = prog.compute(angles=fine_angles())
    figure = plot.reaction_hodograph(t["F21"], t["G21"], label="F21")
    x, y = figure.axes[0].lines[0].get_data()
    assert np.allclose(x, t["F21"] * np.cos(t["G21"])) and np.allclose(
        y, t["F21"] * np.sin(t["G21"]))
    plot.save(figure, tmp_path / "hodograph.png")
    assert (tmp_path / "hodograph.png").stat().st_size > 1000
    m = 73
    phi = np.linspace(0.0, 2 * np.pi, m)
    mpr = 300 * np.sin(phi) - 50.0
    r = sarkp.DZKNDV(m, float(m), 3.0, 60.0, mpr, np.zeros(m))
    imh = sarkp.DMHVK(m, 0.01, 60.0, 3.0, r.DEC).IMHVK
    wm = sarkp.DZKNDV(m, float(m), 3.0, 60.0 + imh, mpr, np.zeros(m)).WPR
    ax = plot.speed_diagram(phi, r.WPR, wm, W1=3.0).axes[0]
    assert np.array_equal(ax.lines[0].get_ydata(), r.WPR)
    assert np.array_equal(ax.lines[1].get_ydata(), wm)
    with pytest.raises(ValueError, match="F and G"):
        plot.reaction_hodograph([1.0, 2.0], [0.0])


@pytest.mark.parametrize("inertia, name", [({"M2": -1.0}, "M2"), ({"J3": float("nan")}, "J3"),
                                           ({"M6": 1.0}, "M6")])
def test_inertia_extension_rejects_bad_masses(inertia, name):
    with pytest.raises(ValueError, match=name):
        prog.compute(inertia=inertia)


#: the force variables of each group (FORCE_GROUPS) and of the crank
GROUP_FORCES = {
    "K": "F63 G63 F76 G76 H76 F70 G70 H70",
    "D": "F43 G43 F54 G54 F50 G50 H50",
    "B": "F21 G21 F23 G23 F30 G30 F3 G3 TM3",
    "P": "F109 G109 H109 F1011 G1011 F110 G110 H110",
    "N": "F81 G81 F89 G89 H89 F90 G90 F9 G9 TM9",
}


@pytest.mark.parametrize("card, failing", [({"RCD": 0.1}, "D"), ({"RAB": 0.05}, "B")])
def test_a_failing_group_leaves_the_forces_that_do_not_depend_on_it(card, failing):
    """on_error="nan": where a group does not assemble, its reactions, those of the
    groups it loads (inward: D and K load link 3 of group B) and MY are NaN; the groups
    on other branches and those outward of it keep theirs -- as in the book's call
    sequence, and equal to a solve of the positions where everything assembles."""
    fi = fine_angles()[::12]
    t = prog.compute(card=card, angles=fi, on_error="nan")
    bad = np.isnan(t["X" + failing])
    assert bad.any() and not bad.all()
    undefined = {"D": {"D", "B"}, "B": {"B", "D", "K"}}[failing]
    for g, names in GROUP_FORCES.items():
        for k in names.split():
            if g in undefined:
                assert np.isnan(t[k][bad]).all() and np.isfinite(t[k][~bad]).all(), k
            else:
                assert np.isfinite(t[k]).all(), k
    assert np.array_equal(np.isnan(t["MY"]), bad)
    ref = prog.compute_by_groups(card=card, angles=fi, on_error="nan")
    for k in t:
        assert np.array_equal(np.isnan(t[k]), np.isnan(ref[k])), k
    good = prog.compute(card=card, angles=fi[~bad])
    for k in t:
        np.testing.assert_array_equal(t[k][~bad], good[k], err_msg=k)
    with pytest.raises(sarkp.AssemblyError, match=f"group .* '{failing}'"):
        prog.compute(card=card, angles=fi)
