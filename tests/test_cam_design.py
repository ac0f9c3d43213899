"""Chapter 5 as a designer uses it (sarkp extensions): motion laws, roller followers and
exact sizing, each against an independent reference: the laws' closed forms written here
and numerical derivatives; the roller profile against the envelope of the roller circles
(nearest roller centres found by minimisation over the pitch curve written here); the
exact radii against the pressure angle and curvature computed by the book routines, and
against brute force."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

import sarkp
from sarkp import (DPRFLK, DPRFLP, LAW_FACTORS, RequirementError, base_radius,
                   flat_base_radius, motion_law, rocker_centre_distance, roller_rocker,
                   roller_translating)

PI = math.pi
LAWS = sorted(LAW_FACTORS)
RISE, DWELL, RET, DWELL2 = 2.0, 0.5, 1.5, 2 * PI - 4.0


# ---- motion laws ---------------------------------------------------------------------------

CLOSED = {   # f(x), f'(x), f''(x) of the rise, written independently of sarkp
    "harmonic": lambda x: ((1 - np.cos(PI * x)) / 2, PI / 2 * np.sin(PI * x),
                           PI**2 / 2 * np.cos(PI * x)),
    "cycloidal": lambda x: (x - np.sin(2 * PI * x) / (2 * PI), 1 - np.cos(2 * PI * x),
                            2 * PI * np.sin(2 * PI * x)),
    "3-4-5": lambda x: (10 * x**3 - 15 * x**4 + 6 * x**5, 30 * x**2 - 60 * x**3 + 30 * x**4,
                        60 * x - 180 * x**2 + 120 * x**3),
    "constant acceleration": lambda x: (np.where(x < 0.5, 2 * x**2, 1 - 2 * (1 - x)**2),
                                        np.where(x < 0.5, 4 * x, 4 * (1 - x)),
                                        np.where(x < 0.5, 4.0, -4.0)),
}


@pytest.mark.parametrize("law", sorted(CLOSED))
def test_motion_law_is_the_closed_form(law):
    H, W = 0.04, 7.0
    fi = np.linspace(0, 2 * PI, 1001)
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=fi)
    up = fi < RISE
    f, f1, f2 = CLOSED[law](fi[up] / RISE)
    np.testing.assert_allclose(m.S[up], H * f, rtol=0, atol=1e-15)
    np.testing.assert_allclose(m.V[up], W * H * f1 / RISE, rtol=0, atol=1e-14)
    np.testing.assert_allclose(m.A[up], W**2 * H * f2 / RISE**2, rtol=0, atol=1e-12)
    down = (fi >= RISE + DWELL) & (fi < RISE + DWELL + RET)
    f, f1, f2 = CLOSED[law]((fi[down] - RISE - DWELL) / RET)
    np.testing.assert_allclose(m.S[down], H * (1 - f), rtol=0, atol=1e-15)
    np.testing.assert_allclose(m.V[down], -W * H * f1 / RET, rtol=0, atol=1e-14)
    np.testing.assert_allclose(m.A[down], -W**2 * H * f2 / RET**2, rtol=0, atol=1e-12)
    top = (fi >= RISE) & (fi < RISE + DWELL)
    assert np.all(m.S[top] == H) and np.all(m.V[top] == 0) and np.all(m.A[top] == 0)
    rest = fi >= RISE + DWELL + RET
    assert np.all(m.S[rest] == 0) and np.all(m.V[rest] == 0) and np.all(m.A[rest] == 0)


def _interior(count, margin=0.02):
    """Cam angles inside the phases (away from the boundaries and the laws' own knots
    at eighths of a phase, where the acceleration's derivative jumps)."""
    fi = np.linspace(0.01, 2 * PI - 0.01, count)
    knots = [RISE * k / 8 for k in range(9)] + [RISE + DWELL + RET * k / 8 for k in range(9)]
    for b in knots:
        fi = fi[np.abs(fi - b) > margin]
    return fi


@pytest.mark.parametrize("law", LAWS)
def test_motion_law_velocity_and_acceleration_are_derivatives(law):
    H, W, h = 0.05, 3.0, 1e-3
    fi = _interior(200)

    def at(x):
        return motion_law(law, H, RISE, DWELL, RET, W=W, FI=x)

    def d(field, scale):                       # 4th-order central difference in FI
        g = [getattr(at(fi + k * h), field) for k in (-2, -1, 1, 2)]
        return W * (g[0] - 8 * g[1] + 8 * g[2] - g[3]) / (12 * h) / scale

    m = at(fi)
    # truncation h^4 f^(5)/30: (1e-3)^4 (2 pi / 1.5)^5 H W/30 < 1e-13 ... bounded by 1e-9
    np.testing.assert_allclose(d("S", 1.0), m.V, rtol=0, atol=1e-9)
    np.testing.assert_allclose(d("V", 1.0), m.A, rtol=0, atol=1e-8)


@pytest.mark.parametrize("law", LAWS)
def test_motion_law_is_continuous_and_reaches_the_stroke(law):
    H, W, e = 0.03, 2.0, 1e-9
    edges = [RISE, RISE + DWELL, RISE + DWELL + RET]
    for b in edges:
        lo = motion_law(law, H, RISE, DWELL, RET, W=W, FI=[b - e, b])
        assert abs(lo.S[0] - lo.S[1]) < 1e-12 and abs(lo.V[0] - lo.V[1]) < 1e-9
        if law not in ("harmonic", "constant acceleration"):     # no jerk spikes
            assert abs(lo.A[0] - lo.A[1]) < 1e-6
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=[RISE * (1 - 1e-15)])
    assert abs(m.S[0] - H) < 1e-15


