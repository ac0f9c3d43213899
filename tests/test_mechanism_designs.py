"""sarkp.Mechanism's solve contract (issue 25): designs in one call, points=/links=
selection, out=, loads as callables, and errors for what was not computed.

References: D separate solves of scalar mechanisms (bit for bit), the full solve (bit for
bit), loads given as the arrays of their values (bit for bit), and the equilibrium of
the crank written out here.
"""

import math
import pickle
import warnings

import numpy as np
import pytest

import sarkp
from sarkp import Mechanism

PHI = np.linspace(0.0, 2 * math.pi, 25)
FIELDS = ("positions", "velocities", "accelerations", "directions", "omegas", "epsilons",
          "reactions", "balancing_moment", "reduced_inertia", "reduced_moment", "status")


def fourbar(xc=0.3, l2=0.35, l3=0.3, m2=1.5, j3=0.01, k=200.0, fx=30.0, M=-20.0):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", l2, l3, branch=1)
    m.point("S2", "A", "B", 0.15, 0.2)
    m.point("S3", "C", "B", 0.1)
    m.mass("O", "A", mass=0.5, inertia=0.001, centre=0.05)
    m.mass("S2", "A", mass=m2, inertia=0.012)
    m.mass("S3", "C", mass=1.0, inertia=j3)
    m.torque("C", "B", M)
    m.force("B", fx, -10.0)
    m.spring("S2", "C", k, 0.2)
    return m


def sixbar(h5=0.64, rde=0.7012536, rcd=0.5787882, offset=0.0):
    m = Mechanism()
    xc, yc = -2.09023145 * math.sin(0.698), 2.09023145 * math.cos(0.698)
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", xc, yc)
    m.fixed("G", 0.0, h5 + yc)
    m.crank("A", "O", 0.16646893)
    m.rrr("B", "A", "C", 2.33535352, 0.5787882, branch=1)
    m.point("D", "C", "B", rcd, math.pi)
    m.rrp("E", "D", "G", 0.0, rde, branch=1, offset=offset)
    m.mass("E", mass=20.0)
    m.force("E", -500.0, 0.0)
    return m


def assert_same(a, b):
    """Two results field by field, bit for bit (NaN where the other has NaN)."""
    da, db = a._asdict(), b._asdict()        # the raw fields (None: not computed)
    for f in FIELDS:
        if da[f] is None or db[f] is None:
            assert da[f] is None and db[f] is None, f
        else:
            np.testing.assert_array_equal(da[f], db[f], err_msg=f)


# -- designs ------------------------------------------------------------------------------

def test_designs_equal_separate_solves_bit_for_bit():
    xc = np.array([0.28, 0.3, 0.32])
    l2 = np.array([0.34, 0.35, 0.36])
    m2 = np.array([1.0, 1.5, 2.0])
    k = np.array([0.0, 100.0, 300.0])
    fx = np.array([[10.0], [20.0], [30.0]])               # one force per design
    M = np.array([-20.0, -10.0, 0.0])[:, None] + 0.5 * np.sin(PHI)   # (D, n)
    m = fourbar(xc=xc, l2=l2, m2=m2, k=k, fx=fx, M=M)
    assert m.designs == 3
    r = m.solve(PHI, omega=12.0, epsilon=3.0, need="forces", gravity=9.81)
    assert r.position("B").shape == (3, PHI.size, 2)
    assert r.position("C").shape == (3, PHI.size, 2)
    assert r.status.shape == (3, PHI.size)
    assert r.balancing_moment.shape == (3, PHI.size)
    for d in range(3):
        one = fourbar(xc=xc[d], l2=l2[d], m2=m2[d], k=k[d], fx=fx[d, 0], M=M[d])
        ro = one.solve(PHI, omega=12.0, epsilon=3.0, need="forces", gravity=9.81)
        for f in FIELDS:
            np.testing.assert_array_equal(getattr(r, f)[d], getattr(ro, f), err_msg=f)
        for name in ("B", "C", "S2"):
            np.testing.assert_array_equal(r.position(name)[d], ro.position(name))
        np.testing.assert_array_equal(r.angle("C", "B")[d], ro.angle("C", "B"))
        np.testing.assert_array_equal(r.angle("O", "A")[d], ro.angle("O", "A"))
        np.testing.assert_array_equal(r.reaction("B")[d], ro.reaction("B"))


