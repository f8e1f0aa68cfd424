"""``ride --steer``'s lanes streamed: a two-wheeler's steady turns on the
globe (or its rider's table) a few whole lanes at a time, on one or several
processes or a dask cluster, handed out in order as
:class:`~deathsphere.api.streams.Chunks` (``deathsphere ride --steer``,
``--jobs``, ``--scheduler``; beyond the paper, docs/two-wheeler.md sec. 10)."""

from __future__ import annotations

from functools import partial

import numpy as np

from deathsphere.api.arguments import INF, G, R, checked_scalar
from deathsphere.api.rides import SINGLE_CONTACT_ONLY, refuse_single_contact
from deathsphere.api.streams import Chunks, cluster_of, evaluated
from deathsphere.api.two_wheelers import TURN_CHUNK, TURN_KEYS, TurnBatch, TurnRequest, turn_request, turn_rows
from deathsphere.chunker import grid_chunks


def two_wheeler_ride_sweep(machine, *, theta=None, height=None, speed=None, steer_torque=None, steer=None, r=R,
                           diameter=None, g=G, mu=INF, max_g=INF, summary=False, stability=True, only=None,
                           surface=None, wall_angle=None, wall_height=None, profile=None, turn_radius=None,
                           chunk_size: int = TURN_CHUNK, jobs: int = 1, scheduler=None, **single_contact) -> Chunks:
    """Every steady turn of a two-wheeler at each lane and rear speed (or
    steer torque), or with ``summary`` its rider's table, lane after lane:
    ``deathsphere ride --steer`` (docs/two-wheeler.md sec. 10, through
    :func:`~deathsphere.api.two_wheelers.turn_rows`).

    The arguments are those of :func:`deathsphere.ride` for a two-wheeler;
    ``chunk_size`` the lanes x speeds per chunk (whole lanes, at least one),
    ``jobs`` and ``scheduler`` as for :func:`~deathsphere.api.sweep`.  What
    only the single-contact machine takes (``alpha``,
    ``vertical``, the machine's overrides ...) is refused by name.

    Returns
    -------
    Chunks
        The rows of every lane with every speed (or torque), their outer
        product in row order, the speeds fastest, as the command line's
        options give them: together those of one :func:`deathsphere.ride`
        call with a column of lanes and a row of speeds (the API
        broadcasts), the same whatever ``chunk_size``, ``jobs`` or
        ``scheduler``; up to MAX_STREAMED_LANES lanes of MAX_TURN_REQUESTS
        speeds each rather than MAX_TURN_REQUESTS requests.

    Raises
    ------
    ParameterError
        At the call, before any chunk: every value checked.

    Examples
    --------
    A chunk holds whole lanes, so one lane is one chunk however small ``chunk_size``:

    >>> from deathsphere.api.two_wheeler_streams import two_wheeler_ride_sweep
    >>> chunks = two_wheeler_ride_sweep("benchmark-bicycle", steer="free", theta=100, speed=[8, 9],
    ...                                 diameter="16ft", stability=False, chunk_size=1)
    >>> chunks.total, [t["input_row"].tolist() for t in chunks]
    (2, [[1, 2]])
    """
    unknown = sorted(set(single_contact) - set(SINGLE_CONTACT_ONLY))
    if unknown:
        raise TypeError(f"two_wheeler_ride_sweep() got an unexpected keyword argument {unknown[0]!r}")
    refuse_single_contact(single_contact)
    typed = {key: value for key, value in locals().items() if key in TURN_KEYS}   # the keywords, as typed
    request = turn_request(machine, typed, streamed=True)
    chunk_size = int(checked_scalar("chunk_size", chunk_size))
    jobs = int(checked_scalar("jobs", jobs))
    width = request.values.size
    # whole lanes per chunk: a lane's lean curve is found once, and its rider's table row sees all its speeds
    rows = max(1, chunk_size // max(1, width)) * max(1, width)
    return Chunks(evaluated(_batches(request, rows), partial(turn_rows, request), jobs, cluster_of(scheduler, jobs)),
                  request.total)


def _batches(request: TurnRequest, rows: int):
    """``(requests, batch)`` per chunk of ``rows`` requests of the lanes x
    values, in row order (:func:`deathsphere.chunker.grid_chunks`)."""
    lanes, given = request.lanes.reshape(-1), request.lanes_given.reshape(-1)
    if request.total == 0:
        # nothing asked for: one empty table, so that the output still has its columns
        empty = np.empty(0, dtype=np.int64)
        yield 0, TurnBatch(lane=lanes[empty], given=given[empty], value=request.values[empty], first=0, group=empty)
        return
    for chunk in grid_chunks({"lane": lanes, "value": request.values}, rows):
        lane = chunk.index["lane"]
        yield len(chunk), TurnBatch(lane=lanes[lane], given=given[lane], value=request.values[chunk.index["value"]],
                                    first=chunk.first, group=lane - lane[0])
