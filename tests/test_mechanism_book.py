"""The book's programs on sarkp.Mechanism: program X's six-bar (x_mechanism), IV.15's
and VII.10's mechanism of Fig. 29/57 (kinds 1-5), against their group-by-group corrected
paths (the chapter 4 and 7 routines called one group at a time), to 1e-13 relative."""

import math

import numpy as np
import pytest

import sarkp
from sarkp.book import prog_x, x_mechanism

TOL = 1e-13


def close(a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = np.max(np.abs(b)) if scale is None else scale
    return np.max(np.abs(a - b)) <= TOL * s


def same_angle(a, b):
    return np.max(np.abs(np.remainder(a - b + math.pi, 2 * math.pi) - math.pi)) <= TOL * 10


@pytest.fixture(scope="module")
def x_paths():
    with sarkp.mode("corrected"):
        links = prog_x.synthesis()
        kin = prog_x.kinematics(links)
        fo = prog_x.forces(links, kin)
        ipr = prog_x.reduced_inertia(links, kin)
        ours = x_mechanism.solve(links)
    return links, kin, fo, ipr, ours


def test_program_x_kinematics(x_paths):
    links, kin, fo, ipr, ours = x_paths
    for name in ("XE", "YE", "XB", "YB", "XD", "YD", "W2", "W3", "W4", "VE", "E2", "E3",
                 "E4", "AE"):
        assert close(ours[name], kin[name]), name
    for name in ("FI2", "FICB", "FIDE", "ALE", "BE"):
        assert same_angle(ours[name], kin[name]), name


def test_program_x_forces_and_reduced_inertia(x_paths):
    links, kin, fo, ipr, ours = x_paths
    scale = max(np.max(fo[f]) for f in ("F43", "F45", "F50", "F21", "F23", "F30"))
    for name in ("F43", "F45", "F50", "F21", "F23", "F30"):
        book = np.stack([fo[name] * np.cos(fo["G" + name[1:]]),
                         fo[name] * np.sin(fo["G" + name[1:]])], -1)
        assert close(ours["vectors"][name], book, scale), name
    assert close(ours["M1"], fo["M1"])
    assert close(ours["IPR"], ipr)


# -- IV.15 and VII.10: the mechanism of Fig. 29 / 57, groups of all five kinds -----------

from sarkp.book import prog_iv_15, prog_vii_10      # noqa: E402


def polar(t, v, a):
    return np.stack([t[v] * np.cos(t[a]), t[v] * np.sin(t[a])], -1)


@pytest.fixture(scope="module")
def iv15():
    with sarkp.mode("corrected"):
        t = prog_iv_15.compute()
        r = prog_iv_15.mechanism().solve(t["FI"], omega=-prog_iv_15.CARD["W1"],
                                          need="accelerations")
    return t, r


def test_iv15_positions(iv15):
    t, r = iv15
    for p, (x, y) in {"B": ("XB", "YB"), "C": ("XC", "YC"), "D": ("XD", "Y"),
                      "H": ("XH", "YH"), "M": ("XM", "YM"), "P": ("XP", "YP")}.items():
        assert close(r.position(p), np.stack([t[x], t[y]], -1)), p
    # the kind-5 group: K = (SGL, 0) (DPRM5), the block SGH up the slot
    assert close(r.position("K")[:, 0], t["SGL"])
    for lk, name in ((("A", "B"), "FI2"), (("F", "B"), "FI3"), (("C", "D"), "FI4"),
                     (("O1", "N"), "FI9")):
        assert same_angle(r.angle(*lk), t[name]), name


def test_iv15_velocities_and_accelerations(iv15):
    t, r = iv15
    for lk, w, e in ((("A", "B"), "W2", "E2"), (("F", "B"), "W3", "E3"),
                     (("C", "D"), "W4", "E4"), (("O1", "N"), "W9", "E9")):
        assert close(r.omega(*lk), t[w]), w
        assert close(r.epsilon(*lk), t[e]), e
    for p, v, a in (("B", ("VB", "ALB"), ("AB", "BB")), ("D", ("VD", "ALD"), ("AD", "BD")),
                    ("K", ("VG", "ALG"), ("AG", "BG")), ("P", ("VP", "ALP"), ("AP", "BP"))):
        assert close(r.velocity(p), polar(t, *v)), v
        assert close(r.acceleration(p), polar(t, *a)), a
    # N of the book is link 9's point under M: omega9 x (M - O1)
    rm = r.position("M") - r.position("O1")
    w9, e9 = r.omega("O1", "N")[:, None], r.epsilon("O1", "N")[:, None]
    k_x = np.stack([-rm[:, 1], rm[:, 0]], -1)
    assert close(w9 * k_x, polar(t, "VN", "ALN"))
    assert close(e9 * k_x - w9**2 * rm, polar(t, "AN", "BN"))


def test_vii10_forces_and_balancing_moment():
    with sarkp.mode("corrected"):
        t = prog_vii_10.compute()
        m, FI = prog_vii_10.mechanism()
        r = m.solve(FI, omega=-prog_iv_15.CARD["W1"], epsilon=0.0, need="forces")
    # the program's forces are static: no masses in the Mechanism, so no inertia
    assert close(r.balancing_moment, t["MY"])
    named = {
        "F63": -r.reaction("H", on=("H", "K"), by=("F", "B")),
        "F76": r.reaction("H", on=("H", "K"), by=("K", "L")),
        "F70": -r.reaction("K", on=("K", "L"), by="frame"),
        "F43": -r.reaction("C"),
        # DNMAF2's second force is that of the rod on the slider (program X calls it
        # F45); VII.10 prints it as F54
        "F54": r.reaction("D", on="D", by=("C", "D")),
        "F50": -r.reaction("D", on="D", by="frame"),
        "F21": -r.reaction("A"),
        "F23": r.reaction("B"),
        "F30": -r.reaction("F"),
        "F109": -r.reaction("P", on=("P", "O1"), by=("O1", "N")),
        "F1011": r.reaction("P", on=("P", "Q"), by=("P", "O1")),
        "F110": -r.reaction("P", on=("P", "Q"), by="frame"),
        "F81": -r.reaction("M"),
        "F89": r.reaction("N", on=("O1", "N"), by=("M", "N")),
        "F90": -r.reaction("O1"),
    }
    scale = max(np.max(t[f]) for f in named)
    bad = [name for name, v in named.items()
           if not close(v, polar(t, name, "G" + name[1:]), scale)]
    assert not bad


def test_program_x_flywheel_from_the_mechanism(x_paths):
    links, kin, fo, ipr, ours = x_paths
    fw = x_mechanism.flywheel(links)
    assert fw.delta == pytest.approx(prog_x.DELTA_FLYWHEEL["corrected"], rel=1e-9)
    # its J_red and M_red on the program's 37 angles are the program's IPR + IS1 and M1
    fs = np.where(ours["W3"] < 0.0, 2000.0, 400.0)
    m = x_mechanism.mechanism(links, fs, crank_inertia=True)
    r = m.solve(prog_x.crank_angles(), omega=1.0, need="forces", gravity=prog_x.G)
    assert close(r.reduced_inertia, ipr + fo["IS1"])
    assert close(r.reduced_moment, fo["M1"])
