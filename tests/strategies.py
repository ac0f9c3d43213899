"""Hypothesis strategies for the random generators of the tests.

The generators of tests/invariants.py and the mechanism builders of the chapter tests
are written against a small part of ``numpy.random.Generator`` (``uniform``,
``integers``, ``standard_normal``, ``random``, ``choice``), so that benchmarks/fuzz.py
can run them for a million calls from seeds.  In the tests they draw from Hypothesis
instead: ``rngs()`` gives an object with the same methods whose every number is a
Hypothesis draw, so a failing example shrinks number by number (towards 0, the lower
bound, or the first choice) and Hypothesis prints the drawn values (``inputs``) or the
calls (``rngs``), not a seed.

``inputs(gen)`` is the strategy of ``gen(rng)`` for one generator.

The example budget and the CI policy are those of the Hypothesis profile
(tests/conftest.py): explore afresh locally, derandomized under CI.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from hypothesis import strategies as st

__all__ = ["DrawnRandom", "inputs", "rngs"]

#: the range of ``standard_normal`` draws (a normal deviate beyond 6 has odds of 1e-9)
NORMAL_RANGE = 6.0
#: the number of steps of a ``uniform`` draw's grid
GRID = 2**32


class DrawnRandom:
    """The methods of ``numpy.random.Generator`` that the generators use, every number
    made from integers that Hypothesis draws: ``integer(a, b)`` returns one in [a, b]
    (``DrawnRandom.of(data.draw)`` inside a test or a composite strategy)."""

    def __init__(self, integer):
        self._int = integer

    @classmethod
    def of(cls, draw):
        """The DrawnRandom of a Hypothesis ``draw`` function (``data.draw``)."""
        return cls(lambda a, b: draw(_integers(a, b)))

    def _many(self, one, size):
        """``one()`` once, or an array of ``size`` of them."""
        if size is None:
            return one()
        shape = (size,) if np.ndim(size) == 0 else tuple(size)
        return np.array([one() for _ in range(int(np.prod(shape)))],
                        dtype=float).reshape(shape)

    def uniform(self, low=0.0, high=1.0, size=None):
        """A float in [low, high] on a grid of (high - low)/2**32: Hypothesis draws the
        grid index, so it may take either end, and shrinks towards 0 (when the interval
        holds it) or towards ``low``.  Values between grid points (1e-38 beside 1) are
        outside the generators' claimed ranges (ratios up to 1e6) and are not drawn."""
        low, high = float(low), float(high)
        step = (high - low) / GRID
        if not step > 0.0:                        # an empty or one-point interval
            return self._many(lambda: low, size)
        if low <= 0.0 <= high:
            a, b = math.ceil(low / step), math.floor(high / step)
            return self._many(lambda: min(max(self._int(a, b) * step, low), high), size)
        return self._many(lambda: min(low + self._int(0, GRID) * step, high), size)

    def random(self):
        return self.uniform(0.0, 1.0)

    def standard_normal(self, size=None):
        """A float in [-6, 6] (the grid of ``uniform``; not normally distributed: the
        generators use it for a signed value of unit scale)."""
        return self.uniform(-NORMAL_RANGE, NORMAL_RANGE, size)

    def integers(self, low, high=None, size=None):
        """An int in [low, high) (numpy's convention), or [0, low) with one bound."""
        if high is None:
            low, high = 0, low
        if size is None:
            return self._int(int(low), int(high) - 1)
        return self._many(lambda: self._int(int(low), int(high) - 1), size).astype(int)

    def choice(self, options):
        options = list(options)
        return options[self._int(0, len(options) - 1)]


@functools.lru_cache(maxsize=None)
def _integers(low, high):
    """One strategy object per range: Hypothesis draws from a known strategy fastest."""
    return st.integers(low, high)


def rngs():
    """A strategy of :class:`DrawnRandom` objects, one per example, drawing lazily (as
    the test calls them) from Hypothesis's own random source (``st.randoms``)."""
    return st.randoms(use_true_random=False).map(lambda r: DrawnRandom(r.randint))


def inputs(gen):
    """The strategy of ``gen(rng)``: a generator of tests/invariants.py as Hypothesis
    draws."""
    @st.composite
    def drawn(draw):
        return gen(DrawnRandom.of(draw))
    return drawn()