@pytest.mark.parametrize("law", LAWS)
def test_peak_factors_are_the_peaks(law):
    H, W = 0.02, 4.0
    # where the peaks are: f' at x = 1/2; f'' at 0 (harmonic), 1/8 (modified sine and
    # trapezoid), 1/4 (cycloidal), (3 - sqrt 3)/6 (3-4-5), anywhere (constant)
    x = np.array([0.0, 0.125, 0.25, 0.5, (3 - math.sqrt(3)) / 6, 0.9])
    fi = np.concatenate([RISE * x, RISE + DWELL + RET * x])
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=fi)
    cv, ca = LAW_FACTORS[law]
    up, down = m.PHASE == 1, m.PHASE == 3
    assert (m.CV, m.CA, m.CV_RETURN, m.CA_RETURN) == (cv, ca, cv, ca)
    assert np.abs(m.V[up]).max() == pytest.approx(cv * H * W / RISE, rel=1e-13)
    assert np.abs(m.A[up]).max() == pytest.approx(ca * H * W**2 / RISE**2, rel=1e-13)
    assert np.abs(m.V[down]).max() == pytest.approx(cv * H * W / RET, rel=1e-13)
    assert np.abs(m.A[down]).max() == pytest.approx(ca * H * W**2 / RET**2, rel=1e-13)
    # and nowhere larger: a fine grid
    g = motion_law(law, H, RISE, DWELL, RET, W=W, N=100001)
    assert np.abs(g.V).max() <= cv * H * W / RET * (1 + 1e-13)
    assert np.abs(g.A).max() <= ca * H * W**2 / RET**2 * (1 + 1e-13)


def test_peak_factors_against_the_literature():
    # the textbook values (e.g. Norton, Cam Design and Manufacturing Handbook, table 3-2)
    printed = {"harmonic": (1.571, 4.935), "cycloidal": (2.000, 6.283),
               "3-4-5": (1.875, 5.774), "modified trapezoid": (2.000, 4.888),
               "modified sine": (1.760, 5.528), "constant acceleration": (2.000, 4.000)}
    for law, (cv, ca) in printed.items():
        assert LAW_FACTORS[law] == pytest.approx((cv, ca), abs=5e-4), law


def test_return_law_and_default_inner_dwell():
    m = motion_law("cycloidal", 0.01, 1.0, 0.5, 2.0, return_law="3-4-5", N=101)
    assert m.FI[-1] == pytest.approx(2 * PI) and (m.CV, m.CV_RETURN) == (2.0, 1.875)
    m2 = motion_law("cycloidal", 0.01, 1.0, 0.5, 2.0, 1.0, N=101)
    assert m2.FI[-1] == pytest.approx(4.5)


