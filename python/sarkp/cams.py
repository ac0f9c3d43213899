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

sarkp extensions (not in the book), for designing a cam rather than checking one:
:func:`motion_law` (the standard laws over rise-dwell-return-dwell, in closed form, with
their peak factors :data:`LAW_FACTORS`); roller followers :func:`roller_translating` and
:func:`roller_rocker` (pitch curve, working profile, curvature, undercut); and exact
sizing beside the book's rules: :func:`base_radius` (DKLCHK), :func:`flat_base_radius`
(DPRFPL) and :func:`rocker_centre_distance` (DKLCHK, INDEX = 2).
"""

from __future__ import annotations

import math

import numpy as np

from .library import ST_REQUIREMENT, ST_SINGULAR, Check, book_routine
from .results import result_type

__all__ = ["DKLCHK", "DPRFLP", "DPRFPL", "DPRFLK", "motion_law", "LAW_FACTORS",
           "roller_translating", "roller_rocker", "base_radius", "flat_base_radius",
           "rocker_centre_distance"]

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
E-DKLCHK-1); sarkp takes the first point.  The rule is the book's, kept as printed; the
smallest radius that keeps the pressure angle within ALD over the whole cycle is
:func:`base_radius` (for a rocker, whose INDEX = 2 rule applies the translating
follower's formula to angles, :func:`rocker_centre_distance`).  Only the point of
largest velocity is checked: on the return stroke the pressure angle can exceed ALD
(Fig. 35 reaches 0.82 rad there); DPRFLP's ``ALFMAX`` and ``NOVER`` report it.
DPRFLP uses RO as the follower's axial distance, not as the base-circle radius that
this rule assumes (E-DPRFLP-3): the cam drawn by DPRFLP is a little larger than needed,
and its rise stays within ALD (Fig. 35: at most 0.52027 rad).
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
The pressure angle is checked on every point, rise and return alike.  ``cos(ALFA)``
and ``sin(ALFA)`` are taken from the tangent, ``C/h`` and ``(s' - e)/h`` with
``h = hypot(C, s' - e)``, not as ``cos(atan(...))``, whose rounding near 90 degrees
leaves only the digits of ``pi/2 - ALFA`` that ALFA holds: ``DPRFLP(1, 1e-14, 0.0,
10.0, [0.7], [3.0], [0.5], [0.0]).ROK`` is 0.025 exactly, where the printed form gives
0.0250185 (ERRATA E-DPRFLP-5).  For a roller follower see :func:`roller_translating`.
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
``RKSH = |s''min/tan(GAMMA) + S[L]|`` (the book's rule looks at that one point; the
smallest radius that keeps the profile convex over the whole cycle is
:func:`flat_base_radius`).  Then, with ``C = RKSH + S``, ``s' = V/W`` and
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


# =========================================================================================
# sarkp extensions (not in the book): motion laws, roller followers, exact sizing.
# =========================================================================================

_TWO_PI = 2.0 * math.pi


class _Pieces:
    """A rise law given by its acceleration f''(x) over x in [0, 1], piece by piece:
    ``c0 + cs sin(w (x - x0)) + cc cos(w (x - x0))`` from ``x0`` to the next piece.
    Velocity and displacement are its integrals in closed form, continuous from f'(0) =
    f(0) = 0; the whole is scaled so that f(1) = 1 exactly (the scale is the law's
    acceleration amplitude)."""

    def __init__(self, pieces):
        self.x0 = np.array([p[0] for p in pieces] + [1.0])
        self.c = np.array([p[1:] for p in pieces], dtype=float)   # c0, cs, cc, w
        v0, s0 = [0.0], [0.0]
        for k in range(len(pieces)):
            u = self.x0[k + 1] - self.x0[k]
            a, v, s = self._local(k, np.array(u), v0[k], s0[k])
            v0.append(float(v))
            s0.append(float(s))
        self.v0, self.s0 = np.array(v0), np.array(s0)
        self.scale = 1.0 / s0[-1]

    def _local(self, k, u, v0, s0):
        c0, cs, cc, w = self.c[k]
        su, cu = np.sin(w * u), np.cos(w * u)
        a = c0 + cs * su + cc * cu
        v = v0 + c0 * u + cs * (1.0 - cu) / w + cc * su / w
        s = s0 + v0 * u + c0 * u**2 / 2 + cs * (u / w - su / w**2) + cc * (1.0 - cu) / w**2
        return a, v, s

    def __call__(self, x):
        f, f1, f2 = np.zeros_like(x), np.zeros_like(x), np.zeros_like(x)
        k = np.clip(np.searchsorted(self.x0, x, side="right") - 1, 0, len(self.c) - 1)
        for j in range(len(self.c)):
            at = k == j
            if at.any():
                a, v, s = self._local(j, x[at] - self.x0[j], self.v0[j], self.s0[j])
                f2[at], f1[at], f[at] = a, v, s
        return f * self.scale, f1 * self.scale, f2 * self.scale


def _poly345(x):
    return (x**3 * (10.0 - 15.0 * x + 6.0 * x**2), 30.0 * x**2 * (1.0 - x)**2,
            60.0 * x * (1.0 - x) * (1.0 - 2.0 * x))


_PI = math.pi
#: rise laws over x in [0, 1]: f, f', f'' (f(0) = 0, f(1) = 1).
_LAWS = {
    "harmonic": _Pieces([(0.0, 0.0, 0.0, _PI**2 / 2, _PI)]),
    "cycloidal": _Pieces([(0.0, 0.0, _TWO_PI, 0.0, _TWO_PI)]),
    "3-4-5": _poly345,
    # modified trapezoid: sine quarter-waves over the eighths 0-1/8, 3/8-5/8, 7/8-1
    "modified trapezoid": _Pieces([(0.0, 0.0, 1.0, 0.0, 4 * _PI), (0.125, 1.0, 0.0, 0.0, 1.0),
                                   (0.375, 0.0, 0.0, 1.0, 4 * _PI),
                                   (0.625, -1.0, 0.0, 0.0, 1.0),
                                   (0.875, 0.0, 0.0, -1.0, 4 * _PI)]),
    # modified sine: a quarter-wave of period 1/2 over 0-1/8 and 7/8-1, of period 3/2 between
    "modified sine": _Pieces([(0.0, 0.0, 1.0, 0.0, 4 * _PI),
                              (0.125, 0.0, 0.0, 1.0, 4 * _PI / 3),
                              (0.875, 0.0, 0.0, -1.0, 4 * _PI)]),
    "constant acceleration": _Pieces([(0.0, 4.0, 0.0, 0.0, 1.0), (0.5, -4.0, 0.0, 0.0, 1.0)]),
}

#: each law's peak velocity and acceleration factors: max f' and max |f''| over [0, 1]
#: (s'max = CV h/beta, |s''|max = CA h/beta**2 for a rise h over the cam angle beta).
LAW_FACTORS = {
    "harmonic": (_PI / 2, _PI**2 / 2),
    "cycloidal": (2.0, _TWO_PI),
    "3-4-5": (15.0 / 8.0, 10.0 / math.sqrt(3.0)),
    "modified trapezoid": (2.0, 8.0 * _PI / (2.0 + _PI)),
    "modified sine": None,                     # below, from the scale of its pieces
    "constant acceleration": (2.0, 4.0),
}


def _modified_sine_factors():
    # f'' = C sin(4 pi x) to x = 1/8, then C cos(4 pi (x - 1/8)/3): f' peaks at x = 1/2 with
    # C/(4 pi) + 3 C/(4 pi) = C/pi; C is the scale that makes f(1) = 1.
    c = _LAWS["modified sine"].scale
    return c / _PI, c


LAW_FACTORS["modified sine"] = _modified_sine_factors()

MotionLaw = result_type("MotionLaw", ("FI", "S", "V", "A", "PHASE", "CV", "CA", "CV_RETURN",
                                       "CA_RETURN"))


def _number(name, arg, value, *, above=None, at_least=None, below=None):
    """A scalar argument of an extension as a float, or TypeError/ValueError naming it."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: {arg} must be a real number, not "
                        f"{type(value).__name__} {value!r:.40}")
    v = float(value)
    bounds = []
    if above is not None:
        bounds.append(f"> {above:g}")
    if at_least is not None:
        bounds.append(f">= {at_least:g}")
    if below is not None:
        bounds.append(f"< {below:g}")
    if not (math.isfinite(v) and (above is None or v > above)
            and (at_least is None or v >= at_least) and (below is None or v < below)):
        raise ValueError(f"{name}: {arg} = {value!r} must be a finite number"
                         + (" " + " and ".join(bounds) if bounds else ""))
    return v


