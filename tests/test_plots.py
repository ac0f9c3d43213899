"""The pictures (sarkp.plot, the book programs' ``plots()``) and ``sarkp book run --plots``.

Every picture of ``book run X``, V.5, V.5-FLAT, VI.6 and VII.10 is drawn in both modes and
checked on matplotlib's own objects (no image comparison): every axis labelled, no two
texts overlapping, every text inside the figure, legends off the drawing, no markers on
hundreds of points, the mode in the title.  The command line checks its arguments
before it runs anything and fails in one line with status 2.
"""

from __future__ import annotations

import itertools
import math
import struct
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import sarkp
from sarkp.cli import main

matplotlib = pytest.importorskip("matplotlib")
from sarkp import plot  # noqa: E402  (needs matplotlib)

PROGRAMS = ("X", "V.5", "V.5-FLAT", "VI.6", "VI.7", "VII.10")
MAGIC = {"png": b"\x89PNG\r\n\x1a\n", "pdf": b"%PDF-", "svg": b"<?xml"}


# ---- the checks of a drawing-sheet figure ----------------------------------------------------

def _texts(figure):
    """The texts matplotlib draws: visible, not empty, not the label of a tick outside
    its axis' view (those are kept but not drawn)."""
    from matplotlib.text import Text
    hidden = set()
    for ax in figure.axes:
        for axes in [ax, *ax.child_axes]:
            for axis in (axes.xaxis, axes.yaxis):
                lo, hi = sorted(axis.get_view_interval())
                slack = 1e-9 * max(abs(lo), abs(hi), 1.0)
                for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                    if not lo - slack <= tick.get_loc() <= hi + slack:
                        hidden.update((id(tick.label1), id(tick.label2)))
    return [t for t in figure.findobj(Text)
            if t.get_visible() and t.get_text().strip() and id(t) not in hidden]


def sheet_problems(figure) -> list:
    """What keeps ``figure`` off a drawing sheet (an empty list when nothing does)."""
    figure.draw_without_rendering()
    renderer = figure.canvas.get_renderer()
    problems = []
    for ax in figure.axes:
        if not ax.get_visible():
            continue
        if not ax.get_xlabel().strip() or not ax.get_ylabel().strip():
            problems.append(f"axes without a label: x {ax.get_xlabel()!r}, "
                            f"y {ax.get_ylabel()!r}")
        for child in ax.child_axes:                 # the book's position numbers on top
            if not child.get_xlabel().strip():
                problems.append("secondary axis without a label")
        for line in ax.get_lines():
            if line.get_marker() not in (None, "None", "", " ") and len(line.get_xdata()) > 60:
                problems.append(f"markers on all {len(line.get_xdata())} points of "
                                f"{line.get_label()!r}")
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in _texts(figure)]
    whole = figure.bbox
    for text, box in boxes:
        if (box.x0 < whole.x0 - 1 or box.x1 > whole.x1 + 1 or box.y0 < whole.y0 - 1
                or box.y1 > whole.y1 + 1):
            problems.append(f"text cut off by the figure's edge: {text!r}")
    for (t1, b1), (t2, b2) in itertools.combinations(boxes, 2):
        # a pixel of slack: glyph boxes of neighbouring tick labels may touch
        if b1.padded(-1).overlaps(b2.padded(-1)):
            problems.append(f"texts overlap: {t1!r} and {t2!r}")
    for ax in figure.axes:
        legend = ax.get_legend()
        if legend is None:
            continue
        lb = legend.get_window_extent(renderer)
        for other in figure.axes:
            if other.get_visible() and lb.padded(-1).overlaps(other.get_window_extent(renderer)):
                first = legend.get_texts()[0].get_text()
                problems.append(f"a legend covers the drawing: {first!r}")
    return problems


def _title(figure) -> str:
    parts = [figure._suptitle.get_text() if figure._suptitle else ""]
    parts += [ax.get_title(loc) for ax in figure.axes for loc in ("center", "left")]
    return " ".join(parts).replace("\n", " ").replace("\N{NO-BREAK SPACE}", " ")


def _caption(figure) -> str:
    return figure._supxlabel.get_text() if figure._supxlabel else ""


@pytest.fixture(scope="module")
def pictures(tmp_path_factory):
    """{(program, mode): {name: Figure}} for every picture the programs draw, through
    ``sarkp book run PROGRAM --plots DIR --mode MODE --dpi 50`` (plot.save recorded);
    ``drawn["dirs"][program, mode]`` is the DIR."""
    drawn = {"dirs": {}}
    save = plot.save
    current = {}

    def recording(figure, path, **kw):
        written = save(figure, path, **kw)
        current[written.stem] = figure
        return written
    plot.save = recording
    try:
        for program, mode in itertools.product(PROGRAMS, sarkp.modes.MODES):
            current = {}
            out = tmp_path_factory.mktemp("p")
            assert main(["book", "run", program, "--plots", str(out), "--mode", mode,
                         "--dpi", "50"]) == 0
            drawn[program, mode] = current
            drawn["dirs"][program, mode] = out
    finally:
        plot.save = save
    return drawn


