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

Beside the text, each error and warning carries what a program needs to act on it:
``status`` (a :class:`Status`), ``index`` (the position of the first failure in an
array call, a tuple; ``None`` for a scalar call) and, for a ``SignificanceWarning``,
``digits`` (about how many significant digits of the result are left; ``None`` when
the routine cannot say).  They pickle with their attributes.
"""

import enum


class SarkpError(ValueError):
    """Base class of every error a sarkp routine raises for a computed condition.

    ``status``: the :class:`Status` of the failure; ``index``: the position (a tuple)
    of the first failing element of an array call, ``None`` for a scalar call.
    """

    #: the status of the class when none is given (each subclass names its own)
    default_status: "Status | None" = None

    def __init__(self, *args, status=None, index=None):
        super().__init__(*args)
        if status is None:
            status = self.default_status
        self.status = None if status is None else _status(status)
        self.index = None if index is None else tuple(int(i) for i in index)


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
    """GELG reported a possible loss of significance (IER > 0); the result was kept.

    ``digits``: about how many significant digits of the result are left (the worst
    position of an array call), or ``None`` when the routine cannot estimate it (GELG's
    IER > 0 alone); ``index``: the first position where digits were lost (``None`` for
    a scalar call); ``status``: always ``Status.SIGNIFICANCE``.
    """

    def __init__(self, *args, digits=None, index=None):
        super().__init__(*args)
        self.status = Status.SIGNIFICANCE
        self.digits = None if digits is None else int(digits)
        self.index = None if index is None else tuple(int(i) for i in index)


def _status(code):
    """``code`` as a Status (an unknown code stays an int)."""
    try:
        return Status(int(code))
    except ValueError:
        return int(code)


for _cls, _code in ((AssemblyError, Status.ASSEMBLY), (SingularError, Status.SINGULAR),
                      (RequirementError, Status.REQUIREMENT), (RangeError, Status.RANGE)):
    _cls.default_status = _code
del _cls, _code
