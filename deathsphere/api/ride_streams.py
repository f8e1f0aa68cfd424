"""``ride``'s grid streamed: every combination of its axes in chunks, each
chunk evaluated by :func:`deathsphere.api.rides.ride` itself, on one or
several processes or a dask cluster, handed out in grid order as
:class:`~deathsphere.api.streams.Chunks` (``deathsphere ride --output``,
``--jobs``, ``--scheduler``; beyond the paper, docs/machine.md)."""

from __future__ import annotations

from functools import partial

import numpy as np

from deathsphere.api.arguments import (
    INF,
    TILTS_PER_SPEED,
    G,
    R,
    checked_axis,
    checked_scalar,
    refuse_large_grid,
    sphere_radius,
)
from deathsphere.records.machine_presets import as_machine
from deathsphere.api.orbits import MAX_CHUNK_ROWS
from deathsphere.api.rides import MAX_RIDE_ROWS, ride
from deathsphere.api.streams import Chunks, cluster_of, evaluated
from deathsphere.chunker import grid_chunks
from deathsphere.params import CHUNK, ParameterError
from deathsphere.table import Table


def ride_sweep(theta=None, alpha=None, *, machine, r=R, g=G, mu=INF, max_g=INF, speed=None, diameter=None,
               height=None, com_speed=None, period=None, only=None, stability: bool = True, chunk_size: int = CHUNK, jobs: int = 1,
               scheduler=None) -> Chunks:
    """Every combination of the axes, chunk by chunk: ``deathsphere ride``
    (docs/machine.md eqs. M1-M12, through :func:`deathsphere.api.ride`).

    Parameters
    ----------
    theta or height, alpha, speed, com_speed or period : float, array_like or str
        The grid's axes (units as in :func:`~deathsphere.api.ride`): a
        value, a list or array, or the command line's text, a value or a
        range ``"start:stop:step"``, or a list mixing both.  Grid order is
        theta (or height), then alpha (or the speed, the centre of mass's
        speed or the lap time) fastest; ``speed`` is the contact's, as for
        :func:`~deathsphere.api.ride`.
    machine, r, diameter, g, mu, max_g, only, stability : as for
        :func:`~deathsphere.api.ride` (r, g, mu, max_g one value each).
    chunk_size : int
        Grid points per chunk (at most 131072; a larger value is clamped).
    jobs, scheduler : as for :func:`~deathsphere.api.sweep`: local
        processes, or a dask.distributed scheduler's address or Client.

    Returns
    -------
    Chunks
        The tables of :func:`~deathsphere.api.ride` over the grid
        flattened, in grid order: together the rows, ``input_row`` the
        grid point's number from 1, that one call would give (and the same
        whatever ``chunk_size``, ``jobs`` or ``scheduler``).

    Raises
    ------
    ParameterError
        At the call, before any chunk: what :func:`~deathsphere.api.ride`
        refuses, for any value of either axis.

    Examples
    --------
    >>> import deathsphere
    >>> chunks = deathsphere.ride_sweep("60:90:30", [10, 20], machine="stunt125", chunk_size=3, stability=False)
    >>> chunks.total, [t["input_row"].tolist() for t in chunks]
    (4, [[1, 2, 3], [4]])
    """
    m = as_machine(machine)
    if (theta is None) == (height is None):
        raise ParameterError("give exactly one of theta and height (the contact's height above the floor)", "theta",
                             missing=theta is None)
    holds = {k: v for k, v in (("alpha", alpha), ("speed", speed), ("com_speed", com_speed), ("period", period))
             if v is not None}
    if len(holds) != 1:
        raise ParameterError("give exactly one of alpha, speed (the contact's), com_speed (the centre of mass's) "
                             "and period (the lap time)", list(holds)[1] if holds else "alpha", missing=not holds)
    chunk_size = min(int(checked_scalar("chunk_size", chunk_size)), MAX_CHUNK_ROWS)
    jobs = int(checked_scalar("jobs", jobs))
    where = ("theta", checked_axis("theta", theta)) if height is None else ("height", checked_axis("height", height))
    (name, values), = holds.items()
    how = (name, checked_axis(name, values))
    setup = {"r": checked_scalar("r", sphere_radius(r, diameter)), "g": checked_scalar("g", g),
             "mu": checked_scalar("mu", mu), "max_g": checked_scalar("max_g", max_g)}
    fixed = dict(machine=m, only=only, stability=stability, **setup)
    # each axis is checked whole below (held in memory once): refuse, from
    # its count alone, one longer than ride holds; the grid itself streams
    for name, values in (where, how):
        refuse_large_grid({name: len(values)}, command="ride", limit=MAX_RIDE_ROWS, param=name,
                          per_point=TILTS_PER_SPEED if how[0] != "alpha" else 1)
    # every value of each axis is checked now, by ride's own rules (a
    # height above the globe, a wheel that does not fit): along one line
    # and one column of the grid, without the stability analysis
    first = np.zeros(1, dtype=np.int64)
    for axis in (where, how):
        probe = {name: values.take(np.arange(len(values)) if name == axis[0] else first)
                 for name, values in (where, how)}
        ride(**probe, **{**fixed, "only": only, "stability": False})
    total = len(where[1]) * len(how[1])
    work = partial(_ride_chunk, **fixed)
    # a chunk's request: its axes' values (how fastest) and the grid points before it (ride numbers its rows
    # from 1 within the chunk)
    batches = ((len(chunk), {**chunk.values(), "first": chunk.first})
               for chunk in grid_chunks(dict((where, how)), chunk_size))
    return Chunks(evaluated(batches, work, jobs, cluster_of(scheduler, jobs)), total)


def _ride_chunk(request: dict, **fixed) -> Table:
    """:func:`ride` of one chunk, its ``input_row`` numbering the grid."""
    request = dict(request)
    first = request.pop("first")
    table = ride(**request, **fixed)
    columns = {name: table[name] for name in table.names}
    columns["input_row"] = np.asarray(columns["input_row"]) + first
    return Table(columns)