def _law(name, what):
    if not isinstance(name, str) or name not in _LAWS:
        raise ValueError(f"motion_law: {what} must be one of {sorted(_LAWS)}, not {name!r}")
    return name


def motion_law(law, H, rise, dwell, ret, dwell2=None, *, W=1.0, N=361, FI=None,
               return_law=None):
    """The follower's motion over a rise-dwell-return-dwell cycle, as the tables ``FI,
    S, V, A`` that the cam routines take -- a sarkp extension (the book integrates an
    acceleration table with DINTGR, program V.5).

    Over the rise (cam angles 0 to ``rise``) the displacement goes from 0 to ``H`` by the
    law ``f``: ``S = H f(x)``, ``x = FI/rise``; it stays at ``H`` over ``dwell``; it comes
    back to 0 over ``ret`` by ``S = H (1 - g(x))`` (``g`` the return law, the same by
    default); it stays at 0 over ``dwell2``.  Every value is the closed form of the law
    (no numerical integration): with the cam's angular velocity ``W``,
    ``V = W dS/dFI``, ``A = W**2 d2S/dFI2``.

    Parameters
    ----------
    law : str
        "harmonic" (f = (1 - cos pi x)/2), "cycloidal" (x - sin(2 pi x)/(2 pi), program
        V.5's law), "3-4-5" (10x^3 - 15x^4 + 6x^5), "modified trapezoid", "modified sine"
        (both with sine quarter-waves over the first and last eighth), "constant
        acceleration" (parabolic: +4, then -4).
    H : float
        Stroke: m for a translating follower, rad for a rocker's swing; > 0.
    rise, dwell, ret : float
        Phase angles of the cam (rad): rise > 0, outer dwell >= 0, return > 0.
    dwell2 : float, optional
        The inner dwell (rad); default: the rest of the turn, ``2 pi - rise - dwell -
        ret`` (which must then be >= 0).  The cycle is ``rise + dwell + ret + dwell2``.
    W : float, keyword
        Angular velocity of the cam (1/s), > 0; default 1 (then V = s', A = s'').
    N : int, keyword
        Number of points over the cycle, both ends included (default 361).
    FI : array_like, keyword
        The cam angles instead (rad, any order, within [0, cycle]); N is then ignored.
    return_law : str, keyword
        The law of the return, if not ``law``.

    Returns
    -------
    MotionLaw(FI, S, V, A, PHASE, CV, CA, CV_RETURN, CA_RETURN)
        Arrays ``FI, S, V, A`` (rad, m or rad, per s, per s^2); ``PHASE`` an int array: 1
        rise, 2 outer dwell, 3 return, 4 inner dwell (a boundary belongs to the phase it
        starts); the floats ``CV, CA``, the rise law's peak velocity and acceleration
        factors (the largest ``|V|`` of the rise is ``CV H W / rise``, the largest
        ``|A|`` ``CA H W**2 / rise**2``), and ``CV_RETURN, CA_RETURN`` the return law's
        (over ``ret``).  The factors are also in :data:`LAW_FACTORS`.

    Raises
    ------
    ValueError
        An unknown law, a non-positive stroke, rise, return or W, negative dwells, or a
        cycle longer than one turn when ``dwell2`` is left to default.
    """
    law = _law(law, "law")
    back = _law(law if return_law is None else return_law, "return_law")
    H, rise, ret, W = (_number("motion_law", a, v, above=0.0) for a, v in
                       (("H", H), ("rise", rise), ("ret", ret), ("W", W)))
    dwell = _number("motion_law", "dwell", dwell, at_least=0.0)
    if dwell2 is None:
        dwell2 = _TWO_PI - rise - dwell - ret
        if dwell2 < -1e-12:
            raise ValueError(f"motion_law: rise + dwell + ret = {rise + dwell + ret!r} is "
                             f"more than a turn; give dwell2 for a longer cycle")
        dwell2 = max(dwell2, 0.0)
    else:
        dwell2 = _number("motion_law", "dwell2", dwell2, at_least=0.0)
    cycle = rise + dwell + ret + dwell2
    if FI is None:
        if not (isinstance(N, (int, np.integer)) and N >= 2):
            raise ValueError(f"motion_law: N = {N!r} must be an integer >= 2")
        fi = np.linspace(0.0, cycle, int(N))
    else:
        from .library import as_real_array
        fi = as_real_array("motion_law", "FI", FI).astype(float)
        if not np.all(np.isfinite(fi)) or np.any(fi < 0.0) or np.any(fi > cycle):
            raise ValueError(f"motion_law: FI must hold finite angles within [0, {cycle!r}]")
    scalar = fi.ndim == 0
    fi = np.atleast_1d(fi)
    s, s1, s2 = np.zeros_like(fi), np.zeros_like(fi), np.zeros_like(fi)
    phase = np.full(fi.shape, 4, dtype=np.int32)
    up = fi < rise
    top = (fi >= rise) & (fi < rise + dwell)
    down = (fi >= rise + dwell) & (fi < rise + dwell + ret)
    phase[up], phase[top], phase[down] = 1, 2, 3
    f, f1, f2 = _rise(law, fi[up] / rise)
    s[up], s1[up], s2[up] = H * f, H * f1 / rise, H * f2 / rise**2
    s[top] = H
    f, f1, f2 = _rise(back, (fi[down] - rise - dwell) / ret)
    s[down], s1[down], s2[down] = H * (1.0 - f), -H * f1 / ret, -H * f2 / ret**2
    v, a = W * s1, W**2 * s2
    if scalar:                                   # a scalar FI gives floats
        fi, s, v, a, phase = float(fi[0]), float(s[0]), float(v[0]), float(a[0]), int(phase[0])
    return MotionLaw(fi, s, v, a, phase, *LAW_FACTORS[law], *LAW_FACTORS[back])