@pytest.mark.parametrize("kw, what", [
    (dict(law="sine"), "law"), (dict(H=0.0), "H"), (dict(rise=-1.0), "rise"),
    (dict(dwell=-0.1), "dwell"), (dict(ret=math.nan), "ret"), (dict(W=0.0), "W"),
    (dict(rise=4.0, ret=3.0), "more than a turn"), (dict(N=1), "N"),
    (dict(FI=[7.0]), "FI"), (dict(return_law=3), "return_law")])
def test_motion_law_bad_input_names_the_argument(kw, what):
    args = dict(law="cycloidal", H=0.01, rise=1.0, dwell=0.5, ret=1.0)
    args.update(kw)
    law, H, rise, dwell, ret = (args.pop(k) for k in ("law", "H", "rise", "dwell", "ret"))
    with pytest.raises(ValueError, match=what):
        motion_law(law, H, rise, dwell, ret, **args)


# ---- roller followers ----------------------------------------------------------------------

W = 5.0


def _translating_pitch(phi, law, H, RO, E):
    phi = np.mod(np.atleast_1d(phi), 2 * PI)
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=phi)
    c = RO + m.S
    return E * np.cos(phi) + c * np.sin(phi), -E * np.sin(phi) + c * np.cos(phi)


def _rocker_pitch(phi, law, H, L, R, ETAO):
    phi = np.mod(np.atleast_1d(phi), 2 * PI)
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=phi)
    p = m.S + ETAO
    return L * np.cos(phi) - R * np.cos(phi + p), -L * np.sin(phi) + R * np.sin(phi + p)


def _nearest_centre(pitch, xw, yw, phi0):
    """Distance of (xw, yw) to the nearest roller centre: a scan of the whole pitch curve,
    then a minimisation near the best of the scan and near phi0."""
    grid = np.linspace(0, 2 * PI, 20001)
    gx, gy = pitch(grid)
    scan = np.hypot(gx - xw, gy - yw)
    best = scan.min()
    for start in (grid[np.argmin(scan)], phi0):
        r = minimize_scalar(lambda f: float(np.hypot(*(np.array(pitch(f)).ravel()
                                                        - (xw, yw)))),
                            bounds=(start - 0.01, start + 0.01), method="bounded",
                            options={"xatol": 1e-12})
        best = min(best, r.fun)
    return best


@pytest.mark.parametrize("law", ["cycloidal", "modified sine"])
def test_translating_roller_profile_is_the_envelope(law):
    H, RO, E, RR = 0.03, 0.06, 0.01, 0.012
    fi = np.linspace(0, 2 * PI, 73)[:-1]
    m = motion_law(law, H, RISE, DWELL, RET, W=W, FI=fi)
    p = roller_translating(fi.size, RO, E, W, fi, m.A, m.V, m.S, RR)
    assert not p.UNDERCUT and p.ROKMIN > RR
    pitch = lambda f: _translating_pitch(f, law, H, RO, E)    # noqa: E731
    for k in range(0, fi.size, 3):
        d = _nearest_centre(pitch, p.XW[k], p.YW[k], fi[k])
        assert abs(d - RR) <= 1e-12 * RR, (k, d - RR)
    np.testing.assert_allclose(p.RW, p.ROK - RR)
    # the working profile lies inside the pitch curve (towards the cam centre) on the dwell
    top = (fi > RISE) & (fi < RISE + DWELL)
    np.testing.assert_allclose(np.hypot(p.XW[top], p.YW[top]),
                               math.hypot(RO + H, E) - RR, rtol=1e-13)


def test_rocker_roller_profile_is_the_envelope():
    H, L, R, ETAO, RR = 0.35, 0.12, 0.09, 0.7, 0.01
    fi = np.linspace(0, 2 * PI, 73)[:-1]
    m = motion_law("3-4-5", H, RISE, DWELL, RET, W=W, FI=fi)
    p = roller_rocker(fi.size, W, ETAO, fi, 0.0, L, R, m.A, m.V, m.S, RR)
    assert not p.UNDERCUT and p.ROKMIN > RR
    pitch = lambda f: _rocker_pitch(f, "3-4-5", H, L, R, ETAO)    # noqa: E731
    for k in range(0, fi.size, 3):
        d = _nearest_centre(pitch, p.XW[k], p.YW[k], fi[k])
        assert abs(d - RR) <= 1e-12 * RR, (k, d - RR)


