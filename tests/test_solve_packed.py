"""Mechanism.solve through the packed entries (issue 25, the one-position cost).

solve calls mech_solve_packed (fortran/mechanism.f90: the description's tables in one
integer and one real array, the outputs in one buffer) and, once an earlier solve has
planned the need and selection, mech_solve_one for a number phi and mech_solve_few for a
1-d array of that size (the fast ways); ``out=`` still calls mech_solve with its forty
arguments.  The three must give the same numbers bit for
bit, at one position and at many (a position's arithmetic does not depend on its
neighbours), for every group kind, need, selection and design; results of two calls never
share memory; bad input raises what it raised before the fast way existed (checked
against a fresh mechanism, which has no plan yet).  The fast way's numbers are held
against the four-bar's closed form too.
"""

import math
import warnings

import numpy as np
import pytest

import sarkp
from sarkp import AssemblyError, Mechanism, RangeError, SingularError

PI = math.pi
PHIS = (0.3, 1.7, 4.0)
NEEDS = ("positions", "velocities", "accelerations", "forces")
ARRAYS = ("positions", "velocities", "accelerations", "directions", "omegas", "epsilons",
          "reactions", "balancing_moment", "reduced_inertia", "reduced_moment", "status")


def fourbar(rab=0.35):
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.05)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", rab, 0.3, branch=1)
    m.point("S2", "A", "B", 0.15, 0.2)
    m.mass("S2", "A", mass=1.5, inertia=0.012)
    m.mass("C", "B", mass=1.0, inertia=0.01, centre=0.15)
    m.torque("C", "B", -20.0)
    m.force("B", 30.0, -10.0)
    return m


def sixbar():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", -1.343, 1.601)
    m.fixed("G", 0.0, 2.241)
    m.crank("A", "O", 0.16646893)
    m.rrr("B", "A", "C", 2.33535352, 0.5787882, branch=1)
    m.point("D", "C", "B", 0.5787882, PI)
    m.rrp("E", "D", "G", 0.0, 0.7012536, branch=1)
    m.mass("C", "B", mass=8.0, inertia=0.9)
    m.mass("E", mass=30.0)
    m.force("E", -400.0, 0.0)
    m.spring("E", "G", 800.0, 0.5)
    return m


def rpr():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.0, -0.25)
    m.crank("A", "O", 0.1)
    m.rpr("B", "A", "C", 0.03, PI / 2, branch=1)
    m.point("S3", "C", "B", 0.2, 0.1)
    m.mass("S3", "C", mass=3.0, inertia=0.05)
    return m


def prp():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.0, 0.05)
    m.crank("A", "O", 0.1)
    m.prp("B", "A", PI / 2, "G", 0.0, guide_m=("O", "A"), rz2=0.01, t2=0.4)
    m.mass("B", "G", mass=1.5, inertia=0.002)
    return m


def rpp():
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("G", 0.2, -0.3)
    m.crank("A", "O", 0.1)
    m.rpp("K", "G", 0.3, "A", PI / 2 + 0.2)
    m.mass("K", "G", mass=2.0, inertia=0.01)
    return m


# each machine with its selections: all, one joint and one link, none
MACHINES = {
    "fourbar": (fourbar, [{}, {"points": ("B",), "links": (("C", "B"),)},
                          {"points": (), "links": ()}]),
    "sixbar": (sixbar, [{}, {"points": ("E",), "links": (("D", "E"),)},
                        {"points": ("E", "B"), "links": ()}]),
    "rpr": (rpr, [{}, {"points": ("B",), "links": (("C", "B"),)}]),
    "prp": (prp, [{}, {"points": ("B",), "links": ()}]),
    "rpp": (rpp, [{}, {"points": (), "links": (("K", "G"),)}]),
}
CASES = [(name, need, k) for name, (_, sels) in MACHINES.items() for need in NEEDS
         for k in range(len(sels))]


def arrays(r):
    """The result's arrays (those its need computed) by name."""
    out = {}
    for f in ARRAYS:
        try:
            out[f] = getattr(r, f)
        except ValueError:
            pass
    return out


def same(a, b, pick=None):
    """Bit for bit: the same fields, shapes, dtypes and bytes (b[pick] for b's position)."""
    fa, fb = arrays(a), arrays(b)
    assert fa.keys() == fb.keys()
    for f in fa:
        x, y = np.asarray(fa[f]), np.asarray(fb[f])
        if pick is not None:
            y = y[pick]
        assert x.dtype == y.dtype and x.shape == y.shape, f
        assert np.ascontiguousarray(x).tobytes() == np.ascontiguousarray(y).tobytes(), f


