"""sarkp: the САРКП-ТММ library of Belokonev (1990) for Python.

Every routine of the book's Table 33 is exported under its book name, with the book's
argument order: ``from sarkp import DVKT``.  See ``help(sarkp.DVKT)``.
"""

from . import cams, dynamics, forces, gears, kinematics, operators, solver, synthesis
from .errors import (AssemblyError, RangeError, RequirementError, SarkpError,
                     SignificanceWarning, SingularError, Status)
from .modes import MODES, as_printed, get_mode, mode, set_mode
from .listings import errata, listing     # the book's code and its errata
from .operators import *      # noqa: F401,F403  chapter 2
from .solver import *         # noqa: F401,F403  GELG
from .synthesis import *      # noqa: F401,F403  chapter 3
from .kinematics import *     # noqa: F401,F403  chapter 4
from .cams import *           # noqa: F401,F403  chapter 5
from .gears import *          # noqa: F401,F403  chapter 6
from .forces import *         # noqa: F401,F403  chapter 7 (DUGL6: sarkp's extension)
from .dynamics import *       # noqa: F401,F403  chapter 8
from .mechanism import Mechanism, MechanismResult   # a whole mechanism (issue 19)

__version__ = "0.1.0"

#: Submodules imported on first use, as attributes (``sarkp.printed.DPRM1``, ``sarkp.plot``):
#: the printed code connects Fortran units when imported, plot needs matplotlib only when
#: it draws, and linkage is plain NumPy.
_LAZY = ("printed", "plot", "linkage")


def __getattr__(name):
    if name in _LAZY:
        import importlib
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'sarkp' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_LAZY))

__all__ = [
    "SarkpError", "AssemblyError", "SingularError", "RequirementError", "RangeError",
    "SignificanceWarning", "Status", "MODES", "set_mode", "get_mode", "mode", "as_printed",
    "listing", "errata", "Mechanism", "MechanismResult",
    *solver.__all__, *operators.__all__, *synthesis.__all__, *kinematics.__all__,
    *cams.__all__, *gears.__all__,
    *forces.__all__, *dynamics.__all__,
]