def _rise(name, x):
    x = np.asarray(x, dtype=float)
    return _LAWS[name](x)


# ---- roller followers --------------------------------------------------------------------

RollerProfile = result_type("RollerProfile", ("XA", "YA", "XW", "YW", "ROK", "RW", "ALFA",
                                             "ROKMIN", "UNDERCUT"))


def _working_profile(xa, ya, dx, dy, rok, alfa, rr, on_undercut, name):
    """Offset the pitch curve (XA, YA), tangent (dx, dy), by the roller radius towards the
    cam centre: the envelope of the roller circles centred on the pitch curve."""
    rr = _number(name, "RR", rr, above=0.0)
    if on_undercut not in ("flag", "raise"):
        raise ValueError(f"{name}: on_undercut must be 'flag' or 'raise', not {on_undercut!r}")
    norm = np.hypot(dx, dy)
    turn = np.sign(xa * dy - ya * dx)             # -1: the pitch curve runs clockwise
    nx, ny = turn * dy / norm, -turn * dx / norm  # the outward normal
    convex = rok[rok > 0.0]
    rokmin = float(convex.min()) if convex.size else math.inf
    undercut = bool(rr >= rokmin)
    if undercut and on_undercut == "raise":
        from .errors import RequirementError
        raise RequirementError(
            f"{name}: the roller radius RR = {rr!r} reaches the smallest convex radius of "
            f"curvature of the pitch curve, {rokmin!r}: the working profile is undercut "
            f"(take a smaller roller or a larger cam)")
    return RollerProfile(xa, ya, xa - rr * nx, ya - rr * ny, rok, rok - rr, alfa, rokmin,
                         undercut)