@pytest.mark.parametrize("mode", sarkp.modes.MODES)
@pytest.mark.parametrize("program", PROGRAMS)
def test_every_picture_is_a_drawing_sheet(pictures, program, mode, capsys):
    capsys.readouterr()
    figures = pictures[program, mode]
    assert figures, "no pictures drawn"
    for name, figure in figures.items():
        assert sheet_problems(figure) == [], name
        title = _title(figure)
        assert ("AS PRINTED" in title) == (mode == "as-printed"), (name, title)


def test_program_x_pictures_say_what_the_book_got_wrong(pictures):
    printed = pictures["X", "as-printed"]
    assert "E-DUSKR1-1" in _caption(printed["x_accelerations"])
    assert "E-X-W4" in _caption(printed["x_accelerations"])
    corrected = pictures["X", "corrected"]
    assert _caption(corrected["x_accelerations"]) == ""
    # omega without a flywheel, as printed: DZKNDV's WPR changes sign -- a caveat says so
    from sarkp.book import prog_x
    with sarkp.as_printed():
        d = prog_x.run(["dynamics"])["dynamics"]
    assert d["WPR"].min() < 0 < d["WPR"].max()
    omega = printed["x_omega"]
    assert "Caveat" in omega.axes[0].get_title("left")
    assert np.array_equal(omega.axes[0].lines[0].get_ydata(), d["WPR"])
    assert np.allclose(omega.axes[0].lines[0].get_xdata(), np.degrees(d["FI1"]))
    # corrected: the machine stalls without the flywheel, only WPRM is drawn, and says why
    assert "stalls" in corrected["x_omega"].axes[0].get_title("left")
    assert len(corrected["x_omega"].axes) == 1


def test_cam_limits_are_drawn(pictures):
    """V.5: the pressure angle against its allowed +-ALFAD (degrees), the positions beyond
    it marked; rho < 0 shaded where the profile is not convex (program X's cam)."""
    from sarkp.book import prog_v_5, prog_x
    figure = pictures["V.5", "corrected"]["v5_alfa_rok"]
    ax = figure.axes[0]
    limit = math.degrees(prog_v_5.ALFAD)
    levels = sorted(line.get_ydata()[0] for line in ax.get_lines()
                    if len(set(line.get_ydata())) == 1 and line.get_ydata()[0] != 0)
    assert np.allclose(levels, [-limit, limit])
    with sarkp.mode("corrected"):
        t = prog_v_5.compute()
    beyond = np.abs(np.degrees(t["ALFA"])) > limit
    marked = [line for line in ax.get_lines() if line.get_marker() == "o"]
    assert beyond.any() and len(marked) == 1
    assert np.allclose(marked[0].get_ydata(), np.degrees(t["ALFA"])[beyond])
    # the book's cam (as printed) is concave at 7 points; the corrected design is sized
    # convex (issue 27, flat_base_radius): nothing to shade there
    corrected = pictures["X", "corrected"]["x_cam_curvature"].axes[0]
    assert not [p for p in corrected.patches if p.get_label().startswith("ρ < 0")]
    curvature = pictures["X", "as-printed"]["x_cam_curvature"].axes[0]
    with sarkp.as_printed():
        rok = prog_x.run(["cam"])["cam"]["ROK"]
    assert (rok < 0).any()
    shaded = [p for p in curvature.patches if p.get_label().startswith("ρ < 0")]
    assert len(shaded) == 1
    y = shaded[0].get_path().transformed(shaded[0].get_patch_transform()).vertices[:, 1]
    assert y.max() == 0.0 and y.min() <= rok.min()


def test_gear_mesh_is_complete(pictures):
    """VI.6 (a): both wheels with their circles in the legend, the line of action and AB,
    the contact ratio in the caption equal to DGMZPC's E."""
    figure = pictures["VI.6", "corrected"]["vi6_mesh_a"]
    labels = [t.get_text() for t in figure.axes[0].get_legend().get_texts()]
    for k in (1, 2):
        for circle in ("tip", "operating pitch", "base", "root"):
            assert any(t.startswith(f"{circle} circle {k}") for t in labels), (circle, k)
    assert any(t.startswith("line of action") for t in labels)
    r = sarkp.DGMZPC(5.0, 11, 26, 0.0, 0.5, 0.5, 0.0)
    assert f"= {r.E:.3f}" in _caption(figure).replace("\n", " ")
    names = {t.get_text() for t in _texts(figure)}
    assert {"P", "A", "B", "N1", "N2"} <= names


