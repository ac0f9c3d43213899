"""Program IV.15 (L2476-2545): the Fig. 29 mechanism with Assur groups of all five kinds.

The book prints no output of IV.15, so the program is held against geometry and physics:
every group closes, velocities are the time derivatives of positions and accelerations
those of velocities (4th-order central differences on the crank angle), over the book's
25 positions and over a fine sweep of the whole turn.  The crank turns clockwise
(``FI = FI - DFI``) at W1, so d/dt = -W1 d/dFI.
"""

from __future__ import annotations

import numpy as np
import pytest

import sarkp
from sarkp.book import prog_iv_15 as prog

CARD = prog.CARD
W1 = CARD["W1"]
O1 = (0.0, -CARD["C"])
F = (CARD["ROF"], 0.0)
LENGTH = max(CARD[k] for k in ("ROA", "RAB", "RBF", "RCF", "RFG", "RCD", "ROM", "ROF")) \
    + CARD["C"] + CARD["D"]

H = 1e-3                                             # step of the difference quotients, rad
STENCIL = (-2, -1, 1, 2)
WEIGHTS = np.array([1.0, -8.0, 8.0, -1.0]) / (12.0 * H)
RTOL = 1e-8


def book_angles():
    return prog.crank_angles()


def fine_angles():
    return np.linspace(0.0, -2.0 * np.pi, 1441)[:-1] - 1e-3 * np.pi   # off the grid


SWEEPS = {"book": book_angles, "fine": fine_angles}


def e(angle):
    return np.array([np.cos(angle), np.sin(angle)])


def vec(modulus, angle):
    return modulus * e(angle)


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def rot(w, r):
    """w k x r for a signed scalar w and a planar vector r."""
    return w * np.array([-r[1], r[0]])


def point(t, x, y):
    return np.array([t[x], t[y]])


@pytest.fixture(scope="module", params=sorted(SWEEPS))
def tables(request):
    """The program at the sweep's angles and at the 4 shifted stencils (corrected mode)."""
    assert sarkp.get_mode() == "corrected"
    fi = SWEEPS[request.param]()
    n = fi.size
    allfi = np.concatenate([fi] + [fi + j * H for j in STENCIL])
    t = prog.compute(angles=allfi)
    base = {k: v[:n] for k, v in t.items()}
    shifted = [{k: v[(i + 1) * n:(i + 2) * n] for k, v in t.items()} for i in range(4)]
    return base, shifted


def ddt(shifted, base, f, angle=False):
    """d f/dt from the stencil, f(table) -> array; ``angle``: differences taken mod 2 pi."""
    f0 = f(base)
    total = 0.0
    for w, t in zip(WEIGHTS, shifted):
        d = f(t) - f0
        if angle:
            d = (d + np.pi) % (2.0 * np.pi) - np.pi
        total = total + w * d
    return -W1 * total                                # clockwise crank: dFI/dt = -W1


def along(t, mod, ang, axis):
    """The signed component of the vector (mod, ang) along the direction ``axis``."""
    return t[mod] * np.cos(t[ang] - t[axis])


def assert_close(numeric, analytic, what):
    numeric, analytic = np.asarray(numeric), np.asarray(analytic)
    scale = max(np.max(np.abs(analytic)), np.max(np.abs(numeric)), 1e-300)
    err = np.max(np.abs(numeric - analytic))
    assert err <= RTOL * scale, f"{what}: max error {err:.3e} vs scale {scale:.3e}"


# --------------------------------------------------------------------------------------
# the sweep of the book
# --------------------------------------------------------------------------------------

def test_book_sweep_is_25_positions_clockwise():
    for mode in sarkp.MODES:
        with sarkp.mode(mode):
            fi = prog.crank_angles()
            assert fi.size == 25
            assert fi[0] == 0.0
            assert np.all(np.diff(fi) < 0)
            assert abs(fi[-1] + 2.0 * np.pi) < 1e-4         # -2 PI, within the book's PI
    fi = prog.crank_angles()
    np.testing.assert_allclose(fi, -np.arange(25) * np.pi / 12.0, rtol=0, atol=1e-15)