def test_undercut_is_flagged_and_raised_on_request():
    H, RO, RR = 0.03, 0.02, 0.025
    fi = np.linspace(0, 2 * PI, 721)
    m = motion_law("cycloidal", H, RISE, DWELL, RET, W=W, FI=fi)
    p = roller_translating(fi.size, RO, 0.0, W, fi, m.A, m.V, m.S, RR)
    assert p.ROKMIN < RR and p.UNDERCUT
    # where undercut, some roller centre is nearer than RR to the working profile: the
    # roller would cut the cam there
    k = int(np.argmin(np.where(p.ROK > 0, p.ROK, np.inf)))
    pitch = lambda f: _translating_pitch(f, "cycloidal", H, RO, 0.0)   # noqa: E731
    grid = np.linspace(fi[k] - 0.3, fi[k] + 0.3, 6001)
    gx, gy = pitch(grid)
    assert np.hypot(gx - p.XW[k], gy - p.YW[k]).min() < RR * (1 - 1e-3)
    with pytest.raises(RequirementError, match="undercut"):
        roller_translating(fi.size, RO, 0.0, W, fi, m.A, m.V, m.S, RR, on_undercut="raise")
    ok = roller_translating(fi.size, RO, 0.0, W, fi, m.A, m.V, m.S, 0.9 * p.ROKMIN,
                            on_undercut="raise")
    assert not ok.UNDERCUT
    with pytest.raises(ValueError, match="RR"):
        roller_translating(fi.size, RO, 0.0, W, fi, m.A, m.V, m.S, 0.0)


# ---- exact sizing --------------------------------------------------------------------------

def _touches(alfa, where, limit):
    """|alfa| <= limit on ``where``, equal (1e-9) at exactly one point."""
    a = np.abs(alfa[where])
    close = np.abs(a - limit) <= 1e-9
    assert close.sum() == 1, np.sort(a)[-3:]
    assert np.all(a[~close] < limit)


@pytest.mark.parametrize("law, beta, ald, ald_ret", [
    ("cycloidal", 0.35, 0.523, 0.523), ("3-4-5", 0.0, PI / 6, PI / 4),
    ("modified trapezoid", -0.2, PI / 5, PI / 3), ("harmonic", 0.1, 0.6, 0.8)])
def test_base_radius_puts_the_pressure_angle_at_its_limit(law, beta, ald, ald_ret):
    n = 721
    m = motion_law(law, 0.05, RISE, DWELL, RET, W=W, N=n)
    b = base_radius(n, m.FI, m.A, m.V, m.S, W, ald, ald_ret, BETA=beta)
    assert b.RO == max(b.RO_RISE, b.RO_RETURN)
    assert b.EXCST == pytest.approx(b.RO * math.sin(beta)) and \
        b.RO_AXIAL == pytest.approx(b.RO * math.cos(beta))
    p = DPRFLP(n, b.RO_AXIAL, b.EXCST, W, m.FI, m.A, m.V, m.S)
    rise, ret = m.V > 0, m.V < 0
    binding = (rise, ald) if b.RO_RISE >= b.RO_RETURN else (ret, ald_ret)
    _touches(p.ALFA, *binding)
    other = (ret, ald_ret) if binding[0] is rise else (rise, ald)
    assert np.all(np.abs(p.ALFA[other[0]]) < other[1])
    # any smaller cam (same BETA) breaks the limit somewhere
    q = DPRFLP(n, b.RO_AXIAL * (1 - 1e-7), b.EXCST * (1 - 1e-7), W, m.FI, m.A, m.V, m.S)
    assert np.any(np.abs(q.ALFA[binding[0]]) > binding[1])


def test_base_radius_beside_the_books_rule():
    # the case: DKLCHK sizes at the fastest point only and its cam passes the limit
    n = 361
    m = motion_law("cycloidal", 0.05, RISE, DWELL, RISE, W=W, N=n)
    b = base_radius(n, m.FI, m.A, m.V, m.S, W, PI / 6)
    book = sarkp.DKLCHK(n, m.S, m.V, m.A, PI / 6, 0.0, W)
    assert b.RO_BOOK == book.RO and b.RO > book.RO
    p = DPRFLP(n, book.RO, 0.0, W, m.FI, m.A, m.V, m.S)
    assert b.ALFMAX_BOOK == pytest.approx(p.ALFMAX, rel=1e-14) and p.ALFMAX > PI / 6