@pytest.mark.parametrize("row", ["a", "b"])
def test_internal_mesh_active_length_is_dgmzvn_contact_ratio(pictures, row):
    """VI.7: the active length AB, where the tip circles cut the line of action drawn
    tangent to both base circles, is DGMZVN's EALFA (its closed form) times the base
    pitch; N1 and N2 lie on the base circles; the caption shows EALFA."""
    from sarkp.book import prog_vi_7
    figure = pictures["VI.7", "corrected"][f"vi7_mesh_{row}"]
    call = prog_vi_7.CALLS[row]
    with sarkp.mode("corrected"):
        r = sarkp.DGMZVN(*call)
        g1, g2 = sarkp.DGMTZK(call[0], call[1], 0.0, call[3]), sarkp.DGMTZK(call[0], call[2],
                                                                           0.0, call[4])
    mesh = figure.mesh
    pb = math.pi * call[0] * math.cos(math.pi / 9)
    assert abs(mesh["active"] - r.EALFA * pb) < 1e-9
    o1, o2 = np.array([0.0, -r.DW1 / 2]), np.array([0.0, -r.DW2 / 2])
    assert abs(np.linalg.norm(mesh["N1"] - o1) - g1.DB / 2) < 1e-9
    assert abs(np.linalg.norm(mesh["N2"] - o2) - g2.DB / 2) < 1e-9
    assert f"= {r.EALFA:.3f}" in _caption(figure).replace("\n", " ")


# ---- the command line --------------------------------------------------------------------------

def _png_size(path):
    head = path.read_bytes()[:24]
    return struct.unpack(">II", head[16:24])


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
@pytest.mark.parametrize("args", [["V.5"], ["V.5-FLAT"], ["VI.6"], ["VI.7"], ["VII.10"],
                                  ["X", "--stage", "kinematics"], ["X", "--stage", "gears"]])
def test_plots_writes_the_files_it_promises(tmp_path, capsys, args, fmt):
    assert main(["book", "run", *args, "--plots", str(tmp_path), "--format", fmt]) == 0
    err = capsys.readouterr().err
    promised = next(line for line in err.splitlines() if line.startswith("pictures ("))
    assert promised.startswith(f"pictures (corrected mode, {fmt}): ")
    names = promised.split(": ", 1)[1].split(", ")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(names)
    for name in names:
        assert name.endswith("." + fmt)
        assert (tmp_path / name).read_bytes().startswith(MAGIC[fmt]), name
        assert f"wrote {tmp_path / name}" in err


def test_plots_of_the_whole_program_x_and_the_dpi(pictures):
    """``book run X --plots DIR --dpi 50``: every stage's pictures, at 50 dots per inch."""
    from sarkp.book import x_plots
    out = pictures["dirs"]["X", "corrected"]
    assert sorted(p.name for p in out.iterdir()) == sorted(
        n + ".png" for n in x_plots.pictures())
    assert len(x_plots.pictures()) == 13
    width, height = pictures["X", "corrected"]["x_mechanism"].get_size_inches()
    assert _png_size(out / "x_mechanism.png") == (round(width * 50), round(height * 50))


@pytest.mark.parametrize("args, message", [
    (["book", "run", "X", "--plots", "/proc/nope"], "--plots /proc/nope: cannot write there"),
    (["book", "run", "II.13", "--plots", "{tmp}"], "program II.13 has no pictures"),
    (["book", "run", "X", "--stage", "teeth", "--plots", "{tmp}"],
     "stage 'teeth' of program X has no pictures"),
    (["book", "run", "V.5", "--plots", "{file}"], "exists and is not a directory"),
    (["book", "run", "V.5", "--plots", "{tmp}", "--format", "gif"], "invalid choice: 'gif'"),
    (["book", "run", "V.5", "--plots", "{tmp}", "--dpi", "0"], "from 10 to 2400"),
    (["book", "run", "V.5", "--format", "svg"], "--format is for the pictures"),
    (["book", "run", "V.5", "--dpi", "90"], "--dpi is for the pictures"),
    (["book", "run", "V.7"], "no book program 'V.7'"),
])
def test_cli_fails_early_in_one_line(tmp_path, args, message):
    """Nothing runs (no printout) and the error is one line, status 2, no traceback."""
    (tmp_path / "f").write_text("x")
    args = [a.format(tmp=tmp_path / "d", file=tmp_path / "f") for a in args]
    done = subprocess.run([sys.executable, "-m", "sarkp", *args], capture_output=True,
                          text=True, cwd=tempfile.gettempdir())
    assert done.returncode == 2, done.stderr
    assert done.stdout == ""
    assert done.stderr.count("\n") == 1 and message in done.stderr, done.stderr
    assert done.stderr.startswith("sarkp: error: ")


