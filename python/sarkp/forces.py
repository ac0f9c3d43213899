"""Chapter 7: force analysis of the class-II Assur groups (listings VII.1-VII.9 and the
DNMA5 listing, book lines L4986-5513).

Two families, one routine per group kind (kinds as in chapter 4: 1 RRR, 2 RRP, 3 RPR,
4 PRP, 5 RPP; links 2 and 3 form the group, links 1 and 4 are the chain links it is
attached to):

* the projection method ``DNMAF1``-``DNMAF5`` (the book's own, Tables 27-31): the group's
  joints and reduction points are given by coordinates; the outputs are the forces the
  group's links exert ON the chain (``F21`` = force of link 2 on link 1, ``F34`` = of 3 on
  4; the internal ``F23`` = of 2 on 3, in ``DNMAF5`` ``F32`` = of 3 on 2);
* the vector method ``DNMA1``-``DNMA5`` (of textbook [1], L5270): lengths and directions
  are given; the outputs are the reactions ON the group's links (``RA`` on 2 from 1,
  ``RC`` on 3 from 4; ``RB`` on 2 from 3, except ``DNMA5``, whose ``RB`` acts on 3).

The book states the two conventions at L4986 and L6423.  ``DUGL6``, which DNMA1-DNMA3 call
and the book never prints, is sarkp's extension (the direction of a vector sum).

Common conventions: angles in radians from +x, counter-clockwise positive; a force is a
pair (modulus >= 0, direction); moments counter-clockwise positive (N*m with forces in N
and lengths in m).  The loads of each link -- external forces, weights and the d'Alembert
inertia loads -m a_S and -J_S epsilon (L4863-4869) -- are reduced by the caller to one
force (``F2, G2`` or ``Q2, G2``) at a reduction point S2 and one moment (``T2`` or ``M2``),
with DSMVKT and DMOMNT (L4870-4890).  No friction: the reaction of a prismatic pair is
normal to its guide.  An arm ``H`` is signed: ``H*F`` is the moment, about the point the
routine names, of the force the routine names; it is 0 when the force is 0 (the pair then
carries a pure couple, which no arm expresses).

One computation serves every routine and :class:`sarkp.Mechanism`: in corrected mode each
routine lays its group out for the force step of fortran/groups.f90 (the six equilibrium
equations of the group's two links in its three pairs' reactions, one kernel for every
kind, parameterised by the kind's pair types) and gives the reactions back in the book's
form; as-printed mode runs the printed code.

The printed code balances only under the reduction-point conventions stated in each
docstring (ERRATA E-DNMA1-3, E-DNMA2-3, E-DNMA3-4, E-DNMA4-2, E-DNMA5-3); each is pinned by a
test (tests/test_forces.py) that also shows the other reading fails.
"""

from __future__ import annotations

import numpy as np

from . import _wrap_forces as _w
from .library import ST_SIGNIFICANCE, ST_SINGULAR, as_real_array, describe

__all__ = ["DNMAF1", "DNMAF2", "DNMAF3", "DNMAF4", "DNMAF5",
           "DNMA1", "DNMA2", "DNMA3", "DNMA4", "DNMA5", "DUGL6", "balancing_moment"]

_RAISES = """
    Raises
    ------
    SingularError
        At a singular position ({what}): the equations of statics have no finite
        answer.

    Warns
    -----
    SignificanceWarning
        Near that position: the denominator (the sine of the angle between the two
        directions, or GELG's pivot) is below the book's 1e-4, or only a few digits of the
        result are left (the warning says how many); the result is kept.
"""

_NEAR = ("near a singular position: the sine of the angle between the two directions that "
         "the equations divide by is below 1e-4, the book's GELG tolerance; the result was "
         "kept")

_MODES = """    Corrected mode solves the group with the force step that :class:`sarkp.Mechanism`
    uses for every group kind (one kernel, fortran/groups.f90) and returns its reactions
    in this routine's form; as-printed mode runs the printed code with PI = 3.14159.  The
    two differ by PI's error (about 1e-6 relative): no printed figure depends on the
    errors corrected in this routine."""

#: the sense of the projection family's forces, said once for DNMAF1-DNMAF5
_SENSE = """    Sense: the projection family (DNMAF1-DNMAF5) returns the forces the group exerts ON
    the chain (F21 on link 1 from link 2), the opposite of the vector family's reactions
    on the group (DNMA*'s RA = -F21).
"""

