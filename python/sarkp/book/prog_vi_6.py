"""The example of DGMZPC (listing VI.6, L4410-4454): Fig. 47, two external meshes.

The calls as printed (L4482-4483) are garbled: (а) lost one 0.5 and (б) has one 0.0 too
many (E-FIG47-2); XS = 1.0000 and E = 2.7280 prove
(а) ``DGMZPC(5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0, 0.0)`` and
(б) ``DGMZPC(7.0, 18.0, 60.0, (PI/180.0)*16.0, 0.0, 0.0, 100.0, 0.0)``.
Output: Fig. 47 (L4456-4476).  (б)'s AW = 283.9946 < A with XS = 0 is DUGINV's early stop
(E-DUGINV-1); its last digit needs the ES EVM's hexadecimal arithmetic (E-FIG47-1), which
:func:`emulate` repeats (the cell is marked not reproducible in data/fig47.csv and checked
against the emulation by tests/test_gears.py).
"""

from __future__ import annotations

from ..gears import DGMZPC
from ..modes import book_pi
from .es_evm import ACOS as _ACOS, ATAN as _ATAN, COS as _COS, Real4 as _R4, SIN as _SIN, \
    TAN as _TAN

LISTING = "VI.6"
TITLE = "External involute mesh (DGMZPC example, chapter 6)"
FIGURES = ("47",)
CORRECTED_DIFFERENCES = {"*": "E-DUGINV-1 (corrected: the exact alpha_w), E-DGMZPC-3 "
                              "(corrected: the helical gear's tip and base circles)"}


def _calls():
    return {"a": (5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0),
            "b": (7.0, 18.0, 60.0, (book_pi() / 180.0) * 16.0, 0.0, 0.0, 100.0)}


def cells() -> dict:
    out = {}
    for row, call in _calls().items():
        result = DGMZPC(*call)
        for name, value in zip(result._fields, result):
            out[(row, name)] = float(value)
    return out


def render() -> str:
    return "\n".join(DGMZPC.spec.report({}, tuple(DGMZPC(*call))) for call in _calls().values())



def _duginv(invx, xnach, tchnst):
    """VI.4 (L4209-4215) in the ES EVM's arithmetic."""
    x = xnach
    while True:
        x1 = _ATAN(x + invx)
        if abs(x1 - x) - tchnst < 0.0:
            return x1
        x = x1


def emulate(calls=None) -> dict:
    """DGMZPC (L4420-4443, with E-DGMZPC-1, -2) statement by statement in the ES EVM's
    truncating hexadecimal REAL*4, left to right as written; library functions are the
    exact values truncated.  Independent of sarkp's Fortran: the evidence for E-FIG47-1.
    Returns ``{(row, name): value}`` keyed as :func:`cells`; ``calls`` ({row: (M, Z1, Z2,
    BETA, X1, X2, BW)}, BETA None for 16 degrees) replaces the figure's calls (program X
    uses it for Fig. 87)."""
    out = {}
    if calls is None:
        calls = {"a": (5.0, 11.0, 26.0, 0.0, 0.5, 0.5, 30.0),
                 "b": (7.0, 18.0, 60.0, None, 0.0, 0.0, 100.0)}
    for row, call in calls.items():
        pi = _R4(3.14159)
        m, z1, z2, beta, x1, x2, bw = (_R4(v) if v is not None else None for v in call)
        if beta is None:
            beta = pi / _R4(180.0) * _R4(16.0)
        alfa = pi / _R4(9.0)
        alfat = _ATAN(_TAN(alfa) / _COS(beta))
        a = (z1 + z2) * m / (_R4(2.0) * _COS(beta))
        xs = x1 + x2
        invalw = (_R4(2.0) * xs * _TAN(alfa)) / (z1 + z2) + _TAN(alfat) - alfat
        alfaw = _duginv(invalw, pi / _R4(18.0), _R4(0.00001))
        aw = (z1 + z2) * m * _COS(alfat) / (_R4(2.0) * _COS(beta) * _COS(alfaw))
        xy = (aw - a) / m
        xur = xs - xy
        da1 = m * z1 + _R4(2.0) * (_R4(1.0) + x1 - xur) * m
        da2 = m * z2 + _R4(2.0) * (_R4(1.0) + x2 - xur) * m
        ala1 = _ACOS(m * z1 * _COS(alfa) / da1)
        ala2 = _ACOS(m * z2 * _COS(alfa) / da2)
        ealfa = (z1 * _TAN(ala1) + z2 * _TAN(ala2) - (z1 + z2) * _TAN(alfaw)) / (_R4(2.0) * pi)
        ebeta = bw * _SIN(beta) / (pi * m)
        for name, value in zip(("A", "XS", "ALFAW", "AW", "XY", "XUR", "E"),
                               (a, xs, alfaw, aw, xy, xur, ealfa + ebeta)):
            out[(row, name)] = float(value)
    return out


def evidence(number: str = "47"):
    """Fig. 47 run in the ES EVM's arithmetic (:func:`emulate`), for
    :func:`sarkp.book.figures.classify`."""
    from .figures import Evidence
    return Evidence(book=emulate())


#: the names (without suffix) of the pictures :func:`plots` writes
PICTURES = ("vi6_mesh_a",)


def plots(directory, *, format: str = "png", dpi: float | None = None) -> list:
    """Write the mesh of example (a), the spur pair z1 = 11, z2 = 26, m = 5 mm,
    x1 = x2 = 0.5 (:func:`sarkp.plot.gear_mesh`), as a ``format`` file (png, svg or pdf)
    in ``directory``; return its path in a list.  Example (b) is a helical pair, which
    the drawing of a spur mesh does not show.  Needs matplotlib."""
    from pathlib import Path

    from .. import plot

    m, z1, z2, _, x1, x2, _ = _calls()["a"]
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    figure = plot.gear_mesh(m, z1, z2, x1, x2, title=plot.mode_title(
        f"VI.6 (a): external spur mesh, m = {m:g} mm, z1 = {z1:g}, z2 = {z2:g}, "
        f"x1 = {x1:g}, x2 = {x2:g}"))
    return [plot.save(figure, directory / PICTURES[0], format=format, dpi=dpi)]