def roller_translating(N, RO, EXCNTR, W, FI, A, V, S, RR, ALD=math.pi / 6.0, *,
                       on_undercut="flag"):
    """Cam profile for a translating roller follower -- a sarkp extension built on DPRFLP.

    The roller's centre moves as DPRFLP's knife edge: DPRFLP's profile is the pitch curve
    ``XA, YA``.  The working profile ``XW, YW`` is the envelope of the roller circles
    of radius ``RR`` centred on it: each pitch point moved by ``RR`` along the normal,
    towards the cam centre.  Its radius of curvature is ``RW = ROK - RR`` (the pitch
    curve's, less the roller; positive where convex).  Where the pitch curve is convex
    with ``ROK <= RR`` the envelope folds back on itself and the cam is undercut: the
    follower would not reproduce the motion.

    Parameters
    ----------
    N, RO, EXCNTR, W, FI, A, V, S, ALD
        As for :func:`DPRFLP` (RO the follower's axial distance at S = 0, for the
        roller's centre).
    RR : float
        Radius of the roller (m), > 0.
    on_undercut : {"flag", "raise"}, keyword
        ``"flag"`` (default) returns ``UNDERCUT = True``; ``"raise"`` raises
        RequirementError.

    Returns
    -------
    RollerProfile(XA, YA, XW, YW, ROK, RW, ALFA, ROKMIN, UNDERCUT)
        The pitch curve ``XA, YA`` (m, the cam's frame), the working profile ``XW, YW``,
        the radii of curvature of both, ``ROK`` and ``RW`` (m), the pressure angle
        ``ALFA`` (rad; the roller's is the knife edge's), ``ROKMIN`` the smallest convex
        radius of curvature of the pitch curve (inf if none) and ``UNDERCUT``
        (``RR >= ROKMIN``).

    Raises
    ------
    RequirementError
        As DPRFLP; and an undercut with ``on_undercut="raise"``.
    ValueError
        RR not > 0, and DPRFLP's bad inputs.
    """
    p = DPRFLP(N, RO, EXCNTR, W, FI, A, V, S, ALD)
    fi = np.asarray(FI, dtype=float)
    s1 = np.asarray(V, dtype=float) / W - EXCNTR
    c = RO + np.asarray(S, dtype=float)
    dx = s1 * np.sin(fi) + c * np.cos(fi)          # d(XA)/dFI, d(YA)/dFI
    dy = s1 * np.cos(fi) - c * np.sin(fi)
    return _working_profile(p.XA, p.YA, dx, dy, p.ROK, p.ALFA, RR, on_undercut,
                            "roller_translating")


