"""sarkp.Mechanism: a planar linkage described once, solved in one compiled call.

The book's own method (chapter 4 for the kinematics, chapter 7 for the forces; the
student's main program of chapter 10 carries it out call by call) made into an object: a
driven crank, then class II Assur groups of kinds 1-5 attached by named joints, points
rigidly on links, masses, loads and springs.  :meth:`Mechanism.solve` runs the whole chain
over all positions in one Fortran call (fortran/mechanism.f90), computing only what
``need`` asks for.

Conventions: lengths in metres, angles in radians counter-clockwise from +x, SI units.
Branches are geometric and mean the same for every kind: +1 puts the group's new joint on
the left of the directed line between its outer joints (kinds 1, 3), or ahead, along the
guide's direction, of the foot of the perpendicular (kind 2); kinds 4 and 5 have a single
position.  A link is named by two joints on it (``("A", "B")``); a slider block, which
carries one joint, by that joint (``"E"``).

Loads on a joint go to the joint's *owner*: the link of the group that made it (the crank
for its pin; for kind 1 the link from the group's first outer joint, A-B; for kind 2 the
slider block; for kinds 3 and 4 the slider through the first input, kind 5's slotted
link), a rigid point's link.  A group attached at a joint bears on that joint's owner.
"""

from __future__ import annotations

import math
import numbers
import warnings

import numpy as np

from . import _sarkp
from .errors import AssemblyError, RangeError, SignificanceWarning, SingularError, Status
from .results import Result, result_type

__all__ = ["Mechanism", "MechanismResult"]

NEEDS = {"positions": 1, "velocities": 2, "accelerations": 3, "forces": 4}
KIND_NAMES = {0: "crank", 1: "rrr", 2: "rrp", 3: "rpr", 4: "prp", 5: "rpp", 6: "point"}
_ST_DIGITS = int(_sarkp.prmtr.st_digits)
_FRAME = 0
_CRANK = 1


def _real(who, name, value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{who}: {name} must be a real number, not {type(value).__name__}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"{who}: {name} must be finite, not {value}")
    return value


def _length(who, name, value):
    value = _real(who, name, value)
    if value <= 0.0:
        raise ValueError(f"{who}: {name} must be a length > 0, not {value}")
    return value


def _branch(who, value):
    if value not in (1, -1):
        raise ValueError(f"{who}: branch must be +1 or -1, not {value!r}")
    return float(value)


def _name(who, name):
    if not isinstance(name, str) or not name:
        raise TypeError(f"{who}: a joint name must be a non-empty string, not {name!r}")
    return name


class _Link:
    __slots__ = ("index", "name", "rigid", "axis", "base", "label", "own")

    def __init__(self, index, name, rigid, base, axis=(), label="", own=False):
        self.own = own            # its cosine and sine are those of its name's direction
        self.index = index
        self.name = name          # its defining name: the direction of its angle
        self.rigid = set(rigid)   # joints rigidly on it
        self.axis = set(axis)     # other two-joint names whose direction turns with it
        self.base = base          # the point its loads are gathered about
        self.label = label

    def __getstate__(self):
        return {k: getattr(self, k) for k in self.__slots__}

    def __setstate__(self, state):
        for k, v in state.items():
            setattr(self, k, v)