def test_as_printed_accumulates_the_crank_angle_in_real4():
    with sarkp.as_printed():
        fi = prog.crank_angles()
        # PI = 3.14159, DFI = 2 PI/24; REAL*4 truncation loses < 1 ulp (1e-6) per step
        np.testing.assert_allclose(fi, -np.arange(25) * (2 * 3.14159 / 24.0), atol=1e-5)
        assert fi[1] != -2 * 3.14159 / 24.0


# --------------------------------------------------------------------------------------
# loop closure of every group
# --------------------------------------------------------------------------------------

def test_every_group_closes(tables):
    t, _ = tables
    tol = 1e-12 * LENGTH
    A, B, C = point(t, "XA", "YA"), point(t, "XB", "YB"), point(t, "XC", "YC")
    D, Hh, M = point(t, "XD", "Y"), point(t, "XH", "YH"), point(t, "XM", "YM")
    P = point(t, "XP", "YP")
    f, o1 = np.array(F)[:, None], np.array(O1)[:, None]
    checks = {
        # crank
        "OA": np.hypot(*A) - CARD["ROA"], "OM": np.hypot(*M) - CARD["ROM"],
        "A, M opposite": A / CARD["ROA"] + M / CARD["ROM"],
        # kind 1: A-B-F
        "B = A + RAB e(FI2)": B - A - vec(CARD["RAB"], t["FI2"]),
        "B = F + RBF e(FI3)": B - f - vec(CARD["RBF"], t["FI3"]),
        # C, H on link 3
        "C on FB": C - f - vec(CARD["RCF"], t["FI3"]),
        "H on FB": Hh - f - vec(CARD["RFG"], t["FI3"]),
        # kind 2: C-D, D on y = A
        "D = C + RCD e(FI4)": D - C - vec(CARD["RCD"], t["FI4"]),
        "D on the guide": t["Y"] - CARD["A"],
        # kind 5: H = (SGL, SGH): yoke along y = 0, block along the vertical slot
        "H = SGL e(0) + SGH e(PI/2)": Hh - np.array([t["SGL"], t["SGH"]]),
        # kind 3: M on the axis of link 9 through O1
        "M = O1 + RO1M e(FIO1M)": M - o1 - vec(t["RO1M"], t["FIO1M"]),
        "M on axis FI9": cross(M - o1, e(t["FI9"])),
        # kind 4: P on link 9 and on y = -(C + D)
        "P = O1 + RO1P e(FIO1P)": P - o1 - vec(t["RO1P"], t["FIO1P"]),
        "P on axis FI9": cross(P - o1, e(t["FI9"])),
        "P on the guide": t["YP"] + CARD["C"] + CARD["D"],
        "P = RV e(FV)": P - vec(t["RV"], t["FV"]),
    }
    for what, residual in checks.items():
        err = np.max(np.abs(residual))
        assert err <= tol, f"{what}: {err:.3e}"
    assert np.all(t["RO1M"] > 0) and np.all(t["RO1P"] > 0)


# --------------------------------------------------------------------------------------
# velocities = d(positions)/dt
# --------------------------------------------------------------------------------------

