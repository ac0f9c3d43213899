"""Chapter 5: cam mechanisms (listings V.1-V.4, book lines L3004-3330).

The follower's motion is given as tables over the cam angles ``FI`` (radians): its
acceleration, velocity and displacement (a translating follower: m/s^2, m/s, m; a
rocker: rad/s^2, rad/s, rad), as program V.5 builds them with DINTGR.  The cam turns
with the angular velocity ``W`` > 0, so the transfer functions are ``s' = V/W`` and
``s'' = A/W**2``.  The profile comes back in the cam's own frame (inversion of the
motion, L3132): Cartesian ``XA, YA`` and polar ``R1, DELTA`` with the book's
``DELTA = atan(XA/YA)`` (the principal value: it jumps by pi where ``YA`` changes sign,
as in Figs. 35-36).  A radius of curvature is positive where the profile is convex.

No routine of this chapter uses PI, so both modes compute the same here; program V.5
(:mod:`sarkp.book.prog_v_5`) differs between modes through PI and the ES EVM's arithmetic.
"""

from __future__ import annotations

import math

import numpy as np

from .library import ST_REQUIREMENT, ST_SINGULAR, Check, book_routine

__all__ = ["DKLCHK", "DPRFLP", "DPRFPL", "DPRFLK"]

_HALF_PI = math.pi / 2.0


def _open_angle(name):
    """ALD-like angle: must lie strictly between 0 and pi/2."""
    return Check(lambda **kw: not (0.0 < kw[name] < _HALF_PI), ST_REQUIREMENT,
                 f"{name} must lie strictly between 0 and pi/2 (radians)")


def _positive(name, what):
    return Check(lambda **kw: not (kw[name] > 0.0), ST_REQUIREMENT,
                 f"{name} = {what} must be > 0")


# ---- V.1 DKLCHK ------------------------------------------------------------------------

