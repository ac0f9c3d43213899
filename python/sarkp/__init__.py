"""sarkp: the САРКП-ТММ library of Belokonev (1990) for Python.

Every routine of the book's Table 33 is exported under its book name, with the book's
argument order: ``from sarkp import DVKT``.  See ``help(sarkp.DVKT)``.
"""

from .errors import (AssemblyError, RequirementError, SarkpError, SignificanceWarning,
                     SingularError)
from .modes import MODES, as_printed, get_mode, mode, set_mode
from .operators import (DFRNCL, DINTGR, DMOMNT, DOMEGA, DSMVKT, DUGL1, DUGL2, DUGL3,
                        DUGL4, DUGL5, DUGOL, DVKT)
from .solver import GELG
from .synthesis import DSNTZ1, DSNTZ2, DSNTZ3, DSNTZK, DSNTZR

__version__ = "0.1.0"

__all__ = [
    "SarkpError", "AssemblyError", "SingularError", "RequirementError",
    "SignificanceWarning", "MODES", "set_mode", "get_mode", "mode", "as_printed", "GELG",
    # chapter 2
    "DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL", "DMOMNT",
    "DOMEGA", "DVKT", "DSMVKT",
    # chapter 3
    "DSNTZR", "DSNTZ1", "DSNTZ2", "DSNTZ3", "DSNTZK",
]