@pytest.mark.parametrize("law", ["cycloidal", "3-4-5", "harmonic", "modified sine"])
def test_flat_base_radius_keeps_the_profile_convex(law):
    n = 721
    m = motion_law(law, 0.04, RISE, DWELL, RET, W=W, N=n)
    f = flat_base_radius(n, m.FI, m.A, m.V, m.S, W)
    rok = f.RKSH + m.S + m.A / W**2              # the flat-faced cam's curvature radius
    close = np.abs(rok) <= 1e-12 * f.RKSH
    assert close.sum() == 1 and np.all(rok[~close] > 0)
    book = sarkp.DPRFPL(n, PI / 4, W, m.FI, m.A, m.V, m.S)
    assert f.RKSH_BOOK == book.RKSH and f.ROKMIN_BOOK == book.ROKMIN
    assert f.RKSH >= book.RKSH * (1 - 1e-12)


@pytest.mark.parametrize("law, ald, ald_ret", [("3-4-5", math.radians(40), math.radians(40)),
                                                ("cycloidal", math.radians(35),
                                                 math.radians(50))])
def test_rocker_centre_distance_is_the_smallest(law, ald, ald_ret):
    n, R, H = 361, 0.1, 0.4
    m = motion_law(law, H, RISE, DWELL, RET, W=W, N=n)
    c = rocker_centre_distance(n, m.FI, m.A, m.V, m.S, W, R, ald, ald_ret)
    p = DPRFLK(n, W, c.ETAO, m.FI, 0.0, c.L, R, m.A, m.V, m.S)
    rise, ret = m.V > 0, m.V < 0
    over = np.concatenate([np.abs(p.ALFA[rise]) - ald, np.abs(p.ALFA[ret]) - ald_ret])
    assert over.max() <= 1e-12 and over.max() >= -1e-9
    assert 1 <= np.sum(over >= -1e-9) <= 2     # on an edge or at a vertex of the region
    # brute force: for each ETAO the smallest L is a largest lower bound; none beats c.L
    t = np.where(m.V > 0, math.tan(ald), np.where(m.V < 0, math.tan(ald_ret),
                                                   math.tan(min(ald, ald_ret))))
    q = R * (1 + m.V / W)
    best = math.inf
    for eta in np.linspace(-PI, PI, 4001):
        psi = m.S + eta
        # tan(alpha) = (q - L cos)/(L sin) within +-t:  L (cos + t sin) >= q, L (cos - t sin) <= q
        d1, d2 = np.cos(psi) + t * np.sin(psi), np.cos(psi) - t * np.sin(psi)
        if np.any(d1 <= 0):
            continue
        lo = np.max(q / d1)
        hi = np.min(np.where(d2 > 0, q / np.where(d2 > 0, d2, 1), np.inf))
        if lo <= hi:
            best = min(best, lo)
    assert best >= c.L * (1 - 1e-9) and best <= c.L * (1 + 1e-3)
    assert c.RO == pytest.approx(np.hypot(p.XA, p.YA).min(), rel=1e-12)
    book = sarkp.DKLCHK(n, m.S, m.V, m.A, ald, 0.0, W, c.L, R, 2)
    assert (c.ETAO_BOOK, c.RO_BOOK) == (book.ETAO, book.RO)
    # the book's rule for a rocker (the translating formula applied to angles) passes the
    # limit with that centre distance; DPRFLK confirms the figure
    pb = DPRFLK(n, W, book.ETAO, m.FI, 0.0, c.L, R, m.A, m.V, m.S)
    assert c.ALFMAX_BOOK == pytest.approx(pb.ALFMAX, rel=1e-13)
    assert pb.ALFMAX > min(ald, ald_ret)
    # each phase alone needs no more, and the same brute force finds each
    assert max(c.L_RISE, c.L_RETURN) <= c.L * (1 + 1e-12)
    for lone, where, limit in ((c.L_RISE, rise, ald), (c.L_RETURN, ret, ald_ret)):
        best_lone, tt, qw = math.inf, math.tan(limit), q[where]
        for eta in np.linspace(-PI, PI, 2001):
            psi = m.S[where] + eta
            d1, d2 = np.cos(psi) + tt * np.sin(psi), np.cos(psi) - tt * np.sin(psi)
            if np.any(d1 <= 0):
                continue
            lo = np.max(qw / d1)
            hi = np.min(np.where(d2 > 0, qw / np.where(d2 > 0, d2, 1), np.inf))
            if lo <= hi:
                best_lone = min(best_lone, lo)
        assert lone * (1 - 1e-9) <= best_lone <= lone * (1 + 1e-3)