def roller_rocker(N, W1, ETAO, FI, RO, L, R, E2, W2, PSI, RR, ALD=math.pi / 4.0, *,
                  on_undercut="flag"):
    """Cam profile for an oscillating (rocker) roller follower -- a sarkp extension built
    on DPRFLK: DPRFLK's profile is the path of the roller's centre (the pitch curve), and
    the working profile is its envelope offset, as in :func:`roller_translating`.

    Parameters
    ----------
    N, W1, ETAO, FI, RO, L, R, E2, W2, PSI, ALD
        As for :func:`DPRFLK` (R the rocker's length to the roller's centre).
    RR : float
        Radius of the roller (m), > 0.
    on_undercut : {"flag", "raise"}, keyword
        As for :func:`roller_translating`.

    Returns
    -------
    RollerProfile(XA, YA, XW, YW, ROK, RW, ALFA, ROKMIN, UNDERCUT)
        As for :func:`roller_translating`; ``ROK`` is DPRFLK's RKRZVN.
    """
    p = DPRFLK(N, W1, ETAO, FI, RO, L, R, E2, W2, PSI, ALD)
    fi = np.asarray(FI, dtype=float)
    psi = np.asarray(PSI, dtype=float) + ETAO
    q = R * (1.0 + np.asarray(W2, dtype=float) / W1)
    dx = -L * np.sin(fi) + q * np.sin(fi + psi)
    dy = -L * np.cos(fi) + q * np.cos(fi + psi)
    return _working_profile(p.XA, p.YA, dx, dy, p.RKRZVN, p.ALFA, RR, on_undercut,
                            "roller_rocker")


# ---- exact sizing ---------------------------------------------------------------------------

BaseRadius = result_type("BaseRadius", ("RO", "EXCST", "RO_AXIAL", "RO_RISE", "RO_RETURN",
                                       "RO_BOOK", "ALFMAX_BOOK"))
FlatRadius = result_type("FlatRadius", ("RKSH", "RKSH_BOOK", "ROKMIN_BOOK"))
CentreDistance = result_type("CentreDistance", ("L", "ETAO", "RO", "L_RISE", "L_RETURN",
                                               "ETAO_BOOK", "RO_BOOK", "ALFMAX_BOOK"))


def _tables(name, N, **tables):
    from .library import as_real_array
    out = []
    for arg, value in tables.items():
        a = as_real_array(name, arg, value)
        if a.shape != (N,):
            raise ValueError(f"{name}: {arg} has shape {a.shape}, but N = {N}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{name}: {arg} holds a value that is not a finite number")
        out.append(a)
    return out


def _limits(name, V, ALD, ALD_return):
    """tan of the allowed pressure angle at each point: the rise's where V > 0, the
    return's where V < 0, the smaller where V = 0 (a dwell)."""
    ret = ALD if ALD_return is None else ALD_return
    t1 = math.tan(_number(name, "ALD", ALD, above=0.0, below=_HALF_PI))
    t2 = math.tan(_number(name, "ALD_return", ret, above=0.0, below=_HALF_PI))
    return np.where(V > 0.0, t1, np.where(V < 0.0, t2, min(t1, t2)))


