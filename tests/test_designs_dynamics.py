"""Chapter 8 at the mechanism level for a Mechanism with designs (issue 25): ``motion``
and ``flywheel`` of D designs described once equal D separate runs of the single
designs, bit for bit.

Why bit for bit: the design solve gives J_red and M_red equal, bit for bit, to separate
solves (tests/test_mechanism_designs.py), and each design's law of motion or flywheel is
then the same computation on the same numbers.  The separate runs are the reference; the
physics of motion and flywheel themselves is tested in tests/test_dynamics.py and
tests/test_flywheel.py.
"""

import math

import numpy as np
import pytest

import sarkp
from sarkp import Mechanism

PHI = np.linspace(0.0, 2 * math.pi, 73)
L2 = np.array([0.34, 0.35, 0.37])
M2 = np.array([1.0, 1.5, 2.5])
XC = np.array([0.30, 0.31, 0.29])
DRIVE = np.array([[3.0], [2.5], [4.0]])           # the crank's torque, one per design (N m)


def machine(xc=0.3, l2=0.35, m2=1.5, drive=3.0, load=-1.0, k=50.0):
    """A four-bar with masses on every link, a spring, a driving torque on the crank and
    a resisting torque on the rocker; any value may be an array over designs."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", l2, 0.3, branch=1)
    m.point("S2", "A", "B", 0.15, 0.2)
    m.point("S3", "C", "B", 0.1)
    m.mass("O", "A", mass=0.5, inertia=0.001, centre=0.05)
    m.mass("S2", "A", mass=m2, inertia=0.012)
    m.mass("S3", "C", mass=1.0, inertia=0.01)
    m.torque("O", "A", drive)
    m.torque("C", "B", load)
    m.spring("S2", "C", k, 0.2)
    return m


def designs():
    return machine(xc=XC, l2=L2, m2=M2, drive=DRIVE)


def design(d):
    return machine(xc=float(XC[d]), l2=float(L2[d]), m2=float(M2[d]),
                   drive=float(DRIVE[d, 0]))


def assert_stacked(together, alone, d, shared=("phi",)):
    """Field by field: design d of the stacked result is the single run, bit for bit."""
    assert together._fields == alone._fields
    for f in together._fields:
        ours = getattr(together, f)
        if f in shared:
            np.testing.assert_array_equal(ours, getattr(alone, f), err_msg=f)
        else:
            np.testing.assert_array_equal(np.asarray(ours)[d], getattr(alone, f),
                                          err_msg=f"{f}, design {d}")


@pytest.mark.parametrize("kw", [dict(), dict(omega0=4.0, t0=0.5),
                                dict(gravity=9.81, omega0=6.0)])
def test_motion_from_a_start_equals_separate_runs(kw):
    together = designs().motion(PHI, **kw)
    assert together.omega.shape == together.t.shape == (3, PHI.size)
    assert together.phi.shape == PHI.shape and together.E0.shape == (3,)
    for d in range(3):
        assert_stacked(together, design(d).motion(PHI, **kw), d)
    # the designs differ: a stack of one run three times would not pass the loop above
    assert len({float(w) for w in together.omega[:, -1]}) == 3


def test_steady_motion_equals_separate_runs():
    together = designs().motion(PHI, omega_mean=40.0, gravity=9.81)
    np.testing.assert_array_equal(together.omega_mean, [40.0, 40.0, 40.0])
    for d in range(3):
        assert_stacked(together, design(d).motion(PHI, omega_mean=40.0, gravity=9.81), d)


@pytest.mark.parametrize("phi", [None, np.linspace(0.0, 2 * math.pi, 145)])
def test_flywheel_equals_separate_runs(phi):
    together = designs().flywheel(0.04, 12.0, phi, gravity=9.81)
    assert together.J_flywheel.shape == together.delta.shape == (3,)
    np.testing.assert_allclose(together.delta, 0.04, rtol=1e-9)      # the promise, per design
    for d in range(3):
        assert_stacked(together, design(d).flywheel(0.04, 12.0, phi, gravity=9.81), d)
    assert len(set(together.J_flywheel.tolist())) == 3


def test_a_design_that_stops_is_named():
    """Design 1's drive is too weak to turn the crank against the load from rest: the
    error is the one its separate run raises, naming design 1 (index first)."""
    m = machine(drive=np.array([[3.0], [0.2], [4.0]]), load=-0.5)
    with pytest.raises(sarkp.RequirementError) as alone:
        machine(drive=0.2, load=-0.5).motion(PHI)
    with pytest.raises(sarkp.RequirementError, match=r"^design 1: ") as err:
        m.motion(PHI)
    assert str(err.value) == f"design 1: {alone.value}"
    assert err.value.index[0] == 1 and err.value.status == alone.value.status


def test_a_single_design_keeps_its_result():
    """Without designs the result is motion's own (numbers where they were numbers)."""
    r = machine().motion(PHI, omega0=4.0)
    assert r.omega.shape == PHI.shape and np.ndim(r.E0) == 0


def test_simulate_with_designs_says_it_takes_one():
    """simulate integrates one mechanism in time (its steps adapt to that mechanism):
    a clear error, not numpy's "only 0-dimensional arrays can be converted"."""
    with pytest.raises(ValueError, match="simulate integrates one mechanism: this one "
                                         "has 3 designs"):
        designs().simulate(np.linspace(0.0, 1.0, 11))