def planned(m, need, sel, *n):
    """Whether solve has the fast way's plan for this need and selection (and size n of
    a 1-d phi)."""
    tab = m._cache
    return tab is not None and (need, sel.get("points"), sel.get("links"), *n) in tab["fast"]


@pytest.mark.parametrize("name,need,k", CASES)
def test_one_position_fast_way_equals_general_ways(name, need, k):
    build, sels = MACHINES[name]
    sel = sels[k]
    kw = dict(omega=7.5, epsilon=-3.0, need=need, gravity=9.81, **sel)
    m = build()
    many = m.solve(np.array(PHIS), **kw)                # the packed entry; leaves a plan
    assert (many.status == 0).all()
    assert not planned(m, need, sel) and planned(m, need, sel, 3)
    same(m.solve(np.array(PHIS), **kw), many)           # mech_solve_few
    for i, phi in enumerate(PHIS):
        one = m.solve(np.array([phi]), **kw)            # the packed entry, n = 1
        same(m.solve(np.array([phi]), **kw), one)       # mech_solve_few, n = 1
        first = m.solve(phi, **kw)                      # the packed entry; leaves the plan
        assert planned(m, need, sel)
        fast = m.solve(phi, **kw)                       # mech_solve_one
        same(fast, first)
        again = m.solve(phi, **kw, out=first)           # mech_solve, 40 arguments
        if first.positions.size:
            assert np.shares_memory(again.positions, first.positions)
        same(fast, again)
        same(fast, one, 0)
        same(fast, many, i)
        assert fast.phi.shape == () and float(fast.phi) == phi
        fresh = build().solve(phi, **kw)                # a description solved once
        same(fast, fresh)


def test_fast_way_against_the_closed_form():
    """B of the four-bar, the fast way, against the circles' intersection; its velocity
    against a central difference of the fast way's positions."""
    m = fourbar()
    m.solve(0.3, need="velocities", omega=2.0)
    for phi in np.linspace(0.1, 6.2, 9):
        r = m.solve(float(phi), need="velocities", omega=2.0)
        a = np.array([0.1 * math.cos(phi), 0.1 * math.sin(phi)])
        c = np.array([0.3, 0.05])
        d = c - a
        L = math.hypot(*d)
        x = (0.35 ** 2 - 0.3 ** 2 + L ** 2) / (2 * L)
        h = math.sqrt(0.35 ** 2 - x ** 2)
        u = d / L
        b = a + x * u + h * np.array([-u[1], u[0]])   # branch +1: left of A->C
        assert np.max(np.abs(r.position("B") - b)) <= 2e-15
        e = 1e-6
        fd = (m.solve(float(phi) + e, need="positions").position("B")
              - m.solve(float(phi) - e, need="positions").position("B")) / (2 * e) * 2.0
        assert np.max(np.abs(r.velocity("B") - fd)) <= 1e-8


def test_designs_and_loads_per_position_through_the_packed_entry():
    """Designs (a leading axis) and loads with a value per position (1-d arrays and
    callables) go through mech_solve_packed; bit for bit mech_solve's (out=) and each
    design's own solve."""
    rab = np.array([0.34, 0.35, 0.36])
    md = fourbar(rab)
    phi = np.linspace(0.0, 2 * PI, 7)
    kw = dict(omega=4.0, epsilon=1.0, need="forces", gravity=9.81)
    r = md.solve(phi, **kw)
    assert r.positions.shape == (3, 7, 3, 2) and r.status.shape == (3, 7)
    same(r, md.solve(phi, **kw, out=md.solve(phi, **kw)))
    for d in range(3):
        single = fourbar(float(rab[d]))
        same(single.solve(phi, **kw), r, d)
        single.solve(0.5, **kw)
        same(single.solve(0.5, **kw), md.solve(0.5, **kw), d)
    m = fourbar()
    m.torque("A", "B", np.linspace(-1.0, 1.0, 7))
    m.force("A", lambda phi, omega: 2.0 * np.sin(phi) * omega, 0.0)
    r = m.solve(phi, **kw)
    same(r, m.solve(phi, **kw, out=m.solve(phi, **kw)))
    # the torque's values reach the balancing moment: 0 without it, with the force kept
    m2 = fourbar()
    m2.force("A", lambda phi, omega: 2.0 * np.sin(phi) * omega, 0.0)
    r2 = m2.solve(phi, **kw)
    # a torque M on link A-B, whose omega is w2: M_b changes by M w2 / omega
    dm = r.balancing_moment - r2.balancing_moment
    assert np.allclose(dm, -np.linspace(-1.0, 1.0, 7) * r.omega("A", "B") / 4.0,
                       rtol=1e-12, atol=1e-11)


