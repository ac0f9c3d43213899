"""The book's programs on sarkp.Mechanism: program X's six-bar (x_mechanism), IV.15's
and VII.10's mechanism of Fig. 29/57 (kinds 1-5), against their group-by-group corrected
paths (the chapter 4 and 7 routines called one group at a time), to 1e-13 relative;
IV.15's corrected compute() is the Mechanism path, read as the book's variables."""

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
        t = prog_iv_15.compute_by_groups()
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
        t = prog_vii_10.compute_by_groups()
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


# -- IV.15's corrected compute(): one Mechanism solve, the book's variables ---------------

#: (modulus, direction) pairs of IV.15's velocities and accelerations
IV15_VECTORS = (
    ("VBA", "ALBA"), ("VBF", "ALBF"), ("VB", "ALB"), ("VC", "ALC"), ("VDC", "ALDC"),
    ("VDE", "ALDE"), ("VD", "ALD"), ("VGH", "ALGH"), ("VGL", "ALGL"), ("VG", "ALG"),
    ("VNM", "ALNM"), ("VNO1", "ALNO1"), ("VN", "ALN"), ("VPM", "ALPM"), ("VPN", "ALPN"),
    ("VP", "ALP"), ("ABAT", "BBAT"), ("ABFT", "BBFT"), ("AB", "BB"), ("AC", "BC"),
    ("ADCT", "BDCT"), ("ADE", "BDE"), ("AD", "BD"), ("AGH", "BGH"), ("AGL", "BGL"),
    ("AG", "BG"), ("ANM", "BNM"), ("ANO1T", "BNO1T"), ("AN", "BN"), ("APR", "BPR"),
    ("APS", "BPS"), ("AP", "BP"))


@pytest.mark.parametrize("card", [{}, {"ROA": 0.2, "RCD": 0.7, "ROM": 0.35}])
@pytest.mark.parametrize("sweep", ["book", "fine"])
def test_iv15_compute_from_the_mechanism_agrees_with_the_groups(card, sweep):
    """Every variable of corrected compute() (the Mechanism) against the book's call
    sequence (compute_by_groups): numbers to 1e-13 of their column's scale, link angles
    in the routines' ranges (DPRM1's FI2, FI3 up to 3 pi, DUGOL's FIO1P, FV), each
    (modulus, direction) pair as a vector to 1e-13 of its largest modulus and its
    direction on the routine's branch (DUGL3: FI +- pi/2, DUGL4: FIM or FIM - pi, DUGL5:
    (-pi/2, 3 pi/2)) wherever the vector is not zero to rounding."""
    fi = (prog_iv_15.crank_angles() if sweep == "book"
          else np.linspace(0.0, -2.0 * math.pi, 1441) - 1e-3)
    t = prog_iv_15.compute(card, angles=fi)
    g = prog_iv_15.compute_by_groups(card, angles=fi)
    assert t.keys() == g.keys()
    directions = {d for _, d in IV15_VECTORS}
    for name in t:
        if name in directions:
            continue
        scale = max(np.max(np.abs(g[name])), 1e-300)
        err = np.max(np.abs(t[name] - g[name]))
        assert err <= TOL * scale, (name, err, scale)
    for mod, ang in IV15_VECTORS:
        scale = np.max(g[mod])
        assert close(polar(t, mod, ang), polar(g, mod, ang), scale), mod
        seen = g[mod] > 1e-9 * scale                      # a direction to compare
        diff = np.abs(t[ang] - g[ang])[seen]
        # DUGL5 gives -pi/2 for x = 0 exactly, the Mechanism's x is a rounding's -0
        ends = np.isclose(g[ang][seen], -math.pi / 2, rtol=0, atol=1e-12) & \
            np.isclose(t[ang][seen], 1.5 * math.pi, rtol=0, atol=1e-12)
        assert np.all((diff <= 1e-9) | ends), (ang, diff.max())


def test_iv15_compute_is_one_solve(monkeypatch):
    from sarkp.mechanism import Mechanism
    calls = []
    solve = Mechanism.solve

    def counted(self, *args, **kwargs):
        calls.append(args[0])
        return solve(self, *args, **kwargs)
    monkeypatch.setattr(Mechanism, "solve", counted)
    t = prog_iv_15.compute()
    assert len(calls) == 1 and np.array_equal(calls[0], t["FI"])
    with sarkp.as_printed():
        prog_iv_15.compute()                       # the book's call sequence: no solve
    assert len(calls) == 1


# -- r.animate(path) as MP4 (program X's six-bar) ------------------------------------------

def _x_sweep(n=6):
    with sarkp.mode("corrected"):
        links = prog_x.synthesis()
        return x_mechanism.mechanism(links).solve(np.linspace(0, 2 * math.pi, n),
                                                  need="positions")