def test_velocities_are_time_derivatives_of_positions(tables):
    t, s = tables
    o1 = np.array(O1)[:, None]
    pos = {name: (lambda x, y: (lambda u: point(u, x, y)))(*xy) for name, xy in {
        "A": ("XA", "YA"), "B": ("XB", "YB"), "C": ("XC", "YC"), "D": ("XD", "Y"),
        "H": ("XH", "YH"), "M": ("XM", "YM"), "P": ("XP", "YP")}.items()}
    v = {name: ddt(s, t, f) for name, f in pos.items()}
    # the inputs of the program: crank points
    assert_close(v["A"], vec(W1 * CARD["ROA"], t["FI"] - np.pi / 2), "v_A")
    assert_close(v["M"], vec(W1 * CARD["ROM"], t["FI"] + np.pi / 2), "v_M")
    # kind 1
    assert_close(ddt(s, t, lambda u: u["FI2"], angle=True), t["W2"], "W2 = dFI2/dt")
    assert_close(ddt(s, t, lambda u: u["FI3"], angle=True), t["W3"], "W3 = dFI3/dt")
    assert_close(v["B"], vec(t["VB"], t["ALB"]), "v_B")
    assert_close(v["B"] - v["A"], vec(t["VBA"], t["ALBA"]), "v_BA")
    assert_close(v["B"], vec(t["VBF"], t["ALBF"]), "v_BF")
    assert_close(v["C"], vec(t["VC"], t["ALC"]), "v_C")
    # kind 2
    assert_close(ddt(s, t, lambda u: u["FI4"], angle=True), t["W4"], "W4 = dFI4/dt")
    assert_close(v["D"], vec(t["VD"], t["ALD"]), "v_D")
    assert_close(v["D"] - v["C"], vec(t["VDC"], t["ALDC"]), "v_DC")
    assert_close(v["D"], vec(t["VDE"], t["ALDE"]), "v_DE (fixed guide)")
    # kind 5: G, the yoke's point at H, moves along x only; G relative to H along y
    vg = np.array([v["H"][0], np.zeros_like(v["H"][0])])
    assert_close(ddt(s, t, lambda u: u["SGL"]) * e(0.0 * t["FI"]), vec(t["VGL"], t["ALGL"]),
                 "v_GL = d(SGL)/dt along the guide")
    assert_close(-ddt(s, t, lambda u: u["SGH"]) * e(np.pi / 2 + 0.0 * t["FI"]),
                 vec(t["VGH"], t["ALGH"]), "v_GH = -d(SGH)/dt along the slot")
    assert_close(vg, vec(t["VG"], t["ALG"]), "v_G")
    assert_close(vg, vec(t["VGL"], t["ALGL"]), "v_GL (fixed guide)")
    assert_close(vg - v["H"], vec(t["VGH"], t["ALGH"]), "v_GH")
    # kind 3: N is the point of link 9 under M
    rm = point(t, "XM", "YM") - o1
    assert_close(ddt(s, t, lambda u: u["FI9"], angle=True), t["W9"], "W9 = dFI9/dt")
    vn = rot(t["W9"], rm)
    assert_close(vn, vec(t["VN"], t["ALN"]), "v_N")
    assert_close(vn, vec(t["VNO1"], t["ALNO1"]), "v_NO1 (fixed O1)")
    assert_close(vn - v["M"], vec(t["VNM"], t["ALNM"]), "v_NM")
    assert_close(-ddt(s, t, lambda u: u["RO1M"]) * e(t["FIO1M"]),
                 vec(t["VNM"], t["ALNM"]), "v_NM = -d(O1M)/dt along O1M")
    # kind 4: P slides along link 9 and along the fixed guide
    rp = point(t, "XP", "YP") - o1
    assert_close(v["P"], vec(t["VP"], t["ALP"]), "v_P")
    assert_close(v["P"] - rot(t["W9"], rp), vec(t["VPM"], t["ALPM"]), "v_PM")
    assert_close(ddt(s, t, lambda u: u["RO1P"]) * e(t["FIO1P"]), vec(t["VPM"], t["ALPM"]),
                 "v_PM = d(O1P)/dt along O1P")
    assert_close(v["P"], vec(t["VPN"], t["ALPN"]), "v_PN (fixed guide)")


# --------------------------------------------------------------------------------------
# accelerations = d(velocities)/dt
# --------------------------------------------------------------------------------------

