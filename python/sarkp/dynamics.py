"""Chapter 8: dynamics of the machine (listings VIII.1-VIII.2, book lines L5935-6082).

``DZKNDV`` finds the steady-state law of motion omega(phi) of the reduction link from the
reduced moment and the reduced moment of inertia over one cycle, in the integral (energy)
form of the equation of motion, with the trapezoid rule; ``DMHVK`` the moment of inertia
of the flywheel that keeps the coefficient of speed fluctuation at a given delta.

Units (section 9.3): angles rad, omega rad/s, moments N*m, inertias kg*m^2, work and
energy J.  The tables span exactly one cycle of the reduction link, phi = 0 .. 2*pi with
both ends included: M points, step H = 2*pi/(M - 1).
"""

from __future__ import annotations

from .library import ST_REQUIREMENT, Check, book_routine

__all__ = ["DZKNDV", "DMHVK"]

_COUNT = range(2, 2**31 - 1)

DZKNDV = book_routine(
    "DZKNDV", listing="VIII.1", lines="L5935-5990", chapter="dynamics",
    inputs=("M", "ZM", "W1", "ISC", "MPR", "ISPR", "AAA"),
    outputs=("AS", "ASUM", "EV", "DEC", "WPR", "EPR"),
    tables={"MPR": "M", "ISPR": "M"}, integers={"M": _COUNT},
    nonnegative=("W1", "ISC", "ISPR"), nonzero=("W1", "ISC"),
    checks=(Check(lambda M, ZM, **_: ZM != M, ST_REQUIREMENT,
                  "ZM must equal M: the book passes the number of points twice, as an "
                  "integer and as a real (the step is 2*pi/(ZM - 1))"),),
    messages={ST_REQUIREMENT: "the kinetic energy would go negative: no steady motion "
                              "with the mean speed W1 has real speeds (the machine would "
                              "stall). More constant inertia ISC is needed, e.g. a "
                              "flywheel from DMHVK (DEC does not depend on ISC)"},
    doc="""Steady-state law of motion of the reduction link, energy form (listing VIII.1).

    Listing VIII.1 (L5939-5990), block diagram Fig. 70, eqs. (8.13)-(8.17), operator
    function (8.18).  The book's call is ``CALL DZKNDV(M, ZM, W1, ISC, MPR, ISPR, AAA, AS,
    ASUM, EV, DEC, WPR, EPR)``.

    Parameters
    ----------
    M : int
        Number of points (>= 2), covering exactly one cycle phi = 0 .. 2*pi, both ends
        included; equals ``len(MPR)``.
    ZM : float
        M again, as a real (the book passes both); must equal M.
    W1 : float
        Mean angular velocity omega_sr = (omega_max + omega_min)/2 of the reduction link
        (rad/s, > 0; the book's definition, L6044).
    ISC : float
        Constant part J_c of the reduced moment of inertia (kg*m^2, > 0).
    MPR : array_like, shape (M,)
        Reduced moment of the forces at the M points (N*m), positive where it does
        positive work on the reduction link (in the book's program X the moment of the
        group reactions on the crank, M1 of Fig. 94).
    ISPR : array_like, shape (M,)
        Variable part J_v(phi) of the reduced moment of inertia (kg*m^2, >= 0).
    AAA : float, optional
        The book's print flag; unused.

    Returns
    -------
    DZKNDV(AS, ASUM, EV, DEC, WPR, EPR)
        Arrays of M values:

        * ``AS``: the trapezoid integral of MPR from phi = 0 (DINTGR, NOMER = 2), J;
        * ``ASUM``: ``AS - (k-1)*AS[M-1]/(M-1)``, the total work when the constant driving
          moment ``-AS[M-1]/(2*pi)`` that makes the cycle's work zero (steady state) is
          added; ``ASUM[0] = ASUM[M-1] = 0``;
        * ``EV``: ``ISPR*W1**2/2``, the kinetic energy of the variable-inertia links at
          the mean speed, J;
        * ``DEC``: ``(ASUM - EV) - (ASUM[0] - EV[0])``, the change of the kinetic energy of
          the constant-inertia links (DMHVK's input), J;
        * ``WPR``: omega(phi), rad/s;
        * ``EPR``: ``(WPR[k] - WPR[k-1])/H``, ``EPR[0] = 0`` (DFRNCL): the backward
          difference d(omega)/d(phi) in 1/s, NOT the angular acceleration the listing's
          comment and the text (L5929) call it (ERRATA E-DZKNDV-1); the angular
          acceleration is ``WPR*EPR``.

    Raises
    ------
    RequirementError
        Corrected mode: no steady motion with mean speed W1 has real speeds -- the kinetic
        energy would go negative somewhere in the cycle (the machine stalls).  Also when
        ZM differs from M.

    Notes
    -----
    WPR, as printed, is eq. (8.17): ``W1 + (DEC - (C1 + C2)/2)/(W1*ISC)`` with C1, C2 the
    extremes of DEC, a linearisation (Delta E = J_c omega_sr Delta omega) that holds only
    for a vanishing fluctuation; it gives negative speeds when the fluctuation is large
    (Fig. 96 without flywheel: WPR = -290 rad/s).  As-printed mode keeps it (Fig. 96 depends
    on it).  Corrected mode solves the energy equation (8.13) itself,
    ``(ISC + ISPR[k])*WPR[k]**2/2 = E0 + ASUM[k]``, with E0 fixed by the same normalisation
    (max WPR + min WPR)/2 = W1, so that WPR is exact up to the trapezoid rule's O(H**2)
    (ERRATA E-DZKNDV-2; tests/test_dynamics.py checks it against a closed form and
    against scipy's solve_ivp).  PI is 3.14159 as printed (the listing's local PI, L5955).
    The printed DINTGR writes a line to unit 3 on every call; nothing is printed here.
    """)

