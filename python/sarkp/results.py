"""The result objects of sarkp.

Every book routine returns a :class:`Result`: a named tuple with the book's output
names in the book's order (``r.FI2``, ``fi2, fi3, xb, yb = r``, ``r[0]``, ``r._fields``,
``r._asdict()``, ``r._replace(...)`` all work as for :func:`collections.namedtuple`),
which also

* pickles, scalar or array, so multiprocessing, joblib and dask can return it (the class
  is rebuilt from its name, fields and base on unpickling; it need not be importable,
  and an instance of a further subclass comes back as its result class);
* prints short: arrays show their shape and a few values, not every position;
* converts to a pandas DataFrame with :meth:`Result.to_frame` (pandas is optional:
  ``pip install 'sarkp[frame]'``).

The small API for other result kinds (a :class:`sarkp.Mechanism` solution, say):

``result_type(name, fields, *, base=Result, doc=None)``
    The class of results called ``name`` with the given fields, made once and cached
    (the same ``(name, fields, base)`` gives the same class).  ``base`` may be a
    subclass of :class:`Result` that adds methods or properties (it must define
    ``__slots__ = ()`` and be importable by its module and name, so that pickle finds
    it); its results pickle, print and convert like the book's.

Hooks a subclass may override: ``_repr_header()`` (the text before the fields) and
``_frame_columns()`` (the ``({column: flat values}, shape)`` that :meth:`Result.to_frame`
uses).
"""

from __future__ import annotations

import importlib
import keyword
from collections import namedtuple
from typing import Any, Iterable

import numpy as np

__all__ = ["Result", "result_type"]

#: how many values of an array the repr shows at each end
_EDGE = 3


class Result(tuple):
    """Base of every sarkp result: a named tuple that pickles, prints short and converts
    to a DataFrame.  Make result classes with :func:`result_type`, not by hand."""

    __slots__ = ()

    # -- printing -----------------------------------------------------------------------
    def _repr_header(self) -> str:
        shapes = {np.shape(v) for v in self}
        shapes.discard(())
        if len(shapes) == 1:
            return f"shape {shapes.pop()}"
        return ""

    def __repr__(self) -> str:
        name = type(self).__name__
        if not any(isinstance(v, np.ndarray) and v.ndim for v in self):
            # scalars: exactly what a namedtuple prints
            return f"{name}({', '.join(f'{f}={v!r}' for f, v in zip(self._fields, self))})"
        shapes = {np.shape(v) for v in self} - {()}
        shape = shapes.pop() if len(shapes) == 1 else None
        head = self._repr_header()
        items = [head] if head else []
        items += [f"{f}={_short(v, shape)}" for f, v in zip(self._fields, self)]
        return f"{name}(" + ",\n    ".join(items) + ")"

    __str__ = __repr__

    # -- pickling -----------------------------------------------------------------------
    def __reduce__(self):
        cls = type(self)
        return (_rebuild, (cls._result_name, self._fields, _where(cls._result_base),
                           tuple(self)))

    # -- pandas -------------------------------------------------------------------------
    def _frame_columns(self) -> tuple[dict[str, Any], tuple[int, ...]]:
        """``({column: flat values}, position shape)`` for :meth:`to_frame`: every
        field, broadcast to one shape."""
        values = [np.asarray(v) for v in self]
        try:
            shape = np.broadcast_shapes(*(v.shape for v in values))
        except ValueError:
            raise ValueError(
                f"{type(self).__name__}: the fields do not share one shape ("
                + ", ".join(f"{f} {v.shape}" for f, v in zip(self._fields, values))
                + "); select fields of one shape, e.g. pandas.DataFrame({'A': r.A})"
            ) from None
        return {f: np.broadcast_to(v, shape).ravel() if shape else v.reshape(1)
                for f, v in zip(self._fields, values)}, shape

    def to_frame(self):
        """A ``pandas.DataFrame`` with a column per field (in the book's order) and a
        row per position: one row for a scalar result; for arrays of shape ``(n,)`` the
        index 0..n-1; for more dimensions a MultiIndex of the position.  A field of a
        smaller shape (a scalar among arrays) is repeated along the rows.  The ``status``
        field, when present, is an integer column.

        Raises ImportError when pandas is not installed (``pip install 'sarkp[frame]'``),
        ValueError when the fields do not broadcast to one shape.
        """
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("Result.to_frame needs pandas, an optional dependency of "
                              "sarkp: pip install 'sarkp[frame]' (or pip install "
                              "pandas)") from None
        columns, shape = self._frame_columns()
        if len(shape) > 1:
            index = pd.MultiIndex.from_product([range(n) for n in shape],
                                               names=[f"i{k}" for k in range(len(shape))])
        else:
            index = None
        return pd.DataFrame(columns, index=index)


def _short(v, shape=None) -> str:
    """A value as the repr shows it: scalars in full; arrays as their first and last
    few values (6 significant digits), with their shape when it is not ``shape``."""
    if not isinstance(v, np.ndarray) or v.ndim == 0:
        return repr(v)
    flat = v.ravel()
    if flat.size > 2 * _EDGE:
        parts = [_number(x) for x in flat[:_EDGE]] + ["..."] + \
            [_number(x) for x in flat[-_EDGE:]]
    else:
        parts = [_number(x) for x in flat]
    text = "[" + ", ".join(parts) + "]"
    return text if v.shape == shape else f"{text} (shape {v.shape})"


def _number(x) -> str:
    if isinstance(x, (np.integer, np.bool_)):
        return str(x)
    return f"{float(x):.6g}"


def _where(base: type) -> tuple[str, str]:
    return base.__module__, base.__qualname__


def _rebuild(name: str, fields: tuple[str, ...], base: tuple[str, str], values: tuple):
    """Unpickle a result: its class from (name, fields, base), then the values."""
    module, qualname = base
    cls: Any = importlib.import_module(module)
    for part in qualname.split("."):
        cls = getattr(cls, part)
    return result_type(name, fields, base=cls)._make(values)


_TYPES: dict[tuple[str, tuple[str, ...], type], type] = {}


def result_type(name: str, fields: Iterable[str], *, base: type = Result,
                doc: str | None = None) -> type:
    """The result class ``name`` with ``fields`` (a named tuple on ``base``), made once.

    ``fields`` are identifiers not starting with an underscore (the book's output names
    are).  ``base`` is :class:`Result` or an importable subclass of it with
    ``__slots__ = ()``.
    """
    fields = tuple(fields)
    if not (isinstance(base, type) and issubclass(base, Result)):
        raise TypeError(f"result_type: base must be a subclass of sarkp.results.Result, "
                        f"not {base!r}")
    bad = [f for f in fields if not f.isidentifier() or keyword.iskeyword(f)
           or f.startswith("_")]
    if bad:
        raise ValueError(f"result_type: {name}: fields {bad} are not valid field names")
    key = (name, fields, base)
    cls = _TYPES.get(key)
    if cls is None:
        plain = namedtuple(name, fields)
        cls = type(name, (base, plain), {
            "__slots__": (),
            "_fields": fields,
            "_result_name": name,
            "_result_base": base,
            "__doc__": doc or f"The result of {name}: {', '.join(fields)}.",
            "__module__": __name__,
        })
        _TYPES[key] = cls
    return cls

