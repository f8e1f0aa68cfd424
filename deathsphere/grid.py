"""Parsing ``start:stop:step`` ranges, cartesian grids and chunking.

A range includes its stop when the stop falls on the grid, as a physicist
reads it: ``5:175:1`` is the 171 values 5, 6, ..., 175.  Values are computed
as ``start + i * step`` (no accumulated round-off).
"""

from __future__ import annotations

import math

import numpy as np

#: A stop within this fraction of a step of the grid counts as on it.
_ON_GRID = 1e-9


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


def range_size(start: float, stop: float, step: float) -> int:
    """Number of values in ``start:stop:step`` (stop included when on the grid)."""
    return int(math.floor((stop - start) / step + _ON_GRID)) + 1


def parse_values(text: str, what: str = "value", max_values: int | None = None) -> np.ndarray:
    """One number (``60``) or a range (``5:175:1``) as a float64 array.

    Ranges need ``start <= stop`` and ``step > 0``.  ``max_values`` bounds the
    size of a range (for commands that hold everything in memory).
    """
    text = text.strip()
    if ":" not in text:
        return np.array([parse_number(text, what)])
    parts = text.split(":")
    if len(parts) != 3:
        raise RangeError(f"{what}: range {text!r} must be start:stop:step, e.g. 5:175:1")
    start, stop, step = (parse_number(p, f"{what} range {text!r}") for p in parts)
    if step <= 0:
        raise RangeError(f"{what}: range {text!r} needs a step > 0")
    if stop < start:
        raise RangeError(f"{what}: range {text!r} is empty: stop must be >= start")
    n = range_size(start, stop, step)
    if max_values is not None and n > max_values:
        raise RangeError(f"{what}: range {text!r} has {n} values, more than {max_values}; use `deathsphere sweep`")
    return start + step * np.arange(n, dtype=float)


def parse_many(texts, what: str, max_values: int | None = None) -> np.ndarray:
    """Concatenate several values/ranges (a repeated option), in the order given."""
    arrays = [parse_values(t, what, max_values) for t in texts]
    return np.concatenate(arrays) if arrays else np.empty(0)


def grid_size(axes: dict[str, np.ndarray]) -> int:
    return math.prod(len(v) for v in axes.values())


def grid_chunks(axes: dict[str, np.ndarray], chunk: int):
    """Yield ``(first_row, {name: values})`` over the cartesian product of
    ``axes`` in row-major order (last axis fastest), ``chunk`` rows at a time.

    Only one chunk is in memory at once, however large the grid.
    """
    names = list(axes)
    shape = tuple(len(axes[n]) for n in names)
    total = math.prod(shape)
    for first in range(0, total, chunk):
        flat = np.arange(first, min(first + chunk, total))
        index = np.unravel_index(flat, shape)
        yield first, {n: axes[n][i] for n, i in zip(names, index)}