def test_book_list_says_which_programs_draw(capsys):
    assert main(["book", "list"]) == 0
    lines = {line.split()[0]: line for line in capsys.readouterr().out.splitlines()}
    drawn = {p for p, line in lines.items() if line.endswith("; pictures: --plots)")}
    assert drawn == set(PROGRAMS)


def test_printout_as_printed_pictures_corrected_by_default(tmp_path, capsys):
    """Without --mode the printout is the book's (as printed) and the pictures the
    corrected design; --mode sets both."""
    assert main(["book", "run", "VI.6", "--plots", str(tmp_path)]) == 0
    default = capsys.readouterr()
    assert main(["book", "run", "VI.6", "--mode", "as-printed"]) == 0
    assert capsys.readouterr().out == default.out
    assert main(["book", "run", "VI.6", "--mode", "corrected"]) == 0
    assert capsys.readouterr().out != default.out         # the modes print differently
    assert "pictures (corrected mode, png)" in default.err
    assert main(["book", "run", "VI.6", "--plots", str(tmp_path), "--mode", "as-printed"]) == 0
    assert "pictures (as-printed mode, png)" in capsys.readouterr().err


# ---- sarkp.plot as a matplotlib user expects it ------------------------------------------------

def test_public_names():
    assert set(plot.__all__) == {"mechanism", "designs", "animate", "diagrams", "cam_profile",
                                 "cam_diagrams",
                                 "reaction_hodograph", "speed_diagram", "gear_mesh",
                                 "internal_mesh", "save",
                                 "mode_title", "FORMATS"}
    assert all(hasattr(plot, name) for name in plot.__all__)
    namespace = {}
    exec("from sarkp.plot import *", namespace)
    assert not {"np", "math", "annotations", "textwrap"} & set(namespace)


def test_functions_draw_on_the_axes_given_and_return_its_figure():
    from matplotlib.figure import Figure
    fi = np.linspace(0.0, 2 * np.pi, 361)
    r = 0.05 + 0.01 * np.sin(fi)
    calls = [
        (1, lambda ax: plot.mechanism({"O": (0.0, 0.0), "A": (np.cos(fi), np.sin(fi))},
                                      [("O", "A")], ax=ax)),
        (2, lambda ax: plot.diagrams(fi, [("y, m", {"a": fi}), ("z, s", {"b": fi})], ax=ax)),
        (1, lambda ax: plot.cam_profile(r * np.cos(fi), r * np.sin(fi), fi, ax=ax)),
        (2, lambda ax: plot.cam_diagrams(fi, r, 0.1 * np.sin(fi), ALD=0.5, ax=ax)),
        (1, lambda ax: plot.reaction_hodograph(1 + fi, fi, ax=ax)),
        (1, lambda ax: plot.speed_diagram(fi, 3 + np.sin(fi), ax=ax)),
        (1, lambda ax: plot.gear_mesh(5.0, 11, 26, 0.5, 0.5, ax=ax)),
        (1, lambda ax: plot.internal_mesh(3.0, 16, 51, 0.25, 0.25, 25, 75, 0.17, 83.8, ax=ax)),
    ]
    for panels, draw in calls:
        figure = Figure(figsize=(8, 8))
        axes = figure.subplots(panels, 1, squeeze=False)[:, 0]
        got = draw(axes[0] if panels == 1 else list(axes))
        assert got is figure
        assert all(ax.has_data() for ax in axes)
    with pytest.raises(ValueError, match="2 Axes"):
        plot.diagrams(fi, [("y, m", {"a": fi}), ("z, s", {"b": fi})], ax=axes[0])


def test_diagrams_of_361_points_have_no_markers_and_degrees():
    fi = np.linspace(0.0, 2 * np.pi, 361)
    figure = plot.diagrams(fi, [("s, m", {"s": np.sin(fi)})], degrees=True,
                           positions=np.arange(1, 362))
    line = figure.axes[0].lines[0]
    assert line.get_marker() in ("None", None, "")
    assert np.allclose(line.get_xdata(), np.degrees(fi))
    assert figure.axes[0].get_xlabel() == "crank angle φ1, °"
    assert sheet_problems(figure) == []