def test_designs_of_a_sixbar_with_a_slider_and_2d_phi():
    h5 = np.linspace(0.62, 0.66, 4)
    off = np.array([0.0, 0.005, -0.005, 0.01])
    m = sixbar(h5=h5, offset=off)
    phi = PHI[:24].reshape(4, 6)
    r = m.solve(phi, omega=10.0, need="forces")
    assert r.position("E").shape == (4, 4, 6, 2)
    assert r.angle("D", "E").shape == (4, 4, 6)
    for d in range(4):
        ro = sixbar(h5=h5[d], offset=off[d]).solve(phi, omega=10.0, need="forces")
        for f in FIELDS:
            np.testing.assert_array_equal(getattr(r, f)[d], getattr(ro, f), err_msg=f)
        np.testing.assert_array_equal(r.angle("D", "E")[d], ro.angle("D", "E"))


def test_design_arrays_are_checked():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", np.array([0.3, 0.31]), 0.0)
    with pytest.raises(ValueError, match="3 designs where the mechanism has 2"):
        m.crank("A", "O", np.array([0.1, 0.1, 0.1]))
    with pytest.raises(ValueError, match="l2 must be a length > 0"):
        m.crank("A", "O", 0.1)
        m.rrr("B", "A", "C", np.array([0.35, -0.1]), 0.3)
    with pytest.raises(TypeError, match="1-d array"):
        m.rrr("B", "A", "C", np.ones((2, 2)), 0.3)


def test_designs_name_the_failed_design():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", np.array([0.35, 0.05]), 0.3)    # design 1 does not assemble
    with pytest.raises(sarkp.AssemblyError, match=r"design 1") as e:
        m.solve(PHI)
    assert e.value.index[0] == 1
    r = m.solve(PHI, on_error="nan")
    assert np.all(r.status[0] == 0) and np.any(r.status[1] != 0)
    assert np.all(np.isnan(r.position("B")[1][r.status[1] != 0]))


def test_design_result_pickles():
    m = sixbar(h5=np.array([0.62, 0.65]))
    r = m.solve(PHI, need="velocities")
    r2 = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(r2.velocity("E"), r.velocity("E"))
    assert "2 designs" in repr(r)


# -- points= and links= -------------------------------------------------------------------

def test_selected_outputs_equal_the_full_solve_bit_for_bit():
    m = sixbar()
    full = m.solve(PHI, omega=10.0, need="forces")
    r = m.solve(PHI, omega=10.0, need="forces", points=("E", "B"),
                links=(("A", "B"), "E", ("C", "D")))
    assert r.positions.shape == (PHI.size, 2, 2)
    assert r.omegas.shape == (PHI.size, 3)
    for name in ("E", "B", "O", "G"):
        for get in ("position", "velocity", "acceleration"):
            np.testing.assert_array_equal(getattr(r, get)(name), getattr(full, get)(name))
    for link in (("A", "B"), ("E",), ("C", "B")):
        for get in ("angle", "omega", "epsilon"):
            np.testing.assert_array_equal(getattr(r, get)(*link), getattr(full, get)(*link))
    for f in ("reactions", "balancing_moment", "reduced_inertia", "reduced_moment",
              "status"):
        np.testing.assert_array_equal(getattr(r, f), getattr(full, f))
    with pytest.raises(ValueError, match=r"'D' was not stored.*points=\('E', 'B'\)"):
        r.position("D")
    with pytest.raises(ValueError, match=r"C->D.*store C and D with points="):
        r.angle("C", "D")              # a fixed angle off C-B's: needs D's position
    with pytest.raises(ValueError, match="link crank was not stored"):
        r.omega("O", "A")
    np.testing.assert_array_equal(r.angle("O", "A"), PHI)     # the crank's is phi


def test_empty_selection():
    m = sixbar()
    r = m.solve(PHI, omega=10.0, need="forces", points=(), links=())
    np.testing.assert_array_equal(r.balancing_moment,
                                  m.solve(PHI, omega=10.0, need="forces").balancing_moment)
    with pytest.raises(ValueError, match="not stored"):
        r.position("E")
    with pytest.raises(ValueError, match="unknown joint 'Z'"):
        m.solve(PHI, points=("Z",))


# -- out= ---------------------------------------------------------------------------------

