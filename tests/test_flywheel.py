"""The flywheel workflow at the book-routine level (issue 20): DZKNDV returns AS, ASUM, EV
and DEC when the machine stalls, and DMHVK_EXACT gives the flywheel whose rerun of DZKNDV
has exactly the coefficient asked for, with DMHVK's (Merkalov's) value beside it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import sarkp
from sarkp import DMHVK, DMHVK_EXACT, DZKNDV

W1 = 3.0


def grid(m):
    return np.linspace(0.0, 2.0 * math.pi, m)


def _stalling(m=37):
    phi = grid(m)
    return m, 300 * np.sin(phi) + 80 * np.cos(2 * phi) - 20.0, 4.0 + 3 * np.sin(phi) ** 2


def _figure96():
    from sarkp.book import load_figure

    def col(number, name):
        cells = sorted((c for c in load_figure(number).cells
                        if c.column == name and c.row.isdigit()), key=lambda c: int(c.row))
        return np.array([c.value for c in cells])
    return col("94", "M1"), col("96", "IPR")


def test_stall_returns_the_work_columns_and_dec():
    """on_error="nan": AS, ASUM, EV, DEC as computed with any ISC (they do not depend on
    it), WPR and EPR NaN, status REQUIREMENT."""
    m, mpr, ispr = _stalling()
    out = DZKNDV(m, float(m), W1, 0.2, mpr, ispr, on_error="nan")
    assert out.status == sarkp.Status.REQUIREMENT
    assert np.isnan(out.WPR).all() and np.isnan(out.EPR).all()
    big = DZKNDV(m, float(m), W1, 1e4, mpr, ispr)            # runs: a big flywheel
    for name in ("AS", "ASUM", "EV", "DEC"):
        assert np.array_equal(getattr(out, name), getattr(big, name)), name
    # the columns themselves: trapezoids of MPR, the cycle's work removed, EV = ISPR W1^2/2
    h = 2 * math.pi / (m - 1)
    trap = np.r_[0.0, np.cumsum(h * (mpr[1:] + mpr[:-1]) / 2)]
    np.testing.assert_allclose(out.AS, trap, rtol=1e-13, atol=1e-12)
    assert out.ASUM[0] == 0.0 and abs(out.ASUM[-1]) < 1e-12
    np.testing.assert_allclose(out.EV, ispr * W1**2 / 2, rtol=1e-15)
    np.testing.assert_allclose(out.DEC, out.ASUM - out.EV + out.EV[0], rtol=0, atol=1e-12)


def test_stall_error_says_to_size_a_flywheel_and_carries_dec():
    m, mpr, ispr = _stalling()
    with pytest.raises(sarkp.RequirementError, match="flywheel from DEC") as info:
        DZKNDV(m, float(m), W1, 0.2, mpr, ispr)
    assert "DMHVK" in str(info.value)
    nan = DZKNDV(m, float(m), W1, 0.2, mpr, ispr, on_error="nan")
    assert np.array_equal(info.value.result.DEC, nan.DEC)
    assert np.isnan(info.value.result.WPR).all()


def test_dec_at_a_stall_equals_dec_with_the_flywheel():
    """Issue 20's check: DZKNDV's DEC without the flywheel (the machine stalls) is DEC with
    it, bit for bit, and the flywheel sized from it runs."""
    m, mpr, ispr = _stalling()
    stalled = DZKNDV(m, float(m), W1, 0.2, mpr, ispr, on_error="nan")
    imh = DMHVK(m, 0.02, 0.2, W1, stalled.DEC).IMHVK
    run = DZKNDV(m, float(m), W1, 0.2 + imh, mpr, ispr)
    assert np.array_equal(stalled.DEC, run.DEC)
    assert np.isfinite(run.WPR).all()


@pytest.mark.parametrize("delta", [0.001, 0.01, 0.05, 0.3])
def test_exact_flywheel_gives_exactly_delta(delta):
    """A variable ISPR (where DMHVK is only approximate): DZKNDV rerun with
    ISC + IMHVK has (max WPR - min WPR)/W1 = delta to 1e-12."""
    m, mpr, ispr = _stalling(73)
    r = DMHVK_EXACT(m, float(m), W1, 0.2, mpr, ispr, delta)
    w = DZKNDV(m, float(m), W1, 0.2 + r.IMHVK, mpr, ispr).WPR
    assert (w.max() - w.min()) / W1 == pytest.approx(delta, rel=1e-12, abs=0)
    assert r.DELTA == pytest.approx(delta, rel=1e-12, abs=0)
    assert (w.max() + w.min()) / 2 == pytest.approx(W1, rel=1e-14)
    dec = DZKNDV(m, float(m), W1, 0.2, mpr, ispr, on_error="nan").DEC
    assert r.IMERK == DMHVK(m, delta, 0.2, W1, dec).IMHVK
    wm = DZKNDV(m, float(m), W1, 0.2 + r.IMERK, mpr, ispr).WPR
    assert abs((wm.max() - wm.min()) / W1 - delta) > 1e-6 * delta   # Merkalov: not exact


def test_exact_flywheel_for_program_x():
    """Fig. 96's machine (corrected mode: exact pi, the energy equation): DMHVK's flywheel
    gives 0.00997 for 0.01 (it neglects IPR); the exact one gives 0.01."""
    m1, ipr = _figure96()
    isc = 50.0 * 0.16646893 ** 3
    r = DMHVK_EXACT(37, 37.0, W1, isc, m1, ipr, 0.01)
    assert r.DELTA == pytest.approx(0.01, rel=1e-12, abs=0)
    w = DZKNDV(37, 37.0, W1, isc + r.IMERK, m1, ipr).WPR
    assert (w.max() - w.min()) / W1 == pytest.approx(0.01, rel=0.01)
    assert abs((w.max() - w.min()) / W1 - 0.01) > 1e-6
    assert r.IMHVK == pytest.approx(r.IMERK, rel=0.01) and r.IMHVK != r.IMERK


def test_exact_flywheel_constant_inertia_is_dmhvk():
    """ISPR = 0: DMHVK is exact in corrected mode too, so both agree to rounding."""
    m = 73
    phi = grid(m)
    mpr = 300 * np.sin(phi) + 120 * np.sin(2 * phi + 0.3) - 40.0
    r = DMHVK_EXACT(m, float(m), W1, 0.5, mpr, np.zeros(m), 0.05)
    assert r.IMHVK == pytest.approx(r.IMERK, rel=1e-12)


def test_exact_flywheel_as_printed_is_dmhvk():
    """As printed, DZKNDV's linear law (8.17) makes DMHVK exact for any ISPR."""
    m, mpr, ispr = _stalling()
    with sarkp.as_printed():
        r = DMHVK_EXACT(m, float(m), W1, 0.2, mpr, ispr, 0.01)
        dec = DZKNDV(m, float(m), W1, 0.2, mpr, ispr).DEC
        assert r.IMHVK == r.IMERK == DMHVK(m, 0.01, 0.2, W1, dec).IMHVK
    assert r.DELTA == pytest.approx(0.01, rel=1e-12)


