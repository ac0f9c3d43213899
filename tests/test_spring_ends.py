"""A spring whose ends meet at some positions only (issue 25's last point, and what the
force step does there).

A crank O-A of radius r and a spring (k, L0 > 0) from A to the frame point F = (r, 0):
the ends meet at phi = 0, where the spring is compressed to zero length and pushes with
k L0 in no defined direction.  Either side of it the balancing moment has a closed
form (the drive balances the spring's moment about O):

    M_b(phi) = k (d - L0) r**2 sin(phi) / d,   d = |F - A| = 2 r |sin(phi/2)|,

which tends to -k L0 r from phi > 0 and to +k L0 r from phi < 0: a jump of 2 k L0 r.
At phi = 0 the force step (fortran/mechanism.f90, subroutine forces) used to leave the
spring out and report status OK with M_b = 0 -- a number that is neither limit, without a
word.  The position now fails: SingularError naming the spring, or NaN and status
SINGULAR with on_error="nan".
"""

import math

import numpy as np
import pytest

import sarkp

R, K, L0 = 0.2, 100.0, 0.1


def machine(free=L0):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("F", R, 0.0)
    m.crank("A", "O", R)
    m.spring("A", "F", K, free)
    return m


def balancing(phi):
    d = 2.0 * R * abs(math.sin(phi / 2.0))
    return K * (d - L0) * R**2 * math.sin(phi) / d


def test_either_side_of_the_meeting_the_closed_form():
    phi = np.array([-0.5, -1e-3, -1e-8, 1e-8, 1e-3, 0.5])
    r = machine().solve(phi, omega=0.0, need="forces")
    assert np.all(r.status == 0)
    want = [balancing(p) for p in phi]
    np.testing.assert_allclose(r.balancing_moment, want, rtol=1e-7)
    # the limits: -k L0 r from above, +k L0 r from below
    assert r.balancing_moment[3] == pytest.approx(-K * L0 * R, rel=1e-7)
    assert r.balancing_moment[2] == pytest.approx(K * L0 * R, rel=1e-7)


def test_a_spring_compressed_to_a_point_is_not_silently_dropped():
    """At phi = 0 the spring's force k L0 has no direction: the position must fail
    (SingularError; NaN and status SINGULAR with on_error="nan"), not give M_b = 0
    (what it gave before: status OK, M_b = 0.0 exactly; the limits are -+2.0 N m)."""
    r = machine().solve([0.0, 0.5], omega=0.0, need="forces", on_error="nan")
    assert r.status[1] == 0 and r.balancing_moment[1] == pytest.approx(balancing(0.5))
    assert r.status[0] == sarkp.Status.SINGULAR, (int(r.status[0]), r.balancing_moment[0])
    assert np.isnan(r.balancing_moment[0])
    with pytest.raises(sarkp.SingularError, match="spring 'A'-'F'.*phi = 0.0"):
        machine().solve([0.5, 0.0], omega=0.0, need="forces")


def test_a_spring_without_a_force_at_the_meeting_is_fine():
    """L0 = 0: the force k d vanishes where the ends meet, so leaving it out there is
    right (M_b = 0 is the limit from both sides: k r**2 sin(phi) -> 0)."""
    r = machine(0.0).solve([-1e-9, 0.0, 1e-9], omega=0.0, need="forces")
    assert np.all(r.status == 0)
    np.testing.assert_allclose(r.balancing_moment, [K * R**2 * math.sin(p) for p in
                                                    (-1e-9, 0.0, 1e-9)], atol=1e-20)