DKLCHK = book_routine(
    "DKLCHK", listing="V.1", lines="L3053-3100", chapter="cams",
    inputs=("N", "PRM", "VLST", "AKSLRT", "ALD", "BETA", "W1", "RSCNTR", "RZMR", "INDEX"),
    outputs=("RO", "EXCST", "ETAO"),
    tables={"PRM": "N", "VLST": "N", "AKSLRT": "N"},
    integers={"INDEX": (1, 2)},
    defaults={"RSCNTR": 0.0, "RZMR": 0.0, "INDEX": 1},
    checks=(
        _open_angle("ALD"),
        _positive("W1", "the angular velocity of the cam"),
        Check(lambda INDEX, ALD, BETA, **_: INDEX == 1 and not (
            abs(BETA) < _HALF_PI and math.sin(ALD + BETA) > 0.0), ST_REQUIREMENT,
              "BETA must satisfy |BETA| < pi/2 and sin(ALD + BETA) > 0"),
        Check(lambda INDEX, RSCNTR, RZMR, **_: INDEX == 2 and not (
            RSCNTR > 0.0 and RZMR > 0.0), ST_REQUIREMENT,
              "a rocker (INDEX = 2) needs the centre distance RSCNTR > 0 and the "
              "rocker length RZMR > 0"),
    ),
    messages={ST_REQUIREMENT: "the book's rule gives no positive radius RO: at the fastest "
                              "point the displacement exceeds VLST/W1/tan(ALD) (or the "
                              "rocker's two lengths and ETAO close the triangle)"},
    doc="""Main dimensions of a cam mechanism (listing V.1, L3053-3100; eq. (5.2), L3046).

The book's call is ``CALL DKLCHK(N, PRM, VLST, AKSLRT)`` with the other inputs, and the
results, in ``COMMON /KLCHK/ ALD, BETA, W1, RSCNTR, RZMR, INDEX, RO, EXCST, ETAO``
(L3079).  sarkp takes the COMMON inputs as arguments, in COMMON order, and returns the
COMMON results.

At the first maximum of the follower's velocity, ``VLST[L]``, the transfer function is
``IFI = VLST[L]/W1`` and the displacement ``S = PRM[L]``:

* ``INDEX = 1`` (translating follower): the offset ``e = RO sin(BETA)`` and the axial
  distance ``RO cos(BETA)`` make the pressure angle there equal to ALD,
  ``RO = (IFI/tan(ALD) - S) sin(ALD)/sin(ALD + BETA)``, ``EXCST = RO sin(BETA)``;
* ``INDEX = 2`` (rocker): ``ETAO = IFI/tan(ALD) - S``,
  ``RO = sqrt(RSCNTR**2 + RZMR**2 - 2 RSCNTR RZMR cos(ETAO))`` (the book's rule).

Parameters
----------
N : int
    Number of points; must equal the length of the tables.
PRM : array_like, shape (N,)
    Displacement of the follower (m), or the rocker's angle (rad) for INDEX = 2.
VLST : array_like, shape (N,)
    Velocity of the follower (m/s), or the rocker's angular velocity (rad/s).
AKSLRT : array_like, shape (N,)
    Acceleration of the follower; not used, as printed.
ALD : float
    Allowed pressure angle (rad), 0 < ALD < pi/2 (V.5: 0.523).
BETA : float
    Angle "from the non-jamming condition" (rad): 0 for a central mechanism
    (V.5: 0.35).  Used for INDEX = 1 only.
W1 : float
    Angular velocity of the cam (1/s), > 0.
RSCNTR, RZMR : float, optional
    Centre distance O1-O2 and rocker length (m); INDEX = 2 only (default 0).
INDEX : {1, 2}, optional
    1 translating follower (default), 2 oscillating follower (rocker).

Returns
-------
DKLCHK(RO, EXCST, ETAO)
    The COMMON /KLCHK/ results: ``RO`` the radius of the cam (m), ``EXCST`` the offset
    of a translating follower (m; 0 for INDEX = 2), ``ETAO`` the initial angle of the
    rocker (rad; 0 for INDEX = 1).

Raises
------
RequirementError
    ALD outside (0, pi/2), W1 <= 0, a BETA with sin(ALD + BETA) <= 0, a rocker without
    its lengths, or a rule that gives RO <= 0 (e.g. a motion whose largest velocity is
    not positive).
ValueError
    N not the length of the tables, INDEX not 1 or 2, a NaN or inf input.

Notes
-----
When ``VLST[0]`` is the largest value the printed loop never sets L (ERRATA
E-DKLCHK-1); sarkp takes the first point.  Only the point of largest velocity is
checked: on the return stroke the pressure angle can exceed ALD (Fig. 35 reaches
0.82 rad there); DPRFLP's ``ALFMAX`` and ``NOVER`` report it.  DPRFLP uses RO as the
follower's axial distance, not as the base-circle radius that this rule assumes
(E-DPRFLP-3): the cam drawn by DPRFLP is a little larger than needed, and its rise
stays within ALD (Fig. 35: at most 0.52027 rad).
""")


# ---- V.2 DPRFLP ------------------------------------------------------------------------

