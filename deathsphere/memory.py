"""glibc's malloc, told to keep freed buffers: every process that
evaluates chunks (a command, a ``--jobs`` process, a dask worker) calls
:func:`reuse_freed_memory` once.  Imports nothing of the package."""

from __future__ import annotations

import sys

#: glibc's malloc thresholds for a command (bytes).  A chunk's column of
#: 16,384 floats is 128 kB, glibc's default mmap threshold: each one was
#: mapped fresh from the kernel and unmapped when freed, so every chunk
#: paid a page fault per 4 kB touched (a quarter of a sweep's CPU time with
#: stability).  Below these sizes freed buffers stay in the heap and the
#: next chunk reuses them; the peak stays that of one chunk.
MMAP_THRESHOLD = 32 * 1024 ** 2   # glibc's largest allowed on 64-bit
TRIM_THRESHOLD = 256 * 1024 ** 2


def reuse_freed_memory() -> None:
    """Raise glibc's mmap and trim thresholds (nothing elsewhere: another
    libc has no ``mallopt`` or its own policy).  A dask worker's nanny sets
    a trim threshold of 64 kB, which made each chunk there 2.6x slower."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return
    m_trim_threshold, m_mmap_threshold = -1, -3  # <malloc.h>
    mallopt(m_mmap_threshold, MMAP_THRESHOLD)
    mallopt(m_trim_threshold, TRIM_THRESHOLD)
