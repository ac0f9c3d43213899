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

import inspect
import math
import numbers
import operator
import warnings

import numpy as np

from . import _sarkp
from .errors import AssemblyError, RangeError, SarkpError, SignificanceWarning, SingularError, Status
from .modes import MODE_CODE
from .results import Result, result_type

__all__ = ["Mechanism", "MechanismResult"]

NEEDS = {"positions": 1, "velocities": 2, "accelerations": 3, "forces": 4}
KIND_NAMES = {0: "crank", 1: "rrr", 2: "rrp", 3: "rpr", 4: "prp", 5: "rpp", 6: "point"}
_ST_DIGITS = int(_sarkp.prmtr.st_digits)
FIELDS = ("mechanism", "columns", "need", "phi", "positions", "velocities", "accelerations",
          "directions", "omegas", "epsilons", "reactions", "balancing_moment",
          "reduced_inertia", "reduced_moment", "status")
_FIELD = {f: i for i, f in enumerate(FIELDS)}
#: the need level that computes each field
NEED_OF = {"positions": 1, "directions": 1, "velocities": 2, "omegas": 2,
           "reduced_inertia": 2, "accelerations": 3, "epsilons": 3, "reactions": 4,
           "balancing_moment": 4, "reduced_moment": 4}
_NEED_NAME = {v: k for k, v in NEEDS.items()}
_FRAME = 0
_CRANK = 1
_SOLVE_PACKED = _sarkp.mechanism.mech_solve_packed
_SOLVE_ONE = _sarkp.mechanism.mech_solve_one
_SOLVE_FEW = _sarkp.mechanism.mech_solve_few
_RECORD_LIMIT = 2 ** 31 - 1     # bytes: the largest structured type numpy makes


def _real(who, name, value):
    if type(value) is float and math.isfinite(value):     # the common case, quickly
        return value
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


def _cos(x):
    return np.cos(x) if isinstance(x, np.ndarray) else math.cos(x)


def _sin(x):
    return np.sin(x) if isinstance(x, np.ndarray) else math.sin(x)


def _branch(who, value):
    if value not in (1, -1):
        raise ValueError(f"{who}: branch must be +1 or -1, not {value!r}")
    return float(value)


def _name(who, name):
    if not isinstance(name, str) or not name:
        raise TypeError(f"{who}: a joint name must be a non-empty string, not {name!r}")
    if name.startswith("\x00"):
        raise ValueError(f"{who}: joint names starting with '\\x00' are reserved, not "
                         f"{name!r}")
    return name


def _arguments(f):
    """How many of (phi, omega, t) the load callable ``f`` takes: its positional
    parameters without a default (1, 2 or 3); 1 when Python cannot tell (a ufunc)."""
    try:
        sig = inspect.signature(f)
    except (TypeError, ValueError):
        return 1
    kinds = (inspect.Parameter.POSITIONAL_ONLY, inspect.Parameter.POSITIONAL_OR_KEYWORD)
    params = list(sig.parameters.values())
    if any(p.kind == inspect.Parameter.VAR_POSITIONAL for p in params):
        return 3
    count = sum(1 for p in params if p.kind in kinds and p.default is p.empty)
    return count


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


class _Load:
    """A load given as a callable of the solve's grid: ``f(phi)``, ``f(phi, omega)`` or
    ``f(phi, omega, t)`` (its positional parameters without a default say which), called
    once per solve with 1-d arrays of the positions; it returns a number or one value per
    position."""

    __slots__ = ("who", "name", "f", "nargs", "lower")

    def __init__(self, who, name, f, lower=None):
        self.who, self.name, self.f, self.lower = who, name, f, lower
        self.nargs = _arguments(f)
        if self.nargs not in (1, 2, 3):
            raise TypeError(f"{who}: {name}: a load callable takes phi, (phi, omega) or "
                            f"(phi, omega, t), not {self.nargs} arguments")

    def __getstate__(self):
        return {k: getattr(self, k) for k in self.__slots__}

    def __setstate__(self, state):
        for k, v in state.items():
            setattr(self, k, v)

    def __call__(self, phi, omega, t):
        if self.nargs == 3 and t is None:
            raise ValueError(f"solve: the load {self.name} of {self.who} depends on time: "
                             f"pass solve(..., t=)")
        args = (phi, omega, t)[:self.nargs]
        value = np.asarray(self.f(*args), dtype=float)
        n = phi.size
        if value.ndim > 1 or (value.ndim == 1 and value.size not in (1, n)):
            raise ValueError(f"solve: the load {self.name} of {self.who} returned shape "
                             f"{value.shape}: want a number or one value for each of the "
                             f"{n} positions")
        if not np.all(np.isfinite(value)):
            raise ValueError(f"solve: the load {self.name} of {self.who} returned a value "
                             f"that is not finite")
        if self.lower == "nonneg" and np.any(value < 0.0):
            raise ValueError(f"solve: the load {self.name} of {self.who} must be >= 0")
        return value.reshape(1, -1)