DPRFLP = book_routine(
    "DPRFLP", listing="V.2", lines="L3149-3189", chapter="cams",
    inputs=("N", "RO", "EXCNTR", "W", "FI", "A", "V", "S", "ALD"),
    outputs=("XA", "YA", "R1", "DELTA", "ALFA", "ROK", "ALFMAX", "NOVER"),
    tables={"FI": "N", "A": "N", "V": "N", "S": "N"},
    lengths=("RO",),
    defaults={"ALD": math.pi / 6.0},
    checks=(
        _positive("W", "the angular velocity of the cam"),
        _open_angle("ALD"),
        Check(lambda RO, S, **_: bool(np.any(RO + np.asarray(S) <= 0.0)), ST_REQUIREMENT,
              "RO + S <= 0 at some point: the follower would pass the cam centre and the "
              "pressure angle reach 90 degrees (RO is smaller than the motion needs)"),
    ),
    messages={ST_SINGULAR: "the profile's curvature is exactly 0 at some point: its radius "
                           "of curvature is infinite"},
    doc="""Cam profile for a translating knife-edge follower with an offset (listing V.2,
L3149-3189).

The book's call is ``CALL DPRFLP(N, RO, EXCNTR, W, FI, A, V, S, XA, YA, R1, DELTA,
ALFA, ROK)`` (V.5 passes DKLCHK's RO and EXCST).  With ``s' = V/W``, ``s'' = A/W**2`` and
``C = RO + S`` (the follower's axis is the line at the distance EXCNTR from the cam
centre; its tip is at C from the foot of that distance):

* ``XA = EXCNTR cos(FI) + C sin(FI)``, ``YA = -EXCNTR sin(FI) + C cos(FI)``,
  ``R1 = sqrt(XA**2 + YA**2)``, ``DELTA = atan(XA/YA)``;
* ``ALFA = atan((s' - EXCNTR)/C)``, the pressure angle (eq. (5.2)): the angle between the
  profile's normal at the tip and the follower's axis;
* ``ROK = 1/OMEGA``, ``OMEGA = (C cos(ALFA) + s' sin(ALFA) cos(ALFA)**2
  - s'' cos(ALFA)**3)/C**2``, the exact curvature of this profile.

Parameters
----------
N : int
    Number of points; must equal the length of the tables.
RO : float
    The follower's axial distance at S = 0 (m), > 0: DKLCHK's RO.
EXCNTR : float
    Offset e of the follower's axis (m), any sign: DKLCHK's EXCST.
W : float
    Angular velocity of the cam (1/s), > 0.
FI : array_like, shape (N,)
    Cam angles (rad), in any order and spacing: every point is computed on its own
    (only the tables' integration, e.g. by DINTGR, needs a uniform step).
A, V, S : array_like, shape (N,)
    Acceleration (m/s^2), velocity (m/s) and displacement (m) of the follower.
ALD : float, optional
    sarkp extension: the allowed pressure angle (rad) for ``NOVER``; default pi/6 (30
    degrees, the usual limit for a translating follower).

Returns
-------
DPRFLP(XA, YA, R1, DELTA, ALFA, ROK, ALFMAX, NOVER)
    Arrays of shape (N,): ``XA, YA`` profile point (m) in the cam's frame, ``R1, DELTA``
    its polar radius (m) and angle (rad), ``ALFA`` pressure angle (rad), ``ROK`` radius
    of curvature (m, negative where the profile is concave).  Then two sarkp
    extensions: ``ALFMAX`` the largest ``|ALFA|`` (rad) and ``NOVER`` the number of points
    where ``|ALFA| > ALD`` (nonzero: the pressure angle passes the allowed one).

Raises
------
RequirementError
    W <= 0, ALD outside (0, pi/2), or RO + S <= 0 at some point.
SingularError
    The curvature is exactly zero at a point (its radius would be infinite).
ValueError
    N not the length of the tables, RO <= 0, a NaN or inf input.

Notes
-----
The printed listing swaps the names of the transfer functions (``D2SDFI = V(K)/W``,
``DSDFI = A(K)/W**2``, L3176-3177, ERRATA E-DPRFLP-1) and garbles the curvature
(L3184-3185, E-DPRFLP-2); Fig. 35 is reproduced only with the forms above, which both
modes use.  RO is an axial distance here, while DKLCHK derives it as the base-circle
radius (E-DPRFLP-3): the profile's smallest radius is ``sqrt(RO**2 + EXCNTR**2)``.
The pressure angle is checked on every point, rise and return alike.
""")


# ---- V.3 DPRFPL ------------------------------------------------------------------------