def base_radius(N, FI, A, V, S, W, ALD, ALD_return=None, BETA=0.0):
    """The smallest cam for a translating follower whose pressure angle stays within the
    allowed one over the whole cycle -- a sarkp extension, beside DKLCHK's rule.

    With DKLCHK's geometry (base radius ``RO``, offset ``e = RO sin(BETA)``, axial
    distance ``RO cos(BETA)``), the pressure angle ``tan(alpha) = (s' - e)/(RO cos(BETA)
    + s)`` is within ``+-ALD`` at a point when ``RO`` is at least a bound linear in the
    point's ``s'`` and ``s``: the answer is the largest bound over all points, exactly
    (DKLCHK looks only at the point of largest velocity).  Points with V > 0 (the rise)
    are held to ``ALD``, those with V < 0 (the return) to ``ALD_return``; points at rest
    to the smaller.

    Parameters
    ----------
    N, FI, A, V, S, W
        The motion, as for :func:`DPRFLP` (A is used for DKLCHK's call only).
    ALD : float
        The allowed pressure angle of the rise (rad), 0 < ALD < pi/2.
    ALD_return : float, optional
        That of the return (default ALD).
    BETA : float, optional
        DKLCHK's angle of the offset (rad), default 0 (a central follower).

    Returns
    -------
    BaseRadius(RO, EXCST, RO_AXIAL, RO_RISE, RO_RETURN, RO_BOOK, ALFMAX_BOOK)
        ``RO`` the smallest base radius (m), ``EXCST = RO sin(BETA)`` the offset and
        ``RO_AXIAL = RO cos(BETA)`` the axial distance (DPRFLP's RO and EXCNTR: with them
        the largest pressure angle equals the limit at one point); ``RO_RISE`` and
        ``RO_RETURN`` the radius each phase alone needs; ``RO_BOOK`` DKLCHK's RO for the
        same motion, ALD and BETA, and ``ALFMAX_BOOK`` the largest pressure angle (rad)
        of the cam with that radius (DKLCHK's geometry).

    Raises
    ------
    RequirementError
        No radius keeps the pressure angle within the limits (an offset BETA beyond the
        return's limit makes the bounds contradict).
    ValueError
        N not the length of the tables, a NaN or inf, W <= 0, a limit outside (0, pi/2).
    """
    from .errors import RequirementError
    fi, a, v, s = _tables("base_radius", N, FI=FI, A=A, V=V, S=S)
    W = _number("base_radius", "W", W, above=0.0)
    BETA = _number("base_radius", "BETA", BETA, above=-_HALF_PI, below=_HALF_PI)
    t = _limits("base_radius", v, ALD, ALD_return)
    s1 = v / W
    cb, sb = math.cos(BETA), math.sin(BETA)
    # (s' - RO sb) <= t (RO cb + s)  and  -(s' - RO sb) <= t (RO cb + s): d RO >= r
    d = np.concatenate([t * cb + sb, t * cb - sb])
    r = np.concatenate([s1 - t * s, -s1 - t * s])
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = r / d
    lower = np.where(d > 0, bound, -np.inf)
    upper = np.where(d < 0, bound, np.inf)
    impossible = (d == 0) & (r > 0)
    ro = max(float(lower.max()), float(np.max(-s)) / cb)   # and RO cb + s > 0 everywhere
    if impossible.any() or ro >= upper.min() or not ro > 0:
        raise RequirementError("base_radius: no base radius keeps the pressure angle within "
                               "the limits over the whole cycle (the offset BETA is too "
                               "large for the return's limit)")
    rise = lower[np.concatenate([v > 0, v > 0])]
    ret = lower[np.concatenate([v < 0, v < 0])]
    book = DKLCHK(N, s, v, a, ALD, BETA, W)
    alfa = np.arctan((s1 - book.RO * sb) / (book.RO * cb + s))
    return BaseRadius(ro, ro * sb, ro * cb, float(rise.max()) if rise.size else 0.0,
                      float(ret.max()) if ret.size else 0.0, book.RO,
                      float(np.abs(alfa).max()))