#: the sense of the vector family's reactions, said once for DNMA1-DNMA5
_SENSE_VECTOR = """    Sense: the vector family (DNMA1-DNMA5) returns the reactions ON the group's links
    (RA on link 2 from link 1), the opposite of the projection family's forces of the
    group on the chain (DNMAF*'s F21 = -RA).
"""


DNMAF1 = describe(
    _w.DNMAF1, listing="VII.2", lines="L5055-5087",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "A, B and C are collinear (the dyad is stretched or folded) or two of "
                 "them coincide: the reactions have no finite value"},
    doc=f"""Reactions in a group of the first kind (RRR), projection method.

{_SENSE}
    Listing VII.2 (L5059-5087), Table 28, Fig. 53.  F12 is split into its component normal
    to AB (link 2's moments about B) and along AB (the group's moments about C); then
    F23 = F12 + F2 and F34 = F23 + F3.

    Returns
    -------
    DNMAF1(F21, G21, F23, G23, F34, G34)
        ``F21, G21``: force of link 2 on link 1 at A (N, rad); ``F23, G23``: force of 2 on 3
        at B; ``F34, G34``: force of 3 on 4 at C.  Directions in the DSMVKT range
        (-pi/2, 3*pi/2), G21 that minus PI.
{_RAISES.format(what="A, B, C collinear, or A = B, or A = C")}
    Notes
    -----
    S2 and S3 may lie anywhere.  Every link balances to rounding
    (tests/test_forces.py::test_dnmaf1_every_link_balances).
{_MODES}
    """)

DNMAF2 = describe(
    _w.DNMAF2, listing="VII.1", lines="L4988-5020",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "AB is perpendicular to the guide, or A = B: the reactions have no "
                 "finite value"},
    doc=f"""Reactions in a group of the second kind (RRP), projection method.

{_SENSE}
    Listing VII.1 (L4992-5020), Table 27, Fig. 52, eqs. (7.3)-(7.10).  The group is
    projected on the guide m (the guide's reaction has no component along it), link 2's
    moments about B give F12's component normal to m.

    Returns
    -------
    DNMAF2(F21, G21, F23, G23, F34, G34, H34)
        ``F21, G21``: force of 2 on 1 at A; ``F23, G23``: force of 2 on 3 at B;
        ``F34, G34``: force of 3 on the guide 4, normal to FIM; ``H34`` (m):
        ``H34*F34`` is the moment about B of the guide's reaction on link 3 (-F34 as a
        vector), i.e. that reaction acts on the line through B + s e(FIM) with
        ``s*(component of -F34 along FIM + pi/2) = H34*F34``.  0 when F34 = 0.
{_RAISES.format(what="AB perpendicular to the guide, or A = B")}
    Notes
    -----
    The text's (7.10) and h34 formula (L4959, L4963) lose a minus sign that the listing and
    Table 27 have; the listing is followed.
{_MODES}
    """)

DNMAF3 = describe(
    _w.DNMAF3, listing="VII.4", lines="L5179-5210",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "CA is perpendicular to the guide of link 3, or A = C: the reactions have "
                 "no finite value"},
    doc=f"""Reactions in a group of the third kind (RPR), projection method.

{_SENSE}
    Listing VII.4 (L5181-5210), Table 30, Fig. 55.  Link 2 (a slider pivoted at A)
    slides along link 3, which is pivoted at C.  Link 2 projected on the guide gives F12's
    component along it, the group's moments about C the normal one.

    Returns
    -------
    DNMAF3(F21, G21, F23, G23, H23, F34, G34)
        ``F21, G21``: force of 2 on 1 at A; ``F23, G23``: force of 2 on 3, normal to the
        guide; ``H23`` (m): ``H23*F23`` is the moment about C of F23 (0 when F23 = 0);
        ``F34, G34``: force of 3 on 4 at C.
{_RAISES.format(what="CA perpendicular to the guide, or A = C")}
    Notes
    -----
{_MODES}
    """)