DPRFPL = book_routine(
    "DPRFPL", listing="V.3", lines="L3213-3257", chapter="cams",
    inputs=("N", "GAMMA", "W", "FI", "A", "V", "S"),
    outputs=("XA", "YA", "R1", "DELTA", "ROK", "RKSH", "ROKMIN", "NCONC"),
    tables={"FI": "N", "A": "N", "V": "N", "S": "N"},
    checks=(
        _positive("W", "the angular velocity of the cam"),
        _open_angle("GAMMA"),
    ),
    messages={ST_REQUIREMENT: "RKSH + S <= 0 at some point: the radius the convexity rule "
                              "gives is smaller than the motion needs"},
    doc="""Cam profile for a translating flat-faced follower (listing V.3, L3213-3257).

The book's call is ``CALL DPRFPL(N, GAMMA, W, FI, A, V, S, XA, YA, R1, DELTA, ROK,
RKSH)``; the radius of the cam RKSH is chosen by the routine.  At the first minimum of
the acceleration, ``A[L]``, with ``s''min = A[L]/W**2`` (the convexity rule (5.4), L3118):
``RKSH = |s''min/tan(GAMMA) + S[L]|``.  Then, with ``C = RKSH + S``, ``s' = V/W`` and
``s'' = A/W**2`` (L3205-3209):

* ``XA = C sin(FI) + s' cos(FI)``, ``YA = C cos(FI) - s' sin(FI)`` (the point where the
  face touches the cam, at ``s'`` from the follower's axis);
* ``R1 = sqrt(C**2 + s'**2)``, ``DELTA = atan(XA/YA)``, ``ROK = C + s''``.

The pressure angle of a flat face perpendicular to its axis is 0 everywhere.

Parameters
----------
N : int
    Number of points; must equal the length of the tables.
GAMMA : float
    Design angle (rad), 0 < GAMMA < pi/2.  GAMMA = pi/4 makes ROK = 0 at the point of
    the smallest acceleration (Fig. 36); a larger GAMMA gives a smaller cam whose
    profile is concave there (program X uses pi/3, Fig. 89).
W : float
    Angular velocity of the cam (1/s), > 0.
FI : array_like, shape (N,)
    Cam angles (rad), in any order and spacing: every point is computed on its own
    (only the tables' integration, e.g. by DINTGR, needs a uniform step).
A, V, S : array_like, shape (N,)
    Acceleration (m/s^2), velocity (m/s) and displacement (m) of the follower.

Returns
-------
DPRFPL(XA, YA, R1, DELTA, ROK, RKSH, ROKMIN, NCONC)
    Arrays of shape (N,): ``XA, YA`` contact point (m) in the cam's frame, ``R1, DELTA``
    its polar radius (m) and angle (rad), ``ROK`` radius of curvature (m); the float
    ``RKSH``, the radius of the cam (m).  Then two sarkp extensions: ``ROKMIN`` the
    smallest ROK (m) and ``NCONC`` the number of points where ROK < 0 beyond rounding
    (``ROK < -16 eps (RKSH + max|S| + max|s''|)``): nonzero means a flat face cannot
    realize this profile.

Raises
------
RequirementError
    W <= 0, GAMMA outside (0, pi/2), or RKSH + S <= 0 at some point.
ValueError
    N not the length of the tables, a NaN or inf input.

Notes
-----
The listing's comment asks for "GAMMA greater than PI/4" (L3225); a convex profile needs
GAMMA <= pi/4 (ERRATA E-DPRFPL-1).  When ``A[0]`` is the smallest value the printed
loop never sets L (E-DPRFPL-2); sarkp takes the first point.  The ABS of the printed
rule is kept: it hides a rule that asks for no radius at all.  Program X calls
DPRFPL without S (L7467, E-X-DPRFPL-1); Fig. 89's radius needs S, so the signature is
V.3's.  Fig. 36's design (GAMMA = pi/4) has ROK = 0 at two points; sarkp's runs of it
are not flagged, while the ES EVM's gave -1.3e-6 m at the second (printed -0.00000).
""")


# ---- V.4 DPRFLK ------------------------------------------------------------------------

def _sin_psi_zero(PSI, ETAO, **_):
    return bool(np.any(np.sin(np.asarray(PSI) + ETAO) == 0.0))


