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
    assert set(plot.__all__) == {"mechanism", "diagrams", "cam_profile", "cam_diagrams",
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
    (lambda: plot.cam_profile([1.0], [1.0], [0.0], follower="roller"), ValueError,
     "follower"),
])
def test_bad_input_names_the_argument(draw, error, message):
    with pytest.raises(error, match=message):
        draw()