def test_mechanism_keeps_its_signature(tmp_path):
    """The call of the mechanism stage (positional points and links, the old keywords)."""
    phi = np.linspace(0, 2 * np.pi, 13)
    pts = {"O": (0.0, 0.0), "A": (0.1 * np.cos(phi), 0.1 * np.sin(phi)), "C": (0.4, 0.0)}
    figure = plot.mechanism(pts, [("O", "A"), ("A", "C")], fixed=("O", "C"), guide=None,
                            highlight=2, every=2, paths=("A",), title="t")
    assert figure.axes[0].get_xlabel() == "x, m" and sheet_problems(figure) == []


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_save_writes_the_format_asked(tmp_path, fmt):
    figure = plot.speed_diagram([0.0, 1.0], [1.0, 2.0])
    path = plot.save(figure, tmp_path / "a.png", format=fmt)
    assert path == tmp_path / f"a.{fmt}" and path.read_bytes().startswith(MAGIC[fmt])
    assert plot.save(figure, tmp_path / f"b.{fmt}").read_bytes().startswith(MAGIC[fmt])
    with pytest.raises(ValueError, match="format"):
        plot.save(figure, tmp_path / "c.gif")
    with pytest.raises(ValueError, match="dpi"):
        plot.save(figure, tmp_path / "c.png", dpi=float("nan"))


@pytest.mark.parametrize("draw, error, message", [
    (lambda: plot.diagrams([0.0, 1.0], [("s, m", {"s": [1.0, 2.0, 3.0]})]), ValueError,
     "the curve 's'"),
    (lambda: plot.cam_diagrams([0.0, 1.0], [1.0, 2.0], [0.1]), ValueError, "ALFA has 1"),
    (lambda: plot.cam_profile([1.0, 2.0], [1.0], [0.0, 1.0]), ValueError, "YA has 1"),
    (lambda: plot.speed_diagram([[0.0, 1.0]], [1.0, 2.0]), ValueError, "phi must be 1-D"),
    (lambda: plot.speed_diagram(["a", "b"], [1.0, 2.0]), TypeError, "phi must be"),
    (lambda: plot.mechanism({"O": (0.0, 0.0), "A": ([0.0, 1.0], [0.0])}, [("O", "A")]),
     ValueError, "points\\['A'\\]"),
    (lambda: plot.mechanism({"O": (0.0, 0.0)}, [("O", "B")]), ValueError, "'B' is not"),
    (lambda: plot.cam_profile([1.0], [1.0], [0.0], follower="spring"), ValueError,
     "follower"),
    (lambda: plot.cam_profile([1.0], [1.0], [0.0], follower="roller"), ValueError,
     "roller_radius must be a number > 0"),
    (lambda: plot.cam_profile([1.0], [1.0], [0.0], roller_radius=0.1), ValueError,
     "for follower='roller'"),
])
def test_bad_input_names_the_argument(draw, error, message):
    with pytest.raises(error, match=message):
        draw()


# ---- issue 27: hodographs from a dense sweep, labels clear, bands, animation, rollers ---------

def _label_problems(figure):
    """The labels sarkp placed (joint names, position numbers) that are hidden or cover
    a drawn line (the lines' vertices and points every 2 pixels along their segments,
    in the renderer's pixels), computed here independently of sarkp.plot's own check."""
    figure.draw_without_rendering()
    renderer = figure.canvas.get_renderer()
    problems = []
    for label in getattr(figure, "_sarkp_labels", []):
        if not label.get_visible():
            problems.append(f"label {label.get_text()!r} hidden")
            continue
        box = label.get_window_extent(renderer)
        for line in label.axes.get_lines():
            if not line.get_visible() or line.get_linestyle() in ("None", "", " "):
                continue
            xy = np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float)
            d = line.get_transform().transform(xy)
            d = d[np.all(np.isfinite(d), axis=1)]
            if len(d) > 1:
                t = np.linspace(0.0, 1.0, 8)[:, None, None]
                d = (d[:-1] + t * (d[1:] - d[:-1])).reshape(-1, 2)
            inside = ((d[:, 0] > box.x0 + 1) & (d[:, 0] < box.x1 - 1)
                      & (d[:, 1] > box.y0 + 1) & (d[:, 1] < box.y1 - 1))
            if inside.any():
                problems.append(f"label {label.get_text()!r} covers {line.get_label()!r}")
    return problems


