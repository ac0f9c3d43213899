"""Mechanism.simulate: the motion in time, against independent references.

* A01-like pendulum released from the horizontal: the Jacobi elliptic solution
  sin(theta/2) = k sn(K - sqrt(g/L) t | k^2) (mpmath), through 16 reversals in 20 s.
* A02 N-four-bar (N = 1, 2, 40): the crank angle from the energy integral (mpmath quad and
  findroot), the chain kept a parallelogram through every toggle and change point.
* A03 Andrews' squeezer from rest: beta(0.03) against the 20-digit reference.
"""

from __future__ import annotations

import math
import pickle
import sys
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import sarkp

sys.path.insert(0, str(Path(__file__).parent))
import machines  # noqa: E402

G = 9.81




def test_pendulum_against_jacobi_through_16_reversals():
    m = machines.pendulum()
    t = np.linspace(0.0, 20.0, 201)
    sim = m.simulate(t, phi0=0.0, omega0=0.0, gravity=G, rtol=1e-10)
    exact = machines.pendulum_exact(t)
    assert np.max(np.abs(sim.phi - exact)) < 1e-9
    # omega from the energy integral, epsilon from the law of motion
    w_exact = np.sqrt(np.maximum(2 * G * (-np.sin(exact)), 0.0))
    assert np.max(np.abs(np.abs(sim.omega) - w_exact)) < 1e-7
    assert np.max(np.abs(sim.epsilon + G * np.cos(sim.phi))) < 1e-8
    # reversals at every half period 2K/sqrt(g), alternately at phi = -pi and 0
    turns = sim.events_of("turning point")
    half = 2 * float(mp.ellipk(0.5)) / math.sqrt(G)
    assert len(turns) == 16
    for i, e in enumerate(turns, start=1):
        assert abs(e.t - i * half) < 1e-9
        assert abs(e.phi - (-math.pi if i % 2 else 0.0)) < 1e-9
        assert e.omega == 0.0 and abs(abs(e.epsilon) - G) < 1e-6
    assert sim.status == "ok" and not sim.events_of("stall")


def test_pendulum_error_follows_rtol():
    m = machines.pendulum()
    t = np.linspace(0.0, 5.0, 26)
    exact = machines.pendulum_exact(t)
    errors = [np.max(np.abs(m.simulate(t, gravity=G, rtol=r).phi - exact))
              for r in (1e-4, 1e-7, 1e-10)]
    assert errors[0] < 1e-3 and errors[1] < 1e-6 and errors[2] < 1e-9


@pytest.mark.parametrize("N, rtol, bound", [(1, 1e-10, 2e-9), (2, 1e-9, 2e-8),
                                            (40, 1e-7, 1e-6)])
def test_n_four_bar_against_the_energy_integral(N, rtol, bound):
    m = machines.n_four_bar(N)
    t = np.linspace(0.0, 20.0, 5)
    exact, T, time = machines.four_bar_exact(N, t)
    sim = m.simulate(t, phi0=math.pi / 2, omega0=1.0, gravity=G, rtol=rtol)
    assert np.max(np.abs(sim.phi - exact)) < bound
    # every toggle (phi = pi mod 2 pi) and change point (0 mod 2 pi) passed is a branch
    # event of all N groups, at the time of the energy integral
    branch = sim.events_of("branch")
    crossings = np.arange(np.ceil(sim.phi[0] / math.pi), np.floor(sim.phi[-1] / math.pi)
                          + 1) * math.pi
    assert len(branch) == len(crossings)
    for e, x in zip(branch, crossings):
        k = math.floor((x - math.pi / 2) / (2 * math.pi))
        te = float(time(mp.mpf(x) - 2 * k * mp.pi)) + k * T
        assert abs(e.phi - x) < 1e-9 and abs(e.t - te) < 50 * bound
        assert all(f"'A{j}'" in e.note for j in range(1, N + 1))
    # the chain stays a parallelogram: A_k = A_0 + (k, 0) at every time
    r = sim.solve(need="positions")
    a0 = r.position("A0")
    for k in (1, N):
        assert np.max(np.abs(r.position(f"A{k}") - a0 - [k, 0.0])) < 1e-9
    # the user's mechanism is not changed
    assert m.branch(f"A{N}") == 1


