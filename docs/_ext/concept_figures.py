"""The pictures of docs/concepts.md, drawn from sarkp's own solution.

Each picture places its joints with :class:`sarkp.Mechanism` (so the picture is what the
solver computes, not a sketch) and draws them with matplotlib: frame pivots as hatched
triangles, guides as hatched lines, sliders as blocks, the joints named.  docs/conf.py
writes them into ``docs/_generated/img`` on every build (``python concept_figures.py DIR``
does the same by hand); tests/test_docs.py checks them as drawing sheets.

* ``kinds.png``: the five kinds of class II group (RRR, RRP, RPR, PRP, RPP), each in a
  small mechanism driven by a crank O-A, the group's links in colour;
* ``branches.png``: branch +1 beside branch -1 for the three kinds that have two
  assemblies (RRR, RRP, RPR), with the directed line the branch is measured from;
* ``signs.png``: the sign conventions: angles counter-clockwise from +x, a velocity as
  the book's (modulus, direction) pair and as sarkp's Cartesian (vx, vy).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

import sarkp

GROUP = "tab:blue"
CRANK = "tab:grey"
PHI = math.radians(60.0)          # the crank angle every picture is drawn at


# ---- the mechanisms, one per kind (the examples of tests/test_mechanism.py) ------------

def rrr(branch=1):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.4, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3, branch=branch)
    return m


def rrp(branch=1):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, -0.05)
    m.crank("A", "O", 0.1)
    m.rrp("B", "A", "K", 0.0, 0.3, branch=branch)
    return m


def rpr(branch=1):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.0, -0.25)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.06, math.pi / 2, branch=branch)
    return m


def prp():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, 0.15)
    m.crank("A", "O", 0.1)
    m.prp("B", "A", math.pi / 2, "G", 0.0, guide_m=("O", "A"))
    return m


def rpp():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, -0.2)
    m.crank("A", "O", 0.1)
    m.rpp("K", "G", 0.0, "A", math.pi / 2)
    return m


# ---- drawing primitives ------------------------------------------------------------------

def _pivot(ax, p, size):
    x, y = p
    ax.fill([x, x - 0.6 * size, x + 0.6 * size], [y, y - size, y - size],
            facecolor="white", edgecolor="k", lw=1.0, zorder=3)
    ax.plot([x - size, x + size], [y - size, y - size], "k", lw=1.0, zorder=3)
    for k in range(5):
        x0 = x - size + 0.4 * size * k
        ax.plot([x0, x0 - 0.3 * size], [y - size, y - 1.35 * size], "k", lw=0.7)
    ax.plot([x], [y], "o", color="white", mec="k", ms=5, zorder=4)


def _guide(ax, p, angle, half, fixed=True, color="k"):
    u = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([math.sin(angle), -math.cos(angle)])        # the right-hand normal
    a, b = np.asarray(p) - half * u, np.asarray(p) + half * u
    ax.plot([a[0], b[0]], [a[1], b[1]], color=color, lw=1.5, zorder=1)
    if fixed:
        for s in np.linspace(-half, half, 13):
            q = np.asarray(p) + s * u
            r = q + 0.012 * n - 0.012 * u
            ax.plot([q[0], r[0]], [q[1], r[1]], color=color, lw=0.6, zorder=1)


def _slider(ax, p, angle, size, color):
    u = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([-u[1], u[0]])
    corners = [np.asarray(p) + a * size * u + b * 0.6 * size * n
               for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    xs, ys = zip(*corners)
    ax.fill(xs, ys, facecolor="white", edgecolor=color, lw=1.8, zorder=4)


def _link(ax, p, q, color, lw=2.5):
    ax.plot([p[0], q[0]], [p[1], q[1]], "-", color=color, lw=lw, solid_capstyle="round",
            zorder=2)


def _joint(ax, p, color="k"):
    ax.plot([p[0]], [p[1]], "o", color="white", mec=color, mew=1.5, ms=6, zorder=5)


def _name(ax, p, text, away, dist=0.035):
    """Name point p, ``dist`` away from the point ``away`` (the picture's middle)."""
    d = np.asarray(p, float) - np.asarray(away, float)
    norm = math.hypot(*d)
    d = d / norm if norm > 1e-12 else np.array([0.0, 1.0])
    ax.text(p[0] + dist * d[0], p[1] + dist * d[1], text, ha="center", va="center",
            fontsize=10, zorder=6)


#: the same window for every panel, so that the kinds are drawn to one scale
WINDOW = ((-0.25, 0.5), (-0.33, 0.37))


def _frame(ax, title):
    ax.set_xlim(*WINDOW[0])
    ax.set_ylim(*WINDOW[1])
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.tick_params(labelsize=8)


def _solve(m):
    return m.solve(np.array([PHI]), need="positions")


def _positions(m, r):
    return {n: r.position(n)[0] for n in m.joints}


# ---- one picture per kind ----------------------------------------------------------------

def draw_rrr(ax, branch=1, title=None):
    m = rrr(branch)
    P = _positions(m, _solve(m))
    mid = np.mean(list(P.values()), axis=0)
    _link(ax, P["O"], P["A"], CRANK)
    _link(ax, P["A"], P["B"], GROUP)
    _link(ax, P["C"], P["B"], GROUP)
    for n in "OC":
        _pivot(ax, P[n], 0.03)
    for n in "AB":
        _joint(ax, P[n], GROUP)
    for n in "OACB":
        _name(ax, P[n], n, mid)
    _frame(ax, title or "RRR (kind 1): m.rrr")
    return P


def draw_rrp(ax, branch=1, title=None):
    m = rrp(branch)
    P = _positions(m, _solve(m))
    mid = np.mean(list(P.values()), axis=0)
    _guide(ax, (0.05, -0.05), 0.0, 0.35)
    _link(ax, P["O"], P["A"], CRANK)
    _link(ax, P["A"], P["B"], GROUP)
    _slider(ax, P["B"], 0.0, 0.03, GROUP)
    _joint(ax, P["B"], GROUP)
    _joint(ax, P["A"], GROUP)
    _pivot(ax, P["O"], 0.03)
    ax.plot(*P["K"], "k+", ms=8)
    for n in "OAB":
        _name(ax, P[n], n, mid, 0.045 if n == "B" else 0.035)
    _name(ax, P["K"], "K", P["K"] + (0.0, 1.0), 0.035)
    _frame(ax, title or "RRP (kind 2): m.rrp")
    return P


def draw_rpr(ax, branch=1, title=None):
    m = rpr(branch)
    r = _solve(m)
    P = _positions(m, r)
    mid = np.mean(list(P.values()), axis=0)
    axis = float(r.angle("C", "B")[0])
    u = np.array([math.cos(axis), math.sin(axis)])
    _link(ax, P["O"], P["A"], CRANK)
    _link(ax, P["C"], P["C"] + 0.36 * u, GROUP)                 # link 3, its axis
    _link(ax, P["A"], P["B"], GROUP, lw=1.5)                    # the slider's arm
    _slider(ax, P["B"], axis, 0.025, GROUP)
    _joint(ax, P["A"], GROUP)
    for n in "OC":
        _pivot(ax, P[n], 0.03)
    for n in "OACB":
        _name(ax, P[n], n, mid if n != "B" else P["A"], 0.04)
    _frame(ax, title or "RPR (kind 3): m.rpr")
    return P


def draw_prp(ax, title=None):
    m = prp()
    r = _solve(m)
    P = _positions(m, r)
    mid = np.mean(list(P.values()), axis=0)
    _guide(ax, P["G"] + (0.05, 0.0), 0.0, 0.25)
    _link(ax, P["O"], P["A"], CRANK)
    slot = PHI + math.pi / 2                                     # the crank's guide
    u = np.array([math.cos(slot), math.sin(slot)])
    _link(ax, P["A"] - 0.03 * u, P["B"] + 0.05 * u, CRANK, lw=1.5)
    _slider(ax, P["B"], slot, 0.025, GROUP)
    _slider(ax, P["B"], 0.0, 0.025, GROUP)
    _joint(ax, P["B"], GROUP)
    _joint(ax, P["A"], CRANK)
    _pivot(ax, P["O"], 0.03)
    ax.plot(*P["G"], "k+", ms=8)
    _name(ax, P["O"], "O", mid)
    _name(ax, P["A"], "A", P["B"])
    _name(ax, P["B"], "B", P["A"], 0.05)
    _name(ax, P["G"], "G", P["G"] - (0.0, 1.0), 0.04)
    _frame(ax, title or "PRP (kind 4): m.prp")
    return P


def draw_rpp(ax, title=None):
    m = rpp()
    r = _solve(m)
    P = _positions(m, r)
    mid = np.mean(list(P.values()), axis=0)
    _guide(ax, P["G"], 0.0, 0.22)
    _link(ax, P["O"], P["A"], CRANK)
    # the yoke: a vertical slot through K, standing on the guide
    top = P["K"] + (0.0, 0.32)
    _link(ax, P["K"], top, GROUP)
    _slider(ax, P["K"], 0.0, 0.035, GROUP)
    _slider(ax, P["A"], math.pi / 2, 0.022, GROUP)
    _joint(ax, P["A"], GROUP)
    _pivot(ax, P["O"], 0.03)
    _name(ax, P["O"], "O", P["A"], 0.04)
    _name(ax, P["A"], "A", mid + (-1.0, 0.0), 0.05)
    _name(ax, P["K"], "K", P["K"] + (0.0, 1.0), 0.055)
    _name(ax, P["G"], "G", P["G"] + (0.0, 1.0), 0.035)
    _frame(ax, title or "RPP (kind 5): m.rpp")
    return P


# ---- the pictures ------------------------------------------------------------------------

def _figure(size):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    figure = Figure(figsize=size, layout="constrained")
    FigureCanvasAgg(figure)               # a renderer, as sarkp.plot's figures have
    return figure


def kinds():
    fig = _figure((11.0, 7.0))
    axes = fig.subplots(2, 3)
    draw_rrr(axes[0, 0])
    draw_rrp(axes[0, 1])
    draw_rpr(axes[0, 2])
    draw_prp(axes[1, 0])
    draw_rpp(axes[1, 1])
    axes[1, 2].set_visible(False)
    fig.suptitle(f"The five kinds of class II group, each driven by a crank O-A "
                 f"(grey) at phi = {math.degrees(PHI):.0f} deg; the group in blue")
    return fig


def _directed(ax, p, q, label):
    """The directed line p -> q that a branch is measured from, dashed, with its arrow."""
    p, q = np.asarray(p), np.asarray(q)
    ax.annotate("", xy=q, xytext=p, zorder=1,
                arrowprops=dict(arrowstyle="->", color="tab:red", ls="--", lw=1.0))


def branches():
    fig = _figure((9.0, 12.0))
    axes = fig.subplots(3, 2)
    for col, b in enumerate((1, -1)):
        P = draw_rrr(axes[0, col], b, f"RRR, branch={b:+d}: B "
                     f"{'left' if b > 0 else 'right'} of A->C")
        _directed(axes[0, col], P["A"], P["C"], "A->C")
        P = draw_rrp(axes[1, col], b, f"RRP, branch={b:+d}: B "
                     f"{'ahead of' if b > 0 else 'behind'} the foot of A")
        foot = np.array([P["A"][0], -0.05])
        axes[1, col].plot([P["A"][0], foot[0]], [P["A"][1], foot[1]], ":", color="tab:red")
        P = draw_rpr(axes[2, col], b, f"RPR, branch={b:+d}: B "
                     f"{'left' if b > 0 else 'right'} of A->C")
        _directed(axes[2, col], P["A"], P["C"], "A->C")
    fig.suptitle(f"Branch +1 (left) and -1 (right) at phi = {math.degrees(PHI):.0f} deg; "
                 f"red: what the branch is measured from")
    return fig


def _arc(ax, centre, radius, start, stop, color, text, text_radius=None):
    """An arc from angle ``start`` to ``stop`` (counter-clockwise) about ``centre``."""
    t = np.linspace(start, stop, 40)
    x0, y0 = centre
    ax.plot(x0 + radius * np.cos(t), y0 + radius * np.sin(t), color=color, lw=1.2)
    ax.annotate("", xy=(x0 + radius * math.cos(stop), y0 + radius * math.sin(stop)),
                xytext=(x0 + radius * math.cos(t[-3]), y0 + radius * math.sin(t[-3])),
                arrowprops=dict(arrowstyle="-|>", color=color, lw=1.2))
    ax.plot([x0, x0 + 1.6 * radius], [y0, y0], ":", color="k", lw=0.8)      # +x
    mid = 0.5 * (start + stop)
    rt = text_radius or 1.45 * radius
    ax.text(x0 + rt * math.cos(mid), y0 + rt * math.sin(mid), text, color=color,
            fontsize=9, ha="center", va="center")


def signs():
    m = rrr(1)
    r = m.solve(np.array([PHI]), omega=10.0, need="velocities")
    P = _positions(m, r)
    v = r.velocity("B")[0]
    w3 = float(r.omega("C", "B")[0])
    fi3 = float(r.angle("C", "B")[0])
    fig = _figure((7.0, 6.0))
    ax = fig.subplots()
    draw_rrr(ax, 1, "")
    ax.set_xlim(-0.12, 0.62)
    ax.set_ylim(-0.27, 0.42)
    scale = 0.25                          # m of drawing per m/s
    B = P["B"]
    ax.annotate("", xy=B + scale * v, xytext=B,
                arrowprops=dict(arrowstyle="-|>", color="tab:green", lw=2))
    ax.text(*(B + scale * v + (-0.01, 0.025)), "v_B", color="tab:green", fontsize=10,
            ha="center")
    speed, direction = math.hypot(*v), math.atan2(v[1], v[0]) % (2 * math.pi)
    _arc(ax, B, 0.065, 0.0, direction, "tab:green", "ALB", 0.09)
    _arc(ax, P["O"], 0.05, 0.0, PHI, "tab:orange", "φ")
    _arc(ax, P["C"], 0.05, 0.0, fi3, "tab:purple", "FI3", 1.7 * 0.05)
    ax.text(0.25, -0.12,
            f"crank: omega = +10 rad/s (counter-clockwise)\n"
            f"v_B, Cartesian (r.velocity('B')): ({v[0]:+.3f}, {v[1]:+.3f}) m/s\n"
            f"v_B, the book's pair (VB, ALB): {speed:.3f} m/s at "
            f"{math.degrees(direction):.1f} deg\n"
            f"link C-B: angle FI3 = {math.degrees(fi3):.1f} deg, omega = {w3:+.3f} rad/s "
            f"({'counter-clockwise' if w3 > 0 else 'clockwise'})", fontsize=8.5,
            ha="center", va="center",
            bbox=dict(facecolor="white", edgecolor="0.7"))
    ax.set_title(f"Angles count counter-clockwise from +x (phi = {math.degrees(PHI):.0f} "
                 f"deg); an angular velocity is positive counter-clockwise", fontsize=9)
    fig.suptitle("Sign conventions (the RRR four-bar, branch +1)")
    return fig


PICTURES = {"kinds": kinds, "branches": branches, "signs": signs}


def write(folder) -> list[Path]:
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for name, draw in PICTURES.items():
        path = folder / f"concepts-{name}.png"
        draw().savefig(path, dpi=90)
        out.append(path)
    return out


if __name__ == "__main__":
    for p in write(sys.argv[1] if len(sys.argv) > 1 else "."):
        print(p)