class Mechanism:
    """A planar mechanism: a driven crank and class II groups, described once.

    Examples
    --------
    >>> import math, numpy as np, sarkp
    >>> m = sarkp.Mechanism()
    >>> m.fixed("O", 0.0, 0.0); m.fixed("C", 0.3, 0.0)
    >>> m.crank("A", "O", 0.1)
    >>> m.rrr("B", "A", "C", 0.35, 0.3, branch=1)
    >>> r = m.solve(np.linspace(0, 2 * math.pi, 5), omega=10.0)
    >>> r.position("B").shape
    (5, 2)
    """

    def __init__(self):
        self._points = {}           # name -> index (0-based)
        self._fixed = {}            # name -> (x, y)
        self._owner = {}            # name -> link index
        self._links = [_Link(0, ("frame",), (), None, label="frame")]
        self._steps = []            # (kind, ints, reals, joint name)
        self._hidden = 0
        self._masses = []           # (link, point, m, J)
        self._forces = []           # (point, link, fx, fy)
        self._torques = []          # (link, M)
        self._springs = []          # (P, Q, k, L0)
        self._pairs = [("O", 1, 0, "R")]   # (joint, on link, by link, R/P) per reaction slot
        self._crank = None
        self._cache = None

    # -- description ------------------------------------------------------------------
    def _new(self, who, name):
        self._cache = None
        name = _name(who, name)
        if name in self._points:
            raise ValueError(f"{who}: joint {name!r} is defined twice")
        self._points[name] = len(self._points)
        return name

    def _known(self, who, name):
        name = _name(who, name)
        if name not in self._points:
            raise ValueError(f"{who}: unknown joint {name!r} (define it first)")
        return self._points[name]

    def _need_crank(self, who):
        if self._crank is None:
            raise ValueError(f"{who}: define the crank first (m.crank)")

    def _add_link(self, name, rigid, base, axis=(), label="", own=False):
        link = _Link(len(self._links), tuple(name), rigid, base, axis, label, own)
        self._links.append(link)
        return link.index

    def fixed(self, name, x, y):
        """A frame point (a fixed pivot or a guide's point) at (x, y)."""
        who = f"fixed({name!r})"
        x, y = _real(who, "x", x), _real(who, "y", y)
        name = self._new(who, name)
        self._fixed[name] = (x, y)
        self._owner[name] = _FRAME
        self._links[0].rigid.add(name)

    def crank(self, A, O, r):
        """The input link O-A of length r about the frame point O; its angle is phi."""
        who = f"crank({A!r}, {O!r})"
        if self._crank is not None:
            raise ValueError(f"{who}: the mechanism has a crank already")
        r = _length(who, "r", r)
        o = self._known(who, O)
        if O not in self._fixed:
            raise ValueError(f"{who}: joint {O!r} must be a frame point (m.fixed)")
        self._new(who, A)
        link = self._add_link((O, A), {O, A}, O, label="crank", own=True)
        self._owner[A] = link
        self._crank = (A, O)
        self._steps.append((0, [self._points[A], o, link], [r], A))

    def _inputs(self, who, *names):
        self._need_crank(who)
        return [self._known(who, n) for n in names]

    def _guide_link(self, who, point, guide):
        """The link a guide through ``point`` belongs to: ``guide`` names it, else the
        frame (``point`` then a frame point)."""
        if guide is None:
            if point not in self._fixed:
                raise ValueError(f"{who}: joint {point!r} is not a frame point: name the "
                                 f"link its guide is on (guide=(P, Q))")
            return _FRAME
        link = self._link(who, guide)
        if point not in link.rigid:
            raise ValueError(f"{who}: joint {point!r} is not on the guide's link "
                             f"{'-'.join(link.name)}")
        return link.index

    def _group(self, kind, B, ints, reals, links, pairs):
        self._steps.append((kind, [self._points[B], *ints], reals, B))
        for joint, on, by, t in pairs:
            self._pairs.append((joint, on, by, t))

    def rrr(self, B, A, C, l2, l3, branch=1):
        """Kind 1 (RRR, DPRM1): joint B at l2 from A and l3 from C.

        Links A-B and C-B.  branch +1: B on the left of the directed line A->C."""
        who = f"rrr({B!r}, {A!r}, {C!r})"
        a, c = self._inputs(who, A, C)
        l2, l3 = _length(who, "l2", l2), _length(who, "l3", l3)
        q = _branch(who, branch)
        self._new(who, B)
        L2 = self._add_link((A, B), {A, B}, A, label=f"{A}-{B}", own=True)
        L3 = self._add_link((C, B), {C, B}, C, label=f"{C}-{B}", own=True)
        self._owner[B] = L2
        self._group(1, B, [a, c, L2, L3, 0, 0], [l2, l3, q, 1.0 / l2, 1.0 / l3], (L2, L3),
                    [(A, L2, self._owner[A], "R"), (B, L3, L2, "R"),
                     (C, L3, self._owner[C], "R")])

    def rrp(self, B, A, K, angle, l2, branch=1, *, offset=0.0, guide=None):
        """Kind 2 (RRP, DPRM2): slider joint B on the guide through K with direction
        ``angle``, rod A-B of length l2.

        ``offset``: B's distance from the guide's axis, along its left normal (DPRM2's
        RZ3*SIN(T)); ``guide``: the link the guide is on (two joints naming it; its angle
        then counts from that link's direction), by default the frame (K a frame point).
        branch +1: B ahead, along the guide's direction, of the foot of the perpendicular
        from A.  Links: the rod A-B and the slider block, named ``B``."""
        who = f"rrp({B!r}, {A!r}, {K!r})"
        a, k = self._inputs(who, A, K)
        angle = _real(who, "angle", angle)
        l2 = _length(who, "l2", l2)
        q = _branch(who, branch)
        off = _real(who, "offset", offset)
        lm = self._guide_link(who, K, guide)
        self._new(who, B)
        L2 = self._add_link((A, B), {A, B}, A, label=f"{A}-{B}", own=True)
        L3 = self._add_link((B,), {B}, B, label=f"slider {B}")
        self._owner[B] = L3
        self._group(2, B, [a, k, L2, L3, lm, 0],
                    [l2, q, math.cos(angle), math.sin(angle), off, angle, 1.0 / l2],
                    (L2, L3),
                    [(A, L2, self._owner[A], "R"), (B, L3, L2, "R"), (B, L3, lm, "P")])

    def rpr(self, B, A, C, rz2, t=math.pi / 2, branch=1):
        """Kind 3 (RPR, DPRM3): a slider pivoted at A slides along link 3, which turns
        about C; A is ``rz2*sin(t)`` from link 3's axis (DPRM3's RZ2, T).

        B is the foot of the perpendicular from A on the axis (a point of the slider);
        branch +1: B on the left of the directed line A->C.  Links: the slider, named
        (A, B), and link 3, named (C, B) (its axis; B slides along it)."""
        who = f"rpr({B!r}, {A!r}, {C!r})"
        a, c = self._inputs(who, A, C)
        rz2 = _real(who, "rz2", rz2)
        t = _real(who, "t", t)
        q = _branch(who, branch)
        h = abs(rz2 * math.sin(t))
        self._new(who, B)
        L2 = self._add_link((A, B), {A, B}, A, label=f"slider {A}")
        L3 = self._add_link((C, B), {C}, C, axis=[(C, B)], label=f"{C}-{B}", own=True)
        self._owner[B] = L2
        self._group(3, B, [a, c, L2, L3, 0, 0], [h, q], (L2, L3),
                    [(A, L2, self._owner[A], "R"), (B, L3, L2, "P"),
                     (C, L3, self._owner[C], "R")])

    def prp(self, B, A, fim, C, fin, *, rz2=0.0, t2=0.0, rz3=0.0, t3=0.0, guide_m=None,
            guide_n=None):
        """Kind 4 (PRP, DPRM4): joint B of two sliders, on the guide through A with
        direction ``fim`` and on the guide through C with direction ``fin``; B is
        ``rz2*sin(t2)`` (``rz3*sin(t3)``) from the guide axes along their left normals.

        ``guide_m``, ``guide_n``: the links the guides are on (default the frame).  One
        position (no branch).  Links: the sliders, named (B, A) and (B, C)."""
        who = f"prp({B!r}, {A!r}, {C!r})"
        a, c = self._inputs(who, A, C)
        fim, fin = _real(who, "fim", fim), _real(who, "fin", fin)
        d2 = _real(who, "rz2", rz2) * math.sin(_real(who, "t2", t2))
        d3 = _real(who, "rz3", rz3) * math.sin(_real(who, "t3", t3))
        lm = self._guide_link(who, A, guide_m)
        ln = self._guide_link(who, C, guide_n)
        self._new(who, B)
        L2 = self._add_link((B, A), {B}, B, label=f"slider {B} on {A}")
        L3 = self._add_link((B, C), {B}, B, label=f"slider {B} on {C}")
        self._owner[B] = L2
        self._group(4, B, [a, c, L2, L3, lm, ln],
                    [math.cos(fim), math.sin(fim), math.cos(fin), math.sin(fin), d2, d3,
                     fim, fin], (L2, L3),
                    [(B, L2, lm, "P"), (B, L3, L2, "R"), (B, L3, ln, "P")])

    def rpp(self, K, A, fim, C, t2, *, guide=None):
        """Kind 5 (RPP, DPRM5): link 2 slides on the guide through A (direction ``fim``);
        a block pivoted at C slides in link 2 along the direction ``fim + t2``.

        K is where the slot's axis meets the guide's axis (a point of link 2).  One
        position.  Links: link 2, named (K, A), and the block, named (C, K)."""
        who = f"rpp({K!r}, {A!r}, {C!r})"
        a, c = self._inputs(who, A, C)
        fim, t2 = _real(who, "fim", fim), _real(who, "t2", t2)
        if math.sin(t2) == 0.0:
            raise ValueError(f"{who}: t2 = {t2}: the slot is parallel to the guide")
        lm = self._guide_link(who, A, guide)
        self._new(who, K)
        L2 = self._add_link((K, A), {K}, K, label=f"slotted link {K}")
        L3 = self._add_link((C, K), {C}, C, label=f"block {C}")
        self._owner[K] = L2
        self._group(5, K, [a, c, L2, L3, lm, 0],
                    [math.cos(fim), math.sin(fim), math.cos(t2), math.sin(t2), fim, t2],
                    (L2, L3),
                    [(K, L2, lm, "P"), (C, L3, L2, "P"), (C, L3, self._owner[C], "R")])

    # Where each kind keeps its branch among its reals (rrr, rrp, rpr); the seam between
    # the description and code that follows a motion through toggles (issue 26).
    _BRANCH_SLOT = {1: 2, 2: 1, 3: 1}

    def branch(self, B):
        """The branch (+1 or -1) of the group that places joint ``B``; None for a group
        kind with one position (prp, rpp)."""
        for kind, _, reals, name in self._steps:
            if name == B and 1 <= kind <= 5:
                slot = self._BRANCH_SLOT.get(kind)
                return None if slot is None else int(reals[slot])
        raise ValueError(f"branch({B!r}): no group places joint {B!r}")

    def set_branch(self, B, branch):
        """Set the branch (+1 or -1) of the group that places joint ``B``."""
        who = f"set_branch({B!r})"
        q = _branch(who, branch)
        for kind, _, reals, name in self._steps:
            if name == B and 1 <= kind <= 5:
                slot = self._BRANCH_SLOT.get(kind)
                if slot is None:
                    raise ValueError(f"{who}: a {('prp', 'rpp')[kind - 4]} group has one "
                                     f"position, no branch")
                reals[slot] = q
                self._cache = None
                return
        raise ValueError(f"{who}: no group places joint {B!r}")

    def _link(self, who, spec):
        """The link named by two joints on it (or one joint: a slider block)."""
        if isinstance(spec, str):
            spec = (spec,)
        spec = tuple(spec)
        for n in spec:
            self._known(who, n)
        if len(spec) == 1:
            # a slider block (or a slotted link, a block) that carries this one joint
            found = [lk for lk in self._links[1:] if lk.name == spec
                     or (lk.name[0] == spec[0] and lk.rigid == {spec[0]})]
        elif len(spec) == 2:
            p, q = spec
            if p == q:
                raise ValueError(f"{who}: a link is named by two different joints, not "
                                 f"{p!r} twice")
            found = [lk for lk in self._links[1:]
                     if (p in lk.rigid and q in lk.rigid) or lk.name in (spec, spec[::-1])
                     or spec in lk.axis or spec[::-1] in lk.axis]
        else:
            raise ValueError(f"{who}: name a link by two joints on it, not {spec!r}")
        if len(found) != 1:
            raise ValueError(f"{who}: joints {' and '.join(map(repr, spec))} are not on one "
                             f"link" if not found else f"{who}: {spec!r} names several links")
        return found[0]

    def _rigid_name(self, link, p, q):
        return (p in link.rigid and q in link.rigid) or (p, q) in link.axis or \
            (q, p) in link.axis

    def point(self, D, P, Q, dist, angle=0.0):
        """Point D rigidly on link P-Q: ``dist`` from P, at ``angle`` (counter-clockwise)
        from the direction P->Q.  ``Q = None``: on the slider block (or slotted link)
        that P names, ``angle`` counted from its guide's direction."""
        who = f"point({D!r}, {P!r}, {Q!r})"
        if Q is None:
            self._inputs(who, P)
            link = self._link(who, (P,))
            Q = P
        else:
            self._inputs(who, P, Q)
            link = self._link(who, (P, Q))
            if not self._rigid_name(link, P, Q):
                raise ValueError(f"{who}: the direction {P}->{Q} does not turn with the "
                                 f"link")
        dist = _real(who, "dist", dist)
        if dist < 0:
            raise ValueError(f"{who}: dist must be >= 0, not {dist}")
        angle = _real(who, "angle", angle)
        self._new(who, D)
        link.rigid.add(D)
        self._owner[D] = link.index
        q = P if link.own and link.name == (P, Q) else Q     # no square root needed
        self._steps.append((6, [self._points[D], self._points[P], self._points[q],
                                link.index], [dist, math.cos(angle), math.sin(angle)], D))

    def _centre(self, who, link, P, Q, centre):
        """The point index of a centre of mass on ``link``: P itself, or a hidden rigid
        point ``centre`` (dist or (dist, angle)) from P along P->Q."""
        if isinstance(centre, tuple):
            if len(centre) != 2:
                raise ValueError(f"{who}: centre must be a distance or (distance, angle)")
            dist, ang = _real(who, "centre", centre[0]), _real(who, "centre", centre[1])
        else:
            dist, ang = _real(who, "centre", centre), 0.0
        if dist < 0:
            raise ValueError(f"{who}: centre distance must be >= 0, not {dist}")
        if dist == 0.0:
            return self._points[P]
        if Q is None or not self._rigid_name(link, P, Q):
            raise ValueError(f"{who}: a centre off joint {P!r} needs two joints whose "
                             f"direction turns with the link")
        self._hidden += 1
        name = f"\x00centre{self._hidden}"
        self._points[name] = len(self._points)
        q = P if link.own and link.name == (P, Q) else Q     # no square root needed
        self._steps.append((6, [self._points[name], self._points[P], self._points[q],
                                link.index], [dist, math.cos(ang), math.sin(ang)], name))
        return self._points[name]

    def mass(self, P, Q=None, *, mass, inertia=0.0, centre=0.0):
        """Mass (kg) and moment of inertia about the centre of mass (kg m^2) of link P-Q
        (or of slider block P), the centre ``centre`` from P along P->Q (a distance, or
        (distance, angle) off that line, as :meth:`point`)."""
        who = f"mass({P!r}, {Q!r})" if Q is not None else f"mass({P!r})"
        link = self._link(who, (P,) if Q is None else (P, Q))
        m = _real(who, "mass", mass)
        j = _real(who, "inertia", inertia)
        if m < 0:
            raise ValueError(f"{who}: mass must be >= 0, not {m}")
        if j < 0:
            raise ValueError(f"{who}: inertia must be >= 0, not {j}")
        point = self._centre(who, link, P, Q, centre)
        self._masses.append((link.index, point, m, j))
        self._cache = None

    def force(self, P, fx, fy, *, link=None):
        """External force (N) at joint or point P: constants, or one value per position
        of the solve.  It acts on ``link`` (two joints naming it, or a slider's joint),
        by default on P's owner (see the module's docstring)."""
        who = f"force({P!r})"
        self._known(who, P)
        if link is None:
            on = self._owner[P]
        else:
            lk = self._link(who, link)
            if P not in lk.rigid:
                raise ValueError(f"{who}: joint {P!r} is not on link {lk.label}")
            on = lk.index
        if on == _FRAME:
            raise ValueError(f"{who}: joint {P!r} is a frame point: a force there does "
                             f"nothing")
        fx, fy = self._load_values(who, "fx", fx), self._load_values(who, "fy", fy)
        self._forces.append((self._points[P], on, fx, fy))
        self._cache = None

    def torque(self, P, Q, M):
        """External moment (N m, counter-clockwise positive) on link P-Q: a constant or
        one value per position.  A driving torque on the crank: ``m.torque("O", "A", M)``."""
        who = f"torque({P!r}, {Q!r})"
        link = self._link(who, (P, Q))
        self._torques.append((link.index, self._load_values(who, "M", M)))
        self._cache = None

    def spring(self, P, Q, k, L0):
        """A linear spring between points P and Q: stiffness k (N/m, >= 0), free length
        L0 (m, >= 0); its force follows the positions."""
        who = f"spring({P!r}, {Q!r})"
        self._known(who, P)
        self._known(who, Q)
        if P == Q:
            raise ValueError(f"{who}: a spring joins two different points")
        k = _real(who, "k", k)
        L0 = _real(who, "L0", L0)
        if k < 0:
            raise ValueError(f"{who}: k must be >= 0, not {k}")
        if L0 < 0:
            raise ValueError(f"{who}: L0 must be >= 0, not {L0}")
        self._springs.append((self._points[P], self._points[Q], self._owner[P],
                              self._owner[Q], k, L0))
        self._cache = None

    @staticmethod
    def _load_values(who, name, value):
        if np.ndim(value) == 0:
            return _real(who, name, value)
        a = np.asarray(value)
        if a.dtype.kind not in "fiu" or a.ndim != 1:
            raise TypeError(f"{who}: {name} must be a number or a 1-d array of numbers")
        a = a.astype(float)
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{who}: {name} must be finite")
        return a

    # -- names ------------------------------------------------------------------------
    @property
    def joints(self):
        """The joint and point names, in the order they were defined."""
        return [n for n in self._points if not n.startswith("\x00")]

    def __repr__(self):
        groups = sum(1 for s in self._steps if 1 <= s[0] <= 5)
        return (f"Mechanism({len(self.joints)} joints, {len(self._links) - 1} moving links, "
                f"{groups} groups)")

    # -- solving ----------------------------------------------------------------------
    def solve(self, phi, omega=1.0, epsilon=0.0, need="accelerations", gravity=0.0, *,
              on_error="raise"):
        """Solve the mechanism at the crank angles ``phi`` in one compiled call.

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad); the link angles are continuous along a 1-d sweep.
        omega, epsilon : float or array_like
            The crank's angular velocity (rad/s) and acceleration (rad/s^2): scalars or one
            value per position.
        need : {"positions", "velocities", "accelerations", "forces"}
            What to compute; what is not asked for is not computed.
        gravity : float
            g (m/s^2), acting along -y; 0 by default.
        on_error : {"raise", "nan"}
            A position where a group does not assemble raises AssemblyError naming the
            group and the angle (a dead centre SingularError; a loss of digits warns with
            SignificanceWarning); ``"nan"``: NaN there and ``r.status``.

        Returns
        -------
        MechanismResult
            ``r.position(name)``, ``r.velocity``, ``r.acceleration`` (shape phi.shape +
            (2,)), ``r.angle(P, Q)``, ``r.omega``, ``r.epsilon``, ``r.reaction(joint)``,
            ``r.balancing_moment``, ``r.reduced_inertia``, ``r.reduced_moment``,
            ``r.status``; ``r.plot()``, ``r.animate(path)``, ``r.to_frame()``.
        """
        if self._crank is None:
            raise ValueError("solve: the mechanism has no crank (m.crank)")
        level = NEEDS.get(need) if isinstance(need, str) else None
        if level is None:
            raise ValueError(f"solve: need must be one of {list(NEEDS)}, not {need!r}")
        if on_error not in ("raise", "nan"):
            raise ValueError(f"solve: on_error must be 'raise' or 'nan', not {on_error!r}")
        phi_in = np.asarray(phi)
        if phi_in.dtype.kind not in "fiu":
            raise TypeError("solve: phi must be real numbers")
        shape = phi_in.shape
        phiv = np.ascontiguousarray(phi_in, dtype=float).reshape(-1)
        n = phiv.size
        if n == 0:
            raise ValueError("solve: phi is empty")
        if not np.isfinite(phiv).all():
            raise ValueError("solve: phi must be finite")
        w, inc_w = self._per_position("omega", omega, n)
        e, inc_e = self._per_position("epsilon", epsilon, n)
        g = _real("solve", "gravity", gravity)
        t = self._tables()
        fval, tval = self._load_tables(n)
        nop, nl, npair = len(t["outp"]), t["nl"], t["npair"]
        nv = n if level >= 2 else 1
        na = n if level >= 3 else 1
        nr = n if level >= 4 else 1
        empty = np.empty
        pos = empty((2, nop, n), order="F")
        vel = empty((2, nop, nv), order="F")
        acc = empty((2, nop, na), order="F")
        th = empty((2, nl, n), order="F")
        om = empty((nl, nv), order="F")
        ep = empty((nl, na), order="F")
        react = empty((3, npair, nr), order="F")
        mbal, jred, mred = empty(nr), empty(nv), empty(nr)
        status = np.zeros(n, dtype=np.int32)
        fgroup = np.zeros(n, dtype=np.int32)
        _sarkp.mechanism.mech_solve(
            level, t["gi"], t["gr"], phiv, w, e, inc_w, inc_e, t["mlink"], t["mpoint"],
            t["mval"], g, t["fpoint"], t["flink"], fval, t["tlink"], tval, t["spp"],
            t["spl"], t["spv"], t["powner"], t["lbase"], t["x0"], t["outp"], t["outl"],
            pos, vel, acc, th, om, ep, react, mbal, jred, mred, status, fgroup)
        ok = status == 0
        if not ok.all():
            ok |= status > _ST_DIGITS
            self._settle(status, fgroup, phiv, shape, on_error)
            bad = ~ok
            if bad.any():
                for arr in (pos, vel, acc, th, om, ep, react):
                    if arr.shape[-1] == n:
                        arr[..., bad] = math.nan
                for arr in (mbal, jred, mred):
                    if arr.size == n:
                        arr[bad] = math.nan

        flat = len(shape) == 1

        def out(a, tail=()):
            if a.shape[-1] != n:
                return None                 # not asked for
            a = a.T
            return a if flat else a.reshape(shape + tail)
        lost = status > _ST_DIGITS
        code = np.where(lost, np.int32(Status.SIGNIFICANCE), status) if lost.any() else status
        return MechanismResult._make((
            self, t["columns"], need, phiv if flat else phiv.reshape(shape),
            out(pos, (nop, 2)), out(vel, (nop, 2)), out(acc, (nop, 2)), out(th, (nl, 2)),
            out(om, (nl,)), out(ep, (nl,)), out(react, (npair, 3)), out(mbal), out(jred),
            out(mred), code if flat else code.reshape(shape)))

    def _tables(self):
        """The description as Fortran tables, built once (until the next change)."""
        t = getattr(self, "_cache", None)
        if t is not None:
            return t
        npt = len(self._points)
        nl = len(self._links) - 1
        steps = self._steps
        gi = np.zeros((8, len(steps)), dtype=np.int32, order="F")
        gr = np.zeros((8, len(steps)), order="F")
        for k, (kind, ints, reals, _) in enumerate(steps):
            gi[0, k] = kind
            npoints = 2 if kind == 0 else 3
            for j, v in enumerate(ints):
                # points are 1-based in Fortran; links 0-based (0 the frame)
                gi[1 + j, k] = v + 1 if j < npoints else v
            gr[:len(reals), k] = reals
        x0 = np.zeros((2, npt), order="F")
        for name, (x, y) in self._fixed.items():
            x0[:, self._points[name]] = (x, y)
        powner = np.zeros(npt, dtype=np.int32)
        for name, l in self._owner.items():
            powner[self._points[name]] = l
        for (l, p, _, _) in self._masses:
            if p not in [self._points[nm] for nm in self._owner]:
                powner[p] = l
        lbase = np.ones(nl + 1, dtype=np.int32)
        for lk in self._links[1:]:
            lbase[lk.index] = self._points[lk.base] + 1
        # f2py takes no empty arrays: an empty list of loads gets one neutral entry (a zero
        # mass, force, torque or spring on the crank)
        a_pin = self._points[self._crank[0]]
        masses = self._masses or [(_CRANK, a_pin, 0.0, 0.0)]
        springs = self._springs or [(a_pin, a_pin, _CRANK, _CRANK, 0.0, 0.0)]
        forces = self._forces or [(a_pin, _CRANK, 0.0, 0.0)]
        torques = self._torques or [(_CRANK, 0.0)]
        # the outputs: the moving points (not the frame's, not the hidden centres) and the
        # moving links
        moving = [name for name in self.joints if name not in self._fixed]
        outp = np.array([self._points[nm] + 1 for nm in moving], dtype=np.int32)
        outl = np.arange(1, nl + 1, dtype=np.int32)
        columns = ({nm: j for j, nm in enumerate(moving)},
                   {nm: tuple(xy) for nm, xy in self._fixed.items()})
        t = {"npt": npt, "nl": nl, "npair": len(self._pairs), "gi": gi, "gr": gr, "x0": x0,
             "outp": outp, "outl": outl, "columns": columns,
             "powner": powner, "lbase": lbase,
             "mlink": np.array([m[0] for m in masses], dtype=np.int32),
             "mpoint": np.array([m[1] + 1 for m in masses], dtype=np.int32),
             "mval": np.array([[m[2], m[3]] for m in masses]).T.copy("F"),
             "spp": np.array([[s[0] + 1, s[1] + 1] for s in springs],
                             dtype=np.int32).T.copy("F"),
             "spl": np.array([[s[2], s[3]] for s in springs], dtype=np.int32).T.copy("F"),
             "spv": np.array([[s[4], s[5]] for s in springs]).T.copy("F"),
             "forces": forces, "torques": torques,
             "fpoint": np.array([f[0] + 1 for f in forces], dtype=np.int32),
             "flink": np.array([f[1] for f in forces], dtype=np.int32),
             "fvar": any(np.ndim(f[2]) or np.ndim(f[3]) for f in forces),
             "tlink": np.array([t[0] for t in torques], dtype=np.int32),
             "tvar": any(np.ndim(t[1]) for t in torques), "loads": {}}
        self._cache = t
        return t

    def _load_tables(self, n):
        """The forces' and torques' values, (2, nf, 1 or n) and (nt, 1 or n)."""
        t = self._tables()
        key = (n if t["fvar"] else 1, n if t["tvar"] else 1)
        if key in t["loads"]:
            return t["loads"][key]
        fval = np.zeros((2, len(t["forces"]), key[0]), order="F")
        names = {i: nm for nm, i in self._points.items()}
        for j, (p, _, fx, fy) in enumerate(t["forces"]):
            fval[0, j, :] = self._values_for(f"force at {names[p]!r}: fx", fx, n)
            fval[1, j, :] = self._values_for(f"force at {names[p]!r}: fy", fy, n)
        tval = np.zeros((len(t["torques"]), key[1]), order="F")
        for j, (li, M) in enumerate(t["torques"]):
            tval[j, :] = self._values_for(f"torque on {self._links[li].label}: M", M, n)
        t["loads"] = {key: (fval, tval)}
        return fval, tval

    def __getstate__(self):
        state = dict(self.__dict__)
        state["_cache"] = None
        return state

    @staticmethod
    def _per_position(name, value, n):
        if type(value) is float or type(value) is int:         # the common case, quickly
            if not math.isfinite(value):
                raise ValueError(f"solve: {name} must be finite")
            return np.array([value], dtype=float), 0
        a = np.asarray(value)
        if a.dtype.kind not in "fiu":
            raise TypeError(f"solve: {name} must be real numbers")
        a = np.ascontiguousarray(a, dtype=float).ravel()
        if a.size == 1:
            inc = 0
        elif a.size == n:
            inc = 1
        else:
            raise ValueError(f"solve: {name} has {a.size} values for {n} positions")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"solve: {name} must be finite")
        return a, inc

    @staticmethod
    def _values_for(who, value, n):
        if np.ndim(value) == 0:
            return value
        if len(value) != n:
            raise ValueError(f"solve: {who} has {len(value)} values for {n} positions")
        return value

    def _step_text(self, k):
        kind, _, _, name = self._steps[k - 1]
        return f"group {KIND_NAMES[kind]} {name!r} (step {k})"

    def _settle(self, status, fgroup, phiv, shape, on_error):
        failed = ~((status == 0) | (status > _ST_DIGITS))
        if on_error == "raise" and failed.any():
            i = int(np.argmax(failed))
            code = int(status[i])
            index = np.unravel_index(i, shape) if shape else None
            where = f"at phi = {float(phiv[i])!r}" + (f" (index {tuple(map(int, index))})"
                                               if shape else "")
            what = self._step_text(int(fgroup[i])) if fgroup[i] else "the mechanism"
            if code == Status.ASSEMBLY:
                raise AssemblyError(f"{what} does not assemble {where}: the links do not "
                                    f"reach", index=index)
            if code == Status.RANGE:
                raise RangeError(f"{what}: a result overflows {where}", index=index)
            raise SingularError(f"{what} is at a dead centre {where}: no significant "
                                f"digit of the result is left", index=index)
        lost = status > _ST_DIGITS
        if lost.any():
            i = int(np.argmax(lost))
            digits = int(status[lost].min() - _ST_DIGITS)
            index = np.unravel_index(i, shape) if shape else None
            warnings.warn(SignificanceWarning(
                f"{self._step_text(int(fgroup[i]))} is near a dead centre at phi = "
                f"{float(phiv[i])!r}: about {digits} significant digits left", digits=digits,
                index=index), stacklevel=3)
        return status, fgroup

    # -- chapter 8 at the mechanism level --------------------------------------------------
    def _loads(self, phi, gravity):
        r = self.solve(phi, omega=1.0, epsilon=0.0, need="forces", gravity=gravity)
        return r.reduced_inertia, r.reduced_moment

    def motion(self, phi, omega0=0.0, *, t0=0.0, omega_mean=None, gravity=0.0):
        """omega(phi) and t(phi) of the crank under the mechanism's loads (a constant
        driving torque is ``m.torque(O, A, M)``), from its J_red and M_red
        (:func:`sarkp.dynamics.motion`): from ``omega0`` at phi[0] (0: from rest), or,
        with ``omega_mean``, the steady state over one cycle (phi spanning exactly one)."""
        from .dynamics import motion
        J, M = self._loads(phi, gravity)
        return motion(phi, J, M, omega0=omega0, t0=t0, omega_mean=omega_mean)

    def simulate(self, t, *, phi0=0.0, omega0=0.0, gravity=0.0, rtol=1e-8,
                 branches="continuous"):
        """The motion in time under the mechanism's loads, from phi0, omega0 at t[0].

        Integrates J(phi) phi'' + J'(phi) phi'^2/2 = M(phi) (masses, inertias, gravity,
        springs, forces, torques) through reversals and from rest, by Gauss-Legendre
        collocation with 8 nodes (order 16 at the step ends, 8 for the dense output,
        whose error estimate is held to rtol), each sweep of the stages one vectorised
        :meth:`solve`.  Turning points (omega = 0, epsilon != 0), stalls (at rest and
        held there) and branch changes are events.  The mechanism itself is not changed.

        Parameters
        ----------
        t : array_like
            The times (s), strictly increasing, at least 2; t[0] is the start.
        phi0, omega0 : float
            The crank's angle (rad) and angular velocity (rad/s) at t[0]; 0: from rest.
        gravity : float
            g (m/s^2) along -y.
        rtol : float
            The error allowed per step, relative to |phi| (at least 1 rad) and to
            |omega| (at least the largest speed so far); in [1e-14, 0.1].  With RRR
            groups followed through toggles (branches="continuous") at most 1e-6 is
            used: looser steps can leap past a crossing's warning.
        branches : {"continuous", "geometric"}
            "continuous": an RRR group passing a toggle or change point takes the
            branch with a continuous velocity (the other geometric one), a "branch"
            event; the branch given is the start's.  "geometric": the book's rule kept
            (an error at a toggle the motion passes).

        Returns
        -------
        Simulation
            ``.t, .phi, .omega, .epsilon`` (shaped like t), ``.events``, ``.branches``,
            ``.status``, ``.stats``; ``.solve(need)`` and ``.animate(path)``.

        Raises
        ------
        ValueError
            Bad input, naming it (t not increasing, rtol, NaN phi0/omega0), or a start
            where the mechanism does not assemble.
        RangeError
            The step size collapses (a dead centre the motion cannot pass).
        """
        from .dynamics import simulate
        return simulate(self, t, phi0=phi0, omega0=omega0, gravity=gravity, rtol=rtol,
                        branches=branches)

    def flywheel(self, delta, omega_mean, phi=None, *, gravity=0.0, J_constant=None):
        """The moment of inertia to add on the crank so that the steady state has the
        coefficient of speed fluctuation exactly ``delta`` (:func:`sarkp.dynamics.
        flywheel`; DMHVK's approximation beside it, the realized delta returned); phi:
        one cycle (default 361 points over 0..2 pi)."""
        from .dynamics import flywheel
        if phi is None:
            phi = np.linspace(0.0, 2.0 * math.pi, 361)
        J, M = self._loads(phi, gravity)
        return flywheel(phi, J, M, delta=delta, omega_mean=omega_mean,
                        J_constant=J_constant)