def test_n_four_bar_geometric_branches_cannot_pass():
    m = machines.n_four_bar(1)
    with pytest.raises(sarkp.SarkpError, match="toggle or change point"):
        m.simulate([0.0, 0.5], phi0=3.0, omega0=5.0, gravity=G, rtol=1e-8,
                   branches="geometric")


def test_squeezer_from_rest():
    m = machines.squeezer()
    sim = m.simulate(np.linspace(0.0, 0.03, 4), phi0=machines.SQUEEZER_BETA0, rtol=1e-10)
    assert abs(sim.phi[-1] - machines.SQUEEZER_BETA_003) < 1e-11
    # the Test Set's published value is right to 10 digits only
    assert abs(15.81077119629904 - machines.SQUEEZER_BETA_003) > 1e-9
    assert not sim.events and sim.status == "ok"
    assert sim.stats["order"] == 16


def test_solve_along_the_motion_gives_the_law_of_motion():
    """At the simulated (phi, omega, epsilon), no balancing moment is needed: the
    mechanism's own loads move it."""
    m = machines.squeezer()
    sim = m.simulate(np.linspace(0.0, 0.03, 31), phi0=machines.SQUEEZER_BETA0, rtol=1e-10)
    r = sim.solve()
    scale = np.max(np.abs(r.reduced_moment))
    assert np.max(np.abs(r.balancing_moment)) < 1e-8 * scale
    assert r.position("E").shape == (31, 2)


def test_result_pickles_prints_and_converts():
    m = machines.pendulum()
    sim = m.simulate(np.linspace(0, 3, 7), gravity=G)
    text = repr(sim)
    assert "turning point" in text and "7 times" in text
    back = pickle.loads(pickle.dumps(sim))
    assert np.array_equal(back.phi, sim.phi) and back.events == sim.events
    frame = sim.to_frame()
    assert list(frame.columns) == ["t", "phi", "omega", "epsilon"]


def test_animation_is_written(tmp_path):
    pytest.importorskip("matplotlib")
    m = machines.n_four_bar(2)
    sim = m.simulate(np.linspace(0, 0.3, 4), phi0=math.pi / 2, omega0=1.0, gravity=G)
    path = tmp_path / "chain.gif"
    sim.animate(path)
    assert path.stat().st_size > 0


@pytest.mark.parametrize("kwargs, name", [
    (dict(t=[0.0, 1.0, 1.0]), "t"), (dict(t=[0.0, 2.0, 1.0]), "t"), (dict(t=[0.0]), "t"),
    (dict(t=[0.0, math.nan]), "t"), (dict(rtol=-1e-8), "rtol"), (dict(rtol=0.0), "rtol"),
    (dict(rtol=math.nan), "rtol"), (dict(rtol=math.inf), "rtol"),
    (dict(phi0=math.nan), "phi0"), (dict(omega0=math.inf), "omega0"),
    (dict(gravity=math.nan), "gravity"), (dict(branches="book"), "branches"),
])
def test_bad_input_names_the_argument(kwargs, name):
    m = machines.pendulum()
    args = dict(t=[0.0, 1.0], gravity=G)
    args.update(kwargs)
    t = args.pop("t")
    with pytest.raises(ValueError, match=name):
        m.simulate(t, **args)


def test_a_start_where_the_mechanism_does_not_assemble():
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.3, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.15, 0.1)          # reaches only near phi = 0... not at pi
    m.mass("A", "B", mass=1.0)
    with pytest.raises(ValueError, match="phi0"):
        m.simulate([0.0, 1.0], phi0=math.pi, gravity=G)


def test_readme_motion_in_time_example(capsys):
    """The README's "Motion in time" example runs and prints what the README shows."""
    import re
    text = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Motion in time"):]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    shown = re.search(r"prints\n\n```\n(.*?)```", section, re.S).group(1)
    exec(compile(code, "README.md", "exec"), {})
    assert capsys.readouterr().out == shown