def test_sizing_bad_input():
    m = motion_law("cycloidal", 0.05, RISE, DWELL, RET, W=W, N=11)
    with pytest.raises(ValueError, match="ALD"):
        base_radius(11, m.FI, m.A, m.V, m.S, W, 2.0)
    with pytest.raises(ValueError, match="N = 12"):
        base_radius(12, m.FI, m.A, m.V, m.S, W, 0.5)
    with pytest.raises(ValueError, match="W"):
        flat_base_radius(11, m.FI, m.A, m.V, m.S, 0.0)
    with pytest.raises(ValueError, match="R = "):
        rocker_centre_distance(11, m.FI, m.A, m.V, m.S, W, -1.0, 0.5)
    with pytest.raises(RequirementError):       # an offset beyond the return's limit
        base_radius(11, m.FI, m.A, m.V, m.S, W, 0.5, 0.3, BETA=0.4)


def test_dprflp_curvature_near_90_degrees_E_DPRFLP_5():
    # C = 1e-14, s' = 0.05: tan(alpha) = 5e12; the exact radius is C^2 h^3/(...) -> 0.025
    r = sarkp.DPRFLP(1, 1e-14, 0.0, 10.0, [0.7], [3.0], [0.5], [0.0])
    assert r.ROK[0] == pytest.approx(0.025, rel=1e-13)


# ---- the README's cam example --------------------------------------------------------------

def test_readme_cam_example_runs_and_its_figures_are_right(tmp_path, monkeypatch, capsys):
    import pathlib
    import re
    pytest.importorskip("matplotlib")
    text = (pathlib.Path(__file__).resolve().parents[1] / "README.md").read_text("utf-8")
    section = text[text.index("## Designing a cam"):]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    monkeypatch.chdir(tmp_path)
    ns = {}
    exec(compile(code, "README.md", "exec"), ns)
    out = capsys.readouterr().out
    assert (tmp_path / "cam_roller.png").stat().st_size > 10000
    # what it prints, against independent figures: the cycloidal peak 2 h W / beta
    assert f"peak velocity {2 * 0.030 * 10.0 / math.radians(120):.4f} m/s" in out
    assert "base radius 36.43 mm; DKLCHK's 34.62 mm reaches 30.97 deg" in out
    assert "largest pressure angle 30.0000 deg" in out
    # and the prose's claims about them
    assert "36.43 mm beside DKLCHK's 34.62 mm" in section and "30.97 degrees" in section
    cam, size = ns["cam"], ns["size"]
    # the exact cam: the rise reaches 30 degrees at one point, the return stays within 45
    law = ns["law"]
    _touches(cam.ALFA, law.V > 0, math.radians(30))
    assert np.all(np.abs(cam.ALFA[law.V < 0]) < math.radians(45))
    # the base circle (the dwell at S = 0) is the pitch curve's smallest convex radius
    assert cam.ROKMIN == pytest.approx(size.RO, rel=1e-12)


def test_extension_results_are_sarkp_results():
    """The extensions' results pickle and print short like the book routines'."""
    import pickle
    m = motion_law("3-4-5", 0.02, RISE, DWELL, RET, W=W, N=50)
    back = pickle.loads(pickle.dumps(m))
    assert type(back).__name__ == "MotionLaw" and np.array_equal(back.S, m.S)
    assert back.CV == m.CV and "..." in repr(m)
    b = base_radius(50, m.FI, m.A, m.V, m.S, W, 0.5)
    assert pickle.loads(pickle.dumps(b)) == b
    pd = pytest.importorskip("pandas")
    frame = m.to_frame()
    assert isinstance(frame, pd.DataFrame) and list(frame.columns) == list(m._fields)
    assert frame.shape == (50, len(m._fields))


