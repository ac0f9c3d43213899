"""Physical laws: velocities are the time derivatives of positions."""

import numpy as np
import pytest

import sarkp
from sarkp.book import prog_ii_13


def derivative(f, x, h):
    """Fourth-order central difference."""
    return (-f(x + 2 * h) + 8 * f(x + h) - 8 * f(x - h) + f(x - 2 * h)) / (12 * h)


@pytest.mark.parametrize("card", [{}, {"LBD": 0.3, "NU": 0.5}, {"LBD": 0.2, "NU": -1.0}])
def test_ii13_corrected_velocities_are_derivatives_of_positions(card):
    w1 = prog_ii_13.W1
    fi1 = np.linspace(0.05, 2 * np.pi - 0.05, 37)
    h = 1e-3

    def column(name):
        return lambda x: prog_ii_13.compute(card, angles=x)[name]

    got = prog_ii_13.compute(card, angles=fi1)
    w2 = derivative(column("FI2"), fi1, h) * w1
    w3 = derivative(column("FI3"), fi1, h) * w1
    vx = derivative(column("XD"), fi1, h) * w1
    vy = derivative(column("YD"), fi1, h) * w1
    np.testing.assert_allclose(got["W2"], w2, rtol=1e-8, atol=1e-9)
    np.testing.assert_allclose(got["W3"], w3, rtol=1e-8, atol=1e-9)
    np.testing.assert_allclose(got["VD"], np.hypot(vx, vy), rtol=1e-8, atol=1e-9)
    np.testing.assert_allclose(np.exp(1j * got["ALD"]) * got["VD"], vx + 1j * vy,
                               rtol=1e-8, atol=1e-9)


def test_ii13_as_printed_reverses_vb_when_vbc_is_negative():
    """E-II13-4: the printed program's ALD points against v_B where VBC < 0."""
    corrected = prog_ii_13.compute()
    with sarkp.as_printed():
        printed = prog_ii_13.compute()
    negative = corrected["W3"] < 0
    assert negative.any() and (~negative).any()
    turn = np.angle(np.exp(1j * (printed["ALD"] - corrected["ALD"])))
    np.testing.assert_allclose(np.abs(turn[negative]), np.pi, atol=1e-4)
    np.testing.assert_allclose(turn[~negative], 0.0, atol=1e-4)