def test_a_loose_tolerance_does_not_lose_a_branch_change():
    """At rtol 1e-4 steps leapt past a crossing's warning and the N-four-bar (N = 1) went
    on the wrong branch, 34.9 rad off by t = 20 s, silently; with groups followed the
    tolerance is at most 1e-6."""
    m = machines.n_four_bar(1)
    t = np.array([0.0, 10.0, 20.0])
    exact, _, _ = machines.four_bar_exact(1, t)
    sim = m.simulate(t, phi0=math.pi / 2, omega0=1.0, gravity=G, rtol=1e-4)
    assert np.max(np.abs(sim.phi - exact)) < 1e-7


def _flywheel(J):
    """A crank carrying a disc of inertia J about its pivot (no gravity load)."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.crank("A", "O", 0.5)
    m.mass("O", "A", mass=1.0, inertia=J, centre=0.0)
    return m


def test_stall_against_coulomb_friction():
    """A flywheel J = 2 at 3 rad/s, a motor torque of 1 N m against dry friction of 3 N m
    (a load of omega, zero at rest): it slows at (1 - 3)/2 = -1 rad/s^2, stops at t = 3 s,
    phi = 4.5 rad, and the friction holds it there (the motor is weaker): a stall event
    at that time and angle, status "stalled", rest afterwards -- not a crash."""
    m = _flywheel(2.0)
    m.torque("O", "A", lambda phi, omega: 1.0 - 3.0 * np.sign(omega))
    t = np.linspace(0.0, 5.0, 11)
    sim = m.simulate(t, phi0=0.0, omega0=3.0, rtol=1e-10)
    assert sim.status == "stalled"
    (stall,) = sim.events_of("stall")
    assert abs(stall.t - 3.0) < 1e-8 and abs(stall.phi - 4.5) < 1e-8
    moving = t < 3.0
    assert np.max(np.abs(sim.phi[moving] - (3.0 * t - 0.5 * t**2)[moving])) < 1e-9
    assert np.max(np.abs(sim.omega[moving] - (3.0 - t)[moving])) < 1e-9
    assert np.all(sim.phi[~moving] == stall.phi) and np.all(sim.omega[~moving] == 0.0)
    assert not sim.events_of("turning point")


def test_stall_against_a_one_way_load():
    """A 1 m pendulum released from the horizontal (phi = pi) with a pawl: a torque of
    2 m g L against any backward turning (a one-way load of omega).  Forward it swings
    freely (the Jacobi solution, mirrored), reaches the far horizontal phi = 2 pi at
    the half period 2 K(1/2)/sqrt(g), where gravity would turn it back: the pawl holds
    it -- a stall at that time and angle."""
    m = machines.pendulum()
    m.torque("O", "P", lambda phi, omega: np.where(omega < 0.0, 2.0 * G, 0.0))
    t = np.linspace(0.0, 2.0, 21)
    sim = m.simulate(t, phi0=math.pi, omega0=0.0, gravity=G, rtol=1e-10)
    half = 2 * float(mp.ellipk(0.5)) / math.sqrt(G)
    assert sim.status == "stalled"
    (stall,) = sim.events_of("stall")
    assert abs(stall.t - half) < 1e-8 and abs(stall.phi - 2 * math.pi) < 1e-8
    moving = t < half
    exact = math.pi - machines.pendulum_exact(t[moving])
    assert np.max(np.abs(sim.phi[moving] - exact)) < 1e-9
    assert np.all(sim.phi[~moving] == stall.phi)


def test_time_dependent_load():
    """A flywheel J = 2 from rest under the torque M(t) = cos(t): omega = sin(t)/2,
    phi = (1 - cos t)/2 (the load's t is the simulation's time), turning back at
    t = k pi."""
    m = _flywheel(2.0)
    m.torque("O", "A", lambda phi, omega, t: np.cos(t))
    t = np.linspace(0.0, 10.0, 21)
    sim = m.simulate(t, rtol=1e-10)
    assert np.max(np.abs(sim.phi - 0.5 * (1.0 - np.cos(t)))) < 1e-9
    assert np.max(np.abs(sim.omega - 0.5 * np.sin(t))) < 1e-9
    turns = sim.events_of("turning point")
    assert len(turns) == 3 and sim.status == "ok"
    for k, e in enumerate(turns, start=1):
        assert abs(e.t - k * math.pi) < 1e-8 and abs(e.epsilon - 0.5 * (-1) ** k) < 1e-8


def _offset_slider_crank():
    """Crank 1 m about O, rod 1.5 m, the slider B on the line y = 0.5 (offset 0.5 from
    the guide y = 0 through K = O): at phi = -pi/2 the rod stands normal to the guide,
    a toggle the crank passes (A is then 1.5 m from the slider's line)."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("K", 0.0, 0.0)
    m.crank("A", "O", 1.0)
    m.rrp("B", "A", "K", 0.0, 1.5, branch=1, offset=0.5)
    m.mass("O", "A", mass=0.0, inertia=1.0, centre=0.0)
    m.mass("B", mass=1.0)
    return m


def _slider_x(phi, lib=np):
    """B's x on the continuous motion: (x - cos phi)^2 = 2.25 - (sin phi - 0.5)^2
    = 2 sin^2(phi/2 + pi/4) (2 - sin phi), the root analytic in phi (period 4 pi)."""
    return lib.cos(phi) + lib.sqrt(2) * lib.sin(phi / 2 + lib.pi / 4) * \
        lib.sqrt(2 - lib.sin(phi))


def test_rrp_group_follows_the_motion_through_its_toggle():
    """The offset slider-crank, free (crank inertia 1, slider 1 kg, no gravity), from
    phi = 0 at 2 rad/s: the slider passes from one geometric branch to the other at
    every phi = 3 pi/2 (mod 2 pi).  References: B's x against the closed form of the
    continuous motion, the times of the toggles against the energy integral t(phi) =
    integral of sqrt(J(phi)/(2 E)) with J = 1 + x'(phi)^2 (mpmath), the energy kept."""
    m = _offset_slider_crank()
    t = np.linspace(0.0, 8.0, 17)
    sim = m.simulate(t, phi0=0.0, omega0=2.0, rtol=1e-10)
    r = sim.solve(need="forces")
    assert np.max(np.abs(r.position("B")[:, 0] - _slider_x(sim.phi))) < 1e-9
    assert np.max(np.abs(r.position("B")[:, 1] - 0.5)) < 1e-12
    energy = r.reduced_inertia * sim.omega**2 / 2
    assert np.max(np.abs(energy / energy[0] - 1.0)) < 1e-9
    with mp.workdps(30):
        J = lambda p: 1 + mp.diff(lambda q: _slider_x(q, mp), p) ** 2      # noqa: E731
        E = J(0) * 2                                                       # omega0 = 2
        when = lambda p: mp.quad(lambda q: mp.sqrt(J(q) / (2 * E)), [0, p])  # noqa: E731
        crossings = [3 * mp.pi / 2 + 2 * k * mp.pi for k in range(2)]
        times = [float(when(p)) for p in crossings]
    branch = sim.events_of("branch")
    assert sim.phi[-1] > float(crossings[-1]) and len(branch) == 2
    for e, p, te in zip(branch, crossings, times):
        assert abs(e.phi - float(p)) < 1e-9 and abs(e.t - te) < 1e-8
        assert "'B'" in e.note
    assert [b[1] for b in sim.branches] == [(1,), (-1,), (1,)]
    assert m.branch("B") == 1


def test_rpr_group_follows_the_motion_through_its_change_point():
    """A crank 1 m about O and a slotted link 3 about C = (1.5, 0) whose axis passes 0.5
    m from the crank pin (rpr, h = 0.5): at phi = 0 (mod 2 pi) the pin comes within 0.5
    m of C, B (the foot of the perpendicular) passes through C, and the continuous motion
    takes the other geometric branch.  References: the energy kept (crank and link 3,
    inertia 1 each, no loads), link 3's axis turning continuously (mod pi), B always
    0.5 m from A and on the axis through C."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 1.5, 0.0)
    m.crank("A", "O", 1.0)
    m.rpr("B", "A", "C", 0.5, math.pi / 2, branch=1)
    m.mass("O", "A", mass=0.0, inertia=1.0, centre=0.0)
    m.mass("C", "B", mass=0.0, inertia=1.0, centre=0.0)
    t = np.linspace(0.0, 8.0, 33)
    sim = m.simulate(t, phi0=math.pi / 2, omega0=2.0, rtol=1e-10)
    branch = sim.events_of("branch")
    assert len(branch) == 2 and sim.status == "ok"
    for e, k in zip(branch, (1, 2)):
        assert abs(e.phi - 2 * k * math.pi) < 1e-9
    r = sim.solve(need="forces")
    energy = r.reduced_inertia * sim.omega**2 / 2
    assert np.max(np.abs(energy / energy[0] - 1.0)) < 1e-9
    # the axis's direction mod pi moves by less than 0.6 rad between outputs
    step = np.diff(r.angle("C", "B"))
    assert np.max(np.abs((step + math.pi / 2) % math.pi - math.pi / 2)) < 0.6
    a, b = r.position("A"), r.position("B")
    assert np.max(np.abs(np.hypot(*(b - a).T) - 0.5)) < 1e-9
    d = b - [1.5, 0.0]
    assert np.max(np.abs(d[:, 0] * (b - a)[:, 0] + d[:, 1] * (b - a)[:, 1])) < 1e-9


def test_set_branch_after_a_solve_takes_effect():
    """set_branch updates the cached tables in place (simulate flips branches often):
    the next solve gives the other root, B mirrored in the line A -> C."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("C", 0.4, 0.0)
    m.crank("A", "O", 0.1)
    m.rrr("B", "A", "C", 0.35, 0.3, branch=1)
    phi = np.linspace(0.0, 2 * math.pi, 7)
    up = m.solve(phi, need="positions")
    b1, a = up.position("B"), up.position("A")
    m.set_branch("B", -1)
    b2 = m.solve(phi, need="positions").position("B")
    u = np.array([0.4, 0.0]) - a
    u /= np.hypot(*u.T)[:, None]
    d = b1 - a
    mirror = a + 2 * (d * u).sum(axis=1)[:, None] * u - d
    assert np.max(np.abs(b2 - mirror)) < 1e-14
    m.set_branch("B", 1)
    assert np.array_equal(m.solve(phi, need="positions").position("B"), b1)


def test_load_of_omega_through_toggles_and_change_points():
    """The N-four-bar (N = 1) with a damping torque -0.3 omega on the crank: its J is
    constant, (4N + 1)/3, so phi'' = (-G cos(phi) - 0.3 phi')/J, integrated here by
    scipy's DOP853 at rtol 1e-13 from the closed form.  The crank passes the toggle at
    pi and the change point at 2 pi, where simulate takes J, J' and M near the crossing
    from samples: M must be the damping at the motion's own omega (the samples are
    taken at omega = 1)."""
    from scipy.integrate import solve_ivp
    N, c = 1, 0.3
    J, Gm = (4 * N + 1) / 3, G * (3 * N + 1) / 2
    m = machines.n_four_bar(N)
    m.torque("O0", "A0", lambda phi, omega: -c * omega)
    t = np.linspace(0.0, 3.0, 13)
    sim = m.simulate(t, phi0=math.pi / 2, omega0=4.0, gravity=G, rtol=1e-10)
    ref = solve_ivp(lambda _, y: [y[1], (-Gm * math.cos(y[0]) - c * y[1]) / J],
                    (0.0, 3.0), [math.pi / 2, 4.0], method="DOP853", rtol=1e-13,
                    atol=1e-13, t_eval=t)
    assert len(sim.events_of("branch")) >= 2          # a toggle and a change point
    assert np.max(np.abs(sim.phi - ref.y[0])) < 1e-8
    assert np.max(np.abs(sim.omega - ref.y[1])) < 1e-8


def _guide_on_the_crank(alpha=0.3):
    """A rod 1.5 m about the frame pivot F = (1, 0) whose end B slides on a guide carried
    by the crank: through O, at the angle alpha from the crank's direction, B 0.5 m off
    its axis (along the left normal).  With psi = phi + alpha, u = (cos psi, sin psi):
    F's distance from B's line is 0.5 + sin psi <= 1.5, so at psi = pi/2 (mod 2 pi) the
    rod stands normal to the guide, a toggle the crank passes."""
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("F", 1.0, 0.0)
    m.crank("P", "O", 1.0)
    m.rrp("B", "F", "O", alpha, 1.5, branch=1, offset=0.5, guide=("O", "P"))
    m.mass("O", "P", mass=0.0, inertia=1.0, centre=0.0)
    m.mass("B", mass=1.0)
    return m


def _along_guide(psi, lib=np):
    """B's coordinate along the guide from O on the continuous motion:
    s = cos psi + root, root^2 = 2.25 - (sin psi + 0.5)^2 = 2 sin^2(pi/4 - psi/2)
    (2 + sin psi), the root analytic in psi (period 4 pi)."""
    return lib.cos(psi) + lib.sqrt(2) * lib.sin(lib.pi / 4 - psi / 2) * \
        lib.sqrt(2 + lib.sin(psi))


def test_rrp_group_on_a_moving_guide_follows_the_motion_through_its_toggle():
    """The guide turns with the crank (crank inertia 1, B 1 kg, no loads), from phi = 0
    at 2 rad/s: B passes from one geometric branch to the other at every psi = pi/2
    (mod 2 pi), where the side (B - F).u / l2 goes through zero while u turns.
    References: B = s u + 0.5 n against the closed form s(psi); the toggle times against
    the energy integral t(phi) = integral of sqrt(J / (2 E)), J = 1 + (s' - 0.5)^2 + s^2
    (B's speed per unit crank rate: v_B = (s' - 0.5) u + s n), by mpmath quad; energy
    kept.  The geometric rule (branches="geometric") stops at the toggle."""
    alpha = 0.3
    m = _guide_on_the_crank(alpha)
    t = np.linspace(0.0, 4.0, 17)
    sim = m.simulate(t, phi0=0.0, omega0=2.0, rtol=1e-10)
    r = sim.solve(need="forces")
    psi = sim.phi + alpha
    u = np.stack((np.cos(psi), np.sin(psi)), axis=1)
    n = np.stack((-np.sin(psi), np.cos(psi)), axis=1)
    exact = _along_guide(psi)[:, None] * u + 0.5 * n
    assert np.max(np.abs(r.position("B") - exact)) < 1e-9
    energy = r.reduced_inertia * sim.omega**2 / 2
    assert np.max(np.abs(energy / energy[0] - 1.0)) < 1e-9
    with mp.workdps(30):
        def J(p):
            s = _along_guide(p + alpha, mp)
            ds = mp.diff(lambda q: _along_guide(q + alpha, mp), p)
            return 1 + (ds - mp.mpf(0.5)) ** 2 + s ** 2
        E = J(0) * 2                                                       # omega0 = 2
        when = lambda p: mp.quad(lambda q: mp.sqrt(J(q) / (2 * E)), [0, p])  # noqa: E731
        crossings = [mp.pi / 2 - alpha + 2 * k * mp.pi for k in range(2)]
        times = [float(when(p)) for p in crossings]
    branch = sim.events_of("branch")
    assert sim.phi[-1] > float(crossings[-1]) and len(branch) == 2
    for e, p, te in zip(branch, crossings, times):
        assert abs(e.phi - float(p)) < 1e-9 and abs(e.t - te) < 1e-8
        assert "'B'" in e.note
    assert [b[1] for b in sim.branches] == [(1,), (-1,), (1,)]
    assert m.branch("B") == 1
    with pytest.raises(sarkp.RangeError, match="cannot (be )?follow"):
        m.simulate(t, phi0=0.0, omega0=2.0, rtol=1e-10, branches="geometric")


def test_side_rate_of_a_group_on_a_moving_guide():
    """The rate of the rrp side (B - F).u / l2 that the crossing search's Newton steps
    use, with the guide u turning with the crank (the term (B - F).u'), against central
    differences of the side itself."""
    from sarkp.dynamics import _Machine
    mach = _Machine(_guide_on_the_crank(), 0.0)
    phi = np.array([0.2, 0.9, 1.1, 2.5, -1.0])
    s, ds = mach.side_rate(phi, [0] * len(phi))
    h = 1e-5
    side = lambda p: mach.sides(mach.solve_with(p, (1,), "positions"))[:, 0]  # noqa: E731
    numeric = (side(phi + h) - side(phi - h)) / (2 * h)
    assert np.max(np.abs(s - side(phi))) < 1e-15
    assert np.max(np.abs(ds - numeric)) < 1e-8


# an output lies 3e-3 rad from a toggle: the solve along the motion warns of digits lost
@pytest.mark.filterwarnings("ignore::sarkp.SignificanceWarning")
def test_rrp_group_on_a_rocker_guide_follows_the_motion_through_its_toggles():
    """A four-bar (crank 0.3 m about O, coupler 1 m, rocker 0.8 m about D = (1, 0))
    whose rocker carries a guide through D along D->C; a rod 0.7 m about the frame pivot
    F = D + 0.5 (cos b, sin b), b = 1.95 + pi/2, slides B on it 0.2 m off the axis (to
    the right).  F's distance from B's line is 0.5 cos(theta - 1.95) + 0.2 <= 0.7 (theta
    the rocker's angle): the rod stands normal to the guide whenever the rocker passes
    theta = 1.95, twice a turn.  References: the crank angles of those toggles in closed
    form (C = D + 0.8 (cos 1.95, sin 1.95), A on the circle of 0.3 m about O 1 m from
    C), the energy kept (inertias 1, 0.5, 0.2 of crank, rocker, rod; B 1 kg; no
    loads), B 0.7 m from F and 0.2 m right of the guide's axis."""
    b = 1.95 + math.pi / 2
    F = np.array([1.0 + 0.5 * math.cos(b), 0.5 * math.sin(b)])
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("D", 1.0, 0.0)
    m.fixed("F", *F)
    m.crank("A", "O", 0.3)
    m.rrr("C", "A", "D", 1.0, 0.8, branch=1)
    m.rrp("B", "F", "D", 0.0, 0.7, branch=1, offset=-0.2, guide=("D", "C"))
    m.mass("O", "A", mass=0.0, inertia=1.0, centre=0.0)
    m.mass("D", "C", mass=0.0, inertia=0.5, centre=0.0)
    m.mass("F", "B", mass=0.0, inertia=0.2, centre=0.0)
    m.mass("B", mass=1.0)
    t = np.linspace(0.0, 6.0, 61)
    sim = m.simulate(t, phi0=0.0, omega0=2.0, rtol=1e-10)
    C = np.array([1.0 + 0.8 * math.cos(1.95), 0.8 * math.sin(1.95)])
    gam = math.atan2(C[1], C[0])
    half = math.acos((0.09 + C @ C - 1.0) / (0.6 * math.hypot(*C)))
    toggles = sorted(p + 2 * math.pi * k for p in (gam + half, gam - half + 2 * math.pi)
                     for k in range(3))
    toggles = [p for p in toggles if p < sim.phi[-1]]
    branch = sim.events_of("branch")
    assert len(toggles) == 4 and len(branch) == 4 and sim.status == "ok"
    for e, p in zip(branch, toggles):
        assert abs(e.phi - p) < 1e-9 and "'B'" in e.note
    assert [b[1] for b in sim.branches] == [(1, 1), (1, -1), (1, 1), (1, -1), (1, 1)]
    r = sim.solve(need="forces")
    energy = r.reduced_inertia * sim.omega**2 / 2
    assert np.max(np.abs(energy / energy[0] - 1.0)) < 1e-9
    B, th = r.position("B"), r.angle("D", "C")
    assert np.max(np.abs(np.hypot(*(B - F).T) - 0.7)) < 1e-12
    n = np.stack((-np.sin(th), np.cos(th)), axis=1)
    assert np.max(np.abs(((B - [1.0, 0.0]) * n).sum(axis=1) + 0.2)) < 1e-12
