"""The exceptions and warnings of sarkp.

Every failure of a book routine maps to one of these, never to a NaN or a crash:

* ``AssemblyError``: a group cannot be assembled (the links do not reach);
* ``SingularError``: a dead-centre or otherwise singular position, where the book's
  formulas have no finite answer (GELG IER = -1, a zero-length direction);
* ``RequirementError``: a synthesis requirement that no mechanism can meet;
* ``RangeError``: finite inputs whose result is not a finite double (it overflows);
* ``SignificanceWarning``: GELG reported a loss of significance (IER > 0); the result is
  kept, as the book kept it.

All errors derive from ``SarkpError``, itself a ``ValueError``, so a caller who only
knows ``ValueError`` still catches them.
"""

import enum


class SarkpError(ValueError):
    """Base class of every error a sarkp routine raises for a computed condition."""


class AssemblyError(SarkpError):
    """The links of a group do not reach: the mechanism cannot be assembled here."""


class SingularError(SarkpError):
    """A singular position (dead centre, zero-length direction): no finite answer."""


class RequirementError(SarkpError):
    """A synthesis requirement that no mechanism can meet."""


class RangeError(SarkpError):
    """Finite inputs whose result overflows double precision (or is not a number)."""


class Status(enum.IntEnum):
    """The status codes of ``on_error="nan"`` results (the ``status`` field).

    Positions with ``OK`` or ``SIGNIFICANCE`` hold the computed result; every other code
    means the outputs there are NaN, for the reason the code names.
    """

    OK = 0              #: computed
    ASSEMBLY = 1        #: the group cannot be assembled: the links do not reach
    SINGULAR = 2        #: a dead centre or another singular position: no finite answer
    SIGNIFICANCE = 3    #: computed, but digits were lost (a SignificanceWarning says how many)
    REQUIREMENT = 4     #: a synthesis requirement no mechanism meets
    MISSING = 5         #: an input was NaN (a failed earlier step of a chain)
    RANGE = 6           #: the result overflows double precision


class SignificanceWarning(UserWarning):
    """GELG reported a possible loss of significance (IER > 0); the result was kept."""