def test_out_reuses_memory_and_equals_a_fresh_solve():
    for m, phi in ((sixbar(), PHI), (sixbar(h5=np.array([0.62, 0.64])), PHI.reshape(5, 5))):
        sel = dict(points=("E", "B"), links=(("C", "B"),))
        r = m.solve(phi, omega=10.0, need="forces", **sel)
        keep = [getattr(r, f) for f in FIELDS]
        phi2 = phi + 0.1
        r2 = m.solve(phi2, omega=7.0, need="forces", out=r, **sel)
        fresh = m.solve(phi2, omega=7.0, need="forces", **sel)
        assert_same(r2, fresh)
        for f, a in zip(FIELDS, keep):
            assert np.shares_memory(getattr(r2, f), a), f
        with pytest.raises(ValueError, match="need="):
            m.solve(phi2, need="positions", out=r2, **sel)
        with pytest.raises(ValueError, match="points= and links="):
            m.solve(phi2, need="forces", out=r2)


def test_out_with_failed_positions_then_good_ones():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.15, 0.1)      # assembles only near phi = 0
    phi = np.linspace(-0.5, 0.5, 11)
    r = m.solve(phi * 6, on_error="nan")
    assert np.any(r.status != 0)
    r2 = m.solve(phi, out=r, on_error="nan")
    assert_same(r2, m.solve(phi, on_error="nan"))


# -- loads as callables -------------------------------------------------------------------

def test_callable_loads_equal_their_values():
    omega = 5.0 + np.cos(PHI)
    t = np.linspace(0.0, 1.0, PHI.size)
    fx = lambda phi: 30.0 * np.sin(phi)                      # noqa: E731
    M = lambda phi, w: -20.0 + 0.1 * w ** 2                  # noqa: E731
    k = lambda phi, w, t: 200.0 + 50.0 * t                   # noqa: E731
    a = fourbar(fx=fx, M=M, k=k).solve(PHI, omega=omega, need="forces", t=t)
    # against one-position solves with the values the callables give there
    for i in (0, 7, 24):
        bi = fourbar(fx=30.0 * np.sin(PHI[i]), M=-20.0 + 0.1 * omega[i] ** 2,
                     k=200.0 + 50.0 * t[i])
        ri = bi.solve(PHI[i], omega=omega[i], need="forces")
        assert a.balancing_moment[i] == ri.balancing_moment
        np.testing.assert_array_equal(a.reaction("B")[i], ri.reaction("B"))
        assert a.reduced_moment[i] == ri.reduced_moment
    # a force of phi against the same values as an array: the whole sweep
    r1 = fourbar(fx=fx).solve(PHI, omega=omega, need="forces")
    r2 = fourbar(fx=30.0 * np.sin(PHI)).solve(PHI, omega=omega, need="forces")
    assert_same(r1, r2)


def test_callable_load_rules():
    m = fourbar(fx=lambda phi, w, t: 1.0)
    with pytest.raises(ValueError, match=r"depends on time: pass solve\(\.\.\., t=\)"):
        m.solve(PHI, need="forces")
    m = fourbar(fx=lambda phi: np.ones(3))
    with pytest.raises(ValueError, match="returned shape"):
        m.solve(PHI, need="forces")
    m = fourbar(k=lambda phi: -1.0)
    with pytest.raises(ValueError, match=">= 0"):
        m.solve(PHI, need="forces")
    with pytest.raises(TypeError, match="not 4 arguments"):
        fourbar(fx=lambda a, b, c, d: 1.0)
    # a ufunc (no signature): a function of phi
    r = fourbar(fx=np.sin).solve(PHI, need="forces")
    r0 = fourbar(fx=np.sin(PHI)).solve(PHI, need="forces")
    np.testing.assert_array_equal(r.balancing_moment, r0.balancing_moment)


# -- defects ------------------------------------------------------------------------------

def test_crank_pivot_of_any_name():
    m = Mechanism()
    m.fixed("P", 0.0, 0.0)
    m.fixed("O", 0.3, 0.05)
    m.crank("A", "P", 0.1)
    m.rrr("B", "A", "O", 0.35, 0.3)
    m.mass("A", "B", mass=1.0)
    r = m.solve(PHI, omega=10.0, need="forces")
    # a massless crank is a two-force member: the frame pushes it at P as it pushes
    # the coupler at A
    np.testing.assert_allclose(r.reaction("P"), r.reaction("A", on=("A", "B"),
                                                           by=("P", "A")), atol=1e-12)
    r.reaction("O")                      # the rocker's pivot: one pair