DNMAF4 = describe(
    _w.DNMAF4, listing="VII.3", lines="L5116-5149",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "the guides FIM and FIN are parallel: the reactions have no finite "
                 "value"},
    doc=f"""Reactions in a group of the fourth kind (PRP), projection method.

{_SENSE}
    Listing VII.3 (L5118-5149), Table 29, Fig. 54.  The group projected on the guide n
    gives F12 (normal to m); then F23 = F12 + F2 and F34 = F23 + F3.

    Returns
    -------
    DNMAF4(F21, G21, H21, F23, G23, F34, G34, H34)
        ``F21, G21``: force of 2 on 1, normal to FIM; ``H21`` (m): ``H21*F21`` is the
        moment about B of F12 (the reaction on link 2); ``F23, G23``: force of 2 on 3 at
        B; ``F34, G34``: force of 3 on 4, normal to FIN; ``H34``: ``H34*F34`` is the
        moment about B of F43 (the reaction on link 3).  Arms are 0 for a zero force.
{_RAISES.format(what="parallel guides")}
    Notes
    -----
    Corrected in both modes (ERRATA): the division sign lost by the OCR before
    ``COS(FIM + PID2 - FIN)`` (E-DNMAF4-1), and the first DSMVKT's ``G21`` for ``G12``
    (E-DNMAF4-2; Table 29 step 6 has gamma_12): with G21, F23, F34 and H34 are wrong and
    link 2 does not balance.  The comment's "arms about C" are about B (E-DNMAF4-3).
{_MODES}
    """)

DNMAF5 = describe(
    _w.DNMAF5, listing="VII.5", lines="L5233-5268",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "the inner guide is parallel to the outer one (TT3 = 0 or pi): the "
                 "reactions have no finite value"},
    doc=f"""Reactions in a group of the fifth kind (RPP), projection method.

{_SENSE}
    Listing VII.5 (L5235-5268), Table 31, Fig. 56.  Link 3 projected on the inner guide
    gives F43; then F32 = F43 + F3 and F21 = F32 + F2.

    Returns
    -------
    DNMAF5(F21, G21, F32, G32, H32, F34, G34, H34)
        ``F21, G21``: force of 2 on 1 at A; ``F32, G32``: force of link 3 ON link 2,
        normal to FIM + TT3 (the printed comment calls them F23, G23: E-DNMAF5-1);
        ``H32`` (m): ``H32*F32`` is the moment about A of F32; ``F34, G34``: force of 3 on
        4, normal to FIM; ``H34``: ``H34*F34`` is the moment about A of F43 (the guide's
        reaction on link 3).  Arms are 0 for a zero force.
{_RAISES.format(what="TT3 = 0 or pi (the guides parallel)")}
    Notes
    -----
{_MODES}
    """)

DNMA1 = describe(
    _w.DNMA1, listing="VII.6", lines="L5272-5318",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "links 2 and 3 are aligned (FI2 parallel to FI3): the reactions have no "
                 "finite value"},
    doc=f"""Reactions in a group of the first kind (RRR), vector method.

{_SENSE_VECTOR}
    Listing VII.6 (L5274-5318).  Each link's moments about B give the reaction's
    component normal to it, the group's force balance (a 2x2 GELG system) the components
    along the links.

    Returns
    -------
    DNMA1(RA, GA, RB, GB, RC, GC)
        ``RA, GA``: reaction on link 2 from link 1 at A; ``RB, GB``: force on link 2 from
        link 3 at B; ``RC, GC``: reaction on link 3 from link 4 at C (N, rad).
{_RAISES.format(what="links 2 and 3 aligned")}
    Notes
    -----
    The printed moment ``Q2*COS(G2)*BS2*SIN(PI + FI2) - ...`` is r x F with r = BS2 e(FI2)
    (written as F x r at PI + FI2), hence the convention above; with S2 = B - BS2 e(FI2)
    the links do not balance (tests/test_forces.py).  GA, GC come from DUGL6, which the
    book never prints (ERRATA E-DUGL6-1; sarkp's :func:`DUGL6`).  The OCR's ``F12``,
    ``F13``, ``RI2`` are FI2, FI3 (E-DNMA1-1).
{_MODES}
    """)