class Mechanism:
    """A planar mechanism: a driven crank and class II groups, described once.

    Any length, coordinate, angle, offset, distance, mass, inertia, centre or spring
    value of the description may be a 1-d array over D designs (scalars broadcast; a
    force or torque per design is a (D, 1) or (D, n) array): :meth:`solve` then solves
    every design in one compiled call and its arrays carry a leading design axis,
    ``r.position("B").shape == (D,) + phi.shape + (2,)``, ``r.status.shape == (D,) +
    phi.shape``.  ``solve(..., points=, links=)`` stores only the joints and links
    asked for, ``solve(..., out=r)`` reuses the arrays of an earlier result, and loads
    may be callables of ``(phi)``, ``(phi, omega)`` or ``(phi, omega, t)`` (see
    :meth:`solve`).

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

    Three rockers in one call, storing only B and the rocker:

    >>> m = sarkp.Mechanism()
    >>> m.fixed("O", 0.0, 0.0); m.fixed("C", 0.3, 0.0)
    >>> m.crank("A", "O", 0.1)
    >>> m.rrr("B", "A", "C", 0.35, np.array([0.28, 0.3, 0.32]))
    >>> r = m.solve(np.linspace(0, 2 * math.pi, 5), omega=10.0, points=("B",),
    ...             links=(("C", "B"),))
    >>> r.position("B").shape, r.omega("C", "B").shape
    ((3, 5, 2), (3, 5))
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
        self._designs = None        # D when some value is a 1-d array over D designs

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

    def _set_designs(self, who, name, count):
        D = getattr(self, "_designs", None)
        if D is not None and D != count:
            raise ValueError(f"{who}: {name} has {count} designs where the mechanism has "
                             f"{D} (every design array has the same length)")
        self._designs = count

    def _value(self, who, name, value, lower=None):
        """A numeric value of the description: a real number, or a 1-d array over D
        designs.  ``lower``: "length" (> 0) or "nonneg" (>= 0)."""
        if isinstance(value, (np.ndarray, list, tuple)) and np.ndim(value) > 0:
            a = np.asarray(value)
            if a.dtype.kind not in "fiu" or a.ndim != 1 or a.size == 0:
                raise TypeError(f"{who}: {name} must be a real number or a 1-d array of "
                                f"numbers over the designs")
            a = a.astype(float)
            if not np.all(np.isfinite(a)):
                raise ValueError(f"{who}: {name} must be finite")
            low = a
        else:
            if isinstance(value, np.ndarray):
                value = value[()]
            a = low = _real(who, name, value)
        if lower == "length" and np.any(low <= 0.0):
            raise ValueError(f"{who}: {name} must be a length > 0, not {value}")
        if lower == "nonneg" and np.any(low < 0.0):
            raise ValueError(f"{who}: {name} must be >= 0, not {value}")
        if isinstance(a, np.ndarray):
            self._set_designs(who, name, a.size)
        return a

    @property
    def designs(self):
        """The number D of designs (None: one mechanism): the length of the 1-d arrays
        given for values of the description."""
        return getattr(self, "_designs", None)

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
        x, y = self._value(who, "x", x), self._value(who, "y", y)
        name = self._new(who, name)
        self._fixed[name] = (x, y)
        self._owner[name] = _FRAME
        self._links[0].rigid.add(name)

    def crank(self, A, O, r):
        """The input link O-A of length r about the frame point O; its angle is phi."""
        who = f"crank({A!r}, {O!r})"
        if self._crank is not None:
            raise ValueError(f"{who}: the mechanism has a crank already")
        r = self._value(who, "r", r, "length")
        o = self._known(who, O)
        if O not in self._fixed:
            raise ValueError(f"{who}: joint {O!r} must be a frame point (m.fixed)")
        self._new(who, A)
        self._pairs[0] = (O, 1, 0, "R")     # the crank's bearing, at its own pivot
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
        l2, l3 = self._value(who, "l2", l2, "length"), self._value(who, "l3", l3, "length")
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
        angle = self._value(who, "angle", angle)
        l2 = self._value(who, "l2", l2, "length")
        q = _branch(who, branch)
        off = self._value(who, "offset", offset)
        lm = self._guide_link(who, K, guide)
        self._new(who, B)
        L2 = self._add_link((A, B), {A, B}, A, label=f"{A}-{B}", own=True)
        L3 = self._add_link((B,), {B}, B, label=f"slider {B}")
        self._owner[B] = L3
        self._group(2, B, [a, k, L2, L3, lm, 0],
                    [l2, q, _cos(angle), _sin(angle), off, angle, 1.0 / l2],
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
        rz2 = self._value(who, "rz2", rz2)
        t = self._value(who, "t", t)
        q = _branch(who, branch)
        h = abs(rz2 * _sin(t))
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
        fim, fin = self._value(who, "fim", fim), self._value(who, "fin", fin)
        d2 = self._value(who, "rz2", rz2) * _sin(self._value(who, "t2", t2))
        d3 = self._value(who, "rz3", rz3) * _sin(self._value(who, "t3", t3))
        lm = self._guide_link(who, A, guide_m)
        ln = self._guide_link(who, C, guide_n)
        self._new(who, B)
        L2 = self._add_link((B, A), {B}, B, label=f"slider {B} on {A}")
        L3 = self._add_link((B, C), {B}, B, label=f"slider {B} on {C}")
        self._owner[B] = L2
        self._group(4, B, [a, c, L2, L3, lm, ln],
                    [_cos(fim), _sin(fim), _cos(fin), _sin(fin), d2, d3, fim, fin], (L2, L3),
                    [(B, L2, lm, "P"), (B, L3, L2, "R"), (B, L3, ln, "P")])

    def rpp(self, K, A, fim, C, t2, *, guide=None):
        """Kind 5 (RPP, DPRM5): link 2 slides on the guide through A (direction ``fim``);
        a block pivoted at C slides in link 2 along the direction ``fim + t2``.

        K is where the slot's axis meets the guide's axis (a point of link 2).  One
        position.  Links: link 2, named (K, A), and the block, named (C, K)."""
        who = f"rpp({K!r}, {A!r}, {C!r})"
        a, c = self._inputs(who, A, C)
        fim, t2 = self._value(who, "fim", fim), self._value(who, "t2", t2)
        if np.any(_sin(t2) == 0.0):
            raise ValueError(f"{who}: t2 = {t2}: the slot is parallel to the guide")
        lm = self._guide_link(who, A, guide)
        self._new(who, K)
        L2 = self._add_link((K, A), {K}, K, label=f"slotted link {K}")
        L3 = self._add_link((C, K), {C}, C, label=f"block {C}")
        self._owner[K] = L2
        self._group(5, K, [a, c, L2, L3, lm, 0],
                    [_cos(fim), _sin(fim), _cos(t2), _sin(t2), fim, t2],
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
        for k, (kind, _, reals, name) in enumerate(self._steps):
            if name == B and 1 <= kind <= 5:
                slot = self._BRANCH_SLOT.get(kind)
                if slot is None:
                    raise ValueError(f"{who}: a {('prp', 'rpp')[kind - 4]} group has one "
                                     f"position, no branch")
                reals[slot] = q
                tab = getattr(self, "_cache", None)
                if tab is not None:         # only the group's reals depend on it
                    tab["gr"][slot, k] = q
                    tab["packed"].clear()   # the packed copies of them go
                    tab["fast"].clear()
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
            if P in self._fixed and Q in self._fixed:
                raise ValueError(f"{who}: {P!r} and {Q!r} are frame points: a point rigid "
                                 f"with the frame is a frame point (m.fixed)")
            link = self._link(who, (P, Q))
            if not self._rigid_name(link, P, Q):
                raise ValueError(f"{who}: the direction {P}->{Q} does not turn with the "
                                 f"link")
        dist = self._value(who, "dist", dist, "nonneg")
        angle = self._value(who, "angle", angle)
        self._new(who, D)
        link.rigid.add(D)
        self._owner[D] = link.index
        q = P if link.own and link.name == (P, Q) else Q     # no square root needed
        self._steps.append((6, [self._points[D], self._points[P], self._points[q],
                                link.index], [dist, _cos(angle), _sin(angle)], D))

    def _centre(self, who, link, P, Q, centre):
        """The point index of a centre of mass on ``link``: P itself, or a hidden rigid
        point ``centre`` (dist or (dist, angle)) from P along P->Q."""
        if isinstance(centre, tuple):
            if len(centre) != 2:
                raise ValueError(f"{who}: centre must be a distance or (distance, angle)")
            dist = self._value(who, "centre distance", centre[0], "nonneg")
            ang = self._value(who, "centre angle", centre[1])
        else:
            dist, ang = self._value(who, "centre distance", centre, "nonneg"), 0.0
        if np.all(dist == 0.0):
            return self._points[P]
        if Q is None or not self._rigid_name(link, P, Q):
            raise ValueError(f"{who}: a centre off joint {P!r} needs two joints whose "
                             f"direction turns with the link")
        self._hidden += 1
        name = f"\x00centre{self._hidden}"
        self._points[name] = len(self._points)
        q = P if link.own and link.name == (P, Q) else Q     # no square root needed
        self._steps.append((6, [self._points[name], self._points[P], self._points[q],
                                link.index], [dist, _cos(ang), _sin(ang)], name))
        return self._points[name]

    def mass(self, P, Q=None, *, mass, inertia=0.0, centre=0.0):
        """Mass (kg) and moment of inertia about the centre of mass (kg m^2) of link P-Q
        (or of slider block P), the centre ``centre`` from P along P->Q (a distance, or
        (distance, angle) off that line, as :meth:`point`)."""
        who = f"mass({P!r}, {Q!r})" if Q is not None else f"mass({P!r})"
        link = self._link(who, (P,) if Q is None else (P, Q))
        m = self._value(who, "mass", mass, "nonneg")
        j = self._value(who, "inertia", inertia, "nonneg")
        point = self._centre(who, link, P, Q, centre)
        self._masses.append((link.index, point, m, j))
        self._cache = None

    def force(self, P, fx, fy, *, link=None):
        """External force (N) at joint or point P, components along +x and +y.

        ``fx``, ``fy``: a number; a 1-d array, one value per position of the solve; a
        2-d array of shape (D, 1) or (D, n), one row per design; or a callable of the
        solve's grid (see :meth:`solve`, "Loads").  It acts on ``link`` (two joints
        naming it, or a slider's joint), by default on P's owner (see the module's
        docstring)."""
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
        """External moment (N m, counter-clockwise positive) on link P-Q: a number, one
        value per position, (D, 1) or (D, n) over designs, or a callable (as
        :meth:`force`).  A driving torque on the crank: ``m.torque("O", "A", M)``."""
        who = f"torque({P!r}, {Q!r})"
        link = self._link(who, (P, Q))
        self._torques.append((link.index, self._load_values(who, "M", M)))
        self._cache = None

    def spring(self, P, Q, k, L0):
        """A linear spring between points P and Q: stiffness k (N/m, >= 0), free length
        L0 (m, >= 0); its force follows the positions (tension positive).  ``k``, ``L0``:
        numbers, 1-d arrays over D designs, or callables of the solve's grid (as
        :meth:`force`).  Ends that coincide at every position (two points of one link
        at one place) with k L0 > 0 make solve(need="forces") raise ValueError: such a
        force has no direction."""
        who = f"spring({P!r}, {Q!r})"
        self._known(who, P)
        self._known(who, Q)
        if P == Q:
            raise ValueError(f"{who}: a spring joins two different points")
        values = []
        for name, v in (("k", k), ("L0", L0)):
            if callable(v):
                values.append(_Load(who, name, v, lower="nonneg"))
            else:
                v = self._value(who, name, v, "nonneg")
                values.append(v[:, None] if isinstance(v, np.ndarray) else v)
        self._springs.append((self._points[P], self._points[Q], self._owner[P],
                              self._owner[Q], *values))
        self._cache = None

    def _load_values(self, who, name, value):
        if callable(value):
            return _Load(who, name, value)
        if np.ndim(value) == 0:
            return _real(who, name, value[()] if isinstance(value, np.ndarray) else value)
        a = np.asarray(value)
        if a.dtype.kind not in "fiu" or a.ndim > 2 or a.size == 0:
            raise TypeError(f"{who}: {name} must be a number, a 1-d array (one value per "
                            f"position), a 2-d array (one row per design) or a callable")
        a = a.astype(float)
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{who}: {name} must be finite")
        if a.ndim == 2:
            self._set_designs(who, name, a.shape[0])
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
              on_error="raise", points=None, links=None, out=None, t=None):
        """Solve the mechanism at the crank angles ``phi`` in one compiled call.

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad), any shape.
        omega, epsilon : float or array_like
            The crank's angular velocity (rad/s) and acceleration (rad/s^2), counter-
            clockwise positive: scalars or one value per position.
        need : {"positions", "velocities", "accelerations", "forces"}
            What to compute; what is not asked for is not computed (asking the result
            for it raises ValueError naming the ``need`` that gives it).
        gravity : float
            g (m/s^2), acting along -y; 0 by default.
        on_error : {"raise", "nan"}
            A position where a group does not assemble raises AssemblyError naming the
            group and the angle (a dead centre SingularError, a result out of the range
            of doubles RangeError; a loss of digits warns with SignificanceWarning);
            ``"nan"``: NaN there and ``r.status``.
        points : sequence of str, optional
            The joints and points whose positions, velocities and accelerations are
            stored (None: all; (): none).  Frame points are always available.
        links : sequence of link names, optional
            The links (each two joints on it, or a slider's joint) whose angle, omega and
            epsilon are stored (None: all; (): none).  The crank's angle is phi itself
            and always available.
        out : MechanismResult, optional
            A previous result of this (unchanged) mechanism with the same ``need``,
            ``points``, ``links``, phi's shape and designs: its arrays are overwritten
            with this solve's values (no new output arrays).
        t : float or array_like, optional
            Time (s) of each position, for loads that are callables of
            ``(phi, omega, t)``.

        Returns
        -------
        MechanismResult
            ``r.position(name)``, ``r.velocity``, ``r.acceleration`` (shape phi.shape +
            (2,)), ``r.angle(P, Q)``, ``r.omega``, ``r.epsilon``, ``r.reaction(joint)``,
            ``r.balancing_moment``, ``r.reduced_inertia``, ``r.reduced_moment``,
            ``r.status``; ``r.plot()``, ``r.animate(path)``, ``r.to_frame()``.  With D
            designs every array has a leading design axis: ``(D,) + phi.shape + ...``.

        Notes
        -----
        *Designs.*  Any length, coordinate, angle, offset, distance, mass, inertia,
        centre or spring value of the description may be a 1-d array of D values, one
        per design (scalars are shared by all designs; every such array has the same
        D, :attr:`designs`).  A force or torque per design is a 2-d array of shape
        (D, 1), or (D, n) with one value per position too (a 1-d force or torque is one
        value per position, shared by the designs).  The designs share phi, omega,
        epsilon, the kinds of the groups, their branches and the joint names; all of
        them are solved in one compiled call, design by design.

        *Loads.*  A force, torque or spring value may be a callable ``f(phi)``,
        ``f(phi, omega)`` or ``f(phi, omega, t)`` -- its positional parameters without
        a default say which.  It is called once per solve with 1-d arrays of the grid
        the solve uses (phi flattened, omega and t one value per position) and returns
        a number or one value per position; write it with numpy functions.  A load of
        ``t`` needs ``solve(..., t=)``.

        *Angles.*  ``r.angle`` is continuous along the positions (phi flattened in C
        order, for each design separately), its first value in (-pi, pi]; the crank's
        angle is phi as given.

        *Statuses.*  ``r.status`` 0 (OK) promises at least 8 correct significant
        digits of every result of the position (normwise: a joint's position relative
        to its link's length, the links' omegas and epsilons as the vector (w l) of the
        group relative to the larger of its norm and its driving velocity); a
        SignificanceWarning states the digits left (never too many); SingularError: no
        digit left.  The estimates are unit-free (the same at every scale 2**k) and
        allow for the rounding of coordinates far from the origin.
        tests/test_mechanism_promise.py checks this for the rrr, rrp and rpr groups:
        seeded random four-bars, offset slider-cranks and inverted slider-cranks,
        positions up to 1e-12 from a toggle, scaled by 2**k and moved, against 40-digit
        mpmath references.

        *Modes.*  The Mechanism has no as-printed mode: inside ``sarkp.as_printed()``
        it computes the corrected results (pi to double precision) and warns that it
        does; the book's routines reproduce the printed tables.
        """
        if out is None and t is None and type(phi) is float:
            # one position, the fast way: a plan an earlier solve of this need and
            # selection left (so they are known good); any other input goes the general
            # way (_solve), which raises what it raises
            tab = self._cache
            fast = None
            if tab is not None:
                try:
                    fast = tab["fast"].get((need, points, links))
                except TypeError:           # a list of names is not a key: the general way
                    pass
            if (fast is not None and type(omega) is float and type(epsilon) is float
                    and type(gravity) is float
                    # one test for the four (an overflow of the sum: the general way)
                    and math.isfinite(phi + omega + epsilon + gravity)
                    and (on_error == "raise" or on_error == "nan")
                    and MODE_CODE.get() == 0):
                level, ipk, rpk, nro, dt, pick, columns, plan, sel = fast
                rout = np.empty(nro)
                st = _SOLVE_ONE(level, ipk, rpk, phi, omega, epsilon, gravity, rout)
                rec = np.ndarray((), dt, rout)
                if not st:
                    # the fields computed and the status: views of rout (pick), in
                    # FIELDS' order with None for those not computed
                    f = pick(rec)
                    ph = np.array(phi)
                    if level == 3:
                        r = (self, columns, need, ph, f[0], f[1], f[2], f[3], f[4], f[5],
                             None, None, f[6], None, f[7])
                    elif level == 4:
                        r = (self, columns, need, ph, *f)
                    elif level == 2:
                        r = (self, columns, need, ph, f[0], f[1], None, f[2], f[3], None,
                             None, None, f[4], None, f[5])
                    else:
                        r = (self, columns, need, ph, f[0], None, None, f[1], None, None,
                             None, None, None, None, f[2])
                    return tuple.__new__(MechanismResult, r)
                if st == -1:
                    raise RuntimeError("solve: the packed tables do not add up (a bug of "
                                       "sarkp)")
                return self._result({k: rec[k] for k in plan["computed"]}, rec["status"],
                                    rec["fgroup"].reshape(1), plan, sel, need,
                                    np.array((phi,)), (), (), on_error, 4)
        elif out is None and t is None and type(phi) is np.ndarray:
            # a 1-d array of doubles, the fast way (its plan left by an earlier solve of
            # this need, selection and size): mech_solve_few checks phi is finite
            tab = self._cache
            fast = None
            if tab is not None and phi.ndim == 1 and phi.dtype == np.float64 and \
                    phi.flags.c_contiguous:
                try:
                    fast = tab["fast"].get((need, points, links, phi.size))
                except TypeError:
                    pass
            if (fast is not None and type(omega) is float and type(epsilon) is float
                    and type(gravity) is float
                    and math.isfinite(omega + epsilon + gravity)
                    and (on_error == "raise" or on_error == "nan")
                    and MODE_CODE.get() == 0):
                level, ipk, rpk, nro, dt, nio, columns, plan, sel = fast
                n = phi.size
                rout = np.empty(nro)
                iout = np.empty(nio, dtype=np.int32)
                nz = _SOLVE_FEW(level, phi, ipk, rpk, omega, epsilon, gravity, rout, iout)
                if nz >= 0:
                    rec = np.ndarray((), dt, rout)
                    res = {k: rec[k] for k in plan["computed"]}
                    phiv = phi.reshape(-1)
                    if nz:
                        return self._result(res, iout[:n], iout[n:], plan, sel, need, phiv,
                                            (n,), (), on_error, 4)
                    return MechanismResult._make((
                        self, columns, need, phiv,
                        *[None if e is False else res[k] if e is None else res[k][e]
                          for k, e in plan["views"]], iout[:n]))
        return self._solve(phi, omega, epsilon, need, gravity, on_error, points, links, out,
                           t)

    def _solve(self, phi, omega, epsilon, need, gravity, on_error, points, links, out, t):
        """solve's general way (every input checked)."""
        if self._crank is None:
            raise ValueError("solve: the mechanism has no crank (m.crank)")
        level = NEEDS.get(need) if isinstance(need, str) else None
        if level is None:
            raise ValueError(f"solve: need must be one of {list(NEEDS)}, not {need!r}")
        if on_error not in ("raise", "nan"):
            raise ValueError(f"solve: on_error must be 'raise' or 'nan', not {on_error!r}")
        if MODE_CODE.get() != 0:
            warnings.warn("Mechanism.solve has no as-printed mode: it computes the "
                          "corrected results (pi to double precision); the book's routines "
                          "reproduce the printed tables", UserWarning, stacklevel=3)
        if type(phi) is float:              # one position, quickly
            if not math.isfinite(phi):
                raise ValueError("solve: phi must be finite")
            phiv = np.array((phi,))
            shape = ()
        else:
            phi_in = np.asarray(phi)
            if phi_in.dtype.kind not in "fiu":
                raise TypeError("solve: phi must be real numbers")
            shape = phi_in.shape
            phiv = np.ascontiguousarray(phi_in, dtype=float).reshape(-1)
            if phiv.size == 0:
                raise ValueError("solve: phi is empty")
            if not np.isfinite(phiv).all():
                raise ValueError("solve: phi must be finite")
        n = phiv.size
        w, inc_w = self._per_position("omega", omega, n)
        e, inc_e = self._per_position("epsilon", epsilon, n)
        tv = None
        if t is not None:
            tv, inc_t = self._per_position("t", t, n)
            tv = np.broadcast_to(tv, (n,)) if inc_t else np.full(n, tv[0])
        g = _real("solve", "gravity", gravity)
        tab = self._tables()
        if level >= 4 and tab["rigid_springs"]:
            self._check_springs(tab, phiv[0])
        sel = self._selection(tab, points, links)
        fval, tval, spv = self._load_tables(n, phiv, w, inc_w, tv)
        D = self.designs
        lead = () if D is None else (D,)
        plan = self._plan(tab, sel, level, shape, n, lead)
        if out is None:
            # the packed entry: the description's tables in two arrays, the outputs in
            # one fresh buffer each call (the result's arrays are views of it)
            ipk, rpk = self._packed(tab, sel, n, fval, tval, spv)
            rout = np.empty(plan["nro"])
            iout = np.empty(plan["nio"], dtype=np.int32)
            _SOLVE_PACKED(level, 1 if D is None else D, ipk, rpk, phiv, w, e, inc_w, inc_e,
                          g, rout, iout)
            if (D is None and not tab["dynamic"] and plan["dt"] is not None
                    and not (level >= 4 and tab["rigid_springs"]
                             and not tab.get("springs_checked"))):
                # what the fast way of solve needs to solve this need and selection again
                # (points and links as given: a list is no key, and goes this way), for
                # a number phi or a 1-d array of this size
                key = None
                if type(phi) is float:
                    key = (need, points, links)
                    value = (level, ipk, rpk, plan["nro"] + 1, plan["dt1"], plan["pick"],
                             sel["columns"], plan, sel)
                elif type(phi) is np.ndarray and phi.ndim == 1 and inc_w == inc_e == 0:
                    key = (need, points, links, n)
                    value = (level, ipk, rpk, plan["nro"], plan["dt"], plan["nio"],
                             sel["columns"], plan, sel)
                try:
                    hash(key)
                except TypeError:
                    key = None
                if key is not None:
                    if len(tab["fast"]) > 32:
                        tab["fast"].clear()
                    tab["fast"][key] = value
            return self._finish(rout, iout, plan, sel, need,
                                phiv, shape, lead, on_error)
        shapes, computed, finals = plan["shapes"], plan["computed"], plan["finals"]
        bufs, status = self._reuse(out, need, sel, shape, lead, shapes)
        res = {k: bufs[k].T.reshape(finals[k]) for k in computed}
        fgroup = np.zeros(lead + (n,), dtype=np.int32).T
        b = bufs
        args = (tab["gi"], tab["gr"], phiv, w, e, inc_w, inc_e, tab["mlink"], tab["mpoint"],
                tab["mval"], g, tab["fpoint"], tab["flink"], fval, tab["tlink"], tval,
                tab["spp"], tab["spl"], spv, tab["powner"], tab["lbase"], tab["x0"],
                sel["outp"], sel["outl"], b["positions"], b["velocities"],
                b["accelerations"], b["directions"], b["omegas"], b["epsilons"],
                b["reactions"], b["balancing_moment"], b["reduced_inertia"],
                b["reduced_moment"], status, fgroup)
        if D is None:
            _sarkp.mechanism.mech_solve(level, *args)
        else:
            _sarkp.mechanism.mech_solve_many(level, *args)
        return self._result(res, status.T.reshape(lead + shape), fgroup.T, plan, sel, need,
                            phiv, shape, lead, on_error, 5)

    def _finish(self, rout, iout, plan, sel, need, phiv, shape, lead, on_error):
        """The result of the packed entry: the fields are views of its output buffer
        ``rout`` (the fields of a structured view of it), status and fgroup of ``iout``."""
        m = math.prod(lead + shape)
        if iout[0] == -1:
            raise RuntimeError("solve: the packed tables do not add up (a bug of sarkp)")
        if plan["dt"] is not None:
            rec = np.ndarray((), plan["dt"], rout)
            res = {k: rec[k] for k in plan["computed"]}
        else:
            res = {k: rout[a:b].reshape(final) for k, (a, b, final) in plan["spans"].items()}
        return self._result(res,
                            iout[:m].reshape(lead + shape),
                            iout[m:].reshape(lead + (phiv.size,)), plan, sel, need, phiv,
                            shape, lead, on_error, 6)

    def _result(self, res, status, fgroup, plan, sel, need, phiv, shape, lead, on_error,
                stacklevel):
        """The result of a solve: ``res`` the computed fields in their final shape,
        ``status`` (lead + shape) and ``fgroup`` (lead + (n,)) as the kernel left them.
        Raises or warns for the positions that failed or lost digits (on_error; the
        warning points ``stacklevel`` frames up, at solve's caller)."""
        if np.count_nonzero(status):
            self._settle(status.T, fgroup.T, phiv, shape, lead, on_error, stacklevel)
            bad = ~((status == 0) | (status > _ST_DIGITS))
            if bad.any():
                for k in plan["computed"]:
                    res[k][bad] = math.nan
            status[status > _ST_DIGITS] = np.int32(Status.SIGNIFICANCE)
        views = []
        for key, empty in plan["views"]:
            if empty is False:
                views.append(None)          # not asked for
            elif empty is None:
                views.append(res[key])
            else:                           # an empty choice: the stored column left out
                views.append(res[key][empty])
        return MechanismResult._make((
            self, sel["columns"], need, phiv if len(shape) == 1 else phiv.reshape(shape),
            *views, status))

    def _packed(self, tab, sel, n, fval, tval, spv):
        """The description as the packed entry takes it (fortran/mechanism.f90,
        mech_solve_packed): one integer array (per selection and whether the loads have
        a value per position) and one real array (per load tables), cached."""
        flags = (int(fval.shape[2] > 1), int(tval.shape[1] > 1), int(spv.shape[2] > 1))
        ipk = sel["ipk"].get(flags)
        if ipk is None:
            head = [tab["npt"], tab["nl"], tab["gi"].shape[1], tab["mlink"].size,
                    tab["fpoint"].size, tab["tlink"].size, tab["spp"].shape[1], tab["npair"],
                    sel["outp"].size, sel["outl"].size, *flags]
            ipk = np.concatenate([np.array(head), *(tab[k].ravel("F") for k in (
                "gi", "mlink", "mpoint", "fpoint", "flink", "tlink", "spp", "spl", "powner",
                "lbase")), sel["outp"], sel["outl"]]).astype(np.int32)
            sel["ipk"][flags] = ipk
        loads = tab["packed"]
        key = (n, id(fval), id(tval), id(spv))
        hit = loads.get(key)
        if hit is not None and hit[0] is fval and hit[1] is tval and hit[2] is spv:
            return ipk, hit[3]
        rpk = np.concatenate([a.ravel("F") for a in (tab["gr"], tab["x0"], tab["mval"], fval,
                                                     tval, spv)])
        loads.clear()
        loads[key] = (fval, tval, spv, rpk)
        return ipk, rpk

    def _plan(self, tab, sel, level, shape, n, lead):
        """What a solve of this need, selection and phi's shape allocates and returns:
        the outputs' shapes, the ones computed, how each is viewed, and the packed
        entry's output buffers: their sizes and the structured type whose fields are the
        results' arrays (cached with the selection)."""
        plans = sel["plans"]
        key = (level, shape)
        plan = plans.get(key)
        if plan is not None:
            return plan
        nop, nol, npair = len(sel["outp"]), len(sel["outl"]), tab["npair"]
        nv = n if level >= 2 else 1
        na = n if level >= 3 else 1
        nr = n if level >= 4 else 1
        shapes = {"positions": (2, nop, n), "velocities": (2, nop, nv),
                  "accelerations": (2, nop, na), "directions": (2, nol, n),
                  "omegas": (nol, nv), "epsilons": (nol, na), "reactions": (3, npair, nr),
                  "balancing_moment": (nr,), "reduced_inertia": (nv,),
                  "reduced_moment": (nr,)}
        computed = tuple(k for k in shapes if NEED_OF[k] <= level)
        tails = {"positions": (nop, 2), "velocities": (nop, 2), "accelerations": (nop, 2),
                 "directions": (nol, 2), "omegas": (nol,), "epsilons": (nol,),
                 "reactions": (npair, 3), "balancing_moment": (), "reduced_inertia": (),
                 "reduced_moment": ()}
        views = []
        finals = {}
        for k in FIELDS[4:-1]:
            if k not in computed:
                views.append((k, False))
                continue
            tail = tails[k]
            finals[k] = lead + shape + tail
            # the columns kept (0 for an empty choice, whose one stored column goes)
            kept = sel["nop"] if k in ("positions", "velocities", "accelerations") else \
                sel["nol"] if k in ("directions", "omegas", "epsilons") else None
            empty = None
            if kept == 0:
                empty = (Ellipsis, slice(0, 0), slice(None)) if len(tail) == 2 else \
                    (Ellipsis, slice(0, 0))
            views.append((k, empty))
        # the packed entry's buffer: each output whole (every design) before the next, in
        # the order of shapes; a computed one's C-ordered final shape is its Fortran
        # shape reversed, so its field of the structured type is the result's array
        width = 1 if not lead else lead[0]
        offset = 0
        fields = {"names": [], "formats": [], "offsets": []}
        for k, v in shapes.items():
            if k in computed:
                fields["names"].append(k)
                fields["formats"].append((np.float64, finals[k]))
                fields["offsets"].append(offset)
            offset += 8 * width * int(np.prod(v))
        # numpy's structured types hold at most 2**31 - 1 bytes: a larger buffer is
        # viewed field by field (spans)
        spans = {k: (o // 8, o // 8 + int(np.prod(f[1])), f[1]) for k, f, o in
                 zip(fields["names"], fields["formats"], fields["offsets"])}
        small = offset + 8 < _RECORD_LIMIT
        dt = np.dtype({**fields, "itemsize": offset}) if small else None
        # the one-position entry's buffer has one element more: its status and fgroup,
        # two 32-bit integers (mech_solve_one); there an empty choice's field is empty
        # (its stored column left out)
        for j, (k, e) in enumerate(v for v in views if v[1] is not False):
            if e is not None:
                tail = finals[k][len(lead + shape):]
                fields["formats"][j] = (np.float64, lead + shape + (0,) + tail[1:])
        fields["names"] += ["status", "fgroup"]
        fields["formats"] += [np.int32, np.int32]
        fields["offsets"] += [offset, offset + 4]
        dt1 = np.dtype({**fields, "itemsize": offset + 8}) if small else None
        plan = {"shapes": shapes, "computed": computed, "views": tuple(views),
                "finals": finals, "nro": offset // 8, "nio": 2 * n * width, "dt": dt,
                "dt1": dt1, "spans": spans,
                # the fast way's result: the computed fields and the status of dt1's
                # record (solve places them)
                "pick": operator.itemgetter(*computed, "status")}
        if len(plans) > 32:                 # many shapes of phi: keep the cache small
            plans.clear()
        plans[key] = plan
        return plan

    def _reuse(self, out, need, sel, shape, lead, shapes):
        """The Fortran-ordered arrays behind the result ``out`` (solve's ``out=``)."""
        if not isinstance(out, _MechanismBase):
            raise TypeError(f"solve: out must be a MechanismResult, not "
                            f"{type(out).__name__}")
        if out.mechanism is not self or out.columns is not sel["columns"]:
            raise ValueError("solve: out is not a result of this mechanism as it is now "
                             "with the same points= and links=")
        if out.need != need or np.shape(out.phi) != shape or \
                out.status.shape != lead + shape:
            raise ValueError(f"solve: out was solved with need={out.need!r}, phi of shape "
                             f"{np.shape(out.phi)} and status of shape {out.status.shape}; "
                             f"this solve has need={need!r}, phi of shape {shape}")
        bufs = {}
        for k, fshape in shapes.items():
            full = fshape + lead
            a = tuple.__getitem__(out, _FIELD[k])
            if a is None or a.size == 0:
                bufs[k] = np.empty(full, order="F")
                continue
            bufs[k] = a.reshape(full[::-1]).T
        n = int(np.prod(shape, dtype=int))
        status = out.status.reshape(((n,) + lead)[::-1]).T
        status.fill(0)
        return bufs, status

    def _selection(self, tab, points, links):
        """The outputs to store (solve's ``points=``, ``links=``), cached per choice."""
        if isinstance(points, str):
            points = (points,)
        if isinstance(links, str):
            links = (links,)
        try:
            key = (None if points is None else tuple(points),
                   None if links is None else tuple((lk,) if isinstance(lk, str)
                                                    else tuple(lk) for lk in links))
            hash(key)
        except TypeError:
            raise TypeError("solve: points must be a sequence of joint names and links a "
                            "sequence of links (each two joint names)") from None
        sel = tab["sel"].get(key)
        if sel is not None:
            return sel
        moving = [nm for nm in self.joints if nm not in self._fixed]
        if key[0] is None:
            chosen = moving
        else:
            chosen = []
            for nm in key[0]:
                if not isinstance(nm, str) or nm not in self._points or nm.startswith("\x00"):
                    raise ValueError(f"solve: points: unknown joint {nm!r}")
                if nm not in self._fixed and nm not in chosen:
                    chosen.append(nm)
        if key[1] is None:
            lidx = list(range(1, tab["nl"] + 1))
        else:
            lidx = []
            for spec in key[1]:
                li = self._link("solve: links", spec).index
                if li not in lidx:
                    lidx.append(li)
        columns = ({nm: j for j, nm in enumerate(chosen)},
                   {nm: xy for nm, xy in self._fixed.items()},
                   {li: j for j, li in enumerate(lidx)})
        # f2py takes no empty arrays: an empty choice stores one column (the crank's pin,
        # the crank) that the result leaves out
        pin = self._points[self._crank[0]] + 1
        sel = {"outp": np.array([self._points[nm] + 1 for nm in chosen] or [pin],
                                dtype=np.int32),
               "outl": np.array(lidx or [_CRANK], dtype=np.int32), "columns": columns,
               "nop": len(chosen), "nol": len(lidx), "plans": {}, "ipk": {}}
        tab["sel"][key] = sel
        return sel

    def _tables(self):
        """The description as Fortran tables, built once (until the next change)."""
        t = getattr(self, "_cache", None)
        if t is not None:
            return t
        npt = len(self._points)
        nl = len(self._links) - 1
        steps = self._steps
        D = self.designs
        lead = () if D is None else (D,)
        gi = np.zeros((8, len(steps)), dtype=np.int32, order="F")
        gr = np.zeros((8, len(steps)) + lead, order="F")
        for k, (kind, ints, reals, _) in enumerate(steps):
            gi[0, k] = kind
            npoints = 2 if kind == 0 else 3
            for j, v in enumerate(ints):
                # points are 1-based in Fortran; links 0-based (0 the frame)
                gi[1 + j, k] = v + 1 if j < npoints else v
            for j, v in enumerate(reals):
                gr[j, k] = v
        x0 = np.zeros((2, npt) + lead, order="F")
        for name, (x, y) in self._fixed.items():
            x0[0, self._points[name]] = x
            x0[1, self._points[name]] = y
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
        mval = np.zeros((2, len(masses)) + lead, order="F")
        for j, m in enumerate(masses):
            mval[0, j] = m[2]
            mval[1, j] = m[3]
        values = [v for f in forces for v in f[2:]] + [tq[1] for tq in torques] + \
            [v for sp in springs for v in sp[4:]]
        t = {"npt": npt, "nl": nl, "npair": len(self._pairs), "gi": gi, "gr": gr, "x0": x0,
             "powner": powner, "lbase": lbase, "sel": {}, "packed": {}, "fast": {},
             "mlink": np.array([m[0] for m in masses], dtype=np.int32),
             "mpoint": np.array([m[1] + 1 for m in masses], dtype=np.int32),
             "mval": mval,
             "spp": np.array([[s[0] + 1, s[1] + 1] for s in springs],
                             dtype=np.int32).T.copy("F"),
             "spl": np.array([[s[2], s[3]] for s in springs], dtype=np.int32).T.copy("F"),
             "forces": forces, "torques": torques, "springs": springs,
             "fpoint": np.array([f[0] + 1 for f in forces], dtype=np.int32),
             "flink": np.array([f[1] for f in forces], dtype=np.int32),
             "tlink": np.array([t[0] for t in torques], dtype=np.int32),
             "dynamic": any(isinstance(v, _Load) for v in values), "loads": {},
             "rigid_springs": [sp for sp in self._springs if self._fixed_length(sp)]}
        self._cache = t
        return t

    def _fixed_length(self, spring):
        """Whether a spring's ends are two points of one rigid link (the frame too), its
        length then the same at every position, and its force may be nonzero."""
        p, q, _, _, k, L0 = spring
        names = {i: nm for nm, i in self._points.items()}
        if not any(names[p] in lk.rigid and names[q] in lk.rigid for lk in self._links):
            return False
        return not any(not isinstance(v, _Load) and np.all(v == 0.0) for v in (k, L0))

    def _check_springs(self, tab, phi0):
        """A spring whose ends always coincide (L0 > 0) has no direction for its force
        k (0 - L0): a ValueError naming it (the kernel would drop it silently).  Checked
        at the first position solved (the ends' distance is the same at every one),
        once per description."""
        if tab.get("springs_checked"):
            return
        names = {i: nm for nm, i in self._points.items()}
        ends = [(names[p], names[q]) for p, q, *_ in tab["rigid_springs"]]
        moving = tuple({nm for e in ends for nm in e if nm not in self._fixed})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = self.solve(float(phi0), need="positions", on_error="nan", points=moving,
                           links=())
        for P, Q in ends:
            a, b = r.position(P), r.position(Q)
            if np.isnan(a).any() or np.isnan(b).any():
                return                      # not assembled here: checked at a later solve
            d = np.hypot(*np.moveaxis(a - b, -1, 0))
            size = np.maximum(np.max(np.abs(a), -1), np.max(np.abs(b), -1))
            # the same point computed two ways differs by rounding only
            if np.any(d <= 8 * np.finfo(float).eps * size):
                raise ValueError(f"spring({P!r}, {Q!r}): its ends coincide at every "
                                 f"position (two points of one rigid link at one place), "
                                 f"so its force k (0 - L0) has no direction; give it "
                                 f"L0 = 0 or join points apart")
        tab["springs_checked"] = True

    def _load_tables(self, n, phiv, w, inc_w, tv):
        """The forces', torques' and springs' values over the positions (and designs):
        (2, nf, 1 or n), (nt, 1 or n), (2, nsp, 1 or n), with a last design axis when
        the mechanism has designs.  Callables are evaluated on this solve's grid."""
        t = self._tables()
        if not t["dynamic"] and n in t["loads"]:
            return t["loads"][n]
        omega = np.broadcast_to(w, (n,)) if inc_w else np.full(n, w[0])
        grid = (phiv, omega, tv)
        D = self.designs
        width = 1 if D is None else D

        def at(who, v):
            if isinstance(v, _Load):
                return v(*grid)
            if isinstance(v, np.ndarray):
                if v.ndim == 1:
                    if v.size != n:
                        raise ValueError(f"solve: {who} has {v.size} values for {n} "
                                         f"positions")
                    return v[None, :]
                if v.shape[1] not in (1, n):
                    raise ValueError(f"solve: {who} has {v.shape[1]} values per design for "
                                     f"{n} positions")
                return v
            return np.full((1, 1), v)

        def table(rows):
            m = n if any(a.shape[1] > 1 for r in rows for a in r) else 1
            tab = np.zeros((len(rows[0]), len(rows), m, width), order="F")
            for j, r in enumerate(rows):
                for c, a in enumerate(r):
                    tab[c, j] = a.T
            return tab if D is not None else tab[..., 0]
        names = {i: nm for nm, i in self._points.items()}
        fval = table([[at(f"force at {names[p]!r}: fx", fx),
                       at(f"force at {names[p]!r}: fy", fy)]
                      for p, _, fx, fy in t["forces"]])
        tval = table([[at(f"torque on {self._links[li].label}: M", M)]
                      for li, M in t["torques"]])[0]
        spv = table([[at(f"spring at {names[p]!r}: k", k), at(f"spring at {names[p]!r}: L0",
                                                             L0)]
                     for p, _, _, _, k, L0 in t["springs"]])
        if not t["dynamic"]:
            t["loads"] = {n: (fval, tval, spv)}
        return fval, tval, spv

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

    def _step_text(self, k):
        kind, _, _, name = self._steps[k - 1]
        what = KIND_NAMES.get(kind, f"of unknown kind {kind}")
        return f"group {what} {name!r} (step {k})"

    def _settle(self, status, fgroup, phiv, shape, lead, on_error, stacklevel=3):
        """Raise for the first failed position (on_error="raise"); warn of the position
        with the fewest digits left."""
        st = status.T.reshape(-1)           # design by design, positions in C order
        fg = fgroup.T.reshape(-1)
        n = phiv.size

        def where(i):
            d, j = divmod(i, n)
            index = (d,) if lead else ()
            if shape:
                index += tuple(int(x) for x in np.unravel_index(j, shape))
            text = f"at phi = {float(phiv[j])!r}"
            if lead:
                text += f" (design {d}" + (f", index {index[1:]})" if shape else ")")
            elif shape:
                text += f" (index {index})"
            return text, (index or None)
        failed = ~((st == 0) | (st > _ST_DIGITS))
        if on_error == "raise" and failed.any():
            i = int(np.argmax(failed))
            code = int(st[i])
            text, index = where(i)
            if fg[i] < 0:               # the force step: spring -fg[i] with meeting ends
                names = {k: nm for nm, k in self._points.items()}
                p, q = self._springs[-int(fg[i]) - 1][:2]
                raise SingularError(f"the spring {names[p]!r}-{names[q]!r}: its ends meet "
                                    f"{text}, and its force k L0 has no direction there",
                                    index=index)
            what = self._step_text(int(fg[i])) if fg[i] else "the mechanism"
            if code == Status.ASSEMBLY:
                raise AssemblyError(f"{what} does not assemble {text}: the links do not "
                                    f"reach", index=index)
            if code == Status.MISSING:
                raise ValueError(f"{what}: unknown group kind (a description this "
                                 f"version cannot solve)")
            if code == Status.RANGE:
                raise RangeError(f"{what}: a result overflows {text}", index=index)
            raise SingularError(f"{what} is at a dead centre {text}: no significant "
                                f"digit of the result is left", index=index)
        lost = st > _ST_DIGITS
        if lost.any():
            i = int(np.argmin(np.where(lost, st, np.iinfo(np.int32).max)))
            digits = int(st[i]) - _ST_DIGITS
            text, index = where(i)
            warnings.warn(SignificanceWarning(
                f"{self._step_text(int(fg[i]))} is near a dead centre {text}: about "
                f"{digits} significant digits left", digits=digits, index=index),
                stacklevel=stacklevel)

    # -- chapter 8 at the mechanism level --------------------------------------------------
    def _loads(self, phi, gravity):
        r = self.solve(phi, omega=1.0, epsilon=0.0, need="forces", gravity=gravity)
        return r.reduced_inertia, r.reduced_moment

    def motion(self, phi, omega0=0.0, *, t0=0.0, omega_mean=None, gravity=0.0):
        """omega(phi) and t(phi) of the crank under the mechanism's loads (a constant
        driving torque is ``m.torque(O, A, M)``), from its J_red and M_red
        (:func:`sarkp.dynamics.motion`): from ``omega0`` at phi[0] (0: from rest), or,
        with ``omega_mean``, the steady state over one cycle (phi spanning exactly one).
        With designs (:attr:`designs`) every design from the same start, J and M from
        one solve: the fields get a leading design axis (``phi`` stays the grid)."""
        from .dynamics import motion
        J, M = self._loads(phi, gravity)
        return _each_design(lambda j, m: motion(phi, j, m, omega0=omega0, t0=t0,
                                                omega_mean=omega_mean), J, M)

    def simulate(self, t, *, phi0=0.0, omega0=0.0, gravity=0.0, rtol=1e-8,
                 branches="continuous"):
        """The motion in time under the mechanism's loads, from phi0, omega0 at t[0].

        Integrates J(phi) phi'' + J'(phi) phi'^2/2 = M(phi, omega, t) (masses,
        inertias, gravity, springs, forces, torques; loads may be callables of phi,
        omega and t) through reversals and from rest, by Gauss-Legendre
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
            "continuous": an RRR group, an RRP group (its guide on the frame or on a
            moving link) or an RPR group passing a toggle or change point takes the
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
        if self.designs is not None:
            raise ValueError(f"simulate integrates one mechanism: this one has "
                             f"{self.designs} designs (describe one design to simulate it)")
        return simulate(self, t, phi0=phi0, omega0=omega0, gravity=gravity, rtol=rtol,
                        branches=branches)

    def flywheel(self, delta, omega_mean, phi=None, *, gravity=0.0, J_constant=None):
        """The moment of inertia to add on the crank so that the steady state has the
        coefficient of speed fluctuation exactly ``delta`` (:func:`sarkp.dynamics.
        flywheel`; DMHVK's approximation beside it, the realized delta returned); phi:
        one cycle (default 361 points over 0..2 pi).  With designs, a flywheel per
        design: the fields get a leading design axis (``phi`` stays the grid)."""
        from .dynamics import flywheel
        if phi is None:
            phi = np.linspace(0.0, 2.0 * math.pi, 361)
        J, M = self._loads(phi, gravity)
        return _each_design(lambda j, m: flywheel(phi, j, m, delta=delta,
                                                  omega_mean=omega_mean,
                                                  J_constant=J_constant), J, M)


def _each_design(law, J, M):
    """``law(J, M)`` of one mechanism, or, for J and M of shape (D, n), of each design,
    stacked along a leading design axis (``phi`` shared); an error names the design."""
    if np.ndim(J) < 2:
        return law(J, M)
    runs = []
    for d in range(J.shape[0]):
        try:
            runs.append(law(J[d], M[d]))
        except SarkpError as exc:
            raise type(exc)(f"design {d}: {exc}", status=exc.status,
                            index=(d,) + (exc.index or ())) from exc
    first = runs[0]
    return type(first)(*(getattr(first, f) if f == "phi" else
                         np.stack([getattr(r, f) for r in runs]) for f in first._fields))


def _field(name, doc):
    """A result field as a documented property; a field ``need`` did not compute
    raises ValueError naming the ``need`` that gives it."""
    i = _FIELD[name]
    level = NEED_OF.get(name)

    def get(self):
        value = tuple.__getitem__(self, i)
        if value is None and level is not None:
            raise ValueError(f"{name} were not computed (need={self.need!r}): solve with "
                             f"need={_NEED_NAME[level]!r} or higher")
        return value
    get.__doc__ = doc
    get.__name__ = name
    return property(get, doc=doc)


class _MechanismBase(Result):
    """What :meth:`Mechanism.solve` returns: the arrays by joint and link name.

    Every array has the shape ``lead + phi.shape + tail``: ``lead`` is ``(D,)`` for a
    mechanism with D designs, else ``()``.  Asking for what ``need`` did not compute
    raises ValueError naming the ``need`` that gives it; asking for a joint or link that
    ``points=``/``links=`` left out raises ValueError naming what was stored.
    """

    __slots__ = ()

    mechanism = _field("mechanism", "The :class:`Mechanism` solved (its description as "
                       "it was at the solve).")
    columns = _field("columns", "Where the stored joints and links are: ({moving joint: "
                     "column}, {frame point: (x, y)}, {link index: column}).")
    need = _field("need", "What was computed: 'positions', 'velocities', "
                  "'accelerations' or 'forces'.")
    phi = _field("phi", "The crank angles (rad) as given to solve.")
    positions = _field("positions", "The stored moving joints' (x, y) (m): shape lead + "
                       "phi.shape + (points, 2); see :meth:`position`.")
    velocities = _field("velocities", "The stored joints' velocities (vx, vy) (m/s), "
                        "need >= 'velocities'; see :meth:`velocity`.")
    accelerations = _field("accelerations", "The stored joints' accelerations (ax, ay) "
                           "(m/s^2), need >= 'accelerations'; see :meth:`acceleration`.")
    directions = _field("directions", "The stored links' direction cosines and sines "
                        "(cos, sin) of their angles; see :meth:`angle`.")
    omegas = _field("omegas", "The stored links' angular velocities (rad/s, counter-"
                    "clockwise positive), need >= 'velocities'; see :meth:`omega`.")
    epsilons = _field("epsilons", "The stored links' angular accelerations (rad/s^2, "
                      "counter-clockwise positive), need >= 'accelerations'; see "
                      ":meth:`epsilon`.")
    reactions = _field("reactions", "Every pair's reaction (fx, fy) (N) and couple (N m), "
                       "need='forces'; see :meth:`reaction`.")
    balancing_moment = _field(
        "balancing_moment", "The moment (N m, counter-clockwise positive) the drive "
        "applies to the crank to keep the given motion (chapter 7's M_b), need='forces'.")
    reduced_inertia = _field(
        "reduced_inertia", "The moment of inertia reduced to the crank, J_red = sum(m "
        "|v_S|^2 + J w^2)/omega^2 (kg m^2, >= 0), need >= 'velocities'.")
    reduced_moment = _field(
        "reduced_moment", "The external loads' moment reduced to the crank, M_red = "
        "sum(F . v + M w)/omega (N m, driving positive; inertia not included), "
        "need='forces'.")
    status = _field("status", "The status of each position (sarkp.Status: 0 OK, "
                    "SIGNIFICANCE digits lost, failures with on_error='nan').")

    def _lead(self):
        st = tuple.__getitem__(self, _FIELD["status"])
        return st.shape[:st.ndim - np.ndim(tuple.__getitem__(self, _FIELD["phi"]))]

    def _repr_header(self):
        n = int(np.size(self.phi))
        failed = int(np.sum(~np.isin(self.status, (0, int(Status.SIGNIFICANCE)))))
        lead = self._lead()
        return (f"{self.mechanism!r}, need={self.need!r}, {n} positions"
                + (f", {lead[0]} designs" if lead else "")
                + (f", {failed} failed" if failed else ""))

    def __repr__(self):
        return f"MechanismResult({self._repr_header()})"

    __str__ = __repr__

    def _point(self, name, field):
        moving, fixed = self.columns[:2]
        m = self.mechanism
        if name not in moving and name not in fixed:
            if isinstance(name, str) and name in m._points and not name.startswith("\x00"):
                raise ValueError(f"joint {name!r} was not stored: this solve stored "
                                 f"points={tuple(moving)} (solve(..., points=))")
            raise ValueError(f"unknown joint {name!r}")
        a = getattr(self, field)
        if name in moving:
            return a[..., moving[name], :]
        lead = self._lead()
        shape = lead + np.shape(self.phi) + (2,)
        if field != "positions":
            return np.zeros(shape)
        x, y = fixed[name]
        xy = np.stack(np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float)), -1)
        if lead and xy.ndim > 1:                 # a frame point given per design
            xy = xy.reshape(lead + (1,) * np.ndim(self.phi) + (2,))
        return np.broadcast_to(xy, shape).copy()

    def position(self, name):
        """Cartesian (x, y) of a joint or point (m).

        Parameters
        ----------
        name : str
            A joint or point (stored by ``points=``) or a frame point.

        Returns
        -------
        numpy.ndarray
            Shape lead + phi.shape + (2,).
        """
        return self._point(name, "positions")

    def velocity(self, name):
        """Velocity (vx, vy) of a joint or point (m/s), need >= 'velocities'; shape lead
        + phi.shape + (2,) (zero at a frame point)."""
        return self._point(name, "velocities")

    def acceleration(self, name):
        """Acceleration (ax, ay) of a joint or point (m/s^2), need >= 'accelerations';
        shape lead + phi.shape + (2,) (zero at a frame point)."""
        return self._point(name, "accelerations")

    def _link(self, P, Q):
        return self.mechanism._link("result", (P,) if Q is None else (P, Q))

    def _column(self, link):
        col = self.columns[2].get(link.index)
        if col is None:
            stored = [self.mechanism._links[li].label for li in self.columns[2]]
            raise ValueError(f"link {link.label} was not stored: this solve stored "
                             f"links {stored} (solve(..., links=))")
        return col

    def angle(self, P, Q=None):
        """The direction P->Q (rad, counter-clockwise from +x) of a link named by two
        joints on it; a slider block's or a slotted link's guide direction (one joint).

        Continuous along the positions (phi flattened in C order, each design on its
        own), its first value in (-pi, pi]; the crank's angle is phi itself.  Computed
        from the link's cosine and sine when asked for.  Shape lead + phi.shape.
        """
        link = self._link(P, Q)
        lead = self._lead()
        if link.index == _CRANK and (P, Q) == link.name:
            return np.broadcast_to(np.asarray(self.phi, dtype=float),
                                   lead + np.shape(self.phi)).copy()
        d = self.directions[..., self._column(link), :]
        shape = d.shape[:-1]
        rows = np.arctan2(d[..., 1], d[..., 0]).reshape(max(1, int(np.prod(lead))), -1)
        for th in rows:
            ok = ~np.isnan(th)              # on_error="nan": unwrap across the failed ones
            th[ok] = np.unwrap(th[ok])
        th = rows.reshape(shape)
        if Q is None or link.name == (P, Q) or not self.mechanism._rigid_name(link, P, Q):
            return th
        known = set(self.columns[0]) | set(self.columns[1])
        if P not in known or Q not in known:
            raise ValueError(f"angle({P!r}, {Q!r}): the direction {P}->{Q} is a fixed angle "
                             f"off link {link.label}'s, found from their positions: store "
                             f"{P} and {Q} with points= (or ask for "
                             f"angle{link.name!r})")
        r = self.position(Q) - self.position(P)
        direct = np.arctan2(r[..., 1], r[..., 0])
        return th + np.remainder(direct - th + math.pi, 2 * math.pi) - math.pi

    def omega(self, P, Q=None):
        """Angular velocity (rad/s, counter-clockwise positive) of link P-Q (or of a
        slider's block, one joint), need >= 'velocities'; shape lead + phi.shape."""
        om = self.omegas
        return om[..., self._column(self._link(P, Q))]

    def epsilon(self, P, Q=None):
        """Angular acceleration (rad/s^2, counter-clockwise positive) of link P-Q,
        need >= 'accelerations'; shape lead + phi.shape."""
        ep = self.epsilons
        return ep[..., self._column(self._link(P, Q))]

    def _pair(self, joint, on, by):
        m = self.mechanism
        self.reactions                      # raises when need < "forces"
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
        """The force (fx, fy) (N) at a pair at ``joint``: that of link ``by`` on link
        ``on``, need='forces'; shape lead + phi.shape + (2,).

        Default: the group's link that the pair was made for (for a group's new joint B
        of kind 1, the force of link C-B's partner A-B on C-B, i.e. of link 2 on link 3;
        at an outer joint, of the earlier link on the group's link; at the crank's
        pivot, of the frame on the crank)."""
        slot, sign, _ = self._pair(joint, on, by)
        return sign * self.reactions[..., slot, :2]

    def couple(self, joint, on=None, by=None):
        """A slider pair's couple (N m, counter-clockwise positive, of ``by`` on ``on``)
        with its reaction (0 for a revolute), need='forces'."""
        slot, sign, _ = self._pair(joint, on, by)
        return sign * self.reactions[..., slot, 2]

    def _frame_columns(self):
        m = self.mechanism
        lead = self._lead()
        shape = lead + np.shape(self.phi)
        cols = {"phi": np.ravel(np.broadcast_to(self.phi, shape))}
        level = NEEDS[self.need]
        stored = [n for n in self.columns[0]]
        for name in [*self.columns[1], *stored]:
            for field, tag in (("positions", ""), ("velocities", "v"),
                               ("accelerations", "a")):
                if NEED_OF[field] <= level:
                    xy = self._point(name, field)
                    cols[f"{tag}x_{name}"] = np.ravel(xy[..., 0])
                    cols[f"{tag}y_{name}"] = np.ravel(xy[..., 1])
        for li in self.columns[2]:
            lk = m._links[li]
            label = "-".join(lk.name)
            cols[f"angle_{label}"] = np.ravel(self.angle(*lk.name))
            if level >= 2:
                cols[f"omega_{label}"] = np.ravel(self.omega(*lk.name))
            if level >= 3:
                cols[f"epsilon_{label}"] = np.ravel(self.epsilon(*lk.name))
        for f in ("balancing_moment", "reduced_inertia", "reduced_moment"):
            if NEED_OF[f] <= level:
                cols[f] = np.ravel(getattr(self, f))
        cols["status"] = np.ravel(self.status)
        return cols, shape

    # -- pictures ---------------------------------------------------------------------
    def _drawing(self, design=None):
        """(points, links, frame points) to draw: ``points`` {name: (x, y)} over the
        positions, of one design (``design``, an index) or, for ``design="all"`` or a
        sequence of indices, with a leading axis over those designs."""
        m = self.mechanism
        lead = self._lead()
        if not lead:
            if design is not None:
                raise ValueError(f"design={design!r}: this result has no designs (the "
                                 f"mechanism's values are numbers, not arrays)")
            pick = ...
        elif design is None:
            raise ValueError(f"this result has {lead[0]} designs: plot(design=i) or "
                             f"animate(path, design=i) draws design i (0 to {lead[0] - 1}); "
                             f"plot(design='all') overlays them")
        elif isinstance(design, str):
            if design != "all":
                raise ValueError(f"design must be an index, a sequence of indices or "
                                 f"'all', not {design!r}")
            pick = slice(None)
        else:
            pick = np.asarray(design)
            if pick.dtype.kind not in "iu" or pick.ndim > 1 or pick.size == 0 or not (
                    (-lead[0] <= pick) & (pick < lead[0])).all():
                raise ValueError(f"design must be an index from 0 to {lead[0] - 1}, a "
                                 f"sequence of them or 'all', not {design!r}")
            pick = int(pick) if pick.ndim == 0 else pick
        known = set(self.columns[0]) | set(self.columns[1])
        pts = {}
        for n in m.joints:
            if n in known:
                p = self.position(n)[pick]
                pts[n] = (p[..., 0], p[..., 1])
        links = []
        for lk in m._links[1:]:
            names = [n for n in lk.name if not n.startswith("\x00")]
            rigid = [n for n in lk.rigid if not n.startswith("\x00") and n not in names
                     and n in known]
            if not all(n in known for n in names):
                continue
            if len(names) == 2 and names[0] in lk.rigid and names[1] in lk.rigid:
                links.append(tuple([names[0], *rigid, names[1]]))
            elif len(names) == 2 and (names[0], names[1]) in lk.axis:
                links.append(tuple(names))
        return pts, links, list(m._fixed)

    def plot(self, position=0, *, design=None, every=None, paths=(), title="", ax=None):
        """The mechanism at one position (in colour) over the sweep (grey); returns the
        matplotlib figure (sarkp.plot.mechanism).  A result with designs draws design
        ``design`` (an index), or overlays the designs at that position
        (``design="all"`` or a sequence of indices: sarkp.plot.designs)."""
        from . import plot
        pts, links, fixed = self._drawing(design)
        # frame points that carry a link are pivots; a guide's frame point is not
        pivots = [f for f in fixed if any(f in link for link in links)]
        if self._lead() and not isinstance(design, (int, np.integer)):
            chosen = np.arange(self._lead()[0])[slice(None) if isinstance(design, str)
                                                  else np.asarray(design)]
            return plot.designs(pts, links, fixed=pivots, highlight=position, paths=paths,
                                names=[f"design {d}" for d in chosen], title=title, ax=ax)
        n = int(np.size(self.phi))
        if every is None:
            every = max(1, n // 12)
        if not title and self._lead():
            title = f"design {design} in its positions"
        return plot.mechanism(pts, links, fixed=pivots, highlight=position, every=every,
                              paths=paths, title=title, ax=ax)

    def animate(self, path, *, design=None, fps=20, every=1, paths=(), title=""):
        """An animation over the sweep written to ``path`` (.gif through Pillow, .mp4
        through ffmpeg: matplotlib's writers), each frame drawn as :meth:`plot` draws
        (the joints' names, the title, the frame pivots): sarkp.plot.animate.  A
        result with designs animates design ``design`` (an index)."""
        from . import plot
        if self._lead() and not isinstance(design, (int, np.integer)):
            raise ValueError(f"animate draws one design: this result has "
                             f"{self._lead()[0]} designs, pass design=i (0 to "
                             f"{self._lead()[0] - 1}); plot(design='all') overlays them")
        pts, links, fixed = self._drawing(design)
        pivots = [f for f in fixed if any(f in link for link in links)]
        if not title and self._lead():
            title = f"design {design} in motion"
        return plot.animate(pts, links, path, fixed=pivots, paths=paths, title=title,
                            fps=fps, every=every)

    # -- what every course asks of a linkage (sarkp.linkage; issue 27) ------------------
    def extremes(self, point=None, *, link=None, along=None):
        """The extreme positions of a point (its coordinate along ``along``: an angle,
        rad, or a vector; default the principal axis of its path, for a slider the
        guide) or of a link (``link=(P, Q)``: its angle, rad), located between the grid
        points: a :class:`sarkp.linkage.Extremes` (``low``, ``high``, the crank angles
        ``phi_low``, ``phi_high``, ``stroke = high - low``, for a point its (x, y) there)."""
        from . import linkage
        return linkage.result_extremes(self, point, link, along)

    def stroke(self, point=None, *, link=None, along=None):
        """The stroke of a point or slider (m), or a rocker's swing (``link=``, rad):
        ``extremes(...).stroke``."""
        return self.extremes(point, link=link, along=along).stroke

    def time_ratio(self, point=None, *, link=None, along=None):
        """The time ratio K >= 1 (coefficient of the change of the mean velocity) of a
        point's or a link's strokes over a full turn of the crank: the crank angle of the
        slower stroke over that of the faster one (:func:`sarkp.linkage.time_ratio`)."""
        from . import linkage
        return linkage.result_time_ratio(self, point, link, along)

    def transmission_angle(self, joint):
        """The transmission angle (rad) at the new joint of a rrr or rrp group over the
        sweep, with its worst acute value and where: a
        :class:`sarkp.linkage.Transmission` (:func:`sarkp.linkage.transmission_angle`)."""
        from . import linkage
        return linkage.transmission_angle(self, joint)


MechanismResult = result_type(
    "MechanismResult", FIELDS,
    base=_MechanismBase,
    doc="The solution of a Mechanism over its positions (Mechanism.solve).")
