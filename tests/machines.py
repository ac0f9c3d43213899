"""The multibody benchmark machines, described as sarkp Mechanisms (shared by the tests
and benchmarks/work_precision.py).

* A01-like pendulum: a crank of length L with a point mass at its tip.
* A02 N-four-bar (IFToMM benchmark library): a crank and N RRR groups of unit bars of
  1 kg (inertia 1/12 about the middle), pivots 1 m apart along x: a chain of
  parallelograms; its crank angle follows J phi'' = -G cos(phi) with the constants
  J = (4N + 1)/3 and G = g (3N + 1)/2.
* A03 Andrews' squeezer (Hairer & Wanner, "Solving ODEs II", section VII.7; the Test Set
  for IVP solvers, problem "andrews"): 7 bodies, the crank K1 driven by a constant torque,
  a spring from point D of body K3 to the frame.  The geometry and data are the Test
  Set's; each body's centre of mass is at the distance the Test Set's mass matrix implies
  (for bodies turning about a frame pivot only that distance matters).
"""

import math

import mpmath as mp
import numpy as np

import sarkp

G = 9.81


def pendulum(L=1.0, mass=1.0):
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.crank("P", "O", L)
    m.mass("O", "P", mass=mass, inertia=0.0, centre=L)
    return m


def n_four_bar(N):
    m = sarkp.Mechanism()
    for k in range(N + 1):
        m.fixed(f"O{k}", float(k), 0.0)
    m.crank("A0", "O0", 1.0)
    m.mass("O0", "A0", mass=1.0, inertia=1.0 / 12.0, centre=0.5)
    for k in range(1, N + 1):
        # the parallelogram: A_k = A_{k-1} + (1, 0), left of the line A_{k-1} -> O_k
        # while the crank points up (0 < phi < pi)
        m.rrr(f"A{k}", f"A{k - 1}", f"O{k}", 1.0, 1.0, branch=1)
        m.mass(f"A{k - 1}", f"A{k}", mass=1.0, inertia=1.0 / 12.0, centre=0.5)
        m.mass(f"O{k}", f"A{k}", mass=1.0, inertia=1.0 / 12.0, centre=0.5)
    return m


# Andrews' squeezer: the Test Set's data (andrews.f)
SQ = dict(m1=.04325, m2=.00365, m3=.02373, m4=.00706, m5=.07050, m6=.00706, m7=.05498,
          i1=2.194e-6, i2=4.410e-7, i3=5.255e-6, i4=5.667e-7, i5=1.169e-5, i6=5.667e-7,
          i7=1.912e-5, d=28e-3, da=115e-4, e=2e-2, ea=1421e-5, rr=7e-3, ra=92e-5,
          ss=35e-3, sa=1874e-5, sb=1043e-5, sc=18e-3, sd=2e-2, ta=2308e-5, tb=916e-5,
          u=4e-2, ua=1228e-5, ub=449e-5, zf=2e-2, zt=4e-2, fa=1421e-5, mom=33e-3,
          c0=4530.0, lo=7785e-5, xa=-.06934, ya=-.00227, xb=-0.03635, yb=.03273,
          xc=.014, yc=.072)
#: the crank angle at rest at t = 0 (the Test Set's consistent initial values)
SQUEEZER_BETA0 = -0.0617138900142764496358948458001
#: beta(0.03) to 20 digits (the issue's 40-digit reference, an independent computation;
#: the Test Set publishes 15.81077119629904, right to 10 digits)
SQUEEZER_BETA_003 = 15.810771195153707097


def squeezer():
    p = SQ
    m = sarkp.Mechanism()
    m.fixed("O", 0.0, 0.0)
    m.fixed("A", p["xa"], p["ya"])
    m.fixed("B", p["xb"], p["yb"])
    m.fixed("C", p["xc"], p["yc"])
    m.crank("F", "O", p["rr"])                         # K1, angle beta
    m.rrr("E", "F", "B", p["d"], p["ss"], branch=1)    # K2 (F-E) and K3 (B-E)
    m.rrr("G", "E", "A", p["e"], p["zt"], branch=-1)    # K4 (E-G) and K5 (A-G)
    m.rrr("H", "E", "A", p["zf"], p["u"], branch=1)   # K6 (E-H) and K7 (A-H)
    # D on K3: sc along B->E, sd to its left (the Test Set's xd, yd)
    m.point("D", "B", "E", math.hypot(p["sc"], p["sd"]), math.atan2(p["sd"], p["sc"]))
    m.mass("O", "F", mass=p["m1"], inertia=p["i1"], centre=p["ra"])
    m.mass("F", "E", mass=p["m2"], inertia=p["i2"], centre=p["da"])
    m.mass("B", "E", mass=p["m3"], inertia=p["i3"], centre=math.hypot(p["sa"], p["sb"]))
    m.mass("E", "G", mass=p["m4"], inertia=p["i4"], centre=p["ea"])
    m.mass("A", "G", mass=p["m5"], inertia=p["i5"], centre=math.hypot(p["ta"], p["tb"]))
    m.mass("E", "H", mass=p["m6"], inertia=p["i6"], centre=p["fa"])
    m.mass("A", "H", mass=p["m7"], inertia=p["i7"], centre=math.hypot(p["ua"], p["ub"]))
    m.spring("D", "C", p["c0"], p["lo"])
    m.torque("O", "F", p["mom"])
    return m


# -- exact references (mpmath) ----------------------------------------------------------
def pendulum_exact(t, L=1.0, g=G):
    """phi(t) of the pendulum from rest at phi = 0 (horizontal), phi from +x."""
    with mp.workdps(30):
        k = mp.sin(mp.pi / 4)
        K = mp.ellipk(k**2)
        w0 = mp.sqrt(mp.mpf(g) / L)
        return np.array([float(-mp.pi / 2 + 2 * mp.asin(
            k * mp.ellipfun("sn", K - w0 * mp.mpf(tt), m=k**2))) for tt in t])


def four_bar_exact(N, t, g=G):
    """The N-four-bar's crank angle from the energy integral J w^2/2 + G sin(phi) =
    J/2 + G (start vertical at 1 rad/s), J = (4N + 1)/3, G = g (3N + 1)/2."""
    with mp.workdps(25):
        J = mp.mpf(4 * N + 1) / 3
        Gm = mp.mpf(g) * (3 * N + 1) / 2
        w = lambda x: mp.sqrt(1 + 2 * Gm * (1 - mp.sin(x)) / J)       # noqa: E731
        time = lambda x: mp.quad(lambda y: 1 / w(y), [mp.pi / 2, x])  # noqa: E731
        T = mp.quad(lambda y: 1 / w(y), [mp.pi / 2, 3 * mp.pi / 2, 5 * mp.pi / 2])
        out = []
        for tt in t:
            k = mp.floor(mp.mpf(tt) / T)
            r = mp.mpf(tt) - k * T
            x = mp.findroot(lambda x: time(x) - r, mp.pi / 2 + r * w(mp.pi))
            out.append(float(x + 2 * mp.pi * k))
        return np.array(out), float(T), time
