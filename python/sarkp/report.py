"""The book's printer layouts, rendered from its FORMAT statements with fortranformat."""

from __future__ import annotations

from functools import lru_cache

from fortranformat import FortranRecordWriter


@lru_cache(maxsize=None)
def _writer(fmt: str) -> FortranRecordWriter:
    return FortranRecordWriter(fmt)


def fortran_write(fmt: str, values=()) -> str:
    """One WRITE/PRINT of ``values`` with the FORMAT ``fmt`` (e.g. ``"(1X,11F10.4)"``).

    Line-printer carriage control is not interpreted: a leading ``1X`` stays a blank.
    """
    return _writer(fmt).write(list(values))