DNMA2 = describe(
    _w.DNMA2, listing="VII.7", lines="L5320-5368",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "AB is perpendicular to the guide: the reactions have no finite value"},
    doc=f"""Reactions in a group of the second kind (RRP), vector method.

{_SENSE_VECTOR}
    Listing VII.7 (L5322-5368).

    Returns
    -------
    DNMA2(RA, GA, RB, GB, RC, HC, GC)
        ``RA, GA``: reaction on 2 from 1 at A; ``RB, GB``: force on 2 from 3 at B;
        ``RC, GC``: reaction on 3 from the guide, normal to FIO; ``HC`` (m): ``HC*RC`` is
        the moment about B of RC (0 when RC = 0: ERRATA E-DNMA-1).
{_RAISES.format(what="AB perpendicular to the guide")}
    Notes
    -----
    The OCR's ``CA``, ``CAN`` are GA, GAN (E-DNMA2-2).
{_MODES}
    """)

DNMA3 = describe(
    _w.DNMA3, listing="VII.8", lines="L5372-5413",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "AC is perpendicular to the guide of link 3: the reactions have no finite "
                 "value"},
    doc=f"""Reactions in a group of the third kind (RPR), vector method.

{_SENSE_VECTOR}
    Listing VII.8 (L5376-5413; no comment block is printed).  The group's moments about C
    give RA's component normal to AC, link 2's force balance (a 2x2 GELG system) its
    component along AC and RB.

    Returns
    -------
    DNMA3(RA, GA, RB, HB, GB, RC, GC)
        ``RA, GA``: reaction on 2 from 1 at A; ``RB, GB``: force on 2 from 3, normal to
        the guide; ``HB`` (m): ``HB*RB`` is the moment about C of the force on 3 from 2
        (-RB as a vector; 0 when RB = 0: E-DNMA-1); ``RC, GC``: reaction on 3 from 4 at C.
{_RAISES.format(what="AC perpendicular to the guide")}
    Notes
    -----
    Corrected in both modes: ``Q2, G2`` are used by the body but missing from the printed
    header; they are inserted after M2, as in DNMA1, DNMA2, DNMA4, DNMA5 (E-DNMA3-1); the
    first ``X(1, 2) = COS(FIAC)`` is X(1, 1) (E-DNMA3-2); ``GR`` is GB (E-DNMA3-3).
{_MODES}
    """)

DNMA4 = describe(
    _w.DNMA4, listing="VII.9", lines="L5415-5460",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "the guides FIM and FIN are parallel: the reactions have no finite "
                 "value"},
    doc=f"""Reactions in a group of the fourth kind (PRP), vector method.

{_SENSE_VECTOR}
    The listing has no heading (L5415-5460); Table 33 numbers it VII.9.

    Returns
    -------
    DNMA4(RA, HA, GA, RB, GB, RC, HC, GC)
        ``RA, GA``: reaction on 2 from 1, normal to FIM; ``HA``: ``HA*RA`` is its moment
        about B; ``RB, GB``: force on 2 from 3 at B; ``RC, GC``: reaction on 3 from 4,
        normal to FIN; ``HC``: ``HC*RC`` is its moment about B.  Arms are 0 for a zero
        force (E-DNMA-1).
{_RAISES.format(what="parallel guides")}
    Notes
    -----
    Corrected in both modes: the second term of HC's moment has ``FIM`` for ``FIN``
    (E-DNMA4-1); with it link 3 does not balance.
{_MODES}
    """)

DNMA5 = describe(
    _w.DNMA5, listing="VII.10", lines="L5464-5513",
    messages={ST_SIGNIFICANCE: _NEAR, ST_SINGULAR: "the inner guide is parallel to the outer one (ETA3 = 0 or pi): the "
                 "reactions have no finite value"},
    doc=f"""Reactions in a group of the fifth kind (RPP), vector method.

{_SENSE_VECTOR}
    Printed under the heading "VII.9" (L5464); Table 33 numbers it VII.10 (ERRATA
    E-DNMA5-1).

    Returns
    -------
    DNMA5(RA, GA, RB, HB, GB, RC, HC, GC)
        ``RA, GA``: reaction on 2 from 1 at A; ``RB, GB``: force on link 3 FROM link 2,
        normal to FIM + ETA3 (unlike DNMA1-DNMA4: E-DNMA5-2); ``HB``: ``HB*RB`` is the
        moment about A of the force on 2 from 3 (-RB); ``RC, GC``: reaction on 3 from 4,
        normal to FIM; ``HC``: ``HC*RC`` is its moment about A.  Arms are 0 for a zero
        force (E-DNMA-1).
{_RAISES.format(what="ETA3 = 0 or pi (the guides parallel)")}
    Notes
    -----
    The printed GELG tolerance ``8.00001`` is the OCR of 0.0001 (E-DNMA5-4).
{_MODES}
    """)