DPRFLK = book_routine(
    "DPRFLK", listing="V.4", lines="L3270-3320", chapter="cams",
    inputs=("N", "W1", "ETAO", "FI", "RO", "L", "R", "E2", "W2", "PSI", "ALD"),
    outputs=("XA", "YA", "R1", "DELTA", "RKRZVN", "ALFA", "ALFMAX", "NOVER"),
    tables={"FI": "N", "E2": "N", "W2": "N", "PSI": "N"},
    lengths=("L", "R"),
    defaults={"ALD": math.pi / 4.0},
    checks=(
        _positive("W1", "the angular velocity of the cam"),
        _open_angle("ALD"),
        Check(_sin_psi_zero, ST_SINGULAR,
              "sin(PSI + ETAO) = 0 at some point: the rocker lies on the line of centres "
              "and the pressure angle is 90 degrees"),
    ),
    messages={
        ST_REQUIREMENT: "the rocker's tip reaches the cam centre (R1 = 0) at some point",
        ST_SINGULAR: "sin(PSI + ETAO) = 0 (pressure angle 90 degrees) or the profile's "
                     "curvature is exactly 0 (radius infinite) at some point",
    },
    doc="""Cam profile for an oscillating (rocker) knife-edge follower (listing V.4,
L3270-3320).

The book's call is ``CALL DPRFLK(N, W1, ETAO, FI, RO, L, R, E2, W2, PSI, XA, YA, R1,
DELTA, RKRZVN, ALFA)`` (printed with ``F1`` for FI, ERRATA E-DPRFLK-1).  The rocker of
length R turns about O2 at the distance L from the cam centre O1; ``psi = PSI + ETAO``
is its angle from the line O2-O1.  With ``psi' = W2/W1`` and ``psi'' = E2/W1**2``:

* ``XA = L cos(FI) - R cos(FI + psi)``, ``YA = -L sin(FI) + R sin(FI + psi)``,
  ``R1 = sqrt(L**2 - 2 L R cos(psi) + R**2)``, ``DELTA = atan(XA/YA)``;
* ``ALFA = atan(R (1 + psi')/(L sin(psi)) - 1/tan(psi))`` (eq. (5.5)), the angle between
  the profile's normal and the velocity of the rocker's tip;
* ``RKRZVN = C1/C2`` with ``C1 = (L**2 + R**2 (1+psi')**2 - 2 L R (1+psi') cos(psi))**1.5``
  and ``C2 = L**2 + R**2 (1+psi')**3 - L R (cos(psi) (1+psi') (2+psi') + psi'' sin(psi))``.

Parameters
----------
N : int
    Number of points; must equal the length of the tables.
W1 : float
    Angular velocity of the cam (1/s), > 0.
ETAO : float
    Initial angle of the rocker (rad): DKLCHK's ETAO for INDEX = 2.
FI : array_like, shape (N,)
    Cam angles (rad), in any order and spacing: every point is computed on its own
    (only the tables' integration, e.g. by DINTGR, needs a uniform step).
RO : float
    Radius of the cam; not used, as printed.
L : float
    Centre distance O1-O2 (m), > 0.
R : float
    Rocker length (m), > 0.
E2, W2, PSI : array_like, shape (N,)
    Angular acceleration (rad/s^2), angular velocity (rad/s) and angle (rad) of the
    rocker.
ALD : float, optional
    sarkp extension: the allowed pressure angle (rad) for ``NOVER``; default pi/4 (45
    degrees, the usual limit for a rocker).

Returns
-------
DPRFLK(XA, YA, R1, DELTA, RKRZVN, ALFA, ALFMAX, NOVER)
    Arrays of shape (N,): ``XA, YA`` profile point (m) in the cam's frame, ``R1, DELTA``
    its polar radius (m) and angle (rad), ``RKRZVN`` radius of curvature (m, negative
    where concave), ``ALFA`` pressure angle (rad).  Then two sarkp extensions: ``ALFMAX``
    the largest ``|ALFA|`` (rad) and ``NOVER`` the number of points where
    ``|ALFA| > ALD``.

Raises
------
SingularError
    sin(PSI + ETAO) = 0 at a point, or the curvature is exactly zero there.
RequirementError
    W1 <= 0, ALD outside (0, pi/2), or the rocker's tip on the cam centre.
ValueError
    N not the length of the tables, L or R <= 0, a NaN or inf input.

Notes
-----
The book prints no example of DPRFLK.  Its C1 is garbled in print (L3312-3313,
E-DPRFLK-2): the form above is ``|P'|**3`` of the profile curve ``P(FI)``, as C2 is the
cross product ``P' x P''``; ``tests/test_cams.py`` proves both against the curvature of the
profile computed independently.  The prose's ``y_A`` has the wrong sign (L3266,
E-DPRFLK-3).
""")