def test_sarkp_plot_is_an_attribute_and_matplotlib_stays_optional():
    code = ("import sys, sarkp; assert 'matplotlib' not in sys.modules; "
            "f = sarkp.plot.mechanism; assert 'matplotlib' not in sys.modules; "
            "print(f.__module__, 'plot' in dir(sarkp))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=tempfile.gettempdir())
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["sarkp.plot", "True"]


@pytest.mark.parametrize("name", ["21", "23", "30", "43"])
def test_program_x_hodographs_are_drawn_from_a_dense_sweep(pictures, name):
    """The curve passes through the 37 positions with DENSE - 1 points between each two
    (the forces stage run over the dense sweep); the 37 positions are marked; every
    position number 1-36 is shown (37 closes the turn on 1), clear of every text and of
    the drawn lines; a jump (FS switching) is dotted, not part of the curve."""
    from sarkp.book import prog_x, x_plots
    figure = pictures["X", "corrected"][f"x_hodograph_{name}"]
    ax = figure.axes[0]
    curve = ax.lines[0]
    x, y = np.asarray(curve.get_xdata()), np.asarray(curve.get_ydata())
    ok = np.isfinite(x)
    with sarkp.mode("corrected"):
        f = prog_x.run(["forces"])["forces"]
    px, py = f["F" + name] * np.cos(f["G" + name]), f["F" + name] * np.sin(f["G" + name])
    assert ok.sum() == 36 * x_plots.DENSE + 1
    scale = np.max(f["F" + name])
    assert np.allclose(x[ok][::x_plots.DENSE], px, atol=1e-9 * scale)
    assert np.allclose(y[ok][::x_plots.DENSE], py, atol=1e-9 * scale)
    # between two positions the dense points are the forces at the crank angles between
    with sarkp.mode("corrected"):
        kin = prog_x.kinematics(prog_x.run(["synthesis"])["synthesis"],
                                [f["FI1"][3] + 0.5 * (f["FI1"][4] - f["FI1"][3])])
        mid = prog_x.forces(prog_x.run(["synthesis"])["synthesis"], kin)
    k = 3 * x_plots.DENSE + x_plots.DENSE // 2
    assert x[ok][k] == pytest.approx(float(mid["F" + name][0] * np.cos(mid["G" + name][0])),
                                     abs=1e-9 * scale)
    marks = [line for line in ax.lines if line.get_marker() == "."]
    assert len(marks) == 1 and len(marks[0].get_xdata()) == 37
    numbers = {t.get_text() for t in _texts(figure)}
    assert {str(k) for k in range(1, 37)} <= numbers
    assert sheet_problems(figure) == []
    assert _label_problems(figure) == []
    gaps = np.flatnonzero(~ok)
    jumps = [line for line in ax.lines if line.get_linestyle() == ":"]
    assert len(jumps) == len(gaps)
    # F43's two pieces between the jumps are each under a fifth of the drawing: each is
    # drawn again enlarged in an inset, with its positions numbered there (not in the main)
    pieces = len(gaps) if abs(x[ok][-1] - x[ok][0]) < 1e-9 * scale else len(gaps) + 1
    insets = ax.child_axes
    if name == "43":
        assert pieces == 2 and len(insets) == 2
        inset_numbers = [{t.get_text() for t in inset.texts} - {""} for inset in insets]
        assert set().union(*inset_numbers) == {str(k) for k in range(1, 37)}
        assert not {t.get_text() for t in ax.texts} & set().union(*inset_numbers)
    else:
        assert insets == [] or all(c.get_xlabel().startswith("enlarged") for c in insets)


def test_vii10_two_panels_keep_their_labels_apart():
    """The docs' two hodographs side by side (ax= of our own): labels of both panels
    placed together after the second panel is drawn, none hidden, none on a text or a
    line (the right panel's numbers sat on each other and on the curve)."""
    from matplotlib.figure import Figure
    from sarkp.book import prog_vii_10
    t = prog_vii_10.compute()
    pair = Figure(figsize=(11, 6.5), layout="constrained")
    left, right = pair.subplots(1, 2)
    plot.reaction_hodograph(t["F21"], t["G21"], label="F21", ax=left, title="F21")
    plot.reaction_hodograph(t["F81"], t["G81"], label="F81", ax=right, title="F81")
    assert sheet_problems(pair) == []
    assert len(pair._sarkp_labels) == 2 * (1 + 24)
    assert _label_problems(pair) == []


@pytest.mark.parametrize("name", ["x_gear_mesh", "x_internal_mesh"])
def test_mesh_pictures_have_no_empty_band(pictures, name):
    """The drawing starts right under the title and the caption right under the legend
    (an equal-aspect drawing left a band of an inch and more under the title)."""
    figure = pictures["X", "corrected"][name]
    figure.draw_without_rendering()
    renderer = figure.canvas.get_renderer()
    ax = figure.axes[0]
    title = figure._suptitle.get_window_extent(renderer)
    drawing = ax.get_tightbbox(renderer)
    legend = ax.get_legend().get_window_extent(renderer)
    caption = figure._supxlabel.get_window_extent(renderer)
    inch = figure.dpi
    assert (title.y0 - drawing.y1) / inch < 0.3
    assert (legend.y0 - caption.y1) / inch < 0.3
    assert sheet_problems(figure) == []


def _four_bar(n=37):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.32, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3)
    return m.solve(np.linspace(0.0, 2 * np.pi, n), need="positions")


