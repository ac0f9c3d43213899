"""sarkp: САРКП-ТММ, the FORTRAN library of Belokonev (1990), for Python."""
from . import _sarkp