class _MechanismBase(Result):
    """What :meth:`Mechanism.solve` returns: the arrays by joint and link name."""

    __slots__ = ()

    def _repr_header(self):
        n = int(np.size(self.phi))
        failed = int(np.sum(~np.isin(self.status, (0, int(Status.SIGNIFICANCE)))))
        return (f"{self.mechanism!r}, need={self.need!r}, {n} positions"
                + (f", {failed} failed" if failed else ""))

    def __repr__(self):
        return f"MechanismResult({self._repr_header()})"

    __str__ = __repr__

    def _point(self, name, field):
        moving, fixed = self.columns
        if name not in moving and name not in fixed:
            raise ValueError(f"unknown joint {name!r}")
        a = getattr(self, field)
        if a is None:
            raise ValueError(f"{field} were not computed: solve with need >= {field!r}")
        if name in moving:
            return a[..., moving[name], :]
        shape = np.shape(self.phi) + (2,)
        if field == "positions":
            return np.broadcast_to(np.array(fixed[name], dtype=float), shape).copy()
        return np.zeros(shape)

    def position(self, name):
        """Cartesian (x, y) of a joint or point: shape phi.shape + (2,)."""
        return self._point(name, "positions")

    def velocity(self, name):
        return self._point(name, "velocities")

    def acceleration(self, name):
        return self._point(name, "accelerations")

    def _link(self, P, Q):
        return self.mechanism._link("result", (P,) if Q is None else (P, Q))

    def angle(self, P, Q=None):
        """The direction P->Q of a link named by two joints on it, continuous along the
        sweep (the first value in (-pi, pi]; the crank's is phi itself); a slider block's
        or a slotted link's guide direction.  Computed from the link's cosine and sine
        when asked for (np.unwrap along the positions)."""
        link = self._link(P, Q)
        if link.index == _CRANK and (P, Q) == link.name:
            return np.array(self.phi, dtype=float)
        d = self.directions[..., link.index - 1, :]
        shape = d.shape[:-1]
        th = np.arctan2(d[..., 1], d[..., 0]).reshape(-1)
        ok = ~np.isnan(th)                  # on_error="nan": unwrap across the failed positions
        th[ok] = np.unwrap(th[ok])
        th = th.reshape(shape)
        if Q is None or link.name == (P, Q) or not self.mechanism._rigid_name(link, P, Q):
            return th
        r = self.position(Q) - self.position(P)
        direct = np.arctan2(r[..., 1], r[..., 0])
        return th + np.remainder(direct - th + math.pi, 2 * math.pi) - math.pi

    def omega(self, P, Q=None):
        if self.omegas is None:
            raise ValueError("omega: solve with need >= 'velocities'")
        return self.omegas[..., self._link(P, Q).index - 1]

    def epsilon(self, P, Q=None):
        if self.epsilons is None:
            raise ValueError("epsilon: solve with need >= 'accelerations'")
        return self.epsilons[..., self._link(P, Q).index - 1]

    def _pair(self, joint, on, by):
        m = self.mechanism
        if self.reactions is None:
            raise ValueError("reaction: solve with need='forces'")
        if joint not in m._points:
            raise ValueError(f"reaction: unknown joint {joint!r}")
        on_i = None if on is None else (0 if on == "frame" else m._link("reaction", on).index)
        by_i = None if by is None else (0 if by == "frame" else m._link("reaction", by).index)
        found = []
        for slot, (j, lon, lby, t) in enumerate(m._pairs):
            if j != joint:
                continue
            for sign, a, b in ((1.0, lon, lby), (-1.0, lby, lon)):
                if (on_i is None and sign < 0) or (on_i is not None and a != on_i):
                    continue
                if by_i is not None and b != by_i:
                    continue
                found.append((slot, sign, t))
        if len(found) != 1:
            choices = [f"on={m._links[lon].label!r} by={m._links[lby].label!r}"
                       for j, lon, lby, t in m._pairs if j == joint]
            raise ValueError(f"reaction: {'no' if not found else 'several'} pairs at "
                             f"{joint!r} match; the pairs there: {choices} (name the link "
                             f"with on= and by=)")
        return found[0]

    def reaction(self, joint, on=None, by=None):
        """The force (fx, fy) at a pair at ``joint``: that of link ``by`` on link ``on``.
        Default: the group's link that the pair was made for (for a group's new joint B
        of kind 1, the force of link C-B's partner A-B on C-B, i.e. of link 2 on link 3;
        at an outer joint, of the earlier link on the group's link; at the crank's O, of
        the frame on the crank)."""
        slot, sign, _ = self._pair(joint, on, by)
        return sign * self.reactions[..., slot, :2]

    def couple(self, joint, on=None, by=None):
        """A slider pair's couple (N m) with its reaction (0 for a revolute)."""
        slot, sign, _ = self._pair(joint, on, by)
        return sign * self.reactions[..., slot, 2]

    def _frame_columns(self):
        m = self.mechanism
        cols = {"phi": np.ravel(self.phi)}
        for name in [*self.columns[1], *self.columns[0]]:
            for field, tag in (("positions", ""), ("velocities", "v"),
                               ("accelerations", "a")):
                a = getattr(self, field)
                if a is not None:
                    xy = self._point(name, field)
                    cols[f"{tag}x_{name}"] = np.ravel(xy[..., 0])
                    cols[f"{tag}y_{name}"] = np.ravel(xy[..., 1])
        for lk in m._links[1:]:
            label = "-".join(lk.name)
            cols[f"angle_{label}"] = np.ravel(self.angle(*lk.name))
            if self.omegas is not None:
                cols[f"omega_{label}"] = np.ravel(self.omegas[..., lk.index - 1])
            if self.epsilons is not None:
                cols[f"epsilon_{label}"] = np.ravel(self.epsilons[..., lk.index - 1])
        for f in ("balancing_moment", "reduced_inertia", "reduced_moment"):
            v = getattr(self, f)
            if v is not None:
                cols[f] = np.ravel(v)
        cols["status"] = np.ravel(self.status)
        return cols, np.shape(self.phi)

    # -- pictures ---------------------------------------------------------------------
    def _drawing(self):
        m = self.mechanism
        pts = {n: (self.position(n)[..., 0], self.position(n)[..., 1])
               for n in m.joints}
        links = []
        for lk in m._links[1:]:
            names = [n for n in lk.name if not n.startswith("\x00")]
            rigid = [n for n in lk.rigid if not n.startswith("\x00") and n not in names]
            if len(names) == 2 and names[0] in lk.rigid and names[1] in lk.rigid:
                links.append(tuple([names[0], *rigid, names[1]]))
            elif len(names) == 2 and (names[0], names[1]) in lk.axis:
                links.append(tuple(names))
        return pts, links, list(m._fixed)

    def plot(self, position=0, *, every=None, paths=(), title="", ax=None):
        """The mechanism at one position (in colour) over the sweep (grey); returns the
        matplotlib figure (sarkp.plot.mechanism)."""
        from . import plot
        pts, links, fixed = self._drawing()
        n = int(np.size(self.phi))
        if every is None:
            every = max(1, n // 12)
        # frame points that carry a link are pivots; a guide's frame point is not
        pivots = [f for f in fixed if any(f in link for link in links)]
        return plot.mechanism(pts, links, fixed=pivots, highlight=position, every=every,
                              paths=paths, title=title, ax=ax)

    def animate(self, path, *, fps=20, every=1, paths=()):
        """An animation over the sweep written to ``path`` (.gif through Pillow, .mp4
        through ffmpeg: matplotlib's writers)."""
        import matplotlib.pyplot as plt
        from matplotlib import animation
        if not str(path).endswith(".gif") and not animation.FFMpegWriter.isAvailable():
            raise RuntimeError(f"animate: writing {str(path)!r} needs ffmpeg (matplotlib's "
                               f"FFMpegWriter), which is not installed (Debian: apt-get "
                               f"install ffmpeg); a .gif path needs only Pillow")
        pts, links, fixed = self._drawing()
        xs = np.concatenate([np.ravel(x) for x, _ in pts.values()])
        ys = np.concatenate([np.ravel(y) for _, y in pts.values()])
        fig, ax = plt.subplots(figsize=(6, 5))
        pad = 0.05 * max(np.nanmax(xs) - np.nanmin(xs), np.nanmax(ys) - np.nanmin(ys), 1e-9)
        ax.set_xlim(np.nanmin(xs) - pad, np.nanmax(xs) + pad)
        ax.set_ylim(np.nanmin(ys) - pad, np.nanmax(ys) + pad)
        ax.set_aspect("equal")
        lines = [ax.plot([], [], "o-", lw=2)[0] for _ in links]
        for name in paths:
            ax.plot(np.ravel(pts[name][0]), np.ravel(pts[name][1]), "-", alpha=0.4)
        frames = range(0, int(np.size(self.phi)), max(1, every))

        def draw(k):
            for line, link in zip(lines, links):
                line.set_data([np.ravel(pts[q][0])[k] for q in link],
                              [np.ravel(pts[q][1])[k] for q in link])
            return lines
        anim = animation.FuncAnimation(fig, draw, frames=frames, blit=True)
        path = str(path)
        writer = animation.PillowWriter(fps=fps) if path.endswith(".gif") else \
            animation.FFMpegWriter(fps=fps)
        anim.save(path, writer=writer)
        plt.close(fig)
        return path


MechanismResult = result_type(
    "MechanismResult",
    ("mechanism", "columns", "need", "phi", "positions", "velocities", "accelerations",
     "directions",
     "omegas", "epsilons", "reactions", "balancing_moment", "reduced_inertia",
     "reduced_moment", "status"),
    base=_MechanismBase,
    doc="The solution of a Mechanism over its positions (Mechanism.solve).")
