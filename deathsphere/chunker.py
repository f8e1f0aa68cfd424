"""An outer-product grid of named axes cut into chunks of rows, in row order.

The one chunker of every streamed grid (``sweep``, ``ride``, ``ride
--steer``, ``vertical``): the grid's rows are every combination of its axes'
values, row-major (the last axis fastest), and a chunk is the rows
``first:first + rows``.  A chunk gives each axis's index at each of its rows
and, on demand, the values there; its caller takes whichever it needs (a
two-wheeler's lanes, for instance, are picked by index, as given and as
angles).  An axis is a :class:`~deathsphere.grid.Axis` (computed lazily:
a chunk of a 1e9-value axis computes only its own values) or an array.
Only one chunk is in memory at once, however large the grid.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from deathsphere.grid import grid_size


@dataclass(frozen=True, eq=False)
class GridChunk:
    """The rows ``first:stop`` of a grid: ``index[name]`` is the index into
    axis ``name`` at each row (int64, in row order)."""

    first: int
    index: dict[str, np.ndarray]
    axes: dict

    def __len__(self) -> int:
        return len(next(iter(self.index.values()))) if self.index else 0

    @property
    def stop(self) -> int:
        return self.first + len(self)

    @property
    def input_row(self) -> np.ndarray:
        """The rows' numbers in the whole grid, from 1 (a table's ``input_row``)."""
        return np.arange(self.first + 1, self.stop + 1, dtype=np.int64)

    def values(self) -> dict[str, np.ndarray]:
        """Each axis's value at each row (float64)."""
        return {name: _take(self.axes[name], i) for name, i in self.index.items()}


def _take(axis, index: np.ndarray) -> np.ndarray:
    # a lazy axis computes its values; an array is read
    if hasattr(axis, "take") and not isinstance(axis, np.ndarray):
        return axis.take(index)
    return np.asarray(axis, dtype=float).reshape(-1)[index]


def grid_chunks(axes: dict, rows: int) -> Iterator[GridChunk]:
    """The chunks of ``rows`` rows (the last may be shorter) of the outer
    product of ``axes`` (name -> :class:`~deathsphere.grid.Axis` or array),
    in row order; a caller that wants whole lines of the last axis per
    chunk asks for a multiple of its length.  An empty grid has no chunk."""
    names = list(axes)
    shape = tuple(len(axes[n]) for n in names)
    total = grid_size(axes)
    rows = max(1, int(rows))
    for first in range(0, total, rows):
        flat = np.arange(first, min(first + rows, total), dtype=np.int64)
        index = np.unravel_index(flat, shape)
        yield GridChunk(first, {n: np.asarray(i, dtype=np.int64) for n, i in zip(names, index)}, axes)