def test_animation_frames_are_drawn_as_the_plot():
    """Each frame has r.plot()'s joint names (at the joints of that frame), its title and
    its frame pivots, and is a drawing sheet (no overlapping texts, labels clear)."""
    r = _four_bar()
    still = r.plot(title="a four-bar")
    pts, links, fixed = r._drawing()
    pivots = [f for f in fixed if any(f in link for link in links)]
    figure, update, frames = plot._animation(pts, links, fixed=pivots, title="a four-bar")
    assert list(frames) == list(range(37))
    hatched = lambda fig: sum(1 for p in fig.axes[0].patches if p.get_hatch())
    for k in (0, 9, 20, 31):
        update(k)
        assert _title(figure) == _title(still)
        assert hatched(figure) == hatched(still) == 2
        names = {t.get_text(): t for t in _texts(figure)}
        for joint in ("O", "A", "B", "C"):
            assert np.allclose(names[joint].xy, r.position(joint)[k]), (joint, k)
        assert sheet_problems(figure) == [], k
        assert _label_problems(figure) == [], k


def test_animate_writes_a_gif_of_its_frames(tmp_path):
    from PIL import Image
    r = _four_bar(25)
    path = r.animate(tmp_path / "a.gif", every=8, title="four-bar")
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 4          # positions 0, 8, 16, 24


def _roller_cam(n):
    from sarkp import cams
    law = cams.motion_law("cycloidal", 0.02, np.radians(120), np.radians(60),
                          np.radians(120), W=10.0, N=n)
    return law, cams.roller_translating(n, 0.05, 0.0, 10.0, law.FI, law.A, law.V, law.S,
                                        0.01)


def test_cam_profile_draws_a_roller_follower():
    """The pitch curve, the working profile (sarkp.cams.roller_translating's XW, YW), the
    rollers along the pitch curve and the follower's roller at the highest lift, tangent
    to the working profile there."""
    from matplotlib.patches import Circle
    law, p = _roller_cam(181)
    figure = plot.cam_profile(p.XA, p.YA, law.FI, follower="roller", roller_radius=0.01,
                              working=(p.XW, p.YW))
    ax = figure.axes[0]
    k = int(np.argmax(np.hypot(p.XA, p.YA)))
    c, s = np.cos(law.FI[k]), np.sin(law.FI[k])
    turn = lambda x, y: (c * x - s * y, s * x + c * y)
    by_label = {line.get_label(): line for line in ax.lines}
    working = next(v for n, v in by_label.items() if n.startswith("working profile"))
    pitch = by_label["pitch curve (the roller's centre)"]
    assert np.allclose(working.get_xdata(), turn(p.XW, p.YW)[0], atol=1e-15)
    assert np.allclose(pitch.get_ydata(), turn(p.XA, p.YA)[1], atol=1e-15)
    rollers = [q for q in ax.patches if isinstance(q, Circle)]
    assert len(rollers) > 20 and all(q.get_radius() == 0.01 for q in rollers)
    follower = next(q for q in rollers if q.get_edgecolor()[:3] != (0.6, 0.6, 0.6))
    centre = np.array(follower.center)
    assert np.allclose(centre, turn(p.XA[k], p.YA[k]), atol=1e-15)
    contact = next(t for t in _texts(figure) if t.get_text() == "contact point")
    assert np.linalg.norm(np.array(contact.xy) - centre) == pytest.approx(0.01, rel=1e-12)
    assert sheet_problems(figure) == [] and _label_problems(figure) == []


def test_cam_profile_roller_default_working_profile():
    """Without ``working=``, the envelope comes from sarkp.cams' offset of the pitch curve
    with the tangent by second-order differences: it converges on roller_translating's
    exact one as h**2 (four times closer for half the step)."""
    errors = []
    for n in (181, 361):
        law, p = _roller_cam(n)
        figure = plot.cam_profile(p.XA, p.YA, law.FI, follower="roller", roller_radius=0.01)
        k = int(np.argmax(np.hypot(p.XA, p.YA)))
        c, s = np.cos(law.FI[k]), np.sin(law.FI[k])
        line = next(v for v in figure.axes[0].lines
                    if v.get_label().startswith("working profile"))
        x = c * p.XW - s * p.YW
        errors.append(np.max(np.abs(line.get_xdata() - x)))
    assert errors[1] < errors[0] / 3.0
    assert errors[1] < 1e-3 * 0.01                      # a thousandth of the roller


# ---- results with designs (a Mechanism whose values are arrays over D designs) ---------------

L2S = np.array([0.33, 0.35, 0.37])