def test_accelerations_are_time_derivatives_of_velocities(tables):
    t, s = tables
    o1, f = np.array(O1)[:, None], np.array(F)[:, None]
    A, B, C = point(t, "XA", "YA"), point(t, "XB", "YB"), point(t, "XC", "YC")
    D, M, P = point(t, "XD", "Y"), point(t, "XM", "YM"), point(t, "XP", "YP")

    def dv(mod, ang):
        return ddt(s, t, lambda u: vec(u[mod], u[ang]))

    # kind 1
    for w, eps in (("W2", "E2"), ("W3", "E3")):
        assert_close(ddt(s, t, lambda u: u[w]), t[eps], f"{eps} = d{w}/dt")
    assert_close(dv("VB", "ALB"), vec(t["AB"], t["BB"]), "a_B")
    assert_close(rot(t["E2"], B - A), vec(t["ABAT"], t["BBAT"]), "a^t_BA")
    assert_close(rot(t["E3"], B - f), vec(t["ABFT"], t["BBFT"]), "a^t_BF")
    assert_close(dv("VC", "ALC"), vec(t["AC"], t["BC"]), "a_C")
    # kind 2
    assert_close(ddt(s, t, lambda u: u["W4"]), t["E4"], "E4 = dW4/dt")
    assert_close(dv("VD", "ALD"), vec(t["AD"], t["BD"]), "a_D")
    assert_close(rot(t["E4"], D - C), vec(t["ADCT"], t["BDCT"]), "a^t_DC")
    assert_close(dv("VD", "ALD"), vec(t["ADE"], t["BDE"]), "a_DE (fixed guide)")
    # kind 5
    assert_close(dv("VG", "ALG"), vec(t["AG"], t["BG"]), "a_G")
    assert_close(dv("VG", "ALG"), vec(t["AGL"], t["BGL"]), "a_GL (fixed guide)")
    assert_close(dv("VGH", "ALGH"), vec(t["AGH"], t["BGH"]), "a_GH (translating yoke)")
    # kind 3: N3 is the point of link 9 at M (a different material point at each
    # instant, so a_N is not dv_N/dt): a_N = E9 k x r - W9**2 r
    rm = M - o1
    assert_close(ddt(s, t, lambda u: u["W9"]), t["E9"], "E9 = dW9/dt")
    assert_close(rot(t["E9"], rm) - t["W9"]**2 * rm, vec(t["AN"], t["BN"]), "a_N")
    assert_close(rot(t["E9"], rm), vec(t["ANO1T"], t["BNO1T"]), "a^t_NO1")
    # relative acceleration along the axis = d/dt of the signed relative speed
    assert_close(ddt(s, t, lambda u: along(u, "VNM", "ALNM", "FIO1M")) * e(t["FIO1M"]),
                 vec(t["ANM"], t["BNM"]), "a^r_NM")
    # kind 4
    rp = P - o1
    assert_close(dv("VP", "ALP"), vec(t["AP"], t["BP"]), "a_P")
    assert_close(dv("VP", "ALP"), vec(t["APS"], t["BPS"]), "a_PS (fixed guide)")
    assert_close(ddt(s, t, lambda u: along(u, "VPM", "ALPM", "FIO1P")) * e(t["FIO1P"]),
                 vec(t["APR"], t["BPR"]), "a^r_PR")
    # the whole of kind 4 about link 9: a_P = a_P9 + a^k + a^r
    ap9 = rot(t["E9"], rp) - t["W9"]**2 * rp
    ak = rot(2.0 * t["W9"], vec(t["VPM"], t["ALPM"]))
    assert_close(ap9 + ak + vec(t["APR"], t["BPR"]), vec(t["AP"], t["BP"]),
                 "a_P = a_P9 + a^k + a^r")


# --------------------------------------------------------------------------------------
# the two modes
# --------------------------------------------------------------------------------------

#: Columns that depend on DUSKR1's E3 (as printed, ABCT = ABS(Y(1)): ERRATA E-DUSKR1-1).
VECTORS = (("VBA", "ALBA"), ("VB", "ALB"), ("VDC", "ALDC"), ("VD", "ALD"), ("ANM", "BNM"),
           ("AN", "BN"), ("APR", "BPR"), ("AP", "BP"), ("ANO1T", "BNO1T"), ("AB", "BB"),
           ("AD", "BD"), ("AGH", "BGH"), ("AG", "BG"), ("VGH", "ALGH"), ("VG", "ALG"),
           ("VNM", "ALNM"), ("VN", "ALN"), ("VPM", "ALPM"), ("VP", "ALP"))