DUGL6 = describe(
    _w.DUGL6, listing="(not printed)", lines="L5311, L5312, L5359, L5401",
    doc="""Direction of the sum of two vectors (sarkp's extension: DUGL6 is not printed).

    DNMA1 (L5311-5312), DNMA2 (L5359) and DNMA3 (L5401) call ``DUGL6(RAN, GAN, RAT, GAT,
    FI2)`` right after ``RA = SQRT(RAN**2 + RAT**2)``; the book prints no DUGL6 and Table 33
    does not list it (ERRATA E-DUGL6-1).  The only meaning under which DNMA1-DNMA3 balance
    is the direction of the reaction whose components are RN at GN and RT at GT, i.e. of
    the vector sum -- what DSMVKT gives the DNMAF routines for the same sum.  The proof is
    statics: with it every link of DNMA1-DNMA3 balances to rounding
    (tests/test_forces.py).

    Returns
    -------
    DUGL6(DUGL6)
        ``DUGL5(RN cos GN + RT cos GT, RN sin GN + RT sin GT)``, in (-pi/2, 3*pi/2).
    """)


# ---- sarkp extension: the balancing moment at the crank ---------------------------------

def balancing_moment(group, XO, YO, XA, YA, M1=0.0):
    """The balancing moment on the crank from the force analysis of the group attached to
    it -- a sarkp extension (chapter 10 computes it by hand with DMOMNT, L7570).

    The crank turns about O and carries the group's link 2 at the revolute A.  The
    group's analysis gives the force between them: DNMAF1, DNMAF2, DNMAF3, DNMAF5 the force
    of link 2 on the crank (``F21, G21``), DNMA1, DNMA2, DNMA3, DNMA5 the reaction on
    link 2 (``RA, GA``), whose opposite acts on the crank.  The balancing moment ``My``
    is the moment the drive applies to the crank so that it is in (d'Alembert)
    equilibrium: ``My + (A - O) x F_on_crank + M1 = 0``.  By virtual work it is minus the
    power of all the loads of the mechanism over the crank's angular velocity.

    Parameters
    ----------
    group : result of DNMAF1-3, DNMAF5 or DNMA1-3, DNMA5
        The analysis of the group at the crank (arrays broadcast with the coordinates).
    XO, YO : float or array_like
        The crank's pivot O (m).
    XA, YA : float or array_like
        The joint A between the crank and the group (m).
    M1 : float or array_like, optional
        The moment about O of the crank's own loads (its weight, inertia, ...), N*m.

    Returns
    -------
    float or ndarray
        ``My`` (N*m, counter-clockwise positive).

    Raises
    ------
    ValueError
        A kind-4 group (DNMAF4, DNMA4: link 2 meets the crank in a prismatic pair, with an
        arm rather than a point of application), or a result of another routine.
    """
    fields = getattr(group, "_fields", ())
    if "H21" in fields or "HA" in fields:
        raise ValueError("balancing_moment: a kind-4 group (PRP) meets the crank in a "
                         "prismatic pair; its force has an arm, not the point A")
    if "F21" in fields and "G21" in fields:
        f, g = np.asarray(group.F21, dtype=float), np.asarray(group.G21, dtype=float)
    elif "RA" in fields and "GA" in fields:
        f, g = -np.asarray(group.RA, dtype=float), np.asarray(group.GA, dtype=float)
    else:
        raise ValueError(f"balancing_moment: group must be the result of DNMAF1-3, DNMAF5 or "
                         f"DNMA1-3, DNMA5, not {type(group).__name__}")
    xo, yo, xa, ya, m1 = (as_real_array("balancing_moment", a, v) for a, v in
                          (("XO", XO), ("YO", YO), ("XA", XA), ("YA", YA), ("M1", M1)))
    rx, ry = xa - xo, ya - yo
    my = -(rx * f * np.sin(g) - ry * f * np.cos(g)) - m1
    return float(my) if np.ndim(my) == 0 else my