def test_results_of_two_calls_do_not_share_memory():
    m = fourbar()
    for need in NEEDS:
        r1 = m.solve(0.3, omega=10.0, need=need)
        r2 = m.solve(0.3, omega=10.0, need=need)       # the fast way
        r3 = m.solve(1.3, omega=10.0, need=need)       # the fast way again
        keep = {f: np.copy(a) for f, a in arrays(r2).items()}
        for f, a in arrays(r2).items():
            for other in (r1, r3):
                assert not np.shares_memory(a, arrays(other)[f]), (need, f)
        for f, a in arrays(r2).items():                # r3 did not write into r2
            assert np.array_equal(a, keep[f])
        a1 = m.solve(np.array([0.3, 1.0]), omega=10.0, need=need)
        a2 = m.solve(np.array([0.3, 1.0]), omega=10.0, need=need)
        for f, a in arrays(a1).items():
            assert not np.shares_memory(a, arrays(a2)[f]), (need, f)


def outcome(f):
    """What f() does: its result's arrays, or the error's type and text, and the
    warnings (category, text, file) it gives."""
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            got = ("ok", {k: np.asarray(v).tobytes() for k, v in arrays(f()).items()})
        except Exception as exc:
            got = (type(exc), str(exc), getattr(exc, "index", None))
    return got, [(x.category, str(x.message), x.filename) for x in w]


BAD = [
    dict(phi=math.nan), dict(phi=math.inf), dict(omega=math.nan), dict(epsilon=-math.inf),
    dict(gravity=math.nan), dict(gravity="9.81"), dict(omega="10"), dict(omega=None),
    dict(need="speeds"), dict(need=None), dict(on_error="ignore"), dict(points=("Z",)),
    dict(points=("B", 3)), dict(links=(("A", "C"),)), dict(links=5), dict(points=["B"]),
    dict(omega=np.array([1.0, 2.0])), dict(t=1.0), dict(phi=np.float64(0.3)),
    dict(omega=10), dict(gravity=0),
    # positions that fail or lose digits (the four-bar with a short rocker: a toggle at pi)
    dict(phi=PI - 1e-5, rcb=0.15), dict(phi=PI - 1e-5, rcb=0.15, on_error="nan"),
    dict(phi=PI - 1e-3, rcb=0.15), dict(phi=PI - 1e-3, rcb=0.15, on_error="nan"),
    dict(phi=1.0, rcb=0.001), dict(phi=1.0, rcb=0.001, on_error="nan"),
    dict(omega=1e155), dict(omega=1e155, on_error="nan"),
    # a 1-d phi of the planned size
    dict(phi=np.array([0.3, 1.0])), dict(phi=np.array([0.3, math.nan])),
    dict(phi=np.array([-math.inf, 1.0])), dict(phi=np.array([0.3, 1.0]), omega=math.inf),
    dict(phi=np.array([0.3, 1.0])[::-1]), dict(phi=np.array([0.3, 1.0], dtype=np.float32)),
    dict(phi=np.array([1.0, PI - 1e-5]), rcb=0.15),
    dict(phi=np.array([1.0, PI - 1e-5]), rcb=0.15, on_error="nan"),
    dict(phi=np.array([PI - 1e-3, PI - 1e-2]), rcb=0.15),
    dict(phi=np.array([0.3, 1.0]), omega=1e155, on_error="nan"),
]