def test_reserved_names():
    m = Mechanism()
    with pytest.raises(ValueError, match="reserved"):
        m.fixed("\x00centre1", 0.0, 0.0)


def test_as_printed_warns():
    m = sixbar()
    with sarkp.as_printed(), pytest.warns(UserWarning, match="no as-printed mode"):
        r = m.solve(PHI)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_array_equal(r.position("E"), m.solve(PHI).position("E"))


def test_overflowing_velocities_raise_range_error():
    m = fourbar()
    for need in ("velocities", "accelerations", "forces"):
        with pytest.raises(sarkp.RangeError, match="overflows at phi = 0.3"):
            m.solve([0.3, 1.0], omega=1e155 if need != "velocities" else 1.7e308, need=need)
    r = m.solve([0.3, 1.0], omega=1e155, on_error="nan")
    assert np.all(r.status == sarkp.Status.RANGE)
    assert np.all(np.isnan(r.acceleration("B")))
    # large but representable: fine
    r = m.solve([0.3, 1.0], omega=1e100, need="forces")
    assert np.all(np.isfinite(r.acceleration("B"))) and np.all(r.status == 0)


def test_a_point_on_the_frame_says_so():
    m = fourbar()
    with pytest.raises(ValueError, match="frame points: a point rigid with the frame"):
        m.point("D", "O", "C", 0.1)


@pytest.mark.parametrize("need", ["positions", "velocities", "accelerations", "forces"])
@pytest.mark.parametrize("designs", [False, True])
def test_one_position_equals_the_sweep_bit_for_bit(need, designs):
    """solve(phi) with a scalar phi (the one-position path: results allocated in their
    final shape, written through their transposes) against the same phi in an array of
    one and of three positions, and a 2-d phi against the flat sweep, bit for bit; the
    results of two solves never share memory."""
    m = fourbar(l2=np.array([0.35, 0.36])) if designs else fourbar()
    lead = (2,) if designs else ()
    grid = np.array([0.3, 1.1, 2.9])
    sweep = m.solve(grid, omega=10.0, epsilon=2.0, need=need)
    one = m.solve(0.3, omega=10.0, epsilon=2.0, need=need)
    again = m.solve(0.3, omega=10.0, epsilon=2.0, need=need)
    first = m.solve(grid[:1], omega=10.0, epsilon=2.0, need=need)
    square = m.solve(np.array([[0.3, 1.1, 2.9]] * 2).T, omega=10.0, epsilon=2.0, need=need)
    for f in FIELDS:
        a = sweep._asdict()[f]
        if a is None:
            assert one._asdict()[f] is None and square._asdict()[f] is None, f
            continue
        assert one._asdict()[f].shape == a.shape[:len(lead)] + a.shape[len(lead) + 1:], f
        np.testing.assert_array_equal(one._asdict()[f], a[(slice(None),) * len(lead) + (0,)])
        np.testing.assert_array_equal(first._asdict()[f], a[(slice(None),) * len(lead)
                                                              + (slice(0, 1),)])
        for col in range(2):
            np.testing.assert_array_equal(
                square._asdict()[f][(slice(None),) * len(lead) + (slice(None), col)], a)
        if f != "status":
            assert not np.shares_memory(one._asdict()[f], again._asdict()[f]), f
    assert one.position("B").shape == lead + (2,)


def test_one_position_failure_is_nan_in_every_computed_field():
    """A scalar phi where the group does not assemble, on_error="nan": NaN in every
    field computed (through the one-position path), none in what was not."""
    m = fourbar(l2=0.1, l3=0.1)              # A-C is 0.2-0.4: never reaches
    r = m.solve(0.3, omega=10.0, need="velocities", on_error="nan")
    assert r.status == sarkp.Status.ASSEMBLY
    for f in ("positions", "velocities", "directions", "omegas", "reduced_inertia"):
        assert np.all(np.isnan(r._asdict()[f])), f
    assert r._asdict()["accelerations"] is None
    with pytest.raises(ValueError, match="need='accelerations'"):
        r.acceleration("B")
