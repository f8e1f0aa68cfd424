"""Files written whole or not at all: the one way deathsphere writes a file.

Every output (tables, Parquet, figures, the 3-D view, GIF and MP4) is
written under a temporary name in the file's own folder, a hidden
``.NAME.XXXXXXXX.part.EXT`` (the extension kept: matplotlib and ffmpeg
choose the format by it), flushed to disk, and renamed over the final
name only when complete (:func:`os.replace`, atomic within a folder).  A
run that fails or is stopped (an exception, Ctrl-C, or SIGTERM once the
command line has turned it into an exception) removes the temporary file:
nothing is left under the final name, and a file that was already there
is left as it was.  The names not written are kept for the command line
to say so (:func:`not_written`).

It imports nothing of the package, so that any layer that writes a file
(the table, the writers, the figures, the viewer) may use it.
"""

from __future__ import annotations

import os
import signal
import tempfile
import threading
from contextlib import contextmanager
from typing import IO, Iterator

__all__ = ["atomic_path", "atomic_file", "not_written", "signals_held", "PART"]

#: what marks a temporary file (before the final name's extension)
PART = ".part"

#: final names whose write was abandoned, oldest first (see :func:`not_written`)
_abandoned: list[str] = []


def not_written() -> list[str]:
    """The final names that a failed or interrupted write left unwritten
    since the last call (and forgets them)."""
    names = list(_abandoned)
    _abandoned.clear()
    return names


@contextmanager
def atomic_path(path) -> Iterator[str]:
    """Yield a temporary path beside ``path`` to write the file to; on
    success it is synced and renamed to ``path``, on any exception
    (KeyboardInterrupt included) it is removed and the exception goes on."""
    final = os.fspath(path)
    folder, name = os.path.split(os.path.abspath(final))
    ext = os.path.splitext(name)[1]
    temp = None
    try:
        # created empty and private (mkstemp's 0600; the final mode is set
        # at the rename), with the signals held: a stop cannot fall between
        # the file's creation and its name being known to the clean-up
        with signals_held():
            fd, temp = tempfile.mkstemp(prefix=f".{name}.", suffix=PART + ext, dir=folder)
            os.close(fd)
        yield temp
        _sync(temp)
        os.chmod(temp, _mode(final))
        os.replace(temp, final)
    except BaseException:
        with signals_held():
            if temp is not None:
                _remove(temp)
            _abandoned.append(final)
        raise
    _sync_folder(folder)


@contextmanager
def atomic_file(path, mode: str = "w", **kwargs) -> Iterator[IO]:
    """:func:`atomic_path` with the temporary file opened (``open``'s
    ``mode`` and keywords): yields the open file."""
    with atomic_path(path) as temp:
        with open(temp, mode, **kwargs) as out:
            yield out


def _mode(final: str) -> int:
    """The mode of the file being replaced, else the one a plain ``open``
    would give (0666 less the umask)."""
    try:
        return os.stat(final).st_mode & 0o7777
    except OSError:
        pass
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def _sync(temp: str) -> None:
    """Flush the file's data to disk, so that the rename never publishes a
    name whose content is still only in memory."""
    fd = os.open(temp, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _sync_folder(folder: str) -> None:
    """Make the rename itself durable (where a folder can be synced)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _remove(temp: str) -> None:
    try:
        os.remove(temp)
    except FileNotFoundError:
        pass


@contextmanager
def signals_held():
    """Hold SIGINT and SIGTERM (acted on when the block ends), so that a
    stop cannot fall between two steps that belong together: the clean-up
    of a temporary file, or starting a helper process and recording it to
    stop it.  Python's handlers are swapped for one that notes the signal
    (one already arrived but not yet acted on is noted too), and the first
    noted is raised again at the end.  Only the main thread has handlers."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    noted = []
    previous = {}
    try:
        for sig in (signal.SIGINT, signal.SIGTERM):
            previous[sig] = signal.signal(sig, lambda signum, frame: noted.append(signum))
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, signal.SIG_DFL if handler is None else handler)
        if noted:
            signal.raise_signal(noted[0])
