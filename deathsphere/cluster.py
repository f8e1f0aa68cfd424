"""Chunks on a dask.distributed cluster: ``--scheduler ADDRESS`` and the
API's ``scheduler=`` (the optional ``distributed`` extra:
``pip install 'deathsphere[distributed]'``).

The cluster is only a place to evaluate chunks: the requests are built
here, each chunk is one task, and the results come back here in submission
order and are written by this process, so the output is that of a local
run, byte for byte.  At most :data:`AHEAD_PER_WORKER` chunks per worker are
in flight: enough to keep every worker busy while this process writes, and
memory stays that of a few chunks however long the grid.

Nothing here imports dask until a scheduler is asked for: distributed takes
about a second to import, which no local command should pay.
"""

from __future__ import annotations

from typing import Callable

from deathsphere.errors import ParameterError
from deathsphere.memory import reuse_freed_memory

#: The line a run asking for a cluster gets when the extra is missing.
EXTRA_MISSING = "--scheduler needs dask.distributed: pip install 'deathsphere[distributed]'"
#: Seconds to reach the scheduler before giving up: a wrong address should
#: fail within a few seconds, not hang the command.
CONNECT_TIMEOUT_S = 5
#: Chunks submitted ahead per worker.  Two keep a worker busy while its last
#: result travels back; more would only hold memory on this side.
AHEAD_PER_WORKER = 2


def connect(scheduler, timeout: float | None = None):
    """``(client, own)``: a :class:`distributed.Client` for ``scheduler`` (an
    address such as ``tcp://host:8786``, or a Client, used as it is) and
    whether this call opened it (and so must close it).  Raises
    :class:`ParameterError` (param ``scheduler``) when the extra is missing
    or the scheduler cannot be reached within ``timeout`` seconds: before
    any work (``timeout`` None: :data:`CONNECT_TIMEOUT_S`)."""
    try:
        from distributed import Client
    except ImportError:
        raise ParameterError(EXTRA_MISSING, "scheduler") from None
    timeout = CONNECT_TIMEOUT_S if timeout is None else timeout

    if isinstance(scheduler, Client):
        return scheduler, False
    if not isinstance(scheduler, str) or not scheduler.strip():
        raise ParameterError(f"scheduler must be an address such as tcp://host:8786 or a distributed.Client "
                             f"(got {scheduler!r})", "scheduler")
    try:
        client = Client(scheduler.strip(), timeout=timeout, set_as_default=False)
    except Exception as exc:  # OSError, TimeoutError, a malformed address: one line, no traceback
        _abandon(exc, Client)
        raise ParameterError(_unreachable(scheduler, timeout, exc), "scheduler") from None
    return client, True


def _unreachable(scheduler: str, timeout: float, exc: BaseException) -> str:
    """Why the scheduler at ``scheduler`` was not reached, in one line."""
    words = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    if isinstance(exc, MemoryError):  # a service that is not a scheduler answered with bytes read as a length
        return f"{scheduler!r} answered, but not as a dask scheduler does (is it the scheduler's port?)"
    if isinstance(exc, ValueError):  # distributed's parser: no port, an unknown scheme
        return f"{scheduler!r} is not a scheduler address such as tcp://host:8786: {words}"
    return f"cannot reach the dask scheduler at {scheduler!r} within {timeout:g} s: {words}"


def _abandon(exc: BaseException, client_type) -> None:
    """Stop the Client a failed constructor left half built.  Found in the
    traceback's frames, it would otherwise be closed by its ``__del__`` at
    exit, which waits for a scheduler that never answered (10 s) and then
    prints an "Exception ignored" traceback after the one-line error."""
    tb = exc.__traceback__
    while tb is not None:
        half = tb.tb_frame.f_locals.get("self")
        if isinstance(half, client_type):
            half.status = "closed"  # its close() (and so __del__) is then a no-op
            try:
                half._loop_runner.stop()
            except Exception:  # an internal of distributed: the exit goes on without it
                pass
        tb = tb.tb_next


def workers(client) -> int:
    """Workers the scheduler knows now (at least 1: more may join later)."""
    try:
        return max(1, len(client.scheduler_info().get("workers", {})))
    except Exception:
        return 1


class OnWorker:
    """``work`` as a task: the first call in a worker process first sets its
    malloc thresholds (:func:`deathsphere.memory.reuse_freed_memory`)."""

    _ready = False  # per process: a class attribute of the worker's copy of the module

    def __init__(self, work: Callable):
        self.work = work

    def __call__(self, item):
        if not OnWorker._ready:
            reuse_freed_memory()
            OnWorker._ready = True
        return self.work(item)


class ClusterPool:
    """The cluster of ``client`` as a pool for
    :func:`deathsphere.parallel.ordered_map`: each item one task,
    :data:`AHEAD_PER_WORKER` per worker in flight; ``close`` closes the
    client when the map ends."""

    def __init__(self, work: Callable, client, close: bool = False):
        self.work, self.client, self.close = OnWorker(work), client, close
        self.ahead = AHEAD_PER_WORKER * workers(client)

    def submit(self, item):
        # pure=False: two equal chunks are two tasks (dask would otherwise
        # hash the requests to decide, which costs more than it saves)
        return self.client.submit(self.work, item, pure=False)

    def stop(self, pending) -> None:
        # release, not Client.cancel: cancel waits for the scheduler's answer,
        # and after a KeyboardInterrupt inside a wait that answer never came
        # (the command hung); a released task nobody wants is dropped by the
        # scheduler (queued ones are never run)
        while pending:
            pending.popleft().release()
        if self.close:
            self.client.close(timeout=CONNECT_TIMEOUT_S)
