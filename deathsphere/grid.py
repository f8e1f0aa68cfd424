"""Parsing values and ``start:stop:step`` ranges into lazy axes, and the
size of their cartesian grid (cut into chunks by :mod:`deathsphere.chunker`).

A range includes its stop when the stop falls on the grid, as a physicist
reads it: ``5:175:1`` is the 171 values 5, 6, ..., 175.  Value i is
``start + i * step`` rounded to the decimals the user wrote (so
``0.3:180:0.1`` ends at exactly 180 and steps through 0.4, 0.5, ... rather
than 0.30000000000000004 ...): inputs are echoed as given.

An axis is never materialised: it is a list of segments, and a chunk of a
grid computes only its own values (:mod:`deathsphere.chunker`).  A sweep over a 1e9-value axis therefore
runs in the memory of one chunk.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

#: A stop within this fraction of a step of the grid counts as on it.
_ON_GRID = 1e-9
#: Values one range may hold (each is computed lazily; this bounds only the
#: index arithmetic and the time a typo such as a step of 1e-300 would take).
MAX_RANGE_VALUES = 1_000_000_000
#: Orbits one grid may hold (row numbers stay exact in int64 and float64).
MAX_GRID_ROWS = 10**15


class RangeError(ValueError):
    """A value or range that cannot be parsed; the message says what is allowed."""


def parse_number(text: str, what: str) -> float:
    """A finite float from text, or :class:`RangeError` saying what is wrong."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        raise RangeError(f"{what}: {text!r} is not a number") from None
    if not math.isfinite(value):
        raise RangeError(f"{what}: {text!r} is not a finite number")
    return value


_DECIMAL = re.compile(r"^\s*[+-]?(\d*)\.?(\d*)\s*$")


def _decimals(text: str) -> int | None:
    """Digits after the point of a plain decimal (``0.25`` -> 2), None for
    exponent notation (then values are not rounded)."""
    m = _DECIMAL.match(text)
    return len(m.group(2)) if m else None


@dataclass(frozen=True)
class Segment:
    """``n`` values ``start + i * step``, rounded to ``decimals`` (None: not
    rounded), times ``scale`` (a unit's factor: the range is written, and
    rounded, in the user's unit; :mod:`deathsphere.api.arguments` converts
    with the exact factor instead)."""

    start: float
    step: float
    n: int
    decimals: int | None
    scale: float = 1.0

    def take(self, i: np.ndarray) -> np.ndarray:
        v = self.start + self.step * i.astype(float)
        v = v if self.decimals is None else np.round(v, self.decimals)
        return v if self.scale == 1.0 else v * self.scale

    @property
    def first(self) -> float:
        return float(self.take(np.zeros(1, dtype=np.int64))[0])

    @property
    def last(self) -> float:
        return float(self.take(np.array([self.n - 1], dtype=np.int64))[0])


class Axis:
    """The values of one option (repeated values and ranges, in order),
    computed on demand: ``len(axis)``, ``axis.take(indices)``; each
    segment's ``first``/``last`` via :attr:`segments`."""

    def __init__(self, segments: list[Segment]):
        self.segments = list(segments)
        self._ends = np.cumsum([s.n for s in self.segments], dtype=np.int64)

    @classmethod
    def of(cls, values) -> Axis:
        """An axis of explicit values (e.g. a default)."""
        return cls([Segment(float(v), 0.0, 1, None) for v in np.atleast_1d(values)])

    def __len__(self) -> int:
        return int(self._ends[-1]) if self.segments else 0

    def take(self, index) -> np.ndarray:
        index = np.asarray(index, dtype=np.int64)
        if len(self.segments) == 1:
            return self.segments[0].take(index)
        seg = np.searchsorted(self._ends, index, side="right")
        out = np.empty(index.shape)
        starts = self._ends - np.array([s.n for s in self.segments])
        for j in np.unique(seg):
            m = seg == j
            out[m] = self.segments[j].take(index[m] - starts[j])
        return out

    def values(self) -> np.ndarray:
        """Every value (only for axes known to be small)."""
        return self.take(np.arange(len(self)))

    def contains_zero(self) -> bool:
        """Whether some value is exactly 0 (for rates that must not be)."""
        for s in self.segments:
            if s.step == 0:
                if s.start == 0:
                    return True
                continue
            i = -s.start / s.step
            for j in {math.floor(i), math.ceil(i)}:
                if 0 <= j < s.n and s.take(np.array([j]))[0] == 0:
                    return True
        return False


def range_size(start: float, stop: float, step: float) -> float:
    """Number of values in ``start:stop:step`` (stop included when on the
    grid), as a float so that a huge count is reported, not overflowed."""
    steps = (stop - start) / step
    if not steps < 2.0 * MAX_RANGE_VALUES:  # inf (1e308 / 1e-300) or simply too many
        return math.inf
    # on the grid within 1e-9 of a step, or float64's rounding of a long quotient
    return math.floor(steps + max(_ON_GRID, 4e-16 * steps)) + 1.0


def parse_segment(text: str, what: str = "value") -> Segment:
    """One number (``60``) or a range (``5:175:1``) as a :class:`Segment`.

    Ranges need ``start <= stop`` and ``step > 0``, and hold at most
    :data:`MAX_RANGE_VALUES` values.
    """
    text = text.strip()
    if ":" not in text:
        return Segment(parse_number(text, what), 0.0, 1, None)
    parts = text.split(":")
    if len(parts) != 3:
        raise RangeError(f"{what}: range {text!r} must be start:stop:step, e.g. 5:175:1")
    start, stop, step = (parse_number(p, f"{what} range {text!r}") for p in parts)
    if step <= 0:
        raise RangeError(f"{what}: range {text!r} needs a step > 0")
    if stop < start:
        raise RangeError(f"{what}: range {text!r} is empty: stop must be >= start")
    n = range_size(start, stop, step)
    if not n <= MAX_RANGE_VALUES:
        many = "too many values" if math.isinf(n) else f"{n:.3g} values"
        raise RangeError(f"{what}: range {text!r} has {many}; at most {MAX_RANGE_VALUES:.0e} are allowed")
    digits = [_decimals(p) for p in parts]
    decimals = None if None in digits else max(digits)
    return Segment(start, step, int(n), decimals)


def parse_values(text: str, what: str = "value", max_values: int | None = None) -> np.ndarray:
    """One number or range as a float64 array (for small axes only)."""
    seg = parse_segment(text, what)
    if max_values is not None and seg.n > max_values:
        raise RangeError(f"{what}: range {text!r} has {seg.n} values, more than {max_values}")
    return Axis([seg]).values()


def parse_many(texts, what: str, max_values: int | None = None) -> np.ndarray:
    """Concatenate several values/ranges as one array (small axes only)."""
    arrays = [parse_values(t, what, max_values) for t in texts]
    return np.concatenate(arrays) if arrays else np.empty(0)


def grid_size(axes: dict) -> int:
    """Rows of the cartesian grid of ``axes``; :class:`RangeError` beyond
    :data:`MAX_GRID_ROWS` (the one place that limit is checked)."""
    total = math.prod(len(v) for v in axes.values())
    if total > MAX_GRID_ROWS:
        raise RangeError(f"the grid has {total:.3g} orbits, more than {MAX_GRID_ROWS:.0e}")
    return total