def test_animate_writes_an_mp4(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    from matplotlib import animation
    if not animation.FFMpegWriter.isAvailable():
        pytest.skip("ffmpeg is not installed (Debian: apt-get install ffmpeg)")
    import shutil
    import subprocess
    out = _x_sweep(6).animate(tmp_path / "six.mp4", fps=5)
    with open(out, "rb") as f:
        head = f.read(12)
    assert head[4:8] == b"ftyp"                    # an ISO base media (MP4) file
    ffprobe = shutil.which("ffprobe")
    if ffprobe:
        frames = subprocess.run(
            [ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0",
             "-show_entries", "stream=nb_read_frames,codec_type", "-of", "csv=p=0", out],
            capture_output=True, text=True, check=True).stdout.split(",")
        assert frames[0] == "video" and int(frames[1]) == 6


def test_animate_without_ffmpeg_names_it(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    import matplotlib
    monkeypatch.setitem(matplotlib.rcParams, "animation.ffmpeg_path",
                        str(tmp_path / "no-such-ffmpeg"))
    r = _x_sweep(3)
    with pytest.raises(RuntimeError, match="needs ffmpeg.*apt-get install ffmpeg"):
        r.animate(tmp_path / "six.mp4")
    assert not (tmp_path / "six.mp4").exists()


# -- VII.10's corrected compute(): the force solve of the loaded Mechanism ----------------

VII10_INERTIA = {"M2": 5.1, "J2": 0.09, "M3": 8.0, "J3": 0.25, "M4": 6.0, "J4": 0.17,
                 "M5": 4.0, "M7": 10.2, "M9": 7.5, "J9": 0.12, "M11": 3.0}


@pytest.mark.parametrize("inertia", [None, VII10_INERTIA])
@pytest.mark.parametrize("card", [{}, {"ROA": 0.2, "RCD": 0.7, "ROM": 0.35, "FS2": 700.0}])
def test_vii10_compute_from_the_mechanism_agrees_with_the_groups(card, inertia):
    """Every force variable of corrected compute() (a Mechanism force solve) against the
    book's call sequence (compute_by_groups: DNMAF1-5 one group at a time): moduli,
    arms H, moments and MY to 1e-13 of their column's scale, each reaction as a vector
    to 1e-13 of its largest modulus and its direction on the routine's branch (DSMVKT's
    DUGL5, DUGL5 - pi, DUGL3(FIM, PI/2, F) - PI) wherever the force is not zero; the two
    ends of DUGL5's range (-pi/2, 3 pi/2) name the same direction of a vertical force."""
    fi = np.concatenate([prog_iv_15.crank_angles(),
                         np.linspace(0.0, -2.0 * math.pi, 361) - 1e-3])
    t = prog_vii_10.compute(card, angles=fi, inertia=inertia)
    g = prog_vii_10.compute_by_groups(card, angles=fi, inertia=inertia)
    assert t.keys() == g.keys()
    forces = [k for k in prog_vii_10.COLUMNS if k[0] == "F" and k != "FI"] + ["F3", "F9"]
    for name in forces + [k for k in prog_vii_10.COLUMNS if k[0] == "H"] + \
            ["TM3", "TM9", "MY", "TMR", "FC1", "FC2", "FC3"]:
        scale = max(np.max(np.abs(g[name])), 1e-300)
        assert np.max(np.abs(t[name] - g[name])) <= TOL * scale, name
    for f in forces:
        ang = "G" + f[1:]
        scale = np.max(g[f])
        assert close(polar(t, f, ang), polar(g, f, ang), scale), f
        seen = g[f] > 1e-9 * scale
        a, b = t[ang][seen], g[ang][seen]
        ends = np.isclose(np.minimum(a, b), -math.pi / 2, rtol=0, atol=1e-12) & \
            np.isclose(np.abs(a - b), 2 * math.pi, rtol=0, atol=1e-12)
        assert np.all((np.abs(a - b) <= 1e-9) | ends), (ang, np.abs(a - b).max())


def test_link_angles_stay_defined_where_the_mechanism_assembles():
    """on_error="nan": r.angle is NaN where the mechanism does not assemble and the link's
    direction where it does (np.unwrap over the sweep once spread one NaN to every later
    position)."""
    fi = -np.linspace(0.0, 4.0 * math.pi, 97)
    r = prog_iv_15.mechanism({"RCD": 0.1}).solve(fi, omega=-2.0, on_error="nan")
    bad = r.status != 0
    assert bad.any() and not bad.all()
    for p, q in (("F", "B"), ("O1", "N"), ("A", "B")):
        a = r.angle(p, q)
        assert np.isnan(a[bad]).all() and np.isfinite(a[~bad]).all()
        d = r.position(q) - r.position(p)
        assert same_angle(a[~bad], np.arctan2(d[~bad, 1], d[~bad, 0]))
