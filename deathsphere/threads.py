"""The size of polars' thread pool in a command.  Imports nothing of the
package.

A long sweep evaluates chunks on the main thread while the compiled writer
formats the previous chunk on a thread of its own (``writers.stream``),
in polars' pool.  polars sizes that pool to every core, so on two cores
its two threads and the evaluation contend for two cores, and the
evaluation, which holds Python's lock between numpy operations, waits on
both.  A command leaves one core to the evaluation: a 1.44 M-row CSV sweep
without stability took 1.49-1.56 s with polars' default pool and
1.25-1.33 s with one thread on a 2-core machine (docs/performance.md).
"""

from __future__ import annotations

import os
import sys

#: polars reads its pool's size from this variable once, when imported.
POLARS_THREADS_VARIABLE = "POLARS_MAX_THREADS"


def leave_a_core_to_the_evaluation() -> None:
    """Size polars' pool to the cores this process may use, less one (at
    least one), unless the user has set it or polars is already imported
    (its pool is then sized).  For a command's process only: a library
    call must not change its caller's environment."""
    if POLARS_THREADS_VARIABLE in os.environ or "polars" in sys.modules:
        return
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    os.environ[POLARS_THREADS_VARIABLE] = str(max(1, cores - 1))