@pytest.mark.parametrize("bad", BAD, ids=[repr(b) for b in BAD])
def test_bad_input_raises_as_before(bad):
    """Each call, once the fast way's plan exists, does what it does on a fresh mechanism
    (no plan: the general way), error, text, warnings and their file alike."""
    bad = dict(bad)
    rcb = bad.pop("rcb", 0.3)

    def build():
        m = Mechanism()
        m.fixed("O", 0.0, 0.0)
        m.fixed("C", 0.4, 0.0)
        m.crank("A", "O", 0.1)
        m.rrr("B", "A", "C", 0.35, rcb, branch=1)
        return m
    base = dict(phi=0.3, omega=10.0, epsilon=0.0, need="accelerations", gravity=0.0,
                on_error="raise", points=None, links=None)
    call = {**base, **bad}
    warm = m = build()
    for need in NEEDS:                                  # every plan the fast way may use
        for s in ({}, {"points": ("B",)}, {"links": (("A", "B"),)}, {"points": ("Z",)}):
            for p in (1.0, np.array([1.0, 2.0])):
                try:
                    warm.solve(p, omega=1.0, need=need, **s)
                    warm.solve(p, omega=1.0, need=need, **s)
                except (ValueError, sarkp.SarkpError):
                    pass
    assert m._cache["fast"]
    phi = call.pop("phi")
    planned_way = outcome(lambda: m.solve(phi, **call))
    fresh_way = outcome(lambda: build().solve(phi, **call))
    assert planned_way == fresh_way
    assert all(w[2] == __file__ for w in planned_way[1])


def test_failures_at_one_position_the_fast_way():
    """The fast way's failures: the same error class and position as DPRM1 says; NaN
    and the status with on_error="nan"."""
    m = Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.4, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.001, branch=1)
    m.solve(1.0, need="positions", on_error="nan")
    r = m.solve(1.0, need="positions", on_error="nan")
    reach = math.hypot(0.4 - 0.1 * math.cos(1.0), 0.1 * math.sin(1.0))
    assert reach > 0.35 + 0.001                        # so B cannot be placed
    assert int(r.status) == int(sarkp.Status.ASSEMBLY)
    assert np.isnan(r.position("B")).all()
    with pytest.raises(AssemblyError, match="phi = 1.0"):
        m.solve(1.0, need="positions")
    m4 = fourbar()
    for _ in range(2):                                 # the general way, then the fast
        with pytest.raises(RangeError, match="overflows at phi = 0.3"):
            m4.solve(0.3, omega=1e155)
    r = m4.solve(0.3, omega=1e155, on_error="nan")
    assert int(r.status) == int(sarkp.Status.RANGE) and np.isnan(r.acceleration("B")).all()
    m5 = Mechanism()
    m5.fixed("O", 0.0, 0.0)
    m5.fixed("C", 0.4, 0.0)
    m5.crank("A", "O", 0.1)
    m5.rrr("B", "A", "C", 0.35, 0.15, branch=1)    # 0.35 + 0.15 = OC + OA: toggle at pi
    m5.solve(1.0)
    with pytest.raises(SingularError):
        m5.solve(PI)


def test_changes_of_the_description_reach_the_fast_way():
    m = fourbar()
    m.solve(0.7, need="forces")
    m.solve(0.7, need="forces")
    m.set_branch("B", -1)
    other = fourbar()
    other.set_branch("B", -1)
    same(m.solve(0.7, need="forces"), other.solve(0.7, need="forces"))
    m.mass("O", "A", mass=0.5, inertia=0.001, centre=0.05)
    other.mass("O", "A", mass=0.5, inertia=0.001, centre=0.05)
    same(m.solve(0.7, need="forces"), other.solve(0.7, need="forces"))
    with sarkp.as_printed():
        with pytest.warns(UserWarning, match="no as-printed mode"):
            m.solve(0.7, need="forces")


def test_buffers_beyond_a_structured_type_are_viewed_field_by_field(monkeypatch):
    """numpy's structured types stop at 2**31 - 1 bytes: a larger output buffer (a long
    sweep) is cut into the fields by slices; the same numbers (the limit lowered here
    instead of solving 10**7 positions)."""
    import sarkp.mechanism as mech
    phi = np.linspace(0.0, 2 * PI, 11)
    for need in NEEDS:
        ref = sixbar().solve(phi, omega=3.0, need=need, points=("E",))
        monkeypatch.setattr(mech, "_RECORD_LIMIT", 64)
        m = sixbar()
        r = m.solve(phi, omega=3.0, need=need, points=("E",))
        assert r.positions.shape == (11, 1, 2)
        same(r, ref)
        same(m.solve(phi, omega=3.0, need=need, points=("E",)), ref)
        monkeypatch.undo()
