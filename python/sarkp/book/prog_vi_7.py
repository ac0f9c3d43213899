"""The example of DGMZVN (listing VI.7, L4512-4631): Fig. 48, two internal meshes cut
by a shaper (z0 = 25, d0 = 75, x0 = 0.17, d_a0 = 83.8), calls L4650-4652.
Output: Fig. 48 (L4656-4730).  (а)'s AW = 52.4986 < A = 52.5 with XD = 0 is DUGINV's early
stop (E-DUGINV-1).  Three printed cells sit on rounding edges of the ES EVM's REAL*4
(E-FIG48-1): :func:`emulate` repeats the machine's arithmetic for them (they are marked
not reproducible in data/fig48.csv and checked by tests/test_gears.py).
"""

from __future__ import annotations

from ..gears import DGMZVN
from .es_evm import ACOS as _ACOS, COS as _COS, Real4 as _R4, TAN as _TAN
from .prog_vi_6 import _duginv

LISTING = "VI.7"
TITLE = "Internal involute mesh (DGMZVN example, chapter 6)"
FIGURES = ("48",)
CALLS = {"a": (3.0, 16.0, 51.0, 0.25, 0.25, 25.0, 75.0, 0.17, 83.8),
         "b": (3.0, 25.0, 31.0, 0.17, 1.2, 25.0, 75.0, 0.17, 83.8)}
CORRECTED_DIFFERENCES = {"*": "E-DUGINV-1 (corrected: the exact alpha_w and alpha_w02)"}


def cells() -> dict:
    out = {}
    for row, call in CALLS.items():
        result = DGMZVN(*call)
        for name, value in zip(result._fields, result):
            out[(row, name)] = float(value)
    return out


def render() -> str:
    return "\n".join(DGMZVN.spec.report({}, tuple(DGMZVN(*call))) for call in CALLS.values())


def emulate(calls=None) -> dict:
    """DGMZVN (L4544-4601, with E-DGMZVN-1..3) statement by statement in the ES EVM's
    truncating hexadecimal REAL*4, left to right as written; library functions are the
    exact values truncated.  Independent of sarkp's Fortran: the evidence for E-FIG48-1.
    Returns ``{(row, name): value}`` keyed as :func:`cells`; ``calls`` ({row: DGMZVN's
    inputs without AAA}) replaces the figure's calls (program X uses it for Fig. 87)."""
    out = {}
    for row, call in (CALLS if calls is None else calls).items():
        m, z1, z2, x1, x2, zo2, _, xo, dao = (_R4(v) for v in call)
        pi = _R4(3.14159)
        one, two = _R4(1.0), _R4(2.0)
        a = m * (z2 - z1) / two
        alfa = pi / _R4(9.0)
        xd = x2 - x1
        invalw = _TAN(alfa) - alfa + two * xd * _TAN(alfa) / (z2 - z1)
        alfaw = _duginv(invalw, pi / _R4(18.0), _R4(0.00001))
        aw = a * _COS(alfa) / _COS(alfaw)
        d1, d2 = m * z1, m * z2
        u = z2 / z1
        dw1 = two * aw / (u - one)
        dw2 = two * aw * u / (u - one)
        xy = (aw - a) / m
        xur = xd - xy
        invo2 = two * (x2 - xo) * _TAN(alfa) / (z2 - zo2) + _TAN(alfa) - alfa
        alfao2 = _duginv(invo2, pi / _R4(18.0), _R4(0.00001))
        awo2 = (z2 - zo2) * m * _COS(alfa) / (two * _COS(alfao2))
        xyo2 = awo2 / m - (z2 - zo2) / two
        xuro2 = x2 - xo - xyo2
        k2 = _R4(0.25) - _R4(0.125) * x2
        da1 = d1 + two * (one + x1 + xur - xuro2) * m
        da2 = d2 - two * (one - x2 + xur - k2) * m
        df1 = d1 - two * (_R4(1.25) - x1) * m
        df2 = two * awo2 + dao
        h1 = (da1 - df1) / two
        h2 = (df2 - da2) / two
        ala1 = _ACOS(m * z1 * _COS(alfa) / da1)
        ala2 = _ACOS(m * z2 * _COS(alfa) / da2)
        ealfa = (z1 * _TAN(ala1) - z2 * _TAN(ala2) + (z2 - z1) * _TAN(alfaw)) / (two * pi)
        sa1 = da1 * ((_R4(0.5) * pi + two * x1 * _TAN(alfa)) / z1 + (_TAN(alfa) - alfa)
                     - (_TAN(ala1) - ala1))
        sa2 = da2 * ((_R4(0.5) * pi - two * x2 * _TAN(alfa)) / z2 - (_TAN(alfa) - alfa)
                     + (_TAN(ala2) - ala2))
        values = (a, xd, alfaw, aw, d1, d2, dw1, dw2, xy, xur, da1, da2, df1, df2, h1, h2,
                  sa1, sa2, ealfa)
        for name, value in zip(DGMZVN.spec.outputs, values):
            out[(row, name)] = float(value)
    return out


def evidence(number: str = "48"):
    """Fig. 48 run in the ES EVM's arithmetic (:func:`emulate`), for
    :func:`sarkp.book.figures.classify`."""
    from .figures import Evidence
    return Evidence(book=emulate())


#: the names (without suffix) of the pictures :func:`plots` writes
PICTURES = ("vi7_mesh_a", "vi7_mesh_b")


def plots(directory, *, format: str = "png", dpi: float | None = None) -> list:
    """Write the two internal meshes of Fig. 48 (:func:`sarkp.plot.internal_mesh`) as
    ``format`` files (png, svg or pdf) in ``directory``; return their paths.  Needs
    matplotlib."""
    from pathlib import Path

    from .. import plot

    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    written = []
    for (row, call), name in zip(CALLS.items(), PICTURES):
        m, z1, z2, x1, x2 = call[:5]
        figure = plot.internal_mesh(*call, title=plot.mode_title(
            f"VI.7 ({row}): internal mesh, m = {m:g} mm, z1 = {z1:g}, z2 = {z2:g}, "
            f"x1 = {x1:g}, x2 = {x2:g}, ring cut by a shaper z0 = {call[5]:g}"))
        written.append(plot.save(figure, directory / name, format=format, dpi=dpi))
    return written
