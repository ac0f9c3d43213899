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
from .listings import errata, listing
from .synthesis import DSNTZ1, DSNTZ2, DSNTZ3, DSNTZK, DSNTZR
from .kinematics import (DKNMA1, DKNMA2, DKNMA3, DKNMA4, DKNMA5, DPRM1, DPRM2, DPRM3,
                         DPRM4, DPRM5, DSKOR1, DSKOR2, DSKOR3, DSKOR4, DSKOR5, DUSKR1,
                         DUSKR2, DUSKR3, DUSKR4, DUSKR5)

__version__ = "0.1.0"

__all__ = [
    "SarkpError", "AssemblyError", "SingularError", "RequirementError",
    "SignificanceWarning", "MODES", "set_mode", "get_mode", "mode", "as_printed", "GELG",
    "listing", "errata",
    # chapter 2
    "DINTGR", "DFRNCL", "DUGL1", "DUGL2", "DUGL3", "DUGL4", "DUGL5", "DUGOL", "DMOMNT",
    "DOMEGA", "DVKT", "DSMVKT",
    # chapter 3
    "DSNTZR", "DSNTZ1", "DSNTZ2", "DSNTZ3", "DSNTZK",
    # chapter 4 (DPRM5 is sarkp's extension: the book has no kind-5 positions)
    "DPRM1", "DPRM2", "DPRM3", "DPRM4", "DPRM5",
    "DSKOR1", "DSKOR2", "DSKOR3", "DSKOR4", "DSKOR5",
    "DUSKR1", "DUSKR2", "DUSKR3", "DUSKR4", "DUSKR5",
    "DKNMA1", "DKNMA2", "DKNMA3", "DKNMA4", "DKNMA5",
]