def flat_base_radius(N, FI, A, V, S, W, ROKMIN=0.0, GAMMA=math.pi / 4.0):
    """The smallest cam for a translating flat-faced follower whose profile is convex over
    the whole cycle -- a sarkp extension, beside DPRFPL's rule.

    A flat face needs the radius of curvature ``RKSH + S + s''`` to be >= 0 (>= ROKMIN)
    at every point: the smallest ``RKSH`` is ``max(ROKMIN - S - s'')`` over all points
    (DPRFPL looks only at the point of the smallest acceleration).

    Parameters
    ----------
    N, FI, A, V, S, W
        The motion, as for :func:`DPRFPL`.
    ROKMIN : float, optional
        The smallest radius of curvature allowed (m), default 0 (convex).
    GAMMA : float, optional
        DPRFPL's design angle for the book's value beside (default pi/4, the convexity
        rule).

    Returns
    -------
    FlatRadius(RKSH, RKSH_BOOK, ROKMIN_BOOK)
        ``RKSH`` the smallest radius of the cam (m); DPRFPL's ``RKSH`` for GAMMA and its
        smallest radius of curvature ``ROKMIN`` (negative: the book's cam is concave
        somewhere and a flat face cannot follow it).

    Raises
    ------
    ValueError
        N not the length of the tables, a NaN or inf, W <= 0, ROKMIN < 0.
    """
    fi, a, v, s = _tables("flat_base_radius", N, FI=FI, A=A, V=V, S=S)
    W = _number("flat_base_radius", "W", W, above=0.0)
    ROKMIN = _number("flat_base_radius", "ROKMIN", ROKMIN, at_least=0.0)
    GAMMA = _number("flat_base_radius", "GAMMA", GAMMA, above=0.0, below=_HALF_PI)
    rksh = max(float(np.max(ROKMIN - s - a / W**2)), float(np.max(-s)))
    book = DPRFPL(N, GAMMA, W, fi, a, v, s)
    return FlatRadius(rksh, book.RKSH, book.ROKMIN)


def rocker_centre_distance(N, FI, E2, W2, PSI, W1, R, ALD, ALD_return=None):
    """The smallest centre distance of a cam with a rocker follower whose pressure angle
    stays within the allowed one over the whole cycle -- a sarkp extension, beside
    DKLCHK's rule for INDEX = 2.

    The rocker of length ``R`` swings by ``PSI`` about O2; the cam centre O1 is free.  In
    DPRFLK's terms, ``tan(alpha) = (R (1 + psi') - L cos(psi))/(L sin(psi))``, ``psi =
    PSI + ETAO``: both the numerator and the denominator are linear in the position of
    O1 (``L cos(ETAO), -L sin(ETAO)`` from O2), so each point's ``|alpha| <= limit`` is a
    pair of half-planes, and the allowed cam centres are their intersection, a convex
    polygon.  The answer is its point nearest to O2 (computed exactly, as the nearest
    point of the polygon's edges): ``L`` and ``ETAO``.  Points with W2 > 0 are held to
    ``ALD``, W2 < 0 to ``ALD_return``, points at rest to the smaller.

    Parameters
    ----------
    N, FI, E2, W2, PSI, W1
        The rocker's motion, as for :func:`DPRFLK` (E2 is used for DKLCHK's call only).
    R : float
        The rocker's length (m), > 0.
    ALD, ALD_return : float
        The allowed pressure angles (rad) of the rise and (default ALD) of the return.

    Returns
    -------
    CentreDistance(L, ETAO, RO, L_RISE, L_RETURN, ETAO_BOOK, RO_BOOK, ALFMAX_BOOK)
        ``L`` the smallest centre distance (m) and ``ETAO`` the rocker's initial angle
        (rad) for DPRFLK; ``RO`` the cam's base radius there (the smallest distance of
        the pitch curve from O1); ``L_RISE`` and ``L_RETURN`` the smallest centre
        distance the rise alone (W2 > 0) and the return alone (W2 < 0) would need (each
        with its own best ETAO; L is at least the larger); then DKLCHK's ``ETAO`` and
        ``RO`` for INDEX = 2 with ``RSCNTR = L``, ``RZMR = R`` and the largest
        ``|alpha|`` (rad) DPRFLK gives with the book's ETAO.

    Raises
    ------
    RequirementError
        No cam centre keeps the pressure angle within the limits.
    ValueError
        N not the length of the tables, a NaN or inf, W1 or R not > 0.
    """
    from .errors import RequirementError
    fi, e2, w2, psi = _tables("rocker_centre_distance", N, FI=FI, E2=E2, W2=W2, PSI=PSI)
    W1 = _number("rocker_centre_distance", "W1", W1, above=0.0)
    R = _number("rocker_centre_distance", "R", R, above=0.0)
    t = _limits("rocker_centre_distance", w2, ALD, ALD_return)
    q = R * (1.0 + w2 / W1)
    c, s = np.cos(psi), np.sin(psi)
    # O1 = (x, y): L cos(psi) = x c + y s, L sin(psi) = x s - y c.  alpha <= limit:
    # x (c + t s) + y (s - t c) >= q;  alpha >= -limit:  -x (c - t s) - y (s + t c) >= -q
    ax = np.concatenate([c + t * s, -(c - t * s)])
    ay = np.concatenate([s - t * c, -(s + t * c)])
    b = np.concatenate([q, -q])
    size = 1e3 * (R + np.abs(q).max())
    x, y = _nearest_in_polygon(ax, ay, b, size)
    phase = []
    for where in (w2 > 0, w2 < 0):
        two = np.concatenate([where, where])
        px, py = _nearest_in_polygon(ax[two], ay[two], b[two], size) if where.any() \
            else (0.0, 0.0)
        phase.append(math.nan if px is None else math.hypot(px, py))
    if x is None:
        raise RequirementError("rocker_centre_distance: no cam centre keeps the pressure "
                               "angle within the limits over the whole cycle")
    L = math.hypot(x, y)
    etao = math.atan2(-y, x)
    ro = float(np.sqrt(np.maximum(L**2 + R**2 - 2 * L * R * np.cos(psi + etao), 0.0)).min())
    book = DKLCHK(N, psi, w2, e2, ALD, 0.0, W1, L, R, 2)
    p = psi + book.ETAO
    with np.errstate(divide="ignore", invalid="ignore"):
        alfa = np.arctan(q / L / np.sin(p) - 1.0 / np.tan(p))
    return CentreDistance(L, etao, ro, *phase, book.ETAO, book.RO,
                          float(np.nanmax(np.abs(alfa))))


