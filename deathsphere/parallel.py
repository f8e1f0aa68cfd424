"""Ordered parallel map over processes, with bounded memory.

:func:`ordered_map` evaluates ``work(item)`` for a stream of items on a pool
of processes and hands the results back in input order, so that a caller's
output is the same as with one process.  The items are drawn lazily and at
most two per process are in flight: enough to keep every process busy while
the caller consumes (writes) results, and memory stays flat however long the
stream.  Leaving the loop early (a reader gone, a failed write, Ctrl-C)
cancels the work still queued.  A dask.distributed cluster is one more
pool for the same loop (:class:`deathsphere.cluster.ClusterPool`).
"""

from __future__ import annotations

from collections import deque
from typing import Callable, Iterable, Iterator, TypeVar

T = TypeVar("T")
R = TypeVar("R")


def ordered_map(work: Callable[[T], R], items: Iterable[T], jobs: int, client=None,
                close: bool = False) -> Iterator[R]:
    """``work(item)`` for each item, in input order, on ``jobs`` processes
    (or, given a ``distributed.Client``, on its cluster:
    :class:`deathsphere.cluster.ClusterPool`, which ``close`` is passed to).

    ``work`` and the items must be picklable (a module-level function and
    plain data); each item's result is computed exactly as in one process.
    With ``jobs`` <= 1 and no client the items are evaluated here, one at a
    time, without a pool.  At most ``pool.ahead`` items (two per process or
    worker) are submitted ahead of the one being handed back; closing the
    generator early drops the queued ones before it returns.
    """
    if client is None and jobs <= 1:
        for item in items:
            yield work(item)
        return
    if client is not None:
        from deathsphere.cluster import ClusterPool

        pool = ClusterPool(work, client, close=close)
    else:
        pool = ProcessPool(work, jobs)
    pending = deque()
    try:
        for item in items:
            pending.append(pool.submit(item))
            if len(pending) >= pool.ahead:
                yield pending.popleft().result()
        while pending:
            yield pending.popleft().result()
    finally:
        # a reader gone (`| head`), a failed write or Ctrl-C: drop queued work
        pool.stop(pending)


class ProcessPool:
    """Local processes for :func:`ordered_map`: two items in flight per process."""

    def __init__(self, work: Callable, jobs: int):
        from concurrent.futures import ProcessPoolExecutor

        self.work, self.ahead = work, 2 * jobs
        self.pool = ProcessPoolExecutor(jobs, initializer=_leave_stops_to_the_caller)

    def submit(self, item):
        return self.pool.submit(self.work, item)

    def stop(self, pending) -> None:
        """Queued items are dropped, running ones finish."""
        self.pool.shutdown(wait=True, cancel_futures=True)


def _leave_stops_to_the_caller() -> None:
    """In a worker: Ctrl-C (which the terminal sends to every process of the
    group) and SIGTERM sent to the group are the caller's to act on: it
    stops the pool itself, the chunk in hand finished.  A worker that raised
    KeyboardInterrupt or inherited the caller's SIGTERM handler would print
    a traceback each; one that died of SIGTERM would leave the pool's
    shutdown waiting for it."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)

