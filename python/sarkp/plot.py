"""Drawing-sheet pictures of mechanisms and their diagrams (matplotlib, an optional extra).

matplotlib is imported inside the functions only, so ``import sarkp`` never needs it.
Every function draws on a new ``matplotlib.figure.Figure`` (no pyplot state, no display
needed), or on the Axes passed as ``ax``, and returns the Figure; :func:`save` writes it
as PNG, SVG or PDF.  The pictures follow the conventions of a drawing sheet: every axis
names its quantity and unit, angles of a crank or cam are in degrees (with the book's
position numbers on the top axis where the book numbers its positions), limits are
drawn where a limit exists, legends sit outside the drawing, and labels never overlap.

Linkages (chapter 4, program X):

* :func:`mechanism`: a planar linkage drawn in several positions, with the paths of
  chosen points, its frame pivots hatched and its slider drawn as a block;
* :func:`animate`: the same picture in motion, one frame per position (GIF or MP4);
* :func:`diagrams`: quantities against the crank angle, one panel per unit.

Cams (chapter 5):

* :func:`cam_profile`: the profile, its base circle and the follower in one position;
* :func:`cam_diagrams`: the pressure angle (with its allowed limit) and the radius of
  curvature (its negative, non-convex part shaded) against the cam angle.

Forces and dynamics (chapters 7-8):

* :func:`reaction_hodograph`: the hodograph of a joint reaction over a crank turn, with
  the position numbers and arrows in the order of the positions;
* :func:`speed_diagram`: omega(phi) of the reduction link without and with the flywheel.

Gears (chapter 6):

* :func:`gear_mesh`: an external spur mesh near its pitch point: both wheels' teeth with
  their roots, the labelled circles, the line of action and its active length, and the
  contact ratio;
* :func:`internal_mesh`: the same for a pinion in a ring cut by a shaper (DGMZVN).

:func:`mode_title` adds the mode to a title: every picture of an as-printed run says so.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np

__all__ = ["mechanism", "designs", "animate", "diagrams", "cam_profile", "cam_diagrams", "reaction_hodograph",
           "speed_diagram", "gear_mesh", "internal_mesh", "save", "mode_title", "FORMATS"]

#: The file formats :func:`save` writes (the file's suffix is set to the format).
FORMATS = ("png", "svg", "pdf")

_LABEL = dict(fontsize=9, zorder=6, bbox=dict(boxstyle="round,pad=0.12", fc="white",
                                              ec="none", alpha=0.85))
# candidate offsets (points) of a label from its point, tried in order
_OFFSETS = ((6, 6), (6, -14), (-14, 6), (-14, -14), (9, -4), (-18, -4), (-4, 9), (-4, -17),
            (14, 12), (-22, 12), (14, -20), (-22, -20))


def _curves(**named):
    """The named arrays as 1-D float arrays of one length, or a ValueError naming the
    argument that does not fit (None passes through)."""
    out, size, first = [], None, None
    for name, value in named.items():
        if value is None:
            out.append(None)
            continue
        try:
            a = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise TypeError(f"{name} must be an array of numbers") from None
        if a.ndim != 1:
            raise ValueError(f"{name} must be 1-D, not of shape {a.shape}")
        if size is None:
            size, first = a.size, name
        elif a.size != size:
            raise ValueError(f"{name} has {a.size} values, {first} has {size}")
        out.append(a)
    return out


def _new_figure(size):
    try:
        from matplotlib.figure import Figure
        from matplotlib.backends.backend_agg import FigureCanvasAgg
    except ImportError as exc:            # pragma: no cover - depends on the installation
        raise ImportError("sarkp.plot needs matplotlib: pip install 'sarkp[plot]' "
                          "(or pip install matplotlib)") from exc
    figure = Figure(figsize=size, layout="constrained")
    FigureCanvasAgg(figure)               # a renderer, to measure and place the labels
    return figure


def _axes(ax, rows=1, size=(6.0, 6.0), sharex=False):
    """(figure, list of Axes): ``ax`` (one Axes, or a sequence of ``rows`` Axes) or a new
    figure with ``rows`` panels."""
    if ax is None:
        figure = _new_figure(size)
        figure._sarkp_own = True          # the title and caption go on the figure
        return figure, list(figure.subplots(rows, 1, squeeze=False, sharex=sharex)[:, 0])
    axes = list(ax) if isinstance(ax, (list, tuple, np.ndarray)) else [ax]
    if len(axes) != rows:
        raise ValueError(f"ax must be {rows} Axes for {rows} panels, not {len(axes)}")
    return axes[0].figure, axes


def mode_title(title: str, mode: str | None = None) -> str:
    """``title`` with the mode named when it is as-printed (``mode``, default the
    caller's mode): ``"... -- AS PRINTED: the book's errors kept"``."""
    from .modes import get_mode
    mode = get_mode() if mode is None else mode
    if mode == "as-printed":
        # no-break spaces: a wrapped title keeps "AS PRINTED" on one line
        return f"{title} \N{EM DASH} AS\N{NO-BREAK SPACE}PRINTED: the book's errors kept"
    return title


def _wrap(text, width_in, fontsize=10.0):
    """Wrap ``text`` to lines that fit ``width_in`` inches at ``fontsize`` points."""
    chars = max(20, int(width_in * 72.0 / (0.55 * fontsize)))
    return "\n".join(textwrap.fill(part, chars) for part in str(text).split("\n"))


def _title(figure, axes, title, caption=None):
    """The title above the picture and the caption below, wrapped to the figure's width;
    on Axes passed by the caller, the title goes on the first Axes."""
    width = figure.get_figwidth()
    own = getattr(figure, "_sarkp_own", None)
    if title:
        if own:
            figure.suptitle(_wrap(title, width - 0.3, 11), fontsize=11)
        else:
            axes[0].set_title(_wrap(title, width * 0.8, 10), fontsize=10)
    if caption:
        if own:
            figure.supxlabel(_wrap(caption, width - 0.3, 9), fontsize=9, ha="center")
        else:
            axes[-1].annotate(_wrap(caption, width * 0.8, 8), (0.5, 0.0),
                              xycoords="axes fraction", xytext=(0, -36),
                              textcoords="offset points", ha="center", va="top",
                              fontsize=8, annotation_clip=False)


def _legend(ax, **kw):
    """A legend below the Axes, outside the drawing (it covers nothing)."""
    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return None
    # points across the Axes (a new figure's single Axes: across the figure)
    share = 1.0 if getattr(ax.figure, "_sarkp_own", False) else ax.get_position().width
    room = ax.figure.get_figwidth() * 72.0 * share - 30.0
    labels = [textwrap.fill(t, int(room / (0.55 * 8) - 8)) for t in labels]
    longest = max(max(len(line) for line in t.split("\n")) for t in labels)
    columns = max(1, min(3, len(handles), int(room // (longest * 0.55 * 8 + 34))))
    kw.setdefault("ncols", columns)
    from matplotlib.transforms import offset_copy
    below = offset_copy(ax.transAxes, ax.figure, x=0, y=-40, units="points")
    return ax.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                     bbox_transform=below, fontsize=8, frameon=False, **kw)


def _renderer(figure):
    canvas = figure.canvas
    if not hasattr(canvas, "get_renderer"):
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        canvas = FigureCanvasAgg(figure)
    return canvas.get_renderer()


def _texts(figure):
    """Every visible, non-empty text of the figure."""
    from matplotlib.text import Text
    return [t for t in figure.findobj(Text)
            if t.get_visible() and t.get_text().strip() and t.figure is not None]


def _ink(ax, renderer, step=2.0):
    """Display points (pixels) along every drawn line of ``ax`` (its vertices and points
    every ``step`` pixels along its segments; markers' centres too): where the drawing
    is, which a label should not cover."""
    pts = []
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        xy = np.column_stack([np.asarray(line.get_xdata(), float),
                              np.asarray(line.get_ydata(), float)])
        if xy.size == 0:
            continue
        d = line.get_transform().transform(xy)
        ok = np.all(np.isfinite(d), axis=1)
        if line.get_linestyle() not in ("None", "", " ") and len(d) > 1:
            a, b = d[:-1], d[1:]
            good = ok[:-1] & ok[1:]
            a, b = a[good], b[good]
            n = np.maximum(1, np.ceil(np.hypot(*(b - a).T) / step)).astype(int)
            t = np.concatenate([np.arange(k) / k for k in n])
            start = np.repeat(a, n, axis=0)
            pts.append(start + (np.repeat(b, n, axis=0) - start) * t[:, None])
        pts.append(d[ok])
    return np.concatenate(pts) if pts else np.empty((0, 2))


def _covered(box, ink):
    """How many ink points lie inside ``box`` (a Bbox, pixels)."""
    if not len(ink):
        return 0
    return int(np.count_nonzero((ink[:, 0] > box.x0) & (ink[:, 0] < box.x1)
                                & (ink[:, 1] > box.y0) & (ink[:, 1] < box.y1)))


def _candidates():
    """Offsets (points) of a label from its point: near ones first, then rings further
    out (joined to the point by a leader line), each ring round the compass."""
    out = list(_OFFSETS)
    for radius in (18, 26, 36, 48, 62):
        for k in range(16):
            a = 2 * math.pi * k / 16 + math.pi / 4
            out.append((radius * math.cos(a) - 4, radius * math.sin(a) - 4))
    return out


_CANDIDATES = _candidates()


def _place_labels(figure, labels, redraw=True):
    """Place every label registered on ``figure`` (this call's ``labels`` and those of
    earlier calls on the same figure, e.g. other panels), each at the first candidate
    offset where it overlaps no other text, covers none of the drawing's lines and stays
    inside its Axes; failing that, where it overlaps no text and covers the least.  A
    label further than its near ring gets a leader line to its point.  A label marked
    ``_sarkp_optional`` that finds no place free of text is hidden.  Needs the layout
    done; all labels are placed again, so a later panel never spoils an earlier one.
    ``redraw=False``: the layout and the limits have not changed since the last draw (an
    animation's frames)."""
    everything = getattr(figure, "_sarkp_labels", [])
    everything += [a for a in labels if a not in everything]
    figure._sarkp_labels = everything
    if not everything:
        return
    for label in everything:
        label.set_visible(True)
        label.set_position(_OFFSETS[0])
        label._sarkp_leader.set_visible(False)
    if redraw:
        figure.draw_without_rendering()
    renderer = _renderer(figure)
    movable = set(map(id, everything))
    placed = [t.get_window_extent(renderer) for t in _texts(figure) if id(t) not in movable]
    inks = {}
    for label in everything:
        ax = label.axes
        if id(ax) not in inks:
            inks[id(ax)] = _ink(ax, renderer)
        ink = inks[id(ax)]
        box_ax = ax.get_window_extent(renderer)
        best, fallback = None, None
        for dx, dy in _CANDIDATES:
            label.set_position((dx, dy))
            box = label.get_window_extent(renderer)
            inside = (box.x0 >= box_ax.x0 and box.x1 <= box_ax.x1 and box.y0 >= box_ax.y0
                      and box.y1 <= box_ax.y1)
            if not inside or any(box.padded(3).overlaps(p) for p in placed):
                continue
            covered = _covered(box.padded(1), ink)
            if covered == 0:
                best = (dx, dy)
                break
            if fallback is None or covered < fallback[0]:
                fallback = (covered, (dx, dy))
        if best is None and fallback is not None:
            best = fallback[1]
        if best is None:
            if getattr(label, "_sarkp_optional", False):
                label.set_visible(False)
                continue
            best = _OFFSETS[0]
        label.set_position(best)
        box = label.get_window_extent(renderer)
        placed.append(box)
        if math.hypot(*best) > 20:                  # a leader from the box's edge
            scale = 72.0 / figure.dpi
            px, py = ax.transData.transform(label.xy)
            cx, cy = (box.x0 + box.x1) / 2 - px, (box.y0 + box.y1) / 2 - py
            half = min(box.width / abs(cx) if cx else math.inf,
                       box.height / abs(cy) if cy else math.inf) / 2
            leader = label._sarkp_leader
            keep = 1 - min(half, 1.0)
            leader.set_position((cx * scale * keep, cy * scale * keep))
            leader.set_visible(True)


def _fit_height(figure, ax, rounds=3):
    """On a figure of sarkp's own, the sheet's height cut to the drawing: an Axes of equal
    aspect is lower than the layout gives it, which left an empty band under the title.
    The Axes goes to the top of its place, and the figure loses the height left between
    the legend below the Axes and the caption."""
    if not getattr(figure, "_sarkp_own", False):
        return
    ax.set_anchor("N")
    for _ in range(rounds):
        figure.draw_without_rendering()
        renderer = _renderer(figure)
        boxes = [ax.get_tightbbox(renderer)]
        if ax.get_legend() is not None:
            boxes.append(ax.get_legend().get_window_extent(renderer))
        low = min(b.y0 for b in boxes)
        caption = figure._supxlabel
        floor = caption.get_window_extent(renderer).y1 if caption is not None else 0.0
        spare = (low - floor) / figure.dpi - 0.15
        if spare < 0.05:
            return
        figure.set_size_inches(figure.get_figwidth(), figure.get_figheight() - spare)


def _label(ax, text, xy, color="k", optional=False, **kw):
    a = ax.annotate(text, xy, xytext=_OFFSETS[0], textcoords="offset points",
                    color=color, **{**_LABEL, **kw})
    a.set_in_layout(False)
    a._sarkp_optional = optional
    # its leader line, shown when the label sits away from its point: an annotation
    # without text (so no text box), its arrow from the label towards the point
    a._sarkp_leader = ax.annotate("", xy, xytext=(0, 0), textcoords="offset points",
                                  arrowprops=dict(arrowstyle="-", color=color, lw=0.6,
                                                  alpha=0.8, shrinkA=0, shrinkB=1.5))
    a._sarkp_leader.set_visible(False)
    a._sarkp_leader.set_in_layout(False)
    return a


def save(figure, path, *, format: str | None = None, dpi: float | None = None):
    """Write ``figure`` to ``path`` in ``format`` (``"png"``, ``"svg"`` or ``"pdf"``;
    default: the suffix of ``path``, or PNG when it has none).  The suffix of the file
    written is the format's; ``dpi`` (default 150) sets the resolution of a PNG.
    Returns the path written (a :class:`pathlib.Path`)."""
    from pathlib import Path
    path = Path(path)
    if format is None:
        format = path.suffix[1:].lower() or "png"
    if format not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, not {format!r}")
    if dpi is None:
        dpi = 150
    if not (isinstance(dpi, (int, float)) and math.isfinite(dpi) and 10 <= dpi <= 2400):
        raise ValueError(f"dpi must be a number from 10 to 2400, not {dpi!r}")
    path = path.with_suffix("." + format)
    figure.savefig(path, format=format, dpi=dpi)
    return path


# ---- angles and the book's position numbers -----------------------------------------------

def _positions_axis(ax, degrees, positions):
    """The book's position numbers on the top axis, for angles ``degrees`` at the
    positions ``positions`` (a linear numbering)."""
    degrees = np.asarray(degrees, dtype=float)
    positions = np.asarray(positions, dtype=float)
    if degrees.size < 2 or degrees[1] == degrees[0]:
        return None
    step = (positions[1] - positions[0]) / (degrees[1] - degrees[0])
    start = positions[0] - step * degrees[0]
    top = ax.secondary_xaxis("top", functions=(lambda d: start + step * d,
                                               lambda p: (p - start) / step))
    top.set_xlabel("position number (as the book numbers them)", fontsize=8)
    top.tick_params(labelsize=7)
    first, last = int(positions.min()), int(positions.max())
    every = max(1, math.ceil((last - first) / 12))
    from matplotlib.ticker import FixedLocator
    top.xaxis.set_major_locator(FixedLocator(range(first, last + 1, every)))
    return top


def _degree_ticks(ax, degrees):
    from matplotlib.ticker import MultipleLocator
    span = float(np.nanmax(degrees) - np.nanmin(degrees)) if len(degrees) else 0.0
    step = 30 if span > 150 else (15 if span > 60 else None)
    if step:
        ax.xaxis.set_major_locator(MultipleLocator(step))


# ---- linkages --------------------------------------------------------------------------------

def _pivot(ax, x, y, size):
    """A frame pivot: a triangle on a hatched base."""
    from matplotlib.patches import Polygon, Rectangle
    h = size
    ax.add_patch(Polygon([(x, y), (x - 0.6 * h, y - h), (x + 0.6 * h, y - h)], closed=True,
                         fc="white", ec="k", lw=1.0, zorder=3))
    ax.add_patch(Rectangle((x - 0.9 * h, y - 1.35 * h), 1.8 * h, 0.35 * h, fc="none",
                           ec="k", lw=0.0, hatch="////", zorder=3))
    ax.plot([x - 0.9 * h, x + 0.9 * h], [y - h, y - h], "-", color="k", lw=1.0, zorder=3)


def mechanism(points, links, *, fixed=(), guide=None, highlight=0, every=1, paths=(),
              title="", slider=None, positions=None, ax=None):
    """A planar linkage in several positions.

    Parameters
    ----------
    points : dict
        ``{name: (x, y)}`` with x, y arrays over the positions (m), or floats for a
        fixed point.
    links : sequence of tuples
        Point names, each tuple drawn as a polyline (a lever B-C-D as one tuple).
    fixed : sequence of str
        Names drawn as frame pivots.
    guide : float, optional
        The height (m) of a horizontal slider guide, drawn hatched.
    highlight : int
        The position drawn in colour, with the point names.
    every : int
        Draw every n-th other position in grey.
    paths : sequence of str
        Names whose paths are drawn.
    title : str
        The title (default: "mechanism in its positions").
    slider : str, optional
        The point drawn as a slider block on the guide (default: the last point of the
        last link when ``guide`` is given).
    positions : sequence of int, optional
        The book's number of each position: the grey positions are numbered at the
        first point of ``paths``.
    ax : matplotlib.axes.Axes, optional
        Draw there instead of on a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.patches import Rectangle
    xy = {n: (np.atleast_1d(np.asarray(x, float)), np.atleast_1d(np.asarray(y, float)))
          for n, (x, y) in points.items()}
    count = max(v[0].size for v in xy.values())
    for name, (x, y) in xy.items():
        if x.size != y.size or x.size not in (1, count):
            raise ValueError(f"points[{name!r}]: x and y must be numbers or arrays of the "
                             f"{count} positions, not of sizes {x.size} and {y.size}")
    for link in links:
        for name in link:
            if name not in xy:
                raise ValueError(f"links: {name!r} is not a name of points")

    def at(name, k):
        x, y = xy[name]
        return (x[k] if x.size > 1 else x[0]), (y[k] if y.size > 1 else y[0])
    figure, (ax,) = _axes(ax, size=(7.5, 6.8))
    allx = np.concatenate([v[0] for v in xy.values()])
    ally = np.concatenate([v[1] for v in xy.values()])
    size = 0.035 * max(np.ptp(allx), np.ptp(ally), 1e-9)
    drawn = [k for k in range(0, count, max(1, every)) if k != highlight]
    for j, k in enumerate(drawn):
        for link in links:
            c = [at(n, k) for n in link]
            ax.plot([p[0] for p in c], [p[1] for p in c], "-", color="0.72", lw=0.8,
                    label="other positions" if j == 0 and link is links[0] else None)
    for i, name in enumerate(paths):
        x, y = xy[name]
        ax.plot(x, y, "-", color=f"C{i + 2}", lw=2.4, alpha=0.5, label=f"path of {name}")
    labels = []
    if positions is not None and paths:
        x, y = xy[paths[0]]
        for k in [highlight] + drawn:
            closes = k != highlight and math.hypot(x[k] - x[highlight],
                                                   y[k] - y[highlight]) < 1e-9 * size
            if k < len(positions) and x.size > 1 and not closes:
                labels.append(_label(ax, str(positions[k]), (x[k], y[k]), color="0.35",
                                     optional=k != highlight, fontsize=7))
    moving = {"links": [], "labels": [], "slider": None, "at": at}
    for i, link in enumerate(links):
        c = [at(n, highlight) for n in link]
        number = f" {positions[highlight]}" if positions is not None else ""
        line, = ax.plot([p[0] for p in c], [p[1] for p in c], "o-", color="C0", lw=2.2,
                        ms=4, label=f"position{number or ' ' + str(highlight + 1)}"
                        if i == 0 else None)
        moving["links"].append((line, link))
    for name in fixed:
        _pivot(ax, *at(name, 0), size)
    if guide is not None:
        lo, hi = allx.min() - 2 * size, allx.max() + 2 * size
        ax.plot([lo, hi], [guide, guide], "-", color="k", lw=1.0)
        ax.add_patch(Rectangle((lo, guide - 0.5 * size), hi - lo, 0.5 * size, fc="none",
                               ec="none", hatch="////", lw=0.0))
        ax.plot([], [], "-", color="k", lw=1.0, label="guide of the slider")
        name = slider if slider is not None else links[-1][-1]
        sx, sy = at(name, highlight)
        block = ax.add_patch(Rectangle((sx - 1.4 * size, guide), 2.8 * size, 1.6 * size,
                                       fc="white", ec="C0", lw=1.8, zorder=4))
        pin, = ax.plot([sx], [sy], "o", color="C0", ms=4, zorder=5)
        moving["slider"] = (block, pin, name, size)
    for name in xy:
        labels.insert(0, _label(ax, name, at(name, highlight), color="C0",
                                fontweight="bold", fontsize=10))
        moving["labels"].append((labels[0], name))
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.grid(True, lw=0.3)
    _legend(ax)
    _title(figure, [ax], title or "mechanism in its positions")
    _place_labels(figure, labels)
    figure._sarkp_moving = moving
    return figure


def designs(points, links, *, fixed=(), highlight=0, paths=(), names=None, title="",
            ax=None):
    """Several designs of one linkage overlaid, each at the same position.

    Parameters
    ----------
    points : dict
        ``{name: (x, y)}`` with x, y arrays of shape (D, n) over D designs and n
        positions, (D,) for a point that does not move, or floats shared by every design
        (m): the points of a :class:`sarkp.Mechanism` result with designs.
    links, fixed, paths
        As for :func:`mechanism`; ``paths`` are drawn for every design, thin, in its colour.
    highlight : int
        The position (index along n) at which every design is drawn.
    names : sequence of str, optional
        The designs' names in the legend (default "design 0", "design 1", ...); beyond
        ten designs a colour bar over the designs' numbers replaces the legend.
    title : str
        The title (default: "D designs at position highlight + 1").
    ax : matplotlib.axes.Axes, optional
        Draw there instead of on a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    xy = {n: (np.asarray(x, float), np.asarray(y, float)) for n, (x, y) in points.items()}
    count = max([v[0].shape[0] for v in xy.values() if v[0].ndim >= 1] or [0])
    if count == 0:
        raise ValueError("points: no array over the designs (use mechanism() for one design)")
    for name, (x, y) in xy.items():
        if x.shape != y.shape or x.ndim > 2 or (x.ndim >= 1 and x.shape[0] != count):
            raise ValueError(f"points[{name!r}]: x and y must be numbers or arrays of "
                             f"shape (D,) or (D, n) over the {count} designs, not of "
                             f"shapes {x.shape} and {y.shape}")
    for link in links:
        for name in link:
            if name not in xy:
                raise ValueError(f"links: {name!r} is not a name of points")
    sizes = {v[0].shape[1] for v in xy.values() if v[0].ndim == 2}
    if len(sizes) > 1 or not (-max(sizes or {1}) <= highlight < max(sizes or {1})):
        raise ValueError(f"highlight = {highlight!r} must index the positions "
                         f"{sorted(sizes) or [1]}")
    names = [f"design {d}" for d in range(count)] if names is None else list(names)
    if len(names) != count:
        raise ValueError(f"names has {len(names)} names for {count} designs")

    def at(name, d):
        x, y = xy[name]
        if x.ndim == 0:
            return float(x), float(y)
        if x.ndim == 1:
            return x[d], y[d]
        return x[d, highlight], y[d, highlight]
    figure, (ax,) = _axes(ax, size=(7.5, 6.8))
    allx = np.concatenate([np.ravel(v[0]) for v in xy.values()])
    ally = np.concatenate([np.ravel(v[1]) for v in xy.values()])
    size = 0.035 * max(np.nanmax(allx) - np.nanmin(allx), np.nanmax(ally) - np.nanmin(ally),
                       1e-9)
    many = count > 10
    cmap = _colormap("viridis")
    colour = [cmap(d / max(count - 1, 1)) if many else f"C{d}" for d in range(count)]
    for d in range(count):
        for name in paths:
            x, y = xy[name]
            if x.ndim == 2:
                ax.plot(x[d], y[d], "-", color=colour[d], lw=0.9, alpha=0.6,
                        label=f"path of {name}" if d == 0 and not many else None)
        for i, link in enumerate(links):
            c = [at(n, d) for n in link]
            ax.plot([p[0] for p in c], [p[1] for p in c], "o-", color=colour[d], lw=1.8,
                    ms=3, label=names[d] if i == 0 and not many else None)
        for name in fixed:
            _pivot(ax, *at(name, d), size)
    labels = [_label(ax, name, at(name, 0), color="k", fontsize=9) for name in xy]
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.grid(True, lw=0.3)
    if many:
        from matplotlib.cm import ScalarMappable
        from matplotlib.colors import Normalize
        bar = figure.colorbar(ScalarMappable(Normalize(0, count - 1), cmap), ax=ax,
                              shrink=0.8)
        bar.set_label("design")
    else:
        _legend(ax)
    _title(figure, [ax], title or f"{count} designs at position {highlight + 1}")
    _place_labels(figure, labels)
    return figure


def _colormap(name):
    from matplotlib import colormaps
    return colormaps[name]


def _animation(points, links, *, fixed=(), paths=(), title="", guide=None, slider=None,
               every=1):
    """(figure, update, frames): the picture of :func:`mechanism` at the first position
    (its labels, title, frame pivots and guide) over the extent of every position, and
    ``update(k)`` that moves the links, the slider and the joints' labels to position k."""
    count = max(np.atleast_1d(np.asarray(x, float)).size for x, _ in points.values())
    figure = mechanism(points, links, fixed=fixed, guide=guide, highlight=0,
                       every=count + 1, paths=paths, slider=slider,
                       title=title or "mechanism in motion")
    ax = figure.axes[0]
    allx = np.concatenate([np.atleast_1d(np.asarray(x, float)) for x, _ in points.values()])
    ally = np.concatenate([np.atleast_1d(np.asarray(y, float)) for _, y in points.values()])
    span = max(np.nanmax(allx) - np.nanmin(allx), np.nanmax(ally) - np.nanmin(ally), 1e-9)
    pad = 0.12 * span
    ax.set_xlim(np.nanmin(allx) - pad, np.nanmax(allx) + pad)
    ax.set_ylim(np.nanmin(ally) - pad, np.nanmax(ally) + pad)
    ax.set_aspect("equal", adjustable="box")
    moving = figure._sarkp_moving
    at = moving["at"]
    legend = ax.get_legend()
    if legend is not None:                # "position 1" would name the first frame only
        legend.remove()
    moving["links"][0][0].set_label("the links, position by position")
    _legend(ax)
    _place_labels(figure, [])
    figure.set_layout_engine("none")     # the layout of the first frame, kept

    def update(k):
        changed = []
        for line, link in moving["links"]:
            c = [at(n, k) for n in link]
            line.set_data([p[0] for p in c], [p[1] for p in c])
            changed.append(line)
        for label, name in moving["labels"]:
            label.xy = at(name, k)
            label._sarkp_leader.xy = label.xy
            changed.append(label)
        if moving["slider"] is not None:
            block, pin, name, size = moving["slider"]
            sx, sy = at(name, k)
            block.set_x(sx - 1.4 * size)
            pin.set_data([sx], [sy])
            changed += [block, pin]
        _place_labels(figure, [], redraw=False)   # the names placed again, clear
        return changed
    return figure, update, range(0, count, max(1, int(every)))


def animate(points, links, path, *, fixed=(), paths=(), title="", guide=None,
            slider=None, fps=20, every=1):
    """An animation of a linkage over its positions written to ``path`` (``.gif``
    through Pillow; ``.mp4`` through ffmpeg): each frame is :func:`mechanism`'s picture
    at that position -- the joints' names, the title, the frame pivots hatched, the
    guide and the slider block -- the paths of ``paths`` drawn throughout.

    Parameters
    ----------
    points, links, fixed, paths, title, guide, slider
        As for :func:`mechanism`.
    path : str or path-like
        The file written.
    fps : float
        Frames per second.
    every : int
        One frame every ``every`` positions.

    Returns
    -------
    str
        ``path``.
    """
    from matplotlib import animation
    path = str(path)
    if not path.endswith(".gif") and not animation.FFMpegWriter.isAvailable():
        raise RuntimeError(f"animate: writing {path!r} needs ffmpeg (matplotlib's "
                           f"FFMpegWriter), which is not installed (Debian: apt-get "
                           f"install ffmpeg); a .gif path needs only Pillow")
    figure, update, frames = _animation(points, links, fixed=fixed, paths=paths,
                                        title=title, guide=guide, slider=slider,
                                        every=every)
    anim = animation.FuncAnimation(figure, update, frames=frames, blit=False)
    writer = animation.PillowWriter(fps=fps) if path.endswith(".gif") else \
        animation.FFMpegWriter(fps=fps)
    anim.save(path, writer=writer)
    return path


def diagrams(x, panels, *, xlabel="crank angle φ1, rad", title="", degrees=False,
             positions=None, notes=None, caption=None, ax=None):
    """Curves against ``x``, one panel per entry of ``panels``.

    Parameters
    ----------
    x : array_like
        The abscissa: a crank angle in rad (drawn in degrees when ``degrees``).
    panels : sequence of (str, dict)
        ``(ylabel with its unit, {curve label: values})`` per panel.
    xlabel : str
        The abscissa's label (with ``degrees``, the default becomes "crank angle φ1, °").
    title : str
    degrees : bool
        Draw ``x`` (rad) in degrees.
    positions : sequence of int, optional
        The book's position number of each x: drawn on the top axis of the first panel.
    notes : sequence of str, optional
        One note per panel drawn inside its top left corner (e.g. a caveat).
    caption : str, optional
        Text below the picture.
    ax : Axes or sequence of Axes, optional
        One Axes per panel, instead of a new figure.

    Returns
    -------
    matplotlib.figure.Figure
    """
    (x,) = _curves(x=x)
    for ylabel, curves in panels:
        for label, values in curves.items():
            _curves(x=x, **{f"the curve {label!r} of the panel {ylabel!r}": values})
    if degrees:
        x = np.degrees(x)
        if xlabel == "crank angle φ1, rad":
            xlabel = "crank angle φ1, °"
    figure, axes = _axes(ax, rows=len(panels), size=(7.5, 2.7 * len(panels) + 1.2))
    for j, (axis, (ylabel, curves)) in enumerate(zip(axes, panels)):
        styles = ("-", "--", "-.", ":")
        for i, (label, values) in enumerate(curves.items()):
            axis.plot(x, np.asarray(values, dtype=float), styles[i % 4], color=f"C{i}",
                      lw=1.4, label=label)
        values = np.concatenate([np.asarray(v, dtype=float).ravel() for v in curves.values()])
        if np.any(np.isfinite(values)) and np.nanmin(values) < 0.0 < np.nanmax(values):
            axis.axhline(0.0, color="k", lw=0.5)
        axis.set_ylabel(ylabel)
        axis.set_xlabel(xlabel)
        axis.grid(True, lw=0.3)
        if degrees:
            _degree_ticks(axis, x)
        if notes and j < len(notes) and notes[j]:
            axis.set_title(_wrap(notes[j], figure.get_figwidth() - 0.8, 8), loc="left",
                           fontsize=8, color="C3")
        _legend(axis)
    if positions is not None:
        _positions_axis(axes[0], x, positions)
    _title(figure, axes, title, caption)
    return figure


# ---- cams ------------------------------------------------------------------------------------

def _rotate(x, y, angle):
    c, s = math.cos(angle), math.sin(angle)
    return c * x - s * y, s * x + c * y


def cam_profile(XA, YA, FI, *, position=None, follower="knife", offset=0.0,
                base_radius=None, roller_radius=None, working=None, title="", ax=None):
    """The cam profile turned to the cam angle ``FI[position]``, with its base circle,
    the cam centre, and the follower touching it there.

    Parameters
    ----------
    XA, YA : array_like
        Profile points in the cam's frame, m.
    FI : array_like
        The cam angles of the points, rad.
    position : int, optional
        The index of the position drawn (default: the highest lift).
    follower : {"knife", "flat", "roller"}
        A translating knife-edge on the line x = ``offset`` (as DPRFLP), a flat face
        perpendicular to the y axis (as DPRFPL), or a translating roller on the line
        x = ``offset`` whose centre follows ``XA, YA`` (the pitch curve, as
        :func:`sarkp.cams.roller_translating` gives it).
    offset : float
        The knife-edge's or the roller's offset e, m.
    base_radius : float, optional
        The radius of the base circle (default: the smallest radius of the profile; for
        a roller, of the pitch curve: the prime circle).
    roller_radius : float, optional
        The roller's radius RR, m (> 0): needed for ``follower="roller"``.
    working : (array_like, array_like), optional
        The working profile XW, YW of a roller cam (default: the envelope of the rollers
        on the pitch curve, by :mod:`sarkp.cams`' offset of the pitch curve).
    title : str
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.patches import Circle, Rectangle
    if follower not in ("knife", "flat", "roller"):
        raise ValueError(f"follower must be 'knife', 'flat' or 'roller', not {follower!r}")
    XA, YA, FI = _curves(XA=XA, YA=YA, FI=FI)
    if follower == "roller":
        if roller_radius is None or not (isinstance(roller_radius, (int, float))
                                         and math.isfinite(roller_radius)
                                         and roller_radius > 0):
            raise ValueError(f"roller_radius must be a number > 0 for a roller follower, "
                             f"not {roller_radius!r}")
        rr = float(roller_radius)
        if working is None:
            XW, YW = _working(XA, YA, FI, rr)
        else:
            XW, YW = _curves(**{"working profile XW": working[0],
                                "working profile YW": working[1]})
            if XW.size != XA.size:
                raise ValueError(f"working has {XW.size} points, XA has {XA.size}")
    elif roller_radius is not None or working is not None:
        raise ValueError("roller_radius and working are for follower='roller'")
    radius = np.hypot(XA, YA)
    k = int(np.argmax(radius)) if position is None else int(position)
    x, y = _rotate(XA, YA, FI[k])                      # the fixed frame: the cam turned
    r0 = float(np.min(radius)) if base_radius is None else float(base_radius)
    size = float(np.max(radius))
    figure, (ax,) = _axes(ax, size=(6.5, 7.2))
    step = abs(FI[-1] - FI[-2]) if FI.size > 1 else 0.0
    gap = 2 * math.pi - abs(FI[-1] - FI[0])
    if follower == "roller":
        wx, wy = _rotate(XW, YW, FI[k])
        ax.plot(wx, wy, "-", color="C0", lw=1.8, label=f"working profile (rollers' "
                                                        f"envelope, RR = {rr * 1000:.2f} mm)")
        ax.plot(x, y, "--", color="C0", lw=0.9, label="pitch curve (the roller's centre)")
        for j in range(0, XA.size, max(1, XA.size // 24)):   # rollers along the pitch curve
            ax.add_patch(Circle((x[j], y[j]), rr, fc="none", ec="0.6", lw=0.5, zorder=1))
        ax.plot([], [], "-", color="0.6", lw=0.5, label="the roller at other angles")
    else:
        ax.plot(x, y, "-", color="C0", lw=1.8, label="cam profile (the table's points)")
    if gap > 1.5 * step:
        # the table stops before the turn is complete (V.5: 250 of 360 degrees): the rest
        # is a dwell at the last radius, an arc back to the first point
        a0, a1 = math.atan2(y[-1], x[-1]), math.atan2(y[0], x[0])
        turn = -1.0 if FI[-1] > FI[0] else 1.0          # the points turn against the cam
        sweep = (a1 - a0) % (2 * math.pi) if turn > 0 else -((a0 - a1) % (2 * math.pi))
        arc = a0 + np.linspace(0.0, sweep, 100)
        r = np.linspace(radius[-1], radius[0], 100)
        ax.plot(r * np.cos(arc), r * np.sin(arc), ":", color="C0", lw=1.6,
                label=f"rest of the turn ({math.degrees(gap):.0f}°): follower at rest, "
                      "arc of constant radius")
    t = np.linspace(0.0, 2 * math.pi, 361)
    circle = "prime circle (of the pitch curve)" if follower == "roller" else "base circle"
    ax.plot(r0 * np.cos(t), r0 * np.sin(t), "--", color="0.5", lw=0.9,
            label=f"{circle}, r0 = {r0 * 1000:.2f} mm")
    ax.plot([-0.08 * size, 0.08 * size], [0, 0], "-", color="k", lw=0.8)
    ax.plot([0, 0], [-0.08 * size, 0.08 * size], "-", color="k", lw=0.8)
    labels = [_label(ax, "O (cam centre)", (0.0, 0.0))]
    tip_x, tip_y = float(x[k]), float(y[k])
    lift = math.degrees(FI[k])
    if follower == "roller":
        ax.axvline(offset, color="C3", lw=0.6, ls=":")
        ax.add_patch(Rectangle((offset - 0.05 * size, tip_y + rr + 0.25 * size),
                               0.1 * size, 0.2 * size, fc="none", ec="k", lw=0.8,
                               hatch="////"))
        ax.plot([offset, offset], [tip_y, tip_y + rr + 0.6 * size], "-", color="C3", lw=3,
                solid_capstyle="butt", label=f"roller follower at {lift:.0f}° "
                                             "(guide hatched)")
        ax.add_patch(Circle((tip_x, tip_y), rr, fc="white", ec="C3", lw=1.6, zorder=4))
        ax.plot([tip_x], [tip_y], "o", color="C3", ms=3, zorder=5)
        tip_x, tip_y = float(wx[k]), float(wy[k])        # the contact: on the working profile
    elif follower == "knife":
        ax.axvline(offset, color="C3", lw=0.6, ls=":")
        ax.add_patch(Rectangle((offset - 0.05 * size, tip_y + 0.25 * size), 0.1 * size,
                               0.2 * size, fc="none", ec="k", lw=0.8, hatch="////"))
        ax.plot([offset, offset], [tip_y, tip_y + 0.6 * size], "-", color="C3", lw=3,
                solid_capstyle="butt", label=f"knife-edge follower at {lift:.0f}° "
                                             "(guide hatched)")
        ax.plot([tip_x], [tip_y], "v", color="C3", ms=8)
    else:
        half = 0.45 * size
        lo, hi = min(-half, tip_x - 0.1 * size), max(half, tip_x + 0.1 * size)
        ax.plot([lo, hi], [tip_y, tip_y], "-", color="C3", lw=3, solid_capstyle="butt",
                label=f"flat-faced follower at {lift:.0f}°")
        ax.plot([0.0, 0.0], [tip_y, tip_y + 0.5 * size], "-", color="C3", lw=2)
        ax.plot([tip_x], [tip_y], "o", color="C3", ms=4)
    labels.append(_label(ax, "contact point", (tip_x, tip_y), color="C3"))
    ax.set_aspect("equal", adjustable="datalim")
    ax.locator_params(axis="x", nbins=6)
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.grid(True, lw=0.3)
    _legend(ax)
    _title(figure, [ax], title or f"cam turned by {lift:.1f}°")
    _place_labels(figure, labels)
    return figure


def _working(XA, YA, FI, rr):
    """The working profile of a roller cam from its pitch curve: sarkp.cams' offset of
    the pitch curve by the roller radius towards the cam centre, with the tangent
    d(XA, YA)/dFI taken by central differences (one-sided at the ends)."""
    from .cams import _working_profile
    dx, dy = np.gradient(XA, FI, edge_order=2), np.gradient(YA, FI, edge_order=2)
    n = XA.size
    p = _working_profile(XA, YA, dx, dy, np.full(n, np.inf), np.zeros(n), rr, "flag",
                         "cam_profile")
    return p.XW, p.YW


def _clip(values, spread=3.0):
    """y limits that keep the bulk of ``values`` visible (a radius of curvature runs off
    to infinity where the curvature changes sign): the data's range, cut at ``spread``
    times the 10-90 percentile range beyond those percentiles."""
    v = np.asarray(values, dtype=float)
    lo, hi = np.percentile(v, [10, 90])
    pad = spread * max(hi - lo, 1e-12)
    low, high = max(v.min(), lo - pad), min(v.max(), hi + pad)
    margin = 0.08 * max(high - low, 1e-12)
    return low - margin, high + margin


def cam_diagrams(FI, ROK, ALFA=None, *, ALD=None, title="", positions=None, ax=None):
    """The pressure angle ALFA and the radius of curvature ROK against the cam angle.

    Parameters
    ----------
    FI : array_like
        Cam angles, rad (drawn in degrees).
    ROK : array_like
        Radius of curvature of the profile, m; where it is negative the profile is not
        convex (shaded).
    ALFA : array_like, optional
        Pressure angle, rad (drawn in degrees); omitted for a flat-faced follower,
        where it is 0.
    ALD : float, optional
        The allowed pressure angle, rad: drawn as two limits, the positions beyond
        them marked.
    title : str
    positions : sequence of int, optional
        The book's position number of each FI, drawn on the top axis.
    ax : Axes or sequence of Axes, optional
        One Axes per panel (two with ALFA, one without).

    Returns
    -------
    matplotlib.figure.Figure
    """
    FI, ROK, ALFA = _curves(FI=FI, ROK=ROK, ALFA=ALFA)
    deg = np.degrees(FI)
    rows = 1 if ALFA is None else 2
    figure, axes = _axes(ax, rows=rows, size=(7.5, 3.3 * rows + 1.0))
    if ALFA is not None:
        axis = axes[0]
        alfa = np.degrees(np.asarray(ALFA, dtype=float))
        axis.plot(deg, alfa, "-", color="C0", lw=1.4, label="pressure angle α")
        if ALD is not None:
            limit = math.degrees(ALD)
            axis.axhspan(limit, max(limit, np.max(alfa)) + 5, color="C3", alpha=0.08, lw=0)
            axis.axhspan(min(-limit, np.min(alfa)) - 5, -limit, color="C3", alpha=0.08, lw=0)
            for sign in (1, -1):
                axis.axhline(sign * limit, color="C3", ls="--", lw=1.0)
            axis.plot([], [], "--", color="C3", label=f"allowed |α| ≤ {limit:.1f}°")
            over = np.abs(alfa) > limit
            if over.any():
                axis.plot(deg[over], alfa[over], "o", color="C3", ms=3.5,
                          label=f"beyond the limit: {int(over.sum())} positions, "
                                f"worst {alfa[np.argmax(np.abs(alfa))]:.1f}°")
            axis.set_ylim(min(-limit, np.min(alfa)) - 5, max(limit, np.max(alfa)) + 5)
        axis.axhline(0.0, color="k", lw=0.5)
        axis.set_ylabel("pressure angle α, °")
        axis.set_xlabel("cam angle φ, °")
        axis.grid(True, lw=0.3)
        _degree_ticks(axis, deg)
        _legend(axis)
    axis = axes[-1]
    low, high = _clip(ROK)
    low = min(low, -0.05 * (high - low)) if (ROK < 0).any() else low
    axis.plot(deg, np.clip(ROK, low, high), "-", color="C2", lw=1.4,
              label="radius of curvature ρ")
    axis.axhline(0.0, color="k", lw=0.6)
    if (ROK < 0).any():
        axis.axhspan(low, 0.0, color="C3", alpha=0.10, lw=0,
                     label=f"ρ < 0: profile not convex ({int(np.sum(ROK < 0))} positions)")
    off = (ROK < low) | (ROK > high)
    if off.any():
        shown = ", ".join(f"{r:.3g}" for r in ROK[off][:4]) + (" ..." if off.sum() > 4 else "")
        axis.plot(deg[off], np.clip(ROK[off], low, high), "^", color="C3", ms=6,
                  label=f"off the scale (value in m: {shown})")
    axis.set_ylim(low, high)
    axis.set_ylabel("radius of curvature ρ, m")
    axis.set_xlabel("cam angle φ, °")
    axis.grid(True, lw=0.3)
    _degree_ticks(axis, deg)
    _legend(axis)
    if positions is not None:
        _positions_axis(axes[0], deg, positions)
    _title(figure, axes, title)
    return figure


# ---- forces and dynamics ---------------------------------------------------------------------

def _jumps(x, y):
    """Indices k where the curve jumps between k and k + 1 (a step far longer than its
    neighbours': a load that switches), for a curve sampled densely."""
    step = np.hypot(np.diff(x), np.diff(y))
    if step.size < 8:
        return np.array([], dtype=int)
    typical = np.median(step)
    return np.flatnonzero(step > 12 * max(typical, 1e-300))


def reaction_hodograph(F, G, *, sweep=None, label=None, mark_every=None, title="",
                       positions=None, jump_label=None, ax=None):
    """The hodograph of a joint reaction over a crank turn.

    Parameters
    ----------
    F, G : array_like
        The modulus (N, >= 0) and direction (rad) of the reaction at each crank
        position, in order (e.g. ``F21``, ``G21`` of :func:`sarkp.book.prog_vii_10.compute`):
        marked and numbered.
    sweep : (array_like, array_like), optional
        The same reaction (modulus, direction) over a dense sweep of the same turn: the
        curve is drawn from it (without it, through the positions).  Where it jumps (a
        load that switches: a step twelve times its median or longer) the jump is drawn
        dotted, not as part of the curve.
    label : str, optional
        The curve's name in the legend.
    mark_every : int, optional
        Mark and number every n-th position (default: every position up to 40 of them,
        every second of 80, ...).  Numbers sit beside their points, or further out with
        a leader line, never on another text nor, where there is room, on the curve.
    title : str
    positions : sequence of int, optional
        The number of each position (default 1, 2, ...).
    jump_label : str, optional
        The legend's words for the jumps of ``sweep`` (default: "jump: a load switches").
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The curve (F cos G, F sin G) is its first line; arrows give the order of the
        positions; the vector of position 1 is drawn from the pole O.
    """
    F = np.asarray(F, dtype=float)
    G = np.asarray(G, dtype=float)
    if F.shape != G.shape or F.ndim != 1:
        raise ValueError(f"F and G must be 1-D arrays of the same length, not {F.shape} "
                         f"and {G.shape}")
    numbers = list(range(1, F.size + 1)) if positions is None else list(positions)
    if len(numbers) != F.size:
        raise ValueError(f"positions has {len(numbers)} numbers for {F.size} positions")
    figure, (ax,) = _axes(ax, size=(6.8, 7.0))
    x, y = F * np.cos(G), F * np.sin(G)
    if sweep is not None:
        fd, gd = (np.asarray(v, dtype=float) for v in sweep)
        if fd.shape != gd.shape or fd.ndim != 1 or fd.size < 2:
            raise ValueError("sweep must be two 1-D arrays (modulus, direction) of the "
                             "same length")
        cx, cy = fd * np.cos(gd), fd * np.sin(gd)
    else:
        cx, cy = x, y
    jumps = _jumps(cx, cy) if sweep is not None else np.array([], dtype=int)
    bx, by = cx.copy(), cy.copy()
    if jumps.size:                               # break the curve at each jump
        bx = np.insert(bx, jumps + 1, np.nan)
        by = np.insert(by, jumps + 1, np.nan)
    ax.plot(bx, by, "-", color="C0", lw=1.4, label=label or "hodograph of the reaction")
    for j, k in enumerate(jumps):
        ax.plot(cx[k:k + 2], cy[k:k + 2], ":", color="0.45", lw=1.0,
                label=(jump_label or "jump: a load switches") if j == 0 else None)
    every = mark_every or max(1, math.ceil(F.size / 40))   # at most about 40 numbers
    ax.plot(x[::every], y[::every], ".", color="C0", ms=5,
            label=f"the {len(x[::every])} positions, numbered" if sweep is not None else None)
    # arrows along the curve, in the order of the positions (not across a jump)
    n = cx.size
    for k in range(0, n - 1, max(1, n // 8)):
        if k in jumps:
            k += 1
        if k < n - 1 and math.hypot(cx[k + 1] - cx[k], cy[k + 1] - cy[k]) > 0:
            ax.annotate("", (0.5 * (cx[k] + cx[k + 1]), 0.5 * (cy[k] + cy[k + 1])),
                        (cx[k], cy[k]), arrowprops=dict(arrowstyle="-|>", color="C0", lw=1.0,
                                                        mutation_scale=12))
    ax.annotate("", (x[0], y[0]), (0.0, 0.0),
                arrowprops=dict(arrowstyle="-|>", color="C3", lw=1.2, mutation_scale=14))
    ax.plot([0.0, x[0]], [0.0, y[0]], "-", color="C3", lw=1.2,
            label=f"reaction at position {numbers[0]}, {F[0]:.0f} N")
    ax.plot([0.0], [0.0], "o", color="k", ms=4, label="pole O (zero force)")
    ax.plot([], [], "-", color="C0", marker=r"$\rightarrow$", ms=10, lw=0,
            label="arrows: order of the positions")
    labels = [_label(ax, "O", (0.0, 0.0))]
    same = np.hypot(x - x[0], y - y[0]) < 1e-9 * max(np.max(F), 1e-300)
    shown = [k for k in range(0, F.size, every) if not (k > 0 and same[k])]
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("reaction, x component, N")
    ax.set_ylabel("reaction, y component, N")
    ax.grid(True, lw=0.3)
    _legend(ax)
    _title(figure, [ax], title)
    zoomed = _zoom(figure, ax, cx, cy, jumps, x, y, shown, numbers, labels) \
        if sweep is not None and getattr(figure, "_sarkp_own", False) else set()
    for k in shown:
        if k not in zoomed:         # the last position closes the turn on the first
            labels.append(_label(ax, str(numbers[k]), (x[k], y[k]), color="C0", fontsize=7,
                                 optional=k > 0))
    _place_labels(figure, labels)
    return figure


# the insets' corners (axes fractions; their tick labels stay inside the Axes) and size
_INSETS = tuple((fx, fy, w, h) for w, h in ((0.32, 0.30), (0.32, 0.20))
                for fy in (0.64, 0.40, 0.14) for fx in (0.14, 0.40, 0.64))


def _zoom(figure, ax, cx, cy, jumps, x, y, shown, numbers, labels):
    """Where the dense curve falls into pieces between its jumps, each too small to read
    (under a fifth of the drawing), each piece is drawn again enlarged in an inset at a
    free corner of the Axes (no line there), with its positions numbered there; returns
    the positions numbered in the insets (``labels`` gets their labels)."""
    n = cx.size
    bounds = [0, *(jumps + 1), n]
    pieces = [np.arange(a, b) for a, b in zip(bounds[:-1], bounds[1:]) if b > a]
    span = max(np.ptp(np.append(cx, 0.0)), np.ptp(np.append(cy, 0.0)), 1e-300)
    if len(pieces) > 1 and math.hypot(cx[-1] - cx[0], cy[-1] - cy[0]) < 1e-9 * span:
        pieces = [np.concatenate([pieces[-1], pieces[0]])] + pieces[1:-1]  # the turn closes
    size = lambda p: max(np.ptp(cx[p]), np.ptp(cy[p]))
    if len(pieces) < 2 or len(pieces) > 4 or max(map(size, pieces)) > 0.2 * span:
        return set()
    figure.draw_without_rendering()
    renderer = _renderer(figure)
    from matplotlib.transforms import Bbox
    ink = _ink(ax, renderer)
    free = []
    for fx, fy, w, h in _INSETS:
        # the inset with its tick labels and its label: 0.12 more to the left and below
        bbox = Bbox(ax.transAxes.transform([(fx - 0.12, fy - 0.12), (fx + w, fy + h)]))
        if _covered(bbox.padded(2), ink) == 0:
            free.append(((fx, fy, w, h), bbox))
    # each position's piece: the piece of the dense point where it lies
    at = [int(np.argmin(np.hypot(cx - x[k], cy - y[k]))) for k in range(len(x))]
    done = set()
    for j, piece in enumerate(pieces):
        if not free:
            break
        centre = ax.transData.transform([(np.mean(cx[piece]), np.mean(cy[piece]))])[0]
        rect, bbox = min(free, key=lambda f: math.hypot(
            (f[1].x0 + f[1].x1) / 2 - centre[0], (f[1].y0 + f[1].y1) / 2 - centre[1]))
        free = [f for f in free if not f[1].overlaps(bbox)]
        order = {int(i): j for j, i in enumerate(piece)}
        members = sorted((k for k in shown if at[k] in order), key=lambda k: order[at[k]])
        if not members:
            continue
        inset = ax.inset_axes(rect)
        inset.plot(cx[piece], cy[piece], "-", color="C0", lw=1.2)
        inset.plot(x[members], y[members], ".", color="C0", ms=4)
        inset.set_aspect("equal", adjustable="datalim")
        inset.margins(0.25)
        inset.tick_params(labelsize=6)
        inset.grid(True, lw=0.3)
        inset.set_xlabel(f"enlarged: positions {numbers[members[0]]} to "
                         f"{numbers[members[-1]]}, N", fontsize=7)
        ax.indicate_inset_zoom(inset, edgecolor="0.5", alpha=0.6)
        for k in members:
            labels.append(_label(inset, str(numbers[k]), (x[k], y[k]), color="C0",
                                 fontsize=7, optional=k > 0))
        done.update(members)
    return done


def speed_diagram(phi, WPR, WPRM=None, *, W1=None, title="", caveat=None, positions=None,
                  ax=None):
    """omega(phi) of the reduction link: DZKNDV's WPR without the flywheel and, if given,
    WPRM with it (DZKNDV rerun with ISC + IMHVK).

    Parameters
    ----------
    phi : array_like
        Crank angle, rad (drawn in degrees).
    WPR, WPRM : array_like
        Angular speed without and with the flywheel, rad/s.
    W1 : float, optional
        The mean speed, drawn dashed.
    title : str
    caveat : str, optional
        A warning drawn on the picture (e.g. a curve that is no physical motion).
    positions : sequence of int, optional
        The book's position number of each phi, on the top axis.
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        ``axes[0].lines[0]`` is WPR, ``lines[1]`` WPRM.
    """
    phi, WPR, WPRM = _curves(phi=phi, WPR=WPR, WPRM=WPRM)
    phi = np.degrees(phi)
    figure, (ax,) = _axes(ax, size=(7.5, 4.8))
    ax.plot(phi, np.asarray(WPR, dtype=float), "-", color="C0", label="without flywheel")
    if WPRM is not None:
        ax.plot(phi, np.asarray(WPRM, dtype=float), "-", color="C1", label="with flywheel")
    if W1 is not None:
        ax.axhline(W1, color="0.5", linestyle="--", linewidth=0.8,
                   label=f"mean speed ω1 = {W1:g} rad/s")
    ax.set_xlabel("crank angle φ, °")
    ax.set_ylabel("angular speed ω, rad/s")
    ax.grid(True, lw=0.3)
    _degree_ticks(ax, phi)
    if caveat:
        ax.set_title(_wrap(caveat, figure.get_figwidth() - 0.8, 8), loc="left", fontsize=8,
                     color="C3")
    if positions is not None:
        _positions_axis(ax, phi, positions)
    _legend(ax)
    _title(figure, [ax], title)
    return figure


# ---- gears -----------------------------------------------------------------------------------

def _involute_flank(rb, r_from, r_to, n=40):
    """Polar (r, theta) of an involute of the base circle rb from radius r_from to r_to,
    theta = inv(alpha_r) = tan(alpha_r) - alpha_r with cos(alpha_r) = rb/r."""
    r = np.linspace(max(r_from, rb), r_to, n)
    alpha = np.arccos(np.clip(rb / r, -1.0, 1.0))
    return r, np.tan(alpha) - alpha


def _wheel_outline(centre, rb, ra, rf, half, z, towards_p, offset, teeth):
    """x, y of a wheel's outline over ``2 teeth + 1`` teeth around ``towards_p``: root
    arcs on the root circle, a radial line up to the base circle (when the root is
    below it), the involute flanks, the tip arcs."""
    rr, th = _involute_flank(rb, max(rb, rf), ra)
    root_ang = half - (np.tan(math.acos(min(1.0, rb / max(rf, rb)))) -
                       math.acos(min(1.0, rb / max(rf, rb))))    # the flank's angle at rf
    pitch = 2 * math.pi / z
    xs, ys = [], []

    def arc(r, a0, a1, n=10):
        a = np.linspace(a0, a1, n)
        xs.append(r * np.cos(a))
        ys.append(r * np.sin(a))
    for j in range(-teeth, teeth + 1):
        axis = towards_p + offset + pitch * j
        # clockwise side (-) up, the tip, the other side down
        a_left = axis - root_ang
        arc(rf, a_left - (pitch - 2 * root_ang) / 2, a_left, 6)       # half a root arc
        if rf < rb:
            xs.append(np.array([rf, rb]) * math.cos(a_left))
            ys.append(np.array([rf, rb]) * math.sin(a_left))
        ang = axis - (half - th)
        xs.append(rr * np.cos(ang))
        ys.append(rr * np.sin(ang))
        arc(ra, axis - (half - th[-1]), axis + (half - th[-1]), 8)
        ang = axis + (half - th)
        xs.append(rr[::-1] * np.cos(ang[::-1]))
        ys.append(rr[::-1] * np.sin(ang[::-1]))
        a_right = axis + root_ang
        if rf < rb:
            xs.append(np.array([rb, rf]) * math.cos(a_right))
            ys.append(np.array([rb, rf]) * math.sin(a_right))
        arc(rf, a_right, a_right + (pitch - 2 * root_ang) / 2, 6)
    return centre[0] + np.concatenate(xs), centre[1] + np.concatenate(ys)


def _ring_outline(centre, rb, ra, rf, half, z, towards_p, teeth):
    """x, y of an internal wheel's outline over ``2 teeth + 1`` spaces around
    ``towards_p``: its spaces have the shape of an external tooth (``half``: the space's
    half angle on the base circle), the flanks run out from the tip circle ``ra``
    (inside) to the root circle ``rf`` (outside), joined by arcs on both circles."""
    rr, th = _involute_flank(rb, ra, rf)
    keep = half - th > 0                       # a space that closes before the root
    rr, th = rr[keep], th[keep]
    pitch = 2 * math.pi / z
    xs, ys = [], []
    for j in range(-teeth, teeth + 1):
        axis = towards_p + pitch * j
        a = np.linspace(axis - pitch + (half - th[0]), axis - (half - th[0]), 12)
        xs.append(ra * np.cos(a))              # the tooth before this space, at its tip
        ys.append(ra * np.sin(a))
        ang = axis - (half - th)
        xs.append(rr * np.cos(ang))
        ys.append(rr * np.sin(ang))
        a = np.linspace(axis - (half - th[-1]), axis + (half - th[-1]), 6)
        xs.append(rr[-1] * np.cos(a))          # the bottom of the space
        ys.append(rr[-1] * np.sin(a))
        ang = axis + (half - th[::-1])
        xs.append(rr[::-1] * np.cos(ang))
        ys.append(rr[::-1] * np.sin(ang))
    return centre[0] + np.concatenate(xs), centre[1] + np.concatenate(ys)


def _half_angle(g):
    """Half the tooth angle of DGMTZK's gear ``g`` on its base circle (rad)."""
    rb, r = g.DB / 2, g.D / 2
    alpha0 = math.acos(rb / r)
    return g.S / (2 * r) + (math.tan(alpha0) - alpha0)


def _draw_mesh(figure, ax, M, wheels, alfaw, teeth, title, caption):
    """Both wheels, their circles, the line of action N1N2 through P (the origin) and
    its active part AB between the tip circles; ``wheels``: per wheel (outline x, y,
    centre, (tip, operating pitch, base, root) radii, name).  Returns the mesh dict."""
    colours = ("tab:blue", "tab:red")
    width = (teeth + 1.5) * math.pi * M
    shown_y = []                               # the outlines' heights inside the x range
    for k, (ox, oy, c, radii, name) in enumerate(wheels):
        shown_y.append(oy[np.abs(ox) <= width])
        ax.plot(ox, oy, "-", color=colours[k], lw=1.3, label=name)
        towards_p = math.atan2(-c[1], -c[0])
        spread = min(math.pi, 1.3 * width / radii[1])
        span = np.linspace(towards_p - spread, towards_p + spread, 200)
        for radius, style, circle in zip(radii, (":", "-.", "--", (0, (1, 3))),
                                         ("tip", "operating pitch", "base", "root")):
            ax.plot(c[0] + radius * np.cos(span), c[1] + radius * np.sin(span),
                    linestyle=style, color=colours[k], lw=0.7, alpha=0.8,
                    label=f"{circle} circle {k + 1}, d = {2 * radius:.2f} mm")
    # the line of action through P, at alpha_w to the common tangent (the x axis); its
    # ends N1, N2 are the feet of the perpendiculars from the centres (the base circles'
    # tangent points)
    direction = np.array([math.cos(alfaw), math.sin(alfaw)])
    n1, n2 = ((w[2] @ direction) * direction for w in wheels)

    def cut(centre, radius):
        """The point of the line P + t*direction on the circle (centre, radius) nearest P."""
        b = direction @ (-centre)
        cc = centre @ centre - radius ** 2
        roots = (-b + np.array([-1.0, 1.0]) * math.sqrt(b * b - cc))
        return roots[np.argmin(np.abs(roots))] * direction

    a_point = cut(wheels[1][2], wheels[1][3][0])          # wheel 2's tip
    b_point = cut(wheels[0][2], wheels[0][3][0])          # wheel 1's tip
    active = float(np.linalg.norm(b_point - a_point))
    ax.plot(*zip(n1, n2), color="k", lw=0.8, label="line of action N1N2")
    if (n1 @ direction) * (n2 @ direction) > 0:     # internal mesh: P outside N1N2
        near = min((n1, n2), key=lambda n: abs(n @ direction))
        ax.plot(*zip(near, np.zeros(2)), ":", color="k", lw=0.8)
    ax.plot(*zip(a_point, b_point), color="k", lw=3.2,
            label=f"active length AB = {active:.2f} mm")
    ax.axvline(0.0, ls="-.", color="0.4", lw=0.6)
    labels = [_label(ax, name, p) for name, p in
              (("P", np.zeros(2)), ("A", a_point), ("B", b_point), ("N1", n1), ("N2", n2))]
    for p in (a_point, b_point, n1, n2, np.zeros(2)):
        ax.plot([p[0]], [p[1]], "o", color="k", ms=3.5, zorder=5)
    ax.set_aspect("equal")
    ax.set_xlim(-width, width)
    heights = np.concatenate(shown_y + [np.array([0.0, a_point[1], b_point[1]])]
                             + [np.array([n[1]]) for n in (n1, n2) if abs(n[0]) <= width])
    ax.set_ylim(heights.min() - M, heights.max() + M)
    ax.set_xlabel("x, mm (along the common tangent at P)")
    ax.set_ylabel("y, mm\n(along the centre line)")
    _legend(ax, ncols=2, prop={"size": 7})
    _title(figure, [ax], title, caption=caption.format(active=active))
    _fit_height(figure, ax)
    _place_labels(figure, labels)
    return {"N1": n1, "N2": n2, "A": a_point, "B": b_point, "active": active}


def gear_mesh(M, Z1, Z2, X1=0.0, X2=0.0, *, teeth=3, title=None, ax=None):
    """Draw an external spur mesh near its pitch point: both wheels' involute teeth with
    their roots, their tip, operating pitch, base and root circles, the line of action
    N1N2 and its active length AB, the contact ratio in the caption.

    The geometry is sarkp's: DGMZPC (operating angle, centre distance, tip shortening) and
    DGMTZK (reference thickness), in the current mode.  Wheel 1 is below, wheel 2 above,
    the pitch point P at the origin, the centre line vertical.

    Parameters
    ----------
    M : float
        Module (mm).
    Z1, Z2 : int
        Tooth numbers.
    X1, X2 : float
        Shift coefficients.
    teeth : int
        Teeth drawn on each side of the centre line.
    title : str, optional
        The title (default: the wheels' data).
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        The drawing; its attribute ``mesh`` is a dict: ``N1``, ``N2`` the ends of the line
        of action (tangent points on the base circles), ``A``, ``B`` the ends of its active
        part (where the tip circles of wheels 2 and 1 cut it), ``active`` the active length
        ``|AB|``, equal to eps_alpha times the base pitch pi m cos(alpha).
    """
    from .gears import DGMTZK, DGMZPC

    mesh = DGMZPC(M, Z1, Z2, 0.0, X1, X2, 0.0)
    aw, alfaw, dy = mesh.AW, mesh.ALFAW, mesh.XUR
    figure, (ax,) = _axes(ax, size=(7.5, 7.2))
    u = Z2 / Z1
    rw = (aw / (1.0 + u), aw * u / (1.0 + u))             # operating pitch radii
    centres = (np.array([0.0, -rw[0]]), np.array([0.0, rw[1]]))
    wheels = []
    for k, (z, x, c) in enumerate(((Z1, X1, centres[0]), (Z2, X2, centres[1]))):
        g = DGMTZK(M, z, 0.0, x)
        rb, ra, rf = g.DB / 2, g.D / 2 + (1.0 + x - dy) * M, g.DF / 2   # tip shortened by dy
        # wheel 1 has a tooth on the centre line, wheel 2 a space there
        ox, oy = _wheel_outline(c, rb, ra, rf, _half_angle(g), z,
                                math.pi / 2 if k == 0 else -math.pi / 2,
                                0.0 if k == 0 else math.pi / z, teeth)
        wheels.append((ox, oy, c, (ra, rw[k], rb, rf), f"wheel {k + 1}, z{k + 1} = {z:g}"))
    pb = math.pi * M * math.cos(math.pi / 9)
    figure.mesh = _draw_mesh(
        figure, ax, M, wheels, alfaw, teeth,
        title or f"External spur mesh: m = {M:g} mm, z1 = {Z1:g}, z2 = {Z2:g}, "
                 f"x1 = {X1:g}, x2 = {X2:g}",
        f"operating angle αw = {math.degrees(alfaw):.2f}°, centre distance aw = {aw:.3f} mm; "
        f"contact ratio εα = AB / pb = {{active:.2f}} / {pb:.2f} = {mesh.E:.3f} (DGMZPC's E)")
    return figure


def internal_mesh(M, Z1, Z2, X1, X2, ZO2, DO, XO, DAO, *, teeth=3, title=None, ax=None):
    """Draw an internal spur mesh near its pitch point: the pinion's teeth and the ring's
    (cut by a shaper), their tip, operating pitch, base and root circles, the line of
    action N1N2 and its active length AB, the contact ratio in the caption.

    The geometry is DGMZVN's (operating angle, pitch, tip and root diameters, in the
    current mode) and DGMTZK's (reference thicknesses: the ring's space is the tooth of
    an external gear with its shift).  Both centres are below the pitch point P, at the
    origin; the centre line is vertical.

    Parameters
    ----------
    M : float
        Module (mm).
    Z1, Z2 : int
        Teeth of the pinion and of the ring.
    X1, X2 : float
        Shift coefficients (the ring's positive away from its axis).
    ZO2, DO, XO, DAO : float
        The shaper that cuts the ring, as :func:`sarkp.DGMZVN` takes them.
    teeth : int
        Teeth drawn on each side of the centre line.
    title : str, optional
    ax : matplotlib.axes.Axes, optional

    Returns
    -------
    matplotlib.figure.Figure
        Its attribute ``mesh`` is a dict as :func:`gear_mesh`'s: ``active`` = ``|AB|``
        equals DGMZVN's EALFA times the base pitch pi m cos(alpha).
    """
    from .gears import DGMTZK, DGMZVN

    mesh = DGMZVN(M, Z1, Z2, X1, X2, ZO2, DO, XO, DAO)
    figure, (ax,) = _axes(ax, size=(7.5, 7.2))
    rw = (mesh.DW1 / 2, mesh.DW2 / 2)
    centres = (np.array([0.0, -rw[0]]), np.array([0.0, -rw[1]]))
    g1, g2 = DGMTZK(M, Z1, 0.0, X1), DGMTZK(M, Z2, 0.0, X2)
    ox, oy = _wheel_outline(centres[0], g1.DB / 2, mesh.DA1 / 2, mesh.DF1 / 2, _half_angle(g1),
                            Z1, math.pi / 2, 0.0, teeth)
    rx, ry = _ring_outline(centres[1], g2.DB / 2, mesh.DA2 / 2, mesh.DF2 / 2, _half_angle(g2),
                           Z2, math.pi / 2, teeth)
    wheels = [(ox, oy, centres[0], (mesh.DA1 / 2, rw[0], g1.DB / 2, mesh.DF1 / 2),
               f"pinion, z1 = {Z1:g}"),
              (rx, ry, centres[1], (mesh.DA2 / 2, rw[1], g2.DB / 2, mesh.DF2 / 2),
               f"ring (internal teeth), z2 = {Z2:g}")]
    pb = math.pi * M * math.cos(math.pi / 9)
    figure.mesh = _draw_mesh(
        figure, ax, M, wheels, mesh.ALFAW, teeth,
        title or f"Internal spur mesh: m = {M:g} mm, z1 = {Z1:g}, z2 = {Z2:g}, "
                 f"x1 = {X1:g}, x2 = {X2:g}",
        f"operating angle αw = {math.degrees(mesh.ALFAW):.2f}°, centre distance "
        f"aw = {mesh.AW:.3f} mm; contact ratio εα = AB / pb = {{active:.2f}} / {pb:.2f} = "
        f"{mesh.EALFA:.3f} (DGMZVN's EALFA)")
    return figure