@pytest.mark.parametrize("call, what", [
    (lambda: motion_law("cycloidal", "0.01", 1.0, 0.5, 1.0), "H"),
    (lambda: motion_law("cycloidal", 0.01, 1.0, 0.5, 1.0, dwell2=[1.0]), "dwell2"),
    (lambda: base_radius(3, [0, 1, 2], [0] * 3, [0, 1, 0], [0, .1, .2], None, 0.5), "W"),
    (lambda: flat_base_radius(3, [0, 1, 2], [0] * 3, [0, 1, 0], [0, .1, .2], 5.0, "0"),
     "ROKMIN"),
    (lambda: rocker_centre_distance(3, [0, 1, 2], [0] * 3, [0, 1, 0], [0, .1, .2], 5.0,
                                    0.1, 1j), "ALD"),
    (lambda: roller_translating(3, 0.05, 0.0, 5.0, [0, 1, 2], [0] * 3, [0, 1, 0],
                                [0, .1, .2], "r"), "RR")])
def test_extensions_type_errors_name_the_argument(call, what):
    with pytest.raises(TypeError, match=what):
        call()


def test_motion_law_scalar_angle_gives_floats():
    m = motion_law("cycloidal", 0.01, 1.0, 0.5, 1.0, W=2.0, FI=0.3)
    assert all(type(v) in (float, int) for v in m)
    full = motion_law("cycloidal", 0.01, 1.0, 0.5, 1.0, W=2.0, FI=[0.3])
    assert (m.S, m.V, m.A, m.PHASE) == (full.S[0], full.V[0], full.A[0], full.PHASE[0])


def test_rocker_roller_undercut():
    H, L, R, ETAO = 0.35, 0.12, 0.09, 0.7
    fi = np.linspace(0, 2 * PI, 361)
    m = motion_law("3-4-5", H, RISE, DWELL, RET, W=W, FI=fi)
    p = roller_rocker(fi.size, W, ETAO, fi, 0.0, L, R, m.A, m.V, m.S, 0.01)
    big = 1.01 * p.ROKMIN
    q = roller_rocker(fi.size, W, ETAO, fi, 0.0, L, R, m.A, m.V, m.S, big)
    assert q.UNDERCUT and not p.UNDERCUT
    assert np.min(q.RW[q.ROK > 0]) < 0            # the working profile's curvature flips
    with pytest.raises(RequirementError, match="undercut"):
        roller_rocker(fi.size, W, ETAO, fi, 0.0, L, R, m.A, m.V, m.S, big,
                      on_undercut="raise")


from hypothesis import given, settings, strategies as st  # noqa: E402


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(LAWS), st.sampled_from(LAWS), st.floats(0.01, 0.1),
       st.floats(0.8, 2.5), st.floats(0.0, 1.0), st.floats(0.8, 2.5), st.floats(-1.0, 1.0),
       st.floats(0.3, 0.8), st.floats(0.3, 0.8))
def test_base_radius_touches_the_limit_once_on_random_cams(law, back, h, rise, dwell, ret,
                                                            frac, ald, ald_ret):
    """Random laws, phases, offsets and limits: the exact radius puts the largest pressure
    angle at its limit at exactly one table point (1e-9) and every other point below.
    The offset angle stays below both limits by 0.02 rad: at |BETA| = ALD the pressure
    angle of a dwell, -BETA, is at the limit all along the dwell (and at BETA = the
    return's limit no radius serves: RequirementError, test_sizing_bad_input)."""
    beta = frac * (min(ald, ald_ret) - 0.02)
    n = 541
    m = motion_law(law, h, rise, dwell, ret, W=W, N=n, return_law=back)
    b = base_radius(n, m.FI, m.A, m.V, m.S, W, ald, ald_ret, BETA=beta)
    p = DPRFLP(n, b.RO_AXIAL, b.EXCST, W, m.FI, m.A, m.V, m.S)
    limit = np.where(m.V > 0, ald, np.where(m.V < 0, ald_ret, min(ald, ald_ret)))
    over = np.abs(p.ALFA) - limit
    assert over.max() <= 1e-12
    assert np.sum(over >= -1e-9) == 1, np.sort(over)[-3:]
