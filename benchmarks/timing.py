"""The one timer of the benchmarks: the best wall time of a few calls (the
least disturbed by a shared machine's other work)."""

import time


def best_of(fn, repeat, before=None):
    """The least wall time [s] of ``repeat`` calls of ``fn()``; ``before()``
    (untimed) runs ahead of each, e.g. to drop a cache."""
    best = float("inf")
    for _ in range(repeat):
        if before is not None:
            before()
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best
