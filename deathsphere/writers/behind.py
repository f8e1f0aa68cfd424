"""A chunk written on a thread of its own while the caller evaluates the
next one (:class:`WriteBehind`)."""

from __future__ import annotations


class WriteBehind:
    """One writer thread: a chunk is formatted and written there while the
    caller evaluates the next one.  polars and pyarrow format, compress and
    write without holding Python's lock, so on two cores the two overlap.
    One chunk at most is in the thread's hands, so the chunks stay in order
    and memory grows by one chunk; a failed write (a reader gone, a full
    disk) is raised here at the next chunk or at the end."""

    def __init__(self):
        from concurrent.futures import ThreadPoolExecutor

        self.pool = ThreadPoolExecutor(1, thread_name_prefix="deathsphere-writer")
        self.pending = None

    def put(self, write, *args, **kwargs) -> None:
        """Wait for the chunk before, then hand ``write(*args, **kwargs)`` over."""
        self.wait()
        self.pending = self.pool.submit(write, *args, **kwargs)

    def wait(self) -> None:
        if self.pending is not None:
            done, self.pending = self.pending, None
            done.result()

    def close(self) -> None:
        self.pool.shutdown(wait=True, cancel_futures=True)