def _designs_four_bar(l2, n=37):
    """The four-bar of _four_bar with coupler lengths ``l2`` (an array: designs) and a
    frame pivot C given per design when ``l2`` is an array."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.32 + 0.0 * np.asarray(l2), 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", l2, 0.3)
    m.point("S", "A", "B", 0.1, 0.3)
    return m.solve(np.linspace(0.0, 2 * np.pi, n), need="positions")


def _lines(figure):
    """The polylines drawn in colour (the links at the highlighted position): their
    vertices, in drawing order."""
    return [np.column_stack(line.get_data()) for line in figure.axes[0].lines
            if line.get_marker() == "o" and len(line.get_xdata()) >= 2]


def test_plot_of_one_design_is_the_plot_of_that_design_alone():
    """plot(design=d) of a result with designs draws exactly what plot() of design d
    solved alone draws: the same links at the same points, the same grey positions."""
    together = _designs_four_bar(L2S)
    for d in (0, 2, -1):
        alone = _designs_four_bar(float(L2S[d]))
        a, b = together.plot(design=d, position=7), alone.plot(position=7)
        assert _title(a).strip() == f"design {d} in its positions"
        for x, y in zip(a.axes[0].lines, b.axes[0].lines):
            np.testing.assert_array_equal(x.get_xydata(), y.get_xydata())
        assert len(a.axes[0].lines) == len(b.axes[0].lines)
        assert sheet_problems(a) == []


def test_plot_overlays_the_designs_at_one_position():
    """design='all' draws every design at the position asked, each in its own colour
    and named in the legend; a sequence of indices draws those designs."""
    r = _designs_four_bar(L2S)
    figure = r.plot(design="all", position=5, paths=("B",))
    lines = _lines(figure)
    k = len(r._drawing(0)[1])                        # three links a design: O-A, A-S-B, C-B
    assert k == 3 and len(lines) == 3 * k
    for d in range(3):
        alone = _designs_four_bar(float(L2S[d]))
        ours = np.concatenate(lines[k * d:k * d + k])
        want = np.concatenate([[alone.position(n)[5] for n in link]
                               for link in alone._drawing()[1]])
        np.testing.assert_array_equal(ours, want)
    legend = [t.get_text() for t in figure.axes[0].get_legend().get_texts()]
    assert legend == ["path of B", "design 0", "design 1", "design 2"]
    assert _title(figure).strip() == "3 designs at position 6"
    assert sheet_problems(figure) == []
    two = r.plot(design=[2, 0], position=5)
    assert [t.get_text() for t in two.axes[0].get_legend().get_texts()] == [
        "design 2", "design 0"]
    np.testing.assert_array_equal(np.concatenate(_lines(two)[:k]),
                                  np.concatenate(lines[2 * k:3 * k]))


def test_plot_of_many_designs_has_a_colour_bar():
    r = _designs_four_bar(np.linspace(0.33, 0.40, 12), n=13)
    figure = r.plot(design="all")
    assert figure.axes[0].get_legend() is None
    assert len(figure.axes) == 2 and figure.axes[1].get_ylabel() == "design"
    assert len(_lines(figure)) == 12 * 3


def test_animate_one_design(tmp_path):
    from PIL import Image
    r = _designs_four_bar(L2S, n=25)
    path = r.animate(tmp_path / "d.gif", design=1, every=8)
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 4


@pytest.mark.parametrize("call, message", [
    (lambda r: r.plot(), r"3 designs: plot\(design=i\) .* \(0 to 2\); "
                         r"plot\(design='all'\) overlays them"),
    (lambda r: r.animate("x.gif"), r"animate draws one design: .* pass design=i \(0 to 2\)"),
    (lambda r: r.animate("x.gif", design="all"), r"animate draws one design"),
    (lambda r: r.plot(design=3), r"index from 0 to 2.*not 3"),
    (lambda r: r.plot(design=1.0), r"index from 0 to 2.*not 1.0"),
    (lambda r: r.plot(design=True), r"index from 0 to 2.*not True"),
    (lambda r: r.plot(design="every"), r"or 'all', not 'every'"),
    (lambda r: r.plot(design=[]), r"index from 0 to 2"),
])
def test_designs_drawn_only_when_named(call, message):
    r = _designs_four_bar(L2S, n=13)
    with pytest.raises(ValueError, match=message):
        call(r)


def test_design_of_a_result_without_designs_is_an_error():
    with pytest.raises(ValueError, match="design=0: this result has no designs"):
        _four_bar(13).plot(design=0)


def test_a_shared_frame_point_of_a_result_with_designs():
    """A frame point given by numbers in a mechanism with designs is at the same place
    in every design (position() raised 'cannot reshape' before)."""
    r = _designs_four_bar(L2S, n=13)
    o = r.position("O")
    assert o.shape == (3, 13, 2) and not o.any()
    np.testing.assert_array_equal(r.position("C"), np.broadcast_to([0.32, 0.0], (3, 13, 2)))
