"""Streamed results: requests in chunks (a grid or an input file), evaluated
on one or several processes, handed out as :class:`Chunks` in order."""

from __future__ import annotations

import os
from collections import deque
from collections.abc import Iterator

import numpy as np

from deathsphere.chunker import grid_chunks
from deathsphere.model import (
    evaluate,
)
from deathsphere.params import ParameterError
from deathsphere.table import Table


class Chunks:
    """The tables of a streamed result, one per chunk of requests, in order:
    an iterator (``for table in chunks``) that knows how far it has got.

    ``total`` is the number of requests (grid points; None when they are
    read from a file as they come) and ``done`` the number evaluated so far
    (the command line's progress bar).  :meth:`table` joins what is left
    into one :class:`Table` (small results only)."""

    def __init__(self, pairs: Iterator[tuple[int, Table]], total: int | None = None):
        self._pairs = iter(pairs)
        self.total = total
        self.done = 0

    def __iter__(self) -> Chunks:
        return self

    def __next__(self) -> Table:
        n, table = next(self._pairs)
        self.done += n
        return table

    def table(self) -> Table:
        """Every remaining chunk as one table."""
        return Table.concat(self)

    def to_arrow(self):
        """Every remaining chunk as one ``pyarrow.Table``, converted chunk by
        chunk (never the whole result as numpy and Arrow at once); the
        types of :meth:`Table.to_arrow`, fixed by the first chunk."""
        from deathsphere.table import frames

        return frames.arrow_concat(self, "Chunks.to_arrow")[0]

    def to_polars(self):
        """Every remaining chunk as one ``polars.DataFrame`` (through :meth:`to_arrow`)."""
        from deathsphere.table import frames

        frames.require("polars", "Chunks.to_polars")
        return frames.polars_frame(frames.arrow_concat(self, "Chunks.to_polars")[0], "Chunks.to_polars")

    def to_pandas(self):
        """Every remaining chunk as one ``pandas.DataFrame`` (through
        :meth:`to_arrow`; the types of :meth:`Table.to_pandas`)."""
        from deathsphere.table import frames

        frames.require("pandas", "Chunks.to_pandas")
        arrow, first = frames.arrow_concat(self, "Chunks.to_pandas")
        return frames.pandas_frame(arrow, first, "Chunks.to_pandas")


def grid_requests(axes: dict, chunk_size: int, make, fixed: dict) -> Iterator[tuple[int, dict]]:
    """``(n, requests)`` per chunk of the grid of ``axes``, numbered from 1 in
    grid order (last axis fastest), cut by :func:`deathsphere.chunker.grid_chunks`
    (``make`` builds a chunk's request from its axes' values and ``input_row``)."""
    for chunk in grid_chunks(axes, chunk_size):
        yield len(chunk), make(len(chunk), input_row=chunk.input_row, **fixed, **chunk.values())


def evaluated(batches, work, jobs: int = 1, cluster=None) -> Iterator[tuple[int, Table]]:
    """``(n, work(requests))`` per batch, in order; on ``jobs`` processes if
    > 1, or on a dask cluster: ``cluster`` is ``(client, own)`` from
    :func:`deathsphere.cluster.connect` (``own``: close it at the end)."""
    if jobs == 1 and cluster is None:
        for n, req in batches:
            yield n, work(req)
        return
    from deathsphere.parallel import ordered_map

    counts = deque()

    def requests():
        for n, req in batches:
            counts.append(n)
            yield req

    client, own = cluster if cluster is not None else (None, False)
    for table in ordered_map(work, requests(), jobs, client=client, close=own):
        yield counts.popleft(), table


def evaluate_filtered(req: dict, stability: bool, keep=None) -> Table:
    """Horizontal orbits of a request batch, keeping only the statuses ``keep``."""
    table = evaluate(req, stability=stability)
    if keep is not None:
        table = table[np.isin(table["status"], keep)]
    return table


def cluster_of(scheduler, jobs: int):
    """``(client, own)`` for the API's ``scheduler`` argument (None: a
    local run), connected now, so that a missing extra or an unreachable
    scheduler fails before any work."""
    if scheduler is None:
        return None
    if jobs != 1:
        raise ParameterError("give jobs (local processes) or a scheduler (a dask cluster), not both", "scheduler")
    from deathsphere.cluster import connect

    return connect(scheduler)


def input_requests(reader, chunk_size: int, make) -> Iterator[tuple[int, dict]]:
    """``(n, requests)`` per chunk of an input file's rows; a file with a
    header and no rows gives one empty batch, so that the output still has
    its header."""
    empty = True
    for part in reader.chunks(chunk_size):
        empty = False
        n = len(part.input_row)
        yield n, make(n, invalid=part.invalid, input_row=part.input_row, **part.values)
    if empty:
        yield 0, make(0, **{name: np.empty(0, dtype=object if name in ("body", "side") else float)
                            for name in reader.fields})


def request_reader(source, fields: dict, overrides: dict, echo: dict, columns, ignore_when=None):
    """A streaming reader of the request CSV ``source`` (a path, or ``"-"``
    for standard input).  ``overrides`` are the options given with it,
    applied to every row over the file's columns.  ``echo`` maps the output
    columns that echo an input back to that input, so that a result CSV can
    be fed back; every other output column in ``columns`` is read and
    ignored (``ignore_when``: see :class:`~deathsphere.inputs.RequestReader`)."""
    from deathsphere.inputs import InputError, RequestReader, open_input

    name = "stdin" if source == "-" else os.fspath(source)
    try:
        return RequestReader(open_input(os.fspath(source)), fields, overrides, source=name, aliases=echo,
                             ignore=[c for c in columns if c not in echo], ignore_when=ignore_when)
    except InputError as exc:
        raise ParameterError(str(exc), "input") from None
