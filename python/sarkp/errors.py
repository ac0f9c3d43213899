"""The exceptions and warnings of sarkp.

Every failure of a book routine maps to one of these, never to a NaN or a crash:

* ``AssemblyError``: a group cannot be assembled (the links do not reach);
* ``SingularError``: a dead-centre or otherwise singular position, where the book's
  formulas have no finite answer (GELG IER = -1, a zero-length direction);
* ``RequirementError``: a synthesis requirement that no mechanism can meet;
* ``SignificanceWarning``: GELG reported a loss of significance (IER > 0); the result is
  kept, as the book kept it.

All errors derive from ``SarkpError``, itself a ``ValueError``, so a caller who only
knows ``ValueError`` still catches them.
"""


class SarkpError(ValueError):
    """Base class of every error a sarkp routine raises for a computed condition."""


class AssemblyError(SarkpError):
    """The links of a group do not reach: the mechanism cannot be assembled here."""


class SingularError(SarkpError):
    """A singular position (dead centre, zero-length direction): no finite answer."""


class RequirementError(SarkpError):
    """A synthesis requirement that no mechanism can meet."""


class SignificanceWarning(UserWarning):
    """GELG reported a possible loss of significance (IER > 0); the result was kept."""