E3_COLUMNS = ("E3", "AC", "BC", "E4", "AD", "BD", "AGH", "BGH", "AG", "BG", "ABFT", "BBFT")


def test_as_printed_differs_from_corrected_only_by_pi_and_duskr1():
    corrected = prog.compute()
    with sarkp.as_printed():
        printed = prog.compute()
    assert sarkp.get_mode() == "corrected"
    pairs = {m: a for m, a in VECTORS}
    angles = set(pairs.values())
    for name in prog.COLUMNS:
        if name in angles:
            continue                                  # compared with its modulus below
        if name in pairs:                             # a vector: compare components
            diff = np.abs(vec(printed[name], printed[pairs[name]])
                          - vec(corrected[name], corrected[pairs[name]])).max(axis=0)
        else:
            diff = np.abs(printed[name] - corrected[name])
            diff = np.minimum(diff, np.abs(diff - 2 * np.pi))   # an angle may wrap
        scale = max(1.0, np.abs(corrected[name]).max())
        if name in E3_COLUMNS:
            assert diff.max() > 0.1, name                       # E-DUSKR1-1 shows
        else:
            assert diff.max() < 1e-4 * scale, (name, diff.max())  # PI = 3.14159 only
    assert abs(printed["E3"][0] - corrected["E3"][0]) > 1.0


def test_first_positions_agree_with_an_independent_port():
    """The reading notes (book-ch4.md section 4.7) ran a separate float64 port of the
    cleaned listing with PI = 3.14159 and the corrected DUSKR1 and DUSKR4, and also gave
    the 4th line of FI = 0 with the book-literal DUSKR1.  Not book data: the book prints
    nothing for IV.15."""
    notes = {
        0: "0.0000 0.8411 1.2810 0.5200 0.3354 1.0713 -0.5021 0.6888 2.0215 0.1306 0.2999 5.1630",
        1: "0.000 0.990 2.412 0.770 2.852 2.200 2.200 0.359 -2.073 1.227 3.142 -0.618",
        2: "0.000 0.424 2.021 -0.973 0.678 0.304 0.078 2.021 0.278 3.142 0.670 0.451",
        3: "0.000 3.352 3.382 2.755 3.542 3.356 1.646 3.142 2.538 1.571 3.344 3.142",
        4: "0.000 0.440 -1.571 1.476 3.142 0.540 -1.120 0.261 0.451 -0.379 0.055 2.021 "
           "0.126 3.142",
        5: "-0.2618 1.1281 1.6129 0.4053 0.3497 0.8956 -0.5427 0.7554 1.9645 0.1121 "
           "0.2924 5.1061",
        6: "-0.262 0.901 2.699 0.929 3.184 2.002 2.654 0.065 1.028 1.292 3.142 0.113",
        7: "-0.262 0.554 1.964 -0.650 0.522 0.047 0.013 5.106 0.144 3.142 0.491 0.394",
        9: "-0.262 0.078 1.571 1.856 3.142 0.476 -1.177 0.366 0.394 -0.484 0.059 1.964 "
           "0.153 3.142",
    }
    with sarkp.as_printed():
        lines = prog.render().splitlines()
    for k, text in notes.items():
        assert lines[k].split() == text.split(), (k, lines[k])


@pytest.mark.parametrize("mode", sarkp.MODES)
def test_render_is_the_books_layout(mode):
    with sarkp.mode(mode):
        text = prog.render()
        table = prog.compute()
    lines = text.split("\n")
    assert len(lines) == 25 * 5                      # 25 positions, PRINT 10, 11, 11, 11, 12
    widths = {prog.FORMAT_10: 1 + 12 * 9, prog.FORMAT_11: 1 + 12 * 10,
              prog.FORMAT_12: 1 + 14 * 8}
    decimals = {prog.FORMAT_10: 4, prog.FORMAT_11: 3, prog.FORMAT_12: 3}
    for k in range(25):
        block = lines[5 * k:5 * k + 5]
        for line, (fmt, names) in zip(block, prog.PRINTS):
            assert len(line) == widths[fmt] and line[0] == " "
            assert "*" not in line                   # no field overflows
            fields = line.split()
            assert len(fields) == len(names)
            for field, name in zip(fields, names):
                assert len(field.split(".")[1]) == decimals[fmt]
                assert abs(float(field) - table[name][k]) <= 0.5 * 10.0**-decimals[fmt] + 1e-12
    assert len(prog.cells()) == 25 * len(prog.COLUMNS)
    assert prog.LISTING == "IV.15" and prog.FIGURES == ()