DMHVK = book_routine(
    "DMHVK", listing="VIII.2", lines="L6052-6082", chapter="dynamics",
    inputs=("N", "DELTA", "ISC", "W1", "DEC", "AAA"), outputs=("IMHVK",),
    tables={"DEC": "N"}, integers={"N": range(1, 2**31 - 1)},
    nonnegative=("ISC", "W1"), nonzero=("ISC", "W1"),
    checks=(Check(lambda DELTA, **_: not 0.0 < DELTA < 1.0, ST_REQUIREMENT,
                  "DELTA, the coefficient of speed fluctuation (omega_max - omega_min)/"
                  "omega_sr, must lie in (0, 1)"),),
    doc="""Moment of inertia of the flywheel (listing VIII.2).

    Listing VIII.2 (L6055-6082), eqs. (8.22)/(8.24): ``IMHVK = (max DEC - min DEC)/
    (DELTA*W1**2) - ISC``, the flywheel that keeps the coefficient of speed fluctuation
    (omega_max - omega_min)/W1 at DELTA, neglecting the variable part J_v of the reduced
    inertia (J_A = J_B = J_c, L6034).

    Parameters
    ----------
    N : int
        Number of values in DEC; equals ``len(DEC)``.
    DELTA : float
        Coefficient of speed fluctuation, in (0, 1).
    ISC : float
        Constant part J_c of the reduced moment of inertia (kg*m^2, > 0).
    W1 : float
        Mean angular velocity of the reduction link (rad/s, > 0).
    DEC : array_like, shape (N,)
        The change of the kinetic energy of the constant-inertia links over the cycle,
        DZKNDV's ``DEC`` (J).  An input: the listing's comment puts it under RESULT
        (ERRATA E-DMHVK-2).
    AAA : float, optional
        The print flag, unused.  The listing has 6 arguments, without AAA; the only call
        in the book (program X, L7631) passes 7, with AAA before IMHVK as every routine of
        the library has it, and its printed result IMH = 4507.27 (L7203) shows that call
        ran: the flag is kept (ERRATA E-DMHVK-1).  ``DMHVK(N, DELTA, ISC, W1, DEC)`` works
        too.

    Returns
    -------
    DMHVK(IMHVK)
        The flywheel's moment of inertia on the reduction link's shaft (kg*m^2).  A
        negative value means that no flywheel is needed.

    Raises
    ------
    RequirementError
        DELTA not in (0, 1).

    Notes
    -----
    With DEC from DZKNDV, DZKNDV rerun with ``ISC + IMHVK`` gives exactly the coefficient
    DELTA: as printed for any ISPR (the linear law (8.17)), in corrected mode for
    ISPR = 0 (then the energy equation gives it exactly too, since
    (omega_max**2 - omega_min**2)/2 = delta*omega_sr**2).  The printed ``C1 + ABS(C2)``
    is the swing C1 - C2 whenever C1 >= 0 >= C2, which DZKNDV's DEC (DEC[0] = 0) always
    satisfies; the swing is used for any DEC (ERRATA E-DMHVK-3).
    """)