def _nearest_in_polygon(ax, ay, b, size):
    """The point of {ax x + ay y >= b} nearest to the origin, or (None, None) if empty:
    the box |x|, |y| <= size clipped by each half-plane, then the nearest point of each
    edge of the polygon left."""
    px = np.array([-size, size, size, -size])
    py = np.array([-size, -size, size, size])
    for a1, a2, c in zip(ax, ay, b):
        g = a1 * px + a2 * py - c                  # >= 0 inside
        inside = g >= 0
        if inside.all():
            continue
        if not inside.any():
            return None, None
        g2 = np.roll(g, -1)
        qx, qy = np.roll(px, -1), np.roll(py, -1)
        keep_x, keep_y = [], []
        for i in range(len(px)):
            if inside[i]:
                keep_x.append(px[i])
                keep_y.append(py[i])
            if (g[i] >= 0) != (g2[i] >= 0):       # the edge crosses the line
                u = g[i] / (g[i] - g2[i])
                keep_x.append(px[i] + u * (qx[i] - px[i]))
                keep_y.append(py[i] + u * (qy[i] - py[i]))
        px, py = np.array(keep_x), np.array(keep_y)
    if px.size == 0:
        return None, None
    if all(a1 * 0.0 + a2 * 0.0 >= c for a1, a2, c in zip(ax, ay, b)):
        return 0.0, 0.0
    qx, qy = np.roll(px, -1), np.roll(py, -1)
    ex, ey = qx - px, qy - py
    e2 = ex**2 + ey**2
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.clip(np.where(e2 > 0, -(px * ex + py * ey) / e2, 0.0), 0.0, 1.0)
    nx, ny = px + u * ex, py + u * ey
    k = int(np.argmin(nx**2 + ny**2))
    x, y = float(nx[k]), float(ny[k])
    # polish: the nearest point of one active line, or the meeting point of two, whichever
    # is nearest among those that keep every constraint (to rounding)
    norm = np.hypot(ax, ay)
    slack = (ax * x + ay * y - b) / norm
    tol = 1e-9 * (math.hypot(x, y) + np.abs(b / norm))
    active = np.flatnonzero(np.abs(slack) <= tol)[:8]
    candidates = [(x, y)]
    for j in active:
        candidates.append((ax[j] * b[j] / norm[j]**2, ay[j] * b[j] / norm[j]**2))
        for i in active:
            det = ax[i] * ay[j] - ax[j] * ay[i]
            if i < j and det != 0:
                candidates.append(((b[i] * ay[j] - b[j] * ay[i]) / det,
                                   (ax[i] * b[j] - ax[j] * b[i]) / det))
    feasible = [(cx, cy) for cx, cy in candidates
                if np.all((ax * cx + ay * cy - b) / norm >= -1e-14 * (math.hypot(cx, cy)
                                                                      + np.abs(b / norm)))]
    if feasible:
        x, y = min(feasible, key=lambda p: p[0]**2 + p[1]**2)
    return float(x), float(y)