def test_a_card_that_cannot_be_assembled_raises():
    # corrected mode: the Mechanism names the group by its new joint and the angle
    with pytest.raises(sarkp.AssemblyError, match=r"group rrp 'D' .*does not assemble at "
                                                  r"phi = 0\.0"):
        prog.compute(card={"RCD": 0.1})
    # as printed: the book's call sequence, the routine names itself
    with sarkp.as_printed(), pytest.raises(sarkp.AssemblyError, match="DPRM2"):
        prog.compute(card={"RCD": 0.1})


#: The columns of each group (the crank's FI, XA, YA, XM, YM belong to none).
GROUP_COLUMNS = {
    "B": "FI2 FI3 XB YB XC YC XH YH VBA ALBA VBF ALBF VB ALB W2 W3 VC ALC ABAT BBAT ABFT "
         "BBFT AB BB E2 E3 AC BC",
    "D": "XD Y FI4 VDC ALDC VDE ALDE VD ALD W4 ADCT BDCT ADE BDE E4 AD BD",
    "K": "SGL SGH VGH ALGH VGL ALGL VG ALG AGH BGH AGL BGL AG BG",
    "N": "RO1M FI9 FIO1M VNM ALNM VNO1 ALNO1 VN ALN W9 ANM BNM ANO1T BNO1T E9 AN BN",
    "P": "XP YP RO1P FIO1P RV FV VPM ALPM VPN ALPN VP ALP APR BPR APS BPS AP BP",
}


def test_the_group_columns_cover_every_variable():
    named = [k for cols in GROUP_COLUMNS.values() for k in cols.split()]
    assert sorted(named + ["FI", "XA", "YA", "XM", "YM"]) == sorted(prog.compute())
    assert set(GROUP_COLUMNS) == set(prog.GROUPS)


@pytest.mark.parametrize("card, failing", [({"RCD": 0.1}, "D"),      # the slider's rod
                                           ({"RAB": 0.05}, "B")])    # the four-bar
def test_a_failing_group_leaves_the_groups_before_it_and_beside_it(card, failing):
    """Under on_error="nan", where a group does not assemble its variables and those of
    the groups built on it (GROUPS) are NaN; the crank, the groups it stands on and the
    groups on other branches keep their values -- the same as the book's call sequence
    gives, and the same as a solve of the positions where everything assembles."""
    fi = fine_angles()[::8]
    t = prog.compute(card=card, angles=fi, on_error="nan")
    bad = np.isnan(t["X" + failing])
    assert bad.any() and not bad.all()
    after = {g for g, needs in prog.GROUPS.items() if failing in needs}
    assert after == ({"D"} if failing == "D" else {"B", "D", "K"})
    for g, cols in GROUP_COLUMNS.items():
        for k in cols.split():
            if g in after:
                assert np.isnan(t[k][bad]).all() and np.isfinite(t[k][~bad]).all(), k
            else:
                assert np.isfinite(t[k]).all(), k
    # the same NaN as the book's call sequence (one chapter 4 routine per group)
    ref = prog.compute_by_groups(card=card, angles=fi, on_error="nan")
    for k in t:
        assert np.array_equal(np.isnan(t[k]), np.isnan(ref[k])), k
    # the positions that assemble: the values of a solve of those positions alone
    good = prog.compute(card=card, angles=fi[~bad])
    for k in t:
        np.testing.assert_array_equal(t[k][~bad], good[k], err_msg=k)