def test_extremes_away_from_decs():
    """A strong variable inertia moves omega's extremes away from DEC's: the closed form
    is redone at omega's extremes, and the law is still the energy equation with the
    book's mean."""
    m = 361
    phi = grid(m)
    mpr = 50 * np.sin(phi) - 10 * np.cos(3 * phi)
    ispr = 40 * (1 + np.cos(phi + 1.0)) ** 2
    dec = DZKNDV(m, float(m), W1, 60.0, mpr, ispr).DEC
    r = DZKNDV(m, float(m), W1, 60.0, mpr, ispr)
    assert r.WPR.argmax() != dec.argmax() or r.WPR.argmin() != dec.argmin()
    e = (60.0 + ispr) * r.WPR**2 / 2 - r.ASUM
    assert np.ptp(e) <= 1e-12 * np.abs(e).max()
    assert (r.WPR.max() + r.WPR.min()) / 2 == pytest.approx(W1, rel=1e-14)
    x = DMHVK_EXACT(m, float(m), W1, 60.0, mpr, ispr, 0.05)
    assert x.DELTA == pytest.approx(0.05, rel=1e-12, abs=0)


@pytest.mark.parametrize("args, name", [
    ((37, 37.0, W1, 0.2, np.zeros(37), np.zeros(37), 0.0), "DELTA"),
    ((37, 37.0, W1, 0.2, np.zeros(37), np.zeros(37), 1.0), "DELTA"),
    ((37, 37.0, W1, 0.2, np.zeros(37), np.zeros(37), math.nan), "DELTA"),
    ((37, 36.0, W1, 0.2, np.zeros(37), np.zeros(37), 0.1), "ZM"),
    ((36, 36.0, W1, 0.2, np.zeros(37), np.zeros(37), 0.1), "M"),
    ((37, 37.0, -1.0, 0.2, np.zeros(37), np.zeros(37), 0.1), "W1"),
    ((37, 37.0, W1, 0.2, np.zeros(37), -np.ones(37), 0.1), "ISPR"),
])
def test_exact_flywheel_bad_input_names_the_argument(args, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        DMHVK_EXACT(*args)


def test_no_flywheel_needed():
    """A machine that fluctuates less than DELTA: IMHVK < 0 (inertia to take away), as
    DMHVK reports it; when even ISC + IMHVK <= 0 would be needed, RequirementError."""
    phi = grid(37)
    r = DMHVK_EXACT(37, 37.0, W1, 5.2, np.sin(phi), np.zeros(37), 0.05)
    assert r.IMHVK < 0 and r.DELTA == pytest.approx(0.05, rel=1e-12)
    with pytest.raises(sarkp.RequirementError, match="no flywheel is needed"):
        DMHVK_EXACT(37, 37.0, W1, 0.2, np.sin(phi), np.full(37, 5.0), 0.5)


def test_stall_decision_is_the_definition():
    """300 random machines, many near a stall: DZKNDV stalls exactly when even the least
    E0 (omega = 0 where ASUM is smallest) gives a mean above W1 (the midrange grows with
    E0), computed here directly from ASUM; otherwise WPR satisfies the energy equation
    with the book's mean."""
    rng = np.random.default_rng(20)
    stalls = 0
    for _ in range(300):
        m = int(rng.integers(5, 80))
        phi = grid(m)
        coeffs = rng.uniform(-50, 50, 6)
        mpr = sum(c * np.sin((k + 1) * phi + k) for k, c in enumerate(coeffs)) - 5.0
        isc = rng.uniform(0.05, 20.0)
        ispr = rng.uniform(0, 30) * (1 + np.cos(phi + rng.uniform(0, 6))) ** 2
        r = DZKNDV(m, float(m), W1, isc, mpr, ispr, on_error="nan")
        j = isc + ispr
        least = np.sqrt(np.maximum(2 * (r.ASUM - r.ASUM.min()) / j, 0.0))
        if r.status == sarkp.Status.REQUIREMENT:
            stalls += 1
            assert (least.max() + least.min()) / 2 > W1
        else:
            assert r.status == sarkp.Status.OK
            assert (least.max() + least.min()) / 2 <= W1 * (1 + 1e-14)
            e = j * r.WPR**2 / 2 - r.ASUM
            assert np.ptp(e) <= 1e-12 * (np.abs(r.ASUM).max() + (j * r.WPR**2).max())
            assert (r.WPR.max() + r.WPR.min()) / 2 == pytest.approx(W1, rel=1e-13)
    assert 30 < stalls < 270                     # both outcomes well represented


def test_huge_and_tiny_scales():
    """Inertias and moments near the ends of the double range: the closed form's
    discriminant is scaled (j1 j2 would overflow), and the results are still the energy
    equation with the book's mean; a flywheel that cannot be represented (J + J_flywheel
    below J's rounding) is a RangeError, not a wrong delta."""
    m = 37
    phi = grid(m)
    r = DZKNDV(m, float(m), W1, 1e300, 1e300 * np.sin(phi), 1e299 * np.sin(phi) ** 2)
    j = 1e300 + 1e299 * np.sin(phi) ** 2
    e = j / 2 * r.WPR**2 - r.ASUM
    assert np.ptp(e) <= 1e-13 * np.abs(e).max()
    assert (r.WPR.max() + r.WPR.min()) / 2 == pytest.approx(W1, rel=1e-13)
    fw = sarkp.flywheel(phi, 1e-300, 1e300 * np.sin(phi), delta=0.1, omega_mean=W1)
    assert fw.delta == pytest.approx(0.1, rel=1e-12)
    x = DMHVK_EXACT(m, float(m), W1, 1e-300, 1e300 * np.sin(phi), np.zeros(m), 0.1)
    assert x.DELTA == pytest.approx(0.1, rel=1e-12)
    with pytest.raises(sarkp.RangeError, match="lost in the rounding"):
        sarkp.flywheel(phi, 1e300, 1e-300 * np.sin(phi), delta=0.1, omega_mean=W1)
    with pytest.raises(sarkp.RangeError, match="underflow"):
        sarkp.flywheel(phi, 1.0, np.sin(phi), delta=0.1, omega_mean=1e-300)
    with pytest.raises(sarkp.RangeError, match="not be a finite double"):
        sarkp.motion(phi, 1e-300, 1e300)
